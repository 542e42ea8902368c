"""The system statics' compiled line profile is the single-line NumPy profile, to the last bit, in every regime.

``seacable.system.statics.catenary.closed_form_profile`` draws a system's sub-lines point by point;
``seacable.statics.catenary._profile`` draws a single line with NumPy. Both evaluate the same closed forms
with the same operations in the same order (np.where keeps one branch; NumPy and the kernel call libm's
asinh, hypot and pow), so every point must agree bit for bit (where NumPy calls libm: not with AVX512, below): a
changed operation, order or branch in either shows here, on any input of any regime (the inputs need not be a
solved line for that).
"""

from __future__ import annotations

import numpy as np
import pytest

from seacable.statics.catenary import CatenaryRegime, _profile
from seacable.system.statics.catenary import closed_form_profile

R = CatenaryRegime

try:  # NumPy's CPU dispatch: with AVX512_SKX its arcsinh and power are SVML's, not libm's (the kernel calls libm)
    from numpy._core._multiarray_umath import __cpu_features__ as _FEATURES
except ImportError:  # pragma: no cover - NumPy < 2
    from numpy.core._multiarray_umath import __cpu_features__ as _FEATURES
#: On such a CPU the two can differ in the last bits (SVML's asinh and pow are within a few ulp of libm's): there
#: they are compared to 1e-13 relative, which still catches a wrong term, sign or branch but not a reordering of
#: the same operations; elsewhere (this project's machines and CI) bit for bit, which catches that too.
SVML = bool(_FEATURES.get("AVX512_SKX", False))


def _same(ours, theirs):
    """Where ``ours`` is ``theirs``: the same bits (signed zeros included), NaN where both are NaN."""
    if SVML:
        close = np.isclose(ours, theirs, rtol=1e-13, atol=0.0) | (ours == theirs)
        return close | (np.isnan(ours) & np.isnan(theirs))
    return (ours.view(np.uint64) == theirs.view(np.uint64)) | (np.isnan(ours) & np.isnan(theirs))


def _inputs(regime: CatenaryRegime, rng: np.random.Generator) -> dict:
    """Random inputs of one regime: spans, length, EA, weight (negative: buoyant), friction, tensions."""
    L = rng.uniform(10.0, 900.0)
    w = rng.choice([-1.0, 1.0]) * rng.uniform(5.0, 2000.0)
    H = rng.choice([0.0, rng.uniform(1e2, 1e6)]) if regime in (R.ON_SEABED, R.TOUCHDOWN_SLACK_ANCHOR) \
        else (0.0 if regime in (R.SLACK_SEABED, R.SLACK_U) else rng.uniform(1e2, 1e6))
    # V_F from w L / 2 (a U, VA < 0) to 2 w L (lifting the anchor, VA > 0: the small-argument series near s = 0)
    VF = abs(w) * L * rng.uniform(0.5, 2.0) * np.sign(w)
    return dict(xF=rng.uniform(0.0, L), zF=rng.choice([-1.0, 0.0, 1.0]) * rng.uniform(0.0, L), L=L,
                EA=rng.uniform(1e5, 1e10), w=w, mu=rng.choice([0.0, rng.uniform(0.1, 1.5)]), H=H, VF=VF,
                LB=rng.uniform(0.0, L) * rng.choice([0.0, 1.0, 1.0]), regime=int(regime))


@pytest.mark.filterwarnings("ignore:.*encountered in.*divide:RuntimeWarning")  # NumPy's inf and NaN of H = 0 inputs
@pytest.mark.parametrize("regime", list(R), ids=[r.name for r in R])
def test_compiled_profile_is_the_numpy_profile_to_the_bit(regime):
    rng = np.random.default_rng(int(regime) + 7)
    for _ in range(60):
        p = _inputs(regime, rng)
        n = int(rng.integers(2, 250))
        ref = _profile(n, **p)
        x, z, T = np.empty(n), np.empty(n), np.empty(n)
        closed_form_profile(ref.s, p["xF"], p["zF"], p["L"], p["EA"], p["w"], p["mu"], p["H"], p["VF"], p["LB"],
                            p["regime"], x, z, T)
        for name, ours, theirs in (("x", x, ref.x), ("z", z, ref.z), ("tension", T, ref.tension)):
            same = _same(ours, theirs)  # NaN where both are NaN: an input outside the regime's domain
            assert same.all(), (f"{regime.name} {name} differs at {np.flatnonzero(~same)[:5]} for {p}, n={n}: "
                                f"{ours[~same][:3]} vs {theirs[~same][:3]}")


def test_the_small_argument_series_is_compared():
    """The suspended arc's asinh(q)/q series (|q| < 1e-3) is one of the branches the regimes above reach."""
    s = np.linspace(0.0, 100.0, 50)
    H, VA, w = 1e5, 1e3, 2.0
    a, b = (VA + w * s) / H, np.full_like(s, VA / H)
    q = (a - b) * (a + b) / (a * np.hypot(1.0, b) + b * np.hypot(1.0, a))
    assert (np.abs(q) < 1e-3).sum() > 10 and (np.abs(q) >= 1e-3).sum() > 10
    ref = _profile(50, 50.0, 40.0, 100.0, 1e8, w, 0.0, H, VA + w * 100.0, 0.0, int(R.SUSPENDED))
    x, z, T = np.empty(50), np.empty(50), np.empty(50)
    closed_form_profile(ref.s, 50.0, 40.0, 100.0, 1e8, w, 0.0, H, VA + w * 100.0, 0.0, int(R.SUSPENDED), x, z, T)
    assert _same(x, ref.x).all() and _same(z, ref.z).all()

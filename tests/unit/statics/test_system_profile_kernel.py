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


def _numpy_line_profile(eq, name, n):
    """A line's profile assembled with NumPy from its sub-lines' profiles (``sub_profile``): each placed in the
    line's frame, ordered by arc length along the line (a stable sort), joined, then interpolated at ``n`` evenly
    spaced arc lengths; the reference of the compiled ``SystemEquilibrium.line_profiles``."""
    from seacable.statics.catenary import CatenaryProfile
    from seacable.system.statics.catenary import sub_profile

    asm = eq._asm
    il = eq.line_names.index(name)
    subs = range(asm.line_first[il], asm.line_last[il] + 1)
    total = sum(asm.sub_L[k] for k in subs)
    S, X, T = [], [], []
    for k in subs:
        m = max(4, int(np.ceil(2 * n * asm.sub_L[k] / total)) + 2)
        prof = sub_profile(eq._cat, k, m, asm.tables, CatenaryProfile)
        a_is = eq._anchor_is_a[k]
        pA = eq._node_position[asm.sub_a[k] if a_is else asm.sub_b[k]]
        e = eq._e[k]
        s = asm.sub_s0[k] + (prof.s if a_is else asm.sub_L[k] - prof.s)
        order = np.argsort(s, kind="stable")
        S.append(s[order])
        X.append(np.array([pA[0] + prof.x * e[0], pA[1] + prof.x * e[1], pA[2] + prof.z])[:, order])
        T.append(prof.tension[order])
    S, X, T = np.concatenate(S), np.concatenate(X, axis=1), np.concatenate(T)
    s = np.linspace(0.0, total, n)
    return np.column_stack([np.interp(s, S, X[j]) for j in range(3)]), np.interp(s, S, T)


def _systems():
    from seacable.system.model import MooringSystem
    from seacable.system.statics import examples as ex

    for build in (ex.oc3_hywind, ex.oc4_semi, ex.moored_buoy):
        system, env = build()
        yield build.__name__, system, env
        # the lines drawn from their fairleads (the anchor at end B): each sub-line's points taken in reverse
        flipped = {k: line.model_copy(update={"end_a": line.end_b, "end_b": line.end_a})
                   for k, line in system.lines.items()}
        yield build.__name__ + " flipped", MooringSystem(points=system.points, bodies=system.bodies,
                                                         lines=flipped), env
        # a strain-tension table: the tabled sub-lines' profiles
        ea = 7.536e8
        table = ex.OC3_CHAIN.model_copy(update={"tension_strain": ((0.0, 0.0), (0.01, 0.003 * ea), (0.1, 0.1 * ea))})
        tabled = {k: line.model_copy(update={"line": line.line.model_copy(update={"segments": tuple(
            seg.model_copy(update={"line_type": table}) for seg in line.line.segments)})})
            for k, line in system.lines.items()}
        yield build.__name__ + " tabled", MooringSystem(points=system.points, bodies=system.bodies,
                                                        lines=tabled), env


@pytest.mark.filterwarnings("ignore::UserWarning")
def test_whole_line_profiles_are_the_numpy_assembly_of_their_sub_lines_to_the_bit():
    from seacable.system.statics import solve_equilibrium

    seen = {"reversed": False, "several": False, "tables": False}
    for label, system, env in _systems():
        eq = solve_equilibrium(system, env)
        asm = eq._asm
        seen["reversed"] |= not eq._anchor_is_a.all()
        seen["several"] |= bool((asm.line_last > asm.line_first).any())
        seen["tables"] |= asm.tables is not None
        for n in (2, 41):
            pos, tension = eq.line_profiles(None, n)
            assert pos.shape == (len(eq.line_names), n, 3) and tension.shape == (len(eq.line_names), n)
            for j, name in enumerate(eq.line_names):
                ref_pos, ref_t = _numpy_line_profile(eq, name, n)
                one_pos, one_t = eq.line_profile(name, n)
                for ours in ((pos[j], tension[j]), (one_pos, one_t)):
                    assert (ours[0].view(np.uint64) == ref_pos.view(np.uint64)).all(), (label, name, n)
                    assert (ours[1].view(np.uint64) == ref_t.view(np.uint64)).all(), (label, name, n)
    assert all(seen.values()), seen


def test_the_written_out_sort_and_interpolation_are_numpys():
    """The line profiles' stable order and interpolation (written out, not numba's np.argsort and np.interp) give
    NumPy's: ties and NaN in the sort, repeated points of ``xp``, points on, between and outside them."""
    from seacable.system.statics.catenary import _interp, _stable_order

    rng = np.random.default_rng(3)
    for _ in range(200):
        m = int(rng.integers(2, 40))
        s = np.round(rng.uniform(0.0, 5.0, m))  # many ties
        s[rng.random(m) < 0.1] = np.nan
        for values in (s, np.sort(s), np.sort(s)[::-1].copy()):
            for reverse in (False, True):
                assert (_stable_order(values, reverse) == np.argsort(values, kind="stable")).all()
        xp = np.sort(np.round(rng.uniform(0.0, 10.0, m), 1))  # repeated points
        fp = rng.normal(size=m)
        fp[rng.random(m) < 0.05] = np.inf
        x = np.concatenate([rng.uniform(-1.0, 11.0, 30), xp, [np.nan]])
        out = np.empty(x.size)
        with np.errstate(all="ignore"):
            _interp(x, xp, fp, out)
            ref = np.interp(x, xp, fp)
        assert ((out.view(np.uint64) == ref.view(np.uint64)) | (np.isnan(out) & np.isnan(ref))).all()

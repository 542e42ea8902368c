"""Unit tests of seacable.statics.catenary: stiffness, vectorisation, profiles, errors."""

import numpy as np
import pytest

from seacable.errors import ConvergenceError, InputError, NoSolutionError
from seacable.statics.catenary import CatenaryRegime as R
from seacable.statics.catenary import catenary

# (x, z, L, EA, w, mu, seabed) in regimes where the fairlead stiffness is smooth
SMOOTH = {
    "suspended": (400.0, 250.0, 470.0, 5e8, 800.0, 0.0, True),
    "U mid-water": (300.0, 50.0, 500.0, 5e8, 800.0, 0.0, False),
    "touchdown": (800.0, 250.0, 900.0, 1e9, 700.0, 0.0, True),
    "touchdown friction": (800.0, 250.0, 900.0, 1e9, 700.0, 0.5, True),
    "friction takes all": (700.0, 250.0, 900.0, 1e9, 700.0, 1.0, True),
    "near-taut": (400.0, 300.0, 499.9, 1e8, 100.0, 0.0, True),
    "buoyant": (300.0, 100.0, 400.0, 1e8, -200.0, 0.0, True),
    "weightless": (300.0, 400.0, 499.0, 1e7, 0.0, 0.0, True),
    "slack L shape": (100.0, 250.0, 900.0, 1e9, 700.0, 0.5, True),
}


def _fd_stiffness(x, z, L, EA, w, mu, sb, h):
    def f(xx, zz):
        r = catenary(xx, zz, L, EA, w, mu, sb, tol=1e-14, max_iter=200)
        return np.array([float(r.H_fairlead), float(r.V_fairlead)])
    return np.column_stack([(f(x + h, z) - f(x - h, z)) / (2 * h), (f(x, z + h) - f(x, z - h)) / (2 * h)])


@pytest.mark.parametrize("case", SMOOTH.values(), ids=SMOOTH.keys())
def test_stiffness_matches_central_differences(case):
    x, z, L, EA, w, mu, sb = case
    K = catenary(*case).stiffness
    # central differences err by C (h/L)^2 with a large C for taut lines (measured 1.2e-4 at
    # h = 1e-4 L, 1.2e-6 at 1e-5 L for "near-taut"); h = 1e-6 L puts truncation near 1e-8
    # and solver noise at tol L / h = 1e-14 / 1e-6 = 1e-8, both far below the 1e-5 asked for
    Kfd = _fd_stiffness(x, z, L, EA, w, mu, sb, 1e-6 * L)
    np.testing.assert_allclose(K, Kfd, rtol=1e-5, atol=1e-5 * np.abs(Kfd).max())


def test_vertical_and_flat_stiffness():
    # straight vertical line: dV/dz = EA / L exactly (only the elastic stretch changes)
    r = catenary(0.0, 500.1, 500.0, 1e9, 700.0, seabed=False)
    assert r.stiffness[1, 1] == pytest.approx(1e9 / 500.0, rel=1e-12)
    # its horizontal stiffness 1 / [ln(V_F/V_A)/w + L/EA] against a one-sided difference
    # (x >= 0): error O(h) with h = 1e-7 L, so 1e-4 relative
    h = 5e-5
    r2 = catenary(h, 500.1, 500.0, 1e9, 700.0, seabed=False, tol=1e-14)
    assert float(r2.H_fairlead) / h == pytest.approx(r.stiffness[0, 0], rel=1e-4)
    # a tensioned line flat on the seabed: dH/dx = EA/L (anchor loaded); dV/dz is infinite
    r = catenary(905.0, 0.0, 900.0, 1e8, 700.0, 0.5)
    assert float(r.H_anchor) > 0
    assert r.stiffness[0, 0] == pytest.approx(1e8 / 900.0, rel=1e-12)
    assert np.isinf(r.stiffness[1, 1])
    # friction takes all the tension: H = sqrt(2 mu w EA (x - L)), dH/dx = mu w EA / H
    r = catenary(900.5, 0.0, 900.0, 1e8, 700.0, 0.5)
    H = np.sqrt(2 * 0.5 * 700.0 * 1e8 * 0.5)
    assert float(r.H_fairlead) == pytest.approx(H, rel=1e-12)
    assert r.stiffness[0, 0] == pytest.approx(0.5 * 700.0 * 1e8 / H, rel=1e-12)


def _random_cases(n, seed=3):
    rng = np.random.default_rng(seed)
    L = rng.uniform(10, 1000, n)
    x = L * rng.uniform(0, 1.05, n)
    x[rng.random(n) < 0.03] = 0.0                       # vertical lines
    z = L * rng.uniform(-1, 1.05, n)
    sb = rng.random(n) < 0.5
    z = np.where(sb, np.abs(z), z)
    z[sb & (rng.random(n) < 0.05)] = 0.0                # flat on the seabed
    w = rng.uniform(-500, 2000, n)
    w[rng.random(n) < 0.01] = 0.0                       # weightless
    EA = np.abs(w).clip(1.0) * L * 10 ** rng.uniform(1, 6, n)
    mu = rng.uniform(0, 1.5, n) * (rng.random(n) < 0.7)
    return x, z, L, EA, w, mu, sb


def test_batch_equals_per_case():
    cases = _random_cases(10_000)
    r = catenary(*cases)
    assert set(np.unique(r.regime)) == set(int(v) for v in R)   # every regime is exercised
    fields = ("H_fairlead", "V_fairlead", "H_anchor", "V_anchor", "grounded_length")
    for i in range(0, 10_000, 7):      # every 7th case keeps the file fast (~1400 solves)
        ri = catenary(*(c[i] for c in cases))
        assert ri.regime == r.regime[i]
        for f in fields:
            # same arithmetic per case; 1e-9 allows SIMD vs scalar libm differences
            # amplified by the solver tolerance (1e-10)
            scale = max(float(ri.fairlead_tension), 1.0)
            assert getattr(r, f)[i] == pytest.approx(float(getattr(ri, f)), rel=1e-9, abs=1e-9 * scale)


def test_broadcast_shapes():
    r = catenary(np.array([[300.0], [400.0], [500.0]]), [200.0, 250.0, 300.0, 350.0], 600.0, 1e9, 700.0)
    assert r.H_fairlead.shape == (3, 4)
    assert r.stiffness.shape == (3, 4, 2, 2)
    assert r.regime.dtype == np.int8
    assert float(r.H_fairlead[1, 2]) == pytest.approx(float(catenary(400.0, 300.0, 600.0, 1e9, 700.0).H_fairlead),
                                                      rel=1e-12)


def test_buoyant_line_is_the_mirror_of_a_heavy_one():
    # z -> -z and w -> -w maps one equilibrium onto the other: H equal, V opposite
    a = catenary(300.0, 50.0, 400.0, 1e8, -200.0, seabed=False)
    b = catenary(300.0, -50.0, 400.0, 1e8, 200.0, seabed=False)
    assert float(a.H_fairlead) == pytest.approx(float(b.H_fairlead), rel=1e-12)
    assert float(a.V_fairlead) == pytest.approx(-float(b.V_fairlead), rel=1e-12)
    assert float(a.V_anchor) == pytest.approx(-float(b.V_anchor), rel=1e-12)


def test_friction_takes_all_tension():
    r = catenary(700.0, 250.0, 900.0, 1e9, 700.0, 1.0)
    assert r.regime == R.TOUCHDOWN_SLACK_ANCHOR
    assert float(r.H_anchor) == 0.0 and float(r.V_anchor) == 0.0
    # H_A = H - mu w L_B exactly when the anchor still holds tension
    r = catenary(800.0, 250.0, 900.0, 1e9, 700.0, 0.5)
    expected = float(r.H_fairlead) - 0.5 * 700.0 * float(r.grounded_length)
    assert float(r.H_anchor) == pytest.approx(expected, rel=1e-12)


PROFILE_CASES = [
    (400.0, 250.0, 470.0, 5e8, 800.0, 0.0, True),
    (300.0, 50.0, 500.0, 5e8, 800.0, 0.0, False),
    (800.0, 250.0, 900.0, 1e9, 700.0, 0.5, True),
    (700.0, 250.0, 900.0, 1e9, 700.0, 1.0, True),
    (100.0, 250.0, 900.0, 1e9, 700.0, 0.5, True),
    (0.0, 500.1, 500.0, 1e9, 700.0, 0.0, False),
    (0.0, 100.0, 500.0, 1e7, 700.0, 0.0, False),
    (900.5, 0.0, 900.0, 1e8, 700.0, 0.5, True),
    (800.0, 0.0, 900.0, 1e8, 700.0, 0.5, True),
    (300.0, 100.0, 400.0, 1e8, -200.0, 0.0, True),
    (300.0, 400.0, 499.0, 1e7, 0.0, 0.0, True),
]


@pytest.mark.parametrize("case", PROFILE_CASES)
def test_profile_reaches_both_ends(case):
    r = catenary(*case)
    p = r.profile(50)
    x, z, L = case[0], case[1], case[2]
    # the profile integrates the same closed forms from the anchor: ends to 1e-8 of L
    assert p.s[0] == 0.0 and p.s[-1] == L
    assert abs(p.x[0]) + abs(p.z[0]) <= 1e-8 * L
    assert p.x[-1] == pytest.approx(x, abs=1e-8 * L)
    assert p.z[-1] == pytest.approx(z, abs=1e-8 * L)
    assert p.tension[-1] == pytest.approx(float(r.fairlead_tension), rel=1e-9, abs=1e-9 * L)
    assert p.tension[0] == pytest.approx(float(r.anchor_tension), rel=1e-9, abs=1e-6 * float(r.fairlead_tension))
    if case[6]:
        assert p.z.min() >= -1e-9 * L          # never below the seabed


def test_profile_of_array_result_needs_index():
    r = catenary([300.0, 400.0], 250.0, 600.0, 1e9, 700.0)
    p = r.profile(10, index=1)
    assert p.x[-1] == pytest.approx(400.0, abs=1e-7)
    with pytest.raises(InputError, match="index must be given"):
        r.profile(10)
    with pytest.raises(InputError, match="n_points must be >= 2"):
        r.profile(1, index=0)


@pytest.mark.parametrize("kwargs, match", [
    (dict(length=-3.0), r"length must be > 0 m, got -3 m\. Suggested fix"),
    (dict(axial_stiffness=0.0), r"axial_stiffness must be > 0 N, got 0 N"),
    (dict(horizontal_span=-1.0), r"horizontal_span must be >= 0 m, got -1 m"),
    (dict(weight_per_length=np.nan), r"weight_per_length must be a finite number"),
    (dict(vertical_span=np.inf), r"vertical_span must be a finite number"),
    (dict(seabed_friction=-0.2), r"seabed_friction must be >= 0, got -0.2"),
    (dict(vertical_span=-5.0), r"vertical_span must be >= 0 m when seabed=True, got -5 m"),
    (dict(length=[500.0, -1.0]), r"length\[1\] must be > 0 m"),
    (dict(tol=0.0), r"tol must be > 0"),
])
def test_bad_inputs(kwargs, match):
    args = dict(horizontal_span=400.0, vertical_span=250.0, length=500.0, axial_stiffness=1e9,
                weight_per_length=700.0)
    args.update(kwargs)
    with pytest.raises(InputError, match=match):
        catenary(**args)


def test_inputs_that_do_not_broadcast():
    with pytest.raises(InputError, match="must broadcast together"):
        catenary([1.0, 2.0], [1.0, 2.0, 3.0], 5.0, 1e9, 700.0)


def test_line_that_cannot_reach():
    # the chord alone needs 150 % strain
    with pytest.raises(NoSolutionError, match=r"line\[1\] cannot reach.*strain of 1\.5.*Suggested fix"):
        catenary([400.0, 1000.0], 0.0, 400.0, 1e9, 700.0)
    # chord strain is small (2 %) but the weight of a very soft line needs T/EA > 1
    with pytest.raises(NoSolutionError, match="cannot reach"):
        catenary(400.0, 400.0, 555.0, 1e3, 700.0)
    # ... which is accepted when the user allows the strain
    r = catenary(400.0, 400.0, 555.0, 1e3, 700.0, max_strain=1e3)
    assert float(r.fairlead_tension) / 1e3 > 1.0


def test_non_convergence_names_case_iterations_and_residual():
    with pytest.raises(ConvergenceError, match=r"case \(1,\).*after 1 iterations") as err:
        catenary([400.0, 800.0], [250.0, 250.0], [470.0, 900.0], 1e9, 700.0, 0.5, max_iter=1)
    assert err.value.iterations == 1
    assert err.value.residual > 1e-10


def test_line_stretched_by_its_own_weight_is_not_called_too_short():
    # A vertical span of 229 m is well inside 738.55 m of line, but at 3000 N/m and EA = 1.76e5 N
    # the line's own tension would stretch it by about 200 %: the message must say so, not suggest
    # lengthening the line (which would make it worse).
    with pytest.raises(NoSolutionError, match="under its own tension") as info:
        catenary(0.0, 229.0, 738.55, 175818.0, 3000.0)
    assert "lengthen" not in str(info.value)

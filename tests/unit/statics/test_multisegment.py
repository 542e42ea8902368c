"""Unit tests of seacable.statics.multisegment (multi-segment line statics)."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import fsolve

from seacable.errors import ConvergenceError, InputError, NoSolutionError
from seacable.statics.multisegment import line_equilibrium, pushover


def ode_end(H, VA, lengths, weights, ea, loads):
    """Integrate the elastic-cable ODE from the anchor with solve_ivp (independent of the closed forms).

    dx/ds = H/T (1 + T/EA), dz/ds = V/T (1 + T/EA), V(s) = V_A + weight below s.
    """
    bounds = np.concatenate([[0.0], np.cumsum(lengths)])
    cuts = np.unique(np.concatenate([bounds, [s for s, _ in loads]]))
    y, V = np.zeros(2), VA
    for a, b in zip(cuts[:-1], cuts[1:]):
        V += sum(p for s, p in loads if s == a)
        k = min(np.searchsorted(bounds, 0.5 * (a + b)) - 1, len(lengths) - 1)
        w, e, V0 = weights[k], ea[k], V

        def rhs(s, _y, w=w, e=e, V0=V0, a=a):
            Vs = V0 + w * (s - a)
            T = np.hypot(H, Vs)
            return [H / T * (1 + T / e), Vs / T * (1 + T / e)]

        y = solve_ivp(rhs, (a, b), y, rtol=1e-12, atol=1e-10, method="DOP853").y[:, -1]
        V = V0 + w * (b - a)
    return y


# ----------------------------------------------------------------------------------------------
# against independent calculations
# ----------------------------------------------------------------------------------------------
def test_point_load_mid_span_matches_ode_shooting():
    """Suspended line with a point mass at mid-length: forces found by fsolve on the ODE."""
    L, w, ea, W = [300.0, 300.0], [200.0, 200.0], [1e8, 1e8], 4e4
    loads = [(300.0, W)]
    X, Z = 450.0, 120.0
    eq = line_equilibrium(L, w, ea, X, Z, point_loads=loads, seabed=False)

    def resid(u):
        return ode_end(u[0] * 1e4, u[1] * 1e4, L, w, ea, loads) - [X, Z]

    u = fsolve(resid, [eq.H_fairlead * 1.05e-4, eq.V_anchor * 0.95e-4], xtol=1e-12)
    # 1e-6 relative: solve_ivp at rtol 1e-12 and fsolve at xtol 1e-12 are far tighter
    assert eq.H_fairlead == pytest.approx(u[0] * 1e4, rel=1e-6)
    assert eq.V_anchor == pytest.approx(u[1] * 1e4, rel=1e-6)
    assert eq.V_fairlead - eq.V_anchor == pytest.approx(sum(a * b for a, b in zip(L, w)) + W, rel=1e-12)


def test_lazy_wave_with_buoyant_segment_matches_ode():
    """Grounded chain, buoyant section (V changes sign twice), chain to the fairlead."""
    L, w, ea = [300.0, 100.0, 200.0], [1000.0, -800.0, 1000.0], [1e9] * 3
    eq = line_equilibrium(L, w, ea, 450.0, 250.0)
    prof = eq.profile(40)
    assert 0 < eq.touchdown_s < 300.0
    susp = prof.s > eq.touchdown_s
    assert prof.z[susp].min() >= 0.0                      # sag bend stays above the seabed
    # shoot the ODE from the touchdown with V = 0 there, grounded part straight with tension H
    s_td = eq.touchdown_s
    end = ode_end(eq.H_fairlead, 0.0, [300.0 - s_td] + L[1:], w, ea, [])
    x_td = s_td * (1 + eq.H_fairlead / 1e9)
    assert eq.touchdown_x == pytest.approx(x_td, rel=1e-12)
    # 1e-7 m on a 600 m line: ODE rtol 1e-12, solver tolerance 1e-9 relative
    assert x_td + end[0] == pytest.approx(450.0, abs=1e-6)
    assert end[1] == pytest.approx(250.0, abs=1e-6)


def test_two_identical_segments_equal_one():
    one = line_equilibrium(1000.0, 700.0, 5e8, 900.0, 250.0, seabed_friction=0.3)
    for split in (200.0, 500.0, 990.0):        # boundary on the seabed, near the fairlead
        two = line_equilibrium([split, 1000.0 - split], [700.0, 700.0], 5e8, 900.0, 250.0,
                               seabed_friction=0.3)
        # same equations, different summation order: round-off only
        for k in ("H_fairlead", "V_fairlead", "H_anchor", "grounded_length", "touchdown_x"):
            assert getattr(two, k) == pytest.approx(getattr(one, k), rel=1e-9)


def test_matches_single_line_catenary_module():
    from seacable.statics.catenary import catenary

    for X, Z, mu, seabed in [(800.0, 250.0, 0.0, True), (900.0, 250.0, 0.7, True),
                             (1030.0, 250.0, 0.0, True), (800.0, 250.0, 0.0, False),
                             (700.0, 250.0, 0.0, True), (752.0, 250.0, 0.0, True)]:  # slack, near-slack
        ours = line_equilibrium(1000.0, 700.0, 5e8, X, Z, seabed_friction=mu, seabed=seabed)
        peer = catenary(X, Z, 1000.0, 5e8, 700.0, seabed_friction=mu, seabed=seabed)
        for k in ("H_fairlead", "V_fairlead", "H_anchor", "grounded_length"):
            # the brief's 1e-6; both solvers converge to ~1e-10
            assert getattr(ours, k) == pytest.approx(float(getattr(peer, k)), rel=1e-6, abs=1e-6)
        np.testing.assert_allclose(ours.stiffness, peer.stiffness, rtol=1e-6)


# ----------------------------------------------------------------------------------------------
# balances and seabed
# ----------------------------------------------------------------------------------------------
def test_force_balance_with_loads_on_suspended_part():
    L, w = [400.0, 50.0, 550.0], [700.0, 3000.0, 500.0]
    loads = [(700.0, 2e4), (800.0, -1.5e4)]
    eq = line_equilibrium(L, w, 5e8, 945.0, 250.0, point_loads=loads)
    s_td = eq.touchdown_s
    assert 0 < s_td < 400.0
    suspended = w[0] * (400.0 - s_td) + w[1] * 50.0 + w[2] * 550.0 + 2e4 - 1.5e4
    # exact identity of the parametrisation: round-off only
    assert eq.V_fairlead - eq.V_anchor == pytest.approx(suspended, rel=1e-12)
    assert eq.V_anchor == 0.0 and eq.H_anchor == eq.H_fairlead     # no friction: H constant
    prof = eq.profile(30)
    # tension at touchdown is H (V = 0 there); profile ends at the fairlead to solver tolerance
    i = np.argmin(np.abs(prof.s - s_td))
    assert prof.tension[i] == pytest.approx(eq.H_fairlead, rel=1e-12)
    assert prof.x[-1] == pytest.approx(945.0, abs=1e-6) and prof.z[-1] == pytest.approx(250.0, abs=1e-6)
    assert prof.tension[-1] == pytest.approx(eq.fairlead_tension, rel=1e-12)
    for s in (400.0, 450.0, 700.0, 800.0):                          # every node is sampled
        assert np.any(prof.s == s)
    assert np.sum(prof.s == 700.0) == 2                             # both sides of the point load


def test_touchdown_exactly_at_point_mass():
    W = 2e5
    eq = line_equilibrium([400.0, 600.0], [700.0, 700.0], 5e8, 935.0, 250.0, point_loads=[(400.0, W)])
    assert eq.touchdown_s == 400.0
    V_above = eq.V_fairlead - 700.0 * 600.0
    assert 0.0 < V_above < W                                        # mass partly carried by the seabed
    assert eq.segment_grounded_length.tolist() == [400.0, 0.0]


def test_friction_profile_is_linear_on_seabed():
    mu, w = 0.4, 700.0
    eq = line_equilibrium(1000.0, w, 5e8, 985.0, 250.0, seabed_friction=mu)
    prof = eq.profile(200)
    g = (prof.s < eq.touchdown_s) & (prof.tension > 0)
    # Coulomb friction: dT/ds = mu w on the grounded part (exact, round-off tolerance)
    slope = np.diff(prof.tension[g]) / np.diff(prof.s[g])
    np.testing.assert_allclose(slope, mu * w, rtol=1e-8)
    assert eq.H_anchor == pytest.approx(eq.H_fairlead - mu * w * eq.grounded_length, rel=1e-10)


def test_stiffness_matches_finite_differences():
    args = ([400.0, 50.0, 550.0], [700.0, 3000.0, 500.0], [5e8, 1e9, 4e8])
    kw = dict(point_loads=[(700.0, 2e4)], seabed_friction=0.3)
    x, z, h = 900.0, 250.0, 1e-3
    eq = line_equilibrium(*args, x, z, **kw)
    fd = np.zeros((2, 2))
    for j, (dx, dz) in enumerate(((h, 0), (0, h))):
        p = line_equilibrium(*args, x + dx, z + dz, **kw)
        m = line_equilibrium(*args, x - dx, z - dz, **kw)
        fd[:, j] = [(p.H_fairlead - m.H_fairlead) / (2 * h), (p.V_fairlead - m.V_fairlead) / (2 * h)]
    # central differences: O(h^2) truncation plus 1e-9 L/h solver noise, both < 1e-5 relative
    np.testing.assert_allclose(eq.stiffness, fd, rtol=1e-5)


def test_pushover_equals_independent_solves():
    offs = np.linspace(0.0, 60.0, 7)
    po = pushover(1000.0, 700.0, 5e8, 900.0, 250.0, offs, seabed_friction=0.2)
    for i, o in enumerate(offs):
        eq = line_equilibrium(1000.0, 700.0, 5e8, 900.0 + o, 250.0, seabed_friction=0.2)
        # continuation changes the start point only
        assert po.H_fairlead[i] == pytest.approx(eq.H_fairlead, rel=1e-9)
        assert po.stiffness_horizontal[i] == pytest.approx(eq.stiffness[0, 0], rel=1e-6)
    assert np.all(np.diff(po.H_fairlead) > 0) and np.all(np.diff(po.grounded_length) < 0)
    assert po.liftoff_offset(0) is None


def test_slack_line_hangs_vertically_with_H_zero():
    """Span shorter than the grounded length at H -> 0: H = 0, the rest hangs vertically."""
    L, w, ea, Z = [400.0, 600.0], 700.0, 5e8, 250.0
    eq = line_equilibrium(L, w, ea, 600.0, Z, point_loads=[(900.0, 1e5)])
    assert eq.H_fairlead == 0.0 and eq.H_anchor == 0.0
    # hanging part of unstretched length l under its own weight: Z = l + w l^2/(2 EA) + P (L - s_P)/EA
    l = 1000.0 - eq.touchdown_s
    assert l + w * l * l / (2 * ea) + 1e5 * 100.0 / ea == pytest.approx(Z, rel=1e-12)
    assert eq.V_fairlead == pytest.approx(w * l + 1e5, rel=1e-12)
    assert eq.stiffness[0, 0] == 0.0 and eq.stiffness[1, 1] == pytest.approx(w, rel=1e-3)
    prof = eq.profile(10)
    assert prof.x.max() == 600.0 and prof.z[-1] == pytest.approx(Z, rel=1e-12)
    # continuation from slack to taut
    po = pushover(L, w, ea, 600.0, Z, [0.0, 100.0, 160.0, 200.0, 250.0], point_loads=[(900.0, 1e5)])
    assert np.all(po.H_fairlead[:2] == 0.0) and np.all(np.diff(po.H_fairlead[1:]) > 0)


def test_buoyant_first_segment_lifts_anchor():
    """Seabed at the anchor but a strongly buoyant first segment: fully suspended, clear of the seabed."""
    L, w, ea = [100.0, 600.0], [-10000.0, 300.0], [1e9, 1e9]
    eq = line_equilibrium(L, w, ea, 650.0, 50.0)
    assert eq.touchdown_s == 0.0 and eq.touchdown_segment == -1 and eq.V_anchor > 0
    assert eq.profile(50).z.min() >= 0.0
    end = ode_end(eq.H_anchor, eq.V_anchor, L, w, ea, [])
    np.testing.assert_allclose(end, [650.0, 50.0], atol=1e-6)   # 1e-9 L solver tolerance


def test_mid_water_anchor_with_buoy():
    """seabed=False, a buoy making V change sign twice; checked against the ODE."""
    L, w, ea = [300.0, 300.0], [200.0, 200.0], [1e8, 1e8]
    loads = [(200.0, -1e5)]
    eq = line_equilibrium(L, w, ea, 400.0, 50.0, point_loads=loads, seabed=False)
    end = ode_end(eq.H_anchor, eq.V_anchor, L, w, ea, loads)
    np.testing.assert_allclose(end, [400.0, 50.0], atol=1e-6)   # 1e-9 L solver tolerance, ODE rtol 1e-12


# ----------------------------------------------------------------------------------------------
# error paths
# ----------------------------------------------------------------------------------------------
GOOD = ([500.0, 500.0], [700.0, 700.0], 5e8, 900.0, 250.0)


@pytest.mark.parametrize("change, match", [
    ({0: [-3.0, 500.0]}, r"lengths\[0\] must be > 0 m, got -3 m"),
    ({1: [700.0, 700.0, 1.0]}, "weights must have one value per segment"),
    ({1: [700.0, np.nan]}, r"weights\[1\] must be a finite number"),
    ({2: 0.0}, "axial_stiffness must be > 0 N"),
    ({3: -5.0}, "horizontal_span must be > 0 m"),
    ({4: np.inf}, "vertical_span must be a finite number"),
])
def test_bad_inputs(change, match):
    args = list(GOOD)
    for k, val in change.items():
        args[k] = val
    with pytest.raises(InputError, match=match):
        line_equilibrium(*args)


@pytest.mark.parametrize("kw, match", [
    (dict(point_loads=[(0.0, 1e3)]), r"point_loads\[0\] arc length must be in \(0, 1000\) m"),
    (dict(point_loads=[(1000.0, 1e3)]), r"point_loads\[0\] arc length"),
    (dict(point_loads=[5.0]), r"point_loads\[0\] must be a pair"),
    (dict(point_loads=[(5.0, np.nan)]), r"net weight must be a finite number"),
    (dict(seabed_friction=-0.1), "seabed_friction must be >= 0"),
    (dict(seabed_slope=0.1), "sloping seabed is not implemented"),
    (dict(seabed_slope=2.0), r"seabed_slope must be in \(-1.5708, 1.5708\) rad"),
    (dict(tol=0.0), "tol must be in"),
    (dict(max_iter=0), "max_iter must be >= 1"),
])
def test_bad_options(kw, match):
    with pytest.raises(InputError, match=match):
        line_equilibrium(*GOOD, **kw)


def test_bad_profile_and_offsets():
    with pytest.raises(InputError, match="points_per_segment must be >= 2"):
        line_equilibrium(*GOOD).profile(1)
    with pytest.raises(InputError, match=r"offsets\[1\] must be a finite number"):
        pushover(*GOOD, [0.0, np.nan])


@pytest.mark.parametrize("args, kw, match", [
    (([500.0], 700.0, 5e8, 700.0, 250.0), {}, "cannot reach the fairlead"),
    (([1000.0], 700.0, 5e8, 900.0, -1.0), {}, "fairlead must be above the seabed"),
    (([1000.0], 700.0, 5e8, 800.0, 250.0), dict(point_loads=[(100.0, -5e4)]),
     r"buoy at s = 100 m .* grounded part"),
    (([100.0, 100.0, 800.0], [700.0, -100.0, 700.0], 5e8, 800.0, 250.0), {},
     "segment 1 is buoyant .* grounded part"),
    (([100.0, 600.0], [-3000.0, 300.0], 1e9, 500.0, 50.0), {},
     "dips .* below the seabed"),
    (([224.0, 331.0, 512.6], [940.1, 1008.2, -99.8], 1e9, 192.74, 447.75), {},
     r"slack \(H = 0\) and a buoyant part .* compression"),
])
def test_no_solution(args, kw, match):
    with pytest.raises(NoSolutionError, match=match):
        line_equilibrium(*args, **kw)


def test_convergence_error_reports_iterations():
    with pytest.raises(ConvergenceError, match="did not converge in 2 iterations") as exc:
        line_equilibrium(1000.0, 700.0, 5e8, 800.0, 250.0, max_iter=2)
    assert exc.value.iterations == 2 and exc.value.residual > 0


@pytest.mark.parametrize("args, kw", [
    (([760.0], 1107.0, 7.5e8, 700.0, 190.0), {}),                                    # grounded, a touchdown
    (([760.0], 1107.0, 7.5e8, 600.0, 190.0), {}),                                    # slack: H = 0
    (([400.0], 500.0, 1e8, 300.0, 140.0), dict(seabed=False)),                       # suspended, a sag bend
    (([100.0, 200.0, 100.0], [800.0, 300.0, 800.0], [1e8, 2e8, 1e8], 300.0, 90.0),
     dict(point_loads=[(150.0, 2e4), (300.0, 5e3)])),                               # point loads: repeated s
])
def test_profile_at_is_the_interpolated_whole_profile_to_the_bit(args, kw):
    """profile_at evaluates only the samples its interpolation reads: the same floats as interpolating the whole
    profile (the first sample of a point load's two), at samples, between them and beyond the ends."""
    eq = line_equilibrium(*args, **kw)
    total = float(np.sum(args[0]))
    s = np.r_[-1.0, np.linspace(0.0, total, 37), 150.0, 300.0, 0.3 * total, total + 1.0]
    prof = eq.profile(points_per_segment=400)
    keep = np.r_[True, np.diff(prof.s) > 0]
    x, z = eq.profile_at(s, points_per_segment=400)
    assert x.tobytes() == np.interp(s, prof.s[keep], prof.x[keep]).tobytes()
    assert z.tobytes() == np.interp(s, prof.s[keep], prof.z[keep]).tobytes()

"""The towed barge (seacable.towline.barge): inertia, hull forces, 3-DOF equations, flat kernel.

Paper 003 (shared/seeds/003_dc854471ee8794a0.txt, slide 12): L_pp 50 m, beam 15 m, draft
0.5 m, block coefficient 0.9, yaw radius of gyration 0.25 L. Closed forms of the cross-flow
integrals and the energy argument for the signs of the equations are in the module docstring.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.errors import InputError, SeacableWarning
from seacable.towline.barge import (
    B_BEAM,
    B_CX,
    B_CY,
    B_DRAFT,
    B_LENGTH,
    B_LIFT,
    B_M11,
    B_M22,
    B_M66,
    B_MASS,
    B_N_STRIPS,
    B_RHO,
    B_SIZE,
    B_TOW_X,
    B_TOW_Z,
    B_XUU,
    B_YCF,
    Barge,
    barge_accelerations,
    barge_equations,
    barge_hull_forces,
    barge_hull_forces_flat,
    barge_mass,
    barge_parameters,
    barge_resistance,
)

RHO = 1025.0
PAPER003 = {"length": 50.0, "beam": 15.0, "draft": 0.5, "block_coefficient": 0.9}
KNOT = 1852.0 / 3600.0


@pytest.fixture(scope="module")
def barge():
    return Barge(**PAPER003)


def _cross_flow_exact(b, v, r, rho=RHO):
    """Closed-form Y, N of the cross-flow integrals (module docstring), r != 0."""
    k, L = 0.5 * rho * b.cross_flow_drag * b.draft, b.length
    w1, w2 = v - r * L / 2, v + r * L / 2
    Y = -k * (abs(w2) ** 3 - abs(w1) ** 3) / (3 * r)
    F = lambda w: w**3 * abs(w) / 4 - v * abs(w) ** 3 / 3
    return Y, -k * (F(w2) - F(w1)) / r**2


# ------------------------------------------------------------------------------------------
# Inertia and resistance
# ------------------------------------------------------------------------------------------

def test_paper003_mass_and_inertia(barge):
    m, M11, M22, M66 = barge_mass(barge, RHO)
    # rho Cb L B T = 1025 * 0.9 * 50 * 15 * 0.5 = 345 937.5 kg (345.9 t); one product: round-off only.
    assert m == pytest.approx(345_937.5, rel=1e-14)
    assert M11 == pytest.approx(1.05 * m, rel=1e-14)
    m22 = 2.37 * 0.5 * RHO * math.pi * 0.5**2 * 50.0
    assert M22 == pytest.approx(m + m22, rel=1e-14)
    # Yaw radius of gyration 0.25 L = 12.5 m; strip-theory added inertia m22 L^2 / 12.
    assert M66 == pytest.approx(m * 12.5**2 + m22 * 50.0**2 / 12, rel=1e-14)
    # A given radius of gyration replaces the default.
    assert barge_mass(barge.replace(yaw_radius_of_gyration=10.0))[3] == pytest.approx(
        m * 100.0 + m22 * 50.0**2 / 12, rel=1e-14)


def test_surge_added_mass_default_follows_soding(barge):
    # Soding (1982): m11 = 2.7 rho V^(5/3) / L^2 = 0.0524 m for paper 003's barge; the default 0.05
    # is that value rounded to one significant figure (5 % below it).
    m = barge_mass(barge)[0]
    soding = 2.7 * RHO * (m / RHO) ** (5 / 3) / 50.0**2 / m
    assert soding == pytest.approx(barge.surge_added_mass, rel=0.05)


def _rectangle_added_mass(half_normal, half_along, n_side=400):
    """2-D added mass of a rectangle in infinite fluid moving along its side 2*half_along, over rho pi a^2.

    Constant-strength source panels (Hess and Smith), cosine-clustered towards the corners;
    added mass = -rho * integral(phi n_x ds) for unit velocity.
    """
    a, b = half_normal, half_along
    corners = np.array([(-b, -a), (b, -a), (b, a), (-b, a)], float)
    s = 0.5 * (1 - np.cos(np.linspace(0.0, np.pi, n_side + 1)))[:-1]
    nodes = np.vstack([corners[k] + (corners[(k + 1) % 4] - corners[k]) * s[:, None] for k in range(4)])
    d = np.roll(nodes, -1, axis=0) - nodes
    length = np.hypot(d[:, 0], d[:, 1])
    t = d / length[:, None]
    n = np.stack([t[:, 1], -t[:, 0]], axis=1)  # outward: the polygon runs counter-clockwise
    mid = nodes + 0.5 * d
    rx = mid[:, 0, None] - nodes[None, :, 0]   # panel i's midpoint from panel j's start, in j's frame (x, y)
    ry = mid[:, 1, None] - nodes[None, :, 1]
    x = rx * t[None, :, 0] + ry * t[None, :, 1]
    y = rx * n[None, :, 0] + ry * n[None, :, 1]
    xl = x - length[None, :]
    r2, r2l = x * x + y * y, xl * xl + y * y
    eye = np.eye(len(length), dtype=bool)
    with np.errstate(divide="ignore", invalid="ignore"):
        ux = -np.log(r2l / r2) / (4 * np.pi)
        uy = (np.arctan2(y, xl) - np.arctan2(y, x)) / (2 * np.pi)
    ux[eye], uy[eye] = 0.0, 0.5
    # normal velocity at i induced by panel j: (ux t_j + uy n_j) . n_i
    A = ux * (n[:, None, 0] * t[None, :, 0] + n[:, None, 1] * t[None, :, 1]) \
        + uy * (n[:, None, 0] * n[None, :, 0] + n[:, None, 1] * n[None, :, 1])
    rhs = n[:, 0]
    sigma = np.linalg.solve(A, rhs)

    def prim(X, Y, R2):  # antiderivative of ln sqrt(X^2 + Y^2) in X, R2 = X^2 + Y^2
        with np.errstate(divide="ignore", invalid="ignore"):
            log_term = np.where(R2 > 0, 0.5 * X * np.log(np.where(R2 > 0, R2, 1.0)), 0.0)
            atan_term = np.where(Y != 0, Y * np.arctan(X / np.where(Y != 0, Y, 1.0)), 0.0)
        return log_term - X + atan_term

    G = (prim(x, y, r2) - prim(xl, y, r2l)) / (2 * np.pi)
    G[eye] = (length * np.log(length / 2) - length) / (2 * np.pi)
    phi = G @ sigma
    return -np.sum(phi * rhs * length) / (np.pi * a**2)


def test_sway_added_mass_default_is_potential_flow_value():
    # The panel method reproduces DNV-RP-C205 Table A-1 (2a/2b = 1: 1.51, 0.1: 2.23, printed to
    # 0.01, i.e. 0.5 %) and a circle's C_a = 1 ...
    assert _rectangle_added_mass(1.0, 1.0) == pytest.approx(1.51, rel=5e-3)
    assert _rectangle_added_mass(1.0, 10.0) == pytest.approx(2.23, rel=5e-3)
    # ... and gives the default 2.37 for the double body of paper 003's barge: 2T = 1 m high
    # (normal to the sway), B = 15 m long. Default printed to 0.01: 0.5 %.
    assert _rectangle_added_mass(0.5, 7.5) == pytest.approx(Barge(**PAPER003).sway_added_mass, rel=5e-3)


def test_resistance_is_quadratic_and_equals_surge_drag(barge):
    U = 2 * KNOT
    R = barge_resistance(barge, U, RHO)
    # 1/2 rho C_x B T U^2 with C_x = 1: 3843.75 N s^2/m^2 * U^2 = 4069.1 N at 2 knots.
    assert R == pytest.approx(3843.75 * U**2, rel=1e-14)
    speeds = np.array([0.5, 1.0, 2.0, 4.0]) * U
    np.testing.assert_allclose(barge_resistance(barge, speeds), R * (speeds / U) ** 2, rtol=1e-14)
    assert barge_resistance(barge, -U) == R  # either direction: a magnitude
    # Steady straight tow: the tow force balances the hull's surge force, and nothing else acts.
    X, Y, N = barge_hull_forces(barge, U, 0.0, 0.0)
    assert -X == pytest.approx(R, rel=1e-15) and Y == 0.0 and N == 0.0
    du, dv, dr = barge_equations(barge, U, 0.0, 0.0, R, 0.0, 0.0)
    # R - R in floating point: at most one rounding of R, divided by M11: 2.2e-16 * R / M11 = 2.5e-18.
    assert abs(du) <= 2.3e-16 * R / barge_mass(barge)[1] and dv == 0.0 and dr == 0.0


# ------------------------------------------------------------------------------------------
# Cross-flow drag
# ------------------------------------------------------------------------------------------

def test_pure_sway_is_exact_for_any_strip_count(barge):
    v = np.array([-0.4, -0.1, 0.05, 0.3])
    for n in (1, 7, 20):
        _, Y, N = barge_hull_forces(barge, 0.0, v, 0.0, n_strips=n)
        # Constant integrand: the midpoint rule is exact; -1/2 rho C_y T L |v| v, round-off only.
        np.testing.assert_allclose(Y, -0.5 * RHO * 1.0 * 0.5 * 50.0 * np.abs(v) * v, rtol=1e-13)
        np.testing.assert_allclose(N, 0.0, atol=1e-9 * np.abs(Y).max() * 50.0)


# ------------------------------------------------------------------------------------------
# Slender-body lift at the trailing edge
# ------------------------------------------------------------------------------------------

def test_hull_lift_is_the_slender_body_force_at_the_stern(barge):
    no_drag = barge.replace(cross_flow_drag=0.0)
    # m22 / L = 2.37 rho pi T^2 / 2 = 2.37 * 402.5 = 953.93 kg/m (module docstring)
    m_t = 2.37 * 0.5 * RHO * math.pi * 0.25
    u, v, r = 1.5, 0.2, 0.01
    _, Y, N = barge_hull_forces(no_drag, u, v, r)
    # going ahead the stern (x = -25 m) sheds the lift: Y = -u m'_T (v - 25 r), N = -25 Y; exact
    assert Y == pytest.approx(-u * m_t * (v - 25.0 * r), rel=1e-13)
    assert N == pytest.approx(-25.0 * Y, rel=1e-13)
    # linear derivatives: Y_v = -u m22 / L, N_v = +u m22 / 2 (weathervane), N_r = -u m22 L / 4
    _, Yv, Nv = barge_hull_forces(no_drag, u, 1.0, 0.0)
    _, _, Nr = barge_hull_forces(no_drag, u, 0.0, 1.0)
    assert (Yv, Nv, Nr) == pytest.approx((-u * m_t, u * m_t * 25.0, -u * m_t * 50.0**2 / 4), rel=1e-13)
    # going astern the bow is the trailing edge: the hull is mirrored fore-aft
    _, Ya, Na = barge_hull_forces(no_drag, -u, v, r)
    assert Ya == pytest.approx(-u * m_t * (v + 25.0 * r), rel=1e-13) and Na == pytest.approx(25.0 * Ya, rel=1e-13)
    # lift grows with the speed and vanishes at rest, and hull_lift scales it (0 removes it)
    assert barge_hull_forces(no_drag, 0.0, v, r)[1:] == (0.0, 0.0)
    half = barge_hull_forces(no_drag.replace(hull_lift=0.5), u, v, r)
    assert half[1:] == pytest.approx((0.5 * Y, 0.5 * N), rel=1e-13)
    assert barge_hull_forces(no_drag.replace(hull_lift=0.0), u, v, r)[1:] == (0.0, 0.0)


def test_hull_lift_does_no_work_against_the_motion(barge):
    # The lift dissipates: its power Y v + N r = -|u| m'_T (v + r x_T)^2 <= 0 for any motion.
    rng = np.random.default_rng(7)
    u, v, r = rng.normal(0, 1.5, 200), rng.normal(0, 0.4, 200), rng.normal(0, 0.03, 200)
    _, Y, N = barge_hull_forces(barge.replace(cross_flow_drag=0.0), u, v, r)
    assert np.all(Y * v + N * r <= 1e-12 * (np.abs(Y * v) + np.abs(N * r)))


def test_pure_yaw_moment_converges_at_second_order(barge):
    r = 0.02
    exact = -RHO * 1.0 * 0.5 * abs(r) * r * 50.0**4 / 64  # -1/2 rho C_y T |r| r 2 (L/2)^4 / 4
    assert _cross_flow_exact(barge, 0.0, r)[1] == pytest.approx(exact, rel=1e-14)
    errors = []
    for n in (10, 20, 40, 80):
        _, Y, N = barge_hull_forces(barge, 0.0, 0.0, r, n_strips=n)
        assert Y == pytest.approx(0.0, abs=1e-12 * abs(exact) / 50.0)  # odd integrand, symmetric strips
        errors.append(abs(N - exact))
    # Midpoint rule on x^2 |x|: error exactly proportional to h^2 on each half; order 2 to round-off.
    np.testing.assert_allclose(np.log2(np.array(errors[:-1]) / errors[1:]), 2.0, atol=1e-6)
    # Midpoint error on each half, int_0^a x^3 dx with strips h: h^2/24 * int f'' = h^2 a^2 / 8, relative
    # h^2 / (2 a^2); the default 20 strips (h/a = 0.1) under-predict the yaw damping by exactly 0.5 %.
    assert errors[1] / abs(exact) == pytest.approx(0.005, rel=1e-9)


@pytest.mark.parametrize("v, r", [(0.2, 0.013), (-0.1, 0.03), (0.3, -0.005)])
def test_combined_sway_and_yaw_converge_to_closed_form(barge, v, r):
    Ye, Ne = _cross_flow_exact(barge, v, r)
    err = {}
    for n in (10, 160):
        _, Y, N = barge_hull_forces(barge, 0.0, v, r, n_strips=n)
        err[n] = (abs(Y - Ye) + 1e-300, abs(N - Ne))
    # Over a 16-fold refinement the observed order is 2 (the kink of |w| w where w changes sign
    # along the hull makes the step-to-step ratio wander between 1.7 and 2.6, the average does not).
    for k in range(2):
        if err[10][k] > 1e-9 * abs((Ye, Ne)[k]):
            assert math.log2(err[10][k] / err[160][k]) / 4 == pytest.approx(2.0, abs=0.15)
    _, Y, N = barge_hull_forces(barge, 0.0, v, r, n_strips=2000)
    # 2000 strips: relative error ~ (h/L)^2 = 2.5e-7 times an O(1) constant.
    assert Y == pytest.approx(Ye, rel=1e-5, abs=1e-5 * abs(Ne) / 50.0)
    assert N == pytest.approx(Ne, rel=1e-5)


def test_symmetries_of_hull_forces(barge):
    rng = np.random.default_rng(3)
    u, v, r = rng.normal(0, 1, 50), rng.normal(0, 0.3, 50), rng.normal(0, 0.02, 50)
    X, Y, N = barge_hull_forces(barge, u, v, r)
    Xm, _, _ = barge_hull_forces(barge, -u, v, r)
    _, Ym, Nm = barge_hull_forces(barge, u, -v, -r)
    # X odd in u; Y, N odd in (v, r) at a given u (|w| w and the lift are odd; the trailing edge is set
    # by the sign of u, so reversing u as well is not a symmetry): exact, the strip abscissae are the same.
    np.testing.assert_array_equal(Xm, -X)
    np.testing.assert_allclose(Ym, -Y, rtol=1e-13, atol=1e-9)
    np.testing.assert_allclose(Nm, -N, rtol=1e-13, atol=1e-7)
    # Fore-aft symmetric hull: (u, r) -> (-u, -r) mirrors x -> -x (the trailing edge too), Y even and
    # N odd (strips symmetric about 0).
    Xf, Yf, Nf = barge_hull_forces(barge, -u, v, -r)
    np.testing.assert_array_equal(Xf, -X)
    np.testing.assert_allclose(Yf, Y, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(Nf, -N, rtol=1e-12, atol=1e-7)
    # Y odd in v at r = 0 and N odd in r at v = 0, and both oppose the motion.
    _, Yv, _ = barge_hull_forces(barge, 0.0, v, 0.0)
    _, _, Nr = barge_hull_forces(barge, 0.0, 0.0, r)
    assert np.all(Yv * v < 0) and np.all(Nr * r < 0)
    # with the lift (u != 0) as well
    _, Yv, _ = barge_hull_forces(barge, u, v, 0.0)
    _, _, Nr = barge_hull_forces(barge, u, 0.0, r)
    assert np.all(Yv * v < 0) and np.all(Nr * r < 0)


# ------------------------------------------------------------------------------------------
# Equations of motion
# ------------------------------------------------------------------------------------------

def _rk4(f, y, dt, steps):
    for _ in range(steps):
        k1 = f(y)
        k2 = f(y + 0.5 * dt * k1)
        k3 = f(y + 0.5 * dt * k2)
        k4 = f(y + dt * k3)
        y = y + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return y


def test_kinetic_energy_conserved_without_loads(barge):
    ideal = barge.replace(surge_drag=0.0, cross_flow_drag=0.0, hull_lift=0.0)
    _, M11, M22, M66 = barge_mass(ideal)

    def rhs(y):
        return np.array(barge_equations(ideal, y[0], y[1], y[2], 0.0, 0.0, 0.0))

    def invariants(y):
        energy = 0.5 * (M11 * y[0] ** 2 + M22 * y[1] ** 2 + M66 * y[2] ** 2)
        impulse = (M11 * y[0]) ** 2 + (M22 * y[1]) ** 2  # |fluid + body impulse|, fixed in space
        return np.array([energy, impulse])

    y0 = np.array([1.0, 0.3, 0.02])
    y1 = _rk4(rhs, y0, 0.5, 400)  # 200 s: the Munk moment turns the barge broadside (unstable)
    # RK4's local error is O(dt^5); with the state changing on a ~20 s scale, dt = 0.5 s gives
    # ~1e-7 relative per step at most; both invariants hold to that, while the state changes by O(1).
    np.testing.assert_allclose(invariants(y1), invariants(y0), rtol=1e-6)
    assert np.abs(y1 - y0).max() > 0.1  # the motion is not trivial

    # The brief's printed yaw sign, M66 r' = +(m22 - m11) u v, pumps energy in: the test can fail.
    def wrong(y):
        du, dv, dr = barge_equations(ideal, y[0], y[1], y[2], 0.0, 0.0, 0.0)
        return np.array([du, dv, dr + 2 * (M22 - M11) * y[0] * y[1] / M66])

    y2 = _rk4(wrong, y0, 0.5, 400)
    assert abs(invariants(y2)[0] / invariants(y0)[0] - 1) > 1e-3


def test_equations_match_hand_evaluation(barge):
    u, v, r, Xe, Ye, Ne = 1.2, -0.15, 0.01, 5e3, -2e3, 4e4
    X, Y, N = barge_hull_forces(barge, u, v, r)
    _, M11, M22, M66 = barge_mass(barge)
    du, dv, dr = barge_equations(barge, u, v, r, Xe, Ye, Ne)
    # Same arithmetic in another order: round-off only.
    assert du == pytest.approx((X + Xe + M22 * v * r) / M11, rel=1e-13)
    assert dv == pytest.approx((Y + Ye - M11 * u * r) / M22, rel=1e-13)
    assert dr == pytest.approx((N + Ne - (M22 - M11) * u * v) / M66, rel=1e-13)


# ------------------------------------------------------------------------------------------
# Flat parameters and the compiled kernel
# ------------------------------------------------------------------------------------------

def test_parameter_layout(barge):
    p = barge_parameters(barge, RHO, n_strips=24)
    assert p.shape == (B_SIZE,) and p.dtype == np.float64
    np.testing.assert_array_equal(p[[B_MASS, B_M11, B_M22, B_M66]], barge_mass(barge, RHO))
    assert p[B_XUU] == 0.5 * RHO * 1.0 * 15.0 * 0.5 and p[B_YCF] == 0.5 * RHO * 1.0 * 0.5
    assert (p[B_LENGTH], p[B_BEAM], p[B_DRAFT]) == (50.0, 15.0, 0.5)
    assert (p[B_TOW_X], p[B_TOW_Z]) == (25.0, 1.0)  # bow, 1 m above the water by default
    assert (p[B_N_STRIPS], p[B_RHO], p[B_CX], p[B_CY]) == (24.0, RHO, 1.0, 1.0)
    assert p[B_LIFT] == pytest.approx(2.37 * 0.5 * RHO * math.pi * 0.25, rel=1e-15)  # m22 / L
    aft = barge_parameters(barge.replace(tow_point_x=-25.0, tow_point_height=2.0))
    assert (aft[B_TOW_X], aft[B_TOW_Z]) == (-25.0, 2.0)


@pytest.mark.parametrize("n_strips", [1, 20, 33])
def test_compiled_kernel_agrees_with_python(barge, n_strips):
    p = barge_parameters(barge, 1000.0, n_strips)
    rng = np.random.default_rng(n_strips)
    for u, v, r, Xe, Ye, Ne in zip(rng.normal(0, 1.5, 20), rng.normal(0, 0.4, 20), rng.normal(0, 0.03, 20),
                                   rng.normal(0, 1e4, 20), rng.normal(0, 1e4, 20), rng.normal(0, 1e5, 20)):
        # Same sums in the same order: agreement to a few ulps.
        np.testing.assert_allclose(barge_hull_forces_flat(p, u, v, r),
                                   barge_hull_forces(barge, u, v, r, 1000.0, n_strips), rtol=1e-12, atol=1e-9)
        np.testing.assert_allclose(barge_accelerations(p, u, v, r, Xe, Ye, Ne),
                                   barge_equations(barge, u, v, r, Xe, Ye, Ne, 1000.0, n_strips),
                                   rtol=1e-12, atol=1e-15)


def test_vectorised_over_states(barge):
    u = np.linspace(-1, 2, 7)[:, None]
    v = np.linspace(-0.3, 0.3, 5)[None, :]
    du, dv, dr = barge_equations(barge, u, v, 0.01, 0.0, 0.0, 0.0)
    assert du.shape == dv.shape == dr.shape == (7, 5)
    assert dr[2, 3] == pytest.approx(barge_equations(barge, u[2, 0], v[0, 3], 0.01, 0.0, 0.0, 0.0)[2], rel=1e-13)


# ------------------------------------------------------------------------------------------
# Input errors
# ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("key, value, expected", [
    ("draft", -0.5, "Barge.draft must be > 0 m, got -0.5 m. Suggested fix"),
    ("length", 0.0, "Barge.length must be > 0 m, got 0 m. Suggested fix"),
    ("beam", float("nan"), "Barge.beam must be a finite number"),
    ("block_coefficient", 1.2, "Barge.block_coefficient must be <= 1, got 1.2. Suggested fix"),
    ("block_coefficient", 0.0, "Barge.block_coefficient must be > 0, got 0. Suggested fix"),
    ("yaw_radius_of_gyration", -3.0, "Barge.yaw_radius_of_gyration must be > 0 m, got -3 m"),
    ("surge_drag", -1.0, "Barge.surge_drag must be >= 0, got -1"),
    ("sway_added_mass", -0.1, "Barge.sway_added_mass must be >= 0, got -0.1"),
])
def test_bad_barge_inputs(key, value, expected):
    with pytest.raises(InputError) as info:
        Barge(**{**PAPER003, key: value})
    assert expected in str(info.value)


def test_unknown_key_and_mapping_input(barge):
    with pytest.raises(InputError, match="Did you mean 'draft'"):
        Barge(**PAPER003, draught=0.5)
    assert barge_mass(dict(PAPER003)) == barge_mass(barge)  # a mapping is parsed
    with pytest.raises(InputError, match="barge.draft must be > 0 m"):
        barge_mass({**PAPER003, "draft": -1.0})
    with pytest.raises(InputError, match="barge must be a Barge, got float"):
        barge_mass(3.0)


def test_bad_function_arguments(barge):
    with pytest.raises(InputError, match="water_density must be > 0 kg/m\\^3, got -1025 kg/m\\^3"):
        barge_mass(barge, -1025.0)
    with pytest.raises(InputError, match="n_strips must be >= 1, got 0"):
        barge_hull_forces(barge, 1.0, 0.0, 0.0, n_strips=0)
    with pytest.raises(InputError, match="n_strips must be a whole number"):
        barge_parameters(barge, n_strips=2.5)
    with pytest.raises(InputError, match="r must be a finite number, got nan rad/s"):
        barge_hull_forces(barge, 1.0, 0.0, float("nan"))
    with pytest.raises(InputError, match="speed must be a finite number"):
        barge_resistance(barge, float("inf"))
    with pytest.raises(InputError, match="N_ext must be a finite number"):
        barge_equations(barge, 1.0, 0.0, 0.0, 0.0, 0.0, float("nan"))


def test_tow_point_outside_hull_warns():
    with pytest.warns(SeacableWarning, match="tow_point_x = 30 m lies outside the hull"):
        b = Barge(**PAPER003, tow_point_x=30.0)
    assert b.tow_x == 30.0

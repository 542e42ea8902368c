"""Unit tests of seacable.statics.towed: closed forms, global equilibrium and error paths."""

import numpy as np
import pytest
from scipy.optimize import brentq

from seacable.errors import InputError, NoSolutionError, SeacableWarning
from seacable.statics.towed import critical_angle, towed_cable_steady

RHO, W, D, U, CDN, CDT, L = 1025.0, 17.7, 0.035, 2.0, 1.5, 0.01, 170.0
EA = 4.4e8 * np.pi / 4 * D**2          # paper 000 Table 1: E = 4.4e8 N/m^2, solid section
QN = 0.5 * RHO * CDN * D * U**2         # normal drag scale [N/m]
QT = 0.5 * RHO * CDT * np.pi * D * U**2  # tangential drag scale [N/m]


def test_critical_angle_is_root_of_balance():
    # Independent root by bracketing; 1e-12 rad is the brentq tolerance, the closed form is exact.
    def f(phi):
        return W * np.cos(phi) - QN * np.sin(phi) ** 2
    ref = brentq(f, 0.0, np.pi / 2, xtol=1e-15)
    assert critical_angle(W, D, U, CDN, RHO) == pytest.approx(ref, abs=1e-12)


def test_critical_angle_vectorised_and_limits():
    speeds = np.array([0.0, 0.5, 2.0, 50.0])
    phi = critical_angle(W, D, speeds, CDN)
    assert phi.shape == (4,)
    assert phi[0] == pytest.approx(np.pi / 2, abs=1e-15)  # no flow: hangs vertically
    # High speed: w cos ~ q phi^2 -> phi ~ sqrt(w/q) (the laying theory's H/V); relative error
    # O(phi^2) ~ 1e-3 at 50 m/s, so 1e-3 is the expected size of the first neglected term.
    q = 0.5 * 1025.0 * CDN * D * 50.0**2
    assert phi[3] == pytest.approx(np.sqrt(W / q), rel=1e-3)
    assert np.all(np.diff(phi) < 0)  # faster tow -> flatter cable


def test_free_end_inextensible_is_straight_at_critical_angle():
    # Closed form: T = (w sin phi_c + D_t) s, straight line at phi_c; the integrator runs at
    # rtol 1e-10, so 1e-8 relative leaves two orders of margin.
    r = towed_cable_steady(L, W, D, U, CDN, CDT, n_points=11)
    phi_c = critical_angle(W, D, U, CDN, RHO)
    slope = W * np.sin(phi_c) + QT * np.cos(phi_c) ** 2
    np.testing.assert_allclose(r.tension, slope * r.s, rtol=1e-8, atol=1e-8)
    np.testing.assert_allclose(r.angle, phi_c, atol=1e-9)
    assert r.layback == pytest.approx(L * np.cos(phi_c), rel=1e-9)
    assert r.depth_of_lower_end == pytest.approx(L * np.sin(phi_c), rel=1e-9)
    assert r.x[-1] == 0.0 and r.z[-1] == 0.0  # top at the tow point
    assert r.top_angle == pytest.approx(phi_c, abs=1e-9)


def test_common_form_with_stretch_matches_closed_form():
    # "common" drag has no stretch factor, so the cable stays at phi_c; its stretched length is
    # L + a L^2 / (2 EA) with a = dT/ds. Closed form, tolerance as above.
    r = towed_cable_steady(L, W, D, U, CDN, CDT, axial_stiffness=EA, tangential_drag="common")
    phi_c = critical_angle(W, D, U, CDN, RHO)
    a = W * np.sin(phi_c) + QT * np.cos(phi_c) ** 2
    stretched = L + a * L**2 / (2 * EA)
    assert r.layback == pytest.approx(stretched * np.cos(phi_c), rel=1e-9)
    assert r.depth_of_lower_end == pytest.approx(stretched * np.sin(phi_c), rel=1e-9)


def test_paper000_form_satisfies_global_equilibrium():
    # Forces on the whole cable: ship pull + integrated weight and drag = 0 (free lower end).
    # Simpson's rule on 2001 points has error ~ 1e-12 here; 1e-7 relative to the top tension
    # covers it and the integrator tolerance.
    r = towed_cable_steady(L, W, D, U, CDN, CDT, axial_stiffness=EA, n_points=2001)
    from scipy.integrate import simpson
    f = np.sqrt(1 + r.tension / EA)
    dn = QN * np.sin(r.angle) ** 2 * f
    dt = QT * np.cos(r.angle) ** 2 * f
    fx = simpson(dn * np.sin(r.angle) + dt * np.cos(r.angle), x=r.s)
    fz = simpson(-W + dn * np.cos(r.angle) - dt * np.sin(r.angle), x=r.s)
    assert -r.top_tension * np.cos(r.top_angle) + fx == pytest.approx(0.0, abs=1e-7 * r.top_tension)
    assert r.top_tension * np.sin(r.top_angle) + fz == pytest.approx(0.0, abs=1e-7 * r.top_tension)
    # The stretch factor raises the drag, so the cable is flatter at the top than at the free end.
    assert r.top_angle < r.angle[0]


def test_diameter_form_is_one_over_pi_of_perimeter_form():
    # Inextensible: T_top = L (w sin phi_c + c * QT cos^2 phi_c), c = 1/pi for "diameter".
    r = towed_cable_steady(L, W, D, U, CDN, CDT, tangential_drag="diameter")
    phi_c = critical_angle(W, D, U, CDN, RHO)
    assert r.top_tension == pytest.approx(L * (W * np.sin(phi_c) + QT / np.pi * np.cos(phi_c) ** 2),
                                          rel=1e-9)


def test_body_on_dragless_cable_is_elastic_catenary():
    # Independent closed form: with C_dn = C_dt = 0 the cable is an elastic catenary with constant
    # horizontal tension H = body drag and vertical tension V = W_b + w s (Irvine 1981).
    cda, wb = 0.3, 800.0
    r = towed_cable_steady(L, W, D, U, 0.0, 0.0, axial_stiffness=EA, body_weight=wb, body_drag_area=cda)
    h = 0.5 * RHO * cda * U**2
    v0, vl = wb, wb + W * L
    layback = h / W * (np.arcsinh(vl / h) - np.arcsinh(v0 / h)) + h * L / EA
    depth = (np.hypot(h, vl) - np.hypot(h, v0)) / W + (v0 * L + W * L**2 / 2) / EA
    assert r.top_tension == pytest.approx(np.hypot(h, vl), rel=1e-9)
    assert r.layback == pytest.approx(layback, rel=1e-8)
    assert r.depth_of_lower_end == pytest.approx(depth, rel=1e-8)
    assert r.tension[0] == pytest.approx(np.hypot(h, v0), rel=1e-12)


def test_heavy_body_gives_near_vertical_cable():
    # Body weight 1e6 N >> cable forces: the cable is within eps ~ 0.02 rad of vertical. Then the
    # horizontal top force is D_body + q_n L and the vertical W_b + w L, up to O(eps^2) and
    # q_n eps L / W_b ~ 4e-4 relative terms; 2e-3 covers both.
    wb, cda = 1.0e6, 0.1
    r = towed_cable_steady(L, W, D, U, CDN, CDT, body_weight=wb, body_drag_area=cda)
    hx = r.top_tension * np.cos(r.top_angle)
    vz = r.top_tension * np.sin(r.top_angle)
    assert hx == pytest.approx(0.5 * RHO * cda * U**2 + QN * L, rel=2e-3)
    assert vz == pytest.approx(wb + W * L, rel=2e-3)
    assert r.depth_of_lower_end == pytest.approx(L, rel=1e-3)


def test_body_drag_force_equals_drag_area():
    cda = 0.25
    a = towed_cable_steady(L, W, D, U, CDN, body_weight=300.0, body_drag_area=cda)
    b = towed_cable_steady(L, W, D, U, CDN, body_weight=300.0, body_drag_force=0.5 * RHO * cda * U**2)
    np.testing.assert_allclose(a.tension, b.tension, rtol=1e-12)


def test_depressor_lift_deepens_the_cable():
    a = towed_cable_steady(L, W, D, U, CDN, body_weight=300.0, body_drag_area=0.1)
    b = towed_cable_steady(L, W, D, U, CDN, body_weight=300.0, body_drag_area=0.1, body_lift=-2000.0)
    assert b.depth_of_lower_end > a.depth_of_lower_end
    assert b.tension[0] == pytest.approx(np.hypot(0.5 * RHO * 0.1 * U**2, 2300.0), rel=1e-12)


def test_lifting_body_above_tow_point_warns():
    with pytest.warns(SeacableWarning, match="above the tow point"):
        towed_cable_steady(L, W, D, U, CDN, body_lift=3000.0)


def test_slack_cable_above_lifting_body_raises():
    with pytest.raises(NoSolutionError, match="tension vanishes"):
        towed_cable_steady(L, W, D, 0.0, CDN, body_lift=100.0)


@pytest.mark.parametrize("kwargs, match", [
    (dict(length=-3.0), "length must be > 0 m, got -3 m"),
    (dict(weight_per_length=-1.0), "weight_per_length must be > 0"),
    (dict(diameter=0.0), "diameter must be > 0"),
    (dict(speed=-1.0), "speed must be >= 0"),
    (dict(drag_normal=np.nan), "drag_normal must be a finite number"),
    (dict(drag_tangential=-0.1), "drag_tangential must be >= 0"),
    (dict(axial_stiffness=0.0), "axial_stiffness must be > 0"),
    (dict(body_drag_area=-1.0), "body_drag_area must be >= 0"),
    (dict(body_drag_force=-1.0), "body_drag_force must be >= 0"),
    (dict(body_weight=np.inf), "body_weight must be a finite number"),
    (dict(body_lift=np.nan), "body_lift must be a finite number"),
    (dict(n_points=1), "n_points must be >= 2"),
    (dict(rtol=1.0), "rtol must be in"),
    (dict(tangential_drag="paper00"), "did you mean 'paper000'"),
    (dict(length=[1.0, 2.0]), "must be a scalar"),
])
def test_bad_inputs_raise(kwargs, match):
    args = dict(length=L, weight_per_length=W, diameter=D, speed=U, drag_normal=CDN)
    args.update(kwargs)
    with pytest.raises(InputError, match=match):
        towed_cable_steady(**args)


@pytest.mark.parametrize("kwargs, match", [
    (dict(weight_per_length=0.0), "weight_per_length must be > 0"),
    (dict(diameter=-0.1), "diameter must be > 0"),
    (dict(speed=[1.0, -1.0]), r"speed\[1\] must be >= 0"),
    (dict(drag_normal=-1.0), "drag_normal must be >= 0"),
    (dict(water_density=0.0), "water_density must be > 0"),
])
def test_critical_angle_bad_inputs_raise(kwargs, match):
    args = dict(weight_per_length=W, diameter=D, speed=U, drag_normal=CDN)
    args.update(kwargs)
    with pytest.raises(InputError, match=match):
        critical_angle(**args)

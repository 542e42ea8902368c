"""Unit tests of seacable.statics.laying: closed forms, derivations and error paths."""

import numpy as np
import pytest
from scipy.optimize import brentq

from seacable.errors import InputError, NoSolutionError, SeacableWarning
from seacable.statics.laying import (cable_slack, hydrodynamic_constant, laying_angle,
                                     straight_line_lay)
from seacable.statics.towed import critical_angle

W, D, CD, RHO = 4.49, 0.0225, 1.85, 1030.0   # paper 001 section 4.1 cable


def test_hydrodynamic_constant_formula():
    assert hydrodynamic_constant(W, D, CD, RHO) == pytest.approx(np.sqrt(2 * W / (CD * RHO * D)), rel=1e-15)
    h = hydrodynamic_constant([W, 4 * W], D, CD, RHO)
    assert h[1] / h[0] == pytest.approx(2.0, rel=1e-15)   # H scales with sqrt(w)


def test_exact_angle_is_root_and_equals_towed_critical_angle():
    # Independent root by bracketing; closed form exact, 1e-12 rad is the brentq tolerance.
    for vs in (0.3, 1.0, 4.0):
        q = 0.5 * CD * RHO * D * vs**2
        ref = brentq(lambda a: W * np.cos(a) - q * np.sin(a) ** 2, 0.0, np.pi / 2, xtol=1e-15)
        assert laying_angle(vs, W, D, CD, RHO) == pytest.approx(ref, abs=1e-12)
        assert laying_angle(vs, W, D, CD, RHO) == critical_angle(W, D, vs, CD, RHO)


def test_small_angle_error_is_second_order():
    # Series of w cos(a) = q sin^2(a) with a0^2 = w/q: cos(a)/sin^2(a) = 1/a^2 - 1/6 + O(a^2), so
    # 1/a^2 = 1/a0^2 + 1/6 and a = a0 (1 - a0^2/12 + O(a0^4)). The relative error divided by
    # a0^2 therefore tends to 1/12; at a0 ~ 0.02 rad the O(a0^2) remainder is ~1e-3 relative, so
    # 2 % is ample and still fails for any other order or coefficient.
    vs = np.array([20.0, 40.0])
    a0 = laying_angle(vs, W, D, CD, RHO, method="small_angle")
    a = laying_angle(vs, W, D, CD, RHO)
    k = (a0 - a) / a0 / a0**2
    assert k[0] == pytest.approx(k[1], rel=2e-2)
    assert k[1] == pytest.approx(1.0 / 12.0, rel=2e-2)


def test_zero_speed_exact_is_vertical():
    assert laying_angle(0.0, W, D, CD, RHO) == pytest.approx(np.pi / 2, abs=1e-15)


def test_small_angle_warns_above_30_degrees():
    with pytest.warns(SeacableWarning, match="exceeds 30 deg"):
        laying_angle(0.5, W, D, CD, RHO, method="small_angle")


def test_broadcasting():
    a = laying_angle(np.array([[1.0], [2.0]]), np.array([W, 2 * W, 3 * W]), D, CD, RHO)
    assert a.shape == (2, 3)
    r = straight_line_lay(np.array([50.0, 100.0, 200.0]), 2.0, W, D, CD, water_density=RHO)
    assert r.top_tension.shape == (3,)
    np.testing.assert_allclose(r.top_tension, W * np.array([50.0, 100.0, 200.0]), rtol=1e-14)


def test_geometry_and_tension_closed_forms():
    h, vs, t0 = 120.0, 1.5, 300.0
    r = straight_line_lay(h, vs, W, D, CD, water_density=RHO, bottom_tension=t0)
    a = laying_angle(vs, W, D, CD, RHO)
    assert r.angle == a
    assert r.suspended_length == pytest.approx(h / np.sin(a), rel=1e-14)
    assert r.layback == pytest.approx(h / np.tan(a), rel=1e-14)
    assert r.top_tension == pytest.approx(t0 + W * h, rel=1e-14)   # eq. (11)
    assert r.slack == 0.0 and r.tangential_drag == 0.0


def test_tangential_drag_with_payout():
    # Derived in the module docstring: V_f = V_c - V_s cos(alpha), D_T = 1/2 C_f rho pi d V_f|V_f|,
    # T_s = T_0 + w h - D_T h / sin(alpha). Closed form, machine precision.
    h, vs, vc, cf = 50.0, 2.0, 2.2, 0.01
    r = straight_line_lay(h, vs, W, D, CD, cf, payout_speed=vc, water_density=RHO)
    a = laying_angle(vs, W, D, CD, RHO)
    vf = vc - vs * np.cos(a)
    dt = 0.5 * cf * RHO * np.pi * D * vf * abs(vf)
    assert r.relative_tangential_speed == pytest.approx(vf, rel=1e-14)
    assert r.tangential_drag == pytest.approx(dt, rel=1e-14)
    assert r.top_tension == pytest.approx(W * h - dt * h / np.sin(a), rel=1e-14)
    assert r.slack == pytest.approx(0.1, rel=1e-12)
    # Payout slower than V_s cos(alpha): the cable is dragged back, tension rises above w h.
    r2 = straight_line_lay(h, vs, W, D, CD, cf, payout_speed=1.5, water_density=RHO)
    assert r2.top_tension > W * h


def test_payout_default_is_ship_speed():
    r = straight_line_lay(50.0, 2.0, W, D, CD, 0.01, water_density=RHO)
    assert r.slack == 0.0
    assert r.relative_tangential_speed == pytest.approx(2.0 * (1 - np.cos(r.angle)), rel=1e-14)


def test_cable_slack():
    np.testing.assert_allclose(cable_slack([1.0, 1.1], 1.0), [0.0, 0.1], atol=1e-15)


def test_excessive_payout_raises():
    with pytest.raises(NoSolutionError, match="tangential drag"):
        straight_line_lay(50.0, 2.0, W, D, CD, 0.01, payout_speed=20.0, water_density=RHO)


def test_small_angle_beyond_90_degrees_raises():
    with pytest.warns(SeacableWarning), pytest.raises(NoSolutionError, match="not below 90 deg"):
        straight_line_lay(50.0, 0.025, W, D, CD, water_density=RHO, method="small_angle")


@pytest.mark.parametrize("call, match", [
    (lambda: hydrodynamic_constant(-W, D, CD), "weight_per_length must be > 0 N/m, got -4.49 N/m"),
    (lambda: hydrodynamic_constant(W, 0.0, CD), "diameter must be > 0 m"),
    (lambda: hydrodynamic_constant(W, D, 0.0), "drag_normal must be > 0"),
    (lambda: hydrodynamic_constant(W, D, CD, -1.0), "water_density must be > 0"),
    (lambda: laying_angle(-1.0, W, D, CD), "ship_speed must be >= 0"),
    (lambda: laying_angle(0.0, W, D, CD, method="small_angle"), "ship_speed must be > 0"),
    (lambda: laying_angle(1.0, W, D, CD, method="exakt"), "did you mean 'exact'"),
    (lambda: laying_angle(1.0, [W, np.nan], D, CD), r"weight_per_length\[1\] must be a finite"),
    (lambda: straight_line_lay(-50.0, 2.0, W, D, CD), "water_depth must be > 0 m"),
    (lambda: straight_line_lay(50.0, 0.0, W, D, CD), "ship_speed must be > 0"),
    (lambda: straight_line_lay(50.0, 2.0, W, D, CD, -0.1), "drag_tangential must be >= 0"),
    (lambda: straight_line_lay(50.0, 2.0, W, D, CD, payout_speed=-1.0), "payout_speed must be >= 0"),
    (lambda: straight_line_lay(50.0, 2.0, W, D, CD, bottom_tension=-5.0), "bottom_tension must be >= 0"),
    (lambda: cable_slack(1.0, 0.0), "ship_speed must be > 0"),
    (lambda: cable_slack(-1.0, 1.0), "payout_speed must be >= 0"),
])
def test_bad_inputs_raise(call, match):
    with pytest.raises(InputError, match=match):
        call()

"""Airy wave kinematics (seacable.waves) against closed forms of linear wave theory.

Dispersion: deep- and shallow-water limits (with the shallow-water series of x tanh x = y), the
residual of omega^2 = g k tanh(k d), and an independent bracketing root finder. Field: Laplace's
equation (divergence-free, irrotational) and the local acceleration by finite differences of the
compiled kernel, the kinematic free-surface and bottom conditions, rotation by the heading, the
deep-water exponential decay, and the treatment above the still-water level.
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from seacable import waves
from seacable.errors import ConvergenceError, InputError, SeacableWarning
from seacable.waves import WaveKinematics, airy_kinematics, airy_kinematics_array, wave_number

G = 9.80665


def _kin(x, y, z, t, H=2.0, T=10.0, d=50.0, b=0.0, p=0.0):
    k = wave_number(T, d, G)
    return np.array(airy_kinematics(x, y, z, t, H, T, k, d, b, p, G))


# ----------------------------------------------------------------------------- dispersion
def test_deep_water_limit():
    # k d = 4.0 * 1000 >> 10: tanh(kd) = 1 to 1e-3000, so k = omega^2/g to rounding (1e-14).
    omega = 2 * math.pi / 4.0
    assert wave_number(4.0, 1000.0) == pytest.approx(omega**2 / G, rel=1e-14)
    assert wave_number(4.0, 1000.0) * 1000.0 > 10.0
    # None and inf are deep water by definition: exactly omega^2/g.
    assert wave_number(4.0, None) == omega**2 / G
    assert wave_number(4.0, np.inf) == omega**2 / G
    # k d = 1e6: Newton must not overflow (sech^2 in exponential form) and stay at the deep value.
    assert wave_number(1.0, 1e6) == pytest.approx((2 * math.pi) ** 2 / G, rel=1e-14)


def test_shallow_water_limit_and_series():
    # T = 100 s, d = 5 m: k d = 0.045 < 0.05. Leading order k = omega/sqrt(g d) with relative error
    # (k d)^2/6 = 3.4e-4; the series of x tanh x = y (x = k d, y = omega^2 d/g) inverted gives
    # k/k_sw = 1 + y/6 + 11 y^2/360 + O(y^3), so the tolerance y^3 = 8e-9 (coefficient < 1).
    T, d = 100.0, 5.0
    omega = 2 * math.pi / T
    k = wave_number(T, d)
    k_sw = omega / math.sqrt(G * d)
    y = omega**2 * d / G
    assert k * d < 0.05
    assert abs(k / k_sw - 1) < (k * d) ** 2 / 6 * 1.01      # limit, error of the stated order
    assert abs(k / k_sw - (1 + y / 6 + 11 * y**2 / 360)) < y**3


@pytest.mark.parametrize("T, d", [(10.0, 50.0), (3.0, 2.0), (15.0, 300.0), (0.5, 0.01)])
def test_dispersion_residual_and_independent_root(T, d):
    # omega^2 = g k tanh(k d) to 1e-12 relative, as required; and brentq (bracketing, tolerance
    # 1e-15 relative) gives the same root to 1e-12.
    omega = 2 * math.pi / T
    k = wave_number(T, d)
    assert abs(G * k * math.tanh(k * d) - omega**2) <= 1e-12 * omega**2
    ref = brentq(lambda kk: G * kk * math.tanh(kk * d) - omega**2, 1e-8, 1e4, xtol=1e-300, rtol=1e-15)
    assert k == pytest.approx(ref, rel=1e-12)


def test_dispersion_residual_over_all_depth_regimes():
    # omega^2 d/g from 1e-6 (very shallow) to 1e3 (deep), one vectorised call: every element's
    # relative residual of omega^2 = g k tanh(k d) below the required 1e-12.
    d = 10.0
    y = np.logspace(-6, 3, 2001)
    T = 2 * np.pi / np.sqrt(y * G / d)
    k = wave_number(T, d)
    omega = 2 * np.pi / T
    assert np.max(np.abs(G * k * np.tanh(k * d) / omega**2 - 1)) < 1e-12


def test_wave_number_vectorised():
    T = np.array([[4.0], [10.0]])
    d = np.array([5.0, 50.0, np.inf])
    k = wave_number(T, d)
    assert k.shape == (2, 3)
    for i in range(2):
        for j in range(3):
            assert k[i, j] == wave_number(float(T[i, 0]), float(d[j]))   # same algorithm elementwise


# ----------------------------------------------------------------------------- the field
# (x, y, z, t), all below the trough (H/2 = 1 m) so the linear field applies
POINTS = [(3.0, -7.0, -10.0, 1.3), (40.0, 12.0, -45.0, 7.9), (-20.0, 5.0, -1.5, 4.2)]


@pytest.mark.parametrize("x, y, z, t", POINTS)
def test_divergence_free_and_irrotational(x, y, z, t):
    # Central differences with h = 1e-3 m: truncation (k h)^2/6 ~ 3e-10 relative, rounding
    # eps*U/h ~ 1e-13; tolerance 1e-7 of the gradient scale k*U.
    b, h = 0.7, 1e-3
    def vel(xx, yy, zz):
        return _kin(xx, yy, zz, t, b=b)[:3]
    dx = (vel(x + h, y, z) - vel(x - h, y, z)) / (2 * h)
    dy = (vel(x, y + h, z) - vel(x, y - h, z)) / (2 * h)
    dz = (vel(x, y, z + h) - vel(x, y, z - h)) / (2 * h)
    k = wave_number(10.0, 50.0)
    scale = k * (2 * math.pi / 10.0) * 1.0 / math.tanh(k * 50.0)   # k * omega H/2 coth(kd), the surface gradient
    div = dx[0] + dy[1] + dz[2]
    curl = np.array([dy[2] - dz[1], dz[0] - dx[2], dx[1] - dy[0]])
    assert abs(div) < 1e-7 * scale
    assert np.abs(curl).max() < 1e-7 * scale
    assert np.abs(dz).max() > 1e-3 * scale            # the field is not trivially constant


@pytest.mark.parametrize("x, y, z, t", POINTS)
def test_acceleration_is_local_time_derivative(x, y, z, t):
    # Central difference in time, h = 1e-4 s: truncation (omega h)^2/6 ~ 7e-11; tolerance 1e-8 of omega*U.
    h = 1e-4
    dudt = (_kin(x, y, z, t + h, b=0.4)[:3] - _kin(x, y, z, t - h, b=0.4)[:3]) / (2 * h)
    acc = _kin(x, y, z, t, b=0.4)[3:6]
    scale = (2 * math.pi / 10.0) ** 2 * 2.0 / 2 * 1.2      # omega^2 H/2 coth(kd) (kd = 2.08: coth = 1.03)
    assert np.allclose(acc, dudt, rtol=0, atol=1e-8 * scale)


@pytest.mark.parametrize("d", [5.0, 50.0, 5000.0, np.inf])
def test_kinematic_free_surface_condition(d):
    # Linearised kinematic condition d(eta)/dt = w at z = 0 (exact for Airy theory when k obeys the
    # dispersion relation, so the tolerance is rounding plus the (omega h)^2/6 = 7e-11 of the
    # central difference). Covers the cosh branch (d = 5, 50) and the exponential one (5000, inf).
    T, H, h = 10.0, 1.0, 1e-4
    k = wave_number(T, d)
    x, y, t = 13.0, -4.0, 2.7
    w = airy_kinematics(x, y, 0.0, t, H, T, k, d, 0.3, 0.2, G)[2]
    eta = [airy_kinematics(x, y, -1.0, tt, H, T, k, d, 0.3, 0.2, G)[6] for tt in (t + h, t - h)]
    detadt = (eta[0] - eta[1]) / (2 * h)
    omega = 2 * math.pi / T
    assert w == pytest.approx(detadt, abs=1e-9 * omega * H)
    # also the closed form: w(z=0) = omega H/2 sin(theta)
    theta = k * (x * math.cos(0.3) + y * math.sin(0.3)) - omega * t + 0.2
    assert w == pytest.approx(omega * H / 2 * math.sin(theta), rel=1e-12)


def test_bottom_condition():
    # w = 0 at z = -d exactly (sinh(0) = 0); the horizontal velocity there is omega H/2 / sinh(kd).
    T, H, d = 8.0, 2.0, 20.0
    k = wave_number(T, d)
    for t in np.linspace(0.0, T, 7):
        r = airy_kinematics(5.0, 1.0, -d, t, H, T, k, d, 0.0, 0.0, G)
        assert r[2] == 0.0 and r[5] == 0.0
    theta = k * 5.0
    assert airy_kinematics(5.0, 1.0, -d, 0.0, H, T, k, d, 0.0, 0.0, G)[0] == pytest.approx(
        2 * math.pi / T * H / 2 / math.sinh(k * d) * math.cos(theta), rel=1e-12)
    # below the seabed (a node pressed into it): the seabed values
    assert np.array_equal(_kin(5.0, 1.0, -50.3, 2.0), _kin(5.0, 1.0, -50.0, 2.0))


def test_deep_water_exponential_decay_and_branch_switch():
    # Deep water: |velocity| = omega H/2 e^{kz} on circles (rel 1e-13, rounding).
    T, H = 6.0, 1.5
    k = wave_number(T, None)
    omega = 2 * math.pi / T
    for z in (-1.0, -3.0, -30.0):                # below the trough (H/2 = 0.75 m)
        for t in (0.0, 1.1, 2.9):
            r = airy_kinematics(2.0, 3.0, z, t, H, T, k, np.inf, 1.0, 0.0, G)
            assert math.hypot(r[0], r[1], r[2]) == pytest.approx(omega * H / 2 * math.exp(k * z), rel=1e-13)
            assert math.hypot(r[3], r[4], r[5]) == pytest.approx(omega**2 * H / 2 * math.exp(k * z), rel=1e-13)
    # k d = 25 uses the exponential form; compare to the plain cosh/sinh formula (no overflow at 25).
    d = 25.0 / k
    for z in (-0.5, -0.9 * d, -d):
        r = airy_kinematics(0.0, 0.0, z, 0.0, H, T, k, d, 0.0, 0.0, G)
        a = G * k * H / (2 * omega)
        assert r[0] == pytest.approx(a * math.cosh(k * (z + d)) / math.cosh(k * d), rel=1e-12)
        assert r[5] == pytest.approx(-a * omega * math.sinh(k * (z + d)) / math.cosh(k * d), rel=1e-12, abs=1e-300)


def test_heading_rotates_the_field():
    # A wave heading b seen at R(b) p equals R(b) applied to the heading-0 wave seen at p (exact, rounding).
    b = 1.1
    R = np.array([[math.cos(b), -math.sin(b), 0], [math.sin(b), math.cos(b), 0], [0, 0, 1]])
    for p in [(10.0, 3.0, -4.0), (-7.0, 20.0, -30.0)]:
        q = R @ np.array(p)
        r0 = _kin(*p, 3.3, b=0.0)
        rb = _kin(*q, 3.3, b=b)
        assert np.allclose(rb[:3], R @ r0[:3], rtol=0, atol=1e-12)
        assert np.allclose(rb[3:6], R @ r0[3:6], rtol=0, atol=1e-12)
        assert rb[6] == pytest.approx(r0[6], abs=1e-12)
    # and the horizontal velocity points along the heading at a crest
    k = wave_number(10.0, 50.0)
    r = airy_kinematics(0.0, 0.0, -2.0, 0.0, 2.0, 10.0, k, 50.0, b, 0.0, G)
    assert math.atan2(r[1], r[0]) == pytest.approx(b, abs=1e-12)


def test_above_still_water_level():
    # t = 0, x = 0: crest (eta = H/2 = 1 m). Between 0 and eta: the z = 0 values; above eta: zero.
    r0 = _kin(0.0, 0.0, 0.0, 0.0)
    assert r0[6] == 1.0
    assert np.array_equal(_kin(0.0, 0.0, 0.7, 0.0), r0)
    assert np.array_equal(_kin(0.0, 0.0, 1.2, 0.0)[:6], np.zeros(6))
    # under a trough (eta = -1 m) a point at z = -0.5 m is in the air: zero kinematics
    T = 10.0
    assert np.array_equal(_kin(0.0, 0.0, -0.5, T / 2)[:6], np.zeros(6))
    assert _kin(0.0, 0.0, -0.5, T / 2)[6] == pytest.approx(-1.0, rel=1e-14)
    # zero height: calm water
    assert np.array_equal(_kin(3.0, 0.0, -2.0, 1.0, H=0.0), np.zeros(7))


# ----------------------------------------------------------------------------- the array wrapper
def test_array_wrapper_broadcasts_and_matches_kernel():
    x = np.linspace(0.0, 100.0, 5)[:, None]
    z = np.array([-40.0, -10.0, -1.0, 0.5])[None, :]
    res = airy_kinematics_array(x, 2.0, z, 3.0, height=2.0, period=10.0, depth=50.0, heading=0.2, phase=0.1)
    assert isinstance(res, WaveKinematics)
    assert res.velocity.shape == (5, 4, 3) and res.acceleration.shape == (5, 4, 3)
    assert res.elevation.shape == (5, 4)
    assert res.wavelength == pytest.approx(2 * math.pi / wave_number(10.0, 50.0), rel=1e-15)
    k = wave_number(10.0, 50.0)
    for i in range(5):
        for j in range(4):
            r = airy_kinematics(x[i, 0], 2.0, z[0, j], 3.0, 2.0, 10.0, k, 50.0, 0.2, 0.1, G)
            assert np.array_equal(res.velocity[i, j], r[:3])
            assert np.array_equal(res.acceleration[i, j], r[3:6])
            assert res.elevation[i, j] == r[6]
    deep = airy_kinematics_array(0.0, 0.0, -1.0, 0.0, height=1.0, period=5.0, depth=None)
    assert deep.wave_number == wave_number(5.0)


def test_warns_breaking_wave():
    # T = 5 s deep water: L = 39.0 m, H = 6 m gives H/L = 0.154 > 1/7 = 0.143.
    with pytest.warns(SeacableWarning, match=r"H/L = 0\.15.* breaking limit 0\.1429"):
        airy_kinematics_array(0.0, 0.0, -1.0, 0.0, height=6.0, period=5.0, depth=None)
    # Miche in finite depth: T = 6 s, d = 10 m, L = 48.39 m, limit tanh(kd)/7 = 0.1230; H = 6.2 m gives
    # H/L = 0.1281: below 1/7 but breaking in this depth (Ursell 14.5 < 26, so only this warning).
    with pytest.warns(SeacableWarning, match=r"H/L = 0\.1281 exceeds the breaking limit 0\.123 \(Miche"):
        airy_kinematics_array(0.0, 0.0, -1.0, 0.0, height=6.2, period=6.0, depth=10.0)


def test_warns_shallow_water_ursell():
    # T = 20 s, d = 10 m: L = 194.7 m; H = 1 m gives Ur = 1 * 194.7^2 / 10^3 = 37.92 > 26.
    with pytest.warns(SeacableWarning, match=r"Ursell number H L\^2/d\^3 = 37\.92 exceeds 26"):
        airy_kinematics_array(0.0, 0.0, -1.0, 0.0, height=1.0, period=20.0, depth=10.0)


def test_no_warning_for_an_ordinary_wave():
    # H = 2 m, T = 10 s, d = 50 m: H/L = 0.013, Ur = 2 * 151^2 / 50^3 = 0.37. pytest turns any
    # SeacableWarning into an error (pyproject filterwarnings), so this fails if one is raised.
    airy_kinematics_array(0.0, 0.0, -1.0, 0.0, height=2.0, period=10.0, depth=50.0)


# ----------------------------------------------------------------------------- errors
@pytest.mark.parametrize("kwargs, match", [
    ({"period": -3.0, "depth": 50.0}, r"period must be > 0 s, got -3 s\. Suggested fix"),
    ({"period": 0.0, "depth": 50.0}, r"period must be > 0 s, got 0 s"),
    ({"period": 10.0, "depth": 0.0}, r"depth must be > 0 m, got 0 m\. Suggested fix: .*deep water"),
    ({"period": 10.0, "depth": np.nan}, r"depth must be a finite number, got nan m"),
    ({"period": 10.0, "depth": -np.inf}, r"depth must be a finite number, got -inf m"),
    ({"period": [10.0, -1.0], "depth": 50.0}, r"period\[1\] must be > 0 s, got -1 s"),
    ({"period": 10.0, "depth": [50.0, np.inf, -2.0]}, r"depth\[2\] must be > 0 m, got -2 m"),
    ({"period": 10.0, "depth": 50.0, "gravity": -9.8}, r"gravity must be > 0 m/s\^2"),
    ({"period": "ten", "depth": 50.0}, r"period must be a number in s"),
])
def test_wave_number_errors(kwargs, match):
    with pytest.raises(InputError, match=match):
        wave_number(**kwargs)


@pytest.mark.parametrize("kwargs, match", [
    ({"height": -1.0, "period": 10.0, "depth": 50.0}, r"height must be >= 0 m, got -1 m\. Suggested fix"),
    ({"height": 1.0, "period": 0.0, "depth": 50.0}, r"period must be > 0 s, got 0 s"),
    ({"height": 1.0, "period": 10.0, "depth": -5.0}, r"depth must be > 0 m, got -5 m"),
    ({"height": 1.0, "period": 10.0, "depth": 50.0, "gravity": 0.0}, r"gravity must be > 0 m/s\^2"),
    ({"height": 1.0, "period": 10.0, "depth": 50.0, "heading": np.nan}, r"heading must be a finite number"),
    ({"height": [1.0, 2.0], "period": 10.0, "depth": 50.0}, r"height must be a single number in m"),
])
def test_array_wrapper_errors(kwargs, match):
    with pytest.raises(InputError, match=match):
        airy_kinematics_array(0.0, 0.0, -1.0, 0.0, **kwargs)


def test_array_wrapper_rejects_nonfinite_points():
    with pytest.raises(InputError, match=r"z\[1\] must be a finite number, got nan m"):
        airy_kinematics_array(0.0, 0.0, [-1.0, np.nan], 0.0, height=1.0, period=10.0, depth=50.0)
    with pytest.raises(InputError, match=r"t must be a finite number, got inf s"):
        airy_kinematics_array(0.0, 0.0, -1.0, np.inf, height=1.0, period=10.0, depth=50.0)


def test_heading_in_degrees_warns():
    with pytest.warns(SeacableWarning, match=r"heading = 45 rad looks like degrees \(0\.7854 rad"):
        airy_kinematics_array(0.0, 0.0, -1.0, 0.0, height=1.0, period=10.0, depth=50.0, heading=45.0)


def test_wave_number_convergence_error(monkeypatch):
    # One Newton step from the Fenton-McKee start (1.5 % off) cannot reach a 1e-14 relative step,
    # so the documented ConvergenceError path is exercised with its iteration count and residual.
    monkeypatch.setattr(waves, "_MAX_NEWTON", 1)
    with pytest.raises(ConvergenceError, match=r"did not converge in 1 iterations") as info:
        wave_number(10.0, 50.0)
    assert info.value.iterations == 1 and info.value.residual > 1e-14

"""Zig-zag vessel path (seacable.towed.vessel.ZigZagPath): closed form, derivative, errors.

Paper 003 (shared/seeds/003_dc854471ee8794a0.txt, slides 17-18): the tug advances at
2 knots (1.0289 m/s) while swaying sinusoidally in Y with 10 m amplitude and a 50 s period.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.errors import InputError, SeacableWarning
from seacable.towed.vessel import VESSEL_PATHS, ZigZagPath, parse_vessel_path, sample_path

KNOT = 1852.0 / 3600.0  # [m/s]
PAPER003 = {"speed": 2 * KNOT, "amplitude": 10.0, "period": 50.0}


def _central_difference(path, t, h):
    plus, _ = sample_path(path, t + h)
    minus, _ = sample_path(path, t - h)
    return (plus - minus) / (2 * h)


def test_paper003_case_sway_amplitude_and_period():
    path = ZigZagPath(**PAPER003)
    assert path.speed == pytest.approx(1.0289, abs=5e-5)  # 2 knots as printed in the brief
    t = np.linspace(0.0, 200.0, 8001)  # 0.025 s spacing: the crest is sampled exactly at 12.5 s + k 50 s
    pos, vel = sample_path(path, t)
    # Heading 0: x is the straight run, y the sway; closed form against closed form: round-off only.
    np.testing.assert_allclose(pos[:, 0], path.speed * t, rtol=0, atol=1e-12)
    np.testing.assert_allclose(vel[:, 0], path.speed, rtol=0, atol=1e-15)
    assert pos[:, 1].max() == pytest.approx(10.0, abs=1e-12)
    assert pos[:, 1].min() == pytest.approx(-10.0, abs=1e-12)
    # Period: the sway repeats after 50 s and upward zero crossings are 50 s apart.
    np.testing.assert_allclose(pos[2000:, 1], pos[:-2000, 1], atol=1e-12)
    up = np.flatnonzero((pos[:-1, 1] < 0) & (pos[1:, 1] >= 0))
    np.testing.assert_allclose(np.diff(t[up]), 50.0, atol=0.025)  # one sample spacing
    # Peak sway speed 2 pi A / T = 1.2566 m/s at the crossings of the course line.
    assert np.abs(vel[:, 1]).max() == pytest.approx(2 * math.pi * 10.0 / 50.0, rel=1e-12)
    assert np.all(pos[:, 2] == 0.0) and np.all(vel[:, 2] == 0.0)


@pytest.mark.parametrize("ramp", [0.0, 30.0])
def test_velocity_is_derivative_of_position(ramp):
    path = ZigZagPath(speed=1.5, amplitude=7.0, period=40.0, phase=0.3, ramp=ramp, heading=0.7,
                      start=(3.0, -2.0))
    # Interior times, away from the ramp's end where the second derivative jumps.
    t = np.array([1.0, 5.3, 12.0, 29.0, 31.0, 47.7, 95.2])
    h = 1e-3
    _, vel = sample_path(path, t)
    # Central-difference truncation error <= h^2/6 * max|x'''|; the sway's third derivative is at most
    # A (w + pi/T_r)^3 ~ 7 * 0.26^3 = 0.12 m/s^3, so 2e-8 m/s; round-off 1e-16 * 1e2 m / 1e-3 s = 1e-11.
    np.testing.assert_allclose(_central_difference(path, t, h), vel, rtol=0, atol=1e-7)


def test_ramp_starts_sway_from_rest_and_reaches_full_amplitude():
    path = ZigZagPath(speed=1.0, amplitude=10.0, period=50.0, phase=0.5, ramp=25.0, heading=math.pi / 2)
    pos, vel = sample_path(path, [0.0, 25.0, 25.0 + 1e-9, 60.0])
    # At t = 0 the ramp and its slope vanish: the tow point is at start, moving along the course only.
    np.testing.assert_allclose(pos[0], 0.0, atol=1e-14)
    np.testing.assert_allclose(vel[0], [0.0, 1.0, 0.0], atol=1e-15)
    # Heading 90 deg: the left normal is -X. After the ramp the sway is the full sine (exact).
    np.testing.assert_allclose(pos[3, 0], -10.0 * math.sin(2 * math.pi * 60.0 / 50.0 + 0.5), atol=1e-12)
    # The ramp's slope is zero at its end too: the velocity is continuous there (to O(1e-9 s) steps).
    np.testing.assert_allclose(vel[1], vel[2], atol=1e-8)
    # Without a ramp, the sway velocity jumps to 2 pi A cos(phase) / T at t = 0.
    _, v0 = sample_path(path.replace(ramp=0.0), 0.0)
    assert -v0[0, 0] == pytest.approx(2 * math.pi * 10.0 * math.cos(0.5) / 50.0, rel=1e-12)


def test_zigzag_is_a_vessel_path_and_parses():
    assert ZigZagPath in VESSEL_PATHS
    path = parse_vessel_path({"type": "zigzag", "speed": 1.0289, "amplitude": 10.0, "period": 50.0})
    assert isinstance(path, ZigZagPath) and path.ramp == 0.0 and path.phase == 0.0
    # sample_path accepts the plain mapping as well.
    a, _ = sample_path({"type": "zigzag", "speed": 1.0289, "amplitude": 10.0, "period": 50.0}, 12.5)
    b, _ = sample_path(path, 12.5)
    np.testing.assert_array_equal(a, b)


def test_towed_dynamic_analysis_accepts_zigzag():
    from seacable.case import TowedDynamicAnalysis
    a = TowedDynamicAnalysis(vessel={"type": "zigzag", "speed": 1.0, "amplitude": 5.0, "period": 30.0},
                             duration=10.0)
    assert isinstance(a.vessel, ZigZagPath)


@pytest.mark.parametrize("key, value, expected", [
    ("amplitude", 0.0, "vessel.amplitude must be > 0 m, got 0 m"),
    ("amplitude", -10.0, "vessel.amplitude must be > 0 m, got -10 m"),
    ("period", 0.0, "vessel.period must be > 0 s, got 0 s"),
    ("period", -50.0, "vessel.period must be > 0 s, got -50 s"),
    ("ramp", -1.0, "vessel.ramp must be >= 0 s, got -1 s"),
    ("speed", -1.0, "vessel.speed must be >= 0 m/s, got -1 m/s"),
])
def test_bad_input_names_the_key(key, value, expected):
    data = {"type": "zigzag", "speed": 1.0, "amplitude": 10.0, "period": 50.0, key: value}
    with pytest.raises(InputError, match="Suggested fix") as info:
        parse_vessel_path(data)
    assert expected in str(info.value)


def test_missing_amplitude_and_typo():
    with pytest.raises(InputError, match="vessel.amplitude is required"):
        parse_vessel_path({"type": "zigzag", "speed": 1.0, "period": 50.0})
    with pytest.raises(InputError, match="Did you mean 'zigzag'"):
        parse_vessel_path({"type": "zig_zag", "speed": 1.0, "amplitude": 10.0, "period": 50.0})


def test_phase_in_degrees_warns():
    with pytest.warns(SeacableWarning, match="vessel.phase = 90 rad looks like degrees"):
        ZigZagPath(speed=1.0, amplitude=10.0, period=50.0, phase=90.0)

"""Issue 17 items 5, 6 and 7 for towline_dynamic: the line's initial heading comes from the tug's
displacement (a table starting from rest put the barge 430 m ahead of the tug), the seabed it does not
model is warned about and measured, and every check before the time loop is in
prepare_towline_dynamic."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import seacable as sc
from seacable.errors import InputError, SeacableWarning
from seacable.towed.vessel import (
    SpeedSchedule,
    StraightPath,
    TablePath,
    TurnPath,
    ZigZagPath,
    initial_heading,
    sample_path,
)
from seacable.towline.run import prepare_towline_dynamic, run_towline_dynamic

KNOTS = 0.514444
WIRE = dict(diameter=0.040, mass_per_length=6.5, axial_stiffness=9.0e7, breaking_load=1.0e6,
            drag_normal=1.2, drag_tangential=0.015, added_mass_normal=1.0)
BARGE = dict(length=60.0, beam=18.0, draft=2.5, block_coefficient=0.9, tow_point_height=2.0)
LENGTH = 400.0


#: the first rows of the repro's tug_bad.csv (x every 0.5 s from t = 0, metres to 0.1 mm): from rest,
#: x growing about as t^2.8, so that the not-a-knot spline's velocity at t = 0 is -2.7e-5 m/s
REPRO_START = (0.0, 0.0002, 0.0011, 0.0031, 0.0066, 0.0121, 0.0200, 0.0308, 0.0448, 0.0626)


def _tug_table(folder, heading=0.0):
    """The repro's tug (../shared/repro/tug_bad.csv): its first rows, then 5 knots reached from rest
    over a 60 s half-cosine ramp and a 90 degree left turn at 0.5 deg/s from t = 300 s (the file's
    pattern to within 0.7 m), every 0.5 s for 1000 s; the whole track turned to ``heading``."""
    path = TurnPath(speed=5 * KNOTS, ramp=60.0, start_time=300.0, turn_rate=math.radians(0.5),
                    end_time=480.0)
    t = np.arange(0.0, 1000.0 + 1e-9, 0.5)
    p, _ = sample_path(path, t)
    p = p[:, :2]
    p[:len(REPRO_START)] = np.column_stack([REPRO_START, np.zeros(len(REPRO_START))])
    c, s = math.cos(heading), math.sin(heading)
    p = p @ np.array([[c, s], [-s, c]])
    file = folder / "tug.csv"
    file.write_text("time,x,y\n" + "".join(f"{a:.4f},{float(x)!r},{float(y)!r}\n" for a, x, y in zip(t, *p.T)))
    return file


def _case(tug, depth=25.0, **analysis):
    spec = dict(type="towline_dynamic", tug=tug, tug_tow_point_height=3.0, barge=dict(BARGE),
                start="straight", n_elements=40, duration=2.0, output_interval=1.0)
    spec.update(analysis)
    env = dict(water_density=1025.0, gravity=9.80665)
    if depth is not None:
        env["depth"] = depth
    return sc.Case.parse(dict(name="table_bad", line_types={"wire40": WIRE},
                              line={"line_type": "wire40", "length": LENGTH}, environment=env, analysis=spec))


@pytest.mark.parametrize("heading", [0.0, 2.0])
def test_a_tug_table_starting_from_rest_has_the_barge_astern(tmp_path, heading):
    file = _tug_table(tmp_path, heading)
    tug = dict(type="table", file=str(file), kind="position")
    # the flaw: the spline's velocity at t = 0 is a tiny artefact pointing astern
    _, v0 = sample_path(TablePath(file=str(file), kind="position"), np.array([0.0]))
    assert np.dot(v0[0, :2], [math.cos(heading), math.sin(heading)]) < 0
    with pytest.warns(SeacableWarning, match="does not model seabed contact"):
        ds = run_towline_dynamic(_case(tug))
    first = ds.isel(time=0)
    tug_point = np.array([float(first.tug_x), float(first.tug_y)])
    barge_point = np.array([float(first.x.isel(node=-1)), float(first.y.isel(node=-1))])
    ahead = np.array([math.cos(heading), math.sin(heading)])
    # astern along the initial heading by the line's horizontal length: sqrt(L^2 - (3 m - 2 m)^2)
    # (the straight start; elements rigid, joints closed: exact to rounding)
    gap = tug_point - barge_point
    assert np.dot(gap, ahead) == pytest.approx(math.sqrt(LENGTH**2 - 1.0), rel=1e-9)
    assert abs(ahead[0] * gap[1] - ahead[1] * gap[0]) < 1e-6
    # the barge's midship is behind its bow tow point, heading the tug's way
    assert float(first.barge_heading) == pytest.approx(heading, abs=1e-9)
    midship = np.array([float(first.barge_x), float(first.barge_y)])
    assert np.dot(barge_point - midship, ahead) == pytest.approx(30.0, rel=1e-9)


@pytest.mark.parametrize("path, expected", [
    (StraightPath(speed=2.0, heading=0.3), 0.3),
    (StraightPath(speed=2.0, heading=-2.5, ramp=30.0), -2.5),
    (SpeedSchedule(times=(0.0, 10.0), speeds=(0.0, 2.0), heading=1.0), 1.0),
    (TurnPath(speed=1.0, heading=0.5, turn_rate=0.01, start_time=20.0, ramp=20.0), 0.5),
    # a turn from t = 0: the chord to the point 0.1 m away is the tangent plus rate * tau / 2
    (TurnPath(speed=1.0, heading=0.5, turn_rate=0.01), 0.5 + 0.01 * 0.1 / 2),
    # a zig-zag starting on the course line swaying left: (V, 2 pi A / T) to within the curvature
    (ZigZagPath(speed=1.0, amplitude=10.0, period=50.0), math.atan2(2 * math.pi * 10.0 / 50.0, 1.0)),
])
def test_initial_heading_of_every_path_kind(path, expected):
    # the chord of a 0.1 m step differs from the tangent by half the turn over it: 1e-3 rad for the
    # turn; for the zig-zag, by the path's curvature times 0.05 m (about 3e-3 rad here)
    assert initial_heading(path, 60.0, distance=0.1) == pytest.approx(expected, abs=3e-3)


def test_turn_speed_ramp_starts_from_rest_and_joins_the_turn_smoothly():
    path = TurnPath(speed=2.0, heading=0.0, ramp=10.0, start_time=15.0, turn_rate=0.05)
    t = np.linspace(0.0, 40.0, 4001)
    p, v = sample_path(path, t)
    assert np.hypot(*v[0, :2]) == 0.0
    # position is the integral of velocity (trapezoid, h^2 error ~ 1e-6 m here)
    integral = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:, 0] + v[:-1, 0]) * np.diff(t))])
    np.testing.assert_allclose(p[:, 0], integral, atol=1e-5)
    # full speed from the end of the ramp; the ramp's distance is V T / 2 (half-cosine mean 1/2)
    assert np.hypot(*v[t >= 10.0, :2].T) == pytest.approx(2.0, rel=1e-12)
    assert p[t == 10.0, 0][0] == pytest.approx(2.0 * 10.0 / 2, rel=1e-12)
    with pytest.raises(InputError, match="ramp .* must end by start_time"):
        sc.Case.parse(dict(name="x", line={"segments": [{"line_type": WIRE, "length": 10.0}]},
                           analysis=dict(type="towline_dynamic", barge=BARGE, duration=1.0,
                                         tug=dict(type="turn", speed=1.0, turn_rate=0.01, ramp=10.0))))


def test_a_towline_sagging_below_the_seabed_is_warned_and_measured():
    # a still tug and a held barge on 400 m of a soft rope (EA 1 MN, 51 N/m in water): the straight
    # line sags, stretching, to about (3 w L^4 / (64 EA))^(1/3) = 39 m, through the seabed 25 m down
    case = _case(dict(type="straight", speed=0.0), depth=25.0, barge_held=True, duration=20.0,
                 n_elements=20)
    case = case.model_copy(update={"line_types": {}, "line": sc.Line.single(
        sc.LineType(**{**WIRE, "axial_stiffness": 1.0e6}), LENGTH)})
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ds = run_towline_dynamic(case)
    messages = [str(w.message) for w in caught if issubclass(w.category, SeacableWarning)]
    z = ds.z.values
    below = (z < -25.0).any(axis=1)
    assert below.any() and not below[0]
    i = int(np.argmax(below))
    j = int(np.nanargmin(z[i]))
    crossing = [m for m in messages if "below the seabed at 25 m" in m]
    assert len(crossing) == 1
    assert f"t = {ds.time.values[i]:g} s joint {j} " in crossing[0]
    np.testing.assert_array_equal(ds.seabed_clearance.values < 0, below)
    np.testing.assert_allclose(ds.seabed_clearance.values, np.nanmin(z, axis=1) + 25.0, atol=1e-12)


@pytest.mark.parametrize("where, value, message", [
    ("barge.length", 1e300, r"analysis.barge.length must be in \[0, 1000\] m, got 1e\+300 m"),
    ("barge.beam", 1.5e4, r"analysis.barge.beam must be in \[0, 200\] m"),
    ("barge.draft", 400.0, r"analysis.barge.draft must be in \[0, 50\] m"),
    ("tug_tow_point_height", 3000.0, r"analysis.tug_tow_point_height must be in \[-100, 100\] m"),
])
def test_implausible_sizes_are_refused_before_the_run(where, value, message):
    spec = {}
    if where.startswith("barge."):
        spec["barge"] = {**BARGE, where.split(".")[1]: value}
    else:
        spec[where] = value
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SeacableWarning)
        case = _case(dict(type="straight", speed=1.0), depth=None, **spec)
    with pytest.raises(InputError, match=message):
        sc.simulate.check(case)


def test_a_time_step_above_the_stability_bound_is_refused_before_the_run():
    with pytest.raises(InputError, match="time_step must be > 0 s and not above the explicit scheme's stability"):
        prepare_towline_dynamic(_case(dict(type="straight", speed=1.0), depth=None, time_step=0.5))


def test_a_barge_deeper_than_the_water_is_refused():
    with pytest.raises(InputError, match=r"analysis.barge.draft must be less than environment.depth = 2 m, "
                                         r"got 2.5 m"):
        prepare_towline_dynamic(_case(dict(type="straight", speed=1.0), depth=2.0))


def test_an_implausible_line_length_is_refused():
    case = sc.Case.parse(dict(name="x", line_types={"w": WIRE}, line={"line_type": "w", "length": 1e300},
                              analysis=dict(type="towline_dynamic", barge=BARGE, duration=1.0,
                                            tug=dict(type="straight", speed=1.0))))
    with pytest.raises(InputError, match=r"line.length must be in \[0, 20000\] m"):
        prepare_towline_dynamic(case)


def test_a_run_too_long_is_refused_with_the_estimate():
    case = _case(dict(type="straight", speed=1.0), depth=None, duration=1e9, output_interval=100.0)
    with pytest.raises(InputError, match="time steps, more than the limit"):
        prepare_towline_dynamic(case)


def test_a_table_shorter_than_the_run_is_refused_before_it(tmp_path):
    file = _tug_table(tmp_path)
    case = _case(dict(type="table", file=str(file), kind="position"), depth=None, duration=2000.0)
    with pytest.raises(InputError, match="table ends at 1000 s"):
        prepare_towline_dynamic(case)

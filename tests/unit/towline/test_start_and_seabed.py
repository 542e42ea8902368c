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


def test_a_towline_sagging_onto_the_seabed_rests_on_it():
    """A still tug and a held barge on 400 m of a soft rope (EA 1 MN, 51 N/m in water): the straight line sags,
    stretching, to about (3 w L^4 / (64 EA))^(1/3) = 39 m without a seabed; with one 25 m down its middle lands
    and rests there. The seabed's penalty presses it in by w / (k_b d) = 0.43 mm at rest: after 40 s (the landing's
    bounce damped by the seabed's damper) no joint is more than 1 cm under the seabed, while a third of the
    line lies on it. Without friction or drag asked of it, the run needs no other change; the step is bounded by
    the seabed's spring and damper (stable_time_step)."""
    case = _case(dict(type="straight", speed=0.0), depth=25.0, barge_held=True, duration=40.0,
                 n_elements=20)
    case = case.model_copy(update={"line_types": {}, "line": sc.Line.single(
        sc.LineType(**{**WIRE, "axial_stiffness": 1.0e6}), LENGTH)})
    with warnings.catch_warnings():
        warnings.simplefilter("error", SeacableWarning)  # contact is modelled: nothing to warn about
        ds = run_towline_dynamic(case)
    z = ds.z.values
    assert z[-1].min() > -25.0 - 0.01
    grounded = z[-1] < -25.0 + 0.01
    assert grounded.sum() >= 6  # joints on the seabed (of 21)
    np.testing.assert_allclose(ds.seabed_clearance.values, np.nanmin(z, axis=1) + 25.0, atol=1e-12)
    without = run_towline_dynamic(_case(dict(type="straight", speed=0.0), depth=None, barge_held=True,
                                        duration=40.0, n_elements=20).model_copy(update={
        "line_types": {}, "line": sc.Line.single(sc.LineType(**{**WIRE, "axial_stiffness": 1.0e6}), LENGTH)}))
    assert without.z.values[-1].min() < -30.0  # the same line without the seabed sags far below it


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
        sc.check(case)


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


def test_the_seabed_presses_up_and_rubs_against_a_sliding_element():
    """One element of the rope lying level 1 mm into the seabed and sliding along itself at 0.5 m/s (no drag
    asked): its loads are the weight, the buoyancy, the seabed's k_b d l x 1 mm up (the three Gauss points'
    shares add up to the length) and the friction mu N u / sqrt(u^2 + v_f^2) against the sliding, to 1e-9;
    moving up at 4 mm/s adds the damper's -c_b d l 0.004 m/s."""
    from seacable.towline import kernel as TK
    from seacable.towline.solver import TowlineModel

    model = TowlineModel(n_elements=1, length=20.0, diameter=0.04, mass_per_length=6.5, axial_stiffness=1e6,
                         drag=False, impact=False, depth=25.0, friction=0.6, friction_velocity=0.01)
    P = model.params
    R = np.array([[0.0, 0.0, -25.001]])
    E = np.eye(3)[None, :, :].copy()
    joint = (0.0,) * 12
    ma = np.zeros((1, 3))
    kb_n = 3.0e6 * 0.04 * 20.0 * 0.001
    buoy = 1025.0 * 9.80665 * math.pi * 0.04**2 / 4 * 20.0
    for w, damp in ((0.0, 0.0), (0.004, 3.0e5 * 0.04 * 20.0 * 0.004)):
        nu = np.array([[0.5, 0.0, w]])
        out = TK._element(0, R, E, nu, np.zeros((1, 2)), P, joint, joint, 0.0, ma, ma)
        normal = kb_n - damp
        # to 1e-9: the kernel is compiled with fastmath's reassociation (sums in another order)
        assert out[2] == pytest.approx(-6.5 * 20.0 * 9.80665 + buoy + normal, rel=1e-9)
        assert out[0] == pytest.approx(-0.6 * normal * 0.5 / math.hypot(0.5, 0.01), rel=1e-9)
        assert out[1] == 0.0

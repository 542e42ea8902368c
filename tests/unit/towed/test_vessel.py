"""Vessel paths (seacable.towed.vessel): closed forms, integrals, tables and errors.

The turning case is paper 000's (shared/seeds/000_e4cc68758a51635b.txt, section 4):
the vessel tows at 1.0 m/s and turns left at 0.5 deg/s from t = 0; Fig. 4 shows it
about 40 m sideways after 100 s.
"""

from __future__ import annotations

import math
import pickle

import numpy as np
import pytest
from pydantic import TypeAdapter, ValidationError
from scipy.integrate import cumulative_trapezoid

from seacable.errors import InputError, SeacableWarning
from seacable.towed.vessel import (VESSEL_PATHS, SpeedSchedule, StraightPath, TablePath, TurnPath,
                                   VesselPath, ZigZagPath, parse_vessel_path, sample_path)

# Positions of order 100 m summed over ~1e4 trapezoids: round-off stays below 1e-9 m.
ROUND_OFF = 1e-9


def _write_csv(path, names, columns):
    lines = [",".join(names)] + [",".join(repr(float(v)) for v in row) for row in zip(*columns)]
    path.write_text("\n".join(lines) + "\n")
    return path


# ------------------------------------------------------------------------------------------
# Closed forms
# ------------------------------------------------------------------------------------------

def test_paper000_turn_closed_form():
    omega = math.radians(0.5)
    path = TurnPath(speed=1.0, turn_rate=omega)
    pos, vel = sample_path(path, [0.0, 100.0])
    # After 100 s the heading is 50 deg; arc from the origin: x = sin(psi)/omega, y = (1 - cos psi)/omega.
    psi = math.radians(50.0)
    # Closed form against closed form in another algebraic arrangement: round-off only.
    assert pos[1, 0] == pytest.approx(math.sin(psi) / omega, rel=1e-12)
    assert pos[1, 1] == pytest.approx((1 - math.cos(psi)) / omega, rel=1e-12)
    # The brief's value 40.93 m, printed to 0.01 m; paper 000 Fig. 4 reads "about 40 m".
    assert pos[1, 1] == pytest.approx(40.93, abs=0.005)
    np.testing.assert_allclose(vel[1], [math.cos(psi), math.sin(psi), 0.0], atol=1e-15)
    np.testing.assert_allclose(pos[0], 0.0, atol=0)
    assert np.all(pos[:, 2] == 0.0)  # the tow point stays on the surface


def test_paper000_rate_as_printed_in_brief():
    # 0.00872665 rad/s is 0.5 deg/s rounded to 6 significant figures (relative error 4e-7),
    # which moves y(100 s) by less than 1e-4 m.
    a = sample_path(TurnPath(speed=1.0, turn_rate=0.00872665), 100.0)[0]
    b = sample_path(TurnPath(speed=1.0, turn_rate=math.radians(0.5)), 100.0)[0]
    np.testing.assert_allclose(a, b, atol=1e-4)


@pytest.mark.parametrize("direction, sign", [("left", 1.0), ("right", -1.0)])
def test_radius_form_equals_rate_form(direction, sign):
    speed, radius = 2.5, 80.0
    t = np.linspace(-10.0, 400.0, 57)
    by_radius = TurnPath(speed=speed, heading=0.3, start=(5.0, -2.0), start_time=12.0,
                         radius=radius, direction=direction)
    by_rate = TurnPath(speed=speed, heading=0.3, start=(5.0, -2.0), start_time=12.0,
                       turn_rate=sign * speed / radius)
    assert by_radius.rate == sign * speed / radius
    for a, b in zip(sample_path(by_radius, t), sample_path(by_rate, t)):
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-12)  # the same arithmetic: round-off only
    # The vessel stays on a circle of that radius while turning, centred left/right of the start.
    pos = sample_path(by_radius, t[t >= 12.0])[0]
    p_s = np.array([5.0, -2.0]) + speed * 12.0 * np.array([math.cos(0.3), math.sin(0.3)])
    centre = p_s + sign * radius * np.array([-math.sin(0.3), math.cos(0.3)])
    np.testing.assert_allclose(np.hypot(*(pos[:, :2] - centre).T), radius, rtol=1e-12)


def test_turn_phases_and_end_time():
    omega, speed = 0.05, 1.5
    path = TurnPath(speed=speed, turn_rate=omega, start_time=10.0, end_time=30.0, heading=0.0)
    pos, vel = sample_path(path, [0.0, 10.0, 30.0, 50.0])
    # Straight along +X for 10 s.
    np.testing.assert_allclose(pos[1], [15.0, 0.0, 0.0], atol=1e-12)
    # 20 s of turn: heading 1 rad; arc from (15, 0).
    psi = omega * 20.0
    end = np.array([15.0 + speed / omega * math.sin(psi), speed / omega * (1 - math.cos(psi)), 0.0])
    np.testing.assert_allclose(pos[2], end, atol=1e-12)
    # Then straight on the new heading.
    e = np.array([math.cos(psi), math.sin(psi), 0.0])
    np.testing.assert_allclose(pos[3], end + speed * 20.0 * e, atol=1e-12)
    np.testing.assert_allclose(vel[3], speed * e, atol=1e-15)
    np.testing.assert_allclose(vel[0], [speed, 0.0, 0.0], atol=1e-15)


def test_vanishing_turn_rate_is_straight():
    # The chord form V*tau*sinc(r*tau/2) has no 1/r: a rate of 1e-14 rad/s must not lose digits.
    t = np.linspace(0.0, 1000.0, 11)
    turn = sample_path(TurnPath(speed=1.0, heading=1.0, turn_rate=1e-14), t)
    straight = sample_path(StraightPath(speed=1.0, heading=1.0), t)
    for a, b in zip(turn, straight):
        np.testing.assert_allclose(a, b, atol=1e-9)  # true difference ~ V t^2 r / 2 = 5e-9 m at most


def test_straight_path_and_builder():
    path = StraightPath(speed=2.0, heading=math.pi / 2, start=(1.0, 2.0))
    pos, vel = sample_path(path, np.array([0.0, 3.0]))
    np.testing.assert_allclose(pos, [[1.0, 2.0, 0.0], [1.0, 8.0, 0.0]], atol=1e-12)
    np.testing.assert_allclose(vel, [[0.0, 2.0, 0.0]] * 2, atol=1e-12)
    turn = path.turn(radius=10.0, direction="right", start_time=5.0)
    assert isinstance(turn, TurnPath) and turn.rate == -0.2 and turn.start == (1.0, 2.0)


def test_speed_schedule_stop_and_go():
    path = SpeedSchedule(times=(0, 10, 20, 30, 40), speeds=(1, 1, 0, 0, 1), heading=math.pi, start=(3.0, 0.0))
    t = np.array([-5.0, 0.0, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 50.0])
    pos, vel = sample_path(path, t)
    # Distance run by hand: 10 m at 1 m/s, 5 m slowing to rest, stopped, 5 m speeding up, then 1 m/s.
    run = np.array([-5.0, 0.0, 10.0, 13.75, 15.0, 15.0, 15.0, 16.25, 20.0, 30.0])
    speed = np.array([1.0, 1.0, 1.0, 0.5, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0])
    np.testing.assert_allclose(pos[:, 0], 3.0 - run, atol=1e-12)  # heading pi: along -X
    np.testing.assert_allclose(pos[:, 1], 0.0, atol=1e-12)
    np.testing.assert_allclose(vel[:, 0], -speed, atol=1e-12)


def test_speed_schedule_starting_late_is_at_start_at_t0():
    path = SpeedSchedule(times=(10.0, 20.0), speeds=(2.0, 0.0))
    pos, vel = sample_path(path, [0.0, 10.0, 20.0, 30.0])
    # Constant 2 m/s before the first point, then 10 m while stopping.
    np.testing.assert_allclose(pos[:, 0], [0.0, 20.0, 30.0, 30.0], atol=1e-12)
    np.testing.assert_allclose(vel[:, 0], [2.0, 2.0, 0.0, 0.0], atol=1e-12)
    one = SpeedSchedule(times=(0.0,), speeds=(1.5,))
    np.testing.assert_allclose(sample_path(one, 4.0)[0], [[6.0, 0.0, 0.0]], atol=1e-12)


# ------------------------------------------------------------------------------------------
# Positions are the integral of the velocities, for every kind of path
# ------------------------------------------------------------------------------------------

def _check_integral(path, t_end, kink_jumps, v2=None, base_dir=None):
    """Compare positions with the cumulative trapezoid of the velocities.

    Trapezoid error on a uniform grid of step h: |E| <= t_end h^2/12 max|v''| on the smooth
    parts (Peano kernel; valid when v' is absolutely continuous), plus |jump of v'| h^2/8 for
    each interval holding a kink of v (there the error is jump * d (h - d) / 2 <= jump h^2 / 8).
    ``v2`` is max|v''| from the closed form; for tables (v is C^1: a spline or its derivative)
    it is taken from second differences of the sampled v, which equal v'' exactly for a
    piecewise quadratic/cubic v when the table knots lie on the grid.
    """
    n = 24001  # h = t_end / 24000: for t_end = 60 s the 1 s table knots lie on the grid
    t = np.linspace(0.0, t_end, n)
    h = t[1] - t[0]
    pos, vel = sample_path(path, t, base_dir=base_dir)
    integral = pos[0] + cumulative_trapezoid(vel, t, axis=0, initial=0.0)
    if v2 is None:
        v2 = np.abs(np.diff(vel, 2, axis=0)).max() / h**2
    bound = t_end * h**2 / 12 * v2 + sum(kink_jumps) * h**2 / 8 + ROUND_OFF
    error = np.abs(integral - pos).max()
    assert error <= bound
    return error, bound


def test_integral_straight():
    _check_integral(StraightPath(speed=1.3, heading=-0.7, start=(4.0, 4.0)), 200.0, [], v2=0.0)


def test_integral_schedule():
    # v is piecewise linear (v'' = 0) with kinks at 10, 20 (accel 0 -> -0.1 -> 0) and 30, 40
    # (0 -> 0.1 -> 0); with t_end = 53 s the kinks fall between grid points.
    path = SpeedSchedule(times=(0.0, 10.0, 20.0, 30.0, 40.0), speeds=(1.0, 1.0, 0.0, 0.0, 1.0), heading=0.4)
    _check_integral(path, 53.0, [0.1, 0.1, 0.1, 0.1], v2=0.0)


def test_integral_turn():
    # v'' = V omega^2 on the arc; acceleration jumps by V omega at start_time and end_time.
    speed, omega = 2.0, -0.03
    path = TurnPath(speed=speed, turn_rate=omega, start_time=13.3, end_time=91.7, heading=2.0)
    _check_integral(path, 150.0, [speed * abs(omega)] * 2, v2=speed * omega**2)


@pytest.mark.parametrize("kind", ["position", "velocity"])
def test_integral_table(tmp_path, kind):
    t = np.arange(0.0, 61.0, 1.0)  # knots on the 0.0025 s test grid
    if kind == "position":
        cols, names = [20 * np.sin(0.1 * t), 20 * (1 - np.cos(0.1 * t)), 0.5 * np.sin(0.3 * t)], "xyz"
    else:
        cols, names = [2 * np.cos(0.1 * t), 2 * np.sin(0.1 * t), 0.15 * np.cos(0.3 * t)], "uvw"
    _write_csv(tmp_path / "path.csv", ["time", *names], [t, *cols])
    _check_integral(TablePath(file="path.csv", kind=kind), 60.0, [], base_dir=tmp_path)


# ------------------------------------------------------------------------------------------
# Tables round-trip an analytic circle
# ------------------------------------------------------------------------------------------

SPEED, OMEGA, RADIUS = 2.0, 0.1, 20.0


def _circle_table(tmp_path, kind, h, name="circle.csv"):
    t = np.arange(0.0, 60.0 + h / 2, h)
    if kind == "position":
        cols = [RADIUS * np.sin(OMEGA * t), RADIUS * (1 - np.cos(OMEGA * t))]
        names = ["time", "x", "y"]
    else:
        cols = [SPEED * np.cos(OMEGA * t), SPEED * np.sin(OMEGA * t)]
        names = ["time", "u", "v"]
    return _write_csv(tmp_path / name, names, [t, *cols])


def _circle_errors(tmp_path, kind, h, inner=False):
    file = _circle_table(tmp_path, kind, h, name=f"circle_{kind}_{h}.csv")
    t = np.linspace(0.0, 60.0, 6001)
    pos, vel = sample_path(TablePath(file=str(file), kind=kind, start=(1.0, -1.0)), t)
    exact_pos = np.stack([1.0 + RADIUS * np.sin(OMEGA * t), -1.0 + RADIUS * (1 - np.cos(OMEGA * t))], -1)
    exact_vel = np.stack([SPEED * np.cos(OMEGA * t), SPEED * np.sin(OMEGA * t)], -1)
    keep = (t >= 5.0 * h) & (t <= 60.0 - 5.0 * h) if inner else slice(None)
    assert np.all(pos[:, 2] == 0.0) and np.all(vel[:, 2] == 0.0)
    return np.abs(pos[keep, :2] - exact_pos[keep]).max(), np.abs(vel[keep, :2] - exact_vel[keep]).max()


@pytest.mark.parametrize("kind", ["position", "velocity"])
def test_table_circle_spline_accuracy(tmp_path, kind):
    h = 1.0
    pos_err, vel_err = _circle_errors(tmp_path, kind, h, inner=True)
    # Hall & Meyer (1976) bounds for cubic spline interpolation with exact end slopes:
    # |f - s| <= 5/384 h^4 max|f''''|, |f' - s'| <= 1/24 h^3 max|f''''|. The not-a-knot end
    # condition's influence decays by (2 - sqrt 3) = 0.27 per knot, so 5 knots inside it is
    # below 0.2 % of the end error and the bounds apply there.
    if kind == "position":
        f4 = RADIUS * OMEGA**4  # position f'''' amplitude
        assert pos_err <= 5 / 384 * h**4 * f4
        assert vel_err <= h**3 / 24 * f4
    else:
        f4 = SPEED * OMEGA**4  # velocity v'''' amplitude
        assert vel_err <= 5 / 384 * h**4 * f4
        # Position = integral from t = 0 of the velocity error, which includes the end zone:
        # bounded by t * max|s - v|, with max|s - v| over the whole table <= 3x the interior
        # Hall-Meyer bound (measured 2.2x at the ends for not-a-knot at this h).
        assert pos_err <= 60.0 * 3 * 5 / 384 * h**4 * f4


@pytest.mark.parametrize("kind, order_pos, order_vel", [("position", 4, 3), ("velocity", 4, 4)])
def test_table_circle_convergence_order(tmp_path, kind, order_pos, order_vel):
    # Cubic splines: position interpolation O(h^4), its derivative O(h^3); a velocity table
    # interpolates v to O(h^4) and its integral is O(h^4) as well. Observed orders from h = 1
    # to 0.5 must be within 0.3 of nominal (the asymptotic regime is reached: h omega = 0.1).
    e1 = _circle_errors(tmp_path, kind, 1.0)
    e2 = _circle_errors(tmp_path, kind, 0.5)
    observed = np.log2(np.array(e1) / np.array(e2))
    assert observed[0] == pytest.approx(order_pos, abs=0.3)
    assert observed[1] == pytest.approx(order_vel, abs=0.3)


def test_table_z_and_w_columns(tmp_path):
    t = np.linspace(0.0, 10.0, 101)
    _write_csv(tmp_path / "heave.csv", ["Time", " X ", "y", "z", "note"],
               [t, t, 0 * t, 0.4 * t**2, 0 * t])
    pos, vel = sample_path(TablePath(file="heave.csv", kind="position"), [2.0, 5.0], base_dir=tmp_path)
    # Quadratic data are reproduced exactly by a not-a-knot cubic spline (round-off only).
    np.testing.assert_allclose(pos[:, 2], [1.6, 10.0], atol=1e-10)
    np.testing.assert_allclose(vel[:, 2], [1.6, 4.0], atol=1e-10)
    _write_csv(tmp_path / "w.csv", ["time", "u", "v", "w"], [t, 1 + 0 * t, 0 * t, -0.2 * t])
    pos, vel = sample_path(TablePath(file="w.csv", kind="velocity", start=(3.0, 4.0)), [0.0, 10.0],
                           base_dir=str(tmp_path))
    # x = 3 + t, z = -0.1 t^2: the spline of linear data is exact, its antiderivative too.
    np.testing.assert_allclose(pos, [[3.0, 4.0, 0.0], [13.0, 4.0, -10.0]], atol=1e-10)


def test_table_relative_to_cwd_and_reloaded_when_changed(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    t = np.array([0.0, 10.0])
    file = _write_csv(tmp_path / "p.csv", ["time", "x", "y"], [t, t, 0 * t])
    path = TablePath(file="p.csv", kind="position")
    assert sample_path(path, 10.0)[0][0, 0] == pytest.approx(10.0, abs=1e-12)
    _write_csv(file, ["time", "x", "y"], [t, 2.5 * t, 0 * t])  # new content, different size
    assert sample_path(path, 10.0)[0][0, 0] == pytest.approx(25.0, abs=1e-12)


# ------------------------------------------------------------------------------------------
# Parsing
# ------------------------------------------------------------------------------------------

def test_parse_from_dicts():
    data = {"type": "turn", "speed": 1.0, "turn_rate": "8.72665e-3"}  # YAML 1.1 text number
    adapter = TypeAdapter(VesselPath)
    for parsed in (adapter.validate_python(data), parse_vessel_path(data), TurnPath.parse(data)):
        assert isinstance(parsed, TurnPath) and parsed.turn_rate == 8.72665e-3
    assert isinstance(parse_vessel_path({"type": "straight", "speed": 1}), StraightPath)
    assert isinstance(parse_vessel_path({"type": "speed_schedule", "times": [0, 1], "speeds": [1, 2]}),
                      SpeedSchedule)
    assert isinstance(parse_vessel_path({"type": "table", "file": "a.csv", "kind": "velocity"}), TablePath)
    pos, _ = sample_path({"type": "straight", "speed": 2.0}, [1.0])
    np.testing.assert_allclose(pos, [[2.0, 0.0, 0.0]])
    assert set(VESSEL_PATHS) == {StraightPath, SpeedSchedule, TurnPath, TablePath, ZigZagPath}


def test_models_are_frozen_and_picklable():
    path = TurnPath(speed=1.0, radius=50.0, direction="right", end_time=20.0)
    assert pickle.loads(pickle.dumps(path)) == path
    with pytest.raises(ValidationError, match="frozen"):
        path.speed = 2.0


# ------------------------------------------------------------------------------------------
# Errors and warnings
# ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("kwargs, match", [
    ({"speed": 1.0}, "exactly one of 'turn_rate'.*got neither"),
    ({"speed": 1.0, "turn_rate": 0.01, "radius": 100.0}, "exactly one of 'turn_rate'.*got both"),
    ({"speed": 1.0, "turn_rate": -0.01, "direction": "left"}, "direction 'left' contradicts turn_rate"),
    ({"speed": 1.0, "turn_rate": 0.01, "direction": "right"}, "direction 'right' contradicts"),
    ({"speed": 1.0, "radius": 0.0}, r"radius must be > 0 m, got 0 m"),
    ({"speed": 1.0, "radius": 50.0, "direction": "up"}, "direction must be 'left' or 'right'"),
    ({"speed": -1.0, "radius": 50.0}, r"speed must be >= 0 m/s, got -1 m/s"),
    ({"speed": 1.0, "radius": 50.0, "start_time": 10.0, "end_time": 5.0}, "end_time must be > start_time"),
    ({"speed": 1.0, "radius": 50.0, "start": (0.0, float("nan"))}, "start must hold two finite"),
])
def test_turn_errors(kwargs, match):
    with pytest.raises(InputError, match=match):
        TurnPath(**kwargs)


def test_negative_rate_without_direction_turns_right():
    assert TurnPath(speed=1.0, turn_rate=-0.01).rate == -0.01
    assert TurnPath(speed=1.0, turn_rate=-0.01, direction="right").rate == -0.01


@pytest.mark.parametrize("kwargs, match", [
    ({"times": (0.0, 10.0), "speeds": (1.0,)}, "same length"),
    ({"times": (0.0, 10.0, 10.0), "speeds": (1.0, 1.0, 0.0)}, r"strictly increasing.*times\[2\] = 10 s"),
    ({"times": (-1.0, 10.0), "speeds": (1.0, 1.0)}, r"times\[0\] must be a finite number >= 0 s"),
    ({"times": (0.0, 10.0), "speeds": (1.0, -0.5)}, r"speeds\[1\] must be a finite number >= 0 m/s"),
    ({"times": (), "speeds": ()}, "times"),
])
def test_schedule_errors(kwargs, match):
    with pytest.raises(InputError, match=match):
        SpeedSchedule(**kwargs)


def test_parse_errors_name_the_key():
    with pytest.raises(InputError, match=r"vessel.type must be one of .*Did you mean 'turn'"):
        parse_vessel_path({"type": "turm", "speed": 1.0})
    with pytest.raises(InputError, match=r"vessel.kind must be 'position' or 'velocity'"):
        parse_vessel_path({"type": "table", "file": "a.csv", "kind": "positions"})
    with pytest.raises(InputError, match="unknown key 'sped'.*Did you mean 'speed'"):
        parse_vessel_path({"type": "straight", "sped": 1.0})
    with pytest.raises(InputError, match="path must be one of StraightPath"):
        sample_path("straight", [0.0])


def test_bad_times():
    path = StraightPath(speed=1.0)
    with pytest.raises(InputError, match=r"times\[1\] must be a finite number"):
        sample_path(path, [0.0, float("nan")])
    with pytest.raises(InputError, match="1-D array"):
        sample_path(path, np.zeros((2, 2)))


def test_degree_warnings():
    with pytest.warns(SeacableWarning, match="turn_rate = 3 rad looks like degrees"):
        TurnPath(speed=1.0, turn_rate=3.0)
    with pytest.warns(SeacableWarning, match="heading = 90 rad looks like degrees"):
        StraightPath(speed=1.0, heading=90.0)


@pytest.mark.parametrize("content, kind, match", [
    (None, "position", "vessel table file .*bad.csv' does not exist"),
    ("", "position", "is empty"),
    ("time,x\n0,0\n1,1\n", "position", r"no column 'y' for a position table.*or set 'kind'"),
    ("time,x,y\n0,0,0\n1,1,1\n", "velocity", r"no column 'u', 'v' for a velocity table"),
    ("time,x,y\n0,0,0\n", "position", r"has 1 row\(s\).*at least 2"),
    ("time,x,y\n0,0,0\n2,1,1\n1,2,2\n", "position",
     r"'time' must be strictly increasing.*line 4 has t = 1 s"),
    ("time,x,y\n0,0,0\n1,nan,1\n", "position", r"line 3, column 'x' holds 'nan'"),
    ("time,x,y\n0,0,0\n1,1,one\n", "position", r"line 3, column 'y' holds 'one'"),
    ("time,u,v\n0,0,0\n1,1\n", "velocity", r"line 3, column 'v' holds ''"),
])
def test_table_errors(tmp_path, content, kind, match):
    if content is not None:
        (tmp_path / "bad.csv").write_text(content)
    path = TablePath(file="bad.csv", kind=kind)
    with pytest.raises(InputError, match=match) as info:
        sample_path(path, [0.0], base_dir=tmp_path)
    assert "bad.csv" in str(info.value) and "Suggested fix" in str(info.value)


def test_table_unreadable(tmp_path):
    (tmp_path / "folder.csv").mkdir()
    with pytest.raises(InputError, match="folder.csv' is a folder, not a file"):
        sample_path(TablePath(file="folder.csv", kind="position"), [0.0], base_dir=tmp_path)


def test_table_time_outside(tmp_path):
    _write_csv(tmp_path / "short.csv", ["time", "x", "y"], [[1.0, 2.0, 50.0], [0.0, 1.0, 2.0], [0.0] * 3])
    path = TablePath(file="short.csv", kind="position")
    with pytest.raises(InputError,
                       match=r"short.csv': the run lasts until t = 100 s but the table ends at 50 s"):
        sample_path(path, [1.0, 100.0], base_dir=tmp_path)
    with pytest.raises(InputError, match=r"the run starts at t = 0 s but the table begins at 1 s"):
        sample_path(path, [0.0], base_dir=tmp_path)
    # Times a hair past the end (n * dt round-off) are accepted.
    sample_path(path, [50.0 * (1 + 1e-13)], base_dir=tmp_path)


def test_an_interrupt_between_an_outputs_appends_keeps_the_whole_outputs(monkeypatch):
    """SIGTERM landing while a box-scheme output is recorded (its positions started, its time not kept): the run
    returns the outputs every list holds, flagged interrupted, instead of failing to build its result."""
    import warnings
    from pathlib import Path

    import seacable as sc
    from seacable.io.case_file import load_case_data, parse_case
    from seacable.towed import solver

    data = load_case_data(Path(__file__).resolve().parents[3] / "examples" / "towed_stop_and_go.yaml")
    data["analysis"].update(duration=10.0, output_interval=1.0)
    calls, original = [], solver.integrate_positions

    def interrupted(*args):
        calls.append(1)
        if len(calls) == 4:
            raise KeyboardInterrupt
        return original(*args)

    monkeypatch.setattr(solver, "integrate_positions", interrupted)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = sc.run(parse_case(data))
    assert ds.attrs["interrupted"] == 1
    assert 0.0 < float(ds.time[-1]) < 10.0 and np.all(np.isfinite(ds.x.values))

"""Vessel paths: where the tow point is, and how fast it moves, at any time.

A towed-cable simulation is driven by the motion of its upper end, the tow point
on the vessel. This module describes that motion as small frozen input models,
one per kind of manoeuvre, that a case file carries under a ``type`` tag:

``straight``
    Constant speed on a constant heading (:class:`StraightPath`), optionally
    reached from rest over a smooth ``ramp``.
``speed_schedule``
    Constant heading, speed piecewise linear in time (:class:`SpeedSchedule`),
    e.g. a stop-and-go manoeuvre.
``turn``
    Straight, then a turn at constant speed and constant rate of turn, then
    straight again (:class:`TurnPath`); paper 000's turning case. Like the
    straight path it may start from rest with a speed ``ramp``.
``zigzag``
    Constant speed on a constant heading plus a sinusoidal sway across the
    course (:class:`ZigZagPath`), optionally with its amplitude ramped up
    smoothly; paper 003's zig-zag tow.
``table``
    Positions or velocities read from a CSV file and interpolated with cubic
    splines (:class:`TablePath`).

:func:`sample_path` returns positions and velocities at an array of times;
:func:`initial_heading` the direction in which a path sets off (from its
displacement, for a line laid out behind the vessel at t = 0).
Positions are the exact integrals of the velocities: closed forms for the first
four paths (a piecewise quadratic in time for the schedule, circular arcs for
the turn, a sine across the course for the zig-zag) and the spline's own
antiderivative for a velocity table.

Frame: global X, Y horizontal, Z up with z = 0 at the mean sea surface; headings
are measured from +X towards +Y (counter-clockwise seen from above). The tow
point stays at z = 0 unless a table gives ``z`` or ``w``. All units SI; angles
in radians. Every path is at ``start`` at t = 0 (a table: at its first time; a
zig-zag without ramp: displaced by ``amplitude sin(phase)`` across the course).

References
----------
.. [1] Park, H. I. and Jung, D. H., "A numerical analysis of the three-dimensional
   nonlinear dynamic behaviour of a low-tension towed cable" (paper 000 of
   ``shared/seeds``): the turning case, speed 1 m/s and 0.5 deg/s to the left.
.. [2] Yoon, H. K., Lee, H. S., Park, J. K. and Kim, Y. K., "Modeling and simulation
   of towline dynamics using multibody element theory" (paper 003 of
   ``shared/seeds``): the tug zig-zags at 2 knots with 10 m sway amplitude and a
   50 s period.
"""

from __future__ import annotations

import csv
import io
import functools
import math
import os
from pathlib import Path
from typing import Annotated, Any, Literal, Union

import numpy as np
from pydantic import Field, TypeAdapter, ValidationError, model_validator

from .._model import UNION_TAGS, Model, _problems, input_error, quantity, unit_float
from .._ramp import smooth_ramp
from .._validate import finite
from ..environment import _warn_if_degrees
from ..errors import InputError

__all__ = ["StraightPath", "SpeedSchedule", "TurnPath", "ZigZagPath", "TablePath", "VESSEL_PATHS",
           "VesselPath", "initial_heading", "parse_vessel_path", "sample_path"]

_XY = tuple[unit_float("m"), unit_float("m")]

#: A turn rate above this looks like degrees per second (0.5 rad/s = 29 deg/s). [rad/s]
_RATE_LOOKS_LIKE_DEGREES = 0.5


class _Planar(Model):
    """Fields shared by every path: the position at t = 0."""

    start: _XY = Field((0.0, 0.0), description="Tow-point position (x, y) at t = 0. [m]")

    @model_validator(mode="after")
    def _finite_start(self):
        if not all(math.isfinite(v) for v in self.start):
            raise ValueError(f"start must hold two finite numbers (x, y) in m, got {self.start}.")
        return self


class _Headed(_Planar):
    heading: quantity("rad") = Field(0.0, description="Course, from +X towards +Y. [rad]")

    @model_validator(mode="after")
    def _heading_in_radians(self):
        _warn_if_degrees("vessel.heading", self.heading, 2 * math.pi)
        return self


class _SpeedRamp(Model):
    """The smooth start of the speed shared by the straight and turning paths."""

    ramp: quantity("s", ge=0, fix="give the duration of the smooth start in seconds, 0 for none.") = Field(
        0.0, description="Duration of the smooth start of the speed from rest; 0 for none. [s]")


class StraightPath(_Headed, _SpeedRamp):
    """Constant speed on a constant heading.

    With ``ramp`` > 0 the vessel starts from rest: its speed is ``speed * r(t)`` with the half-cosine
    ramp ``r`` of :func:`seacable._ramp.smooth_ramp` (zero slope at both ends), and the distance run is
    its exact integral ``speed * (t / 2 - T sin(pi t / T) / (2 pi))`` for ``t < T``, ``speed (t - T / 2)``
    after.

    Parameters
    ----------
    speed
        Vessel speed over ground (after the ramp). [m/s]
    heading
        Course, from +X towards +Y. [rad]
    start
        Tow-point position (x, y) at t = 0. [m]
    ramp
        Duration T of the smooth start from rest; 0 for none. [s]
    """

    type: Literal["straight"] = "straight"
    speed: quantity("m/s", ge=0, fix="give the speed over ground in m/s (1 knot = 0.5144 m/s).") = Field(
        description="Vessel speed. [m/s]")

    def turn(self, rate: float | None = None, *, radius: float | None = None,
             direction: Literal["left", "right"] | None = None, start_time: float = 0.0,
             end_time: float | None = None) -> "TurnPath":
        """This path with a turn: at ``rate`` [rad/s] or on ``radius`` [m], from ``start_time`` [s]."""
        extra = {} if direction is None else {"direction": direction}
        return TurnPath(speed=self.speed, heading=self.heading, start=self.start, turn_rate=rate,
                        radius=radius, start_time=start_time, end_time=end_time, ramp=self.ramp, **extra)


class SpeedSchedule(_Headed):
    """Constant heading, speed piecewise linear in time.

    The speed is interpolated linearly between the table points and held
    constant before the first and after the last, so the distance run is
    piecewise quadratic in time. A stop-and-go manoeuvre is
    ``times=(0, 10, 20, 30, 40), speeds=(1, 1, 0, 0, 1)``.

    Parameters
    ----------
    times
        Times of the table points, strictly increasing, >= 0. [s]
    speeds
        Speeds at ``times``, >= 0. [m/s]
    heading
        Course, from +X towards +Y. [rad]
    start
        Tow-point position (x, y) at t = 0. [m]
    """

    type: Literal["speed_schedule"] = "speed_schedule"
    times: tuple[unit_float("s"), ...] = Field(min_length=1, description="Times of the table points. [s]")
    speeds: tuple[unit_float("m/s"), ...] = Field(min_length=1, description="Speeds at those times. [m/s]")

    @model_validator(mode="after")
    def _table(self):
        t, v = np.asarray(self.times, float), np.asarray(self.speeds, float)
        if t.size != v.size:
            raise ValueError(f"times and speeds must have the same length, got {t.size} and {v.size}. "
                             "Suggested fix: give one speed per time.")
        for name, values, unit in (("times", t, "s"), ("speeds", v, "m/s")):
            bad = ~np.isfinite(values) | (values < 0)
            if bad.any():
                i = int(np.argmax(bad))
                raise ValueError(f"{name}[{i}] must be a finite number >= 0 {unit}, "
                                 f"got {values[i]:g} {unit}. "
                                 "Suggested fix: give times from the start of the run and speeds over "
                                 "ground (0 for a stop).")
        steps = np.diff(t) <= 0
        if steps.any():
            i = int(np.argmax(steps)) + 1
            raise ValueError(f"times must be strictly increasing, got times[{i - 1}] = {t[i - 1]:g} s "
                             f"and times[{i}] = {t[i]:g} s. Suggested fix: sort the table by time and "
                             "drop repeated times.")
        return self


_TurnRate = quantity("rad/s", fix="give the rate of turn in rad/s (0.5 deg/s = 0.008727 rad/s).")
_Radius = quantity("m", gt=0, fix="give the turning radius in metres and the side in 'direction'.")


class TurnPath(_Headed, _SpeedRamp):
    """Straight, then a turn at constant speed and rate of turn, then straight.

    The vessel runs at ``heading`` until ``start_time``, turns on a circle of
    radius ``speed / |rate|`` until ``end_time`` (for ever if ``None``) and then
    runs straight on its new heading. Give exactly one of ``turn_rate`` or
    ``radius``. Paper 000's case is ``speed=1.0, turn_rate=math.radians(0.5)``.
    With ``ramp`` > 0 the vessel starts from rest on the first straight, its
    speed rising as in :class:`StraightPath`; the ramp must end by
    ``start_time``, so the turn is made at full speed on its circle.

    Parameters
    ----------
    speed
        Vessel speed over ground, kept through the turn. [m/s]
    heading
        Course before the turn, from +X towards +Y. [rad]
    start
        Tow-point position (x, y) at t = 0. [m]
    start_time
        Time at which the turn begins. [s]
    turn_rate
        Rate of turn; positive turns left (counter-clockwise seen from above),
        negative turns right. [rad/s]
    radius
        Turning radius, with ``direction``. [m]
    direction
        ``"left"`` or ``"right"``; with ``turn_rate`` it may be given only if it
        agrees with the rate's sign.
    end_time
        Time at which the turn ends, after ``start_time``; ``None`` keeps
        turning. [s]
    ramp
        Duration of the smooth start from rest, not after ``start_time``; 0 for
        none. [s]
    """

    type: Literal["turn"] = "turn"
    speed: quantity("m/s", ge=0, fix="give the speed over ground in m/s (1 knot = 0.5144 m/s).") = Field(
        description="Vessel speed. [m/s]")
    start_time: quantity("s", ge=0) = Field(0.0, description="Time the turn begins. [s]")
    turn_rate: _TurnRate | None = Field(None, description="Rate of turn, positive to the left. [rad/s]")
    radius: _Radius | None = Field(None, description="Turning radius. [m]")
    direction: Literal["left", "right"] = Field("left", description="Side the vessel turns to.")
    end_time: quantity("s", ge=0) | None = Field(None, description="Time the turn ends; none: never. [s]")

    @model_validator(mode="after")
    def _one_way_to_turn(self):
        if (self.turn_rate is None) == (self.radius is None):
            got = "both" if self.radius is not None else "neither"
            raise ValueError(f"needs exactly one of 'turn_rate' (rad/s) or 'radius' (m), got {got}. "
                             "Suggested fix: give 'turn_rate: 0.008727' (0.5 deg/s, positive = left) "
                             "or 'radius: 115.0' with 'direction: left'.")
        if self.turn_rate is not None:
            sign = "left" if self.turn_rate > 0 else "right" if self.turn_rate < 0 else None
            if "direction" in self.model_fields_set and sign is not None and self.direction != sign:
                raise ValueError(f"direction '{self.direction}' contradicts turn_rate = {self.turn_rate:g} "
                                 f"rad/s, which turns {sign} (positive = left, negative = right). "
                                 "Suggested fix: leave 'direction' out and give the rate its sign.")
            _warn_if_degrees("vessel.turn_rate", self.turn_rate, _RATE_LOOKS_LIKE_DEGREES)
        if self.ramp > self.start_time:
            raise ValueError(f"ramp ({self.ramp:g} s) must end by start_time ({self.start_time:g} s): the "
                             "turn is made at full speed. Suggested fix: set start_time to at least the ramp, "
                             f"e.g. start_time: {self.ramp:g}.")
        if self.end_time is not None and self.end_time <= self.start_time:
            raise ValueError(f"end_time must be > start_time = {self.start_time:g} s, got "
                             f"{self.end_time:g} s. Suggested fix: leave end_time out to keep turning.")
        return self

    @property
    def rate(self) -> float:
        """Signed rate of turn, positive to the left. [rad/s]"""
        if self.turn_rate is not None:
            return self.turn_rate
        return (1.0 if self.direction == "left" else -1.0) * self.speed / self.radius


class ZigZagPath(_Headed):
    """Constant speed on a constant heading with a sinusoidal sway across the course.

    The tow point is at

    .. math:: \\mathbf{x}(t) = \\mathbf{x}_0 + V t\\,\\mathbf{e}(\\psi)
              + A\\,r(t) \\sin(2\\pi t / T + \\phi)\\,\\mathbf{n}(\\psi),

    with :math:`\\mathbf{e} = (\\cos\\psi, \\sin\\psi)` the course,
    :math:`\\mathbf{n} = (-\\sin\\psi, \\cos\\psi)` its left normal and
    :math:`r(t) = (1 - \\cos(\\pi t / T_r))/2` for :math:`0 \\le t < T_r`, 1 after
    (:func:`seacable._ramp.smooth_ramp`, shared with the mooring motions), or :math:`r = 1` when
    ``ramp`` is 0. The ramp has zero slope at both ends, so with ``ramp > 0`` the
    sway velocity starts from zero and is continuous; with ``ramp = 0`` the sway
    velocity jumps to :math:`2\\pi A \\cos\\phi / T` at t = 0. The velocity is the
    exact time derivative of the position. Paper 003's case is
    ``speed=1.0289, amplitude=10.0, period=50.0`` (2 knots, 10 m, 50 s).

    Parameters
    ----------
    speed
        Forward speed along the course. [m/s]
    amplitude
        Sway amplitude across the course, > 0. [m]
    period
        Sway period, > 0. [s]
    phase
        Phase of the sine at t = 0; 0 starts on the course line swaying to the
        left. [rad]
    ramp
        Duration of the smooth start of the sway amplitude; 0 for none. [s]
    heading
        Course, from +X towards +Y. [rad]
    start
        Tow-point position (x, y) at t = 0 (plus the sway ``A sin(phase)``
        when ``ramp`` is 0). [m]
    """

    type: Literal["zigzag"] = "zigzag"
    speed: quantity("m/s", ge=0, fix="give the speed over ground in m/s (1 knot = 0.5144 m/s).") = Field(
        description="Forward speed along the course. [m/s]")
    amplitude: quantity("m", gt=0, fix="give the sway amplitude in metres (half the peak-to-peak "
                                       "sway), e.g. 10.0; use type 'straight' for no sway.") = Field(
        description="Sway amplitude across the course. [m]")
    period: quantity("s", gt=0, fix="give the sway period in seconds, e.g. 50.0.") = Field(
        description="Sway period. [s]")
    phase: quantity("rad") = Field(0.0, description="Phase of the sway at t = 0. [rad]")
    ramp: quantity("s", ge=0, fix="give the duration of the smooth start in seconds, 0 for none.") = Field(
        0.0, description="Duration of the smooth start of the sway amplitude. [s]")

    @model_validator(mode="after")
    def _phase_in_radians(self):
        _warn_if_degrees("vessel.phase", self.phase, 2 * math.pi)
        return self


class TablePath(_Planar):
    """Tow-point positions or velocities read from a CSV file.

    The file has a header row and the columns ``time`` [s] and either ``x, y``
    [m] (``kind="position"``, optional ``z``) or ``u, v`` [m/s]
    (``kind="velocity"``, optional ``w``); other columns are ignored and
    names are matched without regard to case or surrounding blanks. Each column
    is interpolated in time with a not-a-knot cubic spline
    (:class:`scipy.interpolate.CubicSpline`). A position table gives the
    velocity as the spline's derivative; ``start`` shifts its x, y. A velocity
    table is integrated with the spline's antiderivative from ``start`` (and
    z = 0) at the table's first time. Times outside the table are refused.

    Parameters
    ----------
    file
        CSV file, relative to the case file's folder (``base_dir`` of
        :func:`sample_path`) or else to the current directory.
    kind
        ``"position"`` or ``"velocity"``: what the table holds.
    start
        Position kind: shift added to x, y; velocity kind: position (x, y) at
        the table's first time. [m]
    """

    type: Literal["table"] = "table"
    file: str = Field(min_length=1, description="CSV file of the path.")
    kind: Literal["position", "velocity"] = Field(description="What the table holds.")


VESSEL_PATHS = (StraightPath, SpeedSchedule, TurnPath, ZigZagPath, TablePath)
VesselPath = Annotated[Union[VESSEL_PATHS], Field(discriminator="type")]
UNION_TAGS.update(cls.model_fields["type"].default for cls in VESSEL_PATHS)

_ADAPTER = TypeAdapter(VesselPath)


def parse_vessel_path(data: Any, *, root: str = "vessel"):
    """Validate plain data (as read from a case file) into one of :data:`VESSEL_PATHS`.

    Parameters
    ----------
    data
        A mapping with a ``type`` key (``straight``, ``speed_schedule``,
        ``turn``, ``zigzag`` or ``table``) and the fields of that path.
    root
        A prefix for the key paths in error messages.

    Raises
    ------
    InputError
        If the data do not describe a valid path.
    """
    try:
        return _ADAPTER.validate_python(data)
    except ValidationError as err:
        raise input_error(_problems(err), root) from None


# ----------------------------------------------------------------------------------------------
# Closed forms
# ----------------------------------------------------------------------------------------------

def _ramped_time(t, ramp):
    """``R(t) = int_0^t r`` and ``r(t)`` of the half-cosine ramp (R = t, r = 1 without one). [s, -]

    With the speed ``V r(t)`` the distance run is ``V R(t)``; before t = 0 a ramped path is at rest.
    """
    t = np.asarray(t, float)
    if ramp <= 0:
        return t, np.ones_like(t)
    r, _, _ = smooth_ramp(t, ramp)
    tc = np.clip(t, 0.0, ramp)
    inside = 0.5 * tc - ramp / (2.0 * math.pi) * np.sin(math.pi * tc / ramp)
    return inside + np.maximum(t - ramp, 0.0), r


def _straight(t, speed, heading, start, ramp=0.0):
    direction = np.array([math.cos(heading), math.sin(heading), 0.0])
    run, r = _ramped_time(t, ramp)
    pos = np.array([start[0], start[1], 0.0]) + speed * run[:, None] * direction
    vel = (speed * r)[:, None] * direction
    return pos, vel


def _schedule_distance(t, times, speeds):
    """Distance run since ``times[0]`` and speed at ``t``: piecewise quadratic / linear."""
    knots, v = np.asarray(times, float), np.asarray(speeds, float)
    accel = np.zeros_like(v)
    accel[:-1] = np.diff(v) / np.diff(knots)
    run = np.concatenate([[0.0], np.cumsum(0.5 * (v[:-1] + v[1:]) * np.diff(knots))])
    k = np.clip(np.searchsorted(knots, t, side="right") - 1, 0, knots.size - 1)
    tau = t - knots[k]
    a = np.where(t < knots[0], 0.0, accel[k])  # constant speed before the first point
    return run[k] + v[k] * tau + 0.5 * a * tau**2, v[k] + a * tau


def _turn(t, path: TurnPath):
    """Positions and velocities of a straight-turn-straight path (exact circular arcs)."""
    speed, psi0, rate = path.speed, path.heading, path.rate
    # time on the first straight at full speed (negative before t = 0), after the speed ramp
    before, ramp_speed = _ramped_time(np.minimum(t, path.start_time), path.ramp)
    turning = np.maximum(t - path.start_time, 0.0)
    after = np.zeros_like(t)
    if path.end_time is not None:
        duration = path.end_time - path.start_time
        after = np.maximum(turning - duration, 0.0)
        turning = np.minimum(turning, duration)
    half = 0.5 * rate * turning
    # Arc chord: x - x_s = (V/r)(sin psi - sin psi0) = V tau sinc(r tau / 2) cos(psi0 + r tau / 2),
    # y - y_s = -(V/r)(cos psi - cos psi0) = V tau sinc(r tau / 2) sin(psi0 + r tau / 2);
    # the sinc form is exact and stays accurate as r -> 0. np.sinc(x) = sin(pi x)/(pi x).
    chord = speed * turning * np.sinc(half / np.pi)
    psi = psi0 + rate * turning
    x = (path.start[0] + speed * before * math.cos(psi0) + chord * np.cos(psi0 + half)
         + speed * after * np.cos(psi))
    y = (path.start[1] + speed * before * math.sin(psi0) + chord * np.sin(psi0 + half)
         + speed * after * np.sin(psi))
    pos = np.stack([x, y, np.zeros_like(t)], axis=-1)
    vel = np.stack([speed * np.cos(psi), speed * np.sin(psi), np.zeros_like(t)], axis=-1)
    vel[:, :2] *= np.where(t < path.start_time, ramp_speed, 1.0)[:, None]
    return pos, vel


# ----------------------------------------------------------------------------------------------
# Tables
# ----------------------------------------------------------------------------------------------

def _table_error(where: str, problem: str, fix: str) -> InputError:
    return InputError(f"vessel table file '{where}': {problem} Suggested fix: {fix}")


def _resolve(file: str, base_dir) -> Path:
    path = Path(file).expanduser()
    if not path.is_absolute():
        path = Path(base_dir if base_dir is not None else os.getcwd()) / path
    return path


def _load_table(resolved: str, kind: str) -> tuple[np.ndarray, np.ndarray]:
    """Read and check a path table: time (n,) and the 2 or 3 value columns (n, k)."""
    columns = ("x", "y", "z") if kind == "position" else ("u", "v", "w")
    unit = "m" if kind == "position" else "m/s"
    from .._text import read_text_file

    text = read_text_file(resolved, "vessel table file", "give a UTF-8 CSV file, its path relative to the case "
                                                         "file's folder")
    rows = list(csv.reader(io.StringIO(text, newline="")))
    numbered = [(i + 1, row) for i, row in enumerate(rows) if any(cell.strip() for cell in row)]
    if not numbered:
        raise _table_error(resolved, "is empty.", f"write a header row 'time,{columns[0]},{columns[1]}' "
                                                  "and at least two rows of numbers.")
    header = [cell.strip().lower() for cell in numbered[0][1]]
    wanted = ["time", columns[0], columns[1]] + ([columns[2]] if columns[2] in header else [])
    missing = [name for name in wanted if name not in header]
    if missing:
        raise _table_error(resolved, f"has no column {', '.join(repr(m) for m in missing)} for a "
                                     f"{kind} table (header: {', '.join(header)}).",
                           f"name the columns time, {columns[0]}, {columns[1]} in the header row, "
                           f"or set 'kind' if the table holds "
                           f"{'velocities' if kind == 'position' else 'positions'}.")
    index = [header.index(name) for name in wanted]
    data = np.empty((len(numbered) - 1, len(wanted)))
    for r, (line, row) in enumerate(numbered[1:]):
        for c, (name, j) in enumerate(zip(wanted, index)):
            cell = row[j].strip() if j < len(row) else ""
            try:
                value = float(cell)
            except ValueError:
                value = None
            if value is None or not math.isfinite(value):
                raise _table_error(resolved, f"line {line}, column '{name}' holds {cell!r}, not a finite "
                                             "number.", "fill in every cell with a number in SI units "
                                                        f"({'s' if name == 'time' else unit}).")
            data[r, c] = value
    if data.shape[0] < 2:
        raise _table_error(resolved, f"has {data.shape[0]} row(s) of numbers; a path needs at least 2.",
                           "give the path at two or more times.")
    steps = np.diff(data[:, 0]) <= 0
    if steps.any():
        r = int(np.argmax(steps)) + 1
        raise _table_error(resolved, f"column 'time' must be strictly increasing, but line "
                                     f"{numbered[r + 1][0]} has t = {data[r, 0]:g} s after "
                                     f"t = {data[r - 1, 0]:g} s.", "sort the rows by time and drop repeats.")
    return data[:, 0], data[:, 1:]


def _splines(resolved: Path, kind: str):
    """Table times and the (position, velocity) splines; cached until the file changes."""
    try:
        info = resolved.stat()
        stamp = (info.st_mtime_ns, info.st_size)
    except OSError:
        stamp = ()  # _load_table reports the missing file
    return _table_spline(str(resolved), kind, stamp)


@functools.lru_cache(maxsize=32)
def _table_spline(resolved: str, kind: str, stamp: tuple):  # stamp: part of the cache key
    from scipy.interpolate import CubicSpline

    time, values = _load_table(resolved, kind)
    spline = CubicSpline(time, values, axis=0)
    if kind == "position":
        return time, (spline, spline.derivative())
    return time, (spline.antiderivative(), spline)


def _zigzag(t, path: ZigZagPath):
    """Positions and velocities of a zig-zag path: straight run plus a ramped sine across it."""
    pos, vel = _straight(t, path.speed, path.heading, path.start)
    normal = np.array([-math.sin(path.heading), math.cos(path.heading), 0.0])
    omega = 2.0 * math.pi / path.period
    arg = omega * t + path.phase
    r, dr, _ = smooth_ramp(t, path.ramp)
    sway = path.amplitude * r * np.sin(arg)
    sway_rate = path.amplitude * (dr * np.sin(arg) + r * omega * np.cos(arg))
    return pos + sway[:, None] * normal, vel + sway_rate[:, None] * normal


def _table(t, path: TablePath, base_dir):
    resolved = _resolve(path.file, base_dir)
    time, (position, velocity) = _splines(resolved, path.kind)
    span = time[-1] - time[0]
    slack = 1e-9 * max(span, 1.0)  # round-off in times computed as n * dt
    if t.size and t.max() > time[-1] + slack:
        raise InputError(f"vessel table file '{resolved}': the run lasts until t = {t.max():g} s but the "
                         f"table ends at {time[-1]:g} s. Suggested fix: extend the table or shorten the "
                         "run's duration.")
    if t.size and t.min() < time[0] - slack:
        raise InputError(f"vessel table file '{resolved}': the run starts at t = {t.min():g} s but the "
                         f"table begins at {time[0]:g} s. Suggested fix: start the table at t = 0 s.")
    tc = np.clip(t, time[0], time[-1])
    pos3, vel3 = np.zeros((t.size, 3)), np.zeros((t.size, 3))
    pos, vel = position(tc), velocity(tc)
    if path.kind == "velocity":
        pos = pos - position(time[0])
    k = pos.shape[1]
    pos3[:, :k], vel3[:, :k] = pos, vel
    pos3[:, :2] += np.asarray(path.start, float)
    return pos3, vel3


# ----------------------------------------------------------------------------------------------
# Public function
# ----------------------------------------------------------------------------------------------

def sample_path(path: VesselPath, times, base_dir=None) -> tuple[np.ndarray, np.ndarray]:
    """Tow-point positions (n, 3) [m] and velocities (n, 3) [m/s] at ``times`` [s] (shape (n,)).

    Parameters
    ----------
    path
        One of :data:`VESSEL_PATHS` (or a mapping with a ``type`` key, parsed
        with :func:`parse_vessel_path`).
    times
        Times, a scalar or a 1-D array, any order. [s]
    base_dir
        Folder against which a :class:`TablePath`'s relative ``file`` is
        resolved, normally the case file's folder; default the current
        directory.

    Returns
    -------
    positions : numpy.ndarray
        Tow-point position (x, y, z), shape (n, 3). [m]
    velocities : numpy.ndarray
        Tow-point velocity, the time derivative of ``positions``, shape (n, 3). [m/s]

    Raises
    ------
    InputError
        If ``times`` hold NaN or are not 1-D, or a table cannot be read or does
        not cover ``times``.

    Notes
    -----
    Straight path: :math:`\\mathbf{x} = \\mathbf{x}_0 + V t\\,\\mathbf{e}(\\psi_0)`. Speed schedule:
    the distance :math:`s(t) = \\int_0^t V\\,d\\tau` is piecewise quadratic. Turn at rate
    :math:`r` from :math:`t_s`: :math:`\\psi = \\psi_0 + r(t - t_s)`,
    :math:`x = x_s + (V/r)(\\sin\\psi - \\sin\\psi_0)`,
    :math:`y = y_s - (V/r)(\\cos\\psi - \\cos\\psi_0)`, evaluated in the equivalent
    chord form :math:`V\\tau\\,\\mathrm{sinc}(r\\tau/2)(\\cos, \\sin)(\\psi_0 + r\\tau/2)`, exact
    also as :math:`r \\to 0`. Zig-zag: the straight path plus
    :math:`A\\,r(t)\\sin(2\\pi t/T + \\phi)` along the left normal
    :math:`(-\\sin\\psi_0, \\cos\\psi_0)`, with the half-cosine ramp :math:`r(t)` of
    :class:`ZigZagPath`; the velocity is its exact derivative (product rule).

    References
    ----------
    .. [1] Paper 000 of ``shared/seeds`` (turning tow, 0.5 deg/s to the left).
    .. [2] Paper 003 of ``shared/seeds`` (zig-zag tow, 2 knots, 10 m, 50 s).
    """
    if isinstance(path, dict):
        path = parse_vessel_path(path)
    if not isinstance(path, VESSEL_PATHS):
        raise InputError(f"path must be one of {', '.join(c.__name__ for c in VESSEL_PATHS)}, got "
                         f"{type(path).__name__}. Suggested fix: build it, e.g. StraightPath(speed=1.0).")
    t = np.asarray(finite("times", times, "s", "give finite times in seconds."), dtype=float)
    if t.ndim > 1:
        raise InputError(f"times must be a scalar or a 1-D array, got shape {t.shape}. "
                         "Suggested fix: pass times.ravel().")
    t = np.atleast_1d(t)
    if isinstance(path, StraightPath):
        return _straight(t, path.speed, path.heading, path.start, path.ramp)
    if isinstance(path, SpeedSchedule):
        run, speed = _schedule_distance(t, path.times, path.speeds)
        run0, _ = _schedule_distance(np.zeros(1), path.times, path.speeds)
        e = np.array([math.cos(path.heading), math.sin(path.heading), 0.0])
        pos = np.array([path.start[0], path.start[1], 0.0]) + (run - run0)[:, None] * e
        return pos, speed[:, None] * e
    if isinstance(path, TurnPath):
        return _turn(t, path)
    if isinstance(path, ZigZagPath):
        return _zigzag(t, path)
    return _table(t, path, base_dir)


def initial_heading(path: VesselPath, duration: float, distance: float, base_dir=None) -> float:
    """Direction in which the tow point sets off: from its position at t = 0 to where it is first
    ``distance`` away (horizontally). [rad]

    A line laid out at rest behind a vessel belongs astern of where the vessel goes, and that is
    the direction of its displacement, not of its velocity at t = 0: a vessel starting from rest has
    no velocity there, and the velocity of a table's spline at t = 0 is a fitting artefact that may
    point anywhere (a position table of a tug starting from rest gave -2.7e-5 m/s, and a barge laid
    430 m ahead of the tug). The same for every kind of path; for a path moving at t = 0 it agrees
    with the velocity's direction to within ``distance`` times the path's curvature.

    Parameters
    ----------
    path
        One of :data:`VESSEL_PATHS`.
    duration
        The run's duration; the path is searched from 0 to this time (a table to its end). [s]
    distance
        The small distance that counts as setting off, > 0. [m]
    base_dir
        Folder of a table path's file, as in :func:`sample_path`.

    Returns
    -------
    float
        Heading from +X towards +Y, in (-pi, pi]; a path that never moves ``distance`` in the run
        gives its ``heading`` (0 for a table that does not move). [rad]
    """
    end = float(duration)
    if isinstance(path, TablePath):  # a short run on a long table: look as far as the table goes
        end = max(end, float(_splines(_resolve(path.file, base_dir), path.kind)[0][-1]))
    times = np.linspace(0.0, end, 4097)
    pos, _ = sample_path(path, times, base_dir)
    p0 = pos[0, :2]
    far = np.hypot(*(pos[:, :2] - p0).T) > distance
    if not far.any():
        return float(getattr(path, "heading", 0.0))
    i = int(np.argmax(far))
    lo, hi = times[i - 1], times[i]
    for _ in range(40):  # bisection for the time the path is first `distance` away
        mid = 0.5 * (lo + hi)
        pm, _ = sample_path(path, np.array([mid]), base_dir)
        if math.hypot(*(pm[0, :2] - p0)) > distance:
            hi = mid
        else:
            lo = mid
    ph, _ = sample_path(path, np.array([hi]), base_dir)
    d = ph[0, :2] - p0
    return float(math.atan2(d[1], d[0]))

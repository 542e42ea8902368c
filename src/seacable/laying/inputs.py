"""Inputs of the ``laying_dynamic`` analysis: ship motion, payout control and bathymetry.

x runs along the ship's track (the ship moves towards +x), z is up with 0 at the sea surface.
"""

from __future__ import annotations

import bisect
import math
from typing import Annotated, Literal

import numpy as np
from pydantic import Field, model_validator

from .._model import UNION_TAGS, Model, quantity, unit_float
from .._text import csv_rows
from ..errors import InputError

__all__ = [
    "Bathymetry",
    "LayTableFile",
    "LayTarget",
    "Payout",
    "PayoutBottomTension",
    "PayoutRate",
    "PayoutSlack",
    "PlanShip",
    "ShipMotion",
    "schedule_value",
]


def _check_schedule(times, values, name: str, unit: str) -> None:
    """Both or neither; equal lengths; times strictly increasing from >= 0; values finite and >= 0."""
    if times is None and values is None:
        return
    if times is None or values is None:
        raise ValueError(f"needs both 'times' and '{name}' for a schedule, or neither. "
                         "Suggested fix: give two lists of equal length.")
    t, v = np.asarray(times, float), np.asarray(values, float)
    if t.size != v.size or t.size < 1:
        raise ValueError(f"times and {name} must have the same non-zero length, got {t.size} and {v.size}.")
    bad = ~np.isfinite(v) | (v < 0)
    if bad.any():
        i = int(np.argmax(bad))
        raise ValueError(f"{name}[{i}] must be a finite number >= 0 {unit}, got {v[i]:g} {unit}.")
    if not np.all(np.isfinite(t)) or np.any(t < 0) or np.any(np.diff(t) <= 0):
        raise ValueError(f"times must be finite, >= 0 s and strictly increasing, got {[float(v) for v in t]} s. "
                         "Suggested fix: sort the table by time and drop repeated times.")


def schedule_value(t: float, constant, times, values) -> float:
    """A constant, or a table linear in time and held constant beyond its ends."""
    if times is None:
        return float(constant)
    return float(np.interp(t, times, values))


class ShipMotion(Model):
    """The cable ship: its speed over ground, constant or scheduled, and repeater slow-downs.

    Parameters
    ----------
    speed
        Constant speed, when no schedule is given. [m/s]
    times, speeds
        Speed schedule, linear between the points and constant beyond. [s], [m/s]
    start_x
        Water-entry point at t = 0: its x, or its KP along a route. [m]
    repeater_speed
        Speed while a repeater descends (from its water entry to its touchdown); ``None`` keeps the
        scheduled speed. [m/s]
    acceleration
        Largest rate of change of the speed when slowing down for a repeater and recovering. [m/s^2]
    """

    speed: quantity("m/s", ge=0, fix="give the ship speed over ground, e.g. 2.0 m/s.") | None = Field(
        None, description="Constant ship speed. [m/s]")
    times: tuple[unit_float("s"), ...] | None = Field(None, description="Times of the speed schedule. [s]")
    speeds: tuple[unit_float("m/s"), ...] | None = Field(None, description="Speeds of the schedule. [m/s]")
    start_x: quantity("m") = Field(0.0, description="Water-entry x at t = 0 (its KP along a route). [m]")
    repeater_speed: quantity("m/s", ge=0) | None = Field(
        None, description="Ship speed while a repeater descends. [m/s]")
    acceleration: quantity("m/s^2", gt=0, fix="a cable ship changes speed at about 0.01-0.1 m/s^2.") = Field(
        0.02, description="Rate of the speed change for repeaters. [m/s^2]")

    @model_validator(mode="after")
    def _check(self):
        _check_schedule(self.times, self.speeds, "speeds", "m/s")
        if (self.speed is None) == (self.times is None):
            raise ValueError("give either 'speed' (m/s) or a schedule 'times' (s) and 'speeds' (m/s). "
                             "Suggested fix: 'ship: {speed: 2.0}'.")
        return self

    def scheduled(self, t: float) -> float:
        """Scheduled speed at time ``t``. [m/s]"""
        return schedule_value(t, self.speed, self.times, self.speeds)


class PayoutRate(Model):
    """Payout at a given speed, constant or scheduled (speed of the cable engine)."""

    type: Literal["rate"] = "rate"
    speed: quantity("m/s", ge=0) | None = Field(None, description="Constant payout speed. [m/s]")
    times: tuple[unit_float("s"), ...] | None = Field(None, description="Times of the payout schedule. [s]")
    speeds: tuple[unit_float("m/s"), ...] | None = Field(None, description="Payout speeds of the schedule. [m/s]")

    @model_validator(mode="after")
    def _check(self):
        _check_schedule(self.times, self.speeds, "speeds", "m/s")
        if (self.speed is None) == (self.times is None):
            raise ValueError("give either 'speed' (m/s) or a schedule 'times' (s) and 'speeds' (m/s).")
        return self


class PayoutSlack(Model):
    """Payout that keeps a target slack: payout speed = (1 + slack) x ship speed on a flat seabed.

    With ``slope_compensation`` the payout follows the seabed as the paper's CPRATE does: the laid
    length per metre run is ``(1 + slack) / cos(beta)`` for a seabed slope ``beta`` at the
    touchdown, and the suspended length ``h / sin(alpha)`` changes with the depth ``h`` there.
    """

    type: Literal["slack"] = "slack"
    slack: quantity("-", ge=0.0, le=1.0, fix="slack is a ratio, 0.05 for 5 % slack; a lay under tension on the "
                    "seabed (slack below zero) is the payout type 'bottom_tension'.") = Field(
        0.0, description="Target slack, laid length over seabed distance minus one, 0 to 1. [-]")
    slope_compensation: bool = Field(True, description="Adjust the payout to the seabed slope (CPRATE).")


class PayoutBottomTension(Model):
    """Payout controlled to hold a target tension at the touchdown point.

    The payout speed is the slack-free feed-forward ``V_s / cos(beta) / (1 + T_0/EA)`` corrected by
    ``gain (e + integral(e dt) / integral_time)`` times it, ``e = (T_b - T_0) / (w h)``, ``T_b`` being the bottom
    tension low-pass filtered with ``time_constant`` (no integral term without an ``integral_time``).
    """

    type: Literal["bottom_tension"] = "bottom_tension"
    tension: quantity("N", ge=0, fix="give the touchdown tension in newtons.") = Field(
        description="Target bottom tension. [N]")
    gain: quantity("-", gt=0) = Field(1.0, description="Proportional gain on (T_b - T_0) / (w h). [-]")
    time_constant: quantity("s", gt=0) = Field(10.0, description="Filter time of the bottom tension. [s]")
    integral_time: quantity("s", gt=0) | None = Field(
        None, description="Integral time of the control (PI): without it the proportional control holds the bottom "
                          "tension off its target wherever the feed-forward misjudges the payout, as over laid cable "
                          "that slides. [s]")


Payout = Annotated[PayoutRate | PayoutSlack | PayoutBottomTension, Field(discriminator="type")]
UNION_TAGS.update(cls.model_fields["type"].default for cls in (PayoutRate, PayoutSlack, PayoutBottomTension))


class Bathymetry(Model):
    """Water depth along the track: a table (inline or a CSV file with columns distance, depth).

    Linear between the points, constant beyond the ends.
    """

    distance: tuple[unit_float("m"), ...] | None = Field(None, description="Distances along the track. [m]")
    depth: tuple[unit_float("m"), ...] | None = Field(None, description="Water depths at those distances. [m]")
    file: str | None = Field(None, description="CSV file with columns 'distance' and 'depth' (relative "
                                               "to the case file).")

    @model_validator(mode="after")
    def _check(self):
        inline = self.distance is not None or self.depth is not None
        if inline == (self.file is not None):
            raise ValueError("give either 'distance' and 'depth' lists (m) or a CSV 'file'.")
        if inline:
            _check_table(self.distance, self.depth, "bathymetry")
        return self

    def table(self) -> tuple[np.ndarray, np.ndarray]:
        """(distance, depth) arrays, reading the file if there is one. [m]"""
        if self.file is None:
            return np.asarray(self.distance, float), np.asarray(self.depth, float)
        return _read_table(self.file)


def _check_table(distance, depth, where: str) -> None:
    if distance is None or depth is None:
        raise ValueError("needs both 'distance' and 'depth'.")
    x, h = np.asarray(distance, float), np.asarray(depth, float)
    if x.size != h.size or x.size < 2:
        raise ValueError(f"{where}: distance and depth must have the same length >= 2, got {x.size} and "
                         f"{h.size}.")
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(h))):
        raise ValueError(f"{where}: distances and depths must be finite numbers [m].")
    if np.any(np.diff(x) <= 0):
        raise ValueError(f"{where}: distances must be strictly increasing, got {[float(v) for v in x]} m. "
                         "Suggested fix: sort the table by distance.")
    if np.any(h <= 0):
        i = int(np.argmax(h <= 0))
        raise ValueError(f"{where}: depth[{i}] must be > 0 m, got {h[i]:g} m. Suggested fix: give depths "
                         "below the surface as positive numbers.")


def _kp_table(kp, values, name: str, unit: str, where: str) -> None:
    """A table by KP: equal lengths >= 1, KP strictly increasing, values finite and >= 0."""
    k, v = np.asarray(kp, float), np.asarray(values, float)
    if k.size != v.size or k.size < 1:
        raise ValueError(f"{where}: kp and {name} must have the same non-zero length, got {k.size} and {v.size}.")
    if not np.all(np.isfinite(k)) or np.any(np.diff(k) <= 0):
        raise ValueError(f"{where}: kp must be finite and strictly increasing, got {[float(v) for v in k]} m. "
                         "Suggested fix: sort the table by KP.")
    bad = ~np.isfinite(v) | (v < 0)
    if bad.any():
        i = int(np.argmax(bad))
        raise ValueError(f"{where}: {name}[{i}] must be a finite number >= 0 {unit}, got {v[i]:g} {unit}.")


class PlanShip(Model):
    """The ship of a lay plan: its speed over ground, constant or by KP, and the repeater slow-down.

    Parameters
    ----------
    speed
        Constant speed. [m/s]
    kp, speeds
        Speed by ship KP instead, linear between the points and constant beyond. [m], [m/s]
    repeater_speed
        Speed while a repeater descends (water entry to touchdown); ``None``: no slow-down. [m/s]
    acceleration
        Rate of the speed changes for repeaters. [m/s^2]
    """

    speed: quantity("m/s", gt=0, fix="give the ship speed over ground, e.g. 1.5 m/s.") | None = Field(
        None, description="Constant ship speed. [m/s]")
    kp: tuple[unit_float("m"), ...] | None = Field(None, description="Ship KPs of the speed table. [m]")
    speeds: tuple[unit_float("m/s"), ...] | None = Field(None, description="Ship speeds of the table. [m/s]")
    repeater_speed: quantity("m/s", gt=0, fix="a cable ship slows to about 0.3-0.8 m/s for a repeater.") | None = \
        Field(None, description="Ship speed while a repeater descends. [m/s]")
    acceleration: quantity("m/s^2", gt=0, fix="a cable ship changes speed at about 0.01-0.1 m/s^2.") = Field(
        0.02, description="Rate of the speed change for repeaters. [m/s^2]")

    @model_validator(mode="after")
    def _check(self):
        if (self.speed is None) == (self.kp is None and self.speeds is None):
            raise ValueError("give either 'speed' (m/s) or a table 'kp' (m) and 'speeds' (m/s). Suggested fix: "
                             "'ship: {speed: 1.5}'.")
        if self.speed is None:
            if self.kp is None or self.speeds is None:
                raise ValueError("a speed table needs both 'kp' (m) and 'speeds' (m/s).")
            _kp_table(self.kp, self.speeds, "speeds", "m/s", "ship")
            if min(self.speeds) <= 0:
                raise ValueError(f"ship.speeds must be > 0 m/s, got {min(self.speeds):g} m/s: a lay plan needs a "
                                 "moving ship. Suggested fix: give the speed over ground of each stretch.")
        fastest = self.speed if self.speed is not None else max(self.speeds)
        if self.repeater_speed is not None and self.repeater_speed > fastest:
            raise ValueError(f"ship.repeater_speed {self.repeater_speed:g} m/s is above the ship's speed "
                             f"({fastest:g} m/s{' at its fastest' if self.speed is None else ''}): it is the speed "
                             "the ship slows to while a repeater descends. Suggested fix: a repeater_speed below "
                             "the ship speed (0.3-0.8 m/s is usual), or leave it out for no slow-down.")
        return self

    def at(self, kp) -> np.ndarray:
        """Scheduled speed at ship KPs. [m/s]"""
        kp = np.asarray(kp, float)
        if self.speed is not None:
            return np.full(kp.shape, float(self.speed))
        return np.interp(kp, self.kp, self.speeds)


class LayTableFile(Model):
    """A lay plan's table to follow: the CSV ``seacable run`` writes for a ``lay_plan`` (``NAME_lay_table.csv``),
    from its first row or from the ship KP ``start_kp`` (a lay taken up mid-route)."""

    file: str = Field(description="The lay table CSV (relative to the case file).")
    start_kp: float | None = Field(None, description="Ship KP to follow the table from (default its first). [m]")


class LayTarget(Model):
    """What the lay holds on the seabed: a slack or a bottom tension, constant or by touchdown KP.

    Parameters
    ----------
    slack
        Laid cable length over the seabed distance, minus one (0.03: 3 % slack). [-]
    bottom_tension
        Tension at the touchdown instead. [N]
    kp
        KPs of a table of either (the values then are lists), linear between and constant beyond. [m]
    """

    slack: float | tuple[float, ...] | None = Field(None, description="Target slack, >= 0. [-]")
    bottom_tension: float | tuple[float, ...] | None = Field(None, description="Target bottom tension. [N]")
    kp: tuple[unit_float("m"), ...] | None = Field(None, description="KPs of a target table. [m]")

    @model_validator(mode="after")
    def _check(self):
        if (self.slack is None) == (self.bottom_tension is None):
            raise ValueError("give one target: 'slack' (e.g. 0.03 for 3 %) or 'bottom_tension' (N).")
        name, unit = ("slack", "(a ratio)") if self.slack is not None else ("bottom_tension", "N")
        value = getattr(self, name)
        if self.kp is None:
            if isinstance(value, tuple):
                raise ValueError(f"target.{name} is a list: give its KPs in target.kp (m), or one number.")
            values = (value,)
        else:
            if not isinstance(value, tuple):
                raise ValueError(f"target.kp is given: target.{name} must be a list of the same length.")
            values = value
            _kp_table(self.kp, [abs(v) for v in value], name, unit, "target")
        for i, v in enumerate(values):
            if not math.isfinite(v) or v < 0:
                what = ("a slack below zero is a cable under tension on the seabed; Suggested fix: give slack >= 0 "
                        "(0.03 for 3 %), or a bottom_tension (N) for a lay under tension"
                        if name == "slack" else "Suggested fix: give the touchdown tension in N, >= 0")
                raise ValueError(f"target.{name}{f'[{i}]' if self.kp is not None else ''} must be a finite number >= 0 "
                                 f"{unit}, got {v:g}: {what}.")
            if name == "slack" and v > 1.0:
                raise ValueError(f"target.slack {v:g} is {100 * v:g} %: slack is a ratio (0.03 for 3 %). Suggested "
                                 "fix: give it as a fraction.")
        return self

    def at(self, kp) -> np.ndarray:
        """The target at KPs. [-] or [N]"""
        value = self.slack if self.slack is not None else self.bottom_tension
        kp = np.asarray(kp, float)
        if self.kp is None:
            return np.full(kp.shape, float(value))
        return np.interp(kp, self.kp, value)


def read_lay_table(file: str) -> dict[str, np.ndarray]:
    """The columns of a lay table CSV (``seacable run`` of a ``lay_plan`` writes one): ``kp``, ``time``,
    ``ship_speed`` and ``payout_speed`` (headers may carry their units in brackets, ``time [s]``). The
    times must increase and the speeds be > 0."""
    path, header, rows = csv_rows(file, "lay table")
    names = [h.split("[")[0].strip() for h in header]
    need = ("kp", "time", "ship_speed", "payout_speed")
    missing = [n for n in need if n not in names]
    if missing:
        raise InputError(f"lay table '{path}' needs the columns {', '.join(need)} (a lay_plan's NAME_lay_table.csv); "
                         f"{', '.join(missing)} missing. Suggested fix: give the table seacable run wrote for the plan.")
    try:
        cols = {n: np.array([float(r[names.index(n)]) for r in rows[1:]]) for n in need}
    except (ValueError, IndexError):
        raise InputError(f"lay table '{path}': every row needs numbers in {', '.join(need)}.") from None
    t, v, c = cols["time"], cols["ship_speed"], cols["payout_speed"]
    if t.size < 1 or not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0):
        raise InputError(f"lay table '{path}': the times must be finite and increase row by row (s).")
    for name, values in (("ship_speed", v), ("payout_speed", c)):
        if not np.all(np.isfinite(values)) or np.any(values < 0) or (name == "ship_speed" and np.any(values <= 0)):
            i = int(np.argmax(~np.isfinite(values) | (values <= (0 if name == "ship_speed" else -1e-300))))
            raise InputError(f"lay table '{path}': {name} in row {i + 1} is {values[i]:g} m/s, must be a finite number "
                             f"{'> 0' if name == 'ship_speed' else '>= 0'} m/s.")
    return cols


def sinking_weights(line, water_density: float, gravity: float) -> list[float]:
    """Weight in water per length of each segment of a cable to be laid; an InputError for one that does not
    sink. [N/m]"""
    weights = []
    for k, seg in enumerate(line.segments):
        w = seg.line_type.submerged_weight(water_density, gravity)
        if not w > 0:
            raise InputError(f"line.segments[{k}] weighs {w:.6g} N/m in water: a laid cable must sink (weight in "
                             "water > 0). Suggested fix: check mass_per_length, diameter and weight_in_water.")
        weights.append(w)
    return weights


def _read_table(file: str) -> tuple[np.ndarray, np.ndarray]:
    path, header, rows = csv_rows(file, "bathymetry file")
    along = "distance" if "distance" in header else "kp"
    if along not in header or "depth" not in header:
        raise InputError(f"bathymetry file '{path}' needs a header row with columns 'distance' (or 'kp') and "
                         f"'depth', got {', '.join(header) or 'an empty file'}.")
    i, j = header.index(along), header.index("depth")
    try:
        values = np.array([[float(r[i]), float(r[j])] for r in rows[1:]], dtype=float).reshape(-1, 2)
    except (ValueError, IndexError):
        raise InputError(f"bathymetry file '{path}': every row needs numbers in the 'distance' and 'depth' "
                         "columns (m).") from None
    try:
        _check_table(values[:, 0], values[:, 1], f"bathymetry file '{path}'")
    except ValueError as err:
        raise InputError(str(err)) from None
    return values[:, 0], values[:, 1]


class Seabed2D:
    """Seabed elevation along the track: a plane (depth at x = 0 and slope) or a bathymetry table.

    ``z(x)`` is the elevation (negative), ``slope(x)`` its derivative and ``arc(x)`` the distance
    along the seabed from x = 0.
    """

    def __init__(self, distance: np.ndarray, depth: np.ndarray):
        self.x = np.asarray(distance, float)
        self.zb = -np.asarray(depth, float)
        seg = np.hypot(np.diff(self.x), np.diff(self.zb))
        self._arc = np.concatenate([[0.0], np.cumsum(seg)])
        # the table as Python floats, for slope() at one point a time step (the same values and arithmetic)
        self._xl, self._zl = self.x.tolist(), self.zb.tolist()

    @classmethod
    def plane(cls, depth: float, slope: float, x0: float, x1: float) -> Seabed2D:
        """A plane seabed, ``depth`` at x = 0 rising at ``slope`` [rad] towards +x, over [x0, x1]."""
        xs = np.array([x0, x1], float)
        return cls(xs, depth - xs * math.tan(slope))

    def z(self, x):
        return np.interp(x, self.x, self.zb)

    def slope(self, x) -> float:
        """dz/dx at ``x`` (of the table segment holding x; 0 beyond the ends)."""
        xs, zs = self._xl, self._zl
        if x <= xs[0] or x >= xs[-1]:
            return 0.0
        k = bisect.bisect_right(xs, x) - 1          # (numpy.searchsorted(..., side="right") - 1 on the sorted x)
        return (zs[k + 1] - zs[k]) / (xs[k + 1] - xs[k])

    def arc(self, x):
        """Distance along the seabed from the table's first point (straight beyond the ends). [m]"""
        x = np.asarray(x, float)
        inside = np.interp(x, self.x, self._arc)
        return inside + np.minimum(x - self.x[0], 0.0) + np.maximum(x - self.x[-1], 0.0)

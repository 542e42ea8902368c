"""Ship speed and payout speed of a laying run (paper 001 section 3.3: speed changes, repeater
slow-down and recovery, payout adjusted on slopes as the paper's CPRATE does, bottom-tension control)."""

from __future__ import annotations

import math

import numpy as np

from .inputs import PayoutBottomTension, PayoutRate, PayoutSlack, ShipMotion, schedule_value
from .kernel import P_COMPLIANCE, P_WEIGHT

__all__ = ["Control"]


def _table(times, values) -> tuple:
    """A schedule's times and values as float arrays (``(None, None)`` for none)."""
    if times is None:
        return None, None
    return np.asarray(times, float), np.asarray(values, float)


class Control:
    """Ship speed and payout speed as the run goes."""

    def __init__(self, ship: ShipMotion, payout, par):
        """``par``: the run's :class:`~seacable.laying.solver.LayParameters`."""
        self.ship, self.payout, self.par = ship, payout, par
        # a constant speed as ShipMotion.scheduled gives it (asked for three times a step)
        self._constant = None if ship.times is not None else float(ship.speed)
        # the schedules as arrays, made once: numpy.interp converts a tuple on every call (a lay table's hundreds of
        # rows, several times a step), to the same float64 values
        self._ship_table = _table(ship.times, ship.speeds)
        self._payout_table = _table(getattr(payout, "times", None), getattr(payout, "speeds", None))
        self.speed = self.scheduled(0.0)
        self.off_schedule = False
        # the filter starts at the target: the payout starts at the feed-forward and follows the
        # measured bottom tension over the filter time, without a jerk
        self.bottom_filtered = payout.tension if isinstance(payout, PayoutBottomTension) else 0.0
        self.integral = 0.0                # integral of the bottom tension's error over time [s]
        p = par.props[par.type_at(0.0)]
        self.weight, self.compliance = p[P_WEIGHT], p[P_COMPLIANCE]
        #: whether :meth:`payout_speed` uses the touchdown's geometry (and the bottom tension, in bottom-tension mode)
        self.uses_geometry = isinstance(payout, PayoutBottomTension) or (
            isinstance(payout, PayoutSlack) and payout.slope_compensation)
        self._rate, self._slack = isinstance(payout, PayoutRate), isinstance(payout, PayoutSlack)

    def scheduled(self, t: float) -> float:
        """The ship's scheduled speed at ``t`` (:meth:`ShipMotion.scheduled`). [m/s]"""
        return self._constant if self._constant is not None else schedule_value(t, None, *self._ship_table)

    def ship_speed(self, t_new: float, dt: float, repeater_in_water: bool) -> float:
        """Ship speed at ``t_new``: the schedule, or the repeater speed approached at the acceleration
        (and the schedule regained at the acceleration after the repeater's touchdown)."""
        sched = self.scheduled(t_new)
        slow = repeater_in_water and self.ship.repeater_speed is not None and self.ship.repeater_speed < sched
        if not slow and not self.off_schedule:
            return sched
        target = self.ship.repeater_speed if slow else sched
        step = self.ship.acceleration * dt
        return self.speed + min(max(target - self.speed, -step), step)

    def update(self, speed: float, t: float) -> None:
        """Accept the ship speed of a step ending at ``t``."""
        self.speed = speed
        self.off_schedule = abs(speed - self.scheduled(t)) > 1e-12

    def payout_speed(self, t: float, vs: float, geometry, bottom_tension: float, dt: float,
                     commit: bool = True) -> float:
        """Payout speed for ship speed ``vs`` and the present touchdown ``geometry``: the seabed's slope along
        the ship's heading there, the depth there [m], the cot of the span's chord angle and the touchdown's
        speed over the ship's from a turn (1 on a straight track), or None where the control does not use them
        (:attr:`uses_geometry`). [m/s]

        In bottom-tension mode ``bottom_tension`` is the bottom tension at the end of the step of
        length ``dt`` [s] (the filter is advanced by backward Euler); ``commit=False`` evaluates the
        speed for a trial value without advancing the filter.
        """
        p = self.payout
        if self._rate:
            return schedule_value(t, p.speed, *self._payout_table)
        if not self.uses_geometry:
            return (1.0 + p.slack) * vs
        slope, h_td, cot_alpha, turn = geometry
        # CPRATE: touchdown speed, laid length per metre run and change of the suspended length
        td_speed = vs * turn / max(1.0 - slope * cot_alpha, 0.1)
        sin_alpha = 1.0 / math.sqrt(1.0 + cot_alpha * cot_alpha)
        arc = math.sqrt(1.0 + slope * slope)
        if self._slack:
            return max(td_speed * ((1.0 + p.slack) * arc - slope / sin_alpha), 0.0)
        filtered = self.bottom_filtered + min(dt / p.time_constant, 1.0) * (bottom_tension - self.bottom_filtered)
        if commit:
            self.bottom_filtered = filtered
        feed = td_speed * (arc / (1.0 + p.tension * self.compliance) - slope / sin_alpha)
        error = (filtered - p.tension) / (self.weight * max(h_td, 1e-9))
        correction = error
        if p.integral_time is not None:
            # backward Euler, and no wind-up: the integral term alone stays within the speed's bounds (0 .. 2 x)
            bound = p.integral_time / p.gain
            integral = min(max(self.integral + dt * error, -bound), bound)
            if commit:
                self.integral = integral
            correction += integral / p.integral_time
        return feed * min(max(1.0 + p.gain * correction, 0.0), 2.0)

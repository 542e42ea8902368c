"""Lay planning along a route: the lay table, KP by KP, from a quasi-static model of the lay.

The model
---------
At each ship KP the suspended cable is taken in its steady state in the frame of the ship, moving
at the ship's speed ``V_s`` along the route's leg at that KP. The cable's material flows along it
at the payout speed ``V_c``, so a material point moves over the ground at ``v = V_s e_1 - V_c t``
(``t`` the unit tangent pointing up towards the ship) and the water passes it at ``u = c(z) - v``.
Per unit length the cable carries its weight in water ``w``, the normal drag
``1/2 rho C_dn d |u_n| u_n`` and the tangential drag ``1/2 rho C_dt pi d |u_t| u_t``; the material
turning along the curve needs the centripetal force ``(m + m_a) V_c^2 dt/ds``. The steady balance
of an element, integrated from the touchdown up to the surface, is::

    dT/ds = -f . t,    (T - (m + m_a) V_c^2) dt/ds = -(f - (f . t) t),    dr/ds = (1 + T/EA) t.

* **Slack target** (zero bottom tension): the cable leaves the seabed straight, in the direction
  where the normal drag balances the normal weight. Projecting the balance on the normal plane of a
  straight cable (derived in :func:`straight_direction`), the horizontal part of ``t`` points along
  the ship's velocity through the water ``W = V_s e_1 - c`` and its angle to the horizontal solves
  Zajac's ``w cos(alpha) = 1/2 rho C_dn d |W|^2 sin^2(alpha)`` with ``|W|`` for ``V_s``. A
  cross-current ``c_2`` therefore turns the cable's vertical plane off the route by
  ``atan(c_2 / (V_s - c_1))`` and the touchdown sits down-current of the route by
  ``h cot(alpha) sin(that angle)``. In a uniform current the cable is straight and this is exact
  (paper 001 section 2); in a current profile the direction is followed up the depth while the
  tangent's relaxation length is below half a step, and the equations above are integrated beyond.
* **Bottom-tension target** ``T_0``: the cable leaves the seabed along the ship's heading, tangent to
  the seabed's slope, with the tension ``T_0``: the catenary with drag.

Turns. In a steady turn (the ship on a circle of radius ``R``) the span is steady in the frame turning at
``Omega = V_s / R``; the frame's velocity ``Omega e_3 x (r - centre)`` replaces ``V_s e_1`` in the drag, and
the centripetal and Coriolis accelerations join ``V_c^2 dt/ds`` (:func:`steady_turn`). The touchdown then runs
on its own circle, inside the ship's by the cut ``R - rho`` (slower than the ship by ``rho / R``). At each
station the span is solved in that frame with the route's curvature near its touchdown, the route's changes of
heading spread over the span's transient by the kernel of its linearised lateral balance (:mod:`.lateral`:
the laid path is the ship's track filtered by the span's lateral response, derived, not fitted; its length is
the layback and its shape depends on the span's angle and bottom tension), and the touchdown is placed on the
route moved across by the span's steady offset (the cut, and a cross-current's ``h cot(alpha) sin(...)``), at the
span's horizontal reach from the ship. On an arc this is exact; at a sharp 20 deg alter-course in 100 m of water
the plan's largest cut is within 6 % of the dynamic model's from 0.5 to 2 m/s and under 200 N of bottom
tension (the tractrix of the layback would cut 26 m at 1 m/s, where both cut 10.5 m).

The touchdown is where the span from the ship meets the seabed: its depth is iterated on (a grid
gives a different depth off the route). The laid cable follows the touchdown's path over the
seabed: per metre of it, ``1 + slack`` of cable (or ``1 / (1 + T_0/EA)`` under a bottom tension).
The cable paid out at a ship KP is the cable laid up to the touchdown plus the suspended length, and
the payout speed is ``V_s d(paid out)/dKP`` (in the span itself the steady lay's, ``1 + slack`` or
``1 / (1 + T_0/EA)`` times the touchdown's speed); the time is the integral of ``dKP / V_s``. A change of the
ship's speed reaches the span through a first-order lag of the time the straight span takes to pay out,
``h / (V_s sin(alpha))`` (about the time a cable element takes to sink to the touchdown), so the touchdown runs
on smoothly through a slow-down. A repeater
(``line.attachments``) slows the ship to ``repeater_speed`` from its water entry (cable paid out =
its ``s``) to its touchdown (cable laid = its ``s``), at the ship's ``acceleration`` (v dv/dKP = a);
the ship speed, the spans and the repeaters' KPs are iterated to agreement. A station whose touchdown
swings between two steady positions as the iteration goes (two spans meet a falling seabed) is held
after a few iterations and flagged.

Limits: the span is in steady state at each KP for the lagged speed and the spread turn (the lag is a model of
the transient, not its solution, and the spread is the linear theory's, without the span's lateral inertia, for the
span in still water on a flat seabed: the dynamic model gives the rest); the seabed's cross slope, a repeater's
own weight and drag and the cable's bending stiffness are left out, and so is a span that touches a ridge between touchdown and ship
(flagged: ``span_clearance < 0``). A touchdown that would move backwards (the seabed falling away
faster than the layback grows) is flagged too. The dynamic model (``laying_dynamic``) has none of
these limits.

References
----------
.. [1] Zajac, E. E., 1957. Dynamics and kinematics of the laying and recovery of submarine cable.
   Bell System Technical Journal 36(5), 1129-1207.
.. [2] Paper 001 (seeds/001), section 2, eq. (1)-(11).

The span's steady state (the RK4 integration, compiled) is in :mod:`.span`, the spread of the route's turns
over the span (:mod:`.lateral`'s kernels) in :mod:`.spread`; this module builds the lay table.
"""

from __future__ import annotations

import math
import time as _time
import warnings
from itertools import pairwise

import numpy as np

from .._jit import njit
from ..errors import InputError, SeacableWarning
from .span import (  # noqa: F401  (the station table's columns: public here too)
    N_STATION_PROPS,
    S_CDN,
    S_CDT,
    S_COMPLIANCE,
    S_D,
    S_MEFF,
    S_MT,
    S_W,
    _pay_out_time,
    _span,
    _straight_layback,
    solve_spans,
    straight_direction,
)
from .spread import _Spread, catenary_profile, clear_spread_cache, span_spread  # noqa: F401  (public here too)

__all__ = ["LayPlan", "catenary_profile", "plan_lay", "solve_spans", "span_spread", "steady_turn",
           "straight_direction"]


_SWING_AFTER = 8     # outer iterations after which a station whose span still changes is held (and flagged)


class LayPlan:
    """The lay table: arrays by ship KP (``columns``), the repeaters' events, and flags."""

    def __init__(self, columns: dict, repeaters: dict, notes: list[str], iterations: int, wall_time: float):
        self.columns, self.repeaters, self.notes = columns, repeaters, notes
        self.iterations, self.wall_time = iterations, wall_time


def _speed_profile(kp, scheduled, windows, repeater_speed, acceleration):
    """Ship speed at the stations: the schedule, slowed to ``repeater_speed`` inside ``windows`` (KP ranges),
    every change at the ``acceleration`` (``v dv/dKP = a``), starting where the window starts."""
    v = np.array(scheduled, float)
    if repeater_speed is None or not windows:
        return v
    target = v.copy()
    for a, b in windows:
        inside = (kp >= a) & (kp <= b)
        target[inside] = np.minimum(target[inside], repeater_speed)
    out = np.empty_like(v)
    out[0] = target[0]
    for i in range(1, kp.size):
        reach = 2.0 * acceleration * (kp[i] - kp[i - 1])
        prev2 = out[i - 1] ** 2
        if target[i] < out[i - 1]:
            out[i] = max(target[i], math.sqrt(max(prev2 - reach, 0.0)))
        else:
            out[i] = min(target[i], math.sqrt(prev2 + reach))
    return out


def _crossing(kp, values, level):
    """First KP where an increasing-ish series reaches ``level`` (linear between stations); NaN if never."""
    above = np.flatnonzero(values >= level)
    if above.size == 0:
        return math.nan
    i = int(above[0])
    if i == 0:
        return float(kp[0])
    f = (level - values[i - 1]) / (values[i] - values[i - 1])
    return float(kp[i - 1] + f * (kp[i] - kp[i - 1]))


def plan_lay(route, seabed, kp, *, scheduled_speed, slack=None, bottom_tension=None, props_at, current,
             water_density, repeaters=(), repeater_speed=None, acceleration=0.02, max_iterations=30) -> LayPlan:
    """The lay table at the ship KPs ``kp`` (see the module's description of the model).

    Parameters
    ----------
    route : RouteGeometry
    seabed : SeabedMap
    kp : (n,) array
        Ship KPs of the table, increasing. [m]
    scheduled_speed : (n,) array
        Ship speed over the ground at them, before repeater slow-downs. [m/s]
    slack, bottom_tension : (n,) arrays, callables or None
        The target at each station's touchdown: one of the two (slack >= 0 [-], or a tension [N]); a callable
        gives it by the touchdown's KP (``f(kp)`` for an array of KPs), taken where the iteration puts the
        touchdown.
    props_at : callable
        ``props_at(s)`` -> (n, 6) station properties (``S_*`` columns) of the cable at material coordinates s.
    current : seacable.environment.Current
    water_density : float
    repeaters : sequence of (name, s)
        In-line bodies at cable coordinates ``s`` from the start of the lay. [m]
    repeater_speed, acceleration : float
        Ship speed while a repeater descends [m/s] (None: no slow-down) and the rate of the change. [m/s^2]

    Returns
    -------
    LayPlan
    """
    wall0 = _time.perf_counter()
    n = kp.size
    ship_xy = route.point(kp)
    psi = route.heading(kp)
    if current.depths is None:
        depths, speeds = np.zeros(1), np.array([current.speed])
    else:
        depths, speeds = np.asarray(current.depths, float), np.asarray(current.speeds, float)
    tension_mode = bottom_tension is not None
    target_at = bottom_tension if tension_mode else slack         # by the touchdown's KP, where callable
    target = np.broadcast_to(np.asarray(target_at(kp) if callable(target_at) else target_at, float), (n,)).copy()
    t0, slack = (target, None) if tension_mode else (np.zeros(n), target)
    seabed.check_covers(ship_xy, "route", kp)
    h_ship = seabed.depth(ship_xy)
    vs = np.array(scheduled_speed, float)
    s_td = np.zeros(n)
    vc = vs * (1.0 + (np.zeros(n) if tension_mode else slack))
    out = np.full((n, 5), np.nan)
    h = h_ship.copy()
    td_xy = ship_xy.copy()
    rep_rows, windows, hold = [], [], False
    tau = np.zeros(n)
    solved = np.full((n, 5), np.nan)             # the inputs each station's span was last solved with
    delta = 5.0                                  # m, half-base of the seabed slope's central difference
    total = 0
    # the route's changes of heading (at its vertices: the sharp waypoints and the arcs' chords), for the turn
    turn_kp, turn = _vertex_turns(route)
    sharp_turns = (route.kp[1:-1][route.sharp], route.vertex_turn[route.sharp])
    spread = _Spread(water_density)
    vs_td = vs.copy()                            # the touchdown's speed (slower inside a turn) [m/s]
    laid_off = np.zeros(n)                       # the touchdown's steady offset from the route (+ port) [m]
    td_kp = kp.copy()                            # the touchdown's KP [m]
    frozen = np.zeros(n, bool)                   # stations held where the iteration swings (see _SWING_AFTER)
    step_h = step_prev = np.zeros(n)             # the touchdown depth's last two changes per outer iteration [m]
    swings = np.zeros(n, int)                    # ... how many times running it went back as far
    h_outer = h.copy()
    for outer in range(max_iterations):
        if callable(target_at) and outer > 0:              # the target where the touchdown now is
            target = np.asarray(target_at(td_kp), float)
            t0, slack = (target, None) if tension_mode else (t0, target)
        props = props_at(s_td)
        per_metre = 1.0 / (1.0 + t0 * props[:, S_COMPLIANCE]) if tension_mode else 1.0 + slack
        # the span's speed (the ship's, lagged by the pay-out time tau) and its turn rate (the route's curvature
        # near the touchdown, spread over the span's transient: :class:`_Spread`)
        speed_eff = _lag(kp, vs, vs, tau)
        # (at the straight span's touchdown over the depth under the ship: kept off the iterated touchdown, whose
        # depth can have two roots where the seabed falls away)
        reach = _straight_layback(h_ship, speed_eff, props, water_density)
        curvature, spread_heading, reach = spread.turns(kp, h_ship, speed_eff, t0, per_metre, props, turn_kp, turn,
                                                        reach)
        omega = speed_eff * curvature
        # (a turn that would move the touchdown by under 0.01 mm, the cut being about 0.08 L^2 Omega / V: none)
        omega[np.abs(omega) * reach**2 < 1e-4 * speed_eff] = 0.0
        # the span's direction (for the current across it and the seabed's slope): the route's heading there, spread
        psi_td = route.heading(kp - reach) + spread_heading
        e1 = np.column_stack([np.cos(psi_td), np.sin(psi_td)])
        cos_c, sin_c = np.cos(current.heading - psi_td), np.sin(current.heading - psi_td)
        # the payout through the span (its tangential drag and turning): the steady lay's, the laid length per metre
        # run times the touchdown's speed (the payout iterate itself, a difference between stations, feeds back
        # through the tangential drag and does not settle where the span changes fast)
        vc_span = vs_td * per_metre
        inputs = np.column_stack([vs_td, omega, psi_td, vc_span, props[:, S_W]])
        # (a payout speed right to 1e-6 changes the tension by far less than the planner's own accuracy)
        active = ~np.all(np.abs(inputs - solved) <= 1e-6 * np.abs(inputs) + 1e-12, axis=1) & ~frozen
        solved = inputs
        h_prev = g_prev = None
        lo, hi = np.full(n, -np.inf), np.full(n, np.inf)
        for inner in range(60):               # the touchdown's depth h = g(h), by the secant method per station
            if not active.any():
                break
            fwd = seabed.depth(td_xy + delta * e1, kp=td_kp + delta)
            back = seabed.depth(td_xy - delta * e1, kp=td_kp - delta)
            beta = np.arctan(np.nan_to_num((back - fwd) / (2.0 * delta)))
            solve_spans(h, beta, vs_td, omega, vc_span, cos_c, sin_c, t0, depths, speeds, water_density, props, active,
                        out)
            total += 1
            if np.isnan(out[active]).any():
                i = int(np.flatnonzero(active & np.isnan(out[:, 0]))[0])
                cause = (f"under the bottom tension of {t0[i]:g} N it leaves the seabed along its slope "
                         f"({math.degrees(beta[i]):+.1f} deg; + rises towards the ship) and, that taut, runs down "
                         "into the seabed before its weight can turn it up" if t0[i] > 0.0 else
                         "the current against the ship turns it down")
                raise InputError(f"lay plan at KP {kp[i]:.1f} m: the cable from the touchdown (depth {h[i]:.1f} m) "
                                 f"does not reach the surface: {cause}. Suggested fix: a lower bottom tension or a "
                                 "slack target there, a check of the current against the ship speed, or the dynamic "
                                 "model (laying_dynamic).")
            laid_off = np.where(active, _steady_offset(out, vs_td, omega), laid_off)
            new_kp = _on_offset_line(route, ship_xy, kp, np.hypot(out[:, 0], out[:, 1]), laid_off, sharp_turns)
            new_xy = _offset_point(route, new_kp, laid_off, sharp_turns)
            seabed.check_covers(new_xy[active], "touchdown", kp[active])
            g = np.where(active, seabed.depth(new_xy, kp=new_kp), h)
            td_xy = np.where(active[:, None], new_xy, td_xy)
            td_kp = np.where(active, new_kp, td_kp)
            step = g - h
            lo = np.where(step > 0.0, np.maximum(lo, h), lo)     # the bracket of r(h) = g(h) - h: > 0 below lo,
            hi = np.where(step < 0.0, np.minimum(hi, h), hi)     # < 0 above hi (g is nearly flat in h)
            if inner >= 8:
                # still moving: bisection in the bracket (where g jumps, at a seabed edge the touchdown rests on,
                # the secant and the fixed point swing across it)
                both = np.isfinite(lo) & np.isfinite(hi)
                step = np.where(both, 0.5 * (np.where(both, lo, h) + np.where(both, hi, h)) - h, step)
            elif h_prev is not None:
                # secant on r(h) = g(h) - h; a fixed-point step where the secant is flat or would go far
                r_prev = g_prev - h_prev
                slope = np.where(np.abs(h - h_prev) > 0, (step - r_prev) / np.where(h != h_prev, h - h_prev, 1.0), 0.0)
                newton = np.where(slope < -0.05, -step / np.where(slope < -0.05, slope, -1.0), step)
                step = np.where(np.abs(newton) <= 2.0 * np.abs(step), newton, step)
            h_prev, g_prev = h.copy(), g
            active = active & (np.abs(g - h) > 1e-6 * np.maximum(h, 1.0)) & ~(hi - lo < 1e-6 * np.maximum(h, 1.0))
            h = np.where(active, h + step, h)
        td_z = -seabed.depth(td_xy)
        step_prev, step_h, h_outer = step_h, h - h_outer, h.copy()
        # the turning frame: the touchdown's speed for which the ship's is the lagged speed; the laid path's
        # steady offset from the route (:func:`_steady_offset`), where the touchdown is; the span's direction
        # (the frame's velocity at the ship, (vs_td - omega o2, omega o1), has the ship's speed)
        top = np.hypot(vs_td - omega * out[:, 1], omega * out[:, 0])
        vs_td_new = vs_td * speed_eff / top
        path = np.concatenate([[0.0], np.cumsum(np.sqrt(np.sum(np.diff(td_xy, axis=0) ** 2, axis=1)
                                                        + np.diff(td_z) ** 2))])
        s_new = np.concatenate([[0.0], np.cumsum(0.5 * (per_metre[1:] + per_metre[:-1]) * np.diff(path))])
        paid = s_new + out[:, 2]
        vc_new = np.maximum(vs * np.gradient(paid, kp), 0.0)
        rep_rows = [(name, s, _crossing(kp, paid, s), _crossing(kp, s_new, s)) for name, s in repeaters]
        found = [(a if math.isfinite(a) else kp[0], b if math.isfinite(b) else kp[-1])
                 for _, _, a, b in rep_rows if math.isfinite(a) or math.isfinite(b)]
        if outer >= 2 and len(found) == len(windows):
            # a slow-down that ends later lays the repeater earlier (the span flattens as the ship speeds up), so
            # the plain iteration can swing between two ends: halfway, and once the ends move by less than a
            # station (the speeds are taken at the stations) the wider of the two windows, held from then on
            swing = max(max(abs(a - c), abs(b - d)) for (a, b), (c, d) in zip(found, windows)) if found else 0.0
            if hold:
                found = windows
            elif outer >= 6 and swing < np.max(np.diff(kp)):
                hold = True
                found = [(min(a, c), max(b, d)) for (a, b), (c, d) in zip(found, windows)]
            else:
                found = [(0.5 * (a + c), 0.5 * (b + d)) for (a, b), (c, d) in zip(found, windows)]
        windows = found
        vs_new = _speed_profile(kp, scheduled_speed, windows, repeater_speed, acceleration)
        # the lag: the time to pay out the straight span at the scheduled speed (of the span's own length the
        # iteration settles slowly, and of V_c not at all)
        tau_new = _pay_out_time(h, vs_new, props, water_density)
        if outer >= _SWING_AFTER:
            # a station still swinging: its span has two steady touchdowns (where the seabed falls away, at an
            # alter-course) and the iteration hops between them; it is held at the last and flagged
            # (a change back by at least 0.95 of the one before, twice running: not a settling one)
            back = (step_h * step_prev < 0.0) & (np.abs(step_h) > 0.95 * np.abs(step_prev)) & (np.abs(step_h) > 1e-9 * h)
            swings = np.where(back, swings + 1, 0)
            frozen |= swings >= 2
            vs_td_new = np.where(frozen, vs_td, vs_td_new)
            tau_new = np.where(frozen, tau, tau_new)
        # settled: speeds to 1e-7 of the ship's, lengths and the lag to 1e-7 (1 mm in 10 km)
        settled = (np.max(np.abs(vc_new - vc)) <= 1e-7 * np.max(vs) and np.max(np.abs(vs_new - vs)) <= 1e-7 * np.max(vs)
                   and np.max(np.abs(s_new - s_td)) <= 1e-7 * max(float(s_new[-1]), 1.0)
                   and np.max(np.abs(tau_new - tau)) <= 1e-7 * np.max(tau_new)
                   and np.max(np.abs(vs_td_new - vs_td)) <= 1e-6 * np.max(vs))
        vc, vs, s_td, tau = vc_new, vs_new, s_new, tau_new
        vs_td = vs_td_new
        if settled:
            break
    else:
        warnings.warn(f"lay plan: the ship speed, payout and repeater positions did not settle in {max_iterations} "
                      "iterations; the table is the last iterate.", SeacableWarning, stacklevel=2)
    # the touchdown's rate along the route from the KP it was placed at (on the route moved across by its offset):
    # smooth through a sharp alter-course, where the nearest route point of a touchdown inside the corner jumps
    # from one leg to the next (a slack of -0.18 for 0.05 at 20 deg)
    td_rate = np.gradient(td_kp, kp)
    td_kp, td_off = route.locate(td_xy)
    time = np.concatenate([[0.0], np.cumsum(np.diff(kp) * 0.5 * (1.0 / vs[1:] + 1.0 / vs[:-1]))])
    moving = td_rate > 0.05
    route_slack = np.where(moving, np.gradient(s_td, kp) / np.where(moving, td_rate, 1.0) - 1.0, np.nan)
    clearance = _span_clearance(seabed, ship_xy, td_xy, td_z)
    notes = _flags(kp, td_rate, clearance, frozen)
    props = props_at(s_td)
    columns = {
        "ship_x": ship_xy[:, 0], "ship_y": ship_xy[:, 1], "ship_heading": psi, "ship_speed": vs,
        "payout_speed": vc, "paid_out": s_td + out[:, 2], "time": time,
        "touchdown_kp": td_kp, "touchdown_offset": td_off, "touchdown_x": td_xy[:, 0], "touchdown_y": td_xy[:, 1],
        "touchdown_depth": -td_z, "touchdown_speed": vs * np.gradient(path, kp), "water_depth": h_ship,
        "layback": np.hypot(out[:, 0], out[:, 1]),
        "layback_along": np.cos(psi) * (ship_xy - td_xy)[:, 0] + np.sin(psi) * (ship_xy - td_xy)[:, 1],
        "layback_across": -np.sin(psi) * (ship_xy - td_xy)[:, 0] + np.cos(psi) * (ship_xy - td_xy)[:, 1],
        "suspended_length": out[:, 2], "laid_length": s_td, "top_tension": out[:, 3],
        "bottom_tension": t0.copy(), "entry_angle": out[:, 4].copy(),
        "slack": (slack if not tension_mode else per_metre - 1.0),
        "route_slack": route_slack, "span_clearance": clearance, "span_speed": speed_eff, "turn_rate": omega,
    }
    reps = {"name": [r[0] for r in rep_rows], "s": np.array([r[1] for r in rep_rows], float),
            "entry_kp": np.array([r[2] for r in rep_rows], float),
            "touchdown_kp": np.array([r[3] for r in rep_rows], float)}
    reps["entry_time"] = np.interp(reps["entry_kp"], kp, time, left=np.nan, right=np.nan)
    reps["touchdown_time"] = np.interp(reps["touchdown_kp"], kp, time, left=np.nan, right=np.nan)
    # where the repeater lands: the touchdown point at the ship KP it lands
    reps["landing_kp"] = np.interp(reps["touchdown_kp"], kp, td_kp, left=np.nan, right=np.nan)
    reps["landing_offset"] = np.interp(reps["touchdown_kp"], kp, td_off, left=np.nan, right=np.nan)
    return LayPlan(columns, reps, notes, outer + 1, _time.perf_counter() - wall0)


def _lag(kp, speed, value, tau) -> np.ndarray:
    """A first-order lag of time constant ``tau`` behind ``value`` over the time the ship takes between the
    stations at ``speed`` (the span sees the ship's speed so).

    Exact for a value held constant between stations: ``l_i = v_i + (l_{i-1} - v_i) exp(-dt / tau_i)``
    with ``dt`` the time between the stations; with ``tau = 0`` the value itself.
    """
    dt = np.diff(kp) * 0.5 * (1.0 / speed[1:] + 1.0 / speed[:-1])
    keep = np.exp(-dt / np.maximum(tau[1:], 1e-300))
    out = np.array(value, float)
    for i in range(1, kp.size):
        out[i] = value[i] + (out[i - 1] - value[i]) * keep[i - 1]
    return out


def _vertex_turns(route):
    """KPs of the route's inner vertices and the change of heading at each (+ to port). [m], [rad]"""
    keep = route.vertex_turn != 0.0
    return route.kp[1:-1][keep], route.vertex_turn[keep]


def _steady_offset(out, vs_td, omega) -> np.ndarray:
    """The touchdown's offset from the ship's track (+ to port) in the span's steady state: in a turn, the
    ship's radius minus the touchdown's (``|ship - centre| - |vs_td / omega|``, on the inside); on a straight
    track ``-o2`` (a cross-current's offset). ``out`` holds the span ``(o1, o2)`` in the touchdown's frame. [m]"""
    side = np.where(omega < 0.0, -1.0, 1.0)                    # the centre's side, (0, c) in the touchdown's frame
    inv = omega / vs_td                                         # 1 / c (0 on a straight track)
    # |ship - centre| - |c| = (o1^2 + o2^2 - 2 o2 c) / (|ship - centre| + |c|), without the cancellation; over |c|:
    lead = np.hypot(out[:, 0] * inv, out[:, 1] * inv - 1.0) + 1.0
    return side * ((out[:, 0] ** 2 + out[:, 1] ** 2) * np.abs(inv) - 2.0 * out[:, 1] * side) / lead


def _offset_point(route, k, offset, turns) -> np.ndarray:
    """The route's points at KPs ``k`` moved by ``offset`` to port, across the route's heading: continuous along the
    arcs (:meth:`RouteGeometry.smooth_heading`), and smoothed over ``|offset|`` either side of a sharp waypoint
    (``turns``: their KPs and changes of heading), where the legs' normals jump. [m]"""
    turn_kp, turn = turns
    psi = _smooth_heading(np.asarray(k, float), np.maximum(np.abs(offset), 1.0), turn_kp, turn,
                          route.smooth_heading(k))
    return route.point(k) + offset[:, None] * np.column_stack([-np.sin(psi), np.cos(psi)])


@njit(cache=True)
def _smooth_heading(k, width, turn_kp, turn, heading):
    """``heading`` (the legs') with each change of heading spread as ``1/2 exp(-|x| / width)`` either side. [rad]"""
    out = heading.copy()
    for i in range(k.size):
        lo = np.searchsorted(turn_kp, k[i] - 40.0 * width[i])
        hi = np.searchsorted(turn_kp, k[i] + 40.0 * width[i])
        for j in range(lo, hi):
            x = (k[i] - turn_kp[j]) / width[i]
            out[i] += turn[j] * (-0.5 * math.exp(-x) if x >= 0.0 else 0.5 * math.exp(x))
    return out


def _on_offset_line(route, ship_xy, ship_kp, reach, offset, turns) -> np.ndarray:
    """The KP of the touchdown: on the route moved by its ``offset`` to port, at the horizontal distance ``reach``
    behind the ship (secant from the straight route's answers). [m]"""
    k0 = ship_kp - np.sqrt(np.maximum(reach * reach - offset * offset, 0.25 * reach * reach))
    k1 = k0 - 1.0

    def miss(k, i):
        return np.hypot(*(ship_xy[i] - _offset_point(route, k, offset[i], turns)).T) - reach[i]

    every = np.arange(k0.size)
    f0, f1 = miss(k0, every), miss(k1, every)
    # to 1e-9 of the reach (a micrometre a kilometre); a station whose offset line folds (an offset wider than the
    # arc's radius inside a turn) has no clean root, and after 15 steps keeps its last
    tol = 1e-9 * max(float(np.max(reach)), 1.0)
    going = every[np.abs(f1) >= tol]
    for _ in range(15):                          # (on the stations not there yet)
        if not going.size:
            break
        a0, b0, a1, b1 = k0[going], f0[going], k1[going], f1[going]
        slope = np.where(b1 != b0, (b1 - b0) / np.where(a1 != a0, a1 - a0, 1.0), -1.0)
        a2 = a1 - b1 / np.where(slope < -0.1, slope, -1.0)
        k0[going], f0[going], k1[going] = a1, b1, a2
        f1[going] = miss(a2, going)
        going = going[np.abs(f1[going]) >= tol]
    return k1


def _span_clearance(seabed, ship_xy, td_xy, td_z, samples: int = 9) -> np.ndarray:
    """Smallest height of the chord from touchdown to ship above the seabed under it (inner points). [m]"""
    lam = np.linspace(0.0, 1.0, samples + 2)[1:-1]
    pts = td_xy[:, None, :] + lam[None, :, None] * (ship_xy - td_xy)[:, None, :]
    z_chord = td_z[:, None] * (1.0 - lam[None, :])
    zb = -seabed.depth(pts)
    return np.nanmin(z_chord - zb, axis=1)


def _ranges(kp, mask) -> str:
    """'KP a-b, c-d m' of the runs of ``mask``."""
    idx = np.flatnonzero(mask)
    runs, start = [], idx[0]
    for a, b in pairwise(idx):
        if b != a + 1:
            runs.append((start, a))
            start = b
    runs.append((start, idx[-1]))
    text = ", ".join(f"{kp[a]:.0f}-{kp[b]:.0f}" if b > a else f"{kp[a]:.0f}" for a, b in runs[:8])
    return f"KP {text}{' ...' if len(runs) > 8 else ''} m"


def _flags(kp, td_rate, clearance, frozen) -> list[str]:
    notes = []
    if frozen.any():
        notes.append(f"the touchdown swings between two steady positions at {_ranges(kp, frozen)} (two spans meet "
                     "the seabed there): the plan holds one of them; run the dynamic model (laying_dynamic) over "
                     "that stretch")
    back = td_rate <= 0.05
    if back.any():
        notes.append(f"the touchdown stalls or moves backwards at {_ranges(kp, back)} (the seabed falls away faster "
                     "than the layback grows): the quasi-static plan does not hold there; run the dynamic model "
                     "(laying_dynamic) over that stretch")
    ridge = clearance < 0.0
    if ridge.any():
        notes.append(f"the span from touchdown to ship crosses the seabed at {_ranges(kp, ridge)} (a ridge under "
                     "the suspended cable): the plan's touchdown is beyond it")
    for note in notes:
        warnings.warn(f"lay plan: {note}.", SeacableWarning, stacklevel=3)
    return notes


def steady_turn(props, depth, ship_speed, radius, *, water_density, slack=None, bottom_tension=None):
    """The steady lay of a ship sailing a circle: where the touchdown runs, inside the ship's track.

    In the frame turning with the ship (rate ``Omega = V_s / R``) the suspended span is steady, and the
    touchdown runs on a circle of its own radius ``rho``; the laid cable lies on that circle, ``R - rho`` inside
    the ship's. The span is :func:`_span` in the turning frame (the frame point at ``r`` moves at
    ``Omega e_3 x (r - centre)``; the material also feels the centripetal and Coriolis accelerations), from
    the touchdown, tangent to its circle and moving at ``Omega rho``, up to the surface; ``rho`` is the root
    of ``|ship - centre| = R`` (Brent). Still water and a flat seabed (a current turns with respect to the frame,
    so it has no steady turn).

    Limits: ``Omega -> 0`` is the straight lay (:func:`plan_lay`'s span); a rigid span of layback ``L`` would
    cut ``R - sqrt(R^2 - L^2)`` (a tractrix's limit circle); a cable without tension follows the track.

    Parameters
    ----------
    props : (N_STATION_PROPS,) array
        The cable (``S_*`` columns).
    depth, ship_speed, radius : float
        Water depth [m], ship speed over ground [m/s] and the radius of its circle [m] (> 0: turning to port).
    water_density : float
        [kg/m^3]
    slack, bottom_tension : float
        The target: one of the two ([-] or [N]).

    Returns
    -------
    dict
        ``touchdown_radius`` [m], ``cut`` = R - rho [m], ``layback`` (horizontal ship - touchdown) [m],
        ``angle`` (of the touchdown behind the ship, seen from the centre) [rad], ``suspended_length`` [m],
        ``top_tension`` [N], ``entry_angle`` [rad].
    """
    from scipy.optimize import brentq

    p = np.asarray(props, float)
    t0 = 0.0 if bottom_tension is None else float(bottom_tension)
    per_metre = 1.0 + slack if bottom_tension is None else 1.0 / (1.0 + t0 * p[S_COMPLIANCE])
    om = ship_speed / radius
    zero = np.zeros(1)
    out = np.empty(5)

    def span(rho):
        vs = abs(om) * rho
        _span(depth, 0.0, vs, om, per_metre * vs, 1.0, 0.0, t0, zero, zero, water_density, p, out, np.empty((0, 4)))
        return out[0], out[1] - rho * math.copysign(1.0, radius)   # the ship from the centre

    def miss(rho):
        a, b = span(rho)
        return math.hypot(a, b) - abs(radius)

    r_abs = abs(radius)
    lo = r_abs
    while miss(lo) >= 0.0:
        lo *= 0.5
        if lo < 1e-6 * r_abs:
            raise InputError(f"steady turn: no touchdown circle inside the ship's circle of radius {r_abs:g} m")
    rho = brentq(miss, lo, r_abs, xtol=1e-10 * r_abs, rtol=1e-14)
    a, b = span(rho)
    s_len, top, entry = out[2], out[3], out[4]
    # the ship's bearing from the centre minus the touchdown's (at (0, -rho) from the centre)
    angle = math.atan2(a, -b if radius > 0 else b)
    return {"touchdown_radius": rho, "cut": r_abs - rho, "layback": math.hypot(out[0], out[1]), "angle": angle,
            "suspended_length": s_len, "top_tension": top, "entry_angle": entry}

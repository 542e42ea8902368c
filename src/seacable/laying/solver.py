"""Time marching of the laying simulation: payout, node birth at the surface, touchdown, control.

The cable is described by its material coordinate ``s`` (unstretched length from end A, the first
cable laid). Between the touchdown node (the last node landed) and the water entry at the ship,
free lumped-mass nodes are advanced by :func:`seacable.laying.kernel.implicit_step`.

Events after each step:

* **payout and birth** - the top segment (last node to the water entry) has the length paid out
  since that node; when it reaches 1.5 segment lengths a node is born one segment length below the
  last one, on the top chord, with the velocity interpolated linearly between the last node's and
  the velocity of the cable leaving the chute (ship velocity plus payout along the cable, paper
  eq. (17)). Position and velocity are linear in ``s`` along the segment, so the mass and the
  momentum of the cable are unchanged by the birth. Repeaters get a node of their own.
* **touchdown** - the lowest free node that reaches the seabed lands: it is put on the seabed,
  stops (its momentum goes to the seabed) and stays there; it becomes the new touchdown node and the
  old one joins the laid cable. Mass is conserved: paid-out length = laid + suspended length.

Controls: the ship speed follows its schedule, slowed to ``repeater_speed`` while a repeater is in
the water and brought back at the given acceleration after its touchdown; the payout speed follows a
schedule, a target slack (with the paper's slope adjustment, CPRATE) or a target bottom tension.
The time step is set from the speed: ``dt = l / (n V)`` for segment length ``l``, ``n`` steps per
segment and ``V`` the larger of the ship and payout speeds (the paper's "time step inversely
proportional to ship speed").
"""

from __future__ import annotations

import math
import time as _time
import warnings
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq

from ..errors import ConvergenceError, InputError, SeacableWarning
from ..statics.laying import laying_angle
from .inputs import PayoutBottomTension, PayoutRate, PayoutSlack, Seabed2D, ShipMotion, schedule_value
from .kernel import N_PROPS, P_COMPLIANCE, P_WEIGHT, implicit_step

__all__ = ["LayParameters", "Repeater", "LayRun", "simulate"]

_MIN_SPEED = 0.05     # floor of the speed that sets the time step [m/s]
_HALVINGS = 6         # a failing step is retried with dt/2, dt/4, ...
_ROUNDS = 20          # active-set updates (segments going slack or taut) per step
_STRAIN_FLOOR = 1e-7  # strain of an 'inextensible' cable at the weight of its suspended length


@dataclass(frozen=True)
class Repeater:
    """A point mass inserted in the cable at material coordinate ``s``."""

    s: float                 # [m]
    mass: float              # [kg]
    added_mass: float        # [kg]
    weight: float            # in water [N]
    drag_area: float         # C_D A [m^2]
    name: str = ""


@dataclass(frozen=True)
class LayParameters:
    """Cable and water data of a laying simulation (SI units).

    ``props`` holds one row per line type (columns ``seacable.laying.kernel.P_*``) and
    ``type_ends`` the material coordinate at which each type ends.
    """

    props: np.ndarray
    type_ends: np.ndarray
    segment_length: float
    cable_length: float
    repeaters: tuple[Repeater, ...] = ()
    water_density: float = 1025.0
    current_depths: np.ndarray = field(default_factory=lambda: np.zeros(1))
    current_speeds: np.ndarray = field(default_factory=lambda: np.zeros(1))

    def type_at(self, s: float) -> int:
        return min(int(np.searchsorted(self.type_ends, s, side="right")), len(self.type_ends) - 1)


@dataclass
class LayRun:
    """Result of :func:`simulate`: output time series, snapshots and the laid cable."""

    time: np.ndarray
    series: dict                 # name -> (n_out,) array
    x: np.ndarray                # (n_out, n_max) suspended nodes, NaN padded [m]
    z: np.ndarray
    tension: np.ndarray          # (n_out, n_max - 1) [N]
    laid: dict                   # x, z, s, time of the landed nodes
    repeater_xz: np.ndarray      # (n_out, n_rep, 2)
    steps: int = 0
    iterations: int = 0
    halvings: int = 0
    wall_time: float = 0.0
    interrupted: bool = False
    stop_reason: str = ""


class _Cable:
    """Node storage: rows ``lo .. hi`` of fixed-capacity arrays are the suspended cable."""

    def __init__(self, capacity: int):
        self.pos = np.zeros((capacity, 2))
        self.vel = np.zeros((capacity, 2))
        self.s = np.zeros(capacity)
        self.point = np.zeros((capacity, 4))
        self.rep = np.full(capacity, -1, dtype=np.int64)
        self.L = np.zeros(capacity)
        self.T = np.zeros(capacity)
        self.active = np.ones(capacity, dtype=np.int64)
        self.seg_type = np.zeros(capacity, dtype=np.int64)
        self.new_pos = np.zeros((capacity, 2))
        self.new_vel = np.zeros((capacity, 2))
        self.lo = 0
        self.hi = 0

    def _arrays(self):
        return (self.pos, self.vel, self.s, self.point, self.rep, self.L, self.T, self.active, self.seg_type,
                self.new_pos, self.new_vel)

    def make_room(self) -> None:
        """Move the suspended rows to the start (or grow) so that a row can be appended."""
        if self.hi + 2 < self.pos.shape[0]:
            return
        n = self.hi - self.lo + 1
        cap = self.pos.shape[0]
        grow = n + 2 >= cap // 2
        for name in ("pos", "vel", "s", "point", "rep", "L", "T", "active", "seg_type", "new_pos", "new_vel"):
            a = getattr(self, name)
            if grow:
                b = np.zeros((2 * cap,) + a.shape[1:], dtype=a.dtype)
                if name == "rep":
                    b[:] = -1
                b[:n] = a[self.lo:self.hi + 1]
                setattr(self, name, b)
            else:
                a[:n] = a[self.lo:self.hi + 1].copy()
        self.lo, self.hi = 0, n - 1


def _initial_angle(par: LayParameters, speed: float, depth: float) -> float:
    """Straight-line laying angle at a relative speed (paper 001 eq. (7)), 90 deg at rest. [rad]"""
    p = par.props[par.type_at(0.0)]
    u = float(np.interp(0.5 * depth, par.current_depths, par.current_speeds)) if par.current_depths.size > 1 \
        else float(par.current_speeds[0])
    rel = speed - u
    if abs(rel) < 1e-6:
        return 0.5 * math.pi
    alpha = float(laying_angle(abs(rel), p[P_WEIGHT], p[2], p[3], par.water_density, method="exact"))
    return alpha if rel > 0 else math.pi - alpha


def _touchdown_distance(seabed: Seabed2D, x0: float, alpha: float, step: float) -> float:
    """Length along the straight line from the water entry at ``x0`` at ``alpha`` to the seabed. [m]"""
    def f(ell):
        return -ell * math.sin(alpha) - float(seabed.z(x0 - ell * math.cos(alpha)))
    a, fa = 0.0, f(0.0)
    if fa <= 0.0:
        raise InputError(f"the seabed at the water entry x = {x0:g} m is at or above the sea surface "
                         f"(z = {float(seabed.z(x0)):g} m). Suggested fix: check the depth or bathymetry.")
    for _ in range(10**6):
        b = a + step
        if f(b) <= 0.0:
            return brentq(f, a, b, xtol=1e-12)
        a = b
    raise InputError("the cable from the ship does not reach the seabed within 1e6 segments. "
                     "Suggested fix: check the depth (m) and the segment length (m).")


def _node_coordinates(length: float, seg: float, marks) -> list[float]:
    """Material coordinates of the nodes on [0, length]: every ``seg``, plus the repeaters."""
    s = [0.0]
    marks = sorted(m for m in marks if 0.0 < m < length - 0.5 * seg)
    while True:
        nxt = s[-1] + seg
        pending = [m for m in marks if m > s[-1] + 1e-9]
        if pending and pending[0] - nxt < 0.5 * seg:
            nxt = pending[0]
        if nxt > length - 0.5 * seg:
            break
        s.append(nxt)
    s.append(length)
    return s


class _Control:
    """Ship speed and payout speed as the run goes."""

    def __init__(self, ship: ShipMotion, payout, par: LayParameters, seabed: Seabed2D):
        self.ship, self.payout, self.par, self.seabed = ship, payout, par, seabed
        self.speed = ship.scheduled(0.0)
        self.bottom_filtered = 0.0
        p = par.props[par.type_at(0.0)]
        self.weight, self.compliance = p[P_WEIGHT], p[P_COMPLIANCE]

    def ship_speed(self, t_new: float, dt: float, repeater_in_water: bool) -> float:
        """Ship speed at ``t_new``: the schedule, or the repeater speed approached at the acceleration."""
        sched = self.ship.scheduled(t_new)
        target = sched
        if repeater_in_water and self.ship.repeater_speed is not None:
            target = min(sched, self.ship.repeater_speed)
        if target == sched and abs(self.speed - sched) <= self.ship.acceleration * dt:
            return sched
        step = self.ship.acceleration * dt
        return self.speed + min(max(target - self.speed, -step), step)

    def payout_speed(self, t: float, vs: float, geometry, bottom_tension: float, dt: float) -> float:
        """Payout speed for ship speed ``vs`` and the present touchdown geometry. [m/s]"""
        p = self.payout
        if isinstance(p, PayoutRate):
            return schedule_value(t, p.speed, p.times, p.speeds)
        x_td, h_td, cot_alpha = geometry
        slope = self.seabed.slope(x_td)
        compensate = isinstance(p, PayoutBottomTension) or p.slope_compensation
        if not compensate:
            return (1.0 + p.slack) * vs
        # CPRATE: touchdown speed, laid length per metre run and change of the suspended length
        td_speed = vs / max(1.0 - slope * cot_alpha, 0.1)
        sin_alpha = 1.0 / math.sqrt(1.0 + cot_alpha * cot_alpha)
        arc = math.sqrt(1.0 + slope * slope)
        if isinstance(p, PayoutSlack):
            return max(td_speed * ((1.0 + p.slack) * arc - slope / sin_alpha), 0.0)
        self.bottom_filtered += min(dt / p.time_constant, 1.0) * (bottom_tension - self.bottom_filtered)
        feed = td_speed * (arc / (1.0 + p.tension * self.compliance) - slope / sin_alpha)
        error = (self.bottom_filtered - p.tension) / (self.weight * max(h_td, 1e-9))
        return max(feed * (1.0 + p.gain * error), 0.0)


def _end_tensions(c: _Cable, props) -> tuple[float, float, float]:
    """Tension at the water entry and at the touchdown (mid-segment values moved to the ends by the
    weight of half a segment), and the entry angle to the horizontal [rad]."""
    lo, hi = c.lo, c.hi
    d_top = c.pos[hi] - c.pos[hi - 1]
    ln_top = math.hypot(*d_top)
    top = c.T[hi - 1] * c.active[hi - 1] + 0.5 * props[c.seg_type[hi - 1], P_WEIGHT] * c.L[hi - 1] * d_top[1] / ln_top
    d_bot = c.pos[lo + 1] - c.pos[lo]
    ln_bot = math.hypot(*d_bot)
    bottom = 0.0
    if c.active[lo]:
        bottom = max(c.T[lo] - 0.5 * props[c.seg_type[lo], P_WEIGHT] * c.L[lo] * d_bot[1] / ln_bot, 0.0)
    angle = math.atan2(d_top[1], d_top[0])
    return top, bottom, angle


def simulate(par: LayParameters, ship: ShipMotion, payout, seabed: Seabed2D, duration: float, *,
             output_interval: float = 1.0, steps_per_segment: float = 4.0, max_time_step: float = 1.0,
             initial_angle: float | None = None, slack_window: float = 60.0, tol: float = 1e-9,
             max_iter: int = 50, progress=None) -> LayRun:
    """Lay cable from a moving ship for ``duration`` seconds.

    Parameters
    ----------
    par
        Cable and water data.
    ship, payout
        Ship motion and payout control (see :mod:`seacable.laying.inputs`).
    seabed
        Seabed elevation along the track.
    duration, output_interval
        Simulated time and the interval of the stored states. [s]
    steps_per_segment
        Time steps while one segment length is paid out (or run); sets ``dt``. [-]
    max_time_step
        Upper bound of ``dt``. [s]
    initial_angle
        Angle of the initial straight cable to the horizontal; default the straight-line steady
        angle at the initial ship speed (paper 001 eq. (7)). [rad]
    slack_window
        Time over which the slack of the laid cable is measured. [s]
    tol, max_iter
        Newton tolerance (relative constraint residual) and iterations per step.
    progress
        Optional ``progress(t, duration)`` callback.

    Returns
    -------
    LayRun

    Raises
    ------
    ConvergenceError
        When a step fails after ``6`` halvings, with the time and the residual.
    """
    wall0 = _time.perf_counter()
    seg = par.segment_length
    props = par.props
    rho = par.water_density
    cur_d, cur_s = par.current_depths, par.current_speeds
    ctl = _Control(ship, payout, par, seabed)
    x_ship = ship.start_x
    depth0 = -float(seabed.z(x_ship))
    alpha = _initial_angle(par, ctl.speed, depth0) if initial_angle is None else float(initial_angle)
    ell = _touchdown_distance(seabed, x_ship, alpha, 0.25 * seg)
    if ell > par.cable_length:
        raise InputError(f"the initial suspended cable needs {ell:.6g} m but the line is {par.cable_length:.6g} m "
                         "long. Suggested fix: make the line (the cable on board) longer.")
    reps = sorted(par.repeaters, key=lambda r: r.s)
    s_nodes = _node_coordinates(ell, seg, [r.s for r in reps])
    cos_a, sin_a = math.cos(alpha), math.sin(alpha)
    geometry = (x_ship - ell * cos_a, depth0, cos_a / max(sin_a, 1e-9))
    vc = ctl.payout_speed(0.0, ctl.speed, geometry, 0.0, 0.0)

    c = _Cable(max(64, 4 * len(s_nodes)))
    n0 = len(s_nodes)
    c.lo, c.hi = 0, n0 - 1
    for k, s in enumerate(s_nodes):
        back = ell - s
        c.pos[k] = (x_ship - back * cos_a, -back * sin_a)
        c.vel[k] = (ctl.speed - vc * cos_a, -vc * sin_a)
        c.s[k] = s
    c.pos[0, 1] = float(seabed.z(c.pos[0, 0]))
    c.vel[0] = 0.0
    c.vel[-1] = 0.0
    rep_state = np.zeros(len(reps), dtype=np.int64)      # 0 on board, 1 in the water, 2 landed
    rep_landed = np.full((len(reps), 2), np.nan)

    def attach(k: int, s: float) -> None:
        for r, rep in enumerate(reps):
            if abs(rep.s - s) < 1e-9:
                c.point[k] = (rep.mass, rep.added_mass, rep.weight, rep.drag_area)
                c.rep[k] = r
                rep_state[r] = 1

    for k in range(1, n0 - 1):
        attach(k, c.s[k])
    for k in range(n0 - 1):
        c.L[k] = c.s[k + 1] - c.s[k]
        c.seg_type[k] = par.type_at(0.5 * (c.s[k] + c.s[k + 1]))
        # tension of the straight steady lay (weight along the cable, no tangential drag) as the guess
        c.T[k] = props[c.seg_type[k], P_WEIGHT] * sin_a * 0.5 * (c.s[k] + c.s[k + 1])
    c.active[0], c.T[0] = 0, 0.0      # zero tension at the touchdown: the straight lay's bottom is slack
    s_paid = ell
    # an inextensible cable is given the compliance of a 1e-7 strain under the weight of the initial
    # suspended length: immaterial for the shape, it keeps a straight taut cable's matrix regular
    floor = _STRAIN_FLOOR / (float(np.max(props[:, P_WEIGHT])) * max(ell, seg))
    laid = {"x": [float(c.pos[0, 0])], "z": [float(c.pos[0, 1])], "s": [0.0], "time": [0.0]}

    out_t, series, snaps = [], {k: [] for k in (
        "ship_x", "ship_speed", "payout_speed", "paid_out", "top_tension", "bottom_tension", "entry_angle",
        "touchdown_x", "touchdown_z", "slack", "suspended_length", "laid_length")}, []
    rep_out = []

    def record(t: float) -> None:
        top, bottom, angle = _end_tensions(c, props)
        out_t.append(t)
        lx, ls, lt = laid["x"], laid["s"], laid["time"]
        k0 = int(np.searchsorted(lt, t - slack_window, side="left"))
        slack = np.nan
        if len(lt) - k0 >= 3:
            run = float(seabed.arc(lx[-1]) - seabed.arc(lx[k0]))
            if run > 0:
                slack = (ls[-1] - ls[k0]) / run - 1.0
        values = dict(ship_x=x_ship, ship_speed=ctl.speed, payout_speed=vc, paid_out=s_paid, top_tension=top,
                      bottom_tension=bottom, entry_angle=math.degrees(angle), touchdown_x=c.pos[c.lo, 0],
                      touchdown_z=c.pos[c.lo, 1], slack=slack, suspended_length=s_paid - c.s[c.lo],
                      laid_length=c.s[c.lo])
        for k, val in values.items():
            series[k].append(float(val))
        snaps.append((c.pos[c.lo:c.hi + 1].copy(), (c.T[c.lo:c.hi] * c.active[c.lo:c.hi]).copy()))
        xz = np.full((len(reps), 2), np.nan)
        for r in range(len(reps)):
            if rep_state[r] == 2:
                xz[r] = rep_landed[r]
        for k in range(c.lo + 1, c.hi):
            if c.rep[k] >= 0:
                xz[c.rep[k]] = c.pos[k]
        rep_out.append(xz)

    t = 0.0
    record(t)
    n_out = max(int(round(duration / output_interval)), 1)
    next_out = 1
    steps = iterations = halvings = 0
    interrupted, stop_reason = False, ""
    try:
        while next_out <= n_out:
            t_out = min(next_out * output_interval, duration)
            top, bottom, angle = _end_tensions(c, props)
            in_water = bool(np.any(rep_state == 1))
            dt = min(seg / (steps_per_segment * max(ctl.speed, vc, _MIN_SPEED)), max_time_step, t_out - t)
            if t_out - t - dt < 1e-3 * dt:
                dt = t_out - t
            chord = c.pos[c.hi] - c.pos[c.lo]
            geometry = (c.pos[c.lo, 0], -c.pos[c.lo, 1], chord[0] / max(chord[1], 1e-9))
            for attempt in range(_HALVINGS + 1):
                vs_new = ctl.ship_speed(t + dt, dt, in_water)
                x_new = x_ship + 0.5 * (ctl.speed + vs_new) * dt
                vc_new = ctl.payout_speed(t + dt, vs_new, geometry, bottom, dt) if attempt == 0 else vc_new
                lo, hi = c.lo, c.hi
                L_top = c.L[hi - 1]
                c.L[hi - 1] = s_paid + vc_new * dt - c.s[hi - 1]
                T_save, act_save = c.T[lo:hi].copy(), c.active[lo:hi].copy()
                ok, it, res = implicit_step(
                    c.pos[lo:hi + 1], c.vel[lo:hi + 1], np.array([x_new, 0.0]), c.L[lo:hi], c.seg_type[lo:hi],
                    props, c.point[lo:hi + 1], cur_d, cur_s, rho, dt, c.T[lo:hi], c.active[lo:hi], floor, tol,
                    max_iter, _ROUNDS, c.new_pos[lo:hi + 1], c.new_vel[lo:hi + 1])
                iterations += it
                if ok:
                    break
                c.L[hi - 1] = L_top
                c.T[lo:hi], c.active[lo:hi] = T_save, act_save
                if attempt == _HALVINGS:
                    raise ConvergenceError(
                        f"the laying step from t = {t:.6g} s did not converge: constraint residual {res:.3g} "
                        f"(relative) after {max_iter} iterations with dt = {dt:.3g} s (halved {_HALVINGS} "
                        "times). Suggested fix: a smaller 'steps_per_segment' dt is not the cause; check for a "
                        "cable that floats or is pulled taut between the ship and the seabed.",
                        time=t, iterations=max_iter, residual=res)
                dt *= 0.5
                halvings += 1
            lo, hi = c.lo, c.hi
            c.pos[lo:hi + 1] = c.new_pos[lo:hi + 1]
            c.vel[lo:hi + 1] = c.new_vel[lo:hi + 1]
            c.vel[hi] = (vs_new, 0.0)
            t += dt
            x_ship, ctl.speed, vc = x_new, vs_new, vc_new
            s_paid += vc * dt
            c.s[hi] = s_paid
            steps += 1
            # births at the surface
            while True:
                s_last = c.s[c.hi - 1]
                nxt = s_last + seg
                pending = [r.s for r, st in zip(reps, rep_state) if st == 0 and r.s > s_last + 1e-9]
                if pending and pending[0] - nxt < 0.5 * seg:
                    nxt = pending[0]
                if s_paid - nxt < 0.5 * seg:
                    break
                if nxt > par.cable_length:
                    break
                c.make_room()
                hi = c.hi
                a, b = c.pos[hi - 1].copy(), c.pos[hi].copy()
                va = c.vel[hi - 1].copy()
                chord = b - a
                unit = chord / math.hypot(*chord)
                v_exit = np.array([ctl.speed, 0.0]) - vc * unit
                f = (nxt - s_last) / (s_paid - s_last)
                for arr in (c.pos, c.vel, c.s, c.point, c.rep):
                    arr[hi + 1] = arr[hi]
                c.point[hi] = 0.0
                c.rep[hi] = -1
                c.pos[hi] = a + f * chord
                c.vel[hi] = va + f * (v_exit - va)
                c.s[hi] = nxt
                attach(hi, nxt)
                c.L[hi - 1] = nxt - s_last
                c.L[hi] = s_paid - nxt
                c.T[hi] = c.T[hi - 1]
                c.active[hi - 1] = c.active[hi] = 1
                c.seg_type[hi - 1] = par.type_at(0.5 * (s_last + nxt))
                c.seg_type[hi] = par.type_at(min(nxt + 0.5 * seg, par.cable_length))
                c.hi = hi + 1
            # touchdown
            while c.hi - c.lo > 2:
                k = c.lo + 1
                zb = float(seabed.z(c.pos[k, 0]))
                if c.pos[k, 1] > zb + 1e-9:
                    break
                c.pos[k, 1] = zb
                c.vel[k] = 0.0
                if not c.active[c.lo]:
                    # the cable arrived slack: its new lowest segment starts slack too (a straight,
                    # taut chain between fixed ends has no well-defined tension)
                    c.active[k], c.T[k] = 0, 0.0
                c.lo = k
                for key, val in (("x", c.pos[k, 0]), ("z", zb), ("s", c.s[k]), ("time", t)):
                    laid[key].append(float(val))
                if c.rep[k] >= 0:
                    rep_state[c.rep[k]] = 2
                    rep_landed[c.rep[k]] = c.pos[k]
            for k in range(c.lo + 2, c.hi):      # other nodes below a rising seabed stay on it
                zb = float(seabed.z(c.pos[k, 0]))
                if c.pos[k, 1] < zb:
                    c.pos[k, 1] = zb
                    c.vel[k, 1] = max(c.vel[k, 1], 0.0)
            if t >= t_out - 1e-9 * max(1.0, t_out):
                record(t)
                next_out += 1
                if progress is not None:
                    progress(t, duration)
            if s_paid >= par.cable_length:
                stop_reason = (f"all {par.cable_length:g} m of cable paid out at t = {t:.6g} s")
                warnings.warn(f"laying stopped: {stop_reason}. Suggested fix: make the line longer.",
                              SeacableWarning, stacklevel=2)
                break
    except KeyboardInterrupt:
        interrupted = True
    n_max = max(len(p) for p, _ in snaps)
    x = np.full((len(snaps), n_max), np.nan)
    z = np.full((len(snaps), n_max), np.nan)
    ten = np.full((len(snaps), n_max - 1), np.nan)
    for k, (p, tension) in enumerate(snaps):
        x[k, :len(p)] = p[:, 0]
        z[k, :len(p)] = p[:, 1]
        ten[k, :len(tension)] = tension
    return LayRun(time=np.array(out_t), series={k: np.array(v) for k, v in series.items()}, x=x, z=z,
                  tension=ten, laid={k: np.array(v) for k, v in laid.items()},
                  repeater_xz=np.array(rep_out).reshape(len(out_t), len(reps), 2), steps=steps,
                  iterations=iterations, halvings=halvings, wall_time=_time.perf_counter() - wall0,
                  interrupted=interrupted, stop_reason=stop_reason)


def props_row(mass, weight, diameter, drag_normal, drag_tangential, added_normal, added_tangential,
              compliance) -> np.ndarray:
    """One row of the property table (per unit length: kg/m, N/m, m, -, -, kg/m, kg/m, 1/N)."""
    row = np.zeros(N_PROPS)
    row[:] = (mass, weight, diameter, drag_normal, drag_tangential, added_normal, added_tangential, compliance)
    return row

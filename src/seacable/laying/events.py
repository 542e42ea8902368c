"""The state of a laying run and the events between its steps (:class:`_Lay`): payout and node birth at the
water entry, touchdown and lift-off, the sliding laid cable, the controls; see :mod:`seacable.laying.solver`.
"""

from __future__ import annotations

import bisect
import math
import warnings

import numpy as np

from ..errors import InputError, SeacableWarning
from .cable import (
    _MARGIN,
    _bottom_tension,
    _Cable,
    _initial_tangent,
    _length,
    _node_coordinates,
    _touchdown_distance,
    seabed_reaction,
)
from .control import Control
from .inputs import ShipMotion
from .kernel import P_WEIGHT, STEP_OK, drag_anchors, implicit_step, settle
from .parameters import LayParameters

_MIN_SPEED = 0.05     # floor of the speed that sets the time step [m/s]


_ROUNDS = 20          # active-set updates (segments going slack or taut) per step, beyond two per segment
_STRAIN_FLOOR = 1e-5  # strain of an 'inextensible' cable at the weight of its suspended length


_MAX_SLIDING = 2000   # laid nodes kept free to slide, at most (or twice the suspended ones, if more)


class _StepFailed(Exception):
    """A trial step of the implicit payout control did not converge (the step is retried with dt / 2)."""


def _rounds(n_segments: int) -> int:
    """Active-set updates allowed in a step.

    A slack cable pulled taut from one end tightens one segment per update (each segment is
    stretched only once the one above it carries tension), so a fixed count runs out on a long
    slack stretch with the Newton residual at round-off: allow two updates per segment.
    """
    return 2 * n_segments + _ROUNDS


class _Lay:
    """State of a laying run and the events between steps."""

    def __init__(self, par: LayParameters, ship: ShipMotion, payout, track, initial_angle: float | None,
                 motion=None):
        self.par, self.track = par, track
        # the chute's motion on the vessel's RAOs: times -> offsets from the track, velocities, accelerations
        # (seacable.vessel_motion.bind_vessel_motion); None: the chute follows the track
        self.motion = motion
        self.t_new = 0.0                   # the time at the end of the step last tried (the chute's there) [s]
        self.slack_seen = False            # whether a slack has been measured (see slack())
        seg = par.segment_length
        props = par.props
        self.ctl = ctl = Control(ship, payout, par)
        self.x_ship = ship.start_x         # distance run along the track (its KP in 3-D) [m]
        self.dt = 0.0                      # the last time step [s]
        self.warned_sliding = False
        self._now = None                   # the touchdown and the geometry of the state as it is (see changed())
        self._heading = None               # (x_ship, direction there, its components as floats): see heading()
        self._contact = par.friction is not None   # whether rows of c.contact may be 1 (see contact_forces())
        self._above = getattr(track, "highest", math.inf) + 1.0   # nodes higher are neither on nor under the seabed
        chute = track.point(self.x_ship)
        if motion is not None:
            chute = chute + motion(np.zeros(1))[0][0]
        depth0 = -float(track.zb(chute[:-1]))
        t = _initial_tangent(par, track, self.x_ship, ctl.speed, depth0, initial_angle)
        ell = _touchdown_distance(track, chute, t, 0.25 * seg)
        if ell > par.cable_length:
            raise InputError(f"the initial suspended cable needs {ell:.6g} m but the line is "
                             f"{par.cable_length:.6g} m long. Suggested fix: make the line (the cable on board) "
                             "longer.")
        self.reps = reps = sorted(par.repeaters, key=lambda r: r.s)
        self.rep_state = np.zeros(len(reps), dtype=np.int64)      # 0 on board, 1 in the water, 2 landed
        self.rep_landed = np.full((len(reps), track.dim), np.nan)
        # cable already on the seabed behind the touchdown (as long as the suspended part, whole segments), along
        # the ship's heading: the run starts in the middle of a lay, and tension can pick laid cable up again
        td = chute - ell * t
        back = track.direction(self.x_ship)
        n_laid = max(int(math.ceil(ell / seg)), 2)
        pre = n_laid * seg
        if pre + ell > par.cable_length:
            raise InputError(f"the run starts with {pre:.6g} m of cable on the seabed and {ell:.6g} m suspended, "
                             f"but the line is {par.cable_length:.6g} m long. Suggested fix: make the line (the "
                             "cable on board) longer.")
        laid_h = [td[:-1]]
        try:
            for _ in range(n_laid):
                slope = float(track.gradient(laid_h[-1] - 0.5 * seg * back) @ back)
                laid_h.append(laid_h[-1] - seg / math.sqrt(1.0 + slope * slope) * back)
            laid_z = track.zb(np.array(laid_h))
        except InputError:                       # a grid that gives no depth there (at the farthest point reached)
            p = laid_h[-1]
            raise InputError(f"the seabed does not cover the cable already on the seabed at the start: no depth "
                             f"behind x = {p[0]:.1f} m" + (f", y = {p[1]:.1f} m" if len(p) > 1 else "")
                             + f" ({pre:.6g} m of cable laid behind the touchdown, {ell:.6g} m from the ship). "
                             "Suggested fix: extend the seabed grid behind the start by twice the layback, or start "
                             "the ship further along the route (analysis.ship.start_x).") from None
        laid_h, laid_z = laid_h[::-1], laid_z[::-1]          # from the far end to the touchdown
        self.laid = {"p": [np.append(h, float(z)) for h, z in zip(laid_h, laid_z)],
                     "s": [k * seg for k in range(n_laid + 1)], "time": [0.0] * (n_laid + 1),
                     "T": [0.0] * (n_laid + 1)}
        for r, rep in enumerate(reps):
            if rep.s <= pre:
                self.rep_state[r] = 2
                k = int(np.argmin(np.abs(np.asarray(self.laid["s"]) - rep.s)))
                self.rep_landed[r] = self.laid["p"][k]
        s_nodes = [pre + v for v in _node_coordinates(ell, seg, [r.s - pre for r in reps])]
        cot = float(np.linalg.norm(t[:-1])) / max(t[-1], 1e-9)
        self.vc = vc = ctl.payout_speed(0.0, ctl.speed, (self.slope_at(td[:-1]), depth0, cot, 1.0), 0.0, 0.0)
        self.c = c = _Cable(max(64, 4 * len(s_nodes)), track.dim)
        n0 = len(s_nodes)
        c.lb = c.lo = _MARGIN
        c.hi = _MARGIN + n0 - 1
        ship_v = self.ship_velocity(ctl.speed)
        for k, s in enumerate(s_nodes):
            row = c.lo + k
            c.pos[row] = chute - (pre + ell - s) * t
            c.vel[row] = ship_v - vc * t
            c.s[row] = s
            if 0 < k < n0 - 1:
                self.attach(row)
            if k < n0 - 1:
                c.L[row] = s_nodes[k + 1] - s
                c.seg_type[row] = par.type_at(0.5 * (s + s_nodes[k + 1]))
                # the straight steady lay's tension (weight along the cable) as the first guess
                c.T[row] = props[c.seg_type[row], P_WEIGHT] * t[-1] * 0.5 * (s + s_nodes[k + 1] - 2 * pre)
        c.pos[c.lo] = self.laid["p"][-1]
        c.vel[c.lo] = 0.0
        c.vel[c.hi] = ship_v if motion is None else ship_v + motion(np.zeros(1))[1][0]
        c.active[c.lo], c.T[c.lo] = 0, 0.0    # zero tension at the touchdown: the straight lay's bottom is slack
        self.s_paid = pre + ell
        self.s_start = pre                 # material coordinate of the touchdown at t = 0 [m]
        self.s_paid0 = self.s_paid         # ... and of the water entry
        # an inextensible cable gets the compliance of a 1e-5 strain under the weight of the initial suspended
        # length: immaterial for the shape, it keeps the matrix of a straight taut cable regular
        self.floor = _STRAIN_FLOOR / (float(np.max(props[:, P_WEIGHT])) * max(ell, seg))

    def heading(self) -> tuple[np.ndarray, list[float]]:
        """The track's direction where the ship is (``track.direction(x_ship)``), as an array and as floats: looked
        up once for each position of the ship (several times a step). Not to be changed in place."""
        h = self._heading
        if h is None or h[0] is not self.x_ship:
            e = self.track.direction(self.x_ship)
            h = self._heading = (self.x_ship, e, e.tolist())
        return h[1], h[2]

    def ship_velocity(self, speed: float) -> np.ndarray:
        """The water entry's velocity at ``speed`` along the track where the ship is. [m/s]"""
        return np.array(self._ship_velocity(speed))

    def _ship_velocity(self, speed: float) -> list[float]:
        """:meth:`ship_velocity` as a list: ``speed`` times the direction, and 0 up (the same products). [m/s]"""
        v = [speed * e for e in self.heading()[1]]
        v.append(0.0)
        return v

    def _chute_velocity(self, speed: float) -> list[float]:
        """The chute's velocity: :meth:`_ship_velocity` plus the vessel's motion at the time of the last step. [m/s]"""
        v = self._ship_velocity(speed)
        if self.motion is not None:
            v = (np.asarray(v) + self.motion(np.array([self.t_new]))[1][0]).tolist()
        return v

    def changed(self) -> None:
        """Forget the touchdown and the geometry worked out for the state (:meth:`touchdown`, :meth:`geometry`):
        called by whatever moves the nodes, the ship or the rows of the suspended cable."""
        self._now = None

    def slope_at(self, ph) -> float:
        """The seabed's slope along the ship's heading under the horizontal point ``ph``. [-]"""
        return self.track.slope_along(ph, self.x_ship)

    def attach(self, row: int) -> None:
        """Put the repeater whose coordinate is ``s[row]`` (if any) on node ``row``."""
        c = self.c
        c.point[row] = 0.0
        c.rep[row] = -1
        for r, rep in enumerate(self.reps):
            if abs(rep.s - c.s[row]) < 1e-9:
                c.point[row] = (rep.mass, rep.added_mass, rep.weight, rep.drag_area)
                c.rep[row] = r
                self.rep_state[r] = 1

    def step(self, t: float, dt: float, in_water: bool, vc_new: float, kernel_args):
        """One implicit step; returns ``(status, iterations, residual, vs_new, x_new)`` (state not committed)."""
        c, ctl = self.c, self.ctl
        vs_new = ctl.ship_speed(t + dt, dt, in_water)
        x_new = self.x_ship + 0.5 * (ctl.speed + vs_new) * dt
        hi = c.hi
        c.L[hi - 1] = self.s_paid + vc_new * dt - c.s[hi - 1]
        props, cur_d, cur_v, rho, tol, max_iter = kernel_args
        pos, vel, point, new_pos, new_vel, contact, normal, grip, anchor, L, seg_type, T, active = c.window()
        seabed = (contact, normal, grip, anchor, self.par.friction_distance)
        chute = self.track.point(x_new)
        if self.motion is not None:
            self.t_new = t + dt
            chute = chute + self.motion(np.array([t + dt]))[0][0]
        status, it, res = implicit_step(
            pos, vel, chute, L, seg_type, props, point, cur_d, cur_v, rho, dt, T, active,
            self.floor, seabed, tol, max_iter, _rounds(hi - c.lb), new_pos, new_vel)
        return status, it, res, vs_new, x_new

    def implicit_payout(self, t: float, dt: float, in_water: bool, first, vc0: float, kernel_args, saved):
        """Solve the step together with a bottom-tension payout control (backward Euler for both).

        The payout speed of the step is the one the control gives for the bottom tension at the
        end of the step, ``v = P(T_b(v))``, instead of the one for the bottom tension at its start.
        The explicit coupling is a discrete feedback loop whose gain per step is
        ``gain (dt / time_constant) V dT_b/dv_c / (w h)``: the bottom of a lay under tension is a
        nearly straight cable, stiff against a change of its length (``dT_b/dv_c`` of several kN
        per m/s at a 0.8 s step), so at a few steps per segment the loop rang at the step frequency
        (bottom tension swinging 0 .. 1200 N around 500 N, nodes landing and lifting in turn).
        ``v - P(T_b(v))`` increases with ``v`` (more payout, less tension, a speed that does not
        grow with it), so its root is unique; it is bracketed from the explicit guess ``vc0`` and
        found by regula falsi (Illinois), every evaluation a step from the same start (``first`` is the
        converged step at ``vc0``, as :meth:`step` returns it; ``saved`` the segment lengths,
        tensions and slack set before it).

        Returns
        -------
        status, iterations, residual, vs_new, x_new
            As :meth:`step`, for the final payout speed.
        vc : float
            Payout speed of the step. [m/s]
        """
        c, ctl = self.c, self.ctl
        lo, hi = c.lb, c.hi
        geometry = self.geometry()
        total = 0
        last = {"v": vc0, "out": first}
        vs_new = first[3]

        known = {}                                  # v -> v - P(T_b(v)); the cable holds the step at last["v"]

        def g(v: float, solve: bool = False) -> float:
            nonlocal total
            if v in known and not solve:
                return known[v]
            if last["v"] != v:
                c.T[lo:hi], c.active[lo:hi] = saved[1], saved[2]
                out = self.step(t, dt, in_water, v, kernel_args)
                total += out[1]
                last["v"], last["out"] = v, out
                if out[0] != STEP_OK:
                    raise _StepFailed
            known[v] = v - ctl.payout_speed(t + dt, vs_new, geometry, self.trial_bottom_tension(), dt, commit=False)
            return known[v]

        # speed tolerance: the paid-out length of the step right to 1e-6 of its advance V dt (a bottom tension
        # right to about 1e-2 N at 8 kN/m, the stiffness above); the bottom tension of a Newton step is itself
        # only right to EA x its relative tolerance (3e-2 N at 3e7 N and 1e-9), 1e-5 m/s in the control
        tol_v = 1e-6 * max(vs_new, vc0, _MIN_SPEED)
        try:
            a, ga = vc0, g(vc0)
            if abs(ga) > tol_v:
                b = vc0 - ga                         # the explicit (fixed-point) update
                gb = g(b)
                for _ in range(40):                  # same side: extrapolate by the secant, widening
                    if ga * gb <= 0.0:
                        break
                    step = -gb * (b - a) / (gb - ga) if gb != ga else b - a
                    step = math.copysign(min(abs(step), 4.0 * abs(b - a)), step)
                    a, ga = b, gb
                    b = max(b + step, 0.0)
                    gb = g(b)
                # bracketed: regula falsi (Illinois), to |g| <= tol_v or a bracket of tol_v (a jump of T_b
                # where a node lands or not)
                for _ in range(100):
                    if abs(gb) <= tol_v or abs(b - a) <= tol_v:
                        break
                    v = b - gb * (b - a) / (gb - ga)
                    gv = g(v)
                    if gv * gb < 0.0:
                        a, ga = b, gb
                    else:
                        ga *= 0.5
                    b, gb = v, gv
                if abs(ga) < abs(gb):
                    b = a
                g(b, solve=True)
        except _StepFailed:
            out = last["out"]
            return out[0], total, out[2], out[3], out[4], last["v"]
        out = last["out"]
        return out[0], total, out[2], out[3], out[4], last["v"]

    def lifts_off(self) -> bool:
        """Whether the bottom segment pulls the touchdown node up harder than the cable weighs on it.

        The node carries half of the bottom segment and half of the laid segment behind it; the
        laid cable takes the pull along the seabed. Pull and weight are compared across the seabed
        (its slope under the bottom segment): a tension along a rising seabed does not lift the
        cable off it.
        """
        c = self.c
        lo = c.lo
        if len(self.laid["s"]) < 2 or not c.active[lo] or c.hi - lo < 2:
            return False
        d = c.new_pos[lo + 1] - c.new_pos[lo]
        grad = self.track.gradient(0.5 * (c.new_pos[lo, :-1] + c.new_pos[lo + 1, :-1]))
        cos_b = 1.0 / math.sqrt(1.0 + float(grad @ grad))     # normal to the seabed: (-grad, 1) cos_b
        up = c.T[lo] * (d[-1] - float(grad @ d[:-1])) * cos_b / _length(d)
        w = self.par.props[c.seg_type[lo], P_WEIGHT]
        behind = self.laid["s"][-1] - self.laid["s"][-2]
        return up > (0.5 * w * (c.L[lo] + behind) + c.point[lo, 2]) * cos_b

    def lift(self) -> None:
        """Pick the touchdown node up off the seabed: the node laid before it becomes the touchdown."""
        c, laid = self.c, self.laid
        self.changed()
        for key in laid:
            laid[key].pop()
        if c.lo - 1 > c.lb:                  # laid cable free to slide: the node is in the step already
            if c.rep[c.lo] >= 0:
                self.rep_state[c.rep[c.lo]] = 1
            c.lo -= 1
            return
        c.make_room_below()
        lo = c.lo
        new = lo - 1
        c.pos[new] = laid["p"][-1]
        c.new_pos[new] = c.pos[new]
        c.vel[new] = 0.0
        c.s[new] = laid["s"][-1]
        self.attach(new)
        if c.rep[new] >= 0:
            self.rep_state[c.rep[new]] = 2     # the new touchdown node is still on the seabed
        if c.rep[lo] >= 0:
            self.rep_state[c.rep[lo]] = 1      # picked up: in the water again
        c.L[new] = c.s[lo] - c.s[new]
        c.T[new] = c.T[lo]
        c.active[new] = 1
        c.seg_type[new] = self.par.type_at(0.5 * (c.s[new] + c.s[lo]))
        c.lb = c.lo = new

    def commit(self, dt: float, vs_new: float, x_new: float, vc_new: float) -> None:
        c = self.c
        self.changed()
        hi = c.hi
        pos, vel, _, new_pos, new_vel = c.window()[:5]
        pos[:] = new_pos
        vel[:] = new_vel
        if c.lo > c.lb:                      # laid cable that slides: back onto the seabed (the step kept it on
            rows = slice(c.lb + 1, c.lo + 1)  # the tangent plane), and its record follows it
            drag_anchors(c.pos[rows], c.contact[rows], c.normal[rows], c.anchor[rows], self.par.friction_distance)
            c.pos[rows, -1] = self.track.zb(c.pos[rows, :-1])
            n = c.lo - c.lb
            self.laid["p"][-n:] = [row.copy() for row in c.pos[rows]]     # (a copy each: a row of one block would
            self.laid["T"][-n:] = (c.T[c.lb:c.lo] * c.active[c.lb:c.lo]).tolist()   # keep the whole block alive)
        self.x_ship, self.vc, self.dt = x_new, vc_new, dt
        c.vel[hi] = self._chute_velocity(vs_new)
        self.s_paid += vc_new * dt
        c.s[hi] = self.s_paid

    def births(self) -> None:
        """Nodes born on the top segment, one segment length apart (repeaters at their own s)."""
        c, par = self.c, self.par
        seg = par.segment_length
        while True:
            s_last = float(c.s[c.hi - 1])      # (Python floats here and below: numpy's arithmetic, to the bit)
            nxt = s_last + seg
            if self.reps:
                pending = [r.s for r, st in zip(self.reps, self.rep_state) if st == 0 and r.s > s_last + 1e-9]
                if pending and pending[0] - nxt < 0.5 * seg:
                    nxt = pending[0]
            if self.s_paid - nxt < 0.5 * seg or nxt > par.cable_length:
                return
            self.changed()
            c.make_room()
            hi = c.hi
            a, va = c.pos[hi - 1].tolist(), c.vel[hi - 1].tolist()
            chord = c.pos[hi] - c.pos[hi - 1]
            ln, vc = _length(chord), self.vc
            chord = chord.tolist()
            v_exit = [v - vc * d / ln for v, d in zip(self._chute_velocity(self.ctl.speed), chord)]
            f = (nxt - s_last) / (self.s_paid - s_last)
            for arr in (c.pos, c.vel, c.s, c.point, c.rep):
                arr[hi + 1] = arr[hi]
            c.pos[hi] = [x + f * d for x, d in zip(a, chord)]
            c.vel[hi] = [v + f * (e - v) for v, e in zip(va, v_exit)]
            c.s[hi] = nxt
            self.attach(hi)
            c.L[hi - 1] = nxt - s_last
            c.L[hi] = self.s_paid - nxt
            c.T[hi] = c.T[hi - 1]
            c.active[hi - 1] = c.active[hi] = 1
            c.seg_type[hi - 1] = par.type_at(0.5 * (s_last + nxt))
            c.seg_type[hi] = par.type_at(min(nxt + 0.5 * seg, par.cable_length))
            c.hi = hi + 1

    def touchdowns(self, t: float) -> None:
        """Land the cable from the geometry: the first node on the seabed counting from the ship side
        and every node below it; keep the free nodes above the seabed.

        Nodes between the old touchdown node and that one that are above the seabed span a hollow of
        the seabed (the tension holds the cable up over a valley corner): they are laid where they
        are, as the laid cable does not move. Looking only at the lowest free node would leave the
        touchdown behind for good once the cable bridges a hollow while the rest of it rests on the
        seabed further on.
        """
        c = self.c
        self.changed()
        lo0 = c.lo
        free = self.seabed_under(c.pos[lo0 + 1:c.hi])     # under the free nodes, in one look-up
        # a seabed rising under the cable holds it up; then the first node on the seabed (landing_row)
        first = settle(c.pos, c.vel, free, lo0, c.hi)
        arrived_slack = not c.active[lo0]
        laid, props = self.laid, self.par.props
        for k in range(lo0 + 1, first + 1):
            zb = float(free[k - lo0 - 1])
            c.pos[k, -1] = max(c.pos[k, -1], zb) if k < first else zb
            c.vel[k] = 0.0
            c.anchor[k] = c.pos[k]
            laid["p"].append(c.pos[k].copy())
            laid["s"].append(float(c.s[k]))
            laid["time"].append(float(t))
            # the tension at the segment's lower end (its mid-segment value less the weight of its lower half)
            d = c.pos[k] - c.pos[k - 1]
            end = (float(c.T[k - 1]) - 0.5 * float(props[c.seg_type[k - 1], P_WEIGHT]) * float(c.L[k - 1])
                   * float(d[-1]) / _length(d))
            laid["T"].append(max(end, 0.0) * float(c.active[k - 1]))
            if c.rep[k] >= 0:
                self.rep_state[c.rep[k]] = 2
                self.rep_landed[c.rep[k]] = c.pos[k]
        if first > c.lo:
            if self.par.friction is None:
                c.lb = first
            c.lo = first
            if arrived_slack:
                # the cable arrived slack: its new lowest segment starts slack too (a straight, taut
                # chain between fixed ends has no well-defined tension)
                c.active[first], c.T[first] = 0, 0.0
        if self.par.friction is not None:
            self.sliding_zone()
            self.changed()
        # the seabed under the free nodes (rows lo + 1 .. hi - 1; -inf where not looked up), for touchdown()
        self._now = {"free": free[first - lo0:]}

    def sliding_zone(self) -> None:
        """Keep the laid cable that friction may let slide in the step (rows ``lb + 1 .. lo``).

        The laid cable takes the bottom tension ``T_b`` off by friction, at most ``mu w`` per metre, so
        beyond ``T_b / (mu w)`` behind the touchdown it carries no tension and lies still (a cable that slides
        across keeps its tension, and stays in the step while it slides). The rows kept reach 1.25 times that
        and four segments more; laid cable beyond is fixed (the row ``lb``) once it holds
        (it moved less than the friction's slip distance in the last step), and laid cable is freed again
        when the bottom tension grows.
        """
        c, laid, par = self.c, self.laid, self.par
        w = float(par.props[c.seg_type[c.lo], P_WEIGHT])
        reach = 4.0 * par.segment_length + 1.25 * _bottom_tension(c, par.props, c.pos, c.lo, 0.0) / (par.friction * w)
        # free again: laid cable behind the anchor, while the rows kept are short of the reach
        while c.s[c.lo] - c.s[c.lb] < reach and len(laid["s"]) - 1 - (c.lo - c.lb) > 0:
            c.make_room_below()
            k = len(laid["s"]) - 2 - (c.lo - c.lb)          # the laid node below the anchor
            new = c.lb - 1
            c.pos[new] = c.anchor[new] = laid["p"][k]
            c.vel[new] = 0.0
            c.s[new] = laid["s"][k]
            self.attach(new)
            if c.rep[new] >= 0:
                self.rep_state[c.rep[new]] = 2
            c.L[new] = c.s[c.lb] - c.s[new]
            c.active[new] = int(np.linalg.norm(c.pos[c.lb] - c.pos[new]) >= c.L[new])
            # the tension it was fixed with, as the first guess (0 would leave its node's predictor out of balance
            # by the whole tension, tens of metres off, and Newton crawling back a quarter segment at a time)
            c.T[new] = laid["T"][k + 1] * c.active[new]
            c.seg_type[new] = par.type_at(0.5 * (c.s[new] + c.s[c.lb]))
            c.lb = new
        # fixed: the laid cable beyond the reach that holds (moved less than the friction's slip in the last step),
        # and, at most _MAX_SLIDING nodes being kept, the oldest even if it slides
        most = max(_MAX_SLIDING, 2 * (c.hi - c.lo))
        while c.lb + 1 < c.lo and c.s[c.lo] - c.s[c.lb + 1] > reach:
            if float(np.linalg.norm(c.vel[c.lb + 1])) * self.dt >= par.friction_distance:
                if c.lo - c.lb <= most:
                    break
                if not self.warned_sliding:
                    self.warned_sliding = True
                    warnings.warn(
                        f"laid cable more than {c.s[c.lo] - c.s[c.lb + 1]:.6g} m behind the touchdown is still sliding "
                        f"(at {float(np.linalg.norm(c.vel[c.lb + 1])):.3g} m/s) and is fixed where it is: at most "
                        f"{most} laid nodes are kept free to slide. The friction (environment.seabed.friction = "
                        f"{par.friction:g}) does not hold the laid cable: a seabed steeper than atan(mu) across the "
                        "route, or a tension round a turn above mu w times its radius. Suggested fix: check the "
                        "friction and the seabed, or use laid_cable: held.", SeacableWarning, stacklevel=4)
            c.lb += 1
            c.vel[c.lb] = 0.0

    def contact_forces(self) -> None:
        """The seabed's normal and friction limit at the laid cable free to slide (rows ``lb + 1 .. lo``).

        The normal ``n`` is the seabed's, under each node; the reaction is what the node's weight (half of
        each adjacent segment and a repeater's) and the tensions of the old time step press along ``-n``
        (clipped at 0: a node pulled off carries no friction); the friction limit is ``mu`` times it.
        """
        c, par = self.c, self.par
        if self._contact:                # (with the laid cable held, no row is ever in contact: nothing to clear)
            c.contact[c.lb:c.hi + 1] = 0
        if c.lo == c.lb:
            return
        self._contact = True
        rows = np.arange(c.lb + 1, c.lo + 1)
        c.contact[rows] = 1
        n = np.concatenate([-self.track.gradients(c.pos[rows, :-1]), np.ones((len(rows), 1))], axis=1)
        n /= np.linalg.norm(n, axis=1)[:, None]
        c.normal[rows] = n
        w = par.props[:, P_WEIGHT]
        weight = 0.5 * (w[c.seg_type[rows]] * c.L[rows] + w[c.seg_type[rows - 1]] * c.L[rows - 1]) + c.point[rows, 2]
        reaction = seabed_reaction(c.pos[rows - 1], c.pos[rows], c.pos[rows + 1], c.T[rows - 1] * c.active[rows - 1],
                                   c.T[rows] * c.active[rows], weight, n)
        c.grip[rows] = par.friction * reaction

    def landing_row(self, pos: np.ndarray, zb: np.ndarray | None = None) -> int:
        """Row of the first node on the seabed counting from the ship side (``c.lo`` if none).

        One free node is always kept below the water entry. ``zb``: the seabed under rows ``c.lo + 1`` to
        ``c.hi - 2`` of ``pos`` when known.
        """
        c = self.c
        rows = pos[c.lo + 1:c.hi - 1]
        zb = self.seabed_under(rows) if zb is None else zb
        on = (rows[:, -1] <= zb + 1e-9).nonzero()[0]
        return c.lo + 1 + int(on[-1]) if on.size else c.lo

    def seabed_under(self, pos: np.ndarray) -> np.ndarray:
        """Seabed elevation under nodes ``pos`` (rows of ``dim`` coordinates); ``-inf`` (or the elevation) under
        those more than a metre above the highest seabed anywhere (``track.highest``), which are neither on nor
        under it. [m]"""
        return self.track.zb_under(pos, self._above)

    def trial_bottom_tension(self) -> float:
        """Bottom tension of the step just solved (``c.new_pos``, ``c.T``), not committed. [N]

        The same as :func:`_end_tensions` gives once the step is committed and its nodes on the
        seabed landed (:meth:`touchdowns`): the landing is done on a copy of the positions.
        """
        c = self.c
        pos = c.new_pos
        zb = self.seabed_under(pos[c.lo + 1:c.hi - 1])      # (looked up once for the landing and the touchdown)
        lo = self.landing_row(pos, zb)
        if lo > c.lo:
            if not c.active[c.lo]:
                return 0.0          # arrived slack: the new bottom segment starts slack (touchdowns)
            pos = pos[:c.hi + 1].copy()           # (the rows the touchdown reads, not the whole store)
            pos[lo, -1] = float(zb[lo - c.lo - 1])
        f = self.touchdown(pos, lo, zb[lo - c.lo:])[2]
        return _bottom_tension(c, self.par.props, pos, lo, f)

    def touchdown(self, pos: np.ndarray | None = None, lo: int | None = None,
                  zb: np.ndarray | None = None) -> tuple[np.ndarray, float, float]:
        """The touchdown point between the touchdown node and the lowest free node.

        The clearance above the seabed of the three lowest free nodes, as a function of the arc
        length, is extrapolated by the parabola through them to the bottom segment: its zero
        nearest to the lowest free node (its vertex if it has none) is the touchdown. A cable that
        reaches the seabed at an angle (zero bottom tension) has a clearance linear in the arc
        length and one under tension a quadratic one, so both are found between the nodes, not at
        the last node landed.

        Parameters
        ----------
        pos, lo
            Node positions and the touchdown node's row; default the committed state
            (``c.pos``, ``c.lo``).
        zb
            The seabed under the rows from ``lo + 1`` up, where known (as :meth:`seabed_under` gives it: looked up
            again where it is short or not finite).

        Returns
        -------
        p : (dim,) array
            Touchdown point (on the bottom segment's chord). [m]
        s : float
            Its material coordinate. [m]
        f : float
            Its fraction of the bottom segment from the touchdown node. [-]
        """
        c, track = self.c, self.track
        if pos is None and lo is None:
            if self._now is None:
                self._now = {}
            now = self._now.get("touchdown")
            if now is None:
                now = self._now["touchdown"] = self.touchdown(c.pos, c.lo)
            return now
        pos = c.pos if pos is None else pos
        lo = c.lo if lo is None else lo
        n_free = min(c.hi - lo - 1, 3)
        # (in Python floats: the same arithmetic as numpy's float64, quicker on scalars) the rows and the material
        # coordinates of the touchdown node and the lowest free nodes (at least the bottom segment's ends)
        m = max(n_free, 1) + 1
        rows, s_rows = pos[lo:lo + m].tolist(), c.s[lo:lo + m].tolist()
        s_lo, s1 = s_rows[0], s_rows[1]
        f = 0.0
        if n_free >= 2:
            ss = [v - s1 for v in s_rows[1:]]
            if zb is None and pos is c.pos and lo == c.lo and self._now is not None:
                zb = self._now.get("free")           # (as touchdowns() looked them up)
            zb = zb[:n_free].tolist() if zb is not None else []
            if len(zb) < n_free or not all(map(math.isfinite, zb)):
                zb = track.zb(pos[lo + 1:lo + 1 + n_free, :-1]).tolist()
            hh = [r[-1] - b for r, b in zip(rows[1:], zb)]
            u_lo = s_lo - s1
            b1 = (hh[1] - hh[0]) / ss[1]
            curv = 0.0
            if n_free == 3:
                curv = ((hh[2] - hh[0]) / ss[2] - b1) / (ss[2] - ss[1])
            slope = b1 - curv * ss[1]         # h(u) = h0 + slope u + curv u^2, u = s - s_1
            u = u_lo
            if abs(curv) * abs(u_lo) < 1e-9 * max(abs(slope), 1e-300):
                if slope > 0.0:
                    u = -hh[0] / slope
            else:
                disc = slope * slope - 4.0 * curv * hh[0]
                if disc < 0.0:
                    u = -slope / (2.0 * curv)
                else:
                    roots = ((-slope + math.sqrt(disc)) / (2.0 * curv), (-slope - math.sqrt(disc)) / (2.0 * curv))
                    below = [r for r in roots if r <= 0.0]
                    u = max(below) if below else u_lo
            u = min(max(u, u_lo), 0.0)
            f = 1.0 - u / u_lo if u_lo < 0.0 else 0.0
        p = np.array([a + f * (b - a) for a, b in zip(rows[0], rows[1])])
        return p, s_lo + f * (s1 - s_lo), f

    def geometry(self):
        """The seabed's slope along the heading at the touchdown, the depth there, the cot of the chord's
        angle and the touchdown's speed over the ship's in a turn (:meth:`turn_factor`), for the payout control."""
        c = self.c
        p, _, _ = self.touchdown()
        now = self._now.get("geometry")
        if now is None:
            chord = c.pos[c.hi] - p
            rise = float(chord[-1])
            # (the chord's horizontal length: in 2-D the one term of _length's dot product, 0.0 + x * x)
            h = float(chord[0])
            run = math.sqrt(0.0 + h * h) if len(chord) == 2 else _length(chord[:-1])
            now = self._now["geometry"] = (self.slope_at(p[:-1]), -float(p[-1]), run / max(rise, 1e-9),
                                           self.turn_factor(chord))
        return now

    def bottom_tension(self) -> float:
        """The bottom tension of the state (as :func:`_end_tensions` gives it). [N]"""
        c = self.c
        return _bottom_tension(c, self.par.props, c.pos, c.lo, self.touchdown()[2])

    def turn_factor(self, chord: np.ndarray) -> float:
        """Touchdown speed over ship speed while the ship turns (1 on a straight track).

        In a steady turn at the rate ``Omega`` the span is steady in the turning frame, so the touchdown moves
        as a point of a rigid body: ``v_td = v_s + Omega e_3 x (r_td - r_s)`` (inside a turn it is slower than
        the ship). ``Omega / V_s`` is taken as the track's change of heading over the chord's horizontal length
        behind the ship (the distance the ship sails while the span is paid out), which on a circle of radius
        R is 1/R exactly.
        """
        if self.track.dim == 2:
            return 1.0
        back = _length(chord[:-1])
        ahead = self.heading()[0]
        behind = self.track.direction(self.x_ship - back)
        turn = math.atan2(behind[0] * ahead[1] - behind[1] * ahead[0], float(behind @ ahead))
        if turn == 0.0:
            return 1.0
        rate = turn / back                              # Omega / V_s [1/m]
        return float(math.hypot(ahead[0] + rate * chord[1], ahead[1] - rate * chord[0]))

    def repeater_positions(self) -> np.ndarray:
        c = self.c
        xz = np.full((len(self.reps), self.track.dim), np.nan)
        if not self.reps:
            return xz
        for r in range(len(self.reps)):
            if self.rep_state[r] == 2:
                xz[r] = self.rep_landed[r]
        for k in range(c.lo + 1, c.hi):
            if c.rep[k] >= 0:
                xz[c.rep[k]] = c.pos[k]
        return xz

    def slack(self, t: float, window: float) -> float:
        """Laid length over seabed distance minus one, over the nodes landed in the last ``window`` s."""
        lp, ls, lt = self.laid["p"], self.laid["s"], self.laid["time"]
        k0 = bisect.bisect_right(lt, max(t - window, 0.0))   # landed during the run (lt: sorted)
        if len(lt) - k0 < 3 and self.slack_seen:
            # fewer than 3 in the window after a slack was measured: nodes lifted off again (a heaving chute picks
            # laid cable up) or landings slowed; the last 3 laid nodes, not a NaN after numbers
            k0 = max(min(k0, len(lt) - 3), 0)
        if len(lt) - k0 < 3:
            return np.nan
        run = self.track.run(lp[k0:])
        if run > 0:
            self.slack_seen = True
        return (ls[-1] - ls[k0]) / run - 1.0 if run > 0 else np.nan

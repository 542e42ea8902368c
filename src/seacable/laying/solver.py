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
* **touchdown** - found from the geometry after every step: the first node on the seabed counting
  from the ship side lands, and so does every free node below it (nodes above the seabed there span
  a hollow, held up by the tension, and are laid where they are). A landed node stops (its momentum
  goes to the seabed) and stays there; the last one is the touchdown node and the others join the
  laid cable. The reported touchdown point lies between the touchdown node and the lowest free node,
  where the clearance of the lowest free nodes extrapolates to zero (:meth:`.events._Lay.touchdown`); the
  layback, the suspended and laid lengths and the bottom tension are taken there. Mass is conserved:
  paid-out length = laid + suspended length.
* **sliding laid cable** (``LayParameters.friction``; default held where it lands) - the laid nodes within
  ``1.25 T_b / (mu w)`` and four segments of the touchdown stay in the step, on the seabed against friction
  (:meth:`.events._Lay.contact_forces`, :meth:`.events._Lay.sliding_zone`); their record (``laid``, with the tension of each laid
  segment) follows them, and beyond that reach the laid cable is fixed once it holds.

Controls: the ship speed follows its schedule, slowed to ``repeater_speed`` while a repeater is in
the water and brought back at the given acceleration after its touchdown; the payout speed follows a
schedule, a target slack (with the paper's slope adjustment, CPRATE) or a target bottom tension.
The bottom-tension control is solved with the step, from the bottom tension at its end (backward
Euler for the cable and its control together, :meth:`.events._Lay.implicit_payout`): from the tension at the
start of the step the loop rings at the step frequency once ``dt`` is a fair part of a segment's
passage (at the default 4 steps per segment).
The time step is set from the speed: ``dt = l / (n V)`` for segment length ``l``, ``n`` steps per
segment and ``V`` the larger of the ship and payout speeds (the paper's "time step inversely
proportional to ship speed"), shortened to equal steps between output times.

The run's parameters are those of :mod:`.parameters`; the cable's node storage and the lay's geometry are in
:mod:`.cable`, the state of a run and its events between steps in :mod:`.events`; this module marches in time.
"""

from __future__ import annotations

import math
import time as _time
import warnings

import numpy as np

from .._atomic import keep_whole_outputs
from ..errors import ConvergenceError, SeacableWarning
from .cable import _end_tensions, _length, seabed_reaction
from .events import _MIN_SPEED, _Lay, _rounds
from .inputs import PayoutBottomTension, ShipMotion
from .kernel import STEP_ACTIVE_SET, STEP_NOT_CONVERGED, STEP_OK
from .parameters import LayParameters, LayRun, Repeater, props_row  # noqa: F401  (props_row: public here too)

__all__ = ["LayParameters", "LayRun", "Repeater", "initial_state", "seabed_reaction", "simulate"]


_HALVINGS = 6         # a failing step is retried with dt/2, dt/4, ...


_MAX_LIFTS = 50       # touchdown nodes picked up off the seabed in one step


def _step_error(status: int, t: float, dt: float, res: float, tol: float, max_iter: int, rounds: int):
    """The ConvergenceError of a step that failed at its smallest time step, naming what failed."""
    head = f"the laying step from t = {t:.6g} s failed with dt = {dt:.3g} s (halved {_HALVINGS} times): "
    fix = ("Suggested fix: check that the cable sinks (weight in water > 0) and that the payout is not far "
           "below the ship speed of an inextensible cable; a smaller analysis.segment_length or a larger "
           "analysis.steps_per_segment may help.")
    if status == STEP_NOT_CONVERGED:
        why = (f"Newton did not converge: residual {res:.3g} > tolerance {tol:.3g} (relative, "
               f"analysis.tolerance) after {max_iter} iterations (analysis.max_iterations). ")
    elif status == STEP_ACTIVE_SET:
        why = (f"Newton converged (residual {res:.3g} <= tolerance {tol:.3g}) but segments kept going slack and "
               f"taut again: the set of slack segments did not settle in {rounds} updates. ")
    else:
        why = f"the Newton matrix is singular (residual {res:.3g}, tolerance {tol:.3g}). "
    return ConvergenceError(head + why + fix, time=t, iterations=max_iter, residual=res)


_SERIES = ("ship_x", "ship_speed", "payout_speed", "paid_out", "top_tension", "bottom_tension", "entry_angle",
           "touchdown_x", "touchdown_z", "layback", "slack", "suspended_length", "laid_length")


def initial_state(par: LayParameters, ship: ShipMotion, payout, track, initial_angle: float | None = None,
                  motion=None) -> None:
    """Build the run's starting lay (the straight span and the cable already on the seabed behind it) and raise
    the InputError :func:`simulate` would (a line too short for it, a seabed that does not cover it): the checks of
    ``validate`` before the time loop."""
    _Lay(par, ship, payout, track, initial_angle, motion)


def simulate(par: LayParameters, ship: ShipMotion, payout, track, duration: float, *,
             output_interval: float = 1.0, steps_per_segment: float = 4.0, max_time_step: float = 1.0,
             initial_angle: float | None = None, slack_window: float = 60.0, tol: float = 1e-9,
             max_iter: int = 50, progress=None, motion=None) -> LayRun:
    """Lay cable from a moving ship for ``duration`` seconds.

    Parameters
    ----------
    par
        Cable and water data.
    ship, payout
        Ship motion and payout control (see :mod:`seacable.laying.inputs`).
    track
        The ship's track and the seabed: :class:`~seacable.laying.track.Track2D` (paper 001's plane) or
        :class:`~seacable.laying.track.Track3D` (a route).
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
    motion
        The chute's motion on the vessel's RAOs: ``motion(times)`` -> offsets from the track, velocities and
        accelerations, each (len(times), D) (:func:`seacable.vessel_motion.bind_vessel_motion`); default None,
        the chute on the track. [m, m/s, m/s^2]

    Returns
    -------
    LayRun

    Raises
    ------
    ConvergenceError
        When a step fails after ``6`` halvings, with the time and the residual.
    """
    wall0 = _time.perf_counter()
    lay = _Lay(par, ship, payout, track, initial_angle, motion)
    c, ctl, props = lay.c, lay.ctl, par.props
    kernel_args = (props, par.current_depths, par.current_velocity, par.water_density, tol, max_iter)
    out_t, series, snaps, rep_out, points = [], {k: [] for k in _SERIES}, [], [], []

    def record(t: float) -> None:
        p_td, s_td, f_td = lay.touchdown()
        top, bottom, angle = _end_tensions(c, props, f_td)
        out_t.append(t)
        ship_p = c.pos[c.hi]
        # the horizontal distance, negative when the touchdown is ahead of the ship (in 2-D: x_ship - x_td)
        reach = ship_p[:-1] - p_td[:-1]
        layback = math.copysign(_length(reach), float(reach @ lay.heading()[0]))
        values = (lay.x_ship, ctl.speed, lay.vc, lay.s_paid - lay.s_paid0, top, bottom, angle, p_td[0],
                  p_td[-1], layback, lay.slack(t, slack_window), lay.s_paid - s_td, s_td - lay.s_start)
        points.append((ship_p.copy(), p_td.copy()))
        for k, val in zip(_SERIES, values):
            series[k].append(float(val))
        snaps.append((c.pos[c.lo:c.hi + 1].copy(), c.T[c.lo:c.hi] * c.active[c.lo:c.hi]))
        rep_out.append(lay.repeater_positions())

    implicit = isinstance(payout, PayoutBottomTension)
    t = 0.0
    record(t)
    n_out = max(int(round(duration / output_interval)), 1)
    next_out = 1
    steps = iterations = halvings = lifts = 0
    interrupted, stop_reason = False, ""
    try:
        while next_out <= n_out:
            t_out = min(next_out * output_interval, duration)
            # (the bottom tension and the geometry: for the payout controls that use them)
            bottom = lay.bottom_tension() if implicit else 0.0
            in_water = bool(lay.reps) and bool(np.any(lay.rep_state == 1))
            # equal steps to the next output, none longer than l / (n V): a sliver of a step to meet the output
            # time would report its own tensions, those of an impulse (the momentum of a node that has just
            # landed, stopped within the sliver: a slack bottom segment at 500 N of bottom tension)
            dt_max = min(par.segment_length / (steps_per_segment * max(ctl.speed, lay.vc, _MIN_SPEED)), max_time_step)
            # (allowed 1 % of a step longer, not to switch between n and n + 1 steps per output as the payout speed
            # of a bottom-tension lay flickers about the ship speed)
            dt = (t_out - t) / max(math.ceil((t_out - t) / dt_max - 0.01), 1)
            # bottom-tension mode: the explicit speed is the first guess of the implicit one (Lay.implicit_payout)
            vc_new = ctl.payout_speed(t + dt, ctl.ship_speed(t + dt, dt, in_water),
                                      lay.geometry() if ctl.uses_geometry else None, bottom, dt, commit=not implicit)
            attempt, lifted = 0, 0
            while True:
                lay.contact_forces()
                lo, hi = c.lb, c.hi
                saved = (c.L[hi - 1], c.T[lo:hi].copy(), c.active[lo:hi].copy())
                status, it, res, vs_new, x_new = lay.step(t, dt, in_water, vc_new, kernel_args)
                iterations += it
                if status == STEP_OK and implicit:
                    status, it, res, vs_new, x_new, vc_new = lay.implicit_payout(
                        t, dt, in_water, (status, it, res, vs_new, x_new), vc_new, kernel_args, saved)
                    iterations += it
                ok = status == STEP_OK
                restore = not ok or (lifted < _MAX_LIFTS and lay.lifts_off())
                if restore:
                    c.L[hi - 1] = saved[0]
                    c.T[lo:hi], c.active[lo:hi] = saved[1], saved[2]
                if ok and not restore:
                    break
                if ok:                       # pulled off the seabed: redo the step with a longer span
                    lay.lift()
                    lifted += 1
                    lifts += 1
                    continue
                if attempt == _HALVINGS:
                    raise _step_error(status, t, dt, res, tol, max_iter, rounds=_rounds(hi - lo))
                dt *= 0.5
                attempt += 1
                halvings += 1
            if implicit:                     # advance the filter with the bottom tension of the accepted step
                ctl.payout_speed(t + dt, vs_new, lay.geometry(), lay.trial_bottom_tension(), dt)
            lay.commit(dt, vs_new, x_new, vc_new)
            t += dt
            ctl.update(vs_new, t)
            steps += 1
            lay.births()
            lay.touchdowns(t)
            if t >= t_out - 1e-9 * max(1.0, t_out):
                record(t)
                next_out += 1
                if progress is not None:
                    progress(t, duration)
            if lay.s_paid >= par.cable_length:
                stop_reason = f"all {par.cable_length:g} m of cable paid out at t = {t:.6g} s"
                warnings.warn(f"laying stopped: {stop_reason}. Suggested fix: make the line longer.",
                              SeacableWarning, stacklevel=2)
                break
    except KeyboardInterrupt:
        interrupted = True
        # an interrupt inside record (or a touchdown's bookkeeping) leaves one list a row longer than the
        # others: keep the outputs (and laid points) that all of them hold
        keep_whole_outputs(out_t, points, snaps, rep_out, *series.values())
        keep_whole_outputs(*lay.laid.values())
    n_max = max(len(p) for p, _ in snaps)
    pos = np.full((len(snaps), n_max, track.dim), np.nan)
    ten = np.full((len(snaps), n_max - 1), np.nan)
    for k, (p, tension) in enumerate(snaps):
        pos[k, :len(p)] = p
        ten[k, :len(tension)] = tension
    return LayRun(time=np.array(out_t), series={k: np.array(v) for k, v in series.items()}, pos=pos,
                  tension=ten, laid={k: np.array(v) for k, v in lay.laid.items()},
                  ship=np.array([a for a, _ in points]), touchdown=np.array([b for _, b in points]),
                  repeater_pos=np.array(rep_out).reshape(len(out_t), len(lay.reps), track.dim), steps=steps,
                  iterations=iterations, halvings=halvings, lifts=lifts, wall_time=_time.perf_counter() - wall0,
                  interrupted=interrupted, stop_reason=stop_reason)

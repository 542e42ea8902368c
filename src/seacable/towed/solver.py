"""Towed-cable dynamics (paper 000): set-up, the steady initial state and the time integration.

:func:`cable_parameters` packs the cable and water into the parameter vector of
:mod:`seacable.towed.equations`; :func:`steady_tow` solves the box equations with the time
derivatives set to zero for a vessel moving at a constant velocity (the initial state of a run:
the static solution of the same discrete equations, no relaxation); :func:`simulate` marches them
in time behind a vessel path with Newton-Raphson at every step, halving the step where Newton
fails.

References
----------
.. [1] Paper 000 (seeds/000_e4cc68758a51635b.txt): eq. (2)-(21), Tables 1-3, Fig. 4-6.
.. [2] Ablow, C. M. and Schechter, S., 1983. Numerical simulation of undersea cable dynamics.
   Ocean Engineering 10(6), 443-457.
.. [3] Gobat, J. I. and Grosenbaugh, M. A., 2006. Time-domain numerical simulation of ocean cable
   structures. Ocean Engineering 33, 1373-1400.
"""

from __future__ import annotations

import math
import time as _time
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from .. import _validate as v
from .._atomic import keep_whole_outputs
from ..errors import ConvergenceError, InputError
from ..statics.towed import TangentialDragForm, towed_cable_steady
from .equations import (
    I_ON,
    I_PH,
    I_T,
    I_TH,
    NV,
    P_DS,
    P_EI,
    P_IEA,
    P_KN,
    P_KT,
    P_M,
    P_MAN,
    P_MAT,
    P_POW,
    P_STRETCH,
    P_W,
    PARAMETERS,
    frame,
    integrate_positions,
)
from .scheme import (B_AXES, B_DRAG, B_HAS, B_MASS, B_MAXES, B_QAXES, B_SIZE, B_WEIGHT, STATUS, march,
                     newton_step, node_currents, velocity_global, workspace)

__all__ = ["TowedBodyParameters", "TowedRun", "cable_parameters", "body_parameters", "steady_tow",
           "simulate"]

_SOLVERS = {"block": 0, "dense": 1, "banded": 2}

MAX_HALVINGS = 6
"""Times a failed step is halved before the run stops with a ConvergenceError."""


def cable_parameters(length, n_nodes, mass_per_length, weight_per_length, diameter, *,
                     axial_stiffness, bending_stiffness, drag_normal, drag_tangential,
                     added_mass_normal=1.0, added_mass_tangential=0.0, water_density=1025.0,
                     tangential_drag: TangentialDragForm = "paper000", shear_power=3.0) -> np.ndarray:
    """Parameter vector of the towed-cable equations (order of :data:`equations.PARAMETERS`).

    Parameters
    ----------
    length : float
        Unstretched cable length. [m]
    n_nodes : int
        Number of nodes, free end to vessel (>= 3). [-]
    mass_per_length : float
        Mass per unit unstretched length. [kg/m]
    weight_per_length : float
        Weight in water per unit length, positive when the cable sinks. [N/m]
    diameter : float
        Hydrodynamic diameter. [m]
    axial_stiffness : float
        EA; ``math.inf`` for an inextensible cable. [N]
    bending_stiffness : float
        EI, > 0: the box scheme of paper 000 needs it (it is what keeps the low-tension problem
        well posed). [N m^2]
    drag_normal, drag_tangential : float
        Drag coefficients C_dn (= C_db) and C_dt. [-]
    added_mass_normal, added_mass_tangential : float
        Added-mass coefficients (paper 000 eq. (7): C_m = 1). [-]
    water_density : float
        [kg/m^3]
    tangential_drag : {"paper000", "common", "diameter"}
        Form of the tangential drag, as in :func:`seacable.statics.towed_cable_steady`.
    shear_power : float
        Power of ``1 + T/EA`` in the moment balance, 3 in paper 000 eq. (3). [-]

    Returns
    -------
    numpy.ndarray
        The parameter vector.
    """
    length = v.positive("length", length, "m", "give the unstretched cable length in metres")
    n_nodes = int(v.at_least("n_nodes", n_nodes, 3, "", "use at least 3 nodes (paper 000 uses 7)"))
    m = v.positive("mass_per_length", mass_per_length, "kg/m", "give the mass per metre in air")
    w = v.finite("weight_per_length", weight_per_length, "N/m", "give the weight in water per metre")
    d = v.positive("diameter", diameter, "m", "give the outer diameter in metres")
    ea = float(axial_stiffness)
    if ea != math.inf:
        ea = v.positive("axial_stiffness", ea, "N", "give EA in newtons (math.inf: inextensible)")
    ei = float(bending_stiffness)
    if not (math.isfinite(ei) and ei > 0):
        raise InputError(
            f"bending_stiffness must be > 0 N m^2 for the towed-cable dynamics, got {ei:g} N m^2: the "
            "box scheme of paper 000 carries the curvatures as unknowns and needs EI to keep a "
            "low-tension cable well posed. Suggested fix: give the cable's EI (a solid section has "
            "E pi d^4 / 64; a small value such as 1 N m^2 stands in for a cable with little stiffness).")
    cdn = v.nonnegative("drag_normal", drag_normal, "", "use a normal drag coefficient such as 1.2-1.8")
    cdt = v.nonnegative("drag_tangential", drag_tangential, "", "use e.g. 0.003-0.02, or 0 for none")
    rho = v.positive("water_density", water_density, "kg/m^3", "sea water is about 1025 kg/m^3")
    v.one_of("tangential_drag", tangential_drag, ("paper000", "common", "diameter"))
    area = math.pi * d * d / 4.0
    perimeter = d if tangential_drag == "diameter" else math.pi * d
    par = np.zeros(len(PARAMETERS))
    par[P_M] = m
    par[P_MAT] = added_mass_tangential * rho * area
    par[P_MAN] = added_mass_normal * rho * area
    par[P_W] = w
    par[P_IEA] = 0.0 if math.isinf(ea) else 1.0 / ea
    par[P_EI] = ei
    par[P_KT] = 0.5 * rho * cdt * perimeter
    par[P_KN] = 0.5 * rho * cdn * d
    par[P_STRETCH] = 1.0 if tangential_drag == "paper000" else 0.0
    par[P_POW] = shear_power
    par[P_DS] = length / (n_nodes - 1)
    return par


@dataclass(frozen=True)
class TowedBodyParameters:
    """A towed body at the lower end: mass and added mass [kg], weight in water [N, positive
    sinks] and drag area C_D A [m^2]; the added mass and the drag area one number (isotropic) or three, along,
    across and vertical in the body's axes (:mod:`seacable.towed.body`)."""

    mass: float
    added_mass: float | tuple = 0.0
    weight_in_water: float = 0.0
    drag_area: float | tuple = 0.0


def _per_axis(name, value, unit, fix):
    """``value`` checked >= 0: a float (isotropic) or a tuple of three (along, across, vertical)."""
    if isinstance(value, (tuple, list, np.ndarray)):
        if len(value) != 3:
            raise InputError(f"{name} must be one number or three (along, across, vertical), got {len(value)} values "
                             f"{list(value)} {unit}. Suggested fix: {fix}")
        return tuple(v.nonnegative(f"{name}[{k}]", x, unit, fix) for k, x in enumerate(value))
    return v.nonnegative(name, value, unit, fix)


def body_parameters(body: TowedBodyParameters | None, water_density=1025.0) -> np.ndarray:
    """Body vector of :mod:`seacable.towed.scheme` (a free end when ``body`` is None)."""
    out = np.zeros(B_SIZE)
    if body is None:
        return out
    mass = v.positive("body.mass", body.mass, "kg",
                      "give the towed body's mass in air (its weight in water alone does not set its inertia)")
    added = _per_axis("body.added_mass", body.added_mass, "kg", "give the added mass in kg")
    drag = _per_axis("body.drag_area", body.drag_area, "m^2", "give C_D times the frontal area")
    out[B_HAS] = 1.0
    out[B_MASS] = mass + (0.0 if isinstance(added, tuple) else added)
    out[B_WEIGHT] = v.finite("body.weight_in_water", body.weight_in_water, "N", "positive when it sinks")
    out[B_DRAG] = 0.0 if isinstance(drag, tuple) else 0.5 * water_density * drag
    if isinstance(added, tuple) or isinstance(drag, tuple):
        out[B_AXES] = 1.0
        if isinstance(drag, tuple):
            out[B_QAXES:B_QAXES + 3] = [0.5 * water_density * x for x in drag]
        if isinstance(added, tuple):
            out[B_MAXES:B_MAXES + 3] = added
    return out


def _steady_drag_area(bpar, water_density):
    """C_D A of the body in the steady tow, whose flow past it is horizontal along the tow: the isotropic one, or
    the along axis's. [m^2]"""
    return (bpar[B_DRAG] + (bpar[B_QAXES] if bpar[B_AXES] > 0.0 else 0.0)) * 2.0 / water_density


def _current_arrays(current, follows_vessel=False):
    """(depths, speeds, (cos heading, sin heading, follows)) of a :class:`seacable.Current`."""
    if current is None:
        return (np.array([0.0]), np.array([0.0]), np.array([1.0, 0.0, 0.0]))
    hd = np.array([math.cos(current.heading), math.sin(current.heading), float(follows_vessel)])
    if current.depths is None:
        return (np.array([0.0]), np.array([float(current.speed)]), hd)
    return (np.asarray(current.depths, float), np.asarray(current.speeds, float), hd)


def _scales(par, n, vessel_speed, current_speed, top_tension):
    """Scale of each unknown for the Newton convergence test."""
    length = par[P_DS] * (n - 1)
    t_ref = max(top_tension, abs(par[P_W]) * length * 1e-2, 1.0)
    v_ref = max(abs(vessel_speed) + abs(current_speed), 0.1)
    return np.array([t_ref] * 3 + [v_ref] * 3 + [1.0, 1.0] + [1.0 / length] * 2)


def _currents_at(cur, pos, vessel_velocity):
    """Current velocity (n, 3) at the positions ``pos (n, 3)``, as the time marching sees it."""
    out = np.zeros_like(pos)
    node_currents(pos, np.zeros_like(pos), 0.0, cur, vessel_velocity, out)
    return out


def steady_tow(par, n_nodes, vessel_velocity, current=None, body=None, *, water_density=1025.0,
               current_follows_vessel=False, tol=1e-10, max_iter=50) -> np.ndarray:
    """Steady state of a cable towed at a constant vessel velocity: the initial state of a run.

    Solves the box equations of paper 000 with all time derivatives zero (the cable translates
    rigidly with the vessel) by Newton-Raphson, from the 2-D steady solution of
    :func:`seacable.statics.towed_cable_steady` (no bending stiffness) in the plane of the relative
    flow. With a depth-varying current the currents at the nodes are updated from the positions
    until they settle.

    Parameters
    ----------
    par : numpy.ndarray
        Parameter vector from :func:`cable_parameters`.
    n_nodes : int
        Number of nodes (the one ``par`` was made for). [-]
    vessel_velocity : array_like
        Tow-point velocity (u, v, w). [m/s]
    current : seacable.Current or None
        The current (uniform or a depth profile).
    body : TowedBodyParameters or None
        Towed body at the lower end; None for a free end.
    water_density : float
        [kg/m^3]
    tol : float
        Scaled Newton tolerance. [-]
    max_iter : int
        Newton iterations allowed. [-]

    Returns
    -------
    numpy.ndarray
        The state ``H (n_nodes, 10)``.

    Raises
    ------
    InputError
        If the relative flow is zero, so the cable would hang vertically: the Euler angles of
        paper 000 are singular there.
    ConvergenceError
        If Newton-Raphson fails.
    """
    n = int(n_nodes)
    length = par[P_DS] * (n - 1)
    vel = np.asarray(vessel_velocity, float).reshape(3)
    cur = _current_arrays(current, current_follows_vessel)
    bpar = body_parameters(body, water_density)
    u_surface = _currents_at(cur, np.zeros((1, 3)), vel)[0]
    rel = vel - u_surface
    speed = math.hypot(rel[0], rel[1])
    if speed < 1e-3:
        raise InputError(
            f"the flow relative to the cable is {speed:.3g} m/s at t = 0 (vessel velocity {tuple(vel)} m/s, "
            f"current {tuple(u_surface)} m/s): the cable would hang vertically, where the Euler angles of "
            "paper 000 are singular. Suggested fix: start the vessel moving (or add a current).")
    heading = math.atan2(rel[1], rel[0])
    guess = towed_cable_steady(
        length, par[P_W], max(2.0 * par[P_KN] / water_density, 1e-9), speed, 1.0,
        0.0, water_density=water_density,
        axial_stiffness=None if par[P_IEA] == 0 else 1.0 / par[P_IEA],
        body_weight=bpar[B_WEIGHT], body_drag_area=_steady_drag_area(bpar, water_density),
        tangential_drag="common", n_points=n)
    h = np.zeros((n, NV))
    h[:, I_T] = guess.tension
    h[:, I_PH] = heading
    h[:, I_TH] = -guess.angle
    h[:, I_ON] = np.gradient(h[:, I_TH], par[P_DS])
    h[:, I_ON][[0, -1]] = 0.0
    _set_rigid_velocity(h, vel)
    scale = _scales(par, n, float(np.linalg.norm(vel)), float(np.linalg.norm(u_surface)),
                    float(np.max(np.abs(guess.tension))))
    w = workspace(n)
    pos = np.zeros((n, 3))
    dummy = np.zeros((n, NV))
    integrate_positions(h, np.zeros(3), par, pos)
    for _ in range(20):
        u = _currents_at(cur, pos, vel)
        # every argument given, as march gives them: one compiled newton_step for both
        status, its, err = newton_step(h, h, dummy, u, u, vel, 1.0, par, bpar, True, scale, tol,
                                       max_iter, w, 0)
        if status != 0:
            raise ConvergenceError(
                f"steady tow: {STATUS[status]} after {its} iterations (scaled correction {err:.3g}). "
                "Suggested fix: check the cable and body inputs; a body much lighter than its lift has "
                "no taut steady state.", time=0.0, iterations=its, residual=err)
        if cur[0].size == 1:  # uniform current: nothing depends on the positions
            break
        previous = pos.copy()
        integrate_positions(h, np.zeros(3), par, pos)
        if np.max(np.abs(pos - previous)) < 1e-9 * length:
            break
    return h


def _set_rigid_velocity(h, vel):
    for j in range(h.shape[0]):
        r = frame(h[j, I_PH], h[j, I_TH])
        h[j, 3:6] = r @ vel


@dataclass
class TowedRun:
    """Output of :func:`simulate`.

    Attributes
    ----------
    time : numpy.ndarray
        Output times. [s]
    s : numpy.ndarray
        Unstretched arc length of the nodes from the lower end. [m]
    state : numpy.ndarray
        ``H`` at the output times, shape (time, node, 10), order of :data:`equations.NV`.
    position : numpy.ndarray
        Node positions (time, node, 3). [m]
    velocity : numpy.ndarray
        Node velocities in the global frame (time, node, 3). [m/s]
    vessel_position : numpy.ndarray
        Tow-point positions (time, 3). [m]
    iterations : int
        Newton iterations over the run. [-]
    steps : int
        Time steps taken (a halved step counts its parts). [-]
    halvings : int
        Steps that had to be halved. [-]
    interrupted : bool
        True when the run was stopped (Ctrl-C) before the end; the arrays hold what was computed.
    wall_time : float
        Wall-clock time of the integration. [s]
    """

    time: np.ndarray
    s: np.ndarray
    state: np.ndarray
    position: np.ndarray
    velocity: np.ndarray
    vessel_position: np.ndarray
    iterations: int = 0
    steps: int = 0
    halvings: int = 0
    interrupted: bool = False
    wall_time: float = 0.0
    settings: dict = field(default_factory=dict)


def simulate(par, n_nodes, path: Callable, duration, time_step, *, output_interval=None, current=None,
             body=None, water_density=1025.0, current_follows_vessel=False, tol=1e-8, max_iter=25,
             initial_state=None, progress: Callable | None = None, linear_solver="block") -> TowedRun:
    """March the towed-cable box equations in time behind a vessel.

    Parameters
    ----------
    par : numpy.ndarray
        Parameter vector from :func:`cable_parameters`.
    n_nodes : int
        Number of nodes. [-]
    path : callable
        ``path(times) -> (positions (n, 3), velocities (n, 3))`` of the tow point, e.g.
        ``functools.partial(seacable.towed.vessel.sample_path, turn)``. [s -> m, m/s]
    duration : float
        Simulated time. [s]
    time_step : float
        Time step (halved locally, down to ``time_step / 2**6``, where Newton fails). [s]
    output_interval : float, optional
        Time between stored states, a multiple of ``time_step`` (default: ``time_step``). [s]
    current : seacable.Current or None
    body : TowedBodyParameters or None
    water_density : float
        [kg/m^3]
    tol : float
        Newton tolerance on the scaled correction. [-]
    max_iter : int
        Newton iterations allowed per step. [-]
    initial_state : numpy.ndarray, optional
        ``H (n, 10)`` at t = 0; by default the steady tow at the vessel's initial velocity.
    progress : callable, optional
        Called as ``progress(t, duration)`` after each output.
    linear_solver : {"block", "dense", "banded"}
        Linear solve of the Newton systems: block tri-diagonal (paper 000), dense LU of the
        assembled matrix (for comparison) or LAPACK's band LU.

    Returns
    -------
    TowedRun

    Raises
    ------
    ConvergenceError
        With the time, iterations and scaled correction, when Newton fails even on the smallest
        halved step.
    """
    n = int(n_nodes)
    duration = v.positive("duration", duration, "s", "give the simulated time in seconds")
    dt = v.positive("time_step", time_step, "s", "use e.g. 0.1 s")
    if dt > duration:
        raise InputError(f"time_step must be <= duration ({duration:g} s), got {dt:g} s. "
                         "Suggested fix: shorten the step.")
    out_dt = dt if output_interval is None else v.positive("output_interval", output_interval, "s",
                                                           "give the time between stored states")
    every = round(out_dt / dt)
    if every < 1 or abs(every * dt - out_dt) > 1e-9 * out_dt:
        raise InputError(f"output_interval must be a multiple of time_step ({dt:g} s), got {out_dt:g} s. "
                         f"Suggested fix: use {max(every, 1) * dt:g} s.")
    n_out = int(math.floor(duration / out_dt + 1e-9))
    solver = _SOLVERS.get(linear_solver)
    if solver is None:
        v.one_of("linear_solver", linear_solver, tuple(_SOLVERS))
    bpar = body_parameters(body, water_density)
    cur = _current_arrays(current, current_follows_vessel)
    pos0, vel0 = path(np.array([0.0]))
    if initial_state is None:
        h = steady_tow(par, n, vel0[0], current, body, water_density=water_density,
                       current_follows_vessel=current_follows_vessel)
    else:
        h = np.array(initial_state, float, copy=True)
    h_prev = h.copy()
    dt_prev = -1.0
    scale = _scales(par, n, float(np.linalg.norm(vel0[0])), float(np.max(np.abs(cur[1]))),
                    float(np.max(np.abs(h[:, I_T]))))
    w = workspace(n)
    times = [0.0]
    states = [h.copy()]
    positions = [np.zeros((n, 3))]
    integrate_positions(h, pos0[0], par, positions[0])
    vessel = [pos0[0].copy()]
    run = TowedRun(time=np.array([]), s=np.linspace(0.0, par[P_DS] * (n - 1), n), state=np.array([]),
                   position=np.array([]), velocity=np.array([]), vessel_position=np.array([]),
                   settings={"time_step": dt, "output_interval": out_dt, "tolerance": tol,
                             "max_iterations": max_iter})
    out_h = np.zeros((1, n, NV))
    out_pos = np.zeros((1, n, 3))
    t0 = _time.perf_counter()
    try:
        for k in range(n_out):
            t_start = k * out_dt
            ts = t_start + dt * np.arange(every + 1)
            vp, vv = path(ts)
            done = 0
            while done < every:
                status, steps, its, last_its, err = march(
                    h, h_prev, dt_prev, dt, vp[done:], vv[done:], cur, par, bpar, scale, tol, max_iter,
                    every - done, out_h, out_pos, w, solver)
                run.iterations += its
                run.steps += steps
                dt_prev = dt if steps > 0 else dt_prev
                done += steps
                if status == 0:
                    break
                dt_prev = _halve(h, h_prev, dt_prev, ts[done], dt, path, cur, par, bpar, scale, tol, max_iter,
                                 w, run, status, last_its, err, solver)
                done += 1
            positions.append(np.zeros((n, 3)))
            integrate_positions(h, vp[-1], par, positions[-1])
            times.append(ts[-1])
            states.append(h.copy())
            vessel.append(vp[-1].copy())
            if progress is not None:
                progress(ts[-1], duration)
    except KeyboardInterrupt:
        run.interrupted = True
        # an interrupt between an output's appends: keep the outputs all four lists hold
        keep_whole_outputs(times, states, positions, vessel)
    run.wall_time = _time.perf_counter() - t0
    run.time = np.asarray(times)
    run.state = np.asarray(states)
    run.position = np.asarray(positions)
    run.vessel_position = np.asarray(vessel)
    run.velocity = np.zeros_like(run.position)
    for i in range(run.state.shape[0]):
        velocity_global(run.state[i], run.velocity[i])
    return run


def _halve(h, h_prev, dt_prev, t, dt, path, cur, par, bpar, scale, tol, max_iter, w, run, status, its, err,
           solver):
    """Redo the step from ``t`` to ``t + dt`` in 2, 4, ... sub-steps; returns the last sub-step."""
    h0, hp0 = h.copy(), h_prev.copy()
    n = h.shape[0]
    out_h = np.zeros((1, n, NV))
    out_pos = np.zeros((1, n, 3))
    for level in range(1, MAX_HALVINGS + 1):
        parts = 2 ** level
        sub = dt / parts
        vp, vv = path(t + sub * np.arange(parts + 1))
        h[:], h_prev[:] = h0, hp0
        status, steps, total, its, err = march(h, h_prev, dt_prev, sub, vp, vv, cur, par, bpar, scale, tol,
                                                max_iter, parts + 1, out_h, out_pos, w, solver)
        run.iterations += total
        if status == 0:
            run.steps += parts
            run.halvings += 1
            return sub
    h[:], h_prev[:] = h0, hp0
    raise ConvergenceError(
        f"towed cable: {STATUS[status]} at t = {t:.6g} s, even with the step halved {MAX_HALVINGS} times "
        f"to {dt / 2 ** MAX_HALVINGS:.3g} s ({its} iterations, scaled correction {err:.3g}). Suggested "
        f"fix: use a smaller time_step (e.g. {dt / 4:.3g} s), more nodes, or a gentler manoeuvre; check "
        "that the bending stiffness is not far too small for the node spacing.",
        time=t, iterations=its, residual=err)

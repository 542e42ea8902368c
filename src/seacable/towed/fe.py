"""The finite-element formulation of a towed system: the mooring model's line behind a moving tow point.

The line runs from its end A, the lower (towed) end, to end B at the tow point, whose node follows the vessel
path (motion channel 0). It is the mooring finite-element model (:mod:`seacable.mooring.kernel`, paper 004):
lumped masses on elastic elements, with bending where the line types give EI (MoorDyn v2's nodal moments),
Morison drag across and along the line and added mass, seabed contact with friction, the segments' own
properties, attachments in line (clumps, floats, a depressor: drag across and along the line, lift) and the
body at the lower end. Its unknowns are the nodes' Cartesian positions: a vertical cable, a start from rest
and a tow from a stop have no singular direction (the box scheme's Euler angles have one at the vertical).

The start is the steady tow: the static equilibrium of the discrete system in the frame moving with the
vessel's velocity at t = 0 (the water streaming past at the current less that velocity,
``kernel.E_FRAMEX``), every node then moving at that velocity. A vessel at rest in still water gives the
hanging cable.

Pay-out and haul-in at the tow point (``winch``) change the top element's length, with nodes born and retired
there (:mod:`seacable.towed.fe_kernel`).

References
----------
.. [1] Paper 004 (seeds/004): the truss finite elements, Newmark's method, Morison loads and seabed contact.
.. [2] Hall, M. and Goupee, A., 2015. Validation of a lumped-mass mooring line model with DeepCwind
   semisubmersible model test data. Ocean Engineering 104, 590-603 (the lumped-mass line, MoorDyn).
.. [3] Buckham, B., Driscoll, F. R. and Nahon, M., 2004. Development of a finite element cable model for use
   in low-tension dynamics simulation. J. Appl. Mech. 71, 476-485 (a towed system's variable-length top
   element with node insertion at the winch).
"""

from __future__ import annotations

import copy
import math
import time as _time
from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError, InputError
from ..mooring import kernel as K
from ..mooring.network import FREE, Network, network_from_line
from ..mooring.solver import (
    MooringModel,
    StepSamples,
    Water,
    advance_interval,
    generalized_alpha,
    static_equilibrium,
)
from . import fe_kernel as FK

__all__ = ["TowedFERun", "TowedSystem", "simulate_towed", "steady_start", "towed_system"]

#: Newton tolerance of the time steps, relative to the largest tension or node weight (as mooring_dynamic's).
TOLERANCE = 1e-7


@dataclass
class TowedSystem:
    """A towed line as the mooring model's network (node 0 the lower end, the last node the tow point).

    ``element_length`` [m] is the paid-out line type's element length (nodes are born and retired at that
    spacing) and ``lock`` [m] the arc length below which no node is retired (the top segment's start)."""

    model: MooringModel
    element_length: float
    lock: float
    line: object = None
    body: object = None
    tangential_drag: str = "common"
    point_contact: np.ndarray | None = None  # (n,) seabed contact area of the body [m^2]


def towed_system(line, tow_point, water: Water, *, n_nodes: int, body=None, tangential_drag: str = "common",
                 damping_ratio: float = 0.0) -> TowedSystem:
    """The network of a towed ``line`` (end A the lower end) hanging from ``tow_point`` (x, y, z) [m].

    ``n_nodes`` sets the element length ``L / (n_nodes - 1)`` (a node also at every segment joint and
    attachment); ``body`` (:class:`seacable.case.TowedBody`) adds its mass, added mass, weight, drag and lift
    at node 0 (a drag or added mass per axis of the body through the kernel's ``E_BODY`` slots of ``env``). ``tangential_drag``: ``"common"`` (the kernel's ``1/2 rho C_dt pi d |u_t| u_t``) or
    ``"diameter"`` (C_dt referred to the diameter: divided by pi).
    """
    L = float(line.length)
    top = np.asarray(tow_point, float)
    ds = L / (n_nodes - 1)
    net = network_from_line(line, top - (0.0, 0.0, L), top, water_density=water.density, gravity=water.gravity,
                            element_length=ds, damping_ratio=damping_ratio, end_b="prescribed")
    kind = net.kind.copy()
    kind[0] = FREE
    changes = {"kind": kind, "line_names": ("towed line",)}
    if tangential_drag == "diameter":
        changes["cdt"] = net.cdt / math.pi
    elif tangential_drag != "common":
        raise InputError(f"tangential_drag '{tangential_drag}' is not a form of the finite-element formulation. "
                         "Suggested fix: 'common' (1/2 rho C_dt pi d U_t^2, the default) or 'diameter' (C_dt "
                         "referred to d); paper 000's stretch factor is the box formulation's.")
    if body is not None:
        # a drag or added mass per axis of the body is the kernel's body at node 0 (env E_BODY, below); a single
        # number joins the node's point arrays (isotropic), as it always did
        iso_drag = 0.0 if body.drag_per_axis else body.drag_area
        iso_added = 0.0 if body.added_mass_per_axis else body.added_mass
        for field, value in (("point_mass", body.mass), ("point_added_mass", iso_added),
                             ("point_weight", body.weight_in_water), ("point_drag_area", iso_drag)):
            arr = getattr(net, field).copy()
            arr[0] += value
            changes[field] = arr
        axial = net.point_drag_area.copy() if net.point_axial_drag_area is None else net.point_axial_drag_area.copy()
        axial[0] += iso_drag
        changes["point_axial_drag_area"] = None if np.array_equal(axial, changes["point_drag_area"]) else axial
        lift = np.zeros(net.n_nodes) if net.point_lift_area is None else net.point_lift_area.copy()
        lift[0] += body.lift_area()
        changes["point_lift_area"] = lift if np.any(lift) else None
    net = net.replace(**changes)
    ends = line.segment_ends
    lock = max([ends[-2]] + [a.s for a in line.attachments])
    # the paid-out type's element length: that of the top piece (from the last joint or attachment, at least one
    # element long: its elements are equal)
    top_ds = float(np.max(np.diff(net.arc_length[net.arc_length >= lock - 1e-9 * L])))
    model = MooringModel(net, water)
    model.env[K.E_DRAGTURN] = 1.0  # the drag sets a towed line's shape: its turning terms in the Newton matrix
    if body is not None and (body.drag_per_axis or body.added_mass_per_axis):
        model.env[K.E_BODY] = 1.0
        model.env[K.E_BDRAG:K.E_BDRAG + 3] = body.drag_areas() if body.drag_per_axis else 0.0
        model.env[K.E_BMASS:K.E_BMASS + 3] = body.added_masses() if body.added_mass_per_axis else 0.0
    contact = np.zeros(net.n_nodes)
    if body is not None:
        contact[0] = body.seabed_area
        model.bedc[0] += contact[0]
    return TowedSystem(model, top_ds, float(lock), line, body, tangential_drag, contact)


def _steady_guess(system: TowedSystem, top, flow):
    """Node positions of the 2-D steady tow (:func:`seacable.statics.towed_line_steady`) in the flow ``flow(z)``
    -> the water's velocity (3,) past the tow point's frame at depth z, laid out astern along the flow at the
    surface; None where that solution does not apply (the flow turning with depth, against the tow at some
    depth, a line that floats, an attachment's drag along the line)."""
    from ..errors import SeacableError
    from ..statics.towed import towed_line_steady

    net = system.model.network
    water = system.model.water
    f0 = flow(0.0)
    speed0 = float(np.hypot(f0[0], f0[1]))
    if speed0 < 1e-6 or system.line is None:
        return None
    e = np.array([f0[0], f0[1], 0.0]) / speed0
    depths = np.asarray(water.current_depths, float)
    along = np.array([float(np.dot(flow(-d), e)) for d in depths])
    across = np.array([abs(float(np.cross(flow(-d), e)[2])) for d in depths])
    if np.any(across > 1e-9 * speed0):
        return None
    speed = speed0 if len(depths) == 1 else (tuple(depths), tuple(along))
    b = system.body
    try:
        with np.errstate(all="ignore"):  # a weightless line: no 2-D solution (the static solve starts otherwise)
            res, _ = towed_line_steady(
                system.line, speed, water_density=water.density, gravity=water.gravity,
                body_weight=b.weight_in_water if b else 0.0, body_drag_area=b.steady_drag_area() if b else 0.0,
                body_lift_area=b.lift_area() if b else 0.0, tangential_drag=system.tangential_drag,
                n_points=max(net.n_nodes, 11), rtol=1e-6)  # a start for the static solve, which makes it exact
    except (SeacableError, ValueError):
        return None
    if not (np.all(np.isfinite(res.x)) and np.all(np.isfinite(res.z))):
        return None
    s = net.arc_length
    x = np.interp(s, res.s, res.x)
    z = np.interp(s, res.s, res.z)
    X = np.asarray(top, float) + x[:, None] * e[None, :] + z[:, None] * np.array([0.0, 0.0, 1.0])
    if water.depth is not None or water.tabulated:  # the shape without the seabed: held above it
        X[:, 2] = np.maximum(X[:, 2], water.seabed_z(X[:, 0], X[:, 1]) + 1e-3)
    return X


def _hanging(net: Network, top, floor, astern):
    """Node positions hanging straight down from ``top`` and, on a seabed at elevation ``floor`` [m] (NaN: none),
    laid along it in the horizontal direction ``astern`` (3,)."""
    below = net.arc_length[-1] - net.arc_length  # arc length below the tow point
    top = np.asarray(top, float)
    drop = below if not np.isfinite(floor) else np.minimum(below, max(top[2] - floor - 1e-3, 0.0))
    X = top + np.outer(drop, (0.0, 0.0, -1.0))
    return X + np.outer(below - drop, astern)


def steady_start(system: TowedSystem, top, velocity) -> np.ndarray:
    """The steady tow behind the tow point at ``top`` moving at ``velocity`` (3,) [m/s]: the static equilibrium
    in the frame moving with it (module docstring). Returns the node positions (n, 3) [m].

    The static solve starts from the 2-D steady tow's shape where that applies (:func:`_steady_guess`), else
    from the cable hanging at rest, its frame's speed raised in steps (each solve starting from the last).

    Raises
    ------
    ConvergenceError
        The static solve did not converge (with its residual).
    """
    model = system.model
    net = model.network
    water = model.water
    v = np.asarray(velocity, float)
    heading = np.array([math.cos(water.current_heading), math.sin(water.current_heading), 0.0])

    def flow(z):
        c = float(np.interp(-z, water.current_depths, water.current_speeds))
        return c * heading - v

    def solve(X0, frame):
        moving = copy.copy(model)  # the same arrays (the body's seabed area among them), its own environment
        moving.env = model.env.copy()
        moving.env[[K.E_FRAMEX, K.E_FRAMEY, K.E_FRAMEZ]] = frame
        # the steps may move a node by 2 % of the line (the shape changes over tens of metres from the start)
        return static_equilibrium(moving, X0, max_step=0.02 * float(net.arc_length[-1])).position

    try:
        guess = _steady_guess(system, top, flow)
        if guess is not None:
            try:
                return solve(guess, v)
            except ConvergenceError:
                pass
        f0 = flow(0.0)
        speed = float(np.hypot(f0[0], f0[1]))
        astern = np.array([f0[0] / speed, f0[1] / speed, 0.0]) if speed > 0.0 else np.array([1.0, 0.0, 0.0])
        X = _hanging(net, top, float(water.seabed_z(*np.asarray(top, float)[:2])), astern)
        for f in (0.25, 0.5, 0.75, 1.0) if np.any(v) else (1.0,):
            X = solve(X, f * v)
        return X
    except ConvergenceError as err:
        raise ConvergenceError(
            f"the steady tow that starts the towed_dynamic run did not converge (tow point moving at "
            f"({v[0]:.4g}, {v[1]:.4g}, {v[2]:.4g}) m/s): {err}", iterations=err.iterations,
            residual=err.residual) from None


@dataclass(frozen=True)
class TowedFERun:
    """Stored states of a finite-element towed run (node slots beyond those in the water are NaN)."""

    time: np.ndarray            # (nt,) [s]
    position: np.ndarray        # (nt, nmax, 3) [m]
    velocity: np.ndarray        # (nt, nmax, 3) [m/s]
    tension: np.ndarray         # (nt, nmax - 1) [N]
    top_force: np.ndarray       # (nt, 3) force of the line on the tow point [N]
    n_nodes: np.ndarray         # (nt,) nodes in the water, the tow point included
    arc_length: np.ndarray      # (nt, nmax) unstretched arc length of each node from the lower end [m]
    deployed: np.ndarray        # (nt,) deployed length [m]
    vessel_position: np.ndarray  # (nt, 3) [m]
    time_step: float
    iterations: int
    steps: int
    births: int
    retirements: int
    interrupted: bool
    wall_time: float


def _capacity(system: TowedSystem, longest: float) -> int:
    """Node slots for a deployed length up to ``longest`` [m]."""
    net = system.model.network
    extra = max(0.0, longest - float(net.arc_length[-1]))
    return net.n_nodes + math.ceil(extra / system.element_length) + 2


def _grown(a, rows, fill=0.0):
    out = np.full((rows,) + a.shape[1:], fill, dtype=a.dtype)
    out[:a.shape[0]] = a
    return out


def simulate_towed(system: TowedSystem, path, duration: float, dt: float, output_interval: float, *,
                   deployed=None, initial=None, tol: float = TOLERANCE, max_iter: int = 30, max_halvings: int = 6,
                   spectral_radius: float = 1.0, progress=None, chunk_seconds: float = 0.25) -> TowedFERun:
    """Generalised-alpha time stepping (``spectral_radius``; 1: Newmark's average acceleration) of ``system``
    behind the tow point ``path(times)`` -> (positions, velocities) (n, 3), from the steady tow (``initial``
    positions, default :func:`steady_start`).

    ``deployed(times)`` -> the deployed length [m] (None: fixed). A step whose Newton iteration fails is redone
    at half the step, six times at most, then :class:`~seacable.errors.ConvergenceError` gives the time and
    residual. Ctrl-C stops the run and returns what it computed (``interrupted``). ``progress(t, duration)``
    is called for each output."""
    model = system.model
    net = model.network
    n0 = net.n_nodes
    n_out = int(round(duration / output_interval))  # noqa: RUF046
    sub = max(1, math.ceil(output_interval / dt - 1e-9))
    h = output_interval / sub
    eps = 1e-3 * h

    def channels(times):
        p, v = path(times)
        _, vp = path(times + eps)
        _, vm = path(np.maximum(times - eps, 0.0))
        span = (times + eps) - np.maximum(times - eps, 0.0)
        a = (vp - vm) / span[:, None]
        return p[:, None, :], v[:, None, :], a[:, None, :]

    def lengths(times):
        return np.full(len(times), np.nan) if deployed is None else np.asarray(deployed(times), float)

    grid = np.linspace(0.0, duration, max(n_out * sub, 1) + 1)
    longest = float(np.max(lengths(grid))) if deployed is not None else float(net.arc_length[-1])
    cap = _capacity(system, longest) if deployed is not None else n0
    p0, v0, a0 = channels(np.zeros(1))
    X = steady_start(system, p0[0, 0], v0[0, 0]) if initial is None else np.array(initial, float)
    V = np.broadcast_to(v0[0, 0], X.shape).copy()
    A = np.zeros_like(X)
    A[-1] = a0[0, 0]
    # arrays at capacity: the slots beyond the nodes in the water hold the top element's line type
    args = list(model.element_args())
    ne = net.n_elements
    elements = np.column_stack([np.arange(cap - 1), np.arange(1, cap)]).astype(np.int64)
    node_fields = {10, 11, 12, 13, 14, 15, 17}  # weight, pmass, padd, pvol, pcda, bedc, pbuoy
    elem_fields = {1, 2, 3, 4, 5, 6, 7, 8, 9, 16, 18, 19}  # L0 .. cat, buoy, ts_lo, ts_hi
    for i in range(len(args)):
        if i == 0:
            args[i] = elements
        elif i in node_fields:
            args[i] = _grown(np.ascontiguousarray(args[i]), cap)
        elif i in elem_fields:
            a = np.ascontiguousarray(args[i])
            g = _grown(a, cap - 1)
            g[ne:] = a[ne - 1]
            args[i] = g
    if model.hinges.shape[0]:  # bending: a hinge at every inner node, k - 1 the k-th's (births add them in order)
        ei = _grown(np.asarray(net.bending_stiffness, float), cap - 1)
        ei[ne:] = ei[ne - 1]
        hh = np.arange(cap - 2)[:, None] + np.arange(3)[None, :]
        table = np.zeros((cap - 2, K.H_SIZE))  # inner hinges (H_INNER), their EI in column H_EI
        table[:, K.H_EI] = 0.5 * (ei[:-1] + ei[1:])
        args[22], args[23] = hh.astype(np.int64), table
    visco = args[24]
    if visco.shape[0]:
        g = _grown(visco, cap - 1)
        g[ne:] = visco[ne - 1]
        args[24] = g
    args = tuple(args)
    wpl = _grown(net.weight_per_length, cap - 1)
    wpl[ne:] = net.weight_per_length[-1]
    pw = _grown(net.point_weight, cap)
    pc = _grown(system.point_contact, cap)
    s_node = _grown(net.arc_length, cap, np.nan)
    fidx = np.full(cap, -1, np.int64)
    fidx[:n0 - 1] = np.arange(n0 - 1)
    channel = np.full(cap, -1, np.int64)
    channel[n0 - 1] = 0
    ia = np.array([n0, n0 - 1, 0, 0], np.int64)
    Xc, Vc, Ac, G = (_grown(Z, cap) for Z in (X, V, A, np.zeros_like(X)))
    F, M = np.zeros((cap, 3)), np.zeros((cap, 3, 3))
    tension = np.zeros(cap - 1)
    bw = model.bw
    band, R, D = np.zeros((3 * cap, 2 * bw + 1)), np.zeros(3 * cap), np.zeros(3 * cap)
    Xn, Vn, An = np.zeros((cap, 3)), np.zeros((cap, 3)), np.zeros((cap, 3))
    env = model.env
    envw = env.copy()
    sea = model.sea
    cd, cs = model.cur_depth, model.cur_speed
    rows = n_out + 1
    times = np.zeros(rows)
    pos, vel = np.full((rows, cap, 3), np.nan), np.full((rows, cap, 3), np.nan)
    ten, top = np.full((rows, cap - 1), np.nan), np.zeros((rows, 3))
    nact, arc = np.zeros(rows, np.int64), np.full((rows, cap), np.nan)
    FK.record(0, 0.0, ia, Xc, Vc, Ac, args, fidx, bw, env, cd, cs, sea, F, M, tension, s_node, times, pos, vel, ten,
              top, nact, arc)
    stats = np.zeros(3)
    count = np.zeros(3, np.int64)
    alpha_m, alpha_f, beta, gamma = generalized_alpha(spectral_radius)
    # the step start's share of the generalised-alpha equilibrium, from the loads record() left in F and M
    K.alpha_history(F[:n0], M[:n0], Ac[:n0], G[:n0], alpha_m, alpha_f, fidx[:n0])

    def steps(t, dtk, px, pv, pa):
        ls = lengths(t + dtk * np.arange(1, px.shape[0] + 1))
        return FK.towed_steps(ia, Xc, Vc, Ac, G, t, dtk, px, pv, pa, ls, system.element_length, system.lock, s_node,
                              wpl, pw, pc, args, fidx, channel, bw, env, cd, cs, sea, beta, gamma, alpha_m, alpha_f, tol,
                              max_iter, F, M, tension, stats, band, R, D, Xn, Vn, An, envw)

    fix = "a smaller time_step, more nodes, or a smoother vessel path or winch schedule"
    interrupted = False
    start = _time.perf_counter()
    reported = 0
    samples = StepSamples(lambda t: (*channels(t), lengths(t)), output_interval, h, sub, n_out * sub)
    k, size = 0, 1
    try:
        while k < n_out:
            k1 = min(n_out, k + size)
            px, pv, pa, ls = samples(k * sub, k1 * sub)  # the motion and lengths at the chunk's steps
            tick = _time.perf_counter()
            got = FK.towed_outputs(k, k1, output_interval, h, sub, px, pv, pa, ls, ia, Xc, Vc, Ac, G,
                                   system.element_length, system.lock, s_node, wpl, pw, pc, args, fidx, channel, bw, env,
                                   env, cd, cs, sea, beta, gamma, alpha_m, alpha_f, tol, max_iter, F, M, tension, stats,
                                   count,
                                   band, R, D, Xn, Vn, An, envw, times[k:], pos[k:], vel[k:], ten[k:], top[k:],
                                   nact[k:], arc[k:])
            if got < k1:  # a step failed: the rest of that interval at halved steps
                done, spent = advance_interval(got * output_interval, h, sub, channels, steps, stats, max_halvings,
                                               max_iter, "towed_dynamic", fix, failed_at=int(count[2]))
                count[0] += done
                count[1] += spent
                FK.record(got + 1, (got + 1) * output_interval, ia, Xc, Vc, Ac, args, fidx, bw, env, cd, cs, sea, F,
                          M, tension, s_node, times, pos, vel, ten, top, nact, arc)
                got += 1
            took = _time.perf_counter() - tick
            k = got
            size = max(1, min(int(size * chunk_seconds / max(took, 1e-6)), 2 * size + 8, 100_000 // sub))
            if progress is not None:
                while reported < k:
                    reported += 1
                    progress(times[reported], duration)
    except KeyboardInterrupt:
        interrupted = True
    wall = _time.perf_counter() - start
    nt = k + 1
    vessel = pos[np.arange(nt), nact[:nt] - 1]
    dep = arc[np.arange(nt), nact[:nt] - 1]
    return TowedFERun(time=times[:nt].copy(), position=pos[:nt], velocity=vel[:nt], tension=ten[:nt],
                      top_force=top[:nt], n_nodes=nact[:nt], arc_length=arc[:nt], deployed=dep,
                      vessel_position=vessel, time_step=h, iterations=int(count[1]), steps=int(count[0]),
                      births=int(ia[FK.I_BORN]), retirements=int(ia[FK.I_GONE]), interrupted=interrupted,
                      wall_time=wall)


"""The coupled dynamics' static start and time loop: the static equilibrium of the finite-element system
(:func:`static_system`), the lines' forces on the bodies, and the Newmark steps of lines and bodies together
(:func:`simulate_system`; a system of lines alone in an irregular sea runs in the mooring model's compiled loop,
:func:`_simulate_lines`). Both give the lines the waves: a regular wave, or an irregular sea precomputed on a grid
(:meth:`seacable.mooring.solver.MooringModel.prepare_sea`) and taken in windows of time, one per output interval.
"""

from __future__ import annotations

import math
import time as _time
import warnings
from dataclasses import dataclass

import numpy as np

from ..._atomic import keep_whole_outputs
from ...errors import ConvergenceError, InputError, SeacableWarning
from ...mooring.motion import RAOMotion, sea_of
from ...mooring.solver import advance_interval, line_end_nodes
from ...mooring.solver import simulate as simulate_lines
from ..case import SystemDynamicAnalysis
from . import body as DB
from . import clamps as DC
from . import frames as DF
from . import kernel as DK
from .fe import SystemFE, _rot

#: The horizontal excursion, as a fraction of the water depth (of the deepest node without a seabed), that an
#: irregular sea's grid allows a free body's fairleads on either side of their start (:func:`sea_positions`): a
#: moored floater's mean and slow-drift offset in a storm is typically 5-10 % of the depth, and the grid's own
#: margin (about Hs) covers its wave-frequency motion. A node outside the grid gets the kinematics at its edge.
SEA_EXCURSION = 0.1

#: A run with a free body takes the irregular sea's grid in depth bands (:class:`seacable.seastate.SeaBands`):
#: below the top band, the components that carry under 0.1 % of the sea's acceleration there are left out and the
#: grid's steps follow the shortest kept, so that the lines' deep part (a floater's mooring reaching 800 m out) is
#: gridded for the waves that reach it (held still, a buoy's lines keep the one grid's tensions: the test
#: tests/validation/test_system_dynamics_irregular_sea.py). False: one grid of all components (as a lines-only run).
SEA_BANDS = True


def sea_bands(fe: SystemFE) -> bool:
    """Whether the run of ``fe`` takes the irregular sea's grid in depth bands (``SEA_BANDS``, a free body)."""
    return SEA_BANDS and len(fe.free_bodies) > 0


@dataclass(frozen=True)
class SystemState:
    """A static state of the finite-element system."""

    position: np.ndarray       # (n, 3) node positions [m]
    body_position: np.ndarray  # (nb, 6) free bodies [m, rad]
    tension: np.ndarray        # (e,) element tensions [N]
    iterations: int
    residual: float
    start: str = "equilibrium"  # how it was found: 'equilibrium', or 'held' (free bodies at their given positions)


def static_system(fe: SystemFE, *, held: bool = False, q=None, X=None, tol: float = 1e-9,
                  max_iter: int = 1000, targets=None, friction_distance: float = 1e-3) -> SystemState:
    """Static equilibrium of the finite-element system, bodies included (``held``: free bodies held at ``q``,
    default their given positions). ``targets`` (n, 3): the nodes' friction targets of the seabed's static
    friction, ``friction_distance`` its slip distance [m] (:mod:`seacable.mooring.friction`; None: frictionless).
    Raises :class:`ConvergenceError` with the residual."""
    m = fe.model
    net = m.network
    X = np.array(net.position if X is None else X, float)
    q = np.array(fe.q0 if q is None else q, float).reshape(-1, 6)
    con_body, con_target = fe.con_body.copy(), fe.con_target.copy()
    qs = q
    if held and len(fe.free_bodies):
        # tie the nodes to where the held bodies put them
        for j in range(len(con_body)):
            b = con_body[j]
            if b >= 0:
                con_target[j] = q[b, :3] + _rot(q[b]) @ fe.con_arm[j]
                con_body[j] = -1
        qs = np.zeros((0, 6))
    n = net.n_nodes
    F, M = np.zeros((n, 3)), np.zeros((n, 3, 3))
    tension = np.zeros(net.n_elements)
    stats = np.zeros(3)
    step = 0.5 * float(np.mean(net.length)) if net.n_elements else 1.0  # no lines: bodies alone
    active = np.ones(len(fe.con_node), np.int64)
    node_mass = float(np.max(net.mass_per_length * net.length, initial=0.0))
    body_mass = float(np.max(fe.bpar[:, DB.B_MASS], initial=0.0)) + float(np.max(fe.badd[:, 0, 0], initial=0.0))
    body_scale = min(1.0, node_mass / body_mass) if body_mass > 0 and node_mass > 0 else 1.0
    bargs = fe.body_args() if not held else tuple(np.zeros((0,) + a.shape[1:], a.dtype) for a in fe.body_args())
    args = fe.kernel_args()
    if held and fe.clamps.shape[0]:
        # the held line ends on the held bodies: turned to the bodies' poses, and held there
        DC.turn_clamps(q, np.zeros((len(q), DF.F_SIZE)), fe.clamps, m.hinge_ei)
        args = (*args[:-1], np.zeros((0, 5)))
    qs = np.array(qs, float)
    frame = np.zeros((len(qs), DF.F_SIZE))
    spin = (fe.spin if fe.spin is not None else np.zeros((len(qs), 3))) if len(qs) else np.zeros((0, 3))
    ok = DK.coupled_static(X, qs, args, m.weight, m.fidx, m.nfree, m.bw, m.env, m.cur_depth, m.cur_speed,
                           fe.node_fext, fe.con_node, con_body, fe.con_arm, con_target, active, *bargs, tol, max_iter,
                           step, body_scale, F, M, tension, stats, frame, spin,
                           np.zeros((0, 3)) if targets is None else np.asarray(targets, float), float(friction_distance))
    qs = _global_pose(qs, frame)
    if not ok:
        qtxt = "" if not len(qs) else f"; the bodies ended at {np.array2string(qs, precision=4)}"
        raise ConvergenceError(
            f"the static equilibrium of the mooring system did not converge in {max_iter} iterations: residual "
            f"{stats[1]:.3g} N against a tolerance of {stats[2]:.3g} N{qtxt}. Suggested fix: start the bodies "
            "nearer their equilibrium, check that the lines reach their points and that the bodies float.",
            iterations=int(stats[0]), residual=float(stats[1]))
    return SystemState(X, q if held else qs, tension.copy(), int(stats[0]), float(stats[1]))


def body_line_force(fe: SystemFE, X, q, V=None, A=None, t=0.0) -> np.ndarray:
    """Force and moment of the lines on each free body (nb, 6) at a state (statics when V, A are None). [N, N m]"""
    m = fe.model
    clamp = DC.clamp_moments(fe, X, q)  # the held line ends' moments, their directions turned to ``q`` first
    V = np.zeros_like(X) if V is None else V
    A = np.zeros_like(X) if A is None else A
    F, M, _, _ = m.evaluate(X, V, A, t, waves=V is not None)
    F = F + fe.node_fext
    out = np.zeros((len(fe.free_bodies), 6))
    for j in range(len(fe.con_node)):
        b = fe.con_body[j]
        if b < 0:
            continue
        i = fe.con_node[j]
        mu = F[i] - M[i] @ A[i]
        arm = _rot(q[b]) @ fe.con_arm[j]
        out[b, :3] += mu
        out[b, 3:] += np.cross(arm, mu)
    out[:, 3:] += clamp
    return out


# --------------------------------------------------------------------------------------------- time loop


@dataclass(frozen=True)
class SystemRun:
    """Stored states of a coupled run at the output times."""

    time: np.ndarray            # (nt,)
    position: np.ndarray        # (nt, n, 3)
    velocity: np.ndarray        # (nt, n, 3)
    tension: np.ndarray         # (nt, e)
    body_position: np.ndarray   # (nt, nb, 6)
    body_velocity: np.ndarray   # (nt, nb, 6)
    failure_time: np.ndarray    # (n_tied,) NaN when the end did not fail
    time_step: float
    steps: int
    iterations: int
    wall_time: float
    interrupted: bool
    body_angular_velocity: np.ndarray | None = None  # (nt, nb, 3) global axes [rad/s]
    # the accelerations (nt, k, 3) [m/s^2] of the nodes ``kinematic_nodes`` (k,): each line's end nodes and their
    # neighbours (seacable.mooring.solver.line_end_nodes), for the lines' end forces; None: not stored (at rest)
    acceleration: np.ndarray | None = None
    kinematic_nodes: np.ndarray | None = None
    # the lines' force on their end points (nt, line, 2, 3) [N] when the run gives them itself (quasi-static lines:
    # their catenaries' end forces); None: the finite-element lines' (seacable.mooring.outputs.line_end_forces)
    end_force: np.ndarray | None = None


def _channels_fn(fe: SystemFE, analysis: SystemDynamicAnalysis | None, duration: float):
    """Positions, velocities and accelerations (len(times), n_channels, 3) of the prescribed nodes."""
    net = fe.model.network
    base = net.channel_positions()
    for k, src in enumerate(fe.channel_source):
        if len(src) > 3:  # a held end's direction point (no node): its rest position
            base[k] = src[3]
    nch = max(net.n_channels, 1)
    groups = {}
    for k, src in enumerate(fe.channel_source):
        key = src[:2]
        groups.setdefault(key, []).append(k)
    motions = []
    for key, chans in groups.items():
        kind, name = key
        mot = None
        if analysis is not None:
            if kind == "point":
                mot = analysis.point_motions.get(name)
            else:
                mot = analysis.body_motions.get(name)
                if mot is not None:
                    mot = mot.model_copy(update={"reference": tuple(fe.system.bodies[name].position[:3])})
                    if isinstance(mot, RAOMotion):
                        mot = mot.in_sea(sea_of(fe.model.water))
                    fe.body_motions[name] = mot
        if mot is not None:
            mot.channels(np.array([0.0, duration]), base[chans])  # a time series too short fails here
            motions.append((mot, np.array(chans)))

    def channels(times):
        shape = (len(times), nch, 3)
        x = np.broadcast_to(base[:nch] if len(base) else np.zeros((nch, 3)), shape).copy()
        v, a = np.zeros(shape), np.zeros(shape)
        for mot, chans in motions:
            x[:, chans], v[:, chans], a[:, chans] = mot.channels(times, base[chans])
        return x, v, a

    return channels


def outside_sea(sea, points) -> int | None:
    """The first of ``points`` (n, 3) [m] outside an irregular sea's kinematics grid horizontally (the packed
    grid of :class:`seacable.seastate.SeaGrid`: along and, for a short-crested sea, across its mean heading), or
    None when all are inside it or there is no grid."""
    from ...seastate import S_COS, S_DX, S_DY, S_MODE, S_NX, S_NY, S_SIN, S_X0, S_Y0

    if sea is None or len(sea) <= S_Y0 or sea[S_MODE] <= 0 or not len(points):
        return None
    # a few points once an output interval: plain floats (numpy's calls on them cost more than the arithmetic)
    h = sea[:max(S_COS, S_SIN, S_DX, S_DY, S_NX, S_NY, S_X0, S_Y0) + 1].tolist()
    cb, sb, dx = h[S_COS], h[S_SIN], h[S_DX]
    tol = 1e-6 * max(1.0, dx)
    lo, hi = h[S_X0] - tol, h[S_X0] + dx * (h[S_NX] - 1) + tol
    wide = h[S_NY] > 1
    ylo, yhi = h[S_Y0] - tol, h[S_Y0] + h[S_DY] * (h[S_NY] - 1) + tol
    for i, (x, y) in enumerate(np.asarray(points, float)[:, :2].tolist()):
        along, across = x * cb + y * sb, -x * sb + y * cb
        if along < lo or along > hi or (wide and (across < ylo or across > yhi)):
            return i
    return None


def sea_positions(fe: SystemFE, X, channels, duration: float, output_interval: float) -> np.ndarray:
    """The points (n, 3) [m] an irregular sea's kinematics grid covers for a run
    (:meth:`seacable.mooring.solver.MooringModel.prepare_sea`): the nodes at ``X``, the prescribed nodes at the
    output times (``channels``, :func:`_channels_fn`), and the nodes tied to a free body moved horizontally by
    ``SEA_EXCURSION`` of the depth each way along x and y (a lines-only system: none, as the mooring model's own
    run takes them)."""
    t_out = np.linspace(0.0, duration, round(duration / output_interval) + 1)
    parts = [np.asarray(X, float).reshape(-1, 3)]
    if fe.model.network.n_channels:  # (without prescribed nodes the channels are one stand-in at the origin)
        parts.append(channels(t_out)[0].reshape(-1, 3))
    tied = np.asarray(fe.con_node)[np.asarray(fe.con_body) >= 0]
    if len(tied):
        depth = fe.model.water.depth
        reach = SEA_EXCURSION * (float(depth) if depth is not None else float(np.max(-parts[0][:, 2], initial=1.0)))
        P = parts[0][tied]
        for dx, dy in ((reach, 0.0), (-reach, 0.0), (0.0, reach), (0.0, -reach)):
            parts.append(P + np.array([dx, dy, 0.0]))
    return np.concatenate(parts)


def initial_accelerations(fe: SystemFE, X, V, A, q, qd, qdd, frame, v0, a0) -> None:
    """The accelerations at t = 0 that satisfy the equations of motion there, in place: ``A`` of the lines'
    nodes and ``qdd`` of the free bodies (and ``V`` of the nodes tied to a body, its velocity there), with the waves at t = 0 and the start's velocities (the bodies'
    ``qd``; the lines at rest), as the mooring model starts (:func:`seacable.mooring.solver.simulate`).

    A free node: ``M a = F``. A node tied to a free body moves with it, ``a_j = a + alpha x r_j + w x (w x
    r_j)``, and its inertia and forces join the body's: ``(M6 + sum T_j^T M_j T_j) (a, alpha) = f6 + sum T_j^T
    (F_j - M_j w x (w x r_j))``, ``T_j = [I, -skew(r_j)]``. A line end tied to a free point's node moves with it:
    the pair's masses and forces together. A tied end held at a point follows it (``v0``, ``a0``: the channels'
    velocities and accelerations at t = 0, (n_channels, 3)).

    Newmark's average acceleration carries an error in the start's acceleration through the whole run (half a
    step of it in every later velocity, undamped): a static start is not at equilibrium once the waves act
    at t = 0, and a start at rest (zero acceleration) put 2.8 kN (3.5 % of the tension range) into 100 s of a
    line in waves that the mooring model, which starts here, does not have.
    """
    m = fe.model
    clamp = DC.clamp_moments(fe, X, q, frame)  # the held line ends' moments on the bodies, turned with them first
    F, M, _, _ = m.evaluate(X, V, A, 0.0, settled=True)
    F = F + fe.node_fext
    free = m.fidx >= 0
    tied = np.zeros(len(X), bool)
    tied[fe.con_node] = True
    own = free & ~tied
    # free nodes and the line ends tied to them (a failing end at a free point): one mass, one force
    Mg, Fg = M.copy(), F.copy()
    for j in range(len(fe.con_node)):
        b = fe.con_body[j]
        if b <= -2:
            Mg[-2 - b] += M[fe.con_node[j]]
            Fg[-2 - b] += F[fe.con_node[j]]
    A[own] = np.linalg.solve(Mg[own], Fg[own][..., None])[..., 0]
    nb = q.shape[0]
    R = np.zeros((3, 3))
    rows = [[] for _ in range(nb)]
    for j in range(len(fe.con_node)):
        i, b = fe.con_node[j], fe.con_body[j]
        if b <= -2:
            A[i] = A[-2 - b]
        elif b == -1:
            ch = fe.con_chan[j]
            if ch >= 0:
                V[i], A[i] = v0[ch], a0[ch]
            else:
                A[i] = 0.0
        else:
            rows[b].append(j)
    for b in range(nb):
        E, ed = np.zeros((3, 3)), np.zeros(3)
        DF.angular_map(q[b], qd[b], E, ed, frame[b])
        w = E @ qd[b, 3:]
        f6, M6 = np.zeros(6), np.zeros((6, 6))
        uc = np.zeros(5)
        DB._body_current(q[b], m.env, m.cur_depth, m.cur_speed, uc)
        DB.body_load(q[b], np.r_[qd[b, :3], w], uc, 0.0, fe.bpar[b], fe.bkhs[b], fe.badd[b], fe.blin[b], fe.bquad[b],
                     fe.ext_t[b], fe.ext_f[b], int(fe.ext_n[b]), m.water.density, m.water.gravity, f6, M6, frame[b])
        DF.body_rotation(q[b], frame[b], R)
        arms = {}
        for j in rows[b]:
            i = fe.con_node[j]
            r = R @ fe.con_arm[j]
            arms[j] = r
            T = np.hstack((np.eye(3), -_cross_matrix(r)))
            M6 += T.T @ M[i] @ T
            f6 += T.T @ (F[i] - M[i] @ np.cross(w, np.cross(w, r)))
        f6[3:] += clamp[b]
        acc = np.linalg.solve(M6, f6)
        qdd[b] = np.r_[acc[:3], np.linalg.solve(E, acc[3:] - ed)]
        for j, r in arms.items():
            V[fe.con_node[j]] = qd[b, :3] + np.cross(w, r)
            A[fe.con_node[j]] = acc[:3] + np.cross(acc[3:], r) + np.cross(w, np.cross(w, r))


def tied_accelerations(fe: SystemFE, A, q, qd, qdd, frame, active, channels, t: float) -> np.ndarray:
    """The nodes' accelerations (n, 3) [m/s^2] at a converged state, each node still tied taking what it is tied to:
    a free body's rigid acceleration at its arm (``a + alpha x r + w x (w x r)``, :func:`initial_accelerations`),
    its free point's node's, its channel's (``channels`` at ``t`` [s]; None: the prescribed node's that follows the
    channel) or none (held fixed).

    The time loop steps a tied node's acceleration by Newmark's rule from the positions it is placed at, which
    holds, besides the body's acceleration, the average-acceleration scheme's undamped mode of period two steps
    (``a`` changing sign at each step, ``x`` and ``v`` untouched) that a jump starts (a line failing): 1.8 m/s^2
    at the fairleads of tests/validation/test_system_dynamics.py's line break, 595 s after it, where the body is at
    rest. The body's own acceleration carries that mode scaled by the nodes' mass over the body's (1e-3 there)."""
    out = np.array(A, float)
    R, E, ed = np.zeros((3, 3)), np.zeros((3, 3)), np.zeros(3)
    chan = None
    for j in range(len(fe.con_node)):
        if not active[j]:
            continue  # a failed end: free, its own equation of motion
        i, b = fe.con_node[j], fe.con_body[j]
        if b >= 0:
            DF.angular_map(q[b], qd[b], E, ed, frame[b])
            DF.body_rotation(q[b], frame[b], R)
            w, alpha, r = E @ qd[b, 3:], E @ qdd[b, 3:] + ed, R @ fe.con_arm[j]
            out[i] = qdd[b, :3] + np.cross(alpha, r) + np.cross(w, np.cross(w, r))
        elif b <= -2:
            out[i] = A[-2 - b]
        elif fe.con_chan[j] >= 0:
            if channels is None:  # the prescribed node that follows the channel
                out[i] = A[np.flatnonzero(fe.model.network.channel == fe.con_chan[j])[0]]
                continue
            if chan is None:
                chan = channels(np.array([t]))[2][0]
            out[i] = chan[fe.con_chan[j]]
        else:
            out[i] = 0.0
    return out


def _cross_matrix(r) -> np.ndarray:
    """skew(r): skew(r) v = r x v."""
    return np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])


def simulate_system(fe: SystemFE, start: SystemState, duration: float, dt: float, output_interval: float, *,
                    analysis: SystemDynamicAnalysis | None = None, tol: float = 1e-7, max_iter: int = 30,
                    beta: float = 0.25, gamma: float = 0.5, progress=None, max_halvings: int = 6,
                    body_velocity=None) -> SystemRun:
    """Newmark time stepping of the coupled system from rest at ``start`` (the free bodies at ``body_velocity``,
    (nb, 6) reference point velocity [m/s] and angle rates [rad/s], when given; the lines at rest)."""
    m = fe.model
    net = m.network
    n = net.n_nodes
    X = start.position.copy()
    V, A = np.zeros_like(X), np.zeros_like(X)
    q = start.body_position.copy().reshape(-1, 6)
    nb = len(fe.free_bodies)
    qd = np.zeros((nb, 6)) if body_velocity is None else np.array(body_velocity, float).reshape(nb, 6)
    qdd = np.zeros((nb, 6))
    channels = _channels_fn(fe, analysis, duration)
    x0, v0, a0 = channels(np.zeros(1))
    pres = np.flatnonzero(net.channel >= 0)
    X[pres], V[pres], A[pres] = x0[0, net.channel[pres]], v0[0, net.channel[pres]], a0[0, net.channel[pres]]
    con_target = fe.con_target.copy()
    active = np.ones(len(fe.con_node), np.int64)
    fail_at = np.full(len(fe.con_node), np.nan)
    # each body's chart: R = R0 R(angles), R0 = I until its |pitch| passes DF.CHART_LIMIT (from the start too)
    frame = np.zeros((nb, DF.F_SIZE))
    frame[:, DF.F_GLOB:DF.F_GLOB + 3] = q[:, 3:]
    for b in range(nb):
        DF.rechart(q[b], qd[b], qdd[b], frame[b], DF.CHART_LIMIT)
    n_out = int(round(duration / output_interval))  # noqa: RUF046
    sub = max(1, math.ceil(output_interval / dt - 1e-9))
    h = output_interval / sub
    F, M = np.zeros((n, 3)), np.zeros((n, 3, 3))
    tension = np.zeros(net.n_elements)
    m.settle_viscoelastic(X, np.zeros_like(X))
    if m.water.sea is not None:  # an irregular sea: its kinematics on a grid over where the lines go
        m.prepare_sea(duration, sea_positions(fe, X, channels, duration, output_interval), bands=sea_bands(fe))
    _, _, t0_tension, _ = m.evaluate(X, V, A, 0.0)
    initial_accelerations(fe, X, V, A, q, qd, qdd, frame, v0[0], a0[0])
    g = _global_state(q, qd, frame)
    times, pos, vel, ten, bq, bqd, bw = [0.0], [X.copy()], [V.copy()], [t0_tension], [g[0]], [g[1]], [g[2]]
    knodes = line_end_nodes(net)  # the lines' end nodes and their neighbours: their accelerations, for the end forces
    acc = [A[knodes]]  # (at t = 0 the tied nodes' are their bodies' and points': initial_accelerations)
    stats = np.zeros(3)
    iterations = steps = 0
    interrupted = False
    args = fe.kernel_args()
    bargs = fe.body_args()
    rker = fe.memory_kernel if fe.memory_kernel is not None else np.zeros((nb, 1, 6, 6))
    memory = rker.shape[1] > 1
    if memory and abs(fe.memory_step - h) > 1e-9 * fe.memory_step:
        raise InputError(f"the bodies' radiation kernel is sampled every {fe.memory_step:g} s, and the run steps "
                         f"{h:g} s. Suggested fix: build the kernel at the run's time step (an "
                         "output_interval that is a whole number of time steps).")
    rhist = np.zeros((nb, rker.shape[1], 6))
    g0 = _global_state(q, qd, frame)
    rhist[:, 0, :3], rhist[:, 0, 3:] = qd[:, :3], g0[2]  # the start's velocity: one step back at the first step
    rhead = np.zeros(nb, np.int64)
    body_nodes = np.asarray(fe.con_node)[np.asarray(fe.con_body) >= 0]  # the free bodies' tied nodes
    left_sea = False  # said once
    begin = _time.perf_counter()
    try:
        for k in range(n_out):
            m.ensure_sea(k * output_interval, (k + 1) * output_interval)  # an irregular sea's grid window

            def coupled(t, dtk, px, pv, pa):
                return DK.coupled_steps(X, V, A, q, qd, qdd, t, dtk, px, pv, pa, net.channel, args, m.weight, m.fidx,
                                        m.nfree, m.bw, m.env, m.cur_depth, m.cur_speed, True, m.sea, fe.node_fext,
                                        fe.con_node, fe.con_body, fe.con_arm, con_target, active, fe.con_chan,
                                        fe.fail_time, fe.fail_tension, fe.fail_elem, fail_at, *bargs, beta, gamma,
                                        tol, max_iter, F, M, tension, stats, frame, rker, rhist, rhead, h)

            # the memory's history is kept every time step h; a halved step uses it as it stands (see coupled_steps)
            done, spent = advance_interval(k * output_interval, h, sub, channels, coupled, stats, max_halvings,
                                           max_iter, "system", "smaller time_step, more elements, or check the "
                                           "motions and external forces for a jump")
            steps += done
            iterations += spent
            times.append((k + 1) * output_interval)
            pos.append(X.copy())
            vel.append(V.copy())
            ten.append(tension.copy())
            acc.append(tied_accelerations(fe, A, q, qd, qdd, frame, active, channels, times[-1])[knodes])
            g = _global_state(q, qd, frame)
            bq.append(g[0])
            bqd.append(g[1])
            bw.append(g[2])
            if not left_sea and len(body_nodes):
                i = outside_sea(m.sea if m.water.sea is not None else None, X[body_nodes])
                if i is not None:
                    left_sea = True
                    x, y = X[body_nodes[i], 0], X[body_nodes[i], 1]
                    warnings.warn(f"at t = {times[-1]:g} s a free body's fairlead (x = {x:.4g} m, y = {y:.4g} m) has "
                                  "left the irregular sea's kinematics grid (it allows "
                                  f"{SEA_EXCURSION:.0%} of the depth of excursion): the lines there take the grid "
                                  "edge's kinematics from now on. Suggested fix: check that the mooring holds the "
                                  "body, or raise seacable.system.dynamics.loop.SEA_EXCURSION.",
                                  SeacableWarning, stacklevel=2)
            if progress is not None:
                progress(times[-1], duration)
    except KeyboardInterrupt:
        interrupted = True
    wall = _time.perf_counter() - begin
    nt = keep_whole_outputs(times, pos, vel, ten, bq, bqd, bw, acc)
    return SystemRun(time=np.array(times), position=np.array(pos), velocity=np.array(vel),
                     tension=np.array(ten), body_position=np.array(bq).reshape(nt, nb, 6),
                     body_velocity=np.array(bqd).reshape(nt, nb, 6), failure_time=fail_at, time_step=h,
                     steps=steps, iterations=iterations, wall_time=wall, interrupted=interrupted,
                     body_angular_velocity=np.array(bw).reshape(nt, nb, 3),
                     acceleration=np.array(acc).reshape(nt, knodes.size, 3), kinematic_nodes=knodes)


def _simulate_lines(fe: SystemFE, start: SystemState, duration: float, dt: float, output_interval: float, *,
                    analysis: SystemDynamicAnalysis | None = None, tol: float = 1e-7, max_iter: int = 30,
                    beta: float = 0.25, gamma: float = 0.5, progress=None) -> SystemRun:
    """:func:`simulate_system` for a system whose lines are all it solves for (:func:`lines_only`): the mooring
    model's compiled time loop (:func:`seacable.mooring.solver.simulate`), the same Newmark scheme."""
    run = simulate_lines(fe.model, _channels_fn(fe, analysis, duration), duration, dt, output_interval,
                         initial=start.position, tol=tol, max_iter=max_iter, progress=progress, beta=beta,
                         gamma=gamma)
    nt = len(run.time)
    return SystemRun(time=run.time, position=run.position, velocity=run.velocity, tension=run.tension,
                     body_position=np.zeros((nt, 0, 6)), body_velocity=np.zeros((nt, 0, 6)),
                     failure_time=np.zeros(0), time_step=run.time_step, steps=run.steps, iterations=run.iterations,
                     wall_time=run.wall_time, interrupted=run.interrupted,
                     body_angular_velocity=np.zeros((nt, 0, 3)), acceleration=run.acceleration,
                     kinematic_nodes=run.kinematic_nodes)


def _global_pose(q, frame) -> np.ndarray:
    """The bodies' poses (nb, 6) with the global (roll, pitch, yaw) of their charts' ``R0 R(angles)``."""
    out = np.array(q, float).reshape(-1, 6)
    for b in range(out.shape[0]):
        if frame[b, DF.F_ON]:
            g = np.empty(3)
            DF.global_angles(out[b], frame[b], g)
            out[b, 3:] = g
    return out


def _global_state(q, qd, frame):
    """Poses (nb, 6) and velocities (nb, 6) in the global angles, and angular velocities (nb, 3), of the
    bodies' chart states: a body never re-charted as it is (its angles are the global ones); a re-charted
    one with the global angles of ``R0 R(angles)`` (continuous, :func:`~seacable.system.dynamics.frames.euler_near`)
    and their rates ``E(global)^-1 w`` (regularised at pitch +-90 deg as the Newton step,
    :func:`~seacable.system.dynamics.frames._angle_increment`)."""
    nb = q.shape[0]
    pose, vel, w = q.copy(), qd.copy(), np.zeros((nb, 3))
    eye = np.zeros(DF.F_SIZE)
    for b in range(nb):
        E, ed = np.zeros((3, 3)), np.zeros(3)
        DF.angular_map(q[b], qd[b], E, ed, frame[b])
        w[b] = E @ qd[b, 3:]
        if frame[b, DF.F_ON]:
            pose[b, 3:] = frame[b, DF.F_GLOB:DF.F_GLOB + 3]
            rates = w[b].copy()
            DF._angle_increment(pose[b], rates, eye)
            vel[b, 3:] = rates
    return pose, vel, w

"""One implicit time step of the lumped-mass laying model (paper 001 section 3), in 2-D or 3-D, compiled.

The suspended cable is a chain of points ``r_0 .. r_N``, in the vertical (x, z) plane of paper 001 or in
(x, y, z) (the same equations in three dimensions; the last coordinate is up): ``r_0`` is the
touchdown node (landed, fixed), ``r_N`` the water entry at the ship (prescribed), and the nodes in
between are free lumped masses. Segment ``j`` joins ``r_j`` and ``r_{j+1}`` and has the unstretched
length ``L_j`` and the tension ``T_j``.

Equations of a free node (paper eq. (12)-(14), corrected as in SPEC: ``K_i`` carries
``cos(theta)`` in both terms and ``J_i`` is ``m_i +`` the added-mass sum)::

    (m_i I + sum_j 1/2 L_j (e_n (I - t_j t_j^T) + e_t t_j t_j^T)) a_i = T_i t_i - T_{i-1} t_{i-1} + D_i + W_i

with ``t_j`` the unit tangent of segment j (``I - t t^T`` is ``n n^T`` in 2-D), ``e_n`` / ``e_t`` the added mass per
length normal / along the cable, ``W_i`` the weight of half of each adjacent segment, and the
Morison drag of each half segment evaluated with the node's velocity relative to the water ``u``::

    D = 1/2 rho C_dn d |u_n| u_n (1/2 L_j) + 1/2 rho C_dt pi d (u.t)|u.t| t (1/2 L_j),   u_n = u - (u.t) t,

(the tangential term carries the diameter, which the printed eq. (14) drops).

Time discretisation (backward Euler, first order, unconditionally stable for this stiff, strongly
damped system; steady translation is reproduced exactly, so the steady lay does not depend on dt)::

    (M_i + dt C_i)(v_i' - v_i) = dt (F_i + T_i' t_i' - T_{i-1}' t_{i-1}'),    r_i' = r_i + dt v_i',

where ``C_i = -dD/dv`` is the drag linearised about the old velocity (implicit drag), ``M_i`` uses the
old tangents and the primes are the new time level. The constraint of each segment is

    |r_{j+1}' - r_j'| = L_j (1 + T_j' / EA)        (eq. (15); 1/EA = 0: inextensible)

and a cable takes no compression: a segment whose tension would be negative goes slack (``T_j = 0``,
chord shorter than ``L_j``) and is taut again once stretched (an active set, updated as Newton goes).
Laid cable free to slide (``laid_cable: sliding``) joins the step as nodes on the seabed: each moves in the
seabed's tangent plane (the normal reaction eliminated from the node's form, :func:`_node_matrices`) against
Coulomb's friction ``mu R``, elastic-perfectly plastic: a spring ``mu R / slip`` from the point it sticks to, up to
``mu R`` once it slides (:func:`_friction`, and :func:`drag_anchors` after the step).

Positions and tensions are solved together by Newton's method; ordered node by node the Jacobian is
block tri-diagonal (3x3 blocks in 2-D, 4x4 in 3-D) (Walton & Polachek's "tentative step and improvement" in modern form). It
includes the geometric stiffness ``T (I - t t^T) / l``: holding the tangents fixed and iterating on
them instead diverges once ``T dt^2 / (m l)`` exceeds about one, which a 1 m segment under 200 N
does at dt = 0.1 s.

References
----------
.. [1] Paper 001 (seeds/001), section 3, eq. (12)-(18).
.. [2] Walton, T. S. & Polachek, H., 1960. Calculation of transient motion of submerged cables.
   Mathematics of Computation 14, 27-46.
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import njit
from ..towed.linalg import block_thomas_small

__all__ = [
    "N_PROPS",
    "P_CDN",
    "P_CDT",
    "P_COMPLIANCE",
    "P_DIAMETER",
    "P_EN",
    "P_ET",
    "P_MASS",
    "P_WEIGHT",
    "STEP_ACTIVE_SET",
    "STEP_NOT_CONVERGED",
    "STEP_OK",
    "STEP_SINGULAR",
    "current_at",
    "drag_anchors",
    "implicit_step",
    "no_contact",
    "settle",
]

# Columns of the per-type property table (per unit unstretched length).
P_MASS, P_WEIGHT, P_DIAMETER, P_CDN, P_CDT, P_EN, P_ET, P_COMPLIANCE = range(8)
N_PROPS = 8
# Outcomes of implicit_step.
STEP_OK = 0               # converged: residual <= tol and the slack set settled
STEP_NOT_CONVERGED = 1    # residual still > tol after max_iter Newton iterations
STEP_ACTIVE_SET = 2       # converged each time, but segments kept going slack / taut for max_rounds rounds
STEP_SINGULAR = 3         # the Newton matrix was singular
# Columns of the per-node point-mass table (repeaters).
Q_MASS, Q_ADDED, Q_WEIGHT, Q_CDA = range(4)


def no_contact(npt: int, dim: int) -> tuple:
    """The ``seabed`` argument of :func:`implicit_step` for a cable with no node sliding on the seabed."""
    return np.zeros(npt, dtype=np.int64), np.zeros((npt, dim)), np.zeros(npt), np.zeros((npt, dim)), 1.0


@njit(cache=True)
def current_at(z, depths, speeds):
    """In-line current at elevation ``z`` from a profile (``depths`` below the surface). [m/s]"""
    if depths.size == 1:
        return speeds[0]
    return np.interp(-z, depths, speeds)


@njit(cache=True, inline="always")
def _water_velocity(z, depths, current, dim, out):
    """Current velocity at elevation ``z`` (the last coordinate) from a profile table: ``current[k]`` at
    ``depths[k]`` below the surface, linear between, constant beyond."""
    n = depths.size
    if n == 1 or -z <= depths[0]:
        for d in range(dim):
            out[d] = current[0, d]
        return
    if -z >= depths[n - 1]:
        for d in range(dim):
            out[d] = current[n - 1, d]
        return
    k = np.searchsorted(depths, -z) - 1
    f = (-z - depths[k]) / (depths[k + 1] - depths[k])
    for d in range(dim):
        out[d] = current[k, d] + f * (current[k + 1, d] - current[k, d])


@njit(cache=True, inline="always")
def _invert_sym(a, dim, out):
    """Inverse of a symmetric positive-definite 2x2 or 3x3 matrix (its adjugate over its determinant)."""
    if dim == 2:
        det = a[0, 0] * a[1, 1] - a[0, 1] * a[0, 1]
        out[0, 0], out[1, 1] = a[1, 1] / det, a[0, 0] / det
        out[0, 1] = out[1, 0] = -a[0, 1] / det
        return
    c00 = a[1, 1] * a[2, 2] - a[1, 2] * a[1, 2]
    c01 = a[0, 2] * a[1, 2] - a[0, 1] * a[2, 2]
    c02 = a[0, 1] * a[1, 2] - a[0, 2] * a[1, 1]
    det = a[0, 0] * c00 + a[0, 1] * c01 + a[0, 2] * c02
    out[0, 0] = c00 / det
    out[0, 1] = out[1, 0] = c01 / det
    out[0, 2] = out[2, 0] = c02 / det
    out[1, 1] = (a[0, 0] * a[2, 2] - a[0, 2] * a[0, 2]) / det
    out[1, 2] = out[2, 1] = (a[0, 2] * a[0, 1] - a[0, 0] * a[1, 2]) / det
    out[2, 2] = (a[0, 0] * a[1, 1] - a[0, 1] * a[0, 1]) / det


@njit(cache=True)
def _node_matrices(pos, vel, L, seg_type, props, point, depths, current, rho, dt, contact, normal, G, b):
    """:func:`_node_matrices_dim` with the dimension (2 or 3) a constant of the compiled code, which unrolls its
    small loops: the same arithmetic, operation for operation."""
    if pos.shape[1] == 2:
        _node_matrices_dim(pos, vel, L, seg_type, props, point, depths, current, rho, dt, contact, normal, G, b, 2)
    else:
        _node_matrices_dim(pos, vel, L, seg_type, props, point, depths, current, rho, dt, contact, normal, G, b, 3)


@njit(cache=True, inline="always")
def _node_matrices_dim(pos, vel, L, seg_type, props, point, depths, current, rho, dt, contact, normal, G, b, dim):
    """Fill ``G_i = dt^2 A_i^-1`` and the free-motion positions ``b_i`` of the free nodes.

    ``A_i = M_i + dt C_i``: the node's mass, the added mass ``e_n (I - t t^T) + e_t t t^T`` of each half
    segment, and ``C_i = dD/du`` the drag's linearisation about the old velocity: for the normal drag
    ``k_n |u_n| u_n`` it is ``k_n (|u_n| (I - t t^T) + u_n u_n^T / |u_n|)`` (in 2-D ``2 k_n |u_n| n n^T``).

    A node on the seabed (``contact[i]``) moves in the seabed's tangent plane through its old position (unit
    normal ``normal[i]``): the seabed's reaction ``R n`` is the multiplier of ``n . (r - r_old) = 0``, and
    eliminating it from ``A (r - b) / dt^2 = F + R n`` leaves the free node's form with

        G' = G - G n n^T G / (n^T G n),    b' = b - G n (n . (b - r_old)) / (n^T G n),

    so the Newton system keeps its blocks (``G'`` is singular along ``n``, and ``I + G' K`` is not).
    """
    npt = pos.shape[0]
    up = dim - 1                                  # the vertical coordinate
    a = np.empty((dim, dim))
    u = np.empty(dim)
    t = np.empty(dim)
    un = np.empty(dim)
    f = np.empty(dim)
    ainv = np.empty((dim, dim))
    for i in range(1, npt - 1):
        _water_velocity(pos[i, up], depths, current, dim, u)
        for d in range(dim):
            u[d] -= vel[i, d]
            f[d] = 0.0
            for e in range(dim):
                a[d, e] = 0.0
            a[d, d] = point[i, Q_MASS] + point[i, Q_ADDED]
        f[up] = -point[i, Q_WEIGHT]
        for j in (i - 1, i):
            p = props[seg_type[j]]
            half = 0.5 * L[j]
            ln = 0.0
            for d in range(dim):
                t[d] = pos[j + 1, d] - pos[j, d]
                ln += t[d] * t[d]
            ln = math.sqrt(ln)
            ut = 0.0
            for d in range(dim):
                t[d] /= ln
                ut += u[d] * t[d]
            size = 0.0
            for d in range(dim):
                un[d] = u[d] - ut * t[d]
                size += un[d] * un[d]
            size = math.sqrt(size)
            mass = p[P_MASS] * half
            en = p[P_EN] * half
            et = p[P_ET] * half
            kn = 0.5 * rho * p[P_CDN] * p[P_DIAMETER] * half
            kt = 0.5 * rho * p[P_CDT] * math.pi * p[P_DIAMETER] * half
            f[up] -= p[P_WEIGHT] * half
            ct = 2.0 * kt * abs(ut)
            for d in range(dim):
                f[d] += kn * size * un[d] + kt * abs(ut) * ut * t[d]
                a[d, d] += mass + en + dt * kn * size
                for e in range(dim):
                    tt = t[d] * t[e]
                    a[d, e] += (et - en) * tt + dt * (ct - kn * size) * tt
                    if size > 0.0:
                        a[d, e] += dt * kn * un[d] * un[e] / size
        cda = point[i, Q_CDA]
        if cda > 0.0:
            k = 0.5 * rho * cda
            speed = 0.0
            for d in range(dim):
                speed += u[d] * u[d]
            speed = math.sqrt(speed)
            for d in range(dim):
                f[d] += k * speed * u[d]
                if speed > 0.0:
                    a[d, d] += dt * k * speed
                    for e in range(dim):
                        a[d, e] += dt * k * u[d] * u[e] / speed
        _invert_sym(a, dim, ainv)
        for d in range(dim):
            acc = 0.0
            for e in range(dim):
                G[i, d, e] = dt * dt * ainv[d, e]
                acc += G[i, d, e] * f[e]
            b[i, d] = pos[i, d] + dt * vel[i, d] + acc
        if contact[i]:
            _on_plane(G[i], b[i], pos[i], normal[i], dim)


@njit(cache=True, inline="always")
def _on_plane(g, b, p0, n, dim):
    """Restrict the node form ``r = b + g F`` to the plane through ``p0`` normal to the unit ``n`` (in place)."""
    gn = np.empty(dim)
    ngn = 0.0
    gap = 0.0
    for d in range(dim):
        gn[d] = 0.0
        for e in range(dim):
            gn[d] += g[d, e] * n[e]
        ngn += n[d] * gn[d]
        gap += n[d] * (b[d] - p0[d])
    for d in range(dim):
        b[d] -= gn[d] * gap / ngn
        for e in range(dim):
            g[d, e] -= gn[d] * gn[e] / ngn


@njit(cache=True)
def implicit_step(pos, vel, chute, L, seg_type, props, point, depths, current, rho, dt, T, active,
                  compliance_floor, seabed, tol, max_iter, max_rounds, new_pos, new_vel):
    """Advance the suspended cable by ``dt``; returns ``(status, iterations, residual)``.

    Parameters
    ----------
    pos, vel : (N+1, D) float arrays
        Node positions and velocities at the old time, in 2-D (x, z) or 3-D (x, y, z), the last coordinate
        up; row 0 is the touchdown node, row N the water entry at the old time. [m], [m/s]
    chute : (D,) float array
        Water-entry point at the new time. [m]
    L : (N,) float array
        Unstretched segment lengths at the new time. [m]
    seg_type, props : int array (N,), float array (n_types, N_PROPS)
        Line type of each segment and the per-length properties of each type.
    point : (N+1, 4) float array
        Point masses at the nodes: mass, added mass [kg], weight in water [N], C_D A [m^2].
    depths, current : (K,) and (K, D) float arrays
        Current profile: the water's velocity at each depth below the surface (vertical part 0). [m], [m/s]
    rho, dt : float
        Water density [kg/m^3] and time step [s].
    T, active : (N,) float and int arrays
        Tension guess and active set (1: taut constraint, 0: slack); updated in place. [N]
    compliance_floor : float
        Smallest compliance 1/EA used: a strain far below any cable's elastic strain that keeps the
        Newton matrix regular when a taut inextensible cable is straight between its ends. [1/N]
    seabed : tuple (contact, normal, grip, anchor, slip)
        Nodes resting on the seabed (laid cable free to slide, :func:`no_contact` for none): ``contact`` (N+1,)
        int, 1 for a node that moves in the seabed's tangent plane through its old position; ``normal``
        (N+1, D) that plane's unit normal; ``grip`` (N+1,) the friction limit ``mu R`` of each node [N];
        ``anchor`` (N+1, D) the point each node sticks to [m], and ``slip`` the distance from it at which the
        friction reaches its limit [m]: the friction is ``-grip d / max(|d|, slip)`` for the node's
        distance ``d`` from its anchor in the plane (a stiff spring that holds, Coulomb's law once it slides;
        implicit, in the Newton system). The caller moves the anchors after a step (:func:`drag_anchors`).
    tol : float
        Tolerance on the constraint residual relative to the segment length. [-]
    max_iter, max_rounds : int
        Newton iterations per active set, and active-set updates (slack <-> taut).
    new_pos, new_vel : (N+1, D) float arrays
        Output: positions and velocities at the new time.

    Returns
    -------
    status : int
        ``STEP_OK`` (0): the residual is ``<= tol`` and no slack segment is stretched; otherwise why
        not: ``STEP_NOT_CONVERGED`` (the residual is still ``> tol`` after ``max_iter`` iterations),
        ``STEP_ACTIVE_SET`` (converged each time, but the slack set changed ``max_rounds`` times) or
        ``STEP_SINGULAR`` (singular Newton matrix).
    iterations : int
        Newton iterations done, all rounds together.
    residual : float
        The quantity compared with ``tol``: largest ``|chord - L (1 + T/EA)| / L`` over the taut
        segments and ``|r_i - b_i - G_i F_i| / L`` over the free nodes, in the last iteration. [-]
    """
    npt, dim = pos.shape
    nseg = npt - 1
    m = dim + 1                                   # block size: a tension and a node's position
    G = np.empty((npt, dim, dim))                 # (rows 1 .. npt - 2 filled and used)
    b = np.empty((npt, dim))
    contact, normal, grip, anchor, slip = seabed
    _node_matrices(pos, vel, L, seg_type, props, point, depths, current, rho, dt, contact, normal, G, b)
    comp = np.empty(nseg)
    for j in range(nseg):
        comp[j] = max(props[seg_type[j], P_COMPLIANCE], compliance_floor)
    # predictor: the old tangents carry the old tensions
    r = new_pos
    c = np.empty((nseg, dim))
    ell = np.empty(nseg)
    _chords(pos, c, ell)
    fk = np.empty(dim)
    for d in range(dim):
        r[0, d] = pos[0, d]
        r[npt - 1, d] = chute[d]
    vp = np.empty(dim)
    dfric = np.empty((dim, dim))
    for i in range(1, npt - 1):
        for d in range(dim):
            fk[d] = T[i] * c[i, d] - T[i - 1] * c[i - 1, d]
        if contact[i] and grip[i] > 0.0:      # the friction that held the old tensions
            _friction(pos[i], anchor[i], normal[i], grip[i], slip, fk, vp, dfric)
        for d in range(dim):
            acc = b[i, d]
            for e in range(dim):
                acc += G[i, d, e] * fk[e]
            r[i, d] = acc
    lower = np.empty((nseg, m, m))                # (zeroed by _assemble, and rhs and x filled)
    diag = np.empty((nseg, m, m))
    upper = np.empty((nseg, m, m))
    rhs = np.empty((nseg, m))
    x = np.empty((nseg, m))
    gamma, lu, piv, scale = np.empty((nseg, m, m)), np.empty((m, m)), np.empty(m, dtype=np.int64), np.empty((3, m))
    shortest = L.min()
    residual = np.inf
    total = 0
    for _ in range(max_rounds):
        converged = False
        for it in range(max_iter + 1):
            _chords(r, c, ell)
            residual = _assemble(r, b, G, T, active, c, ell, L, comp, lower, diag, upper, rhs, seabed)
            if residual <= tol:
                converged = True
                break
            if it == max_iter:
                break
            if block_thomas_small(lower, diag, upper, rhs, x, gamma, lu, piv, scale) != 0:
                total += it
                return STEP_SINGULAR, total, residual
            # damped update: no node moves more than a quarter of the shortest segment per iteration
            move = 0.0
            for k in range(nseg - 1):
                size = 0.0
                for d in range(dim):
                    size += abs(x[k, 1 + d])
                move = max(move, size)
            scale_step = min(1.0, 0.25 * shortest / move) if move > 0.0 else 1.0
            for k in range(nseg):
                T[k] += scale_step * x[k, 0]
                if active[k] and T[k] < 0.0:
                    T[k] = 0.0
                    active[k] = 0      # projected Newton: a segment in compression goes slack at once
                if k + 1 < npt - 1:
                    i = k + 1
                    sliding = contact[i] and grip[i] > 0.0
                    if sliding:
                        before = _plane_offset(r[i], anchor[i], normal[i], vp)
                        for d in range(dim):
                            dfric[0, d] = vp[d]
                    for d in range(dim):
                        r[i, d] += scale_step * x[k, 1 + d]
                    if sliding and before > slip:
                        _plane_offset(r[i], anchor[i], normal[i], vp)
                        turn = 0.0
                        for d in range(dim):
                            turn += vp[d] * dfric[0, d]
                        if turn < 0.0:
                            # a sliding node whose update sends it past its anchor goes back to the anchor
                            # instead: Newton across the friction's jump from +grip to -grip would go back and
                            # forth, where sticking (the stiff spring) is the answer or the way to the other side
                            for d in range(dim):
                                r[i, d] -= vp[d]
        total += it
        if not converged:
            return STEP_NOT_CONVERGED, total, residual
        # complementarity: a slack segment stretched beyond its length is taut again
        changed = False
        for j in range(nseg):
            g = ell[j] - L[j] * (1.0 + T[j] * comp[j])
            if not active[j] and g > 10.0 * tol * L[j]:
                active[j] = 1
                changed = True
        if not changed:
            for i in range(npt):
                for d in range(dim):
                    new_vel[i, d] = (r[i, d] - pos[i, d]) / dt
            new_vel[0, :] = 0.0
            return STEP_OK, total, residual
    return STEP_ACTIVE_SET, total, residual


@njit(cache=True)
def settle(pos, vel, zb, lo, hi):
    """Put the free nodes that went below the seabed on it, and find the first node on the seabed from the ship.

    ``zb`` is the seabed's elevation under rows ``lo + 1 .. hi - 1`` of ``pos`` (``-inf`` where it need not be
    known). Rows ``lo + 2 .. hi - 1`` below it are raised onto it, their vertical velocity clipped at 0 (a seabed
    rising under the cable holds it up); ``pos`` and ``vel`` are changed in place. Returns the last row of
    ``lo + 1 .. hi - 2`` on the seabed (within 1e-9 m), or ``lo`` if none is.
    """
    up = pos.shape[1] - 1
    for k in range(lo + 2, hi):
        z = zb[k - lo - 1]
        if pos[k, up] < z:
            pos[k, up] = z
            v = vel[k, up]
            if not (v > 0.0 or math.isnan(v)):      # as numpy.maximum(v, 0.0): -0.0 gives +0.0, NaN stays
                vel[k, up] = 0.0
    for k in range(hi - 2, lo, -1):
        if pos[k, up] <= zb[k - lo - 1] + 1e-9:
            return k
    return lo


@njit(cache=True)
def _plane_offset(r, p0, n, v):
    """Offset ``v`` of ``r`` from ``p0`` in the seabed plane (normal ``n``); returns its size."""
    dim = r.shape[0]
    vn = 0.0
    for d in range(dim):
        v[d] = r[d] - p0[d]
        vn += v[d] * n[d]
    vv = 0.0
    for d in range(dim):
        v[d] -= vn * n[d]
        vv += v[d] * v[d]
    return math.sqrt(vv)


@njit(cache=True)
def _friction(r, anchor, n, grip, slip, f, v, dfric):
    """Add a seabed node's Coulomb friction to the force ``f`` and set ``dfric = -dPhi / dr``.

    ``Phi = -grip v / max(|v|, slip)``, with ``v = (I - n n^T)(r - anchor)`` the node's offset from its anchor
    in the seabed plane: a spring of stiffness ``grip / slip`` while it holds, Coulomb's law once it slides
    (elastic-perfectly plastic, OrcaFlex's model of seabed friction). Its derivative is
    ``grip (I - n n^T) / slip`` holding and ``grip (I - n n^T - e e^T) / |v|`` sliding (``e = v / |v|``).
    """
    dim = r.shape[0]
    dist = _plane_offset(r, anchor, n, v)
    s = max(dist, slip)
    for d in range(dim):
        f[d] -= grip * v[d] / s
        for e in range(dim):
            p = (1.0 if d == e else 0.0) - n[d] * n[e]
            if dist > slip:
                p -= v[d] * v[e] / (dist * dist)
            dfric[d, e] = grip * p / s


@njit(cache=True)
def drag_anchors(pos, contact, normal, anchor, slip):
    """Move the anchor of each sliding node to ``slip`` behind it, along its offset in the seabed plane
    (after a step: the friction's plastic part). Returns the largest distance slid. [m]"""
    npt, dim = pos.shape
    v = np.empty(dim)
    most = 0.0
    for i in range(npt):
        if not contact[i]:
            continue
        dist = _plane_offset(pos[i], anchor[i], normal[i], v)
        if dist > slip:
            for d in range(dim):
                anchor[i, d] += v[d] * (1.0 - slip / dist)
            most = max(most, dist - slip)
    return most


@njit(cache=True, inline="always")
def _norm_g_d(g, dfric, dim):
    """Largest absolute row sum of ``g dfric`` (the friction's part of a seabed node's diagonal block)."""
    big = 0.0
    for a in range(dim):
        row = 0.0
        for d in range(dim):
            acc = 0.0
            for e in range(dim):
                acc += g[a, e] * dfric[e, d]
            row += abs(acc)
        big = max(big, row)
    return big


@njit(cache=True)
def _chords(r, c, ell):
    """Unit chords ``c`` and lengths ``ell`` of the segments of ``r`` (:func:`_chords_dim`, the dimension a
    constant of the compiled code)."""
    if r.shape[1] == 2:
        _chords_dim(r, c, ell, 2)
    else:
        _chords_dim(r, c, ell, 3)


@njit(cache=True, inline="always")
def _chords_dim(r, c, ell, dim):
    """:func:`_chords` in ``dim`` dimensions."""
    for j in range(c.shape[0]):
        ln = 0.0
        for d in range(dim):
            c[j, d] = r[j + 1, d] - r[j, d]
            ln += c[j, d] * c[j, d]
        ln = max(math.sqrt(ln), 1e-12)
        ell[j] = ln
        for d in range(dim):
            c[j, d] /= ln


@njit(cache=True)
def _assemble(r, b, G, T, active, c, ell, L, comp, lower, diag, upper, rhs, seabed):
    """:func:`_assemble_dim` with the dimension (2 or 3) a constant of the compiled code (as :func:`_node_matrices`)."""
    if c.shape[1] == 2:
        return _assemble_dim(r, b, G, T, active, c, ell, L, comp, lower, diag, upper, rhs, seabed, 2)
    return _assemble_dim(r, b, G, T, active, c, ell, L, comp, lower, diag, upper, rhs, seabed, 3)


@njit(cache=True, inline="always")
def _assemble_dim(r, b, G, T, active, c, ell, L, comp, lower, diag, upper, rhs, seabed, dim):
    """Newton system of the step in block tri-diagonal form; returns the scaled residual.

    Block ``k`` holds the unknowns ``(T_k, r_{k+1})`` (the last block only ``T_{N-1}``) and the equations
    ``g_k`` (constraint of segment k) and ``F_{k+1}`` (motion of node k+1)::

        g_k = |r_{k+1} - r_k| - L_k (1 + T_k / EA)
        F_i = r_i - b_i - G_i (T_i c_i - T_{i-1} c_{i-1}),   c_j = (r_{j+1} - r_j) / |r_{j+1} - r_j|

    with ``dc_j / dr_{j+1} = (I - c_j c_j^T) / |r_{j+1} - r_j|`` (the geometric stiffness). A node on the
    seabed adds its friction (:func:`_friction`) to the force. The right side is minus the residual.
    """
    contact, normal, grip, anchor, slip = seabed
    nseg = c.shape[0]
    vp = np.empty(dim)
    dfric = np.zeros((dim, dim))
    nfree = nseg - 1
    lower[:] = 0.0
    diag[:] = 0.0
    upper[:] = 0.0
    res = 0.0
    f = np.empty(dim)
    kk = np.empty((dim, dim))
    ki = np.empty((dim, dim))
    for k in range(nseg):
        # constraint row
        if active[k]:
            g = ell[k] - L[k] * (1.0 + T[k] * comp[k])
            res = max(res, abs(g) / L[k])
            rhs[k, 0] = -g
            diag[k, 0, 0] = -L[k] * comp[k]
            for d in range(dim):
                if k + 1 <= nfree:
                    diag[k, 0, 1 + d] = c[k, d]
                if k >= 1:
                    lower[k, 0, 1 + d] = -c[k, d]
        else:
            rhs[k, 0] = -T[k]
            diag[k, 0, 0] = 1.0
        if k + 1 > nfree:
            for d in range(dim):
                diag[k, 1 + d, 1 + d] = 1.0
                rhs[k, 1 + d] = 0.0
            continue
        # motion rows of node i = k + 1
        i = k + 1
        for d in range(dim):
            f[d] = T[i] * c[i, d] - T[k] * c[k, d]
        sliding = contact[i] and grip[i] > 0.0
        if sliding:
            _friction(r[i], anchor[i], normal[i], grip[i], slip, f, vp, dfric)
        size = 0.0
        for d in range(dim):
            rd = r[i, d] - b[i, d]
            for e in range(dim):
                rd -= G[i, d, e] * f[e]
            size += abs(rd)
            rhs[k, 1 + d] = -rd
        if sliding:
            # measured as the move that would cancel it: the friction's stiffness grip / slip while it holds
            # magnifies the round-off of r (1e-14 m) to 1e-10 of the residual
            size /= 1.0 + _norm_g_d(G[i], dfric, dim)
        res = max(res, size / L[k])
        # K = T_i P_i + T_k P_k (geometric stiffness at node i), P_j = (I - c c^T) / ell
        # (tension only: a compressive iterate would make the matrix indefinite and Newton wander)
        pk = max(T[k], 0.0) / ell[k]
        pi_ = max(T[i], 0.0) / ell[i]
        for d in range(dim):
            for e in range(dim):
                eye = 1.0 if d == e else 0.0
                kk[d, e] = pk * (eye - c[k, d] * c[k, e])
                ki[d, e] = pi_ * (eye - c[i, d] * c[i, e])
        for a in range(dim):
            gc_k = 0.0
            gc_i = 0.0
            for e in range(dim):
                gc_k += G[i, a, e] * c[k, e]
                gc_i += G[i, a, e] * c[i, e]
            # d F / d T_k = +G c_k, d F / d T_i = -G c_i
            diag[k, 1 + a, 0] = gc_k
            upper[k, 1 + a, 0] = -gc_i
            for d in range(dim):
                gk = 0.0
                gi = 0.0
                gf = 0.0
                for e in range(dim):
                    gk += G[i, a, e] * kk[e, d]
                    gi += G[i, a, e] * ki[e, d]
                    if sliding:
                        gf += G[i, a, e] * dfric[e, d]
                # d F / d r_i = I + G (K_k + K_i + D), d F / d r_{i-1} = -G K_k, d F / d r_{i+1} = -G K_i
                # (D = -dPhi / dr_i, the friction's)
                diag[k, 1 + a, 1 + d] = (1.0 if a == d else 0.0) + gk + gi + gf
                if k >= 1:
                    lower[k, 1 + a, 1 + d] = -gk
                if i + 1 <= nfree:
                    upper[k, 1 + a, 1 + d] = -gi
    return res

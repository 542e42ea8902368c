"""One implicit time step of the 2-D lumped-mass laying model (paper 001 section 3), compiled.

The suspended cable is a chain of points ``r_0 .. r_N`` in the vertical (x, z) plane: ``r_0`` is the
touchdown node (landed, fixed), ``r_N`` the water entry at the ship (prescribed), and the nodes in
between are free lumped masses. Segment ``j`` joins ``r_j`` and ``r_{j+1}`` and has the unstretched
length ``L_j`` and the tension ``T_j``.

Equations of a free node (paper eq. (12)-(14), corrected as in SPEC: ``K_i`` carries
``cos(theta)`` in both terms and ``J_i`` is ``m_i +`` the added-mass sum)::

    (m_i I + sum_j 1/2 L_j (e_n n_j n_j^T + e_t t_j t_j^T)) a_i = T_i t_i - T_{i-1} t_{i-1} + D_i + W_i

with ``t_j`` the unit tangent of segment j, ``n_j`` its normal, ``e_n`` / ``e_t`` the added mass per
length normal / along the cable, ``W_i`` the weight of half of each adjacent segment, and the
Morison drag of each half segment evaluated with the node's velocity relative to the water ``u``::

    D = 1/2 rho C_dn d (u.n)|u.n| n (1/2 L_j) + 1/2 rho C_dt pi d (u.t)|u.t| t (1/2 L_j),

(the tangential term carries the diameter, which the printed eq. (14) drops).

Time discretisation (backward Euler, first order, unconditionally stable for this stiff, strongly
damped system; steady translation is reproduced exactly, so the steady lay does not depend on dt)::

    (M_i + dt C_i)(v_i' - v_i) = dt (F_i + T_i' t_i' - T_{i-1}' t_{i-1}'),    r_i' = r_i + dt v_i',

where ``C_i = -dD/dv`` is the drag linearised about the old velocity (implicit drag), ``M_i`` uses the
old tangents and the primes are the new time level. The constraint of each segment is

    |r_{j+1}' - r_j'| = L_j (1 + T_j' / EA)        (eq. (15); 1/EA = 0: inextensible)

and a cable takes no compression: a segment whose tension would be negative goes slack (``T_j = 0``,
chord shorter than ``L_j``) and is taut again once stretched (an active set, updated as Newton goes).
Positions and tensions are solved together by Newton's method; ordered node by node the Jacobian is
3x3 block tri-diagonal (Walton & Polachek's "tentative step and improvement" in modern form). It
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
from numba import njit

from ..towed.linalg import block_thomas

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
    "implicit_step",
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


@njit(cache=True)
def current_at(z, depths, speeds):
    """In-line current at elevation ``z`` from a profile (``depths`` below the surface). [m/s]"""
    if depths.size == 1:
        return speeds[0]
    return np.interp(-z, depths, speeds)


@njit(cache=True)
def _node_matrices(pos, vel, L, seg_type, props, point, depths, speeds, rho, dt, G, b):
    """Fill ``G_i = dt^2 A_i^-1`` and the free-motion positions ``b_i`` of the free nodes."""
    npt = pos.shape[0]
    for i in range(1, npt - 1):
        vx, vz = vel[i, 0], vel[i, 1]
        ux = current_at(pos[i, 1], depths, speeds) - vx
        uz = -vz
        m = point[i, Q_MASS]
        a11 = m + point[i, Q_ADDED]
        a22 = a11
        a12 = 0.0
        c11 = 0.0
        c12 = 0.0
        c22 = 0.0
        fx = 0.0
        fz = -point[i, Q_WEIGHT]
        for j in (i - 1, i):
            p = props[seg_type[j]]
            half = 0.5 * L[j]
            dx = pos[j + 1, 0] - pos[j, 0]
            dz = pos[j + 1, 1] - pos[j, 1]
            ln = math.sqrt(dx * dx + dz * dz)
            tx, tz = dx / ln, dz / ln
            nx, nz = -tz, tx
            mass = p[P_MASS] * half
            en = p[P_EN] * half
            et = p[P_ET] * half
            a11 += mass + en * nx * nx + et * tx * tx
            a22 += mass + en * nz * nz + et * tz * tz
            a12 += en * nx * nz + et * tx * tz
            fz -= p[P_WEIGHT] * half
            un = ux * nx + uz * nz
            ut = ux * tx + uz * tz
            kn = 0.5 * rho * p[P_CDN] * p[P_DIAMETER] * half
            kt = 0.5 * rho * p[P_CDT] * math.pi * p[P_DIAMETER] * half
            fx += kn * abs(un) * un * nx + kt * abs(ut) * ut * tx
            fz += kn * abs(un) * un * nz + kt * abs(ut) * ut * tz
            # -dD/dv = dD/du: 2 k |u.n| n n^T (+ the same along t)
            cn = 2.0 * kn * abs(un)
            ct = 2.0 * kt * abs(ut)
            c11 += cn * nx * nx + ct * tx * tx
            c22 += cn * nz * nz + ct * tz * tz
            c12 += cn * nx * nz + ct * tx * tz
        cda = point[i, Q_CDA]
        if cda > 0.0:
            k = 0.5 * rho * cda
            speed = math.sqrt(ux * ux + uz * uz)
            fx += k * speed * ux
            fz += k * speed * uz
            if speed > 0.0:
                c11 += k * (speed + ux * ux / speed)
                c22 += k * (speed + uz * uz / speed)
                c12 += k * ux * uz / speed
        a11 += dt * c11
        a22 += dt * c22
        a12 += dt * c12
        det = a11 * a22 - a12 * a12
        s = dt * dt / det
        G[i, 0, 0] = s * a22
        G[i, 1, 1] = s * a11
        G[i, 0, 1] = -s * a12
        G[i, 1, 0] = -s * a12
        b[i, 0] = pos[i, 0] + dt * vx + G[i, 0, 0] * fx + G[i, 0, 1] * fz
        b[i, 1] = pos[i, 1] + dt * vz + G[i, 1, 0] * fx + G[i, 1, 1] * fz


@njit(cache=True)
def implicit_step(pos, vel, chute, L, seg_type, props, point, depths, speeds, rho, dt, T, active,
                  compliance_floor, tol, max_iter, max_rounds, new_pos, new_vel):
    """Advance the suspended cable by ``dt``; returns ``(status, iterations, residual)``.

    Parameters
    ----------
    pos, vel : (N+1, 2) float arrays
        Node positions (x, z) and velocities at the old time; row 0 is the touchdown node, row N the
        water entry at the old time. [m], [m/s]
    chute : (2,) float array
        Water-entry point at the new time. [m]
    L : (N,) float array
        Unstretched segment lengths at the new time. [m]
    seg_type, props : int array (N,), float array (n_types, N_PROPS)
        Line type of each segment and the per-length properties of each type.
    point : (N+1, 4) float array
        Point masses at the nodes: mass, added mass [kg], weight in water [N], C_D A [m^2].
    depths, speeds : float arrays
        In-line current profile. [m], [m/s]
    rho, dt : float
        Water density [kg/m^3] and time step [s].
    T, active : (N,) float and int arrays
        Tension guess and active set (1: taut constraint, 0: slack); updated in place. [N]
    compliance_floor : float
        Smallest compliance 1/EA used: a strain far below any cable's elastic strain that keeps the
        Newton matrix regular when a taut inextensible cable is straight between its ends. [1/N]
    tol : float
        Tolerance on the constraint residual relative to the segment length. [-]
    max_iter, max_rounds : int
        Newton iterations per active set, and active-set updates (slack <-> taut).
    new_pos, new_vel : (N+1, 2) float arrays
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
    npt = pos.shape[0]
    nseg = npt - 1
    G = np.zeros((npt, 2, 2))
    b = np.zeros((npt, 2))
    _node_matrices(pos, vel, L, seg_type, props, point, depths, speeds, rho, dt, G, b)
    comp = np.empty(nseg)
    for j in range(nseg):
        comp[j] = max(props[seg_type[j], P_COMPLIANCE], compliance_floor)
    # predictor: the old tangents carry the old tensions
    r = new_pos
    c = np.empty((nseg, 2))
    ell = np.empty(nseg)
    _chords(pos, c, ell)
    r[0, 0], r[0, 1] = pos[0, 0], pos[0, 1]
    r[npt - 1, 0], r[npt - 1, 1] = chute[0], chute[1]
    for i in range(1, npt - 1):
        fx = T[i] * c[i, 0] - T[i - 1] * c[i - 1, 0]
        fz = T[i] * c[i, 1] - T[i - 1] * c[i - 1, 1]
        r[i, 0] = b[i, 0] + G[i, 0, 0] * fx + G[i, 0, 1] * fz
        r[i, 1] = b[i, 1] + G[i, 1, 0] * fx + G[i, 1, 1] * fz
    lower = np.zeros((nseg, 3, 3))
    diag = np.zeros((nseg, 3, 3))
    upper = np.zeros((nseg, 3, 3))
    rhs = np.zeros((nseg, 3))
    x = np.zeros((nseg, 3))
    gamma, lu, piv, scale = np.empty((nseg, 3, 3)), np.empty((3, 3)), np.empty(3, dtype=np.int64), np.empty((3, 3))
    shortest = L.min()
    residual = np.inf
    total = 0
    for _ in range(max_rounds):
        converged = False
        for it in range(max_iter + 1):
            _chords(r, c, ell)
            residual = _assemble(r, b, G, T, active, c, ell, L, comp, lower, diag, upper, rhs)
            if residual <= tol:
                converged = True
                break
            if it == max_iter:
                break
            if block_thomas(lower, diag, upper, rhs, x, gamma, lu, piv, scale) != 0:
                total += it
                return STEP_SINGULAR, total, residual
            # damped update: no node moves more than a quarter of the shortest segment per iteration
            move = 0.0
            for k in range(nseg - 1):
                move = max(move, abs(x[k, 1]) + abs(x[k, 2]))
            scale_step = min(1.0, 0.25 * shortest / move) if move > 0.0 else 1.0
            for k in range(nseg):
                T[k] += scale_step * x[k, 0]
                if active[k] and T[k] < 0.0:
                    T[k] = 0.0
                    active[k] = 0      # projected Newton: a segment in compression goes slack at once
                if k + 1 < npt - 1:
                    r[k + 1, 0] += scale_step * x[k, 1]
                    r[k + 1, 1] += scale_step * x[k, 2]
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
                new_vel[i, 0] = (r[i, 0] - pos[i, 0]) / dt
                new_vel[i, 1] = (r[i, 1] - pos[i, 1]) / dt
            new_vel[0, 0] = 0.0
            new_vel[0, 1] = 0.0
            return STEP_OK, total, residual
    return STEP_ACTIVE_SET, total, residual


@njit(cache=True)
def _chords(r, c, ell):
    """Unit chords ``c`` and lengths ``ell`` of the segments of ``r``."""
    for j in range(c.shape[0]):
        dx = r[j + 1, 0] - r[j, 0]
        dz = r[j + 1, 1] - r[j, 1]
        ln = max(math.sqrt(dx * dx + dz * dz), 1e-12)
        ell[j] = ln
        c[j, 0] = dx / ln
        c[j, 1] = dz / ln


@njit(cache=True)
def _assemble(r, b, G, T, active, c, ell, L, comp, lower, diag, upper, rhs):
    """Newton system of the step in block tri-diagonal form; returns the scaled residual.

    Block ``k`` holds the unknowns ``(T_k, x_{k+1}, z_{k+1})`` (the last block only ``T_{N-1}``) and
    the equations ``g_k`` (constraint of segment k) and ``F_{k+1}`` (motion of node k+1)::

        g_k = |r_{k+1} - r_k| - L_k (1 + T_k / EA)
        F_i = r_i - b_i - G_i (T_i c_i - T_{i-1} c_{i-1}),   c_j = (r_{j+1} - r_j) / |r_{j+1} - r_j|

    with ``dc_j / dr_{j+1} = (I - c_j c_j^T) / |r_{j+1} - r_j|`` (the geometric stiffness). The right
    side is minus the residual.
    """
    nseg = c.shape[0]
    nfree = nseg - 1
    lower[:] = 0.0
    diag[:] = 0.0
    upper[:] = 0.0
    res = 0.0
    for k in range(nseg):
        # constraint row
        if active[k]:
            g = ell[k] - L[k] * (1.0 + T[k] * comp[k])
            res = max(res, abs(g) / L[k])
            rhs[k, 0] = -g
            diag[k, 0, 0] = -L[k] * comp[k]
            if k + 1 <= nfree:
                diag[k, 0, 1] = c[k, 0]
                diag[k, 0, 2] = c[k, 1]
            if k >= 1:
                lower[k, 0, 1] = -c[k, 0]
                lower[k, 0, 2] = -c[k, 1]
        else:
            rhs[k, 0] = -T[k]
            diag[k, 0, 0] = 1.0
        if k + 1 > nfree:
            diag[k, 1, 1] = 1.0
            diag[k, 2, 2] = 1.0
            rhs[k, 1] = 0.0
            rhs[k, 2] = 0.0
            continue
        # motion rows of node i = k + 1
        i = k + 1
        fx = T[i] * c[i, 0] - T[k] * c[k, 0]
        fz = T[i] * c[i, 1] - T[k] * c[k, 1]
        rx = r[i, 0] - b[i, 0] - (G[i, 0, 0] * fx + G[i, 0, 1] * fz)
        rz = r[i, 1] - b[i, 1] - (G[i, 1, 0] * fx + G[i, 1, 1] * fz)
        res = max(res, (abs(rx) + abs(rz)) / L[k])
        rhs[k, 1] = -rx
        rhs[k, 2] = -rz
        # K = T_i P_i + T_k P_k (geometric stiffness at node i), P_j = (I - c c^T) / ell
        # (tension only: a compressive iterate would make the matrix indefinite and Newton wander)
        pk = max(T[k], 0.0) / ell[k]
        pi_ = max(T[i], 0.0) / ell[i]
        kk11, kk12, kk22 = pk * (1.0 - c[k, 0] ** 2), -pk * c[k, 0] * c[k, 1], pk * (1.0 - c[k, 1] ** 2)
        ki11, ki12, ki22 = pi_ * (1.0 - c[i, 0] ** 2), -pi_ * c[i, 0] * c[i, 1], pi_ * (1.0 - c[i, 1] ** 2)
        for a in range(2):
            ga0, ga1 = G[i, a, 0], G[i, a, 1]
            # d F / d T_k = +G c_k, d F / d T_i = -G c_i
            diag[k, 1 + a, 0] = ga0 * c[k, 0] + ga1 * c[k, 1]
            upper[k, 1 + a, 0] = -(ga0 * c[i, 0] + ga1 * c[i, 1])
            # d F / d r_i = I + G (K_k + K_i)
            diag[k, 1 + a, 1] = (1.0 if a == 0 else 0.0) + ga0 * (kk11 + ki11) + ga1 * (kk12 + ki12)
            diag[k, 1 + a, 2] = (1.0 if a == 1 else 0.0) + ga0 * (kk12 + ki12) + ga1 * (kk22 + ki22)
            # d F / d r_{i-1} = -G K_k, d F / d r_{i+1} = -G K_i
            if k >= 1:
                lower[k, 1 + a, 1] = -(ga0 * kk11 + ga1 * kk12)
                lower[k, 1 + a, 2] = -(ga0 * kk12 + ga1 * kk22)
            if i + 1 <= nfree:
                upper[k, 1 + a, 1] = -(ga0 * ki11 + ga1 * ki12)
                upper[k, 1 + a, 2] = -(ga0 * ki12 + ga1 * ki22)
    return res

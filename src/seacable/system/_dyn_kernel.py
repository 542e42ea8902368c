"""Compiled core of the coupled body-line dynamics: one Newton iteration on the line nodes and body DOFs.

The lines' nodes that are not held are the unknowns of the banded system of
:mod:`seacable.mooring.kernel` (``loads`` assembles their forces, masses and the Newton matrix
``cm M + cc C + K``). A node on a rigid body (a fairlead) is one of those nodes too, tied to its
body by a constraint ``x_j = r + R(theta) p_j``; a line end that may fail is tied the same way to
its anchor or fairlead, or, at a free point, to the point's node (``x_j = x_k``, a row of ``C`` with
``I`` at the end's node and ``-I`` at the point's). With ``mu_j`` the force the node passes to what it is tied to, one Newton
iteration solves the bordered system::

    [ J     C^T   0  ] [du]   [-R_u]        J: banded Newton matrix of the nodes
    [ C     0    -T  ] [mu] = [  0 ]        C: picks the tied nodes, T_j = [I, -skew(R p_j)]
    [ 0    -T^T   J_q] [dq]   [-R_q]        J_q: the bodies' own 6x6 Newton matrices

by its Schur complement: the band is factored once (``J = L U``, on its upper half when it is
symmetric, as the lines' tangents are), ``C J^-1 C^T`` comes from the short sweeps ``L^-1 e_k`` and
``U^-T e_k`` of the ``3 n_c`` tied rows (``n_c`` tied nodes; a few rows each when the node ends its
line's rows in the band, as a fairlead does), the small dense system in ``mu`` and ``dq`` is solved,
and one forward and one backward sweep give ``du``: about one band solve in all, linear in the number
of nodes. Tied nodes are then put back exactly on their body (``x_j = r + R p_j``), so the constraint
holds at every iterate. The first convergence check of a time step (where most steps stop) assembles
the residual only, not the Newton matrix; the criterion is the prescribed-motion model's.

Rotations are the body's (roll, pitch, yaw) with ``R = Rz(yaw) Ry(pitch) Rx(roll)``: the geometry
(points, centre of gravity and of buoyancy) is exact at any angle; the angular velocity is ``w = E
theta'`` (:func:`angular_map`), the body's equations are those of the rigid body in ``(a, dw/dt)`` with
its gyroscopic and centripetal terms (:func:`body_load`). The Newton step is solved in small rotation
vectors ``dphi`` (moments as they are, the tied nodes move by ``-skew(R p_j) dphi``, so ``T_j = [I, -skew(R
p_j)]``) and mapped to the angles by ``dtheta = E^-1 dphi`` (:func:`_angle_increment`, regularised at pitch
+-90 deg, where ``E`` is singular: a horizontal MoorDyn rod starts there); the convergence check is on the
angles' generalised forces ``E^T M``. The Newton matrix leaves out the change of ``E`` with the angles.

Charts: each body's rotation is ``R = R0 R(angles)`` with a base rotation ``R0`` (``frame``, F_SIZE numbers per
body: a flag, ``R0``, and the continuous global angles of ``R`` for the output). ``R0 = I`` until the body's
|pitch| passes ``CHART_LIMIT`` (1 rad) after a converged step; it is then re-charted (:func:`rechart`): ``R0
<- R0 R(angles)``, angles <- 0, rates and accelerations re-expressed with the angular velocity and
acceleration unchanged; and again after every later step (in the statics, whenever |pitch| passes the
limit), so that its Newmark step works on angles within one step's turn of 0 (incremental rotations);
its Newton matrix then also takes the velocity part of the angular acceleration (:func:`rate_tangent`). With ``R0``, ``w = R0 E angles'``, ``dphi = R0 E dangles``: every use of ``E`` is
``R0 E`` and every rotation ``R0 R(angles)`` (:func:`body_rotation`). So the angles never come near pitch
+-90 deg except within one step, and a body that never re-charts runs the same floating-point operations
as without charts.
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import njit
from ..mooring.kernel import (
    E_VDT,
    GRID_HEADER,
    _fluid,
    _force_tolerance,
    commit_viscoelastic,
    loads,
    predict_nodes,
)
from ._stat_kernel import _skew

# body parameter layout (one row per body in ``bpar``)
B_MASS, B_VOL, B_AWP, B_IXX, B_IYY, B_HASK = 0, 1, 2, 3, 4, 5
B_CG, B_CB, B_INERT, B_Q0, B_FEXT = 6, 9, 12, 15, 21
B_SIZE = 27


@njit(cache=True)
def rotation(roll, pitch, yaw, R):
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw),
                              math.sin(yaw))
    R[0, 0] = cy * cp
    R[0, 1] = cy * sp * sr - sy * cr
    R[0, 2] = cy * sp * cr + sy * sr
    R[1, 0] = sy * cp
    R[1, 1] = sy * sp * sr + cy * cr
    R[1, 2] = sy * sp * cr - cy * sr
    R[2, 0] = -sp
    R[2, 1] = cp * sr
    R[2, 2] = cp * cr


# a free body's chart (one row of ``frame`` per body): [0] 1 when its base rotation R0 is not the identity,
# [1:10] R0 row by row, [10:13] the continuous global (roll, pitch, yaw) of R0 R(angles) (see ``rechart``)
F_ON, F_R0, F_GLOB = 0, 1, 10
F_SIZE = 13
CHART_LIMIT = 1.0  # [rad] a body whose |pitch| exceeds this after a step is re-charted (angles back to 0)


@njit(cache=True)
def _premul(fr, a):
    """a <- R0 a for a vector (3,) or the columns of a (3, k) matrix, R0 = the chart ``fr``'s base rotation."""
    if a.ndim == 1:
        a0, a1, a2 = a[0], a[1], a[2]
        for r in range(3):
            a[r] = fr[F_R0 + 3 * r] * a0 + fr[F_R0 + 3 * r + 1] * a1 + fr[F_R0 + 3 * r + 2] * a2
    else:
        for c in range(a.shape[1]):
            a0, a1, a2 = a[0, c], a[1, c], a[2, c]
            for r in range(3):
                a[r, c] = fr[F_R0 + 3 * r] * a0 + fr[F_R0 + 3 * r + 1] * a1 + fr[F_R0 + 3 * r + 2] * a2


@njit(cache=True)
def _premul_t(fr, a):
    """a <- R0^T a for a vector (3,)."""
    a0, a1, a2 = a[0], a[1], a[2]
    for r in range(3):
        a[r] = fr[F_R0 + r] * a0 + fr[F_R0 + 3 + r] * a1 + fr[F_R0 + 6 + r] * a2


@njit(cache=True)
def body_rotation(q, fr, R):
    """The body's rotation ``R = R0 R(roll, pitch, yaw)`` (``R0`` its chart's base rotation, the identity until
    it is first re-charted: then exactly ``R(angles)``)."""
    rotation(q[3], q[4], q[5], R)
    if fr[F_ON] != 0.0:
        _premul(fr, R)


@njit(cache=True)
def _wrap_near(a, ref):
    """a + 2 pi k nearest to ``ref``."""
    return a + 2.0 * math.pi * round((ref - a) / (2.0 * math.pi))


@njit(cache=True)
def euler_near(R, ref, out):
    """out <- the (roll, pitch, yaw) of ``R = Rz Ry Rx`` nearest to ``ref``: of the two branches ``(r, p, y)``
    (pitch in [-pi/2, pi/2]) and ``(r + pi, pi - p, y + pi)``, each angle moved by whole turns towards
    ``ref``, the one nearer it. Followed step by step this keeps the angles continuous through pitch +-90
    deg (pitch then leaves [-pi/2, pi/2]); at that point itself only roll -+ yaw is defined."""
    p = -math.asin(max(-1.0, min(1.0, R[2, 0])))
    r = math.atan2(R[2, 1], R[2, 2])
    y = math.atan2(R[1, 0], R[0, 0])
    best = np.inf
    for k in range(2):
        a0 = _wrap_near(r + k * math.pi, ref[0])
        a1 = _wrap_near(p if k == 0 else math.pi - p, ref[1])
        a2 = _wrap_near(y + k * math.pi, ref[2])
        d = (a0 - ref[0]) ** 2 + (a1 - ref[1]) ** 2 + (a2 - ref[2]) ** 2
        if d < best:
            best = d
            out[0], out[1], out[2] = a0, a1, a2


@njit(cache=True)
def global_angles(q, fr, out):
    """out <- the body's global (roll, pitch, yaw) of ``R0 R(angles)``, continuous with ``fr``'s last ones
    (the angles themselves when the body was never re-charted)."""
    if fr[F_ON] == 0.0:
        out[0], out[1], out[2] = q[3], q[4], q[5]
        return
    R = np.empty((3, 3))
    body_rotation(q, fr, R)
    euler_near(R, fr[F_GLOB:F_GLOB + 3], out)


@njit(cache=True)
def rechart(q, qd, qdd, fr, limit):
    """Re-chart a body whose |pitch| exceeds ``limit`` [rad] (False otherwise, nothing changed): ``R0 <- R0
    R(angles)``, angles <- 0, and the rates re-expressed so that the angular velocity ``w = R0 E qd[3:]`` and
    acceleration ``alpha = R0 (E qdd[3:] + E' qd[3:])`` (global) are unchanged. With the angles 0, ``E = I`` in
    the new chart: ``qd[3:] = R0^T w`` and ``qdd[3:] = R0^T alpha - E'(0) qd[3:]``, ``E'(0) qd = (-yaw' pitch',
    roll' yaw', -roll' pitch')`` (:func:`angular_map` at zero angles). The global angles ``fr[10:13]`` are
    kept continuous."""
    if not abs(q[4]) > limit:
        return False
    E = np.empty((3, 3))
    ed = np.empty(3)
    angular_map(q, qd, E, ed, fr)
    w = np.empty(3)
    al = np.empty(3)
    for r in range(3):
        w[r] = E[r, 0] * qd[3] + E[r, 1] * qd[4] + E[r, 2] * qd[5]
        al[r] = E[r, 0] * qdd[3] + E[r, 1] * qdd[4] + E[r, 2] * qdd[5] + ed[r]
    g = np.empty(3)
    global_angles(q, fr, g)
    R = np.empty((3, 3))
    body_rotation(q, fr, R)
    for r in range(3):
        for c in range(3):
            fr[F_R0 + 3 * r + c] = R[r, c]
    fr[F_ON] = 1.0
    fr[F_GLOB:F_GLOB + 3] = g
    q[3], q[4], q[5] = 0.0, 0.0, 0.0
    _premul_t(fr, w)
    _premul_t(fr, al)
    dr, dp, dy = w[0], w[1], w[2]
    qd[3], qd[4], qd[5] = dr, dp, dy
    qdd[3], qdd[4], qdd[5] = al[0] + dy * dp, al[1] - dr * dy, al[2] + dr * dp
    return True


@njit(cache=True)
def track_frame(q, qd, qdd, fr, gq, limit):
    """After a step: the body's global angles into ``fr`` (``gq`` a work array), then :func:`rechart` past
    ``limit`` [rad]."""
    global_angles(q, fr, gq)
    fr[F_GLOB:F_GLOB + 3] = gq
    rechart(q, qd, qdd, fr, limit)


@njit(cache=True)
def _add_point_force(f6, arm, fx, fy, fz):
    """f6 += (F, arm x F)."""
    f6[0] += fx
    f6[1] += fy
    f6[2] += fz
    f6[3] += arm[1] * fz - arm[2] * fy
    f6[4] += arm[2] * fx - arm[0] * fz
    f6[5] += arm[0] * fy - arm[1] * fx


@njit(cache=True)
def _mv(R, v, out):
    """out = R v (3x3 times 3), without a BLAS call."""
    for r in range(3):
        out[r] = R[r, 0] * v[0] + R[r, 1] * v[1] + R[r, 2] * v[2]


@njit(cache=True)
def _rot6(R, A, out, transposed):
    """out = R6 A R6^T (``transposed``: R6^T A R6) for a 6x6 ``A`` and R6 = diag(R, R), without BLAS calls."""
    for bi in range(2):
        for bj in range(2):
            for r in range(3):
                for c in range(3):
                    s = 0.0
                    for k in range(3):
                        for l in range(3):
                            rk = R[k, r] if transposed else R[r, k]
                            cl = R[l, c] if transposed else R[c, l]
                            s += rk * A[3 * bi + k, 3 * bj + l] * cl
                    out[3 * bi + r, 3 * bj + c] = s


@njit(cache=True)
def _body_current(q, env, cur_depth, cur_speed, uc):
    """The current's velocity (3, global) at the body's reference point (at the surface when it is above)."""
    if cur_depth.size == 1 and cur_speed[0] == 0.0:
        uc[:] = 0.0  # still water
        return
    x = np.array([q[0], q[1], min(q[2], 0.0)])
    acc = np.empty(3)
    _fluid(x, 0.0, env, cur_depth, cur_speed, False, np.zeros(GRID_HEADER), uc, acc)


@njit(cache=True)
def angular_map(q, qd, E, ed, fr):
    """The angular velocity of the angles' rates, ``w = E(q) qd[3:]`` (global axes, ``R = R0 Rz(yaw) Ry(pitch)
    Rx(roll)``: ``w = R0 (roll' Rz Ry e_x + pitch' Rz e_y + yaw' e_z)``, ``R0`` the chart ``fr``'s base
    rotation), and ``ed = dE/dt qd[3:]``, so that the angular acceleration is ``E qdd[3:] + ed``."""
    sp, cp, sy, cy = math.sin(q[4]), math.cos(q[4]), math.sin(q[5]), math.cos(q[5])
    dr, dp, dy = qd[3], qd[4], qd[5]
    E[0, 0], E[0, 1], E[0, 2] = cy * cp, -sy, 0.0
    E[1, 0], E[1, 1], E[1, 2] = sy * cp, cy, 0.0
    E[2, 0], E[2, 1], E[2, 2] = -sp, 0.0, 1.0
    ed[0] = dr * (-sy * cp * dy - cy * sp * dp) - cy * dy * dp
    ed[1] = dr * (cy * cp * dy - sy * sp * dp) - sy * dy * dp
    ed[2] = -dr * cp * dp
    if fr[F_ON] != 0.0:
        _premul(fr, E)
        _premul(fr, ed)


@njit(cache=True)
def rate_tangent(q, qd, fr, P):
    """P <- ``d(E' qd[3:]) / d qd[3:] E^-1`` in the chart ``fr`` (``R0 G E^-1 R0^T``, ``G`` the derivative of
    :func:`angular_map`'s ``ed`` by the rates): the change of the angular acceleration's velocity part per
    small rotation rate, so that a rotation increment ``dphi`` changes the angular acceleration by ``c0 dphi
    + c1 P dphi`` (Newmark's ``c1 = gamma / (beta dt)``). Its size is ``|w|``; times the body's large inertia it
    outweighs ``c0`` times a rod's small spin inertia, and Newton converges only linearly without it."""
    sp, cp, sy, cy = math.sin(q[4]), math.cos(q[4]), math.sin(q[5]), math.cos(q[5])
    dr, dp, dy = qd[3], qd[4], qd[5]
    G = np.empty((3, 3))
    G[0, 0], G[1, 0], G[2, 0] = -sy * cp * dy - cy * sp * dp, cy * cp * dy - sy * sp * dp, -cp * dp
    G[0, 1], G[1, 1], G[2, 1] = -dr * cy * sp - cy * dy, -dr * sy * sp - sy * dy, -dr * cp
    G[0, 2], G[1, 2], G[2, 2] = -dr * sy * cp - cy * dp, dr * cy * cp - sy * dp, 0.0
    # E^-1 = B^-1 Rz^T, B = [[cp, 0, 0], [0, 1, 0], [-sp, 0, 1]]
    ic = cp / (cp * cp + 1e-12)
    Ei = np.empty((3, 3))
    Ei[0, 0], Ei[0, 1], Ei[0, 2] = ic * cy, ic * sy, 0.0
    Ei[1, 0], Ei[1, 1], Ei[1, 2] = -sy, cy, 0.0
    Ei[2, 0], Ei[2, 1], Ei[2, 2] = sp * ic * cy, sp * ic * sy, 1.0
    for r in range(3):
        for c in range(3):
            P[r, c] = G[r, 0] * Ei[0, c] + G[r, 1] * Ei[1, c] + G[r, 2] * Ei[2, c]
    if fr[F_ON] != 0.0:
        _premul(fr, P)  # R0 P
        for r in range(3):  # (R0 P) R0^T
            a0, a1, a2 = P[r, 0], P[r, 1], P[r, 2]
            for c in range(3):
                P[r, c] = a0 * fr[F_R0 + 3 * c] + a1 * fr[F_R0 + 3 * c + 1] + a2 * fr[F_R0 + 3 * c + 2]


@njit(cache=True)
def body_load(q, qd, uc, t, par, khs, add, lin, quad, ext_t, ext_f, ext_n, rho, g, f6, M6, fr):
    """The body's own forces ``f6`` (weight, buoyancy, hydrostatics, damping, external, and minus the rigid
    body's centripetal and gyroscopic terms; global axes, moments about the reference point) and its mass
    matrix ``M6`` (rigid body about the reference point plus added mass, global axes), at the velocity
    ``u = (v, w)`` (reference point, angular velocity; global axes), so that ``M6 (a, alpha) = f6``. The
    quadratic damping (drag) acts on the velocity relative to the current ``uc`` (3, global) at the body,
    the linear damping on the body's own.

    The rigid body's inertia forces about the reference point at ``c`` from the CG are ``M6 (a, alpha)`` and
    ``(m w x (w x c), w x (I_r w))``, ``I_r = I_g + m (|c|^2 - c c^T)`` (the moment of ``m c x (w x (w x c))``
    is ``w x (m (|c|^2 - c c^T) w)``); those of the added mass in a turning frame are left out. The rotation
    is ``R0 R(angles)`` of the body's chart ``fr``; a user's hydrostatic matrix acts on the global angles.
    """
    wk = np.empty(96)  # one allocation for the small work arrays
    R = wk[0:9].reshape((3, 3))
    body_rotation(q, fr, R)
    m = par[B_MASS]
    c = wk[9:12]
    cb = wk[12:15]
    _mv(R, par[B_CG:B_CG + 3], c)
    _mv(R, par[B_CB:B_CB + 3], cb)
    # rigid-body mass matrix about the reference point (I_g = R diag(I) R^T), plus the added mass R6 A R6^T
    cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2]
    Ma = wk[15:51].reshape((6, 6))
    _rot6(R, add, Ma, False)
    M6[:] = Ma
    for r in range(3):
        M6[r, r] += m
        for k in range(3):
            ig = R[r, 0] * par[B_INERT] * R[k, 0] + R[r, 1] * par[B_INERT + 1] * R[k, 1] + R[r, 2] * par[B_INERT + 2] * R[k, 2]
            M6[3 + r, 3 + k] += ig + m * ((cc if r == k else 0.0) - c[r] * c[k])
    # the gyroscopic moment w x (I_r w) and the centripetal force m w x (w x c), with I_r = M6's rigid part
    w = qd[3:]
    h = wk[51:54]
    h[:] = 0.0
    for r in range(3):
        for k in range(3):
            h[r] += (M6[3 + r, 3 + k] - Ma[3 + r, 3 + k]) * w[k]
    wc = w[0] * c[0] + w[1] * c[1] + w[2] * c[2]
    ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2]
    gyro = wk[54:60]
    for r in range(3):
        gyro[r] = m * (w[r] * wc - c[r] * ww)
    gyro[3] = w[1] * h[2] - w[2] * h[1]
    gyro[4] = w[2] * h[0] - w[0] * h[2]
    gyro[5] = w[0] * h[1] - w[1] * h[0]
    # the coupling m skew(c) (moment rows) and -m skew(c) (force rows)
    for r in range(3):
        for k in range(3):
            # skew(c)[r, k] = -eps_rkl c_l
            s = 0.0 if r == k else (c[3 - r - k] if (k - r) % 3 == 2 else -c[3 - r - k])
            M6[3 + r, k] += m * s
            M6[r, 3 + k] -= m * s
    for k in range(6):
        f6[k] = -gyro[k]
    q0 = par[B_Q0:B_Q0 + 6]
    if par[B_HASK] > 0.0:
        # the user's hydrostatic matrix: weight and buoyancy as at the reference pose, restoring from K
        R0 = wk[60:69].reshape((3, 3))
        rotation(q0[3], q0[4], q0[5], R0)
        _mv(R0, par[B_CG:B_CG + 3], c)
        _mv(R0, par[B_CB:B_CB + 3], cb)
        _add_point_force(f6, c, 0.0, 0.0, -m * g)
        _add_point_force(f6, cb, 0.0, 0.0, rho * g * par[B_VOL])
        qg = wk[87:93]  # the pose with the global angles (the chart's own when never re-charted)
        qg[:3] = q[:3]
        global_angles(q, fr, qg[3:])
        for r in range(6):
            for k in range(6):
                f6[r] -= khs[r, k] * (qg[k] - q0[k])
    else:
        _add_point_force(f6, c, 0.0, 0.0, -m * g)
        # buoyancy of the volume at the given pose, and the waterplane's heave restoring at the reference point
        _add_point_force(f6, cb, 0.0, 0.0, rho * g * par[B_VOL])
        f6[2] -= rho * g * par[B_AWP] * (q[2] - q0[2])
        # the waterplane's moment rho g (I_xx a_y, -I_yy a_x, 0), a = R e_z (-rho g I phi for small roll or
        # pitch), as the system statics
        f6[3] += rho * g * par[B_IXX] * R[1, 2]
        f6[4] -= rho * g * par[B_IYY] * R[0, 2]
    for k in range(6):
        f6[k] += par[B_FEXT + k]
    if ext_n > 0:
        for k in range(6):
            f6[k] += np.interp(t, ext_t[:ext_n], ext_f[:ext_n, k])
    # damping, in body axes: vb = R6^T qd, vr = R6^T (qd - uc), f6 -= R6 (B1 vb + B2 |vr| vr)
    vb = wk[69:75]
    fb = wk[75:81]
    vr = wk[81:87]
    _mv(R.T, qd[3:], vb[3:])
    _mv(R.T, qd[:3] - uc, vr[:3])
    vr[3:] = vb[3:]
    _mv(R.T, qd[:3], vb[:3])
    for k in range(6):
        s = 0.0
        for j in range(6):
            s += lin[k, j] * vb[j] + quad[k, j] * abs(vr[j]) * vr[j]
        fb[k] = s
    _mv(R, fb[:3], vb[:3])
    _mv(R, fb[3:], vb[3:])
    for k in range(6):
        f6[k] -= vb[k]


@njit(cache=True)
def body_tangent(q, qd, uc, par, khs, lin, quad, rho, g, K, C, fr):
    """The Newton matrices of the body's own forces: ``K = -df6/dq`` and ``C = -df6/dqd`` (rotation
    increments as small rotation vectors; the damping's turning with the body and the mass matrix's
    change with the angles left out, which only slows Newton, not the answer).

    Weight ``F`` at the turning arm ``c``: ``-skew(F) skew(c)`` (MoorPy's Body.getStiffnessA); buoyancy
    the same at the centre of buoyancy; the waterplane's heave and roll and pitch terms; or the user's
    matrix.
    """
    wk = np.empty(96)  # one allocation for the small work arrays
    R = wk[0:9].reshape((3, 3))
    body_rotation(q, fr, R)
    K[:] = 0.0
    m = par[B_MASS]
    if par[B_HASK] > 0.0:
        K[:] = khs
    else:
        # -skew(F) skew(c) for a vertical force F = (0, 0, f) at c: [[f c_z, 0, -f c_x], [0, f c_z, -f c_y], [0, 0, 0]]
        for off, f in ((B_CG, -m * g), (B_CB, rho * g * par[B_VOL])):
            cx = R[0, 0] * par[off] + R[0, 1] * par[off + 1] + R[0, 2] * par[off + 2]
            cy = R[1, 0] * par[off] + R[1, 1] * par[off + 1] + R[1, 2] * par[off + 2]
            cz = R[2, 0] * par[off] + R[2, 1] * par[off + 1] + R[2, 2] * par[off + 2]
            K[3, 3] += f * cz
            K[4, 4] += f * cz
            K[3, 5] -= f * cx
            K[4, 5] -= f * cy
        K[2, 2] += rho * g * par[B_AWP]
        # d a / d phi = -skew(a) for a = R e_z
        ax, ay, az = R[0, 2], R[1, 2], R[2, 2]
        kx, ky = rho * g * par[B_IXX], rho * g * par[B_IYY]
        K[3, 3] += kx * az
        K[3, 5] -= kx * ax
        K[4, 4] += ky * az
        K[4, 5] -= ky * ay
    # damping: R6 (B1 + 2 B2 |vr|) R6^T, vr relative to the current
    vb = wk[9:15]
    _mv(R.T, qd[:3] - uc, vb[:3])
    _mv(R.T, qd[3:], vb[3:])
    D = wk[15:51].reshape((6, 6))
    for k in range(6):
        for j in range(6):
            D[k, j] = lin[k, j] + 2.0 * quad[k, j] * abs(vb[j])
    _rot6(R, D, C, False)
    # the velocity tangent of the gyroscopic and centripetal terms: d(w x I_r w)/dw = skew(w) I_r - skew(I_r w),
    # d(m w x (w x c))/dw = m ((w.c) I + w c^T - 2 c w^T)
    Ir = wk[51:60].reshape((3, 3))
    c = wk[60:63]
    _mv(R, par[B_CG:B_CG + 3], c)
    cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2]
    for r in range(3):
        for k in range(3):
            Ir[r, k] = (R[r, 0] * par[B_INERT] * R[k, 0] + R[r, 1] * par[B_INERT + 1] * R[k, 1]
                        + R[r, 2] * par[B_INERT + 2] * R[k, 2] + m * ((cc if r == k else 0.0) - c[r] * c[k]))
    w = qd[3:]
    h = wk[63:66]
    _mv(Ir, w, h)
    W = wk[66:75].reshape((3, 3))
    H = wk[75:84].reshape((3, 3))
    _skew(w, W)
    _skew(h, H)
    wc = w[0] * c[0] + w[1] * c[1] + w[2] * c[2]
    for r in range(3):
        for k in range(3):
            s = -H[r, k]
            for l in range(3):
                s += W[r, l] * Ir[l, k]
            C[3 + r, 3 + k] += s
            C[r, 3 + k] += m * ((wc if r == k else 0.0) + w[r] * c[k] - 2.0 * c[r] * w[k])


@njit(cache=True)
def dense_solve(A, b):
    """Solve the small dense system ``A x = b`` in place (Gaussian elimination, partial pivoting); x in b.
    False when singular."""
    m = b.size
    for k in range(m):
        p = k
        big = abs(A[k, k])
        for i in range(k + 1, m):
            if abs(A[i, k]) > big:
                big = abs(A[i, k])
                p = i
        if big == 0.0 or not math.isfinite(big):
            return False
        if p != k:
            for c in range(m):
                A[k, c], A[p, c] = A[p, c], A[k, c]
            b[k], b[p] = b[p], b[k]
        for i in range(k + 1, m):
            f = A[i, k] / A[k, k]
            if f != 0.0:
                for c in range(k + 1, m):
                    A[i, c] -= f * A[k, c]
                b[i] -= f * b[k]
    for k in range(m - 1, -1, -1):
        s = b[k]
        for c in range(k + 1, m):
            s -= A[k, c] * b[c]
        b[k] = s / A[k, k]
    return True


@njit(cache=True)
def band_factor(band, bw):
    """LU factor of a banded matrix in place (no pivoting): the multipliers L below the diagonal, U on and
    above. Returns 0 on a zero pivot, 1, or 2 when the matrix is symmetric: then U = D L^T and only the upper
    band is eliminated (the multipliers written from it), half the work of the general case.
    """
    n = band.shape[0]
    sym = True
    for i in range(n):
        for j in range(i + 1, min(n, i + bw + 1)):
            if band[i, bw + j - i] != band[j, bw + i - j]:
                sym = False
                break
        if not sym:
            break
    for k in range(n):
        piv = band[k, bw]
        if piv == 0.0 or not math.isfinite(piv):
            return 0
        top = min(n, k + bw + 1)
        inv = 1.0 / piv
        if sym:
            for i in range(k + 1, top):
                f = band[k, bw + i - k] * inv
                band[i, bw + k - i] = f
                if f != 0.0:
                    for j in range(i, top):
                        band[i, bw + j - i] -= f * band[k, bw + j - k]
        else:
            for i in range(k + 1, top):
                f = band[i, bw + k - i] * inv
                band[i, bw + k - i] = f
                if f != 0.0:
                    for j in range(k + 1, top):
                        band[i, bw + j - i] -= f * band[k, bw + j - k]
    return 2 if sym else 1


@njit(cache=True)
def band_forward(band, bw, x):
    """x <- L^-1 x with the unit lower factor of :func:`band_factor`."""
    n = x.size
    for k in range(n):
        xk = x[k]
        if xk != 0.0:
            for i in range(k + 1, min(n, k + bw + 1)):
                x[i] -= band[i, bw + k - i] * xk


@njit(cache=True)
def band_backward(band, bw, x):
    """x <- U^-1 x with the upper factor of :func:`band_factor`."""
    n = x.size
    for k in range(n - 1, -1, -1):
        s = x[k]
        for j in range(k + 1, min(n, k + bw + 1)):
            s -= band[k, bw + j - k] * x[j]
        x[k] = s / band[k, bw]


@njit(cache=True)
def unit_column(band, bw, x, first, upper):
    """The part of ``L^-1 e_first`` (``upper``: ``U^-T e_first``) that can be nonzero, in ``x[first:last + 1]``;
    returns ``last``. ``x`` need not be zero on entry: the sweep clears the rows it reaches, and stops where the
    fill ends (``bw`` rows without a nonzero), so the column of a node at the end of its line's rows in
    the band costs a few rows, not the line.
    """
    n = x.size
    x[first] = 1.0
    hi = first
    last = first
    k = first
    while k < n and k <= last + bw:
        xk = x[k]
        if upper:
            xk /= band[k, bw]
            x[k] = xk
        if xk != 0.0:
            last = k
            top = min(n - 1, k + bw)
            for i in range(hi + 1, top + 1):
                x[i] = 0.0
            hi = max(hi, top)
            for i in range(k + 1, top + 1):
                x[i] -= (band[k, bw + i - k] if upper else band[i, bw + k - i]) * xk
        k += 1
    return last


@njit(cache=True)
def place_tied(X, q, con_node, con_body, con_arm, con_target, con_active, frame):
    """Put each tied node where it is tied: on its body (r + R p, ``R = R0 R(angles)`` of its chart
    ``frame[b]``), at its target, or on its free node (``con_body`` = -2 - node)."""
    R = np.empty((3, 3))
    for j in range(con_node.size):
        if con_active[j] == 0:
            continue
        i = con_node[j]
        b = con_body[j]
        if b >= 0:
            body_rotation(q[b], frame[b], R)
            for r in range(3):
                X[i, r] = q[b, r] + R[r, 0] * con_arm[j, 0] + R[r, 1] * con_arm[j, 1] + R[r, 2] * con_arm[j, 2]
        elif b <= -2:
            for r in range(3):
                X[i, r] = X[-2 - b, r]
        else:
            for r in range(3):
                X[i, r] = con_target[j, r]


@njit(cache=True)
def _angle_rows(E, m):
    """m <- E^T m: a moment as the generalised force of the angles."""
    a = E[0, 0] * m[0] + E[1, 0] * m[1] + E[2, 0] * m[2]
    b = E[0, 1] * m[0] + E[1, 1] * m[1] + E[2, 1] * m[2]
    c = E[0, 2] * m[0] + E[1, 2] * m[1] + E[2, 2] * m[2]
    m[0], m[1], m[2] = a, b, c


@njit(cache=True)
def _angle_increment(q, d, fr):
    """d <- the angles' increment of the small rotation vector ``d`` (global axes): ``E^-1 R0^T d`` (``R0`` the
    chart ``fr``'s base rotation) with ``E = Rz(yaw) B``, ``B = [[cos p, 0, 0], [0, 1, 0], [-sin p, 0, 1]]``. At pitch +-90 deg (a horizontal rod, gimbal lock) ``E``
    is singular: roll and yaw turn about the same axis and the rotation about ``Rz e_x`` has no angle rate; the
    roll increment is then regularised to ``cos p v_x / (cos^2 p + 1e-12)`` (relative change < 1e-8 when
    ``|cos p| > 0.01``), so that the Newton step stays finite and the yaw takes the turn about z. A body is
    re-charted (:func:`rechart`) before its pitch comes near +-90 deg, unless a single step takes it there."""
    if fr[F_ON] != 0.0:
        _premul_t(fr, d)
    sp, cp, sy, cy = math.sin(q[4]), math.cos(q[4]), math.sin(q[5]), math.cos(q[5])
    vx = cy * d[0] + sy * d[1]
    vy = -sy * d[0] + cy * d[1]
    vz = d[2]
    roll = cp * vx / (cp * cp + 1e-12)
    d[0], d[1], d[2] = roll, vy, vz + sp * roll


@njit(cache=True)
def iterate(X, V, A, q, qd, qdd, t, cm, cmb, cc, dynamic, check, jac, args, weight, fidx, nfree, bw, env, cur_depth, cur_speed,
            with_waves, node_fext, con_node, con_body, con_arm, con_target, con_active, bpar, bkhs, badd, blin,
            bquad, ext_t, ext_f, ext_n, tol, F, M, tension, band, du, dq, out, Yt, tied, frame, spin):
    """Assemble at the current state and solve one Newton correction ``du`` (3 per band node) and ``dq``
    (6 per body). Returns False when the matrix is singular. ``jac`` False: the residual only (``out``), no
    Newton matrix and no correction.

    ``cm`` multiplies the nodes' masses and ``cmb`` the bodies' in the Newton matrix (the same in a time
    step; statics scales the bodies' pseudo-inertia down to a node's). ``out`` receives (residual of the free nodes and bodies [N], absolute tolerance [N]). Bodies' moments
    count in the residual divided by the body's size (their largest point arm, at least 1 m). ``Yt``
    (12 n_c, 3 n_free) and ``tied`` (n,) are work arrays. ``frame`` (nb, F_SIZE): each body's chart (its
    rotation is ``R0 R(angles)``). ``spin`` (nb, 3): in statics (``dynamic`` False), a body-axes unit axis
    about which turning the body moves none of its points, centres of gravity and buoyancy nor its
    hydrostatics (a rod's own axis; zeros when none): that part of the rotation step is left out, since it
    has no stiffness and the Newton matrix's unsymmetric turning terms would give it an arbitrary size.
    """
    (elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, pmass, padd, pvol, pcda, bedc, buoy, pbuoy,
     ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco) = args
    n = X.shape[0]
    nd = 3 * nfree
    nb = q.shape[0]
    rho, g = env[0], env[1]
    bnd = band if jac else band[:0]  # no rows: loads skips the Newton matrix
    bnd[:] = 0.0
    loads(X, V, t, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda, bedc,
          buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth, cur_speed,
          with_waves, np.zeros(GRID_HEADER), F, M, tension, bnd, bw, cm, cc)  # no irregular sea
    for i in range(n):
        for r in range(3):
            F[i, r] += node_fext[i, r]
    Ru = du  # the residual of the nodes, then the correction in place
    for i in range(n):
        f = fidx[i]
        if f < 0:
            continue
        for r in range(3):
            v = -F[i, r]
            if dynamic:
                for c in range(3):
                    v += M[i, r, c] * A[i, c]
            Ru[3 * f + r] = v
    tied[:] = False
    nca = 0
    for j in range(con_node.size):
        if con_active[j]:
            tied[con_node[j]] = True
            nca += 1
    # a node tied to a free node passes its net force to it: the pair's residual is the sum (added to the
    # free node's for the check only)
    npart = 0
    for sign in (1.0, -1.0):
        for j in range(con_node.size):
            if con_active[j] and con_body[j] <= -2:
                fs, fp = fidx[con_node[j]], fidx[-2 - con_body[j]]
                npart += 1
                for r in range(3):
                    Ru[3 * fp + r] += sign * Ru[3 * fs + r]
        if sign > 0:
            res = 0.0
            for i in range(n):
                f = fidx[i]
                if f >= 0 and not tied[i]:
                    for r in range(3):
                        res = max(res, abs(Ru[3 * f + r]))
    npart //= 2
    scale = 0.0  # not checked: not needed
    if check:
        scale = _force_tolerance(tol, weight, tension, F, M, A, X, fidx, EA, bedc, env, cm if dynamic else 0.0)
    # bodies: own residual R_q = M6 (a, alpha) - f6, residual R_q - sum T^T mu (mu = the tied node's net force
    # -Ru), Newton matrix; their moment rows are then those of the angles (E^T times the moments, with w = E
    # qd[3:], the virtual rotation E dq[3:])
    nwk = 6 * nb + 36 * nb * nb
    wk = np.zeros(2 * nwk + 45 * nb + 3 * con_node.size + 153)  # one allocation for the work arrays
    Rq = wk[0:6 * nb]
    Jq = wk[6 * nb:nwk].reshape((6 * nb, 6 * nb))
    Rr = wk[nwk:nwk + 6 * nb]
    o = 2 * nwk
    f6 = wk[o:o + 6]
    M6 = wk[o + 6:o + 42].reshape((6, 6))
    R = wk[o + 42:o + 51].reshape((3, 3))
    S2 = wk[o + 60:o + 69].reshape((3, 3))
    Kb = wk[o + 69:o + 105].reshape((6, 6))
    Cb = wk[o + 105:o + 141].reshape((6, 6))
    arm = wk[o + 141:o + 144]
    acc = wk[o + 144:o + 150]
    ed = wk[o + 150:o + 153]
    o += 153
    Eb = wk[o:o + 9 * nb].reshape((nb, 3, 3))
    ub = wk[o + 9 * nb:o + 15 * nb].reshape((nb, 6))
    ucb = wk[o + 15 * nb:o + 18 * nb].reshape((nb, 3))
    size = wk[o + 18 * nb:o + 19 * nb]
    size[:] = 1.0
    arms = wk[o + 19 * nb:o + 19 * nb + 3 * con_node.size].reshape((con_node.size, 3))
    for j in range(con_node.size):
        b = con_body[j]
        if b >= 0:
            size[b] = max(size[b], math.sqrt(con_arm[j, 0] ** 2 + con_arm[j, 1] ** 2 + con_arm[j, 2] ** 2))
    for b in range(nb):
        par = bpar[b]
        angular_map(q[b], qd[b], Eb[b], ed, frame[b])
        for r in range(3):
            ub[b, r] = qd[b, r]
            ub[b, 3 + r] = Eb[b, r, 0] * qd[b, 3] + Eb[b, r, 1] * qd[b, 4] + Eb[b, r, 2] * qd[b, 5]
            acc[r] = qdd[b, r]
            acc[3 + r] = Eb[b, r, 0] * qdd[b, 3] + Eb[b, r, 1] * qdd[b, 4] + Eb[b, r, 2] * qdd[b, 5] + ed[r]
        _body_current(q[b], env, cur_depth, cur_speed, ucb[b])
        body_load(q[b], ub[b], ucb[b], t, par, bkhs[b], badd[b], blin[b], bquad[b], ext_t[b], ext_f[b], ext_n[b], rho, g,
                  f6, M6, frame[b])
        for k in range(6):
            v = -f6[k]
            if dynamic:
                for c in range(6):
                    v += M6[k, c] * acc[c]
            Rq[6 * b + k] = v
            for c in range(6):
                Jq[6 * b + k, 6 * b + c] += cmb * M6[k, c]
        if dynamic and frame[b, F_ON] != 0.0:
            # a re-charted body (one that turns a lot): the velocity part of its angular acceleration in the
            # Newton matrix too (left out for the others, whose results stay those without charts)
            P = S2
            rate_tangent(q[b], qd[b], frame[b], P)
            for k in range(6):
                for c in range(3):
                    Jq[6 * b + k, 6 * b + 3 + c] += cc * (M6[k, 3] * P[0, c] + M6[k, 4] * P[1, c] + M6[k, 5] * P[2, c])
        if check:
            scale = max(scale, tol * max(par[B_MASS] * g, rho * g * par[B_VOL]))
    Rr[:] = Rq
    for j in range(con_node.size):
        b = con_body[j]
        if con_active[j] == 0 or b < 0:
            continue
        i = con_node[j]
        f = fidx[i]
        body_rotation(q[b], frame[b], R)
        _mv(R, con_arm[j], arm)
        arms[j] = arm
        m0, m1, m2 = -Ru[3 * f], -Ru[3 * f + 1], -Ru[3 * f + 2]
        # the residual of the body: R_q - T^T mu, force mu and moment arm x mu
        Rr[6 * b + 0] -= m0
        Rr[6 * b + 1] -= m1
        Rr[6 * b + 2] -= m2
        Rr[6 * b + 3] -= arm[1] * m2 - arm[2] * m1
        Rr[6 * b + 4] -= arm[2] * m0 - arm[0] * m2
        Rr[6 * b + 5] -= arm[0] * m1 - arm[1] * m0
    for b in range(nb):
        # the check on the angles' generalised forces E^T M; the Newton step itself is solved in rotation
        # vectors (moments as they are) and mapped to the angles after (see _angle_increment)
        _angle_rows(Eb[b], Rr[6 * b + 3:6 * b + 6])
        for k in range(6):
            res = max(res, abs(Rr[6 * b + k]) / (size[b] if k >= 3 else 1.0))
    out[0] = res
    out[1] = scale
    if not jac or (check and res <= scale):
        return True  # converged: no correction needed
    # the bodies' Newton matrices: their own forces' tangents, and the tied nodes' forces turning with them
    for b in range(nb):
        body_tangent(q[b], ub[b], ucb[b], bpar[b], bkhs[b], blin[b], bquad[b], rho, g, Kb, Cb, frame[b])
        for k in range(6):
            for c in range(6):
                Jq[6 * b + k, 6 * b + c] += Kb[k, c] + (cc * Cb[k, c] if dynamic else 0.0)
    nc3 = 3 * nca
    nt3 = nc3 + 3 * npart  # the rows the constraints touch: the tied nodes', then their free nodes'
    rows = np.empty(nt3, np.int64)
    prow = np.full(nc3, -1, np.int64)  # the row in ``rows`` of a tied row's free node
    kp = nc3
    k = 0
    for j in range(con_node.size):
        if con_active[j] == 0:
            continue
        f = fidx[con_node[j]]
        b = con_body[j]
        if b >= 0:
            arm = arms[j]
            # the moment arm turns with the body: d(-arm x mu)/dphi = -skew(mu) skew(arm) = arm mu^T - (mu.arm) I,
            # mu = -Ru
            ma = 0.0
            for r in range(3):
                ma -= Ru[3 * f + r] * arm[r]
            for r in range(3):
                Jq[6 * b + 3 + r, 6 * b + 3 + r] += ma
                for c in range(3):
                    Jq[6 * b + 3 + r, 6 * b + 3 + c] += arm[r] * Ru[3 * f + c]
        if b <= -2:
            for r in range(3):
                rows[kp] = 3 * fidx[-2 - b] + r
                prow[k + r] = kp
                kp += 1
        for r in range(3):
            rows[k] = 3 * f + r
            k += 1
    # Schur complement of the band J = L U: z0 = L^-1 (-Ru), v_k = L^-1 e_k and w_k = U^-T e_k (w_k = D^-1 v_k
    # when J is symmetric) for the touched rows k, so that (P J^-1 P^T)_ik = w_i . v_k and P J^-1 (-Ru) = w_i .
    # z0, and C = D P with D +1 at a tied row and -1 at its free node's row; each column is short when its node
    # ends its rows in the band (a fairlead at the end of its line)
    kind = band_factor(band, bw)
    if kind == 0:
        return False
    for a in range(nd):
        Ru[a] = -Ru[a]
    z0 = Ru
    band_forward(band, bw, z0)
    last = np.empty(2 * nt3, np.int64)
    for k in range(nt3):
        last[k] = unit_column(band, bw, Yt[k], rows[k], False)
        if kind == 1:
            last[nt3 + k] = unit_column(band, bw, Yt[nt3 + k], rows[k], True)
        else:
            for a in range(rows[k], last[k] + 1):
                Yt[nt3 + k, a] = Yt[k, a] / band[a, bw]
            last[nt3 + k] = last[k]
    m = nc3 + 6 * nb
    Sm = np.zeros((m, m))
    rhs = np.zeros(m)
    for i in range(nt3):
        w = Yt[nt3 + i]
        s = 0.0
        for a in range(rows[i], last[nt3 + i] + 1):
            s += w[a] * z0[a]
        ri = i if i < nc3 else -1
        if i >= nc3:  # a free node's row: into the rows of the tied rows it belongs to, with -1
            for k in range(nc3):
                if prow[k] == i:
                    ri = k
        sgn_i = 1.0 if i < nc3 else -1.0
        rhs[ri] += sgn_i * s
        for c in range(nt3):
            v = Yt[c]
            s = 0.0
            for a in range(max(rows[i], rows[c]), min(last[nt3 + i], last[c]) + 1):
                s += w[a] * v[a]
            rc = c if c < nc3 else -1
            if c >= nc3:
                for k in range(nc3):
                    if prow[k] == c:
                        rc = k
            Sm[ri, rc] += sgn_i * (1.0 if c < nc3 else -1.0) * s
    # S mu + T dq = C y0 and -T^T mu + Jq dq = -Rq, T = [I, -skew(arm)], dq[3:] a rotation vector
    k = 0
    for j in range(con_node.size):
        if con_active[j] == 0:
            continue
        b = con_body[j]
        if b >= 0:
            _skew(arms[j], S2)
            col = nc3 + 6 * b
            for r in range(3):
                row = k + r
                Sm[row, col + r] += 1.0
                Sm[col + r, row] -= 1.0
                for c in range(3):
                    Sm[row, col + 3 + c] -= S2[r, c]
                    Sm[col + 3 + c, row] += S2[r, c]
        k += 3
    for a in range(6 * nb):
        rhs[nc3 + a] = -Rq[a]
        for c in range(6 * nb):
            Sm[nc3 + a, nc3 + c] += Jq[a, c]
    if not dense_solve(Sm, rhs):
        return False
    # du = U^-1 (z0 - sum_k (v_k - v_pk) mu_k)
    for c in range(nt3):
        v = Yt[c]
        if c < nc3:
            mu = rhs[c]
        else:
            for k in range(nc3):
                if prow[k] == c:
                    mu = -rhs[k]
        for a in range(rows[c], last[c] + 1):
            du[a] -= v[a] * mu
    band_backward(band, bw, du)
    for a in range(6 * nb):
        dq[a] = rhs[nc3 + a]
    for b in range(nb):
        d = dq[6 * b + 3:6 * b + 6]
        if not dynamic and (spin[b, 0] != 0.0 or spin[b, 1] != 0.0 or spin[b, 2] != 0.0):
            body_rotation(q[b], frame[b], R)
            _mv(R, spin[b], arm)  # the free axis, global
            s = d[0] * arm[0] + d[1] * arm[1] + d[2] * arm[2]
            for r in range(3):
                d[r] -= s * arm[r]
        _angle_increment(q[b], d, frame[b])
    return True


@njit(cache=True)
def _apply(X, q, du, dq, fidx, s):
    for i in range(X.shape[0]):
        f = fidx[i]
        if f >= 0:
            for r in range(3):
                X[i, r] += s * du[3 * f + r]
    for b in range(q.shape[0]):
        for k in range(6):
            q[b, k] += s * dq[6 * b + k]


@njit(cache=True)
def coupled_steps(X, V, A, q, qd, qdd, t0, dt, px, pv, pa, channel, args, weight, fidx, nfree, bw, env, cur_depth,
                  cur_speed, with_waves, node_fext, con_node, con_body, con_arm, con_target, con_active, con_chan,
                  fail_time, fail_tension, fail_elem, fail_at, bpar, bkhs, badd, blin, bquad, ext_t, ext_f, ext_n,
                  beta, gamma, tol, max_iter, F, M, tension, stats, frame):
    """Advance ``px.shape[0]`` Newmark steps (average acceleration) of the lines and bodies together.

    ``px/pv/pa[k, channel]`` are the prescribed positions, velocities and accelerations at the end of
    step k. After each step a tied line end whose failure time has come, or whose end element's
    tension reached its failure tension, is released (``con_active`` 0, ``fail_at`` the time). Returns
    the number of steps completed; a step whose Newton iteration fails leaves the state at its start.
    ``stats`` receives (iterations, last residual, absolute force tolerance [N]). After each converged step a
    body whose |pitch| exceeds ``CHART_LIMIT``, or that was re-charted before, is re-charted (:func:`rechart`;
    ``frame`` is updated in place, with the continuous global angles of every re-charted body).
    """
    n = X.shape[0]
    nb = q.shape[0]
    nd = 3 * nfree
    band = np.zeros((nd, 2 * bw + 1))
    du = np.zeros(nd)
    dq = np.zeros(6 * nb)
    Du = np.zeros(nd)
    Dq = np.zeros(6 * nb)
    out = np.zeros(2)
    Yt = np.zeros((12 * con_node.size, nd))
    tied = np.zeros(n, np.bool_)
    Xn, Vn, An = np.empty_like(X), np.empty_like(V), np.empty_like(A)
    qn, qdn, qddn = np.empty_like(q), np.empty_like(qd), np.empty_like(qdd)
    c0 = 1.0 / (beta * dt * dt)
    c1 = gamma / (beta * dt)
    spin = np.zeros((nb, 3))  # dynamics: a free spin keeps its (small) inertia
    gq = np.empty(3)
    env = env.copy()
    env[E_VDT] = dt  # viscoelastic lines: the slow stretch advances over the step
    for step in range(px.shape[0]):
        Xn[:] = X
        Vn[:] = V
        An[:] = A
        qn[:] = q
        qdn[:] = qd
        qddn[:] = qdd
        t = t0 + (step + 1) * dt
        predict_nodes(X, V, A, Xn, Vn, An, px, pv, pa, step, channel, fidx, dt)
        for j in range(con_node.size):
            if con_chan[j] >= 0:
                for r in range(3):
                    con_target[j, r] = px[step, con_chan[j], r]
        for b in range(nb):
            for k in range(6):
                q[b, k] = qn[b, k] + dt * qdn[b, k] + 0.5 * dt * dt * qddn[b, k]
        place_tied(X, q, con_node, con_body, con_arm, con_target, con_active, frame)
        ok = False
        res = 0.0
        res_prev = np.inf
        cuts = 0
        scale = 1.0
        for it in range(max_iter):
            for i in range(n):
                if fidx[i] >= 0:
                    for r in range(3):
                        A[i, r] = c0 * (X[i, r] - Xn[i, r]) - Vn[i, r] / (beta * dt) - (0.5 / beta - 1.0) * An[i, r]
                        V[i, r] = Vn[i, r] + dt * ((1.0 - gamma) * An[i, r] + gamma * A[i, r])
            for b in range(nb):
                for k in range(6):
                    qdd[b, k] = c0 * (q[b, k] - qn[b, k]) - qdn[b, k] / (beta * dt) - (0.5 / beta - 1.0) * qddn[b, k]
                    qd[b, k] = qdn[b, k] + dt * ((1.0 - gamma) * qddn[b, k] + gamma * qdd[b, k])
            # the first check of a step, where most steps converge, assembles the residual only
            for jac in (it != 1, True):
                solved = iterate(X, V, A, q, qd, qdd, t, c0, c0, c1, True, it > 0, jac, args, weight, fidx, nfree, bw,
                                 env, cur_depth, cur_speed, with_waves, node_fext, con_node, con_body, con_arm,
                                 con_target, con_active, bpar, bkhs, badd, blin, bquad, ext_t, ext_f, ext_n, tol, F, M,
                                 tension, band, du, dq, out, Yt, tied, frame, spin)
                if jac or out[0] <= out[1] or not (out[0] < res_prev):
                    break
            res, scale = out[0], out[1]
            stats[0] += 1
            if res <= scale and it > 0:
                ok = True
                break
            if it > 0 and not (res < res_prev) and cuts < 6:
                # backtrack: the full Newton step made things worse (contact or slack switching)
                cuts += 1
                Du *= 0.5
                Dq *= 0.5
                _apply(X, q, Du, Dq, fidx, -1.0)
                place_tied(X, q, con_node, con_body, con_arm, con_target, con_active, frame)
                continue
            if not math.isfinite(res) or not solved:
                break
            res_prev = res
            cuts = 0
            Du[:] = du
            Dq[:] = dq
            _apply(X, q, du, dq, fidx, 1.0)
            place_tied(X, q, con_node, con_body, con_arm, con_target, con_active, frame)
        stats[1] = res
        stats[2] = scale
        if not ok:
            X[:] = Xn
            V[:] = Vn
            A[:] = An
            q[:] = qn
            qd[:] = qdn
            qdd[:] = qddn
            return step
        commit_viscoelastic(args[-1])
        for b in range(nb):  # once re-charted, a body is re-charted after every step
            track_frame(q[b], qd[b], qdd[b], frame[b], gq, CHART_LIMIT if frame[b, F_ON] == 0.0 else 0.0)
        for j in range(con_node.size):
            if con_active[j] == 0:
                continue
            e = fail_elem[j]
            if t >= fail_time[j] - 1e-9 * dt or (e >= 0 and tension[e] >= fail_tension[j]):
                con_active[j] = 0
                fail_at[j] = t
    return px.shape[0]


@njit(cache=True)
def coupled_static(X, q, args, weight, fidx, nfree, bw, env, cur_depth, cur_speed, node_fext, con_node, con_body,
                   con_arm, con_target, con_active, bpar, bkhs, badd, blin, bquad, ext_t, ext_f, ext_n, tol, max_iter,
                   max_step, body_scale, F, M, tension, stats, frame, spin):
    """Static equilibrium of the lines and bodies by pseudo-transient Newton, ``(K + lam M) dx = -R``.

    The bodies' mass matrices in ``M`` are scaled by ``body_scale`` (a node's mass over a body's), so
    that the pseudo-time moves a body as fast as a node.

    ``lam`` [1/s^2] starts where a node under its weight moves a fraction of an element and follows the
    residual (switched evolution relaxation); a step is limited to ``max_step`` [m] of any node or body
    and 0.1 rad of rotation (the turn about a body's free ``spin`` axis left out, see :func:`iterate`). A
    body whose |pitch| exceeds ``CHART_LIMIT`` after an iteration is re-charted (``frame``, in place, as in
    :func:`coupled_steps`). Returns True when converged; ``stats`` receives (iterations, residual, absolute
    force tolerance [N]).
    """
    nb = q.shape[0]
    nd = 3 * nfree
    V = np.zeros_like(X)
    A = np.zeros_like(X)
    qd = np.zeros_like(q)
    qdd = np.zeros_like(q)
    band = np.zeros((nd, 2 * bw + 1))
    du = np.zeros(nd)
    dq = np.zeros(6 * nb)
    out = np.zeros(2)
    Yt = np.zeros((12 * con_node.size, nd))
    tied = np.zeros(X.shape[0], np.bool_)
    gq = np.empty(3)
    for b in range(nb):
        if frame[b, F_ON] == 0.0:
            frame[b, F_GLOB:F_GLOB + 3] = q[b, 3:]
        rechart(q[b], qd[b], qdd[b], frame[b], CHART_LIMIT)
    Xp = X.copy()
    qp = q.copy()
    framep = frame.copy()
    lam = env[1] / (0.05 * max_step)
    lam_min = 1e-9 * lam  # keeps a DOF without stiffness (the yaw of a body on one line) regular
    res_prev = np.inf
    place_tied(X, q, con_node, con_body, con_arm, con_target, con_active, frame)
    for it in range(max_iter):
        solved = iterate(X, V, A, q, qd, qdd, 0.0, lam, lam * body_scale, 0.0, False, True, True, args, weight, fidx, nfree, bw, env, cur_depth,
                         cur_speed, False, node_fext, con_node, con_body, con_arm, con_target, con_active, bpar, bkhs,
                         badd, blin, bquad, ext_t, ext_f, ext_n, tol, F, M, tension, band, du, dq, out, Yt, tied, frame,
                         spin)
        res, scale = out[0], out[1]
        stats[0] = it
        stats[1] = res
        stats[2] = scale
        if res <= scale:
            return True
        if not math.isfinite(res) or not solved or res > 1e3 * res_prev:
            # back to the last state, more inertia
            X[:] = Xp
            q[:] = qp
            frame[:] = framep
            lam *= 10.0
            res_prev = np.inf
            continue
        if math.isfinite(res_prev):
            lam = max(lam * min(max(res / res_prev, 0.05), 10.0), lam_min)
        res_prev = res
        big = 0.0
        for k in range(nd):
            big = max(big, abs(du[k]))
        rot = 0.0
        for b in range(nb):
            for k in range(3):
                big = max(big, abs(dq[6 * b + k]))
                rot = max(rot, abs(dq[6 * b + 3 + k]))
        shrink = 1.0
        if big > max_step:
            shrink = max_step / big
        if rot * shrink > 0.1:
            shrink = 0.1 / rot
        Xp[:] = X
        qp[:] = q
        framep[:] = frame
        _apply(X, q, du, dq, fidx, shrink)
        for b in range(nb):
            track_frame(q[b], qd[b], qdd[b], frame[b], gq, CHART_LIMIT)
        place_tied(X, q, con_node, con_body, con_arm, con_target, con_active, frame)
    return False

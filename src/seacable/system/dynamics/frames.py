"""Compiled rotations of the coupled dynamics' rigid bodies: charts, global angles, the angular-velocity map.


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

from ..._jit import njit


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
    fr[F_GLOB], fr[F_GLOB + 1], fr[F_GLOB + 2] = g[0], g[1], g[2]
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
    for k in range(3):
        fr[F_GLOB + k] = gq[k]
    rechart(q, qd, qdd, fr, limit)


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

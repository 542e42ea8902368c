"""Compiled loads of a rigid body of the coupled dynamics and their Newton tangents.

Rotations are the body's (roll, pitch, yaw) with ``R = Rz(yaw) Ry(pitch) Rx(roll)``: the geometry
(points, centre of gravity and of buoyancy) is exact at any angle; the angular velocity is ``w = E
theta'`` (:func:`angular_map`), the body's equations are those of the rigid body in ``(a, dw/dt)`` with
its gyroscopic and centripetal terms (:func:`body_load`). The Newton step is solved in small rotation
vectors ``dphi`` (moments as they are, the tied nodes move by ``-skew(R p_j) dphi``, so ``T_j = [I, -skew(R
p_j)]``) and mapped to the angles by ``dtheta = E^-1 dphi`` (:func:`.frames._angle_increment`, regularised at pitch
+-90 deg, where ``E`` is singular: a horizontal MoorDyn rod starts there); the convergence check is on the
angles' generalised forces ``E^T M``. The Newton matrix leaves out the change of ``E`` with the angles.
"""

from __future__ import annotations

import math

import numpy as np

from ..._jit import copy_2d, njit
from ...mooring.kernel import GRID_HEADER, _fluid
from ..statics.kernel import _skew
from .frames import body_rotation, global_angles, rotation

# body parameter layout (one row per body in ``bpar``)
B_MASS, B_VOL, B_AWP, B_IXX, B_IYY, B_HASK = 0, 1, 2, 3, 4, 5
B_CG, B_CB, B_INERT, B_Q0, B_FEXT = 6, 9, 12, 15, 21
# the current's and the wind's force tables (:func:`_table_force`): their rows, the air's density, and from
# ``B_TAB`` the rows (heading in [0, 2 pi) ascending, surge, sway, yaw areas), the current's then the wind's
B_NCUR, B_NWIND, B_RHOAIR = 27, 28, 29
B_SIZE = 30
B_TAB = B_SIZE


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
    _fluid(x, 0.0, env, cur_depth, cur_speed, np.bool_(False), np.zeros(GRID_HEADER), uc, acc)


@njit(cache=True)
def _table_force(par, off, n, ux, uy, psi, density, out):
    """The force (x, y) and yaw moment ``out`` (3, global axes) of a flow ``(ux, uy)`` [m/s] relative to the body
    (global axes) on a body heading ``psi`` [rad], from its table of ``n`` rows at ``par[off:]`` (``B_TAB``):
    ``1/2 density |u|^2`` times the areas at the flow's direction in the body's axes, interpolated linearly and
    periodically in that direction as :func:`seacable._heading.heading_weights` does."""
    speed2 = ux * ux + uy * uy
    out[0] = out[1] = out[2] = 0.0
    if speed2 == 0.0:
        return
    beta = (math.atan2(uy, ux) - psi) % (2.0 * math.pi)
    lo = n - 1  # before the first heading: between the last and the first plus 2 pi
    for r in range(n):
        if par[off + 4 * r] <= beta:
            lo = r
    hi = (lo + 1) % n
    frac = 0.0
    if n > 1:
        b0, b1 = par[off + 4 * lo], par[off + 4 * hi]
        if hi <= lo:
            b1 += 2.0 * math.pi
        if beta < b0:
            beta += 2.0 * math.pi
        frac = (beta - b0) / (b1 - b0)
    q = 0.5 * density * speed2
    cx = q * ((1.0 - frac) * par[off + 4 * lo + 1] + frac * par[off + 4 * hi + 1])
    cy = q * ((1.0 - frac) * par[off + 4 * lo + 2] + frac * par[off + 4 * hi + 2])
    out[0] = math.cos(psi) * cx - math.sin(psi) * cy
    out[1] = math.sin(psi) * cx + math.cos(psi) * cy
    out[2] = q * ((1.0 - frac) * par[off + 4 * lo + 3] + frac * par[off + 4 * hi + 3])


@njit(cache=True)
def _table_loads(par, qd, uc, psi, rho, f6):
    """f6 += the current's and the wind's table forces (:func:`_table_force`) on a body moving at ``qd`` (its
    reference point's velocity, global axes), the current's velocity ``uc[0:2]`` and the wind's ``uc[3:5]`` at the
    body (global axes)."""
    f3 = np.empty(3)
    nc, nw = int(par[B_NCUR]), int(par[B_NWIND])
    if nc > 0:
        _table_force(par, B_TAB, nc, uc[0] - qd[0], uc[1] - qd[1], psi, rho, f3)
        f6[0] += f3[0]
        f6[1] += f3[1]
        f6[5] += f3[2]
    if nw > 0:
        _table_force(par, B_TAB + 4 * nc, nw, uc[3] - qd[0], uc[4] - qd[1], psi, par[B_RHOAIR], f3)
        f6[0] += f3[0]
        f6[1] += f3[1]
        f6[5] += f3[2]


@njit(cache=True)
def _table_tangent(par, qd, uc, psi, rho, C):
    """C += -d f6 / d qd of :func:`_table_loads` in the horizontal velocities (central differences; the turning
    of the tables with the body's yaw left out of the Newton matrix)."""
    f6 = np.zeros(6)
    v = np.empty(2)
    for j in range(2):
        h = 1e-6 * max(1.0, abs(uc[0] - qd[0]) + abs(uc[1] - qd[1]) + abs(uc[3] - qd[0]) + abs(uc[4] - qd[1]))
        v[0], v[1] = qd[0], qd[1]
        f6[:] = 0.0
        v[j] = qd[j] + h
        _table_loads(par, v, uc, psi, rho, f6)
        fx, fy, mz = f6[0], f6[1], f6[5]
        f6[:] = 0.0
        v[j] = qd[j] - h
        _table_loads(par, v, uc, psi, rho, f6)
        C[0, j] -= (fx - f6[0]) / (2.0 * h)
        C[1, j] -= (fy - f6[1]) / (2.0 * h)
        C[5, j] -= (mz - f6[5]) / (2.0 * h)


@njit(cache=True)
def body_load(q, qd, uc, t, par, khs, add, lin, quad, ext_t, ext_f, ext_n, rho, g, f6, M6, fr):
    """The body's own forces ``f6`` (weight, buoyancy, hydrostatics, damping, external, and minus the rigid
    body's centripetal and gyroscopic terms; global axes, moments about the reference point) and its mass
    matrix ``M6`` (rigid body about the reference point plus added mass, global axes), at the velocity
    ``u = (v, w)`` (reference point, angular velocity; global axes), so that ``M6 (a, alpha) = f6``. The
    quadratic damping (drag) and the current's table act on the velocity relative to the current ``uc[0:3]``
    (global) at the body, the linear damping on the body's own; the wind's table on the wind relative to the
    body, the wind's velocity (columns 6 and 7 of ``ext_f``, interpolated at ``t``) stored in ``uc[3:5]`` for
    :func:`body_tangent` (``uc`` has 5 values when the body has a wind table).

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
    _rot6(R, add, Ma, np.bool_(False))
    copy_2d(M6, Ma)
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
        qg[0], qg[1], qg[2] = q[0], q[1], q[2]
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
    if par[B_NWIND] > 0.0:  # the wind's velocity at the centre of pressure, for the table (and the tangent)
        uc[3] = np.interp(t, ext_t[:ext_n], ext_f[:ext_n, 6])
        uc[4] = np.interp(t, ext_t[:ext_n], ext_f[:ext_n, 7])
    if par[B_NCUR] > 0.0 or par[B_NWIND] > 0.0:
        _table_loads(par, qd, uc, math.atan2(R[1, 0], R[0, 0]), rho, f6)
    # damping, in body axes: vb = R6^T qd, vr = R6^T (qd - uc), f6 -= R6 (B1 vb + B2 |vr| vr)
    vb = wk[69:75]
    fb = wk[75:81]
    vr = wk[81:87]
    _mv(R.T, qd[3:], vb[3:])
    _mv(R.T, qd[:3] - uc[:3], vr[:3])
    vr[3], vr[4], vr[5] = vb[3], vb[4], vb[5]
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
        copy_2d(K, khs)
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
    _mv(R.T, qd[:3] - uc[:3], vb[:3])
    _mv(R.T, qd[3:], vb[3:])
    D = wk[15:51].reshape((6, 6))
    for k in range(6):
        for j in range(6):
            D[k, j] = lin[k, j] + 2.0 * quad[k, j] * abs(vb[j])
    _rot6(R, D, C, np.bool_(False))
    if par[B_NCUR] > 0.0 or par[B_NWIND] > 0.0:
        _table_tangent(par, qd, uc, math.atan2(R[1, 0], R[0, 0]), rho, C)
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

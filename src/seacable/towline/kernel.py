"""Compiled core of the multibody towline (paper 003): element loads, joints, explicit steps.

The towline is a chain of N rigid, slender elements of length ``l``. Element j has its centre ``R_j``
and a frame ``E_j = [e1 e2 e3]`` (columns, inertial components); ``e1`` runs along the element from
the tug end (front, ``a_j = R_j - l/2 e1``) to the barge end (aft, ``b_j = R_j + l/2 e1``). Its
velocity is held in the element's frame, ``nu = (u, v, w)``, with the angular velocity
``omega = q e2 + r e3``: five degrees of freedom, no roll. The frame does not roll (``p = 0``): an
axisymmetric rod has no use for a roll angle, and a non-rolling frame has no singular attitude
(unlike yaw-pitch Euler angles at a vertical element).

Equations of motion in the element frame (Kirchhoff's equations for a body in a fluid, with the
added mass ``m_a = C_a rho A l_wet`` across the element and none along it; ``M_x = m``,
``M_y = M_z = m + m_a``, ``I = m l^2 / 12 + C_a rho A int s^2 ds`` over the wetted part)::

    M_x du/dt = F_x - q M_z w + r M_y v        (Coriolis C and added-mass Coriolis C_A)
    M_y dv/dt = F_y - r M_x u
    M_z dw/dt = F_z + q M_x u
    I dq/dt   = M_q - (M_x - M_z) u w          (Munk moment of the added mass)
    I dr/dt   = M_r - (M_y - M_x) u v

Paper 003 prints C = [-m(gw - rv), -m r u, m q u] ("gw" is qw: OCR) and C_A with rows
``-m_x q v + m_y r v`` and ``(m_x - m_y) r v`` where the derivation gives ``-m_z q w + m_y r v`` and
``(m_y - m_x) u v`` (up to its z-down sign convention); the forms above conserve the kinetic energy
``1/2 (M_x u^2 + M_y v^2 + M_z w^2) + 1/2 I (q^2 + r^2)`` exactly when the forces vanish, which the
tests check.

Forces (F, body components; moments ``(M_q, M_r) = (-s F_z, s F_y)`` of a force at ``s e1``):

- weight ``m g`` at the centre;
- buoyancy with partial immersion at three Gauss points along the element: the immersed fraction of
  the circular section whose axis is ``h`` below the surface, over the section's vertical half-extent
  ``r_v = d/2 sqrt(1 - e1_z^2)``, is ``(acos(-c) + c sqrt(1 - c^2)) / pi`` with ``c = h / r_v``;
- drag on the wetted length: ``-1/2 rho d C_D |v_n| v_n`` across and ``-1/2 rho pi d C_f |u| u``
  along (skin friction on the wetted perimeter), with the velocity of each Gauss point;
- water-entry impact: the momentum given to the added mass as it grows, ``H = -(dm_a/dt)_+ (0, v, w)``
  (paper 003 writes ``-(m_j / dt)(0, v, w)``, the same momentum given in one step), taken at each
  Gauss point with that point's share of the added mass and its own velocity, and so with its
  moment: a force at the centre's velocity pumps energy into an element that rotates through the
  surface (its end entering the water while its centre rises), which made 100-element runs blow up;
  per point, the impact's power ``-(dm_a/dt)_+ |v_p|^2`` is never positive;
- joint tension: the connection points of neighbours (``b_{j-1}`` and ``a_j``; the tug's and the
  barge's tow points at the ends) are joined by a spring of stiffness ``k`` (from the breaking load
  and the elongation at break: ``EA = P / eps_b``, ``k = (n + 1) EA / L`` so that the n + 1 joints
  in series stretch as the line does) and a damper ``c_x`` along the joint,
  ``c_x / 10`` across (``c_x = 2 zeta sqrt(k m)``, paper 003). The tension reported is the joint
  force along the line. A joint whose gap closes along the line (the connection points pushed into
  each other: compression; the line's direction is the mean of the joint's two elements) is slack:
  the spring keeps only its part across the line, so the joint stays pinned sideways but takes no
  compression, and the tension rises again from zero, without a jump, when the gap reopens. Past an
  overlap of half an element the spring takes up compression again (a stop): without it, the
  elements of a line that piles up, as when the barge overruns it, slid along each other without
  end, and the slack joint's pull across a turning axis (a follower force) made them flutter until
  the run blew up. Paper 003 releases the joint entirely (no force) when the next connection point
  comes within ``l/2`` of the previous element's centre; a released joint lets the points drift
  apart sideways by up to an element length while the line folds, and re-engaging it loads the
  spring with ``k`` times that gap, an impulse that made the explicit scheme blow up in our runs
  (energy jumps at each release). A fully pinned joint (no release) instead lets a chain of rigid
  elements carry compression until it buckles, which pushed a floating line under water ahead of a
  drifting barge;
- material damping of bending: a moment ``c_m (omega_j - omega_{j-1})`` between neighbours,
  ``c_m = 2 zeta_m sqrt(T (l/2) I)`` with the joint's tension T (the element's pendulum mode under
  tension, paper 003's ``2 zeta_m sqrt(P l I_y)``).

Paper 003 applies its damping ``D_M = (c_x u, c_y v, c_z w, c_m q, c_r r)`` to each element's own
velocities, which would resist a steady tow in proportion to its speed; here the same coefficients
act on the relative motion at the joints, which is what a material damping is.

Time stepping is explicit (symplectic Euler: velocities first, then positions with the new
velocities; the frame turns by the exact rotation of ``omega dt``), with no iteration, and a step
bounded by the element's axial natural period ``2 pi sqrt(m / k)``. The joints' axial dampers alone
are applied implicitly, joint after joint, to the new velocities (backward Euler on each joint's
relative velocity, a closed form): explicit, at the paper's zeta = 0.5 they bounded the step more
tightly than the springs (by 0.41 against 0.53 sqrt(m / k)), and on a folded joint, where the
damper pushes the other element's end sideways, they broke that bound.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from .barge import barge_accelerations

__all__ = ["P_SIZE", "barge_point", "evaluate", "frame_from_axis", "joint_points", "run_steps"]

# Line parameters (flat vector).
P_L, P_M, P_I, P_D, P_AREA, P_CA, P_CD, P_CF, P_K, P_CX, P_CT, P_ZM = range(12)
P_RHO, P_G, P_BRAKE, P_IMPACT, P_DRAG, P_KT = 12, 13, 14, 15, 16, 17
P_SIZE = 18

# Barge state: x, y, heading, u, v, r (barge frame velocities).
B_X, B_Y, B_PSI, B_U, B_V, B_R = range(6)

# fast floating point short of assuming finite values: the steps check that the state stays finite
_FAST = {"nsz", "arcp", "contract", "reassoc"}

_GP = np.array([-math.sqrt(0.6), 0.0, math.sqrt(0.6)])
_GW = np.array([5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0])


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def _acos01(x):
    """arccos(x) for 0 <= x <= 1 to 2e-8 rad (Abramowitz & Stegun 1964, 4.4.46), without libm's call."""
    p = -0.0012624911
    p = p * x + 0.0066700901
    p = p * x - 0.0170881256
    p = p * x + 0.0308918810
    p = p * x - 0.0501743046
    p = p * x + 0.0889789874
    p = p * x - 0.2145988016
    p = p * x + 1.5707963050
    return math.sqrt(1.0 - x) * p


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def _immersed(h, rv):
    """Immersed fraction of a circular section whose axis lies ``h`` below the surface.

    ``(acos(-c) + c sqrt(1 - c^2)) / pi`` with ``c = h / rv``, to 1e-8 (``_acos01``).
    """
    if h >= rv:
        return 1.0
    if h <= -rv:
        return 0.0
    c = h / rv
    a = math.pi - _acos01(c) if c >= 0.0 else _acos01(-c)
    return (a + c * math.sqrt(1.0 - c * c)) / math.pi


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def frame_from_axis(e1, out):
    """A frame (columns e1, e2, e3) with the given unit axis; e2 horizontal unless e1 is vertical."""
    out[:, 0] = e1
    hx, hy = -e1[1], e1[0]
    n = math.sqrt(hx * hx + hy * hy)
    if n < 1e-9:
        hx, hy, n = 0.0, 1.0, 1.0
    out[0, 1], out[1, 1], out[2, 1] = hx / n, hy / n, 0.0
    out[0, 2] = e1[1] * out[2, 1] - e1[2] * out[1, 1]
    out[1, 2] = e1[2] * out[0, 1] - e1[0] * out[2, 1]
    out[2, 2] = e1[0] * out[1, 1] - e1[1] * out[0, 1]


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def _rotate(E, q, r, dt):
    """E <- E exp(dt [omega]x), omega = (0, q, r) in the element frame (Rodrigues), in place."""
    wy, wz = q * dt, r * dt
    th = math.sqrt(wy * wy + wz * wz)
    if th < 1e-300:
        return
    ky, kz = wy / th, wz / th
    if th < 1e-2:  # Taylor series, to round-off (next terms th^7 / 5040, th^8 / 40320 < 1e-18)
        t2 = th * th
        s = th * (1.0 - t2 / 6.0 * (1.0 - t2 / 20.0 * (1.0 - t2 / 42.0)))
        C = t2 / 2.0 * (1.0 - t2 / 12.0 * (1.0 - t2 / 30.0))
        c = 1.0 - C
    else:
        s, c = math.sin(th), math.cos(th)
        C = 1.0 - c
    # the body-frame rotation about (0, ky, kz): rows of R
    r00, r01, r02 = c, -kz * s, ky * s
    r10, r11, r12 = kz * s, c + C * ky * ky, C * ky * kz
    r20, r21, r22 = -ky * s, C * kz * ky, c + C * kz * kz
    for i in range(3):
        a, b, d = E[i, 0], E[i, 1], E[i, 2]
        E[i, 0] = a * r00 + b * r10 + d * r20
        E[i, 1] = a * r01 + b * r11 + d * r21
        E[i, 2] = a * r02 + b * r12 + d * r22


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def joint_points(R, E, nu, om, half, k, pa, va, pb, vb):
    """Front (a) and aft (b) connection points of element k and their velocities."""
    for i in range(3):
        e1, e2, e3 = E[k, i, 0], E[k, i, 1], E[k, i, 2]
        V = e1 * nu[k, 0] + e2 * nu[k, 1] + e3 * nu[k, 2]
        wxe1 = -om[k, 0] * e3 + om[k, 1] * e2  # omega x e1
        pa[i] = R[k, i] - half * e1
        pb[i] = R[k, i] + half * e1
        va[i] = V - half * wxe1
        vb[i] = V + half * wxe1


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def barge_point(bs, bxt, bzt, p, v):
    c, s = math.cos(bs[B_PSI]), math.sin(bs[B_PSI])
    p[0] = bs[B_X] + bxt * c
    p[1] = bs[B_Y] + bxt * s
    p[2] = bzt
    ux = bs[B_U] * c - bs[B_V] * s
    uy = bs[B_U] * s + bs[B_V] * c
    v[0] = ux - bs[B_R] * bxt * s
    v[1] = uy + bs[B_R] * bxt * c
    v[2] = 0.0


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def _spring(P, gap, dgap, axis, out):
    """Joint force on the previous body (towards the next one) into ``out``; returns the spring's own
    axial force (without the damper) and sets ``out`` to spring plus dampers. Tension is ``> 0``.

    With ``g = gap . axis`` (``axis`` the unit mean of the joint's elements) the spring pulls ``k g``
    along the axis in tension (g > 0) and pins the points across it with the penalty stiffness
    ``k_t``; while the gap closes (the next element's end sliding into the previous one) it takes no
    compression until the overlap reaches half an element, and ``k_t (g + l/2)`` beyond (a stop, so
    that elements cannot slide along each other without end). The damper is ``c_x`` along the axis
    in tension and ``c_t`` across it.
    """
    k, kt, ct = P[P_K], P[P_KT], P[P_CT]
    gl = gap[0] * axis[0] + gap[1] * axis[1] + gap[2] * axis[2]
    ga = dgap[0] * axis[0] + dgap[1] * axis[1] + dgap[2] * axis[2]
    if gl > 0.0:
        fs = k * gl
        fa = fs + P[P_CX] * ga
    else:
        fs = kt * min(gl + 0.5 * P[P_L], 0.0)
        fa = fs
    for i in range(3):
        out[i] = kt * (gap[i] - gl * axis[i]) + fa * axis[i] + ct * (dgap[i] - ga * axis[i])
    return fs


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def _forces(R, E, nu, om, first, P, tug_p, tug_v, bs, bxt, bzt, Fb, Mb, D, mass_t, inert, jf, jaux, tension,
            slack, ma_now, ma_prev, dt, work):
    """Body forces Fb (N, 3), moments Mb (N, 2), transverse mass and inertia, joint forces jf (N+1, 3).

    ``D`` (N, 5) receives the diagonal of the dampers' matrix in each element's own velocities
    (u, v, w, q, r), which the time step takes implicitly. ``jaux`` (N+1, 7) is scratch: each joint's
    axis, the gradient of its spring energy with respect to the axis (the torque of an axis that turns,
    see ``_axis_torque``) and its axial damper.

    ``ma_now`` (N, 3) receives the added mass of each Gauss point's share of the element; with
    ``dt > 0`` its growth since ``ma_prev`` gives the water-entry impact. ``work`` is (12, 3) scratch.
    """
    n = R.shape[0]
    half = 0.5 * P[P_L]
    rho, g = P[P_RHO], P[P_G]
    pb, vb = work[2], work[3]
    qa, wa, qb, wb = work[4], work[5], work[6], work[7]
    gap, dgap, axis, f = work[8], work[9], work[10], work[11]
    jf[:] = 0.0
    tension[:] = 0.0
    slack[:] = False
    # --- joints: j = first is the tug's, j = n the barge's; joint j joins element j-1 (aft) to j (front)
    for j in range(first, n + 1):
        if j == first:
            qa[:] = tug_p
            wa[:] = tug_v
        else:  # the aft point of element j - 1, found as pb, vb at the previous joint
            qa[:] = pb
            wa[:] = vb
        if j == n:
            barge_point(bs, bxt, bzt, qb, wb)
        else:
            joint_points(R, E, nu, om, half, j, qb, wb, pb, vb)
        for i in range(3):
            gap[i] = qb[i] - qa[i]
            dgap[i] = wb[i] - wa[i]
        if j == first and first > 0:
            # paying out from the bitt: the brake tension along the line, no spring
            gl = math.sqrt(gap[0] ** 2 + gap[1] ** 2 + gap[2] ** 2)
            if gl > 0.0 and P[P_BRAKE] > 0.0:
                for i in range(3):
                    jf[j, i] = P[P_BRAKE] * gap[i] / gl
                tension[j] = P[P_BRAKE]
            else:
                slack[j] = True
            jaux[j, :] = 0.0
            continue
        # the joint's axis: along its elements
        for i in range(3):
            axis[i] = 0.0
            if j > first:
                axis[i] += E[j - 1, i, 0]
            if j < n:
                axis[i] += E[j, i, 0]
        al = math.sqrt(axis[0] ** 2 + axis[1] ** 2 + axis[2] ** 2)
        if al < 1e-9:  # folded back on itself: the aft element's direction
            for i in range(3):
                axis[i] = E[j, i, 0]
        else:
            for i in range(3):
                axis[i] /= al
        gl = gap[0] * axis[0] + gap[1] * axis[1] + gap[2] * axis[2]
        fs = _spring(P, gap, dgap, axis, f)
        taut = gl > 0.0
        slack[j] = not taut
        tension[j] = max(f[0] * axis[0] + f[1] * axis[1] + f[2] * axis[2], 0.0) if taut else 0.0
        # the spring energy's gradient with respect to the (unnormalised) axis, for _axis_torque; a
        # joint bent past 120 degrees (al < 1) goes without it rather than divide by a vanishing al
        c = (fs - P[P_KT] * gl) / al if al >= 1.0 else 0.0
        for i in range(3):
            jf[j, i] = f[i]
            jaux[j, i] = axis[i]
            jaux[j, 3 + i] = c * (gap[i] - gl * axis[i])
        jaux[j, 6] = P[P_CX] if taut else 0.0
        jaux[j, 7] = P[P_CT]
    # --- elements
    m, d, area = P[P_M], P[P_D], P[P_AREA]
    for k in range(first, n):
        e1z = E[k, 2, 0]
        rv = 0.5 * d * math.sqrt(max(1.0 - e1z * e1z, 0.0))
        fx = 0.0
        fy = 0.0
        fz = 0.0
        mq = 0.0
        mr = 0.0
        # weight (body components of -m g z)
        fx -= m * g * E[k, 2, 0]
        fy -= m * g * E[k, 2, 1]
        fz -= m * g * E[k, 2, 2]
        wet = 0.0
        wet2 = 0.0
        for ip in range(3):
            s = _GP[ip] * half
            wl = _GW[ip] * half
            z = R[k, 2] + s * e1z
            fr = _immersed(-z, rv) if rv > 0.0 else (1.0 if z < 0.0 else 0.0)
            ma_p = P[P_CA] * rho * area * fr * wl
            grow = (ma_p - ma_prev[k, ip]) / dt if dt > 0.0 and P[P_IMPACT] > 0.0 else 0.0
            ma_now[k, ip] = ma_p
            if fr <= 0.0:
                continue
            wet += fr * wl
            wet2 += fr * wl * s * s
            bz = rho * g * area * fr * wl  # buoyancy, up
            px, py, pz = bz * E[k, 2, 0], bz * E[k, 2, 1], bz * E[k, 2, 2]
            # the point's body velocity (u, v + s r, w - s q), still water
            up = nu[k, 0]
            vp = nu[k, 1] + s * om[k, 1]
            wp = nu[k, 2] - s * om[k, 0]
            if P[P_DRAG] > 0.0:
                vn = math.sqrt(vp * vp + wp * wp)
                qd = 0.5 * rho * d * fr * wl
                px -= qd * math.pi * P[P_CF] * abs(up) * up
                py -= qd * P[P_CD] * vn * vp
                pz -= qd * P[P_CD] * vn * wp
            # water entry: the momentum given to the point's growing added mass, at the point's velocity
            if grow > 0.0:
                py -= grow * vp
                pz -= grow * wp
            fx += px
            fy += py
            fz += pz
            mq -= s * pz
            mr += s * py
        mass_t[k] = m + P[P_CA] * rho * area * wet
        inert[k] = P[P_I] + P[P_CA] * rho * area * wet2
        # joint forces: at the front (s = -l/2) minus joint k's, at the aft (s = +l/2) joint k+1's; the
        # torque of the joint's turning axis; the diagonal of the joint dampers in (u, v, w, q, r)
        du = dv = dw = 0.0
        for side in range(2):
            j = k + side
            sgn = -1.0 if side == 0 else 1.0
            sl = -half if side == 0 else half
            gx = sgn * jf[j, 0]
            gy = sgn * jf[j, 1]
            gz = sgn * jf[j, 2]
            bx = E[k, 0, 0] * gx + E[k, 1, 0] * gy + E[k, 2, 0] * gz
            by = E[k, 0, 1] * gx + E[k, 1, 1] * gy + E[k, 2, 1] * gz
            bzz = E[k, 0, 2] * gx + E[k, 1, 2] * gy + E[k, 2, 2] * gz
            h2 = E[k, 0, 1] * jaux[j, 3] + E[k, 1, 1] * jaux[j, 4] + E[k, 2, 1] * jaux[j, 5]
            h3 = E[k, 0, 2] * jaux[j, 3] + E[k, 1, 2] * jaux[j, 4] + E[k, 2, 2] * jaux[j, 5]
            fx += bx
            fy += by
            fz += bzz
            mq += h3 - sl * bzz
            mr += sl * by - h2
            a1 = E[k, 0, 0] * jaux[j, 0] + E[k, 1, 0] * jaux[j, 1] + E[k, 2, 0] * jaux[j, 2]
            a2 = E[k, 0, 1] * jaux[j, 0] + E[k, 1, 1] * jaux[j, 1] + E[k, 2, 1] * jaux[j, 2]
            a3 = E[k, 0, 2] * jaux[j, 0] + E[k, 1, 2] * jaux[j, 1] + E[k, 2, 2] * jaux[j, 2]
            ct = jaux[j, 7]
            cd = jaux[j, 6] - ct
            du += ct + cd * a1 * a1
            dv += ct + cd * a2 * a2
            dw += ct + cd * a3 * a3
        Fb[k, 0], Fb[k, 1], Fb[k, 2] = fx, fy, fz
        Mb[k, 0], Mb[k, 1] = mq, mr
        D[k, 0], D[k, 1], D[k, 2] = du, dv, dw
        D[k, 3], D[k, 4] = half * half * dw, half * half * dv
    # bending damping between neighbours: c_m (omega_k - omega_{k-1}), c_m = 2 zeta_m sqrt(T l/2 I)
    if P[P_ZM] > 0.0:
        for j in range(first + 1, n):
            if tension[j] <= 0.0:
                continue
            cm = 2.0 * P[P_ZM] * math.sqrt(tension[j] * half * 0.5 * (inert[j - 1] + inert[j]))
            for i in range(3):
                rel = (om[j, 0] * E[j, i, 1] + om[j, 1] * E[j, i, 2]
                       - om[j - 1, 0] * E[j - 1, i, 1] - om[j - 1, 1] * E[j - 1, i, 2])
                f[i] = cm * rel
            D[j - 1, 3] += cm
            D[j - 1, 4] += cm
            D[j, 3] += cm
            D[j, 4] += cm
            Mb[j - 1, 0] += f[0] * E[j - 1, 0, 1] + f[1] * E[j - 1, 1, 1] + f[2] * E[j - 1, 2, 1]
            Mb[j - 1, 1] += f[0] * E[j - 1, 0, 2] + f[1] * E[j - 1, 1, 2] + f[2] * E[j - 1, 2, 2]
            Mb[j, 0] -= f[0] * E[j, 0, 1] + f[1] * E[j, 1, 1] + f[2] * E[j, 2, 1]
            Mb[j, 1] -= f[0] * E[j, 0, 2] + f[1] * E[j, 1, 2] + f[2] * E[j, 2, 2]


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def _release(R, E, nu, om, k, P, tug_p, tug_v, bs, bxt, bzt):
    """Element k leaves the bitt: straight from the tug's tow point to its aft neighbour's front."""
    n = R.shape[0]
    half = 0.5 * P[P_L]
    pa, va, pb, vb = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    if k + 1 == n:
        barge_point(bs, bxt, bzt, pb, vb)
    else:
        joint_points(R, E, nu, om, half, k + 1, pb, vb, pa, va)
    e1 = np.zeros(3)
    for i in range(3):
        e1[i] = pb[i] - tug_p[i]
    gl = math.sqrt(e1[0] ** 2 + e1[1] ** 2 + e1[2] ** 2)
    for i in range(3):
        e1[i] /= gl
    frame_from_axis(e1, E[k])
    V = np.zeros(3)
    dv = np.zeros(3)
    for i in range(3):
        R[k, i] = pb[i] - half * e1[i]
        V[i] = 0.5 * (vb[i] + tug_v[i])
        dv[i] = (vb[i] - tug_v[i]) / P[P_L]
    for c in range(3):
        nu[k, c] = E[k, 0, c] * V[0] + E[k, 1, c] * V[1] + E[k, 2, c] * V[2]
    # omega x e1 = dv across the element: q = -(dv . e3), r = dv . e2
    om[k, 0] = -(dv[0] * E[k, 0, 2] + dv[1] * E[k, 1, 2] + dv[2] * E[k, 2, 2])
    om[k, 1] = dv[0] * E[k, 0, 1] + dv[1] * E[k, 1, 1] + dv[2] * E[k, 2, 1]


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def evaluate(R, E, nu, om, first, P, tug_p, tug_v, bs, bxt, bzt, tension, slack, ma):
    """Joint tensions, slack flags and the added masses ``ma`` (N, 3) of the Gauss points' shares."""
    n = R.shape[0]
    _forces(R, E, nu, om, first, P, tug_p, tug_v, bs, bxt, bzt, np.zeros((n, 3)), np.zeros((n, 2)), np.zeros((n, 5)),
            np.zeros(n), np.zeros(n), np.zeros((n + 1, 3)), np.zeros((n + 1, 8)), tension, slack, ma, ma, 0.0,
            np.zeros((12, 3)))


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def run_steps(dt, tug_p, tug_v, R, E, nu, om, first_arr, P, bs, bpar, bxt, bzt, held, ma_prev,
              tension, slack):
    """Advance ``len(tug_p) - 1`` explicit steps of ``dt``; ``tug_p``, ``tug_v`` at the step times.

    ``first_arr[0]`` is the first element off the bitt (0 when the whole line is out). Returns the
    number of steps taken, fewer when a state is no longer finite.
    """
    n = R.shape[0]
    Fb = np.zeros((n, 3))
    Mb = np.zeros((n, 2))
    D = np.zeros((n, 5))
    mass_t = np.zeros(n)
    inert = np.zeros(n)
    jf = np.zeros((n + 1, 3))
    jaux = np.zeros((n + 1, 8))
    ma_now = np.zeros((n, 3))
    work = np.zeros((12, 3))
    qb, wb, sa, sb = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    m = P[P_M]
    half = 0.5 * P[P_L]
    nstep = tug_p.shape[0] - 1
    for step in range(nstep):
        first = first_arr[0]
        pt = tug_p[step]
        vt = tug_v[step]
        _forces(R, E, nu, om, first, P, pt, vt, bs, bxt, bzt, Fb, Mb, D, mass_t, inert, jf, jaux, tension, slack,
                ma_now, ma_prev, dt, work)
        for k in range(first, n):
            u, v, w = nu[k, 0], nu[k, 1], nu[k, 2]
            q, r = om[k, 0], om[k, 1]
            my = mass_t[k]
            ik = inert[k]
            for ip in range(3):
                ma_prev[k, ip] = ma_now[k, ip]
            # the dampers' own-velocity terms implicitly: x += dt a / (1 + dt d / mass)
            du = (Fb[k, 0] - q * my * w + r * my * v) / (m + dt * D[k, 0])
            dv = (Fb[k, 1] - r * m * u) / (my + dt * D[k, 1])
            dw = (Fb[k, 2] + q * m * u) / (my + dt * D[k, 2])
            dq = (Mb[k, 0] - (m - my) * u * w) / (ik + dt * D[k, 3])
            dr = (Mb[k, 1] - (my - m) * u * v) / (ik + dt * D[k, 4])
            nu[k, 0] = u + dt * du
            nu[k, 1] = v + dt * dv
            nu[k, 2] = w + dt * dw
            om[k, 0] = q + dt * dq
            om[k, 1] = r + dt * dr
            for i in range(3):
                R[k, i] += dt * (E[k, i, 0] * nu[k, 0] + E[k, i, 1] * nu[k, 1] + E[k, i, 2] * nu[k, 2])
            _rotate(E[k], om[k, 0], om[k, 1], dt)
        # the barge: towline force at its tow point (minus joint n's force on the previous body)
        if not held:
            c, s = math.cos(bs[B_PSI]), math.sin(bs[B_PSI])
            fxg = -jf[n, 0]
            fyg = -jf[n, 1]
            X = fxg * c + fyg * s
            Y = -fxg * s + fyg * c
            du, dv, dr = barge_accelerations(bpar, bs[B_U], bs[B_V], bs[B_R], X, Y, bxt * Y)
            bs[B_U] += dt * du
            bs[B_V] += dt * dv
            bs[B_R] += dt * dr
            bs[B_X] += dt * (bs[B_U] * c - bs[B_V] * s)
            bs[B_Y] += dt * (bs[B_U] * s + bs[B_V] * c)
            bs[B_PSI] += dt * bs[B_R]
        # payout: the next element leaves the bitt once there is room for it
        if first > 0:
            if first == n:
                barge_point(bs, bxt, bzt, qb, wb)
            else:
                joint_points(R, E, nu, om, half, first, qb, wb, sa, sb)
            d2 = 0.0
            for i in range(3):
                d2 += (qb[i] - tug_p[step + 1, i]) ** 2
            if d2 >= P[P_L] * P[P_L]:
                _release(R, E, nu, om, first - 1, P, tug_p[step + 1], tug_v[step + 1], bs, bxt, bzt)
                ma_prev[first - 1, :] = 0.0
                first_arr[0] = first - 1
        for k in range(first_arr[0], n):
            if not (math.isfinite(R[k, 0]) and math.isfinite(nu[k, 0]) and math.isfinite(om[k, 1])):
                return step
    return nstep

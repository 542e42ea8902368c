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
- the seabed (``P_DEPTH`` finite): at each Gauss point below it, a penalty force ``k_b d w_l p - c_b d w_l v_z``
  up (``p`` the point's depth below the seabed, ``w_l`` its share of the length; never pulling) and Coulomb
  friction ``-mu N v_h / sqrt(|v_h|^2 + v_f^2)`` against its horizontal velocity, as the mooring model's;
- joint tension: the connection points of neighbours (``b_{j-1}`` and ``a_j``; the tug's and the
  barge's tow points at the ends) are joined by a spring and a damper. Along the joint's axis (the
  mean direction of its two elements) the spring has the line's stiffness ``k`` (from the breaking
  load and the elongation at break: ``EA = P / eps_b``, ``k = (n + 1) EA / L`` so that the n + 1
  joints in series stretch as the line does) and the damper ``c_x = 2 zeta sqrt(k m)``; across it
  the joint is a pin, held by the penalty stiffness ``k_t = k / 3`` and the damper ``c_t = c_x / 10``
  (paper 003's ``c_y = c_z = c_x / 10``). Paper 003's zero-length spring has ``k_t = k``; the pin's
  stiffness is not a property of the line, only a means to keep the points together (its give, the
  joint's shear over ``k_t``, is about 2 mm in the paper's 25 kN steady tow with 11 elements), and at ``k / 3`` the stiffest mode
  of the pins (every element turning the same way, ``omega^2 = 12 k_t / m``) is no stiffer than the
  line's own axial mode (``4 k / m``), which allows a step ``sqrt(3)`` times longer. The spring's
  energy depends on the axis, which turns with the elements; each element takes its share of that
  as a torque (``_step``), so that the spring stays conservative. The tension reported is the joint
  force along the axis. A joint whose gap closes along the axis (the connection points pushed into
  each other: compression) is slack: it keeps its pin but takes no compression, and the tension rises
  again from zero, without a jump, when the gap reopens. Past an overlap of half an element the
  pin's stiffness takes up compression again (a stop): without it, the
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
bounded by the element's axial natural period: ``dt < sqrt(m / k) = T_n / 2 pi`` (``stable_time_step``).
The joint dampers and the bending dampers are taken implicitly along the whole line (backward Euler in
them): the new velocities of all elements solve ``(M + dt D) dx = dt f``, with ``M`` the elements'
masses and inertias, ``f`` all loads at the step's start and ``D`` the dampers' matrix, block
tri-diagonal with 5x5 blocks (a joint couples its two elements), by one forward elimination along the
line as the loads are computed and one back substitution that moves the elements (:func:`_eliminate`,
:func:`_back_substitute`). Elements that move together carry no damper force and feel no inertia from
it. Explicit, the paper's zeta = 0.5 bounded the step more tightly than the springs (0.41 against 0.53
sqrt(m / k) with ``k_t = k``); implicit in each element's own velocities only (each joint on its own, the
neighbour's velocity from the step's start), the damper of a joint whose two elements accelerate
together pulled ``c dt a`` back on each: a false inertia of ``c dt`` per joint, with which a line
falling in water at zeta = 0.5 fell 8.7 % slower than its weight, buoyancy and added mass give.
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
# seabed: depth (inf: none), penalty stiffness and damper per projected area [Pa/m, Pa s/m], Coulomb friction and
# its regularising speed [m/s]
P_DEPTH, P_KBOT, P_CBOT, P_MU, P_VFRIC = 18, 19, 20, 21, 22
P_SIZE = 23

# Barge state: x, y, heading, u, v, r (barge frame velocities).
B_X, B_Y, B_PSI, B_U, B_V, B_R = range(6)

# fast floating point short of assuming finite values: the steps check that the state stays finite
_FAST = {"arcp", "contract", "reassoc"}

_GP = np.array([-math.sqrt(0.6), 0.0, math.sqrt(0.6)])
_GW = np.array([5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0])


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
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


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _immersed(c):
    """Immersed fraction of a circular section whose axis lies ``c`` radii below the surface.

    ``(acos(-c) + c sqrt(1 - c^2)) / pi``, to 1e-8 (``_acos01``).
    """
    if c >= 1.0:
        return 1.0
    if c <= -1.0:
        return 0.0
    a = math.pi - _acos01(c) if c >= 0.0 else _acos01(-c)
    return (a + c * math.sqrt(1.0 - c * c)) * (1.0 / math.pi)


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


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _rotate(E, q, r, dt):
    """E <- E exp(dt [omega]x), omega = (0, q, r) in the element frame (Rodrigues), in place.

    With ``phi = omega dt`` and ``th = |phi|``: ``exp([phi]x) = I + a [phi]x + b [phi]x^2``,
    ``a = sin(th) / th``, ``b = (1 - cos(th)) / th^2``, both series in ``th^2`` for small steps (no
    square root, no division).
    """
    wy, wz = q * dt, r * dt
    t2 = wy * wy + wz * wz
    if t2 < 1e-4:  # th < 1e-2: the series to round-off (next terms th^6 / 362880, th^6 / 3628800 < 1e-17)
        a = 1.0 - t2 / 6.0 * (1.0 - t2 / 20.0 * (1.0 - t2 / 42.0))
        b = 0.5 - t2 / 24.0 * (1.0 - t2 / 30.0 * (1.0 - t2 / 56.0))
    else:
        th = math.sqrt(t2)
        a = math.sin(th) / th
        b = (1.0 - math.cos(th)) / t2
    # rows of the body-frame rotation I + a [phi]x + b [phi]x^2, phi = (0, wy, wz)
    r00, r01, r02 = 1.0 - b * t2, -a * wz, a * wy
    r10, r11, r12 = a * wz, 1.0 - b * wz * wz, b * wy * wz
    r20, r21, r22 = -a * wy, r12, 1.0 - b * wy * wy
    for i in range(3):
        x, y, z = E[i, 0], E[i, 1], E[i, 2]
        E[i, 0] = x * r00 + y * r10 + z * r20
        E[i, 1] = x * r01 + y * r11 + z * r21
        E[i, 2] = x * r02 + y * r12 + z * r22


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def joint_points(R, E, nu, om, half, k):
    """Front (a) and aft (b) connection points of element k and their velocities, as
    ``(a_x, a_y, a_z, va_x, va_y, va_z, b_x, b_y, b_z, vb_x, vb_y, vb_z)``."""
    u, v, w, q, r = nu[k, 0], nu[k, 1], nu[k, 2], om[k, 0], om[k, 1]
    e1x, e1y, e1z = E[k, 0, 0], E[k, 1, 0], E[k, 2, 0]
    Vx = e1x * u + E[k, 0, 1] * v + E[k, 0, 2] * w
    Vy = e1y * u + E[k, 1, 1] * v + E[k, 1, 2] * w
    Vz = e1z * u + E[k, 2, 1] * v + E[k, 2, 2] * w
    # omega x e1 = -q e3 + r e2
    Ox = -q * E[k, 0, 2] + r * E[k, 0, 1]
    Oy = -q * E[k, 1, 2] + r * E[k, 1, 1]
    Oz = -q * E[k, 2, 2] + r * E[k, 2, 1]
    return (R[k, 0] - half * e1x, R[k, 1] - half * e1y, R[k, 2] - half * e1z,
            Vx - half * Ox, Vy - half * Oy, Vz - half * Oz,
            R[k, 0] + half * e1x, R[k, 1] + half * e1y, R[k, 2] + half * e1z,
            Vx + half * Ox, Vy + half * Oy, Vz + half * Oz)


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


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _joint(P, gx, gy, gz, dx, dy, dz, ax, ay, az, al):
    """The joint law: the force on the previous body (towards the next one) for the gap ``g`` between
    the connection points, its rate ``d`` and the joint's unit axis ``a`` (the mean of its elements,
    of length ``al`` before normalising).

    Returns ``(f, h, a, c_axial, c_across, tension)``, 12 floats: ``h`` the gradient of the spring's
    energy with respect to the unnormalised axis (see ``_step``), the dampers' coefficients along
    and across the axis, and the tension along it (0 when slack).

    Along the axis the spring pulls ``k g_a`` in tension (``g_a = g . a > 0``) with the damper
    ``c_x``; while the gap closes (the next element's end sliding into the previous one) it takes no
    compression until the overlap reaches half an element, and ``k_t (g_a + l/2)`` beyond (a stop,
    so that elements cannot slide along each other without end). Across the axis the points are
    pinned by the penalty stiffness ``k_t`` and the damper ``c_t``.
    """
    kt, ct = P[P_KT], P[P_CT]
    gl = gx * ax + gy * ay + gz * az
    ga = dx * ax + dy * ay + dz * az
    if gl > 0.0:
        fs = P[P_K] * gl
        cax = P[P_CX]
    else:
        fs = kt * min(gl + 0.5 * P[P_L], 0.0)
        cax = 0.0
    fa = fs + cax * ga
    # along: fa; across: kt g + ct d
    fx = kt * (gx - gl * ax) + ct * (dx - ga * ax) + fa * ax
    fy = kt * (gy - gl * ay) + ct * (dy - ga * ay) + fa * ay
    fz = kt * (gz - gl * az) + ct * (dz - ga * az) + fa * az
    # the spring energy's gradient with respect to the unnormalised axis; a joint bent past 120 degrees
    # (al < 1) goes without it rather than divide by a vanishing al
    c = (fs - kt * gl) / al if al >= 1.0 else 0.0
    tension = max(fa, 0.0) if gl > 0.0 else 0.0
    return (fx, fy, fz, c * (gx - gl * ax), c * (gy - gl * ay), c * (gz - gl * az), ax, ay, az, cax, ct, tension)


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _element(k, R, E, nu, om, P, front, aft, inv_dt, ma_now, ma_prev):
    """Loads on element k in its frame: weight, buoyancy, drag and water entry at three Gauss points,
    and its two joints (``front``, ``aft``: ``_joint``'s tuples; the front joint's force acts on
    this element with the opposite sign).

    Returns ``(F_x, F_y, F_z, M_q, M_r, D_u, D_v, D_w, D_q, D_r, M_y, I)``: force, moment, the joint
    dampers' diagonal in the element's own velocities, its transverse mass and inertia (wetted).
    """
    half = 0.5 * P[P_L]
    rho, g, m, d, area = P[P_RHO], P[P_G], P[P_M], P[P_D], P[P_AREA]
    e1z, e2z, e3z = E[k, 2, 0], E[k, 2, 1], E[k, 2, 2]
    rv = 0.5 * d * math.sqrt(max(1.0 - e1z * e1z, 0.0))
    inv_rv = 1.0 / rv if rv > 0.0 else 0.0
    # weight (body components of -m g z)
    fx = -m * g * e1z
    fy = -m * g * e2z
    fz = -m * g * e3z
    mq = 0.0
    mr = 0.0
    wet = 0.0
    wet2 = 0.0
    u, v, w, q, r = nu[k, 0], nu[k, 1], nu[k, 2], om[k, 0], om[k, 1]
    for ip in range(3):
        s = _GP[ip] * half
        wl = _GW[ip] * half
        z = R[k, 2] + s * e1z
        fr = _immersed(-z * inv_rv) if rv > 0.0 else (1.0 if z < 0.0 else 0.0)
        ma_p = P[P_CA] * rho * area * fr * wl
        grow = (ma_p - ma_prev[k, ip]) * inv_dt
        ma_now[k, ip] = ma_p
        if fr <= 0.0:
            continue
        wet += fr * wl
        wet2 += fr * wl * s * s
        bz = rho * g * area * fr * wl  # buoyancy, up
        px, py, pz = bz * e1z, bz * e2z, bz * e3z
        # the point's body velocity (u, v + s r, w - s q), still water
        vp = v + s * r
        wp = w - s * q
        if P[P_DRAG] > 0.0:
            vn = math.sqrt(vp * vp + wp * wp)
            qd = 0.5 * rho * d * fr * wl
            px -= qd * math.pi * P[P_CF] * abs(u) * u
            py -= qd * P[P_CD] * vn * vp
            pz -= qd * P[P_CD] * vn * wp
        # the seabed: a penalty spring and damper on the point's share of the projected area d wl (pressing, never
        # pulling) and Coulomb friction against its horizontal velocity, regularised (as the mooring model's)
        pen = -P[P_DEPTH] - z
        if pen > 0.0:
            gx = E[k, 0, 0] * u + E[k, 0, 1] * vp + E[k, 0, 2] * wp
            gy = E[k, 1, 0] * u + E[k, 1, 1] * vp + E[k, 1, 2] * wp
            gz = E[k, 2, 0] * u + E[k, 2, 1] * vp + E[k, 2, 2] * wp
            area_b = d * wl
            fn = max(P[P_KBOT] * area_b * pen - P[P_CBOT] * area_b * gz, 0.0)
            sl = math.sqrt(gx * gx + gy * gy + P[P_VFRIC] * P[P_VFRIC])
            tx, ty = -P[P_MU] * fn * gx / sl, -P[P_MU] * fn * gy / sl
            px += E[k, 0, 0] * tx + E[k, 1, 0] * ty + E[k, 2, 0] * fn
            py += E[k, 0, 1] * tx + E[k, 1, 1] * ty + E[k, 2, 1] * fn
            pz += E[k, 0, 2] * tx + E[k, 1, 2] * ty + E[k, 2, 2] * fn
        # water entry: the momentum given to the point's growing added mass, at the point's velocity
        if grow > 0.0:
            py -= grow * vp
            pz -= grow * wp
        fx += px
        fy += py
        fz += pz
        mq -= s * pz
        mr += s * py
    # the joints: force (minus the front joint's, plus the aft's) at s = -+l/2, the torque of the
    # joint's turning axis, and the diagonal of the joint dampers in (u, v, w, q, r)
    du = dv = dw = 0.0
    for side in range(2):
        jt = front if side == 0 else aft
        sgn = -1.0 if side == 0 else 1.0
        gx, gy, gz = sgn * jt[0], sgn * jt[1], sgn * jt[2]
        bx = E[k, 0, 0] * gx + E[k, 1, 0] * gy + E[k, 2, 0] * gz
        by = E[k, 0, 1] * gx + E[k, 1, 1] * gy + E[k, 2, 1] * gz
        bzz = E[k, 0, 2] * gx + E[k, 1, 2] * gy + E[k, 2, 2] * gz
        h2 = E[k, 0, 1] * jt[3] + E[k, 1, 1] * jt[4] + E[k, 2, 1] * jt[5]
        h3 = E[k, 0, 2] * jt[3] + E[k, 1, 2] * jt[4] + E[k, 2, 2] * jt[5]
        a1 = E[k, 0, 0] * jt[6] + E[k, 1, 0] * jt[7] + E[k, 2, 0] * jt[8]
        a2 = E[k, 0, 1] * jt[6] + E[k, 1, 1] * jt[7] + E[k, 2, 1] * jt[8]
        a3 = E[k, 0, 2] * jt[6] + E[k, 1, 2] * jt[7] + E[k, 2, 2] * jt[8]
        fx += bx
        fy += by
        fz += bzz
        mq += h3 - sgn * half * bzz
        mr += sgn * half * by - h2
        cd = jt[9] - jt[10]
        du += jt[10] + cd * a1 * a1
        dv += jt[10] + cd * a2 * a2
        dw += jt[10] + cd * a3 * a3
    return (fx, fy, fz, mq, mr, du, dv, dw, half * half * dw, half * half * dv,
            m + P[P_CA] * rho * area * wet, P[P_I] + P[P_CA] * rho * area * wet2)


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _damper_block(E, k, l, sk, sl, jt, coef, out):
    """out += coef B(sk)^T (E_k^T C E_l) B(sl): the damper of joint ``jt`` (``_joint``'s tuple: its axis a and
    coefficients c_x along it and c_t across, ``C = c_t I + (c_x - c_t) a a^T``) between the point ``sk e1`` of
    element k and ``sl e1`` of element l, in their velocities ``(u, v, w, q, r)``; ``B(s)`` maps them to the
    point's body velocity ``(u, v + s r, w - s q)``."""
    ct, cd = coef * jt[10], coef * (jt[9] - jt[10])
    ak0 = E[k, 0, 0] * jt[6] + E[k, 1, 0] * jt[7] + E[k, 2, 0] * jt[8]
    ak1 = E[k, 0, 1] * jt[6] + E[k, 1, 1] * jt[7] + E[k, 2, 1] * jt[8]
    ak2 = E[k, 0, 2] * jt[6] + E[k, 1, 2] * jt[7] + E[k, 2, 2] * jt[8]
    if k == l:  # E_k^T E_k = I
        al0, al1, al2 = ak0, ak1, ak2
        g00, g01, g02 = ct + cd * ak0 * ak0, cd * ak0 * ak1, cd * ak0 * ak2
        g10, g11, g12 = g01, ct + cd * ak1 * ak1, cd * ak1 * ak2
        g20, g21, g22 = g02, g12, ct + cd * ak2 * ak2
    else:
        al0 = E[l, 0, 0] * jt[6] + E[l, 1, 0] * jt[7] + E[l, 2, 0] * jt[8]
        al1 = E[l, 0, 1] * jt[6] + E[l, 1, 1] * jt[7] + E[l, 2, 1] * jt[8]
        al2 = E[l, 0, 2] * jt[6] + E[l, 1, 2] * jt[7] + E[l, 2, 2] * jt[8]

        def ee(r, c):
            return E[k, 0, r] * E[l, 0, c] + E[k, 1, r] * E[l, 1, c] + E[k, 2, r] * E[l, 2, c]

        g00, g01, g02 = ct * ee(0, 0) + cd * ak0 * al0, ct * ee(0, 1) + cd * ak0 * al1, ct * ee(0, 2) + cd * ak0 * al2
        g10, g11, g12 = ct * ee(1, 0) + cd * ak1 * al0, ct * ee(1, 1) + cd * ak1 * al1, ct * ee(1, 2) + cd * ak1 * al2
        g20, g21, g22 = ct * ee(2, 0) + cd * ak2 * al0, ct * ee(2, 1) + cd * ak2 * al1, ct * ee(2, 2) + cd * ak2 * al2
    # H = G B(sl) (rows r: (g_r0, g_r1, g_r2, -sl g_r2, sl g_r1)), out += B(sk)^T H (rows 0-2: H, 3: -sk H_2, 4: sk H_1)
    out[0, 0] += g00
    out[0, 1] += g01
    out[0, 2] += g02
    out[0, 3] -= sl * g02
    out[0, 4] += sl * g01
    out[1, 0] += g10
    out[1, 1] += g11
    out[1, 2] += g12
    out[1, 3] -= sl * g12
    out[1, 4] += sl * g11
    out[2, 0] += g20
    out[2, 1] += g21
    out[2, 2] += g22
    out[2, 3] -= sl * g22
    out[2, 4] += sl * g21
    out[3, 0] -= sk * g20
    out[3, 1] -= sk * g21
    out[3, 2] -= sk * g22
    out[3, 3] += sk * sl * g22
    out[3, 4] -= sk * sl * g21
    out[4, 0] += sk * g10
    out[4, 1] += sk * g11
    out[4, 2] += sk * g12
    out[4, 3] -= sk * sl * g12
    out[4, 4] += sk * sl * g11


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _bending_block(E, k, l, coef, out):
    """out[3:, 3:] += coef P_k^T P_l, ``P_k = [e2 e3]`` of element k: the bending damper's moment on k per
    rotation rate (q, r) of l."""
    for r in range(2):
        for c in range(2):
            out[3 + r, 3 + c] += coef * (E[k, 0, 1 + r] * E[l, 0, 1 + c] + E[k, 1, 1 + r] * E[l, 1, 1 + c]
                                         + E[k, 2, 1 + r] * E[l, 2, 1 + c])


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _solve5(S, U, y, W, z, with_u):
    """W = S^-1 U (when ``with_u``) and z = S^-1 y for the symmetric positive definite 5x5 ``S`` (Gaussian
    elimination without pivoting; S and U are overwritten)."""
    for p in range(5):
        inv = 1.0 / S[p, p]
        for i in range(p + 1, 5):
            f = S[i, p] * inv
            if f != 0.0:
                for c in range(p + 1, 5):
                    S[i, c] -= f * S[p, c]
                y[i] -= f * y[p]
                if with_u:
                    for c in range(5):
                        U[i, c] -= f * U[p, c]
    for i in range(4, -1, -1):
        s = y[i]
        for c in range(i + 1, 5):
            s -= S[i, c] * z[c]
        z[i] = s / S[i, i]
        if with_u:
            for cc in range(5):
                s = U[i, cc]
                for c in range(i + 1, 5):
                    s -= S[i, c] * W[c, cc]
                W[i, cc] = s / S[i, i]


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def _step(R, E, nu, om, first, P, tug_p, tug_v, bs, bxt, bzt, inert, tension, slack, ma_now, ma_prev, dt, work,
          Wb, zb, blk):
    """One explicit step of the line (``dt = 0``: the joints' tensions and the wetted inertias only);
    returns the barge joint's force on the line ahead (x, y) and whether the new state is finite.

    One pass over the joints, j = first the tug's, j = n the barge's (joint j joins element j-1's aft
    point to element j's front one); once joint j is known, element j - 1 has all its loads and
    takes its step (no joint needs its old state any more).

    The joints' springs have the energy ``U(g, a)`` of the gap ``g`` and the joint's axis
    ``a = s / |s|``, ``s`` the sum of its elements' directions ``e1``: as ``a`` turns with the
    elements, each feels the torque ``-e1 x dU/ds``, which keeps the spring conservative.

    Material damping of bending at a taut joint j: the moment ``c_m (omega_j - omega_{j-1})``,
    ``c_m = 2 zeta_m sqrt(T (l/2) I)`` with ``I`` the mean wetted inertia of the two elements (element
    j's from the previous step: it has not been loaded yet).

    The dampers (joints' and bending) are implicit along the line: each element's row of the block
    tri-diagonal velocity update is eliminated as soon as its loads are known (:func:`_eliminate`), and the
    elements move in a back substitution after the pass (:func:`_back_substitute`).

    ``inert`` (N) holds the wetted inertias, in and out; ``ma_now`` (N, 3) receives the added mass of
    each Gauss point's share of the element; with ``dt > 0`` its growth since ``ma_prev`` gives the
    water-entry impact. ``work`` is (2, 3) scratch; ``Wb`` (N, 5, 5), ``zb`` (N, 5) and ``blk`` (5, 5, 5)
    the implicit update's (unused when ``dt = 0``).
    """
    n = R.shape[0]
    half = 0.5 * P[P_L]
    inv_dt = 1.0 / dt if dt > 0.0 and P[P_IMPACT] > 0.0 else 0.0
    cz = 2.0 * P[P_ZM] * math.sqrt(0.5 * half)
    qb, wb = work[0], work[1]
    # the previous body's aft point and its velocity: the tug's tow point first
    px, py, pz = tug_p[0], tug_p[1], tug_p[2]
    vx, vy, vz = tug_v[0], tug_v[1], tug_v[2]
    prev = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    cur = prev
    bq = br = bd = 0.0  # bending damping of the previous joint on the element being finished
    cm_front = cm_aft = 0.0
    finite = True
    blk[1, :, :] = 0.0  # nothing eliminated before the first element
    blk[2, 0, :] = 0.0
    for j in range(first, n + 1):
        # the next body's front point (q, w), and the axis sum s of the joint's elements
        sx = sy = sz = 0.0
        if j > first:
            sx, sy, sz = E[j - 1, 0, 0], E[j - 1, 1, 0], E[j - 1, 2, 0]
        if j == n:
            barge_point(bs, bxt, bzt, qb, wb)
            qx, qy, qz, wx, wy, wz = qb[0], qb[1], qb[2], wb[0], wb[1], wb[2]
            ax_, ay_, az_, bvx, bvy, bvz = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
        else:
            qx, qy, qz, wx, wy, wz, ax_, ay_, az_, bvx, bvy, bvz = joint_points(R, E, nu, om, half, j)
            sx += E[j, 0, 0]
            sy += E[j, 1, 0]
            sz += E[j, 2, 0]
        gx, gy, gz = qx - px, qy - py, qz - pz
        if j == first and first > 0:
            # paying out from the bitt: the brake tension along the line, no spring
            gl = math.sqrt(gx * gx + gy * gy + gz * gz)
            if gl > 0.0 and P[P_BRAKE] > 0.0:
                b = P[P_BRAKE] / gl
                cur = (b * gx, b * gy, b * gz, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, P[P_BRAKE])
                slack[j] = False
            else:
                cur = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
                slack[j] = True
        else:
            al = math.sqrt(sx * sx + sy * sy + sz * sz)
            if al < 1e-9:  # folded back on itself: the aft element's direction
                sx, sy, sz, ia = E[j, 0, 0], E[j, 1, 0], E[j, 2, 0], 1.0
            else:
                ia = 1.0 / al
            cur = _joint(P, gx, gy, gz, wx - vx, wy - vy, wz - vz, sx * ia, sy * ia, sz * ia, al)
            slack[j] = (gx * sx + gy * sy + gz * sz) <= 0.0
        tension[j] = cur[11]
        if j > first:
            k = j - 1
            ld = _element(k, R, E, nu, om, P, prev, cur, inv_dt, ma_now, ma_prev)
            mq, mr = ld[3] + bq, ld[4] + br
            cm_front, cm_aft = bd, 0.0
            bq = br = bd = 0.0
            if j < n and cz > 0.0 and cur[11] > 0.0:
                # bending damping at joint j, on element k now and on element j when it is finished
                cm = cz * math.sqrt(cur[11] * (ld[11] + inert[j]))
                rx = om[j, 0] * E[j, 0, 1] + om[j, 1] * E[j, 0, 2] - om[k, 0] * E[k, 0, 1] - om[k, 1] * E[k, 0, 2]
                ry = om[j, 0] * E[j, 1, 1] + om[j, 1] * E[j, 1, 2] - om[k, 0] * E[k, 1, 1] - om[k, 1] * E[k, 1, 2]
                rz = om[j, 0] * E[j, 2, 1] + om[j, 1] * E[j, 2, 2] - om[k, 0] * E[k, 2, 1] - om[k, 1] * E[k, 2, 2]
                mq += cm * (rx * E[k, 0, 1] + ry * E[k, 1, 1] + rz * E[k, 2, 1])
                mr += cm * (rx * E[k, 0, 2] + ry * E[k, 1, 2] + rz * E[k, 2, 2])
                cm_aft = cm
                bq = -cm * (rx * E[j, 0, 1] + ry * E[j, 1, 1] + rz * E[j, 2, 1])
                br = -cm * (rx * E[j, 0, 2] + ry * E[j, 1, 2] + rz * E[j, 2, 2])
                bd = cm
            inert[k] = ld[11]
            if dt > 0.0:
                _eliminate(k, j, n, E, nu, om, P, ld, mq, mr, prev, cur, cm_front, cm_aft, dt, Wb, zb, blk)
        prev = cur
        px, py, pz, vx, vy, vz = ax_, ay_, az_, bvx, bvy, bvz
    if dt > 0.0:
        finite = _back_substitute(first, n, R, E, nu, om, dt, Wb, zb, blk)
    return cur[0], cur[1], finite


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _eliminate(k, j, n, E, nu, om, P, ld, mq, mr, front, aft, cm_front, cm_aft, dt, Wb, zb, blk):
    """Element k's row of the dampers' implicit velocity update, eliminated forward along the line.

    The step solves ``(M + dt D) dx = dt f`` for the velocity increments ``dx = (du, dv, dw, dq, dr)`` of all
    elements at once: ``M`` the elements' (wetted) masses and inertias, ``f`` their loads and Coriolis terms at
    the step's start, ``D`` the joint dampers' and bending dampers' matrix, block tri-diagonal (5x5 blocks: a
    joint couples its two elements). Backward Euler in the dampers along the whole line, so that elements moving
    together (no relative velocity at a joint) feel no damper and no inertia from it. Forward elimination: with
    ``T_k = U_{k-1}^T W_{k-1}``, ``t_k = U_{k-1}^T z_{k-1}`` from element k - 1 (``blk[1]``, ``blk[2, 0]``),
    ``W_k = (A_k - T_k)^-1 U_k`` and ``z_k = (A_k - T_k)^-1 (dt f_k - t_k)``, ``U_k`` the coupling to element k + 1
    through joint j = k + 1 (none at the barge's joint); :func:`_back_substitute` finishes the step."""
    half = 0.5 * P[P_L]
    m = P[P_M]
    u, v, w, q, r = nu[k, 0], nu[k, 1], nu[k, 2], om[k, 0], om[k, 1]
    my, ik = ld[10], ld[11]
    S, U, T = blk[0], blk[3], blk[1]
    y = blk[2, 1]
    for a in range(5):
        for c in range(5):
            S[a, c] = -T[a, c]
            U[a, c] = 0.0
    S[0, 0] += m
    S[1, 1] += my
    S[2, 2] += my
    S[3, 3] += ik
    S[4, 4] += ik
    if front[9] != 0.0 or front[10] != 0.0:
        _damper_block(E, k, k, -half, -half, front, dt, S)
    if aft[9] != 0.0 or aft[10] != 0.0:
        _damper_block(E, k, k, half, half, aft, dt, S)
    S[3, 3] += dt * (cm_front + cm_aft)
    S[4, 4] += dt * (cm_front + cm_aft)
    y[0] = dt * (ld[0] - q * my * w + r * my * v) - blk[2, 0, 0]
    y[1] = dt * (ld[1] - r * m * u) - blk[2, 0, 1]
    y[2] = dt * (ld[2] + q * m * u) - blk[2, 0, 2]
    y[3] = dt * (mq - (m - my) * u * w) - blk[2, 0, 3]
    y[4] = dt * (mr - (my - m) * u * v) - blk[2, 0, 4]
    inner = j < n
    if inner:
        if aft[9] != 0.0 or aft[10] != 0.0:
            _damper_block(E, k, j, half, -half, aft, -dt, U)
        if cm_aft != 0.0:
            _bending_block(E, k, j, -dt * cm_aft, U)
    # keep U (for T of the next element), as the solve overwrites it
    for a in range(5):
        for c in range(5):
            T[a, c] = U[a, c]
    _solve5(S, U, y, Wb[k], zb[k], inner)
    # the next element's share: T = U^T W, t = U^T z (zero after the last)
    for a in range(5):
        s = 0.0
        for c in range(5):
            s += T[c, a] * zb[k, c]
        blk[2, 0, a] = s if inner else 0.0
    for a in range(5):
        for b in range(5):
            s = 0.0
            if inner:
                for c in range(5):
                    s += T[c, a] * Wb[k, c, b]
            blk[4, a, b] = s
    for a in range(5):
        for b in range(5):
            T[a, b] = blk[4, a, b]


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _back_substitute(first, n, R, E, nu, om, dt, Wb, zb, blk):
    """The velocity increments ``dx_k = z_k - W_k dx_{k+1}`` from the barge's end back to the first element off
    the bitt, each element's new velocities, then its position and frame with them (symplectic Euler). Returns
    whether the new state is finite."""
    x = blk[2, 1]
    for a in range(5):
        x[a] = 0.0
    finite = True
    for k in range(n - 1, first - 1, -1):
        for a in range(5):
            s = zb[k, a]
            if k < n - 1:
                for c in range(5):
                    s -= Wb[k, a, c] * x[c]
            blk[2, 2, a] = s
        for a in range(5):
            x[a] = blk[2, 2, a]
        u2, v2, w2 = nu[k, 0] + x[0], nu[k, 1] + x[1], nu[k, 2] + x[2]
        q2, r2 = om[k, 0] + x[3], om[k, 1] + x[4]
        nu[k, 0], nu[k, 1], nu[k, 2], om[k, 0], om[k, 1] = u2, v2, w2, q2, r2
        for i in range(3):
            R[k, i] += dt * (E[k, i, 0] * u2 + E[k, i, 1] * v2 + E[k, i, 2] * w2)
        _rotate(E[k], q2, r2, dt)
        finite = finite and math.isfinite(R[k, 0] + nu[k, 0] + om[k, 1])
    return finite


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def _release(R, E, nu, om, k, P, tug_p, tug_v, bs, bxt, bzt):
    """Element k leaves the bitt: straight from the tug's tow point to its aft neighbour's front."""
    n = R.shape[0]
    half = 0.5 * P[P_L]
    pb, vb = np.zeros(3), np.zeros(3)
    if k + 1 == n:
        barge_point(bs, bxt, bzt, pb, vb)
    else:
        front = joint_points(R, E, nu, om, half, k + 1)
        for i in range(3):
            pb[i], vb[i] = front[i], front[3 + i]
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
def evaluate(R, E, nu, om, first, P, tug_p, tug_v, bs, bxt, bzt, inert, tension, slack, ma):
    """Joint tensions, slack flags, the wetted inertias ``inert`` (N) and the added masses ``ma`` (N, 3)
    of the Gauss points' shares, for the state as it is (a step of zero length)."""
    _step(R, E, nu, om, first, P, tug_p, tug_v, bs, bxt, bzt, inert, tension, slack, ma, ma, 0.0, np.zeros((2, 3)),
          np.zeros((0, 5, 5)), np.zeros((0, 5)), np.zeros((5, 5, 5)))


@njit(cache=True, error_model="numpy", fastmath=_FAST)
def run_steps(dt, tug_p, tug_v, R, E, nu, om, first_arr, P, bs, bpar, bxt, bzt, held, ma, inert, tension, slack):
    """Advance ``len(tug_p) - 1`` explicit steps of ``dt``; ``tug_p``, ``tug_v`` at the step times.

    ``first_arr[0]`` is the first element off the bitt (0 when the whole line is out); ``ma`` (N, 3)
    the Gauss points' added masses and ``inert`` (N) the wetted inertias, in and out. Returns the
    number of steps taken, fewer when a state is no longer finite.
    """
    n = R.shape[0]
    ma_prev, ma_now = ma, np.zeros((n, 3))  # swapped after each step
    work = np.zeros((2, 3))
    Wb, zb, blk = np.zeros((n, 5, 5)), np.zeros((n, 5)), np.zeros((5, 5, 5))  # the dampers' implicit solve
    qb, wb = np.zeros(3), np.zeros(3)
    half = 0.5 * P[P_L]
    nstep = tug_p.shape[0] - 1
    for step in range(nstep):
        first = first_arr[0]
        fbx, fby, finite = _step(R, E, nu, om, first, P, tug_p[step], tug_v[step], bs, bxt, bzt, inert, tension,
                                 slack, ma_now, ma_prev, dt, work, Wb, zb, blk)
        ma_prev, ma_now = ma_now, ma_prev
        # the barge: towline force at its tow point (minus joint n's force on the previous body)
        if not held:
            c, s = math.cos(bs[B_PSI]), math.sin(bs[B_PSI])
            fxg = -fbx
            fyg = -fby
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
                front = joint_points(R, E, nu, om, half, first)
                for i in range(3):
                    qb[i] = front[i]
            d2 = 0.0
            for i in range(3):
                d2 += (qb[i] - tug_p[step + 1, i]) ** 2
            if d2 >= P[P_L] * P[P_L]:
                _release(R, E, nu, om, first - 1, P, tug_p[step + 1], tug_v[step + 1], bs, bxt, bzt)
                ma_prev[first - 1, :] = 0.0
                first_arr[0] = first - 1
        if not finite:
            if step % 2 == 0:
                ma[:] = ma_prev
            return step
    if nstep % 2 == 1:
        ma[:] = ma_prev
    return nstep

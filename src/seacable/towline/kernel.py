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

from .._jit import copy_2d, njit
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
_NO_FRAME = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)  # E_k^T E_l where there is no element l

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
    out[0, 0], out[1, 0], out[2, 0] = e1[0], e1[1], e1[2]
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

    Returns ``(F_x, F_y, F_z, M_q, M_r, M_y, I)``: force, moment, its transverse mass and inertia (wetted). The
    joints' dampers here are their forces at the step's start; their implicit part is :func:`_eliminate`'s.
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
    # the joints: force (minus the front joint's, plus the aft's) at s = -+l/2, and the torque of the joint's
    # turning axis
    for side in range(2):
        jt = front if side == 0 else aft
        sgn = -1.0 if side == 0 else 1.0
        gx, gy, gz = sgn * jt[0], sgn * jt[1], sgn * jt[2]
        bx = E[k, 0, 0] * gx + E[k, 1, 0] * gy + E[k, 2, 0] * gz
        by = E[k, 0, 1] * gx + E[k, 1, 1] * gy + E[k, 2, 1] * gz
        bzz = E[k, 0, 2] * gx + E[k, 1, 2] * gy + E[k, 2, 2] * gz
        h2 = E[k, 0, 1] * jt[3] + E[k, 1, 1] * jt[4] + E[k, 2, 1] * jt[5]
        h3 = E[k, 0, 2] * jt[3] + E[k, 1, 2] * jt[4] + E[k, 2, 2] * jt[5]
        fx += bx
        fy += by
        fz += bzz
        mq += h3 - sgn * half * bzz
        mr += sgn * half * by - h2
    return fx, fy, fz, mq, mr, m + P[P_CA] * rho * area * wet, P[P_I] + P[P_CA] * rho * area * wet2


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _in_frame(E, k, jt):
    """The axis of joint ``jt`` (``_joint``'s tuple) in element k's frame, ``E_k^T a``."""
    return (E[k, 0, 0] * jt[6] + E[k, 1, 0] * jt[7] + E[k, 2, 0] * jt[8],
            E[k, 0, 1] * jt[6] + E[k, 1, 1] * jt[7] + E[k, 2, 1] * jt[8],
            E[k, 0, 2] * jt[6] + E[k, 1, 2] * jt[7] + E[k, 2, 2] * jt[8])


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _relative_frame(E, k, l):
    """``E_k^T E_l`` row by row (9 values): entry (r, c) is column r of ``E_k`` dotted with column c of ``E_l``."""
    return (E[k, 0, 0] * E[l, 0, 0] + E[k, 1, 0] * E[l, 1, 0] + E[k, 2, 0] * E[l, 2, 0],
            E[k, 0, 0] * E[l, 0, 1] + E[k, 1, 0] * E[l, 1, 1] + E[k, 2, 0] * E[l, 2, 1],
            E[k, 0, 0] * E[l, 0, 2] + E[k, 1, 0] * E[l, 1, 2] + E[k, 2, 0] * E[l, 2, 2],
            E[k, 0, 1] * E[l, 0, 0] + E[k, 1, 1] * E[l, 1, 0] + E[k, 2, 1] * E[l, 2, 0],
            E[k, 0, 1] * E[l, 0, 1] + E[k, 1, 1] * E[l, 1, 1] + E[k, 2, 1] * E[l, 2, 1],
            E[k, 0, 1] * E[l, 0, 2] + E[k, 1, 1] * E[l, 1, 2] + E[k, 2, 1] * E[l, 2, 2],
            E[k, 0, 2] * E[l, 0, 0] + E[k, 1, 2] * E[l, 1, 0] + E[k, 2, 2] * E[l, 2, 0],
            E[k, 0, 2] * E[l, 0, 1] + E[k, 1, 2] * E[l, 1, 1] + E[k, 2, 2] * E[l, 2, 1],
            E[k, 0, 2] * E[l, 0, 2] + E[k, 1, 2] * E[l, 1, 2] + E[k, 2, 2] * E[l, 2, 2])


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _damper_own(s, jt, coef, a):
    """``coef B(s)^T (E_k^T C E_k) B(s)``, the lower triangle row by row (15 values): the damper of joint ``jt``
    (``_joint``'s tuple: its coefficients c_x along its axis and c_t across, ``C = c_t I + (c_x - c_t) a a^T``) at
    the point ``s e1`` of element k, in its velocities ``(u, v, w, q, r)``, with ``a`` the axis in k's frame
    (:func:`_in_frame`); ``B(s)`` maps the velocities to the point's body velocity ``(u, v + s r, w - s q)``."""
    ct, cd = coef * jt[10], coef * (jt[9] - jt[10])
    a0, a1, a2 = a
    g00, g11, g22 = ct + cd * a0 * a0, ct + cd * a1 * a1, ct + cd * a2 * a2
    g10, g20, g21 = cd * a1 * a0, cd * a2 * a0, cd * a2 * a1
    s2 = s * s
    return (g00,
            g10, g11,
            g20, g21, g22,
            -s * g20, -s * g21, -s * g22, s2 * g22,
            s * g10, s * g11, s * g21, -s2 * g21, s2 * g11)


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _damper_coupling(sk, sl, jt, coef, cb, ak, al, ee):
    """``coef B(sk)^T (E_k^T C E_l) B(sl)`` (:func:`_damper_own`) between the point ``sk e1`` of element k and
    ``sl e1`` of element l, plus the bending damper's ``cb P_k^T P_l`` (``P = [e2 e3]``: its moment on k per
    rotation rate (q, r) of l) in the rotations' block: the 5x5 block row by row (25 values). ``ak``, ``al``:
    the joint's axis in the frames of k and l; ``ee``: ``E_k^T E_l`` row by row (:func:`_relative_frame`)."""
    ct, cd = coef * jt[10], coef * (jt[9] - jt[10])
    ak0, ak1, ak2 = ak
    al0, al1, al2 = al
    e00, e01, e02, e10, e11, e12, e20, e21, e22 = ee
    g00, g01, g02 = ct * e00 + cd * ak0 * al0, ct * e01 + cd * ak0 * al1, ct * e02 + cd * ak0 * al2
    g10, g11, g12 = ct * e10 + cd * ak1 * al0, ct * e11 + cd * ak1 * al1, ct * e12 + cd * ak1 * al2
    g20, g21, g22 = ct * e20 + cd * ak2 * al0, ct * e21 + cd * ak2 * al1, ct * e22 + cd * ak2 * al2
    # G B(sl) has the rows (g_r0, g_r1, g_r2, -sl g_r2, sl g_r1); B(sk)^T adds the rows -sk (row 2), sk (row 1)
    ss = sk * sl
    return (g00, g01, g02, -sl * g02, sl * g01,
            g10, g11, g12, -sl * g12, sl * g11,
            g20, g21, g22, -sl * g22, sl * g21,
            -sk * g20, -sk * g21, -sk * g22, ss * g22 + cb * e11, -ss * g21 + cb * e12,
            sk * g10, sk * g11, sk * g12, -ss * g12 + cb * e21, ss * g11 + cb * e22)


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _step(R, E, nu, om, first, P, tug_p, tug_v, bs, bxt, bzt, inert, tension, slack, ma_now, ma_prev, dt, work,
          Wz, blk):
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
    water-entry impact. ``work`` is (2, 3) scratch; ``Wz`` (N, 5, 6) and ``blk`` (5, 6) the implicit
    update's (:func:`_eliminate`; unused when ``dt = 0``).
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
    pf = (0.0, 0.0, 0.0)  # the front joint's axis in the frame of the element being finished
    finite = True
    blk[:, :] = 0.0  # nothing eliminated before the first element
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
            if j == first or j == n:
                # an end joint's axis is its one element's direction, of unit length: al = 1 exactly, not its
                # round-off (_joint's al >= 1 kept or dropped the turning axis's torque on the last bit of |e1|)
                al = ia = 1.0
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
            inner = j < n
            ee = _relative_frame(E, k, j) if inner else _NO_FRAME
            if inner and cz > 0.0 and cur[11] > 0.0:
                # bending damping at joint j, the moment cm (Omega_j - Omega_k) (Omega = q e2 + r e3), on element k
                # now and (minus) on element j when it is finished, each in its own frame through E_k^T E_j
                cm = cz * math.sqrt(cur[11] * (ld[6] + inert[j]))
                qk, rk, qj, rj = om[k, 0], om[k, 1], om[j, 0], om[j, 1]
                mq += cm * (ee[4] * qj + ee[5] * rj - qk)
                mr += cm * (ee[7] * qj + ee[8] * rj - rk)
                cm_aft = cm
                bq = -cm * (qj - ee[4] * qk - ee[7] * rk)
                br = -cm * (rj - ee[5] * qk - ee[8] * rk)
                bd = cm
            inert[k] = ld[6]
            if dt > 0.0:
                if k == first:
                    pf = _in_frame(E, k, prev)
                pf = _eliminate(k, j, n, E, nu, om, P, ld, mq, mr, prev, cur, pf, cm_front, cm_aft, ee, dt, Wz, blk)
        prev = cur
        px, py, pz, vx, vy, vz = ax_, ay_, az_, bvx, bvy, bvz
    if dt > 0.0:
        finite = _back_substitute(first, n, R, E, nu, om, dt, Wz)
    return cur[0], cur[1], finite


@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _eliminate(k, j, n, E, nu, om, P, ld, mq, mr, front, aft, pf, cm_front, cm_aft, ee, dt, Wz, blk):
    """Element k's row of the dampers' implicit velocity update, eliminated forward along the line.

    The step solves ``(M + dt D) dx = dt f`` for the velocity increments ``dx = (du, dv, dw, dq, dr)`` of all
    elements at once: ``M`` the elements' (wetted) masses and inertias, ``f`` their loads and Coriolis terms at
    the step's start, ``D`` the joint dampers' and bending dampers' matrix, block tri-diagonal (5x5 blocks: a
    joint couples its two elements). Backward Euler in the dampers along the whole line, so that elements moving
    together (no relative velocity at a joint) feel no damper and no inertia from it.

    Forward elimination: element k's diagonal block less what element k - 1 passed on, ``S_k = A_k - T_k``
    (symmetric positive definite), is factored ``S_k = L D L^T``; with ``U_k`` its coupling to element k + 1
    through joint j = k + 1 (none at the barge's joint) and ``y_k = dt f_k - t_k`` its right-hand side,
    ``Y = L^-1 [U_k | y_k]`` gives what passes on, ``[T_{k+1} | t_{k+1}] = U_k^T S_k^-1 [U_k | y_k] = Y^T D^-1 Y``
    (its lower triangle and last column), and ``Wz[k] = [W_k | z_k] = L^-T D^-1 Y`` is kept for
    :func:`_back_substitute`. ``blk`` (5, 6) carries ``[T | t]`` from element to element.

    ``front``, ``aft``: the joints at the element's ends (``_joint``'s tuples), ``pf`` the front joint's axis in
    the element's frame, ``cm_front``, ``cm_aft`` the bending dampers there, ``ee`` ``E_k^T E_j``. Returns the aft
    joint's axis in element j's frame, its ``pf`` (zeros after the last element)."""
    half = 0.5 * P[P_L]
    m = P[P_M]
    u, v, w, q, r = nu[k, 0], nu[k, 1], nu[k, 2], om[k, 0], om[k, 1]
    my, ik = ld[5], ld[6]
    T, X = blk, Wz[k]
    # the diagonal block: masses, the dampers of the two joints at the element's ends and the bending dampers
    pa = _in_frame(E, k, aft)
    f = _damper_own(-half, front, dt, pf)
    a = _damper_own(half, aft, dt, pa)
    cb = ik + dt * (cm_front + cm_aft)
    s00 = m + f[0] + a[0] - T[0, 0]
    s10, s11 = f[1] + a[1] - T[1, 0], my + f[2] + a[2] - T[1, 1]
    s20, s21, s22 = f[3] + a[3] - T[2, 0], f[4] + a[4] - T[2, 1], my + f[5] + a[5] - T[2, 2]
    s30, s31, s32 = f[6] + a[6] - T[3, 0], f[7] + a[7] - T[3, 1], f[8] + a[8] - T[3, 2]
    s33 = cb + f[9] + a[9] - T[3, 3]
    s40, s41, s42 = f[10] + a[10] - T[4, 0], f[11] + a[11] - T[4, 1], f[12] + a[12] - T[4, 2]
    s43, s44 = f[13] + a[13] - T[4, 3], cb + f[14] + a[14] - T[4, 4]
    # the right-hand side, dt f - t
    x05 = dt * (ld[0] - q * my * w + r * my * v) - T[0, 5]
    x15 = dt * (ld[1] - r * m * u) - T[1, 5]
    x25 = dt * (ld[2] + q * m * u) - T[2, 5]
    x35 = dt * (mq - (m - my) * u * w) - T[3, 5]
    x45 = dt * (mr - (my - m) * u * v) - T[4, 5]
    # the coupling to element j = k + 1 through joint j (none at the barge's joint)
    if j < n:
        pl = _in_frame(E, j, aft)
        c = _damper_coupling(half, -half, aft, -dt, -dt * cm_aft, pa, pl, ee)
    else:
        pl = (0.0, 0.0, 0.0)
        c = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
             0.0, 0.0, 0.0, 0.0, 0.0)
    x00, x01, x02, x03, x04 = c[0], c[1], c[2], c[3], c[4]
    x10, x11, x12, x13, x14 = c[5], c[6], c[7], c[8], c[9]
    x20, x21, x22, x23, x24 = c[10], c[11], c[12], c[13], c[14]
    x30, x31, x32, x33, x34 = c[15], c[16], c[17], c[18], c[19]
    x40, x41, x42, x43, x44 = c[20], c[21], c[22], c[23], c[24]
    # S - T = L D L^T (s_ij its lower triangle, l_ij = L's, i_p = 1 / D_p), right-looking, and Y = L^-1 X with it
    # (x_ic); then h = D^-1 Y; [T | t] = Y^T h for element k + 1; [W | z] = L^-T h into X. Unrolled into
    # scalars: as loops over arrays every operation went through memory (tests/unit/towline/test_implicit_damper.py
    # checks the result against a dense solve of the whole line's system)
    i0 = 1.0 / s00
    l10 = s10 * i0
    s11 = s11 - l10 * s10
    x10, x11, x12 = x10 - l10 * x00, x11 - l10 * x01, x12 - l10 * x02
    x13, x14, x15 = x13 - l10 * x03, x14 - l10 * x04, x15 - l10 * x05
    l20 = s20 * i0
    s21, s22 = s21 - l20 * s10, s22 - l20 * s20
    x20, x21, x22 = x20 - l20 * x00, x21 - l20 * x01, x22 - l20 * x02
    x23, x24, x25 = x23 - l20 * x03, x24 - l20 * x04, x25 - l20 * x05
    l30 = s30 * i0
    s31, s32, s33 = s31 - l30 * s10, s32 - l30 * s20, s33 - l30 * s30
    x30, x31, x32 = x30 - l30 * x00, x31 - l30 * x01, x32 - l30 * x02
    x33, x34, x35 = x33 - l30 * x03, x34 - l30 * x04, x35 - l30 * x05
    l40 = s40 * i0
    s41, s42, s43 = s41 - l40 * s10, s42 - l40 * s20, s43 - l40 * s30
    s44 = s44 - l40 * s40
    x40, x41, x42 = x40 - l40 * x00, x41 - l40 * x01, x42 - l40 * x02
    x43, x44, x45 = x43 - l40 * x03, x44 - l40 * x04, x45 - l40 * x05
    i1 = 1.0 / s11
    l21 = s21 * i1
    s22 = s22 - l21 * s21
    x20, x21, x22 = x20 - l21 * x10, x21 - l21 * x11, x22 - l21 * x12
    x23, x24, x25 = x23 - l21 * x13, x24 - l21 * x14, x25 - l21 * x15
    l31 = s31 * i1
    s32, s33 = s32 - l31 * s21, s33 - l31 * s31
    x30, x31, x32 = x30 - l31 * x10, x31 - l31 * x11, x32 - l31 * x12
    x33, x34, x35 = x33 - l31 * x13, x34 - l31 * x14, x35 - l31 * x15
    l41 = s41 * i1
    s42, s43, s44 = s42 - l41 * s21, s43 - l41 * s31, s44 - l41 * s41
    x40, x41, x42 = x40 - l41 * x10, x41 - l41 * x11, x42 - l41 * x12
    x43, x44, x45 = x43 - l41 * x13, x44 - l41 * x14, x45 - l41 * x15
    i2 = 1.0 / s22
    l32 = s32 * i2
    s33 = s33 - l32 * s32
    x30, x31, x32 = x30 - l32 * x20, x31 - l32 * x21, x32 - l32 * x22
    x33, x34, x35 = x33 - l32 * x23, x34 - l32 * x24, x35 - l32 * x25
    l42 = s42 * i2
    s43, s44 = s43 - l42 * s32, s44 - l42 * s42
    x40, x41, x42 = x40 - l42 * x20, x41 - l42 * x21, x42 - l42 * x22
    x43, x44, x45 = x43 - l42 * x23, x44 - l42 * x24, x45 - l42 * x25
    i3 = 1.0 / s33
    l43 = s43 * i3
    s44 = s44 - l43 * s43
    x40, x41, x42 = x40 - l43 * x30, x41 - l43 * x31, x42 - l43 * x32
    x43, x44, x45 = x43 - l43 * x33, x44 - l43 * x34, x45 - l43 * x35
    i4 = 1.0 / s44
    h00, h01, h02, h03, h04, h05 = x00 * i0, x01 * i0, x02 * i0, x03 * i0, x04 * i0, x05 * i0
    h10, h11, h12, h13, h14, h15 = x10 * i1, x11 * i1, x12 * i1, x13 * i1, x14 * i1, x15 * i1
    h20, h21, h22, h23, h24, h25 = x20 * i2, x21 * i2, x22 * i2, x23 * i2, x24 * i2, x25 * i2
    h30, h31, h32, h33, h34, h35 = x30 * i3, x31 * i3, x32 * i3, x33 * i3, x34 * i3, x35 * i3
    h40, h41, h42, h43, h44, h45 = x40 * i4, x41 * i4, x42 * i4, x43 * i4, x44 * i4, x45 * i4
    T[0, 0] = x00 * h00 + x10 * h10 + x20 * h20 + x30 * h30 + x40 * h40
    T[0, 5] = x00 * h05 + x10 * h15 + x20 * h25 + x30 * h35 + x40 * h45
    T[1, 0] = x01 * h00 + x11 * h10 + x21 * h20 + x31 * h30 + x41 * h40
    T[1, 1] = x01 * h01 + x11 * h11 + x21 * h21 + x31 * h31 + x41 * h41
    T[1, 5] = x01 * h05 + x11 * h15 + x21 * h25 + x31 * h35 + x41 * h45
    T[2, 0] = x02 * h00 + x12 * h10 + x22 * h20 + x32 * h30 + x42 * h40
    T[2, 1] = x02 * h01 + x12 * h11 + x22 * h21 + x32 * h31 + x42 * h41
    T[2, 2] = x02 * h02 + x12 * h12 + x22 * h22 + x32 * h32 + x42 * h42
    T[2, 5] = x02 * h05 + x12 * h15 + x22 * h25 + x32 * h35 + x42 * h45
    T[3, 0] = x03 * h00 + x13 * h10 + x23 * h20 + x33 * h30 + x43 * h40
    T[3, 1] = x03 * h01 + x13 * h11 + x23 * h21 + x33 * h31 + x43 * h41
    T[3, 2] = x03 * h02 + x13 * h12 + x23 * h22 + x33 * h32 + x43 * h42
    T[3, 3] = x03 * h03 + x13 * h13 + x23 * h23 + x33 * h33 + x43 * h43
    T[3, 5] = x03 * h05 + x13 * h15 + x23 * h25 + x33 * h35 + x43 * h45
    T[4, 0] = x04 * h00 + x14 * h10 + x24 * h20 + x34 * h30 + x44 * h40
    T[4, 1] = x04 * h01 + x14 * h11 + x24 * h21 + x34 * h31 + x44 * h41
    T[4, 2] = x04 * h02 + x14 * h12 + x24 * h22 + x34 * h32 + x44 * h42
    T[4, 3] = x04 * h03 + x14 * h13 + x24 * h23 + x34 * h33 + x44 * h43
    T[4, 4] = x04 * h04 + x14 * h14 + x24 * h24 + x34 * h34 + x44 * h44
    T[4, 5] = x04 * h05 + x14 * h15 + x24 * h25 + x34 * h35 + x44 * h45
    X[4, 0], X[4, 1], X[4, 2], X[4, 3], X[4, 4], X[4, 5] = h40, h41, h42, h43, h44, h45
    h30 -= l43 * h40
    h31 -= l43 * h41
    h32 -= l43 * h42
    h33 -= l43 * h43
    h34 -= l43 * h44
    h35 -= l43 * h45
    X[3, 0], X[3, 1], X[3, 2], X[3, 3], X[3, 4], X[3, 5] = h30, h31, h32, h33, h34, h35
    h20 -= l32 * h30 + l42 * h40
    h21 -= l32 * h31 + l42 * h41
    h22 -= l32 * h32 + l42 * h42
    h23 -= l32 * h33 + l42 * h43
    h24 -= l32 * h34 + l42 * h44
    h25 -= l32 * h35 + l42 * h45
    X[2, 0], X[2, 1], X[2, 2], X[2, 3], X[2, 4], X[2, 5] = h20, h21, h22, h23, h24, h25
    h10 -= l21 * h20 + l31 * h30 + l41 * h40
    h11 -= l21 * h21 + l31 * h31 + l41 * h41
    h12 -= l21 * h22 + l31 * h32 + l41 * h42
    h13 -= l21 * h23 + l31 * h33 + l41 * h43
    h14 -= l21 * h24 + l31 * h34 + l41 * h44
    h15 -= l21 * h25 + l31 * h35 + l41 * h45
    X[1, 0], X[1, 1], X[1, 2], X[1, 3], X[1, 4], X[1, 5] = h10, h11, h12, h13, h14, h15
    h00 -= l10 * h10 + l20 * h20 + l30 * h30 + l40 * h40
    h01 -= l10 * h11 + l20 * h21 + l30 * h31 + l40 * h41
    h02 -= l10 * h12 + l20 * h22 + l30 * h32 + l40 * h42
    h03 -= l10 * h13 + l20 * h23 + l30 * h33 + l40 * h43
    h04 -= l10 * h14 + l20 * h24 + l30 * h34 + l40 * h44
    h05 -= l10 * h15 + l20 * h25 + l30 * h35 + l40 * h45
    X[0, 0], X[0, 1], X[0, 2], X[0, 3], X[0, 4], X[0, 5] = h00, h01, h02, h03, h04, h05
    return pl



@njit(cache=True, error_model="numpy", fastmath=_FAST, inline="always")
def _back_substitute(first, n, R, E, nu, om, dt, Wz):
    """The velocity increments ``dx_k = z_k - W_k dx_{k+1}`` from the barge's end back to the first element off
    the bitt, each element's new velocities, then its position and frame with them (symplectic Euler). Returns
    whether the new state is finite."""
    x0 = x1 = x2 = x3 = x4 = 0.0  # dx of element k + 1 (none after the last: W of the last element is 0)
    finite = True
    for k in range(n - 1, first - 1, -1):
        X = Wz[k]
        y0 = X[0, 5] - (X[0, 0] * x0 + X[0, 1] * x1 + X[0, 2] * x2 + X[0, 3] * x3 + X[0, 4] * x4)
        y1 = X[1, 5] - (X[1, 0] * x0 + X[1, 1] * x1 + X[1, 2] * x2 + X[1, 3] * x3 + X[1, 4] * x4)
        y2 = X[2, 5] - (X[2, 0] * x0 + X[2, 1] * x1 + X[2, 2] * x2 + X[2, 3] * x3 + X[2, 4] * x4)
        y3 = X[3, 5] - (X[3, 0] * x0 + X[3, 1] * x1 + X[3, 2] * x2 + X[3, 3] * x3 + X[3, 4] * x4)
        y4 = X[4, 5] - (X[4, 0] * x0 + X[4, 1] * x1 + X[4, 2] * x2 + X[4, 3] * x3 + X[4, 4] * x4)
        x0, x1, x2, x3, x4 = y0, y1, y2, y3, y4
        u2, v2, w2 = nu[k, 0] + x0, nu[k, 1] + x1, nu[k, 2] + x2
        q2, r2 = om[k, 0] + x3, om[k, 1] + x4
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
          np.zeros((0, 5, 6)), np.zeros((5, 6)))


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
    Wz, blk = np.zeros((n, 5, 6)), np.zeros((5, 6))  # the dampers' implicit solve
    qb, wb = np.zeros(3), np.zeros(3)
    half = 0.5 * P[P_L]
    nstep = tug_p.shape[0] - 1
    for step in range(nstep):
        first = first_arr[0]
        fbx, fby, finite = _step(R, E, nu, om, first, P, tug_p[step], tug_v[step], bs, bxt, bzt, inert, tension,
                                 slack, ma_now, ma_prev, dt, work, Wz, blk)
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
                copy_2d(ma, ma_prev)
            return step
    if nstep % 2 == 1:
        copy_2d(ma, ma_prev)
    return nstep

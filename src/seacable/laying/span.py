"""The steady span of a cable being laid, compiled: the straight lay's direction (Zajac's angle turned by a
cross-current), the RK4 integration of the span's balance from the touchdown to the surface in a frame that
may turn, the table of station properties (columns ``S_*``); see :mod:`seacable.laying.plan` for the model.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from .kernel import current_at

# columns of the per-station property table
S_W, S_D, S_CDN, S_CDT, S_MEFF, S_COMPLIANCE, S_MT = range(7)
N_STATION_PROPS = 7
_STEPS = 80          # RK4 steps over the straight cable's length at most (in a turn at 2 m/s the cut is then 1.5 %
                     # long, and 0.1 % with 400 steps, at 3 times the planner's time)
_MAX_STEP = 50.0     # m, longest RK4 step


@njit(cache=True)
def straight_direction(w, kn, vs, c1, c2):
    """Unit tangent (up, towards the ship) of a straight cable under zero tension.

    Derivation: on a straight cable of direction ``t`` the tension has no normal component, so the
    normal drag balances the normal weight: ``k_n |u_n| u_n = w (e_z - (e_z . t) t)``, where
    ``u_n = (c - V_s e_1)_n = -W_n`` (the payout moves the material along ``t`` and drops out).
    Write ``t = (cos(alpha) h, sin(alpha))`` with ``h`` a horizontal unit vector. The horizontal part
    of the balance, ``-(W - (W.t) t)_h = lambda (e_z - sin(alpha) t)_h = -lambda sin(alpha) cos(alpha) h``,
    leaves ``W`` parallel to ``h``; the vertical part then gives ``lambda = |W| tan(alpha) > 0`` only
    for ``h = +W/|W|`` (the cable rises towards where the ship moves through the water), and
    ``|u_n| = |W| sin(alpha)``, so ``k_n |W|^2 sin^2(alpha) = w cos(alpha)``: Zajac's angle with the
    relative speed ``|W|``. Its root: ``cos(alpha) = 2 q / (w + sqrt(w^2 + 4 q^2))``, ``q = k_n |W|^2``.

    Parameters: weight ``w`` [N/m], ``k_n = 1/2 rho C_dn d`` [kg/m^2], ship speed ``vs`` along e_1 and
    the current ``(c1, c2)`` in the ship's frame [m/s]. Returns ``(t1, t2, t3)``.
    """
    w1, w2 = vs - c1, -c2
    speed = math.sqrt(w1 * w1 + w2 * w2)
    if speed < 1e-12:
        return 0.0, 0.0, 1.0
    q = kn * speed * speed
    ca = 2.0 * q / (w + math.sqrt(w * w + 4.0 * q * q))
    sa = math.sqrt(max(1.0 - ca * ca, 0.0))
    return ca * w1 / speed, ca * w2 / speed, sa


@njit(cache=True)
def _rhs(y, h, vs, om, vc, cos_c, sin_c, depths, speeds, rho, p, out):
    """d/ds of (r1, r2, r3, t1, t2, t3, T); returns the normal-force scale |df/dt| for the step control.

    The frame turns at ``om`` about the vertical through ``(0, vs/om)`` (``om = 0``: it moves at ``vs`` along e1),
    so the frame point at ``r`` moves at ``(vs - om r2, om r1, 0)``; a material point moves at that minus
    ``vc t`` and accelerates at the centripetal ``om^2 ((0, vs/om) - r)``, Coriolis ``2 om e3 x (-vc t)`` and
    ``vc^2 dt/ds`` (the last in the effective tension).
    """
    w, d, cdn, cdt, meff, comp, mt = p[S_W], p[S_D], p[S_CDN], p[S_CDT], p[S_MEFF], p[S_COMPLIANCE], p[S_MT]
    kn = 0.5 * rho * cdn * d
    kt = 0.5 * rho * cdt * math.pi * d
    t1, t2, t3, T = y[3], y[4], y[5], y[6]
    c = current_at(-h + y[2], depths, speeds)
    u1 = c * cos_c - (vs - om * y[1] - vc * t1)
    u2 = c * sin_c - (om * y[0] - vc * t2)
    u3 = vc * t3
    ut = u1 * t1 + u2 * t2 + u3 * t3
    n1, n2, n3 = u1 - ut * t1, u2 - ut * t2, u3 - ut * t3
    un = math.sqrt(n1 * n1 + n2 * n2 + n3 * n3)
    f1 = kn * un * n1 + kt * abs(ut) * ut * t1
    f2 = kn * un * n2 + kt * abs(ut) * ut * t2
    f3 = -w + kn * un * n3 + kt * abs(ut) * ut * t3
    if om != 0.0:
        # the inertia of the turn: -(m + m_a) a_n - (m + m_at) a_t
        a1 = -om * om * y[0] + 2.0 * om * vc * t2
        a2 = om * vs - om * om * y[1] - 2.0 * om * vc * t1
        at = a1 * t1 + a2 * t2
        f1 -= meff * (a1 - at * t1) + mt * at * t1
        f2 -= meff * (a2 - at * t2) + mt * at * t2
        f3 -= -meff * at * t3 + mt * at * t3
    ft = f1 * t1 + f2 * t2 + f3 * t3
    teff = T - meff * vc * vc
    if teff == 0.0:                       # (a frozen step, whose direction is not integrated)
        teff = 1e-300
    stretch = 1.0 + T * comp
    out[0], out[1], out[2] = stretch * t1, stretch * t2, stretch * t3
    out[3] = -(f1 - ft * t1) / teff
    out[4] = -(f2 - ft * t2) / teff
    out[5] = -(f3 - ft * t3) / teff
    out[6] = -ft
    return w + 2.0 * kn * (un * un + ut * ut) + 2.0 * kt * ut * ut


@njit(cache=True)
def _span(h, beta, vs, om, vc, cos_c, sin_c, t0, depths, speeds, rho, p, out, rec):
    """One suspended span from the touchdown (depth ``h``) up to the surface; fills ``out`` with
    (ship - touchdown along e_1, along e_2, suspended length, top tension, entry angle); NaN if the
    cable does not reach the surface. ``rec`` (m, 4), if it has rows, takes the profile (arc length, tension,
    t_1, t_3) at the start and after each step; returns the number of rows written.

    The tangent relaxes to the straight cable's direction over the length ``ell = (T - (m + m_a) V_c^2) /
    |df/dt|`` (the effective tension over the normal force's gradient). Where ``ell`` is shorter than
    half the step ``ds`` (1/80 of the straight cable's length, at most 50 m) the tangent is taken there (:func:`straight_direction`,
    exact in a uniform current, where one step reaches the surface: the forces are constant along a
    straight cable) and only the tension and the position advance; beyond, RK4 with the
    step ``min(ds, ell)``, inside its stability bound. A bend at the touchdown shorter than half a
    step (a light bottom tension under strong drag) is not resolved.
    """
    w = p[S_W]
    kn = 0.5 * rho * p[S_CDN] * p[S_D]
    y = np.zeros(7)
    y[6] = t0
    c = current_at(-h, depths, speeds)
    y[3], y[4], y[5] = straight_direction(w, kn, vs, c * cos_c, c * sin_c)
    # the step: 1/80 of the straight cable's length from the seabed to the surface
    ds_max = min(h / max(y[5], 0.05) / _STEPS, _MAX_STEP)
    if t0 > 0.0:
        y[3], y[4], y[5] = math.cos(beta), 0.0, math.sin(beta)
    k1, k2, k3, k4, tmp = np.empty(7), np.empty(7), np.empty(7), np.empty(7), np.empty(7)
    s = 0.0
    meff_v2 = p[S_MEFF] * vc * vc
    uniform = depths.size == 1 and om == 0.0
    n_rec = 0
    if rec.shape[0] > 0:
        rec[0, 0], rec[0, 1], rec[0, 2], rec[0, 3] = 0.0, y[6], y[3], y[5]
        n_rec = 1
    for _ in range(100000):
        if y[2] >= h:
            break
        scale = _rhs(y, h, vs, om, vc, cos_c, sin_c, depths, speeds, rho, p, k1)
        relax = (y[6] - meff_v2) / scale      # length over which the tangent relaxes to its equilibrium [m]
        frozen = relax < 0.5 * ds_max
        if frozen:
            # shorter than the step: the tangent is the straight cable's (exact in a uniform current); the
            # tension and the position advance along it
            ds = ds_max
            if uniform and k1[2] > 0.0:
                ds = (h - y[2]) / k1[2]      # straight, with forces constant along it: one step to the surface
            for j in range(3, 6):
                k1[j] = 0.0
            for j in range(7):
                tmp[j] = y[j] + ds * k1[j]
        else:
            ds = min(ds_max, relax)
            for j in range(7):
                tmp[j] = y[j] + 0.5 * ds * k1[j]
            _rhs(tmp, h, vs, om, vc, cos_c, sin_c, depths, speeds, rho, p, k2)
            for j in range(7):
                tmp[j] = y[j] + 0.5 * ds * k2[j]
            _rhs(tmp, h, vs, om, vc, cos_c, sin_c, depths, speeds, rho, p, k3)
            for j in range(7):
                tmp[j] = y[j] + ds * k3[j]
            _rhs(tmp, h, vs, om, vc, cos_c, sin_c, depths, speeds, rho, p, k4)
            for j in range(7):
                tmp[j] = y[j] + ds / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j])
        if tmp[2] >= h:                       # the surface within the step: linear back to it
            f = (h - y[2]) / (tmp[2] - y[2])
            for j in range(7):
                tmp[j] = y[j] + f * (tmp[j] - y[j])
            ds *= f
        norm = math.sqrt(tmp[3] * tmp[3] + tmp[4] * tmp[4] + tmp[5] * tmp[5])
        tmp[3] /= norm
        tmp[4] /= norm
        tmp[5] /= norm
        if frozen:
            c = current_at(-h + tmp[2], depths, speeds)
            tmp[3], tmp[4], tmp[5] = straight_direction(w, kn, vs - om * tmp[1], c * cos_c, c * sin_c - om * tmp[0])
        for j in range(7):
            y[j] = tmp[j]
        s += ds
        if n_rec < rec.shape[0]:
            rec[n_rec, 0], rec[n_rec, 1], rec[n_rec, 2], rec[n_rec, 3] = s, y[6], y[3], y[5]
            n_rec += 1
        if y[2] < -h:                         # turned down: no span reaches the surface
            out[:] = np.nan
            return n_rec
    if y[2] < h:
        out[:] = np.nan
        return n_rec
    out[0], out[1], out[2], out[3] = y[0], y[1], s, y[6]
    out[4] = math.asin(min(max(y[5], -1.0), 1.0))
    return n_rec


@njit(cache=True)
def _pay_out_time(h, vs, props, rho):
    """Time to pay out the straight span in still water, ``h / (V_s sin(alpha))``, at each station. [s]"""
    out = np.empty(h.size)
    for i in range(h.size):
        p = props[i]
        sin_a = straight_direction(p[S_W], 0.5 * rho * p[S_CDN] * p[S_D], vs[i], 0.0, 0.0)[2]
        out[i] = h[i] / (vs[i] * max(sin_a, 1e-3))
    return out


def _zajac_angle(vs, props, rho) -> tuple[np.ndarray, np.ndarray]:
    """``(cos, sin)`` of Zajac's angle in still water at the speeds ``vs``, for the stations' cables
    (:func:`straight_direction`, vectorised)."""
    q = 0.5 * rho * props[:, S_CDN] * props[:, S_D] * vs * vs
    w = props[:, S_W]
    ca = 2.0 * q / (w + np.sqrt(w * w + 4.0 * q * q))
    return ca, np.sqrt(np.maximum(1.0 - ca * ca, 1e-300))


def _straight_layback(h, vs, props, rho) -> np.ndarray:
    """The straight span's layback in still water, ``h cot(alpha)`` (Zajac's angle at ``vs``). [m]"""
    ca, sa = _zajac_angle(vs, props, rho)
    return h * ca / sa


@njit(cache=True)
def solve_spans(h, beta, vs, om, vc, cos_c, sin_c, t0, depths, speeds, rho, props, active, out):
    """:func:`_span` for the stations with ``active`` set; ``out`` is (n, 5)."""
    none = np.empty((0, 4))
    for i in range(h.size):
        if active[i]:
            _span(h[i], beta[i], vs[i], om[i], vc[i], cos_c[i], sin_c[i], t0[i], depths, speeds, rho, props[i], out[i],
                  none)

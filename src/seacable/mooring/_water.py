"""The water at the mooring line: the instantaneous surface, the water's velocity and acceleration (current,
regular Airy waves, an irregular sea's grid, Wheeler stretching), and the hydrodynamic loads of attachments
(drag across and along the line, lift) and of a half element's drag turning with it, with their tangents.

Part of :mod:`seacable.mooring.kernel`, which re-exports the public names.
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import njit
from .._waves_kernel import airy_linear
from ..seastate import S_MODE, S_STRETCH, grid_eta, grid_point
from ._band import _add_block
from ._indices import E_CHEAD, E_FRAMEX, E_FRAMEY, E_FRAMEZ, E_G, E_WDEPTH, E_WH, E_WHEAD, E_WK, E_WPHASE, E_WT


@njit(cache=True)
def _surface(x, y, t, env, with_waves, sea):
    """Instantaneous water surface eta [m] above (x, y) at time ``t``: the regular Airy wave's plus the
    irregular sea's (grid, :func:`seacable.seastate.grid_eta`); 0 (still water) without waves."""
    if not with_waves:
        return 0.0
    eta = 0.0
    if env[E_WH] > 0.0:
        theta = (env[E_WK] * (x * math.cos(env[E_WHEAD]) + y * math.sin(env[E_WHEAD]))
                 - 2.0 * math.pi / env[E_WT] * t + env[E_WPHASE])
        eta = 0.5 * env[E_WH] * math.cos(theta)
    if sea[S_MODE] > 0.0:
        eta += grid_eta(sea, x, y, t)
    return eta


@njit(cache=True)
def _fluid(x, t, env, cur_depth, cur_speed, with_waves, sea, u, acc):
    """Water velocity ``u`` and acceleration ``acc`` at point ``x`` and time ``t`` (current plus waves).

    Nothing above the instantaneous surface eta (:func:`_surface`). Below it, the current at the point's
    depth (its top value above z = 0) and the waves' linear kinematics (regular Airy, and an irregular sea
    from its grid ``sea``) at the linear-theory depth z' of the point: ``min(z, 0)`` (constant
    extrapolation above the still-water level, the default) or, with Wheeler stretching
    (``sea[S_STRETCH]``), ``z' = (z - eta) d / (d + eta)`` (``z - eta`` in deep water), which puts the
    surface at z' = 0 and keeps the seabed at -d.
    """
    wavy = with_waves and (env[E_WH] > 0.0 or sea[S_MODE] > 0.0)
    eta = _surface(x[0], x[1], t, env, with_waves, sea) if wavy else 0.0
    u[0], u[1], u[2], acc[0], acc[1], acc[2] = _fluid_below(x[0], x[1], x[2], t, env, cur_depth, cur_speed, wavy, sea,
                                                            eta)


@njit(cache=True)
def _fluid_below(x, y, z, t, env, cur_depth, cur_speed, wavy, sea, eta):
    """:func:`_fluid` at the point (x, y, z) with the surface ``eta`` [m] above it known (``wavy``: there are
    waves): the velocity and acceleration ``(u, v, w, ax, ay, az)`` [m/s], [m/s^2]."""
    u0, u1, u2, a0, a1, a2, zs = _water_local(x, y, z, t, env, cur_depth, cur_speed, wavy, sea, eta)
    if not math.isnan(zs):
        k0, k1, k2, k3, k4, k5 = grid_point(sea, x, y, zs, t)
        u0, u1, u2, a0, a1, a2 = u0 + k0, u1 + k1, u2 + k2, a0 + k3, a1 + k4, a2 + k5
    return u0, u1, u2, a0, a1, a2


@njit(cache=True)
def _water_local(x, y, z, t, env, cur_depth, cur_speed, wavy, sea, eta):
    """:func:`_fluid_below` but for the irregular sea's grid: the current's and the regular wave's velocity and
    acceleration, and the linear-theory depth at which to look the grid up (NaN: no look-up, the point above
    the surface or no irregular sea): ``(u, v, w, ax, ay, az, zs)``."""
    if z > eta:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, math.nan
    if cur_depth.size == 1:
        speed = cur_speed[0]
    else:
        speed = np.interp(-z, cur_depth, cur_speed)
    u0 = u1 = u2 = a0 = a1 = a2 = 0.0
    if speed != 0.0:
        u0 = speed * math.cos(env[E_CHEAD])
        u1 = speed * math.sin(env[E_CHEAD])
    u0, u1, u2 = u0 - env[E_FRAMEX], u1 - env[E_FRAMEY], u2 - env[E_FRAMEZ]
    if not wavy:
        return u0, u1, u2, a0, a1, a2, math.nan
    d = env[E_WDEPTH]
    if sea[S_STRETCH] > 0.0:
        zs = (z - eta) * d / (d + eta) if math.isfinite(d) else z - eta
    else:
        zs = min(z, 0.0)
    zs = max(min(zs, 0.0), -d)
    if env[E_WH] > 0.0:
        k0, k1, k2, k3, k4, k5 = airy_linear(x, y, zs, t, env[E_WH], env[E_WT], env[E_WK], d, env[E_WHEAD],
                                             env[E_WPHASE], env[E_G])
        u0, u1, u2, a0, a1, a2 = u0 + k0, u1 + k1, u2 + k2, a0 + k3, a1 + k4, a2 + k5
    return u0, u1, u2, a0, a1, a2, zs if sea[S_MODE] > 0.0 else math.nan


@njit(cache=True)
def _dry_fraction(z0, z1):
    """Fraction of the straight piece from height z0 to z1 above the water surface that lies above it.

    The heights are taken from the instantaneous surface (``z - eta`` at each end, the surface taken
    linear between them; still water: eta = 0).
    """
    lo, hi = min(z0, z1), max(z0, z1)
    if hi <= 0.0:
        return 0.0
    if lo >= 0.0:
        return 1.0
    return hi / (hi - lo)


@njit(cache=True)
def _drag_tangent(un, cd, out, coef):
    """out += coef * cd * d(|u| u)/du restricted to the subspace of ``un`` (out is 3x3)."""
    mag = math.sqrt(un[0] ** 2 + un[1] ** 2 + un[2] ** 2)
    if mag <= 0.0:
        return
    for r in range(3):
        for c in range(3):
            out[r, c] += coef * cd * un[r] * un[c] / mag


@njit(cache=True)
def _point_drag_split(u, qn, qa, tsum, f, out):
    """Drag of an attachment across and along the line, ``qn |u_n| u_n + qa |u_t| u_t`` (``qn``, ``qa``: 1/2 rho
    C_D A of each), added to ``f`` (3,); ``u`` the water's velocity relative to the point, ``tsum`` the sum of its
    elements' unit tangents (zero: no direction, the isotropic drag at ``qn``). ``out`` (3, 3) receives the
    tangent -df/dv = qn (|u_n| P_n + u_n u_n^T / |u_n|) + 2 qa |u_t| t t^T."""
    m = math.sqrt(tsum[0] ** 2 + tsum[1] ** 2 + tsum[2] ** 2)
    out[:] = 0.0
    if m <= 0.0:
        mag = math.sqrt(u[0] ** 2 + u[1] ** 2 + u[2] ** 2)
        for r in range(3):
            f[r] += qn * mag * u[r]
            out[r, r] += qn * mag
        _drag_tangent(u, 1.0, out, qn)
        return
    t0, t1, t2 = tsum[0] / m, tsum[1] / m, tsum[2] / m
    ut = u[0] * t0 + u[1] * t1 + u[2] * t2
    n0, n1, n2 = u[0] - ut * t0, u[1] - ut * t1, u[2] - ut * t2
    mn = math.sqrt(n0 * n0 + n1 * n1 + n2 * n2)
    f[0] += qn * mn * n0 + qa * abs(ut) * ut * t0
    f[1] += qn * mn * n1 + qa * abs(ut) * ut * t1
    f[2] += qn * mn * n2 + qa * abs(ut) * ut * t2
    tv = (t0, t1, t2)
    nv = (n0, n1, n2)
    cun = qn / mn if mn > 0.0 else 0.0
    for r in range(3):
        for c in range(3):
            pn = (1.0 if r == c else 0.0) - tv[r] * tv[c]
            out[r, c] = qn * mn * pn + cun * nv[r] * nv[c] + 2.0 * qa * abs(ut) * tv[r] * tv[c]


@njit(cache=True)
def _drag_turn(band, bw, fk, fa, fb, qn, qt, r0, r1, r2, t0, t1, t2, l, jt, blk):
    """The Newton matrix's terms of a half element's drag turning with the element: K += -dF/dx at node k's row
    (free index ``fk``), the columns of the element's ends a and b (``fa``, ``fb``; -1: prescribed).

    With the water's relative velocity u, ``a = u . t``, ``u_n = u - a t``, the drag
    ``F = qn |u_n| u_n + qt |a| a t`` (qn = 1/2 rho d L/2 C_dn, qt = the same with pi C_dt) changes with t as
    ``dF/dt = -qn (|u_n| I + u_n u_n^T / |u_n|) (t u^T + a I) + qt |a| (2 t u^T + a I)``, and t with the ends as
    ``dt/dx_b = -dt/dx_a = (I - t t^T) / l``."""
    if fk < 0 or l <= 0.0:
        return
    a = r0 * t0 + r1 * t1 + r2 * t2
    n0, n1, n2 = r0 - a * t0, r1 - a * t1, r2 - a * t2
    mn = math.sqrt(n0 * n0 + n1 * n1 + n2 * n2)
    tv = (t0, t1, t2)
    uv = (r0, r1, r2)
    nv = (n0, n1, n2)
    cun = qn / mn if mn > 0.0 else 0.0
    for r in range(3):
        for c in range(3):
            blk[r, c] = 0.0
    for r in range(3):
        for m in range(3):
            dn = qn * mn * (1.0 if r == m else 0.0) + cun * nv[r] * nv[m]
            for c in range(3):
                blk[r, c] -= dn * (tv[m] * uv[c] + (a if m == c else 0.0))
        for c in range(3):
            blk[r, c] += qt * abs(a) * (2.0 * tv[r] * uv[c] + (a if r == c else 0.0))
    # jt = dF/dt (I - t t^T) / l
    for r in range(3):
        for c in range(3):
            v = 0.0
            for m in range(3):
                v += blk[r, m] * ((1.0 if m == c else 0.0) - tv[m] * tv[c])
            jt[r, c] = v / l
    if fb >= 0:
        _add_block(band, bw, fk, fb, -1.0, jt)
    if fa >= 0:
        _add_block(band, bw, fk, fa, 1.0, jt)


@njit(cache=True)
def point_lift(u, ql, f, out):
    """Lift ``ql (|u|^2 e_z - u_z u)`` of an attachment (``ql`` = 1/2 rho C_L A, positive up) added to ``f`` (3,),
    at the water's velocity ``u`` relative to it: across the flow, in the vertical plane through it, of size
    ``ql |u| |u_h|`` (``ql U^2`` in a horizontal flow, none in a vertical one, smoothly: no direction is singular).
    ``out`` (3, 3) receives -df/dv = df/du = ql (2 e_z u^T - u_z I - u e_z^T)."""
    uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2]
    uz = u[2]
    f[0] -= ql * uz * u[0]
    f[1] -= ql * uz * u[1]
    f[2] += ql * (uu - uz * uz)
    for r in range(3):
        for c in range(3):
            out[r, c] = ql * ((2.0 * u[c] if r == 2 else 0.0) - (uz if r == c else 0.0) - (u[r] if c == 2 else 0.0))


"""The seabed under the mooring line: its elevation and slope, a plane or a profile along X
(:func:`seabed_at`), or a grid over X and Y (:func:`grid_at`).

Part of :mod:`seacable.mooring.kernel`, which re-exports the public names.
"""

from __future__ import annotations

import math

from .._jit import njit
from ._indices import E_BEDNY, E_BEDTAB, E_DEPTH, E_SLOPE, ENV_SIZE


@njit(cache=True)
def seabed_at(env, x):
    """Seabed elevation [m] and slope dz/dx [-] at distance ``x`` along X of the profile held in ``env``
    (``E_BEDTAB`` points; level beyond its ends), or of the plane (``E_DEPTH``, ``E_SLOPE``) without one."""
    m = int(env[E_BEDTAB])
    if m == 0:
        t = math.tan(env[E_SLOPE])
        return -env[E_DEPTH] + t * x, t
    x0 = ENV_SIZE
    z0 = ENV_SIZE + m
    i, f, inside = _cell(env, x0, m, x)
    if not inside:  # level beyond the profile's ends
        return env[z0 if f == 0.0 else z0 + m - 1], 0.0
    slope = (env[z0 + i + 1] - env[z0 + i]) / (env[x0 + i + 1] - env[x0 + i])
    return env[z0 + i] + slope * (x - env[x0 + i]), slope


@njit(cache=True)
def _cell(env, g0, n, p):
    """The cell of the grid lines ``env[g0:g0 + n]`` (increasing) under ``p`` (bisection), the fraction ``t`` across
    it, and whether ``p`` lies strictly inside the lines' span (beyond it: clamped to the edge, level)."""
    if p <= env[g0]:
        return 0, 0.0, False
    if p >= env[g0 + n - 1]:
        return n - 2, 1.0, False
    lo, hi = 0, n - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if env[g0 + mid] <= p:
            lo = mid
        else:
            hi = mid
    return lo, (p - env[g0 + lo]) / (env[g0 + hi] - env[g0 + lo]), True


@njit(cache=True)
def grid_at(env, x, y):
    """Seabed elevation [m] and its gradient dz/dx, dz/dy [-] at ``(x, y)`` on the grid held in ``env`` (``E_BEDTAB``
    = -nx, ``E_BEDNY`` = ny): bilinear in the cell under the point (located by bisection on x and on y), level beyond
    the grid's edges (the gradient along an axis 0 beyond its span). :class:`seacable.bathymetry.SeabedGrid`'s ``at``
    in NumPy."""
    nx = int(-env[E_BEDTAB])
    ny = int(env[E_BEDNY])
    i, tx, inx = _cell(env, ENV_SIZE, nx, x)
    j, ty, iny = _cell(env, ENV_SIZE + nx, ny, y)
    z0 = ENV_SIZE + nx + ny + j * nx + i
    z00, z10, z01, z11 = env[z0], env[z0 + 1], env[z0 + nx], env[z0 + nx + 1]
    zb = (1.0 - ty) * ((1.0 - tx) * z00 + tx * z10) + ty * ((1.0 - tx) * z01 + tx * z11)
    gx = gy = 0.0
    if inx:
        gx = ((1.0 - ty) * (z10 - z00) + ty * (z11 - z01)) / (env[ENV_SIZE + i + 1] - env[ENV_SIZE + i])
    if iny:
        gy = ((1.0 - tx) * (z01 - z00) + tx * (z11 - z10)) / (env[ENV_SIZE + nx + j + 1] - env[ENV_SIZE + nx + j])
    return zb, gx, gy


@njit(cache=True)
def penetration(env, x, y, z, profile, depth, nrm):
    """How far the point ``(x, y, z)`` lies into the seabed along its normal [m] (> 0 in it): with ``profile`` (a
    tabulated seabed), of the profile's segment under ``x``, whose unit normal it writes into ``nrm`` (x and z), or of
    the grid under ``(x, y)``, whose unit normal ``(-dz/dx, -dz/dy, 1) / norm`` it writes into ``nrm``; else of the
    plane through ``z = -depth`` at ``x = 0`` whose normal ``nrm`` holds already."""
    if profile:
        if env[E_BEDTAB] < 0.0:
            zb, gx, gy = grid_at(env, x, y)
            cs = 1.0 / math.sqrt(1.0 + gx * gx + gy * gy)
            nrm[0], nrm[1], nrm[2] = -gx * cs, -gy * cs, cs
            return (zb - z) * cs
        zb, slope = seabed_at(env, x)
        cs = 1.0 / math.sqrt(1.0 + slope * slope)
        nrm[0], nrm[2] = -slope * cs, cs
        return (zb - z) * cs
    return -(nrm[0] * x + nrm[2] * (z + depth))


@njit(cache=True)
def rounded_depth(pen, dl):
    """The penalty contact's depth ``q`` and its slope ``dq/dpen`` at penetration ``pen`` [m]: ``pen`` beyond the ramp
    ``dl``, rounded quadratically to ``(pen + dl)^2 / (4 dl)`` over ``|pen| < dl`` (a continuous stiffness, so that
    Newton does not cycle at lift-off); the caller has ``pen > -dl``."""
    if pen < dl:
        return (pen + dl) ** 2 / (4.0 * dl), (pen + dl) / (2.0 * dl)
    return pen, 1.0

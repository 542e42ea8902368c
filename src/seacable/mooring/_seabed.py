"""The seabed under the mooring line: its elevation and slope, a plane or a profile along X
(:func:`seabed_at`).

Part of :mod:`seacable.mooring.kernel`, which re-exports the public names.
"""

from __future__ import annotations

import math

from .._jit import njit
from ._indices import E_BEDTAB, E_DEPTH, E_SLOPE, ENV_SIZE


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
    if x <= env[x0]:
        return env[z0], 0.0
    if x >= env[x0 + m - 1]:
        return env[z0 + m - 1], 0.0
    lo, hi = 0, m - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if env[x0 + mid] <= x:
            lo = mid
        else:
            hi = mid
    slope = (env[z0 + hi] - env[z0 + lo]) / (env[x0 + hi] - env[x0 + lo])
    return env[z0 + lo] + slope * (x - env[x0 + lo]), slope



@njit(cache=True)
def penetration(env, x, z, profile, depth, nrm):
    """How far the point ``(x, z)`` lies into the seabed along its normal [m] (> 0 in it): with a ``profile``, of the
    profile's segment under ``x``, whose unit normal it writes into ``nrm`` (x and z); else of the plane through
    ``z = -depth`` at ``x = 0`` whose normal ``nrm`` holds already."""
    if profile:
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

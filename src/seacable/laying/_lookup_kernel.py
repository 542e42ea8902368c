"""The seabed's look-ups of a 3-D lay, compiled: the nearest point of a route's legs to each point
(:meth:`.route.RouteGeometry.locate`, for a KP table) and a grid's bilinear depth (:class:`.bathymetry._Bilinear`).

The laying run looks the seabed up under its nodes several times a time step; numpy's array expressions over a
few hundred nodes cost more in their calls than in their arithmetic. Each function does numpy's (or scipy's)
arithmetic, operation for operation: the same bits.
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import njit

__all__ = ["bilinear", "nearest_on_legs"]


@njit(cache=True)
def _foot(qx, qy, x0, y0, ux, uy, lo, hi):
    """Distance along the leg to the foot of the perpendicular (clipped to the leg), and the point's offset from it
    (ex, ey), as :meth:`.route.RouteGeometry._nearest`'s array expressions give them, operation for operation."""
    t = (qx - x0) * ux + (qy - y0) * uy
    if t < lo:                       # numpy.clip: max, then min (a NaN stays NaN)
        t = lo
    if t > hi:
        t = hi
    return t, qx - (x0 + t * ux), qy - (y0 + t * uy)


@njit(cache=True)
def nearest_on_legs(qx, qy, x0, y0, ux, uy, lo, hi, kp, out_kp, out_off):
    """KP and offset (+ to port) of the nearest point of every leg to each point ``(qx[i], qy[i])``.

    The legs: start ``(x0, y0)``, unit direction ``(ux, uy)``, the distance along them clipped to ``[lo, hi]``, KP of
    their start ``kp``. The first leg of least ``hypot`` distance, ``hypot`` taken only where the squared distance is
    within 1e-9 of the least (the same choice as :meth:`.route.RouteGeometry._nearest`, and numpy's ``hypot``).
    Finite points only.
    """
    n_leg = x0.shape[0]
    for i in range(qx.shape[0]):
        least = np.inf
        for k in range(n_leg):
            _, ex, ey = _foot(qx[i], qy[i], x0[k], y0[k], ux[k], uy[k], lo[k], hi[k])
            least = min(least, ex * ex + ey * ey)
        bound = least * (1.0 + 1e-9)
        best, dist, t_best, ex_best, ey_best = 0, np.inf, 0.0, 0.0, 0.0
        for k in range(n_leg):
            t, ex, ey = _foot(qx[i], qy[i], x0[k], y0[k], ux[k], uy[k], lo[k], hi[k])
            if ex * ex + ey * ey <= bound:
                d = np.hypot(ex, ey)
                if d < dist:
                    best, dist, t_best, ex_best, ey_best = k, d, t, ex, ey
        side = ux[best] * (qy[i] - y0[best]) - uy[best] * (qx[i] - x0[best])
        out_kp[i] = kp[best] + t_best
        out_off[i] = (-1.0 if side < 0.0 else 1.0) * np.hypot(ex_best, ey_best)


@njit(cache=True)
def _cell(g, v):
    """The cell ``i`` of the ascending grid lines ``g`` with ``g[i] <= v < g[i + 1]`` (the last cell for the last
    line; ``v`` within the grid), and ``v``'s fraction of it."""
    i = min(np.searchsorted(g, v, side="right") - 1, g.size - 2)
    return i, (v - g[i]) / (g[i + 1] - g[i])


@njit(cache=True)
def bilinear(gx, gy, values, x, y, out):
    """Bilinear interpolation of ``values[iy, ix]`` on the grid lines ``gx``, ``gy`` (ascending, at least two each)
    at the points ``(x[k], y[k])``; NaN outside the grid (or at a NaN coordinate).

    scipy's ``RegularGridInterpolator`` (linear, 2-D, NaN fill) term for term:
    ``v00 (1 - fy) (1 - fx) + v01 (1 - fy) fx + v10 fy (1 - fx) + v11 fy fx``, summed in that order.
    """
    for k in range(x.shape[0]):
        xv, yv = x[k], y[k]
        if not (gx[0] <= xv <= gx[-1] and gy[0] <= yv <= gy[-1]):
            out[k] = np.nan
            continue
        i0, y0 = _cell(gy, yv)
        i1, y1 = _cell(gx, xv)
        a, b = 1 - y0, 1 - y1
        out[k] = (values[i0, i1] * a * b + values[i0, i1 + 1] * a * y1 + values[i0 + 1, i1] * y0 * b
                  + values[i0 + 1, i1 + 1] * y0 * y1)

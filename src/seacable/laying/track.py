"""Where the laying ship goes and the seabed under it, for the time loop in 2-D or 3-D.

The time loop (:mod:`seacable.laying.solver`) works with node positions of ``dim`` coordinates, the
last one up. A track gives it the ship's water entry at a distance run ``d`` (its KP in 3-D), the
ship's horizontal direction there, and the seabed: its elevation and gradient at horizontal points
and the distance along it between laid points.

``Track2D``: paper 001's vertical plane, x along the track (the distance run is x), the seabed a
profile (:class:`~seacable.laying.inputs.Seabed2D`). ``Track3D``: a route
(:class:`~seacable.laying.route.RouteGeometry`) over a seabed map
(:class:`~seacable.laying.bathymetry.SeabedMap`): the ship runs along the route's legs and turns at
the waypoints.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["Track2D", "Track3D"]


class Track2D:
    """Paper 001's plane: positions (x, z), the ship on z = 0 moving towards +x."""

    dim = 2

    def __init__(self, seabed):
        self.seabed = seabed
        self.highest = float(np.max(seabed.zb))     # the seabed's highest elevation anywhere [m]

    def point(self, d: float) -> np.ndarray:
        return np.array([d, 0.0])

    def direction(self, d: float) -> np.ndarray:
        return np.array([1.0])

    def zb(self, ph, strict: bool = True) -> np.ndarray:
        """Seabed elevation under horizontal points ``ph`` (shape (..., 1)). [m]"""
        return self.seabed.z(np.asarray(ph, float)[..., 0])

    def gradient(self, ph) -> np.ndarray:
        """Seabed gradient at a horizontal point, shape (1,). [-]"""
        return np.array([self.seabed.slope(float(ph[0]))])

    def gradients(self, ph) -> np.ndarray:
        """Seabed gradients at horizontal points ``ph`` (shape (n, 1)), shape (n, 1). [-]"""
        return np.array([[self.seabed.slope(float(x))] for x in np.asarray(ph, float)[:, 0]]).reshape(-1, 1)

    def slope_along(self, ph, d: float) -> float:
        """The seabed's slope under the horizontal point ``ph`` along the ship's direction at ``d``: ``gradient(ph)
        @ direction(d)``, to the bit (numpy's product of one term is ``0.0 + g * 1.0``: +0.0 for -0.0), without the
        arrays. [-]"""
        return 0.0 + self.seabed.slope(float(ph[0]))

    def zb_under(self, pos: np.ndarray, above: float) -> np.ndarray:
        """The seabed's elevation under nodes ``pos`` (rows of x, z). (A profile is interpolated under every node at
        once, also under those higher than ``above``, which a map may leave out: see :meth:`Track3D.zb_under`.) [m]"""
        return self.seabed.z(pos[:, 0])

    def run(self, points) -> float:
        """Distance along the seabed from the first to the last of laid points (dim columns). [m]"""
        return float(self.seabed.arc(points[-1][0]) - self.seabed.arc(points[0][0]))


class Track3D:
    """A route over a seabed map: positions (x, y, z); the ship follows the route's legs at z = 0.

    ``gradient`` is the central difference of the depth over ``delta`` either side (1 m), and ``run`` the
    length of the laid cable's polyline of points on the seabed.

    The time loop asks for the seabed under the same nodes several times a step (landing, the touchdown point,
    the output), and a KP table locates every point on the route: ``zb`` remembers the points it was last asked
    for (:class:`_Memo`), and looks up only the others (not for a seabed looked up by compiled code, a KP table or a
    regular grid in x and y, ``seabed.compiled``: there the memory costs more than the look-ups). ``point`` and ``direction`` remember the last distance
    run asked for (the ship's, several times a step).
    """

    dim = 3

    def __init__(self, route, seabed, delta: float = 1.0):
        self.route, self.seabed, self.delta = route, seabed, delta
        self._steps = delta * np.eye(2)   # the central differences' steps along x and y
        shallowest = getattr(seabed, "shallowest", math.nan)
        self.highest = -shallowest if math.isfinite(shallowest) else math.inf   # highest seabed elevation [m]
        self._memo = None if getattr(seabed, "flat", False) or getattr(seabed, "compiled", False) else _Memo()
        self._last = {}                   # the last distance run asked for, by what was asked: (d, value)

    def point(self, d: float) -> np.ndarray:
        last = self._last.get("point")
        if last is None or last[0] != d or d == 0.0:       # (0.0: not to take -0.0 for it)
            x, y = self.route.point(d)
            last = self._last["point"] = (d, np.array([x, y, 0.0]))
        return last[1].copy()

    def direction(self, d: float) -> np.ndarray:
        last = self._last.get("direction")
        if last is None or last[0] != d or d == 0.0:       # (asked for several times a step at the ship)
            h = float(self.route.heading(d))
            last = self._last["direction"] = (d, np.array([np.cos(h), np.sin(h)]))
        return last[1].copy()

    def zb(self, ph, strict: bool = True) -> np.ndarray:
        """The seabed's elevation at horizontal points (..., 2); where a grid gives none, an InputError, or NaN if
        not ``strict``. [m]"""
        p = np.asarray(ph, float)
        if not strict:
            return -self.seabed.depth(p)
        if self._memo is None:           # (rows of points, as the memory asks: a grid gives one point's depth as
            return self._elevation(p.reshape(-1, 2)).reshape(p.shape[:-1])     # shape (1,))
        return self._memo.get(p, self._elevation)

    def _elevation(self, p: np.ndarray) -> np.ndarray:
        """The seabed's elevation at horizontal points; an InputError where a grid gives none (the cable has gone
        off it: a NaN would run on silently through the time loop)."""
        z = -self.seabed.depth(p)
        if not np.isnan(z).any():
            return z
        bad = np.isnan(z) & np.all(np.isfinite(p), axis=-1)
        if bad.any():
            q = p[np.unravel_index(np.argmax(bad), bad.shape)]
            self.seabed.check_covers(q[None, :], "cable")
        return z

    def gradient(self, ph) -> np.ndarray:
        p = np.asarray(ph, float)
        e = self._steps
        q = np.empty((4, 2))             # p + e[0], p - e[0], p + e[1], p - e[1]
        q[0::2] = p + e
        q[1::2] = p - e
        z = self.zb(q)
        return np.array([z[0] - z[1], z[2] - z[3]]) / (2.0 * self.delta)

    def gradients(self, ph) -> np.ndarray:
        """Seabed gradients at horizontal points ``ph`` (shape (n, 2)), shape (n, 2), as :meth:`gradient`. [-]"""
        p = np.asarray(ph, float)
        e = self._steps
        z = self.zb(np.concatenate([p + e[0], p - e[0], p + e[1], p - e[1]])).reshape(4, len(p))
        return np.stack([z[0] - z[1], z[2] - z[3]], axis=1) / (2.0 * self.delta)

    def slope_along(self, ph, d: float) -> float:
        """The seabed's slope under the horizontal point ``ph`` along the ship's direction at ``d``. [-]"""
        return float(self.gradient(ph) @ self.direction(d))

    def zb_under(self, pos: np.ndarray, above: float) -> np.ndarray:
        """The seabed's elevation under nodes ``pos`` (rows of x, y, z), ``-inf`` under those higher than ``above``
        (or NaN): those are neither on nor under the seabed, and are not looked up, as they may be off a grid. [m]"""
        low = pos[:, -1] <= above
        if low.all():                    # (as a rule: the seabed under every node)
            return self.zb(pos[:, :-1])
        zb = np.full(len(pos), -np.inf)
        if low.any():
            zb[low] = self.zb(pos[low, :-1])
        return zb

    def run(self, points) -> float:
        p = np.asarray(points, float)
        return float(np.sum(np.sqrt(np.sum(np.diff(p, axis=0) ** 2, axis=1))))


class _Memo:
    """Values of a function of horizontal points (x, y), remembered by the points' exact coordinates.

    The points are kept as complex numbers ``x + iy`` (the same bits), sorted, and found by
    ``numpy.searchsorted``: a point asked for again gets the value computed for it, bit for bit. A call where
    most of more than a few points are new (the cable after a time step) starts the memory afresh from its
    points, so it holds the last state of the cable and the few points asked for since; others add their new
    points.
    """

    _FEW = 4              # new points a call may add to the memory, whatever its size
    _CAP = 4096           # points remembered, at most (then a call starts afresh)

    def __init__(self):
        self.keys = np.empty(0, complex)
        self.values = np.empty(0)

    def get(self, p: np.ndarray, f) -> np.ndarray:
        """``f(p)`` for points ``p`` (shape (..., 2)), from memory where it holds them."""
        key = np.ascontiguousarray(p).reshape(-1, 2).view(complex)[:, 0]
        out = np.empty(key.size)
        if self.keys.size:
            i = np.minimum(np.searchsorted(self.keys, key), self.keys.size - 1)
            hit = self.keys[i] == key
            out[hit] = self.values[i[hit]]
            new = np.flatnonzero(~hit)
        else:
            new = np.arange(key.size)
        if new.size:
            out[new] = f(p.reshape(-1, 2)[new])
            if (new.size > self._FEW and 2 * new.size > key.size) or self.keys.size + new.size > self._CAP:
                order = np.argsort(key)
                self.keys, self.values = key[order], out[order]
            else:
                order = new[np.argsort(key[new])]
                at = np.searchsorted(self.keys, key[order])
                self.keys, self.values = np.insert(self.keys, at, key[order]), np.insert(self.values, at, out[order])
        return out.reshape(p.shape[:-1])

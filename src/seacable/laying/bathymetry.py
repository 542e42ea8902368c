"""Water depth for a route: a table along the route (KP, depth) or a grid (x, y, depth).

The grid and its readers (inline, CSV, NetCDF; GEBCO-like elevations; land masked) are
:class:`seacable.bathymetry.BathymetryGrid`'s, shared with the moorings' seabed; re-exported here. A complete rectangular
grid is interpolated bilinearly (``scipy.interpolate.RegularGridInterpolator``); scattered points
linearly on their Delaunay triangles (``LinearNDInterpolator``). A grid in longitude and latitude
needs a geographic route: points are taken back to degrees with the route's projection.
"""

from __future__ import annotations

import math

import numpy as np

from ..bathymetry import BathymetryGrid
from ..errors import InputError
from .inputs import Bathymetry
from .route import RouteGeometry

__all__ = ["BathymetryGrid", "SeabedMap", "seabed_map"]


class SeabedMap:
    """Water depth at any (x, y) near a route: from a KP table along it, or from a grid.

    ``depth(xy)`` returns NaN outside a grid; :meth:`check_covers` says where the route leaves it.
    ``shallowest`` is the least depth anywhere [m] (NaN when none is known).
    """

    def __init__(self, route: RouteGeometry, *, table: tuple[np.ndarray, np.ndarray] | None = None,
                 grid=None, depth: float | None = None, source: str = ""):
        self.route, self.table, self.source = route, table, source
        self._flat = depth
        self._interp = None
        self.kind = "xy"
        # the least depth anywhere, as linear interpolation stays within the values it interpolates [m]
        self.shallowest = float(np.min(table[1])) if table is not None else float(depth) if depth is not None \
            else math.nan
        if grid is not None:
            from scipy.interpolate import LinearNDInterpolator, RegularGridInterpolator

            self.kind, a, b, d = grid
            if self.kind == "lonlat" and route.transformer is None:
                raise InputError(f"{source}: a grid in longitude and latitude needs a route in latitude and "
                                 "longitude (to project between them). Suggested fix: give the route's waypoints "
                                 "as latitude and longitude, or the grid in x and y [m].")
            known = d[np.isfinite(d)]
            self.shallowest = float(np.min(known)) if known.size else math.nan
            if d.ndim == 2:
                d = np.where(np.isinf(d), np.nan, d)
                rgi = RegularGridInterpolator((b, a), d, bounds_error=False, fill_value=np.nan)
                if min(d.shape) > 1:
                    self._interp = _Bilinear(rgi)
                else:                  # (a line of points: scipy's own branch for it)
                    self._interp = lambda p, f=rgi: f(np.stack([p[..., 1], p[..., 0]], axis=-1))
                self.bounds = (a[0], a[-1], b[0], b[-1])
            else:
                lnd = LinearNDInterpolator(np.column_stack([a, b]), d)
                self._interp = lambda p, f=lnd: f(p[..., 0], p[..., 1])
                self.bounds = (a.min(), a.max(), b.min(), b.max())

    @property
    def compiled(self) -> bool:
        """Whether the depth is looked up by compiled code (a KP table, the route located by
        :func:`._lookup_kernel.nearest_on_legs`; a regular grid in x and y, :class:`_Bilinear`): quick enough that a
        laying run need not remember the points it looked up."""
        return (self.table is not None and self._interp is None) or (isinstance(self._interp, _Bilinear)
                                                                      and self.kind == "xy")

    @property
    def flat(self) -> bool:
        """Whether the depth is the same everywhere (no KP table, no grid)."""
        return self._interp is None and self.table is None

    def depth(self, xy, kp=None) -> np.ndarray:
        """Water depth at points (x, y); NaN outside a grid. [m]

        ``kp``: the points' KPs where the caller knows them (a KP table then skips locating the points)."""
        xy = np.asarray(xy, float)
        if self._interp is not None:
            if self.kind == "lonlat":
                lat, lon = self.route.to_geographic(xy)
                xy = np.stack([lon, lat], axis=-1)
            return np.asarray(self._interp(xy), float)
        if self.table is not None:
            if kp is None:
                kp, _ = self.route.locate(xy)
            return np.interp(kp, *self.table)
        return np.full(xy.shape[:-1], float(self._flat))

    def check_covers(self, xy, what: str, kp=None) -> None:
        """Raise an InputError naming the first point (and its KP) where the grid gives no depth: outside the
        grid, or inside it on land or in a hole (next to a grid point without a water depth)."""
        d = self.depth(xy)
        bad = ~np.isfinite(d)
        if bad.any():
            i = np.unravel_index(np.argmax(bad), bad.shape)
            p = np.asarray(xy, float)[i]
            where = f" at KP {float(np.asarray(kp)[i]):.1f} m" if kp is not None else ""
            q = p if self.kind == "xy" else np.array([v[0] for v in self.route.to_geographic(p[None, :])[::-1]])
            x0, x1, y0, y1 = self.bounds
            if x0 <= q[0] <= x1 and y0 <= q[1] <= y1:
                raise InputError(f"{self.source}: the {what}{where} reaches land or a hole in the seabed grid: no "
                                 f"water depth at x = {p[0]:.1f} m, y = {p[1]:.1f} m (next to a grid point at or "
                                 "above the surface, or without a value). Suggested fix: move the route off the land "
                                 "there, or fill the grid's hole.")
            raise InputError(f"{self.source}: the seabed grid does not cover the {what}{where}: no depth at x = "
                             f"{p[0]:.1f} m, y = {p[1]:.1f} m (grid bounds {self._bounds_text()}). Suggested fix: "
                             "extend the grid over the whole route and a margin either side for the touchdown's "
                             "offset, or shorten the route.")

    def _bounds_text(self) -> str:
        x0, x1, y0, y1 = self.bounds
        unit = "m" if self.kind == "xy" else "degree"
        return f"{x0:g}..{x1:g} x {y0:g}..{y1:g} {unit}"


class _Bilinear:
    """``RegularGridInterpolator((y, x), depth)`` (linear, NaN outside) at points (..., 2) of (x, y), without its
    per-call checks and dispatch (a grid is looked up several times a time step): compiled, with scipy's arithmetic
    operation for operation (:func:`._lookup_kernel.bilinear`) on the interpolator's own grid lines and depths (its
    lines ascending). For grids of at least 2 x 2 points.
    """

    def __init__(self, rgi):
        self.gy, self.gx = (np.ascontiguousarray(g, float) for g in rgi.grid)
        self.values = np.ascontiguousarray(rgi.values, float)

    def __call__(self, p: np.ndarray) -> np.ndarray:
        from ._lookup_kernel import bilinear

        p = np.asarray(p, float)
        out = np.empty(p[..., 0].size)
        bilinear(self.gx, self.gy, self.values, np.ascontiguousarray(p[..., 0]).ravel(),
                 np.ascontiguousarray(p[..., 1]).ravel(), out)
        return out.reshape(p.shape[:-1] or (1,))       # (one point: shape (1,), as scipy gives it)


def seabed_map(route: RouteGeometry, bathymetry: Bathymetry | None, grid: BathymetryGrid | None,
               depth: float, where: str = "analysis") -> SeabedMap:
    """The seabed of a route case: a KP table (``bathymetry``: distance = KP), a grid, or a flat ``depth``."""
    if grid is not None:
        return SeabedMap(route, grid=grid.load(), source=f"{where}.bathymetry_grid"
                         + (f" '{grid.file}'" if grid.file else ""))
    if bathymetry is not None:
        kp, h = bathymetry.table()
        lo, hi = route.kp[0], route.kp[-1]
        if kp[0] > lo + 1e-6 or kp[-1] < hi - 1e-6:
            raise InputError(f"{where}.bathymetry covers KP {kp[0]:g} to {kp[-1]:g} m, but the route runs from KP "
                             f"{lo:g} to {hi:g} m. Suggested fix: extend the bathymetry table over the whole route "
                             "(its 'distance' is the KP), or check the route's kp_start.")
        return SeabedMap(route, table=(kp, h), source=f"{where}.bathymetry")
    return SeabedMap(route, depth=depth, source="environment.depth")

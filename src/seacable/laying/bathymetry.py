"""Water depth for a route: a table along the route (KP, depth) or a grid (x, y, depth).

A grid comes inline, from a CSV file (columns x, y, depth, or longitude, latitude and depth or
elevation) or from a NetCDF file (an xarray grid with coordinates x, y or lon, lat and a variable
``depth``, positive down, or ``elevation``, positive up as GEBCO gives it). A complete rectangular
grid is interpolated bilinearly (``scipy.interpolate.RegularGridInterpolator``); scattered points
linearly on their Delaunay triangles (``LinearNDInterpolator``). A grid in longitude and latitude
needs a geographic route: points are taken back to degrees with the route's projection.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from pydantic import Field, model_validator

from .._model import Model
from ..errors import InputError
from .inputs import Bathymetry, csv_rows
from .route import RouteGeometry

__all__ = ["BathymetryGrid", "SeabedMap", "seabed_map"]

_DEPTH_NAMES = ("depth",)
_ELEVATION_NAMES = ("elevation", "z", "height")


class BathymetryGrid(Model):
    """Water depth on a grid: inline ``x``, ``y`` and ``depth[iy][ix]``, or a CSV or NetCDF ``file``.

    Parameters
    ----------
    x, y
        Grid lines, increasing. [m]
    depth
        Water depth at (y[i], x[j]), rows along y, > 0. [m]
    file
        A ``.csv`` (columns x, y, depth; or longitude, latitude and depth or elevation) or ``.nc`` file.
    variable
        Name of the depth (positive down) or elevation (positive up) variable in a NetCDF file; default
        ``depth``, else ``elevation``.
    """

    x: tuple[float, ...] | None = Field(None, description="Grid x, increasing. [m]")
    y: tuple[float, ...] | None = Field(None, description="Grid y, increasing. [m]")
    depth: tuple[tuple[float, ...], ...] | None = Field(None, description="Depths, one row per y. [m]")
    file: str | None = Field(None, description="CSV or NetCDF grid (relative to the case file).")
    variable: str | None = Field(None, description="NetCDF variable: depth (down) or elevation (up).")

    @model_validator(mode="after")
    def _check(self):
        inline = any(v is not None for v in (self.x, self.y, self.depth))
        if inline == (self.file is not None):
            raise ValueError("give the grid inline ('x', 'y' and 'depth', m) or as a 'file' (.csv or .nc).")
        if inline:
            if self.x is None or self.y is None or self.depth is None:
                raise ValueError("an inline grid needs 'x', 'y' and 'depth' (one row of depths per y).")
            _check_grid(np.asarray(self.x, float), np.asarray(self.y, float), _rows(self.depth), "bathymetry_grid")
        elif Path(self.file).suffix.lower() not in (".csv", ".nc", ".nc4", ".cdf"):
            raise ValueError(f"bathymetry_grid.file '{self.file}': give a .csv or a NetCDF (.nc) file.")
        return self

    def load(self) -> tuple[str, np.ndarray, np.ndarray, np.ndarray]:
        """``(kind, a, b, depth)``: kind ``"xy"`` or ``"lonlat"``; a regular grid as (1-D, 1-D, 2-D [b, a])
        or scattered points as three 1-D arrays."""
        if self.file is None:
            return "xy", np.asarray(self.x, float), np.asarray(self.y, float), _rows(self.depth)
        if Path(self.file).suffix.lower() == ".csv":
            return _read_csv_grid(self.file)
        return _read_netcdf_grid(self.file, self.variable)


def _rows(depth) -> np.ndarray:
    try:
        return np.asarray(depth, float)
    except ValueError:
        raise ValueError("bathymetry_grid.depth: every row needs one depth per x.") from None


def _check_grid(x: np.ndarray, y: np.ndarray, depth: np.ndarray, where: str) -> None:
    for name, a in (("x", x), ("y", y)):
        if a.ndim != 1 or a.size < 2 or not np.all(np.isfinite(a)) or np.any(np.diff(a) <= 0):
            raise ValueError(f"{where}: {name} must be 2 or more finite grid lines, strictly increasing [m].")
    if depth.shape != (y.size, x.size):
        raise ValueError(f"{where}: depth must have one row per y and one column per x, {y.size} x {x.size}, "
                         f"got shape {depth.shape}.")
    bad = ~(depth > 0)
    if bad.any():
        i, j = np.argwhere(bad)[0]
        raise ValueError(f"{where}: depth at x = {x[j]:g} m, y = {y[i]:g} m must be > 0 m, got {depth[i, j]:g} m. "
                         "Suggested fix: give depths below the surface as positive numbers (land cannot be laid "
                         "on).")


def _read_csv_grid(file: str):
    path, header, rows = csv_rows(file, "bathymetry grid")
    kind = "xy" if "x" in header and "y" in header else "lonlat" if "longitude" in header and "latitude" in \
        header else None
    value = next((n for n in _DEPTH_NAMES + _ELEVATION_NAMES if n in header), None)
    if kind is None or value is None:
        raise InputError(f"bathymetry grid '{path}' needs columns x, y (m) or longitude, latitude (degrees), and "
                         f"depth (m, down) or elevation (m, up); got {', '.join(header) or 'an empty file'}.")
    cols = ("x", "y") if kind == "xy" else ("longitude", "latitude")
    idx = [header.index(c) for c in (*cols, value)]
    try:
        v = np.array([[float(r[i]) for i in idx] for r in rows[1:]], float).reshape(-1, 3)
    except (ValueError, IndexError):
        raise InputError(f"bathymetry grid '{path}': every row needs numbers in {', '.join(cols)} and "
                         f"{value}.") from None
    if v.shape[0] < 3 or not np.all(np.isfinite(v)):
        raise InputError(f"bathymetry grid '{path}': needs at least 3 points, all finite.")
    depth = v[:, 2] if value in _DEPTH_NAMES else -v[:, 2]
    a, b = np.unique(v[:, 0]), np.unique(v[:, 1])
    if a.size * b.size == v.shape[0]:            # a complete grid in any row order
        grid = np.full((b.size, a.size), np.nan)
        grid[np.searchsorted(b, v[:, 1]), np.searchsorted(a, v[:, 0])] = depth
        if not np.isnan(grid).any():
            return kind, a, b, _checked(kind, a, b, grid, path)
    return kind, v[:, 0], v[:, 1], _checked(kind, v[:, 0], v[:, 1], depth, path)


def _checked(kind, a, b, depth, path) -> np.ndarray:
    """The grid's depths with land (and zero depth) marked +inf, as a hole: a file cut from GEBCO or EMODnet holds
    land, and only the cable's way over it matters (:meth:`SeabedMap.check_covers` names a point on land). A grid
    all land, or all at or above the surface, is refused: a sign error."""
    water = depth > 0
    if not water.any():
        k = tuple(np.argwhere(~water)[0]) if (~water).any() else (0,) * depth.ndim
        at = (a[k[-1]], b[k[0]]) if depth.ndim == 2 else (a[k[0]], b[k[0]])
        unit = "m" if kind == "xy" else "degree"
        raise InputError(f"bathymetry grid '{path}': no point of it is under water (at ({at[0]:g}, {at[1]:g}) {unit} "
                         f"the depth is {depth[k]:g} m): land, or a sign error (elevations are up, depths down). "
                         "Suggested fix: name the column or variable 'elevation' if the values are heights above the "
                         "sea, 'depth' if they are depths below it.")
    return np.where(water | np.isinf(depth), depth, np.inf)


def _read_netcdf_grid(file: str, variable: str | None):
    import xarray as xr

    path = Path(file)
    try:
        ds = xr.open_dataset(path)
    except (OSError, ValueError) as err:
        raise InputError(f"bathymetry grid '{path}' cannot be read as NetCDF ({err}). Suggested fix: check the "
                         "path (relative to the case file's folder) and the format.") from None
    with ds:
        names = [variable] if variable else [n for n in _DEPTH_NAMES + _ELEVATION_NAMES if n in ds.data_vars]
        if not names or names[0] not in ds.data_vars:
            raise InputError(f"bathymetry grid '{path}' has no variable {variable or 'depth or elevation'}; it has "
                             f"{', '.join(map(str, ds.data_vars)) or 'none'}. Suggested fix: name it with "
                             "bathymetry_grid.variable.")
        da = ds[names[0]]
        for kind, (xa, ya) in (("xy", ("x", "y")), ("lonlat", ("lon", "lat")), ("lonlat", ("longitude", "latitude"))):
            if xa in da.dims and ya in da.dims and da.ndim == 2:
                da = da.transpose(ya, xa)
                a, b = np.asarray(da[xa], float), np.asarray(da[ya], float)
                values = np.asarray(da, float)
                break
        else:
            raise InputError(f"bathymetry grid '{path}': variable '{names[0]}' must have the two dimensions (y, x) or "
                             f"(lat, lon), got {da.dims}.")
        elevation = names[0] in _ELEVATION_NAMES or (variable is not None and
                                                     str(da.attrs.get("positive", "")).lower() == "up")
    if a.size > 1 and a[1] < a[0]:
        a, values = a[::-1], values[:, ::-1]
    if b.size > 1 and b[1] < b[0]:
        b, values = b[::-1], values[::-1]
    depth = -values if elevation else values
    try:
        _check_grid(a, b, np.ones(depth.shape), f"bathymetry grid '{path}'")     # its lines (land: below)
    except ValueError as err:
        raise InputError(str(err)) from None
    return kind, a, b, _checked(kind, a, b, np.where(np.isnan(depth), np.inf, depth), path)


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

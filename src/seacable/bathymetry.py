"""Water depth on a grid (x, y, depth), read once for every model that stands on a seabed: the lay planner's route
(:mod:`seacable.laying.bathymetry`) and the finite-element line of moorings, systems and towed cables
(``environment.seabed.grid``: :class:`seacable.mooring.solver.Water`'s ``grid``).

A grid comes inline, from a CSV file (columns x, y, depth, or longitude, latitude and depth or
elevation) or from a NetCDF file (an xarray grid with coordinates x, y or lon, lat and a variable
``depth``, positive down, or ``elevation``, positive up as GEBCO gives it). Land (a depth at or above the
surface, or a missing value) is marked +inf, a hole in the grid.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from pydantic import Field, model_validator

from ._model import Model
from ._text import csv_rows
from .errors import InputError

__all__ = ["BathymetryGrid", "SeabedGrid", "cartesian_grid"]

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


def cartesian_grid(grid: BathymetryGrid, where: str = "environment.seabed.grid") -> SeabedGrid:
    """A grid's lines and seabed elevations in the case's own axes, for the finite-element line's seabed.

    Parameters
    ----------
    grid
        The grid (inline, CSV or NetCDF).
    where
        The input's key, for messages.

    Returns
    -------
    SeabedGrid
        The grid lines, increasing, (nx,) and (ny,) [m], and the seabed's elevation ``z = -depth`` at
        ``(y[i], x[j])`` (ny, nx), NaN on land (a depth at or above the surface, or a missing value). [m]

    Raises
    ------
    InputError
        For a grid in longitude and latitude (a mooring's axes are metres from its origin: there is no
        projection to place it) or scattered points (not a complete rectangular grid).
    """
    kind, a, b, depth = grid.load()
    src = f"{where}" + (f" '{grid.file}'" if grid.file else "")
    if kind != "xy":
        raise InputError(f"{src} is in longitude and latitude (degrees), but a mooring, a system and a towed line are "
                         "placed in metres from the case's origin: there is no projection between them. Suggested fix: "
                         "project the grid to x, y in metres about the origin (e.g. UTM minus the origin's easting and "
                         "northing) and give columns x, y (CSV) or coordinates x, y (NetCDF).")
    if depth.ndim != 2:
        raise InputError(f"{src} holds {a.size} scattered points, not a complete rectangular grid (every x with every "
                         "y). Suggested fix: resample the points onto a regular x, y grid (e.g. with "
                         "scipy.interpolate.griddata), marking land or holes with a depth of 0 or an empty value.")
    return SeabedGrid(a, b, np.where(np.isfinite(depth), -depth, np.nan))


class SeabedGrid:
    """A seabed on a Cartesian grid: lines ``x`` (nx,), ``y`` (ny,) [m] and elevations ``elevation`` (ny, nx) [m]
    (NaN on land), bilinear in each cell and level beyond the grid's edges, as the finite-element kernel takes it
    (:func:`seacable.mooring._seabed.grid_at`); compared and hashed by value (a :class:`~seacable.mooring.solver.Water`
    holds it)."""

    def __init__(self, x, y, elevation):
        self.x = np.ascontiguousarray(x, float)
        self.y = np.ascontiguousarray(y, float)
        self.elevation = np.ascontiguousarray(elevation, float)

    def __eq__(self, other):
        return isinstance(other, SeabedGrid) and all(
            a.shape == b.shape and np.array_equal(a, b, equal_nan=True)
            for a, b in ((self.x, other.x), (self.y, other.y), (self.elevation, other.elevation)))

    def __hash__(self):
        return hash((self.x.tobytes(), self.y.tobytes(), self.elevation.tobytes()))

    def _cells(self, px, py):
        """Each point's cell (i along x, j along y) and its fractions (tx, ty) across it, the points clamped to the
        grid, and whether each lies inside the grid's span along x and along y (strictly: beyond, level)."""
        cells = []
        for g, p in ((self.x, px), (self.y, py)):
            q = np.clip(p, g[0], g[-1])
            k = np.clip(np.searchsorted(g, q, side="right") - 1, 0, g.size - 2)
            cells += [k, (q - g[k]) / (g[k + 1] - g[k]), (p > g[0]) & (p < g[-1])]
        return cells

    def at(self, px, py):
        """Seabed elevation [m] and its gradient dz/dx, dz/dy [-] at points ``(px, py)`` [m] (any shape): bilinear
        in the cell under each point, the gradient along an axis 0 beyond the grid's span on it (level beyond)."""
        px, py = np.asarray(px, float), np.asarray(py, float)
        i, tx, inx, j, ty, iny = self._cells(px, py)
        z = self.elevation
        z00, z10, z01, z11 = z[j, i], z[j, i + 1], z[j + 1, i], z[j + 1, i + 1]
        dx, dy = self.x[i + 1] - self.x[i], self.y[j + 1] - self.y[j]
        zb = (1 - ty) * ((1 - tx) * z00 + tx * z10) + ty * ((1 - tx) * z01 + tx * z11)
        gx = np.where(inx, ((1 - ty) * (z10 - z00) + ty * (z11 - z01)) / dx, 0.0)
        gy = np.where(iny, ((1 - tx) * (z01 - z00) + tx * (z11 - z10)) / dy, 0.0)
        return zb, gx, gy

    def normal(self, px, py) -> np.ndarray:
        """The seabed's unit normal ``(-dz/dx, -dz/dy, 1) / norm`` at points ``(px, py)``, shape (..., 3). [-]"""
        _, gx, gy = self.at(px, py)
        n = np.stack([-gx, -gy, np.ones_like(gx)], axis=-1)
        return n / np.linalg.norm(n, axis=-1, keepdims=True)

    def env_block(self) -> np.ndarray:
        """The grid as the kernel's environment vector holds it after its fixed slots: x (nx), y (ny), then the
        elevations row by row along y (ny nx). [m]"""
        return np.concatenate([self.x, self.y, self.elevation.ravel()])

    def check_covers(self, X, what: str, where: str = "environment.seabed.grid") -> None:
        """Refuse points ``X`` (..., 3) [m] outside the grid's x, y span or over a cell with a land (NaN) corner,
        naming the first such point, ``what`` it is, and a fix."""
        X = np.asarray(X, float).reshape(-1, 3)
        if X.shape[0] == 0:
            return
        px, py = X[:, 0], X[:, 1]
        outside = (px < self.x[0]) | (px > self.x[-1]) | (py < self.y[0]) | (py > self.y[-1])
        if outside.any():
            k = int(np.argmax(outside))
            raise InputError(f"{where} does not cover the {what}: no seabed under x = {px[k]:.1f} m, y = {py[k]:.1f} m "
                             f"(the grid spans x {self.x[0]:g}..{self.x[-1]:g} m, y {self.y[0]:g}..{self.y[-1]:g} m). "
                             "Suggested fix: extend the grid over the whole line and its anchors, with a margin for "
                             "the line's motion, or move the line onto the grid.")
        i, _, _, j, _, _ = self._cells(px, py)
        z = self.elevation
        land = np.isnan(z[j, i]) | np.isnan(z[j, i + 1]) | np.isnan(z[j + 1, i]) | np.isnan(z[j + 1, i + 1])
        if land.any():
            k = int(np.argmax(land))
            raise InputError(f"{where}: the {what} at x = {px[k]:.1f} m, y = {py[k]:.1f} m lies over land or a hole "
                             f"in the grid (a cell x {self.x[i[k]]:g}..{self.x[i[k] + 1]:g} m, y {self.y[j[k]]:g}.."
                             f"{self.y[j[k] + 1]:g} m with a corner at or above the surface, or without a value). "
                             "Suggested fix: move the line off the land there, or fill the grid's hole.")

    def plane_under(self, a, b) -> tuple[float, float]:
        """The plane a line's catenary start takes from an end ``a`` (x, y, z) on the seabed towards ``b`` [m]: the
        water depth under ``a`` [m] (``-z`` of the seabed there) and the seabed's slope along the horizontal from
        ``a`` to ``b``, ``atan(grad z . u)`` [rad] (0 when ``b`` is above ``a``)."""
        zb, gx, gy = (float(v) for v in self.at(a[0], a[1]))
        d = np.asarray(b, float)[:2] - np.asarray(a, float)[:2]
        h = float(np.hypot(d[0], d[1]))
        return -zb, (float(np.arctan((gx * d[0] + gy * d[1]) / h)) if h > 0 else 0.0)

    def lift(self, X) -> np.ndarray:
        """Positions ``X`` (n, 3) [m] with the inner ones (not the two ends) under the seabed moved up onto it."""
        X = np.array(X, float)
        X[1:-1, 2] = np.maximum(X[1:-1, 2], self.at(X[1:-1, 0], X[1:-1, 1])[0])
        return X

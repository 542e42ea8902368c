"""A cable route: waypoints (alter-course positions), KP along them, and a local projection.

A route is a polyline of waypoints in local x, y [m] or in latitude and longitude [degree, WGS84].
Geographic waypoints are projected to x (east) and y (north) in metres by an azimuthal equidistant
projection centred at the first waypoint (pyproj / PROJ): distances and directions from the centre
are true on the ellipsoid, and the scale error a few hundred kilometres away is below 1e-3, so the
KP of a 100 km route is right to about a metre. Another projection (a UTM zone) is given as a PROJ
string or an EPSG code.

KP (kilometre point, here in metres as everything at the interfaces) is the distance along the
route from its first waypoint, plus ``kp_start``. The lateral offset of a point from the route is
positive to port (to the left looking along increasing KP).

With a ``turn_radius`` the ship sails each alter-course on a circular arc tangent to both legs (the
arc starts ``R tan(|turn|/2)`` before the waypoint), and the KP runs along the arcs. An arc is held as
a polyline of chords within 1 mm of the circle (its KP is short of the arc's length by ``R theta^3 /
(24 m^2)`` for ``m`` chords: under 1 mm for a quarter turn at 1 km).
"""

from __future__ import annotations

import numpy as np
from pydantic import Field, model_validator

from .._model import Model, quantity
from ..errors import InputError
from .inputs import csv_rows

__all__ = ["Route", "RouteGeometry"]


class Route(Model):
    """The planned route: waypoints in x, y [m] or latitude, longitude [degree], or a CSV file of them.

    Parameters
    ----------
    waypoints
        (x, y) of each waypoint, in order along the route. [m]
    latitude, longitude
        Geographic waypoints instead (WGS84). [degree]
    file
        CSV file with columns ``x`` and ``y``, or ``latitude`` and ``longitude`` (relative to the case file).
    kp_start
        KP of the first waypoint. [m]
    turn_radius
        Radius of the arc the ship sails at each alter-course, tangent to both legs: one value, or one per
        inner waypoint (0 for a sharp turn). [m]
    projection
        Projection of geographic waypoints to metres: a PROJ string or ``"EPSG:32631"``-style code; default
        azimuthal equidistant centred at the first waypoint.
    """

    waypoints: tuple[tuple[float, float], ...] | None = Field(None, description="Waypoints (x, y). [m]")
    latitude: tuple[float, ...] | None = Field(None, description="Waypoint latitudes (WGS84). [degree]")
    longitude: tuple[float, ...] | None = Field(None, description="Waypoint longitudes (WGS84). [degree]")
    file: str | None = Field(None, description="CSV of waypoints: columns x, y or latitude, longitude.")
    kp_start: quantity("m") = Field(0.0, description="KP of the first waypoint. [m]")
    turn_radius: quantity("m", ge=0.0) | tuple[quantity("m", ge=0.0), ...] | None = Field(
        None, description="Radius of the arc sailed at each alter-course: one for all, or one per inner "
                          "waypoint (0: a sharp turn). [m]")
    projection: str | None = Field(None, description="PROJ string or EPSG code for geographic waypoints.")

    @model_validator(mode="after")
    def _check(self):
        given = [name for name, value in (("waypoints", self.waypoints), ("latitude/longitude", self.latitude
                                          or self.longitude), ("file", self.file)) if value]
        if len(given) != 1:
            raise ValueError(f"give the route's waypoints one way: 'waypoints' [[x, y], ...] in m, 'latitude' and "
                             f"'longitude' lists in degrees, or a CSV 'file'; got {', '.join(given) or 'none'}.")
        if (self.latitude is None) != (self.longitude is None):
            raise ValueError("needs both 'latitude' and 'longitude' (degrees), of equal length.")
        if self.latitude is not None:
            _check_geographic(self.latitude, self.longitude, "route")
        elif self.waypoints is not None:
            _check_points(np.asarray(self.waypoints, float), "route.waypoints", "m")
        if isinstance(self.turn_radius, tuple) and (self.waypoints is not None or self.latitude is not None):
            n_inner = len(self.waypoints or self.latitude) - 2
            if len(self.turn_radius) != n_inner:
                raise ValueError(f"turn_radius has {len(self.turn_radius)} values but the route has {n_inner} inner "
                                 "waypoints (alter-courses). Suggested fix: one radius per inner waypoint, or one "
                                 "value for all.")
        if self.projection is not None and self.latitude is None and self.file is None:
            raise ValueError("route.projection applies to geographic waypoints (latitude, longitude). Suggested "
                             "fix: leave it out for waypoints in x, y [m].")
        return self

    def geometry(self) -> RouteGeometry:
        """The route in metres (reading and projecting the waypoints)."""
        if self.waypoints is not None:
            return RouteGeometry(np.asarray(self.waypoints, float), self.kp_start, turn_radius=self.turn_radius)
        if self.latitude is not None:
            lat, lon = np.asarray(self.latitude, float), np.asarray(self.longitude, float)
        else:
            table = _read_waypoints(self.file)
            if "x" in table:
                xy = np.column_stack([table["x"], table["y"]])
                _check_points_input(xy, f"route file '{self.file}'", "m")
                if self.projection is not None:
                    raise InputError(f"route.projection applies to geographic waypoints, but '{self.file}' gives "
                                     "x and y [m]. Suggested fix: leave projection out.")
                return RouteGeometry(xy, self.kp_start, turn_radius=self.turn_radius)
            lat, lon = table["latitude"], table["longitude"]
            try:
                _check_geographic(lat, lon, f"route file '{self.file}'")
            except ValueError as err:
                raise InputError(str(err)) from None
        return RouteGeometry.geographic(lat, lon, self.kp_start, self.projection, turn_radius=self.turn_radius)


def _check_geographic(lat, lon, where: str) -> None:
    lat, lon = np.asarray(lat, float), np.asarray(lon, float)
    if lat.size != lon.size:
        raise ValueError(f"{where}: latitude and longitude must have the same length, got {lat.size} and {lon.size}.")
    if not (np.all(np.isfinite(lat)) and np.all(np.isfinite(lon))):
        raise ValueError(f"{where}: latitudes and longitudes must be finite numbers [degree].")
    if np.any(np.abs(lat) > 90.0) or np.any(lon < -180.0) or np.any(lon > 360.0):
        raise ValueError(f"{where}: latitudes must lie in -90..90 and longitudes in -180..360 degrees, got "
                         f"{list(lat)} and {list(lon)}. Suggested fix: check that they are not swapped.")
    _check_points(np.column_stack([lon * 111e3 * np.cos(np.radians(lat)), lat * 111e3]), where, "m")


def _check_points(xy: np.ndarray, where: str, unit: str) -> None:
    """At least two waypoints, finite, none repeating the one before it (a leg of zero length)."""
    if xy.ndim != 2 or xy.shape[1] != 2:
        raise ValueError(f"{where}: each waypoint needs two numbers (x, y) [{unit}].")
    if xy.shape[0] < 2:
        raise ValueError(f"{where}: a route needs at least two waypoints, got {xy.shape[0]}. Suggested fix: give "
                         "the start and the end of the route, and the alter-course positions between them.")
    if not np.all(np.isfinite(xy)):
        raise ValueError(f"{where}: waypoints must be finite numbers.")
    legs = np.hypot(*np.diff(xy, axis=0).T)
    if np.any(legs < 1e-3):
        i = int(np.argmax(legs < 1e-3))
        raise ValueError(f"{where}: waypoints {i} and {i + 1} are the same point (a leg of {legs[i]:.3g} m): a "
                         "route's KP needs legs of non-zero length. Suggested fix: remove the repeated waypoint.")
    if unit == "m" and legs.sum() < 10.0 and np.all(np.abs(xy) <= 180.0):
        raise ValueError(f"{where}: the route is {legs.sum():.3g} m long, waypoints {xy[:2].tolist()} ...: they look "
                         "like degrees typed as x, y in metres. Suggested fix: give them as route.latitude and "
                         "route.longitude [deg], or the waypoints in metres.")


def _check_points_input(xy: np.ndarray, where: str, unit: str) -> None:
    try:
        _check_points(xy, where, unit)
    except ValueError as err:
        raise InputError(str(err)) from None


def _read_waypoints(file: str) -> dict[str, np.ndarray]:
    path, header, rows = csv_rows(file, "route file")
    for names in (("x", "y"), ("latitude", "longitude"), ("lat", "lon")):
        if all(n in header for n in names):
            idx = [header.index(n) for n in names]
            try:
                values = np.array([[float(r[i]) for i in idx] for r in rows[1:]], float).reshape(-1, 2)
            except (ValueError, IndexError):
                raise InputError(f"route file '{path}': every row needs numbers in the columns "
                                 f"{' and '.join(names)}.") from None
            keys = ("x", "y") if names == ("x", "y") else ("latitude", "longitude")
            return {keys[0]: values[:, 0], keys[1]: values[:, 1]}
    raise InputError(f"route file '{path}' needs a header row with columns 'x' and 'y' (m) or 'latitude' and "
                     f"'longitude' (degrees), got {', '.join(header) or 'an empty file'}.")


class RouteGeometry:
    """A route in metres: legs between the waypoints (and arcs at the alter-courses), KP along them.

    Parameters
    ----------
    xy : (n, 2) array
        Waypoints. [m]
    kp_start : float
        KP of the first waypoint. [m]
    transformer : pyproj.Transformer, optional
        Geographic to x, y, for routes given in latitude and longitude.
    turn_radius : float or sequence of float, optional
        Radius of the arc at each alter-course (one for all or one per inner waypoint; 0: sharp). [m]

    Attributes: ``waypoints`` (the given points), ``xy`` and ``kp`` (the track's vertices: the waypoints, or
    the chords of the arcs), ``waypoint_kp`` (KP of the route's point nearest each waypoint) and ``turn_kp``
    (where the heading starts or stops changing: the sharp waypoints and the ends of the arcs).
    """

    def __init__(self, xy: np.ndarray, kp_start: float = 0.0, transformer=None, turn_radius=None):
        self.waypoints = np.asarray(xy, float)
        _check_points_input(self.waypoints, "route", "m")
        self.transformer = transformer
        track, kinks, sharp = _arcs(self.waypoints, turn_radius)
        d = np.diff(track, axis=0)
        self.xy = track
        self.length = np.hypot(d[:, 0], d[:, 1])              # of each leg [m]
        self.direction = d / self.length[:, None]              # unit vector of each leg
        self.kp = kp_start + np.concatenate([[0.0], np.cumsum(self.length)])   # of each vertex [m]
        # each leg for locate: start, direction, and the bounds of the distance along it (the end legs extended)
        lo, hi = np.zeros(len(self.length)), self.length.copy()
        lo[0], hi[-1] = -np.inf, np.inf
        self._legs = (self.xy[:-1, 0].copy(), self.xy[:-1, 1].copy(), self.direction[:, 0].copy(),
                      self.direction[:, 1].copy(), lo, hi)
        x, y = self.xy[:, 0], self.xy[:, 1]
        self._boxes = (np.minimum(x[:-1], x[1:]), np.maximum(x[:-1], x[1:]), np.minimum(y[:-1], y[1:]),
                       np.maximum(y[:-1], y[1:]))           # bounding box of each leg
        self.turn_kp = self.kp[kinks]
        # the change of heading at each inner vertex (+ to port), and which are sharp (not an arc's chords)
        a = np.arctan2(self.direction[:, 1], self.direction[:, 0])
        self.vertex_turn = np.angle(np.exp(1j * np.diff(a)))
        self.sharp = np.zeros(self.vertex_turn.size, bool)
        self.sharp[sharp - 1] = True
        self.waypoint_kp = self.locate(self.waypoints)[0] if turn_radius is not None else self.kp.copy()

    @classmethod
    def geographic(cls, latitude, longitude, kp_start: float = 0.0, projection: str | None = None,
                   turn_radius=None) -> RouteGeometry:
        """A route from WGS84 waypoints, projected (default: azimuthal equidistant at the first waypoint)."""
        from pyproj import CRS, Transformer
        from pyproj.exceptions import CRSError

        lat, lon = np.asarray(latitude, float), np.asarray(longitude, float)
        proj = projection or f"+proj=aeqd +lat_0={float(lat[0])!r} +lon_0={float(lon[0])!r} +datum=WGS84 +units=m +no_defs"
        try:
            crs = CRS.from_user_input(proj)
        except CRSError as err:
            raise InputError(f"route.projection '{projection}' is not a projection PROJ knows ({err}). Suggested "
                             "fix: an EPSG code such as 'EPSG:32631' (UTM 31N) or leave it out.") from None
        if not crs.is_projected:
            raise InputError(f"route.projection '{projection}' is not a projected system (its units are not "
                             "metres). Suggested fix: a UTM zone, e.g. 'EPSG:32631', or leave it out.")
        transformer = Transformer.from_crs("EPSG:4326", crs, always_xy=True)
        x, y = transformer.transform(lon, lat)
        return cls(np.column_stack([x, y]), kp_start, transformer, turn_radius)

    @property
    def kp_end(self) -> float:
        return float(self.kp[-1])

    def leg(self, kp) -> np.ndarray:
        """Index of the leg holding each KP (the first or last leg beyond the ends)."""
        kp = np.asarray(kp, float)
        k = np.searchsorted(self.kp, kp, side="right") - 1
        if kp.ndim == 0:                  # (the ship's KP, several times a step: numpy.clip is slow on a scalar)
            return min(max(int(k), 0), len(self.length) - 1)
        return np.clip(k, 0, len(self.length) - 1)

    def point(self, kp) -> np.ndarray:
        """(x, y) of the route at ``kp`` (along the first or last leg beyond the ends); shape ``kp.shape + (2,)``."""
        kp = np.asarray(kp, float)
        k = self.leg(kp)
        return self.xy[k] + (kp - self.kp[k])[..., None] * self.direction[k]

    def heading(self, kp) -> np.ndarray:
        """Direction of the route at ``kp``, from +x towards +y (of the leg after a waypoint). [rad]"""
        d = self.direction[self.leg(kp)]
        return np.arctan2(d[..., 1], d[..., 0])

    def smooth_heading(self, kp) -> np.ndarray:
        """Direction of the route at ``kp`` with the arcs' headings continuous: across each chord of an arc the
        heading runs linearly from the circle's at one end to the circle's at the other (half the vertices' turns
        either side), so that only the sharp waypoints change it in a step. [rad]"""
        kp = np.asarray(kp, float)
        k = self.leg(kp)
        soft = np.where(self.sharp, 0.0, self.vertex_turn)        # of the inner vertices 1 .. n-2
        before = np.concatenate([[0.0], soft])[k]                 # at the leg's start vertex
        after = np.concatenate([soft, [0.0]])[k]                  # at its end vertex
        f = np.clip((kp - self.kp[k]) / self.length[k], 0.0, 1.0)
        return self.heading(kp) - 0.5 * before * (1.0 - f) + 0.5 * after * f

    def turns(self) -> np.ndarray:
        """Alter-course at each inner waypoint, positive to port (counter-clockwise). [rad]"""
        return _turns(self.waypoints)

    def locate(self, xy, *, chunk: int = 2048) -> tuple[np.ndarray, np.ndarray]:
        """KP of the nearest point of the route to each point, and the lateral offset (+ to port). [m]

        Beyond the route's ends the first and last legs are extended, so a point before the start has a
        KP below ``kp_start``. A route of many legs compares each point with the legs near it only
        (:meth:`_candidates`); the answer is the same as comparing every leg, bit for bit (a point as far from
        two legs, as past the outside of an alter-course, goes to the first of them).
        """
        p = np.asarray(xy, float).reshape(-1, 2)
        shape = np.asarray(xy).shape[:-1]
        kp = np.empty(len(p))
        off = np.empty(len(p))
        for a in range(0, len(p), chunk):
            q = p[a:a + chunk]
            kp[a:a + chunk], off[a:a + chunk] = self._nearest(q, self._candidates(q))
        return kp.reshape(shape), off.reshape(shape)

    _SAMPLE = 10.0         # m between the points of the k-d tree
    _K = 16                # nearest tree points whose legs are compared
    _PAIRS = 4096          # points x legs compared directly, at most
    _GROUP = 32            # consecutive points given the same legs by _nearby
    _WIDE = 64             # legs of a group, at most (else the k-d tree, point by point)

    def _candidates(self, q: np.ndarray) -> np.ndarray | _Ragged | None:
        """Legs to compare for each point, (m, c) in order of leg, or ``None`` for every leg.

        Every leg for a route of at most ``_K`` legs or a call of few points (at most ``_PAIRS`` point-leg
        pairs); else the legs near groups of consecutive points (:meth:`_nearby`), as a cable's nodes come; else,
        for points far apart, the legs of each point's ``_K`` nearest tree points and the two end legs.

        That last holds the nearest leg whenever every tree point within ``sqrt(d0^2 + _SAMPLE^2)`` of the point
        is among the ``_K``, ``d0`` the distance of the nearest tree point: the nearest leg, at ``d <= d0``, has a
        tree point within ``_SAMPLE / 2`` of the foot of the perpendicular, at ``sqrt(d^2 + _SAMPLE^2 / 4)`` from
        the point (a margin of 3/4 ``_SAMPLE^2`` over that). The other points get every leg. (The bound
        ``d0 + _SAMPLE`` holds too, but a point a few hundred metres off the route has about 20 tree points
        within it: more than ``_K``, so it was compared with every leg.)"""
        n_leg = len(self.length)
        if n_leg <= self._K or len(q) * n_leg <= self._PAIRS:
            return None
        cand = self._nearby(q)
        if cand is not None:
            return cand
        dist, idx = self._sample_tree().query(q, k=self._K)
        cand = np.sort(np.column_stack([self._tree_leg[idx], np.zeros(len(q), int), np.full(len(q), n_leg - 1)]),
                       axis=1)
        unsure = dist[:, -1] ** 2 <= dist[:, 0] ** 2 + self._SAMPLE ** 2
        if unsure.any():
            return _Ragged(cand, unsure)
        return cand

    def _sample_tree(self):
        """The k-d tree of points every ``_SAMPLE`` m along the legs (``_tree_leg``: the leg of each)."""
        if getattr(self, "_tree", None) is None:
            from scipy.spatial import cKDTree

            pts, legs = [], []
            for k in range(len(self.length)):
                n = max(int(np.ceil(self.length[k] / self._SAMPLE)), 1)
                u = np.linspace(0.0, self.length[k], n + 1)
                pts.append(self.xy[k] + u[:, None] * self.direction[k])
                legs.append(np.full(n + 1, k))
            self._tree, self._tree_leg = cKDTree(np.vstack(pts)), np.concatenate(legs)
        return self._tree

    def _nearby(self, q: np.ndarray) -> np.ndarray | None:
        """Legs near each group of ``_GROUP`` consecutive points, (m, c) in order of leg; ``None`` when a group
        has more than ``_WIDE`` legs near it (points far apart).

        A group's points lie in a box of half-diagonal ``R`` whose centre is ``d0`` from the nearest tree point,
        so each of them is within ``M = d0 + R`` of the route. A leg whose bounding box stays more than ``M``
        (plus a metre for rounding) from the group's box is farther than that from all of its points: it can be
        neither the nearest leg nor tie with it. The end legs, extended beyond the route's ends, are always in.
        """
        m, g = len(q), self._GROUP
        n = -(-m // g)
        fill = np.minimum(np.arange(n * g), m - 1)          # the last group filled up with its last point
        gx, gy = q[fill, 0].reshape(n, g), q[fill, 1].reshape(n, g)
        x0, x1, y0, y1 = gx.min(axis=1), gx.max(axis=1), gy.min(axis=1), gy.max(axis=1)
        d0, _ = self._sample_tree().query(np.column_stack([0.5 * (x0 + x1), 0.5 * (y0 + y1)]))
        reach = d0 + 0.5 * np.hypot(x1 - x0, y1 - y0) + 1.0
        x_lo, x_hi, y_lo, y_hi = self._boxes
        near = ((x_lo <= (x1 + reach)[:, None]) & (x_hi >= (x0 - reach)[:, None]) & (y_lo <= (y1 + reach)[:, None])
                & (y_hi >= (y0 - reach)[:, None]))
        near[:, 0] = near[:, -1] = True
        group, leg = np.nonzero(near)
        count = np.bincount(group, minlength=n)
        if count.max() > self._WIDE:
            return None
        cand = np.zeros((n, count.max()), int)      # short rows padded with leg 0, their first: ties go to it
        cand[group, np.arange(len(leg)) - (np.cumsum(count) - count)[group]] = leg
        return np.repeat(cand, g, axis=0)[:m]

    def _nearest(self, q: np.ndarray, cand) -> tuple[np.ndarray, np.ndarray]:
        """KP and offset of each point's nearest point on its candidate legs, (m, c) leg numbers or ``None`` for
        every leg."""
        if isinstance(cand, _Ragged):
            kp, off = self._nearest(q, cand.sure)
            kp[cand.unsure], off[cand.unsure] = self._nearest(q[cand.unsure], None)
            return kp, off
        legs = self._legs                                   # x0, y0, ux, uy, lower and upper bound of t
        if cand is None and np.isfinite(q).all():
            # (compiled: the same arithmetic, point by point, without the arrays of points x legs)
            from ._lookup_kernel import nearest_on_legs

            kp, off = np.empty(len(q)), np.empty(len(q))
            nearest_on_legs(np.ascontiguousarray(q[:, 0]), np.ascontiguousarray(q[:, 1]), *legs, self.kp, kp, off)
            return kp, off
        if cand is not None:
            legs = [a[cand] for a in legs]                  # (m, c) each; else (n_leg,), broadcast on (m, n_leg)
        x0, y0, ux, uy, lo, hi = legs
        qx, qy = q[:, :1], q[:, 1:]
        rx, ry = qx - x0, qy - y0
        t = np.clip(rx * ux + ry * uy, lo, hi)              # along the leg from its start, clipped to it
        ex, ey = qx - (x0 + t * ux), qy - (y0 + t * uy)      # from the foot to the point
        # the first leg of least distance as numpy.hypot has it, hypot (slow) taken only where the square is
        # within 1e-9 of the least (hypot and the square, both within an ulp or two, order the others alike)
        sq = ex * ex + ey * ey
        close = sq <= sq.min(axis=1, keepdims=True) * (1.0 + 1e-9)
        dist = np.full(sq.shape, np.inf)
        dist[close] = np.hypot(ex[close], ey[close])
        best = np.argmin(dist, axis=1)
        rows = np.arange(len(q))
        leg = best if cand is None else cand[rows, best]
        ub, vb = self._legs[2][leg], self._legs[3][leg]
        side = ub * ry[rows, best] - vb * rx[rows, best]
        return (self.kp[leg] + t[rows, best],
                np.where(side < 0.0, -1.0, 1.0) * np.hypot(ex[rows, best], ey[rows, best]))

    def variables(self) -> dict:
        """The route for a result: ``waypoint_x/y/kp`` (as given) and ``route_x/y`` (the track's vertices, with
        the arcs), as :func:`seacable.results.var` variables."""
        from ..results import var

        return {"waypoint_x": var("waypoint", self.waypoints[:, 0], "m", "route waypoint x"),
                "waypoint_y": var("waypoint", self.waypoints[:, 1], "m", "route waypoint y"),
                "waypoint_kp": var("waypoint", self.waypoint_kp, "m", "KP of the route's point nearest the waypoint"),
                "route_x": var("route_point", self.xy[:, 0], "m", "x of the route's track (arcs as chords)"),
                "route_y": var("route_point", self.xy[:, 1], "m", "y of the route's track (arcs as chords)")}

    def to_geographic(self, xy) -> tuple[np.ndarray, np.ndarray] | None:
        """(latitude, longitude) [degree] of points in x, y, for a geographic route; else ``None``."""
        if self.transformer is None:
            return None
        xy = np.asarray(xy, float)
        lon, lat = self.transformer.transform(xy[..., 0], xy[..., 1], direction="INVERSE")
        return np.asarray(lat), np.asarray(lon)

    def from_geographic(self, latitude, longitude) -> np.ndarray:
        """x, y [m] of geographic points, in this route's projection."""
        x, y = self.transformer.transform(np.asarray(longitude, float), np.asarray(latitude, float))
        return np.stack([np.asarray(x), np.asarray(y)], axis=-1)


def _turns(xy: np.ndarray) -> np.ndarray:
    d = np.diff(xy, axis=0)
    return np.angle(np.exp(1j * np.diff(np.arctan2(d[:, 1], d[:, 0]))))


_ARC_TOLERANCE = 1e-3    # m, largest distance of an arc's chord from the circle
_MAX_SHARP_TURN = 170.0  # deg, the largest alter-course at a waypoint without an arc (beyond: nearly back on itself)


def _arcs(xy: np.ndarray, turn_radius) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The track's vertices with each alter-course sailed on an arc tangent to both legs, the indices of the kinks
    (sharp waypoints, arc ends) and of the sharp waypoints among them."""
    n = len(xy)
    inner = n - 2
    radii = np.zeros(inner) if turn_radius is None else np.asarray(turn_radius, float)
    if radii.ndim == 0:
        radii = np.full(inner, float(radii))
    elif radii.shape != (inner,):
        raise InputError(f"route.turn_radius has {radii.size} values but the route has {inner} inner waypoints "
                         "(alter-courses). Suggested fix: one radius per inner waypoint, or one value for all.")
    theta = _turns(xy)
    d = np.diff(xy, axis=0)
    legs = np.hypot(d[:, 0], d[:, 1])
    u = d / legs[:, None]
    tangent = radii * np.tan(0.5 * np.abs(theta))
    cut = np.concatenate([[0.0], tangent, [0.0]])       # taken off each end of each leg: cut[i] at waypoint i
    over = cut[:-1] + cut[1:] > legs * (1.0 + 1e-12)
    if over.any():
        k = int(np.argmax(over))
        raise InputError(f"route.turn_radius: the arcs at the ends of the leg from waypoint {k + 1} to {k + 2} ("
                         f"{legs[k]:.6g} m) need {cut[k] + cut[k + 1]:.6g} m of it (R tan(turn/2) at each "
                         "alter-course). Suggested fix: a smaller turn radius there, or waypoints further apart.")
    pts, kinks, sharp = [xy[0]], [0], []
    for i in range(1, n - 1):
        r, th = radii[i - 1], theta[i - 1]
        if r == 0.0 and abs(th) > np.radians(_MAX_SHARP_TURN):
            raise InputError(f"route: the route turns back on itself at waypoint {i + 1} (an alter-course of "
                             f"{np.degrees(abs(th)):.1f} deg, more than {_MAX_SHARP_TURN:g}): the cable would be laid "
                             "back over itself. Suggested fix: sail the turn on an arc (route.turn_radius), or add "
                             "waypoints that take the route round.")
        if r == 0.0 or th == 0.0:
            kinks.append(len(pts))
            sharp.append(len(pts))
            pts.append(xy[i])
            continue
        a = xy[i] - tangent[i - 1] * u[i - 1]
        side = np.sign(th)
        centre = a + side * r * np.array([-u[i - 1][1], u[i - 1][0]])
        start = np.arctan2(*(a - centre)[::-1])
        m = max(int(np.ceil(abs(th) / (2.0 * np.arccos(max(1.0 - _ARC_TOLERANCE / r, -1.0))))), 1)
        phi = start + th * np.arange(m + 1) / m
        arc = centre + r * np.column_stack([np.cos(phi), np.sin(phi)])
        kinks.append(len(pts))
        pts.extend(arc)
        kinks.append(len(pts) - 1)
    kinks.append(len(pts))
    pts.append(xy[-1])
    track = np.array(pts)
    # drop a vertex repeating the one before (an arc ending where the next begins)
    keep = np.concatenate([[True], np.hypot(*np.diff(track, axis=0).T) > 1e-9])
    index = np.cumsum(keep) - 1
    return track[keep], np.unique(index[kinks]), np.unique(index[np.array(sharp, int)])


class _Ragged:
    """Candidates of :meth:`RouteGeometry._candidates` where some points need every leg."""

    def __init__(self, sure: np.ndarray, unsure: np.ndarray):
        self.sure, self.unsure = sure, unsure

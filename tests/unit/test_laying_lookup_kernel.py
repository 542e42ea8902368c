"""The compiled seabed look-ups of a 3-D lay (:mod:`seacable.laying._lookup_kernel`) give the bits of the numpy and
scipy expressions they replace: a route's nearest leg (KP and offset, the ties included) and a grid's bilinear
depth (scipy's ``RegularGridInterpolator``, NaN outside and at holes)."""

from __future__ import annotations

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from seacable.laying.bathymetry import _Bilinear
from seacable.laying.route import RouteGeometry


def _bits(a: np.ndarray) -> np.ndarray:
    return np.where(np.isnan(a), np.nan, a).view(np.int64)     # (any NaN alike)


def test_nearest_leg_is_the_numpy_expressions_bit_for_bit():
    """The compiled path (every leg, finite points) against the numpy path (the same legs given as candidates),
    on polylines, a circle of 1 deg chords (near ties everywhere) and points on the vertices and outside a corner
    (as far from two legs: the first wins)."""
    rng = np.random.default_rng(7)
    angle = np.arange(-0.5, 2.0 * np.pi - 0.3, np.radians(1.0))[:40]
    routes = [RouteGeometry(np.column_stack([300.0 * np.sin(angle), 300.0 * (1.0 - np.cos(angle))])),
              RouteGeometry(np.array([[0.0, 0.0], [100.0, 0.0], [100.0, 100.0]]), kp_start=-50.0)]
    routes += [RouteGeometry(np.cumsum(rng.uniform(-1000.0, 1000.0, (n, 2)), axis=0), kp_start=123.0)
               for n in (2, 5, 12)]
    for route in routes:
        n_leg = len(route.length)
        q = rng.uniform(route.xy.min(axis=0) - 300.0, route.xy.max(axis=0) + 300.0, (4096 // n_leg, 2))
        q[:len(route.xy[:3])] = route.xy[:3]
        q[3] = (200.0, -100.0)                        # outside the square corner: as far from both legs
        every = np.tile(np.arange(n_leg), (len(q), 1))
        kp, off = route._nearest(q, None)
        kp_ref, off_ref = route._nearest(q, every)
        np.testing.assert_array_equal(_bits(kp), _bits(kp_ref))
        np.testing.assert_array_equal(_bits(off), _bits(off_ref))


def test_bilinear_grid_is_scipys_interpolator_bit_for_bit():
    """Random grids (uneven lines, a hole) at random points, on the grid lines, at the corners, outside and NaN."""
    rng = np.random.default_rng(8)
    for trial in range(30):
        nx, ny = rng.integers(2, 9, size=2)
        a, b = np.sort(rng.uniform(-1000.0, 1000.0, nx)), np.sort(rng.uniform(-500.0, 500.0, ny))
        d = rng.uniform(10.0, 300.0, (ny, nx))
        if trial % 3 == 0:
            d[rng.integers(ny), rng.integers(nx)] = np.nan
        rgi = RegularGridInterpolator((b, a), d, bounds_error=False, fill_value=np.nan)
        p = np.column_stack([rng.uniform(a[0] - 50.0, a[-1] + 50.0, 2000), rng.uniform(b[0] - 50.0, b[-1] + 50.0, 2000)])
        p[:100, 0] = rng.choice(a, 100)
        p[50:150, 1] = rng.choice(b, 100)
        p[150], p[151], p[152, 0] = (a[-1], b[-1]), (a[0], b[0]), np.nan
        for q in (p, p.reshape(40, 50, 2), p[7]):
            ref = rgi(np.stack([q[..., 1], q[..., 0]], axis=-1))
            got = _Bilinear(rgi)(q)
            assert got.shape == ref.shape
            np.testing.assert_array_equal(_bits(got), _bits(ref))

"""Route geometry (:mod:`seacable.laying.route`) against closed forms: an alter-course sailed on an arc.

A two-leg route A -> B -> C with legs L1, L2 and an alter-course ``theta`` at B, sailed on an arc of radius R
tangent to both legs, has the arc start ``R tan(|theta|/2)`` before B and end as far after it, so that

* the route's length is ``L1 + L2 - 2 R tan(|theta|/2) + R |theta|``,
* the arc's start is at KP ``kp0 + L1 - R tan(|theta|/2)`` and its end ``R |theta|`` further,
* B's nearest route point is the arc's middle (KP ``arc start + R |theta| / 2``), ``R (1/cos(theta/2) - 1)``
  outside the turn (to starboard for a turn to port),
* a point at angle ``phi`` round the arc has KP ``arc start + R phi``, and one ``d`` from the centre an offset of
  ``R - d`` to the turn's side.

The arc is held as chords within ``e = 1 mm`` of the circle (``_ARC_TOLERANCE``). A chord of angle ``p`` has
sagitta ``R p^2 / 8 <= e`` and falls short of its arc by ``R p^3 / 24 = (p / 3)(R p^2 / 8) <= e p / 3``; summed
over the arc the KP is short by at most ``e |theta| / 3`` (0.8 mm at 135 deg), and every point of the chords is
within ``e`` of the circle. The tolerances below are those bounds (plus 1e-9 of the length for rounding):
a wrong tangent length (``R sin(theta)``, ``R tan(theta)``, ``R``) or arc length (``R sin(theta)``, the chord)
is off by metres at one of the angles tested, a thousand times more.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.laying.route import Route, RouteGeometry

E = 1e-3                                   # m, the chords' largest distance from the circle


def _two_legs(l1, l2, theta):
    """Waypoints A = (0, 0), B = (L1, 0), C = B + L2 (cos theta, sin theta)."""
    return np.array([[0.0, 0.0], [l1, 0.0], [l1 + l2 * math.cos(theta), l2 * math.sin(theta)]])


CASES = [(deg, r) for deg in (10.0, 45.0, 90.0, 135.0) for r in (50.0, 300.0, 1000.0)]


@pytest.mark.parametrize("sign", [1.0, -1.0], ids=["port", "starboard"])
@pytest.mark.parametrize("deg, radius", CASES)
def test_alter_course_length_and_kp_of_the_arc(deg, radius, sign):
    """Length ``L1 + L2 - 2 R tan(theta/2) + R theta`` and the arc's start and end KPs, short by at most the
    chords' ``e theta / 3``; a turn to starboard the mirror image of one to port."""
    theta = math.radians(deg)
    l1, l2, kp0 = 5000.0, 4000.0, 1234.5
    route = RouteGeometry(_two_legs(l1, l2, sign * theta), kp0, turn_radius=radius)
    t = radius * math.tan(theta / 2.0)
    arc = radius * theta
    slack = E * theta / 3.0 + 1e-9 * (l1 + l2)
    length = route.kp_end - kp0
    exact = l1 + l2 - 2.0 * t + arc
    assert exact - slack <= length <= exact + 1e-9 * (l1 + l2), (length, exact)
    # turn_kp: the start of the route, the arc's start and end, the end of the route
    assert route.turn_kp.size == 4
    assert route.turn_kp[0] == pytest.approx(kp0, abs=1e-9)
    assert route.turn_kp[1] == pytest.approx(kp0 + l1 - t, abs=1e-6)            # the first leg is exact
    assert kp0 + l1 - t + arc - slack <= route.turn_kp[2] <= kp0 + l1 - t + arc + 1e-6
    assert route.turn_kp[3] == pytest.approx(route.kp_end, abs=1e-9)
    # the heading: 0 along the first leg, theta along the second, theta / 2 at the arc's middle
    assert float(route.heading(kp0 + 0.5 * (l1 - t))) == pytest.approx(0.0, abs=1e-12)
    assert float(route.heading(route.kp_end - 1.0)) == pytest.approx(sign * theta, abs=1e-9)
    mid = kp0 + l1 - t + 0.5 * arc
    # smooth heading: the circle's own heading along the chords, to half a chord's angle (below 2 sqrt(2e/R))
    assert float(route.smooth_heading(mid)) == pytest.approx(sign * theta / 2.0, abs=2.0 * math.sqrt(2 * E / radius))
    assert route.sharp.sum() == 0


@pytest.mark.parametrize("sign", [1.0, -1.0], ids=["port", "starboard"])
@pytest.mark.parametrize("deg, radius", CASES)
def test_alter_course_waypoint_kp_offset_and_points_on_the_arc(deg, radius, sign):
    """The waypoint's KP is the arc's middle, its offset ``R (1/cos(theta/2) - 1)`` outside the turn; a point
    ``d`` from the centre at angle ``phi`` round the arc has KP ``arc start + R phi`` and offset ``R - d`` to the
    side of the turn; ``point(kp)`` of the arc's KPs lies on the circle (each within the chords' ``e``)."""
    theta = math.radians(deg)
    l1, l2, kp0 = 3000.0, 3500.0, -200.0
    route = RouteGeometry(_two_legs(l1, l2, sign * theta), kp0, turn_radius=radius)
    t = radius * math.tan(theta / 2.0)
    start = kp0 + l1 - t
    slack = E * theta / 3.0 + E + 1e-9 * (l1 + l2)
    assert route.waypoint_kp[1] == pytest.approx(start + 0.5 * radius * theta, abs=slack)
    assert route.waypoint_kp[0] == pytest.approx(kp0, abs=1e-9)
    assert route.waypoint_kp[2] == pytest.approx(route.kp_end, abs=1e-9)
    kp_b, off_b = route.locate(np.array([[l1, 0.0]]))
    assert float(off_b[0]) == pytest.approx(-sign * radius * (1.0 / math.cos(theta / 2.0) - 1.0), abs=E)
    # the arc's centre: R to the turn's side of its start (l1 - t, 0)
    centre = np.array([l1 - t, sign * radius])
    phi = np.linspace(0.05, 0.95, 7) * theta
    for d in (radius, 0.8 * radius, 1.3 * radius):
        p = centre + d * np.column_stack([np.sin(phi), -sign * np.cos(phi)])
        kp, off = route.locate(p)
        # KP: the chords' shortfall (e theta / 3) and, off the circle, the foot's shift along a chord (within
        # e of the circle, a chord's normal departs from the radius by at most half its angle 2 sqrt(2 e / R):
        # |d - R| times that along the route)
        tol = slack + abs(d - radius) * 2.0 * math.sqrt(2.0 * E / radius)
        np.testing.assert_allclose(kp, start + radius * phi, atol=tol)
        np.testing.assert_allclose(off, sign * (radius - d), atol=E + 1e-9 * radius)
    # point(): the route's points at the arc's KPs lie on the circle, at the angle their KP gives
    q = route.point(start + radius * phi)
    np.testing.assert_allclose(np.hypot(*(q - centre).T), radius, atol=E)
    ang = np.arctan2(q[:, 0] - centre[0], -sign * (q[:, 1] - centre[1]))
    np.testing.assert_allclose(ang, phi, atol=(slack + E) / radius)


@pytest.mark.parametrize("deg", [10.0, 45.0, 90.0, 135.0, 170.0])
def test_sharp_alter_course_length_kp_and_offsets(deg):
    """Without an arc the length is ``L1 + L2`` exactly and the waypoint's KP ``L1``; a point ``h`` off the first
    leg (before the turn) has KP ``x`` and offset ``+h`` to port; on the outside of the corner, inside the wedge
    between the legs' normals at B, the nearest route point is B itself (KP ``L1``, offset its distance)."""
    theta = math.radians(deg)
    l1, l2 = 2000.0, 1500.0
    route = Route(waypoints=tuple(map(tuple, _two_legs(l1, l2, theta))), kp_start=100.0).geometry()
    assert route.kp_end == pytest.approx(100.0 + l1 + l2, rel=1e-14)
    np.testing.assert_allclose(route.waypoint_kp, [100.0, 100.0 + l1, 100.0 + l1 + l2], rtol=1e-14)
    kp, off = route.locate(np.array([[700.0, 35.0], [700.0, -35.0], [-50.0, 10.0]]))
    np.testing.assert_allclose(kp, [800.0, 800.0, 50.0], atol=1e-9)              # before the start: KP < kp_start
    np.testing.assert_allclose(off, [35.0, -35.0, 10.0], atol=1e-9)
    # outside the corner (to starboard of a port turn), along the bisector of the normals: nearest is B
    bis = np.array([math.sin(theta / 2.0), -math.cos(theta / 2.0)])
    kp, off = route.locate(np.array([[l1, 0.0]]) + 40.0 * bis)
    assert float(kp[0]) == pytest.approx(100.0 + l1, abs=1e-9)
    assert float(off[0]) == pytest.approx(-40.0, abs=1e-9)
    assert route.sharp.all()


def test_several_alter_courses_add_up():
    """A route of three alter-courses (+30, -120, +75 deg) on different radii: the length is the sum of the
    legs less ``2 R_i tan(|theta_i|/2)`` plus ``R_i |theta_i|`` for each, and each arc's start and end KP are at
    their closed forms (each to the chords' shortfall accumulated so far)."""
    turns = np.radians([30.0, -120.0, 75.0])
    radii = np.array([400.0, 150.0, 0.0])
    legs = np.array([2000.0, 1800.0, 1600.0, 2200.0])
    heading = np.concatenate([[0.0], np.cumsum(turns)])
    xy = np.vstack([[0.0, 0.0], np.cumsum(legs[:, None] * np.column_stack([np.cos(heading), np.sin(heading)]),
                                          axis=0)])
    route = Route(waypoints=tuple(map(tuple, xy)), turn_radius=tuple(radii)).geometry()
    t = radii * np.tan(0.5 * np.abs(turns))
    arcs = radii * np.abs(turns)
    slack = E * np.abs(turns).sum() / 3.0 + 1e-6
    assert route.kp_end == pytest.approx(legs.sum() - 2.0 * t.sum() + arcs.sum(), abs=slack)
    s1 = legs[0] - t[0]
    e1 = s1 + arcs[0]
    s2 = e1 + legs[1] - t[0] - t[1]
    e2 = s2 + arcs[1]
    b3 = e2 + legs[2] - t[1]                               # the sharp waypoint
    np.testing.assert_allclose(route.turn_kp, [0.0, s1, e1, s2, e2, b3, route.kp_end], atol=slack)
    assert route.sharp.sum() == 1
    assert float(route.kp[route.sharp.nonzero()[0][0] + 1]) == pytest.approx(b3, abs=slack)


def test_geographic_route_on_the_equator_is_the_equatorial_arc():
    """Along the equator the geodesic is the equator: one degree of longitude is ``a pi / 180`` =
    111 319.491 m (WGS84 a = 6 378 137 m), and the azimuthal equidistant projection keeps distances from its
    centre true, so the KP of the end of 0 -> 1 deg E is that, to PROJ's rounding (1 mm); and a point 0.001 deg
    north of the route's middle lies to port (north of an eastward route) by the meridian's arc there."""
    route = Route(latitude=(0.0, 0.0), longitude=(0.0, 1.0), kp_start=0.0).geometry()
    assert route.kp_end == pytest.approx(6378137.0 * math.pi / 180.0, abs=1e-3)
    kp, off = route.locate(route.from_geographic(0.001, 0.5))
    # one thousandth of a degree of latitude at the equator: the meridian's radius of curvature there
    # a (1 - e^2) = 6 335 439 m, times pi / 180 / 1000 = 110.574 m (aeqd: 0.5 deg away, its scale error ~1e-5)
    assert float(off) == pytest.approx(6378137.0 * (1 - 0.00669437999014) * math.pi / 180e3, abs=0.05)
    assert float(kp) == pytest.approx(0.5 * 6378137.0 * math.pi / 180.0, rel=1e-4)

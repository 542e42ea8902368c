"""The wind's and the current's force tables of a free body in the coupled step (issue 39):
``F = 1/2 rho |u| u C(beta)`` of the flow relative to the body's reference point, ``beta`` its direction in the body's
axes (:func:`seacable.system.dynamics.body.body_load`), and their Newton tangent (:func:`body_tangent`).

The kernel's force is checked against the closed form and against :meth:`seacable.wind.WindCoefficients.force`
(NumPy, the periodic interpolation of :func:`seacable._heading.heading_weights`), on a body without mass, volume or
other loads, so that ``f6`` is the tables' force alone.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.system.dynamics import body as DB
from seacable.system.dynamics.frames import F_SIZE
from seacable.wind import AIR_DENSITY, WindCoefficients

RHO = 1025.0
# an asymmetric table (areas differ at every heading, yaw moment of both signs), headings given out of order
HEADINGS = np.radians([90.0, 0.0, 200.0, 300.0])
SURGE, SWAY, YAW = [300.0, 1000.0, -800.0, 500.0], [2000.0, 100.0, -400.0, -1500.0], [4e4, 0.0, -2e4, 6e4]
TABLE = WindCoefficients(heading=HEADINGS, surge=SURGE, sway=SWAY, yaw=YAW)


def _par(current: bool, wind: bool) -> np.ndarray:
    """A body's parameter row (no mass, volume or waterplane) with the table as its current's and/or wind's."""
    order = np.argsort(np.mod(HEADINGS, 2 * math.pi))
    rows = np.stack([np.mod(HEADINGS, 2 * math.pi)[order], np.array(SURGE)[order], np.array(SWAY)[order],
                     np.array(YAW)[order]], axis=1).ravel()
    par = np.zeros(DB.B_SIZE + 2 * rows.size)
    par[DB.B_NCUR], par[DB.B_NWIND], par[DB.B_RHOAIR] = (4 if current else 0), (4 if wind else 0), AIR_DENSITY
    tables = [rows] * (int(current) + int(wind))
    if tables:
        par[DB.B_TAB:DB.B_TAB + sum(t.size for t in tables)] = np.concatenate(tables)
    return par


def _load(par, velocity, current=(0.0, 0.0), wind=(0.0, 0.0), yaw=0.0):
    """The body's f6 at yaw ``yaw``, moving at ``velocity`` (x, y), in the current and wind (x, y) given."""
    q = np.array([0.0, 0.0, 0.0, 0.0, 0.0, yaw])
    qd = np.array([velocity[0], velocity[1], 0.0, 0.0, 0.0, 0.0])
    uc = np.array([current[0], current[1], 0.0, 0.0, 0.0])
    ext_t = np.array([0.0, 10.0])
    ext_f = np.zeros((2, 8))
    ext_f[:, 6:] = wind
    f6, M6 = np.zeros(6), np.zeros((6, 6))
    zero = np.zeros((6, 6))
    DB.body_load(q, qd, uc, 3.0, par, zero, zero, zero, zero, ext_t, ext_f, 2, RHO, 9.80665, f6, M6, np.zeros(F_SIZE))
    return f6, uc


def test_a_wind_on_a_still_body_along_a_tabled_heading_is_the_closed_form():
    """Along the body's x axis (the 0 deg row: surge 1000 m^2, sway 100 m^2, yaw 0) at 20 m/s:
    1/2 rho_air U^2 times the areas, in the global axes of a body at yaw 0."""
    f6, uc = _load(_par(False, True), (0.0, 0.0), wind=(20.0, 0.0))
    q = 0.5 * AIR_DENSITY * 20.0 ** 2
    np.testing.assert_allclose(f6, [q * 1000.0, q * 100.0, 0.0, 0.0, 0.0, 0.0], rtol=1e-12, atol=1e-9)
    assert list(uc[3:]) == [20.0, 0.0]  # the wind's velocity kept for the tangent


@pytest.mark.parametrize("velocity, flow, yaw", [
    ((0.0, 0.0), (12.0, 5.0), 0.0),         # between the 0 and 90 deg rows
    ((1.5, -0.7), (-9.0, 3.0), 0.4),        # moving, yawed: the relative flow at ~ 140 deg in the body's axes
    ((0.3, 0.2), (2.0, -11.0), -2.5),       # across the 300 -> 0 deg wrap
    ((4.0, 1.0), (1.0, 1.0), 1.0),          # the body faster than the flow: the force reverses
])
def test_the_wind_table_takes_the_relative_velocity_in_the_body_axes(velocity, flow, yaw):
    """The kernel's force equals WindCoefficients.force (NumPy) with the body's velocity and yaw, for a flow at
    any direction, the body turned and moving: to round-off."""
    f6, _ = _load(_par(False, True), velocity, wind=flow, yaw=yaw)
    ref = TABLE.force(np.array(flow), body_velocity=np.array(velocity), yaw=yaw, rho_air=AIR_DENSITY)
    np.testing.assert_allclose(f6[[0, 1, 5]], ref, rtol=1e-10, atol=1e-9 * np.abs(ref).max())
    assert np.all(f6[2:5] == 0.0)


@pytest.mark.parametrize("velocity, flow, yaw", [((0.0, 0.0), (1.2, 0.5), 0.0), ((0.3, -0.1), (-0.9, 0.6), 0.7)])
def test_the_current_table_takes_the_waters_density_and_the_current(velocity, flow, yaw):
    """The current's table: the same law in the water's density, on the current relative to the body."""
    f6, _ = _load(_par(True, False), velocity, current=flow, yaw=yaw)
    ref = TABLE.force(np.array(flow), body_velocity=np.array(velocity), yaw=yaw, rho_air=RHO)
    np.testing.assert_allclose(f6[[0, 1, 5]], ref, rtol=1e-10, atol=1e-9 * np.abs(ref).max())


def test_current_and_wind_tables_add():
    """Both tables (the current's rows first, then the wind's) each on its own flow."""
    both, _ = _load(_par(True, True), (0.2, 0.1), current=(1.0, -0.5), wind=(-15.0, 8.0), yaw=0.3)
    cur, _ = _load(_par(True, False), (0.2, 0.1), current=(1.0, -0.5), yaw=0.3)
    win, _ = _load(_par(False, True), (0.2, 0.1), wind=(-15.0, 8.0), yaw=0.3)
    np.testing.assert_allclose(both, cur + win, rtol=1e-12, atol=1e-6)


@pytest.mark.parametrize("current, wind", [(True, False), (False, True), (True, True)])
def test_the_newton_tangent_is_the_loads_velocity_derivative(current, wind):
    """``C = -df6/dqd`` of body_tangent in surge and sway against central differences of body_load (the Newton
    matrix of the coupled step; 1e-5 relative: the differences' own error)."""
    par = _par(current, wind)
    flow = {"current": (0.9, -0.4), "wind": (14.0, 6.0), "yaw": 0.6}
    v0 = np.array([0.3, 0.5])
    _, uc = _load(par, v0, **flow)
    q = np.array([0.0, 0.0, 0.0, 0.0, 0.0, flow["yaw"]])
    qd = np.array([v0[0], v0[1], 0.0, 0.0, 0.0, 0.0])
    zero = np.zeros((6, 6))
    K, C = np.zeros((6, 6)), np.zeros((6, 6))
    DB.body_tangent(q, qd, uc, par, zero, zero, zero, RHO, 9.80665, K, C, np.zeros(F_SIZE))
    h = 1e-4
    for j in range(2):
        dv = np.zeros(2)
        dv[j] = h
        fp, _ = _load(par, v0 + dv, **flow)
        fm, _ = _load(par, v0 - dv, **flow)
        np.testing.assert_allclose(C[[0, 1, 5], j], -(fp - fm)[[0, 1, 5]] / (2 * h), rtol=1e-5,
                                   atol=1e-6 * np.abs(C).max())

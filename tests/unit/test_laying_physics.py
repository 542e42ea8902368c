"""Physics terms of the laying model, each against a closed form that fails when the term is wrong.

* Tangential drag: a steady lay pays out faster than the cable sinks along itself; the skin friction
  ``D_T = 1/2 C_t rho pi d V_f |V_f|`` per metre, ``V_f = V_c - V_s cos(alpha)`` (paper 001 eq. (4), (6),
  with the diameter that the printed eq. (14) drops, SPEC), takes ``D_T h / sin(alpha)`` off the ship
  tension ``w h`` of the straight lay (eq. (2), (10); seacable.statics.laying.straight_line_lay), and
  leaves the angle (eq. (7), normal balance) alone.
* Added mass, normal and tangential: a node between two slack segments falls under its weight with the
  acceleration ``w / (m + m_a)`` of the direction it moves in: ``m_a`` is the normal added mass across
  the cable and the tangential one along it (paper 001 eq. (12)-(14) as corrected in SPEC); one backward
  Euler step of the kernel gives ``v' = a dt`` exactly. And the case's added-mass coefficients reach the
  model as ``C_a rho pi d^2 / 4`` per metre.
"""

import math

import numpy as np
import pytest

import seacable as sc
from seacable.laying import kernel as K
from seacable.laying.run import lay_parameters
from seacable.laying.solver import props_row
from seacable.statics.laying import laying_angle, straight_line_lay

CD, RHO, D, W, DEPTH = 1.85, 1030.0, 0.0225, 4.49, 50.0


def test_tangential_drag_lowers_the_ship_tension_of_a_steady_lay():
    """2 m/s, 30 % slack (V_c = 2.6 m/s), C_t = 0.02: V_f = 2.6 - 2 cos(13.05 deg) = 0.651 m/s, D_T = 0.308 N/m
    over L = 221.6 m: the ship tension is w h - D_T L = 224.5 - 68.5 = 156.0 N."""
    cdt, vs, slack = 0.02, 2.0, 0.3
    cable = sc.LineType(diameter=D, mass_per_length=0.867, weight_in_water=W, drag_normal=CD, drag_tangential=cdt,
                        added_mass_normal=1.0, name="paper 001 cable with skin friction")
    ds = sc.run(sc.Case(name="ct", line=sc.Line.single(cable, 5000.0),
                        environment=sc.Environment(water_density=RHO, depth=DEPTH),
                        analysis=sc.LayingDynamicAnalysis(ship=sc.ShipMotion(speed=vs),
                                                          payout=sc.PayoutSlack(slack=slack), duration=400.0,
                                                          segment_length=1.0, output_interval=2.0)))
    theory = straight_line_lay(DEPTH, vs, W, D, CD, cdt, payout_speed=(1.0 + slack) * vs, water_density=RHO)
    drag_effect = W * DEPTH - theory.top_tension
    assert drag_effect == pytest.approx(68.5, abs=0.1)      # the size of the term under test
    # the node births at the surface (every l / V_c) leave a ripple of 0.2 % of w h on the ship tension
    # (test_paper001_laying.test_ship_tension_is_wh); the mean of the last 40 s is within 0.5 % of w h = 1.1 N,
    # 1.6 % of the drag effect: dropping the diameter (x 44), pi (x 0.32) or the sign of the term fails
    top = float(np.mean(ds.top_tension.values[-20:]))
    assert top == pytest.approx(theory.top_tension, abs=5e-3 * W * DEPTH)
    # the tangential drag does not enter the normal balance: the angle is eq. (7)'s, to the transient's 1e-4 deg
    assert float(ds.entry_angle[-1]) == pytest.approx(float(laying_angle(vs, W, D, CD, RHO)), abs=math.radians(1e-4))
    assert float(np.max(ds.bottom_tension.values[-20:])) == 0.0


@pytest.mark.parametrize("theta_deg", [0.0, 90.0, 30.0])
def test_added_mass_sets_the_acceleration_of_a_falling_node(theta_deg):
    """A node between two slack segments whose chords make the angle theta with the horizontal falls under
    its weight W with M a = W, M = m + e_n n n^T + e_t t t^T: across the cable with w / (m + e_n), along it
    with w / (m + e_t). One backward-Euler step from rest without drag: v' = a dt, r' = r + a dt^2."""
    mass, weight, e_n, e_t = 2.0, 10.0, 1.5, 0.25          # per metre: kg/m, N/m, kg/m, kg/m
    props = np.array([props_row(mass, weight, 0.02, 0.0, 0.0, e_n, e_t, 0.0)])
    th = math.radians(theta_deg)
    t = np.array([math.cos(th), math.sin(th)])
    n = np.array([-t[1], t[0]])
    pos = np.array([-5.0 * t, [0.0, 0.0], 5.0 * t]) + np.array([0.0, -20.0])   # chords of 5 m ...
    L = np.array([6.0, 6.0])                                                    # ... in 6 m segments: slack
    T, act = np.zeros(2), np.zeros(2, dtype=np.int64)
    new_pos, new_vel = np.zeros_like(pos), np.zeros_like(pos)
    dt = 0.05
    status, _, _ = K.implicit_step(pos, np.zeros_like(pos), pos[-1].copy(), L, np.zeros(2, dtype=np.int64), props,
                                   np.zeros((3, 4)), np.zeros(1), np.zeros((1, 2)), 1025.0, dt, T, act, 0.0,
                                   K.no_contact(3, 2), 1e-12, 20, 5,
                                   new_pos, new_vel)
    assert status == K.STEP_OK and np.all(T == 0.0)
    g = np.array([0.0, -weight / mass])                    # weight over mass per metre (the node carries 6 m)
    a = (mass / (mass + e_n)) * (g @ n) * n + (mass / (mass + e_t)) * (g @ t) * t
    # the step's closed form, to round-off
    np.testing.assert_allclose(new_vel[1], a * dt, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(new_pos[1], pos[1] + a * dt * dt, rtol=1e-12, atol=1e-14)
    # and it is not the fall without added mass (the term is 6 % to 43 % of the acceleration here)
    assert abs(new_vel[1, 1] - g[1] * dt) > 0.05 * abs(g[1] * dt)


def test_added_mass_coefficients_reach_the_model():
    """Added mass per metre = C_a rho pi d^2 / 4, across (C_a,n) and along (C_a,t) the cable."""
    cable = sc.LineType(diameter=0.05, mass_per_length=3.0, drag_normal=1.2, drag_tangential=0.01,
                        added_mass_normal=1.0, added_mass_tangential=0.2, name="c")
    case = sc.Case(name="am", line=sc.Line.single(cable, 3000.0), environment=sc.Environment(water_density=1025.0,
                                                                                                 depth=50.0),
                   analysis=sc.LayingDynamicAnalysis(ship=sc.ShipMotion(speed=1.0), duration=10.0))
    row = lay_parameters(case).props[0]
    area = math.pi * 0.05 ** 2 / 4.0
    assert row[K.P_EN] == pytest.approx(1.0 * 1025.0 * area, rel=1e-12)
    assert row[K.P_ET] == pytest.approx(0.2 * 1025.0 * area, rel=1e-12)
    assert row[K.P_CDT] == 0.01 and row[K.P_CDN] == 1.2

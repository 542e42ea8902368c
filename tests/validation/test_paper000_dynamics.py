"""Validation of the towed-cable dynamics (box scheme) against paper 000 and closed forms.

Paper 000: Park, H. I. and Jung, D. H., nonlinear dynamic analysis of a low-tension towed cable by
the finite difference method (seeds/000_e4cc68758a51635b.txt), Tables 1-3 and Fig. 4-5.

What the paper's numbers correspond to (found here, see also examples/paper000_turn.yaml):

- Table 2 (steady tow) is the cable with NO tangential drag: 1171.15 N at the top is
  w0 L sin(phi_c) at the critical angle for a 2 m/s relative flow; eq. (6)'s drag with
  C_dt = 0.01 would give 1496 N.
- Table 3 (the 0.5 deg/s turn) is matched only WITH eq. (6)'s tangential drag: the top tension
  relative to its value at t = 0 falls by the paper's percentages to within 0.1 % of the tension,
  whereas without tangential drag it rises during the turn. The reason is exact: integrating the
  tangential equation along the cable gives T_top = w0 (z_top - z_end) + (inertia and tangential
  drag), and Fig. 5 shows the free end sinking; only the loss of tangential drag as the relative
  flow turns away from the cable can make the tension fall. The paper evidently ran the turn with
  the drag and printed it from Table 2's level, so we compare T(t)/T(0) with Table 3 / 1171.15.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
from _evidence import check

from seacable import Current
from seacable.statics.towed import critical_angle, towed_cable_steady
from seacable.towed.solver import TowedBodyParameters, cable_parameters, simulate, steady_tow
from seacable.towed.vessel import StraightPath, TablePath, TurnPath, sample_path

# Table 1, with the mass, EA and EI derived as documented in examples/paper000_turn.yaml
L, D, W0, RHO = 170.0, 0.035, 17.7, 1025.0
MASS = W0 / 9.81 + RHO * math.pi * D * D / 4.0
EA, EI = 4.4e8 * math.pi * D**2 / 4.0, 4.4e8 * math.pi * D**4 / 64.0
CURRENT = Current.uniform(-1.0)
TABLE2 = np.array([0.0, 195.50, 390.38, 585.57, 780.76, 975.96, 1171.15])
TABLE3_TIMES = np.array([20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0, 90.0, 100.0])
TABLE3 = np.array([1168.35, 1166.20, 1162.15, 1159.60, 1157.35, 1155.32, 1154.15, 1153.30, 1153.15])
TURN = functools.partial(sample_path, TurnPath(speed=1.0, turn_rate=math.radians(0.5)))


def params(n, cdt=0.01, **kw):
    base = dict(axial_stiffness=EA, bending_stiffness=EI, drag_normal=1.5, drag_tangential=cdt)
    base.update(kw)
    return cable_parameters(L, n, MASS, W0, D, **base)


@functools.lru_cache(maxsize=None)
def turn_run(n, cdt=0.01, dt=0.5):
    return simulate(params(n, cdt), n, TURN, 100.0, dt, output_interval=10.0, current=CURRENT)


def test_table2_steady_tensions_of_the_box_scheme():
    h = steady_tow(params(7, cdt=0.0), 7, [1.0, 0.0, 0.0], CURRENT)
    # 0.5 % of each tension (the tolerance); ours is within 0.16 % (node 2), the free end
    # is exactly zero by its boundary condition.
    check(h[1:, 0], TABLE2[1:], rtol=5e-3, source="Paper 000 (towed cable), Table 2", unit="N",
          quantity="steady tension by node of the box scheme (time-domain model's start)",
          why="0.5 % acceptance band, as the statics")
    assert h[0, 0] == 0.0


def test_steady_tow_with_tangential_drag_is_the_critical_angle_solution():
    # Inextensible cable: a free-ended cable lies straight at the critical angle and
    # dT/ds = w0 sin(phi) + 1/2 rho C_dt pi d U^2 cos^2(phi) exactly; the box scheme integrates a
    # constant slope exactly, so only the EI boundary layers (length sqrt(EI/T) < 0.2 m of 170 m)
    # differ: 1e-4.
    u = 2.0
    phi = critical_angle(W0, D, u, 1.5, RHO)
    slope = W0 * math.sin(phi) + 0.5 * RHO * 0.01 * math.pi * D * u * u * math.cos(phi) ** 2
    h = steady_tow(params(7, axial_stiffness=math.inf), 7, [1.0, 0.0, 0.0], CURRENT)
    np.testing.assert_allclose(h[:, 0], slope * np.linspace(0.0, L, 7), rtol=1e-4, atol=1e-6)
    np.testing.assert_allclose(-h[:, 7], phi, atol=1e-4)
    # With EA the strain (< 0.35 %) enters the drag through sqrt(1+e): the 0.5 % against
    # the analytic inextensible top tension 1496.3 N.
    h = steady_tow(params(7), 7, [1.0, 0.0, 0.0], CURRENT)
    assert h[-1, 0] == pytest.approx(slope * L, rel=5e-3)


def test_time_domain_steady_tow_stays_steady():
    path = functools.partial(sample_path, StraightPath(speed=1.0))
    run = simulate(params(7), 7, path, 20.0, 0.5, output_interval=5.0, current=CURRENT)
    # the initial state solves the same discrete equations, so nothing moves but round-off
    # (Newton tolerance 1e-8 on the scaled state).
    np.testing.assert_allclose(run.state[:, :, 0], run.state[[0] * run.time.size, :, 0], atol=1e-5)
    np.testing.assert_allclose(run.position[-1, :, 0] - run.position[0, :, 0], 20.0, atol=1e-6)


def test_table3_turn_top_tension():
    run = turn_run(7)
    top = run.state[:, -1, 0]
    ours = np.interp(TABLE3_TIMES, run.time, top) / top[0] * TABLE2[-1]
    # issue tolerance 1 % of each value; we hold 0.5 %, and measure <= 0.1 % (the paper's own
    # deviation from WHOI Cable is up to 0.27 %).
    check(ours, TABLE3, rtol=5e-3, source="Paper 000 (towed cable), Table 3", unit="N",
          quantity="top tension in the 0.5 deg/s turn, 20-100 s (box scheme, 7 nodes)",
          why="0.5 % (the issue's 1 %; the paper's own deviation from WHOI Cable is up to 0.27 %)")
    assert np.all(np.diff(top) < 0)  # falls monotonically, as the table


def test_turn_without_tangential_drag_follows_the_free_end_depth():
    # The exact integral of the tangential equation: T_top = w0 (z_top - z_end) + inertia, where
    # the inertia term is < m a_t L ~ 2.8 * 0.01 * 170 = 5 N; plus the strain (1+e <= 1.003)
    # between dz and ds: 0.5 % in all.
    run = turn_run(7, cdt=0.0)
    depth = run.vessel_position[:, 2] - run.position[:, 0, 2]
    np.testing.assert_allclose(run.state[:, -1, 0], W0 * depth, rtol=5e-3)
    assert run.state[-1, -1, 0] > run.state[0, -1, 0] + 30.0  # so it rises as the end sinks


def test_fig4_fig5_turn_trajectories():
    run = turn_run(7)
    omega = math.radians(0.5)
    # the vessel follows its circle exactly (closed form, round-off)
    assert run.vessel_position[-1, 1] == pytest.approx((1 - math.cos(100 * omega)) / omega, rel=1e-9)
    assert run.vessel_position[-1, 1] == pytest.approx(40.0, abs=1.0)  # "about 40 m" (Fig. 4)
    # The free end moves sideways a few metres only. We get 4.3 m (an independent lumped-mass check
    # gave 3.9-4.3 m); the paper's "about 6 m" is read off Fig. 4 at a scale of tens of metres.
    # Bounds: more than a tenth and less than a fifth of the vessel's 40.9 m.
    y_end = run.position[-1, 0, 1] - run.position[0, 0, 1]
    y_vessel = run.vessel_position[-1, 1] - run.vessel_position[0, 1]
    assert 0.1 * y_vessel < y_end < 0.2 * y_vessel
    # Fig. 5: the free end sinks, slowly for about 30 s, then faster.
    depth = -run.position[:, 0, 2]
    assert np.all(np.diff(depth[1:]) > 0)
    early, late = depth[3] - depth[0], depth[-1] - depth[3]
    assert late > 10 * early


def test_refinement_converges_and_the_paper_grid_error():
    tops = {n: turn_run(n).state[-1, -1, 0] for n in (7, 50, 200)}
    # converging: the 50 -> 200 change is far smaller than the 7 -> 50 change
    assert abs(tops[200] - tops[50]) < 0.1 * abs(tops[50] - tops[7])
    # the paper's 7-node answer is 0.025 % from the converged one (0.37 N of 1472.8 N): < 0.1 %
    assert tops[7] == pytest.approx(tops[200], rel=1e-3)


def test_observed_order_in_space():
    # Top tension at 100 s of the turn on 24, 48, 96, 192 intervals; differences shrink by 4 per
    # halving for a second-order scheme. Measured 2.3, 2.1, 2.0: accept 1.7-2.5.
    q = [turn_run(n).state[-1, -1, 0] for n in (25, 49, 97, 193)]
    d = np.abs(np.diff(q))
    orders = np.log2(d[:-1] / d[1:])
    assert np.all((orders > 1.7) & (orders < 2.5)), orders


def test_observed_order_in_time(tmp_path):
    # A smooth speed-up with a sideways drift (acceleration continuous, so no axial ringing is
    # excited). The lateral position of the free end at 16 s converges at order 2 (measured 2.0,
    # 1.96, 2.05). The top tension carries the undamped axial mode (period 2L/sqrt(EA/m) = 0.9 s)
    # of the non-dissipative centred scheme, so it is not used for the order.
    t = np.linspace(0.0, 20.0, 401)
    ramp = np.clip(t, 0.0, 10.0) / 10.0
    u = 1.0 + 0.25 * (1.0 - np.cos(np.pi * ramp))
    v = 0.2 * np.sin(np.pi * ramp) ** 2
    f = tmp_path / "vel.csv"
    np.savetxt(f, np.c_[t, u, v], delimiter=",", header="time,u,v", comments="")
    path = functools.partial(sample_path, TablePath(file=str(f), kind="velocity"))
    y = [simulate(params(25), 25, path, 16.0, dt, output_interval=16.0, current=CURRENT).position[-1, 0, 1]
         for dt in (0.4, 0.2, 0.1, 0.05)]
    d = np.abs(np.diff(y))
    orders = np.log2(d[:-1] / d[1:])
    assert np.all((orders > 1.7) & (orders < 2.4)), orders


def test_transverse_pulse_travels_at_the_string_speed(tmp_path):
    # A nearly weightless cable with no normal drag towed straight behind a drag body: uniform
    # tension T (the body's drag). A smooth sideways pulse of the tow point travels down the cable
    # at c = sqrt(T / (m + m_a)) in material coordinates.
    n, mass, w = 201, 1.0, 0.02
    par = cable_parameters(L, n, mass, w, D, axial_stiffness=1e9, bending_stiffness=0.01, drag_normal=0.0,
                           drag_tangential=0.0)
    body = TowedBodyParameters(mass=50.0, weight_in_water=0.0, drag_area=0.5)
    u = 2.0
    t = np.linspace(0.0, 40.0, 2001)
    sway = 0.05 * np.exp(-(((t - 3.0) / 0.5) ** 2))
    tab = np.c_[t, np.full_like(t, u), sway]
    f = tmp_path / "pulse.csv"
    np.savetxt(f, tab, delimiter=",", header="time,u,v", comments="")
    path = functools.partial(sample_path, TablePath(file=str(f), kind="velocity"))
    # 9 s: the pulse (peak at 3 s at the tow point, half-width 0.5 s) has passed the farthest node of the three
    # (7.5 s) by three half-widths; its reflection off the body comes back inverted
    run = simulate(par, n, path, 9.0, 0.01, output_interval=0.01, body=body)
    tension = run.state[0, n // 2, 0]
    m_a = RHO * math.pi * D * D / 4.0
    c = math.sqrt(tension / (mass + m_a))
    vy = run.velocity[:, :, 1]
    arrivals = []
    for j in (n - 1 - 40, n - 1 - 80, n - 1 - 120):
        k = np.argmax(vy[:, j])
        # parabolic refinement of the peak time
        y0, y1, y2 = vy[k - 1, j], vy[k, j], vy[k + 1, j]
        arrivals.append(run.time[k] + 0.01 * 0.5 * (y0 - y2) / (y0 - 2 * y1 + y2))
    s_dist = np.array([40, 80, 120]) * (run.s[1] - run.s[0])
    speed = np.polyfit(arrivals, s_dist, 1)[0]
    # 1 %: dispersion of the 0.5 s pulse on 0.85 m nodes and the small tension gradient along the
    # cable (w L / T < 0.4 %)
    assert speed == pytest.approx(c, rel=1e-2)


def test_settles_to_the_static_solution_behind_a_body(tmp_path):
    # Still water; the vessel speeds up smoothly from 1.0 to 1.5 m/s and holds it. The cable and
    # body settle (time constant ~100 s) to the steady solution at 1.5 m/s of the same discrete
    # equations: after 800 s within 1e-4 of the tension. (A ramp with kinks would leave an axial
    # oscillation of ~0.3 N that the centred scheme does not damp.) That steady solution converges
    # at second order to the statics module's steady tow (2-D ODE integration, no EI): 0.05 % on
    # 96 intervals.
    body = TowedBodyParameters(mass=300.0, added_mass=50.0, weight_in_water=1500.0, drag_area=0.3)
    n = 25
    t = np.linspace(0.0, 1000.0, 2001)
    u = 1.0 + 0.25 * (1.0 - np.cos(np.pi * np.clip(t, 0.0, 20.0) / 20.0))
    f = tmp_path / "speed.csv"
    np.savetxt(f, np.c_[t, u, 0.0 * t], delimiter=",", header="time,u,v", comments="")
    path = functools.partial(sample_path, TablePath(file=str(f), kind="velocity"))
    run = simulate(params(n), n, path, 800.0, 2.0, output_interval=800.0, body=body)
    steady = steady_tow(params(n), n, [1.5, 0.0, 0.0], None, body)
    np.testing.assert_allclose(run.state[-1, :, 0], steady[:, 0], rtol=1e-4)
    n = 97
    steady = steady_tow(params(n), n, [1.5, 0.0, 0.0], None, body)
    ref = towed_cable_steady(L, W0, D, 1.5, 1.5, 0.01, water_density=RHO, axial_stiffness=EA,
                             body_weight=1500.0, body_drag_area=0.3, n_points=n)
    np.testing.assert_allclose(steady[:, 0], ref.tension, rtol=5e-4)
    pos = np.zeros((n, 3))
    from seacable.towed.equations import integrate_positions

    integrate_positions(steady, np.zeros(3), params(n), pos)
    # positions: x astern in the statics module; 0.05 % of the layback and depth
    assert -pos[0, 0] == pytest.approx(ref.x[0], rel=5e-4)
    assert pos[0, 2] == pytest.approx(ref.z[0], rel=5e-4)


def stop_and_go(n, ei):
    from seacable.towed.vessel import SpeedSchedule as Sched

    w = 2.0
    par = cable_parameters(L, n, w / 9.81 + RHO * math.pi * D * D / 4, w, D, axial_stiffness=EA,
                           bending_stiffness=ei, drag_normal=1.5, drag_tangential=0.01)
    path = functools.partial(sample_path, Sched(times=(0, 5, 15, 40, 50), speeds=(2, 2, 0, 0, 2)))
    return simulate(par, n, path, 80.0, 0.1, output_interval=0.5)


def test_stop_and_go_low_tension_is_well_posed():
    # examples/towed_stop_and_go.yaml: the top tension falls to ~3 % of its steady value.
    runs = {n: stop_and_go(n, EI) for n in (25, 49, 97)}
    top = {n: r.state[:, -1, 0] for n, r in runs.items()}
    assert top[97].min() < 0.05 * top[97][0]
    assert all(r.halvings == 0 for r in runs.values())
    # with the section's EI the low-tension answer converges with the grid: the minimum top tension
    # to 0.5 N (of 14.4 N) and the free-end track to 5 cm between 48 and 96 intervals
    assert top[49].min() == pytest.approx(top[97].min(), abs=0.5)
    assert np.abs(runs[49].position[:, 0] - runs[97].position[:, 0]).max() < 0.05
    # and the curvature stays that of a smooth cable, |Omega| * ds << 1 rad per interval
    omega = np.abs(runs[25].state[:, :, 8:10]).max()
    assert omega * L / 24 < 1.0
    # Without it (EI = 0.01 N m^2) the same grid carries kinks of several radians per interval and
    # compressive tension: the ill-posed low-tension string (Triantafyllou & Howell 1994).
    rough = stop_and_go(25, 0.01)
    assert np.abs(rough.state[:, :, 8:10]).max() > 10 * omega
    assert rough.state[:, 1:, 0].min() < 0.0

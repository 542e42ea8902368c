"""Mooring-system statics: closed-form checks of its own (no peer code needed).

- The analytic stiffness equals central differences of the equilibrium forces (the body held at
  perturbed positions, free points re-equilibrated): 1e-5 relative.
- A system of one line between two held points is exactly seacable's single-line catenary.
- At equilibrium the forces and moments on every free body and free point sum to zero, computed
  here independently from the result (line end forces, weight, buoyancy, waterplane, loads).
- Bad input: an unstable body, a current, a point below the seabed, no equilibrium.
"""

import math

import numpy as np
import pytest

from seacable.environment import Current, Environment
from seacable.errors import ConvergenceError, InputError
from seacable.line import Line
from seacable.statics.catenary import catenary
from seacable.system import _stat_examples as ex
from seacable.system._stat_model import euler, rotation
from seacable.system.model import MooringSystem, SystemLine, SystemPoint
from seacable.system.statics import _rotvec, solve_equilibrium, system_stiffness


def _line_load_on_body(eq, body):
    """Net force and moment about the reference point of the lines on ``body`` (from the result)."""
    X = eq.body_position[eq.body_names.index(body)][:3]
    f6 = np.zeros(6)
    for i, name in enumerate(eq.line_names):
        sl = eq.system.lines[name]
        for end, f in ((sl.end_a, eq.end_a_force[i]), (sl.end_b, eq.end_b_force[i])):
            p = eq.system.points[end]
            if p.kind == "body" and p.body == body:
                r = eq.point_position[eq.point_names.index(end)] - X
                f6[:3] += f
                f6[3:] += np.cross(r, f)
    return f6


def _held(system, body, q):
    bodies = dict(system.bodies)
    bodies[body] = bodies[body].model_copy(update={"kind": "prescribed", "position": tuple(q)})
    return MooringSystem(points=system.points, bodies=bodies, lines=system.lines)


@pytest.mark.parametrize("build", [ex.oc4_semi, ex.moored_buoy])
def test_stiffness_equals_central_differences_of_equilibrium(build):
    system, env = build()
    body = next(iter(system.bodies))
    eq = solve_equilibrium(system, env, external={body: np.array([1e4, 5e3, 0, 0, 0, 2e3]) * (
        100 if build is ex.oc4_semi else 1)}, tol=1e-12)
    q = eq.body_position[0]
    K_fd = np.zeros((6, 6))
    # steps: 1 mm and 1e-5 rad; truncation error ~ (h/L)^2 and the 1e-12 solves keep round-off
    # below 1e-8 of the force changes (K h ~ 1e2..1e5 N)
    for j in range(6):
        h = 1e-3 if j < 3 else 1e-5
        loads = []
        for sgn in (1, -1):
            qp = q.copy()
            if j < 3:
                qp[j] += sgn * h
            else:
                th = np.zeros(3)
                th[j - 3] = sgn * h
                qp[3:] = euler(_rotvec(th) @ rotation(q[3:]))   # small rotation about the global axis
            e2 = solve_equilibrium(_held(system, body, qp), env, tol=1e-12)
            loads.append(_line_load_on_body(e2, body))
        K_fd[:, j] = -(loads[0] - loads[1]) / (2 * h)
    K = eq.stiffness
    for blk in (slice(0, 3), slice(3, 6)):
        ref = np.abs(np.diag(K)[blk]).max()
        assert np.abs(K[blk] - K_fd[blk]).max() <= 1e-5 * ref, (K[blk], K_fd[blk])
    assert system_stiffness(eq, hydrostatics=True) == pytest.approx(K + eq.hydrostatic)


def test_single_line_system_is_the_catenary():
    env = Environment(depth=100.0)
    lt = ex.BUOY_CHAIN
    system = MooringSystem(
        points={"a": SystemPoint(kind="fixed", position=(10.0, 20.0, -100.0)),
                "b": SystemPoint(kind="coupled", position=(10.0 + 120.0 * math.cos(0.3), 20.0 + 120.0 * math.sin(0.3),
                                                           -5.0))},
        lines={"l": SystemLine(line=Line.single(lt, 150.0), end_a="a", end_b="b")})
    eq = solve_equilibrium(system, env)
    ref = catenary(120.0, 95.0, 150.0, lt.axial_stiffness, lt.submerged_weight(1025.0, 9.81), 0.0, True)
    e = np.array([math.cos(0.3), math.sin(0.3)])
    assert eq.end_b_force[0, :2] == pytest.approx(-float(ref.H_fairlead) * e, rel=1e-12)
    assert eq.end_b_force[0, 2] == pytest.approx(-float(ref.V_fairlead), rel=1e-12)
    assert eq.end_a_tension[0] == pytest.approx(float(ref.anchor_tension), rel=1e-12)
    assert eq.grounded_length[0] == pytest.approx(float(ref.grounded_length), rel=1e-12)
    pos, T = eq.line_profile("l", 50)
    assert pos[0] == pytest.approx([10.0, 20.0, -100.0]) and pos[-1] == pytest.approx(eq.point_position[1])
    assert T[-1] == pytest.approx(float(ref.fairlead_tension), rel=1e-9)


@pytest.mark.parametrize("build", [ex.oc3_hywind, ex.oc4_semi, ex.moored_buoy])
def test_forces_balance_on_bodies_and_points(build):
    # Independent bookkeeping of every force term at the solved state: lines (from the end
    # forces), weight at R r_CG, buoyancy at R r_CB, heave -rho g A_wp z, waterplane moment
    # rho g I (a_y, -a_x, 0), the external load; and at a free point its lines + net weight.
    system, env = build()
    name = next(iter(system.bodies))
    load = np.array([3e5, -2e5, 1e4, 2e5, -1e6, 5e5]) * (0.05 if build is ex.moored_buoy else 1.0)
    eq = solve_equilibrium(system, env, external={name: load})
    b = system.bodies[name]
    q = eq.body_position[0]
    R = rotation(q[3:])
    rho, g = env.water_density, env.gravity
    W = np.array([0, 0, -b.mass * g])
    B = np.array([0, 0, rho * g * b.volume])
    a = R[:, 2]
    f = _line_load_on_body(eq, name) + load + np.asarray(b.external_force)
    f[:3] += W + B
    f[2] -= rho * g * b.waterplane_area * (q[2] - b.position[2])
    f[3:] += np.cross(R @ b.center_of_gravity, W) + np.cross(R @ b.center_of_buoyancy, B)
    f[3:] += rho * g * np.array([b.waterplane_moments[0] * a[1], -b.waterplane_moments[1] * a[0], 0.0])
    scale = max(b.mass * g, rho * g * b.volume)
    assert np.abs(f[:3]).max() <= 1e-7 * scale
    assert np.abs(f[3:]).max() <= 1e-7 * scale * 10.0
    for pname, p in system.points.items():
        if p.kind != "free":
            continue
        fp = np.asarray(p.external_force, float) + np.array([0, 0, -p.net_weight(rho, g)])
        for i, ln in enumerate(eq.line_names):
            sl = system.lines[ln]
            fp += eq.end_a_force[i] * (sl.end_a == pname) + eq.end_b_force[i] * (sl.end_b == pname)
        assert np.abs(fp).max() <= 1e-7 * scale


def test_external_load_moves_body_by_the_stiffness():
    # A small surge load on OC3 moves it by K^-1 F (first order): the load ramp of the result
    # agrees with the linear prediction to O(F^2): 1 kN gives a 2.4 cm surge, 1e-3 relative.
    system, env = ex.oc3_hywind()
    eq0 = solve_equilibrium(system, env)
    F = np.array([1e3, 0, 0, 0, 0, 0])
    eq1 = solve_equilibrium(system, env, external={"platform": F}, initial=eq0)
    d = eq1.body_position[0] - eq0.body_position[0]
    pred = np.linalg.solve(system_stiffness(eq0, hydrostatics=True), F)
    assert d[0] == pytest.approx(pred[0], rel=1e-3)
    assert d[4] == pytest.approx(pred[4], rel=1e-3)


def test_bad_inputs_are_refused_with_a_fix():
    system, env = ex.oc3_hywind()
    with pytest.raises(InputError, match="current"):
        solve_equilibrium(system, env.model_copy(update={"current": Current(speed=0.5)}))
    unstable = system.model_copy(update={"bodies": {"platform": system.bodies["platform"].model_copy(
        update={"center_of_gravity": (0.0, 0.0, 60.0)})}})
    with pytest.raises(InputError, match="pitch|roll"):
        solve_equilibrium(unstable, env)
    deep = dict(system.points)
    deep["anchor1"] = deep["anchor1"].model_copy(update={"position": (-853.87, 0.0, -330.0)})
    with pytest.raises(InputError, match="below the seabed"):
        solve_equilibrium(system.model_copy(update={"points": deep}), env)
    with pytest.raises(InputError, match="no free body"):
        solve_equilibrium(system, env, external={"platfrom": np.zeros(6)})
    # 5e7 N of surge: more than three OC3 lines can hold (they would stretch past breaking)
    with pytest.raises((ConvergenceError, InputError)) as err:
        solve_equilibrium(system, env, external={"platform": np.array([5e8, 0, 0, 0, 0, 0])}, max_iter=30)
    assert "Suggested fix" in str(err.value)

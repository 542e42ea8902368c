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
from seacable.errors import ConvergenceError, InputError, SeacableWarning
from seacable.line import Line
from seacable.statics.catenary import catenary
from seacable.system.model import MooringSystem, SystemLine, SystemPoint
from seacable.system.statics import examples as ex
from seacable.system.statics import solve_equilibrium, system_stiffness
from seacable.system.statics.model import euler, rotation
from seacable.system.statics.problem import _rotvec


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


def _tendon_buoy():
    """A buoy held down by one vertical rope straight above its anchor (the vertical-line limit)."""
    from seacable.system.model import Body

    buoy = Body(mass=10_000.0, volume=30.0, center_of_buoyancy=(0, 0, -1.0), center_of_gravity=(0, 0, -2.0),
                waterplane_area=12.0, waterplane_moments=(11.0, 11.0))
    system = MooringSystem(points={"a": SystemPoint(kind="fixed", position=(0.0, 0.0, -100.0)),
                                   "f": SystemPoint(kind="body", body="b", position=(0.0, 0.0, -2.0))},
                           bodies={"b": buoy}, lines={"l": SystemLine(line=Line.single(ex.BUOY_ROPE, 97.0),
                                                                      end_a="a", end_b="f")})
    return system, Environment(depth=100.0)


def _tabled_oc3():
    """OC3-Hywind on lines with a bilinear strain-tension table (slope 0.3 EA up to strain 0.007, then EA:
    kinked at 807 kN, inside the tension range of one line under the test loads, above and below the
    others) and friction 0.5 on the seabed."""
    system, env = ex.oc3_hywind()
    ea = ex.OC3_CHAIN.axial_stiffness
    t1 = 0.007 * 0.3 * ea
    lt = ex.OC3_CHAIN.model_copy(update={"tension_strain": ((0.0, 0.0), (0.007, t1), (0.1, t1 + 0.093 * ea))})
    lines = {k: v.model_copy(update={"line": Line.single(lt, v.line.length)}) for k, v in system.lines.items()}
    env = env.model_copy(update={"seabed": env.seabed.model_copy(update={"friction": 0.5})})
    return MooringSystem(points=system.points, bodies=system.bodies, lines=lines), env


@pytest.mark.parametrize("build", [ex.oc4_semi, ex.moored_buoy, _tendon_buoy, _tabled_oc3])
def test_stiffness_equals_central_differences_of_equilibrium(build):
    system, env = build()
    body = next(iter(system.bodies))
    # the tendon buoy is solved without a load: its line stays exactly vertical (the limit
    # H/h -> dH/dx of the transverse stiffness)
    load = {ex.oc4_semi: 100.0, ex.moored_buoy: 1.0, _tendon_buoy: 0.0, _tabled_oc3: 50.0}[build]
    eq = solve_equilibrium(system, env, external={body: np.array([1e4, 5e3, 0, 0, 0, 2e3]) * load}, tol=1e-11)
    q = eq.body_position[0]
    K_fd = np.zeros((6, 6))
    # steps: 1 mm and 1e-5 rad; truncation error ~ (h/L)^2 and the 1e-12 solves keep round-off
    # (1e-11 of the force scale, catenary spans to 1e-12) below 1e-7 of the force changes (K h ~ 1e2..1e5 N)
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
            e2 = solve_equilibrium(_held(system, body, qp), env, tol=1e-11)
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
    with pytest.raises(InputError, match="slope"):
        solve_equilibrium(system, env.model_copy(update={"seabed": env.seabed.model_copy(update={"slope": 0.05})}))
    soft = ex.OC3_CHAIN.model_copy(update={"axial_stiffness": None})
    lines = {k: v.model_copy(update={"line": Line.single(soft, 902.2)}) for k, v in system.lines.items()}
    with pytest.raises(InputError, match="axial_stiffness"):
        solve_equilibrium(system.model_copy(update={"lines": lines}), env)
    with pytest.raises(InputError, match="no free body"):
        solve_equilibrium(system, env, external={"platfrom": np.zeros(6)})
    # 5e7 N of surge: more than three OC3 lines can hold (they would stretch past breaking)
    with pytest.raises((ConvergenceError, InputError)) as err:
        solve_equilibrium(system, env, external={"platform": np.array([5e8, 0, 0, 0, 0, 0])}, max_iter=30)
    assert "Suggested fix" in str(err.value)


def test_free_point_lands_on_the_seabed_and_slides_until_held():
    # A 20 t clump (free point) between 50 m of chain to the anchor and 150 m to a held point:
    # it cannot hang, rests on the seabed (z = -depth exactly) and slides (no friction) until the
    # anchor chain, flat on the seabed, carries the pull: x_c = 50 (1 + H / EA), H the horizontal
    # pull of the upper chain at the clump (closed form of a stretched bar; 1e-9).
    env = Environment(depth=100.0)
    chain = ex.BUOY_CHAIN
    system = MooringSystem(
        points={"a": SystemPoint(kind="fixed", position=(0.0, 0.0, -100.0)),
                "c": SystemPoint(kind="free", position=(40.0, 0.0, -80.0), mass=20000.0),
                "b": SystemPoint(kind="coupled", position=(150.0, 0.0, -10.0))},
        lines={"l1": SystemLine(line=Line.single(chain, 50.0), end_a="a", end_b="c"),
               "l2": SystemLine(line=Line.single(chain, 150.0), end_a="c", end_b="b")})
    eq = solve_equilibrium(system, env)
    xc = eq.point_position[1]
    assert xc[2] == -100.0
    H = eq.end_a_force[1, 0]
    assert H > 0
    assert xc[0] == pytest.approx(50.0 * (1.0 + H / chain.axial_stiffness), rel=1e-9)
    assert eq.end_b_force[0, 0] == pytest.approx(-H, rel=1e-9)     # horizontal balance at the clump
    ref = catenary(150.0 - xc[0], 90.0, 150.0, chain.axial_stiffness, chain.submerged_weight(1025.0, 9.81))
    assert eq.end_b_tension[1] == pytest.approx(float(ref.fairlead_tension), rel=1e-9)


def test_a_line_pulled_nearly_straight_warns():
    env = Environment(depth=100.0)
    system = MooringSystem(
        points={"a": SystemPoint(kind="fixed", position=(0.0, 0.0, -100.0)),
                "b": SystemPoint(kind="coupled", position=(150.0, 0.0, -5.0))},
        lines={"l": SystemLine(line=Line.single(ex.BUOY_CHAIN, 100.0), end_a="a", end_b="b")})
    with pytest.warns(SeacableWarning, match="stretched by 77.6 %"):
        solve_equilibrium(system, env)


def _own_load(body, env, q):
    """Weight, buoyancy, heave and waterplane loads of a body at q (the model's equations)."""
    R = rotation(q[3:])
    rho, g = env.water_density, env.gravity
    W = np.array([0, 0, -body.mass * g])
    B = np.array([0, 0, rho * g * body.volume])
    a = R[:, 2]
    f = np.zeros(6)
    f[:3] = W + B
    f[2] -= rho * g * body.waterplane_area * (q[2] - body.position[2])
    f[3:] = np.cross(R @ body.center_of_gravity, W) + np.cross(R @ body.center_of_buoyancy, B)
    f[3:] += rho * g * np.array([body.waterplane_moments[0] * a[1], -body.waterplane_moments[1] * a[0], 0.0])
    return f


@pytest.mark.parametrize("build", [ex.oc3_hywind, ex.oc4_semi])
def test_hydrostatic_matrix_equals_central_differences(build):
    # At an offset and rotated position (under a load) the analytic hydrostatic matrix (weight and
    # buoyancy arms rotating, heave, waterplane) equals central differences of those loads over
    # small global rotations; the loads are closed forms, so 1e-7 (steps 1e-4 m, 1e-6 rad).
    system, env = build()
    name = next(iter(system.bodies))
    eq = solve_equilibrium(system, env, external={name: np.array([5e5, 2e5, 0, 1e6, 3e6, 1e6])})
    q = eq.body_position[0]
    body = system.bodies[name]
    K = np.zeros((6, 6))
    for j in range(6):
        h = 1e-4 if j < 3 else 1e-6
        f = []
        for sgn in (1, -1):
            qp = q.copy()
            if j < 3:
                qp[j] += sgn * h
            else:
                th = np.zeros(3)
                th[j - 3] = sgn * h
                qp[3:] = euler(_rotvec(th) @ rotation(q[3:]))
            f.append(_own_load(body, env, qp))
        K[:, j] = -(f[0] - f[1]) / (2 * h)
    H = eq.hydrostatic
    assert np.abs(H - K).max() <= 1e-7 * np.abs(np.diag(H)).max()
    assert eq.body_stiffness(name, hydrostatics=True) == pytest.approx(eq.stiffness + H)


def test_friction_in_a_moored_system_is_the_catenarys():
    # OC3 on a seabed with friction 0.6 under a surge load: every line's end forces equal the
    # single-line catenary (with friction) at the solved end positions, 1e-9; friction lowers
    # the anchor tension of the loaded lines below the touchdown tension.
    system, env = ex.oc3_hywind()
    env = env.model_copy(update={"seabed": env.seabed.model_copy(update={"friction": 0.6})})
    eq = solve_equilibrium(system, env, external={"platform": np.array([1e6, 0, 0, 0, 0, 0])})
    w = ex.OC3_CHAIN.submerged_weight(env.water_density, env.gravity)
    for i, name in enumerate(eq.line_names):
        sl = system.lines[name]
        pa = eq.point_position[eq.point_names.index(sl.end_a)]
        pb = eq.point_position[eq.point_names.index(sl.end_b)]
        ref = catenary(np.hypot(*(pb - pa)[:2]), pb[2] - pa[2], 902.2, ex.OC3_CHAIN.axial_stiffness, w, 0.6, True)
        assert eq.end_b_tension[i] == pytest.approx(float(ref.fairlead_tension), rel=1e-9)
        assert eq.end_a_tension[i] == pytest.approx(float(ref.anchor_tension), rel=1e-9)
        assert eq.grounded_length[i] == pytest.approx(float(ref.grounded_length), rel=1e-9)
        if ref.grounded_length > 0:
            assert eq.end_a_tension[i] < float(ref.H_fairlead)


def test_line_profile_through_clumps_and_segments():
    # The buoy's line 1: the profile starts at the anchor, ends at the fairlead, passes through
    # the clump and the float nodes, and its tension at the fairlead is the end tension.
    system, env = ex.moored_buoy()
    eq = solve_equilibrium(system, env)
    pos, T = eq.line_profile("line1", 191)       # 1 m spacing over 190 m
    assert pos[0] == pytest.approx(eq.point_position[eq.point_names.index("anchor1")], abs=1e-9)
    assert pos[-1] == pytest.approx(eq.point_position[eq.point_names.index("fairlead1")], abs=1e-9)
    assert T[-1] == pytest.approx(eq.end_b_tension[0], rel=1e-9)
    assert T[0] == pytest.approx(eq.end_a_tension[0], rel=1e-9)
    nodes = eq._node_position[eq._asm.sub_b[eq._asm.line_first[0]:eq._asm.line_last[0]]]
    for s, p in zip((95, 110, 150), nodes):                  # the clump, the chain-rope joint, the float
        assert pos[s] == pytest.approx(p, abs=1e-6)
    assert np.all(np.diff(np.linalg.norm(np.diff(pos, axis=0), axis=1)) < 0.2)   # no jumps


def test_a_line_sagging_into_the_seabed_lands_there(monkeypatch):
    """Two held points 10 m above a 100 m deep seabed, 200 m apart, joined by 300 m of chain: one free
    catenary between them would sag ~90 m, through the seabed. The statics split the line at its lowest
    point, which lands: by symmetry each half is the touchdown catenary from the seabed to a point 10 m up
    and 100 m across, 150 m long (seacable's single-line catenary; 1e-7: the Newton tolerance is 1e-8 of
    the force scale). Without the split (no rounds) the statics warn that the line passes the seabed."""
    from seacable.system.statics import solve as statics

    env = Environment(depth=100.0)
    system = MooringSystem(
        points={"a": SystemPoint(kind="coupled", position=(0.0, 0.0, -90.0)),
                "b": SystemPoint(kind="coupled", position=(200.0, 0.0, -90.0))},
        lines={"l": SystemLine(line=Line.single(ex.BUOY_CHAIN, 300.0), end_a="a", end_b="b")})
    eq = solve_equilibrium(system, env)          # no warning: it lies on the seabed
    w = ex.BUOY_CHAIN.submerged_weight(env.water_density, env.gravity)
    half = catenary(100.0, 10.0, 150.0, ex.BUOY_CHAIN.axial_stiffness, w, 0.0, True)
    assert eq.end_a_tension[0] == pytest.approx(half.fairlead_tension, rel=1e-7)
    assert eq.end_b_tension[0] == pytest.approx(half.fairlead_tension, rel=1e-7)
    assert eq.grounded_length[0] == pytest.approx(2 * half.grounded_length, rel=1e-6)
    monkeypatch.setattr(statics, "_SAG_ROUNDS", 0)
    with pytest.warns(SeacableWarning, match="below the seabed"):
        solve_equilibrium(system, env)
    deep = Environment(depth=300.0)
    solve_equilibrium(system, deep)          # the same line in deeper water: no warning


def _landed_clump():
    env = Environment(depth=100.0, seabed={"friction": 0.5})
    chain = ex.BUOY_CHAIN
    system = MooringSystem(
        points={"a": SystemPoint(kind="fixed", position=(0.0, 0.0, -100.0)),
                "c": SystemPoint(kind="free", position=(45.0, 0.0, -100.0), mass=20000.0),
                "b": SystemPoint(kind="coupled", position=(150.0, 0.0, -10.0))},
        lines={"l1": SystemLine(line=Line.single(chain, 50.0), end_a="a", end_b="c"),
               "l2": SystemLine(line=Line.single(chain, 150.0), end_a="c", end_b="b")})
    return system, env


def _buoy_with_friction():
    system, env = ex.moored_buoy()
    return system, env.model_copy(update={"seabed": env.seabed.model_copy(update={"friction": 0.5})})


@pytest.mark.parametrize("build", [_landed_clump, _buoy_with_friction, ex.oc4_semi, _tabled_oc3])
def test_newton_jacobian_equals_central_differences_with_friction(build):
    # The full Jacobian of the Newton iteration (bodies and free points, before condensation),
    # including the anchor-end terms of grounded sub-lines with Coulomb friction
    # (dH_A = dH_F + mu dV_F) at a free point resting on the seabed, against central
    # differences of the residual (steps 1e-5 m / 1e-7 rad, catenaries to round-off): 1e-6.
    from seacable.system.statics.problem import _Problem

    system, env = build()
    ext = {b: np.array([2e4, 1e4, 0, 0, 0, 1e3]) for b in system.bodies}
    prob = _Problem(system, env, ext, 1e-8, 50)
    st = prob.initial_state(None)
    st, ev, _ = prob.newton(st, 0.5)            # somewhere on the way, not at equilibrium
    n = ev.residual.size
    J = np.zeros((n, n))
    for i in range(n):
        h = 1e-7 if (i < 6 * prob.nb and i % 6 >= 3) else 1e-5
        dq = np.zeros(n)
        dq[i] = h
        rp = prob.eval(prob.step(st, dq, 1.0), 1.0).residual
        rm = prob.eval(prob.step(st, -dq, 1.0), 1.0).residual
        J[:, i] = (rp - rm) / (2 * h)
    ev = prob.eval(st, 1.0)
    free = np.setdiff1d(np.arange(n), prob._z_dof(st))     # a point resting on the seabed has its z held
    D = (J - ev.jac)[np.ix_(free, free)]
    assert np.abs(D).max() <= 1e-6 * np.abs(ev.jac).max()


def _pinned_lever(pinned=True):
    """A body pinned at (0, 0, -20) with its centre of gravity 3 m along body x and a vertical rope from
    body point (8, 0, 0) up to a fixed point 10 m above it (9.99 m long: taut from the start); no volume."""
    from seacable.system.model import Body

    body = Body(mass=2000.0, center_of_gravity=(3.0, 0.0, 0.0), position=(0.0, 0.0, -20.0, 0.0, 0.0, 0.0),
                pinned=pinned)
    system = MooringSystem(points={"top": SystemPoint(kind="fixed", position=(8.0, 0.0, -10.0)),
                                   "p": SystemPoint(kind="body", body="b", position=(8.0, 0.0, 0.0))},
                           bodies={"b": body}, lines={"l": SystemLine(line=Line.single(ex.BUOY_ROPE, 9.99),
                                                                      end_a="p", end_b="top")})
    return system, Environment(depth=100.0)


def test_a_pinned_body_balances_its_moment_about_the_pin():
    """A pinned body keeps its reference point and turns until the moments about the pin balance: a
    vertical rope at arm a = 8 m holds a weight W at arm c = 3 m with T = W c / a, the pin takes W - T.
    (Exact for a vertical rope; the rope tilts by ~stretch / a ~ 1e-4 rad, a 1e-8 relative effect; the
    Newton tolerance is 1e-8 of the force scale: 1e-6 relative.)"""
    system, env = _pinned_lever()
    eq = solve_equilibrium(system, env)
    W = 2000.0 * env.gravity
    assert eq.end_a_tension[0] == pytest.approx(W * 3.0 / 8.0, rel=1e-6)
    assert np.array_equal(eq.body_position[0][:3], [0.0, 0.0, -20.0])     # the pin holds the point
    assert eq.pin_reaction[0] == pytest.approx([0.0, 0.0, W - W * 3.0 / 8.0], abs=1e-6 * W)
    assert abs(eq.body_position[0][4]) > 1e-6           # it turned (pitch) to stretch the rope


def test_a_hanging_rod_is_held_in_spin_and_hangs_as_the_catenary_says():
    """MoorDyn's RodHanging: a 20 m rod hangs level from two identical 450 m ropes to fixed points at
    x = -450 and 450 m. Its spin about its own axis is indeterminate (every load on the axis): held and
    reported, not refused. By symmetry each rope carries half the rod's wet weight at its lower end: with the
    rod level at the depth found, seacable's single-line catenary over the same spans (440 m across) gives a
    lower-end vertical force of W_rod / 2 (1e-6: the Newton tolerance is 1e-8 of the ~1e6 N force scale,
    relative to the 7e3 N half weight)."""
    from pathlib import Path

    from seacable.io.moordyn import moordyn_system, read_moordyn

    deck = Path(__file__).parent / "data" / "moordyn_decks" / "MoorDyn" / "tests" / "Mooring" / "RodHanging.txt"
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        md = read_moordyn(deck)
        system, env = moordyn_system(md)
    eq = solve_equilibrium(system, env)
    assert len(eq.indeterminate) == 1 and "rod1" in eq.indeterminate[0]
    rod = system.bodies["rod1"]
    w_rod = (rod.mass - env.water_density * rod.volume) * env.gravity
    z = eq.body_position[0][2]
    assert eq.body_position[0][4] == pytest.approx(np.pi / 2, abs=1e-9)      # level
    lt = md.line_types["rope"]
    w = (lt.mass_per_length - env.water_density * np.pi * lt.diameter**2 / 4) * env.gravity
    cat = catenary(440.0, -z, 450.0, lt.axial_stiffness, w, 0.0, False)
    assert cat.V_anchor == pytest.approx(w_rod / 2, rel=1e-6)
    assert eq.end_b_tension[0] == pytest.approx(np.hypot(cat.H_anchor, cat.V_anchor), rel=1e-6)


def test_a_line_above_the_water_weighs_its_dry_weight():
    """A 20 m rope hangs plumb from a point 5 m above the water to a 1000 kg weight: the 5 m above the
    surface weigh m g per metre, the 15 m below (m - rho A) g; the top carries the weight plus both. EA is
    1e10 N: the stretch (~1e-6) moves the surface along the rope by ~1e-5 m, 1e-8 of the tension: 1e-7 relative. The surface node
    sits at z = 0. A rope wholly in air between two points 10 m up is the dry catenary (1e-7)."""
    from seacable.line import LineType

    rope = LineType(name="stiff", diameter=0.08, mass_per_length=6.0, axial_stiffness=1e10)
    env = Environment(depth=100.0)
    system = MooringSystem(
        points={"top": SystemPoint(kind="fixed", position=(0.0, 0.0, 5.0)),
                "w": SystemPoint(kind="free", position=(0.0, 0.0, -15.0), mass=1000.0)},
        lines={"l": SystemLine(line=Line.single(rope, 20.0), end_a="w", end_b="top")})
    eq = solve_equilibrium(system, env)
    g = env.gravity
    dry, wet = rope.mass_per_length * g, rope.submerged_weight(env.water_density, g)
    assert eq.end_b_tension[0] == pytest.approx(1000.0 * g + 5.0 * dry + 15.0 * wet, rel=1e-7)
    assert eq.end_a_tension[0] == pytest.approx(1000.0 * g, rel=1e-7)
    nodes = eq._node_position[eq._asm.node_kind == 2]
    assert np.abs(nodes[:, 2]).min() < 1e-6          # a node on the surface
    # wholly in air: the single-line catenary with the dry weight
    air = MooringSystem(points={"a": SystemPoint(kind="fixed", position=(0.0, 0.0, 10.0)),
                                "b": SystemPoint(kind="fixed", position=(30.0, 0.0, 10.0))},
                        lines={"l": SystemLine(line=Line.single(rope, 32.0), end_a="a", end_b="b")})
    eq = solve_equilibrium(air, env)
    cat = catenary(30.0, 0.0, 32.0, 1e10, dry, 0.0, False)
    assert eq.end_a_tension[0] == pytest.approx(cat.fairlead_tension, rel=1e-7)

"""A power cable as a line of a mooring system (issue 40): sections and held ends on system lines.

References and closed forms:

- the single-line finite-element analysis (``mooring_static``, :func:`seacable.mooring.run.case_model`): the same
  line from a fixed point to a point of a body held still solves the same discrete equations (the same nodes, the
  same section resolution, the same hinges), so shape, tensions and curvature agree to the solvers' tolerance;
- a rigid rotation: a clamp on a body turned by ``R = Ry(pitch)`` holds the line at ``R e_b`` (``e_b`` its
  direction in the body's axes), the single line's clamp at that direction;
- the balance of a free body and its lines: at a static equilibrium the external loads on body and lines together
  (the body's weight and buoyancy, the lines' weight in water, the anchors' reactions) have zero resultant force
  and moment, whatever the clamp passes between line and body inside; leaving the clamp's moment off the body
  breaks it by that moment;
- Newton's method converges quadratically when its matrix is the residual's Jacobian: the coupled iteration with a
  clamp on a free body (its direction turning with the body, its moment on the body) reduces the residual as fast
  as with the end pinned.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import seacable as sc
from seacable.errors import InputError
from seacable.io import parse_case
from seacable.mooring.bending import bending_state
from seacable.mooring.ends import end_direction
from seacable.mooring.motion import rotation_matrix
from seacable.mooring.run import case_model
from seacable.mooring.solver import static_equilibrium
from seacable.results import body_pose
from seacable.system.bending import held_directions, pose_rotations
from seacable.system.case import SystemCase
from seacable.system.statics.fe import fe_equilibrium

CABLE = {"diameter": 0.16, "mass_per_length": 36.70, "axial_stiffness": 4.69e8, "bending_stiffness": 1.99e4,
         "drag_normal": 1.2, "drag_tangential": 0.1, "added_mass_normal": 1.0}
# examples/lazy_wave_80m.yaml's smeared buoyancy (Lozon et al. 2025, CableDyn's lozon_gomex80 deck)
SECTIONS = [{"type": "buoyancy", "start": 52.101, "length": 50.0, "pitch": 5.0, "representation": "smeared",
             "module": {"length": 5.0, "diameter": 0.29, "mass": 114.15, "volume": 0.2297289628,
                        "drag_normal": 1.2}}]
ENV = {"water_density": 1025.0, "gravity": 9.80665, "depth": 80.0}
HULL = np.array([120.0, 0.0, -4.0])
ARM = np.array([0.0, 0.0, -10.0])  # the hang-off, 10 m below the hull's reference point
CLAMP = {"type": "clamped", "declination": 0.1745}  # the example's hang-off, 10 deg off vertical
N = 60


def _single(cond, fairlead):
    return parse_case({"name": "lw", "line_types": {"cable": CABLE},
                         "line": {"segments": [{"line_type": "cable", "length": 170.215}], "sections": SECTIONS},
                         "environment": ENV,
                         "analysis": {"type": "mooring_static", "anchor": [0.0, -80.0], "fairlead": list(fairlead),
                                      "n_elements": N, "fairlead_end_condition": cond}})


def _system(cond, pitch=0.0, kind="fixed"):
    return SystemCase.parse({
        "name": "lws", "line_types": {"cable": CABLE}, "environment": ENV,
        "bodies": {"hull": {"kind": kind, "position": [*HULL, 0.0, pitch, 0.0]}},
        "points": {"anchor": {"kind": "fixed", "position": [0.0, 0.0, -80.0]},
                   "hang": {"kind": "body", "body": "hull", "position": list(ARM)}},
        "lines": {"cable": {"segments": [{"line_type": "cable", "length": 170.215}], "sections": SECTIONS,
                            "end_a": "anchor", "end_b": "hang", "n_elements": N, "end_b_condition": cond}},
        "analysis": {"type": "system_static"}})


def _single_solution(cond, fairlead):
    model = case_model(_single(cond, fairlead))
    st = static_equilibrium(model, tol=1e-10)
    return st.position, st.tension, bending_state(model.network, st.position)[0]


@pytest.mark.parametrize("pitch", [0.0, 0.1])
def test_system_cable_is_the_single_line_with_its_clamp_turned_by_the_body(pitch):
    case = _system(CLAMP, pitch)
    eq = fe_equilibrium(case.system(), case.environment, stiffness=False, tol=1e-10)
    s, X, T = eq.line_nodes("cable")
    nodes = eq.fe.line_nodes[0]
    curvature = bending_state(eq.fe.model.network, eq.state.position)[0][nodes]
    # the closed-form rotation: the body's Ry(pitch) turns the hang-off point and the clamp's direction
    R = rotation_matrix(0.0, pitch, 0.0)
    d = R @ end_direction(CLAMP["declination"], 0.0)
    fair = HULL + R @ ARM
    cond = {"type": "clamped", "declination": math.acos(d[2]), "azimuth": math.atan2(d[1], d[0])}
    X1, T1, k1 = _single_solution(cond, (fair[0], fair[2]))
    # both solved to a force residual of 1e-10 of the line's scale (kN): positions to 1e-7 m, curvature to 1e-9
    # 1/m, tensions to 1e-3 N measured; the bounds leave a factor 10 (a 1e-3 rad error of the direction moves the
    # hang-off's curvature by 1e-3 / l = 7e-4 1/m and the sag bend by centimetres)
    assert np.abs(X - X1).max() < 1e-6
    assert np.abs(curvature - k1).max() < 1e-8
    assert np.abs(T - T1).max() < 1e-2
    # the hang-off force includes the clamp's shear, as the single line's end force does
    single = sc.run(_single(cond, (fair[0], fair[2])))
    assert float(eq.end_b_tension[0]) == pytest.approx(float(single.fairlead_tension), abs=1e-2)
    # and the clamp is felt: the hang-off's curvature is that of a clamp, not a pin's zero
    assert curvature[-1] > 1e-3


def test_system_static_reports_why_it_took_the_finite_element_statics_and_the_bending_outputs():
    ds = sc.run(_system(CLAMP))
    assert ds.attrs["statics"] == "finite_element"
    assert "line 'cable' with sections" in ds.attrs["statics_reason"]
    assert "end_b held in bending (clamped)" in ds.attrs["statics_reason"]
    _, _, k1 = _single_solution(CLAMP, (120.0, -14.0))
    got = ds.curvature.sel(condition="intact", line="cable").values
    assert got[np.isfinite(got)] == pytest.approx(k1, abs=1e-8)  # as above: the nodes' curvature, all of them
    assert ds.fe_s.sel(line="cable").values[-1] == pytest.approx(170.215, rel=1e-12)
    for name in ("bend_moment", "shear_force", "declination"):
        assert name in ds


# ------------------------------------------------------------------------------------------------ a free body

CHAIN = {"diameter": 0.1, "mass_per_length": 60.0, "axial_stiffness": 5e8}


def _buoy(cond, ei=1.99e4):
    """A subsea buoy (40 m^3, 20 t, its centre of buoyancy 2 m above its centre of gravity) held down by two chains
    and a cable hung off it at end B, in 300 m of water (no seabed contact)."""
    return SystemCase.parse({
        "name": "buoy", "line_types": {"cable": {**CABLE, "bending_stiffness": ei}, "chain": CHAIN},
        "environment": {"water_density": 1025.0, "gravity": 9.80665, "depth": 300.0},
        "bodies": {"buoy": {"kind": "free", "position": [0.0, 0.0, -40.0, 0.0, 0.0, 0.0], "mass": 2.0e4,
                            "center_of_gravity": [0.0, 0.0, -1.0], "inertia": [1e5, 1e5, 1e5], "volume": 40.0,
                            "center_of_buoyancy": [0.0, 0.0, 1.0]}},
        "points": {"a1": {"kind": "fixed", "position": [-80.0, 0.0, -120.0]},
                   "a2": {"kind": "fixed", "position": [30.0, 0.0, -120.0]},
                   "a3": {"kind": "fixed", "position": [0.0, 30.0, -120.0]},
                   "hang": {"kind": "body", "body": "buoy", "position": [-2.0, 0.0, -2.0]},
                   "t1": {"kind": "body", "body": "buoy", "position": [2.0, 0.0, -2.0]},
                   "t2": {"kind": "body", "body": "buoy", "position": [0.0, 2.0, -2.0]}},
        "lines": {"cable": {"line_type": "cable", "length": 130.0, "end_a": "a1", "end_b": "hang", "n_elements": 40,
                            "end_b_condition": cond},
                  "tether": {"line_type": "chain", "length": 90.0, "end_a": "a2", "end_b": "t1", "n_elements": 10},
                  "tether2": {"line_type": "chain", "length": 90.0, "end_a": "a3", "end_b": "t2", "n_elements": 10}},
        "analysis": {"type": "system_static"}})


def _balance(eq):
    """Resultant force [N] and moment about the origin [N m] of the external loads on the buoy and its lines."""
    fe = eq.fe
    net = fe.model.network
    X, q = eq.state.position, eq.state.body_position[0]
    F = fe.model.evaluate(X, np.zeros_like(X), np.zeros_like(X), 0.0, waves=False)[0]
    g, rho = 9.80665, 1025.0
    R = rotation_matrix(*q[3:])
    loads = [(X[i], np.array([0.0, 0.0, -w])) for i, w in enumerate(net.node_weight())]     # lines in water
    loads += [(X[fe.point_node[p]], -F[fe.point_node[p]]) for p in ("a1", "a2", "a3")]    # the anchors' reactions
    loads += [(q[:3] + R @ [0.0, 0.0, -1.0], np.array([0.0, 0.0, -2.0e4 * g])),           # the buoy's weight
              (q[:3] + R @ [0.0, 0.0, 1.0], np.array([0.0, 0.0, rho * g * 40.0]))]       # and buoyancy
    return sum(f for _, f in loads), sum(np.cross(x, f) for x, f in loads)


@pytest.mark.parametrize("cond", [CLAMP, {"type": "spring", "declination": 0.3, "stiffness": 3e4}])
def test_a_held_end_on_a_free_body_balances_its_moment_on_the_body(cond):
    case = _buoy(cond)
    eq = fe_equilibrium(case.system(), case.environment, stiffness=False, tol=1e-10)
    force, moment = _balance(eq)
    from seacable.system.dynamics.clamps import clamp_moments

    clamp = clamp_moments(eq.fe, eq.state.position, eq.state.body_position)[0]
    # the resultant is the equilibrium's residual, 1e-10 of the loads (2e5 N over arms of 100 m: 1e-3 N m); the
    # clamp's moment on the body (560 N m) is over 1e4 times the bound, so leaving it off the body fails by far
    assert np.abs(force).max() < 1e-4
    assert np.abs(moment).max() < 1e-2
    assert np.linalg.norm(clamp) > 1e2


def test_a_free_body_turns_its_clamp_as_a_body_held_at_its_pose():
    """The free buoy's equilibrium pose, given to the same buoy held fixed there: the held body's clamp is turned by
    the pose once (as the single line's test above pins down), the free body's by the coupled iteration at each
    pose; the lines' shapes agree to the solvers' tolerance, so the free body turns its clamp the same way (a
    rotation the wrong way round, or by the transpose, moves the hang-off's curvature by 1e-2 1/m)."""
    case = _buoy(CLAMP)
    eq = fe_equilibrium(case.system(), case.environment, stiffness=False, tol=1e-10)
    pose = eq.state.body_position[0]
    data = case.model_dump(exclude_none=True)
    data["bodies"]["buoy"] = {**data["bodies"]["buoy"], "kind": "fixed", "position": [float(v) for v in pose]}
    held = SystemCase.parse(data)
    eq2 = fe_equilibrium(held.system(), held.environment, stiffness=False, tol=1e-10)
    nodes = eq.fe.line_nodes[0]
    # the free body's clamp at its pose (the outputs' directions, :func:`seacable.system.bending.held_directions`)
    turned = held_directions(eq.fe, {"buoy": pose_rotations(pose)})
    k_free = bending_state(eq.fe.model.network, eq.state.position, turned)[0][nodes]
    k_held = bending_state(eq2.fe.model.network, eq2.state.position)[0][eq2.fe.line_nodes[0]]
    assert np.abs(eq.state.position[nodes] - eq2.state.position[eq2.fe.line_nodes[0]]).max() < 1e-6
    assert np.abs(k_free - k_held).max() < 1e-7
    assert k_held[-1] > 1e-3  # the hang-off bends: a clamp, not a pin


def test_newton_converges_quadratically_with_a_clamp_on_a_free_body():
    """One Newmark step of the coupled iteration from a state off its solution (:func:`_newton_residuals`): with a
    clamp (stiff, EI 1e6 N m^2) the residual falls as with the end pinned: from 3e4 N to the round-off floor, 3e-4 N, in three
    iterations (quadratic: each about the square of the last, relative); without the clamp's slopes on the body's
    rotation in the Newton matrix the static equilibrium of this system does not even converge."""
    pinned = _newton_residuals(_buoy({"type": "pinned"}, ei=1e6))
    clamped = _newton_residuals(_buoy({"type": "clamped", "declination": 0.3}, ei=1e6))
    for res in (pinned, clamped):
        assert res[0] > 1e4
        assert res[1] < 1e-3 * res[0] and res[2] < 1e-3 * res[1]
        assert res[3] < 1e-8 * res[0]  # the round-off floor: 1e-10 of the chains' 1e6 N


def _newton_residuals(case, n=4, dt=0.1):
    """Residuals [N] of ``n`` Newton iterations of a Newmark step (average acceleration) of ``case``'s system from
    its static equilibrium, the body's trial pose moved by (1e-4 m, 1e-4 m, 1e-4 m, 2e-5, -3e-5, 4e-5 rad)."""
    from seacable.mooring.kernel import n_water
    from seacable.seastate import GRID_HEADER
    from seacable.system.dynamics import frames as DF
    from seacable.system.dynamics import kernel as DK

    eq = fe_equilibrium(case.system(), case.environment, stiffness=False, tol=1e-10)
    fe, m = eq.fe, eq.fe.model
    X = eq.state.position.copy()
    q = eq.state.body_position.reshape(-1, 6).copy()
    Xn, qn = X.copy(), q.copy()
    q += np.array([0.1, 0.1, 0.1, 0.02, -0.03, 0.04]) * 1e-3
    nb, nn, nd = len(q), X.shape[0], 3 * m.nfree
    frame = np.zeros((nb, DF.F_SIZE))
    active = np.ones(len(fe.con_node), np.int64)
    DK.place_tied(X, q, fe.con_node, fe.con_body, fe.con_arm, fe.con_target, active, frame)
    c0, c1 = 4.0 / dt**2, 2.0 / dt
    F, M, tension = np.zeros((nn, 3)), np.zeros((nn, 3, 3)), np.zeros(m.network.n_elements)
    band, du, dq, out = np.zeros((nd, 2 * m.bw + 1)), np.zeros(nd), np.zeros(6 * nb), np.zeros(2)
    Yt = np.zeros((12 * len(fe.con_node) + 6 * fe.clamps.shape[0], nd))
    sea = np.zeros(GRID_HEADER)
    water = np.zeros((n_water(X, m.env, m.cur_depth, np.bool_(False), sea), 7))
    res = []
    for _ in range(n):
        A, qdd = c0 * (X - Xn), c0 * (q - qn)       # Newmark from rest: a = 4 (x - x_n) / dt^2, v = 2 (x - x_n) / dt
        V, qd = c1 * (X - Xn), c1 * (q - qn)
        DK.iterate(X, V, A, q, qd, qdd, 0.0, c0, c0, c1, np.bool_(True), np.bool_(False), np.bool_(True),
                   fe.kernel_args(), m.weight, m.fidx, m.nfree, m.bw, m.env, m.cur_depth, m.cur_speed, np.bool_(False),
                   sea, fe.node_fext, fe.con_node, fe.con_body, fe.con_arm, fe.con_target, active, *fe.body_args(), 1e-12,
                   F, M, tension, band, du, dq, out, Yt, np.zeros(nn, np.bool_), frame, np.zeros((nb, 3)),
                   np.zeros((nb, 6)), np.zeros((nb, 6, 6)), water, np.bool_(True), np.zeros((0, 3)), 0.0)
        res.append(out[0])
        DK._apply(X, q, du, dq, m.fidx, 1.0)
        DK.place_tied(X, q, fe.con_node, fe.con_body, fe.con_arm, fe.con_target, active, frame)
    return np.array(res)


def test_system_dynamic_starts_and_stays_at_the_clamped_equilibrium():
    """Left alone, the coupled run stays at the static equilibrium it starts from (the statics' and the dynamics'
    clamp are one), and its result carries the bending outputs along each line."""
    case = _buoy(CLAMP)
    data = case.model_dump(exclude_none=True)
    data["analysis"] = {"type": "system_dynamic", "duration": 1.0, "time_step": 0.1, "output_interval": 0.5}
    ds = sc.run(SystemCase.parse(data))
    pose = body_pose(ds.sel(body="buoy"))
    # the start's residual (1e-9 of the loads) moves the 20 t buoy by far less than a micrometre in a second
    assert np.abs(pose - pose[0]).max() < 1e-6
    k = ds.curvature.sel(line="cable").values
    assert np.nanmax(np.abs(k - k[0])) < 1e-7 and np.nanmax(k[0]) > 1e-3


# ------------------------------------------------------------------------------------------------ bad input

@pytest.mark.parametrize("change, message", [
    ({"ei": 0.0}, "end_b_condition is clamped, but the line's end segment there has no bending stiffness"),
    ({"free_point": True}, "is a free point, which has no rotation of its own"),
    ({"catenary": True}, "analysis.statics: catenary, but the system has line 'cable' with sections"),
])
def test_bad_cable_input_is_refused_with_a_fix(change, message):
    data = _system(CLAMP).model_dump(exclude_none=True) if "ei" not in change else None
    if "ei" in change:
        with pytest.raises((InputError, ValueError)) as err:
            SystemCase.parse({**_system(CLAMP).model_dump(exclude_none=True),
                              "line_types": {"cable": {**CABLE, "bending_stiffness": 0.0}},
                              "lines": {"cable": {"segments": [{"line_type": "cable", "length": 170.215}],
                                                  "end_a": "anchor", "end_b": "hang", "end_b_condition": CLAMP}}})
    else:
        if "free_point" in change:
            data["points"]["hang"] = {"kind": "free", "position": [120.0, 0.0, -14.0], "volume": 1.0}
            data["lines"]["cable"]["end_b"] = "hang"
        else:
            data["analysis"]["statics"] = "catenary"
        case = SystemCase.parse(data)
        with pytest.raises(InputError) as err:
            sc.validate(case) if hasattr(sc, "validate") else sc.run(case)
    assert message in str(err.value) and "Suggested fix" in str(err.value)


def test_a_clamp_on_a_prescribed_body_turns_with_its_motion():
    """A hull pitching harmonically (0.1 rad, 4 s) about its reference point: after 1 s (a quarter period, pitch 0.1
    rad) the coupled loop's clamp direction is the closed-form ``Ry(0.1) e`` of its direction at rest, and the
    result's hang-off curvature is taken from it."""
    from seacable.mooring.kernel import H_D
    from seacable.system.dynamics import build_system_fe, simulate_system, static_system

    data = _system(CLAMP, kind="prescribed").model_dump(exclude_none=True)
    data["lines"]["cable"]["n_elements"] = 20
    data["analysis"] = {"type": "system_dynamic", "duration": 1.0, "time_step": 0.05, "output_interval": 0.5,
                        "body_motions": {"hull": {"type": "platform", "amplitude": [0, 0, 0, 0, 0.1, 0],
                                                  "period": 4.0}}}
    case = SystemCase.parse(data)
    fe = build_system_fe(case.system(), case.environment, case.analysis)
    (h, _, into), = fe.held
    simulate_system(fe, static_system(fe), 1.0, 0.05, 0.5, analysis=case.analysis)
    expected = rotation_matrix(0.0, 0.1, 0.0) @ into  # the body at rest has no rotation
    assert fe.model.hinge_ei[h, H_D:H_D + 3] == pytest.approx(expected, abs=1e-12)
    assert not np.allclose(expected, into, atol=1e-2)  # and it has turned


# ------------------------------------------------------------------------------- the end force (one definition)
#
# A line's end force is defined once (seacable.mooring.outputs.line_end_forces): its end element's pull, the half
# element's loads lumped at the end node (weight in water, drag, added mass and inertia, seabed) and, for a line
# with bending stiffness, its hinges' forces on the end node (a held end's shear). The single line, the system's
# finite-element statics and system_dynamic report it; these tests hold each of them to the others and to the
# closed form of a cantilever's reaction.

MOTION = {"type": "platform", "amplitude": [0.0, 0.0, 0.5, 0.0, 0.05, 0.0], "period": 4.0, "ramp": 2.0}
DYNAMIC = {"duration": 3.0, "time_step": 0.05, "output_interval": 0.25, "damping_ratio": 0.5}
N_DYN = 20


def test_system_dynamic_end_force_is_the_single_lines_on_a_pitching_hull():
    """The lazy-wave cable clamped to a hull that heaves 0.5 m and pitches 0.05 rad at 4 s, as a system line (the
    hull a prescribed body) and as a single line (``mooring_dynamic``, the platform motion about the hull's reference
    point, the clamp turning with it), 20 elements, 2 s at 0.05 s (Newmark's average acceleration in both): the
    same discrete equations, so the fairlead tension and force agree to the Newton tolerance (1e-8 of the force
    scale: measured 3e-9 of the mean tension here; held to 1e-7). The end force holds the clamp's shear and the half
    element's weight, drag and inertia: the end element's tension alone is 0.3-0.7 % off it (600-1300 N), 10^4
    times the bound; a clamp left at rest (its direction not turned with the hull) moves it by 2e-4."""
    data = _system(CLAMP, kind="prescribed").model_dump(exclude_none=True)
    data["lines"]["cable"]["n_elements"] = N_DYN
    data["analysis"] = {"type": "system_dynamic", **DYNAMIC, "tolerance": 1e-9, "body_motions": {"hull": MOTION}}
    ds = sc.run(SystemCase.parse(data))
    fair = HULL + ARM
    single = _single(CLAMP, (fair[0], fair[2])).model_dump(exclude_none=True)
    single["analysis"] = {**single["analysis"], "type": "mooring_dynamic", "n_elements": N_DYN, **DYNAMIC,
                          "spectral_radius": 1.0, "tolerance": 1e-9,
                          "motion": {**MOTION, "reference": [float(v) for v in HULL]}}
    one = sc.run(parse_case(single))
    ours, theirs = ds.fairlead_tension.sel(line="cable").values, one.fairlead_tension.values
    scale = float(np.mean(theirs))
    assert np.abs(ours - theirs).max() < 1e-7 * scale, np.abs(ours - theirs).max() / scale
    for k in "xyz":
        got = ds[f"fairlead_force_{k}"].sel(line="cable").values
        assert np.abs(got - one[f"fairlead_force_{k}"].values).max() < 1e-7 * scale
    # and the definition matters here: the end element's tension alone is far from it
    element = ds.segment_tension.sel(line="cable").values[:, N_DYN - 1]
    assert np.abs(element - ours).max() > 1e-3 * scale



BEAM = {**CABLE, "bending_stiffness": 2.0e6}   # a stiff cable: EI 2e6 N m^2, 158 N/m in water
TIP_LOAD = np.array([0.0, 2.0e3, 0.0])         # a lateral load on the tip [N]


def _cantilever(analysis):
    """A 10 m cable clamped horizontally at a fixed point (end A, along +x) with a free point at its tip (end B)
    pushed sideways by 2 kN, 50 m down in 300 m of water, 10 elements."""
    return SystemCase.parse({
        "name": "cantilever", "line_types": {"beam": BEAM}, "environment": {**ENV, "depth": 300.0},
        "points": {"root": {"kind": "fixed", "position": [0.0, 0.0, -50.0]},
                   "tip": {"kind": "free", "position": [10.0, 0.0, -50.0],
                           "external_force": [float(v) for v in TIP_LOAD]}},
        "lines": {"beam": {"line_type": "beam", "length": 10.0, "end_a": "root", "end_b": "tip", "n_elements": 10,
                           "end_a_condition": {"type": "clamped", "declination": math.pi / 2, "azimuth": 0.0}}},
        "analysis": analysis})


def test_a_cantilevers_end_forces_are_its_loads_in_the_statics_and_at_rest_in_the_dynamics():
    """A cable clamped at its root and pushed sideways at its free tip (a hang-off under a lateral load, where the
    shear carries the load): at equilibrium the line's force on its root is the sum of the loads on the line, its
    weight in water ``w L`` and the tip load ``P`` (the closed form of any cantilever's reaction, at any deflection),
    and its force on its tip is ``-P``. The finite-element statics (``system_static``) give them to the solver's
    tolerance (measured 1e-7 N of 2.5 kN; held to 1e-3 N); the clamp's shear is nearly all of it, the end element's
    tension 13 N: without the hinges' forces the root force is off by 2.5 kN, without the half element's weight by
    79 N. ``system_dynamic`` left at rest from that equilibrium reports the same end forces (the static limit:
    measured 2e-7 N, held to 1e-7 of them), fairlead (the tip, end B) and anchor (the root) alike."""
    w = (BEAM["mass_per_length"] - ENV["water_density"] * math.pi * BEAM["diameter"] ** 2 / 4) * ENV["gravity"]
    root = TIP_LOAD + np.array([0.0, 0.0, -w * 10.0])  # the closed form: the line's loads, carried to the root
    case = _cantilever({"type": "system_static"})
    eq = fe_equilibrium(case.system(), case.environment, stiffness=False, tol=1e-12)
    np.testing.assert_allclose(eq.end_a_force[0], root, rtol=0, atol=1e-3)
    np.testing.assert_allclose(eq.end_b_force[0], -TIP_LOAD, rtol=0, atol=1e-3)
    # the definition matters: the end element's tension is not the root's force
    assert abs(float(eq.state.tension[eq.fe.line_elements[0][0]]) - np.linalg.norm(root)) > 1e3
    # system_dynamic left at rest: the static limit, every output
    ds = sc.run(_cantilever({"type": "system_dynamic", "duration": 0.5, "time_step": 0.05, "output_interval": 0.25,
                             "tolerance": 1e-10}))
    scale = float(np.linalg.norm(root))
    line = ds.sel(line="beam")
    np.testing.assert_allclose(line.anchor_tension.values, np.linalg.norm(eq.end_a_force[0]), rtol=0,
                               atol=1e-7 * scale)
    np.testing.assert_allclose(line.anchor_vertical_force.values, eq.end_a_force[0][2], rtol=0, atol=1e-7 * scale)
    np.testing.assert_allclose(line.fairlead_tension.values, np.linalg.norm(eq.end_b_force[0]), rtol=0,
                               atol=1e-7 * scale)
    for k, name in enumerate("xyz"):
        np.testing.assert_allclose(line[f"fairlead_force_{name}"].values, eq.end_b_force[0][k], rtol=0,
                                   atol=1e-7 * scale)

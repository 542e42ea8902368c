"""The finite-element formulation of towed_dynamic (issue 21): statics, closed forms and the box scheme.

References, each independent of the model: the hanging cable's exact tension (``w s + W_body``), the steady
2-D towed-cable equations (:func:`seacable.statics.towed_line_steady`, an ODE integration of a different
model) for a depressor two-part tow, the force balance of a body with lift on a weightless line, the
frictional catenary of a sled dragged on the seabed, and paper 000's box scheme on its own turn.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import seacable as sc
from seacable.case import TowedBody
from seacable.mooring import kernel as K
from seacable.mooring.solver import Water
from seacable.statics.towed import towed_line_steady
from seacable.towed.fe import steady_start, towed_system

RHO, G = 1025.0, 9.80665
HEAVY = sc.LineType(diameter=0.03, mass_per_length=3.0, axial_stiffness=4e6, drag_normal=1.5, drag_tangential=0.01)
LIGHT = sc.LineType(diameter=0.02, mass_per_length=0.5, axial_stiffness=2e6, drag_normal=1.2, drag_tangential=0.01)
BODY = TowedBody(mass=200.0, weight_in_water=500.0, drag_area=0.3, added_mass=50.0)
STILL = Water(depth=None, density=RHO, gravity=G)


def _two_part():
    """A depressor two-part tow: 100 m of light pennant from the body to a 2.5 kN depressor whose wing pulls
    down (C_L -0.8 on 0.6 m^2), then 400 m of heavy main tow cable to the tow point."""
    depressor = sc.PointMass(s=100.0, mass=400.0, weight_in_water=2500.0, drag_area=0.4, lift_coefficient=-0.8,
                             reference_area=0.6, kind="depressor")
    return sc.Line(segments=(sc.Segment(line_type=LIGHT, length=100.0), sc.Segment(line_type=HEAVY, length=400.0)),
                   attachments=(depressor,))


def _top_force(system, X, frame):
    """Force of the line on the tow point in the frame moving at ``frame`` (3,) [N]."""
    m = system.model
    env = m.env.copy()
    env[[K.E_FRAMEX, K.E_FRAMEY, K.E_FRAMEZ]] = frame
    n = X.shape[0]
    F, M = np.zeros((n, 3)), np.zeros((n, 3, 3))
    K.loads(X, np.zeros_like(X), 0.0, *m.element_args(), m.fidx, env, m.cur_depth, m.cur_speed, False, m.sea, F, M,
            np.zeros(n - 1), np.zeros((0, 2 * m.bw + 1)), m.bw, 0.0, 0.0)
    return F[-1]


def test_the_steady_two_part_tow_converges_to_the_steady_towed_cable_equations():
    """The steady start (the static equilibrium in the frame moving with the vessel) against the steady 2-D
    equations of the same system, at 51, 101 and 201 nodes: the lumped model's error falls as the square of the
    element length (ratios within 3.5-4.5 of the ideal 4), and at 201 nodes the layback and depth agree to
    2 mm in 430 m and 243 m and the top tension to 0.2 N in 9.35 kN."""
    U = 2.0
    ref, points = towed_line_steady(_two_part(), U, water_density=RHO, gravity=G, body_weight=BODY.weight_in_water,
                                    body_drag_area=BODY.drag_area, tangential_drag="common", n_points=11)
    errors = []
    for n in (51, 101, 201):
        system = towed_system(_two_part(), (0.0, 0.0, 0.0), STILL, n_nodes=n, body=BODY)
        X = steady_start(system, (0.0, 0.0, 0.0), (U, 0.0, 0.0))
        top = _top_force(system, X, (U, 0.0, 0.0))
        errors.append((X[-1, 0] - X[0, 0] - ref.layback, -X[0, 2] - ref.depth_of_lower_end,
                       np.linalg.norm(top) - ref.top_tension))
        assert np.allclose(X[:, 1], 0.0, atol=1e-9)  # the tow stays in the plane of the flow
    errors = np.abs(np.array(errors))
    ratios = errors[:-1] / errors[1:]
    assert np.all((ratios > 3.5) & (ratios < 4.5)), ratios
    assert errors[-1, 0] < 2e-3 and errors[-1, 1] < 2e-3 and errors[-1, 2] < 0.2
    assert points == [(100.0, 3)] and ref.layback > 400.0


def test_a_depressor_without_its_lift_tows_shallower():
    """The depressor's lift (down, 1/2 rho C_L A U^2 = 984 N at 2 m/s) takes the body deeper: the steady state
    with C_L = 0 is shallower, by what the steady equations give (to the 201-node accuracy above)."""
    U = 2.0
    flat = _two_part().model_copy(update={"attachments": (_two_part().attachments[0].model_copy(
        update={"lift_coefficient": 0.0}),)})
    depths = {}
    for name, line in (("wing", _two_part()), ("flat", flat)):
        ref, _ = towed_line_steady(line, U, water_density=RHO, gravity=G, body_weight=BODY.weight_in_water,
                                   body_drag_area=BODY.drag_area, tangential_drag="common")
        system = towed_system(line, (0.0, 0.0, 0.0), STILL, n_nodes=201, body=BODY)
        X = steady_start(system, (0.0, 0.0, 0.0), (U, 0.0, 0.0))
        depths[name] = (-X[0, 2], ref.depth_of_lower_end)
    assert depths["wing"][0] - depths["flat"][0] > 9.0  # 9.14 m
    assert abs((depths["wing"][0] - depths["flat"][0]) - (depths["wing"][1] - depths["flat"][1])) < 4e-3


@pytest.mark.parametrize("heading", [0.0, 2.0])
def test_a_lifting_body_on_a_weightless_line_balances_its_forces(heading):
    """A body of weight W, drag area C_D A and lift area C_L A towed at U on a short line with no weight and no
    drag: the line's force on the tow point is the body's, (1/2 rho C_D A U^2 along the tow, W - 1/2 rho C_L A U^2
    down), whatever the heading: magnitude and angle to 1e-9 (the static solve's tolerance)."""
    U = 1.5
    thread = sc.LineType(diameter=0.001, mass_per_length=1e-9, weight_in_water=0.0, axial_stiffness=1e8,
                         drag_normal=0.0, drag_tangential=0.0)
    wing = TowedBody(mass=300.0, weight_in_water=2000.0, drag_area=0.4, lift_coefficient=0.9, reference_area=1.5)
    system = towed_system(sc.Line.single(thread, 20.0), (0.0, 0.0, 0.0), STILL, n_nodes=5, body=wing)
    v = U * np.array([math.cos(heading), math.sin(heading), 0.0])
    X = steady_start(system, (0.0, 0.0, 0.0), v)
    top = _top_force(system, X, v)
    drag = 0.5 * RHO * 0.4 * U**2
    down = 2000.0 - 0.5 * RHO * 0.9 * 1.5 * U**2
    want = np.array([-drag * math.cos(heading), -drag * math.sin(heading), -down])  # astern and down
    np.testing.assert_allclose(top, want, rtol=1e-9, atol=1e-9 * abs(down))
    assert down > 0.0  # the lift (1556 N) is most of the weight: a wrong sign or size moves the angle by far


def test_the_hanging_cable_started_from_rest_has_the_exact_tension():
    """The vessel at rest in still water (the box scheme's singular case): the cable hangs straight down and each
    element's tension is W_body + w s at its middle (the lumped model is exact there), to 1e-7 relative (the time
    steps' Newton tolerance, 1e-7 of the largest tension), and stays so over a run (velocities below 1e-6 m/s)."""
    case = sc.Case.parse({
        "name": "hang", "line_types": {"c": {"diameter": 0.03, "mass_per_length": 2.0, "axial_stiffness": 4e6,
                                       "drag_normal": 1.5, "drag_tangential": 0.01}},
        "line": {"line_type": "c", "length": 300.0}, "environment": {"water_density": RHO},
        "analysis": {"type": "towed_dynamic", "vessel": {"type": "straight", "speed": 0.0}, "duration": 20.0,
                  "time_step": 1.0, "n_nodes": 31, "body": {"mass": 400.0, "weight_in_water": 3000.0}}})
    ds = sc.run(case)
    w = case.line.segments[0].line_type.submerged_weight(RHO, case.environment.gravity)
    s = ds.s.values
    z, x = ds.z.values, ds.x.values
    np.testing.assert_allclose(x, 0.0, atol=1e-9)
    # node tension: the mean of its elements' W + w s_mid, i.e. W + w s (inner nodes), W + w ds/2 at the body
    want = 3000.0 + w * s
    want[0] = 3000.0 + w * 0.5 * s[1]
    want[-1] = 3000.0 + w * 0.5 * (s[-1] + s[-2])
    np.testing.assert_allclose(ds.tension.values[-1], want, rtol=1e-7)
    assert np.abs(ds.velocity_z.values).max() < 1e-6  # 3e-8: the start and the steps are at their tolerances
    assert ds.top_angle.values[-1] == pytest.approx(math.pi / 2, abs=1e-12)
    # the stretch: the body hangs L + the integral of T / EA below the tow point
    stretch = np.sum((3000.0 + w * 0.5 * (s[1:] + s[:-1])) / 4e6 * np.diff(s))
    assert -z[-1, 0] == pytest.approx(300.0 + stretch, rel=1e-9)


MU, VF = 0.5, 0.01


def test_a_sled_dragged_on_the_seabed_hangs_on_the_frictional_catenary():
    """A 2 kN sled (seabed area 1 m^2) towed at 1 m/s on 300 m of line with no water drag in 100 m of water,
    friction 0.5 (regularised below 0.01 m/s): in steady tow the sled and the grounded line slide, their friction
    mu (W_sled + w L_g) is the horizontal tension H, and the suspended part is the catenary from the touchdown
    (slope 0) to the tow point, of length L_s = sqrt(h^2 + 2 h H / w) (inextensible: EA = 1e9 N), with
    L_g = L - L_s. Solving for H gives 1676.33 N. The steady start's H, the vertical force w L_s and the layback
    (L_g plus the catenary's span) agree to 0.1 N (6e-5) and 2 cm at 61 and 121 nodes: the touchdown lies between
    nodes, which bounds the error by mu w ds / 2 = 8 N; the penalty seabed's rounding makes it far smaller."""
    from scipy.optimize import brentq

    h, L, U = 100.0, 300.0, 1.0
    lt = sc.LineType(diameter=0.03, mass_per_length=2.0, axial_stiffness=1e9, drag_normal=0.0, drag_tangential=0.0)
    w = lt.submerged_weight(RHO, G)
    sled = TowedBody(mass=300.0, weight_in_water=2000.0)
    reg = U / math.hypot(U, VF)

    def suspended(H):
        return math.sqrt(h * h + 2.0 * h * H / w)

    H = brentq(lambda H: H - MU * reg * (2000.0 + w * (L - suspended(H))), 1.0, 1e6)
    span = H / w * math.acosh(1.0 + w * h / H)
    assert H == pytest.approx(1676.33, abs=0.01)
    water = Water(depth=h, density=RHO, gravity=G, friction=MU, friction_velocity=VF)
    for n in (61, 121):
        system = towed_system(sc.Line.single(lt, L), (0.0, 0.0, 0.0), water, n_nodes=n, body=sled)
        X = steady_start(system, (0.0, 0.0, 0.0), (U, 0.0, 0.0))
        top = _top_force(system, X, (U, 0.0, 0.0))
        assert -top[0] == pytest.approx(H, abs=0.1)
        assert -top[2] == pytest.approx(w * suspended(H), abs=0.1)
        assert X[-1, 0] - X[0, 0] == pytest.approx(L - suspended(H) + span, abs=0.02)
        assert X[0, 2] > -h - 1e-3  # the sled on the seabed: pressed in by W / (k A) = 0.7 mm


def _paying(winch, *, duration=150.0, dt=0.5, out=0.5, vessel=None, body_drag=0.0):
    """A 3 kN body (400 kg, added mass 100 kg) hanging on 200 m of cable (d 0.03 m, 2 kg/m, EA 4e6 N, C_dt 0.02)
    from a vessel at rest in still water, its winch running ``winch``."""
    return sc.Case.parse({
        "name": "pay", "line_types": {"c": {"diameter": 0.03, "mass_per_length": 2.0, "axial_stiffness": 4e6,
                                      "drag_normal": 1.5, "drag_tangential": 0.02}},
        "line": {"line_type": "c", "length": 200.0}, "environment": {"water_density": RHO},
        "analysis": {"type": "towed_dynamic", "vessel": vessel or {"type": "straight", "speed": 0.0},
                  "duration": duration, "time_step": dt, "output_interval": out, "n_nodes": 41, "winch": winch,
                  "body": {"mass": 400.0, "added_mass": 100.0, "weight_in_water": 3000.0, "drag_area": body_drag}}})


@pytest.fixture(scope="module")
def paid_out():
    case = _paying({"rate": 1.0, "start_time": 5.0, "ramp": 10.0, "length": 300.0})
    return case, sc.run(case)


def test_paying_out_a_hanging_body_at_a_constant_rate_follows_the_derived_tension(paid_out):
    """Paying out at V_p, every point of the cable and the body sink at V_p: no inertia, and each length ds of
    cable carries its weight less its tangential drag 1/2 rho C_dt pi d V_p^2 ds (the cable moves down through
    still water, the drag points up), the body its weight less its drag (none here). The top tension is then
    T(t) = W_body + (w - 1/2 rho C_dt pi d V_p^2) L(t). Over the constant-rate part (40-100 s, L from 230 to
    290 m): the slope dT/dL fitted to the run is that bracket to 0.5 % (the drag term is 7.7 % of w: a dropped or
    doubled drag misses by 7.7 %), and T is within 10 N of T(t) (0.17 %: the lumped model puts no drag on the
    half element at the tow point, 3.6 N, and the start's axial ringing, damped by the scheme, leaves a few N)."""
    case, ds = paid_out
    w = case.line.segments[0].line_type.submerged_weight(RHO, case.environment.gravity)
    q = 0.5 * RHO * 0.02 * math.pi * 0.03 * 1.0**2
    t, L, T = ds.time.values, ds.deployed_length.values, ds.top_tension.values
    part = (t >= 40.0) & (t <= 100.0)
    np.testing.assert_allclose(np.diff(L[part]), 0.5, rtol=1e-12)  # the rate is constant there
    slope = np.polyfit(L[part], T[part], 1)[0]
    assert slope == pytest.approx(w - q, rel=5e-3)
    assert q > 0.07 * w
    np.testing.assert_allclose(T[part], 3000.0 + (w - q) * L[part], rtol=0, atol=10.0)
    assert ds.paid_out_length.values[-1] == pytest.approx(100.0, rel=1e-12)
    assert ds.attrs["settings"].count('"node_births": 20') == 1


def test_the_body_descends_by_the_length_paid_out_and_the_stretch(paid_out):
    """The body sinks by the length paid out plus the change of the cable's elastic stretch, the integral of
    T / EA over the cable: (W L + (w - q) L^2 / 2) / EA while paying out, (W L + w L^2 / 2) / EA at rest at the
    start, to 5 mm (the tension's 10 N error above is 0.5 mm of stretch; the axial ringing a few mm)."""
    case, ds = paid_out
    w = case.line.segments[0].line_type.submerged_weight(RHO, case.environment.gravity)
    q = 0.5 * RHO * 0.02 * math.pi * 0.03
    t, L = ds.time.values, ds.deployed_length.values
    z = ds.z.values[:, 0]
    part = (t >= 40.0) & (t <= 100.0)
    stretch0 = (3000.0 * 200.0 + w * 200.0**2 / 2) / 4e6
    stretch = (3000.0 * L[part] + (w - q) * L[part] ** 2 / 2) / 4e6
    np.testing.assert_allclose(z[0] - z[part], (L[part] - 200.0) + (stretch - stretch0), rtol=0, atol=5e-3)


def test_the_tension_is_smooth_through_every_node_birth(paid_out):
    """A node is born every 5 m paid out. Over the constant-rate part no step with a birth changes the top
    tension by more than 1.5 times the largest change of the steps without one (measured: 8.2 N against
    12.3 N). A new node put on the chord of the element as it is at the step's end, or given the velocity of the
    chord rather than of the paid-out material, made jumps of hundreds of newtons."""
    _, ds = paid_out
    t, T, n = ds.time.values, ds.top_tension.values, ds.nodes_in_water.values
    steps = np.flatnonzero((t[1:] >= 40.0) & (t[1:] <= 100.0))
    birth = steps[n[steps + 1] > n[steps]]
    other = steps[n[steps + 1] == n[steps]]
    assert len(birth) == 12
    jump = np.abs(np.diff(T))
    assert jump[birth].max() < 1.5 * jump[other].max()


def test_haul_in_after_pay_out_restores_the_start():
    """Pay 100 m out and haul it back in (rate ramps of 10 s): nodes are born and then retired, and the state
    returns to the start: the body's depth to 1e-5 m, every node's position to 1e-5 m, the top tension to 0.1 N
    (what remains of the axial ringing after 165 s at rest)."""
    case = _paying({"times": [0, 5, 15, 105, 115, 125, 135, 225, 235], "lengths": [200, 200, 205, 295, 300, 300,
                                                                                     295, 205, 200]},
                   duration=400.0, out=1.0)
    ds = sc.run(case)
    settings = ds.attrs["settings"]
    assert '"node_births": 20' in settings and '"node_retirements": 20' in settings
    assert ds.nodes_in_water.values[-1] == ds.nodes_in_water.values[0] == 41
    np.testing.assert_allclose(ds.z.values[-1, :41], ds.z.values[0, :41], rtol=0, atol=1e-5)
    assert ds.top_tension.values[-1] == pytest.approx(ds.top_tension.values[0], abs=0.1)
    assert ds.nodes_in_water.values.max() == 61


def test_pay_out_converges_at_second_order_in_the_time_step():
    """The vessel speeds up from rest to 1.5 m/s over 30 s while the winch pays out at 1 m/s (ramped over 20 s):
    the body's position at 40 s at time steps 1/4, 1/8 and 1/16 s against 1/32 s. The generalised-alpha scheme
    is second order; with nodes born on the step grid the errors fall by at least 2.5 per halving (observed 3.1
    and 3.7, approaching 4), far from a first-order scheme's 2."""
    runs = {}
    for dt in (0.25, 0.125, 1 / 16, 1 / 32):
        ds = sc.run(_paying({"rate": 1.0, "ramp": 20.0},
                            vessel={"type": "speed_schedule", "times": [0, 30], "speeds": [0.0, 1.5]},
                            duration=40.0, dt=dt, out=1.0, body_drag=0.5))
        runs[dt] = ds.x.values[-1, 0]
    err = [abs(runs[dt] - runs[1 / 32]) for dt in (0.25, 0.125, 1 / 16)]
    assert err[0] / err[1] > 2.5 and err[1] / err[2] > 2.5, err
    assert runs[1 / 32] > 4.0  # the body has moved 4.5 m (33 m astern of the vessel): a real motion


def test_an_attachment_drags_across_and_along_the_line_by_its_own_areas():
    """A clump on a straight line along X (C_D A 1.0 m^2 across, 0.2 m^2 along) in a flow (1.2, -0.7, 0.5) m/s,
    the line itself without drag, weight or lift: the force on the clump's node is
    1/2 rho (1.0 |u_n| u_n + 0.2 |u_t| u_t) with u_t the flow's X part, u_n the rest (to round-off), and the
    Newton matrix's block of the node is -dF/dv (central differences, 1e-6)."""
    from seacable.mooring.network import network_from_line

    bare = sc.LineType(diameter=0.01, mass_per_length=1.0, weight_in_water=0.0, axial_stiffness=1e6,
                       drag_normal=0.0, drag_tangential=0.0)
    clump = sc.PointMass(s=10.0, mass=50.0, weight_in_water=0.0, drag_area=1.0, axial_drag_area=0.2)
    net = network_from_line(sc.Line.single(bare, 20.0, attachments=(clump,)), (0.0, 0.0, -50.0),
                            (20.0, 0.0, -50.0), water_density=RHO, gravity=G, n_elements=2)
    np.testing.assert_allclose(net.point_hydrodynamics()[1], (1.0, 0.2, 0.0))
    u = np.array([1.2, -0.7, 0.5])
    speed, heading = math.hypot(u[0], u[1]), math.atan2(u[1], u[0])
    from seacable.mooring.solver import MooringModel

    model = MooringModel(net, Water(depth=None, density=RHO, gravity=G, current_speeds=(speed,),
                                    current_heading=heading))
    model.env[K.E_FRAMEZ] = -u[2]  # the frame sinking at 0.5 m/s: the water rises past it
    X = net.position.copy()

    def force(V, cc=1.0):
        F, M = np.zeros((3, 3)), np.zeros((3, 3, 3))
        band = np.zeros((3 * model.nfree, 2 * model.bw + 1))
        K.loads(X, V, 0.0, *model.element_args(), model.fidx, model.env, model.cur_depth, model.cur_speed, False,
                model.sea, F, M, np.zeros(2), band, model.bw, 0.0, cc)
        return F, band

    V = np.zeros((3, 3))
    F, band = force(V)
    band = band - force(V, cc=0.0)[1]  # C alone
    un, ut = np.array([0.0, u[1], u[2]]), np.array([u[0], 0.0, 0.0])
    want = 0.5 * RHO * (1.0 * np.linalg.norm(un) * un + 0.2 * np.linalg.norm(ut) * ut)
    np.testing.assert_allclose(F[1], want, rtol=1e-12, atol=1e-12)
    # -dF/dv of the node (its 3x3 diagonal block in the band: the middle node is the only free one)
    h = 1e-6
    jac = np.zeros((3, 3))
    for r in range(3):
        Vp, Vm = V.copy(), V.copy()
        Vp[1, r] += h
        Vm[1, r] -= h
        jac[:, r] = -(force(Vp)[0][1] - force(Vm)[0][1]) / (2 * h)
    f = model.fidx[1]
    block = np.array([[band[3 * f + r, model.bw + c - r] for c in range(3)] for r in range(3)])
    np.testing.assert_allclose(block, jac, rtol=0, atol=1e-5 * np.abs(jac).max())


def test_the_finite_element_turn_is_paper_000s_box_scheme_turn():
    """Paper 000's turn (examples/paper000_turn.yaml: a left turn at 0.5 deg/s for 100 s against a 1 m/s
    current) in both formulations at 97 nodes, the same tangential drag form: two different discretisations
    (Euler angles on a box scheme with the curvatures as unknowns; lumped masses with MoorDyn's nodal bending)
    of the same continuum. The top tension agrees to 0.1 N in 1.5 kN at every output and the free end's position
    to 5 mm; at 25 nodes the finite-element run is further (0.2 N, 3 cm), so the agreement comes from
    convergence."""
    base = sc.load_case(Path(__file__).resolve().parents[2] / "examples" / "paper000_turn.yaml")
    runs = {}
    for form, n in (("box", 97), ("finite_element", 97), ("finite_element", 25)):
        a = base.analysis.model_copy(update={"formulation": form, "tangential_drag": "common", "n_nodes": n})
        runs[form, n] = sc.run(base.model_copy(update={"analysis": a}))
    box, fe, coarse = runs["box", 97], runs["finite_element", 97], runs["finite_element", 25]
    np.testing.assert_allclose(fe.top_tension.values, box.top_tension.values, rtol=0, atol=0.1)
    for v in ("x", "y", "z"):
        np.testing.assert_allclose(fe[v].values[:, 0], box[v].values[:, 0], rtol=0, atol=5e-3)
    assert np.abs(coarse.top_tension.values - box.top_tension.values).max() > np.abs(
        fe.top_tension.values - box.top_tension.values).max()
    assert box.top_tension.values[0] - box.top_tension.values[-1] > 20.0  # the turn changes the tension


@pytest.mark.parametrize(("law", "normal", "along"), [
    # bare: 1/2 rho C_dn d U^2 and 1/2 rho C_dt pi d U^2 per metre
    ({}, 0.5 * RHO * 1.5 * 0.03, 0.5 * RHO * 0.01 * math.pi * 0.03),
    # faired (Packwood 1990): on the chord 0.12 m, skin friction on the wetted perimeter 2.1 x 0.12 m
    ({"drag_law": "faired", "fairing_chord": 0.12}, 0.5 * RHO * 1.5 * 0.12, 0.5 * RHO * 0.01 * 2.1 * 0.12),
    # strumming at A_rms / d = 0.5: Vandiver's factor 1 + 1.043 (2 x 0.5)^0.65 = 2.043 on the normal drag
    ({"strumming_amplitude": 0.5}, 0.5 * RHO * 1.5 * 0.03 * 2.043, 0.5 * RHO * 0.01 * math.pi * 0.03),
])
def test_the_drag_laws_load_the_line_as_their_formulas_say(law, normal, along):
    """A straight horizontal 100 m line (no weight) in a 1.2 m/s current across it, then along it: the water's
    force on it, summed over the nodes, is the drag law's per-metre drag times the length, to round-off."""
    from seacable.mooring.network import network_from_line
    from seacable.mooring.solver import MooringModel

    lt = sc.LineType(diameter=0.03, mass_per_length=1.0, weight_in_water=0.0, axial_stiffness=1e7, drag_normal=1.5,
                     drag_tangential=0.01, **law)
    net = network_from_line(sc.Line.single(lt, 100.0), (0.0, 0.0, -50.0), (100.0, 0.0, -50.0), water_density=RHO,
                            gravity=G, n_elements=10)
    for heading, per_metre, axis in ((math.pi / 2, normal, 1), (0.0, along, 0)):
        model = MooringModel(net, Water(depth=None, density=RHO, gravity=G, current_speeds=(1.2,),
                                        current_heading=heading))
        F, _, _, _ = model.evaluate(net.position, np.zeros((11, 3)), np.zeros((11, 3)), waves=False)
        assert F[:, axis].sum() == pytest.approx(per_metre * 1.2**2 * 100.0, rel=1e-12)


def test_a_seabed_profile_presses_each_node_along_its_segments_normal():
    """Nodes pressed 1 cm (measured along the vertical) into a seabed profile (100 m deep at x = 0, 60 m at
    x = 100 m, 60 m beyond): the contact force is k d_n times the penetration normal to the segment under the node,
    ``(z_b - z) cos(theta)``, along that segment's normal, and a two-point profile is the same plane as depth and
    slope give (to round-off)."""
    from seacable.mooring.network import network_from_line
    from seacable.mooring.solver import MooringModel

    bare = sc.LineType(diameter=0.05, mass_per_length=1.0, weight_in_water=0.0, axial_stiffness=1e6,
                       drag_normal=0.0)
    xs = np.array([20.0, 50.0, 80.0, 130.0])
    zb = np.interp(xs, (0.0, 100.0), (-100.0, -60.0))
    net = network_from_line(sc.Line.single(bare, 120.0), (0.0, 0.0, 0.0), (120.0, 0.0, 0.0), water_density=RHO,
                            gravity=G, n_elements=3)
    X = np.column_stack([xs, np.zeros(4), zb - 0.01])
    kind = net.kind.copy()
    kind[0] = 0  # free (the anchor's check would refuse it under the seabed)
    net = net.replace(position=X, kind=kind, length=np.linalg.norm(np.diff(X, axis=0), axis=1) * 1.001)  # slack
    kb = 3e6
    profile = Water(depth=None, density=RHO, gravity=G, seabed_stiffness=kb, seabed_damping=0.0,
                    profile=((0.0, 100.0), (100.0, 60.0)))
    F, _, _, _ = MooringModel(net, profile).evaluate(X, np.zeros_like(X), np.zeros_like(X), waves=False)
    theta = math.atan(0.4)
    bedc = MooringModel(net, profile).bedc
    for i in range(3):  # on the slope: 1 cm vertical is 1 cm cos(theta) along the normal (-sin, 0, cos)
        want = kb * bedc[i] * 0.01 * math.cos(theta) * np.array([-math.sin(theta), 0.0, math.cos(theta)])
        np.testing.assert_allclose(F[i], want, rtol=1e-9)
    # beyond the profile's end (x = 130 m) the seabed is level at -60 m: straight up, the full 1 cm
    zb[3] = -60.0
    X[3, 2] = zb[3] - 0.01
    F, _, _, _ = MooringModel(net, profile).evaluate(X, np.zeros_like(X), np.zeros_like(X), waves=False)
    np.testing.assert_allclose(F[3], [0.0, 0.0, kb * bedc[3] * 0.01], rtol=1e-9, atol=1e-9)
    plane = Water(depth=100.0, slope=theta, density=RHO, gravity=G, seabed_stiffness=kb, seabed_damping=0.0)
    X[3, 2] = -40.0  # above the plane's continuation (the elements stay slack: node 3 loads no other)
    Fp, _, _, _ = MooringModel(net.replace(position=X), plane).evaluate(X, np.zeros_like(X), np.zeros_like(X),
                                                                        waves=False)
    F, _, _, _ = MooringModel(net, profile).evaluate(X, np.zeros_like(X), np.zeros_like(X), waves=False)
    np.testing.assert_allclose(Fp[:3], F[:3], rtol=1e-9)


def test_the_two_part_tow_run_in_time_holds_its_steady_state():
    """The depressor two-part tow run for 60 s behind a vessel at a steady 2 m/s: the dynamics start from the
    steady state and stay there (the depressor's and the body's layback and depth within 1 mm, the top tension
    within 0.5 N of their start): the static equilibrium in the moving frame is the time integration's
    equilibrium too (no start-up transient)."""
    spec = {
        "name": "two_part", "environment": {"water_density": RHO, "gravity": G},
        "line_types": {"heavy": HEAVY.model_dump(exclude_none=True), "light": LIGHT.model_dump(exclude_none=True)},
        "line": {"segments": [{"line_type": "light", "length": 100.0}, {"line_type": "heavy", "length": 400.0}],
                 "attachments": [_two_part().attachments[0].model_dump(exclude_none=True)]},
        "analysis": {"type": "towed_dynamic", "vessel": {"type": "straight", "speed": 2.0}, "duration": 60.0,
                     "time_step": 1.0, "n_nodes": 51, "body": BODY.model_dump(exclude_none=True)}}
    ds = sc.run(sc.Case.parse(spec))
    for name in ("point_layback", "point_depth"):
        values = ds[name].values
        np.testing.assert_allclose(values, np.broadcast_to(values[:1], values.shape), rtol=0, atol=1e-3)
    np.testing.assert_allclose(ds.top_tension.values, ds.top_tension.values[0], rtol=0, atol=0.5)
    assert list(ds.point.values) == ["body", "attachments[0] (depressor)"]

"""Steady towing of a composite cable (issue 21): segments of different line types and points in line.

:func:`seacable.statics.towed_line_steady` integrates the steady towed-cable equations segment by segment
from the towed end, the tension's horizontal and vertical parts stepping by each in-line point's drag and
weight. References: the uniform cable's own solution (the same cable cut in two), and the mooring model's
finite-element statics of the same system (a different discretisation: lumped masses, Morison loads at the
nodes, an in-line clump and the body as attachments, pseudo-transient Newton), which must converge to it at
second order in the element length.
"""

from __future__ import annotations

import numpy as np
import pytest

import seacable as sc
from seacable.errors import InputError
from seacable.mooring.network import network_from_line
from seacable.mooring.solver import MooringModel, Water, static_equilibrium
from seacable.statics.towed import towed_cable_steady, towed_line_steady

RHO, G, U = 1025.0, 9.80665, 2.0
HEAVY = sc.LineType(diameter=0.04, mass_per_length=8.0, weight_in_water=60.0, axial_stiffness=2e7, drag_normal=1.4,
                    drag_tangential=0.02)
LIGHT = sc.LineType(diameter=0.03, mass_per_length=2.0, weight_in_water=12.0, axial_stiffness=4e6, drag_normal=1.5,
                    drag_tangential=0.01)


def test_a_uniform_cable_cut_in_two_is_the_uniform_cable():
    """Two segments of the same line type, nothing at the joint: the one-segment solution to the integrator's
    tolerance (1e-9 relative), the joint reported twice with the same values."""
    one = towed_cable_steady(500.0, 12.0, 0.03, U, 1.5, 0.01, axial_stiffness=4e6, body_weight=3000.0,
                             body_drag_area=0.5, n_points=11)
    line = sc.Line(segments=[sc.Segment(line_type=LIGHT, length=200.0), sc.Segment(line_type=LIGHT, length=300.0)])
    two, points = towed_line_steady(line, U, water_density=RHO, gravity=G, body_weight=3000.0, body_drag_area=0.5,
                                    n_points=11)
    assert points == [(200.0, 5)] and two.s[4] == two.s[5] == 200.0
    keep = np.r_[0:5, 6:12]
    np.testing.assert_allclose(two.s[keep], one.s)
    for name in ("tension", "angle", "x", "z"):
        np.testing.assert_allclose(getattr(two, name)[keep], getattr(one, name), rtol=1e-9,
                                   atol=1e-9 * np.max(np.abs(getattr(one, name))))
    assert two.tension[4] == two.tension[5]


def _composite():
    """200 m of heavy cable at the towed end, a 2 kN clump (C_D A 0.3 m^2) at the joint, 300 m of light cable
    to the tow point; a 3 kN body (C_D A 0.5 m^2) at the end."""
    return sc.Line(segments=[sc.Segment(line_type=HEAVY, length=200.0), sc.Segment(line_type=LIGHT, length=300.0)],
                   attachments=[sc.PointMass(s=200.0, weight_in_water=2000.0, drag_area=0.3, mass=250.0)])


def _from_the_tow_point():
    """The composite tow as the mooring model's line: end A at the tow point, the body an attachment at end B."""
    return sc.Line(segments=[sc.Segment(line_type=LIGHT, length=300.0), sc.Segment(line_type=HEAVY, length=200.0)],
                   attachments=[sc.PointMass(s=300.0, weight_in_water=2000.0, drag_area=0.3, mass=250.0),
                                sc.PointMass(s=500.0, weight_in_water=3000.0, drag_area=0.5, mass=400.0)])


@pytest.fixture(scope="module")
def uniform_tow():
    """The composite tow in the uniform 2 m/s flow, common drag form, and its in-line points."""
    return towed_line_steady(_composite(), U, water_density=RHO, gravity=G, body_weight=3000.0, body_drag_area=0.5,
                             tangential_drag="common")


def test_a_composite_tow_is_the_finite_element_statics_of_the_same_system(uniform_tow):
    """The composite tow against the mooring model's statics of the same line hung from the tow point in a
    2 m/s current (end B free: the body an attachment), both with the common drag form: the top tension, the
    body's layback and depth and the clump's position converge to the ODE's at second order (errors falling
    3.5-4.5 times as the elements halve, 50 -> 100 -> 200), the 200-element error below 3e-5 of the tension
    and 1 cm of position."""
    res, points = uniform_tow
    (s_clump, i_clump), = points
    assert s_clump == 200.0
    want = np.array([res.top_tension, res.layback, res.depth_of_lower_end, res.x[i_clump], -res.z[i_clump]])
    # the same system from the tow point down (end A fixed at the tow point, end B free at the body)
    rev = _from_the_tow_point()
    errors = []
    for n in (50, 100, 200):
        net = network_from_line(rev, (0.0, 0.0, 0.0), (res.layback, 0.0, -res.depth_of_lower_end),
                                water_density=RHO, gravity=G, n_elements=n, end_b="free")
        model = MooringModel(net, Water(depth=None, density=RHO, gravity=G, current_speeds=(U,)))
        st = static_equilibrium(model, tol=1e-10)
        clump = int(np.argmin(np.abs(np.cumsum(np.r_[0.0, net.length]) - 300.0)))
        got = np.array([np.linalg.norm(st.support[0]), st.position[-1, 0], -st.position[-1, 2],
                        st.position[clump, 0], -st.position[clump, 2]])
        errors.append(np.abs(got - want))
    errors = np.array(errors)
    ratios = errors[:-1] / errors[1:]
    assert np.all((ratios > 3.5) & (ratios < 4.5)), ratios
    assert errors[-1, 0] < 3e-5 * res.top_tension and np.all(errors[-1, 1:] < 0.01)


def test_a_composite_line_in_a_towed_steady_case_reports_each_point():
    """The case path: a two-segment line with a clump runs (it took the first segment's properties for the
    whole line before) and reports the clump's layback and depth, the lower end's values as the function."""
    case = sc.Case(name="tow2", line_types={"heavy": HEAVY.model_dump(exclude_none=True),
                                            "light": LIGHT.model_dump(exclude_none=True)},
                   line={"segments": [{"line_type": "heavy", "length": 200.0}, {"line_type": "light", "length": 300.0}],
                         "attachments": [{"s": 200.0, "weight_in_water": 2000.0, "drag_area": 0.3}]},
                   environment={"water_density": RHO, "gravity": G},
                   analysis={"type": "towed_steady", "vessel_speed": U, "tangential_drag": "common",
                             "body": {"weight_in_water": 3000.0, "drag_area": 0.5}, "n_nodes": 21})
    ds = sc.run(case)
    res, points = towed_line_steady(_composite(), U, water_density=RHO, gravity=G, body_weight=3000.0,
                                    body_drag_area=0.5, tangential_drag="common", n_points=21)
    assert float(ds.layback) == pytest.approx(res.layback, rel=1e-12)
    assert ds.point_s.values.tolist() == [200.0]
    assert float(ds.point_depth[0]) == pytest.approx(-res.z[points[0][1]], rel=1e-12)
    assert 0 < float(ds.point_depth[0]) < float(ds.lower_end_depth)
    assert float(ds.top_angle) == pytest.approx(res.top_angle, rel=1e-12)
    assert 0 < float(ds.top_angle) < np.pi / 2


def test_bad_composite_tows_are_refused_clearly():
    floating = sc.LineType(diameter=0.03, mass_per_length=0.5, weight_in_water=-3.0, axial_stiffness=4e6)
    line = sc.Line(segments=[sc.Segment(line_type=floating, length=100.0), sc.Segment(line_type=LIGHT, length=100.0)])
    with pytest.raises(InputError, match="lowest segment of the towed line floats"):
        towed_line_steady(line, U)
    with pytest.raises(InputError, match="line must be a seacable.Line"):
        towed_line_steady("cable", U)


PROFILE = ((0.0, 100.0, 300.0), (2.0, 1.6, 1.0))  # relative flow [m/s] at depths below the tow point [m]


@pytest.fixture(scope="module")
def in_profile():
    """The composite tow in the relative flow PROFILE, common drag form (each a whole integration per trial depth
    of the lower end: computed once for the module)."""
    return towed_line_steady(_composite(), PROFILE, water_density=RHO, gravity=G, body_weight=3000.0,
                             body_drag_area=0.5, tangential_drag="common")[0]


def test_a_tow_in_a_current_profile_is_the_finite_element_statics_in_that_current(in_profile, uniform_tow):
    """The composite tow in a relative flow falling from 2.0 m/s at the surface to 1.0 m/s at 300 m (each drag
    at its depth; the lower end's depth found so that the top meets the tow point) against the mooring model's
    statics in the same current profile: the top tension converges at second order (error ratios 3.5-4.7 as
    the elements halve; the profile's kinks at 100 and 300 m make the positions' ratios irregular), within
    5e-6 of the tension and 5 mm of the body's position at 200 elements. The slower flow at depth lets the
    body hang deeper than in the uniform 2 m/s."""
    res = in_profile
    uniform, _ = uniform_tow
    assert res.depth_of_lower_end > uniform.depth_of_lower_end + 100.0
    assert abs(res.z[-1]) < 1e-12 and abs(res.x[-1]) < 1e-12  # the top at the tow point
    want = np.array([res.top_tension, res.layback, res.depth_of_lower_end])
    rev = _from_the_tow_point()
    errors = []
    for n in (50, 100, 200):
        net = network_from_line(rev, (0.0, 0.0, 0.0), (res.layback, 0.0, -res.depth_of_lower_end),
                                water_density=RHO, gravity=G, n_elements=n, end_b="free")
        model = MooringModel(net, Water(depth=None, density=RHO, gravity=G, current_depths=PROFILE[0],
                                        current_speeds=PROFILE[1]))
        st = static_equilibrium(model, tol=1e-10)
        errors.append(np.abs([np.linalg.norm(st.support[0]), st.position[-1, 0], -st.position[-1, 2]] - want))
    errors = np.array(errors)
    ratios = errors[:-1, 0] / errors[1:, 0]
    assert np.all((ratios > 3.5) & (ratios < 4.7)), ratios
    assert errors[-1, 0] < 5e-6 * res.top_tension and np.all(errors[-1, 1:] < 0.005)


def test_a_towed_steady_case_takes_a_current_profile(in_profile):
    """The case's current profile (flowing against the tow at 0, 0.4 and 1.0 m/s at 0, 100 and 300 m, vessel
    at 2 m/s ahead, heading 0: the relative flow 2.0, 1.6 and 1.0 m/s, PROFILE) runs as the function with the
    relative profile (the composite tow of the test above); a current outrunning the vessel at depth is refused
    with the speed named."""
    base = {"name": "towprof", "line_types": {"heavy": HEAVY.model_dump(exclude_none=True),
                                              "light": LIGHT.model_dump(exclude_none=True)},
            "line": {"segments": [{"line_type": "heavy", "length": 200.0}, {"line_type": "light", "length": 300.0}],
                     "attachments": [{"s": 200.0, "weight_in_water": 2000.0, "drag_area": 0.3}]},
            "analysis": {"type": "towed_steady", "vessel_speed": 2.0, "tangential_drag": "common",
                         "body": {"weight_in_water": 3000.0, "drag_area": 0.5}, "n_nodes": 101}}
    env = {"water_density": RHO, "gravity": G,
           "current": {"heading": 0.0, "depths": [0.0, 100.0, 300.0], "speeds": [0.0, 0.4, 1.0]}}
    ds = sc.run(sc.Case(**base, environment=env))
    res = in_profile
    assert float(ds.layback) == pytest.approx(res.layback, rel=1e-9)
    assert float(ds.lower_end_depth) == pytest.approx(res.depth_of_lower_end, rel=1e-9)
    env["current"]["speeds"] = [0.0, 0.4, 2.5]
    with pytest.raises(InputError, match="relative flow speed at 300 m depth is -0.5 m/s"):
        sc.run(sc.Case(**base, environment=env))


def test_a_depressors_lift_pulls_the_body_down_by_its_force_balance():
    """A body of 3 kN in water, C_D A 0.5 m^2, with a depressor wing (C_L -0.6 on 1.2 m^2) at 2 m/s: at the lower
    end the cable holds the body's drag D = 1/2 rho C_D A U^2 and its weight less its lift, W - L with
    L = 1/2 rho C_L A U^2 (negative: down), so its tension is hypot(D, W - L) and its angle atan2(W - L, D)
    (the force balance, 1e-12), and the body goes deeper than without the wing."""
    body = {"weight_in_water": 3000.0, "drag_area": 0.5}
    base = {"name": "depressor", "line_types": {"light": LIGHT.model_dump(exclude_none=True)},
            "line": {"line_type": "light", "length": 500.0}, "environment": {"water_density": RHO, "gravity": G}}
    plain = sc.run(sc.Case(**base, analysis={"type": "towed_steady", "vessel_speed": U, "body": body}))
    winged = sc.run(sc.Case(**base, analysis={"type": "towed_steady", "vessel_speed": U, "body": {
        **body, "lift_coefficient": -0.6, "reference_area": 1.2}}))
    drag = 0.5 * RHO * 0.5 * U**2
    lift = 0.5 * RHO * -0.6 * 1.2 * U**2
    assert float(winged.tension[0]) == pytest.approx(np.hypot(drag, 3000.0 - lift), rel=1e-12)
    assert float(winged.angle[0]) == pytest.approx(np.arctan2(3000.0 - lift, drag), rel=1e-12)
    assert float(winged.lower_end_depth) > float(plain.lower_end_depth) + 10.0


def test_a_lift_without_its_area_and_a_lifting_body_in_the_box_dynamics_are_refused():
    with pytest.raises(InputError, match=r"analysis.body lift_coefficient -0.6 needs reference_area"):
        sc.Case(name="x", line_types={"light": LIGHT.model_dump(exclude_none=True)},
                line={"line_type": "light", "length": 500.0},
                analysis={"type": "towed_steady", "vessel_speed": U,
                          "body": {"weight_in_water": 3000.0, "lift_coefficient": -0.6}})
    with pytest.raises(InputError, match="the box formulation does not model a body's lift"):
        sc.Case(name="x", line_types={"light": {**LIGHT.model_dump(exclude_none=True), "bending_stiffness": 1.0}},
                line={"line_type": "light", "length": 500.0},
                analysis={"type": "towed_dynamic", "formulation": "box", "duration": 10.0,
                          "vessel": {"type": "straight", "speed": 2.0},
                          "body": {"weight_in_water": 3000.0, "mass": 400.0, "lift_coefficient": -0.6,
                                   "reference_area": 1.2}})


def test_a_steady_tow_through_the_seabed_is_warned_with_its_depth():
    """The 500 m tow hangs about 297 m deep at 2 m/s: in 400 m of water the result's seabed clearance is the
    depth less the lowest point's (the lower end); in 250 m of water that is negative and a warning names the
    depth, the seabed and the fix."""
    def case(depth):
        return sc.Case(name="deep", line_types={"heavy": HEAVY.model_dump(exclude_none=True),
                                                "light": LIGHT.model_dump(exclude_none=True)},
                       line={"segments": [{"line_type": "heavy", "length": 200.0},
                                          {"line_type": "light", "length": 300.0}]},
                       environment={"water_density": RHO, "gravity": G, "depth": depth},
                       analysis={"type": "towed_steady", "vessel_speed": U,
                                 "body": {"weight_in_water": 3000.0, "drag_area": 0.5}})
    ds = sc.run(case(400.0))
    assert float(ds.seabed_clearance) == pytest.approx(400.0 - float(ds.lower_end_depth), rel=1e-12)
    with pytest.warns(sc.errors.SeacableWarning, match=r"m deep, below the seabed at 250 m"):
        shallow = sc.run(case(250.0))
    assert float(shallow.seabed_clearance) < 0

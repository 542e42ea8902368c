"""A towed body's drag and added mass per axis of the body (issue 41): closed forms and the two formulations.

References, each independent of the model: the force balance of a body paid out vertically at a constant rate
(WHOI Cable takes a towed terminal body's drag on the vertical with its own coefficient, Gobat & Grosenbaugh
2000; no published WHOI Cable tension for such a case was found, so the closed form stands in), the steady
tow's force balance at the body (the cable's tension there carries the body's weight and its drag along the
tow, 1/2 rho (C_D A)_along U^2, and nothing of its other axes), and the box scheme of paper 000 against the
finite-element formulation on paper 000's turn, where the body sees the flow across it.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import seacable as sc
from seacable.case import TowedBody
from seacable.mooring.solver import Water
from seacable.statics.towed import towed_line_steady
from seacable.towed.fe import steady_start, towed_system

RHO, G = 1025.0, 9.80665
CABLE = sc.LineType(diameter=0.03, mass_per_length=3.0, axial_stiffness=4e6, drag_normal=1.5, drag_tangential=0.01)


def _lowering(drag_area, added_mass=100.0):
    """A 3 kN sled (400 kg) hanging on 200 m of cable (d 0.03 m, 2 kg/m, EA 4e6 N, C_dt 0.02) from a vessel at rest
    in still water, paid out at 1 m/s from t = 5 s (10 s ramp) to 300 m: the cable stays vertical."""
    return sc.Case.parse({
        "name": "lowering", "line_types": {"c": {"diameter": 0.03, "mass_per_length": 2.0, "axial_stiffness": 4e6,
                                                "drag_normal": 1.5, "drag_tangential": 0.02}},
        "line": {"line_type": "c", "length": 200.0}, "environment": {"water_density": RHO},
        "analysis": {"type": "towed_dynamic", "vessel": {"type": "straight", "speed": 0.0},
                     "duration": 60.0, "time_step": 0.5, "output_interval": 0.5, "n_nodes": 41,
                     "winch": {"rate": 1.0, "start_time": 5.0, "ramp": 10.0, "length": 300.0},
                     "body": {"mass": 400.0, "added_mass": added_mass, "weight_in_water": 3000.0,
                              "drag_area": drag_area}}})


def _body_offset(ds, case):
    """Mean over the constant-rate part (30-60 s) of T - (w - q) L: the body's share of the top tension [N]."""
    w = case.line.segments[0].line_type.submerged_weight(RHO, case.environment.gravity)
    q = 0.5 * RHO * 0.02 * math.pi * 0.03 * 1.0**2  # the cable's tangential drag per metre at 1 m/s
    t, L, T = ds.time.values, ds.deployed_length.values, ds.top_tension.values
    part = (t >= 30.0) & (t <= 60.0)
    return float(np.mean(T[part] - (w - q) * L[part]))


def test_a_sled_paid_out_vertically_feels_its_vertical_drag_only():
    """Paid out at V = 1 m/s, the sled sinks at V: the top tension is W_cable_wet - cable tangential drag +
    W_body - 1/2 rho (C_D A)_vertical V^2 (the sled moves down, its drag points up). With C_D A = [0.33, 0.6,
    0.1] (along, across, vertical) its drag is 51.25 N; the isotropic 0.33 m^2 puts 169.1 N on it. The body's
    share of the tension, T - (w - q) L, is the closed form's 2948.75 N to 5 N (the lumped model carries no drag
    on the half element at the tow point and the start's axial ringing leaves a few N: the same offset, 2.5 N,
    as the isotropic run's); the two runs differ by 1/2 rho (0.33 - 0.1) V^2 = 117.9 N to 0.5 N (the common
    offset cancels). Swapping the along and vertical areas, or dropping the vertical one, misses by 50-118 N."""
    axes = _lowering([0.33, 0.6, 0.1])
    iso = _lowering(0.33)
    got_axes = _body_offset(sc.run(axes), axes)
    got_iso = _body_offset(sc.run(iso), iso)
    assert got_axes == pytest.approx(3000.0 - 0.5 * RHO * 0.1, abs=5.0)
    assert got_iso == pytest.approx(3000.0 - 0.5 * RHO * 0.33, abs=5.0)
    assert got_axes - got_iso == pytest.approx(0.5 * RHO * (0.33 - 0.1), abs=0.5)


TOWFISH = {"mass": 300.0, "weight_in_water": 2000.0}


def test_the_steady_tow_balances_the_bodys_along_drag_and_weight():
    """towed_steady of a 2 kN towfish at 2 m/s with C_D A = [0.3, 1.5, 2.0]: the flow past it is horizontal along
    the tow, so the cable's tension at the body is (1/2 rho 0.3 U^2, W) = (615 N, 2000 N), its angle
    atan(W / H) = 72.9 deg, exactly (1e-9: the integration starts there); the isotropic 0.3 m^2 gives the same
    steady tow, and the vertical area (2.0, swapped onto the along axis) would make it 4100 N."""
    U = 2.0
    H, W = 0.5 * RHO * 0.3 * U**2, TOWFISH["weight_in_water"]
    runs = {}
    for name, drag in (("axes", [0.3, 1.5, 2.0]), ("iso", 0.3)):
        case = sc.Case(name="towfish", line=sc.Line.single(CABLE, 300.0), environment=sc.Environment(),
                       analysis=sc.TowedSteadyAnalysis(vessel_speed=U, body=TowedBody(**TOWFISH, drag_area=drag),
                                                       n_nodes=11))
        runs[name] = sc.run(case)
    ds = runs["axes"]
    assert float(ds.tension.values[0]) == pytest.approx(math.hypot(H, W), rel=1e-9)
    assert float(ds.angle.values[0]) == pytest.approx(math.atan2(W, H), rel=1e-9)
    np.testing.assert_array_equal(ds.z.values, runs["iso"].z.values)


@pytest.mark.parametrize("n_nodes", [41])
def test_the_finite_element_steady_tow_of_a_towfish_is_the_steady_towed_cable_equations(n_nodes):
    """The finite-element steady start (the static equilibrium in the frame moving with the vessel) of the same
    towfish on 300 m of cable at 2 m/s, C_D A = [0.3, 1.5, 2.0]: its along axis is the cable's horizontal
    direction at the body, +X, so only the along area acts, and the body's depth and layback are those of the
    steady 2-D equations with 0.3 m^2 (an ODE integration of a different model) to 0.15 m in 155 m and 254 m
    (measured 3 cm and 4 cm: the lumped model's discretisation at 41 nodes, its error falling as ds^2 to 2 mm at
    201 nodes in test_towed_fe, about 5 cm expected here), and those of the isotropic 0.3 m^2 to the static
    solve's tolerance (1 mm). The along and vertical areas swapped (2.0 along) lift the body by 17 m."""
    U = 2.0
    line = sc.Line.single(CABLE, 300.0)
    ref, _ = towed_line_steady(line, U, water_density=RHO, gravity=G, body_weight=TOWFISH["weight_in_water"],
                               body_drag_area=0.3, tangential_drag="common", n_points=11)
    water = Water(depth=None, density=RHO, gravity=G)
    ends = {}
    for name, drag in (("axes", (0.3, 1.5, 2.0)), ("iso", 0.3), ("swapped", (2.0, 1.5, 0.3))):
        system = towed_system(line, (0.0, 0.0, 0.0), water, n_nodes=n_nodes, body=TowedBody(**TOWFISH,
                                                                                            drag_area=drag))
        X = steady_start(system, (0.0, 0.0, 0.0), (U, 0.0, 0.0))
        ends[name] = X[0]
    depth, layback = -ends["axes"][2], -ends["axes"][0]
    assert depth == pytest.approx(-ref.z[0], abs=0.15)
    assert layback == pytest.approx(ref.x[0], abs=0.15)
    np.testing.assert_allclose(ends["axes"], ends["iso"], rtol=0, atol=1e-3)
    assert depth - (-ends["swapped"][2]) > 10.0


def test_the_box_scheme_and_the_finite_elements_turn_a_body_with_drag_per_axis_alike():
    """Paper 000's turn (examples/paper000_turn.yaml: a left turn at 0.5 deg/s for 100 s against a 1 m/s current)
    with a 500 N body of C_D A = [0.3, 0.8, 0.5] and added mass [20, 80, 100] kg at the end, in both formulations
    at 97 and 193 nodes: the body swings out across its axis (its lateral position ends 0.29 m from the
    isotropic 0.3 m^2's). The finite elements take the body's along axis on their end element's chord, the box
    scheme on the tangent at the end node: the two differ by the curvature times half an element, so the body's
    lateral position converges at first order in the element length, 0.107 m at 97 nodes and 0.051 m at 193 from
    the box scheme's (ratio 2.1, in a lateral excursion of 6 m); at 193 nodes the top tension agrees to 0.14 N
    (0.2 N asserted; 0.145 N for the isotropic body) and the body's x and z to 1 cm. A swapped or dropped axis in
    either formulation moves the body by 0.1-0.3 m laterally and the tension by 2-17 N."""
    base = sc.load_case(Path(__file__).resolve().parents[2] / "examples" / "paper000_turn.yaml")
    body = TowedBody(mass=200.0, weight_in_water=500.0, drag_area=[0.3, 0.8, 0.5], added_mass=[20.0, 80.0, 100.0])
    runs = {}
    for form, n in (("box", 193), ("finite_element", 97), ("finite_element", 193)):
        a = base.analysis.model_copy(update={"formulation": form, "tangential_drag": "common", "n_nodes": n,
                                             "body": body})
        runs[form, n] = sc.run(base.model_copy(update={"analysis": a}))
    box = runs["box", 193]
    err = {n: np.abs(runs["finite_element", n].y.values[:, 0] - box.y.values[:, 0]).max() for n in (97, 193)}
    assert err[193] < 0.06
    assert 1.7 < err[97] / err[193] < 2.5  # first order in the element length
    fine = runs["finite_element", 193]
    np.testing.assert_allclose(fine.top_tension.values, box.top_tension.values, rtol=0, atol=0.2)
    for v in ("x", "z"):
        np.testing.assert_allclose(fine[v].values[:, 0], box[v].values[:, 0], rtol=0, atol=0.01)

"""Ties to the seabed on a mooring system's lines (issue 40): clamps and tethers (:mod:`seacable.ties`) of a system
line, in the system's finite-element statics and dynamics.

References and closed forms:

- the single-line finite-element analysis (``mooring_static``, ``mooring_dynamic``): the same tied line between
  two fixed points of a system solves the same discrete equations (the same nodes, a node at each tie, the same
  tie forces), so shapes, tensions and the tethers' tensions agree to the solvers' tolerance;
- a rigid clamp's node divides the line into two lines held at the clamp's point: the system of those two lines
  meeting at a fixed point is the same discrete system, and the clamp's reaction is the sum of their end forces
  there (a chain, no bending: the two lines' pinned ends at the point are the clamped line's hinge-less node);
- a buoy below a vertical cable, held down by a tether (the single line's closed form of
  ``tests/validation/test_seabed_ties.py``): ``T_t = T_c + B``, with the cable's stretch under its own weight and
  the tether's adding up to the gap between the fixed points;
- a dynamic run left alone from its static start stays there: the coupled kernel's tie forces are the statics'.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.errors import InputError
from seacable.io import parse_case
from seacable.mooring.outputs import tether_tension
from seacable.mooring.run import case_model
from seacable.mooring.solver import static_equilibrium
from seacable.system.case import SystemCase
from seacable.system.statics.fe import fe_equilibrium

RHO, G = 1025.0, 9.80665
N = 85  # 2 m elements on the 170 m cable: a node at each tie; both solvers converge from their default starts


def _example(name):
    with open(f"examples/{name}.yaml") as f:
        return yaml.safe_load(f)


def _single_and_system(name):
    """The example's tied cable as a single line (``mooring_static``) and as the line of a system between two fixed
    points at its anchor and hang-off, in the example's current."""
    d = _example(name)
    d["analysis"] = {"type": "mooring_static", "anchor": [0.0, -80.0], "fairlead": [120.0, -14.0], "n_elements": N}
    system = SystemCase.parse({
        "name": name, "line_types": d["line_types"], "environment": d["environment"],
        "points": {"anchor": {"kind": "fixed", "position": [0.0, 0.0, -80.0]},
                   "hang": {"kind": "fixed", "position": [120.0, 0.0, -14.0]}},
        "lines": {"cable": {**d["line"], "end_a": "anchor", "end_b": "hang", "n_elements": N}},
        "analysis": {"type": "system_static"}})
    return parse_case(d), system


@pytest.mark.parametrize("name", ["lazy_s_80m", "pliant_wave_80m"])
def test_tied_cable_as_a_system_line_is_the_single_line(name):
    """The lazy-S (a 35 kN subsea buoy on a 35 m tether at s = 75 m) and the pliant wave (a 2 m tether at the
    touchdown, s = 45 m, and smeared buoyancy) in their current, as a single line and as a system line. Both are
    solved to a force residual of 1e-10 of the line's scale by their own Newton schemes: measured 1.3e-7 m and
    4.9e-7 m apart, tensions 3.5e-4 N and 7e-5 N, the tethers' tensions 2e-9 of 22.3 kN and 5e-8 of 499 N. The
    bounds (1e-6 m, 1e-2 N) are those of tests/validation/test_system_cable.py; a tie dropped moves the cable by
    metres, a tether on the next node by decimetres."""
    single, system = _single_and_system(name)
    model = case_model(single)
    st = static_equilibrium(model, tol=1e-10)
    eq = fe_equilibrium(system.system(), system.environment, stiffness=False, tol=1e-10)
    s, X, T = eq.line_nodes("cable")
    assert s == pytest.approx(model.network.arc_length, abs=1e-12)
    assert np.abs(X - st.position).max() < 1e-6
    assert np.abs(T - st.tension).max() < 1e-2
    t1 = tether_tension(model.network, st.position)
    assert tether_tension(eq.fe.model.network, eq.state.position) == pytest.approx(t1, abs=1e-2)
    # the result: the system's tether_tension (condition, line, tether) and the tether's arc length
    ds = sc.run(system)
    got = ds.tether_tension.sel(condition="intact", line="cable").values
    assert ds.tether_tension.dims == ("condition", "line", "tether")
    assert got == pytest.approx(t1, abs=1e-2) and got[0] > 400.0
    assert ds.tether_s.sel(line="cable").values == pytest.approx([75.0 if name == "lazy_s_80m" else 45.0])
    assert "line 'cable' with " in ds.attrs["statics_reason"] and "ties to the seabed" in ds.attrs["statics_reason"]


# ------------------------------------------------------------------------------------------------ clamps

CHAIN = {"diameter": 0.08, "mass_per_length": 130.0, "axial_stiffness": 5e8}
CLAMP_AT = [80.0, 0.0, -60.0]


def _chain_system(lines, points=None, analysis="system_static"):
    return SystemCase.parse({
        "name": "clamped", "line_types": {"chain": CHAIN}, "environment": {"water_density": RHO, "gravity": G,
                                                                          "depth": 100.0},
        "points": {"anchor": {"kind": "fixed", "position": [0.0, 0.0, -100.0]},
                   "fair": {"kind": "fixed", "position": [170.0, 0.0, -10.0]}, **(points or {})},
        "lines": lines, "analysis": {"type": analysis}})


def _clamped(stiffness=None):
    clamp = {"type": "clamp", "s": 90.0, "position": {"x": CLAMP_AT[0], "z": CLAMP_AT[2]}}
    if stiffness is not None:
        clamp["stiffness"] = stiffness
    return _chain_system({"chain": {"line_type": "chain", "length": 200.0, "end_a": "anchor", "end_b": "fair",
                                    "n_elements": 40, "sections": [clamp]}})


def test_rigid_clamp_on_a_system_line_is_two_lines_meeting_at_its_point():
    """A 200 m chain clamped rigidly at s = 90 m to a point in mid-water, and the two chains (90 m, 110 m, 5 m
    elements as the clamped line's) from the anchor and the fairlead to a fixed point there: the same nodes and
    equations, measured 3e-14 m apart (1e-9 asserted); the clamp's reaction (``clamp_force``) is the sum of the two
    lines' end forces at the point, measured 4e-9 of it (two Newton solves to 1e-10 of the loads), 1e-7 asserted. A clamp dropped
    lets the chain sag tens of metres; its force read at the wrong node, or the half elements' weight (3.2 kN) left
    out, fails by kilonewtons."""
    ds = sc.run(_clamped())
    split = _chain_system({"a": {"line_type": "chain", "length": 90.0, "end_a": "anchor", "end_b": "clamp",
                                 "n_elements": 18},
                           "b": {"line_type": "chain", "length": 110.0, "end_a": "clamp", "end_b": "fair",
                                 "n_elements": 22}},
                          {"clamp": {"kind": "fixed", "position": CLAMP_AT}})
    eq = fe_equilibrium(split.system(), split.environment, stiffness=False, tol=1e-10)
    eq1 = fe_equilibrium(_clamped().system(), split.environment, stiffness=False, tol=1e-10)
    _, X1, _ = eq1.line_nodes("chain")
    Xs = np.vstack([eq.line_nodes("a")[1], eq.line_nodes("b")[1][1:]])
    assert np.abs(X1 - Xs).max() < 1e-9
    assert X1[18] == pytest.approx(CLAMP_AT, abs=0.0)  # the clamped node is held at the point
    total = eq.end_b_force[0] + eq.end_a_force[1]
    reaction = np.array([float(ds[f"clamp_force_{c}"].sel(condition="intact", line="chain")[0]) for c in "xyz"])
    assert reaction == pytest.approx(total, abs=1e-7 * np.linalg.norm(total))
    assert float(ds.clamp_force.sel(condition="intact", line="chain")[0]) == pytest.approx(np.linalg.norm(total),
                                                                                        rel=1e-7)
    assert float(ds.clamp_s.sel(line="chain")[0]) == 90.0 and abs(reaction[2]) > 1e4


def test_spring_clamp_on_a_system_line_holds_its_node_by_its_stiffness():
    """The clamp as a spring of 1e9 N/m: its node sits ``F / k`` from the point along the force ``F`` of the line
    on it (the result's ``clamp_force``), to round-off (1e-6 of the offset asserted), and that force is the rigid
    clamp's to first order in 1 / k (the hanging chains' stiffness over k: measured 1.8e-4; 1e-3 asserted). A spring
    acting the other way, or at the wrong point, fails both."""
    rigid = sc.run(_clamped())
    case = _clamped(1e9)
    eq = fe_equilibrium(case.system(), case.environment, stiffness=False, tol=1e-12)
    ds = sc.run(case)
    force = np.array([float(ds[f"clamp_force_{c}"].sel(condition="intact", line="chain")[0]) for c in "xyz"])
    node = eq.line_nodes("chain")[1][18]
    assert node - np.array(CLAMP_AT) == pytest.approx(force / 1e9, rel=1e-6, abs=1e-12)
    f_rigid = np.array([float(rigid[f"clamp_force_{c}"].sel(condition="intact", line="chain")[0]) for c in "xyz"])
    assert np.linalg.norm(force - f_rigid) < 1e-3 * np.linalg.norm(f_rigid)


# ------------------------------------------------------------------------------------------------ a tethered buoy

W, L, EA, B, L0, EAT, H = 300.0, 60.0, 5e6, 25e3, 19.0, 2e6, 80.0


def _buoy_system(analysis=None, push=0.0):
    """A 60 m cable (EA 5 MN, 300 N/m in water) from a fixed point at z = -20 m down to a free point, a buoy of
    25 kN net buoyancy (and ``push`` [N] of external force down), held by a 19 m tether (EA 2 MN) at the cable's
    end s = 60 m to the seabed at z = -100 m."""
    cable = {"diameter": 0.1, "mass_per_length": W / G + RHO * math.pi / 4 * 0.01, "axial_stiffness": EA}
    return SystemCase.parse({
        "name": "buoy", "line_types": {"cable": cable}, "environment": {"water_density": RHO, "gravity": G,
                                                                        "depth": 100.0},
        "points": {"top": {"kind": "fixed", "position": [0.0, 0.0, -20.0]},
                   "buoy": {"kind": "free", "position": [0.0, 0.0, -80.5], "volume": B / (RHO * G),
                            "external_force": [0.0, 0.0, -push]}},
        "lines": {"cable": {"line_type": "cable", "length": L, "end_a": "top", "end_b": "buoy", "n_elements": 12,
                            "sections": [{"type": "tether", "s": L, "anchor": {"x": 0.0},
                                          "axial_stiffness": EAT, "length": L0}]}},
        "analysis": analysis or {"type": "system_static"}})


def test_tether_holds_the_buoyancy_of_a_free_point():
    """The closed form of the single line's buoy (tests/validation/test_seabed_ties.py) in a system: the buoy a
    free point at the cable's end, the tether at that end. Along the vertical ``T(s) = T_c + w s`` and the buoy's
    balance ``T_t = T_c + B``::

        (T_c L + w L^2 / 2) / EA + L0 (T_c + B) / EA_t = H - L - L0

    The lumped nodes are exact for a uniform load in 1D, so the tether's tension is the closed form's to the
    solver's tolerance (measured 5e-12; 1e-8 asserted, the solver's 1e-10 of the loads); the buoyancy left out, or the tether pushing, fails by
    25 kN."""
    ds = sc.run(_buoy_system())
    Tc = (H - L - L0 - W * L**2 / (2 * EA) - L0 * B / EAT) / (L / EA + L0 / EAT)
    assert float(ds.tether_tension.sel(condition="intact", line="cable")[0]) == pytest.approx(Tc + B, rel=1e-8)
    assert float(ds.tether_s.sel(line="cable")[0]) == L
    z = float(ds.point_z.sel(condition="intact", point="buoy"))
    assert z == pytest.approx(-100.0 + L0 * (1 + (Tc + B) / EAT), abs=1e-8)


def test_system_dynamic_stays_at_the_tethered_equilibrium():
    """The buoy pushed down by 1 kN (a node's external force: the coupled kernel, not the lines-only loop), left
    alone from its static start: the tether's tension stays the closed form's ``T_c + B - 1 kN`` (measured 2e-11
    relative over 2 s; 1e-8 asserted, the start's residual of 1e-9 of the loads); a kernel without the tie's force (or with it the other way)
    lets the buoy rise at once."""
    analysis = {"type": "system_dynamic", "duration": 2.0, "time_step": 0.05, "output_interval": 0.5}
    ds = sc.run(_buoy_system(analysis, push=1000.0))
    b = B - 1000.0
    Tc = (H - L - L0 - W * L**2 / (2 * EA) - L0 * b / EAT) / (L / EA + L0 / EAT)
    got = ds.tether_tension.sel(line="cable").values[:, 0]
    assert ds.tether_tension.dims == ("time", "line", "tether")
    assert got == pytest.approx(np.full(got.shape, Tc + b), rel=1e-8)


# ------------------------------------------------------------------------------------------------ dynamics

TAUT = {"diameter": 0.02, "mass_per_length": RHO * math.pi / 4 * 0.02**2 + 0.2, "axial_stiffness": 1e6}
TIED = {"segments": [{"line_type": "cable", "length": 39.9}],
        "attachments": [{"s": 19.95, "mass": 500.0, "added_mass": 300.0, "volume": 4000.0 / (RHO * G) + 500.0 / RHO,
                         "kind": "buoy"}],
        "sections": [{"type": "tether", "s": 19.95, "anchor": {"x": 20.0, "z": -60.0}, "axial_stiffness": 1e6,
                      "length": 10.0},
                     {"type": "clamp", "s": 7.98, "position": {"x": 8.0, "z": -50.0}},
                     {"type": "clamp", "s": 31.92, "position": {"x": 32.0, "z": -50.0}, "stiffness": 1e4}]}
MOTION = {"type": "harmonic", "amplitude": [0.05, 0.0, 0.05], "period": 4.0}
RUN = {"duration": 4.0, "time_step": 0.02, "output_interval": 0.5}


def test_tied_line_in_system_dynamic_is_the_single_line():
    """A taut light cable (39.9 m, 10 elements) with a buoy (4 kN net) on a 10 m tether at its middle, a rigid
    clamp at s = 7.98 m and a spring clamp (10 kN/m) at s = 31.92 m, its end B moved 5 cm in x and z at 4 s, for one
    period: ``mooring_dynamic`` (Newmark's average acceleration, spectral radius 1) and ``system_dynamic`` (the same
    scheme, the end a coupled point with the same motion). The tether's tension swings by 20 N and the clamps'
    forces from 10 N to 1.6 kN; the two runs agree to 4e-7 m, 2e-4 N on the tether and 1.2e-4 N on the clamps
    (each step solved to its Newton tolerance, 1e-7 of the loads, over 200 steps); 1e-5 m and 1e-2 N asserted. A
    tie dropped, its force on the next node or the spring's force the other way fails by newtons."""
    single = parse_case({"name": "t", "line_types": {"cable": TAUT}, "line": TIED,
                         "environment": {"water_density": RHO, "gravity": G, "depth": 60.0},
                         "analysis": {"type": "mooring_dynamic", "anchor": [0.0, -50.0], "fairlead": [40.0, -50.0],
                                      "n_elements": 10, "spectral_radius": 1.0, "motion": MOTION, **RUN}})
    system = SystemCase.parse({
        "name": "t", "line_types": {"cable": TAUT}, "environment": {"water_density": RHO, "gravity": G, "depth": 60.0},
        "points": {"a": {"kind": "fixed", "position": [0.0, 0.0, -50.0]},
                   "f": {"kind": "coupled", "position": [40.0, 0.0, -50.0]}},
        "lines": {"cable": {**TIED, "end_a": "a", "end_b": "f", "n_elements": 10}},
        "analysis": {"type": "system_dynamic", "point_motions": {"f": MOTION}, **RUN}})
    d1, d2 = sc.run(single), sc.run(system)
    for axis in "xyz":
        assert np.abs(d1[axis].values - d2[axis].sel(line="cable").values).max() < 1e-5
    assert d2.tether_tension.dims == ("time", "line", "tether") and d2.clamp_force.dims == ("time", "line", "clamp")
    assert d2.tether_tension.sel(line="cable").values == pytest.approx(d1.tether_tension.values, abs=1e-2)
    assert np.ptp(d1.tether_tension.values) > 10.0
    for name in ("clamp_force", "clamp_force_x", "clamp_force_z"):
        assert d2[name].sel(line="cable").values == pytest.approx(d1[name].values, abs=1e-2)
    assert d2.clamp_s.sel(line="cable").values == pytest.approx([7.98, 31.92])
    assert d1.clamp_force.values.max() > 1e3


def _subsea_buoy(analysis, force=(0.0, 0.0)):
    """A subsea buoy (40 m^3, 20 t) held by two chains, with a cable hung off it that is tethered at s = 60 m (a
    500 kg, 3 m^3 buoy there) to a point 10 m above the seabed (300 m), ``force`` [N] on the buoy in x and y."""
    cable = {"diameter": 0.16, "mass_per_length": 36.7, "axial_stiffness": 4.69e8}
    return SystemCase.parse({
        "name": "subsea", "line_types": {"cable": cable, "chain": CHAIN},
        "environment": {"water_density": RHO, "gravity": G, "depth": 300.0},
        "bodies": {"buoy": {"kind": "free", "position": [0.0, 0.0, -40.0, 0.0, 0.0, 0.0], "mass": 2.0e4,
                            "center_of_gravity": [0.0, 0.0, -1.0], "inertia": [1e5, 1e5, 1e5], "volume": 40.0,
                            "center_of_buoyancy": [0.0, 0.0, 1.0], "external_force": [*force, 0.0, 0.0, 0.0, 0.0]}},
        "points": {"a1": {"kind": "fixed", "position": [-80.0, 0.0, -120.0]},
                   "a2": {"kind": "fixed", "position": [30.0, 0.0, -120.0]},
                   "a3": {"kind": "fixed", "position": [0.0, 30.0, -120.0]},
                   "hang": {"kind": "body", "body": "buoy", "position": [-2.0, 0.0, -2.0]},
                   "t1": {"kind": "body", "body": "buoy", "position": [2.0, 0.0, -2.0]},
                   "t2": {"kind": "body", "body": "buoy", "position": [0.0, 2.0, -2.0]}},
        "lines": {"cable": {"segments": [{"line_type": "cable", "length": 130.0}], "end_a": "a1", "end_b": "hang",
                            "n_elements": 26, "attachments": [{"s": 60.0, "volume": 3.0, "mass": 500.0, "kind": "buoy"}],
                            "sections": [{"type": "tether", "s": 60.0, "anchor": {"x": -45.0, "z": -140.0},
                                          "axial_stiffness": 1e7, "length": 30.0}]},
                  "tether": {"line_type": "chain", "length": 90.0, "end_a": "a2", "end_b": "t1", "n_elements": 10},
                  "tether2": {"line_type": "chain", "length": 90.0, "end_a": "a3", "end_b": "t2", "n_elements": 10}},
        "analysis": analysis})


def test_system_offsets_carry_the_tethers_tension_per_load_and_heading():
    """``system_offsets`` of a free body whose cable is tethered: ``tether_tension`` (condition, applied_load,
    heading, line, tether) at each load and heading is that of ``system_static`` with the same force on the body
    (the same finite-element equilibrium: 1e-8 relative, the solves' tolerance), NaN for the lines without
    tethers; a load and heading transposed, or the tether left out of the offsets' statics, fails by 10 %."""
    ds = sc.run(_subsea_buoy({"type": "system_offsets", "body": "buoy", "loads": [0.0, 2e4],
                              "headings": [0.0, math.pi / 2], "load_steps": 2}))
    assert ds.tether_tension.dims == ("condition", "applied_load", "heading", "line", "tether")
    got = ds.tether_tension.sel(condition="intact", line="cable").values[..., 0]
    for j, load in enumerate((0.0, 2e4)):
        for k, heading in enumerate((0.0, math.pi / 2)):
            force = (load * math.cos(heading), load * math.sin(heading))
            case = _subsea_buoy({"type": "system_static"}, force)
            eq = fe_equilibrium(case.system(), case.environment, stiffness=False)
            assert got[j, k] == pytest.approx(tether_tension(eq.fe.model.network, eq.state.position)[0], rel=1e-8)
    assert abs(got[1, 0] / got[1, 1] - 1) > 0.1  # the headings differ: a transposition is seen
    assert np.isnan(ds.tether_tension.sel(line="tether").values).all()


# ------------------------------------------------------------------------------------------------ bad input

@pytest.mark.parametrize("change, message", [
    (lambda d: d["lines"]["cable"]["sections"][0].update(s=70.0), "sections[0] (tether) is at s = 70 m, beyond the end"),
    (lambda d: d["lines"]["cable"]["sections"][0]["anchor"].update(z=5.0),
     "lines.cable.sections[0] (tether).anchor.z = 5 m is above the still water level"),
    (lambda d: d["lines"]["cable"]["sections"][0]["anchor"].update(z=-120.0),
     "lines.cable.sections[0] (tether).anchor.z = -120 m is 20 m below the seabed"),
    (lambda d: d["points"]["buoy"].update(kind="fixed"),
     "lines.cable.sections[0] (tether) is at s = 60 m, the line's end_b at point 'buoy', which is a fixed point"),
])
@pytest.mark.parametrize("analysis", ["system_static", "system_dynamic"])
def test_bad_ties_on_a_system_line_are_refused_before_anything_runs(change, message, analysis):
    """What ``run`` refuses, ``validate`` (:func:`seacable.simulate.check`) refuses, naming the line."""
    from seacable.simulate import check

    data = {
        "name": "buoy", "line_types": {"cable": {"diameter": 0.1, "mass_per_length": 40.0, "axial_stiffness": EA}},
        "environment": {"water_density": RHO, "gravity": G, "depth": 100.0},
        "points": {"top": {"kind": "fixed", "position": [0.0, 0.0, -20.0]},
                   "buoy": {"kind": "free", "position": [0.0, 0.0, -80.5], "volume": 2.5}},
        "lines": {"cable": {"line_type": "cable", "length": L, "end_a": "top", "end_b": "buoy",
                            "sections": [{"type": "tether", "s": L, "anchor": {"x": 0.0}, "axial_stiffness": EAT,
                                          "length": L0}]}},
        "analysis": {"type": analysis} if analysis == "system_static" else
        {"type": analysis, "duration": 1.0, "time_step": 0.1}}
    change(data)
    with pytest.raises(InputError) as err:
        check(SystemCase.parse(data))
    assert message in str(err.value) and "Suggested fix" in str(err.value)
    with pytest.raises(InputError) as err:
        sc.run(SystemCase.parse(data))
    assert message in str(err.value)


def test_catenary_statics_refuse_a_tied_line():
    """The catenary statics cannot carry a tie: asked for, they are refused naming the line (``auto`` takes the
    finite-element statics, :func:`test_tied_cable_as_a_system_line_is_the_single_line`)."""
    data = _buoy_system().model_dump(exclude_none=True)
    data["analysis"]["statics"] = "catenary"
    with pytest.raises(InputError) as err:
        sc.run(SystemCase.parse(data))
    assert "line 'cable' with ties to the seabed (clamps or tethers)" in str(err.value)
    assert "Suggested fix" in str(err.value)

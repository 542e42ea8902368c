"""Public MoorDyn decks, read, converted to a mooring system and solved, against MoorDyn and MoorPy.

The decks are vendored in ``data/moordyn_decks`` (``PROVENANCE.md``: repository, path, commit,
licence). ``reference.json`` holds MoorDyn 2.7.2's initial static state (``moordyn.Init``, its own
relaxation) and MoorPy 1.3.0's ``solveEquilibrium`` for each deck, written by ``make_reference.py``
in the same folder, so that this test compares to numbers; ``test_moordyn_live`` re-runs MoorDyn on
two decks to show the cache is MoorDyn's answer.

Tolerances. MoorPy solves the same elastic catenaries exactly (rigid frictionless seabed), as
seacable's system statics do: 1e-4 relative on every line end tension and 1e-3 m on body positions
(both solvers stop at ~1e-6 relative residuals; 1e-4 leaves room, and is 100 times tighter than the
issue's 1 %). MoorDyn is a lumped-mass model relaxed in time: its end-node force differs from the
exact catenary by the discretisation (a few 0.1 % at 20-40 segments) and by where its relaxation
stopped (``threshIC`` of the deck): 1 % where its relaxation converged below 1e-2 m/s^2.
"""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from _evidence import check

from seacable.errors import ConvergenceError, InputError, NoSolutionError
from seacable.io.moordyn import is_moordyn_file, moordyn_system, read_moordyn
from seacable.results import body_pose

HERE = Path(__file__).parent / "data" / "moordyn_decks"
REFERENCE = json.loads((HERE / "reference.json").read_text())
DECKS = sorted(p.relative_to(HERE).as_posix() for p in HERE.rglob("*")
               if p.suffix in (".txt", ".dat") and "LICENSES" not in p.parts and is_moordyn_file(p))  # not the tables the decks name

# Every deck converts to a mooring system: g = 0 and WtrDnsty = 0 switch gravity and buoyancy off (9 decks), rods and
# bodies without lines are systems all the same (7 decks), FAST.Farm's turbines are placed (SharedMooring2).
# Decks that convert but have no static equilibrium, and why (the statics' message must say so); they run in time
# (test_decks_without_a_static_equilibrium_run_in_time).
NO_STATICS = {
    # a 1.03e6 kg body without volume, its three lines at one point 0.22 m below its centre of gravity:
    # it sinks to the anchors' depth (MoorPy: z = -70 m, lines slack, rolled 1.7 rad); a dynamic test
    # deck (TmaxIC = 0) with no upright equilibrium
    "r-test/modules/moordyn/md_BodiesAndRods/moordyn.dat": "capsizes",
    # free bodies and rods with no line: nothing holds them horizontally (they rise, sink, float or, with g = 0, drift)
    "MoorDyn/tests/Mooring/body_tests/floatingBodies.txt": "no horizontal restoring",
    "MoorDyn/tests/Mooring/body_tests/orbitalBody.txt": "no horizontal restoring",
    "r-test/modules/moordyn/md_float/moordyn.dat": "no horizontal restoring",
    "r-test/modules/moordyn/md_horizontal/moordyn.dat": "no horizontal restoring",
    "r-test/modules/moordyn/md_vertical/moordyn.dat": "no horizontal restoring",
    "MoorDyn/tests/Mooring/rod_tests/RodInertia.txt": "no horizontal restoring",
    "MoorDyn/tests/Mooring/rod_tests/AddedMass.txt": "no horizontal restoring",
    # a small tripod floating at the surface on its lines: its lines' buoyancy, all or nothing at z = 0 in the catenary
    # statics, lifts them out of the water and their dry weight sinks them back, round after round (issue 37: this was
    # returned unsettled after 8 rounds); it floats partly immersed, which the dynamics model
    "MoorDyn/tests/Mooring/tripod.txt": "rises above the sea surface while immersed and sinks under its dry weight",
}
# ... and of those, the ones the dynamics refuse too, and why (orbitalBody's body1, a point mass 10 m from its
# reference point, spins freely about its centre of gravity: test_a_point_mass_body_orbits_its_centre_of_gravity)
NO_DYNAMICS: dict[str, str] = {
    # the finite-element statics that starts the run finds no equilibrium of the floating tripod either (its lines
    # float at the surface): refused with the residual, not run from a wrong start
    "MoorDyn/tests/Mooring/tripod.txt": "did not converge",
}
# Decks where MoorDyn's converged start is not the static state seacable models, and why.
MOORDYN_DIFFERS = {
    # a 1 m viscoelastic line between points 2 m apart (strain 1): MoorDyn's static tension 7.07e7 N is not
    # EA_s x strain = 1.424e8 N (MoorPy's and seacable's): MoorDyn splits the strain between its static and
    # dynamic springs, which the conversion (axial_stiffness = EA_s) does not model
    "r-test/modules/moordyn/md_viscoelastic/moordyn.dat",
}
# MoorDyn has no strain limit: the decks are solved admitting up to 20 (its spring tests stretch a line 9.8 times)
MAX_STRAIN = 20.0
# MoorPy 1.3.0 leaves lifting.txt's free point where it starts (zero tension, 'converged'); the closed
# form is tested instead (test_a_weight_on_a_neutral_line_hangs_by_its_weight).
# MoorPy gives 3D_seafloor/hanging_lines' vertical chains with a massless free end half their weight at both ends.
MOORPY_WRONG = {"MoorDyn/tests/Mooring/lifting.txt", "MoorDyn/tests/Mooring/3D_seafloor/hanging_lines.txt"}


# Decks whose LINE TYPES column names are MoorDyn v1's coefficients (Can Cat Cdn Cdt, two with an extra 'tbd' before them)
# over MoorDyn v2's columns (with EI: Cd Ca CdAx CaAx): read by position as MoorDyn reads them, with a warning
# (test_column_names_out_of_moordyn_order_are_warned). Every other deck's headers are in MoorDyn's order.
HEADER_OUT_OF_ORDER = {
    "MoorDyn/tests/Mooring/body_tests/bodyDrag.txt", "MoorDyn/tests/Mooring/body_tests/pinnedBody.txt",
    "MoorDyn/tests/Mooring/body_tests/rotatingBody.txt", "MoorDyn/tests/Mooring/local_euler/complex_system.txt",
    "MoorDyn/tests/Mooring/riser/riser.txt", "MoorDyn/tests/Mooring/syrope/exp_wc/line.txt",
    "MoorDyn/tests/Mooring/syrope/linear_wc/line.txt", "MoorDyn/tests/Mooring/syrope/quadratic_wc/line.txt",
    "MoorDyn/tests/Mooring/syrope/slow_loading.txt", "r-test/modules/moordyn/5MW_OC4/moordyn.dat",
    "r-test/modules/moordyn/5MW_OC4_simple/moordyn.dat", "r-test/modules/moordyn/md_BdyExtLdDmpg/moordyn.dat",
    "r-test/modules/moordyn/md_BodiesAndRods/moordyn.dat", "r-test/modules/moordyn/md_bodyDrag/moordyn.dat",
    "r-test/modules/moordyn/md_float/moordyn.dat", "r-test/modules/moordyn/md_horizontal/moordyn.dat",
    "r-test/modules/moordyn/md_no_line/moordyn.dat", "r-test/modules/moordyn/md_vertical/moordyn.dat",
}


def _quiet(fn, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # each deck's notes (options seacable does not honour) are tested elsewhere
        return fn(*args, **kwargs)


def test_every_vendored_deck_is_listed_with_its_provenance():
    provenance = (HERE / "PROVENANCE.md").read_text()
    assert len(DECKS) >= 40
    for path in HERE.rglob("*"):
        if path.suffix in (".txt", ".dat") and "LICENSES" not in path.parts:  # decks and the tables they name
            assert f"| {path.relative_to(HERE).as_posix()} |" in provenance
    for deck in DECKS:
        assert deck in REFERENCE["decks"]
    assert REFERENCE["moordyn_version"] == "2.7.2" and REFERENCE["moorpy_version"] == "1.3.0"


def _turbines(deck):
    """The turbine poses reference.json records for a deck on FAST.Farm turbines (make_reference.TURBINES), or None."""
    poses = REFERENCE["decks"][deck].get("turbine_positions")
    return None if poses is None else {int(n): tuple(v) for n, v in poses.items()}


@pytest.mark.parametrize("deck", DECKS)
def test_deck_reads_and_converts(deck):
    md = _quiet(read_moordyn, HERE / deck)
    assert md.lines or md.rods or md.bodies
    system, env = _quiet(moordyn_system, md, turbine_positions=_turbines(deck))
    assert len(system.lines) == len(md.lines)
    assert env.water_density == md.water_density and env.gravity == md.gravity


def _system(deck, frictionless=True):
    md = _quiet(read_moordyn, HERE / deck)
    system, env = _quiet(moordyn_system, md, turbine_positions=_turbines(deck))
    if frictionless:
        env = env.model_copy(update={"seabed": env.seabed.model_copy(update={"friction": 0.0})})
    return md, system, env


def _solve(deck, frictionless=True):
    """The deck's equilibrium, refused as ``system_static`` refuses it (a free body with no line and no horizontal
    restoring). ``frictionless``: MoorPy ignores seabed friction, and MoorDyn's relaxed
    initial state has none acting (its friction is a velocity-regularised law, zero at rest after a
    relaxation from the catenary start), so the comparisons take the seabed without friction; seacable's
    statics with friction take the fully mobilised friction toward the fairlead (a different state)."""
    from seacable.system.run import check_bodies_without_lines
    from seacable.system.statics import solve_equilibrium

    md, system, env = _system(deck, frictionless)
    check_bodies_without_lines(system)
    return md, _quiet(solve_equilibrium, system, env, max_strain=MAX_STRAIN)


def test_every_deck_converts_and_all_but_eight_solve_their_statics():
    """84 decks; each converts (test_deck_reads_and_converts); 76 solve their statics (test_deck_statics_solve_or_say
    _why), the 8 of NO_STATICS have no static equilibrium and all 8 run in time."""
    assert len(DECKS) == 84
    assert len(NO_STATICS) == 9 and len(DECKS) - len(NO_STATICS) == 75
    assert list(NO_DYNAMICS) == ["MoorDyn/tests/Mooring/tripod.txt"]


@pytest.mark.parametrize("deck", DECKS)
def test_deck_statics_solve_or_say_why(deck):
    if deck in NO_STATICS:
        with pytest.raises((InputError, NoSolutionError), match=NO_STATICS[deck]):
            _solve(deck)
        return
    _, eq = _solve(deck)
    assert np.all(np.isfinite(eq.end_a_tension)) and np.all(np.isfinite(eq.end_b_tension))
    assert np.all(np.isfinite(eq.body_position)) and np.all(np.isfinite(eq.point_position))


def _run_in_time(deck, duration=1.0, time_step=0.01):
    """``system_dynamic`` of the deck, its free bodies released from where the deck puts them (as MoorDyn)."""
    from seacable.system.case import SystemCase
    from seacable.system.dynamics import SystemDynamicAnalysis, run_system_dynamic

    md, system, env = _system(deck, frictionless=False)
    case = SystemCase(name="deck", environment=env, points=system.points, bodies=system.bodies, lines=system.lines,
                      analysis=SystemDynamicAnalysis(duration=duration, time_step=time_step,
                                                     output_interval=duration / 2, start="held"))
    return md, system, _quiet(run_system_dynamic, case)


@pytest.mark.parametrize("deck", sorted(NO_STATICS))
def test_decks_without_a_static_equilibrium_run_in_time(deck):
    if deck in NO_DYNAMICS:
        with pytest.raises((InputError, ConvergenceError), match=NO_DYNAMICS[deck]):
            _run_in_time(deck)
        return
    _, _, ds = _run_in_time(deck)
    assert np.all(np.isfinite(body_pose(ds)))
    assert ds.sizes["time"] == 3


def _moorpy_decks():
    """Decks MoorPy solved (finite tensions: MoorPy returns NaN for BeamSimplySupported's taut beam in air)."""
    return [d for d in DECKS if "lines" in REFERENCE["decks"][d].get("moorpy", {})
            and all(np.isfinite(v) for ln in REFERENCE["decks"][d]["moorpy"]["lines"].values() for v in ln.values())
            and REFERENCE["decks"][d]["moorpy"]["lines"]  # a deck without lines has no tension to compare
            and d not in NO_STATICS and d not in MOORPY_WRONG]


@pytest.mark.parametrize("deck", _moorpy_decks())
def test_statics_agree_with_moorpy(deck):
    ref = REFERENCE["decks"][deck]["moorpy"]
    md, eq = _solve(deck)
    for k, line in enumerate(md.lines):
        expect = ref["lines"][str(line.id)]
        # 1e-4 relative (see the module docstring); 1 N floor for a slack end that carries ~0
        check([eq.end_a_tension[k], eq.end_b_tension[k]], [expect["end_a_tension"], expect["end_b_tension"]],
              rtol=1e-4, atol=1.0, source="MoorPy 1.3.0 (public MoorDyn decks)", unit="N",
              quantity=f"{deck}, line {line.id}: end A and end B tensions (statics)",
              why="both solve exact catenaries; 1 N floor for a slack end that carries about 0")
    for k, position in enumerate(ref["bodies"].values()):
        assert np.allclose(eq.body_position[k][:3], position[:3], atol=1e-3)
        assert np.allclose(eq.body_position[k][3:], position[3:], atol=1e-4)


def _moordyn_decks():
    return [d for d in DECKS if REFERENCE["decks"][d].get("ic_converged")
            and (REFERENCE["decks"][d].get("ic_residual") or 0.0) < 1e-2
            and d not in NO_STATICS and d not in MOORDYN_DIFFERS]


@pytest.mark.parametrize("deck", _moordyn_decks())
def test_statics_agree_with_moordyn(deck):
    ref = REFERENCE["decks"][deck]
    md, eq = _solve(deck)
    for k, line in enumerate(md.lines):
        for end, ours in (("a", eq.end_a_tension[k]), ("b", eq.end_b_tension[k])):
            theirs = float(np.linalg.norm(ref["lines"][str(line.id)][f"end_{end}_force"]))
            check(ours, theirs, rtol=1e-2, source="MoorDyn 2.7.2 (public decks)", unit="N",
                  quantity=f"{deck}, line {line.id}: end {end.upper()} tension (statics)",
                  why="MoorDyn's lumped-mass discretisation of the catenary (module docstring)")
    for k, (name, position) in enumerate(ref["bodies"].items()):
        assert np.allclose(eq.body_position[k][:3], position[:3], atol=1e-2)


def test_a_free_body_deck_hangs_where_the_elastic_line_puts_it():
    """bodyDrag: a free 10 kg body (no volume) starts at the surface on a 4.5 m spring line from an anchor
    5 m down; it sinks below the anchor and hangs. Closed form for a vertical elastic line of wet weight w
    per metre carrying the body's weight W at its lower end: stretch = (W L + w L^2 / 2) / EA."""
    md, eq = _solve("MoorDyn/tests/Mooring/body_tests/bodyDrag.txt")
    lt, g, rho = md.line_types["spring"], md.gravity, md.water_density
    w = (lt.mass_per_length - rho * np.pi * lt.diameter**2 / 4) * g
    weight, length = md.bodies[0].mass * g, md.lines[0].length
    stretch = (weight * length + w * length**2 / 2) / lt.axial_stiffness
    z_anchor = md.points[1].position[2]
    # 1e-9 relative: the catenary of a vertical line is exact and the Newton residual is 1e-8 of 184 N
    assert eq.body_position[0][2] == pytest.approx(z_anchor - length - stretch, rel=1e-9)
    assert max(eq.end_a_tension[0], eq.end_b_tension[0]) == pytest.approx(weight + w * length, rel=1e-9)


def test_a_weight_on_a_neutral_line_hangs_by_its_weight():
    """lifting: a 1000 kg point on a 100.5 m line as dense as the water (7.85398 kg/m, d = 0.1 m, rho = 1000):
    the line carries the point's weight m g at both ends, and stretches by m g L / EA."""
    md, eq = _solve("MoorDyn/tests/Mooring/lifting.txt")
    weight = md.points[1].mass * md.gravity
    # 1e-6: the line's residual wet weight (7.85398 vs 1000 pi 0.1^2 / 4 = 7.853982 kg/m) is 3e-8 of m g
    assert eq.end_a_tension[0] == pytest.approx(weight, rel=1e-6)
    assert eq.end_b_tension[0] == pytest.approx(weight, rel=1e-6)
    stretch = weight * md.lines[0].length / md.line_types["main"].axial_stiffness
    assert eq.point_position[1][2] == pytest.approx(-(md.lines[0].length + stretch), rel=1e-9)


def test_a_coupled_body_carries_the_fairleads_of_the_points_deck():
    """r-test 5MW_OC4 (early MoorDyn-F v2 layout: a coupled body '1coupled' at the origin, the fairleads on it,
    v1 line columns) is the OC4 semi of NRELOffshrBsline5MW_OC4DeepCwindSemi_MoorDyn.dat with vessel points:
    the same end tensions (1e-9: the same catenaries solved twice)."""
    body_md, body = _solve("r-test/modules/moordyn/5MW_OC4/moordyn.dat")
    _, points = _solve("r-test/glue-codes/openfast/5MW_OC4Semi_WSt_WavesWN/NRELOffshrBsline5MW_OC4DeepCwindSemi_MoorDyn.dat")
    assert body_md.bodies[0].attachment == "coupled" and body_md.layout == "v1"
    assert np.allclose(body.end_b_tension, points.end_b_tension, rtol=1e-9)
    assert np.allclose(body.end_a_tension, points.end_a_tension, rtol=1e-9)


def test_chains_with_a_free_end_hang_straight_down():
    """3D_seafloor/hanging_lines: ten 10 m chains from fixed points, each ending at a massless free point: the
    top carries the chain's wet weight w L, the free end nothing, and hangs L + w L^2 / (2 EA) below the top."""
    md, eq = _solve("MoorDyn/tests/Mooring/3D_seafloor/hanging_lines.txt")
    lt, length = md.line_types["chain"], md.lines[0].length
    w = (lt.mass_per_length - md.water_density * np.pi * lt.diameter**2 / 4) * md.gravity
    # 1e-9 relative / 1e-6 N: exact vertical catenaries, Newton residual ~1e-8 of the force scale
    assert np.allclose(eq.end_a_tension, w * length, rtol=1e-9)
    assert np.allclose(eq.end_b_tension, 0.0, atol=1e-6)
    ends = eq.point_position[[eq.point_names.index(f"point{2 * k + 2}") for k in range(10)]]
    assert np.allclose(ends[:, 2], -6.6 - length - w * length**2 / (2 * lt.axial_stiffness), rtol=1e-9)


def test_a_body_with_an_external_load_balances_it():
    """md_BdyExtLdDmpg: a 21244 kg body (no volume) on a 48 m nylon line from a fixed point, pushed by the
    EXTERNAL LOADS force (104170, 50000, -10000) N: the line's pull on the body balances weight and load."""
    md, eq = _solve("r-test/modules/moordyn/md_BdyExtLdDmpg/moordyn.dat")
    body = md.bodies[0]
    load = np.asarray(md.external_loads[0].force) + (0.0, 0.0, -body.mass * md.gravity)
    # the line ends at the body point (end B): 1e-8 of the 2.5e5 N load, the Newton tolerance
    assert np.allclose(eq.end_b_force[0] + load, 0.0, atol=1e-8 * np.linalg.norm(load) * 10)
    assert eq.body_position[0][0] > 0 and eq.body_position[0][1] > 0  # pushed along +x, +y


def test_a_free_rod_hangs_plumb_with_its_spin_held():
    """md_lineFail: a free 10 m rod hangs from a coupled point by a 10 m line at its top end and is pulled
    sideways at its bottom end by chains from both sides. Nothing resists its spin about its own axis (every
    load on the axis): the spin is held and reported, the rod found plumb. The lines' forces on the rod balance
    its wet weight (1e-6 of it: Newton tolerance 1e-8 of the 4e6 N force scale), independently summed here."""
    md, eq = _solve("r-test/modules/moordyn/md_lineFail/moordyn.dat")
    assert len(eq.indeterminate) == 1 and "(0, 0, 1)" in eq.indeterminate[0]
    rod = eq.system.bodies["rod1"]
    wet = (rod.mass - md.water_density * rod.volume) * md.gravity
    fz = 0.0
    for i, name in enumerate(eq.line_names):
        line = eq.system.lines[name]
        for end, f in ((line.end_a, eq.end_a_force[i]), (line.end_b, eq.end_b_force[i])):
            if end.startswith("rod1"):
                fz += f[2]
    assert fz == pytest.approx(wet, rel=1e-6)
    assert abs(eq.body_position[0][3]) < 1e-9 and abs(eq.body_position[0][4]) < 1e-9


def test_a_spring_line_stretches_as_hookes_law_says():
    """MoorDyn's stability/spring(s): a weightless 1 m line of EA = 1 N carrying a 1 kg point (no volume). The
    statics' default strain limit (1) refuses it, naming max_strain; raised, the line stretches by m g / EA =
    9.8 (a warning names 981 %) and carries m g: closed form, 1e-9 (a straight weightless line, exact)."""
    from seacable.errors import ConvergenceError, SeacableWarning
    from seacable.system.statics import solve_equilibrium

    for deck in ("MoorDyn/tests/Mooring/stability/spring.txt", "MoorDyn/tests/Mooring/stability/springs.txt"):
        md = _quiet(read_moordyn, HERE / deck)
        system, env = _quiet(moordyn_system, md)
        with pytest.raises(ConvergenceError, match="max_strain"):
            solve_equilibrium(system, env)
        with pytest.warns(SeacableWarning, match="981 %"):
            eq = solve_equilibrium(system, env, max_strain=MAX_STRAIN)
        weight = md.points[1].mass * md.gravity
        assert eq.end_a_tension[0] == pytest.approx(weight, rel=1e-9)
        stretch = weight * md.lines[0].length / md.line_types["main"].axial_stiffness
        assert eq.point_position[1][2] == pytest.approx(-(md.lines[0].length + stretch), rel=1e-9)


def test_a_pendulum_on_a_stiff_slack_line_swings_down_plumb():
    """seafloor: a 10 kg point starts 10 m aside on a slack 32 m line (EA 1e9 N, as dense as the water to 2e-7)
    from a fixed point: it hangs plumb below it, the line carrying m g. The stiff line pulled round the arc
    grows the residual at any step along the tangent; the statics still get there. 1e-5: the line's residual
    buoyancy, 32 m x 1.6e-5 N/m = 5e-4 N, is 5e-6 of m g."""
    md, eq = _solve("MoorDyn/tests/Mooring/seafloor.txt")
    weight = md.points[1].mass * md.gravity
    assert eq.end_a_tension[0] == pytest.approx(weight, rel=1e-5)
    assert eq.point_position[1][:2] == pytest.approx(md.points[0].position[:2], abs=1e-6)
    stretch = weight * md.lines[0].length / md.line_types["main"].axial_stiffness
    assert eq.point_position[1][2] == pytest.approx(-(md.lines[0].length + stretch), rel=1e-6)


def test_seabed_friction_is_the_decks():
    """WD0050_Chain asks for FrictionCoefficient 0.5: the environment carries it (the comparisons above take
    the frictionless seabed MoorPy and MoorDyn's relaxed start have); with it the anchor tension drops."""
    md, with_friction = _solve("MoorDyn/tests/Mooring/WD0050_Chain.txt", frictionless=False)
    _, without = _solve("MoorDyn/tests/Mooring/WD0050_Chain.txt")
    assert _quiet(moordyn_system, md)[1].seabed.friction == 0.5
    assert with_friction.end_a_tension[0] < 0.9 * without.end_a_tension[0]


@pytest.mark.parametrize("deck", ["MoorPy/tests/case1.dat", "MoorDyn/tests/Mooring/lines_body.txt"])
def test_moordyn_live(deck):
    """The cached numbers are MoorDyn's: run MoorDyn 2.7.2 here and compare to the cache to 1e-6."""
    moordyn = pytest.importorskip("moordyn")
    import importlib.util

    spec = importlib.util.spec_from_file_location("make_reference", HERE / "make_reference.py")
    m = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(m)
    # MoorDyn runs in its own process (make_reference's child) as before; MoorPy, which this test does not
    # read, is left out
    live = m.run(m.HERE / deck, moorpy=False)
    cached = REFERENCE["decks"][deck]
    del moordyn
    for key, line in cached["lines"].items():
        assert np.allclose(live["lines"][key]["end_b_force"], line["end_b_force"], rtol=1e-6)


def test_gravity_off_leaves_straight_lines_stretched_by_hookes_law():
    """g = 0 (MoorDyn's switch): nothing weighs, so every line is straight and carries EA times its strain.
    rotatingBody: a free body at (0, 0, 5) held by six 0.9 m lines to points 1 m away along +-x, +-y, +-z: each
    carries EA (1 / 0.9 - 1), the body stays put (the forces cancel), and line 7 (1.0 m between points 1.0 m apart)
    carries nothing. syrope/linear_wc: one 1 m line between points 1.0148657 m apart, T = EA x 0.0148657 (EA the
    conversion's constant statics EA). Closed forms; 1e-9: straight weightless lines are exact."""
    md, eq = _solve("MoorDyn/tests/Mooring/body_tests/rotatingBody.txt")
    assert md.gravity == 0.0
    ea = md.line_types["nylon"].axial_stiffness
    for k in range(6):
        assert eq.end_a_tension[k] == pytest.approx(ea * (1.0 / 0.9 - 1.0), rel=1e-9)
        assert eq.end_b_tension[k] == pytest.approx(ea * (1.0 / 0.9 - 1.0), rel=1e-9)
    assert eq.end_a_tension[6] == pytest.approx(0.0, abs=1e-9 * ea)
    assert np.allclose(eq.body_position[0][:3], (0.0, 0.0, 5.0), atol=1e-9)
    # in time (released where the deck puts it) nothing moves: the same tensions throughout, 1e-9
    _, _, ds = _run_in_time("MoorDyn/tests/Mooring/body_tests/rotatingBody.txt")
    assert np.allclose(ds["fairlead_tension"].values[:, :6], ea * (1.0 / 0.9 - 1.0), rtol=1e-9)
    assert np.allclose(body_pose(ds)[:, 0, :3], (0.0, 0.0, 5.0), atol=1e-9)

    deck = "MoorDyn/tests/Mooring/syrope/linear_wc/line.txt"
    md, eq = _solve(deck)
    assert md.gravity == 0.0
    ea = eq.system.lines["line1"].line.segments[0].line_type.axial_stiffness
    span = float(np.linalg.norm(np.subtract(md.points[1].position, md.points[0].position)))
    assert eq.end_a_tension[0] == pytest.approx(ea * (span / md.lines[0].length - 1.0), rel=1e-9)
    assert eq.end_b_tension[0] == pytest.approx(eq.end_a_tension[0], rel=1e-12)


def test_buoyancy_off_leaves_the_dry_weight():
    """pinnedBody (WtrDnsty = 0, MoorDyn's switch): its dummy 5 m nylon line hangs between fixed points 5 m apart
    one above the other. With no water the line weighs its dry w = m g per metre (with water 34 % less). Stretched by
    its weight it is longer than the span: the suspended part L_s reaches it, L_s + w L_s^2 / (2 EA) = 5 m, and the
    top carries w L_s more than the bottom (1715.90 N; the rest, 7.8e-4 m, lies slack). Closed form of a vertical
    elastic line; 1e-7 relative (the Newton tolerance on the 1716 N force scale; MoorPy agrees to 1e-9)."""
    md, eq = _solve("MoorDyn/tests/Mooring/body_tests/pinnedBody.txt")
    assert md.water_density == 0.0
    lt = md.line_types["nylon"]
    w, ea, span = lt.mass_per_length * md.gravity, lt.axial_stiffness, 5.0
    q = w / (2 * ea)
    suspended = (math.sqrt(1 + 4 * q * span) - 1) / (2 * q)
    top, bottom = eq.end_a_tension[0], eq.end_b_tension[0]  # end A is point 1 at z = -5, end B point 2 at z = -10
    assert top - bottom == pytest.approx(w * suspended, rel=1e-7)
    assert suspended == pytest.approx(md.lines[0].length - 7.78e-4, abs=1e-6)


def test_a_pinned_buoyant_rod_without_lines_floats_upright():
    """RodPinnedFloating (no lines): a 1 m rod (d 0.25 m, 10 kg/m) pinned at end A, lying horizontal at z = -5,
    lighter than the water it displaces (50.3 kg, WtrDnsity is misspelt in the deck: MoorDyn's default 1025 kg/m^3,
    as seacable's reader): it turns upright about its pin (pitch 0, end B above), its spin about its own axis
    indeterminate (held, reported), and the pin holds its net buoyancy down: (rho V - m) g = 395.35 N. Closed form;
    1e-9 relative on the force, 1e-7 rad on the angle (Newton tolerance)."""
    md, eq = _solve("MoorDyn/tests/Mooring/RodPinnedFloating.txt")
    rod = eq.system.bodies["rod1"]
    assert not md.lines and rod.pinned
    assert abs(eq.body_position[0][3]) < 1e-7 and abs(eq.body_position[0][4]) < 1e-7
    assert eq.pin_reaction[0][2] == pytest.approx(-(md.water_density * rod.volume - rod.mass) * md.gravity, rel=1e-9)
    assert len(eq.indeterminate) == 1


def test_a_rising_rod_accelerates_with_its_added_mass():
    """rod_tests/AddedMass (no lines; MoorDyn's own check of a rod's inertia): a free horizontal rod 2 m long (d 0.5 m,
    100 kg/m, Ca 1, no drag) released 10 m down rises with a = (rho V - m) g / (m + Ca rho V) = 3.296 m/s^2 (MoorDyn's
    comment: it takes ~2.3 s to reach z = -1, sqrt(2 x 9 / a) = 2.34 s). Its z after 0.5 and 1 s is
    z0 + a t^2 / 2: Newmark's average acceleration is exact for a constant acceleration, 1e-9 relative."""
    md, system, ds = _run_in_time("MoorDyn/tests/Mooring/rod_tests/AddedMass.txt")
    rod = system.bodies["rod1"]
    rho, g, ca = md.water_density, md.gravity, md.rod_types["floatRod"].added_mass_normal
    a = (rho * rod.volume - rod.mass) * g / (rod.mass + ca * rho * rod.volume)
    assert a == pytest.approx(3.296, rel=1e-3)
    t = ds["time"].values
    z = ds.body_position.sel(body="rod1", axis="z").values
    assert z == pytest.approx(-10.0 + a * t**2 / 2, rel=1e-9)
    # it rises level: the added mass acts along the rod, about the reference point at its end A
    assert np.allclose(ds.body_rotation.sel(body="rod1", angle="pitch").values, math.pi / 2, atol=1e-9)


def test_shared_mooring_agrees_with_fast_farm_where_its_moordyn_had_settled():
    """SharedMooring2 with its turbines where FAST.Farm.fstf and the ElastoDyn inputs put them (reference.json):
    FAST.Farm's own MoorDyn (v2.3.8, r-test FAST.Farm.FarmMD.MD.out at t = 0, after its 100 s start relaxation)
    gives AnchTen1-4 and FairTen1-5 within 0.03 % of seacable (1 %: MoorDyn's lumped mass, as above). Its FairTen6-7
    (turbine 2's slack downwind lines, 1.129e6 and 1.118e6 N) are still relaxing (-4.5 % over the first 4 s of the
    run) and are not compared; MoorPy agrees with seacable on every line to 1e-4 (test_statics_agree_with_moorpy)."""
    _, eq = _solve("r-test/glue-codes/fast-farm/MD_Shared/SharedMooring2.dat")
    anchor = (2.7112618e6, 2.5198362e6, 2.7155732e6, 3.0376860e6)
    fair = (2.7090642e6, 2.5200678e6, 2.7176622e6, 3.0598970e6, 3.0300605e6)
    assert np.allclose(eq.end_a_tension[:4], anchor, rtol=1e-2)
    assert np.allclose(eq.end_b_tension[:5], fair, rtol=1e-2)


def test_column_names_out_of_moordyn_order_are_warned():
    """Reading every deck: the 18 of HEADER_OUT_OF_ORDER warn about their LINE TYPES column names (and nothing else about
    column order), every other deck reads without a column-order warning."""
    warned = set()
    for deck in DECKS:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            read_moordyn(HERE / deck)
        order = [str(w.message) for w in caught if "not in the order MoorDyn reads" in str(w.message)]
        if order:
            warned.add(deck)
            assert len(order) == 1 and "the LINE TYPES column names" in order[0], (deck, order)
            assert "(Name Diam MassDen EA BA/-zeta EI Cd Ca CdAx CaAx Cl dF cF)" in order[0]
    assert warned == HEADER_OUT_OF_ORDER

"""Write ``DECKS.md``: for each vendored deck, whether seacable reads it, converts it to a mooring system,
solves its statics (admitting a strain up to 20, as MoorDyn has no limit), and how far its line end tensions are from MoorPy's and from MoorDyn's (``reference.json``).
A deck whose statics are refused (a body with no equilibrium: free with no line and no horizontal restoring,
or one that capsizes) is run in time instead (``system_dynamic``, its free bodies released from where the deck
puts them, 1 s at 0.01 s): the column ``dynamics``. Decks on FAST.Farm turbines take the turbine poses
``reference.json`` records for them (``make_reference.TURBINES``).

    PYTHONPATH=src python tests/validation/data/moordyn_decks/deck_table.py

The comparisons take the seabed without friction, as MoorPy and MoorDyn's relaxed start have it (see
``tests/validation/test_moordyn_decks.py``).
"""

from __future__ import annotations

import json
import time
import warnings
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
NOTES = {  # what the table cannot see: the test that checks the deck instead, or why it does not solve
    "MoorDyn/tests/Mooring/lifting.txt": "MoorPy leaves the free point where it starts (0 N); the closed form m g agrees "
                                         "(test_a_weight_on_a_neutral_line_hangs_by_its_weight)",
    "MoorDyn/tests/Mooring/3D_seafloor/hanging_lines.txt": "MoorPy halves the chains' weight; the closed form agrees "
                                                           "(test_chains_with_a_free_end_hang_straight_down)",
    "r-test/modules/moordyn/5MW_OC4/moordyn.dat": "same tensions as the OC4 points deck to 1e-9 "
                                                  "(test_a_coupled_body_carries_the_fairleads_of_the_points_deck)",
    "r-test/modules/moordyn/md_BdyExtLdDmpg/moordyn.dat": "force balance of the body with its external load "
                                                          "(test_a_body_with_an_external_load_balances_it)",
    "MoorDyn/tests/Mooring/RodHanging.txt": "the rod's spin about its own axis is indeterminate (held, reported); "
                                            "closed form (test_a_hanging_rod_is_held_in_spin_and_hangs_as_the_"
                                            "catenary_says)",
    "r-test/modules/moordyn/md_lineFail/moordyn.dat": "the rod's spin held (indeterminate); force balance "
                                                      "(test_a_free_rod_hangs_plumb_with_its_spin_held); MoorDyn's IC "
                                                      "not converged",
    "r-test/modules/moordyn/md_BodiesAndRods/moordyn.dat": "a 1.03e6 kg body without volume, its three lines at one "
                                                           "point 0.22 m below its centre of gravity: no upright "
                                                           "equilibrium (MoorPy: sunk to z = -70 m, lines slack, "
                                                           "rolled 1.7 rad); a dynamic test deck (TmaxIC = 0): runs "
                                                           "in time",
    "r-test/glue-codes/fast-farm/MD_Shared/SharedMooring2.dat": "turbines placed as FAST.Farm.fstf and the ElastoDyn "
                                                                "inputs place them (reference.json); MoorDyn's IC of "
                                                                "that copy does not converge; FAST.Farm's MoorDyn at "
                                                                "t = 0 agrees on lines 1-5 within 0.03 % (its slack "
                                                                "lines 6-7 still relaxing)",
    "MoorDyn/tests/Mooring/body_tests/rotatingBody.txt": "g = 0: six 0.9 m lines stretched to 1 m, T = EA / 9 "
                                                         "(test_gravity_off_leaves_straight_lines_stretched_by_hookes_law)",
    "MoorDyn/tests/Mooring/syrope/linear_wc/line.txt": "g = 0: a straight line, T = EA strain (test_gravity_off_leaves_"
                                                       "straight_lines_stretched_by_hookes_law)",
    "MoorDyn/tests/Mooring/RodPinnedFloating.txt": "no lines: the pinned buoyant rod turns upright "
                                                   "(test_a_pinned_buoyant_rod_without_lines_floats_upright)",
    "MoorDyn/tests/Mooring/rod_tests/AddedMass.txt": "no lines, a rising rod: z(t) with its added mass "
                                                     "(test_a_rising_rod_accelerates_with_its_added_mass)",
    "MoorDyn/tests/Mooring/body_tests/orbitalBody.txt": "g = 0, free bodies with no line: no static equilibrium; in "
                                                        "time body1, a 40 kg point mass 10 m from its reference "
                                                        "point, spins freely (test_a_point_mass_body_orbits_its_"
                                                        "centre_of_gravity)",
    "MoorDyn/tests/Mooring/rotations/nwu.txt": "g = 0, a coupled body alone: its three points where its pose puts "
                                               "them",
    "MoorDyn/tests/Mooring/wave_surface/wave_surface.txt": "lines crossing the surface are split there, dry weight "
                                                           "above; MoorDyn's IC not converged (0.088 m/s^2): its "
                                                           "wholly submerged lines 1-3 are 1.4 % off too",
    "MoorDyn/tests/Mooring/stability/spring.txt": "a 1 N EA spring stretched 9.8 times (max_strain 20): Hooke's law "
                                                  "(test_a_spring_line_stretches_as_hookes_law_says); MoorDyn's IC "
                                                  "diverges, MoorPy divides by w = 0",
    "MoorDyn/tests/Mooring/stability/springs.txt": "as spring.txt (test_a_spring_line_stretches_as_hookes_law_says)",
    "r-test/modules/moordyn/md_viscoelastic/moordyn.dat": "strain 1 (max_strain 20); MoorDyn's static tension "
                                                          "(7.07e7 N) splits the strain between its static and "
                                                          "dynamic springs, MoorPy and seacable take EA_s (1.424e8 N)",
    "MoorDyn/tests/Mooring/BeamSimplySupported.txt": "a taut EI beam in air (z = +10 m): no reference (MoorPy NaN, "
                                                     "MoorDyn's IC not converged); seacable's catenary has no EI",
}
# solved, but the references solved another system: not compared
NO_COMPARISON: set[str] = set()


FOOTER = """
## The line network's statics against MoorPy (issue 37)

The table compares seacable's system statics (exact elastic catenaries). A plain line-and-point deck run as
`seacable run deck` (`mooring_static`) is solved as a lumped-mass network with the deck's NumSegs instead. Four
plain decks differed there from MoorPy by more than 1 %; for each, which code is right:

- r-test MHK_RM1_Floating (`glue-codes/openfast/MHK_RM1_Floating/MHK_RM1_Floating_MoorDyn.dat`, OpenFAST/r-test
  e4f825bd; not vendored here, its line 2 is written out in `test_moordyn_network_statics.py`): the network's
  anchor tension of lines 2 and 5 is 14110 N, MoorPy's 12467 N (+13.2 %; lines 1, 3, 4, 6 -4.2 %). **MoorPy is
  right**: the closed-form elastic catenary on a frictionless seabed (Jonkman 2007, friction 0) gives H =
  12467.19 N at the anchor and 232247.09 N at the fairlead, MoorPy the same to 1e-6, seacable's system statics
  to 1e-9; the network converges to it as its segments are refined (240 segments: 0.18 %). Cause: the chain's
  5.07 m segments are longer than its catenary's radius of curvature at touchdown, H / w = 2.27 m, so the network
  misplaces the touchdown and its H. MoorDyn 2.7.2's own relaxation of the deck does not settle (it stops after 60 s
  with 0.13 m/s^2 left, given TmaxIC 200 s and threshIC 1e-4), so it is no reference here.
- MoorPy/tests/case6.dat: the network's line 3 end A (at the sinker on the seabed, the line lifting off 2.35 m
  from it) is 130031 N, MoorPy's 133288 N (-2.4 %), as line 2's end there: the network's H. **MoorPy is right**
  (the system statics agree with it to 1e-7): 33 m segments against H / w = 29 m. (Line 3's end read 141161 N,
  +5.9 %, before the end force took the half segment's weight off its pull at a grounded end: grounded_end_force.)
- MoorDyn/tests/Mooring/seafloor.txt: **MoorPy is wrong**: it stalls (1999 iterations, its free point left with
  a residual force of -98.07 N, its whole weight), and its tension is wherever it stopped (101.07 N with its g
  = 9.81, 108.85 N with the deck's 9.80665). The network and the system statics give m g = 98.0665 N, the closed
  form of a point hanging on a line as dense as the water (`test_seafloor_pendulum_network_hangs_by_its_weight`,
  `test_a_pendulum_on_a_stiff_slack_line_swings_down_plumb`). The deck's SeafloorFile (a seabed z = -30 + 0.1 x
  that the pendulum was meant to hit) is read by neither code: seacable warns and takes the flat seabed at
  WtrDpth 500 m.

The run of a plain deck now compares every line end of the network with the exact catenaries of the same deck
(`seacable.mooring.moordyn.catenary_check`) and warns, with both tensions, the segment length and H / w, when
they differ by more than 1 %; the largest difference is the result's `catenary_difference` attribute. Of the
vendored plain decks only case6 warns (2.4 %); the next are md_case5 (0.96 %) and the ITI barge (0.93 %), the
rest 0.5 % or less. Not compared: Syrope ropes (exp_wc, linear_wc, quadratic_wc, slow_loading: the network follows
the working curve from SYROPE IC's Tmax) and lines whose bending stiffness matters (bending length sqrt(EI / T)
over 5 % of the line: BeamSimplySupported). stability/springs.txt, tripod.txt and md_viscoelastic do not solve as
a network (they solve as systems; table above).

## Column names out of MoorDyn's order

MoorDyn reads every table row by position and never its column names; seacable reads them the same way and warns
(file and line, section, the names seen and MoorDyn's order) when a name that is one of MoorDyn's columns stands at
another column's place (one check for every table section: line types, rod types, bodies, rods, points, lines,
failures, external loads, Syrope sections; an OPTIONS row written 'name value' is warned too). 18 of the 84 decks
warn, all for their LINE TYPES: MoorDyn v1's coefficient names `Can Cat Cdn Cdt` written over MoorDyn v2's columns
(with EI), which hold `Cd Ca CdAx CaAx` (two, bodyDrag and rotatingBody, with an extra `tbd` name before them):
body_tests/bodyDrag, pinnedBody, rotatingBody, local_euler/complex_system, riser/riser, syrope/exp_wc/line,
syrope/linear_wc/line, syrope/quadratic_wc/line, syrope/slow_loading, and r-test modules/moordyn 5MW_OC4,
5MW_OC4_simple, md_BdyExtLdDmpg, md_BodiesAndRods, md_bodyDrag, md_float, md_horizontal, md_no_line, md_vertical
(`HEADER_OUT_OF_ORDER` in test_moordyn_decks.py). Every other deck reads without a column-order warning.
"""


def turbine_positions(entry: dict) -> dict | None:
    """The turbine poses ``reference.json`` records for a deck on FAST.Farm turbines (None for others)."""
    poses = entry.get("turbine_positions")
    return None if poses is None else {int(n): tuple(v) for n, v in poses.items()}


def run_in_time(system, env, duration=1.0, time_step=0.01):
    """``system_dynamic`` of the deck's system for ``duration`` [s], free bodies released where the deck puts them."""
    from seacable.system.case import SystemCase
    from seacable.system.dynamics import SystemDynamicAnalysis, run_system_dynamic

    case = SystemCase(name="deck", environment=env, points=system.points, bodies=system.bodies, lines=system.lines,
                      analysis=SystemDynamicAnalysis(duration=duration, time_step=time_step,
                                                     output_interval=duration / 2, start="held"))
    return run_system_dynamic(case)


def main():
    from seacable.errors import InputError, NoSolutionError
    from seacable.io.moordyn import is_moordyn_file, moordyn_system, read_moordyn
    from seacable.system.run import check_bodies_without_lines
    from seacable.system.statics import solve_equilibrium

    ref = json.loads((HERE / "reference.json").read_text())
    rows = ["| deck | read | system | statics | dynamics | vs MoorPy | vs MoorDyn | note |",
            "|---|---|---|---|---|---|---|---|"]
    counts = dict(decks=0, read=0, system=0, statics=0, dynamics=0, moorpy=0, moordyn=0, agree=0)
    for path in sorted(p for p in HERE.rglob("*") if p.suffix in (".txt", ".dat") and "LICENSES" not in p.parts
                       and is_moordyn_file(p)):
        rel = path.relative_to(HERE).as_posix()
        r = ref["decks"].get(rel, {})
        counts["decks"] += 1
        cells, note = ["", "", "", "", ""], ""
        dynamics = ""
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            system = env = None
            try:
                md = read_moordyn(path)
                cells[0] = "yes"
                counts["read"] += 1
                system, env = moordyn_system(md, turbine_positions=turbine_positions(r))
                cells[1] = "yes"
                counts["system"] += 1
                env = env.model_copy(update={"seabed": env.seabed.model_copy(update={"friction": 0.0})})
                t0 = time.time()
                check_bodies_without_lines(system)  # as system_static: a free body nothing holds has no equilibrium
                eq = solve_equilibrium(system, env, max_strain=20.0)  # MoorDyn has no strain limit
                cells[2] = f"yes ({time.time() - t0:.2f} s)"
                counts["statics"] += 1
            except Exception as exc:  # noqa: BLE001 - the table records why
                cells[sum(1 for c in cells if c)] = "no"
                note = str(exc).split(": ", 1)[-1][:140].replace("|", "/")
                eq = None
                if system is not None and isinstance(exc, (InputError, NoSolutionError)):
                    try:
                        t0 = time.time()
                        run_in_time(system, env)
                        dynamics = f"yes ({time.time() - t0:.2f} s)"
                        counts["dynamics"] += 1
                    except Exception as dyn:  # noqa: BLE001
                        dynamics = "no"
                        note += " / dynamics: " + str(dyn)[:120].replace("|", "/")
        cells.insert(3, dynamics)
        agree = []
        if eq is not None and rel in NO_COMPARISON:
            cells[4] = cells[5] = "-"
        elif eq is not None:
            mp = r.get("moorpy", {})
            finite = "lines" in mp and all(np.isfinite(v) for ln in mp["lines"].values() for v in ln.values())
            if "lines" in mp and not finite:
                cells[4] = "NaN (MoorPy)"
            elif "lines" in mp:
                d = [abs(ours - mp["lines"][str(ln.id)][f"end_{e}_tension"]) /
                     max(abs(mp["lines"][str(ln.id)][f"end_{e}_tension"]), 1.0)
                     for k, ln in enumerate(md.lines) for e, ours in (("a", eq.end_a_tension[k]), ("b", eq.end_b_tension[k]))]
                cells[4] = f"{max(d) * 100:.4f} %" if d else "- (no lines)"
                if d:
                    counts["moorpy"] += 1
                    agree.append(max(d) <= 0.01)
            else:
                cells[4] = "-"
                note = note or ("MoorPy: " + mp.get("error", "no result")[-90:]).replace("|", "/")
            if r.get("ic_converged") and r.get("lines"):
                d = [abs(ours - np.linalg.norm(r["lines"][str(ln.id)][f"end_{e}_force"])) /
                     np.linalg.norm(r["lines"][str(ln.id)][f"end_{e}_force"])
                     for k, ln in enumerate(md.lines) for e, ours in (("a", eq.end_a_tension[k]), ("b", eq.end_b_tension[k]))
                     if np.linalg.norm(r["lines"][str(ln.id)][f"end_{e}_force"]) > 0]
                cells[5] = f"{max(d) * 100:.3f} % (IC residual {r.get('ic_residual')})"
                counts["moordyn"] += 1
                agree.append(max(d) <= 0.01)
            else:
                cells[5] = "-" if "error" not in r else "MoorDyn refuses it"
        if agree and any(agree):
            counts["agree"] += 1
        if rel in NOTES:
            note = NOTES[rel] + (f"; {note}" if note and rel not in NOTES else "")
        rows.append(f"| {rel} | " + " | ".join(cells) + f" | {note} |")
    summary = (f"{counts['decks']} decks: {counts['read']} read, {counts['system']} convert to a mooring system, "
               f"{counts['statics']} solve their statics and the {counts['dynamics']} others with no static equilibrium "
               f"run in time; compared with MoorPy {counts['moorpy']}, with a converged MoorDyn "
               f"{counts['moordyn']}; within 1 % of at least one of them: {counts['agree']}.")
    (HERE / "DECKS.md").write_text("# The vendored MoorDyn decks in seacable\n\nWritten by `deck_table.py`. "
                                   + summary + "\n\n" + "\n".join(rows) + "\n" + FOOTER)
    print(summary)


if __name__ == "__main__":
    main()

"""Speed of the mooring-system statics (equilibrium + coupled stiffness) against MoorPy 1.3.0.

Run: ``python bench/bench_system.py [repeats]``. On the three reference systems of
``seacable.system.statics.examples`` (OC3-Hywind spar, OC4-DeepCwind semi, a buoy on lines with
clumps, floats and a junction point), each under a constant external load, times

* seacable: ``solve_equilibrium`` (which returns the analytic coupled stiffness with it), from the
  system as given;
* MoorPy: ``System.solveEquilibrium(tol=1e-7)`` then ``System.getCoupledStiffness(lines_only=True)``
  (its finite-difference coupled stiffness, the call the issue names), and also with
  ``getCoupledStiffnessA`` (analytic) for reference.

Both start from the undisplaced system, except MoorPy on the buoy: from there its solver does
not converge (499 iterations), so it starts from seacable's solution moved 0.1 m in x and y
(which favours MoorPy). The first call of each is a warm-up and is excluded; the figure is the
best of ``repeats`` (default 7) timed with ``time.perf_counter``. The bodies' positions agree
to 1e-6 relative (checked).

Measured (2-core shared machine, 2026-11-24, MoorPy 1.3.0, best of 7, warm-up excluded; MoorPy's
figure is the lowest of three runs that day, the machine being shared; "before" is commit e7dbd95,
before the per-iteration overhead was cut: compiled node positions, trial steps, step limits,
assembly and Newton solve, constants kept with the cached assembly, fewer catenary fallbacks):

=========================  ===========  ============  ==============  =====  =============  =====
system                     before       seacable      MoorPy FD       ratio  MoorPy A       ratio
=========================  ===========  ============  ==============  =====  =============  =====
OC3-Hywind spar            1.19 ms      0.43 ms       45 ms           105    24 ms          56
OC4-DeepCwind semi         1.27 ms      0.46 ms       27 ms           59     9.1 ms         20
buoy, clumps and floats    6.24 ms      1.7-2.0 ms    3500-5300 ms    >1700  40 ms          20
=========================  ===========  ============  ==============  =====  =============  =====

Same iterations (5, 6, 19) and the same equilibria as before (the validation suites unchanged).

The same systems through ``seacable.run`` (issue 38): each as a ``system_static`` case (its load the body's
``external_force``), the whole call timed (checks, solve, profiles and the result Dataset with its
attributes), best of ``repeats`` after a warm-up on the same case object. Printed: ``run`` against
``solve_equilibrium`` alone (target: at most 2), and MoorPy's solveEquilibrium + getCoupledStiffness against
``run`` (target: at least 30). A case run again is stamped with the YAML dumped the first time (the case is
immutable); ``first run`` is the call on a fresh copy of the case, its YAML dumped too.

Measured through ``run`` (2-core machine shared with three other jobs, load average 6-8, 2026-11-29, best of 15;
MoorPy's figures that day were 3-4 times its quiet ones above, so its ratios are inflated alike). "before" is
commit ede2d76; "after" builds the Dataset directly (``seacable.results.dataset``: no merge nor alignment, the
default indexes of the names kept; identical Datasets), hands the start ``check_statics`` evaluated to the first
solve instead of building the problem and evaluating it twice, builds each condition's system once per case
(the damaged ones of ``most_loaded`` too) and takes the variables made for the Dataset without copies:

=========================  ==========  ====================  ====================  =================================
system                     solve [ms]  run [ms] before/after  run/solve bef./aft.  first run [ms] before/after
=========================  ==========  ====================  ====================  =================================
OC3-Hywind spar            0.87        10.0 / 2.43           11.6 / 2.77           12.6 / 5.1
OC4-DeepCwind semi         0.98        6.4 / 3.11            6.5 / 3.2             13.0 / 5.8
buoy, clumps and floats    3.7-4.9     34.5 / 9.4            7.1 / 2.6             37.1 / 33.8
=========================  ==========  ====================  ====================  =================================

MoorPy FD / run the same day: OC3 15.4 before, 73 after; OC4 15.4 before, 30 after (against MoorPy's quiet
45 ms and 27 ms: about 18 and 9). Again later that day: run 2.75, 2.84, 6.8 ms (run/solve 3.2, 2.8, 2.1),
MoorPy FD / run 42 and 43 (MoorPy 115 and 122 ms that hour). What is left of a run around its solve (OC3, about 1.5 ms): the line profiles
(``SystemEquilibrium.line_profile``, 0.5 ms: a few dozen small NumPy calls per sub-line), the checks at the start
(0.2 ms), the result's variables and Dataset (0.35 ms).

Then (2026-11-30, shared machine, MoorPy 2-3 times its quiet figures that hour): the line profiles compiled
(``closed_form_profile``, the same bits; 2.4x faster), the start's stability checked once, and this bench freeing
MoorPy's systems before timing ``run`` (kept alive, they made every garbage collection during the runs slower:
run/solve read 3.7 with them). run / solve, two runs of ``python bench/bench_system.py 15``: OC3 1.93 and 1.97,
OC4 2.23 and 3.12, buoy 1.43 and 1.39; MoorPy FD / run: OC3 43 and 37, OC4 29 and 14. Alternating solve and run
400 times in one process (the best of each): OC3 2.01, OC4 1.96.

Then (2026-11-30, later; shared machine): every line's profile in one compiled call
(``SystemEquilibrium.line_profiles``), the result's variables built without xarray's argument checks (``var``: their
four fields, checked against the constructor at import), the Dataset's sizes taken from ``dataset``'s own walk of the
variables, the equilibrium's variables filled by blocks, and the coordinates and the lines' breaking loads made once
per case (copied into each result); the Datasets identical to the bit (every variable's bytes, attributes, encoding
and index; the system examples' fingerprints). run / solve, thread CPU time, ``solve_equilibrium`` and ``run``
alternated 400 times in one process, the median of each; four processes each, alternating the source before (commit
accdbef) and after: OC3 1.97-2.12 before, 1.57-1.65 after; OC4 1.92-2.08 before, 1.54-1.57 after.
Two runs of ``python bench/bench_system.py 15`` after (best of each, so noisier): run / solve OC3 1.53 and 1.86, OC4
1.68 and 1.85, buoy 2.17 and 1.24; MoorPy FD / run OC3 52 and 51, OC4 30 and 29 (MoorPy 76-82 and 49-51 ms that hour:
against its quiet 45 and 27 ms, about 30 and 17). What is left
around the solve (OC4, about 0.35 ms on a quiet machine): the result's ~50 variables and the Dataset (0.15 ms), the
profiles' own arithmetic (0.03 ms: 2n + 2 points per sub-line, interpolated), the equilibrium's variables (0.05 ms),
the coordinates' copies (0.04 ms), the checks around the start's evaluation (0.02 ms). The profiles' kernel costs
about 8 CPU-s to compile from an empty cache (its closed forms and the tabled ones, 1.7 and 2.5 s of it, 1.5 s
before for the closed forms alone).
"""

from __future__ import annotations

import gc
import sys
import time

import numpy as np

import seacable as sc
from seacable.system.case import SystemCase, SystemStaticAnalysis
from seacable.system.statics import examples as ex
from seacable.system.statics import solve_equilibrium

CASES = {
    "OC3-Hywind spar": (ex.oc3_hywind, (8e5, 1e5, -2e5, 1e6, -5e6, 2e6)),
    "OC4-DeepCwind semi": (ex.oc4_semi, (1.5e6, -3e5, 0.0, 0.0, 2e7, -5e6)),
    "buoy, clumps and floats": (ex.moored_buoy, (2e4, 1e4, 0.0, 0.0, 0.0, 0.0)),
}


def _best(fn, repeats):
    fn()                                   # warm-up, excluded
    best = np.inf
    out = None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def as_case(label, system, env, load) -> SystemCase:
    """The system as a ``system_static`` case, ``load`` [N, N m] on its body (its ``external_force``)."""
    name = next(iter(system.bodies))
    bodies = {**system.bodies, name: system.bodies[name].replace(external_force=tuple(load))}
    return SystemCase(name=label.split()[0].lower(), environment=env.model_dump(), points=system.points,
                      bodies=bodies, lines=system.lines, analysis=SystemStaticAnalysis())


def main(repeats: int = 7):
    try:
        import moorpy
    except ImportError:  # pragma: no cover - bench-only dependency
        moorpy = None
    print(f"{'system':26s} {'seacable [ms]':>14s} {'MoorPy FD [ms]':>15s} {'ratio':>7s} "
          f"{'MoorPy A [ms]':>14s} {'ratio':>7s} {'iters':>6s}")
    rows = []
    for label, (build, load) in CASES.items():
        system, env = build()
        body = next(iter(system.bodies))
        ext = {body: np.array(load)}
        t_ours, eq = _best(lambda s=system, e=env, x=ext: solve_equilibrium(s, e, external=x), repeats)
        t_fd = t_a = np.nan
        if moorpy is not None:
            start = eq if build is ex.moored_buoy else None

            def run(analytic, start=start, system=system, env=env, ext=ext):
                ms, _ = ex.to_moorpy(system, env, external=ext, start=start, shift=0.1 if start else 0.0)
                t0 = time.perf_counter()       # building the MoorPy model is not timed
                ms.solveEquilibrium(tol=1e-7, maxIter=500)
                ms.bodyList[0].type = -1
                K = ms.getCoupledStiffnessA(lines_only=True) if analytic else ms.getCoupledStiffness(
                    lines_only=True)
                return time.perf_counter() - t0, ms, K

            run(False)                         # warm-up
            runs = [run(False) for _ in range(max(2, repeats // 2))]
            t_fd = min(r[0] for r in runs)
            t_a = min(run(True)[0] for _ in range(max(2, repeats // 2)))
            r6 = runs[0][1].bodyList[0].r6
            dev = np.abs(eq.body_position[0][:3] - r6[:3]).max() / np.abs(eq.body_position[0][:3]).max()
            assert dev < 1e-6, f"{label}: MoorPy and seacable disagree ({dev:.2g})"
            del runs   # MoorPy's systems, kept alive, made every garbage collection during the runs below slower
            gc.collect()
        print(f"{label:26s} {1e3 * t_ours:14.2f} {1e3 * t_fd:15.2f} {t_fd / t_ours:7.1f} "
              f"{1e3 * t_a:14.2f} {t_a / t_ours:7.1f} {eq.iterations:6d}")
        case = as_case(label, system, env, load)
        t_run, ds = _best(lambda c=case: sc.run(c), repeats)
        dev = np.abs(ds["body_x"].values[0, 0] - eq.body_position[0][0])
        assert dev < 1e-6 * max(1.0, abs(eq.body_position[0][0])), f"{label}: run and solve_equilibrium disagree"
        t_first = np.inf
        for fresh in [case.model_copy(deep=True) for _ in range(repeats)]:  # copies made outside the timing
            t0 = time.perf_counter()
            sc.run(fresh)
            t_first = min(t_first, time.perf_counter() - t0)
        rows.append((label, t_ours, t_run, t_first, t_fd))
    print("\nthrough seacable.run (a system_static case, result Dataset included; targets: run / solve <= 2, "
          "MoorPy FD / run >= 30)")
    print(f"{'system':26s} {'solve [ms]':>11s} {'run [ms]':>9s} {'run/solve':>10s} {'first run [ms]':>15s} "
          f"{'MoorPy FD [ms]':>15s} {'MoorPy/run':>11s}")
    for label, t_ours, t_run, t_first, t_fd in rows:
        print(f"{label:26s} {1e3 * t_ours:11.2f} {1e3 * t_run:9.2f} {t_run / t_ours:10.2f} {1e3 * t_first:15.2f} "
              f"{1e3 * t_fd:15.2f} {t_fd / t_run:11.1f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 7)

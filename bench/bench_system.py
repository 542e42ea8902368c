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
"""

from __future__ import annotations

import sys
import time

import numpy as np

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


def main(repeats: int = 7):
    try:
        import moorpy
    except ImportError:  # pragma: no cover - bench-only dependency
        moorpy = None
    print(f"{'system':26s} {'seacable [ms]':>14s} {'MoorPy FD [ms]':>15s} {'ratio':>7s} "
          f"{'MoorPy A [ms]':>14s} {'ratio':>7s} {'iters':>6s}")
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
        print(f"{label:26s} {1e3 * t_ours:14.2f} {1e3 * t_fd:15.2f} {t_fd / t_ours:7.1f} "
              f"{1e3 * t_a:14.2f} {t_a / t_ours:7.1f} {eq.iterations:6d}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 7)

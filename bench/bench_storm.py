"""A storm of a 3-line spread driven by RAOs (issue 20's speed target): wall time and simulated-to-wall ratio.

The case: examples/oc3_hywind_storm.yaml, the OC3-Hywind spar's three lines (40 elements each, axial damping
80 % of critical as in MoorDyn's OC3 input) driven at the fairleads by the spar's RAOs in a JONSWAP sea (Hs
10 m, Tp 14 s, 200 components), dt = 0.1 s, an output every 0.5 s, run through the user path (``seacable.run``: case file, statics, the sea's kinematics grid, the
compiled time loop, the result). Printed per run: the wall time, the simulated-to-wall ratio, and the share
of the wall time the sea's kinematics grid and the time loop take. The issue's target: 3 h in at most 10 s
on one core.

Run: ``python bench/bench_storm.py [duration_s ...]`` (default 600 and 10800 s; a first run after an install
compiles the kernels, about a minute: run twice).
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS", "NUMBA_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # one core, as the target says (set before numpy and numba load)

import sys
import time
from pathlib import Path

import seacable as sc
import seacable.mooring.solver as S
import seacable.seastate as SS

CASE = Path(__file__).parents[1] / "examples" / "oc3_hywind_storm.yaml"


def timed(fn, box):
    def wrapper(*args, **kwargs):
        t0 = time.perf_counter()
        try:
            return fn(*args, **kwargs)
        finally:
            box[0] += time.perf_counter() - t0
    return wrapper


def main(durations):
    grid, loop = [0.0], [0.0]
    SS.SeaGrid.__init__ = timed(SS.SeaGrid.__init__, grid)
    SS.SeaGrid.window = timed(SS.SeaGrid.window, grid)
    S.simulate = timed(S.simulate, loop)
    import seacable.system.dynamics.loop as D

    D.simulate_lines = S.simulate
    print(f"{'simulated [s]':>14} {'wall [s]':>9} {'sim/wall':>9} {'sea grid [s]':>13} {'time loop [s]':>14}")
    for duration in durations:
        case = sc.load_case(CASE)
        case = case.model_copy(update={"analysis": case.analysis.model_copy(update={"duration": duration})})
        grid[0] = loop[0] = 0.0
        t0 = time.perf_counter()
        sc.run(case)
        wall = time.perf_counter() - t0
        print(f"{duration:14.0f} {wall:9.2f} {duration / wall:9.1f} {grid[0]:13.2f} {loop[0] - grid[0]:14.2f}",
              flush=True)


if __name__ == "__main__":
    main([float(a) for a in sys.argv[1:]] or [600.0, 10800.0])

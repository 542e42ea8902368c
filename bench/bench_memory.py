"""Memory and wall time of a long mooring run: three 40-element lines, 3 hours, output every 0.1 s (issue 19).

The case: a three-line spread of MoorDyn's WD0200 chain (760 m of 390 kg/m studless chain in 200 m of water,
anchors 700 m from their fairleads at 120 degrees), each line cut into 40 segments, the three fairleads
moved together in heave (2 m at 10 s), 3 h at dt = 0.1 s with the state stored every 0.1 s (108 001
outputs), read and run through the user path (``run_moordyn_case``: file, model, statics, time loop,
Dataset).

Printed: the peak resident memory of the process (``resource.getrusage``: the operating system's own
accounting, the largest the process ever held, Python and numba included), the memory the loop's stored
results take (positions, tensions, support forces, the end nodes' kinematics), the Dataset's, and the wall
times. The issue's target: the run fits in 1 GB.

Run: ``python bench/bench_memory.py [hours]`` (default 3; about a minute on one core).
"""

from __future__ import annotations

import resource
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

from seacable.io.moordyn import load_moordyn_case
from seacable.mooring.moordyn import run_moordyn_case
from seacable.mooring.motion import HarmonicMotion

# three 40-segment chains to a platform, the deck of tests/unit/test_mooring_time_loop.py
DECK = (Path(__file__).parents[1] / "tests" / "validation" / "data" / "three_chains_deck.txt").read_text()


def main(hours: float = 3.0) -> dict:
    path = Path(tempfile.mkdtemp(prefix="bench_memory_")) / "three_chains.txt"
    path.write_text(DECK)
    duration = 3600.0 * hours
    case = load_moordyn_case(path).with_run(duration=duration, time_step=0.1, output_interval=0.1,
                                            motion=HarmonicMotion(amplitude=(0.0, 0.0, 2.0), period=10.0))
    start = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the deck's MoorDyn-only options
        ds = run_moordyn_case(case)
    wall = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024  # kB on Linux
    out = {"hours": hours, "outputs": int(ds.sizes["time"]), "nodes": int(ds.sizes["node"]) * int(ds.sizes["line"]),
           "dataset_bytes": int(ds.nbytes), "peak_rss_bytes": int(peak), "wall": wall,
           "fairlead_tension_max": float(np.nanmax(ds["fairlead_tension"]))}
    print(f"three 40-segment lines, {hours:g} h at dt 0.1 s, output every 0.1 s: {out['outputs']} outputs")
    print(f"  wall {wall:.1f} s (file, statics, time loop and Dataset); simulated / wall {duration / wall:.0f}")
    print(f"  Dataset {out['dataset_bytes'] / 1e9:.3f} GB; peak resident memory of the process "
          f"{peak / 1e9:.3f} GB (target: 1 GB)")
    return out


if __name__ == "__main__":
    main(float(sys.argv[1]) if len(sys.argv) > 1 else 3.0)

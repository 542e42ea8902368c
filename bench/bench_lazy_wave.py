"""The 80 m lazy-wave power cable's static shape: seacable against CableDyn 0.3.0, time and accuracy.

The case is ``examples/lazy_wave_80m.yaml`` (Lozon et al. 2025, Gulf of Mexico 80 m; CableDyn's example deck
``lozon_gomex80_power_cable.dat`` with the same numbers). Each code solves the static equilibrium from its own
start: seacable ``sc.run(case)`` whole (the case, the network on its multi-segment catenary start with the buoyant
segments, Newton, the Dataset), at 1, 0.5, 0.25 and 0.125 m elements, warm (numba compiled once before); CableDyn
its driver process (``tests/validation/_cabledyn_peer.py``: deck written from the case, driver started, deck
parsed, EI continuation, output files) on its example's 1024 elements (0.15-0.20 m) and on half of them. Accuracy:
each code's peak curvature against seacable's Richardson-extrapolated value from the three finest meshes.

Measured (medians of 3 on the shared 2-core machine, loaded by other jobs; each code's nodal peak curvature against
seacable's converged 0.0968296 1/m): seacable 1 m elements 0.068 s, -0.047 %; 0.5 m 0.16 s, -0.013 %, hang-off
9320.14 N; 0.25 m 0.30 s, -0.004 %; CableDyn 512 elements 2.0 s and 1024 elements 4.1 s, -0.0004 % on both,
9320.17 N (on the quiet machine, once: seacable 0.5 m 0.07 s, CableDyn 1024 elements 0.65 s). At the issue's 0.5 %
on the peak curvature seacable's 1 m mesh is 30x faster than CableDyn's 512 elements.

Run: ``python bench/bench_lazy_wave.py [repeat]`` (needs ``pip install cabledyn``; in the ``bench`` extras).
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parents[1] / "tests" / "validation"))

import _cabledyn_peer as peer
import test_cabledyn_lazy_wave as shapes

import seacable as sc


def main(repeat: int = 3) -> None:
    case = sc.load_case(peer.CASE)
    sizes = (1.0, 0.5, 0.25, 0.125)
    runs = {h: case.model_copy(update={"analysis": case.analysis.model_copy(update={"element_length": h})})
            for h in sizes}
    sc.run(runs[1.0])  # compile
    kappa, walls, tension = {}, {}, {}
    for h, c in runs.items():
        times = []
        for _ in range(repeat):
            t = time.perf_counter()
            ds = sc.run(c)
            times.append(time.perf_counter() - t)
        walls[h], kappa[h], tension[h] = statistics.median(times), shapes._shape(ds)[0], float(ds.fairlead_tension)
    k1, k2, k3 = kappa[0.5], kappa[0.25], kappa[0.125]
    converged = k3 + (k3 - k2) ** 2 / ((k2 - k1) - (k3 - k2))  # Aitken's extrapolation
    print(f"converged peak curvature (seacable, Aitken on 0.5/0.25/0.125 m): {converged:.7f} 1/m")
    for h in sizes:
        print(f"seacable {h:5.3f} m: {walls[h]:.3f} s  kappa {kappa[h]:.7f} ({100 * (kappa[h] / converged - 1):+.4f} %)"
              f"  hang-off {tension[h]:.3f} N")
    if peer.driver() is None:
        print("CableDyn: not installed (pip install cabledyn)")
        return
    for segs in ((448, 320, 256), (224, 160, 128)):
        times = []
        for _ in range(repeat):
            with tempfile.TemporaryDirectory() as folder:
                got = peer.run_cabledyn(case, folder, num_segs=segs)
            times.append(got["wall"])
        print(f"CableDyn {sum(segs)} elements: {statistics.median(times):.3f} s  kappa {got['curvature']:.7f} "
              f"({100 * (got['curvature'] / converged - 1):+.4f} %)  hang-off {got['tension']:.3f} N")


if __name__ == "__main__":
    main(*(int(a) for a in sys.argv[1:]))

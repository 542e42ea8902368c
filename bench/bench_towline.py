"""Real-time factor of the towline model (paper 003) on its zig-zag case, 11 and 100 elements.

Paper 003's point is that the multibody towline needs no iteration and can run inside a ship-handling
simulator; the issue's target is at least 100 times faster than real time with 100 elements. The
explicit step follows from the elements' stability bound (``seacable.towline.stable_time_step``),
so it shrinks as the elements get shorter: dt ~ sqrt(m / k) ~ 1 / n.

Run: ``python bench/bench_towline.py [duration_s]`` (default 300 s simulated; best of 3, after a
warm-up run that compiles the kernel).
"""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path

import yaml

import seacable as sc

CASE = Path(__file__).parents[1] / "examples" / "paper003_zigzag.yaml"


def main(duration: float = 300.0) -> None:
    data = yaml.safe_load(CASE.read_text())
    print(f"paper 003 zig-zag (2 knots, 10 m, 50 s), {duration:g} s simulated, best of 3")
    print(f"{'elements':>8} {'dt [s]':>10} {'steps':>8} {'wall [s]':>9} {'real-time factor':>17} "
          f"{'ns / element-step':>18}")
    for n in (11, 100):
        data["analysis"].update(n_elements=n, duration=duration, output_interval=1.0)
        case = sc.parse_case(data)
        warm = dict(data)
        warm["analysis"] = {**data["analysis"], "duration": 2.0}
        sc.run(sc.parse_case(warm))
        best = None
        for _ in range(3):
            start = time.perf_counter()
            ds = sc.run(case)
            wall = time.perf_counter() - start
            best = wall if best is None else min(best, wall)
        settings = json.loads(ds.attrs["settings"])
        dt, steps = settings["time_step"], settings["steps"]
        print(f"{n:8d} {dt:10.3e} {steps:8d} {best:9.3f} {duration / best:17.1f} "
              f"{best / max(steps, 1) / n * 1e9:18.1f}")


if __name__ == "__main__":
    main(float(sys.argv[1]) if len(sys.argv) > 1 else 300.0)

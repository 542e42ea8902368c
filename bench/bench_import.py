"""Start-up time of ``import seacable`` and of the light commands, against ``import numpy`` (issue 38).

Each command runs in a fresh interpreter, once to warm up (the file cache, and numba's cache of the
kernels that ``validate`` of a mooring system solves with: after a source change the warm-up compiles
them), then ``N`` times; the table gives the median and the fastest wall time and the median CPU time
(user + system of the child) of the counted runs, with the issue's target:

- ``import seacable`` at most 0.5 s more than ``import numpy``;
- ``seacable --help`` and ``seacable validate`` of a small case under 1 s (a mooring system, whose check solves
  its lines' catenaries with compiled kernels; paper 002's vertical cable, whose exact solution needs SciPy's
  root finder; a single-line static case; a finite-element pushover, whose check solves with compiled kernels).

The machine's load average is printed first: on a busy machine every figure is slower, the differences
less so. ``--src PATH`` times another checkout's ``src`` folder (e.g. one before a change).

Run: ``python bench/bench_import.py [-n N] [--src PATH]``.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PY = sys.executable
EXAMPLES = ROOT / "examples"

#: label, command, target: ("numpy", extra seconds) against import numpy's median, or ("abs", seconds)
COMMANDS = [
    ("python -c pass", [PY, "-c", "pass"], None),
    ("import numpy", [PY, "-c", "import numpy"], None),
    ("import seacable", [PY, "-c", "import seacable"], ("numpy", 0.5)),
    ("seacable --help", [PY, "-m", "seacable", "--help"], ("abs", 1.0)),
    ("seacable validate spread_mooring.yaml", [PY, "-m", "seacable", "validate",
                                               str(EXAMPLES / "spread_mooring.yaml")], ("abs", 1.0)),
    ("seacable validate paper002_vertical_cable.yaml", [PY, "-m", "seacable", "validate",
                                                        str(EXAMPLES / "paper002_vertical_cable.yaml")], ("abs", 1.0)),
    ("seacable validate oc3_hywind_static.yaml", [PY, "-m", "seacable", "validate",
                                                  str(EXAMPLES / "oc3_hywind_static.yaml")], ("abs", 1.0)),
    ("seacable validate paper004_lena_pushover.yaml", [PY, "-m", "seacable", "validate",
                                                       str(EXAMPLES / "paper004_lena_pushover.yaml")], ("abs", 1.0)),
]


def _time(command: list[str], env: dict) -> tuple[float, float, int]:
    """Wall and CPU seconds (user + system of the child) of one run, and its exit code."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    code = subprocess.run(command, env=env, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                          check=False).returncode
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, code


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-n", type=int, default=7, help="counted runs of each command (default 7)")
    parser.add_argument("--src", type=Path, default=ROOT / "src", help="the src folder to time (default: this one)")
    args = parser.parse_args(argv)
    env = {**os.environ, "PYTHONPATH": str(args.src.resolve())}
    print(f"{args.src.resolve()}, {os.cpu_count()} CPUs, load average (1 min) {os.getloadavg()[0]:.2f}, "
          f"median of {args.n} runs after 1 warm-up")
    print(f"{'command':<48} {'wall [s]':>9} {'fastest':>8} {'cpu [s]':>8} {'target [s]':>11} {'met':>4}")
    medians: dict[str, float] = {}
    for label, command, target in COMMANDS:
        _time(command, env)  # warm-up
        runs = [_time(command, env) for _ in range(args.n)]
        walls, cpus, codes = zip(*runs)
        wall = statistics.median(walls)
        medians[label] = wall
        bound = None if target is None else (target[1] + medians["import numpy"] if target[0] == "numpy"
                                             else target[1])
        met = "" if bound is None else ("yes" if wall <= bound else "no")
        failed = "" if set(codes) == {0} else f"  (exit {sorted(set(codes))})"
        print(f"{label:<48} {wall:9.3f} {min(walls):8.3f} {statistics.median(cpus):8.3f} "
              f"{'' if bound is None else f'{bound:.3f}':>11} {met:>4}{failed}")


if __name__ == "__main__":
    main()

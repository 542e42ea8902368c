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

The runs keep their compiled bytecode (``PYTHONDONTWRITEBYTECODE`` is dropped from their environment): without it
every run compiles every module again, about 0.35 s of CPU that an installed package does not spend.

Measured (2-core machine shared with three other jobs, load average 8-9, 2026-11-29, median of 5; "before" is
commit ede2d76, "after" the port of Brent's method into :mod:`seacable.modal.vertical`, so that a vertical
cable is solved without ``scipy.optimize`` and the ``scipy.linalg`` it imports):

==============================================  ===================  ===================
command                                         wall [s] bef./aft.   CPU [s] bef./aft.
==============================================  ===================  ===================
import numpy                                    0.50 / 0.50          0.25 / 0.25
import seacable                                 0.18 / 0.16          0.08 / 0.08
seacable validate paper002_vertical_cable.yaml  2.70 / 1.94          1.34 / 0.97
seacable validate oc3_hywind_static.yaml        1.96 / 1.81          0.86 / 0.90
seacable validate spread_mooring.yaml           4.2 / 5.0 (load)     1.88 / 2.42 (load)
seacable validate paper004_lena_pushover.yaml   4.3 / 5.0 (load)     1.97 / 2.46 (load)
==============================================  ===================  ===================

The two last need numba: a mooring system's checks evaluate its catenaries and stiffness at the start with the
compiled kernels (``check_statics``: a line that cannot reach, a body nothing restores), the pushover solves
its finite-element line. Of ``validate spread_mooring.yaml`` (cProfile) the check is 55 %, nearly all of it
numba's: its import, loading the cached kernels, which imports its registries and, for its BLAS check,
``scipy.linalg``. Paired runs of the spread mooring before and after: CPU ratio 1.04 (0.95-1.15), unchanged.
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
    # as an installed package runs: its compiled bytecode kept (a PYTHONDONTWRITEBYTECODE in the environment would
    # have every run compile every module again, a third of a second that no user pays)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env["PYTHONPATH"] = str(args.src.resolve())
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

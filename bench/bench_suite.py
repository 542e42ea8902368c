"""Wall time of the README's test command, from a fresh home folder and again warm (issue 38).

The README's test command is ``python -m pytest`` (``-n auto --durations=20`` in pyproject's addopts): the
command a new user runs to see that the install works and every change waits for. Most of a first run is
numba compiling the kernels into the cache folder (``seacable._numba_cache``: ``$XDG_CACHE_HOME/seacable``);
a second run takes them from there. This runs the command twice in a fresh, empty ``XDG_CACHE_HOME`` (and
``HOME``, so that nothing else of the user's is found), then prints the two wall times, the CPU count and
the load average before each run (a busy machine is slower: quote the figures with it), and the slowest
tests of the cold run.

The issue's targets on a quiet 2-core machine: under 4 minutes cold, under 2.5 warm.

Run: ``python bench/bench_suite.py [PYTEST ARGS]`` (e.g. ``-x`` or a test path, to time a part).
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _run(env: dict, args: list[str]) -> tuple[float, int, str]:
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "pytest", "-q", "-rfE", *args], cwd=ROOT, env=env, capture_output=True,
                          text=True, check=False)
    return time.perf_counter() - start, proc.returncode, proc.stdout


def main(args: list[str]) -> None:
    with tempfile.TemporaryDirectory(prefix="seacable-bench-suite-") as home:
        env = {**os.environ, "HOME": home, "XDG_CACHE_HOME": str(Path(home) / ".cache")}
        env.pop("NUMBA_CACHE_DIR", None)
        print(f"README test command ({' '.join(['python -m pytest', *args])}), {os.cpu_count()} CPUs, "
              f"fresh home {home}")
        print(f"{'run':>6} {'load (1 min)':>13} {'wall [s]':>9} {'wall [min]':>11} {'exit':>5}")
        slowest = ""
        for label in ("cold", "warm"):
            load = os.getloadavg()[0]
            wall, code, out = _run(env, args)
            print(f"{label:>6} {load:13.2f} {wall:9.1f} {wall / 60:11.2f} {code:5d}")
            failed = [s for s in out.splitlines() if s.startswith(("FAILED", "ERROR"))]
            if code != 0:  # say what failed: a timing of a failing suite is no timing
                print("\n".join(failed or out.splitlines()[-15:]))
            if label == "cold":
                lines = out.splitlines()
                start = next((k for k, s in enumerate(lines) if "slowest" in s and "durations" in s), None)
                if start is not None:
                    slowest = "\n".join(lines[start:start + 21])
        if slowest:
            print("\ncold run, " + slowest.strip("= \n"))


if __name__ == "__main__":
    main(sys.argv[1:])

"""Memory and wall time of a long mooring run: three 40-element lines, 3 hours, output every 0.1 s (issue 19).

The case: a three-line spread of MoorDyn's WD0200 chain (760 m of 390 kg/m studless chain in 200 m of water,
anchors 700 m from their fairleads at 120 degrees), each line cut into 40 segments, the three fairleads
moved together in heave (2 m at 10 s), 3 h at dt = 0.1 s with the state stored every 0.1 s (108 001
outputs), read and run through the user path (``run_moordyn_case``: file, model, statics, time loop,
result), two ways:

- ``memory``: the result Dataset in memory (0.58 GB of it), filled block by block as the run goes;
- ``file``: the result written into a NetCDF file as the run goes (``out=``), the Dataset returned read
  lazily from it;
- ``cli``: ``seacable run deck.txt --duration 10800 --output-interval 0.1 --motion heave.csv -o
  three_chains.nc`` (in the process, :func:`seacable.cli.main`; the heave as a table every 0.25 s): the file
  written as the run goes, then its two figures.

Each runs in a fresh process, after a short run in another process has put numba's compiled kernels in
its cache (a first run after an install compiles them, about 0.2 GB more for a minute). Printed: the peak
resident memory of the process (``resource.getrusage``: the operating system's own accounting, the
largest the process ever held, Python and numba included), the resident memory of the same process after
a 36 s run (imports and kernels loaded), and the wall time. The issue's target: the run fits in 1 GB.

Run: ``python bench/bench_memory.py [hours]`` (default 3; about a minute on one core).
"""

from __future__ import annotations

import json
import resource
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

DECK = Path(__file__).parents[1] / "tests" / "validation" / "data" / "three_chains_deck.txt"


def _resident() -> float:
    """The process's resident memory now. [bytes]"""
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize()


def child(mode: str, hours: float) -> dict:
    """One run in this process: ``mode`` 'memory', 'file' or 'cli' (with 'warm', a 36 s run only)."""
    from seacable.io.moordyn import load_moordyn_case
    from seacable.mooring.moordyn import run_moordyn_case
    from seacable.mooring.motion import HarmonicMotion

    folder = Path(tempfile.mkdtemp(prefix="bench_memory_"))

    def run(duration, out=None):
        case = load_moordyn_case(DECK).with_run(duration=duration, time_step=0.1, output_interval=0.1,
                                                motion=HarmonicMotion(amplitude=(0.0, 0.0, 2.0), period=10.0))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the deck's MoorDyn-only options
            return run_moordyn_case(case, out=out)

    run(36.0)
    loaded = _resident()
    if mode == "warm":
        return {}
    start = time.perf_counter()
    out = folder / "three_chains.nc"
    if mode == "cli":
        from seacable.cli import main

        deck = folder / "three_chains.txt"
        deck.write_text(DECK.read_text())
        # the same heave, as a table every 0.25 s (the motion file of the command line: a cubic spline)
        t = np.arange(0.0, 3600.0 * hours + 1.0, 0.25)
        offsets = HarmonicMotion(amplitude=(0.0, 0.0, 2.0), period=10.0).channels(t, np.zeros((1, 3)))[0][:, 0]
        motion = folder / "heave.csv"
        np.savetxt(motion, np.column_stack([t, offsets]), delimiter=",", header="time,x,y,z", comments="")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            main(["run", str(deck), "--duration", str(3600.0 * hours), "--time-step", "0.1", "--output-interval",
                  "0.1", "--motion", str(motion), "-o", str(out)])
        import xarray as xr

        ds = xr.open_dataset(out)
    else:
        ds = run(3600.0 * hours, out if mode == "file" else None)
    wall = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024  # kB on Linux
    return {"mode": mode, "outputs": int(ds.sizes["time"]), "peak_rss_bytes": int(peak), "loaded_bytes": loaded,
            "wall": wall, "fairlead_tension_max": float(np.nanmax(ds["fairlead_tension"]))}


def _in_process(mode: str, hours: float) -> dict:
    done = subprocess.run([sys.executable, __file__, "--child", mode, str(hours)], capture_output=True, text=True,
                          check=True)
    return json.loads(done.stdout.strip().splitlines()[-1])


def main(hours: float = 3.0) -> list[dict]:
    _in_process("warm", 0.01)
    rows = [_in_process(mode, hours) for mode in ("memory", "file", "cli")]
    print(f"three 40-segment lines, {hours:g} h at dt 0.1 s, output every 0.1 s: {rows[0]['outputs']} outputs")
    print("| result | peak resident memory | after a 36 s run | wall (deck, statics, loop, result) | "
          "max fairlead tension |")
    print("|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['mode']} | {r['peak_rss_bytes'] / 1e9:.3f} GB | {r['loaded_bytes'] / 1e9:.3f} GB | "
              f"{r['wall']:.1f} s | {r['fairlead_tension_max'] / 1e3:.1f} kN |")
    print("target: 1 GB")
    return rows


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        print(json.dumps(child(sys.argv[2], float(sys.argv[3]))))
    else:
        main(float(sys.argv[1]) if len(sys.argv) > 1 else 3.0)

"""The snap deck of ``bench_mooring.py snap``: the peak fairlead tension against the step, with and without
MoorDyn's slack-segment damping, and MoorDyn's own.

MoorDyn damps every segment with ``BA (dl/dt) / l`` whatever its strain; seacable's truss damps taut
elements only unless ``Water.slack_damping`` (set for MoorDyn decks since issue 19). For each step the
largest fairlead tension over 10 s read at every step, and read from outputs every 0.01 s (the bench's
output interval); "failed": a ConvergenceError. MoorDyn's peak: over its cycles 5 to 7 (t >= 6.25 s),
after its start from its own initial state (0.33 N at the fairlead, against the 2.76 N of the
catenary seacable starts from) has settled: its cycle maxima are 26.8, 24.0, 17.3, then 57.0-57.3 N.

Run: ``python bench/bench_snap_deck.py`` (about 3 minutes on one core).

Measured (2026-11-24, shared 2-core machine; "before": the damper in taut elements only, as seacable
read MoorDyn decks before issue 19; "after": MoorDyn's rule):

    MoorDyn 2.7.2, coupled every 5e-4 s, peak over t >= 6.25 s: CFL 0.1: 57.29 N, CFL 0.035: 57.31 N

| dt [s] | before: every step | before: 0.01 s outputs | after: every step | after: 0.01 s outputs |
|---|---|---|---|---|
| 0.01 | failed | failed | 38.36 N | 38.36 N |
| 0.005 | 116.46 N | 60.74 N | 44.23 N | 44.23 N |
| 0.0025 | 219.79 N | 64.55 N | 51.05 N | 48.24 N |
| 0.00125 | 169.98 N | 162.85 N | 56.79 N | 54.40 N |
| 0.0005 | 240.24 N | 69.39 N | 57.38 N | 57.26 N |
| 0.00025 | 184.82 N | 73.84 N | 57.34 N | 56.39 N |

(after, every step: 57.21 N at 1.25e-4 s and 57.20 N at 6.25e-5 s; before, every step, 160-170 N at
1.25e-4 to 3.1e-5 s: a 2.3 ms spike of about m c v = 0.0948 kg/m * 1779 m/s * 1 m/s, which outputs every
0.01 s miss, so that their maximum, 73.8, 87.8 and 85.5 N at 1.25e-4, 6.25e-5 and 3.1e-5 s, never
converges.) With the rule the snap rises over about 10 ms (8.5 ms above half its peak; MoorDyn the same)
and the peak converges monotonically from below; 1 % needs dt <= 1.25e-3 s. Spectral radius 0.8 (after):
44.1, 50.6, 56.6, 57.4 N at 5e-3 to 5e-4 s, the same as average acceleration.
"""

from __future__ import annotations

import dataclasses
import sys
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
import bench_mooring as B
import moordyn_peer as md

import seacable.mooring.moordyn as SM
from seacable.errors import ConvergenceError
from seacable.io.moordyn import load_moordyn_case

DURATION = 10.0
STEPS = (0.01, 0.005, 0.0025, 0.00125, 5e-4, 2.5e-4)
SETTLED = 6.25  # [s]: MoorDyn's own initial state (its dynamic relaxation) settles by the 5th cycle


def seacable_peaks(dt: float, slack_damping: bool):
    """(peak at every step, peak of the 0.01 s outputs) [N], or None on a ConvergenceError."""
    original = SM.moordyn_model

    def model(data):
        m = original(data)
        return type(m)(m.network, dataclasses.replace(m.water, slack_damping=slack_damping))

    SM.moordyn_model = model
    try:
        case = load_moordyn_case(B.snap_deck()).with_run(duration=DURATION, time_step=dt, output_interval=dt,
                                                         motion=B.snap_motion())
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ds = SM.run_moordyn_case(case)
    except ConvergenceError:
        return None
    finally:
        SM.moordyn_model = original
    f = np.asarray(ds["fairlead_tension"]).reshape(-1)
    return float(f.max()), float(f[::round(B.SNAP_OUTPUT / dt)].max())


def moordyn_peak(cfl: float, out: float = 5e-4) -> float:
    t = np.arange(0.0, DURATION + 1.0 + 1e-9, out)
    x = B.snap_motion().channels(t, np.array([B.SNAP_FAIRLEAD]))[0][:, 0]
    with md._quiet():
        r = md.run_moordyn(B.snap_deck(cfl), {"time": t, "x": x[:, 0], "y": x[:, 1], "z": x[:, 2]},
                           duration=DURATION, dt_out=out, use_ic_file=False)
    return float(np.max(np.asarray(r["fairlead_tension"])[np.asarray(r["time"]) >= SETTLED]))


def main():
    print(f"MoorDyn 2.7.2, coupled every 5e-4 s, peak over t >= {SETTLED:g} s: "
          + ", ".join(f"CFL {c:g}: {moordyn_peak(c):.2f} N" for c in (0.1, 0.035)))
    print("| dt [s] | before: every step | before: 0.01 s outputs | after: every step | after: 0.01 s outputs |")
    print("|---|---|---|---|---|")

    def cell(r, k):
        return "failed" if r is None else f"{r[k]:.2f} N"

    for dt in STEPS:
        before, after = seacable_peaks(dt, False), seacable_peaks(dt, True)
        print(f"| {dt:g} | {cell(before, 0)} | {cell(before, 1)} | {cell(after, 0)} | {cell(after, 1)} |", flush=True)


if __name__ == "__main__":
    main()

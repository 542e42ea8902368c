"""Paper 001 Table 1 reproduced by a sweep of the laying simulation over ship speeds.

Usage: ``python examples/paper001_speed_sweep.py [OUTDIR]`` (default ``sweep_out/``). Runs
``paper001_speed_sweep.yaml`` beside this script on a local Dask cluster (one worker per core;
a second run reuses the cases already in OUTDIR), then prints the table of the paper's two columns
beside the simulated steady entry angle and draws them in ``OUTDIR/paper001_table1.png``.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

import seacable as sc

HERE = Path(__file__).resolve().parent

#: Paper 001 Table 1: ship speed [m/s], incident angle [deg] by the straight-line theory (H/V) and by
#: the paper's numerical method.
TABLE1 = np.array([
    [0.75, 34.965, 33.798], [1.0, 26.224, 25.744], [1.25, 20.979, 20.736], [1.5, 17.483, 17.343],
    [1.75, 14.985, 14.897], [2.0, 13.112, 13.053], [2.25, 11.655, 11.614], [2.5, 10.490, 10.459],
    [2.75, 9.536, 9.513], [3.0, 8.741, 8.724], [3.25, 8.069, 8.055], [3.5, 7.493, 7.481],
    [3.75, 6.993, 6.984], [4.0, 6.556, 6.548], [4.25, 6.170, 6.164], [4.5, 5.828, 5.822],
    [4.75, 5.521, 5.516], [5.0, 5.245, 5.241]])


def main(outdir: str = "sweep_out") -> int:
    summary = sc.sweep(HERE / "paper001_speed_sweep.yaml", outdir)
    speed = summary["analysis.ship.speed"].values
    ours = np.degrees(summary["entry_angle_end"].values)  # results hold angles in rad
    paper = np.interp(speed, TABLE1[:, 0], TABLE1[:, 2])
    print("ship speed [m/s] | paper: straight line [deg] | paper: numerical [deg] | seacable [deg] | "
          "seacable - paper [deg] | layback [m]")
    for v, row, a, lb in zip(speed, TABLE1, ours, summary["layback_end"].values):
        print(f"{v:16.2f} | {row[1]:26.3f} | {row[2]:22.3f} | {a:14.3f} | {a - row[2]:+22.4f} | {lb:11.1f}")
    print(f"largest difference from the paper's numerical column: {np.nanmax(np.abs(ours - paper)):.4f} deg")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.plot(TABLE1[:, 0], TABLE1[:, 1], "s", mfc="none", color="0.5", label="paper 001: straight-line theory")
    ax.plot(TABLE1[:, 0], TABLE1[:, 2], "o", mfc="none", color="k", label="paper 001: numerical")
    ax.plot(speed, ours, "-", color="C3", label="seacable laying_dynamic (sweep)")
    ax.set(xlabel="ship speed [m/s]", ylabel="entry angle at the surface [deg]",
           title="Paper 001 Table 1: cable in 50 m of water")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    path = Path(outdir) / "paper001_table1.png"
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:2]))

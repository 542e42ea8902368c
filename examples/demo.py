"""seacable's main demo: run the example cases, write NetCDF results and PNG plots.

Usage: ``python examples/demo.py [OUTDIR]`` (default ``demo_out/``). Each case is
read from its YAML file beside this script, exactly as ``seacable run`` does; the last
steps are the sweep ``paper001_speed_sweep.yaml`` on a local Dask cluster, as
``seacable sweep`` runs it, and the design of the IEA-15 MW VolturnUS-S moorings: the sweep
``volturnus_design.yaml`` (2 sea states with their wind and current x 2 seeds, intact and with the most loaded chain
removed, the hull coupled with its WAMIT database) and its report (``report.html``: extremes, the load components
modelled, the LF + WF combination, DNV-OS-E301 and API RP 2SK checks, fatigue life over ``volturnus_scatter.csv``),
as ``seacable report`` writes it.
"""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd

import seacable as sc
from seacable.plot import plot_result
from seacable.report import ReportOptions, make_report

HERE = Path(__file__).resolve().parent

#: The cases shown, in order, and the one-line summary printed for each.
CASES = {
    "paper000_turn": lambda ds: (
        f"top tension {float(ds.top_tension[0]):.1f} -> {float(ds.top_tension[-1]):.1f} N in "
        f"{float(ds.time[-1]):g} s ({100 * (float(ds.top_tension[-1] / ds.top_tension[0]) - 1):+.2f} %, paper "
        f"000 Table 3: -1.54 %); vessel {float(ds.vessel_y[-1]):.1f} m, free end "
        f"{float(ds.y[-1, 0] - ds.y[0, 0]):.1f} m sideways"),
    "paper001_lay_2ms_50m": lambda ds: (
        f"entry angle {np.degrees(float(ds.entry_angle[-1])):.3f} deg (paper 001 Table 1: 13.053), ship tension "
        f"{float(ds.top_tension[-20:].mean()):.1f} N (w h = 224.5 N), slack {float(ds.slack[-1]):.4f}; "
        f"{float(ds.laid_length[-1]):.0f} m laid"),
    "lay_route_3d": lambda ds: (
        f"3-D lay along a route: touchdown {float(ds.touchdown_offset.sel(time=200.0)):.1f} m off the route in the "
        f"cross-current, the laid cable up to {float(ds.laid_offset.max()):.1f} m inside the alter-course; slack "
        f"{float(ds.slack[-1]):.4f}, top tension {float(ds.top_tension[-1]):.1f} N"),
    "lay_plan_route": lambda ds: (
        f"lay table, {ds.kp.size} rows over {float(ds.kp[-1]) / 1e3:g} km: layback up to {float(ds.layback.max()):.0f} m, "
        f"touchdown up to {float(abs(ds.touchdown_offset).max()):.0f} m off the route in the cross-current, repeater "
        f"R1 in the water KP {float(ds.repeater_entry_kp[0]):.0f}-{float(ds.repeater_touchdown_kp[0]):.0f} m at "
        f"{float(ds.ship_speed.min()):g} m/s; {float(ds.time[-1]) / 3600:.1f} h (quasi-static planner)"),
    "towed_stop_and_go": lambda ds: (f"top tension {float(ds.top_tension[0]):.0f} N, down to "
                                     f"{float(ds.top_tension.min()):.1f} N while stopped"),
    "towed_stop_and_go_from_rest": lambda ds: (
        f"from rest (hanging, top tension {float(ds.top_tension[0]):.1f} N = w L) to 2 m/s and back: layback up to "
        f"{float(ds.layback.max()):.0f} m, {float(ds.layback.sel(time=250.0)):.0f} m after 150 s stopped "
        "(finite elements)"),
    "towed_depressor_survey": lambda ds: (
        f"depressor two-part tow from rest, {float(ds.paid_out_length[-1]):.0f} m paid out: towfish "
        f"{float(ds.point_depth.sel(time=500.0, point='body')):.0f} m deep and "
        f"{float(ds.point_layback.sel(time=500.0, point='body')):.0f} m astern at 2 m/s, depressor "
        f"{float(ds.point_depth.sel(time=500.0, point='depressor')):.0f} m deep; top tension "
        f"{float(ds.top_tension.sel(time=500.0)) / 1e3:.1f} kN at {float(ds.top_angle.sel(time=500.0)):.2f} rad"),
    "oc3_hywind_static": lambda ds: (f"fairlead tension {float(ds.fairlead_tension) / 1e3:.1f} kN, "
                                   f"{float(ds.grounded_length):.1f} m on the seabed"),
    "oc3_hywind_line": lambda ds: (f"5 m surge at 20 s in 6 m waves: fairlead tension "
                                   f"{float(ds.fairlead_tension.min()) / 1e3:.0f} to "
                                   f"{float(ds.fairlead_tension.max()) / 1e3:.0f} kN (static "
                                   f"{float(ds.fairlead_tension[0]) / 1e3:.1f} kN), truss FE, Newmark"),
    "paper004_buoy_relaxation": lambda ds: (f"buoy released, anchor tension {float(ds.anchor_tension[0]):.3f} -> "
                                            f"{float(ds.anchor_tension[-20:].mean()):.3f} N (at rest 0.475 N)"),
    "oc3_hywind_pushover": lambda ds: (f"H from {float(ds.H_fairlead[0]) / 1e3:.0f} to "
                                       f"{float(ds.H_fairlead[-1]) / 1e3:.0f} kN over "
                                       f"{float(ds.offset[0]):g}..{float(ds.offset[-1]):g} m"),
    "oc3_hywind_modes": lambda ds: (f"first periods {', '.join(f'{p:.2f}' for p in ds.period.values[:4])} s; "
                                    f"wave-speed estimate {float(ds.wave_period):.2f} s"),
    "paper004_lena_pushover": lambda ds: (f"clump lifts off the seabed: contact length "
                                          f"{float(ds.seabed_contact_length[0]):.0f} m at 0 m offset, "
                                          f"{float(ds.seabed_contact_length[-1]):.0f} m at {float(ds.offset[-1]):g} m; "
                                          f"H {float(ds.H_fairlead[0]) / 1e3:.0f} -> "
                                          f"{float(ds.H_fairlead[-1]) / 1e3:.0f} kN"),
    "paper003_zigzag": lambda ds: (f"tug zig-zag 10 m / 50 s at 2 knots: sway {float(np.ptp(ds.y.values[:, 0])):.1f} m at the tug, "
                                   f"{float(np.ptp(ds.y.values[ds.time.values >= 200, -2])):.1f} m next to the barge; barge tension up "
                                   f"to {float(ds.barge_tension.max()) / 1e3:.1f} kN"),
    "paper003_payout": lambda ds: (f"line paid out from the bitt in {float(ds.time[ds.released.all('element')][0]):.0f} s; "
                                   f"barge at {float(ds.barge_speed[-1]):.3f} m/s, tension "
                                   f"{float(ds.barge_tension[-1]) / 1e3:.1f} kN"),
    "spread_mooring": lambda ds: (
        "3-line spread, 500 kN on the buoy: offset "
        + " / ".join(f"{float(ds.body_offset.sel(condition=c, body='buoy')):.1f} m" for c in ds.condition.values)
        + f" (intact / {json.loads(ds.attrs['settings'])['damaged_lines'][0]}, the most loaded, broken); fairlead tensions "
        + " / ".join(", ".join("-" if np.isnan(t) else f"{t / 1e3:.0f}" for t in ds.fairlead_tension.sel(condition=c).values)
                     for c in ds.condition.values)
        + f" kN; surge stiffness {float(ds.stiffness_translation.sel(condition='intact', body='buoy', dof='surge', dof2='surge')) / 1e3:.1f} kN/m"),
    "spread_mooring_watch_circle": lambda ds: (
        f"watch circle, {ds.heading.size} headings: at {float(ds.applied_load[-1]) / 1e6:g} MN the buoy moves "
        f"{float(ds.body_offset.sel(condition='intact', body='buoy').isel(applied_load=-1).min()):.1f} to "
        f"{float(ds.body_offset.sel(condition='intact', body='buoy').isel(applied_load=-1).max()):.1f} m intact, up to "
        f"{float(ds.body_offset.sel(condition='damaged', body='buoy').isel(applied_load=-1).max()):.0f} m with each "
        f"heading's most loaded line broken; "
        f"largest fairlead tension {float(ds.fairlead_tension.sel(condition='intact').max()) / 1e3:.0f} kN intact"),
    "paper000_steady_statics": lambda ds: f"top tension {float(ds.top_tension):.1f} N (paper 000 eq. 6 drag)",
    "paper001_table1": lambda ds: (f"entry angle at 2 m/s {np.degrees(float(ds.angle.sel(ship_speed=2.0))):.3f} deg "
                                   "(paper 001 Table 1: 13.053)"),
    "paper002_vertical_cable": lambda ds: ("fundamental period string/exact/wave "
                                           + "/".join(f"{p:.3f}" for p in ds.period.isel(mode=0).values)
                                           + " s"),
}


def main(outdir: str = "demo_out", *extra: str) -> int:
    if extra or outdir.startswith("-"):
        print("usage: python examples/demo.py [OUTDIR]   (default demo_out/)")
        return 0 if outdir in ("-h", "--help") else 2
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    print(f"seacable {sc.__version__} demo -> {out.resolve()}")
    for name, summary in CASES.items():
        start = time.perf_counter()
        case = sc.load_case(HERE / f"{name}.yaml")
        ds = sc.run(case)
        nc = sc.write_netcdf(ds, out / f"{name}.nc")
        pngs = plot_result(ds, out, prefix=name)
        print(f"{name:26s} {summary(ds)}  [{time.perf_counter() - start:.2f} s]")
        print(f"{'':26s} wrote {nc}, " + ", ".join(p.name for p in pngs))
    start = time.perf_counter()
    sweep_out = out / "paper001_speed_sweep"
    summary = sc.sweep(HERE / "paper001_speed_sweep.yaml", sweep_out)
    pngs = plot_result(summary, sweep_out, prefix="summary")
    angles = np.degrees(summary.entry_angle_end.values)  # results hold angles in rad
    print(f"{'paper001_speed_sweep':26s} {summary.sizes['case']} laying cases on a local Dask cluster: entry angle "
          f"{angles[0]:.3f} deg at {float(summary['analysis.ship.speed'][0]):g} m/s to {angles[-1]:.3f} deg at "
          f"{float(summary['analysis.ship.speed'][-1]):g} m/s (paper 001 Table 1: 33.798 to 5.241)  "
          f"[{time.perf_counter() - start:.2f} s]")
    print(f"{'':26s} wrote {sweep_out / 'summary.nc'}, summary.csv, cases/, " + ", ".join(p.name for p in pngs))
    start = time.perf_counter()
    design_out = out / "volturnus_design"
    summary = sc.sweep(HERE / "volturnus_design.yaml", design_out)
    files = make_report(design_out, design_out / "report.html",
                        ReportOptions(storm_duration=10800.0, scatter=HERE / "volturnus_scatter.csv",
                                      offset_limit=40.0))
    checks = pd.read_csv(design_out / "report_checks.csv")
    lives = pd.read_csv(design_out / "report_fatigue_life.csv")
    tension = checks[checks["check"].str.startswith(("DNV", "API"))]
    worst = tension.loc[tension["utilisation [-]"].idxmax()]
    offsets = checks[checks["check"] == "offset"]
    intact = offsets["load_case"].str.contains("damaged_lines = []", regex=False)
    print(f"{'volturnus_design':26s} {summary.sizes['case']} coupled runs of the VolturnUS-S (WAMIT database, slow "
          f"drift, wind, current): largest tension utilisation {worst['utilisation [-]']:.3f} ({worst['check']}, "
          f"{worst['item']}); largest offset {offsets['demand [N or m, see unit]'][intact].max():.0f} m intact, "
          f"{offsets['demand [N or m, see unit]'][~intact].max():.0f} m with the weather chain broken; "
          f"{int(checks['passed'].sum())} of {len(checks)} checks pass; shortest fatigue life "
          f"{lives['life [years]'].min():.3g} years  [{time.perf_counter() - start:.2f} s]")
    print(f"{'':26s} wrote {files[0]}, " + ", ".join(f.name for f in files[1:]))
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))

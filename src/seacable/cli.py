"""The ``seacable`` command line: run, sweep, validate, plot, animate, schema.

User errors (bad files, bad values, no solution, no convergence) print one
clear message and exit with status 2; an interrupted run exits with 130. A sweep
in which some cases failed exits with 1 (the others ran; the summary says why).
"""

from __future__ import annotations

import argparse
import sys
import warnings
from pathlib import Path

from ._version import __version__
from .errors import SeacableError, SeacableWarning

__all__ = ["main"]

EXIT_CASES_FAILED = 1
EXIT_USER_ERROR = 2
EXIT_INTERRUPTED = 130


def _show_warning(message, category, filename, lineno, file=None, line=None):
    if issubclass(category, SeacableWarning):
        print(f"seacable: warning: {message}", file=sys.stderr)
    else:
        print(warnings.formatwarning(message, category, filename, lineno, line), file=sys.stderr, end="")


class _Progress:
    """Progress line on stderr for time-domain runs, at most once a second."""

    def __init__(self, every: float = 1.0):
        self.every = every
        self.last = None

    def __call__(self, t: float, duration: float) -> None:
        import time

        now = time.monotonic()
        done = t >= duration - 1e-9
        if self.last is None:
            self.last = now
        if done or now - self.last >= self.every:
            self.last = now
            end = "\n" if done else "\r"
            print(f"seacable: t = {t:.6g} s of {duration:.6g} s ({100 * t / duration:.0f} %)",
                  file=sys.stderr, end=end, flush=True)


def _run_moordyn(args):
    """``seacable run lines.txt``: a MoorDyn input file, statics (and dynamics with --duration)."""
    from .errors import InputError
    from .mooring.moordyn import run_moordyn_file
    from .mooring.motion import motion_from_csv

    path = Path(args.case)
    motion = None
    if args.motion is not None:
        if args.duration is None:
            raise InputError("--motion needs --duration (s): the length of the run. Suggested fix: add "
                             "e.g. '--duration 100'.")
        motion = motion_from_csv(args.motion)
    ds = run_moordyn_file(path, duration=args.duration, motion=motion, time_step=args.time_step,
                          output_interval=args.output_interval, progress=_Progress())
    return ds, path.stem


def _cmd_run(args) -> int:
    from .io import load_case
    from .io.moordyn import is_moordyn_file
    from .results import write_netcdf
    from .simulate import run

    if is_moordyn_file(args.case):
        ds, name = _run_moordyn(args)
    else:
        if args.duration is not None or args.motion is not None:
            from .errors import InputError

            raise InputError("--duration and --motion apply to MoorDyn input files; a YAML case gives them "
                             "in its 'analysis'.")
        case = load_case(args.case)
        name = case.name
        ds = run(case, progress=_Progress())
    out = Path(args.output) if args.output else Path(f"{name}.nc")
    path = write_netcdf(ds, out)
    print(f"wrote {path}")
    if not args.no_plots:
        from .plot import plot_result

        for png in plot_result(ds, args.plot_dir or path.parent, prefix=path.stem):
            print(f"wrote {png}")
    if ds.attrs.get("interrupted"):
        t_end = float(ds["time"].values[-1])
        print(f"seacable: interrupted at t = {t_end:g} s; {path} holds the result up to then",
              file=sys.stderr)
        return EXIT_INTERRUPTED
    return 0


class _SweepProgress:
    """Progress line of a sweep on stderr (at most once a second), and each failure as it comes."""

    def __init__(self, every: float = 1.0):
        self.every = every
        self.last = None

    def __call__(self, p) -> None:
        import math
        import time

        r = p.record
        if r is not None and r["status"] == "failed":
            first = r["error"].splitlines()[0] if r["error"] else "failed"
            print(f"\nseacable: case {r['index']} ({r['name']}) failed: {first}", file=sys.stderr)
        if r is not None:
            for w in r["warnings"]:
                print(f"\nseacable: case {r['index']} ({r['name']}): warning: {w}", file=sys.stderr)
        now = time.monotonic()
        done = p.done == p.total
        if self.last is not None and not done and now - self.last < self.every:
            return
        self.last = now
        left = p.remaining_time
        eta = f", about {left:.0f} s left" if math.isfinite(left) and not done else ""
        extra = "".join([f", {p.failed} failed" if p.failed else "",
                         f", {p.reused} from an earlier run" if p.reused else ""])
        print(f"seacable: sweep {p.done} of {p.total} cases{extra}; {p.elapsed:.0f} s{eta}",
              file=sys.stderr, end="\n" if done else "\r", flush=True)


def _print_summary(summary) -> None:
    import json

    from .extremes import KEY_FIGURES
    from .sweeps.engine import summary_table

    table = summary_table(summary)
    params = json.loads(summary.attrs["parameters"])
    figures = [c for c in ("top_tension_max", "top_tension_min", "tension_max", "tension_min",
                           *KEY_FIGURES.get(summary.attrs.get("case_analysis"), ())) if c in table]
    table = table[["name", *params, "status", *figures]]

    def head(name):
        units = summary[name].attrs.get("units", "")
        return f"{name} [{units}]" if units and units != "1" else name

    table.columns = [head(c) for c in table.columns]
    print(table.to_string(float_format=lambda v: f"{v:.6g}"))


def _cmd_sweep(args) -> int:
    from .sweeps import load_sweep, sweep

    spec = load_sweep(args.sweep)
    outdir = Path(args.output) if args.output else Path(spec.name)
    summary = sweep(spec, outdir, scheduler=args.scheduler, workers=args.workers,
                    retry_failed=args.retry_failed, progress=_SweepProgress())
    _print_summary(summary)
    print(f"wrote {outdir / 'summary.nc'}, {outdir / 'summary.csv'} and {summary.attrs['done']} case result(s) "
          f"in {outdir / 'cases'}")
    if not args.no_plots:
        from .plot import plot_result

        for png in plot_result(summary, outdir, prefix="summary"):
            print(f"wrote {png}")
    if summary.attrs.get("interrupted"):
        print(f"seacable: interrupted; {summary.attrs['done'] + summary.attrs['failed']} of "
              f"{summary.attrs['cases']} cases are in {outdir}; run the same command again to finish the others",
              file=sys.stderr)
        return EXIT_INTERRUPTED
    if summary.attrs["failed"]:
        print(f"seacable: {summary.attrs['failed']} of {summary.attrs['cases']} cases failed; their messages "
              f"are in the summary ('error'). Run again with --retry-failed once fixed.", file=sys.stderr)
        return EXIT_CASES_FAILED
    return 0


def _cmd_validate(args) -> int:
    from .io import load_case
    from .sweeps import is_sweep_file, load_sweep

    for name in args.cases:
        if is_sweep_file(name):
            spec = load_sweep(name)
            bad = [c for c in spec.cases() if c.case is None]
            for c in bad:
                print(f"{name}: {c.error}", file=sys.stderr)
            print(f"{name}: valid sweep of {len(spec)} case(s) ({spec.kind} of {', '.join(spec.parameters)})"
                  + (f"; {len(bad)} case(s) invalid" if bad else ""))
            if bad:
                return EXIT_USER_ERROR
            continue
        case = load_case(name)
        print(f"{name}: valid ({case.analysis.type} analysis, {len(case.line.segments)} segment(s), "
              f"line length {case.line.length:g} m)")
    return 0


def _cmd_plot(args) -> int:
    from .plot import plot_result
    from .results import read_netcdf

    path = Path(args.result)
    ds = read_netcdf(path)
    for png in plot_result(ds, args.output or path.parent, prefix=path.stem):
        print(f"wrote {png}")
    return 0


def _cmd_animate(args) -> int:
    from .plot import animate_laying
    from .plot import animate_towline
    from .results import read_netcdf

    path = Path(args.result)
    ds = read_netcdf(path)
    if ds.attrs.get("analysis") == "towline_dynamic":
        animate, tag = animate_towline, "tow"
    else:  # animate_laying names the analyses it accepts in its error
        animate, tag = animate_laying, "lay"
    out = Path(args.output) if args.output else path.parent / f"{path.stem}_{tag}.gif"
    written = animate(ds, out, fps=args.fps, max_frames=args.max_frames)
    print(f"wrote {written}")
    return 0


def _cmd_schema(args) -> int:
    from .io import case_schema

    print(case_schema())
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="seacable",
        description="Statics and dynamics of marine cables: mooring lines, towed cables, cable laying. "
                    "SI units throughout.")
    parser.add_argument("--version", action="version", version=f"seacable {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    p = sub.add_parser("run", help="run a case file and write its result (NetCDF) and plots (PNG)")
    p.add_argument("case", help="YAML case file, or a MoorDyn input file (lines and points)")
    p.add_argument("-o", "--output", help="result file (.nc); default CASE_NAME.nc")
    p.add_argument("--duration", type=float, help="MoorDyn file: simulated time after the statics [s]")
    p.add_argument("--motion", help="MoorDyn file: CSV of vessel offsets (time, x, y, z) applied to every "
                                    "vessel point [s, m], or of rigid platform motions about the origin "
                                    "(time, surge, sway, heave, roll, pitch, yaw) [s, m, rad]")
    p.add_argument("--time-step", type=float, default=0.1, help="MoorDyn file: Newmark time step [s] (0.1)")
    p.add_argument("--output-interval", type=float, default=0.5,
                   help="MoorDyn file: time between stored states [s] (0.5)")
    p.add_argument("--plot-dir", help="folder for the PNG plots; default beside the result")
    p.add_argument("--no-plots", action="store_true", help="write the result only")
    p.set_defaults(func=_cmd_run)

    p = sub.add_parser("sweep", help="run a sweep: a base case over a grid or a table of parameters, on Dask")
    p.add_argument("sweep", help="sweep file (YAML): 'base' (a case file) and 'grid' or 'table'")
    p.add_argument("-o", "--output", help="output folder: per-case results and the summary; default the sweep's "
                                          "name. Cases already there are not run again")
    p.add_argument("--scheduler", help="address of an existing Dask scheduler (tcp://host:8786), whose workers "
                                       "have seacable; default a local cluster on this machine's cores; "
                                       "'synchronous' runs the cases one by one in this process")
    p.add_argument("--workers", type=int, help="workers of the local cluster (default: one per core)")
    p.add_argument("--retry-failed", action="store_true", help="run again the cases that failed before")
    p.add_argument("--no-plots", action="store_true", help="write the results only")
    p.set_defaults(func=_cmd_sweep)

    p = sub.add_parser("validate", help="check case and sweep files without running them")
    p.add_argument("cases", nargs="+", help="YAML case or sweep files")
    p.set_defaults(func=_cmd_validate)

    p = sub.add_parser("plot", help="make the standard figures (PNG) of a result file")
    p.add_argument("result", help="result file (.nc) written by 'seacable run'")
    p.add_argument("-o", "--output", help="folder for the PNG files; default beside the result")
    p.set_defaults(func=_cmd_plot)

    p = sub.add_parser("animate", help="animate a cable lay (laying_dynamic) or a tow (towline_dynamic) "
                                       "as GIF or MP4")
    p.add_argument("result", help="result file (.nc) of a laying_dynamic or towline_dynamic run")
    p.add_argument("-o", "--output", help="animation file (.gif, or .mp4 with ffmpeg); default "
                                          "RESULT_lay.gif or RESULT_tow.gif beside the result")
    p.add_argument("--fps", type=int, default=10, help="frames per second (default 10)")
    p.add_argument("--max-frames", type=int, default=200,
                   help="largest number of frames; output times are subsampled evenly (default 200)")
    p.set_defaults(func=_cmd_animate)

    p = sub.add_parser("schema", help="print the JSON schema of case files")
    p.set_defaults(func=_cmd_schema)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``seacable`` command. Returns the exit status."""
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return EXIT_USER_ERROR
    warnings.showwarning = _show_warning
    try:
        return args.func(args)
    except SeacableError as err:
        print(f"seacable: error: {err}", file=sys.stderr)
        return EXIT_USER_ERROR
    except KeyboardInterrupt:
        print("seacable: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())

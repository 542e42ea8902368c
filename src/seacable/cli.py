"""The ``seacable`` command line: run, sweep, validate, plot, animate, report, schema.

User errors (bad files, bad values or options, paths that cannot be written, no
solution, no convergence) print one clear message and exit with status 2, before
anything is computed whenever they can be known then. A bug (an unexpected
exception) prints a short request to report it and exits with 3 (``--debug``
shows its traceback). A run interrupted by Ctrl-C or SIGTERM (what batch
schedulers send) writes what it computed and exits with 130. A sweep in which
some cases failed exits with 1 (the others ran; the summary says why).
"""

from __future__ import annotations

import argparse
import contextlib
import functools
import math
import os
import signal
import sys
import threading
import warnings
from pathlib import Path

from ._version import __version__
from .errors import InputError, SeacableError, SeacableWarning

__all__ = ["main"]

EXIT_CASES_FAILED = 1
EXIT_USER_ERROR = 2
EXIT_BUG = 3
EXIT_INTERRUPTED = 130


def _show_warning(message, category, filename, lineno, file=None, line=None):
    if issubclass(category, SeacableWarning):
        print(f"seacable: warning: {message}", file=sys.stderr)
    else:
        print(warnings.formatwarning(message, category, filename, lineno, line), file=sys.stderr, end="")


def _is_tty(stream) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):  # closed or not a file
        return False


class _Progress:
    """Progress of a time-domain run on stderr.

    On a terminal: one line rewritten in place (carriage returns), at most once a second. Written to a file
    or a pipe (a batch job's log): one whole line per update, at most every ``pipe_step`` of the run (10 %) or
    every ``pipe_every`` seconds, whichever comes first, so that a log reads line by line and stays short.
    """

    def __init__(self, every: float = 1.0, pipe_every: float = 10.0, pipe_step: float = 0.1, tty: bool | None = None,
                 quiet: bool = False):
        self.tty = _is_tty(sys.stderr) if tty is None else tty
        self.every = every if self.tty else pipe_every
        self.step = pipe_step
        self.last = None
        self.shown = 0.0    # the fraction of the run last shown (pipe)
        self.quiet = quiet  # --quiet: nothing shown (the end of the computation still noted)

    def __call__(self, t: float, duration: float) -> None:
        import time

        now = time.monotonic()
        done = t >= duration - 1e-9
        if self.last is None:
            self.last = now
        if done:
            _computation_done()
        fraction = t / duration
        if self.quiet:
            return
        due = now - self.last >= self.every or (not self.tty and fraction - self.shown >= self.step - 1e-12)
        if done or due:
            self.last, self.shown = now, fraction
            end = "\n" if done or not self.tty else "\r"
            print(f"seacable: t = {t:.6g} s of {duration:.6g} s ({100 * fraction:.0f} %)",
                  file=sys.stderr, end=end, flush=True)


def _moordyn_case(args):
    """``seacable run lines.txt``: the MoorDyn file as a case, with the run its options ask for."""
    from .io import load_case
    from .mooring.motion import motion_from_csv

    if args.motion is not None and args.duration is None:  # before reading the CSV for nothing
        raise InputError("--motion needs --duration (s): the length of the run. Suggested fix: add "
                         "e.g. '--duration 100'.")
    motion = None if args.motion is None else motion_from_csv(args.motion)
    return load_case(args.case).with_run(duration=args.duration, motion=motion, time_step=args.time_step,
                                         output_interval=args.output_interval, spectral_radius=args.spectral_radius)


def _result_path(args, name: str) -> Path:
    return Path(args.output) if args.output else Path(f"{name}.nc")


def _check_run_paths(args, out: Path) -> None:
    """Refuse, before a run starts, an output file or plot folder that cannot be written."""
    from .results import check_output_file, check_output_folder

    check_output_file(out, "-o" if args.output else "the default result file (-o)")
    if not args.no_plots and args.plot_dir is not None:
        check_output_folder(args.plot_dir, "--plot-dir")


def _cmd_run(args) -> int:
    from .io import load_case
    from .io.moordyn import is_moordyn_file
    from .results import write_netcdf
    from .simulate import run, streams
    from .sweeps import is_sweep_file

    if is_sweep_file(args.case):
        raise InputError(f"{args.case} is a sweep file ('base' and 'grid' or 'table'), not a case. Suggested fix: "
                         f"seacable sweep {args.case}")
    if is_moordyn_file(args.case):
        case = _moordyn_case(args)
    else:
        given = [opt for opt, value in (("--duration", args.duration), ("--motion", args.motion),
                                        ("--time-step", args.time_step),
                                        ("--spectral-radius", args.spectral_radius),
                                        ("--output-interval", args.output_interval)) if value is not None]
        if given:
            raise InputError(f"{', '.join(given)} apply to MoorDyn input files; a YAML case gives them in its "
                             "'analysis' (duration, motion, time_step, output_interval, spectral_radius). Suggested "
                             "fix: leave "
                             f"out {', '.join(given)} and set them in {args.case}.")
        case = load_case(args.case)
    out = _result_path(args, case.name)
    _check_run_paths(args, out)
    say = (lambda text: None) if args.quiet else print   # --quiet: nothing on stdout
    _GUARD.update(armed=True, holding=False, held=[])
    try:
        streamed = streams(case)  # a long mooring run writes its outputs into the file as it goes
        ds = run(case, progress=_Progress(quiet=args.quiet), out=out if streamed else None)
        _computation_done()
        path = out if streamed else write_netcdf(ds, out)
        say(f"wrote {path}")
        if ds.attrs.get("analysis") == "lay_plan":      # the lay table, as the ship's crew reads it
            from .laying.plan_run import write_lay_table, write_repeater_table

            table = path.with_name(f"{path.stem}_lay_table.csv")
            write_lay_table(ds, table)
            say(f"wrote {table}")
            events = path.with_name(f"{path.stem}_repeaters.csv")
            if write_repeater_table(ds, events):
                say(f"wrote {events}")
    finally:
        _GUARD.update(armed=False, holding=False)
    if _GUARD["held"]:
        print(f"seacable: interrupted; {path} holds the whole result (no plots made)", file=sys.stderr)
        return EXIT_INTERRUPTED
    if not args.no_plots:
        from .plot import plot_result

        try:
            for png in plot_result(ds, args.plot_dir or path.parent, prefix=path.stem):
                say(f"wrote {png}")
        except KeyboardInterrupt:
            print(f"seacable: interrupted while plotting; {path} holds the whole result. Suggested fix: "
                  f"'seacable plot {path}' makes the figures.", file=sys.stderr)
            return EXIT_INTERRUPTED
    if not args.quiet and not ds.attrs.get("interrupted"):   # the figures an engineer reads first
        from .run_summary import summary

        print(summary(ds))
    if ds.attrs.get("interrupted"):
        if "time" in ds and ds["time"].size:
            print(f"seacable: interrupted at t = {float(ds['time'].values[-1]):g} s; {path} holds the result up "
                  "to then", file=sys.stderr)
        else:
            print(f"seacable: interrupted; {path} holds the cases solved until then (NaN for the others)",
                  file=sys.stderr)
        return EXIT_INTERRUPTED
    return 0


class _SweepProgress:
    """Progress line of a sweep on stderr, and each failure as it comes: on a terminal one line rewritten in
    place at most once a second; to a file or a pipe one whole line per update, at most every 10 % of the cases
    or every 10 s (as :class:`_Progress`)."""

    def __init__(self, every: float = 1.0, pipe_every: float = 10.0, pipe_step: float = 0.1, tty: bool | None = None):
        self.tty = _is_tty(sys.stderr) if tty is None else tty
        self.every = every if self.tty else pipe_every
        self.step = pipe_step
        self.last = None
        self.shown = 0.0

    def __call__(self, p) -> None:
        import time

        r = p.record
        nl = "\n" if self.tty else ""   # ends the line being rewritten on a terminal
        if r is not None and r["status"] == "failed":
            first = r["error"].splitlines()[0] if r["error"] else "failed"
            print(f"{nl}seacable: case {r['index']} ({r['name']}) failed: {first}", file=sys.stderr)
        if r is not None:
            for w in r["warnings"]:
                print(f"{nl}seacable: case {r['index']} ({r['name']}): warning: {w}", file=sys.stderr)
        now = time.monotonic()
        done = p.done == p.total
        fraction = p.done / p.total if p.total else 1.0
        step_due = not self.tty and fraction - self.shown >= self.step - 1e-12
        if self.last is not None and not done and now - self.last < self.every and not step_due:
            return
        self.last, self.shown = now, fraction
        left = p.remaining_time
        eta = f", about {left:.0f} s left" if math.isfinite(left) and not done else ""
        extra = "".join([f", {p.failed} failed" if p.failed else "",
                         f", {p.reused} from an earlier run" if p.reused else ""])
        print(f"seacable: sweep {p.done} of {p.total} cases{extra}; {p.elapsed:.0f} s{eta}",
              file=sys.stderr, end="\n" if done or not self.tty else "\r", flush=True)


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
    from .results import check_output_folder
    from .sweeps import load_sweep, sweep
    from .sweeps.engine import check_scheduler, check_workers

    check_scheduler(args.scheduler)
    if args.workers is not None:
        check_workers(args.workers, "--workers")
    spec = load_sweep(args.sweep)
    outdir = Path(args.output) if args.output else Path(spec.name)
    check_output_folder(outdir, "-o" if args.output else "the default output folder (-o)")
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


def _validate_sweep(name: str) -> list[str]:
    """Load a sweep file and check each of its cases as 'run' would; the messages of the invalid ones."""
    from .simulate import check
    from .sweeps import load_sweep

    spec = load_sweep(name)
    problems = []
    for c in spec.cases(require_valid=False):
        if c.case is None:
            problems.append(c.error)
            continue
        try:
            check(c.case)
        except SeacableError as err:
            values = ", ".join(f"{p} = {v!r}" for p, v in zip(spec.parameters, c.values))
            problems.append(f"case {c.index} ({values}): {err}")
    if not problems:
        print(f"{name}: valid sweep of {len(spec)} case(s) ({spec.kind} of {', '.join(spec.parameters)})")
    return problems


def _validate_case(name: str) -> list[str]:
    """Load a case file and do everything 'run' does before its time loop."""
    from .io import load_case
    from .simulate import check

    case = load_case(name)
    check(case)
    # a case file, or a MoorDyn file (a case with its own network of lines, no single 'line')
    analysis = getattr(getattr(case, "analysis", None), "type", None) or getattr(case, "analysis_type", "?")
    line = getattr(case, "line", None)
    detail = f", {len(line.segments)} segment(s), line length {line.length:g} m" if line is not None else ""
    if getattr(case, "lines", None) is not None and hasattr(case, "bodies"):  # a mooring-system case
        detail = f", {len(case.lines)} line(s), {len(case.bodies)} body(ies), {len(case.points)} point(s)"
    print(f"{name}: valid ({analysis} analysis{detail})")
    return []


def _cmd_validate(args) -> int:
    from .sweeps import is_sweep_file

    status = 0
    for name in args.cases:
        try:
            problems = _validate_sweep(name) if is_sweep_file(name) else _validate_case(name)
        except SeacableError as err:
            problems = [str(err)]
        for message in problems:
            where = "" if message.startswith(name) else f"{name}: "
            print(f"seacable: error: {where}{message}", file=sys.stderr)
        if problems:
            print(f"{name}: invalid" + (f" ({len(problems)} case(s))" if len(problems) > 1 else ""),
                  file=sys.stderr)
            status = EXIT_USER_ERROR
    return status


def _cmd_plot(args) -> int:
    from .plot import plot_result
    from .results import check_output_folder, check_result, read_netcdf

    path = Path(args.result)
    ds = read_netcdf(path)
    check_result(ds, f"result file '{path}'")
    outdir = Path(args.output) if args.output else path.parent
    check_output_folder(outdir, "-o")
    for png in plot_result(ds, outdir, prefix=path.stem):
        print(f"wrote {png}")
    return 0


def _cmd_animate(args) -> int:
    from .plot import animate_laying, animate_towline
    from .results import check_output_file, check_result, read_netcdf

    path = Path(args.result)
    ds = read_netcdf(path)
    analysis = ds.attrs.get("analysis")
    if analysis not in ("laying_dynamic", "towline_dynamic"):
        raise InputError(f"result file '{path}': animate needs a 'laying_dynamic' result or a 'towline_dynamic' "
                         f"result, got analysis '{analysis}'. Suggested fix: 'seacable plot {path}' makes the "
                         "figures of this result.")
    check_result(ds, f"result file '{path}'")
    if analysis == "towline_dynamic":
        animate, tag = animate_towline, "tow"
    else:
        animate, tag = animate_laying, "lay"
    out = Path(args.output) if args.output else path.parent / f"{path.stem}_{tag}.gif"
    check_output_file(out, "-o", (".gif", ".mp4"))
    written = animate(ds, out, fps=args.fps, max_frames=args.max_frames)
    print(f"wrote {written}")
    return 0


def _cmd_view(args) -> int:
    from .plot.view3d import view
    from .results import check_output_file, read_netcdf

    path = Path(args.result)
    out = Path(args.output) if args.output else path.with_suffix(".html")
    check_output_file(out, "-o", (".html", ".htm"))
    view(read_netcdf(path), out, max_frames=args.max_frames, source=f"result file '{path}'")
    print(f"wrote {out}")
    return 0


def _cmd_export(args) -> int:
    from .io.export import export_result

    written, skipped = export_result(args.result, args.format, args.output)
    for path in written:
        print(f"wrote {path}")
    if skipped:
        print(f"not exported (not along the states, or more than 1000 columns): {', '.join(skipped)}")
    return 0


def _cmd_convert(args) -> int:
    from .io.convert import convert

    print(f"wrote {convert(args.source, args.output)}")
    return 0


def _cmd_report(args) -> int:
    from .report import ReportOptions, make_report

    options = ReportOptions(storm_duration=args.storm_duration, quantile=args.quantile,
                            consequence_class=args.consequence_class, offset_limit=args.offset_limit,
                            scatter=args.scatter, tn_curve=args.tn_curve, nominal_diameter=args.nominal_diameter,
                            allowed_uplift=args.allowed_uplift, design_fatigue_factor=args.design_fatigue_factor)
    for path in make_report(args.source, args.output, options):
        print(f"wrote {path}")
    return 0


def _cmd_schema(args) -> int:
    from .io import case_schema

    print(case_schema(system=args.system))
    return 0


class _UsageError(Exception):
    """A command line argparse rejects (unknown option, a value that is not a number, ...)."""


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2 from main(), never SystemExit from inside
        raise _UsageError(f"{self.prog}: {message}. Suggested fix: see '{self.prog} --help'.")


def _number(text: str) -> float:
    return float(text)


def _whole(text: str) -> int:
    value = float(text)
    if not value.is_integer():
        raise ValueError(text)
    return int(value)


_number.__name__ = "number"
_whole.__name__ = "whole number"

#: numeric options: dest -> (option, unit, smallest allowed (inclusive), suggested fix)
_NUMERIC = {
    "time_step": ("--time-step", "s", None, "give the Newmark time step in seconds, e.g. --time-step 0.05"),
    "duration": ("--duration", "s", None, "give the simulated time in seconds, e.g. --duration 100"),
    "output_interval": ("--output-interval", "s", None,
                        "give the time between stored states in seconds, e.g. --output-interval 0.5"),
    "fps": ("--fps", "frames/s", 1, "give the frame rate, e.g. --fps 10"),
    "max_frames": ("--max-frames", "", 1, "give the largest number of frames, e.g. --max-frames 200"),
    "workers": ("--workers", "", 1, "give the number of worker processes, e.g. --workers 4, or leave it out"),
    "max_steps": ("--max-steps", "", None, "give the largest number of time steps, e.g. --max-steps 1e9"),
    "max_memory": ("--max-memory", "bytes", None,
                   "give the largest result memory in bytes, e.g. --max-memory 16e9"),
    "max_cases": ("--max-cases", "", 1, "give the largest number of sweep cases, e.g. --max-cases 1e6"),
    "storm_duration": ("--storm-duration", "s", None, "give the storm's duration in seconds, e.g. 10800 for 3 h"),
    "offset_limit": ("--offset-limit", "m", None, "give the allowed horizontal offset in metres, e.g. 30"),
    "nominal_diameter": ("--nominal-diameter", "m", None,
                         "give the chain's bar diameter or the rope's nominal diameter in metres, e.g. 0.095"),
}


def _check_options(args) -> None:
    """Every numeric option finite and positive (whole numbers >= 1 where counted); else InputError."""
    from ._validate import at_least, positive

    for dest, (option, unit, least, fix) in _NUMERIC.items():
        value = getattr(args, dest, None)
        if value is None:
            continue
        if least is None:
            positive(option, value, unit, fix)
        else:
            at_least(option, value, least, unit, fix)


@contextlib.contextmanager
def _limits(args):
    """Set SEACABLE_MAX_* from --max-steps, --max-memory and --max-cases for the command; restore after."""
    from ._limits import ENVIRONMENT

    saved = {env: os.environ.get(env) for env in ENVIRONMENT.values()}
    try:
        for dest, env in ENVIRONMENT.items():
            value = getattr(args, dest, None)
            if value is not None:
                os.environ[env] = repr(float(value))
        yield
    finally:
        for env, value in saved.items():
            if value is None:
                os.environ.pop(env, None)
            else:
                os.environ[env] = value


def _add_limits(p) -> None:
    p.add_argument("--max-steps", type=_number, help="largest number of time steps of one run (default 1e8; "
                                                     "or SEACABLE_MAX_STEPS)")
    p.add_argument("--max-memory", type=_number, help="largest memory of one run's stored results [bytes] "
                                                      "(default 8e9; or SEACABLE_MAX_MEMORY)")
    p.add_argument("--max-cases", type=_number, help="largest number of cases of a sweep (default 1e5; or "
                                                     "SEACABLE_MAX_CASES)")


@functools.cache
def _parser() -> argparse.ArgumentParser:
    """The command line's parser, built once per process (a parser is not changed by parsing; a test suite or a
    script calls :func:`main` thousands of times)."""
    return build_parser()


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="seacable",
        description="Statics and dynamics of marine cables: mooring lines, towed cables, cable laying. "
                    "SI units throughout.")
    parser.add_argument("--version", action="version", version=f"seacable {__version__}")
    parser.add_argument("--debug", action="store_true", help="show the traceback of an internal error")
    common = _Parser(add_help=False)
    common.add_argument("--debug", action="store_true", default=argparse.SUPPRESS,
                        help="show the traceback of an internal error")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)

    p = sub.add_parser("run", parents=[common],
                       help="run a case file and write its result (NetCDF) and plots (PNG)")
    p.add_argument("case", help="YAML case file, or a MoorDyn input file (lines and points)")
    p.add_argument("-o", "--output", help="result file (.nc); default CASE_NAME.nc")
    p.add_argument("--duration", type=_number, help="MoorDyn file: simulated time after the statics [s]")
    p.add_argument("--motion", help="MoorDyn file: CSV of vessel offsets (time, x, y, z) applied to every "
                                    "vessel point [s, m], or of rigid platform motions about the origin "
                                    "(time, surge, sway, heave, roll, pitch, yaw) [s, m, rad]; a deck's coupled "
                                    "bodies and rods follow the platform motions about their reference points")
    p.add_argument("--time-step", type=_number, help="MoorDyn file: Newmark time step [s] (0.1)")
    p.add_argument("--output-interval", type=_number, help="MoorDyn file: time between stored states [s] (0.5)")
    p.add_argument("--spectral-radius", type=_number,
                   help="MoorDyn file: generalised-alpha spectral radius in [0, 1] (1: average acceleration, the "
                        "default; 0.7-0.9 damps the ringing of stiff modes at a coarse step)")
    p.add_argument("--plot-dir", help="folder for the PNG plots; default beside the result")
    p.add_argument("--no-plots", action="store_true", help="write the result only")
    p.add_argument("-q", "--quiet", action="store_true", help="print nothing on stdout (no 'wrote' lines, no summary) "
                                                              "and no progress; warnings and errors still on stderr")
    _add_limits(p)
    p.set_defaults(func="_cmd_run")

    p = sub.add_parser("sweep", parents=[common],
                       help="run a sweep: a base case over a grid or a table of parameters, on Dask")
    p.add_argument("sweep", help="sweep file (YAML): 'base' (a case file) and 'grid' or 'table'")
    p.add_argument("-o", "--output", help="output folder: per-case results and the summary; default the sweep's "
                                          "name. Cases already there are not run again")
    p.add_argument("--scheduler", help="address of an existing Dask scheduler (tcp://host:8786), whose workers "
                                       "have seacable; default a local cluster on this machine's cores; "
                                       "'synchronous' runs the cases one by one in this process")
    p.add_argument("--workers", type=_whole, help="workers of the local cluster (default: one per core; at most 4 per core)")
    p.add_argument("--retry-failed", action="store_true", help="run again the cases that failed before")
    p.add_argument("--no-plots", action="store_true", help="write the results only")
    _add_limits(p)
    p.set_defaults(func="_cmd_sweep")

    p = sub.add_parser("validate", parents=[common],
                       help="check case and sweep files as 'run' would before computing, without running them")
    p.add_argument("cases", nargs="+", help="YAML case or sweep files")
    _add_limits(p)
    p.set_defaults(func="_cmd_validate")

    p = sub.add_parser("plot", parents=[common], help="make the standard figures (PNG) of a result file")
    p.add_argument("result", help="result file (.nc) written by 'seacable run'")
    p.add_argument("-o", "--output", help="folder for the PNG files; default beside the result")
    p.set_defaults(func="_cmd_plot")

    p = sub.add_parser("animate", parents=[common],
                       help="animate a cable lay (laying_dynamic) or a tow (towline_dynamic) as GIF or MP4")
    p.add_argument("result", help="result file (.nc) of a laying_dynamic or towline_dynamic run")
    p.add_argument("-o", "--output", help="animation file (.gif, or .mp4 with ffmpeg); default "
                                          "RESULT_lay.gif or RESULT_tow.gif beside the result")
    p.add_argument("--fps", type=_whole, default=10, help="frames per second (default 10)")
    p.add_argument("--max-frames", type=_whole, default=200,
                   help="largest number of frames; output times are subsampled evenly (default 200)")
    p.set_defaults(func="_cmd_animate")

    p = sub.add_parser("view", parents=[common],
                       help="3-D interactive view of a result (a self-contained HTML page): the lines coloured by "
                            "tension over the seabed, animated over time")
    p.add_argument("result", help="result file (.nc) of a run with line shapes (static, pushover or time domain)")
    p.add_argument("-o", "--output", help="the HTML page (.html); default RESULT.html beside the result")
    p.add_argument("--max-frames", type=_whole, default=120,
                   help="largest number of animation frames; output times are subsampled evenly (default 120)")
    p.set_defaults(func="_cmd_view")

    p = sub.add_parser("export", parents=[common],
                       help="write a result as files other tools read: CSV tables, or MoorDyn .out files")
    p.add_argument("result", help="result file (.nc)")
    p.add_argument("--format", required=True, choices=("csv", "moordyn"),
                   help="csv: a table of the states (RESULT.csv) and one of each line's nodes (RESULT_LINE.csv); "
                        "moordyn: MoorDyn v2's RESULT.out and RESULT_Line<N>.out")
    p.add_argument("-o", "--output", help="folder for the files (created if missing); default beside the result")
    p.set_defaults(func="_cmd_export")

    p = sub.add_parser("convert", parents=[common],
                       help="convert a MoorDyn input file into a seacable case file (YAML), or the reverse")
    p.add_argument("source", help="MoorDyn input file, or a seacable system case file (.yaml)")
    p.add_argument("-o", "--output", required=True, help="the file to write: case.yaml from a MoorDyn file, "
                                                         "deck.txt from a case file")
    p.set_defaults(func="_cmd_convert")

    p = sub.add_parser("report", parents=[common],
                       help="design report (HTML and CSV) of a mooring_dynamic or system_dynamic result or sweep: "
                            "extremes, DNV-OS-E301 and API RP 2SK checks, fatigue; or the cable checks of a "
                            "mooring_static or mooring_pushover result of a cable")
    p.add_argument("source", help="result file (.nc) of a time-domain mooring run (or of a cable's static or "
                                  "pushover run), or a folder written by 'seacable sweep' (its cases differing only "
                                  "in environment.waves.seed are seeds of one load case)")
    p.add_argument("-o", "--output", required=True,
                   help="the HTML report (.html); the tables go beside it as CSV (REPORT_extremes.csv, ...)")
    p.add_argument("--storm-duration", type=_number,
                   help="duration of the storm the extremes are raised to [s] (default: the runs' duration)")
    p.add_argument("--quantile", type=_number, default=0.9,
                   help="non-exceedance probability of the quantile of the storm maximum (default 0.9)")
    p.add_argument("--consequence-class", type=int, choices=(1, 2), default=1,
                   help="DNV-OS-E301 consequence class (default 1)")
    p.add_argument("--offset-limit", type=_number, help="allowed horizontal offset of the bodies [m] (default: "
                                                        "not checked)")
    p.add_argument("--allowed-uplift", type=_number, default=0.0,
                   help="allowed vertical force on an anchor [N] (default 0: a drag anchor takes no uplift)")
    p.add_argument("--scatter", help="scatter diagram, CSV with columns hs [m], tp [s], probability [-] (and "
                                     "optionally heading [rad]), matched to the load cases' sea states: the "
                                     "fatigue life")
    p.add_argument("--tn-curve", help="T-N curve of DNV-OS-E301: studless, stud, connecting, six_strand, "
                                      "spiral_strand or polyester (default: the line type's material, else its name "
                                      "where the name is not ambiguous)")
    p.add_argument("--design-fatigue-factor", type=_number, default=5.0,
                   help="design fatigue factor on the fatigue life (default 5, DNV-OS-E301 Ch.2 Sec.2 D; API RP 2SK: "
                        "3 for lines inspected regularly, 10 otherwise)")
    p.add_argument("--nominal-diameter", type=_number,
                   help="nominal diameter for the fatigue stress [m] (default: the line type's diameter over "
                        "its volume-equivalent ratio, 1.8 for studless chain)")
    p.set_defaults(func="_cmd_report")

    p = sub.add_parser("schema", parents=[common], help="print the JSON schema of case files")
    p.add_argument("--system", action="store_true",
                   help="the schema of mooring-system cases (points, bodies, lines) instead of single-line ones")
    p.set_defaults(func="_cmd_schema")
    return parser


_GUARD = {"armed": False, "holding": False, "held": []}
"""State of a ``run`` command's result against interrupts (see :func:`_terminate`)."""


def _terminate(signum, frame):
    """Ctrl-C, and SIGTERM (what batch schedulers send before killing a job): stop, keeping the result.

    Raises KeyboardInterrupt, which the time loops catch (they return what they computed) and
    records the request (:data:`seacable._atomic.interrupt_requested`), so that a case whose
    interrupt a library turned into another error is not taken for a failed case.

    While ``seacable run`` computes a result (``_GUARD["armed"]``), the first signal stops the time loop
    and every later one is held until the result file is written; so is any signal that comes once the
    loop has reached its end. Assembling and writing the result is short, and losing a whole run to a
    second Ctrl-C, or to a SIGTERM that came just after the last step, is what must not happen.
    """
    from ._atomic import interrupt_requested

    if _GUARD["holding"]:
        _GUARD["held"].append(signum)
        return
    interrupt_requested.set()
    if _GUARD["armed"]:
        _GUARD["holding"] = True
    raise KeyboardInterrupt


_terminate.seacable_hold = True  # a deferred_interrupts block hands a signal it held to this handler


def _computation_done() -> None:
    """The time loop reached its end: from now on a signal is held until the result is written."""
    if _GUARD["armed"]:
        _GUARD["holding"] = True


@contextlib.contextmanager
def _interrupts():
    """SIGINT and SIGTERM both stop the command as Ctrl-C does (main thread only); restored after."""
    from ._atomic import interrupt_requested

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    interrupt_requested.clear()
    previous = {sig: signal.signal(sig, _terminate) for sig in (signal.SIGINT, signal.SIGTERM)}
    try:
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, signal.SIG_DFL if handler is None else handler)
        interrupt_requested.clear()


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``seacable`` command. Returns the exit status.

    0: done; 1: a sweep in which some cases failed; 2: a user error (one line on stderr);
    3: an internal error (a bug; ``--debug`` shows the traceback); 130: interrupted (Ctrl-C or
    SIGTERM), with what was computed written.
    """
    parser = _parser()
    try:
        args = parser.parse_args(argv)
    except _UsageError as err:
        print(f"seacable: error: {err}", file=sys.stderr)
        return EXIT_USER_ERROR
    if args.command is None:
        parser.print_help()
        return EXIT_USER_ERROR
    with warnings.catch_warnings(), _interrupts():
        # the command line shows warnings (once each), whatever the filters of the caller
        warnings.simplefilter("default", SeacableWarning)
        warnings.showwarning = _show_warning
        try:
            _check_options(args)
            with _limits(args):
                # the command's function is looked up by name when it runs, not bound in the parser that is built
                # once per process: a function replaced after the first call (a test's monkeypatch) is the one run
                return globals()[args.func](args)
        except SeacableError as err:
            print(f"seacable: error: {err}", file=sys.stderr)
            return EXIT_USER_ERROR
        except KeyboardInterrupt:
            print("seacable: interrupted", file=sys.stderr)
            return EXIT_INTERRUPTED
        except Exception as err:
            from ._atomic import interrupt_requested

            if interrupt_requested.is_set():
                # Ctrl-C or SIGTERM that a library turned into another error (numba interrupted while it compiles
                # leaves "no compiled object yet"): an interrupt, not a bug
                print("seacable: interrupted", file=sys.stderr)
                return EXIT_INTERRUPTED
            if args.debug:
                raise
            print(f"seacable: internal error, a bug in seacable {__version__}: {type(err).__name__}: {err}. "
                  "Please report it to the seacable developers with the command and its input files; "
                  f"'seacable --debug {args.command} ...' shows the traceback.", file=sys.stderr)
            return EXIT_BUG


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())

"""Running a sweep on Dask: one task per case, results written as they finish, resumable.

Each case is one ``dask.distributed`` task. By default seacable starts a local cluster with one
single-threaded worker process per core and stops it at the end; ``scheduler="tcp://host:8786"``
sends the same sweep to an existing scheduler (its workers need seacable installed), and
``scheduler="synchronous"`` runs the cases one after another in this process, without Dask.

The output folder holds ``cases/NNNN.nc`` (each case's result) and ``cases/NNNN.json`` (its
record: status, error message, warnings, run time and design figures), written as each case
finishes, and at the end ``summary.nc`` and ``summary.csv``. A record is written after its result
and both are renamed into place, so a killed sweep leaves whole files only; running the sweep
again skips every case whose record matches the case (a hash of its full YAML), and so completes
only the missing ones. Cases that failed are skipped too unless ``retry_failed``; a case whose
worker died is always run again.
"""

from __future__ import annotations

import contextlib
import datetime
import json
import logging
import math
import os
import re
import time
import traceback
import uuid
import warnings
from collections.abc import Callable
from contextlib import ExitStack
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import xarray as xr

from .._atomic import atomic_write, clean_folder_once, deferred_interrupts, interrupt_requested
from .._version import __version__
from ..errors import InputError, SeacableError, SeacableWarning
from ..extremes import case_extremes
from ..line import LineType, Segment
from ..results import make_dataset, var, write_netcdf
from .spec import Sweep, SweepCase, load_sweep, parse_path

__all__ = ["SweepProgress", "check_workers", "run_case", "summary_dataset", "sweep", "work_estimate"]

#: ``scheduler`` value that runs the cases in this process, one after another, without Dask.
SYNCHRONOUS = "synchronous"


@dataclass(frozen=True)
class SweepProgress:
    """State of a running sweep, passed to the ``progress`` callback after each case."""

    done: int          #: cases finished, in this run and earlier ones (failed included)
    total: int         #: cases in the sweep
    failed: int        #: cases that failed
    reused: int        #: cases taken from an earlier run
    ran: int           #: cases run in this run so far
    elapsed: float     #: wall time of this run so far [s]
    record: dict | None  #: the record of the case that just finished (None for the first call)

    @property
    def remaining_time(self) -> float:
        """Rough time to the end from the pace of this run so far. [s]"""
        return math.nan if self.ran <= 0 else self.elapsed / self.ran * (self.total - self.done)


@dataclass(frozen=True)
class ResultTarget:
    """Where a worker writes a case's result itself, if it sees the sweep's output folder."""

    folder: str   #: the sweep's ``cases`` folder, as the client sees it
    token: str    #: a file the client made there: a worker sees it only if they share the folder
    stem: str     #: the case's file name stem
    attrs: dict   #: attributes stamped on the result (sweep name, case index and key)

    def visible(self) -> bool:
        return os.path.exists(os.path.join(self.folder, self.token))


def write_result(ds: xr.Dataset, folder: Path, stem: str, attrs: dict) -> Path:
    """Write a case's result as ``folder/STEM.nc``, whole: under a temporary name, then renamed."""
    import dask

    ds.attrs.update(attrs)
    # xarray locks a write through the default Dask scheduler, which for a distributed client is a
    # round trip to the scheduler per variable: this write is local, so its lock is too
    with dask.config.set(scheduler="synchronous"):
        return write_netcdf(ds, Path(folder) / f"{stem}.nc")   # atomic: see seacable._atomic


def run_case(case, target: ResultTarget | None = None) -> dict:
    """Run one case and reduce it: the task each worker runs.

    Parameters
    ----------
    case
        The :class:`~seacable.case.Case`.
    target
        Where to write the result when this process sees the sweep's folder (a local cluster, a
        shared file system); otherwise the result is returned for the client to write.

    Returns
    -------
    dict
        ``status`` ("done" or "failed"), ``error`` (message, "" when done), ``warnings`` (the
        SeacableWarnings it raised), ``wall_time`` [s], ``extremes`` ({name: (value, units,
        long_name)}), ``result`` (the Dataset, or None when it failed or was written here) and
        ``written`` (True when it was written here).

    Raises
    ------
    KeyboardInterrupt
        If the run was interrupted: its partial result is not the case's.
    """
    from ..simulate import run

    t0 = time.perf_counter()
    out = {"status": "failed", "error": "", "warnings": [], "extremes": {}, "result": None, "written": False}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", SeacableWarning)
        try:
            ds = run(case)
            extremes = case_extremes(ds)
        except SeacableError as err:
            out["error"] = f"{type(err).__name__}: {err}"
        except Exception as err:  # noqa: BLE001  (a bug: keep it with the case, run the others)
            out["error"] = (f"internal error, please report it: {type(err).__name__}: {err}\n"
                            + traceback.format_exc())
        else:
            if ds.attrs.get("interrupted"):
                raise KeyboardInterrupt
            out.update(status="done", result=ds, extremes={
                k: (float(v.values), v.attrs["units"], v.attrs["long_name"]) for k, v in extremes.items()})
    if out["status"] == "failed" and interrupt_requested.is_set():
        raise KeyboardInterrupt   # failed because it was interrupted: not the case's failure
    out["warnings"] = list(dict.fromkeys(str(w.message) for w in caught if issubclass(w.category, SeacableWarning)))
    if out["result"] is not None and target is not None and target.visible():
        write_result(out.pop("result"), Path(target.folder), target.stem, target.attrs)
        out.update(result=None, written=True)
    out["wall_time"] = time.perf_counter() - t0
    return out


def work_estimate(case) -> float:
    """Rough work of a case (time steps x nodes), to start the longest cases first.

    Only an ordering: with a few cases per worker, starting the longest first keeps one long case
    from running alone at the end.
    """
    a = case.analysis
    kind = a.type
    try:
        if kind == "laying_dynamic":
            from ..statics.laying import laying_angle

            env, lt = case.environment, case.line.segments[0].line_type
            speed = max([a.ship.speed or 0.0, *(a.ship.speeds or ())]) or 1.0
            alpha = float(laying_angle(speed, lt.submerged_weight(env.water_density, env.gravity), lt.diameter,
                                       lt.effective_drag()[0], env.water_density))
            nodes = (env.depth or 100.0) / math.sin(alpha) / a.segment_length
            return a.duration * a.steps_per_segment * speed / a.segment_length * nodes
        if kind == "towed_dynamic":
            return a.duration / a.time_step * a.n_nodes
        if kind == "mooring_dynamic":
            return a.duration / a.time_step * (a.n_elements or 20)
        if kind == "towline_dynamic":
            return a.duration * a.n_elements ** 2
    except Exception:  # noqa: BLE001  (an estimate only: never let it stop a sweep)
        return 0.0
    return 1.0


def _seacable_version() -> str:
    """The version of seacable where this runs (a Dask worker: :func:`check_scheduler`)."""
    from .._version import __version__ as version

    return version


_ADDRESS = re.compile(r"^(?:(?P<scheme>[a-z][a-z0-9+]*)://)?(?P<host>\[[0-9a-fA-F:.]+\]|[A-Za-z0-9_.-]+):"
                      r"(?P<port>\d{1,5})/?$")
_SCHEMES = ("tcp", "tls", "ws", "wss", "ucx")


def check_scheduler(scheduler) -> None:
    """Check the form of a scheduler address before connecting: ``[tcp://]host:port`` or 'synchronous'.

    Raises
    ------
    InputError
        If ``scheduler`` is neither None, a ``distributed.Client``, 'synchronous' nor an address.
    """
    if scheduler is None or scheduler == SYNCHRONOUS or not isinstance(scheduler, str):
        if scheduler is None or scheduler == SYNCHRONOUS or type(scheduler).__name__ == "Client":
            return
        raise InputError(f"--scheduler must be an address (tcp://host:8786), '{SYNCHRONOUS}' or a "
                         f"distributed.Client, got {type(scheduler).__name__}.")
    m = _ADDRESS.match(scheduler.strip())
    ok = m is not None and (m["scheme"] or "tcp") in _SCHEMES and 0 < int(m["port"]) < 65536
    if not ok:
        raise InputError(f"--scheduler '{scheduler}' is not the address of a Dask scheduler: expected "
                         f"tcp://host:port (e.g. tcp://10.0.0.5:8786; schemes {', '.join(_SCHEMES)}) or "
                         f"'{SYNCHRONOUS}'. Suggested fix: give the address 'dask scheduler' prints, or leave "
                         "out --scheduler to run on this machine's cores.")


def _cores() -> int:
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1


#: most worker processes of a local cluster per core: more only wait (each case runs on one core) and each
#: costs a Python process (about 100 MB and a second or two to start)
WORKERS_PER_CORE = 4


def check_workers(workers, option: str = "workers") -> int:
    """Check the size of a local cluster: a whole number from 1 to :data:`WORKERS_PER_CORE` per core.

    Raises
    ------
    InputError
        Naming ``option``, the value, the bound and this machine's cores. 100 000 workers would not
        start before the machine ran out of memory and processes, and the sweep would seem to hang.
    """
    if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)) or workers < 1:
        raise InputError(f"{option} must be a whole number >= 1, got {workers!r}. Suggested fix: leave it "
                         "out for one worker per core.")
    cores = _cores()
    most = WORKERS_PER_CORE * cores
    if workers > most:
        raise InputError(f"{option} must be at most {most} ({WORKERS_PER_CORE} per core of this machine's {cores}), "
                         f"got {workers}: each worker is a process of its own (about 100 MB), and the cases run "
                         f"one per core whatever their number. Suggested fix: leave out {option} (one worker per "
                         f"core), or give {option} {cores}; for more cores, start a Dask cluster and give its "
                         "address with --scheduler.")
    return int(workers)


def _reachable(scheduler: str, timeout: float = 5.0) -> None:
    """Open (and close) a TCP connection to the scheduler, so that a wrong address fails in seconds.

    A ``distributed.Client`` that fails to connect hangs for 20 s when it is garbage-collected and
    prints an ignored exception; this probe keeps a wrong address from ever reaching it.
    """
    import socket

    m = _ADDRESS.match(scheduler.strip())
    if (m["scheme"] or "tcp") not in ("tcp", "tls"):
        return
    host = m["host"].strip("[]")
    try:
        with socket.create_connection((host, int(m["port"])), timeout=timeout):
            pass
    except OSError as err:
        raise InputError(f"cannot reach the Dask scheduler at '{scheduler}': {err.strerror or err}. Suggested "
                         "fix: check the address (e.g. tcp://host:8786) and that 'dask scheduler' runs there, "
                         "or leave out --scheduler to run on this machine.") from None


def _connect(stack: ExitStack, scheduler, workers: int | None):
    """A Dask client: the user's, one to a scheduler address, or one to a local cluster started here."""
    from distributed import Client, LocalCluster

    if isinstance(scheduler, Client):
        return scheduler
    if scheduler is None:
        n = workers or _cores()
        cluster = stack.enter_context(LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                                   dashboard_address=None, silence_logs=logging.ERROR))
        return stack.enter_context(Client(cluster, set_as_default=False))
    try:
        client = stack.enter_context(Client(scheduler, timeout="10s", set_as_default=False))
    except (OSError, TimeoutError, ValueError) as err:
        raise InputError(f"cannot reach the Dask scheduler at '{scheduler}': {err}. Suggested fix: check the "
                         "address (e.g. tcp://host:8786) and that 'dask scheduler' runs there, or leave out "
                         "--scheduler to run on this machine.") from None
    try:
        versions = client.run(_seacable_version)
    except ImportError:
        raise InputError(f"the workers of the Dask scheduler at '{scheduler}' cannot import seacable. "
                         f"Suggested fix: install seacable {__version__} where the workers run.") from None
    if not versions:
        raise InputError(f"the Dask scheduler at '{scheduler}' has no workers. Suggested fix: start some with "
                         f"'dask worker {scheduler}'.")
    other = sorted({v for v in versions.values() if v != __version__})
    if other:
        warnings.warn(f"workers at '{scheduler}' run seacable {', '.join(other)}, this client "
                      f"{__version__}; results may differ from a local run.", SeacableWarning, stacklevel=3)
    return client


class _Store:
    """The output folder: per-case results and records, written whole (renamed into place)."""

    def __init__(self, outdir: Path, sweep_name: str):
        self.root = Path(outdir)
        self.cases = self.root / "cases"
        self.sweep_name = sweep_name
        try:
            self.cases.mkdir(parents=True, exist_ok=True)
        except OSError as err:
            raise InputError(f"cannot create the output folder '{self.cases}': {err}. Suggested fix: give -o "
                             "a folder you can write to.") from None
        clean_folder_once(self.root)
        clean_folder_once(self.cases)   # the temporary files of a sweep killed outright (SIGKILL)
        for stale in self.cases.glob(".sweep-*.token"):
            stale.unlink(missing_ok=True)
        self.damaged: list[str] = []   # the cases recorded done whose result file is damaged (earlier())
        self.token = f".sweep-{uuid.uuid4().hex}.token"
        (self.cases / self.token).touch()

    def close(self) -> None:
        (self.cases / self.token).unlink(missing_ok=True)

    def target(self, sc: SweepCase) -> ResultTarget:
        return ResultTarget(str(self.cases.resolve()), self.token, sc.stem,
                            {"sweep": self.sweep_name, "sweep_case": sc.index, "sweep_key": sc.key})

    def result_path(self, sc: SweepCase) -> Path:
        return self.cases / f"{sc.stem}.nc"

    def record_path(self, sc: SweepCase) -> Path:
        return self.cases / f"{sc.stem}.json"

    def earlier(self, sc: SweepCase, retry_failed: bool) -> dict | None:
        """The record of an earlier run of this very case, if it is to be kept."""
        try:
            record = json.loads(self.record_path(sc).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None
        if record.get("key") != sc.key:
            return None
        if record.get("status") == "done":
            problem = self.damage(sc, record)
            if problem is None:
                return record
            self.damaged.append(f"case {sc.index} ({self.result_path(sc)}: {problem})")
            return None
        if record.get("status") == "failed" and not retry_failed and not record.get("retry"):
            return record
        return None

    def damage(self, sc: SweepCase, record: dict) -> str | None:
        """What is wrong with the result file of a case recorded as done; None if it is whole.

        The record is not trusted: the file must exist, have the size recorded when it was written,
        open as NetCDF, belong to this case (its ``sweep_key``) and hold the variables of its analysis
        (:data:`seacable.results.ANALYSIS_VARIABLES`). Its data are not read: a sweep of thousands of
        cases resumes in seconds.
        """
        import netCDF4

        from ..results import ANALYSIS_VARIABLES

        path = self.result_path(sc)
        try:
            size = path.stat().st_size
        except OSError:
            return "missing"
        if record.get("result_bytes") is not None and size != record["result_bytes"]:
            return f"{size} bytes, {record['result_bytes']} when it was written"
        try:
            with netCDF4.Dataset(path, "r") as nc:
                names = set(nc.variables) | set(nc.dimensions)
                attrs = {k: nc.getncattr(k) for k in ("analysis", "sweep_key") if k in nc.ncattrs()}
        except Exception as err:  # noqa: BLE001  (whatever the library says of a damaged file)
            return f"not a readable NetCDF file ({err})"
        if attrs.get("sweep_key", sc.key) != sc.key:
            return "the result of another case"
        analysis = attrs.get("analysis")
        if analysis is None:
            return "no 'analysis' attribute"
        missing = [n for n in ANALYSIS_VARIABLES.get(analysis, ()) if n not in names]
        if missing:
            return f"without the variable(s) {', '.join(missing)} of a '{analysis}' result"
        return None

    def write(self, sc: SweepCase, outcome: dict) -> dict:
        """Write the case's result (unless its worker did) and then its record."""
        record = {"index": sc.index, "name": sc.name, "key": sc.key, "values": list(sc.values),
                  "status": outcome["status"], "error": outcome["error"], "warnings": outcome["warnings"],
                  "wall_time": outcome["wall_time"], "extremes": outcome["extremes"],
                  "retry": bool(outcome.get("retry", False)), "seacable_version": __version__,
                  "finished": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds")}
        text = json.dumps(record, indent=1, default=str)
        with deferred_interrupts():   # the result and its record, both or neither
            if outcome.get("result") is not None:
                target = self.target(sc)
                write_result(outcome["result"], self.cases, sc.stem, target.attrs)
            if record["status"] == "done":   # the size the result has whole: see damage()
                with contextlib.suppress(OSError):
                    record["result_bytes"] = self.result_path(sc).stat().st_size
                text = json.dumps(record, indent=1, default=str)
            atomic_write(self.record_path(sc), lambda tmp: tmp.write_text(text, encoding="utf-8"))
        return record


def _invalid(sc: SweepCase) -> dict:
    return {"status": "failed", "error": f"InputError: {sc.error}", "warnings": [], "wall_time": 0.0,
            "extremes": {}}


def sweep(spec: Sweep | str | Path, outdir: str | Path, *, scheduler=None, workers: int | None = None,
          retry_failed: bool = False, progress: Callable[[SweepProgress], None] | None = None,
          write_summary: bool = True) -> xr.Dataset:
    """Run every case of a sweep and return its summary.

    Parameters
    ----------
    spec
        A :class:`~seacable.sweeps.Sweep`, or a sweep file (YAML).
    outdir
        Output folder: ``cases/NNNN.nc`` and ``cases/NNNN.json`` per case, ``summary.nc`` and
        ``summary.csv``. Cases already there (same case, same result) are not run again.
    scheduler
        None (default): a local Dask cluster on this machine's cores, started and stopped here.
        An address (``"tcp://host:8786"``) or a ``distributed.Client``: an existing cluster, whose
        workers need seacable. ``"synchronous"``: one case after another in this process.
    workers
        Workers of the local cluster; default one per core.
    retry_failed
        Run again the cases that failed in an earlier run (by default their record is kept).
    progress
        Called with a :class:`SweepProgress` once at the start and after each case.
    write_summary
        Write ``summary.nc`` and ``summary.csv`` (the Dataset is returned either way).

    Returns
    -------
    xarray.Dataset
        The summary (see :func:`summary_dataset`); attribute ``interrupted`` is 1 if the sweep was
        stopped (Ctrl-C) before every case ran.

    Raises
    ------
    InputError, CaseFileError
        If the sweep file is bad (an unknown parameter path, say); then nothing runs.
    """
    sweep_ = spec if isinstance(spec, Sweep) else load_sweep(spec)
    if workers is not None:
        check_workers(workers)
        if scheduler is not None:
            raise InputError(f"workers ({workers}) sizes the local cluster seacable starts; with scheduler "
                             f"{scheduler!r} it has no meaning. Suggested fix: leave out one of the two.")
    check_scheduler(scheduler)
    if isinstance(scheduler, str) and scheduler != SYNCHRONOUS:
        _reachable(scheduler)   # before anything is written
    cases = sweep_.cases()
    store = _Store(Path(outdir), sweep_.name)
    atomic_write(store.root / "sweep.yaml", lambda tmp: tmp.write_text(sweep_.text, encoding="utf-8"))
    t0 = time.perf_counter()
    records: dict[int, dict] = {}
    reused: set[int] = set()
    ran = 0

    def report(record):
        if progress is not None:
            failed = sum(r["status"] == "failed" for r in records.values())
            progress(SweepProgress(len(records), len(cases), failed, len(reused), ran,
                                   time.perf_counter() - t0, record))

    for sc in cases:
        earlier = store.earlier(sc, retry_failed)
        if earlier is not None:
            records[sc.index] = earlier
            reused.add(sc.index)
    if store.damaged:
        shown = "; ".join(store.damaged[:10]) + (f"; and {len(store.damaged) - 10} more" if len(store.damaged) > 10
                                                  else "")
        warnings.warn(f"{len(store.damaged)} case result(s) recorded as done in '{store.cases}' are damaged or "
                      f"missing, and are run again: {shown}.", SeacableWarning, stacklevel=2)
    report(None)
    for sc in cases:
        if sc.case is None and sc.index not in records:
            records[sc.index] = store.write(sc, _invalid(sc))
            report(records[sc.index])
    todo = [sc for sc in cases if sc.index not in records]

    def finished(sc, outcome):
        nonlocal ran
        ran += 1
        records[sc.index] = store.write(sc, outcome)
        report(records[sc.index])

    interrupted = False
    try:
        if scheduler == SYNCHRONOUS:
            for sc in todo:
                finished(sc, run_case(sc.case, store.target(sc)))
        elif todo:
            _run_dask(todo, scheduler, workers, store, finished)
    except KeyboardInterrupt:
        interrupted = True
    finally:
        store.close()
    summary = summary_dataset(sweep_, records, reused)
    summary.attrs["interrupted"] = int(interrupted)
    summary.attrs["wall_time"] = round(time.perf_counter() - t0, 3)
    if write_summary:
        try:  # a second Ctrl-C while the summary is written still leaves it whole
            with deferred_interrupts():
                write_netcdf(summary, store.root / "summary.nc")
                table = summary_table(summary)
                atomic_write(store.root / "summary.csv", table.to_csv)
        except KeyboardInterrupt:
            summary.attrs["interrupted"] = 1
    return summary


def _run_dask(todo: list[SweepCase], scheduler, workers, store: _Store, done: Callable) -> None:
    """Submit one task per case, longest first; hand each outcome to ``done`` as it finishes."""
    from concurrent.futures import CancelledError

    from distributed import KilledWorker, as_completed

    with ExitStack() as stack:
        client = _connect(stack, scheduler, workers)
        futures = {}
        # longest first: submitted in that order (the first tasks start as soon as they arrive) and
        # with that priority (for the queue), so that no long case runs alone at the end
        work = {sc.index: work_estimate(sc.case) for sc in todo}
        try:
            for sc in sorted(todo, key=lambda sc: -work[sc.index]):
                fut = client.submit(run_case, sc.case, store.target(sc), key=f"seacable-case-{sc.stem}-{sc.key[:16]}",
                                    pure=False, priority=work[sc.index])
                futures[fut] = sc
            for fut in as_completed(list(futures), loop=client.loop):
                sc = futures.pop(fut)
                try:
                    outcome = fut.result()
                except KilledWorker as err:
                    outcome = {**_invalid(sc), "retry": True,
                               "error": f"the case's worker died ({err}); out of memory, or a crash. It will "
                                        "run again when the sweep is run again."}
                except CancelledError as err:
                    outcome = {**_invalid(sc), "retry": True, "error": f"cancelled: {err}"}
                fut.release()
                done(sc, outcome)
        finally:
            if futures:
                client.cancel(list(futures))


def _parameter_units(case, parts) -> str:
    """Units of a swept parameter, from the description of its field ("... [m/s]")."""
    node, model, field = case, None, parts[-1]
    if parts[0] == "line_types":
        model = LineType
    else:
        for p in parts[:-1]:
            node = node[p] if isinstance(p, int) and isinstance(node, (list, tuple)) else getattr(node, str(p), None)
            if node is None:
                return ""
        model = type(node)
        if parts[:-1] == ("line",) and field not in getattr(model, "model_fields", {}):
            model = Segment  # the short form 'line: {line_type, length}'
    info = getattr(model, "model_fields", {}).get(field)
    m = re.search(r"\[([^\]]+)\]\s*$", (info.description or "") if info else "")
    unit = m.group(1) if m else ""
    return "1" if unit == "-" else unit


def _column(values, unit: str = "") -> np.ndarray:
    if unit and any(isinstance(v, str) for v in values):
        # numbers with units ("3 kn") as the cases read them: the column in the field's SI unit
        from .._units import UnitProblem, to_si

        try:
            values = [to_si(v, unit) if isinstance(v, str) else v for v in values]
        except (UnitProblem, ValueError):
            pass
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
        return np.array(values, float)
    return np.array([v if isinstance(v, str) else json.dumps(v) for v in values], dtype=object)


def summary_dataset(sweep_: Sweep, records: dict[int, dict], reused=frozenset()) -> xr.Dataset:
    """One row per case: the swept parameters (coordinates), status, error and design figures.

    Dims ``case``; coordinates ``case`` (index), ``name`` and one per swept parameter, named by its
    path; variables ``status`` ("done", "failed" or "not run"), ``error`` (the message of a failed
    case), ``warnings``, ``wall_time`` [s], ``reused`` (1: taken from an earlier run) and the
    design figures of :func:`seacable.extremes.case_extremes` (NaN where a case did not run).
    """
    cases = sweep_.cases()
    n = len(cases)
    first = next(c.case for c in cases if c.case is not None)
    coords = {"case": var("case", np.arange(n), "1", "case index"),
              "name": var("case", np.array([c.name for c in cases], dtype=object), "1", "case name")}
    for k, path in enumerate(sweep_.parameters):
        unit = _parameter_units(first, parse_path(path))
        coords[path] = var("case", _column([c.values[k] for c in cases], unit), unit, path)
    get = [records.get(c.index) for c in cases]

    def text(key, join=""):
        return np.array([join.join(r[key]) if isinstance(r and r[key], list) else (r[key] if r else "")
                         for r in get], dtype=object)

    data = {
        "status": var("case", np.array([r["status"] if r else "not run" for r in get], dtype=object), "1",
                      "status of the case (done, failed, not run)"),
        "error": var("case", text("error"), "1", "error message of a failed case"),
        "warnings": var("case", text("warnings", "\n"), "1", "warnings of the case"),
        "wall_time": var("case", np.array([r["wall_time"] if r else np.nan for r in get], float), "s",
                         "wall time of the case"),
        "reused": var("case", np.array([c.index in reused for c in cases], np.int8), "1",
                      "result taken from an earlier run of the sweep"),
    }
    meta = {}
    for r in get:
        for name, (_, units, long_name) in (r or {}).get("extremes", {}).items():
            meta.setdefault(name, (units, long_name))
    for name, (units, long_name) in meta.items():
        values = np.array([(r or {}).get("extremes", {}).get(name, (np.nan,))[0] for r in get], float)
        data[name] = var("case", values, units, long_name)
    status = data["status"].values
    ds = make_dataset(data, coords, analysis="sweep", title=sweep_.name,
                      settings={"parameters": list(sweep_.parameters), "kind": sweep_.kind},
                      references=())
    ds.attrs.update(sweep=sweep_.text, parameters=json.dumps(list(sweep_.parameters)),
                    case_analysis=first.analysis.type, cases=n, done=int(np.sum(status == "done")),
                    failed=int(np.sum(status == "failed")), not_run=int(np.sum(status == "not run")))
    if sweep_.description:
        ds.attrs["comment"] = sweep_.description
    return ds


def summary_table(summary: xr.Dataset):
    """The summary as a pandas DataFrame, one row per case (index: case)."""
    table = summary.reset_coords().to_dataframe()
    first = ["name", *json.loads(summary.attrs["parameters"])]
    return table[first + [c for c in table.columns if c not in first]]

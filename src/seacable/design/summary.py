"""Design tables of time-domain mooring results (issue 20): extremes, code checks and fatigue, per load case and
line, as pandas DataFrames.

The tables read results only (``mooring_dynamic`` and ``system_dynamic`` result files or Datasets, and the
folders ``seacable sweep`` writes), never a model's internals:

- :func:`read_results` lists the runs and groups them into load cases: the runs of a sweep that differ only
  in ``environment.waves.seed`` are the seeds of one load case.
- :func:`seed_table`: per run (seed), line and end (fairlead, anchor), the largest tension, its mean and
  standard deviation (:func:`~seacable.design.statistics.mean_and_dynamic`), and the storm maximum from a
  3-parameter Weibull fit of the record's peaks (:func:`~seacable.design.statistics.weibull_maximum`).
- :func:`extremes_table`: per load case, line and end, the seeds' maxima, the Gumbel fit over seeds
  (:func:`~seacable.design.statistics.gumbel_maximum`), the mean of the seeds' Weibull estimates, and the
  design maximum the checks use, with its basis.
- :func:`checks_table`: DNV-OS-E301 ULS (intact) or ALS (a line failed or removed), API RP 2SK dynamic intact
  or damaged, anchor uplift and the body offset (:mod:`seacable.design.checks`), one row per check, with a
  status "pass", "FAIL" or "not checked: <why>".
- :func:`fatigue_table` and :func:`fatigue_life_table`: Miner's damage of each load case from the rainflow
  count of the fairlead tension (:mod:`seacable.design.fatigue`), and the life over a scatter diagram.
- :func:`design_tables`: the runs and the tables of extremes, checks and fatigue in one pass over the results
  (each result file opened once: the report's reading).

Tensions are in N, durations in s, offsets in m, lives in years.
"""

from __future__ import annotations

import contextlib
import copy
import functools
import json
import math
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd
import xarray as xr
import yaml

from .._model import load_yaml
from .._window import statistics_window
from ..errors import InputError
from ..results import check_time, open_netcdf
from . import combination, fatigue, statistics
from .fatigue import resolve_tn_curve
from .scatter import HEADING_PATH, HS_PATH, SEED_PATH, TP_PATH, read_scatter, scatter_probabilities

__all__ = ["DYNAMIC_ANALYSES", "HEADING_PATH", "HS_PATH", "SEED_PATH", "TP_PATH", "LineInfo", "Run",
           "checks_table", "curve_of_line", "design_tables", "extremes_table", "fatigue_life_table", "fatigue_table", "line_info",
           "line_names", "line_series", "read_results", "read_scatter", "resolve_tn_curve", "seed_table"]

#: The analyses whose results the design tables read.
DYNAMIC_ANALYSES = ("mooring_dynamic", "system_dynamic")
_ENDS = ("fairlead", "anchor")

#: Volume-equivalent over nominal diameter of a line type, by T-N curve: MoorPy's default line properties
#: (Hall et al. 2021, MoorPy, NREL; the 'MoorProps' table): studless chain 1.8, stud-link chain 1.89,
#: wire rope 0.8. The case's ``diameter`` is the volume-equivalent (hydrodynamic) one.
VOLUME_EQUIVALENT_RATIO = {"studless_chain": 1.8, "stud_chain": 1.89, "connecting_link": 1.8,
                           "six_strand_rope": 0.8, "spiral_strand_rope": 0.8}

GUMBEL_REFERENCE = "DNV-OS-E301 (2010) Ch.2 Sec.2 B; DNV-RP-C205 (2021) 3.5.8"
WEIBULL_REFERENCE = "Naess & Moan (2013), Stochastic Dynamics of Marine Structures, ch. 6"


# ---------------------------------------------------------------------------------------------- the runs

@dataclass
class Run:
    """One run (a seed) of a load case.

    Attributes
    ----------
    name
        The case's name.
    load_case
        The label of its load case (the swept parameters other than the seed, or the case's name).
    seed
        Its wave seed, None when it has no irregular sea.
    parameters
        The swept parameters (key path -> value) and the case's sea state (``environment.waves.hs``, ``tp``,
        ``heading``, ``seed``) where the case holds one.
    source
        The result: a file (read when needed) or a Dataset.
    """

    name: str
    load_case: str
    seed: int | None
    parameters: dict = field(default_factory=dict)
    source: Path | xr.Dataset | None = None

    @contextlib.contextmanager
    def open(self) -> Iterator[xr.Dataset]:
        """The result Dataset (a file is opened lazily and closed after the block)."""
        if isinstance(self.source, xr.Dataset):
            yield self.source
            return
        try:
            ds = open_netcdf(self.source)   # time in seconds from the start (the file's is CF time)
        except (OSError, ValueError, RuntimeError, KeyError, TypeError) as err:
            raise InputError(f"result file '{self.source}' cannot be read: {err}. Suggested fix: give a file "
                             "written by 'seacable run' or 'seacable sweep'.") from None
        try:
            yield ds
        finally:
            ds.close()


def _check_dynamic(ds: xr.Dataset, where: str) -> None:
    analysis = ds.attrs.get("analysis")
    if analysis not in DYNAMIC_ANALYSES:
        raise InputError(f"{where} has analysis '{analysis}'; the design tables need a time-domain mooring result "
                         f"({' or '.join(DYNAMIC_ANALYSES)}). Suggested fix: run a mooring_dynamic or "
                         "system_dynamic case (or a sweep of them) and give its result.")
    for name in ("time", "fairlead_tension", "anchor_tension"):
        if name not in ds.variables:
            raise InputError(f"{where} is a '{analysis}' result without '{name}'. Suggested fix: give the file "
                             "written by 'seacable run' or 'seacable sweep'.")
    check_time(ds, where)


def case_data(ds: xr.Dataset) -> dict | None:
    """The case stored with a result (its ``case`` attribute, YAML) as a mapping; None when it has none."""
    text = ds.attrs.get("case")
    if not text:
        return None
    data = _parsed_case(text)
    return copy.deepcopy(data) if data is not None else None  # a copy: the caller may change it


@functools.lru_cache(maxsize=64)
def _parsed_case(text: str) -> dict | None:
    """A case's YAML text as a mapping, parsed once per text (a report reads each result's case for
    every table and figure); None when it is not a mapping."""
    try:
        data = load_yaml(text)
    except yaml.YAMLError:
        return None
    return data if isinstance(data, dict) else None


def _sea_state(data: dict | None) -> dict:
    """The case's irregular sea: environment.waves.hs, tp, heading and seed (those it holds)."""
    waves = ((data or {}).get("environment") or {}).get("waves") or {}
    out = {}
    for key in ("hs", "tp", "heading", "seed"):
        if isinstance(waves, dict) and waves.get(key) is not None and "spectrum" in waves:
            out[f"environment.waves.{key}"] = waves[key]
    return out


def _fmt(value) -> str:
    if isinstance(value, (float, np.floating)):
        return f"{float(value):.4g}"
    return str(value)


def _label(parameters: dict, units: dict) -> str:
    """``name = value unit, ...``: a parameter by its path's last part (last two when two end alike)."""
    last = [path.rsplit(".", 1)[-1] for path in parameters]
    parts = []
    for (path, value), name in zip(parameters.items(), last, strict=True):
        if last.count(name) > 1:
            name = ".".join(path.split(".")[-2:])
        unit = units.get(path, "")
        unit = "" if unit in ("", "1") else f" {unit}"
        parts.append(f"{name} = {_fmt(value)}{unit}")
    return ", ".join(parts)


def read_results(source, visit: Callable[[Run, xr.Dataset], None] | None = None) -> list[Run]:
    """The runs of a result file, a sweep folder, a Dataset, or load cases of Datasets.

    Parameters
    ----------
    source
        A result file (``.nc`` of a mooring_dynamic or system_dynamic run); a folder ``seacable sweep`` wrote
        (``summary.nc`` and ``cases/``: cases that differ only in ``environment.waves.seed`` are the seeds of
        one load case; failed cases are left out); a result Dataset; or a mapping load case -> Datasets (its
        seeds).

    visit
        Called as ``visit(run, ds)`` with each run, in order, and its result while it is open: what reads
        the results once (:func:`design_tables`) does its work there.

    Returns
    -------
    list of Run
        In the order of the sweep's cases.

    Raises
    ------
    InputError
        If the path does not exist, is not a result or a sweep folder, holds no completed case, or a result is
        not of a time-domain mooring analysis.
    """
    if isinstance(source, xr.Dataset):
        return [_dataset_run(source, None, visit)]
    if isinstance(source, Mapping):
        runs = []
        for label, datasets in source.items():
            if isinstance(datasets, xr.Dataset):
                datasets = [datasets]
            runs.extend(_dataset_run(ds, str(label), visit) for ds in datasets)
        if not runs:
            raise InputError("no result given: the mapping of load cases holds no Dataset. Suggested fix: give "
                             "{'load case': [ds_seed1, ds_seed2, ...]}.")
        return runs
    path = Path(source)
    if path.is_dir():
        return _sweep_runs(path, visit)
    if not path.exists():
        raise InputError(f"'{path}' does not exist. Suggested fix: give a result file (.nc) written by 'seacable "
                         "run' or a folder written by 'seacable sweep'.")
    with Run("", "", None, {}, path).open() as ds:
        _check_dynamic(ds, f"result file '{path}'")
        data = case_data(ds)
        name = str(ds.attrs.get("case_name") or ds.attrs.get("title") or path.stem)
        sea = _sea_state(data)
        seed = sea.get(SEED_PATH)
        run = Run(name, name, None if seed is None else int(seed), sea, path)
        if visit is not None:
            visit(run, ds)
    return [run]


def _dataset_run(ds: xr.Dataset, label: str | None, visit=None) -> Run:
    _check_dynamic(ds, f"result '{ds.attrs.get('title', '?')}'")
    sea = _sea_state(case_data(ds))
    name = str(ds.attrs.get("case_name") or ds.attrs.get("title") or "result")
    seed = sea.get(SEED_PATH)
    run = Run(name, label or name, None if seed is None else int(seed), sea, ds)
    if visit is not None:
        visit(run, ds)
    return run


def _sweep_runs(folder: Path, visit=None) -> list[Run]:
    summary_path = folder / "summary.nc"
    if not summary_path.exists():
        raise InputError(f"'{folder}' is a folder without summary.nc: not a sweep's output. Suggested fix: give a "
                         "folder written by 'seacable sweep SWEEP.yaml -o DIR', or a result file (.nc).")
    try:
        with xr.open_dataset(summary_path, engine="netcdf4") as s:
            summary = s.load()
    except (OSError, ValueError, RuntimeError) as err:
        raise InputError(f"'{summary_path}' cannot be read: {err}. Suggested fix: run the sweep again.") from None
    params = json.loads(summary.attrs.get("parameters", "[]"))
    if summary.attrs.get("case_analysis") not in DYNAMIC_ANALYSES:
        raise InputError(f"sweep '{folder}' is of '{summary.attrs.get('case_analysis')}' cases; the design tables "
                         f"need time-domain mooring results ({' or '.join(DYNAMIC_ANALYSES)}). Suggested fix: "
                         "sweep a mooring_dynamic or system_dynamic case.")
    units = {p: summary[p].attrs.get("units", "") for p in params}
    # a load case is named by its sea state and the parameters that tell it from the others: not the seed,
    # nor one value for all (a run's duration, say)
    done = summary["status"].values.astype(str) == "done"
    others = [p for p in params if p != SEED_PATH and (p in (HS_PATH, TP_PATH, HEADING_PATH) or len(
        {json.dumps(_plain(v), default=str) for v in summary[p].values[done]}) > 1)]
    runs = []
    for k in range(summary.sizes["case"]):
        if str(summary["status"].values[k]) != "done":
            continue
        index = int(summary["case"].values[k])
        name = str(summary["name"].values[k])
        path = next((p for p in (folder / "cases" / f"{index:04d}.nc", folder / "cases" / f"{name}.nc")
                     if p.exists()), None)
        if path is None:
            raise InputError(f"sweep '{folder}': case {index} ({name}) is done but its result is not in "
                             f"{folder / 'cases'}. Suggested fix: run the sweep again (it runs the missing cases).")
        values = {p: _plain(summary[p].values[k]) for p in params}
        label = _label({p: values[p] for p in others}, units) or str(summary.attrs.get("title") or folder.name)
        with Run(name, "", None, {}, path).open() as ds:
            _check_dynamic(ds, f"result file '{path}'")
            parameters = {**_sea_state(case_data(ds)), **values}
            seed = parameters.get(SEED_PATH)
            runs.append(Run(name, label, None if seed is None else int(seed), parameters, path))
            if visit is not None:
                visit(runs[-1], ds)
    if not runs:
        raise InputError(f"sweep '{folder}' holds no completed case ({summary.attrs.get('failed', 0)} failed, "
                         f"{summary.attrs.get('not_run', 0)} not run). Suggested fix: run the sweep to its end, "
                         "and see the summary's 'error' for the failed cases.")
    return runs


def _plain(value):
    return value.item() if hasattr(value, "item") else value


# ----------------------------------------------------------------------------------------- lines of a result

def line_names(ds: xr.Dataset) -> list[str]:
    """The lines of a result: its ``line`` coordinate, or the one line of a single-line case."""
    if "line" in ds.dims:
        return [str(v) for v in ds["line"].values]
    data = case_data(ds) or {}
    return [str((data.get("line") or {}).get("name") or "line")]


def line_series(ds: xr.Dataset, variable: str, line: str) -> np.ndarray:
    """The time series of a per-line variable (``fairlead_tension``, ``anchor_tension``) of one line."""
    v = ds[variable]
    if "line" in v.dims:
        v = v.sel(line=line)
    return np.asarray(v.transpose("time").values, float)


def _node_positions(ds: xr.Dataset, line: str) -> np.ndarray:
    """Positions of a line's nodes, (time, node, 3), NaN padding dropped. [m]"""
    out = []
    for k in "xyz":
        v = ds[k]
        if "line" in v.dims:
            v = v.sel(line=line)
        out.append(np.asarray(v.transpose("time", "node").values, float))
    pos = np.stack(out, axis=-1)
    keep = np.all(np.isfinite(pos[0]), axis=-1)
    return pos[:, keep]


@dataclass(frozen=True)
class LineInfo:
    """What a result's case tells of a line: its minimum breaking load [N] (None: unknown; the smallest of its
    segments'), the line type at its fairlead (its name, None when the case does not say, and its volume-equivalent
    diameter [m]), and which end is the anchor (0: end A, node 0; 1: end B; None: not told, the lower end is);
    ``material`` the line type's ``material`` at the fairlead (None: not given)."""

    breaking_load: float | None
    line_type: str | None
    diameter: float | None
    anchor_end: int | None
    source: str
    material: str | None = None
    weight: float = 0.0  # the line's submerged weight [N] (0: unknown), the scale of anchor round-off


def _type_name(lt: dict, types: dict) -> str | None:
    if lt.get("name"):
        return str(lt["name"])
    for key, value in types.items():
        if value == lt:
            return str(key)
    return None


def line_info(ds: xr.Dataset) -> dict[str, LineInfo]:
    """Per line of a result, its :class:`LineInfo`: the breaking load from the result's ``breaking_load``
    variable (NaN: none), else from the case stored with it (``line_types.*.breaking_load``)."""
    names = line_names(ds)
    data = case_data(ds) or {}
    types = data.get("line_types") or {}
    points = data.get("points") or {}
    system_lines = data.get("lines") or {}
    out = {}
    for k, name in enumerate(names):
        if isinstance(system_lines, dict) and name in system_lines:
            entry = system_lines[name] or {}
            line = entry.get("line") or entry
            kinds = [(points.get(entry.get(e)) or {}).get("kind") for e in ("end_a", "end_b")]
            anchor = 0 if kinds[0] == "fixed" else 1 if kinds[1] == "fixed" else None
            fair = 1 if anchor == 0 else 0 if anchor == 1 else None
        elif data.get("line") is not None and len(names) == 1:
            line = data["line"]
            fair = 1 if (data.get("analysis") or {}).get("end_b", "fairlead") == "fairlead" else 0
            anchor = 1 - fair
        else:
            line, anchor, fair = None, None, None
        segments = [s for s in ((line or {}).get("segments") or []) if isinstance(s, dict)]
        seg_types = [s.get("line_type") if isinstance(s.get("line_type"), dict) else types.get(s.get("line_type"))
                     for s in segments]
        seg_types = [t for t in seg_types if isinstance(t, dict)]
        mbs = [t.get("breaking_load") for t in seg_types]
        breaking = float(min(mbs)) if mbs and all(m is not None for m in mbs) else None
        source = "the case's line_types.*.breaking_load (the smallest of the line's segments)" if breaking else ""
        if "breaking_load" in ds.variables:
            v = ds["breaking_load"]
            value = float(v.sel(line=name).values) if "line" in v.dims else float(v.values)
            breaking = value if math.isfinite(value) and value > 0 else None
            source = "the result's breaking_load" if breaking else ""
        top = seg_types[-1 if fair != 0 else 0] if seg_types else None
        weight = sum(float(t.get("weight_in_water") or 0.0) * float(sg.get("length") or 0.0)
                     for sg, t in zip(segments, seg_types, strict=False) if isinstance(t, dict))
        out[name] = LineInfo(breaking, None if top is None else _type_name(top, types),
                             None if top is None else top.get("diameter"), anchor, source,
                             None if top is None else top.get("material"), max(weight, 0.0))
        del k
    return out


def failed_lines(ds: xr.Dataset) -> dict[str, float]:
    """The lines of a run that failed (line -> time [s]; 0 for a line removed from the start: the run's
    ``damaged_lines``, as its settings record them, the line ``most_loaded`` resolved to included)."""
    out: dict[str, float] = {}
    if "failure_time" in ds.variables:
        ft = ds["failure_time"]
        for name in line_names(ds):
            t = float(ft.sel(line=name).values) if "line" in ft.dims else float(ft.values)
            if math.isfinite(t):
                out[name] = t
    analysis = (case_data(ds) or {}).get("analysis") or {}
    try:
        settings = json.loads(ds.attrs.get("settings") or "{}")
    except ValueError:
        settings = {}
    removed = settings.get("damaged_lines") if isinstance(settings, dict) else None
    if not isinstance(removed, list):  # a result without the lines its run removed: those its case names
        removed = analysis.get("damaged_lines")
    for name in removed if isinstance(removed, (list, tuple)) else ():  # 'most_loaded' unresolved: none known
        out[str(name)] = 0.0
    for f in analysis.get("failures") or ():
        if isinstance(f, dict) and f.get("line") is not None:
            out.setdefault(str(f["line"]), float(f.get("time", 0.0) or 0.0))
    return out

def _duration(ds: xr.Dataset) -> float:
    t = np.asarray(ds["time"].values, float)
    return float(t[-1] - t[0]) if t.size > 1 else 0.0


# ------------------------------------------------------------------------------------------------- extremes

def _note(err: Exception) -> str:
    text = str(err).split(" Suggested fix:")[0]
    return f"not fitted: {text}"


def seed_table(runs: Sequence[Run], *, storm_duration: float | None = None, quantile: float = 0.9) -> pd.DataFrame:
    """Per run (seed), line and end: the largest tension, its mean and standard deviation, and the storm maximum
    from a Weibull fit of the record's peaks.

    Parameters
    ----------
    runs
        From :func:`read_results`.
    storm_duration
        The storm the Weibull fit is raised to; default each run's duration. [s]
    quantile
        The non-exceedance probability of the quantile of the storm maximum. [-]

    Returns
    -------
    pandas.DataFrame
        Columns ``load_case, case, seed, line, end, duration [s], maximum [N], mean [N], std [N],
        weibull_mpm [N], weibull_quantile [N], weibull_note, weibull_flag``, and the low- and wave-frequency parts
        ``lf_std, wf_std [N], lf_period, wf_period [s]`` (:func:`~seacable.design.combination.split_columns`,
        NaN for a record too short to split); the Weibull columns NaN, with the
        reason in ``weibull_note``, where the record has too few peaks
        (:data:`~seacable.design.statistics.MIN_PEAKS`); ``weibull_flag`` says why a fit made is uncertain
        (fewer than :data:`~seacable.design.statistics.RELIABLE_PEAKS` peaks), empty where it is not.
    """
    _check_storm(storm_duration)
    statistics._probability(quantile)  # refused here, not taken for a record's failed fit below
    rows = []
    for run in runs:
        with run.open() as ds:
            rows += _seed_rows(run, ds, storm_duration, quantile)
    return _seed_frame(rows)


def _seed_rows(run: Run, ds: xr.Dataset, storm_duration: float | None, quantile: float) -> list[dict]:
    """The rows of :func:`seed_table` of one run, ``ds`` its result, over its statistics window."""
    rows, ds = [], statistics_window(ds)  # the start-up transient left out (analysis.statistics_from)
    duration = _duration(ds)
    time = np.asarray(ds["time"].values, float)
    for line in line_names(ds):
        for end in _ENDS:
            record = line_series(ds, f"{end}_tension", line)
            mean, std = statistics.mean_and_dynamic(record)
            try:
                w = statistics.weibull_maximum(record, duration, storm_duration, quantile)
                mpm, q, note, flag = w.most_probable, w.quantile, "", w.flag
            except InputError as err:
                mpm, q, note, flag = math.nan, math.nan, _note(err), ""
            rows.append({"load_case": run.load_case, "case": run.name, "seed": run.seed, "line": line,
                         "end": end, "duration": duration, "maximum": float(np.max(record)), "mean": mean,
                         "std": std, "weibull_mpm": mpm, "weibull_quantile": q, "weibull_note": note,
                         "weibull_flag": flag, **combination.split_columns(record, time)})
    return rows


def _seed_frame(rows: list[dict]) -> pd.DataFrame:
    return pd.DataFrame(rows, columns=["load_case", "case", "seed", "line", "end", "duration", "maximum", "mean",
                                       "std", "weibull_mpm", "weibull_quantile", "weibull_note", "weibull_flag",
                                       "lf_std", "wf_std", "lf_period", "wf_period"])


def _check_storm(storm_duration) -> None:
    if storm_duration is not None and not (math.isfinite(storm_duration) and storm_duration > 0):
        raise InputError(f"the storm duration must be > 0 s, got {storm_duration} s. Suggested fix: 10800 for a "
                         "3-hour storm, or leave it out for the runs' duration.")


def extremes_table(runs: Sequence[Run] | pd.DataFrame, *, storm_duration: float | None = None,
                   quantile: float = 0.9) -> pd.DataFrame:
    """Per load case, line and end: the maxima of the seeds, the mean and dynamic parts, the storm maximum from a
    Gumbel fit over the seeds and from the seeds' Weibull fits, and the design maximum.

    The Gumbel fit (:func:`~seacable.design.statistics.gumbel_maximum`, at least 5 seeds) gives the maximum of
    a run of the runs' duration; the Weibull fit of each seed's peaks
    (:func:`~seacable.design.statistics.weibull_maximum`) is raised to the storm's duration, and the table holds
    the mean of the seeds' estimates. The design maximum is the Gumbel MPM where it is fitted and the storm is
    the runs' duration, else the mean Weibull MPM, else the Gumbel MPM, else the largest maximum of the seeds (the
    basis says when that is the maximum of a run shorter than the storm); the dynamic part of
    the tension is the design maximum less the mean (DNV-OS-E301 Ch.2 Sec.2 B: T_c = T_c,mean + T_c,dyn).

    Parameters
    ----------
    runs
        From :func:`read_results`, or the :func:`seed_table` of them.
    storm_duration
        The storm's duration; default the runs' duration. [s]
    quantile
        Non-exceedance probability of the quantile of the storm maximum. [-]

    Returns
    -------
    pandas.DataFrame
        Columns ``load_case, line, end, seeds, duration [s], storm [s], maximum_largest [N],
        maximum_mean [N], mean [N], std [N], gumbel_mpm [N], gumbel_quantile [N], gumbel_note, weibull_mpm [N],
        weibull_quantile [N], weibull_note, weibull_flag (the seeds' flags: fits on few peaks), design_maximum [N],
        dynamic [N], design_basis (FLAGGED where it rests on flagged fits), method``.
    """
    seeds = runs if isinstance(runs, pd.DataFrame) else seed_table(runs, storm_duration=storm_duration,
                                                                    quantile=quantile)
    statistics._probability(quantile)  # the quantile's check, before any fit
    rows = []
    for (load_case, line, end), g in seeds.groupby(["load_case", "line", "end"], sort=False):
        n = len(g)
        duration = float(g["duration"].mean())
        storm = duration if storm_duration is None else float(storm_duration)
        try:
            gb = statistics.gumbel_maximum(g["maximum"].to_numpy(), quantile)
            g_mpm, g_q, g_note = gb.most_probable, gb.quantile, ""
        except InputError as err:
            g_mpm, g_q, g_note = math.nan, math.nan, _note(err)
        fitted = g["weibull_mpm"].notna()
        w_mpm = float(g.loc[fitted, "weibull_mpm"].mean()) if fitted.any() else math.nan
        w_q = float(g.loc[fitted, "weibull_quantile"].mean()) if fitted.any() else math.nan
        w_note = statistics.merged_notes(g["weibull_note"])
        w_flag = statistics.merged_notes(g.get("weibull_flag", ()))
        if fitted.any() and not fitted.all():
            w_note = f"mean of {int(fitted.sum())} of {n} seeds; " + w_note
        mean = float(g["mean"].mean())
        same_storm = math.isclose(storm, duration, rel_tol=1e-6)
        short = "" if same_storm else f" of {duration:.6g} s runs, NOT of the {storm:.6g} s storm (no Weibull fit)"
        if math.isfinite(g_mpm) and same_storm:
            design, basis = g_mpm, f"Gumbel MPM over {n} seeds"
        elif math.isfinite(w_mpm):
            design, basis = w_mpm, f"Weibull MPM, mean over {int(fitted.sum())} seed(s)"
            if w_flag:
                basis += " (FLAGGED: fits on few peaks, uncertain)"
        elif math.isfinite(g_mpm):
            design, basis = g_mpm, f"Gumbel MPM over {n} seeds{short}"
        else:
            design, basis = float(g["maximum"].max()), f"largest simulated maximum of {n} seed(s){short}"
        method = (f"Gumbel (max. likelihood) over seeds' maxima of {duration:.6g} s runs, {GUMBEL_REFERENCE}; "
                  f"3-parameter Weibull of each seed's peaks raised to a {storm:.6g} s storm, {WEIBULL_REFERENCE}")
        rows.append({"load_case": load_case, "line": line, "end": end, "seeds": n, "duration": duration,
                     "storm": storm, "maximum_largest": float(g["maximum"].max()),
                     "maximum_mean": float(g["maximum"].mean()), "mean": mean, "std": float(g["std"].mean()),
                     "gumbel_mpm": g_mpm, "gumbel_quantile": g_q, "gumbel_note": g_note, "weibull_mpm": w_mpm,
                     "weibull_quantile": w_q, "weibull_note": w_note, "weibull_flag": w_flag, "design_maximum": design,
                     "dynamic": design - mean, "design_basis": basis, "method": method})
    return pd.DataFrame(rows, columns=["load_case", "line", "end", "seeds", "duration", "storm", "maximum_largest",
                                       "maximum_mean", "mean", "std", "gumbel_mpm", "gumbel_quantile", "gumbel_note",
                                       "weibull_mpm", "weibull_quantile", "weibull_note", "weibull_flag",
                                       "design_maximum", "dynamic", "design_basis", "method"])


# ----------------------------------------------------------------------------------------------- code checks

def anchor_uplift_force(ds: xr.Dataset, line: str, info: LineInfo | None = None) -> float:
    """The largest upward pull of a line on its anchor over a run: the result's ``anchor_vertical_force``, or
    in a result without it (written before it was) the vertical component of the anchor tension along the first
    element from the anchor, ``T_anchor (z1 - z0) / |x1 - x0|`` (> 0 upward). [N]

    The anchor is the end the case ties to a fixed point (end A of a single-line case); where the case does
    not say (a MoorDyn network), the lower end of the line at the start.
    """
    vertical, _ = _anchor_vertical(ds, line, info)
    return float(np.nanmax(vertical))


def anchor_uplift_state(ds: xr.Dataset, line: str, info: LineInfo | None = None) -> tuple[float, float]:
    """The instant of a run that the anchor uplift check takes: its vertical force [N] and the anchor tension
    then [N]; the instant of the largest uplift (:func:`seacable.design.checks.uplift_demand`: round-off left
    out), or of the largest vertical force when there is none."""
    from .checks import uplift_demand

    vertical, tension = _anchor_vertical(ds, line, info)
    demand = uplift_demand(np.nan_to_num(vertical, nan=-np.inf), tension, 0.0 if info is None else info.weight)
    k = int(np.argmax(demand)) if np.any(demand > 0) else int(np.nanargmax(vertical))
    return float(vertical[k]), float(tension[k])


def _anchor_vertical(ds: xr.Dataset, line: str, info: LineInfo | None) -> tuple[np.ndarray, np.ndarray]:
    if "anchor_vertical_force" in ds:
        # the model's own: the end element's pull less the half element's weight the seabed carries
        # (seacable.mooring.run.grounded_end_force); the pull alone showed half an element's weight of uplift at an
        # anchor whose touchdown lies within its first element
        return line_series(ds, "anchor_vertical_force", line), line_series(ds, "anchor_tension", line)
    pos = _node_positions(ds, line)
    end = None if info is None else info.anchor_end
    if end is None:
        end = 0 if pos[0, 0, 2] <= pos[0, -1, 2] else 1
    a, b = (pos[:, 0], pos[:, 1]) if end == 0 else (pos[:, -1], pos[:, -2])
    length = np.linalg.norm(b - a, axis=-1)
    tension = line_series(ds, "anchor_tension", line)
    with np.errstate(invalid="ignore", divide="ignore"):
        vertical = np.where(length > 0, tension * (b[:, 2] - a[:, 2]) / length, 0.0)
    return vertical, tension


def body_offsets(ds: xr.Dataset) -> dict[str, tuple[float, str]]:
    """The largest horizontal offset of each body over a run [m], and its reference: the body's position in the
    case where the result stores it, else its position at the start; a platform following a prescribed
    motion (``platform_position``), from the origin."""
    out = {}
    data = case_data(ds) or {}
    if "body_position" in ds.variables:
        bp = ds["body_position"]   # (time, body, axis) [m], or (time, body, dof) of six in an older file
        bp = bp.transpose("time", "body", bp.dims[-1])
        for k, body in enumerate(str(b) for b in ds["body"].values):
            xy = np.asarray(bp.values[:, k, :2], float)
            given = ((data.get("bodies") or {}).get(body) or {}).get("position")
            if given is not None:
                ref, where = np.asarray(given[:2], float), "from its position in the case"
            else:
                ref, where = xy[0], "from its position at the start of the run"
            out[body] = (float(np.max(np.hypot(*(xy - ref).T))), where)
    if "platform_position" in ds.variables:
        pp = ds["platform_position"].transpose("time", "dof")
        xy = np.asarray(pp.values[:, :2], float)
        out["platform"] = (float(np.max(np.hypot(*xy.T))), "from the origin")
    return out


_CHECK_COLUMNS = ["load_case", "check", "item", "unit", "demand", "capacity", "margin", "utilisation", "passed",
                  "status", "formula", "reference"]


def checks_table(runs: Sequence[Run], extremes: pd.DataFrame | None = None, *, consequence_class: int = 1,
                 offset_limit: float | None = None, allowed_uplift: float = 0.0,
                 lines: Sequence[str] | None = None, storm_duration: float | None = None,
                 quantile: float = 0.9) -> pd.DataFrame:
    """The code checks of each load case (:mod:`seacable.design.checks`), one row per check and item.

    - Line tension, DNV-OS-E301 ULS (``consequence_class`` 1 or 2) for an intact load case, ALS where a line
      failed or was removed: ``T_c,mean`` the mean fairlead tension, ``T_c,dyn`` the design maximum less it
      (:func:`extremes_table`); failed lines themselves are not checked.
    - API RP 2SK, dynamic analysis: the design maximum against MBS / FoS, intact or damaged.
    - Anchor uplift: the largest upward pull over the seeds (:func:`anchor_uplift_state`; round-off, up to
      :data:`~seacable.design.checks.UPLIFT_ROUND_OFF` of the anchor tension, is none) against ``allowed_uplift``
      [N] (0: a drag anchor takes none).
    - Offset: each body's largest horizontal offset over the seeds (:func:`body_offsets`) against
      ``offset_limit`` [m], when one is given.

    A line with no breaking load gets a row "not checked: no breaking_load for line 'L'", unless ``lines`` names
    it: the lines asked for explicitly are checked or refused.

    Returns
    -------
    pandas.DataFrame
        Columns ``load_case, check, item, unit, demand, capacity, margin, utilisation, passed, status, formula,
        reference``: demand, capacity and margin (capacity - demand) in the row's unit (N, or m for offsets),
        utilisation [-] only where the capacity is positive (NaN: a zero capacity, or not checked); never an
        infinite number.

    Raises
    ------
    InputError
        A line of ``lines`` that has no breaking load or is not in the results; a bad consequence class.
    """
    if extremes is None:
        extremes = extremes_table(runs, storm_duration=storm_duration, quantile=quantile)
    _check_offset_limit(offset_limit)
    return _checks_of_facts(_check_facts(runs), extremes, consequence_class, offset_limit, allowed_uplift, lines)


def _check_offset_limit(offset_limit: float | None) -> None:
    if offset_limit is not None and not (math.isfinite(offset_limit) and offset_limit > 0):
        raise InputError(f"the offset limit must be > 0 m, got {offset_limit} m. Suggested fix: give the "
                         "allowed horizontal excursion in m, e.g. 30.")


def _checks_of_facts(facts: dict[str, dict], extremes: pd.DataFrame, consequence_class: int,
                     offset_limit: float | None, allowed_uplift: float, lines: Sequence[str] | None) -> pd.DataFrame:
    """The rows of :func:`checks_table` from the facts of the runs (:func:`_check_facts`) and the extremes."""
    from . import checks

    known = {line for f in facts.values() for line in f["info"]}
    for name in lines or ():
        if name not in known:
            raise InputError(f"line '{name}' is not in the results (lines: {', '.join(sorted(known))}). Suggested "
                             "fix: give one of these names.")
    rows = []
    fair = extremes[extremes["end"] == "fairlead"]
    for load_case, f in facts.items():
        damaged = bool(f["failed"])
        results = []
        for _, e in fair[fair["load_case"] == load_case].iterrows():
            line = e["line"]
            if lines is not None and line not in lines:
                continue
            info = f["info"].get(line)
            mbs = None if info is None else info.breaking_load
            dnv = "ALS" if damaged else "ULS"
            api = "damaged" if damaged else "intact"
            if line in f["failed"]:
                why = f"not checked: line '{line}' failed at t = {f['failed'][line]:.4g} s"
                rows += [_skipped(load_case, f"DNV-OS-E301 {dnv} CC{consequence_class}", line, why),
                         _skipped(load_case, f"API RP 2SK {api} dynamic", line, why)]
                continue
            if mbs is None and lines is None:
                why = f"not checked: no breaking_load for line '{line}'"
                rows += [_skipped(load_case, f"DNV-OS-E301 {dnv} CC{consequence_class}", line, why),
                         _skipped(load_case, f"API RP 2SK {api} dynamic", line, why)]
                continue
            fn = checks.dnv_als if damaged else checks.dnv_uls
            results.append(fn(line, e["mean"], max(e["dynamic"], 0.0), mbs, consequence_class))
            results.append(checks.api_tension(line, e["design_maximum"], mbs, api, "dynamic"))
        for line, (force, tension) in f["uplift"].items():
            if lines is None or line in lines:
                info = f["info"].get(line)
                results.append(checks.anchor_uplift(f"anchor of {line}", force, allowed_uplift, tension,
                                                    0.0 if info is None else info.weight))
        if offset_limit is not None and not f["offsets"]:
            rows.append(_skipped(load_case, "offset", "-", "not checked: the results hold no body or platform "
                                                          "motion (body_position, platform_position)"))
        if offset_limit is not None:
            for body, (offset, where) in f["offsets"].items():
                r = checks.offset_check(body, offset, offset_limit)
                results.append(r)
                f["where"][body] = where
        table = checks.check_table(results)
        for _, r in table.iterrows():
            row = {"load_case": load_case, **r.to_dict()}
            row["passed"] = bool(row["passed"])
            row["status"] = "pass" if row["passed"] else "FAIL"
            if row["check"] == "offset" and row["item"] in f["where"]:
                row["formula"] = f"{row['formula']} (horizontal, {f['where'][row['item']]})"
            rows.append(row)
    return pd.DataFrame(rows, columns=_CHECK_COLUMNS)


def _skipped(load_case, check, item, why) -> dict:
    return {"load_case": load_case, "check": check, "item": item, "unit": "m" if check == "offset" else "N",
            "demand": math.nan, "capacity": math.nan, "margin": math.nan, "utilisation": math.nan, "passed": None,
            "status": why, "formula": "", "reference": ""}


def _uplift_key(state: tuple[float, float], weight: float = 0.0) -> tuple[float, float]:
    """Order of two seeds' anchor states: by uplift (round-off left out), then by vertical force."""
    from .checks import uplift_demand

    return float(uplift_demand(*state, weight)), state[0]


def _check_facts(runs: Sequence[Run]) -> dict[str, dict]:
    """Per load case: its lines' info, the lines failed in any seed, the largest uplift and offsets."""
    facts: dict[str, dict] = {}
    for run in runs:
        with run.open() as ds:
            _add_check_facts(facts, run, ds)
    return facts


def _add_check_facts(facts: dict[str, dict], run: Run, ds: xr.Dataset) -> None:
    """Add one run (``ds`` its result) to the facts of :func:`_check_facts`."""
    f = facts.setdefault(run.load_case, {"info": {}, "failed": {}, "uplift": {}, "offsets": {}, "where": {}})
    info = line_info(ds)
    f["info"].update(info)
    for line, t in failed_lines(ds).items():
        f["failed"][line] = min(t, f["failed"].get(line, math.inf))
    for line in line_names(ds):
        state = anchor_uplift_state(ds, line, info.get(line))
        w = info[line].weight if line in info else 0.0
        if line not in f["uplift"] or _uplift_key(state, w) > _uplift_key(f["uplift"][line], w):
            f["uplift"][line] = state
    for body, (offset, where) in body_offsets(ds).items():
        if offset >= f["offsets"].get(body, (-math.inf, ""))[0]:
            f["offsets"][body] = (offset, where)


# -------------------------------------------------------------------------------------------------- fatigue

def curve_of_line(info: LineInfo | None) -> tuple[str | None, str]:
    """The T-N curve of a line from what its result's case tells (:class:`LineInfo`: the line type's
    ``material`` and name), and how it was chosen or why none was
    (:func:`seacable.design.fatigue.curve_of_line_type`)."""
    return fatigue.curve_of_line_type(None if info is None else info.material,
                                      None if info is None else info.line_type)


def _curve_of_type(line_type: str | None) -> str | None:
    """The T-N curve a line type's name tells, or None (:func:`curve_of_line` with no material)."""
    return curve_of_line(LineInfo(None, line_type, None, None, ""))[0]


_FATIGUE_COLUMNS = ["load_case", "line", "seeds", "duration", "tn_curve", "tn_basis", "nominal_diameter", "damage",
                    "damage_per_year", "life_alone", "probability", "note"]


def fatigue_table(runs: Sequence[Run], *, tn_curve: str | None = None, nominal_diameter: float | None = None,
                  scatter: pd.DataFrame | str | Path | None = None) -> pd.DataFrame:
    """Miner's damage of each load case and line from the rainflow count of the fairlead tension.

    The T-N curve is ``tn_curve`` (a name :func:`resolve_tn_curve` knows), else the line type's ``material``,
    else the one its name tells without ambiguity (:func:`curve_of_line`: "chain" alone is not enough); a line
    whose curve cannot be told is not computed, with the reason in ``note``. The stress range is the tension
    range over the nominal cross-section of the ``nominal_diameter`` [m], else of the line type's
    volume-equivalent diameter over :data:`VOLUME_EQUIVALENT_RATIO` (1.8 for studless chain); a polyester
    rope's curve is on the tension range over the line's breaking load. A load case's damage is the mean over its seeds
    of :func:`~seacable.design.fatigue.fatigue_damage`, over their mean duration. Fatigue is a limit state of
    the intact system (DNV-OS-E301 Ch.2 Sec.2 D): runs with a failed or removed line (:func:`failed_lines`)
    are left out.

    Parameters
    ----------
    scatter
        A scatter diagram (:func:`read_scatter`): each load case gets its sea state's probability, shared
        equally between the load cases of one sea state (headings, say).

    Returns
    -------
    pandas.DataFrame
        Columns ``load_case, line, seeds, duration [s], tn_curve, tn_basis (how the curve was chosen),
        nominal_diameter [m], damage [-],
        damage_per_year [1/year] (if the load case lasted the whole year), life_alone [years] (its inverse),
        probability [-] (NaN without a scatter diagram), note`` (why a line is not computed).
    """
    curve_given = _fatigue_options(tn_curve, nominal_diameter)
    acc: dict[tuple[str, str], dict] = {}
    intact = []
    for run in runs:
        with run.open() as ds:
            if _add_fatigue(acc, ds, run, curve_given, nominal_diameter):
                intact.append(run)
    return _fatigue_of(acc, intact, scatter)


def _fatigue_options(tn_curve: str | None, nominal_diameter: float | None) -> str | None:
    """The T-N curve given (:func:`resolve_tn_curve`), the nominal diameter checked."""
    curve_given = None if tn_curve is None else resolve_tn_curve(tn_curve)
    if nominal_diameter is not None and not (math.isfinite(nominal_diameter) and nominal_diameter > 0):
        raise InputError(f"the nominal diameter must be > 0 m, got {nominal_diameter} m. Suggested fix: give the "
                         "chain's bar diameter or the rope's nominal diameter in m, e.g. 0.095.")
    return curve_given


def _add_fatigue(acc: dict, ds: xr.Dataset, run: Run, curve_given: str | None,
                 nominal_diameter: float | None) -> bool:
    """Add the damage of one run (``ds`` its result) to ``acc`` of :func:`fatigue_table`; False (nothing added)
    for a run with a failed line."""
    if failed_lines(ds):
        return False
    duration = _duration(ds)
    info = line_info(ds)
    for line in line_names(ds):
        a = acc.setdefault((run.load_case, line), {"damage": [], "duration": [], "note": "", "curve": None,
                                                  "diameter": None, "basis": ""})
        i = info.get(line)
        curve, basis = (curve_given, "given (--tn-curve)") if curve_given else curve_of_line(i)
        if curve is None:
            a["note"] = f"not computed: the T-N curve of line '{line}' cannot be told: {basis}"
            continue
        record = line_series(ds, "fairlead_tension", line)
        if fatigue.TN_CURVES[curve].basis == "mbs_ratio":
            mbs = None if i is None else i.breaking_load
            if mbs is None:
                a["note"] = (f"not computed: the {fatigue.TN_CURVES[curve].name} curve of line '{line}' is on the "
                             "tension range over the breaking load, and the line has no breaking_load")
                continue
            d, size = math.nan, {"breaking_load": mbs}
        else:
            d = nominal_diameter
            if d is None and i is not None and i.diameter:
                d = float(i.diameter) / VOLUME_EQUIVALENT_RATIO[curve]
            if d is None:
                a["note"] = (f"not computed: the nominal diameter of line '{line}' is unknown (the result stores "
                             "no line type); give --nominal-diameter")
                continue
            size = {"diameter": d}
        a["damage"].append(fatigue.fatigue_damage(record, curve, **size))
        a["duration"].append(duration)
        a["curve"], a["diameter"], a["basis"] = curve, d, basis
    return True


def _fatigue_of(acc: dict, intact: Sequence[Run], scatter) -> pd.DataFrame:
    """The rows of :func:`fatigue_table` from the damage of its intact runs (:func:`_add_fatigue`)."""
    probability = scatter_probabilities(intact, scatter) if scatter is not None else {}
    rows = []
    for (load_case, line), a in acc.items():
        n = len(a["damage"])
        if n == 0:
            rows.append({"load_case": load_case, "line": line, "seeds": 0, "duration": math.nan, "tn_curve": "",
                         "tn_basis": "", "nominal_diameter": math.nan, "damage": math.nan, "damage_per_year": math.nan,
                         "life_alone": math.nan, "probability": probability.get(load_case, math.nan),
                         "note": a["note"]})
            continue
        damage, duration = float(np.mean(a["damage"])), float(np.mean(a["duration"]))
        per_year = damage / duration * fatigue.SECONDS_PER_YEAR
        rows.append({"load_case": load_case, "line": line, "seeds": n, "duration": duration, "tn_curve": a["curve"],
                     "tn_basis": a["basis"], "nominal_diameter": a["diameter"], "damage": damage, "damage_per_year": per_year,
                     "life_alone": math.inf if per_year == 0 else 1.0 / per_year,
                     "probability": probability.get(load_case, math.nan), "note": ""})
    return pd.DataFrame(rows, columns=_FATIGUE_COLUMNS)


def fatigue_life_table(fatigue_rows: pd.DataFrame, *,
                       design_fatigue_factor: float = fatigue.DNV_DESIGN_FATIGUE_FACTOR) -> pd.DataFrame:
    """The fatigue life of each line over the scatter diagram (:func:`~seacable.design.fatigue.fatigue_life`) from
    a :func:`fatigue_table` made with one, over the design fatigue factor (default DNV-OS-E301's 5,
    :data:`~seacable.design.fatigue.DNV_DESIGN_FATIGUE_FACTOR`).

    Returns
    -------
    pandas.DataFrame
        Columns ``line, tn_curve, load_cases, damage_per_year [1/year], life [years], design_fatigue_factor,
        note``.
    """
    rows = []
    for line, g in fatigue_rows.groupby("line", sort=False):
        if g["probability"].isna().all():
            continue
        if g["damage"].isna().any():
            rows.append({"line": line, "tn_curve": "", "load_cases": len(g), "damage_per_year": math.nan,
                         "life": math.nan, "design_fatigue_factor": design_fatigue_factor,
                         "note": "; ".join(dict.fromkeys(x for x in g["note"] if x))})
            continue
        life = fatigue.fatigue_life(g["damage"].to_numpy(), g["duration"].to_numpy(), g["probability"].to_numpy(),
                                    design_fatigue_factor=design_fatigue_factor)
        per_year = float(np.sum(g["probability"] * g["damage"] / g["duration"])) * fatigue.SECONDS_PER_YEAR
        rows.append({"line": line, "tn_curve": ", ".join(dict.fromkeys(g["tn_curve"])), "load_cases": len(g),
                     "damage_per_year": per_year, "life": life, "design_fatigue_factor": design_fatigue_factor,
                     "note": ""})
    return pd.DataFrame(rows, columns=["line", "tn_curve", "load_cases", "damage_per_year", "life",
                                       "design_fatigue_factor", "note"])


def design_tables(source, *, storm_duration: float | None = None, quantile: float = 0.9, consequence_class: int = 1,
                  offset_limit: float | None = None, allowed_uplift: float = 0.0, tn_curve: str | None = None,
                  nominal_diameter: float | None = None, scatter: pd.DataFrame | str | Path | None = None,
                  visit: Callable[[Run, xr.Dataset], None] | None = None) -> tuple[list[Run], dict[str, pd.DataFrame]]:
    """The runs of ``source`` and their design tables, each result read once.

    :func:`read_results`, then :func:`seed_table`, :func:`extremes_table`, :func:`checks_table` and
    :func:`fatigue_table` of its runs (the same tables, to the bit) made in one pass over the results: a result
    file is opened once, not once per table. The options are checked before any result is read.

    Parameters
    ----------
    source
        What :func:`read_results` reads.
    visit
        Called as ``visit(run, ds)`` with each run and its result while it is open, after the tables took it.
    storm_duration, quantile, consequence_class, offset_limit, allowed_uplift, tn_curve, nominal_diameter, scatter
        As the tables take them.

    Returns
    -------
    runs : list of Run
    tables : dict of pandas.DataFrame
        ``seeds``, ``extremes``, ``checks``, ``fatigue``, ``components`` (per load case, which parts of the load
        its first run modelled: :func:`~seacable.design.combination.modelled_components`) and ``combined`` (the
        LF/WF parts and the standards' combined maxima: :func:`~seacable.design.combination.combined_table`).
    """
    _check_storm(storm_duration)
    statistics._probability(quantile)
    _check_offset_limit(offset_limit)
    curve_given = _fatigue_options(tn_curve, nominal_diameter)
    seed_rows: list[dict] = []
    facts: dict[str, dict] = {}
    damage: dict = {}
    intact: list[Run] = []

    components: dict[str, list[dict]] = {}

    def take(run: Run, ds: xr.Dataset) -> None:
        seed_rows.extend(_seed_rows(run, ds, storm_duration, quantile))
        components.setdefault(run.load_case, combination.modelled_components(case_data(ds)))
        _add_check_facts(facts, run, ds)
        if _add_fatigue(damage, ds, run, curve_given, nominal_diameter):
            intact.append(run)
        if visit is not None:
            visit(run, ds)

    runs = read_results(source, take)
    seeds = _seed_frame(seed_rows)
    extremes = extremes_table(seeds, storm_duration=storm_duration, quantile=quantile)
    checks = _checks_of_facts(facts, extremes, consequence_class, offset_limit, allowed_uplift, None)
    parts = pd.DataFrame([{"load_case": lc, **c} for lc, cs in components.items() for c in cs],
                         columns=["load_case", "component", "status", "how"])
    return runs, {"seeds": seeds, "extremes": extremes, "checks": checks,
                  "fatigue": _fatigue_of(damage, intact, scatter), "components": parts,
                  "combined": combination.combined_table(seeds, extremes, storm_duration)}

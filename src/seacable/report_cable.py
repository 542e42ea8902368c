"""The cable part of the design report (issue 40): range graphs and checks of a line with bending stiffness
(:mod:`seacable.design.cable`), the armour's fatigue when the case asks for it (``analysis.design.armour``,
:mod:`seacable.design.cable_fatigue`), and the whole page of a static or pushover result of a cable
(:func:`make_static_report`: its shape, the checks against the static MBR, and per offset).

:mod:`seacable.report` adds the section to the page of a time-domain result (of a system: each line with bending
stiffness, :func:`seacable.design.system_cable.cable_lines`, with its distance to the other lines) and calls
:func:`make_static_report` for a ``mooring_static`` or ``mooring_pushover`` result with curvature (a
``system_static`` one: :mod:`seacable.report_system_cable`). :func:`system_cable_view` is
:func:`seacable.design.system_cable.system_cable_view`.
"""

from __future__ import annotations

import datetime
import math
from pathlib import Path

import numpy as np
import pandas as pd

from ._atomic import atomic_write
from ._report_html import (
    _CSS,
    _SERIES,
    _column,
    _e,
    _figure,
    _kv,
    _mark,
    _notes_block,
    _num,
    _png,
    _pyplot,
    _relative,
    _status,
    _table,
)
from ._version import __version__
from .design import cable as cable_
from .design import summary as ds_
from .design.cable_fatigue import SNCurve, cable_fatigue_damage
from .design.clearance import line_clearance_check
from .design.system_cable import cable_lines, system_cable_view
from .errors import InputError

__all__ = ["CABLE_CSV_UNITS", "STATIC_ANALYSES", "armour_fatigue_table", "make_static_report", "offset_table",
           "system_cable_view"]

#: The static analyses whose results of a cable :func:`make_static_report` reports.
STATIC_ANALYSES = ("mooring_static", "mooring_pushover", "system_static")

#: Seconds in a year (365.25 days), for a record's damage as if it lasted the year. [s]
YEAR = 365.25 * 86400.0

#: The units of the cable checks' CSV columns (value, limit and margin in the row's unit: N, 1/m, m or rad).
CABLE_CSV_UNITS = {"value": "see unit", "limit": "see unit", "margin": "see unit", "utilisation": "-", "s": "m",
                   "time": "s", "offset": "m"}


class _Cable:
    """Kept as the results are read (with :class:`_MostLoaded`): of each run whose result has curvature, each line's
    range graphs, limits and cable checks (:mod:`seacable.design.cable`)."""

    def __init__(self):
        self.rows: list[pd.DataFrame] = []
        self.graphs: list[tuple] = []  # (run, line, range graphs, limits)
        self.armour: list[pd.DataFrame] = []  # the armour's fatigue, where the case asks for it

    def __call__(self, run, ds) -> None:
        if not cable_.has_curvature(ds):
            return
        # a system's lines: those with bending stiffness (a chain's curvature is 0), each with its distance to the
        # other lines (seacable.design.system_cable)
        for line in cable_lines(ds) if "line" in ds.dims else [None]:
            view = ds.sel(line=line) if line is not None else ds
            limits = cable_.cable_limits(view)
            checks = cable_.cable_checks(ds, limits, line)
            if line is not None:
                checks.append(line_clearance_check(ds, line))
            table = cable_.cable_check_table(checks)
            name = line if line is not None else ds_.line_names(ds)[0]
            table.insert(0, "line", name)
            table.insert(0, "seed", run.seed)
            table.insert(0, "case", run.name)
            table.insert(0, "load_case", run.load_case)
            self.rows.append(table)
            self.graphs.append((run, name, cable_.range_graphs(ds, line), limits))
            fatigue = armour_fatigue_table(ds, line, run.load_case, run.seed)
            if fatigue is not None:
                self.armour.append(fatigue)

    def table(self) -> pd.DataFrame | None:
        return pd.concat(self.rows, ignore_index=True) if self.rows else None

    def armour_table(self) -> pd.DataFrame | None:
        return pd.concat(self.armour, ignore_index=True) if self.armour else None

    def by_load_case(self) -> dict[tuple[str, str], tuple[object, object]]:
        """(load case, line) -> (range graphs over its seeds: the least minimum, the largest maximum, the mean of
        the means, limits): the seeds' envelope."""
        out: dict = {}
        for run, line, rg, limits in self.graphs:
            key = (run.load_case, line)
            if key not in out:
                out[key] = (rg, limits, 1)
                continue
            prev, lim, n = out[key]
            if prev.sizes != rg.sizes:
                continue  # another mesh: its first seed's stand
            merged = prev.copy()
            for v in rg.data_vars:
                a, b = prev[v].values, rg[v].values
                merged[v].values = (np.fmin(a, b) if v.endswith("_min") else np.fmax(a, b) if v.endswith("_max")
                                    else (a * n + b) / (n + 1))
            merged.attrs["states"] = int(prev.attrs["states"]) + int(rg.attrs["states"])
            out[key] = (merged, lim, n + 1)
        return {k: (rg, lim) for k, (rg, lim, _) in out.items()}


def verdict_cards(checks: pd.DataFrame, *more, where=("check",)) -> str:
    """The cable page's verdict cards (HTML): how many of the ``checks`` made fail, the largest utilisation (the
    hang-off declination's is a place in its range, not a ratio of a demand to its limit, and is left out here: its
    rows say it), named by the row's ``where`` columns, and the ``more`` cards, ``(class, key, value)`` each."""
    done = checks[checks["passed"].notna()]
    bad = done[~done["passed"].astype(bool)]
    ratio = done[done["utilisation"].notna() & ~done["check"].str.startswith("hang-off declination")]
    cards = [("bad" if len(bad) else "ok" if len(done) else "warn", "Cable checks",
              f"{len(bad)} of {len(done)} fail" if len(bad) else f"all {len(done)} pass" if len(done) else "none made")]
    if not ratio.empty:
        top = ratio.loc[ratio["utilisation"].idxmax()]
        cards.append(("bad" if top["utilisation"] > 1 else "ok",
                      f"Largest utilisation ({', '.join(_e(top[c]) for c in where)})",
                      _column([float(top["utilisation"])], sig=4, like=[1.0])[0]))
    return '<div class="verdict">' + "".join(
        f'<div class="card {c}"><div class="k">{k}</div><div class="v">{v}</div></div>'
        for c, k, v in (*cards, *more)) + "</div>"


def _figure_range_graphs(key, rg, limits) -> tuple[str, str]:
    load_case, line = key
    plt = _pyplot()
    fig = cable_.plot_range_graphs(rg, limits, colour=_SERIES)
    over = rg.attrs.get("statistics_over", "none")
    n = int(rg.attrs.get("states", 0))
    what = ("its static state" if over == "none" else f"its {n} conditions" if over == "condition" else
            f"{n} states ({over})")
    caption = (f"Range graphs of {line} ({load_case}) along the arc length from end A: the band from the minimum to "
               f"the maximum over {what}, the mean a line; dashed red: the allowable tension, dash-dot: 1 / MBR "
               f"where the line types give them. Seabed: {rg.attrs.get('seabed', '')}.")
    img = _png(fig)
    plt.close(fig)
    return img, caption


#: How the cable checks' units are shown: unit -> (unit shown, scale of the SI value).
_CABLE_UNITS = {"N": ("kN", 1e3), "1/m": ("1/m", 1.0), "m": ("m", 1.0), "rad": ("deg", math.pi / 180.0)}


def _cable_html(table: pd.DataFrame, first: tuple[str, str] = ("Load case", "load_case")) -> str:
    """The cable checks, one row a check and run: value and limit in the row's unit, utilisation, margin, status,
    where (s) and when (t); ``first``: the first column's header and the table's column (a system's condition)."""
    rows, classes = [], []
    notes: dict[str, str] = {}
    for _, r in table.iterrows():
        shown, scale = _CABLE_UNITS.get(r["unit"], (r["unit"], 1.0))
        value, limit, margin = (_column([r[c]], scale, 4, like=[r["value"], r["limit"]])[0]
                                for c in ("value", "limit", "margin"))
        u = _column([r["utilisation"]], 1.0, 4, like=[1.0])[0]
        status, cls = _status(r)
        bound = "&le;" if r["bound"] == "max" else "&ge;"
        when = r["time"] if math.isfinite(r["time"]) else r["offset"]
        when_text = "static" if not math.isfinite(when) else (
            f"t = {_num(when)} s" if math.isfinite(r["time"]) else f"offset {_num(when)} m")
        checked = math.isfinite(r["value"])
        rows.append([_e(r[first[1]]), _e(r["line"]), _e(r["check"]) + _mark(notes, r["formula"]),
                     f"{value} {shown}" if checked else "&ndash;",
                     f"{bound} {limit} {shown}" if checked else "&ndash;", u,
                     f"{margin} {shown}" if checked else "&ndash;",
                     _num(r["s"]) if checked else "&ndash;", when_text if checked else "&ndash;", status])
        classes.append(cls)
    return _table([first[0], "Line", "Check", "Value", "Limit", "Utilisation [-]", "Margin", "s [m]", "When",
                   "Status"], rows, classes, cls="num checks cable",
                  single=table[first[1]].nunique() == 1) + _notes_block(notes)


def _cable_section(table: pd.DataFrame | None, figures: list, armour: pd.DataFrame | None = None) -> list[str]:
    if table is None:
        return []
    return ["<h2>6. Cable: range graphs and checks</h2>",
            ('<p class="method">The line has bending stiffness: along its arc length s from end A, the effective '
             "tension, curvature, bend moment, declination and height above the seabed, their minimum, maximum and "
             "mean over the run (<code>seacable.design.cable.range_graphs</code>; in "
             "<code>*_range_graphs.nc</code>). Checks: the largest curvature against 1 / MBR (the line type's "
             "<code>minimum_bend_radius_dynamic</code> for a dynamic run), utilisation &kappa; MBR; the largest "
             "element tension against <code>allowable_tension</code>; the smallest against &minus;"
             "<code>allowable_compression</code> (0 N unless given); the sag bend (the lowest point between the hog "
             "bend's crest and end B) and the hog bend's crest above the seabed by <code>analysis.design</code>'s "
             "clearances (0 m: no touchdown); the declination at end B within "
             "<code>analysis.design.hang_off_declination</code>; in a system, each line with bending stiffness, and its "
             "smallest distance to the other lines, segment to segment, against <code>analysis.design."
             "line_clearance</code> (<code>seacable.design.clearance</code>). Where: the arc length of the worst node or element; "
             "when: the time of the worst state.</p>"),
            _cable_html(table)] + [_figure(f) for f in figures] + armour_section(armour)


def _range_graphs_file(graphs: dict):
    """The range graphs of the report in one Dataset: one load case and line as it is; several on a ``load_case``
    dimension (and ``line`` beside it), those of another mesh than the first left out (named in its attrs)."""
    import xarray as xr

    items = list(graphs.items())
    if len(items) == 1:
        return items[0][1][0]
    first = items[0][1][0]
    same = [(k, rg) for k, (rg, _) in items if rg.sizes == first.sizes]
    out = xr.concat([rg for _, rg in same], dim="load_case", combine_attrs="drop_conflicts")
    out = out.assign_coords(load_case=("load_case", [k[0] for k, _ in same]), line=("load_case", [k[1] for k, _ in same]))
    left = [f"{k[0]} / {k[1]}" for k, (rg, _) in items if rg.sizes != first.sizes]
    if left:
        out.attrs["left_out"] = "; ".join(left) + " (another mesh)"
    return out


# ------------------------------------------------------------------------------------------- armour fatigue

def _armour(ds) -> dict | None:
    design = ((ds_.case_data(ds) or {}).get("analysis") or {}).get("design") or {}
    return design.get("armour")


def armour_fatigue_table(ds, line: str | None = None, load_case: str = "", seed=None) -> pd.DataFrame | None:
    """The armour's fatigue of a dynamic result whose case gives ``analysis.design.armour``
    (:class:`seacable.case.ArmourFatigue`): Miner's damage of the record at the most damaged node
    (:func:`seacable.design.cable_fatigue.cable_fatigue_damage`), where (``s``) and at which point around the
    section (``hot_spot`` [rad] from the horizontal normal e_1), the damage per year were the record to last the
    year and its life; None when the case gives no armour model or the result has no time."""
    armour = _armour(ds)
    if armour is None or "time" not in ds.dims:
        return None
    view = ds.sel(line=line) if line is not None and "line" in ds.dims else ds
    curve = armour["sn_curve"]
    sn = SNCurve(float(curve["a"]), float(curve["m"]), None if curve.get("m2") is None else float(curve["m2"]),
                 float(curve.get("n_knee") or 1e7))
    keep = np.isfinite(np.asarray(view["x"].isel(time=0).values, float))
    view = view.isel(node=np.flatnonzero(keep))
    damage, hot = cable_fatigue_damage(view, sn, float(armour["tension_factor"]), float(armour["curvature_factor"]),
                                       points=int(armour.get("points") or 8))
    t = np.asarray(view["time"].values, float)
    duration = float(t[-1] - t[0])
    k = int(np.argmax(damage))
    per_year = float(damage[k]) * YEAR / duration if duration > 0 else math.nan
    s = np.asarray(view["s"].values, float)
    return pd.DataFrame([{"load_case": load_case, "seed": seed, "line": line or ds_.line_names(ds)[0],
                          "s": float(s[k]), "hot_spot": float(hot[k]), "damage": float(damage[k]),
                          "duration": duration, "damage_per_year": per_year,
                          "life": 1.0 / per_year if per_year > 0 else math.inf,
                          "sn_curve": f"N = {sn.a:.4g} s^-{sn.m:g}" + (f", m2 = {sn.m2:g} beyond {sn.n_knee:.3g} cycles"
                                                                       if sn.m2 is not None else ""),
                          "stress_model": f"c_T = {float(armour['tension_factor']):.4g} Pa/N, c_kappa = "
                                          f"{float(armour['curvature_factor']):.4g} Pa m, "
                                          f"{int(armour.get('points') or 8)} points"}])


#: The units of the armour fatigue's CSV columns.
ARMOUR_CSV_UNITS = {"s": "m", "hot_spot": "rad", "damage": "-", "duration": "s", "damage_per_year": "1/year",
                    "life": "years"}


def _armour_html(table: pd.DataFrame) -> str:
    rows = [[_e(r["load_case"]), _e(r["line"]), _num(r["s"]), _num(math.degrees(r["hot_spot"]), 3),
             _num(r["damage"], 3), _num(r["duration"]), _num(r["damage_per_year"], 3), _num(r["life"], 3),
             _e(r["sn_curve"]), _e(r["stress_model"])] for _, r in table.iterrows()]
    return _table(["Load case", "Line", "s [m]", "Hot spot [deg]", "Damage of the run [-]", "Run [s]",
                   "If permanent [1/year]", "Life if permanent [years]", "S-N curve (s in MPa)", "Stress model"],
                  rows, cls="num cable")


def armour_section(table: pd.DataFrame | None) -> list[str]:
    """The armour fatigue's part of the cable section (nothing without a table)."""
    if table is None or table.empty:
        return []
    return ["<h3>Armour fatigue</h3>",
            ('<p class="method">The armour\'s stress &sigma; = c<sub>T</sub> T + c<sub>&kappa;</sub> &kappa; '
             "(n &middot; e(&phi;)) at points around the section along the line, each point's record rainflow-counted "
             "(ASTM E1049-85), the S-N curve of <code>analysis.design.armour</code> and Miner's sum "
             "(<code>seacable.design.cable_fatigue</code>); the most damaged node and point. &ldquo;If "
             "permanent&rdquo;: were the run's sea to last the year (the whole record, its ramp included; no scatter "
             "diagram, no design fatigue factor).</p>"),
            _armour_html(table)]


# ---------------------------------------------------------------------------------------- static and pushover

def offset_table(ds, limits=None, line: str | None = None) -> pd.DataFrame:
    """The cable checks of each state of a static or pushover result (:func:`seacable.design.cable.cable_checks`
    on each offset alone, the bends found on that offset's shape): one row an offset (a static result: one row,
    offset 0), with the hang-off (end B) tension, and each check's value and utilisation."""
    one = ds.sel(line=line) if line is not None and "line" in ds.dims else ds
    limits = cable_.cable_limits(one) if limits is None else limits
    offsets = np.asarray(one["offset"].values, float) if "offset" in one.dims else np.zeros(1)
    rows = []
    for k, off in enumerate(offsets):
        state = one.isel(offset=k) if "offset" in one.dims else one
        checks = cable_.cable_checks(state, limits)
        tension = np.asarray(state["tension"].values, float)
        row = {"offset": float(off), "hang_off_tension": float(tension[np.flatnonzero(np.isfinite(tension))[-1]])}
        passed = [c.passed for c in checks if c.passed is not None]
        for c in checks:
            key = c.check.replace(" ", "_").replace("(", "").replace(")", "").replace("-", "_")
            row[f"{key}"] = c.value
            row[f"{key}_utilisation"] = math.nan if c.utilisation is None else c.utilisation
        row["passed"] = all(passed) if passed else None
        rows.append(row)
    return pd.DataFrame(rows)


def _offset_html(table: pd.DataFrame) -> str:
    def cell(r, key, scale=1.0, sig=4):
        v, u = r.get(key, math.nan), r.get(f"{key}_utilisation", math.nan)
        if not math.isfinite(v):
            return "&ndash;"
        text = _num(v / scale, sig)
        return text + (f" ({_num(u, 3)})" if math.isfinite(u) else "")

    rows, classes = [], []
    for _, r in table.iterrows():
        status = "&ndash;" if r["passed"] is None else ('<span class="pass">PASS</span>' if r["passed"] else
                                                        '<span class="fail">FAIL</span>')
        rows.append([_num(r["offset"]), _num(r["hang_off_tension"] / 1e3),
                     cell(r, "curvature_static_MBR"), cell(r, "tension", 1e3), cell(r, "compression", 1e3),
                     cell(r, "sag_bend_clearance"), cell(r, "hog_bend_clearance"),
                     _num(math.degrees(r.get("hang_off_declination_lowest", math.nan)), 4), status])
        classes.append("" if r["passed"] is None else "passed" if r["passed"] else "failed")
    return _table(["Offset [m]", "Hang-off tension [kN]", "Largest curvature [1/m] (&kappa; MBR)",
                   "Largest tension [kN] (T / T<sub>allow</sub>)", "Smallest tension [kN]",
                   "Sag bend above seabed [m] (c<sub>req</sub> / c)", "Hog bend above seabed [m] (c<sub>req</sub> / c)",
                   "Hang-off declination [deg]", "Status"], rows, classes, cls="num checks cable")


def _figure_shape(ds, line: str | None = None) -> tuple[str, str]:
    """The cable's shape at each state: its elevation (x, z) with the seabed, and its plan (x, y) where it leaves the
    plane y = 0 (a cross offset)."""
    one = ds.sel(line=line) if line is not None and "line" in ds.dims else ds
    plt = _pyplot()
    x, y, z = (np.atleast_2d(np.asarray(one[c].transpose(..., "node").values, float)) for c in "xyz")
    offsets = np.asarray(one["offset"].values, float) if "offset" in one.dims else np.zeros(1)
    plan = bool(np.nanmax(np.abs(y)) > 1e-3)
    fig, axes = plt.subplots(2 if plan else 1, 1, figsize=(10.4, 6.4 if plan else 3.8), squeeze=False)
    ax = axes[0, 0]
    cmap = plt.get_cmap("viridis")
    for k, off in enumerate(offsets):
        colour = _SERIES if offsets.size == 1 else cmap(k / max(offsets.size - 1, 1))
        label = "static" if "offset" not in one.dims else f"offset {off:g} m"
        ax.plot(x[k], z[k], color=colour, lw=1.4, label=label)
        if plan:
            axes[1, 0].plot(x[k], y[k], color=colour, lw=1.4)
    floor, what = cable_.seabed_elevation(ds)
    xs = np.linspace(np.nanmin(x), np.nanmax(x), 50)
    if floor is not None:
        ax.plot(xs, floor(xs), color="#8c6d46", lw=2.0, label="seabed")
    h = z[offsets.size // 2] - (floor(x[offsets.size // 2]) if floor is not None else np.nanmin(z))
    found = cable_.bends(h[np.isfinite(h)])
    if found is not None:
        row = offsets.size // 2
        for idx, name in zip(found[1:], ("hog bend", "sag bend"), strict=True):
            ax.annotate(name, (x[row, idx], z[row, idx]), xytext=(0, 12), textcoords="offset points", ha="center",
                        fontsize=8, arrowprops={"arrowstyle": "-", "color": "#555555"})
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(loc="best", fontsize=8, ncol=2)
    if plan:
        axes[1, 0].set_xlabel("x [m]")
        axes[1, 0].set_ylabel("y [m]")
        axes[1, 0].set_title("plan", fontsize=9)
    img = _png(fig)
    plt.close(fig)
    caption = ("The cable's static shape" + ("" if "offset" not in one.dims else " at each offset of the hang-off")
               + f" (elevation{', and plan' if plan else ''}); the bends marked on the "
               + ("" if offsets.size == 1 else "middle offset's ") + f"shape. Seabed: {what}.")
    return img, caption


def _limits_html(limits, data: dict) -> str:
    def first(values, scale=1.0, unit=""):
        if values is None or not np.isfinite(values).any():
            return "not given"
        v = np.asarray(values, float)
        v = v[np.isfinite(v)]
        lo, hi = float(v.min()), float(v.max())
        return f"{_num(lo / scale)} {unit}" if lo == hi else f"{_num(lo / scale)} to {_num(hi / scale)} {unit}"

    design = ((data.get("analysis") or {}).get("design") or {})
    r = limits.hang_off_declination
    return _kv([("Minimum bend radius, static", first(limits.minimum_bend_radius, 1.0, "m")),
                ("Minimum bend radius, dynamic", first(limits.minimum_bend_radius_dynamic, 1.0, "m")
                 + " (not used by a static result)"),
                ("Allowable tension", first(limits.allowable_tension, 1e3, "kN")),
                ("Allowable compression", first(limits.allowable_compression, 1e3, "kN")),
                ("Sag bend clearance", f"{_num(limits.sag_bend_clearance)} m"),
                ("Hog bend clearance", f"{_num(limits.hog_bend_clearance)} m"),
                ("Hang-off declination", "not checked" if r is None else
                 f"{_num(math.degrees(r[0]))} to {_num(math.degrees(r[1]))} deg"),
                ("Line clearance", "not checked (a system result's)" if design.get("line_clearance") is None else
                 f"{_num(float(design['line_clearance']))} m (a system result's)")])


def make_static_report(ds, output: Path, source_label: str) -> list[Path]:
    """The report of a static or pushover result of a cable: one HTML page (inputs and limits, the shape, the
    cable checks against the static MBR, per offset, the range graphs) and the CSV and NetCDF tables beside it
    (``STEM_cable_checks.csv``, ``STEM_cable_offsets.csv``, ``STEM_range_graphs.nc``).

    Parameters
    ----------
    ds
        A ``mooring_static`` or ``mooring_pushover`` result with ``curvature``.
    output
        The HTML file.
    source_label
        How the page names the result.
    """
    analysis = str(ds.attrs.get("analysis", ""))
    if analysis not in STATIC_ANALYSES or not cable_.has_curvature(ds):
        raise InputError(f"the result has analysis '{analysis}'{'' if cable_.has_curvature(ds) else ' and no curvature'}"
                         ": the static cable report takes a mooring_static, mooring_pushover or system_static result of a line with "
                         "bending stiffness. Suggested fix: give the cable's EI (line_types.*.bending_stiffness).")
    if analysis == "system_static":
        raise InputError("make_static_report takes a single line's static or pushover result; a system_static result's "
                         "cables have a page of their own. Suggested fix: seacable.report_system_cable."
                         "make_system_static_report (what seacable report calls for it).")
    data = ds_.case_data(ds) or {}
    name = str(ds.attrs.get("case_name") or "result")
    line = None
    limits = cable_.cable_limits(ds)
    rows = cable_.cable_checks(ds, limits)
    line_name = ds_.line_names(ds)[0]
    checks = cable_.cable_check_table(rows)
    for col, value in (("line", line_name), ("seed", None), ("case", name), ("load_case", name)):
        checks.insert(0, col, value)
    offsets = offset_table(ds, limits, line)
    rg = cable_.range_graphs(ds, line)
    shape = _figure_shape(ds, line)
    graphs = _figure_range_graphs((name, line_name), rg, limits)
    now = datetime.datetime.now(datetime.UTC).strftime("%d %B %Y, %H:%M UTC")
    verdict = verdict_cards(checks, ("", "Hang-off tension" + (" (range over the offsets)" if len(offsets) > 1 else ""),
                                     f"{_num(offsets['hang_off_tension'].min() / 1e3)}" + (
                                         f" to {_num(offsets['hang_off_tension'].max() / 1e3)}" if len(offsets) > 1
                                         else "") + " kN"))
    base = output.resolve().parent
    heading = (data.get("analysis") or {}).get("heading")
    pushover = analysis == "mooring_pushover"
    inputs = [("Source", f"<code>{_e(_relative(source_label, base))}</code>"), ("Analysis", _e(analysis)),
              ("Line", _e(line_name))]
    if pushover:
        inputs.append(("Offsets", (f"{len(offsets)}, {_num(offsets['offset'].min())} to "
                                   f"{_num(offsets['offset'].max())} m along heading "
                                   f"{_num(math.degrees(float(heading or 0.0)))} deg")))
    parts = [(f"<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\">"
              f"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
              f"<title>Cable design report &ndash; {_e(name)}</title><style>{_CSS}</style></head><body><main>"),
             (f'<header class="top"><h1>Cable design report &ndash; {_e(name)}</h1>'
              f'<div class="meta">{_e(now)} &middot; seacable {_e(__version__)}'
              f"{' &middot; ' + _e(ds.attrs.get('comment') or data.get('description') or '')}</div></header>"),
             "<h2>Summary</h2>", verdict, "<h2>1. Inputs and limits</h2>", _kv(inputs),
             "<h3>Limits (line types and <code>analysis.design</code>)</h3>", _limits_html(limits, data)]
    if ds.attrs.get("case"):
        parts.append(f"<details><summary>Case file (YAML)</summary><pre>{_e(_relative(ds.attrs['case'], base))}</pre>"
                     "</details>")
    parts += ["<h2>2. Shape</h2>", _figure(shape),
              "<h2>3. Cable checks</h2>",
              ('<p class="method">Each check&rsquo;s worst value over the line' + (" and the offsets" if pushover else "")
               + " against its limit (<code>seacable.design.cable.cable_checks</code>): the largest curvature against "
               "1 / MBR with the line type's static <code>minimum_bend_radius</code> (a static result: the dynamic "
               "MBR is a dynamic run's), utilisation &kappa; MBR; the largest element tension against "
               "<code>allowable_tension</code>; the smallest against &minus;<code>allowable_compression</code>; the "
               "sag and hog bends above the seabed; the hang-off declination within its range.</p>"),
              _cable_html(checks)]
    if pushover:
        parts += ["<h3>Per offset</h3>",
                  ('<p class="method">The same checks at each offset of the hang-off alone, the bends found on that '
                   "offset's shape; in brackets the utilisation. Positive offsets move the hang-off along the "
                   "heading.</p>"), _offset_html(offsets)]
    parts += ["<h2>4. Range graphs</h2>", _figure(graphs),
              (f"<footer>Generated by seacable {_e(__version__)} on {_e(now)}. The tables are also in CSV files beside "
               "this page, in SI units (N, m, rad).</footer></main></body></html>")]
    page = "\n".join(parts)
    output.parent.mkdir(parents=True, exist_ok=True)
    written = [atomic_write(output, lambda tmp: tmp.write_text(page, encoding="utf-8"))]
    for key, table, units in (("cable_checks", checks, CABLE_CSV_UNITS),
                              ("cable_offsets", offsets, {"offset": "m", "hang_off_tension": "N"})):
        path = output.with_name(f"{output.stem}_{key}.csv")
        shown = table.rename(columns={c: f"{c} [{units[c]}]" for c in table.columns if c in units})
        written.append(atomic_write(path, lambda tmp, t=shown: t.to_csv(tmp, index=False)))
    path = output.with_name(f"{output.stem}_range_graphs.nc")
    written.append(atomic_write(path, lambda tmp: rg.to_netcdf(tmp, engine="netcdf4")))
    return written

"""The report page of a ``system_static`` result's cables (issue 40): a section per line with bending stiffness, each
with its limits, its shape in every condition (intact, damaged), its cable checks per condition
(:mod:`seacable.design.system_cable`: the single line's checks and the distance to the other lines) and its range
graphs over the conditions; the CSV and NetCDF tables a single line's page writes beside it.

:func:`seacable.report.make_report` calls :func:`make_system_static_report` for a ``system_static`` result with
curvature; a ``system_dynamic`` result's cables are a section of the time-domain report
(:class:`seacable.report_cable._Cable`).
"""

from __future__ import annotations

import datetime
import math
from pathlib import Path

import numpy as np
import pandas as pd

from ._atomic import atomic_write
from ._report_html import _CSS, _SERIES, _e, _figure, _kv, _num, _png, _pyplot, _relative, _table
from ._version import __version__
from .design import cable as cable_
from .design import summary as ds_
from .design.system_cable import (
    cable_lines,
    conditions,
    system_cable_checks,
    system_cable_states,
    system_cable_view,
)
from .errors import InputError
from .report_cable import (
    CABLE_CSV_UNITS,
    _cable_html,
    _figure_range_graphs,
    _limits_html,
    offset_table,
    verdict_cards,
)

__all__ = ["make_system_static_report", "system_condition_table"]

#: Colours of the conditions on the figures: intact, then each damaged condition.
_CONDITION_COLOURS = (_SERIES, "#d55e00", "#009e73", "#cc79a7")


def system_condition_table(ds, line: str) -> pd.DataFrame:
    """The checks of a system cable in each condition it is in, a row a condition (as a single line's
    :func:`seacable.report_cable.offset_table` a row an offset): the hang-off (end B) tension, each check's value and
    utilisation, and whether all pass; columns ``line`` and ``condition`` first."""
    rows = []
    names = conditions(ds)
    for k, condition in enumerate(names):
        state = ds.isel(condition=k) if "condition" in ds.dims else ds
        if not np.isfinite(np.asarray(state["fe_x"].sel(line=line).values, float)).any():
            continue  # the line is removed in this condition
        view = system_cable_view(ds, line, k)
        row = offset_table(view, cable_.cable_limits(view)).drop(columns="offset")
        row.insert(0, "condition", condition or "intact")
        row.insert(0, "line", line)
        rows.append(row)
    return pd.concat(rows, ignore_index=True)


def _condition_html(table: pd.DataFrame) -> str:
    def cell(r, key, scale=1.0, sig=4):
        v, u = r.get(key, math.nan), r.get(f"{key}_utilisation", math.nan)
        if not math.isfinite(v):
            return "&ndash;"
        return _num(v / scale, sig) + (f" ({_num(u, 3)})" if math.isfinite(u) else "")

    rows, classes = [], []
    for _, r in table.iterrows():
        status = "&ndash;" if r["passed"] is None else ('<span class="pass">PASS</span>' if r["passed"] else
                                                        '<span class="fail">FAIL</span>')
        rows.append([_e(r["condition"]), _num(r["hang_off_tension"] / 1e3), cell(r, "curvature_static_MBR"),
                     cell(r, "tension", 1e3), cell(r, "compression", 1e3), cell(r, "sag_bend_clearance"),
                     cell(r, "hog_bend_clearance"), _num(math.degrees(r.get("hang_off_declination_lowest", math.nan)), 4),
                     status])
        classes.append("" if r["passed"] is None else "passed" if r["passed"] else "failed")
    return _table(["Condition", "Hang-off tension [kN]", "Largest curvature [1/m] (&kappa; MBR)",
                   "Largest tension [kN] (T / T<sub>allow</sub>)", "Smallest tension [kN]",
                   "Sag bend above seabed [m] (c<sub>req</sub> / c)", "Hog bend above seabed [m] (c<sub>req</sub> / c)",
                   "Hang-off declination [deg]", "Status"], rows, classes, cls="num checks cable")


def _figure_system_shape(ds, line: str) -> tuple[str, str]:
    """A system cable's shape in each condition: its elevation (x, z) with the seabed and the bends of the intact
    shape, and the plan (x, y) of the whole system, the cable coloured by condition, the other lines grey (intact
    solid, damaged dashed)."""
    plt = _pyplot()
    stack = system_cable_states(ds, line)
    names = [str(c) for c in stack["condition"].values]
    fig, axes = plt.subplots(2, 1, figsize=(10.4, 7.6), squeeze=False, layout="constrained")
    ax, plan = axes[0, 0], axes[1, 0]
    for k, name in enumerate(names):
        one = stack.isel(condition=k)
        colour = _CONDITION_COLOURS[k % len(_CONDITION_COLOURS)]
        x, y, z = (np.asarray(one[c].values, float) for c in "xyz")
        style = {"color": colour, "lw": 1.4, "ls": "-" if k == 0 else (0, (5, 3)), "label": f"{line}, {name}"}
        ax.plot(x, z, **style)  # a damaged condition dashed: where it keeps the intact shape, both are seen
        plan.plot(x, y, **style)
    for k, name in enumerate(conditions(ds)):
        state = ds.isel(condition=k) if "condition" in ds.dims else ds
        for other in (str(v) for v in ds["line"].values):
            if other == line:
                continue
            x, y = (np.asarray(state[c].sel(line=other).values, float) for c in ("x", "y"))
            if np.isfinite(x).any():
                plan.plot(x, y, color="#8c8c8c", lw=0.9 if k == 0 else 0.7, ls="-" if k == 0 else "--",
                          label=f"other lines, {name or 'intact'}")
    floor, what = cable_.seabed_elevation(ds)
    x0 = np.asarray(stack["x"].values, float)
    xs = np.linspace(np.nanmin(x0), np.nanmax(x0), 50)
    if floor is not None:
        ax.plot(xs, floor(xs), color="#8c6d46", lw=2.0, label="seabed")
        intact = stack.isel(condition=0)
        h = np.asarray(intact["z"].values, float) - floor(np.asarray(intact["x"].values, float))
        found = cable_.bends(h)
        if found is not None:
            for idx, label in zip(found[1:], ("hog bend", "sag bend"), strict=True):
                ax.annotate(label, (float(intact["x"][idx]), float(intact["z"][idx])), xytext=(0, 12),
                            textcoords="offset points", ha="center", fontsize=8,
                            arrowprops={"arrowstyle": "-", "color": "#555555"})
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    ax.set_title(f"elevation of {line}", fontsize=9)
    ax.legend(loc="best", fontsize=8, ncol=2)
    plan.set_xlabel("x [m]")
    plan.set_ylabel("y [m]")
    plan.set_aspect("equal", adjustable="datalim")
    plan.set_title("plan of the system", fontsize=9)
    handles, labels = plan.get_legend_handles_labels()
    shown = dict(zip(labels, handles, strict=True))
    plan.legend(shown.values(), shown.keys(), loc="best", fontsize=8)
    img = _png(fig)
    plt.close(fig)
    caption = (f"The shape of {line} in each condition ({', '.join(names)}): its elevation, the bends marked on the "
               f"intact shape, and the plan of the system with the other lines. Seabed: {what}.")
    return img, caption


def _range_graphs_file(graphs: dict):
    """The range graphs of the cables in one Dataset: one cable as it is; several on a ``line`` dimension, each
    padded with NaN to the longest (``s`` then on ``line`` and ``node``)."""
    import xarray as xr

    if len(graphs) == 1:
        return next(iter(graphs.values()))
    n = max(rg.sizes["node"] for rg in graphs.values())
    padded = []
    for rg in graphs.values():
        rg = rg.reset_coords()  # s (and element_s) padded with the variables
        pad = {"node": (0, n - rg.sizes["node"])}
        if "element" in rg.dims:
            pad["element"] = (0, n - 1 - rg.sizes["element"])
        padded.append(rg.pad(pad))
    out = xr.concat(padded, dim="line", combine_attrs="drop_conflicts")
    out = out.assign_coords(line=("line", list(graphs)))
    return out.set_coords([c for c in ("s", "element_s") if c in out])


def make_system_static_report(ds, output: Path, source_label: str) -> list[Path]:
    """The report of a ``system_static`` result's cables: one HTML page, a section per line with bending stiffness
    (its limits, its shape in each condition, its checks per condition and its range graphs over them), and beside it
    ``STEM_cable_checks.csv`` (every cable and condition, columns ``line`` and ``condition``),
    ``STEM_cable_offsets.csv`` (a row a cable and condition: the hang-off tension and each check's value and
    utilisation) and ``STEM_range_graphs.nc``.

    Parameters
    ----------
    ds
        A ``system_static`` result with bending outputs (a line with bending stiffness, the finite-element statics).
    output
        The HTML file.
    source_label
        How the page names the result.

    Raises
    ------
    InputError
        A result that is not a ``system_static`` one with a line that bends.
    """
    analysis = str(ds.attrs.get("analysis", ""))
    lines = cable_lines(ds) if analysis == "system_static" and "fe_s" in ds.variables else []
    if not lines:
        raise InputError(f"the result has analysis '{analysis}' and no line with bending stiffness in the finite-element"
                         " statics: the system's cable report takes a system_static result with a cable. Suggested "
                         "fix: give the cable's line type its bending_stiffness (EI, N m^2).")
    data = ds_.case_data(ds) or {}
    name = str(ds.attrs.get("case_name") or ds.attrs.get("title") or "result")
    frames = []
    for line, condition, checks in system_cable_checks(ds, lines):
        table = cable_.cable_check_table(checks)
        for col, value in (("condition", condition or "intact"), ("line", line), ("seed", None), ("case", name),
                           ("load_case", name)):
            table.insert(0, col, value)
        frames.append(table)
    checks = pd.concat(frames, ignore_index=True)
    per_condition = pd.concat([system_condition_table(ds, line) for line in lines], ignore_index=True)
    graphs = {line: cable_.range_graphs(system_cable_states(ds, line)) for line in lines}
    now = datetime.datetime.now(datetime.UTC).strftime("%d %B %Y, %H:%M UTC")
    t_ho = per_condition["hang_off_tension"]
    verdict = verdict_cards(checks, ("", "Hang-off tension" + (" (range)" if len(per_condition) > 1 else ""),
                                     f"{_num(t_ho.min() / 1e3)}"
                                     + (f" to {_num(t_ho.max() / 1e3)}" if len(per_condition) > 1 else "") + " kN"),
                            where=("check", "line", "condition"))
    base = output.resolve().parent
    comment = ds.attrs.get("comment") or data.get("description") or ""
    damaged = (data.get("analysis") or {}).get("damaged_lines")
    inputs = [("Source", f"<code>{_e(_relative(source_label, base))}</code>"), ("Analysis", _e(analysis)),
              ("Lines with bending stiffness", _e(", ".join(lines))),
              ("Other lines", _e(", ".join(str(v) for v in ds["line"].values if str(v) not in lines) or "none")),
              ("Conditions", _e(", ".join(c or "intact" for c in conditions(ds)))
               + (f" (damaged: without {_e(', '.join(damaged) if isinstance(damaged, list) else damaged)})"
                  if damaged else ""))]
    parts = [(f"<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\">"
              f"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
              f"<title>Cable design report &ndash; {_e(name)}</title><style>{_CSS}</style></head><body><main>"),
             (f'<header class="top"><h1>Cable design report &ndash; {_e(name)}</h1>'
              f'<div class="meta">{_e(now)} &middot; seacable {_e(__version__)}'
              f"{(' &middot; ' + _e(comment)) if comment else ''}</div></header>"),
             "<h2>Summary</h2>", verdict, "<h2>1. Inputs</h2>", _kv(inputs)]
    if ds.attrs.get("case"):
        parts.append(f"<details><summary>Case file (YAML)</summary><pre>{_e(_relative(ds.attrs['case'], base))}</pre>"
                     "</details>")
    method = ('<p class="method">Each check&rsquo;s worst value over the line in each condition against its limit '
              "(<code>seacable.design.system_cable</code>, the single line's <code>cable_checks</code> on the line's "
              "finite-element shape): the largest curvature against 1 / MBR with the line type's static "
              "<code>minimum_bend_radius</code>, utilisation &kappa; MBR; the largest element tension against "
              "<code>allowable_tension</code>; the smallest against &minus;<code>allowable_compression</code>; the "
              "sag and hog bends above the seabed; the declination at end B (the hang-off) within its range; the "
              "smallest distance to the other lines of the same condition against <code>analysis.design."
              "line_clearance</code>.</p>")
    for i, line in enumerate(lines, start=2):
        view = system_cable_view(ds, line, 0)
        mine = checks[checks["line"] == line]
        parts += [f"<h2>{i}. Cable &lsquo;{_e(line)}&rsquo;</h2>",
                  "<h3>Limits (its line types and <code>analysis.design</code>)</h3>",
                  _limits_html(cable_.cable_limits(view), data),
                  "<h3>Shape</h3>", _figure(_figure_system_shape(ds, line)),
                  "<h3>Cable checks</h3>", method, _cable_html(mine, ("Condition", "condition"))]
        if mine["condition"].nunique() > 1:
            parts += ["<h3>Per condition</h3>",
                      '<p class="method">The same checks in each condition alone; in brackets the utilisation.</p>',
                      _condition_html(per_condition[per_condition["line"] == line])]
        over = ", ".join(sorted(set(mine["condition"]), key=list(mine["condition"]).index))
        parts += ["<h3>Range graphs</h3>", _figure(_figure_range_graphs((over, line), graphs[line],
                                                                        cable_.cable_limits(view)))]
    parts.append(f"<footer>Generated by seacable {_e(__version__)} on {_e(now)}. The tables are also in CSV files beside "
                 "this page, in SI units (N, m, rad).</footer></main></body></html>")
    page = "\n".join(parts)
    output.parent.mkdir(parents=True, exist_ok=True)
    written = [atomic_write(output, lambda tmp: tmp.write_text(page, encoding="utf-8"))]
    for key, table, units in (("cable_checks", checks, CABLE_CSV_UNITS),
                              ("cable_offsets", per_condition, {"hang_off_tension": "N"})):
        path = output.with_name(f"{output.stem}_{key}.csv")
        shown = table.rename(columns={c: f"{c} [{units[c]}]" for c in table.columns if c in units})
        written.append(atomic_write(path, lambda tmp, t=shown: t.to_csv(tmp, index=False)))
    merged = _range_graphs_file(graphs)
    path = output.with_name(f"{output.stem}_range_graphs.nc")
    written.append(atomic_write(path, lambda tmp: merged.to_netcdf(tmp, engine="netcdf4")))
    return written

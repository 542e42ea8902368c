"""The design report of a time-domain mooring result or a sweep of them (issue 20): one self-contained HTML page
and the same tables as CSV files beside it.

``seacable report RESULT.nc|SWEEP_DIR -o report.html`` (or :func:`make_report`) reads the results and makes the
design tables of :mod:`seacable.design.summary` (extremes, code checks, fatigue) in one pass over them
(:func:`seacable.design.summary.design_tables`: each result file is opened once) and writes:

- ``report.html``: the inputs, the model and its references, the tables (tensions in kN, four significant
  digits) and the figures (matplotlib, inline base64 PNG); inline CSS, no script, nothing fetched;
- ``report_extremes.csv``, ``report_seeds.csv``, ``report_checks.csv``, ``report_fatigue.csv`` (and
  ``report_fatigue_life.csv`` with a scatter diagram): the same tables in SI units (N, m, s), full precision,
  the unit of each column in its header;
- for a result of a line with bending stiffness (one with ``curvature``, issue 40), also its range graphs and
  cable checks (:mod:`seacable.design.cable`): a section of the page, ``report_cable_checks.csv`` and the range
  graphs in ``report_range_graphs.nc`` (a ``load_case`` dimension when there are several), and where the case gives
  ``analysis.design.armour`` the armour's fatigue (``report_cable_fatigue.csv``). A result without curvature gives
  the same page and files as before.

A ``mooring_static`` or ``mooring_pushover`` result of a cable (with ``curvature``) gets a page of its own
(:func:`seacable.report_cable.make_static_report`: its shape, the checks against the static MBR, per offset), and a
``system_static`` result with a cable a page of its cables (:func:`seacable.report_system_cable.
make_system_static_report`: a section a cable, its checks in each condition). A ``system_dynamic`` result's cable
section checks each line with bending stiffness (:mod:`seacable.design.system_cable`), not its chains.

Every file is written whole (:mod:`seacable._atomic`).
"""

from __future__ import annotations

import datetime
import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from ._atomic import atomic_write
from ._report_html import (
    _CSS,
    _SERIES,
    _column,
    _columns,
    _e,
    _figure,
    _kv,
    _mark,
    _notes_block,
    _num,
    _plain,
    _png,
    _pyplot,
    _relative,
    _status,
    _table,
)
from ._version import __version__
from .design import checks as checks_
from .design import summary as ds_
from .design.combination import API_COMBINATION, DNV_COMBINATION, SPLIT_PERIOD
from .design.fatigue import DNV_DESIGN_FATIGUE_FACTOR
from .errors import InputError
from .report_cable import (
    ARMOUR_CSV_UNITS,
    CABLE_CSV_UNITS,
    STATIC_ANALYSES,
    _Cable,
    _cable_section,
    _figure_range_graphs,
    _range_graphs_file,
    make_static_report,
)
from .report_system_cable import make_system_static_report

__all__ = ["CABLE_CSV_UNITS", "CSV_UNITS", "ReportOptions", "make_report"]

#: The unit of each column of the CSV tables, appended to its header.
CSV_UNITS = {"duration": "s", "storm": "s", "maximum": "N", "mean": "N", "std": "N", "weibull_mpm": "N",
             "weibull_quantile": "N", "maximum_largest": "N", "maximum_mean": "N", "gumbel_mpm": "N",
             "gumbel_quantile": "N", "design_maximum": "N", "dynamic": "N", "demand": "N or m, see unit",
             "capacity": "N or m, see unit", "utilisation": "-", "margin": "N or m, see unit", "nominal_diameter": "m", "damage": "-",
             "damage_per_year": "1/year", "life_alone": "years", "probability": "-", "life": "years",
             "lf_std": "N", "wf_std": "N", "lf_period": "s", "wf_period": "s", "api_maximum": "N", "dnv_dynamic": "N",
             "dnv_maximum": "N", "time_domain_maximum": "N"}


@dataclass
class ReportOptions:
    """The choices of a report (see ``seacable report --help``)."""

    storm_duration: float | None = None   #: the storm's duration [s]; None: the runs' duration
    quantile: float = 0.9                 #: non-exceedance probability of the storm maximum's quantile [-]
    consequence_class: int = 1            #: DNV-OS-E301 consequence class, 1 or 2
    offset_limit: float | None = None     #: allowed horizontal offset of the bodies [m]; None: not checked
    scatter: str | Path | None = None     #: scatter diagram CSV (hs, tp, probability)
    tn_curve: str | None = None           #: T-N curve; None: by the line type
    nominal_diameter: float | None = None  #: nominal diameter for fatigue [m]; None: from the line type
    allowed_uplift: float = 0.0           #: allowed vertical force on the anchors [N]
    design_fatigue_factor: float = DNV_DESIGN_FATIGUE_FACTOR  #: DNV-OS-E301's design fatigue factor, 5 [-]
    extra: dict = field(default_factory=dict)


# ------------------------------------------------------------------------------------------------- numbers


def _with_units(table: pd.DataFrame, units: dict | None = None) -> pd.DataFrame:
    units = CSV_UNITS if units is None else units
    return table.rename(columns={c: f"{c} [{units[c]}]" for c in table.columns if c in units})


# ------------------------------------------------------------------------------------------------- figures


class _MostLoaded:
    """Kept as the results are read (a ``visit`` of :func:`seacable.design.summary.design_tables`): the first run's
    attributes, and the time and fairlead tension of the line with the largest fairlead tension so far (the first
    of equal ones, as the seed table's ``idxmax``), so that the figure reads no result file again."""

    def __init__(self):
        self.attrs = None
        self.maximum = -math.inf
        self.run = self.line = self.time = self.tension = None

    def __call__(self, run, ds) -> None:
        if self.attrs is None:
            self.attrs = dict(ds.attrs)
        for line in ds_.line_names(ds):
            record = ds_.line_series(ds, "fairlead_tension", line)
            if float(np.max(record)) > self.maximum:
                self.maximum = float(np.max(record))
                self.run, self.line = run, line
                self.time = np.asarray(ds["time"].values, float)
                self.tension = record


def _figure_time_series(runs, seeds: pd.DataFrame, kept: _MostLoaded | None = None) -> tuple[str, str] | None:
    fair = seeds[seeds["end"] == "fairlead"]
    if fair.empty:
        return None
    top = fair.loc[fair["maximum"].idxmax()]
    run = next(r for r in runs if r.name == top["case"] and r.load_case == top["load_case"])
    if kept is not None and kept.run is run and kept.line == top["line"]:
        t, y = kept.time, kept.tension / 1e3
    else:
        with run.open() as ds:
            t = np.asarray(ds["time"].values, float)
            y = ds_.line_series(ds, "fairlead_tension", top["line"]) / 1e3
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(10.4, 3.4))
    ax.plot(t, y, color=_SERIES, lw=0.9, label="fairlead tension")
    ax.axhline(float(np.mean(y)), color="#7f7f7f", lw=0.8, ls="--", label=f"mean {_plain(np.mean(y))} kN")
    k = int(np.argmax(y))
    ax.plot(t[k], y[k], "o", color="#c00000", ms=6, label=f"maximum {_plain(y[k])} kN at t = {_plain(t[k])} s")
    ax.yaxis.get_major_formatter().set_useOffset(False)
    if np.ptp(y) < 1e-3 * abs(float(np.mean(y))):  # a quasi-static record: its noise is not the message
        ax.set_ylim(float(np.mean(y)) * 0.99, float(np.mean(y)) * 1.01)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("fairlead tension [kN]")
    ax.set_xlim(t[0], t[-1])
    ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.0), fontsize=8, frameon=False, ncol=3)
    seed = "" if pd.isna(top["seed"]) else f", seed {int(top['seed'])}"
    caption = (f"Fairlead tension of the most loaded line, {top['line']} ({top['load_case']}{seed}; case "
               f"{top['case']}), its maximum marked.")
    img = _png(fig)
    plt.close(fig)
    return img, caption


def _figure_maxima(seeds: pd.DataFrame, extremes: pd.DataFrame) -> tuple[str, str] | None:
    fair = seeds[seeds["end"] == "fairlead"]
    ext = extremes[extremes["end"] == "fairlead"].sort_values("design_maximum", ascending=False)
    if fair.empty or fair.groupby(["load_case", "line"]).size().max() < 2:
        return None  # one seed each: the table says it all
    shown = ext.head(40)
    many = ext["load_case"].nunique() > 1
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(10.4, 3.6))
    labels = []
    for k, (_, e) in enumerate(shown.iterrows()):
        g = fair[(fair["load_case"] == e["load_case"]) & (fair["line"] == e["line"])]
        jitter = np.linspace(-0.15, 0.15, len(g)) if len(g) > 1 else np.zeros(1)
        ax.plot(k + jitter, g["maximum"] / 1e3, "o", color=_SERIES, ms=4,
                label="maximum of a seed" if k == 0 else None)
        ax.plot([k - 0.3, k + 0.3], [e["design_maximum"] / 1e3] * 2, color="#c00000", lw=2,
                label="design maximum" if k == 0 else None)
        labels.append(f"{e['line']}\n{e['load_case']}" if many else str(e["line"]))
    crowded = len(labels) > 8
    ax.set_xticks(range(len(labels)), labels, fontsize=7 if crowded else 8.5, rotation=35 if crowded else 0,
                  ha="right" if crowded else "center")
    ax.set_ylabel("fairlead tension maximum [kN]")
    ax.yaxis.get_major_formatter().set_useOffset(False)
    ax.set_xlim(-0.6, len(labels) - 0.4)
    ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.0), fontsize=8, frameon=False, ncol=2)
    caption = "Maximum fairlead tension of each seed, per line" + (" and load case" if many else "") + \
              ", and the design maximum (red)."
    if len(ext) > len(shown):
        caption += f" The {len(shown)} most loaded of {len(ext)} are shown."
    img = _png(fig)
    plt.close(fig)
    return img, caption


def _figure_utilisation(checks: pd.DataFrame) -> tuple[str, str] | None:
    rows = checks[np.isfinite(checks["utilisation"].astype(float))].sort_values("utilisation", ascending=False)
    if rows.empty:
        return None
    shown = rows.head(30).iloc[::-1]
    many = checks["load_case"].nunique() > 1
    u = shown["utilisation"].to_numpy(float)
    top = float(np.max(u))
    limit = max(1.2, top * 1.1)
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(10.4, 0.9 + 0.28 * len(shown)))
    colours = ["#2e7d32" if p else "#c62828" for p in shown["passed"]]
    ax.barh(range(len(shown)), np.minimum(u, limit), color=colours, height=0.65)
    for k, value in enumerate(u):
        ax.text(min(value, limit) + limit * 0.01, k, f"{value:.3f}", va="center", fontsize=7.5)
    ax.axvline(1.0, color="#333333", lw=1.0, ls="--")
    labels = [f"{r['check']} \u2013 {r['item']}" + (f" ({r['load_case']})" if many else "")
              for _, r in shown.iterrows()]
    ax.set_yticks(range(len(shown)), labels, fontsize=7.5)
    ax.set_xlim(0, limit * 1.08)
    ax.set_xlabel("utilisation [-] (1 = the capacity)")
    ax.grid(axis="y", visible=False)
    caption = "Utilisation of each check: green passes, red fails; the dashed line is the capacity."
    zero = int(checks["passed"].notna().sum()) - len(rows)
    if zero:
        caption += (f" {zero} check(s) against a zero capacity (a drag anchor's uplift) have no utilisation: "
                    "their margin is in the table.")
    if len(rows) > len(shown):
        caption += f" The {len(shown)} highest of {len(rows)} are shown."
    img = _png(fig)
    plt.close(fig)
    return img, caption


# -------------------------------------------------------------------------------------------------- tables


def _extremes_html(ext: pd.DataFrame, quantile: float) -> str:
    q = f"q{round(quantile * 100):d}"
    headers = ["Load case", "Line", "End", "Seeds", "Mean [kN]", "Std. dev. [kN]", "Largest max. [kN]",
               "Mean of maxima [kN]", "Gumbel MPM [kN]", f"Gumbel {q} [kN]", "Weibull MPM [kN]",
               f"Weibull {q} [kN]", "Design max. [kN]", "Basis"]
    kn = ("mean", "std", "maximum_largest", "maximum_mean", "gumbel_mpm", "gumbel_quantile", "weibull_mpm",
          "weibull_quantile", "design_maximum")
    col = _columns(ext, {c: (1e3, 4) for c in kn})
    notes: dict[str, str] = {}
    rows = []
    for k, (_, r) in enumerate(ext.iterrows()):
        rows.append([_e(r["load_case"]), _e(r["line"]), _e(r["end"]), str(int(r["seeds"])), col["mean"][k],
                     col["std"][k], col["maximum_largest"][k], col["maximum_mean"][k],
                     col["gumbel_mpm"][k] + _mark(notes, r["gumbel_note"]), col["gumbel_quantile"][k],
                     col["weibull_mpm"][k] + _mark(notes, r["weibull_note"])
                     + _mark(notes, r.get("weibull_flag", "") or ""), col["weibull_quantile"][k],
                     f"<b>{col['design_maximum'][k]}</b>", _e(r["design_basis"])])
    return _table(headers, rows, cls="num extremes", single=ext["load_case"].nunique() == 1) + _notes_block(notes)


def _components_html(parts: pd.DataFrame) -> str:
    """Which parts of the load each load case modelled (:func:`seacable.design.combination.modelled_components`),
    the ones left out in red: the first load case's rows alone when every load case has the same statuses."""
    if parts.empty:
        return ""
    same = parts.groupby("load_case", sort=False)[["component", "status"]].apply(
        lambda g: tuple(map(tuple, g.values))).nunique() == 1  # the same statuses: the first load case's rows
    shown = parts[parts["load_case"] == parts["load_case"].iloc[0]] if same else parts
    rows = [[_e(r["load_case"]), _e(r["component"]), f"<b>{_e(r['status'])}</b>", _e(r["how"])]
            for _, r in shown.iterrows()]
    classes = ["failed" if r["status"] == "NOT MODELLED" else "" for _, r in shown.iterrows()]
    return _table(["Load case", "Component", "Status", "How"], rows, classes, cls="components", single=same)


def _combined_html(comb: pd.DataFrame) -> str:
    """The LF/WF parts of the fairlead tension and the standards' combinations beside the time-domain maximum."""
    if comb.empty:
        return ""
    col = _columns(comb, {**{c: (1e3, 4) for c in ("mean", "lf_std", "wf_std", "api_maximum", "dnv_maximum",
                                                    "time_domain_maximum")}, "lf_period": (1.0, 3),
                          "wf_period": (1.0, 3)})
    notes: dict[str, str] = {}
    rows = [[_e(r["load_case"]), _e(r["line"]) + _mark(notes, r["note"]), col["mean"][k], col["lf_std"][k],
             col["lf_period"][k], col["wf_std"][k], col["wf_period"][k], col["api_maximum"][k], col["dnv_maximum"][k],
             f"<b>{col['time_domain_maximum'][k]}</b>"] for k, (_, r) in enumerate(comb.iterrows())]
    return _table(["Load case", "Line", "Mean [kN]", "LF std. [kN]", "LF T<sub>z</sub> [s]", "WF std. [kN]",
                   "WF T<sub>z</sub> [s]", "API RP 2SK T<sub>max</sub> [kN]", "DNV T<sub>c</sub> [kN]",
                   "Time-domain design max. [kN]"], rows, cls="num combined",
                  single=comb["load_case"].nunique() == 1) + _notes_block(notes)


#: The checks' tables of the page, one per quantity: (rows, title, unit shown, scale, class).
_CHECK_GROUPS = ((lambda c: (c["unit"] == "N") & (c["check"] != "anchor uplift"), "Line tensions", "kN", 1e3, "kN"),
                 (lambda c: c["check"] == "anchor uplift", "Anchor uplift", "kN", 1e3, "uplift"),
                 (lambda c: c["unit"] == "m", "Offsets", "m", 1.0, "m"))


def _checks_html(chk: pd.DataFrame) -> str:
    """The checks, one table per quantity (line tensions and anchor uplift in kN, offsets in m): demand,
    capacity and margin in the header's unit, utilisation
    only where the capacity is positive (a dash where it is zero: the margin says it)."""
    parts = []
    for rows_of, title, shown, scale, name in _CHECK_GROUPS:
        group = chk[rows_of(chk)]
        if group.empty:
            continue
        headers = ["Load case", "Check", "Item", f"Demand [{shown}]", f"Capacity [{shown}]", f"Margin [{shown}]",
                   "Utilisation [-]", "Status"]
        col = _columns(group, {"demand": (scale, 4), "capacity": (scale, 4), "margin": (scale, 4)},
                       alike=("demand", "capacity", "margin"))
        col["utilisation"] = _column(list(group["utilisation"]), 1.0, 4, like=[1.0])  # three decimals (below 10)
        rows, classes = [], []
        for k, (_, r) in enumerate(group.iterrows()):
            status, cls = _status(r)
            rows.append([_e(r["load_case"]), _e(r["check"]), _e(r["item"]), col["demand"][k], col["capacity"][k],
                         col["margin"][k], col["utilisation"][k], status])
            classes.append(cls)
        parts.append(f"<h3>{title}</h3>" + _table(headers, rows, classes, cls=f"num checks {name}",
                                                  single=chk["load_case"].nunique() == 1))
    return "".join(parts)


def _basis_html(chk: pd.DataFrame) -> str:
    done = chk[chk["formula"].astype(str) != ""].drop_duplicates(["check", "formula"])
    if done.empty:
        return ""
    rows = [[_e(r["check"]), f"<code>{_e(r['formula'])}</code>", _e(r["reference"])] for _, r in done.iterrows()]
    return "<h3>Basis of the checks</h3>" + _table(["Check", "Formula", "Reference"], rows, cls="basis")


def _fatigue_html(fat: pd.DataFrame) -> str:
    headers = ["Load case", "Line", "T-N curve", "Nominal diameter [mm]", "Seeds", "Duration [s]", "Damage [-]",
               "Damage per year if permanent [1/yr]", "Life if permanent [years]", "Probability [-]"]
    col = _columns(fat, {"nominal_diameter": (1e-3, 3), "duration": (1.0, 4), "damage": (1.0, 3),
                         "damage_per_year": (1.0, 3), "life_alone": (1.0, 3), "probability": (1.0, 3)})
    notes: dict[str, str] = {}
    rows = []
    for k, (_, r) in enumerate(fat.iterrows()):
        curve = str(r["tn_curve"]).replace("_", " ") if r["tn_curve"] else "&ndash;"
        rows.append([_e(r["load_case"]), _e(r["line"]) + _mark(notes, r["note"]),
                     curve + _mark(notes, f"T-N curve from {r['tn_basis']}" if r.get("tn_basis") else ""),
                     col["nominal_diameter"][k], str(int(r["seeds"])), col["duration"][k], col["damage"][k],
                     col["damage_per_year"][k], col["life_alone"][k], col["probability"][k]])
    return _table(headers, rows, cls="num fatigue", single=fat["load_case"].nunique() == 1) + _notes_block(notes)


def _life_html(life: pd.DataFrame) -> str:
    col = _columns(life, {"damage_per_year": (1.0, 3), "life": (1.0, 3), "design_fatigue_factor": (1.0, 3)})
    rows = []
    notes: dict[str, str] = {}
    for k, (_, r) in enumerate(life.iterrows()):
        rows.append([_e(r["line"]) + _mark(notes, r["note"]), _e(str(r["tn_curve"]).replace("_", " ")),
                     str(int(r["load_cases"])), col["damage_per_year"][k], f"<b>{col['life'][k]}</b>",
                     col["design_fatigue_factor"][k]])
    return _table(["Line", "T-N curve", "Sea states", "Damage per year [1/yr]", "Fatigue life [years]",
                   "Design fatigue factor [-]"], rows, cls="num life") + _notes_block(notes)


# ----------------------------------------------------------------------------------------------------- page


def _first_attrs(runs) -> dict:
    with runs[0].open() as ds:
        return dict(ds.attrs)


def _sweep_info(source) -> dict:
    path = Path(source) if isinstance(source, (str, Path)) else None
    if path is None or not path.is_dir():
        return {}
    import xarray as xr

    with xr.open_dataset(path / "summary.nc", engine="netcdf4") as s:
        s = s.load()
    failed = [(str(n), str(e).splitlines()[0] if str(e) else "") for n, st, e in
              zip(s["name"].values, s["status"].values, s["error"].values) if str(st) != "done"]
    return {"sweep": s.attrs.get("sweep", ""), "name": s.attrs.get("title", path.name),
            "description": s.attrs.get("comment", ""), "parameters": json.loads(s.attrs.get("parameters", "[]")),
            "failed": failed, "cases": int(s.attrs.get("cases", s.sizes["case"]))}


def _settings_html(settings: str) -> str:
    try:
        data = json.loads(settings) if settings else {}
    except ValueError:
        return f"<pre>{_e(settings)}</pre>"
    if not isinstance(data, dict) or not data:
        return "<p>none recorded</p>"
    return _kv([(_e(k), _e(json.dumps(v) if not isinstance(v, str) else v)) for k, v in data.items()])


def _verdict(chk: pd.DataFrame, ext: pd.DataFrame, life: pd.DataFrame | None,
             parts: pd.DataFrame | None = None, cable: pd.DataFrame | None = None) -> str:
    checked = chk[chk["passed"].notna()]
    failed = checked[~checked["passed"].astype(bool)]
    skipped = chk[chk["passed"].isna()]
    cards = []
    if checked.empty:
        cards.append(("warn", "Code checks", "none made"))
    elif failed.empty:
        cards.append(("ok", "Code checks", f"all {len(checked)} pass"))
    else:
        cards.append(("bad", "Code checks", f"{len(failed)} of {len(checked)} fail"))
    ratio = checked[checked["utilisation"].notna()]
    if not ratio.empty:
        top = ratio.loc[ratio["utilisation"].idxmax()]
        u = float(top["utilisation"])
        cards.append(("bad" if u > 1 else "ok", f"Largest utilisation ({_e(top['check'])}, {_e(top['item'])})",
                      _column([u], sig=4, like=[1.0])[0]))  # as the table shows it
    zero = failed[failed["utilisation"].isna()]  # a zero capacity exceeded: no ratio, the margin says it
    for check, g in zero.groupby("check", sort=False):
        worst = g.loc[g["margin"].idxmin()]
        scale, unit = (1.0, "m") if worst["unit"] == "m" else (1e3, "kN")
        cards.append(("bad", f"{_e(check)}: capacity 0, {len(g)} fail (worst: {_e(worst['item'])})",
                      f"margin {_num(worst['margin'], scale=scale)} {unit}"))
    if not skipped.empty:
        cards.append(("warn", "Not checked", f"{len(skipped)} check(s)"))
    missing = [] if parts is None or parts.empty else list(dict.fromkeys(
        parts.loc[parts["status"] == "NOT MODELLED", "component"]))
    if missing:
        cards.append(("bad", "Not modelled (extremes non-conservative)", _e(", ".join(missing))))
    flagged = ext[ext["weibull_flag"].fillna("") != ""] if "weibull_flag" in ext else ext.iloc[:0]
    if not flagged.empty:
        cards.append(("warn", "Weibull fits on few peaks (uncertain)", f"{len(flagged)} of {len(ext)} rows"))
    fair = ext[ext["end"] == "fairlead"]
    if not fair.empty:
        top = fair.loc[fair["design_maximum"].idxmax()]
        cards.append(("", f"Design max. fairlead tension ({_e(top['line'])})",
                      f"{_num(top['design_maximum'], scale=1e3)} kN"))
    if cable is not None:
        done = cable[cable["passed"].notna()]
        bad = done[~done["passed"].astype(bool)]
        cards.append(("bad" if len(bad) else "ok" if len(done) else "warn", "Cable checks",
                      f"{len(bad)} of {len(done)} fail" if len(bad) else f"all {len(done)} pass" if len(done)
                      else "none made"))
    if life is not None and not life.empty and life["life"].notna().any():
        top = life.loc[life["life"].idxmin()]
        cards.append(("", f"Shortest fatigue life ({_e(top['line'])})", f"{_num(top['life'], sig=3)} years"))
    return '<div class="verdict">' + "".join(
        f'<div class="card {c}"><div class="k">{k}</div><div class="v">{v}</div></div>' for c, k, v in cards) + "</div>"


def _html(source, runs, tables: dict, figures: dict, opts: ReportOptions, base: Path | None = None,
          attrs: dict | None = None) -> str:
    """The page; ``base``: its folder, which the paths it shows are relative to; ``attrs``: the first run's
    attributes (read from it when not given)."""
    attrs = _first_attrs(runs) if attrs is None else attrs
    sweep = _sweep_info(source)

    def path(p) -> str:
        return _e(_relative(Path(p).resolve(), base)) if isinstance(p, (str, Path)) else _e(p)

    name = sweep.get("name") or attrs.get("case_name") or attrs.get("title") or "result"
    description = sweep.get("description") or attrs.get("comment", "")
    now = datetime.datetime.now(datetime.UTC).strftime("%d %B %Y, %H:%M UTC")
    ext, chk, fat, life, seeds = (tables[k] for k in ("extremes", "checks", "fatigue", "fatigue_life", "seeds"))
    load_cases = list(dict.fromkeys(r.load_case for r in runs))
    durations = sorted({float(x) for x in seeds["duration"]})
    storm = "the runs' duration" if opts.storm_duration is None else f"{_num(opts.storm_duration)} s"
    shown = path(source)
    source_cell = "the report's own folder" if shown == "." else f"<code>{shown}</code>"
    inputs = [("Source", source_cell), ("Analysis", _e(attrs.get("analysis", ""))),
              ("Runs (seeds)", str(len(runs))), ("Load cases", str(len(load_cases))),
              ("Simulated duration of a run", ", ".join(f"{_num(d)} s" for d in durations)),
              ("Storm duration", storm), ("Quantile of the storm maximum", _num(opts.quantile, sig=3)),
              ("DNV-OS-E301 consequence class", str(opts.consequence_class)),
              ("Offset limit", "not checked" if opts.offset_limit is None else f"{_num(opts.offset_limit)} m"),
              ("Allowed anchor uplift", f"{_num(opts.allowed_uplift, scale=1e3)} kN"),
              ("T-N curve", _e(opts.tn_curve) if opts.tn_curve else "by the line type (its material, else its name)"),
              ("Design fatigue factor", _num(opts.design_fatigue_factor, sig=3)
               + (" (DNV-OS-E301 Ch.2 Sec.2 D)" if opts.design_fatigue_factor == DNV_DESIGN_FATIGUE_FACTOR else "")),
              ("Scatter diagram", f"<code>{path(opts.scatter)}</code>" if opts.scatter else "none")]
    if sweep.get("failed"):
        inputs.append(("Cases not in the report", f"{len(sweep['failed'])} of {sweep['cases']} (failed or not run)"))
    parts = [(f"<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\">"
             f"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
             f"<title>Mooring design report &ndash; {_e(name)}</title><style>{_CSS}</style></head><body><main>"),
             (f'<header class="top"><h1>Mooring design report &ndash; {_e(name)}</h1>'
             f'<div class="meta">{_e(now)} &middot; seacable {_e(__version__)}'
             f"{' &middot; ' + _e(description) if description else ''}</div></header>"),
             "<h2>Summary</h2>", _verdict(chk, ext, life if not life.empty else None, tables.get("components"),
                                          tables.get("cable_checks"))]
    parts += ["<h2>1. Inputs</h2>", _kv(inputs)]
    if tables.get("components") is not None and not tables["components"].empty:
        parts += ["<h3>Components of the load modelled</h3>",
                  ('<p class="method">Read from each load case\'s case file: the wave-frequency response (waves), the '
                  "low-frequency slow drift, the mean loads of wave drift, wind and current. A component NOT "
                  "MODELLED is missing from the extremes and checks below, which are then not conservative "
                  "(DNV-OS-E301 Ch.2 Sec.2 and API RP 2SK ask for all of them). Where every load case modelled the "
                  "same components, the first load case's rows stand for all (its sea shown); the CSV file holds "
                  "every load case.</p>"),
                  _components_html(tables["components"])]
    if sweep.get("parameters"):
        params = [p for p in sweep["parameters"]]
        rows = []
        for lc in load_cases:
            members = [r for r in runs if r.load_case == lc]
            seeds_ = [str(r.seed) for r in members if r.seed is not None]
            rows.append([_e(lc), str(len(members)), _e(", ".join(seeds_) or "–")])
        parts += [f"<h3>Load cases of the sweep (swept: {_e(', '.join(params))})</h3>",
                  _table(["Load case", "Runs", "Seeds"], rows)]
    if sweep.get("failed"):
        rows = [[_e(n), _e(_relative(e, base))] for n, e in sweep["failed"]]
        parts += ["<h3>Cases left out (failed or not run)</h3>", _table(["Case", "Error"], rows)]
    if attrs.get("case"):
        parts.append(f"<details><summary>Case file (YAML) of {_e(runs[0].name)}</summary>"
                     f"<pre>{_e(_relative(attrs['case'], base))}</pre></details>")
    if sweep.get("sweep"):
        parts.append(f"<details><summary>Sweep file (YAML)</summary><pre>{_e(_relative(sweep['sweep'], base))}</pre></details>")
    refs = [r for r in str(attrs.get("references", "")).splitlines() if r.strip()]
    parts += ["<h2>2. Model and references</h2>",
              f"<p>{_e(attrs.get('analysis', ''))} analysis by seacable {_e(attrs.get('seacable_version', '?'))}.</p>",
              "<h3>Settings</h3>", _settings_html(attrs.get("settings", "")), "<h3>References of the model</h3>",
              "<ol>" + "".join(f"<li>{_e(r)}</li>" for r in refs) + "</ol>" if refs else "<p>none recorded</p>",
              ("<h3>References of the design methods</h3><ol>"
              "<li>DNV-OS-E301 Position mooring (October 2010): Ch.2 Sec.2 B (ULS and ALS partial safety factors), "
              "D (fatigue: T-N curves of Table D1 and the polyester rope curve; design fatigue factor 5).</li>"
              "<li>API RP 2SK Design and analysis of stationkeeping systems for floating structures: factors of "
              "safety of line tension.</li>"
              f"<li>Extremes: {_e(ds_.GUMBEL_REFERENCE)} (Gumbel fit over seeds); {_e(ds_.WEIBULL_REFERENCE)} "
              "(Weibull fit of peaks).</li>"
              "<li>Rainflow counting: ASTM E1049-85, section 5.4.4 (the <code>rainflow</code> package).</li></ol>")]
    method = ext["method"].iloc[0] if not ext.empty else ""
    parts += ["<h2>3. Extreme tensions</h2>",
              (f'<p class="method">Method: {_e(method)}. MPM: most probable maximum; q: the quantile of the storm '
              f"maximum of non-exceedance probability {_num(opts.quantile, sig=3)}. The dynamic part used by the "
              "checks is the design maximum less the mean.</p>"),
              _extremes_html(ext, opts.quantile), _figure(figures.get("series")), _figure(figures.get("maxima"))]
    parts += ["<h2>4. Code checks</h2>",
              ('<p class="method">Line tensions from the design maximum of the fairlead tension; DNV-OS-E301 ULS for '
              "intact load cases, ALS where a line failed or was removed (the failed line itself is not checked); "
              "API RP 2SK dynamic analysis, intact or damaged; anchor uplift from the first element at the anchor, "
              "T<sub>anchor</sub> (z<sub>1</sub> &minus; z<sub>0</sub>)/|x<sub>1</sub> &minus; x<sub>0</sub>|, the "
              "largest upward pull over the seeds, less round-off (an upward pull up to "
              f"{checks_.UPLIFT_ROUND_OFF:g} of the anchor tension, the line within "
              f"{math.degrees(checks_.UPLIFT_ROUND_OFF):.2f}&deg; of flat, or of the line's submerged weight where "
              "that is larger, is none). Margin = capacity &minus; "
              "demand, in the check's unit; utilisation = demand / capacity, where the capacity is not zero.</p>"),
              _checks_html(chk), _figure(figures.get("utilisation")), _basis_html(chk)]
    if tables.get("combined") is not None and not tables["combined"].empty:
        parts += ["<h3>Low- and wave-frequency parts of the fairlead tension</h3>",
                  (f'<p class="method">Each record split by an ideal filter at {SPLIT_PERIOD:g} s (longer periods: LF), '
                  f"the seeds' mean of each part's standard deviation and zero up-crossing period T<sub>z</sub>, and "
                  f"the standards' combinations over the storm: {_e(API_COMBINATION)}; {_e(DNV_COMBINATION)}. "
                  "Beside the time-domain design maximum of section 3, which holds both parts as the run modelled them.</p>"),
                  _combined_html(tables["combined"])]
    parts += ["<h2>5. Fatigue</h2>",
              ('<p class="method">Miner\'s damage from the rainflow-counted fairlead tension ranges over the nominal '
              "cross-section (DNV-OS-E301 (2010) Ch.2 Sec.2 D, Table D1; a polyester rope: over its breaking load), "
              "the mean over a load case's seeds; the curve from the line type's material, else from a name that "
              "tells it without ambiguity (a note says which). "
              "&ldquo;If permanent&rdquo;: were the load case to last the whole year.</p>"),
              _fatigue_html(fat)]
    if not life.empty:
        parts += ["<h3>Fatigue life over the scatter diagram</h3>", _life_html(life)]
    else:
        parts.append('<p class="method">No scatter diagram given (<code>--scatter hs,tp,probability CSV</code>): no '
                     "fatigue life over the year.</p>")
    col = _columns(seeds, {c: (1e3, 4) for c in ("maximum", "mean", "std", "weibull_mpm", "weibull_quantile")})
    rows = [[_e(r["load_case"]), _e(r["case"]), "&ndash;" if pd.isna(r["seed"]) else str(int(r["seed"])),
             _e(r["line"]), _e(r["end"]), col["maximum"][k], col["mean"][k], col["std"][k], col["weibull_mpm"][k],
             col["weibull_quantile"][k]] for k, (_, r) in enumerate(seeds.iterrows())]
    q = f"q{round(opts.quantile * 100):d}"
    parts += _cable_section(tables.get("cable_checks"), figures.get("range_graphs") or [], tables.get("cable_fatigue"))
    parts += ["<h2>Appendix: every seed</h2>",
              f"<details><summary>Tensions of each run ({len(seeds)} rows)</summary>"
              + _table(["Load case", "Case", "Seed", "Line", "End", "Maximum [kN]", "Mean [kN]", "Std. dev. [kN]",
                        "Weibull MPM [kN]", f"Weibull {q} [kN]"], rows, cls="num seeds") + "</details>",
              (f"<footer>Generated by seacable {_e(__version__)} on {_e(now)}. The tables are also in CSV files beside "
              "this page, in SI units (N, m, s).</footer></main></body></html>")]
    return "\n".join(parts)


# ------------------------------------------------------------------------------------------------- the report

def make_report(source, output: str | Path, options: ReportOptions | None = None) -> list[Path]:
    """Write the design report of a result file, a sweep folder (or Datasets) and its CSV tables.

    Parameters
    ----------
    source
        What :func:`seacable.design.summary.read_results` reads; or one ``mooring_static`` or ``mooring_pushover``
        result (file or Dataset) of a line with curvature: its cable page
        (:func:`seacable.report_cable.make_static_report`); or a ``system_static`` result with curvature: the page
        of its cables (:func:`seacable.report_system_cable.make_system_static_report`).
    output
        The HTML file (``.html``); the CSV files go beside it, ``STEM_extremes.csv`` and so on.
    options
        The report's choices (:class:`ReportOptions`).

    Returns
    -------
    list of Path
        The files written, the HTML page first.

    Raises
    ------
    InputError
        Bad input: see :mod:`seacable.design.summary`; an output that is not ``.html`` or cannot be written.
    """
    from .results import check_output_file

    opts = options or ReportOptions()
    output = check_output_file(output, "-o", (".html", ".htm"))
    static = _static_cable(source)
    if static is not None:  # a static or pushover result of a cable: its own page (issue 40); a system's: its cables'
        label = str(source) if isinstance(source, (str, Path)) else "result Dataset (Python)"
        if static.attrs.get("analysis") == "system_static":
            return make_system_static_report(static, output, label)
        return make_static_report(static, output, label)
    if opts.scatter is not None and not isinstance(opts.scatter, pd.DataFrame):
        ds_.read_scatter(opts.scatter)  # checked before the results are read, whether or not a life is computed
    if opts.tn_curve is not None:
        ds_.resolve_tn_curve(opts.tn_curve)  # so is the curve: a misspelt name fails before minutes of fits
    if not (math.isfinite(opts.design_fatigue_factor) and opts.design_fatigue_factor >= 1.0):
        raise InputError(f"--design-fatigue-factor must be a number >= 1, got {opts.design_fatigue_factor}. Suggested "
                         "fix: 5 (DNV-OS-E301), or 3 / 10 (API RP 2SK, inspected / not inspected lines).")
    kept, cable = _MostLoaded(), _Cable()

    def visit(run, ds):
        kept(run, ds)
        cable(run, ds)

    runs, made = ds_.design_tables(source, storm_duration=opts.storm_duration, quantile=opts.quantile,
                                   consequence_class=opts.consequence_class, offset_limit=opts.offset_limit,
                                   allowed_uplift=opts.allowed_uplift, tn_curve=opts.tn_curve,
                                   nominal_diameter=opts.nominal_diameter, scatter=opts.scatter, visit=visit)
    seeds, ext, chk, fat = (made[k] for k in ("seeds", "extremes", "checks", "fatigue"))
    life = ds_.fatigue_life_table(fat, design_fatigue_factor=opts.design_fatigue_factor) if opts.scatter else \
        pd.DataFrame(columns=["line", "tn_curve", "load_cases", "damage_per_year", "life", "design_fatigue_factor",
                              "note"])
    tables = {"extremes": ext, "seeds": seeds, "checks": chk, "fatigue": fat, "fatigue_life": life,
              "components": made["components"], "combined": made["combined"]}
    figures = {"series": _figure_time_series(runs, seeds, kept), "maxima": _figure_maxima(seeds, ext),
               "utilisation": _figure_utilisation(chk)}
    graphs = cable.by_load_case()
    if cable.table() is not None:
        tables["cable_checks"] = cable.table()
        figures["range_graphs"] = [_figure_range_graphs(k, rg, lim) for k, (rg, lim) in list(graphs.items())[:6]]
    if cable.armour_table() is not None:
        tables["cable_fatigue"] = cable.armour_table()
    page = _html(source if isinstance(source, (str, Path)) else "result Datasets (Python)", runs, tables, figures,
                 opts, output.resolve().parent, kept.attrs)
    output.parent.mkdir(parents=True, exist_ok=True)
    written = [atomic_write(output, lambda tmp: tmp.write_text(page, encoding="utf-8"))]
    for key, table in tables.items():
        if key == "fatigue_life" and not opts.scatter:
            continue
        path = output.with_name(f"{output.stem}_{key}.csv")
        units = {"cable_checks": CABLE_CSV_UNITS, "cable_fatigue": ARMOUR_CSV_UNITS}.get(key)
        written.append(atomic_write(path, lambda tmp, t=table, u=units: _with_units(t, u).to_csv(tmp, index=False)))
    if graphs:
        path = output.with_name(f"{output.stem}_range_graphs.nc")
        merged = _range_graphs_file(graphs)
        written.append(atomic_write(path, lambda tmp: merged.to_netcdf(tmp, engine="netcdf4")))
    return written




def _static_cable(source):
    """The result of ``source`` when it is one ``mooring_static`` or ``mooring_pushover`` result of a line with
    curvature (loaded), else None (what the time-domain report reads, or refuses)."""
    import xarray as xr

    if isinstance(source, xr.Dataset):
        ds = source
    elif isinstance(source, (str, Path)) and Path(source).is_file():
        try:
            from .results import open_netcdf

            with open_netcdf(source) as f:   # the file's CF form read back (names of lines as their coordinate)
                if f.attrs.get("analysis") not in STATIC_ANALYSES or "curvature" not in f.variables:
                    return None
                ds = f.load()
        except (OSError, ValueError, RuntimeError, KeyError, TypeError):
            return None  # the time-domain reader says what is wrong with it
    else:
        return None
    return ds if ds.attrs.get("analysis") in STATIC_ANALYSES and "curvature" in ds.variables else None

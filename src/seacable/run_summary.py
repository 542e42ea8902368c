"""What a run says: the few figures an engineer looks at first in a result, by analysis family (issue 41).

:func:`summary_rows` reduces a result Dataset of any analysis to a short list of figures (the top and anchor
tensions, touchdown and layback, offsets and the most loaded line with its utilisation, extremes with their
times, the peak curvature and the lowest clearance), each with its value in SI units, the unit it is shown in
and where or when it happens; :func:`summary` writes them as a few aligned lines (kN, m, deg, s), what
``seacable run`` prints after writing its result (``--quiet`` silences it). A time-domain result's extremes are
taken over its statistics window (``analysis.statistics_from``, :mod:`seacable._window`), and the summary says
from when. A sweep prints its table instead (``seacable sweep``).

The figures of each family are one list in :data:`FIGURES`: (label, variable, reduction), the reduction one of

- ``value``: the value of a scalar; of a variable with dimensions, its largest and where,
- ``max`` / ``min``: the largest / smallest over every dimension, and where and when,
- ``end``: the mean over the last tenth of the run (:func:`seacable.extremes.case_extremes`'s ``NAME_end``),
- ``range``: smallest to largest (a touchdown's travel, a sweep of ship speeds).
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from ._window import statistics_start, statistics_window
from .extremes import _end_mean

__all__ = ["FIGURES", "summary", "summary_rows"]

_TENSIONS = [("fairlead tension", "fairlead_tension", "max"), ("anchor tension", "anchor_tension", "max")]
_TOUCHDOWN = [("touchdown x", "touchdown_x", "value"), ("layback", "layback", "value"),
              ("grounded length", "grounded_length", "value"), ("grounded length", "seabed_contact_length", "value")]
_CABLE = [("peak curvature", "curvature", "max"), ("lowest seabed clearance", "seabed_clearance", "min")]
_BODIES = [("body offset", "body_offset", "max"), ("offset", "offset", "max")]

#: analysis -> the figures its summary shows: (label, result variable, reduction); a variable the result does not
#: hold is left out (``layback`` of a static line is computed from its nodes: :func:`_derived`).
FIGURES: dict[str, list[tuple[str, str, str]]] = {
    "static": [*_TENSIONS, *_TOUCHDOWN],
    "pushover": [("fairlead tension", "fairlead_tension", "max"), ("touchdown x", "touchdown_x", "range"),
                 ("grounded length", "grounded_length", "range")],
    "mooring_static": [*_TENSIONS, *_TOUCHDOWN, *_CABLE],
    "mooring_pushover": [("fairlead tension", "fairlead_tension", "max"), ("anchor tension", "anchor_tension", "max"),
                         ("touchdown x", "touchdown_x", "range"), ("grounded length", "seabed_contact_length", "range"),
                         *_CABLE],
    "mooring_dynamic": [("fairlead tension", "fairlead_tension", "max"), ("fairlead tension", "fairlead_tension", "min"),
                        ("anchor tension", "anchor_tension", "max"), ("touchdown s", "touchdown_s", "range"),
                        ("grounded length", "seabed_contact_length", "range"), ("snap load", "snap_tension", "max"),
                        *_CABLE],
    "system_static": [*_BODIES, *_TENSIONS, ("grounded length", "grounded_length", "min")],
    "system_offsets": [*_BODIES, *_TENSIONS],
    "system_dynamic": [*_BODIES, *_TENSIONS, ("fairlead tension", "fairlead_tension", "min"), *_CABLE],
    "towed_steady": [("top tension", "top_tension", "value"), ("top angle", "top_angle", "value"),
                     ("lower end depth", "lower_end_depth", "value"), ("layback", "layback", "value")],
    "towed_dynamic": [("top tension", "top_tension", "max"), ("top tension", "top_tension", "min"),
                      ("lower end depth", "lower_end_depth", "max"), ("lower end depth", "lower_end_depth", "min"),
                      ("layback", "layback", "end"), ("lowest seabed clearance", "seabed_clearance", "min")],
    "laying_theory": [("top tension", "top_tension", "range"), ("layback", "layback", "range"),
                      ("entry angle", "angle", "range"), ("suspended length", "suspended_length", "range")],
    "laying_dynamic": [("top tension", "top_tension", "max"), ("top tension", "top_tension", "end"),
                       ("bottom tension", "bottom_tension", "max"), ("bottom tension", "bottom_tension", "end"),
                       ("layback", "layback", "end"), ("entry angle", "entry_angle", "end"),
                       ("touchdown x", "touchdown_x", "end")],
    "towline_dynamic": [("top tension", "top_tension", "max"), ("top tension", "top_tension", "min"),
                        ("barge tension", "barge_tension", "max"), ("barge tension", "barge_tension", "min"),
                        ("lowest seabed clearance", "seabed_clearance", "min")],
    "modal": [("lowest natural frequency", "frequency", "min")],
    "vertical_modes": [("lowest natural frequency", "frequency", "min")],
}

#: SI unit -> (the unit shown, the factor to it)
_SHOWN = {"N": ("kN", 1e-3), "rad": ("deg", 180.0 / math.pi), "degree": ("deg", 1.0), "1": ("", 1.0)}
_SIZE_DIMS = ("node", "element", "point", "segment")   # dimensions named by index (no coordinate of their own)


def _where(da: xr.DataArray, index: tuple) -> str:
    """Where (and when) the element ``index`` of ``da`` lies: its time, line, body, condition, node, ..."""
    parts = []
    for dim, i in zip(da.dims, index):
        if da.sizes[dim] < 2 and dim != "time":
            continue
        if dim == "time":
            parts.append(f"t = {float(da['time'].values[i]):.6g} s")
        elif "s" in da.coords and da["s"].dims == (dim,):    # a node by its arc length from end A
            parts.append(f"s = {_number(float(da['s'].values[i]), da['s'])}")
        elif dim in da.coords and dim not in _SIZE_DIMS:
            value = da[dim].values[i]
            value = value.decode() if isinstance(value, bytes) else value
            if isinstance(value, (float, np.floating, int, np.integer)):
                parts.append(f"{dim} {_number(float(value), da[dim])}")
            else:
                parts.append(f"{dim} {value}")
        else:
            parts.append(f"{dim} {i}")
    return ", ".join(parts)


def _reduce(da: xr.DataArray, how: str) -> tuple[float, str] | None:
    """The value [SI] and where of ``da`` reduced by ``how`` (None: all NaN, or nothing to reduce)."""
    values = np.asarray(da.values, float)
    if values.size == 0 or not np.isfinite(values).any():
        return None
    if how == "value" and values.ndim == 0:
        return float(values), ""
    if how == "end":
        return (_end_mean(da), "end of run") if "time" in da.dims and da.ndim == 1 else None
    if how == "range":
        return float(np.nanmin(values)), f"to {_number(float(np.nanmax(values)), da)}"
    pick = np.nanargmin if how == "min" else np.nanargmax
    index = np.unravel_index(pick(values), values.shape)
    return float(values[index]), _where(da, index)


def _number(value: float, da: xr.DataArray) -> str:
    shown, factor = _SHOWN.get(da.attrs.get("units", ""), (da.attrs.get("units", ""), 1.0))
    return f"{_fmt(value * factor)}{' ' + shown if shown else ''}"


def _fmt(v: float) -> str:
    """Four significant digits in plain notation from 0.001 to 1e6, scientific outside."""
    if v == 0 or not math.isfinite(v):
        return f"{v:g}"
    if 1e-3 <= abs(v) < 1e6:
        return f"{v:.{max(0, 3 - math.floor(math.log10(abs(v))))}f}"
    return f"{v:.4g}"


def _derived(ds: xr.Dataset) -> xr.Dataset:
    """The figures a single static line's result holds only in its nodes: the layback, the fairlead's
    horizontal distance from the touchdown. [m]"""
    if ds.attrs.get("analysis") not in ("static", "mooring_static") or "layback" in ds or "touchdown_x" not in ds:
        return ds
    if ds["x"].ndim != 1 or ds["touchdown_x"].ndim != 0:   # a network of lines (a MoorDyn deck): no one layback
        return ds
    dim = "point" if "point" in ds["x"].dims else "node"
    dx = float(ds["x"].isel({dim: -1})) - float(ds["touchdown_x"])
    dy = float(ds["y"].isel({dim: -1})) - float(ds["touchdown_y"]) if "y" in ds and "touchdown_y" in ds else 0.0
    layback = xr.DataArray(math.hypot(dx, dy), attrs={"units": "m", "long_name": "horizontal distance from the "
                                                                                 "touchdown to the fairlead"})
    return ds.assign(layback=layback)


def _utilisation(ds: xr.Dataset, tension: xr.DataArray, where: str) -> tuple[float, float] | None:
    """The breaking load [N] of the most loaded line (the one named in ``where``) and the utilisation [-] of
    its largest fairlead tension, where the case gives a breaking load."""
    try:
        from .design.summary import line_info, line_names

        info = line_info(ds)
        names = line_names(ds)
    except Exception:  # noqa: BLE001 - a result whose lines or case cannot be read: no utilisation shown
        return None
    line = next((n for n in names if f"line {n}" in where.split(", ")), names[0] if len(names) == 1 else None)
    mbl = info.get(line).breaking_load if line in info else None
    if not mbl:
        return None
    return mbl, float(tension) / mbl


def summary_rows(ds: xr.Dataset) -> list[dict]:
    """The figures of a result an engineer looks at first.

    Parameters
    ----------
    ds
        A result of :func:`seacable.run` (any analysis) or a result file read back.

    Returns
    -------
    list of dict
        One per figure: ``figure`` (its label), ``variable`` (the result's variable), ``reduction`` (``value``,
        ``max``, ``min``, ``end`` or ``range``), ``value`` in SI units (``units``, the variable's), ``shown`` (the
        value in the unit shown, ``shown_units``: kN, deg, m, s) and ``where`` (when and where it happens, or the
        top of a range). A time-domain result's extremes are over its statistics window
        (``analysis.statistics_from``); ``utilisation`` rows divide the largest fairlead tension by the most
        loaded line's breaking load, where the case gives it.
    """
    analysis = ds.attrs.get("analysis")
    full = _derived(ds)
    window = statistics_window(full)
    rows = []
    for label, name, how in FIGURES.get(analysis, []):
        if name not in full.variables or any(r["variable"] == name and r["reduction"] == how for r in rows):
            continue
        if (name == "grounded_length" and any(r["figure"] == label for r in rows)) or (
                name == "offset" and "body_offset" in full.variables):   # one of each figure
            continue
        da = (full if how == "end" else window)[name]
        how = "value" if da.ndim == 0 else how    # a scalar is its own extreme
        got = _reduce(da, how)
        if got is None:
            continue
        value, where = got
        units = da.attrs.get("units", "1")
        shown_units, factor = _SHOWN.get(units, (units, 1.0))
        kind = "" if how == "value" or label.startswith(("lowest", "peak")) else how
        rows.append({"figure": f"{label} {kind}".strip() if da.ndim else label, "variable": name, "reduction": how,
                     "value": value, "units": units, "shown": value * factor, "shown_units": shown_units,
                     "where": where})
        if name == "fairlead_tension" and how == "max" and analysis in _LINES:
            got = _utilisation(ds, value, where)
            if got is not None:
                mbl, u = got
                rows.append({"figure": "utilisation", "variable": "fairlead_tension / breaking_load",
                             "reduction": how, "value": u, "units": "1", "shown": u, "shown_units": "",
                             "where": f"breaking load {_fmt(mbl * 1e-3)} kN"})
    return rows


_LINES = ("mooring_static", "mooring_pushover", "mooring_dynamic", "system_static", "system_offsets",
          "system_dynamic")


def summary(ds: xr.Dataset) -> str:
    """A few aligned lines of the figures of :func:`summary_rows`, with their units, what ``seacable run``
    prints after writing a result; the first line names the analysis and, for a time-domain result, the
    statistics window ("statistics from t = 20 s")."""
    head = f"{ds.attrs.get('analysis', 'result')} '{ds.attrs.get('case_name', ds.attrs.get('title', ''))}'"
    if "time" in ds.dims and ds["time"].size:
        t = np.asarray(ds["time"].values, float)
        head += f", t = {t[0]:.6g} to {t[-1]:.6g} s, statistics from t = {statistics_start(ds):.6g} s"
    rows = summary_rows(ds)
    if not rows:
        return head
    width = max(len(r["figure"]) for r in rows)
    values = [_fmt(r["shown"]) for r in rows]
    vwidth = max(len(v) for v in values)
    uwidth = max(len(r["shown_units"]) for r in rows)
    lines = [head]
    for r, v in zip(rows, values):
        lines.append(f"  {r['figure']:<{width}}  {v:>{vwidth}} {r['shown_units']:<{uwidth}}  {r['where']}".rstrip())
    return "\n".join(lines)

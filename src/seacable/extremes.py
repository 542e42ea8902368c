"""Design figures of one result: tension extremes, snap loads and each model's own figures.

:func:`case_extremes` reduces a result Dataset of any analysis to scalars, the row a sweep's
summary keeps per case: maximum and minimum top tension, maximum and minimum tension anywhere
(a minimum of 0 or less is slack), snap loads, every scalar of the result (fairlead tension,
touchdown, layback, ...) and the model's own figures (laying: touchdown, bottom tension, layback,
entry angle; towline: barge tension; mooring: anchor tension). Values at the end of a
time-domain run are means over its last tenth, the steady state of a case that settles; the extremes of a
time-domain run leave out its start-up transient (``analysis.statistics_from``, :mod:`seacable._window`).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from ._jit import njit
from ._window import statistics_start, statistics_window
from .results import var

__all__ = ["KEY_FIGURES", "TOP_TENSION", "case_extremes", "snap_loads", "snap_rows"]

#: The variable holding the tension at the top end (fairlead, ship, tow point, tug), by analysis.
TOP_TENSION = {
    "static": "fairlead_tension",
    "pushover": "fairlead_tension",
    "towed_steady": "top_tension",
    "towed_dynamic": "top_tension",
    "laying_theory": "top_tension",
    "laying_dynamic": "top_tension",
    "mooring_static": "fairlead_tension",
    "mooring_pushover": "fairlead_tension",
    "mooring_dynamic": "fairlead_tension",
    "towline_dynamic": "top_tension",
}

#: Time series of each analysis reduced to their extremes (max and min) and to their end value.
_SERIES = {
    "laying_dynamic": {"extremes": ("bottom_tension",),
                       "end": ("entry_angle", "top_tension", "touchdown_x", "layback", "bottom_tension",
                               "suspended_length", "slack")},
    "towed_dynamic": {"extremes": ("lower_end_depth", "layback", "seabed_clearance"),
                      "end": ("lower_end_depth", "layback")},
    "towline_dynamic": {"extremes": ("barge_tension", "seabed_clearance"), "end": ("barge_tension", "barge_speed")},
    "mooring_dynamic": {"extremes": ("anchor_tension", "seabed_contact_length", "touchdown_s"), "end": ()},
}

#: The model's own figures a sweep shows first (in its printed table and its plot), by analysis.
KEY_FIGURES = {
    "laying_dynamic": ("entry_angle_end", "layback_end", "bottom_tension_max"),
    "towed_dynamic": ("lower_end_depth_max", "lower_end_depth_min"),
    "towline_dynamic": ("barge_tension_max", "barge_tension_min"),
    "mooring_dynamic": ("anchor_tension_max", "snap_load_max"),
    "static": ("touchdown_x", "grounded_length"),
    "towed_steady": ("layback", "lower_end_depth"),
    "modal": ("frequency_min",),
}


def snap_loads(time, tension, threshold: float = 0.0, window: float = 2.0):
    """Snap events: an element that was slack (tension <= ``threshold``) pulls taut again.

    Parameters
    ----------
    time
        Output times, (n_time,). [s]
    tension
        Element tensions, (n_time, n_element); NaN where an element does not exist. [N]
    threshold
        Tension at or below which an element counts as slack. [N]
    window
        Time after the element pulls taut within which its peak is taken. [s]

    Returns
    -------
    time, element, peak : numpy.ndarray
        Time of each peak, its element and the peak tension (the largest within ``window``
        after each slack-to-taut transition). [s], [-], [N]
    """
    time = np.asarray(time)
    tension = np.asarray(tension)
    _, j, e = snap_rows(time, tension, threshold, window)
    return np.asarray(time[j], float), e, np.asarray(tension[j, e], float)


def snap_rows(time, tension, threshold: float = 0.0, window: float = 2.0):
    """The rows of the snap events of :func:`snap_loads`: for each event (in the order of the rows where the
    elements pull taut, then of the elements) that row, the row of its peak and its element. [-]"""
    slack = tension <= threshold
    taut = tension > threshold   # NaN (no element) is neither
    rises = np.argwhere(slack[:-1] & taut[1:])
    k, e = rises[:, 0] + 1, rises[:, 1]
    stop = np.searchsorted(time, time[k] + window, side="right")
    j = _window_peaks(np.asarray(tension, float), k, stop, e)
    return k, j, e.astype(int)


@njit(cache=True)
def _window_peaks(tension, start, stop, column):
    """The row of the largest value of ``tension[start[i]:stop[i], column[i]]`` for each i, NaN skipped (the
    first of equal values, as :func:`numpy.nanargmax`; ``tension[start[i], column[i]]`` is a number)."""
    out = np.empty(start.size, np.int64)
    for i in range(start.size):
        c = column[i]
        best = start[i]
        for j in range(start[i] + 1, stop[i]):
            if tension[j, c] > tension[best, c]:
                best = j
        out[i] = best
    return out


def _end_mean(da: xr.DataArray) -> float:
    """Mean over the last tenth of the output times (at least the last one)."""
    n = max(1, da.sizes["time"] // 10)
    return float(da.isel(time=slice(-n, None)).mean())


def _scalar(value: float, da: xr.DataArray, what: str) -> xr.Variable:
    return var((), float(value), da.attrs.get("units", "1"), f"{what} {da.attrs.get('long_name', da.name)}")


def case_extremes(ds: xr.Dataset) -> dict[str, xr.Variable]:
    """The design figures of one result, each a scalar variable with units and long name.

    Parameters
    ----------
    ds
        A result of :func:`seacable.run` (any analysis).

    Returns
    -------
    dict of str to xarray.Variable
        ``top_tension_max``, ``top_tension_min``, ``tension_max`` and ``tension_min`` (tension
        anywhere, element tensions where the model has them), and for time-domain results
        ``snap_count`` and ``snap_load_max`` (the largest peak within 2 s after an element pulled
        taut from slack; 0 when none did), then every scalar variable of the result and the
        model's own figures: ``NAME_max`` and ``NAME_min`` of its key time series and ``NAME_end``,
        their mean over the last tenth of the run (``layback_end``: the water entry or tow point to
        the touchdown or lower end; ``seabed_clearance_min``: the deepest a line went through a
        seabed its model does not contact). The extremes of a time-domain result are taken from
        ``analysis.statistics_from`` on (:func:`seacable._window.statistics_window`; the output times
        before it, a start-up transient, left out), and ``statistics_from`` is one of the figures.
    """
    analysis = ds.attrs.get("analysis")
    full, ds = ds, statistics_window(ds)  # the start-up transient left out (analysis.statistics_from)
    out: dict[str, xr.Variable] = {}
    top = TOP_TENSION.get(analysis)
    if top in ds:
        out["top_tension_max"] = _scalar(ds[top].max(), ds[top], "maximum of")
        out["top_tension_min"] = _scalar(ds[top].min(), ds[top], "minimum of")
    field = "segment_tension" if "segment_tension" in ds else "tension"
    if field in ds and ds[field].size:
        tension = ds[field]
        ends = [float(ds[top].max()), float(ds[top].min())] if top in ds else []
        out["tension_max"] = var((), max([float(tension.max()), *ends]), "N", "maximum tension anywhere")
        out["tension_min"] = var((), min([float(tension.min()), *ends]), "N",
                                 "minimum tension anywhere (0 or less: slack)")
        if "time" in tension.dims and tension.ndim == 2:
            values = tension.transpose("time", ...).values
            _, _, peaks = snap_loads(ds["time"].values, values)
            out["snap_count"] = var((), peaks.size, "1", "snap events (elements pulling taut from slack)")
            out["snap_load_max"] = var((), float(peaks.max()) if peaks.size else 0.0, "N",
                                       "largest snap load (0: no snap event)")
    for name, da in ds.data_vars.items():
        if da.ndim == 0 and da.dtype.kind in "fiu" and name not in out:
            out[name] = var((), da.values, da.attrs.get("units", "1"), da.attrs.get("long_name", name))
    series = _SERIES.get(analysis, {})
    for name in series.get("extremes", ()):
        if name in ds:
            out[f"{name}_max"] = _scalar(ds[name].max(), ds[name], "maximum of")
            out[f"{name}_min"] = _scalar(ds[name].min(), ds[name], "minimum of")
    for name in series.get("end", ()):   # the last tenth of the whole run, whatever the window
        if name in ds:
            out[f"{name}_end"] = _scalar(_end_mean(full[name]), ds[name], "end of run:")
    if "time" in ds.dims:
        out["statistics_from"] = var((), statistics_start(ds), "s", "start of the statistics window")
    if analysis == "modal" and "frequency" in ds:
        out["frequency_min"] = _scalar(ds["frequency"].min(), ds["frequency"], "lowest")
    return out

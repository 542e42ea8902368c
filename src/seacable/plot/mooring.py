"""Standard figures of the mooring analyses (``mooring_static``, ``mooring_pushover``, ``mooring_dynamic``).

The figure functions follow :data:`seacable.plot.FIGURES`: ``function(ds, pyplot)`` returns a
dict ``{figure name: Figure}``; :data:`MOORING_FIGURES` maps the three analysis names to them.
The public ``plot_mooring_*`` functions take a Dataset only and return the figures as a list.

The results are those of :mod:`seacable.mooring.run` (one line: dimensions ``node``,
``element`` and ``time`` or ``offset``, coordinate ``s``) and of a MoorDyn file with several
lines (a leading ``line`` dimension, rows NaN-padded to the longest line, no ``s``). Every
figure draws one curve per line. The shapes are drawn in the vertical plane: against ``x``
when every line lies in the x-z plane, else against the horizontal distance from the line's
end A (node 0). The seabed is drawn at ``z = -depth + x tan(slope)`` when the depth is known
(from the case stamped in the result), the sea surface at ``z = 0``.

matplotlib is imported by the caller (:func:`seacable.plot.plot_result`) or on the first call
of a ``plot_mooring_*`` function, never at import.
"""

from __future__ import annotations

import math

import numpy as np

from ._core import _label, _snapshot_times, figures_of

__all__ = ["MOORING_FIGURES", "plot_mooring_dynamic", "plot_mooring_pushover", "plot_mooring_static"]

_N_SNAPSHOTS = 8  # shape snapshots of a time series (about)
_N_OFFSETS = 5  # shapes drawn along a force-excursion curve (at most)
_LINESTYLES = ("-", "--", ":", "-.")


# ----------------------------------------------------------------------------- helpers

def _lines(ds):
    """(name, Dataset of one line) per line: one entry, name None, without a ``line`` dimension."""
    if "line" not in ds.dims:
        return [(None, ds)]
    names = ds["line"].values if "line" in ds.coords else np.arange(ds.sizes["line"])
    return [(str(name), ds.isel(line=i)) for i, name in enumerate(names)]


def _tension_scale(*arrays) -> tuple[float, str]:
    """(divisor, unit): kN when the largest tension is 10 kN or more, else N."""
    values = np.concatenate([np.abs(np.asarray(a, dtype=float)).ravel() for a in arrays] + [np.zeros(1)])
    return (1e3, "kN") if np.nanmax(values) >= 1e4 else (1.0, "N")


def _in_xz_plane(ds) -> bool:
    """True when every node of every line has y = 0 (to 1e-9 of the line's extent)."""
    if "y" not in ds:
        return True
    y = np.asarray(ds.y.values, dtype=float)
    extent = np.nanmax(np.abs(np.r_[np.asarray(ds.x.values, float).ravel(), np.asarray(ds.z.values, float).ravel(),
                                    1.0]))
    return bool(np.all(np.abs(y[np.isfinite(y)]) <= 1e-9 * extent))


def _horizontal(line, planar: bool):
    """The abscissa of the shapes: x, or the horizontal distance from end A (node 0). [m]"""
    x = np.asarray(line.x.values, dtype=float)
    if planar:
        return x
    y = np.asarray(line.y.values, dtype=float)
    return np.hypot(x - x[..., :1], y - y[..., :1])


def _horizontal_label(ds, planar: bool) -> str:
    return _label(ds.x) if planar else "horizontal distance from end A [m]"


def _arc_length(line):
    """(arc length per node, axis label): ``s`` when stored, else the stretched length from end A."""
    if "s" in line.coords or "s" in line:
        return np.asarray(line.s.values, dtype=float), _label(line.s)
    pts = np.stack([np.asarray(line[c].values, dtype=float) for c in ("x", "y", "z")], axis=-1)
    seg = np.linalg.norm(np.diff(pts, axis=-2), axis=-1)
    s = np.concatenate([np.zeros(seg.shape[:-1] + (1,)), np.cumsum(seg, axis=-1)], axis=-1)
    return s, "arc length from end A, stretched [m]"


def _finite(a, b):
    """The points of two NaN-padded rows where both are defined."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    keep = np.isfinite(a) & np.isfinite(b)
    return a[keep], b[keep]


def _seabed(ds) -> tuple[float, float] | None:
    """(depth [m], slope [rad]) of the case stamped in the result, or None when not known."""
    for key in ("depth", "water_depth"):
        if key in ds.attrs:
            try:
                return float(ds.attrs[key]), float(ds.attrs.get("seabed_slope", 0.0))
            except (TypeError, ValueError):
                pass
    text = ds.attrs.get("case")
    if not text:
        return None
    import yaml

    from .._model import load_yaml

    try:
        env = (load_yaml(text) or {}).get("environment") or {}
        depth = env.get("depth")
        if depth is None:
            return None
        slope = (env.get("seabed") or {}).get("slope") or 0.0
        return float(depth), float(slope)
    except (yaml.YAMLError, AttributeError, TypeError, ValueError):
        return None  # a result written by another tool: no seabed drawn rather than no figure


def _scene(ax, ds, planar: bool, xs) -> None:
    """Seabed (when known) and sea surface under the shapes, whose abscissae are ``xs``."""
    xs = np.asarray(xs, dtype=float)
    xs = xs[np.isfinite(xs)]
    bed = _seabed(ds)
    if bed is not None and xs.size:
        depth, slope = bed
        if not planar:
            slope = 0.0  # distances from end A: a sloping bed is not a line in this plane
        pad = 0.05 * (xs.max() - xs.min()) or 1.0
        bx = np.array([xs.min() - pad, xs.max() + pad])
        ax.plot(bx, -depth + bx * math.tan(slope), color="sienna", lw=1.2, label="seabed", zorder=1)
    ax.axhline(0.0, color="steelblue", lw=0.8, ls="--", label="sea surface", zorder=1)


def _note(ds, time) -> str:
    interrupted = bool(int(ds.attrs.get("interrupted", 0) or 0))
    unit = ds.time.attrs.get("units", "s") if "time" in ds.coords else "s"
    return f" (interrupted at t = {time[-1]:g} {unit})" if interrupted and time.size else ""


def _style(k: int) -> str:
    return _LINESTYLES[k % len(_LINESTYLES)]


def _line_key(ax, lines) -> None:
    """Legend entries naming the line styles when there are several lines."""
    if len(lines) > 1:
        for k, (name, _) in enumerate(lines):
            ax.plot([], [], _style(k), color="k", label=name)


# ----------------------------------------------------------------------------- static

def _mooring_static(ds, plt):
    lines = _lines(ds)
    planar = _in_xz_plane(ds)
    scale, unit = _tension_scale(ds.tension.values)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    xs = []
    for k, (name, line) in enumerate(lines):
        h, z = _finite(_horizontal(line, planar), line.z.values)
        xs.append(h)
        ax1.plot(h, z, "-", color=f"C{k}", lw=1.5, label=name)
        if h.size:
            ax1.plot(h[-1], z[-1], "^", color=f"C{k}", ms=6)  # end B: the fairlead
        s, s_label = _arc_length(line)
        s, t = _finite(s, line.tension.values)
        ax2.plot(s, t / scale, "-", color=f"C{k}", label=name)
    _scene(ax1, ds, planar, np.concatenate(xs))
    ax1.set(xlabel=_horizontal_label(ds, planar), ylabel=_label(ds.z), title="Static shape")
    ax1.legend(fontsize=8)
    title = "Tension along the line"
    if len(lines) == 1:
        title = (f"Fairlead {float(ds.fairlead_tension) / scale:.1f} {unit}, "
                 f"anchor {float(ds.anchor_tension) / scale:.1f} {unit}")
    else:
        ax2.legend(fontsize=8)
    ax2.set(xlabel=s_label, ylabel=f"effective tension [{unit}]", title=title)
    return {"shape": fig, **_range_graphs(ds)}


def _range_graphs(ds) -> dict:
    """The range graphs of a cable's result (a line with curvature, :func:`seacable.design.cable.range_graphs`), with
    its limits where the case gives them: {} for a line without curvature or a result of several lines."""
    from ..design.cable import cable_limits, has_curvature, plot_range_graphs, range_graphs

    if not has_curvature(ds) or "line" in ds.dims:
        return {}
    rg = range_graphs(ds)
    try:
        limits = cable_limits(ds)
    except (KeyError, ValueError, TypeError):  # a result without its case (a deck's): the ranges alone
        limits = None
    return {"range_graphs": plot_range_graphs(rg, limits)}


# ----------------------------------------------------------------------------- pushover

def _offset_indices(n: int, count: int = _N_OFFSETS) -> np.ndarray:
    """About ``count`` indices spread evenly over ``n`` offsets, the first and the last included."""
    return np.unique(np.round(np.linspace(0, n - 1, min(n, count))).astype(int))


def _h_fairlead(line):
    if "H_fairlead" in line:
        return np.asarray(line.H_fairlead.values, dtype=float)
    return np.hypot(line.fairlead_force_x.values, line.fairlead_force_y.values)


def _mooring_pushover(ds, plt):
    from matplotlib import colormaps

    lines = _lines(ds)
    planar = _in_xz_plane(ds)
    offset = np.asarray(ds.offset.values, dtype=float)
    scale, unit = _tension_scale(ds.fairlead_tension.values)
    figs = {}

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    mark = "o-" if offset.size < 30 else "-"
    for k, (name, line) in enumerate(lines):
        tag = f"{name}: " if name else ""
        ax1.plot(offset, _h_fairlead(line) / scale, mark, color=f"C{k}", ms=3, label=f"{tag}horizontal")
        ax1.plot(offset, line.fairlead_tension.values / scale, mark.replace("-", "--"), color=f"C{k}", ms=3,
                 label=f"{tag}total")
        ax2.plot(offset, line.seabed_contact_length.values, mark, color=f"C{k}", ms=3, label=name)
    ax1.set(xlabel=_label(ds.offset), ylabel=f"fairlead tension [{unit}]", title="Force-excursion")
    ax1.legend(fontsize=8)
    ax2.set(xlabel=_label(ds.offset), ylabel=_label(ds.seabed_contact_length), title="Line on the seabed")
    if len(lines) > 1:
        ax2.legend(fontsize=8)
    figs["pushover"] = fig

    picks = _offset_indices(offset.size)
    colours = colormaps["viridis"](np.linspace(0.0, 0.9, picks.size))
    t_scale, t_unit = _tension_scale(ds.tension.values)
    off_unit = ds.offset.attrs.get("units", "m")
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    xs = []
    for k, (name, line) in enumerate(lines):
        s_all, s_label = _arc_length(line)
        h_all = _horizontal(line, planar)
        for i, c in zip(picks, colours):
            label = f"offset {offset[i]:g} {off_unit}" if k == 0 else None
            h, z = _finite(h_all[i], line.z.values[i])
            xs.append(h)
            ax1.plot(h, z, _style(k), color=c, lw=1.3, label=label)
            s = s_all[i] if s_all.ndim == 2 else s_all
            s, t = _finite(s, line.tension.values[i])
            ax2.plot(s, t / t_scale, _style(k), color=c, label=label)
    _scene(ax1, ds, planar, np.concatenate(xs))
    _line_key(ax1, lines)
    ax1.set(xlabel=_horizontal_label(ds, planar), ylabel=_label(ds.z), title="Shapes along the pushover")
    ax1.legend(fontsize=7)
    ax2.set(xlabel=s_label, ylabel=f"effective tension [{t_unit}]", title="Tension along the line")
    ax2.legend(fontsize=7)
    figs["pushover_shapes"] = fig
    figs.update(_range_graphs(ds))
    return figs


# ----------------------------------------------------------------------------- dynamic

def _snaps(ds):
    """(time, tension) of the snap loads, all lines together (NaN padding dropped). [s], [N]"""
    if "snap_time" not in ds or ds.snap_time.size == 0:
        return np.empty(0), np.empty(0)
    return _finite(ds.snap_time.values.ravel(), ds.snap_tension.values.ravel())


def _mooring_dynamic(ds, plt):
    from matplotlib import colormaps

    lines = _lines(ds)
    time = np.asarray(ds.time.values, dtype=float)
    unit_t = ds.time.attrs.get("units", "s")
    note = _note(ds, time)
    step, snaps = _snapshot_times(time, _N_SNAPSHOTS)
    # the shapes drawn: the snapshots' rows only (a long result read from its file is not read whole)
    shots = ds.isel(time=np.searchsorted(time, snaps))  # the snapshots are output times
    planar = _in_xz_plane(shots)
    colours = colormaps["viridis"](np.linspace(0.0, 0.9, snaps.size))
    every = (f"every {step:g} {unit_t}" if step else
             f"at t = {snaps[0]:g} {unit_t}" if snaps.size == 1 else f"at {snaps.size} times")
    figs = {}

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.5))
    t_scale, t_unit = _tension_scale(shots.tension.values)
    xs = []
    for k, (name, line) in enumerate(_lines(shots)):
        h_all = _horizontal(line, planar)
        s_all, s_label = _arc_length(line)
        for i, (t, c) in enumerate(zip(snaps, colours)):
            label = f"t = {t:g} {unit_t}" if k == 0 else None
            h, z = _finite(h_all[i], line.z.values[i])
            xs.append(h)
            ax1.plot(h, z, _style(k), color=c, lw=1.3, label=label)
            s = s_all[i] if s_all.ndim == 2 else s_all
            s, tt = _finite(s, line.tension.values[i])
            ax2.plot(s, tt / t_scale, _style(k), color=c, label=label)
    _scene(ax1, ds, planar, np.concatenate(xs))
    _line_key(ax1, lines)
    ax1.set(xlabel=_horizontal_label(ds, planar), ylabel=_label(ds.z), title=f"Line shape {every}" + note)
    ax1.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax2.set(xlabel=s_label, ylabel=f"effective tension [{t_unit}]", title="Tension along the line" + note)
    figs["shape"] = fig

    has_slack = "slack_elements" in ds
    fig, axes = plt.subplots(3 if has_slack else 2, 1, figsize=(8, 8 if has_slack else 6), sharex=True)
    ax1, ax2 = axes[0], axes[1]
    mark = "o-" if time.size == 1 else "-"
    snap_t, snap_p = _snaps(ds)
    scale, unit = _tension_scale(ds.fairlead_tension.values, ds.anchor_tension.values, snap_p)
    for k, (name, line) in enumerate(lines):
        tag = f"{name}: " if name else ""
        ax1.plot(time, line.fairlead_tension.values / scale, mark, color=f"C{k}", label=f"{tag}fairlead")
        ax1.plot(time, line.anchor_tension.values / scale, mark.replace("-", "--"), color=f"C{k}",
                 label=f"{tag}anchor")
        ax2.plot(time, line.seabed_contact_length.values, mark, color=f"C{k}", label=name)
        if has_slack:
            axes[2].plot(time, line.slack_elements.values, mark, color=f"C{k}", label=name)
    if snap_t.size:
        ax1.plot(snap_t, snap_p / scale, "x", color="red", ms=7, mew=1.5,
                 label=f"snap loads ({snap_t.size}, any element)")
    ax1.set(ylabel=f"tension [{unit}]", title="Line-end tensions" + note)
    ax1.legend(fontsize=8)
    ax2.set(ylabel=_label(ds.seabed_contact_length))
    if len(lines) > 1:
        ax2.legend(fontsize=8)
    if has_slack:
        axes[2].set(ylabel="slack elements")
    axes[-1].set_xlabel(_label(ds.time))
    figs["tension"] = fig
    figs.update(_range_graphs(ds))
    return figs


#: analysis type -> function(ds, pyplot) -> {figure name: Figure}; merged into seacable.plot.FIGURES
MOORING_FIGURES = {
    "mooring_static": _mooring_static,
    "mooring_pushover": _mooring_pushover,
    "mooring_dynamic": _mooring_dynamic,
}


def _figures(ds, analysis: str) -> list:
    return figures_of(ds, analysis, MOORING_FIGURES)


def plot_mooring_static(ds) -> list:
    """Figures of a ``mooring_static`` result: the line shape over the seabed and the tension along it.

    Parameters
    ----------
    ds : xarray.Dataset
        A ``mooring_static`` result (from :func:`seacable.run` or a MoorDyn file), with or
        without a ``line`` dimension.

    Returns
    -------
    list of matplotlib.figure.Figure
        One figure: shape (x or horizontal distance, z) with the seabed and the sea surface,
        and the effective tension against the arc length (kN above 10 kN), one curve per line; for a cable (a
        line with curvature) its tension, curvature, bend moment, declination and seabed clearance along the arc
        length (:func:`seacable.design.cable.plot_range_graphs` of its one state).

    Raises
    ------
    InputError
        The result is not a ``mooring_static`` one.
    """
    return _figures(ds, "mooring_static")


def plot_mooring_pushover(ds) -> list:
    """Figures of a ``mooring_pushover`` result: the force-excursion curve and shapes at a few offsets.

    Parameters
    ----------
    ds : xarray.Dataset
        A ``mooring_pushover`` result.

    Returns
    -------
    list of matplotlib.figure.Figure
        The force-excursion curve (horizontal and total fairlead tension against the offset,
        kN above 10 kN) with the length of line on the seabed; then the shapes and the
        tension along the line at up to five offsets, first and last included; for a cable (a line with
        curvature) its range graphs over the offsets (:func:`seacable.design.cable.plot_range_graphs`).

    Raises
    ------
    InputError
        The result is not a ``mooring_pushover`` one.
    """
    return _figures(ds, "mooring_pushover")


def plot_mooring_dynamic(ds) -> list:
    """Figures of a ``mooring_dynamic`` result: shape snapshots and tension time series.

    Parameters
    ----------
    ds : xarray.Dataset
        A ``mooring_dynamic`` result, with or without a ``line`` dimension.

    Returns
    -------
    list of matplotlib.figure.Figure
        The shapes and the tension along the line at about eight output times (every N s,
        N round, coloured by time); then the fairlead and anchor tensions with the snap loads
        marked, the length of line on the seabed and, when stored, the number of slack
        elements against time; for a cable (a line with curvature) its range graphs along the arc length
        (:func:`seacable.design.cable.plot_range_graphs`).

    Raises
    ------
    InputError
        The result is not a ``mooring_dynamic`` one.
    """
    return _figures(ds, "mooring_dynamic")

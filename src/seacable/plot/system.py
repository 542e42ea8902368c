"""Standard figures of the mooring-system analyses (``system_static``, ``system_offsets``, ``system_dynamic``).

The figure functions follow :data:`seacable.plot.FIGURES`: ``function(ds, pyplot)`` returns a
dict ``{figure name: Figure}``; :data:`SYSTEM_FIGURES` maps the analysis names to them. The public
``plot_system_*`` functions take a Dataset only and return the figures as a list.

The results are those of :mod:`seacable.system.run`: a ``condition`` dimension (intact, damaged),
``line``, ``body`` and ``point`` dimensions holding the names, the line profiles ``x``, ``y``,
``z`` (``condition, line, node``) of ``system_static`` and the sweep (``applied_load``, ``heading``) of
``system_offsets``. The intact condition is drawn solid, the damaged one dashed; a line removed in
the damaged condition (NaN there) is not drawn in it.

matplotlib is imported by the caller (:func:`seacable.plot.plot_result`) or on the first call of a
``plot_system_*`` function, never at import.
"""

from __future__ import annotations

import numpy as np

from ._core import _interrupted_note, _label, _snapshot_times, figures_of

__all__ = ["SYSTEM_FIGURES", "plot_system_dynamic", "plot_system_offsets", "plot_system_static"]

_STYLE = {"intact": "-", "damaged": "--"}


def _names(ds, dim: str) -> list[str]:
    if dim in ds.coords:
        return [str(v) for v in ds[dim].values]
    return [f"{dim} {i}" for i in range(ds.sizes.get(dim, 0))]


def _conditions(ds) -> list[tuple[int, str]]:
    return list(enumerate(_names(ds, "condition")))


def _style(condition: str) -> str:
    return _STYLE.get(condition, ":")


def _scale(*arrays) -> tuple[float, str]:
    """(divisor, unit): kN when the largest force is 10 kN or more, else N."""
    values = np.concatenate([np.abs(np.asarray(a, float)).ravel() for a in arrays] + [np.zeros(1)])
    return (1e3, "kN") if np.nanmax(values) >= 1e4 else (1.0, "N")


def _depth(ds) -> float | None:
    try:
        return float(ds.attrs["depth"])
    except (KeyError, TypeError, ValueError):
        return None


def _anchors(ds) -> np.ndarray:
    """Indices of the fixed points (anchors), when the result says which they are."""
    if "point_kind" not in ds.variables:
        return np.arange(0)
    return np.flatnonzero(np.asarray(ds.point_kind.values).astype(str) == "fixed")


def _system_views(ds, plt):
    """Plan view and elevation of the whole system, every condition."""
    fig, (plan, side) = plt.subplots(1, 2, figsize=(13, 5.2), gridspec_kw={"width_ratios": [1, 1.3]})
    lines = _names(ds, "line")
    anchors = _anchors(ds)
    for c, condition in _conditions(ds):
        ls = _style(condition)
        for k, name in enumerate(lines):
            x, y, z = (np.asarray(ds[v].values[c, k], float) for v in ("x", "y", "z"))
            keep = np.isfinite(x) & np.isfinite(y) & np.isfinite(z)
            if not keep.any():
                continue
            label = name if c == 0 else None
            plan.plot(x[keep], y[keep], ls, color=f"C{k}", lw=1.4, label=label)
            side.plot(x[keep], z[keep], ls, color=f"C{k}", lw=1.4, label=label)
        px, py, pz = (np.asarray(ds[v].values[c], float) for v in ("point_x", "point_y", "point_z"))
        other = np.setdiff1d(np.arange(px.size), anchors)
        for ax, v in ((plan, py), (side, pz)):
            ax.plot(px[other], v[other], "o", ms=3.5, color="k", mfc="white" if c else "k",
                    label=("points" if c == 0 else None) if ax is plan else None)
        bx, by, bz = (np.asarray(ds[v].values[c], float) for v in ("body_x", "body_y", "body_z"))
        for ax, v in ((plan, by), (side, bz)):
            ax.plot(bx, v, "s", ms=9, mfc="none", mec="k", mew=1.5 if c == 0 else 1.0, ls="none",
                    label=f"bodies ({condition})" if ax is plan else None)
        if c == 0 and anchors.size:
            plan.plot(px[anchors], py[anchors], "v", color="sienna", ms=8, label="anchors")
            side.plot(px[anchors], pz[anchors], "v", color="sienna", ms=8)
    if "body" in ds.coords and ds.sizes.get("body", 0):
        for j, name in enumerate(_names(ds, "body")):
            plan.annotate(name, (float(ds.body_x.values[0, j]), float(ds.body_y.values[0, j])),
                          textcoords="offset points", xytext=(6, 6), fontsize=8)
    plan.set(xlabel="x [m]", ylabel="y [m]", title="Plan view (intact solid, damaged dashed)")
    plan.set_aspect("equal", adjustable="datalim")
    plan.legend(fontsize=7, loc="best")
    depth = _depth(ds)
    xs = np.asarray(ds.x.values, float)
    if depth is not None and np.isfinite(xs).any():
        lo, hi = np.nanmin(xs), np.nanmax(xs)
        pad = 0.05 * (hi - lo) or 1.0
        side.plot([lo - pad, hi + pad], [-depth, -depth], color="sienna", lw=1.2, label="seabed")
    side.axhline(0.0, color="steelblue", lw=0.8, ls="--", label="sea surface")
    side.set(xlabel="x [m]", ylabel="z [m]", title="Elevation (looking along +y)")
    side.legend(fontsize=7, loc="best")
    return fig


def _end_tensions(ds, plt):
    """Fairlead and anchor tension of each line, the conditions side by side."""
    lines = _names(ds, "line")
    conds = _conditions(ds)
    scale, unit = _scale(ds.fairlead_tension.values, ds.anchor_tension.values)
    fig, ax = plt.subplots(figsize=(max(6.0, 1.4 * len(lines) + 3), 4.2))
    width = 0.8 / (2 * len(conds))
    pos = np.arange(len(lines), dtype=float)
    for c, condition in conds:
        for e, (key, hatch) in enumerate((("fairlead_tension", None), ("anchor_tension", "//"))):
            off = (2 * c + e - len(conds) + 0.5) * width
            values = np.asarray(ds[key].values[c], float) / scale
            bars = ax.bar(pos + off, np.nan_to_num(values), width, color=f"C{c}", alpha=0.9 if e == 0 else 0.55,
                          hatch=hatch, label=f"{condition}: {'fairlead' if e == 0 else 'anchor'}")
            for b, v in zip(bars, values):
                if not np.isfinite(v):
                    ax.annotate("removed", (b.get_x() + b.get_width() / 2, 0.0), rotation=90, ha="center",
                                va="bottom", fontsize=7)
    ax.set_xticks(pos, lines)
    ax.set(ylabel=f"tension [{unit}]", title="Line end tensions")
    ax.legend(fontsize=7)
    return fig


def _system_static(ds, plt):
    return {"system": _system_views(ds, plt), "tensions": _end_tensions(ds, plt)}


def _offsets_values(ds):
    """(offset x, offset y) of the loaded body, (condition, applied_load, heading). [m]"""
    name = ds.attrs.get("loaded_body")
    bodies = _names(ds, "body")
    j = bodies.index(name) if name in bodies else 0
    return np.asarray(ds.body_offset_x.values[..., j], float), np.asarray(ds.body_offset_y.values[..., j], float)


def _close(a):
    """A closed curve over headings when they go round the circle."""
    return np.concatenate([a, a[:1]])


def _system_offsets(ds, plt):
    from matplotlib import colormaps

    figs = {}
    loads = np.asarray(ds.applied_load.values, float)
    headings = np.asarray(ds.heading.values, float)
    order = np.argsort(np.mod(headings, 2 * np.pi))
    full = headings.size >= 3
    lscale, lunit = _scale(loads)
    colours = colormaps["viridis"](np.linspace(0.0, 0.9, loads.size))
    ox, oy = _offsets_values(ds)
    body = ds.attrs.get("loaded_body", "body")

    fig, ax = plt.subplots(figsize=(7, 6.2))
    for c, condition in _conditions(ds):
        for i, load in enumerate(loads):
            x, y = ox[c, i, order], oy[c, i, order]
            if full:
                x, y = _close(x), _close(y)
            ax.plot(x, y, _style(condition), marker="." if not full else None, color=colours[i],
                    label=f"{load / lscale:g} {lunit}" if c == 0 else None)
    for c, condition in _conditions(ds):
        ax.plot([], [], _style(condition), color="k", label=condition)
    ax.plot(0.0, 0.0, "+", color="k", ms=10)
    ax.set(xlabel="offset x [m]", ylabel="offset y [m]",
           title=f"Watch circle of '{body}': offsets over load headings")
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=7, title="load", title_fontsize=8)
    figs["watch_circle"] = fig

    fscale, funit = _scale(ds.restoring_force.values)
    offset = np.asarray(ds.offset.values, float)
    force = np.asarray(ds.restoring_force.values, float)
    hcol = colormaps["twilight"](np.linspace(0.0, 0.95, headings.size))
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    for c, condition in _conditions(ds):
        for h in range(headings.size):
            ax.plot(offset[c, :, h], force[c, :, h] / fscale, _style(condition), marker="o", ms=3, color=hcol[h],
                    label=f"{np.degrees(headings[h]):.0f} deg" if c == 0 else None)
    for c, condition in _conditions(ds):
        ax.plot([], [], _style(condition), color="k", label=condition)
    ax.set(xlabel=_label(ds.offset), ylabel=f"restoring force [{funit}]",
           title="Restoring force against offset, each load heading")
    ax.legend(fontsize=6, ncol=2 if headings.size > 8 else 1)
    figs["restoring"] = fig

    tension = np.asarray(ds.fairlead_tension.values, float)
    tscale, tunit = _scale(tension)
    peak = np.nanmax(np.where(np.isfinite(tension), tension, -np.inf), axis=-1)
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    deg = np.degrees(np.mod(headings, 2 * np.pi))[order]
    for c, condition in _conditions(ds):
        for i, load in enumerate(loads):
            ax.plot(deg, peak[c, i, order] / tscale, _style(condition), marker="o", ms=3, color=colours[i],
                    label=f"{load / lscale:g} {lunit}" if c == 0 else None)
    for c, condition in _conditions(ds):
        ax.plot([], [], _style(condition), color="k", label=condition)
    ax.set(xlabel="load heading [deg]", ylabel=f"largest fairlead tension [{tunit}]",
           title="Most loaded line against the load heading")
    ax.legend(fontsize=7, title="load", title_fontsize=8)
    figs["offset_tension"] = fig
    return figs


def _failures(ds, ax) -> None:
    """Dotted vertical lines at the times lines failed."""
    if "failure_time" not in ds.variables:
        return
    for k, (name, t) in enumerate(zip(_names(ds, "line"), np.asarray(ds.failure_time.values, float))):
        if np.isfinite(t):
            ax.axvline(t, color=f"C{k}", ls=":", lw=1.0)
            ax.annotate(f"{name} fails", (t, 1.0), xycoords=("data", "axes fraction"), rotation=90, ha="right",
                        va="top", fontsize=7)


def _dynamic_tensions(ds, plt):
    """Fairlead and anchor tension of each line in time, failures marked."""
    time = np.asarray(ds.time.values, float)
    scale, unit = _scale(ds.fairlead_tension.values, ds.anchor_tension.values)
    fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for ax, key, where in ((axes[0], "fairlead_tension", "fairlead"), (axes[1], "anchor_tension", "anchor")):
        for k, name in enumerate(_names(ds, "line")):
            ax.plot(time, np.asarray(ds[key].values[:, k], float) / scale, color=f"C{k}", lw=1.1, label=name)
        _failures(ds, ax)
        ax.set(ylabel=f"{where} tension [{unit}]")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    axes[0].set_title("Line end tensions" + _interrupted_note(ds, time, "s"))
    axes[1].set(xlabel="time [s]")
    return fig


def _dynamic_bodies(ds, plt):
    """Each body's translations and rotations in time, failures marked."""
    time = np.asarray(ds.time.values, float)
    fig, (trans, rot) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    from ..results import body_pose

    pos = body_pose(ds)  # (time, body, dof): x, y, z [m], roll, pitch, yaw [rad]
    for j, body in enumerate(_names(ds, "body")):
        for d, (name, ls) in enumerate(zip(("x", "y", "z"), ("-", "--", ":"))):
            trans.plot(time, pos[:, j, d] - pos[0, j, d], ls, color=f"C{j}", lw=1.1, label=f"{body} {name}")
            rot.plot(time, np.degrees(pos[:, j, 3 + d] - pos[0, j, 3 + d]), ls, color=f"C{j}", lw=1.1,
                     label=f"{body} {('roll', 'pitch', 'yaw')[d]}")
    for ax in (trans, rot):
        _failures(ds, ax)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, ncol=3)
    trans.set(ylabel="displacement from t = 0 [m]", title="Body motions" + _interrupted_note(ds, time, "s"))
    rot.set(xlabel="time [s]", ylabel="rotation from t = 0 [deg]")
    return fig


def _dynamic_views(ds, plt):
    """Plan view and elevation of the lines at a few times."""
    time = np.asarray(ds.time.values, float)
    _, shown = _snapshot_times(time, 5)
    fig, (plan, side) = plt.subplots(1, 2, figsize=(13, 5.2), gridspec_kw={"width_ratios": [1, 1.3]})
    shades = np.linspace(0.35, 1.0, len(shown))
    for i, t in enumerate(shown):
        n = int(np.argmin(np.abs(time - t)))
        for k, name in enumerate(_names(ds, "line")):
            x, y, z = (np.asarray(ds[v].values[n, k], float) for v in ("x", "y", "z"))
            keep = np.isfinite(x) & np.isfinite(y) & np.isfinite(z)
            label = f"{name}" if i == len(shown) - 1 else None
            for ax, v in ((plan, y), (side, z)):
                ax.plot(x[keep], v[keep], color=f"C{k}", alpha=float(shades[i]), lw=1.2, label=label)
        if "body_position" in ds.variables:
            bp = np.asarray(ds.body_position.values[n], float)
            plan.plot(bp[:, 0], bp[:, 1], "s", ms=7, mfc="none", mec="k", alpha=float(shades[i]))
            side.plot(bp[:, 0], bp[:, 2], "s", ms=7, mfc="none", mec="k", alpha=float(shades[i]))
    times = ", ".join(f"{t:g}" for t in shown)
    plan.set(xlabel="x [m]", ylabel="y [m]", title=f"Plan view at t = {times} s (darker: later)")
    plan.set_aspect("equal", adjustable="datalim")
    if ds.sizes.get("line", 0):  # a system of bodies alone has no line to label
        plan.legend(fontsize=7)
    depth = _depth(ds)
    if depth is not None:
        side.axhline(-depth, color="sienna", lw=1.2, label="seabed")
    side.axhline(0.0, color="steelblue", lw=0.8, ls="--", label="sea surface")
    side.set(xlabel="x [m]", ylabel="z [m]", title="Elevation (looking along +y)")
    side.legend(fontsize=7)
    return fig


def _system_dynamic(ds, plt):
    figs = {"tensions": _dynamic_tensions(ds, plt)} if ds.sizes.get("line", 0) else {}  # no lines: no tensions
    figs["system"] = _dynamic_views(ds, plt)
    if "body_position" in ds.variables and ds.sizes.get("body", 0):
        figs["bodies"] = _dynamic_bodies(ds, plt)
    return figs


#: analysis type -> function(ds, pyplot) -> {figure name: Figure}; merged into seacable.plot.FIGURES
SYSTEM_FIGURES = {
    "system_static": _system_static,
    "system_offsets": _system_offsets,
    "system_dynamic": _system_dynamic,
}


def _figures(ds, analysis: str) -> list:
    return figures_of(ds, analysis, SYSTEM_FIGURES)


def plot_system_static(ds) -> list:
    """Figures of a ``system_static`` result: the system in plan and elevation, and the end tensions.

    Parameters
    ----------
    ds : xarray.Dataset
        A ``system_static`` result.

    Returns
    -------
    list of matplotlib.figure.Figure
        The lines' profiles, bodies, points and anchors in plan view and in elevation with the
        seabed and the sea surface (intact solid, damaged dashed); then the fairlead and anchor
        tension of each line, the conditions side by side (kN above 10 kN).

    Raises
    ------
    InputError
        The result is not a ``system_static`` one.
    """
    return _figures(ds, "system_static")


def plot_system_offsets(ds) -> list:
    """Figures of a ``system_offsets`` result: the watch circle, the restoring force, the peak tension.

    Parameters
    ----------
    ds : xarray.Dataset
        A ``system_offsets`` result.

    Returns
    -------
    list of matplotlib.figure.Figure
        The loaded body's offsets over the headings, one closed curve per load (the watch circle);
        the restoring force against the offset along each heading; the largest fairlead tension
        against the heading, one curve per load. Intact solid, damaged dashed.

    Raises
    ------
    InputError
        The result is not a ``system_offsets`` one.
    """
    return _figures(ds, "system_offsets")


def plot_system_dynamic(ds) -> list:
    """Figures of a ``system_dynamic`` result: tensions and body motions in time, the system at a few times.

    Parameters
    ----------
    ds : xarray.Dataset
        A ``system_dynamic`` result.

    Returns
    -------
    list of matplotlib.figure.Figure
        The fairlead and anchor tension of each line against time; the lines in plan view and
        elevation at about five times (later darker), with the bodies; each body's translations and
        rotations from their values at t = 0. Line failures are dotted vertical lines.

    Raises
    ------
    InputError
        The result is not a ``system_dynamic`` one.
    """
    return _figures(ds, "system_dynamic")

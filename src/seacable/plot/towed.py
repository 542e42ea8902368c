"""Figures of the towed-cable dynamics (``towed_dynamic``)."""

from __future__ import annotations

import numpy as np

from ._core import _label, _snapshot_times


def _towed_dynamic(ds, plt):
    from matplotlib import colormaps

    time = ds.time.values
    t_unit = ds.time.attrs.get("units", "s")
    interrupted = bool(int(ds.attrs.get("interrupted", 0) or 0))
    note = f" (interrupted at t = {time[-1]:g} {t_unit})" if interrupted else ""
    top = int(np.argmax(ds.s.values))  # s runs from the lower end, so the top node has the largest s
    low = int(np.argmin(ds.s.values))
    step, snaps = _snapshot_times(time)
    colours = colormaps["viridis"](np.linspace(0.0, 0.9, len(snaps)))
    mark = "o-" if time.size == 1 else "-"
    top_x = ds.vessel_x if "vessel_x" in ds else ds.x.isel(node=top)
    top_y = ds.vessel_y if "vessel_y" in ds else ds.y.isel(node=top)
    xlabel, ylabel = "X [m]", "Y [m]"
    figs = {}

    fig, ax = plt.subplots(figsize=(7, 4.2))
    ax.plot(time, ds.top_tension, mark, lw=1.5, label="top tension")
    at = ds.top_tension.sel(time=snaps)
    ax.plot(snaps, at, "o", color="C1", label="at the plan-view times")
    for t, v in zip(snaps, at.values):
        ax.annotate(f"{v:.1f}", (t, v), textcoords="offset points", xytext=(0, 6), ha="center", fontsize=8)
    ax.margins(y=0.12)  # room for the value labels
    ax.set(xlabel=_label(ds.time), ylabel=_label(ds.top_tension), title="Top tension" + note)
    ax.legend()
    figs["top_tension"] = fig

    fig, ax = plt.subplots(figsize=(7, 5))
    ax.plot(top_x, top_y, "k--", lw=1, label="vessel track")
    for t, c in zip(snaps, colours):
        sel = ds.sel(time=t)
        ax.plot(sel.x, sel.y, "o-", color=c, ms=3, label=f"t = {t:g} {t_unit}")
        ax.plot(sel.x.isel(node=top), sel.y.isel(node=top), "^", color=c, ms=7)
    every = (f"every {step:g} {t_unit}" if step else
             f"at t = {snaps[0]:g} {t_unit}" if snaps.size == 1 else f"at {snaps.size} times")
    ax.plot([], [], "k^", ms=7, label="tow point")
    ax.set(xlabel=xlabel, ylabel=ylabel, title=f"Plan view of the cable {every}" + note)
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=8)
    figs["plan_view"] = fig

    fig, ax = plt.subplots(figsize=(7, 5))
    ax.plot(ds.x.isel(node=top), ds.y.isel(node=top), "o-" if time.size == 1 else "-", color="C0",
            label="vessel (top node)")
    ax.plot(ds.x.isel(node=low), ds.y.isel(node=low), "o-" if time.size == 1 else "-", color="C3",
            label="lower end")
    sel = ds.sel(time=snaps)
    ax.plot(sel.x.isel(node=top), sel.y.isel(node=top), "o", color="C0", ms=4)
    ax.plot(sel.x.isel(node=low), sel.y.isel(node=low), "o", color="C3", ms=4,
            label=f"markers {every}" if snaps.size > 1 else None)
    ax.set(xlabel=xlabel, ylabel=ylabel, title="Trajectories of the cable ends" + note)
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=8)
    figs["end_trajectories"] = fig

    fig, ax = plt.subplots(figsize=(7, 4.2))
    depth = ds.lower_end_depth if "lower_end_depth" in ds else -ds.z.isel(node=low)
    ax.plot(time, depth, mark, color="C3", label="lower end")
    ax.invert_yaxis()  # depth positive down: deeper is lower on the page
    ax.set(xlabel=_label(ds.time), ylabel="lower-end depth, positive down [m]",
           title="Depth of the lower end" + note)
    ax.legend()
    figs["lower_end_depth"] = fig

    fig, ax = plt.subplots(figsize=(7, 4.2))
    for t, c in zip(snaps, colours):
        ax.plot(ds.s, ds.tension.sel(time=t), "o-", color=c, ms=3, label=f"t = {t:g} {t_unit}")
    ax.set(xlabel=_label(ds.s), ylabel=_label(ds.tension), title="Tension along the cable" + note)
    ax.legend(fontsize=8)
    figs["tension_profile"] = fig
    return figs



TOWED_FIGURES = {"towed_dynamic": _towed_dynamic}

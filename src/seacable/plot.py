"""Standard figures of each analysis, written as PNG.

matplotlib is imported when a plot is made, not when seacable is imported, and
uses the non-interactive Agg backend so that plots work on machines without a
screen.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

__all__ = ["plot_result", "FIGURES"]


def _label(da) -> str:
    units = da.attrs.get("units", "")
    units = "deg" if units == "degree" else units.replace(" m-1", "/m").replace("m s-1", "m/s")
    name = da.attrs.get("long_name", da.name)
    return f"{name} [{units}]" if units and units != "1" else str(name)


def _static(ds, plt):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax1.plot(ds.x, ds.z, "-", lw=1.5)
    if "seabed_z" in ds:
        ax1.axhline(float(ds.seabed_z), color="sienna", lw=1)
    ax1.axhline(0.0, color="steelblue", lw=0.8, ls="--")
    ax1.set(xlabel=_label(ds.x), ylabel=_label(ds.z), title="Static shape")
    ax1.set_aspect("equal", adjustable="datalim")
    ax2.plot(ds.s, ds.tension / 1e3)
    ax2.set(xlabel=_label(ds.s), ylabel="effective tension [kN]",
            title=f"Fairlead {float(ds.tension_fairlead) / 1e3:.1f} kN, "
                  f"anchor {float(ds.tension_anchor) / 1e3:.1f} kN")
    return {"shape": fig}


def _pushover(ds, plt):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax1.plot(ds.offset, ds.H_fairlead / 1e3, label="horizontal")
    ax1.plot(ds.offset, ds.tension_fairlead / 1e3, label="total")
    ax1.set(xlabel=_label(ds.offset), ylabel="fairlead tension [kN]", title="Force-excursion")
    ax1.legend()
    ax2.plot(ds.offset, ds.stiffness_horizontal / 1e3)
    ax2.set(xlabel=_label(ds.offset), ylabel="dH/dx [kN/m]", title="Horizontal stiffness")
    return {"pushover": fig}


def _modal(ds, plt):
    fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(15, 4.2))
    planes = ds.plane.values.astype(str)
    for plane, marker in (("in", "o"), ("out", "s")):
        keep = planes == plane
        ax1.plot(ds.mode.values[keep], ds.period.values[keep], marker, label=f"{plane}-plane")
    ax1.axhline(float(ds.wave_period), color="k", ls="--", lw=0.8, label="wave-speed estimate")
    ax1.set(xlabel="mode", ylabel=_label(ds.period), title="Natural periods")
    ax1.legend()
    span = float(np.ptp(ds.x.values)) or float(np.ptp(ds.z.values)) or 1.0
    ax2.plot(ds.x, ds.z, "k-", lw=2, label="static")
    for k in np.flatnonzero(planes == "in")[:3]:
        shp = ds.shape.isel(mode=k).values
        ax2.plot(ds.x + 0.08 * span * shp[:, 0], ds.z + 0.08 * span * shp[:, 2],
                 label=f"mode {k + 1} ({float(ds.period[k]):.2f} s)")
    ax2.set(xlabel=_label(ds.x), ylabel=_label(ds.z), title="In-plane modes")
    ax2.legend(fontsize=8)
    for k in np.flatnonzero(planes == "out")[:3]:
        ax3.plot(ds.s, ds.shape.isel(mode=k).sel(direction="y"),
                 label=f"mode {k + 1} ({float(ds.period[k]):.2f} s)")
    ax3.set(xlabel=_label(ds.s), ylabel="y displacement [-]", title="Out-of-plane modes")
    ax3.legend(fontsize=8)
    return {"modes": fig}


def _towed(ds, plt):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax1.plot(ds.x, ds.z, "o-")
    ax1.set(xlabel=_label(ds.x), ylabel=_label(ds.z),
            title=f"Steady tow, relative speed {float(ds.relative_speed):.2f} m/s")
    ax2.plot(ds.s, ds.tension, "o-")
    ax2.set(xlabel=_label(ds.s), ylabel=_label(ds.tension), title=f"Top tension {float(ds.top_tension):.1f} N")
    return {"towed": fig}


def _laying(ds, plt):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax1.plot(ds.ship_speed, ds.angle, "o-", label="exact root")
    ax1.plot(ds.ship_speed, ds.angle_small, "x--", label="small angle H/V")
    ax1.set(xlabel=_label(ds.ship_speed), ylabel="entry angle [deg]", title="Laying angle", ylim=(0, 90))
    ax1.legend()
    ax2.plot(ds.ship_speed, ds.layback, "o-")
    ax2.set(xlabel=_label(ds.ship_speed), ylabel=_label(ds.layback), title="Layback")
    return {"laying": fig}


def _vertical(ds, plt):
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for solution in ds.solution.values:
        ax.plot(ds.mode, ds.period.sel(solution=solution), "o-", label=str(solution))
    ax.set(xlabel="mode", ylabel=_label(ds.period), title="Vertical cable periods")
    ax.legend()
    return {"periods": fig}


def _nice_step(target: float) -> float:
    """The 'round' number (1, 2, 2.5 or 5 times a power of ten) nearest ``target`` in ratio."""
    exp = np.floor(np.log10(target))
    candidates = np.array([1.0, 2.0, 2.5, 5.0, 10.0]) * 10.0**exp
    return float(candidates[np.argmin(np.abs(np.log(candidates / target)))])


def _snapshot_times(time, n: int = 6) -> tuple[float, np.ndarray]:
    """Times of the plan-view snapshots: every N seconds, N round, giving about ``n`` snapshots.

    N is the round number (1, 2, 2.5 or 5 times a power of ten) nearest to span / (n - 1), so
    that 100 s gives a snapshot every 20 s (0, 20, ..., 100 s: 6 snapshots, as paper 000,
    Fig. 6). The snapshots are the output times nearest to t0, t0 + N, t0 + 2N, ... up to the
    last output time (without repeats).

    Parameters
    ----------
    time
        Output times, increasing. [s]
    n
        Wanted number of snapshots, at least 2.

    Returns
    -------
    step : float
        N; 0 when the snapshots are not N apart (a single output time, or output times too
        coarse to fall on the multiples of N). [s]
    times : numpy.ndarray
        The snapshot times, taken from ``time``. [s]
    """
    time = np.asarray(time, dtype=float).ravel()
    span = float(time[-1] - time[0]) if time.size else 0.0
    if time.size < 2 or span <= 0.0:
        return 0.0, time[:1].copy()
    step = _nice_step(span / (n - 1))
    wanted = time[0] + step * np.arange(int(np.floor(span / step * (1 + 1e-9))) + 1)
    idx = np.unique(np.abs(time[None, :] - wanted[:, None]).argmin(axis=1))
    if idx.size != wanted.size or np.any(np.abs(time[idx] - wanted) > 1e-6 * span):
        step = 0.0  # output too coarse for round steps: the nearest output times, not N apart
    return step, time[idx]


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


#: analysis type -> function(ds, pyplot) -> {figure name: Figure}
FIGURES = {
    "static": _static,
    "pushover": _pushover,
    "modal": _modal,
    "towed_steady": _towed,
    "laying_theory": _laying,
    "vertical_modes": _vertical,
    "towed_dynamic": _towed_dynamic,
}


def plot_result(ds, outdir, prefix: str | None = None) -> list[Path]:
    """Write the standard figures of a result as PNG files.

    Parameters
    ----------
    ds
        A result from :func:`seacable.run` or :func:`seacable.results.read_netcdf`.
    outdir
        Folder for the files (created if needed).
    prefix
        File-name prefix; the case name by default.

    Returns
    -------
    list of Path
        The files written.
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    from .errors import InputError

    analysis = ds.attrs.get("analysis")
    if analysis not in FIGURES:
        raise InputError(f"no standard figures for analysis '{analysis}'. Known: {', '.join(FIGURES)}.")
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    prefix = prefix or ds.attrs.get("case_name", analysis)
    written = []
    for name, fig in FIGURES[analysis](ds, plt).items():
        fig.suptitle(ds.attrs.get("title", ""), fontsize=10)
        fig.tight_layout()
        path = outdir / f"{prefix}_{name}.png"
        fig.savefig(path, dpi=110)
        plt.close(fig)
        written.append(path)
    return written

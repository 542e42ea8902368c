"""Standard figures of each analysis, written as PNG.

matplotlib is imported when a plot is made, not when seacable is imported, and
uses the non-interactive Agg backend so that plots work on machines without a
screen.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

__all__ = ["FIGURES", "animate_laying", "plot_result"]


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


def _interrupted_note(ds, time, t_unit) -> str:
    interrupted = bool(int(ds.attrs.get("interrupted", 0) or 0))
    return f" (interrupted at t = {time[-1]:g} {t_unit})" if interrupted and time.size else ""


def _finite_xz(x, z):
    """The points of a NaN-padded (x, z) row that are defined."""
    x, z = np.asarray(x, dtype=float), np.asarray(z, dtype=float)
    keep = np.isfinite(x) & np.isfinite(z)
    return x[keep], z[keep]


def _lay_scene(ax, ds) -> None:
    """Seabed (filled below), sea surface and axis limits covering the cable and the ship.

    The limits cover every suspended node at every time, the laid cable and the ship track, so
    that snapshots and animation frames share one frame of reference. The aspect ratio is left
    free: a lay is typically tens of metres deep over hundreds of metres or kilometres long.
    """
    xs = [ds.x.values.ravel(), ds.ship_x.values.ravel()]
    zs = [ds.z.values.ravel(), np.zeros(1)]
    if "laid_x" in ds:
        xs.append(ds.laid_x.values.ravel())
        zs.append(ds.laid_z.values.ravel())
    xs, zs = np.concatenate(xs), np.concatenate(zs)
    xs, zs = xs[np.isfinite(xs)], zs[np.isfinite(zs)]
    x0, x1 = (float(xs.min()), float(xs.max())) if xs.size else (0.0, 1.0)
    pad = 0.03 * (x1 - x0) or 1.0
    x0, x1 = x0 - pad, x1 + pad
    bottom = float(zs.min()) if zs.size else -1.0
    bx = bz = np.empty(0)
    if "seabed_x" in ds:
        bx, bz = _finite_xz(ds.seabed_x.values, ds.seabed_z.values)
        order = np.argsort(bx)
        bx, bz = bx[order], bz[order]
        seen = (bx >= x0) & (bx <= x1)
        if seen.any():
            bottom = min(bottom, float(bz[seen].min()))
        if bx.size:  # the profile at the frame edges, so that the fill reaches them
            bottom = min(bottom, float(np.interp(x0, bx, bz)), float(np.interp(x1, bx, bz)))
    depth = max(-bottom, 1.0)
    y0, y1 = bottom - 0.15 * depth, 0.1 * depth
    if bx.size:
        ax.fill_between(bx, bz, y0 - depth, color="tan", alpha=0.7, lw=0, zorder=0)
        ax.plot(bx, bz, color="sienna", lw=1.2, label="seabed", zorder=1)
    ax.axhline(0.0, color="steelblue", lw=0.8, ls="--", label="sea surface", zorder=1)
    ax.set(xlim=(x0, x1), ylim=(y0, y1), xlabel=_label(ds.x), ylabel=_label(ds.z))


def _repeaters_at(ds, i: int):
    """(x, z) of the repeaters in the water at time index ``i`` (empty when there are none)."""
    if "repeater_x" not in ds or ds.repeater_x.size == 0:
        return np.empty(0), np.empty(0)
    return _finite_xz(ds.repeater_x.values[i], ds.repeater_z.values[i])


def _laying_dynamic(ds, plt):
    from matplotlib import colormaps

    time = ds.time.values.astype(float)
    t_unit = ds.time.attrs.get("units", "s")
    note = _interrupted_note(ds, time, t_unit)
    step, snaps = _snapshot_times(time)
    idx = np.searchsorted(time, snaps)  # the snapshots are output times
    colours = colormaps["viridis"](np.linspace(0.0, 0.9, len(snaps)))
    figs = {}

    fig, ax = plt.subplots(figsize=(11, 4.5))
    _lay_scene(ax, ds)
    if "laid_x" in ds and ds.laid_x.size:
        lx, lz = _finite_xz(ds.laid_x.values, ds.laid_z.values)
        ax.plot(lx, lz, "k-", lw=0.8, label="laid cable")
    for i, t, c in zip(idx, snaps, colours):
        x, z = _finite_xz(ds.x.values[i], ds.z.values[i])
        ax.plot(x, z, "-", color=c, lw=1.5, label=f"t = {t:g} {t_unit}")
        ax.plot(float(ds.ship_x.values[i]), 0.0, "v", color=c, ms=7)
    rx, rz = _repeaters_at(ds, idx[-1])
    if rx.size:
        ax.plot(rx, rz, "D", color="C3", ms=6, label=f"repeater (t = {snaps[-1]:g} {t_unit})")
    ax.plot([], [], "kv", ms=7, label="ship")
    every = (f"every {step:g} {t_unit}" if step else
             f"at t = {snaps[0]:g} {t_unit}" if snaps.size == 1 else f"at {snaps.size} times")
    ax.set_title(f"Laying shape {every}" + note)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))  # beside: the cable fills the frame
    figs["shape"] = fig

    fig, (ax1, ax2, ax3) = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    mark = "o-" if time.size == 1 else "-"
    tension_max = np.nanmax(np.abs(np.r_[ds.top_tension.values, ds.bottom_tension.values, 0.0]))
    scale, unit = (1e3, "kN") if tension_max >= 1e4 else (1.0, "N")
    ax1.plot(time, ds.top_tension / scale, mark, label="top (ship)")
    ax1.plot(time, ds.bottom_tension / scale, mark, label="bottom (touchdown)")
    ax1.set(ylabel=f"tension [{unit}]", title="Laying tensions, slack and speeds" + note)
    ax1.legend(fontsize=8)
    in_percent = ds.slack.attrs.get("units", "1") == "%"
    ax2.plot(time, ds.slack * (1.0 if in_percent else 100.0), mark, color="C2", label="slack")
    ax2.set_ylabel("slack [%]")
    twin = ax2.twinx()
    twin.plot(time, ds.entry_angle, mark, color="C4", label="entry angle")
    twin.set_ylabel(_label(ds.entry_angle))
    lines = ax2.get_lines() + twin.get_lines()
    ax2.legend(lines, [ln.get_label() for ln in lines], fontsize=8)
    ax3.plot(time, ds.ship_speed, mark, label="ship")
    ax3.plot(time, ds.payout_speed, mark, label="payout")
    ax3.set(xlabel=_label(ds.time), ylabel="speed [m/s]")
    ax3.legend(fontsize=8)
    figs["tension"] = fig
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
    "laying_dynamic": _laying_dynamic,
}

from .plot_mooring import MOORING_FIGURES  # noqa: E402  (no import loop: it reaches back only when drawing)

FIGURES.update(MOORING_FIGURES)

from .plot_towline import TOWLINE_FIGURES  # noqa: E402  (same: it imports plot only when drawing)

FIGURES.update(TOWLINE_FIGURES)

from .plot_sweep import SWEEP_FIGURES  # noqa: E402  (same)

FIGURES.update(SWEEP_FIGURES)


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


def animation_writer(path, fps, max_frames, dpi, n_times):
    """Check an animation's arguments; return (path, writer, frame indices, pyplot).

    ``.gif`` is written with Pillow, ``.mp4`` with ffmpeg; the ``n_times`` output times are subsampled
    evenly, first and last kept, to at most ``max_frames`` frames.
    """
    from ._validate import positive
    from .errors import InputError

    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in (".gif", ".mp4"):
        raise InputError(f"animation file '{path}' must end in .gif or .mp4, got '{path.suffix}'. "
                         f"Suggested fix: -o {path.with_suffix('.gif')}")
    positive("fps", fps, "1/s", "give the frame rate, e.g. 10")
    max_frames = int(positive("max_frames", max_frames, "", "give the largest number of frames, e.g. 200"))
    if max_frames < 1:
        raise InputError(f"max_frames must be >= 1, got {max_frames}. Suggested fix: e.g. 200.")
    positive("dpi", dpi, "1/in", "e.g. 100")
    if n_times == 0:
        raise InputError("the result has no output times to animate. Suggested fix: rerun the case.")

    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    from matplotlib.animation import FFMpegWriter, PillowWriter

    if suffix == ".mp4":
        if not FFMpegWriter.isAvailable():
            raise InputError(f"cannot write '{path}': MP4 needs ffmpeg, which is not on the PATH. "
                             f"Suggested fix: install ffmpeg or write a GIF: -o {path.with_suffix('.gif')}")
        writer = FFMpegWriter(fps=fps)
    else:
        writer = PillowWriter(fps=fps)
    n = min(max_frames, n_times)
    frames = [n_times - 1] if n == 1 else np.round(np.linspace(0, n_times - 1, n)).astype(int)
    return path, writer, frames, plt


def animate_laying(ds, path, *, fps: int = 10, max_frames: int = 200, dpi: int = 100) -> Path:
    """Write an animation of a cable lay (``laying_dynamic`` result) as GIF or MP4.

    Each frame shows the seabed, the laid cable up to the frame's time (the landed nodes with
    ``laid_time`` <= t), the suspended cable, the ship at (``ship_x``, 0), the repeaters in the
    water and the time. The output times are subsampled evenly, first and last kept, to at most
    ``max_frames`` frames.

    Parameters
    ----------
    ds
        A ``laying_dynamic`` result, from :func:`seacable.run` or
        :func:`seacable.results.read_netcdf`.
    path
        Output file; ``.gif`` (written with Pillow) or ``.mp4`` (needs ffmpeg on the PATH).
    fps
        Frames per second of the animation. [1/s]
    max_frames
        Largest number of frames; the animation has min(max_frames, number of output times).
    dpi
        Resolution of the frames (the figure is 10 x 4.5 in). [1/in]

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    InputError
        The result is not a ``laying_dynamic`` one, the suffix is neither ``.gif`` nor ``.mp4``,
        ``.mp4`` was asked for without ffmpeg, or fps, max_frames or dpi is not positive.
    """
    from .errors import InputError

    analysis = ds.attrs.get("analysis")
    if analysis != "laying_dynamic":
        raise InputError(f"animate_laying needs a 'laying_dynamic' result, got analysis '{analysis}'. "
                         "Suggested fix: run a case with analysis type laying_dynamic, or use "
                         "'seacable plot' for the figures of this result.")
    time = ds.time.values.astype(float)
    path, writer, frames, plt = animation_writer(path, fps, max_frames, dpi, time.size)
    t_unit = ds.time.attrs.get("units", "s")
    has_laid = "laid_x" in ds and ds.laid_x.size > 0
    if has_laid:
        lx, lz = ds.laid_x.values.astype(float), ds.laid_z.values.astype(float)
        lt = ds.laid_time.values.astype(float)

    fig, ax = plt.subplots(figsize=(10, 4.5))
    _lay_scene(ax, ds)
    laid, = ax.plot([], [], "k-", lw=0.8, label="laid cable")
    hanging, = ax.plot([], [], "-", color="C0", lw=1.5, label="suspended cable")
    ship, = ax.plot([], [], "v", color="C1", ms=9, label="ship")
    reps, = ax.plot([], [], "D", color="C3", ms=6, label="repeater")
    label = ax.text(0.01, 0.97, "", transform=ax.transAxes, va="top", fontsize=10)
    ax.set_title(ds.attrs.get("title", "Cable laying"), fontsize=10)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        with writer.saving(fig, str(path), dpi):
            for i in frames:
                t = time[i]
                if has_laid:
                    keep = lt <= t + 1e-9 * max(1.0, abs(t))
                    laid.set_data(*_finite_xz(lx[keep], lz[keep]))
                hanging.set_data(*_finite_xz(ds.x.values[i], ds.z.values[i]))
                ship.set_data([float(ds.ship_x.values[i])], [0.0])
                reps.set_data(*_repeaters_at(ds, i))
                label.set_text(f"t = {t:.1f} {t_unit}")
                writer.grab_frame()
    finally:
        plt.close(fig)
    return path

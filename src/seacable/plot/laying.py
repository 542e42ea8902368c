"""Figures and animation of a cable lay (``laying_dynamic``)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ._core import _degrees, _finite_xz, _interrupted_note, _label, _snapshot_times, animation_writer

__all__ = ["animate_laying"]


def _lay_scene(ax, ds) -> None:
    """Seabed (filled below), sea surface and axis limits covering the cable and the ship, in x.

    The limits cover every suspended node at every time, the laid cable and the ship track, so
    that snapshots and animation frames share one frame of reference (see :func:`_profile_scene`).
    """
    along = [ds.x.values.ravel(), ds.ship_x.values.ravel()]
    zs = [ds.z.values.ravel(), np.zeros(1)]
    if "laid_x" in ds:
        along.append(ds.laid_x.values.ravel())
        zs.append(ds.laid_z.values.ravel())
    seabed = (ds.seabed_x.values, ds.seabed_z.values) if "seabed_x" in ds else None
    _profile_scene(ax, along, zs, seabed, _label(ds.x), _label(ds.z))


def _profile_scene(ax, along, zs, seabed, xlabel: str, zlabel: str) -> None:
    """Seabed (filled below), sea surface and axis limits of a vertical profile.

    Parameters
    ----------
    ax
        The axes.
    along, zs
        Lists of arrays of the horizontal positions and of the elevations to keep in the frame (the
        cable at every time, the ship, the laid cable), NaN where undefined. [m]
    seabed
        (horizontal position, elevation) of the seabed profile, or ``None``. [m]
    xlabel, zlabel
        Axis labels, with their units.

    The aspect ratio is left free: a lay is typically tens of metres deep over hundreds of metres
    or kilometres long.
    """
    xs, zs = np.concatenate(along), np.concatenate(zs)
    xs, zs = xs[np.isfinite(xs)], zs[np.isfinite(zs)]
    x0, x1 = (float(xs.min()), float(xs.max())) if xs.size else (0.0, 1.0)
    pad = 0.03 * (x1 - x0) or 1.0
    x0, x1 = x0 - pad, x1 + pad
    bottom = float(zs.min()) if zs.size else -1.0
    bx = bz = np.empty(0)
    if seabed is not None:
        bx, bz = _finite_xz(*seabed)
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
    ax.set(xlim=(x0, x1), ylim=(y0, y1), xlabel=xlabel, ylabel=zlabel)


def _plan_scene(ax, ds) -> None:
    """The route (legs and waypoints) and the axes of the plan view of a 3-D lay: x, y at one scale.

    The limits cover the ship's track, the laid cable and every suspended node at every time, not the
    whole route (which may run far beyond the lay), so that snapshots and animation frames share one
    frame of reference; the frame is at least a quarter as tall as it is wide, so that a lay along a
    straight route is not a sliver.
    """
    _route_line(ax, ds, 1.0)
    xs, ys = _finite_xz(np.concatenate([ds.ship_x.values.ravel(), ds.laid_x.values.ravel(), ds.x.values.ravel()]),
                        np.concatenate([ds.ship_y.values.ravel(), ds.laid_y.values.ravel(), ds.y.values.ravel()]))
    if not xs.size:
        xs, ys = ds.waypoint_x.values, ds.waypoint_y.values
    x0, x1, y0, y1 = float(xs.min()), float(xs.max()), float(ys.min()), float(ys.max())
    pad = 0.05 * max(x1 - x0, y1 - y0, 1.0)
    width = x1 - x0 + 2.0 * pad
    height = max(y1 - y0 + 2.0 * pad, 0.25 * width)
    middle = 0.5 * (y0 + y1)
    ax.set(xlim=(x0 - pad, x1 + pad), ylim=(middle - 0.5 * height, middle + 0.5 * height), xlabel="x [m]",
           ylabel="y [m]", aspect="equal")


def _fill_box(ax) -> None:
    """Widen the x or the y limits of an axes, about their middle, so that one metre is as long on both
    axes in the axes' present box, and fix that equal aspect (a plan view shows more of the map rather than
    shrinking its box). Called once the layout is made, with the aspect left free until then."""
    pos = ax.get_position()
    width, height = ax.figure.get_size_inches() * (pos.width, pos.height)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    dx, dy = x1 - x0, y1 - y0
    if dy / dx < height / width:
        dy = dx * height / width
    else:
        dx = dy * width / height
    xm, ym = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
    ax.set(xlim=(xm - 0.5 * dx, xm + 0.5 * dx), ylim=(ym - 0.5 * dy, ym + 0.5 * dy), aspect="equal")


def _route_of(ds):
    """The route of a 3-D lay result, rebuilt from its track (``route_x/y``, with the arcs) or, in older
    results, its waypoints (for the KP of points)."""
    from ..laying.route import RouteGeometry

    if "route_x" in ds:
        return RouteGeometry(np.column_stack([ds.route_x.values, ds.route_y.values]), float(ds.waypoint_kp.values[0]))
    return RouteGeometry(np.column_stack([ds.waypoint_x.values, ds.waypoint_y.values]),
                         float(ds.waypoint_kp.values[0]))


def _kp_of(route, x, y) -> np.ndarray:
    """KP along ``route`` of the points (x, y) (the nearest point of the route, as ``laid_kp``); NaN where
    x or y is NaN. [m]"""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    kp = np.full(x.shape, np.nan)
    keep = np.isfinite(x) & np.isfinite(y)
    if keep.any():
        kp[keep] = route.locate(np.column_stack([x[keep], y[keep]]))[0]
    return kp


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
    along_route = "y" in ds and all(name in ds for name in _ROUTE_VARIABLES)
    if along_route:
        # a 3-D lay: the profile along the route by KP (x would fold the cable back on itself after a turn)
        route = _route_of(ds)
        node_x = _kp_of(route, ds.x.values[idx], ds.y.values[idx])
        laid_along, ship_along = ds.laid_kp.values, ds.ship_kp.values
        _profile_scene(ax, [node_x.ravel(), ship_along[idx], laid_along], [ds.z.values[idx].ravel(), np.zeros(1),
                       ds.laid_z.values], (ds.seabed_kp.values, ds.seabed_z.values), "KP [m]", _label(ds.z))
    else:
        _lay_scene(ax, ds)
        node_x, laid_along, ship_along = ds.x.values[idx], ds.laid_x.values if "laid_x" in ds else None, ds.ship_x.values
    if laid_along is not None and laid_along.size:
        lx, lz = _finite_xz(laid_along, ds.laid_z.values)
        ax.plot(lx, lz, "k-", lw=0.8, label="laid cable")
    for k, (i, t, c) in enumerate(zip(idx, snaps, colours)):
        x, z = _finite_xz(node_x[k], ds.z.values[i])
        ax.plot(x, z, "-", color=c, lw=1.5, label=f"t = {t:g} {t_unit}")
        ax.plot(float(ship_along[i]), 0.0, "v", color=c, ms=7)
    rx, rz = (np.empty(0), np.empty(0)) if along_route else _repeaters_at(ds, idx[-1])
    if rx.size:
        ax.plot(rx, rz, "D", color="C3", ms=6, label=f"repeater (t = {snaps[-1]:g} {t_unit})")
    ax.plot([], [], "kv", ms=7, label="ship")
    every = (f"every {step:g} {t_unit}" if step else
             f"at t = {snaps[0]:g} {t_unit}" if snaps.size == 1 else f"at {snaps.size} times")
    ax.set_title(f"Laying shape {every}" + (" along the route" if along_route else "") + note)
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
    twin.plot(time, _degrees(ds.entry_angle), mark, color="C4", label="entry angle")
    twin.set_ylabel(f"{ds.entry_angle.attrs.get('long_name', 'entry angle')} [deg]")
    lines = ax2.get_lines() + twin.get_lines()
    ax2.legend(lines, [ln.get_label() for ln in lines], fontsize=8)
    ax3.plot(time, ds.ship_speed, mark, label="ship")
    ax3.plot(time, ds.payout_speed, mark, label="payout")
    ax3.set(xlabel=_label(ds.time), ylabel="speed [m/s]")
    ax3.legend(fontsize=8)
    figs["tension"] = fig
    if "laid_kp" in ds:                    # along a route, in 3-D
        figs.update(_route_figures(ds, plt, idx, snaps, colours, t_unit))
    return figs


def _route_figures(ds, plt, idx, snaps, colours, t_unit):
    """A 3-D lay along a route: the plan view, and the laid cable's offset from the route by KP."""
    fig, ax = plt.subplots(figsize=(9, 6))
    _plan_scene(ax, ds)
    ax.plot(ds.ship_x, ds.ship_y, "C0-", lw=1.0, label="ship")
    ax.plot(ds.laid_x, ds.laid_y, "-", color="sienna", lw=1.4, label="laid cable")
    for i, t, c in zip(idx, snaps, colours):
        x, y = _finite_xz(ds.x.values[i], ds.y.values[i])
        ax.plot(x, y, "-", color=c, lw=1.0, label=f"suspended, t = {t:g} {t_unit}")
    ax.set_title("Plan view")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    figs = {"plan": fig}
    panels = 3 if "laid_slack" in ds else 1
    fig, axes = plt.subplots(panels, 1, figsize=(9, 3.0 * panels), sharex=True, squeeze=False)
    ax = axes[0, 0]
    ax.plot(ds.laid_kp, ds.laid_offset, "-", color="sienna", label="laid cable")
    ax.plot(ds.touchdown_kp, ds.touchdown_offset, ".", color="C1", ms=3, label="touchdown at the outputs")
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.set(ylabel="offset, + to port [m]", title="Laid cable by KP")
    ax.legend(fontsize=7)
    if panels == 3:
        landed = ds.laid_time.values > 0.0
        kp = ds.laid_kp.values[landed]
        axes[1, 0].plot(kp, ds.laid_slack.values[landed], "-", color="C2", lw=0.8)
        axes[1, 0].set(ylabel="slack [-]")
        axes[2, 0].plot(kp, ds.laid_tension.values[landed], "-", color="C3", lw=0.8, label="bottom tension at landing")
        if "laid_residual_tension" in ds:
            axes[2, 0].plot(kp, ds.laid_residual_tension.values[landed], "--", color="C4", lw=0.8,
                            label="left in the laid cable at the end")
            axes[2, 0].legend(fontsize=7)
        axes[2, 0].set(ylabel="tension [N]")
    axes[-1, 0].set(xlabel="KP [m]")
    fig.tight_layout()
    figs["offset"] = fig
    return figs



def animate_laying(ds, path, *, fps: int = 10, max_frames: int = 200, dpi: int = 100) -> Path:
    """Write an animation of a cable lay (``laying_dynamic`` result) as GIF or MP4.

    Each frame shows the seabed, the laid cable up to the frame's time (the landed nodes with
    ``laid_time`` <= t), the suspended cable, the ship at (``ship_x``, 0), the repeaters in the
    water and the time. The output times are subsampled evenly, first and last kept, to at most
    ``max_frames`` frames.

    A lay along a route in 3-D (a result with ``y`` and the route's waypoints) has two panels per
    frame: the plan view (x, y: the route, the ship's track and the laid cable so far, the
    suspended cable, the ship and the touchdown) and the profile along the route (elevation by KP:
    the seabed on the route, the laid and the suspended cable, the ship at (``ship_kp``, 0) and the
    touchdown at (``touchdown_kp``, ``touchdown_z``)); the KP of a suspended node is that of the
    nearest point of the route, as for ``laid_kp``. Both panels keep the limits of the whole run.

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
        Resolution of the frames (the figure is 10 x 4.5 in, 10 x 8 in in 3-D). [1/in]

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
    from ..errors import InputError

    analysis = ds.attrs.get("analysis")
    if analysis != "laying_dynamic":
        raise InputError(f"animate_laying needs a 'laying_dynamic' result, got analysis '{analysis}'. "
                         "Suggested fix: run a case with analysis type laying_dynamic, or use "
                         "'seacable plot' for the figures of this result.")
    time = ds.time.values.astype(float)
    path, writer, frames, plt = animation_writer(path, fps, max_frames, dpi, time.size)
    if "y" in ds and "waypoint_x" in ds:      # along a route, in 3-D
        return _animate_route(ds, path, writer, frames, plt, dpi)
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


_ROUTE_VARIABLES = ("ship_y", "ship_kp", "touchdown_x", "touchdown_y", "touchdown_z", "touchdown_kp", "laid_x",
                    "laid_y", "laid_z", "laid_kp", "laid_time", "waypoint_y", "waypoint_kp", "seabed_kp", "seabed_z")


def _animate_route(ds, path, writer, frames, plt, dpi) -> Path:
    """The frames of a 3-D lay along a route: plan view above, profile along the route below
    (see :func:`animate_laying`)."""
    from ..errors import InputError

    missing = [name for name in _ROUTE_VARIABLES if name not in ds]
    if missing:
        raise InputError(f"the 3-D lay result (it has y and the route's waypoints) lacks {', '.join(missing)}, which "
                         "the animation along the route draws. Suggested fix: rerun the case with 'seacable run' "
                         "to write a complete result.")
    time = ds.time.values.astype(float)
    t_unit = ds.time.attrs.get("units", "s")
    route = _route_of(ds)
    node_kp = _kp_of(route, ds.x.values, ds.y.values)
    laid_x, laid_y, laid_z = (ds[name].values.astype(float) for name in ("laid_x", "laid_y", "laid_z"))
    laid_kp, laid_t = ds.laid_kp.values.astype(float), ds.laid_time.values.astype(float)
    ship_x, ship_y, ship_kp = (ds[name].values.astype(float) for name in ("ship_x", "ship_y", "ship_kp"))
    td_x, td_y = ds.touchdown_x.values.astype(float), ds.touchdown_y.values.astype(float)
    td_kp, td_z = ds.touchdown_kp.values.astype(float), ds.touchdown_z.values.astype(float)
    has_reps = "repeater_y" in ds and ds.repeater_x.size > 0
    if has_reps:
        rep_x, rep_y, rep_z = (ds[name].values.astype(float) for name in ("repeater_x", "repeater_y", "repeater_z"))
        rep_kp = _kp_of(route, rep_x, rep_y)

    fig, (plan, side) = plt.subplots(2, 1, figsize=(10, 8), gridspec_kw={"height_ratios": (3, 2)})
    _plan_scene(plan, ds)
    plan.set_aspect("auto")                 # the layout first, with the panel filling its place (see _fill_box)
    track, = plan.plot([], [], "-", color="C1", lw=3.0, alpha=0.45, zorder=0.5, label="ship's track")
    laid, hanging, ship, touchdown, reps = _frame_artists(plan, has_reps)
    plan.set_title("Plan view", fontsize=10)
    plan.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    clock = plan.text(0.01, 0.97, "", transform=plan.transAxes, va="top", fontsize=10)

    _profile_scene(side, [node_kp.ravel(), ship_kp, laid_kp, td_kp], [ds.z.values.ravel(), np.zeros(1), laid_z, td_z],
                   (ds.seabed_kp.values, ds.seabed_z.values), "KP [m]", "elevation (0 at the sea surface) [m]")
    side_laid, side_hanging, side_ship, side_td, side_reps = _frame_artists(side, has_reps)
    side.set_title("Profile along the route (seabed on the route)", fontsize=10)
    side.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.suptitle(ds.attrs.get("title", "Cable laying"), fontsize=10)
    fig.tight_layout()
    _fill_box(plan)
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        with writer.saving(fig, str(path), dpi):
            for i in frames:
                t = time[i]
                landed = laid_t <= t + 1e-9 * max(1.0, abs(t))
                laid.set_data(*_finite_xz(laid_x[landed], laid_y[landed]))
                side_laid.set_data(*_finite_xz(laid_kp[landed], laid_z[landed]))
                track.set_data(*_finite_xz(ship_x[:i + 1], ship_y[:i + 1]))
                hanging.set_data(*_finite_xz(ds.x.values[i], ds.y.values[i]))
                side_hanging.set_data(*_finite_xz(node_kp[i], ds.z.values[i]))
                ship.set_data([ship_x[i]], [ship_y[i]])
                side_ship.set_data([ship_kp[i]], [0.0])
                touchdown.set_data([td_x[i]], [td_y[i]])
                side_td.set_data([td_kp[i]], [td_z[i]])
                if has_reps:
                    wet = np.isfinite(rep_x[i]) & np.isfinite(rep_y[i]) & np.isfinite(rep_z[i])
                    reps.set_data(rep_x[i][wet], rep_y[i][wet])
                    side_reps.set_data(rep_kp[i][wet], rep_z[i][wet])
                clock.set_text(f"t = {t:.1f} {t_unit}")
                writer.grab_frame()
    finally:
        plt.close(fig)
    return path


def _lay_plan(ds, plt):
    """The lay table along KP (depth and touchdown, speeds, tensions, layback and offset) and the plan view."""
    kp = ds.kp.values / 1e3
    figs = {}
    fig, axes = plt.subplots(4, 1, figsize=(9, 10), sharex=True)
    ax = axes[0]
    ax.fill_between(kp, -ds.water_depth.values, np.nanmin(-ds.water_depth.values) * 1.05, color="0.85",
                    label="seabed at the ship")
    ax.plot(ds.touchdown_kp.values / 1e3, -ds.touchdown_depth.values, "C1-", lw=1.2, label="touchdown")
    if "repeater_touchdown_kp" in ds:
        for name, k0, k1 in zip(ds.repeater_name.values, ds.repeater_entry_kp.values, ds.repeater_touchdown_kp.values):
            ax.axvspan(k0 / 1e3, k1 / 1e3, color="C3", alpha=0.12)
            ax.annotate(str(name), (k0 / 1e3, 0.0), fontsize=7, color="C3", va="top")
    ax.set(ylabel="elevation [m]", title="Lay table along the route")
    ax.legend(fontsize=7, loc="lower left")
    ax = axes[1]
    ax.plot(kp, ds.ship_speed, label="ship")
    ax.plot(kp, ds.payout_speed, label="payout")
    ax.set_ylabel("speed [m/s]")
    twin = ax.twinx()
    twin.plot(kp, 100.0 * ds.route_slack.values, "C2--", lw=1, label="slack on route KP")
    twin.set_ylabel("route slack [%]")
    lines = ax.get_lines() + twin.get_lines()
    ax.legend(lines, [ln.get_label() for ln in lines], fontsize=7)
    ax = axes[2]
    big = np.nanmax(np.abs(ds.top_tension.values)) >= 1e4
    scale, unit = (1e3, "kN") if big else (1.0, "N")
    ax.plot(kp, ds.top_tension / scale, label="top (ship)")
    ax.plot(kp, ds.bottom_tension / scale, label="bottom (touchdown)")
    ax.set_ylabel(f"tension [{unit}]")
    twin = ax.twinx()
    twin.plot(kp, _degrees(ds.entry_angle), "C4--", lw=1, label="entry angle")
    twin.set_ylabel("entry angle [deg]")      # (the variable's long name runs into the panel above)
    lines = ax.get_lines() + twin.get_lines()
    ax.legend(lines, [ln.get_label() for ln in lines], fontsize=7)
    ax = axes[3]
    ax.plot(kp, ds.layback, label="layback")
    ax.plot(kp, ds.touchdown_offset, label="touchdown offset (+ port)")
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.set(xlabel="ship KP [km]", ylabel="distance [m]")
    ax.legend(fontsize=7)
    figs["table"] = fig

    fig, ax = plt.subplots(figsize=(8, 6))
    _route_line(ax, ds, 1e-3)
    ax.plot(ds.ship_x / 1e3, ds.ship_y / 1e3, "C0-", lw=1.0, label="ship")
    ax.plot(ds.touchdown_x / 1e3, ds.touchdown_y / 1e3, "C1-", lw=1.2, label="touchdown (laid cable)")
    if "repeater_landing_kp" in ds:
        i = np.searchsorted(ds.kp.values, ds.repeater_touchdown_kp.values).clip(0, kp.size - 1)
        ax.plot(ds.touchdown_x.values[i] / 1e3, ds.touchdown_y.values[i] / 1e3, "D", color="C3", ms=5,
                label="repeaters landed")
    ax.set(xlabel="x [km]", ylabel="y [km]")
    _plan_aspect(ax, np.concatenate([ds.ship_x.values, ds.touchdown_x.values]),
                 np.concatenate([ds.ship_y.values, ds.touchdown_y.values]), "Plan view")
    ax.legend(fontsize=7)
    figs["plan"] = fig
    return figs


def _plan_aspect(ax, x, y, title: str) -> None:
    """True scale for a plan view, unless the route is over 5 times longer one way than the other (a long straight
    route at true scale is a strip a few pixels high): then the narrow way is stretched, and the title says by
    how much."""
    x, y = x[np.isfinite(x)], y[np.isfinite(y)]
    wide, high = float(np.ptp(x)) if x.size else 0.0, float(np.ptp(y)) if y.size else 0.0
    if min(wide, high) > 0.0 and max(wide, high) > 5.0 * min(wide, high):
        box = ax.get_position()                               # (figure fractions: the scale is about this)
        w_in, h_in = ax.figure.get_size_inches()
        factor = (box.height * h_in / high) / (box.width * w_in / wide)
        factor = factor if wide > high else 1.0 / factor
        ax.set_title(f"{title} ({'y' if wide > high else 'x'} stretched about {factor:.0f} x)")
    else:
        ax.set_aspect("equal")
        ax.set_title(title)


LAYING_FIGURES = {"laying_dynamic": _laying_dynamic, "lay_plan": _lay_plan}


def _frame_artists(ax, has_reps: bool):
    """The empty lines an animation frame fills: laid cable, suspended cable, ship, touchdown, repeaters."""
    return (ax.plot([], [], "k-", lw=1.2, label="laid cable")[0],
            ax.plot([], [], "-", color="C0", lw=1.5, label="suspended cable")[0],
            ax.plot([], [], "v", color="C1", ms=9, label="ship")[0],
            ax.plot([], [], "o", color="C2", ms=6, label="touchdown")[0],
            ax.plot([], [], "D", color="C3", ms=6, label="repeater" if has_reps else "_repeater")[0])


def _route_line(ax, ds, scale: float) -> None:
    """The route (its track with the arcs, where the result has it) and its waypoints, scaled (1e-3: km)."""
    if "route_x" in ds:
        ax.plot(ds.route_x * scale, ds.route_y * scale, "k--", lw=0.8, label="route", zorder=1)
        ax.plot(ds.waypoint_x * scale, ds.waypoint_y * scale, "ko", ms=3, zorder=1)
    else:
        ax.plot(ds.waypoint_x * scale, ds.waypoint_y * scale, "k--", lw=0.8, marker="o", ms=3, label="route", zorder=1)

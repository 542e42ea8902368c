"""Figures and animation of the tug-barge towline simulation (``towline_dynamic``, paper 003).

The figure functions follow :data:`seacable.plot.FIGURES`: ``function(ds, pyplot)`` returns a
dict ``{figure name: Figure}``; :data:`TOWLINE_FIGURES` maps ``"towline_dynamic"`` to it. The
public functions :func:`towline_tension`, :func:`towline_tracks`, :func:`towline_shape` and
:func:`towline_sway` take the result Dataset only and return one Figure each;
:func:`animate_towline` writes a GIF (or MP4) of the plan view and the elevation side by side.

The result (see the lead's ``towline`` model) has dimensions ``time`` [s], ``node`` (0..N:
node 0 the tug's tow point, node N the barge's, node j the joint between elements j-1 and j)
and ``element`` (0..N-1); the joint positions ``x``, ``y``, ``z`` [m] are NaN for joints not
yet paid out from the tug's bitt, and every figure skips them. Z is up, 0 at the still water
surface. Tensions are drawn in kN.

matplotlib is imported by the caller (:func:`seacable.plot.plot_result`) or on the first call
of a public function here, never at import.

References
----------
.. [1] Yoon, H.K., Lee, H.S., Park, J.K. and Kim, Y.K. (2011). Modeling and simulation of the
   towline dynamics using multibody element theory (in Korean). Proc. KINPR Spring Conference.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ._core import _snapshot_times, animation_writer

__all__ = ["TOWLINE_FIGURES", "animate_towline", "towline_distance", "towline_shape", "towline_sway",
           "towline_tension", "towline_tracks"]

ANALYSIS = "towline_dynamic"
_N_TRACK_SNAPSHOTS = 6  # towline drawn on the plan view at about this many times
_N_SHAPE_SNAPSHOTS = 8  # shape snapshots coloured by time
_SWAY_FRACTIONS = (0.0, 0.25, 0.5, 0.75, 1.0)  # joints of the sway figure, as fractions of N
_ZIGZAG_RATIO = 1e-3  # tug sway (peak to peak) above this fraction of the line length: a zig-zag run
_REQUIRED = ("x", "y", "z", "top_tension", "barge_tension", "tug_x", "tug_y", "barge_x", "barge_y")
_CMAP = "viridis"


# ----------------------------------------------------------------------------- helpers

def _check(ds, who: str) -> None:
    """Raise InputError unless ``ds`` is a towline_dynamic result with the variables drawn."""
    from ..errors import InputError

    found = ds.attrs.get("analysis")
    if found != ANALYSIS:
        raise InputError(f"{who} needs a '{ANALYSIS}' result, got analysis '{found}'. Suggested fix: run a "
                         f"case with analysis type {ANALYSIS}, or use seacable.plot.plot_result for the "
                         "figures of this result.")
    missing = [name for name in _REQUIRED if name not in ds]
    if missing:
        raise InputError(f"the {ANALYSIS} result lacks the variable(s) {', '.join(missing)}. Suggested fix: "
                         "rerun the case with this version of seacable, or add them to the Dataset.")
    if ds.sizes.get("time", 0) == 0:
        raise InputError("the result has no output times to draw. Suggested fix: rerun the case.")


def _pyplot():
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def _time(ds) -> tuple[np.ndarray, str]:
    return np.asarray(ds.time.values, dtype=float), ds.time.attrs.get("units", "s")


def _note(ds, time, unit) -> str:
    interrupted = bool(int(ds.attrs.get("interrupted", 0) or 0))
    return f" (interrupted at t = {time[-1]:g} {unit})" if interrupted and time.size else ""


def _every(step: float, snaps, unit: str) -> str:
    if step:
        return f"every {step:g} {unit}"
    return f"at t = {snaps[0]:g} {unit}" if snaps.size == 1 else f"at {snaps.size} times"


def _snapshots(time, n: int):
    """(step, snapshot times, their indices in ``time``): see :func:`seacable.plot._snapshot_times`."""
    step, snaps = _snapshot_times(time, n)
    return step, snaps, np.searchsorted(time, snaps)


def _finite(a, b):
    """The points of two rows where both are defined (joints not paid out are NaN)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    keep = np.isfinite(a) & np.isfinite(b)
    return a[keep], b[keep]


def _arrays(ds):
    """x, y, z (time, node) and the tug tow point (time,) as float arrays. [m]"""
    return (np.asarray(ds.x.values, dtype=float), np.asarray(ds.y.values, dtype=float),
            np.asarray(ds.z.values, dtype=float), np.asarray(ds.tug_x.values, dtype=float),
            np.asarray(ds.tug_y.values, dtype=float))


def towline_distance(ds) -> np.ndarray:
    """Horizontal distance of each joint from the tug's tow point, sqrt((x - x_tug)² + (y - y_tug)²).

    Parameters
    ----------
    ds : xarray.Dataset
        A ``towline_dynamic`` result.

    Returns
    -------
    numpy.ndarray
        Shape (time, node); NaN where the joint is not paid out. [m]
    """
    x, y, _, tx, ty = _arrays(ds)
    return np.hypot(x - tx[:, None], y - ty[:, None])


def _line_length(ds) -> float:
    """Unstretched towline length n_elements × element_length, or the N of the node dimension. [m]"""
    n = int(ds.attrs.get("n_elements", ds.sizes["node"] - 1))
    return float(ds.attrs.get("element_length", 1.0)) * n


def _sway_amplitude(y) -> np.ndarray:
    """Half the peak-to-peak y over the second half of the record (the first half holds the start).

    Parameters
    ----------
    y
        Sway, shape (time, ...). [m]

    Returns
    -------
    numpy.ndarray
        Amplitude per joint; NaN for a joint never paid out in that window. [m]
    """
    y = np.asarray(y, dtype=float)
    window = y[y.shape[0] // 2:] if y.shape[0] >= 4 else y
    ok = np.isfinite(window).any(axis=0)
    out = np.full(window.shape[1:], np.nan)
    out[ok] = 0.5 * (np.nanmax(window[:, ok], axis=0) - np.nanmin(window[:, ok], axis=0))
    return out


def _is_zigzag(ds) -> bool:
    """True when the tug sways off its mean course by more than 0.1 % of the line length (peak to peak).

    The mean course is the principal direction of the tug's track; the sway is the track's
    distance from it.
    """
    pts = np.column_stack([np.asarray(ds.tug_x.values, float), np.asarray(ds.tug_y.values, float)])
    pts = pts[np.isfinite(pts).all(axis=1)]
    if pts.shape[0] < 3:
        return False
    pts = pts - pts.mean(axis=0)
    _, _, vt = np.linalg.svd(pts, full_matrices=False)
    lateral = pts @ vt[-1]
    return bool(np.ptp(lateral) > _ZIGZAG_RATIO * _line_length(ds))


def _sway_nodes(n_nodes: int) -> np.ndarray:
    """Node indices at the tug, 1/4, 1/2, 3/4 of the line and the barge (rounded, no repeats)."""
    n = n_nodes - 1
    return np.unique(np.round(np.asarray(_SWAY_FRACTIONS) * n).astype(int))


def _title(fig, ds) -> None:
    fig.suptitle(ds.attrs.get("title", ""), fontsize=10)


# ----------------------------------------------------------------------------- figures

def _tension(ds, plt):
    time, unit = _time(ds)
    mark = "o-" if time.size == 1 else "-"
    has_speed = "barge_speed" in ds
    fig, axes = plt.subplots(2 if has_speed else 1, 1, figsize=(8, 6 if has_speed else 4.2), sharex=True,
                             squeeze=False)
    ax1 = axes[0, 0]
    ax1.plot(time, np.asarray(ds.top_tension.values, float) / 1e3, mark, color="C0", label="at the tug")
    ax1.plot(time, np.asarray(ds.barge_tension.values, float) / 1e3, mark, color="C3", label="at the barge")
    ax1.set(ylabel="towline tension [kN]", title="Towline tension at the tow points" + _note(ds, time, unit))
    ax1.legend(fontsize=8)
    if has_speed:
        axes[1, 0].plot(time, np.asarray(ds.barge_speed.values, float), mark, color="C2", label="barge")
        axes[1, 0].set(ylabel="barge speed [m/s]")
    axes[-1, 0].set_xlabel(f"time [{unit}]")
    _title(fig, ds)
    return fig


def _tracks(ds, plt):
    from matplotlib import colormaps

    time, unit = _time(ds)
    x, y, _, tx, ty = _arrays(ds)
    step, snaps, idx = _snapshots(time, _N_TRACK_SNAPSHOTS)
    colours = colormaps[_CMAP](np.linspace(0.0, 0.9, snaps.size))
    mark = "o-" if time.size == 1 else "-"
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.plot(tx, ty, mark, color="k", lw=1.2, label="tug tow point")
    ax.plot(np.asarray(ds.barge_x.values, float), np.asarray(ds.barge_y.values, float), mark.replace("-", "--"),
            color="0.4", lw=1.2, label="barge midship")
    bx, by = np.asarray(ds.barge_x.values, float), np.asarray(ds.barge_y.values, float)
    for i, t, c in zip(idx, snaps, colours):
        ax.plot(*_finite(x[i], y[i]), "o-", color=c, ms=2.5, lw=1.2, label=f"towline, t = {t:g} {unit}")
        ax.plot([tx[i]], [ty[i]], "^", color=c, ms=7, label="_nolegend_")
        ax.plot([bx[i]], [by[i]], "s", color=c, ms=6, label="_nolegend_")
    ax.plot([], [], "k^", ms=7, label="tug at the snapshot")
    ax.plot([], [], "ks", ms=6, label="barge at the snapshot")
    ax.set(xlabel="x [m]", ylabel="y [m]",
           title=f"Tracks, towline {_every(step, snaps, unit)}" + _note(ds, time, unit))
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    _title(fig, ds)
    return fig


def _shape(ds, plt):
    from matplotlib import colormaps
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import Normalize

    time, unit = _time(ds)
    x, y, z, tx, ty = _arrays(ds)
    h = towline_distance(ds)
    step, snaps, idx = _snapshots(time, _N_SHAPE_SNAPSHOTS)
    norm = Normalize(vmin=time[0], vmax=time[-1] if time[-1] > time[0] else time[0] + 1.0)
    cmap = colormaps[_CMAP]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.5))
    ax1.axhline(0.0, color="steelblue", lw=0.8, ls="--", label="water surface", zorder=1)
    for i, t in zip(idx, snaps):
        c = cmap(norm(t))
        ax1.plot(*_finite(h[i], z[i]), "o-", color=c, ms=2.5, lw=1.2, label=f"t = {t:g} {unit}")
        ax2.plot(*_finite(x[i] - tx[i], y[i] - ty[i]), "o-", color=c, ms=2.5, lw=1.2, label=f"t = {t:g} {unit}")
    ax1.set(xlabel="horizontal distance from the tug's tow point [m]", ylabel="z (0 at the water surface) [m]",
            title=f"Elevation {_every(step, snaps, unit)}" + _note(ds, time, unit))
    ax1.legend(handles=[ax1.get_lines()[0]], fontsize=8, loc="best")
    ax2.axhline(0.0, color="0.6", lw=0.6, zorder=0)
    ax2.plot([0.0], [0.0], "^", color="k", ms=7, label="tug tow point")
    ax2.set(xlabel="x - x_tug [m]", ylabel="y - y_tug [m]", title="Plan view relative to the tug")
    ax2.legend(handles=[ax2.get_lines()[-1]], fontsize=8, loc="best")
    bar = fig.colorbar(ScalarMappable(norm=norm, cmap=cmap), ax=ax2, pad=0.02)  # one axes: tight_layout works
    bar.set_label(f"time [{unit}]")
    _title(fig, ds)
    return fig


def _sway(ds, plt):
    time, unit = _time(ds)
    y = np.asarray(ds.y.values, dtype=float)
    nodes = _sway_nodes(ds.sizes["node"])
    amplitude = _sway_amplitude(y[:, nodes])
    length = float(ds.attrs.get("element_length", np.nan))
    n = ds.sizes["node"] - 1
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for k, (j, a) in enumerate(zip(nodes, amplitude)):
        where = ("tug, " if j == 0 else "barge, " if j == n else
                 f"s = {j * length:.0f} m, " if np.isfinite(length) else "")
        amp = f"amplitude {a:.2f} m" if np.isfinite(a) else "not paid out"
        ax.plot(time, y[:, j], "-", color=f"C{k}", lw=1.2, label=f"node {j} ({where}{amp})")
    ax.set(xlabel=f"time [{unit}]", ylabel="sway y [m]", title="Sway along the towline" + _note(ds, time, unit))
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0),
              title="amplitude: half the range\nover the second half", title_fontsize=8)
    _title(fig, ds)
    return fig


def _towline_dynamic(ds, plt):
    """All standard figures of a towline_dynamic result; the sway one only for a zig-zag run."""
    _check(ds, "the towline figures")
    figs = {"tension": _tension(ds, plt), "tracks": _tracks(ds, plt), "shape": _shape(ds, plt)}
    if _is_zigzag(ds):
        figs["sway"] = _sway(ds, plt)
    return figs


#: analysis type -> function(ds, pyplot) -> {figure name: Figure}; merged into seacable.plot.FIGURES
TOWLINE_FIGURES = {ANALYSIS: _towline_dynamic}


def towline_tension(ds):
    """Towline tension at the tug's and the barge's tow points against time, in kN.

    Parameters
    ----------
    ds : xarray.Dataset
        A ``towline_dynamic`` result.

    Returns
    -------
    matplotlib.figure.Figure
        Two curves (``top_tension``, ``barge_tension``) in kN; below them the barge speed
        [m/s] when the result holds ``barge_speed``. Titled with ``ds.attrs["title"]``.

    Raises
    ------
    InputError
        The result is not a ``towline_dynamic`` one, lacks a variable drawn, or has no times.
    """
    _check(ds, "towline_tension")
    return _tension(ds, _pyplot())


def towline_tracks(ds):
    """Plan view of the tug and barge tracks with the towline at about six times.

    The towline snapshots are taken every N s, N a round number (see
    :func:`seacable.plot._snapshot_times`), joints not yet paid out skipped; equal aspect.

    Parameters
    ----------
    ds : xarray.Dataset
        A ``towline_dynamic`` result.

    Returns
    -------
    matplotlib.figure.Figure
        The tug tow-point track, the barge midship track and the joint positions (x, y) [m]
        at the snapshot times, coloured by time.

    Raises
    ------
    InputError
        The result is not a ``towline_dynamic`` one, lacks a variable drawn, or has no times.
    """
    _check(ds, "towline_tracks")
    return _tracks(ds, _pyplot())


def towline_shape(ds):
    """Towline shape at about eight times, in elevation and in plan relative to the tug.

    Left: z against the horizontal distance of each joint from the tug's tow point (see
    :func:`towline_distance`), with the water surface z = 0. Right: (x - x_tug, y - y_tug).
    The curves are coloured by time, with a colour bar.

    Parameters
    ----------
    ds : xarray.Dataset
        A ``towline_dynamic`` result.

    Returns
    -------
    matplotlib.figure.Figure
        Two panels and a colour bar of time [s].

    Raises
    ------
    InputError
        The result is not a ``towline_dynamic`` one, lacks a variable drawn, or has no times.
    """
    _check(ds, "towline_shape")
    return _shape(ds, _pyplot())


def towline_sway(ds):
    """Sway y against time of the joints at the tug, 1/4, 1/2, 3/4 of the line and the barge.

    For a tug zig-zag (paper 003: 10 m amplitude, 50 s period) the sway amplitude falls away
    from the tug. Each curve's legend gives its amplitude, half the peak-to-peak y over the
    second half of the record (the first half holds the start-up transient).

    Parameters
    ----------
    ds : xarray.Dataset
        A ``towline_dynamic`` result.

    Returns
    -------
    matplotlib.figure.Figure
        One curve per joint (node round(k N / 4), k = 0..4), y [m] against time [s].

    Raises
    ------
    InputError
        The result is not a ``towline_dynamic`` one, lacks a variable drawn, or has no times.
    """
    _check(ds, "towline_sway")
    return _sway(ds, _pyplot())


# ----------------------------------------------------------------------------- animation

def _plan_box(ds, x, y):
    """Plan-view limits: one fixed box when the run is compact, else a box that follows the line.

    Returns ``(fixed, half)``: ``fixed`` the (x0, x1, y0, y1) covering the tracks and every
    joint, or None when the run spans more than 3 line lengths; ``half`` the half-size of the
    moving box, 0.7 line lengths (the line, half a barge and a margin about their centre). [m]
    """
    bx, by = np.asarray(ds.barge_x.values, float), np.asarray(ds.barge_y.values, float)
    tx, ty = np.asarray(ds.tug_x.values, float), np.asarray(ds.tug_y.values, float)
    ax_ = np.concatenate([x.ravel(), bx, tx])
    ay_ = np.concatenate([y.ravel(), by, ty])
    ax_, ay_ = _finite(ax_, ay_)
    length = max(_line_length(ds), 1.0)
    if ax_.size == 0:
        return (-length, length, -length, length), length
    span = max(np.ptp(ax_), np.ptp(ay_))
    pad = 0.05 * span + 0.05 * length
    half = 0.7 * length
    if span <= 3.0 * length:
        return (ax_.min() - pad, ax_.max() + pad, ay_.min() - pad, ay_.max() + pad), half
    return None, half


def _fit_box(ax, x0, x1, y0, y1) -> None:
    """Set limits holding [x0, x1] x [y0, y1] whose shape is that of the axes (equal scales in x and y)."""
    fig = ax.figure
    pos = ax.get_position()
    ratio = (pos.width * fig.get_figwidth()) / max(pos.height * fig.get_figheight(), 1e-9)  # width / height
    dx, dy = max(x1 - x0, 1e-9), max(y1 - y0, 1e-9)
    if dx / dy < ratio:
        grow = 0.5 * (dy * ratio - dx)
        x0, x1 = x0 - grow, x1 + grow
    else:
        grow = 0.5 * (dx / ratio - dy)
        y0, y1 = y0 - grow, y1 + grow
    ax.set(xlim=(x0, x1), ylim=(y0, y1))


def animate_towline(ds, path, *, fps: int = 10, max_frames: int = 200, dpi: int = 100) -> Path:
    """Write an animation of a towline run (``towline_dynamic`` result) as GIF or MP4.

    Each frame shows, left, the plan view: the tug and barge tracks up to the frame's time, the
    towline joints (those paid out; slack joints as open circles when ``slack`` is stored), the
    tug's tow point and the barge midship; right, the elevation: z against the horizontal
    distance from the tug's tow point, with the water surface. The output times are subsampled
    evenly, first and last kept, to at most ``max_frames`` frames. The plan view keeps one
    frame of reference when the run spans at most three line lengths, else it follows the line.

    Parameters
    ----------
    ds : xarray.Dataset
        A ``towline_dynamic`` result, from :func:`seacable.run` or
        :func:`seacable.results.read_netcdf`.
    path
        Output file; ``.gif`` (written with Pillow) or ``.mp4`` (needs ffmpeg on the PATH).
    fps
        Frames per second of the animation. [1/s]
    max_frames
        Largest number of frames; the animation has min(max_frames, number of output times).
    dpi
        Resolution of the frames (the figure is 12 x 4.5 in). [1/in]

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    InputError
        The result is not a ``towline_dynamic`` one or lacks a variable drawn, the suffix is
        neither ``.gif`` nor ``.mp4``, ``.mp4`` was asked for without ffmpeg, or fps,
        max_frames or dpi is not positive.
    """
    _check(ds, "animate_towline")
    path, writer, frames, plt = animation_writer(path, fps, max_frames, dpi, ds.sizes["time"])

    time, unit = _time(ds)
    x, y, z, tx, ty = _arrays(ds)
    h = towline_distance(ds)
    bx, by = np.asarray(ds.barge_x.values, float), np.asarray(ds.barge_y.values, float)
    slack = np.asarray(ds.slack.values, dtype=bool) if "slack" in ds else np.zeros(x.shape, dtype=bool)
    fixed, half = _plan_box(ds, x, y)

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.5), gridspec_kw={"width_ratios": [1.2, 1.0]})
    tug_track, = ax1.plot([], [], "-", color="k", lw=0.8, label="tug track")
    barge_track, = ax1.plot([], [], "--", color="0.4", lw=0.8, label="barge track")
    plan, = ax1.plot([], [], "o-", color="C0", ms=3, lw=1.5, label="towline")
    plan_slack, = ax1.plot([], [], "o", mfc="white", mec="C3", ms=5, label="slack joint")
    tug, = ax1.plot([], [], "^", color="k", ms=8, label="tug tow point")
    barge, = ax1.plot([], [], "s", color="0.4", ms=8, label="barge midship")
    ax1.set(xlabel="x [m]", ylabel="y [m]", title="Plan view")
    ax1.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=3)

    hh, zz = _finite(h.ravel(), z.ravel())
    h1 = float(hh.max()) if hh.size else 1.0
    z0, z1 = (min(float(zz.min()), 0.0), max(float(zz.max()), 0.0)) if zz.size else (-1.0, 1.0)
    zpad = 0.15 * (z1 - z0) or 1.0
    ax2.axhline(0.0, color="steelblue", lw=0.8, ls="--", label="water surface")
    side, = ax2.plot([], [], "o-", color="C0", ms=3, lw=1.5, label="towline")
    side_slack, = ax2.plot([], [], "o", mfc="white", mec="C3", ms=5)
    ax2.set(xlim=(-0.03 * h1, 1.05 * h1), ylim=(z0 - zpad, z1 + zpad),
            xlabel="horizontal distance from the tug's tow point [m]", ylabel="z (0 at the water surface) [m]",
            title="Elevation")
    ax2.legend(fontsize=7, loc="upper center")
    label = ax1.text(0.01, 0.97, "", transform=ax1.transAxes, va="top", fontsize=10)
    fig.suptitle(ds.attrs.get("title", "Towline"), fontsize=10)
    fig.tight_layout()
    if fixed is not None:  # after the layout, which sets the axes' shape: equal scales, all data in
        _fit_box(ax1, *fixed)
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        with writer.saving(fig, str(path), dpi):
            for i in frames:
                tug_track.set_data(tx[:i + 1], ty[:i + 1])
                barge_track.set_data(bx[:i + 1], by[:i + 1])
                plan.set_data(*_finite(x[i], y[i]))
                plan_slack.set_data(*_finite(x[i][slack[i]], y[i][slack[i]]))
                tug.set_data([tx[i]], [ty[i]])
                barge.set_data([bx[i]], [by[i]])
                side.set_data(*_finite(h[i], z[i]))
                side_slack.set_data(*_finite(h[i][slack[i]], z[i][slack[i]]))
                if fixed is None:  # follow the line: a box of fixed size about its centre
                    cx, cy = _finite(np.r_[x[i], bx[i], tx[i]], np.r_[y[i], by[i], ty[i]])
                    mx, my = 0.5 * (cx.min() + cx.max()), 0.5 * (cy.min() + cy.max())
                    _fit_box(ax1, mx - half, mx + half, my - half, my + half)
                label.set_text(f"t = {time[i]:.1f} {unit}")
                writer.grab_frame()
    finally:
        plt.close(fig)
    return path

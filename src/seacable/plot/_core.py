"""Shared pieces of the figures: axis labels, snapshot times, notes and the animation writer.

Every figure module of :mod:`seacable.plot` imports from here; this module imports none of them.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

__all__ = ["animation_writer", "figures_of"]


def _label(da) -> str:
    units = da.attrs.get("units", "")
    units = "deg" if units == "degree" else units.replace(" m-1", "/m").replace("m s-1", "m/s")
    name = da.attrs.get("long_name", da.name)
    return f"{name} [{units}]" if units and units != "1" else str(name)


def _degrees(da):
    """An angle variable's values in degrees, for a figure: results hold angles in rad (older files: degree)."""
    values = np.asarray(da, dtype=float)
    return values if da.attrs.get("units", "rad") in ("degree", "deg") else np.degrees(values)


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


def _interrupted_note(ds, time, t_unit) -> str:
    interrupted = bool(int(ds.attrs.get("interrupted", 0) or 0))
    return f" (interrupted at t = {time[-1]:g} {t_unit})" if interrupted and time.size else ""


def _finite_xz(x, z):
    """The points of a NaN-padded (x, z) row that are defined."""
    x, z = np.asarray(x, dtype=float), np.asarray(z, dtype=float)
    keep = np.isfinite(x) & np.isfinite(z)
    return x[keep], z[keep]


def _atomic_writer(base):
    """A matplotlib movie writer class whose ``saving`` writes the file whole (temporary file, rename)."""
    import contextlib

    from .._atomic import atomic_path

    class AtomicWriter(base):
        @contextlib.contextmanager
        def saving(self, fig, outfile, dpi, *args, **kwargs):
            with atomic_path(outfile) as tmp, super().saving(fig, str(tmp), dpi, *args, **kwargs):
                yield self

    AtomicWriter.__name__ = AtomicWriter.__qualname__ = f"Atomic{base.__name__}"
    return AtomicWriter


def animation_writer(path, fps, max_frames, dpi, n_times):
    """Check an animation's arguments; return (path, writer, frame indices, pyplot).

    ``.gif`` is written with Pillow, ``.mp4`` with ffmpeg; the ``n_times`` output times are subsampled
    evenly, first and last kept, to at most ``max_frames`` frames.
    """
    from .._validate import positive
    from ..errors import InputError

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
        writer = _atomic_writer(FFMpegWriter)(fps=fps)
    else:
        writer = _atomic_writer(PillowWriter)(fps=fps)
    n = min(max_frames, n_times)
    frames = [n_times - 1] if n == 1 else np.round(np.linspace(0, n_times - 1, n)).astype(int)
    return path, writer, frames, plt




def figures_of(ds, analysis: str, table: dict) -> list:
    """The figures of ``table[analysis]`` for a result of that analysis (a model's public ``plot_*``).

    Raises
    ------
    InputError
        The result is of another analysis.
    """
    from ..errors import InputError

    found = ds.attrs.get("analysis")
    if found != analysis:
        raise InputError(f"plot_{analysis} needs a '{analysis}' result, got analysis '{found}'. "
                         f"Suggested fix: run a case with analysis type {analysis}, or use "
                         "seacable.plot.plot_result for the figures of this result.")
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return list(table[analysis](ds, plt).values())

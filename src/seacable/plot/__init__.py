"""Standard figures of each analysis, written as PNG, and animations of a lay or a tow.

matplotlib is imported when a plot is made, not when seacable is imported, and
uses the non-interactive Agg backend so that plots work on machines without a
screen. One module per model (:mod:`.statics`, :mod:`.towed`, :mod:`.laying`,
:mod:`.mooring`, :mod:`.towline`, :mod:`.sweep`, :mod:`.system`) registers its figures; they
share :mod:`._core` and never import each other.
"""

from __future__ import annotations

from pathlib import Path

from ._core import animation_writer
from .laying import LAYING_FIGURES, animate_laying
from .mooring import MOORING_FIGURES, plot_mooring_dynamic, plot_mooring_pushover, plot_mooring_static
from .statics import STATICS_FIGURES
from .sweep import SWEEP_FIGURES
from .system import SYSTEM_FIGURES, plot_system_dynamic, plot_system_offsets, plot_system_static
from .towed import TOWED_FIGURES
from .towline import (
    TOWLINE_FIGURES,
    animate_towline,
    towline_distance,
    towline_shape,
    towline_sway,
    towline_tension,
    towline_tracks,
)

__all__ = [
    "FIGURES",
    "animate_laying",
    "animate_towline",
    "animation_writer",
    "plot_mooring_dynamic",
    "plot_mooring_pushover",
    "plot_mooring_static",
    "plot_result",
    "plot_system_dynamic",
    "plot_system_offsets",
    "plot_system_static",
    "towline_distance",
    "towline_shape",
    "towline_sway",
    "towline_tension",
    "towline_tracks",
]

#: analysis type -> function(ds, pyplot) -> {figure name: Figure}
FIGURES = {**STATICS_FIGURES, **TOWED_FIGURES, **LAYING_FIGURES, **MOORING_FIGURES, **TOWLINE_FIGURES,
           **SWEEP_FIGURES, **SYSTEM_FIGURES}


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

    from .._atomic import atomic_path
    from ..errors import InputError
    from ..results import check_result

    analysis = ds.attrs.get("analysis")
    if analysis not in FIGURES:
        raise InputError(f"no standard figures for analysis '{analysis}'. Known: {', '.join(FIGURES)}. "
                         "Suggested fix: give a result written by 'seacable run' or 'seacable sweep'.")
    check_result(ds)  # every variable the figures draw, named if missing
    outdir = Path(outdir)
    try:
        outdir.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise InputError(f"cannot create the plot folder '{outdir}': {err.strerror or err}. Suggested fix: "
                         "give a folder you can write to.") from None
    prefix = prefix or ds.attrs.get("case_name", analysis)
    written = []
    figures = FIGURES[analysis](ds, plt)
    try:
        for name, fig in figures.items():
            fig.suptitle(ds.attrs.get("title", ""), fontsize=10)
            fig.tight_layout()
            path = outdir / f"{prefix}_{name}.png"
            try:  # whole or not at all: an interrupted write leaves the previous figure
                with atomic_path(path) as tmp:
                    fig.savefig(tmp, dpi=110, format="png")
            except OSError as err:
                raise InputError(f"cannot write the figure '{path}': {err.strerror or err}. Suggested fix: "
                                 "free disk space, or give a plot folder you can write to.") from None
            written.append(path)
    finally:
        for fig in figures.values():
            plt.close(fig)
    return written



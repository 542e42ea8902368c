"""Parameter sweeps and design load cases: a base case run over a grid or a table of parameters.

:func:`sweep` runs every case as a ``dask.distributed`` task (a local cluster by default, or an
existing scheduler), writes each result as it finishes and a summary of per-case design figures,
and resumes an interrupted sweep. See :mod:`seacable.sweeps.spec` for the sweep file.

The names are imported on first use (:mod:`seacable._lazy`): reading a sweep file, or asking
whether a file is one, does not import xarray or Dask.
"""

from typing import TYPE_CHECKING

from .._lazy import lazy_names

if TYPE_CHECKING:
    from .engine import SweepProgress, run_case, summary_dataset, sweep, work_estimate
    from .spec import Range, Sweep, SweepCase, SweepFile, is_sweep_file, load_sweep, parse_path

__all__ = ["Range", "Sweep", "SweepCase", "SweepFile", "SweepProgress", "is_sweep_file", "load_sweep", "parse_path",
           "run_case", "summary_dataset", "sweep", "work_estimate"]

__getattr__, __dir__ = lazy_names(__name__, {
    ".engine": ("SweepProgress", "run_case", "summary_dataset", "sweep", "work_estimate"),
    ".spec": ("Range", "Sweep", "SweepCase", "SweepFile", "is_sweep_file", "load_sweep", "parse_path"),
})

"""Parameter sweeps and design load cases: a base case run over a grid or a table of parameters.

:func:`sweep` runs every case as a ``dask.distributed`` task (a local cluster by default, or an
existing scheduler), writes each result as it finishes and a summary of per-case design figures,
and resumes an interrupted sweep. See :mod:`seacable.sweeps.spec` for the sweep file.
"""

from .engine import SweepProgress, run_case, summary_dataset, sweep, work_estimate
from .spec import Range, Sweep, SweepCase, SweepFile, is_sweep_file, load_sweep, parse_path

__all__ = ["Range", "Sweep", "SweepCase", "SweepFile", "SweepProgress", "is_sweep_file", "load_sweep", "parse_path",
           "run_case", "summary_dataset", "sweep", "work_estimate"]

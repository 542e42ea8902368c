"""The dispatch from an analysis type to its runner, and nothing else.

:func:`run` is a pure function of its :class:`~seacable.case.Case`: the same case
gives the same Dataset, and a case can be pickled and sent to another process.
:func:`check` does everything :func:`run` does before its time loop (every check
of the inputs, the geometry and the size of the run), so that ``seacable validate``
rejects exactly what ``seacable run`` would reject before it starts computing.
"""

from __future__ import annotations

from importlib import import_module

from .case import Case
from .errors import InputError
from .io.moordyn import MoorDynCase
from .system.case import SystemCase

__all__ = ["STREAMED", "check", "run", "streams"]

#: analysis type -> (module, runner, check). The check is what the runner calls first: every check of the
#: inputs and, for an analysis without a time loop that is cheap to solve (the static and modal ones), the
#: solve itself, without the Dataset (no xarray); for a time-domain or mooring-system analysis, every check
#: before its time loop or its equilibrium solves.
_ANALYSES = {
    "static": ("seacable.statics.run", "run_static", "solve_static"),
    "pushover": ("seacable.statics.run", "run_pushover", "solve_pushover"),
    "towed_steady": ("seacable.statics.run", "run_towed_steady", "solve_towed_steady"),
    "laying_theory": ("seacable.statics.run", "run_laying_theory", "solve_laying_theory"),
    "modal": ("seacable.modal.run", "run_modal", "solve_modal"),
    "vertical_modes": ("seacable.modal.run", "run_vertical_modes", "solve_vertical_modes"),
    "mooring_static": ("seacable.mooring.run", "run_mooring_static", "solve_mooring_static"),
    "mooring_pushover": ("seacable.mooring.run", "run_mooring_pushover", "solve_mooring_pushover"),
    "towed_dynamic": ("seacable.towed.run", "run_towed_dynamic", "prepare_towed_dynamic"),
    "laying_dynamic": ("seacable.laying.run", "run_laying_dynamic", "prepare_laying_dynamic"),
    "lay_plan": ("seacable.laying.plan_run", "run_lay_plan", None),
    "mooring_dynamic": ("seacable.mooring.run", "run_mooring_dynamic", "prepare_mooring_dynamic"),
    "towline_dynamic": ("seacable.towline.run", "run_towline_dynamic", "prepare_towline_dynamic"),
    "system_static": ("seacable.system.run", "run_system_static", "prepare_system_static"),
    "system_offsets": ("seacable.system.run", "run_system_offsets", "prepare_system_offsets"),
    "system_dynamic": ("seacable.system.dynamics", "run_system_dynamic", "prepare_system_dynamic"),
}
#: an analysis type's other route (``coupling`` of system_dynamic) -> its runner and check, as in ``_ANALYSES``
_ROUTES = {
    ("system_dynamic", "uncoupled"): ("seacable.system.uncoupled", "run_system_uncoupled", "prepare_system_uncoupled"),
}

TIME_DOMAIN = ("towed_dynamic", "laying_dynamic", "mooring_dynamic", "towline_dynamic", "system_dynamic")
"""The analyses with a time loop: they take a ``progress`` callback and can be interrupted."""


STREAMED = ("mooring_dynamic",)
"""The analyses that write their outputs into the result file as they are computed (:mod:`seacable.sink`),
as MoorDyn decks of lines and points do."""


def streams(case) -> bool:
    """Whether :func:`run` writes ``case``'s outputs into its ``out`` file as they are computed: a case of
    :data:`STREAMED`, or a MoorDyn deck of lines and points with a duration."""
    if isinstance(case, MoorDynCase):
        return not case.has_structures and case.duration is not None
    return isinstance(case, Case) and case.analysis.type in STREAMED


def _case(case) -> Case | SystemCase:
    if not isinstance(case, (Case, SystemCase)):
        raise InputError(f"run() takes a seacable.Case or a seacable.SystemCase, got {type(case).__name__}. "
                         "Suggested fix: seacable.load_case('file.yaml') or seacable.Case(...).")
    return case


def _entry(case) -> tuple:
    """The (module, runner, check) of a case's analysis: its type's, or its route's (``coupling``)."""
    a = case.analysis
    return _ROUTES.get((a.type, getattr(a, "coupling", None)), _ANALYSES[a.type])


def run(case: Case, progress=None, out=None):
    """Run a case and return its result.

    Parameters
    ----------
    case
        A validated case, from :func:`seacable.load_case` or built in code.
    progress
        Optional ``progress(t, duration)`` callback of time-domain analyses, called as the
        simulation advances (the CLI prints a progress line with it). [s]
    out
        Optional NetCDF file (``.nc``) the result is written to (atomically: a temporary file renamed
        into place). The analyses of :data:`STREAMED` write their outputs into it as they are
        computed, so that a long run needs the memory of a block of outputs, not of the whole result,
        and return the Dataset read lazily from the file; the others write their result once it is
        complete (:func:`seacable.results.write_netcdf`).

    Returns
    -------
    xarray.Dataset
        Labelled result with units, long names and provenance; its ``analysis``
        attribute names the analysis type.
    """
    if isinstance(case, MoorDynCase) and case.has_structures:  # bodies or rods: the system analyses
        case = case.system_case()
    elif isinstance(case, MoorDynCase):  # a MoorDyn network of lines and points
        from .mooring.moordyn import run_moordyn_case

        return run_moordyn_case(case, progress=progress, out=out)
    kind = _case(case).analysis.type
    module, runner, _ = _entry(case)
    runner = getattr(import_module(module), runner)
    options = {"progress": progress} if progress is not None and kind in TIME_DOMAIN else {}
    if out is not None and kind in STREAMED:
        return runner(case, out=out, **options)
    ds = runner(case, **options)
    if out is not None:
        from .results import write_netcdf

        write_netcdf(ds, out)
    return ds


def check(case: Case) -> None:
    """Do everything :func:`run` does before its time loop, and raise what it would raise.

    A static or modal analysis is solved (it is cheap, and a line that cannot reach its fairlead
    is only found by solving) by the very function its runner calls first, which builds no Dataset
    (``_ANALYSES``); a ``lay_plan`` is run whole; a time-domain analysis builds its model, checks its geometry,
    strains and size, and stops before the first time step; a mooring-system analysis
    (``system_static``, ``system_offsets``) makes every check before its equilibrium solves.

    Raises
    ------
    InputError, NoSolutionError, ConvergenceError
        As :func:`run` would, before its time loop.
    """
    if isinstance(case, MoorDynCase) and case.has_structures:
        case = case.system_case()
    elif isinstance(case, MoorDynCase):
        from .mooring.moordyn import prepare_moordyn

        prepare_moordyn(case)
        return
    module, runner, prepare = _entry(_case(case))
    getattr(import_module(module), prepare or runner)(case)

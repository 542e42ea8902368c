"""seacable: statics and dynamics of marine cables.

Explicit re-exports only. The physics lives in functions in
:mod:`seacable.statics` and :mod:`seacable.modal`; the data model
(:class:`LineType`, :class:`Line`, :class:`Environment`, :class:`Case`) wires
them through :func:`run`.

``import seacable`` is quick: every name below but the version and the errors is
imported when it is first used (PEP 562, :mod:`seacable._lazy`), so that the
command line, a case file check or a plain function of the physics do not pay
for numba, xarray, SciPy's solvers, Dask or matplotlib. ``from seacable import
Case`` and ``seacable.Case`` work as plain imports did; type checkers and IDEs
read the imports of the ``TYPE_CHECKING`` block, which name the same objects as
the table at the end (a test checks it). numba's cache of the kernels is keyed
before any kernel is defined by :mod:`seacable._jit`, where every kernel module
takes its ``njit`` from.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ._lazy import lazy_names
from ._version import __version__
from .errors import (
    CaseFileError,
    ConvergenceError,
    InputError,
    NoSolutionError,
    SeacableError,
    SeacableWarning,
)

if TYPE_CHECKING:
    from . import modal, statics
    from .bathymetry import BathymetryGrid
    from .case import (
        Case,
        LayingDynamicAnalysis,
        LayingTheoryAnalysis,
        LayPlanAnalysis,
        ModalAnalysis,
        MooringDynamicAnalysis,
        MooringPushoverAnalysis,
        MooringStaticAnalysis,
        PushoverAnalysis,
        SeabedContact,
        StaticAnalysis,
        TowedBody,
        TowedDynamicAnalysis,
        TowedSteadyAnalysis,
        VerticalModesAnalysis,
    )
    from .coupling import Coupling
    from .environment import Current, Environment, Seabed, Waves
    from .io import load_case, parse_case
    from .laying.inputs import (
        Bathymetry,
        LayTableFile,
        LayTarget,
        PayoutBottomTension,
        PayoutRate,
        PayoutSlack,
        PlanShip,
        ShipMotion,
    )
    from .laying.route import Route
    from .plot.view3d import view
    from .line import Line, LineType, PointMass, Segment
    from .mooring.motion import HarmonicMotion, PlatformMotion, RAOMotion, TimeSeriesMotion
    from .results import read_netcdf, write_netcdf
    from .run_summary import summary
    from .simulate import check, run
    from .sweeps import Range, Sweep, load_sweep, sweep
    from .system.case import SystemCase, SystemOffsetsAnalysis, SystemStaticAnalysis
    from .system.model import Body, MooringSystem, SystemLine, SystemPoint

__all__ = [
    "__version__",
    "check",
    # data model
    "LineType",
    "Segment",
    "PointMass",
    "Line",
    "Current",
    "Seabed",
    "Environment",
    "Case",
    "StaticAnalysis",
    "PushoverAnalysis",
    "ModalAnalysis",
    "TowedSteadyAnalysis",
    "TowedDynamicAnalysis",
    "TowedBody",
    "LayingTheoryAnalysis",
    "LayingDynamicAnalysis",
    "LayPlanAnalysis",
    "ShipMotion",
    "PlanShip",
    "LayTarget",
    "LayTableFile",
    "Route",
    "BathymetryGrid",
    "PayoutRate",
    "PayoutSlack",
    "PayoutBottomTension",
    "Bathymetry",
    "VerticalModesAnalysis",
    "Waves",
    "MooringStaticAnalysis",
    "MooringPushoverAnalysis",
    "MooringDynamicAnalysis",
    "SeabedContact",
    "HarmonicMotion",
    "TimeSeriesMotion",
    "PlatformMotion",
    "RAOMotion",
    # mooring systems
    "SystemCase",
    "MooringSystem",
    "SystemPoint",
    "Body",
    "SystemLine",
    "SystemStaticAnalysis",
    "SystemOffsetsAnalysis",
    # coupling to another code (MoorDyn's Init/Step/Close)
    "Coupling",
    # running
    "load_case",
    "parse_case",
    "run",
    "read_netcdf",
    "write_netcdf",
    "summary",
    # sweeps
    "Sweep",
    "Range",
    "load_sweep",
    "sweep",
    # pictures
    "view",
    # physics
    "statics",
    "modal",
    # errors
    "SeacableError",
    "InputError",
    "CaseFileError",
    "NoSolutionError",
    "ConvergenceError",
    "SeacableWarning",
]

# where each name above comes from, imported on first use
__getattr__, __dir__ = lazy_names(__name__, {
    ".case": ("Case", "LayingDynamicAnalysis", "LayingTheoryAnalysis", "LayPlanAnalysis", "ModalAnalysis",
              "MooringDynamicAnalysis", "MooringPushoverAnalysis", "MooringStaticAnalysis", "PushoverAnalysis",
              "SeabedContact", "StaticAnalysis", "TowedBody", "TowedDynamicAnalysis", "TowedSteadyAnalysis",
              "VerticalModesAnalysis"),
    ".coupling": ("Coupling",),
    ".environment": ("Current", "Environment", "Seabed", "Waves"),
    ".io": ("load_case", "parse_case"),
    ".bathymetry": ("BathymetryGrid",),
    ".laying.inputs": ("Bathymetry", "LayTableFile", "LayTarget", "PayoutBottomTension", "PayoutRate", "PayoutSlack",
                       "PlanShip", "ShipMotion"),
    ".laying.route": ("Route",),
    ".line": ("Line", "LineType", "PointMass", "Segment"),
    ".mooring.motion": ("HarmonicMotion", "PlatformMotion", "RAOMotion", "TimeSeriesMotion"),
    ".plot.view3d": ("view",),
    ".results": ("read_netcdf", "write_netcdf"),
    ".run_summary": ("summary",),
    ".simulate": ("check", "run"),
    ".sweeps": ("Range", "Sweep", "load_sweep", "sweep"),
    ".system.case": ("SystemCase", "SystemOffsetsAnalysis", "SystemStaticAnalysis"),
    ".system.model": ("Body", "MooringSystem", "SystemLine", "SystemPoint"),
}, submodules=("modal", "statics"))

"""seacable: statics and dynamics of marine cables.

Explicit re-exports only. The physics lives in functions in
:mod:`seacable.statics` and :mod:`seacable.modal`; the data model
(:class:`LineType`, :class:`Line`, :class:`Environment`, :class:`Case`) wires
them through :func:`run`.
"""

# first: numba's cache of the kernels is keyed to this source before any kernel is defined
from . import _numba_cache  # noqa: F401  isort: skip
from . import modal, statics
from ._version import __version__
from .case import (
    Case,
    LayingDynamicAnalysis,
    LayingTheoryAnalysis,
    LayPlanAnalysis,
    ModalAnalysis,
    PushoverAnalysis,
    StaticAnalysis,
    TowedBody,
    TowedDynamicAnalysis,
    TowedSteadyAnalysis,
    VerticalModesAnalysis,
    MooringStaticAnalysis,
    MooringPushoverAnalysis,
    MooringDynamicAnalysis,
    SeabedContact,
)
from .environment import Current, Environment, Seabed, Waves
from .errors import (
    CaseFileError,
    ConvergenceError,
    InputError,
    NoSolutionError,
    SeacableError,
    SeacableWarning,
)
from .io import load_case, parse_case
from .laying.bathymetry import BathymetryGrid
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
from .mooring.motion import HarmonicMotion, PlatformMotion, RAOMotion, TimeSeriesMotion
from .line import Line, LineType, PointMass, Segment
from .results import read_netcdf, write_netcdf
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
    # running
    "load_case",
    "parse_case",
    "run",
    "read_netcdf",
    "write_netcdf",
    # sweeps
    "Sweep",
    "Range",
    "load_sweep",
    "sweep",
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

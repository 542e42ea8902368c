"""Mooring systems: points, rigid bodies and lines; their statics, stiffness and dynamics.

The names are imported on first use (:mod:`seacable._lazy`): importing the data model
(:mod:`.model`) from a lower layer (the statics, the MoorDyn reader) never imports the case
layer (:mod:`seacable.case`) with it, and reading a case does not import the statics' compiled
kernels.
"""

from typing import TYPE_CHECKING

from .._lazy import lazy_names

if TYPE_CHECKING:
    from .case import SYSTEM_ANALYSES, SystemCase, SystemOffsetsAnalysis, SystemStaticAnalysis
    from .model import Body, MooringSystem, SystemLine, SystemPoint
    from .statics import SystemEquilibrium, check_statics, solve_equilibrium, system_stiffness

__all__ = ["SYSTEM_ANALYSES", "Body", "MooringSystem", "SystemCase", "SystemEquilibrium", "SystemLine",
           "SystemOffsetsAnalysis", "SystemPoint", "SystemStaticAnalysis", "check_statics", "solve_equilibrium",
           "system_stiffness"]

__getattr__, __dir__ = lazy_names(__name__, {
    ".case": ("SYSTEM_ANALYSES", "SystemCase", "SystemOffsetsAnalysis", "SystemStaticAnalysis"),
    ".model": ("Body", "MooringSystem", "SystemLine", "SystemPoint"),
    ".statics": ("SystemEquilibrium", "check_statics", "solve_equilibrium", "system_stiffness"),
})

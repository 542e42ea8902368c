"""Mooring systems: points, rigid bodies and lines; their statics, stiffness and dynamics.

The case classes (:mod:`.case`) are loaded on first use, so that importing the data model
(:mod:`.model`) from a lower layer (the statics, the MoorDyn reader) never imports the case
layer (:mod:`seacable.case`) with it.
"""

from .model import Body, MooringSystem, SystemLine, SystemPoint
from .statics import SystemEquilibrium, check_statics, solve_equilibrium, system_stiffness

__all__ = ["SYSTEM_ANALYSES", "Body", "MooringSystem", "SystemCase", "SystemEquilibrium", "SystemLine",
           "SystemOffsetsAnalysis", "SystemPoint", "SystemStaticAnalysis", "check_statics", "solve_equilibrium",
           "system_stiffness"]

_CASE_NAMES = ("SYSTEM_ANALYSES", "SystemCase", "SystemOffsetsAnalysis", "SystemStaticAnalysis")


def __getattr__(name):
    if name in _CASE_NAMES:
        from . import case

        return getattr(case, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

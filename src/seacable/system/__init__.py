"""Mooring systems: points, rigid bodies and lines; their statics, stiffness and dynamics."""

from .model import Body, MooringSystem, SystemLine, SystemPoint
from .statics import SystemEquilibrium, check_statics, solve_equilibrium, system_stiffness

__all__ = ["Body", "MooringSystem", "SystemEquilibrium", "SystemLine", "SystemPoint", "check_statics",
           "solve_equilibrium", "system_stiffness"]

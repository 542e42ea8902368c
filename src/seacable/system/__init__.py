"""Mooring systems: points, rigid bodies and lines; their statics, stiffness and dynamics."""

from .case import SYSTEM_ANALYSES, SystemCase, SystemOffsetsAnalysis, SystemStaticAnalysis
from .model import Body, MooringSystem, SystemLine, SystemPoint

__all__ = ["Body", "MooringSystem", "SYSTEM_ANALYSES", "SystemCase", "SystemLine", "SystemOffsetsAnalysis",
           "SystemPoint", "SystemStaticAnalysis"]

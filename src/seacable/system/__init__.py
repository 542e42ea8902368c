"""Mooring systems: points, rigid bodies and lines; their statics, stiffness and dynamics."""

from .model import Body, MooringSystem, SystemLine, SystemPoint

__all__ = ["Body", "MooringSystem", "SystemLine", "SystemPoint"]

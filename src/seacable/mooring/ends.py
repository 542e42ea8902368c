"""How a line's end is held in bending: pinned, clamped at a direction, or through a rotational spring.

A line with bending stiffness EI takes a moment at an end held at a direction (a hang-off, an I-tube or
J-tube exit, a bend stiffener's root): the end hinge of :func:`seacable.mooring.kernel.end_bending_loads`
between the end's given direction and the line's end element. The direction is given as OrcaFlex gives a
line end's axial direction (Orcina, *OrcaFlex help: Line theory, line end orientation*): along the line
towards end B, at ``declination`` from the upward vertical (0: straight up, pi / 2: horizontal, pi: straight
down) and ``azimuth`` from +x towards +y, both in radians as every angle of a case.
"""

from __future__ import annotations

import math
from typing import Literal

import numpy as np
from pydantic import Field, model_validator

from .._model import Model, quantity

__all__ = ["EndCondition", "end_direction"]

_DECLINATION_FIX = ("give the declination in radians from the upward vertical, 0 to pi (0 to 180 deg): "
                    "e.g. 0.1745 for a hang-off 10 deg off vertical with the line rising to it, 1.5708 for a "
                    "horizontal exit")


def end_direction(declination: float, azimuth: float) -> np.ndarray:
    """Unit vector of a line's axial direction (towards end B) at ``declination`` from the upward vertical
    and ``azimuth`` from +x towards +y: ``(sin d cos a, sin d sin a, cos d)``. [rad] -> [-]"""
    return np.array([math.sin(declination) * math.cos(azimuth), math.sin(declination) * math.sin(azimuth),
                     math.cos(declination)])


class EndCondition(Model):
    """How one end of a line with bending stiffness is held.

    ``pinned`` (the default): no moment, the end free to turn. ``clamped``: the line leaves the end along the
    direction given by ``declination`` and ``azimuth`` (towards end B, :func:`end_direction`), the moment
    ``EI kappa`` of its end element's EI. ``spring``: a rotational spring of ``stiffness`` about that
    direction between the holder and the line's end tangent (the moment ``k theta`` at the angle ``theta`` between
    them; the kernel puts it in series with the end's half element, :func:`seacable.mooring.kernel.end_bending_loads`).
    The direction is fixed in space in statics; in dynamics, at a fairlead a motion moves, it turns with the motion's
    rigid rotation (a platform's roll, pitch and yaw; :func:`seacable.mooring.run.turn_with_motion`).
    """

    type: Literal["pinned", "clamped", "spring"] = Field(
        "pinned", description="pinned (no moment), clamped at the direction, or a rotational spring about it.")
    declination: quantity("rad", ge=0.0, le=math.pi, fix=_DECLINATION_FIX) | None = Field(
        None, description="Angle of the line's direction at the end (towards end B) from the upward vertical, "
                          "0 to pi. [rad]")
    azimuth: quantity("rad") = Field(0.0, description="Azimuth of that direction from +x towards +y. [rad]")
    stiffness: quantity("N m/rad", gt=0.0, fix="give the rotational stiffness in N m/rad, e.g. 1e5.") | None = Field(
        None, description="Rotational stiffness of a spring end. [N m/rad]")

    @model_validator(mode="after")
    def _check(self):
        if self.type == "pinned":
            if self.declination is not None or self.stiffness is not None:
                raise ValueError("a pinned end takes no moment: 'declination' and 'stiffness' are not used. "
                                 "Suggested fix: set type: clamped or type: spring, or leave them out.")
            return self
        if self.declination is None:
            raise ValueError(f"a {self.type} end needs its direction: 'declination' [rad] (and 'azimuth' [rad], "
                             f"default 0). Suggested fix: {_DECLINATION_FIX}.")
        if self.type == "spring" and self.stiffness is None:
            raise ValueError("a spring end needs 'stiffness', its rotational stiffness in N m/rad. Suggested fix: "
                             "add e.g. 'stiffness: 1e5', or use type: clamped for a rigid clamp.")
        if self.type == "clamped" and self.stiffness is not None:
            raise ValueError(f"a clamped end is rigid: 'stiffness' ({self.stiffness:g} N m/rad) is not used. "
                             "Suggested fix: use type: spring for a rotational spring, or leave 'stiffness' out.")
        return self

    @property
    def holds(self) -> bool:
        """Whether the end takes a moment (clamped or spring)."""
        return self.type != "pinned"

    def hinge(self, line: int, end: int) -> tuple:
        """The network's ``end_hinges`` entry of this end of ``line`` (0: end A, 1: end B)
        (:class:`seacable.mooring.network.Network`)."""
        kind = "clamp" if self.type == "clamped" else "spring"
        return (line, end, kind, self.stiffness, end_direction(self.declination, self.azimuth))

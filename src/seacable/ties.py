"""A cable's ties to the seabed: clamps (hold-downs) and tethers, as sections of a line.

A dynamic cable's configuration is often held at a point of its length as well as at its ends:

* a :class:`Clamp` holds the node at arc length ``s`` at a point, rigidly (the node is fixed there, as an
  anchor) or through a translational spring of ``stiffness`` (the force ``-k (x - p)`` on the node): a seabed
  hold-down, the base of a steep wave;
* a :class:`Tether` is a straight elastic tie of axial stiffness ``EA`` and unstretched length ``L0`` from an
  anchor point on or above the seabed to the node at ``s``, carrying tension only::

      T = EA (l / L0 - 1)  for l > L0,  else 0     (l = |x - a|, the force -T (x - a) / l on the node)

  its submerged weight and mass, when given, lumped half at each end (the anchor's half is held there): the
  pliant wave's tether at the touchdown, the lazy-S arch's or subsea buoy's hold-down.

A lazy-S's mid-water arch or subsea buoy is a buoyant :class:`~seacable.line.PointMass` (its net buoyancy, drag
and added mass) at the arc length of a tether; the arch's saddle (the cable's curvature over its radius) is not
modelled: the cable bends over a point.

A point given without ``z`` lies on the seabed under ``(x, y)`` (the plane of the environment's depth and slope,
or its profile or grid). The finite-element line (:mod:`seacable.mooring`) puts a node at every tie's arc length; the
kernel adds their forces and exact tangents (:func:`seacable.mooring._ties.tie_loads`).

References
----------
DNV-RP-F401 (2021). Electrical power cables in subsea applications (dynamic cable configurations). Bai, Y. and
Bai, Q. (2005). Subsea Pipelines and Risers, Elsevier (flexible riser configurations: lazy wave, steep wave,
lazy-S, pliant wave).
"""

from __future__ import annotations

import math
from typing import Literal

import numpy as np
from pydantic import Field

from ._model import UNION_TAGS, Model, quantity

__all__ = ["Clamp", "SeabedPoint", "Tether", "seabed_elevation", "tie_points", "ties_of"]


class SeabedPoint(Model):
    """A point a tie holds to: ``(x, y, z)``, or on the seabed under ``(x, y)`` when ``z`` is left out. [m]"""

    x: quantity("m") = Field(description="x of the point (the line's plane is y = 0, its anchor at x = 0 by "
                                         "default). [m]")
    y: quantity("m") = Field(0.0, description="y of the point. [m]")
    z: quantity("m") | None = Field(None, description="Elevation of the point (0 at the still water level); "
                                                      "None: on the seabed under (x, y). [m]")


class Clamp(Model):
    """A clamp holding the node at arc length ``s`` at ``position``: rigid, or a translational spring.

    Parameters
    ----------
    s
        Unstretched arc length of the clamped node from end A. [m]
    position
        Where the node is held (:class:`SeabedPoint`; on the seabed when its ``z`` is left out). [m]
    stiffness
        Translational stiffness of the clamp, the same in every direction; None: rigid (the node fixed there). [N/m]
    name
        Label.
    """

    type: Literal["clamp"] = "clamp"
    s: quantity("m", ge=0, fix="give the clamp's arc length from end A in metres.") = Field(
        description="Arc length of the clamped node from end A. [m]")
    position: SeabedPoint = Field(description="Where the node is held. [m]")
    stiffness: quantity("N/m", gt=0, fix="give the clamp's translational stiffness in N/m (e.g. 1e6), or leave "
                                         "it out for a rigid clamp.") | None = Field(
        None, description="Translational stiffness; None: rigid. [N/m]")
    name: str | None = None


class Tether(Model):
    """A tension-only straight tie from ``anchor`` to the node at arc length ``s``.

    Parameters
    ----------
    s
        Unstretched arc length of the tethered node from end A. [m]
    anchor
        The tether's lower end, on or above the seabed (:class:`SeabedPoint`). [m]
    axial_stiffness
        Axial stiffness EA of the tether. [N]
    length
        Unstretched length of the tether. [m]
    weight_in_water
        Submerged weight of the whole tether, half lumped at the node (the other half at the anchor). [N]
    mass
        Mass of the whole tether, half lumped at the node. [kg]
    name
        Label.
    """

    type: Literal["tether"] = "tether"
    s: quantity("m", ge=0, fix="give the tethered node's arc length from end A in metres.") = Field(
        description="Arc length of the tethered node from end A. [m]")
    anchor: SeabedPoint = Field(description="The tether's anchor point. [m]")
    axial_stiffness: quantity("N", gt=0, fix="give the tether's axial stiffness EA in N, e.g. 5e7.") = Field(
        description="Axial stiffness EA. [N]")
    length: quantity("m", gt=0, fix="give the tether's unstretched length in metres, e.g. 10.0.") = Field(
        description="Unstretched length. [m]")
    weight_in_water: quantity("N") = Field(0.0, description="Submerged weight of the whole tether. [N]")
    mass: quantity("kg", ge=0) = Field(0.0, description="Mass of the whole tether. [kg]")
    name: str | None = None


# the tags are not keys: an error's path reads ``line.sections[1].s``, not ``line.sections[1].clamp.s``
UNION_TAGS.update(("clamp", "tether"))


def ties_of(line) -> tuple:
    """The clamps and tethers among ``line``'s sections, with their indices: ``((i, tie), ...)``."""
    return tuple((i, sec) for i, sec in enumerate(getattr(line, "sections", ())) if isinstance(sec, (Clamp, Tether)))


def seabed_elevation(environment, x: float, y: float = 0.0) -> float | None:
    """Elevation of the seabed of ``environment`` under ``x`` (its profile, or the plane of its depth and slope
    through ``(0, -depth)``), or under ``(x, y)`` on its grid; None without a seabed. [m]"""
    bed = environment.seabed
    if bed.grid is not None:
        from .environment import seabed_elevation as on_grid

        return on_grid(bed, float(x), float(y), f"seabed point at ({float(x):g}, {float(y):g}) m")
    if bed.profile is not None:
        return -float(np.interp(x, bed.profile.distance, bed.profile.depth))
    if environment.depth is None:
        return None
    return -float(environment.depth) + math.tan(bed.slope) * float(x)


def tie_points(line, environment, where: str = "line") -> dict:
    """The point each clamp and tether of ``line`` holds to, ``{section index: (x, y, z)}`` [m]: as given, or on
    the seabed of ``environment`` under ``(x, y)`` when ``z`` is left out.

    Raises ValueError (a case's validation error) for a point left on the seabed with no seabed, for a point
    below the seabed and for a point above the still water level (a tether's anchor, a clamp's position); the
    message names the line as ``where`` (``line``, or a system's ``lines.NAME``).
    """
    out = {}
    for i, tie in ties_of(line):
        p, key = (tie.position, "position") if isinstance(tie, Clamp) else (tie.anchor, "anchor")
        zb = seabed_elevation(environment, p.x, p.y)
        if p.z is None:
            if zb is None:
                raise ValueError(f"{where}.sections[{i}] ({tie.type}).{key} has no z and the environment no seabed to "
                                 f"put it on. Suggested fix: give {key}.z in m, or environment.depth.")
            out[i] = (p.x, p.y, zb)
            continue
        if p.z > 0.0:
            raise ValueError(f"{where}.sections[{i}] ({tie.type}).{key}.z = {p.z:g} m is above the still water "
                             "level (z = 0 m): a tie holds the cable to the seabed or to a point in the water. "
                             f"Suggested fix: give {key}.z <= 0 m (elevation, 0 at the surface, negative down), or "
                             f"leave it out to put the point on the seabed.")
        if zb is not None and p.z < zb - 1e-9 * max(abs(zb), 1.0):
            raise ValueError(f"{where}.sections[{i}] ({tie.type}).{key}.z = {p.z:g} m is {zb - p.z:.4g} m below the "
                             f"seabed there (z = {zb:g} m at x = {p.x:g} m). Suggested fix: give a point on or above "
                             f"the seabed, or leave {key}.z out to put it on the seabed.")
        out[i] = (p.x, p.y, p.z)
    return out

"""A towed body at the lower end of a towed cable: its weight, lift, and drag and added mass per axis of the body.

The body's axes
---------------
A towed body in seacable has no attitude of its own (no rotational degrees of freedom): its axes are those a
towfish or sled keeps in tow, set by its fins and its bridle,

* ``vertical``: the global Z axis (up). The body stays level, as WHOI Cable takes the body at the lower end of
  a towing or deployment problem: its drag is resolved on the global vertical, with the coefficient along the
  body's axis (``Cdt``), and on the horizontal (``Cdn``), each with its own quadratic law ``bdr |U_r| U_r``
  (Gobat & Grosenbaugh 2000; WHOI Cable's ``solver/dynamic_2d.c``, whose bottom boundary takes a terminal buoy's
  vertical drag ``Mdr Cdt / Cdn`` and horizontal drag ``Mdr``, and a lowered anchor's ``Cdt`` and ``Cdn``);
* ``along``: horizontal, along the towing cable's direction at the body projected on the horizontal, towards the
  tow point: the bridle holds the body's nose to its tow (when the cable is vertical at the body that direction
  is undefined and ``along`` falls back to +X; no horizontal flow acts on such a body in the cases that reach it,
  a vertical lowering);
* ``across``: horizontal, ``vertical x along`` (to port of a body towed along +X).

WHOI Cable's terminal body is round about the vertical, with one horizontal coefficient; the ``along`` and
``across`` axes split the horizontal as OrcaFlex's 6-D buoys do with their drag areas on the buoy's local x and y
axes (a towed fish: along its x axis). The velocity through the water projected horizontally would give no
``across`` component at all (the along axis would lie on it); the cable's direction does, in a cross current or
a turn.

The laws (the axes' unit vectors ``e_k``, ``u`` the water's velocity relative to the body):

* drag ``F = 1/2 rho sum_k (C_D A)_k |u . e_k| (u . e_k) e_k``, each axis its own quadratic law, as OrcaFlex
  applies a 6-D buoy's drag areas;
* added mass ``M_a = sum_k m_k e_k e_k^T`` in the body's equation of motion (its inertia at the line's end node),
  and the force ``M_a a_w`` of the water's acceleration ``a_w``.

A single number for ``drag_area`` is the isotropic drag ``1/2 rho C_D A |u| u`` (the form seacable always had,
whose results stay the same to the bit); a list of three is the per-axis law above (three equal areas are not the
isotropic law: a flow at 45 deg to two axes feels ``1/sqrt(2)`` of it). A single ``added_mass`` is ``m I``, the
same as three equal values.

References
----------
Gobat, J. I., Grosenbaugh, M. A. (2000). WHOI Cable v2.0: time domain numerical simulation of moored and towed
oceanographic systems. WHOI Technical Report WHOI-2000-08.
Orcina. OrcaFlex documentation: 6D buoys, drag (drag areas normal to the buoy's local axes).
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import BeforeValidator, Field

from .._model import quantity, unit_float
from ..line import Lifting

__all__ = ["AXES", "TowedBody", "per_axis_values"]

#: Names of the body's axes, in the order of a per-axis list.
AXES = ("along", "across", "vertical")


def _per_axis(unit: str, what: str, fix: str):
    """A field that takes one number (isotropic) or three, ``[along, across, vertical]``, each >= 0 in ``unit``."""
    from .._model import _number_checker

    one = _number_checker(unit, None, 0.0, None, None, fix)

    def check(value: Any):
        if isinstance(value, (list, tuple)):
            if len(value) != 3:
                raise ValueError(
                    f"must be one number ({what} in every direction) or three, [along, across, vertical] in the "
                    f"body's axes, got {len(value)} values {list(value)} {unit}. Suggested fix: give one number, or "
                    f"three in the order along, across, vertical, e.g. [0.2, 0.6, 0.9] {unit}.")
            out = []
            for name, item in zip(AXES, value):
                try:
                    out.append(one(item))
                except ValueError as exc:
                    raise ValueError(f"its {name} value {exc}") from None
            return tuple(out)
        return one(value)

    return Annotated[float | tuple[unit_float(unit), unit_float(unit), unit_float(unit)], BeforeValidator(check)]


def per_axis_values(value) -> tuple[float, float, float]:
    """``value`` (one number or three) as three, ``(along, across, vertical)``."""
    if isinstance(value, tuple):
        return (float(value[0]), float(value[1]), float(value[2]))
    return (float(value),) * 3


class TowedBody(Lifting):
    """A body at the lower end of a towed cable: its weight, drag, added mass and (a depressor's, a towfish's wing)
    lift ``1/2 rho C_L A U^2``, positive up (a depressor's is negative), at the flow speed U past it.

    ``drag_area`` and ``added_mass`` take one number (isotropic) or three, ``[along, across, vertical]`` in the
    body's axes (:mod:`seacable.towed.body`: vertical is Z, along is the towing cable's horizontal direction)."""

    weight_in_water: quantity("N") = Field(0.0, description="Net weight in water (negative floats). [N]")
    drag_area: _per_axis("m^2", "the drag area", "give C_D times the area normal to that axis, 0 or more.") = Field(
        0.0, description="Drag coefficient times area: one number (isotropic, 1/2 rho C_D A |u| u) or three, "
                         "[along, across, vertical] in the body's axes (each axis its own quadratic law). [m^2]")
    mass: quantity("kg", ge=0) = Field(0.0, description="Mass in air; needed (> 0) by towed_dynamic. [kg]")
    added_mass: _per_axis("kg", "the added mass", "give the added mass in kg, 0 or more.") = Field(
        0.0, description="Added mass: one number (isotropic) or three, [along, across, vertical] in the body's "
                         "axes. [kg]")
    seabed_area: quantity("m^2", ge=0) = Field(
        1.0, description="Area the body bears on the seabed with (towed_dynamic, finite_element): its contact "
                         "force is seabed_contact.stiffness times this times its penetration. [m^2]")

    @property
    def drag_per_axis(self) -> bool:
        """True when the drag is given per axis (three values, each its own quadratic law). [-]"""
        return isinstance(self.drag_area, tuple)

    @property
    def added_mass_per_axis(self) -> bool:
        """True when the added mass is given per axis (three values). [-]"""
        return isinstance(self.added_mass, tuple)

    def drag_areas(self) -> tuple[float, float, float]:
        """C_D A along, across and vertical (a single number: the same three). [m^2]"""
        return per_axis_values(self.drag_area)

    def added_masses(self) -> tuple[float, float, float]:
        """Added mass along, across and vertical (a single number: the same three). [kg]"""
        return per_axis_values(self.added_mass)

    def steady_drag_area(self) -> float:
        """C_D A of the steady tow, whose flow past the body is horizontal along the tow: the along axis's (or the
        isotropic one). [m^2]"""
        return self.drag_area[0] if isinstance(self.drag_area, tuple) else float(self.drag_area)


"""A system case's bodies as MoorDyn v2 ``BODIES`` rows, for ``seacable convert case.yaml -o deck.txt``.

MoorDyn's body [1]_ is a rigid body with a mass, a centre of gravity, three moments of inertia, a displaced volume
whose buoyancy acts at the centre of gravity (MoorDyn v2's
``Body::doRHS`` puts the body's ``(V rho - M) g`` there), drag areas and added-mass coefficients per axis; points on it
(``Body<N>``) move with it. seacable's deck reader (:func:`seacable.io.moordyn.moordyn_system`) reads such a row into
a :class:`~seacable.system.model.Body` so (``rho`` the water density)::

    added_mass[i][i] = Ca_i rho V  (i = surge, sway, heave; nothing else)
    quadratic_damping[i][i] = rho CdA_i / 2  (i = the six degrees of freedom; nothing else)
    center_of_buoyancy = center_of_gravity, waterplane_area = 0, waterplane_moments = (0, 0)

and a point on the body's mass and volume are lumped into the body's. :func:`deck_bodies` writes the inverse, so
the deck reads back to the same body, and refuses by name what a body row cannot hold: a hydrodynamic database, a
waterplane or a hydrostatic stiffness matrix (a MoorDyn body has no hydrostatic stiffness: its buoyancy is the
volume's, at the centre of gravity), a centre of buoyancy off the centre of gravity, wind or current areas, a linear
damping matrix, a quadratic damping or added mass off the diagonal (or rotational added mass), a constant external
force, a free body pinned (MoorDyn pins rods, not bodies), and a point on a body with its own mass, volume or added
mass.

References
----------
.. [1] MoorDyn v2 input file format, section Bodies: ``docs/inputs.rst`` of
   https://github.com/FloatingArrayDesign/MoorDyn (BSD-3).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

__all__ = ["BODY_HEADER", "body_point_attachment", "deck_bodies"]

#: the BODIES section's two header lines
BODY_HEADER = (("ID   Attachment X0           Y0           Z0           r0         p0         y0         Mass       "
                "CG*                  I*                   Volume     CdA*                                Ca*"),
               ("(#)  (-)        (m)          (m)          (m)          (deg)      (deg)      (deg)      (kg)       "
                "(m)                  (kg-m^2)             (m^3)      (m^2)                               (-)"))


def _refuse(what: str, fix: str):
    raise InputError(f"{what}: MoorDyn cannot express it. Suggested fix: {fix}.")


def _bar(values) -> str:
    return "|".join(repr(float(v)) for v in values)


def _body_row(number: int, name: str, body, rho: float) -> str:
    """One BODIES row of ``body`` (refusing what the row cannot hold)."""
    label = f"body '{name}'"
    if body.hydrodynamics is not None:
        _refuse(f"{label} has a hydrodynamic database ({body.hydrodynamics.file})",
                "give its added mass and drag as diagonal matrices and leave out 'hydrodynamics' (a MoorDyn body "
                "has no radiation, wave excitation nor hydrostatics of its own)")
    if body.hydrostatic_stiffness is not None:
        _refuse(f"{label} has a hydrostatic_stiffness matrix",
                "leave it out: a MoorDyn body has no hydrostatic stiffness, only the buoyancy of its volume at its "
                "centre of gravity")
    if body.waterplane_area or any(body.waterplane_moments):
        _refuse(f"{label} has a waterplane (waterplane_area {body.waterplane_area:g} m^2, waterplane_moments "
                f"{tuple(body.waterplane_moments)} m^4)",
                "set them to 0: a MoorDyn body has no waterplane and no hydrostatic stiffness, only the buoyancy of "
                "its volume at its centre of gravity (a surface-piercing body needs a rod on it, written by hand)")
    if body.volume > 0 and tuple(body.center_of_buoyancy) != tuple(body.center_of_gravity):
        _refuse(f"{label} has its centre of buoyancy at {tuple(body.center_of_buoyancy)} m, its centre of gravity at "
                f"{tuple(body.center_of_gravity)} m",
                "give both the same point: a MoorDyn body's buoyancy acts at its centre of gravity (MoorDyn v2 "
                "applies (V rho - M) g there), so a body whose buoyancy rights it needs a rod on it, written by hand")
    for key in ("wind", "current"):
        if getattr(body, key) is not None:
            _refuse(f"{label} has {key} areas", f"leave out the body's '{key}' (a MoorDyn body takes no {key} load)")
    if body.linear_damping is not None and np.any(body.matrix("linear_damping")):
        _refuse(f"{label} has a linear_damping matrix", "leave it out (a MoorDyn body has quadratic drag only)")
    if any(body.external_force):
        _refuse(f"{label} has an external force {tuple(body.external_force)} N, N m",
                "leave out external_force (MoorDyn 2.7's bodies take no constant load)")
    if body.pinned and body.kind == "free":
        _refuse(f"{label} is free and pinned", "make it free or prescribed and pinned (MoorDyn pins rods and coupled "
                                               "bodies, not free bodies)")
    drag = body.matrix("quadratic_damping")
    if np.any(drag - np.diag(np.diag(drag))):
        _refuse(f"{label} has a quadratic_damping matrix with terms off its diagonal",
                "keep its diagonal only (a MoorDyn body's drag is one area per degree of freedom)")
    added = body.matrix("added_mass")
    translational = np.zeros((6, 6))
    translational[:3, :3] = np.diag(np.diag(added)[:3])
    if np.any(added - translational):
        _refuse(f"{label} has added mass in rotation or off the diagonal",
                "keep the surge, sway and heave terms of the diagonal (a MoorDyn body's Ca acts on its volume in "
                "translation only)")
    if np.any(np.diag(added)[:3]) and not body.volume > 0:
        _refuse(f"{label} has added mass {tuple(np.diag(added)[:3])} kg and no volume",
                "give the body its displaced volume (MoorDyn's Ca is per displaced volume)")
    if np.any(drag) and not rho > 0:
        _refuse(f"{label} has drag in water of density {rho:g} kg/m^3", "give the water its density")
    cda = [2.0 * d / rho if d else 0.0 for d in np.diag(drag)]
    ca = [a / (rho * body.volume) if a else 0.0 for a in np.diag(added)[:3]]
    kind = {"free": "Free", "fixed": "Fixed", "prescribed": "CoupledPinned" if body.pinned else "Coupled"}[body.kind]
    x, y, z, *angles = (float(v) for v in body.position)
    r0, p0, y0 = (math.degrees(a) for a in angles)
    return (f"{number:<4} {kind:<10} {x!r:<12} {y!r:<12} {z!r:<12} {r0!r:<10} {p0!r:<10} {y0!r:<10} "
            f"{float(body.mass)!r:<10} {_bar(body.center_of_gravity):<20} {_bar(body.inertia):<20} "
            f"{float(body.volume)!r:<10} {_bar(cda):<35} {_bar(ca)}")


def deck_bodies(case) -> tuple[list[str], dict[str, int]]:
    """The BODIES rows of a system case's bodies and their numbers (1, 2, ... in the case's order).

    Parameters
    ----------
    case : SystemCase
        The case; its water density [kg/m^3] turns drag and added mass into MoorDyn's CdA [m^2] and Ca [-].

    Returns
    -------
    rows : list of str
        One row each, positions in m, angles in degrees (MoorDyn's), mass in kg, inertia in kg m^2.
    number : dict
        The body's deck number by name.

    Raises
    ------
    InputError
        A body a MoorDyn body row cannot express (see the module).
    """
    rho = case.environment.water_density
    number = {name: k for k, name in enumerate(case.bodies, start=1)}
    return [_body_row(number[n], n, b, rho) for n, b in case.bodies.items()], number


def body_point_attachment(name: str, point, number: dict[str, int]) -> str:
    """MoorDyn's attachment word of a point on a body (``Body<N>``); its position stays relative to the body.

    Raises
    ------
    InputError
        A point on a body with a mass, volume or added mass of its own (MoorDyn lumps them into the body: the deck
        would read back to another system).
    """
    if point.mass or point.volume or point.added_mass:
        _refuse(f"point '{name}' on body '{point.body}' has mass {point.mass:g} kg, volume {point.volume:g} m^3, "
                f"added mass {point.added_mass:g} kg",
                "add them to the body's (mass, center_of_gravity, inertia, volume) and give the point none: MoorDyn "
                "lumps a body point's mass and volume into its body")
    return f"Body{number[point.body]}"

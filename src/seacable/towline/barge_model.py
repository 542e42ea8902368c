"""The towed barge's inputs (:class:`Barge`), a pydantic model without numba.

:mod:`seacable.towline.barge` gives it with the barge's inertia, hull forces and equations of motion
(plain functions and the compiled kernels); it lives here so that a case that names a barge is read
without importing numba.
"""

from __future__ import annotations

import warnings

from pydantic import Field, model_validator

from .._model import Model, quantity
from ..errors import SeacableWarning

__all__ = ["Barge"]


class Barge(Model):
    """A box barge towed at ``tow_point_x``: rigid body in surge, sway and yaw.

    The defaults of the hydrodynamic coefficients are chosen for a shallow-draft,
    flat-bottomed, blunt-ended box barge in deep water (paper 003's barge has
    B/T = 30); change them for another hull.

    Parameters
    ----------
    length
        Length between perpendiculars L. [m]
    beam
        Beam B. [m]
    draft
        Draft T. [m]
    block_coefficient
        Block coefficient Cb = displaced volume / (L B T), 0 < Cb <= 1. [-]
    yaw_radius_of_gyration
        Radius of gyration of the mass about the vertical axis through midship;
        default ``0.25 * length`` (paper 003). [m]
    tow_point_x
        Tow point, forward of midship; default ``length / 2`` (the bow). [m]
    tow_point_height
        Tow point height above the water. [m]
    surge_drag
        Resistance coefficient C_x on the frontal area B T, ``R = 1/2 rho C_x B T u^2``.
        Default 1.0: the blunt bow's separation drag, about 0.8 on the frontal area for a
        flat-faced body in axial flow (Hoerner 1965, ch. 3), plus the friction of the
        ITTC-1957 line on the wetted area L B + 2 (L + B) T, which for paper 003's barge
        at 2-5 knots (Re 4e7-1e8, C_F 0.0024-0.0021) adds 0.22-0.26 referred to B T;
        total about 1.0-1.1. Das, Sha and Misra ("An investigation into resistance
        characteristics of rectangular barges", model tests at IIT Kharagpur) likewise
        find the separation at the blunt fore end to be the largest part of a box
        barge's resistance. Wave resistance is neglected (Froude number 0.05-0.12). [-]
    cross_flow_drag
        Two-dimensional cross-flow drag coefficient C_y on the lateral area per metre,
        T. Default 1.0, an engineering choice, not a measurement: Hoerner's curve for
        ship sections (Leite et al. 1998, as used by Fossen 2011) falls to 0.56 at
        B/(2T) = 4, its last point, for round bilges; sharp-cornered rectangles are
        bluffer (about 2.0 up to a side ratio of 1, falling after the flow reattaches
        at a side ratio near 3), and shallow water raises the value further
        (1.0-2.0 and more at depth/draft below 3). [-]
    surge_added_mass
        Surge added mass as a fraction of the mass, m11 / m. Default 0.05: Söding's
        (1982) formula ``2.7 rho V^(5/3) / L^2`` gives 0.052 for paper 003's barge. [-]
    sway_added_mass
        Sway added-mass coefficient C_a of the strip added mass
        ``m22' = C_a rho pi T^2 / 2`` per metre, ``m22 = m22' L``. Default 2.37: the
        two-dimensional potential-flow added mass of the double body (a rectangle
        2T high and B long moving along B) for B/(2T) = 15, continuing DNV-RP-C205
        Table A-1 (1.51, 1.70, 1.98, 2.23 at 2T/B = 1, 0.5, 0.2, 0.1), computed with a
        source-panel method that reproduces those table values to 0.3 %. [-]
    yaw_added_inertia
        Yaw added inertia as a fraction of the strip-theory value
        ``m66 = m22 L^2 / 12`` (uniform sections). Default 1.0. [-]
    hull_lift
        The hull's lift as a fraction of its slender-body value ``-|u| (m22 / L) w(x_T)`` at
        the trailing edge (see the module). Default 1.0; 0 leaves only the cross-flow drag. [-]
    """

    length: quantity("m", gt=0, fix="give the length between perpendiculars in metres, e.g. 50.0.") = Field(
        description="Length between perpendiculars. [m]")
    beam: quantity("m", gt=0, fix="give the beam in metres, e.g. 15.0.") = Field(description="Beam. [m]")
    draft: quantity("m", gt=0, fix="give the draft (depth below the waterline) in metres, e.g. 0.5.") = Field(
        description="Draft. [m]")
    block_coefficient: quantity("-", gt=0, le=1, fix="give the displaced volume over L*B*T, e.g. 0.9 for a "
                                                     "box barge with raked ends.") = Field(
        description="Block coefficient. [-]")
    yaw_radius_of_gyration: quantity("m", gt=0, fix="give it in metres, e.g. 0.25 * length.") | None = Field(
        None, description="Yaw radius of gyration; default 0.25 * length. [m]")
    tow_point_x: quantity("m") | None = Field(None, description="Tow point forward of midship; default "
                                                                "length / 2. [m]")
    tow_point_height: quantity("m") = Field(1.0, description="Tow point height above the water. [m]")
    surge_drag: quantity("-", ge=0) = Field(1.0, description="Surge drag coefficient on B*T. [-]")
    cross_flow_drag: quantity("-", ge=0) = Field(1.0, description="Cross-flow drag coefficient on L*T. [-]")
    surge_added_mass: quantity("-", ge=0) = Field(0.05, description="m11 / m. [-]")
    sway_added_mass: quantity("-", ge=0) = Field(2.37, description="C_a of m22' = C_a rho pi T^2 / 2. [-]")
    yaw_added_inertia: quantity("-", ge=0) = Field(1.0, description="m66 / (m22 L^2 / 12). [-]")
    hull_lift: quantity("-", ge=0) = Field(1.0, description="Hull lift as a fraction of its slender-body "
                                                            "value at the trailing edge. [-]")

    @model_validator(mode="after")
    def _tow_point_on_hull(self):
        x = self.tow_x
        if abs(x) > 0.5 * self.length:
            warnings.warn(f"barge.tow_point_x = {x:g} m lies outside the hull (|x| <= length/2 = "
                          f"{0.5 * self.length:g} m). Fine for a bridle apex; otherwise give x from midship, "
                          "positive forward.", SeacableWarning, stacklevel=2)
        return self

    @property
    def gyradius(self) -> float:
        """Yaw radius of gyration, resolved. [m]"""
        k = self.yaw_radius_of_gyration
        return 0.25 * self.length if k is None else k

    @property
    def tow_x(self) -> float:
        """Tow point forward of midship, resolved. [m]"""
        return 0.5 * self.length if self.tow_point_x is None else self.tow_point_x

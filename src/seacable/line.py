"""Line data: line types (cable, rope, chain), segments, point masses and buoys.

A :class:`Line` runs from end A (the anchor, the free end of a towed cable, or
the seabed end of a lay) to end B (the fairlead, the vessel) as a chain of
:class:`Segment` objects, each of one :class:`LineType`, with
:class:`PointMass` attachments (clump weights, repeaters, buoys, floats) at
given unstretched arc lengths from end A.
"""

from __future__ import annotations

import itertools
import math
import warnings
from typing import Literal

import numpy as np
from pydantic import Field, field_validator, model_serializer, model_validator

from ._model import Model, quantity
from .errors import InputError, SeacableWarning
from .moment_curvature import check_table
from .sections import BendRestrictor, BendStiffener, BuoyancySection, Section, smeared_line_type
from .ties import Clamp, Tether

__all__ = ["Line", "LineType", "PointMass", "RetypedCopies", "Segment", "module_attachments", "resolve_sections",
           "retyped_changes"]

#: Default water density [kg/m^3] and gravity [m/s^2] used where no environment is given.
_RHO, _G = 1025.0, 9.81

#: The cable limits of a line type, left out of a dumped case when not given.
# left out of a dumped line type when not given (with the bending law, which came later)
_LIMITS = ("minimum_bend_radius", "minimum_bend_radius_dynamic", "allowable_tension", "allowable_compression",
           "moment_curvature")
_MBR_FIX = "give the minimum bend radius in metres (> 0 m), e.g. 3.0 for a cable of 0.15 m diameter."
#: An MBR over this many diameters looks like millimetres (cables' MBRs are about 10-40 diameters). [-]
_MBR_IN_MM = 1000.0


class LineType(Model):
    """Properties of one kind of cable, rope or chain.

    The weight in water is either given (``weight_in_water``) or, when left out,
    derived from the mass and the displaced volume of a solid cylinder of the
    given ``diameter``: ``w = (m - rho * pi * d**2 / 4) * g``, with the density
    and gravity of the environment. For chain, give the volume-equivalent
    diameter, or give the weight in water.

    Parameters
    ----------
    diameter
        Volume-equivalent (and drag) diameter. [m]
    mass_per_length
        Mass per unit unstretched length in air. [kg/m]
    weight_in_water
        Submerged weight per unit length, negative for a buoyant line; ``None``
        to derive it from mass and diameter. [N/m]
    axial_stiffness
        Axial stiffness EA; ``None`` for an inextensible line. [N]
    bending_stiffness
        Bending stiffness EI. [N m^2]
    moment_curvature
        Optional nonlinear bending law instead of EI, ``(kappa [1/m], M [N m])`` pairs from ``(0, 0)``, curvature and
        moment rising (e.g. bilinear: the armour's stick and slip, without hysteresis), odd (negative curvatures, if
        given, mirror the positive), linear between pairs and along the last slope beyond (reported by the cable
        checks); its initial slope is the cable's EI (``bending_stiffness``, if given, must agree within 1 %)
        (:mod:`seacable.moment_curvature`; the mooring finite-element line). [1/m, N m]
    drag_normal, drag_tangential
        Drag coefficients normal and tangential to the line, on the diameter (a faired cable: on the fairing's
        chord and on its wetted perimeter, ``drag_law``). [-]
    drag_law
        ``"morison"``: the normal and tangential drag of a bare cable, ``1/2 rho C_dn d |u_n| u_n`` and
        ``1/2 rho C_dt pi d |u_t| u_t`` (the independence principle). ``"faired"``: a faired cable, the same
        independence principle on the fairing, ``1/2 rho C_dn c |u_n| u_n`` on its chord ``fairing_chord`` and
        the skin friction ``1/2 rho C_dt 2.1 c |u_t| u_t`` on its wetted perimeter, about 2.1 c (Packwood 1990,
        who found this crossflow model to predict swept fairings' drag better than the loading functions fitted
        to bare cables).
    fairing_chord
        Chord of the fairing of a faired cable. [m]
    strumming_amplitude
        Root-mean-square cross-flow vibration amplitude over the diameter, A_rms / d, of a strumming cable: its
        normal drag is amplified by Vandiver's (1983) factor ``1 + 1.043 (2 A_rms / d)^0.65``; 0: none. [-]
    added_mass_normal, added_mass_tangential
        Added-mass coefficients on the displaced mass. [-]
    breaking_load
        Minimum breaking load, ``None`` if unknown. [N]
    name
        A label used in plots and messages.
    tension_strain
        A nonlinear axial law, ``(strain, tension)`` pairs from strain 0 with increasing strain
        and non-decreasing tension (a MoorDyn EA table); ``axial_stiffness`` is then a secant EA
        for models that take a constant one. ``None`` for a linear line. [-, N]
    dynamic_axial_stiffness
        Viscoelastic (synthetic rope) dynamic stiffness ``EA_d = EA_Dc + EA_D_Lm * mean tension``
        as ``(EA_Dc, EA_D_Lm)`` (MoorDyn v2's ``EA_s|EA_d`` gives ``(EA_d, 0)``);
        ``axial_stiffness`` is the static EA_s that the statics use. ``None`` for an elastic line.
        [N, -]
    dynamic_axial_damping
        Viscoelastic fast damper BA_D, in parallel with the dynamic spring (MoorDyn v2's ``BA_s|BA_d``);
        the slow damper is the model's ordinary axial damping. ``None`` for none. [N s]
    material
        What the line is made of, for its fatigue curve (DNV-OS-E301 Ch.2 Sec.2 D; the design layer,
        :mod:`seacable.design.fatigue`): ``"studless_chain"``, ``"stud_chain"``, ``"six_strand_rope"``,
        ``"spiral_strand_rope"``, ``"polyester_rope"`` or ``"other"`` (no curve of the standard: a cable, an
        umbilical). ``None`` (the default): not said; the design tables then read it from the name where the name
        is not ambiguous, and compute no fatigue where it is.
    minimum_bend_radius
        The cable's minimum bend radius (MBR) in a static configuration (the cable maker's static, or
        installation, MBR): the cable checks (:mod:`seacable.design.cable`) hold a static result's curvature
        (``mooring_static``, ``mooring_pushover``) to ``1 / MBR``. ``None``: not checked. [m]
    minimum_bend_radius_dynamic
        The cable's MBR in service under dynamic loads (the maker's dynamic MBR, no smaller than the static
        one): the limit of a ``mooring_dynamic`` run's largest curvature. ``None``: not checked (the static MBR
        is not used for a dynamic run). [m]
    allowable_tension
        The largest effective tension allowed in the cable (the maker's allowable, or maximum working,
        tension). ``None``: not checked. [N]
    allowable_compression
        The largest compression (negative effective tension) the cable may take without harm (buckling,
        armour bird-caging); ``None``: 0 N, the effective tension must stay >= 0. [N]
    """

    diameter: quantity("m", gt=0, fix="give the outer diameter in metres, e.g. 0.035.") = Field(
        description="Volume-equivalent and drag diameter. [m]")
    mass_per_length: quantity("kg/m", gt=0, fix="give the mass per metre in air in kg/m.") = Field(
        description="Mass per unit unstretched length in air. [kg/m]")
    weight_in_water: quantity("N/m") | None = Field(
        None, description="Submerged weight per unit length (negative: buoyant); "
                          "derived from mass and diameter when left out. [N/m]")
    axial_stiffness: quantity("N", gt=0, fix="give EA in newtons, e.g. 4.2e5.") | None = Field(
        None, description="Axial stiffness EA; left out for an inextensible line. [N]")
    bending_stiffness: quantity("N m^2", ge=0) = Field(0.0, description="Bending stiffness EI. [N m^2]")
    moment_curvature: tuple[tuple[float, float], ...] | None = Field(
        None, description="Nonlinear bending law: (curvature [1/m], moment [N m]) pairs from (0, 0), rising, odd.")
    drag_normal: quantity("-", ge=0) = Field(1.2, description="Normal drag coefficient. [-]")
    drag_tangential: quantity("-", ge=0) = Field(0.0, description="Tangential drag coefficient. [-]")
    drag_law: Literal["morison", "faired"] = Field(
        "morison", description="Drag law: morison (bare cable) or faired (on fairing_chord).")
    fairing_chord: quantity("m", gt=0) | None = Field(None, description="Fairing chord of a faired cable. [m]")
    strumming_amplitude: quantity("-", ge=0, le=5, fix="give A_rms / d, e.g. 0.3 for a strongly strumming cable.") = Field(
        0.0, description="Strumming rms amplitude over diameter; amplifies the normal drag (Vandiver 1983). [-]")
    added_mass_normal: quantity("-", ge=0) = Field(1.0, description="Normal added-mass coefficient. [-]")
    added_mass_tangential: quantity("-", ge=0) = Field(0.0, description="Tangential added-mass coefficient. [-]")
    breaking_load: quantity("N", gt=0) | None = Field(None, description="Minimum breaking load. [N]")
    name: str | None = Field(None, description="Label used in plots and messages.")
    material: Literal["studless_chain", "stud_chain", "six_strand_rope", "spiral_strand_rope", "polyester_rope",
                      "other"] | None = Field(
        None, description="What the line is made of, for its fatigue (T-N) curve; None: not said (the name tells).")
    tension_strain: tuple[tuple[float, float], ...] | None = Field(
        None, description="Nonlinear axial law: (strain [-], tension [N]) pairs, from strain 0.")
    dynamic_axial_stiffness: tuple[float, float] | None = Field(
        None, description="Viscoelastic dynamic stiffness (EA_Dc [N], EA_D_Lm [-]); statics use axial_stiffness.")
    dynamic_axial_damping: quantity("N s", ge=0) | None = Field(
        None, description="Viscoelastic fast damper BA_D, in parallel with the dynamic spring. [N s]")
    minimum_bend_radius: quantity("m", gt=0, fix=_MBR_FIX) | None = Field(
        None, description="Minimum bend radius in a static configuration: the limit of a static result's "
                          "curvature, 1 / MBR. [m]")
    minimum_bend_radius_dynamic: quantity("m", gt=0, fix=_MBR_FIX) | None = Field(
        None, description="Minimum bend radius in service under dynamic loads: the limit of a dynamic run's "
                          "largest curvature. [m]")
    allowable_tension: quantity("N", gt=0, fix="give the cable's allowable tension in N, e.g. 2.0e5.") | None = Field(
        None, description="Largest effective tension allowed. [N]")
    allowable_compression: quantity(
        "N", ge=0, fix="give the compression the cable may take as a positive force in N (0: none).") | None = Field(
        None, description="Largest compression (negative effective tension) allowed; None: 0 N. [N]")

    @model_serializer(mode="wrap")
    def _omit_unset_limits(self, handler):
        # the cable limits appear in a dumped case (and so in a result's 'case' attribute) only when given, so that
        # the cases and results of lines without them read as they did before the limits existed
        data = handler(self)
        if isinstance(data, dict):
            for key in _LIMITS:
                if data.get(key, 0) is None:
                    del data[key]
        return data

    @model_validator(mode="after")
    def _check_limits(self):
        static, dynamic = self.minimum_bend_radius, self.minimum_bend_radius_dynamic
        if static is not None and dynamic is not None and dynamic < static:
            raise ValueError(
                f"minimum_bend_radius_dynamic {dynamic:g} m is smaller than minimum_bend_radius {static:g} m: a "
                "cable's dynamic MBR (in service, under cyclic bending) is no smaller than its static one. Suggested "
                "fix: check that the two are not swapped, and give both in metres.")
        for key in ("minimum_bend_radius", "minimum_bend_radius_dynamic"):
            mbr = getattr(self, key)
            if mbr is not None and mbr > _MBR_IN_MM * self.diameter:
                warnings.warn(f"LineType.{key} = {mbr:g} m is over {_MBR_IN_MM:g} times the diameter "
                              f"{self.diameter:g} m (cables' MBRs are about 10-40 diameters): is it in millimetres? "
                              "Give it in metres.", SeacableWarning, stacklevel=2)
        return self

    @model_validator(mode="after")
    def _drag_law(self):
        if self.drag_law == "faired" and self.fairing_chord is None:
            raise ValueError("drag_law 'faired' needs fairing_chord (m), the chord its drag coefficients refer to. "
                             "Suggested fix: give the fairing's chord, e.g. 'fairing_chord: 0.1'.")
        if self.drag_law != "faired" and self.fairing_chord is not None:
            raise ValueError(f"fairing_chord {self.fairing_chord:g} m is given but drag_law is '{self.drag_law}'. "
                             "Suggested fix: set drag_law: faired, or leave fairing_chord out.")
        return self

    def drag_amplification(self) -> float:
        """Vandiver's (1983) drag amplification of a strumming cable, ``1 + 1.043 (2 A_rms / d)^0.65`` (1 without
        strumming). [-]"""
        a = self.strumming_amplitude
        return 1.0 + 1.043 * (2.0 * a) ** 0.65 if a > 0 else 1.0

    def effective_drag(self) -> tuple[float, float]:
        """``(C_dn, C_dt)`` referred to the diameter d and the perimeter pi d, as every model takes them: the drag
        law's (``drag_law``: a faired cable's on its chord c and wetted perimeter 2.1 c, so ``C_dn c / d`` and
        ``C_dt 2.1 c / (pi d)``) with the normal one amplified by strumming (:meth:`drag_amplification`). [-]"""
        cdn, cdt = self.drag_normal, self.drag_tangential
        if self.drag_law == "faired":
            c = self.fairing_chord
            cdn, cdt = cdn * c / self.diameter, cdt * 2.1 * c / (math.pi * self.diameter)
        return cdn * self.drag_amplification(), cdt

    @model_validator(mode="after")
    def _check_moment_curvature(self):
        if self.moment_curvature is None:
            return self
        half = check_table(self.moment_curvature, "moment_curvature")
        slope = half[1][1] / half[1][0]
        ei = self.bending_stiffness
        if ei > 0 and not abs(slope - ei) <= 0.01 * ei:
            raise ValueError(f"moment_curvature starts at slope M/kappa = {slope:.6g} N m^2, but bending_stiffness is "
                             f"{ei:.6g} N m^2: the law's initial slope is the cable's EI. Suggested fix: leave "
                             "bending_stiffness out (the law gives it), or check the table's units (1/m, N m).")
        return self

    @field_validator("tension_strain")
    @classmethod
    def _check_table(cls, table):
        if table is None:
            return table
        if len(table) < 2:
            raise ValueError(f"tension_strain must hold at least 2 (strain, tension) pairs, got {len(table)}. "
                             "Suggested fix: give the curve from strain 0 up to the largest strain expected.")
        for k, (e, t) in enumerate(table):
            if not (math.isfinite(e) and math.isfinite(t)) or e < 0 or t < 0:
                raise ValueError(f"tension_strain[{k}] must be finite strain >= 0 [-] and tension >= 0 [N], got "
                                 f"({e}, {t}). Suggested fix: give strains as fractions (0.01 = 1 %) and tensions in N.")
            if k and (e <= table[k - 1][0] or t < table[k - 1][1]):
                raise ValueError(f"tension_strain[{k}] = ({e:g}, {t:g} N) must have a larger strain and no smaller "
                                 f"tension than the pair before, ({table[k - 1][0]:g}, {table[k - 1][1]:g} N). "
                                 "Suggested fix: sort the pairs by strain; softening curves are not supported.")
        if table[-1][1] <= 0:
            raise ValueError(f"must end at a tension > 0 N, got {table[-1][1]:g} N: a line that carries no tension "
                             "at any strain of the table holds nothing. Suggested fix: give the tensions in N.")
        return table

    @field_validator("dynamic_axial_stiffness")
    @classmethod
    def _check_dynamic(cls, value):
        if value is not None and not all(math.isfinite(v) and v >= 0 for v in value):
            raise ValueError(f"dynamic_axial_stiffness must be (EA_Dc >= 0 [N], EA_D_Lm >= 0 [-]), got {value}. "
                             "Suggested fix: give the dynamic stiffness at zero mean load and its slope.")
        return value

    @model_validator(mode="after")
    def _check_viscoelastic(self) -> LineType:
        dyn, ea = self.dynamic_axial_stiffness, self.axial_stiffness
        if dyn is not None and ea is not None and self.tension_strain is None and not dyn[0] > ea:
            raise ValueError(
                f"dynamic_axial_stiffness EA_Dc = {dyn[0]:.6g} N must exceed the static axial_stiffness EA_s = "
                f"{ea:.6g} N: the viscoelastic model puts a slow spring EA_D EA_s / (EA_D - EA_s) in series with "
                "EA_D. Suggested fix: give the dynamic stiffness (typically 1.5-3 x EA_s for polyester), or "
                "leave dynamic_axial_stiffness out for an elastic line.")
        return self

    @model_validator(mode="after")
    def _check_weight(self) -> LineType:
        if self.weight_in_water is not None:
            in_air = self.mass_per_length * _G
            if self.weight_in_water > in_air * 1.0001:
                raise ValueError(
                    f"weight_in_water must not exceed the weight in air "
                    f"(mass_per_length * g = {in_air:.6g} N/m), got {self.weight_in_water:.6g} N/m. "
                    "Suggested fix: give the submerged weight in N/m, not a mass in kg/m.")
        if self.drag_normal > 10:
            warnings.warn(f"LineType.drag_normal = {self.drag_normal:g} is unusually large "
                          "(typical 1.0-2.5 for cable, 2.4 for chain).", SeacableWarning, stacklevel=2)
        return self

    @property
    def area(self) -> float:
        """Cross-section area of the volume-equivalent cylinder. [m^2]"""
        return math.pi * self.diameter**2 / 4.0

    def submerged_weight(self, water_density: float = _RHO, gravity: float = _G) -> float:
        """Weight in water per unit length. [N/m]

        The given ``weight_in_water`` if there is one, else ``(m - rho A) g``.
        """
        if self.weight_in_water is not None:
            return self.weight_in_water
        return (self.mass_per_length - water_density * self.area) * gravity

    def added_mass_per_length(self, water_density: float = _RHO) -> float:
        """Normal added mass per unit length, ``Ca rho A``. [kg/m]"""
        return self.added_mass_normal * water_density * self.area

    def effective_axial_stiffness(self) -> float:
        """EA, or infinity for an inextensible line. [N]"""
        return math.inf if self.axial_stiffness is None else self.axial_stiffness


class Segment(Model):
    """A length of line of one type.

    Parameters
    ----------
    line_type
        The line type (in a case file: the name of an entry of ``line_types``,
        or an inline mapping).
    length
        Unstretched length. [m]
    n_elements
        Number of elements or nodes intervals a discretised model uses on this
        segment; ``None`` lets the model choose.
    """

    line_type: LineType
    length: quantity("m", gt=0, fix="give the unstretched segment length in metres.") = Field(
        description="Unstretched length. [m]")
    n_elements: int | None = Field(None, ge=1, le=100_000,
                                     description="Elements a discretised model uses here (at most 100 000).")


class Lifting(Model):
    """A lift coefficient and the area it refers to: the lift ``1/2 rho C_L A U^2``, positive up (a depressor's
    is negative), at the flow speed U past the body (across the flow, in the vertical plane through it)."""

    lift_coefficient: quantity("-") = Field(0.0, description="Lift coefficient C_L, positive up. [-]")
    reference_area: quantity("m^2", ge=0) | None = Field(
        None, description="Area the lift coefficient refers to (a wing's planform area). [m^2]")

    @model_validator(mode="after")
    def _lift_needs_area(self):
        if self.lift_coefficient != 0.0 and not self.reference_area:
            raise ValueError(f"lift_coefficient {self.lift_coefficient:g} needs reference_area (m^2), the area "
                             f"it refers to, got {self.reference_area}. Suggested fix: give the wing's planform "
                             "area, e.g. 'reference_area: 0.8'.")
        return self

    def lift_area(self) -> float:
        """C_L times its reference area (0 without lift). [m^2]"""
        return self.lift_coefficient * self.reference_area if self.lift_coefficient else 0.0


class PointMass(Lifting):
    """A clump weight, repeater, buoy or float attached at one point of a line.

    Its net weight in water is ``weight_in_water`` if given, else
    ``(mass - rho * volume) * g``; negative means it floats.

    Parameters
    ----------
    s
        Unstretched arc length from end A. [m]
    mass
        Mass in air. [kg]
    volume
        Displaced volume. [m^3]
    weight_in_water
        Net weight in water, overriding mass and volume (negative: buoyant). [N]
    drag_area
        Drag coefficient times frontal area, C_D A: across the line when ``axial_drag_area`` is given,
        else in every direction. [m^2]
    axial_drag_area
        C_D A along the line (a body in line: its axial drag); None: the drag is isotropic. [m^2]
    lift_coefficient, reference_area
        Lift ``1/2 rho C_L A U^2``, positive up, at the flow speed U past it (a depressor's wing). [-], [m^2]
    added_mass
        Added mass. [kg]
    kind
        What it is, for plots and reports.
    name
        Label.
    """

    s: quantity("m", ge=0, fix="give the arc length from end A in metres.") = Field(
        description="Unstretched arc length from end A. [m]")
    mass: quantity("kg", ge=0) = Field(0.0, description="Mass in air. [kg]")
    volume: quantity("m^3", ge=0) = Field(0.0, description="Displaced volume. [m^3]")
    weight_in_water: quantity("N") | None = Field(None, description="Net weight in water. [N]")
    drag_area: quantity("m^2", ge=0) = Field(0.0, description="Drag coefficient times area. [m^2]")
    axial_drag_area: quantity("m^2", ge=0) | None = Field(
        None, description="Drag coefficient times area along the line; default: isotropic drag. [m^2]")
    added_mass: quantity("kg", ge=0) = Field(0.0, description="Added mass. [kg]")
    kind: Literal["clump", "buoy", "repeater", "float", "point", "depressor", "body"] = "point"
    name: str | None = None

    def net_weight(self, water_density: float = _RHO, gravity: float = _G) -> float:
        """Net weight in water, negative when buoyant. [N]"""
        if self.weight_in_water is not None:
            return self.weight_in_water
        return (self.mass - water_density * self.volume) * gravity


class Line(Model):
    """A line from end A to end B: segments in order, and attachments along it.

    Parameters
    ----------
    segments
        Segments from end A to end B.
    attachments
        Point masses and buoys; their ``s`` must lie on the line.
    sections
        Buoyancy sections and bend stiffeners laid over the segments (:mod:`seacable.sections`): buoyancy
        sections inside the line and apart from each other, a stiffener no longer than the segment at its end.
        The models that take segments and attachments take the equivalent line :func:`resolve_sections` gives.
    """

    segments: tuple[Segment, ...] = Field(min_length=1)
    attachments: tuple[PointMass, ...] = ()
    sections: tuple[Section, ...] = ()

    @model_serializer(mode="wrap")
    def _without_empty_sections(self, handler):
        # a line without sections is written as before sections existed (a result's case attribute unchanged)
        data = handler(self)
        if not self.sections and isinstance(data, dict):
            data.pop("sections", None)
        return data

    @classmethod
    def single(cls, line_type: LineType, length: float, **kwargs) -> Line:
        """A homogeneous line of one type and ``length``. [m]"""
        return cls(segments=(Segment(line_type=line_type, length=length),), **kwargs)

    @field_validator("attachments")
    @classmethod
    def _sorted(cls, value):
        return tuple(sorted(value, key=lambda a: a.s))

    @model_validator(mode="after")
    def _attachments_on_line(self) -> Line:
        total = self.length
        for i, a in enumerate(self.attachments):
            if a.s > total * (1 + 1e-12):
                raise ValueError(f"attachments[{i}].s must be <= the line length {total:g} m, "
                                 f"got {a.s:g} m. Suggested fix: give s as the arc length from end A.")
        return self

    @model_validator(mode="after")
    def _sections_on_line(self) -> Line:
        total = self.length
        spans = []
        held = {}
        for i, sec in enumerate(self.sections):
            if isinstance(sec, (BendStiffener, BendRestrictor)):
                sec.check_on(self)
                continue
            if isinstance(sec, (Clamp, Tether)):
                _check_tie(i, sec, total, held)
                continue
            if sec.length > total * (1 + 1e-12):
                raise ValueError(f"sections[{i}] (buoyancy) is {sec.length:g} m long, longer than the line "
                                 f"({total:g} m). Suggested fix: check the section's length and pitch (m).")
            if sec.end > total * (1 + 1e-12):
                raise ValueError(f"sections[{i}] (buoyancy) runs from s = {sec.start:g} m to {sec.end:g} m, beyond "
                                 f"the end of the line at {total:g} m. Suggested fix: start it at s <= "
                                 f"{total - sec.length:g} m (the arc length from end A).")
            spans.append((sec.start, sec.end, i))
        spans.sort()
        for (a0, a1, i), (b0, b1, j) in itertools.pairwise(spans):
            if b0 < a1 - 1e-9 * total:
                raise ValueError(f"sections[{i}] ({a0:g}-{a1:g} m) and sections[{j}] ({b0:g}-{b1:g} m) overlap. "
                                 "Suggested fix: one buoyancy section per stretch of cable; give the second "
                                 f"start >= {a1:g} m.")
        ends = {sec.end for sec in self.sections if isinstance(sec, BendStiffener)}
        if len(ends) < sum(isinstance(sec, BendStiffener) for sec in self.sections):
            raise ValueError("two bend stiffeners at the same end. Suggested fix: give one, its EI table the "
                             "combined stiffness.")
        return self

    @property
    def length(self) -> float:
        """Total unstretched length. [m]"""
        return float(sum(seg.length for seg in self.segments))

    @property
    def segment_ends(self) -> tuple[float, ...]:
        """Arc lengths of the segment boundaries from end A, starting with 0. [m]"""
        ends, s = [0.0], 0.0
        for seg in self.segments:
            s += seg.length
            ends.append(s)
        return tuple(ends)

    def weights(self, water_density: float = _RHO, gravity: float = _G) -> tuple[float, ...]:
        """Submerged weight per length of each segment. [N/m]"""
        return tuple(seg.line_type.submerged_weight(water_density, gravity) for seg in self.segments)

    def point_loads(self, water_density: float = _RHO, gravity: float = _G) -> tuple[tuple[float, float], ...]:
        """``(s, net weight)`` of each attachment. [m, N]"""
        return tuple((a.s, a.net_weight(water_density, gravity)) for a in self.attachments)


def _retyped(line: Line, old: dict, new: dict, where: str) -> Line:
    """``line`` with each segment's named line type (an entry of ``old``, the very object a case's validation put
    there, or one equal to it) replaced by the entry of the same name in ``new``."""
    segments = []
    for i, seg in enumerate(line.segments):
        name = next((k for k, v in old.items() if v is seg.line_type), None)
        name = name or next((k for k, v in old.items() if v == seg.line_type), None)
        if name is not None and name not in new:
            raise InputError(f"{where}.segments[{i}] uses line type '{name}', which the new line_types leave out "
                             f"(given: {', '.join(new) or 'none'}). Suggested fix: keep '{name}' in line_types, or "
                             "give the line anew with its line types.")
        segments.append(seg if name is None else seg.replace(line_type=new[name]))
    return line.replace(segments=tuple(segments))


def retyped_changes(case, changes: dict) -> dict:
    """The ``changes`` of ``case.replace`` (a :class:`~seacable.case.Case` or a system's case), with the line(s)
    retyped when they change ``line_types`` and leave the line(s) as they are: a line holds its line types, not their
    names, so that new types would otherwise reach the case and not its line (a silent wrong answer)."""
    if "line_types" not in changes:
        return changes
    old, new = case.line_types, changes["line_types"]
    if "line" in type(case).model_fields and "line" not in changes:
        return {**changes, "line": _retyped(case.line, old, new, "line")}
    if "lines" in type(case).model_fields and "lines" not in changes:
        return {**changes, "lines": {name: entry.replace(line=_retyped(entry.line, old, new, f"lines.{name}"))
                                     for name, entry in case.lines.items()}}
    return changes


class RetypedCopies:
    """The copies of a case that holds named ``line_types`` and a line (or lines) made of them (a
    :class:`~seacable.case.Case`, a system's case): new ``line_types`` reach the line(s) (:func:`retyped_changes`)."""

    def replace(self, **changes):
        """A copy with some fields changed, validated again; new ``line_types`` reach the line(s)' segments."""
        return super().replace(**retyped_changes(self, changes))

    def model_copy(self, *, update=None, deep: bool = False):
        """Pydantic's copy (``update`` not validated), new ``line_types`` reaching the line(s) as in :meth:`replace`."""
        return super().model_copy(update=retyped_changes(self, update) if update else update, deep=deep)


def _check_tie(i: int, tie, total: float, held: dict) -> None:
    """Refuse a clamp or tether off the line, a clamp at an end (the anchor or the fairlead holds it already), and
    two clamps or two tethers at one node (``held``: the ties seen so far, by kind and arc length)."""
    what = f"sections[{i}] ({tie.type})"
    if tie.s > total * (1 + 1e-12):
        raise ValueError(f"{what} is at s = {tie.s:g} m, beyond the end of the line at {total:g} m. Suggested fix: "
                         f"give s as the arc length from end A, 0 to {total:g} m.")
    if tie.type == "clamp" and (tie.s <= 1e-9 * total or tie.s >= total * (1 - 1e-9)):
        end = "A (the anchor)" if tie.s <= 1e-9 * total else "B (the fairlead)"
        raise ValueError(f"{what} is at s = {tie.s:g} m, at end {end}, which the analysis holds already. Suggested "
                         "fix: move the anchor or fairlead there (and clamp its direction with the end's condition: "
                         "a single line's analysis.anchor_end_condition or fairlead_end_condition, a system line's "
                         "lines.NAME.end_a_condition or end_b_condition), or clamp a node inside the line.")
    for s, j in held.get(tie.type, ()):
        if abs(s - tie.s) <= 1e-9 * total:
            raise ValueError(f"sections[{j}] and sections[{i}] are two {tie.type}s at one node (s = {tie.s:g} m). "
                             f"Suggested fix: give one {tie.type} there"
                             + (", its stiffness the combined one." if tie.type == "clamp" else
                                ", its axial stiffness the combined one, or tether a node beside it."))
    held.setdefault(tie.type, []).append((tie.s, i))


def module_attachments(line_type, section: BuoyancySection, water_density: float, gravity: float):
    """The modules of a section as point attachments at their centres, each with its own drag and added mass.

    Each carries the module's mass, volume and net weight, the drag area ``C_d,m (D_m - d) L_m`` across and
    ``C_a,m pi / 4 (D_m^2 - d^2)`` along the line (over the cable's own drag, which the bare cable keeps) and
    the added mass ``C_m rho V_m``.
    """
    mod, d = section.module, line_type.diameter
    vol = mod.displaced_volume(water_density, gravity)
    return tuple(PointMass(
        s=float(s), mass=mod.mass, volume=vol, weight_in_water=mod.net_weight(water_density, gravity),
        drag_area=mod.drag_normal * max(mod.diameter - d, 0.0) * mod.length,
        axial_drag_area=mod.drag_axial * 0.25 * math.pi * max(mod.diameter**2 - d**2, 0.0),
        added_mass=mod.added_mass * water_density * vol, kind="float",
        name=f"{section.name or 'buoyancy'} module {k + 1}") for k, s in enumerate(section.module_centres()))


def _split_segment(seg, cuts):
    """``seg`` cut at the local arc lengths ``cuts`` (0 < cut < length), its elements shared by length."""
    edges = [0.0, *sorted(cuts), seg.length]
    pieces = []
    for lo, hi in itertools.pairwise(edges):
        n = None if seg.n_elements is None else max(1, round(seg.n_elements * (hi - lo) / seg.length))
        pieces.append(seg.model_copy(update={"length": hi - lo, "n_elements": n}))
    return pieces


#: The line type that stands in, during a case's validation, for a named line type that failed its own checks (each
#: problem is reported once, at ``line_types.NAME``); checks on the line's physics (its weight) skip lines that use it.
STAND_IN = LineType(diameter=1.0, mass_per_length=1.0, axial_stiffness=1.0, name="stand-in for an invalid line type")


def resolve_sections(line, water_density: float, gravity: float):
    """The equivalent line of ``line`` without sections, for the models that take segments and attachments.

    Smeared buoyancy sections become segments of their own (:func:`smeared_line_type` of the cable under
    them), discrete ones attachments (:func:`module_attachments`); a segment is cut at the ends of each
    buoyancy section and at each stiffener's tip, so that nodes lie there. The stiffeners' EI is not in the
    segments: a discretised model adds it per element (:func:`element_bending_stiffness`). A line without
    sections is returned as it is.

    Raises :class:`~seacable.errors.InputError` when the whole line, modules included, would float.
    """
    if not line.sections:
        return line
    ends = line.segment_ends
    total = line.length
    segments, attachments = [], list(line.attachments)
    for k, seg in enumerate(line.segments):
        s0, s1 = ends[k], ends[k + 1]
        cuts = set()
        for sec in line.sections:
            if isinstance(sec, BuoyancySection):
                cuts.update(c for c in (sec.start, sec.end) if s0 + 1e-9 < c < s1 - 1e-9)
            elif isinstance(sec, (BendStiffener, BendRestrictor)):  # a stiffener's tip, a restrictor's far end
                tip = sec.length if sec.end == "A" else total - sec.length
                if s0 + 1e-9 < tip < s1 - 1e-9:
                    cuts.add(tip)
        for piece, lo in zip(_split_segment(seg, [c - s0 for c in cuts]), sorted({s0, *cuts})):
            mid = lo + 0.5 * piece.length
            for sec in line.sections:
                if isinstance(sec, BuoyancySection) and sec.start <= mid <= sec.end and \
                        sec.representation == "smeared":
                    piece = piece.model_copy(update={"line_type": smeared_line_type(
                        piece.line_type, sec, water_density, gravity)})
            segments.append(piece)
    for sec in line.sections:
        if isinstance(sec, BuoyancySection) and sec.representation == "discrete":
            mid = 0.5 * (sec.start + sec.end)
            k = min(int(np.searchsorted(ends, mid, side="right")) - 1, len(line.segments) - 1)
            attachments += module_attachments(line.segments[k].line_type, sec, water_density, gravity)
    out = type(line)(segments=tuple(segments), attachments=tuple(attachments))
    weight = sum(seg.length * seg.line_type.submerged_weight(water_density, gravity) for seg in out.segments) \
        + sum(a.net_weight(water_density, gravity) for a in out.attachments)
    scale = sum(seg.length * abs(seg.line_type.submerged_weight(water_density, gravity)) for seg in out.segments) \
        + sum(abs(a.net_weight(water_density, gravity)) for a in out.attachments)
    tied = any(isinstance(sec, (Clamp, Tether)) for sec in line.sections)  # ties to the seabed hold it down
    stand_in = any(seg.line_type.name == STAND_IN.name for seg in line.segments)  # its weight is not the user's
    if weight < -1e-9 * scale and not (tied or stand_in):  # a neutrally buoyant line (weight 0 to rounding) hangs, under tension
        lift = sum(-sec.count * sec.module.net_weight(water_density, gravity)
                   for sec in line.sections if isinstance(sec, BuoyancySection))
        raise InputError(
            f"the line's buoyancy sections would float the whole cable to the surface: its net weight in water, "
            f"modules included, is {weight:.6g} N (the modules lift {lift:.6g} N), {-weight:.6g} N short of "
            "sinking. Suggested fix: fewer or smaller modules (a longer pitch or a shorter section), or check "
            "the modules' net buoyancy (N, per module) and mass (kg).")
    return out

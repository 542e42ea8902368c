"""Sections along a line: buoyancy sections, bend stiffeners and bend restrictors (data model and equivalent line).

A dynamic power cable or umbilical is a bare cable with *sections* laid over it: a run of buoyancy
modules that lifts it into a lazy wave, and a bend stiffener at the hang-off. Both are given as the
cable maker specifies them and are mapped here onto what the finite-element line model already takes,
so the kernel runs them unchanged:

* a :class:`BuoyancySection` either ``smeared`` (:func:`smeared_line_type`: the modules spread over
  the section as equivalent per-length properties, a line type of its own over the section) or
  ``discrete`` (:func:`seacable.line.module_attachments`: one :class:`~seacable.line.PointMass` per module at its
  centre, with its own drag and added mass, on the bare cable);
* a :class:`BendStiffener` adds its bending stiffness, tapered along its length, to the cable's EI
  (:meth:`BendStiffener.stiffness`); a discretised model takes it at each element's mid arc length
  (:func:`element_bending_stiffness`), or its nonlinear moment-curvature law (``moment_curvature``, scaled along
  it by its EI's taper: :func:`element_moment_curvature`). With its material's ``density`` its own mass, displaced
  volume, drag diameter and added mass go on the elements it covers (:func:`element_section_properties`);
  without, it adds bending stiffness only;
* a :class:`BendRestrictor` (vertebrae) bends freely up to its locking curvature ``1 / locking_radius`` and then
  locks: its law (:func:`seacable.moment_curvature.lock_law`) adds a stiff branch beyond the lock, of
  ``lock_stiffness`` (by default :data:`LOCK_FACTOR` times the cable's EI) over the cable's own law; its mass,
  displaced volume, diameter and added mass go on its elements as a stiffener's.

:func:`seacable.line.resolve_sections` gives the equivalent line without sections (buoyancy sections as segments
of their own or as attachments; a segment split at a stiffener's tip so that a node lies there).

References
----------
DNV-RP-F401 (2021). Electrical power cables in subsea applications, sec. 4 (buoyancy and bend
stiffeners). Lozon, E. et al. (2025). Ocean Engineering 322, 120473 (the lazy-wave cables whose
buoyant section is a smeared equivalent cylinder). Seo, J. H. (2026). CableDyn 0.3.0: its
``EQUIVALENT BUOYANCY`` rows and ``lazy_wave_buoyancy_modules.dat`` (module drag areas
``Cd_n (D_m - d) L_m`` over the cable's own).
"""

from __future__ import annotations

import itertools
import math
from typing import Annotated, ClassVar, Literal

import numpy as np
from pydantic import Field, model_serializer, model_validator

from ._model import Model, quantity
from .errors import InputError
from .moment_curvature import check_table, law_sum, linear_law, lock_law
from .ties import Clamp, Tether

__all__ = ["LOCK_FACTOR", "BendRestrictor", "BendStiffener", "BuoyancyModule", "BuoyancySection", "Cone", "Section",
           "element_bending_stiffness", "element_moment_curvature", "element_section_properties", "smeared_line_type"]

#: A bend restrictor's stiffness beyond its lock, by default, as a multiple of the cable's EI (its law's initial
#: slope) where it sits: the curvature then passes the lock by at most 1 / LOCK_FACTOR of the curvature the bare
#: cable would take under the same moment, ``(M - M_cable(kappa)) / (LOCK_FACTOR EI)`` (0.1 %). [-]
LOCK_FACTOR = 1000.0


class BuoyancyModule(Model):
    """One buoyancy module clamped on the cable, as the cable maker specifies it.

    Parameters
    ----------
    length
        Length of the module along the cable. [m]
    diameter
        Outer diameter of the module. [m]
    mass
        Mass in air of one module (its clamp included). [kg]
    volume
        Volume the module displaces (the cable's own is not counted). [m^3]
    net_buoyancy
        Net buoyancy of one module in water, upthrust less weight, instead of ``volume``: the volume is then
        ``(net_buoyancy / g + mass) / rho``. [N]
    drag_normal
        Drag coefficient across the cable, on the area ``(diameter - d) * length`` the module adds to the
        cable's (d the cable's diameter, whose own drag the cable keeps). [-]
    drag_axial
        Drag coefficient along the cable, on the annulus ``pi / 4 (diameter^2 - d^2)`` of the module's ends. [-]
    added_mass
        Added-mass coefficient on the module's displaced volume (isotropic, as a point attachment's). [-]
    """

    length: quantity("m", gt=0, fix="give the module's length along the cable in metres, e.g. 2.0.") = Field(
        description="Module length along the cable. [m]")
    diameter: quantity("m", gt=0, fix="give the module's outer diameter in metres, e.g. 1.2.") = Field(
        description="Module outer diameter. [m]")
    mass: quantity("kg", ge=0) = Field(description="Mass in air of one module. [kg]")
    volume: quantity("m^3", gt=0) | None = Field(None, description="Displaced volume of one module. [m^3]")
    net_buoyancy: quantity("N") | None = Field(
        None, description="Net buoyancy of one module (upthrust less weight), instead of volume. [N]")
    drag_normal: quantity("-", ge=0) = Field(1.2, description="Drag coefficient across, on (D - d) L. [-]")
    drag_axial: quantity("-", ge=0) = Field(0.0, description="Drag coefficient along, on pi/4 (D^2 - d^2). [-]")
    added_mass: quantity("-", ge=0) = Field(1.0, description="Added-mass coefficient on the volume. [-]")

    @model_validator(mode="after")
    def _volume_or_buoyancy(self):
        if (self.volume is None) == (self.net_buoyancy is None):
            raise ValueError("a buoyancy module needs exactly one of 'volume' (m^3) and 'net_buoyancy' (N), got "
                             f"volume={self.volume}, net_buoyancy={self.net_buoyancy}. Suggested fix: give the "
                             "maker's net buoyancy in N (e.g. 'net_buoyancy: 3000') or the module's volume.")
        return self

    def displaced_volume(self, water_density: float, gravity: float) -> float:
        """The module's displaced volume, given or from its net buoyancy. [m^3]"""
        if self.volume is not None:
            return self.volume
        return (self.net_buoyancy / gravity + self.mass) / water_density

    def net_weight(self, water_density: float, gravity: float) -> float:
        """Net weight in water of one module, negative when it lifts. [N]"""
        if self.net_buoyancy is not None:
            return -self.net_buoyancy
        return (self.mass - water_density * self.volume) * gravity


class BuoyancySection(Model):
    """A run of identical buoyancy modules at a regular pitch along the line.

    The modules' centres lie at ``start + (k + 1/2) pitch``, ``k = 0 .. n - 1``, ``n = length / pitch``
    (a whole number).

    Parameters
    ----------
    start
        Arc length from end A where the section begins. [m]
    length
        Length of the section. [m]
    pitch
        Distance between module centres. [m]
    module
        The modules (:class:`BuoyancyModule`).
    representation
        ``"smeared"``: the modules spread over the section as equivalent per-length properties
        (:func:`smeared_line_type`); ``"discrete"``: a point attachment at each module's centre
        (:func:`seacable.line.module_attachments`), which gives the local bending between modules.
    name
        A label.
    """

    type: Literal["buoyancy"] = "buoyancy"
    start: quantity("m", ge=0, fix="give the arc length from end A where the modules begin.") = Field(
        description="Arc length from end A where the section begins. [m]")
    length: quantity("m", gt=0, fix="give the section's length in metres.") = Field(
        description="Section length. [m]")
    pitch: quantity("m", gt=0, fix="give the distance between module centres in metres.") = Field(
        description="Distance between module centres. [m]")
    module: BuoyancyModule
    representation: Literal["smeared", "discrete"] = Field(
        "smeared", description="smeared (equivalent per-length properties) or discrete (point attachments).")
    name: str | None = None

    @model_validator(mode="after")
    def _pitch(self):
        n = self.length / self.pitch
        if abs(n - round(n)) > 1e-6 * max(n, 1.0) or round(n) < 1:
            raise ValueError(f"the section's length {self.length:g} m must hold a whole number of pitches "
                             f"{self.pitch:g} m, got {n:.6g}. Suggested fix: set length to n x pitch, e.g. "
                             f"{max(round(n), 1) * self.pitch:g} m for {max(round(n), 1)} modules.")
        if self.module.length > self.pitch * (1 + 1e-9):
            raise ValueError(f"module length {self.module.length:g} m must not exceed the pitch {self.pitch:g} m "
                             "(modules would overlap). Suggested fix: check the pitch (centre to centre, in m).")
        return self

    @property
    def count(self) -> int:
        """Number of modules. [-]"""
        return round(self.length / self.pitch)

    @property
    def end(self) -> float:
        """Arc length from end A where the section ends. [m]"""
        return self.start + self.length

    def module_centres(self) -> np.ndarray:
        """Arc lengths from end A of the modules' centres. [m]"""
        return self.start + (np.arange(self.count) + 0.5) * self.pitch


class Cone(Model):
    """A conical bend stiffener: outer diameter linear from root to tip over a bore that is the cable.

    Its own bending stiffness is ``E pi / 64 (D(x)^4 - d^4)`` at distance x from the root, d the cable's
    diameter.
    """

    root_diameter: quantity("m", gt=0, fix="give the stiffener's outer diameter at its root in metres.") = Field(
        description="Outer diameter at the root (the end of the line). [m]")
    tip_diameter: quantity("m", gt=0, fix="give the stiffener's outer diameter at its tip in metres.") = Field(
        description="Outer diameter at the tip. [m]")
    modulus: quantity("Pa", gt=0, fix="give the material's Young's modulus in Pa, e.g. 5e7 for polyurethane.") = \
        Field(description="Young's modulus of the stiffener's material. [Pa]")


class _AtLineEnd:
    """What a section running ``length`` from one end of the line (``end``, "A" or "B") does: a bend stiffener, a
    bend restrictor (``_NOUN`` names it in messages)."""

    _NOUN: ClassVar[str] = "section"

    def distance_from_root(self, s, line_length: float):
        """Distance from the end it runs from (its root) of points at arc lengths ``s`` from end A. [m]"""
        s = np.asarray(s, float)
        return s if self.end == "A" else line_length - s

    def check_on(self, line) -> None:
        """Refuse a section longer than the segment at its end."""
        k = 0 if self.end == "A" else len(line.segments) - 1
        seg = line.segments[k]
        if self.length > seg.length * (1 + 1e-9):
            noun = self._NOUN.split()[-1]
            raise ValueError(f"the {self._NOUN} at end {self.end} is {self.length:g} m long, longer than the "
                             f"segment it sits on (line.segments[{k}], {seg.length:g} m). Suggested fix: "
                             f"shorten the {noun}, or make that segment at least {self.length:g} m long.")


class BendStiffener(_AtLineEnd, Model):
    """A bend stiffener at one end of the line: bending stiffness over the cable's own, tapered along it.

    Parameters
    ----------
    end
        The end of the line it sits at, ``"A"`` or ``"B"`` (its root there).
    length
        Length from the end to its tip. [m]
    table
        ``(x, EI)`` pairs, x the distance from the root (0 to ``length``, increasing) and EI the stiffener's
        own bending stiffness there, added to the cable's; linear between pairs. [m, N m^2]
    cone
        Instead of ``table``: a cone (:class:`Cone`) of root and tip diameters and a modulus.
    moment_curvature
        Optional nonlinear law of the stiffener's material at its root, ``(kappa [1/m], M [N m])`` pairs from
        ``(0, 0)`` (:func:`seacable.moment_curvature.check_table`; its initial slope the root's EI, within 2 %),
        scaled along the stiffener by its EI's taper: ``M(x, kappa) = EI(x) / EI(0) M_root(kappa)``; added to the
        cable's law. [1/m, N m]
    density
        Density of the stiffener's material (polyurethane: about 1150). With it the stiffener's own mass
        ``density A_s(x)``, displaced area ``A_s(x)`` (``A_s = pi / 4 (D(x)^2 - d^2)``, the annulus over the cable),
        drag diameter ``D(x)`` and added mass (on ``pi / 4 D(x)^2``) are on the elements it covers
        (:func:`element_section_properties`); without, only its EI. [kg/m^3]
    geometry
        A table stiffener's outer diameter along it, ``(x [m] from the root, D [m])`` pairs from 0 to ``length``,
        linear between (a cone has its own); needed with ``density``. [m, m]
    name
        A label.
    """

    _NOUN: ClassVar[str] = "bend stiffener"
    type: Literal["bend_stiffener"] = "bend_stiffener"
    end: Literal["A", "B"] = Field("B", description="End of the line with the stiffener's root.")
    length: quantity("m", gt=0, fix="give the stiffener's length from the end to its tip in metres.") = Field(
        description="Length from the end to the tip. [m]")
    table: tuple[tuple[float, float], ...] | None = Field(
        None, description="(x [m] from the root, stiffener EI [N m^2]) pairs, added to the cable's EI.")
    cone: Cone | None = Field(None, description="Cone geometry instead of a table.")
    moment_curvature: tuple[tuple[float, float], ...] | None = Field(
        None, description="Nonlinear law at the root, (curvature [1/m], moment [N m]) pairs from (0, 0), scaled "
                          "along by the EI taper.")
    density: quantity("kg/m^3", gt=0, fix="give the material's density in kg/m^3, e.g. 1150 for polyurethane.") | \
        None = Field(None, description="Density of the stiffener's material: its mass and buoyancy on the line. "
                                       "[kg/m^3]")
    geometry: tuple[tuple[float, float], ...] | None = Field(
        None, description="(x [m] from the root, outer diameter [m]) pairs of a table stiffener.")
    name: str | None = None

    @model_serializer(mode="wrap")
    def _omit_unset(self, handler):
        # a stiffener without a law, a density or a geometry is written as before they existed (a result's case
        # attribute unchanged)
        data = handler(self)
        if isinstance(data, dict):
            for key in ("moment_curvature", "density", "geometry"):
                if data.get(key, 0) is None:
                    del data[key]
        return data

    @model_validator(mode="after")
    def _law_and_geometry(self):
        where = f"the bend stiffener at end {self.end}"
        if (self.table is None) == (self.cone is None):
            return self  # refused by _one_law
        if self.moment_curvature is not None:
            half = check_table(self.moment_curvature, f"{where}: moment_curvature")
            slope = half[1][1] / half[1][0]
            ei0 = float(self.table[0][1]) if self.table is not None else math.nan
            if self.table is not None and not abs(slope - ei0) <= 0.02 * ei0:
                raise ValueError(f"{where}: its moment_curvature starts at slope {slope:.6g} N m^2, but its EI at the "
                                 f"root is {ei0:.6g} N m^2 (table). Suggested fix: give the law of the root "
                                 "section, whose initial slope M/kappa is the table's first EI.")
        if self.geometry is not None:
            if self.cone is not None:
                raise ValueError(f"{where} is a cone, whose geometry is its root and tip diameters: 'geometry' is "
                                 "not used. Suggested fix: leave 'geometry' out.")
            g = self.geometry
            for k, (x, dia) in enumerate(g):
                if not (math.isfinite(x) and math.isfinite(dia)) or dia <= 0 or (k and x <= g[k - 1][0]):
                    raise ValueError(f"{where}: geometry[{k}] must be (x [m], D [m]) with D > 0 m and x larger than the "
                                     f"x before, got ({x}, {dia}). Suggested fix: sort the pairs by distance from "
                                     "the root, diameters in metres.")
            if len(g) < 2 or abs(g[0][0]) > 1e-9 * self.length or abs(g[-1][0] - self.length) > 1e-6 * self.length:
                raise ValueError(f"{where}: geometry must run from x = 0 (the root) to x = length = {self.length:g} "
                                 f"m, got {g[0][0]:g} to {g[-1][0]:g} m. Suggested fix: give the outer diameter "
                                 "at the root and at the tip at least.")
        if self.density is not None and self.cone is None and self.geometry is None:
            raise ValueError(f"{where} has a density ({self.density:g} kg/m^3) but no geometry for its mass: a "
                             "table of EI holds no diameters. Suggested fix: give 'geometry' ((x [m], outer "
                             "diameter [m]) pairs from the root to the tip), or a 'cone' instead of the table.")
        return self

    def root_law(self):
        """The half law at the root (:func:`seacable.moment_curvature.check_table`), or None. [1/m, N m]"""
        if self.moment_curvature is None:
            return None
        return np.array(check_table(self.moment_curvature, "moment_curvature"), float)

    def outer_diameter(self, x, cable_diameter: float):
        """Outer diameter at distance ``x`` from the root (the cable's beyond the tip); None without geometry. [m]"""
        x = np.asarray(x, float)
        if self.cone is not None:
            c = self.cone
            dia = c.root_diameter + (c.tip_diameter - c.root_diameter) * np.clip(x / self.length, 0.0, 1.0)
        elif self.geometry is not None:
            xs, ds = np.array(self.geometry, float).T
            dia = np.interp(x, xs, ds)
        else:
            return None
        return np.where((x >= 0) & (x <= self.length), np.maximum(dia, cable_diameter), cable_diameter)

    def geometry_knots(self) -> np.ndarray:
        """Distances from the root where the outer diameter's slope changes. [m]"""
        if self.geometry is not None:
            return np.array([x for x, _ in self.geometry], float)
        return np.array([0.0, self.length])

    @model_validator(mode="after")
    def _one_law(self):
        if (self.table is None) == (self.cone is None):
            raise ValueError("a bend stiffener needs exactly one of 'table' ((x, EI) pairs) and 'cone' (root and "
                             "tip diameters, modulus). Suggested fix: give the maker's EI table, e.g. "
                             "'table: [[0, 2.0e5], [4, 1.0e3]]'.")
        if self.table is not None:
            t = self.table
            if len(t) < 2:
                raise ValueError(f"a bend stiffener's table needs at least 2 (x, EI) pairs, got {len(t)}. "
                                 "Suggested fix: give EI at the root (x = 0) and at the tip.")
            for k, (x, ei) in enumerate(t):
                if not (math.isfinite(x) and math.isfinite(ei)) or ei < 0:
                    raise ValueError(f"table[{k}] must be finite x [m] and EI >= 0 [N m^2], got ({x}, {ei}). "
                                     "Suggested fix: give EI in N m^2.")
                if k and x <= t[k - 1][0]:
                    raise ValueError(f"table[{k}] x = {x:g} m must be larger than the x before, {t[k - 1][0]:g} m. "
                                     "Suggested fix: sort the pairs by distance from the root.")
            if abs(t[0][0]) > 1e-9 * self.length or abs(t[-1][0] - self.length) > 1e-6 * self.length:
                raise ValueError(f"the table must run from x = 0 (the root) to x = length = {self.length:g} m, got "
                                 f"{t[0][0]:g} to {t[-1][0]:g} m. Suggested fix: give x from the root, ending "
                                 "at the tip.")
        elif self.cone.tip_diameter > self.cone.root_diameter:
            raise ValueError(f"cone.tip_diameter {self.cone.tip_diameter:g} m must not exceed root_diameter "
                             f"{self.cone.root_diameter:g} m: a stiffener tapers towards its tip. Suggested fix: "
                             "swap them.")
        return self

    def stiffness(self, x, cable_diameter: float):
        """The stiffener's own EI at distance ``x`` from its root (0 beyond its tip), vectorised. [N m^2]"""
        x = np.asarray(x, float)
        inside = (x >= 0) & (x <= self.length)
        if self.table is not None:
            xs, es = np.array(self.table, float).T
            ei = np.interp(x, xs, es)
        else:
            c = self.cone
            dia = c.root_diameter + (c.tip_diameter - c.root_diameter) * np.clip(x / self.length, 0.0, 1.0)
            ei = c.modulus * math.pi / 64.0 * np.maximum(dia**4 - cable_diameter**4, 0.0)
        return np.where(inside, ei, 0.0)



class BendRestrictor(_AtLineEnd, Model):
    """A bend restrictor (interlocking vertebrae) at one end of the line: free to bend up to its locking radius,
    then locked.

    Its own law (:func:`seacable.moment_curvature.lock_law`), added to the cable's, is no moment up to the locking
    curvature ``1 / locking_radius`` and a stiff branch ``lock_stiffness (kappa - 1 / locking_radius)`` beyond, so
    that the curvature passes the lock only by ``(M - M_cable) / lock_stiffness``.

    Parameters
    ----------
    end
        The end of the line it sits at, ``"A"`` or ``"B"``, from which it runs ``length``.
    length
        Its length from the end. [m]
    locking_radius
        Bend radius at which the vertebrae lock. [m]
    lock_stiffness
        Bending stiffness of the locked branch; None: :data:`LOCK_FACTOR` times the cable's EI (its law's initial
        slope) at each element. [N m^2]
    diameter
        Outer diameter of the vertebrae: the drag diameter, and the added mass's (flooded vertebrae carry the water
        inside them, ``pi / 4 D^2``). [m]
    mass_per_length
        Mass in air of the vertebrae per length of cable. [kg/m]
    density
        Density of the vertebrae's material: their displaced volume per length is ``mass_per_length / density``.
        [kg/m^3]
    name
        A label.
    """

    _NOUN: ClassVar[str] = "bend restrictor"
    type: Literal["bend_restrictor"] = "bend_restrictor"
    end: Literal["A", "B"] = Field("B", description="End of the line it runs from.")
    length: quantity("m", gt=0, fix="give the restrictor's length from the end in metres.") = Field(
        description="Length from the end. [m]")
    locking_radius: quantity("m", gt=0, fix="give the bend radius at which the vertebrae lock in metres, e.g. "
                                            "2.5 (above the cable's MBR).") = Field(
        description="Bend radius at which the vertebrae lock. [m]")
    lock_stiffness: quantity("N m^2", gt=0, fix="give the locked branch's stiffness in N m^2, or leave it out "
                                                "(1000 times the cable's EI).") | None = Field(
        None, description="Bending stiffness beyond the lock; None: LOCK_FACTOR times the cable's EI. [N m^2]")
    diameter: quantity("m", gt=0, fix="give the vertebrae's outer diameter in metres.") = Field(
        description="Outer diameter of the vertebrae. [m]")
    mass_per_length: quantity("kg/m", ge=0) = Field(0.0, description="Mass in air per length. [kg/m]")
    density: quantity("kg/m^3", gt=0, fix="give the vertebrae's material density in kg/m^3, e.g. 1150 for "
                                          "polyurethane, 7850 for steel.") = Field(
        1150.0, description="Density of the vertebrae's material. [kg/m^3]")
    name: str | None = None



# clamps and tethers to the seabed (:mod:`seacable.ties`) are sections too: the finite-element line takes them
Section = Annotated[BuoyancySection | BendStiffener | BendRestrictor | Clamp | Tether, Field(discriminator="type")]


def smeared_line_type(line_type, section: BuoyancySection, water_density: float, gravity: float):
    """The line type of a cable with a section's modules spread over it: per-length equivalents.

    Per unit length, with p the pitch, d, A the cable's diameter and area, and a module of length
    L_m, diameter D_m, mass m_m, volume V_m and net weight W_m in water:

    * mass ``m + m_m / p``; displaced area ``A_eq = A + V_m / p``, whose diameter ``D_eq`` is the line type's
      (volume-equivalent) diameter; weight in water ``w + W_m / p`` (``w`` the cable's, given or derived);
    * normal drag ``C_dn,eq D_eq = C_dn d + C_d,m (D_m - d) L_m / p`` and axial drag
      ``pi C_dt,eq D_eq = pi C_dt d + C_a,m pi / 4 (D_m^2 - d^2) / p``, the totals of the bare cable and of the
      modules as attachments (:func:`seacable.line.module_attachments`);
    * added mass ``C_an,eq A_eq = C_an A + C_m V_m / p`` normal and ``C_at,eq A_eq = C_at A + C_m V_m / p``
      along (a module's added mass is isotropic).

    Bending and axial stiffness, breaking load and the rest are the cable's.
    """
    mod, p = section.module, section.pitch
    d, a = line_type.diameter, line_type.area
    vol = mod.displaced_volume(water_density, gravity)
    a_eq = a + vol / p
    d_eq = math.sqrt(4.0 * a_eq / math.pi)
    cdn, cdt = line_type.effective_drag()
    ring = max(mod.diameter - d, 0.0)
    annulus = 0.25 * math.pi * max(mod.diameter**2 - d**2, 0.0)
    weight = line_type.submerged_weight(water_density, gravity) + mod.net_weight(water_density, gravity) / p
    return line_type.model_copy(update={
        "diameter": d_eq,
        "mass_per_length": line_type.mass_per_length + mod.mass / p,
        "weight_in_water": weight,
        "drag_normal": (cdn * d + mod.drag_normal * ring * mod.length / p) / d_eq,
        "drag_tangential": (math.pi * cdt * d + mod.drag_axial * annulus / p) / (math.pi * d_eq),
        "drag_law": "morison", "fairing_chord": None, "strumming_amplitude": 0.0,
        "added_mass_normal": (line_type.added_mass_normal * a + mod.added_mass * vol / p) / a_eq,
        "added_mass_tangential": (line_type.added_mass_tangential * a + mod.added_mass * vol / p) / a_eq,
        "name": f"{line_type.name or 'cable'} + {section.name or 'buoyancy'} (smeared)"})


def element_bending_stiffness(line, s, cable_ei, *, min_elements: int = 4):
    """EI per element of a discretised line: the cable's plus each stiffener's at the element's mid arc length.

    Parameters
    ----------
    line
        The line with its sections.
    s
        Unstretched arc lengths of the nodes from end A. [m]
    cable_ei
        The cable's EI per element (from the elements' line types). [N m^2]
    min_elements
        Fewest elements a stiffener must span; fewer is refused with the element length needed. [-]

    Returns the EI per element [N m^2], or ``cable_ei`` itself when the line has no stiffener.
    """
    stiffeners = [sec for sec in line.sections if isinstance(sec, BendStiffener)]
    if not stiffeners:
        return cable_ei
    s = np.asarray(s, float)
    mid = 0.5 * (s[:-1] + s[1:])
    ends = np.asarray(line.segment_ends)
    seg_of = np.clip(np.searchsorted(ends, mid, side="right") - 1, 0, len(line.segments) - 1)
    dia = np.array([line.segments[k].line_type.diameter for k in seg_of])
    ei = np.zeros(len(mid)) if cable_ei is None else np.array(cable_ei, float)
    for sec in stiffeners:
        x = sec.distance_from_root(mid, line.length)
        over = int(np.count_nonzero((x >= 0) & (x <= sec.length)))
        if over < min_elements:
            raise InputError(
                f"the mesh is too coarse for the bend stiffener at end {sec.end}: {over} element(s) over its "
                f"{sec.length:g} m, at least {min_elements} are needed to follow its taper. Suggested fix: "
                f"elements of at most {sec.length / min_elements:.4g} m there (the segment's n_elements, or the "
                "analysis's element_length / n_elements).")
        ei = ei + sec.stiffness(x, 0.0) if sec.cone is None else ei + np.array(
            [float(sec.stiffness(xx, dd)) for xx, dd in zip(x, dia)])
    return ei


def _covered(sec, s, line_length):
    """Per element (nodes at arc lengths ``s``): the distances from the section's root of its ends, ``(xa, xb)``,
    clipped to the section (``xa == xb`` where the element lies outside it). [m]"""
    xa = np.clip(sec.distance_from_root(s[:-1], line_length), 0.0, sec.length)
    xb = np.clip(sec.distance_from_root(s[1:], line_length), 0.0, sec.length)
    return np.minimum(xa, xb), np.maximum(xa, xb)


def _mean_over(f, lo, hi, knots, length):
    """Integral of ``f`` (quadratic between ``knots``) from ``lo`` to ``hi``, over ``length``, per element: exact
    (Simpson's rule on each piece between knots)."""
    out = np.zeros(len(lo))
    for e in np.flatnonzero(hi > lo):
        edges = np.unique(np.r_[lo[e], knots[(knots > lo[e]) & (knots < hi[e])], hi[e]])
        for a, b in itertools.pairwise(edges):
            out[e] += (b - a) / 6.0 * (f(a) + 4.0 * f(0.5 * (a + b)) + f(b))
    return out / length


def element_section_properties(line, s, types, water_density: float, gravity: float):
    """The elements' own mass, weight, drag and added mass with the bend stiffeners (with a ``density``) and bend
    restrictors over them; None when the line has none.

    Over an element of length h of a cable of diameter d, area A, mass m, weight w, drag C_dn, C_dt and added mass
    C_an, C_at, a sheath of outer diameter D(x), material area A_s(x) (a stiffener's ``pi / 4 (D^2 - d^2)``, a
    restrictor's ``mass_per_length / density``) and material density rho_s gives, with ``<f>`` the mean over the
    element (exact for a cone: :func:`_mean_over`; 0 beyond the section's end)::

        m' = m + <rho_s A_s>,   w' = w + <(rho_s - rho) g A_s>,   A' = A + <A_s>,   d' = sqrt(4 A' / pi)
        C_dn' d' = C_dn <D>,    C_dt' d' = C_dt <D>,             C_an' A' = C_an <pi / 4 D^2> (and C_at')

    (the drag on the outer diameter, the added mass on its envelope; the sheath's own coefficients are the cable's).

    Returns a dict of per-element arrays ``mass_per_length`` [kg/m], ``weight_per_length`` [N/m], ``diameter`` [m],
    ``cdn``, ``cdt``, ``can``, ``cat`` [-].
    """
    sheaths = [sec for sec in line.sections if isinstance(sec, BendRestrictor)
               or (isinstance(sec, BendStiffener) and sec.density is not None)]
    if not sheaths:
        return None
    s = np.asarray(s, float)
    h = np.diff(s)
    d = np.array([t.diameter for t in types], float)
    area = 0.25 * math.pi * d**2
    drag = np.array([t.effective_drag() for t in types], float)
    out = {"mass_per_length": np.array([t.mass_per_length for t in types], float),
           "weight_per_length": np.array([t.submerged_weight(water_density, gravity) for t in types], float)}
    a_s = np.zeros(len(h))
    dia = d.copy()            # <D> over the element: the cable's where no sheath
    env = area.copy()         # <pi / 4 D^2>
    for sec in sheaths:
        lo, hi = _covered(sec, s, line.length)
        share = (hi - lo) / h
        if isinstance(sec, BendRestrictor):
            mat = sec.mass_per_length / sec.density * share
            rho_s = sec.density
            dia += (sec.diameter - d) * share
            env += (0.25 * math.pi * sec.diameter**2 - area) * share
        else:
            rho_s = sec.density
            knots = sec.geometry_knots()
            mat = np.zeros(len(h))
            for e in np.flatnonzero(hi > lo):
                def ring(x, sec=sec, de=d[e]):
                    return 0.25 * math.pi * (float(sec.outer_diameter(x, de)) ** 2 - de**2)

                def over(x, sec=sec, de=d[e]):
                    return float(sec.outer_diameter(x, de)) - de

                mat[e] = _mean_over(ring, lo[e:e + 1], hi[e:e + 1], knots, h[e])[0]
                dia[e] += _mean_over(over, lo[e:e + 1], hi[e:e + 1], knots, h[e])[0]
            env += mat
        a_s += mat
        out["mass_per_length"] = out["mass_per_length"] + rho_s * mat
        out["weight_per_length"] = out["weight_per_length"] + (rho_s - water_density) * gravity * mat
    a_eq = area + a_s
    d_eq = np.sqrt(4.0 * a_eq / math.pi)
    out["diameter"] = d_eq
    out["cdn"] = drag[:, 0] * dia / d_eq
    out["cdt"] = drag[:, 1] * dia / d_eq
    out["can"] = np.array([t.added_mass_normal for t in types], float) * env / a_eq
    out["cat"] = np.array([t.added_mass_tangential for t in types], float) * env / a_eq
    return out


def element_moment_curvature(line, s, types, element_ei):
    """The elements' nonlinear moment-curvature laws (:mod:`seacable.moment_curvature`), or None when none has one.

    An element has a law when its line type has one (``LineType.moment_curvature``), or a bend stiffener with a
    ``moment_curvature`` or a bend restrictor covers its mid arc length; the law is then the sum of the cable's (its
    law, else ``EI kappa``), the stiffener's (its root law scaled by ``EI(x) / EI(0)``, else its ``EI(x) kappa``:
    ``element_ei`` less the cable's) and the restrictor's (:func:`seacable.moment_curvature.lock_law`, its
    ``lock_stiffness`` or :data:`LOCK_FACTOR` times the cable's EI). The other elements: None (linear).

    Parameters
    ----------
    line
        The line with its sections.
    s
        Unstretched arc lengths of the nodes from end A. [m]
    types
        The line type of each element.
    element_ei
        EI per element, stiffeners included (:func:`element_bending_stiffness`), or None. [N m^2]
    """
    own = [None if t.moment_curvature is None else np.array(check_table(t.moment_curvature, "moment_curvature"))
           for t in types]
    restrictors = [sec for sec in line.sections if isinstance(sec, BendRestrictor)]
    with_law = [sec for sec in line.sections if isinstance(sec, BendStiffener) and sec.moment_curvature is not None]
    if all(o is None for o in own) and not restrictors and not with_law:
        return None
    s = np.asarray(s, float)
    mid = 0.5 * (s[:-1] + s[1:])
    n = len(mid)
    cable_ei = np.array([o[1, 1] / o[1, 0] if o is not None else t.bending_stiffness for o, t in zip(own, types)])
    given_ei = np.array([t.bending_stiffness for t in types], float)   # what element_ei starts from
    added_ei = np.zeros(n) if element_ei is None else np.asarray(element_ei, float) - given_ei  # the stiffeners'
    parts = [[own[e] if own[e] is not None else linear_law(cable_ei[e])] for e in range(n)]
    has = [own[e] is not None for e in range(n)]
    stiff = np.zeros(n)   # the EI of the stiffeners with a law, taken out of the linear rest
    for sec in with_law:
        x = sec.distance_from_root(mid, line.length)
        root = sec.root_law()
        ei0 = float(sec.stiffness(0.0, types[-1 if sec.end == "B" else 0].diameter))
        slope = root[1, 1] / root[1, 0]
        if not abs(slope - ei0) <= 0.02 * ei0:
            raise InputError(f"the bend stiffener at end {sec.end}: its moment_curvature starts at slope {slope:.6g} "
                             f"N m^2, but its cone's EI at the root is {ei0:.6g} N m^2 (E pi / 64 (D^4 - d^4)). "
                             "Suggested fix: give the law of the root section, or check the cone's modulus and "
                             "diameters.")
        for e in np.flatnonzero((x >= 0) & (x <= sec.length)):
            ei_x = float(sec.stiffness(x[e], types[e].diameter))
            parts[e].append(root * [1.0, ei_x / ei0])
            stiff[e] += ei_x
            has[e] = True
    for sec in restrictors:
        x = sec.distance_from_root(mid, line.length)
        for e in np.flatnonzero((x >= 0) & (x <= sec.length)):
            k = sec.lock_stiffness if sec.lock_stiffness is not None else LOCK_FACTOR * cable_ei[e]
            if not k > 0:
                raise InputError(f"the bend restrictor at end {sec.end} sits on a cable without bending stiffness, "
                                 "so its lock stiffness (1000 times the cable's EI by default) is 0 N m^2. Suggested "
                                 "fix: give 'lock_stiffness' in N m^2, or the cable's bending_stiffness.")
            parts[e].append(lock_law(sec.locking_radius, k))
            has[e] = True
    laws = []
    for e in range(n):
        if not has[e]:
            laws.append(None)
            continue
        rest = added_ei[e] - stiff[e]   # the stiffeners' without a law
        terms = parts[e] + ([linear_law(rest)] if abs(rest) > 1e-12 * max(cable_ei[e], 1.0) else [])
        laws.append(_simplified(law_sum(terms)))
    return tuple(laws)


def _simplified(law: np.ndarray) -> np.ndarray:
    """The law without inner knots where its slope does not change (to 1e-12), at least two knots kept."""
    k, m = law[:, 0], law[:, 1]
    slopes = np.diff(m) / np.diff(k)
    keep = [0]
    for j in range(1, len(k) - 1):
        if abs(slopes[j] - slopes[j - 1]) > 1e-12 * max(abs(slopes[j]), abs(slopes[j - 1]), 1e-300):
            keep.append(j)
    keep.append(len(k) - 1)
    return law[keep]

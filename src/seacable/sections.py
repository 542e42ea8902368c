"""Sections along a line: buoyancy sections and bend stiffeners (data model and their equivalent line).

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
  (:func:`element_bending_stiffness`).

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

import math
from typing import Annotated, Literal

import numpy as np
from pydantic import Field, model_validator

from ._model import Model, quantity
from .errors import InputError
from .ties import Clamp, Tether

__all__ = ["BendStiffener", "BuoyancyModule", "BuoyancySection", "Cone", "Section", "element_bending_stiffness",
           "smeared_line_type"]


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


class BendStiffener(Model):
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
    name
        A label.
    """

    type: Literal["bend_stiffener"] = "bend_stiffener"
    end: Literal["A", "B"] = Field("B", description="End of the line with the stiffener's root.")
    length: quantity("m", gt=0, fix="give the stiffener's length from the end to its tip in metres.") = Field(
        description="Length from the end to the tip. [m]")
    table: tuple[tuple[float, float], ...] | None = Field(
        None, description="(x [m] from the root, stiffener EI [N m^2]) pairs, added to the cable's EI.")
    cone: Cone | None = Field(None, description="Cone geometry instead of a table.")
    name: str | None = None

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

    def distance_from_root(self, s, line_length: float):
        """Distance from the root of points at arc lengths ``s`` from end A. [m]"""
        s = np.asarray(s, float)
        return s if self.end == "A" else line_length - s

    def check_on(self, line) -> None:
        """Refuse a stiffener longer than the segment at its end."""
        k = 0 if self.end == "A" else len(line.segments) - 1
        seg = line.segments[k]
        if self.length > seg.length * (1 + 1e-9):
            raise ValueError(f"the bend stiffener at end {self.end} is {self.length:g} m long, longer than the "
                             f"segment it sits on (line.segments[{k}], {seg.length:g} m). Suggested fix: "
                             f"shorten the stiffener, or make that segment at least {self.length:g} m long.")


# clamps and tethers to the seabed (:mod:`seacable.ties`) are sections too: the finite-element line takes them
Section = Annotated[BuoyancySection | BendStiffener | Clamp | Tether, Field(discriminator="type")]


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

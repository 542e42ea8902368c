"""A mooring system: points, rigid bodies and the lines between them (the input data model).

A :class:`MooringSystem` is what a mooring engineer draws: anchors and other fixed points, free
connection points (clump weights, buoys, the junction of two line types), points that follow a
vessel, rigid bodies (a spar, a semi-submersible, a buoy) with points fixed on them, and lines
from one point to another. The same data model serves the statics (:mod:`seacable.system.statics`),
the offsets and watch circle, and the coupled dynamics; MoorDyn files are read into it
(:func:`seacable.io.moordyn.moordyn_system`).

Conventions (as the rest of seacable): SI units, Z up, z = 0 at the still water level. A body's
``position`` is its reference point (x, y, z) and its rotation (roll, pitch, yaw) about the global
x, y and z axes applied in the order roll, then pitch, then yaw (the rotation matrix
``Rz(yaw) Ry(pitch) Rx(roll)``, as MoorPy and MoorDyn). Body-frame vectors (centre of gravity,
centre of buoyancy, points on the body) are given relative to the reference point in body axes.
Six-component forces are (Fx, Fy, Fz, Mx, My, Mz) in global axes about the reference point.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Literal

import numpy as np
from pydantic import Field, field_validator, model_serializer, model_validator

from .._model import Model, quantity, suggest, unit_float
from ..line import Line
from ..mooring.ends import EndCondition

__all__ = ["Body", "BodyCurrent", "BodyHydrodynamics", "BodyWind", "MooringSystem", "SystemLine", "SystemPoint", "bodies_without_lines"]

_XYZ = tuple[unit_float("m"), unit_float("m"), unit_float("m")]
_SIX = tuple[float, float, float, float, float, float]
#: x, y, z [m], roll, pitch, yaw [rad]
_POSE = tuple[unit_float("m"), unit_float("m"), unit_float("m"), unit_float("rad"), unit_float("rad"), unit_float("rad")]
_FORCE = tuple[(unit_float("N"),) * 3]
_MATRIX6 = tuple[_SIX, _SIX, _SIX, _SIX, _SIX, _SIX]


def _finite(where: str, values, unit: str) -> None:
    flat = np.asarray(values, float).ravel()
    if not np.all(np.isfinite(flat)):
        raise ValueError(f"{where} must hold finite numbers in {unit}, got {tuple(values)}.")


class SystemPoint(Model):
    """A point of the system that lines end at.

    Parameters
    ----------
    kind
        ``fixed`` (an anchor, or any point held in space), ``free`` (a connection point, clump
        weight or buoy that finds its own equilibrium), ``coupled`` (follows a vessel: held at
        ``position`` in statics, moved by the dynamics' motion) or ``body`` (fixed on the body
        named by ``body``).
    position
        Global (x, y, z) for fixed, free and coupled points (the starting guess of a free point);
        for a point on a body, (x, y, z) relative to the body's reference point in body axes. [m]
    body
        The body a ``kind: body`` point is fixed on.
    mass
        Mass in air of what sits at the point (clump, buoy, shackle). [kg]
    volume
        Displaced volume of what sits at the point. [m^3]
    external_force
        Constant force on the point, global axes. [N]
    drag_area
        Drag coefficient times frontal area, C_D A, used by the dynamics. [m^2]
    added_mass
        Added mass, used by the dynamics. [kg]
    """

    kind: Literal["fixed", "free", "coupled", "body"] = Field(description="fixed, free, coupled or body.")
    position: _XYZ = Field(description="Position (global, or in body axes for a point on a body). [m]")
    body: str | None = Field(None, description="The body a 'kind: body' point is fixed on.")
    mass: quantity("kg", ge=0) = Field(0.0, description="Mass in air at the point. [kg]")
    volume: quantity("m^3", ge=0) = Field(0.0, description="Displaced volume at the point. [m^3]")
    external_force: _FORCE = Field((0.0, 0.0, 0.0), description="Constant external force. [N]")
    drag_area: quantity("m^2", ge=0) = Field(0.0, description="C_D A for the dynamics. [m^2]")
    added_mass: quantity("kg", ge=0) = Field(0.0, description="Added mass for the dynamics. [kg]")

    @model_validator(mode="after")
    def _check(self):
        _finite("position", self.position, "m")
        _finite("external_force", self.external_force, "N")
        if self.kind == "body" and self.body is None:
            raise ValueError("a point of kind 'body' needs 'body:' naming the body it is fixed on.")
        if self.kind != "body" and self.body is not None:
            raise ValueError(f"'body: {self.body}' is only for points of kind 'body', this one is "
                             f"'{self.kind}'. Suggested fix: set 'kind: body' or drop 'body'.")
        return self

    def net_weight(self, water_density: float, gravity: float) -> float:
        """Weight minus buoyancy of what sits at the point, fully submerged. [N]"""
        return (self.mass - water_density * self.volume) * gravity


class BodyHydrodynamics(Model):
    """A body's hydrodynamic database and what the dynamics take from it (issue 39, :mod:`seacable.hydro`).

    The database (WAMIT's files ``FILE.1``, ``.hst``, and ``.3`` and a mean drift file when the run has waves, or
    a Capytaine dataset ``FILE.nc``) gives the body its hydrostatic stiffness and infinite-frequency added mass
    (instead of ``waterplane_*``, ``hydrostatic_stiffness`` and ``added_mass``), and in ``system_dynamic`` its
    radiation memory (Cummins), the first-order wave force in the case's waves and the mean or slow drift (Newman,
    or the full difference-frequency QTF of WAMIT's ``.12d``). The coefficients are about the body's reference
    point, in its axes. WAMIT's hydrostatics hold the waterplane and the buoyancy's moment, and the weight's moment
    only when the WAMIT run had the body's centre of gravity; Capytaine's hold the weight's moment from its centre
    of mass (``weight_in_hydrostatics``: by default false for WAMIT, true for Capytaine; when false the moment is
    added from ``mass`` and ``center_of_gravity``, as OpenFAST does).
    """

    file: str = Field(description="WAMIT output's root (the path without '.1', '.3', '.hst') or a Capytaine NetCDF "
                                  "dataset (.nc), relative to the case file.")
    format: Literal["wamit", "capytaine"] | None = Field(
        None, description="The database's format: wamit or capytaine; by default capytaine for a file ending in .nc, "
                          "else wamit.")
    ulen: quantity("m", gt=0, fix="give WAMIT's length scale ULEN in metres (HydroDyn's WAMITULEN).") = Field(
        1.0, description="WAMIT's length scale ULEN. [m]")
    kernel_length: quantity("s", gt=0) = Field(60.0, description="Length of the radiation memory kept. [s]")
    weight_in_hydrostatics: bool | None = Field(
        None, description="The database's hydrostatics already hold the weight's moment (default: false for WAMIT, "
                          "true for Capytaine).")
    excitation: bool = Field(True, description="First-order wave force from the database in the case's waves.")
    drift: Literal["none", "mean", "newman", "qtf"] = Field(
        "newman", description="Second-order drift: none, the mean drift, the mean and slow drift by Newman's "
                              "approximation (needs a .12d, .9 or .8 file), or by the full difference-frequency "
                              "QTF (needs a .12d file with its pairs of periods; a long-crested sea).")
    ramp: quantity("s", ge=0) = Field(
        0.0, description="Smooth start of the oscillating wave loads (half cosine); the mean drift is there from t = 0, "
                         "where the static start puts the body. With 0 they start at t = 0 from zero. [s]")

    @property
    def database_format(self) -> str:
        """``format``, or the format of ``file`` by its extension (``.nc``: capytaine, else wamit)."""
        if self.format is not None:
            return self.format
        return "capytaine" if self.file.lower().endswith(".nc") else "wamit"

    @property
    def weight_included(self) -> bool:
        """Whether the database's hydrostatics hold the weight's moment (``weight_in_hydrostatics`` or the
        format's default)."""
        if self.weight_in_hydrostatics is not None:
            return self.weight_in_hydrostatics
        return self.database_format == "capytaine"

    @model_validator(mode="after")
    def _format(self):
        if self.database_format == "capytaine" and "ulen" in self.model_fields_set:
            raise ValueError("ulen is WAMIT's length scale; a Capytaine dataset is dimensional. Suggested fix: leave "
                             "out ulen.")
        return self


class _AreaTable(Model):
    """Force areas by the direction a relative flow blows towards in the body's axes (linear between ``headings``,
    periodic; one heading: the same at every direction): drag coefficient times area in surge and sway [m^2] and
    times arm in yaw [m^3], so that the force is ``1/2 rho |u| u C`` (:class:`seacable.wind.WindCoefficients`)."""

    headings: tuple[float, ...] = Field((0.0,), description="Relative flow directions, body axes. [rad]")
    surge: tuple[float, ...] = Field(description="Surge force area C A at each heading. [m^2]")
    sway: tuple[float, ...] = Field(description="Sway force area at each heading. [m^2]")
    yaw: tuple[float, ...] = Field(description="Yaw moment area C A L at each heading. [m^3]")

    @model_validator(mode="after")
    def _table(self):
        self.coefficients()  # the table's checks (seacable.wind.WindCoefficients), as a ValueError
        return self

    def coefficients(self):
        """The table as :class:`seacable.wind.WindCoefficients`."""
        from ..wind import WindCoefficients

        return WindCoefficients(heading=np.asarray(self.headings), surge=np.asarray(self.surge),
                                sway=np.asarray(self.sway), yaw=np.asarray(self.yaw))


class BodyWind(_AreaTable):
    """A body's wind areas (issue 39), at the centre of pressure ``height`` above the still-water level, where the
    environment's wind is taken (:mod:`seacable.wind`: ``F = 1/2 rho_air |u| u C``, ``u`` the wind relative to the
    body's reference point)."""

    height: quantity("m", gt=0, fix="give the height of the wind's centre of pressure above the water in m.") = Field(
        description="Centre of pressure above the still-water level. [m]")


class BodyCurrent(_AreaTable):
    """A body's current areas (issue 39): ``F = 1/2 rho |u| u C`` of the current at the body's reference point (its
    depth, or the surface's current when the point is above the water) relative to the reference point's velocity,
    as OCIMF's or a model test's coefficients give them (``C A`` from ``C_X``, ``C_Y`` and ``C_N`` times the
    areas and the length). A body's ``quadratic_damping`` acts on the same relative velocity: give the hull's drag
    in one of them, not both."""


class Body(Model):
    """A rigid body with six degrees of freedom.

    Parameters
    ----------
    kind
        ``free`` (finds its equilibrium; moves in the dynamics), ``fixed`` (held at ``position``)
        or ``prescribed`` (held at ``position`` in statics; moved by ``motion`` in the dynamics, or by
        another code through :mod:`seacable.coupling`). ``coupled`` (MoorDyn's word, as a point's) is
        read as ``prescribed``.
    position
        Reference point (x, y, z) [m] and rotation (roll, pitch, yaw) [rad]; the starting guess of
        a free body.
    mass
        Mass in air. [kg]
    center_of_gravity
        Centre of gravity relative to the reference point, body axes. [m]
    inertia
        Moments of inertia about the centre of gravity, body axes (Ixx, Iyy, Izz). [kg m^2]
    volume
        Displaced volume at the position given. [m^3]
    center_of_buoyancy
        Centre of buoyancy relative to the reference point, body axes. [m]
    waterplane_area
        Waterplane area, for the heave stiffness rho g A_wp. [m^2]
    waterplane_moments
        Second moments of the waterplane area about the body's x and y axes through the reference
        point (I_xx, I_yy), for the roll and pitch stiffness. [m^4]
    hydrostatic_stiffness
        A 6x6 hydrostatic stiffness matrix instead of the waterplane terms (restoring from
        buoyancy and the centre of gravity are then the user's, not added again). [N/m, N, N m]
    external_force
        Constant force and moment on the reference point, global axes (wind, current, drift). [N, N m]
    added_mass, linear_damping, quadratic_damping
        6x6 matrices for the dynamics (about the reference point). [kg, kg m, kg m^2], [N s/m ...],
        [N s^2/m^2 ...]
    pinned
        The reference point is tied where ``position`` puts it (free body) or to the motion
        (prescribed body) by a ball joint: only the three rotations are free (a MoorDyn
        ``Pinned``/``CoupledPinned`` rod or body).
    hydrodynamics
        A hydrodynamic database (:class:`BodyHydrodynamics`) for the hydrostatics, added mass, radiation
        memory and wave loads.
    wind
        Its wind areas (:class:`BodyWind`), for the environment's wind.
    current
        Its current areas (:class:`BodyCurrent`), for the environment's current.
    """

    kind: Literal["free", "fixed", "prescribed", "coupled"] = Field(
        "free", description="free, fixed or prescribed ('coupled', moved by a coupled code, is read as prescribed).")
    position: _POSE = Field((0.0,) * 6, description="x, y, z [m], roll, pitch, yaw [rad].")
    mass: quantity("kg", ge=0, fix="give the body's mass in air in kg.") = Field(
        0.0, description="Mass in air. [kg]")
    center_of_gravity: _XYZ = Field((0.0, 0.0, 0.0), description="Centre of gravity, body axes. [m]")
    inertia: tuple[float, float, float] = Field((0.0, 0.0, 0.0), description="Ixx, Iyy, Izz about the centre of gravity. [kg m^2]")
    volume: quantity("m^3", ge=0) = Field(0.0, description="Displaced volume. [m^3]")
    center_of_buoyancy: _XYZ = Field((0.0, 0.0, 0.0), description="Centre of buoyancy, body axes. [m]")
    waterplane_area: quantity("m^2", ge=0) = Field(0.0, description="Waterplane area. [m^2]")
    waterplane_moments: tuple[float, float] = Field(
        (0.0, 0.0), description="Waterplane second moments I_xx, I_yy about the reference point. [m^4]")
    hydrostatic_stiffness: _MATRIX6 | None = Field(None, description="6x6 hydrostatic stiffness.")
    external_force: _SIX = Field((0.0,) * 6, description="Constant force and moment. [N, N m]")
    added_mass: _MATRIX6 | None = Field(None, description="6x6 added-mass matrix.")
    linear_damping: _MATRIX6 | None = Field(None, description="6x6 linear damping matrix.")
    quadratic_damping: _MATRIX6 | None = Field(None, description="6x6 quadratic damping matrix.")
    pinned: bool = Field(False, description="Reference point tied by a ball joint; only rotations free.")
    hydrodynamics: BodyHydrodynamics | None = Field(
        None, description="Hydrodynamic database (WAMIT files): hydrostatics, added mass, radiation memory, waves.")
    wind: BodyWind | None = Field(None, description="Wind areas by relative wind direction.")
    current: BodyCurrent | None = Field(None, description="Current areas by relative current direction.")

    @field_validator("kind", mode="before")
    @classmethod
    def _coupled(cls, value):
        return "prescribed" if value == "coupled" else value  # MoorDyn's word, as a point's kind

    @model_validator(mode="after")
    def _check(self):
        if self.pinned and self.kind == "fixed":
            raise ValueError("a fixed body cannot be pinned (it has no free rotation). Suggested fix: make it "
                             "kind 'free' with pinned: true to free its rotations, or drop 'pinned'.")
        for key, unit in (("position", "m and rad"), ("center_of_gravity", "m"), ("center_of_buoyancy", "m"),
                          ("external_force", "N and N m"), ("waterplane_moments", "m^4")):
            _finite(key, getattr(self, key), unit)
        if any(not math.isfinite(i) or i < 0 for i in self.inertia):
            raise ValueError(f"inertia must hold three moments >= 0 in kg m^2, got {self.inertia}. "
                             "Suggested fix: give Ixx, Iyy, Izz about the centre of gravity.")
        for key in ("hydrostatic_stiffness", "added_mass", "linear_damping", "quadratic_damping"):
            m = getattr(self, key)
            if m is not None:
                _finite(key, m, "SI units")
        return self

    def database_conflicts(self) -> list[str]:
        """The inputs a body's ``hydrodynamics`` gives and that are given too (a case's check; a system resolved
        from the database holds both)."""
        if self.hydrodynamics is None:
            return []
        given = [k for k in ("hydrostatic_stiffness", "added_mass") if getattr(self, k) is not None]
        return given + [k for k in ("waterplane_area", "waterplane_moments") if any(np.atleast_1d(getattr(self, k)))]

    def matrix(self, key: str) -> np.ndarray:
        """A 6x6 matrix field as an array (zeros when not given)."""
        m = getattr(self, key)
        return np.zeros((6, 6)) if m is None else np.asarray(m, float)

    def mass_matrix(self) -> np.ndarray:
        """The 6x6 mass matrix about the reference point in body axes: the rigid body's (mass at the centre of
        gravity, ``inertia`` about it) plus ``added_mass``. [kg, kg m, kg m^2]"""
        c = np.asarray(self.center_of_gravity, float)
        S = np.array([[0.0, -c[2], c[1]], [c[2], 0.0, -c[0]], [-c[1], c[0], 0.0]])
        m = self.mass
        rigid = np.block([[m * np.eye(3), -m * S], [m * S, np.diag(self.inertia) - m * S @ S]])
        return rigid + self.matrix("added_mass")

    def _spin_free(self) -> np.ndarray:
        """Which of the principal inertias about the centre of gravity are zero (a point mass: all three; masses
        on one axis: the inertia about that axis), when the body has mass and no added mass."""
        inertia = np.asarray(self.inertia, float)
        if self.mass <= 0 or self.added_mass is not None:
            return np.zeros(3, bool)
        c = np.asarray(self.center_of_gravity, float)
        return inertia <= 1e-12 * self.mass * max(float(c @ c), 1.0)

    def dynamic_inertia(self) -> tuple[float, float, float]:
        """``inertia`` as the dynamics use it: a principal inertia about the centre of gravity that is zero (a
        point mass, or masses on one axis) is given ``1e-3 m max(|r_cg|, 1 m)^2``. The dynamics accept such a
        body only when nothing turns it about its centre of gravity (:meth:`check_accelerable`); then its
        angular velocity about that axis stays as it started, whatever the inertia: Euler's equations give
        ``I dw/dt = 0`` (the gyroscopic moment about an axis of zero inertia is zero too, since a rigid body
        with ``Ixx = 0`` has ``Iyy = Izz``). [kg m^2]"""
        c = np.asarray(self.center_of_gravity, float)
        eps = 1e-3 * self.mass * max(float(c @ c), 1.0)
        return tuple(float(i + eps * z) for i, z in zip(self.inertia, self._spin_free(), strict=True))

    def check_accelerable(self, name: str, moment_sources: Sequence[str] = ()) -> None:
        """Refuse a free body whose mass matrix is singular in a free direction (the dynamics solve with it).

        A body with mass whose inertia about its centre of gravity is zero about an axis (a point mass held
        off its reference point, as MoorDyn's orbitalBody) is accepted when ``moment_sources`` (what could
        turn it about its centre of gravity: lines or loaded points off it, buoyancy, damping, external moments)
        is empty: its spin about the centre of gravity is then free and constant (:meth:`dynamic_inertia`).

        Raises
        ------
        InputError
            Naming the body, the direction nothing gives inertia to and what would turn it.
        """
        from ..errors import InputError

        M = self.mass_matrix()
        free = slice(3, 6) if self.pinned else slice(0, 6)
        block = 0.5 * (M[free, free] + M[free, free].T)
        values, vectors = np.linalg.eigh(block)
        if values[0] > 1e-12 * max(values[-1], 1e-300):
            return
        spin = self._spin_free().any() and not self.pinned
        if spin and not moment_sources:
            return
        v = vectors[:, 0]
        what = "rotation about" if self.pinned else "motion along (x, y, z, roll, pitch, yaw)"
        turn = (f"; {', '.join(moment_sources)} would turn it about its centre of gravity, which nothing resists"
                if spin else "")
        raise InputError(
            f"bodies.{name}: its mass matrix about the reference point (mass {self.mass:g} kg, inertia "
            f"{tuple(self.inertia)} kg m^2 about the centre of gravity, added mass) gives no inertia to the "
            f"{what} ({', '.join(f'{x:.3g}' for x in v)}), so the dynamics cannot accelerate it (a point mass with "
            f"no inertia of its own about an axis through it){turn}. Suggested fix: give the body its moments of "
            "inertia (inertia: Ixx, Iyy, Izz > 0) or an added-mass matrix.")


class SystemLine(Model):
    """A line from point ``end_a`` to point ``end_b``.

    Parameters
    ----------
    line
        Segments and attachments, end A first (in a file: ``line_type``/``length`` for one segment,
        or ``segments`` and ``attachments`` as the single-line cases).
    end_a, end_b
        Names of the points the line ends at.
    n_elements
        Elements a finite-element model uses on the line (a segment's own ``n_elements`` wins).
    end_a_condition, end_b_condition
        How each end is held in bending (:class:`seacable.mooring.ends.EndCondition`): pinned (the default),
        clamped at a declination and azimuth, or a rotational spring. At a point on a body the direction is in
        the body's axes and turns with the body; at any other point it is global. A held end needs bending
        stiffness (the line type's EI or a bend stiffener).

    A line's ``sections`` (buoyancy modules, bend stiffeners: :mod:`seacable.sections`) are resolved onto its
    finite-element mesh as a single line's are (:func:`seacable.mooring.network.network_from_line`); the catenary
    statics cannot carry them, so a system with sections or a held end is solved by its finite-element statics
    (:func:`seacable.system.statics_mode.needs_fe`).
    """

    line: Line
    end_a: str = Field(min_length=1, description="Point at end A.")
    end_b: str = Field(min_length=1, description="Point at end B.")
    n_elements: int = Field(20, ge=1, le=100_000, description="Elements of a finite-element model.")
    end_a_condition: EndCondition = Field(
        EndCondition(), description="How end A is held in bending: pinned, clamped at a direction, or a rotational "
                                    "spring (the direction in the axes of the body the end's point is on).")
    end_b_condition: EndCondition = Field(EndCondition(), description="How end B is held in bending (as end A's).")

    @model_validator(mode="after")
    def _ends(self):
        if self.end_a == self.end_b:
            raise ValueError(f"end_a and end_b are the same point '{self.end_a}'. Suggested fix: end the "
                             "line at two different points.")
        return self

    @model_serializer(mode="wrap")
    def _without_pinned_ends(self, handler):
        # a line with pinned ends is written as before end conditions existed (a result's case attribute unchanged)
        data = handler(self)
        if isinstance(data, dict):
            for key in ("end_a_condition", "end_b_condition"):
                if not getattr(self, key).holds and key not in self.model_fields_set:
                    data.pop(key, None)
        return data

    @model_validator(mode="after")
    def _held_ends(self):
        for end, key in enumerate(("end_a_condition", "end_b_condition")):
            cond = getattr(self, key)
            seg = self.line.segments[0 if end == 0 else -1]
            stiffened = any(getattr(sec, "end", None) == "AB"[end] for sec in self.line.sections)
            if cond.holds and not seg.line_type.bending_stiffness > 0 and not stiffened:
                raise ValueError(f"{key} is {cond.type}, but the line's end segment there has no bending stiffness "
                                 f"(EI = {seg.line_type.bending_stiffness:g} N m^2, no bend stiffener): a moment at the "
                                 "end needs a line that bends. Suggested fix: give the end segment's line type "
                                 f"'bending_stiffness' in N m^2 (e.g. 1e4), or leave {key} out (pinned).")
        return self

    @property
    def holds_ends(self) -> bool:
        """Whether an end of the line is clamped or held by a rotational spring."""
        return self.end_a_condition.holds or self.end_b_condition.holds

    def end_hinges(self, index: int) -> tuple:
        """The network's ``end_hinges`` entries of this line's held ends (:meth:`seacable.mooring.ends.EndCondition.
        hinge`), its index in the system being ``index``."""
        return tuple(cond.hinge(index, end) for end, cond in enumerate((self.end_a_condition, self.end_b_condition))
                     if cond.holds)


class MooringSystem(Model):
    """Points, bodies and lines; names are the keys of each mapping.

    Cross-references are checked: each line's ends name points, each ``kind: body`` point names a
    body. A system needs at least one line or body. A body no line ends on is allowed (a fixed or
    prescribed body, a floating body in the dynamics, a MoorDyn deck of rods alone); whether it has
    a static equilibrium (restoring in every free direction) is the statics' check
    (:func:`bodies_without_lines`).
    """

    points: dict[str, SystemPoint] = Field(default_factory=dict, description="Points by name.")
    bodies: dict[str, Body] = Field(default_factory=dict, description="Bodies by name.")
    lines: dict[str, SystemLine] = Field(default_factory=dict, description="Lines by name.")

    @model_validator(mode="after")
    def _references(self):
        problems = []
        for name, line in self.lines.items():
            for end in ("end_a", "end_b"):
                ref = getattr(line, end)
                if ref not in self.points:
                    problems.append(f"lines.{name}.{end}: point '{ref}' is not defined (points: "
                                    f"{', '.join(self.points) or 'none'}).{suggest(ref, self.points)}")
        for name, point in self.points.items():
            if point.kind == "body" and point.body not in self.bodies:
                problems.append(f"points.{name}.body: body '{point.body}' is not defined (bodies: "
                                f"{', '.join(self.bodies) or 'none'}).{suggest(point.body, self.bodies)}")
        if not self.lines and not self.bodies:
            problems.append("lines: the system has no line and no body, nothing to analyse. Suggested fix: add "
                            "the lines (and the bodies they moor).")
        if problems:
            raise ValueError(problems[0] if len(problems) == 1 else
                             f"{len(problems)} problems: " + " ".join(problems))
        return self

    def without(self, *line_names: str) -> MooringSystem:
        """The damaged system: the same points and bodies with the named lines removed.

        Points no line ends at any more are dropped (a free point would float away); bodies keep
        their remaining lines (a free body left with none has no static equilibrium unless its
        hydrostatics restore it in every free direction: the statics refuse it).
        """
        unknown = [n for n in line_names if n not in self.lines]
        if unknown:
            from ..errors import InputError

            raise InputError(f"cannot remove line '{unknown[0]}': no such line (lines: {', '.join(self.lines)})."
                             f"{suggest(unknown[0], self.lines)}")
        lines = {k: v for k, v in self.lines.items() if k not in line_names}
        used = {getattr(line, end) for line in lines.values() for end in ("end_a", "end_b")}
        points = {k: p for k, p in self.points.items() if k in used or p.kind in ("fixed", "coupled")}
        return MooringSystem(points=points, bodies=dict(self.bodies), lines=lines)


def bodies_without_lines(system: MooringSystem) -> tuple[str, ...]:
    """Names of the bodies of ``system`` that no line ends on (through a point on the body)."""
    moored = {system.points[getattr(line, end)].body for line in system.lines.values()
              for end in ("end_a", "end_b") if getattr(line, end) in system.points}
    return tuple(name for name in system.bodies if name not in moored)

"""A mooring-system case: points, bodies and lines, their environment, and what to compute.

A :class:`SystemCase` is to a :class:`~seacable.system.model.MooringSystem` what a
:class:`~seacable.case.Case` is to a single line: :func:`seacable.run` is a pure function of it.
In a file, a case with a top-level ``lines`` (or ``points``, ``bodies``) and no ``line`` is a
system case (:func:`seacable.io.parse_case`)::

    name: spread
    line_types:
      chain: {diameter: 0.09, mass_per_length: 77.7, axial_stiffness: 3.8e8}
    environment: {depth: 200.0}
    points:
      anchor1: {kind: fixed, position: [800.0, 0.0, -200.0]}
      fair1: {kind: body, body: buoy, position: [10.0, 0.0, -10.0]}
    bodies:
      buoy: {mass: 1.0e6, volume: 1100.0, waterplane_area: 80.0}
    lines:
      line1: {line_type: chain, length: 850.0, end_a: anchor1, end_b: fair1}
    analysis: {type: system_static, damaged_lines: [line1]}

Each line is written as a single-line case's ``line`` (``line_type`` and ``length`` for one
segment, or ``segments``, ``attachments`` and ``sections``) plus its ends ``end_a``, ``end_b``, ``n_elements``
and how each end is held in bending, ``end_a_condition`` and ``end_b_condition`` (pinned, clamped, spring).

Analyses: ``system_static`` (equilibrium, end tensions, anchor loads, stiffness; intact and
damaged) and ``system_offsets`` (equilibrium under an external load on one body swept over
magnitudes and headings: offsets, watch circle, restoring force) and ``system_dynamic`` (the
finite-element lines coupled with the rigid bodies in time, line failures;
:mod:`seacable.system.dynamics`). :data:`SYSTEM_ANALYSES` is the union of the system analyses: a
new one is one more entry there.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Any, ClassVar, Literal, Union

import numpy as np
from pydantic import Discriminator, Field, Tag, model_serializer, model_validator

from .._model import UNION_TAGS, Model, input_error, quantity, suggest, unit_float
from .._window import StatisticsWindow, omit_unset_window
from ..case import CableDesign, SeabedContact, check_unused_inputs
from ..environment import SystemEnvironment, seabed_elevation
from ..errors import InputError
from ..line import STAND_IN, LineType, RetypedCopies
from ..mooring.friction import StaticFriction, StaticFrictionOption
from ..mooring.motion import Motion, PlatformMotion, RAOMotion
from ..ties import tie_points
from .model import Body, MooringSystem, SystemLine, SystemPoint

__all__ = ["SYSTEM_ANALYSES", "ExternalForceSeries", "LineFailure", "SystemAnalysis", "SystemCase",
           "SystemDynamicAnalysis", "SystemOffsetsAnalysis", "SystemStaticAnalysis", "UncoupledRoute",
           "is_system_data"]


def _omit_defaults(data):
    """A dumped analysis without 'design' when None and 'static_friction' when the default: the cases without them
    read as they did before they existed."""
    if isinstance(data, dict) and data.get("design", 0) is None:
        del data["design"]
    if isinstance(data, dict) and data.get("static_friction", 0) == StaticFriction().model_dump():
        del data["static_friction"]
    return data


class _Solve(StaticFrictionOption):
    """Options of the system equilibrium shared by the system analyses."""

    damaged_lines: tuple[str, ...] | Literal["most_loaded"] = Field(
        (), description="Lines removed in the damaged condition, solved beside the intact one (none: intact only); "
                        "'most_loaded': the line of the largest tension in the intact equilibrium "
                        "(seacable.system.damaged; in system_offsets, at each heading's largest load).")
    tolerance: quantity("-", gt=0, lt=1e-2) = Field(
        1e-8, description="Equilibrium tolerance on the force residual, relative. [-]")
    max_iterations: int = Field(200, ge=1, le=100_000, description="Newton iterations of one equilibrium.")
    load_steps: int = Field(1, ge=1, le=1000, description="Steps in which the external loads are ramped up "
                                                          "(each solved from the last): 1 for none.")
    max_strain: quantity("-", gt=0, le=100) = Field(
        1.0, description="Largest strain T/EA a line may take; a line that would need more cannot reach its "
                         "ends (strains above 10 % are warned). [-]")
    statics: Literal["auto", "catenary", "finite_element"] = Field(
        "auto", description="Line statics: exact elastic catenaries with analytic stiffness ('catenary'), or the "
                            "finite-element lines with the stiffness by central differences ('finite_element'); "
                            "'auto' takes the catenaries unless a current, a sloping seabed or a wind needs the "
                            "finite elements.")

    @model_serializer(mode="wrap")
    def _omit_unset_design(self, handler):
        return _omit_defaults(handler(self))

    @model_validator(mode="after")
    def _damaged(self):
        if self.static_friction.pushover_path != "as_laid":
            raise ValueError(f"static_friction.pushover_path: '{self.static_friction.pushover_path}' applies to a "
                             "single line's mooring_pushover; a system's loads are applied from the as-laid state, "
                             "each heading's in increasing order from the last (one monotonic loading). Suggested "
                             "fix: drop static_friction.pushover_path.")
        d = self.damaged_lines
        if not isinstance(d, str) and len(set(d)) != len(d):
            raise ValueError(f"damaged_lines names a line twice: {list(d)}. Suggested fix: name each once.")
        return self


class _Designed(Model):
    """The cable checks' criteria of a system's result (issue 40), the single line's ``design`` block: the sag and
    hog bends' clearances and the hang-off (end B) declination range of every line with bending stiffness, each
    checked against its own line types' limits too (:mod:`seacable.design.system_cable`), and
    ``design.line_clearance``, the smallest distance from a cable to the other lines
    (:func:`seacable.design.clearance.line_clearance_check`)."""

    design: CableDesign | None = Field(
        None, description="Design criteria of the system's cables (the bends' clearances, the hang-off declination "
                          "range, the smallest distance to the other lines).")

    @model_serializer(mode="wrap")
    def _omit_unset_design(self, handler):
        # 'design' appears in a dumped case only when given: the cases without it read as they did before it existed
        return omit_unset_window(_omit_defaults(handler(self)))


class SystemStaticAnalysis(_Designed, _Solve):
    """Static equilibrium and stiffness of the system, intact and (with ``damaged_lines``) damaged."""

    type: Literal["system_static"] = "system_static"
    #: environment inputs taken (seacable.case.check_unused_inputs): waves, as every static analysis (still water);
    #: the mean wind on the bodies that give their wind areas
    USES: ClassVar[frozenset[str]] = frozenset({"depth", "current", "seabed.slope", "seabed.friction", "waves",
                                                "wind", "seabed.grid"})
    profile_points: int = Field(41, ge=2, le=10_000, description="Points of each line's stored profile.")


class SystemOffsetsAnalysis(_Solve):
    """Offsets and watch circle: an external horizontal load on ``body`` swept over magnitudes and headings.

    The load ``F (cos heading, sin heading, 0)`` is added to the body's own ``external_force`` at each
    magnitude of ``loads`` [N] and each heading of ``headings`` [rad] (default ``n_headings`` evenly
    spread over the circle from 0); at a load of 0 the equilibrium is the static one. Each heading's
    loads are solved in increasing order, each from the last.
    """

    type: Literal["system_offsets"] = "system_offsets"
    USES: ClassVar[frozenset[str]] = SystemStaticAnalysis.USES
    body: str = Field(min_length=1, description="The free body the load acts on.")
    loads: tuple[unit_float("N"), ...] = Field(min_length=1, description="Load magnitudes, increasing, >= 0. [N]")
    headings: tuple[unit_float("rad"), ...] | None = Field(None, min_length=1,
                                               description="Load headings from +x towards +y. [rad]")
    n_headings: int = Field(12, ge=1, le=3600, description="Headings over the circle when 'headings' is not given.")

    @model_validator(mode="after")
    def _sweep(self):
        for i, f in enumerate(self.loads):
            if not (math.isfinite(f) and f >= 0):
                raise ValueError(f"loads[{i}] must be a finite number >= 0 N, got {f} N. Suggested fix: give "
                                 "load magnitudes in N; the heading sets the direction.")
        if any(b <= a for a, b in zip(self.loads, self.loads[1:])):
            raise ValueError(f"loads must increase, got {list(self.loads)} N (each is solved from the last). "
                             f"Suggested fix: loads: {sorted(set(self.loads))}.")
        if self.headings is not None:
            for i, h in enumerate(self.headings):
                if not math.isfinite(h):
                    raise ValueError(f"headings[{i}] must be a finite number in rad, got {h}.")
            if len(set(self.headings)) != len(self.headings):
                raise ValueError(f"headings gives a heading twice: {list(self.headings)} rad. Suggested fix: "
                                 "give each once.")
            if max(abs(h) for h in self.headings) > 2 * math.pi + 1e-9:
                import warnings

                from ..errors import SeacableWarning

                warnings.warn(f"analysis.headings {list(self.headings)} go beyond 2 pi: they are radians; did you "
                              "give degrees?", SeacableWarning, stacklevel=2)
        return self

    def heading_values(self) -> tuple[float, ...]:
        """The headings to solve at. [rad]"""
        if self.headings is not None:
            return self.headings
        return tuple(2 * math.pi * k / self.n_headings for k in range(self.n_headings))


# The inputs of ``system_dynamic`` (run by :mod:`seacable.system.dynamics`, which re-exports them): here with the
# other system analyses, so that the case layer does not import the analysis that runs it.
_SIX = tuple[float, float, float, float, float, float]


class ExternalForceSeries(Model):
    """A time series of force and moment on a body's reference point, global axes, linear between rows.

    Either ``file``: a CSV with a header row ``time, fx, fy, fz, mx, my, mz`` (any force column may be
    left out, '#' comments), relative to the case file; or ``times`` and ``values`` inline. Zero outside
    the table's time span is not assumed: the table must cover the run.
    """

    file: str | None = Field(None, description="CSV with columns time, fx, fy, fz, mx, my, mz.")
    times: list[float] | None = Field(None, description="Times, increasing. [s]")
    values: list[_SIX] | None = Field(None, description="Force and moment at each time. [N, N m]")

    @model_validator(mode="after")
    def _one_source(self):
        if (self.file is None) == (self.times is None):
            raise ValueError("give either 'file' (a CSV with columns time, fx, fy, fz, mx, my, mz) or 'times' and "
                             "'values', not both or neither.")
        if self.times is not None:
            if self.values is None or len(self.values) != len(self.times):
                raise ValueError(f"'values' needs one row of six numbers per time ({len(self.times)} times). "
                                 "Suggested fix: give [fx, fy, fz, mx, my, mz] in N and N m for each time.")
            if len(self.times) < 2 or np.any(np.diff(self.times) <= 0):
                raise ValueError("'times' needs at least two strictly increasing times in s.")
            if not np.all(np.isfinite(self.values)) or not np.all(np.isfinite(self.times)):
                raise ValueError("'times' and 'values' must hold finite numbers.")
        return self

    def table(self) -> tuple[np.ndarray, np.ndarray]:
        """Times (nt,) [s] and forces (nt, 6) [N, N m]."""
        if self.file is None:
            return np.asarray(self.times, float), np.asarray(self.values, float)
        from ..mooring.motion import _read_table

        t = _read_table(Path(self.file), ("time", "fx", "fy", "fz", "mx", "my", "mz"), "force series")
        return t[:, 0], t[:, 1:]


class LineFailure(Model):
    """A line end that detaches: at ``time``, or when its end element's tension first reaches ``tension``
    (whichever comes first when both are given)."""

    line: str = Field(min_length=1, description="The line that fails.")
    end: Literal["a", "b"] = Field(description="The end that detaches: a or b.")
    time: quantity("s", ge=0) | None = Field(None, description="Time of the failure. [s]")
    tension: quantity("N", gt=0) | None = Field(None, description="Tension at which the end fails. [N]")

    @model_validator(mode="after")
    def _when(self):
        if self.time is None and self.tension is None:
            raise ValueError(f"failure of line '{self.line}' needs 'time' (s) or 'tension' (N). Suggested fix: "
                             "give e.g. 'time: 10'.")
        return self


def _motion_type(value) -> str:
    return value.get("type", "platform") if isinstance(value, dict) else getattr(value, "type", "platform")


#: A prescribed body's motion: 'platform' (harmonic or a time series; the default) or 'rao' (RAOs in the waves).
BodyMotion = Annotated[Union[Annotated[PlatformMotion, Tag("platform")], Annotated[RAOMotion, Tag("rao")]],  # noqa: UP007
                       Discriminator(_motion_type)]



class UncoupledRoute(Model):
    """Options of ``system_dynamic``'s uncoupled route (``coupling: uncoupled``, :mod:`seacable.system.uncoupled`).

    The free body's low-frequency motion is solved alone (Cummins' equation) with the mooring's stiffness about
    the mean position and a damping: the body's own (linear, quadratic, the wind's) plus ``mooring_damping``, the
    lines' damping as a fraction of critical in surge, sway and yaw. Its default, 0, assumes no line damping:
    larger slow-drift motion than with the lines' real damping, so the route errs on the heavy side there; give
    an estimate (a few per cent of critical for chain in deep water) to be less conservative. ``lines``: the
    lines driven by the summed motion in time (``dynamic``: their inertia and drag, the system_dynamic kernel) or
    by their catenary statics at each output time (``quasi_static``: fast, no line dynamics).
    """

    mooring_damping: tuple[float, float, float] = Field(
        (0.0, 0.0, 0.0), description="The lines' damping of the low-frequency motion as a fraction of critical in "
                                     "surge, sway and yaw (one number: all three). [-]")
    lines: Literal["dynamic", "quasi_static"] = Field(
        "dynamic", description="Lines driven by the summed motion in time ('dynamic') or quasi-statically "
                               "('quasi_static': each line's elastic catenary at each output time).")

    @model_validator(mode="before")
    @classmethod
    def _scalar(cls, data):
        if isinstance(data, dict) and isinstance(data.get("mooring_damping"), (int, float)) \
                and not isinstance(data.get("mooring_damping"), bool):
            return {**data, "mooring_damping": (data["mooring_damping"],) * 3}
        return data

    @model_validator(mode="after")
    def _fractions(self):
        for k, z in zip(("surge", "sway", "yaw"), self.mooring_damping, strict=True):
            if not (math.isfinite(z) and 0.0 <= z < 1.0):
                raise ValueError(f"mooring_damping in {k} must be a fraction of critical damping in [0, 1), got {z}. "
                                 "Suggested fix: 0.05 for 5 % of critical (a percentage divided by 100).")
        return self


class SystemDynamicAnalysis(_Designed, StatisticsWindow):
    """Time-domain response of a mooring system: finite-element lines coupled with rigid bodies.

    Free bodies move under their loads and the lines' (added mass, damping, hydrostatics, external force
    series); prescribed bodies and coupled points follow ``body_motions`` / ``point_motions``; line ends
    may fail (``failures``). Newmark's average acceleration with Newton iterations on the nodes and
    bodies together, starting from the static equilibrium (``start: equilibrium``), with the free
    bodies held at their given positions and released at t = 0 (``start: held``), or from the
    equilibrium when it is found and held otherwise, with a warning (``start: auto``, what a MoorDyn
    deck run in time uses: a deck's free bodies are placed where the deck puts them).
    """

    type: Literal["system_dynamic"] = "system_dynamic"
    #: environment inputs taken (seacable.case.check_unused_inputs): not seabed.profile (a plane or a grid); the wind
    #: on the bodies that give their wind areas
    USES: ClassVar[frozenset[str]] = frozenset({"depth", "current", "seabed.slope", "seabed.friction", "waves",
                                                "wind", "seabed.grid"})
    duration: quantity("s", gt=0) = Field(description="Simulated time. [s]")
    time_step: quantity("s", gt=0) = Field(0.1, description="Newmark time step (halved on a failed step). [s]")
    output_interval: quantity("s", gt=0) = Field(0.5, description="Time between stored states. [s]")
    n_elements: int | None = Field(None, ge=1, le=100_000,
                                   description="Elements per line for every line (default: each line's own).")
    body_motions: dict[str, BodyMotion] = Field(
        default_factory=dict, description="6-DOF motion of each prescribed body, about its reference point: "
                                          "'platform' (harmonic or a time series) or 'rao' (its RAOs in the waves).")
    point_motions: dict[str, Motion] = Field(default_factory=dict, description="Motion of each coupled point.")
    external_forces: dict[str, ExternalForceSeries] = Field(
        default_factory=dict, description="External force time series per free body.")
    failures: list[LineFailure] = Field(default_factory=list, description="Line ends that fail.")
    damaged_lines: tuple[str, ...] | Literal["most_loaded"] = Field(
        (), description="Lines left out from the start: the damaged condition (a sweep over [[], [line1]] runs "
                        "intact and damaged); 'most_loaded': the line of the largest tension in the static "
                        "equilibrium the run starts from (seacable.system.damaged).")
    start: Literal["equilibrium", "held", "auto"] = Field(
        "equilibrium", description="Static start of the whole system, or with free bodies held at their position, "
                                   "or 'auto': the static start when it converges, else held (with a warning).")
    release_offsets: dict[str, _SIX] = Field(
        default_factory=dict, description="Free decay: each named free body held at its equilibrium plus this "
                                          "offset (x, y, z [m], roll, pitch, yaw [rad]) while the lines settle, "
                                          "then released at t = 0.")
    seabed_contact: SeabedContact = Field(default_factory=SeabedContact)
    damping_ratio: quantity("-", ge=0, le=10) = Field(
        0.0, description="Axial damping ratio of each element's axial mode (MoorDyn's BA = -ratio). [-]")
    rayleigh: tuple[float, float] = Field((0.0, 0.0), description="Rayleigh damping of the lines (alpha [1/s], "
                                                                   "beta [s]).")
    max_iterations: int = Field(30, ge=2, le=1000, description="Newton iterations per step.")
    numerical_damping: quantity("-", ge=0, le=0.3) = Field(
        0.0, description="Newmark's gamma = 1/2 + this, beta = (1 + this)^2 / 4: damps the ringing of stiff "
                         "modes the step cannot resolve (a snapped line end) at a first-order cost for the "
                         "resolved ones (a damping ratio of about this times w dt / 2). [-]")
    tolerance: quantity("-", gt=0, lt=1e-2) = Field(
        1e-8, description="Newton tolerance of the statics on the force residual, relative. [-]")
    coupling: Literal["coupled", "uncoupled"] = Field(
        "coupled", description="'coupled': the free bodies and the lines in one time step; 'uncoupled': the fast route "
                               "(the body's low-frequency motion alone with the mooring's stiffness, its wave-frequency "
                               "motion from its RAOs, the lines driven by their sum; seacable.system.uncoupled).")
    uncoupled: UncoupledRoute | None = Field(
        None, description="Options of the uncoupled route (coupling: uncoupled): mooring_damping, lines.")

    @model_validator(mode="after")
    def _check(self):
        if self.uncoupled is not None and self.coupling != "uncoupled":
            raise ValueError("'uncoupled' gives the options of the uncoupled route, but coupling is 'coupled'. "
                             "Suggested fix: add 'coupling: uncoupled', or drop 'uncoupled'.")
        if self.coupling == "uncoupled":
            for key, given in (("failures", self.failures), ("release_offsets", self.release_offsets),
                               ("external_forces", self.external_forces), ("body_motions", self.body_motions),
                               ("point_motions", self.point_motions)):
                if given:
                    raise ValueError(f"coupling 'uncoupled' does not take '{key}': the uncoupled route moves its free "
                                     "body by the summed low- and wave-frequency motion about a fixed mooring "
                                     "(seacable.system.uncoupled). Suggested fix: drop it, or use coupling: coupled.")
            if self.start != "equilibrium":
                raise ValueError(f"coupling 'uncoupled' starts from the equilibrium under the mean loads, got start "
                                 f"'{self.start}'. Suggested fix: drop 'start'.")
        if self.output_interval > self.duration:
            raise ValueError(f"output_interval ({self.output_interval:g} s) must not exceed duration "
                             f"({self.duration:g} s).")
        if not isinstance(self.damaged_lines, str) and len(set(self.damaged_lines)) != len(self.damaged_lines):
            raise ValueError(f"damaged_lines names a line twice: {list(self.damaged_lines)}. Suggested fix: name each "
                             "once.")
        if self.release_offsets and self.start != "equilibrium":
            raise ValueError("release_offsets start from the equilibrium: they need 'start: equilibrium'.")
        if any(c < 0 or not math.isfinite(c) for c in self.rayleigh):
            raise ValueError(f"rayleigh must hold two finite numbers >= 0 (alpha [1/s], beta [s]), got "
                             f"{self.rayleigh}.")
        return self


#: The analyses of a system case; a new one is one more entry.
SYSTEM_ANALYSES = (SystemStaticAnalysis, SystemOffsetsAnalysis, SystemDynamicAnalysis)
SystemAnalysis = Annotated[Union[SYSTEM_ANALYSES], Field(discriminator="type")]  # noqa: UP007
UNION_TAGS.update(cls.model_fields["type"].default for cls in SYSTEM_ANALYSES)

_LINE_KEYS = ("segments", "attachments", "sections", "line_type", "length")


def is_system_data(data: Any) -> bool:
    """True for the plain data of a system case: ``lines``, ``points`` or ``bodies`` at the top, no ``line``."""
    return isinstance(data, dict) and "line" not in data and any(k in data for k in ("lines", "points", "bodies"))


def _line_entry(entry: Any, types: Any, where: str) -> Any:
    """One line of a file as a :class:`SystemLine`'s data: the short forms expanded, line types resolved."""
    if not isinstance(entry, dict) or "line" in entry:
        return entry
    entry = dict(entry)
    line = {k: entry.pop(k) for k in _LINE_KEYS if k in entry}
    if "segments" not in line and "line_type" in line:
        line["segments"] = [{k: line.pop(k) for k in ("line_type", "length") if k in line}]
    segments = line.get("segments")
    if isinstance(segments, (list, tuple)):
        out = []
        for i, seg in enumerate(segments):
            ref = seg.get("line_type") if isinstance(seg, dict) else None
            if isinstance(ref, str):
                names = list(types) if isinstance(types, dict) else []
                if ref not in names:
                    at = where if len(segments) == 1 and "segments" not in entry else f"{where}.segments[{i}]"
                    raise ValueError(f"{at}.line_type '{ref}' is not defined in line_types (defined: "
                                     f"{', '.join(names) or 'none'}).{suggest(ref, names)}")
                seg = {**seg, "line_type": types[ref]}
            out.append(seg)
        line["segments"] = out
    return {**entry, "line": line}


class SystemCase(RetypedCopies, Model):
    """A mooring system, its environment and an analysis.

    Parameters
    ----------
    name
        Short name, used for output files.
    description
        Free text: source, assumptions, unit conversions.
    line_types
        Named line types the lines may refer to by name.
    environment
        Water (density, depth), current and seabed; ``depth`` is required.
    points, bodies, lines
        The :class:`~seacable.system.model.MooringSystem`: points (fixed, free, coupled, on a body),
        rigid bodies and lines, each by name. In a file a line is ``{line_type: NAME, length: L,
        end_a: P, end_b: Q}`` or ``{segments: [...], attachments: [...], end_a: P, end_b: Q}``.
    analysis
        What to compute, selected by its ``type`` (:data:`SYSTEM_ANALYSES`).
    """

    name: str = Field("system", min_length=1)
    description: str = ""
    line_types: dict[str, LineType] = Field(default_factory=dict)
    environment: SystemEnvironment = SystemEnvironment()
    points: dict[str, SystemPoint] = Field(default_factory=dict, description="Points by name.")
    bodies: dict[str, Body] = Field(default_factory=dict, description="Bodies by name.")
    lines: dict[str, SystemLine] = Field(default_factory=dict, description="Lines by name.")
    analysis: SystemAnalysis

    @classmethod
    def parse(cls, data: Any, *, root: str = ""):
        """Validate plain data (as read from a file) into a SystemCase.

        Named line types are checked first and each problem is reported once, at
        ``line_types.NAME``; a line's key paths are those of the file (``lines.L1.length``).
        """
        types = data.get("line_types") if isinstance(data, dict) else None
        problems, checked = [], types
        if isinstance(types, dict):
            checked = {}
            for name, entry in types.items():
                try:
                    checked[name] = LineType.parse(entry)
                except InputError as err:
                    problems += [(("line_types", name) + loc, tail) for loc, tail in err.problems]
                    checked[name] = STAND_IN  # keeps lines that use it from failing again
        try:
            case = super().parse(data if checked is types else {**data, "line_types": checked}, root=root)
        except InputError as err:
            problems += [(_file_path(loc, data), tail) for loc, tail in err.problems]
            case = None
        if problems:
            raise input_error(problems, root)
        return case

    @model_validator(mode="before")
    @classmethod
    def _points_on_seabed(cls, data: Any) -> Any:
        """A fixed or free point given at ``(x, y)`` only, or with ``z: seabed``, sits on the seabed there (the
        grid's, or the plane's of the depth and slope): :func:`seabed_points`."""
        return seabed_points(data)

    @model_validator(mode="before")
    @classmethod
    def _resolve_lines(cls, data: Any) -> Any:
        """Expand each line's short form and replace line-type names by the entries of ``line_types``."""
        if not isinstance(data, dict) or not isinstance(data.get("lines"), dict):
            return data
        types = data.get("line_types") or {}
        lines = {name: _line_entry(entry, types, f"lines.{name}") for name, entry in data["lines"].items()}
        return {**data, "lines": lines}

    @model_validator(mode="after")
    def _system(self):
        check_unused_inputs(self.analysis, self.environment, SYSTEM_ANALYSES)
        if self.environment.depth is None and self.environment.seabed.grid is None:
            raise ValueError(f"analysis '{self.analysis.type}' needs environment.depth (m) or seabed.grid: the seabed "
                             "the lines rest on. Suggested fix: add 'depth:' under 'environment'.")
        for name, body in self.bodies.items():
            given = body.database_conflicts()
            if given:
                raise ValueError(f"bodies.{name}: {', '.join(given)} and hydrodynamics both given: the database gives "
                                 f"the hydrostatics and the added mass. Suggested fix: leave out {', '.join(given)}.")
        if self.environment.wind is not None and not any(b.kind == "free" and b.wind is not None
                                                         for b in self.bodies.values()):
            raise ValueError("environment.wind is given, but no free body gives its wind areas (bodies.NAME.wind), so "
                             "it would load nothing (the lines take no wind). Suggested fix: give the bodies' wind "
                             "areas, or remove environment.wind.")
        try:
            system = self.system()
        except InputError as err:
            raise ValueError(str(err).removeprefix("MooringSystem").lstrip(".: ")) from None
        depth = self.environment.depth
        slope = self.environment.seabed.slope
        for name, p in system.points.items():
            if self.environment.seabed.grid is not None:  # the grid's seabed under the point (refused off it)
                bed = seabed_elevation(self.environment.seabed, *p.position[:2], f"point '{name}'") \
                    if p.kind != "body" else 0.0
                depth = -bed
                where = f"z = {bed:g} m (environment.seabed.grid under x = {p.position[0]:g} m, y = {p.position[1]:g} m)"
            else:
                bed = -depth + math.tan(slope) * p.position[0]  # the plane seabed, rising towards +X by its slope
                where = f"z = {bed:g} m" + (f" (environment.depth {depth:g} m" + (
                    f", seabed.slope {slope:g} rad at x = {p.position[0]:g} m)" if slope else ")"))
            if p.kind != "body" and p.position[2] < bed - 1e-9 * (depth + abs(bed)) - 1e-9:
                raise ValueError(f"points.{name}.position: z = {p.position[2]:g} m is below the seabed at "
                                 f"{where}. Suggested fix: put the point on the seabed (z = {bed:g} m) or "
                                 "above it.")
        for name, line in system.lines.items():
            # a tie's point below the seabed or above the sea, or left on a seabed not given (the single line's check)
            tie_points(line.line, self.environment, f"lines.{name}")
            missing = [i for i, seg in enumerate(line.line.segments) if seg.line_type.axial_stiffness is None]
            if missing:
                raise ValueError(f"lines.{name}: the system statics need an axial_stiffness (EA, N) on every "
                                 f"line type; segment(s) {missing} have none. Suggested fix: add 'axial_stiffness'"
                                 " to the line type.")
        a = self.analysis
        named = getattr(a, "damaged_lines", ())
        for i, ref in enumerate(() if isinstance(named, str) else named):
            if ref not in self.lines:
                raise ValueError(f"analysis.damaged_lines[{i}]: line '{ref}' is not defined (lines: "
                                 f"{', '.join(self.lines)}).{suggest(ref, self.lines)}")
        design = getattr(a, "design", None)
        if design is not None:
            _check_cable_design(design, system, self.points)
        if isinstance(a, SystemOffsetsAnalysis):
            body = self.bodies.get(a.body)
            if body is None:
                raise ValueError(f"analysis.body: body '{a.body}' is not defined (bodies: "
                                 f"{', '.join(self.bodies) or 'none'}).{suggest(a.body, self.bodies)}")
            if body.kind != "free":
                raise ValueError(f"analysis.body: body '{a.body}' is '{body.kind}', it cannot move under the load. "
                                 "Suggested fix: name a free body, or set its kind to 'free'.")
        return self

    def system(self) -> MooringSystem:
        """The mooring system of the case (points, bodies, lines); a body's ``hydrodynamics`` gives it the
        database's hydrostatic stiffness and added mass (:func:`seacable.system.hydro.resolve_bodies`)."""
        system = MooringSystem(points=self.points, bodies=self.bodies, lines=self.lines)
        if not any(b.hydrodynamics is not None for b in self.bodies.values()):
            return system
        from .hydro import resolve_bodies

        env = self.environment
        return resolve_bodies(system, env.water_density, env.gravity)

    def damaged_system(self, names: tuple[str, ...] | None = None) -> MooringSystem | None:
        """The system without the analysis's ``damaged_lines`` (or without ``names``, the lines that
        ``damaged_lines: most_loaded`` resolved to), or None when it names none (or has none).

        Raises
        ------
        InputError
            If it removes every line (a body left with none is refused by the statics when nothing
            else holds it: :func:`seacable.system.run.check_bodies_without_lines`), or if the analysis asks for
            the most loaded line and ``names`` does not say which it is.
        """
        if names is None:
            names = getattr(self.analysis, "damaged_lines", ())
            if isinstance(names, str):
                raise InputError("analysis.damaged_lines 'most_loaded' is known once the intact equilibrium is "
                                 "solved. Suggested fix: call damaged_system(names) with the line that "
                                 "seacable.system.damaged.most_loaded_line finds.")
        names = tuple(names)
        if not names:
            return None
        if set(names) >= set(self.lines):
            raise InputError(f"analysis.damaged_lines {list(names)} removes every line: the damaged system has "
                             "nothing left to hold it. Suggested fix: name only the lines that break.")
        try:
            return self.system().without(*names)
        except InputError as err:
            raise InputError(f"analysis.damaged_lines {list(names)}: the damaged system is not valid: "
                             f"{str(err).removeprefix('MooringSystem').lstrip('.: ')} Suggested fix: remove fewer "
                             "lines, or give the body another line.") from None


#: The cable limits of ``analysis.design`` that the cable checks read off a line's shape (beside line_clearance).
_CABLE_LIMITS = ("sag_bend_clearance", "hog_bend_clearance", "hang_off_declination")


def _bends(line) -> bool:
    """Whether a system line bends: a line type's EI > 0, a bend stiffener or restrictor, or an end held."""
    return (any((seg.line_type.bending_stiffness or 0.0) > 0.0 for seg in line.line.segments)
            or any(getattr(sec, "type", "") in ("bend_stiffener", "bend_restrictor") for sec in line.line.sections)
            or line.end_a_condition.holds or line.end_b_condition.holds)


def _check_cable_design(design: CableDesign, system: MooringSystem, points: dict) -> None:
    """A system's cable limits (``analysis.design``) apply to its lines with bending stiffness, hung off at end B:
    limits with no such line to check, or a hang-off declination range for a cable whose only moving end is A,
    are refused (the checks take end B as the hang-off, :mod:`seacable.design.system_cable`)."""
    # given: a clearance above its default 0 m, a declination range (a dumped case writes the defaults)
    given = [k for k in _CABLE_LIMITS if getattr(design, k) not in (None, 0.0)]
    if not given:
        return
    cables = [name for name, line in system.lines.items() if _bends(line)]
    if not cables:
        raise ValueError(f"analysis.design gives {', '.join(given)}, but no line of the system has bending stiffness "
                         "(a line type's bending_stiffness, a bend stiffener or a held end), so there is no cable "
                         "to check. Suggested fix: give the cable's line type its bending_stiffness (EI, N m^2), or "
                         f"remove {', '.join(given)}.")
    if design.hang_off_declination is None:
        return

    def moves(name):
        p = points.get(name)
        return p is not None and p.kind in ("body", "coupled")

    for name in cables:
        line = system.lines[name]
        if moves(line.end_a) and not moves(line.end_b):
            raise ValueError(f"analysis.design.hang_off_declination: line '{name}' is hung off at end A (point "
                             f"'{line.end_a}' moves with a body or vessel, end B's '{line.end_b}' does not), but the "
                             "cable checks take end B as the hang-off (its declination, and the sag bend between "
                             f"the hog bend and end B). Suggested fix: swap the line's ends (end_a: {line.end_b}, "
                             f"end_b: {line.end_a}, and their end conditions).")


def _file_path(loc: tuple, data: Any) -> tuple:
    """A validation error's key path as the file writes it: ``lines.L1.line.segments[0].length`` is
    ``lines.L1.length`` for a line in the short form, ``lines.L1.segments[0].length`` otherwise."""
    if len(loc) < 3 or loc[0] != "lines" or loc[2] != "line" or not isinstance(data, dict):
        return loc
    entry = (data.get("lines") or {}).get(loc[1]) if isinstance(data.get("lines"), dict) else None
    if not isinstance(entry, dict) or "line" in entry:
        return loc
    rest = loc[3:]
    if "segments" not in entry and rest[:2] == ("segments", 0):
        rest = rest[2:]
    return loc[:2] + rest


def seabed_points(data: Any) -> Any:
    """Case data with each fixed or free point given at ``(x, y)`` only, or at ``(x, y, "seabed")``, put on the
    seabed there: the grid's elevation under it (:func:`seacable.environment.seabed_elevation`, refused off the grid
    or over land), or the plane's, ``-depth + tan(slope) x``. Data it cannot read (an environment that does not
    validate) is left as it is, for the case's validation to name."""
    points = data.get("points") if isinstance(data, dict) else None
    if not isinstance(points, dict):
        return data
    todo = [n for n, p in points.items() if isinstance(p, dict) and p.get("kind") in ("fixed", "free")
            and isinstance(p.get("position"), (list, tuple)) and (len(p["position"]) == 2 or (
                len(p["position"]) == 3 and p["position"][2] == "seabed"))]
    if not todo:
        return data
    try:
        env = SystemEnvironment.model_validate(data.get("environment") or {})
        xy = {n: (float(points[n]["position"][0]), float(points[n]["position"][1])) for n in todo}
    except (ValueError, TypeError):
        return data
    out = dict(points)
    for name in todo:
        x, y = xy[name]
        if env.seabed.grid is not None:
            z = seabed_elevation(env.seabed, x, y, f"point '{name}' (given on the seabed)")
        elif env.depth is not None:
            z = -env.depth + math.tan(env.seabed.slope) * x
        else:
            raise ValueError(f"points.{name}.position: given on the seabed (no z), but the environment has no seabed "
                             "(environment.depth or seabed.grid). Suggested fix: give z in m, or the depth.")
        out[name] = {**points[name], "position": [x, y, z]}
    return {**data, "points": out}

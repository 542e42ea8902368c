"""A case: a line, its environment, and what to compute.

A :class:`Case` is the unit of work of seacable: :func:`seacable.run` is a pure
function of it, so that cases can be stored, compared, pickled and farmed out.
Cases are written as YAML files (see :mod:`seacable.io.case_file`) or built in
code::

    import seacable as sc
    chain = sc.LineType(diameter=0.09, mass_per_length=77.7, axial_stiffness=3.8e8)
    case = sc.Case(name="demo", line=sc.Line.single(chain, 902.2),
                   environment=sc.Environment(depth=320.0),
                   analysis=sc.StaticAnalysis(fairlead=(848.67, -70.0)))
    ds = sc.run(case)

Each analysis type is a class with a literal ``type`` (the key a case file uses).
"""

from __future__ import annotations

import math
from typing import Annotated, Any, ClassVar, Literal, Union

import numpy as np
from pydantic import Field, model_serializer, model_validator

from ._model import UNION_TAGS, Model, input_error, quantity, suggest, unit_float
from ._window import StatisticsWindow, omit_unset_window
from .bathymetry import BathymetryGrid
from .environment import Environment, _warn_if_degrees, seabed_elevation
from .errors import InputError
from .laying.inputs import (Bathymetry, LayTableFile, LayTarget, Payout, PayoutBottomTension, PayoutSlack,
                             PlanShip, ShipMotion, read_lay_table)
from .laying.route import Route
from .line import STAND_IN, Line, LineType, RetypedCopies, resolve_sections
from .mooring.ends import EndCondition
from .mooring.friction import StaticFriction, StaticFrictionOption
from .mooring.motion import Motion
from .statics.towed import TangentialDragForm
from .ties import tie_points
from .towed.body import TowedBody
from .towed.vessel import VesselPath
from .towline.barge_model import Barge
from .vessel_motion import VesselMotionOption

__all__ = [
    "Analysis",
    "CableDesign",
    "Case",
    "LayPlanAnalysis",
    "LayingDynamicAnalysis",
    "LayingTheoryAnalysis",
    "ModalAnalysis",
    "MooringDynamicAnalysis",
    "MooringPushoverAnalysis",
    "MooringStaticAnalysis",
    "PushoverAnalysis",
    "SeabedContact",
    "StaticAnalysis",
    "TowedBody",
    "TowedSteadyAnalysis",
    "TowlineDynamicAnalysis",
    "VerticalModesAnalysis",
]

_XZ = tuple[unit_float("m"), unit_float("m")]

#: The environment's optional inputs (key paths under ``environment``) whose use depends on the analysis; each
#: analysis declares those it takes (:meth:`uses`), and a case that gives one its analysis does not use is
#: refused (:meth:`Case._unused_inputs`): a silently ignored input is a result of something other than asked.
ENVIRONMENT_INPUTS = ("depth", "current", "seabed.slope", "seabed.friction", "seabed.profile", "seabed.grid", "waves",
                      "wind")
_SEABED = frozenset({"depth", "seabed.slope", "seabed.friction"})
#: A static analysis is the still-water equilibrium: waves (a zero-mean load in linear theory) are taken, so that one
#: environment serves a line's statics and its dynamics, and have no part in it.
_STILL_WATER = frozenset({"waves"})


def given_environment_inputs(env: Environment) -> tuple[str, ...]:
    """The :data:`ENVIRONMENT_INPUTS` an environment gives (away from their defaults)."""
    cur, bed = env.current, env.seabed
    given = {"depth": env.depth is not None, "current": cur.speed != 0.0 or cur.depths is not None,
             "seabed.slope": bed.slope != 0.0, "seabed.friction": bed.friction != 0.0,
             "seabed.profile": bed.profile is not None, "seabed.grid": bed.grid is not None,
             "waves": env.waves is not None, "wind": env.wind is not None}
    return tuple(k for k in ENVIRONMENT_INPUTS if given[k])


class _Moored(Model):
    """Geometry shared by the analyses of a line between an anchor and a fairlead."""

    fairlead: _XZ = Field(description="Fairlead (end B) position (x, z): x from the anchor, "
                                      "z up from the sea surface. [m]")
    anchor: _XZ | None = Field(None, description="Anchor (end A) position (x, z); "
                                                  "default (0, -depth), on the seabed. [m]")

    @model_validator(mode="after")
    def _finite(self):
        for key in ("fairlead", "anchor"):
            point = getattr(self, key)
            if point is not None and not all(math.isfinite(v) for v in point):
                raise ValueError(f"{key} must hold two finite numbers (x, z) in m, got {point}.")
        return self


class StaticAnalysis(_Moored):
    """Static equilibrium of a (multi-segment) line between anchor and fairlead."""

    type: Literal["static"] = "static"
    USES: ClassVar[frozenset[str]] = _SEABED | _STILL_WATER  # the environment inputs it takes (Case._unused_inputs)
    points_per_segment: int = Field(50, ge=2, le=100_000, description="Profile points per segment.")


class _Offsets(Model):
    """Horizontal fairlead offsets of a force-excursion curve: a list, or a range."""

    offsets: tuple[unit_float("m"), ...] | None = Field(None, description="Horizontal fairlead offsets. [m]")
    min_offset: quantity("m") = Field(0.0, description="First offset when 'offsets' is not given. [m]")
    max_offset: quantity("m") | None = Field(None, description="Last offset when 'offsets' is not given. [m]")
    n_offsets: int = Field(41, ge=2, le=100_000, description="Number of offsets from min to max.")

    @model_validator(mode="after")
    def _range(self):
        if self.offsets is None and self.max_offset is None:
            raise ValueError("needs 'offsets' (a list, m) or 'max_offset' (m). "
                             "Suggested fix: add e.g. 'max_offset: 30.0'.")
        return self

    def offset_values(self) -> tuple[float, ...]:
        """The offsets to solve at. [m]"""
        if self.offsets is not None:
            return self.offsets
        step = (self.max_offset - self.min_offset) / (self.n_offsets - 1)
        return tuple(self.min_offset + i * step for i in range(self.n_offsets))


class PushoverAnalysis(_Offsets, _Moored):
    """Force-excursion curve: the fairlead moved horizontally by ``offsets``."""

    type: Literal["pushover"] = "pushover"
    USES: ClassVar[frozenset[str]] = _SEABED | _STILL_WATER  # the environment inputs it takes (Case._unused_inputs)


class ModalAnalysis(_Moored):
    """Natural frequencies and mode shapes about the static equilibrium.

    With ``free_end: true`` end A is free: the line hangs straight down from the fairlead (a
    hanging chain, a riser or a cable hanging from a ship) and ``anchor`` is not used.
    """

    type: Literal["modal"] = "modal"
    USES: ClassVar[frozenset[str]] = _SEABED | _STILL_WATER  # the environment inputs it takes (Case._unused_inputs)
    n_modes: int = Field(10, ge=1, le=1000, description="Modes to report per plane.")
    n_elements: int = Field(100, ge=2, le=20_000, description="Elements of the linearised model.")
    free_end: bool = Field(False, description="End A (the lower end) free: the line hangs from the fairlead.")

    @model_validator(mode="after")
    def _free_end(self):
        if self.free_end and self.anchor is not None:
            raise ValueError("'anchor' is not used with 'free_end: true' (end A hangs free below the "
                             "fairlead). Suggested fix: leave 'anchor' out, or set 'free_end: false'.")
        return self


class TowedSteadyAnalysis(Model):
    """Steady state of a cable towed in a current, uniform or varying with depth (free end or towed body).

    The line may be composite: its end A is the towed end, its segments and attachments (clumps, floats) run
    from there up to the tow point, at the surface (:func:`seacable.statics.towed.towed_line_steady`). The
    current's part along the tow is taken (the steady tow is 2-D)."""

    type: Literal["towed_steady"] = "towed_steady"
    USES: ClassVar[frozenset[str]] = frozenset({"depth", "current"}) | _STILL_WATER
    vessel_speed: quantity("m/s") = Field(description="Vessel speed along +X. [m/s]")
    body: TowedBody | None = None
    tangential_drag: TangentialDragForm = Field(
        "paper000", description="Form of the tangential drag (seacable.statics.towed.TangentialDragForm); "
                                "set the line type's drag_tangential to 0 for none.")
    n_nodes: int = Field(7, ge=2, le=100_000, description="Nodes at which the result is reported.")


class SeabedContact(Model):
    """Seabed contact of the mooring finite-element model: penalty springs and dampers on the nodes.

    The force per unit length of line is ``stiffness d p - damping d v_n`` (never pulling), with ``d``
    the diameter, ``p`` the penetration and ``v_n`` the velocity normal to the seabed (MoorDyn's kBot
    and cBot); the friction coefficient is ``environment.seabed.friction``, regularised below
    ``friction_velocity``.
    """

    stiffness: quantity("Pa/m", ge=0, fix="MoorDyn's default is 3e6 Pa/m.") = Field(
        3.0e6, description="Penalty stiffness per unit of projected area. [Pa/m]")
    damping: quantity("Pa s/m", ge=0) = Field(3.0e5, description="Damping per unit of projected area. [Pa s/m]")
    friction_velocity: quantity("m/s", gt=0) = Field(
        0.01, description="Sliding speed below which friction is regularised. [m/s]")


class Winch(Model):
    """Pay-out (the deployed length growing) or haul-in of the cable at the tow point.

    Either a ``rate`` [m/s] (positive pays out, negative hauls in) from ``start_time`` until the deployed
    length reaches ``length`` (or the run ends), or a table of deployed ``lengths`` at ``times``, linear in
    between and constant beyond its ends. The cable paid out is the line's last segment (end B's line type)."""

    rate: quantity("m/s") | None = Field(None, description="Pay-out rate, negative hauls in. [m/s]")
    start_time: quantity("s", ge=0) = Field(0.0, description="When the rate starts. [s]")
    ramp: quantity("s", ge=0) = Field(0.0, description="Time over which the rate builds up from 0 (and, with a "
                                                       "'length', falls back to 0 before it). [s]")
    length: quantity("m", gt=0) | None = Field(None, description="Deployed length at which the rate stops. [m]")
    times: tuple[unit_float("s"), ...] | None = Field(None, description="Times of a length table. [s]")
    lengths: tuple[unit_float("m"), ...] | None = Field(None, description="Deployed lengths at those times. [m]")

    @model_validator(mode="after")
    def _check(self):
        table = self.times is not None or self.lengths is not None
        if table == (self.rate is not None):
            raise ValueError("give either 'rate' (m/s, positive pays out) or a table of 'times' (s) and 'lengths' "
                             "(m). Suggested fix: e.g. 'rate: 0.5' or 'times: [0, 600]' with 'lengths: [1000, 1300]'.")
        if table:
            if self.times is None or self.lengths is None or len(self.times) != len(self.lengths) \
                    or len(self.times) < 2:
                raise ValueError("the pay-out table needs 'times' and 'lengths' of the same length, at least 2. "
                                 "Suggested fix: give the deployed length at two or more times.")
            t, length = np.asarray(self.times, float), np.asarray(self.lengths, float)
            if not (np.all(np.isfinite(t)) and np.all(np.isfinite(length))):
                raise ValueError("the pay-out table's times (s) and lengths (m) must be finite numbers.")
            bad = np.flatnonzero(np.diff(t) <= 0)
            if bad.size:
                k = int(bad[0])
                raise ValueError(f"the pay-out table's times must increase, but times[{k + 1}] = {t[k + 1]:g} s follows "
                                 f"times[{k}] = {t[k]:g} s. Suggested fix: sort the table by time and give each "
                                 "time once.")
            if np.any(length <= 0):
                k = int(np.argmax(length <= 0))
                raise ValueError(f"the pay-out table's lengths must be > 0 m, got lengths[{k}] = {length[k]:g} m.")
        elif self.rate == 0.0:
            raise ValueError("winch.rate is 0 m/s: nothing is paid out. Suggested fix: leave 'winch' out, or give "
                             "a rate (m/s, positive pays out, negative hauls in).")
        return self

    def deployed(self, times, length0: float) -> np.ndarray:
        """The deployed length [m] at ``times`` [s] of a cable ``length0`` [m] long at t = 0."""
        t = np.asarray(times, float)
        if self.rate is None:
            return np.interp(t, self.times, self.lengths)
        tau = np.clip(t - self.start_time, 0.0, None)
        r, ramp = abs(self.rate), self.ramp
        # the rate's trapezoid: up over the ramp, constant, and (to a length) down over the ramp before it
        run = r * (tau - 0.5 * ramp) if ramp == 0.0 else np.where(tau < ramp, 0.5 * r / ramp * tau ** 2,
                                                                   r * (tau - 0.5 * ramp))
        if self.length is not None:
            total = abs(self.length - length0)
            end = total / r + ramp
            if ramp > 0.0:
                run = np.where(tau > end - ramp, total - 0.5 * r / ramp * np.clip(end - tau, 0.0, None) ** 2, run)
            run = np.minimum(run, total)
        return length0 + np.sign(self.rate) * run

    def check_against(self, length0: float) -> None:
        """Refuse a rate and a target length that do not fit the line's ``length0`` [m] at t = 0."""
        if self.rate is None or self.length is None:
            return
        if (self.length - length0) * self.rate < 0:
            raise InputError(f"analysis.winch: rate {self.rate:g} m/s {'pays out' if self.rate > 0 else 'hauls in'} "
                             f"but the target length {self.length:g} m is {'shorter' if self.rate > 0 else 'longer'} "
                             f"than the line's {length0:g} m. Suggested fix: give the rate the sign that reaches the "
                             "length (positive pays out).")
        if abs(self.length - length0) < abs(self.rate) * self.ramp:
            raise InputError(f"analysis.winch: {abs(self.length - length0):g} m to go at {abs(self.rate):g} m/s is "
                             f"shorter than the ramps up and down ({self.ramp:g} s each) take. Suggested fix: a "
                             "shorter ramp or a smaller rate.")


class TowedDynamicAnalysis(VesselMotionOption, StatisticsWindow):
    """Time-domain dynamics of a towed system behind a vessel path.

    ``formulation``: ``finite_element`` (the default) is the mooring model's (paper 004: lumped masses on
    elastic elements with bending where the line types give EI, Morison loads, seabed contact) with the
    vessel's tow point moving the top node: composite cables, bodies in line, lift, pay-out and haul-in
    (``winch``), seabed contact and a start from rest; ``box`` is paper 000's implicit finite-difference box
    scheme with bending stiffness (one uniform cable, a body at its end, a moving vessel)."""

    type: Literal["towed_dynamic"] = "towed_dynamic"
    USES: ClassVar[frozenset[str]] = frozenset(ENVIRONMENT_INPUTS) - {"wind"}

    def uses(self, env: Environment) -> frozenset[str]:
        """The environment inputs of this analysis in ``env``: a seabed profile in the finite-element formulation
        only; beside a profile (the seabed) the depth sets only the waves' dispersion."""
        if self.formulation != "finite_element":
            return self.USES - {"seabed.profile"}
        if (env.seabed.profile is not None or env.seabed.grid is not None) and env.waves is None:
            return self.USES - {"depth"}
        return self.USES
    formulation: Literal["finite_element", "box"] = Field(
        "finite_element", description="finite_element (paper 004's model) or box (paper 000's scheme).")
    winch: Winch | None = Field(None, description="Pay-out or haul-in at the tow point (finite_element).")
    spectral_radius: quantity("-", ge=0, le=1, fix="use 0.7 (the default) or 1 for no numerical damping.") = Field(
        0.7, description="finite_element: the generalised-alpha amplification per step of the modes far above "
                         "1 / time_step (the axial modes a towed line's step does not resolve; 1: average "
                         "acceleration, no numerical damping). [-]")
    seabed_contact: SeabedContact = Field(default_factory=SeabedContact)
    vessel: VesselPath = Field(description="Tow-point motion: straight, speed_schedule, turn or table.")
    duration: quantity("s", gt=0) = Field(description="Simulated time. [s]")
    time_step: quantity("s", gt=0) = Field(0.5, description="Time step (halved locally where Newton fails). [s]")
    output_interval: quantity("s", gt=0) | None = Field(
        None, description="Time between stored states, a multiple of time_step (default: time_step). [s]")
    n_nodes: int = Field(7, ge=3, le=100_000, description="Nodes from the lower end to the vessel.")
    body: TowedBody | None = None
    tangential_drag: TangentialDragForm | None = Field(
        None, description="Form of the tangential drag (seacable.statics.towed.TangentialDragForm); default "
                          "paper000 in the box formulation, common in the finite-element one.")
    current_follows_vessel: bool = Field(
        False, description="Turn the current with the vessel's course (heading measured from the course).")
    tolerance: quantity("-", gt=0, lt=1e-2) = Field(1e-8, description="Newton tolerance, scaled. [-]")
    max_iterations: int = Field(25, ge=2, le=1000, description="Newton iterations per step.")

    @model_validator(mode="after")
    def _steps(self):
        if self.time_step > self.duration:
            raise ValueError(f"time_step ({self.time_step:g} s) must not exceed duration "
                             f"({self.duration:g} s). Suggested fix: shorten the step.")
        out = self.output_interval
        if out is not None:
            k = round(out / self.time_step)
            if k < 1 or abs(k * self.time_step - out) > 1e-9 * out:
                raise ValueError(f"output_interval ({out:g} s) must be a multiple of time_step "
                                 f"({self.time_step:g} s). Suggested fix: use {max(k, 1) * self.time_step:g} s.")
        if self.body is not None and not self.body.mass > 0:
            raise ValueError("body.mass must be > 0 kg for towed_dynamic: the body's inertia enters its "
                             "equation of motion. Suggested fix: give the mass in air, e.g. weight/9.81 "
                             "plus the mass of the displaced water.")
        if self.formulation == "box":
            if self.body is not None and self.body.lift_coefficient != 0.0:
                raise ValueError(f"body.lift_coefficient {self.body.lift_coefficient:g}: the box formulation does not "
                                 "model a body's lift. Suggested fix: use formulation: finite_element.")
            if self.winch is not None:
                raise ValueError("winch: the box formulation has a fixed cable length. Suggested fix: use "
                                 "formulation: finite_element for pay-out and haul-in.")
        return self


class LayingTheoryAnalysis(Model):
    """Straight-line laying theory (paper 001 section 2) over a list of ship speeds."""

    type: Literal["laying_theory"] = "laying_theory"
    USES: ClassVar[frozenset[str]] = frozenset({"depth"})
    ship_speeds: tuple[unit_float("m/s"), ...] = Field(min_length=1, description="Ship speeds. [m/s]")
    bottom_tension: quantity("N", ge=0) = Field(0.0, description="Tension at the touchdown. [N]")
    slack: quantity("-", ge=-0.5, le=10.0) = Field(
        0.0, description="Payout speed over ship speed minus one. [-]")

    @model_validator(mode="after")
    def _speeds(self):
        for i, v in enumerate(self.ship_speeds):
            if not (math.isfinite(v) and v > 0):
                raise ValueError(f"ship_speeds[{i}] must be > 0 m/s, got {v} m/s.")
        return self


class LayingDynamicAnalysis(VesselMotionOption, StatisticsWindow):
    """Time-domain laying from a moving ship: paper 001's lumped-mass model with payout, in 2-D or along a route
    in 3-D.

    Without a ``route``: paper 001's vertical plane, x along the ship's track, z up from the sea surface
    (the current's component along x). With a ``route``: the same model in x, y, z, the ship following the
    route's legs from KP ``ship.start_x``, the seabed from ``bathymetry`` (by KP) or ``bathymetry_grid``,
    the current with its heading. The line is the cable on board, end A first: the run starts with cable
    on the seabed behind the touchdown (as long as the suspended part) and ``line.attachments`` are the
    repeaters (point masses) at their arc lengths.
    """

    type: Literal["laying_dynamic"] = "laying_dynamic"
    USES: ClassVar[frozenset[str]] = _SEABED | {"current"}
    lay_table: LayTableFile | None = Field(
        None, description="Follow a lay plan: the ship and payout speeds by time of a lay_plan's table (CSV).")
    ship: ShipMotion = Field(description="Ship speed (constant or a schedule) and repeater slow-downs.")
    payout: Payout = Field(default_factory=PayoutSlack,
                           description="Payout control: 'rate', 'slack' or 'bottom_tension'.")
    bathymetry: Bathymetry | None = Field(
        None, description="Depth along the track (by KP along a route); default environment.depth and seabed.slope.")
    route: Route | None = Field(None, description="A route to lay along, in 3-D (waypoints in x, y or "
                                                  "latitude, longitude); default paper 001's 2-D plane.")
    bathymetry_grid: BathymetryGrid | None = Field(None, description="Depth on a grid (with a route).")
    duration: quantity("s", gt=0) = Field(description="Simulated time. [s]")
    segment_length: quantity("m", gt=0, fix="use about 1/50 of the water depth or less.") = Field(
        1.0, description="Length of the cable between nodes. [m]")
    steps_per_segment: quantity("-", ge=1.0, le=1000.0) = Field(
        4.0, description="Time steps per segment length paid out or run: dt = l / (n max(V_s, V_c)). [-]")
    max_time_step: quantity("s", gt=0) = Field(1.0, description="Upper bound of the time step. [s]")
    output_interval: quantity("s", gt=0) = Field(1.0, description="Time between stored states. [s]")
    initial_angle: quantity("rad", gt=0, lt=math.pi) | None = Field(
        None, description="Angle of the initial straight cable; default the steady laying angle. [rad]")
    extensible: bool = Field(False, description="Elastic cable with the line type's axial_stiffness; "
                                                "default inextensible (paper eq. (15)).")
    laid_cable: Literal["held", "sliding"] = Field(
        "held", description="'held': laid cable stays where it lands (friction without limit); 'sliding': the "
                            "laid cable near the touchdown slides on the seabed against Coulomb friction "
                            "(environment.seabed.friction), pulled by the cable's tension and its weight on a slope.")
    friction_distance: quantity("m", gt=0) = Field(
        1e-3, description="With laid_cable 'sliding': the slip at which the friction reaches its limit; below it the "
                          "laid cable is held by a spring of stiffness mu R / friction_distance. [m]")
    slack_window: quantity("s", gt=0) = Field(60.0, description="Time over which slack is measured. [s]")
    tolerance: quantity("-", gt=0, lt=1e-3) = Field(1e-9, description="Newton tolerance, relative. [-]")
    max_iterations: int = Field(50, ge=2, le=1000, description="Newton iterations per step.")

    @model_validator(mode="before")
    @classmethod
    def _follow_the_plan(cls, data):
        """A lay table gives the ship (its speeds by time, from the table's first KP) and the payout (a rate by
        time): the control mode that follows the plan."""
        if not isinstance(data, dict) or not isinstance(data.get("lay_table"), dict):
            return data
        given = [k for k in ("ship", "payout") if data.get(k) is not None]
        if given:
            raise ValueError(f"lay_table gives the ship's and the payout's speeds; {' and '.join(given)} too. Suggested "
                             f"fix: leave {' and '.join(given)} out, or the lay_table.")
        file = data["lay_table"].get("file")
        if not isinstance(file, str):
            return data                    # the field's own validation says what is missing
        try:
            cols = read_lay_table(file)
        except InputError as err:
            raise ValueError(str(err)) from None
        start = data["lay_table"].get("start_kp")
        if start is not None:
            # from a ship KP on: the row there (interpolated) and the rows after it
            kp = cols["kp"]
            if not (isinstance(start, (int, float)) and kp[0] <= start < kp[-1]):
                raise ValueError(f"lay_table.start_kp = {start!r} m lies outside the table's ship KPs ({kp[0]:g} to "
                                 f"{kp[-1]:g} m). Suggested fix: a KP within the table, or leave it out to start at "
                                 "its first row.")
            after = kp > start
            cols = {name: np.concatenate([[np.interp(start, kp, values)], values[after]])
                    for name, values in cols.items()}
        times = tuple(float(t - cols["time"][0]) for t in cols["time"])
        return {**data, "ship": {"times": times, "speeds": tuple(map(float, cols["ship_speed"])),
                                 "start_x": float(cols["kp"][0])},
                "payout": {"type": "rate", "times": times, "speeds": tuple(map(float, cols["payout_speed"]))}}

    @model_validator(mode="after")
    def _check(self):
        if self.output_interval > self.duration:
            raise ValueError(f"output_interval ({self.output_interval:g} s) must not exceed duration "
                             f"({self.duration:g} s).")
        if self.bathymetry_grid is not None and (self.route is None or self.bathymetry is not None):
            raise ValueError("bathymetry_grid needs a route (it is a map in x, y) and takes the place of "
                             "'bathymetry'. Suggested fix: add 'route' with the waypoints, and give the depth once.")
        if isinstance(self.payout, PayoutBottomTension) and not self.extensible:
            raise ValueError("payout 'bottom_tension' needs 'extensible: true' and an axial_stiffness: for an "
                             "inextensible cable every bottom tension gives the same straight steady lay "
                             "(paper eq. (11)) and cannot be set by the payout. Suggested fix: add "
                             "'extensible: true' and the cable's EA, or use payout 'slack'.")
        return self


class LayPlanAnalysis(Model):
    """The lay table along a route, KP by KP, from a quasi-static model of the lay (:mod:`seacable.laying.plan`).

    The line is the cable on board, end A laid first at the start of the table; ``line.attachments``
    are the repeaters and in-line bodies at their cable lengths ``s``. The current is the environment's
    (its ``heading`` is in the route's x, y frame: from +x, east, towards +y, north).
    """

    type: Literal["lay_plan"] = "lay_plan"
    USES: ClassVar[frozenset[str]] = frozenset({"depth", "current"})
    route: Route = Field(description="Waypoints (alter-course positions) in x, y [m] or latitude, longitude.")
    ship: PlanShip = Field(description="Ship speed over ground (constant or by KP) and the repeater slow-down.")
    target: LayTarget = Field(description="Slack or bottom tension to hold on the seabed (constant or by KP).")
    bathymetry: Bathymetry | None = Field(
        None, description="Depth along the route: 'distance' (or a CSV column 'kp') is the KP. [m]")
    bathymetry_grid: BathymetryGrid | None = Field(None, description="Depth on an x, y (or lon, lat) grid.")
    kp_step: quantity("m", gt=0, fix="a lay table is usually given every 100 m of KP.") = Field(
        100.0, description="KP interval of the table's rows. [m]")
    kp_start: quantity("m") | None = Field(None, description="First ship KP of the table; default the route's "
                                                             "start. [m]")
    kp_end: quantity("m") | None = Field(None, description="Last ship KP of the table; default the route's end. [m]")

    @model_validator(mode="after")
    def _check(self):
        if self.bathymetry is not None and self.bathymetry_grid is not None:
            raise ValueError("give the depth once: 'bathymetry' (a table along the route) or 'bathymetry_grid'.")
        if self.kp_start is not None and self.kp_end is not None and not self.kp_end > self.kp_start:
            raise ValueError(f"kp_end ({self.kp_end:g} m) must be beyond kp_start ({self.kp_start:g} m).")
        return self


VerticalModeMethod = Literal["string", "exact", "wave"]


class VerticalModesAnalysis(Model):
    """Natural periods of a vertical cable (paper 002 eq. 15 and the exact solution).

    ``methods`` lists the solutions to compute (default: every one that applies): ``string``, a
    uniform string at the bottom tension (paper 002 Table 1 row A, gravity neglected; it needs
    ``bottom_tension > 0``), ``exact``, the Bessel-function solution (row B; with ``bottom_tension: 0``
    the hanging chain with its lower end free) and ``wave``, the lateral wave's round trip (eq. 15,
    row C).
    """

    type: Literal["vertical_modes"] = "vertical_modes"
    USES: ClassVar[frozenset[str]] = frozenset()
    bottom_tension: quantity("N", ge=0) = Field(description="Tension at the lower end (0: a free end). [N]")
    n_modes: int = Field(5, ge=1, le=100)
    methods: tuple[VerticalModeMethod, ...] | None = Field(
        None, min_length=1, description="Solutions to compute: string, exact, wave (default: all that apply).")

    @model_validator(mode="after")
    def _methods(self):
        m = self.methods
        if m is not None and len(set(m)) != len(m):
            raise ValueError(f"methods lists a solution twice: {list(m)}. Suggested fix: name each once.")
        if m is not None and "string" in m and self.bottom_tension == 0:
            raise ValueError("methods includes 'string', a uniform string at the bottom tension, but "
                             "bottom_tension is 0 N: a string without tension has no frequency. Suggested fix: "
                             "leave 'string' out of methods (the hanging chain is 'exact' and 'wave').")
        return self

    def solutions(self) -> tuple[str, ...]:
        """The solutions to compute, in the order string, exact, wave unless given."""
        if self.methods is not None:
            return tuple(self.methods)
        return ("string", "exact", "wave") if self.bottom_tension > 0 else ("exact", "wave")


class ArmourSNCurve(Model):
    """An S-N curve of the cable's armour wires on the stress range ``s`` [MPa] (:class:`seacable.design.cable_fatigue.
    SNCurve`): ``N = a s^-m``, below the knee at ``n_knee`` cycles ``m2`` when given."""

    a: quantity("MPa^m", gt=0, fix="give the intercept of N = a s^-m, e.g. 1.0e12 (DNV-RP-C203's B1 in seawater "
                                   "with cathodic protection: 4.0e12 with m = 4).") = Field(
        description="Intercept of the first slope. [MPa^m]")
    m: quantity("-", gt=0, fix="give the slope of N = a s^-m, e.g. 3 or 4.") = Field(description="First slope. [-]")
    m2: quantity("-", gt=0, fix="give the second slope, e.g. 5, or leave it out for one slope.") | None = Field(
        None, description="Second slope, below the knee; none: one slope. [-]")
    n_knee: quantity("1", gt=0, fix="give the cycles at the knee, e.g. 1e7.") = Field(
        1e7, description="Cycles at the knee. [1]")


class ArmourFatigue(Model):
    """The armour's stress model and S-N curve for the cable's fatigue in the report
    (:func:`seacable.design.cable_fatigue.cable_fatigue_damage`): ``sigma = c_T T + c_kappa kappa (n . e(phi))``."""

    tension_factor: quantity("Pa/N", gt=0, fix="give the armour stress per newton of tension, about 1 / (A_armour "
                                               "cos^2 alpha), e.g. 1500 for 600 mm^2 of wires.") = Field(
        description="Armour stress per unit effective tension c_T. [Pa/N]")
    curvature_factor: quantity("Pa m", fix="give the armour stress per 1/m of curvature, about E r cos^2 alpha "
                                           "while the wires stick, e.g. 1.5e10.") = Field(
        description="Armour stress per unit curvature c_kappa (its sign picks the hot spot only). [Pa m]")
    points: int = Field(8, description="Points around the section where the stress is counted, 1 to 360.")
    sn_curve: ArmourSNCurve = Field(description="The armour's S-N curve on the stress range in MPa.")

    @model_validator(mode="after")
    def _nonzero(self):
        if not 1 <= self.points <= 360:
            raise ValueError(f"armour.points must be 1 to 360 points around the section, got {self.points}. Suggested "
                             "fix: 8 points (every 45 deg) find the hot spot of a bend in any plane.")
        if self.curvature_factor == 0.0:
            raise ValueError("armour.curvature_factor is 0 Pa m: the bend would stress no wire. Suggested fix: give the "
                             "stress per 1/m of curvature, about E r cos^2 alpha, e.g. 1.5e10 Pa m.")
        return self


class CableDesign(Model):
    """The design criteria of a cable's configuration that its line types do not hold (issue 40), read by the
    cable checks of :mod:`seacable.design.cable` from the case a result records (a system's: for each of its lines
    with bending stiffness, :mod:`seacable.design.system_cable`).

    Parameters
    ----------
    sag_bend_clearance
        The smallest height above the seabed the sag bend (the trough between the hog bend's arch and end B, the
        hang-off) may come down to; 0: it must not touch the seabed. [m]
    hog_bend_clearance
        The smallest height above the seabed the hog bend's crest (the arch over the buoyancy) may come down to;
        0: the arch must not fall onto the seabed. [m]
    hang_off_declination
        The range ``(lowest, highest)`` the line's declination at end B (its angle from the upward vertical,
        towards end B, as ``declination`` in the results) must stay in; None: not checked. [rad]
    """

    sag_bend_clearance: quantity("m", ge=0, fix="give the sag bend's required height above the seabed in m "
                                               "(0: it must not touch down).") = Field(
        0.0, description="Smallest height of the sag bend above the seabed; 0: no touchdown. [m]")
    hog_bend_clearance: quantity("m", ge=0, fix="give the hog bend's required height above the seabed in m "
                                               "(0: the arch must not fall onto it).") = Field(
        0.0, description="Smallest height of the hog bend's crest above the seabed. [m]")
    hang_off_declination: tuple[float, float] | None = Field(
        None, description="Range (lowest, highest) of the declination at end B, 0 to pi. [rad]")
    armour: ArmourFatigue | None = Field(None, description="Armour stress model and S-N curve for the cable's fatigue.")
    line_clearance: quantity("m", gt=0, fix="give the smallest distance in metres between the cable's and another "
                                            "line's centrelines, e.g. 10.") | None = Field(
        None, description="Smallest distance to the system's other lines. [m]")

    @model_serializer(mode="wrap")
    def _omit_unset(self, handler):
        # the armour and the line clearance appear in a dumped case only when given: a case without them reads as it
        # did before they existed
        data = handler(self)
        if isinstance(data, dict):
            for key in ("armour", "line_clearance"):
                if data.get(key, 0) is None:
                    del data[key]
        return data

    @model_validator(mode="after")
    def _check_range(self):
        r = self.hang_off_declination
        if r is None:
            return self
        lo, hi = r
        fix = ("Suggested fix: give the range in radians from the upward vertical, 0 to pi (0 to 180 deg), lowest "
               "first, e.g. [0.1, 0.35] for a hang-off between 6 and 20 deg off vertical.")
        if not all(math.isfinite(v) for v in r):
            raise ValueError(f"hang_off_declination must be two finite angles in rad, got {list(r)}. {fix}")
        if min(r) < 0.0 or max(r) > math.pi:
            degrees = " (it looks like degrees)" if max(r) > math.pi and max(r) <= 180.0 else ""
            raise ValueError(f"hang_off_declination must lie within 0 to 3.14159 rad, got [{lo:g}, {hi:g}] rad"
                             f"{degrees}. {fix}")
        if not lo < hi:
            raise ValueError(f"hang_off_declination must be (lowest, highest) with lowest < highest, got [{lo:g}, "
                             f"{hi:g}] rad. {fix}")
        return self


class _Mooring(_Moored):
    """Options shared by the analyses of the mooring finite-element model (paper 004)."""

    n_elements: int = Field(50, ge=1, le=100_000,
                            description="Elements on the line, spread by length (a segment's own "
                                        "n_elements wins).")
    element_length: quantity("m", gt=0) | None = Field(
        None, description="Target element length instead of n_elements. [m]")
    seabed_contact: SeabedContact = Field(default_factory=SeabedContact)
    tolerance: quantity("-", gt=0, lt=1e-2) = Field(
        1e-8, description="Newton tolerance on the force residual, relative to the largest tension or "
                          "node weight. [-]")
    anchor_end_condition: EndCondition = Field(
        default_factory=EndCondition, description="How end A (the anchor) is held in bending: pinned (default), "
                                                  "clamped at a declination and azimuth, or a rotational spring.")
    fairlead_end_condition: EndCondition = Field(
        default_factory=EndCondition, description="How end B (the fairlead, a hang-off) is held in bending: "
                                                  "pinned (default), clamped or a rotational spring.")
    design: CableDesign | None = Field(
        None, description="Design criteria of a cable's configuration (clearances of its bends, the hang-off "
                          "angle range) for the cable checks; the cable's own limits are on its line types.")
    compression: bool = Field(
        False, description="The elements carry compression too (EA times a negative strain), as a cable with bending "
                           "stiffness does; false: tension only (MoorDyn's rule). A cable's end held at a direction "
                           "the line pulls away from (a steep wave's base) needs it.")

    @model_serializer(mode="wrap")
    def _omit_unset_design(self, handler):
        # 'design' and 'compression' appear in a dumped case (a result's 'case' attribute) only when given: the
        # cases without them read as they did before they existed
        data = handler(self)
        if isinstance(data, dict) and data.get("design", 0) is None:
            del data["design"]
        if isinstance(data, dict) and data.get("compression", True) is False:
            del data["compression"]
        if isinstance(data, dict) and data.get("static_friction", 0) == StaticFriction().model_dump():
            del data["static_friction"]  # and the default static friction: a case without it reads as before
        return omit_unset_window(data)


class MooringStaticAnalysis(StaticFrictionOption, _Mooring):
    """Static equilibrium of the line by the finite-element model (paper 004), Newton's method."""

    type: Literal["mooring_static"] = "mooring_static"
    USES: ClassVar[frozenset[str]] = _SEABED | _STILL_WATER | {"current", "seabed.profile", "seabed.grid"}


class MooringPushoverAnalysis(StaticFrictionOption, _Offsets, _Mooring):
    """Quasi-static force-excursion curve of the finite-element model: the fairlead moved horizontally by the
    offsets along ``heading`` (0: along +x, away from the anchor, so that positive offsets are the far position and
    negative ones the near; pi/2: across the line's plane, the cross position)."""

    type: Literal["mooring_pushover"] = "mooring_pushover"
    USES: ClassVar[frozenset[str]] = _SEABED | _STILL_WATER | {"current", "seabed.profile", "seabed.grid"}
    heading: quantity("rad") = Field(0.0, description="Direction of the offsets from +x towards +y. [rad]")

    @model_validator(mode="after")
    def _heading(self):
        _warn_if_degrees("analysis.heading", self.heading, 2 * math.pi)
        return self


class MooringDynamicAnalysis(_Mooring, StatisticsWindow):
    """Time-domain response of the line to fairlead motion, current and waves (paper 004).

    Truss finite elements, lumped and added mass, Morison loads, seabed contact, the generalised-alpha
    method (Chung and Hulbert 1993) with Newton iterations each step: ``spectral_radius`` 1 (the
    default for lines without bending stiffness) is Newmark's average acceleration (beta 1/4, gamma 1/2), below 1
    it damps the modes the step cannot resolve (a snap load's ringing; 0.9, a cable's default). The run starts from the static equilibrium. With
    ``end_b: free`` the line's end B is a free node (a buoy: put an attachment at its end) and
    ``release_from`` holds it at (x, z) for the static start, then lets it go at t = 0.
    """

    type: Literal["mooring_dynamic"] = "mooring_dynamic"
    USES: ClassVar[frozenset[str]] = _SEABED | {"current", "waves", "seabed.profile", "seabed.grid"}
    motion: Motion | None = Field(None, description="Fairlead motion: harmonic, time_series or platform.")
    end_b: Literal["fairlead", "free"] = Field("fairlead", description="End B moved by 'motion', or free.")
    release_from: _XZ | None = Field(None, description="Where a free end B is held before release (x, z). [m]")
    duration: quantity("s", gt=0) = Field(description="Simulated time. [s]")
    time_step: quantity("s", gt=0) = Field(0.1, description="Newmark time step (halved on a failed step). [s]")
    spectral_radius: quantity("-", ge=0, le=1, fix="use 1 (no numerical damping) or 0.7-0.9 to damp the "
                                                   "ringing of stiff modes at a coarse step.") | None = Field(
        None, description="Generalised-alpha amplification per step of the modes far above 1 / time_step "
                          "(1: average acceleration, no numerical damping; 0: the most damping). Default: 1 for "
                          "lines without bending stiffness, 0.9 for a cable (a line with bending stiffness, whose "
                          "unresolved bending and axial modes ring at 1 and cost Newton iterations). [-]")
    output_interval: quantity("s", gt=0) = Field(0.5, description="Time between stored states. [s]")
    damping_ratio: quantity("-", ge=0, le=10) = Field(
        0.0, description="Axial damping ratio of each element's axial mode (MoorDyn's BA = -ratio). [-]")
    rayleigh: tuple[float, float] = Field((0.0, 0.0), description="Rayleigh damping (alpha [1/s], beta [s]).")
    max_iterations: int = Field(30, ge=2, le=1000, description="Newton iterations per step.")

    @model_validator(mode="after")
    def _check(self):
        if self.output_interval > self.duration:
            raise ValueError(f"output_interval ({self.output_interval:g} s) must not exceed duration "
                             f"({self.duration:g} s).")
        if self.end_b == "free" and self.fairlead_end_condition.holds:
            raise ValueError(f"a free end B cannot be held at a direction (fairlead_end_condition: "
                             f"{self.fairlead_end_condition.type}): nothing holds it. Suggested fix: leave "
                             "fairlead_end_condition out (pinned), or use end_b: fairlead.")
        if self.end_b == "free" and self.motion is not None:
            raise ValueError("a free end B cannot follow a 'motion'. Suggested fix: drop 'motion' or use "
                             "end_b: fairlead.")
        if self.release_from is not None and self.end_b != "free":
            raise ValueError("'release_from' needs 'end_b: free'.")
        if any(c < 0 or not math.isfinite(c) for c in self.rayleigh):
            raise ValueError(f"rayleigh must hold two finite numbers >= 0 (alpha [1/s], beta [s]), got "
                             f"{self.rayleigh}.")
        return self


class TowlineDynamicAnalysis(StatisticsWindow):
    """A tug towing a barge on the towline: the multibody model of paper 003.

    The line is ``n_elements`` rigid elements joined by spring-dampers; its axial stiffness is the
    line type's ``axial_stiffness``, or ``breaking_load / elongation_at_break`` (paper 003: 16 t and
    15 %). The tug's tow point follows ``tug`` at ``tug_tow_point_height``; the barge is a rigid body in
    surge, sway and yaw towed at its own tow point (``barge_held`` holds it still). ``start``:
    ``straight`` (the line straight astern of the tug, the barge at its end), ``dropped`` (horizontal
    at ``drop_height`` above the water) or ``coiled`` (on the tug's bitt, paid out as the tug moves
    off, the barge starting at the tug).
    """

    type: Literal["towline_dynamic"] = "towline_dynamic"
    USES: ClassVar[frozenset[str]] = frozenset({"depth", "seabed.friction"})
    tug: VesselPath = Field(description="Tug tow-point track: straight, speed_schedule, turn, zigzag or table.")
    tug_tow_point_height: quantity("m") = Field(2.0, description="Tug tow point above the water. [m]")
    barge: Barge = Field(description="The towed barge.")
    barge_held: bool = Field(False, description="Hold the barge still (a fixed end).")
    start: Literal["straight", "dropped", "coiled"] = Field("straight", description="Initial line.")
    drop_height: quantity("m") | None = Field(None, description="Height of a dropped line. [m]")
    n_elements: int = Field(11, ge=1, le=10_000, description="Rigid elements (paper 003: 11).")
    elongation_at_break: quantity("-", gt=0, lt=1) | None = Field(
        None, description="Strain at the breaking load; with the line type's breaking_load gives EA. [-]")
    damping_ratio: quantity("-", ge=0) = Field(0.5, description="Axial joint damping ratio zeta. [-]")
    bending_damping_ratio: quantity("-", ge=0) = Field(0.5, description="Bending damping ratio. [-]")
    transverse_damping_fraction: quantity("-", ge=0) = Field(
        0.1, description="Joint damping across the line over that along it (paper 003: 1/10). [-]")
    brake_tension: quantity("N", ge=0) = Field(0.0, description="Tension holding the line on the bitt. [N]")
    impact: bool = Field(True, description="Water-entry impact force.")
    duration: quantity("s", gt=0) = Field(description="Simulated time. [s]")
    output_interval: quantity("s", gt=0) = Field(1.0, description="Time between stored states. [s]")
    time_step: quantity("s", gt=0) | None = Field(
        None, description="Explicit step; default from the stability bound of the elements. [s]")
    seabed_contact: SeabedContact = Field(default_factory=SeabedContact)

    @model_validator(mode="after")
    def _check(self):
        if self.output_interval > self.duration:
            raise ValueError(f"output_interval ({self.output_interval:g} s) must not exceed duration "
                             f"({self.duration:g} s).")
        if self.start == "dropped" and self.drop_height is None:
            raise ValueError("start 'dropped' needs drop_height (m above the water; paper 003: 1.0).")
        return self


ANALYSES = (StaticAnalysis, PushoverAnalysis, ModalAnalysis, TowedSteadyAnalysis, TowedDynamicAnalysis,
            LayingTheoryAnalysis, LayingDynamicAnalysis, LayPlanAnalysis,
            VerticalModesAnalysis, MooringStaticAnalysis, MooringPushoverAnalysis, MooringDynamicAnalysis,
            TowlineDynamicAnalysis)
Analysis = Annotated[Union[ANALYSES], Field(discriminator="type")]  # noqa: UP007
UNION_TAGS.update(cls.model_fields["type"].default for cls in ANALYSES)


class Case(RetypedCopies, Model):
    """A line, its environment and an analysis.

    Parameters
    ----------
    name
        Short name, used for output files.
    description
        Free text: source, assumptions, unit conversions.
    line_types
        Named line types the segments may refer to by name.
    line
        The line. In a file, ``line: {line_type: NAME, length: L}`` is short for
        a single segment.
    environment
        Water, current and seabed.
    analysis
        What to compute, selected by its ``type``.
    """

    name: str = Field("case", min_length=1)
    description: str = ""
    line_types: dict[str, LineType] = Field(default_factory=dict)
    line: Line
    environment: Environment = Environment()
    analysis: Analysis

    @classmethod
    def parse(cls, data: Any, *, root: str = ""):
        """Validate plain data (as read from a file) into a Case.

        Named line types are checked first and each problem is reported once, at
        ``line_types.NAME``, not again at every segment that uses the name.
        """
        types = data.get("line_types") if isinstance(data, dict) else None
        if not isinstance(types, dict):
            return super().parse(data, root=root)
        problems, checked = [], {}
        for name, entry in types.items():
            try:
                checked[name] = LineType.parse(entry)
            except InputError as err:
                problems += [(("line_types", name) + loc, tail) for loc, tail in err.problems]
                checked[name] = STAND_IN  # keeps segments that use it from failing again
        try:
            case = super().parse({**data, "line_types": checked}, root=root)
        except InputError as err:
            problems += err.problems
            case = None
        if problems:
            raise input_error(problems, root)
        return case

    @model_validator(mode="before")
    @classmethod
    def _resolve_line_types(cls, data: Any) -> Any:
        """Replace line-type names by the entries of ``line_types``; expand the short form."""
        if not isinstance(data, dict) or not isinstance(data.get("line"), dict):
            return data
        data = dict(data)
        types = data.get("line_types") or {}
        line = dict(data["line"])
        if "segments" not in line and "line_type" in line:
            seg = {k: line.pop(k) for k in ("line_type", "length", "n_elements") if k in line}
            line["segments"] = [seg]

        def resolve(ref, where):
            if isinstance(ref, str):
                if not isinstance(types, dict) or ref not in types:
                    names = list(types) if isinstance(types, dict) else []
                    raise ValueError(f"{where}.line_type '{ref}' is not defined in line_types "
                                     f"(defined: {', '.join(names) or 'none'}).{suggest(ref, names)}")
                return types[ref]
            return ref

        segments = line.get("segments")
        if isinstance(segments, (list, tuple)):
            line["segments"] = [
                {**seg, "line_type": resolve(seg.get("line_type"), f"line.segments[{i}]")}
                if isinstance(seg, dict) else seg
                for i, seg in enumerate(segments)
            ]
        data["line"] = line
        return data

    @model_validator(mode="after")
    def _needs(self) -> Case:
        a = self.analysis
        # an input the analysis does not take first: a seabed profile given for an analysis that takes a depth
        # is named as the input not taken, not as a missing depth
        self._unused_inputs()
        if isinstance(a, (StaticAnalysis, PushoverAnalysis, ModalAnalysis, LayingTheoryAnalysis, _Mooring)):
            if self.environment.depth is None and (a.type == "laying_theory" or (
                    a.anchor is None and not getattr(a, "free_end", False)
                    and not (isinstance(a, _Mooring) and self.environment.seabed.tabulated))):
                raise ValueError(f"analysis '{a.type}' needs environment.depth (m). "
                                 "Suggested fix: add 'depth:' under 'environment'.")
        if isinstance(a, (LayingTheoryAnalysis, VerticalModesAnalysis)):
            if len(self.line.segments) != 1 or self.line.attachments:
                raise ValueError(f"analysis '{a.type}' takes a homogeneous line of one segment and no "
                                 f"attachments, got {len(self.line.segments)} segments and "
                                 f"{len(self.line.attachments)} attachments.")
        if isinstance(a, LayingDynamicAnalysis):
            if a.bathymetry is None and a.bathymetry_grid is None and self.environment.depth is None:
                raise ValueError("analysis 'laying_dynamic' needs environment.depth (m) or a bathymetry "
                                 "table. Suggested fix: add 'depth:' under 'environment'.")
            if a.route is not None and self.environment.seabed.slope != 0.0:
                raise ValueError(f"environment.seabed.slope {self.environment.seabed.slope:g} rad: along a route the "
                                 "seabed is the bathymetry (by KP or a grid). Suggested fix: give the depths in "
                                 "analysis.bathymetry, and leave slope out.")
            if a.extensible and any(seg.line_type.axial_stiffness is None for seg in self.line.segments):
                raise ValueError("'extensible: true' needs an axial_stiffness (N) on every line type.")
        if isinstance(a, LayPlanAnalysis) and a.bathymetry is None and a.bathymetry_grid is None \
                and self.environment.depth is None:
            raise ValueError("analysis 'lay_plan' needs the depth: a 'bathymetry' table along the route (KP, depth), "
                             "a 'bathymetry_grid', or environment.depth (m) for a flat seabed.")
        if isinstance(a, _Mooring):
            missing = [i for i, seg in enumerate(self.line.segments) if seg.line_type.axial_stiffness is None]
            if missing:
                raise ValueError(f"analysis '{a.type}' needs an axial_stiffness (EA, N) on every line type; "
                                 f"line.segments {missing} have none. Suggested fix: add 'axial_stiffness'.")
        if self.line.sections:
            if not isinstance(a, _Mooring):
                raise ValueError(f"analysis '{a.type}' does not take line.sections (buoyancy sections, bend "
                                 "stiffeners): the finite-element line of 'mooring_static', 'mooring_pushover' and "
                                 "'mooring_dynamic' does. Suggested fix: use one of those, or give the buoyancy as "
                                 "segments and attachments.")
            # a line the modules would float is refused here, before anything runs (the same check the model makes)
            resolve_sections(self.line, self.environment.water_density, self.environment.gravity)
            tie_points(self.line, self.environment)  # a tie's point below the seabed, or on a seabed not given
        if isinstance(a, TowlineDynamicAnalysis):
            if self.environment.depth is not None and self.environment.seabed.slope != 0.0:
                raise ValueError(f"analysis 'towline_dynamic' takes a level seabed, got seabed.slope "
                                 f"{self.environment.seabed.slope:g} rad. Suggested fix: leave the slope out.")
            lt = self.line.segments[0].line_type
            if len(self.line.segments) != 1 or self.line.attachments:
                raise ValueError("analysis 'towline_dynamic' takes a towline of one segment and no attachments, "
                                 f"got {len(self.line.segments)} segments and {len(self.line.attachments)} "
                                 "attachments.")
            if lt.axial_stiffness is None and (a.elongation_at_break is None or lt.breaking_load is None):
                raise ValueError("analysis 'towline_dynamic' needs the line's stiffness: an axial_stiffness (N) on "
                                 "the line type, or its breaking_load (N) with the analysis's elongation_at_break "
                                 "(paper 003: 16 t = 156906 N and 0.15).")
        return self

    def _unused_inputs(self) -> None:
        """Refuse environment inputs the analysis does not use (:func:`check_unused_inputs`)."""
        check_unused_inputs(self.analysis, self.environment, ANALYSES)

    def anchor_position(self) -> tuple[float, float]:
        """Anchor (x, z): the analysis's, or on the seabed under the origin. [m]"""
        a = self.analysis
        if getattr(a, "anchor", None) is not None:
            return a.anchor
        profile = self.environment.seabed.profile
        if profile is not None:  # on the profile's seabed under the origin
            return (0.0, -float(np.interp(0.0, profile.distance, profile.depth)))
        if self.environment.seabed.grid is not None:  # on the grid's seabed under the origin
            return (0.0, seabed_elevation(self.environment.seabed, 0.0, 0.0, "anchor (its default: the origin)"))
        return (0.0, -float(self.environment.depth))


def check_unused_inputs(analysis, environment: Environment, analyses) -> None:
    """Refuse environment inputs ``analysis`` does not use: its ``uses(environment)`` (or ``USES``) against
    :func:`given_environment_inputs`; one check for every analysis and input, not one per key.

    ``analyses`` are the analysis classes a case of this kind may choose, to name those that use the inputs.
    Raises ValueError (a model validator's error).
    """
    a = analysis
    uses = a.uses(environment) if hasattr(a, "uses") else a.USES
    unused = [k for k in given_environment_inputs(environment) if k not in uses]
    if not unused:
        return
    takers = sorted({cls.model_fields["type"].default for cls in analyses if all(k in cls.USES for k in unused)})
    it = "it" if len(unused) == 1 else "them"
    where = f"analyses that use {it}: {', '.join(takers)}" if takers else \
        f"no analysis of this kind of case uses {it}{'' if len(unused) == 1 else ' all'}"
    extra = ""
    if "seabed.profile" in unused and a.type == "laying_dynamic":
        extra = " (a laying_dynamic case takes its seabed as analysis.bathymetry)"
    if "seabed.profile" in unused and a.type == "towed_dynamic":
        extra = " (the profile is taken by towed_dynamic's finite_element formulation only)"
    if "depth" in unused and environment.seabed.tabulated:
        extra = " (environment.seabed's profile or grid gives the seabed; the depth sets only the waves' dispersion)"
    keys = ", ".join(f"environment.{k}" for k in unused)
    raise ValueError(f"{keys} {'is' if len(unused) == 1 else 'are'} given, but analysis '{a.type}' does not use "
                     f"{'it' if len(unused) == 1 else 'them'}{extra}: the result would not hold "
                     f"{'its' if len(unused) == 1 else 'their'} effect. It uses "
                     f"{', '.join(f'environment.{k}' for k in sorted(uses)) or 'none of them'} ({where}). "
                     f"Suggested fix: remove {keys}, or choose an analysis that models "
                     f"{'it' if len(unused) == 1 else 'them'}.")

"""The records of a MoorDyn deck: line and rod types, points, bodies, rods, lines, failures, external loads
and the file as a whole (:class:`MoorDynInput`, with its options); MoorDyn's axial damping rule."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from ... import _validate
from ...errors import InputError


@dataclass(frozen=True)
class MoorDynLineType:
    """One row of a MoorDyn LINE TYPES section, in SI units as written in the file.

    ``axial_damping`` is the BA column as written: ``>= 0`` an internal damping coefficient
    [N s]; ``< 0`` means ``-zeta``, a damping ratio of the segment's axial mode (see
    :func:`moordyn_axial_damping`). ``bending_stiffness`` is 0 for v1 files.
    """

    name: str
    diameter: float  # volume-equivalent diameter [m]
    mass_per_length: float  # in air [kg/m]
    axial_stiffness: float  # EA [N]
    axial_damping: float  # BA [N s], or -zeta [-] when negative
    bending_stiffness: float  # EI [N m^2]
    drag_normal: float  # Cd [-]
    added_mass_normal: float  # Ca [-]
    drag_tangential: float  # CdAx [-]
    added_mass_tangential: float  # CaAx [-]
    tension_strain: tuple[tuple[float, float], ...] | None = None  # nonlinear EA: (strain [-], tension [N])
    dynamic_stiffness: tuple[float, ...] | None = None  # viscoelastic: (EA_d,) or (EA_Dc, EA_D_Lm) [N, -]
    dynamic_damping: float | None = None  # viscoelastic: BA_d [N s]
    table_file: str | None = None  # the file the nonlinear EA table was read from
    syrope: tuple[str, float, float] | None = None  # Syrope working curve (WCType, k1, k2); tension_strain is the OWC


@dataclass(frozen=True)
class MoorDynPoint:
    """One row of a MoorDyn POINTS section.

    ``attachment`` is ``'fixed'``, ``'vessel'``, ``'free'``, ``'body'`` (``BodyN``: ``position`` is
    then relative to body N's reference point, in body axes; ``body`` is N) or ``'turbine'``
    (``TurbineN`` of FAST.Farm: ``position`` relative to turbine N's platform reference point;
    ``turbine`` is N).
    """

    id: int
    attachment: str
    position: tuple[float, float, float]  # x, y, z (z up, 0 at the mean surface) [m]
    mass: float  # point mass, e.g. a clump weight [kg]
    volume: float  # displaced volume, e.g. a buoy [m^3]
    drag_area: float  # CdA [m^2]
    added_mass_coefficient: float  # Ca [-]
    body: int | None = None  # N of a 'BodyN' point
    turbine: int | None = None  # N of a 'TurbineN' point


@dataclass(frozen=True)
class MoorDynRodType:
    """One row of a MoorDyn ROD TYPES section (SI units)."""

    name: str
    diameter: float  # [m]
    mass_per_length: float  # [kg/m]
    drag_normal: float  # Cd [-]
    added_mass_normal: float  # Ca [-]
    drag_end: float  # CdEnd [-]
    added_mass_end: float  # CaEnd [-]


@dataclass(frozen=True)
class MoorDynBody:
    """One row of a MoorDyn BODIES section (SI units; angles in radians).

    ``attachment`` is ``'free'``, ``'fixed'``, ``'coupled'`` (MoorDyn's Coupled/Vessel: moved by the
    coupled code) or ``'turbine'`` (FAST.Farm's TurbineN, ``turbine`` is N). ``pinned`` is True for
    ``CoupledPinned`` (the reference point follows the vessel, the rotations are free).
    ``drag_area`` is expanded to six values (MoorDyn: 1 for all, 2 translation|rotation, 3 per axis
    for both, or 6); ``added_mass_coefficient`` to three.
    """

    id: int
    attachment: str
    position: tuple[float, float, float, float, float, float]  # x, y, z [m], roll, pitch, yaw [rad]
    mass: float  # [kg]
    center_of_gravity: tuple[float, float, float]  # body axes [m]
    inertia: tuple[float, float, float]  # Ixx, Iyy, Izz [kg m^2]
    volume: float  # [m^3]
    drag_area: tuple[float, float, float, float, float, float]  # CdA [m^2] (rotational: [m^5])
    added_mass_coefficient: tuple[float, float, float]  # Ca [-]
    pinned: bool = False
    turbine: int | None = None


@dataclass(frozen=True)
class MoorDynRod:
    """One row of a MoorDyn RODS section.

    ``attachment`` is ``'fixed'``, ``'free'``, ``'coupled'``, ``'turbine'`` or ``'body'``; ``pinned``
    marks MoorDyn's ``Pinned``, ``CoupledPinned`` and ``BodyNPinned`` (end A held, rotation free).
    ``end_a``/``end_b`` are global, or relative to body N (``body``) in body axes.
    """

    id: int
    rod_type: str
    attachment: str
    end_a: tuple[float, float, float]  # [m]
    end_b: tuple[float, float, float]  # [m]
    n_segments: int
    outputs: str
    pinned: bool = False
    body: int | None = None
    turbine: int | None = None

    @property
    def length(self) -> float:
        """Distance between the two ends. [m]"""
        return math.dist(self.end_a, self.end_b)


@dataclass(frozen=True)
class MoorDynFailure:
    """One row of a MoorDyn FAILURE section: the named lines detach from ``attachment`` (a point
    ID, or a rod end ``(rod ID, 'A' or 'B')``) at ``time`` or when the tension reaches ``tension``,
    whichever comes first (a 0 disables that trigger, as in MoorDyn-F)."""

    id: int
    attachment: int | tuple[int, str]
    lines: tuple[int, ...]
    time: float  # [s], 0 = no time trigger
    tension: float  # [N], 0 = no tension trigger


@dataclass(frozen=True)
class MoorDynExternalLoad:
    """One row of a MoorDyn-F EXTERNAL LOADS section: a constant force and translational linear and
    quadratic damping on a body, point or rod (``kind`` ``'body'``, ``'point'`` or ``'rod'``, ``target``
    its ID). ``frame`` is ``'G'`` (global axes) or ``'L'`` (body axes, bodies only); rods take two damping
    values (transverse, axial)."""

    id: int
    kind: str
    target: int
    force: tuple[float, float, float]  # [N]
    linear_damping: tuple[float, ...]  # [N s/m]
    quadratic_damping: tuple[float, ...]  # [N s^2/m^2]
    frame: str = "G"


@dataclass(frozen=True)
class MoorDynLine:
    """One row of a MoorDyn LINES section; ``length`` is the resolved unstretched length [m]."""

    id: int
    line_type: str
    point_a: int
    point_b: int
    length: float  # unstretched [m]
    n_segments: int
    outputs: str  # MoorDyn's output flags, e.g. 'pt' or '-'
    rod_a: tuple[int, str] | None = None  # end A on a rod end (rod ID, 'A' or 'B'); point_a is then None
    rod_b: tuple[int, str] | None = None  # end B on a rod end (rod ID, 'A' or 'B'); point_b is then None
    # CableDyn's SECTIONS: (line type, length [m], elements) from end A to end B; line_type is then the first's,
    # length and n_segments their sums; () for a MoorDyn line of one type
    sections: tuple[tuple[str, float, int], ...] = ()
    # CableDyn's ATTACHMENTS: (s [m] from end A, mass [kg], volume [m^3], CdA [m^2], Ca [-], CdAx [m^2])
    attachments: tuple[tuple[float, float, float, float, float, float], ...] = ()


_DEPTH = ("WtrDpth", "depth", "WaterDepth")
_RHO = ("WtrDnsty", "rho", "rhoW")
_G = ("g", "gravity")
_KBOT = ("kBot", "kb")
_CBOT = ("cBot", "cb")
_DT = ("dtM", "DT")
_CFL = ("cfl",)
_MU = ("FrictionCoefficient",)
_MU_T, _MU_A = ("mu_kT",), ("mu_kA",)
_FRIC_DAMP = ("FricDamp", "CV")
_FRIC_SCALE = ("StatDynFricScale", "MC")


def _lookup(options: dict, keys):
    """The value of the first of ``keys`` present in ``options`` (names compared case-insensitively, as
    MoorDyn-F does; the last of several spellings in the file wins, as in MoorDyn), else None."""
    wanted = {k.lower() for k in keys}
    found = None
    for name, value in options.items():
        if name.lower() in wanted:
            found = value
    return found


def _option(name, keys, default, doc):
    """A read-only property: the option ``keys`` (any spelling, any case), else ``default``."""

    def get(self):
        value = _lookup(self.options, keys)
        return default if value is None else value

    get.__name__, get.__doc__ = name, doc
    return property(get)


@dataclass(frozen=True)
class MoorDynInput:
    """What :func:`read_moordyn` returns: the file's line types, points, lines, options and outputs.

    ``notes`` are the messages about what the file asks for that seacable's mooring model does not
    do (an option it cannot honour, an unknown option, VIV lift on a line type): each names the
    option, its value and what seacable does instead. The model that runs the file warns with them
    (:func:`seacable.mooring.moordyn.prepare_moordyn`).
    """

    path: str | None
    title: str
    line_types: dict[str, MoorDynLineType]
    points: tuple[MoorDynPoint, ...]
    lines: tuple[MoorDynLine, ...]
    options: dict[str, float | str]
    outputs: tuple[str, ...]
    notes: tuple[str, ...] = ()
    rod_types: dict[str, MoorDynRodType] = dataclasses.field(default_factory=dict)
    bodies: tuple[MoorDynBody, ...] = ()
    rods: tuple[MoorDynRod, ...] = ()
    failures: tuple[MoorDynFailure, ...] = ()
    layout: str = "v2"
    external_loads: tuple[MoorDynExternalLoad, ...] = ()
    # CableDyn's END CONNECTIONS of the ends held in bending: {(line ID, end 0 A / 1 B): (kind, stiffness, direction)}
    # (:func:`seacable.io.moordyn._cabledyn.read_end_connections`)
    end_connections: dict = dataclasses.field(default_factory=dict)
    syrope_ic: dict[int, tuple[float, float]] = dataclasses.field(default_factory=dict)  # line: (Tmax0, Tmean0) [N]  # 'v2', or 'v1' (a file with NTypes/NConnects/NLines count lines or v1 columns)

    water_density = _option("water_density", _RHO, 1025.0, "``WtrDnsty``/``rho``/``rhoW``, default 1025. [kg/m^3]")
    gravity = _option("gravity", _G, 9.80665, "Gravity ``g``, default 9.80665 (MoorDyn v2.0.0). [m/s^2]")
    kbot = _option("kbot", _KBOT, 3.0e6, "Seabed stiffness per contact area ``kBot``, default 3e6. [Pa/m]")
    cbot = _option("cbot", _CBOT, 3.0e5, "Seabed damping per contact area ``cBot``, default 3e5. [Pa s/m]")
    friction_damping = _option("friction_damping", _FRIC_DAMP, 200.0,
                               "``FricDamp`` (MoorDyn-F ``CV``), default 200. [N s/m]")
    static_dynamic_friction_scale = _option("static_dynamic_friction_scale", _FRIC_SCALE, 1.0,
                                            "``StatDynFricScale`` (MoorDyn-F ``MC``), default 1. [-]")
    time_step = _option("time_step", _DT, None, "Mooring time step ``dtM`` (or ``DT``), None if absent. [s]")
    cfl = _option("cfl", _CFL, None, "CFL factor ``cfl``, None if absent. [-]")

    @property
    def given_water_depth(self) -> float | None:
        """The ``WtrDpth`` option as written (``depth``/``WaterDepth`` too), None if absent. [m]"""
        return _lookup(self.options, _DEPTH)

    @property
    def water_depth(self) -> float | None:
        """Water depth: ``WtrDpth``, or, without it, the depth of the deepest point. [m]

        MoorDyn-C reads the depth as ``WtrDpth`` (default 0) and, point by point, deepens it to
        the lowest point (``ReadInFile`` in ``source/MoorDyn2.cpp``: "make default water depth at
        least the depth of the lowest node (so water depth input is optional)"), so a deck
        without ``WtrDpth`` has its seabed at its deepest anchor. None when no point is below
        the surface (no seabed). A point below a given ``WtrDpth`` is refused by the reader.
        """
        given = self.given_water_depth
        if given is not None:
            return given
        globals_ = [p.position[2] for p in self.points if p.attachment in ("fixed", "free", "vessel")]
        globals_ += [z for r in self.rods if r.attachment in ("fixed", "free", "coupled")
                     for z in (r.end_a[2], r.end_b[2])]
        if not globals_:
            return None
        deepest = -min(globals_)
        return deepest if deepest > 0 else None

    @property
    def friction(self) -> float:
        """Seabed friction coefficient: ``FrictionCoefficient`` (MoorDyn-C), else MoorDyn-F's
        ``mu_kT``/``mu_kA`` (their mean when they differ; see ``notes``), else 0. [-]"""
        mu = _lookup(self.options, _MU)
        if mu is not None:
            return mu
        mu_t, mu_a = _lookup(self.options, _MU_T), _lookup(self.options, _MU_A)
        if mu_t is None and mu_a is None:
            return 0.0
        return ((mu_t or 0.0) + (mu_a or 0.0)) / 2  # MoorDyn-F's default for either is 0

    def point(self, point_id: int) -> MoorDynPoint:
        """Return the point with ID ``point_id``."""
        for p in self.points:
            if p.id == point_id:
                return p
        raise InputError(f"no point with ID {point_id}; the IDs are {[p.id for p in self.points]}."
                         " Suggested fix: use one of those IDs.")


def moordyn_axial_damping(axial_damping, axial_stiffness, mass_per_length, segment_length):
    """Internal axial damping coefficient BA that MoorDyn uses for one segment.

    ``BA`` as written when ``axial_damping >= 0``; else ``-axial_damping * l * sqrt(EA m)``,
    i.e. ``-axial_damping`` is the damping ratio of the highest axial mode of the
    lumped-mass line. The segment's damping force is ``BA`` times its strain rate.

    Parameters
    ----------
    axial_damping
        The BA/-zeta column of the line type. [N s] or [-]
    axial_stiffness
        Axial stiffness EA. [N]
    mass_per_length
        Mass per unit length in air. [kg/m]
    segment_length
        Unstretched segment length ``L / N``. [m]

    Returns
    -------
    float or numpy.ndarray
        Damping coefficient BA. [N s]

    References
    ----------
    .. [1] MoorDyn-C ``source/Line.cpp``, ``Line::initialize``:
       ``c = -BAin * UnstrLen / N * sqrt(E * rho)`` with ``E = EA/A``, ``rho = m/A``.
    """
    ba = _validate.finite("axial_damping", axial_damping, "N s")
    ea = _validate.positive("axial_stiffness", axial_stiffness, "N")
    m = _validate.positive("mass_per_length", mass_per_length, "kg/m")
    ls = _validate.positive("segment_length", segment_length, "m")
    out = np.where(np.asarray(ba) < 0, -np.asarray(ba) * ls * np.sqrt(ea * m), ba)
    return float(out) if out.ndim == 0 else out

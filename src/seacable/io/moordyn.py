"""Read MoorDyn input files (v2, v1 and MoorDyn-F layouts) into plain records, and turn them into a system.

seacable reads every section of a MoorDyn deck: line types (constant, viscoelastic ``EA_s|EA_d``,
nonlinear strain-tension tables, Syrope ropes; bending stiffness EI kept), rod types, bodies, rods,
points (fixed, free, coupled, on a body, on a FAST.Farm turbine), lines (ends at points or rod ends),
failures, MoorDyn-F external loads, options and outputs. :func:`moordyn_system` turns the deck into a
:class:`~seacable.system.model.MooringSystem` and its environment for the system analyses; decks with
lines and points only also run as a line network (:mod:`seacable.mooring.moordyn`). What cannot be
read (MoorDyn-F's CONTROL section, a malformed row) is refused with an :class:`~seacable.errors.InputError`
naming the file and line, so that a file is never half read in silence.

File format (as MoorDyn-C reads it: ``MoorDyn::ReadInFile``, ``findStartOfSection``,
``readLineProps`` and ``readOptionsLine`` in ``source/MoorDyn2.cpp`` of FloatingArrayDesign/MoorDyn,
v2.0.0; v1 layout from ``docs/inputs.rst`` of the same repository):

- A section header is any line containing ``---``; its kind is found from a keyword in the
  upper-cased line: ``LINE DICTIONARY``/``LINE TYPES``; ``ROD DICTIONARY``/``ROD TYPES``;
  ``BODIES``/``BODY LIST``/``BODY PROPERTIES``; ``POINTS``/``POINT LIST``/``POINT PROPERTIES``/
  ``CONNECTION PROPERTIES``/``NODE PROPERTIES``; ``RODS``/``ROD LIST``/``ROD PROPERTIES``;
  ``LINES``/``LINE LIST``/``LINE PROPERTIES``; ``FAILURE``; ``OPTIONS``; ``OUTPUT``.
  Lines before the first section are free text (the title).
- A table section has two lines after its header, column names and units, which MoorDyn
  skips unread; the rows follow until the next header. ``OPTIONS`` and ``OUTPUTS`` have none.
- ``!``, ``#`` and ``%`` start a comment that runs to the end of the line, in every line after the
  title (``docs/inputs.rst`` of MoorDyn v2; MoorDyn-C 2.7.2 reads a commented row as the row before
  the comment, which matters for the 9- or 12-column POINTS layout).
- Options are ``value name [comment]``; the name is matched in any case (MoorDyn-F upper-cases it,
  MoorDyn-C's own examples write ``kbot``). Outputs are channel names, several per line allowed.
- The file ends at a header containing ``need this line`` or ``END``, or a line ``END``.
- LINE TYPES, v2 (10 columns): ``name d m EA BA/-zeta EI Cd Ca CdAx CaAx``; v1 (9 columns):
  ``name d m EA BA/-zeta Can Cat Cdn Cdt`` (no EI; coefficients in another order). The layout
  is taken from the column-names line (``EI`` present -> v2). EA may be ``EA_s|EA_d`` or
  ``EA_s|EA_Dc|EA_D_Lm`` (viscoelastic, with BA ``BA_s|BA_d``), a file of ``strain tension`` rows
  (read; lines that do not start with two numbers are skipped), or ``SYROPE:file|EA_Dc|EA_D_Lm``
  (a Syrope settings file naming its original working curve). A BA or EI table is refused.
- v1 count lines (``3 NLines - number of line objects``) opening a section are read and checked
  against the rows.
- ROD TYPES: ``name d m/l Cd Ca CdEnd CaEnd``. RODS: ``ID type attachment Xa Ya Za Xb Yb Zb NumSegs
  outputs``, attachment Fixed, Pinned, Free, Coupled/Vessel, CoupledPinned, BodyN, BodyNPinned,
  TurbineN. BODIES: ``ID attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca`` (CG, I, CdA, Ca one
  value or several separated by '|'), or the early MoorDyn-F layout ``1coupled X0 .. y0 Xcg Ycg Zcg
  M V IX IY IZ CdA Ca``. FAILURE: ``[ID] point-or-rod-end lines time tension``. EXTERNAL LOADS:
  ``ID object Fext Blin Bquad [CSys]``. SYROPE IC: ``lines Tmax0 Tmean0``.
- POINTS: ``ID type X Y Z mass volume CdA Ca``, or 12 columns with ``FX FY FZ`` before ``CdA``.
  Types: ``Fixed``/``Fix``/``Anchor`` -> ``'fixed'``; ``Vessel``/``Ves``/``Coupled``/``Cpld``/
  ``Fairlead`` -> ``'vessel'``; ``Free``/``Point``/``Connect``/``Con`` -> ``'free'``; ``BodyN`` ->
  ``'body'``; ``TurbineN`` -> ``'turbine'``.
- LINES, v2: ``ID type AttachA AttachB UnstrLen NumSegs outputs``; v1 (``LINE PROPERTIES``
  with ``UnstrLen`` in the 3rd column): ``ID type UnstrLen NumSegs NodeAnch NodeFair flags``.
  An attachment is a point number, optionally prefixed ``C``, ``Con``, ``P`` or ``Point``, or a
  rod end ``R1A``/``R1B``. MoorDyn looks the number up by *position* in the point list (it never
  reads the ID column), and so does seacable, with a warning when the IDs are not 1..N in order. A negative ``UnstrLen`` is, as in
  MoorDyn's ``Line::initialize``, a factor on the distance between the two end points.

Physics MoorDyn attaches to these inputs (``source/Line.cpp``, ``Line::initialize`` and
``Line::getStateDeriv``, FloatingArrayDesign/MoorDyn; defaults from the ``MoorDyn`` constructor
in ``source/MoorDyn2.cpp``), for models that convert a MoorDyn file:

- Internal damping: a segment of unstretched length ``l`` carries the axial damping force
  ``BA * (dl_str/dt) / l`` along the segment, whatever its strain (a slack segment, which carries
  no elastic tension, is still damped; MoorDyn's ``Line.cpp``). ``BA >= 0`` is used as written [N s]; ``BA < 0``
  means ``zeta = -BA`` and MoorDyn sets ``BA = zeta * l * sqrt(EA * m)`` with ``l = L / N``
  (``c = -BAin * UnstrLen / N * sqrt(E * rho)`` per unit area). ``zeta`` is the damping ratio of
  the highest axial mode of the lumped-mass line (adjacent nodes out of phase):
  ``k = 4 EA / l``, ``M = m l``, ``c = 4 BA / l`` give ``c / (2 sqrt(k M)) = BA / (l sqrt(EA m))``.
  See :func:`moordyn_axial_damping`.
- Seabed, per node ``i`` below the seabed ``z_b`` (vertical only):
  ``B_z = ((z_b - z_i) * kBot - dz_i/dt * cBot) * d * l_i`` with ``l_i`` half the sum of the
  adjacent unstretched segment lengths (half one segment at an end node).
  Defaults ``kBot = 3.0e6 Pa/m``, ``cBot = 3.0e5 Pa s/m``.
- Seabed friction (same nodes): ``F_max = mu * |B_z|``; ``F = mu * FricDamp * |v_h|`` with
  ``v_h`` the node's horizontal velocity; if ``F > StatDynFricScale * F_max`` then ``F = F_max``;
  applied opposite to ``v_h`` (zero when ``v_h = 0``). Defaults ``FrictionCoefficient mu = 0``,
  ``FricDamp = 200``, ``StatDynFricScale = 1.0``.
- Other defaults: ``g = 9.80665 m/s^2`` (MoorDyn v2.0.0; the 2021-22 alphas used 9.8),
  ``rho_w = 1025 kg/m^3``, ``dtM = 0.001 s``. Water depth: MoorDyn-C deepens ``WtrDpth`` (default
  0) to the deepest point as it reads the POINTS, so a deck without ``WtrDpth`` has its seabed at
  its deepest anchor (:attr:`MoorDynInput.water_depth`). A point below a *given* ``WtrDpth`` is
  refused here (MoorDyn moves the seabed down to it with a warning): a contradiction in the file.

Options, and what seacable does with each (``MoorDynInput.notes`` carries a message for every
option it cannot honour; :func:`seacable.mooring.moordyn.prepare_moordyn` warns with them):

- honoured: ``WtrDpth``/``depth``/``WaterDepth``, ``WtrDnsty``/``rho``/``rhoW``, ``g``/``gravity``,
  ``kBot``/``kb``, ``cBot``/``cb``, ``FrictionCoefficient``, MoorDyn-F's ``mu_kT``/``mu_kA`` when
  equal, ``StatDynFricScale``/``MC`` equal to 1, and ``WaveKin``/``Currents`` equal to 0;
- no counterpart needed, no warning: MoorDyn's own numerics and output (``dtM``, ``DT``, ``cfl``,
  ``tScheme``, ``dtIC``, ``TmaxIC``, ``CdScaleIC``, ``threshIC``, ``ICgenDynamic``, ``fileIC``,
  ``inertialF``, ``inertialF_rampT``, ``writeLog``, ``WriteUnits``, ``dtOut``, ``disableOutput``,
  ``disableOutTime``, ``OutSwitch``, ``Echo``; ``dtWave``, ``waveKin_rampT``, ``UnifyCurrentGrid``
  without waves): seacable solves the static equilibrium by Newton's method and integrates with an
  implicit Newmark scheme at the step the user gives;
- warned: ``WaveKin``/``Currents`` other than 0 and ``WaterKin`` (still water instead),
  ``SeafloorFile`` (flat seabed instead), ``mu_kT`` and ``mu_kA`` that differ (their mean),
  ``FricDamp``/``CV`` and ``StatDynFricScale``/``MC`` other than 1 with friction (Coulomb friction
  regularised over 0.01 m/s instead), a line type's VIV lift ``Cl`` other than 0, and any option
  name seacable does not know (ignored, with a did-you-mean).

References
----------
.. [1] M. Hall and A. Goupee, "Validation of a lumped-mass mooring line model with DeepCwind
   semisubmersible model test data", Ocean Engineering 104, 590-603, 2015.
.. [2] MoorDyn-C source, https://github.com/FloatingArrayDesign/MoorDyn (BSD-3), files
   ``source/MoorDyn2.cpp`` and ``source/Line.cpp``; documentation ``docs/inputs.rst``.
"""

from __future__ import annotations

import dataclasses
import math
import re
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from pydantic import ValidationError

from .. import _limits, _validate
from .._model import format_validation_error, suggest
from .._text import read_text_file
from ..errors import InputError, SeacableWarning

__all__ = [
    "MoorDynBody",
    "MoorDynCase",
    "MoorDynExternalLoad",
    "MoorDynFailure",
    "MoorDynInput",
    "MoorDynLine",
    "MoorDynLineType",
    "MoorDynPoint",
    "MoorDynRod",
    "MoorDynRodType",
    "check_water_kinematics",
    "is_moordyn_file",
    "load_moordyn_case",
    "moordyn_axial_damping",
    "moordyn_system",
    "read_moordyn",
]


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


# --------------------------------------------------------------------------- parsing helpers

_SECTION_KEYS = (  # order matters: 'LINE TYPES' before 'LINES', 'ROD TYPES' before 'RODS'
    ("line_types", ("LINE DICTIONARY", "LINE TYPES")),
    ("rod_types", ("ROD DICTIONARY", "ROD TYPES")),
    ("bodies", ("BODIES", "BODY LIST", "BODY PROPERTIES")),
    ("points", ("POINTS", "POINT LIST", "POINT PROPERTIES", "CONNECTION PROPERTIES", "NODE PROPERTIES")),
    ("rods", ("RODS", "ROD LIST", "ROD PROPERTIES")),
    ("lines", ("LINES", "LINE LIST", "LINE PROPERTIES")),
    ("failure", ("FAILURE",)),
    ("syrope_ic", ("SYROPE IC",)),
    ("syrope_wc", ("SYROPE WORKING CURVES",)),
    ("control", ("CONTROL",)),
    ("external_loads", ("EXTERNAL LOADS",)),
    ("options", ("OPTIONS",)),
    ("outputs", ("OUTPUT",)),
)
_UNSUPPORTED = {"control": "CONTROL"}
_COUNT = re.compile(r"^N[A-Za-z]+$")  # v1 count lines: '3 NLines - number of line objects'

_ATTACH = {"fixed": ("FIXED", "FIX", "ANCHOR"), "vessel": ("VESSEL", "VES", "COUPLED", "CPLD", "FAIRLEAD"),
           "free": ("FREE", "POINT", "CONNECT", "CON")}
_FORTRAN_EXP = re.compile(r"^([+-]?(\d+\.?\d*|\.\d+))[dD]([+-]?\d+)$")


def _as_float(token: str) -> float | None:
    """The token as a finite float, or None (accepts Fortran ``1.0d5``)."""
    m = _FORTRAN_EXP.match(token)
    if m:
        token = f"{m.group(1)}e{m.group(3)}"
    try:
        value = float(token)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


class _Reader:
    """State of one parse: the source label for messages and the lines of text."""

    def __init__(self, label: str, folder: Path | None = None):
        self.label = label
        self.folder = folder  # where files named in the deck (nonlinear tables) are looked up
        self.v1_counts = False
        self.syrope_types: dict[str, int] = {}  # Syrope line types and their line
        self.notes: list[str] = []
        self.option_lines: dict[str, int] = {}
        self.names_line: dict[int, int] = {}  # a table's header line -> the line of its column names

    def at(self, name: str) -> str:
        """``file:line: `` of the option ``name`` (any case), for the notes."""
        lineno = next((n for k, n in self.option_lines.items() if k.lower() == name.lower()), None)
        return f"{self.label}:{lineno}: " if lineno else f"{self.label}: "

    def error(self, lineno: int | None, message: str) -> InputError:
        where = f"{self.label}:{lineno}" if lineno else self.label
        return InputError(f"{where}: {message}")

    def number(self, lineno, token, what, unit, fix="write a plain number in SI units") -> float:
        value = _as_float(token)
        if value is None:
            raise self.error(lineno, f"{what} must be a finite number in {unit}, got {token!r}. "
                                     f"Suggested fix: {fix}.")
        return value

    def check(self, lineno, check, what, value, unit, fix, *args):
        """Run a ``seacable._validate`` check and prefix its message with file and line."""
        try:
            return check(what, value, *args, unit, fix)
        except InputError as exc:
            raise self.error(lineno, str(exc)) from None

    def columns(self, lineno, tokens, needed, what, layout):
        if len(tokens) < needed:
            raise self.error(lineno, f"a {what} row must have {needed} columns ({layout}), got "
                                     f"{len(tokens)}: {' '.join(tokens)!r}. Suggested fix: "
                                     "fill in every column; write 0 or - where a value does not apply.")


def _load(path_or_text, name):
    """Return (text, path or None, label)."""
    if isinstance(path_or_text, Path) or (isinstance(path_or_text, str) and "\n" not in path_or_text):
        path = Path(path_or_text)
        label = name or str(path)
        if not path.is_file():
            raise InputError(f"MoorDyn file {str(path)!r} not found. Suggested fix: check the path, "
                             "or pass the file's text (with its newlines) instead of a path.")
        text = read_text_file(path, "MoorDyn file", "pass the MoorDyn .txt input (not a binary .ic state file)")
        return text, str(path), label
    if isinstance(path_or_text, str):
        return path_or_text, None, name or "<MoorDyn text>"
    raise InputError(f"read_moordyn needs a path or the file's text, got {type(path_or_text).__name__}. "
                     "Suggested fix: pass a str or pathlib.Path.")


def _section_kind(line: str) -> str | None:
    upper = line.upper()
    for kind, keys in _SECTION_KEYS:
        if any(k in upper for k in keys):
            return kind
    return None


def _is_end(line: str) -> bool:
    stripped = line.strip().upper()
    if stripped == "END" or stripped.startswith("END "):
        return True
    return "---" in line and ("NEED THIS LINE" in stripped or re.search(r"\bEND\b", stripped) is not None)


_COMMENT = re.compile(r"[!#%]")


def _strip_comment(line: str) -> str:
    """The line without its comment: MoorDyn v2 ignores the rest of a line from a '!', '#' or '%'.

    ``docs/inputs.rst`` of MoorDyn ("!, #, and % are comment characters ... any of these characters
    will prevent MoorDyn from reading the rest of that line"); MoorDyn-C 2.7.2 reads a points row
    ``3 Free -150 0 -60 1000 0 1 0 # 1 2 3 4`` as the 9-column row before the ``#``.
    """
    match = _COMMENT.search(line)
    return line if match is None else line[:match.start()]


def _split_sections(rd: _Reader, text: str):
    """Return (title lines, echo, {kind: (header lineno, header text, [(lineno, line)])})."""
    title, sections, echo, unknown = [], {}, None, []
    current = None  # [kind, header lineno, header text, rows] of the section being filled
    for lineno, raw in enumerate(text.splitlines(), start=1):
        # the title is free text; from the first section on, '!', '#' and '%' start a comment
        line = (_strip_comment(raw) if sections or current is not None else raw).rstrip()
        if _is_end(line):
            break
        if "---" in line:
            kind = _section_kind(line)
            if kind is None:  # a header seacable does not know (or the title banner)
                current = None if not sections else ("unknown", lineno, line.strip(), [])
                if current is not None:
                    unknown.append(current)
                continue
            if kind in sections:
                raise rd.error(lineno, f"a second {kind.replace('_', ' ').upper()} section (the first "
                                       f"starts at line {sections[kind][1]}); MoorDyn reads only the "
                                       "first. Suggested fix: merge the two sections into one.")
            current = (kind, lineno, line.strip(), [])
            sections[kind] = current
            continue
        if current is None:  # free text before the first section
            tokens = line.split()
            if len(tokens) >= 2 and tokens[1] == "Echo":
                echo = tokens[0]
            elif tokens:
                title.append(line.strip())
            continue
        current[3].append((lineno, line))
    for _, lineno, header, rows in unknown:
        if any(r.strip() for _, r in rows):
            warnings.warn(f"{rd.label}:{lineno}: section {header.strip(' -')!r} is not a MoorDyn "
                          "section seacable knows; its rows are ignored.", SeacableWarning, stacklevel=3)
    return title, echo, sections


def _table(rd: _Reader, section):
    """Return (column names, [(lineno, tokens)]) of a table section, skipping names and units."""
    _, header_no, header, body = section
    count = None
    first = body[0][1].split() if body else []
    if len(first) >= 2 and _as_float(first[0]) is not None and _COUNT.match(first[1]):
        # MoorDyn v1 (MoorDyn-F before v2): a count line 'N NTypes' opens the section
        count = (body[0][0], first[1], first[0])
        body = body[1:]
        rd.v1_counts = True
    names = body[0][1].split() if body else []
    if body:
        rd.names_line[header_no] = body[0][0]
    rows = []
    for index, (lineno, line) in enumerate(body):
        tokens = line.split()
        if index < 2:
            if tokens and _as_float(tokens[0]) is not None:
                which = "column names" if index == 0 else "units"
                raise rd.error(lineno, f"the {which} line of {header.strip(' -')!r} (header at line "
                                       f"{header_no}) must be text, got the data row {line.strip()!r}; "
                                       "MoorDyn skips the two lines after a table header unread. "
                                       "Suggested fix: add the column-names and units lines.")
            continue
        if tokens:
            rows.append((lineno, tokens))
    if count is not None:
        lineno, word, token = count
        value = _as_float(token)
        if value != len(rows):
            raise rd.error(lineno, f"{word} must be the number of rows of {header.strip(' -')!r}, got {token!r} "
                                   f"but the section has {len(rows)} row(s). Suggested fix: write {len(rows)}, or "
                                   "add the missing rows (MoorDyn v1 reads exactly that many).")
    return names, rows


# MoorDyn's column order of each table section (it reads every row by position and never the column names), each
# column with the names decks write for it (compared without case, spaces and punctuation: 'BA/-zeta' is 'bazeta').
# The first name is the one the warning shows.
_COLUMNS = {
    "line_types": (("Name", "LineType", "TypeName", "Type", "ID"), ("Diam", "D", "Diameter", "d_vol"),
                   ("MassDen", "MassDenInAir", "Mass/m", "MassDensity", "Mass", "m", "w"), ("EA", "EAs"),
                   ("BA/-zeta", "BA", "BA/zeta", "c", "zeta"), ("EI",),
                   ("Cd", "Cdn", "CdN"), ("Ca", "Can", "CaN"), ("CdAx", "Cdt", "CdT", "CdA_x"), ("CaAx", "Cat", "CaT"),
                   ("Cl", "CL"), ("dF",), ("cF",)),
    # MoorDyn v1 (no EI column): the coefficients in another order
    "line_types_v1": (("Name", "LineType", "TypeName", "Type", "ID"), ("Diam", "D", "Diameter"),
                      ("MassDen", "MassDenInAir", "Mass/m", "MassDensity", "Mass", "m", "w"), ("EA",),
                      ("BA/-zeta", "BA", "BA/zeta", "c", "zeta"), ("Can", "Ca", "CaN"), ("Cat", "CaAx", "CaT"),
                      ("Cdn", "Cd", "CdN"), ("Cdt", "CdAx", "CdT")),
    "rod_types": (("TypeName", "Name", "RodType", "Type", "ID"), ("Diam", "D", "Diameter"),
                  ("Mass/m", "MassDen", "MassDenInAir", "Mass", "m"), ("Cd", "Cdn"), ("Ca", "Can"),
                  ("CdEnd", "CdE"), ("CaEnd", "CaE")),
    "points": (("ID", "Node", "Point", "Connection", "Num", "Number", "Name"),
               ("Attachment", "Type", "Attach"), ("X",), ("Y",), ("Z",), ("Mass", "M"), ("Volume", "V", "Vol"),
               ("CdA",), ("Ca", "CA")),
    "points_forces": (("ID", "Node", "Point", "Connection", "Num", "Number", "Name"),
                      ("Attachment", "Type", "Attach"), ("X",), ("Y",), ("Z",), ("Mass", "M"),
                      ("Volume", "V", "Vol"), ("FX",), ("FY",), ("FZ",), ("CdA",), ("Ca", "CA")),
    "lines": (("ID", "Line", "Name", "Num", "Number"), ("LineType", "Type", "TypeName"),
              ("AttachA", "NodeA", "EndA", "NodeAnch", "Anchor", "ConnectionA", "PointA"),
              ("AttachB", "NodeB", "EndB", "NodeFair", "Fairlead", "ConnectionB", "PointB"),
              ("UnstrLen", "UnstrLength", "Length", "L"), ("NumSegs", "NSegs", "Segments", "N"),
              ("Outputs", "LineOutputs", "Flags/Outputs", "Flags", "Output")),
    "lines_v1": (("ID", "Line", "Name", "Num", "Number"), ("LineType", "Type", "TypeName"),
                 ("UnstrLen", "UnstrLength", "Length", "L"), ("NumSegs", "NSegs", "Segments", "N"),
                 ("NodeAnch", "AttachA", "NodeA", "EndA", "Anchor"), ("NodeFair", "AttachB", "NodeB", "EndB", "Fairlead"),
                 ("Flags/Outputs", "Flags", "Outputs", "LineOutputs", "Output")),
    "bodies": (("ID", "BodyID", "Body", "Name"), ("Attachment", "Type", "Attach"), ("X0", "X"), ("Y0", "Y"),
               ("Z0", "Z"), ("r0", "Roll", "Roll0"), ("p0", "Pitch", "Pitch0"), ("y0", "Yaw", "Yaw0"),
               ("Mass", "M"), ("CG", "CG*", "CoG", "Xcg"), ("I", "I*", "Inertia"), ("Volume", "V", "Vol"),
               ("CdA", "CdA*"), ("Ca", "Ca*", "CA")),
    # the early MoorDyn-F v2 layout (ID and attachment in one column), rewritten into today's by _read_bodies
    "bodies_v2alpha": (("BodyID", "ID", "Body"), ("X0", "X"), ("Y0", "Y"), ("Z0", "Z"), ("r0", "Roll"),
                       ("p0", "Pitch"), ("y0", "Yaw"), ("Xcg",), ("Ycg",), ("Zcg",), ("M", "Mass"),
                       ("V", "Volume", "Vol"), ("IX",), ("IY",), ("IZ",), ("CdA",), ("Ca", "CA")),
    "rods": (("ID", "Rod", "Name", "Num", "Number"), ("RodType", "Type", "TypeName"), ("Attachment", "Attach"),
             ("Xa",), ("Ya",), ("Za",), ("Xb",), ("Yb",), ("Zb",), ("NumSegs", "NSegs", "Segments", "N"),
             ("RodOutputs", "Outputs", "Flags", "Output")),
    "failure": (("FailureID", "ID"), ("Point", "Attachment", "Attach", "Object", "Node"),
                ("Line(s)", "Lines", "Line", "LineIDs"), ("FailTime", "Time", "T"), ("FailTen", "Tension", "Ten")),
    "external_loads": (("ID",), ("Object", "Obj"), ("Fext", "Force", "F"), ("Blin",), ("Bquad",),
                       ("CSys", "Frame")),
    "syrope_ic": (("Line", "Lines", "Line(s)", "ID", "LineIDs"), ("Tmax0", "Tmax"), ("Tmean0", "Tmean")),
    "syrope_wc": (("LineType", "Name", "Type", "TypeName"), ("WCType", "Type"), ("k1",), ("k2",)),
}
_COLUMNS["failure_no_id"] = _COLUMNS["failure"][1:]  # the ID column is optional
_SECTION_TITLES = {"line_types": "LINE TYPES", "rod_types": "ROD TYPES", "points": "POINTS", "lines": "LINES",
                   "bodies": "BODIES", "rods": "RODS", "failure": "FAILURE", "external_loads": "EXTERNAL LOADS",
                   "syrope_ic": "SYROPE IC", "syrope_wc": "SYROPE WORKING CURVES"}


def _key(name: str) -> str:
    return re.sub(r"[^a-z0-9]", "", name.lower())


def _check_column_order(rd: _Reader, section, names, layout: str) -> None:
    """Warn when a table's column names put a column MoorDyn reads elsewhere (it reads rows by position only).

    ``layout`` is a key of ``_COLUMNS``: MoorDyn's order of the section, as seacable reads it. A name that is one
    of MoorDyn's columns but stands at another column's place (``Can Cat Cdn Cdt`` written over the v2 line
    types' ``Cd Ca CdAx CaAx``; a column name missing or added, shifting the rest) is reported; names seacable does
    not know (``tbd``, units) are not. The rows are still read by position, as MoorDyn reads them.
    """
    if len(section[3]) <= 2:   # the names and units lines, no row: an empty section reads nothing by them
        return
    columns = _COLUMNS[layout]
    keys = [{_key(a) for a in aliases} for aliases in columns]
    wrong = []
    for index, name in enumerate(names):
        key = _key(name)
        if not key or (index < len(keys) and key in keys[index]):
            continue
        meant = next((j for j, ks in enumerate(keys) if key in ks), None)
        if meant is not None and meant != index:
            at = f"reads it as {columns[index][0]}" if index < len(columns) else "has no column there"
            wrong.append(f"column {index + 1} is named {name!r} (MoorDyn's {columns[meant][0]}, its column {meant + 1}) "
                         f"but MoorDyn {at}")
    if not wrong:
        return
    kind, header_no = section[0], section[1]
    title = _SECTION_TITLES.get(kind, kind.upper())
    lineno = rd.names_line.get(header_no, header_no)
    warnings.warn(f"{rd.label}:{lineno}: the {title} column names ({' '.join(names)}) are not in the order MoorDyn "
                  f"reads the section ({' '.join(c[0] for c in columns)}): {'; '.join(wrong)}. MoorDyn reads the rows "
                  "by position and never the names, and so does seacable. Suggested fix: check that each row's values "
                  "are in MoorDyn's order, and write the column names in that order.", SeacableWarning, stacklevel=4)


def _coefficient(rd, lineno, type_name, token, column, unit):
    value = _as_float(token)
    if value is None:
        if "|" in token or "." in token or "/" in token or "\\" in token or token[:1].isalpha():
            raise rd.error(lineno, f"line type {type_name!r} column {column} must be a constant in "
                                   f"{unit}, got {token!r}, a nonlinear table (file name or '|' list) "
                                   "that seacable does not read for this column. Suggested fix: replace it with a "
                                   f"constant {column} (e.g. the secant value at the working tension).")
        raise rd.error(lineno, f"line type {type_name!r} column {column} must be a finite number in "
                               f"{unit}, got {token!r}. Suggested fix: write a plain number in SI units.")
    return value


def _bar_values(rd, lineno, type_name, token, column, unit, counts):
    """The numbers of a MoorDyn '|' list (``EA_s|EA_d``), each checked; ``counts`` the allowed lengths."""
    parts = token.split("|")
    if len(parts) not in counts:
        raise rd.error(lineno, f"line type {type_name!r} column {column} must hold "
                               f"{' or '.join(str(c) for c in counts)} values separated by '|', got {token!r}. "
                               f"Suggested fix: write {column} as MoorDyn v2 does, e.g. EA_s|EA_d or "
                               "EA_s|EA_Dc|EA_D_Lm for the viscoelastic model (docs/inputs.rst of MoorDyn).")
    return [rd.number(lineno, v, f"line type {type_name!r} {column} value {k + 1} of {token!r}", unit)
            for k, v in enumerate(parts)]


def _syrope(rd, lineno, type_name, token):
    """A Syrope configuration file (``value key`` lines: OWC table path relative to the deck, WCType, k1,
    k2): ((WCType, k1, k2), OWC path, OWC table)."""
    if rd.folder is None or not (rd.folder / token).is_file():
        raise rd.error(lineno, f"line type {type_name!r} names the Syrope file {token!r}, which is not a file"
                               f"{'' if rd.folder is None else f' (looked for {rd.folder / token})'}. Suggested fix: "
                               "put it next to the deck and read the deck from its file.")
    values, numeric = {}, 0
    for line in read_text_file(rd.folder / token, "Syrope file").splitlines():
        tokens = _strip_comment(line).split()
        if len(tokens) >= 2:
            values[tokens[1].upper()] = tokens[0]
            numeric += _as_float(tokens[0]) is not None and _as_float(tokens[1]) is not None
    if "OWC" not in values and numeric >= 2:
        # the other MoorDyn Syrope syntax: the file is the original working curve itself, and the working
        # curve comes from the SYROPE WORKING CURVES section (filled in by read_moordyn)
        return None, token, _tension_strain_table(rd, lineno, type_name, token)
    missing = [k for k in ("OWC", "WCTYPE", "K1", "K2") if k not in values]
    if missing:
        raise InputError(f"{rd.folder / token}: the Syrope file must give OWC, WCType, k1 and k2 as 'value key' "
                         f"lines; {', '.join(missing)} missing. Suggested fix: follow MoorDyn's Syrope input format.")
    wc = values["WCTYPE"].upper()
    if wc not in ("LINEAR", "QUADRATIC", "EXP"):
        raise InputError(f"{rd.folder / token}: WCType must be LINEAR, QUADRATIC or EXP, got {values['WCTYPE']!r}. "
                         "Suggested fix: use one of MoorDyn's Syrope working curves.")
    k1, k2 = (rd.number(lineno, values[k], f"line type {type_name!r} Syrope {k.lower()}", "N") for k in ("K1", "K2"))
    table = _tension_strain_table(rd, lineno, type_name, values["OWC"])
    return (wc, k1, k2), values["OWC"], table


def _tension_strain_table(rd, lineno, type_name, token):
    """A MoorDyn nonlinear EA: a file of (strain, tension) rows next to the deck, read and checked.

    MoorDyn-C (``getCoefficientOrCurve``) reads two numbers per line and skips lines that do not
    start with numbers (titles, column names, units); seacable does the same.
    """
    if rd.folder is None:
        raise rd.error(lineno, f"line type {type_name!r} EA names the table file {token!r}, but the deck was "
                               "given as text, so there is no folder to find it in. Suggested fix: read the "
                               "deck from its file, next to the table.")
    path = rd.folder / token
    if not path.is_file():
        raise rd.error(lineno, f"line type {type_name!r} EA names the strain-tension table {token!r}, which is "
                               f"not a file (looked for {path}). Suggested fix: put the table next to the deck, "
                               "or write a constant EA in N.")
    rows = []
    for k, line in enumerate(read_text_file(path, "strain-tension table").splitlines(), start=1):
        tokens = _strip_comment(line).split()
        if len(tokens) < 2 or _as_float(tokens[0]) is None:
            continue
        strain, tension = _as_float(tokens[0]), _as_float(tokens[1])
        if tension is None:
            raise InputError(f"{path}:{k}: the tension of a strain-tension row must be a finite number in N, got "
                             f"{tokens[1]!r}. Suggested fix: write 'strain tension' per line.")
        rows.append((k, strain, tension))
    if len(rows) < 2:
        raise InputError(f"{path}: a strain-tension table needs at least 2 rows of 'strain tension', found "
                         f"{len(rows)}. Suggested fix: give the curve from strain 0 up to the largest strain "
                         "expected.")
    for (k0, e0, t0), (k1, e1, t1) in zip(rows, rows[1:]):
        if e1 <= e0 or t1 < t0:
            raise InputError(f"{path}:{k1}: the strain-tension table must have increasing strain and non-decreasing "
                             f"tension, got ({e1:g}, {t1:g} N) after ({e0:g}, {t0:g} N) at line {k0}. Suggested "
                             "fix: sort the rows by strain; a softening rope curve is not supported.")
    if rows[0][1] < 0 or rows[0][2] < 0:
        raise InputError(f"{path}:{rows[0][0]}: the strain-tension table must start at strain >= 0 and tension "
                         f">= 0, got ({rows[0][1]:g}, {rows[0][2]:g} N). Suggested fix: start the table at (0, 0).")
    for k, strain, _ in rows:
        if strain > MAX_TABLE_STRAIN:
            raise InputError(f"{path}:{k}: strain {strain:g} ({100 * strain:g} %) in a strain-tension table: no mooring "
                             f"line stretches beyond {MAX_TABLE_STRAIN:g} (nylon breaks near 0.3-0.4, steel near "
                             "0.05). Suggested fix: give strain as a fraction (0.02 for 2 %), not in per cent.")
    if rows[-1][2] <= 0:
        raise InputError(f"{path}:{rows[-1][0]}: the strain-tension table's tension stays 0 N up to strain "
                         f"{rows[-1][1]:g}: the line has no axial stiffness. Suggested fix: give the tension (N) at "
                         "each strain.")
    return tuple((e, t) for _, e, t in rows)


#: Largest strain of a strain-tension table: a line stretched to twice its length. [-]
MAX_TABLE_STRAIN = 1.0


def _empty(rd, section, header, row):
    _, header_no, _, _ = section
    return rd.error(header_no, f"the {header} section has no rows; a MoorDyn file needs at least one. "
                               f"Suggested fix: add a row '{row}' after its column-names and units lines.")


def _read_line_types(rd, section) -> dict[str, MoorDynLineType]:
    names, rows = _table(rd, section)
    lowered = [n.lower() for n in names]
    v1 = "ei" not in lowered and ("can" in lowered or "cdn" in lowered or len(names) == 9)
    layout = ("name d m EA BA/-zeta Can Cat Cdn Cdt" if v1
              else "name d m EA BA/-zeta EI Cd Ca CdAx CaAx")
    _check_column_order(rd, section, names, "line_types_v1" if v1 else "line_types")
    if not rows:
        raise _empty(rd, section, "LINE TYPES", layout)
    out: dict[str, MoorDynLineType] = {}
    for lineno, t in rows:
        rd.columns(lineno, t, 9 if v1 else 10, "LINE TYPES", layout)
        name = t[0]
        if name in out:
            raise rd.error(lineno, f"line type {name!r} is defined twice. Suggested fix: give each "
                                   "line type its own name.")
        d = rd.number(lineno, t[1], f"line type {name!r} Diam (diameter)", "m")
        m = rd.number(lineno, t[2], f"line type {name!r} MassDen (mass per length)", "kg/m")
        table = dynamic = ba_dynamic = table_file = syrope = None
        if t[3].upper().startswith("SYROPE:"):  # MoorDyn's Syrope polyester model: SYROPE:file|EA_Dc|EA_D_Lm
            parts = t[3][7:].split("|")
            if len(parts) != 3:
                raise rd.error(lineno, f"line type {name!r} EA {t[3]!r} must be SYROPE:<file>|EA_Dc|EA_D_Lm. "
                                       "Suggested fix: write it as MoorDyn's Syrope documentation does.")
            dynamic = tuple(rd.number(lineno, v, f"line type {name!r} Syrope {c}", u)
                            for v, c, u in zip(parts[1:], ("EA_Dc", "EA_D_Lm"), ("N", "-")))
            syrope, table_file, table = _syrope(rd, lineno, name, parts[0])
            rd.syrope_types[name] = lineno
            e_last, t_last = table[-1]
            ea = t_last / e_last
        elif "|" in t[3]:  # viscoelastic (MoorDyn v2): EA_s|EA_d or EA_s|EA_Dc|EA_D_Lm
            ea, *dyn = _bar_values(rd, lineno, name, t[3], "EA", "N", (2, 3))
            dynamic = tuple(dyn)
            for label, value in zip(("EA_d" if len(dyn) == 1 else "EA_Dc", "EA_D_Lm"), dyn):
                rd.check(lineno, _validate.nonnegative, f"line type {name!r} {label}", value,
                         "N" if label != "EA_D_Lm" else "", "give the dynamic stiffness of the viscoelastic model")
        elif _as_float(t[3]) is None and not v1 and (t[3][:1].isalpha() or "." in t[3] or "/" in t[3]):
            table = _tension_strain_table(rd, lineno, name, t[3])
            table_file = t[3]
            e_last, t_last = table[-1]
            ea = t_last / e_last if e_last > 0 else 0.0  # secant EA at the table's end
        else:
            ea = _coefficient(rd, lineno, name, t[3], "EA", "N")
        if "|" in t[4]:  # viscoelastic: BA_s|BA_d (BA_s may be -zeta)
            ba, ba_dynamic = _bar_values(rd, lineno, name, t[4], "BA/-zeta", "N s (or -zeta)", (2,))
            rd.check(lineno, _validate.nonnegative, f"line type {name!r} BA_d (dynamic damping)", ba_dynamic,
                     "N s", "give the dynamic damping in N s (MoorDyn takes no damping ratio here)")
        else:
            ba = _coefficient(rd, lineno, name, t[4], "BA/-zeta", "N s (or -zeta)")
        if v1:
            ei = 0.0
            can, cat, cdn, cdt = (rd.number(lineno, t[k], f"line type {name!r} {c}", "-")
                                  for k, c in zip(range(5, 9), ("Can", "Cat", "Cdn", "Cdt")))
        else:
            ei = _coefficient(rd, lineno, name, t[5], "EI", "N m^2")
            cdn, can, cdt, cat = (rd.number(lineno, t[k], f"line type {name!r} {c}", "-")
                                  for k, c in zip(range(6, 10), ("Cd", "Ca", "CdAx", "CaAx")))
            if len(t) > 10:  # MoorDyn v2.3+: optional Cl dF cF (vortex-induced vibration)
                cl = rd.number(lineno, t[10], f"line type {name!r} Cl (VIV lift coefficient)", "-")
                if cl != 0:
                    rd.notes.append(f"{rd.label}:{lineno}: line type {name!r} Cl = {cl:g} asks for MoorDyn's "
                                    "vortex-induced vibration lift; seacable has no VIV model and runs the line "
                                    "without it.")
        rd.check(lineno, _validate.positive, f"line type {name!r} Diam (diameter)", d, "m",
                 "give the volume-equivalent diameter in metres")
        rd.check(lineno, _validate.positive, f"line type {name!r} MassDen (mass per length)", m, "kg/m",
                 "give the mass per metre in air in kg/m")
        rd.check(lineno, _validate.positive, f"line type {name!r} EA", ea, "N",
                 "give the axial stiffness EA in newtons")
        rd.check(lineno, _validate.nonnegative, f"line type {name!r} EI", ei, "N m^2",
                 "give the bending stiffness in N m^2, or 0")
        for label, value in (("Cd", cdn), ("Ca", can), ("CdAx", cdt), ("CaAx", cat)):
            rd.check(lineno, _validate.nonnegative, f"line type {name!r} {label}", value, "",
                     "hydrodynamic coefficients are >= 0")
        out[name] = MoorDynLineType(name, d, m, ea, ba, ei, cdn, can, cdt, cat, table, dynamic, ba_dynamic,
                                    table_file, syrope)
    return out


def _attachment(rd, lineno, word, point_id) -> tuple[str, int | None]:
    """A POINTS attachment: (kind, N of BodyN/TurbineN or None)."""
    letters = re.match(r"[A-Za-z]*", word).group(0).upper()
    for kind, words in _ATTACH.items():
        if letters in words and not word[len(letters):]:
            return kind, None
    number = word[len(letters):]
    if letters in ("BODY", "TURBINE") and number.isdigit() and int(number) >= 1:
        return letters.lower(), int(number)
    known = [w.title() for ws in _ATTACH.values() for w in ws] + ["Body1", "Turbine1"]
    why = f"{word!r}, not a point type{suggest(word.title(), known)}"
    raise rd.error(lineno, f"point {point_id} type must be Fixed, Vessel, Free, BodyN or TurbineN, got {why}. "
                           "Suggested fix: use Fixed (anchor), Vessel/Coupled (fairlead moved by the "
                           "vessel), Free (connection point), Body1 (fixed on body 1) or Turbine1 (FAST.Farm).")


def _read_points(rd, section) -> tuple[list[MoorDynPoint], dict[int, int]]:
    names, rows = _table(rd, section)
    forces = any(len(t) >= 12 for _, t in rows) or "fx" in {_key(n) for n in names}
    # the names are checked against the layout they can name: the forces' only where they name FX or every row
    # holds them (rows of both kinds under MoorDyn's nine names are read by their own length)
    named_forces = "fx" in {_key(n) for n in names} or bool(rows) and all(len(t) >= 12 for _, t in rows)
    _check_column_order(rd, section, names, "points_forces" if named_forces else "points")
    points, where, written = [], {}, []
    layout = "ID type X Y Z mass volume CdA Ca, or ID type X Y Z mass volume FX FY FZ CdA Ca"
    if not rows:
        raise _empty(rd, section, "POINTS", "ID type X Y Z mass volume CdA Ca")
    for lineno, t in rows:
        rd.columns(lineno, t, 9, "POINTS", layout)
        pid = _integer(rd, lineno, t[0], "point ID")
        written.append(pid)
        pid = len(points) + 1  # MoorDyn-C numbers the points by position and never reads the ID column
        kind, owner = _attachment(rd, lineno, t[1], pid)
        x, y, z = (rd.number(lineno, t[k], f"point {pid} {c}", "m") for k, c in zip((2, 3, 4), "XYZ"))
        mass = rd.number(lineno, t[5], f"point {pid} Mass", "kg")
        vol = rd.number(lineno, t[6], f"point {pid} Volume", "m^3")
        if len(t) >= 12:
            forces = [rd.number(lineno, t[k], f"point {pid} F{c}", "N") for k, c in zip((7, 8, 9), "XYZ")]
            if any(forces):
                raise rd.error(lineno, f"point {pid} constant force (FX FY FZ) must be 0, got {forces}; "
                                       "seacable does not apply constant point forces. Suggested fix: "
                                       "model the load as a point mass or buoyancy (mass, volume).")
            cda_tok, ca_tok = t[10], t[11]
        else:
            cda_tok, ca_tok = t[7], t[8]
        cda = rd.number(lineno, cda_tok, f"point {pid} CdA", "m^2")
        ca = rd.number(lineno, ca_tok, f"point {pid} Ca", "-")
        for label, value, unit in (("Mass", mass, "kg"), ("Volume", vol, "m^3"), ("CdA", cda, "m^2"),
                                   ("Ca", ca, "")):
            rd.check(lineno, _validate.nonnegative, f"point {pid} {label}", value, unit,
                     "point masses, volumes and coefficients are >= 0")
        points.append(MoorDynPoint(pid, kind, (x, y, z), mass, vol, cda, ca, owner if kind == "body" else None,
                                   owner if kind == "turbine" else None))
        where[pid] = lineno
    if written != list(range(1, len(written) + 1)):
        warnings.warn(f"{rd.label}: point IDs {written} are not 1..{len(written)} in file order; MoorDyn numbers the "
                      "points by their position in the list (it never reads the ID column), and so does seacable: "
                      "lines attach to points 1..N in file order. Suggested fix: number the points 1, 2, 3, ... in "
                      "order.", SeacableWarning, stacklevel=4)
    return points, where


def _integer(rd, lineno, token, what) -> int:
    value = _as_float(token)
    if value is None or value != int(value):
        raise rd.error(lineno, f"{what} must be a whole number, got {token!r}. "
                               "Suggested fix: write an integer such as 1.")
    return int(value)


def _point_ref(rd, lineno, token, points, line_id, end, rods=None):
    """The point ID of a LINES attachment (``end`` names it, e.g. ``'A (AttachA)'``), or a rod end
    ``(rod ID, 'A'|'B')`` for ``R1A``/``Rod1B``."""
    m = re.fullmatch(r"([A-Za-z]*)(\d+)([A-Za-z]*)", token)
    prefix = m.group(1).upper() if m else ""
    if m and prefix in ("R", "ROD") and m.group(3).upper() in ("A", "B"):
        rid, side = int(m.group(2)), m.group(3).upper()
        if not rods or rid not in rods:
            ids = [str(k) for k in (rods or {})]
            raise rd.error(lineno, f"line {line_id} end {end} is attached to rod end {token!r}, but rod {rid} is "
                                   f"not in the RODS section (IDs {', '.join(ids) or 'none'}). Suggested fix: add "
                                   "the rod or correct the ID.")
        return rid, side
    if not m or m.group(3) or prefix not in ("", "C", "CON", "P", "POINT"):
        raise rd.error(lineno, f"line {line_id} end {end} must be a point ID (e.g. 1, C1 or Point1) or a rod end "
                               f"(R1A, R1B), got {token!r}. Suggested fix: write the ID of a row of the POINTS "
                               "section.")
    pid = int(m.group(2))
    if pid not in points:
        ids = [str(k) for k in points]
        raise rd.error(lineno, f"line {line_id} end {end} refers to point {pid}, which is not in the "
                               f"POINTS section (IDs {', '.join(ids)}).{suggest(str(pid), ids)} "
                               "Suggested fix: add the point or correct the ID.")
    return pid


# memory of one node in the model and its result: position, velocity, acceleration and the band of the
# Newton matrix (about 50 values), element properties and the stored shape and tensions [values]
_VALUES_PER_NODE = 64


def _end_position(points, rods, ref):
    """Global position of a line end for a negative UnstrLen (None if it is not global)."""
    if isinstance(ref, tuple):
        rod = rods[ref[0]]
        if rod.attachment == "body":
            return None
        return rod.end_a if ref[1] == "A" else rod.end_b
    p = points[ref]
    return p.position if p.attachment in ("fixed", "free", "vessel") else None


def _read_lines(rd, section, types, points, rods=None) -> list[MoorDynLine]:
    names, rows = _table(rd, section)
    v1 = len(names) > 2 and "len" in names[2].lower()
    layout = ("ID type UnstrLen NumSegs NodeAnch NodeFair flags" if v1
              else "ID type AttachA AttachB UnstrLen NumSegs outputs")
    _check_column_order(rd, section, names, "lines_v1" if v1 else "lines")
    if not rows:
        raise _empty(rd, section, "LINES", layout)
    cols = (4, 5, 2, 3) if v1 else (2, 3, 4, 5)  # attach A, attach B, length, segments
    ends = ("NodeAnch", "NodeFair") if v1 else ("AttachA", "AttachB")
    out, seen, nodes = [], {}, len(points)
    for lineno, t in rows:
        rd.columns(lineno, t, 7, "LINES", layout)
        lid = _integer(rd, lineno, t[0], "line ID")
        if lid in seen:
            raise rd.error(lineno, f"line ID {lid} is used twice (first at line {seen[lid]}). "
                                   "Suggested fix: number the lines 1, 2, 3, ... once each.")
        seen[lid] = lineno
        if t[1] not in types:
            raise rd.error(lineno, f"line {lid} LineType must be one of {sorted(types)}, got "
                                   f"{t[1]!r}.{suggest(t[1], types)} Suggested fix: use a name from the "
                                   "LINE TYPES section (names are case-sensitive).")
        a = _point_ref(rd, lineno, t[cols[0]], points, lid, f"A ({ends[0]})", rods)
        b = _point_ref(rd, lineno, t[cols[1]], points, lid, f"B ({ends[1]})", rods)
        length = rd.number(lineno, t[cols[2]], f"line {lid} UnstrLen (unstretched length)", "m")
        nseg = _integer(rd, lineno, t[cols[3]], f"line {lid} NumSegs (number of segments)")
        rd.check(lineno, _validate.at_least, f"line {lid} NumSegs (number of segments)", nseg, "",
                 "use at least 1 segment (MoorDyn needs about 10 or more for dynamics)", 1)
        nodes += nseg - 1
        try:
            _limits.check_run_size(f"line {lid} NumSegs = {nseg:.6g} (the file's network of {nodes:.3g} nodes)",
                                   steps=1, stored_values=_VALUES_PER_NODE * nodes,
                                   fix="use fewer segments: about 1 per 5-20 m of line is usual")
        except InputError as exc:
            raise rd.error(lineno, str(exc)) from None
        if a == b:
            raise rd.error(lineno, f"line {lid} AttachA and AttachB are the same point ({a}). Suggested fix: "
                                   "attach the line's two ends to two different points.")
        if length < 0:  # MoorDyn: a negative length is a factor on the end-point distance
            pa, pb = _end_position(points, rods, a), _end_position(points, rods, b)
            if pa is None or pb is None:
                raise rd.error(lineno, f"line {lid} UnstrLen {t[cols[2]]} is negative (a factor on the distance "
                                       "between the ends), but an end is on a body, whose global position seacable "
                                       "does not compute while reading. Suggested fix: give the length in metres.")
            length = -length * math.dist(pa, pb)
        rd.check(lineno, _validate.positive, f"line {lid} UnstrLen (unstretched length)", length, "m",
                 "give the unstretched length in metres (or -factor times the end-point distance)")
        rod_a, rod_b = (a if isinstance(a, tuple) else None), (b if isinstance(b, tuple) else None)
        out.append(MoorDynLine(lid, t[1], None if rod_a else a, None if rod_b else b, length, nseg, t[6],
                               rod_a, rod_b))
    return out


_BODY_KINDS = {"FREE": ("free", False), "FIXED": ("fixed", False), "FIX": ("fixed", False),
               "COUPLED": ("coupled", False), "VESSEL": ("coupled", False), "CPLD": ("coupled", False),
               "VES": ("coupled", False), "COUPLEDPINNED": ("coupled", True), "VESSELPINNED": ("coupled", True),
               "CPLDPIN": ("coupled", True)}
_ROD_KINDS = {**_BODY_KINDS, "PINNED": ("free", True), "PIN": ("free", True)}


def _bar_list(rd, lineno, token, what, unit, counts):
    """A value, or several separated by '|' (MoorDyn's CG, I, CdA, Ca columns), each a number >= 0 except CG."""
    parts = token.split("|")
    if len(parts) not in counts:
        raise rd.error(lineno, f"{what} must be {' or '.join(str(c) for c in counts)} value(s) separated by '|' "
                               f"(no spaces), got {token!r}. Suggested fix: e.g. 0 or 0|0|-10.")
    return [rd.number(lineno, v, what, unit) for v in parts]


def _read_rod_types(rd, section) -> dict[str, MoorDynRodType]:
    names, rows = _table(rd, section)
    _check_column_order(rd, section, names, "rod_types")
    layout = "TypeName Diam Mass/m Cd Ca CdEnd CaEnd"
    out: dict[str, MoorDynRodType] = {}
    for lineno, t in rows:
        rd.columns(lineno, t, 7, "ROD TYPES", layout)
        name = t[0]
        if name in out:
            raise rd.error(lineno, f"rod type {name!r} is defined twice. Suggested fix: give each rod type its own "
                                   "name.")
        values = [rd.number(lineno, t[k], f"rod type {name!r} {c}", u) for k, c, u in
                  zip(range(1, 7), ("Diam", "Mass/m", "Cd", "Ca", "CdEnd", "CaEnd"), ("m", "kg/m", "", "", "", ""))]
        rd.check(lineno, _validate.positive, f"rod type {name!r} Diam", values[0], "m",
                 "give the rod's diameter in metres")
        for label, value, unit in zip(("Mass/m", "Cd", "Ca", "CdEnd", "CaEnd"), values[1:],
                                      ("kg/m", "", "", "", "")):
            rd.check(lineno, _validate.nonnegative, f"rod type {name!r} {label}", value, unit,
                     "rod masses and coefficients are >= 0")
        out[name] = MoorDynRodType(name, *values)
    return out


def _read_bodies(rd, section) -> tuple[list[MoorDynBody], dict[int, int]]:
    names, rows = _table(rd, section)
    layout = "ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca"
    early = any(n.lower() == "xcg" for n in names)
    _check_column_order(rd, section, names, "bodies_v2alpha" if early else "bodies")
    if early:
        # the early MoorDyn-F v2 layout (OpenFAST r-test 5MW_OC4): 'BodyID X0 Y0 Z0 r0 p0 y0 Xcg Ycg Zcg M V IX IY IZ
        # CdA Ca', the ID and attachment written together ('1coupled'): rewritten into today's columns
        old = "BodyID X0 Y0 Z0 r0 p0 y0 Xcg Ycg Zcg M V IX IY IZ CdA Ca"
        rewritten = []
        for lineno, t in rows:
            rd.columns(lineno, t, 17, "BODIES", old)
            m = re.fullmatch(r"(\d+)([A-Za-z]\w*)", t[0])
            if not m:
                raise rd.error(lineno, f"the body ID and attachment of this layout ({old}) are written together, e.g. "
                                       f"'1coupled', got {t[0]!r}. Suggested fix: write the ID then the attachment.")
            rewritten.append((lineno, [m.group(1), m.group(2), *t[1:7], t[10], "|".join(t[7:10]), "|".join(t[12:15]),
                                       t[11], t[15], t[16]]))
        rows = rewritten
    bodies, where = [], {}
    for lineno, t in rows:
        rd.columns(lineno, t, 14, "BODIES", layout)
        bid = _integer(rd, lineno, t[0], "body ID")
        if bid in where:
            raise rd.error(lineno, f"body ID {bid} is used twice (first at line {where[bid]}). Suggested fix: number "
                                   "the bodies 1, 2, 3, ... once each.")
        word = t[1].upper()
        turbine = None
        if word in _BODY_KINDS:
            kind, pinned = _BODY_KINDS[word]
        elif word.startswith("TURBINE") and word[7:].isdigit():
            kind, pinned, turbine = "turbine", False, int(word[7:])
        else:
            raise rd.error(lineno, f"body {bid} Attachment must be Free, Fixed, Coupled (Vessel), CoupledPinned or "
                                   f"TurbineN, got {t[1]!r}.{suggest(t[1].title(), ['Free', 'Fixed', 'Coupled'])} "
                                   "Suggested fix: use one of those words.")
        x, y, z = (rd.number(lineno, t[k], f"body {bid} {c}0", "m") for k, c in zip((2, 3, 4), "XYZ"))
        angles = tuple(math.radians(rd.number(lineno, t[k], f"body {bid} {c}", "deg"))
                       for k, c in zip((5, 6, 7), ("r0", "p0", "y0")))
        mass = rd.number(lineno, t[8], f"body {bid} Mass", "kg")
        cg = _bar_list(rd, lineno, t[9], f"body {bid} CG", "m", (1, 3))
        cg = (0.0, 0.0, cg[0]) if len(cg) == 1 else tuple(cg)  # one value: along the body's z axis
        inertia = _bar_list(rd, lineno, t[10], f"body {bid} I", "kg m^2", (1, 3))
        inertia = tuple(inertia * 3) if len(inertia) == 1 else tuple(inertia)
        volume = rd.number(lineno, t[11], f"body {bid} Volume", "m^3")
        cda = _bar_list(rd, lineno, t[12], f"body {bid} CdA", "m^2", (1, 2, 3, 6))
        cda = {1: lambda v: v * 6, 2: lambda v: [v[0]] * 3 + [v[1]] * 3, 3: lambda v: v * 2,
               6: lambda v: v}[len(cda)](cda)
        ca = _bar_list(rd, lineno, t[13], f"body {bid} Ca", "-", (1, 3))
        ca = tuple(ca * 3) if len(ca) == 1 else tuple(ca)
        for label, value, unit in (("Mass", mass, "kg"), ("Volume", volume, "m^3"),
                                   *((f"I[{k}]", v, "kg m^2") for k, v in enumerate(inertia)),
                                   *((f"CdA[{k}]", v, "m^2") for k, v in enumerate(cda)),
                                   *((f"Ca[{k}]", v, "") for k, v in enumerate(ca))):
            rd.check(lineno, _validate.nonnegative, f"body {bid} {label}", value, unit,
                     "body masses, inertias, volumes and coefficients are >= 0")
        bodies.append(MoorDynBody(bid, kind, (x, y, z, *angles), mass, cg, inertia, volume, tuple(cda), ca,
                                  pinned, turbine))
        where[bid] = lineno
    return bodies, where


def _read_rods(rd, section, rod_types, bodies) -> tuple[list[MoorDynRod], dict[int, int]]:
    names, rows = _table(rd, section)
    _check_column_order(rd, section, names, "rods")
    layout = "ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs"
    rods, where = [], {}
    for lineno, t in rows:
        rd.columns(lineno, t, 11, "RODS", layout)
        rid = _integer(rd, lineno, t[0], "rod ID")
        if rid in where:
            raise rd.error(lineno, f"rod ID {rid} is used twice (first at line {where[rid]}). Suggested fix: number "
                                   "the rods 1, 2, 3, ... once each.")
        if t[1] not in rod_types:
            raise rd.error(lineno, f"rod {rid} RodType must be one of {sorted(rod_types)}, got {t[1]!r}."
                                   f"{suggest(t[1], rod_types)} Suggested fix: use a name from the ROD TYPES section.")
        word = t[2].upper()
        body = turbine = None
        m = re.fullmatch(r"(BODY|TURBINE)(\d+)(PINNED|PIN)?", word)
        if word in _ROD_KINDS or re.fullmatch(r"PINNED\d+", word):  # MoorDyn-F's r-test writes 'Pinned1'
            kind, pinned = _ROD_KINDS.get(word, ("free", True))
        elif m and m.group(1) == "BODY":
            kind, pinned, body = "body", m.group(3) is not None, int(m.group(2))
            if body not in bodies:
                raise rd.error(lineno, f"rod {rid} is attached to body {body}, which is not in the BODIES section "
                                       f"(IDs {', '.join(str(b) for b in bodies) or 'none'}). Suggested fix: add the "
                                       "body or correct the ID.")
        elif m:
            kind, pinned, turbine = "turbine", m.group(3) is not None, int(m.group(2))
        else:
            raise rd.error(lineno, f"rod {rid} Attachment must be Fixed, Pinned, Free, Coupled (Vessel), "
                                   f"CoupledPinned, BodyN, BodyNPinned or TurbineN, got {t[2]!r}."
                                   f"{suggest(t[2].title(), ['Fixed', 'Pinned', 'Free', 'Coupled', 'Body1'])} "
                                   "Suggested fix: use one of those words.")
        ends = [rd.number(lineno, t[k], f"rod {rid} {c}", "m") for k, c in
                zip(range(3, 9), ("Xa", "Ya", "Za", "Xb", "Yb", "Zb"))]
        nseg = _integer(rd, lineno, t[9], f"rod {rid} NumSegs")
        rd.check(lineno, _validate.nonnegative, f"rod {rid} NumSegs", nseg, "",
                 "use 0 (a point-like rod) or more segments")
        rod = MoorDynRod(rid, t[1], kind, tuple(ends[:3]), tuple(ends[3:]), nseg, t[10], pinned, body, turbine)
        if rod.length == 0 and nseg > 0:
            raise rd.error(lineno, f"rod {rid} has its two ends at the same place {tuple(ends[:3])} m but {nseg} "
                                   "segment(s). Suggested fix: give the rod a length, or NumSegs 0.")
        if rod.length > 0 and nseg == 0:  # MoorDyn takes a rod of no segments as point-like, of zero length
            raise rd.error(lineno, f"rod {rid} NumSegs = 0 but its ends are {rod.length:.6g} m apart: a rod of 0 "
                                   "segments is point-like (no length, no nodes along it), so its length would be "
                                   "lost. Suggested fix: give NumSegs >= 1, or put both ends at the same place.")
        rods.append(rod)
        where[rid] = lineno
    return rods, where


def _read_failures(rd, section, points, rods, lines) -> list[MoorDynFailure]:
    names, rows = _table(rd, section)
    _check_column_order(rd, section, names, "failure" if rows and len(rows[0][1]) >= 5 else "failure_no_id")
    out = []
    line_ids = {ln.id: ln for ln in lines}
    for index, (lineno, t) in enumerate(rows, start=1):
        if len(t) >= 5:
            fid = _integer(rd, lineno, t[0], "failure ID")
            t = t[1:]
        else:
            rd.columns(lineno, t, 4, "FAILURE", "FailureID Point Line(s) FailTime FailTen")
            fid = index
        ref = t[0]
        m = re.fullmatch(r"(?:R|ROD)(\d+)([AB])", ref.upper())
        if m:
            where = (int(m.group(1)), m.group(2))
            if where[0] not in rods:
                raise rd.error(lineno, f"failure {fid} is at rod end {ref!r}, but there is no rod {where[0]}. "
                                       "Suggested fix: name a rod end of the RODS section, e.g. R1A.")
        else:
            where = _point_ref(rd, lineno, ref, points, f"of failure {fid}", "(Point)")
        ids = []
        for token in t[1].split(","):
            lid = _integer(rd, lineno, token, f"failure {fid} Line(s) entry")
            if lid not in line_ids:
                raise rd.error(lineno, f"failure {fid} names line {lid}, which is not in the LINES section. "
                                       "Suggested fix: list IDs of lines, separated by commas without spaces.")
            ln = line_ids[lid]
            at = [ln.point_a, ln.point_b] if isinstance(where, int) else [ln.rod_a, ln.rod_b]
            if where not in at:
                raise rd.error(lineno, f"failure {fid}: line {lid} is not attached to {ref} (its ends are "
                                       f"{_end_name(ln.point_a, ln.rod_a)} and {_end_name(ln.point_b, ln.rod_b)}). "
                                       "Suggested fix: name the point or rod end the line ends at.")
            ids.append(lid)
        time = rd.number(lineno, t[2], f"failure {fid} FailTime", "s")
        tension = rd.number(lineno, t[3], f"failure {fid} FailTen", "N")
        rd.check(lineno, _validate.nonnegative, f"failure {fid} FailTime", time, "s", "give a time in s, or 0")
        rd.check(lineno, _validate.nonnegative, f"failure {fid} FailTen", tension, "N",
                 "give a tension in N, or 0")
        if time == 0 and tension == 0:
            rd.notes.append(f"{rd.label}:{lineno}: failure {fid} has FailTime 0 and FailTen 0: MoorDyn-F then "
                            "breaks the line(s) at the start.")
        out.append(MoorDynFailure(fid, where, tuple(ids), time, tension))
    return out


def _read_external_loads(rd, section, points, bodies, rods) -> list[MoorDynExternalLoad]:
    names, rows = _table(rd, section)
    _check_column_order(rd, section, names, "external_loads")
    out = []
    for lineno, t in rows:
        rd.columns(lineno, t, 5, "EXTERNAL LOADS", "ID Object Fext Blin Bquad [CSys]")
        lid = _integer(rd, lineno, t[0], "external load ID")
        m = re.fullmatch(r"(BODY|POINT|ROD)(\d+)", t[1].upper())
        pool = {"BODY": bodies, "POINT": points, "ROD": rods}
        if not m or int(m.group(2)) not in pool[m.group(1)]:
            raise rd.error(lineno, f"external load {lid} Object must name a body, point or rod of the deck (e.g. "
                                   f"Body1, Point3, Rod2), got {t[1]!r}. Suggested fix: use the object's kind and ID.")
        kind, target = m.group(1).lower(), int(m.group(2))
        force = _bar_list(rd, lineno, t[2], f"external load {lid} Fext", "N", (3,))
        damp_counts = (2,) if kind == "rod" else (3,)
        blin = _bar_list(rd, lineno, t[3], f"external load {lid} Blin", "N s/m", damp_counts)
        bquad = _bar_list(rd, lineno, t[4], f"external load {lid} Bquad", "N s^2/m^2", damp_counts)
        for label, values in (("Blin", blin), ("Bquad", bquad)):
            for v in values:
                rd.check(lineno, _validate.nonnegative, f"external load {lid} {label}", v, "",
                         "damping coefficients are >= 0")
        frame = t[5].upper() if len(t) > 5 else "G"
        if kind == "body" and frame not in ("G", "L"):
            raise rd.error(lineno, f"external load {lid} CSys must be G (global) or L (body axes) for a body, got "
                                   f"{t[5]!r}. Suggested fix: write G or L.")
        out.append(MoorDynExternalLoad(lid, kind, target, tuple(force), tuple(blin), tuple(bquad),
                                       frame if kind == "body" else "G"))
    return out


def _end_name(point, rod) -> str:
    return f"R{rod[0]}{rod[1]}" if rod else f"point {point}"


def _read_options(rd, section) -> dict[str, float | str]:
    options: dict[str, float | str] = {}
    for lineno, line in section[3]:
        tokens = _strip_comment(line).split()
        if not tokens:
            continue
        if len(tokens) < 2:
            raise rd.error(lineno, f"an option line must be 'value name [comment]', got "
                                   f"{line.strip()!r}. Suggested fix: write the value, then the option "
                                   "name (e.g. '100 WtrDpth').")
        value = _as_float(tokens[0])
        if value is None and _as_float(tokens[1]) is not None:
            # the OPTIONS rows' order is 'value name': MoorDyn reads the first word as the value, whatever it is
            warnings.warn(f"{rd.label}:{lineno}: the OPTIONS row {line.strip()!r} gives a name then a number, but "
                          f"MoorDyn reads options as 'value name': it takes {tokens[0]!r} as the value of an option "
                          f"named {tokens[1]!r}, and so does seacable (an option it does not know: ignored). Suggested "
                          f"fix: write '{tokens[1]} {tokens[0]}'.", SeacableWarning, stacklevel=4)
        _check_option(rd, lineno, tokens[1], tokens[0], value)
        options[tokens[1]] = tokens[0] if value is None else value
        rd.option_lines[tokens[1]] = lineno
    return options


_OPTION_CHECKS = {  # name (lower case): (check, unit, fix)
    **{k.lower(): (_validate.positive, "m", ("give the water depth as a positive number of metres, or remove "
                   "the line (MoorDyn then takes the depth of the deepest point)")) for k in _DEPTH},
    # MoorDyn's own tests switch gravity or buoyancy off with 0: read, and refused by the models that need them
    **{k.lower(): (_validate.nonnegative, "kg/m^3", "give the water density, e.g. 1025") for k in _RHO},
    **{k.lower(): (_validate.nonnegative, "m/s^2", "give g in m/s^2, e.g. 9.80665") for k in _G},
    **{k.lower(): (_validate.nonnegative, "Pa/m", "give the seabed stiffness per contact area, e.g. 3e6")
       for k in _KBOT},
    **{k.lower(): (_validate.nonnegative, "Pa s/m", "give the seabed damping per contact area, e.g. 3e5")
       for k in _CBOT},
    **{k.lower(): (_validate.positive, "s", "give the mooring time step in seconds, e.g. 0.001") for k in _DT},
    **{k.lower(): (_validate.positive, "", "give a CFL factor such as 0.5") for k in _CFL},
    **{k.lower(): (_validate.nonnegative, "", "give a friction coefficient >= 0, e.g. 0.5")
       for k in _MU + _MU_T + _MU_A},
    **{k.lower(): (_validate.nonnegative, "N s/m", "give the friction damping scale, default 200")
       for k in _FRIC_DAMP},
    **{k.lower(): (_validate.positive, "", "give the static/dynamic friction ratio, default 1")
       for k in _FRIC_SCALE},
    **{k.lower(): (_validate.nonnegative, "", "give a whole number: 0 (none) or a MoorDyn mode")
       for k in ("WaveKin", "Currents")},
    **{k.lower(): (_validate.nonnegative, "s", "give a time in seconds")
       for k in ("dtWave", "waveKin_rampT", "dtIC", "ICdt", "TmaxIC", "ICTmax", "dtOut", "inertialF_rampT")},
    **{k.lower(): (_validate.positive, "", "give a positive number") for k in ("CdScaleIC", "ICDfac")},
    **{k.lower(): (_validate.nonnegative, "", "give a number >= 0") for k in ("threshIC", "ICthresh")},
}
_WHOLE = {"wavekin", "currents"}

# Options that only steer MoorDyn's own numerics (explicit time integration, the dynamic-relaxation
# start, coupled-body inertia) or its own files and console: they do not change the mooring problem.
# seacable solves the static equilibrium by Newton's method and integrates in time with an implicit
# Newmark scheme at the time step the user gives (``--time-step``), so they need no counterpart.
_NUMERICS = {k.lower() for k in ("dtM", "DT", "cfl", "tScheme", "dtIC", "ICdt", "TmaxIC", "ICTmax",
                                 "CdScaleIC", "ICDfac", "threshIC", "ICthresh", "ICgenDynamic", "fileIC",
                                 "inertialF", "inertialF_rampT", "writeLog", "WriteUnits", "dtOut",
                                 "disableOutput", "disableOutTime", "OutSwitch", "Echo")}
# Options honoured by the model (``moordyn_model``) or read with the waves they belong to.
_MODEL = {k.lower() for k in _DEPTH + _RHO + _G + _KBOT + _CBOT + _MU + _MU_T + _MU_A + _FRIC_DAMP + _FRIC_SCALE
          + ("WaveKin", "Currents", "WaterKin", "dtWave", "waveKin_rampT", "UnifyCurrentGrid", "SeafloorFile")}
_KNOWN_OPTIONS = ("WtrDpth", "WtrDnsty", "rhoW", "g", "kBot", "cBot", "FrictionCoefficient", "FricDamp",
                  "StatDynFricScale", "mu_kT", "mu_kA", "MC", "CV", "WaveKin", "Currents", "WaterKin", "dtWave",
                  "waveKin_rampT", "UnifyCurrentGrid", "SeafloorFile", "dtM", "cfl", "tScheme", "dtIC",
                  "TmaxIC", "CdScaleIC", "threshIC", "ICgenDynamic", "fileIC", "inertialF", "inertialF_rampT",
                  "writeLog", "WriteUnits", "dtOut", "disableOutput", "disableOutTime", "OutSwitch")


def _check_option(rd, lineno, name, token, value):
    key = name.lower()
    if key not in _OPTION_CHECKS:
        return
    check, unit, fix = _OPTION_CHECKS[key]
    if value is None:
        why = (" (MoorDyn-F reads a bathymetry file here; seacable has a flat seabed and does not read it)"
               if key in {k.lower() for k in _DEPTH} else "")
        raise rd.error(lineno, f"option {name} must be a number in {unit or 'SI units'}, got {token!r}{why}. "
                               f"Suggested fix: {fix}.")
    rd.check(lineno, check, f"option {name}", value, unit, fix)
    if key in _WHOLE and value != int(value):
        raise rd.error(lineno, f"option {name} must be a whole number, got {token!r}. Suggested fix: {fix}.")


def _fmt_value(value) -> str:
    return f"{value:g}" if isinstance(value, float) else repr(value)


def _option_notes(rd, options: dict, depth: float | None, depth_source: str) -> list[str]:
    """What seacable does about each option it cannot honour (see :class:`MoorDynInput` ``notes``)."""
    notes = []
    seabed = (f"a flat seabed at z = {-depth:g} m ({depth_source})" if depth is not None else "no seabed")
    for name, value in options.items():
        key = name.lower()
        if key in _NUMERICS or key in _MODEL:
            continue
        hint = suggest(name, _KNOWN_OPTIONS)
        notes.append(f"{rd.at(name)}option {name} = {_fmt_value(value)} is not a MoorDyn option seacable knows; it is "
                     f"ignored.{hint}")
    wave_kin = _lookup(options, ("WaveKin",))
    if wave_kin:
        notes.append(f"{rd.at('WaveKin')}option WaveKin = {wave_kin:g} asks MoorDyn for wave kinematics (from its wave files or "
                     "a coupled code); seacable runs this file in still water for its statics (as MoorDyn finds its "
                     "initial conditions) and refuses a dynamic run of it. Suggested fix: for waves (regular, or "
                     "an irregular sea from a spectrum) write the mooring as a YAML case with environment.waves.")
    currents = _lookup(options, ("Currents",))
    if currents:
        notes.append(f"{rd.at('Currents')}option Currents = {currents:g} asks MoorDyn for a current read from its current files; "
                     "seacable runs this file without current for its statics and refuses a dynamic run of it. "
                     "Suggested fix: for a current profile write the mooring as a YAML case with environment.current.")
    water_kin = _lookup(options, ("WaterKin",))
    if water_kin is not None and str(water_kin).strip("\"'").lower() not in ("", "unused", "none", "0"):
        notes.append(f"{rd.at('WaterKin')}option WaterKin = {_fmt_value(water_kin)} (MoorDyn-F water kinematics) is not read; "
                     "seacable runs this file in still water.")
    floor = _lookup(options, ("SeafloorFile",))
    if floor is not None:
        notes.append(f"{rd.at('SeafloorFile')}option SeafloorFile = {_fmt_value(floor)} (a 3-D bathymetry) is not read; seacable uses "
                     f"{seabed}.")
    mu = _lookup(options, _MU)
    mu_t, mu_a = _lookup(options, _MU_T), _lookup(options, _MU_A)
    if mu is not None and (mu_t is not None or mu_a is not None):
        notes.append(f"{rd.at('mu_kT')}options mu_kT/mu_kA (MoorDyn-F) are ignored: FrictionCoefficient = {mu:g} is used for "
                     "the seabed friction.")
    elif (mu_t is not None or mu_a is not None) and (mu_t or 0.0) != (mu_a or 0.0):
        mu_t, mu_a = mu_t or 0.0, mu_a or 0.0  # MoorDyn-F's default for either is 0
        notes.append(f"{rd.at('mu_kT' if _lookup(options, _MU_T) is not None else 'mu_kA')}options mu_kT = "
                     f"{mu_t:g} and mu_kA = {mu_a:g} (MoorDyn-F's default 0 where not given) give different "
                     "transverse and axial seabed friction; seacable's seabed friction is isotropic and uses "
                     f"their mean, {(mu_t + mu_a) / 2:g}.")
    friction = mu if mu is not None else max(v for v in (mu_t, mu_a, 0.0) if v is not None)
    damp = [(n, v) for n, v in options.items() if n.lower() in {k.lower() for k in _FRIC_DAMP}]
    if friction > 0 and damp:
        name, value = damp[-1]
        notes.append(f"{rd.at(name)}option {name} = {value:g} (MoorDyn's friction ramp, F = mu * {name} * |v| up to mu N) "
                     "is not used: seacable applies Coulomb friction mu N regularised over 0.01 m/s of "
                     "sliding speed.")
    scale = [(n, v) for n, v in options.items() if n.lower() in {k.lower() for k in _FRIC_SCALE}]
    if friction > 0 and scale and scale[-1][1] != 1.0:
        name, value = scale[-1]
        notes.append(f"{rd.at(name)}option {name} = {value:g} (static/dynamic friction ratio) is not used: seacable's "
                     "static and dynamic friction coefficients are equal (ratio 1).")
    return notes


def _read_outputs(section) -> tuple[str, ...]:
    names = []
    for _, line in section[3]:
        for token in re.split(r"[\s,]+", _strip_comment(line).strip()):
            token = token.strip("\"'")
            if token:
                names.append(token)
    return tuple(names)


def read_moordyn(path_or_text, *, name=None) -> MoorDynInput:
    """Read a MoorDyn v2 (or v1) input file: every section (line and rod types, bodies, rods, points, lines,
    failures, external loads, options, outputs).

    Parameters
    ----------
    path_or_text : str or pathlib.Path
        A path to the file, or the file's text (a string containing a newline).
    name : str, optional
        The name used for the file in error messages (default: the path, or ``<MoorDyn text>``).

    Returns
    -------
    MoorDynInput
        The file's contents in SI units, with convenience properties for the options.

    Raises
    ------
    InputError
        With the file, line number, what was wrong, what was expected and a fix: a missing
        LINE TYPES/POINTS/LINES section; a row with too few columns; a value that is not a
        number; an unknown line type, rod type, point, body or rod ID; a duplicate line,
        body or rod ID; a non-positive diameter, mass, EA or length; fewer than one segment, or
        more than memory allows (see :mod:`seacable._limits`); a line whose two ends are one
        point; an empty LINE TYPES, POINTS or LINES section (without bodies or rods); rows in
        CONTROL; a strain-tension or Syrope file that is missing or not increasing; a BA or EI
        table; an unknown point, body or rod attachment; a failure at a point its lines do not
        end at; a point below a given ``WtrDpth``; an option value out of range or not a number.

    Warns
    -----
    SeacableWarning
        When point IDs are not 1..N in file order (MoorDyn and seacable number the points by
        position), or when a section seacable does not know has rows. Options seacable cannot
        honour are not warned here but listed in :attr:`MoorDynInput.notes`, for the model.

    References
    ----------
    .. [1] MoorDyn-C ``source/MoorDyn2.cpp`` (``ReadInFile``), FloatingArrayDesign/MoorDyn.
    """
    text, path, label = _load(path_or_text, name)
    rd = _Reader(label, Path(path).parent if path else None)
    title, echo, sections = _split_sections(rd, text)
    for kind, header in _UNSUPPORTED.items():
        if kind in sections:
            _, rows = _table(rd, sections[kind])
            if rows:
                raise rd.error(rows[0][0], f"the {header} section has {len(rows)} row(s); seacable does not read "
                                           f"MoorDyn-F's {header} (OpenFAST-coupled). Suggested fix: remove the "
                                           f"{header} section, or give the loads as body external forces in a "
                                           "seacable system case.")
    rod_types = _read_rod_types(rd, sections["rod_types"]) if "rod_types" in sections else {}
    bodies, _ = _read_bodies(rd, sections["bodies"]) if "bodies" in sections else ([], {})
    body_ids = {b.id: b for b in bodies}
    rods, _ = _read_rods(rd, sections["rods"], rod_types, body_ids) if "rods" in sections else ([], {})
    rod_ids = {r.id: r for r in rods}
    structures = bool(bodies or rods)
    required = (("line_types", "LINE TYPES"), ("points", "POINTS"), ("lines", "LINES"))
    for kind, header in required:
        if kind not in sections and not (structures and (kind != "line_types" or "lines" not in sections)):
            raise rd.error(None, f"the file must have a {header} section (a line of dashes containing "
                                 f"'{header}'), found none. Suggested fix: check that this is a MoorDyn "
                                 "input file and that the section header is spelled as MoorDyn expects.")
    types = _read_line_types(rd, sections["line_types"]) if "line_types" in sections else {}
    if "points" in sections and (sections["points"][3] or not structures):
        _, point_rows = _table(rd, sections["points"])
        if point_rows or not structures:
            points, point_lines = _read_points(rd, sections["points"])
        else:
            points, point_lines = [], {}
    else:
        points, point_lines = [], {}
    by_id = {p.id: p for p in points}
    for p in points:
        if p.attachment == "body" and p.body not in body_ids:
            raise rd.error(point_lines[p.id], f"point {p.id} is on body {p.body}, which is not in the BODIES "
                                              f"section (IDs {', '.join(str(b) for b in body_ids) or 'none'}). "
                                              "Suggested fix: add the body or correct the attachment.")
    lines = (_read_lines(rd, sections["lines"], types, by_id, rod_ids)
             if "lines" in sections and (sections["lines"][3] or not structures)
             and (_table(rd, sections["lines"])[1] or not structures) else [])
    failures = _read_failures(rd, sections["failure"], by_id, rod_ids, lines) if "failure" in sections else []
    loads = (_read_external_loads(rd, sections["external_loads"], by_id, body_ids, rod_ids)
             if "external_loads" in sections else [])
    if "syrope_wc" in sections:
        names, rows = _table(rd, sections["syrope_wc"])
        _check_column_order(rd, sections["syrope_wc"], names, "syrope_wc")
        for lineno, t in rows:
            rd.columns(lineno, t, 4, "SYROPE WORKING CURVES", "LineType WCType k1 k2")
            if t[0] not in types:
                raise rd.error(lineno, f"SYROPE WORKING CURVES names line type {t[0]!r}, which is not in LINE TYPES."
                                       f"{suggest(t[0], types)} Suggested fix: use a line type's name.")
            if t[1].upper() not in ("LINEAR", "QUADRATIC", "EXP"):
                raise rd.error(lineno, f"SYROPE WORKING CURVES WCType must be LINEAR, QUADRATIC or EXP, got {t[1]!r}. "
                                       "Suggested fix: use one of MoorDyn's Syrope working curves.")
            k1, k2 = (rd.number(lineno, v, f"SYROPE WORKING CURVES {c}", "-") for v, c in zip(t[2:4], ("k1", "k2")))
            types[t[0]] = dataclasses.replace(types[t[0]], syrope=(t[1].upper(), k1, k2))
    for name, lineno in rd.syrope_types.items():
        if types[name].syrope is None:
            raise rd.error(lineno, f"line type {name!r} is a Syrope rope whose file is its original working curve, "
                                   "but no SYROPE WORKING CURVES row gives its working curve. Suggested fix: add a row "
                                   f"'{name} LINEAR k1 k2' to a SYROPE WORKING CURVES section.")
    syrope_ic = {}
    if "syrope_ic" in sections:
        names, rows = _table(rd, sections["syrope_ic"])
        _check_column_order(rd, sections["syrope_ic"], names, "syrope_ic")
        for lineno, t in rows:
            rd.columns(lineno, t, 3, "SYROPE IC", "Line(s) Tmax0 Tmean0")
            tmax, tmean = (rd.number(lineno, v, f"SYROPE IC {c}", "N") for v, c in zip(t[1:3], ("Tmax0", "Tmean0")))
            for token in t[0].split(","):
                syrope_ic[_integer(rd, lineno, token, "SYROPE IC line")] = (tmax, tmean)
    options = _read_options(rd, sections["options"]) if "options" in sections else {}
    if echo is not None:
        options.setdefault("Echo", echo)
    outputs = _read_outputs(sections["outputs"]) if "outputs" in sections else ()
    lowered = [n.lower() for n in _table(rd, sections["line_types"])[0]] if "line_types" in sections else []
    line_names = _table(rd, sections["lines"])[0] if "lines" in sections else []
    v1 = (rd.v1_counts or ("ei" not in lowered and ("can" in lowered or "cdn" in lowered or len(lowered) == 9))
          or (len(line_names) > 2 and "len" in line_names[2].lower()))  # v1 LINE PROPERTIES columns
    result = MoorDynInput(path, "\n".join(title), types, tuple(points), tuple(lines), options, outputs,
                          rod_types=rod_types, bodies=tuple(bodies), rods=tuple(rods), failures=tuple(failures),
                          layout="v1" if v1 else "v2", external_loads=tuple(loads),
                          syrope_ic=syrope_ic)
    given = result.given_water_depth
    if given is not None:
        for p in points:
            if p.attachment in ("fixed", "free", "vessel") and p.position[2] < -given * (1.0 + 1e-9):
                raise rd.error(point_lines[p.id], f"point {p.id} Z must be >= -WtrDpth = {-given:g} m, "
                                                  f"got {p.position[2]:g} m (below the seabed; MoorDyn would "
                                                  f"move the seabed down to it with a warning). Suggested fix: "
                                                  f"raise the point, set WtrDpth to at least "
                                                  f"{-p.position[2]:g} m, or remove the WtrDpth line (the "
                                                  "depth is then that of the deepest point, as in MoorDyn).")
        source = "WtrDpth"
    else:
        globals_ = [p for p in points if p.attachment in ("fixed", "free", "vessel")]
        if globals_:
            deepest = min(globals_, key=lambda p: p.position[2])
            source = f"no WtrDpth: the depth of the deepest point, point {deepest.id}, as in MoorDyn"
        else:
            source = "no WtrDpth: the depth of the deepest rod end, as in MoorDyn"
    rd.notes.extend(_option_notes(rd, options, result.water_depth, source))
    return dataclasses.replace(result, notes=tuple(rd.notes))


def is_moordyn_file(path) -> bool:
    """Cheap sniff: is ``path`` a MoorDyn text input file?

    True when the file is text (no NUL bytes) and one of its first 40 lines is a MoorDyn
    section header (a line of dashes naming LINE TYPES, LINE DICTIONARY, POINTS, ...), or one
    of its first 5 lines mentions ``MoorDyn``. False for YAML/JSON case files, MoorDyn's binary
    ``.ic`` state files, directories and missing files.
    """
    path = Path(path)
    if path.suffix.lower() in (".yaml", ".yml", ".json", ".nc", ".ic") or not path.is_file():
        return False
    try:
        with path.open("rb") as handle:
            head = handle.read(8192)
    except OSError:
        return False
    if b"\x00" in head:
        return False
    lines = head.decode("utf-8", errors="replace").splitlines()[:40]
    if any("---" in ln and _section_kind(ln) in ("line_types", "points", "lines") for ln in lines):
        return True
    return any("MoorDyn" in ln and not ln.lstrip().startswith("#") for ln in lines[:5])


def check_water_kinematics(md: MoorDynInput, what: str = "a dynamic run") -> None:
    """Refuse a time-domain run of a deck that asks MoorDyn for wave or current kinematics.

    Non-zero ``WaveKin`` and ``Currents`` make MoorDyn take the water kinematics from its own input files
    (wave elevation series, frequency components, a current profile on a grid) or from a coupled code
    through its API; seacable reads none of them. Statics does not need them (MoorDyn's initial
    conditions are found in still water), so only a dynamic run is refused.

    Raises
    ------
    InputError
        Naming the file, the option and its value, and how to give the sea to seacable instead.
    """
    label = md.path or "MoorDyn file"
    for name, fix in (("WaveKin", "give the waves in a YAML case, environment.waves: regular (height, period) or "
                                  "irregular (spectrum: jonswap, hs, tp, gamma, seed), or set WaveKin to 0 to run "
                                  "the deck in still water"),
                      ("Currents", "give the current in a YAML case (environment.current: speed or depths and "
                                   "speeds), or set Currents to 0 to run the deck without current")):
        value = _lookup(md.options, (name,))
        if value not in (None, 0, 0.0):
            raise InputError(f"{label}: option {name} = {_fmt_value(value)} asks MoorDyn for "
                             f"{'wave' if name == 'WaveKin' else 'current'} kinematics from its own input files or "
                             f"a coupled code, which seacable does not read, so {what} of this file cannot honour "
                             f"it. Suggested fix: {fix}.")


@dataclass(frozen=True)
class MoorDynCase:
    """A MoorDyn input file as a case: the file's network and how to run it.

    What :func:`seacable.load_case` returns for a MoorDyn file and :func:`seacable.run` runs
    (``mooring_static`` without ``duration``, ``mooring_dynamic`` with it). Build one with
    :func:`load_moordyn_case`; :meth:`with_run` sets the run.

    Parameters
    ----------
    data
        The file, as read by :func:`read_moordyn`.
    name
        Short name, used for output files (default: the file's stem).
    duration
        Simulated time after the static equilibrium; None for statics only. [s]
    motion
        Vessel-point motion (:mod:`seacable.mooring.motion`); None holds the vessel points still.
    time_step
        Newmark time step. [s]
    output_interval
        Time between stored states. [s]
    spectral_radius
        Generalised-alpha amplification per step of the modes far above 1 / time_step (1: Newmark's
        average acceleration, no numerical damping; :func:`seacable.mooring.solver.generalized_alpha`). [-]
    """

    data: MoorDynInput
    name: str = "moordyn"
    duration: float | None = None
    motion: object = None
    time_step: float = 0.1
    output_interval: float = 0.5
    spectral_radius: float = 1.0

    @property
    def path(self) -> str | None:
        """The file's path (None for text)."""
        return self.data.path

    @property
    def analysis_type(self) -> str:
        """``'mooring_static'`` or, with a ``duration``, ``'mooring_dynamic'``; ``system_static`` and
        ``system_dynamic`` for a deck with bodies, rods or points on a body (:meth:`system_case`)."""
        kind = "system" if self.has_structures else "mooring"
        return f"{kind}_static" if self.duration is None else f"{kind}_dynamic"

    def with_run(self, *, duration=None, motion=None, time_step=None, output_interval=None,
                 spectral_radius=None) -> MoorDynCase:
        """The same file with a run set (each argument None keeps the current value).

        Raises
        ------
        InputError
            A duration, time step or output interval that is not a positive finite number of
            seconds, a motion without a duration, an output interval shorter than the step, or a
            spectral radius outside [0, 1].
        """
        rho = self.spectral_radius if spectral_radius is None else _validate.in_range(
            "spectral radius", spectral_radius, 0.0, 1.0, "", "use 1 (average acceleration, the default) or 0.8")
        duration = self.duration if duration is None else _validate.positive(
            "duration", duration, "s", "give the simulated time in seconds, e.g. 100")
        time_step = self.time_step if time_step is None else _validate.positive(
            "time step", time_step, "s", "give the Newmark time step in seconds, e.g. 0.1")
        interval = self.output_interval if output_interval is None else _validate.positive(
            "output interval", output_interval, "s", "give the time between stored states, e.g. 0.5")
        motion = self.motion if motion is None else motion
        if motion is not None and duration is None:
            raise InputError("a vessel motion needs a duration (s): the length of the run. Suggested fix: "
                             "give the duration too (--duration on the command line).")
        if interval < time_step:
            raise InputError(f"output interval must be >= the time step {time_step:g} s, got {interval:g} s. "
                             "Suggested fix: store every step at most (output interval = time step).")
        return dataclasses.replace(self, duration=duration, motion=motion, time_step=time_step,
                                   output_interval=interval, spectral_radius=rho)

    @property
    def has_structures(self) -> bool:
        """True when the deck has bodies, rods or points on a body or turbine: a system analysis runs it."""
        md = self.data
        return bool(md.bodies or md.rods or any(p.attachment in ("body", "turbine") for p in md.points))

    def system(self, *, turbine_positions: dict | None = None):
        """The deck as ``(MooringSystem, Environment)`` (:func:`moordyn_system`), for the system analyses."""
        return moordyn_system(self.data, turbine_positions=turbine_positions)

    def system_case(self):
        """The deck as a :class:`~seacable.system.case.SystemCase`: ``system_static``, or with a duration
        ``system_dynamic`` with the deck's ``FAILURE`` rows (what :func:`seacable.run` runs for a deck with
        bodies, rods or points on a body), started from the static equilibrium (``start: auto``: held where
        the deck puts the free bodies, with a warning, when that is not found), or with the free bodies
        held there when a free body has no line nor horizontal restoring (no static equilibrium; MoorDyn
        starts them so).

        Raises
        ------
        InputError
            What :func:`moordyn_system` refuses; a vessel ``motion`` (a deck with structures takes its
            motions in a YAML system case: ``body_motions``, ``point_motions``).
        """
        from ..system.case import SystemCase, SystemStaticAnalysis
        from ..system.dynamics import SystemDynamicAnalysis

        label = self.data.path or "MoorDyn file"
        if self.motion is not None:
            raise InputError(f"{label}: a vessel motion for a deck with bodies, rods or points on a body is not "
                             "taken from the command line. Suggested fix: write the system as a YAML case "
                             "(seacable.io.dump_case(case.system_case())) and give 'body_motions' or "
                             "'point_motions' in its system_dynamic analysis.")
        if self.duration is not None and self.spectral_radius != 1.0:
            raise InputError(f"{label}: spectral radius {self.spectral_radius:g}: a deck with bodies, rods or points "
                             "on a body runs as a mooring system, whose dynamics step by average acceleration only "
                             "(spectral radius 1). Suggested fix: leave out the spectral radius (--spectral-radius) "
                             "for this deck.")
        system, environment = self.system()
        if self.duration is None:
            analysis = SystemStaticAnalysis(max_strain=_DECK_MAX_STRAIN)
        else:
            from ..system.run import check_bodies_without_lines

            check_water_kinematics(self.data, "a system_dynamic run")

            try:  # a free body nothing holds has no static start: released where the deck puts it, as MoorDyn
                check_bodies_without_lines(system)
                start = "auto"  # the static start, or held where the deck puts the bodies when none is found
            except InputError:
                start = "held"
            analysis = SystemDynamicAnalysis(duration=self.duration, time_step=self.time_step,
                                             output_interval=self.output_interval,
                                             failures=_line_failures(self.data), start=start)
        return SystemCase(name=self.name, description=f"MoorDyn file {label}", environment=environment,
                          points=system.points, bodies=system.bodies, lines=system.lines, analysis=analysis)

    def describe(self) -> str:
        """One line for ``seacable validate``."""
        md = self.data
        segments = sum(ln.n_segments for ln in md.lines)
        length = sum(ln.length for ln in md.lines)
        depth = md.water_depth
        where = "no seabed" if depth is None else f"depth {depth:g} m"
        return (f"MoorDyn network, {self.analysis_type} analysis: {len(md.lines)} line(s), {len(md.points)} "
                f"point(s), {segments} segment(s), line length {length:g} m, {where}")


#: the largest line strain the statics of a MoorDyn deck accept: MoorDyn has no limit, and its test decks
#: model springs as lines stretched to 10 times their length (stability/spring.txt); above 10 % a warning says so
_DECK_MAX_STRAIN = 20.0


def _line_failures(md: MoorDynInput) -> list:
    """The deck's ``FAILURE`` rows as :class:`~seacable.system.dynamics.LineFailure` items (one per line end)."""
    from ..system.dynamics import LineFailure

    out = []
    for f in md.failures:
        for line_id in f.lines:
            line = next((ln for ln in md.lines if ln.id == line_id), None)
            if line is None:
                raise InputError(f"{md.path or 'MoorDyn file'}: FAILURE {f.id} names line {line_id}, which the "
                                 "LINES section does not define. Suggested fix: name a line of the deck.")
            if isinstance(f.attachment, tuple):
                end = "a" if line.rod_a == f.attachment else "b" if line.rod_b == f.attachment else None
            else:
                end = "a" if line.point_a == f.attachment else "b" if line.point_b == f.attachment else None
            if end is None:
                raise InputError(f"{md.path or 'MoorDyn file'}: FAILURE {f.id}: line {line_id} does not end at "
                                 f"attachment {f.attachment}. Suggested fix: name the point (or rod end) the line "
                                 "ends at.")
            # a 0 disables that trigger; both 0 breaks the line at the start (MoorDyn-F)
            out.append(LineFailure(line=f"line{line_id}", end=end,
                                   time=f.time if f.time > 0 or not f.tension > 0 else None,
                                   tension=f.tension if f.tension > 0 else None))
    return out


def load_moordyn_case(path, *, name=None) -> MoorDynCase:
    """Read a MoorDyn input file (:func:`read_moordyn`) as a :class:`MoorDynCase` (statics).

    Parameters
    ----------
    path : str or pathlib.Path
        The MoorDyn file.
    name : str, optional
        The case name (default: the file's stem).
    """
    data = read_moordyn(path)
    return MoorDynCase(data, name=name or Path(path).stem or "moordyn")


# --------------------------------------------------------------------------- the deck as a MooringSystem

def _rotation(roll, pitch, yaw) -> np.ndarray:
    """``Rz(yaw) Ry(pitch) Rx(roll)`` (the system model's convention, MoorDyn's and MoorPy's)."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw),
                              math.sin(yaw))
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1.0]])
    ry = np.array([[cp, 0, sp], [0, 1.0, 0], [-sp, 0, cp]])
    rx = np.array([[1.0, 0, 0], [0, cr, -sr], [0, sr, cr]])
    return rz @ ry @ rx


class _Rigid:
    """Mass, inertia, buoyancy, waterplane and hydrodynamics gathered on one rigid body, in body axes."""

    def __init__(self):
        self.mass, self.first = 0.0, np.zeros(3)  # sum m, sum m r
        self.inertia = np.zeros((3, 3))  # about the reference point, body axes
        self.volume, self.vfirst = 0.0, np.zeros(3)
        self.awp, self.iwp = 0.0, np.zeros(2)
        self.added = np.zeros((6, 6))  # about the reference point, body axes
        self.drag = np.zeros(3)  # translational, body axes

    def add_mass(self, m, c, inertia_cg):
        c = np.asarray(c, float)
        self.mass += m
        self.first += m * c
        self.inertia += np.asarray(inertia_cg, float) + m * (c @ c * np.eye(3) - np.outer(c, c))

    def add_volume(self, v, c):
        self.volume += v
        self.vfirst += v * np.asarray(c, float)

    def cg(self):
        return self.first / self.mass if self.mass > 0 else np.zeros(3)

    def cb(self):
        return self.vfirst / self.volume if self.volume > 0 else np.zeros(3)

    def inertia_cg(self):
        c = self.cg()
        return self.inertia - self.mass * (c @ c * np.eye(3) - np.outer(c, c))


def _added_about_reference(a3, r) -> np.ndarray:
    """6x6 added mass about the reference point of a 3x3 added mass ``a3`` at ``r`` (body axes)."""
    S = np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])
    return np.block([[a3, -a3 @ S], [S @ a3, -S @ a3 @ S]])


def _add_rod(rigid: _Rigid, rod: MoorDynRod, rt: MoorDynRodType, a_body, b_body, ref, R, rho):
    """Add a rod with ends ``a_body``/``b_body`` (body axes) to a body at global ``ref`` with rotation ``R``.

    Mass ``m L`` at the middle, a slender cylinder's inertia; the displaced volume of the part below
    z = 0 at this pose, at its centroid (MoorDyn's rods are buoyant over their submerged length);
    a rod piercing the surface adds its cross-section ``pi d^2 / 4 / |cos(tilt)|`` to the waterplane
    and its second moments. Added mass ``Ca rho A`` per metre normal to the rod (and the end term
    ``CaEnd rho pi d^3 / 12`` along its axis, at the middle of the submerged part) is integrated
    along the submerged part into the 6x6 added mass about the reference point (a point ``r`` of
    the rod moves at ``v + w x r``, so its added mass ``a`` adds ``[[a, -a S], [S a, -S a S]]``,
    ``S = skew(r)``); drag ``rho Cd d L / 2`` normal to it goes onto the translations (``CdEnd``
    along the axis).
    """
    a, b = np.asarray(a_body, float), np.asarray(b_body, float)
    length = float(np.linalg.norm(b - a))
    u = (b - a) / length if length > 0 else np.array([0.0, 0.0, 1.0])
    area = math.pi * rt.diameter**2 / 4
    m = rt.mass_per_length * length
    i_ax, i_n = m * rt.diameter**2 / 8, m * (length**2 / 12 + rt.diameter**2 / 16)
    rigid.add_mass(m, (a + b) / 2, i_n * np.eye(3) + (i_ax - i_n) * np.outer(u, u))
    ga, gb = ref + R @ a, ref + R @ b
    za, zb = ga[2], gb[2]
    if za <= 0 and zb <= 0:
        frac_lo, frac_hi = 0.0, 1.0
    elif za > 0 and zb > 0:
        frac_lo = frac_hi = 0.0
    else:  # pierces the surface
        f = za / (za - zb)
        frac_lo, frac_hi = (f, 1.0) if za > 0 else (0.0, f)
        cos_tilt = abs((gb - ga)[2]) / length
        awp = area / max(cos_tilt, 1e-6)
        cut = a + f * (b - a)
        rigid.awp += awp
        rigid.iwp += awp * np.array([cut[1] ** 2, cut[0] ** 2]) + math.pi * rt.diameter**4 / 64
    sub = (frac_hi - frac_lo) * length
    if sub > 0:
        rigid.add_volume(area * sub, a + (frac_lo + frac_hi) / 2 * (b - a))
        normal = np.eye(3) - np.outer(u, u)
        per_length = rt.added_mass_normal * rho * area * normal
        # 3-point Gauss-Legendre along the submerged part: exact for the quadratic -S a S
        for x, wt in zip((-math.sqrt(0.6), 0.0, math.sqrt(0.6)), (5 / 9, 8 / 9, 5 / 9)):
            frac = frac_lo + (frac_hi - frac_lo) * (1 + x) / 2
            rigid.added += _added_about_reference(per_length * sub * wt / 2, a + frac * (b - a))
        end = rt.added_mass_end * rho * (math.pi * rt.diameter**3 / 12) * np.outer(u, u)
        rigid.added += _added_about_reference(end, a + (frac_lo + frac_hi) / 2 * (b - a))
        rigid.drag += np.diag(0.5 * rho * rt.drag_normal * rt.diameter * sub * normal) + \
            0.5 * rho * rt.drag_end * area * u**2


def _turbine_pose(label, n, value) -> tuple[float, ...]:
    """A ``turbine_positions`` entry as six floats (x, y, z [m], roll, pitch, yaw [rad])."""
    v = np.asarray(value, float).ravel()
    if v.size not in (3, 6) or not np.all(np.isfinite(v)):
        raise InputError(f"{label}: turbine_positions[{n}] must be (x, y, z) [m] or (x, y, z, roll, pitch, yaw) "
                         f"[m, rad], got {value!r}. Suggested fix: give the platform reference point of turbine {n} "
                         "(FAST.Farm's WT_X, WT_Y, WT_Z plus ElastoDyn's PtfmSurge, PtfmSway, PtfmHeave).")
    return tuple(float(x) for x in np.r_[v, np.zeros(6 - v.size)])


def _turbine_shift(label, poses, n) -> tuple[float, float, float]:
    """The translation of turbine ``n`` for a body or rod on it (refused if the turbine is rotated)."""
    pose = poses.get(n, (0.0,) * 6)
    if any(pose[3:]):
        raise InputError(f"{label}: a body or rod is on turbine {n}, whose turbine_positions entry rotates it "
                         f"({pose[3:]} rad); seacable moves bodies and rods on a turbine by its position only. "
                         f"Suggested fix: give turbine_positions[{n}] as (x, y, z).")
    return pose[:3]


def moordyn_system(md: MoorDynInput, *, turbine_positions: dict | None = None):
    """The deck as a :class:`~seacable.system.model.MooringSystem` and its :class:`~seacable.environment.Environment`.

    Mapping (names: ``point<ID>``, ``body<ID>``, ``rod<ID>``, ``turbine<N>``, ``line<ID>``):

    - points: Fixed -> ``fixed``; Free/Connect -> ``free`` (mass, volume, C_D A, added mass
      ``Ca rho V``); Vessel/Coupled -> ``coupled``; BodyN -> on ``body<N>`` (its mass and volume
      lumped into the body's, as MoorDyn); TurbineN -> on the
      prescribed body ``turbine<N>`` (FAST.Farm places turbine N; the deck does not say where:
      ``turbine_positions`` ``{N: (x, y, z)}`` or ``{N: (x, y, z, roll, pitch, yaw)}`` [m, rad], the
      platform reference point of turbine N: FAST.Farm's ``WT_X, WT_Y, WT_Z`` plus ElastoDyn's
      initial platform displacements; default the origin, with a SeacableWarning). Bodies and rods
      on a turbine are moved with its position (a rotated turbine carries points only).
    - bodies: free/fixed/coupled -> ``free``/``fixed``/``prescribed`` (CoupledPinned: prescribed
      and ``pinned``). Mass, centre of gravity and inertia as written; MoorDyn's body volume acts
      at the reference point and bodies have no waterplane (buoyancy only). ``Ca rho V`` on the
      translations of ``added_mass``; ``rho CdA / 2`` on the diagonal of ``quadratic_damping``.
    - rods: a rod on body N (``BodyN``, and ``BodyNPinned``, taken as rigidly fixed there: the
      data model has no joint on a moving body, a SeacableWarning says so) adds its mass,
      inertia, submerged volume, waterplane and hydrodynamics to ``body<N>``; any other rod
      becomes its own body ``rod<ID>`` (Fixed -> fixed, Coupled -> prescribed, Free -> free,
      Pinned -> free and ``pinned``, CoupledPinned -> prescribed and ``pinned``) with its body
      z axis along the rod from end A (its reference point) to end B. Rod ends a line attaches
      to (``R1A``) become points ``rod<ID>_a``/``rod<ID>_b`` on that body. Buoyancy is the
      submerged part at the deck's pose, a surface-piercing rod adds a waterplane.
    - line types: d, m, EA, EI, Cd, Ca, CdAx, CaAx; a nonlinear EA table goes to
      ``LineType.tension_strain`` (``axial_stiffness`` is its secant at the table's end; the
      statics of :mod:`seacable.system.statics` use that constant EA, a SeacableWarning says so);
      a viscoelastic ``EA_s|EA_d`` to ``axial_stiffness = EA_s`` and ``dynamic_axial_stiffness``.
      The axial damping BA is not in the data model (a dynamics setting).
    - environment (a :class:`~seacable.environment.SystemEnvironment`): WtrDnsty, g, WtrDpth (or
      the deepest point, as MoorDyn), FrictionCoefficient. ``g = 0`` (no weight nor buoyancy) and
      ``WtrDnsty = 0`` (no buoyancy nor hydrodynamics) are kept: MoorDyn's own tests switch gravity
      or buoyancy off so. MoorDyn's soft seabed (kBot) becomes a rigid one.
    - a deck without lines (rods or bodies alone), or with bodies no line ends on, is a system all
      the same (the dynamics run it; the statics need each free body restored).
    - ``FAILURE`` rows stay in ``md.failures`` (a dynamics input).

    Raises
    ------
    InputError
        A deck the data model refuses (a line end on a point that does not exist, ...).
    """
    from ..environment import Seabed, SystemEnvironment
    from ..line import Line, LineType
    from ..system.model import Body, MooringSystem, SystemLine, SystemPoint

    label = md.path or "MoorDyn file"
    rho, g = md.water_density, md.gravity
    turbine_positions = {int(n): _turbine_pose(label, n, v) for n, v in (turbine_positions or {}).items()}
    unplaced: list[int] = []
    bodies_in = {b.id: b for b in md.bodies}
    rods_in = {r.id: r for r in md.rods}
    rigid: dict[str, _Rigid] = {}
    spec: dict[str, dict] = {}
    points: dict[str, SystemPoint] = {}

    def turbine(n):
        name = f"turbine{n}"
        if name not in spec:
            if n not in turbine_positions:
                unplaced.append(n)
            spec[name] = dict(kind="prescribed", position=turbine_positions.get(n, (0.0,) * 6), pinned=False)
            rigid[name] = _Rigid()
        return name

    for b in md.bodies:
        name = f"body{b.id}"
        kind = {"free": "free", "fixed": "fixed", "coupled": "prescribed", "turbine": "prescribed"}[b.attachment]
        position = b.position
        if b.attachment == "turbine":
            tx, ty, tz = _turbine_shift(label, turbine_positions, b.turbine)
            position = (b.position[0] + tx, b.position[1] + ty, b.position[2] + tz, *b.position[3:])
        spec[name] = dict(kind=kind, position=position, pinned=b.pinned, drag=b.drag_area, ca=b.added_mass_coefficient,
                          volume=b.volume)
        r = _Rigid()
        r.add_mass(b.mass, b.center_of_gravity, np.diag(b.inertia))
        r.add_volume(b.volume, (0.0, 0.0, 0.0))  # MoorDyn: the body's buoyancy acts at its reference point
        rigid[name] = r

    rod_end_points: dict[tuple[int, str], str] = {}
    pinned_on_body = []
    for rod in md.rods:
        rt = md.rod_types[rod.rod_type]
        if rod.attachment == "body":
            host = f"body{rod.body}"
            b = bodies_in[rod.body]
            ref, R = np.asarray(spec[host]["position"][:3]), _rotation(*spec[host]["position"][3:])
            _add_rod(rigid[host], rod, rt, rod.end_a, rod.end_b, ref, R, rho)
            if rod.pinned:
                pinned_on_body.append(rod.id)
            for side, end in (("A", rod.end_a), ("B", rod.end_b)):
                rod_end_points[(rod.id, side)] = (host, end)
            del b
            continue
        name = f"rod{rod.id}"
        a, bvec = np.asarray(rod.end_a, float), np.asarray(rod.end_b, float)
        if rod.attachment == "turbine":
            a = a + np.asarray(_turbine_shift(label, turbine_positions, rod.turbine))
            bvec = bvec + np.asarray(_turbine_shift(label, turbine_positions, rod.turbine))
            turbine(rod.turbine)
        axis = bvec - a
        length = float(np.linalg.norm(axis))
        u = axis / length if length > 0 else np.array([0.0, 0.0, 1.0])
        pitch, yaw = math.acos(max(-1.0, min(1.0, u[2]))), math.atan2(u[1], u[0])
        kind = {"free": "free", "fixed": "fixed", "coupled": "prescribed", "turbine": "prescribed"}[rod.attachment]
        spec[name] = dict(kind=kind, position=(*a, 0.0, pitch, yaw), pinned=rod.pinned)
        r = _Rigid()
        _add_rod(r, rod, rt, (0.0, 0.0, 0.0), (0.0, 0.0, length), a, _rotation(0.0, pitch, yaw), rho)
        rigid[name] = r
        rod_end_points[(rod.id, "A")] = (name, (0.0, 0.0, 0.0))
        rod_end_points[(rod.id, "B")] = (name, (0.0, 0.0, length))
    for p in md.points:
        if p.attachment == "turbine":
            turbine(p.turbine)
    if unplaced:
        ns = ", ".join(map(str, sorted(unplaced)))
        warnings.warn(f"{label}: points or rods are on turbine(s) {ns} (FAST.Farm's TurbineN), whose positions are "
                      "set in the FAST.Farm input, not in this deck; seacable puts their reference points at the "
                      f"origin. Suggested fix: give turbine_positions={{{sorted(unplaced)[0]}: (x, y, z), ...}}.",
                      SeacableWarning, stacklevel=2)
    free_pinned = sorted(n for n, sp in spec.items() if sp["pinned"] and sp["kind"] == "free")
    if free_pinned:
        warnings.warn(f"{label}: {', '.join(free_pinned)} pinned (MoorDyn Pinned: end A held, rotation free) is "
                      "recorded as Body.pinned; an analysis that does not hold a pinned body's reference point "
                      "treats it as free.", SeacableWarning, stacklevel=2)
    if pinned_on_body:
        warnings.warn(f"{label}: rod(s) {', '.join(map(str, pinned_on_body))} are pinned to a body (BodyNPinned); "
                      "seacable's system model has no joint on a moving body and fixes them rigidly to it (their "
                      "own rotation is not free).", SeacableWarning, stacklevel=2)

    for p in md.points:
        common = dict(mass=p.mass, volume=p.volume, drag_area=p.drag_area,
                      added_mass=p.added_mass_coefficient * rho * p.volume)
        if p.attachment == "body":
            # MoorDyn lumps a point's mass and volume into the body it is on: so does the conversion (the
            # body's mass, centre of gravity, inertia and buoyancy; the dynamics need the body's own mass)
            rigid[f"body{p.body}"].add_mass(p.mass, p.position, np.zeros((3, 3)))
            rigid[f"body{p.body}"].add_volume(p.volume, p.position)
            common.update(mass=0.0, volume=0.0)
            points[f"point{p.id}"] = SystemPoint(kind="body", body=f"body{p.body}", position=p.position, **common)
        elif p.attachment == "turbine":
            points[f"point{p.id}"] = SystemPoint(kind="body", body=turbine(p.turbine), position=p.position, **common)
        else:
            kind = {"fixed": "fixed", "free": "free", "vessel": "coupled"}[p.attachment]
            points[f"point{p.id}"] = SystemPoint(kind=kind, position=p.position, **common)

    def end(point_id, rod_end):
        if rod_end is None:
            return f"point{point_id}"
        name = f"rod{rod_end[0]}_{rod_end[1].lower()}"
        if name not in points:
            host, where = rod_end_points[rod_end]
            points[name] = SystemPoint(kind="body", body=host, position=tuple(float(v) for v in where))
        return name

    types, tabled = {}, []
    for lt in md.line_types.values():
        dynamic = None
        if lt.dynamic_stiffness is not None:
            dynamic = (lt.dynamic_stiffness[0], lt.dynamic_stiffness[1] if len(lt.dynamic_stiffness) > 1 else 0.0)
        if lt.syrope is not None:
            tabled.append(lt.name)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", SeacableWarning)  # MoorDyn's own Cd values, e.g. chain 2.4+
            types[lt.name] = LineType(
                name=lt.name, diameter=lt.diameter, mass_per_length=lt.mass_per_length,
                axial_stiffness=lt.axial_stiffness, bending_stiffness=lt.bending_stiffness,
                drag_normal=lt.drag_normal, drag_tangential=lt.drag_tangential,
                added_mass_normal=lt.added_mass_normal, added_mass_tangential=lt.added_mass_tangential,
                tension_strain=lt.tension_strain, dynamic_axial_stiffness=dynamic,
                dynamic_axial_damping=lt.dynamic_damping)
    if tabled:
        warnings.warn(f"{label}: Syrope line type(s) {', '.join(tabled)}: the statics (system_static) use the "
                      "original working curve as the rope's strain-tension table; the working curves after a load "
                      "history (SYROPE IC) are followed only when the deck, having no bodies or rods, runs as a "
                      "line network (its time-domain run).",
                      SeacableWarning, stacklevel=2)
    lines = {}
    for ln in md.lines:
        lines[f"line{ln.id}"] = SystemLine(line=Line.single(types[ln.line_type], ln.length),
                                           end_a=end(ln.point_a, ln.rod_a), end_b=end(ln.point_b, ln.rod_b),
                                           n_elements=ln.n_segments)

    body_force = {name: np.zeros(6) for name in spec}
    body_lin = {name: np.zeros(6) for name in spec}
    body_quad = {name: np.zeros(6) for name in spec}
    for load in md.external_loads:
        if load.kind == "point":
            name = f"point{load.target}"
            p = points[name]
            points[name] = p.model_copy(update={"external_force": tuple(np.add(p.external_force, load.force))})
            if any(load.linear_damping) or any(load.quadratic_damping):
                warnings.warn(f"{label}: external load {load.id} damps point {load.target}; the system model has no "
                              "damping on points (it is left out).", SeacableWarning, stacklevel=2)
            continue
        name = f"body{load.target}" if load.kind == "body" else f"rod{load.target}"
        if name not in spec:  # a rod merged into its body
            name = f"body{rods_in[load.target].body}"
        R = _rotation(*spec[name]["position"][3:])
        force = np.asarray(load.force, float)
        if load.frame == "L":  # body axes at the deck's pose; the system model's force is global
            force = R @ force
            warnings.warn(f"{label}: external load {load.id} on {name} is in body axes (CSys L); seacable applies it "
                          "as the constant global force it is at the deck's pose.", SeacableWarning, stacklevel=2)
        body_force[name][:3] += force
        lin, quad = load.linear_damping, load.quadratic_damping
        if len(lin) == 2:  # a rod: transverse and axial, along its axis (body z for a rod body)
            lin, quad = (lin[0], lin[0], lin[1]), (quad[0], quad[0], quad[1])
        body_lin[name][:3] += lin
        body_quad[name][:3] += quad

    bodies = {}
    for name, s in spec.items():
        r = rigid[name]
        drag = body_quad[name].copy()
        added = r.added.copy()
        if "drag" in s:
            drag += 0.5 * rho * np.asarray(s["drag"])
            # MoorDyn: the body's Ca acts on its own volume (its rods carry their own added mass)
            added[:3, :3] += np.diag(np.broadcast_to(np.asarray(s["ca"], float) * rho * s["volume"], 3))
        drag[:3] += r.drag
        inertia = r.inertia_cg()
        bodies[name] = Body(
            kind=s["kind"], position=tuple(float(v) for v in s["position"]), mass=r.mass,
            center_of_gravity=tuple(float(v) for v in r.cg()),
            inertia=tuple(float(max(v, 0.0)) for v in np.diag(inertia)), volume=r.volume,
            center_of_buoyancy=tuple(float(v) for v in r.cb()), waterplane_area=r.awp,
            waterplane_moments=tuple(float(v) for v in r.iwp),
            added_mass=tuple(tuple(float(v) for v in row) for row in added) if added.any() else None,
            quadratic_damping=tuple(tuple(float(v) for v in row) for row in np.diag(drag)) if drag.any() else None,
            linear_damping=(tuple(tuple(float(v) for v in row) for row in np.diag(body_lin[name]))
                            if body_lin[name].any() else None),
            external_force=tuple(float(v) for v in body_force[name]), pinned=s["pinned"])
    try:
        system = MooringSystem(points=points, bodies=bodies, lines=lines)
    except ValidationError as exc:  # say which deck
        raise InputError(f"{label}: the deck does not make a seacable mooring system: "
                         f"{format_validation_error(exc)}") from None
    except InputError as exc:
        raise InputError(f"{label}: the deck does not make a seacable mooring system: {exc}") from None
    env = SystemEnvironment(water_density=rho, gravity=g, depth=md.water_depth, seabed=Seabed(friction=md.friction))
    return system, env

"""The system analyses of a case (``system_static``, ``system_offsets``) as Datasets.

Each analysis solves the equilibrium of the system (:func:`seacable.system.statics.solve_equilibrium`)
in its intact condition and, when the analysis names ``damaged_lines``, in its damaged condition (the
same system without those lines), and reports both along a ``condition`` dimension. Lines, bodies and
points are dimensions (``line``, ``body``, ``point``) whose coordinates hold their names; a line removed
in the damaged condition has NaN there, and ``line_present`` says which lines each condition has.

Which statics: lines of one homogeneous catenary and the FE statics for the rest
(:func:`seacable.system.statics.solve_equilibrium`) when the water has no current and the seabed is
flat; otherwise the finite-element statics of the whole system (:mod:`seacable.system.statics.fe`: the
coupled finite-element lines and bodies of ``system_dynamic`` at rest, with the current's drag and the
sloping seabed, their stiffness by central differences of equilibria). The analysis option ``statics``
(``auto``, ``catenary``, ``finite_element``; default ``auto``) forces one; the Dataset's attributes
``statics`` and ``stiffness_method`` say which were used.

Every check that can be made before solving is in :func:`prepare_system_static` and
:func:`prepare_system_offsets`, which ``seacable validate`` runs (one validation path).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
import weakref
from dataclasses import dataclass

import numpy as np

from .._limits import check_run_size
from ..errors import ConvergenceError, InputError, NoSolutionError
from .case import SystemCase, SystemOffsetsAnalysis, SystemStaticAnalysis
from .damaged import is_most_loaded, line_tensions, most_loaded_line
from .model import MooringSystem
from .statics_mode import STIFFNESS_ANALYTIC, STIFFNESS_FD, line_reasons, needs_fe

__all__ = ["DOFS", "REFERENCES", "SystemSetup", "check_bodies_without_lines", "equilibrium_variables",
           "prepare_system_offsets", "prepare_system_static", "run_system_offsets", "run_system_static"]

#: The six degrees of freedom of a body, in the order of its 6x6 matrices.
DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
_POSE = (("body_x", "m", "x of the body's reference point"), ("body_y", "m", "y of the body's reference point"),
         ("body_z", "m", "z of the body's reference point (0 at the still water level)"),
         ("body_roll", "rad", "body roll (rotation about x, applied first)"),
         ("body_pitch", "rad", "body pitch (rotation about y, applied second)"),
         ("body_yaw", "rad", "body yaw (rotation about z, applied last)"))

REFERENCES = (
    "Irvine, H. M. (1981). Cable Structures. MIT Press (the elastic catenary).",
    ("Hall, M. (2023). MoorPy: quasi-static mooring analysis in Python (System, Body, solveEquilibrium, "
     "getCoupledStiffness); the conventions of bodies and points follow it and MoorDyn v2."),
)

#: name -> (dimensions after the leading ones, units, long name) of the per-equilibrium variables
_VARIABLES = {
    "fairlead_tension": (("line",), "N", "tension at end B of the line (fairlead)"),
    "anchor_tension": (("line",), "N", "tension at end A of the line (anchor)"),
    "anchor_horizontal_force": (("line",), "N", "horizontal force of the line on its end A (anchor)"),
    "anchor_vertical_force": (("line",), "N", "vertical force of the line on its end A (anchor), upward positive"),
    "anchor_uplift_angle": (("line",), "rad", "angle of the line's pull on end A (anchor) above the horizontal"),
    "fairlead_angle": (("line",), "rad", "angle of the line at end B (fairlead) below the horizontal"),
    "fairlead_force_x": (("line",), "N", "x force of the line on its end B (fairlead)"),
    "fairlead_force_y": (("line",), "N", "y force of the line on its end B (fairlead)"),
    "fairlead_force_z": (("line",), "N", "z force of the line on its end B (fairlead)"),
    "grounded_length": (("line",), "m", "length of line resting on the seabed"),
    **{name: (("body",), units, long) for name, units, long in _POSE},
    "body_offset_x": (("body",), "m", "x offset of the body's reference point from its given position"),
    "body_offset_y": (("body",), "m", "y offset of the body's reference point from its given position"),
    "body_offset": (("body",), "m", "horizontal offset of the body's reference point from its given position"),
    "point_x": (("point",), "m", "x of the point"),
    "point_y": (("point",), "m", "y of the point"),
    "point_z": (("point",), "m", "z of the point (0 at the still water level)"),
}
#: the dimensions of :data:`_VARIABLES` -> their names (the rows of one block of NaN in equilibrium_variables)
_BY_DIMS = {dims: tuple(n for n, v in _VARIABLES.items() if v[0] == dims)
            for dims in (("line",), ("body",), ("point",))}
_MATRICES = {
    "stiffness": (("body", "dof", "dof2"), "N/m, N/rad, N m/m, N m/rad by block",
                  "mooring stiffness of the free body, lines only, about its reference point (NaN: not free)"),
    "hydrostatic_stiffness": (("body", "dof", "dof2"), "N/m, N/rad, N m/m, N m/rad by block",
                              "hydrostatic stiffness of the free body about its reference point (NaN: not free)"),
}
_PROFILE = {
    "x": (("line", "node"), "m", "x position along the line"),
    "y": (("line", "node"), "m", "y position along the line"),
    "z": (("line", "node"), "m", "elevation along the line (0 at the still water level)"),
    "tension": (("line", "node"), "N", "effective tension along the line"),
}


@dataclass(frozen=True)
class SystemSetup:
    """What the solves of a system analysis need (see :func:`prepare_system_static`).

    ``conditions`` names the conditions (``intact``, ``damaged``) and ``systems`` holds their
    systems (the damaged one None while ``damaged_lines: most_loaded`` waits for the intact equilibrium:
    :mod:`seacable.system.damaged`); ``lines``, ``bodies`` and ``points`` are the names along the result's dimensions
    (those of the intact system). ``headings`` [rad] and ``loads`` [N] are the sweep of
    ``system_offsets`` (empty for ``system_static``).
    """

    case: SystemCase
    conditions: tuple[str, ...]
    systems: tuple[MooringSystem, ...]
    lines: tuple[str, ...]
    bodies: tuple[str, ...]
    points: tuple[str, ...]
    loads: tuple[float, ...] = ()
    headings: tuple[float, ...] = ()
    statics: str = "catenary"
    #: the lines a condition removes (None: intact) -> the start its checks evaluated
    #: (:class:`~seacable.system.statics.solve.CheckedStart`, or None), which its first solve iterates from
    starts: dict = dataclasses.field(default_factory=dict, repr=False, compare=False)

    @property
    def fe(self) -> bool:
        """The finite-element statics are used (a current, a sloping seabed, or asked for)."""
        return self.statics == "finite_element"

    @property
    def free_bodies(self) -> tuple[str, ...]:
        return tuple(n for n in self.bodies if self.systems[0].bodies[n].kind == "free")


STATICS = ("auto", "catenary", "finite_element")


def statics_used(case, statics: str | None = None) -> str:
    """'catenary' or 'finite_element': the statics a system case is solved with.

    ``statics`` (default the analysis option ``statics``, else ``auto``): ``auto`` takes the catenary
    statics unless the system has what they cannot model (a current, a sloping seabed, a line with sections or an
    end held in bending: :func:`seacable.system.statics_mode.needs_fe`); ``catenary`` then refuses those.
    """
    mode = statics if statics is not None else getattr(case.analysis, "statics", "auto")
    if mode not in STATICS:
        raise InputError(f"analysis.statics: '{mode}' is not one of {', '.join(STATICS)}. Suggested fix: use "
                         "'auto' (the catenary statics unless there is a current or a sloping seabed).")
    if mode == "auto":
        mode = "finite_element" if needs_fe(case.environment, case.lines) else "catenary"
        _check_cable_statics(case, mode, "statics: auto, and nothing in the system needs the finite elements (no "
                                         "current, sections or held ends)")
        return mode
    lines = line_reasons(case.lines) if mode == "catenary" else ""
    if lines:
        raise InputError(f"analysis.statics: catenary, but the system has {lines}, which the catenary lines cannot "
                         "carry (no bending, no sections). Suggested fix: use statics: auto (or finite_element).")
    _check_cable_statics(case, mode, "statics: catenary")
    return mode


def _check_cable_statics(case, mode: str, why: str) -> None:
    """A ``system_static`` that asks for the cable checks (a bend clearance above 0 m, a hang-off declination
    range: :mod:`seacable.design.system_cable`) needs the finite-element statics, whose lines bend: on the
    catenary statics the checks would have no curvature and no bends."""
    design = getattr(case.analysis, "design", None)
    if mode != "catenary" or design is None or case.analysis.type != "system_static":
        return
    given = [k for k in ("sag_bend_clearance", "hog_bend_clearance", "hang_off_declination")
             if getattr(design, k) not in (None, 0.0)]
    if given:
        raise InputError(f"analysis.design gives {', '.join(given)}, but the system is solved by the catenary statics "
                         f"({why}), whose lines carry no bending: the cable checks would have no curvature or bends. "
                         "Suggested fix: add 'statics: finite_element' to the analysis.")


def _setup(case, analysis_type: str, statics: str | None = None) -> SystemSetup:
    if not isinstance(case, SystemCase) or case.analysis.type != analysis_type:
        raise InputError(f"{analysis_type} takes a system case (seacable.system.SystemCase with analysis type "
                         f"'{analysis_type}'), got {type(case).__name__}. Suggested fix: seacable.load_case('file.yaml').")
    mode = statics_used(case, statics)
    intact = _condition_system(case)
    named = case.analysis.damaged_lines
    starts = {}
    if is_most_loaded(named):
        # the line is known once the intact condition is solved: each one it may be is checked here
        for line in intact.lines:
            starts[(line,)] = _check_condition(case, _condition_system(case, (line,)), (line,), mode)
        damaged = None
    else:
        damaged = _condition_system(case, tuple(named)) if named else None
    starts[None] = _check_condition(case, intact, None, mode)
    if damaged is not None:
        starts[tuple(named)] = _check_condition(case, damaged, named, mode)
    several = damaged is not None or (is_most_loaded(named) and len(intact.lines) > 0)
    return SystemSetup(case=case, conditions=("intact", "damaged")[:1 + several], systems=(intact, damaged)[:1 + several],
                       lines=tuple(intact.lines), bodies=tuple(intact.bodies), points=tuple(intact.points),
                       statics=mode, starts=starts)


#: id of a case -> {the lines removed (None: none) -> the system}, while the case lives (:func:`_condition_system`)
_SYSTEMS: dict[int, dict] = {}


def _condition_system(case: SystemCase, removed: tuple[str, ...] | None = None) -> MooringSystem:
    """``case.system()`` (``removed`` None) or ``case.damaged_system(removed)``, built once per case object.

    Cases and systems are immutable (frozen models): the checks and the solves of a run (a damaged condition of
    ``damaged_lines: most_loaded`` is checked for each line it may remove, then solved for the one it does), and a
    case run again (a benchmark, a convergence study), solve the same system object, whose assembly the statics
    keep (as the case's YAML is kept: :func:`seacable.results.case_yaml`); they are forgotten with the case.
    """
    return _kept(_SYSTEMS, case, removed,
                 lambda: case.system() if removed is None else case.damaged_system(tuple(removed)))


def _kept(store: dict, case, key, make):
    """``make()``, kept in ``store`` for the case object under ``key`` while the case lives (cases are immutable:
    what is made of one alone is the same each time it is asked for)."""
    ident = id(case)
    kept = store.get(ident)
    if kept is not None and key in kept:
        return kept[key]
    value = make()
    if kept is None:
        try:
            weakref.finalize(case, store.pop, ident, None)
        except TypeError:  # not weakly referenceable: not kept
            return value
        kept = store[ident] = {}
    kept[key] = value
    return value


def _check_condition(case, system: MooringSystem, removed, mode: str):
    """The checks of one condition's system before solving (``removed``: the lines it lacks; None: intact);
    returns the start the catenary statics' checks evaluated (None for the finite-element statics)."""
    _check_free_points(system, "intact" if removed is None else "damaged")
    where = "" if removed is None else f"damaged condition (analysis.damaged_lines {list(removed)} removed): "
    check_bodies_without_lines(system, where)
    if mode == "finite_element":
        _fe_checks(system, case.environment, where, getattr(case.analysis, "static_friction", None))
        return None
    return _start_checks(system, case.environment, where, case.analysis.max_strain)


def _fe_checks(system: MooringSystem, environment, where: str, friction=None) -> None:
    """The finite-element statics' checks without solving: what they cannot model (a pinned body), and the
    finite-element system's geometry (line ends below the seabed, lines that cannot reach: as the dynamics)."""
    from .dynamics import build_system_fe
    from .statics.fe import check_fe

    try:
        check_fe(system, environment, where, friction)
        build_system_fe(system, environment, None)
    except InputError as err:
        raise type(err)(f"{where}{err}" if where and not str(err).startswith(where) else str(err)) from None


def _check_free_points(system: MooringSystem, condition: str) -> None:
    """A free point no line ends at has no equilibrium (it sinks or floats away)."""
    used = {getattr(line, end) for line in system.lines.values() for end in ("end_a", "end_b")}
    for name, point in system.points.items():
        if point.kind == "free" and name not in used:
            raise InputError(f"points.{name}: a free point that no line ends at ({condition} condition) has no "
                             "equilibrium. Suggested fix: end a line there, make it 'fixed', or remove it.")


def check_bodies_without_lines(system: MooringSystem, where: str = "") -> None:
    """Refuse a free body that no line ends on and that nothing holds horizontally: no static equilibrium.

    A body no line ends on is held by its hydrostatics alone. Fixed and prescribed bodies are held
    where they are given; a pinned free body (only its rotations free) is restored by its weight,
    buoyancy and waterplane (the statics' own checks refuse what they cannot restore). A free body
    that is not pinned needs restoring in surge and sway, which only a ``hydrostatic_stiffness``
    matrix (positive surge and sway terms) gives: without it the body has no equilibrium in the
    horizontal plane (it drifts under any horizontal load, and sits anywhere under none), and
    ``system_static`` refuses it. The dynamics (``system_dynamic``) run such a body.

    Raises
    ------
    InputError
        Naming the body, the hydrostatic surge and sway stiffness [N/m] and the fixes.
    """
    from .model import bodies_without_lines

    for name in bodies_without_lines(system):
        body = system.bodies[name]
        if body.kind != "free" or body.pinned:
            continue
        k = body.matrix("hydrostatic_stiffness")
        if k[0, 0] > 0 and k[1, 1] > 0:
            continue
        raise InputError(
            f"{where}bodies.{name}: a free body that no line of 'lines' ends on has no horizontal restoring (surge "
            f"{k[0, 0]:g} N/m, sway {k[1, 1]:g} N/m: no line and no hydrostatic_stiffness holds it), so it has no "
            "static equilibrium: it drifts under any horizontal load. Suggested fix: end a line on it (a point of "
            "kind 'body'), make it 'fixed' or 'prescribed', pin it (pinned: true, only its rotations free), give a "
            "hydrostatic_stiffness with surge and sway terms, or run it in time (analysis type system_dynamic).")


def prepare_system_static(case: SystemCase, statics: str | None = None) -> SystemSetup:
    """Every check of a ``system_static`` case that needs no solve; returns what the solves need.

    The case's own checks (names of points, bodies and line types, masses and inertias, points below
    the seabed, the damaged lines) ran when it was built; here the damaged system is built, free
    points without lines and free bodies without lines nor horizontal restoring
    (:func:`check_bodies_without_lines`) are refused,
    and the solver's checks at the given positions run for each condition: a line that cannot reach
    between its ends, and a body that nothing restores (unstable hydrostatics and no mooring
    restoring). With a current or a sloping seabed (or ``statics: finite_element``) the
    finite-element statics are used (:func:`statics_used`) and their checks run instead: no pinned
    body, the finite-element system's geometry.
    """
    return _setup(case, "system_static", statics)


def prepare_system_offsets(case: SystemCase, statics: str | None = None) -> SystemSetup:
    """Every check of a ``system_offsets`` case that needs no solve; returns what the solves need.

    As :func:`prepare_system_static`, and the size of the sweep
    (:func:`seacable._limits.check_run_size`: one solve per condition, heading, load and load step).
    """
    setup = _setup(case, "system_offsets", statics)
    a: SystemOffsetsAnalysis = case.analysis
    headings = a.heading_values()
    n_cond = len(setup.conditions)
    solves = n_cond * (a.load_steps + len(headings) * len(a.loads) * a.load_steps)
    stored = n_cond * len(headings) * len(a.loads) * (12 * len(setup.lines) + 12 * len(setup.bodies)
                                                      + 3 * len(setup.points))
    check_run_size(f"system_offsets case '{case.name}' (each of its {solves:.0f} equilibria counted as a time step)",
                   steps=solves, stored_values=stored,
                   fix="give fewer analysis.loads or headings (n_headings), or fewer analysis.load_steps")
    return SystemSetup(**{**setup.__dict__, "loads": tuple(a.loads), "headings": tuple(headings)})


# ----------------------------------------------------------------------------- solving

def _offsets_text(system: MooringSystem, eq) -> str:
    """The horizontal offsets of the free bodies at the last converged state (none: ``eq`` None). [m]"""
    free = [n for n, b in system.bodies.items() if b.kind == "free"]
    if not free or eq is None:
        return ""
    parts = []
    for name in free:
        d = np.asarray(eq.body_offset(name), float)
        parts.append(f"'{name}' {math.hypot(d[0], d[1]):.4g} m (x {d[0]:+.4g} m, y {d[1]:+.4g} m)")
    return "; last converged offset of " + ", ".join(parts)


def _solve_path(case: SystemCase, system: MooringSystem, steps, initial, where: str, fix: str,
                statics: str = "catenary", stiffness: bool = True, start=None):
    """Solve the equilibrium of ``system`` under each external load of ``steps`` (a list of (label,
    ``{body: 6 loads}`` or None)), each from the last; returns the last equilibrium. ``start``: the start the
    checks evaluated (:class:`~seacable.system.statics.solve.CheckedStart`), which the first step takes if it
    is its start.

    A failure raises the solver's error type naming ``where``, the step, the residual, the solver's
    last offsets, the last converged offsets and ``fix``. ``statics``: 'catenary' or 'finite_element'
    (:func:`seacable.system.statics.fe.fe_equilibrium`, its stiffness at the last step when ``stiffness``).
    """
    from .statics import solve_equilibrium
    from .statics.fe import fe_equilibrium

    a = case.analysis
    eq, last_label = initial, None
    for label, external in steps:
        try:
            with warnings.catch_warnings():
                # one warning per line at its largest tension over the run (_warn_breaking), not one per solve
                warnings.filterwarnings("ignore", message=r"lines\.\S+: tension .* exceeds the breaking load")
                # said once by the prepare step
                warnings.filterwarnings("ignore", message=r".*the finite-element statics .* are frictionless")
                if statics == "finite_element":
                    last = label == steps[-1][0]
                    eq = fe_equilibrium(system, case.environment, external=external, tol=a.tolerance,
                                        max_iter=max(a.max_iterations, 1000), initial=eq,
                                        stiffness=stiffness and last,
                                        friction=getattr(a, "static_friction", None))
                else:
                    eq = solve_equilibrium(system, case.environment, external=external, tol=a.tolerance,
                                           max_iter=a.max_iterations, initial=eq, max_strain=a.max_strain,
                                           start=start if eq is None else None)
        except (ConvergenceError, NoSolutionError) as err:
            residual = getattr(err, "residual", None)
            done = f" (the step before, {last_label}, converged)" if last_label else ""
            said = str(err).split(" Suggested fix:")[0].rstrip(". ")
            own = f"{err.fix}; else " if getattr(err, "fix", None) else ""  # the solver's own, for what it found
            message = (f"{where}: no equilibrium found at {label}{done}: {said}{_offsets_text(system, eq)}. "
                       f"Suggested fix: {own}{fix}.")
            if isinstance(err, ConvergenceError):
                raise ConvergenceError(message, iterations=getattr(err, "iterations", None),
                                       residual=residual) from None
            raise NoSolutionError(message) from None
        last_label = label
    return eq


def _start_checks(system: MooringSystem, environment, where: str, max_strain: float = 1.0):
    """The solver's checks at the given positions, without solving (:func:`~seacable.system.statics.check_statics`):
    what its catenaries cannot model, a line that cannot reach between its ends, a body that nothing
    restores (unstable hydrostatics and no mooring restoring). Returns the start they evaluated."""
    from .statics import check_statics

    try:
        return check_statics(system, environment, max_strain=max_strain)
    except InputError as err:
        raise type(err)(f"{where}{err}") from None


def _check_stable(system: MooringSystem, eq, where: str) -> None:
    """Refuse an equilibrium at which a free body's total (mooring + hydrostatic) stiffness is negative."""
    free = [n for n, b in system.bodies.items() if b.kind == "free"]
    if not free:
        return
    km, kh = np.asarray(eq.stiffness, float), np.asarray(eq.hydrostatic, float)
    units = ("N/m", "N/m", "N/m", "N m/rad", "N m/rad", "N m/rad")
    for i, name in enumerate(free):
        body = system.bodies[name]
        # a scale of the body's stiffness: its weight (and buoyancy) over, or times, one metre; a total below
        # 1e-9 of it is a rotation nothing resists nor loads (a rod's spin), held by the statics, not unstable
        scale = (body.mass + 1025.0 * body.volume) * 9.81
        for k in range(6):
            m, h = km[6 * i + k, 6 * i + k], kh[6 * i + k, 6 * i + k]
            if m + h < 0 and abs(m + h) > 1e-9 * max(abs(m) + abs(h), scale):
                hint = ("lower the centre of gravity or enlarge the waterplane moments (a positive metacentric "
                        "height)" if k in (3, 4) else "check the waterplane area and the displaced volume")
                raise NoSolutionError(
                    f"{where}: body '{name}' has no stable equilibrium in {DOFS[k]}: its hydrostatic stiffness "
                    f"is {h:.4g} {units[k]} and the lines add {m:.4g} {units[k]}, a total of {m + h:.4g} "
                    f"{units[k]} < 0 (the body would capsize or sink away from this state). Suggested fix: "
                    f"{hint} of bodies.{name}, or check its hydrostatic_stiffness matrix.")


def _warn_breaking(case: SystemCase, values: dict, where: str) -> None:
    """A SeacableWarning for each line whose end tension exceeds its line types' smallest breaking load."""
    import warnings

    from ..errors import SeacableWarning

    for j, name, mbl in _kept(_BREAKING, case, None, lambda: _breaking_loads(case)):
        peak = np.nanmax(np.stack([values["fairlead_tension"][..., j], values["anchor_tension"][..., j]]))
        if np.isfinite(peak) and peak > mbl:
            warnings.warn(f"{where}: lines.{name} carries {peak:.4g} N, above its breaking_load {mbl:.4g} N: the "
                          "line would break. Suggested fix: check the line's length and the loads, or name the line "
                          "in analysis.damaged_lines.", SeacableWarning, stacklevel=3)


#: id of a case -> {None: :func:`_breaking_loads`}, while the case lives
_BREAKING: dict[int, dict] = {}


def _breaking_loads(case: SystemCase) -> list[tuple[int, str, float]]:
    """(index, name, smallest breaking load [N]) of each line whose segments all give a breaking load."""
    out = []
    for j, name in enumerate(case.lines):
        loads = [seg.line_type.breaking_load for seg in case.lines[name].line.segments]
        if loads and not any(b is None for b in loads):
            out.append((j, name, min(loads)))
    return out


def _ramp(system: MooringSystem, steps: int):
    """(label, external loads) that ramp the free bodies' ``external_force`` up in ``steps`` steps: the
    solver adds ``external`` to each body's own load, so step k adds ``-(1 - k / steps)`` of it."""
    if steps == 1:
        return [("the full load", None)]
    loaded = {n: np.asarray(b.external_force, float) for n, b in system.bodies.items()
              if b.kind == "free" and np.any(np.asarray(b.external_force) != 0)}
    return [(f"load step {k} of {steps}", {n: tuple(-(1 - k / steps) * f) for n, f in loaded.items()})
            for k in range(1, steps + 1)]


def _static_fix(a) -> str:
    more = max(10, 2 * a.load_steps)
    return (f"ramp the bodies' external loads up in steps (analysis.load_steps: {more}), raise "
            f"analysis.max_iterations ({a.max_iterations}), or check that the lines can hold the bodies under their "
            "loads (long enough not to pull taut, taut enough to restore)")


# ----------------------------------------------------------------------------- results

def _nan(shape=()):
    return np.full(shape, np.nan)


def equilibrium_variables(eq, system: MooringSystem, setup: SystemSetup) -> dict[str, np.ndarray]:
    """The per-equilibrium quantities of :data:`_VARIABLES` and :data:`_MATRICES` as arrays along the
    setup's lines, bodies and points (NaN for those the system lacks: removed lines, non-free bodies).

    Anchor loads are those of end A: the horizontal and vertical components of the force of the line
    on its end point and the angle of that pull above the horizontal; the fairlead angle is the angle
    of the line at end B below the horizontal.
    """
    nl, nb, npt = len(setup.lines), len(setup.bodies), len(setup.points)
    # the variables of each dimension are the rows of one block, NaN where the system lacks the item, filled by
    # columns (the items it has) in the order of _BY_DIMS
    lines, bodies, points = (np.full((len(names), size), np.nan) for names, size in zip(_BY_DIMS.values(),
                                                                                        (nl, nb, npt)))
    matrices = {name: _nan((nb, 6, 6)) for name in _MATRICES}
    li = {n: i for i, n in enumerate(eq.line_names)}
    rows = [j for j, name in enumerate(setup.lines) if name in li]
    if rows:
        at = _index([li[setup.lines[j]] for j in rows], len(li))
        rows = _index(rows, nl)
        fa, fb = np.asarray(eq.end_a_force, float)[at], np.asarray(eq.end_b_force, float)[at]
        a, b = fa.tolist(), fb.tolist()
        ha = [math.hypot(f[0], f[1]) for f in a]
        hb = [math.hypot(f[0], f[1]) for f in b]
        lines[:, rows] = [np.asarray(eq.end_b_tension, float)[at], np.asarray(eq.end_a_tension, float)[at], ha,
                          fa[:, 2], [math.atan2(f[2], h) for f, h in zip(a, ha)],
                          [math.atan2(-f[2], h) for f, h in zip(b, hb)], fb[:, 0], fb[:, 1], fb[:, 2],
                          np.asarray(eq.grounded_length, float)[at]]
    bi = {n: i for i, n in enumerate(eq.body_names)}
    rows = [j for j, name in enumerate(setup.bodies) if name in bi]
    if rows:
        pose = np.asarray(eq.body_position, float)[_index([bi[setup.bodies[j]] for j in rows], len(bi))]
        d = pose[:, :2] - np.array([system.bodies[setup.bodies[j]].position[:2] for j in rows], float)
        rows = _index(rows, nb)
        bodies[:6, rows] = pose.T  # the rows of _POSE, then the offsets
        bodies[6:8, rows] = d.T
        bodies[8, rows] = [math.hypot(x, y) for x, y in d.tolist()]
    free = [n for n, b in system.bodies.items() if b.kind == "free"]
    for j, name in enumerate(setup.bodies):
        if name in bi and name in free:
            f = free.index(name)
            matrices["stiffness"][j] = np.asarray(eq.body_stiffness(name), float)
            matrices["hydrostatic_stiffness"][j] = np.asarray(eq.hydrostatic, float)[6 * f:6 * f + 6, 6 * f:6 * f + 6]
    pi = {n: i for i, n in enumerate(eq.point_names)}
    rows = [j for j, name in enumerate(setup.points) if name in pi]
    if rows:
        points[:, _index(rows, npt)] = np.asarray(eq.point_position, float)[
            _index([pi[setup.points[j]] for j in rows], len(pi))].T
    out = {}
    for names, block in zip(_BY_DIMS.values(), (lines, bodies, points)):
        out.update(zip(names, block))
    out.update(matrices)
    return out


def _index(items: list[int], size: int):
    """``items`` as an index: all of ``size`` in order, a slice (a view, not a copy by fancy indexing)."""
    return slice(None) if len(items) == size and items == list(range(size)) else items


def _profiles(eq, setup: SystemSetup, n: int) -> dict[str, np.ndarray]:
    nl = len(setup.lines)
    out = {name: _nan((nl, n)) for name in _PROFILE}
    rows = [j for j, name in enumerate(setup.lines) if name in eq.line_names]
    if not rows:
        return out
    names = [setup.lines[j] for j in rows]
    if hasattr(eq, "line_profiles"):  # the catenary statics: every line in one compiled call
        positions, tension = eq.line_profiles(names, n)
    else:
        got = [eq.line_profile(name, n) for name in names]
        positions = np.array([np.asarray(p, float) for p, _ in got])
        tension = np.array([t for _, t in got])
    for c, name in enumerate("xyz"):
        out[name][rows] = positions[..., c]
    out["tension"][rows] = tension
    return out


def _bending(eq, setup: SystemSetup) -> dict:
    """The bending outputs of the finite-element equilibrium ``eq`` at its nodes (:func:`seacable.system.bending.
    line_bending`), the held ends on free bodies turned to their poses: {name: (line, k) per line of ``setup``, NaN
    for a line not in ``eq``}, with ``fe_s`` the nodes' unstretched arc lengths [m]; {} for the catenary statics or
    lines without bending."""
    fe = getattr(eq, "fe", None)
    if fe is None or not fe.model.hinges.shape[0]:
        return {}
    from .bending import held_directions, line_bending, pose_rotations

    poses = {name: eq.body_position[eq.body_names.index(name)] for name in eq.body_names}
    directions = held_directions(fe, {name: pose_rotations(p) for name, p in poses.items()})
    got = line_bending(fe, eq.state.position, directions)
    net = fe.model.network
    got["fe_s"] = np.array([np.r_[0.0, np.cumsum(net.length[e])] for e in fe.line_elements], dtype=object)
    for c, axis in enumerate("xyz"):  # the shape the bending is of: the nodes' positions
        got[f"fe_{axis}"] = np.array([eq.state.position[nodes, c] for nodes in fe.line_nodes], dtype=object)
    got["fe_segment_tension"] = np.array([eq.state.tension[els] for els in fe.line_elements], dtype=object)
    out = {}
    for name, values in got.items():
        rows = {line: values[i] for i, line in enumerate(fe.line_names)}
        width = max(len(v) for v in values) if values.dtype == object else values.shape[-1]
        out[name] = np.array([np.pad(np.asarray(rows[line], float), (0, width - len(rows[line])),
                                     constant_values=np.nan) if line in rows else np.full(width, np.nan)
                              for line in setup.lines])
    return out


def _bending_variables(bends: list[dict], data: dict, coords: dict) -> None:
    """The bending outputs of each condition (:func:`_bending`) into ``data`` (condition, line, fe_node or
    fe_element) and their arc lengths ``fe_s`` into ``coords``."""
    from ..results import var
    from .bending import BENDING

    keys = next(b for b in bends if b).keys()
    widths = {k: max(b[k].shape[-1] for b in bends if b) for k in keys}
    nl = next(b for b in bends if b)["fe_s"].shape[0]

    def padded(b, k):
        if not b:
            return np.full((nl, widths[k]), np.nan)
        return np.pad(b[k], ((0, 0), (0, widths[k] - b[k].shape[-1])), constant_values=np.nan)

    for name, (where, units, long_name) in BENDING.items():
        data[name] = var(("condition", "line", f"fe_{where}"), np.stack([padded(b, name) for b in bends]), units,
                         long_name + " (at the finite-element nodes)")
    for axis, long_name in (("x", "x position"), ("y", "y position"), ("z", "elevation (0 at the still water level)")):
        data[f"fe_{axis}"] = var(("condition", "line", "fe_node"), np.stack([padded(b, f"fe_{axis}") for b in bends]),
                                 "m", long_name + " of the finite-element node")
    data["fe_segment_tension"] = var(("condition", "line", "fe_element"),
                                     np.stack([padded(b, "fe_segment_tension") for b in bends]), "N",
                                     "effective tension of the finite element")
    s = np.fmax.reduce([padded(b, "fe_s") for b in bends])
    coords["fe_node"] = var("fe_node", np.arange(widths["fe_s"]), "1", "finite-element node along the line, 0 at end A")
    coords["fe_element"] = var("fe_element", np.arange(widths["shear_force"]), "1",
                               "finite element along the line, 0 at end A")
    coords["fe_s"] = var(("line", "fe_node"), s, "m", "unstretched arc length of the finite-element node from end A")


def _stack(records: list[dict], lead: tuple[int, ...]) -> dict[str, np.ndarray]:
    if len(records) == 1:  # one equilibrium (system_static intact): its arrays, with the leading axes
        return {k: np.asarray(v).reshape(lead + np.shape(v)) for k, v in records[0].items()}
    return {k: np.stack([r[k] for r in records]).reshape(lead + np.shape(records[0][k])) for k in records[0]}


#: id of a case -> {profile points (None: system_offsets) -> its result's coordinates}, while the case lives
_COORDS: dict[int, dict] = {}


def _coords(setup: SystemSetup, profile_points: int | None = None) -> dict:
    """The result's coordinates: names and constants of the lines, bodies and points, and with ``profile_points``
    those of ``system_static`` (profile points, arc lengths, degrees of freedom). Made once per case (they are
    the case's), each result given copies of the arrays."""
    from ..results import var  # xarray: imported when a result is built, not when a case is checked

    table = _kept(_COORDS, setup.case, profile_points, lambda: _coord_arrays(setup, profile_points))
    return {name: var(dims, values.copy(), units, long_name) for name, (dims, values, units, long_name) in table.items()}


def _coord_arrays(setup: SystemSetup, n: int | None) -> dict:
    """name -> (dimensions, values, units, long name) of :func:`_coords`."""
    case = setup.case

    def names(items):
        return np.array(list(items), dtype=object)

    table = {
        "condition": ("condition", names(setup.conditions), "1",
                      "condition of the system: intact, or damaged (analysis.damaged_lines removed)"),
        "line": ("line", names(setup.lines), "1", "line name"),
        "body": ("body", names(setup.bodies), "1", "body name"),
        "point": ("point", names(setup.points), "1", "point name"),
        "line_length": ("line", np.asarray([case.lines[n].line.length for n in setup.lines]), "m",
                        "unstretched length of the line"),
        "end_a": ("line", names(case.lines[n].end_a for n in setup.lines), "1", "point at end A of the line (anchor)"),
        "end_b": ("line", names(case.lines[n].end_b for n in setup.lines), "1",
                  "point at end B of the line (fairlead)"),
        "point_kind": ("point", names(case.points[n].kind for n in setup.points), "1",
                       "kind of the point: fixed, free, coupled or body"),
        "body_kind": ("body", names(case.bodies[n].kind for n in setup.bodies), "1",
                      "kind of the body: free, fixed or prescribed"),
    }
    if n is None:
        return table
    s = np.array([np.linspace(0.0, case.lines[name].line.length, n) for name in setup.lines]).reshape(
        len(setup.lines), n)  # (0, node) for a system without lines
    labels = names(f"{b} {d}" for b in setup.free_bodies for d in DOFS)
    table.update({
        "node": ("node", np.arange(n), "1", "profile point, 0 at end A"),
        "s": (("line", "node"), s, "m", "unstretched arc length from end A"),
        "dof": ("dof", names(DOFS), "1", "degree of freedom (force or moment)"),
        "dof2": ("dof2", names(DOFS), "1", "degree of freedom (displacement or rotation)"),
        "body_dof": ("body_dof", labels, "1", "free body and degree of freedom (force or moment)"),
        "body_dof2": ("body_dof2", labels, "1", "free body and degree of freedom (displacement or rotation)"),
    })
    return table


def _line_present(setup: SystemSetup) -> np.ndarray:
    return np.array([[name in system.lines for name in setup.lines] for system in setup.systems], dtype=np.int8)


def _variables(values: dict, lead: tuple[str, ...], table: dict) -> dict:
    from ..results import var

    return {name: var(lead + table[name][0], values[name], table[name][1], table[name][2])
            for name in table if name in values}


def _settings(case: SystemCase, setup: SystemSetup, **more) -> dict:
    """The run's settings; ``damaged_lines`` the lines the damaged condition removed (for ``most_loaded``, the
    line it resolved to; per heading in ``system_offsets``: the result's ``damaged_line``)."""
    a = case.analysis
    damaged = setup.systems[1] if len(setup.systems) > 1 else None
    removed = [n for n in setup.lines if damaged is not None and n not in damaged.lines] if damaged is not None \
        else ("most_loaded" if is_most_loaded(a.damaged_lines) else list(a.damaged_lines))
    return {"tolerance": a.tolerance, "max_iterations": a.max_iterations, "load_steps": a.load_steps,
            "max_strain": a.max_strain, "damaged_lines": removed,
            **({"damaged_lines_rule": "most_loaded"} if is_most_loaded(a.damaged_lines) else {}),
            "depth": case.environment.depth, **more}


def run_system_static(case: SystemCase, statics: str | None = None):
    """Equilibrium, end tensions, anchor loads and stiffness of a system (analysis ``system_static``).

    Returns
    -------
    xarray.Dataset
        Dimensions ``condition`` (intact, and damaged when ``damaged_lines`` are given), ``line``,
        ``body``, ``point``, ``node`` (profile points, evenly spaced in unstretched arc length),
        ``dof`` and ``dof2`` (surge, sway, heave, roll, pitch, yaw) and ``body_dof``, ``body_dof2``
        (those of every free body, for the coupled stiffness). Attributes ``statics`` (``catenary`` or
        ``finite_element``) and ``stiffness_method`` say how the equilibrium and the stiffness were found.

    ``statics`` overrides the analysis option ``statics`` (:func:`statics_used`): ``auto``, ``catenary``,
    ``finite_element``.
    """
    from ..results import make_dataset, var
    from .ties import equilibrium_ties, tie_variables

    a: SystemStaticAnalysis = case.analysis
    setup = prepare_system_static(case, statics)
    records, profiles, bends, ties, coupled, iterations, residuals = [], [], [], [], [], [], []
    pins, held = np.zeros((len(setup.conditions), len(setup.bodies), 3)), []
    intact_eq = None   # the intact equilibrium (the first condition), that most_loaded chooses its line by
    for c, (condition, system) in enumerate(zip(setup.conditions, setup.systems)):
        where = f"system_static case '{case.name}', {condition} condition"
        if system is None:  # damaged_lines: most_loaded, the line of the largest tension in the intact equilibrium
            line = most_loaded_line(setup.lines, line_tensions(intact_eq, setup.lines), f"{where}: ")
            system = _condition_system(case, (line,))
            setup = dataclasses.replace(setup, systems=(setup.systems[0], system))
            where += f" ({line}, the most loaded line, removed)"
            removed = (line,)
        else:
            removed = None if c == 0 else tuple(a.damaged_lines)
        eq = _solve_path(case, system, _ramp(system, a.load_steps), None, where, _static_fix(a), setup.statics,
                         start=setup.starts.get(removed))
        _check_stable(system, eq, where)
        if eq.pin_reaction is not None:
            for k, name in enumerate(eq.free_body_names):
                pins[c, setup.bodies.index(name)] = eq.pin_reaction[k]
        held += [f"{condition}: {what}" for what in eq.indeterminate]
        if c == 0:
            intact_eq = eq
        records.append(equilibrium_variables(eq, system, setup))
        profiles.append(_profiles(eq, setup, a.profile_points))
        bends.append(_bending(eq, setup))
        ties.append(equilibrium_ties(eq, setup.lines))
        coupled.append(np.asarray(eq.stiffness, float))
        iterations.append(int(eq.iterations))
        residuals.append(float(eq.residual))
    nc = len(setup.conditions)
    values = _stack(records, (nc,))
    _warn_breaking(case, values, f"system_static case '{case.name}'")
    data = _variables(values, ("condition",), _VARIABLES)
    from .._cf import matrix_variables  # here: _cf imports xarray, which 'validate' (this module's checks) needs not

    for name, (dims, _, long) in _MATRICES.items():  # a block per unit (CF): seacable._cf.matrix_variables
        if name in values:
            data.update(matrix_variables(name, ("condition",) + dims, values[name], DOFS, DOFS, long))
    data.update(_variables(_stack(profiles, (nc,)), ("condition",), _PROFILE))
    data["line_present"] = var(("condition", "line"), _line_present(setup), "1",
                               "1 where the line is in the condition, 0 where it is removed (its values NaN)")
    labels = [f"{b} {d}" for b in setup.free_bodies for d in DOFS]
    data.update(matrix_variables("coupled_stiffness", ("condition", "body_dof", "body_dof2"), np.stack(coupled),
                                 labels, labels, "coupled mooring stiffness of the free bodies, lines only"))
    data["iterations"] = var("condition", iterations, "1", "iterations of the equilibrium solve")
    data["residual"] = var("condition", residuals, "1", "residual of the equilibrium, relative")
    if setup.bodies:
        for k, axis in enumerate("xyz"):
            data[f"pin_reaction_{axis}"] = var(("condition", "body"), pins[..., k], "N",
                                               f"force of the pin on a pinned body, {axis} (0: not pinned)")
    coords = _coords(setup, a.profile_points)
    if any(bends):
        _bending_variables(bends, data, coords)
    tie_variables(ties, ("condition",), (nc,), data, coords)
    ds = make_dataset(data, coords, analysis="system_static", case=case, references=REFERENCES,
                      settings=_settings(case, setup), owned=True)
    ds.attrs["depth"] = float(case.environment.origin_depth())
    _statics_attrs(ds, setup)
    if held:
        ds.attrs["indeterminate"] = "; ".join(held)  # rotations nothing resists, held where they start
    return ds


def _sweep_offsets(case: SystemCase, setup, loads, headings, records: list, restoring: list,
                   chosen: list | None = None, ties: list | None = None) -> None:
    """Solve the swept loads of each condition and heading in order, appending each equilibrium's
    variables to ``records`` and its restoring force to ``restoring`` (so that an interrupt keeps them), and its
    ties' outputs to ``ties`` (:func:`seacable.system.ties.equilibrium_ties`) when given.

    A damaged condition of ``damaged_lines: most_loaded`` (its system None) removes, at each heading, the line
    of the largest tension in the intact equilibrium under that heading's largest load; ``chosen`` gets those
    lines, heading by heading."""
    from .ties import equilibrium_ties

    a: SystemOffsetsAnalysis = case.analysis
    for c, (condition, system) in enumerate(zip(setup.conditions, setup.systems)):
        where = f"system_offsets case '{case.name}', {condition} condition"
        per_heading = system is None
        bases: dict[str, tuple] = {}
        if not per_heading:
            base = _solve_path(case, system, _ramp(system, a.load_steps), None, where, _static_fix(a), setup.statics,
                               start=setup.starts.get(None if c == 0 else tuple(a.damaged_lines)))
            _check_stable(system, base, f"{where}, at no load")
        for k, h in enumerate(headings):
            at = where
            if per_heading:
                last = records[(k + 1) * len(loads) - 1]  # the intact equilibrium under this heading's largest load
                tension = np.fmax(last["fairlead_tension"], last["anchor_tension"])
                line = most_loaded_line(setup.lines, tension, f"{where}, heading {h:.6g} rad: ")
                if chosen is not None:
                    chosen.append(line)
                at = f"{where} ({line}, the most loaded line at heading {h:.6g} rad, removed)"
                if line not in bases:
                    damaged = _condition_system(case, (line,))
                    eq0 = _solve_path(case, damaged, _ramp(damaged, a.load_steps), None, at, _static_fix(a),
                                      setup.statics, start=setup.starts.get((line,)))
                    _check_stable(damaged, eq0, f"{at}, at no load")
                    bases[line] = (damaged, eq0)
                system, base = bases[line]
            direction = np.array([math.cos(h), math.sin(h), 0.0, 0.0, 0.0, 0.0])
            eq, last = base, 0.0
            for load in loads:
                if load > 0.0:
                    steps = []
                    for k2 in range(1, a.load_steps + 1):
                        f = last + (load - last) * k2 / a.load_steps
                        steps.append((f"{f:.6g} N at heading {h:.6g} rad", {a.body: tuple(f * direction)}))
                    fix = (f"add intermediate loads between {last:g} N and {load:g} N (a finer ramp in "
                           f"analysis.loads, or analysis.load_steps: {max(10, 2 * a.load_steps)}), raise "
                           f"analysis.max_iterations ({a.max_iterations}), or lower the largest load if the lines "
                           "cannot hold it")
                    eq = _solve_path(case, system, steps, eq, at, fix, setup.statics, stiffness=False)
                    last = load
                records.append(equilibrium_variables(eq, system, setup))
                restoring.append(-_body_line_force(eq, system, a.body)[:2] @ direction[:2])
                if ties is not None:
                    ties.append(equilibrium_ties(eq, setup.lines))


def run_system_offsets(case: SystemCase, statics: str | None = None):
    """Offsets, watch circle and restoring force of a body under a swept load (analysis ``system_offsets``).

    Returns
    -------
    xarray.Dataset
        Dimensions ``condition``, ``applied_load`` [N], ``heading`` [rad], ``line``, ``body``, ``point``. The
        ``restoring_force`` is the horizontal force of the lines on the loaded body against the load's
        heading; ``offset`` the loaded body's offset along the heading from its given position.
    """
    from ..results import make_dataset, var
    from .ties import tie_variables

    a: SystemOffsetsAnalysis = case.analysis
    setup = prepare_system_offsets(case, statics)
    loads, headings = np.asarray(setup.loads, float), np.asarray(setup.headings, float)
    records, restoring, chosen, ties = [], [], [], []
    try:
        _sweep_offsets(case, setup, loads, headings, records, restoring, chosen, ties)
        interrupted = False
    except KeyboardInterrupt:  # Ctrl-C or SIGTERM: keep the equilibria found, NaN for the rest
        if not records:
            raise
        interrupted = True
        blank = {k: np.full_like(np.asarray(v, float), np.nan) for k, v in records[0].items()}
        missing = len(setup.conditions) * loads.size * headings.size - len(records)
        records += [blank] * missing
        restoring += [math.nan] * missing
    lead = (len(setup.conditions), loads.size, headings.size)
    values = {k: np.swapaxes(v, 1, 2) for k, v in _stack(records, (lead[0], lead[2], lead[1])).items()}
    dims = ("condition", "applied_load", "heading")
    _warn_breaking(case, values, f"system_offsets case '{case.name}'")
    data = _variables(values, dims, _VARIABLES)
    unit = np.stack([np.cos(headings), np.sin(headings)])
    b = setup.bodies.index(a.body)
    offset = values["body_offset_x"][..., b] * unit[0] + values["body_offset_y"][..., b] * unit[1]
    data["offset"] = var(dims, offset, "m", f"offset of body '{a.body}' along the load's heading")
    restoring = np.swapaxes(np.reshape(restoring, (lead[0], lead[2], lead[1])), 1, 2)
    data["restoring_force"] = var(dims, restoring, "N",
                                  f"horizontal force of the lines on body '{a.body}' against the load's heading")
    if is_most_loaded(a.damaged_lines):  # the line removed depends on the heading
        chosen += [""] * (headings.size - len(chosen))  # an interrupted sweep: none for the headings not reached
        present = np.ones((len(setup.conditions), headings.size, len(setup.lines)), dtype=np.int8)
        for k, line in enumerate(chosen):
            if line:
                present[1, k, setup.lines.index(line)] = 0
        data["line_present"] = var(("condition", "heading", "line"), present, "1",
                                   "1 where the line is in the condition, 0 where it is removed (its values NaN)")
        data["damaged_line"] = var("heading", np.array(chosen, dtype=object), "1",
                                   "the line the damaged condition removes at this heading: the most loaded in "
                                   "the intact equilibrium under the heading's largest load")
    else:
        data["line_present"] = var(("condition", "line"), _line_present(setup), "1",
                                   "1 where the line is in the condition, 0 where it is removed (its values NaN)")
    coords = _coords(setup)
    coords.update({"applied_load": var("applied_load", loads, "N", f"external horizontal load on body '{a.body}'"),
                   "heading": var("heading", headings, "rad", "heading of the load, from +x towards +y")})
    # the ties' outputs (condition, applied_load, heading, line, tether or clamp), solved heading by heading
    ties += [{}] * (lead[0] * lead[1] * lead[2] - len(ties))  # an interrupted sweep: NaN for the rest
    order = np.arange(len(ties)).reshape(lead[0], lead[2], lead[1]).transpose(0, 2, 1).ravel()
    tie_variables([ties[k] for k in order], dims, lead, data, coords)
    ds = make_dataset(data, coords, analysis="system_offsets", case=case, references=REFERENCES,
                      settings=_settings(case, setup, body=a.body), owned=True)
    ds.attrs["loaded_body"] = a.body
    ds.attrs["depth"] = float(case.environment.origin_depth())
    ds.attrs["interrupted"] = int(interrupted)
    _statics_attrs(ds, setup)
    return ds


def _statics_attrs(ds, setup: SystemSetup) -> None:
    """Say which statics and which stiffness the Dataset holds."""

    ds.attrs["statics"] = setup.statics
    ds.attrs["stiffness_method"] = STIFFNESS_FD if setup.fe else STIFFNESS_ANALYTIC
    if setup.fe:
        why = needs_fe(setup.case.environment)
        lines = line_reasons(setup.case.lines)
        why = "; ".join(([f"the environment has {why}"] if why else []) + ([f"the system has {lines}"] if lines else []))
        ds.attrs["statics_reason"] = (f"{why}, which the catenary lines cannot model" if why
                                      else "asked for (analysis.statics: finite_element)")


def _body_line_force(eq, system: MooringSystem, body: str) -> np.ndarray:
    """Force of every line on the points fixed on ``body``, summed, global axes. [N]"""
    total = np.zeros(3)
    for i, name in enumerate(eq.line_names):
        line = system.lines[name]
        for end, forces in (("end_a", eq.end_a_force), ("end_b", eq.end_b_force)):
            p = system.points[getattr(line, end)]
            if p.kind == "body" and p.body == body:
                total += np.asarray(forces[i], float)
    return total

"""The ``system_dynamic`` analysis of a case: its finite-element system and motions (:func:`prepare_system_dynamic`),
the static start (:func:`start_state`) and the run (:func:`run_system_dynamic`).
"""

from __future__ import annotations

import dataclasses
import warnings
from dataclasses import dataclass

import numpy as np

from ..._limits import check_run_size
from ..._model import suggest
from ...errors import ConvergenceError, InputError, SeacableWarning
from ...mooring.motion import RAOMotion
from ...mooring.outputs import at_motion_start
from ..case import SystemDynamicAnalysis
from ..damaged import is_most_loaded, line_tensions, most_loaded_line
from ..model import MooringSystem
from .fe import SystemFE, build_system_fe, lines_only
from .loop import (
    SystemState,
    _channels_fn,
    _simulate_lines,
    sea_bands,
    sea_positions,
    simulate_system,
    static_system,
)
from .outputs import system_result


def _system_of(case) -> MooringSystem:
    """The MooringSystem of a case: ``case.system()`` or ``case.system``, or its points/bodies/lines."""
    damaged = getattr(case, "damaged_system", None)
    named = getattr(case.analysis, "damaged_lines", ())
    if callable(damaged) and named:
        return damaged((most_loaded_at_start(case),)) if is_most_loaded(named) else damaged()
    sys_ = getattr(case, "system", None)
    if callable(sys_):
        sys_ = sys_()
    if isinstance(sys_, MooringSystem):
        return sys_
    try:
        return MooringSystem(points=case.points, bodies=getattr(case, "bodies", {}) or {}, lines=case.lines)
    except AttributeError:
        raise InputError(f"a system_dynamic case needs a mooring system (points, bodies, lines); got "
                         f"{type(case).__name__}. Suggested fix: give 'points', 'bodies' and 'lines'.") from None


def _moment_sources(system: MooringSystem, name: str, analysis: SystemDynamicAnalysis) -> list[str]:
    """What could turn body ``name`` about its centre of gravity (for a body with no inertia about it): lines
    and loaded points off the centre of gravity, buoyancy off it, hydrostatics, external moments (or forces at
    a reference point off it), damping and added mass that act on the rotations or at such a reference point."""
    b = system.bodies[name]
    cg = np.asarray(b.center_of_gravity, float)
    tol = 1e-9 * (1.0 + float(np.linalg.norm(cg)))
    off = float(np.linalg.norm(cg)) > tol
    ends = {e for line in system.lines.values() for e in (line.end_a, line.end_b)}
    out = [f"point {p}" for p, pt in system.points.items()
           if pt.kind == "body" and pt.body == name and float(np.linalg.norm(np.asarray(pt.position) - cg)) > tol
           and (p in ends or pt.mass or pt.volume or pt.drag_area or any(pt.external_force))]
    if b.volume > 0 and float(np.linalg.norm(np.asarray(b.center_of_buoyancy) - cg)) > tol:
        out.append("its buoyancy")
    if b.waterplane_area > 0 or any(b.waterplane_moments) or b.hydrostatic_stiffness is not None:
        out.append("its hydrostatics")
    force = np.asarray(b.external_force, float)
    if force[3:].any() or (off and force[:3].any()) or name in analysis.external_forces:
        out.append("its external force")
    for key in ("linear_damping", "quadratic_damping"):
        m = b.matrix(key)
        if m[3:].any() or m[:, 3:].any() or (off and m.any()):
            out.append(f"its {key}")
    return out


@dataclass
class SystemDynamicSetup:
    """What the time loop of ``system_dynamic`` needs (see :func:`prepare_system_dynamic`)."""

    fe: SystemFE
    analysis: SystemDynamicAnalysis
    start_fe: SystemFE  # the system of the static start: ``fe``, or with the fairleads where the motions start


def prepare_system_dynamic(case) -> SystemDynamicSetup:
    """Every check of a ``system_dynamic`` case that can be made before the time loop.

    The names in ``body_motions``, ``point_motions``, ``external_forces`` and ``failures``; the kinds they
    need (a prescribed body has a motion, a free body's force series covers the run); the network's
    geometry (:func:`seacable.mooring.checks.check_network`, through the model); motions bound over the run;
    and the run size (:func:`seacable._limits.check_run_size`).
    """
    a: SystemDynamicAnalysis = case.analysis
    if getattr(a, "coupling", "coupled") != "coupled":
        raise InputError(f"prepare_system_dynamic runs the coupled route, the case asks for coupling '{a.coupling}'. "
                         "Suggested fix: seacable.run(case) (or seacable.system.uncoupled.run_system_uncoupled).")
    system = _system_of(case)
    where = "analysis"
    for key, names, want in (("body_motions", a.body_motions, ("prescribed",)),
                             ("external_forces", a.external_forces, ("free",)),
                             ("release_offsets", a.release_offsets, ("free",))):
        for name in names:
            if name not in system.bodies:
                raise InputError(f"{where}.{key}: body '{name}' is not defined (bodies: "
                                 f"{', '.join(system.bodies) or 'none'}).{suggest(name, system.bodies)}")
            if system.bodies[name].kind not in want:
                raise InputError(f"{where}.{key}.{name}: body '{name}' is {system.bodies[name].kind}; {key} is for "
                                 f"{want[0]} bodies. Suggested fix: set 'kind: {want[0]}' on the body or drop the entry.")
    for name, body in system.bodies.items():
        if body.kind == "prescribed" and name not in a.body_motions:
            warnings.warn(f"body '{name}' is prescribed but {where}.body_motions has no motion for it: it is held "
                          "still. Suggested fix: add its motion, or make it 'fixed' (a MoorDyn deck: write it as a YAML case with "
                          "seacable.io.dump_case(case.system_case()) and add the motion there).", SeacableWarning,
                          stacklevel=2)
        if body.kind == "free" and body.mass <= 0:
            raise InputError(f"bodies.{name}.mass: a free body needs a mass > 0 kg for the dynamics, got "
                             f"{body.mass:g} kg. Suggested fix: give its mass in air.")
        if body.kind == "free":
            body.check_accelerable(name, _moment_sources(system, name, a))  # not a LinAlgError
    env = case.environment
    # a body with a hydrodynamic database and its excitation feels the waves (seacable.system.hydro); the others not
    free = [n for n, b in system.bodies.items() if b.kind == "free"
            and (b.hydrodynamics is None or not b.hydrodynamics.excitation)]
    if free and env.waves is not None:
        warnings.warn(f"the water's waves act on the lines only, not on the free bodies ({', '.join(free)}): their "
                      "wave loads are not modelled (the current acts on them through their quadratic damping). "
                      "Suggested fix: give the body a hydrodynamic database (bodies.NAME.hydrodynamics), or its wave loads as "
                      "analysis.external_forces (a time series).",
                      SeacableWarning, stacklevel=2)
    for name in a.point_motions:
        if name not in system.points:
            raise InputError(f"{where}.point_motions: point '{name}' is not defined (points: "
                             f"{', '.join(system.points)}).{suggest(name, system.points)}")
        if system.points[name].kind != "coupled":
            raise InputError(f"{where}.point_motions.{name}: point '{name}' is {system.points[name].kind}; only "
                             "coupled points follow a motion. Suggested fix: set 'kind: coupled'.")
    seen = set()
    for k, f in enumerate(a.failures):
        if f.line not in system.lines:
            raise InputError(f"{where}.failures[{k}].line: line '{f.line}' is not defined (lines: "
                             f"{', '.join(system.lines)}).{suggest(f.line, system.lines)}")
        if (f.line, f.end) in seen:
            raise InputError(f"{where}.failures[{k}]: line '{f.line}' end {f.end} fails twice. Suggested fix: give "
                             "one entry per line end (time and tension together if both).")
        seen.add((f.line, f.end))
    for name, ser in a.external_forces.items():
        t, _ = ser.table()
        if t[0] > 1e-9 or t[-1] < a.duration - 1e-9:
            raise InputError(f"{where}.external_forces.{name}: the series covers {t[0]:g} to {t[-1]:g} s, the run "
                             f"needs 0 to {a.duration:g} s. Suggested fix: extend the table.")
    for motion in a.body_motions.values():
        if isinstance(motion, RAOMotion):
            motion.table()   # the RAO file read and checked before the statics of a mean offset are solved
    if any(b.kind == "free" and b.hydrodynamics is not None for b in system.bodies.values()):
        # a floating body from a database: its hydrostatics with the lines must restore it (the catenary statics'
        # checks, at the equilibrium they find), or it would capsize in the first disturbance of the run
        from ..model import bodies_without_lines
        from ..statics import check_statics
        from ..statics_mode import line_reasons

        # (its hydrostatics and lines alone: the catenary statics take no current or wind, nor a line with sections or
        # a held end, a cable: it is left out of this check, its weight a small part of a hull's restoring)
        env = case.environment
        cables = tuple(name for name, line in case.lines.items() if line_reasons({name: line}))
        checked = case.damaged_system(cables) if cables else system
        if not any(checked.bodies[b].kind == "free" and checked.bodies[b].hydrodynamics is not None
                   for b in bodies_without_lines(checked)):
            check_statics(checked, env.model_copy(update={"current": type(env.current)(), "wind": None}))
    a = _mean_offsets(case, system, a)
    fe = build_system_fe(system, case.environment, a)
    net = fe.model.network
    steps = a.duration / min(a.time_step, a.output_interval)
    outputs = a.duration / a.output_interval + 1
    check_run_size(f"system_dynamic case '{getattr(case, 'name', 'system')}'", steps=steps,
                   stored_values=outputs * (2 * 3 * net.n_nodes + net.n_elements + 12 * len(fe.free_bodies)),
                   fix="lengthen analysis.time_step or analysis.output_interval, or shorten analysis.duration")
    channels = _channels_fn(fe, a, a.duration)
    start_fe = fe
    if any(isinstance(m, RAOMotion) for m in a.body_motions.values()):
        # a platform's mean offset: the static start is solved where the motions put the fairleads at t = 0
        # (the run's motions move the nodes from where the case puts them)
        
        start_fe = dataclasses.replace(fe, model=at_motion_start(fe.model, channels))
    if fe.model.water.sea is not None:  # the irregular sea's grid over where the lines go, size-checked
        fe.model.check_sea(a.duration, sea_positions(fe, fe.model.network.position, channels, a.duration,
                                                     a.output_interval), bands=sea_bands(fe))
    return SystemDynamicSetup(fe, a, start_fe)


def _mean_offsets(case, system: MooringSystem, a: SystemDynamicAnalysis) -> SystemDynamicAnalysis:
    """The analysis with each RAO motion's ``mean_offset: equilibrium`` resolved: the body's static equilibrium,
    free under its weight, buoyancy, hydrostatics, steady ``external_force`` and the lines of the run (the damaged
    system's when lines are left out), less its given position (:func:`seacable.system.statics.solve_equilibrium`)."""
    names = [n for n, m in a.body_motions.items() if isinstance(m, RAOMotion) and m.mean_offset == "equilibrium"]
    if not names:
        return a
    from ...errors import NoSolutionError
    from ..statics import solve_equilibrium

    bodies = {n: b.model_copy(update={"kind": "free"}) if n in names else b for n, b in system.bodies.items()}
    where = f"analysis.body_motions ({', '.join(names)}: mean_offset 'equilibrium')"
    try:
        free = MooringSystem(points=system.points, bodies=bodies, lines=system.lines)
        eq = solve_equilibrium(free, case.environment)
    except (InputError, NoSolutionError, ConvergenceError) as err:
        raise InputError(f"{where}: the static equilibrium of the free body could not be found: {err} Suggested fix: "
                         "give the body's mass, volume, centres and waterplane (it floats), or the mean offset "
                         "itself.") from None
    motions = dict(a.body_motions)
    for n in names:
        pose = np.asarray(eq.body_position[eq.body_names.index(n)], float) - np.asarray(system.bodies[n].position)
        motions[n] = motions[n].model_copy(update={"mean_offset": tuple(float(v) for v in pose)})
    return a.model_copy(update={"body_motions": motions})


def most_loaded_at_start(case) -> str:
    """The line ``damaged_lines: most_loaded`` removes from a ``system_dynamic`` case: the line of the largest
    tension in the intact static equilibrium the run starts from (the bodies under their steady
    ``external_force``, a body of a ``rao`` motion with ``mean_offset: equilibrium`` free;
    :func:`seacable.system.statics.solve_equilibrium`, :mod:`seacable.system.damaged`)."""
    from ...errors import NoSolutionError
    from ..statics import solve_equilibrium
    from ..statics_mode import needs_fe

    system = case.system()
    a = case.analysis
    lines = tuple(system.lines)
    names = [n for n, m in a.body_motions.items() if isinstance(m, RAOMotion) and m.mean_offset == "equilibrium"]
    bodies = {n: b.model_copy(update={"kind": "free"}) if n in names else b for n, b in system.bodies.items()}
    loaded = any(b.kind == "free" and b.hydrodynamics is not None for b in system.bodies.values())
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", SeacableWarning)  # the run itself warns of what the statics see
            if (needs_fe(case.environment, system.lines) or loaded) and not names:
                # what the catenary statics cannot see (a current, a wind, a body's mean wave drift): the finite-
                # element start of the intact run itself
                intact = a.model_copy(update={"damaged_lines": ()})
                fe = build_system_fe(system, case.environment, intact)
                state = static_system(fe, tol=intact.tolerance)
                index = {n: i for i, n in enumerate(fe.line_names)}
                tensions = [float(np.max(state.tension[np.asarray(fe.line_elements[index[n]])])) for n in lines]
                return most_loaded_line(lines, tensions, "")
            eq = solve_equilibrium(MooringSystem(points=system.points, bodies=bodies, lines=system.lines),
                                   case.environment)
    except (InputError, NoSolutionError, ConvergenceError) as err:
        raise InputError(f"analysis.damaged_lines 'most_loaded': the intact static equilibrium that tells the most "
                         f"loaded line could not be found: {err} Suggested fix: name the line to remove "
                         "(damaged_lines: [NAME]).") from None
    return most_loaded_line(lines, line_tensions(eq, lines), "")


def start_state(fe: SystemFE, analysis: SystemDynamicAnalysis, environment=None) -> SystemState:
    """The static start of a run: the coupled equilibrium, or the lines' equilibrium with the free bodies held
    (at their given positions, or at the equilibrium plus ``release_offsets``).

    ``start: auto`` falls back, with a warning naming the residual, when the coupled static solve does
    not converge: the free bodies are held where the catenary statics
    (:func:`seacable.system.statics.solve_equilibrium`, given ``environment``) put them, so that the
    release at t = 0 starts near rest, or where the case puts them when that fails too.
    """
    held = analysis.start == "held"
    q = None
    try:
        st = static_system(fe, held=held, tol=analysis.tolerance)
    except ConvergenceError as err:
        if analysis.start != "auto" or not len(fe.free_bodies):
            raise
        where = "where the case puts them"
        if environment is not None:
            from ...errors import InputError, NoSolutionError
            from ..statics import solve_equilibrium

            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", SeacableWarning)
                    eq = solve_equilibrium(fe.system, environment)
                q = np.array([eq.body_position[eq.body_names.index(name)] for name in fe.free_bodies], float)
                where = "at the catenary statics' equilibrium"
            except (InputError, NoSolutionError, ConvergenceError):
                q = None
        warnings.warn(f"system_dynamic: the finite-element static start did not converge ({err}); the free "
                      f"bodies {', '.join(fe.free_bodies)} start held {where} and are released at t = 0. "
                      "Suggested fix: none needed if the release transient is acceptable; otherwise place the "
                      "bodies nearer their equilibrium.", SeacableWarning, stacklevel=2)
        held = True
        st = static_system(fe, held=True, q=q, tol=analysis.tolerance)
    if held:
        st = dataclasses.replace(st, start="held")
    if not analysis.release_offsets:
        return st
    q = st.body_position.copy()
    for name, off in analysis.release_offsets.items():
        q[fe.free_bodies.index(name)] += np.asarray(off, float)
    return static_system(fe, held=True, q=q, X=st.position, tol=analysis.tolerance)


def run_system_dynamic(case, progress=None):
    """Time-domain response of a mooring system (analysis ``system_dynamic``) as a Dataset.

    ``case`` has ``environment``, ``analysis`` (a :class:`SystemDynamicAnalysis`) and a mooring system
    (``case.system()``, ``case.system``, or fields ``points``, ``bodies``, ``lines``).
    """
    setup = prepare_system_dynamic(case)
    a = setup.analysis
    fe = setup.fe
    start = start_state(setup.start_fe, a, case.environment)
    nd = a.numerical_damping
    # lines alone in an irregular sea: the mooring model's compiled loop; else the coupled one (any waves)
    run = (_simulate_lines if fe.model.water.sea is not None and lines_only(fe) else simulate_system)(
        fe, start, a.duration, a.time_step, a.output_interval, analysis=a, tol=min(a.tolerance * 10, 1e-4),
        max_iter=a.max_iterations, progress=progress, beta=(1 + nd) ** 2 / 4, gamma=0.5 + nd)
    removed = [n for n in getattr(case, "lines", None) or () if n not in fe.system.lines]
    return system_result(fe, run, case=case, settings={"damping_ratio": a.damping_ratio, "rayleigh": list(a.rayleigh),
                                                       "start": start.start, "damaged_lines": removed})

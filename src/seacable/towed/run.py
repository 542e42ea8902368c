"""The ``towed_dynamic`` analysis: a case in, a labelled xarray Dataset out."""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from .._validate import in_range
from ..case import Case, TowedDynamicAnalysis
from ..errors import InputError, SeacableWarning
from ..results import make_dataset, var
from .equations import I_OB, I_ON, I_PH, I_SB, I_SN, I_T, I_TH, I_VB, I_VN, I_VT, NV
from .fe_run import check_towed_size, motion_variables, tow_path
from .seabed import seabed_clearance, surface_excursion, warn_depth_not_modelled
from .solver import TowedBodyParameters, cable_parameters, simulate, steady_tow
from .vessel import initial_heading

__all__ = ["PreparedTowed", "case_setup", "prepare_towed_dynamic", "run_towed_dynamic"]

#: Longest plausible towed cable [m]: the longest towed arrays are about 12 km; more is taken for a unit
#: mistake.
MAX_CABLE_LENGTH = 100_000.0

#: Values stored per node and output time: the state, positions, velocities and the Dataset's copies.
_PER_NODE = NV + 6 + 20

REFERENCES = (
    "Paper 000: Park, H. I. & Jung, D. H., nonlinear dynamic analysis of a low-tension towed cable by the "
    "finite difference method (seeds/000): eq. (2)-(21), Tables 1-3, Fig. 4-6.",
    "Ablow, C. M. & Schechter, S. (1983). Numerical simulation of undersea cable dynamics. Ocean Eng. 10(6).",
    "Gobat, J. I. & Grosenbaugh, M. A. (2006). Time-domain numerical simulation of ocean cable structures. "
    "Ocean Eng. 33, 1373-1400.",
)


def case_setup(case: Case, with_motion: bool = False):
    """Parameter vector, node count, vessel path (callable), body and solver keywords of a box-scheme case; with
    ``with_motion``, also the tow point's motion on the vessel's RAOs (:func:`seacable.towed.fe_run.tow_path`)."""
    a: TowedDynamicAnalysis = case.analysis
    env = case.environment
    if len(case.line.segments) != 1 or case.line.attachments:
        raise InputError(
            f"the box formulation of towed_dynamic models a uniform cable, but the line has "
            f"{len(case.line.segments)} segment(s) and {len(case.line.attachments)} attachment(s). Suggested fix: "
            "use formulation: finite_element (composite cables and bodies in line), or give one line type and put "
            "a weight at the lower end as 'analysis.body'.")
    if a.tangential_drag is None:
        a = a.model_copy(update={"tangential_drag": "paper000"})
    lt = case.line.segments[0].line_type
    ei = lt.bending_stiffness
    if not (ei is not None and math.isfinite(ei) and ei > 0):
        named = f" (line type '{lt.name}')" if getattr(lt, "name", None) else ""
        raise InputError(
            f"line.segments[0].line_type.bending_stiffness{named} must be > 0 N m^2 for towed_dynamic, got "
            f"{ei} N m^2: the box scheme of paper 000 carries the curvatures as unknowns and needs EI to keep a "
            "low-tension cable well posed. Suggested fix: give the cable's EI (a solid section has "
            "E pi d^4 / 64; a small value such as 1 N m^2 stands in for a cable with little stiffness).")
    par = cable_parameters(
        case.line.length, a.n_nodes, lt.mass_per_length, lt.submerged_weight(env.water_density, env.gravity),
        lt.diameter, axial_stiffness=lt.effective_axial_stiffness(), bending_stiffness=lt.bending_stiffness,
        drag_normal=lt.effective_drag()[0], drag_tangential=lt.effective_drag()[1],
        added_mass_normal=lt.added_mass_normal,
        added_mass_tangential=lt.added_mass_tangential, water_density=env.water_density,
        tangential_drag=a.tangential_drag)
    body = None
    if a.body is not None:
        body = TowedBodyParameters(mass=a.body.mass, added_mass=a.body.added_mass,
                                   weight_in_water=a.body.weight_in_water, drag_area=a.body.drag_area)
    path, motion = tow_path(case)
    path(np.array([0.0, a.duration]))  # a table too short fails here, before the run
    kwargs = dict(output_interval=a.output_interval, current=env.current, body=body,
                  water_density=env.water_density, current_follows_vessel=a.current_follows_vessel,
                  tol=a.tolerance, max_iter=a.max_iterations)
    return (par, a.n_nodes, path, kwargs, motion) if with_motion else (par, a.n_nodes, path, kwargs)


@dataclass(frozen=True)
class PreparedTowed:
    """What the time loop of a towed-cable run needs (see :func:`prepare_towed_dynamic`)."""

    parameters: np.ndarray
    n_nodes: int
    path: object
    options: dict
    initial_state: np.ndarray
    motion: object = None  # the tow point's motion on the vessel's RAOs (seacable.vessel_motion), or None


def _check_start_direction(a: TowedDynamicAnalysis, path, length: float) -> None:
    """Warn when the vessel's velocity at t = 0 points against where it goes (a table's spline artefact)."""
    _, vel = path(np.array([0.0]))
    u = vel[0, :2]
    speed = math.hypot(*u)
    if speed == 0.0:
        return
    heading = initial_heading(a.vessel, a.duration, distance=1e-3 * length)
    along = (u[0] * math.cos(heading) + u[1] * math.sin(heading)) / speed
    if along < 0.0:
        warnings.warn(
            f"analysis.vessel: the tow point's velocity at t = 0 ({u[0]:.3g}, {u[1]:.3g}) m/s points against "
            f"the direction it then travels (heading {math.degrees(heading):.1f} deg); the steady start is "
            "computed for that velocity. A table that starts from rest gives its spline's artefact here. "
            "Suggested fix: start the table with the vessel already moving, or add a short run-in.",
            SeacableWarning, stacklevel=3)


def prepare_towed_dynamic(case: Case):
    """Every check of a ``towed_dynamic`` case that can be made before its time loop: the box scheme's
    (:func:`prepare_towed_box`) or the finite-element formulation's
    (:func:`seacable.towed.fe_run.prepare_towed_fe`)."""
    in_range("line.length", case.line.length, 0.0, MAX_CABLE_LENGTH, "m",
             "give the cable length in metres (the longest towed cables are about 12 km).")
    if case.analysis.formulation == "finite_element":
        from .fe_run import prepare_towed_fe

        return prepare_towed_fe(case)
    return prepare_towed_box(case)


def prepare_towed_box(case: Case) -> PreparedTowed:
    """Every check of a box-scheme ``towed_dynamic`` case that can be made before its time loop.

    The cable (one uniform segment, plausible length, bending stiffness > 0), the body, the vessel
    path over the whole run (a table must cover it; a velocity at t = 0 pointing against the path's
    first displacement is warned about), the size of the run
    (:func:`seacable._limits.check_run_size`) and the initial steady tow (a vessel at rest in still
    water is refused). A given ``environment.depth`` is warned about: this model has no seabed
    contact.

    Raises
    ------
    InputError, ConvergenceError
        As :func:`run_towed_dynamic` would before its first step.
    """
    a: TowedDynamicAnalysis = case.analysis
    par, n, path, kwargs, motion = case_setup(case, with_motion=True)
    check_towed_size(case, n, _PER_NODE)
    _check_start_direction(a, path, case.line.length)
    _, vel0 = path(np.array([0.0]))
    body = kwargs["body"]
    h0 = steady_tow(par, n, vel0[0], kwargs["current"], body, water_density=kwargs["water_density"],
                    current_follows_vessel=kwargs["current_follows_vessel"])
    depth = case.environment.depth
    from .equations import integrate_positions

    pos = np.zeros((n, 3))
    integrate_positions(h0, np.asarray(path(np.array([0.0]))[0][0], float), par, pos)
    j = int(np.argmax(pos[:-1, 2]))
    if pos[j, 2] > 1e-6 * max(1.0, case.line.length):
        raise InputError(
            f"the steady tow that starts the run puts node {j}{' (the towed body)' if j == 0 and body else ''} "
            f"{pos[j, 2]:.4g} m above the sea surface, and the box formulation weighs every node as immersed. "
            "Suggested fix: a heavier body or cable (less buoyancy), or formulation: finite_element, which weighs "
            "a node above the water at its dry weight.")
    grid = _grid(case)
    if grid is not None:  # the tow point's path and the start over the grid, the start above it
        grid.check_covers(path(np.linspace(0.0, a.duration, 201))[0], "tow point's path")
        grid.check_covers(pos, "towed line's nodes at the start")
        into = grid.at(pos[:, 0], pos[:, 1])[0] - pos[:, 2]
        j = int(np.argmax(into))
        if into[j] > 0.0:
            raise InputError(
                f"the steady tow that starts the run puts node {j}{' (the towed body)' if j == 0 and body else ''} "
                f"{into[j]:.4g} m below the seabed of environment.seabed.grid at x = {pos[j, 0]:.1f} m, y = "
                f"{pos[j, 1]:.1f} m, and the box formulation has no seabed contact. Suggested fix: formulation: "
                "finite_element (seabed contact), a shorter cable or a faster tow.")
        depth = case.environment.origin_depth()
    elif depth is not None:
        j = int(np.argmin(pos[:, 2]))
        if pos[j, 2] < -depth:
            raise InputError(
                f"the steady tow that starts the run puts node {j}{' (the towed body)' if j == 0 and body else ''} "
                f"{-pos[j, 2]:.4g} m deep, below the seabed at {depth:g} m (environment.depth), and the box "
                "formulation has no seabed contact. Suggested fix: formulation: finite_element (seabed contact), "
                "a shorter cable or a faster tow.")
    warn_depth_not_modelled("towed_dynamic (box formulation)", depth)
    return PreparedTowed(par, n, path, kwargs, h0, motion)


def run_towed_dynamic(case: Case, progress=None):
    """Run a ``towed_dynamic`` case; see :func:`seacable.run`.

    ``analysis.formulation``: ``finite_element`` (the default, :func:`seacable.towed.fe_run.run_towed_fe`) or
    ``box`` (paper 000's scheme, below).

    The Dataset has dims ``time`` and ``node`` (node 0 at the lower end, the last at the vessel),
    coordinate ``s`` (unstretched arc length from the lower end) and the positions, forces,
    curvatures, velocities and angles of every node, plus ``top_tension`` and the vessel track.
    An interrupted run (Ctrl-C) returns what it computed, with the attribute ``interrupted = 1``.
    """
    a: TowedDynamicAnalysis = case.analysis
    if a.formulation == "finite_element":
        from .fe_run import run_towed_fe

        return run_towed_fe(case, prepare_towed_dynamic(case), progress=progress)
    prep = prepare_towed_dynamic(case)
    n = prep.n_nodes
    res = simulate(prep.parameters, n, prep.path, a.duration, a.time_step, progress=progress,
                   initial_state=prep.initial_state, **prep.options)
    h, pos, vel = res.state, res.position, res.velocity
    tow = res.vessel_position
    at_surface = bool(np.all(tow[:, 2] == 0.0))
    td = ("time", "node")
    data = {
        "x": var(td, pos[..., 0], "m", "node position X"),
        "y": var(td, pos[..., 1], "m", "node position Y"),
        "z": var(td, pos[..., 2], "m", "node elevation (Z up, 0 at the sea surface)"),
        "tension": var(td, h[..., I_T], "N", "effective tension"),
        "shear_n": var(td, h[..., I_SN], "N", "shear force, normal direction"),
        "shear_b": var(td, h[..., I_SB], "N", "shear force, binormal direction"),
        "curvature_n": var(td, h[..., I_ON], "m-1", "curvature about the normal, d(theta)/ds"),
        "curvature_b": var(td, h[..., I_OB], "m-1", "curvature about the binormal, cos(theta) d(phi)/ds"),
        "velocity_t": var(td, h[..., I_VT], "m s-1", "cable velocity, tangential component"),
        "velocity_n": var(td, h[..., I_VN], "m s-1", "cable velocity, normal component"),
        "velocity_b": var(td, h[..., I_VB], "m s-1", "cable velocity, binormal component"),
        "velocity_x": var(td, vel[..., 0], "m s-1", "cable velocity X"),
        "velocity_y": var(td, vel[..., 1], "m s-1", "cable velocity Y"),
        "velocity_z": var(td, vel[..., 2], "m s-1", "cable velocity Z"),
        "azimuth": var(td, h[..., I_PH], "rad", "tangent azimuth phi, from X towards Y"),
        "inclination": var(td, h[..., I_TH], "rad",
                           "tangent angle theta below the horizontal (negative: rising to the vessel)"),
        "top_tension": var("time", h[:, -1, I_T], "N", "tension at the vessel"),
        "lower_end_depth": var("time", -pos[:, 0, 2], "m",
                               "depth of the lower end below the surface" + (
                                   " (the tow point is at the surface: also its depth below the ship)"
                                   if at_surface else "")),
        "layback": var("time", np.hypot(pos[:, 0, 0] - tow[:, 0], pos[:, 0, 1] - tow[:, 1]), "m",
                       "horizontal distance from the tow point to the lower end"
                       + (" (the towed body)" if a.body is not None else "")),
        "vessel_x": var("time", tow[:, 0], "m", "tow point X"),
        "vessel_y": var("time", tow[:, 1], "m", "tow point Y"),
    }
    if not at_surface:
        data["depth_below_ship"] = var("time", tow[:, 2] - pos[:, 0, 2], "m",
                                       "depth of the lower end below the tow point")
    data["surface_excursion"] = var("time", surface_excursion(res.time, pos[..., 2], analysis="towed_dynamic (box)"),
                                    "m", "highest node (the tow point left out) above the still water level "
                                    "(positive: out of the water, where the box scheme still weighs it as immersed)")
    grid = _grid(case)  # the grid's depth under each node
    depth = case.environment.depth if grid is None else case.environment.origin_depth()
    if depth is not None:
        data["seabed_clearance"] = var("time", seabed_clearance(
            res.time, pos[..., 2], depth, analysis="towed_dynamic",
            node_name=lambda j: f"node {j}" + ("" if j else " (the towed body)" if a.body else " (the lower end)"),
            floor=None if grid is None else grid.at(pos[..., 0], pos[..., 1])[0]),
            "m", "least height of a node above the seabed (negative: below it; no seabed contact modelled)")
    data.update(motion_variables(prep.motion, res.time))
    coords = {"time": var("time", res.time, "s", "time"),
              "s": var("node", res.s, "m", "unstretched arc length from the lower end")}
    settings = dict(res.settings)
    settings.update({"n_nodes": n, "newton_iterations": res.iterations, "steps": res.steps,
                     "halved_steps": res.halvings, "wall_time_s": round(res.wall_time, 4),
                     "interrupted": int(res.interrupted), "tangential_drag": a.tangential_drag or "paper000",
                     "formulation": "box",
                     "current_follows_vessel": int(a.current_follows_vessel),
                     "scheme": "box (centred in s and t), Newton-Raphson, block tri-diagonal solve"})
    ds = make_dataset(data, coords, analysis="towed_dynamic", case=case, references=REFERENCES,
                      settings=settings)
    ds.attrs["interrupted"] = int(res.interrupted)
    return ds


def _grid(case: Case):
    """The case's seabed grid (:class:`seacable.bathymetry.SeabedGrid`), None without one."""
    from ..bathymetry import cartesian_grid

    bed = case.environment.seabed
    return None if bed.grid is None else cartesian_grid(bed.grid)

"""The ``towed_dynamic`` analysis in its finite-element formulation (:mod:`seacable.towed.fe`)."""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from .._limits import check_run_size
from ..case import Case, TowedDynamicAnalysis
from ..environment import IrregularWaves
from ..errors import InputError
from ..mooring.run import water_of
from ..results import make_dataset, var
from ..vessel_motion import bind_vessel_motion
from .fe import TOLERANCE, TowedSystem, simulate_towed, steady_start, towed_system
from .fe_kernel import MERGE
from .vessel import initial_heading, sample_path

__all__ = ["PreparedTowedFE", "check_towed_size", "prepare_towed_fe", "run_towed_fe", "tow_path"]

REFERENCES = (
    "Paper 004 (seeds/004): truss finite elements, Newmark's method, Morison loads, seabed contact.",
    ("Hall, M. & Goupee, A. (2015). Validation of a lumped-mass mooring line model with DeepCwind semisubmersible "
     "model test data. Ocean Eng. 104, 590-603."),
    ("Buckham, B., Driscoll, F. R. & Nahon, M. (2004). Development of a finite element cable model for use in "
     "low-tension dynamics simulation. J. Appl. Mech. 71, 476-485."),
)

#: Values stored per node slot and output: positions, velocities, tensions (twice), arc length.
_PER_NODE = 12


@dataclass(frozen=True)
class PreparedTowedFE:
    """What the time loop of a finite-element towed run needs (see :func:`prepare_towed_fe`)."""

    system: TowedSystem
    path: object
    deployed: object
    initial: np.ndarray
    points: tuple  # (name, s [m], node) of the body and each attachment
    motion: object = None  # the tow point's motion on the vessel's RAOs (seacable.vessel_motion), or None


def _checked_winch(a: TowedDynamicAnalysis, system: TowedSystem, length: float):
    """The deployed length as a function of time, after the checks of the pay-out schedule; None: no winch."""
    w = a.winch
    if w is None:
        return None
    deployed = functools.partial(w.deployed, length0=length)
    if w.rate is None and abs(w.lengths[0] - length) > 1e-9 * length and w.times[0] <= 0.0:
        raise InputError(f"analysis.winch: the pay-out table starts at {w.lengths[0]:g} m deployed, but the line is "
                         f"{length:g} m long (line.length at t = 0). Suggested fix: start the table at the line's "
                         "length, or give the line the length deployed at the start.")
    if w.rate is None and w.times[0] > 0.0 and abs(w.lengths[0] - length) > 1e-9 * length:
        raise InputError(f"analysis.winch: the pay-out table starts at t = {w.times[0]:g} s with {w.lengths[0]:g} m "
                         f"deployed, but the line is {length:g} m long before it. Suggested fix: start the table "
                         "at t = 0 with the line's length.")
    w.check_against(length)
    times = np.linspace(0.0, a.duration, max(2, math.ceil(a.duration / a.time_step) + 1))
    if w.times is not None:
        times = np.union1d(times, np.clip(w.times, 0.0, a.duration))
    lengths = deployed(times)
    least = system.lock + MERGE * system.element_length
    k = int(np.argmin(lengths))
    if lengths[k] < least:
        what = ("the top segment starts" if system.lock > 0 else "the lower end is") + f" at s = {system.lock:g} m"
        raise InputError(f"analysis.winch hauls the cable in to {lengths[k]:g} m deployed at t = {times[k]:g} s, past "
                         f"its length: {what} (a joint, an attachment or the body cannot pass the sheave) and the "
                         f"least length the model keeps is {least:g} m. Suggested fix: stop the haul-in earlier "
                         "(a 'length' of at least that), or haul in less.")
    return deployed


def tow_path(case: Case):
    """The tow point's path of a ``towed_dynamic`` case, ``path(times)`` -> positions and velocities (n, 3), and the
    motion on the vessel's RAOs in it (None without ``analysis.motion``): the vessel path
    (:func:`seacable.towed.vessel.sample_path`) plus the motion's offsets and their velocities
    (:func:`seacable.vessel_motion.bind_vessel_motion`, the vessel heading its path's at the start). The
    formulations take the tow point's acceleration from these velocities."""
    a: TowedDynamicAnalysis = case.analysis
    track = functools.partial(sample_path, a.vessel)
    if a.motion is None:
        return track, None
    p0, _ = track(np.array([0.0]))
    heading = initial_heading(a.vessel, a.duration, distance=1e-3 * case.line.length)
    motion = bind_vessel_motion(a.motion, case.environment, heading=heading, start=p0[0, :2], duration=a.duration)

    def path(times):
        p, v = track(times)
        off, vel, _ = motion(np.atleast_1d(np.asarray(times, float)))
        return p + off, v + vel

    return path, motion


def check_towed_size(case: Case, nodes: int, per_node: int) -> None:
    """Refuse a ``towed_dynamic`` run whose steps or stored values (``per_node`` a node and output) exceed the
    limits (:func:`seacable._limits.check_run_size`), either formulation."""
    a: TowedDynamicAnalysis = case.analysis
    n_out = math.floor(a.duration / (a.output_interval or a.time_step) + 1e-9)
    check_run_size(f"towed_dynamic case '{case.name}'", steps=a.duration / a.time_step,
                   stored_values=(n_out + 1) * nodes * per_node,
                   fix="shorten analysis.duration, lengthen analysis.time_step or analysis.output_interval, or use "
                       "fewer nodes")


def prepare_towed_fe(case: Case) -> PreparedTowedFE:
    """Every check of a finite-element ``towed_dynamic`` case that can be made before its time loop, and the
    steady start (:func:`seacable.towed.fe.steady_start`).

    Raises
    ------
    InputError, ConvergenceError
        As :func:`run_towed_fe` would before its first step.
    """
    a: TowedDynamicAnalysis = case.analysis
    env = case.environment
    if isinstance(env.waves, IrregularWaves):
        raise InputError("environment.waves: towed_dynamic does not take an irregular sea (its kinematics grid "
                         "would have to follow the vessel). Suggested fix: a regular wave, or none.")
    if a.current_follows_vessel:
        raise InputError("analysis.current_follows_vessel turns the current with the vessel, which only the box "
                         "formulation does. Suggested fix: formulation: box, or give the current's heading.")
    path, motion = tow_path(case)
    p0, v0 = path(np.array([0.0]))  # a table too short fails below, before the run
    path(np.array([0.0, a.duration]))
    water = water_of(case)
    if water.grid is not None:  # the tow point's whole path over the grid (the line trails it: a margin astern)
        water.grid.check_covers(path(np.linspace(0.0, a.duration, 201))[0], "tow point's path")
    floor = float(water.seabed_z(p0[0, 0], p0[0, 1]))
    if p0[0, 2] < floor:
        raise InputError(f"the tow point starts {-p0[0, 2]:g} m deep, below the seabed at {-floor:g} m "
                         "(environment.depth or seabed.profile or grid). Suggested fix: check the vessel path's z "
                         "and the depth.")
    system = towed_system(case.line, p0[0], water, n_nodes=a.n_nodes, body=a.body,
                          tangential_drag=a.tangential_drag or "common")
    deployed = _checked_winch(a, system, case.line.length)
    net = system.model.network
    longest = float(np.max(deployed(np.linspace(0.0, a.duration, 64)))) if deployed else case.line.length
    slots = net.n_nodes + math.ceil(max(0.0, longest - case.line.length) / system.element_length) + 2
    check_towed_size(case, slots, _PER_NODE)
    X0 = steady_start(system, p0[0], v0[0])
    if env.depth is not None or water.tabulated:
        if water.grid is not None:
            water.grid.check_covers(X0, "towed line's nodes at the start")
        into = water.seabed_z(X0[:, 0], X0[:, 1]) - X0[:, 2]
        k = int(np.argmax(into))
        if into[k] > max(float(np.max(net.diameter)), 0.05):
            raise InputError(f"the steady start puts node {k} (s = {net.arc_length[k]:g} m) {into[k]:g} m into the "
                             "seabed: the seabed contact cannot carry it. Suggested fix: a stiffer "
                             "analysis.seabed_contact (or the body's seabed_area), or check the weights.")
    points = []
    if a.body is not None:
        points.append(("body", 0.0, 0))
    for k, att in enumerate(case.line.attachments):
        node = int(np.argmin(np.abs(net.arc_length - att.s)))
        points.append((att.name or f"attachments[{k}] ({att.kind})", float(att.s), node))
    return PreparedTowedFE(system, path, deployed, X0, tuple(points), motion)


def _node_tension(tension, n_nodes):
    """Element tensions onto the nodes (the mean of a node's two elements, its one at the ends), (nt, slots)."""
    nt, ne = tension.shape
    out = np.full((nt, ne + 1), np.nan)
    out[:, 0] = tension[:, 0]
    out[:, 1:-1] = 0.5 * (tension[:, :-1] + tension[:, 1:])
    rows = np.arange(nt)
    last = n_nodes - 1
    out[rows, last] = tension[rows, last - 1]
    return out


def _material_arc(res) -> np.ndarray:
    """The arc length of each node slot while it holds cable (not the tow point, whose arc length is the deployed
    length): a slot keeps its arc length from birth to retirement. [m]"""
    slots = res.arc_length.shape[1]
    cable = np.arange(slots)[None, :] < (res.n_nodes[:, None] - 1)
    arc = np.where(cable, res.arc_length, np.nan)
    out = np.full(slots, np.nan)
    held = cable.any(axis=0)
    out[held] = np.nanmax(arc[:, held], axis=0)
    tow = res.n_nodes[0] - 1  # a run without a winch: the tow point's slot too
    if np.all(res.n_nodes == res.n_nodes[0]):
        out[tow] = res.arc_length[0, tow]
    return out


def run_towed_fe(case: Case, prep: PreparedTowedFE, progress=None):
    """Run a finite-element ``towed_dynamic`` case from its checks' result ``prep`` (:func:`prepare_towed_fe`); see
    :func:`seacable.towed.run.run_towed_dynamic`."""
    a: TowedDynamicAnalysis = case.analysis
    out = a.output_interval or a.time_step
    res = simulate_towed(prep.system, prep.path, a.duration, a.time_step, out, deployed=prep.deployed,
                         initial=prep.initial, tol=TOLERANCE, max_iter=a.max_iterations,
                         spectral_radius=a.spectral_radius, progress=progress)
    pos, vel = res.position, res.velocity
    tow = res.vessel_position
    td = ("time", "node")
    top = res.top_force
    horizontal = np.hypot(top[:, 0], top[:, 1])
    low = pos[:, 0]
    data = {
        "x": var(td, pos[..., 0], "m", "node position X (NaN: not in the water)"),
        "y": var(td, pos[..., 1], "m", "node position Y"),
        "z": var(td, pos[..., 2], "m", "node elevation (Z up, 0 at the sea surface)"),
        "tension": var(td, _node_tension(res.tension, res.n_nodes), "N",
                       "effective tension"),
        "velocity_x": var(td, vel[..., 0], "m s-1", "node velocity X"),
        "velocity_y": var(td, vel[..., 1], "m s-1", "node velocity Y"),
        "velocity_z": var(td, vel[..., 2], "m s-1", "node velocity Z"),
        "top_tension": var("time", np.linalg.norm(top, axis=1), "N", "force of the line on the tow point"),
        "top_angle": var("time", np.arctan2(-top[:, 2], horizontal), "rad",
                         "angle of that force below the horizontal at the tow point"),
        "lower_end_depth": var("time", -low[:, 2], "m", "depth of the lower end below the surface"),
        "depth_below_ship": var("time", tow[:, 2] - low[:, 2], "m", "depth of the lower end below the tow point"),
        "layback": var("time", np.hypot(low[:, 0] - tow[:, 0], low[:, 1] - tow[:, 1]), "m",
                       "horizontal distance from the tow point to the lower end"
                       + (" (the towed body)" if a.body is not None else "")),
        "vessel_x": var("time", tow[:, 0], "m", "tow point X"),
        "vessel_y": var("time", tow[:, 1], "m", "tow point Y"),
        "deployed_length": var("time", res.deployed, "m", "unstretched cable length from the lower end to the "
                                                         "tow point"),
        "paid_out_length": var("time", res.deployed - case.line.length, "m",
                               "cable paid out since t = 0 (negative: hauled in)"),
    }
    data.update(motion_variables(prep.motion, res.time))
    coords = {"time": var("time", res.time, "s", "time"),
              "s": var("node", _material_arc(res), "m", "unstretched arc length from the lower end")}
    if prep.deployed is not None:
        data["arc_length"] = var(td, res.arc_length, "m", "unstretched arc length of the node from the lower end "
                                                          "(the tow point's: the deployed length)")
        data["nodes_in_water"] = var("time", res.n_nodes, "1", "nodes from the lower end to the tow point")
    if prep.points:
        idx = np.array([p[2] for p in prep.points])
        pts = pos[:, idx]
        data["point_layback"] = var(("time", "point"), np.hypot(pts[..., 0] - tow[:, None, 0],
                                                                 pts[..., 1] - tow[:, None, 1]), "m",
                                    "horizontal distance from the tow point to the body and each attachment")
        data["point_depth"] = var(("time", "point"), tow[:, None, 2] - pts[..., 2], "m",
                                  "depth of the body and each attachment below the tow point")
        coords["point_s"] = var("point", np.array([p[1] for p in prep.points]), "m",
                                "unstretched arc length of the body and each attachment from the lower end")
        coords["point"] = var("point", np.array([p[0] for p in prep.points]), "",
                              "the body and the attachments")
    water = prep.system.model.water
    depth = case.environment.depth
    if depth is not None or water.tabulated:
        if water.tabulated:  # the height above the profile or the grid under the node
            height = pos[..., 2] - water.seabed_z(pos[..., 0], pos[..., 1])
        else:
            height = -math.sin(water.slope) * pos[..., 0] + math.cos(water.slope) * (pos[..., 2] + depth)
        data["seabed_clearance"] = var("time", np.nanmin(height, axis=1), "m",
                                       "least height of a node above the seabed (contact modelled: a node on it "
                                       "is pressed in by its weight over the contact stiffness)")
    settings = {"formulation": "finite_element", "n_nodes": int(prep.system.model.network.n_nodes),
                "newton_iterations": res.iterations, "steps": res.steps, "node_births": res.births,
                "node_retirements": res.retirements, "wall_time_s": round(res.wall_time, 4),
                "interrupted": int(res.interrupted), "tangential_drag": a.tangential_drag or "common",
                "element_length_m": prep.system.element_length, "spectral_radius": a.spectral_radius,
                "scheme": "lumped masses on elastic elements (paper 004), generalised alpha, Newton, banded LU"}
    ds = make_dataset(data, coords, analysis="towed_dynamic", case=case, references=REFERENCES, settings=settings)
    ds.attrs["interrupted"] = int(res.interrupted)
    return ds


def motion_variables(motion, times) -> dict:
    """The tow point's offsets from the vessel path by the vessel's motion on its RAOs (none without it)."""
    if motion is None:
        return {}
    off = motion(np.asarray(times, float))[0]
    return {f"vessel_motion_{axis}": var("time", off[:, k], "m", f"{axis} offset of the tow point from the vessel "
                                                                 "path by the vessel's motion on its RAOs")
            for k, axis in enumerate("xyz")}

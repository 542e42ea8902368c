"""The result of a coupled system run as a Dataset: lines, bodies, points, anchors and failures
(:func:`system_result`).
"""

from __future__ import annotations

import numpy as np

from ..._cf import ANGLES
from ...mooring.outputs import elevation_variables
from ...results import make_dataset, var
from ..statics.model import euler_rate_map
from ..ties import run_tie_variables
from .fe import SystemFE
from .loop import SystemRun

DOFS = ("x", "y", "z", "roll", "pitch", "yaw")

REFERENCES = (
    ("Paper 004: finite-element analysis of guyed-tower mooring lines (seeds/004): truss elements with "
     "geometric nonlinearity, Newmark-beta with Newton-Raphson."),
    "Bathe, K.-J. (1996). Finite Element Procedures. Prentice Hall, sections 6.3 and 9.2.4.",
    ("Hall, M. (2020). MoorDyn V2: new capabilities in mooring system components and load cases. "
     "ASME OMAE 2020 (rigid bodies coupled with lumped-mass lines)."),
    ("Hall, M. et al. (2021). MoorPy: quasi-static mooring analysis in Python. NREL/TP (Body hydrostatics: "
     "weight at the CG, buoyancy, waterplane heave stiffness)."),
)
#: added when a free body carries a hydrodynamic database or wind and current areas (issue 39)
FLOATING_REFERENCES = (
    "Cummins, W. E. (1962). The impulse response function and ship motions. Schiffstechnik 9 (radiation memory).",
    ("Ogilvie, T. F. (1964). Recent progress toward the understanding and prediction of ship motions. 5th ONR "
     "Symposium on Naval Hydrodynamics (the retardation kernel's A and B)."),
    ("Newman, J. N. (1974). Second-order, slowly-varying forces on vessels in irregular waves. Int. Symp. on "
     "Dynamics of Marine Vehicles and Structures in Waves (slow drift)."),
    "WAMIT User Manual, version 7 (the database's files and conventions).",
    "DNV-RP-C205 (2021). Environmental conditions and environmental loads, sections 2.3 (wind) and 3.5 (JONSWAP).",
)


def _padded(per_line, width, fill=np.nan, lead=()):
    """Stack per-line arrays (..., k_i) into (..., line, width), NaN padded (``lead`` + (0, width): no lines)."""
    if not per_line:
        return np.full(tuple(lead) + (0, width), fill)
    out = []
    for a in per_line:
        a = np.asarray(a, float)
        padw = [(0, 0)] * (a.ndim - 1) + [(0, width - a.shape[-1])]
        out.append(np.pad(a, padw, constant_values=fill))
    return np.stack(out, axis=-2)


def _turned_directions(fe: SystemFE, bodies: list, bp: np.ndarray):
    """The hinge table's given directions (time, h, 3) at each output: each held end on a body turned with the
    body's pose (a prescribed body's motion turns it by ``R(d)`` from its given pose); None when no held end is on a
    moving body (:func:`seacable.system.bending.held_directions`)."""
    from ...mooring.motion import rotation_matrix
    from ..bending import held_directions, pose_rotations

    if not fe.model.hinges.shape[0]:
        return None
    rotations = {}
    for k, name in enumerate(bodies):
        body = fe.system.bodies[name]
        if name in fe.free_bodies:
            rotations[name] = pose_rotations(bp[:, k])
        elif body.kind == "prescribed" and fe.body_motions.get(name) is not None:
            d = bp[:, k, 3:] - np.asarray(body.position[3:])
            rotations[name] = pose_rotations(np.pad(d, ((0, 0), (3, 0)))) @ rotation_matrix(*body.position[3:])
    return held_directions(fe, rotations)


def line_end_force_series(fe: SystemFE, run: SystemRun, directions=None) -> np.ndarray:
    """Force of each line on its two end points at the outputs of a run, (time, line, 2, 3), end A then end B. [N]

    The single line's definition (:func:`seacable.mooring.outputs.line_end_forces`, the same function): the end
    element's pull, the loads of the half element lumped at the end node (weight in water, drag, added mass and
    inertia at the stored velocities and accelerations, seabed contact; the seabed carrying the half element's
    weight at a grounded anchor) and, for a line with bending stiffness, its hinges' forces on the end node (a held
    end's shear), the held ends' ``directions`` (time, h, 3) those of each output (:func:`_turned_directions`; None:
    the hinge table's). A run that gives its lines' end forces itself (``run.end_force``: quasi-static lines, their
    catenaries') gives them."""
    from ...mooring.outputs import line_end_forces

    if run.end_force is not None:
        return np.asarray(run.end_force, float)
    nt, nl = len(run.time), len(fe.line_names)
    knodes = run.kinematic_nodes
    V = run.velocity if knodes is None else run.velocity[:, knodes]
    out = np.zeros((nt, nl, 2, 3))
    for j in range(nl):
        out[:, j] = line_end_forces(fe.model, run.position, V, run.acceleration, run.time, knodes, line=j,
                                    end_directions=directions)
    return out


def _bending_outputs(fe: SystemFE, run: SystemRun, directions) -> dict:
    """Curvature, bend moment, declination (time, line, node) and shear (time, line, element) of lines with bending
    stiffness (:func:`seacable.system.bending.line_bending`), each held end on a body turned with the body's pose at
    each output time (``directions``, :func:`_turned_directions`); {} when no line bends."""
    from ..bending import BENDING, line_bending

    if not fe.model.hinges.shape[0]:
        return {}
    got = line_bending(fe, run.position, directions)
    return {name: var(("time", "line", BENDING[name][0]), values, BENDING[name][1], BENDING[name][2])
            for name, values in got.items()}


def _end_variables(fe: SystemFE, ends: np.ndarray) -> dict:
    """``fairlead_tension``, ``anchor_tension``, ``anchor_vertical_force`` and ``fairlead_force_x``, ``_y``, ``_z``
    (time, line) of the lines' end forces ``ends`` (time, line, 2, 3) (:func:`line_end_force_series`), as the single
    line reports them (:func:`seacable.mooring.run.network_variables`)."""
    nl = len(fe.line_names)
    rows = np.arange(nl)
    fair = fe.fairlead_end
    at_fair, at_anchor = ends[:, rows, fair], ends[:, rows, 1 - fair]  # (time, line, 3)
    data = {
        "fairlead_tension": var(("time", "line"), np.linalg.norm(at_fair, axis=-1), "N",
                                "tension at the fairlead end of the line (its end element and half-element loads)"),
        "anchor_tension": var(("time", "line"), np.linalg.norm(at_anchor, axis=-1), "N",
                              "tension at the anchor end of the line (its end element and half-element loads)"),
        "anchor_vertical_force": var(("time", "line"), at_anchor[..., 2], "N",
                                     "vertical force of the line on its anchor, upward positive (its end element "
                                     "and half-element loads)"),
    }
    for k, name in enumerate("xyz"):
        data[f"fairlead_force_{name}"] = var(("time", "line"), at_fair[..., k], "N",
                                             f"{name} force of the line on its fairlead end")
    return data


def system_result(fe: SystemFE, run: SystemRun, *, case=None, settings=None):
    """The Dataset of a coupled run."""
    sysm = fe.system
    nl = len(fe.line_names)
    nmax = max((len(n) for n in fe.line_nodes), default=0)
    emax = max((len(e) for e in fe.line_elements), default=0)
    nt = len(run.time)
    data = {}
    for k, name in enumerate("xyz"):
        data[name] = var(("time", "line", "node"), _padded([run.position[:, nodes, k] for nodes in fe.line_nodes], nmax, lead=(nt,)),
                         "m", {"x": "x position", "y": "y position",
                               "z": "elevation (0 at the still water level)"}[name])
    data["segment_tension"] = var(("time", "line", "element"),
                                  _padded([run.tension[:, els] for els in fe.line_elements], emax, lead=(nt,)), "N",
                                  "element effective tension")
    ft = np.full(nl, np.nan)
    for j, li in enumerate(fe.con_line):
        if li >= 0 and np.isfinite(run.failure_time[j]):
            ft[li] = np.nanmin([ft[li], run.failure_time[j]])
    data["failure_time"] = var("line", ft, "s", "time the line failed (NaN: intact)")
    mbl = [[seg.line_type.breaking_load for seg in sysm.lines[name].line.segments] for name in fe.line_names]
    data["breaking_load"] = var("line", np.array([min(m) if None not in m else np.nan for m in mbl], float), "N",
                                "minimum breaking load of the line (its weakest segment; NaN: not given)")
    bodies = list(sysm.bodies)
    bp = np.zeros((nt, len(bodies), 6))
    bv = np.zeros((nt, len(bodies), 6))
    bw = np.zeros((nt, len(bodies), 3))
    for k, name in enumerate(bodies):
        body = sysm.bodies[name]
        if name in fe.free_bodies:
            j = fe.free_bodies.index(name)
            bp[:, k], bv[:, k] = run.body_position[:, j], run.body_velocity[:, j]
            if run.body_angular_velocity is not None:
                bw[:, k] = run.body_angular_velocity[:, j]
        else:
            bp[:, k] = body.position
            mot = fe.body_motions.get(name) if body.kind == "prescribed" else None
            if mot is not None:
                d, dd, _ = mot.dofs(run.time)
                bp[:, k] += d
                bv[:, k] = dd
                for i in range(nt):  # the motion turns the body by R(d) from its given pose: w = E(d) d'
                    bw[i, k] = euler_rate_map(d[i, 3:]) @ dd[i, 3:]
    directions = _turned_directions(fe, bodies, bp)
    data.update(_end_variables(fe, line_end_force_series(fe, run, directions)))
    data.update(_bending_outputs(fe, run, directions))
    tie_data, tie_coords = run_tie_variables(fe, run)
    data.update(tie_data)
    coords = {"time": var("time", run.time, "s", "time"),
              "line": var("line", list(fe.line_names), "1", "line"),
              "node": var("node", np.arange(nmax), "1", "node index along the line, 0 at end A"),
              "element": var("element", np.arange(emax), "1", "element index along the line, 0 at end A"),
              "s": var(("line", "node"), _padded([np.r_[0.0, np.cumsum(fe.model.network.length[e])]
                                                  for e in fe.line_elements], nmax), "m",
                       "unstretched arc length from end A")}
    coords.update(tie_coords)
    if bodies:
        coords["body"] = var("body", bodies, "1", "body")
        coords["axis"] = var("axis", ["x", "y", "z"], "1", "global axis")
        coords["angle"] = var("angle", list(ANGLES), "1", "rotation: roll (about x, first), pitch (y), yaw (z, last)")
        # one unit per variable (CF): the translations [m] and the rotations [rad] apart (seacable._cf)
        data["body_position"] = var(("time", "body", "axis"), bp[..., :3], "m", "body reference point")
        data["body_rotation"] = var(("time", "body", "angle"), bp[..., 3:], "rad",
                                    "body rotation (roll, pitch, yaw: global angles)")
        data["body_velocity"] = var(("time", "body", "axis"), bv[..., :3], "m s-1",
                                    "body reference point velocity")
        data["body_rotation_rate"] = var(("time", "body", "angle"), bv[..., 3:], "rad s-1",
                                         "rate of change of the body rotation (roll, pitch, yaw)")
        data["body_angular_velocity"] = var(("time", "body", "axis"), bw, "rad s-1",
                                            "body angular velocity, global axes")
    # the sea that drove the run: its surface at x = y = 0, as a mooring_dynamic result holds it
    data.update(elevation_variables(fe.model.water, run.time))
    title = getattr(case, "name", None) or "system_dynamic"
    floating = any(sysm.bodies[n].hydrodynamics is not None or sysm.bodies[n].wind is not None
                   or sysm.bodies[n].current is not None for n in fe.free_bodies)
    references = REFERENCES + (FLOATING_REFERENCES if floating else ())
    ds = make_dataset(data, coords, analysis="system_dynamic", references=references, title=title,
                      case=case if hasattr(case, "model_dump") else None,  # a case file's, as YAML (a deck: its file)
                      settings={"elements": int(fe.model.network.n_elements), "nodes": int(fe.model.network.n_nodes),
                                "time_step": run.time_step, "steps": run.steps, "newton_iterations": run.iterations,
                                **(settings or {})})
    ds.attrs["interrupted"] = int(run.interrupted)
    ds.attrs["wall_time"] = run.wall_time
    if fe.model.water.depth is not None:
        ds.attrs["depth"] = float(fe.model.water.depth)
    return ds

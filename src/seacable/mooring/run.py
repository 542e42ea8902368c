"""The mooring analyses of a case (``mooring_static``, ``mooring_pushover``, ``mooring_dynamic``) as Datasets."""

from __future__ import annotations

import math

import numpy as np

from ..case import Case, MooringDynamicAnalysis, MooringPushoverAnalysis
from ..extremes import snap_loads
from ..results import make_dataset, var
from ..statics.run import line_arrays
from .motion import bind
from .network import FIXED, PRESCRIBED, Network, catenary_positions, network_from_line
from .solver import MooringModel, MooringRun, Water, pushover, simulate, static_equilibrium

__all__ = [
    "REFERENCES",
    "case_model",
    "network_variables",
    "run_mooring_dynamic",
    "run_mooring_pushover",
    "run_mooring_static",
    "water_of",
]

REFERENCES = (
    "Paper 004: finite-element analysis of guyed-tower mooring lines with clump weights (seeds/004): "
    "truss elements with geometric nonlinearity (eq. A6-A10), Newmark-beta with Newton-Raphson, section 3.",
    "Bathe, K.-J. (1996). Finite Element Procedures. Prentice Hall, sections 6.3 and 9.2.4.",
    "Hall, M. & Goupee, A. (2015). Validation of a lumped-mass mooring line model with DeepCwind "
    "semisubmersible model test data. Ocean Engineering 104, 590-603 (MoorDyn: seabed and damping rules).",
)


def water_of(case: Case) -> Water:
    """The :class:`~seacable.mooring.solver.Water` of a case's environment and seabed contact."""
    env = case.environment
    a = case.analysis
    cur = env.current
    depths, speeds = ((0.0,), (cur.speed,)) if cur.depths is None else (cur.depths, cur.speeds)
    w = env.waves
    contact = a.seabed_contact
    alpha = a.rayleigh[0] if isinstance(a, MooringDynamicAnalysis) else 0.0
    return Water(density=env.water_density, gravity=env.gravity, depth=env.depth, slope=env.seabed.slope,
                 seabed_stiffness=contact.stiffness, seabed_damping=contact.damping, friction=env.seabed.friction,
                 friction_velocity=contact.friction_velocity, current_depths=tuple(depths),
                 current_speeds=tuple(speeds), current_heading=cur.heading,
                 wave_height=w.height if w else 0.0, wave_period=w.period if w else 10.0,
                 wave_heading=w.heading if w else 0.0, wave_phase=w.phase if w else 0.0, rayleigh_mass=alpha)


def case_model(case: Case, *, end_b: str = "prescribed", fairlead=None) -> MooringModel:
    """The mooring model of a case's line: anchor (node 0) to fairlead, initial shape on the catenary."""
    a = case.analysis
    ax, az = case.anchor_position()
    fx, fz = a.fairlead if fairlead is None else fairlead
    anchor, fair = (ax, 0.0, az), (fx, 0.0, fz)
    env = case.environment
    ratio, beta = (a.damping_ratio, a.rayleigh[1]) if isinstance(a, MooringDynamicAnalysis) else (0.0, 0.0)
    net = network_from_line(case.line, anchor, fair, water_density=env.water_density, gravity=env.gravity,
                            n_elements=a.n_elements, element_length=a.element_length, damping_ratio=ratio,
                            stiffness_proportional=beta, end_b=end_b)
    lengths, weights, ea, loads = line_arrays(case)
    start = catenary_positions(anchor, fair, net.arc_length, lengths, weights, ea, point_loads=loads,
                               depth=env.depth, slope=env.seabed.slope)
    if start is not None:
        net = net.replace(position=start)
    return MooringModel(net, water_of(case))


def _node_tension(net: Network, tension):
    """Element tensions averaged onto the nodes (end nodes take their one element), (..., n)."""
    tension = np.asarray(tension)
    total = np.zeros(tension.shape[:-1] + (net.n_nodes,))
    count = np.zeros(net.n_nodes)
    for end in (0, 1):
        np.add.at(total, (..., net.elements[:, end]), tension)
        np.add.at(count, net.elements[:, end], 1)
    return total / np.maximum(count, 1)


def _contact_length(model: MooringModel, X):
    """Unstretched length of line resting on the seabed (nodes below the seabed plane), (...,). [m]"""
    net, water = model.network, model.water
    if water.depth is None:
        return np.zeros(X.shape[:-2])
    share = np.zeros(net.n_nodes)
    np.add.at(share, net.elements[:, 0], 0.5 * net.length)
    np.add.at(share, net.elements[:, 1], 0.5 * net.length)
    s = water.slope
    pen = -(-math.sin(s) * X[..., 0] + math.cos(s) * (X[..., 2] + water.depth))
    return np.sum(np.where(pen > 0, share, 0.0), axis=-1)


def network_variables(model: MooringModel, X, tension, support, dims=("node",)):
    """Shape, tensions and end forces of one line network at one or more states."""
    net = model.network
    lead = tuple(dims[:-1])
    fair = np.flatnonzero(net.kind == PRESCRIBED)
    f_end = fair[-1] if fair.size else net.line_nodes[0][-1]
    data = {
        "x": var(dims, X[..., 0], "m", "x position"),
        "y": var(dims, X[..., 1], "m", "y position"),
        "z": var(dims, X[..., 2], "m", "elevation (0 at the still water level)"),
        "tension": var(dims, _node_tension(net, tension), "N", "effective tension (node average)"),
        "segment_tension": var(lead + ("element",), tension, "N", "element effective tension"),
        "fairlead_tension": var(lead, np.linalg.norm(support[..., f_end, :], axis=-1), "N",
                                "tension at the fairlead (force of the line on it)"),
        "anchor_tension": var(lead, np.linalg.norm(support[..., 0, :], axis=-1), "N",
                              "tension at the anchor (force of the line on it)"),
        "seabed_contact_length": var(lead, _contact_length(model, X), "m", "length of line on the seabed"),
    }
    for k, name in enumerate("xyz"):
        data[f"fairlead_force_{name}"] = var(lead, support[..., f_end, k], "N",
                                             f"{name} force of the line on the fairlead")
    return data


def _coords(net: Network):
    return {"node": var("node", np.arange(net.n_nodes), "1", "node index, 0 at the anchor"),
            "s": var("node", net.arc_length, "m", "unstretched arc length from the anchor"),
            "element": var("element", np.arange(net.n_elements), "1", "element index, 0 at the anchor")}


def _settings(model: MooringModel, **more):
    net = model.network
    return {"elements": int(net.n_elements), "nodes": int(net.n_nodes), "mass": "lumped",
            "seabed_stiffness": model.water.seabed_stiffness, "seabed_damping": model.water.seabed_damping,
            **more}


def run_mooring_static(case: Case):
    """Static equilibrium of the finite-element model (analysis ``mooring_static``)."""
    a = case.analysis
    model = case_model(case)
    st = static_equilibrium(model, tol=a.tolerance)
    data = network_variables(model, st.position, st.tension, st.support)
    return make_dataset(data, _coords(model.network), analysis="mooring_static", case=case, references=REFERENCES,
                        settings=_settings(model, iterations=st.iterations, residual=st.residual))


def run_mooring_pushover(case: Case):
    """Quasi-static force-excursion curve of the finite-element model (analysis ``mooring_pushover``)."""
    a: MooringPushoverAnalysis = case.analysis
    model = case_model(case)
    offsets = np.asarray(a.offset_values(), float)
    states = pushover(model, offsets, tol=a.tolerance)
    X = np.array([st.position for st in states])
    T = np.array([st.tension for st in states])
    S = np.array([st.support for st in states])
    data = network_variables(model, X, T, S, dims=("offset", "node"))
    data["H_fairlead"] = var("offset", -S[:, np.flatnonzero(model.network.kind == PRESCRIBED)[-1], 0], "N",
                             "horizontal force of the line on the fairlead, towards the anchor")
    coords = {**_coords(model.network), "offset": var("offset", offsets, "m", "horizontal fairlead offset")}
    return make_dataset(data, coords, analysis="mooring_pushover", case=case, references=REFERENCES,
                        settings=_settings(model))


def run_events(run: MooringRun) -> dict:
    """Snap loads and the count of slack elements of a time-domain run, as result variables."""
    ts, es, ps = snap_loads(run.time, run.tension)
    return {"snap_time": var("snap", ts, "s", "time of the peak after an element pulled taut from slack"),
            "snap_element": var("snap", es, "1", "element of the snap load (index in the network)"),
            "snap_tension": var("snap", ps, "N", "snap load (peak tension after slack)"),
            "slack_elements": var("time", np.sum(run.tension <= 0.0, axis=1), "1", "number of slack elements")}


def run_result(model: MooringModel, run: MooringRun, *, case=None, analysis="mooring_dynamic", settings=None):
    """A Dataset of a time-domain run of a single-line network."""
    net = model.network
    data = network_variables(model, run.position, run.tension, run.support, dims=("time", "node"))
    data.update(run_events(run))
    coords = {**_coords(net), "time": var("time", run.time, "s", "time")}
    ds = make_dataset(data, coords, analysis=analysis, case=case, references=REFERENCES,
                      settings=_settings(model, time_step=run.time_step, steps=run.steps,
                                         newton_iterations=run.iterations, **(settings or {})))
    ds.attrs["interrupted"] = int(run.interrupted)
    ds.attrs["wall_time"] = run.wall_time
    return ds


def run_mooring_dynamic(case: Case, progress=None):
    """Time-domain response of the finite-element model (analysis ``mooring_dynamic``)."""
    a: MooringDynamicAnalysis = case.analysis
    free = a.end_b == "free"
    model = case_model(case, end_b="free" if free else "prescribed", fairlead=a.release_from)
    if free and a.release_from is not None:
        held = MooringModel(model.network.replace(kind=_held(model.network)), model.water)
        start = static_equilibrium(held, tol=a.tolerance).position
    else:
        start = static_equilibrium(model, tol=a.tolerance).position
    motion = bind(a.motion, model.network.channel_positions(start), a.duration)
    run = simulate(model, motion, a.duration, a.time_step, a.output_interval, initial=start,
                   tol=min(a.tolerance * 10, 1e-4), max_iter=a.max_iterations, progress=progress)
    return run_result(model, run, case=case, settings={"damping_ratio": a.damping_ratio,
                                                       "rayleigh": list(a.rayleigh)})


def _held(net: Network):
    """Kinds with the last node fixed (a free end held for the static start)."""
    kind = net.kind.copy()
    kind[net.line_nodes[0][-1]] = FIXED
    return kind

"""The mooring analyses of a case (``mooring_static``, ``mooring_pushover``, ``mooring_dynamic``) as Datasets."""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from .._limits import check_run_size
from ..case import Case, MooringDynamicAnalysis, MooringPushoverAnalysis
from ..errors import InputError
from ..statics.run import line_arrays
from ..ties import tie_points, ties_of
from .bending import bending_variables
from .checks import check_motion, check_network
from .friction import friction_pushover, friction_static
from .kernel import E_BEDRAMP as K_BEDRAMP
from .kernel import H_D, H_DCH, H_ECH, H_EI, H_INNER, H_KIND
from .motion import RAOMotion, bind, forcing_period, sea_of
from .network import FIXED, FREE, PRESCRIBED, Network, catenary_positions, network_from_line
from .outputs import (
    at_motion_start,
    elevation_variables,
    grounded_end_force,
    height_above_seabed,
    line_end_forces,
    tie_variables,
    turning_hinges,
    water_of_environment,
    wave_elevation,
)
from .solver import MooringModel, MooringRun, Water, line_end_nodes, simulate, static_equilibrium

__all__ = [
    "REFERENCES",
    "MooringDynamicSetup",
    "case_model",
    "contact_length",
    "elevation_variables",
    "grounded_end_force",
    "height_above_seabed",
    "line_end_forces",
    "network_variables",
    "output_count",
    "point_variables",
    "prepare_mooring_dynamic",
    "prepare_mooring_pushover",
    "prepare_mooring_static",
    "run_attributes",
    "run_mooring_dynamic",
    "run_mooring_pushover",
    "run_mooring_static",
    "run_variables",
    "slack_variables",
    "snap_variables",
    "solve_mooring_pushover",
    "solve_mooring_static",
    "stored_per_output",
    "water_of",
    "wave_elevation",
]

REFERENCES = (
    ("Paper 004: finite-element analysis of guyed-tower mooring lines with clump weights (seeds/004): "
    "truss elements with geometric nonlinearity (eq. A6-A10), Newmark-beta with Newton-Raphson, section 3."),
    "Bathe, K.-J. (1996). Finite Element Procedures. Prentice Hall, sections 6.3 and 9.2.4.",
    ("Hall, M. & Goupee, A. (2015). Validation of a lumped-mass mooring line model with DeepCwind "
    "semisubmersible model test data. Ocean Engineering 104, 590-603 (MoorDyn: seabed and damping rules)."),
)


def water_of(case: Case) -> Water:
    """The :class:`~seacable.mooring.solver.Water` of a case's environment and seabed contact."""
    a = case.analysis
    alpha = a.rayleigh[0] if isinstance(a, MooringDynamicAnalysis) else 0.0
    compression = getattr(a, "compression", False)  # a mooring analysis's (the towed lines' take none)
    return water_of_environment(case.environment, a.seabed_contact, alpha, compression=compression)


def case_model(case: Case, *, end_b: str = "prescribed", fairlead=None) -> MooringModel:
    """The mooring model of a case's line: anchor (node 0) to fairlead, initial shape on the catenary."""
    a = case.analysis
    ax, az = case.anchor_position()
    fx, fz = a.fairlead if fairlead is None else fairlead
    anchor, fair = (ax, 0.0, az), (fx, 0.0, fz)
    env = case.environment
    ratio, beta = (a.damping_ratio, a.rayleigh[1]) if isinstance(a, MooringDynamicAnalysis) else (0.0, 0.0)
    points = tie_points(case.line, env)
    ties = tuple((tie, points[i]) for i, tie in ties_of(case.line))
    net = network_from_line(case.line, anchor, fair, water_density=env.water_density, gravity=env.gravity,
                            n_elements=a.n_elements, element_length=a.element_length, damping_ratio=ratio,
                            stiffness_proportional=beta, end_b=end_b, ties=ties)
    conditions = (("anchor_end_condition", a.anchor_end_condition), ("fairlead_end_condition", a.fairlead_end_condition))
    held = tuple(cond.hinge(0, end) for end, (_, cond) in enumerate(conditions) if cond.holds)
    if held:
        ei = np.zeros(net.n_elements) if net.bending_stiffness is None else net.bending_stiffness
        for end, (name, cond) in enumerate(conditions):
            e = 0 if end == 0 else net.n_elements - 1
            if cond.holds and not ei[e] > 0:
                raise InputError(
                    f"analysis.{name} is {cond.type}, but the line's end element there has no bending stiffness "
                    f"(EI = {ei[e]:g} N m^2): a moment at the end needs a line that bends. Suggested fix: give "
                    f"the end segment's line type 'bending_stiffness' in N m^2 (e.g. 1e4), or leave {name} "
                    "out (pinned).")
            laws = net.element_moment_curvature
            if cond.type == "spring" and laws is not None and laws[e] is not None:
                raise InputError(
                    f"analysis.{name} is a rotational spring, but the line's end element there has a nonlinear "
                    "moment-curvature law (a line type's, a bend stiffener's or a bend restrictor's): a spring in "
                    "series with a nonlinear half element is not supported. Suggested fix: type: clamped, or a "
                    "linear law (bending_stiffness) on the end segment.")
        net = net.replace(end_hinges=held)
    lengths, weights, ea, loads = line_arrays(case)
    held = [(0.0, anchor)] + sorted((tie.s, p) for tie, p in ties if tie.type == "clamp" and tie.stiffness is None)
    water = water_of(case)
    grid = water.grid  # a grid: the catenary on the plane under the anchor along the line, lifted onto the grid
    depth, slope = (env.depth, env.seabed.slope) if grid is None else grid.plane_under(anchor, fair)
    start = _start_positions(held + [(float(np.sum(lengths)), fair)], net.arc_length, lengths, weights, ea, loads,
                             depth=depth, slope=slope, buoyant=bool(case.line.sections))
    return MooringModel(net.replace(position=start if grid is None else grid.lift(start)), water)


def _start_positions(held, s, lengths, weights, ea, loads, **kwargs):
    """The start shape of a line held at the points ``held`` (``(arc length, (x, y, z))`` from end A to end B: its
    ends and its rigid clamps): the catenary start (:func:`seacable.mooring.network.catenary_positions`) of each
    piece between two held points, the piece's segments and point loads cut from the line's. [m]"""
    if len(held) == 2:  # ends only: the line's own start, as before clamps
        return catenary_positions(held[0][1], held[1][1], s, lengths, weights, ea, point_loads=loads, **kwargs)
    ends = np.concatenate(([0.0], np.cumsum(lengths)))
    X = np.zeros((len(s), 3))
    for (s0, p0), (s1, p1) in itertools.pairwise(held):
        cut = np.clip(ends, s0, s1)
        keep = np.diff(cut) > 0.0
        inside = (s >= s0 - 1e-9) & (s <= s1 + 1e-9)
        piece = tuple((q - s0, w) for q, w in loads if s0 < q < s1)
        X[inside] = catenary_positions(p0, p1, s[inside] - s0, np.diff(cut)[keep], np.asarray(weights)[keep],
                                       np.asarray(ea)[keep], point_loads=piece, **kwargs)
    return X


def _node_tension(net: Network, tension):
    """Element tensions averaged onto the nodes (end nodes take their one element), (..., n)."""
    tension = np.asarray(tension)
    total = np.zeros(tension.shape[:-1] + (net.n_nodes,))
    count = np.zeros(net.n_nodes)
    for end in (0, 1):
        nodes = net.elements[:, end]
        first = int(nodes[0]) if nodes.size else 0
        if np.array_equal(nodes, np.arange(first, first + nodes.size)):
            # consecutive nodes (a line numbered from end A): the same additions on a slice, without the copies of
            # a fancy index
            total[..., first:first + nodes.size] += tension
            count[first:first + nodes.size] += 1
        elif np.unique(nodes).size == nodes.size:  # each node once (a line): the same additions, without add.at
            total[..., nodes] += tension
            count[nodes] += 1
        else:
            np.add.at(total, (..., nodes), tension)
            np.add.at(count, nodes, 1)
    return np.divide(total, np.maximum(count, 1), out=total)


def contact_length(model: MooringModel, X):
    """Unstretched length of line resting on the seabed, interpolated between nodes, (...,). [m]

    Each node's share of line (half of each adjacent element) counts in the fraction of its weight
    that the seabed carries: the penalty spring's force over the node's weight, between 0 and 1. On a
    flat seabed the reactions add up to the weight of the grounded line, so the sum is the grounded
    length to the accuracy of the model's end forces, wherever the touchdown lies inside an element
    (a node near the touchdown carries part of its weight, the hanging line the rest). A held node
    (an anchor) or a model without seabed stiffness counts as on the seabed when it touches it.
    """
    got = _seabed_shares(model, X)
    if got is None:
        return np.zeros(np.asarray(X).shape[:-2])
    frac, share = got
    return np.sum(np.multiply(frac, share, out=frac), axis=-1)


def touchdown_variables(model: MooringModel, X, dims=("node",)) -> dict:
    """Where a line leaves the seabed, at each state: ``touchdown_s`` (unstretched arc length from end A),
    ``touchdown_x``, ``touchdown_y`` [m]; {} without a seabed.

    The grounded stretch is the one that holds the line's grounded end (end A when it rests on the seabed, else
    end B), its length the seabed's shares of its nodes as in :func:`contact_length` (a node near the touchdown
    carries part of its weight), so the touchdown moves smoothly through an element and its range over a run is the
    touchdown's migration. NaN at a state where neither end rests on the seabed. A line grounded in several
    stretches (a lazy-S's tied arch, a buoy between two touchdowns) has its touchdown at the end of the first.
    """
    from ..results import var

    got = _seabed_shares(model, X)
    if got is None:
        return {}
    frac, share = got
    s = np.asarray(model.network.arc_length, float)
    on = frac > 0
    from_a = np.sum(frac * share * np.cumprod(on, axis=-1), axis=-1)
    from_b = np.sum((frac * share * np.cumprod(on[..., ::-1], axis=-1)[..., ::-1]), axis=-1)
    s_td = np.where(on[..., 0], from_a, np.where(on[..., -1], s[-1] - from_b, np.nan))
    # the position at s_td along the nodes (linear between them)
    k = np.clip(np.searchsorted(s, np.nan_to_num(s_td), side="right") - 1, 0, s.size - 2)
    u = np.clip((np.nan_to_num(s_td) - s[k]) / (s[k + 1] - s[k]), 0.0, 1.0)
    X = np.asarray(X, float)
    pos = [np.take_along_axis(X[..., c], k[..., None], -1)[..., 0] * (1 - u)
           + np.take_along_axis(X[..., c], k[..., None] + 1, -1)[..., 0] * u for c in range(2)]
    lead = tuple(dims[:-1])
    bad = ~np.isfinite(s_td)
    return {"touchdown_s": var(lead, s_td, "m", "unstretched arc length from end A where the line leaves the seabed"),
            "touchdown_x": var(lead, np.where(bad, np.nan, pos[0]), "m", "x where the line leaves the seabed"),
            "touchdown_y": var(lead, np.where(bad, np.nan, pos[1]), "m", "y where the line leaves the seabed")}


def _seabed_shares(model: MooringModel, X):
    """(fraction of each node's weight the seabed carries (..., node), each node's share of line (node,) [m]) for
    :func:`contact_length`, None without a seabed."""
    net, water = model.network, model.water
    X = np.asarray(X, float)
    if water.depth is None:
        return None
    share = np.zeros(net.n_nodes)
    np.add.at(share, net.elements[:, 0], 0.5 * net.length)
    np.add.at(share, net.elements[:, 1], 0.5 * net.length)
    dl = float(model.env[K_BEDRAMP])
    # the penetration -height_above_seabed(water, X) by the same operations, in two arrays instead of five (a
    # run's block of outputs: each temporary is as large as an output variable)
    if water.tabulated:  # the profile's segment, or the grid's cell, under each node
        pen = -height_above_seabed(water, X)
        depth = np.empty_like(pen)
    else:
        sl = water.slope
        pen = np.multiply(X[..., 0], -math.sin(sl))
        depth = np.add(X[..., 2], water.depth)
        np.multiply(depth, math.cos(sl), out=depth)
        np.add(pen, depth, out=pen)
        np.negative(pen, out=pen)
    touching = pen >= -dl
    kb = water.seabed_stiffness
    if kb > 0:
        # q: the penetration beyond the ramp, the ramp's (pen + dl)^2 / (4 dl) on it, 0 above it; then the
        # fraction of each node's weight the seabed carries (a held node's: touching), each in place
        bed = pen >= dl
        ramp = (pen > -dl) & ~bed
        q = depth
        q.fill(0.0)
        q[bed] = pen[bed]
        q[ramp] = (pen[ramp] + dl) ** 2 / (4 * dl)
        weight = model.weight
        held = (net.kind != FREE) | (weight <= 0)
        np.multiply(kb * model.bedc, q, out=q)
        np.divide(q, np.where(held, 1.0, weight), out=q)
        frac = np.clip(q, 0.0, 1.0, out=q)
        frac[..., held] = touching[..., held]
    else:
        frac = (pen >= 0).astype(float)
    return frac, share


def turning_points(model: MooringModel):
    """The held ends of ``model`` at a prescribed node, which turn with the node's platform: ``(rows, end channels,
    points)``, the hinge rows, the end nodes' motion channels and the points (k, 3) [m] one metre from each end along
    its given direction (into the line), which the platform's rigid motion moves with the end."""
    net = model.network
    rows, channels, points = [], [], []
    for h in range(model.hinges.shape[0]):
        end = int(model.hinges[h, 1])
        if model.hinge_ei[h, H_KIND] == H_INNER or net.channel[end] < 0:
            continue
        rows.append(h)
        channels.append(int(net.channel[end]))
        points.append(net.position[end] + model.hinge_ei[h, H_D:H_D + 3])
    return rows, channels, np.array(points, float).reshape(-1, 3)


def turn_with_motion(model: MooringModel, motion, n_channels: int) -> None:
    """Make ``model``'s held ends at prescribed nodes turn with the platform's motion (:func:`turning_points`): their
    direction points are the bound ``motion``'s channels from ``n_channels`` on, in their order; the kernel takes each
    step's direction from them (:func:`seacable.mooring.kernel.turn_held_ends`), the static start the direction at
    t = 0."""
    rows, channels, _ = turning_points(model)
    if not rows or motion is None:
        return
    at_start = motion(np.zeros(1))[0][0]
    for j, (h, ch) in enumerate(zip(rows, channels)):
        model.hinge_ei[h, H_DCH], model.hinge_ei[h, H_ECH] = n_channels + j, ch
        d = at_start[n_channels + j] - at_start[ch]
        model.hinge_ei[h, H_D:H_D + 3] = d / np.linalg.norm(d)


def turning_end_directions(model: MooringModel, motion, times):
    """The held ends' given directions (nt, h, 3) at ``times`` [s] of a run whose held ends turn with its platform
    (:func:`turn_with_motion`), the others' at rest; None when none turns."""
    table = model.hinge_ei
    turning = turning_hinges(model)
    if motion is None or not np.any(turning):
        return None
    P = motion(np.asarray(times, float))[0]
    out = np.repeat(table[None, :, H_D:H_D + 3], len(times), axis=0)
    for h in np.flatnonzero(turning):
        d = P[:, int(table[h, H_DCH])] - P[:, int(table[h, H_ECH])]
        out[:, h] = d / np.linalg.norm(d, axis=-1, keepdims=True)
    return out


def _fairlead_end(net: Network) -> tuple[int, int]:
    """(anchor end, fairlead end) of a single line, 0 = end A, 1 = end B: the fairlead is the moved end,
    end B unless only end A is moved."""
    nodes = net.line_nodes[0]
    a_moved, b_moved = net.kind[nodes[0]] == PRESCRIBED, net.kind[nodes[-1]] == PRESCRIBED
    return (1, 0) if a_moved and not b_moved else (0, 1)


def network_variables(model: MooringModel, X, tension, support, dims=("node",), *, velocity=None,
                      acceleration=None, time=None, kinematic_nodes=None, own_support=False, end_support=None,
                      end_directions=None):
    """Shape, tensions and end forces of one line at one or more states.

    ``fairlead_tension`` and ``anchor_tension`` are the line's own end tensions
    (:func:`line_end_forces`); ``support`` (the force on each node's support, every line and
    attachment there) is not used for them, unless ``own_support``: ``support`` and ``tension`` are then
    ``model``'s own at these states (a static solve's or a time loop's, evaluated with ``model``'s
    environment), read where they hold the line's end loads (:func:`line_end_forces`); ``end_support``
    (..., 2, 3) gives those support forces at the line's two end nodes only (``support`` then unused). Give ``velocity``,
    ``acceleration`` and ``time`` of a time-domain run so that the end forces include the half element's
    water loads and inertia (``kinematic_nodes``: the nodes they hold, None for all). ``end_directions`` (..., h, 3):
    the bending hinges' given directions at each state (:func:`turning_end_directions`), None: at rest.
    """
    from ..results import var

    net = model.network
    lead = tuple(dims[:-1])
    ends = line_end_forces(model, X, velocity, acceleration, time, kinematic_nodes, end_directions=end_directions,
                           **({"support": support, "tension": tension, "end_support": end_support} if own_support
                              else {}))
    anchor, fair = _fairlead_end(net)
    data = {
        "x": var(dims, X[..., 0], "m", "x position"),
        "y": var(dims, X[..., 1], "m", "y position"),
        "z": var(dims, X[..., 2], "m", "elevation (0 at the still water level)"),
        "tension": var(dims, _node_tension(net, tension), "N", "effective tension (node average)"),
        "segment_tension": var(lead + ("element",), tension, "N", "element effective tension"),
        "fairlead_tension": var(lead, np.linalg.norm(ends[..., fair, :], axis=-1), "N",
                                "tension at the fairlead end of the line (its end element and half-element loads)"),
        "anchor_tension": var(lead, np.linalg.norm(ends[..., anchor, :], axis=-1), "N",
                              "tension at the anchor end of the line (its end element and half-element loads)"),
        "anchor_vertical_force": var(lead, ends[..., anchor, 2], "N",
                                     "vertical force of the line on its anchor, upward positive (its end element "
                                     "and half-element loads)"),
        "seabed_contact_length": var(lead, contact_length(model, X), "m",
                                     "length of line on the seabed"),
        **touchdown_variables(model, X, dims),
    }
    for k, name in enumerate("xyz"):
        data[f"fairlead_force_{name}"] = var(lead, ends[..., fair, k], "N",
                                             f"{name} force of the line on its fairlead end")
    data.update(bending_variables(net, X, dims, end_directions))
    data.update(tie_variables(net, X, support, dims))
    return data


def point_variables(model: MooringModel, support, dims=("node",)):
    """Force on each point of a network (held nodes and MoorDyn points): every line meeting there and
    the point's attachments, dimension ``point``. [N]"""
    from ..results import var

    net = model.network
    points = np.flatnonzero((net.kind != FREE) | ~np.isfinite(net.arc_length))
    lead = tuple(dims[:-1])
    f = np.asarray(support)[..., points, :]
    data = {"point_node": var("point", points, "1", "network node of the point"),
            "point_force": var(lead + ("point",), np.linalg.norm(f, axis=-1), "N",
                               "force of the lines and attachments on the point's support")}
    for k, name in enumerate("xyz"):
        data[f"point_force_{name}"] = var(lead + ("point",), f[..., k], "N", f"{name} force on the point")
    return data


def _coords(net: Network):
    from ..results import var

    return {"node": var("node", np.arange(net.n_nodes), "1", "node index, 0 at the anchor"),
            "s": var("node", net.arc_length, "m", "unstretched arc length from the anchor"),
            "element": var("element", np.arange(net.n_elements), "1", "element index, 0 at the anchor")}


def _settings(model: MooringModel, **more):
    net = model.network
    return {"elements": int(net.n_elements), "nodes": int(net.n_nodes), "mass": "lumped",
            "seabed_stiffness": model.water.seabed_stiffness, "seabed_damping": model.water.seabed_damping,
            **more}


def prepare_mooring_static(case: Case) -> MooringModel:
    """Every check of a ``mooring_static`` case that needs no solve; returns the model to solve.

    Builds the network on its start shape, which runs :func:`seacable.mooring.checks.check_network`
    (nodes under the seabed, ends beyond the stretch limit).
    """
    return case_model(case)


def prepare_mooring_pushover(case: Case) -> tuple[MooringModel, np.ndarray]:
    """Every check of a ``mooring_pushover`` case that needs no solve: the model, and the offsets [m].

    The geometric checks run at the start and with the fairlead at the smallest and largest offset.
    """
    a: MooringPushoverAnalysis = case.analysis
    model = case_model(case)
    offsets = np.asarray(a.offset_values(), float)
    net = model.network
    moved = net.kind == PRESCRIBED
    for off in (offsets.min(), offsets.max()) if offsets.size else ():
        X = net.position.copy()
        X[moved, 0] += off * math.cos(a.heading)
        X[moved, 1] += off * math.sin(a.heading)
        check_network(net.replace(position=X), depth=model.water.depth, slope=model.water.slope,
                      profile=model.water.profile, grid=model.water.grid)
    return model, offsets


@dataclass(frozen=True)
class MooringDynamicSetup:
    """What the time loop of ``mooring_dynamic`` needs (see :func:`prepare_mooring_dynamic`)."""

    model: MooringModel
    start_model: MooringModel  # the model of the static start (a free end B held at release_from)
    motion: object = None      # the bound fairlead motion: times -> positions, velocities, accelerations


def stored_per_output(net: Network, seabed: bool = True) -> int:
    """Values the result of a time-domain run holds per output: per line (each padded to the longest, as in a
    MoorDyn deck's result) the positions and tensions of its nodes, its element tensions, its end tensions,
    its anchor's vertical force, fairlead force and grounded length, with a ``seabed`` its touchdown (s, x, y) (and,
    bending, its curvature, bend moment and declination at the nodes and shear per element); the forces on the points;
    the time, the count of slack elements and the wave elevation. [1]

    The run itself holds a block of outputs at a time (:func:`seacable.mooring.solver.simulate`,
    ``on_outputs``), and a run written to a file as it goes (:class:`seacable.sink.NetcdfSink`) holds
    no more than that: this is the size of a result in memory, or of the file before compression."""
    lines = len(net.line_nodes)
    nodes = max(len(n) for n in net.line_nodes)
    elements = int(np.max(np.bincount(net.element_line, minlength=lines)))
    points = int(np.count_nonzero((net.kind != FREE) | ~np.isfinite(net.arc_length)))
    bending = 3 * nodes + elements if net.hinge_arrays()[0].shape[0] else 0  # curvature, moment, declination, shear
    return lines * (4 * nodes + elements + 7 + 3 * seabed + bending) + 4 * points + 3


def prepare_mooring_dynamic(case: Case) -> MooringDynamicSetup:
    """Every check of a ``mooring_dynamic`` case that can be made before the time loop.

    The geometric checks of the network (:func:`seacable.mooring.checks.check_network`) at the start
    and along the fairlead motion at the output times (:func:`seacable.mooring.checks.check_motion`),
    and the size of the run (:func:`seacable._limits.check_run_size`: time steps, and the values of the
    result, :func:`stored_per_output`).
    """
    a: MooringDynamicAnalysis = case.analysis
    free = a.end_b == "free"
    model = case_model(case, end_b="free" if free else "prescribed", fairlead=a.release_from)
    net = model.network
    steps = a.duration / min(a.time_step, a.output_interval)
    outputs = a.duration / a.output_interval + 1
    check_run_size(f"mooring_dynamic case '{case.name}'", steps=steps,
                   stored_values=outputs * stored_per_output(net, model.water.depth is not None),
                   fix="lengthen analysis.time_step or analysis.output_interval, or shorten analysis.duration")
    start = MooringModel(net.replace(kind=_held(net)), model.water) if free and a.release_from is not None else model
    # the motion moves the held fairlead from where the case puts it (statics does not move it): bind it
    # now (a time series too short fails here) and check it at the output times
    # a held end at the moved fairlead turns with the platform: a point one metre along its direction is moved by the
    # same motion, as extra channels after the network's own (turn_with_motion)
    base = net.channel_positions()
    n_channels = len(base)
    motion = bind(a.motion, np.concatenate((base, turning_points(model)[2])), a.duration, sea=sea_of(model.water))
    if isinstance(a.motion, RAOMotion):  # the platform's mean offset: the static start is there
        model, start = (at_motion_start(m, motion) for m in (model, start))
        net = model.network
    for m in {id(model): model, id(start): start}.values():
        turn_with_motion(m, motion, n_channels)
    times = np.linspace(0.0, a.duration, round(a.duration / a.output_interval) + 1)
    if motion is not None:
        check_motion(net, times, motion(times)[0], depth=model.water.depth, slope=model.water.slope,
                     profile=model.water.profile, grid=model.water.grid)
    # an irregular sea: the size of its kinematics grid over the nodes and the fairlead's range
    model.check_sea(a.duration, np.concatenate((net.position, motion(times)[0].reshape(-1, 3)))
                    if motion is not None else net.position)
    return MooringDynamicSetup(model, start, motion)


def solve_mooring_static(case: Case):
    """The checks and the static equilibrium of a ``mooring_static`` case: ``(model, state)``, what
    :func:`run_mooring_static` reports (no Dataset built: :func:`seacable.simulate.check` calls it)."""
    model = prepare_mooring_static(case)
    return model, friction_static(model, case.analysis.static_friction, tol=case.analysis.tolerance)


def solve_mooring_pushover(case: Case):
    """The checks and the equilibria of a ``mooring_pushover`` case: ``(model, offsets, states)``, what
    :func:`run_mooring_pushover` reports (no Dataset built: :func:`seacable.simulate.check` calls it)."""
    a: MooringPushoverAnalysis = case.analysis
    model, offsets = prepare_mooring_pushover(case)
    direction = (math.cos(a.heading), math.sin(a.heading), 0.0)
    return model, offsets, friction_pushover(model, offsets, direction, a.static_friction, tol=a.tolerance)


def run_mooring_static(case: Case):
    """Static equilibrium of the finite-element model (analysis ``mooring_static``)."""
    from ..results import make_dataset

    model, st = solve_mooring_static(case)
    data = network_variables(model, st.position, st.tension, st.support)
    return make_dataset(data, _coords(model.network), analysis="mooring_static", case=case, references=REFERENCES,
                        settings=_settings(model, iterations=st.iterations, residual=st.residual))


def run_mooring_pushover(case: Case):
    """Quasi-static force-excursion curve of the finite-element model (analysis ``mooring_pushover``)."""
    from ..results import make_dataset, var

    model, offsets, states = solve_mooring_pushover(case)
    X = np.array([st.position for st in states])
    T = np.array([st.tension for st in states])
    S = np.array([st.support for st in states])
    data = network_variables(model, X, T, S, dims=("offset", "node"))
    data["H_fairlead"] = var("offset", -S[:, np.flatnonzero(model.network.kind == PRESCRIBED)[-1], 0], "N",
                             "horizontal force of the line on the fairlead along x, towards the anchor")
    coords = {**_coords(model.network), "offset": var("offset", offsets, "m", "horizontal fairlead offset")}
    return make_dataset(data, coords, analysis="mooring_pushover", case=case, references=REFERENCES,
                        settings=_settings(model))


def output_count(duration: float, output_interval: float) -> int:
    """The outputs of a time-domain run, t = 0 included (:func:`seacable.mooring.solver.simulate`). [1]"""
    return int(round(duration / output_interval)) + 1  # noqa: RUF046 (a numpy float rounds to a float)


def slack_variables(run: MooringRun) -> dict:
    """The count of slack elements at each output of a time-domain run (or a block of its outputs)."""
    from ..results import var

    return {"slack_elements": var("time", np.sum(run.tension <= 0.0, axis=1), "1", "number of slack elements")}


def snap_variables(sink, network: Network) -> dict:
    """Snap loads of a time-domain run (:func:`seacable.extremes.snap_loads`), from the element tensions
    ``segment_tension`` stored in ``sink`` (:mod:`seacable.sink`), read line by line: (line, time, element),
    or (time, element) for a single line. Events are in the order of the times the elements pulled taut, then
    of the elements (network indices)."""
    from ..extremes import snap_rows
    from ..results import var

    time = sink.read("time")
    n_lines = len(network.line_nodes)
    rise, peak_time, element, peak = [], [], [], []
    for li in range(n_lines):
        els = np.flatnonzero(network.element_line == li)
        tension = sink.read("segment_tension", (li,) if n_lines > 1 else ())[:, :els.size]
        k, j, e = snap_rows(time, tension)
        rise.append(k)
        peak_time.append(time[j])
        element.append(els[e])
        peak.append(tension[j, e])
    rise, peak_time, element, peak = (np.concatenate(a) for a in (rise, peak_time, element, peak))
    order = np.lexsort((element, rise))
    return {"snap_time": var("snap", peak_time[order].astype(float), "s",
                             "time of the peak after an element pulled taut from slack"),
            "snap_element": var("snap", element[order].astype(int), "1",
                                "element of the snap load (index in the network)"),
            "snap_tension": var("snap", peak[order].astype(float), "N", "snap load (peak tension after slack)")}


def strength_variables(network: Network) -> dict:
    """The line's ``breaking_load``: the least minimum breaking load of its line types [N] (NaN when one has
    none), what the design checks compare its tension with (:mod:`seacable.design.checks`)."""
    from ..results import var

    mbl = network.breaking_load
    value = float(np.min(mbl)) if mbl is not None and mbl.size and np.all(np.isfinite(mbl)) else math.nan
    return {"breaking_load": var((), value, "N", "minimum breaking load of the line (its weakest segment)")}


def run_attributes(run: MooringRun) -> dict:
    """The attributes of a time-domain result: interrupted or not, the wall time, the time step used and the
    recommended one."""
    return {"interrupted": int(run.interrupted), "wall_time": run.wall_time,
            "time_step": run.time_step,  # the Newmark step used (before any halving) [s]
            "recommended_time_step": run.recommended_time_step}  # solver.recommended_time_step [s]


def run_variables(model: MooringModel, run: MooringRun, motion=None):
    """The variables and coordinates of (a block of outputs of) a time-domain run of a single-line network:
    everything but the snap loads, which take the whole run (:func:`snap_variables`). ``motion``: the run's bound
    motion, whose channels turn its held ends (:func:`turn_with_motion`)."""
    from ..results import var

    turning = turning_end_directions(model, motion, run.time)
    # held ends turning with the platform: the end forces as the loop computed them, at each step's direction
    data = network_variables(model, run.position, run.tension, run.support, dims=("time", "node"),
                             velocity=run.velocity, acceleration=run.acceleration, time=run.time,
                             kinematic_nodes=run.kinematic_nodes, end_directions=turning,
                             own_support=turning is not None and run.support is not None)
    data.update(slack_variables(run))
    data.update(elevation_variables(model.water, run.time))
    return data, {**_coords(model.network), "time": var("time", run.time, "s", "time")}


def run_mooring_dynamic(case: Case, progress=None, out=None):
    """Time-domain response of the finite-element model (analysis ``mooring_dynamic``).

    ``out``: a NetCDF file the outputs are written into as they are computed (:class:`seacable.sink.NetcdfSink`);
    the Dataset returned then reads from it. Without it the result is in memory, filled block by block."""
    from ..sink import open_sink

    a: MooringDynamicAnalysis = case.analysis
    setup = prepare_mooring_dynamic(case)
    model = setup.model
    start = static_equilibrium(setup.start_model, tol=a.tolerance).position
    waves = case.environment.waves
    with open_sink(output_count(a.duration, a.output_interval), out) as sink:
        run = simulate(model, setup.motion, a.duration, a.time_step, a.output_interval, initial=start,
                       tol=min(a.tolerance * 10, 1e-4), max_iter=a.max_iterations, progress=progress,
                       spectral_radius=default_spectral_radius(model) if a.spectral_radius is None
                       else a.spectral_radius,
                       forcing_period=forcing_period(a.motion, getattr(waves, "period", None)
                                                     or getattr(waves, "tp", None)),
                       kinematics=line_end_nodes(model.network),
                       on_outputs=lambda block: sink.append(*run_variables(model, block, setup.motion)))
        events = {**snap_variables(sink, model.network), **strength_variables(model.network)}
    settings = _settings(model, time_step=run.time_step, steps=run.steps, newton_iterations=run.iterations,
                         spectral_radius=run.spectral_radius, damping_ratio=a.damping_ratio,
                         rayleigh=list(a.rayleigh))
    return sink.finish(events, attrs=run_attributes(run), analysis="mooring_dynamic", case=case,
                       references=REFERENCES, settings=settings)


#: The generalised-alpha spectral radius of a mooring_dynamic run with a cable (a line with bending stiffness) when
#: the case gives none: the average-acceleration step (1) rings in a cable's unresolved bending and axial modes, and
#: Newton pays for it (16.7 iterations a step against 5.9 on bench_cable_heave's lazy wave; 20 times the wall time on
#: the 80 m lazy wave of tests/validation/test_lazy_wave_orcaflex.py), while 0.9 moves the heave's peak curvature
#: and tensions there by 0.01-0.09 %
CABLE_SPECTRAL_RADIUS = 0.9


def default_spectral_radius(model) -> float:
    """1 (average acceleration), or :data:`CABLE_SPECTRAL_RADIUS` when a line of ``model`` has bending stiffness."""
    table = model.hinge_ei
    return CABLE_SPECTRAL_RADIUS if table.shape[0] and bool(np.any(table[:, H_EI] > 0.0)) else 1.0


def _held(net: Network):
    """Kinds with the last node fixed (a free end held for the static start)."""
    kind = net.kind.copy()
    kind[net.line_nodes[0][-1]] = FIXED
    return kind

"""What the single-line and the system analyses share around the solver: the force of a line on its end points
(:func:`line_end_forces`, one definition for both), the height of points above the seabed and the force of a line
on an anchor resting on it, the surface elevation output, and a model with its prescribed nodes where a motion
starts.

Below both runners (:mod:`seacable.mooring.run`, :mod:`seacable.system.dynamics`), which import these from here.
"""

from __future__ import annotations

import math

import numpy as np

from ..bathymetry import cartesian_grid
from ..environment import IrregularWaves
from ..seastate import S_MODE
from . import kernel as K
from ._indices import H_D, H_DCH, H_INNER, H_KIND
from .loop import evaluate_states
from .network import FIXED, Network
from .solver import MooringModel, Water, wave_number_or_zero

__all__ = [
    "at_motion_start",
    "elevation_variables",
    "grounded_end_force",
    "height_above_seabed",
    "line_end_forces",
    "seabed_slope",
    "tie_variables",
    "turning_hinges",
    "water_of_environment",
    "wave_elevation",
]


def water_of_environment(environment, seabed_contact, rayleigh_mass: float = 0.0, compression: bool = False) -> Water:
    """The :class:`~seacable.mooring.solver.Water` of an environment (a line's or a system's): density, gravity,
    depth, the seabed (plane, or its profile when the environment has one) with ``seabed_contact``'s stiffness,
    damping and friction velocity, the current profile, regular waves or an irregular sea's components, and
    the mass-proportional Rayleigh damping ``rayleigh_mass`` [1/s], and whether the elements carry ``compression``."""
    env = environment
    cur = env.current
    depths, speeds = ((0.0,), (cur.speed,)) if cur.depths is None else (cur.depths, cur.speeds)
    w = env.waves
    sea = w.components(env.depth, env.gravity) if isinstance(w, IrregularWaves) else None
    w_reg = None if sea is not None else w
    profile = env.seabed.profile
    grid = None if env.seabed.grid is None else cartesian_grid(env.seabed.grid)
    depth = env.depth
    if depth is None and profile is not None:  # the water depth at the origin, the profile's there
        depth = float(np.interp(0.0, profile.distance, profile.depth))
    if depth is None and grid is not None:  # the grid's under the origin (or its nearest point), for the waves
        depth = float(-grid.at(0.0, 0.0)[0])
    return Water(density=env.water_density, gravity=env.gravity, depth=depth, slope=env.seabed.slope,
                 seabed_stiffness=seabed_contact.stiffness, seabed_damping=seabed_contact.damping,
                 friction=env.seabed.friction, friction_velocity=seabed_contact.friction_velocity,
                 current_depths=tuple(depths), current_speeds=tuple(speeds), current_heading=cur.heading,
                 wave_height=w_reg.height if w_reg else 0.0, wave_period=w_reg.period if w_reg else 10.0,
                 wave_heading=w_reg.heading if w_reg else 0.0, wave_phase=w_reg.phase if w_reg else 0.0,
                 rayleigh_mass=rayleigh_mass, sea=sea, stretching=w.stretching if w else "none",
                 profile=None if profile is None else (profile.distance, profile.depth), compression=compression,
                 grid=grid)


def seabed_slope(water: Water, x, y=None):
    """Slope dz/dx [-] of the seabed under ``x`` [m]: the plane's ``tan(slope)``, or the profile's segment's (level
    beyond its ends, the segment above a point at a breakpoint: :func:`seacable.mooring.kernel.seabed_at`); on a
    grid, its gradient along x under ``(x, y)`` (``y`` 0 if not given)."""
    x = np.asarray(x, float)
    if water.grid is not None:
        return water.grid.at(x, np.zeros_like(x) if y is None else y)[1]
    if water.profile is None:
        return np.full_like(x, math.tan(water.slope))
    dist, depth = (np.asarray(v, float) for v in water.profile)
    k = np.clip(np.searchsorted(dist, x, side="right"), 1, dist.size - 1)
    slope = -(depth[k] - depth[k - 1]) / (dist[k] - dist[k - 1])
    return np.where((x <= dist[0]) | (x >= dist[-1]), 0.0, slope)


def height_above_seabed(water: Water, X):
    """Height of points above the seabed, normal to it (negative inside it), (..., n): the plane's, or the profile's
    segment under each point's (the kernel's contact, :func:`seacable.mooring.kernel.seabed_at`), or the grid's
    cell's (:func:`seacable.mooring.kernel.grid_at`). [m]"""
    if water.grid is not None:
        zb, gx, gy = water.grid.at(X[..., 0], X[..., 1])
        return (X[..., 2] - zb) / np.sqrt(1.0 + gx * gx + gy * gy)
    if water.profile is not None:
        slope = seabed_slope(water, X[..., 0])
        return (X[..., 2] - water.seabed_z(X[..., 0])) / np.sqrt(1.0 + slope * slope)
    sl = water.slope
    return -math.sin(sl) * X[..., 0] + math.cos(sl) * (X[..., 2] + water.depth)


def grounded_end_force(pull, half_weight, slope: float = 0.0, normal=None):
    """Force of a line on an end held on the seabed (an anchor), (..., 3). [N]

    The end element pulls along its chord with its tension, ``pull = T d / |d|``; that direction is the line's
    at the element's middle, not at its end: between them the half element's weight in water turns the line
    (the catenary's slope changes by ``w ds / T``). Its weight normal to the seabed is taken off the pull's normal
    component, as far as that does not press the end into the seabed, which carries the rest. A line lying
    along the seabed then pulls along it (the catenary's H, the seabed carrying the weight), a line rising from
    the end pulls up with ``T sin(theta_0)`` to second order, and a line whose touchdown lies within its first
    element (the node beyond it lifted a little off the seabed) shows no uplift: with the pull alone it showed
    up to half the element's weight (1.4 kN on the OC3-Hywind demo's intact anchors, 22.6 m elements).

    Parameters
    ----------
    pull
        The end element's pull on the end, ``T d / |d|``, (..., 3). [N]
    half_weight
        The half end element's weight in water, (...,) or scalar (negative: buoyant). [N]
    slope
        The seabed's slope, rising towards +x. [rad]
    normal
        The seabed's unit normal under each end instead, (..., 3) (a grid's). [-]
    """
    pull = np.asarray(pull, float)
    if normal is not None:  # a grid: each end's own normal, its weight's normal share n_z
        n = np.asarray(normal, float)
        across = np.sum(pull * n, axis=-1)
        kept = np.maximum(across - np.asarray(half_weight, float) * n[..., 2], 0.0)
        return pull + (kept - across)[..., None] * n
    n = np.array([-math.sin(slope), 0.0, math.cos(slope)])
    normal = pull @ n
    kept = np.maximum(normal - np.asarray(half_weight, float) * math.cos(slope), 0.0)
    return pull + (kept - normal)[..., None] * n


def wave_elevation(water: Water, time, x: float = 0.0, y: float = 0.0) -> np.ndarray:
    """Surface elevation [m] at (x, y) [m] at ``time`` [s]: the regular wave's and the irregular sea's
    (by direct summation of its components, not from the grid); zeros in calm water."""
    t = np.asarray(time, float)
    eta = np.zeros_like(t)
    if water.wave_height > 0.0:
        k = wave_number_or_zero(water)
        theta = (k * (x * math.cos(water.wave_heading) + y * math.sin(water.wave_heading))
                 - 2.0 * math.pi / water.wave_period * t + water.wave_phase)
        eta += 0.5 * water.wave_height * np.cos(theta)
    if water.sea is not None:
        eta += water.sea.elevation(t, x, y)
    return eta


def elevation_variables(water: Water, time) -> dict:
    """The ``wave_elevation`` at the origin (x = y = 0) of a run with waves (nothing in calm water)."""
    from ..results import var

    if water.wave_height <= 0.0 and water.sea is None:
        return {}
    return {"wave_elevation": var("time", wave_elevation(water, time), "m",
                                  "water surface elevation at x = y = 0 (0 at the still-water level)")}


def at_motion_start(model: MooringModel, motion) -> MooringModel:
    """``model`` with its prescribed nodes where ``motion`` puts them at t = 0 (a platform's mean offset, where
    a run's static start is solved)."""
    net = model.network
    pres = np.flatnonzero(net.channel >= 0)
    X = net.position.copy()
    X[pres] = motion(np.zeros(1))[0][0, net.channel[pres]]
    return MooringModel(net.replace(position=X), model.water)


def tether_tension(net: Network, X) -> np.ndarray:
    """Tension of each tether of ``net`` (its nodes with ``point_tether``) at the states ``X`` (..., n, 3), (...,
    tethers): ``EA psi(l / L0 - 1)``, the tension-only law of the kernel (:func:`seacable.mooring._ties.tie_loads`)
    with its rounding. [N]"""
    table = net.point_tether
    nodes = np.flatnonzero(table[:, 4] > 0) if table is not None else np.zeros(0, np.int64)
    X = np.asarray(X, float)
    if not nodes.size:
        return np.zeros(X.shape[:-2] + (0,))
    row = table[nodes]
    eps = np.linalg.norm(X[..., nodes, :] - row[:, :3], axis=-1) / row[:, 4] - 1.0
    b = row[:, 5]
    rounded = np.where(b > 0, (eps + b) ** 2 / (4.0 * np.where(b > 0, b, 1.0)), 0.0)
    psi = np.where(eps >= b, eps, np.where(eps > -b, rounded, 0.0))
    return row[:, 3] * psi


def clamp_nodes(net: Network) -> np.ndarray:
    """The clamped nodes of a single line: its inner FIXED nodes (rigid clamps) and those with a spring clamp,
    in the order of the line."""
    inner = np.asarray(net.line_nodes[0])[1:-1]
    rigid = inner[net.kind[inner] == FIXED]
    spring = np.flatnonzero(net.point_clamp[:, 3] > 0) if net.point_clamp is not None else np.zeros(0, np.int64)
    return np.sort(np.concatenate((rigid, spring)).astype(np.int64))


def tie_variables(net: Network, X, support, dims=("node",)) -> dict:
    """The tethers' tension and the clamps' reactions of a single line at its states (nothing without ties).

    ``tether_tension`` (dims ``tether``; its node's arc length ``tether_s``) from the tether's stretch;
    ``clamp_force`` and ``clamp_force_x``, ``_y``, ``_z`` (dims ``clamp``, at ``clamp_s``): the force of the line
    on the clamp, for a rigid clamp the support force of its fixed node (``support`` (..., n, 3): every load on the
    node, the line's two elements, its bending, its half elements' weight, water and seabed loads, and a tether
    there), for a spring clamp the spring's ``k (x - p)``. [N]
    """
    from ..results import var

    lead = tuple(dims[:-1])
    X = np.asarray(X, float)
    data = {}
    table = net.point_tether
    tethered = np.flatnonzero(table[:, 4] > 0) if table is not None else np.zeros(0, np.int64)
    if tethered.size:
        data["tether_s"] = var("tether", net.arc_length[tethered], "m", "arc length of the tethered node")
        data["tether_tension"] = var(lead + ("tether",), tether_tension(net, X), "N", "tension of the tether")
    clamped = clamp_nodes(net)
    if clamped.size:
        force = np.array(np.asarray(support, float)[..., clamped, :])
        if net.point_clamp is not None:
            row = net.point_clamp[clamped]
            spring = row[:, 3] > 0
            force[..., spring, :] = row[spring, 3, None] * (X[..., clamped[spring], :] - row[spring, :3])
        data["clamp_s"] = var("clamp", net.arc_length[clamped], "m", "arc length of the clamped node")
        data["clamp_force"] = var(lead + ("clamp",), np.linalg.norm(force, axis=-1), "N",
                                  "force of the line on the clamp")
        for k, name in enumerate("xyz"):
            data[f"clamp_force_{name}"] = var(lead + ("clamp",), force[..., k], "N",
                                              f"{name} force of the line on the clamp")
    return data


# ------------------------------------------------------------------------------------ a line's force on its ends


def _point_nodes(net: Network) -> np.ndarray:
    """The nodes of ``net`` that are shared points (no arc length: MoorDyn points, a system's points), (n,) bool;
    their attachments are the point's, not a line's."""
    return ~np.isfinite(net.arc_length)


def _loaded_points(net: Network) -> bool:
    """Whether a shared point of ``net`` (:func:`_point_nodes`) carries an attachment (mass, weight, volume,
    hydrodynamic areas): the support forces there are then not a line's own end loads."""
    point = _point_nodes(net)
    loaded = point & ((net.point_mass != 0) | (net.point_weight != 0) | (net.point_volume != 0)
                      | np.any(net.point_hydrodynamics() != 0, axis=1) | (net.point_added_mass != 0))
    return bool(np.any(loaded))


def _joining(elements, a: int, b: int) -> int:
    """The element joining the nodes ``a`` and ``b``."""
    return int(np.flatnonzero(((elements[:, 0] == a) & (elements[:, 1] == b))
                              | ((elements[:, 0] == b) & (elements[:, 1] == a)))[0])


def _end_part(model: MooringModel, line: int):
    """The part of ``model``'s network whose loads reach the two end nodes of its line ``line`` from that line: its
    elements and bending hinges holding an end (another line meeting at a shared point left out), and their nodes.

    Returns a dict: ``ends``, ``nbrs`` and ``end_el`` (the end nodes, their neighbours and the end elements, end A and
    end B, network numbering), ``sub`` (the nodes kept, sorted), ``inside`` (those nodes as a mask over the
    network's), ``args`` (:meth:`~seacable.mooring.solver.MooringModel.element_args` of the part but the hinge table
    and the viscoelastic state, which a run changes: :func:`_evaluate_ends` takes them afresh at each call),
    ``hinge_rows`` (the rows of the hinge table kept), ``fidx``, ``ends_sub`` and ``el_sub`` (renumbered) and
    ``elements`` (the elements kept). The part's nodes carry the loads of its own elements only (half of each) and
    no attachment at a shared point (:func:`_point_nodes`): the loads of
    :func:`seacable.mooring.kernel.loads` at the end nodes are then the line's own, the same floats as the whole
    network of that line alone gives (every term that reaches a node comes from its elements, its hinges and the
    node itself), for a fraction of the work.
    """
    net = model.network
    nodes = np.asarray(net.line_nodes[line], np.int64)
    E = net.elements
    ends = np.array([nodes[0], nodes[-1]], np.int64)
    end_el = [_joining(E, nodes[0], nodes[1]), _joining(E, nodes[-1], nodes[-2])]
    mine = np.zeros(net.n_nodes, bool)
    mine[nodes] = True
    elements = np.flatnonzero(np.isin(E, ends).any(axis=1) & mine[E].all(axis=1))
    H = model.hinges
    hinges = (np.flatnonzero(np.isin(H, ends).any(axis=1) & mine[H].all(axis=1)) if H.size
              else np.zeros(0, np.int64))
    sub = np.unique(np.concatenate([ends, E[elements].ravel(), H[hinges].ravel()]))
    (elem, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, _weight, pmass, padd, pvol, pcda, _bedc, buoy, pbuoy, ts_lo,
     ts_hi, ts_x, ts_y, hinge_nodes, _hinge_ei, _visco) = model.element_args()
    renum = np.searchsorted(sub, elem[elements]).astype(elem.dtype)
    keep = ~_point_nodes(net)[sub]
    # each node's weight and seabed contact width from the part's elements (a model's sum those of every line
    # meeting at a point), as MooringModel lumps them (Network.node_weight)
    weight = np.where(keep, net.point_weight[sub], 0.0)
    half = 0.5 * net.weight_per_length[elements] * net.length[elements]
    np.add.at(weight, renum[:, 0], half)
    np.add.at(weight, renum[:, 1], half)
    bedc = np.zeros(sub.size)
    half = 0.5 * net.diameter[elements] * net.length[elements]
    np.add.at(bedc, renum[:, 0], half)
    np.add.at(bedc, renum[:, 1], half)
    args = (renum, *(a[elements] for a in (L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat)), weight,
            *(np.where(keep, a[sub], 0.0) for a in (pmass, padd, pvol)), np.where(keep[:, None], pcda[sub], 0.0),
            bedc, buoy[elements], np.where(keep, pbuoy[sub], 0.0), ts_lo[elements], ts_hi[elements], ts_x, ts_y,
            np.searchsorted(sub, hinge_nodes[hinges]).astype(hinge_nodes.dtype).reshape(-1, 3))
    inside = np.zeros(net.n_nodes, bool)
    inside[sub] = True
    return {"ends": ends, "nbrs": [int(nodes[1]), int(nodes[-2])], "end_el": end_el, "sub": sub, "inside": inside,
            "args": tuple(np.ascontiguousarray(a) for a in args), "hinge_rows": hinges,
            "fidx": np.ascontiguousarray(model.fidx[sub]), "ends_sub": np.searchsorted(sub, ends).astype(np.int64),
            "el_sub": np.searchsorted(elements, np.asarray(end_el)).astype(np.int64), "elements": elements}


def _end_setup(model: MooringModel, line: int = 0):
    """:func:`_end_part` of ``model``'s line ``line``, built at the first call that needs it and kept on ``model`` (a
    run's outputs call it block after block, with the same model), built again if its network, water, environment
    or hinges were replaced."""
    key = (model.network, model.water, model.env, model.hinges)
    kept = model.__dict__.get("_line_ends")
    if kept is None or not all(a is b for a, b in zip(kept["key"], key)):
        kept = {"key": key, "lines": {}}
        model.__dict__["_line_ends"] = kept
    if line not in kept["lines"]:
        kept["lines"][line] = _end_part(model, line)
    return kept["lines"][line]


def turning_hinges(model: MooringModel) -> np.ndarray:
    """Which rows of ``model``'s hinge table are held ends that turn with a platform's motion channels
    (:func:`seacable.mooring.run.turn_with_motion`)."""
    table = model.hinge_ei
    return (table[:, H_KIND] != H_INNER) & (table[:, H_DCH] >= 0)


def _reads_support(model: MooringModel, time) -> bool:
    """Whether the support forces and element tensions of ``model`` at its states, as a static solve or a time
    loop stores them, hold the line's end loads as :func:`line_end_forces` evaluates them, the same floats: a
    single line (no other line at its ends), no attachment at an end point (:func:`_loaded_points`), no
    viscoelastic element (a time loop's outputs keep their slow stretch apart), and for time-domain states no
    waves (a stored state's time is that of its last step, which may round differently from the output time)."""
    if len(model.network.line_nodes) != 1 or _loaded_points(model.network) or model.visco.shape[0]:
        return False
    if time is not None and np.any(turning_hinges(model)):
        return True  # held ends turning with a platform: the loop's own end loads, at each step's direction
    return time is None or (model.env[K.E_WH] <= 0.0 and model.sea[S_MODE] <= 0.0)


def line_end_forces(model: MooringModel, X, V=None, A=None, time=None, kinematic_nodes=None, *, support=None,
                    tension=None, end_support=None, line: int = 0, end_directions=None):
    """Force of a line on its two end points (end A, end B), (..., 2, 3). [N]

    The pull of the end element plus the loads lumped at the end node from that line's half element
    (weight, seabed, water, inertia) and, for a line with bending stiffness, the forces of its bending hinges on
    the end node (the shear of a held end): the line's own end force, as MoorDyn reports it from the end
    segment. A point's attachments and the other lines meeting there are left out (see
    :func:`seacable.mooring.run.point_variables` for the force on a point). The single-line analyses and the
    system's (``system_static``'s finite-element statics, ``system_dynamic``) all report this force.

    Parameters
    ----------
    model : MooringModel
        The network (a single line, or a system's lines).
    X : array_like
        Node positions (..., n, 3) of the whole network. [m]
    V, A : array_like, optional
        Node velocities and accelerations (..., n, 3), or (..., k, 3) of ``kinematic_nodes`` (the others at rest;
        exact when they hold the line's end nodes and their neighbours,
        :func:`seacable.mooring.solver.line_end_nodes`); None: at rest. [m/s], [m/s^2]
    time : array_like, optional
        Time of each state (...,), for the waves; None: a static state (no waves). [s]
    kinematic_nodes : array_like, optional
        The nodes ``V`` and ``A`` hold; None: all.
    support, tension : array_like, optional
        ``model``'s own support forces ``F - M a`` (..., n, 3) and element tensions (..., e) at these states, as
        :func:`seacable.mooring.solver.static_equilibrium` or :func:`seacable.mooring.solver.simulate` store them
        (evaluated with ``model``'s environment). Where they are the line's own end loads (:func:`_reads_support`)
        the end forces are read from them, the same floats as the evaluation gives, without evaluating the states
        again. [N]
    end_support : array_like, optional
        Instead of ``support``: those support forces at the line's two end nodes only (..., 2, 3). [N]
    line : int
        The line of the network (its index in ``model.network.line_nodes``).
    end_directions : array_like, optional
        The hinge table's given directions (..., h, 3) at each state (a held end turning with a platform or a body:
        :func:`seacable.mooring.run.turning_end_directions`, :func:`seacable.system.bending.held_directions`);
        None: the table's as it stands. [-]

    Returns
    -------
    ndarray
        (..., 2, 3): the force of the line on its end A and end B. [N]
    """
    part = _end_setup(model, line)
    ends, nbrs, end_el = part["ends"], part["nbrs"], part["end_el"]
    net = model.network
    ramp = float(model.env[K.E_BEDRAMP])
    X = np.asarray(X, float)
    lead = X.shape[:-2]
    nt = int(np.prod(lead, dtype=np.int64))
    Xs = X.reshape((nt,) + X.shape[-2:])
    given = support is not None or end_support is not None
    if given and tension is not None and _reads_support(model, time):
        out = (np.asarray(support, float).reshape((nt,) + X.shape[-2:])[:, ends] if end_support is None
               else np.array(end_support, float).reshape((nt, 2, 3)))
        tension = np.asarray(tension, float).reshape((nt, -1))[:, end_el]
    else:
        out, tension = _evaluate_ends(model, part, Xs, lead, V, A, time, kinematic_nodes, end_directions)
    if model.water.depth is not None:
        # an end resting on the seabed: the seabed carries its half element's weight as far as the line lies
        # there; the line pulls along its end element, its end slope to second order (grounded_end_force)
        for j in (0, 1):
            grounded = height_above_seabed(model.water, Xs[:, ends[j]]) <= ramp
            if np.any(grounded):
                d = Xs[grounded, nbrs[j]] - Xs[grounded, ends[j]]
                norm = np.maximum(np.linalg.norm(d, axis=-1), 1e-300)
                half = 0.5 * net.weight_per_length[end_el[j]] * net.length[end_el[j]]
                slope = model.water.slope if model.water.profile is None else \
                    float(np.arctan(seabed_slope(model.water, Xs[grounded, ends[j], 0]).mean()))
                nrm = None if model.water.grid is None else \
                    model.water.grid.normal(Xs[grounded, ends[j], 0], Xs[grounded, ends[j], 1])
                out[grounded, j] = grounded_end_force(tension[grounded, j, None] * d / norm[:, None], half, slope,
                                                      nrm)
    return out.reshape(lead + (2, 3))


def _evaluate_ends(model: MooringModel, part: dict, Xs, lead, V, A, time, kinematic_nodes, end_directions=None):
    """The support forces at the line's two end nodes and the tensions of its end elements at the states ``Xs``
    (nt, n, 3) (:func:`line_end_forces`; ``lead`` the states' shape; ``part`` the line's :func:`_end_part`),
    evaluated: ``(nt, 2, 3)``, ``(nt, 2)``."""
    sub, inside, args, fidx = part["sub"], part["inside"], part["args"], part["fidx"]
    ends_sub, el_sub, elements, rows = part["ends_sub"], part["el_sub"], part["elements"], part["hinge_rows"]
    # the hinge table and the viscoelastic state as they are now (a run turns held ends and advances the state)
    hinge_ei = np.ascontiguousarray(model.hinge_ei[rows])
    visco = np.ascontiguousarray(model.visco[elements]) if model.visco.shape[0] else model.visco
    nt = Xs.shape[0]
    knodes = np.arange(Xs.shape[-2]) if kinematic_nodes is None else np.asarray(kinematic_nodes, np.int64)
    kshape = lead + (knodes.size, 3)
    ts = np.zeros(nt) if time is None else np.ascontiguousarray(np.broadcast_to(np.asarray(time, float), lead),
                                                                 float).reshape(nt)
    # every state in one compiled call (what model.evaluate gives state by state), on the part of the network
    # that loads the two end nodes
    Xp = np.ascontiguousarray(Xs[:, sub])
    kin = np.flatnonzero(inside[knodes])
    if V is None:
        Vp = np.zeros((nt, kin.size, 3))
    else:
        Vp = np.ascontiguousarray(np.broadcast_to(np.asarray(V, float), kshape).reshape((nt,) + kshape[-2:])[:, kin])
    if A is None:
        Ap = np.zeros((nt, kin.size, 3))
    else:
        Ap = np.ascontiguousarray(np.broadcast_to(np.asarray(A, float), kshape).reshape((nt,) + kshape[-2:])[:, kin])
    ksub = np.searchsorted(sub, knodes[kin]).astype(np.int64)
    turning = end_directions is not None and rows.size
    if turning:  # each state's directions of the part's hinges
        directions = np.asarray(end_directions, float)
        directions = directions.reshape((nt,) + directions.shape[-2:])[:, rows]
    out, tension = np.zeros((nt, 2, 3)), np.zeros((nt, 2))
    for i0, i1 in model.sea_spans(ts, time is not None):  # an irregular sea: its grid window by window
        for j0, j1 in ((i, i + 1) for i in range(i0, i1)) if turning else ((i0, i1),):
            if turning:
                hinge_ei[:, H_D:H_D + 3] = directions[j0]
            out[j0:j1], tension[j0:j1] = evaluate_states(
                Xp[j0:j1], Vp[j0:j1], Ap[j0:j1], ksub, ts[j0:j1], time is not None, ends_sub, el_sub, *args,
                hinge_ei, visco, fidx, model.bw, model.env, model.cur_depth, model.cur_speed, model.sea)
    return out, tension

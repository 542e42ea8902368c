"""What the single-line and the system time-domain runs share around the solver: the height of points above
the seabed and the force of a line on an anchor resting on it, the surface elevation output, and a model with
its prescribed nodes where a motion starts.

Below both runners (:mod:`seacable.mooring.run`, :mod:`seacable.system.dynamics`), which import these from here.
"""

from __future__ import annotations

import math

import numpy as np

from ..environment import IrregularWaves
from .network import FIXED, Network
from .solver import MooringModel, Water, wave_number_or_zero

__all__ = [
    "at_motion_start",
    "elevation_variables",
    "grounded_end_force",
    "height_above_seabed",
    "seabed_slope",
    "tie_variables",
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
    depth = env.depth
    if depth is None and profile is not None:  # the water depth at the origin, the profile's there
        depth = float(np.interp(0.0, profile.distance, profile.depth))
    return Water(density=env.water_density, gravity=env.gravity, depth=depth, slope=env.seabed.slope,
                 seabed_stiffness=seabed_contact.stiffness, seabed_damping=seabed_contact.damping,
                 friction=env.seabed.friction, friction_velocity=seabed_contact.friction_velocity,
                 current_depths=tuple(depths), current_speeds=tuple(speeds), current_heading=cur.heading,
                 wave_height=w_reg.height if w_reg else 0.0, wave_period=w_reg.period if w_reg else 10.0,
                 wave_heading=w_reg.heading if w_reg else 0.0, wave_phase=w_reg.phase if w_reg else 0.0,
                 rayleigh_mass=rayleigh_mass, sea=sea, stretching=w.stretching if w else "none",
                 profile=None if profile is None else (profile.distance, profile.depth), compression=compression)


def seabed_slope(water: Water, x):
    """Slope dz/dx [-] of the seabed under ``x`` [m]: the plane's ``tan(slope)``, or the profile's segment's (level
    beyond its ends, the segment above a point at a breakpoint: :func:`seacable.mooring.kernel.seabed_at`)."""
    x = np.asarray(x, float)
    if water.profile is None:
        return np.full_like(x, math.tan(water.slope))
    dist, depth = (np.asarray(v, float) for v in water.profile)
    k = np.clip(np.searchsorted(dist, x, side="right"), 1, dist.size - 1)
    slope = -(depth[k] - depth[k - 1]) / (dist[k] - dist[k - 1])
    return np.where((x <= dist[0]) | (x >= dist[-1]), 0.0, slope)


def height_above_seabed(water: Water, X):
    """Height of points above the seabed, normal to it (negative inside it), (..., n): the plane's, or the profile's
    segment under each point's (the kernel's contact, :func:`seacable.mooring.kernel.seabed_at`). [m]"""
    if water.profile is not None:
        slope = seabed_slope(water, X[..., 0])
        return (X[..., 2] - water.seabed_z(X[..., 0])) / np.sqrt(1.0 + slope * slope)
    sl = water.slope
    return -math.sin(sl) * X[..., 0] + math.cos(sl) * (X[..., 2] + water.depth)


def grounded_end_force(pull, half_weight, slope: float = 0.0):
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
    """
    pull = np.asarray(pull, float)
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

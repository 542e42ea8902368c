"""The geometric checks every mooring analysis makes before it solves: one function, every path.

:func:`check_network` runs whenever a :class:`~seacable.mooring.solver.MooringModel` is built, so
``mooring_static``, ``mooring_pushover``, ``mooring_dynamic`` and networks read from MoorDyn files
refuse the same impossible starts with the same message:

* a node the user places (an anchor, a fairlead, a MoorDyn point) under the seabed;
* two held nodes (fixed or moved) farther apart than the line(s) between them can stretch.

The stretch limit of an element is the strain at its line type's breaking load, ``MBL / EA``, when
the breaking load is known: the line would break before it reached. Without a breaking load it is
:data:`seacable.statics.multisegment.MAX_STRAIN` (20 %), the limit the catenary statics
(analysis ``static``) already apply, so that every analysis refuses the same geometry: it is above
the breaking strain of every usual mooring material (chain and wire rope 2-4 %, polyester 10-15 %,
only nylon reaches 20-25 %), so it never refuses a line that could hold, only a geometry no line
can reach (a typing error in a coordinate or a length).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ..statics.multisegment import MAX_STRAIN
from .network import FIXED, PRESCRIBED, Network

__all__ = ["check_motion", "check_network", "element_stretch_limit"]


def element_stretch_limit(network: Network) -> np.ndarray:
    """Largest strain each element may start at: ``MBL / EA``, or ``MAX_STRAIN`` without a breaking load. [-]"""
    limit = np.full(network.n_elements, MAX_STRAIN)
    mbl = network.breaking_load
    if mbl is not None:
        mbl = np.asarray(mbl, float)
        known = np.isfinite(mbl) & (mbl > 0)
        limit[known] = mbl[known] / network.axial_stiffness[known]
    return limit


def _lines_at(network: Network, node: int) -> list[str]:
    return [name for name, nodes in zip(network.line_names, network.line_nodes) if node in nodes]


def _describe(network: Network, node: int) -> str:
    kind = {FIXED: "fixed", PRESCRIBED: "moved"}.get(int(network.kind[node]), "free")
    x, y, z = network.position[node]
    return f"{kind} node {node} at ({x:.6g}, {y:.6g}, {z:.6g}) m"


def _below_seabed(x, z, depth: float, slope: float, profile, grid=None, y=None) -> np.ndarray:
    """How far points (x, z) lie under the seabed [m]: normal to the plane through (0, -depth) rising at ``slope``,
    or vertically under a profile ``(distances, depths)`` along X (level beyond its ends) or a ``grid``
    (:class:`seacable.bathymetry.SeabedGrid`) at (x, ``y``)."""
    if grid is not None:
        return grid.at(x, y)[0] - z
    if profile is not None:
        return -np.interp(x, profile[0], profile[1]) - z
    return ((-depth + math.tan(slope) * x) - z) * math.cos(slope)


def check_network(network: Network, *, depth: float | None, slope: float = 0.0, profile=None, grid=None) -> None:
    """Refuse a start no line can take: a placed node under the seabed, or held ends beyond the stretch limit.

    Parameters
    ----------
    network
        The mooring network at its start positions.
    depth, slope
        The seabed plane, through (0, 0, -depth) rising towards +x at ``slope`` (None: no seabed). [m], [rad]
    profile
        The seabed's profile along X instead of the plane, ``(distances, depths)``; None: the plane. [m]
    grid
        The seabed's grid instead (:class:`seacable.bathymetry.SeabedGrid`): every node, at its start, over it and
        not over land.

    Raises
    ------
    InputError
        Naming the line(s), the node and its position, the limit and why, and a fix.
    """
    X = network.position
    held = np.flatnonzero(network.kind != 0)
    placed = np.union1d(held, np.flatnonzero(~np.isfinite(network.arc_length)))  # plus MoorDyn points
    if grid is not None:
        for nodes, what in ((placed, "anchors, fairleads and points"), (np.arange(network.n_nodes), "line's nodes")):
            grid.check_covers(X[nodes], what)
    if depth is not None:
        below = _below_seabed(X[placed, 0], X[placed, 2], depth, slope, profile, grid, X[placed, 1])
        bed = X[placed, 2] + below / (1.0 if profile is not None or grid is not None else math.cos(slope))
        k = int(np.argmax(below)) if placed.size else 0
        if placed.size and below[k] > 1e-6 * max(depth, 1.0):
            node = int(placed[k])
            raise InputError(
                f"{' and '.join(repr(n) for n in _lines_at(network, node))}: {_describe(network, node)} is "
                f"{below[k]:.4g} m under the seabed (z = {bed[k]:.6g} m there, depth {depth:.6g} m). Suggested "
                "fix: put anchors on or above the seabed (z >= -depth) and fairleads and points above it.")
    if held.size < 2:
        return
    reach = network.length * (1.0 + element_stretch_limit(network))
    el = network.elements
    chain = _chain(network)
    if chain is None:
        from scipy.sparse import coo_matrix
        from scipy.sparse.csgraph import dijkstra

        n = network.n_nodes
        graph = coo_matrix((reach, (el[:, 0], el[:, 1])), shape=(n, n)).tocsr()
        dist, pred = dijkstra(graph, directed=False, indices=held, return_predecessors=True)
    else:
        dist = _chain_distances(chain, held, reach)
    for row, i in enumerate(held):
        for j in held[row + 1:]:
            chord = float(np.linalg.norm(X[j] - X[i]))
            if not np.isfinite(dist[row, j]) or chord <= dist[row, j] * (1.0 + 1e-9):
                continue
            if chain is None:
                path, k = [], int(j)
                while k != i:
                    p = int(pred[row, k])
                    e = np.flatnonzero(((el[:, 0] == p) & (el[:, 1] == k)) | ((el[:, 0] == k) & (el[:, 1] == p)))[0]
                    path.append(e)
                    k = p
                path = np.array(path[::-1])
            else:  # the elements from i to j along the chain
                a, b = chain[i], chain[j]
                path = np.arange(a, b) if a < b else np.arange(a - 1, b - 1, -1)
            lines = list(dict.fromkeys(network.line_names[network.element_line[e]] for e in path))
            unstretched = float(np.sum(network.length[path]))
            mbl = network.breaking_load
            known = mbl is not None and bool(np.all(np.isfinite(np.asarray(mbl, float)[path])))
            why = ("the strain at the line type's breaking load, MBL / EA" if known
                   else f"{MAX_STRAIN:.0%} without a breaking_load (the statics' limit; above the breaking strain "
                        "of chain, wire and polyester)")
            raise InputError(
                f"{' and '.join(repr(n) for n in lines)} ({unstretched:.6g} m unstretched) cannot span the "
                f"{chord:.6g} m between {_describe(network, int(i))} and {_describe(network, int(j))}: it would "
                f"start at a strain of {chord / unstretched - 1:.3g}, and it can stretch to at most "
                f"{dist[row, j]:.6g} m at its limit strain ({why}). Suggested fix: check the end positions "
                "(anchor, fairlead or points) and the line length.")


def _chain(network: Network) -> np.ndarray | None:
    """Each node's place along the network's one line when the network is that line alone, its element ``k``
    joining its nodes ``k`` and ``k + 1`` (element ``k`` then runs from place ``k`` to ``k + 1``); else None."""
    if len(network.line_nodes) != 1:
        return None
    nodes = np.asarray(network.line_nodes[0])
    el = network.elements
    if (nodes.size != network.n_nodes or el.shape[0] != nodes.size - 1 or not np.array_equal(el[:, 0], nodes[:-1])
            or not np.array_equal(el[:, 1], nodes[1:])):
        return None
    place = np.empty(nodes.size, np.int64)
    place[nodes] = np.arange(nodes.size)
    return place


def _chain_distances(place: np.ndarray, held: np.ndarray, reach: np.ndarray) -> np.ndarray:
    """The distances along a chain (:func:`_chain`) from each held node to every node, as the shortest paths
    of a graph search give them: summed element after element from the held node outwards."""
    dist = np.empty((held.size, place.size))
    order = np.argsort(place)  # the nodes along the chain
    for row, i in enumerate(held):
        a = place[i]
        along = np.empty(place.size)
        along[a] = 0.0
        along[a + 1:] = np.cumsum(reach[a:])
        along[:a] = np.cumsum(reach[:a][::-1])[::-1]
        dist[row, order] = along
    return dist


def check_motion(network: Network, times, positions, *, depth: float | None, slope: float = 0.0,
                 profile=None, grid=None) -> None:
    """Refuse a prescribed motion that takes a moved node under the seabed or beyond the lines' reach.

    Parameters
    ----------
    network
        The network at rest (its held nodes and lines).
    times
        (nt,) sample times of the motion. [s]
    positions
        (nt, n_channels, 3) positions of the motion channels at ``times``. [m]
    depth, slope, profile, grid
        The seabed plane, profile or grid (see :func:`check_network`). [m], [rad], [m]

    Raises
    ------
    InputError
        Naming the line(s), the node, the time and the position.
    """
    times = np.asarray(times, float)
    positions = np.asarray(positions, float)
    moved = np.flatnonzero(network.channel >= 0)
    if moved.size == 0 or times.size == 0:
        return
    for node in moved:
        path = positions[:, network.channel[node], :]
        if depth is not None:
            if grid is not None:
                grid.check_covers(path, f"moved node {node}'s path")
            below = _below_seabed(path[:, 0], path[:, 2], depth, slope, profile, grid, path[:, 1])
            k = int(np.argmax(below))
            if below[k] > 1e-6 * max(depth, 1.0):
                raise InputError(
                    f"{' and '.join(repr(n) for n in _lines_at(network, int(node)))}: the motion takes moved node "
                    f"{node} to ({path[k, 0]:.6g}, {path[k, 1]:.6g}, {path[k, 2]:.6g}) m at t = {times[k]:.6g} s, "
                    f"{below[k]:.4g} m under the seabed. Suggested fix: check the motion's amplitude, offsets or "
                    "the fairlead's depth.")
    # the reach: the positions at the time each moved node is farthest from each other held node
    held = np.flatnonzero(network.kind != 0)
    X = network.position
    worst = X.copy()
    for node in moved:
        path = positions[:, network.channel[node], :]
        others = held[held != node]
        if others.size == 0:
            continue
        far = np.max(np.linalg.norm(path[:, None, :] - X[None, others, :], axis=-1), axis=1)
        k = int(np.argmax(far))
        worst[node] = path[k]
        try:
            check_network(network.replace(position=worst), depth=None)
        except InputError as err:
            raise InputError(f"at t = {times[k]:.6g} s of the motion: {err}") from None
        worst[node] = X[node]


def seabed_hold_hint(model, X, friction: bool) -> str:
    """Why a line lying on the seabed may have no static equilibrium, for the statics' message ("" when it is not
    that): the load in the seabed's plane on its grounded elements against what friction can hold.

    Per unit length of each element whose two nodes are on the seabed (``X`` the last state tried): the current's
    drag (``1/2 rho d (C_dn U_n^2 + pi C_dt U_t^2)``, across and along the element) plus the weight's component down
    the seabed's slope (``w sin(beta)``), against the friction ``mu w cos(beta)`` (``w`` the weight in water per
    length, ``beta`` the slope under the element). With ``friction`` False (the seabed has no friction, or the
    statics' friction is off) any such load is unheld: pushed along itself towards its anchor a grounded line would
    take compression, which its elements do not carry.
    """
    water, net = model.water, model.network
    if water.depth is None and not water.tabulated:
        return ""
    X = np.asarray(X, float)
    grounded = X[:, 2] <= water.seabed_z(X[:, 0], X[:, 1]) + 1e-9  # on the seabed or in it (the penalty contact)
    els = np.flatnonzero(grounded[net.elements[:, 0]] & grounded[net.elements[:, 1]])
    if els.size == 0:
        return ""
    a, b = net.elements[els, 0], net.elements[els, 1]
    chord = X[b] - X[a]
    t = chord / np.maximum(np.linalg.norm(chord, axis=1), 1e-300)[:, None]
    mid = 0.5 * (X[a] + X[b])
    h = 1e-3  # the slope under the element's middle, by a central difference [m]
    slope = np.arctan((water.seabed_z(mid[:, 0] + h, mid[:, 1]) - water.seabed_z(mid[:, 0] - h, mid[:, 1])) / (2 * h))
    speed = np.interp(-mid[:, 2], water.current_depths, water.current_speeds)
    u = speed[:, None] * np.array([math.cos(water.current_heading), math.sin(water.current_heading), 0.0])
    ut = np.sum(u * t, axis=1)
    un = np.linalg.norm(u - ut[:, None] * t, axis=1)
    rho = water.density
    d = net.diameter[els]
    drag = 0.5 * rho * d[:, None] * (net.cdn[els][:, None] * un[:, None] * (u - ut[:, None] * t)
                                     + math.pi * net.cdt[els][:, None] * np.abs(ut)[:, None] * ut[:, None] * t)
    w = net.weight_per_length[els]
    along = np.column_stack([np.cos(slope), np.zeros_like(slope), np.sin(slope)])  # up the seabed towards +x
    load = drag - (w * np.sin(slope))[:, None] * along  # the weight's part in the seabed's plane
    q = np.linalg.norm(load, axis=1)
    hold = water.friction * w * np.cos(slope) if friction else np.zeros_like(w)
    if not friction and not np.any(speed != 0.0):
        return ""  # frictionless, no current: the grounded line is held along itself by its tension
    k = int(np.argmax(q - hold))
    if q[k] <= 0.0 or q[k] <= hold[k]:
        if not friction or water.compression:
            return ""
        # held node by node, but perhaps pushed along itself: tension-only elements pass no push on
        return (" Friction can hold each grounded node's own load; if the grounded line is pushed along itself towards "
                "its anchor (a current towards it, the suspended part pushed over), its elements, which carry no "
                "compression, pass no push on, and the nodes there have only their own friction. Suggested fix: let "
                "the elements carry compression (the analysis's 'compression: true'), as a cable with bending "
                "stiffness does, so that the friction of the whole grounded length holds the push.")
    s = 0.5 * (net.arc_length[a[k]] + net.arc_length[b[k]])
    what = (f"the current's drag, {float(np.linalg.norm(drag[k])):.4g} N/m ({float(speed[k]):.3g} m/s at the seabed)"
            if np.any(drag[k]) else "")
    if slope[k] != 0.0:
        what += (" and " if what else "") + (f"the weight down the seabed's {math.degrees(abs(slope[k])):.3g} deg "
                                             f"slope ({float(w[k] * abs(math.sin(slope[k]))):.4g} N/m)")
    if friction:
        return (f" At s = {s:.4g} m the grounded line is loaded along the seabed by {what}: {float(q[k]):.4g} N/m "
                f"in all, more than the seabed's friction holds, mu w cos(slope) = {water.friction:g} x "
                f"{float(w[k]):.4g} N/m x {math.cos(slope[k]):.4g} = {float(hold[k]):.4g} N/m: it slides, and has no "
                "static equilibrium (the statics' friction acts towards each grounded node's target, at most mu N). "
                "Suggested fix: give the seabed more friction (environment.seabed.friction) if the soil has it, or a "
                "current profile that falls towards the seabed (environment.current), as the seabed's boundary layer "
                "does.")
    return (f" At s = {s:.4g} m the grounded line is loaded along the seabed by {what}, and the statics have no "
            "friction to hold it (environment.seabed.friction is 0, or the analysis's static_friction mode is 'off'): "
            "pushed towards its anchor, a grounded line has no equilibrium. Suggested fix: give the seabed its "
            "friction coefficient (environment.seabed.friction, e.g. 0.5-1 for a cable or chain on clay), or a "
            "current profile that falls to zero at the seabed (environment.current depths and speeds), as the "
            "seabed's boundary layer does.")

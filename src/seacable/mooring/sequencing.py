"""Mesh sequencing for the statics of finely meshed lines: a coarser network of the same lines, and its equilibrium
carried onto the fine mesh as a start.

A fine mesh (elements much shorter than the shape's changes: a lazy-wave cable meshed for its curvature at 1-8
elements a metre) is a poor problem for Newton from a catenary start: moving a node sideways by ``d`` stretches its
elements of length ``l`` by ``d^2 / (2 l^2)``, so a step of a metre over quarter-metre elements asks for strains of
8 and the iteration diverges, while steps small enough to stay in Newton's basin need thousands of iterations to
cover the tens of metres between the catenary and the lazy wave. The same lines meshed coarsely converge from the
catenary in a few hundred iterations, and their shape, interpolated along the arc length by a cubic spline (smooth,
so that bending stiffness meets no kinks), starts the fine mesh within a few tens (Newton's own rate): a 500 m
lazy wave with EI 20 kN m^2 at 1, 2, 4 and 8 elements a metre in 14, 18, 24 and 32 iterations after 140 on its
coarse mesh, where the fine meshes alone did not converge in 1500 at any step limit.

:func:`coarsen` keeps every ``k``-th node of each line and every node that matters on its own (line ends, points
shared by lines, held or moved nodes, attachments, and the nodes where the line's properties change), and merges
the elements between kept nodes, which then share their properties: a coarse network is the same physical lines,
only meshed more coarsely. :func:`spline_start` carries positions back.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .network import FREE, Network

__all__ = ["coarsen", "spline_start"]

#: Per-node arrays of a :class:`Network` (its first axis the nodes).
NODE_FIELDS = ("position", "kind", "channel", "point_mass", "point_added_mass", "point_weight", "point_volume",
               "point_drag_area", "arc_length", "point_axial_drag_area", "point_lift_area", "point_tether", "point_clamp")
#: Per-element arrays (the first axis the elements) whose values a merged element keeps; ``length`` adds up.
ELEMENT_FIELDS = ("axial_stiffness", "axial_damping", "mass_per_length", "weight_per_length", "diameter", "cdn",
                  "cdt", "can", "cat", "element_line", "breaking_load", "bending_stiffness", "element_viscoelastic",
                  "element_syrope", "element_tension_strain", "element_moment_curvature")


def _element_key(net: Network, e: int) -> tuple:
    """The properties of element ``e`` that two elements must share to be merged (all but its length)."""
    key = []
    for name in ELEMENT_FIELDS:
        value = getattr(net, name, None)
        if value is None:
            continue
        item = value[e]
        key.append(repr(None if item is None else np.asarray(item, float).tolist()) if isinstance(value, tuple)
                   else np.asarray(item, float).tobytes())
    return tuple(key)


def _between(of: dict, a, b) -> int | None:
    """The element joining nodes ``a`` and ``b`` in either order (``of``: node pair -> element), or None."""
    a, b = int(a), int(b)
    return of.get((a, b), of.get((b, a)))


def _kept_nodes(net: Network, step: int) -> np.ndarray:
    """A mask of the nodes a coarse network keeps (every ``step``-th of each line and those that matter)."""
    n = len(net.position)
    keep = np.zeros(n, bool)
    count = np.zeros(n, int)
    for nodes in net.line_nodes:
        count[nodes] += 1
        keep[nodes[[0, -1]]] = True
        keep[nodes[::step]] = True
    keep |= count != 1                                   # shared points, nodes of no line
    keep |= (net.kind != FREE) | (net.channel >= 0)
    for name in NODE_FIELDS[3:8] + NODE_FIELDS[9:]:
        value = getattr(net, name, None)
        if value is not None:
            keep |= np.any(np.asarray(value, float).reshape(n, -1) != 0.0, axis=1)
    of = {(int(a), int(b)): e for e, (a, b) in enumerate(net.elements)}
    for nodes in net.line_nodes:
        for k in range(1, len(nodes) - 1):
            e1, e2 = _between(of, nodes[k - 1], nodes[k]), _between(of, nodes[k], nodes[k + 1])
            if e1 is None or e2 is None or _element_key(net, e1) != _element_key(net, e2):
                keep[nodes[k]] = True
    return keep


def coarsen(net: Network, elements_per_line: int = 60) -> Network | None:
    """The network with its lines meshed about ``elements_per_line`` elements each, or None when that is not
    coarser (no line has more than twice as many) or the network's elements do not follow its lines.

    Every ``k``-th node of a line is kept (``k`` from its longest line), and every node that matters on its own;
    the elements between two kept nodes become one, of their total unstretched length and their shared properties.
    """
    longest = max((len(nodes) - 1 for nodes in net.line_nodes), default=0)
    if longest <= 2 * elements_per_line:
        return None
    step = -(-longest // elements_per_line)
    keep = _kept_nodes(net, step)
    of = {(int(a), int(b)): e for e, (a, b) in enumerate(net.elements)}
    if len(of) != len(net.elements) or sum(len(nodes) - 1 for nodes in net.line_nodes) != len(net.elements):
        return None
    new_index = np.cumsum(keep) - 1
    first, lengths, pairs, lines = [], [], [], []
    for nodes in net.line_nodes:
        kept = nodes[keep[nodes]]
        lines.append(new_index[kept])
        start = 0
        for k in range(1, len(nodes)):
            if not keep[nodes[k]]:
                continue
            run = [_between(of, nodes[j], nodes[j + 1]) for j in range(start, k)]
            if any(e is None for e in run):
                return None
            forward = int(net.elements[run[0], 0]) == int(nodes[start])
            first.append(run[0])
            lengths.append(float(np.sum(net.length[run])))
            pair = (new_index[nodes[start]], new_index[nodes[k]])
            pairs.append(pair if forward else pair[::-1])
            start = k
    first = np.array(first, np.int64)
    update = {"elements": np.array(pairs, np.int64).reshape(-1, 2), "length": np.array(lengths),
              "line_nodes": tuple(np.asarray(line, np.int64) for line in lines)}
    for name in NODE_FIELDS:
        value = getattr(net, name, None)
        if value is not None:
            update[name] = np.asarray(value)[keep]
    for name in ELEMENT_FIELDS:
        value = getattr(net, name, None)
        if value is not None:
            update[name] = tuple(value[e] for e in first) if isinstance(value, tuple) else np.asarray(value)[first]
    return dataclasses.replace(net, **update)


def spline_start(fine: Network, coarse: Network, X_coarse) -> np.ndarray:
    """The fine network's node positions (n, 3) [m] from the coarse one's ``X_coarse``: along each line a cubic
    spline of the positions over the unstretched arc length through the coarse nodes (the kept nodes at their coarse
    positions), the nodes of no line where the coarse network has them."""
    from scipy.interpolate import CubicSpline

    X = np.array(fine.position, float)
    new_index = {}
    for f_nodes, c_nodes in zip(fine.line_nodes, coarse.line_nodes):
        s_c = np.asarray(coarse.arc_length, float)[c_nodes]
        s_f = np.asarray(fine.arc_length, float)[f_nodes]
        if np.any(~np.isfinite(s_c)) or np.any(np.diff(s_c) <= 0.0) or len(c_nodes) < 2:
            continue
        curve = CubicSpline(s_c, np.asarray(X_coarse, float)[c_nodes], axis=0) if len(c_nodes) > 2 else None
        inner = f_nodes[1:-1]
        if curve is not None:
            X[inner] = curve(s_f[1:-1])
        else:
            X[inner] = np.stack([np.interp(s_f[1:-1], s_c, np.asarray(X_coarse, float)[c_nodes][:, k])
                                 for k in range(3)], axis=1)
        new_index[int(f_nodes[0])], new_index[int(f_nodes[-1])] = int(c_nodes[0]), int(c_nodes[-1])
    for i, j in new_index.items():
        X[i] = X_coarse[j]
    return X

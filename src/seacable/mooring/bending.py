"""Curvature, bend moment, shear and declination along a line with bending stiffness, from its node positions.

The same discrete quantities the kernel's hinges act with (:func:`seacable.mooring.kernel.bending_loads`,
:func:`seacable.mooring.kernel.end_bending_loads`), evaluated in NumPy over any number of states: at an inner
node of elements ``l1``, ``l2`` turned by ``theta``, ``kappa = 4 sin(theta / 2) / (l1 + l2)`` and ``M = EI kappa``
(EI the mean of its two elements'); at a clamped end ``kappa = 4 sin(theta / 2) / l`` from the end's given
direction, ``M = EI kappa`` (a hinge with a nonlinear law: ``M(kappa)``, kappa over its unstretched length, as
the kernel's); at a spring end ``M = k_e theta`` (the spring in series with the half element) and
``kappa = M / EI`` (the line's own curvature under that moment); at a pinned end none. The moment is a vector
along the binormal ``a x b / |a x b|`` of the hinge (``a`` the direction before the node, ``b`` after, along the
line from end A); the shear force across the line in an element is ``|dM/ds|``, the difference of the moment
vectors at its nodes over its stretched length (a rod without torsion or distributed moment: ``dM/ds = -t x Q``,
so this is the shear force normal to the line).
"""

from __future__ import annotations

import numpy as np

from ..moment_curvature import law_moment
from ._indices import H_D, H_EI, H_K, H_KIND, H_L0, H_NLAW, H_SIZE, H_SPRING
from .network import Network

__all__ = ["bending_state", "bending_variables"]


def _unit(v):
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return np.divide(v, n, out=np.zeros_like(v), where=n > 0), n[..., 0]


def bending_state(net: Network, X, directions=None):
    """Curvature [1/m], bend-moment vectors [N m], shear [N] and declination [rad] of a network's lines at ``X``.

    ``X`` (..., n, 3) node positions [m]. Returns ``(curvature, moment, shear, declination)``: ``curvature``
    (..., n) at every node (0 where no hinge acts: a pinned end, a node without EI), ``moment`` (..., n, 3) the
    bend moment vectors (their norm the bend moment), ``shear`` (..., e) per element, ``declination`` (..., n)
    the angle of the line's direction (towards end B) from the upward vertical, at an inner node that of the
    bisector of its two elements, at an end node that of its end element. ``directions`` (..., h, 3), optional: each
    hinge's given direction at each state (a held end turning with a platform), instead of the table's at rest.
    """
    X = np.asarray(X, float)
    lead = X.shape[:-2]
    hinges, table = net.hinge_arrays()
    curvature = np.zeros(lead + (net.n_nodes,))
    moment = np.zeros(lead + (net.n_nodes, 3))
    if hinges.shape[0]:
        i0, i1, i2 = hinges.T
        at_a, at_b = i0 == i1, i1 == i2
        a, l1 = _unit(X[..., i1, :] - X[..., i0, :])
        b, l2 = _unit(X[..., i2, :] - X[..., i1, :])
        e = table[:, H_D:H_D + 3] if directions is None else np.asarray(directions, float)
        a = np.where(at_a[:, None], e, a)      # end A: the direction given, into the line
        b = np.where(at_b[:, None], -e, b)     # end B: the line's direction there (towards end B)
        theta = 2.0 * np.arcsin(np.clip(0.5 * np.linalg.norm(b - a, axis=-1), 0.0, 1.0))
        spring = table[:, H_KIND] == H_SPRING
        ei = table[:, H_EI]
        length = l1 * ~at_a + l2 * ~at_b       # an end hinge's one element
        kappa = 4.0 * np.sin(0.5 * theta) / length
        m = ei * kappa
        for h in np.flatnonzero(table[:, H_NLAW] > 0):  # a nonlinear law on the unstretched length (kernel.hinge_law)
            kappa[..., h] = 2.0 * np.sin(0.5 * theta[..., h]) / table[h, H_L0]
            m[..., h] = law_moment(table[h, H_SIZE:H_SIZE + 2 * int(table[h, H_NLAW])], kappa[..., h])
        if np.any(spring):
            # the spring in series with the end's half element (kernel.end_bending_loads): M = k_e theta
            ke = 1.0 / (1.0 / np.where(spring, table[:, H_K], 1.0) + 0.5 * length / ei)
            m = np.where(spring, ke * theta, m)
            kappa = np.where(spring, m / ei, kappa)
        axis, _ = _unit(np.cross(a, b))
        curvature[..., i1] = kappa
        moment[..., i1, :] = m[..., None] * axis
    el = net.elements
    tv, length = _unit(X[..., el[:, 1], :] - X[..., el[:, 0], :])
    shear = np.linalg.norm(moment[..., el[:, 1], :] - moment[..., el[:, 0], :], axis=-1)
    shear = np.divide(shear, length, out=np.zeros_like(shear), where=length > 0)
    # each node's direction: the bisector of its line's elements (one at an end), along the line towards end B
    t = np.zeros(lead + (net.n_nodes, 3))
    nodes_first, tv_first = np.moveaxis(t, -2, 0), np.moveaxis(tv, -2, 0)  # views: add.at on the node axis
    np.add.at(nodes_first, el[:, 0], tv_first)
    np.add.at(nodes_first, el[:, 1], tv_first)
    t, _ = _unit(t)
    declination = np.arctan2(np.hypot(t[..., 0], t[..., 1]), t[..., 2])
    return curvature, moment, shear, declination


def bending_variables(net: Network, X, dims=("node",), directions=None) -> dict:
    """The Dataset variables of a line with bending stiffness or a held end (none for a truss with pinned ends):
    ``curvature``, ``bend_moment``, ``declination`` at the nodes and ``shear_force`` per element
    (:func:`bending_state`, ``directions`` its held ends' directions at each state). ``dims`` as the positions', the
    node's last."""
    from ..results import var

    if not net.hinge_arrays()[0].shape[0]:
        return {}
    lead = tuple(dims[:-1])
    curvature, moment, shear, declination = bending_state(net, X, directions)
    return {
        "curvature": var(dims, curvature, "1/m", "curvature of the line (0 at a pinned end)"),
        "bend_moment": var(dims, np.linalg.norm(moment, axis=-1), "N m",
                           "bend moment EI kappa (a spring end's k theta; 0 at a pinned end)"),
        "shear_force": var(lead + ("element",), shear, "N", "shear force across the line in the element, |dM/ds|"),
        "declination": var(dims, declination, "rad",
                           "angle of the line (towards end B) from the upward vertical"),
    }

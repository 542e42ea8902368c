"""Curvature, bend moment, shear and declination along a system's finite-element lines (issue 40).

The single line's outputs (:func:`seacable.mooring.bending.bending_state`) on the system's network, per line: the
held ends' directions taken at each state's body poses (a clamp on a body turns with it), the nodes of each line
gathered end A to end B and padded with NaN to the longest line.
"""

from __future__ import annotations

import numpy as np

from ..mooring.bending import bending_state
from ..mooring.kernel import H_D
from ..mooring.motion import rotation_matrix

__all__ = ["BENDING", "held_directions", "line_bending", "pose_rotations"]

#: name -> (per node or per element, units, long name) of the bending outputs
BENDING = {
    "curvature": ("node", "1/m", "curvature of the line (0 at a pinned end)"),
    "bend_moment": ("node", "N m", "bend moment EI kappa (a spring end's k theta; 0 at a pinned end)"),
    "shear_force": ("element", "N", "shear force across the line in the element, |dM/ds|"),
    "declination": ("node", "rad", "angle of the line (towards end B) from the upward vertical"),
}


def held_directions(fe, rotations: dict) -> np.ndarray | None:
    """The hinge table's given directions (..., h, 3) with each held end on a body turned by its body's rotation
    (``rotations``: {body name: (..., 3, 3) rotation matrices, global}; a body not in it keeps the table's
    direction). None when no held end is on a body."""
    m = fe.model
    turning = [(h, fe.system.points[p].body, into) for h, p, into in fe.held
               if into is not None and fe.system.points[p].body in rotations]
    if not turning:
        return None
    lead = np.shape(next(iter(rotations.values())))[:-2]
    _, table = m.network.hinge_arrays()  # the directions at rest (the model's table holds the last state's)
    out = np.broadcast_to(table[:, H_D:H_D + 3], lead + (table.shape[0], 3)).copy()
    for h, body, into in turning:
        out[..., h, :] = rotations[body] @ np.asarray(into, float)
    return out


def pose_rotations(poses) -> np.ndarray:
    """Rotation matrices (..., 3, 3) of poses (..., 6) [m, rad] (``Rz(yaw) Ry(pitch) Rx(roll)``)."""
    poses = np.asarray(poses, float)
    flat = poses.reshape(-1, 6)
    return np.array([rotation_matrix(*p[3:]) for p in flat]).reshape(poses.shape[:-1] + (3, 3))


def line_bending(fe, X, directions=None) -> dict:
    """The bending outputs of ``fe``'s lines at node positions ``X`` (..., n, 3) [m]: {name: (..., line, width)},
    nodes (or elements) of each line from end A, NaN beyond its end (:data:`BENDING`); {} when no line bends."""
    m = fe.model
    if not m.hinges.shape[0]:
        return {}
    curvature, moment, shear, declination = bending_state(m.network, X, directions)
    per = {"curvature": curvature, "bend_moment": np.linalg.norm(moment, axis=-1), "shear_force": shear,
           "declination": declination}
    out = {}
    for name, (where, _, _) in BENDING.items():
        index = fe.line_nodes if where == "node" else fe.line_elements
        width = max((len(i) for i in index), default=0)
        rows = []
        for i in index:
            a = per[name][..., np.asarray(i)]
            rows.append(np.concatenate([a, np.full(a.shape[:-1] + (width - a.shape[-1],), np.nan)], axis=-1))
        out[name] = np.stack(rows, axis=-2)
    return out

"""Tethers' tensions and clamps' forces of a system's lines (issue 40): a single line's tie outputs
(:func:`seacable.mooring.outputs.tie_variables`) per line of the system's finite-element network.

Each line's ties (:attr:`seacable.system.dynamics.fe.SystemFE.line_ties`) in the order of the line, padded with
NaN to the line with the most: ``tether_tension`` (..., line, tether) from each tether's stretch
(:func:`seacable.mooring.outputs.tether_tension`, the kernel's tension-only law), ``clamp_force`` and its
components (..., line, clamp), the force of the line on the clamp: for a rigid clamp the support force of its
held node (every load on it: the line's two elements, its bending, its half elements' weight, water and seabed
loads, a tether there), for a spring clamp ``k (x - p)``; their nodes' unstretched arc lengths ``tether_s`` and
``clamp_s`` (line, tether or clamp).
"""

from __future__ import annotations

import numpy as np

from ..mooring.outputs import tether_tension

__all__ = ["TIES", "line_ties", "needs_support"]

#: name -> (the tie dimension, units, long name) of the tie outputs
TIES = {
    "tether_tension": ("tether", "N", "tension of the tether"),
    "clamp_force": ("clamp", "N", "force of the line on the clamp"),
    "clamp_force_x": ("clamp", "N", "x force of the line on the clamp"),
    "clamp_force_y": ("clamp", "N", "y force of the line on the clamp"),
    "clamp_force_z": ("clamp", "N", "z force of the line on the clamp"),
}


def line_ties(fe, X, support=None) -> dict:
    """The tie outputs of ``fe``'s lines at node positions ``X`` (..., n, 3) [m]: {name: (..., line, width)} of
    :data:`TIES` and ``tether_s``, ``clamp_s`` (line, width) [m], NaN beyond a line's ties; a kind no line has is
    left out ({} without ties).

    ``support`` (..., n, 3): the support force of each node (:meth:`seacable.mooring.solver.MooringModel.evaluate`),
    read at the rigid clamps' nodes; needed only when a line has one. [N]
    """
    rows = getattr(fe, "line_ties", ()) or ()
    X = np.asarray(X, float)
    lead = X.shape[:-2]
    net = fe.model.network
    out = {}
    for kind in ("tether", "clamp"):
        per = [[(j, node) for k, j, node in ties if k == kind] for ties in rows]
        width = max((len(p) for p in per), default=0)
        if not width:
            continue
        s = np.full((len(per), width), np.nan)
        values = np.full(lead + (len(per), width, 3 if kind == "clamp" else 1), np.nan)
        for il, ties in enumerate(per):
            if not ties:
                continue
            j = np.array([t[0] for t in ties], np.int64)
            nodes = np.array([t[1] for t in ties], np.int64)
            s[il, :len(ties)] = np.r_[0.0, np.cumsum(net.length[fe.line_elements[il]])][j]
            if kind == "tether":
                values[..., il, :len(ties), 0] = _tensions(net, X, nodes)
                continue
            force = np.zeros(lead + (len(ties), 3))
            spring = np.zeros(len(ties), bool)
            if net.point_clamp is not None:
                spring = net.point_clamp[nodes, 3] > 0
            if np.any(~spring):
                force[..., ~spring, :] = np.asarray(support, float)[..., nodes[~spring], :]
            if np.any(spring):
                row = net.point_clamp[nodes[spring]]
                force[..., spring, :] = row[:, 3, None] * (X[..., nodes[spring], :] - row[:, :3])
            values[..., il, :len(ties), :] = force
        out[f"{kind}_s"] = s
        if kind == "tether":
            out["tether_tension"] = values[..., 0]
        else:
            out["clamp_force"] = np.linalg.norm(values, axis=-1)
            for k, axis in enumerate("xyz"):
                out[f"clamp_force_{axis}"] = values[..., k]
    return out


def _tensions(net, X, nodes) -> np.ndarray:
    """Tension (..., k) of the tethers on ``nodes`` (:func:`seacable.mooring.outputs.tether_tension`, which takes a
    network's tethers in node order). [N]"""
    every = np.flatnonzero(net.point_tether[:, 4] > 0)
    return tether_tension(net, X)[..., np.searchsorted(every, nodes)]


def needs_support(fe) -> bool:
    """Whether a line of ``fe`` has a rigid clamp, whose force is its node's support force."""
    net = fe.model.network
    for ties in getattr(fe, "line_ties", ()) or ():
        for kind, _, node in ties:
            if kind == "clamp" and (net.point_clamp is None or not net.point_clamp[node, 3] > 0):
                return True
    return False


def equilibrium_ties(eq, lines) -> dict:
    """The tie outputs (:func:`line_ties`) of a finite-element equilibrium ``eq`` (:class:`~seacable.system.
    statics.fe.FEEquilibrium`), rows in the order of ``lines`` (NaN for a line not in ``eq``, a removed one); {}
    for the catenary statics or a system without ties. The rigid clamps' support forces are the network's at rest
    in the equilibrium's water (:meth:`~seacable.mooring.solver.MooringModel.evaluate`, no waves)."""
    fe = getattr(eq, "fe", None)
    if fe is None:
        return {}
    X = eq.state.position
    support = None
    if needs_support(fe):
        support = fe.model.evaluate(X, np.zeros_like(X), np.zeros_like(X), 0.0, waves=False)[3]
    got = line_ties(fe, X, support)
    out = {}
    for name, values in got.items():
        row = {line: values[..., i, :] for i, line in enumerate(fe.line_names)}
        blank = np.full(values.shape[:-2] + values.shape[-1:], np.nan)
        out[name] = np.stack([row.get(line, blank) for line in lines], axis=-2)
    return out


def tie_variables(records: list, dims: tuple, shape: tuple, data: dict, coords: dict) -> None:
    """The tie outputs of each equilibrium (:func:`equilibrium_ties`, {} where none; in C order over the leading
    dimensions ``dims`` of sizes ``shape``) into ``data`` (``dims`` + (line, tether or clamp)) and their arc lengths
    into ``coords`` (line, tether or clamp); nothing when no equilibrium has ties."""
    from ..results import var

    given = [r for r in records if r]
    if not given:
        return
    for kind in ("tether", "clamp"):
        key = f"{kind}_s"
        if not any(key in r for r in given):
            continue
        width = max(r[key].shape[-1] for r in given if key in r)
        nl = next(r[key].shape[0] for r in given if key in r)

        def padded(r, name, width=width, nl=nl):
            if name not in r:
                return np.full((nl, width), np.nan)
            a = r[name]
            return np.pad(a, ((0, 0), (0, width - a.shape[-1])), constant_values=np.nan)

        s = np.fmax.reduce([padded(r, key) for r in records])
        coords[kind] = var(kind, np.arange(width), "1", f"{kind} of the line, in the order of its arc length")
        coords[key] = var(("line", kind), s, "m", f"unstretched arc length of the {kind}'s node from end A")
        for name, (dim, units, long_name) in TIES.items():
            if dim != kind:
                continue
            values = np.stack([padded(r, name) for r in records]).reshape(tuple(shape) + (nl, width))
            data[name] = var(tuple(dims) + ("line", kind), values, units, long_name)


def run_tie_variables(fe, run) -> tuple[dict, dict]:
    """The tie outputs of a coupled run (:class:`~seacable.system.dynamics.loop.SystemRun`) as variables (time,
    line, tether or clamp) and their arc lengths as coordinates: ``({}, {})`` without ties. A rigid clamp's force
    is its held node's support force at each output time, the node at rest (its loads at the run's positions and
    velocities, in the sea at that time: :meth:`~seacable.mooring.solver.MooringModel.evaluate`)."""
    got = line_ties(fe, run.position, _run_support(fe, run) if needs_support(fe) else None)
    return _as_variables(got, ("time",))


def _run_support(fe, run) -> np.ndarray:
    """Support forces (time, n, 3) of the network's nodes at the run's output states, accelerations zero (a rigid
    clamp's node does not move). [N]"""
    model = fe.model
    out = np.zeros(run.position.shape)
    zero = np.zeros(run.position.shape[1:])
    for k, t in enumerate(run.time):
        out[k] = model.evaluate(run.position[k], run.velocity[k], zero, float(t))[3]
    return out


def _as_variables(got: dict, dims: tuple) -> tuple[dict, dict]:
    from ..results import var

    data, coords = {}, {}
    for kind in ("tether", "clamp"):
        if f"{kind}_s" not in got:
            continue
        s = got[f"{kind}_s"]
        coords[kind] = var(kind, np.arange(s.shape[-1]), "1", f"{kind} of the line, in the order of its arc length")
        coords[f"{kind}_s"] = var(("line", kind), s, "m", f"unstretched arc length of the {kind}'s node from end A")
        for name, (dim, units, long_name) in TIES.items():
            if dim == kind:
                data[name] = var(tuple(dims) + ("line", kind), got[name], units, long_name)
    return data, coords

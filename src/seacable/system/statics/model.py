"""The assembled arrays of a mooring system for its statics (private to :mod:`seacable.system.statics`).

A :class:`~seacable.system.model.MooringSystem` is flattened once into *nodes* and *sub-lines*:

* nodes: every system point, plus an internal node wherever a line changes segment or carries
  an attachment (clump, buoy). A node is ``fixed`` (anchors, coupled points, points on fixed or
  prescribed bodies: held), ``body`` (fixed on a free body: moves with it) or ``free``
  (free points and internal nodes: equilibrated, 3 DOF each);
* sub-lines: the homogeneous pieces between consecutive nodes of a line, each one elastic
  catenary.

Everything the Newton iteration touches is a numpy array so one evaluation is one call of
:func:`seacable.statics.catenary.catenary` over all sub-lines.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...environment import Environment
from ...errors import InputError
from ...mooring.network import table_secant
from ..model import MooringSystem

FIXED, BODY, FREE = 0, 1, 2
_MERGE = 1e-9          # arc lengths closer than this fraction of the line length are one node


def rotation(angles) -> np.ndarray:
    """R = Rz(yaw) Ry(pitch) Rx(roll) for (roll, pitch, yaw) [rad] (MoorPy's ``rotationMatrix``)."""
    r, p, y = (float(a) for a in angles)
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def euler(R: np.ndarray) -> np.ndarray:
    """(roll, pitch, yaw) [rad] of R = Rz Ry Rx (pitch in [-pi/2, pi/2])."""
    pitch = -math.asin(max(-1.0, min(1.0, R[2, 0])))
    return np.array([math.atan2(R[2, 1], R[2, 2]), pitch, math.atan2(R[1, 0], R[0, 0])])


def euler_rate_map(angles) -> np.ndarray:
    """T with omega = T d(roll, pitch, yaw)/dt (omega in global axes) for R = Rz Ry Rx."""
    _r, p, y = (float(a) for a in angles)
    cy, sy, cp, sp = math.cos(y), math.sin(y), math.cos(p), math.sin(p)
    return np.array([[cy * cp, -sy, 0.0], [sy * cp, cy, 0.0], [-sp, 0.0, 1.0]])


@dataclass(frozen=True)
class EquilibriumFields:
    """What every static equilibrium of a system holds, whichever statics found it (the catenary's
    :class:`~seacable.system.statics.SystemEquilibrium`, the finite elements'
    :class:`~seacable.system.statics.fe.FEEquilibrium`); the attributes are documented there."""

    system: MooringSystem
    environment: Environment
    body_names: list
    body_position: np.ndarray
    free_body_names: list
    point_names: list
    point_position: np.ndarray
    line_names: list
    end_a_force: np.ndarray
    end_b_force: np.ndarray
    end_a_tension: np.ndarray
    end_b_tension: np.ndarray
    grounded_length: np.ndarray
    stiffness: np.ndarray
    hydrostatic: np.ndarray
    iterations: int
    residual: float

    def _free_body(self, name: str) -> int:
        if name not in self.free_body_names:
            from ..._model import suggest

            raise InputError(f"body '{name}' is not a free body of this system (free bodies: "
                             f"{', '.join(self.free_body_names) or 'none'}).{suggest(name, self.free_body_names)}")
        return self.free_body_names.index(name)

    def body_stiffness(self, name: str, hydrostatics: bool = False) -> np.ndarray:
        """6x6 stiffness of one free body, other free bodies held, free points equilibrated.

        Parameters
        ----------
        name : str
            A free body.
        hydrostatics : bool
            Add the body's hydrostatic (weight, buoyancy, waterplane) restoring.

        Returns
        -------
        ndarray, shape (6, 6)
            [N/m, N/rad, N m/m, N m/rad]
        """
        k = self._free_body(name)
        K = self.stiffness[6 * k:6 * k + 6, 6 * k:6 * k + 6].copy()
        if hydrostatics:
            K += self.hydrostatic[6 * k:6 * k + 6, 6 * k:6 * k + 6]
        return K

    def body_offset(self, name: str) -> np.ndarray:
        """Position of a body minus the position given in the system. [m, rad]"""
        i = self.body_names.index(name)
        return self.body_position[i] - np.asarray(self.system.bodies[name].position, float)


@dataclass
class Assembly:
    """Flattened system (see the module docstring); arrays indexed by node or sub-line."""

    rho: float
    g: float
    depth: float | None
    friction: float
    body_names: list
    free_bodies: list            # indices into body_names of the solved bodies (free, and prescribed pinned)
    node_kind: np.ndarray        # (nn,) FIXED / BODY / FREE
    node_body: np.ndarray        # (nn,) index into free_bodies for BODY nodes, else -1
    node_rel: np.ndarray         # (nn, 3) body-frame offset of BODY nodes
    node_pos0: np.ndarray        # (nn, 3) global position of FIXED nodes and start of FREE nodes
    node_force: np.ndarray       # (nn, 3) constant force on the node (weights, external) [N]
    node_label: list             # what each node is, for messages
    point_node: dict             # system point name -> node
    sub_a: np.ndarray            # (ns,) node at the sub-line's end nearer line end A
    sub_b: np.ndarray
    sub_L: np.ndarray
    sub_EA: np.ndarray
    sub_w: np.ndarray
    sub_line: np.ndarray         # (ns,) index of the line
    sub_s0: np.ndarray           # (ns,) arc length of the sub-line's A end along its line [m]
    line_names: list
    line_first: np.ndarray       # (nl,) first sub-line of each line
    line_last: np.ndarray        # (nl,) last sub-line
    free_nodes: np.ndarray       # indices of FREE nodes (each 3 DOF after the bodies' 6)
    node_dof: np.ndarray         # (nn,) first DOF of the node's body (BODY) or of the node (FREE), else -1
    extra_cuts: dict | None = None   # line name -> arc lengths of added internal nodes (sag onto the seabed)
    air: dict | None = None          # line name -> arc-length intervals above the water (dry weight)
    tables: tuple | None = None      # (ts_lo, ts_hi, tT, te): inverse strain-tension tables, or None
    node_buoy: np.ndarray | None = None  # (nn,) buoyancy of what sits at the nodes (points, attachments), None: none [N]

    @property
    def n_dof(self) -> int:
        return 6 * len(self.free_bodies) + 3 * len(self.free_nodes)


def check_environment(env: Environment) -> None:
    """Refuse what the catenary lines cannot model (current, sloping seabed, wind)."""
    cur = env.current
    speeds = [cur.speed] if cur.depths is None else list(cur.speeds)
    if any(abs(v) > 0 for v in speeds):
        raise InputError(f"environment.current: a current of {max(abs(v) for v in speeds):g} m/s is not "
                         "supported by the catenary system statics: each line is an elastic catenary in the "
                         "vertical plane through its ends, which has no drag load. Suggested fix: set the "
                         "current speed to 0 for the catenary statics, or leave analysis.statics at 'auto' (the "
                         "system analyses then use the finite-element statics: "
                         "seacable.system.statics.fe.fe_equilibrium).")
    wind = getattr(env, "wind", None)
    if wind is not None and wind.speed > 0:
        raise InputError(f"environment.wind: a wind of {wind.speed:g} m/s is not supported by the catenary system "
                         "statics (its force on a body turns with the body's heading). Suggested fix: leave "
                         "analysis.statics at 'auto' (the system analyses then use the finite-element statics), or "
                         "give the wind's force as the body's external_force.")
    if env.seabed.slope != 0:
        raise InputError(f"environment.seabed.slope = {env.seabed.slope:g} rad is not supported by the system "
                         "catenary statics: their seabed is horizontal. Suggested fix: use slope 0, or leave "
                         "analysis.statics at 'auto' (the system analyses then use the finite-element statics).")
    if env.seabed.grid is not None:
        raise InputError("environment.seabed.grid is not supported by the system catenary statics: their seabed is a "
                         "horizontal plane. Suggested fix: leave analysis.statics at 'auto' (the system analyses then "
                         "use the finite-element statics, whose contact follows the grid).")


def assemble(system: MooringSystem, env: Environment, extra_cuts: dict | None = None,
             air: dict | None = None) -> Assembly:
    """Flatten ``system`` in ``env`` into nodes and sub-lines, checking what statics needs.

    ``extra_cuts``: ``{line name: arc lengths [m]}`` of further internal nodes (massless): where a
    line sagging into the seabed between its nodes may land, where a line crosses the surface.
    ``air``: ``{line name: ((s0, s1), ...)}`` arc-length intervals above the water, where a
    sub-line (its middle in one) weighs its dry weight ``m g``.
    """
    check_environment(env)
    from ..statics_mode import line_reasons

    lines = line_reasons(system.lines)
    if lines:
        raise InputError(f"the catenary system statics cannot carry a {lines}: each line is an elastic catenary "
                         "without bending or sections. Suggested fix: leave analysis.statics at 'auto' (the system "
                         "analyses then use the finite-element statics: seacable.system.statics.fe.fe_equilibrium).")
    rho, g = env.water_density, env.gravity
    depth = env.depth
    body_names = list(system.bodies)
    # solved bodies: free ones, and prescribed ones pinned (CoupledPinned: rotations free, point held)
    free_bodies = [i for i, n in enumerate(body_names) if system.bodies[n].kind == "free"
                   or (system.bodies[n].kind == "prescribed" and system.bodies[n].pinned)]
    free_index = {body_names[i]: k for k, i in enumerate(free_bodies)}
    kind, nbody, rel, pos0, force, label, buoy = [], [], [], [], [], [], []
    point_node = {}
    for name, p in system.points.items():
        point_node[name] = len(kind)
        label.append(f"points.{name}")
        f = np.array(p.external_force, float)
        f[2] -= p.net_weight(rho, g)
        force.append(f)
        buoy.append(rho * g * p.volume)
        if p.kind == "body":
            body = system.bodies[p.body]
            if p.body in free_index:
                kind.append(BODY)
                nbody.append(free_index[p.body])
                rel.append(np.array(p.position, float))
                pos0.append(np.zeros(3))
                continue
            R = rotation(body.position[3:])
            kind.append(FIXED)
            pos0.append(np.asarray(body.position[:3], float) + R @ np.asarray(p.position, float))
        else:
            kind.append(FREE if p.kind == "free" else FIXED)
            pos0.append(np.array(p.position, float))
        nbody.append(-1)
        rel.append(np.zeros(3))

    sub = {k: [] for k in ("a", "b", "L", "EA", "w", "line", "s0")}
    ts_lo, ts_hi, ts_T, ts_e = [], [], [], []
    first, last = [], []
    line_names = list(system.lines)
    for il, (lname, sl) in enumerate(system.lines.items()):
        line = sl.line
        total = line.length
        na, nb = point_node[sl.end_a], point_node[sl.end_b]
        # cut points: segment ends and attachments; net weight of the attachments at each cut
        ends = line.segment_ends
        cuts = {}
        for s in list(ends[1:-1]) + list((extra_cuts or {}).get(lname, ())):
            cuts.setdefault(round(s / total / _MERGE), [s, 0.0])
        end_load = {na: 0.0, nb: 0.0}
        end_buoy = {na: 0.0, nb: 0.0}
        for i, att in enumerate(line.attachments):
            wgt = att.net_weight(rho, g)
            b = att.mass * g - wgt            # its buoyancy (it weighs m g in air)
            if att.s <= _MERGE * total:
                end_load[na] += wgt
                end_buoy[na] += b
            elif att.s >= total * (1 - _MERGE):
                end_load[nb] += wgt
                end_buoy[nb] += b
            else:
                c = cuts.setdefault(round(att.s / total / _MERGE), [att.s, 0.0])
                c[1] += wgt
                c.append(b)
        for node, wgt in end_load.items():
            force[node] = force[node] + np.array([0.0, 0.0, -wgt])
            buoy[node] += end_buoy[node]
        cut_s = sorted(cuts.values(), key=lambda c: c[0])
        pa, pb = _guess_end(na, kind, nbody, rel, pos0, system, body_names, free_bodies), \
            _guess_end(nb, kind, nbody, rel, pos0, system, body_names, free_bodies)
        nodes = [na]
        start = _start_positions(line, pa, pb, [c[0] for c in cut_s], rho, g, depth)
        for (s, wgt, *b_att), p0 in zip(cut_s, start):
            nodes.append(len(kind))
            buoy.append(sum(b_att))
            kind.append(FREE)
            nbody.append(-1)
            rel.append(np.zeros(3))
            pos0.append(p0)
            force.append(np.array([0.0, 0.0, -wgt]))
            label.append(f"lines.{lname} at s = {s:g} m")
        nodes.append(nb)
        bounds = [0.0] + [c[0] for c in cut_s] + [total]
        first.append(len(sub["a"]))
        for k in range(len(nodes) - 1):
            s0, s1 = bounds[k], bounds[k + 1]
            mid = 0.5 * (s0 + s1)
            seg = next(j for j in range(len(line.segments)) if mid <= ends[j + 1])
            lt = line.segments[seg].line_type
            if lt.axial_stiffness is None and lt.tension_strain is None:
                raise InputError(f"lines.{lname}: line type {lt.name or seg} has no axial_stiffness; the "
                                 "system statics needs EA in N. Suggested fix: give axial_stiffness "
                                 "(a very large value for an almost inextensible line).")
            sub["a"].append(nodes[k])
            sub["b"].append(nodes[k + 1])
            sub["L"].append(s1 - s0)
            ts_lo.append(len(ts_T))
            if lt.tension_strain is not None:
                T_inv, e_inv = inverse_table(lt.tension_strain)
                ts_T.extend(T_inv)
                ts_e.extend(e_inv)
            ts_hi.append(len(ts_T))
            sub["EA"].append(lt.axial_stiffness if lt.axial_stiffness is not None else table_secant(lt.tension_strain))
            dry = any(a <= mid <= b for a, b in (air or {}).get(lname, ()))
            sub["w"].append(lt.mass_per_length * g if dry else lt.submerged_weight(rho, g))
            sub["line"].append(il)
            sub["s0"].append(s0)
        last.append(len(sub["a"]) - 1)

    kind = np.array(kind, int)
    pos0 = np.array(pos0, float).reshape(-1, 3)  # (0, 3) for a system of bodies alone
    asm = Assembly(rho=rho, g=g, depth=depth, friction=env.seabed.friction, body_names=body_names,
                   free_bodies=free_bodies, node_kind=kind, node_body=np.array(nbody, int),
                   node_rel=np.array(rel, float).reshape(-1, 3), node_pos0=pos0,
                   node_force=np.array(force, float).reshape(-1, 3),
                   node_label=label, point_node=point_node,
                   **{f"sub_{k}": np.array(v, int if k in ("a", "b", "line") else float) for k, v in sub.items()},
                   line_names=line_names, line_first=np.array(first, int), line_last=np.array(last, int),
                   free_nodes=np.flatnonzero(kind == FREE), node_dof=np.full(kind.size, -1),
                   extra_cuts={k: tuple(v) for k, v in (extra_cuts or {}).items()},
                   air={k: tuple(v) for k, v in (air or {}).items()},
                   node_buoy=np.array(buoy, float) if any(buoy) else None,
                   tables=(np.array(ts_lo, np.int64), np.array(ts_hi, np.int64), np.array(ts_T, float),
                           np.array(ts_e, float)) if ts_T else None)
    nb = len(free_bodies)
    asm.node_dof[kind == BODY] = 6 * asm.node_body[kind == BODY]
    asm.node_dof[asm.free_nodes] = 6 * nb + 3 * np.arange(asm.free_nodes.size)
    _check_depths(asm, system)
    return asm


def inverse_table(table) -> tuple[list, list]:
    """A strain-tension table ``((strain, tension), ...)`` as its inverse, tension points from 0 and
    their strains (for :mod:`.catenary`: strain linear in tension between the points).

    MoorDyn's tension is linear in strain between the points and held flat beyond the last; a
    table whose first point is not at the origin is joined to it by a straight line here (MoorDyn
    holds the first point's tension down to zero strain, a jump the statics cannot take).
    """
    pts = [(float(t), float(e)) for e, t in table]
    if pts[0][0] > 0:
        pts.insert(0, (0.0, 0.0))
    return [p[0] for p in pts], [p[1] for p in pts]


def _start_positions(line, pa, pb, cut_s, rho, g, depth):
    """Starting positions of a line's internal nodes: on one catenary of the whole line.

    The line's mean weight and stiffness, its attachments left out (on the chord if that
    catenary has no solution or the line is buoyant on average).
    """
    total = line.length
    chord = [pa + (pb - pa) * s / total for s in cut_s]
    if not cut_s:
        return chord
    lengths = np.array([seg.length for seg in line.segments])
    w = float(np.dot(lengths, line.weights(rho, g)) / total)
    ea = [seg.line_type.axial_stiffness for seg in line.segments]
    if w <= 0 or any(e is None for e in ea):
        return chord
    low, high, flip = (pa, pb, False) if pa[2] <= pb[2] else (pb, pa, True)
    d = high - low
    h = float(np.hypot(d[0], d[1]))
    seabed = depth is not None and low[2] <= -depth + 1e-6 * depth
    try:
        from ...statics.catenary import catenary

        res = catenary(h, max(float(d[2]), 0.0), total, float(np.dot(lengths, ea) / total), w, 0.0, seabed)
        prof = res.profile(400)
    except Exception:  # noqa: BLE001 - any failure only costs a worse starting point
        return chord
    e = d[:2] / h if h > 0 else np.array([1.0, 0.0])
    out = []
    for s in cut_s:
        sc = total - s if flip else s
        x, z = np.interp(sc, prof.s, prof.x), np.interp(sc, prof.s, prof.z)
        p = low + np.array([x * e[0], x * e[1], z])
        if depth is not None:       # nodes start just off the seabed (they land if they must)
            p[2] = max(p[2], -depth + min(1.0, 0.01 * depth))
        out.append(p)
    return out


def _guess_end(node, kind, nbody, rel, pos0, system, body_names, free_bodies):
    if kind[node] == BODY:
        body = system.bodies[body_names[free_bodies[nbody[node]]]]
        return np.asarray(body.position[:3], float) + rotation(body.position[3:]) @ rel[node]
    return np.asarray(pos0[node], float)


def _check_depths(asm: Assembly, system: MooringSystem) -> None:
    if asm.depth is None:
        return
    tol = 1e-6 * asm.depth
    for name, node in asm.point_node.items():
        if asm.node_kind[node] == FIXED and asm.node_pos0[node, 2] < -asm.depth - tol:
            raise InputError(f"points.{name}: z = {asm.node_pos0[node, 2]:.6g} m is below the seabed at "
                             f"z = {-asm.depth:g} m (environment.depth = {asm.depth:g} m). The catenary "
                             "lines cannot end inside the seabed. Suggested fix: put the point on or above "
                             "the seabed, or correct environment.depth.")

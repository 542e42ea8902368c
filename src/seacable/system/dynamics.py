"""Coupled dynamics of a mooring system (analysis ``system_dynamic``): finite-element lines and rigid bodies.

Every line of a :class:`~seacable.system.model.MooringSystem` is discretised into truss elements as
the single-line mooring model (:func:`seacable.mooring.network.network_from_line`: segments,
attachments, element count); lines that end at the same point share its node. Fixed points are held,
coupled points follow a motion, free points move with their mass, volume, added mass and drag area.
A point on a free body is tied to it (``x = r + R(theta) p``); a point on a fixed body is held, a
point on a prescribed body follows the body's 6-DOF motion.

A free body has six degrees of freedom: the reference point (x, y, z) and the angles (roll, pitch,
yaw), ``R = Rz(yaw) Ry(pitch) Rx(roll)``. Its loads (global axes, moments about the reference point):
weight ``m g`` at the centre of gravity and buoyancy ``rho g V`` at the centre of buoyancy (both turning
with the body), the waterplane's heave restoring ``-rho g A_wp (z - z_given)`` at the reference point
(the volume is the one at the body's given position) and its moment ``rho g (I_xx a_y, -I_yy a_x, 0)`` with ``a = R e_z``
(``-rho g I phi`` for small roll or pitch) -- or, when given, the user's 6x6 hydrostatic matrix about
the given position (weight and buoyancy then as at that position): the conventions of the system
statics (:mod:`seacable.system.statics`, MoorPy's Body);
the constant external force, an optional external force time series, linear and quadratic damping
(6x6, body axes: ``-B1 v - B2 |v_r| v_r``, ``v_r`` the velocity relative to the current at the reference
point -- at the surface when it is above --, so that a body in a current drifts to where its lines
balance the current's drag; waves act on the lines only), added mass (6x6, body axes) and the forces
of the lines at its points. The inertia is the rigid body's about the reference point (``I_cg`` moved by the parallel-axis
rule, the coupling ``m skew(c)`` of an offset centre of gravity).

One implicit step advances the lines and the bodies together: Newmark's average acceleration (beta
1/4, gamma 1/2) with Newton iterations on the free nodes and the body DOFs at once; the banded
system of the nodes is bordered by the bodies and solved by its Schur complement
(:mod:`seacable.system._dyn_kernel`), so a step costs no more than one of the prescribed-motion
model (``bench/bench_system_dynamics.py``). Rotations: the unknowns are the angles and the geometry is exact at any angle; the angular
velocity is ``w = E(angles) d(angles)/dt`` (``w = roll' Rz Ry e_x + pitch' Rz e_y + yaw' e_z``) and the
rigid body's rotational inertia acts on ``dw/dt = E angles'' + E' angles'``, with its gyroscopic moment
``w x (I w)`` and the centripetal force ``m w x (w x c)`` of an offset centre of gravity (those of the added
mass in a turning frame are left out); the moments enter as the angles' generalised forces ``E^T M``.
``E`` is singular at pitch +-90 deg, so each body carries a chart: ``R = R0 R(angles)`` with a base
rotation ``R0`` (the identity to start with). After a converged step (and at the start) a body whose
|pitch| exceeds 1 rad is re-charted: ``R0 <- R0 R(angles)``, angles <- 0, and the rates re-expressed so
that the angular velocity and acceleration are unchanged (``angles' = R0^T w``, ``angles'' = R0^T alpha -
E'(0) angles'``, :func:`seacable.system._dyn_kernel.rechart`), and from then on after every step (its
angles then stay within one step's turn of 0: incremental rotations, as accurate whichever way the body
points, and its Newton matrix takes the velocity part of the angular acceleration too,
:func:`~seacable.system._dyn_kernel.rate_tangent`); everything that uses the rotation (points,
centres of gravity and buoyancy, inertia, added mass, damping, waterplane) uses ``R0 R(angles)``, ``E``
becomes ``R0 E``. A body that never passes 1 rad of pitch keeps ``R0 = I`` and its results are those
without charts, bit for bit. The output ``body_position`` angles are the global (roll, pitch, yaw) of
``R = Rz(yaw) Ry(pitch) Rx(roll)`` followed continuously from step to step (of their two Euler branches,
moved by whole turns, the one nearest the last; pitch then leaves [-pi/2, pi/2] when the body turns
over): continuous except at pitch +-90 deg itself, where only roll -+ yaw is defined. ``body_velocity``
reports the reference point's velocity and the rates of those angles (``E^-1 w``, regularised at pitch
+-90 deg as the Newton step is), ``body_angular_velocity`` the angular velocity ``w`` (global axes),
which stays regular there.

The statics (and the static start) leave out of each Newton step the turn about a body's free spin
axis, when it has one: the line through its reference point on which all its line points and its
centres of gravity and buoyancy lie (a MoorDyn rod), turning about which changes none of its loads.
Without it the Newton matrix's unsymmetric turning terms give that stiffness-free turn steps of
hundreds of radians, and the step limit (0.1 rad) then stalls the whole solve.

A line end can fail (``failures``): at a given time, or when the tension of its end element first
reaches a given value; the end's node (a node of its own from the start, tied to its point until
then: held there, on its body, or at a free point on the point's node, ``x_end = x_point``, the tie's
force passing to the point) is released with the position and velocity it has and moves freely with
its half element; the point keeps its own mass, volume and the other lines. The time is recorded
(``failure_time``).

The run starts from the static equilibrium of the same finite-element system, bodies included (and
the current's drag on them; pseudo-transient Newton on the same bordered system with the inertia
replaced by a pseudo-mass); ``release_offsets`` then hold named free bodies at their equilibrium plus an offset while the lines
settle, and release them at t = 0 (a free decay); ``start: held`` instead holds the free bodies at
their given positions for the static start, as MoorDyn starts its free bodies.

Stiff modes the step cannot resolve (the axial ringing of a snapped line end) are not damped by the
average-acceleration rule; the lines' axial damping (``damping_ratio``), water drag and seabed
friction take them, and ``numerical_damping`` adds Newmark's first-order dissipation when needed.
"""

from __future__ import annotations

import dataclasses
import math
import time as _time
import warnings
from dataclasses import dataclass, field

import numpy as np

from .._limits import check_run_size
from .._model import suggest
from ..case import SeabedContact
from ..environment import IrregularWaves
from ..errors import ConvergenceError, InputError, SeacableWarning
from ..mooring.kernel import E_BEDRAMP as K_BEDRAMP
from ..mooring.motion import RAOMotion, rotation_matrix, sea_of
from ..mooring.network import FIXED, FREE, PRESCRIBED, Network, catenary_positions, network_from_line
from ..mooring.run import elevation_variables, grounded_end_force, height_above_seabed
from ..mooring.solver import MooringModel, Water, advance_interval
from ..mooring.solver import simulate as simulate_lines
from ..results import make_dataset, var
from . import _dyn_kernel as DK
from ._stat_model import euler_rate_map
from .case import BodyMotion, ExternalForceSeries, LineFailure, SystemDynamicAnalysis  # noqa: F401  (public here)
from .damaged import is_most_loaded, line_tensions, most_loaded_line
from .model import MooringSystem

__all__ = [
    "ExternalForceSeries",
    "LineFailure",
    "SystemDynamicAnalysis",
    "SystemFE",
    "SystemRun",
    "build_system_fe",
    "prepare_system_dynamic",
    "run_system_dynamic",
    "simulate_system",
    "static_system",
]

DOFS = ("x", "y", "z", "roll", "pitch", "yaw")

REFERENCES = (
    ("Paper 004: finite-element analysis of guyed-tower mooring lines (seeds/004): truss elements with "
     "geometric nonlinearity, Newmark-beta with Newton-Raphson."),
    "Bathe, K.-J. (1996). Finite Element Procedures. Prentice Hall, sections 6.3 and 9.2.4.",
    ("Hall, M. (2020). MoorDyn V2: new capabilities in mooring system components and load cases. "
     "ASME OMAE 2020 (rigid bodies coupled with lumped-mass lines)."),
    ("Hall, M. et al. (2021). MoorPy: quasi-static mooring analysis in Python. NREL/TP (Body hydrostatics: "
     "weight at the CG, buoyancy, waterplane heave stiffness)."),
)


# --------------------------------------------------------------------------------------------- the FE system


@dataclass
class SystemFE:
    """The finite-element system of a :class:`MooringSystem`: the network and what ties nodes to bodies.

    Attributes
    ----------
    model : the lines' network in its water (band nodes: free nodes, nodes on free bodies, ends that may
        fail).
    system : the mooring system.
    free_bodies : names of the free bodies (rows of ``q``).
    q0 : (nb, 6) the free bodies' given positions.
    point_node : node of each point.
    line_names, line_nodes, line_elements : per line, its nodes (end A to B) and elements.
    fairlead_end : per line, 1 when end B is the fairlead (on a body or coupled point), 0 for end A.
    con_* : one row per tied node: node, free body (-1: held at ``con_target``; -2 - k: tied to the free node k,
        a failing line end at a free point), arm (body axes) or held position, channel.
    fail_time, fail_tension, fail_elem : failure of each tied node (inf / -1 when none).
    con_line : line of each tied node with a failure (-1 otherwise).
    """

    model: MooringModel
    system: MooringSystem
    free_bodies: tuple[str, ...]
    q0: np.ndarray
    point_node: dict[str, int]
    line_names: tuple[str, ...]
    line_nodes: tuple[np.ndarray, ...]
    line_elements: tuple[np.ndarray, ...]
    fairlead_end: np.ndarray
    node_fext: np.ndarray
    con_node: np.ndarray
    con_body: np.ndarray
    con_arm: np.ndarray
    con_target: np.ndarray
    con_chan: np.ndarray
    fail_time: np.ndarray
    fail_tension: np.ndarray
    fail_elem: np.ndarray
    con_line: np.ndarray
    channel_source: list = field(default_factory=list)  # per channel: ("point", name) or ("body", name, arm)
    bpar: np.ndarray = None
    bkhs: np.ndarray = None
    badd: np.ndarray = None
    blin: np.ndarray = None
    bquad: np.ndarray = None
    ext_t: np.ndarray = None
    ext_f: np.ndarray = None
    ext_n: np.ndarray = None
    spin: np.ndarray = None  # (nb, 3) body axes: the axis turning about which moves nothing (a rod's), or zeros
    body_motions: dict = field(default_factory=dict)  # prescribed body -> its motion bound to the run (dofs(times))

    def kernel_args(self):
        m = self.model
        net = m.network
        args = (net.elements, net.length, net.axial_stiffness, net.axial_damping, net.mass_per_length, net.diameter,
                net.cdn, net.cdt, net.can, net.cat, net.point_mass, net.point_added_mass, net.point_volume,
                net.point_hydrodynamics(), m.bedc, m.buoyancy, m.point_buoyancy, *m.tension_strain, m.hinges, m.hinge_ei,
                m.visco)
        return args

    def body_args(self):
        return (self.bpar, self.bkhs, self.badd, self.blin, self.bquad, self.ext_t, self.ext_f, self.ext_n)


def _rot(six) -> np.ndarray:
    return rotation_matrix(six[3], six[4], six[5])


def _water(environment, analysis: SystemDynamicAnalysis | None) -> Water:
    env = environment
    cur = env.current
    depths, speeds = ((0.0,), (cur.speed,)) if cur.depths is None else (cur.depths, cur.speeds)
    w = env.waves
    sea = w.components(env.depth, env.gravity) if isinstance(w, IrregularWaves) else None
    w_reg = None if sea is not None else w
    contact = analysis.seabed_contact if analysis is not None else SeabedContact()
    alpha = analysis.rayleigh[0] if analysis is not None else 0.0
    return Water(density=env.water_density, gravity=env.gravity, depth=env.depth, slope=env.seabed.slope,
                 seabed_stiffness=contact.stiffness, seabed_damping=contact.damping, friction=env.seabed.friction,
                 friction_velocity=contact.friction_velocity, current_depths=tuple(depths),
                 current_speeds=tuple(speeds), current_heading=cur.heading,
                 wave_height=w_reg.height if w_reg else 0.0, wave_period=w_reg.period if w_reg else 10.0,
                 wave_heading=w_reg.heading if w_reg else 0.0, wave_phase=w_reg.phase if w_reg else 0.0,
                 rayleigh_mass=alpha, sea=sea, stretching=w.stretching if w else "none")


def build_system_fe(system: MooringSystem, environment, analysis: SystemDynamicAnalysis | None = None, *,
                    n_elements: int | None = None) -> SystemFE:
    """The finite-element system of ``system`` in ``environment`` (nodes at the given positions, lines on
    their catenary start shapes). ``analysis`` gives the element count, damping, failures and external
    force series; ``n_elements`` overrides every line's element count."""
    rho, g = environment.water_density, environment.gravity
    depth = environment.depth
    slope = environment.seabed.slope
    a = analysis
    n_el = n_elements if n_elements is not None else (a.n_elements if a is not None else None)
    ratio, beta = (a.damping_ratio, a.rayleigh[1]) if a is not None else (0.0, 0.0)
    failures = {(f.line, f.end): f for f in (a.failures if a is not None else [])}
    free_bodies = tuple(n for n, b in system.bodies.items() if b.kind == "free")
    bindex = {n: k for k, n in enumerate(free_bodies)}

    # points: one node each
    names = list(system.points)
    pos, kind, chan = [], [], []
    channel_source = []
    for name in names:
        p = system.points[name]
        if p.kind == "body":
            body = system.bodies[p.body]
            x = np.asarray(body.position[:3]) + _rot(body.position) @ np.asarray(p.position)
            if body.kind == "free":
                k = FREE
            elif body.kind == "fixed":
                k = FIXED
            else:
                k = PRESCRIBED
        else:
            x = np.asarray(p.position, float)
            k = {"fixed": FIXED, "free": FREE, "coupled": PRESCRIBED}[p.kind]
        pos.append(x)
        kind.append(k)
        if k == PRESCRIBED:
            chan.append(len(channel_source))
            channel_source.append(("body", p.body, np.asarray(p.position, float)) if p.kind == "body"
                                  else ("point", name))
        else:
            chan.append(-1)
    point_node = {n: k for k, n in enumerate(names)}
    pm = np.array([system.points[n].mass for n in names], float)
    pa = np.array([system.points[n].added_mass for n in names], float)
    pv = np.array([system.points[n].volume for n in names], float)
    pd = np.array([system.points[n].drag_area for n in names], float)
    pw = np.array([system.points[n].net_weight(rho, g) for n in names], float)
    fext = [np.asarray(system.points[n].external_force, float) for n in names]
    # tied nodes: points on free bodies
    con = []  # (node, body, arm, target, chan, fail_time, fail_tension, fail_elem, line)
    for name in names:
        p = system.points[name]
        if p.kind == "body" and system.bodies[p.body].kind == "free":
            con.append([point_node[name], bindex[p.body], np.asarray(p.position, float), np.zeros(3), -1, math.inf,
                        math.inf, -1, -1])

    elements, props, element_line, line_nodes, line_elements = [], [], [], [], []
    arc = [np.nan] * len(names)
    fields = ("length", "axial_stiffness", "axial_damping", "mass_per_length", "weight_per_length", "diameter",
              "cdn", "cdt", "can", "cat", "breaking_load")
    extra = {f: [] for f in ("point_mass", "point_added_mass", "point_weight", "point_volume", "point_drag_area")}
    fairlead_end = []
    tables = []  # per element: its line type's strain-tension table or None
    bending, visco = [], []  # per line: its elements' EI and viscoelastic parameters
    line_names = tuple(system.lines)
    for li, (lname, sl) in enumerate(system.lines.items()):
        ends = [sl.end_a, sl.end_b]
        xa, xb = pos[point_node[ends[0]]], pos[point_node[ends[1]]]
        sub = network_from_line(sl.line, xa, xb, water_density=rho, gravity=g,
                                n_elements=n_el if n_el is not None else sl.n_elements, damping_ratio=ratio,
                                stiffness_proportional=beta, end_b="free")
        s = sub.arc_length
        n = len(s)
        # start shape: the catenary, solved from the lower end up
        lengths = np.array([seg.length for seg in sl.line.segments])
        weights = np.array(sl.line.weights(rho, g))
        ea = np.array([seg.line_type.effective_axial_stiffness() for seg in sl.line.segments])
        if xa[2] <= xb[2]:
            shape = catenary_positions(xa, xb, s, lengths, weights, ea, point_loads=sl.line.point_loads(rho, g),
                                       depth=depth, slope=slope)
        else:
            L = s[-1]
            rev = [(L - ps, w) for ps, w in sl.line.point_loads(rho, g)][::-1]
            shape = catenary_positions(xb, xa, L - s, lengths[::-1], weights[::-1], ea[::-1], point_loads=rev,
                                       depth=depth, slope=slope)
        ids = np.empty(n, np.int64)
        for j, (end, at) in enumerate(((0, 0), (1, n - 1))):
            pname = ends[end]
            f = failures.get((lname, "ab"[end]))
            if f is None:
                ids[at] = point_node[pname]
                continue
            p = system.points[pname]
            node = len(pos)
            pos.append(pos[point_node[pname]].copy())
            kind.append(FREE)
            chan.append(-1)
            arc.append(s[at])
            fext.append(np.zeros(3))
            for values in extra.values():
                values.append(0.0)
            ids[at] = node
            body = system.bodies[p.body] if p.kind == "body" else None
            b = bindex[p.body] if body is not None and body.kind == "free" else -1
            if p.kind == "free":
                b = -2 - point_node[pname]  # tied to the free point's node
            ch = chan[point_node[pname]]
            arm = np.asarray(p.position, float) if b >= 0 else np.zeros(3)
            elem = len(elements) + (0 if at == 0 else n - 2)
            con.append([node, b, arm, pos[point_node[pname]].copy(), ch, math.inf if f.time is None else f.time,
                        math.inf if f.tension is None else f.tension, elem, li])
        first = len(pos)
        ids[1:-1] = np.arange(first, first + n - 2)
        pos.extend(shape[1:-1])
        kind.extend([FREE] * (n - 2))
        chan.extend([-1] * (n - 2))
        arc.extend(s[1:-1])
        fext.extend([np.zeros(3)] * (n - 2))
        for k, values in extra.items():
            vals = getattr(sub, k)
            values.extend(vals[1:-1])
            # attachments at the line's ends sit on the end nodes
            for at in (0, n - 1):
                node = ids[at]
                if node < len(names):
                    {"point_mass": pm, "point_added_mass": pa, "point_weight": pw, "point_volume": pv,
                     "point_drag_area": pd}[k][node] += vals[at]
                else:
                    extra[k][node - len(names)] += vals[at]
        el0 = len(elements)
        elements.extend(ids[sub.elements])
        props.append(np.column_stack([getattr(sub, f) for f in fields]))
        tables.extend(sub.element_tension_strain or [None] * (n - 1))
        bending.append(np.zeros(n - 1) if sub.bending_stiffness is None else sub.bending_stiffness)
        visco.append(np.zeros((n - 1, 3)) if sub.element_viscoelastic is None else sub.element_viscoelastic)
        element_line.extend([li] * (n - 1))
        line_nodes.append(ids)
        line_elements.append(np.arange(el0, el0 + n - 1))
        moved = [system.points[e].kind in ("body", "coupled") for e in ends]
        fairlead_end.append(0 if moved[0] and not moved[1] else 1)
    P = np.vstack(props) if props else np.zeros((0, len(fields)))  # no lines: bodies (and points) alone
    nn = len(pos)
    # a point no line ends at any more (its line fails there: the line's end has its own node) carries
    # nothing: held, and not tied
    used = np.zeros(nn, bool)
    used[np.asarray(elements, np.int64).ravel()] = True
    for k in np.flatnonzero(~used):
        kind[k] = FIXED
    con = [c for c in con if used[c[0]]]
    for c in con:
        if c[1] <= -2 and not used[-2 - c[1]]:
            c[1] = -1  # a free point no other line ends at: its line's end is held there until it fails

    def full(point_values, key):
        return np.r_[point_values, np.asarray(extra[key], float)] if nn > len(names) else point_values

    net = Network(
        position=np.array(pos, float).reshape(-1, 3), kind=np.array(kind, np.int64), channel=np.array(chan, np.int64),
        point_mass=full(pm, "point_mass"), point_added_mass=full(pa, "point_added_mass"),
        point_weight=full(pw, "point_weight"), point_volume=full(pv, "point_volume"),
        point_drag_area=full(pd, "point_drag_area"), elements=np.array(elements, np.int64).reshape(-1, 2),
        length=P[:, 0], axial_stiffness=P[:, 1], axial_damping=P[:, 2], mass_per_length=P[:, 3],
        weight_per_length=P[:, 4], diameter=P[:, 5], cdn=P[:, 6], cdt=P[:, 7], can=P[:, 8], cat=P[:, 9],
        element_line=np.array(element_line, np.int64), line_nodes=tuple(line_nodes), line_names=line_names,
        arc_length=np.array(arc, float), n_channels=len(channel_source),
        channel_names=tuple(f"{src[0]} {src[1]}" for src in channel_source),
        breaking_load=P[:, 10], element_tension_strain=tuple(tables) if any(t is not None for t in tables) else None,
        bending_stiffness=np.concatenate(bending) if bending else np.zeros(0),
            element_viscoelastic=np.vstack(visco) if visco and np.any(np.vstack(visco)) else None)
    model = MooringModel(net, _water(environment, analysis))
    nb = len(free_bodies)
    bpar = np.zeros((nb, DK.B_SIZE))
    bkhs, badd, blin, bquad = (np.zeros((nb, 6, 6)) for _ in range(4))
    series = {}
    if a is not None:
        for name, ser in a.external_forces.items():
            series[name] = ser.table()
    nt = max([len(t) for t, _ in series.values()], default=1)
    ext_t, ext_f, ext_n = np.zeros((nb, nt)), np.zeros((nb, nt, 6)), np.zeros(nb, np.int64)
    for k, name in enumerate(free_bodies):
        b = system.bodies[name]
        bpar[k, DK.B_MASS], bpar[k, DK.B_VOL], bpar[k, DK.B_AWP] = b.mass, b.volume, b.waterplane_area
        bpar[k, DK.B_IXX], bpar[k, DK.B_IYY] = b.waterplane_moments
        bpar[k, DK.B_HASK] = 1.0 if b.hydrostatic_stiffness is not None else 0.0
        bpar[k, DK.B_CG:DK.B_CG + 3] = b.center_of_gravity
        bpar[k, DK.B_CB:DK.B_CB + 3] = b.center_of_buoyancy
        bpar[k, DK.B_INERT:DK.B_INERT + 3] = b.dynamic_inertia()  # a point mass's free spin: its own inertia
        bpar[k, DK.B_Q0:DK.B_Q0 + 6] = b.position
        bpar[k, DK.B_FEXT:DK.B_FEXT + 6] = b.external_force
        bkhs[k], badd[k] = b.matrix("hydrostatic_stiffness"), b.matrix("added_mass")
        blin[k], bquad[k] = b.matrix("linear_damping"), b.matrix("quadratic_damping")
        if name in series:
            t, f = series[name]
            ext_t[k, :len(t)], ext_f[k, :len(t)], ext_n[k] = t, f, len(t)
    spin = np.zeros((nb, 3))
    cur_still = not np.any(model.cur_speed)
    for k, name in enumerate(free_bodies):
        arms = [c[2] for c in con if c[1] == k]
        spin[k] = _free_spin_axis(system.bodies[name], arms, cur_still)
    C = list(zip(*con, strict=True)) if con else [[]] * 9
    fe = SystemFE(
        model=model, system=system, free_bodies=free_bodies,
        q0=np.array([system.bodies[n].position for n in free_bodies], float).reshape(nb, 6),
        point_node=point_node, line_names=line_names, line_nodes=tuple(line_nodes),
        line_elements=tuple(line_elements), fairlead_end=np.array(fairlead_end, np.int64),
        node_fext=np.array(fext, float).reshape(nn, 3),
        con_node=np.array(C[0], np.int64), con_body=np.array(C[1], np.int64),
        con_arm=np.array(C[2], float).reshape(-1, 3), con_target=np.array(C[3], float).reshape(-1, 3),
        con_chan=np.array(C[4], np.int64), fail_time=np.array(C[5], float), fail_tension=np.array(C[6], float),
        fail_elem=np.array(C[7], np.int64), con_line=np.array(C[8], np.int64), channel_source=channel_source,
        bpar=bpar, bkhs=bkhs, badd=badd, blin=blin, bquad=bquad, ext_t=ext_t, ext_f=ext_f, ext_n=ext_n, spin=spin)
    return fe


def _free_spin_axis(body, arms, still_water: bool) -> np.ndarray:
    """The body-axes unit axis about which turning the body changes none of its static loads, or zeros.

    That is the line through the reference point on which its tied points (``arms``), centre of gravity
    and centre of buoyancy all lie (a rod with its lines at its ends), when its hydrostatics do not turn
    with it (no 6x6 matrix; waterplane moments only about a vertical axis) and no current drags it (its
    damping matrices then act on the velocity only). The statics leave the turn about it out of their
    Newton steps: it has no stiffness at all. Zeros when there is no such line, or when every arm is zero
    (a point-like body: no axis is singled out).
    """
    vecs = [np.asarray(v, float) for v in (*arms, body.center_of_gravity, body.center_of_buoyancy)]
    size = max((float(np.linalg.norm(v)) for v in vecs), default=0.0)
    if size == 0.0 or body.hydrostatic_stiffness is not None:
        return np.zeros(3)
    n = max(vecs, key=lambda v: float(np.linalg.norm(v)))
    n = n / np.linalg.norm(n)
    if any(float(np.linalg.norm(np.cross(v, n))) > 1e-9 * size for v in vecs):
        return np.zeros(3)
    if any(body.waterplane_moments) and abs(n[2]) < 1.0 - 1e-12:
        return np.zeros(3)
    if not still_water and (np.any(body.matrix("linear_damping")) or np.any(body.matrix("quadratic_damping"))):
        return np.zeros(3)
    return n


# --------------------------------------------------------------------------------------------- statics


@dataclass(frozen=True)
class SystemState:
    """A static state of the finite-element system."""

    position: np.ndarray       # (n, 3) node positions [m]
    body_position: np.ndarray  # (nb, 6) free bodies [m, rad]
    tension: np.ndarray        # (e,) element tensions [N]
    iterations: int
    residual: float
    start: str = "equilibrium"  # how it was found: 'equilibrium', or 'held' (free bodies at their given positions)


def static_system(fe: SystemFE, *, held: bool = False, q=None, X=None, tol: float = 1e-9,
                  max_iter: int = 1000) -> SystemState:
    """Static equilibrium of the finite-element system, bodies included (``held``: free bodies held at ``q``,
    default their given positions). Raises :class:`ConvergenceError` with the residual."""
    m = fe.model
    net = m.network
    X = np.array(net.position if X is None else X, float)
    q = np.array(fe.q0 if q is None else q, float).reshape(-1, 6)
    con_body, con_target = fe.con_body.copy(), fe.con_target.copy()
    qs = q
    if held and len(fe.free_bodies):
        # tie the nodes to where the held bodies put them
        for j in range(len(con_body)):
            b = con_body[j]
            if b >= 0:
                con_target[j] = q[b, :3] + _rot(q[b]) @ fe.con_arm[j]
                con_body[j] = -1
        qs = np.zeros((0, 6))
    n = net.n_nodes
    F, M = np.zeros((n, 3)), np.zeros((n, 3, 3))
    tension = np.zeros(net.n_elements)
    stats = np.zeros(3)
    step = 0.5 * float(np.mean(net.length)) if net.n_elements else 1.0  # no lines: bodies alone
    active = np.ones(len(fe.con_node), np.int64)
    node_mass = float(np.max(net.mass_per_length * net.length, initial=0.0))
    body_mass = float(np.max(fe.bpar[:, DK.B_MASS], initial=0.0)) + float(np.max(fe.badd[:, 0, 0], initial=0.0))
    body_scale = min(1.0, node_mass / body_mass) if body_mass > 0 and node_mass > 0 else 1.0
    bargs = fe.body_args() if not held else tuple(np.zeros((0,) + a.shape[1:], a.dtype) for a in fe.body_args())
    qs = np.array(qs, float)
    frame = np.zeros((len(qs), DK.F_SIZE))
    spin = (fe.spin if fe.spin is not None else np.zeros((len(qs), 3))) if len(qs) else np.zeros((0, 3))
    ok = DK.coupled_static(X, qs, fe.kernel_args(), m.weight, m.fidx, m.nfree, m.bw, m.env, m.cur_depth, m.cur_speed,
                           fe.node_fext, fe.con_node, con_body, fe.con_arm, con_target, active, *bargs, tol, max_iter,
                           step, body_scale, F, M, tension, stats, frame, spin)
    qs = _global_pose(qs, frame)
    if not ok:
        qtxt = "" if not len(qs) else f"; the bodies ended at {np.array2string(qs, precision=4)}"
        raise ConvergenceError(
            f"the static equilibrium of the mooring system did not converge in {max_iter} iterations: residual "
            f"{stats[1]:.3g} N against a tolerance of {stats[2]:.3g} N{qtxt}. Suggested fix: start the bodies "
            "nearer their equilibrium, check that the lines reach their points and that the bodies float.",
            iterations=int(stats[0]), residual=float(stats[1]))
    return SystemState(X, q if held else qs, tension.copy(), int(stats[0]), float(stats[1]))


def body_line_force(fe: SystemFE, X, q, V=None, A=None, t=0.0) -> np.ndarray:
    """Force and moment of the lines on each free body (nb, 6) at a state (statics when V, A are None). [N, N m]"""
    m = fe.model
    V = np.zeros_like(X) if V is None else V
    A = np.zeros_like(X) if A is None else A
    F, M, _, _ = m.evaluate(X, V, A, t, waves=V is not None)
    F = F + fe.node_fext
    out = np.zeros((len(fe.free_bodies), 6))
    for j in range(len(fe.con_node)):
        b = fe.con_body[j]
        if b < 0:
            continue
        i = fe.con_node[j]
        mu = F[i] - M[i] @ A[i]
        arm = _rot(q[b]) @ fe.con_arm[j]
        out[b, :3] += mu
        out[b, 3:] += np.cross(arm, mu)
    return out


# --------------------------------------------------------------------------------------------- time loop


@dataclass(frozen=True)
class SystemRun:
    """Stored states of a coupled run at the output times."""

    time: np.ndarray            # (nt,)
    position: np.ndarray        # (nt, n, 3)
    velocity: np.ndarray        # (nt, n, 3)
    tension: np.ndarray         # (nt, e)
    body_position: np.ndarray   # (nt, nb, 6)
    body_velocity: np.ndarray   # (nt, nb, 6)
    failure_time: np.ndarray    # (n_tied,) NaN when the end did not fail
    time_step: float
    steps: int
    iterations: int
    wall_time: float
    interrupted: bool
    body_angular_velocity: np.ndarray | None = None  # (nt, nb, 3) global axes [rad/s]


def _channels_fn(fe: SystemFE, analysis: SystemDynamicAnalysis | None, duration: float):
    """Positions, velocities and accelerations (len(times), n_channels, 3) of the prescribed nodes."""
    net = fe.model.network
    base = net.channel_positions()
    nch = max(net.n_channels, 1)
    groups = {}
    for k, src in enumerate(fe.channel_source):
        key = src[:2]
        groups.setdefault(key, []).append(k)
    motions = []
    for key, chans in groups.items():
        kind, name = key
        mot = None
        if analysis is not None:
            if kind == "point":
                mot = analysis.point_motions.get(name)
            else:
                mot = analysis.body_motions.get(name)
                if mot is not None:
                    mot = mot.model_copy(update={"reference": tuple(fe.system.bodies[name].position[:3])})
                    if isinstance(mot, RAOMotion):
                        mot = mot.in_sea(sea_of(fe.model.water))
                    fe.body_motions[name] = mot
        if mot is not None:
            mot.channels(np.array([0.0, duration]), base[chans])  # a time series too short fails here
            motions.append((mot, np.array(chans)))

    def channels(times):
        shape = (len(times), nch, 3)
        x = np.broadcast_to(base[:nch] if len(base) else np.zeros((nch, 3)), shape).copy()
        v, a = np.zeros(shape), np.zeros(shape)
        for mot, chans in motions:
            x[:, chans], v[:, chans], a[:, chans] = mot.channels(times, base[chans])
        return x, v, a

    return channels


def initial_accelerations(fe: SystemFE, X, V, A, q, qd, qdd, frame, v0, a0) -> None:
    """The accelerations at t = 0 that satisfy the equations of motion there, in place: ``A`` of the lines'
    nodes and ``qdd`` of the free bodies (and ``V`` of the nodes tied to a body, its velocity there), with the waves at t = 0 and the start's velocities (the bodies'
    ``qd``; the lines at rest), as the mooring model starts (:func:`seacable.mooring.solver.simulate`).

    A free node: ``M a = F``. A node tied to a free body moves with it, ``a_j = a + alpha x r_j + w x (w x
    r_j)``, and its inertia and forces join the body's: ``(M6 + sum T_j^T M_j T_j) (a, alpha) = f6 + sum T_j^T
    (F_j - M_j w x (w x r_j))``, ``T_j = [I, -skew(r_j)]``. A line end tied to a free point's node moves with it:
    the pair's masses and forces together. A tied end held at a point follows it (``v0``, ``a0``: the channels'
    velocities and accelerations at t = 0, (n_channels, 3)).

    Newmark's average acceleration carries an error in the start's acceleration through the whole run (half a
    step of it in every later velocity, undamped): a static start is not at equilibrium once the waves act
    at t = 0, and a start at rest (zero acceleration) put 2.8 kN (3.5 % of the tension range) into 100 s of a
    line in waves that the mooring model, which starts here, does not have.
    """
    m = fe.model
    F, M, _, _ = m.evaluate(X, V, A, 0.0, settled=True)
    F = F + fe.node_fext
    free = m.fidx >= 0
    tied = np.zeros(len(X), bool)
    tied[fe.con_node] = True
    own = free & ~tied
    # free nodes and the line ends tied to them (a failing end at a free point): one mass, one force
    Mg, Fg = M.copy(), F.copy()
    for j in range(len(fe.con_node)):
        b = fe.con_body[j]
        if b <= -2:
            Mg[-2 - b] += M[fe.con_node[j]]
            Fg[-2 - b] += F[fe.con_node[j]]
    A[own] = np.linalg.solve(Mg[own], Fg[own][..., None])[..., 0]
    nb = q.shape[0]
    R = np.zeros((3, 3))
    rows = [[] for _ in range(nb)]
    for j in range(len(fe.con_node)):
        i, b = fe.con_node[j], fe.con_body[j]
        if b <= -2:
            A[i] = A[-2 - b]
        elif b == -1:
            ch = fe.con_chan[j]
            if ch >= 0:
                V[i], A[i] = v0[ch], a0[ch]
            else:
                A[i] = 0.0
        else:
            rows[b].append(j)
    for b in range(nb):
        E, ed = np.zeros((3, 3)), np.zeros(3)
        DK.angular_map(q[b], qd[b], E, ed, frame[b])
        w = E @ qd[b, 3:]
        f6, M6 = np.zeros(6), np.zeros((6, 6))
        uc = np.zeros(3)
        DK._body_current(q[b], m.env, m.cur_depth, m.cur_speed, uc)
        DK.body_load(q[b], np.r_[qd[b, :3], w], uc, 0.0, fe.bpar[b], fe.bkhs[b], fe.badd[b], fe.blin[b], fe.bquad[b],
                     fe.ext_t[b], fe.ext_f[b], int(fe.ext_n[b]), m.water.density, m.water.gravity, f6, M6, frame[b])
        DK.body_rotation(q[b], frame[b], R)
        arms = {}
        for j in rows[b]:
            i = fe.con_node[j]
            r = R @ fe.con_arm[j]
            arms[j] = r
            T = np.hstack((np.eye(3), -_cross_matrix(r)))
            M6 += T.T @ M[i] @ T
            f6 += T.T @ (F[i] - M[i] @ np.cross(w, np.cross(w, r)))
        acc = np.linalg.solve(M6, f6)
        qdd[b] = np.r_[acc[:3], np.linalg.solve(E, acc[3:] - ed)]
        for j, r in arms.items():
            V[fe.con_node[j]] = qd[b, :3] + np.cross(w, r)
            A[fe.con_node[j]] = acc[:3] + np.cross(acc[3:], r) + np.cross(w, np.cross(w, r))


def _cross_matrix(r) -> np.ndarray:
    """skew(r): skew(r) v = r x v."""
    return np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])


def simulate_system(fe: SystemFE, start: SystemState, duration: float, dt: float, output_interval: float, *,
                    analysis: SystemDynamicAnalysis | None = None, tol: float = 1e-7, max_iter: int = 30,
                    beta: float = 0.25, gamma: float = 0.5, progress=None, max_halvings: int = 6,
                    body_velocity=None) -> SystemRun:
    """Newmark time stepping of the coupled system from rest at ``start`` (the free bodies at ``body_velocity``,
    (nb, 6) reference point velocity [m/s] and angle rates [rad/s], when given; the lines at rest)."""
    m = fe.model
    net = m.network
    n = net.n_nodes
    X = start.position.copy()
    V, A = np.zeros_like(X), np.zeros_like(X)
    q = start.body_position.copy().reshape(-1, 6)
    nb = len(fe.free_bodies)
    qd = np.zeros((nb, 6)) if body_velocity is None else np.array(body_velocity, float).reshape(nb, 6)
    qdd = np.zeros((nb, 6))
    channels = _channels_fn(fe, analysis, duration)
    x0, v0, a0 = channels(np.zeros(1))
    pres = np.flatnonzero(net.channel >= 0)
    X[pres], V[pres], A[pres] = x0[0, net.channel[pres]], v0[0, net.channel[pres]], a0[0, net.channel[pres]]
    con_target = fe.con_target.copy()
    active = np.ones(len(fe.con_node), np.int64)
    fail_at = np.full(len(fe.con_node), np.nan)
    # each body's chart: R = R0 R(angles), R0 = I until its |pitch| passes DK.CHART_LIMIT (from the start too)
    frame = np.zeros((nb, DK.F_SIZE))
    frame[:, DK.F_GLOB:DK.F_GLOB + 3] = q[:, 3:]
    for b in range(nb):
        DK.rechart(q[b], qd[b], qdd[b], frame[b], DK.CHART_LIMIT)
    n_out = int(round(duration / output_interval))  # noqa: RUF046
    sub = max(1, math.ceil(output_interval / dt - 1e-9))
    h = output_interval / sub
    F, M = np.zeros((n, 3)), np.zeros((n, 3, 3))
    tension = np.zeros(net.n_elements)
    m.settle_viscoelastic(X, np.zeros_like(X))
    _, _, t0_tension, _ = m.evaluate(X, V, A, 0.0)
    initial_accelerations(fe, X, V, A, q, qd, qdd, frame, v0[0], a0[0])
    g = _global_state(q, qd, frame)
    times, pos, vel, ten, bq, bqd, bw = [0.0], [X.copy()], [V.copy()], [t0_tension], [g[0]], [g[1]], [g[2]]
    stats = np.zeros(3)
    iterations = steps = 0
    interrupted = False
    args = fe.kernel_args()
    bargs = fe.body_args()
    begin = _time.perf_counter()
    try:
        for k in range(n_out):
            def coupled(t, dtk, px, pv, pa):
                return DK.coupled_steps(X, V, A, q, qd, qdd, t, dtk, px, pv, pa, net.channel, args, m.weight, m.fidx,
                                        m.nfree, m.bw, m.env, m.cur_depth, m.cur_speed, True, fe.node_fext,
                                        fe.con_node, fe.con_body, fe.con_arm, con_target, active, fe.con_chan,
                                        fe.fail_time, fe.fail_tension, fe.fail_elem, fail_at, *bargs, beta, gamma,
                                        tol, max_iter, F, M, tension, stats, frame)

            done, spent = advance_interval(k * output_interval, h, sub, channels, coupled, stats, max_halvings,
                                           max_iter, "system", "smaller time_step, more elements, or check the "
                                                               "motions and external forces for a jump")
            steps += done
            iterations += spent
            times.append((k + 1) * output_interval)
            pos.append(X.copy())
            vel.append(V.copy())
            ten.append(tension.copy())
            g = _global_state(q, qd, frame)
            bq.append(g[0])
            bqd.append(g[1])
            bw.append(g[2])
            if progress is not None:
                progress(times[-1], duration)
    except KeyboardInterrupt:
        interrupted = True
    wall = _time.perf_counter() - begin
    nt = min(len(times), len(pos), len(vel), len(ten), len(bq), len(bqd), len(bw))
    return SystemRun(time=np.array(times[:nt]), position=np.array(pos[:nt]), velocity=np.array(vel[:nt]),
                     tension=np.array(ten[:nt]), body_position=np.array(bq[:nt]).reshape(nt, nb, 6),
                     body_velocity=np.array(bqd[:nt]).reshape(nt, nb, 6), failure_time=fail_at, time_step=h,
                     steps=steps, iterations=iterations, wall_time=wall, interrupted=interrupted,
                     body_angular_velocity=np.array(bw[:nt]).reshape(nt, nb, 3))


def _simulate_lines(fe: SystemFE, start: SystemState, duration: float, dt: float, output_interval: float, *,
                    analysis: SystemDynamicAnalysis | None = None, tol: float = 1e-7, max_iter: int = 30,
                    beta: float = 0.25, gamma: float = 0.5, progress=None) -> SystemRun:
    """:func:`simulate_system` for a system whose lines are all it solves for (:func:`lines_only`): the mooring
    model's compiled time loop (:func:`seacable.mooring.solver.simulate`), the same Newmark scheme."""
    run = simulate_lines(fe.model, _channels_fn(fe, analysis, duration), duration, dt, output_interval,
                         initial=start.position, tol=tol, max_iter=max_iter, progress=progress, beta=beta,
                         gamma=gamma)
    nt = len(run.time)
    return SystemRun(time=run.time, position=run.position, velocity=run.velocity, tension=run.tension,
                     body_position=np.zeros((nt, 0, 6)), body_velocity=np.zeros((nt, 0, 6)),
                     failure_time=np.zeros(0), time_step=run.time_step, steps=run.steps, iterations=run.iterations,
                     wall_time=run.wall_time, interrupted=run.interrupted,
                     body_angular_velocity=np.zeros((nt, 0, 3)))


def _global_pose(q, frame) -> np.ndarray:
    """The bodies' poses (nb, 6) with the global (roll, pitch, yaw) of their charts' ``R0 R(angles)``."""
    out = np.array(q, float).reshape(-1, 6)
    for b in range(out.shape[0]):
        if frame[b, DK.F_ON]:
            g = np.empty(3)
            DK.global_angles(out[b], frame[b], g)
            out[b, 3:] = g
    return out


def _global_state(q, qd, frame):
    """Poses (nb, 6) and velocities (nb, 6) in the global angles, and angular velocities (nb, 3), of the
    bodies' chart states: a body never re-charted as it is (its angles are the global ones); a re-charted
    one with the global angles of ``R0 R(angles)`` (continuous, :func:`~seacable.system._dyn_kernel.euler_near`)
    and their rates ``E(global)^-1 w`` (regularised at pitch +-90 deg as the Newton step,
    :func:`~seacable.system._dyn_kernel._angle_increment`)."""
    nb = q.shape[0]
    pose, vel, w = q.copy(), qd.copy(), np.zeros((nb, 3))
    eye = np.zeros(DK.F_SIZE)
    for b in range(nb):
        E, ed = np.zeros((3, 3)), np.zeros(3)
        DK.angular_map(q[b], qd[b], E, ed, frame[b])
        w[b] = E @ qd[b, 3:]
        if frame[b, DK.F_ON]:
            pose[b, 3:] = frame[b, DK.F_GLOB:DK.F_GLOB + 3]
            rates = w[b].copy()
            DK._angle_increment(pose[b], rates, eye)
            vel[b, 3:] = rates
    return pose, vel, w


# --------------------------------------------------------------------------------------------- the analysis


def _system_of(case) -> MooringSystem:
    """The MooringSystem of a case: ``case.system()`` or ``case.system``, or its points/bodies/lines."""
    damaged = getattr(case, "damaged_system", None)
    named = getattr(case.analysis, "damaged_lines", ())
    if callable(damaged) and named:
        return damaged((most_loaded_at_start(case),)) if is_most_loaded(named) else damaged()
    sys_ = getattr(case, "system", None)
    if callable(sys_):
        sys_ = sys_()
    if isinstance(sys_, MooringSystem):
        return sys_
    try:
        return MooringSystem(points=case.points, bodies=getattr(case, "bodies", {}) or {}, lines=case.lines)
    except AttributeError:
        raise InputError(f"a system_dynamic case needs a mooring system (points, bodies, lines); got "
                         f"{type(case).__name__}. Suggested fix: give 'points', 'bodies' and 'lines'.") from None


def _moment_sources(system: MooringSystem, name: str, analysis: SystemDynamicAnalysis) -> list[str]:
    """What could turn body ``name`` about its centre of gravity (for a body with no inertia about it): lines
    and loaded points off the centre of gravity, buoyancy off it, hydrostatics, external moments (or forces at
    a reference point off it), damping and added mass that act on the rotations or at such a reference point."""
    b = system.bodies[name]
    cg = np.asarray(b.center_of_gravity, float)
    tol = 1e-9 * (1.0 + float(np.linalg.norm(cg)))
    off = float(np.linalg.norm(cg)) > tol
    ends = {e for line in system.lines.values() for e in (line.end_a, line.end_b)}
    out = [f"point {p}" for p, pt in system.points.items()
           if pt.kind == "body" and pt.body == name and float(np.linalg.norm(np.asarray(pt.position) - cg)) > tol
           and (p in ends or pt.mass or pt.volume or pt.drag_area or any(pt.external_force))]
    if b.volume > 0 and float(np.linalg.norm(np.asarray(b.center_of_buoyancy) - cg)) > tol:
        out.append("its buoyancy")
    if b.waterplane_area > 0 or any(b.waterplane_moments) or b.hydrostatic_stiffness is not None:
        out.append("its hydrostatics")
    force = np.asarray(b.external_force, float)
    if force[3:].any() or (off and force[:3].any()) or name in analysis.external_forces:
        out.append("its external force")
    for key in ("linear_damping", "quadratic_damping"):
        m = b.matrix(key)
        if m[3:].any() or m[:, 3:].any() or (off and m.any()):
            out.append(f"its {key}")
    return out


@dataclass
class SystemDynamicSetup:
    """What the time loop of ``system_dynamic`` needs (see :func:`prepare_system_dynamic`)."""

    fe: SystemFE
    analysis: SystemDynamicAnalysis
    start_fe: SystemFE  # the system of the static start: ``fe``, or with the fairleads where the motions start


def prepare_system_dynamic(case) -> SystemDynamicSetup:
    """Every check of a ``system_dynamic`` case that can be made before the time loop.

    The names in ``body_motions``, ``point_motions``, ``external_forces`` and ``failures``; the kinds they
    need (a prescribed body has a motion, a free body's force series covers the run); the network's
    geometry (:func:`seacable.mooring.checks.check_network`, through the model); motions bound over the run;
    and the run size (:func:`seacable._limits.check_run_size`).
    """
    a: SystemDynamicAnalysis = case.analysis
    system = _system_of(case)
    where = "analysis"
    for key, names, want in (("body_motions", a.body_motions, ("prescribed",)),
                             ("external_forces", a.external_forces, ("free",)),
                             ("release_offsets", a.release_offsets, ("free",))):
        for name in names:
            if name not in system.bodies:
                raise InputError(f"{where}.{key}: body '{name}' is not defined (bodies: "
                                 f"{', '.join(system.bodies) or 'none'}).{suggest(name, system.bodies)}")
            if system.bodies[name].kind not in want:
                raise InputError(f"{where}.{key}.{name}: body '{name}' is {system.bodies[name].kind}; {key} is for "
                                 f"{want[0]} bodies. Suggested fix: set 'kind: {want[0]}' on the body or drop the entry.")
    for name, body in system.bodies.items():
        if body.kind == "prescribed" and name not in a.body_motions:
            warnings.warn(f"body '{name}' is prescribed but {where}.body_motions has no motion for it: it is held "
                          "still. Suggested fix: add its motion, or make it 'fixed' (a MoorDyn deck: write it as a YAML case with "
                          "seacable.io.dump_case(case.system_case()) and add the motion there).", SeacableWarning,
                          stacklevel=2)
        if body.kind == "free" and body.mass <= 0:
            raise InputError(f"bodies.{name}.mass: a free body needs a mass > 0 kg for the dynamics, got "
                             f"{body.mass:g} kg. Suggested fix: give its mass in air.")
        if body.kind == "free":
            body.check_accelerable(name, _moment_sources(system, name, a))  # not a LinAlgError
    env = case.environment
    free = [n for n, b in system.bodies.items() if b.kind == "free"]
    if free and env.waves is not None:
        warnings.warn(f"the water's waves act on the lines only, not on the free bodies ({', '.join(free)}): their "
                      "wave loads are not modelled (the current acts on them through their quadratic damping). "
                      "Suggested fix: give the wave loads as analysis.external_forces (a time series).",
                      SeacableWarning, stacklevel=2)
    for name in a.point_motions:
        if name not in system.points:
            raise InputError(f"{where}.point_motions: point '{name}' is not defined (points: "
                             f"{', '.join(system.points)}).{suggest(name, system.points)}")
        if system.points[name].kind != "coupled":
            raise InputError(f"{where}.point_motions.{name}: point '{name}' is {system.points[name].kind}; only "
                             "coupled points follow a motion. Suggested fix: set 'kind: coupled'.")
    seen = set()
    for k, f in enumerate(a.failures):
        if f.line not in system.lines:
            raise InputError(f"{where}.failures[{k}].line: line '{f.line}' is not defined (lines: "
                             f"{', '.join(system.lines)}).{suggest(f.line, system.lines)}")
        if (f.line, f.end) in seen:
            raise InputError(f"{where}.failures[{k}]: line '{f.line}' end {f.end} fails twice. Suggested fix: give "
                             "one entry per line end (time and tension together if both).")
        seen.add((f.line, f.end))
    for name, ser in a.external_forces.items():
        t, _ = ser.table()
        if t[0] > 1e-9 or t[-1] < a.duration - 1e-9:
            raise InputError(f"{where}.external_forces.{name}: the series covers {t[0]:g} to {t[-1]:g} s, the run "
                             f"needs 0 to {a.duration:g} s. Suggested fix: extend the table.")
    for motion in a.body_motions.values():
        if isinstance(motion, RAOMotion):
            motion.table()   # the RAO file read and checked before the statics of a mean offset are solved
    a = _mean_offsets(case, system, a)
    fe = build_system_fe(system, case.environment, a)
    net = fe.model.network
    steps = a.duration / min(a.time_step, a.output_interval)
    outputs = a.duration / a.output_interval + 1
    check_run_size(f"system_dynamic case '{getattr(case, 'name', 'system')}'", steps=steps,
                   stored_values=outputs * (2 * 3 * net.n_nodes + net.n_elements + 12 * len(fe.free_bodies)),
                   fix="lengthen analysis.time_step or analysis.output_interval, or shorten analysis.duration")
    channels = _channels_fn(fe, a, a.duration)
    start_fe = fe
    if any(isinstance(m, RAOMotion) for m in a.body_motions.values()):
        # a platform's mean offset: the static start is solved where the motions put the fairleads at t = 0
        # (the run's motions move the nodes from where the case puts them)
        from ..mooring.run import at_motion_start

        start_fe = dataclasses.replace(fe, model=at_motion_start(fe.model, channels))
    if fe.model.water.sea is not None:
        if not lines_only(fe):
            raise InputError(f"environment.waves: an irregular sea (spectrum '{env.waves.spectrum}') loads the lines of "
                             "a system whose bodies and points all move as prescribed (or are fixed); this one has "
                             f"{_coupled_parts(fe)}. Suggested fix: make the bodies 'prescribed' (a 'rao' motion moves "
                             "one in the sea), drop the failures, or give regular waves (height, period).")
        t_out = np.linspace(0.0, a.duration, round(a.duration / a.output_interval) + 1)
        fe.model.check_sea(a.duration, np.concatenate((fe.model.network.position, channels(t_out)[0].reshape(-1, 3))))
    return SystemDynamicSetup(fe, a, start_fe)


def _mean_offsets(case, system: MooringSystem, a: SystemDynamicAnalysis) -> SystemDynamicAnalysis:
    """The analysis with each RAO motion's ``mean_offset: equilibrium`` resolved: the body's static equilibrium,
    free under its weight, buoyancy, hydrostatics, steady ``external_force`` and the lines of the run (the damaged
    system's when lines are left out), less its given position (:func:`seacable.system.statics.solve_equilibrium`)."""
    names = [n for n, m in a.body_motions.items() if isinstance(m, RAOMotion) and m.mean_offset == "equilibrium"]
    if not names:
        return a
    from ..errors import NoSolutionError
    from .statics import solve_equilibrium

    bodies = {n: b.model_copy(update={"kind": "free"}) if n in names else b for n, b in system.bodies.items()}
    where = f"analysis.body_motions ({', '.join(names)}: mean_offset 'equilibrium')"
    try:
        free = MooringSystem(points=system.points, bodies=bodies, lines=system.lines)
        eq = solve_equilibrium(free, case.environment)
    except (InputError, NoSolutionError, ConvergenceError) as err:
        raise InputError(f"{where}: the static equilibrium of the free body could not be found: {err} Suggested fix: "
                         "give the body's mass, volume, centres and waterplane (it floats), or the mean offset "
                         "itself.") from None
    motions = dict(a.body_motions)
    for n in names:
        pose = np.asarray(eq.body_position[eq.body_names.index(n)], float) - np.asarray(system.bodies[n].position)
        motions[n] = motions[n].model_copy(update={"mean_offset": tuple(float(v) for v in pose)})
    return a.model_copy(update={"body_motions": motions})


def most_loaded_at_start(case) -> str:
    """The line ``damaged_lines: most_loaded`` removes from a ``system_dynamic`` case: the line of the largest
    tension in the intact static equilibrium the run starts from (the bodies under their steady
    ``external_force``, a body of a ``rao`` motion with ``mean_offset: equilibrium`` free;
    :func:`seacable.system.statics.solve_equilibrium`, :mod:`seacable.system.damaged`)."""
    from ..errors import NoSolutionError
    from .statics import solve_equilibrium

    system = case.system()
    a = case.analysis
    names = [n for n, m in a.body_motions.items() if isinstance(m, RAOMotion) and m.mean_offset == "equilibrium"]
    bodies = {n: b.model_copy(update={"kind": "free"}) if n in names else b for n, b in system.bodies.items()}
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", SeacableWarning)  # the run itself warns of what the statics see
            eq = solve_equilibrium(MooringSystem(points=system.points, bodies=bodies, lines=system.lines),
                                   case.environment)
    except (InputError, NoSolutionError, ConvergenceError) as err:
        raise InputError(f"analysis.damaged_lines 'most_loaded': the intact static equilibrium that tells the most "
                         f"loaded line could not be found: {err} Suggested fix: name the line to remove "
                         "(damaged_lines: [NAME]).") from None
    lines = tuple(system.lines)
    return most_loaded_line(lines, line_tensions(eq, lines), "")


def lines_only(fe: SystemFE) -> bool:
    """True when the system's lines are all it solves for: no free bodies, no node tied to a body or a point
    (failing line ends are), no external force on a node. Such a run is the mooring model's
    (:func:`seacable.mooring.solver.simulate`: its compiled time loop, irregular seas)."""
    return not fe.free_bodies and len(fe.con_node) == 0 and not np.any(fe.node_fext)


def _coupled_parts(fe: SystemFE) -> str:
    parts = [f"free bodies ({', '.join(fe.free_bodies)})"] if fe.free_bodies else []
    if np.any(fe.con_line >= 0):
        parts.append("line failures")
    elif len(fe.con_node):
        parts.append("line ends tied to free points")
    if np.any(fe.node_fext):
        parts.append("points with external forces")
    return ", ".join(parts) or "nothing coupled"


def _padded(per_line, width, fill=np.nan, lead=()):
    """Stack per-line arrays (..., k_i) into (..., line, width), NaN padded (``lead`` + (0, width): no lines)."""
    if not per_line:
        return np.full(tuple(lead) + (0, width), fill)
    out = []
    for a in per_line:
        a = np.asarray(a, float)
        padw = [(0, 0)] * (a.ndim - 1) + [(0, width - a.shape[-1])]
        out.append(np.pad(a, padw, constant_values=fill))
    return np.stack(out, axis=-2)


def _anchor_vertical_force(fe: SystemFE, run: SystemRun) -> np.ndarray:
    """Vertical force of each line on its anchor end (the end away from the fairlead), (time, line), upward
    positive [N]: the end element's pull less the half element's weight in water, which the seabed carries at an
    end resting on it (:func:`seacable.mooring.run.grounded_end_force`, the single-line analyses' rule)."""
    net, water = fe.model.network, fe.model.water
    ramp = float(fe.model.env[K_BEDRAMP])
    out = np.zeros((len(run.time), len(fe.line_names)))
    for j, (nodes, els) in enumerate(zip(fe.line_nodes, fe.line_elements)):
        at_a = fe.fairlead_end[j] == 1
        a, b, e = (nodes[0], nodes[1], els[0]) if at_a else (nodes[-1], nodes[-2], els[-1])
        d = run.position[:, b] - run.position[:, a]
        pull = run.tension[:, e, None] * d / np.maximum(np.linalg.norm(d, axis=-1), 1e-300)[:, None]
        half = 0.5 * net.weight_per_length[e] * net.length[e]
        force = pull[:, 2] - half
        if water.depth is not None:
            grounded = height_above_seabed(water, run.position[:, a]) <= ramp
            force[grounded] = grounded_end_force(pull[grounded], half, water.slope)[:, 2]
        out[:, j] = force
    return out


def system_result(fe: SystemFE, run: SystemRun, *, case=None, settings=None):
    """The Dataset of a coupled run."""
    sysm = fe.system
    nl = len(fe.line_names)
    nmax = max((len(n) for n in fe.line_nodes), default=0)
    emax = max((len(e) for e in fe.line_elements), default=0)
    nt = len(run.time)
    data = {}
    for k, name in enumerate("xyz"):
        data[name] = var(("time", "line", "node"), _padded([run.position[:, nodes, k] for nodes in fe.line_nodes], nmax, lead=(nt,)),
                         "m", {"x": "x position", "y": "y position",
                               "z": "elevation (0 at the still water level)"}[name])
    data["segment_tension"] = var(("time", "line", "element"),
                                  _padded([run.tension[:, els] for els in fe.line_elements], emax, lead=(nt,)), "N",
                                  "element effective tension")
    end_t = np.stack([np.stack([run.tension[:, els[0]], run.tension[:, els[-1]]], axis=-1)
                      for els in fe.line_elements], axis=1) if nl else np.zeros((nt, 0, 2))  # (nt, line, 2)
    fair = fe.fairlead_end
    data["fairlead_tension"] = var(("time", "line"), end_t[:, np.arange(nl), fair], "N",
                                   "tension at the fairlead end of the line (its end element)")
    data["anchor_tension"] = var(("time", "line"), end_t[:, np.arange(nl), 1 - fair], "N",
                                 "tension at the anchor end of the line (its end element)")
    data["anchor_vertical_force"] = var(("time", "line"), _anchor_vertical_force(fe, run), "N",
                                        "vertical force of the line on its anchor, upward positive (its end element "
                                        "and half element's weight)")
    ft = np.full(nl, np.nan)
    for j, li in enumerate(fe.con_line):
        if li >= 0 and np.isfinite(run.failure_time[j]):
            ft[li] = np.nanmin([ft[li], run.failure_time[j]])
    data["failure_time"] = var("line", ft, "s", "time the line failed (NaN: intact)")
    mbl = [[seg.line_type.breaking_load for seg in sysm.lines[name].line.segments] for name in fe.line_names]
    data["breaking_load"] = var("line", np.array([min(m) if None not in m else np.nan for m in mbl], float), "N",
                                "minimum breaking load of the line (its weakest segment; NaN: not given)")
    bodies = list(sysm.bodies)
    bp = np.zeros((nt, len(bodies), 6))
    bv = np.zeros((nt, len(bodies), 6))
    bw = np.zeros((nt, len(bodies), 3))
    for k, name in enumerate(bodies):
        body = sysm.bodies[name]
        if name in fe.free_bodies:
            j = fe.free_bodies.index(name)
            bp[:, k], bv[:, k] = run.body_position[:, j], run.body_velocity[:, j]
            if run.body_angular_velocity is not None:
                bw[:, k] = run.body_angular_velocity[:, j]
        else:
            bp[:, k] = body.position
            mot = fe.body_motions.get(name) if body.kind == "prescribed" else None
            if mot is not None:
                d, dd, _ = mot.dofs(run.time)
                bp[:, k] += d
                bv[:, k] = dd
                for i in range(nt):  # the motion turns the body by R(d) from its given pose: w = E(d) d'
                    bw[i, k] = euler_rate_map(d[i, 3:]) @ dd[i, 3:]
    coords = {"time": var("time", run.time, "s", "time"),
              "line": var("line", list(fe.line_names), "1", "line"),
              "node": var("node", np.arange(nmax), "1", "node index along the line, 0 at end A"),
              "element": var("element", np.arange(emax), "1", "element index along the line, 0 at end A"),
              "s": var(("line", "node"), _padded([np.r_[0.0, np.cumsum(fe.model.network.length[e])]
                                                  for e in fe.line_elements], nmax), "m",
                       "unstretched arc length from end A")}
    if bodies:
        coords["body"] = var("body", bodies, "1", "body")
        coords["dof"] = var("dof", list(DOFS), "1", "degree of freedom: x, y, z [m], roll, pitch, yaw [rad]")
        data["body_position"] = var(("time", "body", "dof"), bp, "m or rad",
                                    "body reference point (x, y, z) [m] and rotation (roll, pitch, yaw) [rad]")
        data["body_velocity"] = var(("time", "body", "dof"), bv, "m/s or rad/s",
                                    "body velocity (x, y, z) [m/s] and rotation rates [rad/s]")
        coords["axis"] = var("axis", ["x", "y", "z"], "1", "global axis")
        data["body_angular_velocity"] = var(("time", "body", "axis"), bw, "rad/s",
                                            "body angular velocity, global axes")
    # the sea that drove the run: its surface at x = y = 0, as a mooring_dynamic result holds it
    data.update(elevation_variables(fe.model.water, run.time))
    title = getattr(case, "name", None) or "system_dynamic"
    ds = make_dataset(data, coords, analysis="system_dynamic", references=REFERENCES, title=title,
                      case=case if hasattr(case, "model_dump") else None,  # a case file's, as YAML (a deck: its file)
                      settings={"elements": int(fe.model.network.n_elements), "nodes": int(fe.model.network.n_nodes),
                                "time_step": run.time_step, "steps": run.steps, "newton_iterations": run.iterations,
                                **(settings or {})})
    ds.attrs["interrupted"] = int(run.interrupted)
    ds.attrs["wall_time"] = run.wall_time
    if fe.model.water.depth is not None:
        ds.attrs["depth"] = float(fe.model.water.depth)
    return ds


def start_state(fe: SystemFE, analysis: SystemDynamicAnalysis, environment=None) -> SystemState:
    """The static start of a run: the coupled equilibrium, or the lines' equilibrium with the free bodies held
    (at their given positions, or at the equilibrium plus ``release_offsets``).

    ``start: auto`` falls back, with a warning naming the residual, when the coupled static solve does
    not converge: the free bodies are held where the catenary statics
    (:func:`seacable.system.statics.solve_equilibrium`, given ``environment``) put them, so that the
    release at t = 0 starts near rest, or where the case puts them when that fails too.
    """
    held = analysis.start == "held"
    q = None
    try:
        st = static_system(fe, held=held, tol=analysis.tolerance)
    except ConvergenceError as err:
        if analysis.start != "auto" or not len(fe.free_bodies):
            raise
        where = "where the case puts them"
        if environment is not None:
            from ..errors import InputError, NoSolutionError
            from .statics import solve_equilibrium

            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", SeacableWarning)
                    eq = solve_equilibrium(fe.system, environment)
                q = np.array([eq.body_position[eq.body_names.index(name)] for name in fe.free_bodies], float)
                where = "at the catenary statics' equilibrium"
            except (InputError, NoSolutionError, ConvergenceError):
                q = None
        warnings.warn(f"system_dynamic: the finite-element static start did not converge ({err}); the free "
                      f"bodies {', '.join(fe.free_bodies)} start held {where} and are released at t = 0. "
                      "Suggested fix: none needed if the release transient is acceptable; otherwise place the "
                      "bodies nearer their equilibrium.", SeacableWarning, stacklevel=2)
        held = True
        st = static_system(fe, held=True, q=q, tol=analysis.tolerance)
    if held:
        st = dataclasses.replace(st, start="held")
    if not analysis.release_offsets:
        return st
    q = st.body_position.copy()
    for name, off in analysis.release_offsets.items():
        q[fe.free_bodies.index(name)] += np.asarray(off, float)
    return static_system(fe, held=True, q=q, X=st.position, tol=analysis.tolerance)


def run_system_dynamic(case, progress=None):
    """Time-domain response of a mooring system (analysis ``system_dynamic``) as a Dataset.

    ``case`` has ``environment``, ``analysis`` (a :class:`SystemDynamicAnalysis`) and a mooring system
    (``case.system()``, ``case.system``, or fields ``points``, ``bodies``, ``lines``).
    """
    setup = prepare_system_dynamic(case)
    a = setup.analysis
    fe = setup.fe
    start = start_state(setup.start_fe, a, case.environment)
    nd = a.numerical_damping
    # an irregular sea: the mooring model's loop (the coupled solver takes regular waves only)
    run = (_simulate_lines if fe.model.water.sea is not None else simulate_system)(
        fe, start, a.duration, a.time_step, a.output_interval, analysis=a, tol=min(a.tolerance * 10, 1e-4),
        max_iter=a.max_iterations, progress=progress, beta=(1 + nd) ** 2 / 4, gamma=0.5 + nd)
    removed = [n for n in getattr(case, "lines", None) or () if n not in fe.system.lines]
    return system_result(fe, run, case=case, settings={"damping_ratio": a.damping_ratio, "rayleigh": list(a.rayleigh),
                                                       "start": start.start, "damaged_lines": removed})

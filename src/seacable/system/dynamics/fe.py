"""The finite-element system of a mooring system's coupled dynamics: its lines' network, the bodies'
parameters and what ties nodes to bodies and points (:func:`build_system_fe`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ...bathymetry import cartesian_grid
from ...case import SeabedContact
from ...line import resolve_sections
from ...mooring.motion import rotation_matrix
from ...mooring.network import FIXED, FREE, PRESCRIBED, Network, catenary_positions, network_from_line
from ...mooring.outputs import water_of_environment
from ...mooring.solver import MooringModel, Water
from ...ties import Clamp, tie_points, ties_of
from ...wind import AIR_DENSITY
from ..case import SystemDynamicAnalysis
from ..hydro import area_tables
from ..model import MooringSystem
from . import body as DB


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
    # the bodies' radiation memory (Cummins): kernel (nb, n_k, 6, 6) sampled every ``memory_step`` [s], K(0) first and
    # the last sample halved (:func:`seacable.system.dynamics.kernel.coupled_steps`); n_k = 1 and zeros: none
    memory_kernel: np.ndarray = None
    memory_step: float = 0.0
    body_motions: dict = field(default_factory=dict)  # prescribed body -> its motion bound to the run (dofs(times))
    # the held line ends on free bodies (:func:`_turning_ends`): per row, the row of the model's hinge table, the free
    # body and the end's direction into the line in the body's axes (c, 5); (0, 5) when none
    clamps: np.ndarray = field(default_factory=lambda: np.zeros((0, 5)))
    # every held line end: (row of the hinge table, its point, its direction into the line in its body's axes or None
    # at a point not on a body), for the outputs' directions (:func:`seacable.system.bending.held_directions`)
    held: tuple = ()
    # per line, its ties to the seabed (:mod:`seacable.ties`) in the order of the line: ``(kind, j, node)`` with kind
    # "tether" or "clamp", j the node's index along the line and node its network node (:mod:`seacable.system.ties`)
    line_ties: tuple = ()

    def kernel_args(self):
        m = self.model
        net = m.network
        args = (net.elements, net.length, net.axial_stiffness, net.axial_damping, net.mass_per_length, net.diameter,
                net.cdn, net.cdt, net.can, net.cat, net.point_mass, net.point_added_mass, net.point_volume,
                net.point_hydrodynamics(), m.bedc, m.buoyancy, m.point_buoyancy, *m.tension_strain, m.hinges, m.hinge_ei,
                m.visco, self.clamps)
        return args

    def body_args(self):
        return (self.bpar, self.bkhs, self.badd, self.blin, self.bquad, self.ext_t, self.ext_f, self.ext_n)


def _rot(six) -> np.ndarray:
    return rotation_matrix(six[3], six[4], six[5])


def _water(environment, analysis: SystemDynamicAnalysis | None) -> Water:
    contact = analysis.seabed_contact if analysis is not None else SeabedContact()
    alpha = analysis.rayleigh[0] if analysis is not None else 0.0
    return water_of_environment(environment, contact, alpha)  # a plane or a grid: a system refuses a profile


def build_system_fe(system: MooringSystem, environment, analysis: SystemDynamicAnalysis | None = None, *,
                    n_elements: int | None = None) -> SystemFE:
    """The finite-element system of ``system`` in ``environment`` (nodes at the given positions, lines on
    their catenary start shapes). ``analysis`` gives the element count, damping, failures and external
    force series; ``n_elements`` overrides every line's element count."""
    rho, g = environment.water_density, environment.gravity
    depth = environment.depth
    slope = environment.seabed.slope
    # a seabed grid: each line's catenary start on the plane under its lower end along the line, lifted onto the grid
    grid = None if environment.seabed.grid is None else cartesian_grid(environment.seabed.grid)
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
    laws = []  # per element: its moment-curvature law or None (seacable.sections.element_moment_curvature)
    tethers, springs, line_ties = {}, {}, []  # node -> its tether's or spring clamp's row; per line its ties
    line_names = tuple(system.lines)
    for li, (lname, sl) in enumerate(system.lines.items()):
        ends = [sl.end_a, sl.end_b]
        xa, xb = pos[point_node[ends[0]]], pos[point_node[ends[1]]]
        ties = line_tie_points(lname, sl, system, environment, failures)
        sub = network_from_line(sl.line, xa, xb, water_density=rho, gravity=g,
                                n_elements=n_el if n_el is not None else sl.n_elements, damping_ratio=ratio,
                                stiffness_proportional=beta, end_b="free", ties=ties)
        s = sub.arc_length
        n = len(s)
        # start shape: the catenary, solved from the lower end up (of the line with its sections resolved: a
        # buoyancy section's segment and modules; a line without sections is its own)
        line = resolve_sections(sl.line, rho, g)
        buoyant = bool(sl.line.sections)
        lengths = np.array([seg.length for seg in line.segments])
        weights = np.array(line.weights(rho, g))
        ea = np.array([seg.line_type.effective_axial_stiffness() for seg in line.segments])
        dl, sl_ = (depth, slope) if grid is None else grid.plane_under(*((xa, xb) if xa[2] <= xb[2] else (xb, xa)))
        rigid = sorted(((tie.s, np.asarray(p, float)) for tie, p in ties
                        if isinstance(tie, Clamp) and tie.stiffness is None), key=lambda held: held[0])
        if rigid:  # held at its rigid clamps too: the catenary start of each piece between them (as a single line's)
            from ...mooring.run import _start_positions

            shape = _start_positions([(0.0, xa)] + rigid + [(float(s[-1]), xb)], s, lengths, weights, ea,
                                     line.point_loads(rho, g), depth=dl, slope=sl_, buoyant=buoyant)
            inner = sub.kind == FIXED
            shape[inner] = sub.position[inner]
        elif xa[2] <= xb[2]:
            shape = catenary_positions(xa, xb, s, lengths, weights, ea, point_loads=line.point_loads(rho, g),
                                       depth=dl, slope=sl_, buoyant=buoyant)
        else:
            L = s[-1]
            rev = [(L - ps, w) for ps, w in line.point_loads(rho, g)][::-1]
            shape = catenary_positions(xb, xa, L - s, lengths[::-1], weights[::-1], ea[::-1], point_loads=rev,
                                       depth=dl, slope=sl_, buoyant=buoyant)
        if grid is not None:
            shape = grid.lift(shape)
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
        kind.extend(np.where(sub.kind[1:-1] == FIXED, FIXED, FREE).tolist())  # a rigid clamp's node is held
        line_ties.append(_gather_ties(lname, sub, ids, tethers, springs))
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
        laws.extend(sub.element_moment_curvature or [None] * (n - 1))
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

    held = held_ends(system, failures)
    directions = _direction_channels(system, held, channel_source)

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
            element_viscoelastic=np.vstack(visco) if visco and np.any(np.vstack(visco)) else None,
        element_moment_curvature=tuple(laws) if any(law is not None for law in laws) else None,
        point_tether=_tie_table(tethers, nn, 6), point_clamp=_tie_table(springs, nn, 4))
    if held:
        net = net.replace(end_hinges=tuple(h[:5] for h in held))
    model = MooringModel(net, _water(environment, analysis))
    clamps = _turning_ends(system, model, held, bindex, directions)
    nb = len(free_bodies)
    tables = {name: area_tables(system.bodies[name]) for name in free_bodies}
    bpar = np.zeros((nb, DB.B_SIZE + max([t[2].size for t in tables.values()], default=0)))
    bkhs, badd, blin, bquad = (np.zeros((nb, 6, 6)) for _ in range(4))
    series = {}
    if a is not None:
        for name, ser in a.external_forces.items():
            series[name] = ser.table()
    memory = np.zeros((nb, 1, 6, 6))
    step = 0.0
    wind = getattr(environment, "wind", None)
    winds = {}  # body -> (times, the wind's velocity at its centre of pressure (nt, 2))
    if a is None:  # statics: the mean wind
        from ..hydro import body_wind_velocity

        for name in free_bodies:
            velocity = body_wind_velocity(system.bodies[name], wind)
            if velocity is not None:
                winds[name] = (np.zeros(1), velocity)
    elif any(system.bodies[n].hydrodynamics is not None or (wind is not None and system.bodies[n].wind)
             for n in free_bodies):
        # bodies with a database: their radiation memory at the run's step and their wave loads as force series;
        # bodies with wind areas: the wind's velocity series at their centre of pressure
        from ...mooring.motion import sea_of
        from ..hydro import body_wave_loads, body_wind_velocity, memory_kernels

        step = a.output_interval / max(1, math.ceil(a.output_interval / a.time_step - 1e-9))
        rho, g = model.water.density, model.water.gravity
        memory = memory_kernels(system, free_bodies, rho, g, step)
        times = step * np.arange(math.ceil(a.duration / step) + 2)
        for name in free_bodies:
            velocity = body_wind_velocity(system.bodies[name], wind, times)
            if velocity is not None:
                winds[name] = (times, velocity)
            loads = body_wave_loads(system.bodies[name], name, sea_of(model.water), rho, g, times)
            if loads is None:
                continue
            if name in series:  # the user's series on the same times, added
                t_u, f_u = series[name]
                loads = loads + np.stack([np.interp(times, t_u, f_u[:, k]) for k in range(6)], axis=1)
            series[name] = (times, loads)
    for name, (times, _) in winds.items():  # the wind's times carry the body's force series too
        if name not in series:
            series[name] = (times, np.zeros((times.size, 6)))
        elif series[name][0] is not times:
            t_u, f_u = series[name]
            series[name] = (times, np.stack([np.interp(times, t_u, f_u[:, k]) for k in range(6)], axis=1))
    nt = max([len(t) for t, _ in series.values()], default=1)
    ext_t, ext_f, ext_n = np.zeros((nb, nt)), np.zeros((nb, nt, 8)), np.zeros(nb, np.int64)
    for k, name in enumerate(free_bodies):
        b = system.bodies[name]
        bpar[k, DB.B_MASS], bpar[k, DB.B_VOL], bpar[k, DB.B_AWP] = b.mass, b.volume, b.waterplane_area
        bpar[k, DB.B_IXX], bpar[k, DB.B_IYY] = b.waterplane_moments
        bpar[k, DB.B_HASK] = 1.0 if b.hydrostatic_stiffness is not None else 0.0
        bpar[k, DB.B_CG:DB.B_CG + 3] = b.center_of_gravity
        bpar[k, DB.B_CB:DB.B_CB + 3] = b.center_of_buoyancy
        bpar[k, DB.B_INERT:DB.B_INERT + 3] = b.dynamic_inertia()  # a point mass's free spin: its own inertia
        bpar[k, DB.B_Q0:DB.B_Q0 + 6] = b.position
        bpar[k, DB.B_FEXT:DB.B_FEXT + 6] = b.external_force
        n_current, n_wind, rows = tables[name]
        bpar[k, DB.B_NCUR], bpar[k, DB.B_NWIND], bpar[k, DB.B_RHOAIR] = n_current, n_wind, AIR_DENSITY
        bpar[k, DB.B_TAB:DB.B_TAB + rows.size] = rows
        if n_wind and name not in winds:
            bpar[k, DB.B_NWIND] = 0.0  # no wind: its table idle
        bkhs[k], badd[k] = b.matrix("hydrostatic_stiffness"), b.matrix("added_mass")
        blin[k], bquad[k] = b.matrix("linear_damping"), b.matrix("quadratic_damping")
        if name in series:
            t, f = series[name]
            ext_t[k, :len(t)], ext_f[k, :len(t), :6], ext_n[k] = t, f, len(t)
        if name in winds:
            ext_f[k, :len(t), 6:] = winds[name][1]
    spin = np.zeros((nb, 3))
    cur_still = not np.any(model.cur_speed)
    for k, name in enumerate(free_bodies):
        arms = [c[2] for c in con if c[1] == k]
        if not np.any(clamps[:, 1] == k):  # a held line end turns with the body about any axis
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
        clamps=clamps, held=tuple((model.hinges.shape[0] - len(held) + k, h[5], h[6]) for k, h in enumerate(held)),
        bpar=bpar, bkhs=bkhs, badd=badd, blin=blin, bquad=bquad, ext_t=ext_t, ext_f=ext_f, ext_n=ext_n, spin=spin,
        memory_kernel=memory, memory_step=step, line_ties=tuple(line_ties))
    return fe


def line_tie_points(name: str, sl, system: MooringSystem, environment, failures=()) -> tuple:
    """The ties to the seabed of the system line ``name`` (:mod:`seacable.ties`), each ``(tie, point)`` with the
    point it holds to (x, y, z) [m] (:func:`seacable.ties.tie_points`), as
    :func:`seacable.mooring.network.network_from_line` takes them; () for a line without.

    Raises
    ------
    InputError
        A tie's point left on the seabed with no seabed, below the seabed or above the still water level; a tether
        at a line's end anywhere but at a free point (a fixed, coupled or body point holds the end already), or at
        an end that may fail (``failures``: {(line, "a" or "b"): ...}).
    """
    from ...errors import InputError

    found = ties_of(sl.line)
    if not found:
        return ()
    try:
        points = tie_points(sl.line, environment, f"lines.{name}")
    except ValueError as err:
        raise InputError(str(err)) from None
    total = float(sl.line.length)
    for i, tie in found:
        if not (tie.s <= 1e-9 * total or tie.s >= total * (1 - 1e-9)):
            continue
        end = 0 if tie.s <= 1e-9 * total else 1
        key = ("end_a", "end_b")[end]
        pname = getattr(sl, key)
        kind = system.points[pname].kind
        if kind != "free":
            raise InputError(
                f"lines.{name}.sections[{i}] ({tie.type}) is at s = {tie.s:g} m, the line's {key} at point '{pname}', "
                f"which is a {kind} point: a tether at a line's end is taken only at a free point (a buoy where "
                "lines meet). Suggested fix: tether a node inside the line (s between 0 and "
                f"{total:g} m), or run the tether as a line of its own from a fixed point to '{pname}'.")
        if (name, "ab"[end]) in failures:
            raise InputError(
                f"lines.{name}.sections[{i}] ({tie.type}) is at the line's {key}, which analysis.failures releases: "
                "a tethered end that fails is not modelled. Suggested fix: tether a node inside the line, or leave "
                "the failure out.")
    return tuple((tie, points[i]) for i, tie in found)


def _gather_ties(name: str, sub, ids, tethers: dict, springs: dict) -> tuple:
    """The ties of one line's network ``sub`` (its tethers' and spring clamps' rows, its rigid clamps' held inner
    nodes) moved to the system's nodes ``ids``: rows into ``tethers`` and ``springs`` ({node: row}); returns the
    line's ``(kind, j, node)`` in the order of the line (:attr:`SystemFE.line_ties`).

    Raises InputError for two tethers on one point's node (two lines tethered at the free point they share)."""
    from ...errors import InputError

    out = []
    for j in range(len(ids)):
        node = int(ids[j])
        if 0 < j < len(ids) - 1 and sub.kind[j] == FIXED:
            out.append(("clamp", j, node))
        for table, rows, kind in ((sub.point_tether, tethers, "tether"), (sub.point_clamp, springs, "clamp")):
            if table is None or not table[j, -2 if kind == "tether" else 3] > 0:
                continue
            if node in rows:
                raise InputError(
                    f"lines.{name}: its {kind} at its end is at a free point another line is tethered at already; a "
                    f"node takes one {kind}. Suggested fix: give one {kind} there, its axial stiffness the combined "
                    "one, or tether a node inside one of the lines.")
            rows[node] = table[j]
            out.append((kind, j, node))
    return tuple(out)


def _tie_table(rows: dict, n: int, width: int):
    """The network's ``point_tether`` or ``point_clamp`` (n, width) of the rows {node: row}; None without any."""
    if not rows:
        return None
    out = np.zeros((n, width))
    for node, row in rows.items():
        out[node] = row
    return out


def held_ends(system: MooringSystem, failures=()) -> list:
    """The held line ends of ``system`` (clamped or through a rotational spring), each ``(line index, end, kind,
    stiffness, direction, point, body_direction)``: the first five the network's ``end_hinges`` entry
    (:meth:`seacable.system.model.SystemLine.end_hinges`) with the direction in global axes, the point's name, and
    for a point on a body the direction into the line (from the end towards the line's inside) in the body's axes
    (None otherwise). A body's direction is turned by the body's given pose here; the statics and dynamics turn it
    with the body.

    Raises
    ------
    InputError
        A held end at a free point (it has no rotation to take the moment), or at an end that may fail.
    """
    from ...errors import InputError

    out = []
    for li, (lname, sl) in enumerate(system.lines.items()):
        for entry in sl.end_hinges(li):
            end = entry[1]
            key = ("end_a", "end_b")[end]
            pname = getattr(sl, key)
            p = system.points[pname]
            cond = getattr(sl, f"{key}_condition")
            if p.kind == "free":
                raise InputError(
                    f"lines.{lname}.{key}_condition is {cond.type}, but its point '{pname}' is a free point, which has "
                    "no rotation of its own: nothing would take the end's moment. Suggested fix: hold the end at a "
                    "fixed or coupled point or at a point on a body, or leave it pinned.")
            if (lname, "ab"[end]) in failures:
                raise InputError(
                    f"lines.{lname}.{key}_condition is {cond.type}, and analysis.failures releases that end: a held end "
                    "that fails is not modelled. Suggested fix: leave the end pinned, or the failure out.")
            d = np.asarray(entry[4], float)
            into = d if end == 0 else -d  # from the end into the line
            body = None
            if p.kind == "body":
                body = into
                d = _rot(system.bodies[p.body].position) @ d
            out.append((li, end, entry[2], entry[3], d, pname, body))
    return out


def _direction_channels(system: MooringSystem, held, channel_source) -> dict:
    """The motion channels of the held ends on prescribed bodies' points (added to ``channel_source``): a point
    one metre from the end into the line, moved by the body's rigid motion with the end
    (:func:`seacable.mooring.kernel.turn_held_ends`). Returns {index in ``held``: its channel}."""
    out = {}
    for k, (_, _, _, _, _, pname, into) in enumerate(held):
        p = system.points[pname]
        if into is None or system.bodies[p.body].kind != "prescribed":
            continue
        body = system.bodies[p.body]
        arm = np.asarray(p.position, float) + into
        out[k] = len(channel_source)
        channel_source.append(("body", p.body, arm, np.asarray(body.position[:3]) + _rot(body.position) @ arm))
    return out


def _turning_ends(system: MooringSystem, model: MooringModel, held, bindex: dict, directions: dict) -> np.ndarray:
    """The held ends that turn with their body: those on prescribed bodies take their direction from their
    channels (``hinge_ei`` columns H_DCH, H_ECH, in place), those on free bodies are returned as the rows of
    :attr:`SystemFE.clamps` (hinge row, free body, direction into the line in body axes); those on fixed bodies
    keep the direction of the body's given pose."""
    from ...mooring.kernel import H_DCH, H_ECH

    first = model.hinges.shape[0] - len(held)  # the end hinges follow the inner ones, in their order
    rows = []
    for k, (_, _, _, _, _, pname, into) in enumerate(held):
        h = first + k
        if k in directions:
            end = int(model.hinges[h, 1])
            model.hinge_ei[h, H_DCH], model.hinge_ei[h, H_ECH] = directions[k], model.network.channel[end]
        elif into is not None and system.points[pname].body in bindex:
            rows.append((h, bindex[system.points[pname].body], *into))
    return np.array(rows, float).reshape(-1, 5)


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


def lines_only(fe: SystemFE) -> bool:
    """True when the system's lines are all it solves for: no free bodies, no node tied to a body or a point
    (failing line ends are), no external force on a node. Such a run is the mooring model's
    (:func:`seacable.mooring.solver.simulate`: its compiled time loop, irregular seas)."""
    return not fe.free_bodies and len(fe.con_node) == 0 and not np.any(fe.node_fext)

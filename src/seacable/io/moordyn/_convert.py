"""A MoorDyn deck as a :class:`~seacable.system.model.MooringSystem` and its environment
(:func:`moordyn_system`)."""

from __future__ import annotations

import math
import warnings

import numpy as np
from pydantic import ValidationError

from ..._model import format_validation_error
from ...errors import InputError, SeacableWarning
from . import _cabledyn
from ._records import MoorDynInput, MoorDynRod, MoorDynRodType


def _rotation(roll, pitch, yaw) -> np.ndarray:
    """``Rz(yaw) Ry(pitch) Rx(roll)`` (the system model's convention, MoorDyn's and MoorPy's)."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw),
                              math.sin(yaw))
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1.0]])
    ry = np.array([[cp, 0, sp], [0, 1.0, 0], [-sp, 0, cp]])
    rx = np.array([[1.0, 0, 0], [0, cr, -sr], [0, sr, cr]])
    return rz @ ry @ rx


class _Rigid:
    """Mass, inertia, buoyancy, waterplane and hydrodynamics gathered on one rigid body, in body axes."""

    def __init__(self):
        self.mass, self.first = 0.0, np.zeros(3)  # sum m, sum m r
        self.inertia = np.zeros((3, 3))  # about the reference point, body axes
        self.volume, self.vfirst = 0.0, np.zeros(3)
        self.awp, self.iwp = 0.0, np.zeros(2)
        self.added = np.zeros((6, 6))  # about the reference point, body axes
        self.drag = np.zeros(3)  # translational, body axes

    def add_mass(self, m, c, inertia_cg):
        c = np.asarray(c, float)
        self.mass += m
        self.first += m * c
        self.inertia += np.asarray(inertia_cg, float) + m * (c @ c * np.eye(3) - np.outer(c, c))

    def add_volume(self, v, c):
        self.volume += v
        self.vfirst += v * np.asarray(c, float)

    def cg(self):
        return self.first / self.mass if self.mass > 0 else np.zeros(3)

    def cb(self):
        return self.vfirst / self.volume if self.volume > 0 else np.zeros(3)

    def inertia_cg(self):
        c = self.cg()
        return self.inertia - self.mass * (c @ c * np.eye(3) - np.outer(c, c))


def _added_about_reference(a3, r) -> np.ndarray:
    """6x6 added mass about the reference point of a 3x3 added mass ``a3`` at ``r`` (body axes)."""
    S = np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])
    return np.block([[a3, -a3 @ S], [S @ a3, -S @ a3 @ S]])


def _add_rod(rigid: _Rigid, rod: MoorDynRod, rt: MoorDynRodType, a_body, b_body, ref, R, rho):
    """Add a rod with ends ``a_body``/``b_body`` (body axes) to a body at global ``ref`` with rotation ``R``.

    Mass ``m L`` at the middle, a slender cylinder's inertia; the displaced volume of the part below
    z = 0 at this pose, at its centroid (MoorDyn's rods are buoyant over their submerged length);
    a rod piercing the surface adds its cross-section ``pi d^2 / 4 / |cos(tilt)|`` to the waterplane
    and its second moments. Added mass ``Ca rho A`` per metre normal to the rod (and the end term
    ``CaEnd rho pi d^3 / 12`` along its axis, at the middle of the submerged part) is integrated
    along the submerged part into the 6x6 added mass about the reference point (a point ``r`` of
    the rod moves at ``v + w x r``, so its added mass ``a`` adds ``[[a, -a S], [S a, -S a S]]``,
    ``S = skew(r)``); drag ``rho Cd d L / 2`` normal to it goes onto the translations (``CdEnd``
    along the axis).
    """
    a, b = np.asarray(a_body, float), np.asarray(b_body, float)
    length = float(np.linalg.norm(b - a))
    u = (b - a) / length if length > 0 else np.array([0.0, 0.0, 1.0])
    area = math.pi * rt.diameter**2 / 4
    m = rt.mass_per_length * length
    i_ax, i_n = m * rt.diameter**2 / 8, m * (length**2 / 12 + rt.diameter**2 / 16)
    rigid.add_mass(m, (a + b) / 2, i_n * np.eye(3) + (i_ax - i_n) * np.outer(u, u))
    ga, gb = ref + R @ a, ref + R @ b
    za, zb = ga[2], gb[2]
    if za <= 0 and zb <= 0:
        frac_lo, frac_hi = 0.0, 1.0
    elif za > 0 and zb > 0:
        frac_lo = frac_hi = 0.0
    else:  # pierces the surface
        f = za / (za - zb)
        frac_lo, frac_hi = (f, 1.0) if za > 0 else (0.0, f)
        cos_tilt = abs((gb - ga)[2]) / length
        awp = area / max(cos_tilt, 1e-6)
        cut = a + f * (b - a)
        rigid.awp += awp
        rigid.iwp += awp * np.array([cut[1] ** 2, cut[0] ** 2]) + math.pi * rt.diameter**4 / 64
    sub = (frac_hi - frac_lo) * length
    if sub > 0:
        rigid.add_volume(area * sub, a + (frac_lo + frac_hi) / 2 * (b - a))
        normal = np.eye(3) - np.outer(u, u)
        per_length = rt.added_mass_normal * rho * area * normal
        # 3-point Gauss-Legendre along the submerged part: exact for the quadratic -S a S
        for x, wt in zip((-math.sqrt(0.6), 0.0, math.sqrt(0.6)), (5 / 9, 8 / 9, 5 / 9)):
            frac = frac_lo + (frac_hi - frac_lo) * (1 + x) / 2
            rigid.added += _added_about_reference(per_length * sub * wt / 2, a + frac * (b - a))
        end = rt.added_mass_end * rho * (math.pi * rt.diameter**3 / 12) * np.outer(u, u)
        rigid.added += _added_about_reference(end, a + (frac_lo + frac_hi) / 2 * (b - a))
        rigid.drag += np.diag(0.5 * rho * rt.drag_normal * rt.diameter * sub * normal) + \
            0.5 * rho * rt.drag_end * area * u**2


def _turbine_pose(label, n, value) -> tuple[float, ...]:
    """A ``turbine_positions`` entry as six floats (x, y, z [m], roll, pitch, yaw [rad])."""
    v = np.asarray(value, float).ravel()
    if v.size not in (3, 6) or not np.all(np.isfinite(v)):
        raise InputError(f"{label}: turbine_positions[{n}] must be (x, y, z) [m] or (x, y, z, roll, pitch, yaw) "
                         f"[m, rad], got {value!r}. Suggested fix: give the platform reference point of turbine {n} "
                         "(FAST.Farm's WT_X, WT_Y, WT_Z plus ElastoDyn's PtfmSurge, PtfmSway, PtfmHeave).")
    return tuple(float(x) for x in np.r_[v, np.zeros(6 - v.size)])


def _turbine_shift(label, poses, n) -> tuple[float, float, float]:
    """The translation of turbine ``n`` for a body or rod on it (refused if the turbine is rotated)."""
    pose = poses.get(n, (0.0,) * 6)
    if any(pose[3:]):
        raise InputError(f"{label}: a body or rod is on turbine {n}, whose turbine_positions entry rotates it "
                         f"({pose[3:]} rad); seacable moves bodies and rods on a turbine by its position only. "
                         f"Suggested fix: give turbine_positions[{n}] as (x, y, z).")
    return pose[:3]


def moordyn_system(md: MoorDynInput, *, turbine_positions: dict | None = None):
    """The deck as a :class:`~seacable.system.model.MooringSystem` and its :class:`~seacable.environment.Environment`.

    Mapping (names: ``point<ID>``, ``body<ID>``, ``rod<ID>``, ``turbine<N>``, ``line<ID>``):

    - points: Fixed -> ``fixed``; Free/Connect -> ``free`` (mass, volume, C_D A, added mass
      ``Ca rho V``); Vessel/Coupled -> ``coupled``; BodyN -> on ``body<N>`` (its mass and volume
      lumped into the body's, as MoorDyn); TurbineN -> on the
      prescribed body ``turbine<N>`` (FAST.Farm places turbine N; the deck does not say where:
      ``turbine_positions`` ``{N: (x, y, z)}`` or ``{N: (x, y, z, roll, pitch, yaw)}`` [m, rad], the
      platform reference point of turbine N: FAST.Farm's ``WT_X, WT_Y, WT_Z`` plus ElastoDyn's
      initial platform displacements; default the origin, with a SeacableWarning). Bodies and rods
      on a turbine are moved with its position (a rotated turbine carries points only).
    - bodies: free/fixed/coupled -> ``free``/``fixed``/``prescribed`` (CoupledPinned: prescribed
      and ``pinned``). Mass, centre of gravity and inertia as written; MoorDyn's body volume acts
      at the body's centre of gravity (MoorDyn v2's ``Body::doRHS`` puts ``(V rho - M) g`` there) and
      bodies have no waterplane (buoyancy only). ``Ca rho V`` on the
      translations of ``added_mass``; ``rho CdA / 2`` on the diagonal of ``quadratic_damping``.
    - rods: a rod on body N (``BodyN``, and ``BodyNPinned``, taken as rigidly fixed there: the
      data model has no joint on a moving body, a SeacableWarning says so) adds its mass,
      inertia, submerged volume, waterplane and hydrodynamics to ``body<N>``; any other rod
      becomes its own body ``rod<ID>`` (Fixed -> fixed, Coupled -> prescribed, Free -> free,
      Pinned -> free and ``pinned``, CoupledPinned -> prescribed and ``pinned``) with its body
      z axis along the rod from end A (its reference point) to end B. Rod ends a line attaches
      to (``R1A``) become points ``rod<ID>_a``/``rod<ID>_b`` on that body. Buoyancy is the
      submerged part at the deck's pose, a surface-piercing rod adds a waterplane.
    - line types: d, m, EA, EI, Cd, Ca, CdAx, CaAx; a nonlinear EA table goes to
      ``LineType.tension_strain`` (``axial_stiffness`` is its secant at the table's end; the
      statics of :mod:`seacable.system.statics` use that constant EA, a SeacableWarning says so);
      a viscoelastic ``EA_s|EA_d`` to ``axial_stiffness = EA_s`` and ``dynamic_axial_stiffness``.
      The axial damping BA is not in the data model (a dynamics setting).
    - environment (a :class:`~seacable.environment.SystemEnvironment`): WtrDnsty, g, WtrDpth (or
      the deepest point, as MoorDyn), FrictionCoefficient. ``g = 0`` (no weight nor buoyancy) and
      ``WtrDnsty = 0`` (no buoyancy nor hydrodynamics) are kept: MoorDyn's own tests switch gravity
      or buoyancy off so. MoorDyn's soft seabed (kBot) becomes a rigid one.
    - a deck without lines (rods or bodies alone), or with bodies no line ends on, is a system all
      the same (the dynamics run it; the statics need each free body restored).
    - ``FAILURE`` rows stay in ``md.failures`` (a dynamics input).

    Raises
    ------
    InputError
        A deck the data model refuses (a line end on a point that does not exist, ...).
    """
    from ...environment import Seabed, SystemEnvironment
    from ...line import Line, LineType, PointMass, Segment
    from ...system.model import Body, MooringSystem, SystemLine, SystemPoint

    label = md.path or "MoorDyn file"
    rho, g = md.water_density, md.gravity
    turbine_positions = {int(n): _turbine_pose(label, n, v) for n, v in (turbine_positions or {}).items()}
    unplaced: list[int] = []
    bodies_in = {b.id: b for b in md.bodies}
    rods_in = {r.id: r for r in md.rods}
    rigid: dict[str, _Rigid] = {}
    spec: dict[str, dict] = {}
    points: dict[str, SystemPoint] = {}

    def turbine(n):
        name = f"turbine{n}"
        if name not in spec:
            if n not in turbine_positions:
                unplaced.append(n)
            spec[name] = dict(kind="prescribed", position=turbine_positions.get(n, (0.0,) * 6), pinned=False)
            rigid[name] = _Rigid()
        return name

    for b in md.bodies:
        name = f"body{b.id}"
        kind = {"free": "free", "fixed": "fixed", "coupled": "prescribed", "turbine": "prescribed"}[b.attachment]
        position = b.position
        if b.attachment == "turbine":
            tx, ty, tz = _turbine_shift(label, turbine_positions, b.turbine)
            position = (b.position[0] + tx, b.position[1] + ty, b.position[2] + tz, *b.position[3:])
        spec[name] = dict(kind=kind, position=position, pinned=b.pinned, drag=b.drag_area, ca=b.added_mass_coefficient,
                          volume=b.volume)
        r = _Rigid()
        r.add_mass(b.mass, b.center_of_gravity, np.diag(b.inertia))
        # MoorDyn v2 (Body::doRHS): the body's own weight and buoyancy, (V rho - M) g, act together at its CG
        r.add_volume(b.volume, b.center_of_gravity)
        rigid[name] = r

    rod_end_points: dict[tuple[int, str], str] = {}
    pinned_on_body = []
    for rod in md.rods:
        rt = md.rod_types[rod.rod_type]
        if rod.attachment == "body":
            host = f"body{rod.body}"
            b = bodies_in[rod.body]
            ref, R = np.asarray(spec[host]["position"][:3]), _rotation(*spec[host]["position"][3:])
            _add_rod(rigid[host], rod, rt, rod.end_a, rod.end_b, ref, R, rho)
            if rod.pinned:
                pinned_on_body.append(rod.id)
            for side, end in (("A", rod.end_a), ("B", rod.end_b)):
                rod_end_points[(rod.id, side)] = (host, end)
            del b
            continue
        name = f"rod{rod.id}"
        a, bvec = np.asarray(rod.end_a, float), np.asarray(rod.end_b, float)
        if rod.attachment == "turbine":
            a = a + np.asarray(_turbine_shift(label, turbine_positions, rod.turbine))
            bvec = bvec + np.asarray(_turbine_shift(label, turbine_positions, rod.turbine))
            turbine(rod.turbine)
        axis = bvec - a
        length = float(np.linalg.norm(axis))
        u = axis / length if length > 0 else np.array([0.0, 0.0, 1.0])
        pitch, yaw = math.acos(max(-1.0, min(1.0, u[2]))), math.atan2(u[1], u[0])
        kind = {"free": "free", "fixed": "fixed", "coupled": "prescribed", "turbine": "prescribed"}[rod.attachment]
        spec[name] = dict(kind=kind, position=(*a, 0.0, pitch, yaw), pinned=rod.pinned)
        r = _Rigid()
        _add_rod(r, rod, rt, (0.0, 0.0, 0.0), (0.0, 0.0, length), a, _rotation(0.0, pitch, yaw), rho)
        rigid[name] = r
        rod_end_points[(rod.id, "A")] = (name, (0.0, 0.0, 0.0))
        rod_end_points[(rod.id, "B")] = (name, (0.0, 0.0, length))
    for p in md.points:
        if p.attachment == "turbine":
            turbine(p.turbine)
    if unplaced:
        ns = ", ".join(map(str, sorted(unplaced)))
        warnings.warn(f"{label}: points or rods are on turbine(s) {ns} (FAST.Farm's TurbineN), whose positions are "
                      "set in the FAST.Farm input, not in this deck; seacable puts their reference points at the "
                      f"origin. Suggested fix: give turbine_positions={{{sorted(unplaced)[0]}: (x, y, z), ...}}.",
                      SeacableWarning, stacklevel=2)
    free_pinned = sorted(n for n, sp in spec.items() if sp["pinned"] and sp["kind"] == "free")
    if free_pinned:
        warnings.warn(f"{label}: {', '.join(free_pinned)} pinned (MoorDyn Pinned: end A held, rotation free) is "
                      "recorded as Body.pinned; an analysis that does not hold a pinned body's reference point "
                      "treats it as free.", SeacableWarning, stacklevel=2)
    if pinned_on_body:
        warnings.warn(f"{label}: rod(s) {', '.join(map(str, pinned_on_body))} are pinned to a body (BodyNPinned); "
                      "seacable's system model has no joint on a moving body and fixes them rigidly to it (their "
                      "own rotation is not free).", SeacableWarning, stacklevel=2)

    for p in md.points:
        common = dict(mass=p.mass, volume=p.volume, drag_area=p.drag_area,
                      added_mass=p.added_mass_coefficient * rho * p.volume)
        if p.attachment == "body":
            # MoorDyn lumps a point's mass and volume into the body it is on: so does the conversion (the
            # body's mass, centre of gravity, inertia and buoyancy; the dynamics need the body's own mass)
            rigid[f"body{p.body}"].add_mass(p.mass, p.position, np.zeros((3, 3)))
            rigid[f"body{p.body}"].add_volume(p.volume, p.position)
            common.update(mass=0.0, volume=0.0)
            points[f"point{p.id}"] = SystemPoint(kind="body", body=f"body{p.body}", position=p.position, **common)
        elif p.attachment == "turbine":
            points[f"point{p.id}"] = SystemPoint(kind="body", body=turbine(p.turbine), position=p.position, **common)
        else:
            kind = {"fixed": "fixed", "free": "free", "vessel": "coupled"}[p.attachment]
            points[f"point{p.id}"] = SystemPoint(kind=kind, position=p.position, **common)

    def end(point_id, rod_end):
        if rod_end is None:
            return f"point{point_id}"
        name = f"rod{rod_end[0]}_{rod_end[1].lower()}"
        if name not in points:
            host, where = rod_end_points[rod_end]
            points[name] = SystemPoint(kind="body", body=host, position=tuple(float(v) for v in where))
        return name

    types, tabled = {}, []
    for lt in md.line_types.values():
        dynamic = None
        if lt.dynamic_stiffness is not None:
            dynamic = (lt.dynamic_stiffness[0], lt.dynamic_stiffness[1] if len(lt.dynamic_stiffness) > 1 else 0.0)
        if lt.syrope is not None:
            tabled.append(lt.name)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", SeacableWarning)  # MoorDyn's own Cd values, e.g. chain 2.4+
            types[lt.name] = LineType(
                name=lt.name, diameter=lt.diameter, mass_per_length=lt.mass_per_length,
                axial_stiffness=lt.axial_stiffness, bending_stiffness=lt.bending_stiffness,
                drag_normal=lt.drag_normal, drag_tangential=lt.drag_tangential,
                added_mass_normal=lt.added_mass_normal, added_mass_tangential=lt.added_mass_tangential,
                tension_strain=lt.tension_strain, dynamic_axial_stiffness=dynamic,
                dynamic_axial_damping=lt.dynamic_damping)
    if tabled:
        warnings.warn(f"{label}: Syrope line type(s) {', '.join(tabled)}: the statics (system_static) use the "
                      "original working curve as the rope's strain-tension table; the working curves after a load "
                      "history (SYROPE IC) are followed only when the deck, having no bodies or rods, runs as a "
                      "line network (its time-domain run).",
                      SeacableWarning, stacklevel=2)
    lines = {}
    for ln in md.lines:
        # a CableDyn line of SECTIONS: its segments, each with its element count
        line = (Line(segments=tuple(Segment(line_type=types[name], length=length, n_elements=k)
                                    for name, length, k in ln.sections)) if ln.sections
                else Line.single(types[ln.line_type], ln.length))
        if ln.attachments:  # CableDyn's ATTACHMENTS
            line = line.model_copy(update={"attachments": tuple(sorted(
                (PointMass(s=s, mass=m, volume=v, drag_area=cda, axial_drag_area=cdax,
                           added_mass=ca * md.water_density * v, kind="float") for s, m, v, cda, ca, cdax in
                 ln.attachments), key=lambda a: a.s))})
        lines[f"line{ln.id}"] = SystemLine(line=line, end_a=end(ln.point_a, ln.rod_a), end_b=end(ln.point_b, ln.rod_b),
                                           n_elements=ln.n_segments)

    body_force = {name: np.zeros(6) for name in spec}
    body_lin = {name: np.zeros(6) for name in spec}
    body_quad = {name: np.zeros(6) for name in spec}
    for load in md.external_loads:
        if load.kind == "point":
            name = f"point{load.target}"
            p = points[name]
            points[name] = p.model_copy(update={"external_force": tuple(np.add(p.external_force, load.force))})
            if any(load.linear_damping) or any(load.quadratic_damping):
                warnings.warn(f"{label}: external load {load.id} damps point {load.target}; the system model has no "
                              "damping on points (it is left out).", SeacableWarning, stacklevel=2)
            continue
        name = f"body{load.target}" if load.kind == "body" else f"rod{load.target}"
        if name not in spec:  # a rod merged into its body
            name = f"body{rods_in[load.target].body}"
        R = _rotation(*spec[name]["position"][3:])
        force = np.asarray(load.force, float)
        if load.frame == "L":  # body axes at the deck's pose; the system model's force is global
            force = R @ force
            warnings.warn(f"{label}: external load {load.id} on {name} is in body axes (CSys L); seacable applies it "
                          "as the constant global force it is at the deck's pose.", SeacableWarning, stacklevel=2)
        body_force[name][:3] += force
        lin, quad = load.linear_damping, load.quadratic_damping
        if len(lin) == 2:  # a rod: transverse and axial, along its axis (body z for a rod body)
            lin, quad = (lin[0], lin[0], lin[1]), (quad[0], quad[0], quad[1])
        body_lin[name][:3] += lin
        body_quad[name][:3] += quad

    bodies = {}
    for name, s in spec.items():
        r = rigid[name]
        drag = body_quad[name].copy()
        added = r.added.copy()
        if "drag" in s:
            drag += 0.5 * rho * np.asarray(s["drag"])
            # MoorDyn: the body's Ca acts on its own volume (its rods carry their own added mass)
            added[:3, :3] += np.diag(np.broadcast_to(np.asarray(s["ca"], float) * rho * s["volume"], 3))
        drag[:3] += r.drag
        inertia = r.inertia_cg()
        bodies[name] = Body(
            kind=s["kind"], position=tuple(float(v) for v in s["position"]), mass=r.mass,
            center_of_gravity=tuple(float(v) for v in r.cg()),
            inertia=tuple(float(max(v, 0.0)) for v in np.diag(inertia)), volume=r.volume,
            center_of_buoyancy=tuple(float(v) for v in r.cb()), waterplane_area=r.awp,
            waterplane_moments=tuple(float(v) for v in r.iwp),
            added_mass=tuple(tuple(float(v) for v in row) for row in added) if added.any() else None,
            quadratic_damping=tuple(tuple(float(v) for v in row) for row in np.diag(drag)) if drag.any() else None,
            linear_damping=(tuple(tuple(float(v) for v in row) for row in np.diag(body_lin[name]))
                            if body_lin[name].any() else None),
            external_force=tuple(float(v) for v in body_force[name]), pinned=s["pinned"])
    for (lid, end_index), (kind, stiffness, direction) in getattr(md, "end_connections", {}).items():
        # CableDyn's END CONNECTIONS held in bending: its global direction, in the body's axes at its given pose for
        # an end on a body
        name = f"line{lid}"
        key = ("end_a", "end_b")[end_index]
        point = points[getattr(lines[name], key)]
        rotation = (_rotation(*bodies[point.body].position[3:]) if point.kind == "body" and point.body in bodies
                    else None)
        try:
            condition = _cabledyn.end_condition(kind, stiffness, direction, rotation)
            lines[name] = lines[name].model_copy(update={f"{key}_condition": condition})
            SystemLine.model_validate(lines[name].model_dump())  # its checks (EI at the end)
        except (ValidationError, ValueError) as exc:
            raise InputError(f"{label}: END CONNECTIONS line {lid} End {'AB'[end_index]}: "
                             f"{format_validation_error(exc) if isinstance(exc, ValidationError) else exc}") from None
    try:
        system = MooringSystem(points=points, bodies=bodies, lines=lines)
    except ValidationError as exc:  # say which deck
        raise InputError(f"{label}: the deck does not make a seacable mooring system: "
                         f"{format_validation_error(exc)}") from None
    except InputError as exc:
        raise InputError(f"{label}: the deck does not make a seacable mooring system: {exc}") from None
    env = SystemEnvironment(water_density=rho, gravity=g, depth=md.water_depth, seabed=Seabed(friction=md.friction))
    return system, env

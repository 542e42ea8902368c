"""Reference systems for the statics' validation and benchmark, and their MoorPy twins.

* :func:`oc3_hywind`: the OC3-Hywind spar and its three catenary lines (Jonkman 2010,
  NREL/TP-500-47535, tables 5-1 and 6-1; the delta connection replaced by single lines as in
  the report's linearised stiffness), depth 320 m.
* :func:`oc4_semi`: the OC4-DeepCwind semi-submersible and its three lines (Robertson et al.
  2014, NREL/TP-5000-60601, tables 3-1 and 3-6), depth 200 m.
* :func:`moored_buoy`: a surface buoy on three two-segment lines with clump weights, sub-surface
  floats and one free junction point, depth 100 m.

:func:`to_moorpy` builds the same system in MoorPy 1.3.0 (``moorpy.System``) from seacable's
own split into sub-lines, so both codes see exactly the same points and lines.
"""

from __future__ import annotations

import math

import numpy as np

from ...environment import Environment
from ...line import Line, LineType, PointMass, Segment
from ..model import Body, MooringSystem, SystemLine, SystemPoint

G = 9.80665
RHO = 1025.0


def _spread(n_lines, headings_deg, anchor_r, anchor_z, fair_r, fair_z, line, body="platform"):
    points, lines = {}, {}
    for i, hd in enumerate(headings_deg, start=1):
        c, s = math.cos(math.radians(hd)), math.sin(math.radians(hd))
        points[f"anchor{i}"] = SystemPoint(kind="fixed", position=(anchor_r * c, anchor_r * s, anchor_z))
        points[f"fairlead{i}"] = SystemPoint(kind="body", body=body, position=(fair_r * c, fair_r * s, fair_z))
        lines[f"line{i}"] = SystemLine(line=line, end_a=f"anchor{i}", end_b=f"fairlead{i}")
    return points, lines


OC3_CHAIN = LineType(diameter=0.09, mass_per_length=77.7066, axial_stiffness=384.243e6, name="oc3")
OC3_DEPTH = 320.0


def oc3_hywind(mass: float = 8_066_048.0, z_cg: float = -78.0) -> tuple[MooringSystem, Environment]:
    """OC3-Hywind: 3 x 902.2 m lines, anchors 853.87 m out at 320 m, fairleads 5.2 m out at 70 m.

    Body: total mass (platform 7 466 330 kg + tower 249 718 kg + rotor-nacelle 350 000 kg),
    displaced volume 8029.21 m^3, centre of buoyancy 62.07 m down, waterplane of the 6.5 m
    column (A = 33.18 m^2, I = 87.62 m^4). Lines at 180, 60 and 300 deg.
    """
    points, lines = _spread(3, (180.0, 60.0, 300.0), 853.87, -OC3_DEPTH, 5.2, -70.0,
                            Line.single(OC3_CHAIN, 902.2))
    d = 6.5
    body = Body(mass=mass, center_of_gravity=(0.0, 0.0, z_cg), inertia=(4.229e9, 4.229e9, 1.642e8),
                volume=8029.21, center_of_buoyancy=(0.0, 0.0, -62.07), waterplane_area=math.pi / 4 * d * d,
                waterplane_moments=(math.pi / 64 * d ** 4,) * 2)
    system = MooringSystem(points=points, bodies={"platform": body}, lines=lines)
    return system, Environment(water_density=RHO, gravity=G, depth=OC3_DEPTH)


OC4_CHAIN = LineType(diameter=0.0766, mass_per_length=113.35, axial_stiffness=753.6e6, name="oc4")


def oc4_semi() -> tuple[MooringSystem, Environment]:
    """OC4-DeepCwind semi: 3 x 835.5 m lines, anchors 837.6 m out at 200 m, fairleads 40.868 m out at 14 m.

    Body: platform 13 473 000 kg + turbine 599 718 kg (tower) + 350 000 kg (rotor-nacelle), centre of
    gravity 9.9 m down, displaced volume 13 917 m^3, centre of buoyancy 13.15 m down, waterplane of
    three 12 m offset columns (28.87 m from the axis) and the 6.5 m main column.
    """
    points, lines = _spread(3, (60.0, 180.0, 300.0), 837.6, -200.0, 40.868, -14.0, Line.single(OC4_CHAIN, 835.5))
    r, D, d = 28.8675, 12.0, 6.5
    area = 3 * math.pi / 4 * D * D + math.pi / 4 * d * d
    inertia = 3 * (math.pi / 64 * D ** 4) + 1.5 * (math.pi / 4 * D * D) * r * r + math.pi / 64 * d ** 4
    body = Body(mass=14_422_718.0, center_of_gravity=(0.0, 0.0, -9.9), inertia=(1.2e10, 1.2e10, 1.3e10),
                volume=13917.0, center_of_buoyancy=(0.0, 0.0, -13.15), waterplane_area=area,
                waterplane_moments=(inertia, inertia))
    system = MooringSystem(points=points, bodies={"platform": body}, lines=lines)
    return system, Environment(water_density=RHO, gravity=G, depth=200.0)


BUOY_CHAIN = LineType(diameter=0.05, mass_per_length=50.0, axial_stiffness=2.5e8, name="chain")
BUOY_ROPE = LineType(diameter=0.08, mass_per_length=6.0, axial_stiffness=4.0e7, name="rope")


def moored_buoy() -> tuple[MooringSystem, Environment]:
    """A 5 m surface buoy on three chain-rope lines with clumps and floats, depth 100 m.

    Lines 1 and 2: 110 m chain from the anchor (a 1.5 t clump 95 m from the anchor) then 80 m rope
    with a float (0.5 t, 1 m^3) 150 m from the anchor; anchors 140 m out. Line 3 is the same as two
    system lines joined at a free junction point (300 kg, 0.05 m^3) at the chain-rope boundary.
    """
    att = (PointMass(s=95.0, mass=1500.0, volume=0.2, kind="clump"),
           PointMass(s=150.0, mass=500.0, volume=1.0, kind="float"))
    two = Line(segments=(Segment(line_type=BUOY_CHAIN, length=110.0), Segment(line_type=BUOY_ROPE, length=80.0)),
               attachments=att)
    points, lines = {}, {}
    for i, hd in ((1, 0.0), (2, 120.0)):
        c, s = math.cos(math.radians(hd)), math.sin(math.radians(hd))
        points[f"anchor{i}"] = SystemPoint(kind="fixed", position=(140.0 * c, 140.0 * s, -100.0))
        points[f"fairlead{i}"] = SystemPoint(kind="body", body="buoy", position=(2.5 * c, 2.5 * s, -1.5))
        lines[f"line{i}"] = SystemLine(line=two, end_a=f"anchor{i}", end_b=f"fairlead{i}")
    c, s = math.cos(math.radians(240.0)), math.sin(math.radians(240.0))
    points["anchor3"] = SystemPoint(kind="fixed", position=(140.0 * c, 140.0 * s, -100.0))
    points["junction"] = SystemPoint(kind="free", position=(60.0 * c, 60.0 * s, -70.0), mass=300.0, volume=0.05)
    points["fairlead3"] = SystemPoint(kind="body", body="buoy", position=(2.5 * c, 2.5 * s, -1.5))
    lines["line3a"] = SystemLine(line=Line(segments=(Segment(line_type=BUOY_CHAIN, length=110.0),),
                                           attachments=att[:1]), end_a="anchor3", end_b="junction")
    lines["line3b"] = SystemLine(line=Line(segments=(Segment(line_type=BUOY_ROPE, length=80.0),),
                                           attachments=(att[1].model_copy(update={"s": 40.0}),)),
                                 end_a="junction", end_b="fairlead3")
    D = 5.0
    body = Body(mass=30_000.0, center_of_gravity=(0.0, 0.0, -1.5), volume=math.pi / 4 * D * D * 2.0,
                center_of_buoyancy=(0.0, 0.0, -1.0), waterplane_area=math.pi / 4 * D * D,
                waterplane_moments=(math.pi / 64 * D ** 4,) * 2, inertia=(5e4, 5e4, 8e4))
    system = MooringSystem(points=points, bodies={"buoy": body}, lines=lines)
    return system, Environment(water_density=RHO, gravity=G, depth=100.0)


def to_moorpy(system: MooringSystem, env: Environment, external: dict | None = None, start=None,
              shift: float = 0.0):
    """The same system in MoorPy 1.3.0; returns (moorpy.System, node -> MoorPy point number).

    ``start``: a :class:`~seacable.system.statics.SystemEquilibrium` whose body and free point
    positions MoorPy starts from (the free bodies moved by ``shift`` metres in x and y, so that
    MoorPy still has to iterate).

    Free bodies become type-0 bodies with ``rM = r_CB + (0, 0, I/V)`` (needs I_xx = I_yy), ``v``
    the volume, ``AWP`` the waterplane area (the body must be given at z = 0, MoorPy's heave
    reference), external loads in ``f6Ext``. Each seacable sub-line becomes a MoorPy line, each
    node a MoorPy point (internal nodes free, with their attachment's mass and volume).
    """
    import moorpy as mp

    from .model import BODY, FIXED, assemble

    asm = assemble(system, env)
    ms = mp.System(depth=env.depth, rho=env.water_density, g=env.gravity)
    body_id = {}
    for i in asm.free_bodies:
        name = asm.body_names[i]
        b = system.bodies[name]
        ixx, iyy = b.waterplane_moments
        if abs(ixx - iyy) > 1e-9 * max(abs(ixx), 1.0) or b.hydrostatic_stiffness is not None:
            raise ValueError("MoorPy's Body has one metacentre: needs I_xx == I_yy and no hydrostatic matrix")
        if b.position[2] != 0.0:
            raise ValueError("MoorPy measures heave from z = 0: give the body at z = 0")
        rM = np.asarray(b.center_of_buoyancy, float) + np.array([0.0, 0.0, ixx / b.volume if b.volume else 0.0])
        f6 = np.asarray(b.external_force, float) + np.asarray((external or {}).get(name, np.zeros(6)), float)
        r6 = np.asarray(b.position, float) if start is None else start.body_position[i].copy()
        r6[:2] += shift
        ms.addBody(0, r6, m=b.mass, v=b.volume, rCG=np.asarray(b.center_of_gravity, float),
                   AWP=b.waterplane_area, rM=rM, f6Ext=f6)
        body_id[len(body_id)] = len(ms.bodyList)
    node_pt = {}
    # point loads, rebuilt from the input (not from seacable's assembled node forces, so that an
    # error there shows): system points' mass, volume, force; attachments' mass and volume
    mass = np.zeros(asm.node_kind.size)
    vol = np.zeros(asm.node_kind.size)
    fext = np.zeros((asm.node_kind.size, 3))
    for pname, n in asm.point_node.items():
        p = system.points[pname]
        mass[n], vol[n], fext[n] = p.mass, p.volume, p.external_force
    seg_of = []
    for il, lname in enumerate(asm.line_names):
        subs = range(asm.line_first[il], asm.line_last[il] + 1)
        nodes = [asm.sub_a[subs[0]]] + [asm.sub_b[k] for k in subs]
        arcs = [asm.sub_s0[k] for k in subs] + [system.lines[lname].line.length]
        line = system.lines[lname].line
        for att in line.attachments:
            n = nodes[int(np.argmin(np.abs(np.array(arcs) - att.s)))]
            if att.weight_in_water is not None:
                fext[n, 2] -= att.weight_in_water
            else:
                mass[n] += att.mass
                vol[n] += att.volume
        ends = line.segment_ends
        for k in subs:
            mid = asm.sub_s0[k] + 0.5 * asm.sub_L[k]
            seg_of.append(line.segments[next(j for j in range(len(line.segments)) if mid <= ends[j + 1])])
    for n in range(asm.node_kind.size):
        if asm.node_kind[n] == BODY:
            ms.addPoint(1, asm.node_rel[n], m=mass[n], v=vol[n], fExt=fext[n], body=body_id[asm.node_body[n]])
        else:
            r = asm.node_pos0[n] if start is None or asm.node_kind[n] == FIXED else start._node_position[n]
            ms.addPoint(1 if asm.node_kind[n] == FIXED else 0, np.array(r, float), m=mass[n], v=vol[n],
                        fExt=fext[n])
        node_pt[n] = len(ms.pointList)
    for k in range(asm.sub_a.size):
        name = f"t{k}"
        lt = seg_of[k].line_type
        if lt.weight_in_water is None:      # MoorPy: w = (m - rho pi d^2 / 4) g
            ms.setLineType(dnommm=0.0, name=name, mass=lt.mass_per_length, d_vol=lt.diameter, EA=lt.axial_stiffness)
        else:
            ms.setLineType(dnommm=0.0, name=name, mass=lt.weight_in_water / env.gravity, d_vol=0.0,
                           EA=lt.axial_stiffness)
        ms.addLine(float(asm.sub_L[k]), name, pointA=node_pt[asm.sub_a[k]], pointB=node_pt[asm.sub_b[k]])
    ms.initialize()
    return ms, node_pt

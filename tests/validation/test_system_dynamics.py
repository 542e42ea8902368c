"""Coupled body-line dynamics (analysis ``system_dynamic``): free decays, hydrostatics, body force terms,
line failure.

Each test asserts a number from a closed form (a single-DOF oscillator: ``T = 2 pi sqrt((M + A) / K)``,
the logarithmic decrement of linear damping, the energy a quadratic damper takes per cycle, the static
offset under a force), from MoorDyn v2 (its Python bindings, a free BODY on three lines run side by side),
or from the FE statics of the damaged system. The mooring stiffness ``K`` of a closed form is a central
difference of the FE statics with the body held (``static_system(held=True)``), the mooring's part only.

The system: a buoy (1e6 kg unless said) on three chain lines (d 0.1 m, 150 kg/m, EA 5e8 N, 390 m) from
anchors 380 m out on a 100 m deep seabed to fairleads 10 m from the reference point.
"""

from __future__ import annotations

import contextlib
import math
import os
import sys
from types import SimpleNamespace

import numpy as np
import pytest

from seacable.environment import Environment
from seacable.line import Line, LineType
from seacable.mooring.outputs import line_end_forces
from seacable.results import body_pose
from seacable.system.dynamics import (
    SystemDynamicAnalysis,
    body_line_force,
    build_system_fe,
    run_system_dynamic,
    simulate_system,
    static_system,
)
from seacable.system.model import MooringSystem

RHO, G = 1025.0, 9.81
DEPTH = 100.0
ENV = Environment(depth=DEPTH, water_density=RHO, gravity=G)
CHAIN = {"diameter": 0.1, "mass_per_length": 150.0, "axial_stiffness": 5e8, "drag_normal": 1.2, "added_mass_normal": 1.0}
BARE = dict(CHAIN, drag_normal=0.0, added_mass_normal=0.0)  # no water loads on the lines
# a light rope (0.5 kg/m, 1.75 N/m in water): a weak mooring whose inertia (585 kg on three lines) and
# stiffness are negligible next to a buoy's, without water loads
ROPE = {"diameter": 0.02, "mass_per_length": 0.5, "axial_stiffness": 1e6, "drag_normal": 0.0, "added_mass_normal": 0.0}


def buoy_system(position=(0, 0, -20, 0, 0, 0), mass=1e6, volume=1050.0, inertia=1e8, added=None, L=390.0,
                R=380.0, r=10.0, n_el=20, chain=CHAIN, body=None, fair_z=0.0):
    lt = LineType(**chain)
    points, lines = {}, {}
    for k in range(3):
        ang = 2 * math.pi * k / 3
        points[f"anchor{k}"] = {"kind": "fixed", "position": (R * math.cos(ang), R * math.sin(ang), -DEPTH)}
        points[f"fair{k}"] = {"kind": "body", "body": "buoy", "position": (r * math.cos(ang), r * math.sin(ang), fair_z)}
        lines[f"line{k}"] = {"line": Line.single(lt, L), "end_a": f"anchor{k}", "end_b": f"fair{k}", "n_elements": n_el}
    A = np.zeros((6, 6))
    A[[0, 1, 2], [0, 1, 2]] = RHO * volume if added is None else added
    b = {"kind": "free", "position": position, "mass": mass, "inertia": (inertia,) * 3, "volume": volume, "added_mass": A.tolist()}
    b.update(body or {})
    return MooringSystem(points=points, bodies={"buoy": b}, lines=lines)


def with_body(system, **update):
    body = system.bodies["buoy"].model_copy(update=update)
    return MooringSystem(points=system.points, bodies={"buoy": body}, lines=system.lines)


def run(system, env=ENV, **analysis):
    a = SystemDynamicAnalysis(**analysis)
    return run_system_dynamic(SimpleNamespace(environment=env, analysis=a, system=system, name="test"))


def crossings(t, x):
    """Times where ``x`` crosses its mean upwards, linearly interpolated."""
    x = x - x.mean()
    i = np.flatnonzero((x[:-1] < 0) & (x[1:] >= 0))
    return t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])


def peaks(x):
    """Values of the local maxima of ``x`` (parabola through three samples)."""
    i = np.flatnonzero((x[1:-1] > x[:-2]) & (x[1:-1] >= x[2:])) + 1
    a, b, c = x[i - 1], x[i], x[i + 1]
    return b - 0.125 * (c - a) ** 2 / (a - 2 * b + c)


def mooring_stiffness(system, dof, h):
    """Column ``dof`` of the lines' 6x6 stiffness on the body at the FE equilibrium (central difference of
    the FE statics with the body held), and that equilibrium."""
    fe = build_system_fe(system, ENV)
    st = static_system(fe)
    q = st.body_position.copy()
    f = []
    for s in (1, -1):
        qq = q.copy()
        qq[0, dof] += s * h
        held = static_system(fe, held=True, q=qq, X=st.position)
        f.append(body_line_force(fe, held.position, qq)[0])
    return -(f[0] - f[1]) / (2 * h), st


def release(system, offset, env=ENV, **analysis):
    """Run a free decay: the body held at its equilibrium plus ``offset`` (6), released at t = 0; and the
    equilibrium."""
    fe = build_system_fe(system, env)
    q = static_system(fe).body_position[0]
    return run(system, env, release_offsets={"buoy": tuple(offset)}, **analysis), q


# ------------------------------------------------------------------------------------------- surge decay


def test_surge_decay_period_against_the_single_dof_closed_form():
    """Surge free decay of a heavy buoy (1e7 kg, A11 = 1.08e6 kg, CG 10 m below the reference point so that
    pitch is stiff and does not couple), 0.3 m release: the period against 2 pi sqrt((M + A11) / K11).

    The closed form leaves out the lines' own inertia, which can only lengthen the period: by at most half
    the lines' mass and added mass over M + A11 (the lines moving with the body, 185 t / 11.1e6 kg: 0.84 %).
    Asserted: 0 < T / T0 - 1 < 1.2 % (the 0.84 % plus the 0.3 m amplitude's stiffness change, 0.2 %, and
    Newmark's period error (w dt)^2 / 12 < 1e-4 at 200 steps per period). A mass term left out of the body
    (its added mass: -10 % of M + A) moves the period by -5 %.
    """
    mass = 1e7
    volume = 1050 + (mass - 1e6) / RHO
    system = buoy_system(mass=mass, volume=volume, added=RHO * 1050, body={"center_of_gravity": (0, 0, -10)})
    K, _ = mooring_stiffness(system, 0, 0.1)
    T0 = 2 * math.pi * math.sqrt((mass + RHO * 1050) / K[0])
    ds, _ = release(system, [0.3, 0, 0, 0, 0, 0], duration=4 * T0, time_step=T0 / 200, output_interval=T0 / 200)
    T = np.mean(np.diff(crossings(ds.time.values, ds.body_position.sel(axis="x").values[:, 0])))
    assert 0.0 < T / T0 - 1 < 0.012, (T, T0)


@contextlib.contextmanager
def _quiet():
    """Silence MoorDyn's C library, which prints every time step."""
    sys.stdout.flush()
    fd = os.dup(1)
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)
    try:
        yield
    finally:
        sys.stdout.flush()
        os.dup2(fd, 1)
        os.close(null)
        os.close(fd)


def _moordyn_deck(path, position, mass=1e6, volume=1050.0, inertia=1e8, L=390.0, R=380.0, r=10.0, n_el=20):
    c = CHAIN
    pts = [f"{k + 1} fixed {R * math.cos(2 * math.pi * k / 3):.12g} {R * math.sin(2 * math.pi * k / 3):.12g} "
           f"{-DEPTH} 0 0 0 0" for k in range(3)]
    pts += [f"{k + 4} body1 {r * math.cos(2 * math.pi * k / 3):.12g} {r * math.sin(2 * math.pi * k / 3):.12g} 0 0 0 0 0"
            for k in range(3)]
    x, y, z, rr, pp, yy = position
    path.write_text(f"""MoorDyn v2 input: a submerged buoy on three lines (written by seacable's test)
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA     BA/-zeta    EI   Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)    (N-s/-)   (N-m^2) (-)   (-)    (-)     (-)
chain {c['diameter']} {c['mass_per_length']} {c['axial_stiffness']} 0 0 {c['drag_normal']} {c['added_mass_normal']} 0 0
---------------------- BODIES -----------------------------------
ID   Attachment  X0     Y0    Z0     r0      p0     y0     Mass   CG*   I*      Volume   CdA*   Ca*
(#)     (-)      (m)    (m)   (m)    (deg)   (deg)  (deg)  (kg)   (m)   (kg-m^2) (m^3)   (m^2)  (-)
1 free {x:.12g} {y:.12g} {z:.12g} {math.degrees(rr):.12g} {math.degrees(pp):.12g} {math.degrees(yy):.12g} {mass} 0 {inertia} {volume} 0 1.0
---------------------- POINTS -----------------------------------
ID  Attachment  X       Y      Z      Mass  Volume  CdA    Ca
(#)   (-)       (m)     (m)    (m)    (kg)  (m^3)   (m^2)  (-)
""" + "\n".join(pts) + f"""
---------------------- LINES -----------------------------------
ID   LineType  AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)    (#)      (#)       (m)       (-)       (-)
1 chain 1 4 {L} {n_el} -
2 chain 2 5 {L} {n_el} -
3 chain 3 6 {L} {n_el} -
---------------------- OPTIONS -----------------------------------
0.0005   dtM
3e6      kbot
3e5      cbot
{DEPTH}  WtrDpth
1.0      dtIC
100      TmaxIC
4.0      CdScaleIC
0.001    threshIC
0        writeLog
--------------------- need this line ------------------
""")


def test_surge_decay_side_by_side_with_moordyn(tmp_path):
    """The same free decay in MoorDyn v2.7.2 (a free BODY: mass 1e6 kg, Ca 1 on its 1050 m^3, CG at the
    reference point so that only the lines restore pitch) and in seacable (A = rho V on x, y, z), both
    released 2 m in surge from seacable's FE equilibrium (MoorDyn holds a free body at its input
    position while it settles its lines, and agrees with that equilibrium: fairlead tension 348.7 kN
    against seacable's 349.3 kN).

    Surge couples with pitch through the lines, so the response beats; asserted: each of the three
    up-crossing intervals within 0.5 % (the two models' drag on the end nodes and seabed laws differ in
    detail: MoorDyn's explicit 0.5 ms steps against Newmark at 0.1 s, 0.05 % apart here), and the surge
    and pitch histories within 3 % of the surge amplitude (2 m) and 5 % of the pitch amplitude over 200 s.
    """
    moordyn = pytest.importorskip("moordyn")
    system = buoy_system()
    fe = build_system_fe(system, ENV)
    q = static_system(fe).body_position[0]
    start = q + [2.0, 0, 0, 0, 0, 0]
    deck = tmp_path / "buoy.dat"
    _moordyn_deck(deck, start)
    dt = 0.2
    with _quiet():
        md = moordyn.Create(str(deck))
        moordyn.Init(md, [], [])
        body = moordyn.GetBody(md, 1)
        rows = [moordyn.GetBodyState(body)[0]]
        for k in range(1000):
            moordyn.Step(md, [], [], k * dt, dt)
            rows.append(moordyn.GetBodyState(body)[0])
        moordyn.Close(md)
    ref = np.array(rows)
    t_ref = np.arange(len(ref)) * dt
    ds = run(with_body(system, position=tuple(start)), start="held", duration=200.0, time_step=0.1,
             output_interval=dt)
    x = ds.body_position.sel(axis="x").values[:, 0]
    pitch = ds.body_rotation.sel(angle="pitch").values[:, 0]
    ours, theirs = np.diff(crossings(ds.time.values, x)), np.diff(crossings(t_ref, ref[:, 0]))
    assert len(ours) == len(theirs) == 3
    np.testing.assert_allclose(ours, theirs, rtol=0.005)
    assert np.max(np.abs(x - ref[:, 0])) < 0.03 * 2.0
    assert np.max(np.abs(pitch - ref[:, 4])) < 0.05 * np.max(np.abs(ref[:, 4]))


# ------------------------------------------------------------------------------------------- heave and body terms


def floating(**body):
    """A buoy floating at the surface (1e6 kg, waterplane 50 m^2, 1050 m^3 at z = 0, A33 = 5e5 kg) on three
    light ropes (a weak mooring; no water loads on them), fairleads at the waterline."""
    extra = {"waterplane_area": 50.0, "volume": 1e6 / RHO}
    extra.update(body)
    return buoy_system(position=(0, 0, 0, 0, 0, 0), chain=ROPE, body=extra, added=5e5)


def heave_run(system, amp=0.5, periods=4, steps=100):
    K, st = mooring_stiffness(system, 2, 0.05)
    body = system.bodies["buoy"]
    k_total = RHO * G * (body.waterplane_area or 50.0) + K[2]
    T0 = 2 * math.pi * math.sqrt((body.mass + body.added_mass[2][2]) / k_total)
    q = st.body_position[0]
    ds = run(system, release_offsets={"buoy": (0, 0, amp, 0, 0, 0)}, duration=periods * T0,
             time_step=T0 / steps, output_interval=T0 / steps)
    return ds, T0, k_total, K[2], q


@pytest.mark.parametrize("hydrostatics", ["waterplane", "matrix"])
def test_heave_oscillates_at_the_hydrostatic_frequency(hydrostatics):
    """Heave free decay of the floating buoy on its weak mooring: omega = sqrt((rho g A_wp + K33) / (M + A33))
    with K33 the ropes' heave stiffness (< 1 % of rho g A_wp = 503 kN/m, from the FE statics). Tolerance
    0.3 %: the ropes' inertia (585 kg, 0.04 % of M + A33) and Newmark's (w dt)^2 / 12 = 3e-4 at 100 steps
    per period. A hydrostatic term left out (A_wp) or the added mass left out (A33 = 5e5 kg, a third of the
    inertia) moves the period by > 10 %. The same with the user's 6x6 hydrostatic matrix (rho g A_wp in
    heave, the waterplane area not given)."""
    system = floating()
    if hydrostatics == "matrix":
        C = np.zeros((6, 6))
        C[2, 2] = RHO * G * 50.0
        C[3, 3] = C[4, 4] = 1e8  # roll and pitch held up (not excited)
        system = floating(waterplane_area=0.0, hydrostatic_stiffness=C.tolist())
    ds, T0, _k_total, k_lines, _ = heave_run(system)
    assert abs(k_lines) < 0.01 * RHO * G * 50.0  # a weak mooring: the waterplane carries the heave
    T = np.mean(np.diff(crossings(ds.time.values, ds.body_position.sel(axis="z").values[:, 0])))
    assert T == pytest.approx(T0, rel=0.003)


def test_linear_damping_gives_the_logarithmic_decrement():
    """B33 for a damping ratio zeta = 0.05: the decrement ln(A_n / A_n+1) = 2 pi zeta / sqrt(1 - zeta^2)
    = 0.3146 between heave peaks, within 3 % (the lines' own damping, seabed dampers at the touchdown:
    the undamped run's peaks fall 0.4 % per cycle; Newmark's average acceleration adds none)."""
    system = floating()
    K, _ = mooring_stiffness(system, 2, 0.05)
    k = RHO * G * 50.0 + K[2]
    zeta = 0.05
    B = np.zeros((6, 6))
    B[2, 2] = 2 * zeta * math.sqrt(k * (1e6 + 5e5))
    ds, *_ = heave_run(with_body(system, linear_damping=B.tolist()))
    z = ds.body_position.sel(axis="z").values[:, 0]
    p = peaks(z - z[-len(z) // 4:].mean())
    dec = np.log(p[:-1] / p[1:])
    np.testing.assert_allclose(dec, 2 * math.pi * zeta / math.sqrt(1 - zeta**2), rtol=0.03)


def test_quadratic_damping_takes_its_energy_per_cycle():
    """B2_33 |w| w: over a cycle of amplitude A it takes (8/3) B2 w^2 A^3, so the peaks fall by
    dA = (8/3) B2 A^2 / (M + A33) per cycle (A the mean of the two peaks). B2 = 2e5 N s^2/m^2 from 0.5 m:
    dA = 0.089 m the first cycle; within 5 % (the decay is not sinusoidal at this rate: second order
    in dA / A = 0.2, about 1 %; the lines' damping, 0.4 %)."""
    B2 = np.zeros((6, 6))
    B2[2, 2] = 2e5
    ds, *_ = heave_run(floating(quadratic_damping=B2.tolist()), periods=3)
    z = ds.body_position.sel(axis="z").values[:, 0]
    _, st = mooring_stiffness(floating(quadratic_damping=B2.tolist()), 2, 0.05)
    p = peaks(z - st.body_position[0, 2])
    A = 0.5 * (p[:-1] + p[1:])
    np.testing.assert_allclose(p[:-1] - p[1:], 8 / 3 * 2e5 * A**2 / (1e6 + 5e5), rtol=0.05)


def test_external_force_series_moves_the_body_to_the_static_offset(tmp_path):
    """A surge force from a CSV series, ramped linearly from 0 to 20 kN over 200 s and then held, with
    linear surge damping c (zeta about 0.5). On the ramp F = a t the body follows the quasi-static
    x = a (t - c / K11) / K11 once the start's transient has died (e^-(zeta w t) = 2e-5 at 150 s; the mass
    term vanishes on a linear ramp): at 150 s, x / x_end = (150 - c / K11) / 200 = 0.717, within 2 % (the
    stiffness's change over the 0.44 m, below 1 %). At the end the body sits where the FE statics puts it
    under a constant 20 kN (the same system with external_force), within 1 % of that offset (the decay's
    residue is below 0.1 %). The submerged buoy on its chains (K11 = 45.8 kN/m)."""
    system = buoy_system(body={"center_of_gravity": (0, 0, -10)})
    csv = tmp_path / "force.csv"
    csv.write_text("time,fx,fy,fz,mx,my,mz\n0,0,0,0,0,0,0\n200,2e4,0,0,0,0,0\n1000,2e4,0,0,0,0,0\n")
    c = 3e5
    B = np.zeros((6, 6))
    B[0, 0] = c
    damped = with_body(system, linear_damping=B.tolist())
    K, st0 = mooring_stiffness(system, 0, 0.1)
    q0 = st0.body_position[0]
    loaded = with_body(system, external_force=(2e4, 0, 0, 0, 0, 0))
    q1 = static_system(build_system_fe(loaded, ENV)).body_position[0]
    ds = run(damped, duration=600.0, time_step=0.5, output_interval=1.0,
             external_forces={"buoy": {"file": str(csv)}})
    x = ds.body_position.sel(axis="x").values[:, 0] - q0[0]
    assert q1[0] - q0[0] > 0.3
    assert x[-1] == pytest.approx(q1[0] - q0[0], rel=0.01)
    assert x[150] / x[-1] == pytest.approx((150 - c / K[0]) / 200, rel=0.02)


def test_weight_acts_at_the_centre_of_gravity():
    """The CG 0.2 m forward of the reference point (and 3 m below it): the buoy pitches at its equilibrium
    (the start of a run) to m g x_cg / C55 (small angle), C55 = rho g I_yy + rho g V z_b - m g z_g plus the
    ropes' K55 (central difference of the FE statics). Within 1 % (the pitch is 0.03 rad: the angle against
    its sine, 2e-4; the ropes' coupling). Weight at the reference point instead would give no pitch."""
    body = {"center_of_gravity": (0.2, 0, -3.0), "center_of_buoyancy": (0, 0, -1.0),
                "waterplane_moments": (4000.0, 4000.0)}
    system = floating(**body)
    K, st = mooring_stiffness(system, 4, 0.002)
    b = system.bodies["buoy"]
    C55 = RHO * G * 4000.0 + RHO * G * b.volume * (-1.0) - b.mass * G * (-3.0)
    pitch = b.mass * G * 0.2 / (C55 + K[4])
    assert 0.01 < pitch < 0.05
    assert st.body_position[0, 4] == pytest.approx(pitch, rel=0.01)


def test_pitch_mode_of_a_low_cg_couples_with_surge():
    """The floating buoy with its CG 3 m below the reference point (I_yy = 1e8 kg m^2 about the CG) on
    the weak ropes: surge and pitch share the rigid-body mass matrix [[m + A11, m z_g], [m z_g, I + m
    z_g^2]] (the CG's acceleration a + alpha x c), so the pitch mode's period comes from the 2x2
    generalised eigenproblem with K = the hydrostatic C55 = rho g I_yy + rho g V z_b - m g z_g plus the
    ropes' 2x2 stiffness (central differences of the FE statics). Released in that mode's shape (0.01
    rad of pitch), the pitch period matches within 0.3 % (ropes' inertia 0.04 %, Newmark 3e-4 at 100
    steps per period). Leaving out the coupling m z_g (or the parallel-axis term m z_g^2) moves it by
    2.8 % (or 4 %)."""
    system = floating(center_of_gravity=(0, 0, -3.0), center_of_buoyancy=(0, 0, -1.0),
                      waterplane_moments=(4000.0, 4000.0))
    b = system.bodies["buoy"]
    K1, _st = mooring_stiffness(system, 0, 0.05)
    K5, _ = mooring_stiffness(system, 4, 0.002)
    zg, m = -3.0, b.mass
    Mt = np.array([[m + b.added_mass[0][0], m * zg], [m * zg, b.inertia[1] + m * zg**2]])
    C55 = RHO * G * 4000.0 + RHO * G * b.volume * (-1.0) - m * G * zg
    Kt = np.array([[K1[0], K5[0]], [K1[4], K5[4] + C55]])
    w2, vec = np.linalg.eig(np.linalg.solve(Mt, Kt))
    k = int(np.argmax(w2.real))
    T0 = 2 * math.pi / math.sqrt(w2[k].real)
    shape = vec[:, k].real / vec[1, k].real * 0.01
    ds = run(system, release_offsets={"buoy": (shape[0], 0, 0, 0, shape[1], 0)}, duration=4 * T0,
             time_step=T0 / 100, output_interval=T0 / 100)
    T = np.mean(np.diff(crossings(ds.time.values, ds.body_rotation.sel(angle="pitch").values[:, 0])))
    assert T == pytest.approx(T0, rel=0.003)


# ------------------------------------------------------------------------------------------- line failure


def _energy(fe, run_):
    """Kinetic plus potential energy of the lines (no water loads: node mass, weight in water, strain) and
    the body (rigid body without added mass: 1/2 m |v + w x c|^2 + 1/2 w.I_cg w, w the angle rates;
    weight at its CG, buoyancy with its waterplane) at each output, (nt,). [J]"""
    from seacable.mooring.motion import rotation_matrix

    m = fe.model
    net = m.network
    mass = net.point_mass.copy()
    np.add.at(mass, net.elements[:, 0], 0.5 * net.mass_per_length * net.length)
    np.add.at(mass, net.elements[:, 1], 0.5 * net.mass_per_length * net.length)
    body = fe.system.bodies["buoy"]
    sb = 0.25 * net.mass_per_length * G * net.length / net.axial_stiffness
    out = []
    for k in range(len(run_.time)):
        X, V = run_.position[k], run_.velocity[k]
        e = 0.5 * np.sum(mass * np.sum(V**2, axis=1)) + np.sum(m.weight * X[:, 2])
        eps = np.linalg.norm(X[net.elements[:, 1]] - X[net.elements[:, 0]], axis=1) / net.length - 1
        w = np.where(eps >= sb, eps**2 / 2 + sb**2 / 6, np.where(eps > -sb, (eps + sb) ** 3 / (12 * sb), 0.0))
        e += np.sum(net.axial_stiffness * net.length * w)
        q, qd = run_.body_position[k, 0], run_.body_velocity[k, 0]
        R = rotation_matrix(*q[3:])
        c = R @ np.asarray(body.center_of_gravity)
        v_cg = qd[:3] + np.cross(qd[3:], c)
        I_g = R @ np.diag(body.inertia) @ R.T
        e += 0.5 * body.mass * v_cg @ v_cg + 0.5 * qd[3:] @ I_g @ qd[3:] + body.mass * G * (q[2] + c[2])
        e -= RHO * G * (body.volume * q[2] - 0.5 * body.waterplane_area * (q[2] - body.position[2]) ** 2)
        out.append(e)
    return np.array(out)


def test_line_break_energy_bookkeeping():
    """Line 0 breaks at its fairlead at t = 5 s, in water without a seabed (the lines hang from their
    anchors) and without damping anywhere (no water loads on the lines, no body damping, rotations
    restored by a CG 10 m down), over the 4 s of the snap-back (later, the free end of the undamped broken
    line whips without water to stop it), so that the energy of the system (body and lines: kinetic,
    gravity and buoyancy, waterplane, strain) stays what it was: within 0.5 % of the largest kinetic
    energy of the transient (35 MJ). Average-acceleration Newmark conserves a linear system's energy; the
    slack-taut switching and the strain's nonlinearity cost what converges with the step: 2.2 % at
    0.02 s, 0.42 % at 0.01 s, 0.19 % at the 0.005 s used. A body mass, weight or buoyancy term that were
    wrong would break the balance by its share of the transient."""
    env = Environment(depth=None, water_density=RHO, gravity=G)
    system = buoy_system(position=(0, 0, 0, 0, 0, 0), chain=BARE, added=0.0, fair_z=-5.0,
                         body={"waterplane_area": 50.0, "center_of_gravity": (0, 0, -10)})
    a = SystemDynamicAnalysis(duration=9.0, time_step=0.005, output_interval=0.1,
                              failures=[{"line": "line0", "end": "b", "time": 5.0}])
    fe = build_system_fe(system, env, a)
    st = static_system(fe)
    r = simulate_system(fe, st, a.duration, a.time_step, a.output_interval, analysis=a, tol=1e-9)
    assert r.failure_time[np.flatnonzero(fe.con_line == 0)[0]] == pytest.approx(5.0)
    E = _energy(fe, r)
    before = E[r.time < 5.0]
    net = fe.model.network
    mass = np.zeros(net.n_nodes)
    np.add.at(mass, net.elements[:, 0], 0.5 * net.mass_per_length * net.length)
    np.add.at(mass, net.elements[:, 1], 0.5 * net.mass_per_length * net.length)
    kinetic = np.max(0.5 * np.sum(mass * np.sum(r.velocity**2, axis=2), axis=1))
    assert kinetic > 1e5  # a real transient: the broken line swings down
    assert np.ptp(before) < 1e-6 * kinetic  # at rest before the break
    assert np.max(np.abs(E - E[0])) < 0.005 * kinetic, (np.max(np.abs(E - E[0])), kinetic)


def test_line_break_settles_on_the_damaged_equilibrium():
    """The buoy floating (waterplane 50 m^2) on the chains, fairleads 5 m down, anchors 100 m down in deep
    water (no seabed: the broken line hangs from its anchor; on a seabed it would fold up where it lands,
    and friction, which the statics leaves out, would hold the other lines' grounded parts where the
    transient left them), pushed by a constant 200 kN towards line 0's anchor so that lines 1 and 2 hold
    it, also after the failure. A surge decay released 3 m towards line 0's anchor swings back and loads
    line 0 until it fails at its fairlead at 1.05 times its tension at rest. With body damping (zeta about
    0.16 in surge and sway, 0.05 in heave, rotations damped), the lines' axial damping (ratio 0.8,
    which takes the snapped end's ringing) and their mass-proportional damping (0.05 1/s: the broken line's
    swing under quadratic drag alone decays only algebraically, and whether it had come to rest at 600 s
    depended on round-off: a release 1e-6 m larger left it swinging 25 m), the body and the two remaining lines settle where the FE
    statics of the damaged system (line 0 removed) puts them after 600 s: the body within 1 mm of that
    equilibrium (it moves 73 m; 0.04 mm here) and the tensions within 1e-4 (5e-6 here), the residue of
    the damped transient and of the Newton tolerance."""
    system = buoy_system(position=(0, 0, 0, 0, 0, 0), fair_z=-5.0,
                         body={"center_of_gravity": (0, 0, -10), "waterplane_area": 50.0,
                                   "external_force": (2e5, 0, 0, 0, 0, 0)})
    B = np.zeros((6, 6))
    B[0, 0] = B[1, 1] = B[2, 2] = 1e5
    B[3, 3] = B[4, 4] = B[5, 5] = 1e9
    damped = with_body(system, linear_damping=B.tolist())
    env = Environment(depth=None, water_density=RHO, gravity=G)
    fe0 = build_system_fe(damped, env)
    st0 = static_system(fe0)
    t_rest = st0.tension[fe0.line_elements[0][-1]]
    ds, q = release(damped, [3.0, 0, 0, 0, 0, 0], env, duration=600.0, time_step=0.2, output_interval=1.0,
                    damping_ratio=0.8, rayleigh=(0.05, 0.0),
                    failures=[{"line": "line0", "end": "b", "tension": 1.05 * t_rest}])
    t_fail = float(ds.failure_time.sel(line="line0"))
    assert 5.0 < t_fail < 60.0
    assert np.all(np.isnan(ds.failure_time.sel(line=["line1", "line2"]).values))
    damaged = damped.without("line0")
    fe = build_system_fe(damaged, env)
    st = static_system(fe)
    end = ds.body_position.isel(time=-1).sel(body="buoy").values
    assert abs(st.body_position[0, 0] - q[0]) > 10.0
    np.testing.assert_allclose(end[:3], st.body_position[0, :3], atol=1e-3)
    # the statics' end forces (the single line's definition, seacable.mooring.outputs.line_end_forces)
    tens = [np.linalg.norm(line_end_forces(fe.model, st.position, line=k)[1]) for k in range(2)]
    np.testing.assert_allclose(ds.fairlead_tension.isel(time=-1).sel(line=["line1", "line2"]).values, tens,
                               rtol=1e-4)
    # the broken line hangs from its anchor: its free end element holds the end node's half element, and the
    # line's force on its free end is nothing but its equation of motion's residual
    w = (CHAIN["mass_per_length"] - RHO * math.pi * CHAIN["diameter"] ** 2 / 4) * G
    assert float(ds.segment_tension.isel(time=-1, element=-1).sel(line="line0")) == pytest.approx(w * 390.0 / 20 / 2,
                                                                                                 rel=0.01)
    assert float(ds.fairlead_tension.isel(time=-1).sel(line="line0")) < 1e-6 * tens[0]


# ------------------------------------------------------------------------------------------- prescribed bodies


def test_a_prescribed_body_moved_as_the_free_one_moved_loads_its_lines_alike(tmp_path):
    """The free surge decay of the buoy (released 2 m, 100 s), then the same buoy as a prescribed body whose
    6-DOF motion is the free run's (a CSV of surge ... yaw every 0.1 s, a natural cubic spline between):
    the lines see the same fairlead paths, so the fairlead tensions agree: within 2e-4 of the mean tension
    (the spline through the 0.1 s samples against the coupled step's own Newmark kinematics, 3.4e-5 here;
    a body force or inertia that the coupling lost would show at the percent level, the size of the
    body's line force swing). The prescribed body's reported position is the motion's, and its fairleads
    sit at r + R p."""
    system = buoy_system(body={"center_of_gravity": (0, 0, -10)})
    free, _q = release(system, [2.0, 0, 0, 0, 0, 0], duration=100.0, time_step=0.1, output_interval=0.1)
    qt = body_pose(free.sel(body="buoy"))
    csv = tmp_path / "motion.csv"
    rows = np.column_stack([free.time.values, qt - qt[0]])
    np.savetxt(csv, rows, delimiter=",", header="time,surge,sway,heave,roll,pitch,yaw", comments="")
    prescribed = with_body(system, kind="prescribed", position=tuple(qt[0]))
    ds = run(prescribed, duration=100.0, time_step=0.1, output_interval=0.1,
             body_motions={"buoy": {"type": "platform", "file": str(csv)}})
    T_free, T_pres = free.fairlead_tension.values, ds.fairlead_tension.values
    # (the end force holds the half element's inertia, m a: the CSV's natural spline has no acceleration at its
    # first sample, where the free body starts with 0.074 m/s^2, 114 N of the 1540 kg half element's; compared
    # from the second output on: 7.9e-5 measured)
    assert np.max(np.abs(T_pres - T_free)[1:]) < 2e-4 * np.mean(T_free)
    np.testing.assert_allclose(body_pose(ds.sel(body="buoy")), qt, atol=1e-9)
    # the fairleads sit on the moved body: x = r + R p
    from seacable.mooring.motion import rotation_matrix

    fair = np.column_stack([ds[c].sel(line="line0").values[:, -1] for c in "xyz"])
    R = rotation_matrix(qt[:, 3], qt[:, 4], qt[:, 5])
    np.testing.assert_allclose(fair, qt[:, :3] + R @ np.array([10.0, 0, 0]), atol=1e-9)


# ------------------------------------------------------------------------------------------- bad input


def _case(system, **analysis):
    return SimpleNamespace(environment=ENV, analysis=SystemDynamicAnalysis(**analysis), system=system, name="bad")


@pytest.mark.parametrize("analysis, match", [
    ({"failures": [{"line": "lin0", "end": "a", "time": 1.0}]}, "line 'lin0' is not defined.*line0"),
    ({"external_forces": {"boy": {"times": [0, 10], "values": [[0] * 6, [0] * 6]}}}, "body 'boy' is not defined"),
    ({"external_forces": {"buoy": {"times": [0, 5], "values": [[0] * 6, [0] * 6]}}}, "covers 0 to 5 s"),
    ({"body_motions": {"buoy": {"type": "platform", "amplitude": [1, 0, 0, 0, 0, 0], "period": 10}}},
     "body 'buoy' is free"),
    ({"point_motions": {"anchor0": {"type": "harmonic", "amplitude": [1, 0, 0], "period": 10}}},
     "only coupled points follow a motion"),
])
def test_bad_input_is_refused_before_the_run(analysis, match):
    from seacable.errors import InputError
    from seacable.system.dynamics import prepare_system_dynamic

    with pytest.raises(InputError, match=match):
        prepare_system_dynamic(_case(buoy_system(), duration=10.0, **analysis))


def test_a_prescribed_body_without_motion_is_warned():
    from seacable.errors import SeacableWarning
    from seacable.system.dynamics import prepare_system_dynamic

    with pytest.warns(SeacableWarning, match="prescribed but analysis.body_motions has no motion"):
        prepare_system_dynamic(_case(with_body(buoy_system(), kind="prescribed"), duration=10.0))


def test_a_coupled_point_runs_as_the_single_line_mooring_model():
    """One chain from an anchor to a coupled point moved harmonically (2 m surge, 15 s, 10 s ramp): the
    system model and the single-line mooring model (:func:`seacable.mooring.solver.simulate` on
    :func:`network_from_line`, same elements) run the same kernel loads with the same Newmark step, so
    the fairlead tensions agree to the Newton tolerance (1e-7 of the force scale; asserted 1e-5 of the
    mean tension)."""
    from seacable.mooring.motion import HarmonicMotion, bind
    from seacable.mooring.network import catenary_positions, network_from_line
    from seacable.mooring.solver import MooringModel, Water, simulate, static_equilibrium

    lt = LineType(**CHAIN)
    line = Line.single(lt, 390.0)
    anchor, fair = (380.0, 0.0, -DEPTH), (10.0, 0.0, -20.0)
    system = MooringSystem(points={"a": {"kind": "fixed", "position": anchor}, "f": {"kind": "coupled", "position": fair}},
                           lines={"l": {"line": line, "end_a": "a", "end_b": "f", "n_elements": 20}})
    motion = HarmonicMotion(amplitude=(2.0, 0.0, 0.0), period=15.0, ramp=10.0)
    ds = run(system, duration=60.0, time_step=0.1, output_interval=0.5, point_motions={"f": motion.model_dump()})
    net = network_from_line(line, anchor, fair, water_density=RHO, gravity=G, n_elements=20)
    start = catenary_positions(fair, anchor, 390.0 - net.arc_length, [390.0], [line.weights(RHO, G)[0]],
                               [lt.axial_stiffness], depth=DEPTH)
    model = MooringModel(net.replace(position=start), Water(density=RHO, gravity=G, depth=DEPTH))
    st = static_equilibrium(model, tol=1e-8)
    r = simulate(model, bind(motion, net.channel_positions(st.position), 60.0), 60.0, 0.1, 0.5,
                 initial=st.position, tol=1e-7)
    ours = ds.fairlead_tension.sel(line="l").values
    # the single line's fairlead tension: its end force (end element, half element's weight, drag and inertia)
    theirs = np.linalg.norm(line_end_forces(model, r.position, r.velocity, r.acceleration, r.time)[:, 1], axis=-1)
    assert np.ptp(ours) > 0.1 * np.mean(ours)  # the motion loads the line
    np.testing.assert_allclose(ours, theirs, rtol=0, atol=1e-5 * np.mean(theirs))


def test_waves_on_free_bodies_are_warned():
    from seacable.errors import SeacableWarning
    from seacable.system.dynamics import prepare_system_dynamic

    env = Environment(depth=DEPTH, water_density=RHO, gravity=G, waves={"height": 2.0, "period": 10.0})
    case = SimpleNamespace(environment=env, analysis=SystemDynamicAnalysis(duration=10.0), system=buoy_system(),
                           name="waves")
    with pytest.warns(SeacableWarning, match="not on the free bodies"):
        prepare_system_dynamic(case)

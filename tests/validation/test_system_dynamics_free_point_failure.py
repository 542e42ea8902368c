"""A line that fails at a free point (a subsea buoy shared by three lines) in ``system_dynamic``.

The failing line's end has a node of its own, tied to the buoy's node (the same position) until the
failure, then released with the position and velocity it had; the buoy's mass and volume stay with the
buoy. Asserted: the energy of the whole system through the snap-back (closed form: it is conserved
without damping), and that the buoy and the two remaining lines settle on the FE statics of the damaged
system (the same system with the line removed), as for a line that fails at a body.

The system: a buoy (5 t, 100 m^3: 957 kN net buoyancy) 61 m above three anchors 80 m around it in
deep water (no seabed: a broken line hangs from its anchor), on three 101 m chains (0.1 m, 150 kg/m,
EA 5e8 N, 20 elements).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.environment import Environment
from seacable.line import Line, LineType
from seacable.mooring.outputs import line_end_forces
from seacable.system.dynamics import (
    SystemDynamicAnalysis,
    build_system_fe,
    run_system_dynamic,
    simulate_system,
    static_system,
)
from seacable.system.model import MooringSystem

RHO, G = 1025.0, 9.81
ENV = Environment(depth=None, water_density=RHO, gravity=G)
CHAIN = {"diameter": 0.1, "mass_per_length": 150.0, "axial_stiffness": 5e8, "drag_normal": 1.2, "added_mass_normal": 1.0}
BARE = dict(CHAIN, drag_normal=0.0, added_mass_normal=0.0)


def buoy_on_three(chain=CHAIN, buoy=None):
    lt = LineType(**chain)
    points = {"buoy": {"kind": "free", "position": (0, 0, -40), "mass": 5000.0, "volume": 100.0, **(buoy or {})}}
    lines = {}
    for k in range(3):
        ang = 2 * math.pi * k / 3
        points[f"anchor{k}"] = {"kind": "fixed", "position": (80 * math.cos(ang), 80 * math.sin(ang), -100)}
        lines[f"line{k}"] = {"line": Line.single(lt, 101.0), "end_a": f"anchor{k}", "end_b": "buoy", "n_elements": 20}
    return MooringSystem(points=points, lines=lines)


def energy(fe, r):
    """Kinetic, gravity-buoyancy and strain energy of the nodes (no water loads) at each output. [J]"""
    m = fe.model
    net = m.network
    mass = net.point_mass.copy()
    np.add.at(mass, net.elements[:, 0], 0.5 * net.mass_per_length * net.length)
    np.add.at(mass, net.elements[:, 1], 0.5 * net.mass_per_length * net.length)
    sb = 0.25 * net.mass_per_length * G * net.length / net.axial_stiffness
    out = []
    for X, V in zip(r.position, r.velocity, strict=True):
        eps = np.linalg.norm(X[net.elements[:, 1]] - X[net.elements[:, 0]], axis=1) / net.length - 1
        w = np.where(eps >= sb, eps**2 / 2 + sb**2 / 6, np.where(eps > -sb, (eps + sb) ** 3 / (12 * sb), 0.0))
        out.append(0.5 * np.sum(mass * np.sum(V**2, axis=1)) + np.sum(m.weight * X[:, 2])
                   + np.sum(net.axial_stiffness * net.length * w))
    return np.array(out), mass


def test_energy_through_a_break_at_a_free_point():
    """Line 0 fails at the buoy at t = 2 s, no water loads and no damping anywhere: the buoy jumps away and
    the broken line swings down. At the break the line's end is where the buoy is, at its velocity (the
    tie holds it exactly until then); over the 2 s of the snap-back (12 MJ of kinetic energy) the energy
    stays what it was within 0.5 % of the largest kinetic energy (Newmark's average acceleration conserves
    a linear system's energy; the slack-taut switching and the strain's nonlinearity cost what converges
    with the step: 0.94 % at 0.005 s, 0.092 % at the 0.0025 s used, 0.007 % at 0.00125 s)."""
    system = buoy_on_three(BARE)
    a = SystemDynamicAnalysis(duration=4.0, time_step=0.0025, output_interval=0.05,
                              failures=[{"line": "line0", "end": "b", "time": 2.0}])
    fe = build_system_fe(system, ENV, a)
    st = static_system(fe)
    r = simulate_system(fe, st, a.duration, a.time_step, a.output_interval, analysis=a, tol=1e-9)
    j = int(np.flatnonzero(fe.con_line == 0)[0])
    assert r.failure_time[j] == pytest.approx(2.0)
    end, buoy = fe.con_node[j], fe.point_node["buoy"]
    k = int(np.argmin(np.abs(r.time - 2.0)))
    np.testing.assert_allclose(r.position[k, end], r.position[k, buoy], atol=1e-9)
    np.testing.assert_allclose(r.velocity[k, end], r.velocity[k, buoy], atol=1e-9)
    assert np.linalg.norm(r.position[-1, end] - r.position[-1, buoy]) > 5.0  # they part
    E, mass = energy(fe, r)
    kinetic = np.max(0.5 * np.sum(mass * np.sum(r.velocity**2, axis=2), axis=1))
    assert kinetic > 1e5
    assert np.ptp(E[r.time < 2.0]) < 1e-6 * kinetic  # at rest before the break
    assert np.max(np.abs(E - E[0])) < 0.005 * kinetic, (np.max(np.abs(E - E[0])), kinetic)


def test_break_at_a_free_point_settles_on_the_damaged_equilibrium():
    """Line 0 fails at the buoy at 5 s; with the lines' drag, axial damping (ratio 0.8) and mass-proportional
    damping (0.05 1/s) and the buoy's drag (CdA 2 m^2), the buoy and the two remaining lines settle where
    the FE statics of the damaged system (line 0 removed) puts them: the buoy within 1 mm (it moves 42 m; 0.4 mm
    here), the fairlead tensions within 1e-4 (7e-8 here; the residue of the damped transient after 300 s
    and the Newton tolerance); the broken line hangs from its anchor, its free end element holding half an
    element's weight in water (1 %; 4e-8 here)."""
    system = buoy_on_three(buoy={"drag_area": 2.0, "added_mass": 20.0 * RHO})
    a = SystemDynamicAnalysis(duration=300.0, time_step=0.1, output_interval=1.0, damping_ratio=0.8,
                              rayleigh=(0.05, 0.0), failures=[{"line": "line0", "end": "b", "time": 5.0}])
    from types import SimpleNamespace

    ds = run_system_dynamic(SimpleNamespace(environment=ENV, analysis=a, system=system, name="free point failure"))
    assert float(ds.failure_time.sel(line="line0")) == pytest.approx(5.0)
    damaged = system.without("line0")
    fe = build_system_fe(damaged, ENV)
    st = static_system(fe)
    node = fe.point_node["buoy"]
    intact = static_system(build_system_fe(system, ENV))
    assert np.linalg.norm(st.position[node] - intact.position[build_system_fe(system, ENV).point_node["buoy"]]) > 10
    buoy_end = np.array([float(ds[c].sel(line="line1").isel(time=-1, node=-1)) for c in "xyz"])
    np.testing.assert_allclose(buoy_end, st.position[node], atol=1e-3)
    # the statics' end forces (the single line's definition, seacable.mooring.outputs.line_end_forces)
    tens = [np.linalg.norm(line_end_forces(fe.model, st.position, line=k)[1]) for k in range(2)]
    np.testing.assert_allclose(ds.fairlead_tension.isel(time=-1).sel(line=["line1", "line2"]).values, tens, rtol=1e-4)
    w = (CHAIN["mass_per_length"] - RHO * math.pi * CHAIN["diameter"] ** 2 / 4) * G
    hanging = float(ds.segment_tension.isel(time=-1, element=-1).sel(line="line0"))
    assert hanging == pytest.approx(w * 101.0 / 20 / 2, rel=0.01)
    # the line's force on its free end: its equation of motion's residual
    assert float(ds.fairlead_tension.isel(time=-1).sel(line="line0")) < 1e-6 * tens[0]

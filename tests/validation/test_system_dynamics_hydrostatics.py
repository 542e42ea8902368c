"""Hydrostatic restoring of a floating body in ``system_dynamic``: free decays in heave, roll and pitch.

A body floating freely (on three light ropes whose stiffness is under 1 % of the waterplane's) released from a
small offset in one degree of freedom oscillates at ``T = 2 pi sqrt((M + A) / (C + K))`` in it: ``M`` the mass
(heave) or the moment of inertia about the reference point (roll, pitch), ``A`` the added mass, ``K`` the ropes'
stiffness (central difference of the FE statics with the body held), and the hydrostatic stiffness

* heave: ``C33 = rho g A_wp``,
* roll:  ``C44 = rho g V GM_T = rho g (I_xx + V z_b) - m g z_g`` (``BM_T = I_xx / V``, ``z_b``, ``z_g`` the
  centres of buoyancy and gravity above the reference point),
* pitch: ``C55 = rho g V GM_L = rho g (I_yy + V z_b) - m g z_g``

(e.g. Faltinsen, Sea Loads on Ships and Offshore Structures, 1990, section 2.2; Newman, Marine Hydrodynamics,
1977, section 6.16). The body's roll and pitch differ in every term (waterplane moments 3000 and 5000 m^4,
inertia 0.8e8 and 1.2e8 kg m^2, added inertia 2e7 and 3e7 kg m^2), so a waterplane moment read for the other
axis moves a period by 29 % or 41 %; its centre of buoyancy 1 m below the reference point takes 33 % off C44 and
19 % off C55 (leaving it at the reference point shortens the periods by 18 % and 10 %).
The centre of gravity is at the reference point, so that no rigid-body coupling ties roll to sway or pitch to
surge (that coupling: tests/validation/test_system_dynamics.py, the low-CG pitch mode). Each is run with the
waterplane (area, moments, centres) and with the user's 6x6 hydrostatic matrix of the same C33, C44, C55.

Tolerance 0.2 % on the period: Newmark's average acceleration lengthens it by ``(w dt)^2 / 12 = 3.3e-4`` at 100
steps per period; the ropes' inertia (585 kg on 1.5e6 kg in heave; in roll 585 kg at 10 m: 6e4 kg m^2, 6e-4 of
1e8, so 3e-4 on the period); the ropes' coupling of roll with sway (their stiffness next to the waterplane's
under 1 %); measured +0.043 % to +0.054 % in all six runs. A sign error in a restoring term makes the body capsize (the
amplitude grows: also asserted), a term left out or read for the other axis moves the period by > 10 %.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from seacable.environment import Environment
from seacable.line import Line, LineType
from seacable.results import body_pose
from seacable.system.dynamics import (
    SystemDynamicAnalysis,
    body_line_force,
    build_system_fe,
    run_system_dynamic,
    static_system,
)
from seacable.system.model import MooringSystem

RHO, G, DEPTH = 1025.0, 9.81, 100.0
ENV = Environment(depth=DEPTH, water_density=RHO, gravity=G)
# a light rope (0.5 kg/m) without water loads: a weak mooring
ROPE = {"diameter": 0.02, "mass_per_length": 0.5, "axial_stiffness": 1e6, "drag_normal": 0.0, "added_mass_normal": 0.0}
MASS = 1e6
VOLUME = MASS / RHO                       # floats at its reference pose: 975.6 m^3
AWP = 50.0                                # m^2
IWP = (3000.0, 5000.0)                    # waterplane's second moments about x and y [m^4]
INERTIA = (0.8e8, 1.2e8, 1.0e8)           # about the CG (= the reference point) [kg m^2]
ADDED = np.diag([5e5, 5e5, 5e5, 2e7, 3e7, 1e7])
ZB = -1.0                                 # centre of buoyancy above the reference point [m]
C = np.array([0.0, 0.0, RHO * G * AWP, RHO * G * (IWP[0] + VOLUME * ZB), RHO * G * (IWP[1] + VOLUME * ZB), 0.0])
DOF = {"heave": 2, "roll": 3, "pitch": 4}


def floating(hydrostatics):
    """The body at the surface on three ropes from anchors 380 m out to fairleads 10 m out at the waterline."""
    lt = LineType(**ROPE)
    points, lines = {}, {}
    for k in range(3):
        a = 2 * math.pi * k / 3
        points[f"anchor{k}"] = {"kind": "fixed", "position": (380 * math.cos(a), 380 * math.sin(a), -DEPTH)}
        points[f"fair{k}"] = {"kind": "body", "body": "buoy", "position": (10 * math.cos(a), 10 * math.sin(a), 0.0)}
        lines[f"line{k}"] = {"line": Line.single(lt, 390.0), "end_a": f"anchor{k}", "end_b": f"fair{k}",
                             "n_elements": 20}
    body = {"kind": "free", "position": (0, 0, 0, 0, 0, 0), "mass": MASS, "inertia": INERTIA, "volume": VOLUME,
            "added_mass": ADDED.tolist(), "center_of_buoyancy": (0.0, 0.0, ZB)}
    if hydrostatics == "waterplane":
        body.update(waterplane_area=AWP, waterplane_moments=IWP)
    else:
        body.update(hydrostatic_stiffness=np.diag(C).tolist())
    return MooringSystem(points=points, bodies={"buoy": body}, lines=lines)


def rope_stiffness(system, dof, h):
    """K[dof, dof] of the ropes on the body (central difference of the FE statics, body held), and the
    equilibrium."""
    fe = build_system_fe(system, ENV)
    st = static_system(fe)
    f = []
    for s in (1, -1):
        q = st.body_position.copy()
        q[0, dof] += s * h
        held = static_system(fe, held=True, q=q, X=st.position)
        f.append(body_line_force(fe, held.position, q)[0][dof])
    return -(f[0] - f[1]) / (2 * h), st


def crossings(t, x):
    """Times where ``x`` crosses its mean upwards, linearly interpolated."""
    x = x - x.mean()
    i = np.flatnonzero((x[:-1] < 0) & (x[1:] >= 0))
    return t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])


@pytest.mark.parametrize("hydrostatics", ["waterplane", "matrix"])
@pytest.mark.parametrize("mode", ["heave", "roll", "pitch"])
def test_free_decay_period_is_the_hydrostatic_one(mode, hydrostatics):
    """Released 0.3 m (heave) or 0.02 rad (roll, pitch) from its equilibrium: the period against
    ``2 pi sqrt((M + A) / (C + K))`` (module docstring; roll 13.92 s, pitch 12.09 s, heave 10.85 s), within
    0.2 %, and the motion bounded by its release (a wrong sign grows it)."""
    system = floating(hydrostatics)
    dof = DOF[mode]
    amp = 0.3 if mode == "heave" else 0.02
    k_lines, st = rope_stiffness(system, dof, 0.05 if mode == "heave" else 0.002)
    assert abs(k_lines) < 0.01 * C[dof]                     # the ropes are weak next to the waterplane
    inertia = MASS if mode == "heave" else INERTIA[dof - 3]
    T0 = 2 * math.pi * math.sqrt((inertia + ADDED[dof, dof]) / (C[dof] + k_lines))
    offset = [0.0] * 6
    offset[dof] = amp
    a = SystemDynamicAnalysis(release_offsets={"buoy": tuple(offset)}, duration=3.0 * T0, time_step=T0 / 100,
                              output_interval=T0 / 100)
    ds = run_system_dynamic(SimpleNamespace(environment=ENV, analysis=a, system=system, name="test"))
    x = body_pose(ds)[:, 0, dof] - st.body_position[0, dof]   # dof 2: heave, 3: roll, 4: pitch
    assert np.max(np.abs(x)) < 1.01 * amp                   # oscillates about the equilibrium, no capsize
    T = np.mean(np.diff(crossings(ds.time.values, x)))
    assert T == pytest.approx(T0, rel=0.002)

"""A moored body in a current (``system_dynamic``): its quadratic damping acts on the velocity relative to
the current, so the body drifts to where the lines' restoring balances the current's drag.

Reference: the static equilibrium of the same system under the equivalent constant force, the drag of the
current on the body at rest, ``R6 B2 |R^T u_c| R^T u_c`` at the equilibrium's pose (R the body's rotation):
the FE statics of the same lines (:func:`static_system`), and the catenary system statics
(:func:`seacable.system.statics.solve_equilibrium`).

The system: the submerged buoy of tests/validation/test_system_dynamics.py (1e6 kg, CG 10 m below the
reference point) on three chains without water loads (so that the current acts on the body only), a
uniform 0.8 m/s current at 30 deg, B2 = 1e5 N s^2/m^2 in x, y and z (51 kN of drag at rest).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from seacable.environment import Environment
from seacable.line import Line, LineType
from seacable.mooring.motion import rotation_matrix
from seacable.results import body_pose
from seacable.system.dynamics import SystemDynamicAnalysis, build_system_fe, run_system_dynamic, static_system
from seacable.system.model import MooringSystem
from seacable.system.statics import solve_equilibrium

RHO, G, DEPTH = 1025.0, 9.81, 100.0
SPEED, HEADING = 0.8, math.radians(30.0)
BARE = {"diameter": 0.1, "mass_per_length": 150.0, "axial_stiffness": 5e8, "drag_normal": 0.0, "added_mass_normal": 0.0}
B2 = np.diag([1e5, 1e5, 1e5, 0.0, 0.0, 0.0])


def env(speed):
    return Environment(depth=DEPTH, water_density=RHO, gravity=G, current={"speed": speed, "heading": HEADING})


def buoy(**update):
    lt = LineType(**BARE)
    points, lines = {}, {}
    for k in range(3):
        ang = 2 * math.pi * k / 3
        points[f"anchor{k}"] = {"kind": "fixed", "position": (380 * math.cos(ang), 380 * math.sin(ang), -DEPTH)}
        points[f"fair{k}"] = {"kind": "body", "body": "buoy", "position": (10 * math.cos(ang), 10 * math.sin(ang), 0)}
        lines[f"line{k}"] = {"line": Line.single(lt, 390.0), "end_a": f"anchor{k}", "end_b": f"fair{k}", "n_elements": 20}
    A = np.diag([RHO * 1050.0] * 3 + [0.0] * 3)
    body = {"kind": "free", "position": (0, 0, -20, 0, 0, 0), "mass": 1e6, "inertia": (1e8,) * 3, "volume": 1050.0,
            "added_mass": A.tolist(), "center_of_gravity": (0, 0, -10), "quadratic_damping": B2.tolist()}
    body.update(update)
    return MooringSystem(points=points, bodies={"buoy": body}, lines=lines)


def drag_at(q):
    """The current's drag on the body at rest at pose q: R6 B2 |R^T u_c| R^T u_c. [N, N m]"""
    R = rotation_matrix(*q[3:])
    uc = SPEED * np.array([math.cos(HEADING), math.sin(HEADING), 0.0])
    vr = np.r_[-R.T @ uc, 0, 0, 0]
    fb = -B2 @ (np.abs(vr) * vr)
    return np.r_[R @ fb[:3], R @ fb[3:]]


def test_a_body_in_current_drifts_to_the_offset_of_its_drag():
    """Released at rest at its still-water equilibrium (start: held) in the current, the buoy drifts and
    settles (its drag damps it: zeta about 0.3 in surge, e^-20 left after 600 s) where the FE statics
    under the equivalent force puts it: within 1 mm of a 1.2 m offset (the Newton tolerance and the
    transient's residue). The static start of the same run (start: equilibrium) is that equilibrium too
    (1 mm). The catenary system statics under the same force gives the same offset within 5 mm: the FE
    lines' 80 elements (the FE offset converges at second order, 20 -> 40 -> 80 elements: 35, 10 mm
    apart, so about 3 mm left; 0.2 mm measured). Without the current on the body it would not move."""
    n = 80
    still = static_system(build_system_fe(buoy(), env(0.0), n_elements=n)).body_position[0]
    # held at its still-water equilibrium; linear damping (on the body's own velocity, no steady force) for
    # the heave and rotations, where the current's drag is quadratic only
    system = buoy(position=tuple(still), linear_damping=np.diag([0, 0, 3e5, 1e9, 1e9, 1e9]).tolist())
    ds = run_system_dynamic(SimpleNamespace(environment=env(SPEED), system=system, name="current",
                                            analysis=SystemDynamicAnalysis(duration=600.0, time_step=0.2,
                                                                           output_interval=1.0, start="held",
                                                                           damping_ratio=0.5, rayleigh=(0.05, 0),
                                                                           n_elements=n)))
    q_end = body_pose(ds.sel(body="buoy").isel(time=-1))
    force = drag_at(q_end)
    # per axis |u| u: B2 u^2 (cos^2, sin^2) for a body that barely turns
    assert np.linalg.norm(force[:3]) == pytest.approx(1e5 * SPEED**2 * math.hypot(math.cos(HEADING) ** 2,
                                                                                  math.sin(HEADING) ** 2), rel=1e-3)
    loaded = static_system(build_system_fe(buoy(external_force=tuple(force), quadratic_damping=None), env(0.0),
                                           n_elements=n)).body_position[0]
    offset = loaded[:3] - still[:3]
    assert np.linalg.norm(offset[:2]) > 1.0
    np.testing.assert_allclose(q_end[:3], loaded[:3], atol=1e-3)
    # the static start in the current: the same equilibrium
    start = static_system(build_system_fe(system, env(SPEED), n_elements=n)).body_position[0]
    np.testing.assert_allclose(start[:3], loaded[:3], atol=1e-3)
    # the catenary statics: the same offset within the FE lines' discretisation
    free = solve_equilibrium(buoy(quadratic_damping=None), env(0.0)).body_position[0]
    drift = solve_equilibrium(buoy(quadratic_damping=None), env(0.0), external={"buoy": tuple(force)}).body_position[0]
    np.testing.assert_allclose(q_end[:3] - still[:3], drift[:3] - free[:3], atol=5e-3)

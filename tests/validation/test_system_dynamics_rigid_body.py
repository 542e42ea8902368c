"""Rigid-body rotation of a free body in ``system_dynamic``: the torque-free symmetric top.

A body whose moments of inertia about its centre of gravity are (I_t, I_t, I_3), with no moment on it,
keeps its angular momentum ``H = I_g w`` (global axes); its symmetry axis ``a = R e_z`` turns about ``H``
at the constant rate ``|H| / I_t`` on a cone of constant angle (Goldstein, Classical Mechanics, 3rd ed.,
section 5.6, the force-free symmetric top; Landau & Lifshitz, Mechanics, section 33). The rate needs the
gyroscopic moment ``w x (I w)``: without it ``I_g dw/dt = 0`` and the body turns rigidly about its
first angular velocity, at a rate that is not ``|H| / I_t``.

The body: 1e5 kg, (I_t, I_3) = (1e6, 2e6) kg m^2, centres of gravity and buoyancy at the reference
point, 1 kN net buoyancy, no waterplane, added mass or damping, held by one light rope (0.5 kg/m) tied
at its reference point: no moment acts on it.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from seacable.environment import Environment, SystemEnvironment
from seacable.line import Line, LineType
from seacable.mooring.motion import rotation_matrix
from seacable.system.dynamics import SystemDynamicAnalysis, build_system_fe, simulate_system, static_system
from seacable.system.model import MooringSystem

IT, I3, MASS = 1e6, 2e6, 1e5
RHO, DEPTH = 1025.0, 100.0
ENV = Environment(depth=DEPTH, water_density=RHO, gravity=9.81)
# a light rope without water loads (as tests/validation/test_system_dynamics.py)
ROPE = {"diameter": 0.02, "mass_per_length": 0.5, "axial_stiffness": 1e6, "drag_normal": 0.0, "added_mass_normal": 0.0}


def top(tilt):
    lt = LineType(**ROPE)
    body = {"kind": "free", "position": (0, 0, -50, tilt, 0, 0), "mass": MASS, "inertia": (IT, IT, I3),
            "volume": (MASS + 1000 / 9.81) / RHO}
    return MooringSystem(points={"anchor": {"kind": "fixed", "position": (0, 0, -DEPTH)},
                                 "eye": {"kind": "body", "body": "top", "position": (0, 0, 0)}},
                         bodies={"top": body},
                         lines={"rope": {"line": Line.single(lt, 49.9), "end_a": "anchor", "end_b": "eye",
                                         "n_elements": 5}})


def angular_velocity(q, qd):
    """w = E(q) qd[3:] for R = Rz(yaw) Ry(pitch) Rx(roll), (nt, 3)."""
    p, y = q[:, 4], q[:, 5]
    col0 = np.stack([np.cos(y) * np.cos(p), np.sin(y) * np.cos(p), -np.sin(p)], -1)
    col1 = np.stack([-np.sin(y), np.cos(y), 0 * y], -1)
    return col0 * qd[:, 3:4] + col1 * qd[:, 4:5] + np.array([0, 0, 1.0]) * qd[:, 5:6]


def spin(tilt=0.3, w0=0.5, dt=0.01, duration=20.0):
    """The top tilted by ``tilt`` in roll, set turning at ``w0`` about the vertical; its states."""
    system = top(tilt)
    fe = build_system_fe(system, ENV)
    st = static_system(fe)
    # angle rates of w = w0 e_z: yaw rate w0 (E's third column is e_z)
    r = simulate_system(fe, st, duration, dt, 0.05, analysis=SystemDynamicAnalysis(duration=duration),
                        body_velocity=[[0, 0, 0, 0, 0, w0]], tol=1e-8)
    q, qd = r.body_position[:, 0], r.body_velocity[:, 0]
    R = rotation_matrix(q[:, 3], q[:, 4], q[:, 5])
    Ig = R @ np.diag([IT, IT, I3]) @ np.swapaxes(R, -1, -2)
    H = np.einsum("tij,tj->ti", Ig, angular_velocity(q, qd))
    return r.time, R[:, :, 2], H


def precession_rate(t, a, h):
    """Rate [rad/s] at which the axis ``a`` (nt, 3) turns about the unit vector ``h``: slope of its azimuth."""
    e1 = np.cross(h, [1.0, 0, 0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(h, e1)
    phi = np.unwrap(np.arctan2(a @ e2, a @ e1))
    return np.polyfit(t, phi, 1)[0]


def test_torque_free_symmetric_top_precesses_at_H_over_It():
    """Tilted 0.3 rad and set turning at 0.5 rad/s about the vertical: H = I_g w at t = 0 (closed form
    below), then |H| constant within 1e-6 (the average-acceleration rule conserves it to the Newton
    tolerance and the (w dt)^2 order of the step; the rope's pull at the reference point has no moment),
    the axis on its cone (angle to H constant within 1e-5 rad), and the precession rate |H| / I_t = 0.967
    rad/s within 1e-5 relative (Newmark's phase error (W dt)^2 / 12 = 8e-6 at dt = 0.01 s; measured: |H|
    2.7e-7, cone 4.8e-6 rad, rate 6.5e-7, each about a third of its value at dt = 0.02 s). Leaving out the
    gyroscopic moment keeps |H| (the body then turns rigidly about the vertical) but opens the cone by 0.29
    rad and the rate is 0.5 rad/s, -49 %."""
    tilt, w0 = 0.3, 0.5
    t, a, H = spin(tilt, w0)
    # at t = 0: w = w0 e_z, the axis a0 = Rx(tilt) e_z; I_g w = I_3 (w.a0) a0 + I_t (w - (w.a0) a0)
    a0 = np.array([0, -math.sin(tilt), math.cos(tilt)])
    w = np.array([0, 0, w0])
    H0 = I3 * (w @ a0) * a0 + IT * (w - (w @ a0) * a0)
    np.testing.assert_allclose(H[0], H0, rtol=1e-12, atol=1e-9 * np.linalg.norm(H0))
    assert np.max(np.abs(np.linalg.norm(H, axis=1) / np.linalg.norm(H0) - 1)) < 1e-6
    h = H0 / np.linalg.norm(H0)
    cone = np.arccos(a @ h)
    assert np.ptp(cone) < 1e-5
    rate = precession_rate(t, a, h)
    assert rate == pytest.approx(np.linalg.norm(H0) / IT, rel=1e-5)


ORBITAL = Path(__file__).parent / "data" / "moordyn_decks" / "MoorDyn" / "tests" / "Mooring" / "body_tests" / "orbitalBody.txt"


@pytest.mark.parametrize("dt", [0.25, 0.125, 0.01])
def test_a_point_mass_body_orbits_its_centre_of_gravity(dt):
    """MoorDyn's orbitalBody deck (its test "Excentric body"), g = 0: body1 is a 40 kg point mass 10 m from the
    reference point (no inertia of its own about the centre of gravity), body2 the same mass as a rod through
    it. Set turning at w = 0.2 rad/s about x through the centre of gravity, the reference point orbits it on a
    10 m circle at w. Nothing turns the point mass about its centre of gravity, so its spin keeps w whatever
    its (regularised) inertia: roll = w t to round-off. The reference point's position is a state of its own
    whose circle the average-acceleration rule closes with its period error (w dt)^2 / 12 (radius and rate:
    2.08e-4 at dt = 0.25 s, measured 2.11e-4 and 2.8e-4; a quarter of it at half the step, order 2, asserted
    within 5 %); at dt = 0.01 s both are within MoorDyn's own 1e-6 (measured 3.4e-7, 4.4e-7; MoorDyn runs the
    deck at its dtM = 1e-3 s)."""
    import seacable as sc

    system, env = sc.load_case(ORBITAL).system()
    radius, w = 10.0, 0.2
    fe = build_system_fe(system, env)
    r = simulate_system(fe, static_system(fe, held=True, q=fe.q0), 10.0, dt, 0.25,
                        analysis=SystemDynamicAnalysis(duration=10.0), body_velocity=[[0, 0, radius * w, w, 0, 0]] * 2)
    for j in range(2):
        q = r.body_position[:, j]
        np.testing.assert_allclose(q[:, 3], w * r.time, rtol=0, atol=1e-12)
        d = q[:, :3] - [0.0, 0.0, 20.0]
        err_r = np.abs(np.linalg.norm(d, axis=1) / radius - 1).max()
        err_w = np.abs(np.unwrap(np.arctan2(d[1:, 2], d[1:, 1])) / r.time[1:] / w - 1).max()
        if dt < 0.1:
            assert err_r < 1e-6 and err_w < 1e-6
        else:
            assert err_r == pytest.approx((w * dt) ** 2 / 12, rel=0.05)
            assert err_w < 1.5 * (w * dt) ** 2 / 12


def test_a_point_mass_body_with_a_line_off_its_centre_of_gravity_is_refused():
    """The same point mass with a line tied 1 m from its centre of gravity: the line would turn it about an
    axis with no inertia; the dynamics refuse it naming the point, not with a LinAlgError."""
    from seacable.errors import InputError
    from seacable.system.dynamics import prepare_system_dynamic
    from seacable.system.case import SystemCase

    lt = LineType(**ROPE)
    system = MooringSystem(
        points={"anchor": {"kind": "fixed", "position": (0, 0, -DEPTH)},
                "eye": {"kind": "body", "body": "ball", "position": (1.0, 0, 0)}},
        bodies={"ball": {"kind": "free", "position": (0, 0, -50, 0, 0, 0), "mass": 40.0, "inertia": (0, 0, 0)}},
        lines={"rope": {"line": Line.single(lt, 49.9), "end_a": "anchor", "end_b": "eye", "n_elements": 5}})
    case = SystemCase(name="ball", environment=SystemEnvironment(depth=DEPTH, water_density=RHO, gravity=9.81), points=system.points, bodies=system.bodies, lines=system.lines,
                      analysis=SystemDynamicAnalysis(duration=1.0, start="held"))
    with pytest.raises(InputError, match=r"bodies\.ball: .*point eye would turn it about its centre of gravity"):
        prepare_system_dynamic(case)

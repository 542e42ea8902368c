"""The finite-element towed model's water loads, term by term, against closed forms (issue 37).

Each option of the tangential drag (``tangential_drag``: ``"common"``, ``1/2 rho C_dt pi d |u_t| u_t`` per metre,
the wetted perimeter as MoorDyn; ``"diameter"``, ``1/2 rho C_dt d |u_t| u_t``, C_dt referred to the diameter),
the normal drag in both directions across the line, and the added mass across and along it:

* a neutrally buoyant line towed straight along its axis at U with a body of drag area ``C_D A`` at its end: the
  line stays straight and its tension grows along it by the skin friction alone, ``T(s) = 1/2 rho C_D A U^2 +
  1/2 rho C_dt P U^2 s`` (``P = pi d`` or ``d``), ``s`` from the body (Morison drag of a cylinder along its
  axis; e.g. Hoerner, Fluid-Dynamic Drag, 1965, ch. 3, the cable's skin friction);
* a line held oblique to a 3-D flow: each node's force is ``1/2 rho d ds (C_dn |u_n| u_n + C_dt P/d |u_t| u_t)``
  with ``u_t = (u . t) t``, ``u_n = u - u_t`` (Morison's independence principle);
* each inner node's mass matrix is ``m ds I + rho A ds (C_an (I - t t^T) + C_at t t^T)``.

Line: d 0.03 m, C_dn 1.5, C_dt 0.01, C_an 1.0, C_at 0.3 (values chosen so that no two terms coincide:
the forms differ by pi; the tangential added mass by a factor 3.3 from the normal one).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import seacable as sc
from seacable.case import TowedBody
from seacable.mooring import kernel as K
from seacable.mooring.solver import Water
from seacable.towed.fe import steady_start, towed_system

RHO, G = 1025.0, 9.80665
D, CDN, CDT, CAN, CAT = 0.03, 1.5, 0.01, 1.0, 0.3
AREA = math.pi * D**2 / 4
STILL = Water(depth=None, density=RHO, gravity=G)
PERIMETER = {"common": math.pi * D, "diameter": D}


def _neutral(ea=1e9):
    """A line of d 0.03 m and no weight in water (its mass that of the water it displaces), EA ``ea`` [N]."""
    return sc.LineType(diameter=D, mass_per_length=RHO * AREA, weight_in_water=0.0, axial_stiffness=ea,
                       drag_normal=CDN, drag_tangential=CDT, added_mass_normal=CAN, added_mass_tangential=CAT)


def _loads(system, X, V, frame=(0.0, 0.0, 0.0)):
    """Node forces, node mass matrices and element tensions at positions X, velocities V, in the frame moving at
    ``frame`` [m/s] (the water streaming past at minus that)."""
    m = system.model
    env = m.env.copy()
    env[[K.E_FRAMEX, K.E_FRAMEY, K.E_FRAMEZ]] = frame
    n = X.shape[0]
    F, M, tension = np.zeros((n, 3)), np.zeros((n, 3, 3)), np.zeros(n - 1)
    K.loads(X, V, 0.0, *m.element_args(), m.fidx, env, m.cur_depth, m.cur_speed, False, m.sea, F, M, tension,
            np.zeros((0, 2 * m.bw + 1)), m.bw, 0.0, 0.0)
    return F, M, tension


@pytest.mark.parametrize("form", ["common", "diameter"])
def test_a_line_towed_along_its_axis_gains_its_skin_friction_as_tension(form):
    """200 m of neutrally buoyant line behind a body of no weight and C_D A 0.2 m^2, towed at 2.5 m/s along
    +x (and, to catch a sign, along -y): the steady tow is straight and level, each element's tension the closed
    form at its middle (the lumped drag of the nodes below it sums to exactly that), the tow point's force its
    value at s = L: 1/2 rho U^2 (C_D A + C_dt P L) = 641 N + 604 N (common) or 192 N (diameter). Tolerance 1e-6
    relative: the static solve's residual (1e-7 of the largest force, the tension being 1e9 times the strain);
    the two forms differ by 33 % at the top (pi on the skin friction), a sign error on it by 97 %."""
    U, L, n = 2.5, 200.0, 21
    body = TowedBody(mass=100.0, weight_in_water=0.0, drag_area=0.2, added_mass=10.0)
    system = towed_system(sc.Line.single(_neutral(), L), (0.0, 0.0, 0.0), STILL, n_nodes=n, body=body,
                          tangential_drag=form)
    q = 0.5 * RHO * CDT * PERIMETER[form] * U**2                       # skin friction per metre [N/m]
    drag = 0.5 * RHO * 0.2 * U**2
    s_mid = (np.arange(n - 1) + 0.5) * L / (n - 1)                        # element middles from the body [m]
    for heading in (0.0, -math.pi / 2):
        e = np.array([math.cos(heading), math.sin(heading), 0.0])
        X = steady_start(system, (0.0, 0.0, 0.0), U * e)
        # straight astern and level: every node on the line back from the tow point
        np.testing.assert_allclose(X - np.outer(X[:, :] @ e, e), 0.0, atol=1e-6)
        F, _, tension = _loads(system, X, np.zeros_like(X), U * e)
        np.testing.assert_allclose(tension, drag + q * s_mid, rtol=1e-6)
        np.testing.assert_allclose(F[-1], -(drag + q * L) * e, rtol=1e-6, atol=1e-6 * (drag + q * L))
    assert q * L == pytest.approx(603.77 if form == "common" else 192.19, rel=1e-4)


@pytest.mark.parametrize("form", ["common", "diameter"])
def test_an_oblique_line_in_a_3d_flow_takes_morison_drag_across_and_along(form):
    """A straight line along (1, 2, -2)/3 held in a flow (0.9, -0.4, 0.7) m/s (every component of u_n and u_t
    non-zero, across the line in both directions: horizontal and in the vertical plane): each inner node's force
    is ``1/2 rho d ds (C_dn |u_n| u_n + C_dt (P/d) |u_t| u_t)`` to round-off (1e-10), and the node moving with velocity
    v feels the water's velocity relative to it, ``u - v``."""
    L, n = 30.0, 7
    t = np.array([1.0, 2.0, -2.0]) / 3.0
    u = np.array([0.9, -0.4, 0.7])
    # EA 1e5 N: the elements' rounding of their unstretched length (1e-16) is 1e-11 N of tension, not 1e-7
    system = towed_system(sc.Line.single(_neutral(1e5), L), (0.0, 0.0, -10.0), STILL, n_nodes=n,
                          tangential_drag=form)
    s = np.linspace(0.0, L, n)
    X = np.array([0.0, 0.0, -40.0]) + s[:, None] * t
    ds = L / (n - 1)
    for v in (np.zeros(3), np.array([0.3, 0.5, -0.2])):
        F, _, _ = _loads(system, X, np.tile(v, (n, 1)), frame=-u)      # the frame moving at -u: water at +u
        r = u - v
        ut = (r @ t) * t
        un = r - ut
        want = 0.5 * RHO * D * ds * (CDN * np.linalg.norm(un) * un + CDT * PERIMETER[form] / D * np.linalg.norm(ut)
                                     * ut)
        # inner nodes: two half elements' drag (their tension: none, the line at its unstretched length)
        np.testing.assert_allclose(F[1:-1], np.tile(want, (n - 2, 1)), rtol=1e-10, atol=1e-10 * np.abs(want).max())


def test_the_node_mass_holds_the_added_mass_across_and_along_the_line():
    """Each inner node of an oblique line: ``M = m ds I + rho A ds (C_an (I - t t^T) + C_at t t^T)`` to round-off
    (C_an 1.0 across, C_at 0.3 along: a coefficient read for the other direction is off by 70 %), its end
    nodes half of it (the body's mass and added mass added at node 0)."""
    L, n = 30.0, 7
    t = np.array([2.0, -1.0, 2.0]) / 3.0
    body = TowedBody(mass=100.0, weight_in_water=50.0, drag_area=0.2, added_mass=40.0)
    system = towed_system(sc.Line.single(_neutral(1e5), L), (0.0, 0.0, -10.0), STILL, n_nodes=n, body=body)
    s = np.linspace(0.0, L, n)
    X = np.array([0.0, 0.0, -40.0]) + s[:, None] * t
    _, M, _ = _loads(system, X, np.zeros_like(X))
    ds = L / (n - 1)
    P = np.outer(t, t)
    inner = RHO * AREA * ds * np.eye(3) + RHO * AREA * ds * (CAN * (np.eye(3) - P) + CAT * P)
    np.testing.assert_allclose(M[1:-1], np.tile(inner, (n - 2, 1, 1)), rtol=1e-12)
    np.testing.assert_allclose(M[0], 0.5 * inner + (100.0 + 40.0) * np.eye(3), rtol=1e-12)


def test_an_attachment_in_a_wave_takes_the_froude_krylov_and_added_mass_force_of_its_volume():
    """A clump (0.4 m^3, added mass 150 kg, no drag) on a line without water loads, 10 m deep in a regular
    deep-water wave (H 2 m, T 8 s) at the instant its horizontal acceleration peaks there (velocity zero): the
    force on its node is ``(rho V + A) a_w`` (Froude-Krylov plus added mass; Morison's inertia term with
    ``C_m = 1 + A / (rho V)``), ``a_w`` from Airy theory; its node's mass ``m + A``. To round-off (1e-10): the
    Froude-Krylov part left out is 73 % of the force, the added mass 27 %."""
    from seacable.mooring.network import network_from_line
    from seacable.mooring.solver import MooringModel
    from seacable.waves import airy_kinematics_array

    H, T = 2.0, 8.0
    bare = sc.LineType(diameter=0.01, mass_per_length=1.0, weight_in_water=0.0, axial_stiffness=1e6,
                       drag_normal=0.0, drag_tangential=0.0, added_mass_normal=0.0, added_mass_tangential=0.0)
    clump = sc.PointMass(s=10.0, mass=900.0, volume=0.4, weight_in_water=0.0, added_mass=150.0)
    net = network_from_line(sc.Line.single(bare, 20.0, attachments=(clump,)), (-10.0, 0.0, -10.0),
                            (10.0, 0.0, -10.0), water_density=RHO, gravity=G, n_elements=2)
    model = MooringModel(net, Water(depth=None, density=RHO, gravity=G, wave_height=H, wave_period=T))
    X = net.position
    t = -T / 4                                   # theta = k x - w t = pi / 2 at x = 0: a_x at its peak
    F, M, _, _ = model.evaluate(X, np.zeros_like(X), np.zeros_like(X), t=t, waves=True)
    a = airy_kinematics_array(0.0, 0.0, -10.0, t, height=H, period=T, depth=None, gravity=G).acceleration
    assert abs(a[0]) > 0.3                                                   # 0.37 m/s^2
    # and the line's own Froude-Krylov force, rho A (1 + C_a) over its two half elements (C_a 0): 0.26 N of 184 N
    line = RHO * math.pi * 0.01**2 / 4 * 10.0
    np.testing.assert_allclose(F[1], (RHO * 0.4 + 150.0 + line) * np.asarray(a), rtol=1e-10, atol=1e-10)
    np.testing.assert_allclose(np.diag(M[1]), 1.0 * 10.0 + 900.0 + 150.0, rtol=1e-12)

"""Laid cable sliding on the seabed against Coulomb friction (``laying_dynamic`` with ``laid_cable: sliding``).

The compiled step holds a node on the seabed in its tangent plane (the seabed's reaction eliminated,
``seacable.laying.kernel._on_plane``) and adds its friction ``-mu R d / max(|d|, slip)`` to the Newton system, ``d``
its offset from the point it sticks to (dragged along as it slides: ``seacable.laying.kernel.drag_anchors``).
Checked against closed forms:

* a straight laid cable pulled along its axis: the tension falls from the pull at ``mu w`` per metre over
  the length ``T_0 / (mu w)`` that slides, and an elastic cable stretched by ``delta`` at its end carries
  ``T_0 = sqrt(2 mu w EA delta)`` (the stretch is the integral of ``T / EA`` over the sliding length);
* a laid arc of radius ``rho`` under a tension T: held while ``T / rho <= mu w``, and sliding inward at
  ``(T / rho - mu w) / (m + m_a)`` when the pull exceeds the friction (the added mass across the cable);
* a slack cable lying down a slope ``beta``: held while ``tan(beta) <= mu``, and sliding down at
  ``w (sin(beta) - mu cos(beta)) / (m + m_a,t)`` (the added mass along the cable), the seabed taking
  ``w cos(beta)`` (:func:`seacable.laying.solver.seabed_reaction`).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.laying import kernel as K
from seacable.laying.solver import props_row, seabed_reaction

MASS, W, MU = 4.0, 20.0, 0.5           # kg/m, N/m in water, Coulomb's coefficient


def _run(pos, L, props, T, act, normal, grip, slip, dt, steps, end_velocity=None, tol=1e-10):
    """March the step ``steps`` times with both end nodes fixed (the last one moving at ``end_velocity``);
    every node between them rests on the seabed, stuck where it starts, and slides ``slip`` [m] before the
    friction reaches its limit."""
    npt, dim = pos.shape
    contact = np.ones(npt, dtype=np.int64)
    contact[0] = contact[-1] = 0
    anchor = pos.copy()
    vel = np.zeros_like(pos)
    move = np.zeros(dim) if end_velocity is None else np.asarray(end_velocity, float)
    for _ in range(steps):
        new_pos, new_vel = np.zeros_like(pos), np.zeros_like(pos)
        status, _, res = K.implicit_step(pos, vel, pos[-1] + move * dt, L, np.zeros(npt - 1, dtype=np.int64), props,
                                         np.zeros((npt, 4)), np.zeros(1), np.zeros((1, dim)), 1025.0, dt, T, act,
                                         1e-12, (contact, normal, grip, anchor, slip), tol, 50, 4 * npt, new_pos,
                                         new_vel)
        assert status == K.STEP_OK, (status, res)
        K.drag_anchors(new_pos, contact, normal, anchor, slip)
        pos, vel = new_pos, new_vel
    return pos, vel


def test_pulled_laid_cable_takes_the_pull_off_at_mu_w_per_metre():
    """200 m of elastic cable (EA 1 MN) on a flat seabed, its end pulled 0.05 m along its axis at 1 mm/s:
    T_0 = sqrt(2 mu w EA delta) = 1000 N at the end, falling at mu w = 10 N/m to zero 100 m back. The top
    segment's tension is its middle's, T_0 - mu w l / 2 = 995 N. Tolerances: the friction's slip distance is
    1e-5 m, 2e-4 of the pull, and the nodes at the end of the sliding length, within it, hold a little less
    than mu w (measured 4e-5 of T_0); the slope is fitted over the segments carrying 20 % to 95 % of T_0
    (measured 9.9943 N/m: mu w per metre of unstretched cable, 10 / (1 + T / EA) per metre of the stretched
    one)."""
    n, seg, ea, delta = 200, 1.0, 1e6, 0.05
    props = np.array([props_row(MASS, W, 0.05, 1.2, 0.0, 2.0, 0.0, 1.0 / ea)])
    pos = np.column_stack([np.arange(n + 1) * seg, np.full(n + 1, -100.0)])
    normal = np.tile([0.0, 1.0], (n + 1, 1))
    grip = np.full(n + 1, MU * W * seg)
    T, act = np.zeros(n), np.ones(n, dtype=np.int64)
    speed, dt = 1e-3, 0.5
    pos, _ = _run(pos, np.full(n, seg), props, T, act, normal, grip, 1e-5, dt, round(delta / speed / dt),
                  end_velocity=(speed, 0.0))
    t0 = math.sqrt(2.0 * MU * W * ea * delta)
    assert T[-1] == pytest.approx(t0 - 0.5 * MU * W * seg, rel=3e-4)
    x = 0.5 * (pos[1:, 0] + pos[:-1, 0])
    fit = (T > 0.2 * t0) & (T < 0.95 * t0)
    assert np.polyfit(x[fit], T[fit], 1)[0] == pytest.approx(MU * W, rel=2e-3)
    # beyond the sliding length (5 % on, for the regularised front) no tension is left (measured 0.054 N, 5e-5 of
    # T_0, falling by 2.3 a metre) and the cable has not moved
    far = x < n * seg - 1.05 * t0 / (MU * W)
    assert np.all(T[far] < 1e-4 * t0)
    np.testing.assert_allclose(pos[:n][far, 0], np.arange(n)[far] * seg, rtol=0, atol=1e-6)


@pytest.mark.parametrize("tension", [900.0, 1200.0])
def test_laid_arc_under_tension_slides_inward_only_beyond_the_friction(tension):
    """An arc of radius 100 m of elastic cable (EA 10 kN) on a flat seabed, both ends held, stretched to a tension
    T. Its pull toward the centre, T (1 + T / EA) / rho per metre of cable, against the friction mu w = 10 N/m:
    at 900 N (9.9 N/m) the middle node is held, within the friction's slip distance 1e-5 m; at 1200 N
    (13.44 N/m) it slides inward at (T (1 + T/EA) / rho - mu w) / (m + m_a) t after t = 0.1 s (0.0573 m/s). No drag
    here: the test is the friction's. Tolerance 1 %: in 0.1 s the arc moves 3 mm, which relaxes the tension by
    0.3 %, and the ends' influence travels 1.3 m (a segment)."""
    n, rho, ea, added = 40, 100.0, 1e4, 2.0
    theta = np.linspace(0.0, 0.4, n + 1)
    pos = np.column_stack([rho * np.sin(theta), rho * (1.0 - np.cos(theta)), np.full(n + 1, -50.0)])
    L = np.linalg.norm(np.diff(pos, axis=0), axis=1) / (1.0 + tension / ea)
    props = np.array([props_row(MASS, W, 0.05, 0.0, 0.0, added, 0.0, 1.0 / ea)])
    normal = np.tile([0.0, 0.0, 1.0], (n + 1, 1))
    grip = np.zeros(n + 1)
    grip[1:-1] = MU * W * 0.5 * (L[1:] + L[:-1])
    T, act = np.full(n, tension), np.ones(n, dtype=np.int64)
    dt, steps, slip = 0.02, 5, 1e-5
    end, vel = _run(pos, L, props, T, act, normal, grip, slip, dt, steps)
    m = n // 2
    inward = np.array([-pos[m, 0], rho - pos[m, 1], 0.0])
    inward /= np.linalg.norm(inward)
    pull = tension * (1.0 + tension / ea) / rho
    if pull <= MU * W:
        # held: within the friction's spring, (T / rho) / (mu w) of the slip distance (measured 0.99)
        assert np.linalg.norm(end[m] - pos[m]) <= pull / (MU * W) * slip * (1.0 + 1e-6)
    else:
        assert vel[m] @ inward == pytest.approx((pull - MU * W) / (MASS + added) * steps * dt, rel=1e-2)
        assert abs(vel[m, 2]) < 1e-12              # on the seabed


@pytest.mark.parametrize("slope_deg", [20.0, 35.0])
def test_slack_cable_on_a_slope_slides_down_only_beyond_the_friction_angle(slope_deg):
    """A slack cable lying down a plane slope (segments half as long again as their chords, for the 0.35 m it slides): the seabed takes
    w cos(beta) (seabed_reaction); held at 20 deg (tan 0.36 < mu = 0.5), sliding down along the cable at
    w (sin(beta) - mu cos(beta)) / (m + m_a,t) at 35 deg (after 1 s: 0.689 m/s). Tolerance: 1e-9, the backward-Euler
    step of a constant force is exact (no drag here)."""
    beta = math.radians(slope_deg)
    n, seg, added_t = 10, 1.0, 0.5
    down = np.array([math.cos(beta), -math.sin(beta)])
    pos = np.array([k * seg * down for k in range(n + 1)]) + np.array([0.0, -100.0])
    normal = np.tile([math.sin(beta), math.cos(beta)], (n + 1, 1))
    L = np.full(n, 1.5 * seg)
    props = np.array([props_row(MASS, W, 0.05, 0.0, 0.0, 1.0, added_t, 0.0)])
    T, act = np.zeros(n), np.zeros(n, dtype=np.int64)
    reaction = seabed_reaction(pos[:-2], pos[1:-1], pos[2:], T[:-1], T[1:], W * 0.5 * (L[1:] + L[:-1]), normal[1:-1])
    np.testing.assert_allclose(reaction, W * 1.5 * seg * math.cos(beta), rtol=1e-12)
    grip = np.zeros(n + 1)
    grip[1:-1] = MU * reaction
    dt, steps, slip = 0.1, 10, 1e-5
    end, vel = _run(pos, L, props, T, act, normal, grip, slip, dt, steps)
    assert np.all(act == 0)
    if math.tan(beta) <= MU:
        # held: the weight down the slope stretches the friction's spring by tan(beta) / mu of the slip distance
        # (to 1e-3: the spring and the node's mass still ring after 1 s; measured 1e-5)
        stretch = np.broadcast_to(math.tan(beta) / MU * slip * down, (n - 1, 2))
        np.testing.assert_allclose(end[1:-1] - pos[1:-1], stretch, rtol=1e-3, atol=0)
    else:
        a = W * (math.sin(beta) - MU * math.cos(beta)) / (MASS + added_t)
        np.testing.assert_allclose(vel[1:-1] @ down, a * steps * dt, rtol=1e-9)
        np.testing.assert_allclose(vel[1:-1] @ normal[0], 0.0, atol=1e-12)


def test_seabed_reaction_takes_the_lift_of_the_bottom_segment():
    """A node on a flat seabed with the bottom segment rising at 30 deg under 100 N and the laid segment
    horizontal under 80 N: the seabed takes W - 100 sin(30 deg); pulled harder than it weighs, nothing (the
    lift-off)."""
    below, at, above = np.array([[-1.0, 0.0]]), np.array([[0.0, 0.0]]), np.array([[math.sqrt(3.0), 1.0]])
    n = np.array([[0.0, 1.0]])
    r = seabed_reaction(below, at, above, np.array([80.0]), np.array([100.0]), np.array([70.0]), n)
    assert r[0] == pytest.approx(70.0 - 50.0, rel=1e-12)
    assert seabed_reaction(below, at, above, np.array([80.0]), np.array([200.0]), np.array([70.0]), n)[0] == 0.0

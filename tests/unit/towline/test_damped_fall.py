"""A towline falling in water with its joint dampers on (issue 37, "a wrong answer is never silent").

A straight line held level 10 m under water at both ends and let go from rest falls in its middle as a
free body until the held ends' influence arrives (:mod:`test_added_mass`). Its elements fall together:
no joint opens, so a joint damper, which acts on the relative velocity of the two points it joins,
carries no force, and the fall is the closed form whatever the damping ratio:

* without drag, ``a = g (mu - rho A) / (mu + C_a rho A)`` (weight less buoyancy over mass plus added mass);
* with drag, ``(mu + C_a rho A) dv/dt = w - 1/2 rho d C_D v |v|``: ``v(t) = v_t tanh(a t / v_t)``, the
  terminal velocity ``v_t = sqrt(w / (1/2 rho d C_D))`` where the drag carries the weight in water ``w``.

The kernel used to take each joint's damper implicitly in the element's own velocity only, the
neighbour's velocity from the step's start: elements accelerating together then each felt ``c dt a`` of
damper per joint, a false inertia that made the line fall 8.7 % slower at the default zeta = 0.5 and
step, for any element count. The dampers are now implicit along the whole line (a block tri-diagonal
solve per step), and the fall is the closed form to the time step's first-order error.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.towline.solver import TowlineModel, initial_state, simulate

MU, D, RHO, DEPTH, CA, CD = 3.0, 0.05, 1025.0, 10.0, 1.0, 1.2
G = 9.80665
RHO_A = RHO * math.pi * D * D / 4
W = (MU - RHO_A) * G            # weight in water per length [N/m]
A0 = W / (MU + CA * RHO_A)      # the first acceleration [m/s^2]
VT = math.sqrt(W / (0.5 * RHO * D * CD))  # terminal velocity [m/s]


def _fall(n, duration, *, drag, time_step=None):
    """The middle element's vertical velocity [m/s] after ``duration`` [s] of a line of n 1 m elements, zeta 0.5."""
    model = TowlineModel(n_elements=n, length=float(n), diameter=D, mass_per_length=MU, axial_stiffness=1e7,
                         added_mass=CA, drag_normal=CD, damping_ratio=0.5, bending_damping_ratio=0.0, drag=drag,
                         water_density=RHO, gravity=G, held=True, held_tow_point_height=-DEPTH)
    point = np.array([0.0, 0.0, -DEPTH])

    def held(t):
        t = np.atleast_1d(t)
        return np.broadcast_to(point, (t.size, 3)).copy(), np.zeros((t.size, 3))

    run = simulate(model, held, duration, duration / 2, initial_state(model, point, start="straight"),
                   time_step=time_step)
    k = n // 2
    return float((run.final.E[k] @ run.final.nu[k])[2]), run.time_step


@pytest.mark.parametrize("n", [41, 81, 161])
def test_a_damped_line_falls_as_its_weight_buoyancy_and_added_mass_give(n):
    v, _ = _fall(n, 0.05, drag=False)
    # symplectic Euler adds a dt to the velocity exactly under a constant force: what is left is the held ends'
    # influence (measured 6e-8 on 41 elements, 7e-10 on 161); 1e-6. Before: 8.7 % slow (c dt per joint)
    assert v == pytest.approx(-A0 * 0.05, rel=1e-6)


@pytest.mark.parametrize("n", [81, 161])
def test_a_damped_line_in_drag_falls_towards_its_terminal_velocity(n):
    t = 0.5  # 94 % of the terminal velocity: drag and inertia both matter
    v, dt = _fall(n, t, drag=True)
    exact = -VT * math.tanh(A0 * t / VT)
    # the drag is explicit: a first-order error, measured 0.25 dt [m/s per s of step] (test below), 1.1e-4 m/s
    # at the stable step (4.4e-4 s), plus 8e-6 m/s of the held ends' influence on 81 elements; 3e-4 m/s (6e-4
    # relative). The false inertia's 8.7 % slowed this fall by 2 %
    assert abs(v - exact) < 0.7 * dt
    assert abs(v - exact) < 6e-4 * abs(exact)


def test_the_damped_fall_converges_at_first_order_in_the_step():
    """Symplectic Euler with the drag explicit and the dampers backward Euler: first order in dt. The
    successive differences of three runs at dt, dt/2 and dt/4 halve (order 1 +- 0.1), and the Richardson
    extrapolation ``2 v(dt/4) - v(dt/2)`` meets the closed form to the held ends' influence (8e-6 m/s on 81
    elements at 0.5 s), far below the step's error at dt (1.3e-4 m/s)."""
    t = 0.5
    v = [_fall(81, t, drag=True, time_step=t / m)[0] for m in (1000, 2000, 4000)]
    order = math.log2((v[0] - v[1]) / (v[1] - v[2]))
    assert order == pytest.approx(1.0, abs=0.1)
    exact = -VT * math.tanh(A0 * t / VT)
    assert abs(2 * v[2] - v[1] - exact) < 2e-5
    assert abs(v[0] - exact) > 5e-5  # the step's error is there to be removed

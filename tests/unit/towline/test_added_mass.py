"""The towline's added mass (issue 17, "tests that catch wrong physics").

A straight line held level 10 m under water at both ends and let go from rest, without drag and
joint damping, falls in its middle as a free body: each element's vertical acceleration is its
weight less buoyancy over its mass plus the added mass across it (paper 003's ``M_z = m + m_a``,
``m_a = C_a rho A l``),

    a = g (mu - rho A) / (mu + C_a rho A),

until the held ends' influence, which spreads from them through the pins, arrives. The symplectic
Euler step adds ``a dt`` to the velocity exactly under a constant force, so the middle element's
velocity is ``a t`` to round-off; what is left is that spreading (relative 2e-10 after 0.05 s in the
middle of 161 elements; 1e-4 on 41 elements at 0.1 s), far below the added mass's effect (a is 1.67
times smaller with C_a = 1 than without added mass; 1 % of C_a moves it by 0.4 %).

The joint dampers are off here (``damping_ratio = 0``); with them on, the same fall is checked in
:mod:`test_damped_fall` (the dampers, implicit along the line, carry no force while the elements fall
together).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.towline.solver import TowlineModel, initial_state, simulate

MU, D, RHO, DEPTH = 3.0, 0.05, 1025.0, 10.0


def _fall(added_mass, n=161, duration=0.05):
    model = TowlineModel(n_elements=n, length=float(n), diameter=D, mass_per_length=MU, axial_stiffness=1e7,
                         added_mass=added_mass, damping_ratio=0.0, bending_damping_ratio=0.0, drag=False,
                         water_density=RHO, held=True, held_tow_point_height=-DEPTH)
    point = np.array([0.0, 0.0, -DEPTH])

    def held(t):
        t = np.atleast_1d(t)
        return np.broadcast_to(point, (t.size, 3)).copy(), np.zeros((t.size, 3))

    run = simulate(model, held, duration, duration / 2, initial_state(model, point, start="straight"))
    k = n // 2
    return float((run.final.E[k] @ run.final.nu[k])[2]) / duration, model.gravity


@pytest.mark.parametrize("ca", [1.0, 0.5])
def test_a_submerged_element_accelerates_as_its_mass_plus_added_mass(ca):
    accel, g = _fall(ca)
    rho_a = RHO * math.pi * D * D / 4
    expected = -g * (MU - rho_a) / (MU + ca * rho_a)
    # 1e-6: the spreading from the held ends (2e-10 measured); the added mass changes a by 40-67 %
    assert accel == pytest.approx(expected, rel=1e-6)
    assert abs(expected / (-g * (MU - rho_a) / MU) - 1) > 0.2

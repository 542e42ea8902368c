"""System statics of a pinned prescribed body (MoorDyn's CoupledPinned): its reference point follows
the vessel (held at ``position`` in statics) and its rotations are free: solved for moment equilibrium
about the pin (issue 18). Closed forms (moment balance about the pin):

- the lever of ``test_system_statics``: a vertical rope at arm a holds a weight at arm c: T = W c / a;
- a pendulum hung from the vessel: a body point at depth a below the pin pushed sideways by a constant
  horizontal force F, the weight W at depth c: tan(theta) = F a / (W c).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.environment import Environment
from seacable.line import Line
from seacable.system.statics import examples as ex
from seacable.system.model import Body, MooringSystem, SystemLine, SystemPoint
from seacable.system.statics import solve_equilibrium


def test_a_coupled_pinned_lever_balances_its_moment_about_the_pin():
    """As the free pinned lever: T = W c / a = 3/8 W; the reference point stays where it is given.
    Not a free body of the result (no stiffness block). Exact for a vertical rope (it tilts ~1e-4 rad, a
    1e-8 effect); Newton to 1e-8 of the force scale: 1e-6 relative."""
    body = Body(kind="prescribed", pinned=True, mass=2000.0, center_of_gravity=(3.0, 0.0, 0.0),
                position=(0.0, 0.0, -20.0, 0.0, 0.0, 0.0))
    system = MooringSystem(points={"top": SystemPoint(kind="fixed", position=(8.0, 0.0, -10.0)),
                                   "p": SystemPoint(kind="body", body="b", position=(8.0, 0.0, 0.0))},
                           bodies={"b": body}, lines={"l": SystemLine(line=Line.single(ex.BUOY_ROPE, 9.99),
                                                                      end_a="p", end_b="top")})
    env = Environment(depth=100.0)
    eq = solve_equilibrium(system, env)
    assert eq.end_a_tension[0] == pytest.approx(2000.0 * env.gravity * 3.0 / 8.0, rel=1e-6)
    assert np.array_equal(eq.body_position[0][:3], [0.0, 0.0, -20.0])
    assert abs(eq.body_position[0][4]) > 1e-6               # it turned (pitch) to stretch the rope
    assert eq.free_body_names == [] and eq.stiffness.shape == (0, 0)


def test_a_coupled_pinned_pendulum_swings_to_its_moment_balance():
    """A 5 t body hung from the vessel at (10, 5, -5), its weight 4 m below the pin, a point 10 m below the
    pin pushed by 10 kN in x (a constant point force), a line from the pin itself to an anchor (no moment
    about the pin). Pitch = -atan(F a / (W c)) = -27.0 deg (the bottom swings to +x); the spin about the body
    axis through the pin is indeterminate (held). Newton to 1e-10 of the force scale: 1e-8 relative."""
    W, c, F, a = 5000.0 * 9.80665, 4.0, 1e4, 10.0
    body = Body(kind="prescribed", pinned=True, mass=5000.0, center_of_gravity=(0.0, 0.0, -c),
                position=(10.0, 5.0, -5.0, 0.0, 0.0, 0.0))
    system = MooringSystem(
        points={"pin": SystemPoint(kind="body", body="b", position=(0.0, 0.0, 0.0)),
                "push": SystemPoint(kind="body", body="b", position=(0.0, 0.0, -a), external_force=(F, 0.0, 0.0)),
                "anchor": SystemPoint(kind="fixed", position=(10.0, -95.0, -100.0))},
        bodies={"b": body}, lines={"l": SystemLine(line=Line.single(ex.BUOY_CHAIN, 150.0), end_a="anchor",
                                                     end_b="pin")})
    eq = solve_equilibrium(system, Environment(water_density=1025.0, gravity=9.80665, depth=100.0), tol=1e-10)
    q = eq.body_position[0]
    assert np.array_equal(q[:3], [10.0, 5.0, -5.0])
    assert q[4] == pytest.approx(-math.atan(F * a / (W * c)), rel=1e-8)
    assert q[3] == pytest.approx(0.0, abs=1e-9)
    assert len(eq.indeterminate) == 1

"""System statics: a point above the water weighs its dry weight (issue 18).

A point (a clump, a buoy, an attachment) is a point: its buoyancy rho g V switches off at z = 0
(no partial immersion of a finite volume). Closed forms (statically determinate hanging lines):

- a weight hanging on a rope from a point 20 m above the water: the rope's lower end carries m g
  (not (m - rho V) g); the same weight hung below the surface carries (m - rho V) g;
- a buoy on a vertical rope stretched from an anchor straight below it, whose buoyancy would lift
  it out of the water and whose dry weight would not hold it there: it floats at z = 0, partly
  immersed (the surface takes the difference), and the rope's tension is the vertical elastic
  line's closed form for the span to z = 0.
"""

from __future__ import annotations

import pytest

from seacable.environment import Environment
from seacable.line import Line, LineType
from seacable.system.model import MooringSystem, SystemLine, SystemPoint
from seacable.system.statics import solve_equilibrium

ENV = Environment(depth=100.0)
RHO, G = ENV.water_density, ENV.gravity


def _hang(top_z, length, rope, mass, volume):
    return MooringSystem(points={"top": SystemPoint(kind="fixed", position=(0.0, 0.0, top_z)),
                                 "w": SystemPoint(kind="free", position=(0.0, 0.0, top_z - length), mass=mass,
                                                  volume=volume)},
                         lines={"l": SystemLine(line=Line.single(rope, length), end_a="w", end_b="top")})


def test_a_point_above_the_water_weighs_its_dry_weight():
    """1000 kg of 0.5 m^3 on a 10 m rope (EA 1e10 N: stretch 1e-6 relative). From 20 m up it hangs in the
    air: the rope's lower end carries m g = 9807 N (its buoyancy, 5026 N, is gone), the top m g plus the
    rope's dry weight. From 5 m up it hangs 5 m under water: (m - rho V) g below. The Newton tolerance is
    1e-8 of the ~1e4 N force scale: 1e-7 relative."""
    rope = LineType(name="stiff", diameter=0.08, mass_per_length=6.0, axial_stiffness=1e10)
    m, V = 1000.0, 0.5
    eq = solve_equilibrium(_hang(20.0, 10.0, rope, m, V), ENV)
    assert eq.point_position[1, 2] == pytest.approx(10.0, abs=1e-4)      # stretch T L / EA = 1e-5 m
    assert eq.end_a_tension[0] == pytest.approx(m * G, rel=1e-7) and eq.surfaced == []
    assert eq.end_b_tension[0] == pytest.approx(m * G + 10.0 * rope.mass_per_length * G, rel=1e-7)
    eq = solve_equilibrium(_hang(5.0, 10.0, rope, m, V), ENV)
    assert eq.point_position[1, 2] == pytest.approx(-5.0, abs=1e-4)
    assert eq.end_a_tension[0] == pytest.approx((m - RHO * V) * G, rel=1e-7)


def test_a_buoy_whose_buoyancy_lifts_it_out_floats_at_the_surface():
    """A 200 kg buoy of 1 m^3 (net buoyancy (rho V - m) g = 8.1 kN) on a 50 m rope (EA 1e7 N, 20 N/m in
    water: its weight, 1 kN, cannot hold the buoy down) from an anchor on the seabed 50.01 m straight below z = 0. At z = 0 the rope pulls it down by
    T = EA (50.01 / 50 - 1) + w L / 2 = 2.5 kN (the vertical elastic line, exact for constant EA): immersed it
    rises, in the air its dry weight (2 kN) and the rope pull it down. It stops at z = 0 (a point's
    buoyancy switches there; it is held as a point on the seabed is, the surface taking the difference:
    partly immersed), and the rope is that vertical line: 1e-9 relative (the point's z is held at 0
    exactly; Newton converges on its x, y)."""
    w = 20.0
    rope = LineType(name="rope", diameter=0.05, mass_per_length=w / G + RHO * 0.25 * 3.141592653589793 * 0.05**2,
                    weight_in_water=w, axial_stiffness=1e7)
    m, V = 200.0, 1.0
    system = MooringSystem(points={"a": SystemPoint(kind="fixed", position=(0.0, 0.0, -50.01)),
                                   "b": SystemPoint(kind="free", position=(0.0, 0.0, -1.0), mass=m, volume=V)},
                           lines={"l": SystemLine(line=Line.single(rope, 50.0), end_a="a", end_b="b")})
    T = 1e7 * (50.01 / 50.0 - 1.0) + w * 50.0 / 2
    assert (RHO * V - m) * G > T > -m * G            # immersed it rises, dry it falls: it floats
    eq = solve_equilibrium(system, Environment(depth=50.01))      # the anchor on the seabed
    assert eq.point_position[1, 2] == 0.0 and eq.surfaced == ["b"]
    assert eq.end_b_tension[0] == pytest.approx(T, rel=1e-9)

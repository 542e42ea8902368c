"""Ties to the seabed (:mod:`seacable.ties`) against closed forms: tethers and clamps in the mooring
finite-element line, statics and dynamics.

* A tether pulling a straight taut line: two springs in series, ``T = (D - L - L0) / (L / EA + L0 / EA_t)``.
* A slack tether (its anchor nearer than its length) exerts no force: the line's equilibrium is the untethered one.
* A buoy on a tether below a vertical cable: the force balance at the junction, ``T_t = T_c + B``, with the
  cable's stretch under its own weight and the tether's adding up to the gap between the fixed points.
* A rigid clamp's reaction is the sum of the end forces of the two lines it divides the line into.
* A buoy held by a vertical tether oscillates in heave at ``omega^2 = k / m``: the tether's EA / L0 plus the
  taut cable's geometric stiffness ``2 T / l``, over its mass, added mass and the cable's half elements; the
  amplitude is conserved (Newmark's average acceleration conserves a linear system's energy).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.line import Line, LineType, PointMass
from seacable.mooring.network import network_from_line
from seacable.mooring.outputs import tether_tension
from seacable.mooring.run import line_end_forces
from seacable.mooring.solver import MooringModel, Water, simulate, static_equilibrium
from seacable.ties import Clamp, SeabedPoint, Tether

RHO, G = 1025.0, 9.81


def _neutral(diameter: float, axial_stiffness: float, **kwargs) -> LineType:
    """A line type of no weight in water (its mass the water it displaces)."""
    return LineType(diameter=diameter, mass_per_length=RHO * math.pi / 4 * diameter**2,
                    axial_stiffness=axial_stiffness, **kwargs)


def _tether(s, anchor, ea, length, **kwargs):
    return Tether(s=s, anchor=SeabedPoint(x=anchor[0], y=anchor[1], z=anchor[2]), axial_stiffness=ea,
                  length=length, **kwargs), tuple(float(v) for v in anchor)


def test_tether_and_line_in_series():
    """A 100 m line (EA 1 MN) from a fixed point, its free end pulled by a 50 m tether (EA 2 MN) anchored 160 m
    away: 10 m of stretch shared as by two springs in series, T = 10 / (100 / 1e6 + 50 / 2e6) = 80 kN, the line's
    end at 100 (1 + T / EA) = 108 m. Measured 3e-12 relative (the Newton tolerance 1e-12 of the largest force);
    1e-9 asserted. A tether at half its stiffness or its length read as the stretched one fails by percents."""
    line = Line.single(_neutral(0.1, 1e6), 100.0)
    net = network_from_line(line, (0, 0, -50.0), (100.0, 0, -50.0), water_density=RHO, gravity=G, n_elements=10,
                            end_b="free", ties=(_tether(100.0, (160.0, 0.0, -50.0), 2e6, 50.0),))
    state = static_equilibrium(MooringModel(net, Water(density=RHO, gravity=G)), tol=1e-12)
    T = 10.0 / (100.0 / 1e6 + 50.0 / 2e6)
    assert state.tension == pytest.approx(np.full(10, T), rel=1e-9)
    assert state.position[-1, 0] == pytest.approx(100.0 * (1 + T / 1e6), rel=1e-12)
    assert tether_tension(net, state.position) == pytest.approx([T], rel=1e-9)


def test_slack_tether_exerts_no_force():
    """A taut line between two held points, tethered at its middle node to a point nearer than the tether's
    length (it would have to push): the equilibrium is the untethered line's to the bit and the tether's tension
    0. A tether carrying compression (EA (l / L0 - 1) < 0 applied) would pull the node 2 m towards its anchor."""
    line = Line.single(LineType(diameter=0.1, mass_per_length=20.0, axial_stiffness=1e7), 100.0)
    args = {"water_density": RHO, "gravity": G, "n_elements": 10}
    ends = (0, 0, -60.0), (99.0, 0, -40.0)
    free = static_equilibrium(MooringModel(network_from_line(line, *ends, **args), Water(density=RHO, gravity=G)))
    tied = network_from_line(line, *ends, **args, ties=(_tether(50.0, (49.0, 0.0, -62.0), 1e6, 15.0),))
    state = static_equilibrium(MooringModel(tied, Water(density=RHO, gravity=G)))
    assert np.linalg.norm(state.position[5] - [49.0, 0.0, -62.0]) < 15.0  # the tether would be in compression
    assert np.array_equal(state.position, free.position)
    assert tether_tension(tied, state.position) == [0.0]


def test_buoy_on_a_tether_below_a_vertical_cable():
    """A 60 m cable (EA 5 MN, 300 N/m in water) hanging from a point at z = -20 m, a buoy of net buoyancy
    B = 25 kN at its lower end, held down by a 19 m tether (EA 2 MN) to z = -100 m: 80 m between the fixed
    points, 1 m of stretch for the cable's and the tether's. Along the vertical the cable's tension grows upward
    by its weight, T(s) = T_c + w s, and the junction's balance is T_t = T_c + B:

        (T_c L + w L^2 / 2) / EA + L0 (T_c + B) / EA_t = H - L - L0

    The lumped model's nodes are exact for a uniform load in 1D (its half elements' weights are the consistent
    loads), so the tether's tension is the closed form's to round-off: measured 3e-12, 1e-9 asserted; the buoy's
    buoyancy left out of the balance, or the cable's weight, fails by 25 kN or 5 %."""
    w, L, ea, B, L0, eat, H = 300.0, 60.0, 5e6, 25e3, 19.0, 2e6, 80.0
    cable = LineType(diameter=0.1, mass_per_length=w / G + RHO * math.pi / 4 * 0.01, axial_stiffness=ea)
    buoy = PointMass(s=L, weight_in_water=-B, kind="buoy")
    line = Line(segments=Line.single(cable, L).segments, attachments=(buoy,))
    net = network_from_line(line, (0, 0, -20.0), (0, 0, -20.0 - L), water_density=RHO, gravity=G, n_elements=12,
                            end_b="free", ties=(_tether(L, (0.0, 0.0, -100.0), eat, L0),))
    state = static_equilibrium(MooringModel(net, Water(density=RHO, gravity=G)), tol=1e-12)
    Tc = (H - L - L0 - w * L**2 / (2 * ea) - L0 * B / eat) / (L / ea + L0 / eat)
    assert tether_tension(net, state.position)[0] == pytest.approx(Tc + B, rel=1e-9)
    assert state.position[-1, 2] == pytest.approx(-100.0 + L0 * (1 + (Tc + B) / eat), abs=1e-9)
    assert np.all(state.tension > 0)  # a taut cable: the closed form holds


def test_clamp_reaction_is_the_sum_of_the_lines_end_forces():
    """A 200 m chain (no bending stiffness) from an anchor to a fairlead, clamped rigidly at s = 90 m to a point
    in mid-water: the clamp's fixed node splits it into two lines, each solved on its own (anchor to clamp, clamp to
    fairlead). The clamp's reaction (the force of the line on it, ``clamp_force``) is the sum of the two lines'
    end forces there (their end elements' pull and half elements' weight, :func:`line_end_forces`): measured 7e-10
    of it (three solves' Newton tolerances), 1e-8 asserted. Leaving out either half element's weight (3.1 kN)
    fails it."""
    from seacable.mooring.outputs import tie_variables

    chain = LineType(diameter=0.08, mass_per_length=130.0, axial_stiffness=5e8)
    clamp_at = (80.0, 0.0, -60.0)
    water = Water(density=RHO, gravity=G)
    args = {"water_density": RHO, "gravity": G, "element_length": 5.0}
    whole = network_from_line(Line.single(chain, 200.0), (0, 0, -100.0), (170.0, 0, -10.0), **args,
                              ties=((Clamp(s=90.0, position=SeabedPoint(x=80.0, z=-60.0)), clamp_at),))
    model = MooringModel(whole, water)
    start = model.network.position.copy()
    start[18] = clamp_at  # s = 90 m
    st = static_equilibrium(model, start, tol=1e-12)
    got = tie_variables(whole, st.position, st.support)
    reaction = np.array([got[f"clamp_force_{c}"].values[0] for c in "xyz"])
    parts = []
    for a, b, length in (((0, 0, -100.0), clamp_at, 90.0), (clamp_at, (170.0, 0, -10.0), 110.0)):
        piece = MooringModel(network_from_line(Line.single(chain, length), a, b, **args), water)
        s = static_equilibrium(piece, tol=1e-12)
        parts.append(line_end_forces(piece, s.position))
    total = parts[0][1] + parts[1][0]
    assert reaction == pytest.approx(total, rel=1e-8, abs=1e-8 * np.linalg.norm(total))
    assert got["clamp_s"].values[0] == 90.0 and abs(reaction[2]) > 1e4


def test_tethered_buoy_heave_period_and_amplitude():
    """A buoy (500 kg, 300 kg added mass, 4 kN net buoyancy) at the middle of a light taut horizontal cable (2.5 kN),
    held by a vertical 10 m tether (EA 1 MN), released 1 cm above its equilibrium with no drag: it oscillates at
    omega^2 = (EA_t / L0 + 2 T / l) / m, m = 500 + 300 + the cable's two half elements (the tether's stiffness
    1e5 N/m, the cable's 2 T / l 250 N/m). The period from 20 steps a period (Newmark's average acceleration
    lengthens it by (omega dt)^2 / 12 = 8e-3) is corrected by that and matches to 2e-4 (measured 7e-5; the
    cable's geometric stiffness 2 T / l = 250 N/m left out shifts it by 1.2e-3, the buoy's added mass by 20 %);
    the energy v^2 + (k / m) z^2, which the average-acceleration scheme conserves exactly for a linear system,
    stays within 1e-3 of its start over ten periods (measured 5e-6)."""
    cable = _neutral(0.02, 1e6, added_mass_normal=0.0, added_mass_tangential=0.0, drag_normal=0.0,
                     drag_tangential=0.0)
    buoy = PointMass(s=19.95, mass=500.0, added_mass=300.0, weight_in_water=-4000.0, kind="buoy")
    line = Line(segments=Line.single(cable, 39.9).segments, attachments=(buoy,))
    net = network_from_line(line, (0, 0, -50.0), (40.0, 0, -50.0), water_density=RHO, gravity=G, n_elements=2,
                            ties=(_tether(19.95, (20.0, 0.0, -60.0), 1e6, 10.0),))
    model = MooringModel(net, Water(density=RHO, gravity=G))
    st = static_equilibrium(model, tol=1e-12)
    mid = 1
    assert net.arc_length[mid] == 19.95 and net.n_elements == 2
    T_t = tether_tension(net, st.position)[0]
    l = np.linalg.norm(st.position[1] - st.position[0])
    k = 1e6 / 10.0 + 2.0 * st.tension[0] / l
    m = 500.0 + 300.0 + 2 * 0.5 * cable.mass_per_length * 39.9 / 2
    period = 2 * math.pi * math.sqrt(m / k)
    dt = period / 20
    X0 = st.position.copy()
    X0[mid, 2] += 0.01
    run = simulate(model, None, 10 * period, dt, dt, initial=X0, tol=1e-12)
    z = run.position[:, mid, 2] - st.position[mid, 2]
    t = run.time
    up = np.flatnonzero((z[:-1] < 0) & (z[1:] >= 0))
    crossings = t[up] - z[up] * (t[up + 1] - t[up]) / (z[up + 1] - z[up])
    measured = np.mean(np.diff(crossings))
    newmark = 1 + (2 * math.pi * dt / period) ** 2 / 12
    energy = run.velocity[:, mid, 2] ** 2 + k / m * z**2  # the trapezoidal rule's invariant of x'' = -(k/m) x
    assert T_t == pytest.approx(4000.0, rel=1e-2)  # the tether carries the buoyancy
    assert measured / newmark == pytest.approx(period, rel=2e-4)
    assert np.ptp(energy) < 1e-3 * energy[0]


def test_spring_clamp_tends_to_the_rigid_clamp():
    """The clamp of :func:`test_clamp_reaction_is_the_sum_of_the_lines_end_forces` as a spring: its node sits
    ``F / k`` from the clamp's point along the reaction ``F`` (to round-off), and the reaction differs from the
    rigid clamp's by ``K F / k`` (K the hanging lines' stiffness at the node, about 2e5 N/m here): at first order
    in 1 / k, the difference falling tenfold (measured 9.996) from k = 1e9 to 1e10 N/m, where it is 1.8e-5 of the
    reaction (1e-4 asserted). A spring acting the other way, or at the wrong point, fails it."""
    from seacable.mooring.outputs import tie_variables

    chain = LineType(diameter=0.08, mass_per_length=130.0, axial_stiffness=5e8)
    clamp_at = (80.0, 0.0, -60.0)
    water = Water(density=RHO, gravity=G)
    out = {}
    for k in (None, 1e9, 1e10):
        clamp = Clamp(s=90.0, position=SeabedPoint(x=80.0, z=-60.0), stiffness=k)
        net = network_from_line(Line.single(chain, 200.0), (0, 0, -100.0), (170.0, 0, -10.0), water_density=RHO,
                                gravity=G, element_length=5.0, ties=((clamp, clamp_at),))
        start = net.position.copy()
        start[18] = clamp_at
        st = static_equilibrium(MooringModel(net, water), start, tol=1e-12)
        got = tie_variables(net, st.position, st.support)
        out[k] = np.array([got[f"clamp_force_{c}"].values[0] for c in "xyz"]), st.position[18]
    rigid = out[None][0]
    for k in (1e9, 1e10):
        assert out[k][1] - np.array(clamp_at) == pytest.approx(out[k][0] / k, rel=1e-6, abs=1e-12)
    errors = [np.linalg.norm(out[k][0] - rigid) for k in (1e9, 1e10)]
    assert errors[0] / errors[1] == pytest.approx(10.0, rel=0.1)
    assert errors[1] < 1e-4 * np.linalg.norm(rigid)

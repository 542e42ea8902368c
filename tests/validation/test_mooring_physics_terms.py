"""One closed form per physics term of the mooring model, each with a tolerance far below the term.

Issue 17 (tests that catch wrong physics): the mooring model's added mass, the force of the water's acceleration
(Froude-Krylov and added mass, normal and tangential), its Morison drag magnitude
(without the peer data), the direction of a current, and the direction of a platform's yaw and pitch,
each against a value derived by hand, not by the model's own code.

References: the vibrating string (Rayleigh, Theory of Sound, section 120), its lumped-mass version
(``omega = 2 sqrt(T / (m h^2)) sin(pi / (2 n))``), Morison's drag ``1/2 rho C_D d U^2`` per length, and
the right-hand rule for rotations about z (yaw) and y (pitch).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import seacable as sc
from seacable.mooring.motion import PlatformMotion
from seacable.mooring.network import network_from_line
from seacable.mooring.solver import MooringModel, Water, simulate, static_equilibrium

RHO, G = 1025.0, 9.81
D = 0.1
AREA = math.pi * D**2 / 4


def _taut_line(line_type, length, n, tension, ea):
    """A weightless line stretched to ``tension`` between a fixed end A and a held end B, 50 m deep."""
    stretched = length * (1 + tension / ea)
    net = network_from_line(sc.Line.single(line_type, length), (0, 0, -50.0), (stretched, 0, -50.0),
                            water_density=RHO, gravity=G, n_elements=n)
    return net, stretched


@pytest.mark.parametrize("ca", [0.0, 1.0])
def test_added_mass_sets_the_period_of_a_taut_line_in_water(ca):
    """A neutrally buoyant line (mass rho A per metre, no weight in water) under 10 kN, 100 m long, 20
    elements, plucked into its first mode sideways: the lumped string's period with the added mass.

    T1 = 2 pi / omega, omega = 2 sqrt(T / ((m + Ca rho A) h^2)) sin(pi / (2 n)). With Ca = 1 the added
    mass doubles the moving mass: the period grows by sqrt(2), 41 %.
    """
    ea, tension, length, n = 1e9, 1e4, 100.0, 20
    m = RHO * AREA
    lt = sc.LineType(diameter=D, mass_per_length=m, weight_in_water=0.0, axial_stiffness=ea, drag_normal=0.0,
                     drag_tangential=0.0, added_mass_normal=ca, added_mass_tangential=0.0)
    net, stretched = _taut_line(lt, length, n, tension, ea)
    model = MooringModel(net, Water(depth=None, density=RHO, gravity=G))
    h = stretched / n  # the tension is T over the stretched chord; the mass is per unstretched metre
    omega = 2 * math.sqrt(tension / ((m + ca * RHO * AREA) * length / n * h)) * math.sin(math.pi / (2 * n))
    period = 2 * math.pi / omega
    x0 = net.position.copy()
    x0[:, 1] = 0.01 * np.sin(math.pi * net.arc_length / length)  # first mode, 1 cm: linear
    run = simulate(model, None, 3 * period, period / 400, period / 400, initial=x0, tol=1e-10)
    y = run.position[:, n // 2, 1]
    # zero crossings, interpolated linearly between samples (error (dt omega)^2 / 6 ~ 4e-5 of a half period)
    k = np.flatnonzero(np.diff(np.sign(y)) != 0)
    tz = run.time[k] - y[k] * (run.time[k + 1] - run.time[k]) / (y[k + 1] - y[k])
    observed = 2 * np.mean(np.diff(tz))
    # Newmark's average acceleration lengthens the period by (omega dt)^2 / 12 = 2e-5; 1e-3 is 1/400 of the
    # added mass's 41 % (and of the 0 % of Ca = 0: both directions of a wrong added mass fail)
    assert observed == pytest.approx(period, rel=1e-3)


@pytest.mark.parametrize("heading, axis", [(math.pi / 2, 1), (0.0, 0)])
def test_morison_drag_of_a_line_across_a_current_is_half_rho_cd_d_u2(heading, axis):
    """A taut weightless line along x under 1 MN in a uniform 1.5 m/s current.

    Across the line (heading +y) the supports hold the whole drag, 1/2 rho C_dn d U^2 L = 1/2 1025 1.2 0.1
    2.25 100 = 13 837.5 N, in +y (the current pushes the line the way it flows); along the line (heading
    +x) the normal drag vanishes and, with C_dt = 0, nothing pulls across.
    """
    ea, tension, length, n, u, cd = 1e10, 1e6, 100.0, 20, 1.5, 1.2
    lt = sc.LineType(diameter=D, mass_per_length=RHO * AREA, weight_in_water=0.0, axial_stiffness=ea,
                     drag_normal=cd, drag_tangential=0.0)
    net, _ = _taut_line(lt, length, n, tension, ea)
    water = Water(depth=None, density=RHO, gravity=G, current_speeds=(u,), current_heading=heading)
    st = static_equilibrium(MooringModel(net, water), tol=1e-12)
    total = st.support[0] + st.support[-1]
    if axis == 1:
        expected = 0.5 * RHO * cd * D * u**2 * length
        assert expected == pytest.approx(13837.5)
        # the line bows by q L^2 / (8 T) = 0.17 m, a slope of q L / (2 T) = 7e-3: the normal velocity is
        # U cos(slope), 2.4e-5 short in U^2; 1e-4 allows for it (a drag off by any factor fails)
        assert total[1] == pytest.approx(expected, rel=1e-4)
        # and it pushes the line towards +y
        assert st.position[n // 2, 1] > 0.1
    else:
        assert abs(total[1]) < 1e-6 * 0.5 * RHO * cd * D * u**2 * length
        assert np.max(np.abs(st.position[:, 1])) < 1e-9


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_tangential_drag_of_a_line_along_a_current_is_half_rho_pi_cdt_d_u2(sign):
    """A taut weightless line along x under 1 MN in a uniform 1.5 m/s current along it (+x, or -x): the
    supports hold the skin friction of the wetted perimeter, 1/2 rho pi C_dt d U^2 L = 1/2 1025 pi 0.4 0.1
    2.25 100 = 14 491 N, the way the current flows (MoorDyn's tangential drag), and nothing across (the normal
    drag vanishes). 1e-8 relative: the static solve leaves 1e-12 of the 1 MN tension at each node, 2e-5 N in
    all (the line stays straight: no normal component)."""
    ea, tension, length, n, u, cdt = 1e10, 1e6, 100.0, 20, 1.5, 0.4
    lt = sc.LineType(diameter=D, mass_per_length=RHO * AREA, weight_in_water=0.0, axial_stiffness=ea,
                     drag_normal=1.2, drag_tangential=cdt)
    net, _ = _taut_line(lt, length, n, tension, ea)
    water = Water(depth=None, density=RHO, gravity=G, current_speeds=(u,), current_heading=0.0 if sign > 0 else math.pi)
    st = static_equilibrium(MooringModel(net, water), tol=1e-12)
    total = st.support[0] + st.support[-1]
    expected = 0.5 * RHO * math.pi * cdt * D * u**2 * length
    assert expected == pytest.approx(14490.6, rel=1e-5)
    assert total[0] == pytest.approx(sign * expected, rel=1e-8)
    assert abs(total[1]) < 1e-8 * expected and abs(total[2]) < 1e-8 * expected


@pytest.mark.parametrize(("along", "can", "cat"), [((0.0, 1.0, 0.0), 1.0, 0.3), ((1.0, 0.0, 0.0), 1.0, 0.3),
                                                 ((0.0, 1.0, 0.0), 0.0, 0.0)])
def test_the_waters_acceleration_pushes_a_line_by_rho_a_one_plus_ca(along, can, cat):
    """A horizontal line 10 m deep at rest in a regular deep-water wave (H = 2 m, T = 8 s, towards +x) at the
    instant its horizontal acceleration peaks at x = 0 (velocity and vertical acceleration zero there): each node
    inside the line gets the Froude-Krylov and added-mass force of its two half elements, rho A L/n (1 + C_a)
    a_x(node) (L/n an element's length), with C_an
    for a line across the wave (along y) and C_at along it (along x; a_x is then tangential), a_x from Airy
    theory at the node. No drag (C_d = 0). 1e-9 relative (round-off). A wrong factor (C_a for 1 + C_a, or the
    normal coefficient on the tangent) is off by a third or more."""
    from seacable.waves import airy_kinematics_array

    H, T, n, length = 2.0, 8.0, 4, 12.0
    lt = sc.LineType(diameter=D, mass_per_length=30.0, weight_in_water=10.0, axial_stiffness=1e9, drag_normal=0.0,
                     drag_tangential=0.0, added_mass_normal=can, added_mass_tangential=cat)
    a = np.array([0.0, 0.0, -10.0]) - 0.5 * length * np.array(along)
    net = network_from_line(sc.Line.single(lt, length), tuple(a), tuple(a + length * np.array(along)),
                            water_density=RHO, gravity=G, n_elements=n)
    model = MooringModel(net, Water(depth=None, density=RHO, gravity=G, wave_height=H, wave_period=T))
    X = net.position
    t = -T / 4  # theta = k x - w t = pi / 2 at x = 0: u = 0, a_x = a w^2 at its peak, a_z = 0
    F, _, _, _ = model.evaluate(X, np.zeros_like(X), np.zeros_like(X), t=t, waves=True)
    ax = np.array([airy_kinematics_array(x, y, z, t, height=H, period=T, depth=None, gravity=G).acceleration[0]
                   for x, y, z in X])
    w = 2 * math.pi / T
    assert ax[n // 2] == pytest.approx(H / 2 * w**2 * math.exp(-10.0 * w**2 / G), rel=1e-12)  # the peak, 10 m down
    # the inner nodes (two half elements, length / n; the ends also hold the tension, along x for the second line)
    ca = can if along[1] else cat
    np.testing.assert_allclose(F[1:-1, 0], RHO * AREA * length / n * (1 + ca) * ax[1:-1], rtol=1e-9)


def test_a_current_towards_plus_y_in_a_case_pushes_the_line_to_plus_y():
    """The case file's current heading (radians, the direction it flows towards): 90 degrees is +y."""
    case = sc.Case(name="cur", line_types={"chain": {"diameter": 0.1512, "mass_per_length": 140.4,
                                                      "axial_stiffness": 6.03e8}},
                   line={"line_type": "chain", "length": 850.0},
                   environment={"depth": 200.0, "current": {"speed": 1.0, "heading": math.pi / 2}},
                   analysis={"type": "mooring_static", "fairlead": [796.0, -15.0], "n_elements": 40})
    ds = sc.run(case)
    y = ds.y.values
    assert np.all(y[1:-1] >= -1e-9) and y.max() > 1.0
    # and the fairlead holds the drag: the line pulls it towards +y
    assert float(ds.fairlead_force_y) > 0


def test_platform_yaw_and_pitch_turn_points_by_the_right_hand_rule():
    """A fairlead 50 m ahead of the platform's centre and 10 m down, at a quarter period of 0.1 rad yaw,
    then of 0.1 rad pitch (no ramp: sin(2 pi t / period) = 1 at t = period / 4).

    Yaw (about +z, right-handed) turns +x towards +y: (50 cos 0.1, 50 sin 0.1, -10) =
    (49.750208, 4.991671, -10). Pitch (about +y) turns +z towards +x and +x towards -z:
    (50 cos 0.1 + (-10) sin 0.1, 0, -50 sin 0.1 + (-10) cos 0.1) = (48.751874, 0, -14.941712).
    """
    base = np.array([[50.0, 0.0, -10.0]])
    t = np.array([10.0])
    yaw = PlatformMotion(amplitude=(0, 0, 0, 0, 0, 0.1), period=40.0)
    x, _, _ = yaw.channels(t, base)
    np.testing.assert_allclose(x[0, 0], [49.750208, 4.991671, -10.0], atol=1e-6)
    pitch = PlatformMotion(amplitude=(0, 0, 0, 0, 0.1, 0), period=40.0)
    x, _, _ = pitch.channels(t, base)
    np.testing.assert_allclose(x[0, 0], [48.751874, 0.0, -14.941712], atol=1e-6)

"""Paper 003 (seeds/003): the tug-barge towline as a chain of rigid 5-DOF elements.

The paper (conference slides) prints no numbers for its four scenarios, only their qualitative
outcomes; these are checked here, together with what the physics fixes exactly: the steady tow is an
elastic catenary in air whose horizontal tension is the barge's resistance (checked against the
statics module and against the mooring finite-element model), and with its damping and drag off the
free line conserves energy to the first order of the explicit scheme.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml
from _evidence import check

import seacable as sc
from seacable.statics.catenary import catenary
from seacable.towline import TowlineModel, barge_resistance, energy, initial_state, simulate
from seacable.towline.solver import stable_time_step

EXAMPLES = Path(__file__).parents[2] / "examples"
EA = 156906.0 / 0.15  # 16 t at 15 % elongation
W_AIR = 1.725 * 9.80665


def _run(name, **analysis):
    data = yaml.safe_load((EXAMPLES / f"paper003_{name}.yaml").read_text())
    data["analysis"].update(analysis)
    return sc.run(sc.parse_case(data))


@pytest.fixture(scope="module")
def steady():
    return _run("steady_tow")


def test_dropped_line_floats_except_next_to_the_tow_points():
    ds = _run("drop")
    z = ds.element_z.isel(time=-1).values
    # a floating element sinks until its immersed fraction f carries its weight: f = m / (rho A)
    r, f = 0.025, 1.725 / (1025.0 * math.pi * 0.025**2)
    c = _fraction_depth(f)
    # the inner elements float at that depth, to 2 mm (the slight pull of the end elements); the third
    # from the barge still dips 5 mm into the transition to the barge's tow point
    assert z[2:-3] == pytest.approx(-c * r, abs=2e-3)
    # the paper: all elements at the surface except those next to the tow points (2 m and 1 m up)
    assert z[0] > r and z[-1] > r
    # and the line has come to rest
    assert np.max(np.abs(ds.element_z.isel(time=-1).values - ds.element_z.isel(time=-21).values)) < 1e-3


def _fraction_depth(f):
    """Depth of the axis, in radii, at which a circular section is immersed by the fraction f."""
    from scipy.optimize import brentq

    return brentq(lambda c: (math.acos(-c) + c * math.sqrt(1 - c * c)) / math.pi - f, -1.0, 1.0, xtol=1e-14)


def test_steady_tow_tension_is_the_barge_resistance(steady):
    last = steady.isel(time=slice(-50, None))
    barge = sc.load_case(EXAMPLES / "paper003_steady_tow.yaml").analysis.barge
    resistance = barge_resistance(barge, 2.5722)
    # the towline pulls along its last element, 1-2 deg from horizontal: H = T cos(angle) differs from
    # T by < 1e-3; the barge has settled to the tug's speed (its surge oscillation decays by 1e-4 by then)
    check(last.barge_speed.values, 2.5722, rtol=1e-4, source="Paper 003 (towline), steady tow", unit="m/s",
          quantity="barge speed behind the tug at 5 kn (last 50 outputs)",
          why="the barge's surge oscillation has decayed to 1e-4 by then")
    check(last.barge_tension.values, resistance, rtol=1e-3, source="Paper 003 (towline), steady tow", unit="N",
          quantity="towline tension at the barge = the barge's resistance at 5 kn (last 50 outputs)",
          why="the line pulls 1-2 deg from horizontal: T and H differ by < 1e-3")


def test_steady_tow_shape_is_the_elastic_catenary_in_air(steady):
    """At 25 kN the whole line hangs in air between the tow points (2 m and 1 m up): a catenary."""
    last = steady.isel(time=-1)
    x, z = last.x.values, last.z.values
    n = steady.attrs["n_elements"]
    res = catenary(x[0] - x[-1], z[0] - z[-1], 100.0, EA, W_AIR, seabed=False)
    prof = res.profile(n + 1)
    z_cat = z[-1] + prof.z[::-1] - prof.z[0]
    assert z.min() > 0.3  # clear of the water
    # tensions at both ends within 1e-4: the chain of rigid links settles 3.6e-5 below the continuous catenary
    # (measured at 500-800 s, with the joint dampers implicit along the line and with them point-implicit
    # alike; at 400 s 4.1e-5, and the point-implicit dampers' slower settling crossed the catenary's value
    # there, 1.4e-6, after -1.1e-4 at 300 s), far below any error of the weight or the stiffness; and
    # the joints on the catenary within 1 cm of a 0.9 m sag (measured 5.5 mm): rigid elements carry
    # their weight at their centres, the catenary continuously, so the joints of a chain of rigid links
    # lie on it to O(l^2); and each pin gives by its shear over its stiffness k / 3 (some 2 mm here)
    check(float(last.barge_tension), float(res.anchor_tension), rtol=1e-4, unit="N",
          source="Closed form: elastic catenary (towline in air)", quantity="paper 003's steady tow, barge-end tension",
          why="the chain of rigid links settles 3.6e-5 below the continuous catenary")
    check(float(last.top_tension), float(res.fairlead_tension), rtol=1e-4, unit="N",
          source="Closed form: elastic catenary (towline in air)", quantity="paper 003's steady tow, tug-end tension",
          why="the chain of rigid links settles 3.6e-5 below the continuous catenary")
    assert np.max(np.abs(z - z_cat)) < 1e-2


def test_steady_tow_agrees_with_the_mooring_finite_element_model(steady):
    """The same line between the same tow points, as truss elements in the mooring model's statics."""
    from seacable.mooring.network import network_from_line
    from seacable.mooring.solver import MooringModel, Water, static_equilibrium

    last = steady.isel(time=-1)
    x, z = last.x.values, last.z.values
    wire = sc.LineType(diameter=0.05, mass_per_length=1.725, weight_in_water=W_AIR, axial_stiffness=EA)
    net = network_from_line(sc.Line.single(wire, 100.0), (x[-1], 0, z[-1]), (x[0], 0, z[0]), water_density=1025.0,
                            gravity=9.80665, n_elements=44)
    st = static_equilibrium(MooringModel(net, Water(depth=None, gravity=9.80665)))
    fe_support = np.linalg.norm(st.support[[0, -1]], axis=1)
    # end tensions within 0.2 % (the two discretisations, 11 rigid links and 44 truss elements, differ by
    # O(l^2) in how the weight is lumped), and the lowest point within 1 cm
    assert fe_support == pytest.approx([float(last.barge_tension), float(last.top_tension)], rel=2e-3)
    assert st.position[:, 2].min() == pytest.approx(z.min(), abs=1e-2)


def _zigzag_tow():
    """The zig-zag case's tug speed [m/s] and the barge's straight-ahead resistance at it [N]."""
    analysis = sc.load_case(EXAMPLES / "paper003_zigzag.yaml").analysis
    return analysis.tug.speed, float(barge_resistance(analysis.barge, analysis.tug.speed))


@pytest.fixture(scope="module")
def zigzag():
    # 3000 s: the start (barge at rest, tug at speed) excites the slow sideways swing of the barge on the
    # line (period about 800 s), which the hull's lift damps by e every ~600 s; from 2500 s it is below
    # 3 % of the tension's periodic swing
    return _run("zigzag", duration=3000.0)


def test_zigzag_sway_decays_along_the_line(zigzag):
    """Paper 003: the farther an element from the tug, the smaller its sway."""
    late = zigzag.where(zigzag.time >= 2500.0, drop=True)
    sway = np.ptp(late.y.values, axis=0)
    assert sway[0] == pytest.approx(20.0, rel=1e-3)  # the tug's, 2 x 10 m
    # strictly decreasing from joint to joint along the line (nodes 0 to n - 1); the barge holds its tow
    # point (node n) nearly still, 1.0 m peak to peak, as the last joint: asserted below a tenth of the
    # tug's
    assert np.all(np.diff(sway[:-1]) < 0)
    assert sway[-1] < 0.1 * sway[0] and sway[-2] < 0.1 * sway[0]


def test_zigzag_barge_tension_is_periodic_with_the_tug(zigzag):
    """Paper 003: the tension on the barge acts periodically, with the tug's 50 s period."""
    dt = float(zigzag.time[1] - zigzag.time[0])
    shift = round(50.0 / dt)
    late = zigzag.isel(time=slice(-8 * shift, None))  # the last eight periods, 2600-3000 s
    tension = late.barge_tension.values
    # one period later the tension repeats: the rms difference is 2.2-2.3 % of its standard deviation (the
    # slow swing's remainder, see the fixture); 5 %, while a non-periodic record of the same spread gives
    # about 140 % (sqrt 2 for uncorrelated values; 107-155 % before the hull lift was modelled)
    diff = tension[shift:] - tension[:-shift]
    assert np.sqrt(np.mean(diff**2)) < 0.05 * tension.std()
    # and its spectrum is the tug's: 99.7 % of the variance at multiples of 1/50 Hz (14 % without the hull
    # lift), asserted above 97 %; the rest, the slow swing, falls between them
    power = np.abs(np.fft.rfft(tension - tension.mean())) ** 2
    freq = np.fft.rfftfreq(tension.size, dt)
    harmonics = np.isclose(freq * 50.0, np.round(freq * 50.0), atol=1e-9) & (freq > 0)
    assert power[harmonics].sum() > 0.97 * power.sum()
    # the line stays taut, and pulls on the average the barge's resistance at 2 knots: 0.8 % more (the
    # yawing barge's cross-flow drag and lift, and the line's angle); asserted within 2 %
    assert not late.slack.values.any()
    check(tension.mean(), _zigzag_tow()[1], rtol=2e-2, source="Paper 003 (towline), zig-zag", unit="N",
          quantity="mean barge tension in the 2 kn zig-zag = the barge's straight-ahead resistance",
          why="the yawing barge's cross-flow drag and lift and the line's angle add 0.8 %")


def test_barge_overrunning_the_line_piles_it_up_and_the_run_goes_on():
    """The zig-zag start with 100 elements: the tug sets off at 2 knots with the barge at rest, the line
    snaps taut (63 kN) and throws the barge forward, an elastic overshoot to nearly twice the tug's
    speed (2 U undamped), so that the barge overruns the slack line and pushes it together for a
    minute and a half. Runs of this start blew up at 26-29 s before the joints had their stop at half
    an element's overlap and the water-entry impact its per-point form."""
    ds = _run("zigzag", n_elements=100, duration=120.0, output_interval=1.0)
    speed = ds.barge_speed.values
    tug_speed, resistance = _zigzag_tow()  # 1.0289 m/s, 4069 N
    assert speed.max() > 1.6 * tug_speed  # the overrun: 1.84 m/s
    pushed = ds.where((ds.time >= 30.0) & (ds.time <= 100.0), drop=True)
    # while it overruns, the barge end of the line carries almost nothing (50 N against the 4 kN of the
    # steady tow; asserted below 2 % of it)
    assert float(pushed.barge_tension.max()) < 0.02 * resistance
    # and the line comes taut again once the barge has slowed below the tug's speed: 6 kN at 120 s
    assert speed[-1] < tug_speed and float(ds.barge_tension[-1]) > resistance
    assert np.isfinite(ds.x.values).all()


def test_payout_releases_elements_at_equal_intervals_and_reaches_steady_tow():
    ds = _run("payout")
    released = ds.released.values
    first = np.array([ds.time.values[np.argmax(released[:, k])] for k in range(released.shape[1])])
    # the barge end leaves first; then one element each time the tug has run one element length
    # (9.09 m at 2.5722 m/s = 3.53 s), to the output interval (0.5 s)
    assert np.all(np.diff(first) < 0)
    spacing = np.diff(np.sort(first))
    interval = 100.0 / 11 / 2.5722
    # each release is seen at the next output time (0.5 s), so a spacing is known to +-0.5 s, plus the
    # drift of the element already out as it falls to the water: 0.75 s; the mean spacing to 0.1 s
    assert spacing == pytest.approx(np.full(spacing.size, interval), abs=0.75)
    assert spacing.mean() == pytest.approx(interval, abs=0.1)
    # then the barge follows at the tug's speed, pulled by its resistance. The snap when the line comes
    # taut starts a surge oscillation of the barge on the line (period 2 pi sqrt(M / (EA / L)) = 37 s) that
    # only the quadratic resistance damps: +-0.3 % in speed and +-2 % in tension at 250-300 s; their
    # means over that window (1.35 periods) are within 0.1 % and 1 %
    late = ds.where(ds.time >= 250.0, drop=True)
    check(float(late.barge_speed.mean()), 2.5722, rtol=1e-3, source="Paper 003 (towline), payout", unit="m/s",
          quantity="barge speed once the line is paid out (tug at 5 kn)", why="the late window's surge oscillation")
    barge = sc.load_case(EXAMPLES / "paper003_payout.yaml").analysis.barge
    assert float(late.barge_tension.mean()) == pytest.approx(barge_resistance(barge, 2.5722), rel=1e-2)


def test_free_line_conserves_energy_to_first_order():
    """A line hanging in air between fixed tow points, released from horizontal; no damping, no drag."""
    errors = []
    for factor in (0.8, 0.4, 0.2):
        model = TowlineModel(n_elements=11, length=100.0, diameter=0.05, mass_per_length=1.725, axial_stiffness=EA,
                             barge=None, held_tow_point_height=50.0, damping_ratio=0.0, bending_damping_ratio=0.0,
                             drag=False, impact=False)
        tug = np.array([0.0, 0.0, 50.0])
        state = initial_state(model, tug, start="dropped", drop_height=50.0)

        def still(t, tug=tug):
            t = np.atleast_1d(t)
            return np.broadcast_to(tug, (t.size, 3)).copy(), np.zeros((t.size, 3))

        e0 = energy(model, state, tug)
        dev = []
        for _ in range(20):
            state = simulate(model, still, 0.25, 0.25, state,
                             time_step=factor * stable_time_step(model, 1.0)).final
            dev.append(energy(model, state, tug) - e0)
        errors.append(np.max(np.abs(dev)))
    # the line falls ~7 m: 10 kJ of potential energy turns into motion and stretch; the error of the
    # symplectic Euler scheme is bounded (no drift) and of first order in dt
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert errors[0] < 1e-2 * model.length * model.mass_per_length * model.gravity * 7.0
    assert orders == pytest.approx([1.0, 1.0], abs=0.15)

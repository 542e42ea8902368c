"""A lay or tow vessel on its RAOs (issue 41, :mod:`seacable.vessel_motion`): the chute's or tow point's offset from
its track against closed forms, term by term (heave, the pitch lever arm, surge, the vessel heading), the heave
in a one-component sea against the mooring model's harmonic motion built directly, a zero table giving exactly
zero, and the refusals of the case (a missing file, a heading out of range, a chute under water, calm water)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import seacable as sc
from seacable.environment import IrregularWaves
from seacable.errors import InputError
from seacable.mooring.motion import HarmonicMotion
from seacable.vessel_motion import VesselMotion, bind_vessel_motion
from seacable.waves import wave_number

DEPTH = 60.0
H, T, PHASE = 2.0, 9.0, 0.4      # regular wave: height [m], period [s], phase [rad]
W = 2 * math.pi / T


def rao_csv(path, amplitude, phase=(0.0,) * 6, frequencies=(0.05, 0.3, 1.0, 3.0),
            headings=(0.0, math.pi / 2, math.pi, 1.5 * math.pi)):
    """A made-up RAO table, flat in frequency and heading: amplitude [m/m, rad/m] and phase [rad] of each DOF."""
    rows = ["frequency,heading,dof,amplitude,phase"]
    rows += [f"{w},{b},{j + 1},{amplitude[j]},{phase[j]}" for w in frequencies for b in headings for j in range(6)]
    path.write_text("\n".join(rows) + "\n")
    return str(path)


def env(heading=0.0):
    return sc.Environment(depth=DEPTH, waves=sc.Waves(height=H, period=T, heading=heading, phase=PHASE))


def elevation_phase(x_ref):
    """The wave's elevation at x_ref is (H/2) cos(w t - k x_ref - PHASE): the argument's constant part. [rad]"""
    return -float(wave_number(T, DEPTH, sc.Environment().gravity)) * x_ref - PHASE


def test_heave_in_a_regular_wave_is_the_harmonic_motion_built_directly(tmp_path):
    """A heave RAO of 0.7 m/m and phase 0.5 rad in a regular wave is the harmonic heave
    0.7 (H/2) cos(w t + k-phase + 0.5) of the chute; the mooring model's HarmonicMotion built with that amplitude,
    period and phase (sin(w t + phi): phi = pi/2 + the cosine's phase) gives the same positions, velocities and
    accelerations, ramp included. Tolerance: round-off (1e-12 m) on positions; the velocities and accelerations
    of the RAO path come from central differences in the motions (h = 1e-4: relative 1e-8)."""
    table = rao_csv(tmp_path / "heave.csv", (0.0, 0.0, 0.7, 0.0, 0.0, 0.0), (0.0, 0.0, 0.5, 0.0, 0.0, 0.0))
    x0 = 35.0                       # the chute's start: the reference point (no arm) is there
    motion = VesselMotion(file=table, point=(0.0, 0.0, 4.0), reference=(0.0, 0.0, 4.0), ramp=12.0)
    f = bind_vessel_motion(motion, env(), heading=0.0, start=(x0, 0.0), duration=60.0)
    t = np.linspace(0.0, 60.0, 301)
    off, vel, acc = f(t)
    harmonic = HarmonicMotion(amplitude=(0.0, 0.0, 0.7 * H / 2), period=T,
                              phase=math.pi / 2 + elevation_phase(x0) + 0.5, ramp=12.0)
    x, v, a = harmonic.channels(t, np.zeros((1, 3)))
    np.testing.assert_allclose(off, x[:, 0], rtol=0, atol=1e-12)
    np.testing.assert_allclose(vel, v[:, 0], rtol=0, atol=1e-8 * W * H)
    np.testing.assert_allclose(acc, a[:, 0], rtol=0, atol=1e-7 * W * W * H)
    assert np.max(np.abs(off[:, 2])) == pytest.approx(0.7 * H / 2, rel=1e-3)   # it moves (not a trivial zero)


def test_pitch_moves_a_chute_astern_and_above_the_waterline_by_its_lever_arm(tmp_path):
    """Pitch theta (R = Ry) at a chute 40 m astern of and 5 m above the RAO reference: the chute moves by
    (x, z) = (-40 (cos theta - 1) + 5 sin theta, 40 sin theta + 5 (cos theta - 1)): up by the stern's lever arm,
    forward by the height's (Faltinsen 1990, ch. 3). Exact formula: round-off tolerance."""
    table = rao_csv(tmp_path / "pitch.csv", (0.0, 0.0, 0.0, 0.0, 0.03, 0.0))
    motion = VesselMotion(file=table, reference=(0.0, 0.0, 0.0), point=(-40.0, 0.0, 5.0))
    f = bind_vessel_motion(motion, env(), heading=0.0, start=(0.0, 0.0), duration=30.0, dims=2)
    t = np.linspace(0.0, 30.0, 121)
    off = f(t)[0]
    theta = 0.03 * H / 2 * np.cos(W * t + elevation_phase(40.0))   # the reference is 40 m ahead of the chute
    np.testing.assert_allclose(off[:, 0], 40.0 * (1 - np.cos(theta)) + 5.0 * np.sin(theta), rtol=0, atol=1e-12)
    np.testing.assert_allclose(off[:, 1], 40.0 * np.sin(theta) + 5.0 * (np.cos(theta) - 1), rtol=0, atol=1e-12)
    assert np.max(off[:, 1]) > 1.1                  # 40 m x 0.03 rad: over a metre of heave at the chute


def test_surge_and_the_vessel_heading_turn_into_the_global_frame(tmp_path):
    """Surge s along a vessel heading north (psi = pi/2, a route towards +Y) moves the tow point by s in +Y; with
    wave_heading given, psi = the waves' heading - wave_heading, and the table is read at wave_heading (head seas
    here: the surge RAO's table differs by heading, so reading the wrong heading changes the amplitude)."""
    rows = ["frequency,heading,dof,amplitude,phase"]
    for b, amp in ((0.0, 0.2), (math.pi / 2, 0.0), (math.pi, 0.9), (1.5 * math.pi, 0.0)):
        rows += [f"{w},{b},{j + 1},{amp if j == 0 else 0.0},0.0" for w in (0.05, 3.0) for j in range(6)]
    (tmp_path / "surge.csv").write_text("\n".join(rows) + "\n")
    motion = VesselMotion(file=str(tmp_path / "surge.csv"), point=(0.0, 0.0, 0.0), wave_heading=math.pi)
    # waves travel towards -Y (heading -pi/2); head seas: the vessel heads +Y (psi = -pi/2 - pi = pi/2 mod 2 pi)
    f = bind_vessel_motion(motion, env(heading=-math.pi / 2), heading=0.0, start=(0.0, 0.0), duration=20.0)
    t = np.linspace(0.0, 20.0, 81)
    off = f(t)[0]
    surge = 0.9 * H / 2 * np.cos(W * t - PHASE)
    np.testing.assert_allclose(off[:, 1], surge, rtol=0, atol=1e-12)
    np.testing.assert_allclose(off[:, [0, 2]], 0.0, rtol=0, atol=1e-12)


def test_a_table_of_zeros_moves_nothing_exactly(tmp_path):
    """A zero RAO gives offsets, velocities and accelerations of exactly 0 (the runs then match today's to the bit:
    tests/consistency/test_vessel_rao_runs.py)."""
    motion = VesselMotion(file=rao_csv(tmp_path / "zero.csv", (0.0,) * 6), point=(-30.0, 2.0, 6.0),
                          reference=(1.0, 0.5, 0.3))
    f = bind_vessel_motion(motion, env(), heading=0.7, start=(12.0, -3.0), duration=20.0)
    for arr in f(np.linspace(0.0, 20.0, 41)):
        assert not np.any(arr)


def lay_case(motion, env_=None, **analysis):
    cable = sc.LineType(diameter=0.1, mass_per_length=20.0, weight_in_water=120.0, drag_normal=1.2, name="c")
    return sc.Case(name="lay", line=sc.Line.single(cable, 500.0), environment=env_ or env(),
                   analysis=sc.LayingDynamicAnalysis(ship=sc.ShipMotion(speed=0.5), duration=10.0,
                                                     max_time_step=0.2, motion=motion))


def test_the_case_refuses_a_missing_file_a_heading_out_of_range_and_a_chute_under_water(tmp_path):
    """Each refusal names the key, the value with its unit and a fix; check (validate) refuses what run does."""
    table = rao_csv(tmp_path / "heave.csv", (0.0, 0.0, 1.0, 0.0, 0.0, 0.0))
    with pytest.raises(InputError, match=r"wave_heading = 200 rad is out of range.*Suggested fix"):
        VesselMotion(file=table, point=(0.0, 0.0, 0.0), wave_heading=200.0)
    assert VesselMotion(file=table, point=(0, 0, 0), wave_heading="180 deg").wave_heading == pytest.approx(math.pi)
    with pytest.raises(InputError, match=r"point z = -2 m puts the chute or tow point under water.*Suggested"):
        VesselMotion(file=table, point=(-20.0, 0.0, -2.0))
    missing = lay_case({"type": "rao", "file": str(tmp_path / "nope.csv"), "point": (0.0, 0.0, 2.0)})
    for fn in (sc.check, sc.run):
        with pytest.raises(InputError, match=r"motion.file: RAO file '.*nope.csv' does not exist.*Suggested fix"):
            fn(missing)
    calm = lay_case({"type": "rao", "file": table, "point": (0.0, 0.0, 2.0)}, env_=sc.Environment(depth=DEPTH))
    for fn in (sc.check, sc.run):
        with pytest.raises(InputError, match=r"environment has none.*Suggested fix: give environment.waves"):
            fn(calm)
    narrow = rao_csv(tmp_path / "narrow.csv", (0.0, 0.0, 1.0, 0.0, 0.0, 0.0), frequencies=(1.0, 2.0))
    for fn in (sc.check, sc.run):       # the wave's 0.70 rad/s is outside the table's 1-2 rad/s
        with pytest.raises(InputError, match=r"analysis.motion: RAO file 'narrow.csv' covers 1-2 rad/s"):
            fn(lay_case({"type": "rao", "file": narrow, "point": (0.0, 0.0, 2.0)}))


def test_waves_without_a_vessel_motion_are_still_refused_by_a_lay():
    """The waves move the lay vessel only: a laying_dynamic case without 'motion' does not take them (as before)."""
    with pytest.raises(Exception, match="waves"):
        lay_case(None)


def test_an_irregular_sea_moves_the_chute_as_the_moorings_rao_path_moves_a_platform(tmp_path):
    """In a JONSWAP sea the chute's heave is the RAO response of seacable.raos at the reference point's start (the
    one RAO path: rao_motion with at = the start), ramped; round-off tolerance. A case file's relative RAO file is
    read from the case's folder, and the statistics start by default at the motion's ramp."""
    from seacable.raos import rao_motion, read_rao_csv

    table = rao_csv(tmp_path / "raos.csv", (0.3, 0.0, 0.9, 0.0, 0.01, 0.0), (0.2, 0.0, -0.4, 0.0, 1.1, 0.0))
    sea_env = sc.Environment(depth=DEPTH, waves=IrregularWaves(spectrum="jonswap", hs=2.0, tp=9.0, seed=3,
                                                                  n_components=50))
    motion = VesselMotion(file=table, point=(0.0, 0.0, 0.0), ramp=0.0)
    f = bind_vessel_motion(motion, sea_env, heading=0.0, start=(120.0, 0.0), duration=100.0, dims=2)
    t = np.linspace(0.0, 100.0, 201)
    q = rao_motion(read_rao_csv(table), sea_env.waves.components(DEPTH, sea_env.gravity), t, at=(120.0, 0.0))
    np.testing.assert_allclose(f(t)[0][:, 1], q[2], rtol=0, atol=1e-12)
    np.testing.assert_allclose(f(t)[0][:, 0], q[0], rtol=0, atol=1e-12)     # surge; pitch at no lever arm: none
    (tmp_path / "lay.yaml").write_text(
        "name: lay\nline_types: {c: {diameter: 0.1, mass_per_length: 20.0, weight_in_water: 120.0, drag_normal: 1.2}}\n"
        "line: {line_type: c, length: 500.0}\n"
        "environment: {depth: 60.0, waves: {spectrum: jonswap, hs: 2.0, tp: 9.0, seed: 3}}\n"
        "analysis: {type: laying_dynamic, ship: {speed: 0.5}, duration: 60.0, max_time_step: 0.2,\n"
        "           motion: {type: rao, file: raos.csv, point: [-40, 0, 4], wave_heading: 180 deg, ramp: 20}}\n")
    case = sc.load_case(tmp_path / "lay.yaml")
    assert case.analysis.motion.wave_heading == pytest.approx(math.pi)
    assert case.analysis.statistics_start() == 20.0
    sc.check(case)                                   # the relative file is found and the sea is covered


def test_motion_across_a_2d_lay_is_warned_about(tmp_path):
    """Roll at a chute 3 m to port and 5 m up moves it across the track, which paper 001's plane does not hold:
    warned with the size (roll r = 0.02 rad at a 1 m wave: y moves by 3 (cos r - 1) - 5 sin r, 0.1 m; the vertical
    part enters)."""
    motion = VesselMotion(file=rao_csv(tmp_path / "roll.csv", (0.0, 0.0, 0.0, 0.02, 0.0, 0.0)), point=(0.0, 3.0, 5.0))
    with pytest.warns(sc.SeacableWarning, match=r"moves the chute up to 0.1\d* m across the track"):
        bind_vessel_motion(motion, env(), heading=0.0, start=(0.0, 0.0), duration=30.0, dims=2)

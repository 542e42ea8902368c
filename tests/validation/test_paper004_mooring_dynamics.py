"""Paper 004's dynamic examples and MoorDyn's quasi-static chain cases, against closed forms and OrcaFlex.

Sources: paper 004 (seeds/004) section 4, Tables 2 and 3 (cable-buoy line after Leonard 1972; buoy
relaxation after Meggitt, Palo & Buck 1978); the unit reconstructions are in the example files. The
chain cases and the OrcaFlex series are MoorDyn's public test data (BSD-3), read from
``../shared/peers/moordyn`` when it is there (the tests skip otherwise).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from _evidence import check

import seacable as sc

sys.path.insert(0, str(Path(__file__).parent))
import _moordyn_peer as peer

EXAMPLES = Path(__file__).parents[2] / "examples"
PEERS = peer.PEER_DIR


@pytest.fixture(scope="module")
def cable_buoy():
    case = sc.load_case(EXAMPLES / "paper004_cable_buoy.yaml")
    return case, sc.run(case)


def test_cable_buoy_static_tension(cable_buoy):
    """The unstretched length in the example was chosen for H = 3538 kgf = 34 696 N (Table 2)."""
    _, ds = cable_buoy
    H0 = -float(ds.fairlead_force_x[0])
    # 0.1 %: the length was computed from the parabolic sag, which differs from the catenary by (sag/L)^2
    check(H0, 34696.0, rtol=1e-3, source="Paper 004 (guyed-tower mooring), Table 2", unit="N",
          quantity="cable-buoy line, horizontal tension (3538 kgf)",
          why="the length was set from the parabolic sag, which differs from the catenary by (sag/L)^2")


def test_cable_buoy_lag_is_transverse_wave_travel(cable_buoy):
    """The 3/4, 1/2 and 1/4 points (counted from the anchor) start to move after d / c, d their distance
    from the moving support and c = sqrt(H / (m + m_a)) the transverse wave speed (paper 004 Fig. 10)."""
    case, ds = cable_buoy
    lt = case.line.segments[0].line_type
    H = -float(ds.fairlead_force_x[0])
    c = math.sqrt(H / (lt.mass_per_length + lt.added_mass_per_length(case.environment.water_density)))
    z = ds.z.values
    n = z.shape[1] - 1
    amp = case.analysis.motion.amplitude[2]
    arrival = []
    for frac in (0.75, 0.5, 0.25):
        i = round(frac * n)
        moved = np.abs(z[:, i] - z[0, i]) > 0.02 * amp
        arrival.append(float(ds.time.values[np.argmax(moved)]))
    span = case.analysis.fairlead[0] - case.anchor_position()[0]
    expected = np.array([0.25, 0.5, 0.75]) * span / c
    # The front is smeared by the lumped masses (one element = 6.35 m, 0.022 s of travel) and detected at
    # 2 % of the amplitude, which the support reaches 0.013 s after it starts: 0.04 s covers both.
    assert np.all(np.abs(np.array(arrival) - expected) < 0.04)
    # the lag between neighbouring points is the travel time over a quarter span, to one element's travel
    check(np.diff(arrival), np.diff(expected), atol=0.025, source="Paper 004 (guyed-tower mooring), Fig. 10",
          quantity="cable-buoy line: lag between the 3/4, 1/2 and 1/4 points = transverse wave travel", unit="s",
          why="one element's travel (6.35 m, 0.022 s)")


def test_buoy_relaxation():
    """Table 3: the released buoy swings over its anchor; at rest the anchor carries the net lift less
    the cable's weight in water, 0.538 - 0.0347 * 1.818 = 0.475 N, and it starts from the held catenary."""
    case = sc.load_case(EXAMPLES / "paper004_buoy_relaxation.yaml")
    ds = sc.run(case)
    lift = -case.line.attachments[0].net_weight(case.environment.water_density, case.environment.gravity)
    w = case.line.segments[0].line_type.weight_in_water
    final = ds.anchor_tension.where(ds.time >= 8.0, drop=True).mean()
    # 2 %: the buoy still oscillates axially on the soft cable (EA 21 N) at about 1 % of the tension
    check(float(final), lift - w * case.line.length, rtol=0.02, unit="N",
          source="Paper 004 (guyed-tower mooring), Table 3 (Meggitt's buoy)",
          quantity="released buoy at rest: anchor tension = net lift - cable weight (0.475 N)",
          why="the buoy still oscillates axially on the soft cable (EA 21 N) at about 1 %")
    # released from rest at the held static shape: at t = 0 the anchor tension is that of the cable alone
    # hanging between the anchor and the hand (the hand holds the buoy's lift), the elastic catenary;
    # 4 elements give it to 2.5 % (8 and 16 elements: 0.6 % and 0.16 %, second order), hence 3 %
    from seacable.statics.multisegment import line_equilibrium

    ax, az = case.anchor_position()
    hx, hz = case.analysis.release_from
    lt = case.line.segments[0].line_type
    held = line_equilibrium([case.line.length], [w], [lt.axial_stiffness], hx - ax, hz - az, seabed=False)
    assert float(ds.anchor_tension[0]) == pytest.approx(held.anchor_tension, rel=0.03)
    x_end = ds.x.values[:, -1]
    # relaxed within about 8 s (the paper's curves agree with the experiment from 4 s): buoy within
    # 2 % of the line length of the vertical over the anchor
    assert np.all(np.abs(x_end[ds.time.values >= 8.0]) < 0.02 * case.line.length)


needs_peers = pytest.mark.skipif(PEERS is None, reason="../shared/peers/moordyn not present")
# OrcaFlex static fairlead / anchor tension [kN] (README of the peer data)
ORCAFLEX_STATIC = {"WD0050": (991.6, 826.2), "WD0200": (2065.4, 1402.2), "WD0600": (5232.6, 3244.2)}


@needs_peers
@pytest.mark.parametrize("tag", sorted(ORCAFLEX_STATIC))
def test_chain_static_tension_against_orcaflex(tag):
    from seacable.mooring.moordyn import run_moordyn_file

    ds = run_moordyn_file(PEERS / f"{tag}_Chain.txt")
    fair, anchor = ORCAFLEX_STATIC[tag]
    # 1.5 %: MoorDyn's test accepts 10 %; the remaining difference is the seabed (kBot 1e5 Pa/m sinks the
    # 390 kg/m chain by 13 cm here) and OrcaFlex's own seabed model; an elastic catenary (MoorPy) gives
    # 1001.7 kN at 50 m, 1 % above OrcaFlex
    check(float(ds.fairlead_tension) / 1e3, fair, rtol=0.015, source="OrcaFlex (MoorDyn's chain cases)", unit="kN",
          quantity=f"{tag} chain, static fairlead tension",
          why="the seabed models differ (kBot sinks the chain 13 cm); MoorDyn's own test accepts 10 %")
    check(float(ds.anchor_tension) / 1e3, anchor, rtol=0.02, source="OrcaFlex (MoorDyn's chain cases)", unit="kN",
          quantity=f"{tag} chain, static anchor tension", why="the seabed models differ, at the anchor most")


@needs_peers
@pytest.mark.parametrize("tag", sorted(ORCAFLEX_STATIC))
@pytest.mark.parametrize("amp", ["A1", "A2"])
@pytest.mark.parametrize("rho", [1.0, 0.8])
def test_chain_heave_series_against_orcaflex(tag, amp, rho):
    """Fairlead tension under 2 m (A1) and 5 m (A2) heave at 10 s: the swing about the static value
    follows OrcaFlex's within 15 % of OrcaFlex's peak-to-peak range (MoorDyn's own acceptance), with
    average acceleration (spectral radius 1) and with the generalised-alpha step at 0.8 (its damping of
    the 10 s heave at dt = 0.1 s is of order (w dt)^3, far below the tolerance)."""
    ref = peer.load_reference(tag, amp)
    run = peer.run_seacable(PEERS / f"{tag}_Chain.txt", ref["motion"], 30.0, spectral_radius=rho)
    # the comparison on the series' times 0 ... 20 s, after the motion table's 10 s run-in; the largest
    # difference of T - T_static (each code's own static tension) over OrcaFlex's peak-to-peak range
    check(peer.accuracy(run, ref)["fairlead_max_error_pct"], 0.0, atol=15.0, unit="%",
          source="OrcaFlex (MoorDyn's chain cases)",
          quantity=f"{tag} chain, {amp} heave at 10 s, spectral radius {rho}: largest fairlead-tension difference "
                   "over OrcaFlex's peak-to-peak range",
          why="MoorDyn's own acceptance, 15 %")

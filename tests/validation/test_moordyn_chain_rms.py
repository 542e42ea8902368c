"""MoorDyn's quasi-static chain cases: seacable's fairlead tension against OrcaFlex, no worse than MoorDyn's.

Issue 19, "Validation kept": on MoorDyn v2's public chain cases WD0050, WD0200 and WD0600 (410 / 760 /
1700 m of 390 kg/m chain, EA 1.674 GN, 10 m segments, in 50 / 200 / 600 m of water), with the fairlead
moved in heave by 2 m (A1) and 5 m (A2) at 10 s from rest at full amplitude (MoorDyn's ZZP1 tables,
-10 ... 20 s), the root-mean-square error of seacable's dynamic fairlead tension (``T - T_static``, each
code's own static tension) against OrcaFlex's series (``T - 991.6 / 2065.4 / 5232.6 kN``), on the
series' 201 times 0 ... 20 s (after the tables' 10 s run-in), is no larger than that of MoorDyn 2.7.2
run on the same deck with the same motion. The runs, the reader and the error measure are
``_moordyn_peer.py`` beside this file (:func:`run_seacable`, :func:`run_moordyn`, :func:`accuracy`),
shared with ``bench/moordyn_peer.py``.

Measured (MoorDyn 2.7.2 at its deck's CFL 0.1, dtM = 3.03e-3 s, RK2; seacable at dt = 0.1 s;
RMS error in kN and in % of OrcaFlex's peak-to-peak range of ``T - T_static``):

======  ==  =========  ================  ================  ================
case        range kN   seacable rho 1    seacable rho 0.8  MoorDyn 2.7.2
======  ==  =========  ================  ================  ================
WD0050  A1     194.0     7.75  (3.99 %)    7.06  (3.64 %)   12.96  (6.68 %)
WD0050  A2    1195.4    47.04  (3.93 %)   46.49  (3.89 %)   45.69  (3.82 %)
WD0200  A1     476.6    15.67  (3.29 %)   15.19  (3.19 %)   26.69  (5.60 %)
WD0200  A2    2042.6    98.73  (4.83 %)   98.44  (4.82 %)  116.28  (5.69 %)
WD0600  A1    1504.3    42.57  (2.83 %)   42.39  (2.82 %)   92.21  (6.13 %)
WD0600  A2    4744.7   303.56  (6.40 %)  303.51  (6.40 %)  352.24  (7.42 %)
======  ==  =========  ================  ================  ================

WD0050 A2 (5 m heave in 50 m of water) is the one case where seacable is worse, by 3 % of MoorDyn's
error (1.35 kN of 45.69 kN at rho 1, 0.8 kN at rho 0.8); it is marked a strict expected failure, not
given a wider bound. What was found: fitting the first 8 harmonics of the 10 s heave to each series,
seacable's low-frequency error is 28.8 kN RMS against MoorDyn's 42.1 kN; the rest is a ringing at
2-2.4 Hz (near the line's first axial mode, 2 L / c = 0.4 s) while the fairlead falls through the
tension trough (t = 4.5-6.5 s and 14.5-16.5 s, the chain laying down on the seabed), 37.7 kN RMS in
seacable, 18.4 kN in MoorDyn and 7.0 kN in OrcaFlex. It is tied to the seabed contact: without the
seabed damper (cBot 0, and no friction) it grows to 69 kN in seacable and 30 kN in MoorDyn, and the two
codes' own series (friction 0) differ by 57 kN RMS on the seabed but by 25 kN with the seabed moved out
of reach (WtrDpth 1000 m, the chain hanging from its anchor), so the two seabed contacts (the same
spring-damper law on paper) excite or damp that mode differently: not found further here. It is not
the step (dt 0.1 ... 0.01 s: 47.0-47.5 kN; rho 0.8: 46.5 kN), not the motion table's 3-decimal rounding
(the exact sine: 46.8 kN), not a static offset (the mean of the difference is -1.8 kN, MoorDyn's
-1.5 kN), not the first rows after the 10 s run-in (0-4 s: 23 kN, MoorDyn 42 kN), and not seabed
friction (MoorDyn's FricDamp law makes its friction negligible here: FrictionCoefficient 0 changes its
error by 0.03 kN; seacable's Coulomb friction damps the ringing: without it 45 kN of ringing, 54 kN of
error). OrcaFlex's own fairlead record lags the ZZP1 motion by a constant 0.029 s; driving both codes
0.029 s late is not used: it helps seacable on WD0050 (A2: 44.7 kN, MoorDyn 50.6 kN) but worsens both
codes on WD0200 and WD0600, so it is not the alignment of the tension series.

What the bound sees: halving seacable's normal drag coefficient fails all 12 (WD0050 A1 26.1 kN against
MoorDyn's 13.0, WD0600 A1 100.0 against 92.2). Dropping the lines' added mass (Ca 1 -> 0) is not an error
this comparison can see: it brings seacable closer to OrcaFlex in all six cases (WD0600 A2 303.6 -> 203.5
kN; MoorDyn with Ca 0 moves the same way there, 352 -> 258 kN), so OrcaFlex's chain seems to carry less
added mass than the deck's Ca = 1 on d = 0.252 m; only the WD0050 A2 mark (XPASS, strict) reports it.
"""

from __future__ import annotations

import sys
from functools import cache
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
import _moordyn_peer as peer

needs_peers = pytest.mark.skipif(peer.PEER_DIR is None, reason="../shared/peers/moordyn not present")
DURATION = 30.0  # [s]: the motion tables' whole span, -10 ... 20 s, as test_paper004_mooring_dynamics


@cache
def _moordyn_error(tag: str, amp: str) -> float:
    """MoorDyn's RMS error [N] on one case (run once per session; it takes 0.2-1.4 s)."""
    ref = peer.load_reference(tag, amp)
    run = peer.run_moordyn(peer.PEER_DIR / f"{tag}_Chain.txt", ref["motion"], duration=DURATION)
    return peer.accuracy(run, ref)["fairlead_rms_error"]


CASES = [pytest.param(tag, amp, marks=pytest.mark.xfail(
            strict=True, reason="2 Hz axial ringing at the tension trough, larger than MoorDyn's: see the "
            "module docstring")) if (tag, amp) == ("WD0050", "A2") else (tag, amp)
         for tag in ("WD0050", "WD0200", "WD0600") for amp in ("A1", "A2")]


@needs_peers
@pytest.mark.parametrize(("tag", "amp"), CASES)
@pytest.mark.parametrize("rho", [1.0, 0.8])
def test_chain_heave_rms_error_no_larger_than_moordyns(tag, amp, rho):
    """seacable's RMS error of the dynamic fairlead tension against OrcaFlex <= MoorDyn 2.7.2's, with the
    average-acceleration step (spectral radius 1) and the generalised-alpha step at 0.8. No tolerance:
    the bound is MoorDyn's own error on the same deck, motion, times and measure (the table above)."""
    pytest.importorskip("moordyn")
    ref = peer.load_reference(tag, amp)
    ours = peer.run_seacable(peer.PEER_DIR / f"{tag}_Chain.txt", ref["motion"], DURATION,
                             spectral_radius=rho)
    acc = peer.accuracy(ours, ref)
    assert acc["n_compared"] == len(ref["time"]) == 201
    assert acc["fairlead_rms_error"] <= _moordyn_error(tag, amp)

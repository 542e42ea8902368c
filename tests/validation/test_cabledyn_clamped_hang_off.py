"""CableDyn 0.3.0's lazy-wave deck with its hang-off clamped (END CONNECTIONS ``1 A Rigid``), read and run by seacable,
against CableDyn on the same deck.

The deck is tests/unit/io/test_cabledyn_deck.py's (CableDyn's ``examples/lozon_gomex80_power_cable.dat``, Lozon et
al. 2025, its mesh coarsened fourfold: 0.61 m elements over the hang-off's section) with its End A, the hang-off,
clamped 10 deg off vertical (``EzX EzY EzZ = sin 10, 0, -cos 10``: along the line towards End B, leaving the hang-off
downwards), the clamp of ``examples/lazy_wave_80m.yaml``'s commented ``fairlead_end_condition``. CableDyn's
numbers (its cubic-Hermite elements; :func:`_cabledyn_peer.driver` on the deck, ``out.static.out``) at the deck's
mesh (k = 1) and with the hang-off's section refined twice and four times (k = 2, 4):

=====  ===============  ====================  ===================
k      hang-off T [N]   peak curvature [1/m]  hang-off curvature
=====  ===============  ====================  ===================
1      9319.5598        0.096868581           0.01915408
2      9319.5603        0.09693285            0.019153253
4      9319.5603        0.096932811           0.019153221
=====  ===============  ====================  ===================

seacable's clamp (:func:`seacable.mooring.kernel.end_bending_loads`) resolves the boundary layer ``sqrt(EI / T) =
1.46 m`` at second order in the element length: its hang-off curvature approaches CableDyn's converged 0.0191532
from below, 2.4 % off at k = 1, 0.6 % at k = 2.
"""

from __future__ import annotations

import math
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import seacable as sc

sys.path.insert(0, str(Path(__file__).parent))
sys.path.insert(0, str(Path(__file__).parents[1] / "unit" / "io"))
import _cabledyn_peer
from test_cabledyn_deck import _deck

CABLEDYN = {1: (9319.5598, 0.096868581, 0.01915408), 2: (9319.5603, 0.09693285, 0.019153253)}
CONVERGED_HANG_OFF = 0.019153221  # k = 4


def _clamped_deck(k: int) -> str:
    d = math.radians(10.0)
    extra = ("--------------------- END CONNECTIONS -------------------------------\n"
             "LineID End Stiffness EzX EzY EzZ\n(-) (-) (N-m/rad) (-) (-) (-)\n"
             f"1 A Rigid {math.sin(d):.12g} 0.0 {-math.cos(d):.12g}\n")
    # CableDyn's driver wants dtM with TMax (seacable reads neither for statics)
    return (_deck(extra).replace("0.0      TMax", "0.05     dtM\n0.0      TMax")
            .replace("68.114   112", f"68.114   {112 * k}"))


def _seacable(tmp_path, k):
    path = tmp_path / f"clamped_{k}.dat"
    path.write_text(_clamped_deck(k))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the CableDyn options seacable does not honour, noted
        ds = sc.run(sc.load_case(path))
    curvature = ds.curvature.values
    assert ds.s.values[0] == 0.0  # node 0: the hang-off, End A
    return float(ds.fairlead_tension), float(np.max(curvature)), float(curvature[0])


def test_clamped_hang_off_deck_against_cabledyn(tmp_path):
    errors = []
    for k in (1, 2):
        tension, peak, hang_off = _seacable(tmp_path, k)
        ref_t, ref_peak, _ = CABLEDYN[k]
        # measured 0.05 N and 0.04 N: the two codes' static tolerances and seabed contact (both kBot 1e5)
        assert tension == pytest.approx(ref_t, abs=0.1)
        # the sag bend's curvature, 0.03 % and 0.01 % apart: each element's own discretisation error
        assert peak == pytest.approx(ref_peak, rel=5e-4)
        errors.append(CONVERGED_HANG_OFF - hang_off)
    # the clamp's boundary layer at second order: halving the elements divides the error by 4 (measured 3.98)
    assert 0.0 < errors[1] < errors[0]
    assert errors[0] / errors[1] == pytest.approx(4.0, rel=0.1)
    assert errors[1] < 0.01 * CONVERGED_HANG_OFF


def test_cabledyn_runs_the_clamped_deck(tmp_path):
    """The peer itself on the deck: it gives the numbers above (its output's 5 to 8 digits)."""
    if _cabledyn_peer.driver() is None:
        pytest.skip("cabledyn (with its driver) is not installed: pip install -e '.[test]'")
    deck = tmp_path / "clamped.dat"
    deck.write_text(_clamped_deck(1))
    subprocess.run([str(_cabledyn_peer.driver()), str(deck), str(tmp_path / "out")], check=True, capture_output=True,
                   timeout=300)
    table = np.loadtxt(tmp_path / "out.static.out", skiprows=3)
    tension, kappa = table[:, 6], table[:, 7]
    assert (tension[0], kappa.max(), kappa[0]) == pytest.approx(CABLEDYN[1], rel=1e-6)

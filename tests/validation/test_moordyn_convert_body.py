"""MoorDyn 2.7.2 as the peer of ``seacable convert case.yaml -o deck.txt`` for a system with a free body.

A subsurface buoy (a free body: mass, centre of gravity off its reference point, inertia, volume, added mass, drag)
on three chains to anchors, the chains on pads on the body. seacable solves its statics (the lines' lumped-mass
elements, as MoorDyn's NumSegs); the case, with the buoy put at that equilibrium, is converted to a MoorDyn deck;
MoorDyn relaxes its initial condition and steps 20 s with nothing moving it. At the same statics the buoy stays where
seacable put it: the pads (which carry the body's whole pose: position and rotation) and the fairlead tensions are
compared with seacable's.

MoorDyn v2 puts a body's weight and buoyancy together at its centre of gravity (``Body::doRHS``: ``rCG x (V rho - M)
g``), so the case's buoy has its centre of buoyancy at its centre of gravity (the converter refuses any other). The
pads are below the centre of gravity: the net buoyancy above the lines' pull keeps the buoy upright.

(From the case's own starting pose instead, MoorDyn 2.7.2's initial-condition solve does not converge for this body:
'Remaining error after 500 s = 0.87 m/s2'; its dynamics then drift to the same pose over some 100 s, to a few mm.)
"""

from __future__ import annotations

import math
import contextlib
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.io.convert import case_to_deck

sys.path.insert(0, str(Path(__file__).parent))
import _moordyn_peer as peer  # noqa: E402

moordyn = pytest.importorskip("moordyn")

_CASE = (Path(__file__).parents[1] / "data" / "subsurface_buoy.yaml").read_text(encoding="utf-8")

_PADS = ("pad1", "pad2", "pad3")


def _rotation(roll, pitch, yaw):
    """Rz(yaw) Ry(pitch) Rx(roll), the system model's convention."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw),
                              math.sin(yaw))
    return (np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1.0]]) @ np.array([[cp, 0, sp], [0, 1.0, 0], [-sp, 0, cp]])
            @ np.array([[1.0, 0, 0], [0, cr, -sr], [0, sr, cr]]))


def _run_moordyn(deck: Path, seconds: int = 20):
    """MoorDyn's initial condition, then ``seconds`` of steps of 1 s with nothing moving: the pads' positions (the
    deck's points 4, 5, 6) and the lines' pull on them, averaged over the last half."""
    pads, tens = [], []
    with contextlib.chdir(deck.parent), peer._quiet():  # MoorDyn writes beside its deck; its console output
        system = moordyn.Create(deck.name)
        assert moordyn.Init(system, [], []) == 0
        t = 0.0
        for _ in range(seconds):
            moordyn.Step(system, [], [], t, 1.0)
            t += 1.0
            pads.append([moordyn.GetPointPos(moordyn.GetPoint(system, k)) for k in (4, 5, 6)])
            # the line's pull on its pad: seacable's fairlead tension (MoorDyn's FairTen is its top segment's
            # tension, short of the end node's weight and buoyancy)
            tens.append([np.linalg.norm(moordyn.GetPointForce(moordyn.GetPoint(system, k))) for k in (4, 5, 6)])
        moordyn.Close(system)
    half = seconds // 2
    return np.mean(pads[half:], axis=0), np.mean(tens[half:], axis=0)


def _case(tmp_path, data=None):
    path = tmp_path / "buoy.yaml"
    path.write_text(yaml.safe_dump(data or yaml.safe_load(_CASE)), encoding="utf-8")
    return sc.load_case(path)


def test_moordyn_holds_the_converted_free_body_where_seacable_finds_its_statics(tmp_path):
    """The pads MoorDyn holds agree with seacable's equilibrium to 2e-3 m, the fairlead tensions to 1e-3. Measured:
    the pads' mean position within 1.1e-4 m (MoorDyn's initial condition converges to 1.3e-4 m/s^2 and leaves a
    heave oscillation of 4e-4 m standard deviation, which 2e-3 m covers five times), the tensions within 3.5e-6.
    Planted in the converter, a CG's z sign wrong moves a pad 1.26 m, its x sign 0.36 m, and a pad written at its
    global depth instead of relative to the body 0.92 m: each fails."""
    case = _case(tmp_path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sc.SeacableWarning)
        ours = sc.run(case)
    pose = tuple(float(ours[f"body_{k}"].values.ravel()[0]) for k in ("x", "y", "z", "roll", "pitch", "yaw"))
    rotation = _rotation(*pose[3:])
    expected = np.array([np.asarray(pose[:3]) + rotation @ np.asarray(case.points[p].position) for p in _PADS])
    data = yaml.safe_load(_CASE)
    data["bodies"]["buoy"]["position"] = list(pose)  # start MoorDyn at seacable's equilibrium
    deck = tmp_path / "buoy.txt"
    deck.write_text(case_to_deck(_case(tmp_path, data)), encoding="utf-8")
    pads, tens = _run_moordyn(deck)
    np.testing.assert_allclose(pads, expected, atol=2e-3, rtol=0)
    np.testing.assert_allclose(tens, ours.fairlead_tension.values[0], rtol=1e-3)

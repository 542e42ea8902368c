"""MoorDyn 2.7.2 as the peer of ``seacable export --format moordyn`` and ``seacable convert``.

MoorDyn (FloatingArrayDesign/MoorDyn, BSD-3; the test extra's ``moordyn`` wheel) runs a small deck of two chain
lines to a coupled point with its output channels on (``OUTPUTS`` and the line flags ``pt``) and writes its
``.out`` files; seacable solves the same deck and exports its result. The two sets of files must have the same
names, the same header lines character for character, the same columns, and the numbers of the same statics.
The round trip deck -> case file -> deck gives MoorDyn a deck it solves to the same statics as the original.
"""

from __future__ import annotations

import contextlib
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import seacable as sc
from seacable.cli import main
from seacable.io import load_moordyn_case
from seacable.io.convert import case_to_deck, deck_to_yaml
from seacable.io.export import export_moordyn

sys.path.insert(0, str(Path(__file__).parent))
import _moordyn_peer as peer  # noqa: E402

moordyn = pytest.importorskip("moordyn")

_DECK = """--------------------- MoorDyn Input File ------------------------------------
two chain lines to a coupled point (seacable export test)
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.1     50.0       1.0e8      -0.8        0          1.2    1.0    0.4     0.5
---------------------- POINTS ----------------------------------------------
ID    Attachment  X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)         (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed       -100.0  0.0     -50.0   0      0       0      0
2     Coupled     0.0     0.0     -5.0    0      0       0      0
3     Fixed       90.0    20.0    -50.0   0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        2         110.0     4       pt
2     chain      3        2         105.0     5       pt
---------------------- OPTIONS -----------------------------------------
0             writeLog
0.001         dtM
1025.0        WtrDnsty
50            WtrDpth
1.0e-7        threshIC
500           TmaxIC
{outputs}
------------------------- need this line --------------------------------------
"""

#: the channels seacable's <deck>.out holds for this deck, in its order
_CHANNELS = ("FairTen1 FairTen2 AnchTen1 AnchTen2 Point1Fx Point1Fy Point1Fz Point2Fx Point2Fy Point2Fz Point3Fx "
             "Point3Fy Point3Fz")


def _deck(folder: Path, name="deck") -> Path:
    path = folder / f"{name}.txt"
    path.write_text(_DECK.format(outputs="---------------------- OUTPUTS -----------------------------------------\n"
                                         + _CHANNELS), encoding="utf-8")
    return path


def _run_moordyn(deck: Path, seconds: float = 1.0) -> None:
    """MoorDyn's statics (its dynamic relaxation in Init), then ``seconds`` with the coupled point held: the .out
    files beside the deck (MoorDyn writes a row per step of 0.5 s, from the first step's end)."""
    with contextlib.chdir(deck.parent), peer._quiet():  # MoorDyn writes beside its deck; its console output
        system = moordyn.Create(str(deck.name))
        assert moordyn.Init(system, [0.0, 0.0, -5.0], [0.0, 0.0, 0.0]) == 0
        t = 0.0
        for _ in range(round(seconds / 0.5)):
            moordyn.Step(system, [0.0, 0.0, -5.0], [0.0, 0.0, 0.0], t, 0.5)
            t += 0.5
        moordyn.Close(system)


def _table(path: Path) -> tuple[list[str], np.ndarray]:
    lines = path.read_text().splitlines()
    return lines[:2], np.loadtxt(lines[2:], ndmin=2)


def _static(deck: Path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sc.SeacableWarning)
        return sc.run(load_moordyn_case(deck))


def test_exported_out_files_have_moordyns_layout_and_numbers(tmp_path):
    """The header lines of <deck>.out and <deck>_Line<N>.out are MoorDyn's to the character; the columns hold the
    same statics. MoorDyn's dynamic relaxation (threshIC 1e-7) and seacable's Newton solution (1e-8) of the same
    lumped-mass lines agree in all 8 digits MoorDyn prints (measured: no difference); 1e-6 of the largest value of
    a file is 20 rounding steps of the last printed digit. (With MoorDyn's default threshIC 0.01 the relaxation stops
    1e-4 short.)"""
    peer = tmp_path / "moordyn"
    ours = tmp_path / "seacable"
    peer.mkdir()
    deck = _deck(peer)
    _run_moordyn(deck)
    written = export_moordyn(_static(deck), ours, "deck")
    assert [p.name for p in written] == ["deck.out", "deck_Line1.out", "deck_Line2.out"]
    for name in ("deck.out", "deck_Line1.out", "deck_Line2.out"):
        head_md, rows_md = _table(peer / name)
        head_sc, rows_sc = _table(ours / name)
        assert head_sc == head_md, name
        assert rows_sc.shape == (1, rows_md.shape[1])  # a static result: one row at time 0
        assert rows_sc[0, 0] == 0.0
        md, us = rows_md[-1, 1:], rows_sc[0, 1:]
        if name == "deck.out":  # MoorDyn writes 0 for the force on a Fixed point; seacable the anchor's load
            fixed = [k for k, c in enumerate(head_md[0].split()[1:]) if c.startswith(("Point1", "Point3"))]
            assert np.all(md[fixed] == 0.0) and np.all(np.abs(us[fixed][[0, 2, 3, 5]]) > 1e3)
            md, us = np.delete(md, fixed), np.delete(us, fixed)
        np.testing.assert_allclose(us, md, atol=1e-6 * np.abs(md).max(), rtol=0)


def test_export_cli_writes_moordyn_files_a_dynamic_run_row_per_output(tmp_path, capsys):
    """``seacable run deck.txt --duration`` then ``seacable export --format moordyn``: a row per stored time, the
    time column MoorDyn's ``%10.4f``, and each line file's positions the result's x, y, z (to the 8 digits of
    MoorDyn's ``%20.7e``)."""
    deck = _deck(tmp_path)
    result = tmp_path / "deck.nc"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sc.SeacableWarning)
        assert main(["run", str(deck), "--duration", "1", "--time-step", "0.05", "--output-interval", "0.25",
                     "--no-plots", "-q", "-o", str(result)]) == 0
    assert main(["export", str(result), "--format", "moordyn", "-o", str(tmp_path / "out")]) == 0
    ds = sc.results.read_netcdf(result)
    head, rows = _table(tmp_path / "out" / "deck_Line2.out")
    np.testing.assert_array_equal(rows[:, 0], [0.0, 0.25, 0.5, 0.75, 1.0])
    assert head[0].split()[1:4] == ["Node0px", "Node0py", "Node0pz"] and head[0].split()[-1] == "Seg5Te"
    x = ds.x.sel(line="line 2").values
    np.testing.assert_allclose(rows[:, 1:19:3], x, rtol=5e-8, atol=1e-12)
    assert "wrote" in capsys.readouterr().out


def test_deck_case_deck_round_trip_gives_moordyn_the_same_statics(tmp_path):
    """deck -> case file -> deck: MoorDyn solves both decks to the same statics. The converted deck carries BA = -1
    where the original has -0.8 (a case has no axial damping; the statics do not depend on it) and threshIC 1e-7:
    the tensions agree in the 8 digits MoorDyn prints (measured); 1e-6 is 20 steps of the last digit. The case file
    between runs in seacable to the deck's own numbers (the same lumped-mass lines, statics: finite_element; Newton
    to 1e-8, measured 4e-11)."""
    first = tmp_path / "first"
    back = tmp_path / "back"
    first.mkdir()
    back.mkdir()
    deck = _deck(first)
    case_file = tmp_path / "case.yaml"
    case_file.write_text(deck_to_yaml(deck), encoding="utf-8")
    text = case_to_deck(sc.load_case(case_file))
    (back / "deck.txt").write_text(text, encoding="utf-8")
    _run_moordyn(deck)
    _run_moordyn(back / "deck.txt")
    head_a, rows_a = _table(first / "deck.out")
    head_b, rows_b = _table(back / "deck.out")
    cols_a = head_a[0].split()
    cols_b = head_b[0].split()
    for name in ("FairTen1", "FairTen2", "AnchTen1", "AnchTen2"):
        a, b = rows_a[-1, cols_a.index(name)], rows_b[-1, cols_b.index(name)]
        assert b == pytest.approx(a, rel=1e-6), name
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sc.SeacableWarning)
        ours = sc.run(sc.load_case(case_file))
    deck_run = _static(deck)
    np.testing.assert_allclose(ours.fairlead_tension.values[0], deck_run.fairlead_tension.values, rtol=1e-8)
    np.testing.assert_allclose(ours.anchor_tension.values[0], deck_run.anchor_tension.values, rtol=1e-8)

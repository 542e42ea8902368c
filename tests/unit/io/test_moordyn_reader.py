"""Tests of the MoorDyn input-file reader, ``seacable.io.moordyn``.

Reference values are the numbers printed in MoorDyn's own public input files (MoorDyn-C test
suite, BSD-3, kept in ``../shared/peers/moordyn/``; see its README) and in a file written for
seacable there. Parsing a decimal literal is exact, so those values are compared with ``==``
against the same literal. The error paths are checked on inline text.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from seacable.errors import InputError, SeacableWarning
from seacable.io.moordyn import (
    MoorDynInput,
    MoorDynLine,
    MoorDynLineType,
    MoorDynPoint,
    is_moordyn_file,
    moordyn_axial_damping,
    read_moordyn,
)


def _peer_dir() -> Path | None:
    for base in (Path(__file__).parents[3] / ".." / "shared", Path("/work/shared")):
        folder = base / "peers" / "moordyn"
        if folder.is_dir():
            return folder
    return None


PEERS = _peer_dir()
needs_peers = pytest.mark.skipif(PEERS is None, reason="../shared/peers/moordyn is absent")


# ------------------------------------------------------------------------- peer files

@needs_peers
@pytest.mark.parametrize("depth, anchor_x, length, n_seg", [(50, 400, 410, 41), (200, 700, 760, 76),
                                                             (600, 1500, 1700, 170)])
def test_moordyn_chain_cases(depth, anchor_x, length, n_seg):
    data = read_moordyn(PEERS / f"WD{depth:04d}_Chain.txt")
    assert isinstance(data, MoorDynInput)
    assert data.path == str(PEERS / f"WD{depth:04d}_Chain.txt")
    assert data.title == "MoorDyn input file of the mooring system for FD validation cases"
    # the LINE TYPES row: chain 0.252 390 1.674e9 -1.0 0 1.37 1.0 0.64 0.0
    assert data.line_types == {"chain": MoorDynLineType("chain", 0.252, 390.0, 1.674e9, -1.0, 0.0,
                                                        1.37, 1.0, 0.64, 0.0)}
    assert data.points == (
        MoorDynPoint(1, "fixed", (float(anchor_x), 0.0, -float(depth)), 0.0, 0.0, 0.0, 0.0),
        MoorDynPoint(2, "vessel", (0.0, 0.0, 0.0), 0.0, 0.0, 0.0, 0.0),
    )
    assert data.lines == (MoorDynLine(1, "chain", 1, 2, float(length), n_seg, "-"),)
    assert data.water_depth == depth
    assert (data.kbot, data.cbot) == (1.0e5, 1.0e4)
    assert data.friction == 0.5
    assert data.cfl == 0.1
    assert data.water_density == 1025.0
    assert data.options["fileIC"] == f"WD{depth:04d}_Chain.txt.ic"  # text stays text
    assert data.options["TmaxIC"] == 100.0 and data.options["disableOutTime"] == 1.0
    # not in the file: MoorDyn's defaults (MoorDyn2.cpp constructor)
    assert data.gravity == 9.80665 and data.time_step is None
    assert data.friction_damping == 200.0 and data.static_dynamic_friction_scale == 1.0
    assert data.outputs == ()


@needs_peers
def test_simple_catenary_file():
    data = read_moordyn(str(PEERS / "simple_catenary.txt"))
    assert data.title.startswith("seacable anchor study: one 76 mm")
    assert data.title.endswith("(MoorDyn v2 format)") and data.title.count("\n") == 1
    assert data.line_types["chain76"] == MoorDynLineType("chain76", 0.137, 126.0, 4.93e8, -1.0, 0.0,
                                                         2.4, 1.0, 1.15, 0.5)
    assert [p.attachment for p in data.points] == ["fixed", "vessel"]  # Fixed, Coupled
    assert data.points[0].position == (-480.0, 0.0, -100.0)
    assert data.points[1].position == (0.0, 0.0, -5.0)
    assert data.lines == (MoorDynLine(1, "chain76", 1, 2, 550.0, 30, "pt"),)
    assert data.options["tScheme"] == "RK2"
    assert (data.water_depth, data.gravity, data.kbot, data.cbot) == (100.0, 9.80665, 3.0e6, 3.0e5)
    assert data.friction == 0.0 and data.cfl == 0.1
    assert data.outputs == ("FairTen1", "AnchTen1")


@needs_peers
def test_lowe_and_langley_connection_properties():
    data = read_moordyn(PEERS / "lowe_and_langley_2006" / "line.txt")
    assert data.title == "MoorDyn input file for a flexible jumper (Lowe and Langley, 2006)"
    assert data.options["Echo"] == "True"  # v1-style 'True Echo' line before the first section
    main = data.line_types["main"]
    assert (main.diameter, main.mass_per_length, main.axial_stiffness) == (0.396, 165.0, 500.0e6)
    assert (main.axial_damping, main.bending_stiffness) == (-0.5, 120.8e3)
    assert (main.drag_normal, main.added_mass_normal, main.drag_tangential,
            main.added_mass_tangential) == (1.0, 1.0, 0.0, 0.0)
    assert [(p.id, p.attachment, p.position) for p in data.points] == [
        (1, "fixed", (-100.0, 0.0, -55.0)), (2, "vessel", (0.0, 0.0, -5.0))]
    assert data.lines == (MoorDynLine(1, "main", 1, 2, 170.0, 68, "-"),)
    assert data.time_step == 0.001 and data.cfl is None
    assert (data.water_depth, data.water_density, data.gravity) == (100.0, 1000.0, 9.807)
    assert data.options["tScheme"] == "midpoint5"


@needs_peers
def test_is_moordyn_file_on_peer_files(tmp_path):
    for name in ("WD0050_Chain.txt", "simple_catenary.txt", "lowe_and_langley_2006/line.txt"):
        assert is_moordyn_file(PEERS / name)
    assert not is_moordyn_file(PEERS / "WD0050_Chain.txt.ic")  # binary state file
    renamed = tmp_path / "state.bin"
    renamed.write_bytes((PEERS / "WD0050_Chain.txt.ic").read_bytes())
    assert not is_moordyn_file(renamed)  # refused by its NUL bytes, not only by its suffix


def test_is_moordyn_file_false_for_case_files(tmp_path):
    yaml = tmp_path / "case.yaml"
    yaml.write_text("---\n# converted from MoorDyn\nmodel: truss_fe\nline:\n  diameter: 0.1\n")
    other = tmp_path / "notes.txt"
    other.write_text("---\nsome notes\n--- LINE TYPES are described in the manual\n")
    assert not is_moordyn_file(yaml)
    assert is_moordyn_file(other)  # a dashed LINE TYPES header is what the sniff looks for
    assert not is_moordyn_file(tmp_path / "missing.txt")
    assert not is_moordyn_file(tmp_path)
    text = tmp_path / "lines.txt"
    text.write_text(_deck())
    assert is_moordyn_file(text)


# ------------------------------------------------------------------------- inline text

LINE_TYPES = """----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
{types}
"""
POINTS = """---------------------- POINTS ----------------------------------------------
ID    Attachment  X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)         (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
{points}
"""
LINES = """---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
{lines}
"""
OPTIONS = """---------------------- OPTIONS -----------------------------------------
{options}
"""
TYPE_ROW = "chain      0.1     20.0       1.0e9      -1.0        0          1.2    1.0    0.2     0.0"
POINT_ROWS = ("1     Fixed       -300.0  0.0     -100.0  0      0       0      0\n"
              "2     Vessel      0.0     0.0     -5.0    0      0       0      0")
LINE_ROW = "1     chain      1        2         350.0     20      -"
OPTION_ROWS = "100           WtrDpth       water depth (m)\n1025.0        WtrDnsty      density"


def _deck(types=TYPE_ROW, points=POINT_ROWS, lines=LINE_ROW, options=OPTION_ROWS, extra="",
          drop=()):
    parts = {"types": LINE_TYPES.format(types=types), "points": POINTS.format(points=points),
             "lines": LINES.format(lines=lines), "options": OPTIONS.format(options=options)}
    body = "".join(v for k, v in parts.items() if k not in drop)
    return ("--------------------- MoorDyn Input File ------------------------------------\n"
            "test deck\n" + body + extra + "------------------------- need this line -----------\n")


def _error(text, match, **kwargs):
    with pytest.raises(InputError, match=match) as info:
        read_moordyn(text, **kwargs)
    message = str(info.value)
    assert "Suggested fix:" in message
    return message


def test_inline_deck_reads_and_defaults():
    data = read_moordyn(_deck(options="0.5   cfl"))
    assert data.path is None and data.title == "test deck"
    assert data.lines[0].length == 350.0
    # no WtrDpth: MoorDyn-C's rule (ReadInFile), the depth of the deepest point, the anchor at z = -100 m
    assert data.given_water_depth is None and data.water_depth == 100.0
    assert (data.water_density, data.gravity, data.kbot, data.cbot, data.friction) == (
        1025.0, 9.80665, 3.0e6, 3.0e5, 0.0)
    assert data.point(2).position == (0.0, 0.0, -5.0)
    with pytest.raises(InputError, match="no point with ID 7"):
        data.point(7)


def test_end_of_file_markers_stop_reading():
    text = _deck() + "garbage that would not parse\n------ BODIES ------\nx\ny\n1 2 3\n"
    assert len(read_moordyn(text).lines) == 1
    text = _deck(extra="---------------------- OUTPUTS ------------\nFairTen1, AnchTen1\nEND\nnot read\n")
    assert read_moordyn(text).outputs == ("FairTen1", "AnchTen1")


def test_v1_file_layout():
    """MoorDyn v1 (docs/inputs.rst): 9-column line types (Can Cat Cdn Cdt), NODE PROPERTIES with
    FX FY FZ, LINE PROPERTIES with UnstrLen before the node numbers, SOLVER OPTIONS."""
    text = """MoorDyn input file for OC3-Hywind (v1)
True   Echo   echo the input file data (flag)
---------------------- LINE DICTIONARY ---------------------------------
LineType  Diam    MassDenInAir  EA       BA/-zeta  Can  Cat  Cdn  Cdt
(-)       (m)     (kg/m)        (N)      (Pa-s/-)  (-)  (-)  (-)  (-)
main      0.09    77.7066       384.243E6  -0.8    1.0  0.0  1.6  0.1
---------------------- NODE PROPERTIES ---------------------------------
Node  Type     X       Y      Z      M     V     FX   FY   FZ   CdA  CA
(-)   (-)      (m)     (m)    (m)    (kg)  (m^3) (kN) (kN) (kN) (m^2) (-)
1     Fixed    853.87  0      -320   0     0     0    0    0    0    0
2     Connect  400.0   0      -200   500   0.1   0    0    0    1.0  0.5
3     Vessel   5.2     0      -70.0  0     0     0    0    0    0    0
---------------------- LINE PROPERTIES ---------------------------------
Line  LineType  UnstrLen  NumSegs  NodeAnch  NodeFair  Flags/Outputs
(-)   (-)       (m)       (-)      (-)       (-)       (-)
1     main      500.0     20       1         2         -
2     main      402.0     16       2         3         pt
---------------------- SOLVER OPTIONS ----------------------------------
0.001    dtM       - time step to use in mooring integration (s)
1025     rhoW      - water density (kg/m^3)
320      WtrDpth   - water depth (m)
------------------------- need this line -------------------------------
"""
    data = read_moordyn(text)
    main = data.line_types["main"]
    assert (main.added_mass_normal, main.added_mass_tangential, main.drag_normal,
            main.drag_tangential, main.bending_stiffness) == (1.0, 0.0, 1.6, 0.1, 0.0)
    assert [p.attachment for p in data.points] == ["fixed", "free", "vessel"]
    assert (data.points[1].mass, data.points[1].volume, data.points[1].drag_area,
            data.points[1].added_mass_coefficient) == (500.0, 0.1, 1.0, 0.5)
    assert data.lines[1] == MoorDynLine(2, "main", 2, 3, 402.0, 16, "pt")
    assert (data.time_step, data.water_density, data.water_depth) == (0.001, 1025.0, 320.0)


def test_attachment_spellings_and_point_prefixes():
    points = ("1 Anchor -300 0 -100 0 0 0 0\n2 Coupled 0 0 -5 0 0 0 0\n3 Point -150 0 -60 10 0 0 0\n"
              "4 Fairlead 10 0 -5 0 0 0 0\n5 CPLD 20 0 -5 0 0 0 0\n6 free 0 5 -5 0 0 0 0")
    lines = "1 chain C1 Point3 200 10 -\n2 chain P3 con2 200 10 -"
    data = read_moordyn(_deck(points=points, lines=lines))
    assert [p.attachment for p in data.points] == ["fixed", "vessel", "free", "vessel", "vessel", "free"]
    assert [(ln.point_a, ln.point_b) for ln in data.lines] == [(1, 3), (3, 2)]


def test_negative_length_is_a_factor_on_the_end_distance():
    # MoorDyn Line::initialize: UnstrLen < 0 -> -UnstrLen * |r_B - r_A|; |(300, 0, 95)| = 314.68...
    data = read_moordyn(_deck(lines="1 chain 1 2 -1.1 20 -"))
    assert data.lines[0].length == pytest.approx(1.1 * math.hypot(300.0, 95.0), rel=1e-14)  # round-off


def test_fortran_exponent_and_twelve_column_points():
    types = "chain 0.1 20.0 1.0d9 -1.0 0 1.2 1.0 0.2 0.0"
    points = POINT_ROWS + "\n3 Free -100 0 -50 0 0 0 0 0 2.0 0.8"
    data = read_moordyn(_deck(types=types, points=points))
    assert data.line_types["chain"].axial_stiffness == 1.0e9
    assert (data.points[2].drag_area, data.points[2].added_mass_coefficient) == (2.0, 0.8)


# ------------------------------------------------------------------------- error paths

@pytest.mark.parametrize("drop, header", [("types", "LINE TYPES"), ("points", "POINTS"),
                                          ("lines", "LINES")])
def test_missing_section(drop, header):
    _error(_deck(drop=(drop,)), f"must have a {header} section")


def test_too_few_columns():
    msg = _error(_deck(types="chain 0.1 20.0 1e9 -1 0 1.2 1.0 0.2"), r"LINE TYPES row must have 10 columns")
    assert msg.startswith("<MoorDyn text>:6:")
    _error(_deck(points="1 Fixed -300 0 -100 0 0 0\n2 Vessel 0 0 -5 0 0 0 0"),
           r":10: .*POINTS row must have 9")
    _error(_deck(lines="1 chain 1 2 350 20"), r":15: .*LINES row must have 7 columns .*got 6")


def test_number_that_does_not_parse():
    _error(_deck(types="chain 0.1x 20.0 1e9 -1 0 1.2 1.0 0.2 0"),
           r"Diam \(diameter\) must be a finite number in m, got '0.1x'")
    _error(_deck(points="1 Fixed -300 0 -1e400 0 0 0 0\n2 Vessel 0 0 -5 0 0 0 0"), r"point 1 Z .*'-1e400'")
    _error(_deck(lines="1 chain 1 2 nan 20 -"), r"UnstrLen \(unstretched length\) must be a finite number")
    _error(_deck(lines="1 chain 1 2 350 2.5 -"), r"NumSegs \(number of segments\) must be a whole number, got '2.5'")


def test_unknown_line_type_and_point(tmp_path):
    msg = _error(_deck(lines="1 chian 1 2 350 20 -"), r"LineType must be one of \['chain'\], got 'chian'")
    assert "Did you mean 'chain'?" in msg
    _error(_deck(lines="1 chain 1 3 350 20 -"), r"end B \(AttachB\) refers to point 3, which is not in the POINTS")
    _error(_deck(lines="1 chain R1A 2 350 20 -"), "attached to rod end 'R1A'")
    _error(_deck(lines="1 chain B1 2 350 20 -"), "must be a point ID")
    path = tmp_path / "lines.txt"
    path.write_text(_deck(lines="1 chain 1 9 350 20 -"))
    with pytest.raises(InputError, match=rf"^{path}:15: line 1 end B \(AttachB\) refers to point 9"):
        read_moordyn(path)
    _error(_deck(lines="1 chain 1 9 350 20 -"), r"^mooring.txt:15:", name="mooring.txt")


def test_duplicate_ids():
    _error(_deck(types=TYPE_ROW + "\n" + TYPE_ROW), "line type 'chain' is defined twice")
    # MoorDyn numbers points by position and never reads the ID column: a repeated ID is the next point
    with pytest.warns(SeacableWarning, match=r"point IDs \[1, 2, 2\] are not 1..3 in file order"):
        data = read_moordyn(_deck(points=POINT_ROWS + "\n2 Free 0 0 -50 0 0 0 0"))
    assert [p.id for p in data.points] == [1, 2, 3]
    _error(_deck(lines=LINE_ROW + "\n" + LINE_ROW), "line ID 1 is used twice")
    _error(_deck(extra="---- LINES ----\n"), "a second LINES section")


@pytest.mark.parametrize("row, match", [
    ("1 chain 1 2 350 0 -", r"NumSegs \(number of segments\) must be >= 1, got 0"),
    ("1 chain 1 2 0 20 -", r"UnstrLen \(unstretched length\) must be > 0 m, got 0 m"),
])
def test_bad_line_row(row, match):
    _error(_deck(lines=row), match)


@pytest.mark.parametrize("row, match", [
    ("chain -0.1 20 1e9 -1 0 1.2 1 0.2 0", r"'chain' Diam \(diameter\) must be > 0 m, got -0.1 m"),
    ("chain 0.1 0 1e9 -1 0 1.2 1 0.2 0", r"'chain' MassDen \(mass per length\) must be > 0 kg/m, got 0 kg/m"),
    ("chain 0.1 20 -3 -1 0 1.2 1 0.2 0", r"'chain' EA must be > 0 N, got -3 N"),
    ("chain 0.1 20 1e9 -1 -5 1.2 1 0.2 0", r"'chain' EI must be >= 0 N m\^2"),
    ("chain 0.1 20 1e9 -1 0 -1.2 1 0.2 0", r"'chain' Cd must be >= 0"),
])
def test_bad_line_type_values(row, match):
    _error(_deck(types=row), match)


def test_nonlinear_coefficient_tables_need_their_file_or_valid_values():
    _error(_deck(types="chain 0.1 20 poly_EA.dat -1 0 1.2 1 0.2 0"), r"EA names the table file 'poly_EA.dat'.*as text")
    _error(_deck(types="chain 0.1 20 0.0|1e6 -1 0 1.2 1 0.2 0"), r"'chain' EA must be > 0 N, got 0 N")
    _error(_deck(types="chain 0.1 20 1|2|3|4 -1 0 1.2 1 0.2 0"), r"EA must hold 2 or 3 values separated by '\|'")
    _error(_deck(types="chain 0.1 20 1e9 damp.txt 0 1.2 1 0.2 0"), "column BA/-zeta must be a constant")
    _error(_deck(types="chain 0.1 20 1e9 -1 EI_curve.dat 1.2 1 0.2 0"), "column EI must be a constant")


@pytest.mark.parametrize("section, header", [
    ("---- CONTROL ----\nChannelID Line(s)\n() (,)\n1 1\n", "CONTROL"),
])
def test_unsupported_sections_with_rows(section, header):
    msg = _error(_deck(extra=section),
                 rf"the {header} section has 1 row\(s\); seacable does not read MoorDyn-F's {header}")
    assert msg.startswith("<MoorDyn text>:")


def test_empty_unsupported_section_is_fine():
    assert len(read_moordyn(_deck(extra="---- BODIES ----\nID X\n(#) (m)\n")).lines) == 1


@pytest.mark.parametrize("word, match", [
    ("Fixd", "Did you mean 'Fixed'"), ("Fixed1", "not a point type"), ("Body0", "not a point type"),
])
def test_bad_point_attachment(word, match):
    msg = _error(_deck(points=f"1 {word} -300 0 -100 0 0 0 0\n2 Vessel 0 0 -5 0 0 0 0"), match)
    assert "point 1 type must be Fixed, Vessel, Free, BodyN or TurbineN" in msg
    _error(_deck(points="1 Body1 -300 0 -100 0 0 0 0\n2 Vessel 0 0 -5 0 0 0 0"),
           r"point 1 is on body 1, which is not in the BODIES section \(IDs none\)")


def test_bad_point_values():
    _error(_deck(points="1 Fixed -300 0 -100 -5 0 0 0\n2 Vessel 0 0 -5 0 0 0 0"),
           r"point 1 Mass must be >= 0 kg")
    _error(_deck(points=POINT_ROWS + "\n3 Free 0 0 -50 0 0 0 0 1e3 0 0"),
           r"point 3 constant force .* must be 0")
    _error(_deck(points="1 Fixed -300 0 -120 0 0 0 0\n2 Vessel 0 0 -5 0 0 0 0"),
           r":10: point 1 Z must be >= -WtrDpth = -100 m, got -120 m")


def test_bad_options():
    _error(_deck(options="100"), r"option line must be 'value name \[comment\]', got '100'")
    _error(_deck(options="deep WtrDpth"), r"option WtrDpth must be a number in m, got 'deep'")
    _error(_deck(options="-100 WtrDpth"), r"option WtrDpth must be > 0 m, got -100 m")
    _error(_deck(options="-0.1 FrictionCoefficient"), r"option FrictionCoefficient must be >= 0")


def test_missing_units_line_and_empty_lines_section():
    text = _deck().replace("(#)   (name)     (#)      (#)       (m)       (-)     (-)\n", "")
    _error(text, r"the units line of 'LINES' .* must be text, got the data row")
    _error(_deck(lines=""), "the LINES section has no rows")


def test_file_errors(tmp_path):
    with pytest.raises(InputError, match="not found"):
        read_moordyn(tmp_path / "nope.txt")
    binary = tmp_path / "lines.ic"
    binary.write_bytes(b"MoorDyn\x00\x00\x01")
    with pytest.raises(InputError, match="binary file"):
        read_moordyn(binary)
    with pytest.raises(InputError, match="needs a path or the file's text"):
        read_moordyn(42)


def test_warnings():
    points = "2 Fixed -300 0 -100 0 0 0 0\n1 Vessel 0 0 -5 0 0 0 0"
    with pytest.warns(SeacableWarning, match=r"point IDs \[2, 1\] are not 1..2 in file order; MoorDyn numbers"):
        data = read_moordyn(_deck(points=points))
    # by position, as MoorDyn: point 1 is the first row (written '2', the anchor)
    assert (data.lines[0].point_a, data.lines[0].point_b) == (1, 2)
    assert data.points[0].attachment == "fixed" and data.points[0].id == 1
    with pytest.warns(SeacableWarning, match="'WAVES' is not a MoorDyn section"):
        read_moordyn(_deck(extra="---- WAVES ----\n1 2 3\n"))


# ------------------------------------------------------------------------- damping rule

def test_axial_damping_is_the_damping_ratio_of_the_highest_axial_mode():
    """-BA = zeta is the damping ratio of the node-to-node axial mode: check it on the lumped
    line itself (a ring of N nodes, mass m*l, springs EA/l, dampers BA/l), not on the formula."""
    ea, m, seg, zeta, n = 1.674e9, 390.0, 10.0, 0.3, 8
    ba = moordyn_axial_damping(-zeta, ea, m, seg)
    lap = 2 * np.eye(n) - np.roll(np.eye(n), 1, axis=1) - np.roll(np.eye(n), -1, axis=1)
    mass, k, c = m * seg, ea / seg * lap, ba / seg * lap
    a = np.block([[np.zeros((n, n)), np.eye(n)], [-k / mass, -c / mass]])
    s = np.linalg.eigvals(a)
    fastest = s[np.argmax(np.abs(s))]
    # damping ratio -Re(s)/|s| of the highest mode; 1e-9: eigenvalue round-off at |s| ~ 1e3 1/s
    assert -fastest.real / abs(fastest) == pytest.approx(zeta, rel=1e-9)
    assert moordyn_axial_damping(2.5e5, ea, m, seg) == 2.5e5  # BA >= 0 is used as written
    both = moordyn_axial_damping(np.array([-zeta, 2.5e5]), ea, m, seg)
    assert both.shape == (2,) and both[1] == 2.5e5 and both[0] == ba
    with pytest.raises(InputError, match="segment_length must be > 0 m"):
        moordyn_axial_damping(-1.0, ea, m, 0.0)

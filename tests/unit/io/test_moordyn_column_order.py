"""Column names that disagree with MoorDyn's positional order are read by position, as MoorDyn reads them, and warned.

MoorDyn reads every table row by position and skips the column-names line unread (``MoorDyn2.cpp``), so a deck whose
header names another order (an OpenFAST r-test deck labels its v2 LINE TYPES ``Can Cat Cdn Cdt`` over MoorDyn v2's
``Cd Ca CdAx CaAx``) holds numbers MoorDyn reads otherwise than the header says. seacable keeps MoorDyn's reading and
says so (one check, ``_check_column_order``, for every table section). Before it, such decks read without a word.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from seacable.errors import SeacableWarning
from seacable.io.moordyn import read_moordyn

DECKS = Path(__file__).parents[2] / "validation" / "data" / "moordyn_decks"

TYPES = ("Name Diam MassDen EA BA/-zeta EI Cd Ca CdAx CaAx", "main 0.1 20.0 1e8 -0.8 0 1.2 1.0 0.2 0.1")
ROD_TYPES = ("TypeName Diam Mass/m Cd Ca CdEnd CaEnd", "buoy 1.0 100 0.6 1.0 0.7 0.3")
BODIES = ("ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca",
          "1 Free 0 0 -20 0 0 0 1000 0 100 2.0 0 0")
RODS = ("ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs", "1 buoy Body1 0 0 0 0 0 2 1 -")
POINTS = ("ID Attachment X Y Z Mass Volume CdA Ca",
          "1 Fixed -100 0 -50 0 0 0 0", "2 Body1 0 0 0 0 0 0 0", "3 Free -50 0 -30 50 0.01 0 0")
LINES = ("ID LineType AttachA AttachB UnstrLen NumSegs Outputs", "1 main 1 3 60 10 -", "2 main 3 2 60 10 -")


def _deck(types=TYPES, rod_types=ROD_TYPES, bodies=BODIES, rods=RODS, points=POINTS, lines=LINES):
    def section(title, rows):
        return f"---------------------- {title} ----------------------\n{rows[0]}\n{'(-) ' * len(rows[0].split())}\n" + \
            "".join(r + "\n" for r in rows[1:])

    return ("MoorDyn input\n" + section("LINE TYPES", types) + section("ROD TYPES", rod_types)
            + section("BODIES", bodies) + section("RODS", rods) + section("POINTS", points) + section("LINES", lines)
            + "---------------------- OPTIONS ----------------------\n50 WtrDpth\n"
            + "------------------------- need this line -------------------------\n")


def test_a_deck_in_moordyn_order_reads_quietly():
    md = read_moordyn(_deck())  # pytest makes a SeacableWarning an error
    assert md.line_types["main"].drag_normal == 1.2 and md.points[2].mass == 50.0


@pytest.mark.parametrize("section, rows, match", [
    # v1 coefficient names over the v2 columns (the r-test deck's header)
    ("types", ("Name Diam MassDen EA BA/-zeta EI Can Cat Cdn Cdt", TYPES[1]),
     r"LINE TYPES column names \(Name Diam MassDen EA BA/-zeta EI Can Cat Cdn Cdt\) .* \(Name Diam MassDen EA BA/-zeta "
     r"EI Cd Ca CdAx CaAx Cl dF cF\): column 7 is named 'Can' \(MoorDyn's Ca, its column 8\) but MoorDyn reads it as Cd"),
    ("rod_types", ("TypeName Diam Mass/m Ca Cd CdEnd CaEnd", ROD_TYPES[1]),
     r"ROD TYPES .* column 4 is named 'Ca' .* reads it as Cd"),
    ("bodies", ("ID Attachment X0 Y0 Z0 r0 p0 y0 Volume CG I Mass CdA Ca", BODIES[1]),
     r"BODIES .* column 9 is named 'Volume' .* reads it as Mass"),
    ("rods", ("ID RodType Attachment Xb Yb Zb Xa Ya Za NumSegs RodOutputs", RODS[1]),
     r"RODS .* column 4 is named 'Xb' .* reads it as Xa"),
    ("points", ("ID Attachment X Y Z Volume Mass CdA Ca",) + POINTS[1:],
     r"POINTS column names \(ID Attachment X Y Z Volume Mass CdA Ca\) .* column 6 is named 'Volume' \(MoorDyn's "
     r"Volume, its column 7\) but MoorDyn reads it as Mass; column 7 is named 'Mass'"),
    ("lines", ("ID LineType AttachA AttachB NumSegs UnstrLen Outputs",) + LINES[1:],
     r"LINES .* column 5 is named 'NumSegs' .* reads it as UnstrLen"),
])
def test_a_header_out_of_moordyn_order_is_warned_and_read_by_position(section, rows, match):
    """Each table section, its header with two columns swapped: the warning names the file and line, the section, the
    names seen and MoorDyn's order; the values are MoorDyn's, read by position."""
    with pytest.warns(SeacableWarning, match=r"<MoorDyn text>:\d+: the " + match):
        md = read_moordyn(_deck(**{section: rows}))
    assert md == read_moordyn(_deck())  # read exactly as the deck in MoorDyn's order


def test_the_r_test_deck_with_v1_coefficient_names_is_read_as_moordyn_reads_it():
    """OpenFAST r-test modules/moordyn/5MW_OC4/moordyn.dat writes its v2 line type (with EI) under 'Can Cat Cdn Cdt'
    with the values 0.8 0.25 2.0 0.4: MoorDyn v2 reads them as Cd Ca CdAx CaAx, and so does seacable, with a warning
    naming the file, the section, the names and MoorDyn's order."""
    path = DECKS / "r-test/modules/moordyn/5MW_OC4/moordyn.dat"
    with pytest.warns(SeacableWarning, match=r"5MW_OC4/moordyn\.dat:5: the LINE TYPES column names \(LineType Diam "
                                             r"MassDen EA BA/-zeta EI Can Cat Cdn Cdt\) are not in the order MoorDyn "
                                             r"reads the section \(Name Diam MassDen EA BA/-zeta EI Cd Ca CdAx CaAx"):
        md = read_moordyn(path)
    lt = md.line_types["main"]
    assert (lt.drag_normal, lt.added_mass_normal, lt.drag_tangential, lt.added_mass_tangential) == (0.8, 0.25, 2.0, 0.4)


def test_a_v1_deck_under_v1_names_reads_quietly():
    """MoorDyn v1's LINE TYPES (no EI) are 'Can Cat Cdn Cdt': in order there, no warning."""
    types = ("LineType Diam MassDenInAir EA BA/-zeta Can Cat Cdn Cdt", "main 0.1 20.0 1e8 -0.8 1.0 0.1 1.2 0.2")
    md = read_moordyn(_deck(types=types))
    assert md.line_types["main"].added_mass_normal == 1.0 and md.line_types["main"].drag_normal == 1.2


def test_an_option_written_name_first_is_warned():
    """OPTIONS rows are 'value name'; '50 WtrDpth' written 'WtrDpth 50' is, for MoorDyn, an option named '50'."""
    text = _deck().replace("50 WtrDpth\n", "50 WtrDpth\ndtM 0.001\n")
    with pytest.warns(SeacableWarning, match=r"OPTIONS row 'dtM 0.001' gives a name then a number, .* write '0.001 dtM'"):
        md = read_moordyn(text)
    assert md.options["0.001"] == "dtM"

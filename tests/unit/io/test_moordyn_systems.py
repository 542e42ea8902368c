"""MoorDyn decks with bodies, rods, failures, viscoelastic and nonlinear lines, v1 count lines and
turbine points: what the reader keeps (``read_moordyn``) and the system it makes (``moordyn_system``).

Numbers read from a deck are compared exactly with the literal written in it (parsing a decimal is
exact); derived ones (a rod's mass, volume, centre of buoyancy) with closed forms at 1e-12.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from seacable.errors import InputError, SeacableWarning
from seacable.io.moordyn import MoorDynFailure, load_moordyn_case, moordyn_system, read_moordyn

DECKS = Path(__file__).parents[2] / "validation" / "data" / "moordyn_decks"

V1 = """--------------------- MoorDyn Input File ------------------------------------
Mooring system for OC4-DeepCwind Semi (MoorDyn v1 layout with count lines)
FALSE    Echo      - echo the input file data (flag)
----------------------- LINE TYPES ------------------------------------------
1    NTypes    - number of LineTypes
Name     Diam      MassDen       EA     BA/-zeta    Can     Cat    Cdn     Cdt
(-)       (m)      (kg/m)        (N)    (N-s/-)     (-)     (-)    (-)     (-)
main     0.0766    113.35     7.536E8    -1.0       0.8     0.25   2.0     0.4
---------------------- CONNECTION PROPERTIES --------------------------------
2     NConnects    - number of connections including anchors and fairleads
Node    Type      X        Y         Z        M        V        FX       FY      FZ     CdA   CA
(-)     (-)      (m)      (m)       (m)      (kg)     (m^3)    (kN)     (kN)    (kN)   (m^2)  (-)
1   Fixed   -837.6   0.0    -200.0    0   0   0   0   0   0   0
2   Vessel  -40.868  0.0    -14.0     0   0   0   0   0   0   0
---------------------- LINE PROPERTIES --------------------------------------
1     NLines    - number of line objects
Line    LineType  UnstrLen  NumSegs   NodeAnch  NodeFair  Flags/Outputs
(-)     (-)       (m)         (-)       (-)       (-)       (-)
1        main     835.35      20          1         2         -
---------------------- SOLVER OPTIONS ---------------------------------------
200      WtrDpth
------------------------- need this line --------------------------------------
"""


# the r-test and MoorDyn decks read here whose LINE TYPES names are out of MoorDyn's order warn so (tested in
# test_moordyn_column_order.py and test_moordyn_decks.py); read quietly where a test is about something else
def _quiet(fn, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SeacableWarning)
        return fn(*args, **kwargs)


def test_v1_layout_with_count_lines():
    md = read_moordyn(V1)
    assert md.layout == "v1"
    lt = md.line_types["main"]
    assert (lt.axial_stiffness, lt.added_mass_normal, lt.added_mass_tangential, lt.drag_normal,
            lt.drag_tangential, lt.bending_stiffness) == (7.536e8, 0.8, 0.25, 2.0, 0.4, 0.0)
    assert [p.attachment for p in md.points] == ["fixed", "vessel"]
    assert (md.lines[0].length, md.lines[0].point_a, md.lines[0].point_b) == (835.35, 1, 2)
    with pytest.raises(InputError, match=r":10: NConnects must be the number of rows .* got '3' but the section "
                                         r"has 2 row\(s\)"):
        read_moordyn(V1.replace("2     NConnects", "3     NConnects"))


def test_bodies_rods_and_rod_ends():
    md = _quiet(read_moordyn, DECKS / "r-test/modules/moordyn/md_BodiesAndRods/moordyn.dat")
    (body,) = md.bodies
    assert (body.attachment, body.position, body.mass, body.inertia) == ("free", (0, 0, 0, 0, 0, 0), 1e6,
                                                                         (1e10, 1e10, 1e10))
    rt = md.rod_types["Can"]
    assert (rt.diameter, rt.mass_per_length, rt.drag_normal, rt.added_mass_normal, rt.drag_end,
            rt.added_mass_end) == (10.0, 1.0e3, 0.6, 1.0, 1.2, 1.0)
    r1, r2 = md.rods
    assert (r1.attachment, r1.body, r1.pinned, r1.end_a, r1.end_b, r1.n_segments) == ("body", 1, False, (0, 0, 2),
                                                                                     (0, 0, 15), 3)
    assert (r2.attachment, r2.body, r2.pinned) == ("body", 1, True)
    assert [(p.attachment, p.body) for p in md.points[:2]] == [("body", 1), ("fixed", None)]
    coupled = read_moordyn(DECKS / "MoorDyn/tests/Mooring/lines_body.txt").bodies[0]
    assert coupled.center_of_gravity == (0.0, 0.0, -35.0)  # one CG value: along the body's z axis (MoorDyn docs)
    floating = read_moordyn(DECKS / "MoorDyn/tests/Mooring/body_tests/floatingBodies.txt")
    assert floating.bodies[1].center_of_gravity == (0.0, -10.0, 0.0)  # 0|-10|0
    drag = _quiet(read_moordyn, DECKS / "MoorDyn/tests/Mooring/body_tests/bodyDrag.txt").bodies[0]
    assert drag.drag_area == (0.1,) * 6 and drag.position[4] == pytest.approx(-math.pi / 2, rel=1e-15)
    fail = read_moordyn(DECKS / "r-test/modules/moordyn/md_lineFail/moordyn.dat")
    assert fail.lines[1].rod_b == (1, "A") and fail.lines[1].point_b is None and fail.lines[3].rod_a == (1, "B")
    assert fail.failures == (MoorDynFailure(1, (1, "A"), (2,), 15.0, 0.0), MoorDynFailure(2, 2, (1,), 11.0, 0.0),
                             MoorDynFailure(3, (1, "A"), (3,), 10.0, 100000.0), MoorDynFailure(4, (1, "B"), (4,), 5.0, 0.0))


def test_bad_structures_are_refused_with_the_line():
    text = (DECKS / "r-test/modules/moordyn/md_lineFail/moordyn.dat").read_text()
    with pytest.raises(InputError, match=r":33: failure 2: line 1 is not attached to 3"):
        read_moordyn(text.replace("2            2        1          11", "2            3        1          11"))
    with pytest.raises(InputError, match=r"rod 1 RodType must be one of \['main'\], got 'mian'"):
        read_moordyn(text.replace("1     main      Free", "1     mian      Free"))
    with pytest.raises(InputError, match=r"rod 1 Attachment must be Fixed, Pinned, Free"):
        read_moordyn(text.replace("1     main      Free", "1     main      Floating"))
    with pytest.raises(InputError, match=r"line 2 end B \(AttachB\) is attached to rod end 'R2A', but rod 2"):
        read_moordyn(text.replace("2         R1A     150.00", "2         R2A     150.00"))


def test_viscoelastic_line_types():
    lt = read_moordyn(DECKS / "MoorDyn/tests/Mooring/polyester/visco.txt").line_types["Polyester_290mm"]
    assert (lt.axial_stiffness, lt.dynamic_stiffness, lt.axial_damping, lt.dynamic_damping) == (
        3.39e8, (4.048e8, 8.855e6), -1.0, 1e11)
    system, _ = moordyn_system(read_moordyn(DECKS / "MoorDyn/tests/Mooring/polyester/visco.txt"))
    t = system.lines["line1"].line.segments[0].line_type
    assert (t.axial_stiffness, t.dynamic_axial_stiffness) == (3.39e8, (4.048e8, 8.855e6))


def test_nonlinear_ea_table_from_a_file(tmp_path):
    deck = (DECKS / "MoorDyn/tests/Mooring/polyester/simple.txt").read_text().replace("3.339E+08", "poly.dat")
    (tmp_path / "lines.txt").write_text(deck)
    (tmp_path / "poly.dat").write_text("Strain Tension\n(-) (N)\n0.0 0.0\n0.01 2.0e6\n0.02 5.0e6\n")
    md = read_moordyn(tmp_path / "lines.txt")
    lt = md.line_types["Polyester_290mm"]
    assert lt.tension_strain == ((0.0, 0.0), (0.01, 2.0e6), (0.02, 5.0e6)) and lt.table_file == "poly.dat"
    assert lt.axial_stiffness == 5.0e6 / 0.02  # the secant at the table's end
    # no warning (SeacableWarning is an error in the tests): the statics and the FE lines both use the table
    system, _ = moordyn_system(md)
    assert system.lines["line1"].line.segments[0].line_type.tension_strain == lt.tension_strain
    (tmp_path / "poly.dat").write_text("0.0 0.0\n0.02 2.0e6\n0.01 5.0e6\n")
    with pytest.raises(InputError, match=r"poly.dat:3: the strain-tension table must have increasing strain"):
        read_moordyn(tmp_path / "lines.txt")
    (tmp_path / "poly.dat").unlink()
    with pytest.raises(InputError, match=r"names the strain-tension table 'poly.dat', which is not a file"):
        read_moordyn(tmp_path / "lines.txt")


def test_free_rod_becomes_a_body_along_its_axis():
    """md_lineFail's free rod: d = 0.333 m, 685 kg/m, from (1, 0, -20) to (1, 0, -10), fully submerged."""
    md = read_moordyn(DECKS / "r-test/modules/moordyn/md_lineFail/moordyn.dat")
    system, env = moordyn_system(md)
    rod = system.bodies["rod1"]
    length, area = 10.0, math.pi * 0.333**2 / 4
    assert rod.kind == "free" and rod.position[:3] == (1.0, 0.0, -20.0)
    assert rod.position[4] == pytest.approx(0.0, abs=1e-15)  # vertical: body z along the rod
    assert rod.mass == pytest.approx(685.0 * length, rel=1e-12)
    assert rod.volume == pytest.approx(area * length, rel=1e-12)
    assert rod.center_of_gravity == pytest.approx((0, 0, 5.0), abs=1e-12)
    assert rod.center_of_buoyancy == pytest.approx((0, 0, 5.0), abs=1e-12)
    assert rod.inertia[0] == pytest.approx(685.0 * length * (length**2 / 12 + 0.333**2 / 16), rel=1e-12)
    assert system.points["rod1_b"].body == "rod1" and system.points["rod1_b"].position == (0.0, 0.0, 10.0)
    assert system.lines["line2"].end_b == "rod1_a" and system.lines["line4"].end_a == "rod1_b"
    assert env.depth == 215.0


def test_rods_on_a_body_add_their_mass_and_submerged_volume():
    """md_float: a body at z = -1 pitched 45 deg carries a 5 m can (d 2 m, 100 kg/m) from z_b = -1 to 4 and a
    1 m weight (d 4 m, 2.15e4 kg/m); the can pierces the surface at 1/5 of its length (body z = 1)."""
    md = _quiet(read_moordyn, DECKS / "r-test/modules/moordyn/md_float/moordyn.dat")
    unmoored, _ = _quiet(moordyn_system, md)  # the body no line ends on is a body all the same
    # the same deck with the body moored by its line: end the line on a point on the body
    text = (DECKS / "r-test/modules/moordyn/md_float/moordyn.dat").read_text().replace(
        "1         Fixed      3        0        -4", "1         Body1      0        0        -2")
    system, _ = _quiet(moordyn_system, _quiet(read_moordyn, text))
    body = system.bodies["body1"]
    assert body == unmoored.bodies["body1"]
    assert body.mass == pytest.approx(100.0 * 5 + 2.15e4 * 1, rel=1e-12)
    # pitched 45 deg: a point at body z is at global z = -1 + z cos(45 deg); the can's top end is at
    # -1 + 4 cos 45 > 0, its lower end -1 - cos 45 < 0: submerged from body z = -1 to z = 1/cos 45 = 1.414
    z_cut = 1.0 / math.cos(math.pi / 4)
    can = math.pi * 1.0**2 * (z_cut + 1.0)
    weight = math.pi * 2.0**2 * 1.0
    assert body.volume == pytest.approx(can + weight, rel=1e-12)
    assert body.center_of_buoyancy[2] == pytest.approx((can * (z_cut - 1) / 2 + weight * -1.5) / (can + weight),
                                                       rel=1e-12)
    assert body.waterplane_area == pytest.approx(math.pi / math.cos(math.pi / 4), rel=1e-12)


def test_bending_stiffness_is_kept_in_the_line_type():
    md = read_moordyn(DECKS / "MoorDyn/tests/Mooring/tripod.txt")
    system, _ = _quiet(moordyn_system, md)
    t = system.lines["line1"].line.segments[0].line_type
    assert t.bending_stiffness == 93212594.98 and t.name == "nodeFloat"


def test_turbine_points_follow_the_turbine_positions():
    md = read_moordyn(DECKS / "r-test/glue-codes/fast-farm/MD_Shared/SharedMooring2.dat")
    assert (md.points[0].attachment, md.points[0].turbine, md.points[3].turbine) == ("turbine", 1, 2)
    with pytest.warns(SeacableWarning, match=r"turbine\(s\) 1, 2 .* FAST.Farm input"):
        moordyn_system(md)
    system, _ = moordyn_system(md, turbine_positions={1: (0.0, 0.0, 0.0), 2: (1600.0, 0.0, 0.0)})
    assert system.bodies["turbine2"].kind == "prescribed" and system.bodies["turbine2"].position[0] == 1600.0
    # a pose (x, y, z, roll, pitch, yaw): turbine 1 of SharedMooring2 is yawed 180 deg, its fairlead point 1 at
    # (-58, 0, -14) in its axes is 58 m downwind of it
    system, _ = moordyn_system(md, turbine_positions={1: (20.3, 0.0, 0.0, 0.0, 0.0, math.pi), 2: (1600.0, 0.0, 0.0)})
    assert system.bodies["turbine1"].position == pytest.approx((20.3, 0.0, 0.0, 0.0, 0.0, math.pi))
    with pytest.raises(InputError, match=r"turbine_positions\[2\] must be \(x, y, z\)"):
        moordyn_system(md, turbine_positions={1: (0.0, 0.0, 0.0), 2: (1600.0, 0.0)})
    assert system.points["point4"].body == "turbine2" and system.points["point4"].position == (-58.0, 0.0, -14.0)


def test_case_exposes_the_system():
    case = load_moordyn_case(DECKS / "MoorPy/tests/case7a.dat")
    assert case.has_structures
    system, env = case.system()
    assert system.bodies["body1"].kind == "prescribed" and system.points["point2"].body == "body1"
    assert not load_moordyn_case(DECKS / "MoorPy/tests/case1.dat").has_structures
    assert np.isclose(env.depth, 50.0)


def test_external_loads_are_read_and_refused_when_wrong():
    md = _quiet(read_moordyn, DECKS / "r-test/modules/moordyn/md_BdyExtLdDmpg/moordyn.dat")
    (load,) = md.external_loads
    assert (load.kind, load.target, load.force, load.linear_damping, load.quadratic_damping, load.frame) == (
        "body", 1, (1.0417e5, 0.5e5, -1.0e4), (1.0e3, 0.7e3, 0.6e2), (3.0e3, 2.1e3, 1.0e4), "G")
    system, _ = moordyn_system(md)
    body = system.bodies["body1"]
    assert body.external_force == (1.0417e5, 0.5e5, -1.0e4, 0.0, 0.0, 0.0)
    assert body.matrix("linear_damping")[2, 2] == 60.0 and body.matrix("quadratic_damping")[1, 1] == 2.1e3
    text = (DECKS / "r-test/modules/moordyn/md_BdyExtLdDmpg/moordyn.dat").read_text()
    with pytest.raises(InputError, match=r"external load 1 Object must name a body, point or rod .* got 'Body2'"):
        _quiet(read_moordyn, text.replace(" 1     Body1  1.0417e5", " 1     Body2  1.0417e5"))
    with pytest.raises(InputError, match=r"external load 1 Fext must be 3 value\(s\)"):
        _quiet(read_moordyn, text.replace("1.0417e5|0.5e5|-1.0e4", "1.0417e5|0.5e5"))
    with pytest.raises(InputError, match=r"external load 1 CSys must be G \(global\) or L"):
        _quiet(read_moordyn, text.replace("1.0e4       G", "1.0e4       Q"))


def test_syrope_line_type():
    md = _quiet(read_moordyn, DECKS / "MoorDyn/tests/Mooring/syrope/linear_wc/line.txt")
    lt = md.line_types["poly"]
    assert lt.syrope == ("LINEAR", 1.25e8, 0.0) and lt.dynamic_stiffness == (1.53e8, 23.12)
    assert lt.tension_strain[1] == (2.06897e-03, 1.71768e+05) and len(lt.tension_strain) == 30  # owc.dat
    assert lt.axial_stiffness == 4.38601e+06 / 6.00000e-02  # secant at the table's end
    assert md.syrope_ic == {1: (1.3886e6, 4.339e5)}


def test_line_type_tables_are_checked():
    from seacable.line import LineType

    ok = LineType(diameter=0.2, mass_per_length=50.0, axial_stiffness=1e8, tension_strain=((0.0, 0.0), (0.01, 1e6)),
                  dynamic_axial_stiffness=(1.5e8, 20.0))
    assert ok.tension_strain == ((0.0, 0.0), (0.01, 1e6)) and ok.dynamic_axial_stiffness == (1.5e8, 20.0)
    with pytest.raises(InputError, match=r"tension_strain\[2\] = \(0.005, 2e\+06 N\) must have a larger strain"):
        LineType(diameter=0.2, mass_per_length=50.0, tension_strain=((0.0, 0.0), (0.01, 1e6), (0.005, 2e6)))
    with pytest.raises(InputError, match=r"tension_strain must hold at least 2"):
        LineType(diameter=0.2, mass_per_length=50.0, tension_strain=((0.0, 0.0),))
    with pytest.raises(InputError, match=r"dynamic_axial_stiffness must be \(EA_Dc >= 0"):
        LineType(diameter=0.2, mass_per_length=50.0, dynamic_axial_stiffness=(-1.0, 0.0))


def test_syrope_working_curves_section():
    """The other Syrope syntax: SYROPE:<the OWC table itself>, the working curve in its own section."""
    md = _quiet(read_moordyn, DECKS / "MoorDyn/tests/Mooring/syrope/exp_wc/line.txt")
    lt = md.line_types["poly"]
    assert lt.syrope == ("EXP", 0.2, 1.5) and lt.table_file == "../owc.dat" and len(lt.tension_strain) == 30
    text = (DECKS / "MoorDyn/tests/Mooring/syrope/exp_wc/line.txt").read_text()
    broken = DECKS / "MoorDyn/tests/Mooring/syrope/exp_wc" / "_no_wc.txt"
    try:
        broken.write_text(text.replace("poly      EXP        0.2     1.5\n", ""))
        with pytest.raises(InputError, match=r"_no_wc.txt:5: line type 'poly' is a Syrope rope .* no SYROPE WORKING"):
            _quiet(read_moordyn, broken)
    finally:
        broken.unlink()

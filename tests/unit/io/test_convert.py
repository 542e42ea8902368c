"""``seacable convert``: a MoorDyn deck as a minimal case file that holds the same system, the reverse for what
MoorDyn can express, and the refusals. MoorDyn's own run of the converted decks is in
``tests/validation/test_moordyn_export.py``."""

from __future__ import annotations

import re
import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.cli import main
from seacable.errors import InputError
from seacable.io import dump_case, load_moordyn_case
from seacable.io.convert import case_to_deck, deck_to_yaml

ROOT = Path(__file__).resolve().parents[3]
BODY_DECK = ROOT / "tests" / "validation" / "data" / "moordyn_decks" / "MoorDyn" / "example" / "body.txt"

_DECK = """--------------------- MoorDyn Input File ------------------------------------
a buoy between two chains
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.1     50.0       1.0e8      -0.8        0          1.4    1.0    0.4     0.5
rope       0.05    5.0        2.0e7      -0.8        0          1.2    1.0    0.4     0.5
---------------------- POINTS ----------------------------------------------
ID    Attachment  X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)         (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed       -100.0  0.0     -50.0   0      0       0      0
2     Free        -30.0   0.0     -30.0   100    2.0     1.5    0.8
3     Coupled     0.0     0.0     -5.0    0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        2         80.0      6       p
2     rope       2        3         40.0      4       -
---------------------- OPTIONS -----------------------------------------
0.0005        dtM
1025.0        WtrDnsty
50            WtrDpth
0.2           FrictionCoefficient
---------------------- OUTPUTS -----------------------------------------
FairTen2
------------------------- need this line --------------------------------------
"""


@pytest.fixture()
def deck(tmp_path) -> Path:
    path = tmp_path / "buoy.txt"
    path.write_text(_DECK, encoding="utf-8")
    return path


def _full(case):
    """Every value of a case, the line types as their lines hold them (a line type named under ``line_types`` is
    not given its name by the reader: the names are left out)."""
    data = yaml.safe_load(dump_case(case))
    data.pop("line_types", None)
    for line in data["lines"].values():
        for seg in line["line"]["segments"]:
            seg["line_type"].pop("name")
    return data


def test_deck_to_case_is_minimal_and_holds_the_decks_system(deck, tmp_path):
    """The case file: no null, no default written out (water density 1025, drag 1.2 are MoorDyn's and seacable's
    defaults), the line types once, comments on what has no counterpart; parsed, it is the system the deck
    runs as, value for value (the lumped-mass statics included)."""
    text = deck_to_yaml(deck)
    data = yaml.safe_load(text)
    assert "null" not in text and "water_density" not in text
    assert set(data["line_types"]) == {"chain", "rope"} and "drag_normal" not in data["line_types"]["rope"]
    assert data["line_types"]["chain"]["drag_normal"] == 1.4
    assert data["lines"]["line2"] == {"line_type": "rope", "length": 40.0, "end_a": "point2", "end_b": "point3",
                                      "n_elements": 4}
    assert data["points"]["point2"]["added_mass"] == pytest.approx(0.8 * 1025.0 * 2.0)
    assert data["analysis"] == {"type": "system_static", "max_strain": 20.0, "statics": "finite_element"}
    comments = [ln for ln in text.splitlines() if ln.startswith("#")]
    assert any("dtM 0.0005" in c for c in comments) and any("BA/-zeta" in c for c in comments)
    assert any("OUTPUTS FairTen2" in c for c in comments)
    case_file = tmp_path / "buoy.yaml"
    case_file.write_text(text, encoding="utf-8")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sc.SeacableWarning)
        expected = load_moordyn_case(deck).system_case()
    expected = expected.model_copy(update={"analysis": expected.analysis.model_copy(update={"statics": "finite_element"}),
                                           "description": sc.load_case(case_file).description})
    assert _full(sc.load_case(case_file)) == _full(expected)
    assert main(["validate", str(case_file)]) == 0


def test_case_to_deck_reads_back_as_the_same_deck(deck, tmp_path):
    """deck -> case -> deck: the deck seacable reads back has the original's line types, points, lines and
    options (BA aside: a case has none; the deck gets -1)."""
    case_file = tmp_path / "buoy.yaml"
    assert main(["convert", str(deck), "-o", str(case_file)]) == 0
    back = tmp_path / "back.txt"
    assert main(["convert", str(case_file), "-o", str(back)]) == 0
    a, b = load_moordyn_case(deck).data, load_moordyn_case(back).data
    assert a.points == b.points and a.lines != () and len(a.lines) == len(b.lines)
    for la, lb in zip(a.lines, b.lines):
        assert (la.point_a, la.point_b, la.length, la.n_segments, la.line_type) == \
               (lb.point_a, lb.point_b, lb.length, lb.n_segments, lb.line_type)
    for name, ta in a.line_types.items():
        tb = b.line_types[name]
        assert ta == tb.__class__(**{**tb.__dict__, "axial_damping": ta.axial_damping}) and tb.axial_damping == -1.0
    assert (a.water_density, a.water_depth, a.gravity, a.friction) == (b.water_density, b.water_depth, b.gravity,
                                                                         b.friction)


def test_deck_with_bodies_converts_and_the_case_keeps_its_bodies(tmp_path):
    text = deck_to_yaml(BODY_DECK)
    data = yaml.safe_load(text)
    assert data["bodies"]["body1"]["kind"] == "prescribed" and data["points"]["point4"]["body"] == "body1"
    assert "statics" not in data["analysis"]  # the system statics 'seacable run body.txt' runs
    case_file = tmp_path / "body.yaml"
    case_file.write_text(text, encoding="utf-8")
    back = load_moordyn_case_quietly(case_to_deck(sc.load_case(case_file)), tmp_path)
    assert back.data.bodies[0].attachment == "coupled" and back.data.points[3].attachment == "body"


@pytest.mark.parametrize("edit, expected", [
    (lambda d: d["lines"]["line1"].update(line={"segments": [{"line_type": d["line_types"]["chain"], "length": 40.0},
                                                             {"line_type": d["line_types"]["rope"], "length": 40.0}]},
                                          line_type=None, length=None),
     "line 'line1' has 2 sections"),
    (lambda d: (d["lines"]["line1"].update(end_a_condition={"type": "clamped", "declination": 1.0}),
                d["line_types"]["chain"].update(bending_stiffness=1.0e4)), "held in bending"),
    (lambda d: d["environment"].update(current={"speed": 0.5}), "environment.current"),
    (lambda d: d["points"]["point2"].update(external_force=[0.0, 0.0, 100.0]), "external force"),
    (lambda d: d["line_types"]["chain"].update(weight_in_water=300.0), "weight_in_water 300 N/m"),
])
def test_what_moordyn_cannot_express_is_refused(edit, expected, deck, tmp_path, capsys):
    data = yaml.safe_load(deck_to_yaml(deck))
    edit(data)
    for line in data["lines"].values():
        for key in [k for k, v in line.items() if v is None]:
            del line[key]
    case_file = tmp_path / "edited.yaml"
    case_file.write_text(yaml.safe_dump(data), encoding="utf-8")
    assert main(["convert", str(case_file), "-o", str(tmp_path / "deck.txt")]) == 2
    err = capsys.readouterr().err
    assert err.count("seacable: error:") == 1 and expected in err and "Suggested fix" in err
    assert "Traceback" not in err and not (tmp_path / "deck.txt").exists()


@pytest.mark.parametrize("source, output, expected", [
    ("deck", "out.txt", "-o must be a case file (.yaml)"),
    ("yaml", "out.yaml", "-o is the MoorDyn deck to write"),
    ("missing", "out.yaml", "is not a file"),
    ("deck", "buoy.txt", "is the source itself"),
    ("single", "out.txt", "single-line case"),
])
def test_convert_bad_input_is_one_clear_line(source, output, expected, deck, tmp_path, capsys):
    paths = {"deck": deck, "missing": tmp_path / "nope.txt", "single": ROOT / "examples" / "oc3_hywind_static.yaml"}
    if source == "yaml":
        paths["yaml"] = tmp_path / "buoy.yaml"
        paths["yaml"].write_text(deck_to_yaml(deck), encoding="utf-8")
    assert main(["convert", str(paths[source]), "-o", str(tmp_path / output)]) == 2
    err = capsys.readouterr().err
    assert err.count("seacable: error:") == 1 and expected in err and "Traceback" not in err


# ------------------------------------------------------------------------------------------------ bodies

# the buoy of tests/data/subsurface_buoy.yaml turned and moved off its reference, so that the pose goes through the deck
_BODY_CASE = (Path(__file__).parents[2] / "data" / "subsurface_buoy.yaml").read_text(encoding="utf-8").replace(
    "position: [0.0, 0.0, -20.0, 0.0, 0.0, 0.0]", "position: [0.3, -0.2, -20.0, 0.02, -0.03, 0.1]")


def load_moordyn_case_quietly(text, folder, name="back.txt"):
    path = Path(folder) / name
    path.write_text(text, encoding="utf-8")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sc.SeacableWarning)
        return load_moordyn_case(path)


def _body_case(tmp_path, edit=None):
    data = yaml.safe_load(_BODY_CASE)
    if edit is not None:
        edit(data)
    path = tmp_path / "buoy.yaml"
    path.write_text(yaml.safe_dump(data), encoding="utf-8")
    return sc.load_case(path)


def test_a_free_body_converts_to_a_deck_that_reads_back_to_the_same_system(tmp_path):
    """case -> deck -> case: the body (mass, CG, inertia, volume, added mass, drag, a turned pose) and the points on
    it come back as they were (names aside: MoorDyn numbers them), and the statics of both cases agree. The only
    change is the pose's angles through degrees and back (1 ulp), so the body's equilibrium agrees to the Newton
    tolerance (1e-8, the statics' own); a CG sign or a point's body-relative position written wrong moves the
    equilibrium by centimetres and fails."""
    case = _body_case(tmp_path)
    back = load_moordyn_case_quietly(case_to_deck(case), tmp_path).system_case()
    body, again = case.bodies["buoy"], back.bodies["body1"]
    assert again.kind == "free"
    for key in ("mass", "volume", "center_of_gravity", "inertia", "added_mass", "quadratic_damping",
                "center_of_buoyancy", "external_force"):
        np.testing.assert_allclose(np.asarray(getattr(again, key), float), np.asarray(getattr(body, key), float),
                                   rtol=1e-12, atol=1e-12, err_msg=key)  # through repr and back: exact but Ca, CdA
    assert again.position == pytest.approx(body.position, rel=1e-14, abs=1e-15)  # angles through degrees
    for k, name in enumerate(("pad1", "pad2", "pad3"), start=4):
        assert back.points[f"point{k}"].body == "body1"
        assert back.points[f"point{k}"].position == case.points[name].position
    back = back.model_copy(update={"analysis": case.analysis})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sc.SeacableWarning)
        ours, theirs = sc.run(case), sc.run(back)
    for key in ("x", "y", "z", "roll", "pitch", "yaw"):
        a, b = float(ours[f"body_{key}"].values.ravel()[0]), float(theirs[f"body_{key}"].values.ravel()[0])
        assert b == pytest.approx(a, rel=1e-8, abs=1e-8), key
    assert theirs.fairlead_tension.values == pytest.approx(ours.fairlead_tension.values, rel=1e-8)


@pytest.mark.parametrize("edit, expected", [
    (lambda d: d["bodies"]["buoy"].update(waterplane_area=3.0),
     "has a waterplane.*no waterplane and no hydrostatic stiffness"),
    (lambda d: d["bodies"]["buoy"].update(hydrostatic_stiffness=[[0.0] * 6] * 5 + [[0.0] * 5 + [1.0]]),
     "hydrostatic_stiffness matrix"),
    (lambda d: d["bodies"]["buoy"].update(center_of_buoyancy=[0.4, -0.2, 0.5]),
     "centre of buoyancy.*centre of gravity"),
    (lambda d: d["bodies"]["buoy"].update(linear_damping=[[1.0] * 6] * 6), "linear_damping"),
    (lambda d: d["bodies"]["buoy"]["quadratic_damping"][0].__setitem__(1, 10.0), "off its diagonal"),
    (lambda d: d["bodies"]["buoy"]["added_mass"][3].__setitem__(3, 10.0), "added mass in rotation"),
    (lambda d: d["bodies"]["buoy"].update(external_force=[1.0e3, 0, 0, 0, 0, 0]), "external force"),
    (lambda d: d["bodies"]["buoy"].update(pinned=True), "free and pinned"),
    (lambda d: d["bodies"]["buoy"].update(wind={"surge": [1.0], "sway": [1.0], "yaw": [0.0], "height": 5.0}),
     "wind areas"),
    (lambda d: (d["bodies"]["buoy"].pop("added_mass"), d["bodies"]["buoy"].update(
        hydrodynamics={"file": str(ROOT / "examples" / "data" / "volturnus" / "IEA-15-240-RWT-UMaineSemi")})),
     "hydrodynamic database"),
    (lambda d: d["points"]["pad1"].update(mass=50.0), "point 'pad1' on body 'buoy' has mass 50 kg"),
])
def test_what_a_moordyn_body_cannot_hold_is_refused_by_name(edit, expected, tmp_path):
    case = _body_case(tmp_path, edit)
    with pytest.raises(InputError, match=r"MoorDyn cannot express it\. Suggested fix: ") as info:
        case_to_deck(case)
    assert re.search(expected, str(info.value)), str(info.value)

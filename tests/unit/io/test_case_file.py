"""Unit tests of case-file reading and validation (seacable.io.case_file)."""

import pickle
import textwrap
from pathlib import Path

import pytest

import seacable as sc
from seacable.io import dump_case, parse_case
from seacable.sweeps import is_sweep_file

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"

GOOD = textwrap.dedent("""
    name: t
    line_types:
      chain: {diameter: 0.09, mass_per_length: 77.7066, axial_stiffness: 384.243e6}
    line: {line_type: chain, length: 902.2}
    environment: {depth: 320.0}
    analysis: {type: static, fairlead: [848.67, -70.0]}
""")


def write(tmp_path, text, name="case.yaml"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return path


def test_good_file_loads_into_an_immutable_picklable_case(tmp_path):
    case = sc.load_case(write(tmp_path, GOOD))
    assert case.line.segments[0].line_type.axial_stiffness == 384.243e6  # YAML 1.1 reads "384.243e6" as text
    assert case.analysis.fairlead == (848.67, -70.0)
    assert pickle.loads(pickle.dumps(case)) == case


def test_dump_and_parse_round_trip(tmp_path):
    case = sc.load_case(write(tmp_path, GOOD))
    import yaml

    assert parse_case(yaml.safe_load(dump_case(case))) == case


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.yaml")), ids=lambda p: p.name)
def test_every_example_is_valid(path):
    if is_sweep_file(path):
        assert all(c.case is not None for c in sc.load_sweep(path).cases())
    else:
        sc.load_case(path)


@pytest.mark.parametrize("text, sweep", [
    ("base: case.yaml\ngrid:\n  line.length: [900, 910]\n", True),
    ("base: case.yaml\ntable: cases.csv\n", True),
    ("{base: case.yaml, grid: {line.length: [900, 910]}}\n", True),          # flow style
    ("'base': case.yaml\n\"grid\": {line.length: [900]}\n", True),           # quoted keys
    ("base: case.yaml\n", False),                                             # no grid nor table
    ("grid: {line.length: [900]}\n", False),
    ("name: t\nline: {base: x, grid: y}\n", False),                         # not at the top level
    ("- base\n- grid\n", False),                                             # a list
    ("base: [\n", False),                                                     # not YAML
    ("", False),
])
def test_a_sweep_file_is_told_from_a_case_by_its_top_level_keys(tmp_path, text, sweep):
    assert is_sweep_file(write(tmp_path, text, "f.yaml")) is sweep


@pytest.mark.parametrize("edit, expected", [
    (("diameter: 0.09", "diamter: 0.09"), "line_types.chain has an unknown key 'diamter'. Did you mean 'diameter'?"),
    (("diameter: 0.09", "diameter: -0.09"), "line_types.chain.diameter must be > 0 m, got -0.09 m"),
    (("diameter: 0.09", "diameter: .nan"), "line_types.chain.diameter must be a finite number"),
    (("length: 902.2", "length: long"), "line.segments[0].length must be a number in m, got 'long'"),
    (("line_type: chain,", "line_type: chian,"), ("'chian' is not defined in line_types (defined: chain). "
                                                 "Did you mean 'chain'?")),
    (("type: static", "type: statik"), "analysis.type must be one of"),
    (("depth: 320.0", "dept: 320.0"), "environment has an unknown key 'dept'. Did you mean 'depth'?"),
    (("name: t", "nme: t"), "has an unknown key 'nme'. Did you mean 'name'?"),
    (("{depth: 320.0}", "{}"), "analysis 'static' needs environment.depth"),
])
def test_bad_files_name_the_key_value_unit_and_fix(tmp_path, edit, expected):
    text = GOOD.replace(*edit)
    assert text != GOOD
    with pytest.raises(sc.CaseFileError) as info:
        sc.load_case(write(tmp_path, text))
    assert expected in str(info.value)
    assert str(tmp_path) in str(info.value)  # the file is named


def test_missing_file_and_bad_yaml(tmp_path):
    with pytest.raises(sc.CaseFileError, match="does not exist"):
        sc.load_case(tmp_path / "nope.yaml")
    with pytest.raises(sc.CaseFileError, match=r"not valid YAML at line \d+, column \d+"):
        sc.load_case(write(tmp_path, "line: [1, 2\nanalysis: x\n"))
    with pytest.raises(sc.CaseFileError, match="must be a mapping"):
        sc.load_case(write(tmp_path, "- just\n- a list\n"))


@pytest.mark.parametrize("given, fix", [({"name": "a case"}, "parse_case"), (None, "the path of a YAML case file"),
                                        (3.0, "the path of a YAML case file")])
def test_a_case_given_where_its_path_goes_is_a_clear_error(given, fix):
    """load_case (and load_case_data) given a mapping or nothing: one InputError naming the type and the fix,
    not pathlib's TypeError."""
    from seacable.io.case_file import load_case_data

    for load in (sc.load_case, load_case_data):
        with pytest.raises(sc.InputError, match=f"must be a str or a path, got {type(given).__name__}.*{fix}"):
            load(given)


def test_several_problems_are_all_reported(tmp_path):
    text = GOOD.replace("diameter: 0.09", "diameter: -1").replace("length: 902.2", "length: -5")
    with pytest.raises(sc.CaseFileError, match="2 problems") as info:
        sc.load_case(write(tmp_path, text))
    assert "diameter must be > 0 m" in str(info.value) and "length must be > 0 m" in str(info.value)


def test_cases_built_in_code_equal_cases_from_files(tmp_path):
    chain = sc.LineType(diameter=0.09, mass_per_length=77.7066, axial_stiffness=384.243e6)
    case = sc.Case(name="t", line_types={"chain": chain}, line=sc.Line.single(chain, 902.2),
                   environment=sc.Environment(depth=320.0),
                   analysis=sc.StaticAnalysis(fairlead=(848.67, -70.0)))
    assert case == sc.load_case(write(tmp_path, GOOD))


# --------------------------------------------------------------------------- duplicated keys (issue 17)

@pytest.mark.parametrize("text, key, first, second", [
    # two analysis blocks: PyYAML kept the second silently, the case ran a modal analysis
    (GOOD + "analysis: {type: modal}\n", "analysis", 7, 8),
    # a key repeated inside a nested mapping
    (GOOD.replace("environment: {depth: 320.0}", "environment:\n  depth: 320.0\n  seabed: {}\n  depth: 32.0"),
     "depth", 7, 9),
    (GOOD.replace("line_types:\n", "line_types:\n  chain: {diameter: 0.1}\n"), "chain", 4, 5),
])
def test_a_key_given_twice_is_an_error_naming_both_lines(tmp_path, text, key, first, second):
    path = write(tmp_path, text)
    with pytest.raises(sc.CaseFileError) as info:
        sc.load_case(path)
    message = str(info.value)
    assert message.startswith(f"{path}: key '{key}' is given twice in the same mapping, at line {first} and at "
                              f"line {second}")
    assert "Suggested fix:" in message


def test_a_sweep_file_with_a_key_given_twice_is_refused(tmp_path):
    write(tmp_path, GOOD, "base.yaml")
    sweep = write(tmp_path, "base: base.yaml\ngrid:\n  line.segments.0.length: [900.0, 905.0]\n"
                            "grid:\n  environment.depth: [300.0]\n", "sweep.yaml")
    with pytest.raises(sc.CaseFileError, match=r"sweep.yaml: key 'grid' is given twice .* at line 2 and at line 4"):
        sc.load_sweep(sweep)


def test_merge_keys_may_override_and_equal_values_in_other_mappings_are_fine(tmp_path):
    text = GOOD.replace("analysis: {type: static, fairlead: [848.67, -70.0]}",
                        "defaults: &d {type: static, fairlead: [1.0, -70.0]}\n"
                        "analysis:\n  <<: *d\n  fairlead: [848.67, -70.0]").replace("name: t", "name: t\n")
    from seacable.io.case_file import read_yaml

    data, _ = read_yaml(write(tmp_path, text))
    assert data["analysis"] == {"type": "static", "fairlead": [848.67, -70.0]}  # the merge is overridden

"""Units in case files (issue 41): a number with a unit is read into the field's SI number, and a wrong one is refused.

The SI numbers asserted are the units' definitions (a knot is 1852 m per hour, a tonne 1000 kg, a degree pi/180
rad: SI Brochure, 9th ed., tables 8 and 9), so the tolerance is round-off (1e-12 relative: one conversion factor
and a multiplication). Errors are checked through ``seacable validate`` (exit status 2) and ``seacable run`` alike.
"""

from __future__ import annotations

import json
import math
import re
import warnings
from pathlib import Path

import pytest
import yaml

import seacable as sc
from seacable.cli import main
from seacable.errors import InputError

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SRC = Path(sc.__file__).resolve().parent
KNOT = 1852.0 / 3600.0   # [m/s], by definition
DEG = math.pi / 180.0    # [rad]


def _steady(**changes) -> dict:
    """Paper 000's steady tow (examples/paper000_steady_statics.yaml) as data, with key paths changed."""
    data = yaml.safe_load((EXAMPLES / "paper000_steady_statics.yaml").read_text())
    for path, value in changes.items():
        *head, last = path.split(".")
        node = data
        for key in head:
            node = node[key]
        node[last] = value
    return data


def _turn(**vessel) -> dict:
    data = yaml.safe_load((EXAMPLES / "paper000_turn.yaml").read_text())
    data["analysis"]["vessel"].update(vessel)
    return data


def _write(tmp_path, data, name="case.yaml") -> Path:
    path = tmp_path / name
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path


@pytest.mark.parametrize(("key", "typed", "si"), [
    ("line_types.towcable.diameter", "35 mm", 0.035),
    ("line_types.towcable.diameter", "3.5 cm", 0.035),
    ("line_types.towcable.mass_per_length", "2.79 kg/m", 2.79),
    ("line_types.towcable.weight_in_water", "17.7 N/m", 17.7),
    ("line_types.towcable.axial_stiffness", "423.3 kN", 4.233e5),
    ("line_types.towcable.axial_stiffness", "0.4233 MN", 4.233e5),
    ("line.length", "170 m", 170.0),
    ("line.length", "0.1 nmi", 185.2),
    ("environment.water_density", "1.025 t/m^3", 1025.0),
    ("environment.current.speed", "-2 kn", -2 * KNOT),
    ("environment.current.heading", "45 deg", 45 * DEG),
    ("environment.current.heading", "0.5 rad", 0.5),
    ("analysis.vessel_speed", "3 kn", 3 * KNOT),
    ("analysis.vessel_speed", "3.6 km/h", 1.0),
])
def test_each_unit_form_is_read_as_the_SI_number(key, typed, si):
    case = sc.Case.parse(_steady(**{key: typed}))
    obj = case
    for part in key.split("."):
        obj = obj[part] if isinstance(obj, dict) else getattr(obj, part)
    if key.startswith("line."):
        obj = case.line.segments[0].length
    assert obj == pytest.approx(si, rel=1e-12)


def test_vessel_speed_heading_and_turn_rate_in_units():
    vessel = sc.Case.parse(_turn(speed="3 kn", heading="45 deg", turn_rate="3 deg/s", start=["1 km", "-20 m"])
                           ).analysis.vessel
    assert vessel.speed == pytest.approx(3 * KNOT, rel=1e-12)
    assert vessel.heading == pytest.approx(math.pi / 4, rel=1e-12)
    assert vessel.turn_rate == pytest.approx(3 * DEG, rel=1e-12)
    assert vessel.start == pytest.approx((1000.0, -20.0), rel=1e-12)   # a vector's items take units too


def test_mass_breaking_load_and_fairlead_in_units():
    data = yaml.safe_load((EXAMPLES / "oc3_hywind_static.yaml").read_text())
    fairlead = data["analysis"]["fairlead"]
    data["analysis"]["fairlead"] = [f"{fairlead[0] / 1e3} km", f"{fairlead[1]} m"]
    lt = next(iter(data["line_types"].values()))
    lt["breaking_load"] = "7500 kN"
    lt["mass_per_length"] = f"{lt['mass_per_length'] * 1e-3} t/m"
    case = sc.Case.parse(data)
    assert case.analysis.fairlead == pytest.approx(tuple(fairlead), rel=1e-12)
    line_type = next(iter(case.line_types.values()))
    assert line_type.breaking_load == pytest.approx(7.5e6, rel=1e-12)
    assert line_type.mass_per_length == pytest.approx(77.7066, rel=1e-12)
    point = sc.PointMass(s=10.0, mass="10 t", volume="2 m^3")
    assert (point.mass, point.volume) == pytest.approx((1e4, 2.0), rel=1e-12)


def test_degree_warning_stays_for_plain_numbers_only():
    with pytest.warns(UserWarning, match="degrees"):
        sc.Case.parse(_steady(**{"environment.current.heading": 45}))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sc.Case.parse(_steady(**{"environment.current.heading": "45 deg"}))


BAD = [
    ("line.length", "3 kN", "must be a length in m, got '3 kN', a force"),
    ("line_types.towcable.diameter", "35 furlongz", "unknown unit 'furlongz'"),
    ("line.length", "2 nm", "ambiguous unit 'nm'"),
    ("environment.water_density", "1 ton/m^3", "ambiguous unit 'ton'"),
    ("analysis.vessel_speed", "3 kt", "ambiguous unit 'kt'"),
    ("environment.current.heading", "3 m", "must be an angle in rad"),
    ("line_types.towcable.drag_normal", "1.5 m", "takes a plain number (no unit)"),
]


@pytest.mark.parametrize(("key", "typed", "message"), BAD)
def test_a_wrong_unit_is_refused_naming_the_key(key, typed, message):
    with pytest.raises(InputError) as err:
        sc.Case.parse(_steady(**{key: typed}))
    text = str(err.value)
    assert message in text and "Suggested fix" in text
    shown = key.replace("line.length", "line.segments[0].length")
    assert shown in text


def test_a_rate_in_hz_is_not_a_rate_of_turn():
    """pint counts the radian as dimensionless: Hz and rad/s are a factor 2 pi apart and must not pass."""
    with pytest.raises(InputError, match=r"turn_rate must be a rate of turn in rad/s, got '0.5 Hz', a frequency"):
        sc.Case.parse(_turn(turn_rate="0.5 Hz"))
    with pytest.raises(InputError, match="must be a length in m"):
        sc.Case.parse(_steady(**{"line.length": "170 m*rad"}))


@pytest.mark.parametrize(("key", "typed"), [("line.length", "3 kN"), ("line_types.towcable.diameter", "35 furlongz")])
def test_validate_and_run_refuse_a_wrong_unit_alike(tmp_path, capsys, key, typed):
    path = _write(tmp_path, _steady(**{key: typed}))
    assert main(["validate", str(path)]) == 2
    problem = next(line for line in capsys.readouterr().err.splitlines() if typed in line)
    assert "Suggested fix" in problem
    assert main(["run", str(path), "-o", str(tmp_path / "r.nc"), "--no-plots"]) == 2
    assert problem in capsys.readouterr().err.splitlines()
    assert not (tmp_path / "r.nc").exists()


def test_a_result_stores_its_case_in_SI_and_reruns_the_same():
    plain = sc.run(sc.Case.parse(_steady()))
    typed = sc.run(sc.Case.parse(_steady(**{
        "line_types.towcable.diameter": "35 mm", "line.length": "170 m", "analysis.vessel_speed": "3.6 km/h",
        "environment.current.speed": "-3.6 km/h", "line_types.towcable.axial_stiffness": "423.3 kN"})))
    stored = yaml.safe_load(typed.attrs["case"])
    assert stored == yaml.safe_load(plain.attrs["case"])     # the same SI numbers as the plain case's
    assert not re.search(r"\d\s*(mm|km|kN|kn|deg)\b", typed.attrs["case"])
    rerun = sc.run(sc.Case.parse(stored))
    assert float(rerun.top_tension) == float(typed.top_tension) == float(plain.top_tension)


def test_angles_in_results_are_rad():
    """One convention: a towed cable's angles and the laying theory's entry angles in rad, against the closed
    forms (the critical angle, eq. (7) of paper 001), to round-off."""
    from seacable.laying.plan_run import LAY_TABLE_COLUMNS
    from seacable.statics.laying import laying_angle
    from seacable.statics.towed import critical_angle

    ds = sc.run(sc.Case.parse(_steady()))
    for name in ("angle", "top_angle", "critical_angle"):
        assert ds[name].attrs["units"] == "rad", name
    assert float(ds.critical_angle) == pytest.approx(float(critical_angle(17.7, 0.035, 2.0, 1.5, 1025.0)),
                                                     rel=1e-12)
    lay = sc.run(sc.load_case(EXAMPLES / "paper001_table1.yaml"))
    assert lay.angle.attrs["units"] == lay.angle_small.attrs["units"] == "rad"
    assert float(lay.angle.sel(ship_speed=2.0)) == pytest.approx(float(laying_angle(2.0, 4.49, 0.0225, 1.85, 1030.0)),
                                                                 rel=1e-12)
    assert {n: u for n, u, _ in LAY_TABLE_COLUMNS}["entry_angle"] == "rad"


def test_no_result_variable_is_in_degrees():
    """Every result variable (``var(dims, values, units, ...)``) states its angle in rad: none says degree."""
    found = []
    for path in SRC.rglob("*.py"):
        text = path.read_text()
        found += [f"{path.name}: {m.group(0)[:60]}" for m in re.finditer(r'var\([^()]*(\([^()]*\)[^()]*)*"(degree|deg)"',
                                                                         text)]
        found += [f"{path.name}: {m.group(0)}" for m in re.finditer(r'\("\w+", "(degree|deg)",', text)]
    assert not found


def test_schema_says_a_unit_string_is_accepted():
    from seacable.io import case_schema

    schema = json.loads(case_schema())
    line_type = schema["$defs"]["LineType"]["properties"]
    diameter = line_type["diameter"]
    assert diameter["unit"] == "m" and "type" not in diameter
    text = next(o for o in diameter["anyOf"] if o["type"] == "string")
    assert re.match(text["pattern"], "160 mm") and not re.match(text["pattern"], "mm")
    assert {"type": "number"} in diameter["anyOf"]
    assert "string" not in json.dumps(line_type["drag_normal"])   # no unit on a number without dimension


def test_the_unit_registry_loads_once():
    """pint's registry is built on the first unit and then reused (``import seacable`` and case files of plain
    numbers do not import pint at all: tests/unit/test_import.py counts it among the heavy modules)."""
    from seacable import _units

    sc.Case.parse(_steady(**{"analysis.vessel_speed": "3 kn"}))
    sc.Case.parse(_steady(**{"analysis.vessel_speed": "2 kn", "line.length": "0.17 km"}))
    assert _units._registry.cache_info().currsize == 1 and _units._registry.cache_info().misses == 1


def test_a_sweep_takes_units_and_its_summary_is_in_SI(tmp_path):
    """Swept values with units are read as the cases read them: each case and the summary's column hold the SI
    number (the summary of cases not run: its parameter columns are the same as after a run)."""
    from seacable.sweeps import load_sweep
    from seacable.sweeps.engine import summary_dataset

    sweep = tmp_path / "sweep.yaml"
    sweep.write_text(yaml.safe_dump({"name": "knots", "base": str(EXAMPLES / "paper000_steady_statics.yaml"),
                                     "grid": {"analysis.vessel_speed": ["1 kn", "2 kn"]}}))
    spec = load_sweep(sweep)
    assert [c.case.analysis.vessel_speed for c in spec.cases()] == pytest.approx([KNOT, 2 * KNOT], rel=1e-12)
    column = summary_dataset(spec, {})["analysis.vessel_speed"]
    assert column.attrs["units"] == "m/s"
    assert column.values.tolist() == pytest.approx([KNOT, 2 * KNOT], rel=1e-12)


def test_a_system_case_takes_units():
    """The system case (bodies, points, line types) reads units as the single-line cases do."""
    from seacable.system.case import SystemCase

    data = yaml.safe_load((EXAMPLES / "spread_mooring.yaml").read_text())
    data["line_types"]["chain"].update(diameter="171 mm", breaking_load="7.3 MN", mass_per_length="0.18 t/m")
    data["bodies"]["buoy"].update(mass="1650 t", position=["0 m", "0 m", "0 m", "0 deg", "0 deg", "90 deg"])
    data["points"]["anchor1"]["position"] = ["-0.606 km", "0 m", "-150 m"]
    data["lines"]["line1"]["length"] = "650 m"
    case = SystemCase.parse(data)
    chain = case.line_types["chain"]
    assert (chain.diameter, chain.breaking_load, chain.mass_per_length) == pytest.approx((0.171, 7.3e6, 180.0),
                                                                                         rel=1e-12)
    buoy = case.bodies["buoy"]
    assert buoy.mass == pytest.approx(1.65e6, rel=1e-12)
    assert buoy.position == pytest.approx((0.0, 0.0, 0.0, 0.0, 0.0, math.pi / 2), rel=1e-12)
    assert case.points["anchor1"].position == pytest.approx((-606.0, 0.0, -150.0), rel=1e-12)
    with pytest.raises(InputError, match=r"bodies\.buoy\.position\[5\] must be an angle in rad, got '90 m'"):
        SystemCase.parse({**data, "bodies": {"buoy": {**data["bodies"]["buoy"],
                                                      "position": [0, 0, 0, 0, 0, "90 m"]}}})

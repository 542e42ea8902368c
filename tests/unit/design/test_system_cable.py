"""The cable checks of a mooring system's cables (seacable.design.system_cable, issue 40): every line with bending
stiffness, with its own line types' limits and the analysis's design block, in each condition of a system_static and
over a system_dynamic run; the bad limits that validate and run both refuse.

References: the single line's checks (seacable.design.cable.cable_checks) on the same cable's shape. A cable of a
system between a fixed point and a point of a fixed body solves the same discrete equations as the single line
(tests/validation/test_system_cable.py: positions to 1e-7 m, curvature to 1e-9 1/m, tensions to 1e-3 N at a
residual of 1e-8 of the line's scale), so each check's value agrees with the single line's to that tolerance and its
limit, place and pass/fail exactly.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.cli import main
from seacable.design.cable import CableLimits, cable_check_table, cable_checks
from seacable.design.clearance import line_distance
from seacable.design.system_cable import (
    cable_lines,
    system_cable_check_table,
    system_cable_states,
    system_cable_view,
)
from seacable.errors import InputError
from seacable.system.case import SystemCase

#: Each check's tolerance against the single line's: the solvers' (module docstring), with a factor 10; a check's
#: unit -> absolute tolerance (curvature [1/m], tension [N], clearance [m], declination [rad]).
TOLERANCE = {"1/m": 1e-8, "N": 1e-2, "m": 1e-6, "rad": 1e-8}


def _rows(table, line, condition=None):
    t = table[table["line"] == line]
    return (t if condition is None else t[t["condition"] == condition]).set_index("check")


def _assert_same_checks(mine, single):
    """Each single-line check's value to the solvers' tolerance, its limit, place and status exactly."""
    for check, row in single.iterrows():
        got = mine.loc[check]
        assert got["value"] == pytest.approx(row["value"], abs=TOLERANCE[row["unit"]]), check
        assert got["limit"] == row["limit"] and got["s"] == row["s"] and got["status"] == row["status"], check
        if math.isfinite(row["utilisation"]):
            assert got["utilisation"] == pytest.approx(row["utilisation"], rel=1e-6), check


def test_each_cable_of_a_system_static_has_the_checks_of_the_same_cable_alone(two_cables):
    """Both cables, intact: the checks of each equal those of the same cable run alone (mooring_static, its own line
    type's limits and the same design block); the chain, without bending stiffness, has none."""
    table = system_cable_check_table(two_cables.static)
    assert cable_lines(two_cables.static) == ["cable_a", "cable_b"]
    assert set(table["line"]) == {"cable_a", "cable_b"}
    for name in ("cable_a", "cable_b"):
        single = cable_check_table(cable_checks(sc.run(two_cables.single(name)))).set_index("check")
        mine = _rows(table, name, "intact")
        assert list(mine.index) == list(single.index) + ["line clearance"]
        _assert_same_checks(mine, single)
    # each with its own limits: 1 / MBR and the allowables of its line type (a check with the other line's fails)
    for name, lim in two_cables.limits.items():
        mine = _rows(table, name, "intact")
        assert mine.loc["curvature (static MBR)", "limit"] == 1.0 / lim["minimum_bend_radius"]
        assert mine.loc["tension", "limit"] == lim["allowable_tension"]
        assert mine.loc["compression", "limit"] == -lim.get("allowable_compression", 0.0)
        assert mine.loc["sag bend clearance", "limit"] == two_cables.design["sag_bend_clearance"]
        assert mine.loc["hang-off declination (highest)", "limit"] == two_cables.design["hang_off_declination"][1]


def test_the_checks_pass_and_fail_by_their_limits(two_cables):
    """The sag bends stand 16.0 m (cable_a) and 10.9 m (cable_b) above the seabed: 12 m required, cable_b's fails
    and cable_a's passes; each status is its margin's sign."""
    table = system_cable_check_table(two_cables.static)
    a, b = _rows(table, "cable_a", "intact"), _rows(table, "cable_b", "intact")
    assert a.loc["sag bend clearance", "status"] == "pass" and 15.0 < a.loc["sag bend clearance", "value"] < 17.0
    assert b.loc["sag bend clearance", "status"] == "FAIL" and 10.0 < b.loc["sag bend clearance", "value"] < 12.0
    checked = table[table["passed"].notna()]
    np.testing.assert_array_equal(checked["passed"].astype(bool), checked["margin"] >= 0.0)


def test_each_condition_is_checked_and_a_removed_line_has_none(two_cables):
    """Damaged without cable_b: cable_b has no checks in it; the hull is fixed, so cable_a's shape and checks are
    the intact ones (to the solver's tolerance) but its nearest line is no longer cable_b's hang-off, 5 m from its
    own on the hull (both clamped at their points), but the chain."""
    ds = two_cables.static
    table = system_cable_check_table(ds)
    assert set(table[table["condition"] == "damaged"]["line"]) == {"cable_a"}
    intact, damaged = _rows(table, "cable_a", "intact"), _rows(table, "cable_a", "damaged")
    _assert_same_checks(damaged.drop(index="line clearance"), intact.drop(index="line clearance"))
    assert intact.loc["line clearance", "value"] == pytest.approx(5.0, abs=1e-9)
    chain = {d.other: d.distance for d in line_distance(ds.isel(condition=1), "cable_a", others=["chain"])}["chain"]
    assert damaged.loc["line clearance", "value"] == chain and chain > 15.0
    # the stacked states (range graphs over the conditions): cable_b only in the intact one
    assert list(system_cable_states(ds, "cable_b")["condition"].values) == ["intact"]
    assert list(system_cable_states(ds, "cable_a")["condition"].values) == ["intact", "damaged"]


def test_a_system_dynamic_run_checks_each_cable_against_its_own_dynamic_limits(two_cables):
    """1 s of still water from the equilibrium, the hull fixed: each cable's checks are the single line's checks of
    the run with its own line type's limits given explicitly (CableLimits.uniform: not read from the case), the
    curvature against the dynamic MBR; its values those of the static system (nothing moves: to the solvers'
    tolerance)."""
    dyn = system_cable_check_table(two_cables.dynamic)
    static = system_cable_check_table(two_cables.static)
    design = {k: v for k, v in two_cables.design.items() if k != "line_clearance"}
    for name, lim in two_cables.limits.items():
        n = two_cables.dynamic.sizes["node"]  # the lines' nodes, the shorter ones padded with NaN
        limits = CableLimits.uniform(n, **lim, **design)
        expected = cable_check_table(cable_checks(two_cables.dynamic, limits, name)).set_index("check")
        mine = _rows(dyn, name)
        assert list(mine.index) == list(expected.index) + ["line clearance"]
        for check, row in expected.iterrows():
            assert mine.loc[check, "value"] == row["value"] and mine.loc[check, "limit"] == row["limit"], check
            assert mine.loc[check, "status"] == row["status"], check
        kappa = mine.loc["curvature (dynamic MBR)"]
        assert kappa["utilisation"] == pytest.approx(kappa["value"] * lim["minimum_bend_radius_dynamic"], rel=1e-12)
        still = _rows(static, name, "intact")
        assert kappa["value"] == pytest.approx(still.loc["curvature (static MBR)", "value"], abs=1e-8)
        for check in ("tension", "sag bend clearance", "hang-off declination (lowest)"):
            assert mine.loc[check, "value"] == pytest.approx(still.loc[check, "value"],
                                                             abs=TOLERANCE[still.loc[check, "unit"]]), check


def test_the_66kv_system_checks_its_cable_in_each_condition_on_that_condition_s_shape():
    """examples/cable_66kv_system.yaml with chain 2 broken (damaged_lines): the free hull drifts and turns, and the
    cable's shape changes (its largest curvature from 0.050 to 0.039 1/m); each condition's checks read that
    condition's result: the largest curvature and element tension, the declination of the end element at end B (the
    hang-off), and the distance to the chains still there."""
    from pathlib import Path

    case = sc.load_case(Path(__file__).resolve().parents[3] / "examples" / "cable_66kv_system.yaml")
    data = case.model_dump(mode="json", exclude_none=True)
    data["analysis"]["damaged_lines"] = ["chain2"]
    data["analysis"]["design"].update(sag_bend_clearance=30.0, hog_bend_clearance=50.0, hang_off_declination=[0.05, 0.4])
    ds = sc.run(type(case).parse(data))
    table = system_cable_check_table(ds)
    assert set(table["line"]) == {"cable"}  # the chains do not bend
    got = {}
    for k, condition in enumerate(("intact", "damaged")):
        rows = _rows(table, "cable", condition)
        one = ds.sel(condition=condition, line="cable")
        kappa = float(np.nanmax(one["curvature"].values))
        assert rows.loc["curvature (static MBR)", "value"] == kappa
        assert rows.loc["curvature (static MBR)", "utilisation"] == pytest.approx(kappa * 2.37, rel=1e-12)
        assert rows.loc["tension", "value"] == float(np.nanmax(one["fe_segment_tension"].values))
        declination = one["declination"].values
        end_b = declination[np.isfinite(declination)][-1]
        assert rows.loc["hang-off declination (lowest)", "value"] == end_b
        others = ["chain1", "chain3"] + (["chain2"] if condition == "intact" else [])
        nearest = min(d.distance for d in line_distance(ds.isel(condition=k), "cable", others=others))
        assert rows.loc["line clearance", "value"] == nearest
        got[condition] = rows
        assert (rows["status"] == "pass").all()
    # the conditions differ (so a condition read in place of another is seen)
    for check, apart in (("curvature (static MBR)", 5e-3), ("hang-off declination (lowest)", 1e-2),
                         ("sag bend clearance", 1.0), ("hog bend clearance", 1.0)):
        assert abs(got["intact"].loc[check, "value"] - got["damaged"].loc[check, "value"]) > apart, check


def test_the_view_of_a_condition_and_its_refusals(two_cables):
    ds = two_cables.static
    view = system_cable_view(ds, "cable_b", "intact")
    # its finite-element nodes: 60 elements and the buoyancy section's two ends
    assert view.sizes["node"] == 62 and str(view["line"].values) == "cable_b"
    assert view["s"].values[-1] == two_cables.length["cable_b"]
    np.testing.assert_array_equal(view["curvature"].values,
                                  ds["curvature"].sel(condition="intact", line="cable_b").values[:view.sizes["node"]])
    with pytest.raises(InputError, match="no line 'chain' with curvature.*Suggested fix"):
        system_cable_view(ds, "chain")
    with pytest.raises(InputError, match="condition='storm' is not one of.*Suggested fix"):
        system_cable_view(ds, "cable_a", "storm")
    with pytest.raises(InputError, match="system_static or system_dynamic.*Suggested fix"):
        system_cable_check_table(sc.run(two_cables.single("cable_a")))


# ---------------------------------------------------------------------------------------------------- bad limits

def _bad_cases():
    """(what, edit of the case's data, words of the message) for the limits a system case refuses."""
    def design(**kw):
        return lambda d: d["analysis"]["design"].update(kw)

    def line_type(**kw):
        return lambda d: d["line_types"]["cb"].update(kw)

    def hung_at_a(d):
        cable = d["lines"]["cable_b"]
        cable["end_a"], cable["end_b"] = cable["end_b"], cable["end_a"]
        cable["end_a_condition"] = cable.pop("end_b_condition")

    def no_cable(d):
        for name in ("cable_a", "cable_b"):
            del d["lines"][name]
        d["analysis"]["design"] = {"sag_bend_clearance": 5.0}

    def catenary(d):
        for name in ("cable_a", "cable_b"):
            d["lines"][name].pop("sections")
            d["lines"][name].pop("end_b_condition")

    return [
        ("negative sag bend clearance", design(sag_bend_clearance=-1.0), ["sag_bend_clearance", "Suggested fix"]),
        ("hog bend clearance not a number", design(hog_bend_clearance="high"), ["hog_bend_clearance"]),
        ("declination range in degrees", design(hang_off_declination=[5.0, 20.0]),
         ["hang_off_declination", "looks like degrees", "Suggested fix"]),
        ("declination range reversed", design(hang_off_declination=[0.3, 0.1]), ["lowest < highest"]),
        ("zero line clearance", design(line_clearance=0.0), ["line_clearance", "Suggested fix"]),
        ("zero MBR", line_type(minimum_bend_radius=0.0), ["minimum_bend_radius"]),
        ("dynamic MBR below the static", line_type(minimum_bend_radius_dynamic=1.0), ["minimum_bend_radius_dynamic"]),
        ("negative allowable compression", line_type(allowable_compression=-5.0), ["allowable_compression"]),
        ("a hang-off range for a cable hung off at end A", hung_at_a,
         ["line 'cable_b'", "hung off at end A", "Suggested fix: swap"]),
        ("cable limits without a cable", no_cable, ["no line of the system has bending stiffness", "Suggested fix"]),
        ("cable limits on the catenary statics", catenary,
         ["catenary statics", "no bending", "Suggested fix: add 'statics: finite_element'"]),
    ]


@pytest.mark.parametrize(("what", "edit", "words"), _bad_cases(), ids=[c[0] for c in _bad_cases()])
@pytest.mark.parametrize("analysis", ["system_static", "system_dynamic"])
def test_bad_limits_are_refused_by_validate_and_run_alike(two_cables, tmp_path, capsys, what, edit, words, analysis):
    extra = {"duration": 1.0} if analysis == "system_dynamic" else {}
    data = two_cables.data({"type": analysis, "design": dict(two_cables.design), **extra})
    two_cables.case(data["analysis"])  # the case as given is good
    edit(data)
    if what == "cable limits on the catenary statics":
        fixed = {**data, "analysis": {**data["analysis"], "statics": "finite_element"}}
        SystemCase.parse(fixed if analysis == "system_static" else data)  # as the message suggests; the dynamics'
        if analysis == "system_dynamic":                                  # lines bend whatever the statics
            return
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    messages = []
    for argv in (["validate", str(path)], ["run", str(path), "-o", str(tmp_path / "bad.nc")]):
        assert main(argv) == 2, (what, argv[0])
        messages.append(capsys.readouterr().err)
    assert not (tmp_path / "bad.nc").exists()
    for message in messages:
        assert "Traceback" not in message
        for word in words:
            assert word in message, (what, word, message)

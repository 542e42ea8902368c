"""Design checks (issue 20): line tension by DNV-OS-E301 (2010) Ch.2 Sec.2 (ULS and ALS partial safety factors,
S_C = 0.95 S_mbs) and API RP 2SK 3rd ed. (2005) Table 2 (factors of safety), anchor uplift and offset.

The factors below are written out from the standards' tables, not read from the module, so a wrong factor in
the module fails a test. The arithmetic is a handful of float operations: relative tolerance 1e-12 (a few
units in the last place of float64)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from seacable.design import (
    CheckResult,
    anchor_uplift,
    api_tension,
    check_table,
    dnv_als,
    dnv_uls,
    offset_check,
)
from seacable.errors import InputError

REL = 1e-12  # float64 round-off of a few multiplications and a division

MEAN, DYN, MBS = 2.0e6, 1.0e6, 7.3e6  # [N]; mean != dyn so that swapped factors give another T_d


def test_dnv_uls_cc1_worked_example():
    """T_d = 1.10 * 2 MN + 1.50 * 1 MN = 3.7 MN; S_C = 0.95 * 7.3 MN = 6.935 MN; utilisation 0.53353."""
    r = dnv_uls("L1", MEAN, DYN, MBS)
    assert r.check == "DNV-OS-E301 ULS CC1" and r.item == "L1"
    assert r.demand == pytest.approx(3.7e6, rel=REL)
    assert r.capacity == pytest.approx(6.935e6, rel=REL)
    assert r.utilisation == pytest.approx(3.7 / 6.935, rel=REL)
    assert r.utilisation == pytest.approx(0.5335255948, rel=1e-9)
    assert r.passed and r.margin == pytest.approx(6.935e6 - 3.7e6, rel=REL) and r.unit == "N"  # S_C - T_d [N]
    assert r.formula == "T_d = 1.10 T_c,mean + 1.50 T_c,dyn <= S_C = 0.95 MBS"
    assert "DNV-OS-E301 (October 2010) Ch.2 Sec.2" in r.reference and "consequence class 1" in r.reference


@pytest.mark.parametrize("check, cc, gamma_mean, gamma_dyn", [
    (dnv_uls, 1, 1.10, 1.50),
    (dnv_uls, 2, 1.40, 2.10),
    (dnv_als, 1, 1.00, 1.10),
    (dnv_als, 2, 1.00, 1.25),
])
def test_dnv_partial_safety_factors(check, cc, gamma_mean, gamma_dyn):
    """Each limit state and consequence class: T_d = gamma_mean T_mean + gamma_dyn T_dyn against 0.95 MBS
    (CC2 ULS 4.9 MN, ALS CC1 3.1 MN, ALS CC2 3.25 MN)."""
    r = check("L2", MEAN, DYN, MBS, consequence_class=cc)
    limit = "ULS" if check is dnv_uls else "ALS"
    assert r.check == f"DNV-OS-E301 {limit} CC{cc}"
    assert r.demand == pytest.approx(gamma_mean * MEAN + gamma_dyn * DYN, rel=REL)
    assert r.capacity == pytest.approx(0.95 * MBS, rel=REL)
    assert r.utilisation == pytest.approx((gamma_mean * MEAN + gamma_dyn * DYN) / (0.95 * MBS), rel=REL)
    assert f"{gamma_mean:.2f} T_c,mean + {gamma_dyn:.2f} T_c,dyn" in r.formula
    assert limit in r.reference and f"consequence class {cc}" in r.reference


def test_dnv_cc2_and_als_numbers():
    """The same line: ULS CC2 4.9 MN (utilisation 0.70656), ALS CC1 3.1 MN, ALS CC2 3.25 MN."""
    assert dnv_uls("L", MEAN, DYN, MBS, 2).demand == pytest.approx(4.9e6, rel=REL)
    assert dnv_uls("L", MEAN, DYN, MBS, 2).utilisation == pytest.approx(0.7065609229, rel=1e-9)
    assert dnv_als("L", MEAN, DYN, MBS, 1).demand == pytest.approx(3.1e6, rel=REL)
    assert dnv_als("L", MEAN, DYN, MBS, 2).demand == pytest.approx(3.25e6, rel=REL)


@pytest.mark.parametrize("condition, method, fos, percent", [
    ("intact", "quasi_static", 2.00, 50),
    ("intact", "dynamic", 1.67, 60),
    ("damaged", "quasi_static", 1.43, 70),
    ("damaged", "dynamic", 1.25, 80),
    ("transient", "quasi_static", 1.18, 85),
    ("transient", "dynamic", 1.05, 95),
])
def test_api_factors_of_safety(condition, method, fos, percent):
    """API RP 2SK Table 2: capacity MBS / FoS (50, 60, 70, 80, 85, 95 % of MBS)."""
    r = api_tension("L3", 3.0e6, MBS, condition=condition, method=method)
    assert r.check == f"API RP 2SK {condition} {method.replace('_', '-')}"
    assert r.demand == 3.0e6
    assert r.capacity == pytest.approx(MBS / fos, rel=REL)
    assert r.utilisation == pytest.approx(3.0e6 * fos / MBS, rel=REL)
    assert r.passed == (3.0e6 * fos / MBS <= 1.0)
    assert r.formula == f"T_max <= MBS / {fos:.2f} ({percent} % of MBS)"
    assert "API RP 2SK 3rd edition" in r.reference and "Table 2" in r.reference


def test_api_defaults_are_intact_dynamic():
    """4.5 MN on a 7.3 MN line, intact, dynamic: capacity 7.3 / 1.67 = 4.371 MN, utilisation 1.0295: fails."""
    r = api_tension("L", 4.5e6, MBS)
    assert r.check == "API RP 2SK intact dynamic" and r.capacity == pytest.approx(MBS / 1.67, rel=REL)
    assert r.utilisation == pytest.approx(1.0294520548, rel=1e-9)
    assert not r.passed and r.margin == pytest.approx(7.3e6 / 1.67 - 4.5e6, rel=REL) and r.margin < 0  # [N]


def test_pass_flips_exactly_at_utilisation_one():
    """passed is utilisation <= 1: a demand equal to the capacity passes, the next float above fails."""
    at = api_tension("L", MBS / 1.25, MBS, condition="damaged")
    assert at.utilisation == 1.0 and at.passed and at.margin == 0.0
    above = api_tension("L", np.nextafter(MBS / 1.25, math.inf), MBS, condition="damaged")
    assert above.utilisation > 1.0 and not above.passed

    assert offset_check("B", 30.0, 30.0).passed
    assert not offset_check("B", np.nextafter(30.0, math.inf), 30.0).passed

    # DNV: T_d = 1.50 T_dyn (no mean) on either side of S_C = 0.95 MBS by 1e-9
    for factor, expected in ((1 - 1e-9, True), (1 + 1e-9, False)):
        r = dnv_uls("L", 0.0, factor * 0.95 * MBS / 1.50, MBS)
        assert r.utilisation == pytest.approx(factor, rel=1e-12) and r.passed is expected


def test_anchor_uplift_on_a_drag_anchor():
    """Allowed uplift 0 N (drag anchor, intact): no pull passes with a margin of 0 N, a downward pull is no uplift,
    an upward pull fails with its margin in N; a zero capacity has no utilisation (None, never inf)."""
    none = anchor_uplift("A1", 0.0)
    assert none.passed and none.utilisation is None and none.demand == 0.0 and none.capacity == 0.0
    assert none.margin == 0.0 and none.unit == "N"
    down = anchor_uplift("A1", -5.0e3)
    assert down.passed and down.demand == 0.0 and down.utilisation is None and down.margin == 0.0
    up = anchor_uplift("A1", 1.0)
    assert not up.passed and up.utilisation is None and up.margin == -1.0 and up.demand == 1.0
    assert up.check == "anchor uplift" and "drag anchor" in up.reference


def test_anchor_uplift_round_off_is_a_thousandth_of_the_tension():
    """The OC3-Hywind demo's 35 N of computed pull on a grounded anchor under 700 kN of tension is round-off (5e-5
    of the tension, under UPLIFT_ROUND_OFF = 1e-3): no uplift, a pass with a margin of 0 N. The limit is exact:
    700 N under 700 kN (1e-3) is round-off, the next float above is uplift and fails by its own size."""
    t = 7.0e5
    r = anchor_uplift("A1", 35.0, tension=t)
    assert r.passed and r.demand == 0.0 and r.margin == 0.0 and r.utilisation is None
    assert anchor_uplift("A1", 700.0, tension=t).passed
    above = anchor_uplift("A1", np.nextafter(700.0, math.inf), tension=t)
    assert not above.passed and above.margin == -np.nextafter(700.0, math.inf)
    assert "1e-3" not in above.formula and "0.001 T_anchor" in above.formula
    # with an allowed uplift (a pile) the round-off is left out as well: 35 N of 100 kN is no use of it
    assert anchor_uplift("P1", 35.0, allowed=1.0e5, tension=t).utilisation == 0.0
    # a real lift-off: 60 kN up under 700 kN (4.9 deg) is uplift: against a 100 kN pile capacity 0.6, margin 40 kN
    pile = anchor_uplift("P1", 6.0e4, allowed=1.0e5, tension=t)
    assert pile.utilisation == pytest.approx(0.6, rel=REL) and pile.margin == pytest.approx(4.0e4, rel=REL)


def test_anchor_uplift_with_an_allowed_pull():
    """A pile that may take 100 kN: 50 kN is utilisation 0.5; 100 kN passes at exactly 1; 120 kN fails."""
    assert anchor_uplift("P1", 5.0e4, allowed=1.0e5).utilisation == pytest.approx(0.5, rel=REL)
    assert anchor_uplift("P1", 1.0e5, allowed=1.0e5).passed
    r = anchor_uplift("P1", 1.2e5, allowed=1.0e5)
    assert r.utilisation == pytest.approx(1.2, rel=REL) and not r.passed and r.capacity == 1.0e5


def test_offset_check():
    """12 m against a 30 m limit: utilisation 0.4, margin 18 m."""
    r = offset_check("FPSO", 12.0, 30.0)
    assert (r.check, r.item, r.unit, r.demand, r.capacity) == ("offset", "FPSO", "m", 12.0, 30.0)
    assert r.utilisation == pytest.approx(0.4, rel=REL) and r.margin == 18.0 and r.passed


def test_check_result_is_frozen():
    r = offset_check("B", 1.0, 2.0)
    assert isinstance(r, CheckResult)
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.utilisation = 0.0


def test_check_table():
    """One row per check, in order, with the API's columns; margin = capacity - demand in the row's unit; the
    drag anchor's utilisation NaN (no ratio to a zero capacity), no number of the table infinite."""
    results = [dnv_uls("L1", MEAN, DYN, MBS), api_tension("L1", 4.5e6, MBS), anchor_uplift("A1", 1.0),
               offset_check("FPSO", 12.0, 30.0)]
    table = check_table(results)
    assert list(table.columns) == ["check", "item", "unit", "demand", "capacity", "margin", "utilisation", "passed",
                                   "formula", "reference"]
    assert list(table["check"]) == ["DNV-OS-E301 ULS CC1", "API RP 2SK intact dynamic", "anchor uplift", "offset"]
    assert list(table["unit"]) == ["N", "N", "N", "m"]
    assert list(table["passed"]) == [True, False, False, True]
    assert table["demand"].iloc[0] == pytest.approx(3.7e6, rel=REL)
    assert table["capacity"].iloc[0] == pytest.approx(6.935e6, rel=REL)
    np.testing.assert_array_equal(table["margin"], table["capacity"] - table["demand"])
    assert math.isnan(table["utilisation"].iloc[2]) and table["margin"].iloc[2] == -1.0
    numbers = table[["demand", "capacity", "margin"]].to_numpy(float)
    assert np.isfinite(numbers).all() and not np.isinf(table["utilisation"].to_numpy(float)).any()
    empty = check_table([])
    assert empty.empty and list(empty.columns) == list(table.columns)


def test_check_table_refuses_other_objects():
    with pytest.raises(InputError, match=r"results\[1\] must be a CheckResult, got dict.*Suggested fix"):
        check_table([offset_check("B", 1.0, 2.0), {"check": "offset"}])


@pytest.mark.parametrize("mbs", [None, float("nan"), 0.0, -7.3e6, "7.3 MN", math.inf, [7.3e6, 7.3e6]])
@pytest.mark.parametrize("check", [dnv_uls, dnv_als])
def test_dnv_refuses_a_line_without_breaking_load(check, mbs):
    with pytest.raises(InputError, match=r"^line 'L7' has no breaking_load: give the line type's breaking_load "
                                         r"\[N\].*got .*Suggested fix: set breaking_load"):
        check("L7", MEAN, DYN, mbs)


@pytest.mark.parametrize("mbs", [None, float("nan"), 0.0])
def test_api_refuses_a_line_without_breaking_load(mbs):
    with pytest.raises(InputError, match=r"^line 'L7' has no breaking_load: give the line type's breaking_load"):
        api_tension("L7", 1.0e6, mbs)


@pytest.mark.parametrize("mean, dyn, message", [
    (-5.0, DYN, r"line 'L1' mean_tension must be >= 0 N, got -5 N\. Suggested fix: give the mean tension"),
    (MEAN, -1.0e3, r"line 'L1' dynamic_tension must be >= 0 N, got -1000 N\. Suggested fix: give the dynamic"),
    (float("nan"), DYN, r"line 'L1' mean_tension must be a finite number, got nan N\. Suggested fix"),
    (MEAN, None, r"line 'L1' dynamic_tension must be one number in N, got None\. Suggested fix"),
    (np.array([1.0, 2.0]), DYN, r"line 'L1' mean_tension must be one number in N, got .*Suggested fix"),
])
def test_dnv_refuses_bad_tensions(mean, dyn, message):
    with pytest.raises(InputError, match=message):
        dnv_uls("L1", mean, dyn, MBS)


@pytest.mark.parametrize("cc", [0, 3, "CC1", True, None, 1.5, np.array([1, 2])])
def test_dnv_refuses_an_unknown_consequence_class(cc):
    with pytest.raises(InputError, match=r"consequence_class must be 1 or 2 \(DNV-OS-E301 \(October 2010\) "
                                         r"Ch\.2 Sec\.2\), got .*Suggested fix: 1 where"):
        dnv_als("L1", MEAN, DYN, MBS, consequence_class=cc)


def test_api_refuses_bad_input():
    with pytest.raises(InputError, match=r"condition must be one of 'intact', 'damaged', 'transient', got 'intakt'\. "
                                         r"Suggested fix: did you mean 'intact'\?"):
        api_tension("L1", 1.0e6, MBS, condition="intakt")
    with pytest.raises(InputError, match=r"method must be one of 'dynamic', 'quasi_static', got 'quasi-static'\. "
                                         r"Suggested fix: did you mean 'quasi_static'\?"):
        api_tension("L1", 1.0e6, MBS, method="quasi-static")
    with pytest.raises(InputError, match=r"line 'L1' max_tension must be >= 0 N, got -1 N\. Suggested fix"):
        api_tension("L1", -1.0, MBS)


def test_anchor_and_offset_refuse_bad_input():
    with pytest.raises(InputError, match=r"anchor 'A1' vertical_force must be a finite number, got nan N\. "
                                         r"Suggested fix: give the largest upward"):
        anchor_uplift("A1", float("nan"))
    with pytest.raises(InputError, match=r"anchor 'A1' allowed uplift must be >= 0 N, got -10 N\. "
                                         r"Suggested fix: 0 N for a drag anchor"):
        anchor_uplift("A1", 0.0, allowed=-10.0)
    with pytest.raises(InputError, match=r"body 'B' offset must be >= 0 m, got -2 m\. Suggested fix"):
        offset_check("B", -2.0, 30.0)
    with pytest.raises(InputError, match=r"body 'B' offset limit must be > 0 m, got 0 m\. Suggested fix"):
        offset_check("B", 2.0, 0.0)
    with pytest.raises(InputError, match=r"body 'B' offset must be a finite number, got nan m"):
        offset_check("B", float("nan"), 30.0)


def test_anchor_round_off_of_a_slack_grounded_line_is_scaled_by_its_weight():
    """A slack line lying on the seabed has an anchor tension near zero: 1e-3 of it is no tolerance, and the
    solver's round-off of a few newtons up (here 5 N, the contact's residual) would fail a drag anchor. With the
    line's submerged weight W = 698 N/m x 902 m = 630 kN, anything up to 1e-3 W = 630 N is round-off; a real
    pull of 5 kN still fails."""
    from seacable.design.checks import uplift_demand

    weight = 698.094 * 902.2
    assert anchor_uplift("A1", 5.0, tension=1.0).passed is False  # the tension's tolerance alone: 1 mN
    ok = anchor_uplift("A1", 5.0, tension=1.0, weight=weight)
    assert ok.passed and ok.demand == 0.0 and "0.001 W_line if larger" in ok.formula
    assert uplift_demand([600.0, 640.0], [0.0, 0.0], weight).tolist() == [0.0, 640.0]
    assert anchor_uplift("A1", 5.0e3, tension=1.0, weight=weight).passed is False

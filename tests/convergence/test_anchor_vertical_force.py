"""The vertical force of a line on its anchor converges at second order, and a grounded anchor shows no uplift.

The end element pulls along its chord, whose slope is the line's at the element's middle; between the middle and
the anchor the half element's weight turns the line (the catenary's slope changes by ``w ds / T``). The pull alone
(``T dz / L``, what the anchor uplift check took before) over-states the anchor's vertical force by about half the
element's weight, a first-order error, and shows an uplift of up to that much at an anchor whose touchdown lies
within its first element (1.4 kN on the OC3-Hywind demo's intact anchors, 22.6 m elements; 15 kN below with
45 m elements). ``grounded_end_force`` takes the half element's weight off the pull's normal component, as far as
the seabed does not carry it. Checked against the exact elastic catenary (``static``) of the OC3-Hywind line, in
the single-line finite elements (``mooring_static``) and in a mooring system's time loop (``system_dynamic``).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.mooring.run import grounded_end_force

EXAMPLE = yaml.safe_load((Path(__file__).parents[2] / "examples" / "oc3_hywind_static.yaml").read_text(
    encoding="utf-8"))


def _exact(fairlead_x: float):
    return sc.run(sc.parse_case({**EXAMPLE, "analysis": {"type": "static", "fairlead": [fairlead_x, -70.0]}}))


def _fe(fairlead_x: float, n: int):
    return sc.run(sc.parse_case({**EXAMPLE, "analysis": {"type": "mooring_static", "fairlead": [fairlead_x, -70.0],
                                                         "n_elements": n}}))


def test_a_line_lying_on_the_seabed_pulls_along_it():
    # flat: the seabed carries the half element's weight; the pull is the catenary's H (exact)
    np.testing.assert_allclose(grounded_end_force([5.0e5, 0.0, 0.0], 8.0e3), [5.0e5, 0.0, 0.0], rtol=0, atol=1e-9)
    # on a 0.1 rad slope, lying along it: the same, along the slope
    a = 0.1
    pull = 5.0e5 * np.array([math.cos(a), 0.0, math.sin(a)])
    np.testing.assert_allclose(grounded_end_force(pull, 8.0e3, a), pull, rtol=0, atol=1e-9)


def test_a_line_rising_from_the_anchor_loses_its_half_weight_normal_to_the_seabed():
    pull = np.array([5.0e5, 0.0, 3.0e4])
    # flat: T dz/L less the half weight, 3e4 - 8e3 N (closed form, exact)
    np.testing.assert_allclose(grounded_end_force(pull, 8.0e3), [5.0e5, 0.0, 2.2e4], rtol=0, atol=1e-9)
    # a buoyant end element (negative weight in water) lifts the anchor more: 3e4 + 2e3 N
    np.testing.assert_allclose(grounded_end_force(pull, -2.0e3), [5.0e5, 0.0, 3.2e4], rtol=0, atol=1e-9)
    # a slope: only the weight's component normal to the seabed, W cos(a), comes off the normal pull
    a = 0.2
    n = np.array([-math.sin(a), 0.0, math.cos(a)])
    pull = 5.0e5 * np.array([math.cos(a + 0.06), 0.0, math.sin(a + 0.06)])   # 0.06 rad above the slope
    assert pull @ n > 8.0e3 * math.cos(a)
    out = grounded_end_force(pull, 8.0e3, a)
    assert out @ n == pytest.approx(pull @ n - 8.0e3 * math.cos(a), abs=1e-9)
    t = np.array([math.cos(a), 0.0, math.sin(a)])
    assert out @ t == pytest.approx(pull @ t, abs=1e-9)   # along the seabed: unchanged


def test_anchor_uplift_converges_at_second_order():
    # fairlead at 860 m: the line leaves the seabed at the anchor, V = 25.5 kN (exact catenary)
    exact = float(_exact(860.0)["V_anchor"])
    assert exact > 2.0e4
    errors = [float(_fe(860.0, n)["anchor_vertical_force"]) - exact for n in (20, 40, 80)]
    orders = [math.log2(abs(errors[k] / errors[k + 1])) for k in range(2)]
    # measured -362, -90, -23 N: order 2.01, 1.99 (the pull alone: 15.4, 7.8, 3.9 kN, order 1); 1.8 leaves room for
    # the discretisation's higher-order terms, an order-1 error fails it
    assert min(orders) > 1.8, (errors, orders)
    assert abs(errors[-1]) < 50.0, errors   # 23 N of 25.5 kN with 80 elements


@pytest.mark.parametrize("fairlead_x, n", [(858.0, 20), (858.0, 40), (857.0, 20)])
def test_a_touchdown_within_the_first_element_is_no_uplift(fairlead_x, n):
    # 858 m: 0.61 m on the seabed, 857 m: 17.0 m (exact catenary), within the first element (45 m at n = 20, 22.6 m
    # at n = 40); V = 0 exactly. The pull alone gave 15.0, 7.4 and 4.0 kN of uplift here
    assert float(_exact(fairlead_x)["V_anchor"]) == 0.0
    ds = _fe(fairlead_x, n)
    # the uplift check's own round-off bound, 1e-3 T (seacable.design.checks.UPLIFT_ROUND_OFF)
    assert float(ds["anchor_vertical_force"]) <= 1e-3 * float(ds["anchor_tension"])


def _system(fairlead_x: float, n: int):
    """The OC3-Hywind line in a mooring system between two fixed points: a short run from its equilibrium."""
    lt = EXAMPLE["line_types"]["oc3"]
    return sc.parse_case({
        "name": "oc3_line",
        "line_types": {"oc3": {k: lt[k] for k in ("diameter", "mass_per_length", "weight_in_water",
                                                  "axial_stiffness", "drag_normal", "added_mass_normal")}},
        "environment": {"water_density": 1025.0, "gravity": 9.80665, "depth": 320.0},
        "points": {"anchor": {"kind": "fixed", "position": [0.0, 0.0, -320.0]},
                   "fair": {"kind": "fixed", "position": [fairlead_x, 0.0, -70.0]}},
        "lines": {"l": {"line_type": "oc3", "length": 902.2, "end_a": "anchor", "end_b": "fair"}},
        "analysis": {"type": "system_dynamic", "duration": 0.5, "time_step": 0.01, "output_interval": 0.5,
                     "n_elements": n}})


def test_a_system_reports_the_anchor_force_of_the_single_line_rule():
    exact = float(_exact(860.0)["V_anchor"])
    force = [float(sc.run(_system(860.0, n))["anchor_vertical_force"].isel(time=-1, line=0)) for n in (20, 40)]
    errors = [f - exact for f in force]
    # the single line's finite elements: -362 and -90 N at 20 and 40 elements (the pull alone: 15.4 and 7.8 kN);
    # the system's time loop holds its start within 0.01 N over 0.5 s. Order 2 within 0.2
    assert math.log2(errors[0] / errors[1]) > 1.8, errors
    assert abs(errors[1]) < 150.0, errors
    # a grounded anchor (17 m on the seabed, within the 45 m first element): no uplift
    ds = sc.run(_system(857.0, 20))
    assert float(ds["anchor_vertical_force"].isel(time=-1, line=0)) <= 1e-3 * float(
        ds["anchor_tension"].isel(time=-1, line=0))

"""Slack, grounded and close-ended lines in the mooring finite-element model, against the catenary.

Issue 17 items 2, 6 and 8: a slack line (part of it on the seabed, the rest hanging straight up, H = 0),
a line lying entirely on the seabed and a hanging line whose ends are close together are ordinary
states and must solve (the first crashed with a ZeroDivisionError: the catenary start bunched the
slack line's grounded length at the touchdown, nodes on top of each other); the seabed contact length
is interpolated between nodes; nodes above the water weigh their weight in air. References: the
elastic catenary with seabed contact (:func:`seacable.statics.catenary.catenary`, Irvine 1981
eq. 2.15-2.16; MoorPy's slack profile for H = 0).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import seacable as sc
from seacable.mooring.network import network_from_line
from seacable.mooring.solver import MooringModel, Water, static_equilibrium
from seacable.statics.catenary import catenary

RHO, G = 1025.0, 9.80665
CHAIN = {"diameter": 0.1512, "mass_per_length": 140.4, "axial_stiffness": 6.03e8}
W = (140.4 - RHO * math.pi / 4 * 0.1512**2) * G  # weight in water [N/m]


def _case(length, fairlead, n_elements, depth=200.0):
    return sc.Case(name="slack", line_types={"chain": CHAIN}, line={"line_type": "chain", "length": length},
                   environment={"depth": depth}, analysis={"type": "mooring_static", "fairlead": list(fairlead),
                                                          "n_elements": n_elements})


def test_a_slack_line_solves_and_matches_the_catenary_with_seabed_contact():
    """The repro of issue 17 item 2 (850 m of chain, fairlead 581 m away and 185 m up): H = 0.

    The catenary: the line lies on the seabed to below the fairlead and hangs straight up from there,
    fairlead tension w (L - grounded) = 221.3 kN, grounded 665.03 m, anchor tension 0.
    """
    h = 5.0
    ds = sc.run(_case(850.0, (581.0, -15.0), int(850 / h)))
    ref = catenary(581.0, 185.0, 850.0, 6.03e8, W)
    assert float(ref.H_fairlead) == 0.0  # the slack regime this test is about
    # the element that holds the touchdown lumps part of its hanging weight on its grounded node (and
    # the reverse), so the fairlead tension is known to half an element's weight, w h / 2 = 3.0 kN
    assert float(ds.fairlead_tension) == pytest.approx(float(ref.fairlead_tension), abs=0.5 * W * h)
    # the element above the last grounded node hangs slack (the line turns straight up inside it), so half
    # its length lumps on that node and lies on the seabed in the lumped model: h / 2 is the model's
    # resolution of the touchdown here (measured 2.47 m with h = 5 m)
    assert float(ds.seabed_contact_length) == pytest.approx(float(ref.grounded_length), abs=0.5 * h)
    # the grounded part carries no tension: the end element's tension is the 1/16 of an element's weight
    # in air of the rounded tension-only law at most (rounding over a quarter of that weight, see kernel)
    assert float(ds.anchor_tension) < 140.4 * G * h / 16


def test_the_contact_length_is_interpolated_between_nodes_on_a_taut_line():
    """A taut catenary (H > 0) with 10 m elements, its fairlead moved 2 m in 0.2 m steps.

    The grounded length falls by 1.2 m a step, so the touchdown crosses elements; counted by nodes it
    would step by 5 or 10 m (half an element's share per node) and be off by up to 5 m. Counted by the
    fraction of each node's weight the seabed carries, it follows the catenary.
    """
    h = 10.0
    offsets = [round(0.2 * k, 3) for k in range(11)]
    case = sc.Case(name="taut", line_types={"chain": CHAIN}, line={"line_type": "chain", "length": 850.0},
                   environment={"depth": 200.0},
                   analysis={"type": "mooring_pushover", "fairlead": [790.0, -15.0], "n_elements": int(850 / h),
                             "offsets": offsets})
    ds = sc.run(case)
    ref = np.array([float(catenary(790.0 + o, 185.0, 850.0, 6.03e8, W).grounded_length) for o in offsets])
    assert np.all(catenary(790.0 + np.array(offsets), 185.0, 850.0, 6.03e8, W).H_fairlead > 0)
    # measured at most 0.18 m (the seabed reactions add up to the grounded weight to the accuracy of the
    # fairlead's vertical force, with the penalty sink of 2.6 mm); 0.5 m is 1/20 of an element
    assert ds.seabed_contact_length.values == pytest.approx(ref, abs=0.05 * h)


@pytest.mark.parametrize("mirrored", [False, True])
def test_the_touchdown_follows_the_catenary_from_the_grounded_end(mirrored):
    """The touchdown's migration (issue 40): the taut catenary's fairlead moved 2 m in 0.5 m steps, 10 m elements.

    ``touchdown_s`` is the catenary's grounded length ``L_B`` from the grounded end, ``touchdown_x`` its end
    stretched under the horizontal tension, ``L_B (1 + H / EA)`` (frictionless). Mirrored, the line is grounded
    at end B (its end A held 15 m deep): the touchdown is counted from end B, ``s = L - L_B``.
    """
    h, span = 10.0, 790.0
    offsets = [0.0, 0.5, 1.0, 1.5, 2.0]
    ends = {"anchor": [0.0, -200.0], "fairlead": [span, -15.0]}
    if mirrored:  # end A up, end B on the seabed, moved away from end A by the offsets
        ends = {"anchor": [0.0, -15.0], "fairlead": [span, -200.0]}
    case = sc.Case(name="taut", line_types={"chain": CHAIN}, line={"line_type": "chain", "length": 850.0},
                   environment={"depth": 200.0},
                   analysis={"type": "mooring_pushover", **ends, "n_elements": int(850 / h), "offsets": offsets})
    ds = sc.run(case)
    ref = catenary(span + np.array(offsets), 185.0, 850.0, 6.03e8, W)
    L_B, x_td = ref.grounded_length, ref.grounded_length * (1 + ref.H_fairlead / 6.03e8)
    # the same resolution as the contact length's (measured at most 0.18 m there): 1/20 of an element
    if mirrored:
        assert ds.touchdown_s.values == pytest.approx(850.0 - L_B, abs=0.05 * h)
        assert ds.touchdown_x.values == pytest.approx(span + np.array(offsets) - x_td, abs=0.05 * h)
    else:
        assert ds.touchdown_s.values == pytest.approx(L_B, abs=0.05 * h)
        assert ds.touchdown_x.values == pytest.approx(x_td, abs=0.05 * h)
    assert np.all(ds.touchdown_y.values == 0.0)
    # it migrates: 2 m of offset pulls 5.3 m of chain off the seabed
    assert float(np.ptp(ds.touchdown_s.values)) == pytest.approx(float(np.ptp(L_B)), rel=0.05)


def test_a_hanging_line_has_no_touchdown():
    ds = sc.run(sc.Case(name="hanging", line_types={"chain": CHAIN}, line={"line_type": "chain", "length": 220.0},
                        environment={"depth": 300.0},
                        analysis={"type": "mooring_static", "anchor": [0.0, -250.0], "fairlead": [50.0, -15.0],
                                  "n_elements": 22}))
    assert np.isnan(float(ds.touchdown_s)) and np.isnan(float(ds.touchdown_x))
    assert float(ds.seabed_contact_length) == 0.0


def test_a_line_lying_entirely_on_the_seabed_has_no_tension():
    """400 m of chain with both ends on the seabed 300 m apart: it lies slack on the seabed."""
    line = sc.Line.single(sc.LineType(**CHAIN), 400.0)
    net = network_from_line(line, (0, 0, -200.0), (300.0, 0, -200.0), water_density=RHO, gravity=G,
                            n_elements=40)
    from seacable.mooring.network import catenary_positions

    start = catenary_positions((0, 0, -200.0), (300.0, 0, -200.0), net.arc_length, [400.0], [W], [6.03e8],
                               depth=200.0)
    model = MooringModel(net.replace(position=start), Water(depth=200.0, density=RHO, gravity=G))
    st = static_equilibrium(model)
    # no element is stretched beyond the rounding of the tension-only law: tensions below 1/16 of an
    # element's weight in air (10 m of chain: 860 N)
    assert np.max(st.tension) < 140.4 * G * 10.0 / 16
    # and every node rests on the seabed (within the penalty sink w / (k d) = 2.6 mm)
    assert np.all(np.abs(st.position[:, 2] + 200.0) < 0.01)


def test_a_hanging_line_with_its_ends_close_together_matches_the_catenary():
    """100 m of chain hanging in mid-water from two points 2 m apart at the same height (no seabed).

    The suspended catenary with equal end heights: each end carries half the weight vertically,
    V = w L / 2, and H from the span: 2 a asinh(L / (2 a)) = span (inextensible, EA 6e8 N stretches
    the line by 1e-6), T = sqrt(H^2 + V^2).
    """
    line = sc.Line.single(sc.LineType(**CHAIN), 100.0)
    span = 2.0
    net = network_from_line(line, (0, 0, -10.0), (span, 0, -10.0), water_density=RHO, gravity=G, n_elements=100)
    from seacable.mooring.network import catenary_positions

    start = catenary_positions((0, 0, -10.0), (span, 0, -10.0), net.arc_length, [100.0], [W], [6.03e8])
    model = MooringModel(net.replace(position=start), Water(depth=None, density=RHO, gravity=G))
    st = static_equilibrium(model)
    from scipy.optimize import brentq

    a = brentq(lambda a: 2 * a * math.asinh(50.0 / a) - span, 1e-6, 1e3)
    H, V = W * a, W * 50.0
    expected = math.hypot(H, V)
    # the end force includes the half element's weight at the end node; the lumped model's tension at
    # the end is then the catenary's to O(h^2): measured 1e-5, 1e-4 allowed
    assert np.linalg.norm(st.support[-1]) == pytest.approx(expected, rel=1e-4)
    assert np.linalg.norm(st.support[0]) == pytest.approx(expected, rel=1e-4)
    # the sag: the lowest point is 50 m - (span / 2) below the ends, less the catenary's rounding a
    sag = a * (math.cosh(span / 2 / a) - 1)
    assert -st.position[:, 2].min() - 10.0 == pytest.approx(sag, abs=0.5)


def test_a_line_hanging_in_air_weighs_its_weight_in_air():
    """A wire hanging between two points 5 m above the water: the catenary with the weight in air.

    With the weight in water (the old model) the tension would be short by the buoyancy, rho A g /
    (m g) = 1025 * 7.85e-5 / 0.6 = 13 % here.
    """
    wire = sc.LineType(diameter=0.01, mass_per_length=0.6, axial_stiffness=1e9)
    length, span = 12.0, 10.0
    line = sc.Line.single(wire, length)
    net = network_from_line(line, (0, 0, 5.0), (span, 0, 5.0), water_density=RHO, gravity=G, n_elements=60)
    from seacable.mooring.network import catenary_positions

    w_air = 0.6 * G
    start = catenary_positions((0, 0, 5.0), (span, 0, 5.0), net.arc_length, [length], [w_air], [1e9])
    model = MooringModel(net.replace(position=start), Water(depth=50.0, density=RHO, gravity=G))
    st = static_equilibrium(model)
    # the sag of 12 m between points 10 m apart (3.3 m) keeps the whole line above the water
    assert st.position[:, 2].min() > 0
    ref = catenary(span, 0.0, length, 1e9, w_air, seabed=False)
    # lumped masses on 60 elements reproduce the catenary end tension to O(h^2): measured 3e-5, 2e-4 allowed
    # (the weight-in-water alternative is 13 % off)
    assert np.linalg.norm(st.support[-1]) == pytest.approx(float(ref.fairlead_tension), rel=2e-4)

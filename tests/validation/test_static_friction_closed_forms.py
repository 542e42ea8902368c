"""The statics' seabed friction against closed forms (issue 40): a grounded line pulled along itself, held across a
current, and on a slope.

Coulomb friction ``mu N`` per node towards its target, regularised as ``mu N d / sqrt(d^2 + d_f^2)``
(:mod:`seacable.mooring._friction`; targets from the as-laid state, :mod:`seacable.mooring.friction`).

* **A grounded line pulled along itself** (an elastic rope of ``EA`` lying straight and unstretched on a flat seabed
  from its anchor to its other end, that end then pulled along the seabed by ``Delta``): rigid-plastic Coulomb
  friction ``mu w`` per length holds the line beyond the slid length ``l = P / (mu w)`` from the pulled end, whose
  stretch is the pull, ``Delta = P l / (2 EA)``: ``P = sqrt(2 EA mu w Delta)``, the anchor tension 0 while
  ``l < L``; once the whole line slides, ``Delta = (P L - mu w L^2 / 2) / EA`` and the anchor tension is
  ``P - mu w L``: ``max(P - mu w L, 0)`` under monotonic pull.
* **A grounded line in a lateral current** of drag ``q`` per length: where the line is straight (away from its
  ends) every node moves the same, so that the elements carry nothing new and each node's friction balances its drag:
  ``mu w d / sqrt(d^2 + d_f^2) = q``, ``d = d_f r / sqrt(1 - r^2)``, ``r = q / (mu w)``. With ``q > mu w``
  friction cannot hold it: it slides, and with its ends held bows until its tension carries ``q - mu w`` (a line
  with nothing else to hold it has no static equilibrium: ``tests/unit/test_cable_66kv_demo.py``'s grounded cable
  pushed towards its anchor, and the lazy wave of ``tests/validation/test_lazy_wave_friction.py``).
* **On a slope** ``beta`` along the contour the weight's part down the slope, ``w sin(beta)``, against the friction
  ``mu w cos(beta)``: held ``d = d_f r / sqrt(1 - r^2)`` with ``r = tan(beta) / mu``, and sliding when
  ``tan(beta) > mu`` (bowed between the held ends until the tension carries the rest).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from _evidence import check

import seacable as sc
from seacable.mooring.friction import SLIDE_FACTOR, friction_targets
from seacable.mooring.network import network_from_line
from seacable.mooring.solver import MooringModel, Water, static_equilibrium

G, RHO = 9.81, 1025.0  # the environment's defaults
L, DEPTH, MU, EA, D, MASS = 200.0, 50.0, 0.5, 1.0e6, 0.05, 12.0
ROPE = sc.LineType(diameter=D, mass_per_length=MASS, axial_stiffness=EA, drag_normal=1.2, drag_tangential=0.0)
W = float(network_from_line(sc.Line.single(ROPE, L), (0, 0, -DEPTH), (L, 0, -DEPTH), water_density=RHO, gravity=G,
                            n_elements=1).weight_per_length[0])  # weight in water per length, seacable's [N/m]


def _pull(offsets, n, friction_distance, path="incremental"):
    """The rope lying straight and unstretched on the seabed, its end B pulled along the seabed by ``offsets``."""
    return sc.run(sc.Case.parse({
        "name": "pull",
        "line_types": {"rope": {"diameter": D, "mass_per_length": MASS, "axial_stiffness": EA}},
        "line": {"segments": [{"line_type": "rope", "length": L}]},
        "environment": {"depth": DEPTH, "seabed": {"friction": MU}},
        "analysis": {"type": "mooring_pushover", "anchor": [0.0, -DEPTH], "fairlead": [L, -DEPTH],
                     "n_elements": n, "offsets": list(offsets),
                     "static_friction": {"pushover_path": path, "friction_distance": friction_distance}}}))


def test_a_grounded_line_pulled_along_itself_meets_coulombs_closed_form_at_first_order():
    """The pull P at 0.25 m (half the line slid: anchor tension 0) and at 1.5 m (all of it: anchor tension
    ``P - mu w L``, 2600 N), pulled there monotonically, at 50, 100 and 200 elements and ``d_f`` 1e-5 m (its
    shear-lag length ``sqrt(2 EA d_f / (mu w))`` 0.6 m, under an element).

    The lumped line's error is first order in the element length ``l_e``: the half elements at the two held ends lie
    on the seabed without friction (a held node's load is its support's), so that (summing the inner nodes'
    friction ``mu w l_e`` and the elements' stretch) the pull is exactly ``mu w l_e / 2`` low and the anchor tension
    as much high: 0.2-0.8 % of the pull here. With that term the closed forms hold to 1e-3 of the pull (what is left,
    0.01-0.05 %: the regularisation and the contact's rounding), and the error falls by 1.8-2.0 as ``l_e`` halves.
    The anchor tension of the half slid line is the as-laid state's: the elements' rounding at zero strain,
    ``m g l_e / 16`` (1.8-7 N), instead of 0."""
    closed_p = np.array([math.sqrt(2 * EA * MU * W * 0.25), (EA * 1.5 + MU * W * L**2 / 2) / L])
    closed_a = closed_p[1] - MU * W * L
    assert closed_p[0] < MU * W * L < closed_p[1]  # the two regimes
    errors = []
    for n in (50, 100, 200):
        ds = _pull([0.25, 1.5], n, 1e-5)
        pull, anchor = ds.fairlead_tension.values, ds.anchor_tension.values
        ends = MU * W * L / n / 2  # the held ends' half elements, without friction
        np.testing.assert_allclose(pull, closed_p - ends, rtol=0, atol=1e-3 * closed_p[1])
        assert anchor[1] == pytest.approx(closed_a + ends, abs=1e-3 * closed_p[1])
        assert anchor[0] == pytest.approx(MASS * G * L / n / 16, rel=0.05)  # still as laid: the rounding's tension
        errors.append(pull - closed_p)
    ratio = np.array(errors[:-1]) / np.array(errors[1:])
    assert np.all((ratio > 1.75) & (ratio < 2.05)), ratio  # first order


def test_the_slid_length_of_a_pulled_line_is_its_pull_over_the_friction():
    """The line slides from its pulled end over ``P / (mu w)`` (100 m of its 200 at 0.25 m). Within it the line has
    moved ``u = mu w x^2 / (2 EA)`` at ``x`` from the slide's front, so the nodes moved more than ``u_s`` = 10 d_f
    (slid, :data:`SLIDE_FACTOR`) end ``x_s = sqrt(2 EA u_s / (mu w))`` (2 m) short of it: to 1.5 elements (3 m;
    the last slid node is within an element of the front, and the held end's half element without friction shifts
    it by half an element). The same pull loaded from the as-laid targets in one offset (``pushover_path:
    as_laid``) gives the same line: the regularised friction of a monotonic pull does not depend on the path (to
    1e-6 m, the solver's tolerance)."""
    ds = _pull([0.1, 0.25], 100, 1e-5)
    once = _pull([0.25], 100, 1e-5, path="as_laid")
    P = float(ds.fairlead_tension[1])
    moved = ds.x.values[1] - ds.s.values  # laid at x = s, unstretched
    u_s = SLIDE_FACTOR * 1e-5
    slid = L - float(ds.s.values[np.argmax(moved > u_s)])
    assert slid + math.sqrt(2 * EA * u_s / (MU * W)) == pytest.approx(P / (MU * W), abs=1.5 * L / 100)
    np.testing.assert_allclose(once.x.values[0], ds.x.values[1], rtol=0, atol=1e-6)
    check(float(once.fairlead_tension[0]), P, rtol=1e-6, source="Closed form: Coulomb friction with a slip distance",
          unit="N", quantity="pull on a grounded line held by friction: fairlead tension = the pull",
          why="the Newton solve's tolerance")


def _lateral(speed, friction_distance=0.01):
    """The rope lying on the seabed, stretched 0.1 %, in a uniform current across it."""
    return sc.Case.parse({
        "name": "lateral",
        "line_types": {"rope": ROPE.model_dump()},
        "line": {"segments": [{"line_type": "rope", "length": L}]},
        "environment": {"depth": DEPTH, "seabed": {"friction": MU}, "current": {"speed": speed,
                                                                                "heading": math.pi / 2}},
        "analysis": {"type": "mooring_static", "anchor": [0.0, -DEPTH], "fairlead": [1.001 * L, -DEPTH],
                     "n_elements": 40, "static_friction": {"friction_distance": friction_distance}}})


@pytest.mark.parametrize("ratio", [0.3, 0.9])
def test_a_grounded_line_in_a_lateral_current_below_its_friction_is_held_its_slip_the_regularisations(ratio):
    """Drag ``q = 1/2 rho d C_dn U^2`` at ``r = q / (mu w)`` = 0.3 and 0.9 of the friction: the middle of the line
    moves across by ``d_f r / sqrt(1 - r^2)`` (3.1 and 20.6 mm at ``d_f`` 1 cm), to 1e-4 (the line's tension, 980 N,
    bends it only within a few elements of its held ends: its geometric stiffness against the shear spring
    ``mu N / d_f``); and by as much along the current's direction only (nothing along the line)."""
    q = ratio * MU * W
    speed = math.sqrt(q / (0.5 * RHO * D * 1.2))
    ds = sc.run(_lateral(speed))
    mid = ds.sizes["node"] // 2
    want = 0.01 * ratio / math.sqrt(1 - ratio**2)
    check(float(ds.y[mid]), want, rtol=1e-4, source="Closed form: Coulomb friction with a slip distance", unit="m",
          quantity=f"grounded line in a lateral current at {ratio} of its friction: slip d_f r / sqrt(1 - r^2)",
          why="the line's tension bends it only near its held ends")
    assert float(ds.x[mid]) == pytest.approx(1.001 * float(ds.s[mid]), abs=1e-6)


def _pull_of_elements(X, tension, i):
    """The force of node ``i``'s two elements on it (their tensions along their chords). [N]"""
    out = np.zeros(3)
    for j in (i - 1, i + 1):
        chord = X[j] - X[i]
        out += tension[min(i, j)] * chord / np.linalg.norm(chord)
    return out


def test_beyond_its_friction_a_grounded_line_in_a_lateral_current_slides_until_its_tension_carries_the_rest():
    """At ``q = 1.2 mu w`` friction cannot hold the line: it slides across (the middle metres, not millimetres) and
    bows between its held ends until its tension carries what friction cannot, ``(q - mu w)`` per length: at the
    middle node the elements' pull across is ``(q - mu w) l_e`` (a sliding node's friction is ``mu N``, less
    ``d_f^2 / (2 d^2)`` of it, 1e-8 here), to 1e-3 (the drag's direction turned by the bowed elements, 1e-4)."""
    q = 1.2 * MU * W
    speed = math.sqrt(q / (0.5 * RHO * D * 1.2))
    ds = sc.run(_lateral(speed))
    mid = ds.sizes["node"] // 2
    assert float(ds.y[mid]) > 1.0
    X = np.column_stack([ds.x.values, ds.y.values, ds.z.values])
    pull = _pull_of_elements(X, ds.tension.values, mid)
    assert -pull[1] == pytest.approx((q - MU * W) * L / 40, rel=1e-3)


def _contour(beta, friction_distance=0.01):
    """The rope along a contour of a seabed rising towards +x at ``beta``, from an anchor at y = 0 to a held end at
    y = L, laid straight on it; its friction targets are where it lies."""
    z = -DEPTH
    net = network_from_line(sc.Line.single(ROPE, L), (0.0, 0.0, z), (0.0, 1.001 * L, z), water_density=RHO,
                            gravity=G, n_elements=40)
    X = net.position.copy()
    X[:, 0], X[:, 2] = 0.0, z  # straight along y on the seabed
    model = MooringModel(net.replace(position=X), Water(depth=DEPTH, slope=beta, friction=MU), checked=True)
    return model, X, friction_targets(model, X)


def test_a_grounded_line_along_a_slope_below_atan_mu_is_held():
    """``tan(beta) = 0.6 mu``: the middle of the line slips down the slope by ``d_f r / sqrt(1 - r^2)`` (7.5 mm at
    ``d_f`` 1 cm) in the seabed's plane, to 1e-4 (as across a current)."""
    beta = math.atan(0.6 * MU)
    model, X, targets = _contour(beta)
    state = static_equilibrium(model, X, targets=targets, friction_distance=0.01)
    mid = X.shape[0] // 2
    down = np.array([-math.cos(beta), 0.0, -math.sin(beta)])
    assert float((state.position[mid] - targets[mid]) @ down) == pytest.approx(0.01 * 0.6 / math.sqrt(1 - 0.36),
                                                                             rel=1e-4)


def test_a_grounded_line_along_a_slope_steeper_than_atan_mu_slides_until_its_tension_holds_it():
    """``tan(beta) = 1.2 mu`` (31 deg at mu 0.5): friction cannot hold the line; it slides down the slope (the middle
    metres) and bows between its held ends until its tension carries the rest, ``w sin(beta) - mu w cos(beta)`` per
    length, across the line at its middle node, to 1e-3 (as across a current)."""
    beta = math.atan(1.2 * MU)
    model, X, targets = _contour(beta)
    state = static_equilibrium(model, X, targets=targets, friction_distance=0.01)
    mid = X.shape[0] // 2
    down = np.array([-math.cos(beta), 0.0, -math.sin(beta)])
    assert float((state.position[mid] - targets[mid]) @ down) > 1.0
    pull = _pull_of_elements(state.position, state.tension, mid)
    assert -float(pull @ down) == pytest.approx(W * (math.sin(beta) - MU * math.cos(beta)) * L / 40, rel=1e-3)

"""Order of convergence of the fairlead tension of a grounded mooring line with the element length.

Issue 37 item 2: the finite-element fairlead tension of a slack chain (850 m, fairlead 581 m off and
185 m up, H = 0) is off the catenary by +3.4, -2.3, +0.5, -0.9 % at 20, 40, 80, 160 elements: it does
not fall steadily, because the error depends on where the touchdown falls between two nodes. Sampled
over that position (a fraction of an element), the error has a known form and a known order, which these
tests assert (the observed order from the error ratios per halving of the element length, against the
nominal one, as PyBaMM's convergence tests do). The reference is the elastic catenary with seabed
contact (:func:`seacable.statics.catenary.catenary`, Irvine 1981 eq. 2.15-2.16).

The end tension is the pull of the end element plus the end node's share of its half element's loads
(:func:`seacable.mooring.run.line_end_forces`). What limits it is the touchdown: the line's curvature
jumps there from ``w / H`` to 0 (``w`` the weight in water per length, ``H`` the horizontal tension),
and straight two-node elements with their weight lumped at the nodes place the touchdown on the node
grid. The error is therefore:

- second order, ``|dT| <= c (w h)^2 / H`` (``h`` the element length), for a catenary that meets the seabed
  with ``H > 0``;
- first order for a slack line (``H = 0``): it hangs straight down and turns flat at the seabed, a kink
  no straight element holds. The element crossing the seabed hangs slack from the last suspended node,
  which then carries half that element's weight whatever the part of it that hangs, so that the
  fairlead tension is ``w h (m + 1/2)`` for ``m + phi`` elements' worth of hanging line (``0 < phi < 1``):
  an error ``w h (1/2 - phi)``, at most half an element's weight.

The seabed contact (a penalty at the nodes) is not what sets these. Integrated along the element chords
instead (a prototype, the penetration linear along each element, its exact integral shared to the two
nodes), it moved the slack line's fairlead tension by 0.03 N and the taut line's by 9 N at most (3e-5 of it)
from 10 to 320 elements: a straight element crossing the seabed at a slope penetrates it over
``pen / slope`` only, millimetres, so its grounded node carries the reaction either way.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

import seacable as sc
from seacable.statics.catenary import catenary

RHO, G = 1025.0, 9.80665
EA = 6.03e8
CHAIN = {"diameter": 0.1512, "mass_per_length": 140.4, "axial_stiffness": EA}
W = (140.4 - RHO * math.pi / 4 * 0.1512**2) * G  # weight in water [N/m]
LENGTH, DEPTH = 850.0, 200.0
# the touchdown's place inside an element, as a fraction of it, sampled evenly
FRACTIONS = (0.125, 0.375, 0.625, 0.875)


def _fairlead_tension(n_elements, fairlead):
    case = sc.Case(name="touchdown", line_types={"chain": CHAIN},
                   line={"line_type": "chain", "length": LENGTH},
                   environment={"depth": DEPTH, "water_density": RHO, "gravity": G},
                   analysis={"type": "mooring_static", "fairlead": list(fairlead), "n_elements": n_elements})
    return float(sc.run(case).fairlead_tension)


def _orders(errors, n_elements):
    """Observed orders log2(E_n / E_2n) of the largest error over the touchdown's places at each mesh."""
    env = np.max(np.abs(errors), axis=1)
    assert all(b == 2 * a for a, b in zip(n_elements, n_elements[1:]))  # halvings of the element length
    return np.log2(env[:-1] / env[1:])


def test_a_slack_line_end_tension_converges_at_first_order():
    """H = 0: the fairlead tension is ``w h (m + 1/2)``, first order, at most ``w h / 2`` off the catenary.

    For each mesh the fairlead's height is set so that ``m + phi`` elements hang (unstretched length
    ``s = (m + phi) h``, stretched ``s + w s^2 / (2 EA)``, the vertical span of a straight hang).
    """
    meshes = (20, 40, 80)
    errors, predicted = [], []
    for n in meshes:
        h = LENGTH / n
        m = math.floor(150.0 / h)  # about 150 m hanging, the fairlead well under water on every mesh
        row = []
        for phi in FRACTIONS:
            s = (m + phi) * h
            span = s + W * s * s / (2 * EA)
            ref = catenary(581.0, span, LENGTH, EA, W)
            assert float(ref.H_fairlead) == 0.0  # the slack regime this test is about
            row.append(_fairlead_tension(n, (581.0, span - DEPTH)) - float(ref.fairlead_tension))
            predicted.append(W * h * (0.5 - phi))
        errors.append(row)
    errors = np.array(errors)
    # the closed form holds to round-off: measured within 1e-6 N (of errors of 1.6 to 19 kN); 1 N allowed
    # (the static solve's force tolerance is far below it, and the hanging nodes' places, set from the
    # fairlead by the stretched element lengths, do not depend on the seabed penalty's sink)
    assert np.max(np.abs(errors.ravel() - np.array(predicted))) < 1.0
    # hence first order, the error's largest value over the touchdown's places halving with the element
    # length: measured orders 1.0000, 1.0000; 0.02 allows the 1 N above on the smallest (4.8 kN)
    assert np.all(np.abs(_orders(errors, meshes) - 1.0) < 0.02)
    # and within half an element's weight, the bound of the closed form (the sampled places reach 3 / 4 of it)
    assert np.all(np.abs(errors) <= 0.5 * W * LENGTH / np.array(meshes)[:, None])


def test_a_taut_line_end_tension_converges_at_second_order():
    """H > 0 (the same chain, its fairlead about 760 m off and 185 m up, 570 m grounded): second order.

    For each mesh the fairlead's distance is set so that the catenary's touchdown (its unstretched
    grounded length from the anchor) falls at each sampled fraction of an element.
    """
    meshes = (20, 40, 80, 160)
    g0 = float(catenary(760.0, 185.0, LENGTH, EA, W).grounded_length)
    errors, scaled = [], []  # [N], and over (w h)^2 / H
    for n in meshes:
        h = LENGTH / n
        row, srow = [], []
        for phi in FRACTIONS:
            target = (math.floor(g0 / h) + phi) * h
            x = brentq(lambda x: float(catenary(x, 185.0, LENGTH, EA, W).grounded_length) - target,
                       700.0, 800.0, xtol=1e-9)
            ref = catenary(x, 185.0, LENGTH, EA, W)
            err = _fairlead_tension(n, (x, -15.0)) - float(ref.fairlead_tension)
            row.append(err)
            srow.append(err / ((W * h) ** 2 / float(ref.H_fairlead)))
        errors.append(row)
        scaled.append(srow)
    errors = np.array(errors)
    # the error scaled by (w h)^2 / H is a function of the touchdown's place in its element that barely moves
    # with the mesh: measured between -0.143 and 0.153 here (and within 0.27 over eight places from 10 to
    # 160 elements); 0.3 bounds it
    assert np.all(np.abs(scaled) < 0.3)
    # second order: measured orders 2.35, 2.05, 2.14 per halving (largest fairlead errors 3122, 611, 147,
    # 34 N at 20, 40, 80, 160 elements). The scaled error at a given place drifts with the mesh (the first
    # suspended element's slope w h / H goes from 0.35 to 0.04), by up to 30 % between 20 and 160 elements,
    # which moves an order by up to log2(1.3) = 0.4; a first-order error would give orders near 1. Finer
    # meshes are left out: the limit is the catenary over the seabed lowered by the penalty's sink
    # w / (k d) = 2.6 mm, 11 N away (3e-5 of the tension), where the 320-element errors (up to 22 N) stop
    # scaling
    orders = _orders(errors, meshes)
    assert np.all(np.abs(orders - 2.0) < 0.4)
    assert abs(np.mean(orders) - 2.0) < 0.25  # measured 2.18

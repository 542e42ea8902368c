"""Ties to the seabed in the mooring kernel and the case schema (:mod:`seacable.ties`,
:func:`seacable.mooring._ties.tie_loads`): the exact tangent against central differences, the outputs, and one
clear message for each bad input (also from ``validate``)."""

from __future__ import annotations

import numpy as np
import pytest

from seacable.mooring import kernel as K
from seacable.mooring._ties import tie_loads


def _table(n_rows):
    """An attachments' table with a taut tether (node 0), a tether inside its rounding band (node 1), a slack one
    (node 2) and a spring clamp with a tether on the same node (node 3)."""
    P = np.zeros((n_rows, K.P_SIZE))
    P[0, K.P_TX:K.P_TX + 3], P[0, [K.P_TEA, K.P_TL, K.P_TB]] = (0.0, 0.0, -100.0), (5e7, 10.0, 0.0)
    P[1, K.P_TX:K.P_TX + 3], P[1, [K.P_TEA, K.P_TL, K.P_TB]] = (20.0, 1.0, -100.0), (2e6, 12.0, 1e-3)
    P[2, K.P_TX:K.P_TX + 3], P[2, [K.P_TEA, K.P_TL, K.P_TB]] = (40.0, 0.0, -100.0), (2e6, 30.0, 1e-3)
    P[3, K.P_TX:K.P_TX + 3], P[3, [K.P_TEA, K.P_TL, K.P_TB]] = (60.0, -2.0, -100.0), (3e6, 8.0, 0.0)
    P[3, K.P_CX:K.P_CX + 3], P[3, K.P_CK] = (61.0, 0.5, -99.0), 4e5
    return P


def _forces(X, P, fidx, band=None, bw=5):
    F = np.zeros_like(X)
    tie_loads(X, P, F, np.zeros((0, 2 * bw + 1)) if band is None else band, bw, fidx)
    return F


def test_tie_tangent_is_the_derivative_of_the_forces():
    """K = -dF/dx of the ties (taut, rounded and slack tethers, a spring clamp) against central differences of step
    1e-6 m: their error is round-off, the rounding of a length of 100 m (1e-14 m) times EA / L0 (up to 5e6 N/m)
    over the step 2e-6 m, 0.03 N/m, so 0.1 N/m is asserted against entries up to 4.6e6 N/m. Dropping the
    geometric term T / l (1e4-1e5 N/m here) or the rounding's slope fails it (planted, both fail)."""
    X = np.array([[3.0, 1.0, -89.5], [21.0, 2.0, -88.0], [41.0, 0.0, -95.0], [62.0, -1.0, -93.0]])
    P = _table(4)
    fidx = np.arange(4, dtype=np.int64)
    # node 1 inside its band: strain within +-1e-3
    eps1 = np.linalg.norm(X[1] - P[1, K.P_TX:K.P_TX + 3]) / 12.0 - 1.0
    X[1] = P[1, K.P_TX:K.P_TX + 3] + (X[1] - P[1, K.P_TX:K.P_TX + 3]) * (1.0 + 0.0004) / (1.0 + eps1)
    bw = 5
    band = np.zeros((12, 2 * bw + 1))
    F = _forces(X, P, fidx, band, bw)
    assert F[0, 2] < -1e6 and F[1, 2] < 0.0 and np.all(F[2] == 0.0)  # taut, rounded, slack
    got = np.zeros((12, 12))
    for r in range(12):
        for c in range(max(0, r - bw), min(12, r + bw + 1)):
            got[r, c] = band[r, bw + c - r]
    want = np.zeros((12, 12))
    h = 1e-6
    for i in range(4):
        for r in range(3):
            Xp, Xm = X.copy(), X.copy()
            Xp[i, r] += h
            Xm[i, r] -= h
            want[:, 3 * i + r] = -((_forces(Xp, P, fidx) - _forces(Xm, P, fidx)) / (2 * h)).ravel()
    assert np.max(np.abs(got - want)) < 0.1  # measured 9e-3 N/m
    assert np.max(np.abs(want)) > 1e6
    # a node not free (a fixed node) gets forces but no rows
    fixed = fidx.copy()
    fixed[0] = -1
    band2 = np.zeros((12, 2 * bw + 1))
    assert np.array_equal(_forces(X, P, fixed, band2, bw), F)


def test_a_slack_tether_exerts_no_force_and_a_taut_one_its_closed_form():
    """A tether shorter than its anchor's distance pulls with EA (l / L0 - 1) along it (beyond its band), one
    longer pulls with nothing (compression: no force)."""
    P = np.zeros((1, K.P_SIZE))
    P[0, [K.P_TEA, K.P_TL, K.P_TB]] = 1e6, 10.0, 1e-4
    taut = _forces(np.array([[6.0, 0.0, 8.5]]), P, np.zeros(1, np.int64))
    l = np.hypot(6.0, 8.5)
    assert taut[0] == pytest.approx(-1e6 * (l / 10.0 - 1.0) * np.array([6.0, 0.0, 8.5]) / l, rel=1e-14)
    assert np.all(_forces(np.array([[6.0, 0.0, 7.9]]), P, np.zeros(1, np.int64)) == 0.0)


def test_compressed_elements_tangent_is_the_derivative_of_the_forces():
    """With compression (:data:`seacable.mooring.kernel.E_COMPRESS`) a shortened bent rod's elements carry
    ``EA eps < 0``: the loads pass's Newton matrix (axial EA / L and the geometric T / l, negative) against central
    differences of step 1e-6 m (round-off: EA / L = 2e6 N/m times 1e-14 m over 2e-6 m, 0.01 N/m; measured 9e-4,
    0.1 asserted against entries up to 4e6 N/m, bending's included). A tangent that kept the tension-only switch
    (no axial stiffness in compression) would be 2e6 N/m off."""
    import math

    from seacable.line import Line, LineType
    from seacable.mooring.network import network_from_line
    from seacable.mooring.solver import MooringModel, Water

    rod = LineType(diameter=0.1, mass_per_length=20.0, axial_stiffness=1e6, bending_stiffness=1e4)
    net = network_from_line(Line.single(rod, 2.0), (0, 0, -50.0), (1.9, 0, -50.0), water_density=1025.0,
                            gravity=9.81, n_elements=4)
    model = MooringModel(net, Water(compression=True))
    X = net.position.copy()
    X[1:-1, 2] += 0.05 * np.sin(math.pi * net.arc_length[1:-1] / 2.0)  # a bow: every element shortened
    nd = 3 * model.nfree
    free = np.flatnonzero(model.fidx >= 0)

    def forces(Y, band=None):
        F, M, ten = np.zeros_like(Y), np.zeros((len(Y), 3, 3)), np.zeros(net.n_elements)
        K.loads(Y, np.zeros_like(Y), 0.0, *model.element_args(), model.fidx, model.env, model.cur_depth,
                model.cur_speed, False, model.sea, F, M, ten,
                np.zeros((0, 2 * model.bw + 1)) if band is None else band, model.bw, 0.0, 0.0)
        return F, ten

    band = np.zeros((nd, 2 * model.bw + 1))
    _, ten = forces(X, band)
    assert np.all(ten < -1e3)
    got = np.zeros((nd, nd))
    for r in range(nd):
        for c in range(max(0, r - model.bw), min(nd, r + model.bw + 1)):
            got[r, c] = band[r, model.bw + c - r]
    want = np.zeros((nd, nd))
    for i in free:
        for r in range(3):
            Xp, Xm = X.copy(), X.copy()
            Xp[i, r] += 1e-6
            Xm[i, r] -= 1e-6
            dF = (forces(Xp)[0] - forces(Xm)[0]) / 2e-6
            want[:, 3 * model.fidx[i] + r] = -dF[free].ravel()
    assert np.max(np.abs(want)) > 1e6
    assert np.max(np.abs(got - want)) < 0.1

"""Bending stiffness EI in the mooring finite-element lines (MoorDyn v2's nodal bending), against beam theory.

Issue 18: a line type's EI acts at each inner node of a line as the moment ``M = EI kappa`` with
``kappa = 4 sin(theta / 2) / (l1 + l2)`` (``theta`` the angle between the node's two elements), turned
into forces ``M / l`` on the neighbours normal to their elements and their opposite on the node
(MoorDyn v2 ``Line::getStateDeriv``, ``GetCurvature``); line ends at points are pinned.

Closed forms (Euler-Bernoulli; Timoshenko and Gere, *Theory of Elastic Stability*, for the tensioned
beam):

- a simply supported beam under a uniform load ``w``: midspan deflection ``5 w L^4 / (384 EI)``;
- the same beam under a midspan point load ``P``: ``P L^3 / (48 EI)``;
- the lateral vibration of a pinned-pinned beam under tension ``T``:
  ``f_n = n / (2 L) sqrt(T / m) sqrt(1 + n^2 pi^2 EI / (T L^2))``;

each converging at second order in the element length (the nodal moment is the central difference of
the slope). The tangent stiffness against central differences of the forces, EI = 0 against the truss
bit for bit, and MoorDyn 2.7.2 on its own deck ``BeamSimplySupported.txt`` side by side.

The beams here are straight between two fixed nodes at their unstretched length, so the sag stretches
them: with EA = 1e9 N and deflections of 1e-4 m that tension is below 1 N, and its stiffening
``T L^2 / (pi^2 EI)`` below 1e-5, far under the tolerances (the MoorDyn deck's beam, 1e4 times heavier,
carries 6 kN, and there the comparison is with MoorDyn, which has the same tension).
"""

from __future__ import annotations

import itertools
import math
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg

import seacable as sc
from seacable.mooring import kernel as K
from seacable.mooring.moordyn import moordyn_model
from seacable.mooring.network import FIXED, FREE, Network
from seacable.mooring.solver import MooringModel, Water, simulate, static_equilibrium

DECKS = Path(__file__).parent / "data" / "moordyn_decks" / "MoorDyn" / "tests" / "Mooring"
L, EI, MPL = 10.0, 1e7, 10.0


def _beam(n, *, w=0.0, ei=EI, ea=1e9, tension=0.0, point=None, bending=True):
    """A straight horizontal beam of n elements from (0, 0, 0) to (L, 0, 0), ends fixed (pinned), no water.

    ``w`` is the weight per length [N/m], ``point`` a (node, load [N]) pair; ``tension`` pre-stretches the
    elements so that the straight beam carries it [N]. ``bending`` False leaves the EI array out (None).
    """
    s = np.linspace(0.0, L, n + 1)
    nn = n + 1
    kind = np.full(nn, FREE)
    kind[[0, -1]] = FIXED
    zero, one = np.zeros(nn), np.ones(n)
    weight = zero.copy()
    if point is not None:
        weight[point[0]] = point[1]
    net = Network(position=np.column_stack([s, zero, zero]), kind=kind, channel=np.full(nn, -1),
                  point_mass=zero.copy(), point_added_mass=zero.copy(), point_weight=weight,
                  point_volume=zero.copy(), point_drag_area=zero.copy(),
                  elements=np.column_stack([np.arange(n), np.arange(1, nn)]), length=np.diff(s) / (1 + tension / ea),
                  axial_stiffness=ea * one, axial_damping=0.0 * one, mass_per_length=MPL * one,
                  weight_per_length=w * one, diameter=0.1 * one, cdn=0.0 * one, cdt=0.0 * one, can=0.0 * one,
                  cat=0.0 * one, element_line=np.zeros(n, np.int64), line_nodes=(np.arange(nn),), line_names=("beam",),
                  arc_length=s, n_channels=0, channel_names=(), bending_stiffness=ei * one if bending else None)
    return MooringModel(net, Water(density=0.0, gravity=9.81, depth=None))


def _order(errors):
    return [math.log2(a / b) for a, b in itertools.pairwise(errors)]


def test_simply_supported_beam_under_uniform_load():
    """Midspan deflection 5 w L^4 / (384 EI) = 1.302e-4 m; relative error 8.0e-3, 2.0e-3, 5.0e-4 at 10,
    20, 40 elements: order 2 (asserted to 0.05), and 40 elements within 6e-4 (the series' own value)."""
    w = 10.0
    exact = 5 * w * L**4 / (384 * EI)
    errors = []
    for n in (10, 20, 40):
        st = static_equilibrium(_beam(n, w=w), tol=1e-12)
        errors.append(abs(-st.position[n // 2, 2] / exact - 1.0))
    assert errors[-1] < 6e-4
    assert _order(errors) == pytest.approx([2.0, 2.0], abs=0.05)


def test_simply_supported_beam_under_midspan_point_load():
    """Midspan deflection P L^3 / (48 EI) = 2.083e-4 m; relative error 2 / n^2 (2.0e-2, 5.0e-3, 1.25e-3):
    order 2 to 0.05, and 40 elements within 1.5e-3."""
    P = 100.0
    exact = P * L**3 / (48 * EI)
    errors = []
    for n in (10, 20, 40):
        st = static_equilibrium(_beam(n, point=(n // 2, P)), tol=1e-12)
        errors.append(abs(-st.position[n // 2, 2] / exact - 1.0))
        assert st.iterations <= 4  # the exact tangent: Newton converges at once on this linear problem
    assert errors[-1] < 1.5e-3
    assert _order(errors) == pytest.approx([2.0, 2.0], abs=0.05)


def _stiffness_and_mass(model, X, V=None):
    """The Newton matrix K (cm = cc = 0) and the node masses of the free nodes, dense."""
    n = model.network.n_nodes
    F, M = np.zeros((n, 3)), np.zeros((n, 3, 3))
    tension = np.zeros(model.network.n_elements)
    nd, bw = 3 * model.nfree, model.bw
    band = np.zeros((nd, 2 * bw + 1))
    K.loads(X, np.zeros_like(X) if V is None else V, 0.0, *model.element_args(), model.fidx, model.env,
            model.cur_depth, model.cur_speed, False, model.sea, F, M, tension, band, bw, 0.0, 0.0)
    Kd = np.zeros((nd, nd))
    for i in range(nd):
        for j in range(max(0, i - bw), min(nd, i + bw + 1)):
            Kd[i, j] = band[i, bw + j - i]
    Md = np.zeros((nd, nd))
    for i in np.flatnonzero(model.fidx >= 0):
        f = model.fidx[i]
        Md[3 * f:3 * f + 3, 3 * f:3 * f + 3] = M[i]
    return Kd, Md, F, tension


def test_tensioned_beam_lateral_frequencies():
    """f_n = n / (2 L) sqrt(T / m) sqrt(1 + n^2 pi^2 EI / (T L^2)) for n = 1, 2, 3 with T = 20 kN and
    EI = 1e5 N m^2 (bending raises f_1 by 22 % and f_3 by 133 % over the string's); the eigenvalues of
    the tangent and the lumped masses err by 1.4e-3, 6.8e-3, 1.7e-2 at 20 elements and a quarter of that
    at 40, 1/16 at 80: order 2 for each mode, to 0.15 (mode 1 shows 2.03 then 2.14: its error, 8e-5 at
    80 elements, mixes the string's and the bending's h^2 terms of opposite sign, so the next term shows;
    modes 2 and 3 give 2.00-2.03)."""
    T, ei = 2.0e4, 1.0e5
    n_modes = np.arange(1, 4)
    exact = n_modes / (2 * L) * np.sqrt(T / MPL) * np.sqrt(1 + n_modes**2 * math.pi**2 * ei / (T * L**2))
    errors = []
    for n in (20, 40, 80):
        model = _beam(n, ei=ei, tension=T)
        Kd, Md, _, tension = _stiffness_and_mass(model, model.network.position)
        assert tension == pytest.approx(T, rel=1e-9)
        z = np.arange(2, Kd.shape[0], 3)  # the vertical degrees of freedom (uncoupled from the others)
        f = np.sqrt(scipy.linalg.eigh(Kd[np.ix_(z, z)], Md[np.ix_(z, z)], eigvals_only=True)[:3]) / (2 * math.pi)
        errors.append(np.abs(f / exact - 1.0))
    errors = np.array(errors)
    assert np.all(errors[-1] < 1.1e-3)
    for mode in range(3):
        assert _order(errors[:, mode]) == pytest.approx([2.0, 2.0], abs=0.15)


def test_bending_tangent_is_the_derivative_of_the_forces():
    """The tangent (K = -dF/dx, all nine node pairs of each hinge) against central differences of the
    forces on a bent, stretched 3D line whose bending dominates its axial stiffness (EI / l^3 = 1.5e4 N/m
    against EA / l = 800 N/m): 1e-6 relative to the largest entry (the differences, with a 1e-6 m step,
    agree to 3e-9)."""
    n = 8
    model = _beam(n, ei=3.0e4, ea=1e3)
    rng = np.random.default_rng(18)
    X = model.network.position + rng.normal(scale=0.3, size=(n + 1, 3)) * (model.network.kind == FREE)[:, None]
    X[:, 2] -= 100.0  # under water: the buoyancy given back above the surface has no tangent (by design)
    Kd, _, _, _ = _stiffness_and_mass(model, X)
    h = 1e-6
    Kfd = np.zeros_like(Kd)
    for i in np.flatnonzero(model.fidx >= 0):
        for r in range(3):
            Xp, Xm = X.copy(), X.copy()
            Xp[i, r] += h
            Xm[i, r] -= h
            Fp = _stiffness_and_mass(model, Xp)[2]
            Fm = _stiffness_and_mass(model, Xm)[2]
            col = 3 * model.fidx[i] + r
            for j in np.flatnonzero(model.fidx >= 0):
                Kfd[3 * model.fidx[j]:3 * model.fidx[j] + 3, col] = -(Fp[j] - Fm[j]) / (2 * h)
    assert np.max(np.abs(Kd - Kfd)) < 1e-6 * np.max(np.abs(Kd))


def test_zero_bending_stiffness_is_the_truss_bit_for_bit():
    """EI = 0 (an array of zeros) and no EI (None) take the same path: no hinges, the same band width,
    identical statics and time steps (np.array_equal, not a tolerance)."""
    runs = []
    for bending in (True, False):
        model = _beam(20, w=50.0, ei=0.0, ea=1e7, bending=bending)
        assert model.hinges.shape == (0, 3)
        st = static_equilibrium(model, tol=1e-10)
        model.network.position[:] = st.position
        run = simulate(model, None, 1.0, 0.05, 0.5, initial=st.position + 0.01)
        runs.append((model.bw, st.position, run.position, run.tension))
    assert runs[0][0] == runs[1][0]
    for a, b in zip(runs[0][1:], runs[1][1:]):
        assert np.array_equal(a, b)


def test_moordyn_simply_supported_beam_side_by_side(tmp_path):
    """MoorDyn's own deck BeamSimplySupported.txt (10 m, 19 segments, EI = 1e7 N m^2, 100 kg/m in air,
    ends fixed): the node deflections and the tension against MoorDyn 2.7.2's initial state within 1e-4
    relative. The deck's relaxation (TmaxIC 40 s, threshIC 1e-5) stops 2.4 % short of rest; it runs here
    with TmaxIC 100 s and threshIC 1e-9, where MoorDyn's answer moves by 2e-5 relative from 400 s.
    Both are 0.4 % under the continuous 5 w L^4 / (384 EI) at the nodes beside midspan: the sag tension
    (6 kN) stiffens the beam by T L^2 / (pi^2 EI) = 0.6 %, the discretisation softens it by 0.2 %."""
    moordyn = pytest.importorskip("moordyn")
    text = (DECKS / "BeamSimplySupported.txt").read_text()
    text = text.replace("40.0          TmaxIC", "100.0         TmaxIC").replace("1e-5          threshIC",
                                                                               "1e-9          threshIC")
    deck = tmp_path / "beam.txt"
    deck.write_text(text)
    system = moordyn.Create(str(deck))
    try:
        moordyn.Init(system, [], [])
        line = moordyn.GetLine(system, 1)
        peer = np.array([moordyn.GetLineNodePos(line, i) for i in range(20)])
        peer_tension = moordyn.GetLineNodeTen(line, 0)
    finally:
        moordyn.Close(system)
    model = moordyn_model(deck)
    st = static_equilibrium(model, tol=1e-12)
    ours = st.position[model.network.line_nodes[0]]
    sag, peer_sag = 10.0 - ours[:, 2], 10.0 - peer[:, 2]
    assert sag[9] == pytest.approx(peer_sag[9], rel=1e-4) and sag[9] == pytest.approx(0.012677, rel=1e-3)
    assert np.max(np.abs(sag - peer_sag)) < 1e-4 * peer_sag.max()
    assert st.tension[0] == pytest.approx(np.linalg.norm(peer_tension), rel=1e-4)
    w = 100.0 * 9.80665  # in air: its full weight
    x = ours[9, 0]
    continuous = w * x * (L**3 - 2 * L * x**2 + x**3) / (24 * EI)
    assert sag[9] / continuous - 1 == pytest.approx(-0.004, abs=0.001)


def test_coupled_system_kernel_carries_the_bending(two_kernels):
    """The coupled body-line kernel (system_dynamic) and the mooring kernel run the same line with EI =
    2e5 N m^2 under the same fairlead motion: the same tensions to 1e-6 of the largest (observed 2e-8,
    the two Newton solves' tolerance), and EI raises the tension range by 16 % over the truss's (so the
    agreement is not the truss's)."""
    bent = two_kernels(sc.LineType(diameter=0.1, mass_per_length=20.0, axial_stiffness=1e7,
                                            bending_stiffness=2e5))
    truss = two_kernels(sc.LineType(diameter=0.1, mass_per_length=20.0, axial_stiffness=1e7))
    assert np.max(np.abs(bent[0] - bent[1])) < 1e-6 * np.max(bent[1])
    assert np.ptp(bent[1][:, -1]) > 1.1 * np.ptp(truss[1][:, -1])

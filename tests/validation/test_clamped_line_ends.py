"""Clamped and spring line ends of the mooring finite-element line with bending stiffness, against closed forms.

Issue 40: a line end held at a direction (``analysis.anchor_end_condition`` / ``fairlead_end_condition``) is a
hinge between the given direction ``e`` and the end element (:func:`seacable.mooring.kernel.end_bending_loads`):
``kappa = 4 sin(theta / 2) / l`` (the end node's half element ``l / 2``), ``M = EI kappa`` for a clamp, and a
rotational spring ``k`` in series with that half element, ``M = theta / (1 / k + l / (2 EI))``. Its curvature,
bend moment and shear outputs are :func:`seacable.mooring.bending.bending_state`.

References and closed forms:

- Euler-Bernoulli cantilever under a tip load ``P``: tip deflection ``P L^3 / (3 EI)`` (plus ``P L^2 / k`` on a
  root spring ``k``), root moment ``P L``, shear ``P`` (Timoshenko and Gere, *Mechanics of Materials*);
- the elastica of that cantilever at large deflection (the load staying vertical): Bisshopp, K. E. and
  Drucker, D. C. (1945), Large deflection of cantilever beams, *Quarterly of Applied Mathematics* 3, 272-275;
  the tip values by elliptic integrals of Mattiasson, K. (1981), Numerical results from large deflection beam
  and frame problems analysed by means of elliptic integrals, *IJNME* 17, 145-153, Table 1: for
  ``P L^2 / EI`` = 1, ``w / L = 0.30172``, ``u / L = 0.05643``; for 2, ``0.49346``, ``0.16064`` (a shooting
  solution of ``theta'' = -(P L^2 / EI) cos(theta)`` with scipy's solve_ivp at rtol 1e-12 gives the same to
  the fifth decimal); the root curvature is ``P (L - u) / EI`` by statics;
- a simply supported beam under a uniform load ``w``: midspan moment ``w L^2 / 8``;
- a tensioned cable clamped at one end (Irvine, H. M. (1981), *Cable Structures*, MIT Press, ch. 3 on the
  bending boundary layer; Irvine, H. M. (1993), Local bending stresses in cables, *Int. J. Offshore and Polar
  Engineering* 3(3)): as ``EI -> 0`` the line is the catenary, except in a layer of length
  ``lambda = sqrt(EI / T)`` at the clamp, where the moment ``M0 = sqrt(EI T) Delta`` (``Delta`` the angle
  between the clamp's direction and the catenary's tangent) decays as ``exp(-s / lambda)``; here with the
  layer's exact (elastica) moment ``2 sqrt(EI T) sin(Delta / 2)`` and the catenary's own ``EI kappa_cat``
  added (the layer bends against the catenary's curvature).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
import scipy.linalg
from scipy.optimize import brentq

import seacable as sc
from seacable.errors import InputError
from seacable.mooring import kernel as K
from seacable.mooring.bending import bending_state
from seacable.mooring.ends import end_direction
from seacable.mooring.network import FIXED, FREE, Network
from seacable.mooring.solver import MooringModel, Water, static_equilibrium

L, EI = 10.0, 1e7
X_AXIS = np.array([1.0, 0.0, 0.0])


def _line(s, X0, kind, *, w=0.0, tip=None, ei=EI, ea=1e12, hinges=(), laws=None):
    """A line of nodes at arc lengths ``s`` from positions ``X0`` with node kinds ``kind``, no water.

    ``w`` weight per length [N/m], ``tip`` a (node, downward load [N]) pair, ``hinges`` its ``end_hinges``, ``laws``
    its elements' moment-curvature laws (``element_moment_curvature``).
    EA = 1e12 N makes it inextensible for these loads (strain below 1e-6)."""
    nn = len(s)
    n = nn - 1
    zero, one = np.zeros(nn), np.ones(n)
    pw = zero.copy()
    if tip is not None:
        pw[tip[0]] = tip[1]
    net = Network(position=np.asarray(X0, float), kind=np.asarray(kind), channel=np.full(nn, -1),
                  point_mass=zero.copy(), point_added_mass=zero.copy(), point_weight=pw, point_volume=zero.copy(),
                  point_drag_area=zero.copy(), elements=np.column_stack([np.arange(n), np.arange(1, nn)]),
                  length=np.diff(s), axial_stiffness=ea * one, axial_damping=0 * one, mass_per_length=10 * one,
                  weight_per_length=w * one, diameter=0.1 * one, cdn=0 * one, cdt=0 * one, can=0 * one,
                  cat=0 * one, element_line=np.zeros(n, np.int64), line_nodes=(np.arange(nn),), line_names=("c",),
                  arc_length=np.asarray(s, float), n_channels=0, channel_names=(), bending_stiffness=ei * one,
                  end_hinges=tuple(hinges), element_moment_curvature=laws)
    return MooringModel(net, Water(density=0.0, gravity=9.81, depth=None))


def _cantilever(n, P, kind="clamp", k=None):
    """A horizontal cantilever along +x, clamped (or on a root spring ``k``) at node 0, tip load P down.

    EA = 1e7 P: inextensible to 1e-7, and no stiffer, so that the force residual's round-off floor (EA times
    the positions' 1e-16) stays far below the Newton tolerance."""
    s = np.linspace(0.0, L, n + 1)
    kinds = np.full(n + 1, FREE)
    kinds[0] = FIXED
    return _line(s, np.column_stack([s, 0 * s, 0 * s]), kinds, tip=(n, P), ea=1e7 * P,
                 hinges=[(0, 0, kind, k, X_AXIS)])


def _order(errors):
    return [math.log2(a / b) for a, b in itertools.pairwise(errors)]


def test_cantilever_tip_load_small_deflection():
    """P = 100 N, EI = 1e7 N m^2, L = 10 m: tip deflection P L^3 / (3 EI) = 3.333e-3 m with relative errors
    5.0e-3, 1.25e-3, 3.1e-4 at 10, 20, 40 elements (exactly 1 / (2 n^2)): order 2, asserted to 0.05. The
    root moment is P times the tip's lever arm to 1e-10 (statics makes the discrete moment at each node P times
    its lever arm exactly, on any mesh: 1e-14 measured), which is P L to 1e-6, and the shear P in every element
    to 1e-6 (|dM/ds| along the element's chord: P cos(slope), 1 - 1.25e-7 at the tip)."""
    P = 100.0
    errors = []
    for n in (10, 20, 40):
        model = _cantilever(n, P)
        X = static_equilibrium(model, tol=1e-12).position
        errors.append(-X[-1, 2] / (P * L**3 / (3 * EI)) - 1)
        _, moment, shear, _ = bending_state(model.network, X)
        assert np.linalg.norm(moment[0]) == pytest.approx(P * X[-1, 0], rel=1e-10)
        assert np.linalg.norm(moment[0]) == pytest.approx(P * L, rel=1e-6)   # L - x_tip below 1e-6 L here
        assert shear == pytest.approx(P, rel=1e-6)
    assert errors[-1] == pytest.approx(3.1e-4, rel=0.05)
    assert _order(errors) == pytest.approx([2.0, 2.0], abs=0.05)


def test_cantilever_on_a_root_spring():
    """A root spring k = 2e6 N m/rad adds the rigid turn P L / k: tip P L^3 / (3 EI) + P L^2 / k = 8.333e-3 m,
    relative errors 2.0e-3, 5.0e-4, 1.24e-4 at 10, 20, 40 elements: order 2 (to 0.05), which holds because
    the spring sits in series with the end's half element (a spring on the first element's chord alone errs
    by -5.8 %, -2.9 %, -1.5 %: order 1). The spring's moment is P times the lever arm (statics, to 1e-10)."""
    P, k = 100.0, 2e6
    exact = P * L**3 / (3 * EI) + P * L**2 / k
    errors = []
    for n in (10, 20, 40):
        model = _cantilever(n, P, "spring", k)
        X = static_equilibrium(model, tol=1e-12).position
        errors.append(-X[-1, 2] / exact - 1)
        _, moment, _, _ = bending_state(model.network, X)
        assert np.linalg.norm(moment[0]) == pytest.approx(P * X[-1, 0], rel=1e-10)
    assert abs(errors[-1]) < 1.5e-4
    assert _order(errors) == pytest.approx([2.0, 2.0], abs=0.05)


# Mattiasson (1981) Table 1: P L^2 / EI -> (w / L, u / L) at the tip
MATTIASSON = {1.0: (0.30172, 0.05643), 2.0: (0.49346, 0.16064)}


def _elastica_root_curvature(alpha):
    """The elastica's root curvature kappa_0 L: theta'' = -alpha cos(theta) on [0, 1], theta(0) = 0 and
    theta'(1) = 0, by shooting on theta'(0) with scipy's solve_ivp at rtol 1e-12 (Bisshopp and Drucker's
    equation; the table gives it to its rounding as alpha (1 - u / L)). [-]"""
    from scipy.integrate import solve_ivp

    def end_moment(k0):
        sol = solve_ivp(lambda s, y: [y[1], -alpha * math.cos(y[0])], (0.0, 1.0), [0.0, k0], rtol=1e-12, atol=1e-14)
        return sol.y[1, -1]

    return brentq(end_moment, 1e-3, alpha, xtol=1e-14)


@pytest.mark.parametrize("alpha", sorted(MATTIASSON))
def test_cantilever_elastica_bisshopp_drucker(alpha):
    """The large-deflection cantilever: tip deflection w / L and shortening u / L against Mattiasson's table,
    and the root curvature (0.943567 / L and 1.678717 / L by shooting, which the table's alpha (1 - u / L)
    confirms to its rounding, 1e-5): the known curvature of the mesh study. At 10, 20, 40 elements w / L errs
    by 1.5e-3, 3.7e-4, 9.3e-5 (alpha 1) and 2.3e-3, 5.8e-4, 1.4e-4 (alpha 2), the root curvature by -3.5e-4,
    -8.8e-5, -2.2e-5 (alpha 1) and -1.0e-3, -2.6e-4, -6.5e-5 (alpha 2) relative: order 2 for both, asserted to
    0.1; at 40 elements w / L and u / L within 2e-4 (the table's rounding is 5e-6) and the curvature within
    1e-4 relative."""
    w_ref, u_ref = MATTIASSON[alpha]
    P = alpha * EI / L**2
    kappa_ref = _elastica_root_curvature(alpha) / L
    assert kappa_ref == pytest.approx(alpha * (1.0 - u_ref) / L, abs=1e-5 / L)
    err_w, err_k = [], []
    for n in (10, 20, 40):
        model = _cantilever(n, P)
        X = static_equilibrium(model, tol=1e-12).position
        curvature, _, _, _ = bending_state(model.network, X)
        err_w.append(-X[-1, 2] / L - w_ref)
        err_k.append(curvature[0] / kappa_ref - 1)
        u = 1.0 - X[-1, 0] / L
    assert abs(err_w[-1]) < 2e-4
    assert abs(u - u_ref) < 2e-4
    assert abs(err_k[-1]) < 1e-4
    assert _order(np.abs(err_w)) == pytest.approx([2.0, 2.0], abs=0.1)
    assert _order(np.abs(err_k)) == pytest.approx([2.0, 2.0], abs=0.1)


def test_pinned_beam_uniform_load_moment_and_deflection():
    """The pinned ends unchanged: a simply supported beam (EI = 1e7 N m^2, L = 10 m, w = 10 N/m) has its midspan
    moment w L^2 / 8 = 125 N m and deflection 5 w L^4 / (384 EI) = 1.302e-4 m. The discrete moment at midspan
    is w L^2 / 8 exactly by statics on any even mesh (the supports' reactions w (L - h) / 2 on the line, the
    inner nodes' loads w h): -3.5e-6 and -4.8e-6 measured at 20 and 40 elements (the sag's own lever arms),
    asserted to 1e-5; the deflection errs by 2.0e-3, 5.0e-4 (asserted to 10 % of that); no moment at the pins."""
    w = 10.0
    for n in (20, 40):
        s = np.linspace(0.0, L, n + 1)
        kinds = np.full(n + 1, FREE)
        kinds[[0, -1]] = FIXED
        model = _line(s, np.column_stack([s, 0 * s, 0 * s]), kinds, w=w, ea=1e9)
        X = static_equilibrium(model, tol=1e-12).position
        curvature, moment, _, _ = bending_state(model.network, X)
        mid = np.linalg.norm(moment[n // 2])
        assert mid == pytest.approx(w * L**2 / 8, rel=1e-5)
        assert -X[n // 2, 2] == pytest.approx(5 * w * L**4 / (384 * EI), rel=2.2e-3 if n == 20 else 5.5e-4)
        assert curvature[0] == curvature[-1] == 0.0


# the Irvine case: a heavy cable (w = 100 N/m, 10 m) between level supports 9.9 m apart, the catenary parameter
# a = H / w = 20.137 m, end tension 2075 N, end slope 0.2434 rad below the horizontal, curvature there 0.0468 1/m
CAB_L, CAB_S, CAB_W = 10.0, 9.9, 100.0


def _cable(lam, delta, h0, hmax, refine=0):
    """The cable clamped at end A at ``delta`` above the EI = 0 catenary's end tangent, EI = lam^2 T_end; the
    mesh grows from ``h0`` by 1.1 an element to ``hmax`` (then each element halved ``refine`` times).
    Returns (s, X, state, EI, d, catenary parameter a)."""
    a = brentq(lambda a: 2 * a * math.sinh(CAB_S / (2 * a)) - CAB_L, 1.0, 1e3)
    phi = math.atan(CAB_L / (2 * a))
    ei = lam**2 * CAB_W * a / math.cos(phi)
    s = [0.0]
    h = h0
    while s[-1] < CAB_L:
        s.append(s[-1] + h)
        h = min(1.1 * h, hmax)
    s = np.array(s) * CAB_L / s[-1]
    for _ in range(refine):
        s = np.sort(np.concatenate([s, 0.5 * (s[1:] + s[:-1])]))
    u = s - CAB_L / 2
    X0 = np.column_stack([a * np.arcsinh(u / a) + CAB_S / 2, 0 * s, np.sqrt(a * a + u * u) - math.hypot(a, CAB_L / 2)])
    kinds = np.full(len(s), FREE)
    kinds[[0, -1]] = FIXED
    d = np.array([math.cos(delta - phi), 0.0, math.sin(delta - phi)])
    model = _line(s, X0, kinds, w=CAB_W, ei=ei, ea=1e10, hinges=[(0, 0, "clamp", None, d)])
    return s, model, static_equilibrium(model, tol=1e-10), ei, d, a


def test_clamped_cable_catenary_limit():
    """As EI -> 0 the clamped cable tends to the catenary: its horizontal tension H errs from the catenary's
    w a = 2013.7 N by -0.80 %, -0.40 %, -0.20 % at lambda = sqrt(EI / T) = 0.04, 0.02, 0.01 m (Delta = 0.2 rad):
    the boundary layer's first-order effect, order 1 in lambda (asserted to 0.05), within 0.25 % at 0.01 m."""
    errors = []
    for lam in (0.04, 0.02, 0.01):
        _, _, st, _, _, a = _cable(lam, 0.2, lam / 4, 0.1)
        errors.append(-st.support[-1, 0] / (CAB_W * a) - 1)
    assert all(e < 0 for e in errors)
    assert abs(errors[-1]) < 2.5e-3
    assert _order(np.abs(errors)) == pytest.approx([1.0, 1.0], abs=0.05)


def test_clamped_cable_boundary_layer_irvine():
    """lambda = 0.02 m, the clamp 0.2 rad off the catenary: the end moment against the boundary layer's
    2 sqrt(EI T) sin(Delta / 2) - EI kappa_cat (about 8.28 N m), with T and the catenary's tangent those of the
    line's force on the clamp (the outer solution's, which the layer shifts by O(lambda) from the EI = 0
    catenary's: Delta 0.2012 rad). The mesh grows from lambda / 2 by 1.1 to 0.2 m (72 elements), halved
    twice: errors -3.2e-2, -8.1e-3, -1.95e-3 (a third halving: -4.7e-4, so the closed form holds to about
    5e-4): order 2 to 0.1, and within 3e-3 at 288 elements. The moment's decay length over lambda to 4 lambda
    is lambda to 1 % (1.0027 measured; the layer's nonlinearity and the tension's change along it)."""
    errors = []
    for refine in range(3):
        s, model, st, ei, d, a = _cable(0.02, 0.2, 0.01, 0.2, refine)
        force = st.support[0].copy()
        force[2] += 0.5 * CAB_W * (s[1] - s[0])  # the end node's half-element weight, which its support carries
        T = np.linalg.norm(force)
        delta = math.acos(float(d @ force) / T)
        kappa_cat = a / (a * a + (CAB_L / 2) ** 2)
        reference = 2 * math.sqrt(ei * T) * math.sin(delta / 2) - ei * kappa_cat
        _, moment, _, _ = bending_state(model.network, st.position)
        errors.append(np.linalg.norm(moment[0]) / reference - 1)
    assert abs(errors[-1]) < 3e-3
    assert _order(np.abs(errors)) == pytest.approx([2.0, 2.0], abs=0.1)
    # the decay: the signed moment less the catenary's (which bends the other way), on a log scale
    lam = 0.02
    u = s - CAB_L / 2
    layer = np.sign(moment[0, 1]) * moment[:, 1] + ei * a / (a * a + u * u)
    near = (s > lam) & (s < 4 * lam)
    decay = -1.0 / np.polyfit(s[near], np.log(layer[near]), 1)[0]
    assert decay == pytest.approx(lam, rel=0.01)


def _stiffness_and_mass(model, X):
    """The Newton matrix K = -dF/dx (dense) and the lumped node masses of the free nodes, and the forces."""
    nn = model.network.n_nodes
    F, M = np.zeros((nn, 3)), np.zeros((nn, 3, 3))
    nd, bw = 3 * model.nfree, model.bw
    band = np.zeros((nd, 2 * bw + 1))
    K.loads(X, np.zeros_like(X), 0.0, *model.element_args(), model.fidx, model.env, model.cur_depth,
            model.cur_speed, False, model.sea, F, M, np.zeros(model.network.n_elements), band, bw, 0.0, 0.0)
    Kd, Md = np.zeros((nd, nd)), np.zeros((nd, nd))
    for i in range(nd):
        for j in range(max(0, i - bw), min(nd, i + bw + 1)):
            Kd[i, j] = band[i, bw + j - i]
    for i in np.flatnonzero(model.fidx >= 0):
        f = model.fidx[i]
        Md[3 * f:3 * f + 3, 3 * f:3 * f + 3] = M[i]
    return Kd, Md, F


def test_cantilever_natural_frequencies():
    """The clamp in the dynamics' matrices: the bending frequencies of a cantilever (EI = 1e7 N m^2, 10 kg/m,
    L = 10 m) from the tangent and the lumped masses, f_n = (beta_n L)^2 / (2 pi L^2) sqrt(EI / m) with
    beta_n L = 1.875104, 4.694091, 7.854757 (5.596, 35.07, 98.20 Hz): errors -8.4e-3, -2.1e-3, -5.3e-4 (mode
    1), -4.1e-2, -1.06e-2, -2.7e-3 (mode 2), -8.3e-2, -2.2e-2, -5.6e-3 (mode 3) at 10, 20, 40 elements: order
    2 for each, asserted to 0.15 (mode 3 at 10 elements is still coarse: 1.9), and within 6e-4, 3e-3, 6e-3 at
    40. The axial modes (250 Hz and up) stay above them; each bending mode is there twice (y and z)."""
    beta = np.array([1.875104069, 4.694091133, 7.854757438])
    exact = beta**2 / (2 * math.pi * L**2) * math.sqrt(EI / 10.0)
    errors = []
    for n in (10, 20, 40):
        s = np.linspace(0.0, L, n + 1)
        kinds = np.r_[FIXED, np.full(n, FREE)]
        model = _line(s, np.column_stack([s, 0 * s, 0 * s]), kinds, ea=1e9, hinges=[(0, 0, "clamp", None, X_AXIS)])
        Kd, Md, _ = _stiffness_and_mass(model, model.network.position)
        f = np.sqrt(np.abs(scipy.linalg.eigh(Kd, Md, eigvals_only=True))) / (2 * math.pi)
        pairs = np.sort(f)[:6]
        assert pairs[0::2] == pytest.approx(pairs[1::2], rel=1e-9)
        errors.append(pairs[0::2] / exact - 1)
    errors = np.abs(np.array(errors))
    assert np.all(errors[-1] < [6e-4, 3e-3, 6e-3])
    for mode in range(3):
        assert _order(errors[:, mode]) == pytest.approx([2.0, 2.0], abs=0.15)


#: A moment-curvature law with three slopes (30000, 10000 and 4000 N m^2) whose pieces the bent line's hinges
#: all fall on (their curvatures 0.23 to 0.88 1/m), beyond its last knot too
LAW3 = np.array([[0.0, 0.0], [0.25, 7500.0], [0.45, 9500.0], [0.7, 10500.0]])


@pytest.mark.parametrize("kind", ["clamp", "spring", "clamp-law", "law-mixed"])
def test_end_hinge_tangent_is_the_derivative_of_the_forces(kind):
    """The Newton matrix (K = -dF/dx) of a line held at both ends by end hinges, against central differences of
    the forces, on a bent 3D line with every node free (the end nodes too, so that all four blocks of each end
    hinge show), bending dominating the axial stiffness: 1e-6 relative to the largest entry (the differences
    with a 1e-6 m step agree to about 1e-9). ``clamp-law``: every element with the nonlinear law :data:`LAW3`
    (inner and clamped hinges of :func:`seacable.mooring.kernel.hinge_law`, the exact gradient of their energy, so
    that K is symmetric too, to 1e-12); ``law-mixed``: every other element, the hinges between taking the mean of
    a law and a linear EI (measured: 2.5e-9 for all four; a tangent without the axial pair's or with the clamp's
    dg/dl halved, a slip found in writing it, is off by 1e-3 to 1e-2)."""
    n = 6
    s = np.linspace(0.0, L, n + 1)
    rng = np.random.default_rng(40)
    X = np.column_stack([s, 0 * s, 0 * s]) + rng.normal(scale=0.4, size=(n + 1, 3))
    X[:, 2] -= 100.0
    da, db = np.array([0.8, 0.36, 0.48]), np.array([0.6, -0.64, 0.48])
    k = 5e4 if kind == "spring" else None
    laws = None
    if kind == "clamp-law":
        laws = (LAW3,) * n
    elif kind == "law-mixed":
        laws = tuple(LAW3 if e % 2 else None for e in range(n))
    held = "spring" if kind == "spring" else "clamp"
    model = _line(s, np.column_stack([s, 0 * s, 0 * s]), np.full(n + 1, FREE), ei=3e4, ea=1e3,
                  hinges=[(0, 0, held, k, da), (0, 1, held, k, db)], laws=laws)

    def loads(X):
        Kd, _, F = _stiffness_and_mass(model, X)
        return F, Kd

    _, Kd = loads(X)
    h = 1e-6
    Kfd = np.zeros_like(Kd)
    for i in range(n + 1):
        for r in range(3):
            Xp, Xm = X.copy(), X.copy()
            Xp[i, r] += h
            Xm[i, r] -= h
            dF = -(loads(Xp)[0] - loads(Xm)[0]) / (2 * h)
            for j in range(n + 1):
                Kfd[3 * model.fidx[j]:3 * model.fidx[j] + 3, 3 * model.fidx[i] + r] = dF[j]
    assert np.max(np.abs(Kd - Kfd)) < 1e-6 * np.max(np.abs(Kd))
    if kind == "clamp-law":
        assert np.max(np.abs(Kd - Kd.T)) < 1e-12 * np.max(np.abs(Kd))
        kappa = bending_state(model.network, X)[0]
        assert set(np.searchsorted(LAW3[:, 0], kappa)) == {1, 2, 3, 4}   # a hinge on each piece


_HANG = """
name: hang
line:
  segments:
    - length: 60
      line_type: {name: cable, diameter: 0.15, mass_per_length: 40, axial_stiffness: 5e8, bending_stiffness: 7.2e6}
environment: {depth: 100}
analysis:
  type: mooring_static
  anchor: [0, -70]
  fairlead: [0, -9.9]
  n_elements: 60
"""


def _case(**analysis):
    import yaml

    data = yaml.safe_load(_HANG)
    data["analysis"].update(analysis)
    return sc.Case(**data)


def test_case_fairlead_clamp_declination_convention():
    """Through the case file (OrcaFlex's direction: along the line towards end B, declination from the upward
    vertical): a taut vertical line (60 m between z = -70 and -9.9 m: T = 0.90 MN at the top, lambda =
    sqrt(EI / T) = 2.83 m) clamped at the fairlead at declination 0.1 rad. Its top moment against the layer's
    2 sqrt(EI T) sin(Delta / 2) = 2.666e5 N m, T and Delta (0.1049 rad) from the line's force on the fairlead
    (the outer line's direction): -1.5e-2, -4.0e-3 at 60 and 120 elements (-1.1e-3 at 240): order 2 to 0.15,
    within 6e-3 at 120. Azimuth 0 tilts the line's top towards +x, so the line comes up from -x; pi the mirror,
    the same moment (to 1e-9). End A pinned: no curvature there."""
    errors, runs = [], {}
    for n, azimuth in ((60, 0.0), (120, 0.0), (60, math.pi)):
        clamp = {"type": "clamped", "declination": 0.1, "azimuth": azimuth}
        ds = sc.run(_case(n_elements=n, fairlead_end_condition=clamp))
        runs[n, azimuth] = ds
        assert float(ds.curvature[0]) == 0.0
        if azimuth == 0.0:
            force = np.array([float(ds[f"fairlead_force_{c}"]) for c in "xyz"])
            T = np.linalg.norm(force)
            delta = math.acos(float(-force @ end_direction(0.1, 0.0)) / T)
            errors.append(float(ds.bend_moment[-1]) / (2 * math.sqrt(7.2e6 * T) * math.sin(delta / 2)) - 1)
    assert abs(errors[-1]) < 6e-3
    assert _order(np.abs(errors)) == pytest.approx([2.0], abs=0.15)
    x0, xp = (runs[60, a].x.values for a in (0.0, math.pi))
    assert x0[-2] < x0[-1] and xp[-2] > xp[-1]
    assert float(runs[60, math.pi].bend_moment[-1]) == pytest.approx(float(runs[60, 0.0].bend_moment[-1]), rel=1e-9)
    assert runs[60, 0.0].shear_force.dims == ("element",) and runs[60, 0.0].declination.attrs["units"] == "rad"


@pytest.mark.parametrize("end, message", [
    ({"type": "clamped", "declination": 200.0}, "must be <= 3.14159 rad, got 200 rad"),
    ({"type": "clamped", "declination": -0.1}, "must be >= 0 rad"),
    ({"type": "clamped"}, "needs its direction: 'declination'"),
    ({"type": "spring", "declination": 0.1}, "needs 'stiffness'"),
    ({"type": "pinned", "declination": 0.1}, "a pinned end takes no moment"),
])
def test_bad_end_conditions_are_refused(end, message):
    with pytest.raises(InputError, match=message):
        _case(fairlead_end_condition=end)


def test_clamp_on_a_line_without_bending_stiffness_is_refused():
    import yaml

    data = yaml.safe_load(_HANG)
    data["line"]["segments"][0]["line_type"]["bending_stiffness"] = 0.0
    data["analysis"]["anchor_end_condition"] = {"type": "clamped", "declination": 0.0}
    with pytest.raises(InputError, match=r"anchor_end_condition is clamped, but .* bending stiffness \(EI = 0 N m\^2\)"):
        sc.check(sc.Case(**data))


def test_clamp_turns_with_the_platform():
    """A fairlead clamp on a pitching platform turns with it (mooring_dynamic): the taut line above, clamped at
    declination 0.1 rad, the platform pitching 0.05 rad about the fairlead at a period of 400 s (quasi-static: the
    line's own periods are under a second). A quarter period in, the clamp's direction is at declination 0.1 + 0.05
    (a pitch turns +z towards +x), so the top moment and the fairlead's force are the statics' with the clamp at
    0.15 rad: measured 3e-5 and 3.5e-6 of them (the line's small inertia and drag in the slow turn), held to 1e-3
    and 1e-4. A clamp left at rest would keep the 0.1 rad moment, 35 % smaller."""
    clamp = {"type": "clamped", "declination": 0.1, "azimuth": 0.0}
    motion = {"type": "platform", "reference": [0.0, 0.0, -9.9], "amplitude": [0, 0, 0, 0, 0.05, 0], "period": 400.0}
    ds = sc.run(_case(type="mooring_dynamic", fairlead_end_condition=clamp, duration=100.0, time_step=0.5,
                      output_interval=10.0, motion=motion))
    static = sc.run(_case(fairlead_end_condition={**clamp, "declination": 0.15}))
    assert float(ds.bend_moment[-1, -1]) == pytest.approx(float(static.bend_moment[-1]), rel=1e-3)
    assert float(ds.fairlead_tension[-1]) == pytest.approx(float(static.fairlead_tension), rel=1e-4)
    at_rest = sc.run(_case(fairlead_end_condition=clamp))
    assert float(ds.bend_moment[0, -1]) == pytest.approx(float(at_rest.bend_moment[-1]), rel=1e-6)  # t = 0

"""Nonlinear moment-curvature laws, bend restrictors and a bend stiffener's own weight, against closed forms.

Issue 40: a line type's or a bend stiffener's law ``M(kappa)`` (:mod:`seacable.moment_curvature`) acts at each hinge
of the mooring finite-element line with the gradient of its stored energy ``U = L W(kappa)``, ``W = integral M dk``
(:func:`seacable.mooring.kernel.bending_loads`); a bend restrictor (:class:`seacable.sections.BendRestrictor`) adds
a lock at ``1 / locking_radius`` with a stiff branch of ``LOCK_FACTOR`` times the cable's EI; a stiffener with a
density and a restrictor put their own mass and buoyancy on the line (:func:`seacable.sections.
element_section_properties`).

Closed forms:

- a cantilever under a tip load P, small deflection (Timoshenko and Gere, *Mechanics of Materials*: the moment
  ``M(u) = P u`` at the distance u from the tip is known by statics whatever the law; the curvature is the law's
  inverse of it and the tip deflection the moment-area integral ``w = integral_0^L kappa(P u) u du``). For the
  bilinear law ``EI1 kappa`` up to ``kappa_y``, then ``M_y + EI2 (kappa - kappa_y)``, with ``u_y = M_y / P``::

      w = P u_y^3 / (3 EI1) + kappa_y (L^2 - u_y^2) / 2 + P (L^3 - u_y^3) / (3 EI2) - M_y (L^2 - u_y^2) / (2 EI2)
      kappa_root = kappa_y + (P L - M_y) / EI2

- the same cantilever with a bend restrictor over it whose lock curvature ``1 / R`` the root passes: where
  ``P u > EI / R`` the curvature is ``1 / R + (P u - EI / R) / (EI + k)``, k the lock's stiffness;
- a cable hanging free from its hang-off: the hang-off's vertical force is the line's weight in water, and a cone
  stiffener of root and tip diameters D0, D1 over a cable of diameter d adds ``(rho_s - rho) g (pi L_s / 12
  (D0^2 + D0 D1 + D1^2) - pi / 4 d^2 L_s)`` (a frustum less its bore), a restrictor ``(m_r - rho m_r / rho_r) g
  L_r``.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from seacable.line import Line, LineType, Segment
from seacable.moment_curvature import law_energy
from seacable.mooring import kernel as K
from seacable.mooring._indices import H_L0, H_NLAW, H_SIZE
from seacable.mooring.bending import bending_state
from seacable.mooring.network import FIXED, FREE, Network, network_from_line
from seacable.mooring.solver import MooringModel, Water, static_equilibrium
from seacable.sections import LOCK_FACTOR, BendRestrictor, BendStiffener, Cone

L, EI1, P = 10.0, 1e7, 100.0
KY = 2e-5                    # the armour's slip curvature [1/m]
MY = EI1 * KY                # 200 N m
EI2 = 2e6                    # full slip [N m^2]
BILINEAR = np.array([[0.0, 0.0], [KY, MY], [2 * KY, MY + EI2 * KY]])


def _model(n, laws=None, *, ei=EI1, positions=None, kinds=None, hinges=None, ea=1e9):
    """A cantilever along +x of n elements, clamped at node 0 along +x, tip load P down, no water; or any line of
    ``positions`` and ``kinds``."""
    s = np.linspace(0.0, L, n + 1)
    X0 = np.column_stack([s, 0 * s, 0 * s]) if positions is None else positions
    if kinds is None:
        kinds = np.r_[FIXED, np.full(n, FREE)]
    zero, one = np.zeros(n + 1), np.ones(n)
    pw = zero.copy()
    pw[n] = P
    net = Network(position=X0, kind=np.asarray(kinds), channel=np.full(n + 1, -1), point_mass=zero.copy(),
                  point_added_mass=zero.copy(), point_weight=pw, point_volume=zero.copy(), point_drag_area=zero.copy(),
                  elements=np.column_stack([np.arange(n), np.arange(1, n + 1)]), length=np.diff(s),
                  axial_stiffness=ea * one, axial_damping=0 * one, mass_per_length=10 * one,
                  weight_per_length=0 * one, diameter=0.1 * one, cdn=0 * one, cdt=0 * one, can=0 * one, cat=0 * one,
                  element_line=np.zeros(n, np.int64), line_nodes=(np.arange(n + 1),), line_names=("c",),
                  arc_length=s, n_channels=0, channel_names=(), bending_stiffness=ei * one,
                  end_hinges=((0, 0, "clamp", None, np.array([1.0, 0.0, 0.0])),) if hinges is None else hinges,
                  element_moment_curvature=laws)
    return MooringModel(net, Water(density=0.0, gravity=9.81, depth=None))


def _forces(model, X):
    F, M = np.zeros((len(X), 3)), np.zeros((len(X), 3, 3))
    K.loads(X, np.zeros_like(X), 0.0, *model.element_args(), model.fidx, model.env, model.cur_depth,
            model.cur_speed, False, model.sea, F, M, np.zeros(model.network.n_elements), np.zeros((0, 0)), model.bw,
            0.0, 0.0)
    return F


def _bending_energy(model, X):
    """U = sum over the hinges of L0 W(kappa), kappa = 2 sin(theta / 2) / L0 (L0 the hinge's unstretched length,
    half the end element at a clamp), from the hinge table's laws, independently of the kernel. [J]"""
    hinges, table = model.network.hinge_arrays()
    u = 0.0
    for (i0, i1, i2), row in zip(hinges, table):
        law = row[H_SIZE:H_SIZE + 2 * int(row[H_NLAW])]
        if i0 == i1 or i1 == i2:   # a clamp: the given direction e against the end element
            iw = i2 if i0 == i1 else i0
            a = row[2:5]
            b = (X[iw] - X[i1]) / np.linalg.norm(X[iw] - X[i1])
        else:
            a = (X[i1] - X[i0]) / np.linalg.norm(X[i1] - X[i0])
            b = (X[i2] - X[i1]) / np.linalg.norm(X[i2] - X[i1])
        kappa = np.linalg.norm(b - a) / row[H_L0]   # |b - a| = 2 sin(theta / 2)
        u += row[H_L0] * float(law_energy(law, kappa))
    return u


def test_law_hinges_act_with_the_gradient_of_their_energy():
    """On a bent 3D line (every node free, clamped at both ends, every element with a three-piece law whose pieces
    its hinges all fall on), the kernel's bending forces (the loads less those of the same line without bending)
    against central differences of ``U = sum L0 W(kappa)`` summed independently from the law (:func:`law_energy`):
    to 1e-7 of the largest force (measured 8e-10 with a 1e-6 m step). MoorDyn's linear hinge, ``-M grad(theta)``
    on the stretched lengths, is not such a gradient (with a linear law's U it misses by 0.57 of the largest force
    on this strongly bent and stretched line), and the law's force written that way (planted) fails, as does a law
    whose slopes the kernel takes 1 % off."""
    n = 6
    s = np.linspace(0.0, L, n + 1)
    rng = np.random.default_rng(7)
    X = np.column_stack([s, 0 * s, 0 * s]) + rng.normal(scale=0.4, size=(n + 1, 3))
    law = np.array([[0.0, 0.0], [0.15, 4500.0], [0.3, 6000.0], [0.5, 6600.0]])   # hinges at 0.12 to 1.6 1/m
    held = ((0, 0, "clamp", None, np.array([0.8, 0.36, 0.48])), (0, 1, "clamp", None, np.array([0.6, -0.64, 0.48])))
    bent = _model(n, (law,) * n, ei=3e4, kinds=np.full(n + 1, FREE), hinges=held, ea=1e3)
    bare = _model(n, None, ei=0.0, kinds=np.full(n + 1, FREE), hinges=(), ea=1e3)
    f = _forces(bent, X) - _forces(bare, X)
    grad = np.zeros_like(X)
    h = 1e-6
    for i, r in itertools.product(range(n + 1), range(3)):
        Xp, Xm = X.copy(), X.copy()
        Xp[i, r] += h
        Xm[i, r] -= h
        grad[i, r] = (_bending_energy(bent, Xp) - _bending_energy(bent, Xm)) / (2 * h)
    assert np.max(np.abs(f + grad)) < 1e-7 * np.max(np.abs(f))
    kappa = bending_state(bent.network, X)[0]
    assert set(np.searchsorted(law[:, 0], kappa)) == {1, 2, 3, 4}   # a hinge on each piece, and beyond


def test_cantilever_with_a_bilinear_law_under_a_tip_load():
    """EI1 = 1e7 N m^2 up to kappa_y = 2e-5 1/m (M_y = 200 N m), then EI2 = 2e6 N m^2; P = 100 N, L = 10 m: the
    armour slips over the 8 m nearest the root. Tip deflection 1.272e-2 m (the module's closed form) with relative
    errors 5.5e-3, 1.37e-3, 3.4e-4 at 10, 20, 40 elements: order 2 to 0.05 (the kink of the law at u_y does not
    spoil it) and within 3.5e-4 at 40. The root curvature is the law's inverse of the clamp's moment, P times the
    tip's lever arm (statics), to 1e-7 (the law's hinge transmits M cos(theta / 2), theta ~ 4e-4 rad here), and
    kappa_y + (P L - M_y) / EI2 = 4.2e-4 1/m to 2e-6 (the lever arm is L less 1e-5 m; measured 7e-9 and 1.16e-6 at
    10 elements). A law the kernel took 1 % stiffer (planted) moves the tip 0.9 %: it fails."""
    uy = MY / P
    w = (P * uy**3 / (3 * EI1) + KY * (L**2 - uy**2) / 2 + P * (L**3 - uy**3) / (3 * EI2)
         - MY * (L**2 - uy**2) / (2 * EI2))
    errors = []
    for n in (10, 20, 40):
        model = _model(n, (BILINEAR,) * n)
        X = static_equilibrium(model, tol=1e-12).position
        errors.append(-X[-1, 2] / w - 1)
        kappa = bending_state(model.network, X)[0]
        assert kappa[0] == pytest.approx(KY + (P * X[-1, 0] - MY) / EI2, rel=1e-7)
        assert kappa[0] == pytest.approx(KY + (P * L - MY) / EI2, rel=2e-6)
    assert abs(errors[-1]) < 3.5e-4
    assert [math.log2(a / b) for a, b in itertools.pairwise(errors)] == pytest.approx([2.0, 2.0], abs=0.05)


def _restrictor_laws(n, **kw):
    """The elements' laws of a 10 m cable of EI 1e7 N m^2 with a bend restrictor over it all, through the line's
    sections (:func:`network_from_line`)."""
    cable = LineType(diameter=0.1, mass_per_length=10.0, axial_stiffness=1e9, bending_stiffness=EI1)
    line = Line(segments=(Segment(line_type=cable, length=L),),
                sections=(BendRestrictor(end="A", length=L, diameter=0.2, **kw),))
    return network_from_line(line, (0, 0, 0), (L, 0, 0), water_density=1025.0, gravity=9.81,
                             n_elements=n).element_moment_curvature


@pytest.mark.parametrize("lock_stiffness", [None, 3e8])
def test_restrictor_caps_the_curvature_of_a_cantilever(lock_stiffness):
    """A restrictor locking at R = 2e4 m (1 / R = 5e-5 1/m, reached where P u > EI / R: the 5 m nearest the root) on
    the cantilever, whose free root curvature would be P L / EI = 1e-4 1/m: the root's curvature is 1 / R + (P x_tip
    - EI / R) / (EI + k), k = LOCK_FACTOR EI by default (1 / R (1 + 0.999e-3)) or as given (3e8 N m^2: 1 / R (1 +
    0.323)), to 1e-9 (statics; measured 1e-13); the free nodes' curvature is P u / EI (to 1e-6: the lever arm's
    shortening); a restrictor that did not lock (its lock law left out, planted) fails."""
    R = 2e4
    k = LOCK_FACTOR * EI1 if lock_stiffness is None else lock_stiffness
    n = 20
    model = _model(n, _restrictor_laws(n, locking_radius=R, lock_stiffness=lock_stiffness))
    X = static_equilibrium(model, tol=1e-12).position
    kappa = bending_state(model.network, X)[0]
    assert kappa[0] == pytest.approx(1 / R + (P * X[-1, 0] - EI1 / R) / (EI1 + k), rel=1e-9)
    if lock_stiffness is None:
        assert kappa[0] * R - 1 == pytest.approx(1 / (1 + LOCK_FACTOR) * (P * L * R / EI1 - 1), rel=1e-5)
    u = L - X[:, 0]
    free = (P * u < 0.9 * EI1 / R) & (np.arange(n + 1) > 0) & (np.arange(n + 1) < n)
    assert free.sum() >= 8
    assert kappa[free] == pytest.approx(P * u[free] / EI1, rel=1e-6)


def _hang_off_force(line, rho=1025.0, g=9.81):
    """The vertical force a cable hanging free from z = -10 m takes at its hang-off (its weight in water). [N]"""
    net = network_from_line(line, (0, 0, -10.0 - line.length), (0, 0, -10.0), water_density=rho, gravity=g,
                            n_elements=30)
    kinds = net.kind.copy()
    kinds[0] = FREE
    model = MooringModel(net.replace(kind=kinds), Water(density=rho, gravity=g, depth=None))
    X = static_equilibrium(model, tol=1e-10).position
    return -_forces(model, X)[-1, 2]


def test_a_stiffeners_and_a_restrictors_own_weight_in_the_hang_off_force():
    """A 30 m cable (40 kg/m, d = 0.1 m) hanging free, 1025 kg/m^3 water: its hang-off force is its weight in water
    w L = 9402.8 N; a 4 m polyurethane cone (D 0.4 to 0.12 m, 1150 kg/m^3) adds (rho_s - rho) g V, V the frustum
    less its bore, 0.2015 m^3: 247.1 N (the Simpson mean over each element is exact for the cone's quadratic
    area); a table stiffener with the same diameters as its geometry the same; a restrictor of 20 kg/m at 1150
    kg/m^3 over 4 m, 85.30 N. To 1e-6 of the added weight (the static solve's residual: measured 1.4e-7 and
    5.6e-7); sections that added only their EI (their weight left out, planted) fail."""
    rho, g, d = 1025.0, 9.81, 0.1
    cable = LineType(diameter=d, mass_per_length=40.0, axial_stiffness=1e9, bending_stiffness=1e4)
    bare = Line(segments=(Segment(line_type=cable, length=30.0),))
    w = _hang_off_force(bare)
    assert w == pytest.approx(cable.submerged_weight(rho, g) * 30.0, rel=1e-9)
    cone = Cone(root_diameter=0.4, tip_diameter=0.12, modulus=5e7)
    frustum = math.pi / 12 * 4.0 * (0.4**2 + 0.4 * 0.12 + 0.12**2) - math.pi / 4 * d**2 * 4.0
    table = BendStiffener(end="B", length=4.0, table=((0.0, 2e5), (4.0, 1e3)), density=1150.0,
                          geometry=((0.0, 0.4), (4.0, 0.12)))
    cases = [(BendStiffener(end="B", length=4.0, cone=cone, density=1150.0), (1150.0 - rho) * g * frustum),
             (table, (1150.0 - rho) * g * frustum),
             (BendRestrictor(end="B", length=4.0, locking_radius=3.0, diameter=0.3, mass_per_length=20.0),
              (20.0 - rho * 20.0 / 1150.0) * g * 4.0)]
    for sec, added in cases:
        line = Line(segments=(Segment(line_type=cable, length=30.0),), sections=(sec,))
        assert _hang_off_force(line) - w == pytest.approx(added, rel=1e-6)

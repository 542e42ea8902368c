"""The mooring kernel's Newton matrix: the derivatives of its forces, against central differences.

:func:`seacable.mooring.kernel.loads` adds ``cm M + cc C + K`` to the band, with ``K = -dF/dx`` and
``C = -dF/dv`` of the forces it returns. A line in a current lying partly on the seabed (the contact spring
in its linear range, its damper ramping, Coulomb friction regularised), slack and taut elements, moving
nodes: each block of K and C against central differences of F (steps 1e-7 m, 1e-7 m/s; their error is
round-off, 1e-16 F / 1e-7, about 1e-3 in these units).

The Newton matrix leaves out on purpose the change of the drag and of the axial damper with the elements'
direction (``d(drag)/dx`` through the tangent, at most the drag over an element's length, about 30 N/m here;
the damper's rate ``t . dv`` turning with t, at most ``c |dv| / (L l)``, a few 1e3 N/m with these random
velocities, computed below), against stiffnesses of 1e5 to 1e7 N/m: Newton converges as fast without them.
K is compared to 1e4 N/m, C (nothing left out) to its round-off, 1e-2 N s/m. A dropped or wrong term of
either (the drag tangent's u_n u_n^T part, about 1e3 N s/m; the geometric stiffness T / l, 1e5 N/m; the
friction's change with the normal force, mu k_b d_n, 3e6 N/m; a block's sign) is far above those.
"""

from __future__ import annotations

import numpy as np
import pytest

import seacable as sc
from seacable.mooring import kernel as K
from seacable.mooring.network import network_from_line
from seacable.mooring.solver import MooringModel, Water, static_equilibrium

CHAIN = sc.LineType(diameter=0.09, mass_per_length=77.7, weight_in_water=698.0, axial_stiffness=3.84e8,
                    drag_normal=1.6, drag_tangential=0.1, added_mass_normal=1.0, added_mass_tangential=0.5)


def _state():
    net = network_from_line(sc.Line.single(CHAIN, 400.0), (0, 0, -120.0), (330.0, 0, -20.0), water_density=1025.0,
                            gravity=9.80665, n_elements=20, damping_ratio=0.5)
    model = MooringModel(net, Water(depth=120.0, friction=0.6, current_depths=(0.0,), current_speeds=(0.8,),
                                    current_heading=0.5, rayleigh_mass=0.05))
    X = static_equilibrium(model).position.copy()
    rng = np.random.default_rng(2)
    grounded = X[:, 2] < -119.99
    assert 3 <= grounded.sum() <= 15  # a touchdown in the middle of the line
    X[~grounded] += rng.normal(0.0, 0.05, (int((~grounded).sum()), 3))
    X[grounded, :2] += rng.normal(0.0, 0.05, (int(grounded.sum()), 2))  # pressed in as at rest: linear spring
    V = rng.normal(0.0, 0.15, X.shape)
    return model, X, V


def _forces(model, X, V, band=None, cc=0.0):
    n = X.shape[0]
    F, M, ten = np.zeros((n, 3)), np.zeros((n, 3, 3)), np.zeros(model.network.n_elements)
    mat = np.zeros((0, 2 * model.bw + 1)) if band is None else band
    K.loads(X, V, 0.0, *model.element_args(), model.fidx, model.env, model.cur_depth, model.cur_speed, False,
            model.sea, F, M, ten, mat, model.bw, 0.0, cc)
    return F, ten


def _dense(model, band):
    """The band (rows of the free nodes' coordinates) as a dense matrix."""
    nd, bw = band.shape[0], model.bw
    out = np.zeros((nd, nd))
    for r in range(nd):
        for c in range(max(0, r - bw), min(nd, r + bw + 1)):
            out[r, c] = band[r, bw + c - r]
    return out


def _differences(model, X, V, which, h):
    """-dF/dx ("K") or -dF/dv ("C") by central differences of step ``h``, in the band's order of the free nodes."""
    free = np.flatnonzero(model.fidx >= 0)
    nd = 3 * model.nfree
    want = np.zeros((nd, nd))
    for i in free:
        for r in range(3):
            Xp, Xm, Vp, Vm = X.copy(), X.copy(), V.copy(), V.copy()
            if which == "K":
                Xp[i, r] += h
                Xm[i, r] -= h
            else:
                Vp[i, r] += h
                Vm[i, r] -= h
            dF = (_forces(model, Xp, Vp)[0] - _forces(model, Xm, Vm)[0]) / (2 * h)
            for j in free:  # the band's rows and columns: the free nodes in their order for a small bandwidth
                want[3 * model.fidx[j]:3 * model.fidx[j] + 3, 3 * model.fidx[i] + r] = -dF[j]
    return want


@pytest.mark.parametrize(("which", "atol"), [("K", 1e4), ("C", 1e-2)])
def test_the_newton_matrix_is_the_derivative_of_the_forces(which, atol):
    model, X, V = _state()
    nd = 3 * model.nfree
    band = np.zeros((nd, 2 * model.bw + 1))
    _, ten = _forces(model, X, V, band, cc=1.0 if which == "C" else 0.0)
    if which == "C":  # C alone: the matrix with cc = 1 less the one with cc = 0
        k_only = np.zeros_like(band)
        _forces(model, X, V, k_only, cc=0.0)
        band = band - k_only
    assert np.any(ten == 0.0) and np.any(ten > 1e4)  # slack elements on the seabed, taut ones above
    net = model.network
    ia, ib = net.elements[:, 0], net.elements[:, 1]
    chord = np.linalg.norm(X[ib] - X[ia], axis=1)
    turning = net.axial_damping * np.linalg.norm(V[ib] - V[ia], axis=1) / (net.length * chord)
    assert turning.max() < 0.5 * atol or which == "C"  # the damper's turning, left out of K, under the tolerance
    got = _dense(model, band)
    want = _differences(model, X, V, which, 1e-7)
    scale = np.abs(want).max()
    assert scale > (1e6 if which == "K" else 1e5)
    np.testing.assert_allclose(got, want, rtol=0, atol=atol)


def _towed_state(drag_area=0.4, added_mass=0.0):
    """A towed line in a 2 m/s flow (the frame moving with the vessel), with the drag's turning terms on: a body
    with lift at the end (its drag and added mass one number or three, per axis of the body), a lifting clump in
    line, moving nodes."""
    from seacable.case import TowedBody
    from seacable.towed.fe import steady_start, towed_system

    cable = sc.LineType(diameter=0.03, mass_per_length=2.0, axial_stiffness=4e6, drag_normal=1.5,
                        drag_tangential=0.02)
    clump = sc.PointMass(s=60.0, mass=200.0, weight_in_water=1500.0, drag_area=0.3, lift_coefficient=-0.5,
                         reference_area=0.4)
    body = TowedBody(mass=300.0, weight_in_water=2000.0, drag_area=drag_area, added_mass=added_mass,
                     lift_coefficient=0.6, reference_area=1.0)
    system = towed_system(sc.Line.single(cable, 200.0, attachments=(clump,)), (0.0, 0.0, 0.0),
                          Water(depth=None, current_speeds=(0.3,), current_heading=0.4), n_nodes=21, body=body)
    X = steady_start(system, (0.0, 0.0, 0.0), (2.0, 0.0, 0.0))
    model = system.model
    model.env[[K.E_FRAMEX, K.E_FRAMEY, K.E_FRAMEZ]] = (2.0, 0.0, 0.0)
    rng = np.random.default_rng(3)
    X[:-1] += rng.normal(0.0, 0.05, X[:-1].shape)
    V = rng.normal(0.0, 0.3, X.shape)
    return model, X, V


def _matrix_and_differences(model, X, V, which):
    """The towed line's Newton matrix ``which`` (K, or C alone: the band with cc = 1 less the band with cc = 0), its
    band, its dense form and the central differences of the forces it should equal."""
    band = np.zeros((3 * model.nfree, 2 * model.bw + 1))
    _forces(model, X, V, band, cc=1.0 if which == "C" else 0.0)
    if which == "C":
        k_only = np.zeros_like(band)
        _forces(model, X, V, k_only, cc=0.0)
        band = band - k_only
    return band, _dense(model, band), _differences(model, X, V, which, 1e-6)


@pytest.mark.parametrize(("which", "atol"), [("K", 1e-2), ("C", 1e-2)])
def test_a_towed_lines_newton_matrix_is_the_derivative_of_its_forces(which, atol):
    """The same check on a towed line, whose shape the drag sets: with ``E_DRAGTURN`` the drag's change with the
    elements' direction is in K (about 10-100 N/m here, against geometric stiffnesses T / l of a few 100 N/m),
    and the lift of the body and of a clump in line (1/2 rho C_L A (|u|^2 e_z - u_z u)) is in C. Nothing is left
    out: both to their round-off, 1e-2 (a dropped turning term or a lift tangent of the wrong sign is 1 to 1e3)."""
    model, X, V = _towed_state()
    band, got, want = _matrix_and_differences(model, X, V, which)
    np.testing.assert_allclose(got, want, rtol=0, atol=atol)
    # the terms under test are there: the turning terms without E_DRAGTURN, the lift's without lift, differ
    model.env[K.E_DRAGTURN] = 0.0
    bare = np.zeros_like(band)
    _forces(model, X, V, bare, cc=1.0 if which == "C" else 0.0)
    if which == "K":
        assert np.abs(_dense(model, bare) - got).max() > 10.0


@pytest.mark.parametrize("which", ["K", "C"])
def test_a_towed_bodys_drag_per_axis_is_in_the_newton_matrix(which):
    """A body with C_D A = [0.4, 1.2, 2.5] (along, across, vertical) and added mass [50, 150, 400] kg in the
    towed line above, across a current at 0.4 rad: its drag's damping sum_k 2 q_k |u_k| e_k e_k^T (in C) and the
    turn of its axes with the cable's direction at it (in K, the blocks of nodes 0 and 1) against central
    differences to the same round-off, 1e-2 (the body's drag is 1e3 N here: a dropped turn term is about
    q U^2 / l ~ 1e2 N/m, a dropped axis's damping 2 q U ~ 1e3 N s/m). And the body's node mass is
    M + sum_k m_k e_k e_k^T with the axes from nodes 0 and 1, to round-off."""
    from seacable.mooring._body import body_added_mass, body_axes

    model, X, V = _towed_state(drag_area=[0.4, 1.2, 2.5], added_mass=[50.0, 150.0, 400.0])
    band, got, want = _matrix_and_differences(model, X, V, which)
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-2)
    def node_mass(m):
        n = X.shape[0]
        F, M = np.zeros((n, 3)), np.zeros((n, 3, 3))
        K.loads(X, V, 0.0, *m.element_args(), m.fidx, m.env, m.cur_depth, m.cur_speed, False, m.sea, F, M,
                np.zeros(n - 1), np.zeros((0, 2 * m.bw + 1)), m.bw, 0.0, 0.0)
        return M[0]

    without, _, _ = _towed_state(drag_area=[0.4, 1.2, 2.5], added_mass=0.0)
    axes, ma = np.zeros((3, 3)), np.zeros((3, 3))
    body_axes(X[1, 0] - X[0, 0], X[1, 1] - X[0, 1], axes)
    body_added_mass(axes, np.array([50.0, 150.0, 400.0]), ma)
    assert abs(ma[0, 1]) > 1.0  # the axes are turned from the global ones: the tensor is not diagonal
    np.testing.assert_allclose(node_mass(model) - node_mass(without), ma, rtol=0, atol=1e-9)

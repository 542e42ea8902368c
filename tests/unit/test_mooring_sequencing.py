"""Mesh sequencing of the mooring statics (seacable.mooring.sequencing): a finely meshed lazy-wave cable, which the
pseudo-transient Newton cannot bring from its catenary start, converges from its coarse mesh's equilibrium; the
coarse network is the same lines meshed more coarsely."""

from __future__ import annotations

import numpy as np
import pytest

from seacable.case import Case
from seacable.errors import ConvergenceError
from seacable.mooring import solver
from seacable.mooring.run import case_model
from seacable.mooring.sequencing import coarsen, spline_start
from seacable.mooring.solver import static_equilibrium


def lazy_wave(per_metre: float, ei: float = 2.0e4) -> Case:
    """A 500 m lazy-wave cable in 200 m of water: 200 m on and off the seabed, 90 m of smeared buoyancy (net 60 kg/m
    up), 210 m up to a hang-off 300 m out and 10 m down; 70 kg/m cable of 0.2 m (net 37.8 kg/m), EI ``ei``."""
    cable = {"diameter": 0.2, "mass_per_length": 70.0, "axial_stiffness": 7e8, "bending_stiffness": ei}
    buoyant = {"diameter": 0.473, "mass_per_length": 120.0, "axial_stiffness": 7e8, "bending_stiffness": ei}
    lengths = (200.0, 90.0, 210.0)
    return Case.model_validate({
        "name": "lazy_wave",
        "line_types": {"cable": cable, "buoyant": buoyant},
        "line": {"segments": [{"line_type": t, "length": L, "n_elements": round(L * per_metre)}
                              for t, L in zip(("cable", "buoyant", "cable"), lengths)]},
        "environment": {"water_density": 1025.0, "gravity": 9.81, "depth": 200.0},
        "analysis": {"type": "mooring_static", "fairlead": [300.0, -10.0]}})


def peak_curvature(X, lo: int, hi: int) -> float:
    """The largest discrete curvature 4 sin(theta / 2) / (l1 + l2) [1/m] at the inner nodes lo..hi - 1."""
    d = np.diff(X, axis=0)
    length = np.linalg.norm(d, axis=1)
    t = d / length[:, None]
    theta = np.arccos(np.clip(np.sum(t[:-1] * t[1:], axis=1), -1.0, 1.0))
    kappa = 4.0 * np.sin(theta / 2.0) / (length[:-1] + length[1:])
    return float(np.max(kappa[lo - 1:hi - 1]))


def test_coarse_network_is_the_same_lines_meshed_coarsely():
    """Every kept element merges a run of identical elements: total unstretched length, weight and mass of each
    segment kept, the segment boundaries kept as nodes, about COARSE_ELEMENTS elements."""
    net = case_model(lazy_wave(2.0)).network
    coarse = coarsen(net, 60)
    assert 60 <= len(coarse.elements) <= 70
    assert np.sum(coarse.length) == pytest.approx(np.sum(net.length), rel=1e-12)
    for field in ("weight_per_length", "mass_per_length"):  # per length: the sum over elements weighs the lengths
        assert np.sum(getattr(coarse, field) * coarse.length) == pytest.approx(
            np.sum(getattr(net, field) * net.length), rel=1e-12)
    assert {200.0, 290.0} <= set(np.round(coarse.arc_length, 9))  # the buoyant section's ends stay nodes
    assert coarse.kind[0] == net.kind[0] and coarse.kind[-1] == net.kind[-1]
    assert coarsen(coarse, 60) is None  # not finer than asked: nothing to coarsen


def test_spline_start_puts_the_fine_nodes_on_the_coarse_shape():
    """The fine nodes of a coarse circle's arc lie on it to the spline's O(h^4) error (h the coarse step)."""
    net = case_model(lazy_wave(1.0)).network
    coarse = coarsen(net, 60)
    s_c, s_f = coarse.arc_length, net.arc_length
    radius = 200.0
    circle = lambda s: np.stack([radius * np.sin(s / radius), 0.0 * s, radius * (1.0 - np.cos(s / radius))], 1)
    X = spline_start(net, coarse, circle(s_c))
    h = float(np.max(np.diff(s_c)))
    assert np.max(np.abs(X - circle(s_f))) < (h / radius) ** 4 * radius  # about 1.6e-3 m at h 9 m


def test_fine_lazy_wave_converges_by_sequencing_and_its_curvature_converges():
    """At 2 and 4 elements a metre (the direct solve from the catenary: no convergence in 1500 iterations at any
    step limit), both converge; the hang-off tension is the same to 1e-5 (the mesh's effect on a tension of 58 kN
    is below 1 N), and the sag bend's peak curvature converges at the discrete rod's second order: the errors
    against 8 elements a metre fall by 3.6-5.2 per halving of the elements (measured 0.28 %, 0.055 %, 0.012 % at 1,
    2, 4 a metre), so an error ratio of 3 or more is asserted (first order would give 2)."""
    peaks, tops = [], []
    for per_metre in (1.0, 2.0, 4.0, 8.0):
        model = case_model(lazy_wave(per_metre))
        state = static_equilibrium(model, tol=1e-8)
        s = model.network.arc_length
        sag = (s > 100.0) & (s < 200.0)
        idx = np.flatnonzero(sag)
        peaks.append(peak_curvature(state.position, idx[0], idx[-1] + 1))
        tops.append(float(np.linalg.norm(state.support[-1])))  # the hang-off's force
    assert np.ptp(tops) < 1e-5 * tops[-1]
    errors = np.abs(np.array(peaks[:3]) - peaks[3])
    assert errors[0] / errors[1] > 3.0 and errors[1] / errors[2] > 3.0
    assert errors[0] < 0.005 * peaks[3]  # 1 element a metre: within 0.5 % of the converged peak (0.28 %)


def test_sequencing_finds_the_direct_solves_equilibrium(monkeypatch):
    """Where the direct solve converges (the same line without EI at 1 element a metre, in 475 iterations), the
    sequenced one (the direct attempt cut short) finds the same equilibrium: nodes within 1 mm."""
    model = case_model(lazy_wave(1.0, ei=0.0))
    direct = static_equilibrium(model, tol=1e-8, max_iter=1000)
    monkeypatch.setattr(solver, "FINE_DIRECT_ITERATIONS", 5)
    sequenced = static_equilibrium(model, tol=1e-8)
    assert np.max(np.abs(sequenced.position - direct.position)) < 1e-3


def test_failure_says_sequencing_was_tried(monkeypatch):
    """A fine line that converges neither way says so (here: 3 iterations allowed)."""
    model = case_model(lazy_wave(1.0))
    with pytest.raises(ConvergenceError, match="from a coarser mesh's equilibrium"):
        static_equilibrium(model, tol=1e-8, max_iter=3)

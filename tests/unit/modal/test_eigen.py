"""Unit tests of seacable.modal.eigen: API, labels, shapes, solver paths and error paths."""

import dataclasses

import numpy as np
import pytest
import scipy.sparse.linalg

from seacable.errors import ConvergenceError, InputError
from seacable.modal import eigen
from seacable.modal.eigen import CableModes, MassMatrix, Plane, cable_modes

G = 9.80665


def string(n=10, length=10.0):
    x = np.linspace(0.0, length, n + 1)
    return np.c_[x, np.zeros_like(x)]


def sagged(n=40, span=100.0, a=60.0, mass=1.0):
    """Discrete catenary equilibrium (lumped weights, constant H = m g a), as (n+1, 2) nodes."""
    horizontal = mass * G * a
    l0 = 2 * a * np.sinh(span / (2 * a))
    h = l0 / n
    v = mass * G * h * ((n - 1) / 2 - np.arange(n))
    t = np.hypot(horizontal, v)
    steps = np.c_[h * horizontal / t, -h * v / t]
    return np.vstack([[0.0, 0.0], np.cumsum(steps, axis=0)]), h, t


# --- results ------------------------------------------------------------------------------------

def test_result_fields_consistent_sorted_and_frozen():
    modes = cable_modes(string(), 1.0, 1000.0, 2.0, 1e6, n_modes=7)
    assert isinstance(modes, CableModes) and len(modes) == 7
    assert np.all(np.diff(modes.frequency) >= 0)
    np.testing.assert_allclose(modes.angular_frequency, 2 * np.pi * modes.frequency, rtol=1e-15)
    np.testing.assert_allclose(modes.period, 1 / modes.frequency, rtol=1e-15)
    assert set(modes.plane) <= {"in", "out"}
    assert modes.shape.shape == (7, 11, 3)
    with pytest.raises(dataclasses.FrozenInstanceError):
        modes.frequency = None


def test_shapes_normalised_signed_and_zero_at_fixed_nodes():
    nodes, h, t = sagged()
    modes = cable_modes(nodes, h, t, 1.0, 1e8, n_modes=6, fixed=(0, 5, -1))
    amp = np.linalg.norm(modes.shape, axis=2)
    np.testing.assert_allclose(amp.max(axis=1), 1.0, rtol=1e-12)
    assert np.all(modes.shape[:, [0, 5, -1], :] == 0.0)
    flat = modes.shape.reshape(len(modes), -1)
    first = np.argmax(np.abs(flat) >= (1 - 1e-6) * np.abs(flat).max(axis=1, keepdims=True), axis=1)
    assert np.all(flat[np.arange(len(modes)), first] > 0)
    # labels: out-of-plane shapes move along y only, in-plane ones in x-z only
    out, inp = modes.select("out"), modes.select(Plane.IN)
    assert len(out) and len(inp) and len(out) + len(inp) == len(modes)
    assert np.all(out.shape[:, :, [0, 2]] == 0.0) and np.all(inp.shape[:, :, 1] == 0.0)


def test_planes_option_and_n_modes_limit():
    only_out = cable_modes(string(4), 2.5, 100.0, 1.0, 1e5, planes="out", n_modes=50)
    assert set(only_out.plane) == {"out"}
    assert len(only_out) == 3  # 3 free nodes x 1 DOF: fewer modes than asked
    both = cable_modes(string(4), 2.5, 100.0, 1.0, 1e5, n_modes=50)
    assert len(both) == 9


def test_per_element_arrays_equal_broadcast_scalars():
    n = 10
    a = cable_modes(string(n), 1.0, 500.0, 2.0, 1e6, added_mass_per_length=0.5)
    b = cable_modes(string(n), np.ones(n), np.full(n, 500.0), np.full(n, 2.0), np.full(n, 1e6),
                    added_mass_per_length=np.full(n, 0.5), point_masses=np.zeros(n + 1))
    np.testing.assert_array_equal(a.frequency, b.frequency)


def test_mass_matrix_accepts_enum_and_string():
    a = cable_modes(string(), 1.0, 500.0, 2.0, 1e6, mass_matrix=MassMatrix.CONSISTENT)
    b = cable_modes(string(), 1.0, 500.0, 2.0, 1e6, mass_matrix="consistent")
    np.testing.assert_array_equal(a.frequency, b.frequency)


# --- geometry: 2-D vs 3-D, rotations, non-planar ----------------------------------------------------

def test_three_d_input_in_rotated_vertical_plane_gives_same_modes():
    nodes, h, t = sagged()
    ref = cable_modes(nodes, h, t, 1.0, 1e8, n_modes=8)
    ang = 0.7
    rotated = np.c_[nodes[:, 0] * np.cos(ang), nodes[:, 0] * np.sin(ang), nodes[:, 1]]
    modes = cable_modes(rotated, h, t, 1.0, 1e8, n_modes=8)
    # round-off: eps x condition number (omega_max/omega_min)^2 ~ (EA/T)(n/pi)^2 ~ 3e7: 1e-8
    np.testing.assert_allclose(modes.frequency, ref.frequency, rtol=1e-8)
    np.testing.assert_array_equal(modes.plane, ref.plane)
    out = modes.select("out").shape  # out-of-plane motion along (-sin, cos, 0)
    np.testing.assert_allclose(out[:, :, 0], -np.sin(ang) * out[:, :, 1] / np.cos(ang),
                               atol=1e-12)
    # and the shape rotates with the cable: ref's y-motion maps onto the normal direction
    np.testing.assert_allclose(np.abs(out[0, :, 1]), np.abs(ref.select("out").shape[0, :, 1])
                               * np.cos(ang), atol=1e-9)


def test_vertical_cable_is_planar_with_x_z_plane():
    z = np.linspace(0.0, 30.0, 31)
    modes = cable_modes(np.c_[0 * z, 0 * z, z], 1.0, 1000.0, 1.0, 1e7, fixed=(-1,), n_modes=6)
    # transverse modes come in degenerate in/out pairs (x and y)
    np.testing.assert_allclose(modes.frequency[0::2], modes.frequency[1::2], rtol=1e-10)
    assert sorted(modes.plane[:2]) == ["in", "out"]


def test_non_planar_equilibrium_solved_in_3d_equals_union_of_planes():
    """Tilting the plane of a sagged cable about x makes it non-vertical: the 3-D solve
    must give the same spectrum (a rigid rotation does not change K and M's eigenvalues)."""
    nodes, h, t = sagged()
    planar = cable_modes(nodes, h, t, 1.0, 1e8, n_modes=10)
    tilt = 0.4
    tilted = np.c_[nodes[:, 0], -nodes[:, 1] * np.sin(tilt), nodes[:, 1] * np.cos(tilt)]
    modes = cable_modes(tilted, h, t, 1.0, 1e8, n_modes=10)
    assert set(modes.plane) == {"3d"}
    np.testing.assert_allclose(modes.frequency, planar.frequency, rtol=1e-8)  # as above
    assert len(modes.select("3d")) == 10
    with pytest.raises(InputError, match="non-planar"):
        cable_modes(tilted, h, t, 1.0, 1e8, planes=("out",))


# --- solver paths ---------------------------------------------------------------------------------

def test_sparse_shift_invert_agrees_with_dense(monkeypatch):
    nodes, h, t = sagged(n=60)
    monkeypatch.setattr(eigen, "DENSE_LIMIT", 10**6)
    dense = cable_modes(nodes, h, t, 1.0, 1e8, added_mass_per_length=0.3, n_modes=8)
    monkeypatch.setattr(eigen, "DENSE_LIMIT", 0)
    sparse = cable_modes(nodes, h, t, 1.0, 1e8, added_mass_per_length=0.3, n_modes=8)
    np.testing.assert_allclose(sparse.frequency, dense.frequency, rtol=1e-9)  # ARPACK tol=eps
    np.testing.assert_array_equal(sparse.plane, dense.plane)
    # shapes agree up to the sign convention, which is applied identically
    np.testing.assert_allclose(sparse.shape, dense.shape, atol=1e-6)


@pytest.mark.parametrize("dense_limit", [10**6, 0])
def test_low_frequencies_keep_precision_when_ea_dwarfs_tension(monkeypatch, dense_limit):
    """Both paths solve about omega = 0, so EA/T up to 1e12 must not spoil the low modes.

    Hanging chain: its in-plane transverse (x) modes equal its out-of-plane (y) modes
    exactly, but the in-plane problem also holds axial modes 1e6 times higher in frequency.
    (scipy.linalg.eigh(K, M) solved directly is off by 6e-5 here; we require 1e-10.)
    """
    monkeypatch.setattr(eigen, "DENSE_LIMIT", dense_limit)
    n, length, mass = 100, 100.0, 2.0
    h = length / n
    z = np.linspace(0.0, length, n + 1)
    tension = mass * G * (np.arange(n) + 0.5) * h
    args = (np.c_[0 * z, z], h, tension, mass, 1e12)
    inplane = cable_modes(*args, fixed=(-1,), planes="in", n_modes=3)
    out = cable_modes(*args, fixed=(-1,), planes="out", n_modes=3)
    np.testing.assert_allclose(inplane.angular_frequency, out.angular_frequency, rtol=1e-10)


def test_arpack_failure_raises_convergence_error(monkeypatch):
    def fail(*args, **kwargs):
        raise scipy.sparse.linalg.ArpackNoConvergence("no convergence", np.array([]),
                                                      np.zeros((0, 0)))

    monkeypatch.setattr(eigen, "DENSE_LIMIT", 0)
    monkeypatch.setattr(eigen.scipy.sparse.linalg, "eigsh", fail)
    with pytest.raises(ConvergenceError, match="did not converge") as info:
        cable_modes(string(), 1.0, 100.0, 1.0, 1e6)
    assert info.value.iterations is not None


def test_singular_factor_raises_input_error(monkeypatch):
    def singular(*args, **kwargs):
        raise RuntimeError("Factor is exactly singular")

    monkeypatch.setattr(eigen, "DENSE_LIMIT", 0)
    monkeypatch.setattr(eigen.scipy.sparse.linalg, "eigsh", singular)
    with pytest.raises(InputError, match="positive definite"):
        cable_modes(string(), 1.0, 100.0, 1.0, 1e6)


def test_failed_cholesky_raises_input_error(monkeypatch):
    def not_pd(*args, **kwargs):
        raise np.linalg.LinAlgError("not positive definite")

    monkeypatch.setattr(eigen.scipy.linalg, "eigh", not_pd)
    with pytest.raises(InputError, match="positive definite"):
        cable_modes(string(), 1.0, 100.0, 1.0, 1e6)


def test_non_positive_eigenvalue_raises_input_error(monkeypatch):
    monkeypatch.setattr(eigen.scipy.linalg, "eigh",
                        lambda a, b, subset_by_index: (np.array([-1.0]), np.ones((a.shape[0], 1))))
    with pytest.raises(InputError, match="omega\\^2"):
        cable_modes(string(), 1.0, 100.0, 1.0, 1e6, n_modes=1, planes="out")


# --- input errors ---------------------------------------------------------------------------------

GOOD = dict(nodes=string(), unstretched_lengths=1.0, tensions=100.0, mass_per_length=1.0,
            axial_stiffness=1e6)


def call(**changes):
    kw = {**GOOD, **changes}
    return cable_modes(kw.pop("nodes"), kw.pop("unstretched_lengths"), kw.pop("tensions"),
                       kw.pop("mass_per_length"), kw.pop("axial_stiffness"), **kw)


@pytest.mark.parametrize("changes, match", [
    (dict(tensions=np.full(9, 100.0)), r"tensions must be a scalar or have one value per element \(10,\)"),
    (dict(unstretched_lengths=np.ones(11)), "unstretched_lengths must be a scalar"),
    (dict(mass_per_length=np.ones((10, 2))), "mass_per_length must be a scalar"),
    (dict(point_masses=np.zeros(10)), r"point_masses must have one value per node \(11,\)"),
    (dict(nodes=np.zeros((5, 4))), "nodes must have shape"),
    (dict(nodes=np.zeros(5)), "nodes must have shape"),
    (dict(nodes=np.vstack([string()[:-1], [[np.nan, 0.0]]])), r"nodes\[\(10, 0\)\] must be a finite"),
    (dict(tensions=np.r_[np.full(9, 100.0), np.nan]), r"tensions\[9\] must be a finite number"),
    (dict(tensions=np.r_[np.full(9, 100.0), 0.0]), r"tensions\[9\] must be > 0 N, got 0 N.*slack"),
    (dict(tensions=-5.0), r"tensions must be > 0 N, got -5 N"),
    (dict(unstretched_lengths=-3.0), r"unstretched_lengths must be > 0 m, got -3 m"),
    (dict(mass_per_length=0.0), r"mass_per_length must be > 0 kg/m"),
    (dict(axial_stiffness=-1.0), r"axial_stiffness must be > 0 N"),
    (dict(added_mass_per_length=-0.1), r"added_mass_per_length must be >= 0 kg/m"),
    (dict(point_masses=-np.ones(11)), r"point_masses\[0\] must be >= 0 kg"),
    (dict(nodes=np.r_[[[0.0, 0.0]], string()[:-1]]), "element 0 must have a stretched length > 0 m"),
    (dict(fixed=(0, 11)), r"fixed node index must be in \[-11, 10\], got 11"),
    (dict(fixed=()), "fixed must be a non-empty sequence"),
    (dict(fixed=(0.5,)), "fixed must be a non-empty sequence"),
    (dict(fixed=tuple(range(11))), "at least one node must be free"),
    (dict(n_modes=0), "n_modes must be an integer >= 1"),
    (dict(n_modes=2.5), "n_modes must be an integer >= 1"),
    (dict(mass_matrix="diagonal"), r"mass_matrix must be one of 'lumped', 'consistent'"),
    (dict(planes=("in", "sideways")), "planes must be one of"),
    (dict(planes=()), "planes must be a non-empty subset"),
    (dict(planes=("3d",)), "planes must be a non-empty subset"),
])
def test_input_errors(changes, match):
    with pytest.raises(InputError, match=match) as info:
        call(**changes)
    assert "Suggested fix" in str(info.value)


def test_select_rejects_unknown_plane():
    modes = call()
    with pytest.raises(InputError, match="plane must be one of"):
        modes.select("up")

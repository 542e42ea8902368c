"""The coupling interface's contract (:mod:`seacable.coupling`): its stiffness is the derivative of its static
forces, the dataset at close is system_dynamic's, bodies of kind 'coupled' are coupled, and bad inputs get one
clear error each."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from seacable.coupling import Coupling
from seacable.errors import InputError
from seacable.results import joined

BODY_DECK = Path(__file__).parents[1] / "validation" / "data" / "moordyn_decks" / "MoorDyn" / "example" / "body.txt"


def _case(kind="coupled", **analysis):
    from seacable.system.case import SystemCase

    return SystemCase.parse({
        "line_types": {"chain": {"diameter": 0.09, "mass_per_length": 77.7, "axial_stiffness": 3.84e8}},
        "environment": {"depth": 300.0},
        "points": {"a1": {"kind": "fixed", "position": [400.0, 0.0, -300.0]},
                   "a2": {"kind": "fixed", "position": [-200.0, 346.4, -300.0]},
                   "f1": {"kind": "body", "body": "hull", "position": [5.0, 0.0, -20.0]},
                   "f2": {"kind": "body", "body": "hull", "position": [-2.5, 4.33, -20.0]}},
        "bodies": {"hull": {"kind": kind, "position": [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]}},
        "lines": {"l1": {"line_type": "chain", "length": 480.0, "end_a": "a1", "end_b": "f1", "n_elements": 12},
                  "l2": {"line_type": "chain", "length": 480.0, "end_a": "a2", "end_b": "f2", "n_elements": 12}},
        "analysis": {"type": "system_dynamic", "duration": 1.0, **analysis}})


@pytest.fixture(scope="module")
def hull():
    return Coupling(_case(), time_step=0.1)


def test_a_body_of_kind_coupled_is_a_prescribed_body_and_its_six_dofs_are_coupled(hull):
    assert hull.system.bodies["hull"].kind == "prescribed"
    assert hull.dof_names == tuple(f"body hull {d}" for d in ("x", "y", "z", "roll", "pitch", "yaw"))
    assert hull.n_dof == 6


@pytest.mark.parametrize("offset", [np.zeros(6), np.array([8.0, -3.0, 1.0, 0.0, 0.0, 0.0])], ids=["rest", "offset"])
def test_the_stiffness_is_minus_the_derivative_of_the_static_forces(hull, offset):
    """K = -dF/dx by central differences of the static forces (1 cm, 1e-4 rad: their truncation error, O(h^2), is
    ~1e-6 of the entries; 1e-4 of the largest entry of each column is left for the statics' 1e-10 residual divided
    by h). The rotations at zero angles: the Euler increments are the small rotations of the stiffness."""
    x = offset.copy()
    K = hull.stiffness(x)
    steps = np.array([0.01, 0.01, 0.01, 1e-4, 1e-4, 1e-4])
    fd = np.zeros((6, 6))
    for j in range(6):
        e = np.zeros(6)
        e[j] = steps[j]
        fd[:, j] = -(hull.static_forces(x + e) - hull.static_forces(x - e)) / (2 * steps[j])
    for j in range(6):
        assert K[:, j] == pytest.approx(fd[:, j], abs=1e-4 * np.abs(fd).max()), j
    assert K[0, 0] > 0 and K[2, 2] > 0  # restoring in surge and heave


def test_init_step_and_close_give_system_dynamics_dataset(hull):
    """A short surge: the Dataset at close has system_dynamic's variables, the coupled DOFs and forces at every kept
    time, and the forces at close are those step returned."""
    f0 = hull.init(np.zeros(6))
    assert f0 == pytest.approx(hull.static_forces(np.zeros(6)), rel=2e-2, abs=1e-2 * np.abs(f0).max())
    forces = [f0]
    for k in range(4):
        x = np.zeros(6)
        x[0] = 0.5 * (k + 1)
        forces.append(hull.step(x, np.r_[2.5, np.zeros(5)], 0.2 * k, 0.2))
    assert forces[-1][0] < forces[0][0]  # pulled back as it surges
    assert set(hull.tensions()) == {"l1", "l2"} and hull.fast_tensions().shape == (2, 4)
    assert hull.node_positions("l1").shape == (13, 3)
    ds = hull.close()
    for name in ("x", "y", "z", "segment_tension", "fairlead_tension", "anchor_tension", "body_position",
                 "coupled_position", "coupled_force"):
        assert name in ds
    assert ds.time.values == pytest.approx([0.0, 0.2, 0.4, 0.6, 0.8])
    # the forces [N] and moments [N m] of the coupled DOFs, one variable per unit (NaN at the other kind's DOFs)
    assert joined([ds.coupled_force, ds.coupled_moment]) == pytest.approx(np.array(forces))
    assert ds.body_position.sel(body="hull", axis="x").values == pytest.approx([0.0, 0.5, 1.0, 1.5, 2.0])


def test_bad_inputs_get_one_clear_error_each():
    c = Coupling(_case(), time_step=0.1)
    with pytest.raises(InputError, match="step before init"):
        c.step(np.zeros(6), np.zeros(6), 0.0, 0.1)
    with pytest.raises(InputError, match="x must have 6 values .* got 3"):
        c.init(np.zeros(3))
    bad = np.zeros(6)
    bad[4] = math.nan
    with pytest.raises(InputError, match=r"x\[4\] \(body hull pitch\) must be a finite number"):
        c.init(bad)
    c.init(np.zeros(6))
    c.step(np.zeros(6), np.zeros(6), 0.0, 0.1)
    with pytest.raises(InputError, match="t = 0 s goes back: the coupling is at t = 0.1 s"):
        c.step(np.zeros(6), np.zeros(6), 0.0, 0.1)
    with pytest.raises(InputError, match="skips ahead"):
        c.step(np.zeros(6), np.zeros(6), 0.5, 0.1)
    with pytest.raises(InputError, match="dt must be a finite time step > 0 s"):
        c.step(np.zeros(6), np.zeros(6), 0.1, -0.1)
    with pytest.raises(InputError, match=r"xd\[0\] .* must be a finite number"):
        c.step(np.zeros(6), np.r_[math.inf, np.zeros(5)], 0.1, 0.1)
    with pytest.raises(InputError, match="no coupled object"):
        Coupling(_case(kind="fixed"))
    with pytest.raises(InputError, match="line 'l3' is not in the system"):
        c.node_positions("l3")
    with pytest.raises(InputError, match="angles must be 'seacable'"):
        Coupling(_case(), angles="degrees")
    c.close()
    with pytest.raises(InputError, match="step after close"):
        c.step(np.zeros(6), np.zeros(6), 0.1, 0.1)


def test_output_interval_keeps_the_states_at_its_multiples():
    c = Coupling(_case(), time_step=0.1, output_interval=0.3)
    c.init(np.zeros(6))
    for k in range(7):
        c.step(np.zeros(6), np.zeros(6), 0.1 * k, 0.1)
    assert c.close().time.values == pytest.approx([0.0, 0.3, 0.6])


def test_a_moordyn_deck_with_a_coupled_body_reads_as_a_coupling():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        c = Coupling(BODY_DECK)
    assert c.dof_names[0] == "body body1 x" and c.n_dof == 6


def _clump_case(fairlead_mass=0.0):
    from seacable.system.case import SystemCase

    return SystemCase.parse({
        "line_types": {"chain": {"diameter": 0.09, "mass_per_length": 77.7, "axial_stiffness": 3.84e8}},
        "environment": {"depth": 200.0},
        "points": {"anchor": {"kind": "fixed", "position": [-400.0, 0.0, -200.0]},
                   "clump": {"kind": "free", "position": [-150.0, 0.0, -150.0], "mass": 2.0e4, "volume": 1.0},
                   "fair": {"kind": "coupled", "position": [0.0, 0.0, -10.0], "mass": fairlead_mass}},
        "lines": {"lower": {"line_type": "chain", "length": 300.0, "end_a": "anchor", "end_b": "clump",
                            "n_elements": 10},
                  "upper": {"line_type": "chain", "length": 200.0, "end_a": "clump", "end_b": "fair",
                            "n_elements": 10}},
        "analysis": {"type": "system_dynamic", "duration": 1.0}})


def test_a_free_clumps_equilibrium_is_condensed_out_of_the_fairlead_stiffness():
    """A clump weight (a free point) between two chains: the fairlead stiffness is the derivative of the static
    force with the clump re-found at each offset (the condensed stiffness, MoorPy's coupled stiffness); the clump
    held would give a stiffer fairlead. Central differences of 1 cm: 1e-4 of the largest entry (see above)."""
    c = Coupling(_clump_case())
    x = np.array([0.0, 0.0, -10.0])
    K = c.stiffness(x)
    fd = np.column_stack([-(c.static_forces(x + e) - c.static_forces(x - e)) / 0.02 for e in 0.01 * np.eye(3)])
    assert K == pytest.approx(fd, abs=1e-4 * np.abs(fd).max())
    assert K[0, 0] > 0 and K[2, 2] > 0


def test_the_fairleads_own_mass_is_accelerated_by_the_coupled_object():
    """A coupled point carrying a 5 t mass (no volume, no drag) moved harmonically: the force on it is the same
    line's force less ``m a`` and its weight ``m g``, ``a`` the motion's acceleration at the step's end (the cubic's
    through both ends: ``(6 x0 + 2 dt v0 - 6 x1 + 4 dt v1) / dt^2``). The lines do not see the mass (the node is
    prescribed), so the difference of the two runs is exactly that: 1e-6 of ``m a`` (the Newton tolerance)."""
    mass, dt, w, amp = 5.0e3, 0.1, 2 * math.pi / 8.0, 2.0
    runs = []
    for m_p in (0.0, mass):
        c = Coupling(_clump_case(m_p), time_step=dt, tolerance=1e-10)
        x0 = np.array([0.0, 0.0, -10.0])
        c.init(x0)
        f, acc = [], []
        prev = (x0.copy(), np.zeros(3))
        for k in range(10):
            t = (k + 1) * dt
            x = x0 + [amp * math.sin(w * t) ** 2, 0.0, 0.0]
            xd = np.array([amp * w * math.sin(2 * w * t), 0.0, 0.0])
            f.append(c.step(x, xd, k * dt, dt))
            acc.append((6 * prev[0] + 2 * dt * prev[1] - 6 * x + 4 * dt * xd) / dt ** 2)
            prev = (x, xd)
        runs.append((np.array(f), np.array(acc)))
    (f0, acc), (f1, _) = runs
    expect = -mass * acc - [0.0, 0.0, mass * c.case.environment.gravity]
    assert f1 - f0 == pytest.approx(expect, rel=1e-6, abs=1e-6 * mass * np.abs(acc).max())


def test_init_without_settling_starts_from_the_catenary_shapes():
    """MoorDyn's Init_NoIC: the lines start on their catenary shapes between their ends (the statics not solved),
    near the settled start (their ends' forces within 1e-4 of the largest: the elastic catenary is the continuous
    line's equilibrium, the 12 elements' differs by their discretisation, measured 1e-5), and step from there."""
    c = Coupling(_case(), time_step=0.1)
    settled = c.init(np.zeros(6))
    shape = c.init(np.zeros(6), settle=False)
    assert np.isfinite(shape).all()
    assert shape[:3] == pytest.approx(settled[:3], abs=1e-4 * np.abs(settled[:3]).max())
    assert np.isfinite(c.step(np.zeros(6), np.zeros(6), 0.0, 0.1)).all()


def test_a_free_bodys_equilibrium_is_condensed_out_of_the_fairlead_stiffness():
    """A free subsurface buoy (a body, its lines at its ends) between the anchor's chain and the fairlead's: the
    fairlead stiffness with the buoy re-found at each offset (its six DOFs condensed out) is the central difference
    of the static force (1e-4 of the largest entry, as above; measured 2e-8), and the lines step with the free buoy."""
    from seacable.system.case import SystemCase

    case = SystemCase.parse({
        "line_types": {"chain": {"diameter": 0.09, "mass_per_length": 77.7, "axial_stiffness": 3.84e8}},
        "environment": {"depth": 200.0},
        "points": {"anchor": {"kind": "fixed", "position": [-300.0, 0.0, -200.0]},
                   "low": {"kind": "body", "body": "buoy", "position": [0.0, 0.0, -1.0]},
                   "high": {"kind": "body", "body": "buoy", "position": [0.0, 0.0, 1.0]},
                   "fair": {"kind": "coupled", "position": [100.0, 0.0, -10.0]}},
        "bodies": {"buoy": {"kind": "free", "position": [-100.0, 0.0, -100.0, 0.0, 0.0, 0.0], "mass": 5.0e3,
                            "volume": 30.0, "inertia": [1e4, 1e4, 1e4]}},
        "lines": {"lower": {"line_type": "chain", "length": 260.0, "end_a": "anchor", "end_b": "low", "n_elements": 10},
                  "upper": {"line_type": "chain", "length": 230.0, "end_a": "high", "end_b": "fair", "n_elements": 10}},
        "analysis": {"type": "system_dynamic", "duration": 1.0}})
    c = Coupling(case)
    x = np.array([100.0, 0.0, -10.0])
    K = c.stiffness(x)
    fd = np.column_stack([-(c.static_forces(x + e) - c.static_forces(x - e)) / 0.02 for e in 0.01 * np.eye(3)])
    assert K == pytest.approx(fd, abs=1e-4 * np.abs(fd).max())
    c.init(x)
    assert np.isfinite(c.step(x + [0.5, 0.0, 0.0], [1.0, 0.0, 0.0], 0.0, 0.5)).all()

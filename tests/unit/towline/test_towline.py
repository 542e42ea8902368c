"""Unit tests of the towline model: input errors, kinematics of release, interruption, CLI."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.cli import main
from seacable.towline import TowlineModel, initial_state, simulate
from seacable.towline.solver import joint_positions

EXAMPLES = Path(__file__).parents[3] / "examples"


def _data():
    return yaml.safe_load((EXAMPLES / "paper003_steady_tow.yaml").read_text())


@pytest.mark.parametrize("change, message", [
    ({"start": "dropped"}, "needs drop_height"),
    ({"elongation_at_break": None}, "needs the line's stiffness"),
    ({"output_interval": 1000.0}, "must not exceed duration"),
    ({"n_elements": 0}, "n_elements"),
])
def test_bad_towline_analyses_are_refused(change, message):
    data = _data()
    data["analysis"].update(change)
    with pytest.raises(sc.InputError, match=message):
        sc.parse_case(data)


def test_initial_lines_have_closed_joints_and_the_right_length():
    model = TowlineModel(n_elements=11, length=100.0, diameter=0.05, mass_per_length=1.725, axial_stiffness=1e6)
    tug = np.array([0.0, 0.0, 2.0])
    for start in ("straight", "dropped"):
        st = initial_state(model, tug, start=start, drop_height=1.0)
        nodes = joint_positions(model, st, tug)
        # consecutive joints one element length apart (rigid elements, closed joints): the line is 100 m
        assert np.linalg.norm(np.diff(nodes, axis=0), axis=1) == pytest.approx(np.full(11, 100.0 / 11), rel=1e-12)
        assert nodes[-1, 2] == pytest.approx(model.barge_tow_point[1])
    coiled = initial_state(model, tug, start="coiled")
    assert coiled.first == 11 and np.all(np.isnan(joint_positions(model, coiled, tug)[1:-1]))


def _held_line():
    """A 50 m line of 5 elements dropped 1 m below a tug that stays put: the model, the tug point, its motion."""
    model = TowlineModel(n_elements=5, length=50.0, diameter=0.05, mass_per_length=1.725, axial_stiffness=1e6,
                         held_tow_point_height=2.0)
    tug = np.array([0.0, 0.0, 2.0])

    def still(t):
        t = np.atleast_1d(t)
        return np.broadcast_to(tug, (t.size, 3)).copy(), np.zeros((t.size, 3))

    return model, tug, still


def test_interrupted_towline_run_keeps_what_it_computed():
    model, tug, still = _held_line()

    def progress(t, duration):
        if t >= 2.0:
            raise KeyboardInterrupt

    run = simulate(model, still, 10.0, 1.0, initial_state(model, tug, start="dropped", drop_height=1.0),
                   progress=progress)
    assert run.interrupted and run.time[-1] == pytest.approx(2.0) and run.nodes.shape[0] == 3


def test_an_interrupt_between_an_outputs_appends_keeps_the_whole_outputs(monkeypatch):
    """SIGTERM landing while an output is recorded (its time kept, its snapshot not): the run keeps the
    outputs every list holds, instead of arrays of different lengths."""
    from seacable.towline import solver

    model, tug, still = _held_line()

    calls, original = [], solver.joint_positions

    def interrupted(*args):
        calls.append(1)
        if len(calls) == 4:   # the snapshot of the third output
            raise KeyboardInterrupt
        return original(*args)

    monkeypatch.setattr(solver, "joint_positions", interrupted)
    run = solver.simulate(model, still, 10.0, 1.0, initial_state(model, tug, start="dropped", drop_height=1.0))
    assert run.interrupted and run.time[-1] == pytest.approx(2.0)
    assert run.time.size == run.nodes.shape[0] == run.tug.shape[0] == 3


def test_cli_runs_a_towline_case(tmp_path):
    data = _data()
    data["analysis"].update(duration=20.0)
    f = tmp_path / "tow.yaml"
    f.write_text(yaml.safe_dump(data))
    out = tmp_path / "tow.nc"
    # the result and the animation; the figures of 'run' are those of plot_result, tested in test_plot_towline
    assert main(["run", str(f), "-o", str(out), "--no-plots"]) == 0
    ds = sc.read_netcdf(out)
    assert ds.attrs["analysis"] == "towline_dynamic" and ds.sizes["node"] == 12
    assert main(["animate", str(out), "--max-frames", "3"]) == 0
    assert (tmp_path / "tow_tow.gif").stat().st_size > 0


def _taut_line(n, stretch):
    """An undamped line of n elements in air between two fixed points, stretched by ``stretch`` [m]."""
    model = TowlineModel(n_elements=n, length=100.0, diameter=0.05, mass_per_length=1.725, axial_stiffness=1e6,
                         damping_ratio=0.0, bending_damping_ratio=0.0, drag=False, impact=False, gravity=0.0,
                         held_tow_point_height=10.0)
    tug = np.array([0.0, 0.0, 10.0])
    state = initial_state(model, tug, start="straight")  # astern of the tug, along -x
    # every joint open by stretch / (n + 1): the line in equilibrium at the tension EA stretch / L
    state.R[:, 0] -= (np.arange(n) + 1) * stretch / (n + 1)
    state.barge[0] -= stretch
    state.R[:, 1] += 1e-6 * np.sin(np.arange(n))  # a ripple across the line, to excite every mode

    def still(t):
        t = np.atleast_1d(t)
        return np.broadcast_to(tug, (t.size, 3)).copy(), np.zeros((t.size, 3))

    return model, state, still


def test_stable_step_is_the_axial_chain_bound():
    """The step bound is sqrt(m / k): symplectic Euler is stable for omega dt < 2 and the chain's stiffest
    modes, neighbours beating against each other along the line (omega^2 -> 4 k / m) and every element
    turning the same way against the pins (12 k_t / m with k_t = k / 3), share omega = 2 sqrt(k / m)."""
    from seacable.towline import kernel as K
    from seacable.towline.solver import stable_time_step

    n, stretch = 40, 0.05
    model, state, still = _taut_line(n, stretch)  # 5 cm on 100 m: 500 N
    ea, length = model.axial_stiffness, model.length
    k, m = (n + 1) * ea / length, model.mass_per_length * length / n
    assert stable_time_step(model, 1.0) == pytest.approx(np.sqrt(m / k), rel=1e-12)
    bound = stable_time_step(model, 1.0)
    # just below the bound the taut line runs on (2 s, some 1600 steps) at its tension EA e / L (to the
    # ripple's 1e-6 m: 1e-6)
    run = simulate(model, still, 2.0, 2.0, state, time_step=2.0 / np.ceil(2.0 / (0.97 * bound)))
    assert run.tension[-1] == pytest.approx(np.full(n + 1, ea * stretch / length), rel=1e-6)
    # 2 % above it the stiffest mode grows and the run ends (after 74 of 2000 steps; asserted within 200):
    # the bound is tight (the compiled steps themselves, as simulate refuses such a step)
    n_steps = 2000
    tp, tv = still(np.zeros(n_steps + 1))
    S = state
    done = K.run_steps(1.02 * bound, tp, tv, S.R.copy(), S.E.copy(), S.nu.copy(), S.om.copy(), np.array([0]),
                       model.params, S.barge.copy(), model.barge_params, 0.0, 10.0, True, np.zeros((n, 3)),
                       np.full(n, model.params[K.P_I]), np.zeros(n + 1), np.zeros(n + 1, np.bool_))
    assert done < 200


def test_time_step_above_the_stability_bound_is_refused():
    model, state, still = _taut_line(10, 0.05)
    with pytest.raises(sc.InputError, match="stability bound"):
        simulate(model, still, 1.0, 1.0, state, time_step=0.1)


def test_a_state_that_is_not_finite_stops_the_run_with_its_time():
    model, state, still = _taut_line(10, 0.05)
    state.nu[3, 1] = np.nan
    with pytest.raises(sc.ConvergenceError, match="stopped being finite at t = 0 s"):
        simulate(model, still, 1.0, 1.0, state)


def test_implicit_joint_dampers_give_the_joint_damping_ratio():
    """One element in air between two fixed points, moved along the line and let go. The joint behind it
    opens and the one ahead closes, and a closing joint takes no compression: in each half cycle one
    joint (stiffness k, damper c_x = 2 zeta sqrt(k m)) holds the mass m, a damped oscillator with
    omega = sqrt(k / m) and ratio zeta. The damper's term in the element's own velocity is implicit (backward
    Euler), exact here as the other end of the joint is fixed, so the step does not matter."""
    zeta, ea, length, mass = 0.05, 1e6, 10.0, 1.725
    model = TowlineModel(n_elements=1, length=length, diameter=0.05, mass_per_length=mass, axial_stiffness=ea,
                         damping_ratio=zeta, bending_damping_ratio=0.0, gravity=0.0, drag=False, impact=False,
                         held_tow_point_height=10.0)
    tug = np.array([0.0, 0.0, 10.0])
    state = initial_state(model, tug, start="straight")
    state.R[0, 0] -= 1e-3  # 1 mm aft (the tug is ahead, at x = 0): 1 mm into the aft joint, far from its stop
    k, m = 2 * ea / length, mass * length  # (n + 1) EA / L with n = 1
    omega = np.sqrt(k / m)
    period = 2 * np.pi / omega
    run = simulate(model, lambda t: (np.tile(tug, (np.size(t), 1)), np.zeros((np.size(t), 3))),
                   30 * period, period / 40, state, time_step=period / 4000)
    x = run.centres[:, 0, 0] - (run.centres[0, 0, 0] + 1e-3)  # displacement from rest
    from scipy.signal import find_peaks

    index = find_peaks(x)[0]
    peaks = x[index]
    measured = -np.log(peaks[1:] / peaks[:-1]).mean()
    # the log decrement 2 pi zeta / sqrt(1 - zeta^2) per period; the step (period / 4000) leaves
    # backward Euler's O(c dt / m) = 1e-4 in it, the peaks sampled at period / 40 a (1 - cos(pi / 40))
    # = 3e-3 in each peak that cancels in the ratios: 1 %
    assert peaks.size >= 20
    assert measured == pytest.approx(2 * np.pi * zeta / np.sqrt(1 - zeta**2), rel=1e-2)
    # the damped period 2 pi / (omega sqrt(1 - zeta^2)), from the peaks' spacing, to a sample (1/40) over
    # the 20 periods: 0.2 %
    spacing = (run.time[index[-1]] - run.time[index[0]]) / (index.size - 1)
    assert spacing == pytest.approx(period / np.sqrt(1 - zeta**2), rel=2e-3)


def test_immersed_fraction_matches_the_circular_segment():
    from seacable.towline.kernel import _immersed

    c = np.linspace(-1.0, 1.0, 2001)
    exact = (np.arccos(-c) + c * np.sqrt(1 - c * c)) / np.pi
    ours = np.array([_immersed(h) for h in c])
    # Abramowitz & Stegun 4.4.46: arccos to 2e-8 rad, so the fraction to 2e-8 / pi; asserted to 1e-8
    np.testing.assert_allclose(ours, exact, rtol=0, atol=1e-8)
    assert _immersed(2.0) == 1.0 and _immersed(-2.0) == 0.0


def test_frame_rotation_series_matches_the_exact_rotation():
    from scipy.spatial.transform import Rotation

    from seacable.towline.kernel import _rotate

    # one step of 0.02 s turning by 0.02, 0.0072 and 1e-4 rad: above the series' switch (0.01), below it
    for q, r in ((0.6, -0.8), (0.3, -0.2), (3e-3, 4e-3)):
        E = np.eye(3)
        _rotate(E, q, r, 0.02)
        # the body rotation by (0, q, r) dt: round-off on both branches
        np.testing.assert_allclose(E, Rotation.from_rotvec([0.0, 0.02 * q, 0.02 * r]).as_matrix(), atol=1e-15)



@pytest.mark.parametrize("end", [0, 1])
def test_an_end_joint_keeps_its_turning_axis_torque_whatever_the_last_bit_of_its_axis(end):
    """An end joint's axis (the tug's, the barge's) is its one element's direction e1, of unit length. The kernel
    took the torque of a joint's turning axis only where the axis sum's length al >= 1 (a joint bent past 120
    degrees goes without it), so at an end joint it kept or dropped that torque on the last bit of |e1|: 10 N m
    on a 2500 N m moment here, and between two runs differing by round-off a jump of 1e-4 in the elements' rates
    once |e1| rounded the other way. One step of a 2-element line with 1 cm of gap across the tug's joint (end 0)
    or the held end's (end 1): the end element's axis 2^-52 short of unit length must give the same rates as the
    unit one, to the round-off that 2^-52 makes (measured: equal; the dropped torque made 4e-3)."""
    from seacable.towline import kernel as K

    model = TowlineModel(n_elements=2, length=20.0, diameter=0.05, mass_per_length=1.725, axial_stiffness=1e6,
                         drag=False, impact=False)  # no barge: the line's aft end held at (0, 0, 1 m) + (x, y)_barge
    P = model.params
    E0 = np.zeros((3, 3))
    K.frame_from_axis(np.array([-1.0, 0.0, 0.0]), E0)
    gap = 0.01  # ahead of element 0's front / beyond element 1's aft, and as much across [m]
    tug_p = np.array([[20.0 + gap, gap, 1.0] if end == 0 else [20.0, 0.0, 1.0]] * 2)
    barge = np.array([0.0, 0.0, 0.0, 0.0, 0.0, 0.0] if end == 0 else [-gap, -gap, 0.0, 0.0, 0.0, 0.0])
    rates = []
    for scale in (1.0, 1.0 - 2.0**-52):
        R = np.array([[15.0, 0.0, 1.0], [5.0, 0.0, 1.0]])
        E = np.array([E0, E0])
        E[end, :, 0] *= scale
        nu, om = np.zeros((2, 3)), np.zeros((2, 2))
        assert K.run_steps(1e-4, tug_p, np.zeros((2, 3)), R, E, nu, om, np.zeros(1, np.int64), P, barge.copy(),
                           np.zeros(1), 0.0, 1.0, True, np.zeros((2, 3)), np.full(2, P[K.P_I]), np.zeros(3),
                           np.zeros(3, np.bool_)) == 1
        rates.append(om[end].copy())
    assert abs(rates[0][1]) > 1e-3  # the pin's moment turns the end element about e3 [rad/s]
    assert np.max(np.abs(rates[1] - rates[0])) < 1e-12 * np.max(np.abs(rates[0]))

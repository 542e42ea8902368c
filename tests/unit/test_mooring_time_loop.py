"""The compiled time loop of the mooring model (issue 19): the same numbers as the loop it replaced.

The reference is the former time loop, written out here: one compiled call of
:func:`seacable.mooring.kernel.newmark_steps` per output interval from Python (with the motion evaluated for
that interval, halved steps on a failed step), and the output state evaluated from Python. The compiled
loop runs the same floating-point operations in the same order, so the agreement is to round-off.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.interpolate import CubicSpline

import seacable as sc
from seacable.errors import ConvergenceError
from seacable.mooring import kernel as K
from seacable.mooring.motion import HarmonicMotion, PlatformMotion, TimeSeriesMotion, bind
from seacable.mooring.network import network_from_line
from seacable.mooring.solver import (
    MooringModel,
    Water,
    advance_interval,
    recommended_time_step,
    simulate,
    static_equilibrium,
)

CHAIN = sc.LineType(diameter=0.09, mass_per_length=77.7066, weight_in_water=698.094, axial_stiffness=384.243e6)


def _model(n=20):
    net = network_from_line(sc.Line.single(CHAIN, 902.2), (0, 0, -320), (848.67, 0, -70), water_density=1025,
                            gravity=9.81, n_elements=n, damping_ratio=0.5)
    return MooringModel(net, Water(depth=320.0, seabed_stiffness=1e5, seabed_damping=1e4, wave_height=3.0,
                                   wave_period=9.0))


def _old_simulate(model, motion, duration, dt, output_interval, *, initial, tol, max_iter, max_halvings=6,
                  spectral_radius=1.0):
    """The time loop as it was before the compiled one (Python for each output interval)."""
    from seacable.mooring.solver import generalized_alpha

    alpha_m, alpha_f, beta, gamma = generalized_alpha(spectral_radius)
    net = model.network
    n = net.n_nodes
    X = np.array(initial, float)
    V, A = np.zeros_like(X), np.zeros_like(X)
    n_out = round(duration / output_interval)
    sub = max(1, math.ceil(output_interval / dt - 1e-9))
    h = output_interval / sub
    F, M, tension = np.zeros((n, 3)), np.zeros((n, 3, 3)), np.zeros(net.n_elements)
    x0, v0, a0 = motion(np.zeros(1))
    pres = np.flatnonzero(net.channel >= 0)
    X[pres], V[pres], A[pres] = x0[0, net.channel[pres]], v0[0, net.channel[pres]], a0[0, net.channel[pres]]
    Fi, Mi, _, _ = model.evaluate(X, V, A, settled=True)
    free = model.fidx >= 0
    A[free] = np.linalg.solve(Mi[free], Fi[free][..., None])[..., 0]
    G = np.zeros_like(X)
    K.alpha_history(Fi, Mi, A, G, alpha_m, alpha_f, model.fidx)
    ten = [model.evaluate(X, V, A, 0.0, settled=True)[2]]
    sup = [model.evaluate(X, V, A, 0.0, settled=True)[3]]
    stats = np.zeros(3)
    steps = 0
    for k in range(n_out):
        def newmark(t, dtk, px, pv, pa):
            return K.newmark_steps(X, V, A, t, dtk, px, pv, pa, net.channel, *model.element_args(), model.fidx,
                                   model.nfree, model.bw, model.env, model.cur_depth, model.cur_speed, True,
                                   model.sea, beta, gamma, alpha_m, alpha_f, G, tol, max_iter, F, M, tension, stats)

        done, _ = advance_interval(k * output_interval, h, sub, motion, newmark, stats, max_halvings, max_iter,
                                   "mooring", "fix")
        steps += done
        _, _, t_e, s_n = model.evaluate(X, V, A, (k + 1) * output_interval, settled=True)
        ten.append(t_e)
        sup.append(s_n)
    return np.array(ten), np.array(sup), steps


@pytest.mark.parametrize("dt, max_iter, rho", [(0.1, 30, 1.0), (0.25, 3, 1.0), (0.1, 30, 0.8)])
def test_compiled_loop_reproduces_the_former_loop(dt, max_iter, rho):
    """Tensions and support forces of 30 s of 3 m waves and a 4 m surge at the fairlead, to 1e-10 relative.

    With ``max_iter = 3`` at 0.25 s steps the Newton iteration fails now and then and those intervals are
    finished at halved steps (more steps than 4 per second): that path is compared too.
    """
    model = _model()
    st = static_equilibrium(model)
    motion = bind(_harmonic(), model.network.channel_positions(), 30.0)
    old_t, old_s, old_steps = _old_simulate(model, motion, 30.0, dt, 0.5, initial=st.position, tol=1e-7,
                                            max_iter=max_iter, spectral_radius=rho)
    run = simulate(model, motion, 30.0, dt, 0.5, initial=st.position, tol=1e-7, max_iter=max_iter,
                   spectral_radius=rho)
    assert run.steps == old_steps
    if max_iter == 3:
        assert run.steps > round(30.0 / dt)  # some intervals were halved
    # round-off only: the same operations in the same order (1e-10 of the largest tension)
    scale = np.abs(old_t).max()
    assert np.abs(run.tension - old_t).max() <= 1e-10 * scale
    assert np.abs(run.support - old_s).max() <= 1e-10 * scale
    assert run.time == pytest.approx(np.arange(61) * 0.5, abs=1e-12)


def _harmonic():
    return HarmonicMotion(amplitude=(4.0, 0.0, 1.0), period=12.0, ramp=6.0)


def test_failed_step_at_the_smallest_step_names_time_and_residual():
    model = _model()
    st = static_equilibrium(model)
    motion = bind(_harmonic(), model.network.channel_positions(), 5.0)
    # two Newton iterations never reach the tolerance from the predictor (the first is never accepted)
    with pytest.raises(ConvergenceError, match=r"did not converge at t = 0 s with dt = 0\.25 s after 0 halvings") \
            as err:
        simulate(model, motion, 5.0, 0.25, 0.5, initial=st.position, max_iter=1, max_halvings=0)
    assert err.value.residual > 0


def test_interrupt_inside_a_chunk_keeps_every_stored_output():
    """Ctrl-C arriving in the middle of the compiled chunk: the outputs it stored are kept (the progress
    callback sees the chunk's outputs one by one and raises at the 7th)."""
    model = _model()
    st = static_equilibrium(model)
    seen = []

    def progress(t, duration):
        seen.append(t)
        if len(seen) == 7:
            raise KeyboardInterrupt

    run = simulate(model, None, 20.0, 0.1, 0.5, initial=st.position, progress=progress)
    assert run.interrupted and run.time.size == 8 and run.time[-1] == pytest.approx(3.5)
    assert seen == pytest.approx(list(np.arange(1, 8) * 0.5))


def test_csv_motion_sampled_equals_the_spline_of_its_table(tmp_path):
    """A time-series motion sampled on a step grid equals the natural cubic spline of its table evaluated
    directly (position, velocity, acceleration), and the file is read once."""
    t = np.linspace(0.0, 20.0, 41)
    table = np.column_stack([t, 2 * np.sin(t / 3), 0 * t, 0.5 * np.cos(t / 2)])
    path = tmp_path / "m.csv"
    np.savetxt(path, table, delimiter=",", header="time,x,y,z", comments="")
    base = np.array([[100.0, 0.0, -20.0]])
    motion = TimeSeriesMotion(file=str(path))
    grid = np.arange(1, 191) * 0.1
    x, v, a = motion.channels(grid, base)
    cs = CubicSpline(t, table[:, 1:], bc_type="natural")
    assert np.array_equal(x[:, 0], base[0] + cs(grid))
    assert np.array_equal(v[:, 0], cs(grid, 1))
    assert np.array_equal(a[:, 0], cs(grid, 2))
    from seacable.mooring import motion as mo

    hits = mo._fitted_table.cache_info().hits
    motion.channels(grid[:5], base)
    assert mo._fitted_table.cache_info().hits == hits + 1  # not read nor fitted again
    # a changed file is read again
    np.savetxt(path, table * [1, 2, 1, 1], delimiter=",", header="time,x,y,z", comments="")
    x2, _, _ = motion.channels(grid, base)
    assert np.allclose(x2[:, 0, 0] - base[0, 0], 2 * cs(grid)[:, 0], atol=1e-12)


def test_platform_motion_from_csv_equals_its_harmonic_twin(tmp_path):
    """A platform CSV sampled finely equals the harmonic platform motion it tabulates (spline error only)."""
    amp, period = (1.0, 0.5, 0.8, 0.02, 0.03, 0.05), 10.0
    harm = PlatformMotion(amplitude=amp, period=period, reference=(0.0, 0.0, 0.0))
    t = np.arange(0.0, 40.001, 0.01)
    q = np.asarray(amp) * np.sin(2 * np.pi * t[:, None] / period)
    path = tmp_path / "p.csv"
    np.savetxt(path, np.column_stack([t, q]), delimiter=",", header="time,surge,sway,heave,roll,pitch,yaw",
               comments="")
    csv = PlatformMotion(file=str(path))
    base = np.array([[40.0, 10.0, -5.0], [-20.0, 30.0, -5.0]])
    grid = np.linspace(5.0, 35.0, 301)
    for got, want in zip(csv.channels(grid, base), harm.channels(grid, base), strict=True):
        # a cubic spline of samples h = 0.01 s apart: its second derivative is off by about q'''' h^2 / 12
        # = w^4 A h^2 / 12 = 1.3e-6 A (w = 2 pi / 10 s); A up to 2 m at the fairleads (a 40 m arm turning
        # 0.05 rad): 3e-6 m/s^2, well under 1e-5; positions and velocities are closer
        assert got == pytest.approx(want, abs=1e-5)


def test_recommended_time_step_from_the_axial_wave_speed_and_the_forcing():
    """Closed forms: the first axial period of a uniform line held at both ends is 2 L / sqrt(EA / m)."""
    model = _model()
    c = math.sqrt(CHAIN.axial_stiffness / CHAIN.mass_per_length)  # 2223.7 m/s
    axial = 2 * 902.2 / c                                         # 0.811 s
    dt, why = recommended_time_step(model, 12.0)
    assert dt == pytest.approx(axial / 10, rel=1e-12)  # 0.0811 s < 12 s / 50
    assert "axial period" in why and f"{c:.4g} m/s" in why
    assert recommended_time_step(model, 2.0)[0] == pytest.approx(2.0 / 50, rel=1e-12)  # the forcing decides
    assert recommended_time_step(model)[0] == pytest.approx(axial / 10, rel=1e-12)


def test_a_mooring_run_records_and_prints_its_time_step(capsys):
    case = sc.parse_case({"line_types": {"c": {"diameter": 0.09, "mass_per_length": 77.7066,
                                               "weight_in_water": 698.094, "axial_stiffness": 384.243e6}},
                          "line": {"line_type": "c", "length": 902.2},
                          "environment": {"depth": 320.0},
                          "analysis": {"type": "mooring_dynamic", "anchor": [0.0, -320.0], "fairlead": [848.67, -70.0],
                                       "duration": 2.0, "time_step": 0.1, "output_interval": 0.5, "n_elements": 10,
                                       "motion": {"type": "harmonic", "amplitude": [1.0, 0.0, 0.0], "period": 4.0}}})
    ds = sc.run(case, progress=lambda t, d: None)
    assert ds.attrs["time_step"] == pytest.approx(0.1)
    assert ds.attrs["recommended_time_step"] == pytest.approx(4.0 / 50)  # 0.08 s < the axial 0.0811 s
    err = capsys.readouterr().err
    assert "time step 0.1 s; recommended 0.08 s (1/50 of the forcing period 4 s" in err


# three 40-segment chains to a platform (also bench/bench_memory.py's case)
THREE_LINES = (Path(__file__).parents[1] / "validation" / "data" / "three_chains_deck.txt").read_text()


def test_end_forces_from_the_line_ends_kinematics_equal_those_from_every_node(tmp_path):
    """Storing the velocities and accelerations of the lines' end nodes and their neighbours only gives the
    same fairlead and anchor tensions as storing every node's (the others do not enter the end nodes'
    loads): to round-off, on three lines moved 2 m in surge at 10 s."""
    from seacable.mooring.moordyn import _variables, moordyn_model
    from seacable.mooring.solver import line_end_nodes

    path = tmp_path / "three.txt"
    path.write_text(THREE_LINES)
    model = moordyn_model(path)
    st = static_equilibrium(model)
    motion = bind(HarmonicMotion(amplitude=(2.0, 0.0, 0.0), period=10.0, ramp=2.0),
                  model.network.channel_positions(st.position), 6.0)
    full = simulate(model, motion, 6.0, 0.1, 0.5, initial=st.position)
    ends = line_end_nodes(model.network)
    assert ends.size == 12
    part = simulate(model, motion, 6.0, 0.1, 0.5, initial=st.position, kinematics=ends)
    assert part.velocity.shape == (13, 12, 3)
    assert np.array_equal(part.position, full.position)
    a = _variables(model, full.position, full.tension, full.support, full.time, velocity=full.velocity,
                   acceleration=full.acceleration)[0]
    b = _variables(model, part.position, part.tension, part.support, part.time, velocity=part.velocity,
                   acceleration=part.acceleration, kinematic_nodes=part.kinematic_nodes)[0]
    for name in ("fairlead_tension", "anchor_tension"):
        ref = a[name].values
        assert np.abs(b[name].values - ref).max() <= 1e-12 * np.abs(ref).max()
    # and the velocities matter: the end forces without them differ (drag and damping at the fairlead)
    c = _variables(model, part.position, part.tension, part.support, part.time, velocity=0 * part.velocity,
                   acceleration=0 * part.acceleration, kinematic_nodes=part.kinematic_nodes)[0]
    assert np.abs(c["fairlead_tension"].values[:, 1:] - a["fairlead_tension"].values[:, 1:]).max() > 1.0


WD0200 = Path(__file__).parents[1] / "validation" / "data" / "moordyn_decks" / "MoorDyn" / "tests" / "Mooring" \
    / "WD0200_Chain.txt"


def _wd0200_line(tmp_path):
    """MoorDyn's WD0200 chain at 20 segments: its deck, model, line view, the line's nodes and elements, and its
    static equilibrium."""
    from seacable.mooring.moordyn import _line_views, moordyn_model

    path = tmp_path / "wd0200.txt"
    path.write_text(WD0200.read_text().replace("760       82", "760       20"))
    model = moordyn_model(path)
    view = _line_views(model)[0]
    nodes, els = model.network.line_nodes[0], np.flatnonzero(model.network.element_line == 0)
    return path, model, view, nodes, els, static_equilibrium(model)


def test_single_line_end_forces_read_from_the_stored_supports_are_the_evaluated_ones(tmp_path, monkeypatch):
    """A single line without attachments at its ends: its end forces at the static equilibrium and at each output
    of a run are the network's stored support forces at its end nodes (and its end elements' tensions for an end
    on the seabed), read instead of evaluated again, the same floats to the last bit; and a run of such a deck
    evaluates no state for them (issue 38: the overhead around the time loop)."""
    import seacable.mooring.outputs as O
    import seacable.mooring.run as R
    from seacable.io.moordyn import load_moordyn_case
    from seacable.mooring.moordyn import run_moordyn_case
    from seacable.mooring.solver import line_end_nodes

    path, model, view, nodes, els, st = _wd0200_line(tmp_path)
    X = st.position[nodes]
    read = R.line_end_forces(view, X, support=st.support[nodes], tension=st.tension[els])
    assert np.array_equal(read, R.line_end_forces(view, X))
    motion = bind(HarmonicMotion(amplitude=(0.0, 0.0, 2.0), period=10.0), model.network.channel_positions(st.position),
                  20.0)
    run = simulate(model, motion, 20.0, 0.1, 0.1, initial=st.position, kinematics=line_end_nodes(model.network))
    local = np.full(model.network.n_nodes, -1)
    local[nodes] = np.arange(nodes.size)
    mine = np.flatnonzero(local[run.kinematic_nodes] >= 0)
    args = (view, run.position[:, nodes], run.velocity[:, mine], run.acceleration[:, mine], run.time,
            local[run.kinematic_nodes[mine]])
    evaluated = R.line_end_forces(*args)
    read = R.line_end_forces(*args, support=run.support[:, nodes], tension=run.tension[:, els])
    assert np.array_equal(read, evaluated)
    # the support forces given at the two end nodes only: the same floats
    ends = R.line_end_forces(*args, end_support=run.support[:, nodes[[0, -1]]], tension=run.tension[:, els])
    assert np.array_equal(ends, evaluated)
    grounded = R.height_above_seabed(model.water, run.position[:, nodes[0]]) <= float(view.env[R.K_BEDRAMP])
    assert grounded.all()  # the anchor end lies on the seabed: its force comes from the end element's tension
    # and the whole run reads them: no state evaluated for the end forces
    calls = []
    monkeypatch.setattr(O, "evaluate_states", lambda *a: calls.append(a) or (_ for _ in ()).throw(AssertionError))
    case = load_moordyn_case(path).with_run(duration=2.0, time_step=0.1, output_interval=0.1,
                                            motion=HarmonicMotion(amplitude=(0.0, 0.0, 2.0), period=10.0))
    ds = run_moordyn_case(case)
    assert not calls and ds["fairlead_tension"].size == 21


def test_grounded_length_and_node_tensions_are_their_formulas_to_the_bit(tmp_path):
    """The grounded length (computed in place) and the node tensions (added on slices for a line numbered from
    end A) of a run's outputs are the floats of their formulas written plainly, states on, off and within the
    seabed's ramp alike (issue 38: the outputs without temporaries as large as themselves)."""
    import seacable.mooring.run as R

    _, model, view, nodes, els, st = _wd0200_line(tmp_path)
    motion = bind(HarmonicMotion(amplitude=(0.0, 0.0, 2.0), period=10.0), model.network.channel_positions(st.position),
                  10.0)
    run = simulate(model, motion, 10.0, 0.1, 0.1, initial=st.position)
    net, water = view.network, view.water
    X, T = run.position[:, nodes], run.tension[:, els]
    # the formulas as written before: every intermediate its own array
    share = np.zeros(net.n_nodes)
    np.add.at(share, net.elements[:, 0], 0.5 * net.length)
    np.add.at(share, net.elements[:, 1], 0.5 * net.length)
    dl = float(view.env[R.K_BEDRAMP])
    held = (net.kind != R.FREE) | (view.weight <= 0)

    def plain(X):
        pen = -R.height_above_seabed(water, X)
        q = np.where(pen >= dl, pen, np.where(pen > -dl, (pen + dl) ** 2 / (4 * dl), 0.0))
        carried = np.clip(water.seabed_stiffness * view.bedc * q / np.where(held, 1.0, view.weight), 0.0, 1.0)
        return np.sum(np.where(held, pen >= -dl, carried) * share, axis=-1)

    pen = -R.height_above_seabed(water, X)
    assert ((pen > -dl) & (pen < dl)).any() and (pen >= dl).any()  # nodes within the ramp and beyond it
    assert np.array_equal(R.contact_length(view, X), plain(X))
    assert np.array_equal(R.contact_length(view, X[3]), plain(X[3]))  # one state
    total, count = np.zeros(T.shape[:-1] + (net.n_nodes,)), np.zeros(net.n_nodes)
    for end in (0, 1):
        np.add.at(total, (..., net.elements[:, end]), T)
        np.add.at(count, net.elements[:, end], 1)
    assert np.array_equal(R._node_tension(net, T), total / np.maximum(count, 1))


def test_a_run_that_fails_after_a_jump_at_the_start_says_so():
    """A harmonic hang-off heave of 5 cm at 8 s without a ramp (the 80 m lazy wave, 0.5 m elements) starts the
    hang-off at 0.0393 m/s beside a cable at rest: the jump sends an axial wave of ``sqrt(EA m) dv`` = 5.15 kN
    (EA 4.69e8 N, m 36.7 kg/m) along a line held at 9.3 kN, which slackens and snaps it, and the tension-only
    elements' Newton fails within 0.3 s (with compression the same run passes, its tension 0.6 to 13.5 kN: the
    wave). The message names the jump and the ramp that removes it; with a one-period ramp the run passes."""
    case = sc.load_case(Path(__file__).parents[2] / "examples" / "lazy_wave_80m.yaml")
    analysis = {**case.analysis.model_dump(exclude={"type"}), "type": "mooring_dynamic", "duration": 0.5,
                "time_step": 0.05, "output_interval": 0.1,
                "motion": {"type": "harmonic", "amplitude": [0.0, 0.0, 0.05], "period": 8.0}}
    dv = 0.05 * 2 * math.pi / 8.0
    with pytest.raises(ConvergenceError) as err:
        sc.run(case.model_copy(update={"analysis": sc.Case.model_validate(
            {**case.model_dump(), "analysis": analysis}).analysis}))
    assert f"starts from rest at {dv:.3g} m/s" in str(err.value)
    assert f"sqrt(EA m) dv = {math.sqrt(4.69e8 * 36.7) * dv:.3g} N" in str(err.value)
    assert "'ramp'" in str(err.value)
    analysis["motion"]["ramp"] = 8.0
    ds = sc.run(sc.Case.model_validate({**case.model_dump(), "analysis": analysis}))
    assert float(ds.fairlead_tension.max()) < 9.4e3  # no snap

"""The uncoupled route of ``system_dynamic`` (``coupling: uncoupled``, issue 39) against closed forms: the
frequency-domain RAO of the database with the mooring's stiffness, and the slow-drift variance of Newman's
approximation through the low-frequency transfer function (Pinkster's force spectrum,
:func:`seacable.hydro.response.slow_drift_variance`); the slow drift of the full difference-frequency QTF
(``drift: qtf``) against its frequency-domain synthesis, and against Newman's for a QTF that is Newman's; the mean
offset and the low-frequency damping of a hull's current table against their closed forms; and against the coupled
route of the same case.

The VolturnUS-S hull of tests/data/volturnus (the ``hull_case`` fixture) on three taut ropes; its QTF extract
tests/data/volturnus/qtf (every pair of periods for 0.30-1.00 rad/s, heading 0).
"""

from __future__ import annotations

import dataclasses
import math
import shutil
from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.errors import InputError
from seacable.hydro import frequency_response, read_wamit
from seacable.hydro.loads import _drift, qtf_at
from seacable.hydro.response import _transfer, coefficients_at, slow_drift_variance
from seacable.mooring.motion import sea_of
from seacable.mooring.outputs import water_of_environment
from seacable.results import body_pose, stiffness_matrix
from seacable.system.uncoupled import prepare_system_uncoupled, uncoupled_motion

DATA = Path(__file__).parents[1] / "data" / "volturnus"
ROOT = DATA / "IEA-15-240-RWT-UMaineSemi"
QTF = DATA / "qtf" / "IEA-15-240-RWT-UMaineSemi.12d"
RHO, G = 1025.0, 9.80665
VOLUME = 20206.34889
INERTIA = (1.2507e10, 1.2507e10, 2.3667e10)
DAMPING = np.diag([6e5, 6e5, 1.4e6, 1.4e9, 1.4e9, 6e8])
ZG = -5.0
# ropes 10x stiffer than the fixture's: a mooring the low-frequency motion feels (surge period about 190 s)
ROPE = {"diameter": 0.05, "mass_per_length": 5.0, "axial_stiffness": 1e7, "drag_normal": 1.2,
        "added_mass_normal": 1.0}


def _rigid():
    m = RHO * VOLUME
    rigid = np.diag([m, m, m, *INERTIA])
    rigid[0, 4] = rigid[4, 0] = m * ZG
    rigid[1, 3] = rigid[3, 1] = -m * ZG
    rigid[3, 3] += m * ZG ** 2
    rigid[4, 4] += m * ZG ** 2
    return rigid


def _hydro(**more):
    return {"hydrodynamics": {"file": str(ROOT), "kernel_length": 60.0, "ramp": 40.0, **more}}


def test_a_regular_wave_moves_the_uncoupled_body_by_the_database_rao(tmp_path, hull_case):
    """(a) No drift, a regular wave at a frequency of the database (0.85 rad/s): after the ramp the body's motion
    about its static equilibrium is ``Re(H eta)``, ``eta`` the wave's complex elevation at the reference point (the
    run's own ``wave_elevation``) and ``H`` the frequency-domain RAO with the database's A, B and X there, the
    body's linear damping, its hydrostatics with the weight's moment and the mooring's stiffness of system_static.
    To 1e-6 of the motion: the same linear algebra, so round-off and the table's 8e-8 rad/s off the node."""
    db = read_wamit(ROOT, rho=RHO, g=G)
    omega = float(db.excitation_omega[4])
    waves = {"height": 2.0, "period": 2 * math.pi / omega}
    static = sc.run(sc.load_case(hull_case(tmp_path, waves=waves, rope=ROPE, body=_hydro(drift="none"),
                                           analysis={"type": "system_static"})))
    case = sc.load_case(hull_case(tmp_path, waves=waves, rope=ROPE, body=_hydro(drift="none"), analysis={
        "duration": 80.0, "output_interval": 0.5, "coupling": "uncoupled", "uncoupled": {"lines": "quasi_static"}}))
    ds = sc.run(case)
    assert ds.attrs["coupling"] == "uncoupled" and ds.attrs["analysis"] == "system_dynamic"
    t = np.asarray(ds["time"])
    q = body_pose(ds)[:, 0]
    mean = np.array([float(np.asarray(static[k]).reshape(-1)[0]) for k in
                     ("body_x", "body_y", "body_z", "body_roll", "body_pitch", "body_yaw")])
    np.testing.assert_allclose(ds.attrs["mean_position"], mean, atol=1e-9)
    moor = np.asarray(stiffness_matrix(static)).reshape(6, 6)
    hydrostatic = np.asarray(case.system().bodies["hull"].hydrostatic_stiffness)
    a, b = (m[0] for m in coefficients_at(db, omega))
    h = frequency_response(_rigid(), a, b + DAMPING, hydrostatic + moor, db.excitation_at(omega, 0.0), omega)
    after = t > 40.0  # the ramp's end
    eta = np.asarray(ds["wave_elevation"])[after]
    basis = np.column_stack([np.cos(omega * t[after]), np.sin(omega * t[after])])
    c = np.linalg.lstsq(basis, eta, rcond=None)[0]  # eta = Re(E e^(-i w t)), E = c0 + i c1
    expect = np.real(np.outer(np.exp(-1j * omega * t[after]), (c[0] + 1j * c[1]) * h))
    scale = np.abs(h) * abs(c[0] + 1j * c[1])
    for j in (0, 2, 4):  # surge, heave, pitch (sway, roll, yaw are 0 in head seas)
        assert np.max(np.abs(q[after, j] - mean[j] - expect[:, j])) < 1e-6 * scale[j], j
    # the quasi-static lines at the start (the mean position) have the statics' end forces: their catenaries' own,
    # the closed form system_static solves (measured 2e-15; their finite elements' mid-element tension, which the
    # route reported before, was off by the half end element's weight, 5 kg/m of 30 m elements: 0.6 kN of 0.66 MN)
    for name in ("fairlead_tension", "anchor_vertical_force"):
        np.testing.assert_allclose(np.asarray(ds[name])[0], np.asarray(static[name])[0], rtol=1e-12)


def test_the_uncoupled_slow_drift_has_the_frequency_domain_variance(tmp_path, hull_case):
    """(b) Newman's slow drift in a JONSWAP storm (Hs 6 m, Tp 10 s, 60 components) through Cummins' equation with the
    mooring's stiffness and 5 % of critical of line damping (2 z sqrt(K (M + A(0))) in surge, sway and yaw, written
    out here), over 28 hours (the first 1000 s, the transient, left out):

    - the record is the frequency-domain synthesis of its own sea, ``sum Re(H_LF(mu_ij) c_ij e^(-i mu_ij t))`` over
      the pairs (Pinkster's terms through the LF transfer function with the database's A and B): its variance to
      1 % (measured 0.1 %: the kernel's A and B, cut at 60 s, against the database's, and the 0.5 s step);
    - its variance is :func:`~seacable.hydro.response.slow_drift_variance`'s expectation within three standard errors
      of one such record, 12 % (the ratio's scatter over 30 realisations of this sea, synthesised in the frequency
      domain: 4 % over 28 h, 13 % over 3 h, where the surge's 190 s period beats between pairs outlast the record).
    """
    db = read_wamit(ROOT, rho=RHO, g=G)
    waves = {"spectrum": "jonswap", "hs": 6.0, "tp": 10.0, "seed": 1, "n_components": 60,
             "frequency_range": [0.3, 1.4]}
    case = sc.load_case(hull_case(tmp_path, waves=waves, rope=ROPE, body=_hydro(excitation=False), analysis={
        "duration": 100000.0, "time_step": 0.5, "output_interval": 1.0, "coupling": "uncoupled",
        "uncoupled": {"mooring_damping": 0.05, "lines": "quasi_static"}}))
    setup = prepare_system_uncoupled(case)
    motion = uncoupled_motion(case, setup)
    keep = motion.time > 1000.0
    surge = motion.low[keep, 0]
    stiffness = setup.stiffness + setup.mooring_stiffness
    damping = DAMPING.copy()
    for j in (0, 1, 5):
        damping[j, j] += 2 * 0.05 * math.sqrt(stiffness[j, j] * (_rigid()[j, j] + db.added_mass_zero[j, j]))
    np.testing.assert_allclose(setup.linear_damping, damping, rtol=1e-12, atol=1e-6)
    sea = sea_of(water_of_environment(case.environment, case.analysis.seabed_contact))
    # the realisation in the frequency domain, every 4 s (the record's low frequencies, 0.03-0.2 rad/s, resolved)
    d = np.sqrt(np.maximum(_drift(db, sea), 0.0))  # surge's drift is positive at every frequency here
    w, a = sea.omega, sea.amplitude
    i, j = np.triu_indices(w.size, 1)
    c = (2 * a[i] * a[j])[:, None] * d[i] * d[j] * np.exp(1j * (sea.phase[j] - sea.phase[i]))[:, None]
    response = np.linalg.solve(_transfer(db, _rigid(), stiffness, damping, w[j] - w[i]), c[..., None])[..., 0, 0]
    t = motion.time[keep][::8]
    synth = np.concatenate([(np.exp(-1j * np.outer(t[lo:lo + 1000], w[j] - w[i])) @ response).real
                            for lo in range(0, t.size, 1000)])
    assert np.var(surge[::8]) == pytest.approx(np.var(synth), rel=0.01)
    expected = slow_drift_variance(db, sea, _rigid(), stiffness, damping)[0]
    assert np.var(surge) == pytest.approx(expected, rel=0.12)


def test_uncoupled_keys_refused_with_one_message(tmp_path, hull_case):
    waves = {"height": 2.0, "period": 7.4}
    cases = [
        ({"uncoupled": {"lines": "quasi_static"}}, (r"'uncoupled' gives the options of the uncoupled route, but "
                                                    r"coupling is 'coupled'")),
        ({"coupling": "uncoupled", "uncoupled": {"mooring_damping": 5.0}},
         r"mooring_damping in surge must be a fraction of critical damping in \[0, 1\), got 5.0.*0.05 for 5 %"),
        ({"coupling": "uncoupled", "uncoupled": {"lines": "static"}}, r"lines"),
        ({"coupling": "sometimes"}, r"coupling"),
        ({"coupling": "uncoupled", "failures": [{"line": "rope0", "end": "b", "time": 5.0}]},
         r"coupling 'uncoupled' does not take 'failures'"),
        ({"coupling": "uncoupled", "start": "held"}, r"coupling 'uncoupled' starts from the equilibrium"),
    ]
    for analysis, message in cases:
        with pytest.raises(InputError, match=message):
            sc.load_case(hull_case(tmp_path, waves=waves, rope=ROPE, body=_hydro(), analysis=analysis))


@pytest.mark.parametrize("body, rope, message", [
    ({"hydrodynamics": None, "hydrostatic_stiffness": np.diag([0, 0, 4.5e6, 1e9, 1e9, 0]).tolist()}, ROPE,
     r"bodies.hull: coupling 'uncoupled' needs the body's hydrodynamic database"),
    (_hydro(), {**ROPE, "tension_strain": [[0.0, 0.0], [1e6, 0.1]], "axial_stiffness": 1e7},
     r"lines.rope0: analysis.uncoupled.lines 'quasi_static' takes a constant axial stiffness"),
])
def test_an_uncoupled_case_it_cannot_run_is_refused_by_validate_and_run(tmp_path, hull_case, body, rope, message):
    case = sc.load_case(hull_case(tmp_path, waves={"height": 2.0, "period": 7.4}, rope=rope, body=body, analysis={
        "duration": 10.0, "coupling": "uncoupled", "uncoupled": {"lines": "quasi_static"}}))
    with pytest.raises(InputError, match=message):
        sc.check(case)
    with pytest.raises(InputError, match=message):
        sc.run(case)


def test_the_uncoupled_route_against_the_coupled_one_in_a_storm(tmp_path, hull_case):
    """(c) The same case (a JONSWAP storm, Hs 6 m, Tp 10 s, Newman's drift, 600 s) by both routes: the fairlead
    tensions' mean and standard deviation after 200 s (the coupled body's start: its first-order force ramped on
    over 40 s rings its 190 s surge mode, damped in about 110 s; the uncoupled route ramps the response instead).

    Both start from the equilibrium under the mean drift and feel the same sea with the same phases, so they differ
    by what the uncoupled route leaves out: the lines' damping of the body (here none is estimated, mooring_damping
    0, against the light ropes' drag in the coupled run), the lines' inertia and drag felt by the body at wave
    frequency, and the RAOs taken about the mean position rather than the instantaneous one. With these light taut
    ropes (5 kg/m) all three are small: measured 0.3-0.8 % on the mean and 1.3-1.8 % on the standard deviation
    (after 100 s of 600 s): asserted to 3 % and 5 %. The quasi-static lines give the dynamic
    lines' tensions to 0.3 % (the ropes' own dynamics are negligible here; for chain in deep water they are not:
    README). The README says when the uncoupled route is not conservative."""
    waves = {"spectrum": "jonswap", "hs": 6.0, "tp": 10.0, "seed": 3, "n_components": 60,
             "frequency_range": [0.3, 1.4]}
    run = {"duration": 600.0, "output_interval": 0.5}
    stats = {}
    for route, extra in (("coupled", {}),
                         ("dynamic", {"coupling": "uncoupled", "uncoupled": {"lines": "dynamic"}}),
                         ("quasi_static", {"coupling": "uncoupled", "uncoupled": {"lines": "quasi_static"}})):
        ds = sc.run(sc.load_case(hull_case(tmp_path, waves=waves, rope=ROPE, body=_hydro(), analysis={**run, **extra})))
        keep = np.asarray(ds["time"]) > 200.0
        tension = np.asarray(ds["fairlead_tension"])[keep]
        stats[route] = tension.mean(axis=0), tension.std(axis=0)
    for route in ("dynamic", "quasi_static"):
        np.testing.assert_allclose(stats[route][0], stats["coupled"][0], rtol=0.03)
        np.testing.assert_allclose(stats[route][1], stats["coupled"][1], rtol=0.05)
    np.testing.assert_allclose(stats["quasi_static"][1], stats["dynamic"][1], rtol=0.01)


def test_the_mean_wind_moves_the_uncoupled_body_as_the_statics_under_its_force(tmp_path, hull_case):
    """The mean position under a 20 m/s wind (at 10 m; NPD's profile to the 100 m centre of pressure, 1/2 rho_air
    C A U^2 with C A = 1000 m^2: about 0.4 MN) is system_static's equilibrium under that force as the body's
    external force (to the statics' tolerance); the gusts move the body about it (a low-frequency motion > 0)."""
    from seacable.wind import AIR_DENSITY, npd_profile

    wind_areas = {"wind": {"height": 100.0, "surge": [1000.0], "sway": [0.0], "yaw": [0.0]}}
    waves = {"height": 2.0, "period": 7.4}
    env_wind = {"speed": 20.0, "heading": 0.0, "spectrum": "npd", "seed": 2}
    path = hull_case(tmp_path, waves=waves, rope=ROPE, body={**_hydro(drift="none"), **wind_areas}, analysis={
        "duration": 200.0, "output_interval": 1.0, "coupling": "uncoupled", "uncoupled": {"lines": "quasi_static"}})
    data = yaml.safe_load(path.read_text())
    data["environment"]["wind"] = env_wind
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    ds = sc.run(sc.load_case(path))
    force = 0.5 * AIR_DENSITY * 1000.0 * float(npd_profile(20.0, 100.0)) ** 2
    static = sc.run(sc.load_case(hull_case(tmp_path, waves=waves, rope=ROPE, body={
        **_hydro(drift="none"), "external_force": [force, 0, 0, 0, 0, 0]}, analysis={"type": "system_static"})))
    mean = np.array([float(np.asarray(static[k]).reshape(-1)[0]) for k in ("body_x", "body_y", "body_z")])
    assert mean[0] > 5.0  # the wind moves it metres
    np.testing.assert_allclose(ds.attrs["mean_position"][:3], mean, atol=1e-6 * abs(mean[0]))
    assert np.std(np.asarray(ds["body_low_frequency_motion"])[:, 0, 0]) > 0.01


def test_the_coupled_runner_refuses_an_uncoupled_case(tmp_path, hull_case):
    """Called directly, the coupled route's runner does not run an uncoupled case coupled in silence."""
    from seacable.system.dynamics import prepare_system_dynamic

    case = sc.load_case(hull_case(tmp_path, waves={"height": 2.0, "period": 7.4}, rope=ROPE, body=_hydro(),
                                  analysis={"duration": 10.0, "coupling": "uncoupled"}))
    with pytest.raises(InputError, match=r"prepare_system_dynamic runs the coupled route, the case asks for coupling "
                                         r"'uncoupled'.*seacable.run\(case\)"):
        prepare_system_dynamic(case)


def _qtf_root(folder: Path, twelve_d: str) -> Path:
    """The VolturnUS-S database with ``twelve_d`` (the text of a .12d file) as its drift and QTF: the files' root."""
    for ext in (".1", ".3", ".hst"):
        shutil.copy(f"{ROOT}{ext}", folder / f"hull{ext}")
    (folder / "hull.12d").write_text(twelve_d, encoding="utf-8")
    return folder / "hull"


def _newman_12d() -> str:
    """The QTF extract with every pair's QTF replaced by Newman's approximation from its own diagonal, sign-split
    (``sqrt(D+_i D+_j) - sqrt(D-_i D-_j)``, real), its diagonal (the mean drift) unchanged; 17 digits."""
    rows = [line.split() for line in QTF.read_text().splitlines()]
    diagonal = {(r[0], r[4]): float(r[7]) for r in rows if r[0] == r[1]}
    out = []
    for r in rows:
        d1, d2 = diagonal[r[0], r[4]], diagonal[r[1], r[4]]
        t = math.sqrt(max(d1, 0.0) * max(d2, 0.0)) - math.sqrt(max(-d1, 0.0) * max(-d2, 0.0))
        if r[0] == r[1]:
            t = d1
        out.append(" ".join(r[:5] + [f"{abs(t):.16E}", "0.0" if t >= 0 else "180.0", f"{t:.16E}", "0.0"]))
    return "\n".join(out) + "\n"


QTF_SEA = {"spectrum": "jonswap", "hs": 6.0, "tp": 11.0, "seed": 3, "n_components": 60, "frequency_range": [0.3, 0.99]}


def _qtf_case(hull_case, folder: Path, root: Path, drift: str, duration: float):
    """The hull in :data:`QTF_SEA` (within the extract's frequencies) with the drift and QTF of ``root``, uncoupled
    at the low-frequency step (0.5 s) with 5 % of critical of the lines' damping, no first-order loads."""
    return sc.load_case(hull_case(folder, waves=QTF_SEA, rope=ROPE, body={"hydrodynamics": {
        "file": str(root), "kernel_length": 60.0, "ramp": 40.0, "drift": drift, "excitation": False}}, analysis={
        "duration": duration, "time_step": 0.5, "output_interval": 1.0, "coupling": "uncoupled",
        "uncoupled": {"mooring_damping": 0.05, "lines": "quasi_static"}}))


def test_the_uncoupled_slow_drift_of_the_full_qtf_is_its_frequency_domain_synthesis(tmp_path, hull_case):
    """``drift: qtf`` (the VolturnUS-S QTF extract) in a JONSWAP sea (Hs 6 m, Tp 11 s, 60 components in 0.30-0.99
    rad/s): the low-frequency motion after its start (1000 s: the 5 % line damping and the hull's own, about 35 % of
    critical in surge, have damped the ramp's transient by e^-10) is, at every time, the frequency-domain synthesis
    of its own sea, ``sum_(w_i > w_j) Re(H_LF(mu) 2 a_i a_j T(w_i, w_j) e^(i (p_i - p_j)) e^(-i mu t))``, ``mu = w_i -
    w_j``, with ``T`` the QTF between the components (:func:`seacable.hydro.loads.qtf_at`) and ``H_LF`` the body's
    transfer function with the database's A and B, its hydrostatics, the mooring's stiffness and the damping of
    the route.

    Tolerances: the rms difference in surge within 2 % of the record's standard deviation (measured 0.74 %: the
    radiation kernel cut at 60 s against the database's A and B, 0.36 % with 120 s, and the 0.5 s step's, 1.8 %
    at 1 s); heave and pitch within 6 % (measured 3.6 % and 2.7 %, Newmark's second-order error at their 20-28 s
    periods, where the difference frequencies up to 0.69 rad/s reach: 13.5 % and 10 % at a 1 s step). Planted in
    the route's force, the QTF conjugated (the pairs' phases reversed, their variances the same) is 29 % off in surge,
    Newman's approximation in its place 16 %, the QTF's diagonal alone 56 %."""
    root = _qtf_root(tmp_path, QTF.read_text())
    case = _qtf_case(hull_case, tmp_path, root, "qtf", 3000.0)
    setup = prepare_system_uncoupled(case)
    motion = uncoupled_motion(case, setup)
    db = read_wamit(root, rho=RHO, g=G)
    sea = sea_of(water_of_environment(case.environment, case.analysis.seabed_contact))
    w, a, p = sea.omega, sea.amplitude, sea.phase
    i, j = np.triu_indices(w.size, 1)
    hi, lo = np.where(w[i] > w[j], i, j), np.where(w[i] > w[j], j, i)
    t_ij = qtf_at(db, w, 0.0)[hi, lo]  # (pairs, 6)
    c = (2 * a[hi] * a[lo] * np.exp(1j * (p[hi] - p[lo])))[:, None] * t_ij
    mu = w[hi] - w[lo]
    stiffness = setup.stiffness + setup.mooring_stiffness
    response = np.linalg.solve(_transfer(db, _rigid(), stiffness, setup.linear_damping, mu), c[..., None])[..., 0]
    keep = motion.time > 1000.0
    synth = (np.exp(-1j * np.outer(motion.time[keep], mu)) @ response).real
    record = motion.low[keep]
    for dof, tol in ((0, 0.02), (2, 0.06), (4, 0.06)):
        rms = np.sqrt(np.mean((record[:, dof] - synth[:, dof]) ** 2))
        assert rms < tol * np.std(synth[:, dof]), dof
    assert np.std(record[:, 0]) > 1.0  # metres of slow drift


def test_a_qtf_that_is_newmans_gives_the_uncoupled_route_newmans_slow_drift(tmp_path, hull_case):
    """A .12d whose pairs are Newman's approximation of its own diagonal (sign-split, real; 17 digits): ``drift:
    qtf`` and ``drift: newman`` give the same low-frequency motion, to round-off (1e-9 of its largest value in
    every DOF, measured 4e-15; the two sums are taken by different algebra), in a sea of 13 components on the QTF's
    grid frequencies
    (0.35-0.95 rad/s; JONSWAP amplitudes, seeded phases): there the bilinear QTF is Newman's exactly (off the grid
    it interpolates the products, Newman's approximation the drift)."""
    from seacable.seastate import jonswap
    from seacable.waves import wave_number

    root = _qtf_root(tmp_path, _newman_12d())
    db = read_wamit(root, rho=RHO, g=G)
    w = db.qtf_omega[1:14]
    on_grid = {"omega": w, "amplitude": np.sqrt(2 * jonswap(w, 6.0, 11.0) * 0.05), "heading": np.zeros(w.size),
               "phase": np.random.default_rng(5).uniform(0, 2 * math.pi, w.size),
               "wave_number": np.asarray(wave_number(2 * math.pi / w, 200.0, G), float)}
    low = {}
    for drift in ("qtf", "newman"):
        case = _qtf_case(hull_case, tmp_path, root, drift, 1500.0)
        setup = prepare_system_uncoupled(case)
        setup.sea = dataclasses.replace(setup.sea, **on_grid)  # the low-frequency motion's sea (its mean is removed)
        low[drift] = uncoupled_motion(case, setup).low
    scale = np.abs(low["newman"]).max(axis=0)
    assert scale[0] > 0.05 and scale[2] > 1e-3  # the sea moves it (surge, heave)
    np.testing.assert_array_less(np.abs(low["qtf"] - low["newman"]).max(axis=0), 1e-9 * scale + 1e-300)


# a hull's current areas by the relative current's direction in its axes (every 45 deg; surge and sway drag, a yaw
# moment largest off the axes), and a current between two of its headings
CURRENT_TABLE = {"headings": np.radians(np.arange(0, 360, 45)).tolist(),
                 "surge": [600.0, 450.0, 0.0, -450.0, -600.0, -450.0, 0.0, 450.0],
                 "sway": [0.0, 500.0, 700.0, 500.0, 0.0, -500.0, -700.0, -500.0],
                 "yaw": [0.0, 8000.0, 0.0, -8000.0, 0.0, 8000.0, 0.0, -8000.0]}
CURRENT = {"speed": 1.2, "heading": 0.3}


def _current_case(hull_case, folder: Path, *, table=True, external=None, analysis=None):
    """The hull on its ropes (10 elements each in every analysis) in :data:`CURRENT`, still water, with
    :data:`CURRENT_TABLE` (``table``) and an ``external`` force; uncoupled with dynamic lines by default."""
    body = {"hydrodynamics": {"file": str(ROOT), "kernel_length": 60.0, "drift": "none"}}
    if table:
        body["current"] = CURRENT_TABLE
    if external is not None:
        body["external_force"] = [float(v) for v in external]
    path = hull_case(folder, waves=None, rope=ROPE, body=body, analysis=analysis or {
        "duration": 5.0, "coupling": "uncoupled", "uncoupled": {"lines": "dynamic"}})
    data = yaml.safe_load(path.read_text())
    data["environment"]["current"] = CURRENT
    for line in data["lines"].values():
        line["n_elements"] = 10  # the statics' lines as the dynamics' (the ropes' own drag the same in both)
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    return sc.load_case(path)


def _table_closed_form(yaw: float):
    """The table's force and yaw moment (3,) on the hull at rest at ``yaw`` [rad] (``1/2 rho U^2 C(beta)``, C linear
    between the table's headings, the force turned from the body's axes to the global ones) and its damping
    -dF/dv (3, 2) at rest: ``dF_b/dw = rho C u^T + 1/2 rho U C' (-sin th, cos th)`` of the relative current ``w =
    u - v`` (``th`` its direction, ``beta = th - yaw``), the first two rows turned by the yaw."""
    speed, th = CURRENT["speed"], CURRENT["heading"]
    u = speed * np.array([math.cos(th), math.sin(th)])
    beta = th - yaw
    step = math.pi / 4
    k = int(beta // step)
    table = np.array([CURRENT_TABLE[key] for key in ("surge", "sway", "yaw")]).T  # (8, 3)
    slope = (table[(k + 1) % 8] - table[k]) / step
    c = table[k] + slope * (beta - k * step)
    rot = np.array([[math.cos(yaw), -math.sin(yaw)], [math.sin(yaw), math.cos(yaw)]])
    fb = 0.5 * RHO * speed ** 2 * c
    db = RHO * np.outer(c, u) + 0.5 * RHO * speed * np.outer(slope, [-math.sin(th), math.cos(th)])
    return np.r_[rot @ fb[:2], fb[2]], np.vstack([rot @ db[:2], db[2:]])


def test_the_current_table_sets_the_uncoupled_mean_and_damps_the_low_frequency_motion(tmp_path, hull_case):
    """A hull current table in a 1.2 m/s current at 0.3 rad (between the table's headings 0 and 45 deg), still
    water, uncoupled (lines in time: the catenaries take no current):

    - the mean position is system_static's equilibrium without the table under the table's closed-form force and
      moment ``1/2 rho |u| u C(beta)`` at the yaw found as the body's external force (the ropes' own drag the same
      in both), to the statics' tolerance (1e-6 of the 11.3 m offset: measured 2.5e-7; their force tolerance is
      1e-8); the table moves the hull by metres and turns it by 0.03 rad (a table left out, or its sign flipped,
      misses the offset by that much), and the coupled route's calm run stays there (measured 3e-9);
    - the low-frequency equation's linear damping is the hull's own plus the table's -dF/dv at rest (the relative
      velocity's damping the coupled step has; closed form in :func:`_table_closed_form`: surge about rho C U, 0.7
      MN s/m), to 1e-5 (the central differences' (h / U)^2 = 1e-6 of the force law: measured 5e-7); dropped, or
      of the wrong sign, it is 100 % off."""
    case = _current_case(hull_case, tmp_path)
    setup = prepare_system_uncoupled(case)
    pose = setup.mean + np.asarray(setup.system.bodies["hull"].position, float)
    force, damping = _table_closed_form(float(pose[5]))
    assert 0.0 < CURRENT["heading"] - pose[5] < math.pi / 4  # between the two headings the closed form takes
    static = sc.run(_current_case(hull_case, tmp_path, table=False, external=(force[0], force[1], 0, 0, 0, force[2]),
                                  analysis={"type": "system_static"}))
    by_hand = np.array([float(static[f"body_{k}"].values[0, 0]) for k in ("x", "y", "z", "roll", "pitch", "yaw")])
    still = prepare_system_uncoupled(_current_case(hull_case, tmp_path, table=False))
    offset = float(np.hypot(*(setup.mean - still.mean)[:2]))
    assert offset > 3.0 and abs(setup.mean[5] - still.mean[5]) > 0.01  # metres, and turned
    np.testing.assert_allclose(pose, by_hand, rtol=0, atol=1e-6 * offset)
    expected = DAMPING.copy()  # the hull's own (isotropic in the horizontal: the same at any yaw)
    expected[np.ix_([0, 1, 5], [0, 1])] += damping
    np.testing.assert_allclose(setup.linear_damping, expected, rtol=1e-5, atol=1e-5 * np.abs(damping).max())
    assert damping[0, 0] > 0.5e6  # the current damps the surge by as much as the hull's own 0.6 MN s/m
    coupled = sc.run(_current_case(hull_case, tmp_path, analysis={"duration": 5.0}))
    np.testing.assert_allclose(body_pose(coupled)[:, 0], np.tile(pose, (coupled.sizes["time"], 1)),
                               rtol=0, atol=1e-6 * offset)


def test_the_current_tables_damping_gives_the_uncoupled_route_the_coupled_slow_drift(tmp_path, hull_case):
    """The storm of (c) (JONSWAP Hs 6 m, Tp 10 s, Newman's drift, 600 s at 0.2 s) with the hull's current table in
    its current (:data:`CURRENT_TABLE`, 1.2 m/s), by both routes: the fairlead tensions' standard deviation after
    200 s, whose slow part the current's damping of the surge sets (0.68 MN s/m, as much as the hull's own). The
    uncoupled route within 10 % of the coupled one (measured 3.6-5.3 % low: the lines' damping, none estimated
    here, and the RAOs about the mean, as in (c); and the damping linearised at rest, the LF velocity 0.04 m/s
    against the current's 1.2 m/s); without the table's damping in its LF equation it was 43-69 % high."""
    waves = {"spectrum": "jonswap", "hs": 6.0, "tp": 10.0, "seed": 3, "n_components": 60,
             "frequency_range": [0.3, 1.4]}
    std = {}
    for route, extra in (("coupled", {}), ("uncoupled", {"coupling": "uncoupled", "uncoupled": {"lines": "dynamic"}})):
        path = hull_case(tmp_path, waves=waves, rope=ROPE, body={**_hydro(), "current": CURRENT_TABLE}, analysis={
            "duration": 600.0, "time_step": 0.2, "output_interval": 0.5, **extra})
        data = yaml.safe_load(path.read_text())
        data["environment"]["current"] = CURRENT
        path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
        ds = sc.run(sc.load_case(path))
        std[route] = np.asarray(ds["fairlead_tension"])[np.asarray(ds["time"]) > 200.0].std(axis=0)
    np.testing.assert_allclose(std["uncoupled"], std["coupled"], rtol=0.10)

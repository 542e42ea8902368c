"""A floating body with a hydrodynamic database, from a case file (issue 39): ``bodies.NAME.hydrodynamics`` gives
the statics its hydrostatics and the dynamics its added mass, radiation memory and wave loads.

The VolturnUS-S hull (tests/data/volturnus, WAMIT; its hydrostatics without the weight's moment, which seacable
adds from the mass and the centre of gravity 5 m below the reference point) on three light taut ropes, which the
reference leaves out (their stiffness, about 5 kN/m, is 2e-4 of the hull's inertia w^2 (M + A) in surge at this
frequency, and less in heave and pitch), with a
linear damping of 5-20 % of critical, in a 2 m regular wave of 0.85 rad/s (7.4 s) from 0 deg, ramped over 40 s.
Its steady surge, heave and pitch against the frequency domain with the kernel's A and B and the rigid body's
mass matrix about the reference point: within 0.5 % and 0.002 rad (measured 0.11-0.14 % and 1.3e-4 rad: the time
step's error, second order, tests/unit/hydro/test_cummins.py).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import seacable as sc
from seacable.errors import InputError
from seacable.hydro import frequency_response, ogilvie, read_wamit, retardation_kernel
from seacable.results import body_pose

ROOT = Path(__file__).parents[1] / "data" / "volturnus" / "IEA-15-240-RWT-UMaineSemi"
RHO, G = 1025.0, 9.80665
VOLUME = 20206.34889
DAMPING = np.diag([6e5, 6e5, 1.4e6, 1.4e9, 1.4e9, 6e8])
ZG = -5.0  # the centre of gravity 5 m below the reference point: its weight's moment m g 5 stiffens roll and pitch
OMEGA, HEIGHT = 0.85, 2.0


ROPE = {"diameter": 0.02, "mass_per_length": 0.5, "axial_stiffness": 1e6, "drag_normal": 0.0, "added_mass_normal": 0.0}
WAVES = {"height": HEIGHT, "period": 2 * math.pi / OMEGA}


def test_the_database_gives_the_statics_its_hydrostatics(tmp_path, hull_case):
    """The static heave: the ropes' pull down over C33 = rho g A_wp of the database (443 m^2), and no rotation."""
    case = sc.load_case(hull_case(tmp_path, waves=WAVES, rope=ROPE, analysis={"type": "system_static"}))
    system = case.system()
    body = system.bodies["hull"]
    db = read_wamit(ROOT, rho=RHO, g=G)
    k = np.asarray(body.hydrostatic_stiffness)
    assert k[2, 2] == pytest.approx(db.hydrostatics[2, 2], rel=1e-14)
    # the weight's moment added: -m g z_G in roll and pitch
    assert k[4, 4] == pytest.approx(db.hydrostatics[4, 4] - RHO * VOLUME * G * ZG, rel=1e-14)
    np.testing.assert_allclose(np.asarray(body.added_mass), db.added_mass_inf, rtol=1e-14)
    ds = sc.run(case)
    # the same body with the database's matrices given by hand: the same equilibrium, to round-off
    by_hand = sc.load_case(hull_case(tmp_path, waves=WAVES, rope=ROPE, analysis={"type": "system_static"}, body={
        "hydrodynamics": None, "hydrostatic_stiffness": k.tolist(), "added_mass": db.added_mass_inf.tolist()}))
    ref = sc.run(by_hand)
    for key in ("body_z", "body_roll", "body_pitch", "fairlead_tension"):
        np.testing.assert_allclose(np.asarray(ds[key]), np.asarray(ref[key]), rtol=1e-9, atol=1e-12)
    assert -0.05 < float(np.asarray(ds["body_z"]).reshape(-1)[0]) < 0.0  # three taut ropes pull it down a few cm


def test_a_regular_wave_from_the_case_moves_the_body_as_the_frequency_domain(tmp_path, hull_case):
    case = sc.load_case(hull_case(tmp_path, waves=WAVES, rope=ROPE))
    ds = sc.run(case)
    t = np.asarray(ds["time"])
    q = body_pose(ds).reshape(t.size, 6)
    period = 2 * math.pi / OMEGA
    window = t > t[-1] - 10 * period
    basis = np.column_stack([np.cos(OMEGA * t[window]), np.sin(OMEGA * t[window]), np.ones(window.sum())])
    coef = np.linalg.lstsq(basis, q[window], rcond=None)[0]
    h = (coef[0] + 1j * coef[1]) / (HEIGHT / 2)
    db = read_wamit(ROOT, rho=RHO, g=G)
    tk, kernel = retardation_kernel(db, 0.1, 60.0)
    kernel[-1] *= 0.5
    a, b = (m[0] for m in ogilvie(tk, kernel, db.added_mass_inf, OMEGA))
    stiffness = np.asarray(case.system().bodies["hull"].hydrostatic_stiffness)
    # the rigid body about the reference point (the centre of gravity ZG below it), the added mass left to the kernel
    rigid = case.system().bodies["hull"].model_copy(update={"added_mass": None}).mass_matrix()
    assert rigid[0, 4] == pytest.approx(RHO * VOLUME * ZG, rel=1e-12)  # surge-pitch: m z_G
    ref = frequency_response(rigid, a, b + DAMPING, stiffness, db.excitation_at(OMEGA, 0.0), OMEGA)
    for j in (0, 2, 4):
        assert abs(h[j]) == pytest.approx(abs(ref[j]), rel=0.005), (j, h[j], ref[j])
        assert abs(np.angle(h[j] / ref[j])) < 0.002, j
    # the mean drift D a^2 (the .12d diagonal at 0.85 rad/s, heading 0: 33 kN in surge, the ropes soft: metres) moves
    # the body's mean as the statics move it under that force given by hand, within 1 % of the move. The mean is
    # compared with the same run's without the drift: both carry the same second-order mean of the first-order
    # motion (the damping, in the body's axes, turning with its pitch: about 1 kN here, 3 % of the move).
    bare = sc.run(sc.load_case(hull_case(tmp_path, waves=WAVES, rope=ROPE, body={"hydrodynamics": {
        "file": str(ROOT), "kernel_length": 60.0, "ramp": 40.0, "drift": "none"}})))
    mean_bare = np.linalg.lstsq(basis, body_pose(bare).reshape(t.size, 6)[window], rcond=None)[0][2]
    drift = db.drift_at(OMEGA, 0.0) * (HEIGHT / 2) ** 2
    poses = []
    for force in (None, drift):
        body = None if force is None else {"external_force": force.tolist()}
        eq = sc.run(sc.load_case(hull_case(tmp_path, waves=WAVES, rope=ROPE, body=body,
                                           analysis={"type": "system_static"})))
        poses.append(np.array([float(eq[f"body_{k}"].values[0, 0]) for k in ("x", "y", "z", "roll", "pitch", "yaw")]))
    assert poses[1][0] - poses[0][0] > 5.0
    assert coef[2][0] - mean_bare[0] == pytest.approx(poses[1][0] - poses[0][0], rel=0.01)


def test_a_body_with_both_a_database_and_matrices_is_refused(tmp_path, hull_case):
    with pytest.raises(InputError, match=r"added_mass and hydrodynamics both given"):
        sc.load_case(hull_case(tmp_path, waves=WAVES, rope=ROPE, body={"added_mass": np.eye(6).tolist()}))
    with pytest.raises(InputError, match=r"WAMIT file '.*nothere.1' does not exist"):
        sc.load_case(hull_case(tmp_path, waves=WAVES, rope=ROPE, body={"hydrodynamics": {"file": "nothere"}},
                               analysis={"type": "system_static"}))


@pytest.mark.parametrize("changes, message", [
    # the memory cut at 20 s, where the VolturnUS-S kernel is still 3.4 % of its peak
    ({"body": {"hydrodynamics": {"file": str(ROOT), "kernel_length": 20.0}}},
     (r"bodies.hull.hydrodynamics.kernel_length: the radiation memory is cut at 20 s where it is still 3.4% of its "
      r"peak \(more than 2%\).*a kernel_length of 40 s or more")),
    # the centre of gravity 20 m above the water line: roll and pitch restoring -1.9e9 N m/rad, the ropes 6e6
    ({"body": {"center_of_gravity": [0.0, 0.0, 20.0]}},
     r"bodies.hull: the hydrostatic stiffness in roll is -1.868e\+09 N m/rad \(unstable.*so the body capsizes"),
    # a body without its own mass properties: the database holds the water's inertia only
    ({"body": {"volume": 0.0}}, r"bodies.hull: a body with hydrodynamics needs its displaced volume"),
    ({"body": {"inertia": [0.0, 0.0, 0.0]}},
     r"bodies.hull: a free body with hydrodynamics needs its mass \(kg\) and its three moments of inertia.*got mass "
     r"2.07115e\+07 kg and inertia \[0.0, 0.0, 0.0\] kg m\^2"),
    # a sea beyond the database's excitation (the extract stops at 1.45 rad/s)
    ({"waves": {"spectrum": "jonswap", "hs": 4.0, "tp": 10.0, "frequency_range": [0.3, 2.0]}},
     (r"bodies.hull.hydrodynamics: .*wave excitation is asked for at .* rad/s, outside its frequencies 0.05-1.45 "
      r"rad/s")),
])
def test_a_floating_body_that_cannot_run_is_refused_before_the_time_loop(tmp_path, hull_case, changes, message):
    """One clear message each, from validate as from run (both prepare the run: tests/unit/test_check_run_parity.py)."""
    waves = changes.pop("waves", WAVES)
    with pytest.raises(InputError, match=message):  # when the case is read, or when its run is prepared
        sc.check(sc.load_case(hull_case(tmp_path, waves=waves, rope=ROPE, analysis={"duration": 10.0}, **changes)))

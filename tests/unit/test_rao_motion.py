"""Fairleads moved by a platform's RAOs in the case's waves (issue 20): the motion in a regular wave against its
closed form, the phase referred to the platform's position, the mean offset as the static start, the fairlead
of a run following the RAO motion in an irregular sea, and the refusals."""

from __future__ import annotations

import math

import numpy as np
import pytest

import seacable as sc
from seacable.errors import InputError
from seacable.mooring.motion import RAOMotion, bind, rotation_matrix, sea_of
from seacable.mooring.solver import Water
from seacable.raos import rao_motion, read_rao_csv
from seacable.waves import wave_number

#: A made-up RAO table, flat in frequency and heading: amplitude [m/m, rad/m] and phase [rad] of each DOF.
AMPLITUDE = (0.8, 0.3, 0.6, 0.010, 0.020, 0.005)
PHASE = (0.4, -1.1, 0.2, 1.3, -0.6, 2.0)
DEPTH = 320.0


def _csv(tmp_path, frequencies=(0.1, 0.5, 1.0, 2.0, 3.0), headings=(0.0, math.pi / 2, math.pi, 1.5 * math.pi)):
    rows = ["frequency,heading,dof,amplitude,phase"]
    rows += [f"{w},{b},{j + 1},{AMPLITUDE[j]},{PHASE[j]}" for w in frequencies for b in headings for j in range(6)]
    path = tmp_path / "raos.csv"
    path.write_text("\n".join(rows) + "\n")
    return path


def _water(**waves):
    return Water(density=1025.0, gravity=9.80665, depth=DEPTH, **waves)


def test_a_regular_wave_moves_each_fairlead_rigidly_by_the_rao_about_the_mean_offset(tmp_path):
    """H = 2 m, T = 10 s, heading 0, phase 0.3 rad: each DOF is q_j = mean_j + |X_j| (H/2) cos(w t - k x_r - 0.3 +
    phase_j) (elevation at the reference point x_r: a cos(k x_r - w t + 0.3)), and a fairlead at p moves to
    r + d + R(angles)(p - r). Closed form against the motion, positions and the velocities by the time derivative."""
    mean = (5.0, -2.0, 0.3, 0.01, -0.02, 0.05)
    ref = (30.0, 10.0, 0.0)
    motion = RAOMotion(file=str(_csv(tmp_path)), reference=ref, mean_offset=mean)
    water = _water(wave_height=2.0, wave_period=10.0, wave_phase=0.3)
    base = np.array([[25.0, 10.0, -15.0], [33.0, 14.0, -15.0]])
    fn = bind(motion, base, 60.0, sea=sea_of(water))
    t = np.linspace(0.0, 60.0, 241)
    x, v, _ = fn(t)
    w = 2 * math.pi / 10.0
    k = float(wave_number(10.0, DEPTH, 9.80665))
    q = np.array([mean[j] + AMPLITUDE[j] * np.cos(w * t - k * ref[0] - 0.3 + PHASE[j]) for j in range(6)]).T
    R = rotation_matrix(q[:, 3], q[:, 4], q[:, 5])
    expected = np.asarray(ref) + q[:, None, :3] + np.einsum("tij,kj->tki", R, base - np.asarray(ref))
    np.testing.assert_allclose(x, expected, rtol=0, atol=1e-12)  # the same formula: round-off only
    # velocity: the time derivative of the closed form (central differences of 1e-4 s: error w^3 h^2 |x| ~ 1e-9)
    h = 1e-4
    dq = np.array([-AMPLITUDE[j] * w * np.sin(w * t - k * ref[0] - 0.3 + PHASE[j]) for j in range(6)]).T
    qp, qm = q + h * dq, q - h * dq
    xp = np.asarray(ref) + qp[:, None, :3] + np.einsum("tij,kj->tki", rotation_matrix(*qp[:, 3:].T), base - ref)
    xm = np.asarray(ref) + qm[:, None, :3] + np.einsum("tij,kj->tki", rotation_matrix(*qm[:, 3:].T), base - ref)
    np.testing.assert_allclose(v, (xp - xm) / (2 * h), rtol=0, atol=1e-7)


def test_the_rao_phase_is_referred_to_the_wave_at_the_platform(tmp_path):
    """Moving the platform (its reference and its fairleads) one wavelength down-wave leaves its motion as it
    is; half a wavelength reverses the wave part (the elevation there is the opposite)."""
    water = _water(wave_height=3.0, wave_period=9.0, wave_heading=math.pi / 2)
    lam = 2 * math.pi / float(wave_number(9.0, DEPTH, 9.80665))
    t = np.linspace(0.0, 30.0, 3001)

    def heave(y):
        motion = RAOMotion(file=str(_csv(tmp_path)), reference=(0.0, y, 0.0))
        return bind(motion, np.array([[0.0, y, 0.0]]), 30.0, sea=sea_of(water))(t)[0][:, 0, 2]  # at the reference

    amplitude = 1.5 * AMPLITUDE[2]
    # the peak of a cosine sampled every 0.01 s: within 1 - cos(pi 0.01 / 9) = 6e-6 of its amplitude
    assert np.max(np.abs(heave(0.0))) == pytest.approx(amplitude, rel=1e-5)
    np.testing.assert_allclose(heave(lam), heave(0.0), rtol=0, atol=1e-9 * amplitude)
    np.testing.assert_allclose(heave(lam / 2), -heave(0.0), rtol=0, atol=1e-9 * amplitude)


def _line_case(tmp_path, motion, waves, duration=20.0):
    return sc.parse_case({"line_types": {"c": {"diameter": 0.09, "mass_per_length": 77.7066,
                                               "weight_in_water": 698.094, "axial_stiffness": 384.243e6}},
                          "line": {"line_type": "c", "length": 902.2},
                          "environment": {"depth": DEPTH, "waves": waves},
                          "analysis": {"type": "mooring_dynamic", "fairlead": [848.67, -70.0], "n_elements": 20,
                                       "duration": duration, "time_step": 0.1, "output_interval": 0.5,
                                       "motion": motion}})


SEA = {"spectrum": "jonswap", "hs": 6.0, "tp": 11.0, "seed": 3, "n_components": 80}


def test_a_run_follows_the_rao_motion_in_an_irregular_sea_from_a_static_start_at_the_mean_offset(tmp_path):
    """The fairlead of a run is where the RAO motion in the case's irregular sea puts it (rao_motion on the same
    sea, by the motion's own formula), and the run starts from the static equilibrium with the fairlead at the
    mean offset: the shape and element tensions at t = 0 are those of a mooring_static case whose fairlead is moved
    by it (to the statics' tolerance)."""
    mean = (-12.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    ref = (853.87, 0.0, 0.0)
    motion = {"type": "rao", "file": str(_csv(tmp_path)), "reference": list(ref), "mean_offset": list(mean),
              "ramp": 5.0}
    case = _line_case(tmp_path, motion, SEA)
    ds = sc.run(case)
    t = ds.time.values
    sea = case.environment.waves.components(DEPTH, 9.81)
    q = rao_motion(read_rao_csv(_csv(tmp_path)), sea, t, at=ref[:2])
    ramp = np.where(t < 5.0, 0.5 * (1 - np.cos(math.pi * t / 5.0)), 1.0)
    arm = np.array([848.67, 0.0, -70.0]) - ref
    R = rotation_matrix(*(q[3:] * ramp))
    fair = np.asarray(ref)[:, None] + np.asarray(mean[:3])[:, None] + q[:3] * ramp + np.einsum("tij,j->it", R, arm)
    end = ds.sizes["node"] - 1
    for axis, name in enumerate("xyz"):
        np.testing.assert_allclose(ds[name].values[:, end], fair[axis], rtol=0, atol=1e-9)  # the same motion
    assert np.ptp(ds.x.values[:, end]) > 1.0  # the sea moves it by metres: the test is not of a still fairlead
    static = sc.run(sc.parse_case({**_line_case(tmp_path, None, None).model_dump(mode="json"),
                                   "analysis": {"type": "mooring_static", "fairlead": [848.67 - 12.0, -70.0],
                                                "n_elements": 20}}))
    # the start is the static profile (the fairlead tension at t = 0 is not: the sea's and the ramp's loads act)
    for name in "xyz":
        np.testing.assert_allclose(ds[name].values[0], static[name].values, rtol=0, atol=1e-6)  # statics' tolerance
    assert float(ds.segment_tension[0, -1]) == pytest.approx(float(static.segment_tension[-1]), rel=1e-6)


def test_rao_motions_are_refused_without_waves_or_outside_their_table(tmp_path):
    """Each refused by seacable.check (what `validate` runs) before any time step: no waves, a table that does
    not cover the sea's frequencies, a missing file."""
    with pytest.raises(InputError, match="environment has none"):
        sc.check(_line_case(tmp_path, {"type": "rao", "file": str(_csv(tmp_path))}, None))
    narrow = _csv(tmp_path, frequencies=(0.6, 0.7))
    with pytest.raises(InputError, match=r"covers 0.6-0.7 rad/s.*outside it"):
        sc.check(_line_case(tmp_path, {"type": "rao", "file": str(narrow)}, SEA))
    with pytest.raises(InputError, match="does not exist"):
        sc.check(_line_case(tmp_path, {"type": "rao", "file": str(tmp_path / "none.4")}, SEA))


def test_components_outside_the_table_are_left_out_and_said_so(tmp_path):
    """A sea wider than the table (its components outside hold 0.08 % < 0.1 % of the variance here): they are
    left out of the motion, with a warning naming how many, their band and their share; the motion is that of
    the components inside (rao_motion drops the same ones)."""
    sea = {**SEA, "frequency_range": [0.02, 4.0]}
    table = _csv(tmp_path, frequencies=(0.05, 0.5, 1.0, 3.0))
    case = _line_case(tmp_path, {"type": "rao", "file": str(table), "reference": [853.87, 0.0, 0.0]}, sea)
    with pytest.warns(sc.SeacableWarning, match=r"covers 0.05-3 rad/s; \d+ components of the sea .*% of its variance\) "
                                                r"lie outside"):
        sc.check(case)
    components = case.environment.waves.components(DEPTH, 9.80665)
    from seacable.raos import outside_table

    outside, share = outside_table(read_rao_csv(table), components)
    assert outside.sum() > 0 and 0 < share < 1e-3


def test_the_motions_sines_and_cosines_on_a_step_grid_are_those_of_numpy_to_the_times_rounding():
    """RAOResponse and the sea grid evaluate cos(w t) and sin(w t) of times a constant step apart by rotating the
    last row by w h (fresh every 32 rows and where the step changes): against numpy's, on a 3-hour run's step
    grid, within 31 w ulp(t) (the step's rounding accumulated over the rotations, the stated bound), and exactly
    at times with no common step."""
    from seacable.seastate import cos_sin

    w = np.linspace(0.2, 2.0, 50)
    grid = 10000.0 + 0.1 * np.arange(1, 4001)
    grid[2000:] += 0.05  # the step changes once
    rand = np.sort(np.random.default_rng(3).uniform(0.0, 10800.0, 500))
    for t in (grid, rand):
        ref = np.concatenate((np.cos(np.multiply.outer(t, w)), np.sin(np.multiply.outer(t, w))), axis=1)
        bound = 31 * w.max() * np.spacing(t.max()) if t is grid else 0.0
        assert np.max(np.abs(cos_sin(w, t) - ref)) <= bound + 1e-15

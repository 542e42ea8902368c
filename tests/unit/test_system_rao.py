"""A mooring system whose platform follows its RAOs in an irregular sea (issue 20): the system's lines-only runs
take the mooring model's compiled time loop, which converges to the coupled solver's answer; the platform's
motion and its static start at the mean offset; a free body in an irregular sea passes the checks."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
import seacable.system.dynamics as D
from seacable.errors import InputError, SeacableWarning
from seacable.raos import rao_motion, read_rao_csv
from seacable.results import body_pose
from seacable.system.dynamics.loop import _simulate_lines

from .test_rao_motion import _csv

SPREAD = Path(__file__).parents[2] / "examples" / "spread_mooring.yaml"
SEA = {"spectrum": "jonswap", "hs": 6.0, "tp": 11.0, "seed": 1, "n_components": 100}


def _spread(analysis, waves, kind="prescribed"):
    data = yaml.safe_load(SPREAD.read_text())
    data["bodies"]["buoy"]["kind"] = kind
    if kind != "free":
        data["bodies"]["buoy"].pop("external_force")
    data["environment"]["waves"] = waves
    data["analysis"] = {"type": "system_dynamic", "output_interval": 0.5, "n_elements": 20, **analysis}
    return sc.parse_case(data)


def test_a_lines_only_system_runs_as_in_the_coupled_solver(monkeypatch):
    """A prescribed buoy (surge, heave, pitch at 10 s) in calm water: the mooring model's compiled loop (what
    runs a system in an irregular sea, :func:`seacable.system.dynamics.loop._simulate_lines`) and the coupled system
    solver take the same Newmark steps of the same equations: node positions agree to 1e-6 m and tensions to
    1e-6 of the mean fairlead tension over 50 steps (each step converged to the Newton tolerance: measured
    1.4e-8 m; the chains' axial ringing amplifies such differences over longer runs)."""
    motion = {"buoy": {"type": "platform", "amplitude": [1.0, 0, 0.5, 0, 0.01, 0], "period": 10.0, "ramp": 5.0}}
    case = _spread({"duration": 5.0, "time_step": 0.1, "body_motions": motion}, None)
    setup = D.prepare_system_dynamic(case)
    assert D.lines_only(setup.fe)
    coupled = sc.run(case)
    a = case.analysis
    start = D.start_state(setup.start_fe, a, case.environment)
    run = _simulate_lines(setup.fe, start, a.duration, a.time_step, a.output_interval, analysis=a,
                            tol=min(a.tolerance * 10, 1e-4), max_iter=a.max_iterations)
    fast = D.system_result(setup.fe, run, case=case)
    for k in "xyz":
        np.testing.assert_allclose(fast[k].values, coupled[k].values, rtol=0, atol=1e-6)
    np.testing.assert_allclose(fast.fairlead_tension.values, coupled.fairlead_tension.values, rtol=0,
                               atol=1e-6 * float(coupled.fairlead_tension.mean()))
    assert np.ptp(coupled.fairlead_tension.values) > 1e3  # the motion loads the lines: not a still comparison


def test_a_platform_follows_its_raos_in_an_irregular_sea_about_a_mean_offset(tmp_path):
    """The buoy's stored pose is the mean offset plus the RAO response to the case's JONSWAP sea (rao_motion on
    the same sea, referred to the buoy's position, ramped over 10 s); the run starts from the statics with the
    buoy at the mean offset (the fairleads 8 m down-wave of where the case puts them)."""
    mean = [8.0, -1.0, 0.0, 0.0, 0.0, 0.02]
    motion = {"buoy": {"type": "rao", "file": str(_csv(tmp_path)), "mean_offset": mean, "ramp": 10.0}}
    case = _spread({"duration": 20.0, "time_step": 0.1, "body_motions": motion}, SEA)
    ds = sc.run(case)
    t = ds.time.values
    q = rao_motion(read_rao_csv(_csv(tmp_path)), case.environment.waves.components(150.0, 9.81), t).T
    ramp = np.where(t < 10.0, 0.5 * (1 - np.cos(math.pi * t / 10.0)), 1.0)[:, None]
    np.testing.assert_allclose(body_pose(ds)[:, 0], np.asarray(mean) + ramp * q, rtol=0, atol=1e-12)
    fair = np.array([-6.0, 0.0, -10.0])  # fairlead1 on the buoy, turned by the mean yaw and moved by the offset
    c, s = math.cos(0.02), math.sin(0.02)
    expected = np.array([c * fair[0] - s * fair[1] + 8.0, s * fair[0] + c * fair[1] - 1.0, fair[2]])
    line1 = list(ds.line.values).index("line1")
    end = int(np.max(np.flatnonzero(np.isfinite(ds.x.values[0, line1]))))  # end B: the fairlead
    np.testing.assert_allclose([float(ds[k][0, line1, end]) for k in "xyz"], expected, rtol=0, atol=1e-9)
    assert float(ds.fairlead_tension.max()) < 7.3e6  # a sane run: below the chain's breaking load


def test_an_irregular_sea_loads_the_lines_of_a_free_body_too():
    """A free buoy couples the lines to a body: the coupled solver runs it in an irregular sea too (its lines given
    the sea's kinematics on a grid, tests/validation/test_system_dynamics_irregular_sea.py), refused before. The
    checks (`validate`) pass, and say that the waves act on the lines only (the buoy has no wave loads)."""
    case = _spread({"duration": 10.0}, SEA, kind="free")
    with pytest.warns(SeacableWarning, match="waves act on the lines only"):
        sc.check(case)
    with pytest.warns(SeacableWarning, match="waves act on the lines only"):
        setup = D.prepare_system_dynamic(case)
    assert not D.lines_only(setup.fe)  # the coupled solver's


def test_a_damaged_condition_leaves_its_lines_out_from_the_start():
    """analysis.damaged_lines runs the system without them: the same result, bit for bit, as the case file with
    the line deleted (the report's ALS condition); an unknown line is refused by name."""
    motion = {"buoy": {"type": "platform", "amplitude": [1.0, 0, 0, 0, 0, 0], "period": 10.0, "ramp": 5.0}}
    damaged = _spread({"duration": 3.0, "body_motions": motion, "damaged_lines": ["line1"]}, None)
    data = yaml.safe_load(SPREAD.read_text())
    data["bodies"]["buoy"]["kind"] = "prescribed"
    data["bodies"]["buoy"].pop("external_force")
    del data["lines"]["line1"], data["points"]["anchor1"], data["points"]["fairlead1"]
    data["analysis"] = {"type": "system_dynamic", "output_interval": 0.5, "n_elements": 20, "duration": 3.0,
                        "body_motions": motion}
    a, b = sc.run(damaged), sc.run(sc.parse_case(data))
    assert list(a.line.values) == ["line2", "line3"]
    np.testing.assert_array_equal(a.fairlead_tension.values, b.fairlead_tension.values)
    with pytest.raises(InputError, match=r"damaged_lines\[0\]: line 'line9' is not defined"):
        _spread({"duration": 3.0, "body_motions": motion, "damaged_lines": ["line9"]}, None)


def test_the_mean_offset_is_the_bodys_static_equilibrium_under_its_steady_loads(tmp_path):
    """mean_offset 'equilibrium': the buoy, made free, in static equilibrium under its 500 kN steady load with the
    run's lines: the pose system_static finds for the same system (examples/spread_mooring.yaml), to the statics'
    tolerance; with line1 left out (damaged), the damaged equilibrium. A single line's fairlead motion has no
    body to take it from: refused."""
    data = yaml.safe_load(SPREAD.read_text())
    static = sc.run(sc.parse_case(data))
    body = data["bodies"]["buoy"]
    data["bodies"]["buoy"] = {**body, "kind": "prescribed"}
    data["environment"]["waves"] = SEA
    motion = {"buoy": {"type": "rao", "file": str(_csv(tmp_path)), "mean_offset": "equilibrium"}}
    for condition, damaged in (("intact", []), ("damaged", ["line1"])):
        data["analysis"] = {"type": "system_dynamic", "duration": 1.0, "n_elements": 20, "body_motions": motion,
                            "damaged_lines": damaged}
        setup = D.prepare_system_dynamic(sc.parse_case(data))
        got = setup.analysis.body_motions["buoy"].mean_offset
        want = [float(static[f"body_{k}"].sel(condition=condition, body="buoy"))
                for k in ("x", "y", "z", "roll", "pitch", "yaw")]
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-6)  # the statics' tolerance (1e-8 of the loads)
    assert abs(want[0]) > 1.0  # the load moves it metres
    line = {"type": "rao", "file": str(_csv(tmp_path)), "mean_offset": "equilibrium"}
    from .test_rao_motion import SEA as LINE_SEA
    from .test_rao_motion import _line_case

    with pytest.raises(InputError, match="mean_offset 'equilibrium' is the static position of a body"):
        sc.check(_line_case(tmp_path, line, LINE_SEA))


def test_a_bad_rao_file_is_refused_before_the_mean_offset_is_solved(tmp_path, monkeypatch):
    """A bad RAO file behind ``mean_offset: equilibrium`` is refused as it is read, before the statics of the
    mean offset are solved (on a fresh machine their kernels compiled first: tens of seconds before the message)."""
    import seacable.system.statics as S

    def solved(*args, **kwargs):
        raise AssertionError("the mean offset's statics were solved before the RAO file was read")

    monkeypatch.setattr(S, "solve_equilibrium", solved)
    bad = tmp_path / "raos.csv"
    bad.write_text("frequency,heading,dof,amplitude,phase\n0.5,0.0,1,1.0,0.0\n0.6,180.0,1,1.0,0.0\n")
    data = yaml.safe_load(SPREAD.read_text())
    data["bodies"]["buoy"]["kind"] = "prescribed"
    data["environment"]["waves"] = SEA
    data["analysis"] = {"type": "system_dynamic", "duration": 1.0, "n_elements": 20,
                        "body_motions": {"buoy": {"type": "rao", "file": str(bad), "mean_offset": "equilibrium"}}}
    with pytest.raises(InputError, match="heading = 180 rad is beyond 2 pi: it looks like degrees"):
        D.prepare_system_dynamic(sc.parse_case(data))

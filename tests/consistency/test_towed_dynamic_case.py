"""The towed_dynamic analysis end to end: case files, the dataset, NetCDF, CLI, interrupts."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import seacable as sc
from seacable.cli import main
from seacable.errors import InputError
from seacable.results import read_netcdf
from seacable.towed.solver import cable_parameters, steady_tow

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def turn():
    return sc.run(sc.load_case(EXAMPLES / "paper000_turn.yaml"))


def test_dataset_layout_and_units(turn):
    assert dict(turn.sizes) == {"time": 101, "node": 7}
    assert turn.s.values[0] == 0.0 and turn.s.values[-1] == pytest.approx(170.0)
    for name, unit in (("x", "m"), ("z", "m"), ("tension", "N"), ("shear_n", "N"), ("curvature_b", "m-1"),
                       ("velocity_x", "m s-1"), ("top_tension", "N")):
        assert turn[name].attrs["units"] == unit
    # node 0 is the free end (zero tension), the last node is at the vessel, at the surface
    np.testing.assert_array_equal(turn.tension.isel(node=0), 0.0)
    np.testing.assert_allclose(turn.z.isel(node=-1), 0.0, atol=1e-12)
    np.testing.assert_allclose(turn.top_tension, turn.tension.isel(node=-1))
    # the top node's velocity is the vessel's: 1 m/s over the ground (eq. (15))
    speed = np.hypot(turn.velocity_x.isel(node=-1), turn.velocity_y.isel(node=-1))
    np.testing.assert_allclose(speed, 1.0, atol=1e-8)


def test_cli_run_writes_netcdf_and_plots(tmp_path, capsys):
    out = tmp_path / "steady.nc"
    assert main(["run", str(EXAMPLES / "paper000_steady_tow.yaml"), "-o", str(out)]) == 0
    ds = read_netcdf(out)
    assert ds.attrs["analysis"] == "towed_dynamic"
    assert (tmp_path / "steady_plan_view.png").stat().st_size > 10_000
    # the steady tow of Table 2 (no tangential drag) holds its 1171 N top tension (0.03 % from the
    # paper's 1171.15 on 7 nodes)
    np.testing.assert_allclose(ds.top_tension, 1171.15, rtol=5e-4)
    assert "100 %" in capsys.readouterr().err


def test_interrupted_run_keeps_what_it_computed(monkeypatch):
    calls = {"n": 0}

    def stop_after_three(t, duration):
        calls["n"] += 1
        if calls["n"] == 3:
            raise KeyboardInterrupt

    case = sc.load_case(EXAMPLES / "paper000_turn.yaml")
    ds = sc.run(case, progress=stop_after_three)
    assert ds.attrs["interrupted"] == 1
    assert ds.sizes["time"] == 4  # t = 0 and the three outputs reached
    assert float(ds.time[-1]) == 3.0


def test_vessel_table_is_read_beside_the_case_file(tmp_path):
    t = np.linspace(0.0, 30.0, 31)
    np.savetxt(tmp_path / "track.csv", np.c_[t, t * 1.0, 0.0 * t], delimiter=",", header="time,x,y",
               comments="")
    text = (EXAMPLES / "paper000_steady_tow.yaml").read_text().replace(
        "vessel: {type: straight, speed: 1.0, heading: 0.0}", "vessel: {type: table, file: track.csv, kind: position}")
    (tmp_path / "case.yaml").write_text(text)
    ds = sc.run(sc.load_case(tmp_path / "case.yaml"))
    # a straight track at 1 m/s given as a table is the straight case (spline of a linear track)
    ref = sc.run(sc.load_case(EXAMPLES / "paper000_steady_tow.yaml"))
    np.testing.assert_allclose(ds.top_tension, ref.top_tension, rtol=1e-8)


def test_body_without_mass_is_a_case_error(tmp_path):
    text = (EXAMPLES / "paper000_turn.yaml").read_text().replace(
        "  n_nodes: 7", "  n_nodes: 7\n  body: {weight_in_water: 500.0, drag_area: 0.2}")
    (tmp_path / "bad.yaml").write_text(text)
    with pytest.raises(InputError, match=r"body.mass must be > 0 kg"):
        sc.load_case(tmp_path / "bad.yaml")


def test_depth_profile_current():
    par = cable_parameters(170.0, 25, 2.7904, 17.7, 0.035, axial_stiffness=4.2333e5, bending_stiffness=32.41,
                           drag_normal=1.5, drag_tangential=0.0)
    uniform = steady_tow(par, 25, [1.0, 0.0, 0.0], sc.Current.uniform(-1.0))
    flat = steady_tow(par, 25, [1.0, 0.0, 0.0], sc.Current.profile([0.0, 200.0], [-1.0, -1.0]))
    # a constant profile is the uniform current (to the Newton tolerance)
    np.testing.assert_allclose(flat[:, 0], uniform[:, 0], rtol=1e-9)
    # a current that weakens with depth: the deep part sees less relative flow, hangs steeper, and
    # the local angle still obeys the critical-angle balance at the local relative speed
    sheared = steady_tow(par, 25, [1.0, 0.0, 0.0], sc.Current.profile([0.0, 100.0], [-1.0, 0.0]))
    assert -sheared[0, 7] > -uniform[0, 7]
    from seacable.statics.towed import critical_angle
    from seacable.towed.equations import integrate_positions

    pos = np.zeros((25, 3))
    integrate_positions(sheared, np.zeros(3), par, pos)
    u_rel = 1.0 + np.interp(-pos[0, 2], [0.0, 100.0], [1.0, 0.0])
    # free end: T = 0 there, so its angle is the critical angle at the local flow (0.3 deg: the
    # box scheme's average over the last 7 m of a curving cable)
    assert math.degrees(-sheared[0, 7]) == pytest.approx(math.degrees(critical_angle(17.7, 0.035, u_rel, 1.5)),
                                                         abs=0.3)

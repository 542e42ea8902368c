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


def test_interrupted_towline_run_keeps_what_it_computed():
    model = TowlineModel(n_elements=5, length=50.0, diameter=0.05, mass_per_length=1.725, axial_stiffness=1e6,
                         held_tow_point_height=2.0)
    tug = np.array([0.0, 0.0, 2.0])

    def still(t):
        t = np.atleast_1d(t)
        return np.broadcast_to(tug, (t.size, 3)).copy(), np.zeros((t.size, 3))

    def progress(t, duration):
        if t >= 2.0:
            raise KeyboardInterrupt

    run = simulate(model, still, 10.0, 1.0, initial_state(model, tug, start="dropped", drop_height=1.0),
                   progress=progress)
    assert run.interrupted and run.time[-1] == pytest.approx(2.0) and run.nodes.shape[0] == 3


def test_cli_runs_a_towline_case(tmp_path):
    data = _data()
    data["analysis"].update(duration=20.0)
    f = tmp_path / "tow.yaml"
    f.write_text(yaml.safe_dump(data))
    out = tmp_path / "tow.nc"
    assert main(["run", str(f), "-o", str(out)]) == 0
    ds = sc.read_netcdf(out)
    assert ds.attrs["analysis"] == "towline_dynamic" and ds.sizes["node"] == 12
    assert main(["animate", str(out), "--max-frames", "3"]) == 0
    assert (tmp_path / "tow_tow.gif").stat().st_size > 0

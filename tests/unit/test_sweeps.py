"""Sweeps: sweep files, parameter paths, the Dask engine, failures, resuming, the summary.

The engine tests run cheap laying cases (5 m segments, 100 s) so that a dozen cases take seconds.
Results of the same case are compared exactly: the same code on the same input is deterministic,
whether it runs in this process or in a worker process.
"""

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.cli import main
from seacable.errors import CaseFileError, InputError
from seacable.results import open_netcdf
from seacable.sweeps import Sweep, load_sweep, parse_path, run_case
from seacable.sweeps.engine import summary_table

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

BASE = {
    "name": "lay",
    "line_types": {"cable": {"diameter": 0.0225, "mass_per_length": 0.867, "weight_in_water": 4.49,
                             "drag_normal": 1.85, "drag_tangential": 0.0, "added_mass_normal": 1.0}},
    "line": {"line_type": "cable", "length": 3000.0},
    "environment": {"water_density": 1030.0, "depth": 50.0},
    "analysis": {"type": "laying_dynamic", "ship": {"speed": 2.0}, "payout": {"type": "slack", "slack": 0.05},
                 "duration": 100.0, "segment_length": 5.0, "output_interval": 2.0, "initial_angle": 0.3},
}
SPEEDS = [0.75, 1.0, 1.5, 2.0, 2.5, 3.0]
SLACKS = [0.03, 0.05]   # 12 cases


def write_sweep(folder: Path, **spec) -> Path:
    path = folder / "sweep.yaml"
    path.write_text(yaml.safe_dump({"name": "t", "base": BASE, **spec}, sort_keys=False), encoding="utf-8")
    return path


def grid_sweep():
    return Sweep(BASE, grid={"analysis.ship.speed": SPEEDS, "analysis.payout.slack": SLACKS}, name="t")


# --- parameter paths ---------------------------------------------------------------------------

def test_parse_path_forms():
    assert parse_path("analysis.ship.speed") == ("analysis", "ship", "speed")
    assert parse_path("line.segments[1].length") == ("line", "segments", 1, "length")
    assert parse_path("line.segments.1.length") == ("line", "segments", 1, "length")
    for bad in ("", "a..b", ".a", "a.", "[0].a", "a[x]"):
        with pytest.raises(InputError, match="not a key path"):
            parse_path(bad)


def test_grid_is_the_product_last_parameter_fastest():
    s = grid_sweep()
    assert len(s) == 12
    cases = s.cases()
    assert [c.values for c in cases[:3]] == [(0.75, 0.03), (0.75, 0.05), (1.0, 0.03)]
    assert cases[3].case.analysis.ship.speed == 1.0 and cases[3].case.analysis.payout.slack == 0.05
    assert [c.name for c in cases[:2]] == ["t_0000", "t_0001"]
    # the base is not changed by the sweep
    assert BASE["analysis"]["ship"]["speed"] == 2.0


def test_a_table_with_a_grid_runs_each_row_at_every_combination(tmp_path):
    """Sea states x seeds, say: the table's rows (its columns together) each at every value of the grid, the
    grid fastest; the table written in the file or as a CSV gives the same cases."""
    (tmp_path / "rows.csv").write_text("analysis.ship.speed,analysis.payout.slack\n0.75,0.03\n1.5,0.05\n")
    inline = sc.load_sweep(write_sweep(tmp_path, table={"analysis.ship.speed": [0.75, 1.5],
                                                        "analysis.payout.slack": [0.03, 0.05]},
                                       grid={"analysis.duration": [10.0, 20.0, 30.0]}))
    from_csv = sc.load_sweep(write_sweep(tmp_path, table="rows.csv", grid={"analysis.duration": [10.0, 20.0, 30.0]}))
    for s in (inline, from_csv):
        assert s.kind == "table x grid" and len(s) == 6
        assert s.parameters == ("analysis.ship.speed", "analysis.payout.slack", "analysis.duration")
        assert [c.values for c in s.cases()] == [(0.75, 0.03, 10.0), (0.75, 0.03, 20.0), (0.75, 0.03, 30.0),
                                                (1.5, 0.05, 10.0), (1.5, 0.05, 20.0), (1.5, 0.05, 30.0)]
        assert s.cases()[4].case.analysis.ship.speed == 1.5 and s.cases()[4].case.analysis.duration == 20.0


def test_range_values():
    s = Sweep(BASE, grid={"analysis.ship.speed": sc.Range(start=0.75, stop=5.0, step=0.25)})
    values = [c.values[0] for c in s.cases()]
    assert len(values) == 18 and values[0] == 0.75 and values[-1] == pytest.approx(5.0, abs=1e-12)
    assert sc.Range(start=1.0, stop=2.0, num=3).values() == [1.0, 1.5, 2.0]
    with pytest.raises(InputError, match="exactly one of 'step' or 'num'"):
        sc.Range(start=0.0, stop=1.0)
    with pytest.raises(InputError, match="does not lead from start"):
        sc.Range(start=0.0, stop=1.0, step=-0.1)


def test_paths_absent_from_the_base_but_keys_of_the_case():
    # environment.current is not in the base: its default is swept
    s = Sweep(BASE, grid={"environment.current.speed": [0.0, 0.5], "line_types.cable.drag_normal": [1.2]})
    case = s.cases()[1].case
    assert case.environment.current.speed == 0.5
    assert case.line.segments[0].line_type.drag_normal == 1.2


@pytest.mark.parametrize("path, hint", [
    ("analysis.ship.sped", "Did you mean 'analysis.ship.speed'?"),
    ("analysis.shp.speed", "Did you mean 'analysis.ship.speed'?"),
    ("enviroment.depth", "Did you mean 'environment.depth'?"),
    ("vessel.speed", "'analysis.ship.speed'"),
    ("analysis.ship.speed.knots", "is a value (2.0), not a mapping"),
    ("line_types.cable.diamter", "Did you mean 'line_types.cable.diameter'?"),
])
def test_unknown_path_fails_before_anything_runs(tmp_path, path, hint):
    spec = write_sweep(tmp_path, grid={path: [1.0, 2.0]})
    with pytest.raises(CaseFileError) as info:
        sc.sweep(spec, tmp_path / "out")
    message = str(info.value)
    assert f"parameter '{path}' is not a key path of the case" in message and hint in message
    assert not (tmp_path / "out").exists()        # nothing ran, nothing written
    # the command line: one message, exit status 2
    assert main(["sweep", str(spec), "-o", str(tmp_path / "out")]) == 2
    assert not (tmp_path / "out").exists()


def test_sweep_file_errors(tmp_path):
    with pytest.raises(CaseFileError, match="needs 'grid'.*'table'.*or both"):
        sc.load_sweep(write_sweep(tmp_path, name="no_cases"))
    with pytest.raises(CaseFileError, match="analysis.ship.speed is in both the grid and the table"):
        sc.load_sweep(write_sweep(tmp_path, grid={"analysis.ship.speed": [1.0]},
                                  table={"analysis.ship.speed": [2.0]}))
    with pytest.raises(CaseFileError, match=r"columns have different lengths \[1, 2\]"):
        sc.load_sweep(write_sweep(tmp_path, table={"analysis.ship.speed": [2.0],
                                                   "analysis.payout.slack": [0.03, 0.05]}))
    with pytest.raises(CaseFileError, match="unknown key 'gird'. Did you mean 'grid'"):
        sc.load_sweep(write_sweep(tmp_path, gird={"analysis.ship.speed": [1.0]}))
    with pytest.raises(CaseFileError, match="has no values"):
        sc.load_sweep(write_sweep(tmp_path, grid={"analysis.ship.speed": []}))
    with pytest.raises(CaseFileError, match="table '.*cases.csv' does not exist"):
        sc.load_sweep(write_sweep(tmp_path, table="cases.csv"))
    (tmp_path / "cases.csv").write_text("analysis.ship.speed,analysis.payout.slack\n1.0\n")
    with pytest.raises(CaseFileError, match="line 2 has 1 values for 2 columns"):
        sc.load_sweep(write_sweep(tmp_path, table="cases.csv"))
    with pytest.raises(CaseFileError, match="does not exist"):
        sc.load_sweep(tmp_path / "nope.yaml")


def test_every_case_invalid_is_an_error():
    with pytest.raises(InputError, match="no case of the sweep is valid; case 0: .*must be >= 0 m/s"):
        Sweep(BASE, grid={"analysis.ship.speed": [-1.0, -2.0]}).cases()


def test_case_key_is_the_full_case():
    s = Sweep(BASE, grid={"analysis.ship.speed": [1.0, 1.0, 2.0]}, name="k").cases()
    # the key hashes the whole case, its name included: equal values in two cases are two cases
    assert s[0].key != s[1].key
    again = Sweep(BASE, grid={"analysis.ship.speed": [1.0, 1.0, 2.0]}, name="k").cases()
    assert [c.key for c in again] == [c.key for c in s]
    changed = Sweep({**BASE, "environment": {"water_density": 1025.0, "depth": 50.0}},
                    grid={"analysis.ship.speed": [1.0, 1.0, 2.0]}, name="k").cases()
    assert all(a.key != b.key for a, b in zip(changed, s))


# --- running -----------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def scheduler():
    """A 2-worker Dask cluster standing in for a user's scheduler (the sweep gets its address)."""
    from distributed import LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                      silence_logs=40) as cluster:
        yield cluster.scheduler_address


@pytest.fixture(scope="module")
def one_by_one():
    """Each case of the 12-case grid run on its own with seacable.run, in this process."""
    return [sc.run(c.case) for c in grid_sweep().cases()]


def test_sweep_on_2_workers_equals_cases_one_by_one(tmp_path, scheduler, one_by_one):
    summary = sc.sweep(grid_sweep(), tmp_path, scheduler=scheduler)
    assert summary.sizes["case"] == 12 and list(summary.status.values) == ["done"] * 12
    np.testing.assert_array_equal(summary["analysis.ship.speed"].values, np.repeat(SPEEDS, 2))
    np.testing.assert_array_equal(summary["analysis.payout.slack"].values, np.tile(SLACKS, 6))
    for i, ds in enumerate(one_by_one):
        # the same numbers: the per-case file is the result of seacable.run, bit for bit
        with open_netcdf(tmp_path / "cases" / f"{i:04d}.nc") as saved:
            for name in ("top_tension", "entry_angle", "x", "z", "tension"):
                np.testing.assert_array_equal(saved[name].values, ds[name].values, err_msg=name)
        # and the summary row is the extremes of that result
        assert summary.top_tension_max.values[i] == float(ds.top_tension.max())
        assert summary.top_tension_min.values[i] == float(ds.top_tension.min())
        assert summary.bottom_tension_max.values[i] == float(ds.bottom_tension.max())
        n = ds.sizes["time"] // 10
        assert summary.entry_angle_end.values[i] == float(ds.entry_angle[-n:].mean())
        layback = (ds.ship_x - ds.touchdown_x)[-n:].mean()
        assert summary.layback_end.values[i] == float(layback)
    # units and names of the swept parameters
    assert summary["analysis.ship.speed"].attrs["units"] == "m/s"
    assert summary.top_tension_max.attrs["units"] == "N"
    # the summary and its table are on disk
    on_disk = sc.read_netcdf(tmp_path / "summary.nc")
    np.testing.assert_array_equal(on_disk.entry_angle_end.values, summary.entry_angle_end.values)
    table = (tmp_path / "summary.csv").read_text().splitlines()
    assert table[0].startswith("case,name,analysis.ship.speed,analysis.payout.slack,status,")
    assert len(table) == 13


def test_a_worker_killed_mid_sweep_costs_nothing(tmp_path, scheduler, one_by_one):
    """Dask runs the killed worker's case again on a worker the nanny restarts; the sweep completes."""
    from distributed import Client

    with Client(scheduler, set_as_default=False) as client:
        pids = list(client.run(os.getpid).values())
    killed = []

    def kill_one(progress):
        if progress.record is not None and not killed:
            os.kill(pids[0], signal.SIGKILL)
            killed.append(progress.done)

    summary = sc.sweep(grid_sweep(), tmp_path, scheduler=scheduler, progress=kill_one)
    assert killed and killed[0] < 12
    assert list(summary.status.values) == ["done"] * 12
    top = [float(ds.top_tension.max()) for ds in one_by_one]
    np.testing.assert_array_equal(summary.top_tension_max.values, top)


def test_failed_cases_are_reported_and_the_others_complete(tmp_path, scheduler):
    """A table of cases: one with a bad value (rejected before it runs), one that fails in its run."""
    (tmp_path / "cases.csv").write_text(
        "analysis.ship.speed,line_types.cable.weight_in_water\n"
        "1.0,4.49\n"
        "-1.0,4.49\n"        # a negative speed: rejected by the case's validation
        "1.5,-2.0\n"         # a cable that floats: the laying model refuses it when it runs
        "2.0,4.49\n")
    spec = write_sweep(tmp_path, table="cases.csv")
    summary = sc.sweep(spec, tmp_path / "out", scheduler=scheduler)
    assert list(summary.status.values) == ["done", "failed", "failed", "done"]
    assert "analysis.ship.speed must be >= 0 m/s, got -1 m/s" in summary.error.values[1]
    assert "weighs -2 N/m in water: a laid cable must sink" in summary.error.values[2]
    assert summary.error.values[0] == summary.error.values[3] == ""
    assert np.isnan(summary.top_tension_max.values[1:3]).all()
    assert np.isfinite(summary.top_tension_max.values[[0, 3]]).all()
    assert summary.attrs["failed"] == 2 and summary.attrs["done"] == 2
    assert not (tmp_path / "out" / "cases" / "0002.nc").exists()
    record = json.loads((tmp_path / "out" / "cases" / "0002.json").read_text())
    assert record["status"] == "failed" and "must sink" in record["error"]
    # a second run keeps the failures (deterministic) unless asked to retry them
    again = sc.sweep(spec, tmp_path / "out", scheduler="synchronous")
    assert again.reused.values.tolist() == [1, 1, 1, 1]
    retried = sc.sweep(spec, tmp_path / "out", scheduler="synchronous", retry_failed=True)
    assert retried.reused.values.tolist() == [1, 0, 0, 1]
    assert list(retried.status.values) == ["done", "failed", "failed", "done"]


def test_cli_sweep_exit_status_table_and_plot(tmp_path, capsys):
    spec = write_sweep(tmp_path, grid={"analysis.ship.speed": [1.0, -1.0, 2.0]})
    out = tmp_path / "out"
    assert main(["sweep", str(spec), "-o", str(out), "--scheduler", "synchronous"]) == 1  # a case failed
    captured = capsys.readouterr()
    assert "t_0002" in captured.out and "entry_angle_end [rad]" in captured.out
    assert "case 1 (t_0001) failed: InputError" in captured.err
    assert "1 of 3 cases failed" in captured.err
    assert (out / "summary_sweep.png").exists()
    # seacable plot on the summary draws it again
    assert main(["plot", str(out / "summary.nc"), "-o", str(tmp_path / "figs")]) == 0
    assert (tmp_path / "figs" / "summary_sweep.png").exists()


def test_run_case_records_warnings_and_errors():
    case = grid_sweep().cases()[0].case
    cable = case.line.segments[0].line_type
    # 400 m of cable: more than the 339 m on the seabed and hanging at the start, all paid out within
    # the 100 s (at 0.79 m/s)
    out = run_case(case.replace(line=sc.Line.single(cable, 400.0)))
    assert out["status"] == "done" and out["result"] is not None
    assert any("all 400 m of cable paid out" in w for w in out["warnings"])
    out = run_case(case.replace(line=sc.Line.single(cable, 60.0)))
    assert out["status"] == "failed" and out["result"] is None and out["extremes"] == {}
    assert out["error"].startswith("InputError: the initial suspended cable needs 169.193 m")


def test_interrupted_sweep_resumes_with_the_missing_cases_only(tmp_path, scheduler, capsys):
    """Kill a running sweep (the command and its workers), run it again: only the missing cases run."""
    # 50 s cases (0.1-0.2 s each, one after another on the command's one worker): the test polls every 0.05 s, so
    # the kill still lands part way through the 12. One worker (its nanny and worker processes killed with the
    # command as two would be): each worker process imports seacable and loads the laying kernels before its first
    # case (3 to 4 CPU-seconds); the 100 s cases of two workers took twice as long, here and in the run again
    base = {**BASE, "analysis": {**BASE["analysis"], "segment_length": 2.0, "duration": 50.0}}
    spec = tmp_path / "sweep.yaml"
    spec.write_text(yaml.safe_dump({"name": "k", "base": base,
                                    "grid": {"analysis.ship.speed": [1.0 + 0.25 * i for i in range(12)]}}))
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "seacable", "sweep", str(spec), "-o", str(out), "--workers", "1", "--no-plots"]
    proc = subprocess.Popen(cmd, start_new_session=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    records = out / "cases"
    deadline = time.monotonic() + 300
    while len(list(records.glob("[0-9]*.json"))) < 3:
        assert proc.poll() is None, proc.stderr.read().decode()
        assert time.monotonic() < deadline, "the sweep did not get going"
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)       # the command, its cluster and its workers
    proc.wait()
    proc.stderr.close()
    done = {p.stem: p.stat().st_mtime_ns for p in records.glob("[0-9]*.json")}   # not the partial files
    assert 3 <= len(done) < 12, "kill the sweep part way"
    # the kill needs the command in a process of its own; the run again does not: the same sweep into the same
    # folder, in this process on the module's warm 2-worker cluster (which cases run again is the output folder's
    # records' business, whatever the scheduler), instead of a second command starting a cluster of its own
    # (about 10 s of a fresh interpreter's imports, a cluster's start and its workers' kernel loading)
    status = main(["sweep", str(spec), "-o", str(out), "--scheduler", scheduler, "--no-plots"])
    err = capsys.readouterr().err
    assert status == 0, err
    summary = sc.read_netcdf(out / "summary.nc")
    assert list(summary.status.values) == ["done"] * 12
    reused = {f"{i:04d}" for i in np.flatnonzero(summary.reused.values)}
    assert reused == set(done)                # what was done is kept ...
    for stem, mtime in done.items():          # ... untouched
        assert (records / f"{stem}.json").stat().st_mtime_ns == mtime
    assert f"{len(done)} from an earlier run" in err
    assert not list(records.glob(".*"))       # no partial file left
    # and the resumed sweep gives the numbers of the cases run one by one
    cases = load_sweep(spec).cases()
    for i in (0, 11):
        ds = sc.run(cases[i].case)
        assert summary.top_tension_max.values[i] == float(ds.top_tension.max())


def test_summary_table_columns(tmp_path):
    summary = sc.sweep(Sweep(BASE, grid={"analysis.ship.speed": [1.0]}, name="one"), tmp_path,
                       scheduler="synchronous", write_summary=False)
    table = summary_table(summary)
    assert list(table.columns[:3]) == ["name", "analysis.ship.speed", "status"]
    assert not (tmp_path / "summary.nc").exists()


def test_engine_argument_errors(tmp_path, capsys):
    with pytest.raises(InputError, match="workers must be a whole number >= 1, got 0"):
        sc.sweep(grid_sweep(), tmp_path, workers=0)
    with pytest.raises(InputError, match="workers .2. sizes the local cluster"):
        sc.sweep(grid_sweep(), tmp_path, workers=2, scheduler="synchronous")
    # a scheduler that is not there: one message, exit status 2 (the client gives up after 10 s)
    spec = write_sweep(tmp_path, grid={"analysis.ship.speed": [1.0]})
    assert main(["sweep", str(spec), "-o", str(tmp_path / "out"), "--scheduler", "tcp://127.0.0.1:9"]) == 2
    assert "cannot reach the Dask scheduler at 'tcp://127.0.0.1:9'" in capsys.readouterr().err


def test_grid_values_must_be_lists():
    with pytest.raises(InputError, match=r"parameter 'analysis.ship.speed' needs a list of values .* got 2.0"):
        Sweep(BASE, grid={"analysis.ship.speed": 2.0})
    with pytest.raises(InputError, match="the table's columns have different lengths"):
        Sweep(BASE, table={"analysis.ship.speed": [1.0, 2.0], "analysis.duration": [10.0]})


# --- sizes and scheduler addresses, checked before anything runs (issue 17) ---------------------

@pytest.mark.parametrize("spec", [{"start": 0.0, "stop": 1.0, "step": 0.1}, {"start": 0.5, "stop": 5.0, "step": 0.25},
                                  {"start": 1.0, "stop": 0.0, "step": -0.3}, {"start": 0.0, "stop": 1.0, "num": 7},
                                  {"start": 0.0, "stop": 0.0, "step": 1.0}, {"start": 0.1, "stop": 0.7, "step": 0.1}])
def test_range_is_counted_as_listed(spec):
    """The case count (checked against the limit before the grid is expanded) is the number of values."""
    from seacable.sweeps.spec import Range, _count

    r = Range.parse(spec)
    assert _count(r) == len(r.values())


def test_grid_over_the_case_limit_is_refused_before_expansion(monkeypatch):
    monkeypatch.setenv("SEACABLE_MAX_CASES", "11")
    with pytest.raises(InputError, match=r"\(6 x 2\) has 12 cases, more than the limit of 11"):
        grid_sweep()
    monkeypatch.setenv("SEACABLE_MAX_CASES", "12")
    assert len(grid_sweep()) == 12


@pytest.mark.parametrize("address", [None, "synchronous", "tcp://10.0.0.5:8786", "localhost:8786",
                                     "tls://scheduler.example.org:8786", "tcp://[::1]:8786", "ws://host:80/"])
def test_scheduler_address_forms_accepted(address):
    from seacable.sweeps.engine import check_scheduler

    check_scheduler(address)


@pytest.mark.parametrize("address", ["not a scheduler", "tcp://host", "host", "http://host:8786", "tcp://:8786",
                                     "host:0", "host:70000", "", 8786])
def test_scheduler_address_forms_refused(address):
    from seacable.sweeps.engine import check_scheduler

    with pytest.raises(InputError, match="--scheduler"):
        check_scheduler(address)


def test_sigterm_stops_a_sweep_like_ctrl_c(tmp_path):
    """SIGTERM (what a batch scheduler sends) stops a sweep as Ctrl-C does: the cases done are kept,
    the summary is written and says so, exit 130."""
    spec = write_sweep(tmp_path, grid={"analysis.ship.speed": [1.0 + 0.1 * i for i in range(40)]})
    out = tmp_path / "out"
    src = str(Path(sc.__file__).resolve().parents[1])
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([src, os.environ.get("PYTHONPATH", "")])}
    proc = subprocess.Popen([sys.executable, "-m", "seacable", "sweep", str(spec), "-o", str(out), "--scheduler",
                             "synchronous", "--no-plots"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
    deadline = time.monotonic() + 300
    while len(list((out / "cases").glob("[0-9]*.json"))) < 2:
        assert proc.poll() is None, proc.stderr.read().decode()
        assert time.monotonic() < deadline, "the sweep did not get going"
        time.sleep(0.05)
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=300)
    assert proc.returncode == 130, err.decode()
    assert b"Traceback" not in err and b"interrupted" in err
    summary = sc.read_netcdf(out / "summary.nc")
    assert summary.attrs["interrupted"] == 1
    finished = summary.attrs["done"] + summary.attrs["failed"]
    assert summary.attrs["done"] >= 1 and 2 <= finished < 40, summary.error.values
    assert summary.attrs["not_run"] == 40 - finished
    assert not list((out / "cases").glob(".*"))


def test_a_case_failing_after_an_interrupt_stops_the_sweep(monkeypatch):
    """A library may turn the KeyboardInterrupt raised in its callback into another error: after the
    user asked to stop, a failed case is the interrupt, not the case's failure."""
    from seacable import _atomic

    def broken(case, progress=None):
        raise sc.errors.ConvergenceError("did not converge (interrupted inside a solver)")

    monkeypatch.setattr("seacable.simulate.run", broken)
    case = grid_sweep().cases()[0].case
    assert run_case(case)["status"] == "failed"
    _atomic.interrupt_requested.set()
    try:
        with pytest.raises(KeyboardInterrupt):
            run_case(case)
    finally:
        _atomic.interrupt_requested.clear()

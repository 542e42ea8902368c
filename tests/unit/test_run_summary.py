"""What a run says (issue 41): the summary ``seacable run`` prints, ``--quiet``, progress to a pipe, and the
statistics window (``analysis.statistics_from``) that leaves a start-up transient out of extremes and summaries."""

import io
import math
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import yaml

import seacable as sc
from seacable import cli
from seacable._window import statistics_start
from seacable.cli import main
from seacable.extremes import case_extremes
from seacable.results import case_yaml, open_netcdf
from seacable.run_summary import _fmt, summary_rows

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _rows(ds):
    return {(r["variable"], r["reduction"]): r for r in summary_rows(ds)}


# ------------------------------------------------------------------------------------------- the figures


def test_static_summary_is_the_results_numbers():
    ds = sc.run(sc.load_case(EXAMPLES / "oc3_hywind_static.yaml"))
    rows = _rows(ds)
    # the figures are the result's own variables, to the bit
    for name in ("fairlead_tension", "anchor_tension", "touchdown_x", "grounded_length"):
        assert rows[(name, "value")]["value"] == float(ds[name]), name
    # the layback: the fairlead's (last point's) horizontal distance from the touchdown
    assert rows[("layback", "value")]["value"] == pytest.approx(float(ds.x[-1] - ds.touchdown_x), rel=1e-12)
    text = sc.summary(ds)
    # shown in kN: a planted N-for-kN (or a wrong factor) prints another number
    assert f"{_fmt(float(ds.fairlead_tension) / 1e3)} kN" in text
    assert f"{_fmt(float(ds.touchdown_x))} m" in text


def test_pushover_and_towed_steady_summaries():
    ds = sc.run(sc.load_case(EXAMPLES / "oc3_hywind_pushover.yaml"))
    row = _rows(ds)[("fairlead_tension", "max")]
    i = int(np.argmax(ds.fairlead_tension.values))
    assert row["value"] == float(ds.fairlead_tension.max())
    assert row["where"] == f"offset {_fmt(float(ds.offset[i]))} m"          # the offset it happens at
    grounded = _rows(ds)[("grounded_length", "range")]
    assert grounded["value"] == float(ds.grounded_length.min())

    ds = sc.run(sc.load_case(EXAMPLES / "paper000_steady_statics.yaml"))
    rows = _rows(ds)
    for name in ("top_tension", "lower_end_depth", "layback"):
        assert rows[(name, "value")]["value"] == float(ds[name])
    # the top angle in rad in the result, shown in degrees
    assert rows[("top_angle", "value")]["shown"] == pytest.approx(math.degrees(float(ds.top_angle)), rel=1e-14)
    assert rows[("top_angle", "value")]["shown_units"] == "deg"


def _case_yaml(statistics_from=None, analysis="towline_dynamic", ramp=None):
    a = {"type": analysis, "duration": 100.0}
    if statistics_from is not None:
        a["statistics_from"] = statistics_from
    if ramp is not None:
        a["motion"] = {"type": "harmonic", "ramp": ramp}
    return yaml.safe_dump({"name": "synthetic", "analysis": a})


def _series(analysis, names, statistics_from=None, ramp=None, line=False):
    """A time-domain result of ``analysis``: each variable a sine-free ramp with a start spike at t = 1 s."""
    t = np.arange(0.0, 100.0, 1.0)
    data = {}
    for k, name in enumerate(names):
        v = 1000.0 * (k + 1) + 10.0 * t          # largest at the end ...
        v[1] = 1e5 * (k + 1)                     # ... but for a start spike
        units = "degree" if "angle" in name else ("N" if "tension" in name else "m")
        data[name] = (("time", "line") if line else ("time",), v[:, None] * [1.0, 0.5] if line else v,
                      {"units": units, "long_name": name})
    coords = {"time": ("time", t, {"units": "s"})}
    if line:
        coords["line"] = ("line", ["line1", "line2"])
    return xr.Dataset(data, coords=coords, attrs={"analysis": analysis, "case": _case_yaml(statistics_from,
                                                                                          analysis, ramp)})


@pytest.mark.parametrize("analysis, names", [
    ("towline_dynamic", ["top_tension", "barge_tension"]),
    ("towed_dynamic", ["top_tension", "lower_end_depth", "layback"]),
    ("laying_dynamic", ["top_tension", "bottom_tension", "layback", "entry_angle", "touchdown_x"]),
    ("mooring_dynamic", ["fairlead_tension", "anchor_tension", "seabed_contact_length"]),
])
def test_time_domain_summaries_are_the_results_extremes(analysis, names):
    ds = _series(analysis, names, statistics_from=10.0)
    rows = summary_rows(ds)
    assert rows, analysis
    for r in rows:
        v = ds[r["variable"]].sel(time=slice(10.0, None))
        if r["reduction"] == "max":
            assert r["value"] == float(v.max()) and r["where"] == f"t = {float(v.idxmax()):.6g} s", r
        elif r["reduction"] == "min":
            assert r["value"] == float(v.min()) and r["where"] == f"t = {float(v.idxmin()):.6g} s", r
        elif r["reduction"] == "end":   # the mean over the last tenth of the whole run
            assert r["value"] == float(ds[r["variable"]].isel(time=slice(-10, None)).mean()), r
        elif r["reduction"] == "range":
            assert r["value"] == float(v.min()), r
    assert "statistics from t = 10 s" in sc.summary(ds)


def test_system_summary_names_the_most_loaded_line_and_its_utilisation():
    ds = _series("system_dynamic", ["fairlead_tension", "body_offset"], line=True)
    ds["breaking_load"] = ("line", [2e6, 1e6], {"units": "N"})
    rows = _rows(ds)
    top = rows[("fairlead_tension", "max")]
    assert top["value"] == 1e5 and top["where"] == "t = 1 s, line line1"   # no window: statistics from 0
    util = next(r for r in summary_rows(ds) if r["figure"] == "utilisation")
    assert util["value"] == 1e5 / 2e6      # line1's breaking load, not line2's (planted: the other line's)


# ------------------------------------------------------------------------------------------- the window


def test_default_window_is_the_end_of_the_ramp():
    assert statistics_start(_series("mooring_dynamic", ["fairlead_tension"], ramp=20.0)) == 20.0
    assert statistics_start(_series("mooring_dynamic", ["fairlead_tension"], ramp=20.0, statistics_from=5.0)) == 5.0
    assert statistics_start(_series("towline_dynamic", ["top_tension"])) == 0.0
    # a free body's wave-load ramp (the case's bodies) counts too, the longest ramp wins
    ds = _series("system_dynamic", ["fairlead_tension"], ramp=20.0)
    data = yaml.safe_load(ds.attrs["case"])
    data["bodies"] = {"hull": {"kind": "free", "hydrodynamics": {"ramp": 60.0}}}
    assert statistics_start(ds.assign_attrs(case=yaml.safe_dump(data))) == 60.0
    # a ramp as long as the run leaves the whole run to the statistics
    assert statistics_start(_series("mooring_dynamic", ["fairlead_tension"], ramp=100.0)) == 0.0


def _drop(statistics_from=None):
    case = sc.load_case(EXAMPLES / "paper003_drop.yaml")
    update = {"duration": 8.0, "output_interval": 0.5}
    if statistics_from is not None:
        update["statistics_from"] = statistics_from
    return case.model_copy(update={"analysis": case.analysis.model_validate(
        {**case.analysis.model_dump(), **update})})


@pytest.fixture(scope="module")
def towline_drop():
    """Paper 003's dropped towline (both ends held): the line's fall snatches the tug's tow point at the start
    (about 2.0 kN at t = 0.5 s) above the tension it settles at (about 1.43 kN)."""
    return sc.run(_drop(statistics_from=3.0))


def test_the_start_snatch_is_not_the_peak(towline_drop):
    ds = towline_drop
    top = ds.top_tension
    assert float(top.max()) > 1.2 * float(top.sel(time=slice(3.0, None)).max())   # the transient is there
    out = {k: float(v.values) for k, v in case_extremes(ds).items()}
    assert out["statistics_from"] == 3.0
    # the window leaves the snatch out: the extremes are those from t = 3 s on
    assert out["top_tension_max"] == float(top.sel(time=slice(3.0, None)).max())
    assert out["top_tension_min"] == float(top.sel(time=slice(3.0, None)).min())
    text = sc.summary(ds)
    assert "statistics from t = 3 s" in text
    assert f"{_fmt(float(top.sel(time=slice(3.0, None)).max()) / 1e3)} kN" in text
    # the same result without a window: the snatch is the peak
    whole = ds.assign_attrs(case=ds.attrs["case"].replace("statistics_from: 3.0", "statistics_from: 0.0"))
    assert float(case_extremes(whole)["top_tension_max"]) == float(top.max())


def test_a_case_without_a_window_dumps_as_before():
    case = _drop()
    assert "statistics_from" not in case_yaml(case)      # results of old cases keep their bits
    assert "statistics_from: 3.0" in case_yaml(_drop(3.0))


@pytest.mark.parametrize("value, says", [(8.0, "must lie within the run"), (20.0, "must lie within the run"),
                                         (-1.0, "statistics_from")])
def test_bad_window_refused_by_validate_and_run(tmp_path, capsys, value, says):
    data = yaml.safe_load((EXAMPLES / "paper003_drop.yaml").read_text())
    data["analysis"].update(statistics_from=value, duration=8.0)     # within [0 s, 8 s) only
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data))
    assert main(["validate", str(path)]) == 2
    err = capsys.readouterr().err
    assert says in err and "Suggested fix" in err
    assert main(["run", str(path), "--no-plots", "-o", str(tmp_path / "r.nc")]) == 2
    assert says in capsys.readouterr().err
    assert not (tmp_path / "r.nc").exists()


# ------------------------------------------------------------------------------------------- the CLI


def test_run_prints_the_summary_and_quiet_prints_nothing(tmp_path, capsys):
    case = str(EXAMPLES / "oc3_hywind_static.yaml")
    assert main(["run", case, "--no-plots", "-o", str(tmp_path / "a.nc")]) == 0
    out = capsys.readouterr().out
    ds = open_netcdf(tmp_path / "a.nc")
    assert "fairlead tension" in out and f"{_fmt(float(ds.fairlead_tension) / 1e3)} kN" in out
    ds.close()
    assert main(["run", case, "--no-plots", "--quiet", "-o", str(tmp_path / "b.nc")]) == 0
    assert capsys.readouterr().out == ""
    assert (tmp_path / "b.nc").exists()


class _Pipe(io.StringIO):
    def isatty(self):
        return False


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def test_progress_to_a_pipe_is_whole_lines_every_tenth(monkeypatch):
    monkeypatch.setattr(cli, "_computation_done", lambda: None)
    pipe = _Pipe()
    monkeypatch.setattr(sys, "stderr", pipe)
    progress = cli._Progress()
    for t in np.linspace(0.0, 100.0, 1001):     # 1000 steps within a second
        progress(float(t), 100.0)
    text = pipe.getvalue()
    assert "\r" not in text
    lines = text.splitlines()
    assert len(lines) == 10 and lines[-1].endswith("(100 %)")   # every 10 %, the last at the end
    # on a terminal the line is rewritten in place, as before
    term = _Terminal()
    monkeypatch.setattr(sys, "stderr", term)
    progress = cli._Progress(every=0.0)
    progress(50.0, 100.0)
    assert term.getvalue().endswith("\r")
    quiet = _Pipe()
    monkeypatch.setattr(sys, "stderr", quiet)
    progress = cli._Progress(quiet=True)
    for t in (0.0, 50.0, 100.0):
        progress(t, 100.0)
    assert quiet.getvalue() == ""


def test_the_reports_seed_statistics_leave_the_transient_out():
    from seacable.design.summary import Run, seed_table

    ds = _series("mooring_dynamic", ["fairlead_tension", "anchor_tension"], statistics_from=10.0)
    table = seed_table([Run("synthetic", "synthetic", None, source=ds)])
    fair = table[table.end == "fairlead"].iloc[0]
    after = ds.fairlead_tension.sel(time=slice(10.0, None))
    # the start spike (1e5 N at 1 s) is left out: the maximum, mean and duration are those from 10 s on
    assert fair["maximum"] == float(after.max()) and fair["mean"] == pytest.approx(float(after.mean()), rel=1e-12)
    assert fair["duration"] == float(after.time[-1] - after.time[0])

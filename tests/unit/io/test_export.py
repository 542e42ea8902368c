"""``seacable export``: CSV tables that read back to the result's numbers, MoorDyn files, and what is refused.

The MoorDyn layout itself is checked against MoorDyn 2.7.2's own files in
``tests/validation/test_moordyn_export.py``.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import seacable as sc
from seacable.cli import main
from seacable.errors import InputError
from seacable.io.export import export_csv, export_moordyn, export_result
from seacable.results import write_netcdf

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"

_DECK = """--------------------- MoorDyn Input File ------------------------------------
two lines of different lengths and segment counts
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.1     50.0       1.0e8      -0.8        0          1.2    1.0    0.4     0.5
---------------------- POINTS ----------------------------------------------
ID    Attachment  X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)         (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed       -100.0  0.0     -50.0   0      0       0      0
2     Coupled     0.0     0.0     -5.0    0      0       0      0
3     Fixed       90.0    20.0    -50.0   0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        2         110.0     4       -
2     chain      3        2         105.0     6       -
---------------------- OPTIONS -----------------------------------------
1025.0        WtrDnsty
50            WtrDpth
------------------------- need this line --------------------------------------
"""


def _quiet_run(case):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sc.SeacableWarning)
        return sc.run(case)


@pytest.fixture(scope="module")
def deck(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("deck") / "two.txt"
    path.write_text(_DECK, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def dynamic(deck):
    from seacable.mooring.motion import HarmonicMotion

    case = sc.load_case(deck).with_run(duration=1.0, time_step=0.05, output_interval=0.25,
                                       motion=HarmonicMotion(amplitude=(1.0, 0.0, 0.5), period=4.0))
    return _quiet_run(case)


def _read(path: Path) -> pd.DataFrame:
    return pd.read_csv(path)  # pandas reads a float's shortest repr back to the same float


def test_csv_of_a_time_series_reads_back_to_the_results_numbers(dynamic, tmp_path):
    """Every number of the tables is the NetCDF value to the bit (Python's shortest round-trip text); a line's nodes
    as a tidy table (a row per time and node: lines of 5 and 7 nodes keep their own count, no NaN padding)."""
    written, skipped = export_csv(dynamic, tmp_path, "run")
    assert [p.name for p in written] == ["run.csv", "run_line1.csv", "run_line1_elements.csv", "run_line2.csv",
                                         "run_line2_elements.csv"]
    assert "snap_time" in skipped and "point_node" in skipped
    table = _read(tmp_path / "run.csv")
    np.testing.assert_array_equal(table["time [s]"], dynamic.time.values)
    np.testing.assert_array_equal(table["fairlead_tension (line 2) [N]"],
                                  dynamic.fairlead_tension.sel(line="line 2").values)
    np.testing.assert_array_equal(table["point_force_z (point 1) [N]"], dynamic.point_force_z.isel(point=1).values)
    nodes = _read(tmp_path / "run_line2.csv")
    assert list(nodes.columns[:5]) == ["time [s]", "node", "x [m]", "y [m]", "z [m]"]
    assert len(nodes) == dynamic.sizes["time"] * 7  # 6 segments: 7 nodes, none padded
    at = nodes[(nodes["time [s]"] == 0.75) & (nodes["node"] == 3)]
    assert float(at["z [m]"].iloc[0]) == float(dynamic.z.sel(line="line 2", time=0.75, node=3))
    assert len(_read(tmp_path / "run_line1.csv")) == dynamic.sizes["time"] * 5
    elements = _read(tmp_path / "run_line1_elements.csv")
    np.testing.assert_array_equal(elements["segment_tension [N]"],
                                  dynamic.segment_tension.sel(line="line 1").isel(element=slice(0, 4)).values.ravel())


def test_csv_of_a_static_result_is_one_row(deck, tmp_path):
    ds = _quiet_run(sc.load_case(deck))
    export_csv(ds, tmp_path, "static")
    table = _read(tmp_path / "static.csv")
    assert len(table) == 1 and "time [s]" not in table
    assert table["anchor_tension (line 1) [N]"].iloc[0] == float(ds.anchor_tension.sel(line="line 1"))
    assert list(_read(tmp_path / "static_line2.csv").columns[:2]) == ["node", "x [m]"]


def test_pushover_exports_as_a_state_table_and_is_refused_as_moordyn(tmp_path, capsys):
    """A pushover's rows are its offsets; MoorDyn's files are time series: refused, exit 2, one line naming the
    axis and the fix."""
    ds = _quiet_run(sc.load_case(EXAMPLES / "oc3_hywind_pushover.yaml"))
    result = write_netcdf(ds, tmp_path / "push.nc")
    assert main(["export", str(result), "--format", "csv"]) == 0
    table = _read(tmp_path / "push.csv")
    np.testing.assert_array_equal(table["offset [m]"], ds.offset.values)
    np.testing.assert_array_equal(table["fairlead_tension [N]"], ds.fairlead_tension.values)
    capsys.readouterr()
    assert main(["export", str(result), "--format", "moordyn", "-o", str(tmp_path / "md")]) == 2
    err = capsys.readouterr().err
    assert err.count("seacable: error:") == 1 and "runs along 'offset'" in err and "--format csv" in err
    assert "Traceback" not in err and not (tmp_path / "md").exists()


def test_moordyn_files_of_a_dynamic_run(dynamic, tmp_path):
    """A row per stored time; FairTen is end B's tension (the moved end here), AnchTen end A's."""
    written = export_moordyn(dynamic, tmp_path, "two")
    assert [p.name for p in written] == ["two.out", "two_Line1.out", "two_Line2.out"]
    lines = (tmp_path / "two.out").read_text().splitlines()
    names = lines[0].split()
    rows = np.loadtxt(lines[2:], ndmin=2)
    assert rows.shape == (dynamic.sizes["time"], len(names))
    np.testing.assert_allclose(rows[:, names.index("FairTen2")], dynamic.fairlead_tension.sel(line="line 2"),
                               rtol=1e-7)  # %20.7e: 8 digits
    np.testing.assert_allclose(rows[:, names.index("AnchTen1")], dynamic.anchor_tension.sel(line="line 1"),
                               rtol=1e-7)
    line2 = (tmp_path / "two_Line2.out").read_text().splitlines()
    assert line2[0].split()[-1] == "Seg6Te" and len(line2[0].split()) == 1 + 7 * 3 + 6


def test_fairlead_at_end_a_is_moordyns_anchtensions_end(tmp_path):
    """MoorDyn's FairTen is always end B. A line whose end A is the moved one (seacable's fairlead there) has its
    fairlead tension written as AnchTen: the columns follow MoorDyn's ends, not seacable's names."""
    flipped = tmp_path / "flipped.txt"
    flipped.write_text(_DECK.replace("1     chain      1        2         110.0     4",
                                     "1     chain      2        1         110.0     4"), encoding="utf-8")
    ds = _quiet_run(sc.load_case(flipped))
    export_moordyn(ds, tmp_path, "flipped")
    lines = (tmp_path / "flipped.out").read_text().splitlines()
    names, row = lines[0].split(), np.loadtxt(lines[2:], ndmin=2)[0]
    assert row[names.index("AnchTen1")] == pytest.approx(float(ds.fairlead_tension.sel(line="line 1")), rel=1e-7)
    assert row[names.index("FairTen1")] == pytest.approx(float(ds.anchor_tension.sel(line="line 1")), rel=1e-7)
    assert row[names.index("FairTen1")] < row[names.index("AnchTen1")]  # the anchor end is the lower, slacker one


@pytest.mark.parametrize("setup, args, expected", [
    (None, ["export", "{d}/missing.nc", "--format", "csv"], "does not exist"),
    ("text", ["export", "{d}/bad.nc", "--format", "csv"], "not a readable NetCDF file"),
    ("result", ["export", "{d}/ok.nc", "--format", "csv", "-o", "{d}/ok.nc"], "is a file, expected a folder"),
    ("result", ["export", "{d}/ok.nc", "--format", "xlsx"], "invalid choice"),
    ("result", ["export", "{d}/ok.nc"], "--format"),
])
def test_export_bad_input_is_one_clear_line(setup, args, expected, deck, tmp_path, capsys):
    if setup == "text":
        (tmp_path / "bad.nc").write_text("not a result", encoding="utf-8")
    elif setup == "result":
        write_netcdf(_quiet_run(sc.load_case(deck)), tmp_path / "ok.nc")
    assert main([a.format(d=tmp_path) for a in args]) == 2
    err = capsys.readouterr().err
    assert err.count("seacable: error:") == 1 and expected in err and "Traceback" not in err


def test_a_result_without_tables_is_refused(tmp_path):
    import xarray as xr

    f = np.linspace(0.01, 2.0, 2000)
    ds = xr.Dataset({"spectrum": ("frequency", np.ones(f.size), {"units": "m2 s"})}, coords={"frequency": f},
                    attrs={"analysis": "spectral"})
    with pytest.raises(InputError, match=r"no quantity along a state axis.*Suggested fix"):
        export_csv(ds, tmp_path, "x")
    with pytest.raises(InputError, match=r"no node positions.*Suggested fix: export it with --format csv"):
        export_moordyn(ds, tmp_path, "x")
    with pytest.raises(InputError, match=r"format must be one of csv, moordyn"):
        export_result(tmp_path / "x.nc", "json")


def test_quantities_on_two_label_axes_and_the_arc_length(tmp_path):
    """A body's six motions (time, body, dof) spread over a column per body and dof, labelled by the coordinates;
    a line's tidy table carries the nodes' arc length s, a coordinate of the result."""
    import xarray as xr

    rng = np.random.default_rng(1)
    pos = rng.normal(size=(3, 2, 6))
    s = np.array([[0.0, 5.0, 10.0], [0.0, 4.0, 8.0]])
    ds = xr.Dataset({"body_position": (("time", "body", "dof"), pos, {"units": "m"}),
                     "x": (("time", "line", "node"), rng.normal(size=(3, 2, 3)), {"units": "m"})},
                    coords={"time": ("time", [0.0, 0.5, 1.0], {"units": "s"}), "body": ["buoy", "hull"],
                            "dof": ["x", "y", "z", "roll", "pitch", "yaw"], "line": ["line1", "line2"],
                            "s": (("line", "node"), s, {"units": "m"})},
                    attrs={"analysis": "system_dynamic"})
    export_csv(ds, tmp_path, "r")
    table = _read(tmp_path / "r.csv")
    assert len(table.columns) == 1 + 2 * 6
    np.testing.assert_array_equal(table["body_position (hull, pitch) [m]"], pos[:, 1, 4])
    nodes = _read(tmp_path / "r_line2.csv")
    assert list(nodes.columns) == ["time [s]", "node", "s [m]", "x [m]"]
    np.testing.assert_array_equal(nodes["s [m]"], np.tile(s[1], 3))

"""The command line: exit codes, one clear message on bad input, files written."""

import subprocess
import sys
from pathlib import Path

import pytest
import xarray as xr

import seacable as sc
from seacable.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_version_and_help(capsys):
    with pytest.raises(SystemExit) as info:
        main(["--version"])
    assert info.value.code == 0
    assert capsys.readouterr().out.strip() == f"seacable {sc.__version__}"
    assert main([]) == 2  # no command: help, non-zero


def test_run_writes_a_labelled_netcdf_and_plots(tmp_path, capsys):
    out = tmp_path / "res" / "tow.nc"
    assert main(["run", str(EXAMPLES / "paper000_steady_statics.yaml"), "-o", str(out)]) == 0
    printed = capsys.readouterr().out
    assert f"wrote {out}" in printed and ".png" in printed
    ds = xr.open_dataset(out)
    assert ds.attrs["analysis"] == "towed_steady"
    assert ds.attrs["seacable_version"] == sc.__version__
    assert "vessel_speed: 1.0" in ds.attrs["case"]
    for name in list(ds.data_vars) + list(ds.coords):
        assert {"units", "long_name"} <= set(ds[name].attrs), name
    assert list((tmp_path / "res").glob("*.png"))
    ds.close()
    # plot again from the file
    assert main(["plot", str(out), "-o", str(tmp_path / "figs")]) == 0
    assert list((tmp_path / "figs").glob("tow_*.png"))


def test_validate_reports_each_file(capsys):
    files = sorted(str(p) for p in EXAMPLES.glob("*.yaml"))
    assert main(["validate", *files]) == 0
    assert capsys.readouterr().out.count(": valid") == len(files)


@pytest.mark.parametrize("argv, expected", [
    (["run", "no_such_case.yaml"], "does not exist"),
    (["plot", "no_such_result.nc"], "does not exist"),
    (["validate", "__BAD__"], "diameter must be > 0 m, got -0.035 m"),
    (["run", "__SHORT__"], "cannot reach"),
])
def test_user_errors_exit_2_with_one_message(tmp_path, capsys, argv, expected):
    if "__BAD__" in argv:
        bad = tmp_path / "bad.yaml"
        bad.write_text((EXAMPLES / "paper000_steady_statics.yaml").read_text().replace(
            "diameter: 0.035", "diameter: -0.035"))
        argv = [a.replace("__BAD__", str(bad)) for a in argv]
    if "__SHORT__" in argv:  # 400 m of chain cannot span 848.67 m by 250 m
        short = tmp_path / "short.yaml"
        short.write_text((EXAMPLES / "oc3_hywind_static.yaml").read_text().replace("length: 902.2", "length: 400.0"))
        argv = [a.replace("__SHORT__", str(short)) for a in argv]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("seacable: error: ") and expected in err
    assert "Traceback" not in err


def test_console_script_exits_non_zero_without_traceback(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("line: {line_type: x, length: 1}\nanalysis: {type: static}\n")
    proc = subprocess.run([sys.executable, "-m", "seacable", "run", str(bad)], capture_output=True, text=True)
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr and "seacable: error:" in proc.stderr


def test_schema_is_json(capsys):
    import json

    assert main(["schema"]) == 0
    schema = json.loads(capsys.readouterr().out)
    assert "analysis" in schema["properties"]

"""NetCDF results follow the CF-1.8 conventions they claim (issue 41; :mod:`seacable._cf`).

The IOOS compliance checker (``compliance-checker``, its ``cf:1.8`` suite; in the ``test`` extra, from wheels:
its UDUNITS-2 comes with ``cf-units``' wheel) checks a small result of each analysis kind: zero errors (its
high-priority failures) and no check that crashes on the file; its warnings (medium) are listed, and the only
ones left are CF 2.4's recommended dimension order (``x(time, node)``: CF recommends the non-spatial ``node``
left of ``time``; seacable keeps the output order of its time loops, which every reader and the streamed files'
unlimited ``time`` rely on). ``cfchecker`` (the CF community's checker) needs ``cfunits``, which has no wheel and
needs the system's libudunits2, so it is not used.

Besides the checker: every unit string parses in UDUNITS-2 (``cf_units``), each standard name of
:data:`seacable._cf.STANDARD_NAMES` is an entry of the CF standard-name table shipped with the checker (version
93) and the variable's units convert to the entry's canonical units, and the split variables read back as the
quantities they were split from (``body_pose``, ``stiffness_matrix``, ``joined``), old files too.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import yaml

import seacable as sc
from seacable import _cf
from seacable.results import body_pose, make_dataset, open_netcdf, read_netcdf, stiffness_matrix, var, write_netcdf

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

if os.environ.get("CI"):  # under CI a missing checker is an error, so that the check cannot silently stop
    import cf_units
    from compliance_checker.runner import CheckSuite
else:
    cf_units = pytest.importorskip("cf_units")
    CheckSuite = pytest.importorskip("compliance_checker.runner").CheckSuite

#: a small result of each analysis kind: analysis -> (example, shortened duration [s] or None)
CASES = {
    "static": ("oc3_hywind_static.yaml", None),
    "pushover": ("oc3_hywind_pushover.yaml", None),
    "modal": ("oc3_hywind_modes.yaml", None),
    "towed_steady": ("paper000_steady_statics.yaml", None),
    "laying_theory": ("paper001_table1.yaml", None),
    "vertical_modes": ("paper002_vertical_cable.yaml", None),
    "mooring_static": ("lazy_wave_80m.yaml", None),
    "mooring_pushover": ("paper004_lena_pushover.yaml", None),
    "mooring_dynamic": ("oc3_hywind_line.yaml", 1.0),
    "towed_dynamic": ("towed_stop_and_go.yaml", 0.5),
    "towed_dynamic_box": ("paper000_steady_tow.yaml", 1.0),
    "laying_dynamic": ("paper001_lay_2ms_50m.yaml", 2.0),
    "lay_plan": ("lay_plan_route.yaml", None),
    "towline_dynamic": ("paper003_zigzag.yaml", 1.0),
    "system_static": ("spread_mooring.yaml", None),
    "system_offsets": ("spread_mooring_watch_circle.yaml", None),
    "system_dynamic": ("spread_mooring_line_break.yaml", 0.5),
}
#: the checker's warnings that stay, and why (see the module docstring)
ALLOWED_WARNINGS = (re.compile(r"spatio-temporal dimensions are not in the recommended order"),)


def _result(kind: str, folder: Path, monkeypatch) -> tuple[xr.Dataset, Path]:
    example, duration = CASES[kind]
    data = yaml.safe_load((EXAMPLES / example).read_text())
    if duration is not None:
        data["analysis"]["duration"] = duration
    monkeypatch.chdir(EXAMPLES)  # the examples' relative paths (bathymetry, routes)
    path = folder / f"{kind}.yaml"
    path.write_text(yaml.safe_dump(data))
    ds = sc.run(sc.load_case(path))
    return ds, write_netcdf(ds, folder / f"{kind}.nc")


def _check(path: Path) -> tuple[list, list, dict]:
    """(errors, warnings, crashed checks) of the checker's cf:1.8 suite on ``path``."""
    suite = CheckSuite()
    suite.load_all_available_checkers()
    results, crashed = suite.run_all(suite.load_dataset(str(path)), ["cf:1.8"], skip_checks=[])["cf:1.8"]
    failed = [r for r in results if isinstance(r.value, tuple) and r.value[0] < r.value[1]]
    errors = [f"{r.name}: {m}" for r in failed if r.weight == 3 for m in r.msgs]
    warnings = [f"{r.name}: {m}" for r in failed if r.weight == 2 for m in r.msgs]
    return errors, warnings, crashed


@pytest.mark.parametrize("kind", sorted(CASES))
def test_each_analysis_result_passes_the_cf_checker(kind, tmp_path, monkeypatch):
    ds, path = _result(kind, tmp_path, monkeypatch)
    errors, warnings, crashed = _check(path)
    assert crashed == {}, f"checks that could not run on {kind}: {list(crashed)}"
    assert errors == []
    assert [w for w in warnings if not any(p.search(w) for p in ALLOWED_WARNINGS)] == []
    # every unit a UDUNITS-2 string (the checker checks those of variables it recognises; here all of them)
    with xr.open_dataset(path, decode_times=False) as f:
        for name, v in f.variables.items():
            if v.dtype.kind in "fiu":
                cf_units.Unit(v.attrs["units"])  # raises on "m or rad", "-", "[m]"
            assert v.dtype.kind not in "iu" or v.dtype.itemsize <= 4, f"{name}: {v.dtype} (CF-1.8: no 64-bit integers)"
    # read back: the same numbers, time in seconds from the start, the names of each dimension its index again
    back = read_netcdf(path)
    for name, v in ds.variables.items():
        assert name in back.variables, name
        if v.dtype.kind in "fiu":
            np.testing.assert_array_equal(back[name].values, v.values, err_msg=name)
    if "time" in ds.variables:
        assert back["time"].attrs["units"] == "s"
        assert set(back.indexes) == set(ds.indexes)


def test_the_checker_sees_what_seacable_fixed(tmp_path):
    """The checker used above fails the faults this module guards against, planted in a small result: a unit
    that is not UDUNITS, time in plain seconds, a 64-bit integer, a standard name not in the table."""
    t = np.arange(3.0)
    ds = make_dataset({"tension": var("time", 1e3 * t, "N", "tension"),
                       "position": var("time", t, "m or rad", "mixed"),
                       "count": var("time", np.arange(3), "1", "count")},
                      {"time": var("time", t, "s", "time")}, analysis="mooring_dynamic")
    ds["tension"].attrs["standard_name"] = "sea_water_tension"   # not in the table
    path = tmp_path / "bad.nc"
    ds.to_netcdf(path)   # written as plain xarray writes it, not through write_netcdf
    errors = " ".join(_check(path)[0])
    for fault in ("m or rad", "time", "int64", "sea_water_tension"):
        assert fault in errors, fault
    # and through write_netcdf, the same result (less the two faults only a rename fixes) passes
    ok = ds.drop_vars("position")
    del ok["tension"].attrs["standard_name"]
    assert _check(write_netcdf(ok, tmp_path / "ok.nc"))[0] == []


def _table() -> dict[str, str]:
    import compliance_checker

    text = (Path(compliance_checker.__file__).parent / "data" / "cf-standard-name-table.xml").read_text()
    return dict(re.findall(r'<entry id="([^"]+)">\s*<canonical_units>([^<]*)</canonical_units>', text))


def test_standard_names_are_table_entries_with_convertible_units():
    table = _table()
    assert len(table) > 4000   # the whole table was read
    units = {"time": "s", "water_depth": "m", "touchdown_depth": "m", "lower_end_depth": "m"}
    assert set(units) == set(_cf.STANDARD_NAMES)
    for name, standard in _cf.STANDARD_NAMES.items():
        assert standard in table, standard
        canonical = table[standard] or "1"
        if standard == "time":  # a reference time: seconds since an epoch, the table's canonical unit s
            assert cf_units.Unit(_cf.TIME_UNITS).is_time_reference() and canonical == "s"
            continue
        assert cf_units.Unit(units[name]).is_convertible(cf_units.Unit(canonical)), (name, units[name], canonical)


def test_time_is_a_cf_time_coordinate_read_back_in_seconds(tmp_path):
    t = np.array([0.0, 0.1, 0.25, 7.5])
    ds = make_dataset({"tension": var("time", t * 2, "N", "tension")}, {"time": var("time", t, "s", "time")},
                      analysis="mooring_dynamic")
    path = write_netcdf(ds, tmp_path / "t.nc")
    with xr.open_dataset(path) as cf:   # a CF reader: the run's clock from the nominal epoch
        expected = np.datetime64("1970-01-01T00:00:00") + (t * 1e9).astype("timedelta64[ns]")
        np.testing.assert_array_equal(cf["time"].values, expected)
        assert cf["time"].attrs["standard_name"] == "time" and cf["time"].attrs["axis"] == "T"
    back = read_netcdf(path)
    np.testing.assert_array_equal(back["time"].values, t)   # the same floats
    assert back["time"].attrs == {"units": "s", "long_name": "time"}
    with open_netcdf(path) as lazy:
        np.testing.assert_array_equal(lazy["time"].values, t)
    assert ds["time"].attrs == {"units": "s", "long_name": "time"}   # the result in memory is left alone


def test_split_variables_join_back_and_old_files_still_read(tmp_path):
    rng = np.random.default_rng(1)
    pose = rng.normal(size=(4, 2, 6))
    names = ["surge", "sway", "heave", "roll", "pitch", "yaw"]
    k = rng.normal(size=(2, 6, 6))
    parts = _cf.matrix_variables("stiffness", ("body", "dof", "dof2"), k, names, names, "stiffness")
    assert [parts[n].attrs["units"] for n in parts] == ["N m-1", "N rad-1", "N m m-1", "N m rad-1"]
    assert not np.isnan(parts["stiffness_translation"].values[:, :3, :3]).any()
    assert np.isnan(parts["stiffness_translation"].values[:, 3:, :]).all()
    new = xr.Dataset({**parts, "body_position": (("time", "body", "axis"), pose[..., :3]),
                      "body_rotation": (("time", "body", "angle"), pose[..., 3:])})
    np.testing.assert_array_equal(stiffness_matrix(new).values, k)
    np.testing.assert_array_equal(body_pose(new), pose)
    # a file written before the split: its one variable of six components, its mixed-unit matrix
    old = xr.Dataset({"stiffness": (("body", "dof", "dof2"), k), "body_position": (("time", "body", "dof"), pose)})
    np.testing.assert_array_equal(stiffness_matrix(old).values, k)
    np.testing.assert_array_equal(body_pose(old), pose)
    # the coupled DOFs' forces and moments, split by kind and joined
    f = rng.normal(size=(3, 9))
    kinds = [_cf.dof_kind(n) for n in [f"body hull {d}" for d in ("x", "y", "z", "roll", "pitch", "yaw")]
             + [f"point p {d}" for d in "xyz"]]
    split = _cf.split_by_kind(f, kinds, axis=1)
    np.testing.assert_array_equal(_cf.joined([split["translation"], split["rotation"]]), f)


def test_system_dynamic_body_position_and_rotation_are_the_run_s_pose(tmp_path, monkeypatch):
    """The split result holds the run's six degrees of freedom: x, y, z in body_position [m], roll, pitch,
    yaw in body_rotation [rad], to the bit (the same floats, only their place changed)."""
    ds, _ = _result("system_dynamic", tmp_path, monkeypatch)
    assert ds.body_position.attrs["units"] == "m" and ds.body_rotation.attrs["units"] == "rad"
    assert list(ds.axis.values) == ["x", "y", "z"] and list(ds.angle.values) == ["roll", "pitch", "yaw"]
    pose = body_pose(ds)
    # a buoy moored on its waterline reference point: z within a metre of 0, rotations small, not metres
    assert abs(pose[0, 0, 2]) < 1.0 and np.abs(pose[..., 3:]).max() < 0.2
    np.testing.assert_array_equal(ds.body_velocity.values, body_pose(ds, "body_velocity", "body_rotation_rate")
                                  [..., :3])

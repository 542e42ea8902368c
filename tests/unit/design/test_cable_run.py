"""The cable checks and range graphs on a real small run (issue 40), and in the design report.

A 160 m cable (EI 2e4 N m^2) from an anchor on the seabed at 100 m to a hang-off 10 m below the surface, clamped
there at 0.1 rad from the vertical, 20 elements: its static equilibrium (a second) and 3 s of a harmonic hang-off
motion. Each check's value is recomputed here from the result's positions and tensions by the vocabulary's
formulas (``curvature`` ``4 sin(theta / 2) / (l1 + l2)`` at an inner node, ``declination`` the end element's angle
from the upward vertical, the clearance ``z + depth``), not read from the module: the same float operations in
another order, so to 1e-9 relative."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
import xarray as xr
import yaml

import seacable as sc
from seacable.design import cable

_HANG = """
name: hang
line_types:
  cable: {diameter: 0.15, mass_per_length: 40, axial_stiffness: 5e8, bending_stiffness: 2e4, minimum_bend_radius: 2.0,
          minimum_bend_radius_dynamic: 4.0, allowable_tension: 2.5e4}
line: {line_type: cable, length: 160}
environment: {depth: 100}
analysis:
  type: mooring_static
  anchor: [0, -100]
  fairlead: [80, -10]
  n_elements: 20
  fairlead_end_condition: {type: clamped, declination: 0.1}
  design: {hang_off_declination: [0.0, 0.3]}
"""
MOTION = {"type": "harmonic", "amplitude": [1.0, 0.0, 0.5], "period": 4.0, "ramp": 1.0}


def _data(**analysis):
    data = yaml.safe_load(_HANG)
    data["analysis"].update(analysis)
    return data


@pytest.fixture(scope="module")
def static():
    return sc.run(sc.Case(**_data()))


@pytest.fixture(scope="module")
def dynamic():
    return sc.run(sc.Case(**_data(type="mooring_dynamic", duration=3.0, time_step=0.1, output_interval=0.5,
                                  motion=MOTION)))


def _inner_curvature(X, i):
    a, b = X[i] - X[i - 1], X[i + 1] - X[i]
    la, lb = np.linalg.norm(a), np.linalg.norm(b)
    theta = math.acos(np.clip(a @ b / (la * lb), -1.0, 1.0))
    return 4.0 * math.sin(theta / 2) / (la + lb)


def test_the_checks_of_a_static_run(static):
    ds = static
    X = np.column_stack([ds[k].values for k in "xyz"])
    rows = {r.check: r for r in cable.cable_checks(ds)}
    curv = rows["curvature (static MBR)"]
    i = int(np.flatnonzero(ds["s"].values == curv.s)[0])
    assert 0 < i < 20  # the touchdown's sag bend, an inner node
    assert curv.value == pytest.approx(_inner_curvature(X, i), rel=1e-9)
    assert curv.utilisation == pytest.approx(_inner_curvature(X, i) * 2.0, rel=1e-9) and curv.limit == 0.5
    ten = rows["tension"]
    assert ten.value == float(ds.segment_tension.max()) and ten.utilisation == pytest.approx(ten.value / 2.5e4, rel=1e-12)
    assert rows["compression"].value == float(ds.segment_tension.min()) and rows["compression"].passed
    d = X[-1] - X[-2]
    decl = math.atan2(math.hypot(d[0], d[1]), d[2])
    lo, hi = rows["hang-off declination (lowest)"], rows["hang-off declination (highest)"]
    assert lo.value == pytest.approx(decl, rel=1e-9) and hi.value == lo.value
    assert hi.utilisation == pytest.approx(decl / 0.3, rel=1e-9) and hi.passed is (decl <= 0.3)
    assert "no arch" in rows["sag bend clearance"].status  # a plain catenary to its touchdown
    rg = cable.range_graphs(ds)
    assert np.allclose(rg["seabed_clearance_min"], ds.z.values + 100.0, rtol=0, atol=1e-12)
    assert np.array_equal(rg["curvature_max"], ds.curvature.values)


def test_the_checks_of_a_dynamic_run_take_its_extremes_and_the_dynamic_mbr(dynamic, static):
    dd = dynamic
    rows = {r.check: r for r in cable.cable_checks(dd)}
    curv = rows["curvature (dynamic MBR)"]
    k = np.unravel_index(int(np.argmax(dd.curvature.values)), dd.curvature.shape)
    assert curv.value == float(dd.curvature.values[k]) and curv.time == float(dd.time[k[0]])
    assert curv.limit == 0.25 and curv.utilisation == pytest.approx(curv.value * 4.0, rel=1e-12)
    assert curv.value > float(static.curvature.max())  # the motion bends the sag bend harder than the statics
    rg = cable.range_graphs(dd)
    assert np.allclose(rg["tension_max"], dd.tension.max("time")) and rg.attrs["states"] == dd.sizes["time"]


def test_the_report_has_the_cable_section_of_a_result_with_curvature(dynamic, tmp_path):
    from seacable.report import make_report

    written = make_report(dynamic, tmp_path / "report.html")
    names = [p.name for p in written]
    assert "report_cable_checks.csv" in names and "report_range_graphs.nc" in names
    page = (tmp_path / "report.html").read_text()
    assert "6. Cable: range graphs and checks" in page and "Range graphs of line" in page
    table = pd.read_csv(tmp_path / "report_cable_checks.csv")
    ours = cable.cable_check_table(cable.cable_checks(dynamic))
    assert list(table["check"]) == list(ours["check"])
    assert np.allclose(table["value [see unit]"], ours["value"], equal_nan=True, rtol=1e-15)
    with xr.open_dataset(tmp_path / "report_range_graphs.nc") as rg:
        xr.testing.assert_allclose(rg.load(), cable.range_graphs(dynamic))


def test_a_result_without_curvature_gets_the_report_it_had(tmp_path):
    from seacable.report import make_report

    data = _data(type="mooring_dynamic", duration=3.0, time_step=0.1, output_interval=0.5, motion=MOTION)
    data["line_types"]["cable"]["bending_stiffness"] = 0.0
    del data["analysis"]["fairlead_end_condition"]
    ds = sc.run(sc.Case(**data))
    assert "curvature" not in ds
    written = make_report(ds, tmp_path / "report.html")
    assert sorted(p.name for p in written) == sorted(
        ["report.html", "report_extremes.csv", "report_seeds.csv", "report_checks.csv", "report_fatigue.csv",
         "report_components.csv", "report_combined.csv"])
    assert "Cable" not in (tmp_path / "report.html").read_text()


def test_the_report_envelopes_a_load_cases_seeds_and_keeps_load_cases_apart(dynamic, tmp_path):
    """Two seeds of one load case (the second's curvature 1.1 and 0.9 times the first's at alternate nodes): the
    report's range graphs are their envelope (the larger maximum at each node, the mean of the means); two load
    cases: a load_case dimension, and the checks of each run in the CSV."""
    from seacable.report import make_report

    other = dynamic.copy(deep=True)
    other["curvature"] = other["curvature"] * xr.DataArray(np.where(np.arange(21) % 2, 1.1, 0.9), dims="node")
    make_report({"storm": [dynamic, other]}, tmp_path / "one" / "report.html")
    first, second = cable.range_graphs(dynamic), cable.range_graphs(other)
    with xr.open_dataset(tmp_path / "one" / "report_range_graphs.nc") as rg:
        assert np.allclose(rg["curvature_max"], np.fmax(first["curvature_max"], second["curvature_max"]))
        assert np.allclose(rg["curvature_mean"], 0.5 * (first["curvature_mean"] + second["curvature_mean"]))
        assert rg.attrs["states"] == 2 * dynamic.sizes["time"]
    make_report({"near": [dynamic], "far": [other]}, tmp_path / "two" / "report.html")
    with xr.open_dataset(tmp_path / "two" / "report_range_graphs.nc") as rg:
        assert list(rg["load_case"].values) == ["near", "far"]
        assert np.allclose(rg["curvature_max"].sel(load_case="far"), second["curvature_max"])
    table = pd.read_csv(tmp_path / "two" / "report_cable_checks.csv")
    assert sorted(set(table["load_case"])) == ["far", "near"] and len(table) == 14

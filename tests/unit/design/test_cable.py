"""Range graphs and cable checks of a line with bending stiffness (issue 40, :mod:`seacable.design.cable`).

Each check is computed here by hand on a small Dataset built for it (a few nodes, two or three states), the
numbers written out in the test, not read from the module; then on a real small run. The arithmetic is a few
float operations on given numbers: relative tolerance 1e-12 (a few units in the last place of float64), and
the flips at a limit are asserted exactly (the limit itself passes: margin 0, utilisation 1)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr
import yaml

from seacable.design import cable
from seacable.design.cable import CableLimits, cable_check_table, cable_checks, cable_limits, range_graphs
from seacable.errors import InputError
from seacable.results import var

REL = 1e-12

#: s of the 7 nodes [m]; the line rises from the anchor, arches at node 3 and sags at node 5 before end B.
S = np.array([0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0])
X = np.array([0.0, 10.0, 19.0, 27.0, 35.0, 43.0, 50.0])
#: heights above a flat seabed at 100 m, per state (3 times): the arch falls and the sag bend comes down
H = np.array([[0.0, 8.0, 20.0, 30.0, 22.0, 15.0, 40.0],
              [0.0, 8.0, 19.0, 27.0, 21.0, 12.0, 40.0],
              [0.0, 8.0, 21.0, 29.0, 23.0, 14.0, 40.0]])
#: curvature [1/m] per state: largest 0.25 at node 3, t = 1 s
KAPPA = np.array([[0.0, 0.01, 0.05, 0.20, 0.04, 0.06, 0.10],
                  [0.0, 0.01, 0.06, 0.25, 0.05, 0.07, 0.12],
                  [0.0, 0.01, 0.04, 0.18, 0.03, 0.05, 0.09]])
#: element tensions [N] per state: the largest 9000 N in element 5 at t = 2 s, the smallest -300 N in element 2
#: at t = 1 s
TENSION = np.array([[5000.0, 4000.0, 500.0, 1000.0, 3000.0, 8000.0],
                    [5100.0, 3900.0, -300.0, 900.0, 3100.0, 8500.0],
                    [5200.0, 4100.0, 100.0, 1100.0, 3200.0, 9000.0]])
#: declination at the nodes [rad]; at end B (node 6) 0.20, 0.35, 0.15 rad at t = 0, 1, 2 s
DECL = np.array([[1.5, 1.2, 1.0, 1.57, 2.0, 1.0, 0.20],
                 [1.5, 1.2, 1.0, 1.57, 2.0, 1.0, 0.35],
                 [1.5, 1.2, 1.0, 1.57, 2.0, 1.0, 0.15]])
DEPTH = 100.0
TIMES = np.array([0.0, 1.0, 2.0])


def _case(line_types=None, segments=None, design=None, environment=None, analysis="mooring_dynamic") -> str:
    lt = line_types or {"cable": {"diameter": 0.15, "mass_per_length": 40.0}}
    data = {"name": "c", "line_types": lt,
            "line": {"segments": segments or [{"line_type": "cable", "length": 60.0}]},
            "environment": environment or {"depth": DEPTH},
            "analysis": {"type": analysis, **({"design": design} if design else {})}}
    return yaml.safe_dump(data)


def _result(*, states=True, case=None, analysis="mooring_dynamic", height=H, kappa=KAPPA, tension=TENSION,
            decl=DECL, z=None, attrs=None):
    """A mooring result of 7 nodes and 6 elements: over 3 times (``states``) or the first state alone."""
    pick = (lambda a: a) if states else (lambda a: a[0])
    dims = ("time", "node") if states else ("node",)
    edims = ("time", "element") if states else ("element",)
    zz = (height - DEPTH) if z is None else z
    xs = np.broadcast_to(X, zz.shape)
    data = {"x": var(dims, pick(xs), "m", "x"), "y": var(dims, pick(0 * xs), "m", "y"),
            "z": var(dims, pick(zz), "m", "z"),
            "tension": var(dims, pick(np.column_stack([tension[:, :1], 0.5 * (tension[:, :-1] + tension[:, 1:]),
                                                       tension[:, -1:]])), "N", "tension"),
            "segment_tension": var(edims, pick(tension), "N", "element tension"),
            "curvature": var(dims, pick(kappa), "1/m", "curvature"),
            "bend_moment": var(dims, pick(2e4 * kappa), "N m", "bend moment"),
            "declination": var(dims, pick(decl), "rad", "declination"),
            "shear_force": var(edims, pick(np.abs(np.diff(2e4 * kappa, axis=-1)) / 10.0), "N", "shear")}
    coords = {"node": ("node", np.arange(7)), "s": ("node", S, {"units": "m", "long_name": "arc length"}),
              "element": ("element", np.arange(6))}
    if states:
        coords["time"] = ("time", TIMES, {"units": "s", "long_name": "time"})
    a = {"analysis": analysis, "case_name": "c", "case": case if case is not None else _case(analysis=analysis)}
    a.update(attrs or {})
    return xr.Dataset(data, coords=coords, attrs=a)


# ------------------------------------------------------------------------------------------- range graphs

def test_range_graphs_min_max_mean_along_s(tmp_path):
    """At node 3 the curvature is 0.20, 0.25, 0.18 1/m over the three times: min 0.18, max 0.25, mean 0.21;
    the seabed clearance z + 100 m is H; the shear per element; units and long names; NetCDF round trip."""
    rg = range_graphs(_result())
    assert rg["curvature_min"][3] == pytest.approx(0.18, rel=REL)
    assert rg["curvature_max"][3] == pytest.approx(0.25, rel=REL)
    assert rg["curvature_mean"][3] == pytest.approx(0.21, rel=REL)
    assert np.allclose(rg["seabed_clearance_min"], H.min(axis=0), rtol=0, atol=1e-12)
    assert rg["seabed_clearance_max"][5] == pytest.approx(15.0, abs=1e-12)
    assert rg["tension_max"][6] == 9000.0 and rg["tension_min"][2] == pytest.approx(0.5 * (3900 - 300), rel=REL)
    assert rg["declination_mean"][6] == pytest.approx((0.20 + 0.35 + 0.15) / 3, rel=REL)
    assert rg["bend_moment_max"].attrs["units"] == "N m" and rg["curvature_max"].attrs["units"] == "1/m"
    assert rg["seabed_clearance_mean"].attrs["long_name"] == "mean height above the seabed"
    assert rg["shear_force_max"].dims == ("element",) and rg["element_s"][0] == 5.0
    assert rg.attrs["statistics_over"] == "time" and rg.attrs["states"] == 3
    path = tmp_path / "rg.nc"
    rg.to_netcdf(path)
    with xr.open_dataset(path) as back:
        xr.testing.assert_identical(back.load(), rg)


def test_range_graphs_of_a_static_result_are_its_values():
    rg = range_graphs(_result(states=False, analysis="mooring_static"))
    for q in ("tension", "curvature", "bend_moment", "declination", "seabed_clearance"):
        assert np.array_equal(rg[f"{q}_min"], rg[f"{q}_max"]) and np.array_equal(rg[f"{q}_min"], rg[f"{q}_mean"])
    assert np.array_equal(rg["curvature_max"], KAPPA[0]) and rg.attrs["statistics_over"] == "none"


def test_seabed_clearance_on_a_slope_a_profile_and_attrs_depth():
    """A slope of 0.1 rad rising towards +x: the seabed at x is -100 + x tan(0.1) m, so node 6 (x = 50 m) at
    z = -60 m stands 40 - 50 tan(0.1) = 34.983 m above it; a profile of depths 100 m at x = 0 and 80 m at x = 100 m
    puts the seabed at -90 m under x = 50 m (clearance 30 m); without a case, attrs['depth'] gives a flat seabed."""
    sloped = _result(case=_case(environment={"depth": DEPTH, "seabed": {"slope": 0.1}}))
    h = cable.seabed_clearance(sloped)
    assert float(h[0, 6]) == pytest.approx(40.0 - 50.0 * math.tan(0.1), rel=REL)
    profiled = _result(case=_case(environment={"seabed": {"profile": {"distance": [0.0, 100.0],
                                                                        "depth": [100.0, 80.0]}}}))
    assert float(cable.seabed_clearance(profiled)[0, 6]) == pytest.approx(30.0, rel=REL)
    bare = _result(case="", attrs={"depth": 100.0})
    assert float(cable.seabed_clearance(bare)[1, 5]) == pytest.approx(12.0, rel=REL)
    assert cable.seabed_clearance(_result(case="")) is None
    assert "seabed_clearance_min" not in range_graphs(_result(case=""))


def test_the_figure_has_a_panel_a_quantity():
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    ds = _result(case=_case(line_types={"cable": {"diameter": 0.15, "mass_per_length": 40.0,
                                                  "minimum_bend_radius_dynamic": 5.0, "allowable_tension": 1e4}}))
    fig = cable.plot_range_graphs(range_graphs(ds), cable_limits(ds))
    labels = [ax.get_ylabel() for ax in fig.axes]
    assert labels == ["effective tension [kN]", "curvature [1/m]", "bend moment [kN m]", "declination [deg]",
                      "height above seabed [m]"]
    limit = [line for line in fig.axes[1].lines if line.get_label().startswith("1 / MBR")]
    assert limit and np.allclose(limit[0].get_ydata(), 0.2)  # 1 / 5 m
    plt.close(fig)


# ------------------------------------------------------------------------------------------------ checks

def _by_check(rows):
    return {r.check: r for r in rows}


def test_curvature_against_the_dynamic_mbr():
    """Dynamic MBR 3 m: the largest kappa MBR is 0.25 x 3 = 0.75 (node 3, s = 30 m, t = 1 s), margin
    1/3 - 0.25 = 0.083333 1/m. A radius mistaken for a curvature (kappa / MBR = 0.0833, or R / MBR) gives
    another utilisation."""
    limits = CableLimits.uniform(7, minimum_bend_radius=2.0, minimum_bend_radius_dynamic=3.0)
    r = cable_checks(_result(), limits)[0]
    assert r.check == "curvature (dynamic MBR)" and r.unit == "1/m" and r.bound == "max"
    assert r.value == 0.25 and r.limit == pytest.approx(1 / 3, rel=REL)
    assert r.utilisation == pytest.approx(0.75, rel=REL)
    assert r.margin == pytest.approx(1 / 3 - 0.25, rel=REL)
    assert r.passed and r.status == "pass" and (r.s, r.time) == (30.0, 1.0) and math.isnan(r.offset)
    assert "bend radius 1 / kappa = 4 m" in r.formula


def test_the_static_mbr_is_for_a_static_result_and_the_dynamic_for_a_dynamic_run():
    """A static result takes the static MBR (2 m: 0.20 x 2 = 0.40), a dynamic run the dynamic one; a run given
    only the other one is not checked (a static MBR would pass this run's 0.25 1/m at 2 m: 0.5 < 1, where the
    dynamic limit of 5 m fails it: 1.25)."""
    both = CableLimits.uniform(7, minimum_bend_radius=2.0, minimum_bend_radius_dynamic=5.0)
    static = cable_checks(_result(states=False, analysis="mooring_static"), both)[0]
    assert static.check == "curvature (static MBR)" and static.utilisation == pytest.approx(0.40, rel=REL)
    assert math.isnan(static.time)
    dynamic = cable_checks(_result(), both)[0]
    assert dynamic.utilisation == pytest.approx(1.25, rel=REL) and not dynamic.passed and dynamic.status == "FAIL"
    only_static = cable_checks(_result(), CableLimits.uniform(7, minimum_bend_radius=2.0))[0]
    assert only_static.passed is None and "no line type gives minimum_bend_radius_dynamic" in only_static.status
    only_dynamic = cable_checks(_result(states=False, analysis="mooring_static"),
                                CableLimits.uniform(7, minimum_bend_radius_dynamic=5.0))[0]
    assert only_dynamic.passed is None and "no line type gives minimum_bend_radius " in only_dynamic.status


@pytest.mark.parametrize("mbr, passed", [(4.0, True), (4.0 * (1 + 1e-12), False), (4.0 * (1 - 1e-12), True)])
def test_curvature_flips_at_the_limit(mbr, passed):
    """kappa = 0.25 1/m is a bend radius of 4 m: an MBR of 4 m is the limit (utilisation 1, margin 0, pass)."""
    r = cable_checks(_result(), CableLimits.uniform(7, minimum_bend_radius_dynamic=mbr))[0]
    assert r.passed is passed and (r.utilisation > 1.0) is (not passed)


def test_tension_and_compression():
    """Allowable 10 kN: the largest element tension 9000 N (element 5, s = 55 m, t = 2 s), utilisation 0.9; the
    smallest -300 N (element 2, s = 25 m, t = 1 s) against no compression: margin -300 N, FAIL, no ratio; with
    500 N of compression allowed: margin 200 N, utilisation 0.6; with 300 N: the limit (margin 0, pass)."""
    rows = _by_check(cable_checks(_result(), CableLimits.uniform(7, allowable_tension=1e4)))
    t, c = rows["tension"], rows["compression"]
    assert (t.value, t.limit, t.s, t.time, t.quantity) == (9000.0, 1e4, 55.0, 2.0, "segment_tension")
    assert t.utilisation == pytest.approx(0.9, rel=REL) and t.margin == 1000.0 and t.passed
    assert (c.value, c.limit, c.s, c.time, c.margin, c.passed, c.utilisation) == (-300.0, 0.0, 25.0, 1.0, -300.0,
                                                                                   False, None)
    c = _by_check(cable_checks(_result(), CableLimits.uniform(7, allowable_compression=500.0)))["compression"]
    assert (c.limit, c.margin, c.passed) == (-500.0, 200.0, True) and c.utilisation == pytest.approx(0.6, rel=REL)
    c = _by_check(cable_checks(_result(), CableLimits.uniform(7, allowable_compression=300.0)))["compression"]
    assert c.margin == 0.0 and c.passed and c.utilisation == 1.0
    t = _by_check(cable_checks(_result(), CableLimits.uniform(7, allowable_tension=9000.0 * (1 - 1e-12))))["tension"]
    assert not t.passed and t.utilisation > 1.0


def test_limits_by_segment_from_the_case():
    """Two segments (0-30 m: allowable 20 kN, MBR 2 m; 30-60 m: 8.5 kN, MBR 6 m): the tension's worst is element 5
    (9000 / 8500 = 1.0588) and element 0's 5200 N counts against 20 kN; node 3 at the joint takes the stricter
    MBR, 6 m (0.25 x 6 = 1.5); the design block's clearances and range are read; the limits go with the case."""
    types = {"a": {"diameter": 0.15, "mass_per_length": 40.0, "allowable_tension": 2e4, "minimum_bend_radius_dynamic": 2.0},
             "b": {"diameter": 0.15, "mass_per_length": 40.0, "allowable_tension": 8500.0,
                   "minimum_bend_radius_dynamic": 6.0, "allowable_compression": 1000.0}}
    case = _case(line_types=types, segments=[{"line_type": "a", "length": 30.0}, {"line_type": "b", "length": 30.0}],
                 design={"sag_bend_clearance": 5.0, "hang_off_declination": [0.1, 0.3]})
    ds = _result(case=case)
    limits = cable_limits(ds)
    assert list(limits.minimum_bend_radius_dynamic) == [2.0, 2.0, 2.0, 6.0, 6.0, 6.0, 6.0]
    assert limits.minimum_bend_radius is None and limits.sag_bend_clearance == 5.0
    assert limits.hang_off_declination == (0.1, 0.3)
    assert list(limits.element_allowable_tension) == [2e4, 2e4, 2e4, 8500.0, 8500.0, 8500.0]
    assert list(limits.element_allowable_compression) == [0.0, 0.0, 0.0, 1000.0, 1000.0, 1000.0]
    rows = _by_check(cable_checks(ds))
    assert rows["tension"].utilisation == pytest.approx(9000 / 8500, rel=REL) and rows["tension"].s == 55.0
    assert rows["curvature (dynamic MBR)"].utilisation == pytest.approx(1.5, rel=REL)
    assert rows["curvature (dynamic MBR)"].s == 30.0
    assert rows["compression"].value == -300.0 and rows["compression"].limit == 0.0  # element 2 lies in segment a


def test_the_worst_point_is_by_utilisation_not_by_value():
    """Segments 0-35 m (MBR 10 m, no compression) and 35-60 m (MBR 1 m, 1000 N of compression allowed): the worst
    curvature is node 3's 0.25 x 10 = 2.5 (s = 30 m), not node 6's larger share of its own radius (0.12 / 1 m
    over 0.25 / 10 m, what kappa / MBR would pick); the worst compression is element 2's -300 N against none
    (margin -300 N), not element 4's -800 N against 1000 N allowed (margin +200 N)."""
    types = {"a": {"diameter": 0.15, "mass_per_length": 40.0, "minimum_bend_radius_dynamic": 10.0},
             "b": {"diameter": 0.15, "mass_per_length": 40.0, "minimum_bend_radius_dynamic": 1.0,
                   "allowable_compression": 1000.0}}
    case = _case(line_types=types, segments=[{"line_type": "a", "length": 35.0}, {"line_type": "b", "length": 25.0}])
    tension = TENSION.copy()
    tension[0, 4] = -800.0
    rows = _by_check(cable_checks(_result(case=case, tension=tension)))
    curv, comp = rows["curvature (dynamic MBR)"], rows["compression"]
    assert (curv.value, curv.s, curv.time) == (0.25, 30.0, 1.0) and curv.utilisation == pytest.approx(2.5, rel=REL)
    assert (comp.value, comp.limit, comp.margin, comp.s, comp.passed) == (-300.0, 0.0, -300.0, 25.0, False)


def test_sag_and_hog_bend_clearance():
    """The mean shape's arch is node 3 (28.67 m), its sag bend node 5 (13.67 m), the low point before it node 0.
    The sag bend comes down to 12 m (node 5, s = 50 m, t = 1 s): with 5 m required, margin 7 m, utilisation
    5/12; the crest falls to 27 m at t = 1 s (node 3): with 10 m required, margin 17 m. 12 m required is the
    sag bend's limit (pass), more fails; a sag bend that touches down (height 0 at a state) fails the default."""
    limits = CableLimits.uniform(7, sag_bend_clearance=5.0, hog_bend_clearance=10.0)
    rows = _by_check(cable_checks(_result(), limits))
    sag, hog = rows["sag bend clearance"], rows["hog bend clearance"]
    assert (sag.value, sag.limit, sag.margin, sag.s, sag.time, sag.bound) == (12.0, 5.0, 7.0, 50.0, 1.0, "min")
    assert sag.utilisation == pytest.approx(5.0 / 12.0, rel=REL) and sag.passed
    assert (hog.value, hog.limit, hog.margin, hog.s, hog.time) == (27.0, 10.0, 17.0, 30.0, 1.0)
    assert cable.bends(H.mean(axis=0)) == (0, 3, 5)
    at = _by_check(cable_checks(_result(), CableLimits.uniform(7, sag_bend_clearance=12.0)))["sag bend clearance"]
    assert at.passed and at.margin == 0.0 and at.utilisation == 1.0
    over = _by_check(cable_checks(_result(), CableLimits.uniform(7, sag_bend_clearance=12.5)))["sag bend clearance"]
    assert not over.passed and over.margin == -0.5
    touch = H.copy()
    touch[2, 5] = -0.002  # the sag bend on the seabed at t = 2 s (the contact's penetration)
    down = _by_check(cable_checks(_result(height=touch), CableLimits.uniform(7)))["sag bend clearance"]
    assert not down.passed and down.value == pytest.approx(-0.002, abs=1e-12) and down.time == 2.0
    assert down.utilisation is None


def test_a_catenary_has_no_arch_to_check():
    plain = np.array([[0.0, 0.0, 0.0, 2.0, 8.0, 20.0, 40.0]] * 3)
    rows = _by_check(cable_checks(_result(height=plain), CableLimits.uniform(7)))
    assert rows["sag bend clearance"].passed is None and "no arch" in rows["sag bend clearance"].status
    assert cable.bends(plain[0]) is None


def test_hang_off_declination_range():
    """End B's declination is 0.20, 0.35, 0.15 rad: against (0.1, 0.4) both rows pass, the lowest 0.15 with margin
    0.05 rad and utilisation (0.4 - 0.15) / 0.3 = 0.8333 (t = 2 s), the highest 0.35 with margin 0.05 and
    (0.35 - 0.1) / 0.3 = 0.8333 (t = 1 s); against (0.1, 0.3) the highest fails by 0.05 rad."""
    rows = _by_check(cable_checks(_result(), CableLimits.uniform(7, hang_off_declination=(0.1, 0.4))))
    lo, hi = rows["hang-off declination (lowest)"], rows["hang-off declination (highest)"]
    assert (lo.value, lo.limit, lo.time, lo.s, lo.bound) == (0.15, 0.1, 2.0, 60.0, "min")
    assert lo.margin == pytest.approx(0.05, rel=1e-9) and lo.utilisation == pytest.approx(0.25 / 0.3, rel=1e-12)
    assert (hi.value, hi.limit, hi.time) == (0.35, 0.4, 1.0) and hi.utilisation == pytest.approx(0.25 / 0.3, rel=REL)
    hi = _by_check(cable_checks(_result(), CableLimits.uniform(7, hang_off_declination=(0.1, 0.3))))[
        "hang-off declination (highest)"]
    assert not hi.passed and hi.margin == pytest.approx(-0.05, rel=1e-9) and hi.utilisation > 1.0
    at = _by_check(cable_checks(_result(), CableLimits.uniform(7, hang_off_declination=(0.15, 0.35))))
    assert at["hang-off declination (lowest)"].passed and at["hang-off declination (highest)"].passed
    assert at["hang-off declination (highest)"].utilisation == 1.0


def test_the_table_has_every_check_with_where_and_when():
    table = cable_check_table(cable_checks(_result(), CableLimits.uniform(7)))
    assert list(table["check"]) == ["curvature (dynamic MBR)", "tension", "compression", "sag bend clearance",
                                    "hog bend clearance", "hang-off declination (lowest)",
                                    "hang-off declination (highest)"]
    assert {"value", "limit", "unit", "utilisation", "margin", "passed", "status", "s", "time"} <= set(table)
    assert table["status"].str.startswith("not checked").sum() == 4  # no MBR, allowable or range given


@pytest.mark.parametrize("kwargs, message", [
    ({"minimum_bend_radius": 0.0}, r"limits.minimum_bend_radius must be > 0 m, got 0 m"),
    ({"minimum_bend_radius_dynamic": -2.0}, r"limits.minimum_bend_radius_dynamic must be > 0 m, got -2 m"),
    ({"minimum_bend_radius": 3.0, "minimum_bend_radius_dynamic": 2.0}, r"dynamic 2 m is smaller than .* 3 m"),
    ({"allowable_tension": 0.0}, r"limits.allowable_tension must be > 0 N"),
    ({"allowable_compression": -1.0}, r"limits.allowable_compression must be >= 0 N"),
    ({"sag_bend_clearance": -1.0}, r"limits.sag_bend_clearance must be >= 0 m"),
    ({"hang_off_declination": (10.0, 20.0)}, r"looks like degrees"),
    ({"hang_off_declination": (0.3, 0.1)}, r"lowest < highest"),
    ({"minimum_bend_radius": math.nan}, r"limits.minimum_bend_radius must be a finite number"),
])
def test_bad_limits_are_refused_with_one_clear_message(kwargs, message):
    with pytest.raises(InputError, match=message) as err:
        CableLimits.uniform(7, **kwargs)
    assert "Suggested fix" in str(err.value) and len(err.value.problems) == 1


def test_the_limits_go_into_a_dumped_case_only_when_given():
    """A case without cable limits dumps as it did before they existed (so its results' 'case' attribute, and their
    fingerprints, are unchanged); one with them keeps them through a dump and a reload."""
    import seacable as sc
    from seacable._model import dump_yaml

    data = yaml.safe_load(_case(analysis="mooring_static"))
    data["line"]["segments"][0]["length"] = 60.0
    data["line_types"]["cable"]["axial_stiffness"] = 1e8
    data["analysis"].update(fairlead=[40.0, -10.0])
    plain = dump_yaml(sc.Case(**data))
    assert "minimum_bend_radius" not in plain and "allowable_" not in plain and "design" not in plain
    data["line_types"]["cable"].update(minimum_bend_radius=2.0, allowable_compression=0.0)
    data["analysis"]["design"] = {"hang_off_declination": [0.1, 0.3]}
    text = dump_yaml(sc.Case(**data))
    again = sc.Case(**yaml.safe_load(text))
    assert again.line.segments[0].line_type.minimum_bend_radius == 2.0
    assert again.line.segments[0].line_type.allowable_compression == 0.0
    assert again.analysis.design.hang_off_declination == (0.1, 0.3)
    assert dump_yaml(again) == text


def test_an_mbr_in_millimetres_is_warned_about():
    import seacable as sc
    from seacable.errors import SeacableWarning

    with pytest.warns(SeacableWarning, match=r"minimum_bend_radius = 3000 m is over 1000 times the diameter 0.15 m"):
        sc.LineType(diameter=0.15, mass_per_length=40.0, minimum_bend_radius=3000.0)


def test_a_result_of_several_lines_is_read_line_by_line():
    """A result with a ``line`` dimension (a MoorDyn deck's): line 'b' is line 'a' with a node less, padded with
    NaN as the results pad a shorter line; its checks and range graphs are its own nodes'; a missing name is
    refused naming the lines."""
    a = _result()
    b = a.copy(deep=True)
    for v in ("x", "y", "z", "tension", "curvature", "bend_moment", "declination"):
        b[v].values[..., -1] = np.nan
    b["z"].values[:, 5] = H[:, 5] - DEPTH - 1.0  # its sag bend a metre lower
    both = xr.concat([a, b], dim="line").assign_coords(line=["a", "b"])
    sag = _by_check(cable_checks(both, CableLimits.uniform(7), line="b"))["sag bend clearance"]
    assert sag.passed and sag.value == 11.0 and (sag.s, sag.time) == (50.0, 1.0)
    rg = range_graphs(both, line="b")
    assert rg["curvature_max"][3] == 0.25 and np.isnan(rg["curvature_max"][6])
    with pytest.raises(InputError, match=r"the result holds the lines \['a', 'b'\]; line='c'"):
        range_graphs(both, line="c")

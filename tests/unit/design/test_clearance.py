"""The smallest distance from a cable to the other lines of its system (seacable.design.clearance, issue 40): closed
forms of straight lines, and the check against analysis.design.line_clearance."""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr
import yaml

from seacable.design.clearance import line_clearance_check, line_distance, segment_distances
from seacable.errors import InputError


def _system(lines: dict[str, np.ndarray], times=None, design: dict | None = None) -> xr.Dataset:
    """A system result of polylines: name -> positions (time, node, 3) [m] (or (node, 3) for one state), padded with
    NaN to the longest; ``s`` the polyline's own arc length (straight lines: unstretched)."""
    names = list(lines)
    n = max(p.shape[-2] for p in lines.values())
    timed = times is not None
    nt = len(times) if timed else 1
    xyz = np.full((nt, len(names), n, 3), np.nan)
    s = np.full((len(names), n), np.nan)
    for k, name in enumerate(names):
        p = lines[name] if timed else lines[name][None]
        xyz[:, k, :p.shape[1]] = p
        s[k, :p.shape[1]] = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(p[0], axis=0), axis=1))])
    dims = ("time", "line", "node") if timed else ("line", "node")
    data = {c: (dims, xyz[..., i] if timed else xyz[0, ..., i]) for i, c in enumerate("xyz")}
    coords = {"line": names, "s": (("line", "node"), s)}
    if timed:
        coords["time"] = np.asarray(times, float)
    case = {"name": "sys", "analysis": {"type": "system_dynamic" if timed else "system_static"}}
    if design is not None:
        case["analysis"]["design"] = design
    return xr.Dataset(data, coords=coords, attrs={"analysis": case["analysis"]["type"], "case": yaml.safe_dump(case)})


def _straight(a, b, n):
    return np.linspace(np.asarray(a, float), np.asarray(b, float), n)


def test_two_crossing_straight_lines_are_their_offset_apart_where_they_cross():
    # closed form: line A along x at z = 0 from x = -50 to 50; line B along (cos 30 deg, sin 30 deg, 0) at height h
    # through (x0, y0, h). Their common normal is z: the distance is h, at the point of A under the crossing
    # (x0 - y0 / tan 30 deg, 0, 0), s_A = that x + 50, and on B at the same point's arc length from its end A.
    # The nodes (11 on A, 7 on B) do not fall on the crossing: the segments' own closest points find it.
    h, x0, y0 = 3.7, 4.0, 2.0
    u = np.array([math.cos(math.radians(30)), math.sin(math.radians(30)), 0.0])
    start = np.array([x0, y0, h]) - 40.0 * u
    ds = _system({"cable": _straight((-50, 0, 0), (50, 0, 0), 11), "chain": _straight(start, start + 80.0 * u, 7)})
    (d,) = line_distance(ds, "cable")
    x_cross = x0 - y0 / math.tan(math.radians(30))
    assert d.other == "chain"
    # exact to round-off: straight segments are the lines themselves
    assert d.distance == pytest.approx(h, abs=1e-12)
    assert d.s == pytest.approx(x_cross + 50.0, abs=1e-9)
    assert d.s_other == pytest.approx(40.0 - y0 / math.sin(math.radians(30)), abs=1e-9)
    assert d.position == pytest.approx((x_cross, 0.0, 0.0), abs=1e-9)
    assert d.position_other == pytest.approx((x_cross, 0.0, h), abs=1e-9)
    assert math.isnan(d.time)


def test_the_smallest_distance_over_time_is_found_where_and_when_it_is():
    # the chain crosses over the cable at a height h(t) = 5 + 2 cos(2 pi t / 10), least (3 m) at t = 5 s; the
    # cable's segment under the crossing moves nowhere. Each state's distance is h(t) exactly.
    t = np.arange(0.0, 10.01, 0.5)
    h = 5.0 + 2.0 * np.cos(2 * np.pi * t / 10.0)
    cable = np.repeat(_straight((0, 0, -100), (100, 0, -100), 21)[None], t.size, axis=0)
    chain = np.stack([_straight((30, -40, -100 + hk), (30, 40, -100 + hk), 9) for hk in h])
    ds = _system({"cable": cable, "chain": chain}, times=t)
    (d,) = line_distance(ds, "cable")
    np.testing.assert_allclose(d.history.values, h, atol=1e-12)
    assert d.distance == pytest.approx(3.0, abs=1e-12) and d.time == 5.0
    assert d.s == pytest.approx(30.0, abs=1e-9) and d.s_other == pytest.approx(40.0, abs=1e-9)


def test_parallel_and_end_to_end_segments():
    # parallel segments 2 m apart, overlapping: 2 m; collinear segments end to end with a 1.5 m gap: 1.5 m; a
    # segment against one of no length (a point) 0.5 m off its middle: 0.5 m
    d, _, _ = segment_distances([0, 0, 0], [10, 0, 0], [3, 2, 0], [20, 2, 0])
    assert d == pytest.approx(2.0, abs=1e-12)
    d, a, b = segment_distances([0, 0, 0], [10, 0, 0], [11.5, 0, 0], [20, 0, 0])
    assert (d, a, b) == pytest.approx((1.5, 1.0, 0.0), abs=1e-12)
    d, a, _ = segment_distances([0, 0, 0], [10, 0, 0], [5, 0.5, 0], [5, 0.5, 0])
    assert (d, a) == pytest.approx((0.5, 0.5), abs=1e-12)


def test_the_check_against_the_case_limit():
    h = 3.7
    lines = {"cable": _straight((-50, 0, 0), (50, 0, 0), 11), "chain": _straight((0, -50, h), (0, 50, h), 11),
             "chain2": _straight((-50, 20, 0), (50, 20, 0), 3)}
    fails = line_clearance_check(_system(lines, design={"line_clearance": 5.0}), "cable")
    assert fails.status == "FAIL" and fails.value == pytest.approx(h) and fails.limit == 5.0
    assert fails.utilisation == pytest.approx(5.0 / h) and fails.margin == pytest.approx(h - 5.0)
    assert "chain " in fails.formula and fails.s == pytest.approx(50.0)
    passes = line_clearance_check(_system(lines), "cable", limit=2.0)
    assert passes.passed and passes.utilisation == pytest.approx(2.0 / h)
    assert line_clearance_check(_system(lines), "cable").status.startswith("not checked")


@pytest.mark.parametrize("bad", [0.0, -3.0, math.nan])
def test_a_bad_clearance_limit_is_refused(bad):
    lines = {"cable": _straight((-50, 0, 0), (50, 0, 0), 11), "chain": _straight((0, -50, 3), (0, 50, 3), 11)}
    with pytest.raises(InputError, match="line_clearance must be a distance > 0 m.*Suggested fix"):
        line_clearance_check(_system(lines), "cable", limit=bad)


def test_a_result_without_lines_or_a_missing_line_is_refused():
    lines = {"cable": _straight((-50, 0, 0), (50, 0, 0), 11), "chain": _straight((0, -50, 3), (0, 50, 3), 11)}
    with pytest.raises(InputError, match="line 'riser' is not in the result.*Suggested fix"):
        line_distance(_system(lines), "riser")
    with pytest.raises(InputError, match="no 'line' dimension.*Suggested fix"):
        line_distance(_system(lines).isel(line=0), "cable")


def test_a_system_cable_s_report_rows_add_its_line_clearance():
    """In the report's cable section (seacable.report_cable), a line of a system result that bends (some non-zero
    curvature: a cable) gets the line-clearance row when the case gives the limit; a line that does not bend (a
    chain: curvature 0) gets none."""
    from types import SimpleNamespace

    from seacable.report_cable import _Cable

    t = np.arange(0.0, 10.01, 0.5)
    h = 5.0 + 2.0 * np.cos(2 * np.pi * t / 10.0)
    cable = np.repeat(_straight((0, 0, -100), (100, 0, -100), 21)[None], t.size, axis=0)
    chain = np.stack([_straight((30, -40, -100 + hk), (30, 40, -100 + hk), 21) for hk in h])
    ds = _system({"cable": cable, "chain": chain}, times=t, design={"line_clearance": 4.0})
    kappa = np.zeros((t.size, 2, 21))
    kappa[:, 0, 5:15] = 0.01
    ds["curvature"] = (("time", "line", "node"), kappa)
    ds["tension"] = (("time", "line", "node"), np.full((t.size, 2, 21), 1.0e4))
    keep = _Cable()
    keep(SimpleNamespace(load_case="storm", name="storm", seed=1), ds)
    table = keep.table()
    rows = table[table["check"] == "line clearance"]
    assert list(rows["line"]) == ["cable"]
    row = rows.iloc[0]
    # the chain comes within 3 m of the cable at t = 5 s: under the 4 m asked
    assert row["status"] == "FAIL" and row["value"] == pytest.approx(3.0) and row["time"] == 5.0


def test_the_66kv_cable_in_its_mooring_system_keeps_clear_of_the_chains():
    """examples/cable_66kv_system.yaml: the cable clamped on the VolturnUS-S, with its three chains, in the storm's
    mean wind and current (a system_static result, on the dimension ``condition``). The configuration is symmetric
    about y = 0 (chains 2 and 3 at +-60 deg, the cable along +x, the loads along +x), so the cable is as far from
    chain 2 as from chain 3; nearest at the hull, between the hang-off and the chains' fairleads."""
    from pathlib import Path

    import seacable as sc

    ds = sc.run(sc.load_case(Path(__file__).parents[3] / "examples" / "cable_66kv_system.yaml"))
    assert "'cable' with sections" in ds.attrs["statics_reason"]  # the finite-element statics, saying why
    assert float(ds.body_x.squeeze()) > 10.0  # the hull drifts along +x, towards the cable's seabed end
    near = {d.other: d for d in line_distance(ds, "cable")}
    # mirror images: the same to the solver's tolerance (1e-8 of the forces; measured 1e-9 m)
    assert near["chain2"].distance == pytest.approx(near["chain3"].distance, abs=1e-6)
    assert near["chain2"].position_other[1] == pytest.approx(-near["chain3"].position_other[1], abs=1e-6)
    # nearest at chain 2's fairlead (its end B, s = 850 m): then the distance is that point's to the cable's polyline,
    # no nearer than to its hang-off's segment (a closed form of the two points' places in the result)
    assert near["chain2"].s_other == pytest.approx(850.0) and math.isnan(near["chain2"].time)  # a static state
    fairlead = ds.sel(point="fairlead2")
    hang_off = ds.sel(point="hang_off")
    to_hang_off = math.dist(*[[float(p[f"point_{c}"].squeeze()) for c in "xyz"] for p in (fairlead, hang_off)])
    assert near["chain2"].distance <= to_hang_off + 1e-9
    assert near["chain2"].distance == pytest.approx(to_hang_off, rel=0.05)  # the cable leaves it 10 deg off vertical
    check = line_clearance_check(ds, "cable")
    assert check.passed and check.limit == 20.0 and check.value == pytest.approx(near["chain2"].distance)
    # the finite-element shape the curvature is of (fe_x, fe_y, fe_z): its hinges' 4 sin(theta/2) / (l1 + l2) at the
    # inner nodes are the result's curvature (the discrete rod's; 7e-9 1/m apart at most, where the grounded cable's
    # hinges are straight to 1e-8 and arccos loses its digits), its ends the profile's
    cable = ds.sel(line="cable").isel(condition=0)
    xyz = np.stack([cable[f"fe_{c}"].values for c in "xyz"], axis=-1)
    xyz = xyz[np.isfinite(xyz).all(axis=1)]
    d = np.diff(xyz, axis=0)
    length = np.linalg.norm(d, axis=1)
    t = d / length[:, None]
    theta = np.arccos(np.clip(np.sum(t[:-1] * t[1:], axis=1), -1.0, 1.0))
    kappa = 4.0 * np.sin(theta / 2.0) / (length[:-1] + length[1:])
    assert kappa == pytest.approx(cable.curvature.values[1:len(xyz) - 1], rel=1e-9, abs=1e-8)
    assert xyz[-1] == pytest.approx([float(cable[c].values[np.isfinite(cable[c].values)][-1]) for c in "xyz"])


def test_the_66kv_cable_system_runs_in_time_and_its_range_graphs_read_the_element_tensions(tmp_path):
    """The same system in time (system_dynamic, 1 s): the floating hull's start is checked without the cable (the
    catenary check takes no sections or clamps), the range graphs take the node tension from the elements'
    (system_dynamic results keep ``segment_tension`` only) and a chain's, padded to the cable's nodes, plots."""
    from pathlib import Path

    import matplotlib

    matplotlib.use("Agg")
    import seacable as sc
    from seacable.design.cable import node_tension, plot_range_graphs, range_graphs

    examples = Path(__file__).parents[3] / "examples"
    data = yaml.safe_load((examples / "cable_66kv_system.yaml").read_text())
    data["analysis"] = {"type": "system_dynamic", "duration": 1.0, "time_step": 0.1, "output_interval": 0.5,
                        "design": {"line_clearance": 20.0}}
    hydro = data["bodies"]["hull"]["hydrodynamics"]
    hydro["file"] = str(examples / hydro["file"])
    (tmp_path / "case.yaml").write_text(yaml.safe_dump(data, sort_keys=False))
    ds = sc.run(sc.load_case(tmp_path / "case.yaml"))
    element = ds.segment_tension.sel(line="cable").isel(time=-1).values
    node = node_tension(ds.segment_tension).sel(line="cable").isel(time=-1).values
    # a node's tension is its two elements' mean, an end node's its element's (the mooring analyses' 'tension')
    assert node[1:-1][:279] == pytest.approx(0.5 * (element[:-1] + element[1:]), rel=1e-12)
    assert (node[0], node[280]) == (element[0], element[279])
    rg = range_graphs(ds, "cable")
    assert float(rg.tension_max.max()) == pytest.approx(float(np.nanmax(node_tension(ds.segment_tension)
                                                                         .sel(line="cable"))), rel=1e-12)
    plot_range_graphs(range_graphs(ds, "chain1"))  # its s padded with NaN past its 41 nodes
    assert line_clearance_check(ds, "cable").passed
    # a system line's limits are its own line type's (the system case's lines.cable): the MBR checks are made
    from seacable.design.cable import cable_checks, cable_limits

    limits = cable_limits(ds.sel(line="cable"))
    assert np.nanmin(limits.minimum_bend_radius) == 2.37 and np.nanmax(limits.minimum_bend_radius_dynamic) == 3.55
    assert np.nanmin(limits.allowable_tension) == 4.309e5
    mbr = next(c for c in cable_checks(ds, limits, "cable") if c.check == "curvature (dynamic MBR)")
    assert mbr.utilisation == pytest.approx(float(ds.curvature.sel(line="cable").max()) * 3.55, rel=1e-12)
    assert cable_limits(ds.sel(line="chain1")).minimum_bend_radius is None  # the chain's type gives none

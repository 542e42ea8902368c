"""The lay plan's inputs: the route (KP, offsets, projection), the bathymetry grid, the target, bad input,
and the lay table as CSV and figures."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import yaml

from seacable.cli import main
from seacable.errors import InputError
from seacable.laying.bathymetry import BathymetryGrid, seabed_map
from seacable.laying.route import Route, RouteGeometry
from seacable.results import read_netcdf

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "lay_plan_route.yaml"


def test_kp_and_offsets_along_a_route_with_alter_courses():
    """KP is the distance along the legs; a point's KP is that of its nearest route point and its offset is
    the distance to it, + to port (left looking along increasing KP)."""
    r = RouteGeometry(np.array([[0.0, 0.0], [3000.0, 0.0], [3000.0, 4000.0]]), kp_start=1000.0)
    np.testing.assert_allclose(r.kp, [1000.0, 4000.0, 8000.0])
    np.testing.assert_allclose(r.point([2500.0, 6000.0]), [[1500.0, 0.0], [3000.0, 2000.0]])
    np.testing.assert_allclose(r.turns(), [math.pi / 2])                    # a left turn: + (port)
    kp, off = r.locate(np.array([[1500.0, 20.0], [1500.0, -20.0], [3100.0, 2000.0], [-100.0, 5.0]]))
    np.testing.assert_allclose(kp, [2500.0, 2500.0, 6000.0, 900.0])
    np.testing.assert_allclose(off, [20.0, -20.0, -100.0, 5.0])
    kp, off = r.locate(np.array([[3010.0, -10.0]]))                       # outside the corner: to the waypoint
    assert kp[0] == pytest.approx(4000.0) and off[0] == pytest.approx(-math.hypot(10.0, 10.0))
    np.testing.assert_allclose(r.heading([2000.0, 4000.0, 5000.0]), [0.0, math.pi / 2, math.pi / 2])


def test_geographic_route_kp_is_the_geodesic_length():
    """Latitude/longitude waypoints are projected (azimuthal equidistant at the first waypoint): the KP of
    each waypoint equals the sum of the WGS84 geodesic leg lengths to 1e-4 (the projection's scale error
    100 km from its centre is about (d/R)^2 / 6 = 4e-5) and the first leg from the centre is exact to 1e-9."""
    from pyproj import Geod

    lat, lon = [50.0, 50.3, 50.6, 50.7], [1.0, 1.4, 1.5, 2.2]
    r = Route(latitude=lat, longitude=lon).geometry()
    _, _, legs = Geod(ellps="WGS84").inv(lon[:-1], lat[:-1], lon[1:], lat[1:])
    np.testing.assert_allclose(np.diff(r.kp), legs, rtol=1e-4)
    assert r.kp[1] == pytest.approx(legs[0], rel=1e-9)
    back = r.to_geographic(r.xy)
    np.testing.assert_allclose(back[0], lat, atol=1e-9)
    np.testing.assert_allclose(back[1], lon, atol=1e-9)


def _plane(x, y):
    """A plane seabed: bilinear and Delaunay interpolation are exact on it. [m]"""
    return 500.0 + 0.01 * x - 0.02 * y


def test_grids_from_csv_netcdf_and_lonlat_interpolate_a_plane_exactly(tmp_path):
    route = RouteGeometry(np.array([[0.0, 0.0], [1000.0, 500.0]]))
    xs, ys = np.linspace(-200.0, 1200.0, 8), np.linspace(-300.0, 800.0, 6)
    X, Y = np.meshgrid(xs, ys)
    pts = np.array([[130.0, 40.0], [777.0, 333.0], [1000.0, 500.0]])
    # a regular grid as CSV (rows in any order), as NetCDF, and scattered points
    rows = np.column_stack([X.ravel(), Y.ravel(), _plane(X, Y).ravel()])[::-1]
    np.savetxt(tmp_path / "g.csv", rows, delimiter=",", header="x,y,depth", comments="")
    xr.Dataset({"elevation": (("y", "x"), -_plane(X, Y))}, coords={"x": xs, "y": ys}).to_netcdf(tmp_path / "g.nc")
    rng = np.random.default_rng(1)
    sx, sy = rng.uniform(-300, 1300, 400), rng.uniform(-400, 900, 400)
    np.savetxt(tmp_path / "s.csv", np.column_stack([sx, sy, _plane(sx, sy)]), delimiter=",", header="x,y,depth",
               comments="")
    for name in ("g.csv", "g.nc", "s.csv"):
        m = seabed_map(route, None, BathymetryGrid(file=str(tmp_path / name)), math.nan)
        np.testing.assert_allclose(m.depth(pts), _plane(pts[:, 0], pts[:, 1]), rtol=1e-12, err_msg=name)
    inline = BathymetryGrid(x=tuple(xs), y=tuple(ys), depth=tuple(map(tuple, _plane(X, Y))))
    np.testing.assert_allclose(seabed_map(route, None, inline, math.nan).depth(pts), _plane(*pts.T), rtol=1e-12)
    # a grid in longitude and latitude, for a geographic route: a plane in lon/lat is interpolated exactly there
    geo = Route(latitude=[50.0, 50.05], longitude=[1.0, 1.1]).geometry()
    lon, lat = np.linspace(0.9, 1.2, 7), np.linspace(49.9, 50.2, 7)
    LON, LAT = np.meshgrid(lon, lat)
    xr.Dataset({"depth": (("lat", "lon"), 100.0 + 50.0 * (LON - 1.0) + 80.0 * (LAT - 50.0))},
               coords={"lon": lon, "lat": lat}).to_netcdf(tmp_path / "ll.nc")
    m = seabed_map(geo, None, BathymetryGrid(file=str(tmp_path / "ll.nc")), math.nan)
    q = geo.point(np.array([100.0, 5000.0]))
    qlat, qlon = geo.to_geographic(q)
    np.testing.assert_allclose(m.depth(q), 100.0 + 50.0 * (qlon - 1.0) + 80.0 * (qlat - 50.0), rtol=1e-10)


def _yaml(tmp_path, edit) -> Path:
    data = yaml.safe_load(EXAMPLE.read_text())
    edit(data)
    path = tmp_path / "case.yaml"
    path.write_text(yaml.safe_dump(data))
    return path


def _set(path, value):
    def edit(data):
        node = data
        for key in path[:-1]:
            node = node[key]
        if value is None:
            node.pop(path[-1])
        else:
            node[path[-1]] = value
    return edit


@pytest.mark.parametrize("edit, expected", [
    (_set(("analysis", "route", "waypoints"), [[0.0, 0.0]]), "at least two waypoints"),
    (_set(("analysis", "route", "waypoints"), [[0.0, 0.0], [10.0, 0.0], [10.0, 0.0], [20.0, 0.0]]),
     "waypoints 1 and 2 are the same point"),
    (_set(("analysis", "route", "waypoints"), [[0.0, 0.0], [20000.0, 0.0]]), "bathymetry covers KP 0 to 14000 m"),
    (_set(("analysis", "target"), {"slack": -0.01}), "slack below zero"),
    (_set(("analysis", "target"), {"slack": 3.0}), "slack is a ratio"),
    (_set(("analysis", "target"), {"slack": 0.03, "bottom_tension": 100.0}), "give one target"),
    (_set(("analysis", "route"), {"latitude": [50.0, 95.0], "longitude": [1.0, 1.1]}), "latitudes must lie"),
    (_set(("analysis", "ship"), {"kp": [0.0, 1000.0], "speeds": [1.5, 0.0]}), "must be > 0 m/s"),
    (_set(("analysis", "kp_start"), 20000.0), "lies outside the route"),
    (lambda data: data["analysis"].update(route={"waypoints": [[0.0, 0.0], [6000.0, 0.0], [3000.0, 0.0]]}),
     "the route turns back on itself at waypoint 2 (an alter-course of 180.0 deg"),
    (_set(("analysis", "route"), {"waypoints": [[50.0, -1.0], [50.0, -0.9], [50.05, -0.85]]}),
     "the route is 0.171 m long, waypoints [[50.0, -1.0], [50.0, -0.9]] ...: they look like degrees"),
    (_set(("analysis", "ship"), {"speed": 1.5, "repeater_speed": 3.0}),
     "ship.repeater_speed 3 m/s is above the ship's speed (1.5 m/s)"),
    (_set(("analysis", "target"), {"bottom_tension": 20000.0}),
     "does not reach the surface: under the bottom tension of 20000 N it leaves the seabed along its slope (-10."),
    (_set(("analysis", "bathymetry", "distance"), [0, 5000, 1000, 6000, 10000, 14000]),
     "distances must be strictly increasing, got [0.0, 5000.0, 1000.0,"),
])
def test_bad_lay_plan_input_one_message(tmp_path, capsys, edit, expected):
    """Each bad input: exit 2 from validate and from run, one message naming it."""
    path = _yaml(tmp_path, edit)
    for command in ("validate", "run"):
        assert main([command, str(path), "-o", str(tmp_path / "out.nc")] if command == "run"
                    else [command, str(path)]) == 2
        err = capsys.readouterr().err
        assert expected in err, err
        assert "Traceback" not in err


def test_grid_that_does_not_cover_the_route(tmp_path, capsys):
    xs, ys = np.array([-500.0, 8000.0]), np.array([-2000.0, 4000.0])
    xr.Dataset({"depth": (("y", "x"), np.full((2, 2), 300.0))}, coords={"x": xs, "y": ys}).to_netcdf(
        tmp_path / "grid.nc")

    def edit(data):
        data["analysis"].pop("bathymetry")
        data["analysis"]["bathymetry_grid"] = {"file": "grid.nc"}
    path = _yaml(tmp_path, edit)
    assert main(["validate", str(path)]) == 2
    err = capsys.readouterr().err
    assert "does not cover the route at KP 8" in err and "x = 8" in err, err


@pytest.mark.parametrize("island_y, expected", [(7000.0, None), (0.0, "the route at KP 1500.0 m")])
def test_grid_with_land_is_used_where_the_lay_is_at_sea(tmp_path, capsys, island_y, expected):
    """A GEBCO-style grid (elevation, up) holding an island: away from the route (y = 7 km) the plan runs, with the
    depths the island does not touch; on the route (y = 0) it is refused, the KP and point named, as land (from
    x = 1500 m, where the grid's cell reaches the island's first point). A grid all land is a sign error, said so."""
    xs, ys = np.arange(-2000.0, 16001.0, 500.0), np.arange(-3000.0, 9001.0, 500.0)
    elevation = np.full((ys.size, xs.size), -300.0)
    elevation[np.abs(ys - island_y) <= 500.0, 8:12] = 15.0            # x = 2000 .. 3500 m
    xr.Dataset({"elevation": (("y", "x"), elevation)}, coords={"x": xs, "y": ys}).to_netcdf(tmp_path / "grid.nc")
    xr.Dataset({"elevation": (("y", "x"), np.full((2, 2), 5.0))}, coords={"x": xs[[0, -1]], "y": ys[[0, -1]]}
               ).to_netcdf(tmp_path / "land.nc")

    def edit(data, file="grid.nc"):
        data["analysis"].pop("bathymetry")
        data["analysis"]["bathymetry_grid"] = {"file": file}
    path = _yaml(tmp_path, edit)
    out = tmp_path / "out.nc"
    if expected is None:
        assert main(["run", str(path), "-o", str(out)]) == 0
        np.testing.assert_allclose(read_netcdf(out).water_depth.values, 300.0, rtol=1e-12)
    else:
        assert main(["validate", str(path)]) == 2
        err = capsys.readouterr().err
        assert expected in err and "reaches land or a hole in the seabed grid" in err and "x = 1500.0" in err, err
    assert main(["validate", str(_yaml(tmp_path, lambda d: edit(d, "land.nc")))]) == 2
    assert "no point of it is under water" in capsys.readouterr().err


def test_row_spacing_does_not_change_the_plan(tmp_path):
    """The plan is computed on stations 100 m apart at most, whatever the rows asked for: with rows every 1 km the
    example's lay (a repeater slowing the ship for 50 m ramps, alter-courses on 1 km arcs) takes the same time and
    lands its repeater at the same KP as with rows every 100 m, and the common rows are equal (to 1e-9 of their
    scale: the same stations, the same iteration). Before, 1 km rows gave a lay 10 % longer (12191 s for 11036 s)
    and the repeater 190 m further on."""
    import seacable as sc

    result = {}
    for step in (100.0, 1000.0):
        case = sc.load_case(_yaml(tmp_path, _set(("analysis", "kp_step"), step)))
        result[step] = sc.run(case)
    fine, coarse = result[100.0], result[1000.0]
    assert coarse.kp.size < fine.kp.size / 5
    common = fine.sel(kp=coarse.kp.values)
    for name in ("time", "paid_out", "touchdown_kp", "touchdown_offset", "ship_speed", "top_tension"):
        scale = max(float(np.max(np.abs(fine[name]))), 1.0)
        np.testing.assert_allclose(coarse[name].values, common[name].values, rtol=0, atol=1e-9 * scale, err_msg=name)
    np.testing.assert_allclose(coarse.repeater_landing_kp.values, fine.repeater_landing_kp.values, rtol=0, atol=1e-6)


def test_rows_closer_than_5_m_are_interpolated_between_stations(tmp_path):
    """Rows every 2.5 m are read off the plan at stations every 5 m (a quasi-static plan has nothing to say between
    them; rows every 0.5 m over the example's 14 km took 10 minutes): the rows on the stations are the 5 m plan's
    (to 1e-9 of their scale), the others lie between their neighbours."""
    import seacable as sc

    def case(step):
        def edit(data):
            data["analysis"]["kp_step"] = step
            data["analysis"]["kp_end"] = 3000.0
        return sc.load_case(_yaml(tmp_path, edit))

    fine, five = sc.run(case(2.5)), sc.run(case(5.0))
    assert fine.kp.size == 2 * five.kp.size - 1
    on = fine.sel(kp=five.kp.values)
    for name in ("time", "paid_out", "touchdown_kp", "touchdown_offset", "top_tension"):
        scale = max(float(np.max(np.abs(five[name]))), 1.0)
        np.testing.assert_allclose(on[name].values, five[name].values, rtol=0, atol=1e-9 * scale, err_msg=name)
    mid = fine.time.values[1::2]
    assert np.all((mid > five.time.values[:-1]) & (mid < five.time.values[1:]))


def test_plan_over_the_breaking_load_says_so(tmp_path):
    """A cable whose minimum breaking load (2 kN here) is below the planned top tension (3.24 kN in 800 m of
    water): the plan warns, with the tension, the load and the ship KPs, and keeps the note in the result."""
    import json

    import seacable as sc

    def edit(data):
        next(iter(data["line_types"].values()))["breaking_load"] = 2000.0
    with pytest.warns(sc.SeacableWarning, match=r"the top tension reaches 32\d\d\.\d+ N, over the cable's minimum "
                                                 r"breaking load of 2000 N, at ship KP \d+\.0 to \d+\.0 m"):
        ds = sc.run(sc.load_case(_yaml(tmp_path, edit)))
    assert "over the cable's minimum breaking load" in json.loads(ds.attrs["settings"])["notes"]


def test_lonlat_grid_needs_a_geographic_route(tmp_path):
    xr.Dataset({"depth": (("lat", "lon"), np.full((2, 2), 300.0))},
               coords={"lon": [0.0, 1.0], "lat": [50.0, 51.0]}).to_netcdf(tmp_path / "ll.nc")
    route = RouteGeometry(np.array([[0.0, 0.0], [10.0, 0.0]]))
    with pytest.raises(InputError, match="needs a route in latitude and longitude"):
        seabed_map(route, None, BathymetryGrid(file=str(tmp_path / "ll.nc")), math.nan)


def test_cli_writes_the_lay_table_as_csv_and_the_figures(tmp_path):
    """`seacable run` on a lay_plan case: the NetCDF result, the lay table as CSV with units in its header (the
    same numbers as the result) and the two figures."""
    out = tmp_path / "plan.nc"
    assert main(["run", str(EXAMPLE), "-o", str(out)]) == 0
    ds = read_netcdf(out)
    table = np.genfromtxt(tmp_path / "plan_lay_table.csv", delimiter=",", names=True)
    header = (tmp_path / "plan_lay_table.csv").read_text().splitlines()[0]
    assert header.startswith("kp [m],time [s],ship_speed [m s-1],payout_speed [m s-1]")
    np.testing.assert_allclose(table["kp_m"], ds.kp.values)
    np.testing.assert_allclose(table["top_tension_N"], ds.top_tension.values, rtol=1e-5)
    assert (tmp_path / "plan_table.png").stat().st_size > 10_000
    assert (tmp_path / "plan_plan.png").stat().st_size > 10_000
    # the repeaters' events beside it: the example's one repeater, its numbers the result's
    events = (tmp_path / "plan_repeaters.csv").read_text().splitlines()
    assert events[0] == ("name [],s [m],entry_kp [m],entry_time [s],touchdown_kp [m],touchdown_time [s],"
                         "landing_kp [m],landing_offset [m]")
    assert len(events) == 1 + ds.repeater.size
    row = events[1].split(",")
    assert row[0] == str(ds.repeater_name.values[0])
    np.testing.assert_allclose([float(v) for v in row[1:]],
                               [float(ds[f"repeater_{k}"][0]) for k in ("s", "entry_kp", "entry_time", "touchdown_kp",
                                                                        "touchdown_time", "landing_kp", "landing_offset")],
                               rtol=1e-9)


def test_following_a_lay_table_bad_input(tmp_path, capsys):
    """A 3-D lay that follows a lay table: the table gives the ship and the payout, so giving them too is refused;
    a table without the columns, or with a ship at rest, is refused with the file named."""
    base = yaml.safe_load((EXAMPLE.parent / "lay_route_3d.yaml").read_text())
    (tmp_path / "t.csv").write_text("kp [m],time [s],ship_speed [m s-1],payout_speed [m s-1]\n0,0,1.0,1.05\n"
                                    "100,100,1.0,1.05\n")
    (tmp_path / "bad.csv").write_text("kp,time,ship_speed\n0,0,1.0\n")
    (tmp_path / "stop.csv").write_text("kp,time,ship_speed,payout_speed\n0,0,1.0,1.0\n10,10,0.0,0.0\n")
    cases = [({"lay_table": {"file": "t.csv"}}, "lay_table gives the ship's and the payout's speeds; ship and payout"),
             ({"lay_table": {"file": "bad.csv"}, "ship": None, "payout": None}, "payout_speed missing"),
             ({"lay_table": {"file": "stop.csv"}, "ship": None, "payout": None}, "ship_speed in row 2 is 0 m/s"),
             ({"lay_table": {"file": "t.csv", "start_kp": 500.0}, "ship": None, "payout": None},
              "lay_table.start_kp = 500.0 m lies outside the table's ship KPs (0 to 100 m)")]
    for edit, expected in cases:
        data = {**base, "analysis": {**base["analysis"], **edit}}
        data["analysis"] = {k: v for k, v in data["analysis"].items() if v is not None}
        path = tmp_path / "case.yaml"
        path.write_text(yaml.safe_dump(data))
        assert main(["validate", str(path)]) == 2
        err = capsys.readouterr().err
        assert expected in err and "Traceback" not in err, err
    data = {**base, "analysis": {k: v for k, v in base["analysis"].items() if k not in ("ship", "payout")}}
    data["analysis"]["lay_table"] = {"file": "t.csv"}
    (tmp_path / "case.yaml").write_text(yaml.safe_dump(data))
    assert main(["validate", str(tmp_path / "case.yaml")]) == 0


@pytest.mark.parametrize("edit, expected", [
    ({"payout": {"type": "slack", "slack": -0.05}}, "analysis.payout.slack must be >= 0, got -0.05"),
    ({"payout": {"type": "slack", "slack": 5.0}}, "analysis.payout.slack must be <= 1, got 5"),
    ({"ship": {"speed": 1.0, "start_x": 5000.0}}, "start_x = 5000 m lies outside the route, which runs from KP -1000"),
    ({"bathymetry_grid": {"x": [-300.0, 1500.0], "y": [-200.0, 600.0], "depth": [[100.0, 100.0], [100.0, 100.0]]}},
     ("the seabed does not cover the cable already on the seabed at the start: no depth behind x = -299.8 m, "
      "y = 41.6 m")),
    ({"bathymetry_grid": {"x": [-100.0, 1500.0], "y": [-200.0, 600.0], "depth": [[100.0, 100.0], [100.0, 100.0]]}},
     "the seabed grid does not cover the cable: no depth at x = -100"),
    ({"line_length": 400.0}, "the run starts with 236 m of cable on the seabed and 234.317 m suspended"),
])
def test_laying_dynamic_bad_input_one_message(tmp_path, capsys, edit, expected):
    """A 3-D lay (examples/lay_route_3d.yaml) with a negative or a percent slack, a start off the route, a grid that
    covers the ship's path but not the cable on the seabed behind the start (it gave NaN positions), a line too
    short for the starting lay: validate and run refuse it before the time loop, exit 2, one message. (A grid that
    ends under the span, x from -100 m, is met where the starting span's touchdown is looked for.)"""
    data = yaml.safe_load((EXAMPLE.parent / "lay_route_3d.yaml").read_text())
    if "line_length" in edit:
        data["line"]["length"] = edit.pop("line_length")
    data["analysis"].update(edit)
    path = tmp_path / "case.yaml"
    path.write_text(yaml.safe_dump(data))
    for argv in (["validate", str(path)], ["run", str(path), "-o", str(tmp_path / "out.nc")]):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert expected in err and "Traceback" not in err, err
    assert not (tmp_path / "out.nc").exists()


def _every_leg(route, q):
    """KP and offset of the nearest point of every leg, the first of equal distances (numpy.hypot's)."""
    start, d = route.xy[:-1], route.direction
    rel = q[:, None, :] - start                                              # (m, legs, 2)
    lo = np.where(np.arange(len(d)) == 0, -np.inf, 0.0)
    hi = np.where(np.arange(len(d)) == len(d) - 1, np.inf, route.length)
    t = np.clip(rel[..., 0] * d[:, 0] + rel[..., 1] * d[:, 1], lo, hi)
    dist = np.hypot(q[:, None, 0] - (start[:, 0] + t * d[:, 0]), q[:, None, 1] - (start[:, 1] + t * d[:, 1]))
    best = np.argmin(dist, axis=1)
    rows = np.arange(len(q))
    side = d[best, 0] * rel[rows, best, 1] - d[best, 1] * rel[rows, best, 0]
    return route.kp[best] + t[rows, best], np.where(side < 0.0, -1.0, 1.0) * dist[rows, best]


def test_locate_on_a_long_route_is_the_every_leg_answer():
    """A route of 500 legs is searched through the legs near groups of points or a k-d tree; KP and offset equal
    the comparison with every leg bit for bit, for points near the route, far from it and beyond its ends, in
    any order or in a row like a cable's nodes, and on the waypoints (as far from two legs: the first)."""
    rng = np.random.default_rng(3)
    kp = np.linspace(0.0, 100e3, 501)
    route = RouteGeometry(np.column_stack([kp, 300.0 * np.sin(kp / 3000.0) + rng.normal(0.0, 20.0, kp.size)]))
    near = route.point(rng.uniform(-500.0, 100.5e3, 3000)) + rng.normal(0.0, 150.0, (3000, 2))
    s = np.arange(700) * 5.0
    cables = [route.point(k0 + s) + np.column_stack([np.zeros(700), off + 0.05 * s])
              for k0, off in ((-1000.0, 30.0), (20e3, -650.0), (60e3, 2.0), (98e3, 400.0))]
    q = np.vstack([near, rng.uniform(-5e3, 105e3, (200, 2)) * [1.0, 0.02], route.xy[::7], *cables])
    for part in (q, *cables, q[:5]):
        kp_fast, off_fast = route.locate(part)
        kp_all, off_all = _every_leg(route, part)
        np.testing.assert_array_equal(kp_fast, kp_all)
        np.testing.assert_array_equal(off_fast, off_all)
    assert route._nearby(cables[1]) is not None and route._nearby(near) is None     # both ways were taken
    # a point whose nearest tree points lie on a short leg 100.06 m away, while a long leg passes 100 m away
    # between its tree points: with 2 tree points it is not sure, and the every-leg comparison finds the long leg
    trap = RouteGeometry(np.array([[-5000.0, -3000.0], [-1003.0, 0.0], [1003.0, 0.0], [1003.0, 1500.0], [3.0, 200.06],
                                   [-3.0, 200.06], [-3.0, 1500.0], [-3000.0, 3000.0], [-6000.0, 3000.0]]))
    trap._K, trap._PAIRS = 2, 0
    for wide in (64, 0):                          # the legs near the point; the k-d tree (no group is narrow)
        trap._WIDE = wide
        t_kp, t_off = trap.locate(np.array([[0.0, 100.0]]))
        assert t_off[0] == pytest.approx(100.0) and t_kp[0] == pytest.approx(trap.kp[1] + 1003.0)



def test_route_turn_radius_sails_arcs():
    """`turn_radius`: each alter-course on an arc tangent to both legs, starting R tan(|turn|/2) before the
    waypoint; the KP runs along the arcs (a square's three quarter-turns at 300 m: legs minus 6 R plus
    3 (pi/2) R, to the chords' shortfall, under 1 mm per quarter turn); a point on an arc has its arc length as
    KP and lies on the route (the chords within 1 mm of the circle); the waypoint KPs are the route's nearest
    points (an arc's middle) and turn_kp the arcs' ends."""
    r = Route(waypoints=((0.0, 0.0), (1000.0, 0.0), (1000.0, 1000.0), (0.0, 1000.0), (0.0, 0.0)),
              turn_radius=300.0).geometry()
    assert r.kp_end == pytest.approx(4000.0 - 6 * 300.0 + 3 * (math.pi / 2) * 300.0, abs=3e-3)
    np.testing.assert_allclose(r.turn_kp[:3], [0.0, 700.0, 700.0 + math.pi / 2 * 300.0], atol=1e-3)
    phi = 0.3
    kp, off = r.locate(np.array([[700.0 + 300.0 * math.sin(phi), 300.0 - 300.0 * math.cos(phi)]]))
    assert float(kp[0]) == pytest.approx(700.0 + 300.0 * phi, abs=1e-3)
    assert abs(float(off[0])) < 1e-3
    assert r.waypoint_kp[1] == pytest.approx(700.0 + math.pi / 4 * 300.0, abs=1e-3)
    np.testing.assert_allclose(r.turns(), [math.pi / 2] * 3)          # the alter-courses, as without arcs
    # one radius per inner waypoint; 0 for a sharp one
    sharp = Route(waypoints=((0.0, 0.0), (1000.0, 0.0), (1000.0, 1000.0), (0.0, 1000.0)),
                  turn_radius=(0.0, 300.0)).geometry()
    assert 1000.0 in sharp.turn_kp


@pytest.mark.parametrize("waypoints, radius, match", [
    (((0.0, 0.0), (1000.0, 0.0), (1000.0, 500.0), (0.0, 500.0)), 300.0, "need 600 m of it"),
    (((0.0, 0.0), (1000.0, 0.0), (1000.0, 500.0)), (100.0, 200.0), "2 values but the route has 1 inner"),
    (((0.0, 0.0), (1000.0, 0.0), (1000.0, 500.0)), -5.0, "turn_radius"),
])
def test_route_turn_radius_bad_input(waypoints, radius, match):
    with pytest.raises(InputError, match=match):
        Route(waypoints=waypoints, turn_radius=radius).geometry()

def test_seabed_under_a_route_is_remembered_bit_for_bit():
    """Track3D.zb remembers the points it was asked for: the same points again, some of them, or new ones
    mixed in give the seabed map's depths exactly; so does the gradient. ``highest`` bounds the seabed."""
    from seacable.laying.inputs import Bathymetry
    from seacable.laying.track import Track3D

    rng = np.random.default_rng(4)
    kp = np.linspace(0.0, 20e3, 101)
    route = RouteGeometry(np.column_stack([kp, 200.0 * np.sin(kp / 2000.0) + rng.normal(0.0, 10.0, kp.size)]))
    table = np.linspace(-1e3, 21e3, 500)
    seabed = seabed_map(route, Bathymetry(distance=tuple(table), depth=tuple(1000.0 + 50.0 * np.sin(table / 900.0))),
                        None, math.nan)
    track = Track3D(route, seabed)
    cable = route.point(5e3 + 5.0 * np.arange(600)) + [0.0, 120.0]
    for p in (cable, cable[3:200], cable[100], np.vstack([cable[::5], cable[::3] + 0.5]), cable + 1.0,
              cable[:, None, :], np.empty((0, 2))):
        np.testing.assert_array_equal(track.zb(p), -seabed.depth(p))
    g = track.gradient(cable[50])
    e = np.eye(2)
    np.testing.assert_array_equal(g, [(-seabed.depth(cable[50] + e[k]) + seabed.depth(cable[50] - e[k])) / 2.0
                                      for k in range(2)])
    assert Track3D(route, seabed_map(route, None, None, 1000.0))._memo is None        # flat: nothing to remember
    assert track.highest == -float(np.min(seabed.table[1]))      # nodes above it are not looked up
    # over a regular grid a single point gives a single elevation (the 3-D lay's start takes float() of it)
    x, y = np.linspace(-1e3, 21e3, 12), np.linspace(-1e3, 1e3, 5)
    grid = seabed_map(route, None, BathymetryGrid(x=tuple(x), y=tuple(y), depth=tuple(
        tuple(900.0 + 0.01 * x + yi * 0.02) for yi in y)), math.nan)
    z = Track3D(route, grid).zb(cable[7])
    assert z.shape == () and z == -grid.depth(cable[7])[0] and Track3D(route, grid).highest == -870.0


def test_time_loop_shortcuts_of_the_tracks_are_their_array_arithmetic_to_the_bit():
    """The look-ups the laying time loop makes every step without arrays or numpy scalars give what the array
    arithmetic gives, bit for bit (signed zeros too): a track's ``slope_along`` is ``gradient @ direction``, its
    ``zb_under`` the seabed under the nodes (-inf above ``above`` where the map leaves them out), a profile's
    ``slope`` its table segment's by numpy.searchsorted, and ``LayParameters.type_at`` numpy.searchsorted's."""
    from seacable.laying.inputs import Bathymetry, Seabed2D
    from seacable.laying.parameters import LayParameters
    from seacable.laying.track import Track2D, Track3D

    def bits(a):
        return np.asarray(a, float).tobytes()

    profile = Seabed2D(np.array([-500.0, 0.0, 200.0, 800.0, 1100.0]), np.array([50.0, 50.0, 200.0, 200.0, 100.0]))
    flat, plane = Track2D(profile), Track2D(Seabed2D.plane(80.0, -0.1, -1e3, 1e3))
    xs = [-600.0, -500.0, -1e-9, -0.0, 0.0, 1e-300, 100.0, 200.0, 500.0, 800.0, 1000.0, 1100.0, 1200.0]
    for track in (flat, plane):
        sx, sz = track.seabed.x, track.seabed.zb
        for x in xs:
            k = int(np.searchsorted(sx, x, side="right")) - 1
            slope = 0.0 if x <= sx[0] or x >= sx[-1] else float((sz[k + 1] - sz[k]) / (sx[k + 1] - sx[k]))
            assert bits(track.seabed.slope(x)) == bits(slope)
            ph = np.array([x])
            assert bits(track.slope_along(ph, x)) == bits(float(track.gradient(ph) @ track.direction(x)))
        nodes = np.array([[x, z] for x in xs for z in (-300.0, -60.0, -10.0, np.nan)])
        zb = track.zb_under(nodes, -49.0)
        np.testing.assert_array_equal(zb, track.zb(nodes[:, :-1]))
    rng = np.random.default_rng(5)
    kp = np.linspace(0.0, 5e3, 51)
    route = RouteGeometry(np.column_stack([kp, 300.0 * np.sin(kp / 1500.0)]))
    table = np.linspace(-1e3, 6e3, 200)
    seabed = seabed_map(route, Bathymetry(distance=tuple(table), depth=tuple(300.0 + 40.0 * np.sin(table / 700.0))),
                        None, math.nan)
    track = Track3D(route, seabed)
    for d in rng.uniform(0.0, 5e3, 20):
        ph = route.point(d) + rng.normal(0.0, 30.0, 2)
        assert bits(track.slope_along(ph, d)) == bits(float(track.gradient(ph) @ track.direction(d)))
    nodes = np.column_stack([route.point(rng.uniform(0.0, 5e3, 40)), rng.uniform(-400.0, 0.0, 40)])
    above = track.highest + 1.0
    low = nodes[:, -1] <= above
    assert 0 < low.sum() < len(nodes)
    zb = track.zb_under(nodes, above)
    np.testing.assert_array_equal(zb[low], -seabed.depth(nodes[low, :-1]))
    assert np.all(zb[~low] == -np.inf)
    ends = np.array([100.0, 250.0, 1000.0])
    par = LayParameters(props=np.zeros((3, 8)), type_ends=ends, segment_length=1.0, cable_length=1000.0)
    for s in (-1.0, 0.0, 99.999, 100.0, 100.001, 250.0, 999.0, 1000.0, 2000.0, np.float64(250.0)):
        assert par.type_at(s) == min(int(np.searchsorted(ends, s, side="right")), 2)

"""The 3-D view (issue 41, 'Pictures'): ``seacable view RESULT.nc -o view.html`` and :func:`seacable.view`.

The figure's traces carry the result's own numbers (read back from the figure's JSON), the seabed is the case's
(flat, sloped, a profile) or the lay's, a result without a shape is refused, a 3-hour run's page stays a few
megabytes, and the page opens in headless Chromium with no console message and no network request and shows
its lines.
"""

from __future__ import annotations

import base64
import json
import math
import re
import shutil
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import yaml

import seacable as sc
from seacable.cli import main
from seacable.errors import InputError
from seacable.plot.view3d import view_figure
from seacable.results import make_dataset, var, write_netcdf

from .conftest import CHROMIUM

_DTYPES = {"f8": "<f8", "f4": "<f4", "i4": "<i4", "i2": "<i2", "i1": "i1", "u1": "u1", "u2": "<u2", "u4": "<u4"}


def _array(value) -> np.ndarray:
    """A trace's array from the figure's JSON: a list, or plotly's typed array (dtype, base64 bytes, shape)."""
    if isinstance(value, dict) and "bdata" in value:
        out = np.frombuffer(base64.b64decode(value["bdata"]), dtype=_DTYPES[value["dtype"]]).astype(float)
        shape = value.get("shape")
        return out.reshape([int(n) for n in str(shape).split(",")]) if shape else out
    return np.asarray(value, dtype=float)


def _figure_json(ds, **kw) -> dict:
    """The figure as the page gets it (plotly's JSON), decoded."""
    return json.loads(view_figure(ds, **kw).to_json())


def _lines_result(nt=300, dt=0.5, n_nodes=9, lines=("L1", "L2"), case: dict | None = None):
    """A 'mooring_dynamic' result of lines whose nodes all move (a different number at every node, line and
    time, so a frame from the wrong time, node or line, or a swapped axis, is seen), with their tensions [N]."""
    t = np.arange(nt) * dt
    s = np.linspace(0.0, 1.0, n_nodes)
    x = np.empty((len(lines), nt, n_nodes))
    y, z, tension = np.empty_like(x), np.empty_like(x), np.empty_like(x)
    for k in range(len(lines)):
        heading = 2 * math.pi * k / len(lines)
        reach = 300.0 * s[None, :] + 5.0 * np.sin(0.1 * t)[:, None] * s[None, :]
        x[k] = reach * math.cos(heading) + 0.01 * k
        y[k] = reach * math.sin(heading) + 0.001 * t[:, None]
        z[k] = -100.0 + 95.0 * s[None, :] ** 2 + 0.5 * np.cos(0.2 * t)[:, None] * s[None, :]
        tension[k] = 1e5 * (1.0 + s[None, :]) + 1e3 * np.sin(0.3 * t)[:, None] + 1e4 * k
    d3 = ("line", "time", "node")
    data = {"x": var(d3, x, "m", "x position"), "y": var(d3, y, "m", "y position"),
            "z": var(d3, z, "m", "elevation"), "tension": var(d3, tension, "N", "effective tension")}
    coords = {"line": var("line", list(lines), "1", "line"), "time": var("time", t, "s", "time"),
              "node": var("node", np.arange(n_nodes), "1", "node")}
    ds = make_dataset(data, coords, analysis="mooring_dynamic", settings={"time_step": dt},
                      references=["A reference of the model."], title="view test")
    ds.attrs["case_name"] = "view test"
    if case is not None:
        ds.attrs["case"] = yaml.safe_dump(case, sort_keys=False)
    return ds


def _traces(fig: dict) -> list[dict]:
    """The line traces the page first shows (not the legend's entries: a trace of no point each)."""
    return [d for d in fig["data"] if d["type"] == "scatter3d" and d["mode"] == "lines" and d["x"] != [None]]


# ----------------------------------------------------------------------------------------------- the numbers

def test_traces_carry_the_results_positions_and_tensions_at_the_frames_times():
    ds = _lines_result()
    fig = _figure_json(ds, max_frames=25)
    frames = fig["frames"]
    # 300 output times decimated evenly to 25 frames, the first and the last kept: frame k at the output time
    # nearest k 299/24 output steps (6.23 s) from the start, so within half a step of it
    idx = fig["layout"]["meta"]["frame_index"]["time"]
    assert len(frames) == 25 and idx[0] == 0 and idx[-1] == 299
    assert np.all(np.abs(np.array(idx) - np.arange(25) * 299 / 24) <= 0.5 + 1e-9)
    steps = fig["layout"]["sliders"][0]["steps"]
    assert [s["label"] for s in steps][:2] == ["t = 0 s", f"t = {ds.time.values[idx[1]]:.6g} s"]
    for f, i in enumerate(idx):
        lines = [d for d in frames[f]["data"] if d["mode"] == "lines"]
        assert [d["name"] for d in lines] == ["L1", "L2"]
        for k, d in enumerate(lines):
            # the same float64 numbers (plotly writes the bytes): equal, not close
            for axis in "xyz":
                np.testing.assert_array_equal(_array(d[axis]), ds[axis].values[k, i])
            # the colour is the tension in kN: N / 1000, to the last bit of a division
            np.testing.assert_array_equal(_array(d["line"]["color"]), ds.tension.values[k, i] / 1e3)
    # the first frame is what the page shows before it plays
    shown = _traces(fig)
    for k in range(2):
        np.testing.assert_array_equal(_array(shown[k]["z"]), ds.z.values[k, 0])
    # one colour scale for every frame: the whole run's range of tension [kN], so that colours compare in time
    ax = fig["layout"]["coloraxis"]
    assert ax["cmin"] == pytest.approx(ds.tension.values.min() / 1e3, rel=1e-12)
    assert ax["cmax"] == pytest.approx(ds.tension.values.max() / 1e3, rel=1e-12)
    assert ax["colorbar"]["title"]["text"] == "tension [kN]"


def test_segment_tensions_are_averaged_to_the_nodes():
    # a lay's tension is per segment: a linear tension along the cable, T = 1000 s [N] at the segments' middles,
    # averages to T = 1000 s at the interior nodes (uniform segments), and the end nodes take their segment's
    nt, nn = 4, 6
    s_node = np.arange(nn, dtype=float)
    s_mid = 0.5 * (s_node[1:] + s_node[:-1])
    t = np.arange(nt) * 1.0
    x = np.broadcast_to(s_node, (nt, nn)).copy()
    z = -np.broadcast_to(s_node, (nt, nn)).copy()
    seg = np.broadcast_to(1000.0 * s_mid, (nt, nn - 1)).copy()
    ds = make_dataset({"x": var(("time", "node"), x, "m", "x"), "z": var(("time", "node"), z, "m", "z"),
                       "tension": var(("time", "segment"), seg, "N", "segment tension")},
                      {"time": var("time", t, "s", "time")}, analysis="laying_dynamic", settings={},
                      references=["r"], title="lay")
    fig = _figure_json(ds)
    colour = _array(_traces(fig)[0]["line"]["color"])
    expected = np.concatenate([[seg[0, 0]], 1000.0 * s_node[1:-1], [seg[0, -1]]]) / 1e3
    np.testing.assert_allclose(colour, expected, rtol=1e-14)   # sums of two halves: exact but for rounding
    # a 2-D result: the line in the x-z plane (y = 0)
    np.testing.assert_array_equal(_array(_traces(fig)[0]["y"]), np.zeros(nn))


def _seabed_surface(fig: dict) -> dict:
    (bed,) = [d for d in fig["data"] if d["type"] == "surface" and d["name"] == "seabed"]
    return bed


def test_the_seabed_is_the_cases_flat_sloped_or_profile():
    flat = _seabed_surface(_figure_json(_lines_result(nt=3, case={"environment": {"depth": 100.0}})))
    np.testing.assert_array_equal(_array(flat["z"]), -100.0)
    # a slope rising towards +X: z = -depth + x tan(slope) at the surface's corners (environment.Seabed)
    slope = 0.05
    bed = _seabed_surface(_figure_json(_lines_result(nt=3, case={
        "environment": {"depth": 100.0, "seabed": {"slope": slope}}})))
    bx, bz = _array(bed["x"]), _array(bed["z"])
    np.testing.assert_allclose(bz, -100.0 + bx * math.tan(slope), rtol=0, atol=1e-12)
    assert np.ptp(bz) > 10.0   # a slope seen (the lines span 600 m: 30 m of rise)
    # the case's own units (issue 41): a slope of "3 deg" is 3 degrees, read through the case's Seabed model
    bed = _seabed_surface(_figure_json(_lines_result(nt=3, case={
        "environment": {"depth": 100.0, "seabed": {"slope": "3 deg"}}})))
    bx, bz = _array(bed["x"]), _array(bed["z"])
    np.testing.assert_allclose(bz, -100.0 + bx * math.tan(math.radians(3.0)), rtol=0, atol=1e-12)
    # a profile along X: the depths at its points, linear between them, level beyond
    profile = {"distance": [-100.0, 0.0, 200.0], "depth": [150.0, 100.0, 80.0]}
    bed = _seabed_surface(_figure_json(_lines_result(nt=3, case={
        "environment": {"depth": 100.0, "seabed": {"profile": profile}}})))
    bx, bz = _array(bed["x"])[:, 0], _array(bed["z"])[:, 0]
    for d, h in zip(profile["distance"], profile["depth"], strict=True):
        assert bz[np.flatnonzero(bx == d)[0]] == -h
    assert bz[0] == -80.0 and bz[-1] == -80.0 or bx[0] < -100.0   # beyond the profile: level
    assert np.all(bz[bx >= 200.0] == -80.0) and np.all(bz[bx <= -100.0] == -150.0)
    # no depth known: no seabed drawn, the sea surface still is
    fig = _figure_json(_lines_result(nt=3))
    assert [d["name"] for d in fig["data"] if d["type"] == "surface"] == ["sea surface"]


def test_a_seabed_grid_is_drawn_as_the_grid_with_land_left_open(tmp_path):
    """A case's seabed grid (``environment.seabed.grid``) is drawn over the lines' box at the grid's own bilinear
    elevations (here a saddle ``z = -100 + x y / 1e4``, which bilinear interpolation holds exactly), and a land
    cell is a gap in the surface, not a plane at some depth."""
    x, y = [-400.0, 0.0, 400.0], [-400.0, 0.0, 400.0]
    depth = [[100.0 - a * b / 1e4 for a in x] for b in y]
    bed = _seabed_surface(_figure_json(_lines_result(nt=3, case={
        "environment": {"depth": 100.0, "seabed": {"grid": {"x": x, "y": y, "depth": depth}}}})))
    bx, by, bz = _array(bed["x"]), _array(bed["y"]), _array(bed["z"])
    assert bz.shape == bx.shape == by.shape and bz.size > 100
    np.testing.assert_allclose(bz, -100.0 + bx * by / 1e4, rtol=0, atol=1e-9)
    assert np.ptp(bz) > 5.0   # the saddle seen, not a plane
    # a GEBCO-like file, elevation up, with land (5 m above the sea) at the corner (-400, -400): no seabed drawn
    # over its cell
    elevation = -np.array(depth)
    elevation[0, 0] = 5.0
    path = tmp_path / "grid.nc"
    xr.Dataset({"elevation": (("y", "x"), elevation)}, coords={"x": x, "y": y}).to_netcdf(path)
    bed = _seabed_surface(_figure_json(_lines_result(nt=3, case={
        "environment": {"depth": 100.0, "seabed": {"grid": {"file": str(path)}}}})))
    bx, by, bz = _array(bed["x"]), _array(bed["y"]), _array(bed["z"])
    assert np.all(np.isnan(bz[(bx < 0.0) & (by < 0.0)])) and np.all(np.isfinite(bz[(bx > 0.0) | (by > 0.0)]))


def test_the_lays_seabed_and_the_ship_are_drawn():
    nt, nn = 3, 5
    x = np.broadcast_to(np.linspace(0.0, 40.0, nn), (nt, nn)).copy()
    z = np.broadcast_to(np.linspace(-50.0, 0.0, nn), (nt, nn)).copy()
    ds = make_dataset({"x": var(("time", "node"), x, "m", "x"), "z": var(("time", "node"), z, "m", "z"),
                       "ship_x": var("time", [40.0, 41.0, 42.0], "m", "ship x"),
                       "seabed_x": var("seabed_point", [-10.0, 20.0, 60.0], "m", "seabed x"),
                       "seabed_z": var("seabed_point", [-50.0, -50.0, -45.0], "m", "seabed z")},
                      {"time": var("time", np.arange(nt) * 1.0, "s", "time")}, analysis="laying_dynamic",
                      settings={}, references=["r"], title="lay")
    fig = _figure_json(ds)
    bed = _seabed_surface(fig)
    bx, bz = _array(bed["x"])[:, 0], _array(bed["z"])[:, 0]
    np.testing.assert_allclose(bz, np.interp(bx, [-10.0, 20.0, 60.0], [-50.0, -50.0, -45.0]), atol=1e-12)
    assert 20.0 in bx   # the profile's kink kept
    ship = [d for d in fig["frames"][2]["data"] if d["mode"] == "markers"]
    assert [d["name"] for d in ship] == ["ship (water entry)"]
    assert (_array(ship[0]["x"])[0], _array(ship[0]["y"])[0], _array(ship[0]["z"])[0]) == (42.0, 0.0, 0.0)


def test_the_seabed_along_a_lay_route_is_under_the_route():
    # a route of two legs, (-1000, 0) -> (300, 0) -> (300, 500), its KP -1000 at the first vertex (the ship's KP
    # tells); the seabed on the route at KP -500 (on the first leg), 300 (the corner) and 550 (250 m up the
    # second): its ribbon's middle is on the route there, at the seabed's elevation
    nt, nn = 3, 4
    ship_kp = np.array([400.0, 450.0, 500.0])
    ship_xy = np.column_stack([np.full(nt, 300.0), ship_kp - 300.0])
    x = np.repeat(ship_xy[:, :1], nn, axis=1)
    y = ship_xy[:, 1:] - np.linspace(40.0, 0.0, nn)
    z = np.broadcast_to(np.linspace(-60.0, 0.0, nn), (nt, nn)).copy()
    tn = ("time", "node")
    ds = make_dataset({"x": var(tn, x, "m", "x"), "y": var(tn, y, "m", "y"), "z": var(tn, z, "m", "z"),
                       "ship_x": var("time", ship_xy[:, 0], "m", "ship x"),
                       "ship_y": var("time", ship_xy[:, 1], "m", "ship y"),
                       "ship_kp": var("time", ship_kp, "m", "ship KP"),
                       "route_x": var("route_point", [-1000.0, 300.0, 300.0], "m", "route x"),
                       "route_y": var("route_point", [0.0, 0.0, 500.0], "m", "route y"),
                       "seabed_kp": var("seabed_point", [-500.0, 300.0, 550.0], "m", "seabed KP"),
                       "seabed_z": var("seabed_point", [-70.0, -60.0, -65.0], "m", "seabed z")},
                      {"time": var("time", np.arange(nt) * 1.0, "s", "time")}, analysis="laying_dynamic",
                      settings={}, references=["r"], title="lay")
    bed = _seabed_surface(_figure_json(ds))
    mid_x, mid_y = _array(bed["x"]).mean(axis=1), _array(bed["y"]).mean(axis=1)
    np.testing.assert_allclose(mid_x, [-500.0, 300.0, 300.0], atol=1e-9)
    np.testing.assert_allclose(mid_y, [0.0, 0.0, 250.0], atol=1e-9)
    np.testing.assert_array_equal(_array(bed["z"]), [[-70.0, -70.0], [-60.0, -60.0], [-65.0, -65.0]])


def test_system_bodies_are_markers_at_their_positions(synth):
    body = np.column_stack([np.linspace(0.0, 10.0, 5), np.linspace(0.0, -3.0, 5)])
    ds = synth.result({"L1": np.ones(5), "L2": np.ones(5)}, body_xy=body, analysis="system_dynamic")
    fig = _figure_json(ds)
    for f in range(5):
        (hull,) = [d for d in fig["frames"][f]["data"] if d["mode"] == "markers"]
        assert hull["name"] == "body hull"
        assert (_array(hull["x"])[0], _array(hull["y"])[0]) == tuple(body[f])


# ------------------------------------------------------------------------------------------------ refusals

@pytest.mark.parametrize("analysis, data", [
    ("pushover", {"offset": ("offset", [0.0, 1.0]), "fairlead_tension": ("offset", [1.0, 2.0])}),
    ("lay_plan", {"kp": ("kp", [0.0, 1.0]), "ship_x": ("kp", [0.0, 1.0])}),
    ("mooring_static", {"tension": ("node", [1.0, 2.0])}),      # a shape's result without its shape
])
def test_a_result_without_a_shape_is_refused(tmp_path, capsys, analysis, data):
    ds = make_dataset({k: var(d, v, "1", k) for k, (d, v) in data.items()}, {}, analysis=analysis, settings={},
                      references=["r"], title="t")
    with pytest.raises(InputError, match=rf"'{analysis}' result: .*nothing to view in 3-D.*Suggested fix"):
        sc.view(ds)
    path = write_netcdf(ds, tmp_path / "r.nc")
    assert main(["view", str(path), "-o", str(tmp_path / "v.html")]) == 2
    err = capsys.readouterr().err
    assert f"result file '{path}' is a '{analysis}' result" in err and "Traceback" not in err
    assert not (tmp_path / "v.html").exists()


def test_bad_options_are_refused(tmp_path, capsys):
    path = write_netcdf(_lines_result(nt=3), tmp_path / "r.nc")
    assert main(["view", str(path), "-o", str(tmp_path / "v.png")]) == 2
    assert "must end in .html" in capsys.readouterr().err
    assert main(["view", str(path), "--max-frames", "0"]) == 2
    assert "--max-frames" in capsys.readouterr().err
    with pytest.raises(InputError, match="max_frames 0: expected a whole number of frames"):
        sc.view(_lines_result(nt=3), max_frames=0)
    ds = _lines_result(nt=3)
    ds["time"] = ("time", [0.0, 2.0, 1.0], ds.time.attrs)
    with pytest.raises(InputError, match="time"):
        sc.view(ds)


def test_the_page_is_written_whole_or_not_at_all(tmp_path, monkeypatch):
    import plotly.graph_objects as go

    out = tmp_path / "v.html"
    path = write_netcdf(_lines_result(nt=3), tmp_path / "r.nc")
    assert main(["view", str(path), "-o", str(out)]) == 0
    good = out.read_bytes()
    # plotly's script is in the page: no script element loads one from elsewhere
    assert good.startswith(b"<!doctype html>") and re.search(rb"<script[^>]*\bsrc=", good) is None

    def broken(self, file, **kw):
        Path(file).write_text("<html>half a page")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(go.Figure, "write_html", broken)
    with pytest.raises(InputError, match="cannot write the 3-D view"):
        sc.view(_lines_result(nt=3), out)
    assert out.read_bytes() == good and sorted(p.name for p in tmp_path.iterdir()) == ["r.nc", "v.html"]
    monkeypatch.undo()
    # without -o: RESULT.html beside the result (the same page but for its random element id)
    assert main(["view", str(path)]) == 0 and (tmp_path / "r.html").stat().st_size == len(good)


# -------------------------------------------------------------------------------------------------- its size

def test_a_three_hour_runs_page_stays_a_few_megabytes(tmp_path):
    import plotly

    # a 3-hour storm stored every 0.5 s (21 601 output times) of 3 lines of 41 nodes: 120 frames; the page is
    # plotly's script (4.8 MB) and the figure (0.87 MB when this was written: 120 frames of 3 x 41 nodes of
    # x, y, z, tension as float64 in base64, and each frame's trace settings; every one of the 21 601 times
    # would make a page of about 150 MB). Bound: 1.5 MB of figure, 6.5 MB in all
    ds = _lines_result(nt=21_601, dt=0.5, n_nodes=41, lines=("L1", "L2", "L3"))
    out = tmp_path / "storm.html"
    fig = sc.view(ds, out)
    script = (Path(plotly.__file__).parent / "package_data" / "plotly.min.js").stat().st_size
    size = out.stat().st_size
    assert len(fig.frames) == 120 and float(ds.time.values[fig.layout.meta["frame_index"]["time"][-1]]) == 10_800.0
    assert size - script < 1.5e6, size - script
    assert size < 6.5e6, size


# --------------------------------------------------------------------------------------- in a real browser

#: A policy that lets the page run its own inline script and nothing else: any request the page makes (a script,
#: a style sheet, a font, an image, a fetch; http or file) is refused and logged in the console by the browser
_NO_REQUESTS = ("<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
                "script-src 'unsafe-inline' 'unsafe-eval'; style-src 'unsafe-inline'; img-src data: blob:; "
                "worker-src blob:\">")
#: no network at all: every request the browser makes goes to a proxy where nothing listens
_OFFLINE = ("--proxy-server=http://127.0.0.1:9", "--proxy-bypass-list=<-loopback>")


def _watched(page: Path) -> Path:
    """A copy of ``page`` under :data:`_NO_REQUESTS`."""
    out = page.with_name(f"watched_{page.name}")
    out.write_text(page.read_text().replace("<head>", "<head>" + _NO_REQUESTS, 1))
    return out


@pytest.mark.skipif(shutil.which(CHROMIUM) is None,
                    reason=f"{CHROMIUM} is missing (Debian's 'chromium' package: .ci/run installs it)")
def test_the_view_renders_in_headless_chromium_offline(tmp_path, browser):
    from PIL import Image

    # one line at one tension everywhere: drawn in the colour scale's lowest colour, Viridis' #440154
    ds = _lines_result(nt=5, lines=("L1", "L2", "L3"), case={"environment": {"depth": 100.0}})
    ds["tension"] = ds.tension * 0 + 2e5
    page = tmp_path / "view.html"
    sc.view(ds, page)
    # the same page with its lines hidden (the colour bar, seabed and sea kept): the pixels of the line colour
    # it has are the colour bar's
    hidden = tmp_path / "hidden.html"
    fig = view_figure(ds)
    # (the plant of the console check: its lines in the legend, whose typed-array colours plotly warns of)
    fig.for_each_trace(lambda tr: tr.update(visible="legendonly", showlegend=True),
                       selector=lambda tr: tr.type == "scatter3d" and tr.mode == "lines" and tr.x[0] is not None)
    fig.write_html(hidden, include_plotlyjs=True)
    # a page that asks the network for plotly's script: the check that a request is seen
    planted = tmp_path / "planted.html"
    planted.write_text('<html><head></head><body><script src="https://cdn.plot.ly/plotly-3.0.1.min.js"></script>'
                       '</body></html>')
    # software WebGL (SwiftShader) opted in, as Chromium asks of a machine without a GPU; 10 s of the page's own
    # time for plotly to draw
    extra = [*_OFFLINE, "--enable-unsafe-swiftshader", "--virtual-time-budget=10000"]
    shots = {name: tmp_path / f"{name}.png" for name in ("view", "hidden", "planted")}
    runs = {name: browser.start(_watched(p), shots[name], tmp_path / f"profile_{name}", size=(1200, 800),
                                extra=extra)
            for name, p in (("view", page), ("hidden", hidden), ("planted", planted))}
    consoles = {name: browser.console(run) for name, run in runs.items()}
    assert any("script 'https://cdn.plot.ly/plotly-3.0.1.min.js' violates the following Content Security Policy"
               in line for line in consoles["planted"]), consoles["planted"]
    # no console message but the software renderer's performance notes (a GPU stall reading pixels back;
    # Chrome's advice on 2-D canvas readbacks): no request refused, no error, no warning of plotly's; the
    # plant's warning is seen
    notes = ("GL Driver Message (OpenGL, Performance", "Canvas2D: Multiple readback operations")
    left = {name: [line for line in lines if not any(n in line for n in notes)] for name, lines in consoles.items()}
    assert left["view"] == [], left["view"]
    assert any("Invalid color specifier" in line for line in left["hidden"]), left["hidden"]
    rgb = np.asarray(Image.open(shots["view"]).convert("RGB"), dtype=int)
    bare = np.asarray(Image.open(shots["hidden"]).convert("RGB"), dtype=int)
    assert rgb.shape == (800, 1200, 3)
    # the lines, under the sea surface (opacity 0.25, rgb(70, 130, 180)), are seen in Viridis' lowest colour
    # #440154 through it: 0.75 (68, 1, 84) + 0.25 (70, 130, 180) = (68.5, 33.3, 108); Chromium drew (73, 37, 112)
    # (its blending in 8-bit steps; tolerance 12 levels as the report's test). Counted left of the colour bar.
    seen = tuple(0.75 * np.array((0x44, 0x01, 0x54)) + 0.25 * np.array((70, 130, 180)))
    lines, bare = browser.near(rgb[:, :1050], seen, 12), browser.near(bare[:, :1050], seen, 12)
    # three lines of about 300 px on the screen, 3 px wide: 816 px of that colour when this was written (its
    # edges blended with the background besides); the page without its lines has none
    assert lines > 400 and bare == 0, (lines, bare)
    # the seabed and the sea are drawn too: sand (194, 166, 120) seen through the sea
    assert browser.near(rgb, (194, 166, 120), 40) > 20_000

"""Figures, animation and the ``animate`` command of the cable-laying dynamics result (paper 001).

The result is synthetic, built here in the documented ``laying_dynamic`` layout so that the
expected curves are known exactly: a ship at x = 2 t m in 50 m of water over a flat seabed, the
suspended cable a straight line at 13 deg down from the ship to the touchdown point, nodes every
20 m of arc length, the count of suspended nodes varying with time (NaN padding beyond it), the
nodes behind the touchdown point laid in landing order, and one repeater entering the water at
about t = 47 s. Each test checks something that can fail: file names, the PNG signature, the
number of GIF frames, what each curve of the figures holds, and the errors.

The animation of a lay along a route in 3-D is checked on a short real run (100 s, 5 m segments,
100 m of water, an alter-course at KP 50 m and a cross-current): plan view and profile by KP.
"""

import math
import struct
from pathlib import Path

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from PIL import Image

import seacable as sc
from seacable.cli import main
from seacable.errors import InputError
from seacable.plot import FIGURES, animate_laying, plot_result
from seacable.results import make_dataset, read_netcdf, var, write_netcdf

DEPTH = 50.0  # [m]
ANGLE = np.radians(13.0)  # entry angle from the horizontal [rad]
SPEED = 2.0  # ship speed [m/s]
SPACING = 20.0  # arc length between nodes [m]
X_START = -300.0  # x of the first laid node (s = 0) [m]
H = 20e3  # horizontal tension [N]
W = 200.0  # submerged weight [N/m]
S_REPEATER = 400.0  # arc length of the repeater [m]
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
DEPTH_3D = 100.0  # water depth of the 3-D lay [m]


def _touchdown_x(t):
    return SPEED * t - DEPTH / np.tan(ANGLE)


def _point(s, t):
    """(x, z) of arc length s at time t on the seabed-then-straight-line shape."""
    s_td = _touchdown_x(t) - X_START
    d = np.maximum(s - s_td, 0.0)
    x = np.where(s <= s_td, X_START + s, _touchdown_x(t) + d * np.cos(ANGLE))
    z = np.where(s <= s_td, -DEPTH, -DEPTH + d * np.sin(ANGLE))
    return x, z


def synthetic_lay(time, *, repeater=True, interrupted=0):
    """A laying_dynamic result of the straight 13-deg lay described in the module docstring."""
    time = np.asarray(time, dtype=float)
    s_td = _touchdown_x(time) - X_START
    s_ship = s_td + DEPTH / np.sin(ANGLE)
    k0 = np.floor(s_td / SPACING).astype(int)  # last landed node
    rows = []
    for t, k, top in zip(time, k0, s_ship):
        s = np.arange(k, np.floor(top / SPACING) + 1) * SPACING
        s = np.append(s[s < top - 1e-9], top)  # the last node is the water-entry point at the ship
        rows.append(s)
    n_node = max(len(r) for r in rows)
    x = np.full((time.size, n_node), np.nan)
    z = np.full_like(x, np.nan)
    tension = np.full((time.size, n_node - 1), np.nan)
    for i, (t, s) in enumerate(zip(time, rows)):
        x[i, :s.size], z[i, :s.size] = _point(s, t)
        z_mid = 0.5 * (z[i, 1:s.size] + z[i, :s.size - 1])
        tension[i, :s.size - 1] = H + W * (z_mid + DEPTH)
    k_laid = np.arange(k0.max() + 1)
    laid_x = X_START + k_laid * SPACING
    laid_time = np.maximum((laid_x + DEPTH / np.tan(ANGLE)) / SPEED, time[0])
    slack = np.where(time < 3.0, np.nan, 0.02)
    rep_x = np.full((time.size, 1 if repeater else 0), np.nan)
    rep_z = np.full_like(rep_x, np.nan)
    if repeater:
        wet = s_ship >= S_REPEATER
        rep_x[wet, 0], rep_z[wet, 0] = _point(S_REPEATER, time[wet])
    t1 = ("time",)
    data = {
        "x": var(("time", "node"), x, "m", "x"),
        "z": var(("time", "node"), z, "m", "z, up from the sea surface"),
        "tension": var(("time", "segment"), tension, "N", "effective tension"),
        "ship_x": var(t1, SPEED * time, "m", "ship x"),
        "ship_speed": var(t1, np.full(time.size, SPEED), "m s-1", "ship speed"),
        "payout_speed": var(t1, np.full(time.size, SPEED * 1.02), "m s-1", "payout speed"),
        "paid_out": var(t1, s_ship, "m", "cable paid out"),
        "top_tension": var(t1, np.full(time.size, H + W * DEPTH), "N", "top tension"),
        "bottom_tension": var(t1, np.full(time.size, H), "N", "bottom tension"),
        "entry_angle": var(t1, np.full(time.size, np.radians(13.0)), "rad", "entry angle"),
        "touchdown_x": var(t1, _touchdown_x(time), "m", "touchdown x"),
        "touchdown_z": var(t1, np.full(time.size, -DEPTH), "m", "touchdown z"),
        "slack": var(t1, slack, "1", "slack"),
        "suspended_length": var(t1, s_ship - k0 * SPACING, "m", "suspended length"),
        "laid_length": var(t1, k0 * SPACING, "m", "laid length"),
        "laid_x": var("laid", laid_x, "m", "laid x"),
        "laid_z": var("laid", np.full(laid_x.size, -DEPTH), "m", "laid z"),
        "laid_s": var("laid", k_laid * SPACING, "m", "laid arc length"),
        "laid_time": var("laid", laid_time, "s", "landing time"),
        "seabed_x": var("seabed_point", np.linspace(-400.0, 400.0, 9), "m", "seabed x"),
        "seabed_z": var("seabed_point", np.full(9, -DEPTH), "m", "seabed z"),
        "repeater_x": var(("time", "repeater"), rep_x, "m", "repeater x"),
        "repeater_z": var(("time", "repeater"), rep_z, "m", "repeater z"),
        "repeater_s": var("repeater", [S_REPEATER] if repeater else [], "m", "repeater arc length"),
    }
    coords = {"time": var("time", time, "s", "time")}
    ds = make_dataset(data, coords, analysis="laying_dynamic", title="synthetic lay")
    ds.attrs["case_name"] = "lay"
    ds.attrs["interrupted"] = interrupted
    return ds


@pytest.fixture(scope="module")
def lay():
    return synthetic_lay(np.arange(0.0, 100.5, 1.0))


def test_synthetic_layout_is_what_the_figures_expect(lay):
    # guards the fixture itself: the node count varies, node 0 is on the seabed, the last valid
    # node is at the ship on the surface (1e-9 m: float round-off of sums of O(100) m)
    count = np.isfinite(lay.x.values).sum(axis=1)
    assert count.min() < count.max()
    last = lay.x.values[np.arange(lay.time.size), count - 1]
    np.testing.assert_allclose(last, lay.ship_x.values, atol=1e-9)
    np.testing.assert_allclose(lay.z.values[:, 0], -DEPTH, atol=1e-9)
    np.testing.assert_allclose(lay.z.values[np.arange(lay.time.size), count - 1], 0.0, atol=1e-9)


def _png_size(path: Path) -> tuple[int, int]:
    head = path.read_bytes()[:24]
    assert head[:8] == PNG_SIGNATURE, f"{path.name} is not a PNG"
    return struct.unpack(">II", head[16:24])


@pytest.mark.parametrize("repeater", [True, False])
def test_plot_result_writes_the_two_pngs_from_netcdf(tmp_path, repeater, n_colours):
    ds = synthetic_lay(np.arange(0.0, 40.5, 2.0), repeater=repeater)
    ds = read_netcdf(write_netcdf(ds, tmp_path / "lay.nc"))
    paths = plot_result(ds, tmp_path / "figs", prefix="lay")
    assert "laying_dynamic" in FIGURES
    assert [p.name for p in paths] == ["lay_shape.png", "lay_tension.png"]
    for path in paths:
        width, height = _png_size(path)
        # the figures are 11 x 4.5 and 8 x 8 in at 110 dpi; tight_layout does not crop the canvas
        assert width >= 800 and height >= 490, (path.name, width, height)
        pixels = plt.imread(path)[..., :3]
        # more than a handful of colours: curves, fill and text were drawn on the white canvas
        assert n_colours(pixels) > 10, path.name


def test_shape_figure_snapshots_laid_cable_and_repeater(lay):
    figs = FIGURES["laying_dynamic"](lay, plt)
    assert set(figs) == {"shape", "tension"}
    ax = figs["shape"].axes[0]
    lines = {ln.get_label(): ln for ln in ax.get_lines()}
    # 100 s -> a snapshot every 20 s (the rule of _snapshot_times): 6 snapshots
    snaps = [f"t = {t:g} s" for t in range(0, 101, 20)]
    assert set(snaps) <= set(lines)
    assert "every 20 s" in ax.get_title()
    for label in snaps:
        t = float(label.split()[2])
        x, z = lines[label].get_data()
        i = int(np.flatnonzero(lay.time.values == t)[0])
        n = int(np.isfinite(lay.x.values[i]).sum())
        # exactly the valid nodes of that time, NaN padding dropped, ending at the ship
        assert len(x) == n and np.all(np.isfinite(x))
        np.testing.assert_array_equal(x, lay.x.values[i, :n])
        assert x[-1] == pytest.approx(2.0 * t, abs=1e-9) and z[-1] == pytest.approx(0.0, abs=1e-9)
    np.testing.assert_array_equal(lines["laid cable"].get_xdata(), lay.laid_x.values)
    rx, rz = lines["repeater (t = 100 s)"].get_data()
    np.testing.assert_allclose(np.r_[rx, rz], _point(S_REPEATER, 100.0), atol=1e-9)
    # the frame covers the cable and the ship: laid start and final ship position inside
    x0, x1 = ax.get_xlim()
    assert x0 < X_START and x1 > 200.0
    y0, y1 = ax.get_ylim()
    assert y0 < -DEPTH and y1 > 0.0
    for fig in figs.values():
        plt.close(fig)


def test_tension_figure_panels(lay):
    figs = FIGURES["laying_dynamic"](lay, plt)
    fig = figs["tension"]
    ax1, ax2, ax3, twin = fig.axes
    assert ax1.get_shared_x_axes().joined(ax1, ax3)
    # tensions of 20-30 kN are drawn in kN
    assert ax1.get_ylabel() == "tension [kN]"
    top, bottom = (ln.get_ydata() for ln in ax1.get_lines())
    np.testing.assert_allclose(top, (H + W * DEPTH) / 1e3)
    np.testing.assert_allclose(bottom, H / 1e3)
    # slack in percent (NaN before t = 3 s left as gaps), entry angle in degrees on the twin axis
    slack = ax2.get_lines()[0].get_ydata()
    assert np.isnan(slack[:3]).all()
    np.testing.assert_allclose(slack[3:], 2.0)
    assert ax2.get_ylabel() == "slack [%]" and twin.get_ylabel() == "entry angle [deg]"
    np.testing.assert_allclose(twin.get_lines()[0].get_ydata(), 13.0)
    ship, payout = (ln.get_ydata() for ln in ax3.get_lines())
    np.testing.assert_allclose(ship, SPEED)
    np.testing.assert_allclose(payout, 1.02 * SPEED)
    assert "interrupted" not in ax1.get_title()
    for f in figs.values():
        plt.close(f)


def test_interrupted_run_says_so_in_the_titles():
    ds = synthetic_lay(np.arange(0.0, 37.5, 0.5), interrupted=1)
    figs = FIGURES["laying_dynamic"](ds, plt)
    assert "interrupted at t = 37 s" in figs["shape"].axes[0].get_title()
    assert "interrupted at t = 37 s" in figs["tension"].axes[0].get_title()
    for f in figs.values():
        plt.close(f)


@pytest.mark.parametrize("n_times, max_frames, expected", [(101, 12, 12), (7, 200, 7), (5, 1, 1)])
def test_gif_has_min_of_max_frames_and_times(tmp_path, n_times, max_frames, expected):
    ds = synthetic_lay(np.linspace(0.0, 100.0, n_times))
    path = animate_laying(ds, tmp_path / "sub" / "lay.gif", fps=5, max_frames=max_frames, dpi=30)
    assert path == tmp_path / "sub" / "lay.gif"
    with Image.open(path) as gif:
        assert gif.format == "GIF"
        assert gif.n_frames == expected
        gif.seek(0)
        first = np.asarray(gif.convert("RGB"))
        gif.seek(gif.n_frames - 1)
        last = np.asarray(gif.convert("RGB"))
    if expected > 1:  # the ship moves 200 m and the laid cable grows: the frames differ
        assert np.any(first != last)


@pytest.mark.parametrize("name, kwargs, message", [
    ("lay.avi", {}, "must end in .gif or .mp4"),
    ("lay", {}, "must end in .gif or .mp4"),
    ("lay.gif", {"fps": 0}, "fps must be > 0 1/s, got 0 1/s"),
    ("lay.gif", {"max_frames": -3}, "max_frames must be > 0, got -3"),
    ("lay.gif", {"dpi": -1}, "dpi must be > 0 1/in, got -1 1/in"),
])
def test_animate_bad_arguments(tmp_path, lay, name, kwargs, message):
    with pytest.raises(InputError, match="Suggested fix") as info:
        animate_laying(lay, tmp_path / name, **kwargs)
    assert message in str(info.value)
    assert not (tmp_path / name).exists()


def test_animate_refuses_other_analyses(tmp_path, lay):
    other = lay.copy()
    other.attrs["analysis"] = "towed_dynamic"
    with pytest.raises(InputError, match="needs a 'laying_dynamic' result, got analysis 'towed_dynamic'"):
        animate_laying(other, tmp_path / "lay.gif")


def test_mp4_without_ffmpeg_suggests_gif(tmp_path, lay, monkeypatch):
    from matplotlib.animation import FFMpegWriter

    monkeypatch.setattr(FFMpegWriter, "isAvailable", classmethod(lambda cls: False))
    with pytest.raises(InputError, match="ffmpeg") as info:
        animate_laying(lay, tmp_path / "lay.mp4")
    assert f"-o {tmp_path / 'lay.gif'}" in str(info.value)


def test_cli_animate(tmp_path, capsys):
    nc = write_netcdf(synthetic_lay(np.arange(0.0, 20.5, 1.0)), tmp_path / "run.nc")
    assert main(["animate", str(nc), "--max-frames", "4", "--fps", "4"]) == 0
    default = tmp_path / "run_lay.gif"
    assert capsys.readouterr().out.strip() == f"wrote {default}"
    with Image.open(default) as gif:
        assert gif.n_frames == 4
    out = tmp_path / "anim" / "x.gif"
    assert main(["animate", str(nc), "-o", str(out), "--max-frames", "3"]) == 0
    with Image.open(out) as gif:
        assert gif.n_frames == 3


@pytest.mark.parametrize("case, expected", [
    ("missing", "does not exist"),
    ("other", "needs a 'laying_dynamic' result"),
    ("suffix", "must end in .gif or .mp4"),
])
def test_cli_animate_user_errors_exit_2(tmp_path, capsys, case, expected):
    ds = synthetic_lay(np.arange(0.0, 4.5, 1.0))
    argv = ["animate", str(tmp_path / "none.nc")]
    if case == "other":
        ds.attrs["analysis"] = "towed_dynamic"
        argv = ["animate", str(write_netcdf(ds, tmp_path / "tow.nc"))]
    if case == "suffix":
        argv = ["animate", str(write_netcdf(ds, tmp_path / "lay.nc")), "-o", str(tmp_path / "lay.png")]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("seacable: error: ") and expected in err
    assert "Traceback" not in err


def _short_route_lay():
    """A 100 s lay of paper 001's cable along a route turning 20 deg to port at KP 50 m, in 100 m of water
    with 0.2 m/s of cross-current: the ship passes the waypoint, the span is turned off the route."""
    from seacable.laying.route import Route

    cable = sc.LineType(diameter=0.0225, mass_per_length=0.867, weight_in_water=4.49, drag_normal=1.85,
                        drag_tangential=0.01, name="paper001")
    route = Route(waypoints=((-1000.0, 0.0), (50.0, 0.0), (600.0, 200.0)), kp_start=-1000.0)
    return sc.Case(name="lay3d", line=sc.Line.single(cable, 2000.0),
                   environment=sc.Environment(water_density=1030.0, depth=DEPTH_3D,
                                              current=sc.Current(speed=0.2, heading=math.pi / 2)),
                   analysis=sc.LayingDynamicAnalysis(ship=sc.ShipMotion(speed=1.0), payout=sc.PayoutSlack(slack=0.05),
                                                     duration=100.0, segment_length=5.0, output_interval=10.0,
                                                     route=route))


@pytest.fixture(scope="module")
def short_route_lay():
    """The run of `_short_route_lay`, shared by the two tests that draw it (each takes a deep copy)."""
    return sc.run(_short_route_lay())


def test_cli_animate_route_lay_plan_and_profile(tmp_path, monkeypatch, short_route_lay):
    """A 3-D lay animates as two panels, plan view (x, y) and profile by KP; the last frame's suspended
    cable runs from the ship, at its KP on the surface, down to the touchdown on the seabed."""
    nc = write_netcdf(short_route_lay.copy(deep=True), tmp_path / "lay3d.nc")
    ds = read_netcdf(nc)
    figures = []
    close = plt.close
    monkeypatch.setattr(plt, "close", lambda fig=None: figures.append(fig))   # keep the frame to look at
    out = tmp_path / "lay3d.gif"
    assert main(["animate", str(nc), "-o", str(out), "--max-frames", "3"]) == 0
    monkeypatch.setattr(plt, "close", close)
    with Image.open(out) as gif:
        assert gif.format == "GIF" and gif.n_frames == 3
    (fig,) = figures
    plan, side = fig.axes[:2]
    assert len(fig.axes) == 2
    assert (plan.get_xlabel(), plan.get_ylabel()) == ("x [m]", "y [m]")
    assert (side.get_xlabel(), side.get_ylabel()) == ("KP [m]", "elevation (0 at the sea surface) [m]")
    lines = {ln.get_label(): ln for ln in side.get_lines()}
    kp, z = lines["suspended cable"].get_data()      # the last frame: t = 100 s
    assert kp[-1] == pytest.approx(float(ds.ship_kp[-1]), abs=1e-6) and z[-1] == pytest.approx(0.0, abs=1e-9)
    assert z[0] == pytest.approx(-DEPTH_3D, abs=1e-6)
    # node 0 is the first node on the seabed: within a segment (5 m) behind the touchdown
    assert float(ds.touchdown_kp[-1]) - 5.0 - 1e-6 <= kp[0] <= float(ds.touchdown_kp[-1]) + 1e-6
    np.testing.assert_allclose(lines["ship"].get_data(), [[float(ds.ship_kp[-1])], [0.0]])
    x, y = {ln.get_label(): ln for ln in plan.get_lines()}["suspended cable"].get_data()
    n = int(np.isfinite(ds.x.values[-1]).sum())
    np.testing.assert_array_equal(np.c_[x, y], np.c_[ds.x.values[-1, :n], ds.y.values[-1, :n]])
    # the limits cover the whole run: from the first laid node to the ship's last position
    assert side.get_xlim()[0] < float(ds.laid_kp.min()) and side.get_xlim()[1] > float(ds.ship_kp[-1])
    assert plan.get_xlim()[0] < float(ds.laid_x.min()) and plan.get_xlim()[1] > float(ds.ship_x[-1])
    close(fig)


def test_route_lay_shape_is_the_profile_by_kp(short_route_lay):
    """A 3-D lay's shape figure draws each snapshot along the route by KP (by x it would fold back on itself after
    an alter-course): the last snapshot runs from the ship's KP on the surface down to the seabed, and the laid
    cable is drawn at its KPs."""
    from seacable.plot.laying import _laying_dynamic

    ds = short_route_lay.copy(deep=True)
    fig = _laying_dynamic(ds, plt)["shape"]
    (ax,) = fig.axes
    assert ax.get_xlabel() == "KP [m]" and "along the route" in ax.get_title()
    lines = {ln.get_label(): ln for ln in ax.get_lines()}
    kp, z = lines[f"t = {float(ds.time[-1]):g} s"].get_data()
    assert kp[-1] == pytest.approx(float(ds.ship_kp[-1]), abs=1e-6) and z[-1] == pytest.approx(0.0, abs=1e-9)
    assert z[0] == pytest.approx(-DEPTH_3D, abs=1e-6)
    laid_kp, _ = lines["laid cable"].get_data()
    np.testing.assert_allclose(np.sort(laid_kp), np.sort(ds.laid_kp.values[np.isfinite(ds.laid_kp.values)]))
    plt.close(fig)


def test_plan_view_of_a_long_route_is_stretched_and_says_so():
    """A plan view at true scale of a route 100 km long and 2.2 km wide is a strip a few pixels high: it is drawn
    stretched across, the title giving the stretch (the axes' pixels per metre across over along; for this panel,
    2.8 by 4.6 inches, about 75); a compact route keeps the true scale."""
    from seacable.plot.laying import _plan_aspect

    fig, (long, compact) = plt.subplots(1, 2, figsize=(8, 6))
    _plan_aspect(long, np.array([0.0, 100.0]), np.array([0.0, 2.2]), "Plan view")
    _plan_aspect(compact, np.array([0.0, 10.0]), np.array([0.0, 3.0]), "Plan view")
    factor = float(long.get_title().split("about ")[1].split(" x")[0])
    assert 50.0 < factor < 100.0
    assert "y stretched" in long.get_title() and long.get_aspect() == "auto"
    assert compact.get_title() == "Plan view" and compact.get_aspect() == 1.0
    plt.close(fig)

"""Figures and animation of the tug-barge towline result (``towline_dynamic``, paper 003).

The results are synthetic, built here in the documented ``towline_dynamic`` layout so that every
curve is known exactly: an 11-element, 100 m towline (paper 003, Table) behind a tug moving along
+x at U; joint j at x = U t - j L/N, y = A (1 - j/N) cos(2 pi t / T) (a zig-zag whose sway falls
linearly from the tug to the barge; A = 0 for a straight tow), z = 2 m at the tug's tow point,
1 m at the barge's and 0 between (the line floats); the barge midship 25 m behind its tow point.
The payout variant (straight) starts with tug and barge together and every joint but the two tow
points on the bitt (NaN); it pays one element out every L/N / U seconds, the paid-out joints L/N
apart ahead of the barge, which stays put until the whole line is out. Each test checks what a curve holds, a label with its unit, or
an error, so that it fails when a figure is wrong, not only when it is missing.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest
import xarray as xr

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from PIL import Image

from seacable import plot as plot_module
from seacable.plot import towline as pt
from seacable.errors import InputError
from seacable.plot import plot_result
from seacable.plot.towline import (
    TOWLINE_FIGURES,
    animate_towline,
    towline_distance,
    towline_shape,
    towline_sway,
    towline_tension,
    towline_tracks,
)
from seacable.results import make_dataset, read_netcdf, var, write_netcdf

N = 11  # elements (paper 003)
LENGTH = 100.0  # towline length [m]
LE = LENGTH / N  # element length [m]
PERIOD = 50.0  # zig-zag period (paper 003) [s]
AMPLITUDE = 10.0  # zig-zag sway amplitude at the tug (paper 003) [m]
KNOT = 1852.0 / 3600.0  # [m/s]
TITLE = "Tug-barge towline, synthetic"
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def towline_result(time=None, *, amplitude=AMPLITUDE, speed=2 * KNOT, payout=False,
                   analysis="towline_dynamic"):
    """A towline_dynamic result of the synthetic tow described in the module docstring."""
    t = np.asarray(np.arange(101.0) if time is None else time, dtype=float)[:, None]
    j = np.arange(N + 1)[None, :]
    x = speed * t - j * LE
    y = amplitude * (1 - j / N) * np.cos(2 * np.pi * t / PERIOD)
    z = np.where(j == 0, 2.0, np.where(j == N, 1.0, 0.0)) + 0 * t
    released = np.ones((t.size, N), dtype=bool)
    if payout:
        out = np.minimum(np.floor(speed * t[:, 0] / LE).astype(int), N)  # elements paid out
        bow = np.maximum(speed * t - LENGTH, 0.0)  # the barge's tow point waits until the line is out
        x = np.where(j == 0, speed * t, bow + (N - j) * LE)  # paid-out joints: L/N apart from the barge
        for i, k in enumerate(out):
            hidden = (j[0] >= 1) & (j[0] <= N - 1 - k)  # joints still on the bitt
            x[i, hidden] = y[i, hidden] = z[i, hidden] = np.nan
            released[i, : N - k] = False
    top_tension = 20e3 + 5e3 * np.sin(2 * np.pi * t[:, 0] / PERIOD)
    barge_tension = 15e3 + 3e3 * np.sin(2 * np.pi * t[:, 0] / PERIOD - 0.5)
    tension = np.linspace(1.0, 0.75, N + 1)[None, :] * top_tension[:, None]

    def mid(a):
        return 0.5 * (a[:, 1:] + a[:, :-1])

    tn = ("time", "node")
    te = ("time", "element")
    data = {
        "x": var(tn, x, "m", "x position"), "y": var(tn, y, "m", "y position"),
        "z": var(tn, z, "m", "elevation"),
        "tension": var(tn, tension, "N", "joint tension"),
        "top_tension": var("time", top_tension, "N", "tension at the tug"),
        "barge_tension": var("time", barge_tension, "N", "tension at the barge"),
        "tug_x": var("time", x[:, 0], "m", "tug tow point x"), "tug_y": var("time", y[:, 0], "m", "tug tow point y"),
        "barge_x": var("time", x[:, N] - 25.0, "m", "barge x"), "barge_y": var("time", y[:, N], "m", "barge y"),
        "barge_heading": var("time", 0 * t[:, 0], "rad", "barge heading"),
        "barge_speed": var("time", speed + 0 * t[:, 0], "m s-1", "barge speed"),
        "element_x": var(te, mid(x), "m", "element centre x"), "element_y": var(te, mid(y), "m", "element centre y"),
        "element_z": var(te, mid(z), "m", "element centre z"),
        "released": var(te, released, "1", "element paid out"),
        "slack": var(tn, np.zeros_like(x, dtype=bool), "1", "joint slack"),
    }
    ds = make_dataset(data, {"time": var("time", t[:, 0], "s", "time"), "node": var("node", j[0], "1", "joint"),
                             "element": var("element", np.arange(N), "1", "element")},
                      analysis=analysis, title=TITLE)
    ds.attrs.update(n_elements=N, element_length=LE, scenario="synthetic")
    return ds


@pytest.fixture(scope="module")
def zigzag():
    return towline_result()


@pytest.fixture(scope="module")
def straight():
    return towline_result(amplitude=0.0)


@pytest.fixture(scope="module")
def payout():
    return towline_result(amplitude=0.0, speed=5 * KNOT, payout=True)


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _labelled(ax):
    return {ln.get_label(): ln for ln in ax.get_lines()}


def _snapshot_lines(ax):
    return [ln for ln in ax.get_lines() if ln.get_label().startswith(("t = ", "towline, t = "))]


# ----------------------------------------------------------------------------- fixtures

def test_synthetic_payout_hides_joints(payout):
    # guards the fixture: at t = 0 only the two tow points exist; 5 kn pays 100 m out in 39 s
    assert np.isfinite(payout.x.values[0]).sum() == 2
    assert np.isfinite(payout.x.values[-1]).all()
    assert not payout.released.values[0].any() and payout.released.values[-1].all()
    # every paid-out joint lies between the barge's tow point and the tug's
    x = payout.x.values
    assert np.all((x[:, 1:] <= x[:, :1] + 1e-9) | np.isnan(x[:, 1:]))
    assert np.all((x[:, :-1] >= x[:, -1:] - 1e-9) | np.isnan(x[:, :-1]))


# ----------------------------------------------------------------------------- tension

def test_tension_curves_in_kilonewtons(zigzag):
    fig = towline_tension(zigzag)
    ax1, ax2 = fig.axes
    lines = _labelled(ax1)
    assert list(lines) == ["at the tug", "at the barge"]
    # the plotted values are the result's divided by 1e3: exact to round-off
    np.testing.assert_allclose(lines["at the tug"].get_ydata(), zigzag.top_tension.values / 1e3, rtol=1e-15)
    np.testing.assert_allclose(lines["at the barge"].get_ydata(), zigzag.barge_tension.values / 1e3, rtol=1e-15)
    np.testing.assert_array_equal(lines["at the tug"].get_xdata(), zigzag.time.values)
    assert ax1.get_ylabel() == "towline tension [kN]"
    assert ax2.get_ylabel() == "barge speed [m/s]" and ax2.get_xlabel() == "time [s]"
    np.testing.assert_array_equal(ax2.get_lines()[0].get_ydata(), zigzag.barge_speed.values)
    assert fig._suptitle.get_text() == TITLE


def test_tension_without_barge_speed_is_one_panel(zigzag):
    fig = towline_tension(zigzag.drop_vars("barge_speed"))
    (ax,) = fig.axes
    assert ax.get_xlabel() == "time [s]" and len(ax.get_lines()) == 2


# ----------------------------------------------------------------------------- tracks

def test_tracks_plan_view(zigzag):
    fig = towline_tracks(zigzag)
    (ax,) = fig.axes
    lines = _labelled(ax)
    np.testing.assert_array_equal(lines["tug tow point"].get_xdata(), zigzag.tug_x.values)
    np.testing.assert_array_equal(lines["tug tow point"].get_ydata(), zigzag.tug_y.values)
    np.testing.assert_array_equal(lines["barge midship"].get_xdata(), zigzag.barge_x.values)
    # tug and barge marked at each snapshot (unlabelled markers, one legend entry each)
    markers = [ln for ln in ax.get_lines() if ln.get_label() == "_nolegend_"]
    np.testing.assert_array_equal([ln.get_xdata()[0] for ln in markers[0::2]], zigzag.tug_x.values[::20])
    np.testing.assert_array_equal([ln.get_xdata()[0] for ln in markers[1::2]], zigzag.barge_x.values[::20])
    assert "tug at the snapshot" in lines and "barge at the snapshot" in lines
    snaps = _snapshot_lines(ax)
    # 100 s: the round step nearest 100/5 s is 20 s -> 0, 20, ..., 100 s
    assert [ln.get_label() for ln in snaps] == [f"towline, t = {t} s" for t in range(0, 101, 20)]
    for ln, t in zip(snaps, range(0, 101, 20)):
        np.testing.assert_array_equal(ln.get_xdata(), zigzag.x.sel(time=t).values)
        np.testing.assert_array_equal(ln.get_ydata(), zigzag.y.sel(time=t).values)
    assert len({tuple(ln.get_color()) for ln in snaps}) == 6  # coloured by time
    assert ax.get_aspect() == 1.0  # equal aspect
    assert ax.get_xlabel() == "x [m]" and ax.get_ylabel() == "y [m]"
    assert "every 20 s" in ax.get_title()


# ----------------------------------------------------------------------------- shape

def test_horizontal_distance_from_the_tug(zigzag, straight):
    # straight tow: joint j is j L/N behind the tug (1e-12 m: round-off of 100 m)
    np.testing.assert_allclose(towline_distance(straight), np.broadcast_to(np.arange(N + 1) * LE, (101, N + 1)),
                               atol=1e-12)
    # zig-zag: Pythagoras with the sway relative to the tug, A j/N cos(2 pi t/T)
    t = zigzag.time.values[:, None]
    dy = AMPLITUDE * np.arange(N + 1) / N * np.cos(2 * np.pi * t / PERIOD)
    np.testing.assert_allclose(towline_distance(zigzag), np.hypot(np.arange(N + 1) * LE, dy), atol=1e-12)


def test_shape_elevation_and_plan(zigzag):
    from matplotlib import colormaps
    from matplotlib.colors import Normalize

    fig = towline_shape(zigzag)
    ax1, ax2, bar = fig.axes
    water = _labelled(ax1)["water surface"]
    np.testing.assert_array_equal(water.get_ydata(), [0.0, 0.0])
    elevation, plan = _snapshot_lines(ax1), _snapshot_lines(ax2)
    # 100 s, about 8 snapshots: the round step nearest 100/7 = 14.3 s in ratio is 20 s
    # (|ln(20/14.3)| = 0.34 < |ln(10/14.3)| = 0.36) -> 0, 20, ..., 100 s
    times = np.arange(0.0, 101.0, 20.0)
    assert [ln.get_label() for ln in elevation] == [f"t = {t:g} s" for t in times]
    h = towline_distance(zigzag)
    norm = Normalize(0.0, 100.0)
    for ln, ln2, t in zip(elevation, plan, times):
        i = int(t)
        np.testing.assert_array_equal(ln.get_xdata(), h[i])
        np.testing.assert_array_equal(ln.get_ydata(), zigzag.z.values[i])
        np.testing.assert_allclose(ln2.get_xdata(), -np.arange(N + 1) * LE, atol=1e-12)  # x - x_tug
        np.testing.assert_allclose(ln2.get_ydata(), zigzag.y.values[i] - zigzag.tug_y.values[i], atol=1e-12)
        # the colour is the colour bar's at that time
        np.testing.assert_allclose(ln.get_color(), colormaps["viridis"](norm(t)))
    assert ax1.get_xlabel() == "horizontal distance from the tug's tow point [m]"
    assert ax1.get_ylabel() == "z (0 at the water surface) [m]"
    assert ax2.get_xlabel() == "x - x_tug [m]" and ax2.get_ylabel() == "y - y_tug [m]"
    assert bar.get_ylabel() == "time [s]"


# ----------------------------------------------------------------------------- sway

def test_sway_amplitude_is_exact_on_sampled_peaks():
    # cos(2 pi t / 50) sampled every 1 s hits its peak (t = 50, 100) and trough (t = 75) exactly
    t = np.arange(101.0)
    y = np.outer(np.cos(2 * np.pi * t / PERIOD), [10.0, 5.0, 0.0]) + 3.0  # an offset does not count
    np.testing.assert_allclose(pt._sway_amplitude(y), [10.0, 5.0, 0.0], atol=1e-12)
    y[:, 1] = np.nan
    assert np.isnan(pt._sway_amplitude(y)[1])


def test_sway_falls_away_from_the_tug(zigzag):
    fig = towline_sway(zigzag)
    (ax,) = fig.axes
    lines = ax.get_lines()
    nodes = [0, 3, 6, 8, 11]  # round(k 11 / 4), k = 0..4 (numpy rounds 5.5 to 6)
    assert len(lines) == 5
    for ln, j in zip(lines, nodes):
        np.testing.assert_array_equal(ln.get_ydata(), zigzag.y.values[:, j])
        # the legend gives A (1 - j/N), the synthetic amplitude, to 0.01 m
        assert f"amplitude {AMPLITUDE * (1 - j / N):.2f} m" in ln.get_label()
    assert lines[0].get_label().startswith("node 0 (tug, ")
    assert lines[-1].get_label().startswith("node 11 (barge, ")
    assert "s = 27 m" in lines[1].get_label()  # 3 x 9.09 m
    ranges = [np.ptp(ln.get_ydata()) for ln in lines]
    assert all(np.diff(ranges) < 0)
    assert ax.get_xlabel() == "time [s]" and ax.get_ylabel() == "sway y [m]"


def test_sway_of_a_joint_never_paid_out(zigzag):
    ds = zigzag.copy(deep=True)
    ds["y"][:, 6] = np.nan
    labels = [ln.get_label() for ln in towline_sway(ds).axes[0].get_lines()]
    assert labels[2] == "node 6 (s = 55 m, not paid out)"


def test_zigzag_detection(straight, zigzag):
    assert not pt._is_zigzag(straight) and pt._is_zigzag(zigzag)
    # threshold 0.1 % of 100 m = 0.1 m peak to peak: 1 cm of sway is a straight tow, 0.2 m is not
    assert not pt._is_zigzag(towline_result(amplitude=0.005))
    assert pt._is_zigzag(towline_result(amplitude=0.1))
    # a straight tow along a diagonal course is still straight (the course is the track's own axis)
    ds = straight.copy()
    ds["tug_y"] = ds.tug_x * 0.7 + 3.0
    assert not pt._is_zigzag(ds)


# ----------------------------------------------------------------------------- payout (NaN joints)

def test_payout_figures_skip_joints_on_the_bitt(payout):
    figs = TOWLINE_FIGURES["towline_dynamic"](payout, plt)
    snaps = _snapshot_lines(figs["tracks"].axes[0])
    n_out = [np.isfinite(payout.x.sel(time=t).values).sum() for t in range(0, 101, 20)]
    assert n_out[0] == 2 and n_out[-1] == N + 1  # the fixture pays the line out between the snapshots
    assert [ln.get_xdata().size for ln in snaps] == n_out
    for fig in (figs["tracks"], figs["shape"]):
        for ax in fig.axes:
            for ln in ax.get_lines():
                assert np.isfinite(np.asarray(ln.get_xdata(), float)).all(), ln.get_label()
                assert np.isfinite(np.asarray(ln.get_ydata(), float)).all(), ln.get_label()
    elevation = _snapshot_lines(figs["shape"].axes[0])
    np.testing.assert_array_equal(elevation[0].get_ydata(), [2.0, 1.0])  # t = 0: the two tow points
    assert "sway" not in figs  # a straight payout tow
    # asked for anyway, the sway figure draws the NaN rows as gaps; every joint is out after 39 s
    labels = [ln.get_label() for ln in towline_sway(payout).axes[0].get_lines()]
    assert all(label.endswith("amplitude 0.00 m)") for label in labels)


# ----------------------------------------------------------------------------- plot_result and files

def test_towline_dynamic_is_registered():
    # plot_result (and so 'seacable run' and 'seacable plot') draws a towline result with these figures
    assert plot_module.FIGURES["towline_dynamic"] is TOWLINE_FIGURES["towline_dynamic"]


@pytest.mark.parametrize("fixture, names", [
    ("zigzag", ["tow_tension.png", "tow_tracks.png", "tow_shape.png", "tow_sway.png"]),
    ("straight", ["tow_tension.png", "tow_tracks.png", "tow_shape.png"]),
])
def test_plot_result_writes_pngs(request, monkeypatch, tmp_path, fixture, names, n_colours):
    ds = request.getfixturevalue(fixture)
    for analysis, function in TOWLINE_FIGURES.items():  # as the lead registers them in plot.FIGURES
        monkeypatch.setitem(plot_module.FIGURES, analysis, function)
    paths = plot_result(ds, tmp_path, prefix="tow")
    assert [p.name for p in paths] == names
    for path in paths:
        assert path.read_bytes()[:8] == PNG_SIGNATURE
        pixels = plt.imread(path)[..., :3]
        assert n_colours(pixels) > 10, path.name  # something was drawn


def test_figures_from_a_netcdf_file(tmp_path, payout):
    # booleans and attributes survive NetCDF: the figures of the file are those of the Dataset
    ds = read_netcdf(write_netcdf(payout, tmp_path / "tow.nc"))
    fig = towline_tracks(ds)
    sizes = [ln.get_xdata().size for ln in _snapshot_lines(fig.axes[0])]
    assert sizes == [np.isfinite(payout.x.sel(time=t).values).sum() for t in range(0, 101, 20)]


# ----------------------------------------------------------------------------- animation

def test_animation_gif_has_the_frames(tmp_path, zigzag):
    path = animate_towline(zigzag, tmp_path / "sub" / "tow.gif", fps=5, max_frames=3, dpi=30)
    assert path == tmp_path / "sub" / "tow.gif" and path.stat().st_size > 0
    with Image.open(path) as gif:
        assert gif.format == "GIF" and gif.n_frames == 3
        gif.seek(0)
        first = np.asarray(gif.convert("RGB"))
        gif.seek(2)
        last = np.asarray(gif.convert("RGB"))
    assert np.any(first != last)  # the tug moved 100 m: the frames differ


def test_animation_follows_a_long_run(tmp_path, payout):
    # 5 kn for 300 s spans 772 m of track plus the barge: more than 3 line lengths -> moving box;
    # the 100 s run spans 257 m + 25 m (barge midship behind its tow point): one fixed box
    long = towline_result(time=np.arange(0.0, 301.0, 5.0), amplitude=0.0, speed=5 * KNOT, payout=True)
    fixed, half = pt._plan_box(long, long.x.values, long.y.values)
    assert fixed is None and half == pytest.approx(0.7 * LENGTH)
    assert pt._plan_box(payout, payout.x.values, payout.y.values)[0] is not None
    path = animate_towline(long, tmp_path / "long.gif", max_frames=3, dpi=30)
    with Image.open(path) as gif:
        assert gif.n_frames == 3


@pytest.mark.parametrize("name, kwargs, message", [
    ("tow.avi", {}, "must end in .gif or .mp4"),
    ("tow", {}, "must end in .gif or .mp4"),
    ("tow.gif", {"fps": 0}, "fps must be > 0 1/s, got 0 1/s"),
    ("tow.gif", {"max_frames": -3}, "max_frames must be > 0, got -3"),
    ("tow.gif", {"dpi": -1}, "dpi must be > 0 1/in, got -1 1/in"),
])
def test_animate_bad_arguments(tmp_path, zigzag, name, kwargs, message):
    with pytest.raises(InputError, match="Suggested fix") as info:
        animate_towline(zigzag, tmp_path / name, **kwargs)
    assert message in str(info.value)


def test_mp4_without_ffmpeg(tmp_path, zigzag, monkeypatch):
    from matplotlib.animation import FFMpegWriter

    monkeypatch.setattr(FFMpegWriter, "isAvailable", classmethod(lambda cls: False))
    with pytest.raises(InputError, match=r"MP4 needs ffmpeg.*Suggested fix: .* -o .*tow\.gif"):
        animate_towline(zigzag, tmp_path / "tow.mp4")


# ----------------------------------------------------------------------------- errors

@pytest.mark.parametrize("function", [towline_tension, towline_tracks, towline_shape, towline_sway,
                                      lambda ds: animate_towline(ds, "unused.gif")])
def test_wrong_analysis_is_an_input_error(function):
    ds = towline_result(analysis="towed_dynamic")
    with pytest.raises(InputError, match=r"needs a 'towline_dynamic' result, got analysis 'towed_dynamic'\. "
                                         r"Suggested fix"):
        function(ds)


def test_missing_variable_and_no_times(zigzag):
    with pytest.raises(InputError, match=r"lacks the variable\(s\) tug_x, barge_y\. Suggested fix"):
        towline_tracks(zigzag.drop_vars(["tug_x", "barge_y"]))
    with pytest.raises(InputError, match="no output times to draw. Suggested fix"):
        towline_tension(zigzag.isel(time=slice(0, 0)))
    with pytest.raises(InputError, match="needs a 'towline_dynamic'"):
        TOWLINE_FIGURES["towline_dynamic"](xr.Dataset(attrs={"analysis": "static"}), plt)

"""Figures of the mooring analyses (``seacable.plot.mooring``).

The results are real runs of the OC3-Hywind line (examples/oc3_hywind_line.yaml: 902.2 m of
line, anchor 320 m deep, fairlead at x = 848.67 m, z = -70 m) with 20 elements, through
:func:`seacable.run`: the static equilibrium, a pushover to 20 m and a 10 s run with a 5 m
surge of 10 s period (ramped over 5 s), which slackens the line and gives snap loads. A
``line`` dimension is built by concatenating two runs. Each test checks what a curve holds
(the data of the result, in the documented units) or a geometric identity, so that it fails
when the figure is wrong, not only when it is missing.
"""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib
import numpy as np
import pytest
import xarray as xr
import yaml

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import seacable as sc
from seacable import plot as plot_module
from seacable.errors import InputError
from seacable.plot import plot_result
from seacable.plot._core import _snapshot_times
from seacable.plot.mooring import (
    MOORING_FIGURES,
    plot_mooring_dynamic,
    plot_mooring_pushover,
    plot_mooring_static,
)

EXAMPLE = Path(__file__).parents[2] / "examples" / "oc3_hywind_line.yaml"
DEPTH = 320.0  # water depth of the example [m]
LENGTH = 902.2  # unstretched line length [m]
FAIRLEAD = [848.67, -70.0]  # [m]
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
SHAPE_Y = "elevation (0 at the still water level) [m]"  # long_name and units of z in mooring/run.py
SCENE = {"seabed", "sea surface"}


def _case(**analysis):
    data = yaml.safe_load(EXAMPLE.read_text())
    data["analysis"] = {"fairlead": FAIRLEAD, "n_elements": 20, **analysis}
    return sc.Case.model_validate(data)


def _dynamic(amplitude: float, n_elements: int = 20):
    return sc.run(_case(type="mooring_dynamic", n_elements=n_elements, duration=10.0, time_step=0.1,
                        output_interval=0.5,
                        motion={"type": "harmonic", "amplitude": [amplitude, 0.0, 0.0], "period": 10.0,
                                "ramp": 5.0}))


def _two_lines(a, b):
    """Two single-line runs as one result with a leading ``line`` dimension (snap rows NaN-padded)."""
    a, b = (d.assign_coords(snap=np.arange(d.sizes.get("snap", 0))) for d in (a, b))
    return xr.concat([a, b], dim=xr.DataArray(["line 1", "line 2"], dims="line", name="line"),
                     join="outer", data_vars="all", coords="minimal", compat="override")


@pytest.fixture(scope="module")
def static():
    return sc.run(_case(type="mooring_static"))


@pytest.fixture(scope="module")
def pushover():
    return sc.run(_case(type="mooring_pushover", max_offset=20.0, n_offsets=9))


@pytest.fixture(scope="module")
def dynamic():
    return _dynamic(5.0)


@pytest.fixture(scope="module")
def calm():
    return _dynamic(2.0)


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _cable_lines(ax):
    return [ln for ln in ax.get_lines() if ln.get_label() not in SCENE and len(ln.get_xdata()) > 1]


def _by_label(ax):
    return {ln.get_label(): ln for ln in ax.get_lines()}


# ----------------------------------------------------------------------------- fixtures

def test_runs_are_what_the_figures_are_tested_on(static, dynamic, calm):
    # guards the fixtures: the surge slackens the line (snap loads), the 2 m one does not,
    # and the anchor rests on the seabed plane z = -320 m (penalty contact: 1 mm)
    assert dynamic.sizes["snap"] > 0 and calm.sizes["snap"] == 0
    assert static.z.values[0] == pytest.approx(-DEPTH, abs=1e-3)
    assert static.attrs["analysis"] == "mooring_static"


# ----------------------------------------------------------------------------- static

def test_static_shape_and_tension(static):
    (fig,) = plot_mooring_static(static)
    ax1, ax2 = fig.axes
    assert ax1.get_xlabel() == "x position [m]" and ax1.get_ylabel() == SHAPE_Y
    assert ax2.get_xlabel() == "unstretched arc length from the anchor [m]"
    assert ax2.get_ylabel() == "effective tension [kN]"  # tensions near 1 MN are drawn in kN
    (cable,) = _cable_lines(ax1)
    # the plotted points are the result's (no resampling): exact equality
    np.testing.assert_array_equal(cable.get_xdata(), static.x.values)
    np.testing.assert_array_equal(cable.get_ydata(), static.z.values)
    seabed = _by_label(ax1)["seabed"]
    np.testing.assert_array_equal(seabed.get_ydata(), -DEPTH)  # the case's depth, flat seabed
    (profile,) = ax2.get_lines()
    np.testing.assert_array_equal(profile.get_xdata(), static.s.values)
    np.testing.assert_allclose(profile.get_ydata(), static.tension.values / 1e3, rtol=1e-15)
    assert f"Fairlead {float(static.fairlead_tension) / 1e3:.1f} kN" in ax2.get_title()


def test_sloping_seabed_follows_the_plane_of_the_contact_model(static):
    # the contact of mooring/run.py penetrates below z = -depth + x tan(slope)
    ds = static.copy()
    case = yaml.safe_load(ds.attrs["case"])
    case["environment"]["seabed"]["slope"] = 0.05
    ds.attrs["case"] = yaml.safe_dump(case)
    (fig,) = plot_mooring_static(ds)
    x, z = _by_label(fig.axes[0])["seabed"].get_data()
    np.testing.assert_allclose(z, -DEPTH + np.asarray(x) * math.tan(0.05), rtol=1e-12)


def test_no_seabed_without_a_depth(static):
    ds = static.copy()
    ds.attrs = {k: v for k, v in ds.attrs.items() if k != "case"}
    (fig,) = plot_mooring_static(ds)
    assert "seabed" not in _by_label(fig.axes[0])
    ds.attrs["case"] = "environment: [unclosed"  # not YAML: the figure is still drawn, without a seabed
    (fig,) = plot_mooring_static(ds)
    assert "seabed" not in _by_label(fig.axes[0]) and len(_cable_lines(fig.axes[0])) == 1
    ds.attrs["depth"] = 250.0  # a result stamped with its depth (e.g. from a MoorDyn file)
    (fig,) = plot_mooring_static(ds)
    np.testing.assert_array_equal(_by_label(fig.axes[0])["seabed"].get_ydata(), -250.0)


def test_out_of_plane_line_uses_horizontal_distance(static):
    # a rotation about the vertical axis leaves the horizontal distance from the anchor unchanged:
    # the rotated line is drawn as x - x_anchor of the unrotated one (1e-9 m: round-off of 1e3 m)
    ds = static.copy()
    c, s = math.cos(1.0), math.sin(1.0)
    x, y = ds.x.values.copy(), ds.y.values.copy()
    ds["x"] = ds.x.copy(data=c * x - s * y)
    ds["y"] = ds.y.copy(data=s * x + c * y)
    (fig,) = plot_mooring_static(ds)
    ax1 = fig.axes[0]
    assert ax1.get_xlabel() == "horizontal distance from end A [m]"
    (cable,) = _cable_lines(ax1)
    np.testing.assert_allclose(cable.get_xdata(), x - x[0], atol=1e-9)


# ----------------------------------------------------------------------------- pushover

def test_pushover_force_excursion(pushover):
    figs = plot_mooring_pushover(pushover)
    assert len(figs) == 2
    ax1, ax2 = figs[0].axes
    assert ax1.get_xlabel() == "horizontal fairlead offset [m]"
    assert ax1.get_ylabel() == "fairlead tension [kN]"
    horizontal, total = ax1.get_lines()
    np.testing.assert_array_equal(horizontal.get_xdata(), pushover.offset.values)
    np.testing.assert_allclose(horizontal.get_ydata(), pushover.H_fairlead.values / 1e3, rtol=1e-15)
    np.testing.assert_allclose(total.get_ydata(), pushover.fairlead_tension.values / 1e3, rtol=1e-15)
    # the total tension is never below its horizontal part
    assert np.all(total.get_ydata() >= horizontal.get_ydata())
    (contact,) = ax2.get_lines()
    np.testing.assert_array_equal(contact.get_ydata(), pushover.seabed_contact_length.values)
    assert ax2.get_ylabel() == "length of line on the seabed [m]"


def test_pushover_shapes_at_five_offsets(pushover):
    fig = plot_mooring_pushover(pushover)[1]
    ax1, ax2 = fig.axes
    wanted = [f"offset {o:g} m" for o in (0.0, 5.0, 10.0, 15.0, 20.0)]  # 9 offsets -> every second
    assert [ln.get_label() for ln in _cable_lines(ax1)] == wanted
    assert [ln.get_label() for ln in ax2.get_lines()] == wanted
    last = _cable_lines(ax1)[-1]
    np.testing.assert_array_equal(last.get_xdata(), pushover.x.values[-1])
    assert last.get_xdata()[-1] == pytest.approx(FAIRLEAD[0] + 20.0, abs=1e-9)


# ----------------------------------------------------------------------------- dynamic

def test_dynamic_shape_snapshots(dynamic):
    fig = plot_mooring_dynamic(dynamic)[0]
    ax1, ax2 = fig.axes
    step, snaps = _snapshot_times(dynamic.time.values, 8)
    assert step == 2.0 and snaps.size == 6  # 10 s: the round step nearest 10/7 s is 2 s
    labels = [f"t = {t:g} s" for t in snaps]
    cables = _cable_lines(ax1)
    assert [ln.get_label() for ln in cables] == labels
    assert "every 2 s" in ax1.get_title()
    for ln, t in zip(cables, snaps):
        np.testing.assert_array_equal(ln.get_xdata(), dynamic.x.sel(time=t).values)
        np.testing.assert_array_equal(ln.get_ydata(), dynamic.z.sel(time=t).values)
    # coloured by time: six different colours
    assert len({tuple(ln.get_color()) for ln in cables}) == 6
    assert ax1.get_xlabel() == "x position [m]" and ax1.get_ylabel() == SHAPE_Y
    assert len(ax2.get_lines()) == 6 and ax2.get_ylabel() == "effective tension [kN]"


def test_dynamic_tension_series_and_snap_loads(dynamic):
    fig = plot_mooring_dynamic(dynamic)[1]
    ax1, ax2, ax3 = fig.axes
    assert ax1.get_ylabel() == "tension [kN]"
    lines = _by_label(ax1)
    np.testing.assert_allclose(lines["fairlead"].get_ydata(), dynamic.fairlead_tension.values / 1e3, rtol=1e-15)
    np.testing.assert_allclose(lines["anchor"].get_ydata(), dynamic.anchor_tension.values / 1e3, rtol=1e-15)
    snaps = lines[f"snap loads ({dynamic.sizes['snap']}, any element)"]
    np.testing.assert_array_equal(snaps.get_xdata(), dynamic.snap_time.values)
    np.testing.assert_allclose(snaps.get_ydata(), dynamic.snap_tension.values / 1e3, rtol=1e-15)
    np.testing.assert_array_equal(ax2.get_lines()[0].get_ydata(), dynamic.seabed_contact_length.values)
    assert ax2.get_ylabel() == "length of line on the seabed [m]"
    np.testing.assert_array_equal(ax3.get_lines()[0].get_ydata(), dynamic.slack_elements.values)
    assert ax3.get_xlabel() == "time [s]"


def test_no_snap_marker_without_snap_loads(calm):
    fig = plot_mooring_dynamic(calm)[1]
    assert not any(ln.get_label().startswith("snap") for ln in fig.axes[0].get_lines())


def test_interrupted_run_is_said_in_the_titles(calm):
    ds = calm.copy()
    ds.attrs["interrupted"] = 1
    figs = plot_mooring_dynamic(ds)
    assert "(interrupted at t = 10 s)" in figs[0].axes[0].get_title()
    assert "(interrupted at t = 10 s)" in figs[1].axes[0].get_title()


def test_small_tensions_in_newtons(calm):
    ds = calm.copy()
    for name in ("tension", "fairlead_tension", "anchor_tension"):
        ds[name] = ds[name] / 1e3  # a laboratory line: below 10 kN
    figs = plot_mooring_dynamic(ds)
    assert figs[0].axes[1].get_ylabel() == "effective tension [N]"
    assert figs[1].axes[0].get_ylabel() == "tension [N]"
    np.testing.assert_allclose(_by_label(figs[1].axes[0])["fairlead"].get_ydata(), ds.fairlead_tension.values)


# ----------------------------------------------------------------------------- several lines

def test_line_dimension_gives_one_curve_per_line(dynamic, calm, static):
    ds = _two_lines(dynamic, calm)
    assert ds.snap_time.dims == ("line", "snap")
    shape, series = plot_mooring_dynamic(ds)
    ax1 = shape.axes[0]
    # 6 snapshots x 2 lines; line 2 dashed, named in the legend
    cables = _cable_lines(ax1)
    assert len(cables) == 12
    assert [ln.get_linestyle() for ln in cables] == ["-"] * 6 + ["--"] * 6
    np.testing.assert_array_equal(cables[6].get_xdata(), calm.x.isel(time=0).values)
    legend = [t.get_text() for t in ax1.get_legend().get_texts()]
    assert "line 1" in legend and "line 2" in legend
    lines = _by_label(series.axes[0])
    for name, run in (("line 1", dynamic), ("line 2", calm)):
        np.testing.assert_allclose(lines[f"{name}: fairlead"].get_ydata(), run.fairlead_tension.values / 1e3)
        np.testing.assert_allclose(lines[f"{name}: anchor"].get_ydata(), run.anchor_tension.values / 1e3)
    # the NaN padding of line 2's (empty) snap rows is dropped: line 1's snaps only
    assert lines[f"snap loads ({dynamic.sizes['snap']}, any element)"].get_xdata().size == dynamic.sizes["snap"]
    assert len(series.axes[1].get_lines()) == 2

    (fig,) = plot_mooring_static(_two_lines(static, static.copy()))
    assert [ln.get_label() for ln in _cable_lines(fig.axes[0])] == ["line 1", "line 2"]
    assert [ln.get_label() for ln in fig.axes[1].get_lines()] == ["line 1", "line 2"]


def test_nan_padded_lines_without_s(calm):
    # the layout of a MoorDyn file with lines of different element counts: rows NaN-padded, no s
    short = _dynamic(2.0, n_elements=16)
    ds = _two_lines(calm.drop_vars("s"), short.drop_vars("s"))
    assert np.isnan(ds.x.sel(line="line 2").values[:, -1]).all()
    shape = plot_mooring_dynamic(ds)[0]
    ax1, ax2 = shape.axes
    cables = _cable_lines(ax1)
    assert [ln.get_xdata().size for ln in cables] == [21] * 6 + [17] * 6
    assert ax2.get_xlabel() == "arc length from end A, stretched [m]"
    # the stretched length of the whole line: 902.2 m plus the elastic stretch T/EA < 0.5 %
    # (T < 1.8 MN, EA = 384 MN); the chords of 45-56 m elements on the catenary lose < 0.01 %
    for ln in ax2.get_lines():
        assert LENGTH * (1 - 1e-4) < ln.get_xdata()[-1] < LENGTH * 1.005


# ----------------------------------------------------------------------------- output and errors

@pytest.mark.parametrize("fixture, names", [
    ("static", ["oc3_shape.png"]),
    ("pushover", ["oc3_pushover.png", "oc3_pushover_shapes.png"]),
    ("dynamic", ["oc3_shape.png", "oc3_tension.png"]),
])
def test_plot_result_writes_pngs(request, monkeypatch, tmp_path, fixture, names, n_colours):
    ds = request.getfixturevalue(fixture)
    for analysis, function in MOORING_FIGURES.items():  # as the lead registers them in plot.FIGURES
        monkeypatch.setitem(plot_module.FIGURES, analysis, function)
    paths = plot_result(ds, tmp_path, prefix="oc3")
    assert [p.name for p in paths] == names
    for path in paths:
        assert path.read_bytes()[:8] == PNG_SIGNATURE
        pixels = plt.imread(path)[..., :3]
        # more than a handful of colours: curves and text were drawn on the white canvas
        assert n_colours(pixels) > 10, path.name


def test_figures_of_a_line_dimension_write_to_png(dynamic, calm, tmp_path):
    for k, fig in enumerate(plot_mooring_dynamic(_two_lines(dynamic, calm))):
        path = tmp_path / f"two_{k}.png"
        fig.savefig(path, dpi=60)
        assert path.read_bytes()[:8] == PNG_SIGNATURE


@pytest.mark.parametrize("function, wrong", [(plot_mooring_static, "pushover"),
                                             (plot_mooring_pushover, "static"),
                                             (plot_mooring_dynamic, "static")])
def test_wrong_analysis_is_an_input_error(function, wrong, static, pushover):
    ds = {"static": static, "pushover": pushover}[wrong]
    with pytest.raises(InputError, match=r"needs a 'mooring_\w+' result, got analysis 'mooring_\w+'\. "
                                         r"Suggested fix"):
        function(ds)


def test_a_cable_pushover_gets_its_range_graphs(monkeypatch, tmp_path):
    """A line with curvature (the 80 m lazy wave, 2 m elements, hang-off moved 0 and 5 m) gets the range graphs
    among its figures, their curvature panel the result's largest curvature at each node; a chain's figures stay
    as they were (test_plot_result_writes_pngs)."""
    from seacable.design.cable import range_graphs

    data = yaml.safe_load((EXAMPLE.parent / "lazy_wave_80m.yaml").read_text())
    data["analysis"] = {**data["analysis"], "type": "mooring_pushover", "element_length": 2.0, "offsets": [0.0, 5.0]}
    data["line_types"]["cable"]["minimum_bend_radius"] = 3.0
    ds = sc.run(sc.Case.model_validate(data))
    for analysis, function in MOORING_FIGURES.items():
        monkeypatch.setitem(plot_module.FIGURES, analysis, function)
    paths = plot_result(ds, tmp_path, prefix="lw")
    assert [p.name for p in paths] == ["lw_pushover.png", "lw_pushover_shapes.png", "lw_range_graphs.png"]
    fig = plot_mooring_pushover(ds)[-1]
    rg = range_graphs(ds)
    panel = next(ax for ax in fig.axes if "curvature" in ax.get_ylabel())
    tops = [ln.get_ydata() for ln in panel.get_lines() if len(ln.get_ydata()) == rg.sizes["node"]]
    assert any(np.allclose(y, rg.curvature_max.values) for y in tops)
    # the static MBR's limit drawn at 1 / 3 m
    assert any(np.allclose(ln.get_ydata(), 1 / 3.0) for ln in panel.get_lines())
    static = ds.isel(offset=0).drop_vars("offset")
    static.attrs["analysis"] = "mooring_static"
    assert [p.name for p in plot_result(static, tmp_path, prefix="st")] == ["st_shape.png", "st_range_graphs.png"]

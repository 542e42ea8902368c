"""Standard figures of the towed-cable dynamics result (paper 000, Table 3 and Figs. 4-6).

The figures are drawn from a real run of ``examples/paper000_turn.yaml`` (about 1 s). Each test
checks something that can fail: the file is a PNG of the documented size with more than one
colour in it, the plan-view snapshot times follow the documented rule, the titles say when the
run was interrupted, and a one-step result still plots.
"""

import struct
from pathlib import Path

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from seacable.errors import InputError  # noqa: E402
from seacable.io import load_case  # noqa: E402
from seacable.plot import FIGURES, plot_result
from seacable.plot._core import _nice_step, _snapshot_times  # noqa: E402
from seacable.simulate import run  # noqa: E402

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
NAMES = ["top_tension", "plan_view", "end_trajectories", "lower_end_depth", "tension_profile"]
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def turn():
    return run(load_case(EXAMPLES / "paper000_turn.yaml"))


def _png_size(path: Path) -> tuple[int, int]:
    """Width and height from the IHDR chunk, which the PNG standard puts first."""
    head = path.read_bytes()[:24]
    assert head[:8] == PNG_SIGNATURE, f"{path.name} is not a PNG"
    assert head[12:16] == b"IHDR"
    return struct.unpack(">II", head[16:24])


def _check_pngs(paths, prefix, n_colours):
    assert [p.name for p in paths] == [f"{prefix}_{n}.png" for n in NAMES]
    for path in paths:
        width, height = _png_size(path)
        # every figure is at least 6 x 4.2 in at 110 dpi; tight_layout does not crop the canvas
        assert width >= 600 and height >= 450, (path.name, width, height)
        # measured: a blank canvas is 2.5 kB, empty axes with ticks 10 kB; with labels, title and
        # curves even the one-step figures are 22-36 kB and the 101-step ones 28-47 kB
        assert path.stat().st_size > 15_000, (path.name, path.stat().st_size)
        pixels = plt.imread(path)[..., :3]
        # more than one colour: something was drawn (a blank canvas is all white)
        assert n_colours(pixels) > 10, path.name


def test_towed_dynamic_is_registered():
    assert "towed_dynamic" in FIGURES


def test_every_figure_is_a_valid_png(turn, tmp_path, n_colours):
    paths = plot_result(turn, tmp_path / "figs")
    _check_pngs(paths, "paper000_turn", n_colours)


@pytest.mark.parametrize("time, step, expected", [
    # paper 000 Fig. 6: 100 s, output every 1 s -> every 20 s, 6 snapshots
    (np.arange(0.0, 100.5, 1.0), 20.0, np.arange(0.0, 101.0, 20.0)),
    # the same with output every 0.5 s and a start time that is not zero
    (np.arange(10.0, 110.25, 0.5), 20.0, np.arange(10.0, 111.0, 20.0)),
    # 600 s -> 600 / 5 = 120 s, nearest round step 100 s -> 7 snapshots
    (np.arange(0.0, 600.5, 1.0), 100.0, np.arange(0.0, 601.0, 100.0)),
    # an interrupted run, 37.5 s: 7.5 s is nearer (in ratio) to 10 s than to 5 s -> 4 snapshots
    (np.arange(0.0, 37.75, 0.5), 10.0, np.array([0.0, 10.0, 20.0, 30.0])),
    # output every 30 s is too coarse for a 20 s step: the nearest outputs, step reported as 0
    (np.arange(0.0, 90.5, 30.0), 0.0, np.array([0.0, 30.0, 60.0, 90.0])),
    # a single output time
    (np.array([5.0]), 0.0, np.array([5.0])),
])
def test_snapshot_times(time, step, expected):
    got_step, got = _snapshot_times(time)
    assert got_step == step
    np.testing.assert_array_equal(got, expected)  # the times are taken from `time`: exact


@pytest.mark.parametrize("target, nice", [(20.0, 20.0), (12.0, 10.0), (17.0, 20.0), (0.34, 0.25),
                                          (3.7, 5.0), (140.0, 100.0), (160.0, 200.0)])
def test_nice_step_is_the_nearest_round_number_in_ratio(target, nice):
    assert _nice_step(target) == pytest.approx(nice, rel=1e-12)  # powers of ten in floating point


def test_plan_view_shows_the_documented_snapshots(turn):
    figs = FIGURES["towed_dynamic"](turn, plt)
    try:
        ax = figs["plan_view"].axes[0]
        labels = [line.get_label() for line in ax.get_lines() if line.get_label().startswith("t = ")]
        assert labels == [f"t = {t:g} s" for t in range(0, 101, 20)]
        assert "every 20 s" in ax.get_title()
        assert ax.get_aspect() == 1.0  # equal aspect
        assert any(line.get_label() == "vessel track" for line in ax.get_lines())
        # the vessel track is the tow point's path
        track = next(line for line in ax.get_lines() if line.get_label() == "vessel track")
        np.testing.assert_array_equal(track.get_xdata(), turn.vessel_x.values)
        # depth is plotted positive down
        depth_ax = figs["lower_end_depth"].axes[0]
        assert depth_ax.yaxis_inverted()
        assert float(np.min(depth_ax.get_lines()[0].get_ydata())) > 0.0
        for fig in figs.values():
            assert "interrupted" not in fig.axes[0].get_title()
    finally:
        for fig in figs.values():
            plt.close(fig)


def test_interrupted_result_says_so_in_every_title(turn):
    cut = turn.isel(time=slice(0, 38))  # as if stopped at t = 37 s
    cut.attrs["interrupted"] = 1
    figs = FIGURES["towed_dynamic"](cut, plt)
    try:
        assert set(figs) == set(NAMES)
        for name, fig in figs.items():
            assert "(interrupted at t = 37 s)" in fig.axes[0].get_title(), name
    finally:
        for fig in figs.values():
            plt.close(fig)


def test_single_time_step_still_plots(turn, tmp_path, n_colours):
    one = turn.isel(time=[0])
    paths = plot_result(one, tmp_path, prefix="one")
    _check_pngs(paths, "one", n_colours)


def test_unknown_analysis_is_refused(turn, tmp_path):
    bad = turn.copy()
    bad.attrs["analysis"] = "no_such_analysis"
    with pytest.raises(InputError, match="no standard figures for analysis 'no_such_analysis'"):
        plot_result(bad, tmp_path)

"""Figures of the mooring-system analyses (seacable.plot.system)."""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

import seacable as sc
from seacable.plot import FIGURES, plot_result, plot_system_offsets, plot_system_static
from seacable.results import ANALYSIS_VARIABLES
from seacable.system import SystemOffsetsAnalysis

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def static():
    return sc.run(sc.load_case(EXAMPLES / "spread_mooring.yaml"))


@pytest.fixture(scope="module")
def offsets():
    case = sc.load_case(EXAMPLES / "spread_mooring_watch_circle.yaml")
    small = case.replace(analysis=SystemOffsetsAnalysis(body="buoy", loads=(0.0, 2.5e5, 5.0e5), n_headings=6,
                                                        damaged_lines=("line1",)))
    return sc.run(small)


def test_both_analyses_are_registered():
    assert {"system_static", "system_offsets"} <= set(FIGURES)


def test_plan_view_draws_the_profiles_and_the_damaged_condition_dashed(static):
    import matplotlib.pyplot as plt

    figs = plot_system_static(static)
    try:
        plan = figs[0].axes[0]
        drawn = {ln.get_label(): ln for ln in plan.get_lines()}
        # the intact line1 is drawn from its stored profile (x, y), anchor to fairlead
        line1 = drawn["line1"]
        np.testing.assert_array_equal(line1.get_xdata(), static.x.sel(condition="intact", line="line1").values)
        np.testing.assert_array_equal(line1.get_ydata(), static.y.sel(condition="intact", line="line1").values)
        assert line1.get_linestyle() == "-"
        # the damaged condition: lines 2 and 3 dashed, line1 (removed, NaN) not drawn
        dashed = [ln for ln in plan.get_lines() if ln.get_linestyle() == "--"]
        assert len(dashed) == 2
        xs = [ln.get_xdata() for ln in dashed]
        for k, name in enumerate(("line2", "line3")):
            np.testing.assert_array_equal(xs[k], static.x.sel(condition="damaged", line=name).values)
        # anchors where the fixed points are
        anchors = drawn["anchors"]
        np.testing.assert_allclose(sorted(anchors.get_xdata()), [-606.0, 303.0, 303.0])
    finally:
        for f in figs:
            plt.close(f)


def test_watch_circle_closes_each_loads_curve_over_the_headings(offsets):
    import matplotlib.pyplot as plt

    figs = plot_system_offsets(offsets)
    try:
        ax = figs[0].axes[0]
        curves = [ln for ln in ax.get_lines() if len(ln.get_xdata()) == offsets.heading.size + 1]
        # a curve per load and condition, each closed (first point repeated)
        assert len(curves) == offsets.applied_load.size * offsets.condition.size
        for ln in curves:
            assert ln.get_xdata()[0] == ln.get_xdata()[-1] and ln.get_ydata()[0] == ln.get_ydata()[-1]
        # the largest intact circle is the intact offsets at the largest load
        big = curves[offsets.applied_load.size - 1]
        radius = np.hypot(big.get_xdata()[:-1], big.get_ydata()[:-1])
        expected = offsets.body_offset.sel(condition="intact", body="buoy").isel(applied_load=-1).values
        np.testing.assert_allclose(np.sort(radius), np.sort(expected), rtol=1e-12)
    finally:
        for f in figs:
            plt.close(f)


@pytest.mark.parametrize("which", ["static", "offsets"])
def test_schema_is_what_the_figures_need(which, static, offsets, tmp_path):
    """A real result holds every variable of its schema, and its figures draw from those alone."""
    ds = {"static": static, "offsets": offsets}[which]
    names = ANALYSIS_VARIABLES[ds.attrs["analysis"]]
    assert [n for n in names if n not in ds.variables] == []
    only = ds[[n for n in names if n in ds.data_vars]]
    only = only.drop_vars([c for c in only.coords if c not in names])
    written = plot_result(only, tmp_path, prefix="p")
    assert len(written) == {"static": 2, "offsets": 3}[which]


def test_figures_from_the_netcdf(static, offsets, tmp_path):
    for ds, n in ((static, 2), (offsets, 3)):
        path = sc.write_netcdf(ds, tmp_path / f"{ds.attrs['analysis']}.nc")
        written = plot_result(sc.read_netcdf(path), tmp_path / "figs")
        assert len(written) == n and all(p.stat().st_size > 1000 for p in written)


def test_wrong_result_is_refused(static):
    with pytest.raises(sc.InputError, match="plot_system_offsets needs a 'system_offsets' result"):
        plot_system_offsets(static)


def test_an_intact_only_result_plots(tmp_path):
    case = sc.load_case(EXAMPLES / "spread_mooring_watch_circle.yaml")
    one = case.replace(analysis=SystemOffsetsAnalysis(body="buoy", loads=(1.0e5,), headings=(0.0, math.pi / 2)))
    ds = sc.run(one)
    assert list(ds.condition.values) == ["intact"]
    assert len(plot_result(ds, tmp_path)) == 3


def test_an_intact_only_static_result_plots(tmp_path):
    case = sc.load_case(EXAMPLES / "spread_mooring.yaml")
    ds = sc.run(case.replace(analysis=case.analysis.replace(damaged_lines=())))
    assert list(ds.condition.values) == ["intact"]
    assert [p.name for p in plot_result(ds, tmp_path)] == ["spread_mooring_system.png", "spread_mooring_tensions.png"]

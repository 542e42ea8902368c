"""Per-case design figures: snap loads, tension extremes, end-of-run values, each analysis's own."""

from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import seacable as sc
from seacable.extremes import case_extremes, snap_loads

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_snap_loads_peak_after_slack_within_the_window():
    t = np.arange(0.0, 10.0, 0.5)
    T = np.full((t.size, 3), 100.0)
    T[4:6, 1] = 0.0                   # element 1 slack at 2.0-2.5 s, taut again at 3.0 s
    T[6:9, 1] = [300.0, 900.0, 400.0]  # peak 900 N at 3.5 s
    T[12, 1] = 5000.0                  # 6 s: outside the 2 s window after 3.0 s
    T[:, 2] = np.nan                   # an element that does not exist (NaN) is never a snap
    times, elements, peaks = snap_loads(t, T, window=2.0)
    np.testing.assert_array_equal(times, [3.5])
    np.testing.assert_array_equal(elements, [1])
    np.testing.assert_array_equal(peaks, [900.0])
    assert snap_loads(t, np.full((t.size, 2), 50.0))[2].size == 0


def _towline_like():
    t = np.arange(0.0, 100.0, 1.0)
    tension = np.tile(np.linspace(2e4, 1e4, 5), (t.size, 1))
    tension[10, 2] = 0.0
    tension[11, 2] = 3e4
    ds = xr.Dataset(
        {"tension": (("time", "node"), tension, {"units": "N", "long_name": "joint tension"}),
         "top_tension": ("time", tension[:, 0], {"units": "N", "long_name": "towline tension at the tug"}),
         "barge_tension": ("time", np.r_[np.full(90, 1e4), np.full(10, 2e4)],
                           {"units": "N", "long_name": "towline tension at the barge"}),
         "barge_speed": ("time", np.full(t.size, 1.0), {"units": "m s-1", "long_name": "barge speed"})},
        coords={"time": ("time", t, {"units": "s", "long_name": "time"})},
        attrs={"analysis": "towline_dynamic"})
    return ds


def test_tension_extremes_snaps_and_end_values():
    out = case_extremes(_towline_like())
    value = {k: float(v.values) for k, v in out.items()}
    assert value["top_tension_max"] == value["top_tension_min"] == 2e4
    assert value["tension_max"] == 3e4 and value["tension_min"] == 0.0
    assert value["snap_count"] == 1 and value["snap_load_max"] == 3e4
    assert value["barge_tension_max"] == 2e4 and value["barge_tension_min"] == 1e4
    # the end value is the mean over the last tenth of the run: the last 10 of 100 samples
    assert value["barge_tension_end"] == 2e4
    assert out["barge_tension_end"].attrs["units"] == "N"
    assert out["snap_load_max"].attrs["long_name"] == "largest snap load (0: no snap event)"


def test_static_catenary_max_tension_is_at_the_fairlead():
    ds = sc.run(sc.load_case(EXAMPLES / "oc3_hywind_static.yaml"))
    out = {k: float(v.values) for k, v in case_extremes(ds).items()}
    # a catenary's tension grows with height (dT/dz = w): the largest is the fairlead's
    assert out["top_tension_max"] == out["top_tension_min"] == float(ds.fairlead_tension)
    assert out["tension_max"] == pytest.approx(float(ds.fairlead_tension), rel=1e-9)
    # every scalar of the result comes along
    assert out["grounded_length"] == float(ds.grounded_length)
    assert "snap_count" not in out       # no time axis

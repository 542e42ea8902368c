"""A run's results do not depend on how its time loop is cut into chunks: the loop sizes its chunks of outputs
from the wall clock, so a result that depended on them would depend on the speed of the machine. The same
case under two forced chunkings (one output a chunk, and chunks growing as fast as the loop allows) gives the
same floats, to the last bit, for every result variable."""

from __future__ import annotations

import itertools
import math
import types

import numpy as np

import seacable as sc
from seacable.mooring import solver as S
from seacable.mooring.solver import StepSamples

DEPTH = 320.0
AMPLITUDE = (0.8, 0.3, 0.6, 0.010, 0.020, 0.005)  # a made-up RAO table, flat in frequency and heading [m/m, rad/m]
PHASE = (0.4, -1.1, 0.2, 1.3, -0.6, 2.0)  # [rad]


def _case(tmp_path):
    """A line whose fairlead moves by a platform's RAOs in an irregular sea, 10 s."""
    rows = ["frequency,heading,dof,amplitude,phase"]
    rows += [f"{w},{b},{j + 1},{AMPLITUDE[j]},{PHASE[j]}" for w in (0.1, 0.5, 1.0, 2.0, 3.0)
             for b in (0.0, math.pi / 2, math.pi, 1.5 * math.pi) for j in range(6)]
    path = tmp_path / "raos.csv"
    path.write_text("\n".join(rows) + "\n")
    motion = {"type": "rao", "file": str(path), "reference": [853.87, 0.0, 0.0],
              "mean_offset": [-12.0, 0.0, 0.0, 0.0, 0.0, 0.0], "ramp": 3.0}
    sea = {"spectrum": "jonswap", "hs": 6.0, "tp": 11.0, "seed": 3, "n_components": 80}
    return sc.parse_case({"line_types": {"c": {"diameter": 0.09, "mass_per_length": 77.7066,
                                               "weight_in_water": 698.094, "axial_stiffness": 384.243e6}},
                          "line": {"line_type": "c", "length": 902.2},
                          "environment": {"depth": DEPTH, "waves": sea},
                          "analysis": {"type": "mooring_dynamic", "fairlead": [848.67, -70.0], "n_elements": 10,
                                       "duration": 10.0, "time_step": 0.1, "output_interval": 0.5,
                                       "motion": motion}})


def _run_chunked(case, monkeypatch, took):
    """The case with every chunk of the time loop taking ``took`` seconds by the loop's clock: 10 s (against
    its 0.25 s a chunk) keeps one output a chunk; 1e-9 s lets each chunk grow to 2 n + 8 outputs."""
    clock = [0.0]

    def perf_counter():
        clock[0] += took
        return clock[0]

    with monkeypatch.context() as m:
        m.setattr(S, "_time", types.SimpleNamespace(perf_counter=perf_counter))
        return sc.run(case)


def test_a_run_is_the_same_to_the_last_bit_however_its_time_loop_is_chunked(tmp_path, monkeypatch):
    """Two chunkings, the sea's kinematics in windows of a few seconds (the windows move on inside the run):
    every result variable bit for bit the same."""
    monkeypatch.setattr(S, "SEA_WINDOW_VALUES", 1e5)
    case = _case(tmp_path)
    one, grown = (_run_chunked(case, monkeypatch, took) for took in (10.0, 1e-9))
    assert np.ptp(one.x.values[:, -1]) > 0.1  # the fairlead moves: the motion is sampled
    assert set(one.data_vars) == set(grown.data_vars)
    for name in one.data_vars:
        a, b = one[name].values, grown[name].values
        if a.dtype.kind in "fc":
            assert np.array_equal(a, b, equal_nan=True), name
        else:
            assert np.array_equal(a, b), name


def test_step_samples_are_those_of_fixed_blocks_whatever_range_is_asked_for():
    """StepSamples gives each step's value from the block it belongs to, at the time interval k + h (s + 1) of
    step k sub + s, and the same floats for any range asked for."""
    interval, sub, n_out = 0.5, 5, 300
    h = interval / sub
    w = np.linspace(0.3, 2.0, 7)

    def fn(t):  # a product whose rounding may change with the number of rows
        return (np.cos(np.multiply.outer(t, w)) @ np.arange(1.0, 8.0), t.copy())

    whole = StepSamples(fn, interval, h, sub, n_out * sub, block=64)(0, n_out * sub)
    times = ((interval * np.arange(n_out))[:, None] + h * np.arange(1, sub + 1)[None, :]).ravel()
    assert np.array_equal(whole[1], times)
    rng = np.random.default_rng(1)
    for _ in range(5):
        samples = StepSamples(fn, interval, h, sub, n_out * sub, block=64)
        cuts = np.unique(np.concatenate(([0, n_out * sub], sub * rng.integers(1, n_out, 12))))
        for i0, i1 in itertools.pairwise(cuts):
            got = samples(int(i0), int(i1))
            assert all(g.flags.c_contiguous for g in got)
            assert np.array_equal(got[0], whole[0][i0:i1]) and np.array_equal(got[1], whole[1][i0:i1])

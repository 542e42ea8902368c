"""Issue 37: no time-domain result holds a non-finite number silently (:class:`seacable.results.FiniteGuard`,
in :func:`~seacable.results.make_dataset` and in each block a streamed run writes, :mod:`seacable.sink`)."""

from __future__ import annotations

import numpy as np
import pytest

from seacable.errors import ConvergenceError
from seacable.results import make_dataset, var
from seacable.sink import open_sink


def _result(x, tension):
    t = np.arange(len(x)) * 0.5
    return ({"x": var(("time", "node"), x, "m", "x"), "tension": var(("time", "node"), tension, "N", "tension")},
            {"time": var("time", t, "s", "time")})


def test_padding_passes_and_a_diverged_or_infinite_value_is_refused_with_its_time(tmp_path):
    x = np.array([[0.0, 1.0, np.nan], [0.0, 1.1, 2.0], [0.0, 1.2, 2.1]])  # a node paid out at t = 0.5 s
    ten = np.array([[np.nan, np.nan, np.nan], [1.0, 2.0, 3.0], [1.0, 2.0, 3.0]])  # not measured at t = 0
    make_dataset(*_result(x, ten), analysis="towed_dynamic")
    gone = ten.copy()
    gone[2] = np.nan  # the tension NaN at every node at t = 1 s after finite values: diverged
    with pytest.raises(ConvergenceError, match=r"'tension' is NaN throughout, after finite values before at t = 1 s"):
        make_dataset(*_result(x, gone), analysis="towed_dynamic")
    lost = x.copy()
    lost[0] = np.nan  # the state NaN at every node at the first output
    with pytest.raises(ConvergenceError, match=r"'x' is NaN at every node at t = 0 s") as err:
        make_dataset(*_result(lost, ten), analysis="towed_dynamic")
    assert err.value.time == 0.0
    inf = ten.copy()
    inf[1, 2] = np.inf
    with pytest.raises(ConvergenceError, match=r"'tension' is inf N at entry 2 at t = 0.5 s"):
        make_dataset(*_result(x, inf), analysis="towed_dynamic")
    # a streamed run: the block with the NaN is refused before it is written, and no file is left
    out = tmp_path / "r.nc"
    with pytest.raises(ConvergenceError, match="NaN throughout"), open_sink(3, out) as sink:
        data, coords = _result(x, gone)
        sink.append({k: v[:2] for k, v in data.items()}, {"time": coords["time"][:2]})
        sink.append({k: v[2:] for k, v in data.items()}, {"time": coords["time"][2:]})
    assert not out.exists()

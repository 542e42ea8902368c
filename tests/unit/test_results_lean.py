"""Issue 38: what a result costs around its solver is cut without changing a bit of it (:mod:`seacable.results`):
the case's YAML, the names' variables, the non-finite check of a streamed run."""

from __future__ import annotations

import gc
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import yaml

import seacable as sc
from seacable import results
from seacable.errors import ConvergenceError
from seacable.results import FiniteGuard, case_yaml, make_dataset, var

EXAMPLES = Path(__file__).parents[2] / "examples"


@pytest.mark.parametrize("name", ["spread_mooring.yaml", "oc3_hywind_line.yaml", "paper003_zigzag.yaml"])
def test_the_case_yaml_is_pyyamls_safe_dump_dumped_once_per_case(name):
    case = sc.load_case(EXAMPLES / name)
    text = case_yaml(case)
    assert text == yaml.safe_dump(case.model_dump(mode="json"), sort_keys=False)  # the text the pure emitter gives
    assert case_yaml(case) is text  # the same case: not dumped again
    key = id(case)
    del case
    gc.collect()
    assert key not in results._CASE_YAML  # forgotten with its case


def test_names_are_the_variable_xarray_would_make():
    names = np.array(["line1", "line2", "line 3"], dtype=object)
    fast = var("line", names, "1", "line name")
    slow = xr.Variable(("line",), names, attrs={"units": "1", "long_name": "line name"})
    assert fast.identical(slow) and fast.dtype == slow.dtype == object
    mixed = var("x", np.array(["a", None], dtype=object), "1", "a name or none")  # not all text: xarray's own path
    assert mixed.identical(xr.Variable(("x",), np.array(["a", None], dtype=object), attrs=mixed.attrs))


def test_a_variable_the_blocks_did_not_hold_is_still_checked_at_the_end():
    t = var("time", [0.0, 0.5], "s", "time")
    block = {"x": var(("time", "node"), np.ones((2, 3)), "m", "x")}
    guard = FiniteGuard()
    guard.check(block, {"time": t})  # a streamed run's block
    late = {**block, "slack": var("time", [1.0, np.inf], "m", "slack")}
    with pytest.raises(ConvergenceError, match="'slack' is inf"):
        make_dataset(late, {"time": t}, analysis="towed_dynamic", guard=guard)
    ds = make_dataset(block, {"time": t}, analysis="towed_dynamic", guard=guard)
    assert ds.x.shape == (2, 3)

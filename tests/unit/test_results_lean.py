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


@pytest.mark.parametrize("values", [np.arange(6.0).reshape(2, 3), np.arange(6).reshape(2, 3), np.ones((2, 3), bool),
                                    np.full((2, 3), 1 + 2j), np.array([["a", "bc", "d"], ["e", "f", "g"]]),
                                    [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]])
def test_numbers_and_text_are_the_variable_xarray_would_make(values):
    """var takes plain numbers, booleans and strings as they are (xarray's fast path): the same Variable, its
    data the array given, not a copy."""
    fast = var(("a", "b"), values, "m", "x")
    slow = xr.Variable(("a", "b"), values, attrs={"units": "m", "long_name": "x"})
    assert fast.identical(slow) and fast.dtype == slow.dtype and type(fast.data) is np.ndarray
    if isinstance(values, np.ndarray):
        assert fast.data is values


def test_dates_still_take_xarrays_own_path():
    t = np.array(["2026-11-29T00:00", "2026-11-29T00:10"], dtype="datetime64[s]")
    for values in (t, t - t[0], t.astype(object)):  # dates, durations, dates as objects: xarray converts them
        made = var("time", values, "1", "date")
        assert made.identical(xr.Variable(("time",), values, attrs={"units": "1", "long_name": "date"}))


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


def _same_dataset(fast: xr.Dataset, slow: xr.Dataset) -> None:
    """The Dataset :func:`results.dataset` built is the one ``xarray.Dataset`` builds: values, attributes, the
    order of the variables and dimensions, which are coordinates, the variables' types and the indexes."""
    assert fast.identical(slow)
    assert list(fast.variables) == list(slow.variables)
    assert list(fast.sizes.items()) == list(slow.sizes.items())
    assert set(fast.coords) == set(slow.coords)
    for name, v in slow.variables.items():
        w = fast.variables[name]
        assert type(w) is type(v) and w.dtype == v.dtype and w.encoding == v.encoding, name
    assert list(fast.xindexes) == list(slow.xindexes)
    for name, index in slow.xindexes.items():
        other = fast.xindexes[name]
        assert type(other) is type(index) and other.equals(index), name
        assert other.coord_dtype == index.coord_dtype and type(other.index) is type(index.index), name
        assert other.index.dtype == index.index.dtype and other.index.name == index.index.name, name


@pytest.mark.parametrize("name", ["spread_mooring.yaml", "spread_mooring_watch_circle.yaml", "oc3_hywind_static.yaml",
                                  "oc3_hywind_modes.yaml", "paper004_lena_pushover.yaml"])
def test_a_result_is_the_dataset_xarray_would_make(name, monkeypatch):
    seen = []
    build = results.dataset

    def spy(data_vars, coords, owned=False):
        seen.append((data_vars, coords, owned))
        return build(data_vars, coords)  # not owned: the variables are built into a Dataset again below

    monkeypatch.setattr(results, "dataset", spy)
    sc.run(sc.load_case(EXAMPLES / name))
    assert seen
    for data_vars, coords, owned in seen:
        _same_dataset(build(data_vars, coords), xr.Dataset(data_vars=data_vars, coords=coords))


def test_the_direct_dataset_in_every_case_it_takes_and_the_constructor_for_the_rest():
    names = np.array(["a", "b"], dtype=object)
    cases = [
        ({"x": var(("line", "node"), np.ones((2, 3)), "m", "x"), "n": var((), 3, "1", "a scalar")},
         {"line": var("line", names, "1", "line"), "node": var("node", np.arange(3), "1", "node"),
          "s": var(("line", "node"), np.zeros((2, 3)), "m", "s")}),
        ({"x": var(("line", "node"), np.ones((0, 3)), "m", "x")},  # no lines
         {"line": var("line", np.array([], dtype=object), "1", "line"), "node": var("node", [0.5, 1.0, 2.0], "m", "n")}),
        ({"x": var("t", [1.0, 2.0], "m", "x")}, {"t": var("t", np.array([0.0, 1.0], np.float32), "s", "t")}),
        ({"x": var("k", [1.0, 2.0], "m", "x")}, {"k": var("k", np.array(["a", None], dtype=object), "1", "k")}),
        ({"x": var("k", [1.0, 2.0], "m", "x")}, {}),  # a dimension without a coordinate
        ({"x": var("t", [1.0, 2.0], "m", "x")},
         {"t": var("t", np.array(["2000-01-01", "2000-01-02"], dtype="datetime64[ns]"), "1", "t")}),  # constructor
        ({"x": xr.DataArray([1.0, 2.0], dims="k")}, {"k": var("k", [0, 1], "1", "k")}),                 # constructor
        ({"k": var("k", [1.0, 2.0], "m", "a variable named after its dimension")}, {}),                  # constructor
    ]
    for data_vars, coords in cases:
        _same_dataset(results.dataset(data_vars, coords), xr.Dataset(data_vars=data_vars, coords=coords))
        _same_dataset(results.dataset(data_vars, coords), xr.Dataset(data_vars=data_vars, coords=coords))  # kept
        _same_dataset(results.dataset(data_vars, coords, owned=True), xr.Dataset(data_vars=data_vars, coords=coords))
    with pytest.raises(ValueError, match="conflicting sizes"):
        results.dataset({"x": var("line", [1.0], "m", "x")}, {"line": var("line", names, "1", "line")})


def test_a_changed_private_constructor_falls_back_to_the_public_one(monkeypatch):
    """results.dataset uses xarray's private Dataset._construct_direct: if a later xarray changes its signature,
    the result is still the constructor's Dataset, not an error."""
    import sys

    original = xr.Dataset.__dict__["_construct_direct"].__func__

    def changed(cls, *args, **kwargs):  # refuses seacable's call only (xarray's own calls go through)
        if sys._getframe(1).f_globals.get("__name__") == "seacable.results":
            raise TypeError("_construct_direct() got an unexpected keyword argument 'indexes'")
        return original(cls, *args, **kwargs)

    data_vars = {"x": var(("line",), [1.0, 2.0], "m", "x")}
    coords = {"line": var("line", np.array(["a", "b"], dtype=object), "1", "line")}
    monkeypatch.setattr(xr.Dataset, "_construct_direct", classmethod(changed))
    _same_dataset(results.dataset(data_vars, coords), xr.Dataset(data_vars=data_vars, coords=coords))


def test_the_index_of_the_same_names_is_made_once_and_the_datasets_stay_apart():
    def build():
        return results.dataset({"x": var("line", [1.0, 2.0], "m", "x")},
                               {"line": var("line", np.array(["l1", "l2"], dtype=object), "1", "line name")})

    first, second = build(), build()
    assert first.xindexes["line"] is second.xindexes["line"]  # kept: xarray shares indexes itself
    assert first["line"].variable is not second["line"].variable
    first["line"].attrs["long_name"] = "changed"
    first["x"].attrs["units"] = "km"
    assert second["line"].attrs["long_name"] == "line name" and second["x"].attrs["units"] == "m"
    assert build()["line"].attrs["long_name"] == "line name"

"""Issue 38: a system run builds its systems and its start once (:mod:`seacable.system.run`,
:func:`seacable.system.statics.check_statics`), and solves the same equilibrium to the bit."""

from __future__ import annotations

import gc
from pathlib import Path

import numpy as np

import seacable as sc
from seacable.system import run as system_run
from seacable.system.statics import check_statics, solve_equilibrium
from seacable.system.statics import examples as ex

EXAMPLES = Path(__file__).parents[2] / "examples"


def _same(a, b):
    for name in ("body_position", "point_position", "end_a_force", "end_b_force", "stiffness", "hydrostatic"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name
    assert a.iterations == b.iterations and a.residual == b.residual


def test_a_solve_from_the_checked_start_is_the_solve_from_nothing():
    system, env = ex.oc3_hywind()
    start = check_statics(system, env)
    from_start = solve_equilibrium(system, env, start=start)
    assert start.take(system, env, None, 1.0) is None  # used once
    _same(from_start, solve_equilibrium(system, env))
    other = check_statics(system, env)  # the start of a solve without a load: not of one with a load
    load = {next(iter(system.bodies)): (1e5, 0.0, 0.0, 0.0, 0.0, 0.0)}
    _same(solve_equilibrium(system, env, external=load, start=other), solve_equilibrium(system, env, external=load))
    assert other.prob is not None  # left unused


def test_a_solve_from_the_checked_start_checks_its_stability_again_only_at_a_tighter_tolerance(monkeypatch):
    """check_statics checked the start's stability at its tolerance (1e-8): a solve from that start at the same or
    a looser one does not check it again (every bound grows with the tolerance); at a tighter one it does."""
    from seacable.system.statics import solve as solve_module

    calls = []
    real = solve_module._check_stability
    monkeypatch.setattr(solve_module, "_check_stability", lambda *a: calls.append(a[0].tol) or real(*a))
    system, env = ex.oc3_hywind()
    for tol, checks in ((1e-8, []), (1e-6, []), (1e-10, [1e-10])):
        start = check_statics(system, env)
        calls.clear()
        from_start = solve_equilibrium(system, env, tol=tol, start=start)
        assert calls == checks, (tol, calls)
        _same(from_start, solve_equilibrium(system, env, tol=tol))
        assert calls == checks + [tol]  # from nothing: checked


def test_a_case_solves_one_system_per_condition_and_forgets_it_with_the_case():
    case = sc.load_case(EXAMPLES / "spread_mooring.yaml")  # damaged_lines: most_loaded
    setup = system_run.prepare_system_static(case)
    line = next(iter(case.lines))
    assert system_run._condition_system(case) is setup.systems[0] is system_run._condition_system(case)
    assert system_run._condition_system(case, (line,)) is system_run._condition_system(case, (line,))
    assert set(setup.starts) == {None} | {(name,) for name in case.lines}
    first = sc.run(case)
    assert sc.run(case).identical(first)
    assert sc.run(case.model_copy(deep=True)).identical(first)  # a fresh case: its own systems, the same result
    key = id(case)
    del case, setup
    gc.collect()
    assert key not in system_run._SYSTEMS


def test_a_case_makes_its_coordinates_once_and_each_result_has_its_own():
    """The coordinates (names, lengths, kinds, arc lengths, degrees of freedom) are the case's: made on its first
    run, copied into each result, so that a result changed in place changes no other; forgotten with the case."""
    case = sc.load_case(EXAMPLES / "spread_mooring.yaml")
    first = sc.run(case)
    kept = system_run._COORDS[id(case)][case.analysis.profile_points]
    second = sc.run(case)
    assert system_run._COORDS[id(case)][case.analysis.profile_points] is kept  # not made again
    assert second.identical(first)
    for name in ("s", "line_length", "end_a", "point_kind"):  # (an index of names is shared: results._default_index)
        assert not np.shares_memory(first[name].values, second[name].values), name
        assert not np.shares_memory(first[name].values, kept[name][1]), name
    first["s"].values[...] = -1.0
    first["line_length"].values[...] = -1.0
    third = sc.run(case)
    assert third.identical(second) and not third.identical(first)
    key = id(case)
    del case
    gc.collect()
    assert key not in system_run._COORDS

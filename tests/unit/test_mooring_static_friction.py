"""The statics' seabed friction (:mod:`seacable.mooring._friction`, :mod:`seacable.mooring.friction`): its tangent,
the targets, the case key and what stays as it was.

The closed forms and the peer (MoorPy) are in ``tests/validation/test_static_friction_closed_forms.py`` and
``tests/validation/test_moorpy_friction.py``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import seacable as sc
from seacable.errors import InputError
from seacable.mooring import kernel as K
from seacable.mooring.friction import SLIDE_FACTOR, friction_targets, slide_targets
from seacable.mooring.network import network_from_line
from seacable.mooring.solver import MooringModel, Water, static_equilibrium

CHAIN = sc.LineType(diameter=0.09, mass_per_length=77.7, weight_in_water=698.0, axial_stiffness=3.84e8,
                    drag_normal=1.6, drag_tangential=0.1)


def _grounded(water):
    """A chain from an anchor on the seabed with 10-15 nodes lying on it, at its frictionless equilibrium."""
    net = network_from_line(sc.Line.single(CHAIN, 400.0), (0, 0, -120.0), (330.0, 0, -20.0), water_density=1025.0,
                            gravity=9.80665, n_elements=20)
    model = MooringModel(net, water)
    return model, static_equilibrium(model).position.copy()


def _friction(model, X, targets, dfric, band=None):
    F = np.zeros_like(X)
    mat = np.zeros((0, 2 * model.bw + 1)) if band is None else band
    K.friction_loads(X, targets, model.bedc, model.env, model.fidx, F, mat, model.bw, dfric)
    return F


@pytest.mark.parametrize("seabed", ["flat", "slope", "profile"])
def test_the_friction_tangent_is_the_derivative_of_its_force(seabed):
    """``K = -dF/dx`` of :func:`friction_loads` against central differences (step 1e-7 m; their round-off about
    1e-16 mu N / 1e-7, under 1e-2 N/m here), at grounded nodes moved 0.1-10 d_f from their targets in every direction
    (the elastic and the sliding range), some pressed in beyond the contact's rounding band and some within it (its
    quadratic part: the normal force's slope changes there). Tolerance 1e-3 of the largest entry (about 1e6 N/m, the
    shear spring mu N / d_f): a dropped normal-force term (``mu k_b d_n q' d n^T / s``, up to mu k_b d_n, 1.6e5 N/m
    here), a lost ``d d^T / s^2`` (the spring's softening, up to mu N / d_f) or a wrong sign are far above it."""
    water = {"flat": Water(depth=120.0, friction=0.6),
             "slope": Water(depth=120.0, slope=0.05, friction=0.6),
             "profile": Water(profile=((0.0, 60.0, 400.0), (118.0, 120.0, 126.0)), depth=None, friction=0.6)}[seabed]
    model, X = _grounded(water)
    on = np.flatnonzero(np.isfinite(friction_targets(model, X)[:, 0]))
    assert len(on) >= 5
    dfric = 0.01
    rng = np.random.default_rng(5)
    targets = np.full_like(X, np.nan)
    scale = dfric * 10.0 ** rng.uniform(-1.0, 1.0, len(on))
    targets[on] = X[on] - scale[:, None] * rng.normal(0.0, 1.0, (len(on), 3))
    ramp = model.env[K.E_BEDRAMP]
    X[on[::2], 2] += 1.5 * ramp  # from their rest (2 bands in) to half a band in: the rounded part
    nd = 3 * model.nfree
    band = np.zeros((nd, 2 * model.bw + 1))
    _friction(model, X, targets, dfric, band)
    got = np.zeros((nd, nd))
    for r in range(nd):
        for c in range(max(0, r - model.bw), min(nd, r + model.bw + 1)):
            got[r, c] = band[r, model.bw + c - r]
    want = np.zeros((nd, nd))
    h = 1e-7
    for i in on:
        for r in range(3):
            Xp, Xm = X.copy(), X.copy()
            Xp[i, r] += h
            Xm[i, r] -= h
            dF = (_friction(model, Xp, targets, dfric) - _friction(model, Xm, targets, dfric)) / (2 * h)
            want[3 * model.fidx[i]:3 * model.fidx[i] + 3, 3 * model.fidx[i] + r] = -dF[i]
    top = np.abs(want).max()
    assert top > 1e5
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-3 * top)


def test_the_friction_force_is_the_regularised_coulomb_law_in_the_seabed_plane():
    """At a node ``d`` from its target across the seabed, the force is ``-mu N d / sqrt(d^2 + d_f^2)`` with ``N`` the
    contact force (here the node's share of the weight, on a flat seabed at rest), in the plane (none along the
    normal): to round-off. A wrong scale (``d_f`` for ``d_f^2``), sign or direction fails."""
    model, X = _grounded(Water(depth=120.0, friction=0.6))
    i = int(np.flatnonzero(np.isfinite(friction_targets(model, X)[:, 0]))[3])
    pen = model.water.seabed_z(X[i, 0]) - X[i, 2]
    assert pen > model.env[K.E_BEDRAMP]  # the contact's linear range: N = k_b d_n pen
    N = model.water.seabed_stiffness * model.bedc[i] * pen
    targets = np.full_like(X, np.nan)
    d = np.array([0.003, -0.004, 0.002])  # 5 mm across the plane, and 2 mm along the normal (not counted)
    targets[i] = X[i] - d
    F = _friction(model, X, targets, 0.004)
    want = -0.6 * N * np.array([0.003, -0.004, 0.0]) / math.hypot(0.005, 0.004)
    np.testing.assert_allclose(F[i], want, rtol=1e-12)
    assert np.all(np.delete(F, i, axis=0) == 0.0)


def test_targets_follow_a_node_that_slid_and_are_kept_by_one_that_did_not():
    """:func:`slide_targets`: a node moved more than ``SLIDE_FACTOR d_f`` across the seabed has its target moved to
    that distance behind it, along its slip; one moved less keeps its target; one without a target (touched down)
    takes its position, and a node off the seabed has none."""
    model, X = _grounded(Water(depth=120.0, friction=0.6))
    targets = friction_targets(model, X)
    on = np.flatnonzero(np.isfinite(targets[:, 0]))
    assert not np.isfinite(targets[-2, 0])  # a suspended node: no target
    Y = X.copy()
    Y[on[0], 0] += 1.0  # slid 1 m along x
    Y[on[1], 1] += 0.5 * SLIDE_FACTOR * 1e-3  # within the reach: held
    targets[on[2]] = np.nan  # as if it had just touched down
    new = slide_targets(model, Y, targets, 1e-3)
    np.testing.assert_allclose(new[on[0]], Y[on[0]] - [SLIDE_FACTOR * 1e-3, 0.0, 0.0], rtol=0, atol=1e-12)
    np.testing.assert_array_equal(new[on[1]], targets[on[1]])
    np.testing.assert_array_equal(new[on[2]], Y[on[2]])
    assert np.all(np.isnan(new[-2]))


LINE = {"line_types": {"chain": {"diameter": 0.09, "mass_per_length": 77.7, "axial_stiffness": 3.84e8}},
        "line": {"segments": [{"line_type": "chain", "length": 400.0}]}}


def _case(friction=0.0, static_friction=None, current=0.0, kind="mooring_static"):
    analysis = {"type": kind, "anchor": [0.0, -120.0], "fairlead": [330.0, -20.0], "n_elements": 20}
    if kind == "mooring_pushover":
        analysis["offsets"] = [-10.0, 0.0, 10.0]
    if static_friction is not None:
        analysis["static_friction"] = static_friction
    env = {"depth": 120.0, "seabed": {"friction": friction}, "current": {"speed": current}}
    return sc.Case.parse({"name": "f", **LINE, "environment": env, "analysis": analysis})


@pytest.mark.parametrize("kind", ["mooring_static", "mooring_pushover"])
def test_without_friction_or_in_still_water_the_statics_are_the_frictionless_ones_to_the_bit(kind):
    """Seabed friction 0 (the default) or ``static_friction.mode: off`` give the frictionless statics, and so does
    friction in still water (the as-laid state is the equilibrium, its friction force 0): the same bits. And the
    default key is left out of a dumped case (a result's ``case`` attribute reads as before)."""
    base = sc.run(_case(0.0, kind=kind))
    for case in (_case(0.8, {"mode": "off"}, kind=kind), _case(0.8, kind=kind) if kind == "mooring_static" else None):
        if case is None:
            continue
        ds = sc.run(case)
        for name in ("x", "y", "z", "tension"):
            np.testing.assert_array_equal(ds[name].values, base[name].values)
    assert "static_friction" not in _case(0.0, kind=kind).model_dump()["analysis"]
    assert _case(0.0, {"mode": "off"}, kind=kind).model_dump()["analysis"]["static_friction"]["mode"] == "off"


@pytest.mark.parametrize(("key", "value", "says"), [
    ("mode", "on", "as_laid"), ("pushover_path", "monotonic", "incremental"),
    ("friction_distance", -0.001, "Suggested fix"), ("friction_distance", 0.0, "friction_distance"),
    ("slip", 0.001, "unknown key")])
def test_bad_static_friction_is_refused_by_name(key, value, says):
    with pytest.raises(InputError, match=says):
        _case(0.5, {key: value})


@pytest.mark.parametrize("load", ["current", "slope"])
def test_the_message_weighs_the_grounded_lines_load_against_its_friction(load):
    """When the statics fail, :func:`seabed_hold_hint` says which load on the grounded line friction cannot hold:
    per metre of an element on the seabed, the current's drag across it (``1/2 rho d C_dn U^2``) or the weight down
    the slope (``w sin(beta)``) against ``mu w cos(beta)``, with the numbers in N/m and a suggested fix; under the
    friction it names no such load (and, the elements carrying no compression, suggests they do)."""
    from seacable.mooring.checks import seabed_hold_hint

    rope = sc.LineType(diameter=0.05, mass_per_length=12.0, axial_stiffness=1e6, drag_normal=1.2,
                       drag_tangential=0.0)
    net = network_from_line(sc.Line.single(rope, 100.0), (0, 0, -50.0), (0, 100.0, -50.0), water_density=1025.0,
                            gravity=9.81, n_elements=10)
    w = float(net.weight_per_length[0])
    for ratio in (1.2, 0.8):
        if load == "current":
            speed = math.sqrt(ratio * 0.5 * w / (0.5 * 1025.0 * 0.05 * 1.2))
            water = Water(depth=50.0, gravity=9.81, friction=0.5, current_speeds=(speed,), current_heading=0.0)
            X = net.position.copy()
            X[:, 0] = 0.0
            q, hold = ratio * 0.5 * w, 0.5 * w
        else:
            beta = math.atan(ratio * 0.5)
            water = Water(depth=50.0, gravity=9.81, slope=beta, friction=0.5)
            X = net.position.copy()
            X[:, 0], X[:, 2] = 0.0, -50.0
            q, hold = w * math.sin(beta), 0.5 * w * math.cos(beta)
        model = MooringModel(net.replace(position=X), water, checked=True)
        X[1:-1, 2] -= 1e-4  # pressed into the seabed
        text = seabed_hold_hint(model, X, True)
        if ratio > 1:
            assert f"{q:.4g} N/m in all, more than the seabed's friction holds" in text
            assert f"= {hold:.4g} N/m: it slides" in text and "Suggested fix" in text
        else:
            assert "more than the seabed's friction holds" not in text and "'compression: true'" in text

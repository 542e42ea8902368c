"""The seabed's static friction in a mooring system's finite-element statics (issue 40;
:mod:`seacable.system.statics.fe`, :mod:`seacable.mooring.friction`).

(a) One chain between two fixed points as a system line and as a single line (``friction_static`` on the same
    finite-element model), in a current across it: the same equilibrium to the solvers' tolerance; the friction holds
    the grounded chain (1 m sideways at most, 18 m frictionless).
(b) A slack chain pushed by a current towards its anchor: frictionless it has no static equilibrium and the message
    says why and what to give (as the single line's, ``tests/unit/test_lazy_wave_friction.py``); with friction it
    converges, its grounded part held where it was laid (within the slip distance).
(c) The example spread mooring without current, 500 kN along +x, seabed friction 0.1: the finite-element statics with
    friction against the catenary statics with friction (MoorPy's rigid-plastic model, the friction fully mobilised
    along the grounded length as when a line is pulled out monotonically from a lay without tension: the anchor
    tension ``max(H - mu w L_B, 0)``). Where both apply, the pulled-out line1 (its whole grounded length slides
    towards the fairlead), they agree: the tension falls by ``mu w`` per metre from the touchdown towards the anchor in
    both, and the anchor tensions agree within 1.3 % (664.8 kN catenary, 656.1 kN finite elements). Lines 2 and 3
    differ, and should: the body moves towards their anchors, so they are pushed back, not pulled out; the finite
    elements' friction (OrcaFlex's targets from the as-laid state, 304 kN on the seabed) resists the retraction, so
    the tension *rises* by ``mu w`` per metre from the touchdown towards the anchor (216 -> 262 kN), while the
    catenary's rule lets it fall (214 -> 151 kN). That history is also why the body's offset differs by 0.23 m
    (16.56 m against 16.78 m; frictionless 16.784 and 16.788 m): the retracting lines 2 and 3 stay stretched.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml

from seacable.errors import ConvergenceError, SeacableWarning
from seacable.io import parse_case
from seacable.mooring.friction import StaticFriction, friction_static
from seacable.system.run import _condition_system, run_system_static
from seacable.system.statics.fe import fe_equilibrium

SPREAD = Path(__file__).resolve().parents[2] / "examples" / "spread_mooring.yaml"
CHAIN_W = 698.0  # the chain's weight in water [N/m]


def _chain(mu, speed, heading, x=330.0, mode="as_laid"):
    """A 400 m chain from an anchor on the seabed (120 m of water) to a fixed point 100 m above it, ``x`` away."""
    return parse_case({
        "name": "one_chain",
        "line_types": {"chain": {"diameter": 0.09, "mass_per_length": 77.7, "weight_in_water": CHAIN_W,
                                 "axial_stiffness": 3.84e8, "drag_normal": 1.6, "drag_tangential": 0.1}},
        "environment": {"water_density": 1025.0, "gravity": 9.80665, "depth": 120.0, "seabed": {"friction": mu},
                        "current": {"speed": speed, "heading": heading}},
        "points": {"anchor": {"kind": "fixed", "position": [0.0, 0.0, -120.0]},
                   "fairlead": {"kind": "fixed", "position": [x, 0.0, -20.0]}},
        "lines": {"chain": {"line_type": "chain", "length": 400.0, "end_a": "anchor", "end_b": "fairlead",
                            "n_elements": 20}},
        "analysis": {"type": "system_static", "static_friction": {"mode": mode}},
    })


def _fe(case):
    return fe_equilibrium(_condition_system(case), case.environment, friction=case.analysis.static_friction,
                          stiffness=False)


def test_a_system_line_and_the_single_line_agree_with_friction():
    """0.5 m/s across the chain (its drag on the seabed 18.5 N/m against mu w = 419 N/m: held). The system's
    coupled_static and the single line's static_solve both converge to a force residual of 1e-8 of the line's
    forces; the friction's shear spring (mu N / d_f, about 8e6 N/m per node) and the line's tension turn that into
    micrometres: positions within 1e-5 m (1e-5 of the 1 m the current moves the line), tensions within 1e-6."""
    case = _chain(0.6, 0.5, math.pi / 2)
    eq = _fe(case)
    single = friction_static(eq.fe.model, StaticFriction(), tol=case.analysis.tolerance)
    X, Y = eq.state.position, single.position
    np.testing.assert_allclose(X, Y, rtol=0, atol=1e-5)
    np.testing.assert_allclose(eq.state.tension, single.tension, rtol=1e-6)
    assert np.abs(X[:, 1]).max() < 1.1                # the friction holds the grounded chain
    with pytest.warns(SeacableWarning, match=r"frictionless: analysis.static_friction.mode is 'off'"):
        free = _fe(_chain(0.6, 0.5, math.pi / 2, mode="off"))
    assert np.abs(free.state.position[:, 1]).max() > 15.0  # frictionless the current carries it 18 m sideways


def test_a_grounded_chain_pushed_towards_its_anchor_needs_the_friction():
    """1 m/s towards the anchor on a slack chain (fairlead 300 m out): its grounded part is pushed along itself,
    14.5 N/m of drag, which its tension-only elements cannot hold: frictionless there is no equilibrium, and the
    message says so with the fix. With friction 0.6 (419 N/m) each grounded node holds its own load elastically
    (``r = q / (mu w) = 0.035``: a slip ``d_f r / sqrt(1 - r^2)``, 35 um): the nodes lying more than 100 m from the
    touchdown stay within the slip distance, 1 mm, of where they were laid."""
    with pytest.raises(ConvergenceError, match=r"the current's drag, 14.49 N/m \(1 m/s at the seabed\), and the "
                                               r"statics have no friction to hold it.*Suggested fix: give the seabed "
                                               r"its friction coefficient"):
        run_system_static(_chain(0.0, 1.0, math.pi, x=300.0))
    with pytest.raises(ConvergenceError, match=r"static_friction mode is 'off'"), pytest.warns(SeacableWarning):
        run_system_static(_chain(0.6, 1.0, math.pi, x=300.0, mode="off"))
    eq = _fe(_chain(0.6, 1.0, math.pi, x=300.0))
    laid = _fe(_chain(0.6, 0.0, math.pi, x=300.0))
    X, L = eq.state.position, laid.state.position
    near = np.flatnonzero((L[:, 2] < -119.99) & (L[:, 0] < 100.0))
    assert near.size >= 4
    assert np.abs(X[near] - L[near]).max() < 1e-3
    assert eq.end_a_tension[0] > 0.0


def _spread(mu, load):
    d = yaml.safe_load(SPREAD.read_text(encoding="utf-8"))
    d["environment"]["seabed"] = {"friction": mu}
    d["bodies"]["buoy"]["external_force"] = [load, 0.0, 0.0, 0.0, 0.0, 0.0]
    for line in d["lines"].values():
        line["n_elements"] = 40
    d["analysis"] = {"type": "system_static"}
    return parse_case(d)


def _grounded_gradient(ds, j):
    """The tension's change per metre along line j's grounded nodes, from the anchor on (finite elements). [N/m]"""
    z, T = ds.z.values[0, j], ds.tension.values[0, j]
    x, y = ds.x.values[0, j], ds.y.values[0, j]
    g = np.flatnonzero(z < -150.0 + 0.01)
    s = np.r_[0.0, np.cumsum(np.hypot(np.diff(x[g]), np.diff(y[g])))]
    return s, T[g]


def test_the_fe_and_the_catenary_statics_with_friction_on_a_spread_mooring():
    mu = 0.1
    w = (180.0 - 1025.0 * math.pi / 4 * 0.171 ** 2) * 9.81  # the chain's weight in water [N/m]
    fe = run_system_static(_spread(mu, 5e5), statics="finite_element")
    cat = run_system_static(_spread(mu, 5e5), statics="catenary")
    laid = run_system_static(_spread(mu, 0.0), statics="finite_element")
    free = run_system_static(_spread(0.0, 5e5), statics="finite_element")
    # line1, pulled out: the tension falls by mu w per metre towards the anchor over the whole grounded length (the
    # nodes within 2 of the touchdown left out: the contact's rounding; and the anchor's: its tension is the end
    # force, half an element from the next node's mean of two elements); 1 % (the stretch T/EA, 0.09 %, between the
    # stretched s here and the unstretched length friction acts per, and the penalty seabed's slope)
    s, T = _grounded_gradient(fe, 0)
    slope = np.polyfit(s[1:-2], T[1:-2], 1)[0]
    assert slope == pytest.approx(mu * w, rel=0.01)
    # the anchor tensions where both apply: 1.3 % apart, the body's 0.23 m smaller offset in the finite elements
    # (the docstring: lines 2 and 3 retract against their friction) times line1's stiffness, 42 kN/m; 2 % bounds it
    ta_fe, ta_cat = fe.anchor_tension.values[0], cat.anchor_tension.values[0]
    assert ta_fe[0] == pytest.approx(ta_cat[0], rel=0.02)
    assert abs(ta_fe[0] - free.anchor_tension.values[0, 0]) > 0.9 * mu * w * fe.grounded_length.values[0, 0]
    # lines 2 and 3, pushed back: the finite elements' tension rises towards the anchor by mu w per metre from the
    # touchdown's (its newly laid elements, held where they touched down, left out), up to at most the as-laid
    # tension; the catenary's rule has it fall to max(H - mu w L_B, 0)
    for j in (1, 2):
        s, T = _grounded_gradient(fe, j)
        slope = np.polyfit(s[1:12], T[1:12], 1)[0]
        assert slope == pytest.approx(-mu * w, rel=0.05)
        assert free.anchor_tension.values[0, j] < ta_fe[j] <= laid.anchor_tension.values[0, j]
        assert ta_cat[j] == pytest.approx(max(cat.anchor_tension.values[0, j], 0.0))
        assert ta_fe[j] - ta_cat[j] > 0.9 * mu * w * cat.grounded_length.values[0, j]
    # the offset: 0.23 m (1.4 %) apart, the lines' different histories; frictionless the two statics agree to 4 mm
    assert abs(free.body_x.values[0, 0] - 16.7875) < 0.01
    assert fe.body_x.values[0, 0] == pytest.approx(cat.body_x.values[0, 0], rel=0.02)


def test_with_no_load_the_friction_statics_are_the_frictionless_ones():
    """No current, no load: the as-laid state is the equilibrium (no friction force at the targets): the same to the
    solver's tolerance; the system_static without friction unchanged (friction 0 to the bit: the fingerprints)."""
    a = run_system_static(_spread(0.5, 0.0), statics="finite_element")
    b = run_system_static(_spread(0.0, 0.0), statics="finite_element")
    np.testing.assert_allclose(a.fairlead_tension.values, b.fairlead_tension.values, rtol=1e-9)
    np.testing.assert_allclose(a.anchor_tension.values, b.anchor_tension.values, rtol=1e-9)

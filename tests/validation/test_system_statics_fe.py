"""The finite-element statics of a mooring system (seacable.system.statics.fe): the fallback of
``system_static`` for a current or a sloping seabed.

Asserted:

(a) With no current and a flat seabed, forced onto the finite-element path, the equilibrium converges to
    the exact elastic catenary's (seacable.system.statics) at second order in the element length: the
    error ratio between 10, 20 and 40 elements is 4 (order 2 within 0.1), the Richardson extrapolation
    of 20 and 40 elements agrees with the catenary to 2e-6, and the stiffness by central differences
    converges to the analytic one at second order too.
(b) A body in a uniform current: its equilibrium (the lines' pull balances its drag), the whole system's
    (the anchors hold the body's drag plus the lines' drag), the lines' drag against the integral of
    1/2 rho d (Cdn |u_n| u_n + pi Cdt |u_t| u_t) over the finite-element profile, and the body carried
    further downstream than in still water.
(c) A sloping seabed: the grounded part of each line lies on the slope, within the penalty contact's
    static penetration w / (k d).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.environment import Current
from seacable.io import parse_case
from seacable.system.statics.fe import fe_equilibrium
from seacable.system.statics.model import rotation
from seacable.system.run import run_system_static
from seacable.system.statics import solve_equilibrium

SPREAD = Path(__file__).resolve().parents[2] / "examples" / "spread_mooring.yaml"


def _suspended(**env) -> dict:
    """The example spread's buoy on three 335 m chains to anchors 300 m out at 150 m depth, in 400 m of
    water: every line hangs clear of the seabed (no touchdown to resolve), 200 kN along +x."""
    d = yaml.safe_load(SPREAD.read_text(encoding="utf-8"))
    for i, h in ((1, 180.0), (2, 60.0), (3, 300.0)):
        d["points"][f"anchor{i}"]["position"] = [300.0 * math.cos(math.radians(h)), 300.0 * math.sin(math.radians(h)),
                                                 -150.0]
        d["lines"][f"line{i}"]["length"] = 335.0
    d["bodies"]["buoy"]["external_force"] = [2.0e5, 0.0, 0.0, 0.0, 0.0, 0.0]
    d["environment"] = {"water_density": 1025.0, "gravity": 9.81, "depth": 400.0, **env}
    d["analysis"] = {"type": "system_static"}
    return d


# --- (a) no current: converges to the catenary at second order -------------------------------------------

def _errors(eq, fe):
    """Relative errors of the end tensions, and errors of surge, heave, pitch scaled by the line length."""
    return np.r_[fe.end_b_tension / eq.end_b_tension - 1, fe.end_a_tension / eq.end_a_tension - 1,
                 (fe.body_position[0, [0, 2, 4]] - eq.body_position[0, [0, 2, 4]]) / np.r_[335.0, 335.0, 1.0]]


def test_fe_statics_converge_to_the_catenary_at_second_order():
    case = parse_case(_suspended())
    system, env = case.system(), case.environment
    eq = solve_equilibrium(system, env)
    assert np.all(eq.grounded_length == 0) and eq.end_a_force[0, 2] > 0  # hanging clear: no touchdown
    runs = {n: fe_equilibrium(system, env, n_elements=n) for n in (10, 20, 40)}
    e = {n: _errors(eq, f) for n, f in runs.items()}
    # lumped weight on truss elements: the chord of an element is the catenary's secant, its tension the
    # midpoint value, both second order in h; an order within 0.1 of 2 (measured 1.99-2.01)
    for coarse, fine in ((10, 20), (20, 40)):
        order = np.log2(np.abs(e[coarse] / e[fine]))
        assert np.all(np.abs(order - 2.0) < 0.1), (coarse, fine, order)
    # Richardson's extrapolation removes the h^2 term; what is left (h^3, h^4 and the solvers' 1e-8
    # tolerances) is below 2e-6 (measured < 3e-7 on the tensions)
    rich = (4 * e[40] - e[20]) / 3
    assert np.all(np.abs(rich) < 2e-6), rich
    # the stiffness by central differences of equilibria against the analytic catenary tangents: the
    # held equilibria carry a noise of ~2e-5 of K (measured by varying the step and the tolerance), so the
    # order is taken over 10 -> 40 elements: 2 within 0.3 (measured 2.0-2.2), and 4e-4 off at 40 elements
    # (measured 1e-4 to 3.4e-4)
    k = {n: np.diag(f.stiffness) / np.diag(eq.stiffness) - 1 for n, f in runs.items()}
    order = np.log(k[10] / k[40]) / np.log(4.0)
    assert np.all(np.abs(order - 2.0) < 0.3), order
    assert np.all(np.abs(k[40]) < 4e-4), k[40]


def test_auto_statics_keep_the_catenary_path_and_the_fe_path_is_reported():
    case = parse_case(_suspended())
    cat = run_system_static(case)
    assert cat.attrs["statics"] == "catenary" and cat.attrs["stiffness_method"].startswith("analytic")
    eq = solve_equilibrium(case.system(), case.environment, tol=case.analysis.tolerance,
                           max_iter=case.analysis.max_iterations)
    assert np.array_equal(cat.fairlead_tension.values[0], eq.end_b_tension)  # bit for bit
    fe = run_system_static(case, statics="finite_element")
    assert fe.attrs["statics"] == "finite_element"
    assert fe.attrs["stiffness_method"] == "central differences of the finite-element statics"
    # 20 elements per line (the lines' default): 1e-3 of the catenary (the h^2 error measured above)
    np.testing.assert_allclose(fe.fairlead_tension.values, cat.fairlead_tension.values, rtol=2e-3)
    with pytest.raises(sc.InputError, match="environment.current"):
        run_system_static(parse_case(_suspended(current={"speed": 0.5})), statics="catenary")


# --- (b) a uniform current ----------------------------------------------------------------------------------

def _line_drag(eq, u: np.ndarray) -> np.ndarray:
    """Integral of the drag per unstretched length over the finite-element profile, trapezoidal over the
    nodes with the tangent by central differences (one-sided at the ends): an independent quadrature of
    the kernel's lumped drag (which takes each element's chord). [N]"""
    total = np.zeros(3)
    for name in eq.line_names:
        lt = eq.system.lines[name].line.segments[0].line_type
        s, X, _ = eq.line_nodes(name)
        t = np.gradient(X, s, axis=0)
        t /= np.linalg.norm(t, axis=1)[:, None]
        ut = (t @ u)[:, None] * t
        un = u - ut
        f = 0.5 * 1025.0 * lt.diameter * (lt.drag_normal * np.linalg.norm(un, axis=1)[:, None] * un
                                          + math.pi * lt.drag_tangential * np.linalg.norm(ut, axis=1)[:, None] * ut)
        total += np.trapezoid(f, s, axis=0)
    return total


def _body_drag(eq, B2: np.ndarray, u: np.ndarray) -> np.ndarray:
    """The body's quadratic damping at rest in the current: -R B2 |v_r| v_r, v_r = R^T (0 - u). [N]"""
    R = rotation(eq.body_position[0, 3:])
    vr = R.T @ (-u)
    return -R @ (B2[:3, :3] @ (np.abs(vr) * vr))


@pytest.mark.parametrize("n", [20, 40])
def test_a_body_in_a_uniform_current(n):
    speed = 1.0
    d = _suspended(current={"speed": speed})
    d["bodies"]["buoy"]["external_force"] = [0.0] * 6
    B2 = np.diag([2.0e5, 2.0e5, 0.0, 0.0, 0.0, 0.0])  # N/(m/s)^2: 200 kN at 1 m/s
    d["bodies"]["buoy"]["quadratic_damping"] = B2.tolist()
    case = parse_case(d)
    system, env = case.system(), case.environment
    eq = fe_equilibrium(system, env, n_elements=n)
    still = fe_equilibrium(system, env.model_copy(update={"current": Current()}), n_elements=n)
    u = np.array([speed, 0.0, 0.0])
    on_body = eq.end_b_force.sum(axis=0)          # end B of every line is on the buoy
    on_anchors = eq.end_a_force.sum(axis=0)
    body_drag = _body_drag(eq, B2, u)
    scale = np.abs(eq.end_b_force).max()
    # the body: the lines' pull balances its drag (horizontal), to the solver's tolerance (1e-8 relative)
    np.testing.assert_allclose(on_body[:2] + body_drag[:2], 0.0, atol=1e-6 * scale)
    # the whole system: the anchors hold the body's drag and the lines' (no friction, no seabed contact);
    # the lines' drag by an independent quadrature of the profile differs from the lumped one by O(h^2):
    # 1e-3 at 20 elements, 2.5e-4 at 40 (measured 2.7e-4 and 4.9e-5: the ratio of second order)
    drag = _line_drag(eq, u)
    assert drag[0] > 0.1 * body_drag[0]            # the lines' drag is not negligible (measured 28 %)
    lumped = on_anchors[0] + on_body[0]            # the lines' end forces sum to their drag
    assert lumped == pytest.approx(drag[0], rel=1e-3 if n == 20 else 2.5e-4)
    assert on_anchors[0] == pytest.approx(body_drag[0] + drag[0], rel=1e-3 if n == 20 else 2.5e-4)
    # carried downstream by the drag of the body and of the lines: further than in still water under the
    # body's drag alone as an external load, by at most the lines' whole drag over the surge stiffness
    # (part of the lines' drag goes straight to the anchors; measured 0.26 m of at most 0.88 m)
    pushed = fe_equilibrium(system, still.environment, external={"buoy": (*body_drag, 0.0, 0.0, 0.0)}, n_elements=n,
                            stiffness=False)
    extra = eq.body_position[0, 0] - pushed.body_position[0, 0]
    assert 0.0 < extra < drag[0] / eq.stiffness[0, 0]
    assert eq.body_position[0, 0] - still.body_position[0, 0] > extra


# --- (c) a sloping seabed -----------------------------------------------------------------------------------

def test_grounded_lines_lie_on_a_sloping_seabed():
    """The example spread moved 700 m along +x onto a seabed rising at 0.05 rad towards +x, 185 m deep at the
    origin (150 m under the buoy); anchors on the seabed."""
    slope, depth, x0 = 0.05, 185.0, 700.0
    d = yaml.safe_load(SPREAD.read_text(encoding="utf-8"))
    d["environment"]["depth"] = depth
    d["environment"]["seabed"] = {"slope": slope}
    d["bodies"]["buoy"]["position"][0] = x0
    for i in (1, 2, 3):
        p = d["points"][f"anchor{i}"]["position"]
        p[0] += x0
        p[2] = -depth + math.tan(slope) * p[0]
    d["analysis"] = {"type": "system_static"}
    case = parse_case(d)
    ds = run_system_static(case)
    assert ds.attrs["statics"] == "finite_element" and "slop" in ds.attrs["statics_reason"]
    eq = fe_equilibrium(case.system(), case.environment)
    lt = case.line_types["chain"]
    w = (lt.mass_per_length - 1025.0 * math.pi / 4 * lt.diameter ** 2) * 9.81   # weight in water [N/m]
    pen = w / (3.0e6 * lt.diameter)   # static penetration of the penalty seabed (3e6 Pa/m): 3 mm
    grounded = 0
    for name in eq.line_names:
        _, X, _ = eq.line_nodes(name)
        bed = -depth + math.tan(slope) * X[:, 0]
        gap = (X[:, 2] - bed) * math.cos(slope)       # normal distance, > 0 above the seabed
        on = gap < 0.5 * pen
        assert on[0]                                   # from the anchor
        run = np.flatnonzero(~on)[0]                   # the grounded run up to the touchdown
        assert run >= 3, name
        assert np.all(gap[1:run - 1] > -1.5 * pen) and np.all(gap[1:run - 1] < 0.5 * pen), (name, gap[:run])
        # on the slope, not on a flat bottom: the grounded nodes' heights differ by metres along the line
        assert np.ptp(X[:run, 2]) > 1.0
        grounded += run
        assert np.all(gap >= -1.5 * pen)               # nowhere through the seabed
    assert grounded > 10
    np.testing.assert_allclose(ds.grounded_length.values[0], eq.grounded_length)


# --- system_offsets and damaged lines in a current -----------------------------------------------------------

def test_offsets_and_damaged_lines_in_a_current():
    """The watch circle in a current, intact and with line1 broken: the lines' restoring force on the
    buoy (no drag of its own) balances the applied load at every heading and in both conditions (to the
    solver's 1e-8, checked to 1e-6 of the load), and the current carries the intact buoy downstream (+x)
    at no load."""
    from seacable.system.run import run_system_offsets

    d = _suspended(current={"speed": 1.0})
    d["bodies"]["buoy"]["external_force"] = [0.0] * 6
    d["analysis"] = {"type": "system_offsets", "body": "buoy", "loads": [0.0, 5.0e4, 1.0e5], "headings": [0.0, math.pi / 2],
                     "damaged_lines": ["line2"]}
    ds = run_system_offsets(parse_case(d))
    assert ds.attrs["statics"] == "finite_element"
    load = ds.applied_load.values[None, :, None]
    np.testing.assert_allclose(ds.restoring_force.values, np.broadcast_to(load, ds.restoring_force.shape),
                               atol=1e-6 * 1.0e5)
    assert np.all(ds.body_offset_x.values[0, 0, :, 0] > 0)      # intact: downstream at no load (0.44 m)
    assert np.isnan(ds.fairlead_tension.values[1, :, :, 1]).all()   # line2 removed in the damaged condition

"""A towed body's drag and added mass per axis of the body (seacable.towed.body, seacable.mooring._body).

The law, per axis k of the body (along: the towing cable's horizontal direction, across: e_z x along, vertical:
e_z), is ``f = sum_k q_k |u_k| u_k e_k`` and ``M_a = sum_k m_k e_k e_k^T``: checked against those sums written
out for flows along single axes (each axis's area is distinct, so a swapped or dropped axis changes the force by
its whole size), and the derivatives the Newton matrices use against central differences.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.case import TowedBody
from seacable.errors import InputError
from seacable.mooring._body import body_added_mass, body_axes, body_drag, body_drag_turn

Q = np.array([10.0, 40.0, 160.0])  # 1/2 rho C_D A along, across, vertical [kg/m]: distinct, so a swap shows


def _axes(tx, ty):
    axes = np.zeros((3, 3))
    h = body_axes(tx, ty, axes)
    return axes, h


def test_the_axes_are_the_cables_horizontal_direction_its_left_and_up():
    """A cable rising towards +X+Y at the body: along is (1, 1, 0)/sqrt 2, across (-1, 1, 0)/sqrt 2, vertical e_z;
    a vertical cable: along falls back to +X. Exact to round-off."""
    axes, h = _axes(3.0, 3.0)
    r = 1.0 / math.sqrt(2.0)
    np.testing.assert_allclose(axes, [[r, r, 0.0], [-r, r, 0.0], [0.0, 0.0, 1.0]], rtol=0, atol=1e-15)
    assert h == pytest.approx(3.0 * math.sqrt(2.0), rel=1e-15)
    axes, h = _axes(0.0, 0.0)
    np.testing.assert_array_equal(axes, np.eye(3))
    assert h == 0.0


@pytest.mark.parametrize("k", [0, 1, 2])
def test_a_flow_along_one_axis_feels_that_axis_drag_only(k):
    """A flow of 2 m/s along axis k (body heading 30 deg): the force is q_k 4 N along e_k, exactly (1e-12), and
    reversing the flow reverses it (the law is odd: |u_k| u_k)."""
    axes, _ = _axes(math.cos(0.5236), math.sin(0.5236))
    for sign in (1.0, -1.0):
        u = sign * 2.0 * axes[k]
        f, out = np.zeros(3), np.zeros((3, 3))
        body_drag(u, axes, Q, f, out)
        np.testing.assert_allclose(f, sign * Q[k] * 4.0 * axes[k], rtol=1e-12, atol=1e-12)


def test_an_oblique_flow_adds_the_axes_quadratic_laws():
    """u = (1, -2, 0.5) m/s on a body heading along +X: f = (q_a 1, -q_c 4, q_v 0.25), the sum of three laws
    (the isotropic law q |u| u would give another direction: |u| = 2.29)."""
    axes, _ = _axes(1.0, 0.0)
    f, out = np.zeros(3), np.zeros((3, 3))
    body_drag(np.array([1.0, -2.0, 0.5]), axes, Q, f, out)
    np.testing.assert_allclose(f, [Q[0] * 1.0, -Q[1] * 4.0, Q[2] * 0.25], rtol=1e-14)


def _fd(fun, x, h=1e-6):
    cols = []
    for c in range(3):
        e = np.zeros(3)
        e[c] = h
        cols.append((fun(x + e) - fun(x - e)) / (2 * h))
    return np.array(cols).T


def test_the_drags_derivatives_are_those_of_the_force():
    """df/du (the damping of the Newton matrices) and df/dt (the axes turning with the cable's direction t, the
    towed line's stiffness) against central differences, steps 1e-6: agree to 1e-6 of their size (the
    differences' truncation error, h^2 f''' ~ 1e-10, and round-off 1e-16 f / h ~ 1e-8)."""
    u = np.array([1.3, -0.7, 0.4])
    t = np.array([2.0, 0.6, 1.5])

    def force(u_, t_=t):
        axes, _ = _axes(t_[0], t_[1])
        f, out = np.zeros(3), np.zeros((3, 3))
        body_drag(u_, axes, Q, f, out)
        return f

    axes, h = _axes(t[0], t[1])
    f, dfu = np.zeros(3), np.zeros((3, 3))
    body_drag(u, axes, Q, f, dfu)
    np.testing.assert_allclose(dfu, _fd(force, u), rtol=0, atol=1e-6 * np.abs(dfu).max())
    dft = np.zeros((3, 3))
    body_drag_turn(u, axes, Q, h, dft)
    want = _fd(lambda t_: force(u, t_), t)
    assert np.abs(want).max() > 1.0  # the turning is there to test
    np.testing.assert_allclose(dft, want, rtol=0, atol=1e-6 * np.abs(want).max())


def test_the_added_mass_is_the_sum_of_the_axes_dyads():
    """m = (50, 200, 800) kg on a body heading 90 deg (along = +Y): M_a = diag(200, 50, 800), exactly."""
    axes, _ = _axes(0.0, 2.0)
    out = np.zeros((3, 3))
    body_added_mass(axes, np.array([50.0, 200.0, 800.0]), out)
    np.testing.assert_allclose(out, np.diag([200.0, 50.0, 800.0]), rtol=0, atol=1e-12)


def test_the_body_takes_one_number_or_three():
    """One number is the isotropic form (stored as given, so its results stay the same); three are along, across
    and vertical, with units; the steady tow's area is the along one."""
    iso = TowedBody(mass=10.0, drag_area=0.3, added_mass=5.0)
    assert iso.drag_area == 0.3 and not iso.drag_per_axis and iso.drag_areas() == (0.3, 0.3, 0.3)
    assert iso.steady_drag_area() == 0.3
    axes = TowedBody(mass=10.0, drag_area=[0.2, "0.6 m^2", 0.9], added_mass=[1, 2, 3])
    assert axes.drag_area == (0.2, 0.6, 0.9) and axes.drag_per_axis and axes.added_mass_per_axis
    assert axes.steady_drag_area() == 0.2
    assert TowedBody.parse(axes.model_dump()) == axes


@pytest.mark.parametrize(("field", "value", "words"), [
    ("drag_area", [0.2, 0.6], ["drag_area", "got 2 values", "along, across, vertical", "Suggested fix"]),
    ("drag_area", [0.2, -0.6, 0.9], ["drag_area", "across", "-0.6 m^2", ">= 0", "Suggested fix"]),
    ("drag_area", -0.3, ["drag_area", "-0.3 m^2", "Suggested fix"]),
    ("added_mass", [1.0, 2.0, 3.0, 4.0], ["added_mass", "got 4 values", "kg", "Suggested fix"]),
    ("added_mass", [1.0, 2.0, -3.0], ["added_mass", "vertical", "-3 kg", "Suggested fix"]),
])
def test_bad_per_axis_values_are_clear_errors(field, value, words):
    with pytest.raises(InputError) as err:
        TowedBody(mass=10.0, **{field: value})
    for word in words:
        assert word in str(err.value)


@pytest.mark.parametrize("body", ["{mass: 200, drag_area: [0.3, 0.8]}", "{mass: 200, added_mass: [20, -80, 100]}"])
def test_validate_rejects_a_bad_body_as_run_does(tmp_path, capsys, body):
    """A towed case with a body of two drag areas, or a negative added mass, fails validate and run alike
    (exit code 2, the key and the fix in one message, no traceback)."""
    from pathlib import Path

    from seacable.cli import main

    text = (Path(__file__).resolve().parents[2] / "examples" / "paper000_turn.yaml").read_text()
    case = tmp_path / "body.yaml"
    case.write_text(text + f"  body: {body}\n")
    assert main(["validate", str(case)]) == 2
    out, err = capsys.readouterr()
    assert "analysis.body" in err and "Suggested fix" in err and "Traceback" not in err and ": valid" not in out
    assert main(["run", str(case), "-o", str(tmp_path / "r.nc")]) == 2
    assert "analysis.body" in capsys.readouterr().err


def test_a_per_axis_body_in_a_case_file_runs_and_validates(tmp_path, capsys):
    """The same case with [along, across, vertical] values (one with a unit) validates."""
    from pathlib import Path

    from seacable.cli import main

    text = (Path(__file__).resolve().parents[2] / "examples" / "paper000_turn.yaml").read_text()
    case = tmp_path / "body.yaml"
    case.write_text(text + "  body: {mass: 200, weight_in_water: 500, drag_area: [0.3, '0.8 m^2', 0.5], "
                           "added_mass: [20, 80, 100]}\n")
    assert main(["validate", str(case)]) == 0
    assert ": valid" in capsys.readouterr().out


def test_the_added_mass_per_axis_takes_the_waters_acceleration():
    """A towed body 15 m deep under a 3 m, 6 s regular wave (heading 0.7 rad): the finite-element kernel's force on
    the end node with added mass m = [50, 150, 400] kg per axis less the same without is M_a a_w, the dyads'
    tensor times the water's acceleration there (about 0.3 m/s^2: a force of 10-100 N), to round-off (1e-9 N)."""
    import seacable as sc
    from seacable.mooring import kernel as K
    from seacable.mooring.solver import Water
    from seacable.towed.fe import towed_system

    cable = sc.LineType(diameter=0.03, mass_per_length=2.0, axial_stiffness=4e6, drag_normal=1.5,
                        drag_tangential=0.02)
    water = Water(depth=None, wave_height=3.0, wave_period=6.0, wave_heading=0.7)
    forces = {}
    for name, added in (("axes", [50.0, 150.0, 400.0]), ("none", 0.0)):
        system = towed_system(sc.Line.single(cable, 40.0), (0.0, 0.0, 0.0), water, n_nodes=5,
                              body=TowedBody(mass=300.0, weight_in_water=2000.0, drag_area=[0.4, 1.2, 2.5],
                                             added_mass=added))
        m = system.model
        n = m.network.n_nodes
        X = np.zeros((n, 3))
        X[:, 0] = np.linspace(-30.0, 0.0, n)  # the cable rises towards +X to the tow point, the body 15 m deep
        X[:, 1] = np.linspace(4.0, 0.0, n)
        X[:, 2] = np.linspace(-15.0, 0.0, n)
        F, M = np.zeros((n, 3)), np.zeros((n, 3, 3))
        K.loads(X, np.zeros_like(X), 1.3, *m.element_args(), m.fidx, m.env, m.cur_depth, m.cur_speed, True, m.sea,
                F, M, np.zeros(n - 1), np.zeros((0, 2 * m.bw + 1)), m.bw, 0.0, 0.0)
        forces[name] = F[0].copy()
    u, acc = np.zeros(3), np.zeros(3)
    K._fluid(X[0], 1.3, m.env, m.cur_depth, m.cur_speed, True, m.sea, u, acc)
    axes, ma = np.zeros((3, 3)), np.zeros((3, 3))
    body_axes(X[1, 0] - X[0, 0], X[1, 1] - X[0, 1], axes)
    body_added_mass(axes, np.array([50.0, 150.0, 400.0]), ma)
    assert np.abs(ma @ acc).max() > 5.0
    np.testing.assert_allclose(forces["axes"] - forces["none"], ma @ acc, rtol=0, atol=1e-9)

"""The towed-cable equations' analytic Jacobians against finite differences, and the error paths."""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest

from seacable import Current
from seacable.errors import ConvergenceError, InputError
from seacable.towed.equations import NV, c_terms, g_terms
from seacable.towed.scheme import _assemble, _bc_lower, _bc_top, workspace
from seacable.towed.solver import TowedBodyParameters, body_parameters, cable_parameters, simulate, steady_tow
from seacable.towed.vessel import StraightPath, TurnPath, sample_path

RNG = np.random.default_rng(7)
PAR = cable_parameters(170.0, 7, 2.79, 17.7, 0.035, axial_stiffness=4.2e5, bending_stiffness=32.4,
                       drag_normal=1.5, drag_tangential=0.01)


def random_state(n=1):
    h = RNG.normal(size=(n, NV))
    h[:, 0] = 500.0 + 100.0 * RNG.random(n)
    h[:, 1:3] *= 5.0
    h[:, 7] = -0.4 + 0.2 * RNG.random(n)
    return h


def central_jacobian(f, x, eps):
    cols = []
    for k in range(x.size):
        dx = np.zeros_like(x)
        dx[k] = eps[k]
        cols.append((f(x + dx) - f(x - dx)) / (2 * eps[k]))
    return np.array(cols).T


EPS = np.array([1e-3, 1e-4, 1e-4, 1e-6, 1e-6, 1e-6, 1e-7, 1e-7, 1e-7, 1e-7])


def test_c_terms_jacobian():
    h, u = random_state()[0], np.array([-1.0, 0.3, 0.0])

    def f(x):
        c, dc = np.zeros(NV), np.zeros((NV, NV))
        c_terms(x, u, PAR, c, dc, False)
        return c

    c, dc = np.zeros(NV), np.zeros((NV, NV))
    c_terms(h, u, PAR, c, dc, True)
    # central differences: truncation ~eps^2 * third derivative, relative 1e-6 of the entries
    np.testing.assert_allclose(dc, central_jacobian(f, h, EPS), rtol=1e-5, atol=1e-6)


def test_g_terms_jacobians():
    h, hd = random_state()[0], RNG.normal(size=NV)
    g, dg, b = np.zeros(NV), np.zeros((NV, NV)), np.zeros((NV, NV))
    g_terms(h, hd, PAR, g, dg, b)

    def gh(x):
        out = np.zeros(NV)
        g_terms(x, hd, PAR, out, np.zeros((NV, NV)), np.zeros((NV, NV)))
        return out

    def gd(x):
        out = np.zeros(NV)
        g_terms(h, x, PAR, out, np.zeros((NV, NV)), np.zeros((NV, NV)))
        return out

    np.testing.assert_allclose(dg, central_jacobian(gh, h, EPS), rtol=1e-6, atol=1e-7)
    # G is linear in Hdot, so B is exact
    np.testing.assert_allclose(b, central_jacobian(gd, hd, np.full(NV, 1e-3)), rtol=1e-8, atol=1e-9)


@pytest.mark.parametrize("steady", [False, True])
@pytest.mark.parametrize("with_body", [False, True])
def test_global_jacobian(steady, with_body):
    n = 5
    par = PAR.copy()
    par[-1] = 10.0
    bpar = body_parameters(TowedBodyParameters(mass=80.0, added_mass=10.0, weight_in_water=300.0,
                                               drag_area=0.2) if with_body else None)
    ho = random_state(n)
    hn = ho + 0.01 * random_state(n)
    co = np.zeros((n, NV))
    un = np.tile([-1.0, 0.2, 0.0], (n, 1))
    for j in range(n):
        c_terms(ho[j], un[j], par, co[j], np.zeros((NV, NV)), False)
    vessel = np.array([1.0, 0.3, 0.0])
    w = workspace(n)

    def residual(x):
        _assemble(x.reshape(n, NV), ho, co, un, un, vessel, 0.3, par, bpar, steady, w)
        return -w[11].ravel().copy()

    _assemble(hn, ho, co, un, un, vessel, 0.3, par, bpar, steady, w)
    lower, diag, upper = w[8].copy(), w[9].copy(), w[10].copy()
    full = np.zeros((n * NV, n * NV))
    for k in range(n):
        full[k * NV:(k + 1) * NV, k * NV:(k + 1) * NV] = diag[k]
        if k > 0:
            full[k * NV:(k + 1) * NV, (k - 1) * NV:k * NV] = lower[k]
        if k < n - 1:
            full[k * NV:(k + 1) * NV, (k + 1) * NV:(k + 2) * NV] = upper[k]
    num = central_jacobian(residual, hn.ravel(), np.tile(EPS, n))
    np.testing.assert_allclose(full, num, rtol=1e-5, atol=1e-5)


def test_boundary_jacobians_at_the_ends():
    h = random_state()[0]
    res, jac = np.zeros(5), np.zeros((5, NV))
    vel = np.array([1.0, -0.4, 0.1])

    def top(x):
        r = np.zeros(5)
        _bc_top(x, vel, r, np.zeros((5, NV)))
        return r

    _bc_top(h, vel, res, jac)
    np.testing.assert_allclose(jac, central_jacobian(top, h, EPS), rtol=1e-7, atol=1e-8)
    bpar = body_parameters(TowedBodyParameters(mass=80.0, weight_in_water=300.0, drag_area=0.2))
    u = np.array([-1.0, 0.0, 0.0])

    def low(x):
        r = np.zeros(5)
        _bc_lower(x, h, u, u, bpar, 0.2, False, r, np.zeros((5, NV)))
        return r

    _bc_lower(h + 0.01, h, u, u, bpar, 0.2, False, res, jac)
    np.testing.assert_allclose(jac, central_jacobian(low, h + 0.01, EPS), rtol=1e-6, atol=1e-6)


def test_zero_bending_stiffness_is_refused_with_a_fix():
    with pytest.raises(InputError, match=r"bending_stiffness must be > 0 N m\^2.*Suggested fix"):
        cable_parameters(170.0, 7, 2.79, 17.7, 0.035, axial_stiffness=4.2e5, bending_stiffness=0.0,
                         drag_normal=1.5, drag_tangential=0.0)


def test_vertical_start_is_refused():
    with pytest.raises(InputError, match="hang vertically.*Suggested fix: start the vessel moving"):
        steady_tow(PAR, 7, [0.0, 0.0, 0.0], Current.uniform(0.0))


def test_body_needs_mass():
    with pytest.raises(InputError, match="body.mass must be > 0 kg"):
        body_parameters(TowedBodyParameters(mass=0.0, weight_in_water=100.0))


def test_output_interval_must_be_a_multiple_of_the_step():
    path = functools.partial(sample_path, StraightPath(speed=1.0))
    with pytest.raises(InputError, match=r"multiple of time_step \(0.3 s\).*Suggested fix: use 0.9 s"):
        simulate(PAR, 7, path, 10.0, 0.3, output_interval=1.0, current=Current.uniform(-1.0))


def test_newton_failure_reports_time_iterations_and_a_smaller_step():
    # two Newton iterations cannot reach 1e-14 even on halved steps: the error names the time
    path = functools.partial(sample_path, TurnPath(speed=1.0, turn_rate=0.05))
    with pytest.raises(ConvergenceError, match=r"at t = 0 s.*Suggested fix: use a smaller time_step") as err:
        simulate(PAR, 7, path, 5.0, 1.0, current=Current.uniform(-1.0), tol=1e-14, max_iter=2)
    assert err.value.time == 0.0 and err.value.iterations == 2 and err.value.residual > 0


def test_step_halving_rescues_a_hard_step():
    # an abrupt stop of a light cable: a step of 1 s fails within 6 iterations, halving gets through.
    # The shape then matches a run with 1/64 s steps throughout to 0.2 m of 170 m (measured 0.12 m:
    # the O(dt^2) error of the unhalved 1 s steps); the tension is not compared, as it carries the
    # axial ringing of the abrupt stop, which 1 s steps cannot resolve.
    from seacable.towed.vessel import SpeedSchedule

    par = cable_parameters(170.0, 13, 1.2, 2.0, 0.035, axial_stiffness=4.2e5, bending_stiffness=32.4,
                           drag_normal=1.5, drag_tangential=0.01)
    path = functools.partial(sample_path, SpeedSchedule(times=(0.0, 2.0, 2.5), speeds=(2.0, 2.0, 0.0)))
    run = simulate(par, 13, path, 6.0, 1.0, max_iter=6)
    assert run.halvings >= 1
    assert np.all(np.isfinite(run.state))
    fine = simulate(par, 13, path, 6.0, 1.0 / 2 ** 6, max_iter=25)
    assert np.abs(run.position[-1] - fine.position[-1]).max() < 0.2


@pytest.mark.parametrize("solver", ["dense", "banded"])
def test_the_three_linear_solvers_give_the_same_run(solver):
    # the same Newton systems solved three ways: identical to round-off (1e-10 relative)
    path = functools.partial(sample_path, TurnPath(speed=1.0, turn_rate=math.radians(0.5)))
    runs = [simulate(PAR, 7, path, 10.0, 0.5, current=Current.uniform(-1.0), linear_solver=s)
            for s in ("block", solver)]
    np.testing.assert_allclose(runs[1].state[-1, :, 0], runs[0].state[-1, :, 0], rtol=1e-10)

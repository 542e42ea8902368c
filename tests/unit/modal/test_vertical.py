"""Unit tests of seacable.modal.vertical (Lee & Kim 1986, section 4)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.linalg import eigh_tridiagonal
from scipy.special import j1, jn_zeros, y0

from seacable.errors import ConvergenceError, InputError
from seacable.modal import vertical
from seacable.modal.vertical import travel_time, vertical_cable_frequencies, vertical_cable_period

G = 9.81


def test_wave_is_printed_eq15():
    L, m, dm, v = 300.0, 20.0, 8.0, 15.0
    T0 = m * v * v
    printed = 4 * np.sqrt((m + dm) / m) * v / G * (np.sqrt(G * L / v**2 + 1) - 1)
    # Our rationalised form equals eq. (15) up to rounding (no cancellation at this v).
    assert vertical_cable_period(L, T0, m, dm, "wave") == pytest.approx(printed, rel=1e-13)


def test_travel_time_is_eq14_quadrature():
    L, T0, m, dm, w = 250.0, 3.0e4, 40.0, 10.0, 300.0  # w: weight in water, not m g
    q = quad(lambda z: np.sqrt((m + dm) / (T0 + w * z)), 0.0, L, epsabs=0, epsrel=1e-13)[0]
    assert travel_time(L, T0, m, dm, weight_per_length=w) == pytest.approx(q, rel=1e-12)


def test_wave_limits():
    L, m = 100.0, 5.0
    # T0 = 0: tau = 2 sqrt(L/g), T1 = 4 sqrt(L/g) (a closed form).
    assert vertical_cable_period(L, 0.0, m, method="wave") == pytest.approx(4 * np.sqrt(L / G), rel=1e-14)
    # w L << T0: the string at the bottom tension, relative gap w L / (4 T0) + O(eps^2).
    T0 = 1e4 * m * G * L
    ratio = vertical_cable_period(L, T0, m, method="wave") / vertical_cable_period(L, T0, m, method="string")
    assert 1 - ratio == pytest.approx(1e-4 / 4, rel=1e-3)


def test_exact_hanging_chain():
    # T0 = 0: D. Bernoulli's hanging chain, omega_n = (j0n / 2) sqrt(g / L), closed form.
    L = 50.0
    w = vertical_cable_frequencies(L, 0.0, 3.0, n_modes=4)
    np.testing.assert_allclose(w, jn_zeros(0, 4) / 2 * np.sqrt(G / L), rtol=1e-13)
    # A vanishing bottom tension tends to it slowly: with J0(a) ~ 1 and Y0(a) ~ (2/pi) ln(a)
    # large, the root b = j + delta, delta = -Y0(j) / (J1(j) Y0(a)) (first order in 1/ln a).
    # Our root must match that within the O((delta/j)^2) remainder of the expansion.
    ratio = 1e-12  # T0 / (w L)
    near = vertical_cable_frequencies(L, ratio * 3.0 * G * L, 3.0, n_modes=4)
    j = jn_zeros(0, 4)
    a = j * np.sqrt(ratio / (1 + ratio))  # lower-end argument, to leading order
    delta = -y0(j) / (j1(j) * y0(a))
    assert np.all(np.abs(near / (w * (j + delta) / j) - 1) < (delta / j) ** 2)
    assert np.all(near > w)  # a fixed lower end stiffens every mode


def test_exact_root_solvers_agree_at_switch():
    # McMahon's expansion (A&S 9.5.28, three terms) against bracketing + brentq: both near
    # machine precision at the switch w L / T0 = 1e-3 (neglected McMahon term ~1e-20; Bessel
    # phase error of bracketing ~1e-16 * a with a ~ 6e3).
    eps = 1e-3
    brent = vertical._exact_roots(eps * (1 + 1e-12), 6)
    mcm = vertical._exact_roots(eps * (1 - 1e-12), 6)
    np.testing.assert_allclose(mcm, brent, rtol=1e-11)


def test_exact_tends_to_wave_estimate_at_second_order():
    # x_1 = omega_1 tau -> pi with 1 - x_1/pi = eps^2 / (32 pi^2) + O(eps^3) (McMahon's p term,
    # eps = w L / T0); checked on the bracketing solver at eps = 0.01 (O(eps) relative remainder).
    eps = 0.01
    x1 = vertical._exact_roots(eps, 1)[0]
    assert 1 - x1 / np.pi == pytest.approx(eps**2 / (32 * np.pi**2), rel=0.02)


def _fd_modes(L, T0, M, w, n=4000, k=4):
    """M y_tt = ((T0 + w z) y_z)_z, y(0) = y(L) = 0; FD on n and 2n cells, Richardson."""
    res = []
    for cells in (n, 2 * n):
        h = L / cells
        T = T0 + w * (np.arange(cells) + 0.5) * h
        lam = eigh_tridiagonal((T[:-1] + T[1:]) / (h * h * M), -T[1:-1] / (h * h * M),
                               select="i", select_range=(0, k - 1), eigvals_only=True)
        res.append(np.sqrt(lam))
    return (4 * res[1] - res[0]) / 3


@pytest.mark.parametrize("T0_over_wL", [0.0065, 0.2, 5.0])
def test_exact_against_finite_differences(T0_over_wL):
    # Independent route: the PDE discretised directly. After Richardson extrapolation the FD
    # error is O(h^4) ~ 1e-9 relative; 1e-7 leaves margin for the T(z) = w z end at small T0.
    L, m, dm, w = 427.0, 10.0, 4.0, 80.0  # w (in water) deliberately not m g
    T0 = T0_over_wL * w * L
    ours = vertical_cable_frequencies(L, T0, m, dm, n_modes=4, weight_per_length=w)
    np.testing.assert_allclose(ours, _fd_modes(L, T0, m + dm, w), rtol=1e-7)


def test_added_mass_scaling_and_mode_sequences():
    L, T0, m = 200.0, 5e3, 10.0
    for method in ("wave", "exact", "string"):
        dry = vertical_cable_frequencies(L, T0, m, 0.0, method, weight_per_length=m * G)
        wet = vertical_cable_frequencies(L, T0, m, 6.0, method, weight_per_length=m * G)
        # Same tension field, inertia m + dm: every frequency scales by sqrt(m / (m + dm)).
        np.testing.assert_allclose(wet, dry * np.sqrt(10.0 / 16.0), rtol=1e-12)
    n = np.arange(1, 6)
    wave = vertical_cable_frequencies(L, T0, m, method="wave")
    np.testing.assert_allclose(wave, n * wave[0], rtol=1e-15)  # "n times omega_1"
    string = vertical_cable_frequencies(L, T0, m, method="string")
    np.testing.assert_allclose(string, n * np.pi / L * np.sqrt(T0 / m), rtol=1e-14)


def test_vectorised():
    L = np.array([100.0, 200.0, 300.0])[:, None]
    T0 = np.array([0.0, 1e3, 1e4, 1e4])[None, :]  # a repeated value exercises the root cache
    T1 = vertical_cable_period(L, T0, 2.0, method="exact")
    assert T1.shape == (3, 4)
    assert T1[1, 2] == pytest.approx(vertical_cable_period(200.0, 1e4, 2.0, method="exact"), rel=1e-15)
    assert vertical_cable_frequencies(L, T0, 2.0, n_modes=3).shape == (3, 4, 3)
    assert isinstance(vertical_cable_period(10.0, 1.0, 1.0), float)


# ----------------------------------------------------------------------------- error paths

def test_bad_inputs():
    with pytest.raises(InputError, match="length must be > 0 m, got -3 m. Suggested fix"):
        vertical_cable_period(-3.0, 1e3, 1.0)
    with pytest.raises(InputError, match="bottom_tension must be a finite number"):
        vertical_cable_period(10.0, np.nan, 1.0)
    with pytest.raises(InputError, match="bottom_tension must be >= 0 N"):
        vertical_cable_period(10.0, -1.0, 1.0)
    with pytest.raises(InputError, match=r"mass_per_length\[1\] must be > 0 kg/m"):
        vertical_cable_period(10.0, 1.0, [1.0, 0.0])
    with pytest.raises(InputError, match="bottom_tension must be > 0 N for method='string'"):
        vertical_cable_period(10.0, 0.0, 1.0, method="string")


def test_bad_options():
    with pytest.raises(InputError, match="method must be one of .*did you mean 'exact'"):
        vertical_cable_period(10.0, 1.0, 1.0, method="exakt")
    with pytest.raises(InputError, match="n_modes must be an integer >= 1, got 2.5"):
        vertical_cable_frequencies(10.0, 1.0, 1.0, n_modes=2.5)


def test_root_bracketing_failure_raises(monkeypatch):
    # A cross product that never changes sign must not give NaN: ConvergenceError with counts.
    monkeypatch.setattr(vertical, "_cross", lambda x, rm1: 1.0)
    with pytest.raises(ConvergenceError, match="found 0 of 1 roots") as info:
        vertical_cable_period(100.0, 10.0, 1.0, method="exact")
    assert info.value.iterations == 0 and info.value.residual == 1.0


@pytest.mark.parametrize("eps", [0.3, 1.0, 4.7, 25.0, 1e3])
def test_the_roots_are_scipys_brentq_to_the_bit(eps):
    """vertical._brentq is SciPy's brentq step for step (its C code), so the exact roots are the same numbers
    as before it replaced ``scipy.optimize.brentq`` (whose import was most of ``seacable validate``'s time)."""
    from scipy.optimize import brentq

    rm1 = eps / (np.sqrt(1.0 + eps) + 1.0)
    roots = vertical._exact_roots(eps, 6)
    step = np.pi / 64.0
    for x in roots:
        lo = 1e-9 + step * np.floor((x - 1e-9) / step)
        ours = vertical._brentq(vertical._cross, lo, lo + step, (rm1,), xtol=1e-14, rtol=1e-14)
        assert ours == brentq(vertical._cross, lo, lo + step, args=(rm1,), xtol=1e-14, rtol=1e-14)
    def outcome(solve, f, a, b, **tol):
        try:
            return solve(f, a, b, **tol)
        except (RuntimeError, ConvergenceError) as err:  # no root in 100 iterations: SciPy's RuntimeError, ours
            return "no root" if "100 iterations" in str(err) else str(err)

    for f, a, b in [(lambda x: x ** 3 - 2.0, 0.0, 2.0), (lambda x: np.cos(x) - x, -1.0, 3.0),
                    (lambda x: np.exp(x) - 10.0, -5.0, 7.0), (lambda x: (x - 0.3) ** 3, 0.0, 1.0),
                    (lambda x: (x - 0.3) ** 5, 0.0, 1.0)]:
        for tol in ({}, {"xtol": 1e-15, "rtol": 1e-15}, {"xtol": 1e-6}):
            assert outcome(vertical._brentq, f, a, b, **tol) == outcome(brentq, f, a, b, **tol)
    assert outcome(brentq, lambda x: (x - 0.3) ** 5, 0.0, 1.0) == "no root"  # the failure is compared too
    with pytest.raises(ConvergenceError, match="same sign"):
        vertical._brentq(lambda x: x * x + 1.0, -1.0, 1.0)


def test_validate_of_a_vertical_cable_imports_no_scipy_optimize():
    """``seacable validate`` of paper 002's vertical cable solves its exact modes without ``scipy.optimize`` (nor
    the ``scipy.linalg`` it imports): their import was most of the command's time (issue 38)."""
    import json
    import os
    import subprocess
    import sys
    from pathlib import Path

    import seacable

    src = Path(seacable.__file__).parents[1]
    case = src.parent / "examples" / "paper002_vertical_cable.yaml"
    probe = (f"from seacable.cli import main\nassert main(['validate', {str(case)!r}]) == 0\n"
             "import json, sys\nprint(json.dumps(sorted(sys.modules)))")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=False,
                         env={**os.environ, "PYTHONPATH": str(src)})
    assert out.returncode == 0, out.stderr
    loaded = set(json.loads(out.stdout.splitlines()[-1]))
    assert "seacable.modal.vertical" in loaded
    assert sorted(m for m in ("scipy.optimize", "scipy.linalg", "numba") if m in loaded) == []

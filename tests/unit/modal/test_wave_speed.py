"""Unit tests of seacable.modal.wave_speed (Lee & Kim 1986, eq. 4-12)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.linalg import eigh_tridiagonal

from seacable.errors import InputError
from seacable.modal.wave_speed import (
    mode_frequencies,
    period_factor,
    sagged_cable_frequencies,
    sagged_cable_period,
    suspended_cable_period,
)


def _quad_factor(phi0):
    return quad(lambda p: np.cos(p) ** -1.5, 0.0, phi0, epsabs=0.0, epsrel=1e-13, limit=200)[0]


@pytest.mark.parametrize("phi0", [1e-6, 0.01, 0.3, 0.7854, 1.2, 1.5, 1.57])
def test_period_factor_matches_quadrature(phi0):
    # Closed form eq. (7) against adaptive quadrature of eq. (6); both are good to ~1e-14,
    # 1e-10 relative is the brief's requirement and leaves margin for the 1.57 rad end.
    assert period_factor(phi0) == pytest.approx(_quad_factor(phi0), rel=1e-10)


def test_period_factor_limits_and_shape():
    assert period_factor(0.0) == 0.0
    phi = 1e-3
    # Taylor: sec^{3/2} = 1 + 3 phi^2 / 4 + O(phi^4) -> f = phi + phi^3 / 4 + O(phi^5).
    assert period_factor(phi) == pytest.approx(phi + phi**3 / 4, rel=1e-12)
    # phi0 -> pi/2: f sqrt(cos phi0) -> 2 with an O(sqrt(cos phi0)) = O(1e-4) remainder.
    near = np.pi / 2 - 1e-8
    assert period_factor(near) * np.sqrt(np.cos(near)) == pytest.approx(2.0, rel=1e-3)
    out = period_factor(np.array([[0.1, 0.2], [0.3, 0.4]]))
    assert out.shape == (2, 2) and np.all(np.diff(out.ravel()) > 0)


def _quad_period(H, M, w, s_lo, s_hi):
    """Eq. (4) integrated in arc length: T1 = 2 int ds / c, c = sqrt(H sqrt(1 + (w s/H)^2) / M)."""
    integrand = lambda s: np.sqrt(M / (H * np.sqrt(1.0 + (w * s / H) ** 2)))  # noqa: E731
    return 2.0 * quad(integrand, s_lo, s_hi, epsabs=0.0, epsrel=1e-13, limit=200)[0]


def test_two_sided_and_one_sided_against_arc_length_quadrature():
    H, m, dm, w = 2.0e4, 30.0, 12.0, 250.0  # submerged weight differs from m g on purpose
    phi0, phi1 = 0.9, 0.4
    s0, s1 = H * np.tan(phi0) / w, H * np.tan(phi1) / w  # eq. (1) with the shaping weight
    kw = dict(added_mass_per_length=dm, weight_per_length=w)
    # Independent route (quadrature over s, no period factor): agreement to quadrature accuracy.
    between = sagged_cable_period(H, m, phi0, phi1, vertex="between", **kw)
    assert between == pytest.approx(_quad_period(H, m + dm, w, -s1, s0), rel=1e-10)
    outside = sagged_cable_period(H, m, phi0, phi1, vertex="outside", **kw)
    assert outside == pytest.approx(_quad_period(H, m + dm, w, s1, s0), rel=1e-10)
    one_sided = sagged_cable_period(H, m, phi0, **kw)
    assert one_sided == pytest.approx(_quad_period(H, m + dm, w, 0.0, s0), rel=1e-10)
    # Same-side order does not matter.
    assert sagged_cable_period(H, m, phi1, phi0, vertex="outside", **kw) == pytest.approx(outside)


def test_added_mass_scales_period_as_paper_section_2():
    # Same shape (same H and w): T1 in water = T1 in air * sqrt((m + dm)/m), exactly.
    base = sagged_cable_period(1e4, 10.0, 0.6, 0.3)
    wet = sagged_cable_period(1e4, 10.0, 0.6, 0.3, added_mass_per_length=5.0)
    assert wet / base == pytest.approx(np.sqrt(1.5), rel=1e-14)


def test_eq11_is_eq10_with_equal_angles():
    g, m, L, phi0 = 9.81, 3.0, 80.0, 0.5
    H = m * g * L / (2 * np.tan(phi0))
    expected = 4.0 / g * np.sqrt(H / m) * period_factor(phi0)  # eq. (11) as printed
    assert suspended_cable_period(L, phi0, m) == pytest.approx(expected, rel=1e-14)
    assert sagged_cable_period(H, m, phi0, phi0) == pytest.approx(expected, rel=1e-14)


def test_mode_numbering():
    T1 = np.array([2.0, 4.0])
    out = mode_frequencies(T1, 3, "out")
    inp = mode_frequencies(T1, 3, "in")
    assert out.shape == inp.shape == (2, 3)
    np.testing.assert_allclose(out[0], np.pi * np.array([1, 2, 3]), rtol=1e-15)
    # In plane, mode n is string harmonic n + 1: the lowest is twice the lowest out of plane.
    np.testing.assert_allclose(inp[:, :-1], out[:, 1:], rtol=1e-15)
    w = sagged_cable_frequencies([1e4, 2e4], 10.0, 0.6, n_modes=4, plane="in")
    assert w.shape == (2, 4)


def test_small_sag_in_plane_matches_irvine_antisymmetric_mode():
    # Irvine (1981): the antisymmetric in-plane modes of a shallow cable have exactly the
    # taut-string frequencies of even order, omega = 2 pi k / L sqrt(H/m); the in-plane
    # wave estimate with n = 1 is the first of them. Error O(phi0^2) ~ 1e-8 at phi0 = 1e-4.
    g, m, L, phi0 = 9.81, 2.0, 60.0, 1e-4
    H = m * g * L / (2 * np.tan(phi0))
    w = mode_frequencies(suspended_cable_period(L, phi0, m), 1, "in")[0]
    assert w == pytest.approx(2 * np.pi / L * np.sqrt(H / m), rel=1e-7)


def _out_of_plane_fd(length, phi0, m=1.0, g=9.81, n=4000, k=8):
    """Out-of-plane modes of an equal-height catenary, m y_tt = (T y_s)_s, fixed ends.

    Second-order finite differences on n and 2n cells with Richardson extrapolation.
    """
    H = m * g * length / (2 * np.tan(phi0))
    res = []
    for cells in (n, 2 * n):
        h = length / cells
        s = (np.arange(cells) + 0.5) * h - length / 2
        T = H * np.sqrt(1 + (m * g * s / H) ** 2)
        lam = eigh_tridiagonal((T[:-1] + T[1:]) / (h * h * m), -T[1:-1] / (h * h * m),
                               select="i", select_range=(0, k - 1), eigvals_only=True)
        res.append(np.sqrt(lam))
    return (4 * res[1] - res[0]) / 3


def test_out_of_plane_wave_estimate_against_finite_differences():
    """The wave estimate is the leading WKB term of the out-of-plane (swinging) problem.

    Its relative error should fall as phi0^2 for the fundamental (shallow cables) and as
    1/n^2 with the mode number; we check those orders, not a tuned tolerance.
    """
    L = 100.0
    err = {}
    for deg in (5.0, 10.0, 40.0):
        phi0 = np.radians(deg)
        est = mode_frequencies(suspended_cable_period(L, phi0, 1.0), 8, "out")
        err[deg] = 1.0 - est / _out_of_plane_fd(L, phi0)
    # The estimate is always low (the wave misses the O(1) phase of the slow region).
    assert all(np.all(e > 0) for e in err.values())
    # Order in phi0 of the fundamental: log2(e(10 deg)/e(5 deg)) = 2 within 0.1
    # (next term O(phi0^4); FD error after Richardson ~1e-9, far below e ~ 4e-4).
    order = np.log2(err[10.0][0] / err[5.0][0])
    assert order == pytest.approx(2.0, abs=0.1)
    # Order in 1/n at 40 deg: e(4)/e(8) = 4 within 10 % (next WKB term O(1/n^4)).
    assert err[40.0][3] / err[40.0][7] == pytest.approx(4.0, rel=0.1)
    # Magnitude at 40 deg, fundamental: 2.7 % (the paper's Fig. 4 notes the gap opens near 40 deg).
    assert err[40.0][0] == pytest.approx(0.027, abs=0.002)


# ----------------------------------------------------------------------------- error paths

@pytest.mark.parametrize("phi0", [0.0, np.pi / 2, 2.0, -0.1, 30.0])
def test_phi0_out_of_range(phi0):
    with pytest.raises(InputError, match=r"phi0 must be in \(0, 1.5708\) rad.*Suggested fix: .*radians"):
        sagged_cable_period(1e4, 10.0, phi0)


def test_phi1_out_of_range_and_period_factor_range():
    with pytest.raises(InputError, match=r"phi1 must be in \[0, 1.5708\) rad"):
        sagged_cable_period(1e4, 10.0, 0.5, np.pi / 2)
    with pytest.raises(InputError, match=r"phi0\[1\] must be in \[0"):
        period_factor([0.1, -0.2])


def test_nan_and_nonpositive_inputs():
    with pytest.raises(InputError, match="mass_per_length must be a finite number"):
        sagged_cable_period(1e4, np.nan, 0.5)
    with pytest.raises(InputError, match="horizontal_tension must be > 0 N, got -5 N"):
        sagged_cable_period(-5.0, 10.0, 0.5)
    with pytest.raises(InputError, match="added_mass_per_length must be >= 0 kg/m"):
        sagged_cable_period(1e4, 10.0, 0.5, added_mass_per_length=-1.0)
    with pytest.raises(InputError, match="weight_per_length must be > 0 N/m"):
        sagged_cable_period(1e4, 10.0, 0.5, weight_per_length=0.0)
    with pytest.raises(InputError, match="length must be > 0 m, got -3 m. Suggested fix"):
        suspended_cable_period(-3.0, 0.5, 1.0)
    with pytest.raises(InputError, match="end_angle must be a finite number, got nan rad"):
        suspended_cable_period(10.0, np.nan, 1.0)
    with pytest.raises(InputError, match="fundamental_period must be > 0 s"):
        mode_frequencies(0.0)


def test_options_are_validated():
    with pytest.raises(InputError, match="vertex must be one of .*did you mean 'outside'"):
        sagged_cable_period(1e4, 10.0, 0.5, 0.2, vertex="outsid")
    with pytest.raises(InputError, match="plane must be one of .*did you mean 'in'"):
        sagged_cable_frequencies(1e4, 10.0, 0.5, plane="inn")
    with pytest.raises(InputError, match="n_modes must be an integer >= 1, got 0"):
        mode_frequencies(1.0, 0)
    with pytest.raises(InputError, match="phi0 and phi1 must differ"):
        sagged_cable_period(1e4, 10.0, 0.5, 0.5, vertex="outside")

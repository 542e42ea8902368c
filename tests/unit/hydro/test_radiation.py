"""Cummins' radiation memory (issue 39): the retardation kernel from the damping and Ogilvie's relations back,
on a closed-form pair and on the VolturnUS-S database."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from seacable.errors import InputError
from seacable.hydro import (
    HydroDatabase,
    kernel_check,
    linear_transforms,
    ogilvie,
    read_wamit,
    retardation_kernel,
)

ROOT = Path(__file__).parents[2] / "data" / "volturnus" / "IEA-15-240-RWT-UMaineSemi"
ALPHA, BETA = 0.3, 1.0


def _closed_form_kernel(t):
    """K(t) = e^(-a t) (cos b t - (a / b) sin b t): decays, and its integral B(0) is 0 as a floating body's."""
    return np.exp(-ALPHA * t) * (np.cos(BETA * t) - ALPHA / BETA * np.sin(BETA * t))


def _closed_form_coefficients(w):
    """B(w) and A(w) - A_inf of that kernel: F(w) = int_0^inf K e^(-i w t) dt = B + i w (A - A_inf), with
    K = Re[(1 + i a / b) e^(-(a - i b) t)]."""
    f = 0.5 * ((1 + 1j * ALPHA / BETA) / (ALPHA + 1j * (w - BETA)) + (1 - 1j * ALPHA / BETA) / (ALPHA + 1j * (w + BETA)))
    return f.real, f.imag / w


def _database(omega, b_diag, a_diag, a_inf=1.0):
    eye = np.eye(6)
    return HydroDatabase(omega=omega, added_mass=a_inf * eye + a_diag[:, None, None] * eye,
                         damping=b_diag[:, None, None] * eye, added_mass_inf=a_inf * eye, hydrostatics=np.zeros((6, 6)),
                         source="closed form")


def test_linear_transforms_are_exact_for_a_piecewise_linear_function():
    """A hat function's cosine and sine transforms, by hand, at s = 0, small s (the series) and large s."""
    x = np.array([0.0, 1.0, 3.0])
    f = np.array([[0.0], [2.0], [0.0]])
    s = np.array([0.0, 1e-4, 0.7, 25.0])
    # at s = 1e-4 the closed forms below cancel (their error ~ 1e-16 / s^2): the series cos = 3 - s^2/2 int x^2 f
    # (int x^2 f = 0.5 + 6 = 6.5) and sin = s int x f (int x f = 2/3 + 10/3 = 4) to O(s^3) instead
    cos_int, sin_int = linear_transforms(x, f, s)
    # int_0^1 2x cos(sx) dx + int_1^3 (3 - x) cos(sx) dx, by parts
    def exact(s):
        if s < 1e-3:
            return 3.0 - 0.5 * s ** 2 * 6.5, 4.0 * s
        c1 = 2 * (math.sin(s) / s + (math.cos(s) - 1) / s ** 2)
        s1 = 2 * (-math.cos(s) / s + math.sin(s) / s ** 2)
        c2 = -2 * math.sin(s) / s - (math.cos(3 * s) - math.cos(s)) / s ** 2
        s2 = 2 * math.cos(s) / s - (math.sin(3 * s) - math.sin(s)) / s ** 2
        return c1 + c2, s1 + s2
    for k, sk in enumerate(s):
        c, sn = exact(sk)
        assert cos_int[k, 0] == pytest.approx(c, rel=1e-9, abs=1e-12)
        assert sin_int[k, 0] == pytest.approx(sn, rel=1e-7, abs=1e-12)


def test_the_kernel_of_a_closed_form_damping_is_the_closed_form_kernel():
    """B(w) sampled every 0.005 rad/s to 5 rad/s and at 400 geometric steps to 2000 rad/s: the kernel within
    5e-4 of K(0) = 1. The kernel drops the damping above the last frequency, B ~ 2a / w^2 there, so K(0) misses
    (2 / pi) 2a / 2000 = 1.9e-4; the linear interpolation adds O(dw^2 B'') (a planted 40 rad/s cut-off, 9.5e-3 off,
    fails)."""
    w = np.r_[np.arange(0.005, 5.0, 0.005), np.geomspace(5.0, 2000.0, 400)]
    b, a = _closed_form_coefficients(w)
    t, k = retardation_kernel(_database(w, b, a), dt=0.05, t_max=30.0)
    exact = _closed_form_kernel(t)
    for j in range(6):
        assert np.max(np.abs(k[:, j, j] - exact)) < 5e-4, j
    assert np.all(k[:, 0, 1] == 0.0)


def test_ogilvie_gives_the_closed_form_added_mass_and_damping_back():
    """From the exact kernel sampled every 0.01 s to 60 s (e^-18 left): A and B to 1e-4 (the kernel's linear
    interpolation, (w dt)^2 / 12 of it at w = 3 rad/s: 7.5e-5)."""
    t = np.arange(0.0, 60.0 + 1e-9, 0.01)
    kernel = _closed_form_kernel(t)[:, None, None] * np.eye(6)
    w = np.linspace(0.1, 3.0, 30)
    a, b = ogilvie(t, kernel, np.eye(6), w)
    b_exact, a_exact = _closed_form_coefficients(w)
    np.testing.assert_allclose(b[:, 2, 2], b_exact, atol=1e-4)
    np.testing.assert_allclose(a[:, 2, 2] - 1.0, a_exact, atol=1e-4)


def test_the_volturnus_kernel_gives_its_database_back():
    """The VolturnUS-S kernel (0.05 s, 300 s) through Ogilvie's relations, against the database's own A(w) and
    B(w) at its 100 frequencies. The damping within 1 % of its peak (what the kernel's 300 s drops: the damping
    stops at 5 rad/s, and that step rings as 1/t). The added mass differs more where the database's damping has
    peaks two or three samples wide (column interaction, 1.1-1.5 rad/s): the kernel takes B linear between the
    samples, so A from it is that B's Kramers-Kronig pair, not WAMIT's, and the difference is the data's, not the
    kernel's: it moves by less than 1 % between 150 and 300 s (0.54 %, at 0.05 rad/s, where the 1/w of
    equation 2 weighs the kernel's tail most). Over all frequencies it is 1.3 % of the range of A - A_inf
    (rms, surge; measured), within 1.5 %; at the worst sample 5.3 % (surge at 1.40 rad/s), within 6 %."""
    db = read_wamit(ROOT)
    t, k = retardation_kernel(db, dt=0.05, t_max=300.0)
    check = kernel_check(db, t, k)
    assert np.all(check["damping"] < 0.01), check["damping"]
    assert np.all(check["tail"] < 1e-3), check["tail"]
    assert np.all(check["added_mass"] < 0.06), check["added_mass"]
    a, _ = ogilvie(t, k, db.added_mass_inf, db.omega)
    t_half, k_half = retardation_kernel(db, dt=0.05, t_max=150.0)
    a_half, _ = ogilvie(t_half, k_half, db.added_mass_inf, db.omega)
    for j in range(6):
        spread = np.max(np.abs(db.added_mass[:, j, j] - db.added_mass_inf[j, j]))
        error = (a[:, j, j] - db.added_mass[:, j, j]) / spread
        assert np.sqrt(np.mean(error ** 2)) < 0.015, j
        assert np.max(np.abs(a[:, j, j] - a_half[:, j, j])) < 0.01 * spread, j
    # the zero-frequency limit: A(0) = A_inf - int t K dt, against WAMIT's PER = -1 row; surge and pitch to 0.5 %
    # (heave's zero-frequency added mass grows like log(1/w) in deep water, so WAMIT's finite-depth limit and
    # the sampled damping's differ more: 2.6 %, not asserted)
    a0 = db.added_mass_inf - np.trapezoid(k * t[:, None, None], t, axis=0)
    for j in (0, 4):
        assert a0[j, j] == pytest.approx(db.added_mass_zero[j, j], rel=0.005)


@pytest.mark.parametrize("dt, t_max, message", [(0.0, 60.0, "time step must be > 0 s, got 0.0"),
                                                 (0.1, 0.1, r"t_max = 0.1 s must be at least two time steps")])
def test_a_bad_kernel_request_is_refused(dt, t_max, message):
    w = np.linspace(0.1, 2.0, 5)
    with pytest.raises(InputError, match=message):
        retardation_kernel(_database(w, np.ones(5), np.zeros(5)), dt=dt, t_max=t_max)

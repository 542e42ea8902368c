"""Wind (issue 39): DNV-RP-C205's profiles and gust spectra, gust records that have their spectrum, and the force
from coefficient tables with the relative velocity."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate, signal, special

from seacable.errors import InputError
from seacable.wind import (
    WindCoefficients,
    api_profile,
    api_spectrum,
    gust_series,
    npd_profile,
    npd_spectrum,
    npd_turbulence,
)


def test_npd_profile_and_turbulence_by_hand():
    """U0 = 30 m/s at 10 m: C = 5.73e-2 sqrt(5.44) = 0.13365, at 100 m the 1-hour mean U0 (1 + C ln 10) = 39.23
    m/s; I_u(10 m) = 0.06 x 2.29 = 0.1374; the 10-minute mean at 10 m 30 (1 + 0.41 x 0.1374 ln 6) = 33.03 m/s."""
    assert npd_profile(30.0, 100.0) == pytest.approx(30.0 * (1 + 5.73e-2 * math.sqrt(5.44) * math.log(10)), rel=1e-12)
    assert npd_profile(30.0, 100.0) == pytest.approx(39.23, abs=0.01)
    assert npd_turbulence(30.0) == pytest.approx(0.1374, rel=1e-12)
    assert npd_profile(30.0, 10.0, averaging=600.0) == pytest.approx(33.03, abs=0.01)


def test_npd_spectrum_integrates_to_its_closed_form_variance():
    """int_0^inf dx / (1 + x^n)^p = Gamma(1/n) Gamma(p - 1/n) / (n Gamma(p)), so NPD's variance is
    320 (U0/10)^2 (z/10)^0.45 / (172 (z/10)^(2/3) (U0/10)^-0.75) times that (p = 5 / 3n, n = 0.468)."""
    n, p = 0.468, 5.0 / (3 * 0.468)
    closed = special.gamma(1 / n) * special.gamma(p - 1 / n) / (n * special.gamma(p))
    for u0, z in ((10.0, 10.0), (30.0, 100.0)):
        variance = 320 * (u0 / 10) ** 2 * (z / 10) ** 0.45 / (172 * (z / 10) ** (2 / 3) * (u0 / 10) ** -0.75) * closed
        numeric = integrate.quad(lambda f, u0=u0, z=z: npd_spectrum(f, u0, z), 0, np.inf, limit=200)[0]
        assert numeric == pytest.approx(variance, rel=1e-6)
    # at 10 m and 10 m/s: sigma = 1.02 m/s, a 10 % intensity
    assert math.sqrt(integrate.quad(lambda f: npd_spectrum(f, 10.0), 0, np.inf, limit=200)[0]) == pytest.approx(1.02, abs=0.01)


def test_api_spectrum_has_the_variance_of_its_intensity():
    """API's spectrum integrates to sigma^2 = (I(z) U(z))^2; at 50 m, I = 0.15 (50/20)^-0.275."""
    z, u0 = 50.0, 25.0
    sigma = 0.15 * (z / 20) ** -0.275 * u0 * (z / 10) ** 0.125
    assert api_profile(u0, z) == pytest.approx(u0 * 5 ** 0.125)
    assert integrate.quad(lambda f: api_spectrum(f, u0, z), 0, np.inf, limit=200)[0] == pytest.approx(sigma ** 2, rel=1e-6)


def test_a_gust_record_has_the_target_spectrum_and_variance():
    """A 3-hour record of the NPD spectrum (U0 = 20 m/s, z = 100 m) at 1 s, 1000 components over 0.001-0.4 Hz:
    its variance that of the spectrum over the band within 5 % (the record's sampling error: -3.1 to +3.2 % over
    eight seeds, measured), and its Welch spectrum (16 segments) within 15 % of the target on each octave from
    0.005 to 0.32 Hz (the amplitudes are the spectrum's, not random: the scatter is the phases' and Welch's alone,
    8 % at most over eight seeds)."""
    u0, z = 20.0, 100.0
    t = np.arange(0.0, 10800.0, 1.0)
    u = gust_series(lambda f: npd_spectrum(f, u0, z), t, seed=7, f_range=(1e-3, 0.4), n_components=1000)
    target = integrate.quad(lambda f: npd_spectrum(f, u0, z), 1e-3, 0.4, limit=200)[0]
    assert abs(u.mean()) < 0.1 * math.sqrt(target)
    assert u.var() == pytest.approx(target, rel=0.05)
    f, s = signal.welch(u, fs=1.0, nperseg=t.size // 16)
    for lo in (0.005, 0.01, 0.02, 0.04, 0.08, 0.16):
        band = (f >= lo) & (f < 2 * lo)
        assert s[band].mean() == pytest.approx(npd_spectrum(f[band], u0, z).mean(), rel=0.15), lo


def test_wind_force_by_direction_with_the_relative_velocity():
    """1/2 rho |u| u C at the relative wind's direction in body axes, turned to the global axes; a body moving with
    the wind feels less of it (the damping of its slow drift)."""
    coef = WindCoefficients(heading=np.radians([0.0, 90.0, 180.0, 270.0]), surge=[1000.0, 0.0, -1000.0, 0.0],
                            sway=[0.0, 800.0, 0.0, -800.0], yaw=[0.0, 5e3, 0.0, -5e3])
    q = 0.5 * 1.225 * 20.0 ** 2
    np.testing.assert_allclose(coef.force([20.0, 0.0]), [1000 * q, 0.0, 0.0], atol=1e-9)
    # half way between 0 and 90 deg: the mean of the two headings' areas, at the speed's square
    w = 20.0 * np.array([math.cos(math.pi / 4), math.sin(math.pi / 4)])
    np.testing.assert_allclose(coef.force(w), [500 * q, 400 * q, 2500 * q], rtol=1e-12)
    # the body yawed by 90 deg: a wind towards +x is a wind towards -y in its axes (270 deg): sway -800, turned back
    np.testing.assert_allclose(coef.force([20.0, 0.0], yaw=math.pi / 2), [800 * q, 0.0, -5e3 * q], atol=1e-6)
    # moving downwind at 2 m/s: the force of 18 m/s
    np.testing.assert_allclose(coef.force([20.0, 0.0], body_velocity=[2.0, 0.0])[0], 1000 * 0.5 * 1.225 * 18 ** 2)
    # between 270 and 0 deg: periodic
    w = 20.0 * np.array([math.cos(-math.pi / 4), math.sin(-math.pi / 4)])
    np.testing.assert_allclose(coef.force(w), [500 * q, -400 * q, -2500 * q], rtol=1e-12)


@pytest.mark.parametrize("call, message", [
    (lambda: npd_spectrum(0.1, -5.0), r"the wind speed U0 must be > 0 m/s"),
    (lambda: npd_profile(20.0, 0.0), r"height above the still-water level must be > 0 m, got 0 m"),
    (lambda: api_spectrum(0.1, 20.0, peak=0.5), r"f_p must be 0.01-0.1 Hz, got 0.5 Hz"),
    (lambda: WindCoefficients(heading=[0.0, 1.0], surge=[1.0], sway=[0.0, 0.0], yaw=[0.0, 0.0]),
     r"'surge' must have one finite value per heading \(2\)"),
    (lambda: gust_series(lambda f: f, [0.0], seed=1, f_range=(0.5, 0.1)), r"0 < low < high Hz"),
])
def test_bad_wind_inputs(call, message):
    with pytest.raises(InputError, match=message):
        call()

"""Wind on a floating body: mean profiles, gust spectra, gust time series and forces from coefficients (issue 39).

Profiles and spectra as DNV-RP-C205 (2021) [1]_ gives them, for the 1-hour mean speed ``U0`` at 10 m [m/s] and
the height ``z`` above the still-water level [m]:

- NPD (Frøya) [1]_ 2.3.2.11-12: the mean speed over ``T`` [s] at ``z``,
  ``U(T, z) = U0 (1 + C ln(z / 10)) (1 - 0.41 I_u(z) ln(T / 3600))``, ``C = 5.73e-2 sqrt(1 + 0.148 U0)``,
  ``I_u = 0.06 (1 + 0.043 U0) (z / 10)^-0.22``; its gust spectrum, one-sided in frequency ``f`` [Hz],
  ``S(f) = 320 (U0 / 10)^2 (z / 10)^0.45 / (1 + x^n)^(5 / 3n)`` [m^2/s^2/Hz] with
  ``x = 172 f (z / 10)^(2/3) (U0 / 10)^-0.75`` and ``n = 0.468``;
- API RP 2A / 2SK [1]_ 2.3.2.13: ``U(z) = U0 (z / 10)^0.125``, ``S(f) = sigma^2 / f_p / (1 + 1.5 f / f_p)^(5/3)``
  with ``sigma = I(z) U(z)``, ``I(z) = 0.15 (z / 20)^-0.125`` up to 20 m and ``0.15 (z / 20)^-0.275`` above, and
  ``f_p`` between 0.01 and 0.1 Hz (0.025 by default): its variance is ``sigma^2``.

A gust record (:func:`gust_series`) is the random-phase sum of the spectrum's components, seeded, on equal
bands with a frequency drawn in each (no repeat period), as :func:`seacable.seastate.synthesise` does for waves.

The force on a body (:class:`WindCoefficients`): ``F = 1/2 rho_air |u| u C(b)`` in surge and sway and the yaw
moment likewise, with ``C`` [m^2, m^2, m^3] the body's force and moment areas (drag coefficient times area, and
times arm for the moment) at ``b``, the direction the relative wind blows towards in the body's axes, linear
between a table's headings; ``u`` the wind relative to the body's own horizontal velocity, so that the force
damps the body's slow motion as it does at sea.

References
----------
.. [1] DNV-RP-C205, 2021. Environmental conditions and environmental loads, section 2.3.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ._heading import heading_weights
from ._phasor import phasor_sum
from .errors import InputError

__all__ = ["AIR_DENSITY", "WindCoefficients", "api_profile", "api_spectrum", "gust_series", "npd_profile",
           "npd_spectrum", "npd_turbulence"]

#: Density of air at 15 degC and sea-level pressure. [kg/m^3]
AIR_DENSITY = 1.225


def _speed_height(u0, z):
    u0 = float(u0)
    if not (u0 > 0 and math.isfinite(u0)):
        raise InputError(f"the wind speed U0 must be > 0 m/s (the 1-hour mean at 10 m), got {u0}.")
    z = np.asarray(z, float)
    if np.any(~(z > 0)):
        raise InputError(f"the height above the still-water level must be > 0 m, got {np.min(z):g} m. Suggested fix: "
                         "the height of the body's wind centre of pressure.")
    return u0, z


def npd_turbulence(u0, z=10.0):
    """NPD's turbulence intensity ``I_u(z)`` [-] for the 1-hour mean speed ``u0`` at 10 m [m/s]."""
    u0, z = _speed_height(u0, z)
    return 0.06 * (1.0 + 0.043 * u0) * (z / 10.0) ** -0.22


def npd_profile(u0, z, averaging: float = 3600.0):
    """NPD's mean wind speed over ``averaging`` [s] at heights ``z`` [m] for the 1-hour mean ``u0`` at 10 m. [m/s]"""
    u0, z = _speed_height(u0, z)
    if not averaging > 0:
        raise InputError(f"the averaging time must be > 0 s, got {averaging}.")
    c = 5.73e-2 * math.sqrt(1.0 + 0.148 * u0)
    return u0 * (1.0 + c * np.log(z / 10.0)) * (1.0 - 0.41 * npd_turbulence(u0, z) * math.log(averaging / 3600.0))


def npd_spectrum(f, u0, z=10.0):
    """NPD's (Frøya) gust spectrum at frequencies ``f`` [Hz]: ``S(f)`` [m^2/s^2/Hz]."""
    u0, z = _speed_height(u0, z)
    n = 0.468
    x = 172.0 * np.asarray(f, float) * (z / 10.0) ** (2.0 / 3.0) * (u0 / 10.0) ** -0.75
    return 320.0 * (u0 / 10.0) ** 2 * (z / 10.0) ** 0.45 / (1.0 + x ** n) ** (5.0 / (3.0 * n))


def api_profile(u0, z):
    """API's mean wind speed at heights ``z`` [m] for the 1-hour mean ``u0`` at 10 m. [m/s]"""
    u0, z = _speed_height(u0, z)
    return u0 * (z / 10.0) ** 0.125


def api_spectrum(f, u0, z=10.0, peak: float = 0.025):
    """API's gust spectrum at frequencies ``f`` [Hz], ``peak`` the frequency f_p [Hz]: ``S(f)`` [m^2/s^2/Hz]."""
    u0, z = _speed_height(u0, z)
    if not 0.01 <= peak <= 0.1:
        raise InputError(f"API's spectral peak f_p must be 0.01-0.1 Hz, got {peak} Hz. Suggested fix: 0.025 Hz.")
    intensity = np.where(z <= 20.0, 0.15 * (z / 20.0) ** -0.125, 0.15 * (z / 20.0) ** -0.275)
    sigma = intensity * api_profile(u0, z)
    return sigma ** 2 / peak / (1.0 + 1.5 * np.asarray(f, float) / peak) ** (5.0 / 3.0)


def gust_series(spectrum, t, *, seed: int, f_range=(1e-3, 0.5), n_components: int = 1000) -> np.ndarray:
    """A gust record ``u(t)`` [m/s] (zero mean) of the one-sided spectrum ``spectrum(f)`` [m^2/s^2/Hz] at times ``t``
    [s]: ``n_components`` on equal bands of ``f_range`` [Hz], each at a frequency drawn in its band, with amplitude
    ``sqrt(2 S df)`` and a uniform phase (seeded)."""
    lo, hi = (float(v) for v in f_range)
    if not 0 < lo < hi:
        raise InputError(f"the gusts' frequency range must be 0 < low < high Hz, got {f_range}.")
    if n_components < 1:
        raise InputError(f"n_components must be >= 1, got {n_components}.")
    rng = np.random.default_rng(seed)
    df = (hi - lo) / n_components
    f = lo + df * (np.arange(n_components) + rng.uniform(0.0, 1.0, n_components))
    amp = np.sqrt(2.0 * np.asarray(spectrum(f), float) * df)
    phase = rng.uniform(0.0, 2.0 * math.pi, n_components)
    t = np.atleast_1d(np.asarray(t, float))
    # sum a cos(2 pi f t + phase) = Re sum a e^(-i phase) e^(-i 2 pi f t)
    return phasor_sum((amp * np.exp(-1j * phase))[:, None], 2.0 * math.pi * f, t)[:, 0].real


@dataclass(frozen=True)
class WindCoefficients:
    """A body's wind force areas by the relative wind's direction (module docstring).

    ``heading`` (n,) [rad], the direction the wind blows towards in the body's axes, from +x towards +y;
    ``surge``, ``sway`` (n,) [m^2] and ``yaw`` (n,) [m^3]: drag coefficient times area (and times arm), so that
    the force is ``1/2 rho_air |u| u`` times them. One heading: the same at every direction (a turbine's rotor,
    for instance, facing the wind).
    """

    heading: np.ndarray
    surge: np.ndarray
    sway: np.ndarray
    yaw: np.ndarray

    def __post_init__(self):
        b = np.atleast_1d(np.asarray(self.heading, float))
        for name in ("surge", "sway", "yaw"):
            v = np.atleast_1d(np.asarray(getattr(self, name), float))
            if v.shape != b.shape or not np.all(np.isfinite(v)):
                raise InputError(f"wind coefficients: '{name}' must have one finite value per heading ({b.size}), got "
                                 f"{v.tolist()[:6]}.")
        if np.unique(np.round(np.mod(b, 2 * math.pi), 9)).size != b.size:
            raise InputError(f"wind coefficients: each heading must be given once, got {np.degrees(b).tolist()} deg.")

    def at(self, heading) -> np.ndarray:
        """The areas (..., 3) [m^2, m^2, m^3] at the relative wind's directions ``heading`` [rad] (body axes)."""
        order, lo, hi, frac = heading_weights(self.heading, heading)
        table = np.stack([np.atleast_1d(np.asarray(getattr(self, k), float))[order] for k in ("surge", "sway", "yaw")],
                         axis=-1)
        return (1 - frac)[..., None] * table[lo] + frac[..., None] * table[hi]

    def force(self, wind, body_velocity=(0.0, 0.0), yaw: float = 0.0, rho_air: float = AIR_DENSITY) -> np.ndarray:
        """The force (fx, fy) [N] and yaw moment [N m] in the global axes from the wind's velocity ``wind`` (..., 2)
        [m/s] and the body's horizontal velocity (..., 2) [m/s] at the body's yaw angle ``yaw`` [rad]:
        (..., 3)."""
        u = np.asarray(wind, float) - np.asarray(body_velocity, float)
        speed = np.hypot(u[..., 0], u[..., 1])
        direction = np.arctan2(u[..., 1], u[..., 0])
        c = self.at(direction - yaw)
        q = 0.5 * rho_air * speed ** 2
        cy, sy = math.cos(yaw), math.sin(yaw)
        fx_b, fy_b = q * c[..., 0], q * c[..., 1]
        return np.stack([cy * fx_b - sy * fy_b, sy * fx_b + cy * fy_b, q * c[..., 2]], axis=-1)

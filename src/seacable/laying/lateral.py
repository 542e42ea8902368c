"""The lateral response of a lay span: how the laid cable's path follows the ship's track.

A span in its steady lay (the ship at speed ``V`` along ``e_1``, the span in the vertical plane of ``e_1``) is
moved across by a small lateral displacement ``eta(s, t)`` of its material (``s`` arc length from the
touchdown, ``e_2`` across). Its tangent turns by ``eta_s`` across, and the lateral components of the forces
on an element, linearised about the steady span, are:

* the tension, ``d/ds (T eta_s)``;
* the normal drag ``k_n |u_n| u_n`` (``k_n = 1/2 rho C_dn d``): the steady normal flow ``u_n0`` lies in the
  span's plane, of speed ``|u_n0| = V sin(alpha)`` whatever the payout (``u_0 = -(V e_1 - V_c t)``), so the
  drag across is ``k_n |u_n0| u_n2`` with ``u_n2 = u_2 - (u_0 . t) t_2``. The material's own lateral velocity
  ``u_2 = -(eta_t - V_c eta_s)`` and the tilt of the tangent ``-(V_c - V cos(alpha)) eta_s`` add to
  ``-(eta_t - V cos(alpha) eta_s)``: the payout drops out, as it does from Zajac's straight line;
* the tangential drag ``f_t`` along the turned tangent, ``f_t eta_s``; with ``T' = w sin(alpha) - f_t``.

Quasi-static (the lateral inertia ``(m + m_a) D^2 eta / Dt^2`` left out: about 1 % of the drag at the
frequencies of an alter-course), the balance across is::

    T eta_ss + (w sin(alpha) + c V cos(alpha)) eta_s - c eta_t = 0,      c = k_n V sin(alpha).

At the ship ``eta = y_ship(t)``; at the touchdown the cable is tangent to the laid path ``Y(X)``, which it
joins as the touchdown moves on at ``V``: ``eta_s = cos(alpha_0) Y'`` with ``V Y' = eta_t``. For a
track ``y_ship = exp(i k X_ship)`` the span answers ``eta = f(s) exp(i k V t)`` with::

    T f'' + (w sin(alpha) + c V cos(alpha)) f' - i k V c f = 0,    f(L) = 1,    f'(0) = i k cos(alpha_0) f(0),

and the laid path is the track filtered by ``G(k) = f(0) exp(i k l)`` (``l`` the horizontal layback; the
touchdown lands ``l`` behind the ship). Without bottom tension ``T(0) = 0`` and the touchdown condition is the
equation itself at ``s = 0``. Checks of the model:

* A straight track at an angle is laid on itself (``G = 1 - g_2 k^2 + ...`` with no term in ``k``): exact for
  any steady span, since the horizontal balance of the span is the condition.
* On Zajac's straight span (``T = T' s``, ``alpha`` constant) the equation is Kummer's limit, and
  ``G(k) = exp(i k l) / 0F1(; b; i k L / D)`` with ``D = T' / (c V)`` and ``b = (w sin(alpha) + c V
  cos(alpha)) / (c V D)`` (``1 / sin^2(alpha)`` without tangential drag) (:func:`straight_span_transfer`). Its
  ``g_2 = l^2 sin^2(alpha) / (2 (1 + sin^2(alpha)))`` (without tangential drag) is the steady turn's cut per unit
  curvature: on a 300 m circle in 100 m of water at 1 m/s (paper 001's cable) ``g_2 / R = 11.38 m``, 11.34 m
  with its tangential drag, where the full steady span in the turning frame gives 11.38 m and the dynamic model
  11.37 m; on a 30 km circle the linear and the full steady turn agree to 0.3 % from 0.5 to 1 m/s and under
  200-500 N of bottom tension.

The laid path's offset from the route ``e = Y - y`` follows the route's curvature ``kappa = y''`` through
``e^(k) = (1 - G(k)) / k^2 kappa^(k)``, a kernel of area ``g_2``; :func:`spread_kernel` gives it normalised to
unit area, so that a planner can spread each change of heading over the span's transient and take the cut's
size from the full nonlinear steady turn. The kernel's length is the layback, and its shape depends on the
span alone (on the angle only, for Zajac's span): longer and flatter on a steep span, where the lateral
tension pulls the laid path across harder.

References
----------
.. [1] Zajac, E. E., 1957. Dynamics and kinematics of the laying and recovery of submarine cable.
   Bell System Technical Journal 36(5), 1129-1207.
.. [2] Paper 001 (seeds/001), section 2.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import hyp0f1

from .._jit import njit

__all__ = ["span_transfer", "spread_kernel", "straight_span_transfer"]

_MAX_ORDER = 150.0       # the largest 0F1 order b taken in closed form (b = 1 / sin^2(alpha): spans above 4.7 deg)
_STRAIGHT_NODES = 401    # the finite differences' samples of a flatter straight span (G to 2e-5)


def span_transfer(k, s, tension, sin_alpha, cos_alpha, *, speed, weight, kn, layback):
    """The laid path's response ``G(k)`` to a ship track ``exp(i k X)``, for a span given by its profile.

    Solves the lateral balance (module description) by second-order finite differences on the span's
    samples, for every wavenumber at once.

    Parameters
    ----------
    k : (nk,) array
        Wavenumbers along the track. [rad/m]
    s : (n,) array
        Arc length from the touchdown (0) to the ship, equally spaced. [m]
    tension, sin_alpha, cos_alpha : (n,) arrays
        The steady span's tension [N] and the sine and cosine of its angle to the horizontal there [-].
    speed : float
        Ship speed over the ground (still water). [m/s]
    weight : float
        Weight in water per length. [N/m]
    kn : float
        ``1/2 rho C_dn d``. [kg/m^2]
    layback : float
        Horizontal distance from the touchdown to the ship. [m]

    Returns
    -------
    (nk,) complex array
    """
    k = np.asarray(k, float)
    s = np.asarray(s, float)
    n = s.size
    h = s[1] - s[0]
    if n < 4 or not np.allclose(np.diff(s), h, rtol=1e-9, atol=0.0):
        raise ValueError("span_transfer needs four or more equally spaced samples of the span")
    c = kn * speed * np.asarray(sin_alpha, float)           # lateral drag per lateral speed [N s/m^2]
    drift = weight * np.asarray(sin_alpha, float) + c * speed * np.asarray(cos_alpha, float)   # [N/m]
    f0 = _touchdown_response(k, np.asarray(tension, float), drift, c, h, speed, float(cos_alpha[0]))
    return f0 * np.exp(1j * k * layback)


@njit(cache=True)
def _touchdown_response(k, tension, drift, c, h, speed, cos0):
    """``f(0)`` of ``T f'' + drift f' - i k V c f = 0``, ``f(L) = 1``, ``f'(0) = i k cos0 f(0)`` on equally spaced
    samples (central differences; the touchdown's condition one-sided to second order, its ``f_2`` eliminated
    with the first row), by the Thomas algorithm for each ``k``."""
    n = tension.size
    out = np.empty(k.size, np.complex128)
    cp = np.empty(n, np.complex128)
    dp = np.empty(n, np.complex128)
    for q in range(k.size):
        ik = 1j * k[q]
        # row 0: (-3 f0 + 4 f1 - f2) / 2h = i k cos0 f0, less m times row 1 to drop f2
        lo1 = tension[1] / h**2 - drift[1] / (2.0 * h)
        di1 = -2.0 * tension[1] / h**2 - ik * speed * c[1]
        up1 = tension[1] / h**2 + drift[1] / (2.0 * h)
        m = (-1.0 / (2.0 * h)) / up1
        b0 = -3.0 / (2.0 * h) - ik * cos0 - m * lo1
        c0 = 2.0 / h - m * di1
        cp[0] = c0 / b0
        dp[0] = 0.0
        for i in range(1, n - 1):
            a = tension[i] / h**2 - drift[i] / (2.0 * h)
            b = -2.0 * tension[i] / h**2 - ik * speed * c[i]
            cc = tension[i] / h**2 + drift[i] / (2.0 * h)
            inv = 1.0 / (b - a * cp[i - 1])
            cp[i] = cc * inv
            dp[i] = -a * dp[i - 1] * inv
        f = 1.0 + 0.0j                                     # f_{n-1}
        for i in range(n - 2, -1, -1):
            f = dp[i] - cp[i] * f
        out[q] = f
    return out


def straight_span_transfer(k, *, angle, suspended_length, speed, weight, kn, tension_gradient):
    """``G(k)`` of Zajac's straight span without bottom tension, in closed form (module description).

    Parameters
    ----------
    k : array
        Wavenumbers. [rad/m]
    angle : float
        The span's angle to the horizontal. [rad]
    suspended_length : float
        [m]
    speed : float
        [m/s]
    weight : float
        [N/m]
    kn : float
        [kg/m^2]
    tension_gradient : float
        ``T' = w sin(alpha) - f_t`` along the span. [N/m]

    Returns
    -------
    complex array
    """
    k = np.asarray(k, float)
    sa, ca = np.sin(angle), np.cos(angle)
    c = kn * speed * sa
    d = tension_gradient / (c * speed)
    b = (weight * sa + c * speed * ca) / (c * speed * d)
    if b > _MAX_ORDER:
        # scipy's 0F1 needs Gamma(b) (overflow past 171): the same balance by finite differences
        s = np.linspace(0.0, suspended_length, _STRAIGHT_NODES)
        return span_transfer(k, s, tension_gradient * s, np.full(s.size, sa), np.full(s.size, ca), speed=speed,
                             weight=weight, kn=kn, layback=suspended_length * ca)
    with np.errstate(over="ignore", invalid="ignore"):
        f = hyp0f1(b, 1j * k * suspended_length / d)       # grows as exp(2 sqrt(z)): past overflow, G = 0
        return np.where(np.isfinite(f), np.exp(1j * k * suspended_length * ca) / f, 0.0)


def spread_kernel(transfer, layback, *, extent=(-2.0, 20.0), samples=4096):
    """The unit-area kernel by which the route's curvature reaches the laid path's offset, and its integral.

    ``K(x)`` with ``x`` the touchdown's KP minus the KP of the curvature: the inverse Fourier transform of
    ``(1 - G(k)) / (g_2 k^2)``, ``g_2 = lim (1 - G(k)) / k^2`` (module description). It starts about 0.75
    laybacks before the curvature (when the ship reaches it) and has decayed to 1e-6 of its area 20 laybacks
    after it, for spans from 6 to 89 deg.

    Parameters
    ----------
    transfer : callable
        ``transfer(k)`` -> ``G(k)`` for an array of wavenumbers ``k >= 0`` (``G(-k)`` is its conjugate). [rad/m]
    layback : float
        The span's horizontal layback, the kernel's length scale. [m]
    extent : (float, float)
        The range of ``x`` kept, in laybacks; the transform's period is twice its length. [-]
    samples : int
        Points over the period (even).

    Returns
    -------
    x : (m,) array
        Equally spaced. [m]
    kernel : (m,) array
        ``K(x)``, of unit area. [1/m]
    integral : (m,) array
        ``int_-inf^x K``, from 0 to 1. [-]
    g2 : float
        The steady turn's cut per unit curvature in the linear theory (the cut is ``g2 / R``). [m^2]
    """
    period = 2.0 * (extent[1] - extent[0]) * layback
    dx = period / samples
    k = 2.0 * np.pi * np.fft.rfftfreq(samples, dx)
    # g_2 from two small wavenumbers (Richardson: the next term goes as k^2)
    k1 = 1e-3 / layback
    response = transfer(np.concatenate([[k1, 2.0 * k1], k[1:]]))
    e1, e2 = (1.0 - response[:2].real) / np.array([k1, 2.0 * k1]) ** 2
    g2 = (4.0 * e1 - e2) / 3.0
    # the spectrum falls as 1 / (g_2 k^2) (G vanishes faster than any power), a kink of K at x = 0: that part is
    # taken exactly, as exp(-a |x|) / (2 a g_2) of spectrum 1 / (g_2 (k^2 + a^2)), and the rest, falling as
    # k^-4, by the FFT; a = 1 / sqrt(g_2) gives the exact part unit area and the kernel's own width
    a = 1.0 / math.sqrt(g2)
    spectrum = np.full(k.size, 1.0 - 1.0 / (g2 * a * a), complex)
    spectrum[1:] = (1.0 - response[2:]) / (g2 * k[1:] ** 2) - 1.0 / (g2 * (k[1:] ** 2 + a * a))
    # the points kept, by index: x = j dx for j from ceil(extent_0 / du) to floor(extent_1 / du) (du = dx / l), the
    # same count whatever the layback
    du = dx / layback
    j = np.arange(math.ceil(extent[0] / du - 1e-9), math.floor(extent[1] / du + 1e-9) + 1)
    x = j * dx
    rest = (np.fft.irfft(spectrum, samples) / dx)[j % samples]    # at j dx (periodic)
    kernel = rest + np.exp(-a * np.abs(x)) / (2.0 * a * g2)
    # the integral from the first point (K = 0 before it: the turn is ahead of the ship): the exact part's in
    # closed form (a^2 g_2 = 1), the smooth rest's by the trapezoid rule
    exact = np.where(x < 0.0, 0.5 * np.exp(a * np.minimum(x, 0.0)), 1.0 - 0.5 * np.exp(-a * np.maximum(x, 0.0)))
    integral = exact - exact[0] + np.concatenate([[0.0], np.cumsum(0.5 * (rest[1:] + rest[:-1]) * dx)])
    return x, kernel, integral, g2

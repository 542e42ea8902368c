"""Natural frequencies of a vertical cable hanging under its own weight (Lee & Kim 1986, section 4).

A vertical cable of length L, fixed at both ends, with tension growing linearly
from the bottom, ``T(z) = T0 + w z`` (``z`` up from the lower end, ``w`` the weight
per length), vibrating laterally with inertia ``M = m + dm``:

.. math:: M \\ddot y = \\partial_z (T \\partial_z y).

Three estimates of its natural frequencies are offered (``method``):

``"wave"``
    Lee & Kim's eq. (14)-(15): the fundamental period is the round trip of a
    lateral wave, ``T1 = 2 tau``, with the one-way travel time

    .. math:: \\tau = \\int_0^L \\sqrt{\\frac{M}{T_0 + w z}}\\,dz
              = \\frac{2\\sqrt{M}}{w}\\left(\\sqrt{T_0 + wL} - \\sqrt{T_0}\\right),

    which with ``w = m g`` and ``v = sqrt(T0/m)`` is the printed eq. (15),
    ``T1 = 4 sqrt((m + dm)/m) (v/g) [sqrt(gL/v^2 + 1) - 1]`` (dimensions: ``v/g`` is
    a time, the bracket is a number). Higher modes ``omega_n = n pi / tau``.
    The paper writes the weight as ``m g``; physically the tension gradient is the
    weight *in water* (structural mass less buoyancy) while the inertia is
    ``m + dm``, so this module takes ``w`` separately (``weight_per_length``) and
    defaults to ``m g`` as in the paper (a cable in air).

``"exact"``
    With ``u = T0 + w z`` and ``r = 2 omega sqrt(M u) / w`` the equation becomes
    Bessel's equation of order zero, ``y'' + y'/r + y = 0``, so
    ``y = A J0(r) + B Y0(r)``. Fixed ends at ``r = a = 2 omega sqrt(M T0)/w`` and
    ``r = b = 2 omega sqrt(M (T0 + w L))/w`` give

    .. math:: J_0(a) Y_0(b) - J_0(b) Y_0(a) = 0, \\qquad b/a = \\sqrt{1 + wL/T_0}.

    Note ``b - a = omega tau``: the exact roots ``x_n = omega_n tau`` tend to
    ``n pi`` (the wave estimate) for nearly uniform tension (McMahon's expansion,
    Abramowitz & Stegun 9.5.28). With ``T0 = 0`` the lower end is free and
    ``J0(b) = 0``: the hanging chain of D. Bernoulli, ``omega_1 = (j01/2) sqrt(g/L)``
    with ``j01 = 2.4048``.

``"string"``
    Constant tension equal to the bottom tension ``T0`` (gravity neglected), row A
    of the paper's Table 1: ``T1 = 2 L sqrt(M/T0)`` (``= 2L/v`` when ``dm = 0``).
    The paper prints this as ``2L sqrt(g/T0)``, which is not a time in SI units;
    the tabulated numbers are ``2L/v``.

References
----------
.. [1] Lee, S.-M. and Kim, Y.-C. (1986). A simple technique to predict the natural
   frequencies of the sagged cable structures. Journal of the Society of Naval
   Architects of Korea, 23(3), section 4 and Table 1.
.. [2] Wolff, F. H. Dynamics of long vertical cables (cited by [1]; year unknown).
.. [3] Abramowitz, M. and Stegun, I. A. (1964). Handbook of Mathematical Functions,
   9.5.28 (zeros of cross products of Bessel functions).
"""

from __future__ import annotations

import math
from typing import Literal

import numpy as np
from scipy.special import j0, jn_zeros, y0

from .. import _validate
from ..errors import ConvergenceError, InputError
from .wave_speed import _check_n_modes, _mass_and_weight

__all__ = ["vertical_cable_period", "vertical_cable_frequencies", "travel_time"]

Method = Literal["wave", "exact", "string"]
_METHODS = ("wave", "exact", "string")

# Below this w L / T0 the three-term McMahon expansion of the cross-product roots is
# used instead of bracketing: its first neglected term is O((rho - 1)^6 / (n pi)^6),
# below 1e-20 relative here, while the Bessel functions of argument ~ 2 n pi / eps
# lose digits as eps -> 0.
_MCMAHON_EPS = 1e-3


def _inputs(length, bottom_tension, mass_per_length, added_mass_per_length, weight_per_length,
            gravity):
    L = _validate.positive("length", length, "m", "give the cable length in metres")
    T0 = _validate.nonnegative("bottom_tension", bottom_tension, "N",
                               "give the tension at the lower end in newtons (0 for a free end)")
    m, dm, g, w = _mass_and_weight(mass_per_length, added_mass_per_length, weight_per_length, gravity)
    L, T0, M, w = np.broadcast_arrays(np.asarray(L, float), np.asarray(T0, float),
                                      np.asarray(m, float) + dm, np.asarray(w, float))
    return L, T0, M, w


def travel_time(length, bottom_tension, mass_per_length, added_mass_per_length=0.0, *,
                weight_per_length=None, gravity=9.81):
    """One-way travel time of a lateral wave along a vertical cable (eq. 14 / 2).

    ``tau = 2 sqrt(M) L / (sqrt(T0 + w L) + sqrt(T0))``, the rationalised form of
    ``(2 sqrt(M)/w)(sqrt(T0 + w L) - sqrt(T0))`` that does not cancel when
    ``w L << T0``.

    Parameters
    ----------
    length : array_like
        Cable length L. [m]
    bottom_tension : array_like
        Tension T0 at the lower end (0 for a free hanging chain). [N]
    mass_per_length : array_like
        Structural mass per unit length m. [kg/m]
    added_mass_per_length : array_like, optional
        Transverse added mass per unit length dm. [kg/m]
    weight_per_length : array_like, optional
        Weight per unit length w that sets the tension gradient; ``None`` takes
        ``m g``. [N/m]
    gravity : float, optional
        Gravitational acceleration. [m/s^2]

    Returns
    -------
    tau : float or numpy.ndarray
        One-way travel time. [s]

    References
    ----------
    .. [1] Lee, S.-M. and Kim, Y.-C. (1986), eq. (14).
    """
    L, T0, M, w = _inputs(length, bottom_tension, mass_per_length, added_mass_per_length,
                          weight_per_length, gravity)
    tau = 2.0 * np.sqrt(M) * L / (np.sqrt(T0 + w * L) + np.sqrt(T0))
    return float(tau) if tau.ndim == 0 else tau


def _cross(x, rho_minus_1):
    """J0(a) Y0(b) - J0(b) Y0(a) with a = x/(rho-1), b = a + x."""
    a = x / rho_minus_1
    b = a + x
    return j0(a) * y0(b) - j0(b) * y0(a)


def _brentq(f, xa, xb, args=(), xtol=2e-12, rtol=8.881784197001252e-16, maxiter=100):
    """A root of ``f(x, *args)`` between ``xa`` and ``xb`` (of opposite signs): Brent's method as SciPy's
    ``scipy.optimize.brentq`` (its C code, ``scipy/optimize/Zeros/brentq.c``, step for step, so the same root
    to the bit: tests/unit/modal/test_vertical.py), without importing ``scipy.optimize`` (and with it
    ``scipy.linalg``: most of the time of ``seacable validate`` of a vertical cable).

    Raises
    ------
    ConvergenceError
        The ends do not bracket a root, ``f`` is NaN, or no root within ``maxiter`` iterations.
    """
    def call(x):
        fx = float(f(x, *args))
        if math.isnan(fx):
            raise ConvergenceError(f"the function is NaN at x = {x}: no root found", iterations=0)
        return fx

    xpre, xcur = float(xa), float(xb)
    xblk = fblk = spre = scur = 0.0
    fpre, fcur = call(xpre), call(xcur)
    if fpre == 0.0:
        return xpre
    if fcur == 0.0:
        return xcur
    if math.copysign(1.0, fpre) == math.copysign(1.0, fcur):
        raise ConvergenceError(f"f({xpre}) = {fpre} and f({xcur}) = {fcur} have the same sign: no root bracketed",
                               iterations=0, residual=min(abs(fpre), abs(fcur)))
    for _ in range(maxiter):
        if fpre != 0.0 and fcur != 0.0 and math.copysign(1.0, fpre) != math.copysign(1.0, fcur):
            xblk, fblk = xpre, fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = (xtol + rtol * abs(xcur)) / 2
        sbis = (xblk - xcur) / 2
        if fcur == 0.0 or abs(sbis) < delta:
            return xcur
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:  # interpolate
                stry = -fcur * (xcur - xpre) / (fcur - fpre)
            else:  # extrapolate
                dpre = (fpre - fcur) / (xpre - xcur)
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            if 2 * abs(stry) < min(abs(spre), 3 * abs(sbis) - delta):  # a good short step
                spre, scur = scur, stry
            else:  # bisect
                spre = scur = sbis
        else:  # bisect
            spre = scur = sbis
        xpre, fpre = xcur, fcur
        xcur += scur if abs(scur) > delta else (delta if sbis > 0 else -delta)
        fcur = call(xcur)
    raise ConvergenceError(f"no root within {maxiter} iterations of Brent's method (last x = {xcur})",
                           iterations=maxiter, residual=abs(fcur))


def _mcmahon(eps, n_modes):
    """Roots x_s = (rho - 1) a_s of the cross product, A&S 9.5.28 with nu = 0 (mu = 0)."""
    rho = np.sqrt(1.0 + eps)
    rm1 = eps / (rho + 1.0)
    s = np.arange(1, n_modes + 1, dtype=float)
    beta = s * np.pi / rm1
    p = -1.0 / (8.0 * rho)
    # q = 4 (mu-1)(mu-25)(rho^3-1) / (3 (8 rho)^3 (rho-1)), mu = 0; (rho^3-1)/(rho-1) = rho^2+rho+1
    q = 100.0 * (rho * rho + rho + 1.0) / (3.0 * (8.0 * rho) ** 3)
    a = beta + p / beta + (q - p * p) / beta ** 3
    return rm1 * a


def _exact_roots(eps: float, n_modes: int) -> np.ndarray:
    """First ``n_modes`` values of x = omega * tau for w L / T0 = eps (inf for T0 = 0)."""
    if np.isinf(eps):
        return jn_zeros(0, n_modes)
    if eps < _MCMAHON_EPS:
        return _mcmahon(eps, n_modes)
    rm1 = eps / (np.sqrt(1.0 + eps) + 1.0)
    step = np.pi / 64.0
    roots: list[float] = []
    x_lo = 1e-9
    f_lo = _cross(x_lo, rm1)
    x_max = (n_modes + 2) * np.pi
    while len(roots) < n_modes:
        x_hi = x_lo + step
        f_hi = _cross(x_hi, rm1)
        if f_lo == 0.0:
            roots.append(x_lo)
        elif f_lo * f_hi < 0.0:
            roots.append(_brentq(_cross, x_lo, x_hi, (rm1,), xtol=1e-14, rtol=1e-14))
        x_lo, f_lo = x_hi, f_hi
        if x_lo > x_max:
            # The roots satisfy (s - 1/4) pi < x_s <= s pi (between the free-end and the
            # uniform-string limits); failing to bracket them means a numerical breakdown.
            raise ConvergenceError(
                f"found {len(roots)} of {n_modes} roots of J0(a)Y0(b) - J0(b)Y0(a) = 0 for "
                f"w L / T0 = {eps:.6g} by x = {x_lo:.4g}. Suggested fix: report this case; "
                "use method='wave' meanwhile.", iterations=len(roots), residual=float(abs(f_lo)))
    return np.asarray(roots)


def vertical_cable_frequencies(length, bottom_tension, mass_per_length, added_mass_per_length=0.0,
                               method: Method = "exact", *, n_modes: int = 5, weight_per_length=None,
                               gravity=9.81):
    """Angular natural frequencies of a vertical cable fixed at both ends, ``n = 1 ... n_modes``.

    ``method="exact"``: Bessel-function solution, ``omega_n = x_n / tau`` with
    ``x_n`` the n-th root of ``J0(a)Y0(b) - J0(b)Y0(a) = 0`` in ``x = b - a``.
    ``method="wave"``: ``omega_n = n pi / tau`` (eq. 15 and "higher frequencies are
    n times omega_1"). ``method="string"``: ``omega_n = (n pi / L) sqrt(T0/M)``.
    Periods are ``2 pi / omega``.

    Parameters
    ----------
    length : array_like
        Cable length L. [m]
    bottom_tension : array_like
        Tension T0 at the lower end; 0 gives the hanging chain with a free lower
        end (not allowed for ``"string"``). [N]
    mass_per_length : array_like
        Structural mass per unit length m. [kg/m]
    added_mass_per_length : array_like, optional
        Transverse added mass per unit length dm. [kg/m]
    method : {"exact", "wave", "string"}, optional
        Which estimate (see the module docstring). [-]
    n_modes : int, optional
        Number of modes returned. [-]
    weight_per_length : array_like, optional
        Weight per unit length w setting the tension gradient (weight in water
        for a submerged cable); ``None`` takes ``m g`` as the paper does. [N/m]
    gravity : float, optional
        Gravitational acceleration. [m/s^2]

    Returns
    -------
    omega : numpy.ndarray
        Angular frequencies, shape ``(*broadcast_shape, n_modes)``. [rad/s]

    Raises
    ------
    InputError
        Non-positive length or mass, negative tension, NaN, unknown ``method``,
        ``n_modes < 1``, or ``bottom_tension = 0`` with ``method="string"``.
    ConvergenceError
        If the Bessel roots cannot be bracketed (not expected).

    References
    ----------
    .. [1] Lee, S.-M. and Kim, Y.-C. (1986), section 4 and Table 1.
    .. [2] Abramowitz, M. and Stegun, I. A. (1964), 9.5.28.
    """
    method = _validate.one_of("method", method, _METHODS)
    n_modes = _check_n_modes(n_modes)
    L, T0, M, w = _inputs(length, bottom_tension, mass_per_length, added_mass_per_length,
                          weight_per_length, gravity)
    n = np.arange(1, n_modes + 1, dtype=float)
    if method == "string":
        if np.any(T0 == 0.0):
            raise InputError("bottom_tension must be > 0 N for method='string', got 0 N. "
                             "Suggested fix: use method='exact' (the hanging chain) for a free "
                             "lower end.")
        return n * np.pi / (L * np.sqrt(M / T0))[..., None]
    tau = 2.0 * np.sqrt(M) * L / (np.sqrt(T0 + w * L) + np.sqrt(T0))
    if method == "wave":
        return n * np.pi / tau[..., None]
    with np.errstate(divide="ignore"):
        eps = np.where(T0 > 0.0, w * L / np.where(T0 > 0.0, T0, 1.0), np.inf)
    x = np.empty(eps.shape + (n_modes,))
    cache: dict[float, np.ndarray] = {}
    for idx in np.ndindex(eps.shape):
        key = float(eps[idx])
        if key not in cache:
            cache[key] = _exact_roots(key, n_modes)
        x[idx] = cache[key]
    return x / tau[..., None]


def vertical_cable_period(length, bottom_tension, mass_per_length, added_mass_per_length=0.0,
                          method: Method = "wave", *, weight_per_length=None, gravity=9.81):
    """Fundamental period of a vertical cable fixed at both ends (eq. 15; Table 1 rows A-C).

    ``method="wave"`` is Lee & Kim's eq. (15),
    ``T1 = 4 sqrt((m + dm)/m) (v/g) [sqrt(gL/v^2 + 1) - 1]`` with ``v = sqrt(T0/m)``
    (row C); ``"exact"`` the Bessel-function solution (row B); ``"string"`` the
    uniform string at the bottom tension, ``2 L sqrt((m + dm)/T0)`` (row A).
    The wave estimate is shorter than the exact period by up to about 5 % over
    the range of Table 1 (5.3 % at v = 6.1 m/s, L = 427 m); at ``T0 = 0`` it is
    ``4 sqrt(L/g)`` against the hanging chain's ``4 pi / j01 sqrt(L/g)``
    (-23 %).

    Parameters
    ----------
    length, bottom_tension, mass_per_length, added_mass_per_length, weight_per_length, gravity
        As in :func:`vertical_cable_frequencies`.
    method : {"wave", "exact", "string"}, optional
        Which estimate. [-]

    Returns
    -------
    T1 : float or numpy.ndarray
        Fundamental period, broadcast shape of the inputs. [s]

    Raises
    ------
    InputError
        As :func:`vertical_cable_frequencies`.

    References
    ----------
    .. [1] Lee, S.-M. and Kim, Y.-C. (1986), eq. (13)-(15) and Table 1.
    .. [2] Wolff, F. H. Dynamics of long vertical cables (cited by [1]).
    """
    omega = vertical_cable_frequencies(length, bottom_tension, mass_per_length, added_mass_per_length,
                                       method, n_modes=1, weight_per_length=weight_per_length,
                                       gravity=gravity)
    T1 = 2.0 * np.pi / omega[..., 0]
    return float(T1) if T1.ndim == 0 else T1

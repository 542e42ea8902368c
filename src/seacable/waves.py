"""Regular (Airy, linear) wave kinematics for the dynamic line models.

Coordinates: Z up, z = 0 at the still-water level, the seabed at z = -depth. A wave of height H
and period T travels towards ``heading`` b (radians from +X towards +Y) with the phase

    theta = k (x cos b + y sin b) - omega t + phase,        omega = 2 pi / T,

and the surface elevation eta = H/2 cos(theta). Linear (Airy) theory derives everything from the
velocity potential (Dean & Dalrymple [1]_ ch. 3, DNV-RP-C205 [2]_ table 3-1)

    phi = g H / (2 omega) cosh(k (z + d)) / cosh(k d) sin(theta),

whose free-surface conditions, linearised at z = 0, give the dispersion relation
omega^2 = g k tanh(k d) (:func:`wave_number`). The water particle velocity and acceleration at a
fixed point are

    u_h =  omega H/2 C(z) cos(theta),   a_h =  omega^2 H/2 C(z) sin(theta)   (along the heading),
    w   =  omega H/2 S(z) sin(theta),   a_z = -omega^2 H/2 S(z) cos(theta),

with C(z) = g k / omega^2 cosh(k (z + d)) / cosh(k d) and S(z) the same with sinh in the
numerator; under the dispersion relation C = cosh(k (z + d)) / sinh(k d). For k d > 20 the
hyperbolic ratios are evaluated in exponential form, so deep water (``depth = inf``) gives
C = S = exp(k z) and nothing overflows.

Linear theory is valid only below z = 0. Here the kinematics above the still-water level are
the z = 0 values held constant up to the instantaneous surface (constant extrapolation; Wheeler
stretching is an option of the mooring kernel, :func:`seacable.mooring.kernel._fluid`, through
:func:`airy_linear`), points above the surface (z > eta) get zero, and points below the seabed
(a node pressed into a soft seabed) get the seabed values. The accelerations are local
(d/dt at a fixed point); the convective terms are second order in H and dropped, consistently
with linear theory.

References
----------
.. [1] Dean, R. G. & Dalrymple, R. A., 1991. Water Wave Mechanics for Engineers and Scientists.
   World Scientific, ch. 3-4.
.. [2] DNV-RP-C205, 2021. Environmental conditions and environmental loads, section 3.2.
.. [3] Fenton, J. D. & McKee, W. D., 1990. On calculating the lengths of water waves.
   Coastal Engineering 14, 499-513.
.. [4] Miche, R., 1944. Mouvements ondulatoires de la mer en profondeur constante ou décroissante.
   Annales des Ponts et Chaussées 114.
.. [5] Hedges, T. S., 1995. Regions of validity of analytical wave theories. Proc. ICE Water,
   Maritime and Energy 112, 111-114.
.. [6] McCowan, J., 1894. On the highest wave of permanent type. Philosophical Magazine 38, 351-358
   (the depth-limited breaking height H_b = 0.78 d).
.. [7] Lighthill, J., 1978. Waves in Fluids. Cambridge University Press, section 3.2 (capillary-gravity
   waves: omega^2 = g k (1 + sigma k^2 / (rho g))).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from . import _validate as v
from .errors import ConvergenceError, InputError, SeacableWarning

if TYPE_CHECKING:
    from ._waves_kernel import airy_kinematics, airy_linear

__all__ = ["SeaStateCheck", "WaveKinematics", "airy_kinematics", "airy_kinematics_array", "airy_linear",
           "check_sea_state", "wave_number"]


def __getattr__(name: str):
    """The compiled kernels (:mod:`seacable._waves_kernel`), imported with numba when first asked for."""
    if name in ("airy_kinematics", "airy_linear"):
        from . import _waves_kernel

        return getattr(_waves_kernel, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | {"airy_kinematics", "airy_linear"})


STANDARD_GRAVITY = 9.80665
#: Ursell number H L^2 / d^3 above which linear theory is poor in shallow water (Hedges [5]_).
URSELL_LIMIT = 26.0
#: Limiting steepness H/L of a deep-water wave (Miche: 1/7 tanh(k d) in finite depth) [4]_.
BREAKING_STEEPNESS = 1.0 / 7.0
#: Depth-limited breaking: no wave higher than this fraction of the water depth (McCowan [6]_). [-]
BREAKING_DEPTH_RATIO = 0.78
#: Shortest wavelength of gravity-wave theory: below it surface tension changes omega^2 by more than 3 %
#: (sigma k^2 / (rho g) = 0.029 at 0.1 m for sea water, Lighthill [7]_), and the kinematics grid of an
#: irregular sea (a tenth of a wavelength apart) explodes. [m]
MIN_WAVELENGTH = 0.1
#: DNV-RP-C205 section 3.5.5's limits of the average steepness Sp = 2 pi Hs / (g Tp^2) of a sea state
#: "in the absence of other information": 1/15 for Tp <= 8 s, 1/25 for Tp >= 15 s, linear in between.
DNV_STEEPNESS = ((8.0, 1.0 / 15.0), (15.0, 1.0 / 25.0))

_MAX_NEWTON = 50
_NEWTON_RTOL = 1e-14


def _depth_array(depth):
    """Depth as a float array with +inf for deep water; raise on NaN, -inf or depth <= 0."""
    if depth is None:
        return np.asarray(np.inf)
    fix = "give the water depth in metres (> 0), or None / numpy.inf for deep water"
    d = np.asarray(v.finite("depth", depth, "m", fix) if not _numeric(depth) else depth, dtype=float)
    v.positive("depth", np.where(np.isposinf(d), 1.0, d), "m", fix)   # +inf is allowed: deep water
    return d


def _numeric(value) -> bool:
    try:
        np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return False
    return True


def wave_number(period, depth=None, gravity=STANDARD_GRAVITY):
    """Wave number of a linear (Airy) wave from the dispersion relation.

    Solves ``omega^2 = g k tanh(k d)`` with ``omega = 2 pi / T``: in the variable ``x = k d`` the
    equation ``x tanh x = omega^2 d / g`` is started from Fenton & McKee's explicit approximation
    (within 1.7 %, measured over 1e-4 < omega^2 d/g < 100) and refined by Newton's method to a relative step below 1e-14 (two to
    four iterations). ``depth`` of None or ``inf`` gives the deep-water value ``k = omega^2 / g``.

    Parameters
    ----------
    period : float or array_like
        Wave period T (> 0). [s]
    depth : float, array_like or None, optional
        Water depth d (> 0); None or ``numpy.inf`` for deep water. Broadcast against ``period``. [m]
    gravity : float, optional
        Acceleration of gravity g (> 0). [m/s^2]

    Returns
    -------
    float or numpy.ndarray
        Wave number k; a float when the inputs are scalars. [rad/m]

    Raises
    ------
    InputError
        If ``period`` or ``gravity`` is not a positive finite number or ``depth`` is not positive.
    ConvergenceError
        If Newton's method has not converged in 50 iterations (not expected for valid input).

    References
    ----------
    .. [1] Fenton, J. D. & McKee, W. D., 1990. On calculating the lengths of water waves.
       Coastal Engineering 14, 499-513.
    .. [2] Dean, R. G. & Dalrymple, R. A., 1991. Water Wave Mechanics for Engineers and
       Scientists. World Scientific, section 3.4.
    """
    T = v.positive("period", period, "s", "give the wave period in seconds")
    g = v.positive("gravity", gravity, "m/s^2", "use 9.80665 m/s^2")
    d = _depth_array(depth)
    T, d = np.broadcast_arrays(np.asarray(T, dtype=float), d)
    omega = 2.0 * np.pi / T
    k_deep = omega ** 2 / g
    deep = np.isinf(d)
    d_fin = np.where(deep, 1.0, d)
    y = k_deep * d_fin                                   # omega^2 d / g, deep-water k d
    with np.errstate(over="ignore"):
        x = y / np.tanh(y ** 0.75) ** (2.0 / 3.0)        # Fenton & McKee (1990)
    for iteration in range(1, _MAX_NEWTON + 1):
        t = np.tanh(x)
        q = np.exp(-2.0 * x)
        sech2 = 4.0 * q / (1.0 + q) ** 2                 # sech^2 x without overflow
        dx = (x * t - y) / (t + x * sech2)
        x = x - dx
        if np.all(np.abs(dx) <= _NEWTON_RTOL * x):
            break
    else:
        worst = float(np.max(np.abs(dx) / x))
        raise ConvergenceError(
            f"wave_number: Newton's method on omega^2 = g k tanh(k d) did not converge in "
            f"{_MAX_NEWTON} iterations (relative step {worst:.3g}). Suggested fix: check that "
            "period, depth and gravity are in s, m and m/s^2.",
            iterations=_MAX_NEWTON, residual=worst)
    k = np.where(deep, k_deep, x / d_fin)
    return k if k.ndim else float(k)


@dataclass(frozen=True)
class WaveKinematics:
    """Airy wave kinematics at a set of points (result of :func:`airy_kinematics_array`).

    Attributes
    ----------
    velocity : numpy.ndarray
        Water particle velocity (u, v, w), shape ``(..., 3)``. [m/s]
    acceleration : numpy.ndarray
        Local water particle acceleration (du/dt at a fixed point), shape ``(..., 3)``. [m/s^2]
    elevation : numpy.ndarray
        Surface elevation eta above the still-water level at each point's (x, y), shape ``(...)``. [m]
    wave_number : float
        Wave number k from the dispersion relation. [rad/m]
    """

    velocity: np.ndarray
    acceleration: np.ndarray
    elevation: np.ndarray
    wave_number: float

    @property
    def wavelength(self) -> float:
        """Wavelength L = 2 pi / k. [m]"""
        return 2.0 * math.pi / self.wave_number


def _scalar(name, value, unit):
    arr = np.asarray(value)
    if arr.ndim != 0:
        raise InputError(f"{name} must be a single number in {unit}, got an array of shape {arr.shape}. "
                         f"Suggested fix: call airy_kinematics_array once per wave.")
    return value


def airy_kinematics_array(x, y, z, t, *, height, period, depth, heading=0.0, phase=0.0,
                          gravity=STANDARD_GRAVITY):
    """Airy wave kinematics at many points and times (NumPy broadcasting over x, y, z, t).

    A checked, vectorised front end to :func:`airy_kinematics` (see it and the module docstring
    for the formulas and the treatment above z = 0). Warns (:class:`SeacableWarning`) when the
    wave is steeper than Miche's breaking limit H/L > tanh(k d)/7 (1/7 in deep water), or when
    the Ursell number H L^2 / d^3 exceeds 26, where linear theory is poor (use a cnoidal or
    stream-function wave).

    Parameters
    ----------
    x, y, z : array_like
        Positions, Z up from the still-water level; broadcast together with ``t``. [m]
    t : array_like
        Times. [s]
    height : float
        Wave height H (>= 0, crest to trough). [m]
    period : float
        Wave period T (> 0). [s]
    depth : float or None
        Water depth d (> 0); None or ``numpy.inf`` for deep water. [m]
    heading : float, optional
        Direction the wave travels towards, from +X towards +Y. [rad]
    phase : float, optional
        Phase of the elevation at x = y = t = 0. [rad]
    gravity : float, optional
        Acceleration of gravity g (> 0). [m/s^2]

    Returns
    -------
    WaveKinematics
        Velocity and acceleration of shape ``broadcast_shape + (3,)`` and elevation of shape
        ``broadcast_shape``.

    Raises
    ------
    InputError
        If an input is not finite, ``height < 0``, ``period <= 0``, ``depth <= 0``,
        ``gravity <= 0``, or a wave parameter is not a single number.

    References
    ----------
    .. [1] Dean, R. G. & Dalrymple, R. A., 1991. Water Wave Mechanics for Engineers and
       Scientists. World Scientific, ch. 3-4.
    .. [2] Miche, R., 1944. Mouvements ondulatoires de la mer en profondeur constante ou
       décroissante. Annales des Ponts et Chaussées 114.
    .. [3] Hedges, T. S., 1995. Regions of validity of analytical wave theories. Proc. ICE Water,
       Maritime and Energy 112, 111-114.
    """
    from ._waves_kernel import _airy_points

    H = float(v.nonnegative("height", _scalar("height", height, "m"), "m",
                            "give the crest-to-trough wave height in metres"))
    T = float(v.positive("period", _scalar("period", period, "s"), "s", "give the wave period in seconds"))
    g = float(v.positive("gravity", _scalar("gravity", gravity, "m/s^2"), "m/s^2", "use 9.80665 m/s^2"))
    d = float(_depth_array(_scalar("depth", depth, "m")))
    b = float(v.finite("heading", _scalar("heading", heading, "rad"), "rad"))
    p = float(v.finite("phase", _scalar("phase", phase, "rad"), "rad"))
    if abs(b) > 2.0 * math.pi:
        warnings.warn(f"heading = {b:g} rad looks like degrees ({math.radians(b):.4g} rad if it was "
                      f"meant as {b:g} deg). seacable takes angles in radians.", SeacableWarning,
                      stacklevel=2)
    arrays = []
    for name, val in (("x", x), ("y", y), ("z", z), ("t", t)):
        arrays.append(np.asarray(v.finite(name, val, "s" if name == "t" else "m"), dtype=float))
    k = wave_number(T, d, g)
    _check_wave_validity(H, k, d)
    xb, yb, zb, tb = np.broadcast_arrays(*arrays)
    shape = xb.shape
    n = xb.size
    vel, acc, eta = np.empty((n, 3)), np.empty((n, 3)), np.empty(n)
    _airy_points(np.ascontiguousarray(xb).ravel(), np.ascontiguousarray(yb).ravel(),
                 np.ascontiguousarray(zb).ravel(), np.ascontiguousarray(tb).ravel(),
                 H, T, k, d, b, p, g, vel, acc, eta)
    return WaveKinematics(velocity=vel.reshape(shape + (3,)), acceleration=acc.reshape(shape + (3,)),
                          elevation=eta.reshape(shape), wave_number=k)


def _check_wave_validity(height, k, depth):
    """Warn about breaking (Miche) and shallow-water (Ursell) waves where Airy theory is poor."""
    if height == 0.0:
        return
    L = 2.0 * math.pi / k
    steep = height / L
    limit = BREAKING_STEEPNESS * (1.0 if math.isinf(depth) else math.tanh(k * depth))
    if steep > limit:
        warnings.warn(f"wave steepness H/L = {steep:.4g} exceeds the breaking limit {limit:.4g} "
                      f"(Miche: tanh(k d)/7; H = {height:g} m, L = {L:.4g} m): the wave would break "
                      "and Airy kinematics are unreliable. Suggested fix: lower the height or "
                      "lengthen the period.", SeacableWarning, stacklevel=3)
    if not math.isinf(depth):
        ursell = height * L ** 2 / depth ** 3
        if ursell > URSELL_LIMIT:
            warnings.warn(f"Ursell number H L^2/d^3 = {ursell:.4g} exceeds {URSELL_LIMIT:g} "
                          f"(H = {height:g} m, L = {L:.4g} m, d = {depth:g} m): shallow-water wave "
                          "where linear (Airy) theory is poor. Suggested fix: use a cnoidal or "
                          "stream-function wave theory for these kinematics.",
                          SeacableWarning, stacklevel=3)


@dataclass(frozen=True)
class SeaStateCheck:
    """What :func:`check_sea_state` found: ``refused`` (physically impossible) and ``warned`` (suspicious)
    messages, each naming the keys."""

    refused: tuple[str, ...]
    warned: tuple[str, ...]


def check_sea_state(height, period, depth=None, gravity=STANDARD_GRAVITY, *, irregular=False,
                    height_key="waves.height", period_key="waves.period", how="") -> SeaStateCheck:
    """The one breaking and steepness check of a sea state, regular or irregular.

    A regular wave of height H and period T (an irregular sea: its significant height Hs and peak period Tp,
    whose wave stands for its largest waves) with the linear wavelength L (:func:`wave_number`) is

    - refused (physically impossible, no wave of permanent form exists): when ``L < MIN_WAVELENGTH`` (0.1 m:
      a capillary ripple, not a gravity wave, Lighthill [7]_), ``H > 0.78 d`` (depth-limited breaking,
      McCowan [6]_; DNV-RP-C205 3.2), or ``H / L > tanh(k d) / 7`` (Miche's limit of steepness [4]_; in deep
      water 1/7);
    - warned (suspicious) for an irregular sea whose average steepness ``Sp = 2 pi Hs / (g Tp^2)`` exceeds
      DNV-RP-C205 3.5.5's limits (1/15 for Tp <= 8 s to 1/25 for Tp >= 15 s, :data:`DNV_STEEPNESS`).

    Parameters
    ----------
    height, period : float
        H or Hs [m] and T or Tp [s].
    depth : float or None
        Water depth; None for deep water. [m]
    gravity : float
        [m/s^2]
    irregular : bool
        An irregular sea (Hs, Tp): the DNV steepness warning applies.
    height_key, period_key : str
        The keys (or a description of where the values come from) the messages name.
    how : str
        How the values were obtained (e.g. a table spectrum's Hs from its m0), added to each message.

    Returns
    -------
    SeaStateCheck
    """
    H, T, g = float(height), float(period), float(gravity)
    d = math.inf if depth is None else float(depth)
    refused, warned = [], []
    if not (T > 0 and g > 0 and math.isfinite(T)):
        return SeaStateCheck((), ())
    k = float(wave_number(T, d, g))
    L = 2.0 * math.pi / k
    h_sym, t_sym = ("Hs", "Tp") if irregular else ("H", "T")
    if L < MIN_WAVELENGTH:
        refused.append(f"{period_key} = {T:.6g} s gives a wavelength of {L:.3g} m, under {MIN_WAVELENGTH:g} m: "
                       "a capillary ripple whose dispersion surface tension governs, not a gravity wave (and "
                       "whose kinematics grid would explode). Suggested fix: give the "
                       f"{'peak ' if irregular else ''}period in seconds (ocean waves: 3-25 s).")
        return SeaStateCheck(tuple(refused), ())
    if H <= 0.0:
        return SeaStateCheck((), ())
    if math.isfinite(d) and H > BREAKING_DEPTH_RATIO * d:
        refused.append(f"{height_key} = {H:.6g} m{how} exceeds {BREAKING_DEPTH_RATIO:g} times the water depth "
                       f"{d:g} m ({BREAKING_DEPTH_RATIO * d:.4g} m): no wave that high exists in that depth "
                       "(depth-limited breaking, McCowan 1894; DNV-RP-C205 3.2). Suggested fix: check the "
                       f"{'significant ' if irregular else ''}wave height (m) and environment.depth (m).")
    limit = BREAKING_STEEPNESS * (1.0 if math.isinf(d) else math.tanh(k * d))
    if H / L > limit:
        refused.append(f"{height_key} = {H:.6g} m{how} with {period_key} = {T:.6g} s: steepness {h_sym}/L = "
                       f"{H / L:.4g} (L = {L:.4g} m, the linear wavelength at {t_sym}) exceeds the breaking limit "
                       f"{limit:.4g} (Miche: tanh(k d)/7; DNV-RP-C205 3.2): such a wave breaks. Suggested fix: "
                       f"lower {h_sym} or lengthen {t_sym} (a storm sea: Hs 10 m, Tp 14 s).")
    if irregular and not refused:
        (t1, s1), (t2, s2) = DNV_STEEPNESS
        s_lim = float(np.interp(T, (t1, t2), (s1, s2)))
        sp = 2.0 * math.pi * H / (g * T * T)
        if sp > s_lim:
            warned.append(f"{height_key} = {H:.6g} m{how} with {period_key} = {T:.6g} s: average steepness Sp = "
                          f"2 pi Hs/(g Tp^2) = {sp:.4g} exceeds DNV-RP-C205 3.5.5's limit 1/{1 / s_lim:.3g} at this "
                          "Tp (1/15 for Tp <= 8 s to 1/25 for Tp >= 15 s): a sea this steep is not observed. "
                          "Suggested fix: check Hs and Tp.")
    return SeaStateCheck(tuple(refused), tuple(warned))

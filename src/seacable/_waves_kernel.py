"""The compiled (numba) kernels of :mod:`seacable.waves`: Airy wave kinematics at one point.

:mod:`seacable.waves` gives them under their public names (:func:`seacable.waves.airy_kinematics`,
:func:`seacable.waves.airy_linear`); they live here so that the wave checks a case makes when it is
read do not import numba. The formulas and the treatment above z = 0 are in :mod:`seacable.waves`'
docstring.
"""

from __future__ import annotations

import math

from ._jit import njit

__all__ = ["airy_kinematics", "airy_linear"]

#: Above this k d the hyperbolic ratios are taken in exponential form (cosh would overflow at ~710).
_DEEP_KD = 20.0


@njit(cache=True)
def airy_kinematics(x, y, z, t, height, period, wave_number, depth, heading, phase, gravity):
    """Water particle velocity, acceleration and surface elevation of an Airy wave at one point.

    Compiled (numba) and scalar, for use inside the dynamic models' loops: no input checks (use
    :func:`airy_kinematics_array` or check the inputs once outside). ``wave_number`` must satisfy
    the dispersion relation with the same ``gravity`` (use :func:`wave_number`); otherwise the
    free-surface conditions do not hold. Points above the instantaneous surface (z > eta) get
    zero; between z = 0 and eta the z = 0 values (constant extrapolation, no Wheeler stretching);
    below the seabed (z < -depth) the seabed values.

    Parameters
    ----------
    x, y, z : float
        Position, Z up from the still-water level. [m]
    t : float
        Time. [s]
    height : float
        Wave height H (crest to trough). [m]
    period : float
        Wave period T. [s]
    wave_number : float
        Wave number k. [rad/m]
    depth : float
        Water depth d (> 0); ``numpy.inf`` for deep water. [m]
    heading : float
        Direction the wave travels towards, from +X towards +Y. [rad]
    phase : float
        Phase of the elevation at x = y = t = 0 (eta = H/2 cos(phase) there). [rad]
    gravity : float
        Acceleration of gravity g. [m/s^2]

    Returns
    -------
    tuple of 7 floats
        ``(u, v, w, ax, ay, az, eta)``: velocity [m/s], local acceleration [m/s^2] and
        surface elevation at (x, y) [m].

    References
    ----------
    .. [1] Dean, R. G. & Dalrymple, R. A., 1991. Water Wave Mechanics for Engineers and
       Scientists. World Scientific, ch. 3-4.
    .. [2] DNV-RP-C205, 2021. Environmental conditions and environmental loads, table 3-1.
    """
    omega = 2.0 * math.pi / period
    theta = wave_number * (x * math.cos(heading) + y * math.sin(heading)) - omega * t + phase
    eta = 0.5 * height * math.cos(theta)
    if z > eta:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, eta
    r = airy_linear(x, y, min(z, 0.0), t, height, period, wave_number, depth, heading, phase, gravity)
    return r[0], r[1], r[2], r[3], r[4], r[5], eta


@njit(cache=True)
def airy_linear(x, y, z, t, height, period, wave_number, depth, heading, phase, gravity):
    """Linear-theory (Airy) kinematics at depth ``z`` <= 0, with no cut at the instantaneous surface.

    As :func:`airy_kinematics` but ``z`` is taken as given (clamped to [-depth, 0]): the point where a
    stretching rule (Wheeler) maps a point of the wetted column. Returns ``(u, v, w, ax, ay, az)``
    [m/s], [m/s^2].
    """
    omega = 2.0 * math.pi / period
    cb = math.cos(heading)
    sb = math.sin(heading)
    theta = wave_number * (x * cb + y * sb) - omega * t + phase
    c = math.cos(theta)
    s = math.sin(theta)
    amp = 0.5 * height
    zz = min(z, 0.0)                      # constant extrapolation above the still-water level
    zz = max(zz, -depth)                       # below the seabed: seabed values
    kd = wave_number * depth
    if kd > _DEEP_KD:
        # cosh(k(z+d))/cosh(kd) = e^{kz} (1 + e^{-2k(z+d)}) / (1 + e^{-2kd}); sinh: minus sign
        e1 = math.exp(-2.0 * wave_number * (zz + depth))
        ez = math.exp(wave_number * zz) / (1.0 + math.exp(-2.0 * kd))
        ch = ez * (1.0 + e1)
        sh = ez * (1.0 - e1)
    else:
        ckd = math.cosh(kd)
        ch = math.cosh(wave_number * (zz + depth)) / ckd
        sh = math.sinh(wave_number * (zz + depth)) / ckd
    a = amp * gravity * wave_number / omega          # = omega H/2 coth(kd) under dispersion
    uh = a * ch * c
    w = a * sh * s
    ah = a * omega * ch * s
    az = -a * omega * sh * c
    return uh * cb, uh * sb, w, ah * cb, ah * sb, az


@njit(cache=True)
def _airy_points(x, y, z, t, height, period, k, depth, heading, phase, gravity, vel, acc, eta):
    for i in range(x.size):
        r = airy_kinematics(x[i], y[i], z[i], t[i], height, period, k, depth, heading, phase, gravity)
        vel[i, 0] = r[0]
        vel[i, 1] = r[1]
        vel[i, 2] = r[2]
        acc[i, 0] = r[3]
        acc[i, 1] = r[4]
        acc[i, 2] = r[5]
        eta[i] = r[6]

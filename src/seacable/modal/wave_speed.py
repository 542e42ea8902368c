"""Natural frequencies of sagged cables from the lateral wave speed (Lee & Kim 1986).

A lateral (transverse) wave runs along a cable at the local speed
``c(s) = sqrt(T(s) / (m + dm))``. Taking the fundamental period as the time the
wave needs to run from one support to the other and back,

.. math:: T_1 = 2 \\int_0^L \\frac{ds}{c(s)},

and putting the catenary ``s = H tan(phi) / w``, ``T = H sec(phi)`` into it gives
(Lee & Kim 1986, eq. 4-5, 9-10)

.. math:: T_1 = \\frac{2 \\sqrt{(m + \\Delta m) H}}{w} \\, [f(\\phi_0) \\pm f(\\phi_1)],
          \\qquad f(\\phi_0) = \\int_0^{\\phi_0} \\sec^{3/2}\\phi \\, d\\phi ,

with the sign ``+`` when the vertex (the point of zero slope) lies between the two
ends and ``-`` when both ends are on the same side of it. ``w`` is the weight per
length that shapes the catenary: the paper writes ``m g`` (a cable in air); for a
submerged cable it is the weight in water, while the inertia keeps ``m + dm``.

Derivation check of eq. (5): ``ds = H sec^2(phi) dphi / w`` and
``1/c = sqrt((m + dm) / (H sec phi))``, so ``ds/c = sqrt((m + dm) H) / w *
sec^{3/2}(phi) dphi``; the printed equations (4), (5), (9), (10) and (11) agree
with this once ``w = m g``.

The meaning of the mode number ``n`` (section 3 of the paper): out of plane
``omega_n = 2 pi n / T1`` (``n = 1, 2, ...``; the string harmonics); in plane
``omega_n = 2 pi (n + 1) / T1`` (``n = 1, 2, ...``): the lowest in-plane mode of a
sagged cable is antisymmetric and has the frequency of the *second* string
harmonic (Irvine 1981), so in-plane mode ``n`` is string harmonic ``n + 1`` and the
lowest in-plane frequency is twice the lowest out-of-plane one.

References
----------
.. [1] Lee, S.-M. and Kim, Y.-C. (1986). A simple technique to predict the natural
   frequencies of the sagged cable structures. Journal of the Society of Naval
   Architects of Korea, 23(3).
.. [2] Irvine, H. M. (1981). Cable Structures. MIT Press.
"""

from __future__ import annotations

from typing import Literal

import numpy as np
from scipy.special import ellipeinc, ellipkinc

from .. import _validate
from ..errors import InputError

__all__ = [
    "period_factor",
    "sagged_cable_period",
    "sagged_cable_frequencies",
    "suspended_cable_period",
    "mode_frequencies",
]

Plane = Literal["out", "in"]
Vertex = Literal["between", "outside"]

_HALF_PI = 0.5 * np.pi


def _mass_and_weight(mass_per_length, added_mass_per_length, weight_per_length, gravity):
    """Checked (m, added mass, g, w); w defaults to m g, the cable in air as in the paper."""
    m = _validate.positive("mass_per_length", mass_per_length, "kg/m",
                           "give the structural mass per metre of cable")
    dm = _validate.nonnegative("added_mass_per_length", added_mass_per_length, "kg/m",
                               "give 0 in air, or the transverse added mass per metre in water")
    g = _validate.positive("gravity", gravity, "m/s^2", "use 9.81 m/s^2")
    w = (np.asarray(m) * g if weight_per_length is None else
         _validate.positive("weight_per_length", weight_per_length, "N/m",
                            "give the weight per metre (in water for a submerged cable)"))
    return m, dm, g, w


def _check_n_modes(n_modes) -> int:
    if isinstance(n_modes, bool) or not isinstance(n_modes, (int, np.integer)) or n_modes < 1:
        raise InputError(f"n_modes must be an integer >= 1, got {n_modes!r}. "
                         "Suggested fix: ask for at least one mode, e.g. n_modes=5.")
    return int(n_modes)


def _angle(name: str, value, *, allow_zero: bool):
    """Check an end angle: in (0, pi/2) or [0, pi/2) [rad]; name degrees in the fix."""
    fix = ("give the angle from the horizontal in radians, strictly below pi/2 "
           "(use numpy.radians for degrees).")
    arr = np.asarray(_validate.finite(name, value, "rad", fix), dtype=float)
    if allow_zero:
        bad = (arr < 0.0) | (arr >= _HALF_PI)
        expected = "in [0, 1.5708) rad (0 <= angle < pi/2)"
    else:
        bad = (arr <= 0.0) | (arr >= _HALF_PI)
        expected = "in (0, 1.5708) rad (0 < angle < pi/2)"
    if bad.any():
        idx = tuple(int(i) for i in np.argwhere(bad)[0]) if arr.ndim else ()
        where = f"[{idx[0] if len(idx) == 1 else idx}]" if idx else ""
        raise InputError(f"{name}{where} must be {expected}, got {float(arr[idx]):.6g} rad. "
                         f"Suggested fix: {fix}")
    return arr


def _out(arr):
    arr = np.asarray(arr, dtype=float)
    return float(arr) if arr.ndim == 0 else arr


def period_factor(phi0):
    r"""Period factor ``f(phi0)``, the integral of ``sec^{3/2}`` (Lee & Kim 1986, eq. 6-8).

    .. math:: f(\phi_0) = \int_0^{\phi_0} \sec^{3/2}\phi\,d\phi
              = 2\tan\phi_0\sqrt{\cos\phi_0}
              + \sqrt{2}\,[F(\alpha, k) - 2E(\alpha, k)],
              \quad \alpha = \arccos\sqrt{\cos\phi_0},\ k = 1/\sqrt{2}

    ``F`` and ``E`` are the incomplete elliptic integrals of the first and second
    kind with modulus ``k``; scipy's ``ellipkinc``/``ellipeinc`` take the
    parameter ``m = k**2 = 1/2``. ``alpha`` is evaluated as
    ``arcsin(sqrt(2) sin(phi0/2))`` (the same angle, since ``sin^2 alpha =
    1 - cos phi0``), which keeps full precision at small angles. For small
    ``phi0``, ``f ~ phi0``; as ``phi0 -> pi/2``, ``f ~ 2 / sqrt(cos phi0)``.

    Parameters
    ----------
    phi0 : array_like
        Angle of the cable from the horizontal at the end, ``0 <= phi0 < pi/2``. [rad]

    Returns
    -------
    f : float or numpy.ndarray
        Period factor, same shape as ``phi0``. [-]

    Raises
    ------
    InputError
        If ``phi0`` is not finite or outside ``[0, pi/2)``.

    References
    ----------
    .. [1] Lee, S.-M. and Kim, Y.-C. (1986). A simple technique to predict the
       natural frequencies of the sagged cable structures. J. Soc. Naval
       Architects of Korea, 23(3), eq. (6)-(8).
    """
    phi = _angle("phi0", phi0, allow_zero=True)
    alpha = np.arcsin(np.sqrt(2.0) * np.sin(0.5 * phi))
    cos_phi = np.cos(phi)
    f = (2.0 * np.sin(phi) / np.sqrt(cos_phi)
         + np.sqrt(2.0) * (ellipkinc(alpha, 0.5) - 2.0 * ellipeinc(alpha, 0.5)))
    return _out(f)


def sagged_cable_period(horizontal_tension, mass_per_length, phi0, phi1=0.0, *,
                        added_mass_per_length=0.0, weight_per_length=None, gravity=9.81,
                        vertex: Vertex = "between"):
    r"""Fundamental period of a sagged (catenary) cable from the wave speed (eq. 5, 9, 10).

    .. math:: T_1 = \frac{2\sqrt{(m + \Delta m) H}}{w}\,[f(\phi_0) \pm f(\phi_1)]

    One-sided cable (from the vertex, e.g. a touchdown point, to an end at
    ``phi0``): leave ``phi1 = 0`` (eq. 5). Vertex between the supports, ends at
    ``phi0`` and ``phi1`` on either side (eq. 10): ``vertex="between"`` (sum).
    Both ends on the same side of the vertex, e.g. a mooring line meeting the
    seabed at ``phi1 > 0`` (eq. 9): ``vertex="outside"`` (difference).

    Parameters
    ----------
    horizontal_tension : array_like
        Horizontal component H of the static tension. [N]
    mass_per_length : array_like
        Structural mass per unit length m of the cable. [kg/m]
    phi0 : array_like
        Angle from the horizontal at one end, ``0 < phi0 < pi/2``. [rad]
    phi1 : array_like, optional
        Angle from the horizontal at the other end, ``0 <= phi1 < pi/2``; 0 for
        an end at the vertex. [rad]
    added_mass_per_length : array_like, optional
        Added (hydrodynamic) mass per unit length for transverse motion. [kg/m]
    weight_per_length : array_like, optional
        Weight per unit length w that shapes the catenary; ``None`` takes
        ``mass_per_length * gravity`` as in the paper (cable in air). For a
        submerged cable give the weight in water. [N/m]
    gravity : float, optional
        Gravitational acceleration g. [m/s^2]
    vertex : {"between", "outside"}, optional
        Where the point of zero slope lies relative to the two ends. [-]

    Returns
    -------
    T1 : float or numpy.ndarray
        Fundamental period, broadcast shape of the inputs. [s]

    Raises
    ------
    InputError
        Non-positive tension, mass or weight, negative added mass, angles out of
        range, NaN, an unknown ``vertex``, or ``vertex="outside"`` with
        ``phi0 == phi1`` (a cable of zero length).

    References
    ----------
    .. [1] Lee, S.-M. and Kim, Y.-C. (1986). A simple technique to predict the
       natural frequencies of the sagged cable structures. J. Soc. Naval
       Architects of Korea, 23(3), eq. (4)-(10).
    """
    vertex = _validate.one_of("vertex", vertex, ("between", "outside"))
    H = _validate.positive("horizontal_tension", horizontal_tension, "N",
                           "give the horizontal component of the static tension in newtons")
    m, dm, g, w = _mass_and_weight(mass_per_length, added_mass_per_length, weight_per_length, gravity)
    f0 = np.asarray(period_factor(_angle("phi0", phi0, allow_zero=False)))
    f1 = np.asarray(period_factor(_angle("phi1", phi1, allow_zero=True)))
    if vertex == "between":
        factor = f0 + f1
    else:
        factor = np.abs(f0 - f1)
        if np.any(factor == 0.0):
            raise InputError("phi0 and phi1 must differ when vertex='outside', got equal angles "
                             "(a cable of zero length). Suggested fix: use vertex='between' for "
                             "supports on either side of the lowest point.")
    T1 = 2.0 * np.sqrt((np.asarray(m) + dm) * H) / w * factor
    return _out(T1)


def mode_frequencies(fundamental_period, n_modes: int = 5, plane: Plane = "out"):
    """Angular natural frequencies from the fundamental wave period (section 3 of the paper).

    ``omega_n = 2 pi n / T1`` out of plane and ``omega_n = 2 pi (n + 1) / T1`` in
    plane, ``n = 1 ... n_modes``.

    Parameters
    ----------
    fundamental_period : array_like
        Round-trip wave period T1. [s]
    n_modes : int, optional
        Number of modes returned. [-]
    plane : {"out", "in"}, optional
        Out-of-plane (swinging) or in-plane modes. [-]

    Returns
    -------
    omega : numpy.ndarray
        Angular frequencies, shape ``(*T1.shape, n_modes)``. [rad/s]

    Raises
    ------
    InputError
        Non-positive period, ``n_modes < 1`` or an unknown ``plane``.

    References
    ----------
    .. [1] Lee, S.-M. and Kim, Y.-C. (1986), section 3.
    .. [2] Irvine, H. M. (1981). Cable Structures. MIT Press.
    """
    plane = _validate.one_of("plane", plane, ("out", "in"))
    n_modes = _check_n_modes(n_modes)
    T1 = np.asarray(_validate.positive("fundamental_period", fundamental_period, "s"))
    n = np.arange(1, n_modes + 1, dtype=float) + (1.0 if plane == "in" else 0.0)
    return 2.0 * np.pi * n / T1[..., None]


def sagged_cable_frequencies(horizontal_tension, mass_per_length, phi0, phi1=0.0, *,
                             n_modes: int = 5, plane: Plane = "out", added_mass_per_length=0.0,
                             weight_per_length=None, gravity=9.81, vertex: Vertex = "between"):
    """Angular natural frequencies of a sagged cable, ``n = 1 ... n_modes``.

    :func:`sagged_cable_period` followed by :func:`mode_frequencies`: out of
    plane ``omega_n = 2 pi n / T1``, in plane ``omega_n = 2 pi (n + 1) / T1``.
    The paper warns that the higher modes are less reliable (the dynamic tension
    of the in-plane modes changes the wave speed), as is the in-plane estimate of
    deeply sagged cables.

    Parameters
    ----------
    horizontal_tension, mass_per_length, phi0, phi1, added_mass_per_length, weight_per_length, gravity, vertex
        As in :func:`sagged_cable_period`.
    n_modes : int, optional
        Number of modes returned. [-]
    plane : {"out", "in"}, optional
        Out-of-plane or in-plane modes. [-]

    Returns
    -------
    omega : numpy.ndarray
        Angular frequencies, shape ``(*broadcast_shape, n_modes)``. [rad/s]

    References
    ----------
    .. [1] Lee, S.-M. and Kim, Y.-C. (1986), eq. (9)-(10) and section 3.
    """
    plane = _validate.one_of("plane", plane, ("out", "in"))
    n_modes = _check_n_modes(n_modes)
    T1 = sagged_cable_period(horizontal_tension, mass_per_length, phi0, phi1,
                             added_mass_per_length=added_mass_per_length,
                             weight_per_length=weight_per_length, gravity=gravity, vertex=vertex)
    return mode_frequencies(T1, n_modes, plane)


def suspended_cable_period(length, end_angle, mass_per_length, *, added_mass_per_length=0.0,
                           weight_per_length=None, gravity=9.81):
    r"""Fundamental period of a cable hung between supports at equal height (eq. 11).

    By symmetry the vertex is at mid-length and ``tan(phi0) = w L / (2 H)``
    (eq. 1), so ``H = w L / (2 tan phi0)`` and

    .. math:: T_1 = \frac{4\sqrt{(m + \Delta m) H}}{w} f(\phi_0)
              \;\xrightarrow{\Delta m = 0,\ w = m g}\; \frac{4}{g}\sqrt{\frac{H}{m}} f(\phi_0).

    Limits. Small sag: ``f ~ phi0`` and ``T1 -> 2 L sqrt((m + dm)/H)``, the taut
    string (eq. 12). Near-vertical ends (``phi0 -> pi/2``): ``f sqrt(cos phi0) -> 2``
    so ``T1 -> 8 sqrt((m + dm) L / (2 w))``; with ``w = m g`` the out-of-plane
    fundamental is ``(pi/4) sqrt(2g/L) = 0.785 sqrt(2g/L)`` and the in-plane one
    ``(pi/2) sqrt(2g/L) = 1.571 sqrt(2g/L)``, the paper's "about 1.6". The exact
    limit, two hanging chains of length L/2, is ``(j01/2) sqrt(2g/L) =
    1.2024 sqrt(2g/L)`` for both planes.

    Parameters
    ----------
    length : array_like
        Total cable length L between the supports. [m]
    end_angle : array_like
        Angle from the horizontal at both supports, ``0 < phi0 < pi/2``. [rad]
    mass_per_length : array_like
        Structural mass per unit length m. [kg/m]
    added_mass_per_length : array_like, optional
        Transverse added mass per unit length. [kg/m]
    weight_per_length : array_like, optional
        Weight per unit length w; ``None`` takes ``m g``. [N/m]
    gravity : float, optional
        Gravitational acceleration. [m/s^2]

    Returns
    -------
    T1 : float or numpy.ndarray
        Fundamental period. [s]

    Raises
    ------
    InputError
        Non-positive length, mass or weight, angle outside ``(0, pi/2)``, NaN.

    References
    ----------
    .. [1] Lee, S.-M. and Kim, Y.-C. (1986), eq. (11)-(12) and section 5.
    .. [2] Goodey, W. J. (1961). On the natural modes and frequencies of a
       suspended chain. Q. J. Mech. Appl. Math. 14.
    """
    L = _validate.positive("length", length, "m", "give the cable length between supports in metres")
    m, _, g, w = _mass_and_weight(mass_per_length, 0.0, weight_per_length, gravity)
    phi = _angle("end_angle", end_angle, allow_zero=False)
    H = w * np.asarray(L) / (2.0 * np.tan(phi))
    return sagged_cable_period(H, m, phi, phi, added_mass_per_length=added_mass_per_length,
                               weight_per_length=w, gravity=g, vertex="between")

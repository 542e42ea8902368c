"""Straight-line theory of cable laying (paper 001, section 2; Zajac 1957, Richardson 1974).

A cable paid out at speed ``V_c`` from a ship moving at constant speed ``V_s`` over a flat seabed
reaches a steady state in which, with zero tension at the touchdown point, it lies straight from
the ship to the seabed at the angle ``alpha`` to the horizontal where the weight's normal
component balances the normal drag (paper 001 eq. (1), (3), (5), (7))::

    w cos(alpha) = 1/2 C_D rho d V_s^2 sin^2(alpha).

Derivation of the relative velocities (ship moving in +x, cable descending astern along
``b = (-cos(alpha), -sin(alpha))``): a material point of the cable moves with the ship plus the
payout along the cable, ``v = (V_s, 0) + V_c b``. Its normal component is ``-V_s sin(alpha)``
(payout does not enter, eq. (5)) and its component along ``b`` is ``V_f = V_c - V_s cos(alpha)``
(eq. (6)). The tangential drag ``D_T = 1/2 C_f rho pi d V_f |V_f|`` (eq. (4)) opposes that
motion, i.e. it pulls the cable towards the ship when ``V_c > V_s cos(alpha)``, so the balance
along the suspended length ``L = h / sin(alpha)`` gives the ship tension (eq. (2), (11))::

    T_s = T_0 + w L sin(alpha) - D_T L = T_0 + w h - D_T h / sin(alpha).

With ``D_T`` neglected this is ``T_s = w h`` (eq. (10)) and ``T_0 + w h`` (eq. (11)). With zero
bottom tension the straight line is exact (the normal balance does not involve ``T``); with
``T_0 > 0`` the suspended shape is no longer straight and eq. (11) is the paper's approximation.

References
----------
.. [1] Paper 001 (seeds/001_24abb5c08bf41930.txt), section 2, eq. (1)-(11); section 4.1, Table 1.
.. [2] Zajac, E. E., 1957. Dynamics and kinematics of the laying and recovery of submarine cable.
   Bell System Technical Journal 36(5), 1129-1207.
.. [3] Richardson, M. J., 1974. Mechanics of the laying of submarine cables. Bell Labs.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import Literal

import numpy as np

from .. import _validate as v
from ..errors import NoSolutionError, SeacableWarning
from .towed import _critical_cos

__all__ = ["LayingAngleMethod", "StraightLineLay", "hydrodynamic_constant", "laying_angle",
           "cable_slack", "straight_line_lay"]

LayingAngleMethod = Literal["exact", "small_angle"]
"""``"exact"``: root of paper 001 eq. (7); ``"small_angle"``: ``alpha = H / V_s``, eq. (9)."""

_METHODS = ("exact", "small_angle")
_SMALL_ANGLE_LIMIT = np.radians(30.0)   # paper 001 after eq. (8): valid below about 30 degrees

_FIX_W = "give the weight in water (positive for a cable that sinks)"
_FIX_D = "give the outer diameter in metres"
_FIX_CD = "use a normal drag coefficient such as 1.2-2.0"
_FIX_RHO = "sea water is about 1025 kg/m^3"


def _out(a):
    a = np.asarray(a, dtype=float)
    return a if a.ndim else float(a)


def hydrodynamic_constant(weight_per_length, diameter, drag_normal, water_density=1025.0):
    """Hydrodynamic constant ``H = (2 w / (C_D rho d))^1/2`` of a cable (paper 001 eq. (8)).

    ``H / V_s`` is the small-angle laying (critical) angle in radians at ship speed ``V_s``.

    Parameters
    ----------
    weight_per_length : array_like
        Weight in water per unit length, positive. [N/m]
    diameter : array_like
        Outer diameter. [m]
    drag_normal : array_like
        Normal drag coefficient C_D. [-]
    water_density : array_like, optional
        Density of sea water. [kg/m^3]

    Returns
    -------
    numpy.ndarray or float
        Hydrodynamic constant. [m/s rad]

    Raises
    ------
    InputError
        If an input is not > 0.

    References
    ----------
    .. [1] Paper 001, eq. (8)-(9); the text of section 4.1 swaps two numbers, the constant for
       the validation cable is H = 0.4577 m/s rad (see SPEC.md).
    """
    w = v.positive("weight_per_length", weight_per_length, "N/m", _FIX_W)
    d = v.positive("diameter", diameter, "m", _FIX_D)
    cd = v.positive("drag_normal", drag_normal, "", _FIX_CD)
    rho = v.positive("water_density", water_density, "kg/m^3", _FIX_RHO)
    return _out(np.sqrt(2.0 * np.asarray(w) / (cd * rho * d)))


def laying_angle(ship_speed, weight_per_length, diameter, drag_normal, water_density=1025.0,
                 method: LayingAngleMethod = "exact"):
    """Angle of a straight laid cable to the horizontal (paper 001 eq. (7) and (9)).

    Parameters
    ----------
    ship_speed : array_like
        Ship speed through the water V_s (>= 0 for ``"exact"``, > 0 for ``"small_angle"``). [m/s]
    weight_per_length : array_like
        Weight in water per unit length, positive. [N/m]
    diameter : array_like
        Outer diameter. [m]
    drag_normal : array_like
        Normal drag coefficient C_D. [-]
    water_density : array_like, optional
        Density of sea water. [kg/m^3]
    method : {"exact", "small_angle"}, optional
        ``"exact"``: the root of ``w cos(alpha) = 1/2 C_D rho d V_s^2 sin^2(alpha)``, in closed
        form ``cos(alpha) = 2q / (w + sqrt(w^2 + 4 q^2))`` with ``q = 1/2 C_D rho d V_s^2``;
        ``"small_angle"``: ``alpha = H / V_s`` (eq. (9)). [-]

    Returns
    -------
    numpy.ndarray or float
        Angle to the horizontal. [rad]

    Raises
    ------
    InputError
        If an input is out of range or ``method`` is unknown.

    Warns
    -----
    SeacableWarning
        For ``"small_angle"`` when the result exceeds 30 degrees, where the paper states the
        approximation no longer holds (above pi/2 it has no geometric meaning).

    References
    ----------
    .. [1] Paper 001, eq. (7)-(9), Table 1.
    """
    v.one_of("method", method, _METHODS)
    if method == "small_angle":
        vs = v.positive("ship_speed", ship_speed, "m/s",
                        "the small-angle formula needs a moving ship; use method='exact'")
        alpha = hydrodynamic_constant(weight_per_length, diameter, drag_normal, water_density) / vs
        if np.any(np.asarray(alpha) > _SMALL_ANGLE_LIMIT):
            warnings.warn(f"small-angle laying angle up to {np.degrees(np.max(alpha)):.4g} deg "
                          "exceeds 30 deg, outside the validity of alpha = H/V_s; use method='exact'.",
                          SeacableWarning, stacklevel=2)
        return _out(alpha)
    vs = v.nonnegative("ship_speed", ship_speed, "m/s", "give the ship speed through the water")
    w = v.positive("weight_per_length", weight_per_length, "N/m", _FIX_W)
    d = v.positive("diameter", diameter, "m", _FIX_D)
    cd = v.positive("drag_normal", drag_normal, "", _FIX_CD)
    rho = v.positive("water_density", water_density, "kg/m^3", _FIX_RHO)
    q = 0.5 * cd * rho * d * np.asarray(vs) ** 2
    return _out(np.arccos(np.clip(_critical_cos(w, q), 0.0, 1.0)))


def cable_slack(payout_speed, ship_speed):
    """Slack of a laid cable, ``V_c / V_s - 1`` (paper 001 section 2).

    Parameters
    ----------
    payout_speed : array_like
        Cable payout speed V_c. [m/s]
    ship_speed : array_like
        Ship speed V_s, > 0. [m/s]

    Returns
    -------
    numpy.ndarray or float
        Slack: fraction of cable paid out beyond the distance run. [-]

    Raises
    ------
    InputError
        If ``payout_speed < 0`` or ``ship_speed <= 0``.
    """
    vc = v.nonnegative("payout_speed", payout_speed, "m/s", "give the payout speed of the cable engine")
    vs = v.positive("ship_speed", ship_speed, "m/s", "slack is undefined for a ship at rest")
    return _out(np.asarray(vc) / vs - 1.0)


@dataclass(frozen=True)
class StraightLineLay:
    """Straight-line laying solution (result of :func:`straight_line_lay`).

    Attributes
    ----------
    angle : numpy.ndarray or float
        Angle of the cable to the horizontal. [rad]
    layback : numpy.ndarray or float
        Horizontal distance from the ship (water entry) to the touchdown point. [m]
    suspended_length : numpy.ndarray or float
        Length of cable between the water entry and the touchdown point. [m]
    top_tension : numpy.ndarray or float
        Tension at the ship, ``T_0 + w h - D_T L``. [N]
    tangential_drag : numpy.ndarray or float
        Tangential drag per unit length ``D_T`` (positive towards the ship). [N/m]
    relative_tangential_speed : numpy.ndarray or float
        ``V_f = V_c - V_s cos(alpha)``, cable speed along itself relative to the water. [m/s]
    slack : numpy.ndarray or float
        ``V_c / V_s - 1``. [-]
    """

    angle: np.ndarray
    layback: np.ndarray
    suspended_length: np.ndarray
    top_tension: np.ndarray
    tangential_drag: np.ndarray
    relative_tangential_speed: np.ndarray
    slack: np.ndarray


def straight_line_lay(water_depth, ship_speed, weight_per_length, diameter, drag_normal,
                      drag_tangential=0.0, *, payout_speed=None, bottom_tension=0.0,
                      water_density=1025.0, method: LayingAngleMethod = "exact") -> StraightLineLay:
    """Straight-line laying theory: angle, layback, suspended length and ship tension.

    Vectorised: all numeric arguments broadcast against each other.

    Parameters
    ----------
    water_depth : array_like
        Water depth at the touchdown point h. [m]
    ship_speed : array_like
        Ship speed through the water V_s, > 0. [m/s]
    weight_per_length : array_like
        Weight in water per unit length, positive. [N/m]
    diameter : array_like
        Outer diameter. [m]
    drag_normal : array_like
        Normal drag coefficient C_D. [-]
    drag_tangential : array_like, optional
        Tangential (skin-friction) drag coefficient C_f, referred to the perimeter pi d
        (eq. (4)); 0 neglects the tangential drag. [-]
    payout_speed : array_like or None, optional
        Cable payout speed V_c; ``None`` means equal to the ship speed (zero slack). [m/s]
    bottom_tension : array_like, optional
        Tension at the touchdown point T_0 (eq. (11)); with ``T_0 > 0`` the result is the
        paper's approximation. [N]
    water_density : array_like, optional
        Density of sea water. [kg/m^3]
    method : {"exact", "small_angle"}, optional
        How the angle is computed, see :func:`laying_angle`. [-]

    Returns
    -------
    StraightLineLay
        Fields broadcast to the common shape of the inputs (floats for scalar inputs).

    Raises
    ------
    InputError
        If an input is out of range.
    NoSolutionError
        If the tangential drag exceeds the weight component along the cable so that the ship
        tension would be negative (the cable cannot hang straight: payout too fast).

    References
    ----------
    .. [1] Paper 001, section 2, eq. (1)-(11).
    """
    h = v.positive("water_depth", water_depth, "m", "give the depth at touchdown in metres")
    vs = v.positive("ship_speed", ship_speed, "m/s", "give the ship speed through the water")
    w = v.positive("weight_per_length", weight_per_length, "N/m", _FIX_W)
    d = v.positive("diameter", diameter, "m", _FIX_D)
    cf = v.nonnegative("drag_tangential", drag_tangential, "",
                       "use a tangential drag coefficient such as 0.005-0.02, or 0 to neglect it")
    vc = vs if payout_speed is None else v.nonnegative(
        "payout_speed", payout_speed, "m/s", "give the payout speed of the cable engine")
    t0 = v.nonnegative("bottom_tension", bottom_tension, "N", "give the touchdown tension, 0 for slack lay")
    rho = v.positive("water_density", water_density, "kg/m^3", _FIX_RHO)
    alpha = np.asarray(laying_angle(vs, w, d, drag_normal, rho, method=method))
    if method == "small_angle" and np.any(alpha >= np.pi / 2):
        raise NoSolutionError(f"small-angle laying angle H/V_s = {np.degrees(np.max(alpha)):.6g} deg is not "
                              "below 90 deg, so no straight cable exists. Suggested fix: use method='exact'.")
    sin_a, cos_a = np.sin(alpha), np.cos(alpha)
    length = h / sin_a
    layback = h * cos_a / sin_a
    vf = np.asarray(vc) - np.asarray(vs) * cos_a
    d_t = 0.5 * cf * rho * np.pi * d * vf * np.abs(vf)
    top = t0 + w * h - d_t * length
    if np.any(top < 0.0):
        i = np.unravel_index(int(np.argmax(np.ravel(top < 0.0))), np.shape(top))
        raise NoSolutionError(
            f"the tangential drag {np.asarray(d_t)[i]:.6g} N/m exceeds the weight component along the cable "
            f"({np.broadcast_to(w * sin_a, np.shape(top))[i]:.6g} N/m): the ship tension would be "
            f"{np.asarray(top)[i]:.6g} N. Suggested fix: reduce the payout speed (slack) or check C_f.")
    slack = np.asarray(vc) / vs - 1.0
    shape = np.broadcast(alpha, h, w, t0, vf, d_t).shape
    b = [np.broadcast_to(np.asarray(a, dtype=float), shape).copy()
         for a in (alpha, layback, length, top, d_t, vf, slack)]
    return StraightLineLay(*[x if x.ndim else float(x) for x in b])

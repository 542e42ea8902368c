"""The towed barge of the towline simulator: a rigid drag body in surge, sway and yaw.

Paper 003 tows "a simple drag body": a box barge (L_pp 50 m, beam 15 m, draft 0.5 m,
block coefficient 0.9, yaw radius of gyration 0.25 L) at its bow. This module gives
its inertia, its hull forces and its 3-DOF equations of motion in the horizontal
plane, as plain (vectorised) functions of a :class:`Barge` (whose inputs are in
:mod:`seacable.towline.barge_model`, so that reading a case does not import numba), and
the same in a flat float array with an ``@njit`` function for the compiled towline kernel.

Frame: the barge frame has its origin at midship on the waterline, x forward, y to
port, z up (so that with heading psi measured from global +X towards +Y, the usual
seacable convention, yaw rate ``r`` is positive counter-clockwise seen from above).
``u, v`` are the surge and sway velocities of the origin relative to the water, in
the barge frame. The centre of gravity is at the origin.

Equations (Fossen 2011, ch. 6-7, the 3-DOF manoeuvring model M nu' + C_RB(nu) nu + C_A(nu) nu = tau with
M = diag(M11, M22, M66), M11 = m + m11, M22 = m + m22, M66 = I_zz + m66)::

    M11 du/dt - M22 v r          = X
    M22 dv/dt + M11 u r          = Y
    M66 dr/dt + (m22 - m11) u v  = N

The yaw line carries the Munk moment ``-(m22 - m11) u v`` on the right-hand side.
(The task brief printed ``- (m22 - m11) u v`` on the left; that sign does not conserve
the kinetic energy ``T = (M11 u^2 + M22 v^2 + M66 r^2)/2``: with the signs above,
``dT/dt = u (M22 v r) + v (-M11 u r) + r (-(M22 - M11) u v) = 0``, since
M22 - M11 = m22 - m11; the test suite checks this by integration.)

Hull forces (X, Y, N), with ``w(x) = v + r x`` the cross-flow velocity of the strip at x::

    X = -1/2 rho C_x B T |u| u
    Y = -1/2 rho C_y T  int_{-L/2}^{L/2} |w| w dx  -  |u| m'_T w(x_T)
    N = -1/2 rho C_y T  int_{-L/2}^{L/2} x |w| w dx  -  x_T |u| m'_T w(x_T)

The last terms are the hull's lift by slender-body theory (Newman 1977, sec. 7.9): the sections
pass aft at the speed ``|u|``, each carrying the lateral momentum ``m' w`` of its added mass, and
the flow separating at the trailing edge ``x_T = -sign(u) L/2`` (the square stern when going ahead)
sheds that momentum into the wake. Integrating the sectional force ``|u| d(m' w)/dx`` along the hull
gives the Munk moment ``-m22 u v`` (in the equations below) plus the force ``-|u| m'_T w(x_T)`` at
the trailing edge, with ``m'_T = m22 / L`` for uniform sections. It is the linear part of the hull's
sway and yaw damping, proportional to the speed: ``Y_v = -|u| m22 / L``, ``N_r = -|u| m22 L / 4``, and
a weathervane moment ``m22 u v / 2`` about midship against the Munk moment ``(m22 - m11) u v`` (1.27
times larger for paper 003's barge, so the free hull is still directionally unstable and the towline
at the bow holds it). Without the lift the hull damps sway and yaw only quadratically, through the
cross-flow drag, and the towed barge wanders in yaw instead of settling to the tug's rhythm.

integrated with the midpoint rule over ``n_strips`` strips (exact for r = 0, second
order in the strip width otherwise; for pure yaw the relative error is
``2 / n_strips^2``, 0.5 % at the default 20 strips). In closed form, with w1 = v - rL/2, w2 = v + rL/2,
``int |w| w dx = (|w2|^3 - |w1|^3) / (3 r)`` and
``int x |w| w dx = [w^3 |w| / 4 - v |w|^3 / 3]_{w1}^{w2} / r^2``; for v = 0,
``N = -rho C_y T |r| r L^4 / 64``.

References
----------
.. [1] Yoon, H. K., Lee, H. S., Park, J. K. and Kim, Y. K. (2011), "Modeling and
   simulation of towline dynamics using multibody element theory", KINPR (paper 003
   of ``shared/seeds``): the barge's particulars.
.. [2] Fossen, T. I. (2011), *Handbook of Marine Craft Hydrodynamics and Motion
   Control*, Wiley: the 3-DOF manoeuvring model with added-mass Coriolis terms, and
   the cross-flow drag strip integrals (also in Fossen's Python Vehicle Simulator,
   ``crossFlowDrag``).
.. [3] Söding, H. (1982), "Prediction of ship steering capabilities",
   Schiffstechnik 29, 3-29: surge added mass ``2.7 rho V^(5/3) / L^2``.
.. [7] Newman, J. N. (1977), *Marine Hydrodynamics*, MIT Press, sec. 7.9: slender-body
   theory of the lateral force and moment, with the lift shed at the trailing edge.
.. [4] DNV-RP-C205 (2010), *Environmental conditions and environmental loads*,
   App. A, Table A-1: two-dimensional added mass of a rectangle.
.. [5] Hoerner, S. F. (1965), *Fluid-Dynamic Drag*, ch. 3 (blunt bodies in axial
   flow); Leite, A. J. P. et al. (1998), Applied Ocean Research 20, 145-156, the
   cross-flow drag curve of ship sections used by Fossen (``Hoerner(B, T)``).
.. [6] ITTC (1957): the model-ship correlation line ``C_F = 0.075 / (log10 Re - 2)^2``.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .._jit import njit
from .._validate import at_least, finite, positive
from ..errors import InputError
from .barge_model import Barge

__all__ = [
    "B_BEAM",
    "B_CX",
    "B_CY",
    "B_DRAFT",
    "B_LENGTH",
    "B_LIFT",
    "B_M11",
    "B_M22",
    "B_M66",
    "B_MASS",
    "B_N_STRIPS",
    "B_RHO",
    "B_SIZE",
    "B_TOW_X",
    "B_TOW_Z",
    "B_XUU",
    "B_YCF",
    "Barge",
    "barge_accelerations",
    "barge_equations",
    "barge_hull_forces",
    "barge_hull_forces_flat",
    "barge_mass",
    "barge_parameters",
    "barge_resistance",
]

# Layout of the flat parameter array of barge_parameters().
B_MASS = 0       #: mass m = rho Cb L B T [kg]
B_M11 = 1        #: m + m11, surge [kg]
B_M22 = 2        #: m + m22, sway [kg]
B_M66 = 3        #: I_zz + m66, yaw [kg m^2]
B_XUU = 4        #: 1/2 rho C_x B T, so that X = -B_XUU |u| u [kg/m]
B_YCF = 5        #: 1/2 rho C_y T, cross-flow force per metre of hull / (|w| w) [kg/m^2]
B_LENGTH = 6     #: L [m]
B_BEAM = 7       #: B [m]
B_DRAFT = 8      #: T [m]
B_TOW_X = 9      #: tow point x, forward of midship [m]
B_TOW_Z = 10     #: tow point height above the water [m]
B_N_STRIPS = 11  #: strips of the cross-flow integral (a float holding an integer) [-]
B_RHO = 12       #: water density [kg/m^3]
B_CX = 13        #: surge drag coefficient C_x [-]
B_CY = 14        #: cross-flow drag coefficient C_y [-]
B_LIFT = 15      #: hull_lift * m22 / L, the sectional added mass at the trailing edge [kg/m]
B_SIZE = 16      #: length of the array

_RHO = 1025.0


def _barge(barge: Any) -> Barge:
    if isinstance(barge, Barge):
        return barge
    if isinstance(barge, dict):
        return Barge.parse(barge, root="barge")
    raise InputError(f"barge must be a Barge, got {type(barge).__name__}. Suggested fix: build it, e.g. "
                     "Barge(length=50.0, beam=15.0, draft=0.5, block_coefficient=0.9).")


def _rho(water_density) -> float:
    return positive("water_density", water_density, "kg/m^3", "sea water is about 1025 kg/m^3.")


def _strips(n_strips) -> int:
    if isinstance(n_strips, bool) or not float(n_strips).is_integer():
        raise InputError(f"n_strips must be a whole number >= 1, got {n_strips!r}. Suggested fix: use 20.")
    return int(at_least("n_strips", n_strips, 1, "", "use 20 or more strips along the hull."))


def barge_mass(barge: Barge, water_density: float = _RHO) -> tuple[float, float, float, float]:
    """Mass and the inertia terms, rigid plus added, of the 3-DOF barge model.

    Parameters
    ----------
    barge
        The barge.
    water_density
        Density of the water. [kg/m^3]

    Returns
    -------
    mass : float
        ``m = rho Cb L B T``. [kg]
    surge : float
        ``m + m11``, with ``m11 = surge_added_mass * m``. [kg]
    sway : float
        ``m + m22``, with ``m22 = sway_added_mass * rho pi T^2 / 2 * L``. [kg]
    yaw : float
        ``I_zz + m66``, with ``I_zz = m k^2`` and
        ``m66 = yaw_added_inertia * m22 L^2 / 12``. [kg m^2]

    References
    ----------
    .. [1] Fossen (2011), ch. 6; Söding (1982); DNV-RP-C205 Table A-1 (see the module).
    """
    b, rho = _barge(barge), _rho(water_density)
    L, B, T = b.length, b.beam, b.draft
    m = rho * b.block_coefficient * L * B * T
    m11 = b.surge_added_mass * m
    m22 = b.sway_added_mass * 0.5 * rho * math.pi * T**2 * L
    m66 = b.yaw_added_inertia * m22 * L**2 / 12.0
    return m, m + m11, m + m22, m * b.gyradius**2 + m66


def barge_resistance(barge: Barge, speed, water_density: float = _RHO):
    """Steady straight-ahead resistance ``R = 1/2 rho C_x B T U^2`` (the tow force at steady tow).

    Parameters
    ----------
    barge
        The barge.
    speed
        Speed through the water, either sign. [m/s]
    water_density
        Density of the water. [kg/m^3]

    Returns
    -------
    float or numpy.ndarray
        Resistance, >= 0. [N]
    """
    b, rho = _barge(barge), _rho(water_density)
    U = finite("speed", speed, "m/s", "give the speed through the water in m/s.")
    return 0.5 * rho * b.surge_drag * b.beam * b.draft * np.square(U)


def _velocities(u, v, r):
    return (finite("u", u, "m/s", "give the surge velocity in m/s."),
            finite("v", v, "m/s", "give the sway velocity in m/s."),
            finite("r", r, "rad/s", "give the yaw rate in rad/s."))


def barge_hull_forces(barge: Barge, u, v, r, water_density: float = _RHO, n_strips: int = 20):
    """Hull forces in the barge frame: surge resistance, cross-flow drag force and moment.

    Parameters
    ----------
    barge
        The barge.
    u
        Surge velocity relative to the water. [m/s]
    v
        Sway velocity of midship relative to the water, positive to port. [m/s]
    r
        Yaw rate, positive counter-clockwise seen from above. [rad/s]
    water_density
        Density of the water. [kg/m^3]
    n_strips
        Strips of the midpoint rule along the hull. [-]

    Returns
    -------
    X, Y, N : float or numpy.ndarray
        Surge force [N], sway force [N] and yaw moment about midship [N m], broadcast
        over ``u, v, r``.

    Notes
    -----
    ``X = -1/2 rho C_x B T |u| u``; ``Y, N = -1/2 rho C_y T int (1, x) |v + r x| (v + r x) dx``
    over ``-L/2 <= x <= L/2`` (Fossen 2011, cross-flow drag), by the midpoint rule:
    exact for ``r = 0``, error O((L/n)^2) otherwise; plus the slender-body lift
    ``Y_L = -hull_lift |u| (m22 / L) (v + r x_T)``, ``N_L = x_T Y_L`` at the trailing edge
    ``x_T = -sign(u) L / 2`` (Newman 1977, sec. 7.9).

    References
    ----------
    .. [1] Fossen, T. I. (2011), *Handbook of Marine Craft Hydrodynamics and Motion Control*.
    .. [2] Newman, J. N. (1977), *Marine Hydrodynamics*, sec. 7.9.
    """
    b, rho, n = _barge(barge), _rho(water_density), _strips(n_strips)
    u, v, r = _velocities(u, v, r)
    L = b.length
    dx = L / n
    x = -0.5 * L + (np.arange(n) + 0.5) * dx
    w = np.asarray(v)[..., None] + np.asarray(r)[..., None] * x
    drag = 0.5 * rho * b.cross_flow_drag * b.draft * np.abs(w) * w * dx
    X = -0.5 * rho * b.surge_drag * b.beam * b.draft * np.abs(u) * u
    x_t = -0.5 * L * np.sign(u)
    lift = -_lift_per_metre(b, rho) * np.abs(u) * (v + r * x_t)
    Y = -drag.sum(axis=-1) + lift
    N = -(drag * x).sum(axis=-1) + x_t * lift
    return X, Y, N


def _lift_per_metre(b: Barge, rho: float) -> float:
    """``hull_lift m22 / L``: the sectional sway added mass at the trailing edge, scaled. [kg/m]"""
    return b.hull_lift * b.sway_added_mass * 0.5 * rho * math.pi * b.draft**2


def barge_equations(barge: Barge, u, v, r, X_ext, Y_ext, N_ext, water_density: float = _RHO,
                    n_strips: int = 20):
    """Accelerations of the 3-DOF barge under its hull forces and external loads.

    Parameters
    ----------
    barge
        The barge.
    u, v
        Surge and sway velocity (to port) relative to the water. [m/s]
    r
        Yaw rate, positive counter-clockwise. [rad/s]
    X_ext, Y_ext
        External force in the barge frame (e.g. the towline at the tow point). [N]
    N_ext
        External yaw moment about midship; a towline force (Fx, Fy) at the tow point
        gives ``tow_x * Fy``. [N m]
    water_density
        Density of the water. [kg/m^3]
    n_strips
        Strips of the cross-flow integral. [-]

    Returns
    -------
    du_dt, dv_dt, dr_dt : float or numpy.ndarray
        ``[m/s^2, m/s^2, rad/s^2]`` from
        ``M11 u' = M22 v r + X``, ``M22 v' = -M11 u r + Y``,
        ``M66 r' = -(m22 - m11) u v + N`` with X, Y, N the hull plus external loads.

    References
    ----------
    .. [1] Fossen (2011), ch. 6-7: rigid-body and added-mass Coriolis-centripetal terms.
    """
    b = _barge(barge)
    X, Y, N = barge_hull_forces(b, u, v, r, water_density, n_strips)
    X = X + finite("X_ext", X_ext, "N")
    Y = Y + finite("Y_ext", Y_ext, "N")
    N = N + finite("N_ext", N_ext, "N m")
    _, M11, M22, M66 = barge_mass(b, water_density)
    u, v, r = (np.asarray(a, float) for a in (u, v, r))
    return ((M22 * v * r + X) / M11, (-M11 * u * r + Y) / M22, (-(M22 - M11) * u * v + N) / M66)


def barge_parameters(barge: Barge, water_density: float = _RHO, n_strips: int = 20) -> np.ndarray:
    """The barge as a flat float array for compiled code (index constants ``B_*`` of this module).

    Parameters
    ----------
    barge
        The barge.
    water_density
        Density of the water. [kg/m^3]
    n_strips
        Strips of the cross-flow integral, stored as a float. [-]

    Returns
    -------
    numpy.ndarray
        Shape ``(B_SIZE,)``: ``B_MASS, B_M11, B_M22, B_M66`` [kg, kg m^2], ``B_XUU``
        (1/2 rho C_x B T) [kg/m], ``B_YCF`` (1/2 rho C_y T) [kg/m^2], ``B_LENGTH, B_BEAM,
        B_DRAFT, B_TOW_X, B_TOW_Z`` [m], ``B_N_STRIPS`` [-], ``B_RHO`` [kg/m^3],
        ``B_CX, B_CY`` [-].
    """
    b, rho, n = _barge(barge), _rho(water_density), _strips(n_strips)
    p = np.zeros(B_SIZE)
    p[B_MASS], p[B_M11], p[B_M22], p[B_M66] = barge_mass(b, rho)
    p[B_XUU] = 0.5 * rho * b.surge_drag * b.beam * b.draft
    p[B_YCF] = 0.5 * rho * b.cross_flow_drag * b.draft
    p[B_LENGTH], p[B_BEAM], p[B_DRAFT] = b.length, b.beam, b.draft
    p[B_TOW_X], p[B_TOW_Z] = b.tow_x, b.tow_point_height
    p[B_N_STRIPS], p[B_RHO], p[B_CX], p[B_CY] = n, rho, b.surge_drag, b.cross_flow_drag
    p[B_LIFT] = _lift_per_metre(b, rho)
    return p


@njit(cache=True)
def barge_hull_forces_flat(params, u, v, r):
    """Hull forces (X [N], Y [N], N [N m]) from the flat ``params``; as :func:`barge_hull_forces`."""
    L = params[B_LENGTH]
    n = int(params[B_N_STRIPS])
    dx = L / n
    Y = 0.0
    N = 0.0
    for k in range(n):
        x = -0.5 * L + (k + 0.5) * dx
        w = v + r * x
        f = abs(w) * w * dx
        Y += f
        N += f * x
    k_cf = params[B_YCF]
    x_t = -0.5 * L if u > 0.0 else (0.5 * L if u < 0.0 else 0.0)
    lift = -params[B_LIFT] * abs(u) * (v + r * x_t)
    return -params[B_XUU] * abs(u) * u, -k_cf * Y + lift, -k_cf * N + x_t * lift


@njit(cache=True)
def barge_accelerations(params, u, v, r, X_ext, Y_ext, N_ext):
    """(du/dt [m/s^2], dv/dt [m/s^2], dr/dt [rad/s^2]) from the flat ``params``; as :func:`barge_equations`.

    ``u, v`` are the surge and sway velocities relative to the water and ``r`` the yaw rate,
    all in the barge frame (x forward, y to port); ``X_ext, Y_ext`` [N] and ``N_ext`` [N m, about
    midship] the external loads, e.g. a towline force (Fx, Fy) at the tow point gives
    ``N_ext = params[B_TOW_X] * Fy``.
    """
    X, Y, N = barge_hull_forces_flat(params, u, v, r)
    M11 = params[B_M11]
    M22 = params[B_M22]
    M66 = params[B_M66]
    du = (M22 * v * r + X + X_ext) / M11
    dv = (-M11 * u * r + Y + Y_ext) / M22
    dr = (-(M22 - M11) * u * v + N + N_ext) / M66
    return du, dv, dr

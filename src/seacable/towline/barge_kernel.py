"""The towed barge's hull forces and equations of motion from its flat parameter array, compiled (numba).

The same as :func:`seacable.towline.barge.barge_hull_forces` and
:func:`seacable.towline.barge.barge_equations`, on the flat array of
:func:`seacable.towline.barge.barge_parameters` (index constants ``B_*`` of that module), for the
towline kernel (:mod:`seacable.towline.kernel`).
"""

from __future__ import annotations

from .._jit import njit
from .barge import B_LENGTH, B_LIFT, B_M11, B_M22, B_M66, B_N_STRIPS, B_XUU, B_YCF

__all__ = ["barge_accelerations", "barge_hull_forces_flat"]


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

"""A towed body's drag and added mass per axis of the body, the one law of the finite-element and box kernels.

The body's axes (:mod:`seacable.towed.body`): ``along``, the horizontal projection of the towing cable's direction
``t`` at the body (+X when that is vertical), ``across = e_z x along`` and ``vertical = e_z``. With the water's
velocity ``u`` relative to the body and ``u_k = u . e_k``, the drag is ``f = sum_k q_k |u_k| u_k e_k`` (``q_k`` =
1/2 rho C_D A of axis k) and the added mass ``M_a = sum_k m_k e_k e_k^T``.

Derivatives (for the Newton matrices): ``df/du = sum_k 2 q_k |u_k| e_k e_k^T``; the axes turn with ``t``,
``d e_along/dt = e_across e_across^T / h`` and ``d e_across/dt = -e_along e_across^T / h`` (``h`` the horizontal
length of ``t``), so that ``df/dt = (alpha e_along + beta e_across) e_across^T / h`` with
``alpha = 2 q_a |u_a| u_c - q_c |u_c| u_c`` and ``beta = q_a |u_a| u_a - 2 q_c |u_c| u_a``.
"""

from __future__ import annotations

import math

from .._jit import njit

__all__ = ["body_added_mass", "body_axes", "body_drag", "body_drag_turn"]


@njit(cache=True)
def body_axes(tx, ty, axes):
    """The body's axes into ``axes`` (3, 3), rows along, across, vertical, from the horizontal part (tx, ty) of
    the towing cable's direction at the body; returns its length h (0: vertical, along is +X). [-]"""
    h = math.sqrt(tx * tx + ty * ty)
    if h > 0.0:
        ax, ay = tx / h, ty / h
    else:
        ax, ay = 1.0, 0.0
    axes[0, 0], axes[0, 1], axes[0, 2] = ax, ay, 0.0
    axes[1, 0], axes[1, 1], axes[1, 2] = -ay, ax, 0.0
    axes[2, 0], axes[2, 1], axes[2, 2] = 0.0, 0.0, 1.0
    return h


@njit(cache=True)
def body_drag(u, axes, q, f, out):
    """Drag ``sum_k q_k |u_k| u_k e_k`` added to ``f`` (3,), ``u`` the water's velocity relative to the body [m/s],
    ``q`` (3,) 1/2 rho C_D A per axis [kg/m]; ``out`` (3, 3) receives df/du = sum_k 2 q_k |u_k| e_k e_k^T."""
    for r in range(3):
        for c in range(3):
            out[r, c] = 0.0
    for k in range(3):
        uk = u[0] * axes[k, 0] + u[1] * axes[k, 1] + u[2] * axes[k, 2]
        s = q[k] * abs(uk)
        for r in range(3):
            f[r] += s * uk * axes[k, r]
            for c in range(3):
                out[r, c] += 2.0 * s * axes[k, r] * axes[k, c]


@njit(cache=True)
def body_drag_turn(u, axes, q, h, out):
    """``out`` (3, 3) = df/dt, the drag's change with the towing cable's direction ``t`` at the body (its length
    does not count: the axes are its direction's); zero when the cable is vertical there (h = 0)."""
    for r in range(3):
        for c in range(3):
            out[r, c] = 0.0
    if h <= 0.0:
        return
    ua = u[0] * axes[0, 0] + u[1] * axes[0, 1]
    uc = u[0] * axes[1, 0] + u[1] * axes[1, 1]
    alpha = 2.0 * q[0] * abs(ua) * uc - q[1] * abs(uc) * uc
    beta = q[0] * abs(ua) * ua - 2.0 * q[1] * abs(uc) * ua
    for r in range(2):
        g = (alpha * axes[0, r] + beta * axes[1, r]) / h
        for c in range(2):
            out[r, c] = g * axes[1, c]


@njit(cache=True)
def body_added_mass(axes, m, out):
    """``out`` (3, 3) += sum_k m_k e_k e_k^T, the added mass per axis ``m`` (3,) [kg] in the global frame."""
    for k in range(3):
        for r in range(3):
            for c in range(3):
                out[r, c] += m[k] * axes[k, r] * axes[k, c]

"""Nonlinear moment-curvature laws M(kappa) of a cable, a bend stiffener or a bend restrictor: checks and arithmetic.

A law is odd, ``M(-kappa) = -M(kappa)``, and held as its half for ``kappa >= 0``: knots ``kappa_0 = 0 < kappa_1 <
... < kappa_n`` [1/m] with moments ``M_0 = 0, M_1, ... M_n`` [N m], linear between knots and, beyond the last, along
the last segment's slope (a case's check reports a hinge past a user's table:
:func:`seacable.design.cable.cable_checks`). A linear law ``EI kappa`` is the two knots ``(0, 0), (1, EI)``. Its
stored energy per length is ``W(kappa) = integral_0^kappa M dk`` [N m / m = N]; a hinge of length ``L`` stores
``L W(kappa)`` (:func:`seacable.mooring.kernel.bending_loads`).

Laws add (a cable inside a bend stiffener: :func:`law_sum`) on the union of their knots; a bend restrictor's
law is :func:`lock_law` (free to its locking curvature, then a stiff branch).

References
----------
DNV-RP-F401 (2021). Electrical power cables in subsea applications, sec. 4.6 (bend stiffeners and restrictors).
Tan, Z., Quiggin, P. and Sheldrake, T. (2007). Time domain simulation of the 3D bending hysteresis behaviour of an
unbonded flexible riser. OMAE2007-29315 (the armour's slip: a bilinear moment-curvature law, without its
hysteresis here).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["check_table", "law_energy", "law_moment", "law_slope", "law_sum", "linear_law", "lock_law"]


def check_table(table, name: str) -> tuple[tuple[float, float], ...]:
    """The half law (``kappa >= 0``) of a user's ``(kappa [1/m], M [N m])`` table, or ValueError with a fix.

    The table starts at ``(0, 0)`` and rises (curvature and moment both strictly increasing); it may hold negative
    curvatures too, which must then mirror the positive ones (``M(-kappa) = -M(kappa)``: a law without hysteresis
    bends alike both ways). ``name`` names it in the messages (e.g. ``line_types.cable.moment_curvature``).
    """
    pairs = [(float(k), float(m)) for k, m in table]
    if len(pairs) < 2:
        raise ValueError(f"{name} needs at least 2 (curvature [1/m], moment [N m]) pairs, got {len(pairs)}. "
                         "Suggested fix: give the law from (0, 0) to the largest curvature expected, e.g. "
                         "[[0, 0], [0.05, 2000], [0.5, 6000]].")
    for k, (c, m) in enumerate(pairs):
        if not (math.isfinite(c) and math.isfinite(m)):
            raise ValueError(f"{name}[{k}] must be finite (curvature [1/m], moment [N m]), got ({c}, {m}). "
                             "Suggested fix: give numbers in SI units.")
    for k in range(1, len(pairs)):
        (c0, m0), (c1, m1) = pairs[k - 1], pairs[k]
        if not (c1 > c0 and m1 > m0):
            raise ValueError(f"{name}[{k}] = ({c1:g} 1/m, {m1:g} N m) must have a larger curvature and a larger moment "
                             f"than the pair before, ({c0:g} 1/m, {m0:g} N m): the law must be monotone. Suggested "
                             "fix: sort the pairs by curvature; a law that softens to zero slope or below is not "
                             "supported (give a small positive slope for a plateau).")
    zero = [k for k, (c, _) in enumerate(pairs) if c == 0.0]
    if not zero or pairs[zero[0]][1] != 0.0:
        c, m = min(pairs, key=lambda p: abs(p[0]))
        raise ValueError(f"{name} must start at (0, 0): no moment without curvature; its pair nearest zero "
                         f"curvature is ({c:g} 1/m, {m:g} N m). Suggested fix: add the pair [0, 0] (a law with "
                         "hysteresis or a residual moment is not supported).")
    half = pairs[zero[0]:]
    negative = pairs[:zero[0]][::-1]
    if negative:
        mirror = {round(c, 12): m for c, m in half}
        for c, m in negative:
            other = mirror.get(round(-c, 12))
            if other is None or abs(m + other) > 1e-9 * max(abs(m), abs(other), 1.0):
                raise ValueError(
                    f"{name} is not odd: the pair ({c:g} 1/m, {m:g} N m) has no mirror ({-c:g} 1/m, {-m:g} N m). "
                    "Suggested fix: give the law from (0, 0) for positive curvatures only (it is mirrored), or "
                    "mirror every pair.")
        if len(negative) != len(half) - 1:
            raise ValueError(f"{name} is not odd: {len(negative)} negative curvatures against {len(half) - 1} "
                             "positive ones. Suggested fix: give the law from (0, 0) for positive curvatures only.")
    return tuple(half)


def linear_law(ei: float) -> np.ndarray:
    """The law ``EI kappa`` as knots ``(2, 2)``: rows ``(kappa, M)``. [N m^2] -> [1/m, N m]"""
    return np.array([[0.0, 0.0], [1.0, float(ei)]])


def lock_law(locking_radius: float, lock_stiffness: float) -> np.ndarray:
    """A bend restrictor's own law: no moment up to ``1 / locking_radius``, then ``k (kappa - 1 / R)``.

    ``locking_radius`` [m], ``lock_stiffness`` k [N m^2]; knots ``(0, 0), (1 / R, 0), (2 / R, k / R)``."""
    kl = 1.0 / locking_radius
    return np.array([[0.0, 0.0], [kl, 0.0], [2.0 * kl, lock_stiffness * kl]])


def _as_law(law) -> np.ndarray:
    a = np.asarray(law, float)
    return a.reshape(-1, 2)


def law_moment(law, kappa):
    """M at curvatures ``kappa`` (any sign; odd), vectorised. [1/m] -> [N m]"""
    law = _as_law(law)
    k, m = law[:, 0], law[:, 1]
    x = np.abs(np.asarray(kappa, float))
    slope = (m[-1] - m[-2]) / (k[-1] - k[-2])
    inside = np.interp(x, k, m)
    return np.sign(kappa) * np.where(x > k[-1], m[-1] + slope * (x - k[-1]), inside)


def law_slope(law, kappa):
    """dM/dkappa at curvatures ``kappa`` (the right-hand slope at a knot), vectorised. [N m^2]"""
    law = _as_law(law)
    k, m = law[:, 0], law[:, 1]
    slopes = np.diff(m) / np.diff(k)
    j = np.clip(np.searchsorted(k, np.abs(np.asarray(kappa, float)), side="right") - 1, 0, len(slopes) - 1)
    return slopes[j]


def law_energy(law, kappa):
    """W(kappa) = integral_0^|kappa| M dk, the stored energy per length, vectorised. [1/m] -> [N]"""
    law = _as_law(law)
    k, m = law[:, 0], law[:, 1]
    x = np.abs(np.asarray(kappa, float))
    cum = np.r_[0.0, np.cumsum(0.5 * (m[1:] + m[:-1]) * np.diff(k))]
    slopes = np.diff(m) / np.diff(k)
    j = np.clip(np.searchsorted(k, x, side="right") - 1, 0, len(slopes) - 1)
    dx = x - k[j]
    return cum[j] + m[j] * dx + 0.5 * slopes[j] * dx * dx


def law_sum(laws, weights=None) -> np.ndarray:
    """``sum_i w_i M_i(kappa)`` as one law, on the union of the knots (each law extended along its last slope). [-]"""
    laws = [_as_law(law) for law in laws]
    weights = np.ones(len(laws)) if weights is None else np.asarray(weights, float)
    knots = np.unique(np.concatenate([law[:, 0] for law in laws]))
    if len(knots) < 2:
        knots = np.array([0.0, 1.0])
    moment = sum(w * law_moment(law, knots) for w, law in zip(weights, laws))
    return np.column_stack([knots, moment])

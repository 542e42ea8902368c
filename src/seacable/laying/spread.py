"""The spread of a route's turns over the span being laid: the kernels of the span's linearised lateral balance
(:mod:`.lateral`) for a straight span or a catenary under a bottom tension, cached by angle and tension, and
the turn each station's span feels (:class:`_Spread`); see :mod:`seacable.laying.plan` for the model.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from numba import njit

from . import lateral
from .span import S_CDN, S_CDT, S_COMPLIANCE, S_D, S_W, _span, _zajac_angle, straight_direction

# the spread kernels' grid (in laybacks, :func:`.lateral.spread_kernel`) and the steps of their cache: the span's
# angle [deg] and, under a bottom tension, the log of T_0 / (w h)
_SPREAD_EXTENT, _SPREAD_SAMPLES = (-1.5, 10.5), 1024
_ANGLE_STEP, _TENSION_STEP = 0.5, 0.1
_CATENARY_NODES = 51       # the catenary's samples in the lateral balance's finite differences (g_2 to 1e-3)


@lru_cache(maxsize=4096)
def _straight_kernel(angle_level, tangential_level):
    """The spread kernel of Zajac's straight span (no bottom tension), in laybacks: ``(K l, int K)`` on the common
    grid. Its shape depends on the angle ``alpha`` and the tangential drag's share ``eps`` of ``w sin(alpha)``
    only: ``G = exp(i k l) / 0F1(1 / (cos(alpha) D); i k l / (cos(alpha) D))``, ``cos(alpha) D = (1 - eps)
    sin^2(alpha)`` (:func:`.lateral.straight_span_transfer` with Zajac's ``w / (k_n V^2) = sin^2 / cos``)."""
    alpha = math.radians(angle_level * _ANGLE_STEP)
    ca, sa = math.cos(alpha), math.sin(alpha)
    # the span of unit layback at unit speed with k_n = 1, so w = sin^2 / cos (Zajac)
    w = sa * sa / ca

    def transfer(k):
        return lateral.straight_span_transfer(k, angle=alpha, suspended_length=1.0 / ca, speed=1.0, weight=w, kn=1.0,
                                              tension_gradient=(1.0 - 0.01 * tangential_level) * w * sa)

    _, kernel, integral, _ = lateral.spread_kernel(transfer, 1.0, extent=_SPREAD_EXTENT, samples=_SPREAD_SAMPLES)
    return kernel, integral


def span_spread(props, depth, ship_speed, *, water_density, slack=None, bottom_tension=None,
                extent=_SPREAD_EXTENT, samples=_SPREAD_SAMPLES):
    """How a station's span spreads a change of the route's heading: the kernel of its linearised lateral balance.

    The span is the steady lay in still water on a straight track over a flat seabed: Zajac's straight span without
    bottom tension (the closed form, :func:`.lateral.straight_span_transfer`), the catenary with drag under one
    (:func:`_span`'s profile and :func:`.lateral.span_transfer`). See :mod:`.lateral` for the model.

    Parameters
    ----------
    props : (N_STATION_PROPS,) array
        The cable (``S_*`` columns).
    depth, ship_speed : float
        Water depth [m] and ship speed over the ground [m/s].
    water_density : float
        [kg/m^3]
    slack, bottom_tension : float
        The target: one of the two ([-] or [N]).
    extent, samples
        The kernel's range in laybacks and the transform's points (:func:`.lateral.spread_kernel`).

    Returns
    -------
    dict or None
        ``x`` (the touchdown's KP minus the change of heading's) [m], ``kernel`` [1/m], ``integral`` [-], ``g2``
        (the steady turn's cut on a circle of radius R is ``g2 / R``) [m^2], ``layback`` [m]; None if no span reaches
        the surface.
    """
    p = np.asarray(props, float)
    w, d = p[S_W], p[S_D]
    kn, kt = 0.5 * water_density * p[S_CDN] * d, 0.5 * water_density * p[S_CDT] * math.pi * d
    if not bottom_tension:
        ca, _, sa = straight_direction(w, kn, ship_speed, 0.0, 0.0)
        ut = (1.0 + (slack or 0.0)) * ship_speed - ship_speed * ca     # the water along the cable [m/s]
        layback = depth * ca / sa

        def transfer(k):
            return lateral.straight_span_transfer(k, angle=math.atan2(sa, ca), suspended_length=depth / sa,
                                                  speed=ship_speed, weight=w, kn=kn,
                                                  tension_gradient=w * sa - kt * abs(ut) * ut)
    else:
        profile = catenary_profile(p, depth, ship_speed, bottom_tension, water_density=water_density)
        if profile is None:
            return None
        s, tension, sin_a, cos_a, layback = profile

        def transfer(k):
            return lateral.span_transfer(k, s, tension, sin_a, cos_a, speed=ship_speed, weight=w, kn=kn,
                                         layback=layback)

    x, kernel, integral, g2 = lateral.spread_kernel(transfer, layback, extent=extent, samples=samples)
    return {"x": x, "kernel": kernel, "integral": integral, "g2": g2, "layback": layback}


def catenary_profile(props, depth, ship_speed, bottom_tension, *, water_density, nodes=_CATENARY_NODES):
    """The steady lay's span under a bottom tension (the catenary with drag, :func:`_span`, in still water on a
    straight track over a flat seabed) at ``nodes`` equally spaced points from the touchdown: arc length [m],
    tension [N], sine and cosine of the angle to the horizontal [-], and the layback [m]; None if the span does not
    reach the surface."""
    p = np.asarray(props, float)
    out, rec = np.empty(5), np.empty((4000, 4))
    zero = np.zeros(1)
    payout = ship_speed / (1.0 + bottom_tension * p[S_COMPLIANCE])
    m = _span(depth, 0.0, ship_speed, 0.0, payout, 1.0, 0.0, bottom_tension, zero, zero, water_density, p, out, rec)
    if not np.isfinite(out[0]) or m >= rec.shape[0]:
        return None
    s = np.linspace(0.0, out[2], nodes)
    r = rec[:m]
    t1, t3 = np.interp(s, r[:, 0], r[:, 2]), np.interp(s, r[:, 0], r[:, 3])
    norm = np.hypot(t1, t3)
    return s, np.interp(s, r[:, 0], r[:, 1]), t3 / norm, t1 / norm, float(out[0])


@lru_cache(maxsize=4096)
def _catenary_kernel(angle_level, tension_level, props, water_density):
    """The spread kernel of the catenary with drag under a bottom tension, in laybacks ``(K l, int K)``, and its
    layback over its depth: :func:`span_spread` at the speed whose Zajac angle is the level's and the depth where
    ``T_0 / (w h)`` is; its shape, in laybacks, depends on those two numbers (and, by under 1 %, on the payout's
    inertia, the stretch and the tangential drag)."""
    p = np.array(props)
    w, kn = p[S_W], 0.5 * water_density * p[S_CDN] * p[S_D]
    alpha = math.radians(angle_level * _ANGLE_STEP)
    speed = math.sqrt(w * math.cos(alpha) / (kn * math.sin(alpha) ** 2))
    depth = 100.0
    spread = span_spread(p, depth, speed, water_density=water_density,
                         bottom_tension=math.exp(tension_level * _TENSION_STEP) * w * depth, extent=_SPREAD_EXTENT,
                         samples=_SPREAD_SAMPLES)
    if spread is None:
        return None
    return spread["kernel"] * spread["layback"], spread["integral"], spread["layback"] / depth


def clear_spread_cache() -> None:
    """Forget the spread kernels computed so far in this process (they are kept by angle and tension level)."""
    _straight_kernel.cache_clear()
    _catenary_kernel.cache_clear()


class _Spread:
    """Each station's spread of the route's changes of heading over its span's transient (:mod:`.lateral`).

    A station's kernel is that of its span in still water on a straight track at the span's speed: Zajac's
    straight span in closed form without bottom tension, the catenary with drag under a bottom tension (its
    lateral balance by finite differences). The kernels are computed at levels of the numbers their shape
    depends on (the angle every 0.5 deg, the log of ``T_0 / (w h)`` every 0.1) and interpolated linearly between
    them, so that the plan's iteration sees a spread that changes smoothly with the speed and the depth. They
    share one grid in laybacks, ``u0 + j du``.
    """

    def __init__(self, water_density):
        self.rho = water_density
        self.rows, self.kernels, self.integrals = {}, [], []
        self.du = 2.0 * (_SPREAD_EXTENT[1] - _SPREAD_EXTENT[0]) / _SPREAD_SAMPLES
        self.u0 = math.ceil(_SPREAD_EXTENT[0] / self.du - 1e-9) * self.du     # the first point of any kernel

    def _row(self, key, tables):
        if key not in self.rows:
            self.rows[key] = len(self.kernels)
            self.kernels.append(tables[0])
            self.integrals.append(tables[1])
        return self.rows[key]

    def groups(self, h, vs, t0, per_metre, props):
        """The kernels' rows and weights (four a station; row -1 where no span reaches the surface) and the spans'
        laybacks at stations of depth ``h``, span speed ``vs``, bottom tension ``t0``, laid length per metre run
        ``per_metre`` and cable ``props``. [-], [-], [m]"""
        n = h.size
        rows, weights = np.full((n, 4), -1), np.zeros((n, 4))
        w, kt = props[:, S_W], 0.5 * self.rho * props[:, S_CDT] * math.pi * props[:, S_D]
        ca, sa = _zajac_angle(vs, props, self.rho)
        # the angle's levels, between 0.5 deg and 89 deg
        angle = np.clip(np.degrees(np.arctan2(sa, ca)), _ANGLE_STEP, 89.0) / _ANGLE_STEP
        a0 = np.minimum(np.floor(angle).astype(int), round(89.0 / _ANGLE_STEP) - 1)
        fa = angle - a0
        layback = h * ca / sa
        # (a span within 1.15 deg of the vertical lays the track itself, spread over 2 % of the depth: no spread)
        steep = layback < 0.02 * h
        slack = (t0 <= 0.0) & ~steep
        if slack.any():
            ut = per_metre * vs - vs * ca                    # the water along the cable, past the material [m/s]
            tangential = np.rint(100.0 * kt * np.abs(ut) * ut / (w * sa)).astype(int)
            for j, (level, weight) in enumerate(((a0, 1.0 - fa), (a0 + 1, fa))):
                keys = np.column_stack([level, tangential])[slack]
                unique, back = np.unique(keys, axis=0, return_inverse=True)
                found = np.array([self._row((0, *key), _straight_kernel(*key)) for key in map(tuple, unique)])
                rows[slack, j], weights[slack, j] = found[back.ravel()], weight[slack]
        taut = (t0 > 0.0) & ~steep
        if taut.any():
            ratio = np.log(np.where(taut, t0, 1.0) / (w * h)) / _TENSION_STEP
            b0 = np.floor(ratio).astype(int)
            fb = ratio - b0
            cable, which = np.unique(props[taut], axis=0, return_inverse=True)
            which = which.ravel()
            layback[taut] = 0.0
            for j, (la, lb, weight) in enumerate(((a0, b0, (1 - fa) * (1 - fb)), (a0 + 1, b0, fa * (1 - fb)),
                                                  (a0, b0 + 1, (1 - fa) * fb), (a0 + 1, b0 + 1, fa * fb))):
                keys = np.column_stack([la[taut], lb[taut], which])
                unique, back = np.unique(keys, axis=0, return_inverse=True)
                found, scale = [], []
                for key in map(tuple, unique):
                    c = tuple(cable[key[2]].tolist())
                    tables = _catenary_kernel(key[0], key[1], c, self.rho)
                    found.append(-1 if tables is None else self._row((1, key[0], key[1], c), tables))
                    scale.append(np.nan if tables is None else tables[2])
                back = back.ravel()
                rows[taut, j], weights[taut, j] = np.array(found)[back], weight[taut]
                layback[taut] += weight[taut] * np.array(scale)[back] * h[taut]
            lost = taut & (np.any(rows < 0, axis=1) | ~np.isfinite(layback))
            rows[lost], weights[lost], layback[lost] = -1, 0.0, (h * ca / sa)[lost]
        return rows, weights, layback

    def turns(self, kp, h, vs, t0, per_metre, props, turn_kp, turn, reach):
        """The route's curvature at the stations' touchdowns (``layback`` behind the ship KPs ``kp``) spread over
        the span's transient [1/m], the change of the spread heading from the legs' there [rad], and the
        layback [m] (``reach``, Zajac's, where no change of heading is near)."""
        n = kp.size
        rows, weights, layback = np.full((n, 4), -1), np.zeros((n, 4)), np.array(reach, float)
        # the stations whose window (the kernel's, over twice Zajac's layback) holds a change of heading
        lo = np.searchsorted(turn_kp, kp - reach - 2.0 * _SPREAD_EXTENT[1] * reach)
        hi = np.searchsorted(turn_kp, kp - reach - 2.0 * _SPREAD_EXTENT[0] * reach, side="right")
        near = hi > lo
        if not near.any():
            return np.zeros(n), np.zeros(n), layback
        rows[near], weights[near], layback[near] = self.groups(h[near], vs[near], t0[near], per_metre[near],
                                                               props[near])
        if not self.kernels:
            return np.zeros(n), np.zeros(n), layback
        curvature, heading = _spread_turns(kp - layback, layback, rows, weights, self.u0, self.du,
                                           np.array(self.kernels), np.array(self.integrals), turn_kp, turn)
        return curvature, heading, layback


@njit(cache=True)
def _spread_turns(x_td, layback, rows, weights, u0, du, kernels, integrals, turn_kp, turn):
    """Each change of heading ``d_j`` at KP ``k_j`` spread as ``d_j K((x - k_j) / l) / l`` (curvature) and
    ``d_j (I - H)((x - k_j) / l)`` (the heading's change from the legs', ``I`` the kernel's integral and ``H``
    the step of the sharp turn), at the stations' touchdown KPs ``x``; a station's ``K`` is the weighted sum of
    its kernels' ``rows`` (none where the first is -1)."""
    n, m = x_td.size, kernels.shape[1]
    curvature, heading = np.zeros(n), np.zeros(n)
    u1 = u0 + (m - 1) * du
    for i in range(n):
        ell = layback[i]
        if rows[i, 0] < 0:
            continue
        lo = np.searchsorted(turn_kp, x_td[i] - u1 * ell)
        hi = np.searchsorted(turn_kp, x_td[i] - u0 * ell, side="right")
        for j in range(lo, hi):
            u = (x_td[i] - turn_kp[j]) / ell
            f = (u - u0) / du
            a = min(max(int(f), 0), m - 2)
            r = f - a
            kv, iv = 0.0, 0.0
            for c in range(rows.shape[1]):
                g, wt = rows[i, c], weights[i, c]
                if g >= 0 and wt != 0.0:
                    kv += wt * (kernels[g, a] * (1.0 - r) + kernels[g, a + 1] * r)
                    iv += wt * (integrals[g, a] * (1.0 - r) + integrals[g, a + 1] * r)
            curvature[i] += turn[j] * kv / ell
            heading[i] += turn[j] * (iv - (1.0 if u >= 0.0 else 0.0))
    return curvature, heading

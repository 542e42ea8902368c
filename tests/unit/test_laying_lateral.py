"""The lateral response of a lay span (:mod:`seacable.laying.lateral`): closed form, finite differences, kernel.

The span is paper 001's cable (4.49 N/m in water, 22.5 mm, C_dn 1.85) laid at 1 m/s in 100 m of water: Zajac's
straight span at 25.7 deg, 230 m long, 207.8 m of layback; and, under a bottom tension, the catenary with drag
that :func:`seacable.laying.plan.span_spread` integrates.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.laying import lateral
from seacable.laying.plan import straight_direction

RHO, W, D, CDN = 1030.0, 4.49, 0.0225, 1.85
KN = 0.5 * RHO * CDN * D
V, H = 1.0, 100.0


def _zajac(speed=V):
    """Angle, suspended length and layback of Zajac's straight span."""
    ca, _, sa = straight_direction(W, KN, speed, 0.0, 0.0)
    return math.atan2(sa, ca), H / sa, H * ca / sa


def _closed(k, speed=V, gradient=None):
    alpha, length, _ = _zajac(speed)
    return lateral.straight_span_transfer(k, angle=alpha, suspended_length=length, speed=speed, weight=W, kn=KN,
                                          tension_gradient=W * math.sin(alpha) if gradient is None else gradient)


def _finite(k, n, speed=V):
    alpha, length, layback = _zajac(speed)
    s = np.linspace(0.0, length, n)
    return lateral.span_transfer(k, s, W * math.sin(alpha) * s, np.full(n, math.sin(alpha)),
                                 np.full(n, math.cos(alpha)), speed=speed, weight=W, kn=KN, layback=layback)


def test_finite_differences_converge_to_the_closed_form_at_second_order():
    """On Zajac's straight span (T = w sin(alpha) s) the lateral balance is Kummer's limit equation, solved by
    ``0F1``; the finite differences (central, the touchdown's condition one-sided to second order) reach it with
    the error falling 4 times per halving of the step (measured 3.96-3.98 from 51 to 401 samples)."""
    k = np.linspace(0.0, 0.2, 21)                          # to 0.2 rad/m: 6.6 rad over the layback
    exact = _closed(k)
    errors = [np.max(np.abs(_finite(k, n) - exact)) for n in (51, 101, 201, 401)]
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    assert np.all((ratios > 3.8) & (ratios < 4.2)), ratios
    assert errors[-1] < 2e-5


@pytest.mark.parametrize("speed", [0.5, 1.0, 2.0])
def test_steady_cut_per_curvature_is_the_closed_form(speed):
    """``G = 1 - g_2 k^2 + ...``: a ship on a wide circle of radius R lays the cable ``g_2 / R`` inside its track,
    with ``g_2 = l^2 sin^2(alpha) / (2 (1 + sin^2(alpha)))`` for Zajac's span (expanding ``exp(i k l) / 0F1``);
    the kernel's own ``g_2`` (Richardson on two small wavenumbers) to 1e-6."""
    alpha, _, layback = _zajac(speed)
    s2 = math.sin(alpha) ** 2
    _, _, _, g2 = lateral.spread_kernel(lambda k: _closed(k, speed), layback)
    assert g2 == pytest.approx(layback**2 * s2 / (2.0 * (1.0 + s2)), rel=1e-6)


@pytest.mark.parametrize("transfer", ["closed", "finite", "catenary"])
def test_a_straight_track_at_an_angle_is_laid_on_itself(transfer):
    """The laid path of a straight track at any angle is that track: ``G(k) = 1 + O(k^2)`` with no term in k
    (a term ``i k delta`` would lay the cable ``delta`` times the angle off the route). It holds because the
    lateral drag is advected at ``V cos(alpha)`` (the tilt of the tangent cancels the payout's ``V_c``): with
    ``V_c`` instead, delta would be the layback times 0.05 (5 % slack) = 10 m. Checked at ``k l = 1e-3``:
    ``|Im G| / (k l) < 1e-4`` (measured 1.4e-8, the ``k^3`` term)."""
    from seacable.laying.plan import S_CDN, S_CDT, S_COMPLIANCE, S_D, S_MEFF, S_MT, S_W, catenary_profile

    _, _, layback = _zajac()
    if transfer == "catenary":
        p = np.zeros(7)
        p[[S_W, S_D, S_CDN, S_CDT, S_MEFF, S_COMPLIANCE, S_MT]] = W, D, CDN, 0.01, 1.28, 1.0 / 3e7, 0.867
        s, tension, sin_a, cos_a, layback = catenary_profile(p, H, V, 200.0, water_density=RHO, nodes=201)
        k = np.array([1e-3 / layback])
        g = lateral.span_transfer(k, s, tension, sin_a, cos_a, speed=V, weight=W, kn=KN, layback=layback)
    else:
        k = np.array([1e-3 / layback])
        g = _closed(k) if transfer == "closed" else _finite(k, 201)
    assert abs(g[0].imag) / (k[0] * layback) < 1e-4
    assert abs(g[0] - 1.0) < 1e-5                           # and G -> 1: the track itself, to O((k l)^2)


@pytest.mark.parametrize("speed", [0.5, 1.0, 2.0, 4.0])
def test_kernel_has_unit_area_and_sees_a_turn_only_once_the_ship_has(speed):
    """The spread kernel ``K(x)`` (x: the touchdown's KP minus the turn's) has unit area (1e-5: its kink at 0 taken
    in closed form, the rest by the trapezoid rule; measured 2e-7 to 4e-6), is zero (to 1e-6 of its peak; measured
    1e-7 at most) for x < -l, where the turn lies ahead of the ship, peaks at x = 0 (the turn reaches the
    touchdown) and falls to 1e-6 of its peak beyond 10 laybacks (measured 5e-8). Its length is the layback: from
    0.5 to 4 m/s its peak times l goes from 1.24 to 7.0 (the flatter the span, the more a turn stays on the
    track)."""
    _, _, layback = _zajac(speed)
    x, kernel, integral, _ = lateral.spread_kernel(lambda k: _closed(k, speed), layback, extent=(-1.5, 10.5),
                                                   samples=1024)
    peak = kernel.max()
    assert integral[-1] == pytest.approx(1.0, abs=1e-5)
    assert np.max(np.abs(kernel[x < -1.0001 * layback])) < 1e-6 * peak
    assert abs(x[np.argmax(kernel)]) <= (x[1] - x[0]) + 1e-9
    assert np.max(np.abs(kernel[x > 10.0 * layback])) < 1e-6 * peak


def test_flat_span_beyond_the_closed_forms_order_takes_the_finite_differences():
    """At 8 m/s the span is 3.3 deg: ``0F1``'s order ``1 / sin^2`` is 300, past scipy's Gamma, and the transfer
    is the finite differences' on the straight span; the kernel still has unit area (1e-5; measured 6e-7)."""
    _, _, layback = _zajac(8.0)
    _, _, integral, _ = lateral.spread_kernel(lambda k: _closed(k, 8.0), layback, extent=(-1.5, 10.5), samples=1024)
    assert np.isfinite(integral).all()
    assert integral[-1] == pytest.approx(1.0, abs=1e-5)

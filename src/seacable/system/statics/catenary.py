"""Warm-started elastic catenaries of many sub-lines, compiled (private to :mod:`seacable.system.statics`).

Inside the system's Newton iteration the sub-lines move a little between evaluations, so each
catenary restarts from its previous end forces and converges in one or two steps. This kernel
solves the two generic regimes of :func:`seacable.statics.catenary.catenary` - suspended (any
shape, seabed or not) and touching down on the seabed with Coulomb friction - with the same
equations (Irvine 1981 eqs. 2.26-2.27; Jonkman 2007 eqs. 2-35 to 2-42, in the forms of
``catenary._spans``) and the same tolerance, and a weighty mid-water line with zero horizontal span
(the public function's closed form). Every other case (buoyant or weightless lines, a zero span
on the seabed, the slack L shape, a failure to converge, a strain above 1) is flagged and left to
the vectorised public function, which also serves the first evaluation.
"""

from __future__ import annotations

import math
import re

import numpy as np

from ..._jit import njit
from ...errors import NoSolutionError
from ...statics.catenary import CatenaryResult, _guess, catenary


@njit(cache=True, error_model="numpy")
def _asinh_over(q):
    if abs(q) < 1e-3:
        return 1.0 - q * q / 6.0 + 0.075 * q ** 4
    return math.asinh(q) / q


@njit(cache=True, error_model="numpy")
def _spans(H, V, L, EA, w, mu, seabed):
    """Fairlead (x, z) and d(x, z)/d(H, V); grounded flag (as catenary._spans, one line)."""
    if seabed and V < w * L:
        ag = V / H
        Rg = math.hypot(1.0, ag)
        LB = L - V / w
        xB = LB - H / (mu * w) if mu > 0 else 0.0
        xBp = max(xB, 0.0)
        if abs(ag) < 1e-3:
            am = ag ** 3 / 3.0 - 0.3 * ag ** 5
        else:
            am = math.asinh(ag) - ag / math.hypot(1.0, ag)
        x = LB + V / w * _asinh_over(ag) + H * L / EA - 0.5 * mu * w / EA * (LB * LB - xBp * xBp)
        z = V / w * ag / (Rg + 1.0) + V * V / (2.0 * w * EA)
        c = -ag * ag / (Rg * (Rg + 1.0)) / w
        return x, z, am / w + (L - xBp) / EA, c + mu * (LB - xBp) / EA, c, ag / Rg / w + V / (w * EA), True
    a = V / H
    b = (V - w * L) / H
    Ra = math.hypot(1.0, a)
    Rb = math.hypot(1.0, b)
    if a * b > 0:
        c = (a + b) / (a * Rb + b * Ra)
        g = _asinh_over((a - b) * c) * c
    elif a == b:
        c, g = 1.0, 1.0
    else:
        c = (a * Rb - b * Ra) / (a - b)
        g = (math.asinh(a) - math.asinh(b)) / (a - b)
    LH = L / H
    x = L * g + H * L / EA
    z = L * (a + b) / (Ra + Rb) + (V * L - 0.5 * w * L * L) / EA
    m = LH * (a + b) / ((Ra + Rb) * Ra * Rb)
    n = LH * c / (Ra * Rb)
    return x, z, LH * g - n + L / EA, -m, -m, n + L / EA, False


# ---- nonlinear axial stiffness: a strain-tension table ------------------------------------------
#
# A sub-line with a table carries its inverse, strain as a function of tension, as the points
# ``tT[lo:hi]`` (tension, increasing from 0) and ``te[lo:hi]`` (strain): linear between them, and
# beyond the last point the last piece continued. (MoorDyn holds the tension flat there: the line
# yields at the table's last tension. The continuation keeps Newton's tangent finite on the way; an
# equilibrium that needs a tension above the table's end is refused by the caller, statics.py.) On a
# piece eps = a + b T, and with T = sqrt(H^2 + V^2) along the catenary (V the vertical force, linear
# in the unstretched arc length s, dV = w ds) the stretch integrals are closed forms:
#
#   x:  int eps/T dV = a [asinh(V/H)] + b [V],         z:  int eps V/T dV = int eps dT = [G(T)],
#
# G(T) = int_0^T eps; d/dH of the first is -a [V/(H T)] (eps continuous: the pieces' moving ends
# add nothing).


@njit(cache=True, error_model="numpy")
def _piece(j, hi, tT, te):
    """(a, b, T_lo, T_hi) of piece j (j = hi - 1: the continuation beyond the table)."""
    if j < hi - 1:
        dT = tT[j + 1] - tT[j]
        b = (te[j + 1] - te[j]) / dT if dT > 0 else 0.0
        return te[j] - b * tT[j], b, tT[j], tT[j + 1]
    T1, e1 = tT[hi - 1], te[hi - 1]
    dT = T1 - tT[hi - 2]
    b = (e1 - te[hi - 2]) / dT if dT > 0 else 0.0
    if not b > 0:
        b = e1 / T1
    return e1 - b * T1, b, T1, math.inf


@njit(cache=True, error_model="numpy")
def table_eps(T, lo, hi, tT, te):
    """Strain and d(strain)/dT at tension T >= 0."""
    for j in range(lo, hi):
        a, b, _t0, t1 = _piece(j, hi, tT, te)
        if T < t1:
            return a + b * T, b
    return math.nan, math.nan


@njit(cache=True, error_model="numpy")
def table_G(T, lo, hi, tT, te):
    """int_0^T eps(t) dt."""
    g = 0.0
    for j in range(lo, hi):
        a, b, t0, t1 = _piece(j, hi, tT, te)
        if t1 <= t0:
            continue
        top = min(T, t1)
        if top > t0:
            g += a * (top - t0) + 0.5 * b * (top * top - t0 * t0)
        if T <= t1:
            break
    return g


@njit(cache=True, error_model="numpy")
def _J(u, H, lo, hi, tT, te):
    """(int_0^u eps(T)/T dv, its d/dH) with T = sqrt(H^2 + v^2), u >= 0, H > 0."""
    Tu = math.hypot(H, u)
    J = 0.0
    JH = 0.0
    for j in range(lo, hi):
        a, b, t0, t1 = _piece(j, hi, tT, te)
        tl, th = max(t0, H), min(t1, Tu)
        if th <= tl:
            if t1 >= Tu:
                break
            continue
        vl = math.sqrt(max(tl * tl - H * H, 0.0))
        vh = math.sqrt(max(th * th - H * H, 0.0))
        J += b * (vh - vl)
        if a != 0.0:
            # asinh(vh/H) - asinh(vl/H) without the division by H
            J += a * math.asinh((th * th - tl * tl) / (vh * tl + vl * th))
            JH -= a * (vh / th - vl / tl) / H
        if t1 >= Tu:
            break
    return J, JH


@njit(cache=True, error_model="numpy")
def _I(V, H, lo, hi, tT, te):
    """int_0^V eps/T dv (odd in V) and its d/dH."""
    J, JH = _J(abs(V), H, lo, hi, tT, te)
    if V < 0:
        return -J, -JH
    return J, JH


@njit(cache=True, error_model="numpy")
def _spans_nl(H, V, L, w, mu, seabed, lo, hi, tT, te):
    """:func:`_spans` of a line whose strain is the table's eps(T) (w > 0, H > 0)."""
    x, z, xh, xv, zh, zv, grd = _spans(H, V, L, math.inf, w, mu, seabed)
    TF = math.hypot(H, V)
    eF, _d = table_eps(TF, lo, hi, tT, te)
    GF = table_G(TF, lo, hi, tT, te)
    if grd:
        LB = L - V / w
        IF, IFH = _I(V, H, lo, hi, tT, te)
        eH, dH = table_eps(H, lo, hi, tT, te)
        # grounded part: T falls from H at the touchdown by mu w per metre towards the anchor
        if mu > 0:
            HA = H - mu * w * LB
            if HA > 0:
                eA, _d = table_eps(HA, lo, hi, tT, te)
                Sg = (table_G(H, lo, hi, tT, te) - table_G(HA, lo, hi, tT, te)) / (mu * w)
                SgH, SgV = (eH - eA) / (mu * w), -eA / w
            else:
                Sg = table_G(H, lo, hi, tT, te) / (mu * w)
                SgH, SgV = eH / (mu * w), 0.0
        else:
            Sg, SgH, SgV = LB * eH, LB * dH, -eH / w
        x += H / w * IF + Sg
        xh += IF / w + H / w * IFH + SgH
        xv += H / w * eF / TF + SgV
        z += (GF - table_G(H, lo, hi, tT, te)) / w
        zh += (eF * H / TF - eH) / w
        zv += eF * V / TF / w
        return x, z, xh, xv, zh, zv, grd
    VA = V - w * L
    TA = math.hypot(H, VA)
    eA, _d = table_eps(TA, lo, hi, tT, te)
    IF, IFH = _I(V, H, lo, hi, tT, te)
    IA, IAH = _I(VA, H, lo, hi, tT, te)
    x += H / w * (IF - IA)
    xh += (IF - IA) / w + H / w * (IFH - IAH)
    xv += H / w * (eF / TF - eA / TA)
    z += (GF - table_G(TA, lo, hi, tT, te)) / w
    zh += H * (eF / TF - eA / TA) / w
    zv += (eF * V / TF - eA * VA / TA) / w
    return x, z, xh, xv, zh, zv, grd


@njit(cache=True, error_model="numpy")
def _log_int(T1, T2, lo, hi, tT, te):
    """int_T1^T2 eps(T)/T dT, 0 < T1 <= T2 (a vertical line's horizontal compliance)."""
    out = 0.0
    for j in range(lo, hi):
        a, b, t0, t1 = _piece(j, hi, tT, te)
        tl, th = max(t0, T1), min(t1, T2)
        if th > tl:
            out += b * (th - tl) + (a * math.log(th / tl) if a != 0.0 else 0.0)
        if t1 >= T2:
            break
    return out


@njit(cache=True, error_model="numpy")
def _vertical_nl(k, z, L, w, lo, hi, tT, te, out):
    """:func:`_vertical` of a line with a strain-tension table: straight and taut when the chord
    ``z`` is at least ``L + G(w L)/w`` (hanging under its own weight from the upper end), else a U
    folded at its lowest point (branch lengths l1 above the fairlead's side, L - l1 the anchor's).
    Safeguarded Newton (bisection on a bracket) to 1e-14 x L."""
    Gw = table_G(w * L, lo, hi, tT, te)
    zc = L + Gw / w
    if z >= zc:
        # z = L + (G(V) - G(V - w L)) / w, increasing in V >= w L
        lo_v, hi_v = w * L, w * L
        while True:
            hi_v = 2.0 * hi_v + tT[hi - 1]
            if L + (table_G(hi_v, lo, hi, tT, te) - table_G(hi_v - w * L, lo, hi, tT, te)) / w > z:
                break
            if hi_v > 1e300:
                return
        V = 0.5 * (lo_v + hi_v)
        for _it in range(200):
            f = L + (table_G(V, lo, hi, tT, te) - table_G(V - w * L, lo, hi, tT, te)) / w - z
            if abs(f) <= 1e-14 * L:
                break
            if f > 0:
                hi_v = V
            else:
                lo_v = V
            d = (table_eps(V, lo, hi, tT, te)[0] - table_eps(V - w * L, lo, hi, tT, te)[0]) / w
            Vn = V - f / d if d > 0 else 0.5 * (lo_v + hi_v)
            if not (lo_v < Vn < hi_v):
                Vn = 0.5 * (lo_v + hi_v)
            if abs(Vn - V) <= 1e-15 * Vn:
                V = Vn
                break
            V = Vn
        VA = V - w * L
        dzdV = (table_eps(V, lo, hi, tT, te)[0] - table_eps(VA, lo, hi, tT, te)[0]) / w
        k00 = 0.0
        if VA > 0:
            k00 = w / (math.log(V / VA) + _log_int(VA, V, lo, hi, tT, te))
        out[k, 0], out[k, 1], out[k, 2], out[k, 3], out[k, 4] = 0.0, V, 0.0, VA, 0.0
        out[k, 5], out[k, 6], out[k, 7], out[k, 8] = k00, 0.0, 0.0, 1.0 / dzdV
        out[k, 9] = 6.0
        out[k, 10] = 1.0
        return
    # U: z = l1 + G(w l1)/w - l2 - G(w l2)/w, l2 = L - l1, increasing in l1 in [L/2, L]
    a_, b_ = 0.5 * L, L
    l1 = 0.5 * (a_ + b_)
    for _it in range(200):
        l2 = L - l1
        f = l1 - l2 + (table_G(w * l1, lo, hi, tT, te) - table_G(w * l2, lo, hi, tT, te)) / w - z
        if abs(f) <= 1e-14 * L:
            break
        if f > 0:
            b_ = l1
        else:
            a_ = l1
        d = 2.0 + table_eps(w * l1, lo, hi, tT, te)[0] + table_eps(w * l2, lo, hi, tT, te)[0]
        ln = l1 - f / d
        if not (a_ <= ln <= b_):
            ln = 0.5 * (a_ + b_)
        if abs(ln - l1) <= 1e-15 * L:
            l1 = ln
            break
        l1 = ln
    l2 = L - l1
    d = 2.0 + table_eps(w * l1, lo, hi, tT, te)[0] + table_eps(w * l2, lo, hi, tT, te)[0]
    out[k, 0], out[k, 1], out[k, 2], out[k, 3], out[k, 4] = 0.0, w * l1, 0.0, -w * l2, 0.0
    out[k, 5], out[k, 6], out[k, 7], out[k, 8] = 0.0, 0.0, 0.0, w / d
    out[k, 9] = 5.0
    out[k, 10] = 1.0


@njit(cache=True, error_model="numpy")
def _spans_any(H, V, L, EA, w, mu, seabed, lo, hi, tT, te):
    if hi > lo:
        return _spans_nl(H, V, L, w, mu, seabed, lo, hi, tT, te)
    return _spans(H, V, L, EA, w, mu, seabed)


@njit(cache=True, error_model="numpy")
def solve_warm(x, z, L, EA, w, mu, seabed, H0, V0, tol, ts_lo, ts_hi, tT, te, max_strain, out):
    """Newton from (H0, V0) per sub-line; ``out[k]`` = H, V, HA, VA, LB, K00, K01, K10, K11, regime, ok.

    ``ts_lo/ts_hi`` index each sub-line's inverse strain-tension table in ``tT``/``te`` (empty:
    constant EA); ok = 1 solved, 0 left to the public function, -1 a tabled sub-line strained
    beyond ``max_strain``."""
    for k in range(x.size):
        _solve_one(k, x, z, L, EA, w, mu, seabed, H0, V0, tol, ts_lo[k], ts_hi[k], tT, te, max_strain, out)


@njit(cache=True, error_model="numpy")
def _guess_one(x, z, L, EA, w):
    """Peyrot & Goulois (1979) start, raised to the straight-bar tension when taut (as catenary._guess)."""
    chord = math.hypot(x, z)
    lam = 0.2
    if L > chord and x > 0:
        q = 3.0 * ((L * L - z * z) / (x * x) - 1.0)
        if q > 0 and math.isfinite(q) and math.sqrt(q) >= 0.2:
            lam = min(math.sqrt(q), 1e6)
    H = 0.5 * w * x / lam
    V = 0.5 * w * (z / math.tanh(lam) + L)
    if chord >= L:
        T = EA * (chord / L - 1.0)
        H = max(H, T * x / chord)
        V = T * z / chord + 0.5 * w * L
    return max(H, 1e-15 * (w * L + abs(V))), V


@njit(cache=True, error_model="numpy")
def geometry_and_solve(P, sub_a, sub_b, L, EA, w, mu, depth, seabed_tol, H0, V0, have_warm, tol,
                       ts_lo, ts_hi, tT, te, max_strain, geom, seabed, anchor_is_a, out):
    """Each sub-line's catenary frame (lower end = anchor) and its warm-started solution.

    ``geom[s]`` = horizontal span, vertical span, e_x, e_y, tiny (horizontal span ~ 0);
    ``depth`` NaN for no seabed; without ``have_warm`` the start is Peyrot & Goulois's.
    """
    for s in range(sub_a.size):
        pa, pb = P[sub_a[s]], P[sub_b[s]]
        a_is = pa[2] <= pb[2]
        pA, pF = (pa, pb) if a_is else (pb, pa)
        dx, dy, dz = pF[0] - pA[0], pF[1] - pA[1], pF[2] - pA[2]
        h = math.hypot(dx, dy)
        tiny = h <= 1e-9 * L[s]
        geom[s, 0] = h
        geom[s, 1] = max(dz, 0.0)
        geom[s, 2] = 1.0 if tiny else dx / h
        geom[s, 3] = 0.0 if tiny else dy / h
        geom[s, 4] = 1.0 if tiny else 0.0
        anchor_is_a[s] = a_is
        seabed[s] = (not math.isnan(depth)) and pA[2] <= -depth + seabed_tol
        if not have_warm or (w[s] > 0 and not H0[s] > 0):
            # no start, or a last solution with no horizontal force (a vertical or slack-L line that
            # the public function solved): Peyrot & Goulois's start
            if w[s] > 0:
                H0[s], V0[s] = _guess_one(h, geom[s, 1], L[s], EA[s], w[s])
            else:
                H0[s], V0[s] = 0.0, 0.0
    solve_warm(geom[:, 0], geom[:, 1], L, EA, w, mu, seabed, H0, V0, tol, ts_lo, ts_hi, tT, te, max_strain, out)


@njit(cache=True, error_model="numpy")
def _vertical(k, z, L, EA, w, out):
    """A weighty line hanging in mid-water with zero horizontal span (``catenary``'s closed form:
    straight and vertical when taut, else a U folded at its lowest point); out[k, 10] = 1 unless its
    strain exceeds 1 (the public function decides)."""
    f = 1.0 + 0.5 * w * L / EA
    taut = abs(z) >= L * f
    sz = 1.0 if z > 0 else (-1.0 if z < 0 else 0.0)
    VA3 = EA * (z - sz * L) / L - 0.5 * w * L
    k00 = 0.0
    if taut:
        q = w * L / VA3 if VA3 != 0.0 else math.inf
        if math.isfinite(q) and q > -1.0:
            dxdH = abs(math.log1p(q)) / w + L / EA
            if math.isfinite(dxdH):
                k00 = 1.0 / dxdH
    d = z / f
    V = VA3 + w * L if taut else 0.5 * w * (L + d)
    VA = VA3 if taut else V - w * L
    out[k, 0], out[k, 1], out[k, 2], out[k, 3], out[k, 4] = 0.0, V, 0.0, VA, 0.0
    out[k, 5], out[k, 6], out[k, 7] = k00, 0.0, 0.0
    out[k, 8] = EA / L if taut else 0.5 * w / f
    out[k, 9] = 6.0 if taut else 5.0          # CatenaryRegime.VERTICAL, SLACK_U
    if max(abs(V), abs(VA)) > EA:
        return
    out[k, 10] = 1.0


@njit(cache=True, error_model="numpy")
def _solve_one(k, x, z, L, EA, w, mu, seabed, H0, V0, tol, lo, hi, tT, te, max_strain, out):
    """Sub-line ``k``: damped Newton on (H, V) with one polishing step; out[k, 10] = 1 if solved."""
    out[k, 10] = 0.0
    if w[k] > 0 and not seabed[k] and x[k] <= 1e-12 * L[k] and math.hypot(x[k], z[k]) / L[k] - 1.0 <= 1.0:
        if hi > lo:
            _vertical_nl(k, z[k], L[k], w[k], lo, hi, tT, te, out)
            _check_table_strain(k, lo, hi, tT, te, max_strain, out)
        else:
            _vertical(k, z[k], L[k], EA[k], w[k], out)
        return
    if not (w[k] > 0 and H0[k] > 0 and x[k] > 1e-9 * L[k]) or (seabed[k] and z[k] <= 1e-12 * L[k]):
        return
    H, V = H0[k], V0[k]
    scale = max(L[k], math.hypot(x[k], z[k]))
    fx, fz, jxh, jxv, jzh, jzv, grd = _spans_any(H, V, L[k], EA[k], w[k], mu[k], seabed[k], lo, hi, tT, te)
    fx -= x[k]
    fz -= z[k]
    ok = False
    polished = False
    for _it in range(31):
        if max(abs(fx), abs(fz)) <= tol * scale:
            if polished:
                ok = True
                break
            polished = True          # one more full step: quadratic convergence to round-off
        det = jxh * jzv - jxv * jzh
        dH = -(jzv * fx - jxv * fz) / det
        dV = -(-jzh * fx + jxh * fz) / det
        if not (math.isfinite(dH) and math.isfinite(dV)):
            break
        alpha = 1.0
        if H + dH < 0.1 * H:
            alpha = min(alpha, 0.9 * H / -dH)
        if seabed[k] and V > 0 and V + dV < 0.1 * V:
            alpha = min(alpha, 0.9 * V / -dV)
        f2 = fx * fx + fz * fz
        for _ls in range(30):
            Ht = max(H + alpha * dH, 1e-15 * (w[k] * L[k] + abs(V + alpha * dV)))
            Vt = V + alpha * dV
            gx, gz, a1, a2, a3, a4, g5 = _spans_any(Ht, Vt, L[k], EA[k], w[k], mu[k], seabed[k], lo, hi, tT, te)
            gx -= x[k]
            gz -= z[k]
            if (math.isfinite(gx) and math.isfinite(gz) and (polished or gx * gx + gz * gz <= (1 - 1e-4 * alpha) * f2)) \
                    or _ls == 29:
                H, V, fx, fz, jxh, jxv, jzh, jzv, grd = Ht, Vt, gx, gz, a1, a2, a3, a4, g5
                break
            alpha *= 0.5
    if not ok or H <= 0:
        return
    det = jxh * jzv - jxv * jzh
    out[k, 0], out[k, 1] = H, V
    if grd:
        LB = L[k] - V / w[k]
        HA = max(H - mu[k] * w[k] * LB, 0.0)
        out[k, 2], out[k, 3], out[k, 4] = HA, 0.0, LB
        out[k, 9] = 2.0 if HA > 0 else 3.0
    else:
        out[k, 2], out[k, 3], out[k, 4] = H, V - w[k] * L[k], 0.0
        out[k, 9] = 1.0
    out[k, 5], out[k, 6] = jzv / det, -jxv / det
    out[k, 7], out[k, 8] = -jzh / det, jxh / det
    if hi > lo:
        out[k, 10] = 1.0
        _check_table_strain(k, lo, hi, tT, te, max_strain, out)
        return
    if max(math.hypot(H, V), math.hypot(out[k, 2], out[k, 3])) > EA[k]:
        return                         # strain above 1: the public function explains it
    out[k, 10] = 1.0


@njit(cache=True, error_model="numpy")
def _check_table_strain(k, lo, hi, tT, te, max_strain, out):
    """ok = -1 if a solved tabled sub-line's largest strain exceeds max_strain."""
    if out[k, 10] == 1.0:
        T = max(math.hypot(out[k, 0], out[k, 1]), math.hypot(out[k, 2], out[k, 3]))
        if table_eps(T, lo, hi, tT, te)[0] > max_strain:
            out[k, 10] = -1.0


_NO_TABLE = (np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros(0), np.zeros(0))


def frame_and_catenaries(P, sub_a, sub_b, L, EA, w, mu, depth, warm=None, tol=1e-12, max_strain=1.0, tables=None):
    """Sub-line frames and catenaries from node positions; (cat, anchor_is_a, e, tiny).

    ``max_strain``: a sub-line stretched more is refused (NoSolutionError). ``tables``:
    ``(ts_lo, ts_hi, tT, te)``, each sub-line's inverse strain-tension table (see :func:`_piece`;
    ``ts_lo == ts_hi``: constant EA), or None for none. In the result a tabled sub-line's ``EA``
    is its secant at the fairlead tension (what :meth:`CatenaryResult.profile` draws it with)."""
    ns = sub_a.size
    geom = np.empty((ns, 5))
    seabed = np.empty(ns, np.bool_)
    anchor_is_a = np.empty(ns, np.bool_)
    out = np.zeros((ns, 11))
    mu_arr = np.full(ns, float(mu))
    have = warm is not None
    H0 = warm[0].copy() if have else np.empty(ns)
    V0 = warm[1].copy() if have else np.empty(ns)
    dep = math.nan if depth is None else float(depth)
    if tables is None:
        tables = _no_tables(ns)
    geometry_and_solve(P, sub_a, sub_b, L, EA, w, mu_arr, dep, 1e-6 * (1.0 if depth is None else max(1.0, dep)),
                       H0, V0, have, tol, *tables, float(max_strain), geom, seabed, anchor_is_a, out)
    h, v = geom[:, 0], geom[:, 1]
    cat = _finish(out, h, v, L, EA, w, mu_arr, seabed, tol, max_strain, tables)
    return cat, anchor_is_a, np.ascontiguousarray(geom[:, 2:4]), geom[:, 4] > 0


def _no_tables(ns):
    """Table arrays saying "no table" for ``ns`` sub-lines (writable, as the tables are: numba compiles its
    kernels again for read-only arrays)."""
    z = np.zeros(ns, np.int64)
    return z, z, _NO_TABLE[2], _NO_TABLE[3]


def table_strain(T, k, tables):
    """Strain of sub-line ``k`` at tension(s) ``T`` from its table. [-]"""
    lo, hi, tT, te = int(tables[0][k]), int(tables[1][k]), tables[2], tables[3]
    return np.array([table_eps(float(t), lo, hi, tT, te)[0] for t in np.atleast_1d(T)])


def _columns(out):
    """H, V, HA, VA and LB of the kernel's table ``out`` as contiguous copies, not its columns: the kernels they go
    to are compiled for C-contiguous arrays (a strided column would make numba compile them again)."""
    return tuple(np.ascontiguousarray(out[:, k]) for k in range(5))


def _finish(out, h, v, L, EA, w, mu_arr, seabed, tol, max_strain=1.0, tables=None) -> CatenaryResult:
    n = h.size
    flags = out[:, 10]
    all_ok = bool(flags.size == 0 or flags.min() == 1.0)  # no sub-lines: bodies alone
    over = np.zeros(0, int) if all_ok else np.flatnonzero(flags == -1.0)
    if over.size:
        # a tabled sub-line strained beyond max_strain (the table's continuation: T above its end)
        k = int(over[0])
        T = max(math.hypot(out[k, 0], out[k, 1]), math.hypot(out[k, 2], out[k, 3]))
        err = NoSolutionError(
            f"the line[{k}] would stretch by {table_strain(T, k, tables)[0]:.3g} > max_strain={max_strain:.3g} "
            f"(tension {T:.6g} N on its tension-strain table, which ends at {tables[2][tables[1][k] - 1]:.6g} N): "
            f"horizontal_span={h[k]:.6g} m, vertical_span={v[k]:.6g} m, length={L[k]:.6g} m. Suggested fix: "
            "lengthen the line or bring the ends closer, or extend the table to the strains expected.")
        err.sub_line = k
        raise err
    bad = flags == 0.0
    H, V, HA, VA, LB = _columns(out)
    K = out[:, 5:9].reshape(n, 2, 2).copy()
    reg = out[:, 9].astype(np.int8)
    iters = 0
    if not all_ok and bad.any():
        # (a tabled sub-line here - buoyant, weightless, slack on the seabed - takes its EA: the table's
        # secant; statics._warn_strain says so)
        try:
            r = catenary(h[bad], v[bad], L[bad], EA[bad], w[bad], mu_arr[bad], seabed[bad], tol=tol,
                         max_strain=max_strain)
        except NoSolutionError as err:  # say which sub-line of the whole system (the caller names its line)
            found = re.search(r"the line\[(\d+)\]", str(err))
            if found:
                err.sub_line = int(np.flatnonzero(bad)[int(found.group(1))])
            raise
        H[bad], V[bad], HA[bad], VA[bad], LB[bad] = r.H_fairlead, r.V_fairlead, r.H_anchor, r.V_anchor, \
            r.grounded_length
        K[bad] = r.stiffness
        reg[bad] = r.regime
        iters = r.iterations
    ea = EA
    if tables is not None and tables[2].size:
        tabled = np.flatnonzero((tables[1] > tables[0]) & ~bad)
        if tabled.size:
            ea = EA.copy()
            for k in tabled:
                T = math.hypot(H[k], V[k])
                e = table_strain(T, k, tables)[0]
                ea[k] = T / e if e > 0 and T > 0 else EA[k]
    return CatenaryResult(H, V, HA, VA, np.hypot(H, V), np.hypot(HA, VA), LB, K, reg, iters, h, v, L, ea, w,
                          mu_arr, seabed)


def catenaries(h, v, L, EA, w, mu, seabed, warm=None, tol=1e-12) -> CatenaryResult:
    """All sub-lines at once (constant EA): warm-started kernel where it applies, the public function elsewhere."""
    n = h.size
    mu_arr = np.broadcast_to(np.asarray(mu, float), (n,)).copy()
    if warm is None:
        # Peyrot & Goulois's start, as the public function (for w > 0; others fall back)
        wp = np.where(w > 0, w, 1.0)
        warm = _guess(h, v, L, EA, wp)
        warm = (np.where(w > 0, warm[0], 0.0), warm[1])
    out = np.zeros((n, 11))
    zero = np.zeros(n, np.int64)
    solve_warm(h, v, L, EA, w, mu_arr, seabed, warm[0], warm[1], tol, zero, zero, _NO_TABLE[2], _NO_TABLE[3], 1.0, out)
    bad = out[:, 10] == 0.0
    H, V, HA, VA, LB = _columns(out)
    K = out[:, 5:9].reshape(n, 2, 2).copy()
    reg = out[:, 9].astype(np.int8)
    iters = 0
    if bad.any():
        r = catenary(h[bad], v[bad], L[bad], EA[bad], w[bad], mu_arr[bad], seabed[bad], tol=tol)
        H[bad], V[bad], HA[bad], VA[bad], LB[bad] = r.H_fairlead, r.V_fairlead, r.H_anchor, r.V_anchor, \
            r.grounded_length
        K[bad] = r.stiffness
        reg[bad] = r.regime
        iters = r.iterations
    return CatenaryResult(H, V, HA, VA, np.hypot(H, V), np.hypot(HA, VA), LB, K, reg, iters, h, v, L, EA, w,
                          mu_arr, np.asarray(seabed, bool))



@njit(cache=True, error_model="numpy")
def _table_profile(s, H, V, L, w, mu, LB, regime, lo, hi, tT, te, x, z, T):
    """Shape (x, z from the lower end) and tension at arc lengths ``s`` of a solved tabled sub-line:
    the stretch integrals of :func:`_spans_nl` over [0, s] (each part of a catenary is one)."""
    VA = V - w * L
    for i in range(s.size):
        si = s[i]
        if regime == 5 or regime == 6:           # vertical: taut or folded
            Vs = VA + w * si
            x[i] = 0.0
            z[i] = (abs(Vs) - abs(VA) + table_G(abs(Vs), lo, hi, tT, te) - table_G(abs(VA), lo, hi, tT, te)) / w
            T[i] = abs(Vs)
        elif regime == 2 or regime == 3:         # grounded up to LB, then suspended
            if si >= LB:
                x[i], z[i] = _spans_nl(H, w * (si - LB), si, w, mu, np.bool_(True), lo, hi, tT, te)[:2]
                T[i] = math.hypot(H, w * (si - LB))
            else:
                if mu > 0:
                    T0 = max(H - mu * w * LB, 0.0)
                    Ts = max(H - mu * w * (LB - si), 0.0)
                    x[i] = si + (table_G(Ts, lo, hi, tT, te) - table_G(T0, lo, hi, tT, te)) / (mu * w)
                else:
                    Ts = H
                    x[i] = si + si * table_eps(H, lo, hi, tT, te)[0]
                z[i] = 0.0
                T[i] = Ts
        else:                                    # suspended
            Vs = VA + w * si
            if si > 0:
                x[i], z[i] = _spans_nl(H, Vs, si, w, 0.0, np.bool_(False), lo, hi, tT, te)[:2]
            else:
                x[i], z[i] = 0.0, 0.0
            T[i] = math.hypot(H, Vs)


# The closed-form profile of one sub-line, point by point: ``seacable.statics.catenary._profile`` (NumPy, for a
# single line, where no kernel is loaded) in compiled form for the system's line profiles (a few dozen NumPy calls a
# sub-line were most of the time of a small system's run around its solve). Each point is computed with the same
# operations in the same order as there (the branch np.where keeps, libm's asinh, hypot and pow as NumPy calls
# them; error_model "numpy": a division by zero gives inf or NaN, as there), so the two give the same bits:
# tests/unit/statics/test_system_profile_kernel.py checks every regime.
@njit(cache=True)
def _np_max(a, b):
    """``np.maximum(a, b)`` of two floats (a where a >= b or a is NaN)."""
    return a if (a >= b or a != a) else b


@njit(cache=True)
def _np_min(a, b):
    """``np.minimum(a, b)`` of two floats (a where a <= b or a is NaN)."""
    return a if (a <= b or a != a) else b


@njit(cache=True, error_model="numpy")
def _arc_point(s, H, VA, V, w, EA):
    """x, z, T at unstretched distance ``s`` from a point of vertical tension ``VA`` (``_suspended_arc``)."""
    a = V / H
    b = VA / H
    Ra = math.hypot(1.0, a)
    Rb = math.hypot(1.0, b)
    if a * b > 0:
        c = (a + b) / (a * Rb + b * Ra)
        q = (a - b) * c
        if abs(q) < 1e-3:
            g = (1.0 - q * q / 6.0 + 0.075 * math.pow(q, 4.0)) * c
        else:
            g = math.asinh(q) / q * c
    elif a - b == 0:
        g = 1.0
    else:
        g = (math.asinh(a) - math.asinh(b)) / (a - b)
    return s * g + H * s / EA, s * (a + b) / (Ra + Rb) + (VA * s + 0.5 * w * s * s) / EA, math.hypot(H, V)


@njit(cache=True, error_model="numpy")
def _grounded_point(s, H, LB, mu, w, EA):
    """x and T at ``s`` (<= LB) along a grounded length LB of touchdown tension H (``_grounded``)."""
    if mu <= 0:
        return s + H * s / EA, H
    xB = LB - H / (mu * w)
    if 0.0 > xB:
        xB = 0.0
    u = _np_max(s, xB)
    stretch = ((H - mu * w * LB) * (u - xB) + 0.5 * mu * w * (u * u - xB * xB)) / EA
    return s + stretch, _np_max(H - mu * w * (LB - s), 0.0)


@njit(cache=True, error_model="numpy")
def closed_form_profile(s, xF, zF, L, EA, w, mu, H, VF, LB, regime, x, z, T):
    """x, z, T at arc lengths ``s`` of one solved line (``seacable.statics.catenary._profile``, the same bits)."""
    n = s.size
    sg = -1.0 if w < 0 else 1.0
    w, zF, VF = abs(w), sg * zF, sg * VF
    if regime == 7:                                   # weightless
        Th = math.hypot(H, VF)
        for i in range(n):
            x[i], z[i], T[i] = xF * s[i] / L, zF * s[i] / L, Th
    elif regime == 6:                                 # vertical
        VA = VF - w * L
        sign = 1.0 if zF > 0 else (-1.0 if zF < 0 else (0.0 if zF == 0 else zF))
        for i in range(n):
            V = VA + w * s[i]
            x[i], z[i], T[i] = xF, sign * s[i] + (VA * s[i] + 0.5 * w * s[i] * s[i]) / EA, abs(V)
    elif regime == 5:                                 # slack U
        L1 = L - VF / w
        d1 = L1 + 0.5 * w * L1 * L1 / EA
        for i in range(n):
            si = s[i]
            T[i] = w * abs(si - L1)
            if si <= L1:
                z[i] = -(si + w / EA * (L1 * si - 0.5 * si * si))
            else:
                z[i] = -d1 + (si - L1) + 0.5 * w * ((si - L1) * (si - L1)) / EA
            x[i] = xF
    elif regime == 1:                                 # suspended
        VA = VF - w * L
        for i in range(n):
            x[i], z[i], T[i] = _arc_point(s[i], H, VA, VA + w * s[i], w, EA)
    else:                                             # on the seabed for s <= LB, then suspended from the touchdown
        slack = regime == 4 or H == 0
        if slack:
            xTD = LB if LB < xF else xF
            scale = xTD / LB if LB > 0 else 0.0
        else:
            xTD = _grounded_point(_np_min(LB, LB), H, LB, mu, w, EA)[0]
        for i in range(n):
            si = s[i]
            if si <= LB:
                if slack:
                    x[i], T[i] = _np_min(si, LB) * scale, 0.0
                else:
                    x[i], T[i] = _grounded_point(_np_min(si, LB), H, LB, mu, w, EA)
                z[i] = 0.0
            else:
                u = _np_max(si - LB, 0.0)
                if regime == 0:
                    x[i], z[i] = xTD + 0.0, 0.0
                    T[i] = _grounded_point(_np_min(si, LB), H, LB, mu, w, EA)[1] if not slack else 0.0
                elif regime == 4:
                    x[i], z[i], T[i] = xTD + 0.0, u + 0.5 * w * u * u / EA, w * u
                else:
                    xa, z[i], T[i] = _arc_point(u, H, 0.0, w * u, w, EA)
                    x[i] = xTD + xa
    for i in range(n):
        z[i] = sg * z[i]


def sub_profile(cat, k, n, tables, profile_cls):
    """Profile of sub-line ``k`` at ``n`` points: exact for a tabled sub-line solved here (regimes
    suspended, grounded, vertical), else the closed forms of ``cat.profile`` (:func:`closed_form_profile`)."""
    L = float(cat.length[k])
    s = np.linspace(0.0, L, n)
    x, z, T = np.empty(n), np.empty(n), np.empty(n)
    if tables is not None and tables[1][k] > tables[0][k] and int(cat.regime[k]) in (1, 2, 3, 5, 6) \
            and float(cat.weight_per_length[k]) > 0:
        _table_profile(s, float(cat.H_fairlead[k]), float(cat.V_fairlead[k]), L,
                       float(cat.weight_per_length[k]), float(cat.seabed_friction[k]), float(cat.grounded_length[k]),
                       int(cat.regime[k]), int(tables[0][k]), int(tables[1][k]), tables[2], tables[3], x, z, T)
    else:
        closed_form_profile(s, float(cat.horizontal_span[k]), float(cat.vertical_span[k]), L,
                            float(cat.axial_stiffness[k]), float(cat.weight_per_length[k]),
                            float(cat.seabed_friction[k]), float(cat.H_fairlead[k]), float(cat.V_fairlead[k]),
                            float(cat.grounded_length[k]), int(cat.regime[k]), x, z, T)
    return profile_cls(s, x, z, T)


# The profiles of whole lines in one call (:meth:`SystemEquilibrium.line_profiles`): per sub-line the points of
# :func:`sub_profile`, placed in the line's frame, ordered by arc length along the line and joined, then
# interpolated at evenly spaced arc lengths, with the same operations as the NumPy calls they replace (NumPy's
# linspace formula, its stable sort's order, its interp's search and formula), so the same bits: a run of a small
# system built them sub-line by sub-line in a few dozen NumPy calls each, most of its time around the solve. The
# sort and the interpolation are written out (numba's np.argsort and np.interp took 10 CPU-s to compile).
@njit(cache=True)
def _before(a, i, b, j):
    """Whether (value a, index i) sorts before (b, j) in NumPy's stable sort: by value, NaN last, then index."""
    if a != a:
        return b != b and i < j
    if b != b or a < b:
        return True
    return a == b and i < j


@njit(cache=True)
def _stable_order(s, reverse):
    """``np.argsort(s, kind="stable")``; ``reverse``: ``s`` is (about) non-increasing, so the sort starts from the
    reversed order (an insertion sort: the few items out of place moved)."""
    m = s.size
    order = np.empty(m, np.int64)
    for i in range(m):
        order[i] = m - 1 - i if reverse else i
    for i in range(1, m):
        o = order[i]
        k = i
        while k > 0 and _before(s[o], o, s[order[k - 1]], order[k - 1]):
            order[k] = order[k - 1]
            k -= 1
        order[k] = o
    return order


@njit(cache=True, error_model="numpy")
def _interp(x, xp, fp, out):
    """``out[:] = np.interp(x, xp, fp)`` for sorted ``xp`` of at least two points (NumPy's arr_interp: the last
    ``j`` with ``xp[j] <= x``, ``fp[j]`` at a point of ``xp``, else its slope formula, the other end's if NaN)."""
    n = xp.size
    for i in range(x.size):
        v = x[i]
        if v != v:
            out[i] = v
            continue
        if v > xp[n - 1]:
            out[i] = fp[n - 1]
            continue
        if v < xp[0]:
            out[i] = fp[0]
            continue
        lo, hi = 0, n                    # the first index with xp > v, by bisection
        while lo < hi:
            mid = lo + ((hi - lo) >> 1)
            if v >= xp[mid]:
                lo = mid + 1
            else:
                hi = mid
        j = lo - 1
        if j == n - 1 or xp[j] == v:
            out[i] = fp[j]
        else:
            slope = (fp[j + 1] - fp[j]) / (xp[j + 1] - xp[j])
            r = slope * (v - xp[j]) + fp[j]
            if r != r:
                r = slope * (v - xp[j + 1]) + fp[j + 1]
                if r != r and fp[j] == fp[j + 1]:
                    r = fp[j]
            out[i] = r


@njit(cache=True, error_model="numpy")
def _linspace(start, stop, num):
    """``np.linspace(start, stop, num)`` of floats, ``num >= 2`` (NumPy's formula: ``i * step + start``)."""
    y = np.empty(num)
    div = num - 1
    delta = stop - start
    step = delta / div
    for i in range(num):
        y[i] = (i / div * delta if step == 0 else i * step) + start
    y[num - 1] = stop
    return y


@njit(cache=True, error_model="numpy")
def line_profiles(n, lines, line_first, line_last, sub_L, sub_s0, sub_a, sub_b, anchor_is_a, node_position, e,
                  length, hspan, vspan, EA, w, mu, H, V, LB, regime, lo, hi, tT, te, has_tables, pos, tension):
    """Positions ``pos[j]`` (n, 3) [m] and tension ``tension[j]`` (n,) [N] of line ``lines[j]`` at ``n`` points
    evenly spaced in unstretched arc length (:meth:`SystemEquilibrium.line_profile`)."""
    for j in range(lines.size):
        il = lines[j]
        k0, k1 = line_first[il], line_last[il] + 1
        total = 0.0
        for k in range(k0, k1):
            total += sub_L[k]
        size = 0
        for k in range(k0, k1):
            size += max(4, int(np.ceil(2 * n * sub_L[k] / total)) + 2)
        S, X, T = np.empty(size), np.empty((3, size)), np.empty(size)
        at = 0
        for k in range(k0, k1):
            m = max(4, int(np.ceil(2 * n * sub_L[k] / total)) + 2)
            Lk = length[k]
            sp = _linspace(0.0, Lk, m)
            x, z, t = np.empty(m), np.empty(m), np.empty(m)
            if has_tables and hi[k] > lo[k] and (regime[k] == 1 or regime[k] == 2 or regime[k] == 3
                                                 or regime[k] == 5 or regime[k] == 6) and w[k] > 0:
                _table_profile(sp, H[k], V[k], Lk, w[k], mu[k], LB[k], regime[k], lo[k], hi[k], tT, te, x, z, t)
            else:
                closed_form_profile(sp, hspan[k], vspan[k], Lk, EA[k], w[k], mu[k], H[k], V[k], LB[k], regime[k],
                                    x, z, t)
            a_is = anchor_is_a[k]
            pA = node_position[sub_a[k] if a_is else sub_b[k]]
            s = sub_s0[k] + (sp if a_is else sub_L[k] - sp)
            order = _stable_order(s, not a_is)
            for i in range(m):
                o = order[i]
                S[at + i] = s[o]
                X[0, at + i] = pA[0] + x[o] * e[k, 0]
                X[1, at + i] = pA[1] + x[o] * e[k, 1]
                X[2, at + i] = pA[2] + z[o]
                T[at + i] = t[o]
            at += m
        s = _linspace(0.0, total, n)
        out = np.empty(n)
        for c in range(3):
            _interp(s, S, X[c], out)
            pos[j, :, c] = out
        _interp(s, S, T, tension[j])

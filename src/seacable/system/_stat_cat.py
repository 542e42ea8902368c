"""Warm-started elastic catenaries of many sub-lines, compiled (private to :mod:`.statics`).

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
from numba import njit

from ..errors import NoSolutionError
from ..statics.catenary import CatenaryResult, _guess, catenary


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


@njit(cache=True, error_model="numpy")
def solve_warm(x, z, L, EA, w, mu, seabed, H0, V0, tol, out):
    """Newton from (H0, V0) per sub-line; ``out[k]`` = H, V, HA, VA, LB, K00, K01, K10, K11, regime, ok."""
    for k in range(x.size):
        _solve_one(k, x, z, L, EA, w, mu, seabed, H0, V0, tol, out)


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
                       geom, seabed, anchor_is_a, out):
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
    solve_warm(geom[:, 0], geom[:, 1], L, EA, w, mu, seabed, H0, V0, tol, out)


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
def _solve_one(k, x, z, L, EA, w, mu, seabed, H0, V0, tol, out):
    """Sub-line ``k``: damped Newton on (H, V) with one polishing step; out[k, 10] = 1 if solved."""
    out[k, 10] = 0.0
    if w[k] > 0 and not seabed[k] and x[k] <= 1e-12 * L[k] and math.hypot(x[k], z[k]) / L[k] - 1.0 <= 1.0:
        _vertical(k, z[k], L[k], EA[k], w[k], out)
        return
    if not (w[k] > 0 and H0[k] > 0 and x[k] > 1e-9 * L[k]) or (seabed[k] and z[k] <= 1e-12 * L[k]):
        return
    H, V = H0[k], V0[k]
    scale = max(L[k], math.hypot(x[k], z[k]))
    fx, fz, jxh, jxv, jzh, jzv, grd = _spans(H, V, L[k], EA[k], w[k], mu[k], seabed[k])
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
            gx, gz, a1, a2, a3, a4, g5 = _spans(Ht, Vt, L[k], EA[k], w[k], mu[k], seabed[k])
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
    if max(math.hypot(H, V), math.hypot(out[k, 2], out[k, 3])) > EA[k]:
        return                         # strain above 1: the public function explains it
    out[k, 10] = 1.0


def frame_and_catenaries(P, sub_a, sub_b, L, EA, w, mu, depth, warm=None, tol=1e-12, max_strain=1.0):
    """Sub-line frames and catenaries from node positions; (cat, anchor_is_a, e, tiny).

    ``max_strain``: a sub-line stretched more is refused (NoSolutionError) by the public function."""
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
    geometry_and_solve(P, sub_a, sub_b, L, EA, w, mu_arr, dep, 1e-6 * (1.0 if depth is None else max(1.0, dep)),
                       H0, V0, have, tol, geom, seabed, anchor_is_a, out)
    h, v = geom[:, 0], geom[:, 1]
    cat = _finish(out, h, v, L, EA, w, mu_arr, seabed, tol, max_strain)
    return cat, anchor_is_a, geom[:, 2:4], geom[:, 4] > 0


def _finish(out, h, v, L, EA, w, mu_arr, seabed, tol, max_strain=1.0) -> CatenaryResult:
    n = h.size
    bad = out[:, 10] == 0.0
    H, V, HA, VA, LB = out[:, 0], out[:, 1], out[:, 2], out[:, 3], out[:, 4]
    K = out[:, 5:9].reshape(n, 2, 2).copy()
    reg = out[:, 9].astype(np.int8)
    iters = 0
    if bad.any():
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
    return CatenaryResult(H, V, HA, VA, np.hypot(H, V), np.hypot(HA, VA), LB, K, reg, iters, h, v, L, EA, w,
                          mu_arr, seabed)


def catenaries(h, v, L, EA, w, mu, seabed, warm=None, tol=1e-12) -> CatenaryResult:
    """All sub-lines at once: warm-started kernel where it applies, the public function elsewhere."""
    n = h.size
    mu_arr = np.broadcast_to(np.asarray(mu, float), (n,)).copy()
    if warm is None:
        # Peyrot & Goulois's start, as the public function (for w > 0; others fall back)
        wp = np.where(w > 0, w, 1.0)
        warm = _guess(h, v, L, EA, wp)
        warm = (np.where(w > 0, warm[0], 0.0), warm[1])
    out = np.zeros((n, 11))
    solve_warm(h, v, L, EA, w, mu_arr, seabed, warm[0], warm[1], tol, out)
    bad = out[:, 10] == 0.0
    H, V, HA, VA, LB = out[:, 0], out[:, 1], out[:, 2], out[:, 3], out[:, 4]
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


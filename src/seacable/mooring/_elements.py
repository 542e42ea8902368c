"""The mooring line's internal forces beyond the elastic truss element: strain-tension tables, a Syrope rope's
working curves, MoorDyn v2's viscoelastic element (each with its pass over the elements) and the nodal bending
moments, with their tangents added to the band.

The elastic element is part of the loads pass (:func:`seacable.mooring._loads.loads_water`), which calls these.
Part of :mod:`seacable.mooring.kernel`, which re-exports the public names.
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import njit
from ._band import _add_block
from ._indices import (
    H_CLAMP,
    H_D,
    H_EI,
    H_K,
    H_KIND,
    H_L0,
    H_NLAW,
    H_SIZE,
    V_BAD,
    V_EAD,
    V_K1,
    V_K2,
    V_LM,
    V_TM,
    V_TM0,
    V_U,
    V_U0,
    V_WC,
    V_Y,
    V_Y0,
)


@njit(cache=True)
def table_tension(eps, lo, hi, ts_x, ts_y):
    """Tension [N] and slope dT/d(eps) [N] of the strain-tension table ``ts_x/ts_y[lo:hi]`` at ``eps``.

    MoorDyn's convention (``Line::getNonlinearEA`` with ``moordyn::interp``): linear between the
    points; held at the first point's tension below its strain and at the last point's tension
    beyond the table (slope 0 there); a breakpoint takes the slope of the piece above it.
    Compression (eps < 0) is handled by the caller (no tension).
    """
    if eps <= ts_x[lo]:
        return ts_y[lo], 0.0
    if eps >= ts_x[hi - 1]:
        return ts_y[hi - 1], 0.0
    j = lo + 1
    while ts_x[j] <= eps:
        j += 1
    k = (ts_y[j] - ts_y[j - 1]) / (ts_x[j] - ts_x[j - 1])
    return ts_y[j - 1] + k * (eps - ts_x[j - 1]), k


@njit(cache=True)
def syrope_tension(eps, row, lo, hi, ts_x, ts_y):
    """Tension [N] and slope dT/d(eps) [N] of a Syrope rope element at strain ``eps`` (Falkenberg et al. 2017).

    MoorDyn's Syrope model, quasi-static: the original working curve (OWC, the strain-tension table
    ``ts_x/ts_y[lo:hi]``) beyond the strain ``eps_max`` at which it reaches the largest mean tension so far
    ``Tmax = row[V_TM0]``, and below it the working curve of that ``Tmax``, from zero tension at
    ``eps_min`` to ``Tmax`` at ``eps_max``, with ``xi = (eps - eps_min) / (eps_max - eps_min)``::

        eps_min = eps_0 + k1 (eps_max - eps_0)     (eps_0 the OWC's first strain)
        eps_min = eps_max - Tmax / k1              (LINEAR with k1 >= 1: k1 is the curve's stiffness [N])
        T = Tmax xi                                (LINEAR)
        T = Tmax xi (k2 xi + 1 - k2)               (QUADRATIC)
        T = Tmax (exp(k2 xi) - 1) / (exp(k2) - 1)  (EXP)

    and no tension below ``eps_min`` (the permanent stretch). Writes the ``Tmax`` this state would leave,
    ``max(Tmax, T)`` on the OWC, in ``row[V_TM]`` (committed after a converged step).
    """
    tmax = row[V_TM0]
    # the OWC's strain at Tmax (the table is increasing; held at its ends as MoorDyn's interp)
    if tmax <= ts_y[lo]:
        emax = ts_x[lo]
    elif tmax >= ts_y[hi - 1]:
        emax = ts_x[hi - 1]
    else:
        j = lo + 1
        while ts_y[j] <= tmax:
            j += 1
        emax = ts_x[j - 1] + (tmax - ts_y[j - 1]) * (ts_x[j] - ts_x[j - 1]) / (ts_y[j] - ts_y[j - 1])
    if eps >= emax:
        T, k = table_tension(eps, lo, hi, ts_x, ts_y)
        row[V_TM] = max(tmax, T)
        return T, k
    row[V_TM] = tmax
    form, k1, k2 = row[V_WC], row[V_K1], row[V_K2]
    if form == 1.0 and k1 >= 1.0:
        emin = emax - tmax / k1
    else:
        emin = ts_x[lo] + k1 * (emax - ts_x[lo])
    d = emax - emin
    if d <= 0.0:
        return table_tension(eps, lo, hi, ts_x, ts_y)
    xi = (eps - emin) / d
    if xi <= 0.0:
        return 0.0, 0.0
    if form == 2.0:
        return tmax * xi * (k2 * xi + 1.0 - k2), tmax * (2.0 * k2 * xi + 1.0 - k2) / d
    if form == 3.0 and abs(k2) > 1e-12:
        den = math.exp(k2) - 1.0
        return tmax * (math.exp(k2 * xi) - 1.0) / den, tmax * k2 * math.exp(k2 * xi) / den / d
    return tmax * xi, tmax / d


@njit(cache=True)
def hinge_law(row, kappa):
    """A hinge's nonlinear law at curvature ``kappa >= 0`` (its knots from ``row[H_SIZE]`` on, :mod:`._indices`).

    Returns ``(M, dM/dkappa, W, sigma, q)``: the moment [N m], its slope [N m^2], the energy per length
    ``W = integral_0^kappa M dk`` [N], the secant ``sigma = M / kappa`` [N m^2] and ``q = (dM/dkappa - sigma) /
    kappa^2`` [N m^4], the last two exact (the first segment's slope, 0) on the first segment, where kappa may be 0.
    Beyond the last knot the law goes on along its last segment's slope.
    """
    n = int(row[H_NLAW])
    w = 0.0
    j = 0
    while j < n - 2 and kappa > row[H_SIZE + 2 * (j + 1)]:
        k0, m0 = row[H_SIZE + 2 * j], row[H_SIZE + 2 * j + 1]
        k1, m1 = row[H_SIZE + 2 * j + 2], row[H_SIZE + 2 * j + 3]
        w += 0.5 * (m0 + m1) * (k1 - k0)
        j += 1
    k0, m0 = row[H_SIZE + 2 * j], row[H_SIZE + 2 * j + 1]
    k1, m1 = row[H_SIZE + 2 * j + 2], row[H_SIZE + 2 * j + 3]
    mp = (m1 - m0) / (k1 - k0)
    dk = kappa - k0
    m = m0 + mp * dk
    w += m0 * dk + 0.5 * mp * dk * dk
    if j == 0:
        return m, mp, w, mp, 0.0
    sigma = m / kappa
    return m, mp, w, sigma, (mp - sigma) / (kappa * kappa)


@njit(cache=True)
def bending_loads(X, hinges, hinge_ei, F, band, bw, fidx):
    """MoorDyn v2's nodal bending stiffness: forces on the three nodes of each hinge, and their tangent.

    A hinge is an inner node ``i1`` of a line with its neighbours ``i0`` and ``i2``. With the unit
    vectors ``a`` (i0 to i1) and ``b`` (i1 to i2) of the stretched elements of lengths ``l1``, ``l2``, the
    angle ``theta`` between them and ``c = cos(theta) = a . b``, the curvature and moment are
    (``Line::getStateDeriv`` and ``GetCurvature`` of MoorDyn v2)::

        kappa = 4 sin(theta / 2) / (l1 + l2),   M = EI kappa

    and M acts as forces M / l1 and M / l2 on the neighbours, normal to their elements in the plane of the
    hinge, and their opposite on the node. These are ``-M grad(theta)``: with
    ``g = M / sin(theta) = 2 EI / ((l1 + l2) cos(theta / 2))`` (smooth at theta = 0)::

        f0 = -g (b - c a) / l1,   f2 = g (a - c b) / l2,   f1 = -f0 - f2

    ``hinge_ei`` (h, H_SIZE) holds each hinge's EI in its column ``H_EI`` (:mod:`seacable.mooring._indices`).
    A line's ends are pinned (no moment), as MoorDyn's ends at points, unless a row ends it: a row
    ``(i1, i1, i2)`` or ``(i0, i1, i1)`` is an end hinge at the end node ``i1`` with its one neighbour
    (:func:`end_bending_loads`: a clamp or a rotational spring). When ``band`` has rows, ``K = -df/dx`` of
    the nine node pairs is added for the free nodes (exact: it couples ``i0`` with ``i2``, which the caller's
    band width allows for).

    A hinge with a nonlinear law ``M(kappa)`` (``hinge_ei[h, H_NLAW] > 0``, :func:`hinge_law`) acts with the exact
    gradient of its stored energy ``U = L0 W(kappa)``, ``L0`` the hinge's unstretched length (``H_L0``: the mean of
    its elements'), ``W`` the law's energy per length and ``kappa = 2 sin(theta / 2) / L0``: ``f = -U_c grad(c)``,
    ``U_c = dU/dc = -M / (2 sin(theta / 2))``, the forms above with ``g = -U_c = sigma / L0`` (``sigma = M / kappa``,
    smooth at theta = 0) and ``dg/dc = -U_cc = -q / L0^3`` (``q`` of :func:`hinge_law`), ``dg/dl = 0``: a symmetric
    tangent, the Hessian of U. A linear hinge keeps MoorDyn's ``-EI kappa grad(theta)`` on the stretched lengths,
    the same to ``O(theta^2)`` (the factor ``cos(theta / 2)``) and the strain.
    """
    jac = band.shape[0] > 0
    a, b, u, w = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    Pa, Pb = np.zeros((3, 3)), np.zeros((3, 3))
    Da = np.zeros((3, 3, 3))      # d a / d r_k
    Db = np.zeros((3, 3, 3))      # d b / d r_k
    dl1 = np.zeros((3, 3))        # d l1 / d r_k
    dl2 = np.zeros((3, 3))
    dg = np.zeros(3)
    du, dw, blk = np.zeros((3, 3)), np.zeros((3, 3)), np.zeros((3, 3))
    J = np.zeros((3, 3, 3, 3))    # J[m, k] = d f_m / d r_k
    for h in range(hinges.shape[0]):
        i0, i1, i2 = hinges[h, 0], hinges[h, 1], hinges[h, 2]
        if i0 == i1 or i1 == i2:
            end_bending_loads(X, i1, i2 if i0 == i1 else i0, hinge_ei[h], F, band, bw, fidx)
            continue
        l1 = l2 = 0.0
        for r in range(3):
            a[r] = X[i1, r] - X[i0, r]
            b[r] = X[i2, r] - X[i1, r]
            l1 += a[r] * a[r]
            l2 += b[r] * b[r]
        l1, l2 = math.sqrt(l1), math.sqrt(l2)
        if l1 <= 0.0 or l2 <= 0.0:
            continue  # coincident nodes: no direction, no moment
        c = 0.0
        for r in range(3):
            a[r] /= l1
            b[r] /= l2
            c += a[r] * b[r]
        if c <= -1.0 + 1e-9:
            continue  # folded back on itself: the moment's plane is undefined
        law = hinge_ei[h, H_NLAW] > 0.0
        lh = 1.0
        ql = 0.0
        if law:
            lh = hinge_ei[h, H_L0]
            dd = 0.0
            for r in range(3):
                dd += (b[r] - a[r]) ** 2
            kappa = math.sqrt(dd) / lh   # 2 sin(theta / 2) / L0, accurate at small angles
            _, _, _, sigma, ql = hinge_law(hinge_ei[h], kappa)
            g = sigma / lh
        else:
            ei = hinge_ei[h, H_EI]
            g = 2.0 * ei / ((l1 + l2) * math.sqrt(0.5 * (1.0 + c)))
        for r in range(3):
            u[r] = (b[r] - c * a[r]) / l1
            w[r] = (a[r] - c * b[r]) / l2
            F[i0, r] -= g * u[r]
            F[i2, r] += g * w[r]
            F[i1, r] += g * (u[r] - w[r])
        if not jac:
            continue
        for r in range(3):
            for q in range(3):
                d = 1.0 if r == q else 0.0
                Pa[r, q] = (d - a[r] * a[q]) / l1
                Pb[r, q] = (d - b[r] * b[q]) / l2
        Da[:] = 0.0
        Db[:] = 0.0
        dl1[:] = 0.0
        dl2[:] = 0.0
        for r in range(3):
            for q in range(3):
                Da[0, r, q] = -Pa[r, q]
                Da[1, r, q] = Pa[r, q]
                Db[1, r, q] = -Pb[r, q]
                Db[2, r, q] = Pb[r, q]
            dl1[0, r], dl1[1, r] = -a[r], a[r]
            dl2[1, r], dl2[2, r] = -b[r], b[r]
        if law:
            gc = -ql / (lh * lh * lh)     # dg/dc = -U_cc
            gl = 0.0                      # L0 does not stretch
        else:
            gc = -g / (2.0 * (1.0 + c))   # dg/dc
            gl = -g / (l1 + l2)           # dg/dl1 = dg/dl2
        for k in range(3):
            # dg/dr_k (a row), du/dr_k and dw/dr_k (3x3), from c = a.b, u(a, b, l1), w(a, b, l2)
            for q in range(3):
                s = 0.0
                for r in range(3):
                    s += b[r] * Da[k, r, q] + a[r] * Db[k, r, q]
                dg[q] = gc * s + gl * (dl1[k, q] + dl2[k, q])
            for r in range(3):
                for q in range(3):
                    sa = sb = sa2 = sb2 = 0.0
                    for p in range(3):
                        d = 1.0 if r == p else 0.0
                        # du/da = -(c I + a b^T) / l1, du/db = (I - a a^T) / l1
                        sa += -(c * d + a[r] * b[p]) * Da[k, p, q]
                        sb += (d - a[r] * a[p]) * Db[k, p, q]
                        # dw/da = (I - b b^T) / l2, dw/db = -(c I + b a^T) / l2
                        sa2 += (d - b[r] * b[p]) * Da[k, p, q]
                        sb2 += -(c * d + b[r] * a[p]) * Db[k, p, q]
                    du[r, q] = (sa + sb) / l1 - u[r] * dl1[k, q] / l1
                    dw[r, q] = (sa2 + sb2) / l2 - w[r] * dl2[k, q] / l2
            for r in range(3):
                for q in range(3):
                    J[0, k, r, q] = -(u[r] * dg[q] + g * du[r, q])
                    J[2, k, r, q] = w[r] * dg[q] + g * dw[r, q]
                    J[1, k, r, q] = -J[0, k, r, q] - J[2, k, r, q]
        nodes = (i0, i1, i2)
        for m in range(3):
            fm = fidx[nodes[m]]
            if fm < 0:
                continue
            for k in range(3):
                for r in range(3):
                    for q in range(3):
                        blk[r, q] = J[m, k, r, q]
                _add_block(band, bw, fm, fidx[nodes[k]], -1.0, blk)


@njit(cache=True)
def end_bending_loads(X, ie, iw, row, F, band, bw, fidx):
    """The bending moment at a line's end node ``ie`` held at a given direction: a clamp or a rotational spring.

    The end hinge lies between the end's given direction ``e`` (``row[H_D:H_D + 3]``, a unit vector from the
    end into the line: the line's tangent there, turned to point into the line at end B) and the end element
    to the neighbour ``iw``, of stretched length ``l`` and unit vector ``b`` from ``ie`` to ``iw``. With
    ``c = cos(theta) = e . b``, the moment is that of a clamp::

        kappa = 2 sin(theta / 2) / (l / 2) = 4 sin(theta / 2) / l,   M = EI kappa

    (the inner hinge's ``4 sin(theta / 2) / (l1 + l2)`` with a virtual element of no length along ``e``: the
    end node's share of line is the half element ``l / 2``; for small angles ``2 theta / l``, the central
    difference of the slope with a ghost node mirrored about ``e``, the second-order clamped boundary of finite
    differences). A rotational spring ``k`` between the holder and the line's end tangent sits in series with
    that half element's bending, whose compliance the clamp's law gives as ``l / (2 EI)``, so that
    ``theta = M / k + M l / (2 EI)``::

        M = k_e theta,   k_e = 1 / (1 / k + l / (2 EI))

    (k -> infinity: the clamp to O(theta^3); k -> 0: a pin). Like an inner hinge's, its forces are
    ``-M grad(theta)``: with ``g = M / sin(theta)``, ``2 EI / (l cos(theta / 2))`` (clamp) or
    ``k_e theta / sin(theta)`` (spring), both smooth at theta = 0, and ``w = (e - c b) / l``::

        f_w = g w on the neighbour,   f_e = -f_w on the end node

    a couple of moment ``M`` that turns the element towards ``e``; the end's holder (an anchor, a fairlead,
    a body) takes ``f_e`` and the reaction moment ``-M``. When ``band`` has rows, ``K = -df/dx`` is added for
    the free nodes, exact: ``d f_w / d x_w = w (g_c w + g_l b)^T - g (b w^T + w b^T + c (I - b b^T) / l) / l``
    with ``g_c = dg/dc``, ``g_l = dg/dl``, and ``d f_w / d x_e = -d f_w / d x_w``.

    A clamp with a nonlinear law (``row[H_NLAW] > 0``) acts, as an inner hinge with one (:func:`bending_loads`), with
    the gradient of ``U = L0 W(kappa)`` over the unstretched half element ``L0`` (``row[H_L0]``), ``kappa = 2 sin(theta
    / 2) / L0``: ``g = sigma / L0``, ``g_c = -q / L0^3``, ``g_l = 0``. A spring end takes the linear law of its
    row's EI (a spring end over a nonlinear law is refused before a run).
    """
    b = np.zeros(3)
    w = np.zeros(3)
    l = 0.0
    for r in range(3):
        b[r] = X[iw, r] - X[ie, r]
        l += b[r] * b[r]
    l = math.sqrt(l)
    if l <= 0.0:
        return  # coincident nodes: no direction, no moment
    c = 0.0
    dd = 0.0
    for r in range(3):
        b[r] /= l
        c += row[H_D + r] * b[r]
        dd += (b[r] - row[H_D + r]) ** 2
    if c <= -1.0 + 1e-9:
        return  # folded back against its holder: the moment's plane is undefined
    ei = row[H_EI]
    law = row[H_NLAW] > 0.0 and row[H_KIND] == H_CLAMP
    if law:
        lh = row[H_L0]
        kappa = math.sqrt(dd) / lh   # 2 sin(theta / 2) / L0
        _, _, _, sigma, ql = hinge_law(row, kappa)
        g = sigma / lh
        gc = -ql / (lh * lh * lh)
        gl = 0.0
    elif row[H_KIND] == H_CLAMP:
        g = 2.0 * ei / (l * math.sqrt(0.5 * (1.0 + c)))
        gc = -g / (2.0 * (1.0 + c))
        gl = -g / l
    else:
        ke = 1.0 / (1.0 / row[H_K] + 0.5 * l / ei)
        theta = 2.0 * math.asin(min(0.5 * math.sqrt(dd), 1.0))  # accurate at small angles, as acos(c) is not
        s = math.sin(theta)
        if theta < 1e-4:  # the series of theta / sin(theta) and of its slope on c
            g = ke * (1.0 + theta * theta / 6.0)
            gc = -ke * (1.0 / 3.0 + 2.0 * theta * theta / 15.0)
        else:
            g = ke * theta / s
            gc = -ke * (s - theta * math.cos(theta)) / (s * s * s)
        gl = -g * ke / (2.0 * ei)   # dk_e/dl = -k_e^2 / (2 EI)
    for r in range(3):
        w[r] = (row[H_D + r] - c * b[r]) / l
        F[iw, r] += g * w[r]
        F[ie, r] -= g * w[r]
    if band.shape[0] == 0:
        return
    J = np.zeros((3, 3))   # d f_w / d x_w
    for r in range(3):
        for q in range(3):
            d = 1.0 if r == q else 0.0
            J[r, q] = (w[r] * (gc * w[q] + gl * b[q])
                       - g * (b[r] * w[q] + w[r] * b[q] + c * (d - b[r] * b[q]) / l) / l)
    fw, fe = fidx[iw], fidx[ie]
    _add_block(band, bw, fw, fw, -1.0, J)
    _add_block(band, bw, fw, fe, 1.0, J)
    _add_block(band, bw, fe, fw, 1.0, J)
    _add_block(band, bw, fe, fe, -1.0, J)


@njit(cache=True)
def _chord(X, a, b, tv):
    """tv <- X[b] - X[a]; returns its length. [m]"""
    l = 0.0
    for r in range(3):
        tv[r] = X[b, r] - X[a, r]
        l += tv[r] * tv[r]
    return math.sqrt(l)


@njit(cache=True)
def viscoelastic_tension(dl, ldot, L, ea_s, ba, row, dt):
    """Tension [N] of a viscoelastic element and its slopes dT/d(dl) [N/m] and dT/d(dl/dt) [N s/m].

    MoorDyn v2's model (Hall, Duong and Lozon 2023): a fast spring EA_D with damper BA_D in series with
    a slow spring EA_1 = EA_D EA_s / (EA_D - EA_s) with damper BA, so that the static stiffness is EA_s.
    The slow stretch ``y`` (MoorDyn's ``dl_1``) follows::

        (BA + BA_D) dy/dt = EA_D dl - (EA_D + EA_1) y + BA_D d(dl)/dt,    T = (EA_1 y + BA dy/dt) / L

    with ``dl`` the element's stretch [m]. Written ``dy/dt = k (u - y)`` with
    ``k = (EA_D + EA_1) / (BA + BA_D)`` and ``u = (EA_D dl + BA_D d(dl)/dt) / (EA_D + EA_1)``, it is
    integrated exactly over the step ``dt`` for ``u`` linear in time from the step's start (``row[V_U0]``,
    ``row[V_Y0]``): ``y = e y0 + (phi - e) u0 + (1 - phi) u`` with ``e = exp(-k dt)``,
    ``phi = (1 - e) / (k dt)`` (second order, unconditionally stable). ``dt`` = inf is the static limit
    (``y = u``: T = EA_s dl / L), ``dt`` = 0 the state at the step's start. A mean-load-dependent dynamic
    stiffness ``EA_D = EA_Dc + EA_D_Lm T_mean`` (MoorDyn's ``EA_s|alphaMBL|vbeta``, with the slow spring's
    tension ``EA_1 y / L`` as the mean tension, solved for EA_D) takes ``y`` at the step's start; in
    statics the mean tension is the static tension ``EA_s dl / L``.
    Writes ``y`` and ``u`` in ``row[V_Y]``, ``row[V_U]``. The caller keeps the tension >= 0 (no compression).
    """
    ead = row[V_EAD]
    if row[V_LM] > 0.0:
        if math.isinf(dt):
            # statics: the mean tension is the static one, EA_s dl / L (then y = u below is consistent)
            ead += row[V_LM] * max(ea_s * dl / L, 0.0)
        elif row[V_Y0] > 0.0:
            # EA_D = EA_Dc + EA_D_Lm EA_1(EA_D) y0 / L, solved for EA_D (the root above EA_s)
            sd = ead + ea_s + row[V_LM] * row[V_Y0] * ea_s / L
            ead = 0.5 * (sd + math.sqrt(max(sd * sd - 4.0 * ead * ea_s, 0.0)))
    ea1 = ead * ea_s / (ead - ea_s)
    bsum = ba + row[V_BAD]
    kk = ead + ea1
    u = (ead * dl + row[V_BAD] * ldot) / kk
    if bsum <= 0.0 or math.isinf(dt):
        e, phi = 0.0, 0.0
    else:
        x = kk / bsum * dt
        if x < 1e-8:
            e, phi = 1.0 - x, 1.0 - 0.5 * x
        else:
            e = math.exp(-x)
            phi = (1.0 - e) / x
    y = e * row[V_Y0] + (phi - e) * row[V_U0] + (1.0 - phi) * u
    row[V_Y] = y
    row[V_U] = u
    rate = kk / bsum * (u - y) if bsum > 0.0 else 0.0
    T = (ea1 * y + ba * rate) / L
    dtdu = (ea1 * (1.0 - phi) + ba * kk / bsum * phi) / L if bsum > 0.0 else ea1 / L
    return T, dtdu * ead / kk, dtdu * row[V_BAD] / kk


@njit(cache=True)
def viscoelastic_loads(X, V, elements, L0, EA, cdamp, visco, dt, fidx, F, tension, band, bw, cc, mpl, g):
    """Axial forces, tensions and tangents of the viscoelastic elements (``visco`` rows with EA_Dc > 0).

    Each element's slow stretch advances over ``dt`` (:func:`viscoelastic_tension`); no tension in
    compression, the switch rounded as the elastic element's: the model's tension ``T`` becomes
    ``(T + Tb)^2 / (4 Tb)`` for ``|T| < Tb`` (0 below, and 0 for a strain below ``-sband``, as the elastic
    element), with ``Tb`` a quarter of the element's weight in air (the elastic element's band
    ``EA_s sband``; in the static limit ``T = EA_s eps`` this is its rounding exactly). In statics (``dt`` = inf) the element is the elastic one at EA_s of :func:`loads`, and
    only its static slow stretch is written (the start of a time-domain run).
    """
    jac = band.shape[0] > 0
    eye = np.eye(3)
    blk = np.zeros((3, 3))
    tv = np.zeros(3)
    static = math.isinf(dt)
    for e in range(elements.shape[0]):
        if visco[e, V_EAD] <= 0.0:
            continue
        a = elements[e, 0]
        b = elements[e, 1]
        l = _chord(X, a, b, tv)
        L = L0[e]
        if static:
            viscoelastic_tension(l - L, 0.0, L, EA[e], cdamp[e], visco[e], math.inf)
            continue
        if l > 0.0:
            for r in range(3):
                tv[r] /= l
        ldot = tv[0] * (V[b, 0] - V[a, 0]) + tv[1] * (V[b, 1] - V[a, 1]) + tv[2] * (V[b, 2] - V[a, 2])
        T, kdl, kdv = viscoelastic_tension(l - L, ldot, L, EA[e], cdamp[e], visco[e], dt)
        tb = 0.25 * mpl[e] * g * L
        if T <= -tb or l - L <= -tb / EA[e] * L or (tb <= 0.0 and T <= 0.0):
            continue  # slack, or shortened beyond the elastic element's band (no compression)
        if T < tb:
            kdl *= (T + tb) / (2.0 * tb)
            kdv *= (T + tb) / (2.0 * tb)
            T = (T + tb) ** 2 / (4.0 * tb)
        tension[e] = T
        for r in range(3):
            F[a, r] += T * tv[r]
            F[b, r] -= T * tv[r]
        if jac:
            for r in range(3):
                for c in range(3):
                    tt = tv[r] * tv[c]
                    blk[r, c] = (kdl + cc * kdv) * tt + T / l * (eye[r, c] - tt)
            fa, fb = fidx[a], fidx[b]
            _add_block(band, bw, fa, fa, 1.0, blk)
            _add_block(band, bw, fb, fb, 1.0, blk)
            _add_block(band, bw, fa, fb, -1.0, blk)
            _add_block(band, bw, fb, fa, -1.0, blk)


@njit(cache=True)
def syrope_loads(X, V, elements, L0, EA, cdamp, mpl, visco, ts_lo, ts_hi, ts_x, ts_y, fidx, F, tension, band, bw,
                 cc, g):
    """Axial forces, tensions and tangents of the Syrope rope elements (``visco`` rows with a working curve).

    The elastic element of :func:`loads` with :func:`syrope_tension` in place of its table (the same
    slack rounding and damper), in a pass of its own so that lines without Syrope ropes compile as before.
    """
    jac = band.shape[0] > 0
    eye = np.eye(3)
    blk = np.zeros((3, 3))
    tv = np.zeros(3)
    for e in range(elements.shape[0]):
        if visco[e, V_WC] <= 0.0:
            continue
        a = elements[e, 0]
        b = elements[e, 1]
        l = _chord(X, a, b, tv)
        if l > 0.0:
            for r in range(3):
                tv[r] /= l
        L = L0[e]
        eps = l / L - 1.0
        sband = 0.25 * mpl[e] * g * L / EA[e]
        if eps >= sband:
            psi, dpsi, ddpsi = eps, 1.0, 0.0
            tel, kel = syrope_tension(eps, visco[e], ts_lo[e], ts_hi[e], ts_x, ts_y)
        elif eps > -sband:
            psi, dpsi, ddpsi = (eps + sband) ** 2 / (4.0 * sband), (eps + sband) / (2.0 * sband), 0.5 / sband
            tb, _ = syrope_tension(sband, visco[e], ts_lo[e], ts_hi[e], ts_x, ts_y)
            visco[e, V_TM] = visco[e, V_TM0]
            tel, kel = tb / sband * psi, tb / sband * dpsi
        else:
            visco[e, V_TM] = visco[e, V_TM0]  # a slack Syrope rope keeps its Tmax
            continue
        ldot = tv[0] * (V[b, 0] - V[a, 0]) + tv[1] * (V[b, 1] - V[a, 1]) + tv[2] * (V[b, 2] - V[a, 2])
        T = max(tel + cdamp[e] * ldot / L * dpsi, 0.0)
        tension[e] = T
        for r in range(3):
            F[a, r] += T * tv[r]
            F[b, r] -= T * tv[r]
        if jac and T > 0.0:
            kax = kel + cc * cdamp[e] * dpsi
            for r in range(3):
                for c in range(3):
                    tt = tv[r] * tv[c]
                    blk[r, c] = (kax + cdamp[e] * ldot / L * ddpsi) / L * tt + T / l * (eye[r, c] - tt)
            fa, fb = fidx[a], fidx[b]
            _add_block(band, bw, fa, fa, 1.0, blk)
            _add_block(band, bw, fb, fb, 1.0, blk)
            _add_block(band, bw, fa, fb, -1.0, blk)
            _add_block(band, bw, fb, fa, -1.0, blk)


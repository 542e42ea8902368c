"""Compiled core of the mooring finite-element model (paper 004): loads, tangents, Newmark, statics.

Nodes carry lumped masses; two-node truss elements join them. For element ``e`` from node a to b,
with unstretched length ``L``, current chord ``l`` and unit tangent ``t``::

    eps = l / L - 1,    T = EA eps + c (t . (v_b - v_a)) / L   if eps > 0, else 0  (no compression)

(an element whose line type has a strain-tension table takes ``T(eps)`` from it instead of ``EA eps``,
piecewise linear as MoorDyn's nonlinear EA, and the table's slope in place of EA in the tangent; a Syrope
rope's element takes it from the working curve of the largest mean tension so far, :func:`syrope_tension`,
with that tension as a state committed after each converged step, in a pass of its own, :func:`syrope_loads`)

(the kink at eps = 0 rounded over a strain band at which EA eps is a quarter of the element's weight;
an element of a viscoelastic line type takes its tension from MoorDyn v2's series spring-damper model
with its slow stretch as an internal state, :func:`viscoelastic_loads`, and is the elastic one at EA_s
in statics)
    f_a = T t,  f_b = -T t,
    K_e = EA / L t t^T + T / l (I - t t^T)          (paper 004 eq. A6-A10: linear plus geometric)

so that the tangent of the pair is ``[[K_e, -K_e], [-K_e, K_e]]``. A line with bending stiffness EI
adds MoorDyn v2's nodal bending moments at its inner nodes (:func:`bending_loads`, with their exact
tangent, which couples a node's two neighbours: the band is widened for it only when a line bends).
Half of each element's mass and
weight in water goes to each end; the part of a half element above the water surface (straight
from the node to the element's middle, the surface taken linear between them: the still-water level,
or with waves the instantaneous elevation eta at the node and over the middle, :func:`_surface`) gets its
buoyancy back (weight in air), and an attachment's buoyancy scales with its immersed fraction across the
instantaneous waterline; the added mass is ``rho A L/2 (C_an P_n + C_at P_t)`` with
``P_n = I - t t^T`` and ``P_t = t t^T``. A node above the instantaneous surface gets no water load.
Morison loads on each half element use the node's velocity relative to the water ``u = u_w - v``
(current plus regular Airy waves or an irregular sea interpolated from its precomputed grid, the
argument ``sea`` of :mod:`seacable.seastate`; above z = 0 the z = 0 kinematics or Wheeler stretching,
:func:`_fluid`)::

    F = 1/2 rho d L/2 (C_dn |u_n| u_n + pi C_dt |u_t| u_t) + rho A L/2 ((1 + C_an) P_n + (1 + C_at) P_t) a_w

(the tangential drag on the wetted perimeter ``pi d``, as MoorDyn). Attachments add mass, isotropic
added mass, drag ``1/2 rho C_D A |u| u`` and the Froude-Krylov force of their volume. The seabed
is a plane; a node below it gets a penalty force ``k_b d_n (penetration) - c_b d_n v_n``, rounded
over a small band of penetration so that the contact stiffness is continuous (the damper engaging
gradually, or for MoorDyn decks in full beyond the band, ``E_BEDFULL``), with ``d_n`` the sum of
``d L / 2`` of the node's elements (MoorDyn's kBot, cBot in Pa/m, Pa s/m), and Coulomb friction regularised as ``-mu N v_t / sqrt(|v_t|^2 + v_f^2)``.

Time integration: the generalised-alpha method (Chung and Hulbert 1993) with Newton iterations at
each step on the equilibrium of the free nodes at the intermediate times,

    (1 - alpha_m) M a_{n+1} + alpha_m M_n a_n - (1 - alpha_f) F(x_{n+1}, v_{n+1}) - alpha_f F_n = 0,

with Newmark's updates of x and v (beta, gamma); inertia and forces are interpolated between the
step's ends (Erlicher, Bonaventura and Bursi 2002, the form for nonlinear forces, which keeps the
viscoelastic state at the step's end). ``alpha_m = alpha_f = 0`` is Newmark's average acceleration
(beta 1/4, gamma 1/2), the default. Prescribed nodes (fairleads) move the
coupling terms to the right-hand side (the partitioned equations of paper 004 section 3). The
Jacobian ``(1 - alpha_m) M / (beta dt^2) + (1 - alpha_f) (C gamma / (beta dt) + K)`` (divided by
``1 - alpha_f``) is assembled in band storage (nodes ordered
for a small bandwidth) and factored without pivoting: it is diagonally dominated by the mass term.
A step's first correction is a full Newton one; the next reuse its factors (modified Newton) while each
cuts the residual at least tenfold, a fresh matrix otherwise; every step ends on the same force tolerance.
Statics drops the inertia and solves ``(K + lam M) dx = -R`` with ``lam`` following the residual
(pseudo-transient continuation, switched evolution relaxation), so that it starts from
a straight line.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..seastate import GRID_HEADER, S_ETAMAX, S_MODE, S_STRETCH, grid_eta, grid_point, grid_points
from ..waves import airy_linear

__all__ = ["ENV_SIZE", "V_SIZE", "alpha_history", "band_factor", "band_solve", "bending_loads", "commit_viscoelastic",
           "loads", "loads_water", "lu_solve", "n_water", "newmark_steps", "static_solve", "syrope_loads", "syrope_tension",
           "table_tension", "viscoelastic_loads", "viscoelastic_tension"]

# Environment vector layout.
E_RHO, E_G, E_DEPTH, E_SLOPE, E_KBOT, E_CBOT, E_MU, E_VFRIC = 0, 1, 2, 3, 4, 5, 6, 7
E_WH, E_WT, E_WK, E_WHEAD, E_WPHASE, E_CHEAD, E_ALPHA, E_WDEPTH = 8, 9, 10, 11, 12, 13, 14, 15
E_BEDRAMP = 16
E_VDT = 17  # the time step over which the viscoelastic elements' slow stretch advances (inf: statics) [s]
E_SLACKDAMP = 18  # 1: the axial damper acts in slack elements too (MoorDyn's rule), 0: only in taut ones
E_BEDFULL = 19  # 1: the seabed damper acts in full wherever the spring is linear (MoorDyn's rule), 0: ramped
# velocity of the frame the nodes are seen in [m/s]: the water moves past them at (its velocity) - (this), the seabed
# at -(this); 0 but in the statics of a towed system, whose steady state is a static equilibrium in the frame moving
# with the vessel
E_FRAMEX, E_FRAMEY, E_FRAMEZ = 20, 21, 22
# 1: the Newton matrix holds the drag's change with the elements' direction (:func:`_drag_turn`; a towed line, whose
# shape the drag sets), 0: not (a mooring line, whose shape its weight and tension set: the terms cost time)
E_DRAGTURN = 23
# a seabed profile: its number of points m (0: the plane of E_DEPTH and E_SLOPE); the points follow the vector's
# ENV_SIZE slots, m distances along X [m] then m seabed elevations there [m] (linear between, level beyond)
E_BEDTAB = 24
ENV_SIZE = 25

# Columns of the attachments' hydrodynamics ``pcda`` (n, 3): drag area C_D A across the line (of all directions at
# a point whose axial one is the same) and along it [m^2], and lift area C_L A [m^2], the lift
# 1/2 rho C_L A (|u|^2 e_z - (u . e_z) u) at the water's velocity u relative to the point (:func:`point_lift`)
P_CDA, P_CDA_AXIAL, P_CLA = 0, 1, 2

# Columns of the viscoelastic element table (one row per element, or none when no element is viscoelastic):
# dynamic stiffness EA_Dc [N] (0: an elastic element) and its slope on the mean tension EA_D_Lm [-], the
# fast damper BA_D [N s], and the slow stretch and its input at the start of the step (Y0, U0) and at the
# state last evaluated (Y, U) [m]
V_EAD, V_LM, V_BAD, V_Y0, V_U0, V_Y, V_U = 0, 1, 2, 3, 4, 5, 6
# and, for an element of a Syrope rope (whose strain-tension table is its original working curve), the working
# curve's form (0: none, 1: linear, 2: quadratic, 3: exponential) and its parameters k1, k2 [-] (k1 [N] for a
# linear curve with k1 >= 1), and the largest mean tension so far, Tmax, committed (TM0) and at the state last
# evaluated (TM) [N] (:func:`syrope_tension`)
V_WC, V_K1, V_K2, V_TM0, V_TM = 7, 8, 9, 10, 11
V_SIZE = 12


@njit(cache=True)
def _surface(x, y, t, env, with_waves, sea):
    """Instantaneous water surface eta [m] above (x, y) at time ``t``: the regular Airy wave's plus the
    irregular sea's (grid, :func:`seacable.seastate.grid_eta`); 0 (still water) without waves."""
    if not with_waves:
        return 0.0
    eta = 0.0
    if env[E_WH] > 0.0:
        theta = (env[E_WK] * (x * math.cos(env[E_WHEAD]) + y * math.sin(env[E_WHEAD]))
                 - 2.0 * math.pi / env[E_WT] * t + env[E_WPHASE])
        eta = 0.5 * env[E_WH] * math.cos(theta)
    if sea[S_MODE] > 0.0:
        eta += grid_eta(sea, x, y, t)
    return eta


@njit(cache=True)
def _fluid(x, t, env, cur_depth, cur_speed, with_waves, sea, u, acc):
    """Water velocity ``u`` and acceleration ``acc`` at point ``x`` and time ``t`` (current plus waves).

    Nothing above the instantaneous surface eta (:func:`_surface`). Below it, the current at the point's
    depth (its top value above z = 0) and the waves' linear kinematics (regular Airy, and an irregular sea
    from its grid ``sea``) at the linear-theory depth z' of the point: ``min(z, 0)`` (constant
    extrapolation above the still-water level, the default) or, with Wheeler stretching
    (``sea[S_STRETCH]``), ``z' = (z - eta) d / (d + eta)`` (``z - eta`` in deep water), which puts the
    surface at z' = 0 and keeps the seabed at -d.
    """
    wavy = with_waves and (env[E_WH] > 0.0 or sea[S_MODE] > 0.0)
    eta = _surface(x[0], x[1], t, env, with_waves, sea) if wavy else 0.0
    u[0], u[1], u[2], acc[0], acc[1], acc[2] = _fluid_below(x[0], x[1], x[2], t, env, cur_depth, cur_speed, wavy, sea,
                                                            eta)


@njit(cache=True)
def _fluid_below(x, y, z, t, env, cur_depth, cur_speed, wavy, sea, eta):
    """:func:`_fluid` at the point (x, y, z) with the surface ``eta`` [m] above it known (``wavy``: there are
    waves): the velocity and acceleration ``(u, v, w, ax, ay, az)`` [m/s], [m/s^2]."""
    u0, u1, u2, a0, a1, a2, zs = _water_local(x, y, z, t, env, cur_depth, cur_speed, wavy, sea, eta)
    if not math.isnan(zs):
        k0, k1, k2, k3, k4, k5 = grid_point(sea, x, y, zs, t)
        u0, u1, u2, a0, a1, a2 = u0 + k0, u1 + k1, u2 + k2, a0 + k3, a1 + k4, a2 + k5
    return u0, u1, u2, a0, a1, a2


@njit(cache=True)
def _water_local(x, y, z, t, env, cur_depth, cur_speed, wavy, sea, eta):
    """:func:`_fluid_below` but for the irregular sea's grid: the current's and the regular wave's velocity and
    acceleration, and the linear-theory depth at which to look the grid up (NaN: no look-up, the point above
    the surface or no irregular sea): ``(u, v, w, ax, ay, az, zs)``."""
    if z > eta:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, math.nan
    if cur_depth.size == 1:
        speed = cur_speed[0]
    else:
        speed = np.interp(-z, cur_depth, cur_speed)
    u0 = u1 = u2 = a0 = a1 = a2 = 0.0
    if speed != 0.0:
        u0 = speed * math.cos(env[E_CHEAD])
        u1 = speed * math.sin(env[E_CHEAD])
    u0, u1, u2 = u0 - env[E_FRAMEX], u1 - env[E_FRAMEY], u2 - env[E_FRAMEZ]
    if not wavy:
        return u0, u1, u2, a0, a1, a2, math.nan
    d = env[E_WDEPTH]
    if sea[S_STRETCH] > 0.0:
        zs = (z - eta) * d / (d + eta) if math.isfinite(d) else z - eta
    else:
        zs = min(z, 0.0)
    zs = max(min(zs, 0.0), -d)
    if env[E_WH] > 0.0:
        k0, k1, k2, k3, k4, k5 = airy_linear(x, y, zs, t, env[E_WH], env[E_WT], env[E_WK], d, env[E_WHEAD],
                                             env[E_WPHASE], env[E_G])
        u0, u1, u2, a0, a1, a2 = u0 + k0, u1 + k1, u2 + k2, a0 + k3, a1 + k4, a2 + k5
    return u0, u1, u2, a0, a1, a2, zs if sea[S_MODE] > 0.0 else math.nan


@njit(cache=True)
def _dry_fraction(z0, z1):
    """Fraction of the straight piece from height z0 to z1 above the water surface that lies above it.

    The heights are taken from the instantaneous surface (``z - eta`` at each end, the surface taken
    linear between them; still water: eta = 0).
    """
    lo, hi = min(z0, z1), max(z0, z1)
    if hi <= 0.0:
        return 0.0
    if lo >= 0.0:
        return 1.0
    return hi / (hi - lo)


@njit(cache=True)
def _add_block(band, bw, fi, fj, coef, blk):
    if fi < 0 or fj < 0:
        return
    for r in range(3):
        row = 3 * fi + r
        for c in range(3):
            band[row, bw + 3 * fj + c - row] += coef * blk[r, c]


@njit(cache=True)
def _add_block_sym(band, bw, i, j, sign, k00, k01, k02, k11, k12, k22):
    """``sign`` times the symmetric 3 x 3 block (k00 k01 k02 / . k11 k12 / . . k22) added to the band at the
    rows of free node ``i`` and the columns of free node ``j``."""
    r = 3 * i
    o = bw + 3 * (j - i)
    band[r, o] += sign * k00
    band[r, o + 1] += sign * k01
    band[r, o + 2] += sign * k02
    band[r + 1, o - 1] += sign * k01
    band[r + 1, o] += sign * k11
    band[r + 1, o + 1] += sign * k12
    band[r + 2, o - 2] += sign * k02
    band[r + 2, o - 1] += sign * k12
    band[r + 2, o] += sign * k22


@njit(cache=True)
def _add_pair(band, bw, fa, fb, k00, k01, k02, k11, k12, k22):
    """An element's tangent [[K, -K], [-K, K]] (K symmetric, its upper entries given) added to the band at the
    rows of its free nodes ``fa`` and ``fb`` (-1: not free)."""
    if fa >= 0:
        _add_block_sym(band, bw, fa, fa, 1.0, k00, k01, k02, k11, k12, k22)
        if fb >= 0:
            _add_block_sym(band, bw, fa, fb, -1.0, k00, k01, k02, k11, k12, k22)
    if fb >= 0:
        _add_block_sym(band, bw, fb, fb, 1.0, k00, k01, k02, k11, k12, k22)
        if fa >= 0:
            _add_block_sym(band, bw, fb, fa, -1.0, k00, k01, k02, k11, k12, k22)


@njit(cache=True)
def _drag_tangent(un, cd, out, coef):
    """out += coef * cd * d(|u| u)/du restricted to the subspace of ``un`` (out is 3x3)."""
    mag = math.sqrt(un[0] ** 2 + un[1] ** 2 + un[2] ** 2)
    if mag <= 0.0:
        return
    for r in range(3):
        for c in range(3):
            out[r, c] += coef * cd * un[r] * un[c] / mag


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

    The line's ends at points are pinned (no moment), as MoorDyn's ends at points. When ``band`` has
    rows, ``K = -df/dx`` of the nine node pairs is added for the free nodes (exact: it couples ``i0`` with
    ``i2``, which the caller's band width allows for).
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
        ei = hinge_ei[h]
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


@njit(cache=True)
def seabed_at(env, x):
    """Seabed elevation [m] and slope dz/dx [-] at distance ``x`` along X of the profile held in ``env``
    (``E_BEDTAB`` points; level beyond its ends), or of the plane (``E_DEPTH``, ``E_SLOPE``) without one."""
    m = int(env[E_BEDTAB])
    if m == 0:
        t = math.tan(env[E_SLOPE])
        return -env[E_DEPTH] + t * x, t
    x0 = ENV_SIZE
    z0 = ENV_SIZE + m
    if x <= env[x0]:
        return env[z0], 0.0
    if x >= env[x0 + m - 1]:
        return env[z0 + m - 1], 0.0
    lo, hi = 0, m - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if env[x0 + mid] <= x:
            lo = mid
        else:
            hi = mid
    slope = (env[z0 + hi] - env[z0 + lo]) / (env[x0 + hi] - env[x0 + lo])
    return env[z0 + lo] + slope * (x - env[x0 + lo]), slope


@njit(cache=True)
def _point_drag_split(u, qn, qa, tsum, f, out):
    """Drag of an attachment across and along the line, ``qn |u_n| u_n + qa |u_t| u_t`` (``qn``, ``qa``: 1/2 rho
    C_D A of each), added to ``f`` (3,); ``u`` the water's velocity relative to the point, ``tsum`` the sum of its
    elements' unit tangents (zero: no direction, the isotropic drag at ``qn``). ``out`` (3, 3) receives the
    tangent -df/dv = qn (|u_n| P_n + u_n u_n^T / |u_n|) + 2 qa |u_t| t t^T."""
    m = math.sqrt(tsum[0] ** 2 + tsum[1] ** 2 + tsum[2] ** 2)
    out[:] = 0.0
    if m <= 0.0:
        mag = math.sqrt(u[0] ** 2 + u[1] ** 2 + u[2] ** 2)
        for r in range(3):
            f[r] += qn * mag * u[r]
            out[r, r] += qn * mag
        _drag_tangent(u, 1.0, out, qn)
        return
    t0, t1, t2 = tsum[0] / m, tsum[1] / m, tsum[2] / m
    ut = u[0] * t0 + u[1] * t1 + u[2] * t2
    n0, n1, n2 = u[0] - ut * t0, u[1] - ut * t1, u[2] - ut * t2
    mn = math.sqrt(n0 * n0 + n1 * n1 + n2 * n2)
    f[0] += qn * mn * n0 + qa * abs(ut) * ut * t0
    f[1] += qn * mn * n1 + qa * abs(ut) * ut * t1
    f[2] += qn * mn * n2 + qa * abs(ut) * ut * t2
    tv = (t0, t1, t2)
    nv = (n0, n1, n2)
    cun = qn / mn if mn > 0.0 else 0.0
    for r in range(3):
        for c in range(3):
            pn = (1.0 if r == c else 0.0) - tv[r] * tv[c]
            out[r, c] = qn * mn * pn + cun * nv[r] * nv[c] + 2.0 * qa * abs(ut) * tv[r] * tv[c]


@njit(cache=True)
def _drag_turn(band, bw, fk, fa, fb, qn, qt, r0, r1, r2, t0, t1, t2, l, jt, blk):
    """The Newton matrix's terms of a half element's drag turning with the element: K += -dF/dx at node k's row
    (free index ``fk``), the columns of the element's ends a and b (``fa``, ``fb``; -1: prescribed).

    With the water's relative velocity u, ``a = u . t``, ``u_n = u - a t``, the drag
    ``F = qn |u_n| u_n + qt |a| a t`` (qn = 1/2 rho d L/2 C_dn, qt = the same with pi C_dt) changes with t as
    ``dF/dt = -qn (|u_n| I + u_n u_n^T / |u_n|) (t u^T + a I) + qt |a| (2 t u^T + a I)``, and t with the ends as
    ``dt/dx_b = -dt/dx_a = (I - t t^T) / l``."""
    if fk < 0 or l <= 0.0:
        return
    a = r0 * t0 + r1 * t1 + r2 * t2
    n0, n1, n2 = r0 - a * t0, r1 - a * t1, r2 - a * t2
    mn = math.sqrt(n0 * n0 + n1 * n1 + n2 * n2)
    tv = (t0, t1, t2)
    uv = (r0, r1, r2)
    nv = (n0, n1, n2)
    cun = qn / mn if mn > 0.0 else 0.0
    for r in range(3):
        for c in range(3):
            blk[r, c] = 0.0
    for r in range(3):
        for m in range(3):
            dn = qn * mn * (1.0 if r == m else 0.0) + cun * nv[r] * nv[m]
            for c in range(3):
                blk[r, c] -= dn * (tv[m] * uv[c] + (a if m == c else 0.0))
        for c in range(3):
            blk[r, c] += qt * abs(a) * (2.0 * tv[r] * uv[c] + (a if r == c else 0.0))
    # jt = dF/dt (I - t t^T) / l
    for r in range(3):
        for c in range(3):
            v = 0.0
            for m in range(3):
                v += blk[r, m] * ((1.0 if m == c else 0.0) - tv[m] * tv[c])
            jt[r, c] = v / l
    if fb >= 0:
        _add_block(band, bw, fk, fb, -1.0, jt)
    if fa >= 0:
        _add_block(band, bw, fk, fa, 1.0, jt)


@njit(cache=True)
def point_lift(u, ql, f, out):
    """Lift ``ql (|u|^2 e_z - u_z u)`` of an attachment (``ql`` = 1/2 rho C_L A, positive up) added to ``f`` (3,),
    at the water's velocity ``u`` relative to it: across the flow, in the vertical plane through it, of size
    ``ql |u| |u_h|`` (``ql U^2`` in a horizontal flow, none in a vertical one, smoothly: no direction is singular).
    ``out`` (3, 3) receives -df/dv = df/du = ql (2 e_z u^T - u_z I - u e_z^T)."""
    uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2]
    uz = u[2]
    f[0] -= ql * uz * u[0]
    f[1] -= ql * uz * u[1]
    f[2] += ql * (uu - uz * uz)
    for r in range(3):
        for c in range(3):
            out[r, c] = ql * ((2.0 * u[c] if r == 2 else 0.0) - (uz if r == c else 0.0) - (u[r] if c == 2 else 0.0))


@njit(cache=True)
def loads(X, V, t, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat,
          weight, pmass, padd, pvol, pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco,
          fidx, env, cur_depth, cur_speed, with_waves, sea,
          F, M, tension, band, bw, cm, cc):
    """Forces on the nodes (all but inertia and supports), node masses, and the Newton matrix.

    Fills ``F`` (n, 3) with internal, gravity, hydrodynamic and seabed forces, ``M`` (n, 3, 3) with the
    node mass including added mass, ``tension`` (e,) and, when ``band`` has rows, adds
    ``cm M + cc C + K`` (C = -dF/dv, K = -dF/dx) for the free nodes (``fidx`` >= 0) in band storage.
    ``hinges`` (h, 3) and ``hinge_ei`` (h,) are the inner nodes of lines with bending stiffness
    (:func:`bending_loads`; none: a truss); ``visco`` (e, V_SIZE) the viscoelastic elements
    (:func:`viscoelastic_tension`, advanced over ``env[E_VDT]``; no rows: none).
    """
    water = np.zeros((n_water(X, env, cur_depth, with_waves, sea), 7))
    loads_water(X, V, t, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda, bedc,
                buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth, cur_speed,
                with_waves, sea, F, M, tension, band, bw, cm, cc, water, True)


@njit(cache=True)
def n_water(X, env, cur_depth, with_waves, sea):
    """Rows of the water array of :func:`loads_water`: one a node, or none in still water with a current
    uniform over depth (the same water velocity at every immersed point)."""
    wavy = with_waves and (env[E_WH] > 0.0 or sea[S_MODE] > 0.0)
    return 0 if not wavy and cur_depth.size == 1 else X.shape[0]


@njit(cache=True)
def loads_water(X, V, t, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat,
                weight, pmass, padd, pvol, pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco,
                fidx, env, cur_depth, cur_speed, with_waves, sea,
                F, M, tension, band, bw, cm, cc, water, fresh):
    """:func:`loads` with the water over each node in ``water`` (:func:`n_water` rows: the surface eta, the
    velocity (3) and the acceleration (3) of the water at the node), computed here when ``fresh``, else those
    it holds (of the same time, at nearby positions: a Newton iteration's start)."""
    wavy = with_waves and (env[E_WH] > 0.0 or sea[S_MODE] > 0.0)  # else the surface is z = 0 everywhere
    nvis = visco.shape[0]
    vstatic = math.isinf(env[E_VDT])
    sdamp = env[E_SLACKDAMP] > 0.0
    n = X.shape[0]
    rho = env[E_RHO]
    pdia = pvol  # the attachments' sphere diameters, needed (and computed) only when one has a buoyancy
    for i in range(n):
        if pbuoy[i] != 0.0:
            pdia = (6.0 / math.pi * pvol) ** (1.0 / 3.0)
            break
    F[:] = 0.0
    M[:] = 0.0
    tension[:] = 0.0
    jac = band.shape[0] > 0
    turn = env[E_DRAGTURN] > 0.0
    # the small work arrays in two allocations (a call's fixed cost: 14 allocations were about 1 us)
    mats = np.zeros((3, 3, 3))
    eye, blk, hb = mats[0], mats[1], mats[2]
    eye[0, 0] = eye[1, 1] = eye[2, 2] = 1.0
    vecs = np.zeros((6, 3))
    uw, aw, ur, vt, nrm, origin = vecs[0], vecs[1], vecs[2], vecs[3], vecs[4], vecs[5]
    # still water and a current uniform over depth: the same water velocity at every immersed point
    uniform = not wavy and cur_depth.size == 1
    if uniform:
        _fluid(origin, t, env, cur_depth, cur_speed, with_waves, sea, uw, aw)
    # otherwise the surface over each node and the water's velocity and acceleration there, once per node (the
    # two elements of a node see the same): columns eta, u (3), a (3)
    # an irregular sea alone without stretching: below its lowest trough (-S_ETAMAX) the surface tells nothing
    # (a point there is wet, its kinematics those of its depth) and is not looked up
    below = -math.inf
    if wavy and env[E_WH] <= 0.0 and sea[S_STRETCH] <= 0.0:
        below = -sea[S_ETAMAX]
    if fresh and water.shape[0] > 0:
        # the current's and a regular wave's part node by node, then the irregular sea's grid at all nodes at once
        nw = water.shape[0]
        zs = np.empty(nw)
        # an irregular sea alone (no regular wave, no stretching) and a uniform current: _water_local's few lines
        # here (its call, with its arrays, cost as much as the grid's look-up)
        plain = wavy and env[E_WH] <= 0.0 and sea[S_STRETCH] <= 0.0 and cur_depth.size == 1
        cu = cur_speed[0] * math.cos(env[E_CHEAD]) - env[E_FRAMEX]
        cv = cur_speed[0] * math.sin(env[E_CHEAD]) - env[E_FRAMEY]
        for k in range(nw):
            water[k, 0] = _surface(X[k, 0], X[k, 1], t, env, with_waves, sea) if wavy and X[k, 2] >= below else 0.0
            if not plain:
                water[k, 1], water[k, 2], water[k, 3], water[k, 4], water[k, 5], water[k, 6], zs[k] = _water_local(
                    X[k, 0], X[k, 1], X[k, 2], t, env, cur_depth, cur_speed, wavy, sea, water[k, 0])
            elif X[k, 2] > water[k, 0]:  # out of the water
                water[k, 1] = water[k, 2] = water[k, 3] = water[k, 4] = water[k, 5] = water[k, 6] = 0.0
                zs[k] = math.nan
            else:
                water[k, 1], water[k, 2], water[k, 3] = cu, cv, -env[E_FRAMEZ]
                water[k, 4] = water[k, 5] = water[k, 6] = 0.0
                zs[k] = max(min(X[k, 2], 0.0), -env[E_WDEPTH])
        if wavy and sea[S_MODE] > 0.0:
            kin = np.empty((nw, 6))
            grid_points(sea, X, zs, t, kin)
            for k in range(nw):
                for r in range(6):
                    water[k, 1 + r] += kin[k, r]
    # an attachment whose drag along the line differs from its drag across: the line's direction at its node
    split = False
    for i in range(n):
        if pcda[i, P_CDA_AXIAL] != pcda[i, P_CDA]:
            split = True
    tnode = np.zeros((n if split else 0, 3))
    for e in range(elements.shape[0]):
        a = elements[e, 0]
        b = elements[e, 1]
        d0, d1, d2 = X[b, 0] - X[a, 0], X[b, 1] - X[a, 1], X[b, 2] - X[a, 2]
        l = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        if l > 0.0:
            t0, t1, t2 = d0 / l, d1 / l, d2 / l  # the unit tangent, in scalars (see the half elements below)
        else:
            t0 = t1 = t2 = 0.0  # coincident nodes: no direction, no tension (a folded slack line)
        if split:
            for k in (a, b):
                tnode[k, 0] += t0
                tnode[k, 1] += t1
                tnode[k, 2] += t2
        L = L0[e]
        eps = l / L - 1.0
        # tension-only law rounded over |eps| < sband (C1, so that Newton does not cycle between slack and
        # taut; the tangent below includes the rounding of the damper): EA sband is a quarter of the
        # element's weight in air, so the rounding adds at most 1/16 of that weight to a tension (at
        # eps = 0), below the lumped model's own resolution (tensions step by an element's weight from
        # element to element of a hanging line), and nothing once eps > sband
        sband = 0.25 * mpl[e] * env[E_G] * L / EA[e]
        if eps >= sband:
            psi, dpsi, ddpsi = eps, 1.0, 0.0
        elif eps > -sband:
            psi, dpsi, ddpsi = (eps + sband) ** 2 / (4.0 * sband), (eps + sband) / (2.0 * sband), 0.5 / sband
        else:
            psi, dpsi, ddpsi = 0.0, 0.0, 0.0
        tab = ts_hi[e] > ts_lo[e]
        tel = kel = 0.0
        if tab and dpsi > 0.0:
            # a strain-tension table: T(eps) and its slope beyond the band; within it the same quadratic
            # rounding, scaled to the table's secant at eps = sband (continuous tension)
            if eps >= sband:
                tel, kel = table_tension(eps, ts_lo[e], ts_hi[e], ts_x, ts_y)
            else:
                tb, _ = table_tension(sband, ts_lo[e], ts_hi[e], ts_x, ts_y)
                tel, kel = tb / sband * psi, tb / sband * dpsi
        if (dpsi > 0.0 or sdamp and l > 0.0) and not (nvis > 0 and (visco[e, V_EAD] > 0.0 and not vstatic
                                                                   or visco[e, V_WC] > 0.0)):
            ldot = t0 * (V[b, 0] - V[a, 0]) + t1 * (V[b, 1] - V[a, 1]) + t2 * (V[b, 2] - V[a, 2])
            # the damper: rounded with the spring (0 in a slack element), or with ``sdamp`` (MoorDyn's rule)
            # the whole ``cdamp ldot / L`` whatever the strain, so that a slack element resists its rate of
            # shortening (an axial force that may be compressive)
            cd = cdamp[e] if sdamp else cdamp[e] * dpsi
            if tab:
                T = tel + cd * ldot / L
            else:
                T = EA[e] * psi + cd * ldot / L
            if not sdamp:
                T = max(T, 0.0)
            tension[e] = T
            F[a, 0] += T * t0
            F[a, 1] += T * t1
            F[a, 2] += T * t2
            F[b, 0] -= T * t0
            F[b, 1] -= T * t1
            F[b, 2] -= T * t2
            if jac and T != 0.0:
                # axial stiffness plus damper: the table's slope, or EA (the same operations as before tables)
                if sdamp:
                    kax = kel + cc * cd if tab else EA[e] * dpsi + cc * cd
                    ka = kax / L
                else:
                    kax = kel + cc * cdamp[e] * dpsi if tab else (EA[e] + cc * cdamp[e]) * dpsi
                    ka = (kax + cdamp[e] * ldot / L * ddpsi) / L
                kg = T / l
                # the pair's tangent [[K_e, -K_e], [-K_e, K_e]], K_e = ka t t^T + kg (I - t t^T), into the band
                g = ka - kg
                _add_pair(band, bw, fidx[a], fidx[b], kg + g * t0 * t0, g * t0 * t1, g * t0 * t2, kg + g * t1 * t1,
                          g * t1 * t2, kg + g * t2 * t2)
        area = 0.25 * math.pi * dia[e] ** 2
        half = 0.5 * L
        zmid = 0.5 * (X[a, 2] + X[b, 2])
        # the water surface over the element's middle (0: still water; with waves the instantaneous eta)
        emid = _surface(0.5 * (X[a, 0] + X[b, 0]), 0.5 * (X[a, 1] + X[b, 1]), t, env, with_waves, sea) \
            if wavy and max(X[a, 2], X[b, 2]) >= below else 0.0
        # the half elements' loads in scalars (work vectors would be arrays, which stores into F, M and the band
        # could alias: each would be read again after every store)
        qd = 0.5 * rho * dia[e] * half
        ma = rho * area * half
        mh = mpl[e] * half
        mc, md = ma * can[e], ma * (cat[e] - can[e])  # added mass ma (C_an P_n + C_at P_t) = mc I + md t t^T
        for k in (a, b):
            M[k, 0, 0] += mh
            M[k, 1, 1] += mh
            M[k, 2, 2] += mh
            # ``weight`` holds the weight in water; the part of this half element above the instantaneous
            # surface (straight from the node to the element's middle, the surface linear between) loses its
            # buoyancy
            ek = water[k, 0] if wavy else 0.0
            dry = _dry_fraction(X[k, 2] - ek, zmid - emid)
            if dry > 0.0:
                F[k, 2] -= dry * buoy[e] * half
            if X[k, 2] > ek:
                continue  # out of the water: no hydrodynamic load
            if uniform:
                w0, w1, w2, b0, b1, b2 = uw[0], uw[1], uw[2], aw[0], aw[1], aw[2]
            else:
                w0, w1, w2, b0, b1, b2 = water[k, 1], water[k, 2], water[k, 3], water[k, 4], water[k, 5], water[k, 6]
            r0, r1, r2 = w0 - V[k, 0], w1 - V[k, 1], w2 - V[k, 2]  # the water's velocity relative to the node
            ut_s = r0 * t0 + r1 * t1 + r2 * t2
            n0, n1, n2 = r0 - ut_s * t0, r1 - ut_s * t1, r2 - ut_s * t2  # its normal part
            mn = math.sqrt(n0 * n0 + n1 * n1 + n2 * n2)
            mt = abs(ut_s)
            if wavy:  # the water's acceleration (Froude-Krylov and added mass); none in still water
                at_s = b0 * t0 + b1 * t1 + b2 * t2
                fn_, ft_ = ma * (1.0 + can[e]), ma * (1.0 + cat[e]) * at_s
                F[k, 0] += fn_ * (b0 - at_s * t0) + ft_ * t0
                F[k, 1] += fn_ * (b1 - at_s * t1) + ft_ * t1
                F[k, 2] += fn_ * (b2 - at_s * t2) + ft_ * t2
            dn, dt_ = qd * cdn[e] * mn, qd * math.pi * cdt[e] * mt * ut_s
            F[k, 0] += dn * n0 + dt_ * t0
            F[k, 1] += dn * n1 + dt_ * t1
            F[k, 2] += dn * n2 + dt_ * t2
            if jac and turn:
                _drag_turn(band, bw, fidx[k], fidx[a], fidx[b], qd * cdn[e], qd * math.pi * cdt[e], r0, r1, r2, t0,
                           t1, t2, l, blk, hb)
            M[k, 0, 0] += mc + md * t0 * t0
            M[k, 0, 1] += md * t0 * t1
            M[k, 0, 2] += md * t0 * t2
            M[k, 1, 0] += md * t1 * t0
            M[k, 1, 1] += mc + md * t1 * t1
            M[k, 1, 2] += md * t1 * t2
            M[k, 2, 0] += md * t2 * t0
            M[k, 2, 1] += md * t2 * t1
            M[k, 2, 2] += mc + md * t2 * t2
            if jac and fidx[k] >= 0 and cc != 0.0:
                # the drag's tangent -dF/dv = qd (C_dn (|u_n| P_n + u_n u_n^T / |u_n|) + 2 pi C_dt |u_t| t t^T)
                # (d(|u| u)/du in the normal plane and along the tangent), straight into the node's block:
                # cnm I + ctt t t^T + cun u_n u_n^T, ctt the tangential part 2 pi C_dt |u_t| less the normal one
                cn = cc * qd * cdn[e]
                cnm = cn * mn
                cun = cn / mn if mn > 0.0 else 0.0
                ctt = cc * qd * 2.0 * math.pi * cdt[e] * mt - cnm
                row0 = 3 * fidx[k]
                band[row0, bw] += cnm + ctt * t0 * t0 + cun * n0 * n0
                band[row0, bw + 1] += ctt * t0 * t1 + cun * n0 * n1
                band[row0, bw + 2] += ctt * t0 * t2 + cun * n0 * n2
                band[row0 + 1, bw - 1] += ctt * t1 * t0 + cun * n1 * n0
                band[row0 + 1, bw] += cnm + ctt * t1 * t1 + cun * n1 * n1
                band[row0 + 1, bw + 1] += ctt * t1 * t2 + cun * n1 * n2
                band[row0 + 2, bw - 2] += ctt * t2 * t0 + cun * n2 * n0
                band[row0 + 2, bw - 1] += ctt * t2 * t1 + cun * n2 * n1
                band[row0 + 2, bw] += cnm + ctt * t2 * t2 + cun * n2 * n2
    if nvis > 0:
        viscoelastic_loads(X, V, elements, L0, EA, cdamp, visco, env[E_VDT], fidx, F, tension, band, bw, cc, mpl,
                           env[E_G])
        syrope_loads(X, V, elements, L0, EA, cdamp, mpl, visco, ts_lo, ts_hi, ts_x, ts_y, fidx, F, tension, band,
                     bw, cc, env[E_G])
    if hinges.shape[0] > 0:
        bending_loads(X, hinges, hinge_ei, F, band, bw, fidx)
    # node loads: weight, attachments, seabed, mass-proportional damping
    sl = env[E_SLOPE]
    nrm[0], nrm[1], nrm[2] = -math.sin(sl), 0.0, math.cos(sl)
    depth = env[E_DEPTH]
    kb, cb, mu, vf = env[E_KBOT], env[E_CBOT], env[E_MU], env[E_VFRIC]
    bedfull = env[E_BEDFULL] > 0.0
    alpha = env[E_ALPHA]
    profile = env[E_BEDTAB] > 0.0
    for i in range(n):
        F[i, 2] -= weight[i]
        qn, qa, ql = 0.5 * rho * pcda[i, P_CDA], 0.5 * rho * pcda[i, P_CDA_AXIAL], 0.5 * rho * pcda[i, P_CLA]
        wet = qn > 0.0 or qa > 0.0 or ql != 0.0 or pvol[i] > 0.0 or padd[i] > 0.0
        ei = _surface(X[i, 0], X[i, 1], t, env, with_waves, sea) if wavy and (pbuoy[i] != 0.0 or wet) else 0.0
        if pbuoy[i] != 0.0 and X[i, 2] - ei > -0.5 * pdia[i]:
            # an attachment at the surface: its buoyancy scales with the immersed fraction of a body of
            # height pdia (its volume's sphere diameter), linear across the waterline
            F[i, 2] -= pbuoy[i] * min((X[i, 2] - ei) / pdia[i] + 0.5, 1.0) if pdia[i] > 0.0 else pbuoy[i]
        for r in range(3):
            M[i, r, r] += pmass[i] + padd[i]
        if wet and X[i, 2] <= ei:
            _fluid(X[i], t, env, cur_depth, cur_speed, with_waves, sea, uw, aw)
            for r in range(3):
                ur[r] = uw[r] - V[i, r]
            mag = math.sqrt(ur[0] ** 2 + ur[1] ** 2 + ur[2] ** 2)
            for r in range(3):
                F[i, r] += (rho * pvol[i] + padd[i]) * aw[r]
            if qa == qn:  # the same drag in every direction: 1/2 rho C_D A |u| u
                for r in range(3):
                    F[i, r] += qn * mag * ur[r]
                if jac and fidx[i] >= 0 and cc != 0.0 and qn > 0.0:
                    for r in range(3):
                        for c in range(3):
                            hb[r, c] = qn * mag * eye[r, c]
                    _drag_tangent(ur, 1.0, hb, qn)
                    _add_block(band, bw, fidx[i], fidx[i], cc, hb)
            else:  # across and along the line's direction at the node (the mean of its elements' tangents)
                _point_drag_split(ur, qn, qa, tnode[i], F[i], hb)
                if jac and fidx[i] >= 0 and cc != 0.0:
                    _add_block(band, bw, fidx[i], fidx[i], cc, hb)
            if ql != 0.0:
                point_lift(ur, ql, F[i], hb)
                if jac and fidx[i] >= 0 and cc != 0.0:
                    _add_block(band, bw, fidx[i], fidx[i], cc, hb)
        if alpha > 0.0:
            for r in range(3):
                for c in range(3):
                    F[i, r] -= alpha * M[i, r, c] * V[i, c]
            if jac and fidx[i] >= 0:
                _add_block(band, bw, fidx[i], fidx[i], cc * alpha, M[i])
        if kb > 0.0 and bedc[i] > 0.0 and (profile or math.isfinite(depth)):
            if profile:  # the profile's segment under the node: its elevation and normal
                zb, slope = seabed_at(env, X[i, 0])
                cs = 1.0 / math.sqrt(1.0 + slope * slope)
                nrm[0], nrm[2] = -slope * cs, cs
                pen = (zb - X[i, 2]) * cs
            else:
                pen = -(nrm[0] * X[i, 0] + nrm[2] * (X[i, 2] + depth))
            dl = env[E_BEDRAMP]
            if pen > -dl:
                # penalty spring k q(pen), q rounded quadratically over |pen| < dl (continuous stiffness,
                # so that Newton does not cycle at lift-off); the damper engages as r = q / (q + dl), or with
                # ``bedfull`` (MoorDyn's rule: c_b in full on every penetrating node) as the spring's slope
                # r = dq: c_b in full once pen >= dl, where the spring is k pen, rounded with it below
                if pen < dl:
                    q = (pen + dl) ** 2 / (4.0 * dl)
                    dq = (pen + dl) / (2.0 * dl)
                else:
                    q = pen
                    dq = 1.0
                # the node's velocity over the seabed (which moves at -frame in a moving frame)
                g0, g1, g2 = V[i, 0] + env[E_FRAMEX], V[i, 1] + env[E_FRAMEY], V[i, 2] + env[E_FRAMEZ]
                vn = nrm[0] * g0 + nrm[1] * g1 + nrm[2] * g2
                if bedfull:
                    ramp = dq
                    dramp = 0.5 / dl if pen < dl else 0.0
                else:
                    ramp = q / (q + dl)
                    dramp = dl / (q + dl) ** 2 * dq
                fn = kb * bedc[i] * q - cb * bedc[i] * ramp * vn
                for r in range(3):
                    F[i, r] += fn * nrm[r]
                    vt[r] = (g0 if r == 0 else g1 if r == 1 else g2) - vn * nrm[r]
                s = math.sqrt(vt[0] ** 2 + vt[1] ** 2 + vt[2] ** 2 + vf * vf)
                fr = mu * max(fn, 0.0) / s
                if fr > 0.0:
                    for r in range(3):
                        F[i, r] -= fr * vt[r]
                if jac and fidx[i] >= 0:
                    # -dfn/dx = dk n^T (pen = -n . x + ...), -dfn/dv = cb d_n ramp n^T; the friction -mu fn v_t / s
                    # follows fn (its row: mu v_t / s times fn's derivatives, negated) and v_t
                    dk = kb * bedc[i] * dq - cb * bedc[i] * vn * dramp
                    dn = dk + cc * cb * bedc[i] * ramp
                    mus = mu / s if fr > 0.0 else 0.0
                    for r in range(3):
                        for c in range(3):
                            nn = nrm[r] * nrm[c]
                            blk[r, c] = dn * nn
                            if fr > 0.0:
                                blk[r, c] += cc * fr * ((eye[r, c] - nn) - vt[r] * vt[c] / (s * s)) \
                                    - mus * vt[r] * dn * nrm[c]
                    _add_block(band, bw, fidx[i], fidx[i], 1.0, blk)
        if jac and fidx[i] >= 0 and cm != 0.0:
            _add_block(band, bw, fidx[i], fidx[i], cm, M[i])


@njit(cache=True)
def _eliminate5(band, r, o, inv, u1, u2, u3, u4, u5):
    """Row ``r``'s elimination by the pivot row whose reciprocal pivot is ``inv`` and whose U entries right of
    the diagonal are ``u1`` .. ``u5``, the multiplier at column ``o`` of its band row."""
    f = band[r, o] * inv
    band[r, o] = f
    band[r, o + 1] -= f * u1
    band[r, o + 2] -= f * u2
    band[r, o + 3] -= f * u3
    band[r, o + 4] -= f * u4
    band[r, o + 5] -= f * u5


@njit(cache=True)
def _factor5(band):
    """:func:`band_factor` of half-bandwidth 5 (a single line: 3 x 3 blocks, each node coupled to the next):
    each pivot row's U entries held in registers over its eliminations (the rows it updates cannot be
    assumed apart from it otherwise), with constant bounds away from the last rows."""
    n = band.shape[0]
    for k in range(n):
        piv = band[k, 5]
        if piv == 0.0 or not math.isfinite(piv):
            return False
        inv = 1.0 / piv
        band[k, 5] = inv
        if k + 5 < n:
            u1, u2, u3, u4, u5 = band[k, 6], band[k, 7], band[k, 8], band[k, 9], band[k, 10]
            _eliminate5(band, k + 1, 4, inv, u1, u2, u3, u4, u5)
            _eliminate5(band, k + 2, 3, inv, u1, u2, u3, u4, u5)
            _eliminate5(band, k + 3, 2, inv, u1, u2, u3, u4, u5)
            _eliminate5(band, k + 4, 1, inv, u1, u2, u3, u4, u5)
            _eliminate5(band, k + 5, 0, inv, u1, u2, u3, u4, u5)
        else:
            m = n - k
            for i in range(1, m):
                o = 5 - i
                f = band[k + i, o] * inv
                band[k + i, o] = f
                for j in range(1, m):
                    band[k + i, o + j] -= f * band[k, 5 + j]
    return True


@njit(cache=True)
def band_factor(band, bw):
    """Factor the banded matrix in place (LU without pivoting): the multipliers below the diagonal, U above it,
    and the reciprocals of U's pivots on it (a product, not a division, on the solves' critical path). Returns
    False on a zero or non-finite pivot."""
    if bw == 5:
        return _factor5(band)
    n = band.shape[0]
    for k in range(n):
        piv = band[k, bw]
        if piv == 0.0 or not math.isfinite(piv):
            return False
        inv = 1.0 / piv
        band[k, bw] = inv
        end = min(n, k + bw + 1)
        for i in range(k + 1, end):
            o = bw + k - i  # row i's column j is at o + (j - k) of its band row, row k's at bw + (j - k)
            f = band[i, o] * inv
            band[i, o] = f
            for j in range(1, end - k):
                band[i, o + j] -= f * band[k, bw + j]
    return True


@njit(cache=True)
def _lu_solve5(band, rhs):
    """:func:`lu_solve` of half-bandwidth 5: the last five values carried in registers, and each row's sum taken
    farthest term first, so that a row waits on the one before it for a single product."""
    n = rhs.size
    if n < 12:
        return _lu_solve_any(band, 5, rhs)
    for i in range(1, 5):
        s = 0.0
        for k in range(i):
            s += band[i, 5 + k - i] * rhs[k]
        rhs[i] -= s
    y5, y4, y3, y2, y1 = rhs[0], rhs[1], rhs[2], rhs[3], rhs[4]
    for i in range(5, n):
        s = band[i, 0] * y5 + band[i, 1] * y4 + band[i, 2] * y3 + band[i, 3] * y2
        yi = rhs[i] - s - band[i, 4] * y1
        rhs[i] = yi
        y5, y4, y3, y2, y1 = y4, y3, y2, y1, yi
    for k in range(n - 1, n - 6, -1):
        s = 0.0
        for j in range(n - 1, k, -1):
            s += band[k, 5 + j - k] * rhs[j]
        rhs[k] = (rhs[k] - s) * band[k, 5]
    x1, x2, x3, x4, x5 = rhs[n - 5], rhs[n - 4], rhs[n - 3], rhs[n - 2], rhs[n - 1]
    for k in range(n - 6, -1, -1):
        s = band[k, 10] * x5 + band[k, 9] * x4 + band[k, 8] * x3 + band[k, 7] * x2
        xk = (rhs[k] - s - band[k, 6] * x1) * band[k, 5]
        rhs[k] = xk
        x5, x4, x3, x2, x1 = x4, x3, x2, x1, xk
    return True


@njit(cache=True)
def _lu_solve_any(band, bw, rhs):
    """:func:`lu_solve` of any half-bandwidth: forward by rows, then back, each row's sum farthest term first."""
    n = rhs.size
    for i in range(1, n):
        s = 0.0
        for k in range(max(0, i - bw), i):
            s += band[i, bw + k - i] * rhs[k]
        rhs[i] -= s
    for k in range(n - 1, -1, -1):
        s = 0.0
        for j in range(min(n - 1, k + bw), k, -1):
            s += band[k, bw + j - k] * rhs[j]
        rhs[k] = (rhs[k] - s) * band[k, bw]
    return True


@njit(cache=True)
def lu_solve(band, bw, rhs):
    """Solve in place with the factors :func:`band_factor` left in ``band`` (its multipliers below the
    diagonal, U above it, U's reciprocal pivots on it)."""
    if bw == 5:
        _lu_solve5(band, rhs)
    else:
        _lu_solve_any(band, bw, rhs)


@njit(cache=True)
def band_solve(band, bw, rhs):
    """Solve the banded system in place (LU without pivoting, :func:`band_factor`, whose factors ``band`` keeps
    for :func:`lu_solve`); returns False on a zero or non-finite pivot."""
    if not band_factor(band, bw):
        return False
    lu_solve(band, bw, rhs)
    return True


@njit(cache=True)
def _residual(F, M, A, fidx, R):
    """R = M a - F at the free nodes; returns max |R|."""
    res = 0.0
    for i in range(F.shape[0]):
        f = fidx[i]
        if f < 0:
            continue
        for r in range(3):
            v = -F[i, r]
            for c in range(3):
                v += M[i, r, c] * A[i, c]
            R[3 * f + r] = v
            res = max(res, abs(v))
    return res


@njit(cache=True)
def _residual_alpha(F, M, A, G, wm, wg, fidx, R):
    """R = wm M a - F + wg G at the free nodes (the generalised-alpha equilibrium divided by
    ``1 - alpha_f``: ``wm = (1 - alpha_m) / (1 - alpha_f)``, ``wg = 1 / (1 - alpha_f)``); returns max |R|."""
    res = 0.0
    for i in range(F.shape[0]):
        f = fidx[i]
        if f < 0:
            continue
        for r in range(3):
            v = 0.0
            for c in range(3):
                v += M[i, r, c] * A[i, c]
            v = wm * v - F[i, r] + wg * G[i, r]
            R[3 * f + r] = v
            res = max(res, abs(v))
    return res


@njit(cache=True)
def alpha_history(F, M, A, G, alpha_m, alpha_f, fidx):
    """The share of a step's start in the next step's generalised-alpha equilibrium:
    ``G = alpha_m M a - alpha_f F`` at the free nodes (zero elsewhere). [N]"""
    for i in range(F.shape[0]):
        for r in range(3):
            v = 0.0
            if fidx[i] >= 0:
                for c in range(3):
                    v += M[i, r, c] * A[i, c]
                v = alpha_m * v - alpha_f * F[i, r]
            G[i, r] = v


@njit(cache=True)
def _norm2(v):
    s = 0.0
    for k in range(v.size):
        s += v[k] * v[k]
    return math.sqrt(s)


@njit(cache=True)
def _force_tolerance(tol, weight, tension, F, M, A, X, fidx, EA, bedc, env, c0):
    """The absolute force tolerance [N] of a Newton iteration: ``tol`` times a force scale, plus the
    round-off floor of the residual.

    The scale is the largest of the total weight of the nodes (the whole network's weight in water),
    the element tensions, and the net node forces (seabed reaction, drag, ...) and inertia forces
    ``M a`` at the free nodes. It cannot collapse to the weight of one node of a tank-scale model in a
    slack phase, where no tension is larger. The floor is the force that moves a node by 1024 units in
    the last place of its coordinates through the largest term the residual is computed from
    (``M c0 x`` of Newmark's acceleration, ``k_b d_n (z + depth)`` of the seabed, ``EA l / L`` of an
    element): about 1e-11 m for a line 30 m from the origin, far below any accuracy a step needs, and
    a level that a residual computed from those terms cannot be asked to go below when the time step
    is small (``c0`` the mass coefficient of the Newton matrix, ``1 / (beta dt^2)`` for Newmark,
    ``(1 - alpha_m) / ((1 - alpha_f) beta dt^2)`` for the generalised alpha).
    """
    return _residual_tolerance(F, M, A, fidx, np.empty(0), tol, weight, tension, X, EA, bedc, env, c0)[1]


@njit(cache=True)
def _residual_tolerance(F, M, A, fidx, R, tol, weight, tension, X, EA, bedc, env, c0):
    """:func:`_residual` (into ``R`` unless it is empty) and :func:`_force_tolerance` in one pass over the nodes:
    ``(max |R|, the tolerance [N])``."""
    res = 0.0
    s = 0.0
    total = 0.0
    big = 0.0
    keep = R.size > 0
    kb = env[E_KBOT]
    depth = env[E_DEPTH] if math.isfinite(env[E_DEPTH]) else 0.0
    for i in range(weight.size):
        total += abs(weight[i])
        f = fidx[i]
        if f < 0:
            continue
        xm = max(abs(X[i, 0]), abs(X[i, 1]), abs(X[i, 2]))
        for r in range(3):
            ma = M[i, r, 0] * A[i, 0] + M[i, r, 1] * A[i, 1] + M[i, r, 2] * A[i, 2]
            v = ma - F[i, r]
            if keep:
                R[3 * f + r] = v
            res = max(res, abs(v))
            s = max(s, abs(F[i, r]), abs(ma))
            big = max(big, M[i, r, r] * c0 * xm)
        big = max(big, kb * bedc[i] * (xm + depth))
    s = max(s, total)
    for e in range(tension.size):
        s = max(s, tension[e])
        big = max(big, EA[e])
    if s <= 0.0:
        s = 1.0
    return res, tol * s + 1024.0 * 2.220446049250313e-16 * big


@njit(cache=True)
def predict_nodes(X, V, A, Xn, Vn, An, px, pv, pa, step, channel, fidx, dt):
    """The start of a Newmark step: prescribed nodes where their channel puts them at ``step``, free nodes
    at the constant-acceleration predictor from the last state (``Xn``, ``Vn``, ``An``)."""
    for i in range(X.shape[0]):
        ch = channel[i]
        for r in range(3):
            if ch >= 0:
                X[i, r] = px[step, ch, r]
                V[i, r] = pv[step, ch, r]
                A[i, r] = pa[step, ch, r]
            elif fidx[i] >= 0:
                X[i, r] = Xn[i, r] + dt * Vn[i, r] + 0.5 * dt * dt * An[i, r]


@njit(cache=True)
def newmark_steps(X, V, A, t0, dt, px, pv, pa, channel, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can,
                  cat, weight, pmass, padd, pvol, pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx,
                  nfree, bw,
                  env, cur_depth,
                  cur_speed, with_waves, sea, beta, gamma, alpha_m, alpha_f, G, tol, max_iter, F, M, tension, stats):
    """Advance ``px.shape[0]`` generalised-alpha steps in place; ``px/pv/pa[k, channel]`` are the
    prescribed positions, velocities and accelerations at the end of step k.

    ``beta``, ``gamma`` are Newmark's parameters and ``alpha_m``, ``alpha_f`` the weights of the step's
    start in the inertia and in the forces (:func:`seacable.mooring.solver.generalized_alpha`; both 0:
    Newmark, the equilibrium at the step's end). ``G`` (n, 3) holds ``alpha_m M a - alpha_f F`` of
    the state at the start (:func:`alpha_history`) and is advanced with it; unused when both alphas
    are 0. Returns the number of steps completed; a step whose Newton iteration fails leaves the
    state (and ``G``) at its start. ``stats`` receives (iterations, last residual, absolute force
    tolerance [N]).
    """
    nd = 3 * nfree
    work = (np.zeros((nd, 2 * bw + 1)), np.zeros(nd), np.zeros(nd), np.empty_like(X), np.empty_like(V),
            np.empty_like(A), env.copy())
    return newmark_work(X, V, A, t0, dt, px, pv, pa, channel, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat,
                        weight, pmass, padd, pvol, pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei,
                        visco, fidx, nfree, bw, env, cur_depth, cur_speed, with_waves, sea, beta, gamma, alpha_m,
                        alpha_f, G, tol, max_iter, F, M, tension, stats, *work)


@njit(cache=True)
def newmark_work(X, V, A, t0, dt, px, pv, pa, channel, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can,
                  cat, weight, pmass, padd, pvol, pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx,
                  nfree, bw,
                  env, cur_depth,
                  cur_speed, with_waves, sea, beta, gamma, alpha_m, alpha_f, G, tol, max_iter, F, M, tension, stats, band, R, D, Xn, Vn, An, envw):
    """:func:`newmark_steps` with its work arrays given, so that a caller stepping output interval after output
    interval allocates them once: ``band`` (3 nfree, 2 bw + 1), ``R`` and ``D`` (3 nfree,), ``Xn``, ``Vn``, ``An``
    (n, 3) and ``envw`` (a copy of ``env``, its ``E_VDT`` set here)."""
    n = X.shape[0]
    nd = 3 * nfree
    none = np.zeros((0, 2 * bw + 1))  # no Newton matrix
    c0 = 1.0 / (beta * dt * dt)
    c1 = gamma / (beta * dt)
    # generalised alpha: the equilibrium divided by 1 - alpha_f, so that the Newton matrix is
    # wm c0 M + c1 C + K, i.e. ((1 - alpha_m) c0 M + (1 - alpha_f) (c1 C + K)) / (1 - alpha_f)
    galpha = alpha_m != 0.0 or alpha_f != 0.0
    wm = (1.0 - alpha_m) / (1.0 - alpha_f)
    wg = 1.0 / (1.0 - alpha_f)
    cm = wm * c0
    envw[:] = env
    envw[E_VDT] = dt  # the viscoelastic elements' slow stretch advances over the step
    env = envw
    # an irregular sea: the water's kinematics of a step are looked up at its predicted positions and held over
    # its Newton iterations, whose corrections move the nodes by millimetres (the kinematics change over them by
    # about k dx, 1e-4 of themselves, far below the grid's interpolation error); else evaluated at each iterate
    held = sea[S_MODE] > 0.0 and with_waves
    unheld = not held
    water = np.zeros((n_water(X, env, cur_depth, with_waves, sea), 7))
    for step in range(px.shape[0]):
        Xn[:] = X
        Vn[:] = V
        An[:] = A
        t = t0 + (step + 1) * dt
        predict_nodes(X, V, A, Xn, Vn, An, px, pv, pa, step, channel, fidx, dt)
        ok = False
        res = 0.0
        res_prev = np.inf
        cuts = 0
        scale = 1.0
        jac = True  # assemble the Newton matrix with the loads
        lu_step = False  # ``band`` holds the factors of a Newton matrix of this step
        for it in range(max_iter):
            for i in range(n):
                if fidx[i] >= 0:
                    for r in range(3):
                        A[i, r] = c0 * (X[i, r] - Xn[i, r]) - Vn[i, r] / (beta * dt) - (0.5 / beta - 1.0) * An[i, r]
                        V[i, r] = Vn[i, r] + dt * ((1.0 - gamma) * An[i, r] + gamma * A[i, r])
            mat = band if jac else none
            fresh = it == 0 or not held
            if jac:
                band[:] = 0.0
                lu_step = False
            loads_water(X, V, t, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol,
                        pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env,
                        cur_depth, cur_speed, with_waves, sea, F, M, tension, mat, bw, cm, c1, water, fresh)
            if galpha:
                res = _residual_alpha(F, M, A, G, wm, wg, fidx, R)
                scale = _force_tolerance(tol, weight, tension, F, M, A, X, fidx, EA, bedc, env, cm)
            else:
                res, scale = _residual_tolerance(F, M, A, fidx, R, tol, weight, tension, X, EA, bedc, env, cm)
            stats[0] += 1
            if res <= scale and it > 0:
                ok = True
                break
            if it > 0 and not (res < res_prev) and cuts < 6:
                # backtrack: the full Newton step made things worse (contact or slack switching)
                cuts += 1
                for i in range(n):
                    f = fidx[i]
                    if f >= 0:
                        for r in range(3):
                            D[3 * f + r] *= 0.5
                            X[i, r] -= D[3 * f + r]
                jac = True
                continue
            if not math.isfinite(res):
                break
            # the correction: with this step's factors again while the last correction cut the residual at least
            # tenfold (a modified Newton iteration, its rate that of the tangent's change), else a fresh matrix
            modified = lu_step and res <= 0.1 * res_prev
            if not jac and not modified:
                band[:] = 0.0
                loads_water(X, V, t, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd,
                            pvol, pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env,
                            cur_depth, cur_speed, with_waves, sea, F, M, tension, band, bw, cm, c1, water, unheld)
                stats[0] += 1
            res_prev = res
            cuts = 0
            for k in range(nd):
                R[k] = -R[k]
            if modified:
                lu_solve(band, bw, R)
            elif band_solve(band, bw, R):
                lu_step = True
            else:
                break
            jac = not lu_step
            for i in range(n):
                f = fidx[i]
                if f >= 0:
                    for r in range(3):
                        D[3 * f + r] = R[3 * f + r]
                        X[i, r] += R[3 * f + r]
        stats[1] = res
        stats[2] = scale
        if not ok:
            X[:] = Xn
            V[:] = Vn
            A[:] = An
            return step
        commit_viscoelastic(visco)
        if galpha:
            alpha_history(F, M, A, G, alpha_m, alpha_f, fidx)  # F, M: the converged state's
    return px.shape[0]


@njit(cache=True)
def commit_viscoelastic(visco):
    """Start the next step from the viscoelastic state last evaluated (a converged step's end), and a
    Syrope rope's largest mean tension Tmax from that state's."""
    for e in range(visco.shape[0]):
        visco[e, V_Y0] = visco[e, V_Y]
        visco[e, V_U0] = visco[e, V_U]
        visco[e, V_TM0] = visco[e, V_TM]


@njit(cache=True)
def static_solve(X, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda,
                 bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, nfree, bw, env, cur_depth, cur_speed,
                 tol, max_iter,
                 max_step, F, M, tension,
                 stats):
    """Static equilibrium by pseudo-transient Newton, ``(K + lam M) dx = -R``; X is updated in place.

    Returns True when ``max |F|`` at the free nodes is within the tolerance of :func:`_force_tolerance`.
    ``stats`` receives (iterations, residual, absolute force tolerance [N]).
    """
    n = X.shape[0]
    nd = 3 * nfree
    V = np.zeros_like(X)
    A = np.zeros_like(X)
    band = np.zeros((nd, 2 * bw + 1))
    empty = np.zeros((0, 2 * bw + 1))
    R = np.zeros(nd)
    Rt = np.zeros(nd)
    R0 = np.zeros(nd)
    Xt = X.copy()
    env = env.copy()
    env[E_VDT] = math.inf  # statics: viscoelastic elements at their static stiffness
    sea = np.zeros(GRID_HEADER)  # statics: still water
    loads(X, V, 0.0, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda,
          bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth, cur_speed, False, sea, F, M, tension,
          band, bw, 0.0, 0.0)
    res = _residual(F, M, A, fidx, R)
    # pseudo-transient continuation: (K + lam M) dx = -R, lam [1/s^2] starting where a node under its
    # weight moves a fraction of an element, and decreasing as Newton takes over
    lam = env[E_G] / (0.05 * max_step)
    for it in range(max_iter):
        scale = _force_tolerance(tol, weight, tension, F, M, A, X, fidx, EA, bedc, env, 0.0)
        stats[0] = it
        stats[1] = res
        stats[2] = scale
        if res <= scale:
            return True
        for i in range(n):
            f = fidx[i]
            if f >= 0:
                for r in range(3):
                    band[3 * f + r, bw] += lam * M[i, r, r]
        for k in range(nd):
            R0[k] = R[k]
            R[k] = -R[k]
        if not band_solve(band, bw, R):
            lam *= 10.0
            band[:] = 0.0
            loads(X, V, 0.0, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol,
                  pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth, cur_speed, False, sea,
                  F, M, tension, band, bw, 0.0, 0.0)
            res = _residual(F, M, A, fidx, R)
            continue
        big = 0.0
        for k in range(nd):
            big = max(big, abs(R[k]))
        shrink = 1.0 if big <= max_step else max_step / big
        Xt[:] = X
        for i in range(n):
            f = fidx[i]
            if f >= 0:
                for r in range(3):
                    Xt[i, r] += shrink * R[3 * f + r]
        loads(Xt, V, 0.0, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol,
              pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth, cur_speed, False, sea, F,
              M, tension, empty, bw, 0.0, 0.0)
        _residual(F, M, A, fidx, Rt)
        # switched evolution relaxation: always step, lam follows the residual
        r_new, r_old = _norm2(Rt), _norm2(R0)
        if math.isfinite(r_new):
            X[:] = Xt
            lam *= min(max(r_new / r_old, 0.05), 10.0)
        else:
            lam *= 10.0
        band[:] = 0.0
        loads(X, V, 0.0, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda,
              bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth, cur_speed, False, sea, F, M,
              tension, band, bw, 0.0, 0.0)
        res = _residual(F, M, A, fidx, R)
    stats[1] = res
    return False

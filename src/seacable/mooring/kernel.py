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
is a plane, a profile along X or a grid over X and Y (:mod:`._seabed`: bilinear, the normal from its
gradient); a node below it gets a penalty force ``k_b d_n (penetration) - c_b d_n v_n``, rounded
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
a straight line; with friction targets it adds the seabed's static Coulomb friction towards them
(:mod:`._friction`: the velocity's friction gives no force at rest).

The kernel's parts are private modules, their public names re-exported here: :mod:`._indices` (the layouts
of ``env``, ``pcda`` and ``visco``), :mod:`._water` (the surface, the water's kinematics, the attachments'
drag and lift), :mod:`._elements` (tension laws, the viscoelastic and Syrope passes, bending),
:mod:`._seabed` (the seabed's elevation under a node), :mod:`._ties` (tethers and spring clamps), :mod:`._band` (band storage: blocks and
LU), :mod:`._friction` (the statics' seabed friction) and :mod:`._loads` (the loads pass that assembles them); this module keeps the residual, the time
integration and the statics.
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import copy_1d, copy_2d, njit
from ..seastate import GRID_HEADER, S_MODE
from ._band import band_factor, band_solve, lu_solve
from ._elements import (bending_loads, syrope_loads, syrope_tension, table_tension, viscoelastic_loads,
                        viscoelastic_tension)
from ._friction import friction_loads
from ._indices import E_DEPTH, E_G, E_KBOT, E_VDT, ENV_SIZE, V_SIZE, V_TM, V_TM0, V_U, V_U0, V_Y, V_Y0
from ._loads import loads, loads_water, n_water

# re-exported: the arrays' layouts, which the solver, the run modules and the coupled system kernel fill through
# this module, and the parts' names they and the tests use
from ._indices import (  # noqa: F401
    E_ALPHA, E_BEDFULL, E_BEDNY, E_BEDRAMP, E_BEDTAB, E_CBOT, E_CHEAD, E_DRAGTURN, E_FRAMEX, E_FRAMEY, E_FRAMEZ,
    E_MU, E_RHO, E_SLACKDAMP, E_SLOPE, E_VFRIC, E_WDEPTH, E_WH, E_WHEAD, E_WK, E_WPHASE, E_WT, H_CLAMP, H_D, H_DCH,
    H_ECH, H_EI, H_INNER, H_K, H_KIND, H_SIZE, H_SPRING, P_CDA, P_CDA_AXIAL, P_CLA, V_BAD, V_EAD, V_K1, V_K2, V_LM, V_WC)
from ._seabed import grid_at, seabed_at  # noqa: F401
from ._water import _fluid, point_lift  # noqa: F401
# the ties to the seabed: their columns of the attachments' table and their pass (:mod:`._ties`); compression
from ._indices import E_COMPRESS, P_CK, P_CX, P_SIZE, P_TB, P_TEA, P_TL, P_TX  # noqa: F401
from ._ties import tie_loads  # noqa: F401
# a towed body with drag and added mass per axis of the body at node 0 (:mod:`._body`)
from ._indices import E_BDRAG, E_BMASS, E_BODY  # noqa: F401

__all__ = ["ENV_SIZE", "V_SIZE", "alpha_history", "band_factor", "band_solve", "bending_loads", "commit_viscoelastic",
           "friction_loads",
           "loads", "loads_water", "lu_solve", "n_water", "newmark_steps", "static_solve", "syrope_loads", "syrope_tension",
           "table_tension", "viscoelastic_loads", "viscoelastic_tension"]


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
def turn_held_ends(hinge_ei, px, step):
    """The held ends that turn with a moving platform (``hinge_ei[h, H_DCH] >= 0``) take their direction at ``step``:
    from the end's motion channel to its direction point's, both moved by the platform's rigid motion."""
    for h in range(hinge_ei.shape[0]):
        dch = int(hinge_ei[h, H_DCH])
        if hinge_ei[h, H_KIND] == H_INNER or dch < 0:
            continue
        ech = int(hinge_ei[h, H_ECH])
        norm = 0.0
        for r in range(3):
            norm += (px[step, dch, r] - px[step, ech, r]) ** 2
        norm = math.sqrt(norm)
        for r in range(3):
            hinge_ei[h, H_D + r] = (px[step, dch, r] - px[step, ech, r]) / norm


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
    copy_1d(envw, env)
    envw[E_VDT] = dt  # the viscoelastic elements' slow stretch advances over the step
    env = envw
    # an irregular sea: the water's kinematics of a step are looked up at its predicted positions and held over
    # its Newton iterations, whose corrections move the nodes by millimetres (the kinematics change over them by
    # about k dx, 1e-4 of themselves, far below the grid's interpolation error); else evaluated at each iterate
    held = sea[S_MODE] > 0.0 and with_waves
    unheld = not held
    water = np.zeros((n_water(X, env, cur_depth, with_waves, sea), 7))
    for step in range(px.shape[0]):
        copy_2d(Xn, X)
        copy_2d(Vn, V)
        copy_2d(An, A)
        t = t0 + (step + 1) * dt
        predict_nodes(X, V, A, Xn, Vn, An, px, pv, pa, step, channel, fidx, dt)
        turn_held_ends(hinge_ei, px, step)
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
            copy_2d(X, Xn)
            copy_2d(V, Vn)
            copy_2d(A, An)
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
                 stats, targets, dfric):
    """Static equilibrium by pseudo-transient Newton, ``(K + lam M) dx = -R``; X is updated in place.

    Returns True when ``max |F|`` at the free nodes is within the tolerance of :func:`_force_tolerance`.
    ``stats`` receives (iterations, residual, absolute force tolerance [N]). ``targets`` (n, 3): the nodes' friction
    targets [m] of the seabed's static friction, its slip distance ``dfric`` [m] (:func:`friction_loads`); no rows:
    frictionless statics.
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
          bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth, cur_speed, np.bool_(False), sea, F, M, tension,
          band, bw, 0.0, 0.0)
    friction_loads(X, targets, bedc, env, fidx, F, band, bw, dfric)
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
                  pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth, cur_speed, np.bool_(False), sea,
                  F, M, tension, band, bw, 0.0, 0.0)
            friction_loads(X, targets, bedc, env, fidx, F, band, bw, dfric)
            res = _residual(F, M, A, fidx, R)
            continue
        big = 0.0
        for k in range(nd):
            big = max(big, abs(R[k]))
        shrink = 1.0 if big <= max_step else max_step / big
        copy_2d(Xt, X)
        for i in range(n):
            f = fidx[i]
            if f >= 0:
                for r in range(3):
                    Xt[i, r] += shrink * R[3 * f + r]
        loads(Xt, V, 0.0, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol,
              pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth, cur_speed, np.bool_(False), sea, F,
              M, tension, empty, bw, 0.0, 0.0)
        friction_loads(Xt, targets, bedc, env, fidx, F, empty, bw, dfric)
        _residual(F, M, A, fidx, Rt)
        # switched evolution relaxation: always step, lam follows the residual
        r_new, r_old = _norm2(Rt), _norm2(R0)
        if math.isfinite(r_new):
            copy_2d(X, Xt)
            lam *= min(max(r_new / r_old, 0.05), 10.0)
        else:
            lam *= 10.0
        band[:] = 0.0
        loads(X, V, 0.0, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda,
              bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth, cur_speed, np.bool_(False), sea, F, M,
              tension, band, bw, 0.0, 0.0)
        friction_loads(X, targets, bedc, env, fidx, F, band, bw, dfric)
        res = _residual(F, M, A, fidx, R)
    stats[1] = res
    return False


"""Boundary conditions, Newton-Raphson and time marching of the towed-cable box scheme.

The global system at a time step has ``10 n`` equations for the ``10 n`` unknowns of the ``n``
nodes: 5 boundary conditions at the lower end, 10 box equations per interval and 5 boundary
conditions at the vessel. Grouped ten rows at a time (see :data:`equations.ORDER`) it is block
tri-diagonal (paper 000 Fig. 2): block row ``k`` touches the nodes ``k-1, k, k+1`` only.

Lower end (node 0), paper 000 eq. (14): a free end has ``T = S_n = S_b = Om_n = Om_b = 0``
(zero force and moment; the vanishing moment gradient of eq. (14) is the zero shear through rows
9-10). A towed body of mass ``M`` and added mass ``M_a`` with weight in water ``W`` and drag area
``C_D A`` obeys, in the global frame and centred in time like the box scheme,
``(M + M_a) (v^{i+1} - v^i)/dt = 1/2 (F^{i+1} + F^i)`` with
``F = T t + S_n n + S_b b - W Z - 1/2 rho C_D A |v - U| (v - U)`` and ``Om_n = Om_b = 0`` (pinned). A body
with drag or added mass per axis of the body (:mod:`seacable.mooring._body`: along the horizontal projection of the
tangent t, across it, vertical) has ``sum_k 1/2 rho (C_D A)_k |w_k| w_k e_k`` (w = U - v) for its drag and
``M + sum_k m_k e_k e_k^T`` (the axes at the new step) for its inertia; its Jacobian holds the axes' turn with phi.
Vessel end (node n-1), eq. (15): the cable velocity equals the vessel's, ``(v_t, v_n, v_b) =
(t.V, n.V, b.V)``, and ``Om_n = Om_b = 0``.
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import copy_1d, copy_2d, njit
from ..mooring._body import body_axes, body_drag, body_drag_turn
from .equations import (
    I_OB,
    I_ON,
    I_PH,
    I_SB,
    I_SN,
    I_T,
    I_TH,
    I_VB,
    I_VN,
    I_VT,
    NV,
    ORDER,
    box_assemble,
    c_terms,
    current_velocity,
    frame,
    g_terms,
    integrate_positions,
)
from .lapack import solve_banded, solve_dense
from .linalg import block_thomas, block_tridiagonal_workspace

__all__ = ["B_HAS", "B_MASS", "B_WEIGHT", "B_DRAG", "B_AXES", "B_QAXES", "B_MAXES", "B_SIZE", "STATUS", "newton_step",
           "march", "node_currents"]

B_HAS, B_MASS, B_WEIGHT, B_DRAG, B_AXES, B_QAXES, B_MAXES, B_SIZE = 0, 1, 2, 3, 4, 5, 8, 11
"""Entries of the body vector ``bpar``: 1 if a body is attached (else a free end), its mass plus
isotropic added mass [kg], its weight in water [N, positive sinks] and its isotropic ``1/2 rho C_D A`` [kg/m];
then 1 if it has drag or added mass per axis of the body (:mod:`seacable.mooring._body`), its ``1/2 rho C_D A``
along, across and vertical (``B_QAXES + k``) [kg/m] and its added mass along, across and vertical
(``B_MAXES + k``) [kg]."""

STATUS = {0: "converged", 1: "Newton-Raphson did not converge", 2: "the solution became non-finite",
          3: "the linear system is singular", 4: "the cable became vertical (|cos theta| < 1e-6), where "
                                                 "the Euler angles of paper 000 are singular"}


@njit(cache=True)
def _bc_lower(hn, ho, un, uo, bpar, dt, steady, res, jac):
    """Five lower-end residuals ``res (5)`` and their Jacobian ``jac (5, 10)`` w.r.t. node 0."""
    jac[:, :] = 0.0
    res[3] = hn[I_ON]
    jac[3, I_ON] = 1.0
    res[4] = hn[I_OB]
    jac[4, I_OB] = 1.0
    if bpar[B_HAS] == 0.0:
        res[0] = hn[I_T]
        res[1] = hn[I_SN]
        res[2] = hn[I_SB]
        jac[0, I_T] = 1.0
        jac[1, I_SN] = 1.0
        jac[2, I_SB] = 1.0
        return
    fn = np.zeros(3)
    dfn = np.zeros((3, NV))
    vg = np.zeros(3)
    dvg = np.zeros((3, NV))
    _body_force(hn, un, bpar, fn, dfn, vg, dvg)
    if steady:
        for d in range(3):
            res[d] = -fn[d]
            for c in range(NV):
                jac[d, c] = -dfn[d, c]
        return
    fo = np.zeros(3)
    vgo = np.zeros(3)
    _body_force(ho, uo, bpar, fo, np.zeros((3, NV)), vgo, np.zeros((3, NV)))
    mass = bpar[B_MASS]
    for d in range(3):
        res[d] = mass * (vg[d] - vgo[d]) / dt - 0.5 * (fn[d] + fo[d])
        for c in range(NV):
            jac[d, c] = mass * dvg[d, c] / dt - 0.5 * dfn[d, c]
    if bpar[B_AXES] > 0.0:
        _added_mass_axes(hn, bpar, vg, vgo, dvg, dt, res, jac)


@njit(cache=True)
def _added_mass_axes(h, bpar, vg, vgo, dvg, dt, res, jac):
    """The added mass per axis ``M_a = sum_k m_k e_k e_k^T`` (axes at the new state) in the body's equation:
    ``M_a (v^{i+1} - v^i) / dt`` added to ``res`` (3 rows), with its Jacobian (``M_a dv/dH`` and the axes'
    turn with phi, ``dM_a/dphi = (m_a - m_c) (e_c e_a^T + e_a e_c^T)`` times ``e_c . dt_h/dphi / h``)."""
    r = frame(h[I_PH], h[I_TH])
    axes = np.zeros((3, 3))
    hh = body_axes(r[0, 0], r[0, 1], axes)
    ma = np.zeros((3, 3))
    dma = np.zeros((3, 3))
    turn = 0.0
    if hh > 0.0:  # e_c . d(t_h)/dphi / h, t_h = cos(theta) (cos phi, sin phi): 1
        turn = (axes[1, 0] * r[1, 0] * math.cos(h[I_TH]) + axes[1, 1] * r[1, 1] * math.cos(h[I_TH])) / hh
    for k in range(3):
        mk = bpar[B_MAXES + k]
        for a in range(3):
            for b in range(3):
                ma[a, b] += mk * axes[k, a] * axes[k, b]
    dm = (bpar[B_MAXES] - bpar[B_MAXES + 1]) * turn
    for a in range(3):
        for b in range(3):
            dma[a, b] = dm * (axes[1, a] * axes[0, b] + axes[0, a] * axes[1, b])
    for d in range(3):
        dv = 0.0
        ddv = 0.0
        for e in range(3):
            dv += ma[d, e] * (vg[e] - vgo[e])
            ddv += dma[d, e] * (vg[e] - vgo[e])
        res[d] += dv / dt
        jac[d, I_PH] += ddv / dt
        for c in range(NV):
            acc = 0.0
            for e in range(3):
                acc += ma[d, e] * dvg[e, c]
            jac[d, c] += acc / dt


@njit(cache=True)
def _body_force(h, u, bpar, f, df, vg, dvg):
    """Force on the body ``f`` (global) with ``df/dH``, and the body velocity ``vg`` with ``dvg/dH``."""
    ph, th = h[I_PH], h[I_TH]
    cth, sth = math.cos(th), math.sin(th)
    r = frame(ph, th)
    tv, nv, bv = r[0], r[1], r[2]
    dt_dph, dn_dph, db_dph = cth * nv, -cth * tv - sth * bv, sth * nv
    dt_dth, db_dth = -bv, tv
    vt, vn, vb = h[I_VT], h[I_VN], h[I_VB]
    tension, sn, sb = h[I_T], h[I_SN], h[I_SB]
    for d in range(3):
        vg[d] = vt * tv[d] + vn * nv[d] + vb * bv[d]
        dvg[d, :] = 0.0
        dvg[d, I_VT], dvg[d, I_VN], dvg[d, I_VB] = tv[d], nv[d], bv[d]
        dvg[d, I_PH] = vt * dt_dph[d] + vn * dn_dph[d] + vb * db_dph[d]
        dvg[d, I_TH] = vt * dt_dth[d] + vb * db_dth[d]
        f[d] = tension * tv[d] + sn * nv[d] + sb * bv[d]
        df[d, :] = 0.0
        df[d, I_T], df[d, I_SN], df[d, I_SB] = tv[d], nv[d], bv[d]
        df[d, I_PH] = tension * dt_dph[d] + sn * dn_dph[d] + sb * db_dph[d]
        df[d, I_TH] = tension * dt_dth[d] + sb * db_dth[d]
    f[2] -= bpar[B_WEIGHT]
    kd = bpar[B_DRAG]
    if kd > 0.0:
        vr = vg - u
        speed = math.sqrt(vr[0] ** 2 + vr[1] ** 2 + vr[2] ** 2)
        for d in range(3):
            f[d] -= kd * speed * vr[d]
        if speed > 1e-12:
            for d in range(3):
                for e in range(3):
                    dd = kd * (speed * (1.0 if d == e else 0.0) + vr[d] * vr[e] / speed)
                    for c in range(df.shape[1]):  # a loop: numba's slice assignment compiles its error message
                        df[d, c] -= dd * dvg[e, c]
    if bpar[B_AXES] > 0.0:
        # drag per axis of the body: the water's velocity past it w = u - v, df/dH = (df/dw)(-dv/dH) + (df/dt) dt/dH
        axes = np.zeros((3, 3))
        dfw = np.zeros((3, 3))
        dft = np.zeros((3, 3))
        w = u - vg
        hh = body_axes(tv[0], tv[1], axes)
        body_drag(w, axes, bpar[B_QAXES:B_QAXES + 3], f, dfw)
        body_drag_turn(w, axes, bpar[B_QAXES:B_QAXES + 3], hh, dft)
        for d in range(3):
            for c in range(df.shape[1]):
                acc = 0.0
                for e in range(3):
                    acc -= dfw[d, e] * dvg[e, c]
                df[d, c] += acc
            for e in range(3):
                df[d, I_PH] += dft[d, e] * dt_dph[e]
                df[d, I_TH] += dft[d, e] * dt_dth[e]


@njit(cache=True)
def _bc_top(h, vessel_velocity, res, jac):
    """Five vessel-end residuals and their Jacobian w.r.t. the last node."""
    jac[:, :] = 0.0
    ph, th = h[I_PH], h[I_TH]
    cth, sth = math.cos(th), math.sin(th)
    r = frame(ph, th)
    vt_v = r[0, 0] * vessel_velocity[0] + r[0, 1] * vessel_velocity[1] + r[0, 2] * vessel_velocity[2]
    vn_v = r[1, 0] * vessel_velocity[0] + r[1, 1] * vessel_velocity[1]
    vb_v = r[2, 0] * vessel_velocity[0] + r[2, 1] * vessel_velocity[1] + r[2, 2] * vessel_velocity[2]
    res[0] = h[I_VT] - vt_v
    res[1] = h[I_VN] - vn_v
    res[2] = h[I_VB] - vb_v
    res[3] = h[I_ON]
    res[4] = h[I_OB]
    jac[0, I_VT] = 1.0
    jac[1, I_VN] = 1.0
    jac[2, I_VB] = 1.0
    jac[3, I_ON] = 1.0
    jac[4, I_OB] = 1.0
    jac[0, I_PH] = -cth * vn_v
    jac[0, I_TH] = vb_v
    jac[1, I_PH] = cth * vt_v + sth * vb_v
    jac[2, I_PH] = -sth * vn_v
    jac[2, I_TH] = -vt_v


@njit(cache=True)
def _assemble(hn, ho, co, un, uo, vessel_velocity, dt, par, bpar, steady, w):
    """Fill the block tri-diagonal system ``w.lower, w.diag, w.upper, w.rhs`` (= -residual)."""
    n = hn.shape[0]
    cn, dcn, gm, dgm, bm, res, jl, jr, lower, diag, upper, rhs, r5, j5, mid, rate = w[:16]
    for j in range(n):
        c_terms(hn[j], un[j], par, cn[j], dcn[j], np.bool_(True))
        if not steady:
            for r in range(NV):
                mid[r] = 0.5 * (hn[j, r] + ho[j, r])
                rate[r] = (hn[j, r] - ho[j, r]) / dt
            g_terms(mid, rate, par, gm[j], dgm[j], bm[j])
    box_assemble(hn, ho, cn, dcn, co, gm, dgm, bm, dt, par, steady, res, jl, jr)
    lower[:] = 0.0
    diag[:] = 0.0
    upper[:] = 0.0
    _bc_lower(hn[0], ho[0], un[0], uo[0], bpar, dt, steady, r5, j5)
    for r in range(5):
        rhs[0, r] = -r5[r]
        copy_1d(diag[0, r], j5[r])
    for j in range(n - 1):
        for q in range(5):
            top, bot = ORDER[q], ORDER[q + 5]
            # rows closing the block of the left node j
            rhs[j, 5 + q] = -res[j, top]
            copy_1d(diag[j, 5 + q], jl[j, top])
            copy_1d(upper[j, 5 + q], jr[j, top])
            # rows opening the block of the right node j+1
            rhs[j + 1, q] = -res[j, bot]
            copy_1d(lower[j + 1, q], jl[j, bot])
            copy_1d(diag[j + 1, q], jr[j, bot])
    _bc_top(hn[n - 1], vessel_velocity, r5, j5)
    for r in range(5):
        rhs[n - 1, 5 + r] = -r5[r]
        copy_1d(diag[n - 1, 5 + r], j5[r])


def workspace(n):
    """Scratch arrays for :func:`newton_step` for ``n`` nodes (a tuple, reused across steps)."""
    z = np.zeros
    return (z((n, NV)), z((n, NV, NV)), z((n, NV)), z((n, NV, NV)), z((n, NV, NV)), z((n - 1, NV)),
            z((n - 1, NV, NV)), z((n - 1, NV, NV)), z((n, NV, NV)), z((n, NV, NV)), z((n, NV, NV)),
            z((n, NV)), z(5), z((5, NV)), z(NV), z(NV), z((n, NV))) + block_tridiagonal_workspace(n, NV)


@njit(cache=True)
def newton_step(hn, ho, co, un, uo, vessel_velocity, dt, par, bpar, steady, scale, tol, max_iter, w,
                solver=0):
    """Solve the box equations for the new state ``hn`` (updated in place; on entry the guess).

    ``solver`` picks the linear solve of the Newton systems: 0 block tri-diagonal (paper 000),
    1 dense LU of the assembled matrix (the baseline of the benchmark), 2 LAPACK band LU.

    Returns ``(status, iterations, correction)`` with ``status`` a key of :data:`STATUS` and
    ``correction`` the last scaled correction ``max |dH_k| / scale_k``.
    """
    n = hn.shape[0]
    dx = w[16]
    lower, diag, upper, rhs = w[8], w[9], w[10], w[11]
    err = np.inf
    for it in range(1, max_iter + 1):
        for j in range(n):
            if abs(math.cos(hn[j, I_TH])) < 1e-6:
                return 4, it, err
        _assemble(hn, ho, co, un, uo, vessel_velocity, dt, par, bpar, steady, w)
        if solver == 0:
            status = block_thomas(lower, diag, upper, rhs, dx, w[17], w[18], w[19], w[20])
        elif solver == 1:
            status = solve_dense(lower, diag, upper, rhs, dx, np.bool_(False))
        else:
            status = solve_banded(lower, diag, upper, rhs, dx, np.bool_(False))
        if status != 0:
            return 3, it, err
        err = 0.0
        for j in range(n):
            for r in range(NV):
                hn[j, r] += dx[j, r]
                a = abs(dx[j, r]) / scale[r]
                if not a < np.inf:
                    return 2, it, np.inf
                if a > err:
                    err = a
        if err < tol:
            return 0, it, err
    return 1, max_iter, err


@njit(cache=True)
def velocity_global(h, out):
    """Global velocities ``out (n, 3)`` of the nodes from their local components."""
    for j in range(h.shape[0]):
        r = frame(h[j, I_PH], h[j, I_TH])
        for d in range(3):
            out[j, d] = h[j, I_VT] * r[0, d] + h[j, I_VN] * r[1, d] + h[j, I_VB] * r[2, d]


@njit(cache=True)
def node_currents(pos, vel, dt, cur, vessel_velocity, out):
    """Current velocity at the nodes' elevations predicted ``dt`` ahead.

    ``cur = (depths, speeds, (cos heading, sin heading, follows))``; with ``follows`` = 1 the
    heading is measured from the vessel's course (a current that turns with the vessel).
    """
    depths, speeds, ch, sh = cur[0], cur[1], cur[2][0], cur[2][1]
    if cur[2][2] > 0.0:
        course = math.atan2(vessel_velocity[1], vessel_velocity[0])
        ch, sh = ch * math.cos(course) - sh * math.sin(course), sh * math.cos(course) + ch * math.sin(course)
    for j in range(pos.shape[0]):
        current_velocity(pos[j, 2] + dt * vel[j, 2], depths, speeds, ch, sh, out[j])


@njit(cache=True)
def march(h, h_prev, dt_prev, dt, vessel_pos, vessel_vel, cur, par, bpar, scale, tol, max_iter,
          save_every, out_h, out_pos, w, solver=0):
    """Advance ``len(vessel_vel) - 1`` steps of ``dt`` from the state ``h`` (at ``vessel_*[0]``).

    ``h`` and ``h_prev`` (the state one step ``dt_prev`` earlier, for the extrapolated guess of
    paper 000 eq. (19); ``dt_prev <= 0`` for none) are updated in place. Every ``save_every``
    steps the state and the node positions are written to ``out_h`` and ``out_pos``.
    Returns ``(status, steps_done, iterations_total, last_iterations, last_correction)``; on
    failure ``h`` holds the last converged state.
    """
    n = h.shape[0]
    nsteps = vessel_vel.shape[0] - 1
    hn = np.empty_like(h)
    co = np.zeros((n, NV))
    dummy = np.zeros((NV, NV))
    pos = np.zeros((n, 3))
    vel = np.zeros((n, 3))
    uo = np.zeros((n, 3))
    un = np.zeros((n, 3))
    integrate_positions(h, vessel_pos[0], par, pos)
    velocity_global(h, vel)
    node_currents(pos, vel, 0.0, cur, vessel_vel[0], uo)
    total = 0
    saved = 0
    for i in range(nsteps):
        for j in range(n):
            c_terms(h[j], uo[j], par, co[j], dummy, np.bool_(False))
        node_currents(pos, vel, dt, cur, vessel_vel[i + 1], un)
        if dt_prev > 0.0:
            for j in range(n):
                for r in range(NV):
                    hn[j, r] = h[j, r] + dt * (h[j, r] - h_prev[j, r]) / dt_prev
        else:
            copy_2d(hn, h)
        status, its, err = newton_step(hn, h, co, un, uo, vessel_vel[i + 1], dt, par, bpar, np.bool_(False),
                                       scale, tol, max_iter, w, solver)
        total += its
        if status != 0:
            return status, i, total, its, err
        copy_2d(h_prev, h)
        copy_2d(h, hn)
        dt_prev = dt
        integrate_positions(h, vessel_pos[i + 1], par, pos)
        velocity_global(h, vel)
        copy_2d(uo, un)
        if (i + 1) % save_every == 0 and saved < out_h.shape[0]:
            copy_2d(out_h[saved], h)
            copy_2d(out_pos[saved], pos)
            saved += 1
    return 0, nsteps, total, 0, 0.0

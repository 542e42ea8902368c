"""Compiled core of the coupled body-line dynamics: one Newton iteration on the line nodes and body DOFs.

The lines' nodes that are not held are the unknowns of the banded system of
:mod:`seacable.mooring.kernel` (``loads`` assembles their forces, masses and the Newton matrix
``cm M + cc C + K``). A node on a rigid body (a fairlead) is one of those nodes too, tied to its
body by a constraint ``x_j = r + R(theta) p_j``; a line end that may fail is tied the same way to
its anchor or fairlead, or, at a free point, to the point's node (``x_j = x_k``, a row of ``C`` with
``I`` at the end's node and ``-I`` at the point's). With ``mu_j`` the force the node passes to what it is tied to, one Newton
iteration solves the bordered system::

    [ J     C^T   0  ] [du]   [-R_u]        J: banded Newton matrix of the nodes
    [ C     0    -T  ] [mu] = [  0 ]        C: picks the tied nodes, T_j = [I, -skew(R p_j)]
    [ 0    -T^T   J_q] [dq]   [-R_q]        J_q: the bodies' own 6x6 Newton matrices

by its Schur complement: the band is factored once (``J = L U``, on its upper half when it is
symmetric, as the lines' tangents are), ``C J^-1 C^T`` comes from the short sweeps ``L^-1 e_k`` and
``U^-T e_k`` of the ``3 n_c`` tied rows (``n_c`` tied nodes; a few rows each when the node ends its
line's rows in the band, as a fairlead does), the small dense system in ``mu`` and ``dq`` is solved,
and one forward and one backward sweep give ``du``: about one band solve in all, linear in the number
of nodes. Tied nodes are then put back exactly on their body (``x_j = r + R p_j``), so the constraint
holds at every iterate. The first convergence check of a time step (where most steps stop) assembles
the residual only, not the Newton matrix; the criterion is the prescribed-motion model's.

The bodies' rotations and charts are those of :mod:`.frames`, their loads and tangents those of
:mod:`.body`, the band and dense solves those of :mod:`.linsolve`.
"""

from __future__ import annotations

import math

import numpy as np

from ..._jit import copy_1d, copy_2d, njit
from ...mooring.kernel import (
    E_VDT,
    GRID_HEADER,
    _force_tolerance,
    commit_viscoelastic,
    friction_loads,
    loads_water,
    n_water,
    predict_nodes,
    turn_held_ends,
)
from ...seastate import S_MODE
from ..statics.kernel import _skew
from .body import B_MASS, B_VOL, _body_current, _mv, body_load, body_tangent
from .clamps import C_BODY, C_ROW, clamp_moment, clamp_slopes, clamp_state, end_nodes, turn_clamps
from .frames import (
    CHART_LIMIT,
    F_GLOB,
    F_ON,
    _angle_increment,
    angular_map,
    body_rotation,
    rate_tangent,
    rechart,
    track_frame,
)
from .linsolve import band_backward, band_factor, band_forward, dense_solve, unit_column


@njit(cache=True)
def place_tied(X, q, con_node, con_body, con_arm, con_target, con_active, frame):
    """Put each tied node where it is tied: on its body (r + R p, ``R = R0 R(angles)`` of its chart
    ``frame[b]``), at its target, or on its free node (``con_body`` = -2 - node)."""
    R = np.empty((3, 3))
    for j in range(con_node.size):
        if con_active[j] == 0:
            continue
        i = con_node[j]
        b = con_body[j]
        if b >= 0:
            body_rotation(q[b], frame[b], R)
            for r in range(3):
                X[i, r] = q[b, r] + R[r, 0] * con_arm[j, 0] + R[r, 1] * con_arm[j, 1] + R[r, 2] * con_arm[j, 2]
        elif b <= -2:
            for r in range(3):
                X[i, r] = X[-2 - b, r]
        else:
            for r in range(3):
                X[i, r] = con_target[j, r]


@njit(cache=True)
def _angle_rows(E, m):
    """m <- E^T m: a moment as the generalised force of the angles."""
    a = E[0, 0] * m[0] + E[1, 0] * m[1] + E[2, 0] * m[2]
    b = E[0, 1] * m[0] + E[1, 1] * m[1] + E[2, 1] * m[2]
    c = E[0, 2] * m[0] + E[1, 2] * m[1] + E[2, 2] * m[2]
    m[0], m[1], m[2] = a, b, c


@njit(cache=True)
def iterate(X, V, A, q, qd, qdd, t, cm, cmb, cc, dynamic, check, jac, args, weight, fidx, nfree, bw, env, cur_depth, cur_speed,
            with_waves, sea, node_fext, con_node, con_body, con_arm, con_target, con_active, bpar, bkhs, badd, blin,
            bquad, ext_t, ext_f, ext_n, tol, F, M, tension, band, du, dq, out, Yt, tied, frame, spin, bmem, bk0, water,
            fresh, targets, dfric):
    """Assemble at the current state and solve one Newton correction ``du`` (3 per band node) and ``dq``
    (6 per body). Returns False when the matrix is singular. ``jac`` False: the residual only (``out``), no
    Newton matrix and no correction. ``with_waves`` and ``sea``: the waves on the lines, the regular wave of ``env``
    and the irregular sea's packed grid (:meth:`seacable.mooring.solver.MooringModel.prepare_sea`; its window must
    cover ``t``), as :func:`seacable.mooring.kernel.loads` takes them.

    ``cm`` multiplies the nodes' masses and ``cmb`` the bodies' in the Newton matrix (the same in a time
    step; statics scales the bodies' pseudo-inertia down to a node's). ``out`` receives (residual of the free nodes and bodies [N], absolute tolerance [N]). Bodies' moments
    count in the residual divided by the body's size (their largest point arm, at least 1 m). ``Yt``
    (12 n_c, 3 n_free) and ``tied`` (n,) are work arrays. ``frame`` (nb, F_SIZE): each body's chart (its
    rotation is ``R0 R(angles)``). ``spin`` (nb, 3): in statics (``dynamic`` False), a body-axes unit axis
    about which turning the body moves none of its points, centres of gravity and buoyancy nor its
    hydrostatics (a rod's own axis; zeros when none): that part of the rotation step is left out, since it
    has no stiffness and the Newton matrix's unsymmetric turning terms would give it an arbitrary size.
    ``water`` (:func:`seacable.mooring.kernel.n_water` rows, 7): the water over each node, computed here when
    ``fresh``, else the one it holds (:func:`seacable.mooring.kernel.loads_water`).
    ``bmem`` (nb, 6) and ``bk0`` (nb, 6, 6): each body's radiation memory (Cummins), the force of its velocities
    before this step and the matrix of the current one's share (``dt K_0 / 2``): the force ``-bmem - bk0 u``
    (global axes, ``u`` the reference point's velocity and the angular velocity); zeros without memory.
    ``targets`` (n, 3) and ``dfric`` [m]: the statics' seabed friction towards the nodes' friction targets
    (:func:`seacable.mooring.kernel.friction_loads`; no rows: none, as in the dynamics).
    """
    (elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, pmass, padd, pvol, pcda, bedc, buoy, pbuoy,
     ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, clamps) = args
    n = X.shape[0]
    nd = 3 * nfree
    nb = q.shape[0]
    rho, g = env[0], env[1]
    ncl = clamps.shape[0]
    if ncl:  # the held line ends on free bodies turn with them
        turn_clamps(q, frame, clamps, hinge_ei)
    bnd = band if jac else band[:0]  # no rows: loads skips the Newton matrix
    bnd[:] = 0.0
    loads_water(X, V, t, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda,
                bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth, cur_speed,
                with_waves, sea, F, M, tension, bnd, bw, cm, cc, water, fresh)
    friction_loads(X, targets, bedc, env, fidx, F, bnd, bw, dfric)
    for i in range(n):
        for r in range(3):
            F[i, r] += node_fext[i, r]
    Ru = du  # the residual of the nodes, then the correction in place
    for i in range(n):
        f = fidx[i]
        if f < 0:
            continue
        for r in range(3):
            v = -F[i, r]
            if dynamic:
                for c in range(3):
                    v += M[i, r, c] * A[i, c]
            Ru[3 * f + r] = v
    tied[:] = False
    nca = 0
    for j in range(con_node.size):
        if con_active[j]:
            tied[con_node[j]] = True
            nca += 1
    # a node tied to a free node passes its net force to it: the pair's residual is the sum (added to the
    # free node's for the check only)
    npart = 0
    for sign in (1.0, -1.0):
        for j in range(con_node.size):
            if con_active[j] and con_body[j] <= -2:
                fs, fp = fidx[con_node[j]], fidx[-2 - con_body[j]]
                npart += 1
                for r in range(3):
                    Ru[3 * fp + r] += sign * Ru[3 * fs + r]
        if sign > 0:
            res = 0.0
            for i in range(n):
                f = fidx[i]
                if f >= 0 and not tied[i]:
                    for r in range(3):
                        res = max(res, abs(Ru[3 * f + r]))
    npart //= 2
    scale = 0.0  # not checked: not needed
    if check:
        scale = _force_tolerance(tol, weight, tension, F, M, A, X, fidx, EA, bedc, env, cm if dynamic else 0.0)
    # bodies: own residual R_q = M6 (a, alpha) - f6, residual R_q - sum T^T mu (mu = the tied node's net force
    # -Ru), Newton matrix; their moment rows are then those of the angles (E^T times the moments, with w = E
    # qd[3:], the virtual rotation E dq[3:])
    nwk = 6 * nb + 36 * nb * nb
    wk = np.zeros(2 * nwk + 45 * nb + 3 * con_node.size + 153)  # one allocation for the work arrays
    Rq = wk[0:6 * nb]
    Jq = wk[6 * nb:nwk].reshape((6 * nb, 6 * nb))
    Rr = wk[nwk:nwk + 6 * nb]
    o = 2 * nwk
    f6 = wk[o:o + 6]
    M6 = wk[o + 6:o + 42].reshape((6, 6))
    R = wk[o + 42:o + 51].reshape((3, 3))
    S2 = wk[o + 60:o + 69].reshape((3, 3))
    Kb = wk[o + 69:o + 105].reshape((6, 6))
    Cb = wk[o + 105:o + 141].reshape((6, 6))
    arm = wk[o + 141:o + 144]
    acc = wk[o + 144:o + 150]
    ed = wk[o + 150:o + 153]
    o += 153
    Eb = wk[o:o + 9 * nb].reshape((nb, 3, 3))
    ub = wk[o + 9 * nb:o + 15 * nb].reshape((nb, 6))
    ucb = wk[o + 15 * nb:o + 20 * nb].reshape((nb, 5))  # the current (3) and the wind (2) at each body
    size = wk[o + 20 * nb:o + 21 * nb]
    size[:] = 1.0
    arms = wk[o + 21 * nb:o + 21 * nb + 3 * con_node.size].reshape((con_node.size, 3))
    for j in range(con_node.size):
        b = con_body[j]
        if b >= 0:
            size[b] = max(size[b], math.sqrt(con_arm[j, 0] ** 2 + con_arm[j, 1] ** 2 + con_arm[j, 2] ** 2))
    for b in range(nb):
        par = bpar[b]
        angular_map(q[b], qd[b], Eb[b], ed, frame[b])
        for r in range(3):
            ub[b, r] = qd[b, r]
            ub[b, 3 + r] = Eb[b, r, 0] * qd[b, 3] + Eb[b, r, 1] * qd[b, 4] + Eb[b, r, 2] * qd[b, 5]
            acc[r] = qdd[b, r]
            acc[3 + r] = Eb[b, r, 0] * qdd[b, 3] + Eb[b, r, 1] * qdd[b, 4] + Eb[b, r, 2] * qdd[b, 5] + ed[r]
        _body_current(q[b], env, cur_depth, cur_speed, ucb[b])
        body_load(q[b], ub[b], ucb[b], t, par, bkhs[b], badd[b], blin[b], bquad[b], ext_t[b], ext_f[b], ext_n[b], rho, g,
                  f6, M6, frame[b])
        if dynamic:  # the radiation memory: its past, and the current velocity's share
            for k in range(6):
                v = bmem[b, k]
                for c in range(6):
                    v += bk0[b, k, c] * ub[b, c]
                f6[k] -= v
        for k in range(6):
            v = -f6[k]
            if dynamic:
                for c in range(6):
                    v += M6[k, c] * acc[c]
            Rq[6 * b + k] = v
            for c in range(6):
                Jq[6 * b + k, 6 * b + c] += cmb * M6[k, c]
        if dynamic and frame[b, F_ON] != 0.0:
            # a re-charted body (one that turns a lot): the velocity part of its angular acceleration in the
            # Newton matrix too (left out for the others, whose results stay those without charts)
            P = S2
            rate_tangent(q[b], qd[b], frame[b], P)
            for k in range(6):
                for c in range(3):
                    Jq[6 * b + k, 6 * b + 3 + c] += cc * (M6[k, 3] * P[0, c] + M6[k, 4] * P[1, c] + M6[k, 5] * P[2, c])
        if check:
            scale = max(scale, tol * max(par[B_MASS] * g, rho * g * par[B_VOL]))
    # the held line ends' moments on their free bodies (:mod:`.clamps`): each end's couple on its line, reversed
    cf, cd, cJ = np.zeros((ncl, 3)), np.zeros((ncl, 3)), np.zeros((ncl, 3, 3))
    for c in range(ncl):
        b = int(clamps[c, C_BODY])
        clamp_state(X, hinges, hinge_ei, int(clamps[c, C_ROW]), cf[c], cJ[c], cd[c])
        clamp_moment(cf[c], cd[c], ed)
        for r in range(3):
            Rq[6 * b + 3 + r] -= ed[r]
    copy_1d(Rr, Rq)
    for j in range(con_node.size):
        b = con_body[j]
        if con_active[j] == 0 or b < 0:
            continue
        i = con_node[j]
        f = fidx[i]
        body_rotation(q[b], frame[b], R)
        _mv(R, con_arm[j], arm)
        copy_1d(arms[j], arm)
        m0, m1, m2 = -Ru[3 * f], -Ru[3 * f + 1], -Ru[3 * f + 2]
        # the residual of the body: R_q - T^T mu, force mu and moment arm x mu
        Rr[6 * b + 0] -= m0
        Rr[6 * b + 1] -= m1
        Rr[6 * b + 2] -= m2
        Rr[6 * b + 3] -= arm[1] * m2 - arm[2] * m1
        Rr[6 * b + 4] -= arm[2] * m0 - arm[0] * m2
        Rr[6 * b + 5] -= arm[0] * m1 - arm[1] * m0
    for b in range(nb):
        # the check on the angles' generalised forces E^T M; the Newton step itself is solved in rotation
        # vectors (moments as they are) and mapped to the angles after (see _angle_increment)
        _angle_rows(Eb[b], Rr[6 * b + 3:6 * b + 6])
        for k in range(6):
            res = max(res, abs(Rr[6 * b + k]) / (size[b] if k >= 3 else 1.0))
    out[0] = res
    out[1] = scale
    if not jac or (check and res <= scale):
        return True  # converged: no correction needed
    # the bodies' Newton matrices: their own forces' tangents, and the tied nodes' forces turning with them
    for b in range(nb):
        body_tangent(q[b], ub[b], ucb[b], bpar[b], bkhs[b], blin[b], bquad[b], rho, g, Kb, Cb, frame[b])
        for k in range(6):
            for c in range(6):
                Jq[6 * b + k, 6 * b + c] += Kb[k, c] + (cc * (Cb[k, c] + bk0[b, k, c]) if dynamic else 0.0)
    nc3 = 3 * nca
    nt3 = nc3 + 3 * npart  # the rows the constraints touch: the tied nodes', then their free nodes'
    rows = np.empty(nt3, np.int64)
    prow = np.full(nc3, -1, np.int64)  # the row in ``rows`` of a tied row's free node
    kp = nc3
    k = 0
    for j in range(con_node.size):
        if con_active[j] == 0:
            continue
        f = fidx[con_node[j]]
        b = con_body[j]
        if b >= 0:
            arm = arms[j]
            # the moment arm turns with the body: d(-arm x mu)/dphi = -skew(mu) skew(arm) = arm mu^T - (mu.arm) I,
            # mu = -Ru
            ma = 0.0
            for r in range(3):
                ma -= Ru[3 * f + r] * arm[r]
            for r in range(3):
                Jq[6 * b + 3 + r, 6 * b + 3 + r] += ma
                for c in range(3):
                    Jq[6 * b + 3 + r, 6 * b + 3 + c] += arm[r] * Ru[3 * f + c]
        if b <= -2:
            for r in range(3):
                rows[kp] = 3 * fidx[-2 - b] + r
                prow[k + r] = kp
                kp += 1
        for r in range(3):
            rows[k] = 3 * f + r
            k += 1
    # the held line ends on free bodies: their slopes on the body's rotation and the moment's on the nodes (:mod:`.clamps`);
    # the end node's through its tie, the neighbour's (a band node) through the Schur complement below
    cBw, cBm = np.zeros((ncl, 3, 3)), np.zeros((ncl, 3, 3))
    wrow = np.full(ncl, -1, np.int64)  # first band row of the neighbour, -1: not a band node of its own
    nwc = 0
    for c in range(ncl):
        b = int(clamps[c, C_BODY])
        ie, iw = end_nodes(hinges, int(clamps[c, C_ROW]))
        clamp_slopes(cf[c], cJ[c], cd[c], cBw[c], cBm[c], Kb[:3, :3])
        for r in range(3):
            for col in range(3):
                Jq[6 * b + 3 + r, 6 * b + 3 + col] += Kb[r, col]
        for j in range(con_node.size):
            if con_active[j] == 0 or con_node[j] != ie or con_body[j] != b:
                continue
            # du_e = T dq, T = [I, -skew(arm)]: the end's residual slope -Bw on the rotation enters as T^T (-Bw),
            # the moment's slope -Bm on the end as (-Bm) T
            _skew(arms[j], S2)
            for r in range(3):
                for col in range(3):
                    sb = S2[r, 0] * cBw[c, 0, col] + S2[r, 1] * cBw[c, 1, col] + S2[r, 2] * cBw[c, 2, col]
                    sm = cBm[c, r, 0] * S2[0, col] + cBm[c, r, 1] * S2[1, col] + cBm[c, r, 2] * S2[2, col]
                    Jq[6 * b + r, 6 * b + 3 + col] -= cBw[c, r, col]
                    Jq[6 * b + 3 + r, 6 * b + col] -= cBm[c, r, col]
                    Jq[6 * b + 3 + r, 6 * b + 3 + col] += sm - sb
        if fidx[iw] >= 0 and not tied[iw]:
            wrow[c] = 3 * fidx[iw]
            nwc += 1
    # Schur complement of the band J = L U: z0 = L^-1 (-Ru), v_k = L^-1 e_k and w_k = U^-T e_k (w_k = D^-1 v_k
    # when J is symmetric) for the touched rows k, so that (P J^-1 P^T)_ik = w_i . v_k and P J^-1 (-Ru) = w_i .
    # z0, and C = D P with D +1 at a tied row and -1 at its free node's row; each column is short when its node
    # ends its rows in the band (a fairlead at the end of its line)
    kind = band_factor(band, bw)
    if kind == 0:
        return False
    for a in range(nd):
        Ru[a] = -Ru[a]
    z0 = Ru
    band_forward(band, bw, z0)
    last = np.empty(2 * nt3, np.int64)
    for k in range(nt3):
        last[k] = unit_column(band, bw, Yt[k], rows[k], np.bool_(False))
        if kind == 1:
            last[nt3 + k] = unit_column(band, bw, Yt[nt3 + k], rows[k], np.bool_(True))
        else:
            for a in range(rows[k], last[k] + 1):
                Yt[nt3 + k, a] = Yt[k, a] / band[a, bw]
            last[nt3 + k] = last[k]
    m = nc3 + 6 * nb
    Sm = np.zeros((m, m))
    rhs = np.zeros(m)
    for i in range(nt3):
        w = Yt[nt3 + i]
        s = 0.0
        for a in range(rows[i], last[nt3 + i] + 1):
            s += w[a] * z0[a]
        ri, sgn_i = _tied_row(i, nc3, prow)  # a free node's row: into the tied row it belongs to, with -1
        rhs[ri] += sgn_i * s
        for c in range(nt3):
            v = Yt[c]
            s = 0.0
            for a in range(max(rows[i], rows[c]), min(last[nt3 + i], last[c]) + 1):
                s += w[a] * v[a]
            rc, sgn_c = _tied_row(c, nc3, prow)
            Sm[ri, rc] += sgn_i * sgn_c * s
    # S mu + T dq = C y0 and -T^T mu + Jq dq = -Rq, T = [I, -skew(arm)], dq[3:] a rotation vector
    k = 0
    for j in range(con_node.size):
        if con_active[j] == 0:
            continue
        b = con_body[j]
        if b >= 0:
            _skew(arms[j], S2)
            col = nc3 + 6 * b
            for r in range(3):
                row = k + r
                Sm[row, col + r] += 1.0
                Sm[col + r, row] -= 1.0
                for c in range(3):
                    Sm[row, col + 3 + c] -= S2[r, c]
                    Sm[col + 3 + c, row] += S2[r, c]
        k += 3
    for a in range(6 * nb):
        rhs[nc3 + a] = -Rq[a]
        for c in range(6 * nb):
            Sm[nc3 + a, nc3 + c] += Jq[a, c]
    nw3 = 3 * nwc
    wk3 = np.empty(nw3, np.int64)   # the neighbours' band rows, and their clamps
    wcl = np.empty(nw3, np.int64)
    lastw = np.empty(2 * nw3, np.int64)
    if nw3:
        _clamp_schur(band, bw, kind, Yt, 2 * nt3, rows, last, nt3, nc3, prow, wrow, wk3, wcl, lastw, clamps, cBw, cBm,
                     z0, Sm, rhs)
    if not dense_solve(Sm, rhs):
        return False
    # du = U^-1 (z0 - sum_k (v_k - v_pk) mu_k)
    for c in range(nt3):
        v = Yt[c]
        rc, sgn_c = _tied_row(c, nc3, prow)
        mu = sgn_c * rhs[rc]
        for a in range(rows[c], last[c] + 1):
            du[a] -= v[a] * mu
    for a in range(nw3):  # the neighbours' share of the bodies' turn: du -= J^-1 P_w^T Bw dphi
        c = wcl[a]
        b = int(clamps[c, C_BODY])
        r = a % 3
        coef = 0.0
        for col in range(3):
            coef += cBw[c, r, col] * rhs[nc3 + 6 * b + 3 + col]
        v = Yt[2 * nt3 + a]
        for k in range(wk3[a], lastw[a] + 1):
            du[k] -= v[k] * coef
    band_backward(band, bw, du)
    for a in range(6 * nb):
        dq[a] = rhs[nc3 + a]
    for b in range(nb):
        d = dq[6 * b + 3:6 * b + 6]
        if not dynamic and (spin[b, 0] != 0.0 or spin[b, 1] != 0.0 or spin[b, 2] != 0.0):
            body_rotation(q[b], frame[b], R)
            _mv(R, spin[b], arm)  # the free axis, global
            s = d[0] * arm[0] + d[1] * arm[1] + d[2] * arm[2]
            for r in range(3):
                d[r] -= s * arm[r]
        _angle_increment(q[b], d, frame[b])
    return True


@njit(cache=True)
def _tied_row(i, nc3, prow):
    """The constraint row of unknown ``i`` and its sign: a tied row (``i < nc3``) its own, +1; a free node's row the
    tied row it belongs to (``prow[k] == i``), -1 (-1 and -1 when it belongs to none)."""
    if i < nc3:
        return i, 1.0
    r = -1
    for k in range(nc3):
        if prow[k] == i:
            r = k
    return r, -1.0


@njit(cache=True)
def _dot(x, y, lo, hi):
    s = 0.0
    for a in range(lo, hi + 1):
        s += x[a] * y[a]
    return s


@njit(cache=True)
def _clamp_schur(band, bw, kind, Yt, base, rows, last, nt3, nc3, prow, wrow, wk3, wcl, lastw, clamps, cBw, cBm, z0,
                 Sm, rhs):
    """The held line ends' neighbour nodes in the Schur complement of :func:`iterate` (:mod:`.clamps`).

    With ``P_w`` the neighbours' rows, ``Bw`` their residuals' slope on their bodies' rotation and ``Bm`` the bodies'
    moment residual's slope on them, the bordered system gains ``J du + C^T mu + P_w^T Bw dq = -R_u`` and ``Bm P_w du
    - T^T mu + J_q dq = -R_q``; with ``G = P J^-1 P^T`` over the touched rows (``w_i . v_k``, as the tied rows'),
    the constraint rows gain ``+ G_cw Bw`` on the rotations, and the bodies' rows ``- Bm G_wc`` on ``mu``, ``- Bm
    G_ww Bw`` on the rotations and ``- Bm P_w J^-1 (-R_u)`` on the right. ``wk3``, ``wcl``, ``lastw`` receive the
    rows, their clamps and the columns' last rows; ``Yt[base:]`` their columns ``v`` then ``w``."""
    nw3 = wk3.size
    a = 0
    for c in range(clamps.shape[0]):
        if wrow[c] < 0:
            continue
        for r in range(3):
            wk3[a] = wrow[c] + r
            wcl[a] = c
            a += 1
    for a in range(nw3):
        lastw[a] = unit_column(band, bw, Yt[base + a], wk3[a], np.bool_(False))
        if kind == 1:
            lastw[nw3 + a] = unit_column(band, bw, Yt[base + nw3 + a], wk3[a], np.bool_(True))
        else:
            for k in range(wk3[a], lastw[a] + 1):
                Yt[base + nw3 + a, k] = Yt[base + a, k] / band[k, bw]
            lastw[nw3 + a] = lastw[a]
    # the constraint rows (the tied rows and their free nodes', as iterate maps them) on the rotations
    for i in range(nt3):
        w = Yt[nt3 + i]
        ri, sgn_i = _tied_row(i, nc3, prow)
        for a in range(nw3):
            G = _dot(w, Yt[base + a], max(rows[i], wk3[a]), min(last[nt3 + i], lastw[a]))
            c = wcl[a]
            b = int(clamps[c, 1])
            for cc in range(3):
                Sm[ri, nc3 + 6 * b + 3 + cc] += sgn_i * G * cBw[c, a % 3, cc]
    # the bodies' moment rows
    for a in range(nw3):
        w = Yt[base + nw3 + a]
        c = wcl[a]
        b = int(clamps[c, 1])
        r = a % 3
        s = _dot(w, z0, wk3[a], lastw[nw3 + a])
        for p in range(3):
            rhs[nc3 + 6 * b + 3 + p] -= cBm[c, p, r] * s
        for k in range(nt3):
            G = _dot(w, Yt[k], max(wk3[a], rows[k]), min(lastw[nw3 + a], last[k]))
            rk, sgn = _tied_row(k, nc3, prow)
            for p in range(3):
                Sm[nc3 + 6 * b + 3 + p, rk] -= cBm[c, p, r] * sgn * G
        for a2 in range(nw3):
            G = _dot(w, Yt[base + a2], max(wk3[a], wk3[a2]), min(lastw[nw3 + a], lastw[a2]))
            c2 = wcl[a2]
            b2 = int(clamps[c2, 1])
            for p in range(3):
                for cc in range(3):
                    Sm[nc3 + 6 * b + 3 + p, nc3 + 6 * b2 + 3 + cc] -= cBm[c, p, r] * G * cBw[c2, a2 % 3, cc]


@njit(cache=True)
def _apply(X, q, du, dq, fidx, s):
    for i in range(X.shape[0]):
        f = fidx[i]
        if f >= 0:
            for r in range(3):
                X[i, r] += s * du[3 * f + r]
    for b in range(q.shape[0]):
        for k in range(6):
            q[b, k] += s * dq[6 * b + k]


@njit(cache=True)
def coupled_steps(X, V, A, q, qd, qdd, t0, dt, px, pv, pa, channel, args, weight, fidx, nfree, bw, env, cur_depth,
                  cur_speed, with_waves, sea, node_fext, con_node, con_body, con_arm, con_target, con_active, con_chan,
                  fail_time, fail_tension, fail_elem, fail_at, bpar, bkhs, badd, blin, bquad, ext_t, ext_f, ext_n,
                  beta, gamma, tol, max_iter, F, M, tension, stats, frame, rker, rhist, rhead, hk):
    """Advance ``px.shape[0]`` Newmark steps (average acceleration) of the lines and bodies together.

    ``px/pv/pa[k, channel]`` are the prescribed positions, velocities and accelerations at the end of
    step k; ``sea`` is the irregular sea's packed grid (see :func:`iterate`), its window covering the steps.
    After each step a tied line end whose failure time has come, or whose end element's tension reached
    its failure tension, is released (``con_active`` 0, ``fail_at`` the time). Returns
    the number of steps completed; a step whose Newton iteration fails leaves the state at its start.
    ``stats`` receives (iterations, last residual, absolute force tolerance [N]). After each converged step a
    body whose |pitch| exceeds ``CHART_LIMIT``, or that was re-charted before, is re-charted (:func:`rechart`;
    ``frame`` is updated in place, with the continuous global angles of every re-charted body).

    ``rker`` (nb, n_k, 6, 6): each body's radiation kernel sampled every ``hk`` [s], the run's time step
    (``rker[b, 0]`` = K(0), the last sample halved: the trapezoidal rule), zeros for a body without memory (n_k 1
    when none has any); ``rhist`` (nb, n_k, 6) the velocities ``u`` at the past multiples of ``hk``,
    ``rhist[b, (rhead[b] - j + 1) % n_k]`` the one ``j`` samples back, advanced in place. The memory force at a
    step's end is ``-hk (K_0 u / 2 + sum_{j>=1} K_j u_{-j})``. A step shorter than ``hk`` (an interval finished
    at halved steps) takes that same sum over the history as it stands, its lags short by less than one ``hk``
    (an approximation for the few halved steps of a run), and adds its velocity to the history only when it
    ends on a multiple of ``hk``.
    """
    n = X.shape[0]
    nb = q.shape[0]
    nk = rker.shape[1]
    bmem = np.zeros((nb, 6))
    bk0 = np.zeros((nb, 6, 6))
    Eu = np.empty((3, 3))
    edu = np.empty(3)
    nd = 3 * nfree
    band = np.zeros((nd, 2 * bw + 1))
    du = np.zeros(nd)
    dq = np.zeros(6 * nb)
    Du = np.zeros(nd)
    Dq = np.zeros(6 * nb)
    out = np.zeros(2)
    Yt = np.zeros((12 * con_node.size + 6 * args[24].shape[0], nd))
    tied = np.zeros(n, np.bool_)
    Xn, Vn, An = np.empty_like(X), np.empty_like(V), np.empty_like(A)
    qn, qdn, qddn = np.empty_like(q), np.empty_like(qd), np.empty_like(qdd)
    c0 = 1.0 / (beta * dt * dt)
    c1 = gamma / (beta * dt)
    spin = np.zeros((nb, 3))  # dynamics: a free spin keeps its (small) inertia
    gq = np.empty(3)
    env = env.copy()
    env[E_VDT] = dt  # viscoelastic lines: the slow stretch advances over the step
    # an irregular sea: the water's kinematics of a step are looked up at its predicted positions and held over
    # its Newton iterations, as the single line's kernel does (:func:`seacable.mooring.kernel.newmark_steps`): the
    # corrections move the nodes by millimetres, the kinematics change over them by about k dx (1e-4 of themselves,
    # far below the grid's interpolation error), and with them in the iterations the Newton matrix, which leaves
    # out their gradient, took a third iteration at most steps of a storm
    held = sea[S_MODE] > 0.0 and with_waves
    water = np.zeros((n_water(X, env, cur_depth, with_waves, sea), 7))
    for step in range(px.shape[0]):
        copy_2d(Xn, X)
        copy_2d(Vn, V)
        copy_2d(An, A)
        copy_2d(qn, q)
        copy_2d(qdn, qd)
        copy_2d(qddn, qdd)
        t = t0 + (step + 1) * dt
        if nk > 1:  # the radiation memory of the velocities before this step
            for b in range(nb):
                for r in range(6):
                    v = 0.0
                    for j in range(1, nk):
                        h = rhist[b, (rhead[b] - j + 1) % nk]
                        for c in range(6):
                            v += rker[b, j, r, c] * h[c]
                    bmem[b, r] = hk * v
                    for c in range(6):
                        bk0[b, r, c] = 0.5 * hk * rker[b, 0, r, c]
        predict_nodes(X, V, A, Xn, Vn, An, px, pv, pa, step, channel, fidx, dt)
        turn_held_ends(args[22], px, step)  # the held ends on prescribed bodies turn with their motion
        for j in range(con_node.size):
            if con_chan[j] >= 0:
                for r in range(3):
                    con_target[j, r] = px[step, con_chan[j], r]
        for b in range(nb):
            for k in range(6):
                q[b, k] = qn[b, k] + dt * qdn[b, k] + 0.5 * dt * dt * qddn[b, k]
        place_tied(X, q, con_node, con_body, con_arm, con_target, con_active, frame)
        ok = False
        res = 0.0
        res_prev = np.inf
        cuts = 0
        scale = 1.0
        for it in range(max_iter):
            for i in range(n):
                if fidx[i] >= 0:
                    for r in range(3):
                        A[i, r] = c0 * (X[i, r] - Xn[i, r]) - Vn[i, r] / (beta * dt) - (0.5 / beta - 1.0) * An[i, r]
                        V[i, r] = Vn[i, r] + dt * ((1.0 - gamma) * An[i, r] + gamma * A[i, r])
            for b in range(nb):
                for k in range(6):
                    qdd[b, k] = c0 * (q[b, k] - qn[b, k]) - qdn[b, k] / (beta * dt) - (0.5 / beta - 1.0) * qddn[b, k]
                    qd[b, k] = qdn[b, k] + dt * ((1.0 - gamma) * qddn[b, k] + gamma * qdd[b, k])
            fresh = it == 0 or not held
            # the first check of a step, where most steps converge, assembles the residual only
            for jac in (it != 1, np.bool_(True)):
                solved = iterate(X, V, A, q, qd, qdd, t, c0, c0, c1, np.bool_(True), it > 0, jac, args, weight, fidx, nfree, bw,
                                 env, cur_depth, cur_speed, with_waves, sea, node_fext, con_node, con_body, con_arm,
                                 con_target, con_active, bpar, bkhs, badd, blin, bquad, ext_t, ext_f, ext_n, tol, F, M,
                                 tension, band, du, dq, out, Yt, tied, frame, spin, bmem, bk0, water, fresh,
                                 np.zeros((0, 3)), 0.0)
                if jac or out[0] <= out[1] or not (out[0] < res_prev):
                    break
            res, scale = out[0], out[1]
            stats[0] += 1
            if res <= scale and it > 0:
                ok = True
                break
            if it > 0 and not (res < res_prev) and cuts < 6:
                # backtrack: the full Newton step made things worse (contact or slack switching)
                cuts += 1
                Du *= 0.5
                Dq *= 0.5
                _apply(X, q, Du, Dq, fidx, -1.0)
                place_tied(X, q, con_node, con_body, con_arm, con_target, con_active, frame)
                continue
            if not math.isfinite(res) or not solved:
                break
            res_prev = res
            cuts = 0
            copy_1d(Du, du)
            copy_1d(Dq, dq)
            _apply(X, q, du, dq, fidx, 1.0)
            place_tied(X, q, con_node, con_body, con_arm, con_target, con_active, frame)
        stats[1] = res
        stats[2] = scale
        if not ok:
            copy_2d(X, Xn)
            copy_2d(V, Vn)
            copy_2d(A, An)
            copy_2d(q, qn)
            copy_2d(qd, qdn)
            copy_2d(qdd, qddn)
            return step
        commit_viscoelastic(args[23])
        # this step's velocities into the memory (before a re-chart changes the angles' map), at multiples of hk
        if nk > 1 and (dt == hk or abs(t / hk - round(t / hk)) < 1e-6):
            for b in range(nb):
                angular_map(q[b], qd[b], Eu, edu, frame[b])
                rhead[b] = (rhead[b] + 1) % nk
                for r in range(3):
                    rhist[b, rhead[b], r] = qd[b, r]
                    rhist[b, rhead[b], 3 + r] = Eu[r, 0] * qd[b, 3] + Eu[r, 1] * qd[b, 4] + Eu[r, 2] * qd[b, 5]
        for b in range(nb):  # once re-charted, a body is re-charted after every step
            track_frame(q[b], qd[b], qdd[b], frame[b], gq, CHART_LIMIT if frame[b, F_ON] == 0.0 else 0.0)
        for j in range(con_node.size):
            if con_active[j] == 0:
                continue
            e = fail_elem[j]
            if t >= fail_time[j] - 1e-9 * dt or (e >= 0 and tension[e] >= fail_tension[j]):
                con_active[j] = 0
                fail_at[j] = t
    return px.shape[0]


@njit(cache=True)
def coupled_static(X, q, args, weight, fidx, nfree, bw, env, cur_depth, cur_speed, node_fext, con_node, con_body,
                   con_arm, con_target, con_active, bpar, bkhs, badd, blin, bquad, ext_t, ext_f, ext_n, tol, max_iter,
                   max_step, body_scale, F, M, tension, stats, frame, spin, targets, dfric):
    """Static equilibrium of the lines and bodies by pseudo-transient Newton, ``(K + lam M) dx = -R``.

    The bodies' mass matrices in ``M`` are scaled by ``body_scale`` (a node's mass over a body's), so
    that the pseudo-time moves a body as fast as a node.

    ``lam`` [1/s^2] starts where a node under its weight moves a fraction of an element and follows the
    residual (switched evolution relaxation); a step is limited to ``max_step`` [m] of any node or body
    and 0.1 rad of rotation (the turn about a body's free ``spin`` axis left out, see :func:`iterate`). A
    body whose |pitch| exceeds ``CHART_LIMIT`` after an iteration is re-charted (``frame``, in place, as in
    :func:`coupled_steps`). Returns True when converged; ``stats`` receives (iterations, residual, absolute
    force tolerance [N]). ``targets`` (n, 3), ``dfric`` [m]: the seabed's static friction (:func:`iterate`; no rows:
    frictionless).
    """
    nb = q.shape[0]
    nd = 3 * nfree
    V = np.zeros_like(X)
    A = np.zeros_like(X)
    qd = np.zeros_like(q)
    qdd = np.zeros_like(q)
    band = np.zeros((nd, 2 * bw + 1))
    du = np.zeros(nd)
    dq = np.zeros(6 * nb)
    out = np.zeros(2)
    Yt = np.zeros((12 * con_node.size + 6 * args[24].shape[0], nd))
    tied = np.zeros(X.shape[0], np.bool_)
    water = np.zeros((n_water(X, env, cur_depth, np.bool_(False), np.zeros(GRID_HEADER)), 7))
    gq = np.empty(3)
    for b in range(nb):
        if frame[b, F_ON] == 0.0:
            for k in range(3):
                frame[b, F_GLOB + k] = q[b, 3 + k]
        rechart(q[b], qd[b], qdd[b], frame[b], CHART_LIMIT)
    Xp = X.copy()
    qp = q.copy()
    framep = frame.copy()
    lam = env[1] / (0.05 * max_step)
    lam_min = 1e-9 * lam  # keeps a DOF without stiffness (the yaw of a body on one line) regular
    res_prev = np.inf
    place_tied(X, q, con_node, con_body, con_arm, con_target, con_active, frame)
    for it in range(max_iter):
        solved = iterate(X, V, A, q, qd, qdd, 0.0, lam, lam * body_scale, 0.0, np.bool_(False), np.bool_(True), np.bool_(True), args, weight, fidx, nfree, bw, env, cur_depth,
                         cur_speed, np.bool_(False), np.zeros(GRID_HEADER), node_fext, con_node, con_body, con_arm, con_target, con_active, bpar, bkhs,
                         badd, blin, bquad, ext_t, ext_f, ext_n, tol, F, M, tension, band, du, dq, out, Yt, tied, frame,
                         spin, np.zeros((nb, 6)), np.zeros((nb, 6, 6)), water, np.bool_(True), targets, dfric)
        res, scale = out[0], out[1]
        stats[0] = it
        stats[1] = res
        stats[2] = scale
        if res <= scale:
            return True
        if not math.isfinite(res) or not solved or res > 1e3 * res_prev:
            # back to the last state, more inertia
            copy_2d(X, Xp)
            copy_2d(q, qp)
            copy_2d(frame, framep)
            lam *= 10.0
            res_prev = np.inf
            continue
        if math.isfinite(res_prev):
            lam = max(lam * min(max(res / res_prev, 0.05), 10.0), lam_min)
        res_prev = res
        big = 0.0
        for k in range(nd):
            big = max(big, abs(du[k]))
        rot = 0.0
        for b in range(nb):
            for k in range(3):
                big = max(big, abs(dq[6 * b + k]))
                rot = max(rot, abs(dq[6 * b + 3 + k]))
        shrink = 1.0
        if big > max_step:
            shrink = max_step / big
        if rot * shrink > 0.1:
            shrink = 0.1 / rot
        copy_2d(Xp, X)
        copy_2d(qp, q)
        copy_2d(framep, frame)
        _apply(X, q, du, dq, fidx, shrink)
        for b in range(nb):
            track_frame(q[b], qd[b], qdd[b], frame[b], gq, CHART_LIMIT)
        place_tied(X, q, con_node, con_body, con_arm, con_target, con_active, frame)
    return False

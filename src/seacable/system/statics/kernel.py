"""Compiled assembly of the system's residual and Jacobian (private to :mod:`.evaluation`).

The same equations as the module docstring of :mod:`.evaluation`, in loops: sub-line end
forces and their 3x3 derivative blocks, node forces, the residual of every DOF and its
Jacobian ``J = G^T D G`` plus the moment arms' rotation ``[f]x [r]x`` (G maps DOF increments
to node displacements: identity for a free node, ``[I, -[r]x]`` for a node on a body), and the
bodies' own weight, buoyancy, heave and waterplane terms.
"""

from __future__ import annotations

import math

import numpy as np

from ..._jit import copy_2d, njit


@njit(cache=True, error_model="numpy")
def _skew(v, out):
    out[0, 0] = 0.0
    out[0, 1] = -v[2]
    out[0, 2] = v[1]
    out[1, 0] = v[2]
    out[1, 1] = 0.0
    out[1, 2] = -v[0]
    out[2, 0] = -v[1]
    out[2, 1] = v[0]
    out[2, 2] = 0.0


@njit(cache=True, error_model="numpy")
def _block(kxx, kxz, kzx, kzz, kt, ex, ey, out):
    e = (ex, ey)
    for i in range(2):
        for j in range(2):
            ee = e[i] * e[j]
            out[i, j] = kxx * ee + kt * ((1.0 if i == j else 0.0) - ee)
        out[i, 2] = kxz * e[i]
        out[2, i] = kzx * e[i]
    out[2, 2] = kzz


@njit(cache=True, error_model="numpy")
def assemble(P, X, sub_a, sub_b, anchor_is_a, e, tiny, HF, VF, HA, VA, K, grounded, mu, node_force, node_buoy,
             node_kind, node_body, node_dof, nb, ndof, fa, fb, nf, res, jac):
    """Fill fa, fb (ns, 3), nf (nn, 3), res (ndof,) and jac (ndof, ndof) with the line terms (and the node
    loads: ``node_force``, less the buoyancy ``node_buoy`` of nodes above the water)."""
    ns = sub_a.size
    nn = P.shape[0]
    copy_2d(nf, node_force)
    for n in range(nn):
        if node_buoy[n] != 0.0 and P[n, 2] > 0.0:
            nf[n, 2] -= node_buoy[n]           # above the water: dry weight (a step, no Jacobian term)
    res[:] = 0.0
    jac[:, :] = 0.0
    DF = np.empty((3, 3))
    DAF = np.empty((3, 3))
    # node -> DOF maps G (3 x 6 for a body node, 3 x 3 for a free node)
    r = np.zeros((nn, 3))
    G = np.zeros((nn, 3, 6))
    S = np.empty((3, 3))
    for n in range(nn):
        if node_kind[n] == 1:
            k = node_body[n]
            for i in range(3):
                r[n, i] = P[n, i] - X[k, i]
            _skew(r[n], S)
            for i in range(3):
                G[n, i, i] = 1.0
                for j in range(3):
                    G[n, i, 3 + j] = -S[i, j]
        elif node_kind[n] == 2:
            for i in range(3):
                G[n, i, i] = 1.0
    for s in range(ns):
        ex, ey = e[s, 0], e[s, 1]
        fF = (-HF[s] * ex, -HF[s] * ey, -VF[s])
        fA = (HA[s] * ex, HA[s] * ey, VA[s])
        ia, ib = sub_a[s], sub_b[s]
        iA, iF = (ia, ib) if anchor_is_a[s] else (ib, ia)
        for i in range(3):
            if anchor_is_a[s]:
                fa[s, i], fb[s, i] = fA[i], fF[i]
            else:
                fa[s, i], fb[s, i] = fF[i], fA[i]
            nf[iA, i] += fA[i]
            nf[iF, i] += fF[i]
        k00, k01, k10, k11 = K[s, 0, 0], K[s, 0, 1], K[s, 1, 0], K[s, 1, 1]
        # a tensioned line lying flat has dV/dz = inf (lift-off); its end's height is held
        k00 = k00 if np.isfinite(k00) else 0.0
        k01 = k01 if np.isfinite(k01) else 0.0
        k10 = k10 if np.isfinite(k10) else 0.0
        k11 = k11 if np.isfinite(k11) else 0.0
        hs = max(np.hypot(P[ib, 0] - P[ia, 0], P[ib, 1] - P[ia, 1]), 1e-300)
        kt = k00 if tiny[s] else HF[s] / hs
        _block(k00, k01, k10, k11, kt, ex, ey, DF)
        for i in range(3):
            for j in range(3):
                DF[i, j] = -DF[i, j]
        if grounded[s]:
            if HA[s] > 0:
                hx, hz = k00 + mu * k10, k01 + mu * k11
            else:
                hx, hz = 0.0, 0.0
            vx, vz = 0.0, 0.0
        else:
            hx, hz, vx, vz = k00, k01, k10, k11
        kta = hx if tiny[s] else HA[s] / hs
        _block(hx, hz, vx, vz, kta, ex, ey, DAF)
        # node-node blocks: (F,F) DF, (F,A) -DF, (A,F) DAF, (A,A) -DAF, mapped through G
        for (ni, nj, sgn, D) in ((iF, iF, 1.0, DF), (iF, iA, -1.0, DF), (iA, iF, 1.0, DAF), (iA, iA, -1.0, DAF)):
            if node_kind[ni] == 0 or node_kind[nj] == 0:
                continue
            di, dj = node_dof[ni], node_dof[nj]
            wi = 6 if node_kind[ni] == 1 else 3
            wj = 6 if node_kind[nj] == 1 else 3
            # T = D G_j (3 x wj); jac[di.., dj..] += G_i^T T
            for b in range(wj):
                t0 = sgn * (D[0, 0] * G[nj, 0, b] + D[0, 1] * G[nj, 1, b] + D[0, 2] * G[nj, 2, b])
                t1 = sgn * (D[1, 0] * G[nj, 0, b] + D[1, 1] * G[nj, 1, b] + D[1, 2] * G[nj, 2, b])
                t2 = sgn * (D[2, 0] * G[nj, 0, b] + D[2, 1] * G[nj, 1, b] + D[2, 2] * G[nj, 2, b])
                for a in range(wi):
                    jac[di + a, dj + b] += G[ni, 0, a] * t0 + G[ni, 1, a] * t1 + G[ni, 2, a] * t2
    # residual and the rotation of the moment arms
    Sf = np.empty((3, 3))
    for n in range(nn):
        d = node_dof[n]
        if node_kind[n] == 2:
            for i in range(3):
                res[d + i] += nf[n, i]
        elif node_kind[n] == 1:
            rr = r[n]
            f = nf[n]
            res[d] += f[0]
            res[d + 1] += f[1]
            res[d + 2] += f[2]
            res[d + 3] += rr[1] * f[2] - rr[2] * f[1]
            res[d + 4] += rr[2] * f[0] - rr[0] * f[2]
            res[d + 5] += rr[0] * f[1] - rr[1] * f[0]
            _skew(f, Sf)
            _skew(rr, S)
            for i in range(3):
                for j in range(3):
                    jac[d + 3 + i, d + 3 + j] += Sf[i, 0] * S[0, j] + Sf[i, 1] * S[1, j] + Sf[i, 2] * S[2, j]


@njit(cache=True, error_model="numpy")
def body_terms(R, X, mass, rcg, volume, rcb, awp, iwp, z0, rho, g, own, own_jac):
    """Weight at R r_CG, buoyancy at R r_CB, heave -rho g A_wp (z - z0), waterplane moment; and -d/dq."""
    Sw = np.empty((3, 3))
    Sr = np.empty((3, 3))
    for k in range(X.shape[0]):
        W = -mass[k] * g
        B = rho * g * volume[k]
        rg = R[k] @ rcg[k]
        rb = R[k] @ rcb[k]
        a = R[k][:, 2]
        own[k, :] = 0.0
        own_jac[k, :, :] = 0.0
        own[k, 2] = W + B - rho * g * awp[k] * (X[k, 2] - z0[k])
        # r x (0, 0, F) = (r_y F, -r_x F, 0)
        own[k, 3] = rg[1] * W + rb[1] * B + rho * g * iwp[k, 0] * a[1]
        own[k, 4] = -rg[0] * W - rb[0] * B - rho * g * iwp[k, 1] * a[0]
        own_jac[k, 2, 2] = -rho * g * awp[k]
        for (F, rr) in ((W, rg), (B, rb)):
            _skew(np.array([0.0, 0.0, F]), Sw)
            _skew(rr, Sr)
            for i in range(3):
                for j in range(3):
                    own_jac[k, 3 + i, 3 + j] += Sw[i, 0] * Sr[0, j] + Sw[i, 1] * Sr[1, j] + Sw[i, 2] * Sr[2, j]
        # - P [a]x with P = rho g [[0, Ixx, 0], [-Iyy, 0, 0], [0, 0, 0]]
        _skew(a, Sr)
        for j in range(3):
            own_jac[k, 3, 3 + j] -= rho * g * iwp[k, 0] * Sr[1, j]
            own_jac[k, 4, 3 + j] += rho * g * iwp[k, 1] * Sr[0, j]


@njit(cache=True, error_model="numpy")
def node_positions(P, X, R, node_kind, node_body, node_rel, out):
    """out = P with every body node at X + R r_rel of its body."""
    for n in range(P.shape[0]):
        if node_kind[n] == 1:
            k = node_body[n]
            r = node_rel[n]
            for i in range(3):
                out[n, i] = X[k, i] + R[k, i, 0] * r[0] + R[k, i, 1] * r[1] + R[k, i, 2] * r[2]
        else:
            for i in range(3):
                out[n, i] = P[n, i]


@njit(cache=True, error_model="numpy")
def step_state(X, R, P, dq, alpha, free_nodes, depth, X2, R2, P2, grounded, floats, surfaced):
    """X2, R2, P2 = the state moved by alpha dq (rotations R -> Rot(alpha th) R, Rodrigues); free
    nodes below the seabed (depth NaN: none) put on it and flagged in ``grounded``; free nodes with
    buoyancy (``floats``) that rise through the surface from below stopped at z = 0 and flagged in
    ``surfaced``."""
    nb = X.shape[0]
    K = np.empty((3, 3))
    Q = np.empty((3, 3))
    for k in range(nb):
        for i in range(3):
            X2[k, i] = X[k, i] + alpha * dq[6 * k + i]
        t0, t1, t2 = alpha * dq[6 * k + 3], alpha * dq[6 * k + 4], alpha * dq[6 * k + 5]
        a = math.sqrt(t0 * t0 + t1 * t1 + t2 * t2)
        if a < 1e-300:
            for i in range(3):
                for j in range(3):
                    R2[k, i, j] = R[k, i, j]
            continue
        k0, k1, k2 = t0 / a, t1 / a, t2 / a
        K[0, 0], K[0, 1], K[0, 2] = 0.0, -k2, k1
        K[1, 0], K[1, 1], K[1, 2] = k2, 0.0, -k0
        K[2, 0], K[2, 1], K[2, 2] = -k1, k0, 0.0
        s, c = math.sin(a), 1.0 - math.cos(a)
        for i in range(3):
            for j in range(3):
                KK = K[i, 0] * K[0, j] + K[i, 1] * K[1, j] + K[i, 2] * K[2, j]
                Q[i, j] = (1.0 if i == j else 0.0) + s * K[i, j] + c * KK
        for i in range(3):
            for j in range(3):
                R2[k, i, j] = Q[i, 0] * R[k, 0, j] + Q[i, 1] * R[k, 1, j] + Q[i, 2] * R[k, 2, j]
    for n in range(P.shape[0]):
        for i in range(3):
            P2[n, i] = P[n, i]
    base = 6 * nb
    for j in range(free_nodes.size):
        n = free_nodes[j]
        for i in range(3):
            P2[n, i] = P[n, i] + alpha * dq[base + 3 * j + i]
        if not math.isnan(depth) and P2[n, 2] < -depth:
            P2[n, 2] = -depth
            grounded[n] = True
        if floats[n] and P[n, 2] <= 0.0 and P2[n, 2] > 0.0:
            P2[n, 2] = 0.0
            surfaced[n] = True


@njit(cache=True, error_model="numpy")
def _absmax(dq, i0, i1):
    m = 0.0
    for i in range(i0, i1):
        m = max(m, abs(dq[i]))
    return m


@njit(cache=True, error_model="numpy")
def clip_step(dq, nb, step_len, out):
    """out = dq with each body's translation (rotation) scaled to at most step_len (0.2 rad) in its
    largest component, and each free node's to step_len."""
    for i in range(dq.size):
        out[i] = dq[i]
    for k in range(nb):
        for i0, lim in ((6 * k, step_len), (6 * k + 3, 0.2)):
            n = _absmax(dq, i0, i0 + 3)
            if n > lim:
                f = lim / n
                for i in range(i0, i0 + 3):
                    out[i] *= f
    for i0 in range(6 * nb, dq.size, 3):
        n = _absmax(dq, i0, i0 + 3)
        if n > step_len:
            f = step_len / n
            for i in range(i0, i0 + 3):
                out[i] *= f


@njit(cache=True, error_model="numpy")
def uniform_limit(dq, nb, step_len):
    """Factor that brings the largest translation to step_len and rotation to 0.2 rad (at most 1)."""
    lim = 1.0
    for k in range(nb):
        lim = min(lim, step_len / max(_absmax(dq, 6 * k, 6 * k + 3), 1e-300),
                  0.2 / max(_absmax(dq, 6 * k + 3, 6 * k + 6), 1e-300))
    if dq.size > 6 * nb:
        lim = min(lim, step_len / max(_absmax(dq, 6 * nb, dq.size), 1e-300))
    return lim


@njit(cache=True, error_model="numpy")
def force_scale(fa, fb, own, floor):
    """max(floor, largest |component| of fa, fb and own)."""
    m = floor
    for a in (fa, fb):
        for i in range(a.shape[0]):
            for j in range(3):
                m = max(m, abs(a[i, j]))
    for i in range(own.shape[0]):
        for j in range(6):
            m = max(m, abs(own[i, j]))
    return m


@njit(cache=True, error_model="numpy")
def assemble_all(P, X, R, sub_a, sub_b, anchor_is_a, e, tiny, HF, VF, HA, VA, K, regime, grounded_of, mu,
                 node_force, node_buoy, node_kind, node_body, node_dof, nb, ndof, mass, rcg, volume, rcb, awp, iwp,
                 z0, rho,
                 g, external, load_factor, floor, fa, fb, nf, res, jac_lines, jac, hydro):
    """:func:`assemble` and :func:`body_terms` in one call (bodies without a user hydrostatic matrix):
    fills fa, fb, nf, res (lines, bodies' own terms and external loads), jac_lines, jac (all terms)
    and hydro (6 nb x 6 nb, the bodies' own restoring); returns the force scale
    max(floor, |fa|, |fb|, |own terms|)."""
    ns = sub_a.size
    grounded = np.empty(ns, np.bool_)
    for s in range(ns):
        grounded[s] = grounded_of[regime[s]]
    assemble(P, X, sub_a, sub_b, anchor_is_a, e, tiny, HF, VF, HA, VA, K, grounded, mu, node_force, node_buoy, node_kind,
             node_body, node_dof, nb, ndof, fa, fb, nf, res, jac_lines)
    own = np.zeros((nb, 6))
    own_jac = np.zeros((nb, 6, 6))
    if nb:
        body_terms(R, X, mass, rcg, volume, rcb, awp, iwp, z0, rho, g, own, own_jac)
    for i in range(ndof):
        for j in range(ndof):
            jac[i, j] = jac_lines[i, j]
    hydro[:, :] = 0.0
    for k in range(nb):
        for i in range(6):
            res[6 * k + i] += own[k, i] + load_factor * external[k, i]
            for j in range(6):
                jac[6 * k + i, 6 * k + j] += own_jac[k, i, j]
                hydro[6 * k + i, 6 * k + j] = -own_jac[k, i, j]
    return force_scale(fa, fb, own, floor)


@njit(cache=True)
def solve(A, b):
    """np.linalg.solve compiled (no Python call overhead); raises LinAlgError when A is singular."""
    return np.linalg.solve(A, b)

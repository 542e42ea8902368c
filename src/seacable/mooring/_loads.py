"""The mooring kernel's loads pass: every force on the nodes but inertia and supports, the node masses and the
Newton matrix (:func:`loads`, :func:`loads_water`).

The elastic elements, weight and buoyancy across the waterline, the Morison loads of the half elements, the
attachments and the seabed contact, node by node; the other element kinds in the passes of
:mod:`seacable.mooring._elements`. Part of :mod:`seacable.mooring.kernel`, which re-exports the public names.
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import njit
from ..seastate import S_ETAMAX, S_MODE, S_STRETCH, grid_points
from ._band import _add_block, _add_pair
from ._body import body_added_mass, body_axes, body_drag, body_drag_turn
from ._elements import bending_loads, syrope_loads, table_tension, viscoelastic_loads
from ._indices import (E_ALPHA, E_BDRAG, E_BEDFULL, E_BEDRAMP, E_BEDTAB, E_BMASS, E_BODY, E_CBOT, E_CHEAD, E_COMPRESS, E_DEPTH, E_DRAGTURN,
                       E_FRAMEX, E_FRAMEY, E_FRAMEZ, E_G, E_KBOT, E_MU, E_RHO, E_SLACKDAMP, E_SLOPE, E_VDT, E_VFRIC, E_WDEPTH,
                       E_WH, P_CDA, P_CDA_AXIAL, P_CLA, P_TX, V_EAD, V_WC)
from ._seabed import penetration, rounded_depth
from ._ties import tie_loads
from ._water import (_drag_tangent, _drag_turn, _dry_fraction, _fluid, _point_drag_split, _surface, _water_local,
                     point_lift)

__all__ = ["loads", "loads_water", "n_water"]


@njit(cache=True)
def loads(X, V, t, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat,
          weight, pmass, padd, pvol, pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco,
          fidx, env, cur_depth, cur_speed, with_waves, sea,
          F, M, tension, band, bw, cm, cc):
    """Forces on the nodes (all but inertia and supports), node masses, and the Newton matrix.

    Fills ``F`` (n, 3) with internal, gravity, hydrodynamic and seabed forces, ``M`` (n, 3, 3) with the
    node mass including added mass, ``tension`` (e,) and, when ``band`` has rows, adds
    ``cm M + cc C + K`` (C = -dF/dv, K = -dF/dx) for the free nodes (``fidx`` >= 0) in band storage.
    ``hinges`` (h, 3) and ``hinge_ei`` (h, H_SIZE) are the bending hinges, inner nodes and held ends of lines with
    bending stiffness (:func:`bending_loads`; none: a truss with pinned ends); ``visco`` (e, V_SIZE) the viscoelastic elements
    (:func:`viscoelastic_tension`, advanced over ``env[E_VDT]``; no rows: none).
    """
    water = np.zeros((n_water(X, env, cur_depth, with_waves, sea), 7))
    loads_water(X, V, t, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda, bedc,
                buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth, cur_speed,
                with_waves, sea, F, M, tension, band, bw, cm, cc, water, np.bool_(True))


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
    compress = env[E_COMPRESS] > 0.0
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
    mats = np.zeros((5, 3, 3))
    eye, blk, hb, baxes, bma = mats[0], mats[1], mats[2], mats[3], mats[4]
    eye[0, 0] = eye[1, 1] = eye[2, 2] = 1.0
    vecs = np.zeros((7, 3))
    uw, aw, ur, vt, nrm, origin, bq = vecs[0], vecs[1], vecs[2], vecs[3], vecs[4], vecs[5], vecs[6]
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
        tab = ts_hi[e] > ts_lo[e]
        # EA eps in compression too (a beam's; not a strain-tension table's element, nor coincident nodes')
        comp = compress and not tab and l > 0.0
        if eps >= sband or comp:
            psi, dpsi, ddpsi = eps, 1.0, 0.0
        elif eps > -sband:
            psi, dpsi, ddpsi = (eps + sband) ** 2 / (4.0 * sband), (eps + sband) / (2.0 * sband), 0.5 / sband
        else:
            psi, dpsi, ddpsi = 0.0, 0.0, 0.0
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
            if not sdamp and not comp:
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
    if pcda.shape[1] > P_TX:  # a node tied to the seabed: tethers and spring clamps
        tie_loads(X, pcda, F, band, bw, fidx)
    # node loads: weight, attachments, seabed, mass-proportional damping
    sl = env[E_SLOPE]
    nrm[0], nrm[1], nrm[2] = -math.sin(sl), 0.0, math.cos(sl)
    depth = env[E_DEPTH]
    kb, cb, mu, vf = env[E_KBOT], env[E_CBOT], env[E_MU], env[E_VFRIC]
    bedfull = env[E_BEDFULL] > 0.0
    alpha = env[E_ALPHA]
    profile = env[E_BEDTAB] != 0.0  # a profile (> 0) or a grid (< 0)
    # a towed body at node 0 with drag or added mass per axis of the body (mooring._body), its axes from the
    # towing cable's direction at it (node 0 to node 1)
    body = env[E_BODY] > 0.0 and n > 1
    bh = 0.0
    if body:
        for k in range(3):
            bq[k] = 0.5 * rho * env[E_BDRAG + k]
        bh = body_axes(X[1, 0] - X[0, 0], X[1, 1] - X[0, 1], baxes)
        body_added_mass(baxes, env[E_BMASS:E_BMASS + 3], bma)
    for i in range(n):
        F[i, 2] -= weight[i]
        qn, qa, ql = 0.5 * rho * pcda[i, P_CDA], 0.5 * rho * pcda[i, P_CDA_AXIAL], 0.5 * rho * pcda[i, P_CLA]
        wet = qn > 0.0 or qa > 0.0 or ql != 0.0 or pvol[i] > 0.0 or padd[i] > 0.0 or (body and i == 0)
        ei = _surface(X[i, 0], X[i, 1], t, env, with_waves, sea) if wavy and (pbuoy[i] != 0.0 or wet) else 0.0
        if pbuoy[i] != 0.0 and X[i, 2] - ei > -0.5 * pdia[i]:
            # an attachment at the surface: its buoyancy scales with the immersed fraction of a body of
            # height pdia (its volume's sphere diameter), linear across the waterline
            F[i, 2] -= pbuoy[i] * min((X[i, 2] - ei) / pdia[i] + 0.5, 1.0) if pdia[i] > 0.0 else pbuoy[i]
        for r in range(3):
            M[i, r, r] += pmass[i] + padd[i]
        if body and i == 0:
            for r in range(3):
                for c in range(3):
                    M[0, r, c] += bma[r, c]
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
            if body and i == 0:
                for r in range(3):
                    for c in range(3):
                        F[0, r] += bma[r, c] * aw[c]
                body_drag(ur, baxes, bq, F[0], hb)
                if jac and fidx[0] >= 0:
                    if cc != 0.0:
                        _add_block(band, bw, fidx[0], fidx[0], cc, hb)
                    # the axes turn with the cable's direction t = X1 - X0: K = -dF/dX, dF0/dX1 = df/dt = -dF0/dX0
                    body_drag_turn(ur, baxes, bq, bh, blk)
                    _add_block(band, bw, fidx[0], fidx[1], -1.0, blk)
                    _add_block(band, bw, fidx[0], fidx[0], 1.0, blk)
        if alpha > 0.0:
            for r in range(3):
                for c in range(3):
                    F[i, r] -= alpha * M[i, r, c] * V[i, c]
            if jac and fidx[i] >= 0:
                _add_block(band, bw, fidx[i], fidx[i], cc * alpha, M[i])
        if kb > 0.0 and bedc[i] > 0.0 and (profile or math.isfinite(depth)):
            pen = penetration(env, X[i, 0], X[i, 1], X[i, 2], profile, depth, nrm)  # the normal too, tabulated
            dl = env[E_BEDRAMP]
            if pen > -dl:
                # penalty spring k q(pen), q rounded quadratically over |pen| < dl (continuous stiffness,
                # so that Newton does not cycle at lift-off); the damper engages as r = q / (q + dl), or with
                # ``bedfull`` (MoorDyn's rule: c_b in full on every penetrating node) as the spring's slope
                # r = dq: c_b in full once pen >= dl, where the spring is k pen, rounded with it below
                q, dq = rounded_depth(pen, dl)
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


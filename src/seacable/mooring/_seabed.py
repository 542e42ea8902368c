"""The seabed under the mooring line: its elevation and slope, a plane or a profile along X (:func:`seabed_at`),
and a node's contact with it, a rounded penalty spring and damper with regularised Coulomb friction, and their
tangent (:func:`seabed_contact`).

Part of :mod:`seacable.mooring.kernel`, which re-exports the public names.
"""

from __future__ import annotations

import math

from numba import njit

from ._band import _add_block
from ._indices import (E_BEDFULL, E_BEDRAMP, E_BEDTAB, E_CBOT, E_DEPTH, E_FRAMEX, E_FRAMEY, E_FRAMEZ, E_KBOT, E_MU,
                       E_SLOPE, E_VFRIC, ENV_SIZE)


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
def seabed_normal(env, nrm):
    """``nrm`` (3,) <- the unit normal, up, of the seabed plane of ``env`` (``E_SLOPE``: rising along X)."""
    sl = env[E_SLOPE]
    nrm[0], nrm[1], nrm[2] = -math.sin(sl), 0.0, math.cos(sl)


@njit(cache=True)
def seabed_contact(i, X, V, env, bedc, F, band, bw, fidx, cc, nrm, vt, blk, eye):
    """The seabed's force on node ``i`` added to ``F``, and when ``band`` has rows its tangent ``K + cc C`` at the
    node's free rows (``fidx``).

    A penalty spring and damper along the seabed's normal, ``k_b d_n q(pen) - c_b d_n r v_n`` (``bedc[i]`` = d_n,
    the sum of ``d L / 2`` of the node's elements; ``E_KBOT``, ``E_CBOT`` in Pa/m, Pa s/m), the penetration
    ``pen`` rounded quadratically over ``|pen| < E_BEDRAMP`` so that the contact stiffness is continuous, the
    damper engaging gradually with it (or with ``E_BEDFULL`` in full beyond the band, MoorDyn's rule), and
    Coulomb friction regularised as ``-mu N v_t / sqrt(|v_t|^2 + v_f^2)`` (``E_MU``, ``E_VFRIC``), with the
    node's velocity taken over the seabed (which moves at ``-E_FRAME*`` in a moving frame). The seabed is the
    plane whose normal :func:`seabed_normal` left in ``nrm``, or the profile of :func:`seabed_at` (``nrm``
    then overwritten with its segment's normal). ``vt`` (3,) and ``blk`` (3, 3) are work arrays, ``eye`` the
    3 x 3 identity. No contact without a stiffness, on a node without ``d_n``, or without a seabed (infinite
    depth).
    """
    kb = env[E_KBOT]
    depth = env[E_DEPTH]
    profile = env[E_BEDTAB] > 0.0
    if not (kb > 0.0 and bedc[i] > 0.0 and (profile or math.isfinite(depth))):
        return
    cb, mu, vf = env[E_CBOT], env[E_MU], env[E_VFRIC]
    bedfull = env[E_BEDFULL] > 0.0
    jac = band.shape[0] > 0
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

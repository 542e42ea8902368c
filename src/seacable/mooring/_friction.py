"""The seabed's Coulomb friction in the statics: a force towards each grounded node's friction target, and its
exact tangent (:func:`friction_loads`).

In the dynamics the seabed's friction acts on the nodes' velocity (:func:`seacable.mooring._loads.loads_water`),
so that a line at rest feels none. The statics use OrcaFlex's model instead (Orcina, *OrcaFlex help: Friction
theory*): each node on the seabed has a friction *target position*, and the friction force acts in the seabed's
plane towards it, elastic up to ``mu N`` and sliding beyond (the target follows the node: :mod:`.friction`). Here
the elastic-sliding law is regularised smoothly::

    d = P (x - x_T),   P = I - n n^T,   s = sqrt(|d|^2 + d_f^2),   f = -mu N d / s

with ``n`` the seabed's normal under the node (the plane's, or the profile's segment's), ``x_T`` the target,
``d_f`` the slip distance (:class:`seacable.mooring.friction.StaticFriction`'s ``friction_distance``: a shear
spring of stiffness ``mu N / d_f`` below it, the force within 0.5 % of ``mu N`` beyond ``10 d_f``), and ``N`` the
penalty contact's normal force at rest, ``k_b d_n q(pen)`` (:func:`seacable.mooring._loads.loads_water`'s, with
its rounding ``q`` over the band ``E_BEDRAMP``). Its tangent ``K = -df/dx`` is exact, the normal force's
dependence on the position included (``dN/dx = -k_b d_n q'(pen) n^T``)::

    K = mu N / s (P - d d^T / s^2) - mu k_b d_n q' d n^T / s

(not symmetric: the friction follows the normal force). Part of :mod:`seacable.mooring.kernel`, which re-exports
the public names.
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import njit
from ._band import _add_block
from ._indices import E_BEDRAMP, E_BEDTAB, E_DEPTH, E_KBOT, E_MU, E_SLOPE
from ._seabed import penetration, rounded_depth

__all__ = ["friction_loads"]


@njit(cache=True)
def friction_loads(X, targets, bedc, env, fidx, F, band, bw, dfric):
    """Add the static seabed friction on the nodes to ``F`` (n, 3) and, when ``band`` has rows, its tangent
    ``K = -dF/dx`` (module docstring).

    ``targets`` (n, 3) holds each node's friction target [m] (a row of NaN: none, no friction: a node that was
    not on the seabed when the targets were set), or has no rows (no static friction: nothing is added);
    ``bedc`` the nodes' contact areas ``d_n`` [m^2]; ``dfric`` the slip distance ``d_f`` [m].
    """
    mu = env[E_MU]
    kb = env[E_KBOT]
    if targets.shape[0] == 0 or mu <= 0.0 or kb <= 0.0:
        return
    profile = env[E_BEDTAB] != 0.0  # a profile (> 0) or a grid (< 0)
    depth = env[E_DEPTH]
    if not profile and not math.isfinite(depth):
        return
    jac = band.shape[0] > 0
    dl = env[E_BEDRAMP]
    nrm = np.zeros(3)
    d = np.zeros(3)
    blk = np.zeros((3, 3))
    sl = env[E_SLOPE]
    nrm[0], nrm[2] = -math.sin(sl), math.cos(sl)
    df2 = dfric * dfric
    for i in range(X.shape[0]):
        if bedc[i] <= 0.0 or math.isnan(targets[i, 0]):
            continue
        pen = penetration(env, X[i, 0], X[i, 1], X[i, 2], profile, depth, nrm)  # the normal too, tabulated
        if pen <= -dl:
            continue  # off the seabed: no normal force, no friction
        q, dq = rounded_depth(pen, dl)
        fn = kb * bedc[i] * q
        # the displacement from the target in the seabed's plane
        r0, r1, r2 = X[i, 0] - targets[i, 0], X[i, 1] - targets[i, 1], X[i, 2] - targets[i, 2]
        rn = nrm[0] * r0 + nrm[1] * r1 + nrm[2] * r2
        d[0], d[1], d[2] = r0 - rn * nrm[0], r1 - rn * nrm[1], r2 - rn * nrm[2]
        s = math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + df2)
        fr = mu * fn / s
        for r in range(3):
            F[i, r] -= fr * d[r]
        if jac and fidx[i] >= 0:
            dn = mu * kb * bedc[i] * dq / s  # d(mu N / s)/d(pen), and pen's gradient is -n
            for r in range(3):
                for c in range(3):
                    p = (1.0 if r == c else 0.0) - nrm[r] * nrm[c]
                    blk[r, c] = fr * (p - d[r] * d[c] / (s * s)) - dn * d[r] * nrm[c]
            _add_block(band, bw, fidx[i], fidx[i], 1.0, blk)

"""The forces of a line's ties to the seabed on its nodes, and their tangents: tethers and spring clamps
(:mod:`seacable.ties`; a rigid clamp is a fixed node and needs nothing here).

Part of :mod:`seacable.mooring.kernel`: the loads pass (:func:`seacable.mooring._loads.loads_water`) calls
:func:`tie_loads` when the attachments' table has the tie columns (:mod:`seacable.mooring._indices`, ``P_TX`` on).
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import njit
from ._band import _add_block
from ._indices import P_CK, P_CX, P_TB, P_TEA, P_TL, P_TX

__all__ = ["tie_loads"]


@njit(cache=True)
def tie_loads(X, pcda, F, band, bw, fidx):
    """Add the ties' forces on the nodes to ``F`` (n, 3) and, when ``band`` has rows, their tangent ``K = -dF/dx``.

    A tether from the anchor ``a`` to node ``i`` (``pcda[i, P_TL]`` > 0), with ``d = x_i - a``, ``l = |d|``,
    ``t = d / l`` and the strain ``eps = l / L0 - 1``, pulls the node towards its anchor with the tension-only
    law of the line's elements::

        T = EA psi(eps),   f_i = -T t,   K = EA psi'(eps) / L0 t t^T + T / l (I - t t^T)

    ``psi = eps`` when taut (``eps >= b``), 0 when slack (``eps <= -b``), rounded between as
    ``(eps + b)^2 / (4 b)`` (C1, so that Newton does not cycle at the switch; ``b = pcda[i, P_TB]``, 0: a sharp
    switch at ``eps = 0``). A spring clamp (``pcda[i, P_CK]`` = k > 0) holding node ``i`` to the point ``p``:
    ``f_i = -k (x_i - p)``, ``K = k I``. The anchor and the clamp's point are fixed: only node ``i``'s block.
    """
    jac = band.shape[0] > 0
    blk = np.zeros((3, 3))
    t = np.zeros(3)
    for i in range(X.shape[0]):
        L = pcda[i, P_TL]
        if L > 0.0:
            l = 0.0
            for r in range(3):
                t[r] = X[i, r] - pcda[i, P_TX + r]
                l += t[r] * t[r]
            l = math.sqrt(l)
            eps = l / L - 1.0
            b = pcda[i, P_TB]
            if eps >= b:
                psi, dpsi = eps, 1.0
            elif eps > -b:
                psi, dpsi = (eps + b) ** 2 / (4.0 * b), (eps + b) / (2.0 * b)
            else:
                psi, dpsi = 0.0, 0.0
            if psi > 0.0:
                ea = pcda[i, P_TEA]
                T = ea * psi
                for r in range(3):
                    t[r] /= l
                    F[i, r] -= T * t[r]
                if jac and fidx[i] >= 0:
                    ka, kg = ea * dpsi / L, T / l
                    for r in range(3):
                        for c in range(3):
                            blk[r, c] = (ka - kg) * t[r] * t[c] + (kg if r == c else 0.0)
                    _add_block(band, bw, fidx[i], fidx[i], 1.0, blk)
        k = pcda[i, P_CK]
        if k > 0.0:
            for r in range(3):
                F[i, r] -= k * (X[i, r] - pcda[i, P_CX + r])
            if jac and fidx[i] >= 0:
                blk[:] = 0.0
                blk[0, 0] = blk[1, 1] = blk[2, 2] = k
                _add_block(band, bw, fidx[i], fidx[i], 1.0, blk)

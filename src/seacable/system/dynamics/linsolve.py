"""Compiled linear solves of the coupled dynamics' Newton step: the band of the line nodes (factor, sweeps,
the unit columns of the tied rows) and the small dense system of the bodies and ties (see :mod:`.kernel`).
"""

from __future__ import annotations

import math

from ..._jit import dense_solve, njit  # noqa: F401  (dense_solve: the bodies' and ties' small system)


@njit(cache=True)
def band_factor(band, bw):
    """LU factor of a banded matrix in place (no pivoting): the multipliers L below the diagonal, U on and
    above. Returns 0 on a zero pivot, 1, or 2 when the matrix is symmetric: then U = D L^T and only the upper
    band is eliminated (the multipliers written from it), half the work of the general case.
    """
    n = band.shape[0]
    sym = True
    for i in range(n):
        for j in range(i + 1, min(n, i + bw + 1)):
            if band[i, bw + j - i] != band[j, bw + i - j]:
                sym = False
                break
        if not sym:
            break
    for k in range(n):
        piv = band[k, bw]
        if piv == 0.0 or not math.isfinite(piv):
            return 0
        top = min(n, k + bw + 1)
        inv = 1.0 / piv
        if sym:
            for i in range(k + 1, top):
                f = band[k, bw + i - k] * inv
                band[i, bw + k - i] = f
                if f != 0.0:
                    for j in range(i, top):
                        band[i, bw + j - i] -= f * band[k, bw + j - k]
        else:
            for i in range(k + 1, top):
                f = band[i, bw + k - i] * inv
                band[i, bw + k - i] = f
                if f != 0.0:
                    for j in range(k + 1, top):
                        band[i, bw + j - i] -= f * band[k, bw + j - k]
    return 2 if sym else 1


@njit(cache=True)
def band_forward(band, bw, x):
    """x <- L^-1 x with the unit lower factor of :func:`band_factor`."""
    n = x.size
    for k in range(n):
        xk = x[k]
        if xk != 0.0:
            for i in range(k + 1, min(n, k + bw + 1)):
                x[i] -= band[i, bw + k - i] * xk


@njit(cache=True)
def band_backward(band, bw, x):
    """x <- U^-1 x with the upper factor of :func:`band_factor`."""
    n = x.size
    for k in range(n - 1, -1, -1):
        s = x[k]
        for j in range(k + 1, min(n, k + bw + 1)):
            s -= band[k, bw + j - k] * x[j]
        x[k] = s / band[k, bw]


@njit(cache=True)
def unit_column(band, bw, x, first, upper):
    """The part of ``L^-1 e_first`` (``upper``: ``U^-T e_first``) that can be nonzero, in ``x[first:last + 1]``;
    returns ``last``. ``x`` need not be zero on entry: the sweep clears the rows it reaches, and stops where the
    fill ends (``bw`` rows without a nonzero), so the column of a node at the end of its line's rows in
    the band costs a few rows, not the line.
    """
    n = x.size
    x[first] = 1.0
    hi = first
    last = first
    k = first
    while k < n and k <= last + bw:
        xk = x[k]
        if upper:
            xk /= band[k, bw]
            x[k] = xk
        if xk != 0.0:
            last = k
            top = min(n - 1, k + bw)
            for i in range(hi + 1, top + 1):
                x[i] = 0.0
            hi = max(hi, top)
            for i in range(k + 1, top + 1):
                x[i] -= (band[k, bw + i - k] if upper else band[i, bw + k - i]) * xk
        k += 1
    return last

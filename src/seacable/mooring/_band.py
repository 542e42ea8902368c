"""The Newton matrix of the mooring kernel in band storage: 3 x 3 blocks added at the free nodes' rows and
columns, and its LU factors without pivoting (:func:`band_factor`, :func:`lu_solve`, :func:`band_solve`).

Free node ``f``'s rows are ``3 f .. 3 f + 2``; the full matrix's column ``c`` of row ``row`` is at
``bw + c - row`` of the band row, ``bw`` the half-bandwidth. Part of :mod:`seacable.mooring.kernel`, which
re-exports the public names.
"""

from __future__ import annotations

import math

from .._jit import njit


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


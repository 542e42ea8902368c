"""Dense and banded LAPACK solves of the block tri-diagonal towed-cable systems, from numba.

The same systems as :mod:`seacable.towed.linalg` (storage, status codes and checks there), solved
as a full matrix by LAPACK ``dgesv`` (the baseline the benchmark compares the block algorithm
against, as paper 000 compared Gauss-Jordan) or in band storage by ``dgbsv``. LAPACK comes from
``scipy.linalg.cython_lapack``, its function pointers registered with LLVM under fixed symbol
names at import, so that the compiled functions can be cached on disk.

References
----------
.. [1] E. Anderson et al., *LAPACK Users' Guide*, 3rd ed., SIAM, 1999 (``dgbsv``, ``dgesv``,
   band storage).
"""

from __future__ import annotations

import math

import numpy as np
from llvmlite import binding as _llvm
from llvmlite import ir as _ir
from numba import types
from numba.core import cgutils
from numba.extending import get_cython_function_address, intrinsic

from .._jit import njit
from .linalg import _EPS, SINGULAR_RTOL, _condition_check, _first_nonfinite_block, _shapes_ok

__all__ = ["solve_dense", "solve_banded", "assemble_dense", "banded_bandwidths"]

# --------------------------------------------------------------------------------------------
# LAPACK through scipy's cython_lapack, as named external symbols (cache-friendly)
# --------------------------------------------------------------------------------------------
_DGBSV_SYMBOL = "seacable_towed_linalg_dgbsv"
_DGESV_SYMBOL = "seacable_towed_linalg_dgesv"
_llvm.add_symbol(_DGBSV_SYMBOL, get_cython_function_address("scipy.linalg.cython_lapack", "dgbsv"))
_llvm.add_symbol(_DGESV_SYMBOL, get_cython_function_address("scipy.linalg.cython_lapack", "dgesv"))

_I32 = _ir.IntType(32)
_I32P = _I32.as_pointer()


def _lapack_codegen(symbol):
    """Code generator calling the Fortran routine ``symbol`` with every argument by reference:
    integers through an int32 stack slot, arrays by their data pointer, then ``info``."""
    def codegen(context, builder, signature, args):
        ptrs = []
        for ty, val in zip(signature.args, args):
            if isinstance(ty, types.Array):
                ptrs.append(context.make_array(ty)(context, builder, val).data)
            else:
                ptrs.append(cgutils.alloca_once_value(builder, builder.trunc(val, _I32)))
        info = cgutils.alloca_once_value(builder, _ir.Constant(_I32, 0))
        fnty = _ir.FunctionType(_ir.VoidType(), [p.type for p in ptrs] + [_I32P])
        builder.call(cgutils.get_or_insert_function(builder.module, fnty, symbol), ptrs + [info])
        return builder.load(info)
    return codegen


@intrinsic
def _dgbsv(typingctx, n, kl, ku, nrhs, ab, ldab, ipiv, b, ldb):
    """LAPACK ``dgbsv``, returns ``info``; ``ab``, ``b`` float64, ``ipiv`` int32 arrays."""
    i64 = types.int64
    return (types.int32(i64, i64, i64, i64, ab, i64, ipiv, b, i64),
            _lapack_codegen(_DGBSV_SYMBOL))


@intrinsic
def _dgesv(typingctx, n, nrhs, a, lda, ipiv, b, ldb):
    """LAPACK ``dgesv`` (``a`` column-major), returns ``info``."""
    i64 = types.int64
    return types.int32(i64, i64, a, i64, ipiv, b, i64), _lapack_codegen(_DGESV_SYMBOL)



# --------------------------------------------------------------------------------------------
# dense and banded solvers (LAPACK)
# --------------------------------------------------------------------------------------------
@njit(cache=True)
def _prepare(lower, diag, upper, rhs, x):
    """Shape check and the rows' scales and power-of-two equilibration factors of both solvers."""
    big_n = rhs.shape[0] * rhs.shape[1]
    scale = np.empty(big_n)
    factor = np.empty(big_n)
    if not _shapes_ok(lower, diag, upper, rhs, x):
        return -1, scale, factor
    return _original_row_scales(lower, diag, upper, scale, factor), scale, factor


@njit(cache=True)
def _original_row_scales(lower, diag, upper, scale, factor):
    """Row equilibration of the assembled matrix; ``k + 1`` of a zero/non-finite row, else 0.

    ``factor[r]`` is the power of two (exact scaling) that brings the largest magnitude of row
    ``r`` into [0.5, 1); ``scale[r]`` is that equilibrated largest magnitude. Equilibrating the
    rows makes LAPACK's partial pivoting choose the pivots that implicit (scaled) pivoting would,
    so rows in different units (newtons, 1/m) are solved as accurately as unscaled ones.
    """
    n, m = diag.shape[0], diag.shape[1]
    for k in range(n):
        for i in range(m):
            s = 0.0
            for j in range(m):
                v = abs(diag[k, i, j])
                if k > 0:
                    v = max(v, abs(lower[k, i, j]))
                if k < n - 1:
                    v = max(v, abs(upper[k, i, j]))
                s = max(s, v)
            if not (0.0 < s <= 1.0e308):  # all-zero row or inf (NaN: caught after the solve)
                return k + 1
            f = math.ldexp(1.0, -math.frexp(s)[1])
            factor[k * m + i] = f
            scale[k * m + i] = s * f
    return 0


@njit(cache=True)
def _finish(info, udiag, ipiv, scale, b, lower, diag, upper, rhs, x, check):
    """Status of a LAPACK solve from ``info``, the diagonal of ``U`` and the 1-based row
    interchanges ``ipiv``; copies the solution ``b`` into ``x``.

    Tracks which original row became row ``j`` of ``U`` and flags ``|u_jj|`` at or below
    ``SINGULAR_RTOL * N * eps`` times that row's (equilibrated) scale.
    """
    n, m = x.shape
    if info != 0:
        return (info - 1) // m + 1 if info > 0 else -1
    big_n = ipiv.shape[0]
    perm = np.arange(big_n)
    tol = SINGULAR_RTOL * big_n * _EPS
    for j in range(big_n):
        p = ipiv[j] - 1
        perm[j], perm[p] = perm[p], perm[j]
        if not (abs(udiag[j]) > tol * scale[perm[j]]):
            return j // m + 1
    for r in range(big_n):
        x[r // m, r % m] = b[r]
    if not check:
        return _first_nonfinite_block(x)
    return _condition_check(lower, diag, upper, rhs, x)


@njit(cache=True)
def assemble_dense(lower, diag, upper):
    """The full ``(n m) x (n m)`` matrix (C-contiguous) of the blocks ``(n, m, m)``. [mixed]"""
    n, m = diag.shape[0], diag.shape[1]
    a = np.zeros((n * m, n * m))
    for k in range(n):
        for i in range(m):
            r = k * m + i
            for j in range(m):
                a[r, k * m + j] = diag[k, i, j]
                if k > 0:
                    a[r, (k - 1) * m + j] = lower[k, i, j]
                if k < n - 1:
                    a[r, (k + 1) * m + j] = upper[k, i, j]
    return a


@njit(cache=True)
def solve_dense(lower, diag, upper, rhs, x, check=True):
    """Solve the block tri-diagonal system as a full matrix (the benchmark baseline).

    Assembles the ``(n m) x (n m)`` matrix and solves it by LU with partial pivoting, LAPACK
    ``dgesv`` -- the routine behind ``np.linalg.solve``, called directly so that a singular
    matrix yields a status instead of an exception. Rows are first equilibrated by powers of two
    (exact), which makes partial pivoting invariant to the units of the rows. Cost
    ``O((n m)^3)`` and ``(n m)^2`` words of memory (3.2 GB at n = 2000, m = 10): for
    comparison only.

    Parameters
    ----------
    lower, diag, upper : ndarray of shape (n, m, m)
        Blocks; ``lower[0]`` and ``upper[n-1]`` are ignored. [mixed]
    rhs : ndarray of shape (n, m)
        Right-hand side. [mixed]
    x : ndarray of shape (n, m)
        Output: the solution, overwritten. [mixed]
    check : bool, optional
        Apply the a-posteriori error estimate (:data:`ERROR_LIMIT`); a Newton iteration, which
        checks its own convergence, passes False. [-]

    Returns
    -------
    status : int
        0 on success; ``k + 1`` if block row ``k`` holds an all-zero or infinite row, or the
        first pivot of ``U`` zero to working precision relative to its original row's scale
        (:data:`SINGULAR_RTOL`; with row interchanges this may lie below the defect), or if the
        solution fails the checks of :func:`solve_block_tridiagonal`; -1 for inconsistent
        shapes. The inputs are not modified.

    References
    ----------
    .. [1] Anderson et al., *LAPACK Users' Guide*, 3rd ed., SIAM, 1999 (``dgesv``).
    """
    st, scale, factor = _prepare(lower, diag, upper, rhs, x)
    if st != 0:
        return st
    n, m = rhs.shape
    big_n = n * m
    # at[c, r] = A[r, c]: a C-ordered array of A^T is A in column-major (Fortran) order
    at = assemble_dense(lower, diag, upper).T.copy()
    b = np.empty(big_n)
    for r in range(big_n):
        b[r] = rhs[r // m, r % m] * factor[r]
    for c in range(big_n):
        for r in range(big_n):
            at[c, r] *= factor[r]
    ipiv = np.empty(big_n, dtype=np.int32)
    info = _dgesv(big_n, 1, at, big_n, ipiv, b, big_n)
    return _finish(info, np.diag(at), ipiv, scale, b, lower, diag, upper, rhs, x, check)


@njit(cache=True)
def banded_bandwidths(lower, diag, upper):
    """Tight lower and upper bandwidths of the assembled block tri-diagonal matrix.

    Parameters
    ----------
    lower, diag, upper : ndarray of shape (n, m, m)
        Blocks; ``lower[0]`` and ``upper[n-1]`` are ignored. [mixed]

    Returns
    -------
    kl : int
        Largest ``row - col`` of a non-zero entry (at most ``2 m - 1``), or 0. [-]
    ku : int
        Largest ``col - row`` of a non-zero entry (at most ``2 m - 1``), or 0. [-]
    """
    n, m = diag.shape[0], diag.shape[1]
    kl = 0
    ku = 0
    for k in range(n):
        for i in range(m):
            for j in range(m):
                if diag[k, i, j] != 0.0:
                    kl = max(kl, i - j)
                    ku = max(ku, j - i)
                if k > 0 and lower[k, i, j] != 0.0:
                    kl = max(kl, m + i - j)
                if k < n - 1 and upper[k, i, j] != 0.0:
                    ku = max(ku, m + j - i)
    return kl, ku


@njit(cache=True)
def solve_banded(lower, diag, upper, rhs, x, check=True):
    """Solve the block tri-diagonal system as a band matrix with LAPACK ``dgbsv``.

    The matrix, rows equilibrated as in :func:`solve_dense`, is stored in LAPACK band form with
    the tight bandwidths of :func:`banded_bandwidths` (at most ``2 m - 1`` each way) and
    factored by band LU with partial pivoting, cost ``O(n m kl (kl + ku))``.

    Parameters
    ----------
    lower, diag, upper, rhs, x, check
        As :func:`solve_dense`.

    Returns
    -------
    status : int
        As :func:`solve_dense`. The inputs are not modified; the band storage
        ``(2 kl + ku + 1) n m`` words is allocated per call.

    References
    ----------
    .. [1] Anderson et al., *LAPACK Users' Guide*, 3rd ed., SIAM, 1999 (``dgbsv``, band
       storage).
    .. [2] Press et al., *Numerical Recipes*, 2nd ed., 1992, section 2.4.
    """
    st, scale, factor = _prepare(lower, diag, upper, rhs, x)
    if st != 0:
        return st
    n, m = rhs.shape
    big_n = n * m
    kl, ku = banded_bandwidths(lower, diag, upper)
    ldab = 2 * kl + ku + 1
    # Fortran AB(kl+ku+1+i-j, j) = A(i, j) (1-based); C-ordered abt[j, kl+ku+i-j] (0-based)
    abt = np.zeros((big_n, ldab))
    b = np.empty(big_n)
    off = kl + ku
    for k in range(n):
        for i in range(m):
            r = k * m + i
            f = factor[r]
            b[r] = rhs[k, i] * f
            for j in range(m):
                c = k * m + j
                if r - c <= kl and c - r <= ku:
                    abt[c, off + r - c] = diag[k, i, j] * f
                if k > 0:
                    c = (k - 1) * m + j
                    if r - c <= kl:
                        abt[c, off + r - c] = lower[k, i, j] * f
                if k < n - 1:
                    c = (k + 1) * m + j
                    if c - r <= ku:
                        abt[c, off + r - c] = upper[k, i, j] * f
    ipiv = np.empty(big_n, dtype=np.int32)
    info = _dgbsv(big_n, kl, ku, 1, abt, ldab, ipiv, b, big_n)
    return _finish(info, abt[:, off], ipiv, scale, b, lower, diag, upper, rhs, x, check)



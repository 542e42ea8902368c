"""Block tri-diagonal, banded and dense linear solvers for the towed-cable Newton systems.

Each Newton iteration of the box scheme of paper 000 solves ``A x = r`` where ``A`` is block
tri-diagonal: ``n`` block rows of ``m x m`` blocks (``m = 10`` unknowns per node). Block row
``k`` reads::

    lower[k] @ x[k-1] + diag[k] @ x[k] + upper[k] @ x[k+1] = rhs[k]

with ``lower[0]`` and ``upper[n-1]`` ignored. Storage is float64, C-contiguous:
``lower, diag, upper`` of shape ``(n, m, m)``, ``rhs`` and ``x`` of shape ``(n, m)``.

Three solvers, all ``numba.njit(cache=True)`` and callable from other njit code:

* :func:`solve_block_tridiagonal` -- block Thomas algorithm, ``O(n m^3)``, the paper's method;
* :func:`seacable.towed.lapack.solve_banded` -- band storage, LAPACK ``dgbsv``;
* :func:`seacable.towed.lapack.solve_dense` -- full matrix, LAPACK ``dgesv``, the benchmark baseline.

Every solver returns an int status instead of raising: ``0`` solved (``x`` finite);
``k + 1`` singular to working precision, non-finite entry or non-finite solution at block row
``k`` (see :data:`SINGULAR_RTOL`, :data:`ERROR_LIMIT`; ``x`` is then undefined); ``-1``
inconsistent shapes. LAPACK comes from ``scipy.linalg.cython_lapack``, its function pointers
registered with LLVM under fixed symbol names at import, so that the compiled functions can
be cached on disk.

References
----------
.. [1] W. H. Press, S. A. Teukolsky, W. T. Vetterling and B. P. Flannery, *Numerical Recipes*,
   2nd ed., Cambridge University Press, 1992, sections 2.3 (LU with implicit pivoting, ``ludcmp``),
   2.4 (band-diagonal systems) and 17.3 (relaxation, block elimination of ``solvde``).
.. [2] G. H. Golub and C. F. Van Loan, *Matrix Computations*, 4th ed., Johns Hopkins
   University Press, 2013, section 4.5.1 (block tri-diagonal LU).
.. [3] E. Anderson et al., *LAPACK Users' Guide*, 3rd ed., SIAM, 1999 (``dgbsv``, ``dgesv``,
   band storage).
.. [4] Paper 000 (towed cable, box scheme, block tri-diagonal solver), /work/shared/seeds/.
"""

from __future__ import annotations

import numpy as np

from .._jit import njit
from ..errors import InputError, NoSolutionError

__all__ = [
    "SINGULAR_RTOL",
    "ERROR_LIMIT",
    "solve_block_tridiagonal",
    "block_thomas",
    "block_thomas_small",
    "solve_block_tridiagonal_work",
    "block_tridiagonal_workspace",
    "check_block_tridiagonal",
    "block_tridiagonal_solve",
]

_EPS = float(np.finfo(np.float64).eps)

#: Pivot threshold: ``u_jj`` is singular when ``|u_jj| <= SINGULAR_RTOL * N * eps * s``, with
#: ``s`` the largest magnitude in the row it came from and ``N`` the order of the factored
#: matrix (``m`` per block, ``n m`` dense/banded). Exactly singular matrices leave pivots of
#: order ``N eps s`` (rounding noise), not exact zeros. Row-relative: rows in different units
#: (newtons, 1/m) do not trigger it.
SINGULAR_RTOL = 4.0

#: Limit on the a-posteriori forward-error estimate ``max(omega, eps) * kappa`` of a solution:
#: ``omega = max_i |r - A x|_i / (|A||x| + |r|)_i`` is its componentwise backward error
#: (Oettli-Prager) and ``kappa = max_i (|A||x|)_i / s_i / max_i (|r_i| / s_i)`` (``s_i`` the
#: largest magnitude in row ``i``) a lower bound of ``|| |A| |A^-1| ||_inf`` of the
#: row-equilibrated matrix; both are invariant to the scaling of rows and unknowns. An
#: estimate at or above 1 % flags a matrix singular to working precision whose zero pivot
#: rounding noise hid (in 720 random numerically singular block systems, n = 7..200,
#: m = 3, 10, the block solver's misses by the pivot test had estimates >= 0.013), or a
#: block elimination made unstable by ill-conditioned intermediate Schur blocks.
ERROR_LIMIT = 0.01


# --------------------------------------------------------------------------------------------
# helpers shared by the solvers
# --------------------------------------------------------------------------------------------
@njit(cache=True)
def _shapes_ok(lower, diag, upper, rhs, x):
    n, m = rhs.shape
    if n < 1 or m < 1:
        return False
    for arr in (lower, diag, upper):
        if arr.shape[0] != n or arr.shape[1] != m or arr.shape[2] != m:
            return False
    return x.shape[0] == n and x.shape[1] == m


@njit(cache=True)
def _first_nonfinite_block(x):
    """``k + 1`` of the first block row of ``x (n, m)`` with a non-finite entry, else 0."""
    n, m = x.shape
    for k in range(n):
        for i in range(m):
            if not np.isfinite(x[k, i]):
                return k + 1
    return 0


@njit(cache=True, inline="always")
def _lu_factor(a, piv, scale, m):
    """In-place LU of the small square ``a (m, m)`` with scaled (implicit) partial pivoting [1]_.

    ``piv[j]`` is the row swapped with row ``j`` at step ``j``. ``scale (3, m)``: on entry
    ``scale[1, i]`` is the magnitude of the terms that formed row ``i`` (its rounding-noise
    scale, at least the row's largest entry); ``scale[0]`` receives the row maxima and
    ``scale[2]`` the reciprocals of U's diagonal (for :func:`_lu_solve` and
    :func:`_lu_solve_columns`). Returns 0, or ``j + 1`` when the pivot of step ``j`` is at most
    ``SINGULAR_RTOL * m * eps`` times the noise scale of its row, or non-finite. Inlined, so that
    a caller passing a constant ``m`` gets the small loops unrolled.
    """
    for i in range(m):
        s = 0.0
        for j in range(m):
            v = abs(a[i, j])
            if not (v <= 1.0e308):  # NaN or inf
                return 1
            s = max(s, v)
        if s == 0.0:
            return 1
        scale[0, i] = s
        scale[1, i] = max(scale[1, i], s)
    tol = SINGULAR_RTOL * m * _EPS
    for j in range(m):
        p = j
        best = -1.0
        for i in range(j, m):
            r = abs(a[i, j]) / scale[0, i]
            if r > best:
                best = r
                p = i
        if not (abs(a[p, j]) > tol * scale[1, p]):  # also catches NaN
            return j + 1
        piv[j] = p
        if p != j:
            for c in range(m):
                a[j, c], a[p, c] = a[p, c], a[j, c]
            for r in range(2):
                scale[r, j], scale[r, p] = scale[r, p], scale[r, j]
        inv = 1.0 / a[j, j]
        scale[2, j] = inv
        for i in range(j + 1, m):
            f = a[i, j] * inv
            a[i, j] = f
            if f != 0.0:
                for c in range(j + 1, m):
                    a[i, c] -= f * a[j, c]
    return 0


@njit(cache=True, inline="always")
def _lu_solve(a, piv, b, m, inv):
    """Overwrite the vector ``b (m,)`` with ``A^-1 b`` from :func:`_lu_factor`'s ``a`` and ``piv``
    (``inv`` the reciprocals of U's diagonal)."""
    for j in range(m):
        p = piv[j]
        if p != j:
            b[j], b[p] = b[p], b[j]
    for i in range(1, m):
        for j in range(i):
            f = a[i, j]
            if f != 0.0:
                b[i] -= f * b[j]
    for i in range(m - 1, -1, -1):
        for j in range(i + 1, m):
            f = a[i, j]
            if f != 0.0:
                b[i] -= f * b[j]
        b[i] *= inv[i]


@njit(cache=True, inline="always")
def _lu_solve_columns(a, piv, b, m, inv):
    """Overwrite the matrix ``b (m, m)`` with ``A^-1 b``, row-oriented (contiguous inner loop);
    :func:`_lu_solve` column by column, operation for operation."""
    for j in range(m):
        p = piv[j]
        if p != j:
            for c in range(m):
                b[j, c], b[p, c] = b[p, c], b[j, c]
    for i in range(1, m):
        for j in range(i):
            f = a[i, j]
            if f != 0.0:
                for c in range(m):
                    b[i, c] -= f * b[j, c]
    for i in range(m - 1, -1, -1):
        for j in range(i + 1, m):
            f = a[i, j]
            if f != 0.0:
                for c in range(m):
                    b[i, c] -= f * b[j, c]
        for c in range(m):
            b[i, c] *= inv[i]


@njit(cache=True)
def _condition_check(lower, diag, upper, rhs, x):
    """Status from non-finite ``x`` or the forward-error estimate of :data:`ERROR_LIMIT`."""
    st = _first_nonfinite_block(x)
    if st != 0:
        return st
    n, m = rhs.shape
    num = 0.0
    den = 0.0
    omega = 0.0
    kmax = 0
    xmax = 0.0
    for k in range(n):
        for i in range(m):
            xmax = max(xmax, abs(x[k, i]))
    for k in range(n):
        for i in range(m):
            s = 0.0
            t = 0.0
            ax = 0.0
            for j in range(m):
                v = diag[k, i, j]
                s = max(s, abs(v))
                t += abs(v * x[k, j])
                ax += v * x[k, j]
                if k > 0:
                    v = lower[k, i, j]
                    s = max(s, abs(v))
                    t += abs(v * x[k - 1, j])
                    ax += v * x[k - 1, j]
                if k < n - 1:
                    v = upper[k, i, j]
                    s = max(s, abs(v))
                    t += abs(v * x[k + 1, j])
                    ax += v * x[k + 1, j]
            if s == 0.0:
                return k + 1
            if t / s > num:
                num = t / s
                kmax = k
            b = abs(rhs[k, i])
            den = max(den, b / s)
            # noise floor eps |A_i| max|x|: a row whose right-hand side is exactly zero carries
            # only rounding in A x, which must not count as a lost digit
            floor = t + b + _EPS * s * xmax
            if floor > 0.0:
                omega = max(omega, abs(rhs[k, i] - ax) / floor)
    if num == 0.0:
        return 0
    if not (max(omega, _EPS) * num < ERROR_LIMIT * den):
        return kmax + 1
    return 0


# --------------------------------------------------------------------------------------------
# block Thomas algorithm
# --------------------------------------------------------------------------------------------
@njit(cache=True)
def block_tridiagonal_workspace(n, m):
    """Work arrays ``(gamma (n, m, m), lu (m, m), piv (m,) int64, scale (3, m))`` for
    :func:`solve_block_tridiagonal_work`, for ``n`` block rows of size ``m``."""
    return (np.empty((n, m, m)), np.empty((m, m)), np.empty(m, dtype=np.int64), np.empty((3, m)))


@njit(cache=True)
def block_thomas(lower, diag, upper, rhs, x, gamma, lu, piv, scale):
    """Block Thomas elimination with the pivot test only (no a-posteriori error estimate).

    The core of :func:`solve_block_tridiagonal_work`; a Newton iteration, which checks its own
    convergence, calls it directly so that an ill-conditioned but regular Jacobian is not refused.

    Block Thomas algorithm with caller-supplied work arrays (no allocation).

    As :func:`solve_block_tridiagonal`, with the work arrays of
    :func:`block_tridiagonal_workspace` (``gamma, lu, piv, scale``, overwritten) allocated once
    by the caller, for use inside Newton and time loops. Returns the same status (-1 also when
    a work array has the wrong shape).
    """
    if not _shapes_ok(lower, diag, upper, rhs, x):
        return -1
    n, m = rhs.shape
    if gamma.shape[0] < n - 1 or gamma.shape[1] != m or gamma.shape[2] != m \
            or lu.shape[0] != m or lu.shape[1] != m or piv.shape[0] != m or scale.shape[1] != m \
            or scale.shape[0] != 3:
        return -1
    return _block_thomas(lower, diag, upper, rhs, x, gamma, lu, piv, scale, m)


@njit(cache=True)
def block_thomas_small(lower, diag, upper, rhs, x, gamma, lu, piv, scale):
    """:func:`block_thomas` without its shape checks, for the blocks of 3 or 4 of the laying step.

    The same arithmetic, operation for operation (the same pivots, the same bits of ``x``, the
    same status), with the block size a constant of the compiled code, which unrolls the small
    loops (about twice as fast). Blocks of other sizes return -1 (use :func:`block_thomas`): a
    general copy here would add a third of this function's compile time for no caller. The caller
    guarantees the shapes of :func:`block_tridiagonal_workspace`.
    """
    m = rhs.shape[1]
    if m == 3:
        return _block_thomas(lower, diag, upper, rhs, x, gamma, lu, piv, scale, 3)
    if m == 4:
        return _block_thomas(lower, diag, upper, rhs, x, gamma, lu, piv, scale, 4)
    return -1


@njit(cache=True, inline="always")
def _block_thomas(lower, diag, upper, rhs, x, gamma, lu, piv, scale, m):
    """The block Thomas elimination of :func:`block_thomas` for blocks of size ``m``."""
    n = rhs.shape[0]
    for k in range(n):
        # Schur complement S_k = diag[k] - lower[k] gamma[k-1] and y_k = rhs[k] - lower[k] y[k-1]; the noise scale
        # of each row of S_k: max|diag[k]| + sum_j |lower[k]_ij| max_c |gamma_jc|
        for i in range(m):
            s = 0.0
            for j in range(m):
                v = diag[k, i, j]
                lu[i, j] = v
                s = max(s, abs(v))
            x[k, i] = rhs[k, i]
            scale[1, i] = s
        if k > 0:
            for j in range(m):
                s = 0.0
                for c in range(m):
                    s = max(s, abs(gamma[k - 1, j, c]))
                scale[2, j] = s
            for i in range(m):
                s = 0.0
                for j in range(m):
                    s += abs(lower[k, i, j]) * scale[2, j]
                scale[1, i] += s
            for i in range(m):
                s = x[k, i]
                for j in range(m):
                    f = lower[k, i, j]
                    if f != 0.0:
                        s -= f * x[k - 1, j]
                        for c in range(m):
                            lu[i, c] -= f * gamma[k - 1, j, c]
                x[k, i] = s
        if _lu_factor(lu, piv, scale, m) != 0:
            return k + 1
        _lu_solve(lu, piv, x[k], m, scale[2])
        if k < n - 1:
            g = gamma[k]
            for i in range(m):
                for j in range(m):
                    g[i, j] = upper[k, i, j]
            _lu_solve_columns(lu, piv, g, m, scale[2])
    # back substitution x_k = y_k - gamma_k x_{k+1}
    for k in range(n - 2, -1, -1):
        for i in range(m):
            s = x[k, i]
            for j in range(m):
                s -= gamma[k, i, j] * x[k + 1, j]
            x[k, i] = s
    return 0


@njit(cache=True)
def solve_block_tridiagonal_work(lower, diag, upper, rhs, x, gamma, lu, piv, scale):
    """:func:`block_thomas` followed by the a-posteriori error estimate (:data:`ERROR_LIMIT`)."""
    status = block_thomas(lower, diag, upper, rhs, x, gamma, lu, piv, scale)
    if status != 0:
        return status
    return _condition_check(lower, diag, upper, rhs, x)


@njit(cache=True)
def solve_block_tridiagonal(lower, diag, upper, rhs, x):
    """Solve a block tri-diagonal system by the block Thomas algorithm.

    Block LU factorisation without pivoting between blocks: forward elimination forms the
    Schur complements ``S_0 = diag[0]``, ``S_k = diag[k] - lower[k] S_{k-1}^-1 upper[k-1]``,
    each factored by LU with scaled partial pivoting (Numerical Recipes' implicit pivoting,
    invariant to the scaling of the rows, which carry different units), then back
    substitution. Cost ``O(n m^3)``, the method of paper 000 (72 times faster than
    Gauss-Jordan on the full matrix there).

    Parameters
    ----------
    lower, diag, upper : ndarray of shape (n, m, m)
        Blocks; ``lower[0]`` and ``upper[n-1]`` are ignored. [mixed]
    rhs : ndarray of shape (n, m)
        Right-hand side. [mixed]
    x : ndarray of shape (n, m)
        Output: the solution, overwritten. [mixed]

    Returns
    -------
    status : int
        0 on success; ``k + 1`` if the Schur-complemented diagonal block of block row ``k`` is
        singular to working precision (:data:`SINGULAR_RTOL`) or non-finite, or if the
        solution is non-finite or has no reliable digits (:data:`ERROR_LIMIT`), ``k`` then
        being the block row of the largest ``|A||x|``; -1 if the shapes are inconsistent. A
        nonsingular matrix whose block elimination meets a singular block (which would need
        pivoting between blocks) also returns ``k + 1``.

    Notes
    -----
    The inputs are not modified. Allocates ``n m^2 + m^2 + 4 m`` words of work space per call;
    in hot loops call :func:`solve_block_tridiagonal_work` instead.

    References
    ----------
    .. [1] Press et al., *Numerical Recipes*, 2nd ed., 1992, sections 2.3 and 17.3.
    .. [2] Golub and Van Loan, *Matrix Computations*, 4th ed., 2013, section 4.5.1.
    """
    n, m = rhs.shape
    gamma, lu, piv, scale = block_tridiagonal_workspace(max(n, 1), max(m, 1))
    return solve_block_tridiagonal_work(lower, diag, upper, rhs, x, gamma, lu, piv, scale)


# --------------------------------------------------------------------------------------------
# Python-level entry points (input checks and errors in the house style)
# --------------------------------------------------------------------------------------------
def check_block_tridiagonal(lower, diag, upper, rhs, x=None):
    """Check the arrays of a block tri-diagonal system (once, outside compiled loops).

    The njit solvers only return status -1 on bad shapes; this names the offending array.

    Parameters
    ----------
    lower, diag, upper : ndarray of shape (n, m, m)
        Blocks. [mixed]
    rhs : ndarray of shape (n, m)
        Right-hand side. [mixed]
    x : ndarray of shape (n, m), optional
        Output array. [mixed]

    Raises
    ------
    InputError
        If an array is not a C-contiguous float64 ndarray or its shape does not match
        ``rhs.shape = (n, m)``.
    """
    arrays = {"lower": lower, "diag": diag, "upper": upper, "rhs": rhs, "x": x}
    for name, arr in arrays.items():
        if arr is None:
            continue
        if not (isinstance(arr, np.ndarray) and arr.dtype == np.float64 and arr.flags.c_contiguous):
            got = (f"{type(arr).__name__} of dtype {getattr(arr, 'dtype', None)}"
                   if getattr(arr, "dtype", None) != np.float64 else "a non-contiguous view")
            raise InputError(f"{name} must be a C-contiguous float64 numpy array, got {got}. "
                             f"Suggested fix: np.ascontiguousarray({name}, dtype=np.float64).")
    if rhs.ndim != 2 or min(rhs.shape) < 1:
        raise InputError(f"rhs must have shape (n, m) with n, m >= 1, got {rhs.shape}. "
                         "Suggested fix: one row of m unknowns per node.")
    n, m = rhs.shape
    for name, shape in (("lower", (n, m, m)), ("diag", (n, m, m)), ("upper", (n, m, m)),
                        ("x", (n, m))):
        if arrays[name] is not None and arrays[name].shape != shape:
            raise InputError(f"{name} must have shape {shape} to match rhs {rhs.shape}, got "
                             f"{arrays[name].shape}. Suggested fix: one m x m block (one "
                             "m-vector for x) per node.")


def block_tridiagonal_solve(lower, diag, upper, rhs):
    """Solve a block tri-diagonal system from Python, raising on failure.

    Converts the inputs to C-contiguous float64, checks them with
    :func:`check_block_tridiagonal` and calls :func:`solve_block_tridiagonal`.

    Parameters
    ----------
    lower, diag, upper : array_like of shape (n, m, m)
        Blocks; ``lower[0]`` and ``upper[n-1]`` are ignored. [mixed]
    rhs : array_like of shape (n, m)
        Right-hand side. [mixed]

    Returns
    -------
    x : ndarray of shape (n, m)
        The solution. [mixed]

    Raises
    ------
    InputError
        Inconsistent shapes.
    NoSolutionError
        The matrix is singular to working precision (or needs pivoting between blocks).

    References
    ----------
    .. [1] Golub and Van Loan, *Matrix Computations*, 4th ed., 2013, section 4.5.1.
    """
    arrs = [np.ascontiguousarray(a, dtype=np.float64) for a in (lower, diag, upper, rhs)]
    check_block_tridiagonal(*arrs)
    x = np.empty_like(arrs[3])
    status = solve_block_tridiagonal(*arrs, x)
    if status != 0:
        raise NoSolutionError(
            f"the block tri-diagonal matrix is singular to working precision at block row "
            f"{status - 1} of {x.shape[0]}. Suggested fix: check the boundary conditions and "
            "that no node has zero tension together with zero bending stiffness.")
    return x

"""numba's ``njit`` for seacable's kernels, with the cache of compiled kernels keyed first.

Every kernel module takes its decorator from here (``from .._jit import njit``), never from
numba itself: importing this module installs :mod:`seacable._numba_cache`'s cache locator
before the module's first ``@njit(cache=True)`` runs, which is when numba picks where a
kernel's machine code is cached. ``import seacable`` alone does not import numba: a kernel
module, and so numba and the locator, is imported when a function that needs it first is.
``tests/unit/test_import.py`` checks that no other module imports ``njit`` from numba.
"""

from __future__ import annotations

import math

from . import _numba_cache  # noqa: F401  isort: skip  (installs the cache locator, before any kernel)
from numba import njit

__all__ = ["copy_1d", "copy_2d", "dense_solve", "njit"]


# A slice assignment from an array (``a[:] = b``) makes numba compile the message of its shape check (str, repr
# and join of the shape tuples) for each kernel and shapes: seconds of compile each, 13.5 CPU-s over the kernel
# families (bench/bench_compile.py). Kernels copy arrays of known equal shapes with these loops instead.
@njit(cache=True)
def copy_1d(dst, src):
    """``dst[:] = src`` for 1-D arrays of the same length, element by element."""
    for i in range(src.shape[0]):
        dst[i] = src[i]


@njit(cache=True)
def copy_2d(dst, src):
    """``dst[:, :] = src`` for 2-D arrays of the same shape, element by element."""
    for i in range(src.shape[0]):
        for j in range(src.shape[1]):
            dst[i, j] = src[i, j]


@njit(cache=True)
def dense_solve(A, b):
    """Solve the small dense system ``A x = b`` in place (Gaussian elimination, partial pivoting); x in b.
    False when singular."""
    m = b.size
    for k in range(m):
        p = k
        big = abs(A[k, k])
        for i in range(k + 1, m):
            if abs(A[i, k]) > big:
                big = abs(A[i, k])
                p = i
        if big == 0.0 or not math.isfinite(big):
            return False
        if p != k:
            for c in range(m):
                A[k, c], A[p, c] = A[p, c], A[k, c]
            b[k], b[p] = b[p], b[k]
        for i in range(k + 1, m):
            f = A[i, k] / A[k, k]
            if f != 0.0:
                for c in range(k + 1, m):
                    A[i, c] -= f * A[k, c]
                b[i] -= f * b[k]
    for k in range(m - 1, -1, -1):
        s = b[k]
        for c in range(k + 1, m):
            s -= A[k, c] * b[c]
        b[k] = s / A[k, k]
    return True

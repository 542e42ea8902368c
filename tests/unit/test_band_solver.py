"""The banded LU of the mooring kernel's Newton matrix: :func:`band_factor`, :func:`lu_solve`, :func:`band_solve`.

The reference is a dense solve (numpy's LAPACK, partial pivoting) of the same matrix. The matrices are
diagonally dominant, as the Newton matrix is (its mass term), so that LU without pivoting is stable and the
two agree to round-off: 1e-13 relative, a few hundred ulps for systems of a few hundred unknowns.
"""

from __future__ import annotations

import numpy as np
import pytest

from seacable.mooring import kernel as K


def _banded(n, bw, seed):
    """A random diagonally dominant matrix of half-bandwidth ``bw``, dense and in the kernel's band storage
    (``band[i, bw + j - i] = A[i, j]``)."""
    rng = np.random.default_rng(seed)
    A = np.zeros((n, n))
    band = np.zeros((n, 2 * bw + 1))
    for i in range(n):
        for j in range(max(0, i - bw), min(n, i + bw + 1)):
            A[i, j] = rng.normal() + (4.0 * bw if i == j else 0.0)
            band[i, bw + j - i] = A[i, j]
    return A, band


# bandwidth 5 (one line: its own code, unrolled away from the last rows) at sizes around its switch to the
# general loops, and other bandwidths (lines with bending, networks)
@pytest.mark.parametrize(("n", "bw"), [(351, 5), (11, 5), (12, 5), (13, 5), (6, 5), (30, 8), (3, 2), (100, 11)])
def test_band_solve_and_the_reused_factors_match_a_dense_solve(n, bw):
    A, band = _banded(n, bw, seed=n + bw)
    b = np.random.default_rng(1).normal(size=(2, n))
    x = b[0].copy()
    assert K.band_solve(band, bw, x)
    ref = np.linalg.solve(A, b.T).T
    assert np.max(np.abs(x - ref[0])) < 1e-13 * np.max(np.abs(ref[0]))
    # the factors left in the band solve another right-hand side (the modified Newton iterations)
    y = b[1].copy()
    K.lu_solve(band, bw, y)
    assert np.max(np.abs(y - ref[1])) < 1e-13 * np.max(np.abs(ref[1]))


@pytest.mark.parametrize("bad", [0.0, np.nan, np.inf])
@pytest.mark.parametrize(("n", "bw"), [(60, 5), (60, 8)])
def test_a_zero_or_non_finite_pivot_is_reported_not_divided_by(n, bw, bad):
    _, band = _banded(n, bw, seed=3)
    band[n // 2, :] = 0.0
    band[n // 2, bw] = bad
    x = np.ones(n)
    assert not K.band_solve(band, bw, x)

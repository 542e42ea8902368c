"""Unit tests of seacable.towed.linalg: block tri-diagonal, banded and dense solvers.

Reference solutions come from ``scipy.linalg.solve`` (LAPACK ``gesv``) on the assembled dense
matrix. Tolerances follow the standard forward-error bound of a backward-stable solver,
``||x - x_ref|| / ||x_ref|| <~ c N eps cond(A)``; the reference itself carries an error of the
same order, so ``100 eps cond_inf(A)`` (with N <= 500 unknowns and growth factors O(1) on these
random matrices) bounds the difference of two such solutions with margin.
"""

import numpy as np
import pytest
import scipy.linalg
from numba import njit

from seacable.errors import InputError, NoSolutionError
from seacable.towed.lapack import assemble_dense, banded_bandwidths, solve_banded, solve_dense
from seacable.towed.linalg import (
    block_tridiagonal_solve,
    block_tridiagonal_workspace,
    check_block_tridiagonal,
    solve_block_tridiagonal,
    solve_block_tridiagonal_work,
)

EPS = np.finfo(np.float64).eps
SOLVERS = [solve_block_tridiagonal, solve_dense, solve_banded]
IDS = ["block", "dense", "banded"]


def random_system(n, m, seed, dominance=1.0):
    """Random blocks; ``dominance * sqrt(m)`` on the diagonal keeps cond(A) ~ 10..1e3."""
    rng = np.random.default_rng(seed)
    lower = rng.standard_normal((n, m, m))
    upper = rng.standard_normal((n, m, m))
    diag = rng.standard_normal((n, m, m)) + dominance * np.sqrt(m) * np.eye(m)
    rhs = rng.standard_normal((n, m))
    return lower, diag, upper, rhs


def reference(lower, diag, upper, rhs):
    a = assemble_dense(lower, diag, upper)
    x = scipy.linalg.solve(a, rhs.ravel()).reshape(rhs.shape)
    return x, np.linalg.cond(a, np.inf)


def rel_err(x, ref):
    return np.abs(x - ref).max() / np.abs(ref).max()


@pytest.mark.parametrize("solver", SOLVERS, ids=IDS)
@pytest.mark.parametrize("m", [10, 3])
@pytest.mark.parametrize("n", [1, 2, 7, 50])
def test_matches_scipy_dense_solve(solver, n, m):
    lower, diag, upper, rhs = random_system(n, m, seed=100 * n + m)
    ref, cond = reference(lower, diag, upper, rhs)
    assert cond < 1e5  # the premise "well-conditioned": otherwise the tolerance is vacuous
    x = np.full((n, m), np.nan)
    assert solver(lower, diag, upper, rhs, x) == 0
    # forward-error bound of two backward-stable solves, see module docstring
    assert rel_err(x, ref) <= 100 * EPS * cond


@pytest.mark.parametrize("solver", SOLVERS, ids=IDS)
def test_residual_is_backward_stable(solver):
    # Normwise backward error ||r - A x|| / (||A|| ||x|| + ||r||) of LU with pivoting is
    # bounded by ~ N eps times the growth factor (Wilkinson); 10 N eps allows growth up to 10.
    n, m = 50, 10
    lower, diag, upper, rhs = random_system(n, m, seed=7, dominance=0.5)
    a = assemble_dense(lower, diag, upper)
    x = np.empty((n, m))
    assert solver(lower, diag, upper, rhs, x) == 0
    res = np.abs(rhs.ravel() - a @ x.ravel()).max()
    scale = np.abs(a).sum(1).max() * np.abs(x).max() + np.abs(rhs).max()
    assert res / scale <= 10 * n * m * EPS


@pytest.mark.parametrize("solver", SOLVERS, ids=IDS)
@pytest.mark.parametrize("m", [10, 3])
def test_rows_of_very_different_scales(solver, m):
    # Rows in newtons next to rows in 1/m: multiply rows alternately by 1e6 and 1e-6 (cond of
    # the scaled matrix ~1e12 cond(A)). Scaled (implicit) pivoting and the power-of-two row
    # equilibration before LAPACK make the solvers invariant to row scaling, so the solution
    # must keep the accuracy of the unscaled system: 100 eps cond(unscaled A) as above.
    n = 50
    lower, diag, upper, rhs = random_system(n, m, seed=3)
    ref, cond = reference(lower, diag, upper, rhs)
    f = np.where(np.arange(n * m) % 2 == 0, 1e6, 1e-6).reshape(n, m)
    ls, ds, us, rs = (lower * f[:, :, None], diag * f[:, :, None], upper * f[:, :, None],
                      rhs * f)
    assert np.linalg.cond(assemble_dense(ls, ds, us), np.inf) > 1e6 * cond  # premise
    x = np.empty((n, m))
    assert solver(ls, ds, us, rs, x) == 0
    assert rel_err(x, ref) <= 100 * EPS * cond


@pytest.mark.parametrize("solver", SOLVERS, ids=IDS)
def test_inputs_not_modified(solver):
    arrays = random_system(7, 10, seed=11)
    copies = [a.copy() for a in arrays]
    solver(*arrays, np.empty((7, 10)))
    for a, c in zip(arrays, copies):
        np.testing.assert_array_equal(a, c)


def test_all_three_solvers_agree():
    # Two backward-stable solves differ by at most ~2 eps cond each: 100 eps cond as above.
    lower, diag, upper, rhs = random_system(100, 10, seed=5)
    _, cond = reference(lower, diag, upper, rhs)
    xs = []
    for solver in SOLVERS:
        x = np.empty((100, 10))
        assert solver(lower, diag, upper, rhs, x) == 0
        xs.append(x)
    assert rel_err(xs[1], xs[0]) <= 100 * EPS * cond
    assert rel_err(xs[2], xs[0]) <= 100 * EPS * cond


def test_work_variant_is_the_same_computation():
    # Same arithmetic in the same order: bit-for-bit equal, also when the workspace is reused.
    lower, diag, upper, rhs = random_system(20, 10, seed=9)
    x1 = np.empty((20, 10))
    assert solve_block_tridiagonal(lower, diag, upper, rhs, x1) == 0
    work = block_tridiagonal_workspace(20, 10)
    x2 = np.empty((20, 10))
    for _ in range(2):
        assert solve_block_tridiagonal_work(lower, diag, upper, rhs, x2, *work) == 0
        np.testing.assert_array_equal(x1, x2)


# ---------------------------------------------------------------------------- singular cases
@pytest.mark.parametrize("solver", SOLVERS, ids=IDS)
def test_zero_block_row_reports_its_index(solver):
    lower, diag, upper, rhs = random_system(7, 10, seed=1)
    lower[3] = diag[3] = upper[3] = 0.0  # block row 3 all zero: A singular
    x = np.empty((7, 10))
    assert solver(lower, diag, upper, rhs, x) == 4


@pytest.mark.parametrize("solver", SOLVERS, ids=IDS)
def test_duplicated_row_is_singular(solver):
    lower, diag, upper, rhs = random_system(7, 10, seed=2)
    for blocks in (lower, diag, upper):
        blocks[3, 6] = blocks[3, 1]  # two equal rows: rank deficient
    x = np.empty((7, 10))
    status = solver(lower, diag, upper, rhs, x)
    # The block solver meets the defect in block row 3 (its own Schur block has two equal
    # rows); LAPACK's row interchanges may carry the zero pivot to a later block row.
    assert status == 4 if solver is solve_block_tridiagonal else status >= 4


@pytest.mark.parametrize("solver", SOLVERS, ids=IDS)
@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("n,m", [(7, 10), (50, 10), (50, 3)])
def test_numerically_singular_matrix_gives_status_not_garbage(solver, n, m, seed):
    # Make A z = 0 for a random z by a rank-one change of every diagonal block: in floating
    # point cond(A) ~ 1e16..1e17, no pivot is exactly zero, and a plain solve returns finite
    # numbers of size 1e15. The solvers must report it instead (pivot threshold or the
    # a-posteriori estimate COND_LIMIT).
    lower, diag, upper, rhs = random_system(n, m, seed=seed)
    rng = np.random.default_rng(seed + 1000)
    z = rng.standard_normal((n, m))
    w = (assemble_dense(lower, diag, upper) @ z.ravel()).reshape(n, m)
    diag = diag - np.einsum("ki,kj->kij", w, z) / np.sum(z * z, axis=1)[:, None, None]
    a = assemble_dense(lower, diag, upper)
    assert np.abs(a @ z.ravel()).max() < 1e-12 * np.abs(a).max()  # premise: z is a null vector
    assert solver(lower, diag, upper, rhs, np.empty((n, m))) > 0


@pytest.mark.parametrize("solver", SOLVERS, ids=IDS)
@pytest.mark.parametrize("where", ["diag", "lower", "upper", "rhs"])
@pytest.mark.parametrize("bad", [np.nan, np.inf])
def test_non_finite_input_gives_status(solver, where, bad):
    arrays = dict(zip(("lower", "diag", "upper", "rhs"), random_system(7, 10, seed=4)))
    arrays[where][2, 0] = bad
    x = np.empty((7, 10))
    status = solver(arrays["lower"], arrays["diag"], arrays["upper"], arrays["rhs"], x)
    assert status > 0


def test_zero_first_block_needs_block_pivoting():
    # Documented limitation: diag[0] = 0 with the matrix nonsingular (coupling through
    # upper[0], lower[1]) needs pivoting between blocks. The block solver says so with status 1;
    # the dense and banded LAPACK solvers pivot across blocks and solve it.
    lower, diag, upper, rhs = random_system(7, 10, seed=8)
    diag[0] = 0.0
    ref, cond = reference(lower, diag, upper, rhs)
    assert cond < 1e5  # premise: nonsingular and well-conditioned
    assert solve_block_tridiagonal(lower, diag, upper, rhs, np.empty((7, 10))) == 1
    for solver in (solve_dense, solve_banded):
        x = np.empty((7, 10))
        assert solver(lower, diag, upper, rhs, x) == 0
        assert rel_err(x, ref) <= 100 * EPS * cond


@pytest.mark.parametrize("solver", SOLVERS, ids=IDS)
def test_zero_rhs_gives_zero_solution(solver):
    lower, diag, upper, _ = random_system(7, 10, seed=6)
    x = np.full((7, 10), np.nan)
    assert solver(lower, diag, upper, np.zeros((7, 10)), x) == 0
    np.testing.assert_array_equal(x, 0.0)


# ---------------------------------------------------------------------------- band structure
def brute_force_bandwidths(a):
    rows, cols = np.nonzero(a)
    return max(0, int((rows - cols).max())), max(0, int((cols - rows).max()))


@pytest.mark.parametrize("pattern", ["full", "no_lower", "triangular_diag", "corner_coupling"])
def test_banded_bandwidths_are_tight(pattern):
    n, m = 6, 4
    lower, diag, upper, rhs = random_system(n, m, seed=12, dominance=3.0)
    if pattern == "no_lower":
        lower[:] = 0.0
    elif pattern == "triangular_diag":
        lower[:] = 0.0
        diag[:] = np.triu(diag)
        upper[:] = np.triu(upper)
    elif pattern == "corner_coupling":  # only the nearest unknowns of neighbour nodes coupled
        mask = np.zeros((m, m))
        mask[0, m - 1] = 1.0
        lower *= mask
        upper *= mask.T
    a = assemble_dense(lower, diag, upper)
    kl, ku = banded_bandwidths(lower, diag, upper)
    assert (kl, ku) == brute_force_bandwidths(a)
    if pattern == "full":
        assert (kl, ku) == (2 * m - 1, 2 * m - 1)
    ref, cond = reference(lower, diag, upper, rhs)
    x = np.empty((n, m))
    assert solve_banded(lower, diag, upper, rhs, x) == 0
    assert rel_err(x, ref) <= 100 * EPS * cond


# ---------------------------------------------------------------------------- interfaces
@pytest.mark.parametrize("solver", SOLVERS, ids=IDS)
def test_callable_from_njit_code(solver):
    @njit
    def newton_like(lower, diag, upper, rhs):
        x = np.empty_like(rhs)
        total = 0
        for _ in range(3):
            total += solver(lower, diag, upper, rhs, x)
        return total, x

    lower, diag, upper, rhs = random_system(7, 10, seed=13)
    ref, cond = reference(lower, diag, upper, rhs)
    status, x = newton_like(lower, diag, upper, rhs)
    assert status == 0
    assert rel_err(x, ref) <= 100 * EPS * cond


@pytest.mark.parametrize("solver", SOLVERS, ids=IDS)
def test_inconsistent_shapes_give_minus_one(solver):
    lower, diag, upper, rhs = random_system(7, 10, seed=14)
    assert solver(lower, diag, upper, rhs, np.empty((7, 9))) == -1
    assert solver(lower[:6], diag, upper, rhs, np.empty((7, 10))) == -1


def test_wrong_workspace_gives_minus_one():
    lower, diag, upper, rhs = random_system(7, 10, seed=15)
    gamma, lu, piv, scale = block_tridiagonal_workspace(7, 9)
    assert solve_block_tridiagonal_work(lower, diag, upper, rhs, np.empty((7, 10)),
                                        gamma, lu, piv, scale) == -1


def test_check_block_tridiagonal_errors():
    lower, diag, upper, rhs = random_system(7, 10, seed=16)
    check_block_tridiagonal(lower, diag, upper, rhs, np.empty((7, 10)))  # valid: no error
    with pytest.raises(InputError, match=r"upper must have shape \(7, 10, 10\).*Suggested fix"):
        check_block_tridiagonal(lower, diag, np.ascontiguousarray(upper[:, :9]), rhs)
    with pytest.raises(InputError, match=r"x must have shape \(7, 10\).*Suggested fix"):
        check_block_tridiagonal(lower, diag, upper, rhs, np.empty((7, 11)))
    with pytest.raises(InputError, match="diag must be a C-contiguous float64.*Suggested fix"):
        check_block_tridiagonal(lower, diag.astype(np.float32), upper, rhs)
    with pytest.raises(InputError, match="lower must be a C-contiguous .* got a non-contiguous"):
        check_block_tridiagonal(np.asfortranarray(lower), diag, upper, rhs)
    with pytest.raises(InputError, match=r"rhs must have shape \(n, m\)"):
        check_block_tridiagonal(lower, diag, upper, rhs.ravel())


def test_block_tridiagonal_solve_wrapper():
    lower, diag, upper, rhs = random_system(7, 10, seed=17)
    ref, cond = reference(lower, diag, upper, rhs)
    x = block_tridiagonal_solve(lower.tolist(), diag, upper, rhs)  # array_like accepted
    assert rel_err(x, ref) <= 100 * EPS * cond
    diag[2] = lower[2] = upper[2] = 0.0
    with pytest.raises(NoSolutionError, match="singular to working precision at block row 2"):
        block_tridiagonal_solve(lower, diag, upper, rhs)
    with pytest.raises(InputError, match="must have shape"):
        block_tridiagonal_solve(lower[:, :, :9], diag, upper, rhs)


@pytest.mark.parametrize("solver", SOLVERS, ids=IDS)
def test_ill_conditioned_but_regular_system_is_not_flagged(solver):
    # Same rank-one construction as the singular test, stopped short: sigma_min shrunk by
    # ~1e-8, cond(A) ~ 3e10, still far inside working precision. The singularity checks must
    # not fire, and the forward-error bound 100 eps cond(A) of the well-conditioned tests still
    # holds (measured: <= 0.1 eps cond for the three solvers).
    n, m = 50, 10
    lower, diag, upper, rhs = random_system(n, m, seed=21)
    rng = np.random.default_rng(21)
    z = rng.standard_normal((n, m))
    w = (assemble_dense(lower, diag, upper) @ z.ravel()).reshape(n, m)
    diag = diag - (1 - 1e-8) * np.einsum("ki,kj->kij", w, z) / np.sum(z * z, 1)[:, None, None]
    ref, cond = reference(lower, diag, upper, rhs)
    assert 1e7 < cond < 1e11  # premise
    x = np.empty((n, m))
    assert solver(lower, diag, upper, rhs, x) == 0
    assert rel_err(x, ref) <= 100 * EPS * cond

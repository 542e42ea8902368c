"""The compiled laying step: its Newton Jacobian against finite differences, and a closed form.

Assembled blocks of the 3x3 block tri-diagonal Newton system (seacable.laying.kernel._assemble)
against central differences of the residual; and a free fall with drag-free, weight-only node
against the backward-Euler closed form.
"""

import math

import numpy as np

from seacable.laying import kernel as K
from seacable.laying.solver import props_row


def _residual_and_blocks(r, T, b, G, act, L, comp):
    nseg = L.size
    c, ell = np.zeros((nseg, 2)), np.zeros(nseg)
    K._chords(r, c, ell)
    lo, di, up = np.zeros((nseg, 3, 3)), np.zeros((nseg, 3, 3)), np.zeros((nseg, 3, 3))
    rhs = np.zeros((nseg, 3))
    K._assemble(r, b, G, T, act, c, ell, L, comp, lo, di, up, rhs, K.no_contact(r.shape[0], 2))
    return -rhs, lo, di, up


def test_jacobian_matches_finite_differences():
    rng = np.random.default_rng(1)
    n = 6
    r = np.array([[k * 0.9, k * 0.5 + 0.1 * rng.standard_normal()] for k in range(n + 1)])
    b = r + 0.01 * rng.standard_normal(r.shape)
    G = np.zeros((n + 1, 2, 2))
    for i in range(n + 1):
        a = rng.standard_normal((2, 2))
        G[i] = 0.01 * (a @ a.T + np.eye(2))
    T = rng.uniform(1.0, 5.0, n)
    act = np.ones(n, dtype=np.int64)
    act[2] = 0                                   # one slack segment
    L, comp = np.ones(n), np.full(n, 1e-3)
    res, lo, di, up = _residual_and_blocks(r, T, b, G, act, L, comp)
    m = 3 * n
    J = np.zeros((m, m))
    for k in range(n):
        J[3 * k:3 * k + 3, 3 * k:3 * k + 3] = di[k]
        if k > 0:
            J[3 * k:3 * k + 3, 3 * k - 3:3 * k] = lo[k]
        if k < n - 1:
            J[3 * k:3 * k + 3, 3 * k + 3:3 * k + 6] = up[k]

    def shifted(u):
        r2, T2 = r.copy(), T.copy()
        for k in range(n):
            T2[k] += u[3 * k]
            if k + 1 < n:
                r2[k + 1] += u[3 * k + 1:3 * k + 3]
        return _residual_and_blocks(r2, T2, b, G, act, L, comp)[0].ravel()

    h = 1e-6
    Jfd = np.column_stack([(shifted(h * e) - shifted(-h * e)) / (2 * h) for e in np.eye(m)])
    keep = np.ones(m, bool)
    keep[-2:] = False                            # the last block's padding rows/columns
    # central differences with h = 1e-6 on O(1) entries: truncation ~h^2, round-off ~1e-16/h = 1e-10
    np.testing.assert_allclose(J[np.ix_(keep, keep)], Jfd[np.ix_(keep, keep)], atol=1e-8)


def test_single_node_sinks_at_the_backward_euler_rate():
    """One node between two slack segments, no drag, no added mass: v' = v - g_eff dt exactly."""
    mass, weight = 2.0, 10.0                      # per unit length: 2 kg/m, 10 N/m; node carries 1 m
    props = np.array([props_row(mass, weight, 0.02, 0.0, 0.0, 0.0, 0.0, 0.0)])
    pos = np.array([[0.0, -10.0], [0.5, -5.0], [1.0, 0.0]])      # chords of 5.02 m ...
    L = np.array([6.0, 6.0])                                    # ... in 6 m segments: both slack
    vel = np.zeros((3, 2))
    T, act = np.zeros(2), np.zeros(2, dtype=np.int64)
    new_pos, new_vel = np.zeros_like(pos), np.zeros_like(vel)
    dt = 0.1
    status, _, _ = K.implicit_step(pos, vel, pos[-1].copy(), L, np.zeros(2, dtype=np.int64), props,
                               np.zeros((3, 4)), np.zeros(1), np.zeros((1, 2)), 1025.0, dt, T, act, 0.0,
                               K.no_contact(3, 2), 1e-12, 20, 5, new_pos, new_vel)
    assert status == K.STEP_OK
    accel = weight / mass                          # net weight over mass, per unit length
    # the free node's backward-Euler step, to round-off
    assert math.isclose(new_vel[1, 1], -accel * dt, rel_tol=1e-13)
    assert math.isclose(new_pos[1, 1], -5.0 - accel * dt * dt, rel_tol=1e-13)
    assert new_vel[1, 0] == 0.0
    assert np.all(T == 0.0)


def test_jacobian_with_nodes_sliding_on_the_seabed_matches_finite_differences():
    """3-D, three nodes on the seabed (each in its tangent plane, ``_on_plane``): two sliding (farther from their
    anchors than the friction's slip distance, Coulomb's branch) and one holding (the spring's branch); the
    friction's derivative in the diagonal blocks against central differences (h = 1e-6 m against a kink 2e-3 m
    away)."""
    rng = np.random.default_rng(2)
    n, dim = 6, 3
    r = np.array([[k * 0.9, 0.3 * k, k * 0.5 + 0.1 * rng.standard_normal()] for k in range(n + 1)])
    old = r + 0.01 * rng.standard_normal(r.shape)
    anchor = r + 0.02 * rng.standard_normal(r.shape)
    anchor[4] = r[4] + 1e-3                     # 1.7e-3 m from it, within the 5e-3 m slip distance
    b = r + 0.01 * rng.standard_normal(r.shape)
    G = np.zeros((n + 1, dim, dim))
    normal = rng.standard_normal((n + 1, dim))
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    contact = np.array([0, 1, 1, 0, 1, 0, 0])
    for i in range(n + 1):
        a = rng.standard_normal((dim, dim))
        G[i] = 0.01 * (a @ a.T + np.eye(dim))
        if contact[i]:
            K._on_plane(G[i], b[i], old[i], normal[i], dim)
    seabed = (contact, normal, rng.uniform(1.0, 3.0, n + 1), anchor, 5e-3)
    T = rng.uniform(1.0, 5.0, n)
    act = np.ones(n, dtype=np.int64)
    L, comp = np.ones(n), np.full(n, 1e-3)
    m = dim + 1

    def residual_and_blocks(r2, T2):
        c, ell = np.zeros((n, dim)), np.zeros(n)
        K._chords(r2, c, ell)
        lo, di, up, rhs = np.zeros((n, m, m)), np.zeros((n, m, m)), np.zeros((n, m, m)), np.zeros((n, m))
        K._assemble(r2, b, G, T2, act, c, ell, L, comp, lo, di, up, rhs, seabed)
        return -rhs, lo, di, up

    _, lo, di, up = residual_and_blocks(r, T)
    J = np.zeros((m * n, m * n))
    for k in range(n):
        J[m * k:m * k + m, m * k:m * k + m] = di[k]
        if k > 0:
            J[m * k:m * k + m, m * k - m:m * k] = lo[k]
        if k < n - 1:
            J[m * k:m * k + m, m * k + m:m * k + 2 * m] = up[k]

    def shifted(u):
        r2, T2 = r.copy(), T.copy()
        for k in range(n):
            T2[k] += u[m * k]
            if k + 1 < n:
                r2[k + 1] += u[m * k + 1:m * k + m]
        return residual_and_blocks(r2, T2)[0].ravel()

    h = 1e-6
    Jfd = np.column_stack([(shifted(h * e) - shifted(-h * e)) / (2 * h) for e in np.eye(m * n)])
    keep = np.ones(m * n, bool)
    keep[-dim:] = False                          # the last block's padding rows/columns
    # the friction's second derivative ~ grip / slip^2 = 1e5 makes the h^2 truncation ~1e-7
    np.testing.assert_allclose(J[np.ix_(keep, keep)], Jfd[np.ix_(keep, keep)], atol=1e-6)


def test_block_thomas_small_gives_the_bits_of_block_thomas():
    """The step's block solver (block size 3 or 4 a compile-time constant, unrolled) is block_thomas operation for operation:
    the same solution to the last bit, pivot swaps and zero blocks included, and the same status of a singular
    system."""
    from seacable.towed.linalg import block_thomas, block_thomas_small

    rng = np.random.default_rng(7)
    for m in (3, 4):
        for n in (1, 2, 9, 40):
            lower, diag, upper = (rng.standard_normal((n, m, m)) for _ in range(3))
            lower[::3] = 0.0                             # zero blocks and entries, as the step's matrix has
            upper[:, :, 0] = 0.0
            diag[:, 0, 0] = 1e-3 * rng.standard_normal(n)    # small leading entries: rows swapped
            rhs = rng.standard_normal((n, m))
            out = []
            for solve in (block_thomas, block_thomas_small):
                x = np.zeros((n, m))
                work = (np.empty((n, m, m)), np.empty((m, m)), np.empty(m, dtype=np.int64), np.empty((3, m)))
                out.append((solve(lower, diag, upper, rhs, x, *work), x.tobytes()))
            assert out[0][0] == 0
            assert out[1] == out[0]
        diag[n // 2] = 0.0                               # singular at that block row
        lower[n // 2] = 0.0
        status = [solve(lower, diag, upper, rhs, np.zeros((n, m)), np.empty((n, m, m)), np.empty((m, m)),
                        np.empty(m, dtype=np.int64), np.empty((3, m))) for solve in (block_thomas, block_thomas_small)]
        assert status[0] == status[1] == n // 2 + 1
    # blocks of another size are not its job: refused with block_thomas's shape status, not solved wrongly
    lower, diag, upper = (rng.standard_normal((4, 5, 5)) for _ in range(3))
    assert block_thomas_small(lower, diag, upper, rng.standard_normal((4, 5)), np.zeros((4, 5)),
                              np.empty((4, 5, 5)), np.empty((5, 5)), np.empty(5, dtype=np.int64),
                              np.empty((3, 5))) == -1

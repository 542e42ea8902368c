"""The towline's implicit dampers solve the whole line's block tri-diagonal system exactly.

Each step takes the joint dampers and the bending dampers by backward Euler along the whole line: the new
velocities of all elements solve ``(M + dt D) dx = dt f`` (``seacable.towline.kernel``). The kernel assembles
and eliminates it element by element, unrolled into scalars (:func:`_eliminate`, :func:`_back_substitute`). Here
the same system is assembled densely from its definition, each joint's damper ``C = c_t I + (c_x - c_t) a a^T``
on the relative velocity of the two points it joins and each bending damper ``c_m`` on the relative angular
velocity of its two elements, and solved with numpy: the kernel's increments must equal it to round-off.
"""

from __future__ import annotations

import numpy as np
import pytest

from seacable.towline import kernel as K


def _frame(rng):
    e1 = rng.normal(size=3)
    e1 /= np.linalg.norm(e1)
    E = np.zeros((3, 3))
    K.frame_from_axis(e1, E)
    return E


def _point_map(E, s):
    """(3, 5): an element's velocities (u, v, w, q, r) to the inertial velocity of its point s e1."""
    return np.column_stack([E[:, 0], E[:, 1], E[:, 2], -s * E[:, 2], s * E[:, 1]])


def _rotation_map(E):
    """(3, 5): an element's velocities to its inertial angular velocity q e2 + r e3."""
    return np.column_stack([np.zeros((3, 3)), E[:, 1], E[:, 2]])


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_the_line_implicit_dampers_are_the_dense_solve(seed):
    rng = np.random.default_rng(seed)
    n, dt = 7, 1e-3
    P = np.zeros(K.P_SIZE)
    P[K.P_L], P[K.P_M] = 1.3, 2.0
    half, m = 0.65, 2.0
    R = rng.normal(size=(n, 3))
    E = np.array([_frame(rng) for _ in range(n)])
    nu, om = rng.normal(size=(n, 3)), rng.normal(size=(n, 2))
    my = m + rng.uniform(0.5, 2.0, n)          # wetted transverse masses [kg]
    ik = rng.uniform(0.2, 0.5, n)              # wetted inertias [kg m^2]
    loads = rng.normal(scale=50.0, size=(n, 5))
    # joints 0 (the tug's) .. n (the barge's): axis, c_x (0: slack), c_t; bending at the inner taut ones
    joints = []
    for j in range(n + 1):
        a = rng.normal(size=3)
        a /= np.linalg.norm(a)
        cx = 0.0 if j == 3 else rng.uniform(10.0, 400.0)
        ct = rng.uniform(1.0, 40.0)
        joints.append((0.0, 0.0, 0.0, 0.0, 0.0, 0.0, a[0], a[1], a[2], cx, ct, 0.0))
    cm = np.zeros(n + 1)
    cm[1:n] = rng.uniform(0.0, 5.0, n - 1)
    cm[5] = 0.0

    # the kernel's elimination and back substitution
    Rk, Ek, nuk, omk = R.copy(), E.copy(), nu.copy(), om.copy()
    Wz, blk = np.zeros((n, 5, 6)), np.zeros((5, 6))
    pf = K._in_frame(Ek, 0, joints[0])
    for k in range(n):
        ld = (loads[k, 0], loads[k, 1], loads[k, 2], 0.0, 0.0, my[k], ik[k])
        ee = K._relative_frame(Ek, k, k + 1) if k + 1 < n else K._NO_FRAME
        pf = K._eliminate(k, k + 1, n, Ek, nuk, omk, P, ld, loads[k, 3], loads[k, 4], joints[k], joints[k + 1],
                          pf, cm[k], cm[k + 1], ee, dt, Wz, blk)
    assert K._back_substitute(0, n, Rk, Ek, nuk, omk, dt, Wz)
    dx = np.hstack([nuk - nu, omk - om]).ravel()

    # the dense system from its definition
    A = np.zeros((5 * n, 5 * n))
    rhs = np.zeros(5 * n)
    for k in range(n):
        A[5 * k:5 * k + 5, 5 * k:5 * k + 5] = np.diag([m, my[k], my[k], ik[k], ik[k]])
        u, v, w = nu[k]
        q, r = om[k]
        rhs[5 * k:5 * k + 5] = dt * (loads[k] + [-q * my[k] * w + r * my[k] * v, -r * m * u, q * m * u,
                                                 -(m - my[k]) * u * w, -(my[k] - m) * u * v])
    for j in range(n + 1):
        a, cx, ct = np.array(joints[j][6:9]), joints[j][9], joints[j][10]
        C = ct * np.eye(3) + (cx - ct) * np.outer(a, a)
        J = np.zeros((3, 5 * n))   # the relative velocity of the joint's points (the tug and barge held)
        Jr = np.zeros((3, 5 * n))  # the relative angular velocity of its elements
        if j > 0:
            J[:, 5 * (j - 1):5 * j] -= _point_map(E[j - 1], half)
            Jr[:, 5 * (j - 1):5 * j] -= _rotation_map(E[j - 1])
        if j < n:
            J[:, 5 * j:5 * j + 5] += _point_map(E[j], -half)
            Jr[:, 5 * j:5 * j + 5] += _rotation_map(E[j])
        A += dt * (J.T @ C @ J + cm[j] * Jr.T @ Jr)
    exact = np.linalg.solve(A, rhs)
    # the same system by another elimination: round-off of a condition number ~1e3, measured 3e-16 relative
    assert np.max(np.abs(dx - exact)) < 1e-12 * np.max(np.abs(exact))

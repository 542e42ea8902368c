"""Compiled time loop of Cummins' equation for one rigid body (:mod:`seacable.hydro.cummins`)."""

from __future__ import annotations

import numpy as np

from .._jit import dense_solve, njit


@njit(cache=True)
def cummins_steps(x, v, a, hist, head, kernel, mass, damping, quad, stiffness, force, dt, tol, out_x, out_v):
    """Advance ``force.shape[0] - 1`` steps of ``mass a + damping v + quad |v| v + memory + stiffness x = force``
    (Newmark's average acceleration), where the memory is the trapezoidal convolution of the kernel with the
    velocity history: ``dt (K_0 v_now / 2 + sum_{j>=1} K_j v_{now-j})`` (the last ``K_j`` halved by the caller).

    ``x``, ``v``, ``a`` (6,): the state at ``force[0]``'s time, advanced in place. ``hist`` (n_k, 6): the past
    velocities, ``hist[(head - j) % n_k]`` the one ``j`` steps back (j = 1 the previous step); ``head`` (1,) int.
    ``kernel`` (n_k, 6, 6) with ``kernel[0]`` the K_0 term; ``out_x``, ``out_v`` (n, 6) receive each step's
    state (row 0 the start). Returns the number of steps done (fewer when a Newton iteration fails).
    """
    n_k = kernel.shape[0]
    n = force.shape[0]
    c_v = 0.5 * dt
    c_x = 0.25 * dt * dt
    mem = np.zeros(6)
    S = np.empty((6, 6))
    r = np.empty(6)
    xp = np.empty(6)
    vp = np.empty(6)
    an = np.empty(6)
    for k in range(6):
        out_x[0, k] = x[k]
        out_v[0, k] = v[k]
    for step in range(1, n):
        # the memory of the velocities before this step (j >= 1), known at its start
        for k in range(6):
            mem[k] = 0.0
        for j in range(1, n_k):
            h = hist[(head[0] - j + 1) % n_k]
            K = kernel[j]
            for r0 in range(6):
                s = 0.0
                for c in range(6):
                    s += K[r0, c] * h[c]
                mem[r0] += dt * s
        for k in range(6):
            xp[k] = x[k] + dt * v[k] + c_x * a[k]
            vp[k] = v[k] + c_v * a[k]
            an[k] = a[k]
        ok = False
        for it in range(30):
            # residual at the accelerations an: x = xp + c_x an, v = vp + c_v an
            for r0 in range(6):
                s = force[step, r0] - mem[r0]
                for c in range(6):
                    xc = xp[c] + c_x * an[c]
                    vc = vp[c] + c_v * an[c]
                    s -= mass[r0, c] * an[c] + (damping[r0, c] + 0.5 * dt * kernel[0, r0, c]) * vc \
                        + quad[r0, c] * abs(vc) * vc + stiffness[r0, c] * xc
                    S[r0, c] = mass[r0, c] + c_v * (damping[r0, c] + 0.5 * dt * kernel[0, r0, c]
                                                    + 2.0 * quad[r0, c] * abs(vc)) + c_x * stiffness[r0, c]
                r[r0] = s
            if not dense_solve(S, r):  # r becomes the correction
                return step - 1
            big = 0.0
            size = 0.0
            for k in range(6):
                an[k] += r[k]
                big = max(big, abs(r[k]))
                size = max(size, abs(an[k]))
            if big <= tol * max(size, 1e-12):
                ok = True
                break
        if not ok:
            return step - 1
        for k in range(6):
            x[k] = xp[k] + c_x * an[k]
            v[k] = vp[k] + c_v * an[k]
            a[k] = an[k]
            out_x[step, k] = x[k]
            out_v[step, k] = v[k]
        head[0] = (head[0] + 1) % n_k
        for k in range(6):
            hist[head[0], k] = v[k]
    return n - 1

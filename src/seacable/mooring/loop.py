"""The compiled time loop of a mooring network: many output intervals in one call, no Python per step.

:func:`run_outputs` advances the state output interval after output interval with the per-step
machinery of :mod:`seacable.mooring.kernel` (:func:`~seacable.mooring.kernel.newmark_steps`, generalised-alpha) and
stores each output state (:func:`record_output`) in preallocated arrays. The prescribed nodes' motion
comes pre-sampled on the step grid. An interval whose step does not converge stops the call, so that
the caller can redo the rest of that interval at a smaller step (:func:`seacable.mooring.solver.simulate`).
"""

from __future__ import annotations

import numpy as np

from .._jit import njit
from . import kernel as K

__all__ = ["evaluate_states", "record_output", "run_outputs"]


@njit(cache=True)
def record_output(k, t, X, V, A, knodes, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol,
                  pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, bw, env_rec,
                  cur_depth, cur_speed, sea, F, M, tension, times, pos, vel, acc, ten, sup, evaluated=False):
    """Store the state at time ``t`` in row ``k`` of the stored arrays: positions, element tensions, the force each node applies
    to its support, ``F - M a`` (what :meth:`seacable.mooring.solver.MooringModel.evaluate` gives, with
    ``env_rec`` its environment), and the velocities and accelerations of the nodes ``knodes``.

    ``evaluated``: ``F``, ``M`` and ``tension`` already hold the loads of this state with ``env_rec`` (the
    last evaluation of a converged step), and are not evaluated again."""
    if not evaluated:
        empty = np.zeros((0, 2 * bw + 1))
        K.loads(X, V, t, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda, bedc,
                buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env_rec, cur_depth, cur_speed,
                np.bool_(True), sea, F, M, tension, empty, bw, 0.0, 0.0)
    times[k] = t
    for i in range(X.shape[0]):
        for r in range(3):
            pos[k, i, r] = X[i, r]
            sup[k, i, r] = F[i, r] - (M[i, r, 0] * A[i, 0] + M[i, r, 1] * A[i, 1] + M[i, r, 2] * A[i, 2])
    for j in range(knodes.size):
        for r in range(3):
            vel[k, j, r] = V[knodes[j], r]
            acc[k, j, r] = A[knodes[j], r]
    for e in range(tension.size):
        ten[k, e] = tension[e]


@njit(cache=True)
def run_outputs(k0, k1, base, interval, h, sub, px, pv, pa, X, V, A, knodes, channel, elements, L0, EA, cdamp, mpl,
                dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges,
                hinge_ei, visco, fidx, nfree, bw, env, env_rec, cur_depth, cur_speed, sea, beta, gamma, alpha_m, alpha_f,
                G, tol, max_iter, F, M, tension, stats, count, times, pos, vel, acc, ten, sup):
    """Advance outputs ``k0`` to ``k1``: each interval ``sub`` Newmark steps of ``h`` from ``k interval``, its
    end state stored as output ``k + 1`` in row ``k + 1 - base`` of the stored arrays (``base``: the output in
    their row 0, so that a long run can go out in blocks through arrays of a few outputs).

    ``px/pv/pa[(k - k0) sub + j]`` are the prescribed channels at ``k interval + (j + 1) h``. ``count``
    receives (outputs stored, steps taken, Newton iterations, steps of the failed interval that converged),
    updated as the loop goes; ``stats`` the last (iterations, residual, tolerance) of
    :func:`~seacable.mooring.kernel.newmark_steps`. Returns the interval that failed (its state at the failed
    step's start), or ``k1`` when all converged.

    An output's loads are those of the interval's last Newton evaluation (the converged state, at the time
    ``k interval + sub h``, equal to ``(k + 1) interval`` but for rounding), unless viscoelastic elements
    make the output's environment differ from the step's (their slow stretch held at the last step's).
    """
    same = visco.shape[0] == 0
    nd = 3 * nfree
    work = (np.zeros((nd, 2 * bw + 1)), np.zeros(nd), np.zeros(nd), np.empty_like(X), np.empty_like(V),
            np.empty_like(A), env.copy())
    for k in range(k0, k1):
        j0 = (k - k0) * sub
        stats[0] = 0.0
        got = K.newmark_work(X, V, A, k * interval, h, px[j0:j0 + sub], pv[j0:j0 + sub], pa[j0:j0 + sub], channel,
                              elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda,
                              bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, nfree, bw,
                              env, cur_depth, cur_speed, np.bool_(True), sea, beta, gamma, alpha_m, alpha_f, G, tol, max_iter,
                              F, M, tension, stats, *work)
        count[1] += got
        count[2] += np.int64(stats[0])
        if got < sub:
            count[3] = got
            return k
        record_output(k + 1 - base, (k + 1) * interval, X, V, A, knodes, elements, L0, EA, cdamp, mpl, dia, cdn, cdt,
                      can, cat, weight, pmass, padd, pvol, pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei,
                      visco, fidx, bw, env_rec, cur_depth, cur_speed, sea, F, M, tension, times, pos, vel, acc, ten,
                      sup, same)
        count[0] = k + 1
    return k1


@njit(cache=True)
def evaluate_states(Xs, Vs, As, knodes, ts, with_waves, nodes, elems, elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat,
                    weight, pmass, padd, pvol, pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei,
                    visco, fidx, bw, env, cur_depth, cur_speed, sea):
    """The support forces ``F - M a`` at ``nodes`` and the tensions of ``elems`` at many states (positions ``Xs``
    (nt, n, 3) at times ``ts``, velocities ``Vs`` and accelerations ``As`` (nt, k, 3) of the nodes ``knodes``,
    the others' taken as 0), as :meth:`seacable.mooring.solver.MooringModel.evaluate` gives them one by one:
    exact when ``knodes`` holds ``nodes`` and their neighbours. Returns ``support`` (nt, len(nodes), 3) [N]
    and ``tension`` (nt, len(elems)) [N]."""
    n = Xs.shape[1]
    V, A = np.zeros((n, 3)), np.zeros((n, 3))
    F, M = np.zeros((n, 3)), np.zeros((n, 3, 3))
    tension = np.zeros(elements.shape[0])
    empty = np.zeros((0, 2 * bw + 1))
    support = np.zeros((Xs.shape[0], nodes.size, 3))
    out_t = np.zeros((Xs.shape[0], elems.size))
    for s in range(Xs.shape[0]):
        for j in range(knodes.size):
            for r in range(3):
                V[knodes[j], r] = Vs[s, j, r]
                A[knodes[j], r] = As[s, j, r]
        K.loads(Xs[s], V, ts[s], elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd,
                pvol, pcda, bedc, buoy, pbuoy, ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco, fidx, env, cur_depth,
                cur_speed, with_waves, sea, F, M, tension, empty, bw, 0.0, 0.0)
        for j in range(nodes.size):
            i = nodes[j]
            for r in range(3):
                support[s, j, r] = F[i, r] - (M[i, r, 0] * A[i, 0] + M[i, r, 1] * A[i, 1] + M[i, r, 2] * A[i, 2])
        for j in range(elems.size):
            out_t[s, j] = tension[elems[j]]
    return support, out_t

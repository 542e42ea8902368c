"""Sums of harmonics at many times, ``sum_j c_j e^(-i w_j t)``: the wave loads' and the gusts' records.

At equally spaced times the sum is one matrix product with no transcendental function in it: the times cut in
blocks, ``e^(-i w (t0 + tau)) = e^(-i w t0) e^(-i w tau)``, the offsets' factors ``e^(-i w tau)`` (block, n) computed
once and each block's start folded into the coefficients (n, blocks x m) (each start's factor computed anew: no
error accumulates). Other times are summed directly, block by block. A 3-hour record at 0.1 s of 200 components in
6 columns takes about 0.1 s instead of 2-5 s of cosines.
"""

from __future__ import annotations

import numpy as np

__all__ = ["phasor_sum"]

_BLOCK = 1024  # times a block: a (block x components) matrix


def phasor_sum(coef, omega, t) -> np.ndarray:
    """``sum_j coef[j] e^(-i omega_j t)`` at each time ``t`` (nt,) [s]: (nt, m) complex for ``coef`` (n, m) and
    ``omega`` (n,) [rad/s]."""
    coef = np.asarray(coef, complex)
    omega = np.asarray(omega, float)
    t = np.asarray(t, float)
    step = (t[-1] - t[0]) / (t.size - 1) if t.size > 1 else 0.0
    # equal steps: each time within a few roundings of t0 + k step (a phase error of w 1e-14 |t|, as the direct sum's)
    if step > 0 and np.all(np.abs(t - (t[0] + step * np.arange(t.size))) <= 1e-14 * np.abs(t).max()):
        size = min(_BLOCK, t.size)
        offsets = np.exp(-1j * np.multiply.outer(step * np.arange(size), omega))  # (size, n)
        starts = t[::size]  # each block's first time
        # all blocks in one product: (size, n) @ (n, blocks * m), the blocks' starts folded into the coefficients
        shifted = coef[:, None, :] * np.exp(-1j * np.multiply.outer(omega, starts))[:, :, None]
        res = offsets @ shifted.reshape(omega.size, -1)
        return res.reshape(size, starts.size, -1).transpose(1, 0, 2).reshape(-1, coef.shape[1])[:t.size]
    out = np.empty((t.size, coef.shape[1]), complex)
    for lo in range(0, t.size, _BLOCK):
        out[lo:lo + _BLOCK] = np.exp(-1j * np.multiply.outer(t[lo:lo + _BLOCK], omega)) @ coef
    return out

"""``seacable._phasor.phasor_sum``: the blocked product at equal time steps against the direct sum."""

from __future__ import annotations

import numpy as np
import pytest

from seacable._phasor import _BLOCK, phasor_sum


def _direct(coef, omega, t):
    return np.exp(-1j * np.multiply.outer(t, omega)) @ coef


@pytest.mark.parametrize("times", [
    0.1 * np.arange(3 * _BLOCK + 17),            # several blocks and a short last one
    1234.5 + 0.05 * np.arange(_BLOCK // 2),      # one block, late start
    np.array([7.0]),                             # one time
])
def test_equal_steps_give_the_direct_sum(times):
    """Within the phases' own rounding, 10 eps max(w t) of the sum's size (the direct sum's error too): the offsets'
    and the blocks' factors are each computed directly, so nothing accumulates over a long record."""
    rng = np.random.default_rng(1)
    omega = rng.uniform(0.05, 3.0, 120)
    coef = rng.normal(size=(120, 3)) + 1j * rng.normal(size=(120, 3))
    got = phasor_sum(coef, omega, times)
    assert got.shape == (times.size, 3)
    np.testing.assert_allclose(got, _direct(coef, omega, times), rtol=0,
                               atol=10 * np.finfo(float).eps * omega.max() * max(times.max(), 1.0) * np.abs(coef).sum())


def test_uneven_times_are_summed_directly():
    rng = np.random.default_rng(2)
    t = np.sort(rng.uniform(0.0, 500.0, 3000))
    omega, coef = rng.uniform(0.1, 2.0, 50), rng.normal(size=(50, 2)) + 0j
    np.testing.assert_allclose(phasor_sum(coef, omega, t), _direct(coef, omega, t), rtol=0, atol=1e-12 * 100)

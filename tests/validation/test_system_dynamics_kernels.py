"""The coupled body-line kernel (``system_dynamic``) and the mooring kernel (``mooring_dynamic``) are two
implementations of the same finite-element line (issue 37, "a wrong answer is never silent"): on the same
case they must agree to their Newton tolerance, not to the time step's error.

The case exercises every load of the lines at once (:func:`conftest.system_and_mooring_cases`): waves and
current (drag on the relative velocity, Froude-Krylov and added mass), seabed contact with Coulomb friction,
a clump weight with its own drag and added mass, and a prescribed fairlead motion.
"""

from __future__ import annotations

import numpy as np


def test_the_two_kernels_agree_on_a_line_in_waves_current_and_on_the_seabed(two_kernel_cases):
    """Same positions and element tensions from both kernels over 10 s: the tensions to 1e-6 of the largest
    (observed 6e-9, 1.4e-3 N: both statics stop at 1e-8 of the forces, both time steps at 1e-7), the positions
    to 1e-5 m (observed 3e-7 m). Before, the coupled kernel started from zero accelerations where the mooring
    kernel starts from M a = F at t = 0 (the waves act on the static start): Newmark's average acceleration
    kept that error, 53 N here (2.3e-4 of the largest tension) and 1.5 mm, and 2.8 kN (3.5 % of the tension
    range) after 100 s of the same line with 40 elements."""
    system, mooring = two_kernel_cases(duration=10.0)
    ts, tm = system.segment_tension.values[:, 0, :], mooring.segment_tension.values
    assert np.max(np.abs(ts - tm)) < 1e-6 * np.max(tm)
    for name in "xyz":
        assert np.max(np.abs(system[name].values[:, 0, :] - mooring[name].values)) < 1e-5
    # the case is not still: the fairlead's tension moves by more than 1 % of itself, the waves reach the line
    assert np.ptp(tm[:, -1]) > 0.01 * np.max(tm)
    # and the sea that drove both is the same record
    assert np.max(np.abs(system.wave_elevation.values - mooring.wave_elevation.values)) == 0.0

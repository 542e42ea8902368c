"""Towed-cable dynamics: the 3-D implicit finite-difference box scheme of paper 000.

Modules (imported on demand, so that ``import seacable`` does not load numba):

``equations``
    The ten equations per node, their box-scheme residual and analytic Jacobians (numba).
``scheme``
    Boundary conditions (free end, towed body, vessel), Newton-Raphson, time marching.
``linalg``, ``lapack``
    Block tri-diagonal solve (paper 000) and, for comparison, dense and banded LAPACK solves.
``solver``
    :func:`~seacable.towed.solver.cable_parameters`, :func:`~seacable.towed.solver.steady_tow`
    (the initial state) and :func:`~seacable.towed.solver.simulate` (with step halving).
``vessel``
    Vessel paths: straight, speed schedule, turn, CSV table.
``run``
    The ``towed_dynamic`` analysis of a case, as an xarray Dataset.
"""

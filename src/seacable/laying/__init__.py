"""Cable laying: the 2-D lumped-mass model of paper 001 with payout, touchdown and repeaters.

Modules (imported on demand, so that ``import seacable`` does not load numba):

``inputs``
    Ship motion, payout control (rate, slack, bottom tension), bathymetry; the seabed profile.
``kernel``
    One implicit time step of the suspended cable (numba): node masses with directional added
    mass, Morison drag, tension with the inextensible (or elastic) constraint, slack segments.
``control``
    Ship speed (schedule, repeater slow-down) and payout speed (rate, slack with CPRATE, bottom tension).
``solver``
    :func:`~seacable.laying.solver.simulate`: payout, node birth at the water entry, touchdown and
    lift-off, repeaters, controls, automatic time step.
``run``
    The ``laying_dynamic`` analysis of a case, as an xarray Dataset.
"""

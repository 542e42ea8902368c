"""Mooring lines: the truss finite-element model of paper 004, and MoorDyn input files.

Modules (imported on demand, so that ``import seacable`` does not load numba):

``network``
    Nodes and two-node truss elements as flat arrays, built from a case's line.
``kernel``
    Loads, tangents, the Newmark-Newton step and the static Newton solver (numba); its parts, whose
    public names it re-exports, in private modules: ``_indices`` (the layouts of its flat arrays),
    ``_water``, ``_elements``, ``_seabed``, ``_band``, ``_loads`` (the loads pass) and ``_friction`` (the
    statics' seabed friction).
``checks``
    The geometric checks every mooring path makes before it solves (nodes under the seabed, ends
    beyond the lines' reach, a fairlead motion that does either).
``solver``
    :class:`~seacable.mooring.solver.MooringModel`, static equilibrium, pushover, time stepping.
``motion``
    Prescribed fairlead motion: harmonic, time series, rigid platform.
``moordyn``
    A MoorDyn input file as a network (lines, fixed, vessel and free points).
``friction``
    The seabed's Coulomb friction in the statics: the friction targets of the as-laid state, load steps, the
    pushover's paths, ``analysis.static_friction`` (its force and tangent in the kernel's ``_friction``).
``run``
    The ``mooring_static``, ``mooring_pushover`` and ``mooring_dynamic`` analyses as Datasets, each
    with its ``prepare_*`` function (every check that can be made before solving).
"""

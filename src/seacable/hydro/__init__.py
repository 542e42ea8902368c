"""Floating bodies' hydrodynamics (issue 39): the hydrodynamic database, its readers and the radiation memory.

- :class:`HydroDatabase` (``database``): added mass, damping, excitation, hydrostatics and mean drift, SI;
- :func:`read_wamit` (``wamit``): WAMIT's ``.1``, ``.3``, ``.hst`` and mean drift files, as HydroDyn reads them;
- ``radiation``: Cummins' retardation kernel and Ogilvie's relations back to the frequency domain.
"""

from .cummins import CumminsMotion, frequency_response, simulate_cummins
from .database import HydroDatabase
from .radiation import kernel_check, linear_transforms, ogilvie, retardation_kernel
from .wamit import read_wamit

__all__ = ["CumminsMotion", "HydroDatabase", "frequency_response", "kernel_check", "linear_transforms", "ogilvie",
           "read_wamit", "retardation_kernel", "simulate_cummins"]

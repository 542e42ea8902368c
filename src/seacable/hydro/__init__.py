"""Floating bodies' hydrodynamics (issue 39): the hydrodynamic database, its readers and the radiation memory.

- :class:`HydroDatabase` (``database``): added mass, damping, excitation, hydrostatics and mean drift, SI;
- :func:`read_wamit` (``wamit``): WAMIT's ``.1``, ``.3``, ``.hst`` and mean drift files, as HydroDyn reads them,
  with the full difference-frequency QTF of a ``.12d``;
- :func:`read_capytaine` (``capytaine``): Capytaine's datasets (NetCDF or xarray);
- ``loads``: first-order, mean-drift and slow-drift wave loads (Newman's, or the full QTF's) in an irregular sea;
- ``radiation``: Cummins' retardation kernel and Ogilvie's relations back to the frequency domain.
"""

from .capytaine import read_capytaine
from .cummins import CumminsMotion, frequency_response, simulate_cummins
from .database import HydroDatabase
from .radiation import kernel_check, linear_transforms, ogilvie, retardation_kernel
from .wamit import read_wamit

__all__ = ["CumminsMotion", "HydroDatabase", "frequency_response", "kernel_check", "linear_transforms", "ogilvie",
           "read_capytaine", "read_wamit", "retardation_kernel", "simulate_cummins"]

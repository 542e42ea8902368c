"""numba's ``njit`` for seacable's kernels, with the cache of compiled kernels keyed first.

Every kernel module takes its decorator from here (``from .._jit import njit``), never from
numba itself: importing this module installs :mod:`seacable._numba_cache`'s cache locator
before the module's first ``@njit(cache=True)`` runs, which is when numba picks where a
kernel's machine code is cached. ``import seacable`` alone does not import numba: a kernel
module, and so numba and the locator, is imported when a function that needs it first is.
``tests/unit/test_import.py`` checks that no other module imports ``njit`` from numba.
"""

from __future__ import annotations

from . import _numba_cache  # noqa: F401  isort: skip  (installs the cache locator, before any kernel)
from numba import njit

__all__ = ["njit"]

"""A package's public names imported on first use (PEP 562), for a quick ``import``.

A package whose ``__init__`` would import NumPy-heavy, numba, SciPy, xarray or Dask
modules only to re-export some of their names declares instead where each name lives::

    from typing import TYPE_CHECKING
    from .._lazy import lazy_names

    if TYPE_CHECKING:  # what type checkers and IDEs read: the same names from the same modules
        from .engine import sweep
        from .spec import Sweep, load_sweep

    __getattr__, __dir__ = lazy_names(__name__, {".engine": ("sweep",), ".spec": ("Sweep", "load_sweep")})

``package.sweep`` and ``from package import sweep`` then import ``package.engine`` the first
time the name is asked for and keep the name in the package's namespace, so later lookups
cost nothing; ``dir(package)`` and ``from package import *`` (with ``__all__``) see every
name. ``tests/unit/test_import.py`` checks that each package's ``TYPE_CHECKING`` block
names the same objects as its table.
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Iterable, Mapping

__all__ = ["lazy_names"]


def lazy_names(package: str, names: Mapping[str, Iterable[str]],
               submodules: Iterable[str] = ()) -> tuple[Callable[[str], object], Callable[[], list[str]]]:
    """The module ``__getattr__`` and ``__dir__`` of a package whose names are imported on first use.

    Parameters
    ----------
    package : str
        The package's ``__name__``. [-]
    names : mapping of str to iterable of str
        Module (relative to the package, as ``".engine"``, or absolute) -> the names it gives
        the package. [-]
    submodules : iterable of str
        Subpackages or submodules that are public names themselves (``seacable.statics``). [-]

    Returns
    -------
    (callable, callable)
        ``__getattr__(name)``, which raises AttributeError for any other name, and ``__dir__()``.
    """
    where = {name: module for module, given in names.items() for name in given}
    subs = frozenset(submodules)

    def __getattr__(name: str):
        if name in subs:
            return importlib.import_module(f"{package}.{name}")  # binds the package's attribute itself
        try:
            module = where[name]
        except KeyError:
            raise AttributeError(f"module {package!r} has no attribute {name!r}") from None
        value = getattr(importlib.import_module(module, package), name)
        setattr(sys.modules[package], name, value)
        return value

    def __dir__() -> list[str]:
        return sorted(set(vars(sys.modules[package])) | set(where) | subs)

    __getattr__.table = dict(where)  # type: ignore[attr-defined]  (the test: TYPE_CHECKING says the same)
    __getattr__.submodules = subs  # type: ignore[attr-defined]
    return __getattr__, __dir__

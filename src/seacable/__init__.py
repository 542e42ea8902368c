"""seacable: statics and dynamics of marine cables."""

from ._version import __version__
from .errors import (
    CaseFileError,
    ConvergenceError,
    InputError,
    NoSolutionError,
    SeacableError,
    SeacableWarning,
)

__all__ = [
    "__version__",
    "SeacableError",
    "InputError",
    "CaseFileError",
    "NoSolutionError",
    "ConvergenceError",
    "SeacableWarning",
]

"""Exceptions and warnings raised by seacable.

Every error a user can cause is a :class:`SeacableError`. Its message names the
input, the value with its unit, what was expected, and a suggested fix, so that
the command-line tool can print it as one line and exit non-zero.
"""

from __future__ import annotations

__all__ = [
    "SeacableError",
    "InputError",
    "CaseFileError",
    "NoSolutionError",
    "ConvergenceError",
    "SeacableWarning",
]


class SeacableError(Exception):
    """Base class of every error seacable raises on purpose."""


class InputError(SeacableError, ValueError):
    """An input value is out of range, of the wrong type, or inconsistent."""


class CaseFileError(InputError):
    """A case file cannot be read or does not follow the case schema."""


class NoSolutionError(InputError):
    """The inputs are legal one by one but admit no equilibrium.

    For example a mooring line too short to reach its fairlead.
    """


class ConvergenceError(SeacableError, RuntimeError):
    """An iterative solver did not converge.

    Parameters
    ----------
    message
        What failed and a remedy.
    time
        Simulated time at the failure, ``None`` for a static solve. [s]
    iterations
        Iterations done.
    residual
        Residual norm at the last iteration (units of the solver's residual).
    """

    def __init__(self, message: str, *, time: float | None = None,
                 iterations: int | None = None, residual: float | None = None):
        super().__init__(message)
        self.time = time
        self.iterations = iterations
        self.residual = residual


class SeacableWarning(UserWarning):
    """Input that is legal but physically suspicious (e.g. an angle that looks like degrees)."""

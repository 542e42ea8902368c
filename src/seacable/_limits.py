"""Size limits of a run, checked before its time loop starts.

A case that asks for 1e300 s of simulation, or for output that cannot fit in
memory, is refused with an estimate and a fix instead of running until the
machine runs out of memory. The limits are generous defaults that a user can
raise: by the environment variables ``SEACABLE_MAX_STEPS``,
``SEACABLE_MAX_MEMORY`` (bytes) and ``SEACABLE_MAX_CASES``, or by the command
line options ``--max-steps``, ``--max-memory`` and ``--max-cases`` that set them.
"""

from __future__ import annotations

import math
import os

from .errors import InputError

__all__ = ["ENVIRONMENT", "check_case_count", "check_run_size", "max_cases", "max_memory", "max_steps"]

DEFAULT_MAX_STEPS = 1.0e8
"""Time steps of one run: about a day of computing for the slowest kernel. [1]"""
DEFAULT_MAX_MEMORY = 8.0e9
"""Memory of one run's stored results. [byte]"""
DEFAULT_MAX_CASES = 1.0e5
"""Cases of one sweep. [1]"""
ENVIRONMENT = {"max_steps": "SEACABLE_MAX_STEPS", "max_memory": "SEACABLE_MAX_MEMORY",
               "max_cases": "SEACABLE_MAX_CASES"}
"""The environment variable of each limit."""


def _limit(env: str, default: float) -> float:
    text = os.environ.get(env)
    if text is None or not text.strip():
        return default
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (value > 0 and math.isfinite(value)):
        raise InputError(f"environment variable {env} must be a positive number, got {text!r}. "
                         f"Suggested fix: unset it (default {default:.3g}) or give e.g. {env}={default:.0e}.")
    return value


def max_steps() -> float:
    """Largest number of time steps one run may take. [1]"""
    return _limit(ENVIRONMENT["max_steps"], DEFAULT_MAX_STEPS)


def max_memory() -> float:
    """Largest memory one run's stored results may take. [byte]"""
    return _limit(ENVIRONMENT["max_memory"], DEFAULT_MAX_MEMORY)


def max_cases() -> float:
    """Largest number of cases in one sweep. [1]"""
    return _limit(ENVIRONMENT["max_cases"], DEFAULT_MAX_CASES)


def _size(value: float) -> str:
    for unit, scale in (("TB", 1e12), ("GB", 1e9), ("MB", 1e6)):
        if value >= scale:
            return f"{value / scale:.3g} {unit}"
    return f"{value:.3g} bytes"


def check_run_size(what: str, *, steps: float, stored_values: float, fix: str) -> None:
    """Refuse a run whose time steps or stored results exceed the limits.

    Parameters
    ----------
    what
        The run, for the message (``"laying_dynamic case 'lay'"``).
    steps
        Estimated number of time steps (may be ``inf`` or ``nan`` for nonsense input). [1]
    stored_values
        Estimated number of floating-point values kept for the result. [1]
    fix
        How to make the run smaller (``"lengthen analysis.output_interval"``).

    Raises
    ------
    InputError
        With the estimate, the limit and how to raise it.
    """
    steps, stored_values = float(steps), float(stored_values)
    limit = max_steps()
    if not steps <= limit:
        raise InputError(f"{what} needs about {steps:.3g} time steps, more than the limit of {limit:.3g}. "
                         f"Suggested fix: {fix}; or raise the limit with --max-steps (or the environment "
                         f"variable SEACABLE_MAX_STEPS) if the run is meant to be that long.")
    memory = 8.0 * stored_values
    limit = max_memory()
    if not memory <= limit:
        raise InputError(f"{what} would store about {_size(memory)} of results, more than the limit of "
                         f"{_size(limit)}. Suggested fix: {fix}; or raise the limit with --max-memory "
                         f"(bytes; or the environment variable SEACABLE_MAX_MEMORY).")


def check_case_count(what: str, cases: float, fix: str) -> None:
    """Refuse a sweep of more cases than the limit (``SEACABLE_MAX_CASES``)."""
    cases = float(cases)
    limit = max_cases()
    if not cases <= limit:
        raise InputError(f"{what} has {cases:.3g} cases, more than the limit of {limit:.3g}. Suggested fix: "
                         f"{fix}; or raise the limit with --max-cases (or the environment variable "
                         f"SEACABLE_MAX_CASES).")

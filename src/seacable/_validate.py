"""Argument checks shared by the public functions.

Each check raises :class:`~seacable.errors.InputError` with a message in the house
style: ``<name> must be <expected>, got <value> <unit>. Suggested fix: <fix>``.
They accept scalars or arrays; for arrays the first offending element is named.
"""

from __future__ import annotations

import difflib
import math

import numpy as np

from .errors import InputError

__all__ = ["positive", "nonnegative", "finite", "at_least", "in_range", "one_of"]


def _fmt(value, unit: str) -> str:
    value = float(value)
    text = f"{value:.6g}"
    return f"{text} {unit}".rstrip() if unit else text


def _fail(name, values, bad, unit, expected, fix):
    arr = np.asarray(values)
    if arr.ndim == 0:
        where, value = "", arr[()]
    else:
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        where = f"[{index[0] if len(index) == 1 else index}]"
        value = arr[index]
    msg = f"{name}{where} must be {expected}, got {_fmt(value, unit)}."
    if fix:
        msg += f" Suggested fix: {fix}"
    raise InputError(msg)


def finite(name: str, value, unit: str = "", fix: str | None = None):
    """Return ``value`` as float array/scalar; raise if any element is NaN or infinite."""
    if type(value) is float and math.isfinite(value):  # a plain finite float: itself, as below, without numpy
        return value
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be a number in {unit or 'SI units'}, got {value!r}."
                         + (f" Suggested fix: {fix}" if fix else "")) from None
    bad = ~np.isfinite(arr)
    if bad.any():
        _fail(name, arr, bad, unit, "a finite number", fix or "check the input for NaN or inf")
    return arr if arr.ndim else float(arr)


def positive(name: str, value, unit: str = "", fix: str | None = None):
    """Check ``value > 0`` (and finite)."""
    if type(value) is float and math.isfinite(value) and value > 0:
        return value
    arr = np.asarray(finite(name, value, unit, fix))
    bad = arr <= 0
    if bad.any():
        _fail(name, arr, bad, unit, f"> 0 {unit}".rstrip(), fix)
    return arr if arr.ndim else float(arr)


def nonnegative(name: str, value, unit: str = "", fix: str | None = None):
    """Check ``value >= 0`` (and finite)."""
    if type(value) is float and math.isfinite(value) and value >= 0:
        return value
    arr = np.asarray(finite(name, value, unit, fix))
    bad = arr < 0
    if bad.any():
        _fail(name, arr, bad, unit, f">= 0 {unit}".rstrip(), fix)
    return arr if arr.ndim else float(arr)


def at_least(name: str, value, bound: float, unit: str = "", fix: str | None = None):
    """Check ``value >= bound`` (and finite)."""
    arr = np.asarray(finite(name, value, unit, fix))
    bad = arr < bound
    if bad.any():
        _fail(name, arr, bad, unit, f">= {_fmt(bound, unit)}", fix)
    return arr if arr.ndim else float(arr)


def in_range(name: str, value, low: float, high: float, unit: str = "", fix: str | None = None,
             *, inclusive: bool = True):
    """Check ``low <= value <= high`` (or strict when ``inclusive=False``)."""
    arr = np.asarray(finite(name, value, unit, fix))
    bad = (arr < low) | (arr > high) if inclusive else (arr <= low) | (arr >= high)
    if bad.any():
        lo, hi = ("[", "]") if inclusive else ("(", ")")
        _fail(name, arr, bad, unit, f"in {lo}{_fmt(low, '')}, {_fmt(high, '')}{hi} {unit}".rstrip(), fix)
    return arr if arr.ndim else float(arr)


def one_of(name: str, value, allowed):
    """Return ``value`` if it is one of the option strings ``allowed``; else raise with a suggestion."""
    allowed = tuple(str(a) for a in allowed)
    if isinstance(value, str) and value in allowed:
        return value
    listing = ", ".join(repr(a) for a in allowed)
    close = difflib.get_close_matches(str(value), allowed, n=1)
    hint = f"did you mean {close[0]!r}? " if close else ""
    raise InputError(f"{name} must be one of {listing}, got {value!r}. Suggested fix: {hint}use one of {listing}.")

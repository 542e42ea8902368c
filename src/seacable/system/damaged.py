"""Which lines a damaged condition removes: the lines named, or ``most_loaded``.

The accidental limit state of a mooring (DNV-OS-E301 (2010) Ch.2 Sec.2, ALS: "one line failed"; API RP 2SK
3rd ed.: the damaged condition, one line broken) is the system after the failure of the line whose loss is
worst, in practice the most loaded line of the intact system under the design environment. An analysis's
``damaged_lines`` names the lines removed, or says ``most_loaded``: the line with the largest tension (the
larger of its two end tensions) in the intact equilibrium of the same loads. Where the largest tensions of
two lines agree to :data:`TIE` (a symmetric spread: the two weather lines of a three-line spread under a
load along its axis of symmetry), the first of them in the case's order is taken, so that the choice does not
hang on the solver's round-off.

- ``system_static``: the intact equilibrium of the case.
- ``system_offsets``: for each heading, the intact equilibrium under the largest load of that heading (the
  line removed may differ from heading to heading: the result's ``damaged_line`` says which).
- ``system_dynamic``: the static equilibrium the run starts from (the bodies under their steady
  ``external_force``, a body of a ``rao`` motion with ``mean_offset: equilibrium`` free).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..errors import InputError

__all__ = ["MOST_LOADED", "TIE", "is_most_loaded", "most_loaded_line"]

#: The word of ``damaged_lines`` that asks for the most loaded line.
MOST_LOADED = "most_loaded"

#: Largest tensions that agree to this, relative, are a tie (the first line in the case's order is taken): a
#: hundred times the statics' default tolerance on the force residual (1e-8). [-]
TIE = 1e-6


def is_most_loaded(damaged_lines) -> bool:
    """True when ``damaged_lines`` asks for the most loaded line."""
    return isinstance(damaged_lines, str) and damaged_lines == MOST_LOADED


def most_loaded_line(lines: Sequence[str], tensions, where: str = "") -> str:
    """The most loaded of ``lines``, given the largest tension of each [N] (NaN: not in the system).

    Ties within :data:`TIE` (relative) go to the first line in the given order.

    Raises
    ------
    InputError
        If no line has a finite tension.
    """
    t = np.asarray(tensions, float)
    finite = np.isfinite(t)
    if not finite.any():
        raise InputError(f"{where}analysis.damaged_lines 'most_loaded': no line has a tension to compare (lines: "
                         f"{', '.join(lines) or 'none'}). Suggested fix: name the lines to remove.")
    top = float(np.max(t[finite]))
    for name, value in zip(lines, t):
        if np.isfinite(value) and value >= top - TIE * abs(top):
            return str(name)
    raise AssertionError("unreachable: the largest tension is one of the lines'")  # pragma: no cover


def line_tensions(eq, lines: Sequence[str]) -> np.ndarray:
    """The larger end tension of each of ``lines`` in an equilibrium (NaN for a line it lacks). [N]"""
    index = {n: i for i, n in enumerate(eq.line_names)}
    out = np.full(len(lines), np.nan)
    for j, name in enumerate(lines):
        if name in index:
            i = index[name]
            out[j] = max(float(eq.end_a_tension[i]), float(eq.end_b_tension[i]))
    return out

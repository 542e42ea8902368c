"""Scatter diagrams (issue 20): the sea states of a year and their probabilities, read from a CSV file and matched
to the load cases of results (:mod:`seacable.design.summary`'s fatigue life).

A load case is matched by the sea state its runs' parameters hold: ``environment.waves.hs`` and ``tp`` (and
``heading`` where the diagram has one).
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pandas as pd

from ..errors import InputError
from . import fatigue

__all__ = ["HEADING_PATH", "HS_PATH", "SEED_PATH", "TP_PATH", "read_scatter", "scatter_probabilities"]

#: The swept parameters that make a sea state: seeds of a load case differ in SEED_PATH only.
SEED_PATH = "environment.waves.seed"
HS_PATH = "environment.waves.hs"
TP_PATH = "environment.waves.tp"
HEADING_PATH = "environment.waves.heading"


def read_scatter(path: str | Path) -> pd.DataFrame:
    """A scatter diagram: a CSV with columns ``hs`` [m], ``tp`` [s] and ``probability`` [-] (and optionally
    ``heading`` [rad]), one sea state a row ('#' starts a comment line, as in RAO tables), checked as it is read:
    hs and tp finite and > 0, headings finite and in radians, the probabilities finite, >= 0 and summing to 1
    (:func:`~seacable.design.fatigue.check_probabilities`, as :func:`~seacable.design.fatigue.fatigue_life` checks
    them again). Messages name the file's own line numbers."""
    from .._text import read_text_file

    path = Path(path)
    text = read_text_file(path, "scatter diagram", "give a CSV file with columns hs, tp, probability")
    reader = csv.reader(io.StringIO(text, newline=""))
    numbered = [(reader.line_num, r) for r in reader
                if any(c.strip() for c in r) and not r[0].lstrip().startswith("#")]
    header = [h.strip().lower() for h in numbered[0][1]] if numbered else []
    need = ["hs", "tp", "probability"]
    missing = [c for c in need if c not in header]
    if missing or len(numbered) < 2:
        semicolons = bool(numbered) and len(numbered[0][1]) == 1 and ";" in numbered[0][1][0]
        raise InputError(f"scatter diagram '{path}' needs a header with columns hs [m], tp [s], probability [-] "
                         f"and one sea state a row; {'it lacks ' + ', '.join(missing) if missing else 'it has no row'}"
                         f"{' (its columns are separated by semicolons)' if semicolons else ''}. Suggested fix: e.g. "
                         "'hs,tp,probability' then '2.0,8.0,0.6' (commas between columns, a point for decimals).")
    cols = [c for c in ("hs", "tp", "heading", "probability") if c in header]
    out, lines = [], []
    for k, row in numbered[1:]:
        try:
            out.append([float(row[header.index(c)]) for c in cols])
        except (ValueError, IndexError):
            raise InputError(f"scatter diagram '{path}' line {k}: expected numbers in columns {', '.join(cols)}, got "
                             f"{row}. Suggested fix: one sea state a row, SI units (m, s, rad).") from None
        lines.append(k)
    table = pd.DataFrame(out, columns=cols)
    for col, unit in (("hs", "m"), ("tp", "s")):
        bad = np.flatnonzero(~(np.isfinite(table[col].to_numpy()) & (table[col].to_numpy() > 0)))
        if bad.size:
            raise InputError(f"scatter diagram '{path}' line {lines[bad[0]]}: {col} = {table[col].iloc[bad[0]]:g} "
                             f"{unit}; it must be a finite number > 0 {unit}. Suggested fix: one sea state a row, SI "
                             "units (m, s, rad).")
    if "heading" in table:
        heading = table["heading"].to_numpy()
        bad = np.flatnonzero(~np.isfinite(heading))
        if bad.size:
            raise InputError(f"scatter diagram '{path}' line {lines[bad[0]]}: heading is not a finite number (rad). "
                             "Suggested fix: give the heading in radians.")
        if np.any(np.abs(heading) > 2 * np.pi):
            # the same rule as an RAO table's headings: beyond a full turn they are degrees
            k = int(np.argmax(np.abs(heading) > 2 * np.pi))
            raise InputError(f"scatter diagram '{path}' line {lines[k]}: heading = {heading[k]:g} rad, more than a "
                             "full turn (2 pi rad): it looks like degrees. Suggested fix: give the headings in radians "
                             "(180 deg = 3.1416 rad).")
    fatigue.check_probabilities(table["probability"].to_numpy(), f"scatter diagram '{path}'")
    return table


def scatter_probabilities(runs: Sequence, scatter) -> dict[str, float]:
    """Each load case's share of the scatter diagram's probability, matched on hs and tp (and heading).

    Parameters
    ----------
    runs
        The runs (:class:`seacable.design.summary.Run`: their ``load_case`` and ``parameters``).
    scatter
        A table of :func:`read_scatter`, or its file.

    Returns
    -------
    dict
        Load case -> probability [-], shared equally between the load cases of one sea state.
    """
    table = scatter if isinstance(scatter, pd.DataFrame) else read_scatter(scatter)
    keys = [c for c in ("hs", "tp", "heading") if c in table.columns]
    paths = {"hs": HS_PATH, "tp": TP_PATH, "heading": HEADING_PATH}
    states: dict[str, tuple] = {}
    for run in runs:
        missing = [paths[k] for k in keys if run.parameters.get(paths[k]) is None]
        if missing:
            raise InputError(f"load case '{run.load_case}' has no {', '.join(missing)}: it cannot be matched to the "
                             "scatter diagram. Suggested fix: sweep irregular seas (environment.waves with spectrum, "
                             "hs and tp), or leave out the scatter diagram.")
        states.setdefault(run.load_case, tuple(float(run.parameters[paths[k]]) for k in keys))

    def same(a, b):
        return all(math.isclose(x, y, rel_tol=1e-6, abs_tol=1e-9) for x, y in zip(a, b))

    def show(values):
        units = {"hs": "m", "tp": "s", "heading": "rad"}
        return ", ".join(f"{k} = {v:.4g} {units[k]}" for k, v in zip(keys, values))

    out = {}
    for _, row in table.iterrows():
        values = tuple(float(row[k]) for k in keys)
        matched = [lc for lc, s in states.items() if same(s, values)]
        if not matched:
            raise InputError(f"the scatter diagram's sea state {show(values)} (probability {row['probability']:.4g}) "
                             f"has no case in the results (their sea states: "
                             f"{'; '.join(sorted({show(s) for s in states.values()}))}). Suggested fix: add it to "
                             "the sweep, or merge it into a neighbouring sea state of the diagram.")
        for lc in matched:
            out[lc] = out.get(lc, 0.0) + float(row["probability"]) / len(matched)
    lonely = [lc for lc in states if lc not in out]
    if lonely:
        raise InputError(f"load case(s) {', '.join(repr(x) for x in lonely)} ({show(states[lonely[0]])}) have no sea "
                         "state in the scatter diagram. Suggested fix: add the sea state to the diagram (with its "
                         "probability), or leave the case out of the sweep.")
    return out

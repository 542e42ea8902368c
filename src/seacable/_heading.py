"""Linear interpolation in heading, periodic over 2 pi: the weights that RAO, hydrodynamic and wind tables share."""

from __future__ import annotations

import math

import numpy as np


def heading_weights(table_headings, at):
    """Where the headings ``at`` [rad] (any shape) fall in a table's headings [rad], periodically.

    Returns ``(order, lo, hi, frac)``: ``order`` sorts the table's headings by their angle in [0, 2 pi); a value at
    ``at`` is ``(1 - frac) v[lo] + frac v[hi]`` of the table's values in that order (``lo``, ``hi`` and ``frac`` of
    ``at``'s shape; after the last heading comes the first plus 2 pi). A table of one heading gives it everywhere.
    """
    b = np.mod(np.asarray(at, float), 2 * math.pi)
    wrapped = np.mod(np.atleast_1d(np.asarray(table_headings, float)), 2 * math.pi)
    order = np.argsort(wrapped)
    hs = wrapped[order]
    if hs.size == 1:
        return order, np.zeros(b.shape, int), np.zeros(b.shape, int), np.zeros(b.shape)
    ext = np.r_[hs, hs[0] + 2 * math.pi]
    b2 = np.where(b < hs[0], b + 2 * math.pi, b)
    lo = np.clip(np.searchsorted(ext, b2, side="right") - 1, 0, hs.size - 1)
    frac = (b2 - ext[lo]) / (ext[lo + 1] - ext[lo])
    return order, lo, (lo + 1) % hs.size, frac

"""The smooth start shared by prescribed motions: a half-cosine ramp and its derivatives."""

from __future__ import annotations

import math

import numpy as np


def smooth_ramp(t, duration):
    """``r(t) = (1 - cos(pi t / T)) / 2`` on ``[0, T)``, 0 before and 1 after, with dr/dt and d2r/dt2.

    The slope is zero at both ends, so a motion multiplied by the ramp starts from rest; ``T <= 0``
    gives ``r = 1`` (no ramp). Right-continuous at t = 0.
    """
    t = np.asarray(t, float)
    if duration <= 0:
        one = np.ones_like(t)
        return one, 0 * one, 0 * one
    s = np.clip(t / duration, 0.0, 1.0)
    inside = (t >= 0) & (t < duration)
    w = math.pi / duration
    r = 0.5 * (1 - np.cos(math.pi * s))
    dr = np.where(inside, 0.5 * w * np.sin(math.pi * s), 0.0)
    ddr = np.where(inside, 0.5 * w * w * np.cos(math.pi * s), 0.0)
    return r, dr, ddr

"""Wave loads on a floating body in an irregular sea: first order, mean drift and slow drift (issue 39).

For a sea of components ``a_j cos(k_j . x - w_j t + p_j)`` (:class:`seacable.seastate.SeaComponents`), the
elevation's phasor at the database's reference point is ``a_j e^(i p_j)`` and:

- the first-order force is ``F1(t) = sum_j Re(X(w_j, b_j) a_j e^(i p_j) e^(-i w_j t))`` (:func:`first_order_force`),
  ``X`` the excitation per metre of amplitude in seacable's convention (:mod:`seacable.hydro.database`);
- the mean drift is ``sum_j a_j^2 D(w_j, b_j)`` (:func:`mean_drift_force`), ``D`` the database's mean drift per
  square metre of amplitude;
- the slow drift by Newman's approximation (Newman 1974: the difference-frequency QTF ``T(w_i, w_j)`` taken from
  its diagonal, ``T_ij = sgn sqrt(D_i D_j)`` where the two have one sign) is, with the coefficients split by sign
  so that a sign change along the frequencies is kept (``D+ = max(D, 0)``, ``D- = max(-D, 0)``),

      F2(t) = |sum_j a_j sqrt(D+_j) e^(i (w_j t - p_j))|^2 - |sum_j a_j sqrt(D-_j) e^(i (w_j t - p_j))|^2,

  the slowly varying part of the square of the components: its mean is the mean drift, and its difference-
  frequency terms ``2 a_i a_j sqrt(D_i D_j) cos((w_i - w_j) t - p_i + p_j)`` (:func:`slow_drift_force`).

Each component's heading must be one of the drift table's (within ``HEADING_TOLERANCE``) when the table has
a single heading (WAMIT's .12d is often computed for one): a drift force is not made up for another direction.
The time sums are taken in blocks of times, so that a 3-hour record at 0.1 s holds no (times x components)
matrix.
"""

from __future__ import annotations

import math

import numpy as np

from .._phasor import phasor_sum
from ..errors import InputError
from .database import HydroDatabase

__all__ = ["HEADING_TOLERANCE", "first_order_force", "mean_drift_force", "slow_drift_force"]

#: How far a component's heading may be from the single heading of a drift table. [rad]
HEADING_TOLERANCE = math.radians(0.5)


def _drift(db: HydroDatabase, sea) -> np.ndarray:
    """The mean drift coefficients (components, 6) at the sea's frequencies and headings."""
    if db.drift is None:
        raise InputError(f"{db.source} has no mean drift. Suggested fix: give WAMIT's .8, .9 or .12d file, or leave "
                         "the drift out.")
    if db.drift_heading.size == 1:
        off = np.abs(np.angle(np.exp(1j * (np.asarray(sea.heading) - db.drift_heading[0]))))
        if np.any(off > HEADING_TOLERANCE):
            j = int(np.argmax(off))
            raise InputError(f"{db.source} gives the mean drift for waves towards {math.degrees(db.drift_heading[0]):g} "
                             f"deg only, and a component of the sea travels towards {math.degrees(sea.heading[j]):.4g} "
                             "deg. Suggested fix: a long-crested sea along the drift's heading, or a drift file with "
                             "more headings.")
    return db.drift_at(sea.omega, sea.heading)


def _times(t) -> np.ndarray:
    t = np.atleast_1d(np.asarray(t, float))
    if t.ndim != 1 or not np.all(np.isfinite(t)):
        raise InputError("the times must be a 1-D array of finite values [s].")
    return t


def first_order_force(db: HydroDatabase, sea, t) -> np.ndarray:
    """The first-order wave force and moment on the body at times ``t`` [s]: (nt, 6) [N, N m]."""
    t = _times(t)
    x = db.excitation_at(sea.omega, sea.heading)  # (n, 6)
    coef = x * (sea.amplitude * np.exp(1j * sea.phase))[:, None]
    return phasor_sum(coef, sea.omega, t).real


def mean_drift_force(db: HydroDatabase, sea) -> np.ndarray:
    """The sea's mean drift force and moment: (6,) [N, N m]."""
    return (sea.amplitude ** 2) @ _drift(db, sea)


def slow_drift_force(db: HydroDatabase, sea, t) -> np.ndarray:
    """The mean and slowly varying drift force by Newman's approximation (module docstring) at times ``t`` [s]:
    (nt, 6) [N, N m]."""
    t = _times(t)
    d = _drift(db, sea)
    phasor = (sea.amplitude * np.exp(1j * sea.phase))[:, None]
    # both signs in one sum: the columns of the positive parts, then those of the negative parts
    both = phasor_sum(phasor * np.sqrt(np.concatenate([np.maximum(d, 0.0), np.maximum(-d, 0.0)], axis=1)),
                       sea.omega, t)
    power = both.real ** 2 + both.imag ** 2
    return power[:, :6] - power[:, 6:]

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

- the slow drift from the full difference-frequency QTF ``T`` (:func:`qtf_drift_force`, WAMIT's ``.12d``) is the
  double sum over every ordered pair of components,

      F2(t) = Re sum_i sum_j c_i conj(c_j) T(w_i, w_j) e^(-i (w_i - w_j) t),     c_j = a_j e^(i p_j),

  real because ``T`` is Hermitian (``T(w_j, w_i) = conj T(w_i, w_j)``): the pair (i, j) and its mirror (j, i) give
  together ``2 a_i a_j |T_ij| cos((w_i - w_j) t - p_i + p_j - arg T_ij)``, and the diagonal the mean drift. Newman's
  approximation is this sum with ``T_ij = sqrt(D_i D_j)`` (sign split).

Each component's heading must be one of the drift table's (within ``HEADING_TOLERANCE``) when the table has
a single heading (WAMIT's .12d is often computed for one): a drift force is not made up for another direction.
The time sums are taken in blocks of times, so that a 3-hour record at 0.1 s holds no (times x components)
matrix.
"""

from __future__ import annotations

import math

import numpy as np

from .._heading import heading_weights
from .._phasor import phasor_sum
from ..errors import InputError
from .database import HydroDatabase

__all__ = ["HEADING_TOLERANCE", "first_order_force", "mean_drift_force", "qtf_at", "qtf_drift_force",
           "slow_drift_force"]

#: How far a component's heading may be from the single heading of a drift table. [rad]
HEADING_TOLERANCE = math.radians(0.5)


def _drift(db: HydroDatabase, sea) -> np.ndarray:
    """The mean drift coefficients (components, 6) at the sea's frequencies and headings."""
    if db.drift is None:
        raise InputError(f"{db.source} has no mean drift. Suggested fix: give WAMIT's .8, .9 or .12d file, or leave "
                         "the drift out (drift: none; a Capytaine dataset has no drift).")
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


def _long_crested(db: HydroDatabase, sea) -> float:
    """The one heading of a long-crested sea [rad], checked against the QTF's headings (one heading: within
    :data:`HEADING_TOLERANCE`): the pairs of components of two headings would need the QTF across headings."""
    if db.qtf is None:
        raise InputError(f"{db.source} has no full difference-frequency QTF (its drift file holds the mean drift only). "
                         "Suggested fix: give WAMIT's .12d output with its pairs of periods, or drift: newman.")
    heading = np.asarray(sea.heading, float)
    spread = np.abs(np.angle(np.exp(1j * (heading - heading[0]))))
    if np.any(spread > HEADING_TOLERANCE):
        raise InputError(f"the full QTF slow drift takes a long-crested sea, and the sea's components travel towards "
                         f"{math.degrees(heading.min()):.4g} to {math.degrees(heading.max()):.4g} deg (the QTF of two "
                         "components of different headings is not in the database). Suggested fix: a sea without "
                         "spreading, or drift: newman for a spread sea.")
    if db.qtf_heading.size == 1:
        off = abs(math.remainder(float(heading[0] - db.qtf_heading[0]), 2 * math.pi))
        if off > HEADING_TOLERANCE:
            raise InputError(f"{db.source} gives the QTF for waves towards {math.degrees(db.qtf_heading[0]):g} deg only, "
                             f"and the sea travels towards {math.degrees(heading[0]):.4g} deg. Suggested fix: a sea "
                             "along the QTF's heading, or a QTF file with more headings.")
    return float(heading[0])


def _qtf_table(db: HydroDatabase, omega: np.ndarray, heading: float):
    """The QTF's grid table at ``heading`` (nf, nf, 6) and the interpolation weights (n, nf) of the frequencies
    ``omega`` on its grid (two per row: linear), refusing frequencies outside it."""
    if db.qtf is None:
        raise InputError(f"{db.source} has no full difference-frequency QTF. Suggested fix: give WAMIT's .12d output.")
    grid = db.qtf_omega
    lo_w, hi_w = float(grid[0]), float(grid[-1])
    outside = (omega < lo_w * (1 - 1e-12)) | (omega > hi_w * (1 + 1e-12))
    if np.any(outside):
        raise InputError(f"{db.source}: the QTF is asked for at {float(omega[outside][0]):.4g} rad/s, outside its "
                         f"frequencies {lo_w:.4g}-{hi_w:.4g} rad/s. Suggested fix: cut the sea's spectrum to the QTF's "
                         "frequencies (omega_range), or give a QTF that covers the sea.")
    order, lo, hi, frac = heading_weights(db.qtf_heading, np.array([heading]))
    q = np.asarray(db.qtf)[order]
    table = (1 - frac[0]) * q[lo[0]] + frac[0] * q[hi[0]]
    k = np.clip(np.searchsorted(grid, omega, side="right") - 1, 0, grid.size - 2)
    f = np.clip((omega - grid[k]) / (grid[k + 1] - grid[k]), 0.0, 1.0)
    weights = np.zeros((omega.size, grid.size))
    rows = np.arange(omega.size)
    weights[rows, k] = 1.0 - f
    weights[rows, k + 1] += f
    return table, weights


def qtf_at(db: HydroDatabase, omega, heading: float) -> np.ndarray:
    """The difference-frequency QTF (n, n, 6) [N/m^2, N m/m^2] between the frequencies ``omega`` (n,) [rad/s] of
    waves travelling towards ``heading`` [rad]: bilinear in the two frequencies (real and imaginary parts),
    periodic-linear in heading, Hermitian; its diagonal is the mean drift :meth:`HydroDatabase.drift_at` (linear
    along the database's diagonal, as the mean drift force takes it). Frequencies outside the QTF's are refused."""
    w = np.asarray(omega, float).ravel()
    table, weights = _qtf_table(db, w, heading)
    t = np.einsum("if,fgm,jg->ijm", weights, table, weights)
    diag = np.arange(w.size)
    t[diag, diag] = _qtf_diagonal(db, w, heading, t[diag, diag])
    return t


def _qtf_diagonal(db: HydroDatabase, omega, heading, bilinear):
    """The mean drift the QTF's diagonal takes: the drift table's, where the database has one (as
    :func:`mean_drift_force` takes it), else the bilinear QTF's."""
    if db.drift is None:
        return bilinear.real
    return db.drift_at(omega, np.full(omega.size, heading))


def qtf_drift_force(db: HydroDatabase, sea, t) -> np.ndarray:
    """The mean and slowly varying drift force from the full difference-frequency QTF (module docstring) at times
    ``t`` [s]: (nt, 6) [N, N m], in a long-crested sea along one of the QTF's headings.

    The double sum is taken as a sum of squares, exactly. Off its diagonal the QTF between the sea's ``n``
    frequencies is the bilinear interpolation ``T = W Q W^T`` of the database's grid ``Q`` (nf x nf, Hermitian;
    ``W`` the linear weights, two per row), so with ``u_i(t) = c_i e^(-i w_i t)`` and ``Q = V diag(lambda) V^H``
    (for each DOF), ``sum_ij u_i T_ij conj(u_j) = sum_k lambda_k |sum_i (W V)_ik u_i(t)|^2``: at most ``nf`` terms
    per DOF, the grid frequencies the sea falls between. The diagonal, the mean drift, differs from the bilinear
    ``T_ii`` by a constant, ``a_i^2 (D_i - T_ii)``, added. Cost: ``nt n r`` complex products for the ``r <= 6 nf``
    eigenvectors (against ``6 nt n^2`` for the double sum, ``2 nt n`` for Newman's two terms), taken in blocks of
    times: for 200 components on the VolturnUS-S QTF (27 grid frequencies in a 0.3-1.6 rad/s sea) ``r = 162``,
    and a 3-hour record at 0.1 s took 2.6 s of CPU as a whole process against Newman's 1.1 s (medians of 5; about
    0.9 s of each is the imports and the database).

    Parameters
    ----------
    db : HydroDatabase
        With ``qtf`` (WAMIT's ``.12d`` with its pairs of periods).
    sea : seacable.seastate.SeaComponents
        The sea at the database's reference point, long-crested.
    t : array_like
        Times [s].
    """
    t = _times(t)
    heading = _long_crested(db, sea)
    w = np.asarray(sea.omega, float)
    table, weights = _qtf_table(db, w, heading)
    used = np.flatnonzero(np.any(weights != 0.0, axis=0))
    weights, table = weights[:, used], table[np.ix_(used, used)]
    a = np.asarray(sea.amplitude, float)
    c = a * np.exp(1j * np.asarray(sea.phase, float))
    bilinear = np.einsum("if,fgm,ig->im", weights, table, weights).real
    constant = (a * a) @ (_qtf_diagonal(db, w, heading, bilinear) - bilinear)  # (6,)
    columns, eigen, dofs = [], [], []
    for m in range(6):
        q = table[:, :, m]
        if not np.any(q):
            continue
        lam, vec = np.linalg.eigh(0.5 * (q + q.conj().T))
        columns.append(c[:, None] * (weights @ vec))
        eigen.append(lam)
        dofs.append(np.full(lam.size, m))
    out = np.tile(constant, (t.size, 1))
    if not columns:
        return out
    coef, lam, dof = np.concatenate(columns, axis=1), np.concatenate(eigen), np.concatenate(dofs)
    select = np.zeros((lam.size, 6))
    select[np.arange(lam.size), dof] = lam  # the eigenvalues into their DOF's column
    block = 8192  # times at a time: a block's phasors (block x r) stay small
    for lo in range(0, t.size, block):
        p = phasor_sum(coef, w, t[lo:lo + block])
        out[lo:lo + block] += (p.real ** 2 + p.imag ** 2) @ select
    return out

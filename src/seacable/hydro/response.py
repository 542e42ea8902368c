"""A moored floating body's response in the frequency domain: its RAOs from the database, and the variance of its
slow drift (issue 39).

The linear response per metre of wave amplitude (seacable's ``e^(-i w t)`` convention) solves

    (C - w^2 (M + A(w)) - i w (B(w) + B_v)) H(w, b) = X(w, b)                                  (:func:`raos`)

with ``C`` the whole restoring matrix (hydrostatics, the weight's moment and the mooring's stiffness about the
reference point) and ``B_v`` any linear viscous damping. The slow drift of Newman's approximation
(:mod:`seacable.hydro.loads`) is a sum of difference-frequency terms, ``c_ij cos(mu_ij t - p_i + p_j)`` with
``mu_ij = w_i - w_j`` and ``c_ij = 2 a_i a_j (sqrt(D+_i D+_j) - sqrt(D-_i D-_j))`` (6,); the linear body turns each
into ``H_LF(mu_ij) c_ij`` with ``H_LF(mu) = (C - mu^2 (M + A(mu)) - i mu (B(mu) + B_v))^-1``, so that the slow-drift
response's variance in a sea of components is

    var x_m = 1/2 sum_{i<j} |(H_LF(mu_ij) c_ij)_m|^2                                              (:func:`slow_drift_variance`)

Pinkster's force spectrum through the transfer function, summed over the sea's own components rather than
integrated, so that a time-domain run of the same sea is compared with its own expectation. With the full
difference-frequency QTF ``T`` (``drift="qtf"``, :func:`seacable.hydro.loads.qtf_drift_force`) the pair's force
is ``Re(2 c_i conj(c_j) T_ij e^(-i mu_ij t))`` for ``w_i > w_j``, so ``c_ij = 2 a_i a_j T(w_i, w_j)`` (complex: the
DOFs' relative phases kept), ``c_i = a_i e^(i p_i)`` contributing a phase common to the DOFs.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ..raos import RAOTable
from .database import HydroDatabase
from .loads import _drift, _long_crested, qtf_at

__all__ = ["coefficients_at", "natural_periods", "raos", "slow_drift_variance"]


def coefficients_at(db: HydroDatabase, omega) -> tuple[np.ndarray, np.ndarray]:
    """The added mass and damping (n, 6, 6) at frequencies ``omega`` [rad/s], linear between the database's; below
    its first frequency the added mass is interpolated to the zero-frequency limit (when it has one, else held)
    and the damping to zero, as a floating body radiates no wave at rest; above its last they are refused."""
    w = np.atleast_1d(np.asarray(omega, float))
    if np.any(w > db.omega[-1] * (1 + 1e-12)) or np.any(w < 0):
        bad = float(w[(w > db.omega[-1]) | (w < 0)][0])
        raise InputError(f"{db.source}: added mass and damping asked for at {bad:.4g} rad/s, outside 0-"
                         f"{db.omega[-1]:.4g} rad/s. Suggested fix: a sea within the database's frequencies.")
    a0 = db.added_mass_zero if db.added_mass_zero is not None else db.added_mass[0]
    grid = np.r_[0.0, db.omega]
    a = np.concatenate([a0[None], db.added_mass]).reshape(grid.size, 36)
    b = np.concatenate([np.zeros((1, 6, 6)), db.damping]).reshape(grid.size, 36)
    out_a = np.stack([np.interp(w, grid, a[:, k]) for k in range(36)], axis=-1).reshape(w.size, 6, 6)
    out_b = np.stack([np.interp(w, grid, b[:, k]) for k in range(36)], axis=-1).reshape(w.size, 6, 6)
    return out_a, out_b


def _transfer(db, mass, stiffness, damping, omega) -> np.ndarray:
    """``(C - w^2 (M + A) - i w (B + B_v))`` at each frequency: (n, 6, 6) complex."""
    a, b = coefficients_at(db, omega)
    w = np.atleast_1d(np.asarray(omega, float))[:, None, None]
    return np.asarray(stiffness)[None] - w ** 2 * (np.asarray(mass)[None] + a) - 1j * w * (b + np.asarray(damping)[None])


def _check(mass, stiffness, damping):
    out = []
    for name, m in (("mass", mass), ("stiffness", stiffness), ("damping", damping)):
        m = np.zeros((6, 6)) if m is None else np.asarray(m, float)
        if m.shape != (6, 6) or not np.all(np.isfinite(m)):
            raise InputError(f"{name} must be a finite 6x6 matrix (surge, sway, heave, roll, pitch, yaw), got "
                             f"shape {m.shape}.")
        out.append(m)
    return out


def raos(db: HydroDatabase, mass, stiffness, damping=None) -> RAOTable:
    """The body's RAOs at the database's excitation frequencies and headings (:class:`seacable.raos.RAOTable`,
    per metre of amplitude, seacable's convention), from its mass ``mass``, restoring ``stiffness`` and viscous
    ``damping`` (6x6 each, about the reference point). A DOF without restoring or inertia is refused: its RAO
    would be infinite."""
    mass, stiffness, damping = _check(mass, stiffness, damping)
    if db.excitation is None:
        raise InputError(f"{db.source} has no wave excitation: the RAOs need it. Suggested fix: give the .3 file.")
    system = _transfer(db, mass, stiffness, damping, db.excitation_omega)
    try:
        h = np.linalg.solve(system[None], db.excitation[..., None])[..., 0]  # (nh, nw, 6)
    except np.linalg.LinAlgError:
        raise InputError("the body's equation of motion is singular at a wave frequency (a DOF with neither restoring "
                         "nor inertia nor damping). Suggested fix: give the mass, inertias and the mooring's "
                         "stiffness.") from None
    return RAOTable(omega=db.excitation_omega, heading=db.heading, values=np.transpose(h, (2, 0, 1)),
                    source=f"RAOs of {db.source}")


def slow_drift_variance(db: HydroDatabase, sea, mass, stiffness, damping=None, *, drift: str = "newman") -> np.ndarray:
    """The variance (6,) [m^2, rad^2] of the body's slow-drift response in ``sea`` (module docstring), about its
    mean offset: to Newman's slow drift (``drift="newman"``) or to the full difference-frequency QTF's
    (``drift="qtf"``, a long-crested sea along one of its headings)."""
    mass, stiffness, damping = _check(mass, stiffness, damping)
    a = np.asarray(sea.amplitude, float)
    w = np.asarray(sea.omega, float)
    i, j = np.triu_indices(w.size, 1)
    if drift == "newman":
        d = _drift(db, sea)
        plus, minus = np.sqrt(np.maximum(d, 0.0)), np.sqrt(np.maximum(-d, 0.0))
        c = 2.0 * (a[i] * a[j])[:, None] * (plus[i] * plus[j] - minus[i] * minus[j])  # (pairs, 6)
    elif drift == "qtf":
        t = qtf_at(db, w, _long_crested(db, sea))
        hi, lo = np.where(w[i] > w[j], i, j), np.where(w[i] > w[j], j, i)
        c = 2.0 * (a[i] * a[j])[:, None] * t[hi, lo]  # (pairs, 6) complex
    else:
        raise InputError(f"drift must be 'newman' or 'qtf', got {drift!r}.")
    mu = np.abs(w[i] - w[j])
    if mu.size and mu.min() <= 0:
        raise InputError("two components of the sea have one frequency: their difference frequency is zero.")
    var = np.zeros(6)
    for lo in range(0, mu.size, 4096):  # (block, 6, 6) systems at a time
        system = _transfer(db, mass, stiffness, damping, mu[lo:lo + 4096])
        x = np.linalg.solve(system, c[lo:lo + 4096, :, None].astype(complex))[..., 0]
        var += 0.5 * np.sum(np.abs(x) ** 2, axis=0)
    return var


def natural_periods(db: HydroDatabase, mass, stiffness, iterations: int = 50) -> np.ndarray:
    """The undamped natural period of each DOF alone (6,) [s], ``2 pi sqrt((M_jj + A_jj(w_n)) / C_jj)`` with the
    added mass at its own frequency (fixed-point iteration); ``inf`` for a DOF without restoring."""
    mass, stiffness, _ = _check(mass, stiffness, None)
    out = np.full(6, math.inf)
    for k in range(6):
        if stiffness[k, k] <= 0:
            continue
        w = math.sqrt(stiffness[k, k] / (mass[k, k] + db.added_mass_inf[k, k]))
        for _ in range(iterations):
            a = coefficients_at(db, min(w, float(db.omega[-1])))[0][0, k, k]
            w_new = math.sqrt(stiffness[k, k] / (mass[k, k] + a))
            if abs(w_new - w) <= 1e-12 * w:
                break
            w = w_new
        out[k] = 2 * math.pi / w
    return out

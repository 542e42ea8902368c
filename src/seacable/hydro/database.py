"""A floating body's hydrodynamic database: the linear potential-flow coefficients a body model runs on (issue 39).

Everything is dimensional and SI, about the database's reference point, in seacable's axes (x, y horizontal, z
up; DOFs surge, sway, heave, roll, pitch, yaw, :data:`seacable.raos.DOFS`):

- ``added_mass[f]`` and ``damping[f]`` (6, 6) at ``omega[f]`` [rad/s]: [kg], [kg m], [kg m^2] and [N s/m],
  [N s], [N m s]; ``added_mass_inf`` and ``added_mass_zero`` the limits at infinite and zero frequency;
- ``excitation[h, f]`` (6,) complex, the first-order wave force per metre of wave amplitude [N/m, N m/m] at
  ``heading[h]`` (the direction the waves travel towards, from +x towards +y [rad]) and ``omega[f]``, in
  seacable's convention (:mod:`seacable.raos`): a wave whose elevation at the origin is ``a cos(w t)`` exerts
  ``a |X| cos(w t + phase)``, ``X = |X| e^(-i phase)``;
- ``hydrostatics`` (6, 6) the hydrostatic restoring matrix [N/m, N, N m/rad] as the database gives it (WAMIT's
  ``.hst`` holds the waterplane and the buoyancy's moment, and the weight's moment only where the centre of
  gravity was given: :func:`seacable.hydro.wamit.read_wamit` says which);
- ``drift[h, f]`` (6,) the mean wave drift force per square metre of wave amplitude [N/m^2, N m/m^2] at
  ``drift_heading[h]`` and ``drift_omega[f]``: a regular wave of amplitude ``a`` pushes the body by
  ``drift a^2`` on average;
- ``qtf[h, f1, f2]`` (6,) complex, the full difference-frequency quadratic transfer function [N/m^2, N m/m^2] at
  ``qtf_heading[h]`` (both waves along it) and the frequencies ``qtf_omega[f1]``, ``qtf_omega[f2]``, in seacable's
  convention: the waves ``sum_j a_j cos(w_j t - p_j)`` at the reference point (phasors ``c_j = a_j e^(i p_j)``)
  exert ``F(t) = Re sum_i sum_j c_i conj(c_j) qtf(w_i, w_j) e^(-i (w_i - w_j) t)``, the double sum over every
  ordered pair, so that ``qtf(w2, w1) = conj(qtf(w1, w2))`` (Hermitian) and its diagonal is the mean drift.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .._heading import heading_weights
from ..errors import InputError

__all__ = ["HydroDatabase"]


def _check_frequencies(omega: np.ndarray, what: str, source: str) -> None:
    if omega.ndim != 1 or omega.size < 2 or not np.all(np.isfinite(omega)) or omega[0] <= 0 or np.any(np.diff(omega) <= 0):
        raise InputError(f"{source}: the {what} frequencies must be at least two, positive and increasing, got "
                         f"{np.round(omega[:8], 6).tolist()} rad/s. Suggested fix: give each frequency once.")


def _check_headings(heading: np.ndarray, what: str, source: str) -> None:
    wrapped = np.mod(heading, 2 * math.pi)
    if heading.ndim != 1 or heading.size < 1 or not np.all(np.isfinite(heading)) or \
            np.unique(np.round(wrapped, 9)).size != heading.size:
        raise InputError(f"{source}: each {what} heading must be given once (modulo 360 deg), got "
                         f"{np.round(np.degrees(heading), 3).tolist()} deg. Suggested fix: remove the repeated "
                         "headings (-180 and 180 deg are the same).")


def _check_qtf(heading, omega, qtf, src: str) -> None:
    """The difference-frequency QTF: all three given or none, each heading and frequency once, the shape (headings,
    frequencies, frequencies, 6), finite and Hermitian in its two frequencies."""
    if qtf is None and heading is None and omega is None:
        return
    if qtf is None or heading is None or omega is None:
        raise InputError(f"{src}: the difference-frequency QTF needs its headings and frequencies, and they need it.")
    b, w, q = (np.asarray(a) for a in (heading, omega, qtf))
    _check_headings(b, "QTF", src)
    _check_frequencies(w, "QTF", src)
    if q.shape != (b.size, w.size, w.size, 6):
        raise InputError(f"{src}: the QTF must have the shape ({b.size} headings, {w.size} x {w.size} frequencies, "
                         f"6 DOFs), got {q.shape}. Suggested fix: give every DOF at every pair of frequencies.")
    if not np.all(np.isfinite(q)):
        raise InputError(f"{src}: the QTF holds a NaN or an infinity. Suggested fix: check the source file.")
    gap = np.abs(q - np.conj(np.swapaxes(q, 1, 2)))
    scale = np.abs(q).max(axis=(0, 1, 2))
    if np.any(gap > 1e-9 * scale + 1e-300):
        _, i, j, k = np.unravel_index(int(np.argmax(gap / (scale + 1e-300))), gap.shape)
        raise InputError(f"{src}: the difference-frequency QTF must be Hermitian, qtf(w2, w1) = conj(qtf(w1, w2)); "
                         f"DOF {k + 1} at {w[i]:.4g} and {w[j]:.4g} rad/s is not. Suggested fix: fill one triangle "
                         "from the other by conjugation.")


def _check_table(heading, omega, values, what: str, src: str) -> None:
    """A table by heading and frequency: all three given or none, each heading and frequency once, and the
    shape (headings, frequencies, 6 DOFs)."""
    if values is None and heading is None and omega is None:
        return
    if values is None or heading is None or omega is None:
        raise InputError(f"{src}: the {what} needs its headings and frequencies, and they need it.")
    b, w, v = (np.asarray(a) for a in (heading, omega, values))
    _check_headings(b, what, src)
    _check_frequencies(w, what, src)
    if v.shape != (b.size, w.size, 6):
        raise InputError(f"{src}: the {what} must have the shape ({b.size} headings, {w.size} frequencies, 6 DOFs), "
                         f"got {v.shape}. Suggested fix: give every DOF at every heading and frequency.")


@dataclass(frozen=True)
class HydroDatabase:
    """A body's linear hydrodynamic coefficients (module docstring for the units and conventions).

    ``excitation`` and ``drift`` may be left out (None) for a body that is only radiated or only excited;
    ``added_mass_zero`` is None when the source has no zero-frequency limit; ``qtf`` (the full difference-frequency
    QTF) is None when the source has only the mean drift; ``inertia`` is the body's mass matrix (6, 6) [kg, kg m,
    kg m^2] about the reference point where the source gives it (Capytaine's ``inertia_matrix``), else None. ``reference`` is the point the
    coefficients are about, in the body's axes [m]; ``rho`` [kg/m^3] and ``g`` [m/s^2] are those the
    dimensional values were made with.
    """

    omega: np.ndarray
    added_mass: np.ndarray
    damping: np.ndarray
    added_mass_inf: np.ndarray
    hydrostatics: np.ndarray
    heading: np.ndarray | None = None
    excitation_omega: np.ndarray | None = None
    excitation: np.ndarray | None = None
    added_mass_zero: np.ndarray | None = None
    drift_omega: np.ndarray | None = None
    drift_heading: np.ndarray | None = None
    drift: np.ndarray | None = None
    qtf_omega: np.ndarray | None = None
    qtf_heading: np.ndarray | None = None
    qtf: np.ndarray | None = None
    inertia: np.ndarray | None = None
    reference: np.ndarray = field(default_factory=lambda: np.zeros(3))
    rho: float = 1025.0
    g: float = 9.80665
    source: str = "hydrodynamic database"

    def __post_init__(self):
        src = self.source
        w = np.asarray(self.omega, float)
        _check_frequencies(w, "radiation", src)
        for name, shape in (("added_mass", (w.size, 6, 6)), ("damping", (w.size, 6, 6)),
                            ("added_mass_inf", (6, 6)), ("hydrostatics", (6, 6))):
            value = np.asarray(getattr(self, name))
            if value.shape != shape:
                raise InputError(f"{src}: {name} must have the shape {shape} (frequencies x 6 x 6 DOFs), got "
                                 f"{value.shape}. Suggested fix: give every DOF pair at every frequency.")
            if not np.all(np.isfinite(value)):
                raise InputError(f"{src}: {name} holds a NaN or an infinity. Suggested fix: check the source file.")
        _check_table(self.heading, self.excitation_omega, self.excitation, "excitation", src)
        _check_table(self.drift_heading, self.drift_omega, self.drift, "mean drift", src)
        _check_qtf(self.qtf_heading, self.qtf_omega, self.qtf, src)
        if self.inertia is not None and (np.shape(self.inertia) != (6, 6) or not np.all(np.isfinite(self.inertia))):
            raise InputError(f"{src}: the inertia (mass matrix) must be a finite 6 x 6 matrix, got the shape "
                             f"{np.shape(self.inertia)}.")
        if not (self.rho > 0 and self.g > 0):
            raise InputError(f"{src}: rho = {self.rho} kg/m^3 and g = {self.g} m/s^2 must be > 0.")

    @property
    def omega_range(self) -> tuple[float, float]:
        """The lowest and highest radiation frequency [rad/s]."""
        return float(self.omega[0]), float(self.omega[-1])

    def excitation_at(self, omega, heading) -> np.ndarray:
        """The excitation per metre of amplitude at frequencies ``omega`` [rad/s] and headings ``heading`` [rad]
        (arrays of one shape): (..., 6) complex, linear in frequency (real and imaginary parts) and in heading
        (periodic over 2 pi). Frequencies outside the database are refused: no force is made up."""
        if self.excitation is None:
            raise InputError(f"{self.source} has no wave excitation. Suggested fix: give the WAMIT .3 file (or a "
                             "Capytaine dataset with diffraction).")
        return _interp_heading_frequency(self.heading, self.excitation_omega, self.excitation, omega, heading,
                                         "wave excitation", self.source)

    def drift_at(self, omega, heading) -> np.ndarray:
        """The mean drift per square metre of amplitude at ``omega`` [rad/s] and ``heading`` [rad]: (..., 6)."""
        if self.drift is None:
            raise InputError(f"{self.source} has no mean drift. Suggested fix: give WAMIT's .8, .9 or .12d file.")
        return _interp_heading_frequency(self.drift_heading, self.drift_omega, self.drift, omega, heading,
                                         "mean drift", self.source).real


def _interp_heading_frequency(heading, omega_table, table, omega, at_heading, what: str, source: str) -> np.ndarray:
    """``table[h, f, :]`` at the points (``omega``, ``at_heading``): linear in frequency, periodic-linear in heading."""
    w = np.asarray(omega, float)
    w, b = np.broadcast_arrays(w, np.asarray(at_heading, float))
    lo_w, hi_w = float(omega_table[0]), float(omega_table[-1])
    outside = (w < lo_w * (1 - 1e-12)) | (w > hi_w * (1 + 1e-12))
    if np.any(outside):
        bad = float(w[outside].flat[0])
        raise InputError(f"{source}: the {what} is asked for at {bad:.4g} rad/s, outside its frequencies "
                         f"{lo_w:.4g}-{hi_w:.4g} rad/s. Suggested fix: cut the sea's spectrum to the database's "
                         "frequencies, or give a database that covers the sea.")
    order, lo, hi, frac = heading_weights(heading, b.ravel())
    vals = np.asarray(table)[order]
    # frequency first: (headings, points, 6)
    re = np.stack([np.stack([np.interp(w.ravel(), omega_table, vals[h, :, j].real) for j in range(6)], axis=-1)
                   for h in range(order.size)])
    im = np.stack([np.stack([np.interp(w.ravel(), omega_table, vals[h, :, j].imag) for j in range(6)], axis=-1)
                   for h in range(order.size)]) if np.iscomplexobj(vals) else np.zeros_like(re)
    at_w = re + 1j * im
    idx = np.arange(w.size)
    out = (1 - frac)[:, None] * at_w[lo, idx] + frac[:, None] * at_w[hi, idx]
    return out.reshape(w.shape + (6,))

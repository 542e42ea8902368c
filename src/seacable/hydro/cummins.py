"""A rigid body's motion by Cummins' equation, in the time domain (issue 39).

    (M + A_inf) x'' + B_v x' + B_q |x'| x' + int_0^t K(t - s) x'(s) ds + C x = F(t)

about the database's reference point, for small motions (the coefficients act in the global axes, as
HydroDyn's do): ``M`` the rigid body's mass matrix, ``A_inf`` the infinite-frequency added mass and ``K`` the
retardation kernel of the database (:mod:`seacable.hydro.radiation`), ``B_v`` and ``B_q`` viscous damping, ``C``
the hydrostatic and any mooring stiffness, ``F`` the loads (waves, drift, wind, ...). Newmark's average
acceleration steps it, with the memory's trapezoidal rule: the current velocity's share ``dt K_0 / 2`` is
solved with the step (a damping), the earlier ones are known at the step's start. This is the body model of
the uncoupled route and the reference the coupled one is checked against.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError, InputError
from .database import HydroDatabase
from .radiation import retardation_kernel

__all__ = ["CumminsMotion", "frequency_response", "simulate_cummins"]


@dataclass(frozen=True)
class CumminsMotion:
    """The body's motion: ``position`` and ``velocity`` (n, 6) [m, rad; m/s, rad/s] at ``time`` (n,) [s]."""

    time: np.ndarray
    position: np.ndarray
    velocity: np.ndarray


def _matrix(value, name: str) -> np.ndarray:
    m = np.zeros((6, 6)) if value is None else np.asarray(value, float)
    if m.shape != (6, 6) or not np.all(np.isfinite(m)):
        raise InputError(f"{name} must be a finite 6x6 matrix, got shape {m.shape}. Suggested fix: one row per DOF "
                         "(surge, sway, heave, roll, pitch, yaw), SI units.")
    return m


def simulate_cummins(db: HydroDatabase, mass, force, dt: float, *, stiffness=None, linear_damping=None,
                     quadratic_damping=None, kernel_length: float = 60.0, position=None, velocity=None,
                     tol: float = 1e-10) -> CumminsMotion:
    """Step Cummins' equation (module docstring) through the loads ``force`` (n, 6) [N, N m] given every ``dt``
    [s] from ``t = 0``.

    Parameters
    ----------
    db : HydroDatabase
        The body's database: ``A_inf`` and the kernel; its hydrostatics unless ``stiffness`` is given.
    mass : (6, 6) array_like
        The rigid body's mass matrix about the reference point [kg, kg m, kg m^2].
    stiffness : (6, 6) array_like, optional
        The whole restoring matrix (hydrostatics, the weight's moment, the mooring) [N/m, N/rad, N m/rad];
        by default the database's hydrostatics.
    linear_damping, quadratic_damping : (6, 6) array_like, optional
        Viscous damping beyond the radiation [N s/m, ...; N s^2/m^2, ...].
    kernel_length : float
        The memory kept [s] (:func:`~seacable.hydro.radiation.retardation_kernel`).
    position, velocity : (6,) array_like, optional
        The state at ``t = 0`` (at rest before: the memory starts empty).
    """
    from ._cummins_kernel import cummins_steps

    force = np.ascontiguousarray(force, float)
    if force.ndim != 2 or force.shape[1] != 6 or force.shape[0] < 2:
        raise InputError(f"force must be (n >= 2 times, 6 DOFs) [N, N m], got the shape {force.shape}.")
    if not np.all(np.isfinite(force)):
        raise InputError("force holds a NaN or an infinity. Suggested fix: check the loads' inputs.")
    mass = _matrix(mass, "mass")
    stiffness = db.hydrostatics if stiffness is None else _matrix(stiffness, "stiffness")
    _, kernel = retardation_kernel(db, dt, kernel_length)
    kernel[-1] *= 0.5  # the trapezoidal rule's end weight
    x = np.zeros(6) if position is None else np.array(position, float)
    v = np.zeros(6) if velocity is None else np.array(velocity, float)
    if x.shape != (6,) or v.shape != (6,):
        raise InputError("position and velocity must have 6 values each (surge, sway, heave, roll, pitch, yaw).")
    total = mass + db.added_mass_inf
    lin = _matrix(linear_damping, "linear_damping")
    quad = _matrix(quadratic_damping, "quadratic_damping")
    # the acceleration at t = 0 from the equation (an empty memory but the current velocity's share)
    rhs = force[0] - (lin + 0.5 * dt * kernel[0]) @ v - quad @ (np.abs(v) * v) - stiffness @ x
    try:
        a = np.linalg.solve(total, rhs)
    except np.linalg.LinAlgError:
        raise InputError("the body's mass matrix with the added mass is singular. Suggested fix: give the body's "
                         "mass and inertias (every DOF needs inertia).") from None
    hist = np.zeros((kernel.shape[0], 6))
    hist[0] = v
    head = np.zeros(1, np.int64)
    out_x = np.empty_like(force)
    out_v = np.empty_like(force)
    done = cummins_steps(x, v, a, hist, head, kernel, total, lin, quad, stiffness, force, float(dt), tol, out_x, out_v)
    if done < force.shape[0] - 1:
        raise ConvergenceError(f"Cummins' equation did not converge at t = {(done + 1) * dt:g} s (the step's Newton "
                               "iteration on the quadratic damping failed, or the matrix is singular). Suggested fix: "
                               "a smaller time step.", time=(done + 1) * dt)
    return CumminsMotion(time=dt * np.arange(force.shape[0]), position=out_x, velocity=out_v)


def frequency_response(mass, added_mass, damping, stiffness, excitation, omega) -> np.ndarray:
    """The linear response ``H`` (6,) per metre of wave amplitude at ``omega`` [rad/s]: ``(C - w^2 (M + A(w)) - i w
    (B(w) + B_v)) H = X`` in seacable's ``e^(-i w t)`` convention (``x = Re(H a e^(-i w t))``)."""
    omega = float(omega)
    system = np.asarray(stiffness) - omega ** 2 * (np.asarray(mass) + added_mass) - 1j * omega * damping
    return np.linalg.solve(system, np.asarray(excitation, complex))

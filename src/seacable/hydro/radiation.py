"""The radiation memory of Cummins' equation: the retardation kernel of a body's damping, and the check that it
gives the database's added mass and damping back.

Cummins' equation (Cummins 1962; Ogilvie 1964) for a body's motion ``x`` (6 DOFs):

    (M + A_inf) x'' + int_0^t K(t - s) x'(s) ds + C x = F(t),

with the retardation kernel (the radiation force's impulse response)

    K(t) = (2 / pi) int_0^inf B(w) cos(w t) dw                                                        (1)

and Ogilvie's relations back to the frequency domain

    B(w) = int_0^inf K(t) cos(w t) dt,      A(w) = A_inf - (1 / w) int_0^inf K(t) sin(w t) dt.          (2)

seacable takes ``B`` linear between the database's frequencies, zero at ``w = 0`` (a floating body radiates no
wave at rest) and above the last frequency, as HydroDyn does (its ``RdtnMod = 1``), but integrates (1) exactly
for that piecewise-linear ``B`` (:func:`linear_transforms`) instead of on a uniform frequency grid: the kernel
then depends on the database only, not on a grid's step, and costs (times x frequencies), not (times^2). The memory is then a convolution over the kernel's
``t_max`` (:func:`retardation_kernel`), a choice over a state-space fit: the convolution is exact to the
kernel's truncation and the grid, has no fitting order to choose or fail, and on a 60 s kernel at 0.1 s costs
600 6x6 products per step, a few microseconds. :func:`ogilvie` evaluates (2) on a kernel so that a test (and a
user, :func:`kernel_check`) sees how well the kernel gives the database back.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from .database import HydroDatabase

__all__ = ["kernel_check", "linear_transforms", "ogilvie", "retardation_kernel"]


def _g(x: np.ndarray) -> np.ndarray:
    """``(sin x - x cos x) / x^2``, with its series ``x / 3 - x^3 / 30`` near 0 (no cancellation)."""
    small = np.abs(x) < 1e-2
    xs = np.where(small, 1.0, x)
    return np.where(small, x / 3.0 - x ** 3 / 30.0, (np.sin(xs) - xs * np.cos(xs)) / xs ** 2)


def linear_transforms(x: np.ndarray, f: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``int f(x) cos(s x) dx`` and ``int f(x) sin(s x) dx`` over ``x[0]..x[-1]``, exact for ``f`` linear between
    its nodes ``x`` (n,) with values ``f`` (n, m): each (len(s), m).

    Segment by segment, with ``c`` its midpoint, ``h`` its half width, ``b`` its mean value and ``d`` its slope
    and ``z = h s``: the cosine integral is ``2 h b cos(c s) sinc(z) - 2 h^2 d sin(c s) g(z)`` and the sine
    integral ``2 h b sin(c s) sinc(z) + 2 h^2 d cos(c s) g(z)``, ``g(z) = (sin z - z cos z) / z^2`` (both without
    cancellation as ``s -> 0``)."""
    h = 0.5 * np.diff(x)
    c = 0.5 * (x[1:] + x[:-1])
    b = 0.5 * (f[1:] + f[:-1])
    d = (f[1:] - f[:-1]) / (2 * h)[:, None]
    z = np.outer(s, h)
    sinc = np.sinc(z / math.pi)
    g = _g(z)
    cs, sn = np.cos(np.outer(s, c)), np.sin(np.outer(s, c))
    cos_int = (2 * h * cs * sinc) @ b - (2 * h ** 2 * sn * g) @ d
    sin_int = (2 * h * sn * sinc) @ b + (2 * h ** 2 * cs * g) @ d
    return cos_int, sin_int


def retardation_kernel(db: HydroDatabase, dt: float, t_max: float = 60.0):
    """The retardation kernel ``K(t)`` (equation 1 of the module) at ``t = 0, dt, ..., t_max``.

    Parameters
    ----------
    db : HydroDatabase
        The body's database; its damping is used.
    dt : float
        The kernel's time step [s] (the time loop's step, or a divisor of it).
    t_max : float
        The kernel's length [s]: the memory beyond it is dropped. It must be long enough for ``K`` to have
        decayed (:func:`kernel_check` shows what is lost).

    Returns
    -------
    t : (n,) ndarray
        The kernel's times [s].
    K : (n, 6, 6) ndarray
        The kernel [N/m/s, N/s, N m/s per unit velocity and second...]: ``K[k] @ v`` is a force per second of
        the velocity ``v``'s history, integrated over ``ds``.
    """
    if not (dt > 0 and math.isfinite(dt)):
        raise InputError(f"the radiation kernel's time step must be > 0 s, got {dt}. Suggested fix: the time step.")
    if not (t_max >= 2 * dt and math.isfinite(t_max)):
        raise InputError(f"the radiation kernel's length t_max = {t_max} s must be at least two time steps "
                         f"(2 x {dt} s). Suggested fix: t_max of 60 s or more for a floating platform.")
    w = np.r_[0.0, db.omega]
    b = np.concatenate([np.zeros((1, 36)), db.damping.reshape(db.omega.size, 36)])
    t = dt * np.arange(round(t_max / dt) + 1)
    kernel = (2.0 / math.pi) * linear_transforms(w, b, t)[0]
    return t, kernel.reshape(t.size, 6, 6)


def ogilvie(t: np.ndarray, kernel: np.ndarray, a_inf: np.ndarray, omega) -> tuple[np.ndarray, np.ndarray]:
    """The added mass and damping a kernel gives (equation 2 of the module, exact for the kernel linear between
    its times): ``(A, B)``, each (frequencies, 6, 6), at ``omega`` [rad/s] (> 0)."""
    omega = np.atleast_1d(np.asarray(omega, float))
    if np.any(omega <= 0):
        raise InputError("Ogilvie's relations are evaluated at frequencies > 0 rad/s.")
    cos_int, sin_int = linear_transforms(t, kernel.reshape(t.size, 36), omega)
    b = cos_int
    a = a_inf.reshape(1, 36) - sin_int / omega[:, None]
    return a.reshape(-1, 6, 6), b.reshape(-1, 6, 6)


def kernel_check(db: HydroDatabase, t: np.ndarray, kernel: np.ndarray, dofs=range(6)) -> dict:
    """How well a kernel gives the database's added mass and damping back, DOF by DOF on the diagonal: the
    largest difference over the database's frequencies, relative to the largest value of that coefficient
    (``added_mass``: of ``A - A_inf``, the part the kernel carries), and the kernel's last value relative to
    its largest (how much memory its length drops)."""
    a, b = ogilvie(t, kernel, db.added_mass_inf, db.omega)
    out = {"added_mass": np.zeros(6), "damping": np.zeros(6), "tail": np.zeros(6)}
    for j in dofs:
        mem = db.added_mass[:, j, j] - db.added_mass_inf[j, j]
        scale_a = max(np.max(np.abs(mem)), 1e-30)
        scale_b = max(np.max(np.abs(db.damping[:, j, j])), 1e-30)
        out["added_mass"][j] = np.max(np.abs(a[:, j, j] - db.added_mass[:, j, j])) / scale_a
        out["damping"][j] = np.max(np.abs(b[:, j, j] - db.damping[:, j, j])) / scale_b
        out["tail"][j] = abs(kernel[-1, j, j]) / max(np.max(np.abs(kernel[:, j, j])), 1e-30)
    return out

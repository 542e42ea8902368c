"""The generalised-alpha time integration's parameters (Chung and Hulbert 1993), for the mooring and towed cable
finite-element models (:func:`seacable.mooring.solver.simulate`, :mod:`seacable.towed.fe`).

References
----------
Chung, J. and Hulbert, G. M. (1993). A time integration algorithm for structural dynamics with improved numerical
dissipation: the generalized-alpha method. Journal of Applied Mechanics 60(2), 371-375.
"""

from __future__ import annotations

from .. import _validate
from ..errors import InputError

__all__ = ["generalized_alpha"]


def generalized_alpha(spectral_radius: float = 1.0) -> tuple[float, float, float, float]:
    """The generalised-alpha parameters ``(alpha_m, alpha_f, beta, gamma)`` of a spectral radius at
    infinite frequency ``rho_inf`` (Chung and Hulbert 1993)::

        alpha_m = (2 rho_inf - 1) / (rho_inf + 1),   alpha_f = rho_inf / (rho_inf + 1),
        gamma = 1/2 - alpha_m + alpha_f,              beta = (1 - alpha_m + alpha_f)^2 / 4

    (``alpha_m`` and ``alpha_f`` weigh the step's start in the inertia and in the forces of the
    equilibrium, :func:`seacable.mooring.kernel.newmark_steps`). Second order for every ``rho_inf``
    in [0, 1]; a mode with ``omega dt >> 1`` is multiplied by ``-rho_inf`` each step, while the
    dissipation of the low frequencies is the least of the one-parameter schemes. ``rho_inf = 1``
    (no numerical damping) gives ``alpha_m = alpha_f = 1/2, beta = 1/4, gamma = 1/2``: the same
    step as Newmark's average acceleration, whose equilibrium at the step's end holds at every step
    once it holds at the start (the interpolated equilibrium is the mean of the two ends'), so it is
    returned as that, ``alpha_m = alpha_f = 0``, the scheme the model has always used, without the
    spurious root -1 that would carry a Newton residual from step to step.

    Raises
    ------
    InputError
        A spectral radius that is not a number in [0, 1].
    """
    if isinstance(spectral_radius, bool):
        raise InputError(f"spectral_radius must be a number in [0, 1], got {spectral_radius!r}. Suggested fix: "
                         "use 1.0 (the default) or 0.8.")
    rho = _validate.in_range("spectral_radius", spectral_radius, 0.0, 1.0, "",
                             "use 1 (average acceleration, no numerical damping, the default) or 0.7-0.9 to damp "
                             "the ringing of stiff modes at a coarse step.")
    if rho == 1.0:
        return 0.0, 0.0, 0.25, 0.5
    alpha_m = (2.0 * rho - 1.0) / (rho + 1.0)
    alpha_f = rho / (rho + 1.0)
    gamma = 0.5 - alpha_m + alpha_f
    beta = 0.25 * (1.0 - alpha_m + alpha_f) ** 2
    return alpha_m, alpha_f, beta, gamma

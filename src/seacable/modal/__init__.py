"""Natural frequencies of cables.

- :mod:`.wave_speed`: paper 002's estimate from the lateral wave speed (period factor with
  elliptic integrals; sagged and suspended cables).
- :mod:`.vertical`: vertical cables by eq. (15), the exact Bessel solution and the string.
- :mod:`.eigen`: eigen-analysis of a cable linearised about its static equilibrium.

The names are imported on first use (:mod:`seacable._lazy`), each with the part of SciPy it needs.
"""

from typing import TYPE_CHECKING

from .._lazy import lazy_names

if TYPE_CHECKING:
    from .eigen import CableModes, cable_modes
    from .vertical import travel_time, vertical_cable_frequencies, vertical_cable_period
    from .wave_speed import (
        mode_frequencies,
        period_factor,
        sagged_cable_frequencies,
        sagged_cable_period,
        suspended_cable_period,
    )

__all__ = [
    "period_factor",
    "sagged_cable_period",
    "sagged_cable_frequencies",
    "suspended_cable_period",
    "mode_frequencies",
    "vertical_cable_period",
    "vertical_cable_frequencies",
    "travel_time",
    "cable_modes",
    "CableModes",
]

__getattr__, __dir__ = lazy_names(__name__, {
    ".eigen": ("CableModes", "cable_modes"),
    ".vertical": ("travel_time", "vertical_cable_frequencies", "vertical_cable_period"),
    ".wave_speed": ("mode_frequencies", "period_factor", "sagged_cable_frequencies", "sagged_cable_period",
                    "suspended_cable_period"),
})

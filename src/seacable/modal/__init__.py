"""Natural frequencies of cables.

- :mod:`.wave_speed`: paper 002's estimate from the lateral wave speed (period factor with
  elliptic integrals; sagged and suspended cables).
- :mod:`.vertical`: vertical cables by eq. (15), the exact Bessel solution and the string.
- :mod:`.eigen`: eigen-analysis of a cable linearised about its static equilibrium.
"""

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

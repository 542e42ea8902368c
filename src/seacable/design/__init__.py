"""The design layer on the models' results: fatigue (issue 20); extremes, code checks and the report to come."""

from .fatigue import (
    TN_CURVES,
    TNCurve,
    fatigue_damage,
    fatigue_life,
    narrow_band_damage,
    nominal_area,
    tension_cycles,
)

__all__ = ["TN_CURVES", "TNCurve", "fatigue_damage", "fatigue_life", "narrow_band_damage", "nominal_area",
           "tension_cycles"]

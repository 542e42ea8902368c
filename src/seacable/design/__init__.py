"""The design layer on the models' results (issue 20): fatigue, extreme statistics; code checks and the report
to come."""

from .fatigue import (
    TN_CURVES,
    TNCurve,
    fatigue_damage,
    fatigue_life,
    narrow_band_damage,
    nominal_area,
    tension_cycles,
)
from .statistics import StormMaximum, gumbel_maximum, mean_and_dynamic, peaks, weibull_maximum

__all__ = ["TN_CURVES", "StormMaximum", "TNCurve", "fatigue_damage", "fatigue_life", "gumbel_maximum",
           "mean_and_dynamic", "narrow_band_damage", "nominal_area", "peaks", "tension_cycles", "weibull_maximum"]

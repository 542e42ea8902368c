"""The design layer on the models' results (issue 20): fatigue, extreme statistics, code checks (DNV-OS-E301,
API RP 2SK, anchor uplift, offset) and the design tables of results and sweeps (:mod:`.summary`), which
:mod:`seacable.report` writes as an HTML page and CSV files."""

from .checks import (
    API_FACTORS_OF_SAFETY,
    DNV_PARTIAL_SAFETY_FACTORS,
    DNV_STRENGTH_FACTOR,
    CheckResult,
    anchor_uplift,
    api_tension,
    check_table,
    dnv_als,
    dnv_uls,
    offset_check,
)
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

__all__ = ["API_FACTORS_OF_SAFETY", "DNV_PARTIAL_SAFETY_FACTORS", "DNV_STRENGTH_FACTOR", "TN_CURVES", "CheckResult",
           "StormMaximum", "TNCurve", "anchor_uplift", "api_tension", "check_table", "dnv_als", "dnv_uls",
           "fatigue_damage", "fatigue_life", "gumbel_maximum", "mean_and_dynamic", "narrow_band_damage",
           "nominal_area", "offset_check", "peaks", "tension_cycles", "weibull_maximum"]

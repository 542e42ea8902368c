"""The design layer on the models' results (issue 20): fatigue, extreme statistics, code checks (DNV-OS-E301,
API RP 2SK, anchor uplift, offset), the combined low- and wave-frequency tension (:mod:`.combination`, issue 39),
a cable's range graphs and checks (curvature against its MBR, tension, compression, clearance, hang-off angle:
:mod:`.cable`, issue 40) and the design tables of results and sweeps (:mod:`.summary`), which
:mod:`seacable.report` writes as an HTML page and CSV files."""

from .cable import (
    CableCheck,
    CableLimits,
    cable_check_table,
    cable_checks,
    cable_limits,
    plot_range_graphs,
    range_graphs,
    seabed_clearance,
)
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
from .combination import (
    CombinedTension,
    TensionComponents,
    api_combined_tension,
    dnv_combined_tension,
    modelled_components,
    most_probable_maximum,
    split_tension,
)
from .fatigue import (
    DNV_DESIGN_FATIGUE_FACTOR,
    MATERIAL_CURVES,
    TN_CURVES,
    TNCurve,
    curve_of_line_type,
    dnv_design_fatigue_factor,
    fatigue_damage,
    fatigue_life,
    narrow_band_damage,
    nominal_area,
    tension_cycles,
)
from .statistics import StormMaximum, gumbel_maximum, mean_and_dynamic, peaks, weibull_maximum

__all__ = ["API_FACTORS_OF_SAFETY", "DNV_DESIGN_FATIGUE_FACTOR", "DNV_PARTIAL_SAFETY_FACTORS", "DNV_STRENGTH_FACTOR",
           "MATERIAL_CURVES", "TN_CURVES", "CableCheck", "CableLimits", "CheckResult", "CombinedTension", "StormMaximum", "TNCurve",
           "TensionComponents", "anchor_uplift", "api_combined_tension", "api_tension", "cable_check_table", "cable_checks",
           "cable_limits", "check_table",
           "curve_of_line_type", "dnv_als", "dnv_combined_tension", "dnv_design_fatigue_factor", "dnv_uls",
           "fatigue_damage", "fatigue_life", "gumbel_maximum", "mean_and_dynamic", "modelled_components",
           "most_probable_maximum", "narrow_band_damage", "nominal_area", "offset_check", "peaks", "plot_range_graphs", "range_graphs",
           "seabed_clearance", "split_tension",
           "tension_cycles", "weibull_maximum"]

"""Static equilibrium of cables, functions first.

- :func:`catenary`: elastic catenary of one homogeneous line, all regimes, vectorised.
- :func:`line_equilibrium`, :func:`pushover`: multi-segment lines with point masses,
  buoys and clump segments on a flat seabed.
- :func:`towed_cable_steady`, :func:`critical_angle`: steady towed cable (paper 000).
- :func:`straight_line_lay` and friends: straight-line laying theory (paper 001).
"""

from .catenary import CatenaryProfile, CatenaryRegime, CatenaryResult, catenary
from .laying import StraightLineLay, cable_slack, hydrodynamic_constant, laying_angle, straight_line_lay
from .multisegment import LineEquilibrium, LineProfile, Pushover, line_equilibrium, pushover
from .towed import TowedCableSteady, critical_angle, towed_cable_steady

__all__ = [
    "catenary",
    "CatenaryResult",
    "CatenaryProfile",
    "CatenaryRegime",
    "line_equilibrium",
    "pushover",
    "LineEquilibrium",
    "LineProfile",
    "Pushover",
    "towed_cable_steady",
    "critical_angle",
    "TowedCableSteady",
    "straight_line_lay",
    "laying_angle",
    "hydrodynamic_constant",
    "cable_slack",
    "StraightLineLay",
]

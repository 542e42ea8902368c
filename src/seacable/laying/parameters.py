"""The inputs and the output of a laying simulation (:func:`seacable.laying.solver.simulate`): the cable and
water data (:class:`LayParameters`, with rows of the property table from :func:`props_row`), the repeaters and
the run's time series (:class:`LayRun`).
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass, field

import numpy as np

from .kernel import N_PROPS


@dataclass(frozen=True)
class Repeater:
    """A point mass inserted in the cable at material coordinate ``s``."""

    s: float                 # [m]
    mass: float              # [kg]
    added_mass: float        # [kg]
    weight: float            # in water [N]
    drag_area: float         # C_D A [m^2]
    name: str = ""


@dataclass(frozen=True)
class LayParameters:
    """Cable and water data of a laying simulation (SI units).

    ``props`` holds one row per line type (columns ``seacable.laying.kernel.P_*``) and
    ``type_ends`` the material coordinate at which each type ends. The current is the water's velocity
    at ``current_depths`` below the surface, one row of ``dim`` components per depth (2-D: along x and
    0; 3-D: x, y and 0).
    """

    props: np.ndarray
    type_ends: np.ndarray
    segment_length: float
    cable_length: float
    repeaters: tuple[Repeater, ...] = ()
    water_density: float = 1025.0
    current_depths: np.ndarray = field(default_factory=lambda: np.zeros(1))
    current_velocity: np.ndarray = field(default_factory=lambda: np.zeros((1, 2)))   # (K, dim), vertical 0
    friction: float | None = None      # Coulomb coefficient of the laid cable on the seabed; None: held where laid
    friction_distance: float = 1e-3    # slip at which the friction reaches its limit (a spring below) [m]

    def __post_init__(self):
        # the type ends as Python floats, for type_at at every node born (bisect_right on them is
        # numpy.searchsorted(type_ends, s, side="right"), without its conversions)
        object.__setattr__(self, "_ends", np.asarray(self.type_ends, float).tolist())

    def type_at(self, s: float) -> int:
        ends = self._ends
        return min(bisect.bisect_right(ends, s), len(ends) - 1)


@dataclass
class LayRun:
    """Result of :func:`simulate`: output time series, snapshots and the laid cable."""

    time: np.ndarray
    series: dict                 # name -> (n_out,) array
    pos: np.ndarray              # (n_out, n_max, dim) suspended nodes, NaN padded [m]
    tension: np.ndarray          # (n_out, n_max - 1) [N]
    laid: dict                   # "p" (n, dim), "s", "time" of the landed nodes
    repeater_pos: np.ndarray     # (n_out, n_rep, dim)
    ship: np.ndarray             # (n_out, dim) water entry [m]
    touchdown: np.ndarray        # (n_out, dim) touchdown point [m]
    steps: int = 0
    iterations: int = 0
    halvings: int = 0
    lifts: int = 0
    wall_time: float = 0.0
    interrupted: bool = False
    stop_reason: str = ""


def props_row(mass, weight, diameter, drag_normal, drag_tangential, added_normal, added_tangential,
              compliance) -> np.ndarray:
    """One row of the property table (per unit length: kg/m, N/m, m, -, -, kg/m, kg/m, 1/N)."""
    row = np.zeros(N_PROPS)
    row[:] = (mass, weight, diameter, drag_normal, drag_tangential, added_normal, added_tangential, compliance)
    return row

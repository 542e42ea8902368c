"""Tug-barge towline as a chain of rigid 5-DOF elements joined by spring-dampers (paper 003).

The names are imported on first use (:mod:`seacable._lazy`): a case that names a barge does not
import the towline's solver and compiled kernels (:mod:`.barge_model`).
"""

from typing import TYPE_CHECKING

from .._lazy import lazy_names

if TYPE_CHECKING:
    from .barge import barge_mass, barge_resistance
    from .barge_model import Barge
    from .solver import TowlineModel, TowlineRun, energy, initial_state, simulate, stable_time_step

__all__ = ["Barge", "TowlineModel", "TowlineRun", "barge_mass", "barge_resistance", "energy", "initial_state",
           "simulate", "stable_time_step"]

__getattr__, __dir__ = lazy_names(__name__, {
    ".barge": ("barge_mass", "barge_resistance"),
    ".barge_model": ("Barge",),
    ".solver": ("TowlineModel", "TowlineRun", "energy", "initial_state", "simulate", "stable_time_step"),
})

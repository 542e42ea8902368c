"""Tug-barge towline as a chain of rigid 5-DOF elements joined by spring-dampers (paper 003)."""

from .barge import Barge, barge_mass, barge_resistance
from .solver import TowlineModel, TowlineRun, energy, initial_state, simulate, stable_time_step

__all__ = ["Barge", "TowlineModel", "TowlineRun", "barge_mass", "barge_resistance", "energy", "initial_state",
           "simulate", "stable_time_step"]

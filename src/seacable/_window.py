"""The statistics window of a time-domain run: the time from which its extremes and statistics are taken.

A run's start-up transient (a towline's start snatch, a mooring line settling from its static start, a
motion ramping up) is not its storm response. ``analysis.statistics_from`` [s] of the time-domain analyses
(``towed_dynamic``, ``laying_dynamic``, ``mooring_dynamic``, ``towline_dynamic``, ``system_dynamic``) says where
the statistics start; by default, the end of the analysis's ramp where it has one (a mooring motion's or a
system's body and point motions' ``ramp``), else 0. It is applied in one place, :func:`statistics_window`, which
:mod:`seacable.extremes` (a sweep's summary), :mod:`seacable.run_summary` (what ``seacable run`` prints) and the
report's tables use. The window is read back from the case a result records (its ``case`` attribute), so a
result file needs no new attribute and results written before the window existed read as they did.
"""

from __future__ import annotations

import functools
import math
from typing import TYPE_CHECKING

from pydantic import Field, model_serializer, model_validator

from ._model import Model, load_yaml, quantity

if TYPE_CHECKING:  # xarray is not imported by reading a case (case.py imports this module)
    import xarray as xr

__all__ = ["StatisticsWindow", "default_statistics_from", "omit_unset_window", "statistics_start",
           "statistics_window"]


def default_statistics_from(analysis: dict, bodies: dict | None = None) -> float:
    """The default start of the statistics of an analysis (a dict, as dumped): the end of its ramp. [s]

    The ramp of ``motion`` (mooring_dynamic), or the longest of ``body_motions``, ``point_motions`` and the
    ``bodies``' ``hydrodynamics`` (the case's, system_dynamic: the ramp of a free body's wave loads); 0 without
    one, and 0 when the ramp does not end before ``duration`` (the whole run is then the ramp: its statistics are
    the run's).
    """
    motions = [analysis.get("motion")]
    for key in ("body_motions", "point_motions"):
        motions.extend((analysis.get(key) or {}).values())
    motions.extend(b.get("hydrodynamics") for b in (bodies or {}).values() if isinstance(b, dict))
    ramps = [float(m.get("ramp") or 0.0) for m in motions if isinstance(m, dict)]
    ramp = max(ramps, default=0.0)
    duration = float(analysis.get("duration") or math.inf)
    return ramp if ramp < duration else 0.0


class StatisticsWindow(Model):
    """The ``statistics_from`` option of the time-domain analyses (a mixin with their ``duration``)."""

    statistics_from: quantity("s", ge=0, fix="give a time within the run, e.g. the end of the start-up "
                                             "transient, or leave it out (the end of the ramp).") | None = Field(
        None, description="Time from which extremes, summaries, sweep tables and the report's statistics are "
                          "taken, leaving out the start-up transient (default: the end of the motion's ramp "
                          "where the analysis has one, else 0). [s]")

    @model_validator(mode="after")
    def _window_in_run(self):
        if self.statistics_from is not None and self.statistics_from >= self.duration:
            raise ValueError(f"statistics_from ({self.statistics_from:g} s) must lie within the run, in [0 s, "
                             f"duration = {self.duration:g} s). Suggested fix: a start before the end of the "
                             "run, e.g. the end of the start-up transient.")
        return self

    def statistics_start(self) -> float:
        """The time from which this run's statistics are taken: ``statistics_from`` or the end of the analysis's
        own ramp (a system's bodies' hydrodynamics ramp is the case's: :func:`statistics_start` of its result). [s]"""
        if self.statistics_from is not None:
            return float(self.statistics_from)
        return default_statistics_from(self.model_dump(mode="json"))

    @model_serializer(mode="wrap")
    def _omit_unset_window(self, handler):
        return omit_unset_window(handler(self))


def omit_unset_window(data):
    """Drop an unset ``statistics_from`` from a dumped analysis (in its model serializer), so that a case
    without it dumps (and a result records it) as before the option existed."""
    if isinstance(data, dict) and "statistics_from" in data and data["statistics_from"] is None:
        del data["statistics_from"]
    return data


@functools.lru_cache(maxsize=64)
def _start_of_case(text: str) -> float:
    try:
        data = load_yaml(text) or {}
        analysis = data.get("analysis") or {}
    except Exception:  # noqa: BLE001 - a result whose case does not parse has no window
        return 0.0
    if not isinstance(analysis, dict):
        return 0.0
    given = analysis.get("statistics_from")
    bodies = data.get("bodies") if isinstance(data.get("bodies"), dict) else None
    return float(given) if given is not None else default_statistics_from(analysis, bodies)


def statistics_start(ds: xr.Dataset) -> float:
    """The time from which the statistics of a result are taken (0 for a result without time or case). [s]"""
    if "time" not in ds.dims or not isinstance(ds.attrs.get("case"), str):
        return 0.0
    return _start_of_case(ds.attrs["case"])


def statistics_window(ds: xr.Dataset) -> xr.Dataset:
    """The part of a time-domain result its statistics are taken over: the output times at or after
    :func:`statistics_start` (the whole result when it starts at 0, or has no time)."""
    start = statistics_start(ds)
    if start <= 0.0:
        return ds
    keep = ds["time"].values >= start
    if not keep.any():  # an interrupted run that stopped before the window: all it has
        return ds
    return ds.isel(time=keep)

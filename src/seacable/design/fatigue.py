"""Fatigue of mooring lines: rainflow-counted tension ranges, T-N curves, Miner's sum and the life over a
scatter diagram.

The T-N curves are those of DNV-OS-E301 *Position mooring* (October 2010), Ch.2 Sec.2 D200, Table D1: the
number of cycles to failure at a nominal stress range ``s`` [MPa] is ``N(s) = a_D s^-m``, the stress range
being the tension range over the component's nominal cross-section (a chain link: its two bars,
``2 pi d^2 / 4``; a wire rope: ``pi d^2 / 4`` of its nominal diameter, or the metallic area given).
Damage adds up by Miner's rule over the rainflow cycles of the tension record (ASTM E1049-85, section 5.4.4,
counted by the maintained ``rainflow`` package), half cycles counting half. Over a scatter diagram, each sea
state's damage per unit time, weighted by its probability, gives the damage per year and the life.

The narrow-band closed form (:func:`narrow_band_damage`, a Gaussian process whose ranges are twice its
Rayleigh envelope) is the check of the counting: D = nu0 T / a_D (2 sqrt(2 m0))^m Gamma(1 + m/2) (DNV-OS-E301
Ch.2 Sec.2 D; Almar-Naess 1985, Fatigue Handbook).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate as v
from ..errors import InputError

__all__ = ["SECONDS_PER_YEAR", "TN_CURVES", "TNCurve", "fatigue_damage", "fatigue_life", "narrow_band_damage",
           "nominal_area", "tension_cycles"]

SECONDS_PER_YEAR = 365.25 * 86400.0
_EDITION = "DNV-OS-E301 (October 2010) Ch.2 Sec.2 Table D1"


@dataclass(frozen=True)
class TNCurve:
    """A T-N curve ``N = a_D s^-m``: ``a_D`` the intercept [MPa^m], ``m`` the slope, ``bars`` the bars of the
    nominal cross-section (2 for a chain link, 1 for a rope), ``reference`` the table."""

    name: str
    a_d: float
    m: float
    bars: int
    reference: str = _EDITION

    def cycles_to_failure(self, stress_range):
        """Cycles to failure at the nominal stress ranges ``stress_range`` [MPa]. [1]"""
        return self.a_d * np.asarray(stress_range, float) ** -self.m


#: The curves of DNV-OS-E301 (2010) Ch.2 Sec.2 Table D1, by component.
TN_CURVES: dict[str, TNCurve] = {
    "stud_chain": TNCurve("common stud chain link", 1.2e11, 3.0, 2),
    "studless_chain": TNCurve("common studless chain link", 6.0e10, 3.0, 2),
    "connecting_link": TNCurve("Baldt and Kenter connecting link", 1.2e10, 3.0, 2),
    "six_strand_rope": TNCurve("six strand wire rope", 3.4e14, 4.0, 1),
    "spiral_strand_rope": TNCurve("spiral strand wire rope", 1.7e17, 4.8, 1),
}


def _curve(curve) -> TNCurve:
    if isinstance(curve, TNCurve):
        return curve
    if curve not in TN_CURVES:
        raise InputError(f"T-N curve '{curve}' is not one of {', '.join(TN_CURVES)}. Suggested fix: give one of "
                         f"these ({_EDITION}), or a TNCurve of your own.")
    return TN_CURVES[curve]


def nominal_area(curve, diameter: float) -> float:
    """The nominal cross-section of the T-N curve's stress range [m^2] for a nominal diameter [m]: the two bars
    of a chain link, ``2 pi d^2 / 4``; a rope, ``pi d^2 / 4``."""
    d = float(v.positive("diameter", diameter, "m", "give the chain's bar diameter or the rope's nominal diameter in m"))
    return _curve(curve).bars * math.pi * d * d / 4.0


def tension_cycles(tension) -> tuple[np.ndarray, np.ndarray]:
    """Rainflow cycles of a tension record (ASTM E1049-85, the ``rainflow`` package): their ranges [N] and
    counts (1 a full cycle, 0.5 a half cycle), in the order they close."""
    import rainflow

    t = np.asarray(tension, float).ravel()
    if not np.all(np.isfinite(t)):
        bad = int(np.flatnonzero(~np.isfinite(t))[0])
        raise InputError(f"the tension record holds a non-finite value at sample {bad} ({t[bad]}). Suggested fix: "
                         "give the record of a completed run (an interrupted result holds NaN after its end).")
    cycles = list(rainflow.extract_cycles(t)) if t.size > 1 else []
    ranges = np.array([c[0] for c in cycles], float)
    counts = np.array([c[2] for c in cycles], float)
    return ranges, counts


def _area(curve: TNCurve, diameter, area) -> float:
    if (diameter is None) == (area is None):
        raise InputError("give either the nominal diameter (m) or the nominal area (m^2) of the component, not "
                         f"{'both' if area is not None else 'neither'}. Suggested fix: diameter=0.09 for a 90 mm "
                         "chain.")
    if area is not None:
        return float(v.positive("area", area, "m^2", "give the nominal cross-section in m^2"))
    return nominal_area(curve, diameter)


def fatigue_damage(tension, curve="studless_chain", *, diameter: float | None = None,
                   area: float | None = None) -> float:
    """Miner's damage of a tension record [N]: sum over its rainflow cycles of ``n_i / N(s_i)``, with
    ``s_i`` = range / area in MPa and ``N`` the T-N curve (a name of :data:`TN_CURVES` or a :class:`TNCurve`);
    the area from the nominal ``diameter`` [m] (:func:`nominal_area`) or given as ``area`` [m^2]. [1]"""
    c = _curve(curve)
    a = _area(c, diameter, area)
    ranges, counts = tension_cycles(tension)
    with np.errstate(divide="ignore"):  # a zero range: infinitely many cycles to failure, no damage
        return float(np.sum(counts / c.cycles_to_failure(ranges / a / 1e6)))  # stress ranges [MPa]


def narrow_band_damage(m0: float, zero_upcrossing_rate: float, duration: float, curve="studless_chain", *,
                       diameter: float | None = None, area: float | None = None) -> float:
    """Damage of a narrow-band Gaussian tension process of variance ``m0`` [N^2] and mean zero-upcrossing
    rate ``nu0`` [1/s] over ``duration`` [s], in closed form: its ranges are twice its Rayleigh envelope,
    D = nu0 T / a_D (2 sqrt(2 m0_s))^m Gamma(1 + m/2), with m0_s the variance of the stress [MPa^2]. [1]"""
    c = _curve(curve)
    a = _area(c, diameter, area)
    m0 = float(v.nonnegative("m0", m0, "N^2", "give the variance of the tension"))
    nu0 = float(v.nonnegative("zero_upcrossing_rate", zero_upcrossing_rate, "1/s", "give sqrt(m2/m0)/(2 pi)"))
    duration = float(v.nonnegative("duration", duration, "s", "give the exposure time in s"))
    sigma = math.sqrt(m0) / a / 1e6  # [MPa]
    return nu0 * duration / c.a_d * (2.0 * math.sqrt(2.0) * sigma) ** c.m * math.gamma(1.0 + c.m / 2.0)


#: How far the probabilities of a scatter diagram may sum from 1 (rounding of the values written). [-]
PROBABILITY_TOLERANCE = 1e-6


def check_probabilities(probability, where: str = "the scatter diagram") -> None:
    """Refuse probabilities of occurrence that are not finite numbers >= 0 summing to 1 (to
    :data:`PROBABILITY_TOLERANCE`), naming the first bad one (``where``: the diagram, for messages)."""
    p = np.atleast_1d(np.asarray(probability, float))
    bad = np.flatnonzero(~np.isfinite(p) | (p < 0))
    if bad.size:
        i = int(bad[0])
        raise InputError(f"{where}: the probability of sea state {i + 1} is {p[i]:g}; a probability of occurrence "
                         "must be a finite number >= 0. Suggested fix: give every sea state's probability (0 for "
                         "one that never occurs).")
    total = float(np.sum(p))
    if abs(total - 1.0) > PROBABILITY_TOLERANCE:
        raise InputError(f"{where}: the probabilities must sum to 1, got a sum of {total:.6g} ({p.size} sea states). "
                         "Suggested fix: normalise them (divide by their sum), write them as fractions not per cent, "
                         "or add the missing sea states.")


def fatigue_life(damage, duration, probability, *, design_fatigue_factor: float = 1.0) -> float:
    """Fatigue life [years] over a scatter diagram: each sea state's ``damage`` [1] over its simulated
    ``duration`` [s], weighted by its ``probability`` of occurrence (they sum to 1), gives the damage per
    year; the life is its inverse over the design fatigue factor (DNV-OS-E301 Ch.2 Sec.2 D: 3 for
    inspectable moorings, up to 10). [years]"""
    d = np.atleast_1d(np.asarray(damage, float))
    t = np.broadcast_to(np.asarray(duration, float), d.shape)
    p = np.broadcast_to(np.asarray(probability, float), d.shape)
    if not (np.all(np.isfinite(d)) and np.all(d >= 0)):
        raise InputError(f"damage must be finite and >= 0 for every sea state, got {d.tolist()}. Suggested fix: "
                         "give the damage of each sea state's record (fatigue_damage).")
    if not np.all(t > 0):
        raise InputError(f"each sea state's duration must be > 0 s, got {t.tolist()}. Suggested fix: give the "
                         "simulated time of each record in s.")
    check_probabilities(p)
    dff = float(v.at_least("design_fatigue_factor", design_fatigue_factor, 1.0, "", "give 1 or more (DNV: 3 to 10)"))
    per_year = float(np.sum(p * d / t)) * SECONDS_PER_YEAR
    return math.inf if per_year == 0.0 else 1.0 / (per_year * dff)

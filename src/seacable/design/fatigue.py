"""Fatigue of mooring lines: rainflow-counted tension ranges, T-N curves, Miner's sum and the life over a
scatter diagram.

The T-N curves are those of DNV-OS-E301 *Position mooring* (October 2010), Ch.2 Sec.2 D200, Table D1: the
number of cycles to failure at a nominal stress range ``s`` [MPa] is ``N(s) = a_D s^-m``, the stress range
being the tension range over the component's nominal cross-section (a chain link: its two bars,
``2 pi d^2 / 4``; a wire rope: ``pi d^2 / 4`` of its nominal diameter, or the metallic area given). A polyester
rope's curve is on the tension range over the rope's characteristic (minimum breaking) strength,
``N(R) = a_D R^-m`` with ``R = range / MBS``, ``a_D = 0.259``, ``m = 13.46`` (DNV-OS-E301 (2010) Ch.2 Sec.2
D, the polyester rope curve; the same numbers in DNVGL-OS-E301 (2015-2018) Ch.2 Sec.2 [6]).

Which curve a line takes: its line type's ``material`` (:data:`MATERIAL_CURVES`), chosen by the user; the
design tables (:mod:`seacable.design.summary`) tell it from the line type's name only where the name is not
ambiguous, and say so.

The design fatigue factor (:data:`DNV_DESIGN_FATIGUE_FACTOR`): DNV-OS-E301 (2010) Ch.2 Sec.2 D, the single
safety factor of the fatigue limit state, ``gamma_F = 5`` where the ratio of the characteristic damages of two
adjacent lines ``d_F <= 0.8``, rising linearly to 8 at ``d_F = 1`` (:func:`dnv_design_fatigue_factor`); the
standard gives it for both consequence classes, for lines that are not inspected in service (the
check's premise: the life is not extended by inspection). API RP 2SK (3rd ed., 2005) asks for a fatigue
life of 3 times the service life for lines inspected regularly, 10 for those not inspected.
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

__all__ = ["DNV_DESIGN_FATIGUE_FACTOR", "MATERIAL_CURVES", "SECONDS_PER_YEAR", "TN_CURVES", "TNCurve",
           "curve_of_line_type", "dnv_design_fatigue_factor", "fatigue_damage", "fatigue_life", "narrow_band_damage",
           "nominal_area", "resolve_tn_curve", "tension_cycles"]

SECONDS_PER_YEAR = 365.25 * 86400.0
_EDITION = "DNV-OS-E301 (October 2010) Ch.2 Sec.2 Table D1"


@dataclass(frozen=True)
class TNCurve:
    """A T-N curve ``N = a_D s^-m``: ``a_D`` the intercept [MPa^m, or 1 for a ratio], ``m`` the slope, ``bars``
    the bars of the nominal cross-section (2 for a chain link, 1 for a rope, 0 for a curve on the ratio to
    the breaking strength), ``reference`` the table, ``basis`` what ``s`` is: ``"stress"`` the nominal stress
    range [MPa], ``"mbs_ratio"`` the tension range over the breaking strength [-] (a fibre rope)."""

    name: str
    a_d: float
    m: float
    bars: int
    reference: str = _EDITION
    basis: str = "stress"

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
    "polyester_rope": TNCurve("polyester rope", 0.259, 13.46, 0,
                              "DNV-OS-E301 (2010) Ch.2 Sec.2 D (polyester rope, R = range / MBS)", "mbs_ratio"),
}

#: The T-N curve of each ``LineType.material`` (:class:`seacable.line.LineType`); None: no curve of the
#: standard (a power cable, an umbilical, a rope of another fibre), fatigue not computed.
MATERIAL_CURVES: dict[str, str | None] = {
    "studless_chain": "studless_chain",
    "stud_chain": "stud_chain",
    "six_strand_rope": "six_strand_rope",
    "spiral_strand_rope": "spiral_strand_rope",
    "polyester_rope": "polyester_rope",
    "other": None,
}

#: DNV-OS-E301 (2010) Ch.2 Sec.2 D: the design fatigue factor gamma_F where the damage ratio of adjacent
#: lines d_F <= 0.8 (either consequence class). [-]
DNV_DESIGN_FATIGUE_FACTOR = 5.0


#: Words of a line type's name that tell its T-N curve alone (the name split at anything but letters and
#: digits, lower case): a name holding words of one curve only tells it.
_NAME_WORDS = {"studless": "studless_chain", "studlink": "stud_chain", "spiral": "spiral_strand_rope",
               "iwrc": "six_strand_rope", "polyester": "polyester_rope"}
#: Words that say what the line is but not which curve: chain (studless or stud link, a_D differs by 2), wire
#: rope (six strand or spiral strand, lives orders of magnitude apart).
_AMBIGUOUS_WORDS = {"chain": "studless or stud-link chain", "wire": "six-strand or spiral-strand wire rope",
                    "rope": "a wire (six or spiral strand) or fibre rope", "strand": "six- or spiral-strand wire rope"}


def curve_of_line_type(material: str | None, name: str | None) -> tuple[str | None, str]:
    """The T-N curve (a key of :data:`TN_CURVES`) of a line type, and how it was chosen or why none was: its
    ``material`` (:data:`MATERIAL_CURVES`), else its ``name`` where the name tells one curve only
    ("studless_chain", "r3_studlink", "spiral_strand_127", "polyester"), else None with the reason: a name
    that could be two curves ("chain": studless or stud link; "wire": six or spiral strand) is refused, never
    guessed."""
    if material is not None:
        if material not in MATERIAL_CURVES:
            return None, (f"line type '{name}' has material '{material}', not one of "
                          f"{', '.join(MATERIAL_CURVES)}")
        curve = MATERIAL_CURVES[material]
        if curve is None:
            return None, (f"line type '{name}' has material 'other': DNV-OS-E301 gives it no T-N curve; give "
                          "--tn-curve if one applies")
        return curve, f"the line type's material ({material})"
    text = (name or "").lower()
    words = set("".join(ch if ch.isalnum() else " " for ch in text).split())
    if "stud" in words and "link" in words:
        words.add("studlink")
    if "six" in words and "strand" in words:
        words.add("iwrc")
    if "spiral" in words or "iwrc" in words:
        words -= {"wire", "rope", "strand"}
    if words & {"studless", "studlink"}:
        words.discard("chain")
    if "polyester" in words:
        words.discard("rope")
    curves = {_NAME_WORDS[w] for w in words if w in _NAME_WORDS}
    if len(curves) == 1:
        return curves.pop(), f"the line type's name '{name}' (no material given)"
    fix = ("set line_types.<type>.material (studless_chain, stud_chain, six_strand_rope, spiral_strand_rope, "
           "polyester_rope or other), or give --tn-curve")
    if len(curves) > 1:
        return None, f"line type '{name}' names {' and '.join(sorted(curves))}: ambiguous; {fix}"
    vague = [_AMBIGUOUS_WORDS[w] for w in sorted(words) if w in _AMBIGUOUS_WORDS]
    if vague:
        return None, f"line type '{name}' could be {vague[0]}: ambiguous, not guessed; {fix}"
    return None, f"line type '{name or 'unknown'}' says nothing of its material; {fix}"


def resolve_tn_curve(name: str) -> str:
    """The key of :data:`~seacable.design.TN_CURVES` a name stands for: the key itself, its first word
    ("studless", "stud", "six", "spiral", "connecting") or a prefix of one key ("six_strand")."""
    text = str(name).strip().lower().replace("-", "_").replace(" ", "_")
    if text in TN_CURVES:
        return text
    hits = [k for k in TN_CURVES if k.split("_")[0] == text] or [
        k for k in TN_CURVES if k.startswith(text)]
    if len(hits) != 1:
        raise InputError(f"T-N curve '{name}' is not one of {', '.join(TN_CURVES)} (DNV-OS-E301 (2010) "
                         "Ch.2 Sec.2 Table D1). Suggested fix: e.g. --tn-curve studless.")
    return hits[0]


def dnv_design_fatigue_factor(damage_ratio: float = 0.0) -> float:
    """DNV-OS-E301 (2010) Ch.2 Sec.2 D's design fatigue factor ``gamma_F``: 5 where the ratio ``d_F`` of the
    characteristic fatigue damages of two adjacent lines (the smaller over the larger) is <= 0.8, else
    ``5 + 3 (d_F - 0.8) / 0.2`` (8 at ``d_F = 1``: two lines as likely to fail together). [-]"""
    d = float(v.nonnegative("damage_ratio", damage_ratio, "", "give the smaller over the larger damage, 0 to 1"))
    if d > 1.0:
        raise InputError(f"damage_ratio d_F must lie between 0 and 1 (the smaller of two adjacent lines' damages "
                         f"over the larger), got {d:g}. Suggested fix: divide the smaller damage by the larger.")
    return DNV_DESIGN_FATIGUE_FACTOR if d <= 0.8 else DNV_DESIGN_FATIGUE_FACTOR + 3.0 * (d - 0.8) / 0.2


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
    c = _curve(curve)
    if c.basis != "stress":
        raise InputError(f"the {c.name} T-N curve is on the tension range over the breaking strength, not on a "
                         "stress: it has no nominal area. Suggested fix: give breaking_load [N] instead.")
    return c.bars * math.pi * d * d / 4.0


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


def _scale(curve: TNCurve, diameter, area, breaking_load) -> float:
    """What a tension range [N] is divided by to give the curve's ``s``: the nominal area in mm^2 (MPa), or
    the breaking strength [N] (a ratio)."""
    if curve.basis == "mbs_ratio":
        if breaking_load is None:
            raise InputError(f"the {curve.name} T-N curve ({curve.reference}) is on the tension range over the "
                             "breaking strength: give breaking_load [N]. Suggested fix: breaking_load=the rope's "
                             "minimum breaking strength in N.")
        return float(v.positive("breaking_load", breaking_load, "N", "give the minimum breaking strength in N"))
    return _area(curve, diameter, area) * 1e6


def _area(curve: TNCurve, diameter, area) -> float:
    if (diameter is None) == (area is None):
        raise InputError("give either the nominal diameter (m) or the nominal area (m^2) of the component, not "
                         f"{'both' if area is not None else 'neither'}. Suggested fix: diameter=0.09 for a 90 mm "
                         "chain.")
    if area is not None:
        return float(v.positive("area", area, "m^2", "give the nominal cross-section in m^2"))
    return nominal_area(curve, diameter)


def fatigue_damage(tension, curve="studless_chain", *, diameter: float | None = None,
                   area: float | None = None, breaking_load: float | None = None) -> float:
    """Miner's damage of a tension record [N]: sum over its rainflow cycles of ``n_i / N(s_i)``, with
    ``s_i`` = range / area in MPa and ``N`` the T-N curve (a name of :data:`TN_CURVES` or a :class:`TNCurve`);
    the area from the nominal ``diameter`` [m] (:func:`nominal_area`) or given as ``area`` [m^2]; a curve on
    the ratio to the breaking strength (polyester) takes ``s_i`` = range / ``breaking_load`` [N]. [1]"""
    c = _curve(curve)
    scale = _scale(c, diameter, area, breaking_load)
    ranges, counts = tension_cycles(tension)
    with np.errstate(divide="ignore"):  # a zero range: infinitely many cycles to failure, no damage
        return float(np.sum(counts / c.cycles_to_failure(ranges / scale)))  # stress ranges [MPa] or ratios


def narrow_band_damage(m0: float, zero_upcrossing_rate: float, duration: float, curve="studless_chain", *,
                       diameter: float | None = None, area: float | None = None,
                       breaking_load: float | None = None) -> float:
    """Damage of a narrow-band Gaussian tension process of variance ``m0`` [N^2] and mean zero-upcrossing
    rate ``nu0`` [1/s] over ``duration`` [s], in closed form: its ranges are twice its Rayleigh envelope,
    D = nu0 T / a_D (2 sqrt(2 m0_s))^m Gamma(1 + m/2), with m0_s the variance of the stress [MPa^2]. [1]"""
    c = _curve(curve)
    scale = _scale(c, diameter, area, breaking_load)
    m0 = float(v.nonnegative("m0", m0, "N^2", "give the variance of the tension"))
    nu0 = float(v.nonnegative("zero_upcrossing_rate", zero_upcrossing_rate, "1/s", "give sqrt(m2/m0)/(2 pi)"))
    duration = float(v.nonnegative("duration", duration, "s", "give the exposure time in s"))
    sigma = math.sqrt(m0) / scale  # [MPa], or a ratio
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


def fatigue_life(damage, duration, probability, *,
                 design_fatigue_factor: float = DNV_DESIGN_FATIGUE_FACTOR) -> float:
    """Fatigue life [years] over a scatter diagram: each sea state's ``damage`` [1] over its simulated
    ``duration`` [s], weighted by its ``probability`` of occurrence (they sum to 1), gives the damage per
    year; the life is its inverse over the design fatigue factor, by default DNV-OS-E301 (2010) Ch.2 Sec.2 D's
    5 (:data:`DNV_DESIGN_FATIGUE_FACTOR`; :func:`dnv_design_fatigue_factor` for adjacent lines of similar
    damage; API RP 2SK: 3 for lines inspected regularly, 10 otherwise). [years]"""
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
    dff = float(v.at_least("design_fatigue_factor", design_fatigue_factor, 1.0, "", "give 1 or more (DNV-OS-E301: 5 to 8; API RP 2SK: 3 or 10)"))
    per_year = float(np.sum(p * d / t)) * SECONDS_PER_YEAR
    return math.inf if per_year == 0.0 else 1.0 / (per_year * dff)

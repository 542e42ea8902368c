"""Design checks of a mooring (issue 20): line tension against the breaking strength by DNV-OS-E301 and by
API RP 2SK, anchor uplift and offset, each one :class:`CheckResult` with its demand, capacity, margin
(capacity - demand, in the check's own unit: N or m), pass (margin >= 0) and utilisation (demand / capacity,
only where the capacity is positive: a zero capacity, a drag anchor's allowed uplift, has no ratio);
:func:`check_table` puts them in a table. Every number of a check is finite: a check is made by one function,
:func:`_result`, for every kind.

- DNV-OS-E301 *Position mooring* (October 2010), Ch.2 Sec.2 (the design of mooring lines; the edition of
  the T-N curves in :mod:`seacable.design.fatigue`). The characteristic capacity of a line of new chain or
  steel wire rope is ``S_C = 0.95 S_mbs``, ``S_mbs`` its minimum breaking strength; the design tension is
  ``T_d = gamma_mean T_c,mean + gamma_dyn T_c,dyn`` (``T_c,mean`` the mean tension from pretension and the
  mean environmental loads, ``T_c,dyn`` the characteristic dynamic tension, the storm maximum less the
  mean); the line passes when ``T_d <= S_C``. Partial safety factors, from the standard's tables for the
  ULS (intact system, dynamic analysis) and the ALS (after one line has failed):

  =====  =====================  ==========  =========
  limit  consequence class      gamma_mean  gamma_dyn
  =====  =====================  ==========  =========
  ULS    1                      1.10        1.50
  ULS    2                      1.40        2.10
  ALS    1                      1.00        1.10
  ALS    2                      1.00        1.25
  =====  =====================  ==========  =========

  Consequence class 1: a mooring failure is unlikely to lead to unacceptable consequences (loss of life,
  collision with an adjacent installation, uncontrolled outflow of oil or gas, capsize or sinking); class 2:
  it may well lead to them. The ULS factors are those for a dynamic analysis of the line tension (the
  standard gives others for a quasi-static one, not implemented here).
- API RP 2SK *Design and Analysis of Stationkeeping Systems for Floating Structures*, 3rd edition (October
  2005), the design criteria's table of line tension limits and factors of safety (Table 2): ``T_max <= MBS / FoS``, with

  =========  ====================  ====================
  condition  quasi-static          dynamic
  =========  ====================  ====================
  intact     2.00 (50 % of MBS)    1.67 (60 % of MBS)
  damaged    1.43 (70 % of MBS)    1.25 (80 % of MBS)
  transient  1.18 (85 % of MBS)    1.05 (95 % of MBS)
  =========  ====================  ====================

  "damaged" is the system with one line broken, "transient" the motion that follows the break.
- Anchor uplift: a drag anchor takes no upward pull in the intact condition (API RP 2SK 3rd ed., anchor
  design; DNV-OS-E301 (2010) Ch.2 Sec.4, fluke anchors), so the default allowed uplift is 0 N; another anchor (a pile, a
  suction anchor) takes the allowed uplift of its design. A computed upward pull no larger than
  :data:`UPLIFT_ROUND_OFF` (1e-3) times the larger of the line's tension at the anchor (a line meeting the seabed
  within 0.057 deg of flat) and the line's submerged weight (a slack grounded line, whose anchor tension may be
  near zero), is round-off, not uplift (:func:`uplift_demand`).
- Offset: the largest horizontal offset of a body against the limit set by its risers, gangway or
  umbilicals (a project value, not a code's).

Verification of the factors (issue 20): the values above were checked against an independent
implementation of the same checks (the ``cabledyn`` package's tension check, which gives the identical
API RP 2SK and DNV-OS-E301 factors and ``S_C = 0.95 S_mbs``) and, for API's intact and damaged dynamic
factors 1.67 and 1.25 (60 % and 80 % of MBS), a SNAME TOS 2018 paper on mooring factors of safety. The
standards' own pages could not be read from the sources available, so the table numbers (DNV-OS-E301 (2010)
Ch.2 Sec.2, the ULS and ALS partial safety factor tables; API RP 2SK Table 2; the anchor clauses) and whether the later
DNVGL-OS-E301 (2015, 2018) and DNV-OS-E301 (2021) editions keep the same numbers are not verified: check
them against the edition a project is designed to.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, fields
from typing import Literal

import numpy as np

from .. import _validate as v
from ..errors import InputError

__all__ = ["API_FACTORS_OF_SAFETY", "DNV_PARTIAL_SAFETY_FACTORS", "DNV_STRENGTH_FACTOR", "UPLIFT_ROUND_OFF",
           "CheckResult", "anchor_uplift", "api_tension", "check_table", "dnv_als", "dnv_uls", "offset_check",
           "uplift_demand"]

DNV_EDITION = "DNV-OS-E301 (October 2010)"
API_EDITION = "API RP 2SK 3rd edition (October 2005)"

#: DNV-OS-E301 (2010) Ch.2 Sec.2: the characteristic capacity of new chain or steel wire rope, S_C = 0.95 S_mbs.
DNV_STRENGTH_FACTOR = 0.95

#: DNV-OS-E301 (2010) Ch.2 Sec.2 partial safety factors, ``(limit state, consequence class) ->
#: (gamma_mean, gamma_dyn)``: ULS (intact, dynamic analysis) and ALS (one line failed).
DNV_PARTIAL_SAFETY_FACTORS: dict[tuple[str, int], tuple[float, float]] = {
    ("ULS", 1): (1.10, 1.50),
    ("ULS", 2): (1.40, 2.10),
    ("ALS", 1): (1.00, 1.10),
    ("ALS", 2): (1.00, 1.25),
}

#: API RP 2SK (3rd ed., 2005) factors of safety on the line tension, ``(condition, method) -> FoS``.
API_FACTORS_OF_SAFETY: dict[tuple[str, str], float] = {
    ("intact", "quasi_static"): 2.00,
    ("intact", "dynamic"): 1.67,
    ("damaged", "quasi_static"): 1.43,
    ("damaged", "dynamic"): 1.25,
    ("transient", "quasi_static"): 1.18,
    ("transient", "dynamic"): 1.05,
}

_CONDITIONS = ("intact", "damaged", "transient")
_METHODS = ("dynamic", "quasi_static")
_LIMIT_STATE = {"ULS": "ULS, intact system, dynamic analysis", "ALS": "ALS, one line failed"}


#: A computed upward pull on an anchor no larger than this share of the line's tension there is round-off,
#: not uplift: the pull of a line meeting the seabed within 1e-3 rad (0.057 deg) of flat. Below it the sign of
#: the first element's slope is set by the seabed contact's penetration and the solver's tolerance, not by the
#: mooring (the OC3-Hywind demo's grounded lines show 35 N under several hundred kN, a few 1e-5 of the
#: tension); a line that lifts off its anchor pulls up with the weight of the lifted length, kN per metre of
#: chain, far above it. [-]
UPLIFT_ROUND_OFF = 1e-3

_UNITS = ("N", "m")


@dataclass(frozen=True)
class CheckResult:
    """One design check: a demand against a capacity, in one unit.

    Attributes
    ----------
    check
        The check, e.g. ``"DNV-OS-E301 ULS CC1"``, ``"API RP 2SK intact dynamic"``, ``"anchor uplift"``,
        ``"offset"``.
    item
        What is checked: a line, an anchor, a body.
    unit
        The unit of demand, capacity and margin: ``"N"`` or ``"m"``.
    demand
        The design value compared with the capacity: design tension [N], uplift force [N] or offset [m].
    capacity
        The capacity: ``S_C`` [N], ``MBS / FoS`` [N], the allowed uplift [N] or the offset limit [m].
    margin
        ``capacity - demand``, in ``unit``: what is left, negative when the check fails. Finite.
    utilisation
        ``demand / capacity`` [-] where the capacity is positive; None where it is zero (a drag anchor's
        allowed uplift: no ratio, the margin says it).
    passed
        ``demand <= capacity`` (margin >= 0).
    formula
        The check's formula with its factors, one line.
    reference
        The standard, edition, section and table.
    """

    check: str
    item: str
    unit: str
    demand: float
    capacity: float
    margin: float
    utilisation: float | None
    passed: bool
    formula: str
    reference: str


def _result(check, item, demand, capacity, unit, formula, reference) -> CheckResult:
    """The one way a check is made: margin ``capacity - demand`` in the check's unit, pass ``margin >= 0``,
    utilisation ``demand / capacity`` only for a positive capacity; every number finite."""
    demand, capacity = float(demand), float(capacity)
    if unit not in _UNITS or not (math.isfinite(demand) and math.isfinite(capacity)) or capacity < 0.0:
        raise InputError(f"check '{check}' of '{item}': demand {demand!r} {unit} and capacity {capacity!r} {unit} must "
                         f"be finite numbers in {' or '.join(_UNITS)}, the capacity >= 0. Suggested fix: check the "
                         "inputs of the check (tensions, breaking load, limits).")
    margin = capacity - demand
    return CheckResult(check=check, item=str(item), unit=unit, demand=demand, capacity=capacity, margin=margin,
                       utilisation=demand / capacity if capacity > 0.0 else None, passed=bool(margin >= 0.0),
                       formula=formula, reference=reference)


def _scalar(name: str, value, unit: str, fix: str, *, check) -> float:
    """A finite scalar passing ``check`` (one of the _validate functions); arrays are refused."""
    if value is None or isinstance(value, bool) or np.ndim(value) != 0:
        raise InputError(f"{name} must be one number in {unit}, got {value!r}. Suggested fix: {fix}")
    return float(check(name, value, unit, fix))


def _mbs(line, mbs) -> float:
    """The minimum breaking strength [N], or the house-style refusal naming the line."""
    try:
        value = float(mbs) if not isinstance(mbs, bool) and np.ndim(mbs) == 0 else math.nan
    except (TypeError, ValueError):
        value = math.nan
    if not (math.isfinite(value) and value > 0.0):
        raise InputError(f"line '{line}' has no breaking_load: give the line type's breaking_load [N] (the minimum "
                         f"breaking strength, a finite number > 0 N; got {mbs!r}). Suggested fix: set breaking_load "
                         f"[N] on the line type from the chain's or rope's certificate or catalogue.")
    return value


def _tensions(line, mean_tension, dynamic_tension) -> tuple[float, float]:
    mean = _scalar(f"line '{line}' mean_tension", mean_tension, "N",
                   "give the mean tension T_c,mean [N] (pretension and mean loads, >= 0 N).", check=v.nonnegative)
    dyn = _scalar(f"line '{line}' dynamic_tension", dynamic_tension, "N",
                  "give the dynamic tension T_c,dyn [N]: the storm maximum less the mean, >= 0 N "
                  "(seacable.design.mean_and_dynamic).", check=v.nonnegative)
    return mean, dyn


def _consequence_class(consequence_class) -> int:
    if (isinstance(consequence_class, bool) or not isinstance(consequence_class, (int, np.integer))
            or consequence_class not in (1, 2)):
        raise InputError(f"consequence_class must be 1 or 2 ({DNV_EDITION} Ch.2 Sec.2), got {consequence_class!r}. "
                         "Suggested fix: 1 where a mooring failure is unlikely to lead to unacceptable consequences, "
                         "2 where it may well lead to loss of life, collision with an adjacent installation, outflow "
                         "of oil or gas, capsize or sinking.")
    return int(consequence_class)


def _dnv(limit: str, line, mean_tension, dynamic_tension, mbs, consequence_class) -> CheckResult:
    cc = _consequence_class(consequence_class)
    s_mbs = _mbs(line, mbs)
    mean, dyn = _tensions(line, mean_tension, dynamic_tension)
    g_mean, g_dyn = DNV_PARTIAL_SAFETY_FACTORS[(limit, cc)]
    t_d = g_mean * mean + g_dyn * dyn
    s_c = DNV_STRENGTH_FACTOR * s_mbs
    formula = (f"T_d = {g_mean:.2f} T_c,mean + {g_dyn:.2f} T_c,dyn <= S_C = {DNV_STRENGTH_FACTOR:.2f} MBS")
    reference = (f"{DNV_EDITION} Ch.2 Sec.2: partial safety factors for the {_LIMIT_STATE[limit]}, consequence "
                 f"class {cc}; S_C = 0.95 S_mbs (new chain or steel wire rope)")
    return _result(f"DNV-OS-E301 {limit} CC{cc}", line, t_d, s_c, "N", formula, reference)


def dnv_uls(line, mean_tension, dynamic_tension, mbs, consequence_class=1) -> CheckResult:
    """DNV-OS-E301 ultimate limit state of a line in the intact system (dynamic analysis).

    ``T_d = gamma_mean T_c,mean + gamma_dyn T_c,dyn <= S_C = 0.95 S_mbs``, utilisation ``T_d / S_C``, with
    ``(gamma_mean, gamma_dyn)`` = (1.10, 1.50) in consequence class 1 and (1.40, 2.10) in class 2
    (DNV-OS-E301 (October 2010) Ch.2 Sec.2).

    Parameters
    ----------
    line
        The line's name.
    mean_tension
        Characteristic mean tension ``T_c,mean``: pretension and mean environmental loads. [N]
    dynamic_tension
        Characteristic dynamic tension ``T_c,dyn``: the storm maximum less the mean. [N]
    mbs
        Minimum breaking strength ``S_mbs`` of the line (its line type's ``breaking_load``). [N]
    consequence_class
        1 or 2.

    Returns
    -------
    CheckResult
        Demand ``T_d`` [N], capacity ``S_C`` [N].

    Raises
    ------
    InputError
        No breaking strength (None, NaN, <= 0), a negative or NaN tension, a consequence class other than 1, 2.
    """
    return _dnv("ULS", line, mean_tension, dynamic_tension, mbs, consequence_class)


def dnv_als(line, mean_tension, dynamic_tension, mbs, consequence_class=1) -> CheckResult:
    """DNV-OS-E301 accidental limit state: a line of the system after one line has failed.

    ``T_d = gamma_mean T_c,mean + gamma_dyn T_c,dyn <= S_C = 0.95 S_mbs``, utilisation ``T_d / S_C``, with
    ``(gamma_mean, gamma_dyn)`` = (1.00, 1.10) in consequence class 1 and (1.00, 1.25) in class 2
    (DNV-OS-E301 (October 2010) Ch.2 Sec.2). The tensions are those of the damaged system.

    Parameters
    ----------
    line
        The line's name.
    mean_tension
        Characteristic mean tension ``T_c,mean`` with one line failed. [N]
    dynamic_tension
        Characteristic dynamic tension ``T_c,dyn`` with one line failed. [N]
    mbs
        Minimum breaking strength ``S_mbs`` of the line. [N]
    consequence_class
        1 or 2.

    Returns
    -------
    CheckResult
        Demand ``T_d`` [N], capacity ``S_C`` [N].

    Raises
    ------
    InputError
        As :func:`dnv_uls`.
    """
    return _dnv("ALS", line, mean_tension, dynamic_tension, mbs, consequence_class)


def api_tension(line, max_tension, mbs, condition: Literal["intact", "damaged", "transient"] = "intact",
                method: Literal["dynamic", "quasi_static"] = "dynamic") -> CheckResult:
    """API RP 2SK line tension limit: ``T_max <= MBS / FoS``, utilisation ``T_max FoS / MBS``.

    FoS (API RP 2SK 3rd ed. (2005), Table 2), quasi-static / dynamic analysis: intact 2.00 / 1.67,
    damaged (one line broken) 1.43 / 1.25, transient (after the break) 1.18 / 1.05.

    Parameters
    ----------
    line
        The line's name.
    max_tension
        The largest line tension of the condition. [N]
    mbs
        Minimum breaking strength of the line. [N]
    condition
        ``"intact"``, ``"damaged"`` or ``"transient"``.
    method
        ``"dynamic"`` or ``"quasi_static"``: how the tension was analysed.

    Returns
    -------
    CheckResult
        Demand ``T_max`` [N], capacity ``MBS / FoS`` [N].

    Raises
    ------
    InputError
        No breaking strength, a negative or NaN tension, an unknown condition or method.
    """
    condition = v.one_of("condition", condition, _CONDITIONS)
    method = v.one_of("method", method, _METHODS)
    s_mbs = _mbs(line, mbs)
    t_max = _scalar(f"line '{line}' max_tension", max_tension, "N",
                    "give the largest tension of the line in this condition [N], >= 0 N.", check=v.nonnegative)
    fos = API_FACTORS_OF_SAFETY[(condition, method)]
    capacity = s_mbs / fos
    words = method.replace("_", "-")
    return _result(f"API RP 2SK {condition} {words}", line, t_max, capacity, "N",
                   f"T_max <= MBS / {fos:.2f} ({100.0 / fos:.0f} % of MBS)",
                   f"{API_EDITION} Table 2: line tension limits and factors of safety, {condition} "
                   f"condition, {words} analysis (FoS {fos:.2f})")


def uplift_demand(vertical_force, tension, weight=0.0):
    """The uplift a vertical force on an anchor is: ``F_z`` where ``F_z > UPLIFT_ROUND_OFF * max(T, W)``, else 0
    (a downward pull, or an upward one of round-off size: :data:`UPLIFT_ROUND_OFF`). Vectorised. [N]

    Parameters
    ----------
    vertical_force
        Vertical force of the line on its anchor, upward positive. [N]
    tension
        The line's tension at the anchor at the same instant (NaN or missing: 0). [N]
    weight
        The line's submerged weight ``W``, its weight in water per metre times its length (0: unknown): the
        tolerance's scale where the anchor tension is near zero (a slack line lying on the seabed). [N]
    """
    f_z = np.asarray(vertical_force, float)
    t = np.nan_to_num(np.abs(np.asarray(tension, float)), nan=0.0)
    w = float(np.nan_to_num(abs(float(weight)), nan=0.0))
    return np.where(f_z > UPLIFT_ROUND_OFF * np.maximum(t, w), f_z, 0.0)


def anchor_uplift(anchor, vertical_force, allowed=0.0, tension=0.0, weight=0.0) -> CheckResult:
    """Anchor uplift: the largest upward pull on the anchor against the allowed uplift.

    ``F_up <= F_allowed``, ``F_up`` the upward vertical force ``F_z`` less round-off (:func:`uplift_demand`: an
    ``F_z`` no larger than ``UPLIFT_ROUND_OFF = 1e-3`` times the larger of the anchor tension ``T`` and the line's
    submerged weight ``W`` is none), the margin
    ``F_allowed - F_up`` [N]. With ``F_allowed = 0`` (the default: a drag anchor takes no uplift in the intact
    condition, API RP 2SK 3rd ed., DNV-OS-E301 (2010) Ch.2 Sec.4) the check passes only without uplift, with a
    margin of 0 N, and has no utilisation (no ratio to a zero capacity); with ``F_allowed > 0`` the utilisation
    is ``F_up / F_allowed``.

    Parameters
    ----------
    anchor
        The anchor's name.
    vertical_force
        The largest upward (positive) vertical force of the line on the anchor; a downward pull (negative) is no
        uplift. [N]
    allowed
        The uplift the anchor may take, >= 0. [N]
    tension
        The line's tension at the anchor when ``vertical_force`` acts, >= 0. [N]
    weight
        The line's submerged weight, >= 0 (0: unknown; with ``tension`` 0, no round-off tolerance). [N]

    Returns
    -------
    CheckResult
        Demand ``F_up`` [N], capacity ``F_allowed`` [N], margin [N].

    Raises
    ------
    InputError
        A NaN force, a negative or NaN allowed uplift or tension.
    """
    f_z = _scalar(f"anchor '{anchor}' vertical_force", vertical_force, "N",
                  "give the largest upward vertical force of the line on the anchor [N].", check=v.finite)
    cap = _scalar(f"anchor '{anchor}' allowed uplift", allowed, "N",
                  "0 N for a drag anchor; the design uplift capacity of a pile or suction anchor [N].",
                  check=v.nonnegative)
    t = _scalar(f"anchor '{anchor}' tension", tension, "N",
                "give the line's tension at the anchor [N], >= 0 N (0: no round-off tolerance).", check=v.nonnegative)
    w = _scalar(f"anchor '{anchor}' line weight", weight, "N",
                "give the line's submerged weight [N], >= 0 N (0: unknown).", check=v.nonnegative)
    up = float(uplift_demand(f_z, t, w))
    reference = (f"{API_EDITION} (anchor design) and {DNV_EDITION} Ch.2 Sec.4: no uplift on a drag anchor in the intact "
                 "condition" if cap == 0.0 else "the anchor's design uplift capacity")
    return _result("anchor uplift", anchor, up, cap, "N",
                   f"F_up <= {cap:.6g} N (F_up = F_z where F_z > {UPLIFT_ROUND_OFF:g} T_anchor, or {UPLIFT_ROUND_OFF:g} "
                   "W_line if larger: less is round-off)",
                   reference)


def offset_check(body, offset, limit) -> CheckResult:
    """A body's offset against its limit: ``offset <= limit``, utilisation ``offset / limit``.

    Parameters
    ----------
    body
        The body's name.
    offset
        The largest horizontal offset from the body's neutral position, >= 0. [m]
    limit
        The allowed offset (set by risers, umbilicals, a gangway), > 0. [m]

    Returns
    -------
    CheckResult
        Demand the offset [m], capacity the limit [m].

    Raises
    ------
    InputError
        A negative or NaN offset, a limit not > 0.
    """
    off = _scalar(f"body '{body}' offset", offset, "m",
                  "give the largest horizontal offset from the neutral position [m], >= 0 m.", check=v.nonnegative)
    lim = _scalar(f"body '{body}' offset limit", limit, "m",
                  "give the allowed offset [m] (from the risers', umbilicals' or gangway's design), > 0 m.",
                  check=v.positive)
    return _result("offset", body, off, lim, "m", f"offset <= {lim:.6g} m",
                   "project offset limit (risers, umbilicals, gangway)")


_COLUMNS = ("check", "item", "unit", "demand", "capacity", "margin", "utilisation", "passed", "formula",
            "reference")


def check_table(results: Iterable[CheckResult]):
    """The checks as a table: one row per :class:`CheckResult`, in the given order.

    Parameters
    ----------
    results
        The checks.

    Returns
    -------
    pandas.DataFrame
        Columns check, item, unit, demand, capacity, margin (in the row's unit: N or m), utilisation (NaN where
        the capacity is zero), passed, formula, reference.

    Raises
    ------
    InputError
        An entry that is not a CheckResult.
    """
    import pandas as pd

    rows = []
    for i, r in enumerate(results):
        if not isinstance(r, CheckResult):
            raise InputError(f"results[{i}] must be a CheckResult, got {type(r).__name__}. Suggested fix: pass "
                             "what dnv_uls, dnv_als, api_tension, anchor_uplift or offset_check return.")
        row = {f.name: getattr(r, f.name) for f in fields(r)}
        row["utilisation"] = math.nan if r.utilisation is None else r.utilisation
        rows.append(row)
    return pd.DataFrame(rows, columns=list(_COLUMNS))

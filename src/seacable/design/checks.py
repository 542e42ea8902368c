"""Design checks of a mooring (issue 20): line tension against the breaking strength by DNV-OS-E301 and by
API RP 2SK, anchor uplift and offset, each one :class:`CheckResult` with its demand, capacity, utilisation
(demand / capacity), pass (utilisation <= 1) and margin (1 - utilisation); :func:`check_table` puts them in
a table.

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
  suction anchor) takes the allowed uplift of its design.
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

__all__ = ["API_FACTORS_OF_SAFETY", "DNV_PARTIAL_SAFETY_FACTORS", "DNV_STRENGTH_FACTOR", "CheckResult",
           "anchor_uplift", "api_tension", "check_table", "dnv_als", "dnv_uls", "offset_check"]

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


@dataclass(frozen=True)
class CheckResult:
    """One design check: a demand against a capacity.

    Attributes
    ----------
    check
        The check, e.g. ``"DNV-OS-E301 ULS CC1"``, ``"API RP 2SK intact dynamic"``, ``"anchor uplift"``,
        ``"offset"``.
    item
        What is checked: a line, an anchor, a body.
    demand
        The design value compared with the capacity: design tension [N], uplift force [N] or offset [m].
    capacity
        The capacity: ``S_C`` [N], ``MBS / FoS`` [N], the allowed uplift [N] or the offset limit [m].
    utilisation
        ``demand / capacity``. [-]
    passed
        ``utilisation <= 1``.
    formula
        The check's formula with its factors, one line.
    reference
        The standard, edition, section and table.
    """

    check: str
    item: str
    demand: float
    capacity: float
    utilisation: float
    passed: bool
    formula: str
    reference: str

    @property
    def margin(self) -> float:
        """``1 - utilisation``: the share of the capacity left, negative when the check fails. [-]"""
        return 1.0 - self.utilisation


def _result(check, item, demand, capacity, utilisation, formula, reference) -> CheckResult:
    return CheckResult(check=check, item=str(item), demand=float(demand), capacity=float(capacity),
                       utilisation=float(utilisation), passed=bool(utilisation <= 1.0), formula=formula,
                       reference=reference)


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
    return _result(f"DNV-OS-E301 {limit} CC{cc}", line, t_d, s_c, t_d / s_c, formula, reference)


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
    return _result(f"API RP 2SK {condition} {words}", line, t_max, capacity, t_max / capacity,
                   f"T_max <= MBS / {fos:.2f} ({100.0 / fos:.0f} % of MBS)",
                   f"{API_EDITION} Table 2: line tension limits and factors of safety, {condition} "
                   f"condition, {words} analysis (FoS {fos:.2f})")


def anchor_uplift(anchor, vertical_force, allowed=0.0) -> CheckResult:
    """Anchor uplift: the largest upward pull on the anchor against the allowed uplift.

    ``F_up = max(F_z, 0) <= F_allowed``. With ``F_allowed > 0`` the utilisation is ``F_up / F_allowed``. With
    ``F_allowed = 0`` (the default: a drag anchor takes no uplift in the intact condition, API RP 2SK 3rd ed.,
    DNV-OS-E301 (2010) Ch.2 Sec.4) the check passes only when there is no upward pull at all, and the
    utilisation is 0 without uplift and ``inf`` with any (there is no finite ratio to a zero capacity); to
    absorb a solver's noise give a small ``allowed`` instead.

    Parameters
    ----------
    anchor
        The anchor's name.
    vertical_force
        The largest upward (positive) vertical force of the line on the anchor; a downward pull (negative) is no
        uplift. [N]
    allowed
        The uplift the anchor may take, >= 0. [N]

    Returns
    -------
    CheckResult
        Demand ``F_up`` [N], capacity ``F_allowed`` [N].

    Raises
    ------
    InputError
        A NaN force, a negative or NaN allowed uplift.
    """
    f_z = _scalar(f"anchor '{anchor}' vertical_force", vertical_force, "N",
                  "give the largest upward vertical force of the line on the anchor [N].", check=v.finite)
    cap = _scalar(f"anchor '{anchor}' allowed uplift", allowed, "N",
                  "0 N for a drag anchor; the design uplift capacity of a pile or suction anchor [N].",
                  check=v.nonnegative)
    up = max(f_z, 0.0)
    utilisation = up / cap if cap > 0.0 else (0.0 if up == 0.0 else math.inf)
    reference = (f"{API_EDITION} (anchor design) and {DNV_EDITION} Ch.2 Sec.4: no uplift on a drag anchor in the intact "
                 "condition" if cap == 0.0 else "the anchor's design uplift capacity")
    return _result("anchor uplift", anchor, up, cap, utilisation, f"F_up = max(F_z, 0) <= {cap:.6g} N", reference)


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
    return _result("offset", body, off, lim, off / lim, f"offset <= {lim:.6g} m",
                   "project offset limit (risers, umbilicals, gangway)")


_COLUMNS = ("check", "item", "demand", "capacity", "utilisation", "margin", "passed", "formula", "reference")


def check_table(results: Iterable[CheckResult]):
    """The checks as a table: one row per :class:`CheckResult`, in the given order.

    Parameters
    ----------
    results
        The checks.

    Returns
    -------
    pandas.DataFrame
        Columns check, item, demand, capacity, utilisation, margin, passed, formula, reference (demand and
        capacity in the check's units: N or m).

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
        row["margin"] = r.margin
        rows.append(row)
    return pd.DataFrame(rows, columns=list(_COLUMNS))

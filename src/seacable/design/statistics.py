"""Extreme statistics of a response (issue 20): the storm maximum from the maxima of several seeds (a
Gumbel fit) or from the peaks of one record (a Weibull fit), and the mean and dynamic parts.

- Over seeds: the maxima of independent realisations of one sea state follow, for many cycles, the Gumbel
  (type I extreme value) distribution F(x) = exp(-exp(-(x - mu)/beta)), fitted by maximum likelihood
  (``scipy.stats.gumbel_r``). The most probable maximum (MPM) is its mode ``mu``; the quantile q of the storm
  maximum is ``mu - beta ln(-ln q)`` (DNV-OS-E301 (2010) Ch.2 Sec.2 B; DNV-RP-C205 (2021) 3.5.8).
- In one record: its peaks (the largest value between consecutive mean up-crossings) are fitted by a
  three-parameter Weibull distribution (``scipy.stats.weibull_min``); the largest of the ``N`` peaks of the
  storm (``N`` = peaks per second x the storm's duration) has the distribution F(x)^N: its mode, near
  F(x) = 1 - 1/N, is the MPM, and its quantile q is F^-1(q^(1/N)) (Naess & Moan 2013, Stochastic Dynamics
  of Marine Structures, ch. 6).

How many peaks a Weibull fit needs: the fit extrapolates from the record's peaks to the largest of the storm's,
and its tail is set by the few largest peaks. For a Gaussian response (Rayleigh peaks) raised to a 3-hour storm
of 1000 peaks, the 90 % band of the estimated MPM over independent records spans 0.73-1.58 times the true
value from 25 peaks, 0.83-1.33 from 50, 0.92-1.12 from 200 (tests/unit/design/test_statistics.py, which
checks these bands). So a record of fewer than :data:`MIN_PEAKS` (50) peaks is refused, and one of fewer than
:data:`RELIABLE_PEAKS` (200) is fitted but flagged (:attr:`StormMaximum.flag`): the design tables and the report
carry the flag (the OC3-Hywind demo's 300 s runs, a few tens of peaks, put one seed's 3-hour maximum anywhere
between 708 and 1800 kN).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np
from scipy import optimize, stats

from ..errors import InputError

__all__ = ["MIN_PEAKS", "RELIABLE_PEAKS", "StormMaximum", "gumbel_maximum", "mean_and_dynamic", "merged_notes",
           "peaks", "weibull_maximum"]

#: Fewest peaks of a record a Weibull fit takes: fewer are refused. [-]
MIN_PEAKS = 50
#: Fewest peaks of a record whose Weibull storm maximum is not flagged as uncertain. [-]
RELIABLE_PEAKS = 200


@dataclass(frozen=True)
class StormMaximum:
    """The most probable maximum and a quantile of a storm's maximum, with the fit behind them."""

    most_probable: float
    quantile: float
    probability: float  # the quantile's non-exceedance probability
    method: str
    parameters: dict
    flag: str = ""  # why the estimate is uncertain ("" when it is not): a fit on few peaks


def _finite(name: str, x, at_least: int) -> np.ndarray:
    a = np.asarray(x, float).ravel()
    if a.size < at_least or not np.all(np.isfinite(a)):
        raise InputError(f"{name} must hold at least {at_least} finite values, got {a.size} "
                         f"({int(np.sum(~np.isfinite(a)))} not finite). Suggested fix: run more seeds, or give "
                         "the records of completed runs.")
    return a


def _probability(q: float) -> float:
    if not 0.0 < q < 1.0:
        raise InputError(f"the quantile's probability must lie between 0 and 1, got {q}. Suggested fix: 0.9 for "
                         "the 90 % quantile of the storm maximum.")
    return float(q)


def gumbel_maximum(maxima, quantile: float = 0.9) -> StormMaximum:
    """The storm maximum from the maxima of several seeds (at least 5): a Gumbel fit by maximum likelihood;
    its mode (the MPM) and its ``quantile``."""
    x = _finite("the seeds' maxima", maxima, 5)
    q = _probability(quantile)
    mu, beta = stats.gumbel_r.fit(x)
    return StormMaximum(float(mu), float(mu - beta * math.log(-math.log(q))), q,
                        f"Gumbel fit (maximum likelihood) to the maxima of {x.size} seeds",
                        {"location": float(mu), "scale": float(beta), "seeds": int(x.size)})


def peaks(record) -> np.ndarray:
    """The peaks of a record: its largest value between consecutive up-crossings of its mean."""
    r = _finite("the record", record, 3)
    up = np.flatnonzero((r[:-1] < r.mean()) & (r[1:] >= r.mean())) + 1
    return np.maximum.reduceat(r, up)[:-1] if up.size > 1 else np.zeros(0)


def weibull_maximum(record, duration: float, storm: float | None = None, quantile: float = 0.9) -> StormMaximum:
    """The maximum of a storm of ``storm`` seconds (default: the record's ``duration`` [s]) from the peaks of
    one record: a three-parameter Weibull fit, raised to the storm's number of peaks. Fewer than
    :data:`MIN_PEAKS` peaks are refused; fewer than :data:`RELIABLE_PEAKS` give an estimate with a ``flag``."""
    p = peaks(record)
    if p.size < MIN_PEAKS:
        raise InputError(f"the record has {p.size} peaks (mean up-crossings), too few for a Weibull fit ({MIN_PEAKS} "
                         "at least: from fewer, the 90 % band of a 3-hour maximum spans a factor 2). Suggested fix: a "
                         "longer record, or the maxima of several seeds (gumbel_maximum).")
    if not duration > 0:
        raise InputError(f"the record's duration must be > 0 s, got {duration}. Suggested fix: give it in s.")
    q = _probability(quantile)
    n = p.size * (duration if storm is None else storm) / duration
    shape, loc, scale = stats.weibull_min.fit(p, loc=float(p.min()) - 1e-6 * float(np.ptp(p) or 1.0))
    dist = stats.weibull_min(shape, loc, scale)

    def density_of_max(x):  # d/dx F(x)^n, in logs
        return -(math.log(n) + (n - 1) * dist.logcdf(x) + dist.logpdf(x))

    mode = float(dist.ppf(1.0 - 1.0 / n))  # the mode of F^n, for many peaks
    if n > 10:  # the mode itself, between the values F reaches at 1 - 10/n and 1 - 0.1/n
        lo, hi = (float(dist.ppf(1.0 - k / n)) for k in (10.0, 0.1))
        mode = float(optimize.minimize_scalar(density_of_max, bounds=(lo, hi), method="bounded",
                                              options={"xatol": 1e-10 * (abs(hi) + 1.0)}).x)
    flag = "" if p.size >= RELIABLE_PEAKS else (
        f"uncertain: a Weibull fit to {p.size} peaks (fewer than {RELIABLE_PEAKS}) puts the storm maximum within "
        "about -20 % to +40 % (90 % band); run longer records or more seeds")
    return StormMaximum(mode, float(dist.ppf(q ** (1.0 / n))), q,
                        f"3-parameter Weibull fit to {p.size} peaks, {n:.4g} peaks in the storm",
                        {"shape": float(shape), "location": float(loc), "scale": float(scale), "peaks": int(p.size),
                         "storm_peaks": float(n)}, flag)


def merged_notes(texts) -> str:
    """One note for the seeds' notes of a Weibull fit (refusals or flags) that differ only in their numbers of
    peaks: "k seed(s): ... the record has 24-30 peaks ..."; other notes joined by "; ", each once."""
    texts = [str(t) for t in texts if isinstance(t, str) and t]
    shapes = list(dict.fromkeys(re.sub(r"\b\d+ peaks", "# peaks", t) for t in texts))
    counts = [int(m.group(1)) for t in texts if (m := re.search(r"\b(\d+) peaks", t))]
    if len(shapes) == 1 and len(counts) == len(texts) and len(texts) > 1:
        lo, hi = min(counts), max(counts)
        return f"{len(texts)} seeds: " + shapes[0].replace("# peaks", f"{lo}-{hi} peaks" if hi > lo else f"{lo} peaks")
    return "; ".join(dict.fromkeys(texts))


def mean_and_dynamic(record) -> tuple[float, float]:
    """The mean of a record and the standard deviation of its dynamic part."""
    r = _finite("the record", record, 2)
    return float(r.mean()), float(r.std())

"""Extreme statistics (issue 20): the storm maximum over seeds (Gumbel) and from one record's peaks (Weibull),
against the exact distribution of the largest of N Rayleigh peaks (the peaks of a narrow-band Gaussian
process of unit standard deviation): F_max(x) = (1 - exp(-x^2/2))^N."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scipy import optimize

from seacable.design.statistics import gumbel_maximum, mean_and_dynamic, peaks, weibull_maximum
from seacable.errors import InputError


def exact_maximum(n: int, q: float = 0.9) -> tuple[float, float]:
    """Mode and q-quantile of the largest of ``n`` unit Rayleigh variates (closed form for the quantile)."""
    def minus_log_density(x):
        return -(math.log(n) + (n - 1) * math.log1p(-math.exp(-x * x / 2)) + math.log(x) - x * x / 2)

    mode = optimize.minimize_scalar(minus_log_density, bounds=(1.0, 10.0), method="bounded",
                                    options={"xatol": 1e-12}).x
    return mode, math.sqrt(-2.0 * math.log(1.0 - q ** (1.0 / n)))


def test_gumbel_fit_over_seeds_gives_the_storm_maximum():
    """100 seeds of 1000 Rayleigh peaks: the Gumbel fit's mode and 90 % quantile are those of the exact
    distribution of the maximum, 3.737 and 4.280 (sqrt(2 ln N) = 3.717 is the asymptote). Six seeds of the
    whole draw gave 0.982-1.001 and 0.991-1.015 of them (the fit's sampling error over 100 maxima, about
    1.05 beta / sqrt(100) = 0.7 %, and the Gumbel form's asymptotic bias): bound 3 %."""
    mode, q90 = exact_maximum(1000)
    assert mode == pytest.approx(3.7368, abs=1e-4) and q90 == pytest.approx(4.2798, abs=1e-4)
    maxima = np.random.default_rng(0).rayleigh(1.0, (100, 1000)).max(axis=1)
    got = gumbel_maximum(maxima, quantile=0.9)
    assert got.most_probable == pytest.approx(mode, rel=0.03)
    assert got.quantile == pytest.approx(q90, rel=0.03)
    assert got.parameters["seeds"] == 100 and "Gumbel" in got.method


def test_weibull_fit_of_one_record_gives_the_storm_maximum():
    """One record of 20 000 cycles (every 10 s) whose peaks are unit Rayleigh: the Weibull fit has shape 2
    (the Rayleigh distribution; 1.986-2.008 over six seeds), and the maximum of a 3 h storm (1080 peaks) has
    the mode and 90 % quantile of the exact distribution: 0.997-1.007 of them over six seeds, bound 2 %."""
    rng = np.random.default_rng(1)
    record = np.ravel(np.column_stack([rng.rayleigh(1.0, 20000), -rng.rayleigh(1.0, 20000)]))
    got = weibull_maximum(record, duration=200_000.0, storm=10_800.0, quantile=0.9)
    mode, q90 = exact_maximum(1080)
    assert got.parameters["shape"] == pytest.approx(2.0, abs=0.05)
    assert got.parameters["storm_peaks"] == pytest.approx(1080.0, rel=1e-3)  # 19 998 whole peaks in the record
    assert got.most_probable == pytest.approx(mode, rel=0.02)
    assert got.quantile == pytest.approx(q90, rel=0.02)


def test_peaks_are_the_largest_values_between_mean_up_crossings():
    record = [0.0, 2.0, 1.0, 3.0, -1.0, -2.0, 4.0, 0.5, -3.0, 1.0, -1.0]  # mean 0.5: up at 1, 6, 9
    assert peaks(record).tolist() == [3.0, 4.0]
    assert mean_and_dynamic([1.0, 3.0]) == (2.0, 1.0)


@pytest.mark.parametrize("call, match", [
    (lambda: gumbel_maximum([1.0, 2.0, 3.0]), "at least 5 finite values, got 3"),
    (lambda: gumbel_maximum([1.0, 2.0, 3.0, 4.0, np.nan]), r"\(1 not finite\)"),
    (lambda: gumbel_maximum(np.arange(10.0), quantile=1.0), "between 0 and 1, got 1.0"),
    (lambda: weibull_maximum(np.sin(np.arange(100.0)), duration=100.0), "peaks .* too few for a Weibull fit"),
])
def test_bad_statistics_input_is_refused_clearly(call, match):
    with pytest.raises(InputError, match=match):
        call()


def _spread_of_weibull_mpm(n_peaks: int, records: int, seed: int) -> tuple[float, float, list[str]]:
    """10 % and 90 % quantiles, over ``records`` records of ``n_peaks`` unit Rayleigh peaks, of the Weibull MPM
    of a 1000-peak storm over the exact mode; the flags of the fits."""
    rng = np.random.default_rng(seed)
    mode, _ = exact_maximum(1000)
    got, flags = [], []
    for _ in range(records):
        record = np.ravel(np.column_stack([rng.rayleigh(1.0, n_peaks + 1), -rng.rayleigh(1.0, n_peaks + 1)]))
        w = weibull_maximum(record, duration=1.0, storm=1000.0 / n_peaks)
        got.append(w.most_probable / mode)
        flags.append(w.flag)
    lo, hi = np.percentile(got, [10, 90])
    return float(lo), float(hi), flags


def test_a_weibull_fit_on_few_peaks_is_refused_or_flagged():
    """The 3-hour maximum (1000 peaks) from a record of n Rayleigh peaks: its 90 % band over records spans
    0.73-1.58 of the exact mode from 25 peaks (100 records; the OC3 demo's seeds gave 708-1800 kN), 0.83-1.33
    from 50, 0.92-1.12 from 200. So fewer than 50 peaks are refused (MIN_PEAKS), fewer than 200 flagged
    (RELIABLE_PEAKS). Here 25 records of 60 and of 250 peaks (a few seconds of fits): their 10-90 % bands
    measured 0.79-1.16 and 0.92-1.08 (40 records, three seeds: widths 0.37-0.42 and 0.15-0.18 for 5-95 %);
    bounds: wider than 0.2 from 60 peaks, inside 0.85-1.15 from 250."""
    from seacable.design.statistics import MIN_PEAKS, RELIABLE_PEAKS

    assert (MIN_PEAKS, RELIABLE_PEAKS) == (50, 200)
    few = np.ravel(np.column_stack([np.ones(MIN_PEAKS), -np.ones(MIN_PEAKS)]))  # 49 up-crossings, 48 peaks between them
    with pytest.raises(InputError, match=r"48 peaks .* too few for a Weibull fit \(50 at least"):
        weibull_maximum(few, duration=100.0)
    lo, hi, flags = _spread_of_weibull_mpm(60, 25, seed=5)
    assert hi - lo > 0.2, (lo, hi)
    assert all(re.match(r"uncertain: a Weibull fit to \d+ peaks \(fewer than 200\)", f) for f in flags), flags[0]
    lo, hi, flags = _spread_of_weibull_mpm(250, 25, seed=6)
    assert 0.85 < lo and hi < 1.15, (lo, hi)
    assert not any(flags)


def test_the_seeds_notes_of_a_weibull_fit_merge_into_one():
    """Five seeds refused for 24 to 30 peaks make one note (the report listed five, one per row and seed)."""
    from seacable.design.statistics import merged_notes

    notes = [f"not fitted: the record has {n} peaks (mean up-crossings), too few" for n in (30, 24, 27)] + [""]
    assert merged_notes(notes) == "3 seeds: not fitted: the record has 24-30 peaks (mean up-crossings), too few"
    assert merged_notes(["a", "b", "a", float("nan")]) == "a; b"

"""Extreme statistics (issue 20): the storm maximum over seeds (Gumbel) and from one record's peaks (Weibull),
against the exact distribution of the largest of N Rayleigh peaks (the peaks of a narrow-band Gaussian
process of unit standard deviation): F_max(x) = (1 - exp(-x^2/2))^N."""

from __future__ import annotations

import math

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

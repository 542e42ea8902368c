"""Fatigue of mooring lines (issue 20): rainflow counting, the T-N curves of DNV-OS-E301, Miner's sum and the
life over a scatter diagram."""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
from scipy.signal import hilbert

from seacable.design import (
    TN_CURVES,
    fatigue_damage,
    fatigue_life,
    narrow_band_damage,
    nominal_area,
    tension_cycles,
)
from seacable.design.fatigue import SECONDS_PER_YEAR
from seacable.errors import InputError


def test_rainflow_count_of_the_astm_e1049_example():
    """ASTM E1049-85 (2017), Fig. 6 and its table: the history -2, 1, -3, 5, -1, 3, -4, 4, -2 holds half
    cycles of range 3, 6 and 9, one and a half of range 4, and one full cycle of range 8."""
    ranges, counts = tension_cycles([-2, 1, -3, 5, -1, 3, -4, 4, -2])
    got = {}
    for r, c in zip(ranges, counts, strict=True):
        got[r] = got.get(r, 0.0) + c
    assert got == {3.0: 0.5, 4.0: 1.5, 6.0: 0.5, 8.0: 1.0, 9.0: 0.5}


def test_damage_of_constant_amplitude_cycles_is_the_t_n_curve():
    """1000 cycles of 4 MN on a 0.1 m studless chain (area 2 pi 0.05^2 = 0.0157 m^2: 254.6 MPa): damage
    1000 s^3 / 6.0e10 = 0.275; the same range on a 0.1 m spiral strand rope (127.3 MPa, a_D 1.7e17, m 4.8)."""
    tension = np.tile([1e6, 5e6], 1000)
    tension = np.r_[tension, 1e6]
    s = 4e6 / (2 * math.pi * 0.05**2) / 1e6
    assert nominal_area("studless_chain", 0.1) == pytest.approx(2 * math.pi * 0.05**2, rel=1e-15)
    assert fatigue_damage(tension, diameter=0.1) == pytest.approx(1000 * s**3 / 6.0e10, rel=1e-12)
    rope = 4e6 / (math.pi * 0.05**2) / 1e6
    assert fatigue_damage(tension, "spiral_strand_rope", diameter=0.1) == pytest.approx(
        1000 * rope**4.8 / 1.7e17, rel=1e-12)
    # the curves of DNV-OS-E301 (2010) Table D1, and its polyester rope curve (on R = range / MBS)
    assert [(c.a_d, c.m) for c in TN_CURVES.values()] == [(1.2e11, 3.0), (6.0e10, 3.0), (1.2e10, 3.0),
                                                          (3.4e14, 4.0), (1.7e17, 4.8), (0.259, 13.46)]


def test_polyester_damage_is_its_curve_on_the_ratio_to_the_breaking_strength():
    """1000 cycles of 1.5 MN on a polyester rope of MBS 15 MN: R = 0.1, N = 0.259 R^-13.46 (DNV-OS-E301 (2010)
    Ch.2 Sec.2 D), damage 1000 / N; the curve needs the breaking strength, not a diameter."""
    tension = np.r_[np.tile([2e6, 3.5e6], 1000), 2e6]
    assert fatigue_damage(tension, "polyester_rope", breaking_load=15e6) == pytest.approx(
        1000 * 0.1**13.46 / 0.259, rel=1e-12)
    with pytest.raises(InputError, match="on the tension range over the breaking strength: give breaking_load"):
        fatigue_damage(tension, "polyester_rope", diameter=0.2)
    with pytest.raises(InputError, match="has no nominal area"):
        nominal_area("polyester_rope", 0.2)


def test_the_line_type_tells_its_curve_and_an_ambiguous_name_is_refused():
    """The material given wins; a name tells the curve only when it names one (a chain could be studless or
    stud-link, a wire rope six or spiral strand: refused, not guessed as spiral strand was in the OC3 demo)."""
    from seacable.design.fatigue import curve_of_line_type

    assert curve_of_line_type("studless_chain", "oc3")[0] == "studless_chain"
    assert curve_of_line_type(None, "R3 studless chain 76 mm")[0] == "studless_chain"
    assert curve_of_line_type(None, "stud link chain")[0] == "stud_chain"
    assert curve_of_line_type(None, "spiral_strand_rope")[0] == "spiral_strand_rope"
    assert curve_of_line_type(None, "six strand wire")[0] == "six_strand_rope"
    assert curve_of_line_type(None, "polyester")[0] == "polyester_rope"
    for name, why in (("chain", "studless or stud-link chain: ambiguous"), ("wire", "six-strand or spiral-strand"),
                      ("oc3", "says nothing of its material"), ("studless spiral", "ambiguous")):
        curve, reason = curve_of_line_type(None, name)
        assert curve is None and why in reason and "material" in reason, reason
    assert curve_of_line_type("other", "power cable")[0] is None


def test_the_design_fatigue_factor_defaults_to_dnv():
    """DNV-OS-E301 (2010) Ch.2 Sec.2 D: gamma_F = 5 for adjacent lines' damage ratio d_F <= 0.8, 5 + 3 (d_F - 0.8)
    / 0.2 above (8 at d_F = 1); fatigue_life divides the life by 5 unless told otherwise."""
    from seacable.design.fatigue import DNV_DESIGN_FATIGUE_FACTOR, dnv_design_fatigue_factor

    assert DNV_DESIGN_FATIGUE_FACTOR == 5.0
    assert [dnv_design_fatigue_factor(d) for d in (0.0, 0.8, 0.9, 1.0)] == pytest.approx([5.0, 5.0, 6.5, 8.0])
    per_year = 1e-4 / 10800.0 * SECONDS_PER_YEAR
    assert fatigue_life([1e-4], 10800.0, [1.0]) == pytest.approx(1 / per_year / 5, rel=1e-12)
    with pytest.raises(InputError, match="damage_ratio d_F must lie between 0 and 1"):
        dnv_design_fatigue_factor(1.5)


@functools.cache
def _narrow_band_turning_points(seed, cycles=100_000, f0=0.1, delta=0.03, per_cycle=8):
    """A Gaussian process with a flat spectrum over f0 (1 +- delta) (random phases), its turning points read
    from its analytic signal (envelope at each half turn of its phase, alternating sign); its m0 and nu0.
    Made once per seed for the module (the T-N curves share it), the turning points read-only."""
    rng = np.random.default_rng(seed)
    fs = per_cycle * f0
    n = cycles * per_cycle
    f = np.fft.rfftfreq(n, 1 / fs)
    df = f[1] - f[0]
    spectrum = np.where(np.abs(f - f0) <= delta * f0, 1e10, 0.0)  # [N^2 s]: sigma about 1.6e4 N
    x = np.fft.irfft(np.sqrt(2 * spectrum * df) * np.exp(1j * rng.uniform(0, 2 * np.pi, f.size)) * n / 2, n)
    m0 = float(np.sum(spectrum * df))
    nu0 = math.sqrt(float(np.sum(spectrum * df * (2 * np.pi * f) ** 2)) / m0) / (2 * np.pi)
    z = hilbert(x)
    phase = np.unwrap(np.angle(z))
    t = np.arange(n) / fs
    k = np.arange(np.ceil(phase[0] / np.pi), np.floor(phase[-1] / np.pi))
    tk = np.interp(k * np.pi, phase, t)
    points = 5e5 + np.interp(tk, t, np.abs(z)) * np.cos(k * np.pi)
    points.flags.writeable = False
    return points, m0, nu0, n / fs


@pytest.mark.parametrize("curve, bound", [("studless_chain", 0.02), ("spiral_strand_rope", 0.05)])
def test_damage_of_a_narrow_band_gaussian_record_is_the_closed_form(curve, bound):
    """100 000 cycles of a narrow-band Gaussian tension (band 0.1 Hz +- 3 %, about a 500 kN mean) on a 0.1 m
    line: the rainflow damage is the closed form nu0 T / a_D (2 sqrt(2 m0))^m Gamma(1 + m/2).

    The record's own sampling error grows with m: a cycle's S^m has a relative variance
    Gamma(1 + m)/Gamma(1 + m/2)^2 - 1, 2.4 for m = 3 and 8.6 for m = 4.8 (1.9 times the scatter). Eight seeds
    gave 0.996-1.005 of the closed form for m = 3 and 0.979-1.033 for m = 4.8: bounds 2 % and 5 %."""
    tension, m0, nu0, duration = _narrow_band_turning_points(seed=3)
    got = fatigue_damage(tension, curve, diameter=0.1)
    assert got == pytest.approx(narrow_band_damage(m0, nu0, duration, curve, diameter=0.1), rel=bound)


def test_fatigue_life_over_a_scatter_diagram():
    """Two sea states, 3 h records: damages 1e-4 and 4e-4, probabilities 0.75 and 0.25: damage per year
    (0.75e-4 + 1e-4) / 10800 s x 1 year, life its inverse (1/3 of it with a design fatigue factor of 3)."""
    per_year = (0.75 * 1e-4 + 0.25 * 4e-4) / 10800.0 * SECONDS_PER_YEAR
    assert fatigue_life([1e-4, 4e-4], 10800.0, [0.75, 0.25], design_fatigue_factor=1) == pytest.approx(
        1 / per_year, rel=1e-12)
    assert fatigue_life([1e-4, 4e-4], 10800.0, [0.75, 0.25], design_fatigue_factor=3) == pytest.approx(
        1 / per_year / 3, rel=1e-12)
    assert fatigue_life([0.0], 10800.0, [1.0]) == math.inf


@pytest.mark.parametrize("call, match", [
    (lambda: fatigue_life([1e-4, 4e-4], 10800.0, [0.5, 0.25]), r"sum to 1, got a sum of 0\.75 \(2 sea states\)"),
    (lambda: fatigue_life([1e-4, -1.0], 10800.0, [0.5, 0.5]), "damage must be finite and >= 0"),
    (lambda: fatigue_life([1e-4], 0.0, [1.0]), "duration must be > 0 s"),
    (lambda: fatigue_damage([1.0, 2.0], "chain", diameter=0.1), "T-N curve 'chain' is not one of stud_chain"),
    (lambda: fatigue_damage([1.0, 2.0]), "either the nominal diameter .* or the nominal area .* not neither"),
    (lambda: fatigue_damage([1.0, np.nan, 2.0], diameter=0.1), "non-finite value at sample 1"),
    (lambda: nominal_area("studless_chain", -0.1), "diameter must be > 0 m"),
])
def test_bad_fatigue_input_is_refused_clearly(call, match):
    with pytest.raises(InputError, match=match):
        call()


@pytest.mark.parametrize("probabilities, match", [
    ("0.5\n4.0,9.0,0.4", r"sum to 1, got a sum of 0.9 \(2 sea states\)"),
    ("50\n4.0,9.0,50", r"sum to 1, got a sum of 100 .*not per cent"),
    ("nan\n4.0,9.0,1.0", r"probability of sea state 1 is nan"),
    ("-0.2\n4.0,9.0,1.2", r"probability of sea state 1 is -0.2"),
])
def test_a_scatter_diagram_is_checked_when_read(tmp_path, probabilities, match):
    """Issue 37: a scatter diagram's probabilities (finite, >= 0, summing to 1 to 1e-6) are checked as it is read,
    not only when a fatigue life is computed (a report whose lines had no T-N curve exited 0 on a bad diagram)."""
    from seacable.design.summary import read_scatter

    path = tmp_path / "scatter.csv"
    path.write_text("hs,tp,probability\n2.0,8.0," + probabilities + "\n")
    with pytest.raises(InputError, match=match):
        read_scatter(path)
    path.write_text("hs,tp,probability\n2.0,8.0,0.6\n4.0,9.0,0.4\n")
    assert list(read_scatter(path)["probability"]) == [0.6, 0.4]
    path.write_text("hs,tp,probability\n2.0,0.0,0.6\n4.0,9.0,0.4\n")
    with pytest.raises(InputError, match=r"line 2: tp = 0 s; it must be a finite number > 0 s"):
        read_scatter(path)


def test_the_oc3_demo_line_is_a_studless_chain():
    """The OC3-Hywind demo's line type says what it is (issue 39: its chain was counted on the spiral strand curve,
    a life 1.8e5 times too long): studless chain, and its sea takes DNV-RP-C205's peakedness (no gamma given)."""
    from pathlib import Path

    import seacable as sc
    from seacable.design.fatigue import curve_of_line_type

    case = sc.load_case(Path(__file__).parents[3] / "examples" / "oc3_hywind_storm.yaml")
    lt = case.line_types["oc3"]
    assert curve_of_line_type(lt.material, "oc3") == ("studless_chain", "the line type's material (studless_chain)")
    assert case.environment.waves.gamma is None
    assert case.environment.waves.peak_enhancement() == pytest.approx(1.932, abs=5e-4)

"""Issue 37: the one breaking and steepness check of a sea state, regular or irregular, at its published limits;
a table spectrum's Hs from its m0; the share of a spectrum's energy in a frequency_range; the environment inputs
an analysis does not use; and the run-size bound of an irregular sea's grid taken before the grid's tables.

Each limit is asserted at its boundary: a value just inside passes, one just outside is refused (or warned), so
a limit moved or dropped fails here. Before issue 37 an irregular sea was never checked (Hs 1000 m in 320 m of
water ran, and Tp 0.001 s allocated 4.7 GB before any size check).
"""

from __future__ import annotations

import math
import warnings

import pytest

import seacable as sc
from seacable.case import ANALYSES, ENVIRONMENT_INPUTS
from seacable.environment import Environment, IrregularWaves
from seacable.errors import InputError, SeacableWarning
from seacable.waves import check_sea_state, wave_number

G = 9.80665


def _refused(h, t, d=None, irregular=False):
    return check_sea_state(h, t, d, G, irregular=irregular).refused


def test_depth_limited_breaking_is_mccowans_078_of_the_depth():
    # d = 20 m, T = 20 s: Miche's steepness limit (H/L 0.061) is not reached below 16.8 m, so 0.78 d = 15.6 m rules
    assert _refused(15.5, 20.0, 20.0) == ()
    (msg,) = _refused(15.7, 20.0, 20.0)
    assert "exceeds 0.78 times the water depth 20 m (15.6 m)" in msg


def test_steepness_is_miches_limit_in_finite_and_deep_water():
    # T = 6 s in 10 m: L = 48.39 m and tanh(k d)/7 = 0.1230 (tests/unit/test_waves.py), H_lim = 5.9545 m
    L = 2 * math.pi / wave_number(6.0, 10.0, G)
    limit = math.tanh(2 * math.pi / L * 10.0) / 7
    assert limit * L == pytest.approx(5.9545, abs=1e-4)
    assert _refused(5.94, 6.0, 10.0) == ()
    assert "exceeds the breaking limit 0.123" in _refused(5.96, 6.0, 10.0)[0]
    # deep water, T = 10 s: L = g T^2 / (2 pi) = 156.13 m, H_lim = L / 7 = 22.30 m (also for Hs at Tp)
    assert _refused(22.29, 10.0, irregular=True) == ()
    assert "steepness Hs/L = 0.143 (L = 156.1 m" in _refused(22.32, 10.0, irregular=True)[0]


def test_an_irregular_sea_steeper_than_dnv_is_warned_not_refused():
    # DNV-RP-C205 3.5.5: Sp = 2 pi Hs / (g Tp^2) <= 1/15 at Tp = 8 s, i.e. Hs <= 6.659 m; 1/25 at 15 s (14.04 m)
    assert check_sea_state(6.65, 8.0, irregular=True).warned == ()
    assert "exceeds DNV-RP-C205 3.5.5's limit 1/15" in check_sea_state(6.67, 8.0, irregular=True).warned[0]
    assert check_sea_state(14.0, 15.0, irregular=True).warned == ()
    assert check_sea_state(14.1, 15.0, irregular=True).warned != ()
    # a regular wave of the same height and period is not a sea state: no such warning
    assert check_sea_state(6.67, 8.0, irregular=False).warned == ()
    with pytest.warns(SeacableWarning, match="average steepness Sp"):
        Environment(waves={"spectrum": "jonswap", "hs": 6.67, "tp": 8.0})


def test_a_capillary_period_is_refused_for_regular_and_irregular_waves():
    # deep-water L = g T^2 / (2 pi) = 0.1 m at T = 0.2531 s (surface tension: 3 % of omega^2 there)
    assert check_sea_state(0.001, 0.26, irregular=True).refused == ()
    assert "under 0.1 m" in check_sea_state(0.001, 0.25, irregular=True).refused[0]
    with pytest.raises(InputError, match=r"(?i)environment.waves.tp = 0.001 s gives a wavelength of 1.56e-06 m"):
        Environment(depth=320.0, waves={"spectrum": "jonswap", "hs": 4.0, "tp": 0.001})
    with pytest.raises(InputError, match=r"waves.period = 0.01 s gives a wavelength"):
        Environment(waves={"height": 1e-4, "period": 0.01})


def test_regular_and_irregular_waves_share_the_check():
    # Hs or H of 1000 m in 320 m of water: the same two refusals, by the same keys
    for waves, key in (({"spectrum": "jonswap", "hs": 1000.0, "tp": 10.0}, "hs"), ({"height": 1000.0, "period": 10.0},
                                                                                     "height")):
        with pytest.raises(InputError, match=rf"(?s)2 problems.*waves.{key} = 1000 m exceeds 0.78 times.*breaking limit"):
            Environment(depth=320.0, waves=waves)


def test_a_table_spectrums_hs_is_4_sqrt_m0_of_the_table():
    # a triangle 1 rad/s wide and 2 m^2 s high: m0 = 1 m^2, Hs = 4 m, peak at 1 rad/s
    tab = IrregularWaves(spectrum="table", frequencies=(0.5, 1.0, 1.5), density=(0.0, 2.0, 0.0))
    hs, tp, how = tab.sea_state()
    assert hs == pytest.approx(4.0, rel=1e-12) and tp == pytest.approx(2 * math.pi, rel=1e-12)
    assert "m0 = 1 m^2" in how
    # the same triangle 1e12 times higher: Hs 4e6 m, refused in any depth (before issue 37 a hang)
    with pytest.raises(InputError, match=r"density's Hs = 4e\+06 m \(Hs = 4 sqrt\(m0\), m0 = 1e\+12 m\^2"):
        Environment(waves={"spectrum": "table", "frequencies": (0.5, 1.0, 1.5), "density": (0.0, 2e12, 0.0)})


def test_a_frequency_range_must_hold_half_the_spectrums_energy():
    # Pierson-Moskowitz: the energy below w is exp(-5/4 (wp/w)^4) of m0 (integral of DNV eq. 3.5.5.1), so
    # [wp, 2 wp] holds exp(-5/64) - exp(-5/4) = 0.63835; the numerical integral on 40001 points agrees to 1e-5
    pm = IrregularWaves(spectrum="pierson_moskowitz", hs=4.0, tp=10.0)
    wp = 2 * math.pi / 10.0
    assert pm.energy_share(wp, 2 * wp) == pytest.approx(math.exp(-5 / 64) - math.exp(-1.25), abs=1e-5)
    IrregularWaves(spectrum="pierson_moskowitz", hs=4.0, tp=10.0, frequency_range=(wp, 2 * wp))
    # [1.5 wp, 20 wp] holds exp(-5/(4*20^4)) - exp(-5/(4*1.5^4)) = 0.2191: refused
    with pytest.raises(InputError, match="holds 0.219 of the spectrum's energy"):
        IrregularWaves(spectrum="pierson_moskowitz", hs=4.0, tp=10.0, frequency_range=(1.5 * wp, 20 * wp))
    with pytest.raises(InputError, match="highest frequency 3000 rad/s gives components 6.85e-06 m long"):
        IrregularWaves(spectrum="jonswap", hs=4.0, tp=10.0, frequency_range=(0.3, 3000.0))


def test_each_analysis_declares_the_environment_inputs_it_uses():
    for cls in ANALYSES:
        assert set(cls.USES) <= set(ENVIRONMENT_INPUTS), cls.__name__
    base = {"line_types": {"c": {"diameter": 0.09, "mass_per_length": 77.7, "axial_stiffness": 3.8e8}},
            "line": {"line_type": "c", "length": 902.2}, "environment": {"depth": 320.0},
            "analysis": {"type": "static", "fairlead": [848.67, -70.0]}}
    sc.Case.parse(base)  # depth: used
    # waves: a static analysis is the still-water equilibrium, and takes them (one environment for the statics and
    # the dynamics); a current is a mean load the catenary statics does not model
    sc.Case.parse({**base, "environment": {"depth": 320.0, "waves": {"height": 2.0, "period": 8.0}}})
    with pytest.raises(InputError, match=r"environment.current is given, but analysis 'static' does not use it"):
        sc.Case.parse({**base, "environment": {"depth": 320.0, "current": {"speed": 0.5}}})
    # the same inputs are taken by the mooring dynamics
    dyn = {**base, "environment": {"depth": 320.0, "waves": {"height": 2.0, "period": 8.0}, "current": {"speed": 0.5}},
           "analysis": {"type": "mooring_dynamic", "fairlead": [848.67, -70.0], "duration": 1.0}}
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sc.Case.parse(dyn)


def test_the_sea_grid_is_size_checked_before_its_column_tables(monkeypatch):
    # a 1 cm sea at Tp 1 s (L = 1.56 m) at a fairlead 1 cm deep: the nodes above its cutoff depth span metres, a
    # grid of ~2 cm steps, more than 25 columns x 10 times x 5 values + 8 a column (1e4 bytes, the limit given)
    # before _sea_columns allocates its nx x ny tables (before issue 37 they were made first: 4.85 GB at Tp 1 ms)
    import seacable.mooring.solver as solver
    from seacable.mooring.run import case_model

    case = sc.Case.parse({"line_types": {"c": {"diameter": 0.09, "mass_per_length": 77.7, "axial_stiffness": 3.8e8}},
                          "line": {"line_type": "c", "length": 70.0},
                          "environment": {"depth": 50.0, "waves": {"spectrum": "jonswap", "hs": 0.01, "tp": 1.0}},
                          "analysis": {"type": "mooring_dynamic", "fairlead": [40.0, -0.01], "n_elements": 50,
                                       "duration": 1.0}})
    model = case_model(case)
    monkeypatch.setenv("SEACABLE_MAX_MEMORY", "1e4")
    monkeypatch.setattr(solver, "_sea_columns", lambda *a, **k: pytest.fail("tables made before the size check"))
    with pytest.raises(InputError, match="the irregular sea's kinematics grid would store about"):
        model.check_sea(1.0, model.network.position)

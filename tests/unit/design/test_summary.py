"""The design tables of time-domain mooring results (seacable.design.summary, issue 20): extremes per load case
and line from seacable.design.statistics, the code checks through seacable.design.checks, anchor uplift and
offsets in closed form, fatigue damage and life over a scatter diagram in closed form."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from seacable.design import checks, statistics, summary
from seacable.design.fatigue import SECONDS_PER_YEAR
from seacable.errors import InputError

DT = 0.5


def _record(seed: int, n: int = 1200, mean: float = 2.0e6) -> np.ndarray:
    """A random-phase sea-like tension record [N]: 30 components between 0.07 and 0.15 Hz."""
    rng = np.random.default_rng(seed)
    t = np.arange(n) * DT
    f = np.linspace(0.07, 0.15, 30)
    amp = rng.rayleigh(4e4, f.size)
    return mean + np.sum(amp[:, None] * np.cos(2 * np.pi * f[:, None] * t + rng.uniform(0, 2 * np.pi, f.size)[:, None]),
                         axis=0)


@pytest.fixture
def storm(synth):
    """One load case of 6 seeds, two lines; seed 0's L1 peaks at its last sample, seed 1's at its first."""
    out = []
    for k in range(6):
        l1 = _record(k)
        if k < 2:
            l1[-1 if k == 0 else 0] = l1.max() + 1e5
        out.append(synth.result({"L1": l1, "L2": 0.5 * _record(100 + k)}, dt=DT,
                                case=synth.case(hs=6.0, tp=10.0, seed=k)))
    return {"storm": out}


def test_seed_maxima_mean_and_std_are_those_of_each_series(storm):
    runs = summary.read_results(storm)
    seeds = summary.seed_table(runs)
    assert len(seeds) == 6 * 2 * 2  # seeds x lines x ends
    for k, ds in enumerate(storm["storm"]):
        for line in ("L1", "L2"):
            for end in ("fairlead", "anchor"):
                row = seeds[(seeds["seed"] == k) & (seeds["line"] == line) & (seeds["end"] == end)].iloc[0]
                x = ds[f"{end}_tension"].sel(line=line).values
                # the same numbers, computed once: exact
                assert row["maximum"] == np.max(x)
                assert row["mean"] == np.mean(x) and row["std"] == np.std(x)
                assert row["duration"] == (x.size - 1) * DT


def test_gumbel_and_weibull_columns_are_those_of_the_statistics_module(storm):
    runs = summary.read_results(storm)
    ext = summary.extremes_table(runs, storm_duration=10800.0, quantile=0.9)
    row = ext[(ext["line"] == "L1") & (ext["end"] == "fairlead")].iloc[0]
    records = [ds["fairlead_tension"].sel(line="L1").values for ds in storm["storm"]]
    maxima = [r.max() for r in records]
    g = statistics.gumbel_maximum(maxima, 0.9)
    w = [statistics.weibull_maximum(r, (r.size - 1) * DT, 10800.0, 0.9) for r in records]
    # the module's own functions on the same data: equal to rounding only
    assert row["seeds"] == 6
    assert row["gumbel_mpm"] == pytest.approx(g.most_probable, rel=1e-12)
    assert row["gumbel_quantile"] == pytest.approx(g.quantile, rel=1e-12)
    assert row["weibull_mpm"] == pytest.approx(np.mean([x.most_probable for x in w]), rel=1e-12)
    assert row["weibull_quantile"] == pytest.approx(np.mean([x.quantile for x in w]), rel=1e-12)
    assert row["maximum_largest"] == max(maxima) and row["maximum_mean"] == pytest.approx(np.mean(maxima), rel=1e-12)
    # a 3-hour storm is longer than the 600 s runs: the design maximum is the Weibull extrapolation
    assert row["design_maximum"] == row["weibull_mpm"] and row["design_basis"].startswith("Weibull MPM")
    assert row["dynamic"] == pytest.approx(row["design_maximum"] - np.mean([r.mean() for r in records]), rel=1e-12)
    assert row["weibull_mpm"] > row["maximum_largest"]  # 18 times the runs' peaks: a larger maximum
    # the storm of the runs' duration: the Gumbel MPM over the seeds
    same = summary.extremes_table(runs, quantile=0.9)
    row = same[(same["line"] == "L1") & (same["end"] == "fairlead")].iloc[0]
    assert row["design_maximum"] == row["gumbel_mpm"] and row["design_basis"] == "Gumbel MPM over 6 seeds"
    assert "Naess & Moan" in row["method"] and "DNV-OS-E301" in row["method"]


def test_a_bad_quantile_or_storm_is_refused_not_noted(storm):
    runs = summary.read_results(storm)
    with pytest.raises(InputError, match="between 0 and 1, got 1.5"):
        summary.seed_table(runs, quantile=1.5)
    with pytest.raises(InputError, match="storm duration must be > 0 s, got -1"):
        summary.extremes_table(runs, storm_duration=-1.0)


def test_too_few_seeds_for_gumbel_says_so_and_uses_the_weibull_fit(storm):
    runs = summary.read_results({"storm": storm["storm"][:3]})
    ext = summary.extremes_table(runs)
    row = ext.iloc[0]
    assert math.isnan(row["gumbel_mpm"]) and "at least 5" in row["gumbel_note"] and "got 3" in row["gumbel_note"]
    # the fixture's records hold fewer than 200 peaks: the basis says the Weibull fits are flagged (issue 39)
    assert row["design_basis"] == "Weibull MPM, mean over 3 seed(s) (FLAGGED: fits on few peaks, uncertain)"
    assert row["weibull_flag"].startswith("3 seeds: uncertain: a Weibull fit to ")  # merged over the seeds


def test_a_sweep_folder_groups_seeds_into_load_cases(synth, tmp_path):
    runs = []
    for hs in (2.0, 4.0):
        for seed in (1, 2):
            ds = synth.result({"L1": _record(seed, n=200) * hs}, case=synth.case(hs=hs, tp=8.0, seed=seed,
                                                                                 lines=("L1",)))
            runs.append(({"environment.waves.hs": hs, "environment.waves.tp": 8.0,
                          "environment.waves.seed": float(seed), "analysis.duration": 100.0}, ds))
    found = summary.read_results(synth.sweep(tmp_path / "sw", runs))
    # named by the sea state; the seed and a parameter of one value for all (the duration) left out
    assert [r.load_case for r in found] == ["hs = 2 m, tp = 8 s"] * 2 + ["hs = 4 m, tp = 8 s"] * 2
    assert [r.seed for r in found] == [1, 2, 1, 2]
    assert [r.name for r in found] == [f"storm_{k:04d}" for k in range(4)]
    seeds = summary.seed_table(found)
    fair = seeds[seeds["end"] == "fairlead"]
    assert list(fair["maximum"]) == [float(np.max(ds["fairlead_tension"].values)) for _, ds in runs]


def test_checks_rows_are_the_checks_modules_numbers(storm):
    runs = summary.read_results(storm)
    ext = summary.extremes_table(runs)
    for cc in (1, 2):
        table = summary.checks_table(runs, ext, consequence_class=cc)
        for line in ("L1", "L2"):
            e = ext[(ext["line"] == line) & (ext["end"] == "fairlead")].iloc[0]
            want = [checks.dnv_uls(line, e["mean"], e["dynamic"], 7.3e6, cc),
                    checks.api_tension(line, e["design_maximum"], 7.3e6, "intact", "dynamic")]
            for w in want:
                got = table[(table["check"] == w.check) & (table["item"] == line)]
                assert len(got) == 1, w.check
                got = got.iloc[0]
                assert (got["demand"], got["capacity"], got["utilisation"], got["margin"]) == (
                    w.demand, w.capacity, w.utilisation, w.margin)
                assert got["passed"] == w.passed and got["status"] == ("pass" if w.passed else "FAIL")
                assert got["formula"] == w.formula and got["reference"] == w.reference


def test_a_failed_line_makes_the_load_case_damaged(synth):
    ds = synth.result({"L1": _record(1), "L2": _record(2)}, failure_time={"L1": 50.0},
                      case=synth.case(hs=6.0, tp=10.0, seed=1))
    runs = summary.read_results(ds)
    ext = summary.extremes_table(runs)
    table = summary.checks_table(runs, ext)
    l1 = table[table["item"] == "L1"]
    assert list(l1["status"]) == ["not checked: line 'L1' failed at t = 50 s"] * 2
    assert l1["utilisation"].isna().all()
    e = ext[(ext["line"] == "L2") & (ext["end"] == "fairlead")].iloc[0]
    als = checks.dnv_als("L2", e["mean"], e["dynamic"], 7.3e6, 1)
    api = checks.api_tension("L2", e["design_maximum"], 7.3e6, "damaged", "dynamic")
    for w in (als, api):
        row = table[(table["check"] == w.check) & (table["item"] == "L2")].iloc[0]
        assert row["utilisation"] == w.utilisation
    assert not table["check"].str.contains("ULS").any()


def test_a_line_with_no_breaking_load_is_reported_or_refused_when_asked_for(synth):
    ds = synth.result({"L1": _record(1), "L2": _record(2)}, breaking_load={"L1": 7.3e6})  # L2: NaN
    runs = summary.read_results(ds)
    table = summary.checks_table(runs)
    l2 = table[(table["item"] == "L2")]
    assert list(l2["status"]) == ["not checked: no breaking_load for line 'L2'"] * 2
    assert l2["passed"].isna().all()
    l1 = table[(table["item"] == "L1") & table["check"].str.startswith("DNV")].iloc[0]
    assert l1["capacity"] == checks.dnv_uls("L1", 1.0, 1.0, 7.3e6).capacity
    with pytest.raises(InputError, match="L2.*breaking_load"):
        summary.checks_table(runs, lines=["L2"])
    with pytest.raises(InputError, match="line 'L9' is not in the results"):
        summary.checks_table(runs, lines=["L9"])


def test_anchor_uplift_is_the_vertical_component_along_the_first_element(synth):
    """The first element at the anchor rises 3 m over 5 m: F_z = T_anchor 3/5; the largest over the run."""
    anchor = np.full(40, 1.0e6)
    anchor[17] = 1.5e6
    ds = synth.result({"L1": np.full(40, 2e6)}, anchor={"L1": anchor}, breaking_load={"L1": 7.3e6})
    assert summary.anchor_uplift_force(ds, "L1") == pytest.approx(1.5e6 * 3 / 5, rel=1e-14)
    runs = summary.read_results(ds)
    table = summary.checks_table(runs, allowed_uplift=1.0e6)
    row = table[table["check"] == "anchor uplift"].iloc[0]
    want = checks.anchor_uplift("anchor of L1", 9.0e5, 1.0e6)
    assert row["demand"] == pytest.approx(9.0e5, rel=1e-14) and row["utilisation"] == pytest.approx(
        want.utilisation, rel=1e-14)
    # the case ties end B to the anchor: the nodes run from the fairlead, the anchor element is the last
    case = synth.case(lines=("L1",))
    case["lines"]["L1"].update(end_a="f0", end_b="a0")
    flipped = synth.result({"L1": np.full(40, 2e6)}, anchor={"L1": anchor}, case=case, nodes=synth.nodes[::-1])
    info = summary.line_info(flipped)["L1"]
    assert info.anchor_end == 1
    assert summary.anchor_uplift_force(flipped, "L1", info) == pytest.approx(9.0e5, rel=1e-14)
    # no case (a MoorDyn network): the lower end is the anchor
    assert summary.anchor_uplift_force(synth.result({"L1": np.full(40, 2e6)}, anchor={"L1": anchor},
                                                    nodes=synth.nodes[::-1]), "L1") == pytest.approx(9.0e5, rel=1e-14)


def test_anchor_round_off_is_no_uplift(synth):
    """A grounded line whose first element rises 5e-5 of its length (the solver's round-off at the seabed): 35 N
    up under 700 kN of anchor tension is no uplift (under UPLIFT_ROUND_OFF = 1e-3 of the tension): the drag
    anchor passes with a margin of 0 N and no utilisation. With a real 4.9 deg lift at one instant (60 kN up)
    that instant is taken, and the check fails by 60 kN."""
    nodes = synth.nodes.copy()
    nodes[1] = [4.0, 0.0, -100.0 + 4.0 * 5e-5]
    anchor = np.full(40, 7.0e5)
    ds = synth.result({"L1": np.full(40, 2e6)}, anchor={"L1": anchor}, breaking_load={"L1": 7.3e6}, nodes=nodes)
    assert summary.anchor_uplift_force(ds, "L1") == pytest.approx(35.0, rel=1e-6)
    row = summary.checks_table(summary.read_results(ds)).query("check == 'anchor uplift'").iloc[0]
    assert row["status"] == "pass" and row["demand"] == 0.0 and row["margin"] == 0.0
    assert math.isnan(row["utilisation"]) and row["unit"] == "N"
    z = np.broadcast_to(nodes[:, 2], (40, 3)).copy()
    z[25, 1] = -100.0 + 4.0 * 6e4 / math.sqrt(7.0e5 ** 2 - 6e4 ** 2)  # F_z = 60 kN of 700 kN at step 25
    ds["z"] = (("line", "time", "node"), z[None])
    assert summary.anchor_uplift_state(ds, "L1") == pytest.approx((6e4, 7.0e5), rel=1e-9)
    row = summary.checks_table(summary.read_results(ds)).query("check == 'anchor uplift'").iloc[0]
    assert row["status"] == "FAIL" and row["margin"] == pytest.approx(-6e4, rel=1e-9)


def test_offset_is_the_largest_horizontal_distance_from_the_case_position(synth):
    xy = np.zeros((20, 2))
    xy[7] = [3.0, 4.0]
    case = synth.case()
    ds = synth.result({"L1": _record(1, n=20), "L2": _record(2, n=20)}, case=case, body_xy=xy)
    assert summary.body_offsets(ds)["hull"][0] == 5.0
    case["bodies"]["hull"]["position"] = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    ds = synth.result({"L1": _record(1, n=20), "L2": _record(2, n=20)}, case=case, body_xy=xy)
    assert summary.body_offsets(ds)["hull"][0] == pytest.approx(math.hypot(2.0, 4.0), rel=1e-15)
    table = summary.checks_table(summary.read_results(ds), offset_limit=10.0)
    row = table[table["check"] == "offset"].iloc[0]
    assert row["item"] == "hull" and row["utilisation"] == pytest.approx(math.hypot(2.0, 4.0) / 10.0, rel=1e-15)
    assert "from its position in the case" in row["formula"]
    # no body: the limit given, the check said not made
    table = summary.checks_table(summary.read_results(synth.result({"L1": _record(1, n=20)})), offset_limit=10.0)
    assert list(table.loc[table["check"] == "offset", "status"]) == [
        "not checked: the results hold no body or platform motion (body_position, platform_position)"]


def _cycles(low, tension_range, n):
    """n constant-amplitude cycles of ``tension_range`` [N] from ``low`` [N]."""
    return np.r_[np.tile([low, low + tension_range], n), low]


def test_fatigue_life_over_a_two_state_scatter_diagram_is_the_closed_form(synth, tmp_path):
    """Two sea states of constant-amplitude cycles, 200 of 1 MN and 200 of 2 MN in 200 s (two seeds each), on a
    studless chain of volume-equivalent diameter 0.171 m (nominal 0.171/1.8 = 0.095 m): D_i = n_i s_i^3 / a_D,
    s_i = R_i / (2 pi d^2/4) (DNV-OS-E301 Table D1, a_D = 6.0e10, m = 3), and the life over probabilities
    0.75 and 0.25 is 1 / (year (0.75 D_1/T_1 + 0.25 D_2/T_2))."""
    runs, table = [], [("hs", "tp", "probability"), (2.0, 8.0, 0.75), (4.0, 9.0, 0.25)]
    for hs, tp, r in ((2.0, 8.0, 1.0e6), (4.0, 9.0, 2.0e6)):
        for seed in (1, 2):
            ds = synth.result({"L1": _cycles(1.0e6, r, 200)}, dt=DT, case=synth.case(hs=hs, tp=tp, seed=seed,
                                                                                       lines=("L1",)))
            runs.append(({"environment.waves.hs": hs, "environment.waves.tp": tp,
                          "environment.waves.seed": float(seed)}, ds))
    found = summary.read_results(synth.sweep(tmp_path / "sw", runs))
    scatter = tmp_path / "scatter.csv"
    scatter.write_text("\n".join(",".join(str(x) for x in row) for row in table) + "\n")
    fat = summary.fatigue_table(found, scatter=scatter)
    area = 2 * math.pi * (0.171 / 1.8) ** 2 / 4
    duration = 400 * DT
    damage = [200 * (r / area / 1e6) ** 3 / 6.0e10 for r in (1.0e6, 2.0e6)]
    assert list(fat["tn_curve"]) == ["studless_chain"] * 2
    assert list(fat["nominal_diameter"]) == pytest.approx([0.095, 0.095], rel=1e-15)
    assert list(fat["damage"]) == pytest.approx(damage, rel=1e-12)  # rainflow counts exactly: rounding only
    assert list(fat["probability"]) == [0.75, 0.25]
    assert list(fat["life_alone"]) == pytest.approx([duration / d / SECONDS_PER_YEAR for d in damage], rel=1e-12)
    life = summary.fatigue_life_table(fat, design_fatigue_factor=1.0)
    want = 1.0 / (SECONDS_PER_YEAR * (0.75 * damage[0] / duration + 0.25 * damage[1] / duration))
    assert life["life"].iloc[0] == pytest.approx(want, rel=1e-12)
    # by default DNV-OS-E301's design fatigue factor, 5
    assert summary.fatigue_life_table(fat)["life"].iloc[0] == pytest.approx(want / 5, rel=1e-12)
    assert summary.fatigue_life_table(fat, design_fatigue_factor=3.0)["life"].iloc[0] == pytest.approx(want / 3,
                                                                                                      rel=1e-12)
    # the T-N curve and diameter given: a spiral strand rope of 0.1 m, D = n s^4.8 / 1.7e17
    rope = summary.fatigue_table(found, tn_curve="spiral", nominal_diameter=0.1)
    assert rope["damage"].iloc[0] == pytest.approx(200 * (1e6 / (math.pi * 0.05**2) / 1e6) ** 4.8 / 1.7e17, rel=1e-12)

    # refusals, by name
    bad = tmp_path / "bad.csv"
    bad.write_text("hs,tp,probability\n2.0,8.0,0.5\n4.0,9.0,0.25\n6.0,10.0,0.25\n")
    with pytest.raises(InputError, match=r"sea state hs = 6 m, tp = 10 s .* has no case"):
        summary.fatigue_table(found, scatter=bad)
    bad.write_text("hs,tp,probability\n2.0,8.0,1.0\n")
    with pytest.raises(InputError, match=r"'hs = 4 m, tp = 9 s'.* no sea state in the scatter diagram"):
        summary.fatigue_table(found, scatter=bad)
    bad.write_text("hs,tp,probability\n2.0,8.0,0.7\n4.0,9.0,0.25\n")
    with pytest.raises(InputError, match="sum to 1"):  # refused as the diagram is read (issue 37)
        summary.fatigue_table(found, scatter=bad)
    bad.write_text("hs,probability\n2.0,1.0\n")
    with pytest.raises(InputError, match="lacks tp"):
        summary.fatigue_table(found, scatter=bad)


def test_fatigue_without_a_known_curve_or_diameter_says_why(synth):
    ds = synth.result({"L1": _cycles(1e6, 1e6, 50)})  # no case: neither line type nor diameter
    fat = summary.fatigue_table(summary.read_results(ds))
    assert fat["note"].iloc[0].startswith("not computed: the T-N curve of line 'L1'") and math.isnan(fat["damage"][0])
    fat = summary.fatigue_table(summary.read_results(ds), tn_curve="studless")
    assert "nominal diameter of line 'L1' is unknown" in fat["note"].iloc[0]
    fat = summary.fatigue_table(summary.read_results(ds), tn_curve="studless", nominal_diameter=0.1)
    assert fat["damage"].iloc[0] == pytest.approx(50 * (1e6 / (2 * math.pi * 0.05**2) / 1e6) ** 3 / 6.0e10,
                                                  rel=1e-12)


def test_tn_curve_names():
    assert [summary.resolve_tn_curve(n) for n in ("studless", "stud", "six_strand", "spiral", "Studless-Chain",
                                                  "connecting")] == [
        "studless_chain", "stud_chain", "six_strand_rope", "spiral_strand_rope", "studless_chain", "connecting_link"]
    assert summary.resolve_tn_curve("polyester") == "polyester_rope"  # DNV-OS-E301's fibre rope curve
    with pytest.raises(InputError, match="T-N curve 'nylon' is not one of"):
        summary.resolve_tn_curve("nylon")


def test_results_of_other_analyses_are_refused(synth):
    ds = synth.result({"L1": np.ones(5)}, analysis="mooring_static")
    with pytest.raises(InputError, match="analysis 'mooring_static'.*mooring_dynamic or system_dynamic"):
        summary.read_results(ds)


def test_a_sea_state_of_several_headings_shares_its_probability(synth, tmp_path):
    """One sea state of the diagram (probability 1) and two headings in the sweep: each heading gets 1/2, and
    the life is 1 / (year (D_0/T + D_1/T) / 2)."""
    runs = []
    for heading, r in ((0.0, 1.0e6), (1.5, 2.0e6)):
        case = synth.case(hs=2.0, tp=8.0, seed=1, lines=("L1",))
        case["environment"]["waves"]["heading"] = heading
        ds = synth.result({"L1": _cycles(1.0e6, r, 100)}, dt=DT, case=case)
        runs.append(({"environment.waves.heading": heading}, ds))
    found = summary.read_results(synth.sweep(tmp_path / "sw", runs))
    assert [r.load_case for r in found] == ["heading = 0", "heading = 1.5"]
    scatter = tmp_path / "scatter.csv"
    scatter.write_text("hs,tp,probability\n2.0,8.0,1.0\n")
    fat = summary.fatigue_table(found, scatter=scatter)
    assert list(fat["probability"]) == [0.5, 0.5]
    area = 2 * math.pi * (0.171 / 1.8) ** 2 / 4
    damage = [100 * (r / area / 1e6) ** 3 / 6.0e10 for r in (1.0e6, 2.0e6)]
    want = 1.0 / (SECONDS_PER_YEAR * 0.5 * (damage[0] + damage[1]) / (200 * DT))
    assert summary.fatigue_life_table(fat, design_fatigue_factor=1.0)["life"].iloc[0] == pytest.approx(want,
                                                                                                      rel=1e-12)


def test_fatigue_counts_the_intact_runs_only(synth, tmp_path):
    """Fatigue is a limit state of the intact system (DNV-OS-E301 Ch.2 Sec.2 D): a damaged load case of the same
    sea state (a line failed) adds nothing to the damage nor takes a share of the scatter diagram's probability."""
    runs = []
    for damaged in (False, True):
        ds = synth.result({"L1": _cycles(1.0e6, 1.0e6, 200), "L2": _cycles(1.0e6, 3.0e6, 200)}, dt=DT,
                          failure_time={"L2": 1.0} if damaged else None,
                          case=synth.case(hs=2.0, tp=8.0, seed=1))
        runs.append(({"environment.waves.hs": 2.0, "environment.waves.tp": 8.0, "environment.waves.seed": 1.0,
                      "analysis.duration": 100.0 + damaged}, ds))
    scatter = tmp_path / "scatter.csv"
    scatter.write_text("hs,tp,probability\n2.0,8.0,1.0\n")
    fat = summary.fatigue_table(summary.read_results(synth.sweep(tmp_path / "sw", runs)), scatter=scatter)
    area = 2 * math.pi * (0.171 / 1.8) ** 2 / 4
    assert list(fat["line"]) == ["L1", "L2"] and list(fat["probability"]) == [1.0, 1.0]
    assert list(fat["damage"]) == pytest.approx([200 * (r / area / 1e6) ** 3 / 6.0e10 for r in (1e6, 3e6)],
                                                rel=1e-12)


def test_design_tables_are_the_tables_made_one_by_one_from_one_read_of_each_file(synth, tmp_path, monkeypatch):
    """design_tables (the report's reading) gives the tables of seed_table, extremes_table, checks_table and
    fatigue_table to the bit, and opens each result file once (the four tables read every file again: 44 opens
    for the report of 10 runs); the visitor sees each run, in order, with its result open."""
    import pandas as pd
    import xarray as xr

    runs = []  # two sea states of two seeds, a line failed in one run (16 Weibull fits in all: a second)
    for hs in (4.0, 8.0):
        for seed in range(2):
            track = np.c_[np.linspace(0.0, 3.0 + 3 * seed, 600), np.zeros(600)]
            ds = synth.result({"L1": _record(seed, n=600, mean=hs * 5e5)}, body_xy=track,
                              failure_time={"L1": 10.0} if (hs, seed) == (8.0, 1) else None,
                              case=synth.case(name=f"s{hs:g}_{seed}", hs=hs, tp=10.0, seed=seed, lines=("L1",)))
            runs.append(({"environment.waves.hs": hs, "environment.waves.tp": 10.0,
                          "environment.waves.seed": float(seed)}, ds))
    folder = synth.sweep(tmp_path / "sw", runs)
    scatter = tmp_path / "scatter.csv"
    scatter.write_text("hs,tp,probability\n4.0,10.0,0.7\n8.0,10.0,0.3\n")
    options = {"storm_duration": 10800.0, "quantile": 0.8}
    found = summary.read_results(folder)
    seeds = summary.seed_table(found, **options)
    ext = summary.extremes_table(seeds, **options)
    want = {"seeds": seeds, "extremes": ext,
            "checks": summary.checks_table(found, ext, consequence_class=2, offset_limit=5.0, allowed_uplift=1e6),
            "fatigue": summary.fatigue_table(found, tn_curve="studless", scatter=scatter)}
    # issue 39: the load components each load case modelled, and the LF/WF parts and their combinations
    from seacable.design.combination import combined_table, modelled_components

    rows = []
    for lc, first in (("hs = 4 m, tp = 10 s", "0000.nc"), ("hs = 8 m, tp = 10 s", "0002.nc")):
        with xr.open_dataset(folder / "cases" / first) as ds:
            rows += [{"load_case": lc, **c} for c in modelled_components(summary.case_data(ds))]
    want["components"] = pd.DataFrame(rows, columns=["load_case", "component", "status", "how"])
    want["combined"] = combined_table(seeds, ext, 10800.0)

    opened = []
    open_dataset = xr.open_dataset

    def counted(path, *args, **kwargs):
        opened.append(Path(path).name)
        return open_dataset(path, *args, **kwargs)

    monkeypatch.setattr(xr, "open_dataset", counted)
    seen = []
    got_runs, got = summary.design_tables(folder, consequence_class=2, offset_limit=5.0, allowed_uplift=1e6,
                                          tn_curve="studless", scatter=scatter,
                                          visit=lambda run, ds: seen.append((run.name, float(ds.time[-1]))), **options)
    assert sorted(opened) == [f"{k:04d}.nc" for k in range(4)] + ["summary.nc"]
    assert [(r.name, r.load_case, r.seed, r.parameters) for r in got_runs] == [
        (r.name, r.load_case, r.seed, r.parameters) for r in found]
    assert seen == [(r.name, 299.5) for r in found]
    assert list(got) == list(want)
    for key, table in want.items():
        pd.testing.assert_frame_equal(got[key], table, check_exact=True, obj=key)
    assert set(got["checks"]["status"]) == {"pass", "FAIL", "not checked: line 'L1' failed at t = 10 s"}
    assert got["fatigue"]["seeds"].tolist() == [2, 1]


def test_load_case_labels_tell_apart_parameters_that_end_alike():
    """A sweep of the wind's and the current's speed labels them by their last two parts, the rest by the last."""
    from seacable.design.summary import _label

    label = _label({"environment.waves.hs": 10.0, "environment.wind.speed": 30.0, "environment.current.speed": 1.0},
                   {"environment.waves.hs": "m", "environment.wind.speed": "m/s", "environment.current.speed": "m/s"})
    assert label == "hs = 10 m, wind.speed = 30 m/s, current.speed = 1 m/s"

"""The cable part of the design report (seacable.report_cable, issue 40): the page of a static or pushover result of a
cable (its shape, the checks against the static MBR with their utilisations, one row an offset), the armour's
fatigue in a dynamic result's cable section, the refusal of bad limits, and the page in headless Chromium."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

import seacable as sc
from seacable.design.cable_fatigue import SNCurve, cable_fatigue_damage
from seacable.report import make_report

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CHROMIUM = "/usr/bin/chromium"

#: Limits of the 80 m lazy wave (examples/lazy_wave_80m.yaml) for these tests: its curvature (0.097 1/m) is 0.39 of
#: 1 / MBR at a 4 m static MBR; its sag bend stands about 15 m above the seabed, its hog bend about 22 m.
LIMITS = {"minimum_bend_radius": 4.0, "minimum_bend_radius_dynamic": 6.0, "allowable_tension": 2.0e4}
DESIGN = {"sag_bend_clearance": 5.0, "hog_bend_clearance": 5.0, "hang_off_declination": [0.0, 0.6]}


def _lazy_wave(analysis: dict | None = None) -> sc.Case:
    data = yaml.safe_load((EXAMPLES / "lazy_wave_80m.yaml").read_text())
    data["line_types"]["cable"].update(LIMITS)
    data["analysis"].update({"element_length": 1.0, "design": DESIGN,
                             "fairlead_end_condition": {"type": "clamped", "declination": 0.2, "azimuth": 0.0}})
    data["analysis"].update(analysis or {})
    return sc.Case.parse(data)


@pytest.fixture(scope="module")
def pushover():
    return sc.run(_lazy_wave({"type": "mooring_pushover", "offsets": [-6.0, 0.0, 6.0], "heading": 0.0}))


def _cell_numbers(text: str, check: str) -> list[str]:
    row = next(r for r in text.split("<tr") if f">{check}<" in r)
    return [c.split("</td>")[0] for c in row.split("<td>")[1:]]


def test_a_static_result_of_a_cable_gets_its_own_page_with_each_check_and_its_utilisation(tmp_path):
    ds = sc.run(_lazy_wave())
    page = tmp_path / "static.html"
    written = make_report(ds, page)
    assert [p.name for p in written] == ["static.html", "static_cable_checks.csv", "static_cable_offsets.csv",
                                         "static_range_graphs.nc"]
    text = page.read_text(encoding="utf-8")
    assert "Cable design report" in text and "2. Shape" in text and "Per offset" not in text  # one state
    table = pd.read_csv(tmp_path / "static_cable_checks.csv")
    # every check is made (the case gives every limit) and shown with its utilisation, as the page formats it
    assert table["status"].eq("pass").all() and len(table) == 7
    kappa = float(np.nanmax(ds.curvature.values))
    # the curvature's utilisation is kappa MBR with the static MBR: 0.0968 x 4 = 0.39 (the dynamic 6 m not used)
    row = table.set_index("check").loc["curvature (static MBR)"]
    assert row["utilisation [-]"] == pytest.approx(kappa * 4.0, rel=1e-12) and 0.3 < kappa * 4.0 < 0.45
    for check, u in zip(table["check"], table["utilisation [-]"], strict=True):
        cells = _cell_numbers(text, check)
        assert cells[4] == (f"{u:.3f}" if math.isfinite(u) else "&ndash;"), (check, cells)
    # the tension's utilisation: the largest element tension over the allowable 20 kN
    assert table.set_index("check").loc["tension", "utilisation [-]"] == pytest.approx(
        float(ds.segment_tension.max()) / 2.0e4, rel=1e-12)


def test_a_system_static_result_of_a_cable_gets_the_page_of_its_cable_with_its_clearance(tmp_path):
    """examples/cable_66kv_system.yaml: the page of the system's cable (the line that bends: the chains' curvature is
    0), on its finite-element shape, its limits its own line type's, and its distance to the chains as a row."""
    from seacable.design.clearance import line_distance
    from seacable.report_cable import system_cable_view

    ds = sc.run(sc.load_case(EXAMPLES / "cable_66kv_system.yaml"))
    page = tmp_path / "system.html"
    make_report(ds, page)
    text = page.read_text(encoding="utf-8")
    assert "<td>cable</td>" in text and "system_static" in text
    table = pd.read_csv(tmp_path / "system_cable_checks.csv").set_index("check")
    view = system_cable_view(ds)
    assert str(view["line"].values) == "cable" and view.sizes["node"] == 281  # its 280 finite elements
    kappa = float(np.nanmax(ds.curvature.sel(line="cable").values))
    assert table.loc["curvature (static MBR)", "utilisation [-]"] == pytest.approx(kappa * 2.37, rel=1e-12)
    assert table.loc["tension", "value [see unit]"] == pytest.approx(
        float(np.nanmax(ds.fe_segment_tension.sel(line="cable"))))
    nearest = min(d.distance for d in line_distance(ds, "cable"))
    assert table.loc["line clearance", "value [see unit]"] == pytest.approx(nearest) and table.loc["line clearance", "status"] \
        == "pass"
    assert (table["status"].isin(["pass"]) | table["status"].str.startswith("not checked")).all()


def test_the_pushover_page_has_a_row_an_offset_whose_worst_is_the_checks(pushover, tmp_path):
    page = tmp_path / "push.html"
    make_report(pushover, page)
    offsets = pd.read_csv(tmp_path / "push_cable_offsets.csv")
    checks = pd.read_csv(tmp_path / "push_cable_checks.csv").set_index("check")
    assert list(offsets["offset [m]"]) == [-6.0, 0.0, 6.0]
    # the hang-off tension of each offset is the tension at end B; moving the hang-off away from the seabed end
    # (positive offsets along heading 0) lifts more cable and raises it
    np.testing.assert_array_equal(offsets["hang_off_tension [N]"], pushover.tension.values[:, -1])
    assert np.all(np.diff(offsets["hang_off_tension [N]"]) > 0)
    # the worst over the offsets is the checks' worst: the largest curvature and where it was
    assert offsets["curvature_static_MBR"].max() == checks.loc["curvature (static MBR)", "value [see unit]"]
    k = int(offsets["curvature_static_MBR"].idxmax())
    assert offsets["offset [m]"][k] == checks.loc["curvature (static MBR)", "offset [m]"]
    text = page.read_text(encoding="utf-8")
    assert text.count("offset ") >= 3 and "<h3>Per offset</h3>" in text
    # the summary's largest utilisation is of a demand over its limit: the declination's place in its range (0.71
    # here, the largest number) is not one
    ratios = checks[~checks.index.str.startswith("hang-off declination")]["utilisation [-]"].dropna()
    top = ratios.idxmax()
    assert f'Largest utilisation ({top})</div><div class="v">{ratios[top]:.3f}' in text


def test_the_armour_fatigue_is_in_a_dynamic_report_when_the_case_asks(tmp_path):
    """A 3 s run of the clamped cable of test_report's Chromium test with analysis.design.armour: the section shows
    the damage of the most damaged node, the same as seacable.design.cable_fatigue computes from the result, and as
    if the run lasted the year: damage x (365.25 x 86400 s) / 3 s."""
    armour = {"tension_factor": 600.0, "curvature_factor": 4.0e8, "points": 8,
              "sn_curve": {"a": 8.26e14, "m": 4.0, "m2": 5.0, "n_knee": 1.0e6}}
    ds = sc.run(sc.Case.parse({
        "name": "hang",
        "line_types": {"cable": {"diameter": 0.15, "mass_per_length": 40, "axial_stiffness": 5e8,
                                 "bending_stiffness": 2e4, "minimum_bend_radius": 2.0,
                                 "minimum_bend_radius_dynamic": 4.0, "allowable_tension": 2.5e4}},
        "line": {"line_type": "cable", "length": 160}, "environment": {"depth": 100},
        "analysis": {"type": "mooring_dynamic", "anchor": [0, -100], "fairlead": [80, -10], "n_elements": 20,
                     "fairlead_end_condition": {"type": "clamped", "declination": 0.1},
                     "duration": 3.0, "time_step": 0.1, "output_interval": 0.5, "design": {"armour": armour},
                     "motion": {"type": "harmonic", "amplitude": [1.0, 0.0, 0.5], "period": 4.0, "ramp": 1.0}}}))
    page = tmp_path / "dyn.html"
    written = make_report(ds, page)
    assert page.with_name("dyn_cable_fatigue.csv") in written
    text = page.read_text(encoding="utf-8")
    assert "<h3>Armour fatigue</h3>" in text
    row = pd.read_csv(page.with_name("dyn_cable_fatigue.csv")).iloc[0]
    damage, _ = cable_fatigue_damage(ds, SNCurve(8.26e14, 4.0, 5.0, 1.0e6), 600.0, 4.0e8, points=8)
    assert row["damage [-]"] == pytest.approx(float(damage.max()), rel=1e-12) and damage.max() > 0
    assert row["s [m]"] == pytest.approx(float(ds.s.values[int(np.argmax(damage))]))
    assert row["damage_per_year [1/year]"] == pytest.approx(damage.max() * 365.25 * 86400 / 3.0, rel=1e-12)
    # a case without the armour block has no such section (and no file)
    plain = ds.copy()
    plain.attrs["case"] = ds.attrs["case"].replace("armour", "unused_key")
    make_report(plain, tmp_path / "plain.html")
    assert "Armour fatigue" not in (tmp_path / "plain.html").read_text() and not (
        tmp_path / "plain_cable_fatigue.csv").exists()


@pytest.mark.parametrize(("design", "message"), [
    ({"armour": {"tension_factor": 600.0, "curvature_factor": 0.0, "sn_curve": {"a": 1e12, "m": 3}}},
     "curvature_factor is 0 Pa m"),
    ({"armour": {"tension_factor": -1.0, "curvature_factor": 4e8, "sn_curve": {"a": 1e12, "m": 3}}},
     "tension_factor must be > 0 Pa/N"),
    ({"armour": {"tension_factor": 600.0, "curvature_factor": 4e8, "sn_curve": {"a": 0.0, "m": 3}}},
     "a must be > 0 MPa"),
    ({"armour": {"tension_factor": 600.0, "curvature_factor": 4e8, "sn_curve": {"a": 1e12, "m": 3},
                 "points": 0}}, "armour.points must be 1 to 360"),
    ({"line_clearance": -2.0}, "line_clearance must be > 0 m"),
])
def test_bad_design_limits_are_refused_by_validate_and_run(tmp_path, capsys, design, message):
    from seacable.cli import main

    data = yaml.safe_load((EXAMPLES / "cable_66kv_static.yaml").read_text())
    data["analysis"]["design"].update(design)
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data))
    for command in (["validate", str(path)], ["run", str(path), "-o", str(tmp_path / "out.nc")]):
        assert main(command) == 2
        err = capsys.readouterr().err
        assert message in err and "Suggested fix" in err, (command, err)
    assert not (tmp_path / "out.nc").exists()


@pytest.mark.skipif(shutil.which(CHROMIUM) is None,
                    reason=f"{CHROMIUM} is missing (Debian's 'chromium' package: .ci/run installs it)")
def test_the_pushover_page_renders_in_headless_chromium(pushover, tmp_path, browser):
    """The page of a pushover in a real browser: no console message; its shape figure drawn (the seabed's brown,
    (140, 109, 70): 1 770 px when this was written, none on the same page without its figures), its range graphs'
    light-blue bands ((191, 219, 235): 8 130 px, none without the figures) and the tables' PASS badges' green
    ((227, 241, 228): 4 920 px, the checks' 7 and the offsets' 3)."""
    from PIL import Image

    page = tmp_path / "push.html"
    make_report(pushover, page)
    png = tmp_path / "push.png"
    assert browser.console(browser.start(page, png, tmp_path / "profile", size=(1280, 4000))) == []
    rgb = np.asarray(Image.open(png).convert("RGB"), dtype=int)
    assert browser.near(rgb, (140, 109, 70), 3) > 800
    assert browser.near(rgb, (191, 219, 235), 3) > 4000
    assert browser.near(rgb, (227, 241, 228), 3) > 3000

"""The report of a mooring system's cables (seacable.report_system_cable, issue 40): a system_static result's page
gives every line with bending stiffness a section, its checks in every condition with the CSV and NetCDF tables of a
single line's page; a system_dynamic result's report checks its cables (not its chains); the page in headless
Chromium. The numbers are those of seacable.design.system_cable (tests/unit/design/test_system_cable.py checks them
against the same cables alone)."""

from __future__ import annotations

import shutil

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from seacable.design.system_cable import system_cable_check_table
from seacable.report import make_report

CHROMIUM = "/usr/bin/chromium"


def test_a_system_static_page_has_a_section_a_cable_and_its_checks_in_each_condition(two_cables, tmp_path):
    ds = two_cables.static
    page = tmp_path / "two.html"
    written = make_report(ds, page)
    assert [p.name for p in written] == ["two.html", "two_cable_checks.csv", "two_cable_offsets.csv",
                                         "two_range_graphs.nc"]
    text = page.read_text(encoding="utf-8")
    assert "<h2>2. Cable &lsquo;cable_a&rsquo;</h2>" in text and "<h2>3. Cable &lsquo;cable_b&rsquo;</h2>" in text
    assert "chain&rsquo;" not in text and "<h3>Per condition</h3>" in text  # cable_a's two conditions
    # the CSV: every cable and condition, each row the design layer's (the same number to the bit)
    csv = pd.read_csv(tmp_path / "two_cable_checks.csv")
    table = system_cable_check_table(ds)
    assert list(zip(csv["line"], csv["condition"], csv["check"], strict=True)) == list(
        zip(table["line"], table["condition"], table["check"], strict=True))
    np.testing.assert_array_equal(csv["value [see unit]"], table["value"])
    np.testing.assert_array_equal(csv["utilisation [-]"], table["utilisation"])
    assert list(csv["status"]) == list(table["status"])
    # cable_b's sag bend fails (10.9 m against 12 m): a FAIL in its section, and the summary counts it
    fails = int((table["status"] == "FAIL").sum())
    assert fails >= 1 and f"{fails} of {int(table['passed'].notna().sum())} fail" in text
    # a row a cable and condition: the hang-off tension is the end element's at end B in that condition
    per = pd.read_csv(tmp_path / "two_cable_offsets.csv")
    assert list(zip(per["line"], per["condition"], strict=True)) == [("cable_a", "intact"), ("cable_a", "damaged"),
                                                                     ("cable_b", "intact")]
    for _, r in per.iterrows():
        t = ds["fe_segment_tension"].sel(line=r["line"], condition=r["condition"]).values
        # the view's node tension at end B: its one element's
        assert r["hang_off_tension [N]"] == t[np.isfinite(t)][-1]
    # the range graphs: both cables on 'line', each over its conditions (cable_b's padded to cable_a's nodes)
    with xr.open_dataset(tmp_path / "two_range_graphs.nc") as rg:
        assert list(rg["line"].values) == ["cable_a", "cable_b"]
        for name in ("cable_a", "cable_b"):
            kappa = ds["curvature"].sel(line=name).values
            assert float(rg["curvature_max"].sel(line=name).max()) == float(np.nanmax(kappa))


def test_a_system_dynamic_report_checks_its_cables_not_its_chain(two_cables, tmp_path):
    dyn = two_cables.dynamic
    page = tmp_path / "run.html"
    make_report(dyn, page)
    csv = pd.read_csv(tmp_path / "run_cable_checks.csv")
    table = system_cable_check_table(dyn)
    assert set(csv["line"]) == {"cable_a", "cable_b"}
    for name in ("cable_a", "cable_b"):
        mine, want = csv[csv["line"] == name], table[table["line"] == name]
        assert list(mine["check"]) == list(want["check"])
        np.testing.assert_array_equal(mine["value [see unit]"], want["value"])
        assert list(mine["status"]) == list(want["status"])
    assert "curvature (dynamic MBR)" in set(csv["check"]) and "line clearance" in set(csv["check"])


@pytest.mark.skipif(shutil.which(CHROMIUM) is None,
                    reason=f"{CHROMIUM} is missing (Debian's 'chromium' package: .ci/run installs it)")
def test_the_system_page_renders_in_headless_chromium(two_cables, tmp_path, browser):
    """The page in a real browser: no console message; the shapes of the damaged condition drawn in its orange
    ((213, 94, 0), dashed over the intact shape: cable_a's in its elevation and plan and the legends'), the seabed's
    brown ((140, 109, 70)) in both cables' elevations, the FAIL red ((198, 40, 40): cable_b's sag bend's badge and
    the summary's count) and the range graphs' light-blue bands ((191, 219, 235): the legends'
    patches). When this was written: 227, 3 780, 969 and 531 px; on the same page without its figures 0, 0, 971
    and 0. The bounds are about half of these."""
    from PIL import Image

    page = tmp_path / "two.html"
    make_report(two_cables.static, page)
    png = tmp_path / "two.png"
    assert browser.console(browser.start(page, png, tmp_path / "profile", size=(1280, 9000))) == []
    rgb = np.asarray(Image.open(png).convert("RGB"), dtype=int)
    counts = {name: browser.near(rgb, colour, 3) for name, colour in (
        ("damaged", (213, 94, 0)), ("seabed", (140, 109, 70)), ("fail", (198, 40, 40)), ("band", (191, 219, 235)))}
    assert counts["damaged"] > 100, counts
    assert counts["seabed"] > 1800, counts
    assert counts["fail"] > 450, counts
    assert counts["band"] > 250, counts

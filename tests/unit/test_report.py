"""The design report (seacable.report, ``seacable report``, issue 20): one self-contained HTML page and the same
tables as CSV; the tables' numbers, the command's errors, a real run, and the page in a real browser (headless
Chromium, Debian's package)."""

from __future__ import annotations

import base64
import contextlib
import io
import math
import re
import shutil
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from seacable.cli import main
from seacable.design import summary
from seacable.results import open_netcdf

DT = 0.5
CHROMIUM = "/usr/bin/chromium"
DECK = Path(__file__).resolve().parents[1] / "validation" / "data" / "three_chains_deck.txt"


class _Page(HTMLParser):
    """The tables of a page (by class: rows of cell texts, <sup> written as '^'), its images and tags."""

    def __init__(self):
        super().__init__()
        self.tables: dict[str, list[list[str]]] = {}
        self.images: list[str] = []
        self.tags: list[tuple[str, dict]] = []
        self._table = None
        self._cell = None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.tags.append((tag, a))
        if tag == "table":
            self._table = self.tables.setdefault(a.get("class", ""), [])
        elif tag == "tr" and self._table is not None:
            self._table.append([])
        elif tag in ("td", "th") and self._table is not None:
            self._cell = []
        elif tag == "sup" and self._cell is not None:
            self._cell.append("^")
        elif tag == "img":
            self.images.append(a.get("src", ""))

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self._table[-1].append("".join(self._cell).strip())
            self._cell = None
        elif tag == "table":
            self._table = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)


def _page(path) -> _Page:
    p = _Page()
    p.feed(Path(path).read_text(encoding="utf-8"))
    return p


def _value(text: str) -> float:
    """A number as the page shows it: '1388', '−0.5', '3.03×10^-5', '–' (none), '∞', a footnote mark '^a'."""
    text = re.sub(r"\^[a-z]+$", "", text.replace("\u2212", "-")).strip()
    if text in ("\u2013", ""):
        return math.nan
    if text == "\u221e":
        return math.inf
    m = re.fullmatch(r"(-?[\d.]+)\u00d710\^(-?\d+)", text)
    return float(m[1]) * 10.0 ** int(m[2]) if m else float(text)


def _format(text: str) -> tuple | None:
    """The number format of a cell: ('fixed', decimals), ('sci', mantissa decimals), or None (no number: a dash,
    a zero shown as '0' in a scientific column)."""
    text = re.sub(r"\^[a-z]+$", "", text.replace("\u2212", "-")).strip()
    m = re.fullmatch(r"-?\d+(?:\.(\d+))?\u00d710\^-?\d+", text)
    if m:
        return ("sci", len(m[1] or ""))
    m = re.fullmatch(r"-?\d+(?:\.(\d+))?", text)
    if m and not (text == "0"):
        return ("fixed", len(m[1] or ""))
    return None


def _one_format_per_column(page: _Page) -> None:
    """Every numeric table of the page shows each column in one format (fixed with one number of decimals, or
    scientific), and never an infinite or NaN number."""
    for cls, rows in page.tables.items():
        if not cls.startswith("num"):
            continue
        for c in range(len(rows[0])):
            cells = [r[c] for r in rows[1:] if c < len(r)]
            assert not any(x in cell.lower() for cell in cells for x in ("\u221e", "inf", "nan")), (cls, rows[0][c])
            formats = {_format(cell) for cell in cells} - {None}
            numeric = [cell for cell in cells if _format(cell)]
            if len(numeric) == len(cells) or rows[0][c].endswith("]"):  # a number column (its header has a unit)
                assert len(formats) <= 1, (cls, rows[0][c], formats, cells)


def _within_last_digit(text: str, si_value: float, scale: float) -> bool:
    """The cell ``text`` shows ``si_value / scale`` rounded to its last shown digit (fixed or scientific)."""
    value = _value(text)
    x = si_value / scale
    if math.isnan(x):
        return math.isnan(value)
    f = _format(text)
    if f is None:
        return value == x == 0 or (value == 0 and f is None and abs(x) < 1e-300)
    kind, decimals = f
    unit = 10.0 ** -decimals if kind == "fixed" else 10.0 ** (math.floor(math.log10(abs(value))) - decimals)
    return abs(value - x) <= 0.5 * unit * (1 + 1e-9)


def _shown(html_value: float, si_value: float, scale: float, sig: int) -> bool:
    """The page shows ``si_value / scale`` to ``sig`` significant digits: within half a unit of its last digit."""
    x = si_value / scale
    if math.isnan(x) or math.isinf(x):
        return (math.isnan(x) and math.isnan(html_value)) or x == html_value
    if x == 0:
        return html_value == 0
    half = 0.5 * 10.0 ** (math.floor(math.log10(abs(x))) - (sig - 1))
    return abs(html_value - x) <= half * (1 + 1e-9)


def _record(seed: int, n: int = 600, mean: float = 2.0e6, amplitude: float = 4e4) -> np.ndarray:
    rng = np.random.default_rng(seed)
    t = np.arange(n) * DT
    f = np.linspace(0.07, 0.15, 30)
    amp = rng.rayleigh(amplitude, f.size)
    phase = rng.uniform(0, 2 * np.pi, f.size)
    return mean + np.sum(amp[:, None] * np.cos(2 * np.pi * f[:, None] * t + phase[:, None]), axis=0)


@pytest.fixture
def files_only(monkeypatch):
    """The report's figures at 30 dpi instead of 110, for a test that reads the page's text and the CSV files, not
    the figures' pixels (a third less time to draw them)."""
    monkeypatch.setattr("seacable._report_html._DPI", 30)


@pytest.fixture(scope="module")
def built_sweep(synth, tmp_path_factory):
    """Two sea states x five seeds of a two-line chain mooring (MBS 7.3 MN); in the 8 m sea line L1's tension
    reaches 4.6 MN, over the API RP 2SK intact allowable 7.3 / 1.67 = 4.37 MN: a check that fails. The anchors
    take an uplift of 0.8 T 3/5 (under 2.3 MN). Built once; each test reads its own copy (``sweep_dir``)."""
    tmp_path = tmp_path_factory.mktemp("built")
    runs = []
    for hs, tp, mean in ((4.0, 9.0, 2.0e6), (8.0, 11.0, 4.2e6)):
        for seed in range(5):
            case = synth.case(name=f"spread_{hs:g}_{seed}", hs=hs, tp=tp, seed=seed)
            track = np.c_[np.linspace(0.0, 3.0 + seed, 600), np.zeros(600)]  # the hull drifts 3 to 7 m in x
            ds = synth.result({"L1": _record(seed, mean=mean), "L2": _record(50 + seed, mean=0.6 * mean)},
                              dt=DT, case=case, body_xy=track)
            runs.append(({"environment.waves.hs": hs, "environment.waves.tp": tp,
                          "environment.waves.seed": float(seed)}, ds))
    return synth.sweep(tmp_path / "sweep", runs, name="spread_storm")


@pytest.fixture
def sweep_dir(built_sweep, tmp_path):
    """A copy of ``built_sweep`` in this test's folder (a test may write beside it), and a scatter diagram."""
    folder = Path(shutil.copytree(built_sweep, tmp_path / "sweep"))
    scatter = tmp_path / "scatter.csv"
    scatter.write_text("hs,tp,probability\n4.0,9.0,0.8\n8.0,11.0,0.2\n", encoding="utf-8")
    return folder, scatter


def _report(sweep_dir, tmp_path, *extra) -> Path:
    folder, scatter = sweep_dir
    out = tmp_path / "out" / "report.html"
    assert main(["report", str(folder), "-o", str(out), "--scatter", str(scatter), "--allowed-uplift", "2.5e6",
                 *extra]) == 0
    return out


@pytest.fixture(scope="module")
def storm_report(built_sweep, tmp_path_factory) -> tuple[Path, str]:
    """The report of ``built_sweep`` for a 3-hour storm with an offset limit (the page and its CSV files in a
    folder of their own) and what the command printed: built once, read by the CSV test and rendered by the
    browser test (each built the same page, 3 s a build)."""
    tmp_path = tmp_path_factory.mktemp("storm_report")
    scatter = tmp_path / "scatter.csv"
    scatter.write_text("hs,tp,probability\n4.0,9.0,0.8\n8.0,11.0,0.2\n", encoding="utf-8")
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        out = _report((built_sweep, scatter), tmp_path, "--storm-duration", "10800", "--offset-limit", "30")
    return out, printed.getvalue()


def test_the_csv_tables_are_the_html_tables(storm_report, built_sweep):
    out, printed = storm_report
    names = ["report.html", "report_extremes.csv", "report_seeds.csv", "report_checks.csv", "report_fatigue.csv",
             "report_fatigue_life.csv", "report_components.csv", "report_combined.csv"]
    assert sorted(p.name for p in out.parent.iterdir()) == sorted(names)  # nothing else beside the page
    assert all(f"wrote {out.parent / n}" in printed for n in names)
    page = _page(out)

    ext = pd.read_csv(out.parent / "report_extremes.csv")
    rows = page.tables["num extremes"][1:]
    assert len(rows) == len(ext) == 2 * 2 * 2  # load cases x lines x ends
    columns = {4: "mean [N]", 5: "std [N]", 6: "maximum_largest [N]", 7: "maximum_mean [N]", 8: "gumbel_mpm [N]",
               9: "gumbel_quantile [N]", 10: "weibull_mpm [N]", 11: "weibull_quantile [N]", 12: "design_maximum [N]"}
    for row, (_, csv) in zip(rows, ext.iterrows(), strict=True):
        assert row[:4] == [csv["load_case"], csv["line"], csv["end"], str(csv["seeds"])]
        for k, col in columns.items():
            assert _shown(_value(row[k]), csv[col], 1e3, 4), (row, col)  # kN, 4 significant digits
        assert row[13] == csv["design_basis"]

    chk = pd.read_csv(out.parent / "report_checks.csv", keep_default_na=False, na_values=[""])
    # one table per unit: tensions and uplift in kN, offsets in m; demand, capacity and margin in the header's unit
    assert len(chk) == 2 * (2 * 2 + 2 + 1)  # per load case: 2 lines x 2, 2 anchors, hull
    uplift = chk["check"] == "anchor uplift"
    for cls, part, shown, scale in (("num checks kN", chk[(chk["unit"] == "N") & ~uplift], "kN", 1e3),
                                    ("num checks uplift", chk[uplift], "kN", 1e3),
                                    ("num checks m", chk[chk["unit"] == "m"], "m", 1.0)):
        rows = page.tables[cls]
        assert rows[0][3:7] == [f"Demand [{shown}]", f"Capacity [{shown}]", f"Margin [{shown}]", "Utilisation [-]"]
        assert len(rows) - 1 == len(part) > 0
        for row, (_, csv) in zip(rows[1:], part.iterrows(), strict=True):
            assert row[:3] == [csv["load_case"], csv["check"], csv["item"]]
            for k, name in ((3, "demand [N or m, see unit]"), (4, "capacity [N or m, see unit]"),
                            (5, "margin [N or m, see unit]")):
                assert _within_last_digit(row[k], csv[name], scale), (row, name)
            assert csv["margin [N or m, see unit]"] == csv["capacity [N or m, see unit]"] - csv[
                "demand [N or m, see unit]"]
            assert _within_last_digit(row[6], csv["utilisation [-]"], 1.0)
            assert row[7] == {"pass": "PASS", "FAIL": "FAIL"}.get(csv["status"], csv["status"])
    _one_format_per_column(page)
    assert (chk["status"] == "FAIL").sum() == 1  # API RP 2SK intact, L1, in the 8 m sea
    failed = chk[chk["status"] == "FAIL"].iloc[0]
    assert (failed["check"], failed["item"], failed["load_case"]) == ("API RP 2SK intact dynamic", "L1",
                                                                     "hs = 8 m, tp = 11 s")

    fat = pd.read_csv(out.parent / "report_fatigue.csv")
    rows = page.tables["num fatigue"][1:]
    for row, (_, csv) in zip(rows, fat.iterrows(), strict=True):
        assert _shown(_value(row[3]), csv["nominal_diameter [m]"], 1e-3, 3)
        assert _shown(_value(row[6]), csv["damage [-]"], 1.0, 3)
        assert _shown(_value(row[8]), csv["life_alone [years]"], 1.0, 3)
        assert _shown(_value(row[9]), csv["probability [-]"], 1.0, 3)
    life = pd.read_csv(out.parent / "report_fatigue_life.csv")
    rows = page.tables["num life"][1:]
    assert [r[0] for r in rows] == list(life["line"]) == ["L1", "L2"]
    for row, (_, csv) in zip(rows, life.iterrows(), strict=True):
        assert _shown(_value(row[4]), csv["life [years]"], 1.0, 3)

    # the CSV holds the library's tables, in SI units
    runs = summary.read_results(built_sweep)
    want = summary.extremes_table(runs, storm_duration=10800.0)
    assert np.allclose(ext["design_maximum [N]"], want["design_maximum"], rtol=1e-15, atol=0)

    # issue 39: the components each load case modelled (a chain mooring in an irregular sea, no body loads: waves
    # only, the rest NOT MODELLED and in red), and the LF/WF parts with the standards' combinations
    parts = pd.read_csv(out.parent / "report_components.csv")
    assert list(parts["status"][:5]) == ["modelled", "NOT MODELLED", "NOT MODELLED", "NOT MODELLED", "NOT MODELLED"]
    rows = page.tables["components single"][1:] if "components single" in page.tables else page.tables["components"][1:]
    assert [r[-2] for r in rows][:5] == list(parts["status"][:5])
    comb = pd.read_csv(out.parent / "report_combined.csv")
    rows = page.tables["num combined"][1:]
    assert len(rows) == len(comb) == 2 * 2  # load cases x lines, fairlead
    for row, (_, csv) in zip(rows, comb.iterrows(), strict=True):
        for k, col in ((2, "mean [N]"), (7, "api_maximum [N]"), (8, "dnv_maximum [N]"), (9, "time_domain_maximum [N]")):
            assert _shown(_value(row[k]), csv[col], 1e3, 4), (row, col)
    assert "Not modelled (extremes non-conservative)" in out.read_text(encoding="utf-8")


def test_the_page_is_self_contained_and_has_its_sections(sweep_dir, tmp_path):
    out = _report(sweep_dir, tmp_path)
    text = out.read_text(encoding="utf-8")
    page = _page(out)
    tags = {t for t, _ in page.tags}
    assert "script" not in tags and "link" not in tags and "iframe" not in tags
    for _, attrs in page.tags:
        for key in ("src", "href"):
            assert not str(attrs.get(key, "")).startswith(("http:", "https:", "//", "file:")), attrs
    assert "http://" not in text and "https://" not in text
    assert len(page.images) == 3  # the time series, the seeds' maxima, the utilisations
    for src in page.images:
        assert src.startswith("data:image/png;base64,")
        png = base64.b64decode(src.split(",", 1)[1])
        assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10_000
    for title in ("Summary", "1. Inputs", "2. Model and references", "3. Extreme tensions", "4. Code checks",
                  "5. Fatigue"):
        assert f"<h2>{title}</h2>" in text
    assert "<details><summary>Case file (YAML) of spread_storm_0000</summary>" in text
    assert "A reference of the model." in text and "DNV-OS-E301" in text and "API RP 2SK" in text
    assert "1 of 12 fail" in text  # the summary's verdict: no offset limit, no offset check
    assert str(tmp_path) not in text  # no absolute path: the source is shown relative to the page
    assert "<code>../sweep</code>" in text  # out/report.html and sweep/ side by side


def test_a_short_real_run_of_the_three_chain_deck(tmp_path, files_only):
    """A few seconds of the three-chain MoorDyn deck: the report's seed maxima are the stored series' maxima; the
    deck has no breaking load, so the checks say so instead of failing."""
    nc = tmp_path / "three.nc"
    assert main(["run", str(DECK), "--duration", "3", "--output-interval", "0.1", "--no-plots", "-o", str(nc)]) == 0
    out = tmp_path / "three.html"
    assert main(["report", str(nc), "-o", str(out), "--tn-curve", "studless", "--nominal-diameter", "0.14"]) == 0
    seeds = pd.read_csv(tmp_path / "three_seeds.csv")
    with open_netcdf(nc) as ds:   # seacable's reader: the lines' names (the file's line_label) as the coordinate
        for line in ds["line"].values:
            row = seeds[(seeds["line"] == line) & (seeds["end"] == "fairlead")].iloc[0]
            assert row["maximum [N]"] == float(ds["fairlead_tension"].sel(line=line).max())
    chk = pd.read_csv(tmp_path / "three_checks.csv", keep_default_na=False)
    tension = chk[chk["check"].str.startswith(("DNV", "API"))]
    assert list(tension["status"]) == [f"not checked: no breaking_load for line 'line {k}'" for k in (1, 1, 2, 2, 3, 3)]
    fat = pd.read_csv(tmp_path / "three_fatigue.csv")
    assert list(fat["tn_curve"]) == ["studless_chain"] * 3 and (fat["damage [-]"] >= 0).all()
    assert "not checked: no breaking_load for line &#x27;line 1&#x27;" in out.read_text(encoding="utf-8")


@pytest.mark.parametrize(("args", "message"), [
    (["-o", "{out}", "--tn-curve", "nylon"], "T-N curve 'nylon' is not one of"),
    (["-o", "{out}", "--quantile", "1.5"], "quantile's probability must lie between 0 and 1"),
    (["-o", "{out}", "--storm-duration", "-3"], "--storm-duration must be"),
    (["-o", "{out}", "--consequence-class", "3"], "invalid choice"),
    (["-o", "{dir}/report.txt"], "must end in .html"),
    ([], "the following arguments are required: -o"),
    (["-o", "{out}", "--scatter", "{dir}/missing.csv"], "scatter diagram"),
])
def test_bad_options_are_one_line_errors(sweep_dir, tmp_path, capsys, args, message):
    folder, _ = sweep_dir
    args = [a.format(out=tmp_path / "r.html", dir=tmp_path) for a in args]
    assert main(["report", str(folder), *args]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err and err.count("\n") == 1, err
    assert not (tmp_path / "r.html").exists()


def test_a_bad_tn_curve_is_refused_before_the_results_are_read(sweep_dir, tmp_path, monkeypatch, capsys):
    """As the scatter diagram: a misspelt T-N curve is an error before the results of a sweep are read and fitted
    (it came after the seeds' Weibull fits, seconds here and minutes for a sweep of hundreds of runs)."""
    folder, _ = sweep_dir

    def read_results(*args, **kwargs):
        raise AssertionError("the results were read")

    monkeypatch.setattr(summary, "read_results", read_results)
    assert main(["report", str(folder), "-o", str(tmp_path / "r.html"), "--tn-curve", "nylon"]) == 2
    err = capsys.readouterr().err
    assert "T-N curve 'nylon' is not one of" in err and "Traceback" not in err and err.count("\n") == 1, err
    assert not (tmp_path / "r.html").exists()


def test_a_missing_source_or_another_analysis_is_refused(synth, tmp_path, capsys):
    assert main(["report", str(tmp_path / "nothing.nc"), "-o", str(tmp_path / "r.html")]) == 2
    assert "does not exist" in capsys.readouterr().err
    from seacable.results import write_netcdf

    static = write_netcdf(synth.result({"L1": np.ones(4)}, analysis="mooring_static"), tmp_path / "static.nc")
    assert main(["report", str(static), "-o", str(tmp_path / "r.html")]) == 2
    assert "analysis 'mooring_static'" in capsys.readouterr().err


# ------------------------------------------------------------------------------------------ in a real browser

@pytest.mark.skipif(shutil.which(CHROMIUM) is None,
                    reason=f"{CHROMIUM} is missing (Debian's 'chromium' package: .ci/run installs it)")
def test_the_report_renders_in_headless_chromium(storm_report, tmp_path, browser):
    from PIL import Image

    # the page of the CSV test (built once for both; this test built its own for the runs' duration, the same page
    # but for the 3-hour storm's figures), and a reference page; the two browsers (each of its own profile) start
    # together: their start-ups overlap instead of following one another. The reference page is blank but for a
    # script that logs an error and calls a missing function: its console is the check that the console is read,
    # its screenshot the check that a blank page has no pixel off the background (a page of its own each took a
    # third browser, 2 to 4 s on a loaded 2-core machine)
    out, _ = storm_report
    png = tmp_path / "report.png"
    report_browser = browser.start(out, png, tmp_path / "profile")
    planted = tmp_path / "planted.html"
    planted.write_text("<html><body><script>console.error('planted'); missing();</script></body></html>")
    blank = tmp_path / "blank.png"
    planted_browser = browser.start(planted, blank, tmp_path / "profile0")
    # the console is read: a page with an error in its console is caught
    lines = browser.console(planted_browser)
    assert any("planted" in line for line in lines) and any("Uncaught" in line for line in lines)

    assert browser.console(report_browser) == []  # no console message at all
    rgb = np.asarray(Image.open(png).convert("RGB"), dtype=int)
    assert rgb.shape == (5000, 1280, 3)
    # non-background pixels: any channel 10 levels off white. A blank page has none; a page of text alone
    # (the same tables unstyled) under 5 %. This page, with its shaded table headers, zebra rows and three
    # figures in its first 5000 px (4000 until issue 39 added the components table and the records' 40-odd
    # peaks, under the 50 a Weibull fit now takes, lengthened the extremes' basis: the figures moved down), is over 8 % (11.6 % when this was written, 11.8 % for the 3-hour storm's page;
    # the same page without its CSS and figures 4.2 %, with its CSS but no figures 10.2 %: the colours below tell
    # the figures).
    share = float(np.mean(np.any(rgb < 245, axis=-1)))
    blank_rgb = np.asarray(Image.open(blank).convert("RGB"), dtype=int)
    assert blank_rgb.shape == rgb.shape and float(np.mean(np.any(blank_rgb < 245, axis=-1))) == 0.0
    assert share > 0.08, share
    # the tables and figures are drawn: the table headers' shade (#eef2f6; 146 000 px when this was written),
    # the figures' blue data (#0072b2, the time series and the seeds' maxima: 4 000 px), the passing bars'
    # green (#2e7d32: 60 000 px) and the failing bar's red (#c62828, also the FAIL badge: 11 000 px). The same
    # page without its figures has 65 px of that green, 950 px of that red and none of that blue. The 3-hour
    # storm's page: 195 000, 4 300, 50 000 and 10 900 px.
    assert browser.near(rgb, (0xEE, 0xF2, 0xF6), 2) > 20_000
    assert browser.near(rgb, (0x00, 0x72, 0xB2)) > 1_500
    assert browser.near(rgb, (0x2E, 0x7D, 0x32)) > 10_000
    assert browser.near(rgb, (0xC6, 0x28, 0x28)) > 4_000


def test_failed_cases_are_listed_and_left_out(synth, tmp_path, files_only):
    runs = [({"environment.waves.seed": float(k)},
             synth.result({"L1": _record(k)}, case=synth.case(hs=4.0, tp=9.0, seed=k, lines=("L1",))))
            for k in range(3)]
    folder = synth.sweep(tmp_path / "sw", runs, failed={1: "ConvergenceError: no convergence at t = 12 s\nmore"})
    assert [r.seed for r in summary.read_results(folder)] == [0, 2]
    out = tmp_path / "r.html"
    assert main(["report", str(folder), "-o", str(out)]) == 0
    page = _page(out)
    assert ["storm_0001", "ConvergenceError: no convergence at t = 12 s"] in page.tables[""]
    seeds = pd.read_csv(tmp_path / "r_seeds.csv")
    assert sorted(set(seeds["seed"])) == [0, 2]


def test_the_report_of_datasets_from_python(synth, tmp_path, files_only):
    """The library call: make_report on Datasets, a platform following a prescribed motion checked for offset
    (its horizontal distance from the origin, the largest: |(6, 8)| = 10 m)."""
    from seacable.report import ReportOptions, make_report
    from seacable.results import var

    ds = synth.result({"L1": _record(1)}, case=synth.case(lines=("L1",)))
    xy = np.zeros((ds.sizes["time"], 6))
    xy[30, :2] = [6.0, 8.0]
    ds["platform_position"] = var(("time", "dof"), xy, "m or rad", "platform motion")
    ds = ds.assign_coords(dof=["x", "y", "z", "roll", "pitch", "yaw"])
    written = make_report({"storm": [ds]}, tmp_path / "lib.html", ReportOptions(offset_limit=20.0))
    assert [p.name for p in written] == ["lib.html", "lib_extremes.csv", "lib_seeds.csv", "lib_checks.csv",
                                         "lib_fatigue.csv", "lib_components.csv", "lib_combined.csv"]
    chk = pd.read_csv(tmp_path / "lib_checks.csv")
    row = chk[chk["check"] == "offset"].iloc[0]
    assert row["item"] == "platform" and row["demand [N or m, see unit]"] == 10.0 and row["unit"] == "m"
    assert row["utilisation [-]"] == 0.5 and row["margin [N or m, see unit]"] == 10.0
    assert "result Datasets (Python)" in written[0].read_text(encoding="utf-8")


# ------------------------------------------------------------------------------------------ bad inputs (issue 37)

@pytest.mark.parametrize(("where", "value", "message"), [
    (-1, math.inf, "time[599] is inf s"),
    (-1, math.nan, "time[599] is nan s"),
    (0, -math.inf, "time[0] is -inf s"),
    (slice(None), math.nan, "time[0] is nan s, expected finite times (600 of 600"),
    (300, math.nan, "time[300] is nan s"),
    (300, 0.0, "time[300] = 0 s does not come after time[299] = 149.5 s"),
])
def test_a_result_with_a_bad_time_is_refused(synth, tmp_path, capsys, where, value, message):
    """A result file whose time is not finite and increasing (edited, damaged, written by another tool): exit 2
    naming the file and the time, no report written (it was an internal error, 'Axis limits cannot be NaN or
    Inf', or, for one NaN inside, a report of NaN statistics)."""
    from seacable.results import write_netcdf

    ds = synth.result({"L1": _record(1)}, case=synth.case(lines=("L1",)))
    t = ds["time"].values.copy()
    t[where] = value
    nc = write_netcdf(ds.assign_coords(time=("time", t, ds["time"].attrs)), tmp_path / "bad_time.nc")
    out = tmp_path / "r.html"
    assert main(["report", str(nc), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert message in err and str(nc) in err and "Traceback" not in err and err.count("\n") == 1, err
    assert list(tmp_path.glob("r*")) == []


@pytest.mark.parametrize("content", [b"hs,tp,probability\n4.0,9.0,0.8\n8.0,11.0,0.2 # \xe9t\xe9\n",   # Latin-1
                                     b"\xff\xfeh\x00s\x00"])                                             # UTF-16
def test_a_scatter_diagram_not_in_utf8_is_refused(sweep_dir, tmp_path, capsys, content):
    folder, _ = sweep_dir
    scatter = tmp_path / "scatter_latin1.csv"
    scatter.write_bytes(content)
    out = tmp_path / "r.html"
    assert main(["report", str(folder), "-o", str(out), "--scatter", str(scatter)]) == 2
    err = capsys.readouterr().err
    assert f"scatter diagram '{scatter}'" in err and ("not UTF-8" in err or "binary" in err), err
    assert "Traceback" not in err and err.count("\n") == 1, err
    assert not out.exists()


def test_no_table_holds_a_non_finite_utilisation_or_margin(sweep_dir, tmp_path, files_only):
    """Issue 37: a drag anchor (allowed uplift 0 N, the default) under a real uplift was reported with utilisation
    inf, at the top of the page and as inf in the CSV. Now every check of every kind (tension, uplift, offset)
    has a finite margin in its own unit and a utilisation only where its capacity is positive: no cell of a
    utilisation or margin column, in the HTML tables or the CSV files, is inf, -inf or nan. The sweep's anchors
    lift by 0.8 T 3/5 (about 1 MN): they fail by that margin, in kN."""
    import csv

    folder, scatter = sweep_dir
    out = tmp_path / "out" / "report.html"
    assert main(["report", str(folder), "-o", str(out), "--scatter", str(scatter), "--offset-limit", "30"]) == 0
    checked = 0
    for path in sorted(out.parent.glob("*.csv")):
        with path.open(newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        for c, name in enumerate(rows[0]):
            if not name.startswith(("utilisation", "margin")):
                continue
            for row in rows[1:]:
                cell = row[c].strip().lower()
                assert cell == "" or math.isfinite(float(cell)), (path.name, name, cell)
                checked += cell != ""
    assert checked == 14 + 10  # 14 checks with a margin each; utilisations for all but the 4 drag anchors
    chk = pd.read_csv(out.parent / "report_checks.csv")
    uplift = chk[chk["check"] == "anchor uplift"]
    assert len(uplift) == 4 and (uplift["status"] == "FAIL").all() and uplift["utilisation [-]"].isna().all()
    np.testing.assert_array_equal(uplift["margin [N or m, see unit]"], -uplift["demand [N or m, see unit]"])
    page = _page(out)
    _one_format_per_column(page)  # no infinite or NaN number in any numeric table, one format per column
    rows = page.tables["num checks uplift"]
    assert len(rows) == 1 + 4
    for row in rows[1:]:
        assert row[1] == "anchor uplift" and row[6] == "\u2013" and _value(row[5]) < -500  # no utilisation; margin
    text = out.read_text(encoding="utf-8")
    assert "&infin;" not in text and "\u221e" not in text
    # the summary says it by the margin: one card for the four drag anchors, the worst of them
    assert re.search(r"anchor uplift: capacity 0, 4 fail \(worst: anchor of L\d\)</div><div class=\"v\">margin "
                     r"&minus;\d+ kN</div>", text)


def test_a_report_inside_its_sweep_folder_names_the_folder_in_words(synth, tmp_path, files_only):
    """Written into the sweep's own folder (as the demo does), the source relative to the page is '.': the
    Inputs table says "the report's own folder" rather than a bare dot. (A sweep of two runs of one line: the
    words are the folder's, whatever the sweep; the 20 records of ``built_sweep`` took 2 s more to report.)"""
    runs = [({"environment.waves.seed": float(k)},
             synth.result({"L1": _record(k)}, case=synth.case(hs=4.0, tp=9.0, seed=k, lines=("L1",))))
            for k in range(2)]
    folder = synth.sweep(tmp_path / "sw", runs)
    out = folder / "report_here.html"
    assert main(["report", str(folder), "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert "<td>the report's own folder</td>" in text and "<code>.</code>" not in text


@pytest.mark.skipif(shutil.which(CHROMIUM) is None,
                    reason=f"{CHROMIUM} is missing (Debian's 'chromium' package: .ci/run installs it)")
def test_the_cable_section_renders_in_headless_chromium(tmp_path, browser):
    """A cable's report (issue 40: range graphs and checks of a clamped 160 m cable, EI 2e4 N m^2, 3 s of hang-off
    motion) in a real browser: no console message, and its section drawn. Without the cable section the page is
    the mooring tables alone; with it, the range graphs' five panels add their light-blue min-to-max bands
    ((191, 219, 235): 38 600 px when this was written, none anywhere else on the page) and the allowable tension's
    and the MBR's dashed red lines ((206, 59, 59): 1 800 px)."""
    from PIL import Image

    import seacable as sc
    from seacable.report import make_report

    ds = sc.run(sc.Case(name="hang", line_types={"cable": {"diameter": 0.15, "mass_per_length": 40, "axial_stiffness": 5e8,
                                 "bending_stiffness": 2e4, "minimum_bend_radius": 2.0,
                                 "minimum_bend_radius_dynamic": 4.0, "allowable_tension": 2.5e4}}, line={"line_type": "cable", "length": 160}, environment={"depth": 100}, analysis={"type": "mooring_dynamic", "anchor": [0, -100], "fairlead": [80, -10], "n_elements": 20,
                     "fairlead_end_condition": {"type": "clamped", "declination": 0.1},
                     "duration": 3.0, "time_step": 0.1, "output_interval": 0.5,
                     "motion": {"type": "harmonic", "amplitude": [1.0, 0.0, 0.5], "period": 4.0, "ramp": 1.0}}))
    page = tmp_path / "report.html"
    make_report(ds, page)
    assert "6. Cable: range graphs and checks" in page.read_text()
    png = tmp_path / "report.png"
    assert browser.console(browser.start(page, png, tmp_path / "profile", size=(1280, 8000))) == []
    rgb = np.asarray(Image.open(png).convert("RGB"), dtype=int)
    assert browser.near(rgb, (191, 219, 235), 3) > 20_000
    assert browser.near(rgb, (206, 59, 59), 3) > 800

"""The documentation site (docs/) and its validation page: built offline, opened in headless Chromium.

The site is built here without the API pages' module contents (``-D seacable_quick=1``: every page, the theme,
the math, the case-file reference, the examples and the validation page are there; the full build with autodoc,
``.ci/run``'s, takes 25-60 s on 2 shared cores, this one 8-15 s) and from an evidence file this test writes (the
suite's own evidence file is written when the whole run ends, after this test). The evidence helper
(``tests/_evidence.py``) and the list of sources the page must carry are checked on their own.
"""

from __future__ import annotations

import ast
import html
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import _evidence
import numpy as np
import pytest

from .conftest import CHROMIUM

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
sphinx = pytest.importorskip("sphinx", reason="the docs extra (sphinx, numpydoc, furo) is not installed")
sys.path.insert(0, str(DOCS / "_ext"))
import seacable_docs  # noqa: E402, I001


# ----------------------------------------------------------------------------------------- the evidence helper

def test_check_asserts_and_records_what_it_compared(monkeypatch):
    monkeypatch.setattr(_evidence, "RECORDS", [])
    _evidence.check(1171.16, 1171.15, atol=0.1, source="Paper X", quantity="top tension", why="printed digits",
                    unit="N")
    _evidence.check([1.0, 2.0], [1.001, 2.0], rtol=2e-3, source="Paper X", quantity="two values", why="w")
    # a planted error: 1 % off with a 0.5 % tolerance fails, and is recorded as failed
    with pytest.raises(AssertionError, match="Paper X: wrong: ours 1.01 vs reference 1.0"):
        _evidence.check(1.01, 1.0, rtol=5e-3, source="Paper X", quantity="wrong", why="w")
    # a NaN never passes, whatever the tolerance
    with pytest.raises(AssertionError):
        _evidence.check(np.nan, 1.0, atol=1e9, source="Paper X", quantity="nan", why="w")
    first, pair, wrong, nan = _evidence.RECORDS
    assert first["passed"] and first["ours"] == 1171.16 and first["reference"] == 1171.15 and first["unit"] == "N"
    assert first["deviation"] == pytest.approx(0.01) and first["atol"] == 0.1 and first["rtol"] is None
    assert pair["passed"] and pair["ours"] == [1.0, 2.0] and pair["deviation"] == pytest.approx(1e-3)
    assert not wrong["passed"] and wrong["relative_deviation"] == pytest.approx(0.01)
    assert not nan["passed"]
    assert first["test"].endswith("test_docs_site.py::test_check_asserts_and_records_what_it_compared")
    # a check without a tolerance or a justification is refused
    with pytest.raises(ValueError, match="rtol or atol"):
        _evidence.check(1.0, 1.0, source="s", quantity="q", why="w")
    with pytest.raises(ValueError, match="why"):
        _evidence.check(1.0, 1.0, rtol=1e-3, source="s", quantity="q", why="")


def test_a_runs_records_are_merged_into_the_evidence_file(tmp_path, monkeypatch):
    """The controller's writer keeps the file's records of tests not run this time (their file still there) and
    replaces those of the tests run now; written atomically (no temporary file left)."""
    path = tmp_path / "evidence.json"
    monkeypatch.setenv("SEACABLE_EVIDENCE", str(path))
    this = "tests/unit/test_docs_site.py::t"
    old = [{"source": "A", "test": this, "passed": True},
           {"source": "B", "test": "tests/unit/test_cli.py::u", "passed": True},
           {"source": "C", "test": "tests/gone.py::v", "passed": True}]
    path.write_text(json.dumps({"records": old}))
    _evidence.write_records([{"source": "A2", "test": this, "passed": True}])
    got = json.loads(path.read_text())["records"]
    assert sorted(r["source"] for r in got) == ["A2", "B"]
    assert [p.name for p in tmp_path.iterdir()] == ["evidence.json"]


def _recorded_sources() -> set[str]:
    """The ``source=`` of every ``check(...)`` call in the tests (a string, or an f-string's constant start)."""
    def text(value, names):
        if isinstance(value, ast.Constant) and isinstance(value.value, str):
            return value.value
        if isinstance(value, ast.JoinedStr) and value.values and isinstance(value.values[0], ast.Constant):
            return value.values[0].value
        if isinstance(value, ast.Name):           # a name bound to a string in the file (``src = "..."``)
            return names.get(value.id)
        return None

    found = set()
    for path in (ROOT / "tests").rglob("test_*.py"):
        tree = ast.parse(path.read_text())
        names = {}
        for node in ast.walk(tree):
            if isinstance(node, ast.Assign) and len(node.targets) == 1:
                targets, values = node.targets[0], node.value
                pairs = (zip(targets.elts, values.elts) if isinstance(targets, ast.Tuple)
                         and isinstance(values, ast.Tuple) else [(targets, values)])
                for t, v in pairs:
                    if isinstance(t, ast.Name) and text(v, {}) is not None:
                        names[t.id] = text(v, {})
        for node in ast.walk(tree):
            if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "check":
                for kw in node.keywords:
                    if kw.arg == "source" and text(kw.value, names):
                        found.add(text(kw.value, names))
    return found


def test_the_validation_tests_record_every_source_the_page_must_carry():
    """Papers 000-004, WHOI Cable, MoorPy, MoorDyn, OrcaFlex, CableDyn and closed forms (the sources the README and
    the closing notes' validation tables cite) are each recorded by some test's ``check``; the docs build (``.ci/run``,
    after the suite) refuses an evidence file without one of them."""
    sources = _recorded_sources()
    missing = [s for s in seacable_docs.REQUIRED_SOURCES if not any(src.startswith(s) for src in sources)]
    assert missing == [], missing
    # the published numbers the README quotes: the 80 m lazy wave against CableDyn and OrcaFlex, paper 000's
    # Table 2 and its WHOI Cable column, paper 001's Table 1 and paper 004's cable-buoy line
    text = "\n".join(p.read_text() for p in (ROOT / "tests" / "validation").glob("test_*.py"))
    for number in ("9320.17", "0.096834", '"tension": 9320.0', "TABLE2_WHOI", "34696.0"):
        assert number in text, number


# ------------------------------------------------------------------------------------------------ the site

def _evidence_file(path: Path) -> None:
    """A small evidence file: a record of every required source, one of them a list of values."""
    records = [{"source": f"{s} (test)", "quantity": f"q of {s}", "unit": "N", "ours": 1.0, "reference": 1.0005,
                "rtol": 1e-3, "atol": None, "deviation": 5e-4, "relative_deviation": 5e-4, "why": "printed digits",
                "passed": True, "test": "tests/validation/test_x.py::test_y"}
               for s in seacable_docs.REQUIRED_SOURCES]
    records[0].update(ours=[1.0, 2.0, 3.0, 4.0, 5.0], reference=[1.0, 2.0, 3.0, 4.0, 5.0], quantity="Table 2 tensions")
    path.write_text(json.dumps({"written": "2026-11-30T00:00:00Z", "records": records}))


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    out = tmp_path_factory.mktemp("site")
    evidence = out / "evidence.json"
    _evidence_file(evidence)
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "SEACABLE_EVIDENCE": str(evidence)}
    build = subprocess.run([sys.executable, "-m", "sphinx", "-W", "-q", "-b", "html", "-d", str(out / "doctrees"),
                            "-D", "seacable_quick=1", str(DOCS), str(out / "html")],
                           capture_output=True, text=True, env=env, timeout=300, check=False)
    assert build.returncode == 0, build.stderr[-3000:]
    return out / "html"


def test_the_site_has_its_pages_and_asks_nothing_of_the_network(site):
    for page in ("index", "getting_started", "validation", "case_reference", "examples", "vocabulary", "api",
                 "models/towed", "models/laying", "models/modal", "models/towline", "models/mooring",
                 "models/systems", "models/cables", "models/lay_planning", "models/design", "models/units",
                 "models/view3d", "models/seabed", "files"):
        assert (site / f"{page}.html").is_file(), page
    # MathJax is the site's own copy; no page loads a script, a style sheet or a font from elsewhere
    assert (site / "_static" / "mathjax" / "tex-chtml.js").is_file()
    for page in site.rglob("*.html"):
        text = page.read_text()
        for attr in ('src="http', "src='http", 'href="//', 'src="//'):
            assert attr not in text, (page, attr)
        assert "<link rel=\"stylesheet\" href=\"http" not in text, page
    # the examples page shows every example file, and the pre-built figures (docs/make_figures.py)
    examples = (site / "examples.html").read_text()
    for path in (ROOT / "examples").glob("*.yaml"):
        assert f'id="example-{path.stem.replace("_", "-")}"' in examples, path.stem
    for png in (DOCS / "_static" / "examples").glob("*.png"):
        assert f'src="_images/{png.name}"' in examples, png.name
    towed = (site / "models" / "towed.html").read_text()
    assert "../_static/mathjax/tex-chtml.js" in towed and "\\frac{\\partial T}{\\partial s}" in towed


def test_the_case_reference_is_the_schema(site):
    """Every key of every model of the schema is in the page, with its unit (a planted key missing from the page,
    or a unit lost, fails here)."""
    from seacable.io.case_file import case_schema

    text = (site / "case_reference.html").read_text()
    for system in (False, True):
        schema = json.loads(case_schema(system=system))
        for name, model in schema["$defs"].items():
            assert f'id="case-{name.lower()}"' in text, name
            for key in model.get("properties", {}):
                assert f"<code class=\"docutils literal notranslate\"><span class=\"pre\">{key}</span></code>" \
                    in text, (name, key)
    # LineType.diameter: a number with a unit, in metres
    line_type = text[text.index('id="case-linetype"'):]
    row = line_type[line_type.index('<span class="pre">diameter</span>'):][:600]
    assert "number with unit" in row and "<td><p>m</p></td>" in row and "required" in row, row


def test_the_validation_page_tabulates_the_evidence(site):
    text = (site / "validation.html").read_text()
    for source in seacable_docs.REQUIRED_SOURCES:
        assert html.escape(f"{source} (test)", quote=False) in text, source
    assert "5 values, 1 to 5" in text and "rel 0.001" in text and "printed digits" in text
    n = len(seacable_docs.REQUIRED_SOURCES)
    assert f"{n} checks, {n} passed" in text


def test_a_missing_required_source_or_a_failed_check_fails_the_build(tmp_path):
    """The evidence file decides the build: without a record of a required source, or with a failed check, the
    -W build stops (so a CI run whose suite lost a validation check cannot publish the page)."""
    from sphinx.application import Sphinx  # noqa: F401  (the docs extra is installed: the site fixture needs it)

    evidence = tmp_path / "evidence.json"
    _evidence_file(evidence)
    data = json.loads(evidence.read_text())

    class Config:
        seacable_evidence = str(evidence)
        seacable_require_sources = True

    class App:
        config = Config()

    warnings: list[str] = []

    class Log:
        def warning(self, msg, *args):
            warnings.append(msg % args)

    old_logger, old_write = seacable_docs.logger, seacable_docs._write
    seacable_docs.logger, seacable_docs._write = Log(), lambda path, text: None
    try:
        seacable_docs.generate(App())
        assert warnings == []
        data["records"] = [r for r in data["records"] if not r["source"].startswith("MoorDyn")]
        data["records"][0]["passed"] = False
        evidence.write_text(json.dumps(data))
        seacable_docs.generate(App())
        assert any("required source 'MoorDyn'" in w for w in warnings), warnings
        assert any("a failed check" in w for w in warnings), warnings
        warnings.clear()
        Config.seacable_evidence = str(tmp_path / "absent.json")
        seacable_docs.generate(App())
        assert any("no evidence file" in w for w in warnings), warnings
    finally:
        seacable_docs.logger, seacable_docs._write = old_logger, old_write


#: a policy under which the page may load its own files (the site's folder: 'self' of a file page) and nothing else:
#: a request for anything else (a script, a style sheet, a font from the network) is refused and logged in the
#: browser's console
_OWN_FILES_ONLY = ("<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'self' 'unsafe-inline' "
                   "'unsafe-eval' data: blob:\">")
#: and no network at all: every request the browser makes goes to a proxy where nothing listens
_OFFLINE = ("--proxy-server=http://127.0.0.1:9", "--proxy-bypass-list=<-loopback>")


def _watched(page: Path, name: str, extra_head: str = "") -> Path:
    """A copy of ``page`` beside it (its links the same) under :data:`_OWN_FILES_ONLY`."""
    out = page.with_name(name)
    out.write_text(page.read_text().replace("<head>", "<head>" + _OWN_FILES_ONLY, 1)
                   .replace("</head>", extra_head + "</head>", 1))
    return out


def _dom(page: Path, profile: Path) -> subprocess.CompletedProcess:
    """The page's DOM after its scripts ran (MathJax typesetting), and its console on stderr."""
    return subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", *_OFFLINE,
                           f"--user-data-dir={profile}", "--enable-logging=stderr", "--v=0",
                           "--virtual-time-budget=8000", "--dump-dom", page.resolve().as_uri()],
                          capture_output=True, text=True, timeout=180, check=False)


@pytest.mark.skipif(shutil.which(CHROMIUM) is None,
                    reason=f"{CHROMIUM} is missing (Debian's 'chromium' package: .ci/run installs it)")
def test_the_index_page_opens_in_headless_chromium_offline(site, tmp_path, browser):
    """The index page in headless Chromium with no network and a policy that refuses anything but the site's own
    files: no console message (a refused request, a script error), the title and the navigation drawn; a page with
    a planted request to the network is seen refused; a page of equations is typeset by the site's own MathJax."""
    from PIL import Image

    png, planted_png = tmp_path / "index.png", tmp_path / "planted.png"
    index = _watched(site / "index.html", "watched_index.html")
    planted = _watched(site / "index.html", "watched_planted.html",
                       '<script src="https://cdn.example.org/mathjax/tex-chtml.js"></script>')
    runs = [browser.start(page, shot, tmp_path / f"profile_{k}", size=(1280, 900),
                          extra=[*_OFFLINE, "--virtual-time-budget=5000"])
            for k, (page, shot) in enumerate(((index, png), (planted, planted_png)))]
    console, console_planted = (browser.console(run) for run in runs)
    assert console == [], console
    assert any("Loading the script 'https://cdn.example.org/mathjax/tex-chtml.js' violates" in line
               for line in console_planted), console_planted
    dom = _dom(index, tmp_path / "profile_dom")
    assert dom.returncode == 0, dom.stderr[-2000:]
    page = dom.stdout
    assert "<title>seacable" in page and "sidebar-tree" in page
    for entry in ("Getting started", "Models", "Case-file reference", "Validation", "API reference"):
        assert f">{entry}</a>" in page, entry
    rgb = np.asarray(Image.open(png).convert("RGB"), dtype=int)
    assert rgb.shape == (900, 1280, 3)
    # text drawn: dark pixels in the navigation (left) and in the page (the title and the text)
    dark = np.all(rgb < 90, axis=-1)
    assert dark[:, :300].sum() > 500 and dark[:, 300:].sum() > 2000, (dark[:, :300].sum(), dark[:, 300:].sum())
    # the towed-cable page's equations, typeset offline (MathJax's output elements in the DOM), nothing refused
    towed = _dom(_watched(site / "models" / "towed.html", "watched_towed.html"), tmp_path / "profile_math")
    assert towed.returncode == 0, towed.stderr[-2000:]
    assert towed.stdout.count("<mjx-container") >= 5, towed.stdout.count("<mjx-container")
    assert [line for line in towed.stderr.splitlines() if "CONSOLE" in line] == []

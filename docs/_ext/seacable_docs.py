"""Pages of seacable's documentation written at build time: the case-file reference, the examples, the validation.

``case_reference.rst``
    Every model of a case file (single-line cases and mooring-system cases) from the pydantic JSON schema
    (``seacable.io.case_file.case_schema``): every key with its type, unit, default and description, as the
    schema (and so ``seacable schema``) states them.
``examples.rst``
    Every ``examples/*.yaml`` with its description, its analysis and the file itself; the figures the example
    makes where ``docs/_static/examples/NAME*.png`` holds them (pre-built: no case is run at build time).
``validation.rst``
    The evidence the test suite recorded (``tests/_evidence.py``: each ``check`` of ours against a published
    number, a peer code or a closed form): a table per source. Made from the evidence file
    (``seacable_evidence`` in ``conf.py``: ``build/evidence/evidence.json``, which ``python -m pytest`` writes).
    A missing file, a failed check or a required source without a record is a build warning (an error under
    ``-W``): the page never shows numbers the suite did not produce. ``-D seacable_require_sources=0`` turns the
    required-source check off (the suite's docs test builds the site from a small file of its own).
"""

from __future__ import annotations

import json
import math
import os
import re
import tempfile
from pathlib import Path

from sphinx.util import logging

logger = logging.getLogger(__name__)

DOCS = Path(__file__).resolve().parents[1]
ROOT = DOCS.parent

#: The sources the validation page must carry (the published numbers the README and the closing notes cite): a
#: record's source must start with one of these; ``tests/unit/test_docs_site.py`` checks that the tests record
#: each of them, and the build (with ``seacable_require_sources``) that the evidence file holds them.
REQUIRED_SOURCES = (
    "Paper 000",
    "WHOI Cable",
    "Paper 001",
    "Paper 002",
    "Paper 003",
    "Paper 004",
    "MoorPy",
    "MoorDyn",
    "OrcaFlex",
    "CableDyn",
    "Lowe & Langley",
    "Closed form",
)


def _write(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` atomically, and only if it changed (Sphinx then rebuilds only what changed)."""
    if path.is_file() and path.read_text() == text:
        return
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _cell(text: str) -> str:
    """One line of a list-table cell: no line breaks; characters rst would read as markup escaped."""
    text = " ".join(str(text).split())
    return text.replace("\\", "\\\\").replace("*", "\\*").replace("|", "\\|").replace("_ ", "\\_ ")


def _title(text: str, char: str) -> str:
    return f"{text}\n{char * len(text)}\n"


# ---------------------------------------------------------------------------------------- case-file reference

def _type(prop: dict) -> str:
    """A short type of a schema property: number, string, a model's name (linked), list of ..., one of ..."""
    if "$ref" in prop:
        name = prop["$ref"].rsplit("/", 1)[-1]
        return f":ref:`{name} <case-{name.lower()}>`"
    if "const" in prop:
        return f"``{json.dumps(prop['const'])}``"
    if "enum" in prop:
        return "one of " + ", ".join(f"``{json.dumps(v)}``" for v in prop["enum"])
    for key in ("anyOf", "oneOf"):
        if key in prop:
            parts = []
            for p in prop[key]:
                t = _type(p)
                if p.get("type") == "string" and "pattern" in p and "unit" in str(p.get("description", "")):
                    t = "number with unit"
                if t not in parts:
                    parts.append(t)
            return " or ".join(parts)
    t = prop.get("type")
    if t == "array":
        if "prefixItems" in prop:
            return "[" + ", ".join(_type(p) for p in prop["prefixItems"]) + "]"
        return "list of " + _type(prop.get("items", {}))
    if t == "object":
        extra = prop.get("additionalProperties")
        return f"mapping of name to {_type(extra)}" if isinstance(extra, dict) else "mapping"
    if isinstance(t, list):
        return " or ".join(t)
    return t or "any"


def _unit(prop: dict) -> str:
    if "unit" in prop:
        return str(prop["unit"])
    for key in ("anyOf", "oneOf"):
        for p in prop.get(key, []):
            u = _unit(p)
            if u:
                return u
    return ""


def _default(prop: dict, required: bool) -> str:
    if required:
        return "required"
    if "default" not in prop:
        return ""
    text = json.dumps(prop["default"])
    return f"``{text}``" if len(text) <= 60 else "(a model of defaults: see its table)"


def _model_section(name: str, schema: dict, anchor_prefix: str = "case-") -> list[str]:
    lines = [f".. _{anchor_prefix}{name.lower()}:", "", _title(name, "~")]
    desc = schema.get("description", "").strip().split("\n\n")[0]
    if desc:
        lines += [_cell(desc), ""]
    props = schema.get("properties", {})
    if not props:
        return lines
    required = set(schema.get("required", []))
    lines += [".. list-table::", "   :header-rows: 1", "   :widths: 18 20 8 14 40", "",
              "   * - key", "     - type", "     - unit", "     - default", "     - description"]
    for key, prop in props.items():
        lines += [f"   * - ``{key}``", f"     - {_type(prop)}", f"     - {_cell(_unit(prop))}",
                  f"     - {_default(prop, key in required)}", f"     - {_cell(prop.get('description', ''))}"]
    return lines + [""]


def case_reference() -> str:
    """The case-file reference page (rst) from the schemas of single-line and mooring-system cases."""
    from seacable.io.case_file import case_schema

    out = [".. This page is generated by docs/_ext/seacable_docs.py from the case schema: do not edit.", "",
           _title("Case-file reference", "="),
           ("Every key a case file takes, from the schema ``seacable schema`` prints (``--system`` for mooring "
            "systems). A number is SI; a key whose type says *number with unit* also takes a number and a unit "
            "(``3 kn``, ``45 deg``; see :doc:`models/units`). Unknown keys are refused with a suggestion."), ""]
    done: set[str] = set()
    for title, system, prefix in (("Single-line cases", False, "case-"), ("Mooring-system cases", True, "system-")):
        schema = json.loads(case_schema(system=system))
        out += [_title(title, "-")]
        top = schema.get("title", "Case")
        out += _model_section(top, schema, prefix)
        for name in sorted(schema.get("$defs", {})):
            if system and name in done:
                continue
            # one anchor a model name: the system's models of the same name are the single-line ones
            out += _model_section(name, schema["$defs"][name], "case-")
            done.add(name)
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------------------------------------- examples

def examples_page() -> str:
    import yaml

    out = [".. This page is generated by docs/_ext/seacable_docs.py from examples/*.yaml: do not edit.", "",
           _title("Examples", "="),
           ("The case files in ``examples/``: run one with ``seacable run examples/NAME.yaml -o out/NAME.nc`` "
            "(its figures beside the result); ``python examples/demo.py`` runs the main ones. Figures shown here "
            "were made by those runs (``python docs/make_figures.py``) and are kept in ``docs/_static/examples``: "
            "the site does not run cases."), ""]
    figures = DOCS / "_static" / "examples"
    for path in sorted((ROOT / "examples").glob("*.yaml")):
        data = yaml.safe_load(path.read_text()) or {}
        analysis = (data.get("analysis") or {}).get("type", "")
        out += [f".. _example-{path.stem}:", "", _title(path.stem, "-")]
        desc = data.get("description") or ""
        if desc:
            out += [_cell(desc), ""]
        if analysis:
            out += [f"Analysis: ``{analysis}``.", ""]
        for png in sorted(figures.glob(f"{path.stem}_*.png")):
            out += [f".. figure:: _static/examples/{png.name}", "   :width: 90%", "", f"   ``{png.name}``", ""]
        out += [f".. literalinclude:: ../examples/{path.name}", "   :language: yaml", ""]
    return "\n".join(out) + "\n"


# -------------------------------------------------------------------------------------------- validation

def _fmt(value) -> str:
    if isinstance(value, list):
        if len(value) <= 4:
            return ", ".join(_fmt(v) for v in value)
        return f"{len(value)} values, {_fmt(min(value))} to {_fmt(max(value))}"
    if value is None:
        return ""
    v = float(value)
    return f"{v:.6g}"


def _tolerance(r: dict) -> str:
    parts = []
    if r.get("rtol") is not None:
        parts.append(f"rel {r['rtol']:.3g}")
    if r.get("atol") is not None:
        parts.append(f"abs {r['atol']:.3g} {r.get('unit', '')}".strip())
    return " or ".join(parts)


def validation_page(evidence: dict | None, path: str) -> str:
    out = [".. This page is generated by docs/_ext/seacable_docs.py from the test suite's evidence file: do not edit.",
           "", _title("Validation", "="),
           ("Every number below was produced by the test suite: each validation test states what it checks "
            "against a reference (a paper's printed number, a peer code run on the same data, or a closed form) "
            "through ``tests/_evidence.py``'s ``check``, which asserts it and records it; the suite's run writes "
            "the records to ``build/evidence/evidence.json``, and this page is made from that file when the site is "
            "built (CI: ``.ci/run`` runs the suite, then builds the site). *ours* is the suite's value, *reference* "
            "the source's, *tolerance* what the test allows (relative to the reference, or absolute) and *why* its "
            "justification; a list of values shows its count and range, and the deviation is the largest."), ""]
    if evidence is None:
        out += [".. warning::", "", f"   No evidence file was found (``{path}``): run ``python -m pytest`` first.", ""]
        return "\n".join(out) + "\n"
    records = evidence.get("records", [])
    passed = sum(1 for r in records if r.get("passed"))
    out += [f"Recorded {evidence.get('written', '?')} UTC: {len(records)} checks, {passed} passed.", ""]
    by_source: dict[str, list[dict]] = {}
    for r in records:
        by_source.setdefault(r["source"], []).append(r)
    for source in sorted(by_source):
        out += [_title(source, "-"),
                ".. list-table::", "   :header-rows: 1", "   :widths: 40 15 15 11 13 6", "",
                "   * - quantity (why the tolerance; the test file)", "     - ours", "     - reference",
                "     - tolerance", "     - deviation", "     - pass"]
        for r in by_source[source]:
            unit = f" {r['unit']}" if r.get("unit") else ""
            dev = _fmt(r.get("deviation"))
            rel = r.get("relative_deviation")
            if rel is not None and not math.isnan(rel):
                dev += f" ({rel:.2g} rel)"
            test = r.get("test", "").split("::")   # the file (the function is in the evidence file)
            out += [f"   * - {_cell(r['quantity'])}", "",
                    f"       *why:* {_cell(r.get('why', ''))} (``{_cell(test[0].rsplit('/', 1)[-1])}``)",
                    f"     - {_cell(_fmt(r['ours']) + unit)}",
                    f"     - {_cell(_fmt(r['reference']) + unit)}", f"     - {_cell(_tolerance(r))}",
                    f"     - {_cell(dev)}", f"     - {'yes' if r.get('passed') else '**NO**'}"]
        out.append("")
    return "\n".join(out) + "\n"


def _load_evidence(path: str) -> dict | None:
    try:
        return json.loads(Path(path).read_text())
    except (OSError, ValueError):
        return None


def generate(app) -> None:
    """Write the three generated pages into the source folder (``builder-inited``)."""
    _write(DOCS / "case_reference.rst", case_reference())
    _write(DOCS / "examples.rst", examples_page())
    path = app.config.seacable_evidence
    evidence = _load_evidence(path)
    if evidence is None:
        logger.warning("validation page: no evidence file at %s (run 'python -m pytest' first, or set "
                       "SEACABLE_EVIDENCE)", path)
    else:
        records = evidence.get("records", [])
        failed = [r for r in records if not r.get("passed")]
        for r in failed:
            logger.warning("validation page: a failed check: %s: %s (%s)", r["source"], r["quantity"], r["test"])
        if app.config.seacable_require_sources:
            for source in REQUIRED_SOURCES:
                if not any(r["source"].startswith(source) for r in records):
                    logger.warning("validation page: no record of the required source %r in %s", source, path)
    _write(DOCS / "validation.rst", validation_page(evidence, path))


# ------------------------------------------------------------------------------ docstrings read as rst

_CODE = re.compile(r"(``.+?``|:math:`[^`]+`|`[^`]+`_*)")


def _escape_plain(text: str) -> str:
    """Escape what plain prose in a docstring means but rst reads as markup: ``|x|`` (an absolute value, not a
    substitution) and a ``*`` before a name (``(nt, *P, 3)``, not emphasis); code and math spans are kept."""
    parts = _CODE.split(text)
    for k in range(0, len(parts), 2):
        parts[k] = re.sub(r"(?<!\\)\|", r"\\|", parts[k])
        parts[k] = re.sub(r"(?<=[\s(,\[])\*(?=\w)", r"\\*", parts[k])
    return "".join(parts)


def fix_docstring(app, what, name, obj, options, lines) -> None:
    """Read the docstrings' prose as the text it is (``autodoc-process-docstring``, after numpydoc): escape
    :func:`_escape_plain`'s characters outside code, math and literal blocks; a citation ``[N]_`` whose
    reference is not in the same docstring (a module's references cited by its functions) is shown as ``[N]``.
    A ``typing`` alias's docstring (``typing.Literal``'s, which autodoc finds on a module's alias) is dropped."""
    if getattr(obj, "__module__", None) == "typing":
        lines[:] = []
        return
    defined = {m.group(1) for line in lines for m in re.finditer(r"^\s*\.\. \[([^\]]+)\]", line)}
    block_indent = None
    out: list[str] = []
    for line in lines:
        stripped = line.strip()
        indent = len(line) - len(line.lstrip())
        if block_indent is not None:
            if stripped and indent <= block_indent:
                block_indent = None
            else:
                out.append(line)
                continue
        if stripped.startswith((".. math::", ".. code")) or stripped.endswith("::"):
            block_indent = indent
            out.append(line)
            continue
        fixed = _escape_plain(line)
        fixed = re.sub(r"\[(\w+)\]_", lambda m: m.group(0) if m.group(1) in defined or m.group(1).startswith("R")
                       else f"[{m.group(1)}]", fixed)
        out.append(fixed)
    lines[:] = out


def _quick(app, config) -> None:
    """``-D seacable_quick=1``: the site without the API's module contents (``automodule`` writes nothing), for the
    test suite's build (the pages, the theme, the math and the generated pages are all there)."""
    if config.seacable_quick:
        from docutils.parsers.rst import Directive

        class _Nothing(Directive):
            has_content = True
            optional_arguments = 1
            final_argument_whitespace = True
            option_spec = None

            def run(self):
                return []

        _Nothing.option_spec = {k: (lambda x: x) for k in ("members", "no-members", "noindex", "no-index")}
        app.add_directive("automodule", _Nothing, override=True)


def setup(app):
    app.add_config_value("seacable_evidence", str(ROOT / "build" / "evidence" / "evidence.json"), "env")
    app.add_config_value("seacable_require_sources", True, "env", types=(bool, int))
    app.add_config_value("seacable_quick", False, "env", types=(bool, int))
    app.connect("config-inited", _quick)
    app.connect("builder-inited", generate)
    app.connect("autodoc-process-docstring", fix_docstring, priority=600)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}

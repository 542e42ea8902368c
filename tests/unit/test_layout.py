"""The package's layering: no two modules import each other, and a lower layer never imports a higher one.

The import graph is read from the source (every ``import``, including those inside functions, which are
the usual way to hide a circle), so a circle fails here before it fails at import time in some order.
"""

from __future__ import annotations

import ast
from pathlib import Path

import seacable

ROOT = Path(seacable.__file__).parent


def _module_name(path: Path) -> str:
    parts = path.relative_to(ROOT.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path: Path, modules: set[str]) -> set[str]:
    """The seacable modules ``path`` imports (a name imported from a package counts as its submodule if one)."""
    name = _module_name(path)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.startswith("seacable"))
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.rsplit(".", node.level - 1)[0] if node.level > 1 else package
                target = f"{base}.{node.module}" if node.module else base
            else:
                target = node.module or ""
            if not target.startswith("seacable"):
                continue
            subs = {f"{target}.{a.name}" for a in node.names} & modules
            found.update(subs or {target})
    return {m for m in found if m in modules and m != name}


def _graph():
    files = sorted(ROOT.rglob("*.py"))
    modules = {_module_name(p) for p in files}
    return {_module_name(p): _imports(p, modules) for p in files}


def _is_package_link(a: str, b: str) -> bool:
    """A package's ``__init__`` re-exporting its own submodules is not a circle of layers."""
    return a.startswith(b + ".") or b.startswith(a + ".")


def test_no_two_modules_import_each_other():
    graph = _graph()
    pairs = sorted({tuple(sorted((a, b))) for a, deps in graph.items() for b in deps
                    if a in graph.get(b, ()) and not _is_package_link(a, b)})
    assert pairs == []


def test_lower_layers_do_not_import_higher_ones():
    graph = _graph()
    low = ["seacable.line", "seacable.environment", "seacable.waves", "seacable.statics.catenary",
           "seacable.statics.multisegment", "seacable.statics.towed", "seacable.statics.laying",
           "seacable.modal.eigen", "seacable.modal.vertical", "seacable.modal.wave_speed"]
    high = {"seacable.case", "seacable.simulate", "seacable.results", "seacable.cli", "seacable.io",
            "seacable.sweeps", "seacable.extremes"}

    def reach(start):
        seen, todo = set(), [start]
        while todo:
            for dep in graph[todo.pop()]:
                if dep not in seen:
                    seen.add(dep)
                    todo.append(dep)
        return seen

    bad = {m: sorted(d for d in reach(m) if d in high or d.startswith(("seacable.plot", "seacable.io.")))
           for m in low if m in graph}
    assert {m: d for m, d in bad.items() if d} == {}


def test_the_graph_sees_a_planted_circle(tmp_path):
    """The check itself: two modules importing each other are found."""
    pkg = tmp_path / "seacable"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "a.py").write_text("def f():\n    from .b import g\n")
    (pkg / "b.py").write_text("from .a import f\n")
    global ROOT
    saved, ROOT = ROOT, pkg
    try:
        graph = _graph()
    finally:
        ROOT = saved
    assert graph["seacable.a"] == {"seacable.b"} and graph["seacable.b"] == {"seacable.a"}

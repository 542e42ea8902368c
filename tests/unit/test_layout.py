"""The package's layering: no import circle of any length, and a lower layer never imports a higher one.

The import graph is read from the source (every ``import``, including those inside functions, which are
the usual way to hide a circle), so a circle fails here before it fails at import time in some order.
Circles are the strongly connected components of the whole graph (Tarjan), so a circle through 14
modules fails as a pair importing each other does.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

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


def _components(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of ``graph`` (Tarjan's algorithm), each a sorted list of modules.

    A package's ``__init__`` importing its own submodules is an edge like any other: it closes a circle
    only when a module below imports the package back, and that circle is a real one at import time (the
    package is then half initialised), so no edge is left out.
    """
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found = []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while not comp or comp[-1] != v:
                comp.append(stack.pop())
                on_stack.discard(comp[-1])
            found.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def _cycle(graph: dict[str, set[str]], component: list[str]) -> list[str]:
    """A shortest circle through the component's first module, ``[a, b, ..., a]`` (one of the imports to cut)."""
    members, start = set(component), component[0]
    previous, todo = {start: None}, [start]
    while todo:
        v = todo.pop(0)
        for w in sorted(graph[v] & members):
            if w == start:
                path = [v]
                while path[-1] != start:
                    path.append(previous[path[-1]])
                return [*reversed(path), start]
            if w not in previous:
                previous[w] = v
                todo.append(w)
    raise AssertionError(f"no circle through {start}")


@pytest.fixture(scope="module")
def package_graph():
    """The import graph of the installed package, read once for the tests of this file (a second each)."""
    return _graph()


def _circles(graph: dict[str, set[str]]) -> list[str]:
    """One line per import circle: its size, its modules and one circle through them."""
    return [f"{len(c)} modules {c}: " + " -> ".join(_cycle(graph, c))
            for c in _components(graph) if len(c) > 1]


def test_no_import_circle(package_graph):
    circles = _circles(package_graph)
    assert not circles, "import circles (cut one import of each):\n" + "\n".join(circles)


def _reach(graph: dict[str, set[str]], start: str) -> set[str]:
    """Every module ``start`` imports, directly or through others."""
    seen, todo = set(), [start]
    while todo:
        for dep in graph[todo.pop()]:
            if dep not in seen:
                seen.add(dep)
                todo.append(dep)
    return seen


def test_lower_layers_do_not_import_higher_ones(package_graph):
    graph = package_graph
    low = ["seacable.line", "seacable.environment", "seacable.waves", "seacable.statics.catenary",
           "seacable.statics.multisegment", "seacable.statics.towed", "seacable.statics.laying",
           "seacable.modal.eigen", "seacable.modal.vertical", "seacable.modal.wave_speed",
           "seacable.hydro.database", "seacable.hydro.wamit", "seacable.hydro.radiation",
           "seacable.hydro.cummins", "seacable.hydro.loads", "seacable.hydro.response", "seacable.wind"]
    high = {"seacable.case", "seacable.simulate", "seacable.results", "seacable.cli", "seacable.io",
            "seacable.sweeps", "seacable.extremes"}
    bad = {m: sorted(d for d in _reach(graph, m) if d in high or d.startswith(("seacable.plot", "seacable.io.")))
           for m in low if m in graph}
    assert {m: d for m, d in bad.items() if d} == {}


def _runs(module: str) -> bool:
    """An analysis (it runs a case) or anything above the analyses: files, sweeps, figures, the command line."""
    return (module.rpartition(".")[2] in ("run", "plan_run", "fe_run") or module in (
        "seacable", "seacable.simulate", "seacable.cli", "seacable.report", "seacable.report_cable", "seacable.extremes",
        "seacable.sink")
        or module.startswith(("seacable.io", "seacable.sweeps", "seacable.plot", "seacable.design",
                              "seacable.system.dynamics", "seacable.system.statics")))


def test_the_inputs_and_the_result_format_do_not_import_the_analyses(package_graph):
    """The cases (single line and system) and the result format sit below every analysis: an analysis
    imports its case and writes a result, never the other way round; the result format is below the cases
    too (it records a case it is given)."""
    graph = package_graph
    below = {"seacable.case": (), "seacable.system.case": (),
             "seacable.results": ("seacable.case", "seacable.system.case")}
    bad = {m: sorted(d for d in _reach(graph, m) if _runs(d) or d in above) for m, above in below.items()}
    assert {m: d for m, d in bad.items() if d} == {}


def _planted(tmp_path, files: dict[str, str]) -> dict[str, set[str]]:
    """The import graph of a package ``seacable`` made of ``files`` (path: text) under ``tmp_path``."""
    for name, text in files.items():
        path = tmp_path / "seacable" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    global ROOT
    saved, ROOT = ROOT, tmp_path / "seacable"
    try:
        return _graph()
    finally:
        ROOT = saved


def test_the_graph_sees_a_planted_circle(tmp_path):
    """The check itself: two modules importing each other are found."""
    graph = _planted(tmp_path, {"__init__.py": "", "a.py": "def f():\n    from .b import g\n",
                                "b.py": "from .a import f\n"})
    assert graph["seacable.a"] == {"seacable.b"} and graph["seacable.b"] == {"seacable.a"}
    assert _circles(graph) == ["2 modules ['seacable.a', 'seacable.b']: seacable.a -> seacable.b -> seacable.a"]


def test_the_check_sees_a_long_circle_and_names_a_path_through_it(tmp_path):
    """A circle of four modules, closed by an import inside a function in a subpackage, is one component;
    a package re-exporting its own submodules alone is none, but a submodule importing its package back is."""
    graph = _planted(tmp_path, {
        "__init__.py": "from .a import f\n",                   # re-exports: no circle by itself
        "a.py": "from . import b\n", "b.py": "from .sub.c import g\n",
        "sub/__init__.py": "", "sub/c.py": "from ..d import h\n",
        "d.py": "def h():\n    from .a import f\n",           # closes a -> b -> sub.c -> d -> a
        "e.py": "from .a import f\n",                          # outside the circle
        "p/__init__.py": "from .q import k\n", "p/q.py": "from seacable.p import k2\n"})
    assert _circles(graph) == [
        ("4 modules ['seacable.a', 'seacable.b', 'seacable.d', 'seacable.sub.c']: "
         "seacable.a -> seacable.b -> seacable.sub.c -> seacable.d -> seacable.a"),
        "2 modules ['seacable.p', 'seacable.p.q']: seacable.p -> seacable.p.q -> seacable.p"]


#: The longest a source module may be (issue 38): a longer one is split by responsibility.
MAX_MODULE_LINES = 1000


def test_no_source_module_is_over_a_thousand_lines():
    long = {str(p.relative_to(ROOT.parent)): n for p in sorted(ROOT.rglob("*.py"))
            if (n := len(p.read_text(encoding="utf-8").splitlines())) > MAX_MODULE_LINES}
    assert not long, f"modules over {MAX_MODULE_LINES} lines (split them by responsibility): {long}"

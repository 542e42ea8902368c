"""A quick ``import seacable``: what it and the light entry points load, and that every public name resolves.

``import seacable`` must not load numba, xarray, pandas, matplotlib, Dask or SciPy's solvers (issue 38):
they come with the first function that needs them (:mod:`seacable._lazy`, :mod:`seacable._jit`). The
checks are structural (which modules a fresh interpreter has loaded), not timed; ``bench/bench_import.py``
prints the times.
"""

from __future__ import annotations

import ast
import importlib
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import seacable

ROOT = Path(seacable.__file__).parent
EXAMPLES = ROOT.parents[1] / "examples"
#: pint (case files' units, issue 41) is loaded by the first unit a case file holds, not by plain numbers: its import
#: brings Dask's base
HEAVY = ("numba", "xarray", "pandas", "matplotlib", "dask", "scipy.optimize", "pint")


def _loaded_after_each(codes: list[str]) -> list[set[str]]:
    """The modules one fresh interpreter has loaded after each of ``codes``, run one after another.

    One interpreter for several probes: a module that a probe needs is in the set after it whether or not an
    earlier probe loaded it first (``sys.modules`` only grows), so "no heavy module after probe k" holds for
    probe k run alone too; a failing probe fails the probes after it as well."""
    marker = "seacable-probe-modules:"
    steps = [f"{code}\nprint({marker!r} + json.dumps(sorted(sys.modules)), flush=True)" for code in codes]
    probe = "import json, sys\n" + "\n".join(f"exec({step!r})" for step in steps)
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=False,
                         cwd=ROOT.parents[1], env={**os.environ, "PYTHONPATH": str(ROOT.parent)})
    found = [set(json.loads(line[len(marker):])) for line in out.stdout.splitlines() if line.startswith(marker)]
    assert out.returncode == 0 and len(found) == len(codes), out.stderr
    return found  # with the probe's json, imported before the first code (no library of HEAVY)


def _heavy(modules: set[str], heavy=HEAVY) -> list[str]:
    return sorted(m for m in heavy if m in modules)


CASES = ("paper002_vertical_cable.yaml", "spread_mooring.yaml", "paper003_zigzag.yaml")
VALIDATED = ["paper002_vertical_cable.yaml", "oc3_hywind_static.yaml", "oc3_hywind_modes.yaml",
             "paper004_lena_pushover.yaml"]


@pytest.fixture(scope="module")
def loaded_after() -> dict:
    """The modules one fresh interpreter has loaded after each probe, run one after another: ``import seacable``
    ("seacable"), the command's parser ("cli"), reading each case of :data:`CASES` (its name), and ``seacable
    validate`` of each of :data:`VALIDATED` (("validate", its name)). Each probe is checked on what is loaded
    after it, so the lighter probes come first (was three interpreters, and one per probe before that: a fresh
    interpreter's start and imports were most of each test's time)."""
    codes = {"seacable": "import seacable", "cli": "import seacable.cli"}
    codes.update({name: f"import seacable; seacable.load_case({str(EXAMPLES / name)!r})" for name in CASES})
    codes.update({("validate", name): f"from seacable.cli import main\nassert main(['validate', "
                                      f"{str(EXAMPLES / name)!r}]) == 0" for name in VALIDATED})
    return dict(zip(codes, _loaded_after_each(list(codes.values())), strict=True))


def test_import_seacable_loads_none_of_the_heavy_libraries(loaded_after):
    modules = loaded_after["seacable"]
    assert "seacable" in modules
    assert _heavy(modules, HEAVY + ("scipy",)) == []


def test_the_command_line_and_reading_a_case_load_only_what_they_need(loaded_after):
    # the command's parser (seacable --help) needs none of them, not even NumPy
    assert _heavy(loaded_after["cli"], HEAVY + ("scipy", "numpy")) == []
    # a case and its checks are pydantic models: no compiled kernels, no Dataset, no solver
    for name in CASES:
        assert _heavy(loaded_after[name], HEAVY + ("scipy",)) == [], name


@pytest.mark.parametrize("name", VALIDATED)
def test_validate_of_a_static_or_modal_case_builds_no_dataset(name, loaded_after):
    """``seacable validate`` solves a static or modal case (the runner's own ``solve_*``) but builds no Dataset:
    no xarray, pandas, Dask or matplotlib (the finite-element statics of a mooring line do load numba)."""
    assert _heavy(loaded_after["validate", name], ("xarray", "pandas", "dask", "matplotlib")) == [], name


def test_every_public_name_resolves():
    for name in seacable.__all__:
        assert getattr(seacable, name) is not None, name
    assert set(seacable.__all__) <= set(dir(seacable))
    namespace: dict = {}
    exec("from seacable import *", namespace)  # noqa: S102  (the star import a user may write)
    assert set(seacable.__all__) <= set(namespace)
    with pytest.raises(AttributeError, match="no attribute 'no_such_name'"):
        seacable.no_such_name  # noqa: B018


def _lazy_packages() -> list[str]:
    """The packages whose ``__init__`` declares its names with ``_lazy.lazy_names``."""
    found = []
    for path in sorted(ROOT.rglob("__init__.py")):
        if "lazy_names(" in path.read_text():
            rel = path.parent.relative_to(ROOT.parent)
            found.append(".".join(rel.parts))
    return found


def _type_checking_imports(package: str) -> dict[str, str]:
    """name -> absolute module of the imports in the ``if TYPE_CHECKING:`` block of ``package``'s ``__init__``."""
    tree = ast.parse((ROOT.parent / package.replace(".", "/") / "__init__.py").read_text())
    names = {}
    for node in tree.body:
        if isinstance(node, ast.If) and getattr(node.test, "id", None) == "TYPE_CHECKING":
            for imp in node.body:
                assert isinstance(imp, ast.ImportFrom) and imp.level == 1, ast.dump(imp)
                for alias in imp.names:
                    module = f"{package}.{imp.module}" if imp.module else f"{package}.{alias.name}"
                    names[alias.asname or alias.name] = module
    return names


@pytest.mark.parametrize("package", _lazy_packages())
def test_the_type_checking_block_names_the_same_objects_as_the_lazy_table(package):
    """What type checkers and IDEs read (the TYPE_CHECKING imports) is what the package gives at run time."""
    pkg = importlib.import_module(package)
    table, subs = pkg.__getattr__.table, pkg.__getattr__.submodules
    declared = _type_checking_imports(package)
    assert set(declared) == set(table) | subs
    for name, module in declared.items():
        expected = importlib.import_module(module) if name in subs else getattr(importlib.import_module(module), name)
        assert getattr(pkg, name) is expected, name
    # every public name is either eager (errors, version) or in the table
    assert set(pkg.__all__) - set(table) - subs <= set(vars(pkg)), package
    # a submodule named like a lazy name would replace it in the package once imported
    files = {p.stem for p in (ROOT.parent / package.replace(".", "/")).iterdir() if p.suffix == ".py" or p.is_dir()}
    assert not set(table) & files, package


_DECORATORS = ("njit", "jit", "vectorize", "guvectorize", "cfunc", "generated_jit")


def _imports_numba_njit(tree: ast.AST) -> list[int]:
    """Lines that take a decorator from numba itself (``from numba import njit``, ``numba.njit``)."""
    lines = []
    for node in ast.walk(tree):
        from_numba = (isinstance(node, ast.ImportFrom) and (node.module or "").split(".")[0] == "numba"
                      and any(a.name in _DECORATORS for a in node.names))
        numba_attr = (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name)
                      and node.value.id == "numba" and node.attr in _DECORATORS)
        if from_numba or numba_attr:
            lines.append(node.lineno)
    return lines


def test_every_kernel_takes_its_njit_from_seacable_jit():
    """A kernel decorated with numba's own njit would be cached beside its source, keyed to its file only
    (the bug :mod:`seacable._numba_cache` fixes), whenever no other kernel module happened to be imported
    first; ``seacable._jit`` installs the cache locator before it hands out njit."""
    bad = {}
    for path in sorted(ROOT.rglob("*.py")):
        if path.name == "_jit.py" and path.parent == ROOT:
            continue
        text = path.read_text()
        if "numba" not in text:   # both forms name numba: a file that does not is not parsed (1 s of the test)
            continue
        lines = _imports_numba_njit(ast.parse(text))
        if lines:
            bad[str(path.relative_to(ROOT))] = lines
    assert bad == {}, "take njit from seacable._jit ('from .._jit import njit'): " + repr(bad)


def test_the_njit_check_sees_a_planted_import():
    assert _imports_numba_njit(ast.parse("from numba import njit, types\n")) == [1]
    assert _imports_numba_njit(ast.parse("import numba\n\n@numba.njit(cache=True)\ndef f():\n    pass\n")) == [3]
    assert _imports_numba_njit(ast.parse("from numba import types\nfrom .._jit import njit\n")) == []

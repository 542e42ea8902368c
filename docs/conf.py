"""Sphinx configuration of seacable's documentation site (``python -m sphinx -W -b html docs docs/_build/html``).

The site builds offline: the theme (furo), numpydoc and MathJax (``sphinx-mathjax-offline``, copied into the
site) come from the ``docs`` and ``test`` extras; nothing is fetched at build time or when a page is opened.
Three pages are written at build time by ``_ext/seacable_docs.py``: the case-file reference (from the pydantic
schema), the examples (from ``examples/*.yaml``) and the validation page (from the evidence file the test suite
writes, ``build/evidence/evidence.json``).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "_ext"))
sys.path.insert(0, str(HERE.parent / "src"))   # the source beside this folder, before an installed seacable

from seacable import __version__  # noqa: E402

project = "seacable"
author = "seacable developers"
copyright = "2026, seacable developers"
release = version = __version__

# no sphinx.ext.viewcode: its highlighted copy of every module (50 pages, each with furo's navigation) was a third of
# the build (29 -> 19 s), which CI runs after the suite; the source is in the repository
extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.mathjax",
    "numpydoc",
    "sphinx-mathjax-offline",     # MathJax 3 served from the site itself (no CDN)
    "seacable_docs",
]

# the API pages document what the docstrings say; numpydoc's own validation is not run (the docstrings are
# checked for units and references by the project's tests)
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False
numpydoc_validation_checks: set[str] = set()
autodoc_member_order = "bysource"
autodoc_typehints = "none"         # numpydoc's Parameters sections carry the types
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False}
# pydantic models: their fields are documented in the case-file reference
autodoc_pydantic_model_show_json = False

nitpicky = False
suppress_warnings = [
    # numpydoc renames a docstring's References ([1] -> [R...-1]); one not cited in the text is not an error
    "ref.citation",
    # numpydoc's See Also and the models' inherited pydantic docstrings point at names outside the pages
    "ref.python",
    # the same public class is reached through seacable and through its own module
    "autodoc.import_object",
]

templates_path: list[str] = []
exclude_patterns = ["_build", "Thumbs.db", ".DS_Store"]
html_theme = "furo"
html_title = f"seacable {release}"
html_static_path = ["_static"]
html_show_sourcelink = False
html_theme_options = {"navigation_with_keys": True}
# no external resource: furo's fonts are the system's; MathJax is copied in by sphinx-mathjax-offline
html_permalinks_icon = "#"

#: the evidence file the validation page is made from (written by the test suite's run)
seacable_evidence = os.environ.get("SEACABLE_EVIDENCE") or str(HERE.parent / "build" / "evidence" / "evidence.json")

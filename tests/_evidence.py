"""The validation ledger: a test states what it asserts against a reference, and the run records it.

A validation test calls :func:`check` where it would ``assert abs(ours - reference) <= tol``::

    from _evidence import check

    check(ours, 1.2045e6, rtol=2e-3, source="Paper 004 (Lena guyed tower)", quantity="fairlead tension [N]",
          why="the paper's figures are read to 3 digits")

It asserts (``rtol``: ``|ours - reference| <= rtol |reference|``; ``atol``: ``|ours - reference| <= atol``; both:
either holds, as ``numpy.isclose``), and it records the source, the quantity, our value, the reference value, the
tolerance with its justification and the test that made it. The suite's ``conftest.py`` collects the records of a
run (each pytest-xdist worker's, merged by the controller) and writes them atomically to
``build/evidence/evidence.json`` (or ``$SEACABLE_EVIDENCE``); the documentation's validation page is built from
that file (``docs/_ext/seacable_docs.py``). A failed check is recorded as failed, and the assertion is raised.

References in the records are the published numbers themselves: a check of a closed form passes the closed form's
value, a check of a peer code the peer's number (computed in the run or committed under ``tests/validation/data``).
"""

from __future__ import annotations

import math
import os
from typing import Any

import numpy as np

#: The records of this process: a dict a check (see :func:`check`); read by ``tests/conftest.py``.
RECORDS: list[dict[str, Any]] = []

#: Where a run's records are written (the docs build reads the same file): the repository's build folder
DEFAULT_PATH = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "build", "evidence",
                            "evidence.json")


def evidence_path() -> str:
    """The evidence file of a run: ``$SEACABLE_EVIDENCE`` or :data:`DEFAULT_PATH`."""
    return os.environ.get("SEACABLE_EVIDENCE") or DEFAULT_PATH


def _number(value) -> float | list:
    """A JSON number (or a list of them) for ``value``."""
    arr = np.asarray(value, dtype=float)
    if arr.ndim == 0:
        return float(arr)
    return [float(v) for v in arr.ravel()]


def _test_id() -> str:
    """The running test's node id (pytest sets ``PYTEST_CURRENT_TEST`` to ``'<nodeid> (call)'``)."""
    current = os.environ.get("PYTEST_CURRENT_TEST", "")
    return current.rsplit(" (", 1)[0]


def check(ours, reference, *, rtol: float | None = None, atol: float | None = None, source: str, quantity: str,
          why: str, unit: str = "") -> None:
    """Assert that ``ours`` matches ``reference`` within the tolerance, and record it for the validation page.

    Parameters
    ----------
    ours, reference : float or array_like
        Our value and the published (or closed-form, or peer-code) value; arrays are compared element-wise and the
        largest deviation is recorded.
    rtol, atol : float, optional
        Relative tolerance (of ``|reference|``) and absolute tolerance (in ``unit``); at least one. With both, a
        value passes if either holds (``numpy.isclose``'s rule).
    source : str
        The reference: the paper, the peer code and its version, or "closed form: ..." (the page's tables are by
        source).
    quantity : str
        What is compared, with the case (e.g. "fairlead tension, 5 m offset").
    why : str
        The tolerance's justification (the digits a paper prints, the discretisation's order, ...).
    unit : str
        The unit of ``ours``, ``reference`` and ``atol`` (SI; ``""`` for a number without dimension).
    """
    if rtol is None and atol is None:
        raise ValueError("check() needs rtol or atol: a tolerance and its justification")
    if not source or not quantity or not why:
        raise ValueError("check() needs a source, a quantity and why the tolerance is what it is")
    a = np.asarray(ours, dtype=float)
    b = np.asarray(reference, dtype=float)
    a, b = np.broadcast_arrays(a, b)
    dev = np.abs(a - b)
    limit = np.maximum(0.0 if atol is None else atol, 0.0 if rtol is None else rtol * np.abs(b))
    ok = bool(np.all(np.isfinite(a)) and np.all(dev <= limit))
    worst = int(np.argmax(np.where(np.isfinite(dev), dev - limit, np.inf))) if dev.size else 0
    rel = float(dev.ravel()[worst] / abs(b.ravel()[worst])) if dev.size and b.ravel()[worst] != 0 else math.nan
    RECORDS.append({
        "source": source, "quantity": quantity, "unit": unit,
        "ours": _number(ours), "reference": _number(reference),
        "rtol": rtol, "atol": atol, "deviation": float(dev.ravel()[worst]) if dev.size else 0.0,
        "relative_deviation": rel, "why": why, "passed": ok, "test": _test_id()})
    assert ok, (f"{source}: {quantity}: ours {float(a.ravel()[worst])!r} vs reference {float(b.ravel()[worst])!r}"
                f"{' ' + unit if unit else ''}; "
                f"deviation {dev.ravel()[worst]:.6g} > tolerance {limit.ravel()[worst]:.6g} "
                f"(rtol={rtol}, atol={atol}: {why})")


def write_records(records: list[dict[str, Any]]) -> None:
    """Write a run's ``records`` to :func:`evidence_path` atomically (a temporary file renamed into place), keeping
    the file's records of the tests not run this time whose test file still exists (a run of a few files updates
    their records and leaves the rest)."""
    import json
    import tempfile
    import time
    from pathlib import Path

    path = Path(evidence_path())
    root = Path(__file__).resolve().parents[1]
    ran = {r["test"] for r in records}
    try:
        old = json.loads(path.read_text())["records"]
    except (OSError, ValueError, KeyError, TypeError):
        old = []
    kept = [r for r in old if r.get("test") not in ran and (root / r.get("test", "").split("::")[0]).is_file()]
    stamp = time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())
    for r in records:
        r.setdefault("recorded", stamp)
    out = {"written": stamp, "records": sorted(kept + records, key=lambda r: (r["source"], r["test"]))}
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w") as f:
            json.dump(out, f, indent=1)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise

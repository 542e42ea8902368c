"""Fingerprints of every example's result, to show a refactor changes no result by a single bit (issue 38).

Each case of ``examples/*.yaml`` (and the MoorDyn decks named below; a case refused is fingerprinted by its message) is run through :func:`seacable.run`;
every variable and coordinate of its Dataset is hashed (SHA-256 of its dtype, shape and bytes), and so is
every attribute but the ones that name the run (seacable's version, the time of the run). The hashes are
written to a JSON file; ``--compare`` prints the variables whose hashes differ between two such files.

Show a refactor is pure: run this once with the source before it and once after, then compare::

    git worktree add /tmp/before <commit before>
    PYTHONPATH=/tmp/before/src python bench/fingerprint.py --out before.json
    python bench/fingerprint.py --out after.json
    python bench/fingerprint.py --compare before.json after.json

It is a bench, not a test: the whole set runs for minutes, and a result may rightly change bit-wise when
the physics changes (then the tests say whether it changed for the better).

Run: ``python bench/fingerprint.py [--out FILE] [--only SUBSTRING ...]`` or ``--compare A.json B.json``.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DECKS = [
    # MoorDyn input files (kept in the tests' data, with their provenance there): lines and points, and bodies
    "tests/validation/data/moordyn_decks/r-test/modules/moordyn/5MW_OC4_simple/moordyn.dat",
    "tests/validation/data/moordyn_decks/r-test/modules/moordyn/md_lineFail/moordyn.dat",
]
# attributes that say when and by which version a result was made, not what it is
_RUN_ATTRS = {"seacable_version", "version", "created", "date_created", "history", "run_time", "source", "wall_time"}
_RUN_SETTINGS = ("wall_time_s",)  # keys of the ``settings`` attribute (JSON) that time the run


def _digest(values) -> str:
    import numpy as np

    array = np.asarray(values)
    h = hashlib.sha256(f"{array.dtype.str} {array.shape}".encode())
    h.update(array.tobytes() if array.dtype != object else repr(array.tolist()).encode())
    return h.hexdigest()[:20]


def fingerprint(ds) -> dict[str, str]:
    """Hash of every coordinate, variable and attribute of a result Dataset."""
    out = {}
    for name in sorted(map(str, ds.variables)):
        out[f"var:{name}"] = _digest(ds[name].values)
        for key, value in sorted(ds[name].attrs.items()):
            out[f"attr:{name}.{key}"] = hashlib.sha256(repr(value).encode()).hexdigest()[:20]
    for key, value in sorted(ds.attrs.items()):
        if key == "settings" and isinstance(value, str):
            value = {k: v for k, v in json.loads(value).items() if k not in _RUN_SETTINGS}
        if key not in _RUN_ATTRS:
            out[f"attr:{key}"] = hashlib.sha256(repr(value).encode()).hexdigest()[:20]
    return out


def cases(only: list[str]) -> list[Path]:
    paths = sorted((ROOT / "examples").glob("*.yaml")) + [ROOT / d for d in DECKS]
    return [p for p in paths if not only or any(s in str(p) for s in only)]


def run_all(only: list[str]) -> dict:
    import seacable

    result = {}
    os.chdir(ROOT)  # cases read by their path in the checkout: a MoorDyn deck's result names its file
    for path in cases(only):
        name = str(path.relative_to(ROOT))
        path = Path(name)
        start = time.perf_counter()
        try:
            try:
                case = seacable.load_case(path)
            except seacable.SeacableError:  # a sweep file, not a case: its summary is its result
                with tempfile.TemporaryDirectory() as outdir:
                    ds = seacable.sweep(seacable.load_sweep(path), outdir).load()
            else:
                ds = seacable.run(case)
        except seacable.SeacableError as exc:  # a refusal is a result too: the same message before and after
            result[name] = {"error": f"{type(exc).__name__}: {exc}"}
        else:
            result[name] = fingerprint(ds)
        print(f"{name:70s} {len(result[name]):4d} hashes {time.perf_counter() - start:7.1f} s", flush=True)
    return result


def compare(a: dict, b: dict) -> int:
    differ = 0
    for name in sorted(set(a) | set(b)):
        if name not in a or name not in b:
            print(f"{name}: only in {'the second' if name not in a else 'the first'} file")
            differ += 1
            continue
        keys = sorted(set(a[name]) | set(b[name]))
        bad = [k for k in keys if a[name].get(k) != b[name].get(k)]
        print(f"{name:70s} {'same to the bit' if not bad else f'{len(bad)} of {len(keys)} differ'}")
        for k in bad:
            print(f"    {k}")
        differ += bool(bad)
    print(f"{differ} case(s) differ of {len(set(a) | set(b))}")
    return 1 if differ else 0


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="fingerprint.json", help="JSON file of the hashes (default %(default)s)")
    parser.add_argument("--only", nargs="*", default=[], help="run only the cases whose path holds one of these")
    parser.add_argument("--compare", nargs=2, metavar=("A", "B"), help="compare two JSON files and exit")
    args = parser.parse_args(argv)
    if args.compare:
        a, b = (json.loads(Path(p).read_text()) for p in args.compare)
        return compare(a, b)
    result = run_all(args.only)
    Path(args.out).write_text(json.dumps(result, indent=1, sort_keys=True))
    print(f"{len(result)} cases -> {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

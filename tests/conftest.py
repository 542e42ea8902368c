"""Suite-wide set-up: on a parallel run of the whole suite, each worker compiles its own share of the kernels first.

numba compiles a kernel the first time a process calls it and writes it to the cache folder that every
process shares (``seacable._numba_cache``); a process that needs it later loads it from there in a fraction
of a second. From an empty cache (a fresh install) the two workers of a 2-core run used to reach the same
big kernels within seconds of each other and both compiled them: about 130 CPU-seconds of a cold run went to
compiling the mooring, towline and system-statics kernels twice. Here, on a run of more than
``_MIN_TESTS`` tests with two or more pytest-xdist workers, each worker first compiles kernel families
(``_FAMILIES``) by running a short example case of each, so that each family is compiled once, by one worker,
at the same time as the other worker compiles others; a family's later users load it from the cache. The
workers take the families one at a time, largest first, each claiming the next one nobody has claimed (a
file created exclusively in the run's temporary folder), so that they finish together whatever the machine
(a fixed share by measured compile times left one worker 40 CPU-seconds behind the other). With a warm cache
the runs cost a few seconds a worker. Nothing is asserted here: the same examples are run and checked by the
tests.

Bytecode is cached even where ``PYTHONDONTWRITEBYTECODE`` is set (as on the machines this suite was timed on):
without it each worker compiled and re-wrote the asserts of 220 test modules at every run (8 of its 15
CPU-seconds of collection), and every process a test starts (the command line, a sweep's workers) compiled
seacable's sources again. The files go to the ``__pycache__`` folders git ignores; where they cannot be
written, Python goes on without them.
"""

from __future__ import annotations

import os
import sys
import warnings
from pathlib import Path

import pytest

sys.dont_write_bytecode = False                  # this process: the test modules pytest rewrites, seacable
os.environ.pop("PYTHONDONTWRITEBYTECODE", None)  # the xdist workers and the processes the tests start

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"

sys.path.insert(0, str(Path(__file__).resolve().parent))   # the tests' own helpers: _evidence
import _evidence  # noqa: E402

#: A parallel run of at least this many tests shares the compilation out (a run of a few files does not).
_MIN_TESTS = 1000

#: Kernel families: (the example cases that compile them, analysis keys overridden to make each run short),
#: and the CPU-seconds their compilation took from an empty cache on a 2-core machine (2026-11-29), by which
#: the workers take them, largest first. The system dynamics call the mooring element loads, so the
#: two are one family (compiled by one worker, in that order).
_FAMILIES = (
    ((("paper004_buoy_relaxation", {"duration": 0.2}), ("spread_mooring_line_break", {"duration": 0.5})), 140.0),
    ((("paper003_drop", {"duration": 1.0}),), 48.0),
    ((("paper000_turn", {"duration": 2.0, "output_interval": 1.0}),), 44.0),
    ((("towed_depressor_survey", {"duration": 4.0}),), 42.0),
    ((("spread_mooring", {}),), 34.0),
    ((("paper001_lay_2ms_50m", {"duration": 4.0}), ("lay_plan_route", {})), 15.0),
)


def _claim(folder: Path, k: int) -> bool:
    """Claim family ``k`` for this worker: True if no worker had (the claim file is created exclusively)."""
    try:
        os.close(os.open(folder / f"family-{k}", os.O_CREAT | os.O_EXCL | os.O_WRONLY))
    except FileExistsError:
        return False
    return True


def _run_example(name: str, analysis: dict) -> None:
    import seacable as sc
    from seacable.io.case_file import load_case_data, parse_case

    data = load_case_data(EXAMPLES / f"{name}.yaml")
    data["analysis"].update(analysis)
    sc.run(parse_case(data, source=name))


@pytest.fixture(scope="session", autouse=True)
def _compile_this_workers_kernels(request, tmp_path_factory):
    """On a parallel run of the whole suite, compile the kernel families no other worker has taken, first."""
    worker = os.environ.get("PYTEST_XDIST_WORKER", "")
    n_workers = int(os.environ.get("PYTEST_XDIST_WORKER_COUNT", "1"))
    if n_workers < 2 or not worker.startswith("gw") or len(request.session.items) < _MIN_TESTS:
        return
    folder = tmp_path_factory.getbasetemp().parent / "kernel-families"  # shared by the run's workers
    folder.mkdir(exist_ok=True)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")   # the examples' own warnings are the tests' business
        for k in sorted(range(len(_FAMILIES)), key=lambda k: -_FAMILIES[k][1]):
            if _claim(folder, k):
                for name, analysis in _FAMILIES[k][0]:
                    _run_example(name, analysis)


# ------------------------------------------------------------------------- the validation ledger (_evidence)
# Each process records the checks its tests make (_evidence.RECORDS); a pytest-xdist worker hands its records to
# the controller at its end, and the controller (or a run without workers) writes them to the evidence file the
# documentation's validation page is built from, merged with that file's records of the tests not run this time.

_WORKER_RECORDS: list[dict] = []


def pytest_sessionfinish(session, exitstatus):
    import json

    if hasattr(session.config, "workerinput"):          # an xdist worker: to the controller
        session.config.workeroutput["seacable_evidence"] = json.dumps(_evidence.RECORDS)
        return
    records = _WORKER_RECORDS + _evidence.RECORDS
    if records:
        _evidence.write_records(records)


@pytest.hookimpl(optionalhook=True)
def pytest_testnodedown(node, error):
    import json

    _WORKER_RECORDS.extend(json.loads(getattr(node, "workeroutput", {}).get("seacable_evidence", "[]")))

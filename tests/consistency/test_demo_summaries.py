"""The main demo's one-line summaries read the names the analyses write (a renamed result variable
broke the demo once without any test failing). The quick cases run here; each summary is also
checked for the number it quotes, against the result it was made from."""

import functools
import sys
from pathlib import Path

import pytest

import seacable as sc

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
sys.path.insert(0, str(EXAMPLES))
import demo  # noqa: E402

#: the demo's cases that solve in about a second (statics, offsets, short runs); the slow time-domain
#: ones are left to the demo itself
QUICK = ("oc3_hywind_static", "oc3_hywind_pushover", "oc3_hywind_modes", "spread_mooring",
         "spread_mooring_watch_circle")


@functools.cache
def _result(name):
    """The example's result, run once for the module (the summaries only read it)."""
    return sc.run(sc.load_case(EXAMPLES / f"{name}.yaml"))


@pytest.mark.parametrize("name", QUICK)
def test_the_demo_summary_reads_its_result(name):
    assert name in demo.CASES, f"{name} left the demo: update QUICK"
    ds = _result(name)
    line = demo.CASES[name](ds)
    assert isinstance(line, str) and line


def test_the_spread_mooring_summary_quotes_the_result():
    ds = _result("spread_mooring_watch_circle")
    largest = float(ds.fairlead_tension.sel(condition="intact").max()) / 1e3
    # the summary rounds the largest intact fairlead tension to a whole kN
    assert f"largest fairlead tension {largest:.0f} kN" in demo.CASES["spread_mooring_watch_circle"](ds)

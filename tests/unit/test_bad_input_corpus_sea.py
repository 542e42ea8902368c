"""Issue 37: bad sea states, RAO tables, ignored inputs and MoorDyn tables never crash and never exit 0.

Each file of ``tests/unit/bad_inputs/`` named ``sea_*`` is one bad input (a YAML case or a MoorDyn deck, its data
files in ``bad_inputs/data_sea/``), its first line ``# expect: <phrase>`` the words its message must hold. Both
``seacable validate FILE`` and ``seacable run FILE -o OUT`` are run in this process (``seacable.cli.main``) and
must exit 2 (a user error), print the phrase in one ``seacable: error:`` message, and print no traceback: the
one validation path (:func:`seacable.simulate.check`) refuses what a run would, before its time loop.

Classes: impossible sea states (capillary periods, depth-limited breaking at 0.78 d, Miche's steepness, a table
spectrum's Hs from its m0, a frequency_range off the spectrum's energy), environment inputs the analysis does
not use (waves, current, seabed slope, friction or profile, a depth beside a profile), RAO tables (empty, no
rows, headings in degrees, implausible amplitudes, fractional or unknown DOF, negative amplitudes, repeated
rows, empty or text cells; CSV and WAMIT .4) and MoorDyn decks (a rod of length with 0 segments, strain-tension
tables in per cent or without tension).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from seacable.cli import main

CORPUS = Path(__file__).resolve().parent / "bad_inputs"
FILES = sorted(p for p in CORPUS.glob("sea_*") if p.is_file())


def _expect(path: Path) -> str:
    first = path.read_text(encoding="utf-8").splitlines()[0]
    assert first.startswith("# expect:"), f"{path.name}: the first line must be '# expect: <phrase>'"
    return first.removeprefix("# expect:").strip()


def test_the_corpus_holds_sixty_distinct_bad_inputs():
    # one file per bad input: at least 60, none a copy of another
    assert len(FILES) >= 60
    assert len({p.read_text(encoding="utf-8") for p in FILES}) == len(FILES)


@pytest.mark.parametrize("command", ["validate", "run"])
@pytest.mark.parametrize("path", FILES, ids=[p.stem for p in FILES])
def test_a_bad_input_exits_2_with_its_message(path, command, tmp_path, capsys):
    phrase = _expect(path)
    argv = [command, str(path)] + (["-o", str(tmp_path / "out.nc"), "--no-plots"] if command == "run" else [])
    code = main(argv)
    err = capsys.readouterr().err
    assert code == 2, f"{path.name}: exit {code}, stderr:\n{err}"
    assert "Traceback" not in err and "internal error" not in err
    assert "seacable: error:" in err
    assert phrase in " ".join(err.split()), f"{path.name}: {phrase!r} not in:\n{err}"
    assert not (tmp_path / "out.nc").exists()

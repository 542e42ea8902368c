"""``seacable validate`` (:func:`seacable.simulate.check`) refuses what ``seacable run`` refuses, with the same error.

The static and modal analyses are cheap: their check is the very solve their runner calls first, without the
Dataset (issue 38: no xarray to validate them). Here each of them is given a case that loads but cannot be
solved (a line too short to reach its fairlead, a line that floats, a string without tension), and
``check`` must raise what ``run`` raises, message and all.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

import seacable as sc
from seacable.errors import SeacableError
from seacable.simulate import _ANALYSES, check

EXAMPLES = Path(sc.__file__).resolve().parents[2] / "examples"


def _set(data: dict, dotted: str, value) -> None:
    *head, last = dotted.split(".")
    for key in head:
        data = data[key]
    data[last] = value


#: cheap analysis type -> (example, edits that make it unsolvable, a phrase of the error)
UNSOLVABLE = {
    "static": ("oc3_hywind_static.yaml", {"line.length": 400.0}, "cannot reach"),
    "pushover": ("oc3_hywind_pushover.yaml", {"line.length": 400.0}, "cannot reach"),
    "modal": ("oc3_hywind_modes.yaml", {"line.length": 400.0}, "cannot reach"),
    "towed_steady": ("paper000_steady_statics.yaml", {"line_types.towcable.weight_in_water": -17.7},
                     "no steady shape"),
    "laying_theory": ("paper001_table1.yaml", {"line_types.cable.weight_in_water": -4.49},
                      "weight_per_length"),
    "vertical_modes": ("paper002_vertical_cable.yaml", {"line_types.cable.weight_in_water": -10.0},
                       "weight_per_length"),
    "mooring_static": ("paper004_lena_pushover.yaml",
                       {"analysis": {"type": "mooring_static", "fairlead": [1001.0, -15.24], "element_length": 2.0},
                        "line.segments": [{"line_type": "guy", "length": 400.0}]}, "cannot span"),
    "mooring_pushover": ("paper004_lena_pushover.yaml", {"line.segments": [{"line_type": "guy", "length": 400.0}]},
                         "cannot span"),
}


def test_every_cheap_analysis_is_covered():
    """The analyses whose check is their solve (``solve_*``) are all in :data:`UNSOLVABLE`."""
    solved = {kind for kind, (_, _, step) in _ANALYSES.items() if step and step.startswith("solve_")}
    assert solved == set(UNSOLVABLE)


@pytest.mark.parametrize("kind", sorted(UNSOLVABLE))
def test_check_raises_what_run_raises(kind, tmp_path):
    example, edits, phrase = UNSOLVABLE[kind]
    data = yaml.safe_load((EXAMPLES / example).read_text())
    for key, value in edits.items():
        _set(data, key, value)
    path = tmp_path / "case.yaml"
    path.write_text(yaml.safe_dump(data))
    case = sc.load_case(path)            # the file is well formed: only solving finds the problem
    assert case.analysis.type == kind
    with pytest.raises(SeacableError) as checked:
        check(case)
    with pytest.raises(SeacableError) as ran:
        sc.run(case)
    assert type(checked.value) is type(ran.value)
    assert str(checked.value) == str(ran.value)
    assert phrase in str(checked.value)

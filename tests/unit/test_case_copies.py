"""A case changed in code (``replace``, ``model_copy(update=...)``) is validated again, and new line types reach
its line: a line holds its line types, not their names, so a copy that changed only ``line_types`` used to run the
old line (a silent wrong answer)."""

import pytest

import seacable as sc
from seacable.errors import InputError

LINE = "examples/oc3_hywind_static.yaml"
SYSTEM = "examples/spread_mooring.yaml"


def _heavier(case, factor=2.0):
    (name, lt), = case.line_types.items()
    weight = None if lt.weight_in_water is None else factor * lt.weight_in_water
    return {name: lt.replace(mass_per_length=factor * lt.mass_per_length, weight_in_water=weight)}


@pytest.mark.parametrize("how", ["replace", "model_copy"])
def test_a_copy_with_new_line_types_runs_as_a_case_written_with_them(how):
    case = sc.load_case(LINE)
    types = _heavier(case)
    copy = case.replace(line_types=types) if how == "replace" else case.model_copy(update={"line_types": types})
    fresh = sc.Case(**{**{k: getattr(case, k) for k in sc.Case.model_fields}, "line_types": types,
                       "line": sc.Line(segments=[s.replace(line_type=types["oc3"]) for s in case.line.segments])})
    ours, theirs, old = (float(sc.run(c)["tension"].max()) for c in (copy, fresh, case))
    assert ours == theirs  # the same line, so the same floats
    assert ours > 1.5 * old  # a chain of twice the weight hangs at about twice the tension: the change did reach it


def test_a_system_copy_with_new_line_types_reaches_every_line():
    case = sc.load_case(SYSTEM)
    copy = case.model_copy(update={"line_types": _heavier(case, 3.0)})
    for name, entry in copy.lines.items():
        assert entry.line.segments[0].line_type.mass_per_length == 3.0 * case.line_types["chain"].mass_per_length, name


def test_a_copy_that_drops_a_used_line_type_is_refused_by_name():
    with pytest.raises(InputError, match=r"lines\.line1\.segments\[0\] uses line type 'chain'.*Suggested fix"):
        sc.load_case(SYSTEM).replace(line_types={})


def test_model_copy_with_an_update_validates_it():
    # pydantic's own model_copy(update=...) would keep a negative length
    seg = sc.load_case(LINE).line.segments[0]
    with pytest.raises(InputError, match="length"):
        seg.model_copy(update={"length": -5.0})

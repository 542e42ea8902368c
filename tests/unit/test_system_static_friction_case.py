"""The ``static_friction`` key of a system's static analyses (``system_static``, ``system_offsets``): one schema with
the single line's (:class:`seacable.mooring.friction.StaticFriction`), refused where it does not apply, absent from a
dumped case when it is the default; and ``system_offsets`` with friction in a current (the numbers against closed
forms and the single line are in ``tests/validation/test_system_static_friction.py``)."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from seacable.errors import InputError
from seacable.io import parse_case
from seacable.system.run import run_system_offsets

SPREAD = Path(__file__).resolve().parents[2] / "examples" / "spread_mooring.yaml"


def _data(analysis, mu=0.5, speed=0.3):
    d = yaml.safe_load(SPREAD.read_text(encoding="utf-8"))
    d["environment"]["seabed"] = {"friction": mu}
    d["environment"]["current"] = {"speed": speed, "heading": 0.0}
    d["bodies"]["buoy"]["external_force"] = [0.0] * 6
    for line in d["lines"].values():
        line["n_elements"] = 10
    d["analysis"] = analysis
    return d


def test_an_incremental_pushover_path_is_refused_on_a_system():
    with pytest.raises(InputError, match=r"pushover_path: 'incremental' applies to a single line's "
                                         r"mooring_pushover.*Suggested fix: drop static_friction.pushover_path"):
        parse_case(_data({"type": "system_static", "static_friction": {"pushover_path": "incremental"}}))


def test_the_default_static_friction_is_left_out_of_a_dumped_case():
    plain = parse_case(_data({"type": "system_static"}))
    assert "static_friction" not in plain.analysis.model_dump()
    given = parse_case(_data({"type": "system_offsets", "body": "buoy", "loads": [0.0],
                              "static_friction": {"mode": "off"}}))
    assert given.analysis.model_dump()["static_friction"]["mode"] == "off"


def test_system_offsets_hold_the_lines_against_the_current_with_friction():
    """0.3 m/s along +x at no load: frictionless the current's drag on the three chains carries the buoy 0.14 m;
    with friction 0.5 the grounded parts are held where they were laid and only the suspended parts' drag moves it
    (0.04 m at 10 elements). The anchor tensions with friction stay the as-laid state's (306 kN) within the
    friction's reach: a load the touchdown's friction takes up does not reach the anchor."""
    analysis = {"type": "system_offsets", "body": "buoy", "loads": [0.0, 2e5], "headings": [0.0]}
    free = run_system_offsets(parse_case(_data(analysis, mu=0.0)))
    held = run_system_offsets(parse_case(_data(analysis)))
    assert abs(held.body_offset_x.values.ravel()[0]) < 0.5 * abs(free.body_offset_x.values.ravel()[0])
    laid = parse_case(_data({"type": "system_static"}, speed=0.0))
    from seacable.system.run import run_system_static

    h0 = run_system_static(laid, statics="finite_element").anchor_tension.values[0]
    ta = held.anchor_tension.values.reshape(-1, 3)
    assert ta[0] == pytest.approx(h0, rel=1e-3)  # at no load: the as-laid anchor tensions
    assert ta[1, 1:] == pytest.approx(h0[1:], rel=1e-3)  # lines 2, 3 retract: their anchors keep the lay's tension

"""The cable checks' rows for bend restrictors and moment-curvature tables (seacable.design.cable.section_checks).

The 160 m cable of ``test_cable_run.py`` (clamped at its hang-off at 0.1 rad, 20 elements), its EI given as a bilinear
law (2e4 N m^2 to 0.05 1/m, then 1e4 N m^2, to 0.1 1/m) and a 10 m bend restrictor at the hang-off: its static
result's clamp curvature is 0.025 1/m without a lock. A restrictor locking at 8 m (0.125 1/m) stays free; one at
60 m (0.0167 1/m) locks and holds the clamp within 1 % of its lock curvature (the stated rule: the overshoot is
(M - M_cable) / (LOCK_FACTOR EI); the locked end, stiffer, takes 2640 N m against the free end's 500, so 2300 /
(1000 x 2e4) = 1.15e-4 1/m, 6.9e-3 of the lock curvature, measured). The sag bend's curvature, 0.11 1/m, is past
the table's last 0.1 1/m: that row fails.
"""

from __future__ import annotations

import pytest
import yaml

import seacable as sc
from seacable.design import cable

_HANG = """
name: hang
line_types:
  cable: {diameter: 0.15, mass_per_length: 40, axial_stiffness: 5e8, moment_curvature: [[0, 0], [0.05, 1000], [0.1, 1500]]}
line: {line_type: cable, length: 160}
environment: {depth: 100}
analysis:
  type: mooring_static
  anchor: [0, -100]
  fairlead: [80, -10]
  n_elements: 20
  fairlead_end_condition: {type: clamped, declination: 0.1}
"""


def _run(locking_radius):
    data = yaml.safe_load(_HANG)
    data["line"]["sections"] = [{"type": "bend_restrictor", "end": "B", "length": 10.0, "locking_radius": locking_radius,
                                 "diameter": 0.3, "mass_per_length": 10.0}]
    return sc.run(sc.Case(**data))


@pytest.mark.parametrize("radius, status", [(8.0, "free"), (60.0, "LOCKED")])
def test_restrictor_row_says_locked_or_free_with_its_utilisation(radius, status):
    ds = _run(radius)
    rows = {c.check: c for c in cable.cable_checks(ds)}
    row = rows["bend restrictor at end B"]
    on = ds["s"].values >= 150.0 - 1e-9
    kappa = float(ds["curvature"].values[on].max())
    assert row.status == status
    assert row.value == kappa
    assert row.limit == 1.0 / radius
    assert row.utilisation == pytest.approx(kappa * radius, rel=1e-12)
    if status == "LOCKED":
        assert 0.0 < kappa * radius - 1.0 < 1e-2
    table = rows["moment-curvature table (line.segments[0])"]
    assert table.status == "FAIL" and table.limit == 0.1
    assert table.value == float(ds["curvature"].values.max()) > 0.1

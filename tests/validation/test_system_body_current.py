"""The current on a body from its coefficient table (issue 39): ``bodies.NAME.current {headings, surge, sway, yaw}``,
``F = 1/2 rho |u| u C(beta)`` of the current at the body relative to it, ``beta`` in the body's axes
(:mod:`seacable.system.dynamics.body`; the force law against its closed form in tests/unit/test_body_tables.py).

The spread mooring of ``examples/spread_mooring.yaml`` (a 12 m buoy on three chains in 150 m of water) in a 1.5 m/s
current at 30 deg: its equilibrium with the table is the one under the table's force and moment at the heading
the buoy takes, given by hand as its ``external_force`` (the lines' drag the same in both).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.errors import InputError
from seacable.results import body_pose
from seacable.system.model import BodyCurrent

EXAMPLE = Path(__file__).parents[2] / "examples" / "spread_mooring.yaml"
SPEED, HEADING, RHO = 1.5, math.radians(30.0), 1025.0
# an OCIMF-like table of the buoy's current areas: surge and sway drag, a yaw moment largest off the axes
TABLE = {"headings": np.radians([0, 45, 90, 135, 180, 225, 270, 315]).tolist(),
         "surge": [90.0, 70.0, 0.0, -70.0, -90.0, -70.0, 0.0, 70.0],
         "sway": [0.0, 110.0, 160.0, 110.0, 0.0, -110.0, -160.0, -110.0],
         "yaw": [0.0, 400.0, 0.0, -400.0, 0.0, 400.0, 0.0, -400.0]}


def _case(tmp_path, *, table=True, external=(0.0,) * 6, analysis=None) -> Path:
    data = yaml.safe_load(EXAMPLE.read_text())
    body = data["bodies"]["buoy"]
    body["external_force"] = list(external)
    if table:
        body["current"] = TABLE
    data["environment"]["current"] = {"speed": SPEED, "heading": HEADING}
    data["analysis"] = analysis or {"type": "system_static"}
    path = tmp_path / "current.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    return path


def test_the_current_table_loads_the_body_as_its_force_by_hand(tmp_path):
    """The finite-element statics with the table (the current at the buoy's reference point, on the waterline)
    against the same statics with the table's force and moment at the yaw found, by hand: equal to the
    statics' tolerance (1e-6 of the offset); the table's load moves the buoy by metres and turns it."""
    tabled = sc.run(sc.load_case(_case(tmp_path)))
    plain = sc.run(sc.load_case(_case(tmp_path, table=False)))
    pose = np.array([float(tabled[f"body_{k}"].values[0, 0]) for k in ("x", "y", "z", "roll", "pitch", "yaw")])
    coef = BodyCurrent(**TABLE).coefficients()
    f3 = coef.force(SPEED * np.array([math.cos(HEADING), math.sin(HEADING)]), yaw=pose[5], rho_air=RHO)
    assert np.hypot(*f3[:2]) > 1e5 and abs(f3[2]) > 1e5  # about 200 kN and 0.4 MN m
    pushed = sc.run(sc.load_case(_case(tmp_path, table=False, external=(float(f3[0]), float(f3[1]), 0.0, 0.0, 0.0, float(f3[2])))))
    by_hand = np.array([float(pushed[f"body_{k}"].values[0, 0]) for k in ("x", "y", "z", "roll", "pitch", "yaw")])
    still = np.array([float(plain[f"body_{k}"].values[0, 0]) for k in ("x", "y", "yaw")])
    assert np.hypot(*(pose[:2] - still[:2])) > 1.0 and abs(pose[5] - still[2]) > 1e-3
    np.testing.assert_allclose(pose, by_hand, rtol=0, atol=1e-6 * np.hypot(*(pose[:2] - still[:2])))


def test_a_table_is_checked_as_the_wind_s(tmp_path):
    """A table with a heading given twice or an area missing is refused with the key."""
    data = yaml.safe_load(_case(tmp_path).read_text())
    data["bodies"]["buoy"]["current"] = {"headings": [0.0, 0.0], "surge": [1.0, 2.0], "sway": [0.0, 0.0],
                                         "yaw": [0.0, 0.0]}
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    with pytest.raises(InputError, match=r"bodies\.buoy\.current.*each heading must be given once"):
        sc.load_case(bad)
    data["bodies"]["buoy"]["current"] = {"headings": [0.0, 1.0], "surge": [1.0], "sway": [0.0, 0.0], "yaw": [0.0, 0.0]}
    bad.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    with pytest.raises(InputError, match=r"bodies\.buoy\.current.*'surge' must have one finite value per heading"):
        sc.load_case(bad)



def test_a_floating_body_with_a_database_runs_in_a_current(tmp_path, hull_case):
    """The VolturnUS-S hull with its database (which the catenary statics' stability check sees without the current
    and wind; it refused a current before) in a 1 m/s current on its table, in still water: the run starts from
    the finite-element statics with the table and the ropes' drag, and stays there (the start is the dynamic
    equilibrium: 1e-5 m over 20 s, against an offset of decimetres)."""
    rope = {"diameter": 0.1, "mass_per_length": 50.0, "axial_stiffness": 5e8, "drag_normal": 1.2,
            "added_mass_normal": 1.0}
    table = {"headings": [0.0, math.pi / 2, math.pi, 3 * math.pi / 2], "surge": [600.0, 0.0, -600.0, 0.0],
             "sway": [0.0, 700.0, 0.0, -700.0], "yaw": [0.0, 0.0, 0.0, 0.0]}
    path = hull_case(tmp_path, waves=None, rope=rope, body={"current": table}, analysis={"duration": 20.0})
    data = yaml.safe_load(path.read_text())
    data["environment"]["current"] = {"speed": 1.0, "heading": 0.5}
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    ds = sc.run(sc.load_case(path))
    xyz = body_pose(ds)[:, 0, :3]
    assert np.hypot(*xyz[0, :2]) > 0.1  # the current pushes it along 0.5 rad
    # along the table's force (409 and 223 kN/(m/s)^2 in surge and sway at 0.5 rad, interpolated) and the ropes' drag
    # (along the current): the three ropes' horizontal stiffness is isotropic (three-fold symmetry), so within 5 %
    f = BodyCurrent(**table).coefficients().force(np.array([math.cos(0.5), math.sin(0.5)]), rho_air=1025.0)
    assert xyz[0, 1] / xyz[0, 0] == pytest.approx(f[1] / f[0], rel=0.05)
    assert np.abs(xyz - xyz[0]).max() < 1e-5
    assert "Cummins, W. E. (1962)" in ds.attrs["references"]  # the floating body's models cited with the result


def test_the_most_loaded_line_in_a_current_is_the_intact_runs(tmp_path, hull_case):
    """``damaged_lines: most_loaded`` with what the catenary statics cannot see (here a current on the hull's table
    and the ropes; they refused it before): the line of the largest tension at the intact run's own static start.
    The current flows towards -x, so the rope anchored at +x (rope0) holds the hull."""
    from seacable.system.dynamics import most_loaded_at_start

    rope = {"diameter": 0.1, "mass_per_length": 50.0, "axial_stiffness": 5e8, "drag_normal": 1.2,
            "added_mass_normal": 1.0}
    table = {"headings": [0.0, math.pi / 2, math.pi, 3 * math.pi / 2], "surge": [600.0, 0.0, -600.0, 0.0],
             "sway": [0.0, 700.0, 0.0, -700.0], "yaw": [0.0, 0.0, 0.0, 0.0]}
    path = hull_case(tmp_path, waves=None, rope=rope, body={"current": table},
                     analysis={"duration": 1.0, "damaged_lines": "most_loaded"})
    data = yaml.safe_load(path.read_text())
    data["environment"]["current"] = {"speed": 1.0, "heading": math.pi}
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    case = sc.load_case(path)
    assert most_loaded_at_start(case) == "rope0"
    intact = sc.run(case.model_copy(update={"analysis": case.analysis.model_copy(update={"damaged_lines": ()})}))
    start = intact["fairlead_tension"].values[0]
    assert int(np.argmax(start)) == 0 and start[0] > 1.005 * max(start[1:])  # 1.5 % above: the taut ropes share it

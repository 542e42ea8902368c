"""RAOs of the IEA-15 MW VolturnUS-S about its mean position in the design storm, for the 66 kV cable demo
(``cable_66kv_storm.yaml``), written as an SI CSV table (``cable_66kv_raos.csv``).

The hull is that of ``volturnus_storm.yaml`` (the public OpenFAST model of the IEA Wind Task 37 reference turbine,
Allen et al. 2020, NREL/TP-5000-76773; its WAMIT ``.1``, ``.3`` and ``.hst`` files in ``data/volturnus``): the case's
mean position in its storm (the statics of the hull on its three chains under the mean wave drift, the parked
turbine's mean wind load and the 1 m/s current: :func:`seacable.system.uncoupled.prepare_system_uncoupled`) and
the first-order RAOs there, :func:`seacable.hydro.response.raos` with the rigid body's mass, the database's
hydrostatics with the weight's moment, the chains' stiffness at the mean position and the hull's drag linearised
at the current (HydroDyn's AddBQuad on the relative velocity), at the database's frequencies and at its
headings within 10 deg of the storm's (+x).
The OpenFAST model ships no WAMIT ``.4`` file; these RAOs are what a ``.4`` of this mass, stiffness and damping
would hold.

Run: ``python examples/cable_66kv_raos.py`` (about 10 s; prints the mean position).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

import seacable as sc
from seacable.hydro.response import raos
from seacable.system.hydro import database
from seacable.system.uncoupled import prepare_system_uncoupled

HERE = Path(__file__).resolve().parent
#: The headings kept in the table: the storm's (0, along +x) and those within 10 deg of it. [rad]
HEADINGS = math.radians(10.0)


def write(path: Path) -> np.ndarray:
    """Write the RAO table to ``path`` and return the mean position (surge, sway, heave [m], roll, pitch, yaw
    [rad])."""
    case = sc.load_case(HERE / "volturnus_storm.yaml")
    analysis = case.analysis.model_copy(update={"coupling": "uncoupled"})
    setup = prepare_system_uncoupled(case.model_copy(update={"analysis": analysis}))
    env = case.environment
    db = database(setup.system.bodies[setup.body], env.water_density, env.gravity)
    table = raos(db, setup.mass, setup.stiffness + setup.mooring_stiffness, setup.wave_damping)
    rows = ["frequency,heading,dof,amplitude,phase"]
    for j in range(6):
        for h, b in enumerate(table.heading):
            if abs(b) > HEADINGS + 1e-9:
                continue
            for i, w in enumerate(table.omega):
                v = complex(table.values[j, h, i])
                rows.append(f"{w:.6f},{b:.6f},{j + 1},{abs(v):.6e},{-np.angle(v) if abs(v) > 0 else 0.0:.6f}")
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")
    return np.asarray(setup.mean, float)


if __name__ == "__main__":
    mean = write(HERE / "cable_66kv_raos.csv")
    surge, sway, heave, roll, pitch, yaw = (float(v) for v in mean)
    print(f"mean position: surge {surge:.3f} m, sway {sway:.3f} m, heave {heave:.3f} m, roll {roll:.5f} rad, "
          f"pitch {pitch:.5f} rad ({math.degrees(pitch):.2f} deg), yaw {yaw:.5f} rad")

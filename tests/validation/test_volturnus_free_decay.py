"""Free decay of the moored VolturnUS-S (issue 39): the coupled system (hull with its WAMIT database and radiation
memory, three finite-element chains) released from an offset, against the natural periods of the files' closed
form, ``2 pi sqrt((M_jj + A_jj(w_n)) / C_jj)`` with the added mass at the period's own frequency
(:func:`seacable.hydro.response.natural_periods`), ``C`` the database's hydrostatics with the weight's moment plus
the chains' stiffness at the equilibrium (``system_static``'s ``coupled_stiffness``).

The hull, chains and mass properties are those of ``examples/volturnus_storm.yaml`` in still water without wind or
current. The closed form leaves out what the coupled run has: the chains' own mass and added mass moving with the
hull, their drag (the decay is damped: the damped period is longer by 1 / sqrt(1 - zeta^2), under 0.1 % here), the
couplings between DOFs, and the mooring's nonlinearity over the amplitude. A period is read from a full cycle
(two zero crossings apart about the equilibrium, so that a small shift of the mean does not bias it).

Measured (10 elements a line, 0.1 s): surge 133.4 s against 134.2 s (-0.6 %: the chains stiffen over the 5 m
swing more than their mass adds), heave 20.65 against 20.42 s (+1.1 %: the chains' vertical mass), pitch 28.59
against 28.54 s (+0.2 %), yaw 92.2 against 88.4 s (+4.3 %: the chains swing sideways with the fairleads 58 m out;
a third of each suspended chain's mass and added mass, some 130 t a line at that radius, adds about 1.3e9 of the
hull's 3.9e10 kg m^2 with added inertia, +1.6 %, and the seabed chains' lateral drag and inertia the rest).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml
from _evidence import check

import seacable as sc
from seacable.hydro.response import natural_periods
from seacable.results import body_pose, stiffness_matrix
from seacable.system.hydro import database

EXAMPLE = Path(__file__).parents[2] / "examples" / "volturnus_storm.yaml"
DOFS = ("x", "y", "z", "roll", "pitch", "yaw")


@pytest.fixture(scope="module")
def still(tmp_path_factory):
    """The example in still water: its case data (database path made absolute), the static equilibrium and the
    closed-form periods."""
    data = yaml.safe_load(EXAMPLE.read_text())
    for key in ("current", "waves", "wind"):
        data["environment"].pop(key)
    hull = data["bodies"]["hull"]
    hull.pop("wind")
    hull["hydrodynamics"]["file"] = str(EXAMPLE.parent / hull["hydrodynamics"]["file"])
    data["analysis"] = {"type": "system_static"}
    path = tmp_path_factory.mktemp("decay") / "still.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    case = sc.load_case(path)
    eq = sc.run(case)
    body = case.system().bodies["hull"]  # the database's hydrostatics resolved, the weight's moment added
    stiffness = stiffness_matrix(eq, "coupled_stiffness").values[0] + np.asarray(body.hydrostatic_stiffness)
    mass = body.model_copy(update={"added_mass": None}).mass_matrix()  # rigid, about the reference point
    periods = natural_periods(database(body, 1025.0, 9.80665), mass, stiffness)
    pose = np.array([float(eq[f"body_{k}"].values[0, 0]) for k in DOFS])
    return data, path.parent, pose, periods


def _period(still, dof: int, offset: float, duration: float) -> float:
    data, folder, pose, _ = still
    release = [0.0] * 6
    release[dof] = offset
    data = {**data, "analysis": {"type": "system_dynamic", "duration": duration, "time_step": 0.1,
                                 "output_interval": 0.1, "n_elements": 10, "release_offsets": {"hull": release}}}
    path = folder / f"decay{dof}.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    ds = sc.run(sc.load_case(path))
    x = body_pose(ds)[:, 0, dof] - pose[dof]
    t = ds["time"].values
    i = np.where(np.sign(x[:-1]) * np.sign(x[1:]) < 0)[0]
    crossings = t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])
    assert crossings.size >= 3, f"{DOFS[dof]}: fewer than a full cycle in {duration} s"
    return float(crossings[2] - crossings[0])


@pytest.mark.parametrize("dof, offset, duration, tolerance", [
    (0, 5.0, 200.0, 0.015),   # surge: -0.6 % (the chains' stiffening over 5 m against their mass)
    (2, 1.0, 40.0, 0.02),     # heave: +1.1 % (the chains' vertical mass)
    (4, 0.05, 50.0, 0.01),    # pitch: +0.2 %
    (5, 0.05, 140.0, 0.06),   # yaw: +4.3 % (the chains' lateral mass and drag, about +1.6 % by hand and more)
])
def test_free_decay_periods_are_the_closed_forms(still, dof, offset, duration, tolerance):
    check(_period(still, dof, offset, duration), still[3][dof], rtol=tolerance, unit="s",
          source="Closed form: natural periods of a moored body (VolturnUS-S)",
          quantity=f"free-decay period, {DOFS[dof]} (from {offset} {'m' if dof < 3 else 'rad'})",
          why="the chains' own mass, drag and stiffening, which the closed form leaves out (see the parameters)")

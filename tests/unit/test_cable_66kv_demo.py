"""The 66 kV lazy-wave cable demo off the VolturnUS-S in 200 m of water (examples/cable_66kv_*.yaml, issue 40): its
physics, not its own numbers: the static hang-off force is the weight of the cable from the sag bend up and the
horizontal tension, the far offset raises the hang-off tension, the storm's hang-off sits at the platform's mean
position, the RAO table is its script's output, and the case files' limits reach the checks."""

from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.design import cable
from seacable.raos import read_rao_csv

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
G, RHO = 9.80665, 1025.0


def _case(name: str, **analysis):
    data = yaml.safe_load((EXAMPLES / f"cable_66kv_{name}.yaml").read_text())
    data["analysis"].update(analysis)
    motion = data["analysis"].get("motion")
    if motion and "file" in motion:
        motion["file"] = str((EXAMPLES / motion["file"]).resolve())
    return sc.Case.parse(data)


@pytest.fixture(scope="module")
def static():
    return sc.run(_case("static"))


def test_the_hang_off_force_is_the_weight_from_the_sag_bend_and_the_horizontal_tension(static):
    """Below the hang-off the cable is bare (the stiffener adds stiffness, no weight), in still water: at the sag
    bend's trough the tangent is horizontal and the bend moment is at its extreme (no shear), so the force at the
    hang-off is the horizontal tension H and the wet weight w (L - s*) of the cable from the trough s* up, w from
    the line type alone: (m - rho pi d^2 / 4) g."""
    ds = static
    lt = yaml.safe_load((EXAMPLES / "cable_66kv_static.yaml").read_text())["line_types"]["cable66"]
    w = (lt["mass_per_length"] - RHO * math.pi * lt["diameter"] ** 2 / 4) * G
    length = sum(seg["length"] for seg in yaml.safe_load((EXAMPLES / "cable_66kv_static.yaml").read_text())[
        "line"]["segments"])
    s, theta, z = (np.asarray(ds[k].values, float) for k in ("s", "declination", "z"))
    _, crest, sag = cable.bends(z + 200.0)
    # the trough: where the declination passes pi/2 past the hog bend's crest, linear between the nodes
    i = crest + int(np.flatnonzero((theta[crest:-1] - math.pi / 2) * (theta[crest + 1:] - math.pi / 2) <= 0)[0])
    s_star = s[i] + (math.pi / 2 - theta[i]) / (theta[i + 1] - theta[i]) * (s[i + 1] - s[i])
    assert abs(s_star - s[sag]) < 2.0  # the trough the bends found
    vertical = w * (length - s_star)
    # 2 N of 30.9 kN: the linear interpolation of the trough between 2 m nodes (the declination's second
    # difference there is 1e-4 rad, a 0.02 m error in s*, 4 N... measured 0.02 N: the trough's curvature is
    # nearly uniform) and the shear EI dkappa/ds at a trough that is not exactly the curvature's extreme; the
    # Newton tolerance is 1e-8 of the largest tension (3e-4 N). A wet weight 1 % off is 309 N.
    assert -float(ds.fairlead_force_z) == pytest.approx(vertical, abs=2.0)
    horizontal = float(ds.fairlead_force_x)
    assert float(ds.fairlead_tension) == pytest.approx(math.hypot(horizontal, vertical), abs=2.0)
    # H is the tension at the trough, where the line is level (the element tensions either side)
    assert horizontal == pytest.approx(float(ds.segment_tension[sag]), rel=2e-3)


def test_the_far_offset_raises_the_hang_off_tension_and_the_near_lowers_the_sag_bend(static):
    """Offsets along heading pi move the hang-off away from the cable's seabed end (positive: far): more cable
    hangs and the horizontal tension grows, so the hang-off tension rises monotonically with the offset; the near
    offsets give the cable slack and its sag bend drops towards the seabed."""
    ds = sc.run(_case("pushover"))
    offsets = np.asarray(ds.offset.values, float)
    tension = np.asarray(ds.fairlead_tension.values, float)
    assert np.all(np.diff(offsets) > 0) and np.all(np.diff(tension) > 0)
    # the pushover's zero offset is the static solution (one solver, one mesh: to its tolerance)
    assert float(ds.fairlead_tension.sel(offset=0.0)) == pytest.approx(float(static.fairlead_tension), rel=1e-7)
    table = cable.cable_check_table(cable.cable_checks(ds))
    sag = table.set_index("check").loc["sag bend clearance"]
    assert sag["offset"] == offsets.min() and sag["status"] == "pass"
    # the static MBR, not the dynamic one, is a static result's limit
    curvature = table.iloc[0]
    assert curvature["check"] == "curvature (static MBR)" and curvature["limit"] == pytest.approx(1 / 2.37)


def test_the_storm_hangs_the_cable_off_the_platform_at_its_mean_position():
    """The storm at a coarse setting (8 s, 0.5 m elements at the clamp, about 4 s): the wave response is ramped
    in from nothing, so at t = 0 the hang-off (5, 0, -15) m is where the mean position puts it, the platform's
    rigid motion about its reference point: surge 26.03 m, heave -0.087 m and pitch -0.0167 rad,
    x = 26.03 + 5 cos(p) - 15 sin(p), z = -0.087 - 5 sin(p) - 15 cos(p); then it moves by the RAOs."""
    case = _case("storm", duration=8.0, time_step=0.1, output_interval=0.5)
    data = case.model_dump()
    data["analysis"]["motion"]["ramp"] = 4.0
    data["line"]["segments"][0]["n_elements"] = 100
    data["line"]["segments"][1]["n_elements"] = 40
    ds = sc.run(sc.Case.parse(data))
    p = -0.0167
    x0, z0 = float(ds.x.isel(time=0)[-1]), float(ds.z.isel(time=0)[-1])
    # the kernel places the end exactly where the motion says (to round-off)
    assert (x0, z0) == pytest.approx((26.03 + 5 * math.cos(p) - 15 * math.sin(p),
                                      -0.087 - 5 * math.sin(p) - 15 * math.cos(p)), abs=1e-9)
    assert float(np.ptp(ds.x.values[:, -1])) > 1.0  # Hs 10 m moves it by metres in 8 s
    checks = cable.cable_check_table(cable.cable_checks(ds)).set_index("check")
    assert checks.loc["curvature (dynamic MBR)", "limit"] == pytest.approx(1 / 3.55)
    assert checks["utilisation"].notna().sum() >= 5


def test_the_rao_table_is_its_scripts_output_and_heaves_with_long_waves(tmp_path):
    """The shipped cable_66kv_raos.csv is what cable_66kv_raos.py writes (to the digits written), and the hull's
    heave follows the longest waves of the database: at 0.05 rad/s against its heave natural frequency 2 pi / 20.4 s
    (tests/validation/test_volturnus_free_decay.py) the response is 1 / (1 - (w / w3)^2) = 1.027 of the wave,
    less the little the heave plates' pressure decays at that depth (k = 2.5e-4 1/m): within 5 %."""
    spec = importlib.util.spec_from_file_location("cable_66kv_raos", EXAMPLES / "cable_66kv_raos.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    mean = module.write(tmp_path / "raos.csv")
    assert (tmp_path / "raos.csv").read_text() == (EXAMPLES / "cable_66kv_raos.csv").read_text()
    assert mean[0] == pytest.approx(26.03, abs=0.005) and mean[4] == pytest.approx(-0.0167, abs=5e-5)
    table = read_rao_csv(EXAMPLES / "cable_66kv_raos.csv")
    k = int(np.argmin(np.abs(table.heading)))
    assert abs(table.values[2, k, 0]) == pytest.approx(1.0, abs=0.05)


def test_a_current_at_the_seabed_pushing_the_grounded_cable_to_its_anchor_says_why_the_statics_fail():
    """The demo's seabed has no friction (environment.seabed.friction 0): a uniform 1 m/s current along +x, from the
    hang-off towards the cable's seabed end, pushes the grounded cable along itself towards its anchor, into the
    compression the elements do not carry (0.9 m/s converges, its grounded tension down to 458 N; 0.95 does not).
    The message says so and gives the fixes; with the seabed's friction (0.5) and the elements carrying compression
    (a cable's) the statics hold it (:mod:`seacable.mooring.friction`; tests/unit/test_lazy_wave_friction.py)."""
    data = yaml.safe_load((EXAMPLES / "cable_66kv_static.yaml").read_text())
    data["environment"]["current"] = {"speed": 1.0, "heading": 0.0}
    with pytest.raises(sc.errors.ConvergenceError, match=r"the current's drag, 2.035 N/m \(1 m/s at the seabed\), "
                                                         r"and the statics have no friction to hold it"
                                                         r".*falls to zero at the seabed"):
        sc.run(sc.Case.parse(data))
    data["environment"]["seabed"] = {"friction": 0.5}
    data["analysis"]["compression"] = True
    ds = sc.run(sc.Case.parse(data))
    assert float(ds.seabed_contact_length) > 10.0  # the cable still lies on the seabed, held there

"""The four dynamic-cable configurations of issue 40 from their case files (``examples/``): lazy wave, steep wave
(rising from a clamped seabed base), lazy-S (over a tethered subsea buoy) and pliant wave (a lazy wave tethered at
its touchdown), each from the solver's default start with no tuning, on a flat, a sloped and a profiled seabed,
in a current that weakens with depth, at the mean, near and far platform offsets; and why a steep wave's base
held against the line's pull has no equilibrium on a fine mesh (the elements carry no compression)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.case import Case
from seacable.errors import ConvergenceError
from seacable.mooring.run import case_model
from seacable.mooring.solver import static_equilibrium
from seacable.ties import seabed_elevation

EXAMPLES = Path(sc.__file__).resolve().parents[2] / "examples"
CURRENT = {"depths": [0.0, 40.0, 80.0], "speeds": [0.8, 0.5, 0.2], "heading": 0.3}
SEABEDS = {"flat": {}, "sloped": {"slope": 0.02},
           "profiled": {"profile": {"distance": [0.0, 10.0, 60.0, 200.0], "depth": [80.0, 80.0, 72.0, 70.0]}}}


def _case(name: str, seabed: str, offset: float) -> Case:
    data = yaml.safe_load((EXAMPLES / name).read_text())
    env = data["environment"]
    env["current"] = CURRENT
    env["seabed"] = SEABEDS[seabed]
    data["analysis"]["element_length"] = 1.0
    data["analysis"]["fairlead"][0] += offset
    return Case.parse(data)


def _at(ds, s):
    return int(np.argmin(np.abs(ds.s.values - s)))


def _wave(ds, lo, hi):
    """(hog, sag) elevations [m]: the highest point of the buoyant stretch ``lo``-``hi`` and the lowest beyond it."""
    s, z = ds.s.values, ds.z.values
    hog = float(np.max(z[(s >= lo) & (s <= hi)]))
    sag = float(np.min(z[(s > s[np.argmax(np.where((s >= lo) & (s <= hi), z, -np.inf))])]))
    return hog, sag


@pytest.mark.parametrize("offset", [-8.0, 0.0, 8.0], ids=["near", "mean", "far"])
@pytest.mark.parametrize("seabed", list(SEABEDS))
@pytest.mark.parametrize("name", ["lazy_wave_80m.yaml", "steep_wave_80m.yaml", "lazy_s_80m.yaml",
                                  "pliant_wave_80m.yaml"])
def test_configuration_converges_from_the_default_start(name, seabed, offset):
    """Each converges (its iterations in the result's settings, under the solver's 500) into its shape: a wave
    (a hog over the buoyancy at least 2 m above the sag beyond it) for the lazy, steep and pliant waves, the
    steep wave leaving its clamped base vertically
    (a bend moment over 1 kN m there), the lazy-S's cable over its buoy (the
    buoy's node above the cable before it and 2 m above the S after it, its tether taut, 15-30 kN, against the buoy's 35 kN of net buoyancy less
    the cable's pull down), the pliant wave's tether taut (0.05-1 kN) and its node within the tether's stretched
    length of its anchor. Without the tethers (their force left out) the lazy-S's buoy floats up to the
    surface and the pliant wave's touchdown lifts: these fail."""
    case = _case(name, seabed, offset)
    ds = sc.run(case)
    iterations = json.loads(ds.attrs["settings"])["iterations"]
    assert 0 < iterations < 500
    if name in ("lazy_wave_80m.yaml", "pliant_wave_80m.yaml"):
        hog, sag = _wave(ds, 52.101, 102.101)
        assert hog > sag + 2.0
    if name == "steep_wave_80m.yaml":
        hog, sag = _wave(ds, 10.0, 70.0)
        assert hog > sag + 2.0
        assert float(ds.declination[0]) < 0.3 and float(ds.bend_moment[0]) > 1e3  # the base clamp holds it up
    if name == "lazy_s_80m.yaml":
        k = _at(ds, 75.0)
        z = ds.z.values
        assert z[k] > z[k - 1] and z[k] > np.min(z[k:]) + 2.0  # up to the arch, then an S down and up
        assert 15e3 < float(ds.tether_tension[0]) < 30e3
        assert float(ds.tether_s[0]) == 75.0
    if name == "pliant_wave_80m.yaml":
        k = _at(ds, 45.0)
        T = float(ds.tether_tension[0])
        assert 50.0 < T < 1e3
        anchor = np.array([44.0, 0.0, seabed_elevation(case.environment, 44.0)])
        reach = 2.0 * (1 + T / 1e6)
        node = np.array([float(ds.x[k]), float(ds.y[k]), float(ds.z[k])])
        assert np.linalg.norm(node - anchor) == pytest.approx(reach, rel=1e-9)


def _steep(per_metre: float, fairlead_x: float, bare: float = 30.0) -> Case:
    """A 130 m steep wave clamped straight up at its base, 50 m of buoyancy from ``bare`` m, hung off at
    ``fairlead_x``, no current."""
    data = yaml.safe_load((EXAMPLES / "steep_wave_80m.yaml").read_text())
    data["environment"].pop("current")
    data["line"]["sections"][0].update(start=bare, length=50.0)
    data["analysis"].update(fairlead=[fairlead_x, -14.0], element_length=1.0 / per_metre)
    return Case.parse(data)


def test_held_end_element_tension_tends_to_the_pull_along_the_clamp():
    """The steep wave clamped straight up with its line pulling at Delta = 76.5 deg off vertical (pinned: T =
    8348 N): as the mesh is refined the end element's tension falls towards T cos(Delta) = 1.95 kN, at first order
    (its excess over that, 4.6, 2.9, 1.5, 0.7 kN at 0.5 to 4 elements a metre, falls by 1.6-2.2 per halving): a
    pull at more than 90 deg from the clamp would ask the end element for compression, which the elements do not
    carry. Asserted: the excess falls by 1.4-2.6 per halving, and its extrapolation (Richardson, first order) lies
    within 15 % of T cos(Delta)."""
    tensions = []
    for per_metre in (0.5, 1.0, 2.0, 4.0):
        model = case_model(_steep(per_metre, 110.0))
        tensions.append(float(static_equilibrium(model, tol=1e-8).tension[0]))
    pinned = case_model(_steep(4.0, 110.0))
    pinned = type(pinned)(pinned.network.replace(end_hinges=()), pinned.water, checked=True)
    st = static_equilibrium(pinned, tol=1e-8)
    pull = st.position[1] - st.position[0]
    along = float(np.linalg.norm(st.support[0])) * pull[2] / np.linalg.norm(pull)
    excess = np.array(tensions) - along
    ratios = excess[:-1] / excess[1:]
    assert np.all((ratios > 1.4) & (ratios < 2.6)), ratios
    assert 2 * tensions[-1] - tensions[-2] == pytest.approx(along, rel=0.15)


def test_a_base_held_against_the_lines_pull_fails_with_the_reason():
    """The same steep wave hung off 100 m away pulls its base at 90.3 deg from the clamp's vertical: its end
    element would carry T cos(Delta) = -13 N. At 2 m elements it converges (the coarse end element's tension is
    larger by O(l): 267 N); at 1 m it has no equilibrium, and the message says so, with the angle and the
    tension."""
    assert float(static_equilibrium(case_model(_steep(0.5, 100.0)), tol=1e-8).tension[0]) > 0
    with pytest.raises(ConvergenceError, match=r"end A is held at a direction 90\.\d deg from the line's pull .*"
                                               r"would carry T cos\(angle\) = -\d+(\.\d+)? N"):
        sc.run(_steep(1.0, 100.0))


def test_near_far_and_cross_offsets_of_a_pliant_wave():
    """A pushover of the pliant wave (its tether holding the touchdown) along x, near -8 m to far +8 m, holds at
    each offset the static equilibrium with the hang-off moved there (the fairlead tension within 1e-6: both
    solve to the same tolerance from different starts), and across (heading pi / 2, the cross offsets) the
    tether's pull grows as the hang-off moves sideways by 8 m (the cable swings about its touchdown)."""
    data = yaml.safe_load((EXAMPLES / "pliant_wave_80m.yaml").read_text())
    data["analysis"].update(type="mooring_pushover", offsets=[-8.0, 0.0, 8.0])
    sweep = sc.run(Case.parse(data))
    for k, offset in enumerate((-8.0, 0.0, 8.0)):
        static = sc.run(_case("pliant_wave_80m.yaml", "flat", offset))
        assert float(sweep.fairlead_tension[k]) == pytest.approx(float(static.fairlead_tension), rel=1e-6)
        assert float(sweep.tether_tension[k, 0]) == pytest.approx(float(static.tether_tension[0]), rel=1e-5)
    data["analysis"].update(offsets=[0.0, 4.0, 8.0], heading=math.pi / 2)
    cross = sc.run(Case.parse(data)).tether_tension.values[:, 0]
    assert np.all(np.diff(cross) > 10.0)


def test_tether_and_clamp_in_the_dynamics():
    """``mooring_dynamic`` of the lazy-S at 2 m elements, its fairlead held, with a spring clamp (1 MN/m) on the
    seabed at s = 20 m: the tether's tension and the clamp's force are outputs over time (dims ``time``,
    ``tether`` / ``clamp``), at t = 0 the statics' (the run starts from it: within 1e-6), and the clamp's force is
    ``k |x - p|`` at every output."""
    data = yaml.safe_load((EXAMPLES / "lazy_s_80m.yaml").read_text())
    data["line"]["sections"].append({"type": "clamp", "s": 20.0, "position": {"x": 19.8}, "stiffness": 1e6})
    data["analysis"]["element_length"] = 2.0
    static = sc.run(Case.parse(data))
    data["analysis"].update(type="mooring_dynamic", duration=0.5, time_step=0.05, output_interval=0.25,
                            spectral_radius=0.9)
    ds = sc.run(Case.parse(data))
    assert ds.tether_tension.dims == ("time", "tether") and ds.clamp_force.dims == ("time", "clamp")
    assert float(ds.tether_tension[0, 0]) == pytest.approx(float(static.tether_tension[0]), rel=1e-6)
    assert float(ds.clamp_force[0, 0]) == pytest.approx(float(static.clamp_force[0]), rel=1e-6)
    k = _at(ds, 20.0)
    moved = np.stack([ds.x[:, k] - 19.8, ds.y[:, k], ds.z[:, k] + 80.0], axis=-1)
    assert ds.clamp_force.values[:, 0] == pytest.approx(1e6 * np.linalg.norm(moved, axis=-1), rel=1e-9)

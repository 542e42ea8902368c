"""A ``system_dynamic`` result holds the sea that drove it (issue 37, "a wrong answer is never silent").

``wave_elevation`` is the water surface at x = y = 0 with the name, units and long_name of a
``mooring_dynamic`` result's. Checked against the sea's own elevation: for a regular wave the closed
form ``H/2 cos(phase - omega t)`` at the origin, for an irregular sea the direct sum of the seeded
components that also load the lines; and absent in calm water.
"""

from __future__ import annotations

import math

import numpy as np

import seacable as sc
from seacable.mooring.run import elevation_variables
from seacable.mooring.solver import Water


def _case(waves):
    """One 60 m chain from an anchor 40 m deep to a coupled point 5 m deep, held still: a short run."""
    return sc.parse_case({
        "name": "one_line",
        "line_types": {"chain": {"diameter": 0.08, "mass_per_length": 40.0, "axial_stiffness": 5.0e8}},
        "environment": {"water_density": 1025.0, "gravity": 9.81, "depth": 40.0,
                        **({"waves": waves} if waves else {})},
        "points": {"anchor": {"kind": "fixed", "position": [0.0, 0.0, -40.0]},
                   "fair": {"kind": "coupled", "position": [50.0, 0.0, -5.0]}},
        "lines": {"l": {"line_type": "chain", "length": 60.0, "end_a": "anchor", "end_b": "fair"}},
        "analysis": {"type": "system_dynamic", "duration": 4.0, "time_step": 0.1, "output_interval": 0.25,
                     "n_elements": 6}})


def test_a_regular_wave_is_stored_as_its_closed_form_at_the_origin():
    H, T, phase = 2.0, 8.0, 0.7
    ds = sc.run(_case({"height": H, "period": T, "phase": phase}))
    t = ds["time"].values
    eta = ds["wave_elevation"]
    # eta = H/2 cos(k x cos(heading) + k y sin(heading) - omega t + phase) at x = y = 0; the elevation is a
    # sum of cosines evaluated in double precision: 1e-12 m
    assert np.max(np.abs(eta.values - 0.5 * H * np.cos(phase - 2 * math.pi / T * t))) < 1e-12
    # 4 s of an 8 s wave, sampled every 0.25 s: the crest or trough within 1 - cos(pi / 32) = 0.5 %
    assert np.max(np.abs(eta.values)) > 0.49 * H
    assert eta.attrs["units"] == "m"
    assert eta.attrs["long_name"] == "water surface elevation at x = y = 0 (0 at the still-water level)"
    # the mooring results' own variable: the same attributes
    water = Water(density=1025.0, gravity=9.81, depth=40.0, wave_height=1.0, wave_period=8.0)
    assert eta.attrs == elevation_variables(water, t)["wave_elevation"].attrs


def test_an_irregular_sea_is_stored_as_the_sum_of_its_components():
    waves = {"spectrum": "jonswap", "hs": 3.0, "tp": 9.0, "seed": 3}
    case = _case(waves)
    ds = sc.run(case)
    t = ds["time"].values
    sea = case.environment.waves.components(case.environment.depth, case.environment.gravity)
    # the direct sum over the seeded components, written out: sum_j a_j cos(p_j - w_j t) at x = y = 0; 1e-12 m
    direct = np.sum(sea.amplitude * np.cos(sea.phase - np.multiply.outer(t, sea.omega)), axis=1)
    assert np.max(np.abs(ds["wave_elevation"].values - direct)) < 1e-12
    assert np.std(direct) > 0.1  # Hs 3 m: a sea, not calm water


def test_calm_water_has_no_elevation():
    assert "wave_elevation" not in sc.run(_case(None))

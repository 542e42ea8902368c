"""mooring_pushover's offsets along a heading (issue 40: near, far and cross offsets of a cable's hang-off)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable import run
from seacable.case import Case


def pushover(offsets, heading=0.0):
    return run(Case.model_validate({
        "name": "cross",
        "line_types": {"c": {"diameter": 0.1, "mass_per_length": 20.0, "axial_stiffness": 5e8}},
        "line": {"line_type": "c", "length": 300.0},
        "environment": {"depth": 100.0},
        "analysis": {"type": "mooring_pushover", "fairlead": [250.0, -5.0], "offsets": list(offsets),
                     "heading": heading}}))


def test_cross_offset_is_the_far_offset_of_the_same_span():
    """A single line in still water pulls its fairlead straight at the anchor, with a force that depends only on the
    horizontal span: moved 20 m across (heading pi/2), the fairlead is sqrt(250^2 + 20^2) m out, and its pull is the
    far offset's at that span (the same static problem turned; to the solver's tolerance, 1e-6 of the force)."""
    cross = pushover([20.0], heading=math.pi / 2)
    far = pushover([math.hypot(250.0, 20.0) - 250.0])
    fx, fy = float(cross["fairlead_force_x"][0]), float(cross["fairlead_force_y"][0])
    assert float(cross["y"][0, -1]) == pytest.approx(20.0, abs=1e-12)
    assert math.atan2(fy, fx) == pytest.approx(math.atan2(-20.0, -250.0), abs=1e-9)
    assert math.hypot(fx, fy) == pytest.approx(-float(far["fairlead_force_x"][0]), rel=1e-6)


def test_heading_zero_is_the_far_and_near_pushover_along_x():
    """heading 0 (the default) moves the fairlead along +x: the same positions and forces as before the heading
    existed (offsets -10 m near, +10 m far; the pull grows with the offset)."""
    ds = pushover([-10.0, 0.0, 10.0])
    np.testing.assert_allclose(ds["x"].values[:, -1], [240.0, 250.0, 260.0], atol=1e-12)
    assert np.all(np.diff(-ds["fairlead_force_x"].values) > 0)
    np.testing.assert_array_equal(ds["fairlead_force_y"].values, 0.0)

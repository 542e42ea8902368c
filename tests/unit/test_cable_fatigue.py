"""Cable fatigue (seacable.design.cable_fatigue): the armour stress from tension and curvature around the section,
rainflow and Miner against the closed form of a cyclic bend and a cyclic tension."""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

from seacable.design.cable_fatigue import SNCurve, armour_stress, cable_fatigue_damage
from seacable.errors import InputError

N_CYCLES, PER_CYCLE = 10, 64
CURVE = SNCurve(a=1.0e12, m=3.0)


def bent_line(kappa, tension):
    """A result of a 9-node line along +x bent in the x-z plane on circular arcs (centre above: concave up) of
    curvature ``kappa[k]`` [1/m] at each time, the tension ``tension[k]`` [N] everywhere; 4 m elements."""
    s = 4.0 * np.arange(9) - 16.0
    X = np.zeros((len(kappa), 9, 3))
    for k, c in enumerate(kappa):
        X[k, :, 0] = np.sin(c * s) / c
        X[k, :, 2] = -100.0 + (1.0 - np.cos(c * s)) / c
    node = ("time", "node")
    return xr.Dataset({"x": (node, X[..., 0]), "y": (node, X[..., 1]), "z": (node, X[..., 2]),
                       "curvature": (node, np.repeat(np.asarray(kappa)[:, None], 9, 1)),
                       "tension": (node, np.repeat(np.asarray(tension)[:, None], 9, 1))},
                      coords={"time": np.arange(len(kappa)) * 0.1})


def cycle(mean, amplitude):
    """``mean - amplitude cos(2 pi t / T)`` over N_CYCLES periods from a trough to a trough."""
    t = np.arange(N_CYCLES * PER_CYCLE + 1) / PER_CYCLE
    return mean - amplitude * np.cos(2.0 * math.pi * t)


def test_a_cyclic_bend_damages_the_points_in_its_plane_as_miners_closed_form():
    """Curvature 0.05 +- 0.02 1/m at constant tension, c_kappa 2e9 Pa m: the inside and the outside of the bend (the
    points facing towards and away from the centre of curvature, phi = 3 pi / 2 and pi / 2 from the horizontal e_1 =
    t x z) see ranges of 2 c_kappa 0.02 = 80 MPa, ten cycles: D = 10 / (1e12 80^-3) = 5.12e-6 (to round-off); the
    points at phi = 0 and pi (the bend's neutral axis) see no range."""
    ds = bent_line(cycle(0.05, 0.02), np.full(N_CYCLES * PER_CYCLE + 1, 2.0e5))
    damage, hot = cable_fatigue_damage(ds, CURVE, tension_factor=1e3, curvature_factor=2e9)
    assert damage[4] == pytest.approx(N_CYCLES / CURVE.cycles_to_failure(80.0), rel=1e-9)
    assert hot[4] in (pytest.approx(0.5 * math.pi), pytest.approx(1.5 * math.pi))
    stress = armour_stress(ds, 1e3, 2e9)
    assert np.ptp(stress[:, 4, 0]) == pytest.approx(0.0, abs=1e-3)  # phi = 0: on the neutral axis
    assert np.ptp(stress[:, 4, 6]) == pytest.approx(80e6, rel=1e-9)


def test_a_cyclic_tension_stresses_every_point_alike():
    """Tension 300 +- 100 kN with a still bend, c_T 200 Pa/N: every point's range 40 MPa, D = 10 / (1e12 40^-3)."""
    ds = bent_line(np.full(N_CYCLES * PER_CYCLE + 1, 0.05), cycle(3.0e5, 1.0e5))
    damage, _ = cable_fatigue_damage(ds, CURVE, tension_factor=200.0, curvature_factor=2e9)
    np.testing.assert_allclose(damage, N_CYCLES / CURVE.cycles_to_failure(40.0), rtol=1e-9)


def test_tension_and_bend_in_phase_add_at_the_inside_point():
    """Both cycling in phase: the inside point's range (phi = 3 pi / 2, facing the centre of curvature) is the sum 40 +
    80 MPa, and it is the hot spot; the outside point's 80 - 40 MPa."""
    ds = bent_line(cycle(0.05, 0.02), cycle(3.0e5, 1.0e5))
    stress = armour_stress(ds, 200.0, 2e9)
    assert np.ptp(stress[:, 4, 6]) == pytest.approx(120e6, rel=1e-9)
    assert np.ptp(stress[:, 4, 2]) == pytest.approx(40e6, rel=1e-9)
    damage, hot = cable_fatigue_damage(ds, CURVE, 200.0, 2e9)
    assert damage[4] == pytest.approx(N_CYCLES / CURVE.cycles_to_failure(120.0), rel=1e-9)
    assert hot[4] == pytest.approx(1.5 * math.pi)


def test_two_slope_curve_is_continuous_at_its_knee():
    """N = a s^-m above the knee (1e7 cycles), N = 1e7 (s / s_knee)^-m2 below: continuous, and the lower slope."""
    c = SNCurve(a=1.0e12, m=3.0, m2=5.0, n_knee=1e7)
    knee = c.knee_range
    assert knee == pytest.approx((1e12 / 1e7) ** (1 / 3))
    assert c.cycles_to_failure(knee * (1 + 1e-12)) == pytest.approx(1e7, rel=1e-9)
    assert c.cycles_to_failure(knee / 2) == pytest.approx(1e7 * 2 ** 5, rel=1e-12)
    assert c.cycles_to_failure(2 * knee) == pytest.approx(1e7 / 2 ** 3, rel=1e-12)


def test_bad_inputs_are_refused():
    ds = bent_line(cycle(0.05, 0.02), np.full(N_CYCLES * PER_CYCLE + 1, 2.0e5))
    with pytest.raises(InputError, match="no curvature"):
        cable_fatigue_damage(ds.drop_vars("curvature"), CURVE, 1.0, 1.0)
    with pytest.raises(InputError, match="time-domain"):
        cable_fatigue_damage(ds.isel(time=0), CURVE, 1.0, 1.0)
    with pytest.raises(InputError, match="S-N curve m"):
        SNCurve(a=1e12, m=0.0)

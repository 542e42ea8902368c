"""Unit tests of seacable.environment."""

import math

import numpy as np
import pytest

import seacable as sc


def test_defaults_are_sea_water_and_standard_gravity():
    env = sc.Environment()
    assert (env.water_density, env.gravity, env.depth) == (1025.0, 9.81, None)


def test_uniform_current_velocity_has_its_heading():
    cur = sc.Current.uniform(1.5, heading=math.pi / 2)
    u, v, w = cur.velocity(-10.0)
    assert (u, v, w) == pytest.approx((0.0, 1.5, 0.0), abs=1e-12)


def test_profile_interpolates_linearly_and_holds_beyond_its_ends():
    cur = sc.Current.profile(depths=[0.0, 100.0], speeds=[1.0, 0.0])
    np.testing.assert_allclose(cur.speed_at([0.0, -50.0, -100.0, -300.0]), [1.0, 0.5, 0.0, 0.0])


@pytest.mark.parametrize("kw, expected", [
    (dict(depths=[10.0, 5.0], speeds=[1.0, 0.5]), "strictly increasing"),
    (dict(depths=[0.0, 5.0], speeds=[1.0]), "same non-zero length"),
    (dict(depths=[0.0, 5.0]), "needs both 'depths' and 'speeds'"),
])
def test_bad_profiles(kw, expected):
    with pytest.raises(sc.InputError, match=expected):
        sc.Current(**kw)


def test_heading_in_degrees_is_flagged():
    with pytest.warns(sc.SeacableWarning, match="looks like degrees"):
        sc.Current(speed=1.0, heading=90.0)


def test_slope_beyond_vertical_is_rejected_and_large_slope_warned():
    with pytest.raises(sc.InputError, match=r"seabed\.slope must be < 1\.5708 rad, got 5 rad"):
        sc.Environment(seabed={"slope": 5.0})
    with pytest.warns(sc.SeacableWarning, match="looks like degrees"):
        sc.Seabed(slope=1.0)


def test_negative_depth_and_friction_are_rejected():
    with pytest.raises(sc.InputError, match="depth must be > 0 m, got -3 m"):
        sc.Environment(depth=-3.0)
    with pytest.raises(sc.InputError, match="friction must be >= 0"):
        sc.Seabed(friction=-0.2)


def test_implausible_water_density_warns():
    with pytest.warns(sc.SeacableWarning, match="water_density"):
        sc.Environment(water_density=1.025)

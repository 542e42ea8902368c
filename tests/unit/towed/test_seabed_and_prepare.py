"""Issue 17 items 5, 6 and 7 for towed_dynamic's box formulation: the seabed it does not model is warned
about and measured, the checks before the time loop are made by prepare_towed_dynamic, and the result
carries the layback (the finite-element formulation's seabed contact: tests/validation/test_towed_fe.py)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import seacable as sc
from seacable.errors import InputError, SeacableWarning
from seacable.towed.run import prepare_towed_dynamic, run_towed_dynamic

CABLE = dict(diameter=0.035, mass_per_length=2.7904, weight_in_water=17.7, axial_stiffness=4.2333e5,
             bending_stiffness=32.41, drag_normal=1.5, drag_tangential=0.01, added_mass_normal=1.0)
DEPTH = 100.0


def _sled(depth=DEPTH, **analysis):
    """Paper 000's cable with a 2 kN sled, towed at 2 m/s, slowing to 0.5 m/s from t = 5 s to 15 s:
    the sled sinks from about 45 m to more than 150 m below the surface."""
    spec = dict(type="towed_dynamic", formulation="box",
                vessel=dict(type="speed_schedule", times=[0.0, 5.0, 15.0], speeds=[2.0, 2.0, 0.5]),
                duration=60.0, time_step=0.5, output_interval=1.0, n_nodes=7,
                body=dict(weight_in_water=2000.0, mass=250.0, added_mass=50.0, drag_area=0.5))
    spec.update(analysis)
    env = {"water_density": 1025.0} if depth is None else {"water_density": 1025.0, "depth": depth}
    return sc.Case.parse(dict(name="sled", line_types={"c": CABLE}, line={"line_type": "c", "length": 170.0},
                              environment=env, analysis=spec))


@pytest.fixture(scope="module")
def sled():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ds = run_towed_dynamic(_sled())
    return ds, [str(w.message) for w in caught if issubclass(w.category, SeacableWarning)]


def test_a_sled_that_crosses_the_seabed_is_warned_about_with_time_node_and_depth(sled):
    ds, messages = sled
    # one warning before the run (depth given, no contact modelled) and one for the crossing
    assert any("does not model seabed contact" in m for m in messages)
    crossing = [m for m in messages if "below the seabed at 100 m" in m]
    assert len(crossing) == 1
    z = ds.z.values
    below = np.argwhere(z < -DEPTH)
    i, j = below[0]
    assert f"t = {ds.time.values[i]:g} s" in crossing[0]
    assert f"node {j} (the towed body)" in crossing[0] and f"{-z[i, j]:g} m deep" in crossing[0]
    # the sled really does cross: above the seabed at the start, below it at the end
    assert z[0].min() > -DEPTH and z[-1].min() < -DEPTH


def test_seabed_clearance_is_negative_exactly_where_a_node_is_below_the_seabed(sled):
    ds, _ = sled
    clearance = ds.seabed_clearance.values
    z = ds.z.values  # the result's own node positions, independent of the clearance's computation
    np.testing.assert_array_equal(clearance < 0, (z < -DEPTH).any(axis=1))
    # and it is the lowest node's height above the seabed (the same subtraction: exact to rounding)
    np.testing.assert_allclose(clearance, z.min(axis=1) + DEPTH, rtol=0, atol=1e-12 * DEPTH)
    assert ds.seabed_clearance.attrs["units"] == "m"


def test_no_depth_no_warning_and_no_clearance():
    with warnings.catch_warnings():
        warnings.simplefilter("error", SeacableWarning)
        prepare_towed_dynamic(_sled(depth=None))


def test_layback_is_the_horizontal_distance_from_the_tow_point_to_the_sled(sled):
    ds, _ = sled
    end = ds.isel(node=0)
    expected = np.hypot(end.x.values - ds.vessel_x.values, end.y.values - ds.vessel_y.values)
    np.testing.assert_allclose(ds.layback.values, expected, rtol=1e-12)
    # as the vessel slows the sled falls back under it: the layback shrinks while the depth grows
    assert ds.layback.values[-1] < 0.8 * ds.layback.values[0]
    assert ds.lower_end_depth.values[-1] > ds.lower_end_depth.values[0]
    assert ds.layback.attrs["units"] == "m"
    # the tow point is at the surface: lower_end_depth is the depth below the ship, and says so
    assert "depth_below_ship" not in ds
    assert "below the ship" in ds.lower_end_depth.attrs["long_name"]


def test_zero_bending_stiffness_is_refused_before_the_run():
    case = sc.Case.parse(dict(name="c", line_types={"c": {**CABLE, "bending_stiffness": 0.0}},
                              line={"line_type": "c", "length": 170.0},
                              analysis=dict(type="towed_dynamic", formulation="box",
                                            vessel=dict(type="straight", speed=1.0), duration=10.0)))
    with pytest.raises(InputError, match=r"line.segments\[0\].line_type.bending_stiffness .*must be > 0 N m\^2 "
                                         r"for towed_dynamic, got 0.0 N m\^2"):
        sc.check(case)


def test_a_run_too_long_is_refused_with_the_estimate(monkeypatch):
    monkeypatch.setenv("SEACABLE_MAX_STEPS", "1000")
    with pytest.raises(InputError, match=r"needs about 2\.4e\+03 time steps"):
        prepare_towed_dynamic(_sled(depth=None, duration=1200.0))


def test_an_implausible_cable_length_is_refused():
    case = sc.Case.parse(dict(name="c", line_types={"c": CABLE}, line={"line_type": "c", "length": 1e300},
                              analysis=dict(type="towed_dynamic", vessel=dict(type="straight", speed=1.0),
                                            duration=10.0)))
    with pytest.raises(InputError, match=r"line.length must be in \[0, 100000\] m, got 1e\+300 m"):
        prepare_towed_dynamic(case)


def test_a_vessel_at_rest_in_still_water_is_refused_before_the_run():
    with pytest.raises(InputError, match="relative to the cable"):
        prepare_towed_dynamic(_sled(depth=None, vessel=dict(type="straight", speed=0.0)))


def test_a_velocity_at_t0_against_the_travel_is_warned_about(tmp_path):
    # a velocity table whose first sample points astern for an instant: the vessel then goes ahead
    t = np.arange(0.0, 61.0, 1.0)
    u = np.where(t == 0.0, -0.01, 1.0)
    path = tmp_path / "v.csv"
    path.write_text("time,u,v\n" + "".join(f"{a},{b},0\n" for a, b in zip(t, u)))
    case = _sled(depth=None, vessel=dict(type="table", file=str(path), kind="velocity"),
                 duration=20.0)
    with pytest.warns(SeacableWarning, match="points against the direction it then travels"):
        prepare_towed_dynamic(case)

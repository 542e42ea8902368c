"""Bad input to towed_dynamic's finite-element formulation, and the variables of its result (issue 21).

Each bad input gets one clear message (what, the value with units, what was expected, a fix) from the checks
``validate`` and ``run`` share (:func:`seacable.simulate.check`), and the CLI exits non-zero with it.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.cli import main
from seacable.errors import InputError

CABLE = {"diameter": 0.03, "mass_per_length": 2.0, "axial_stiffness": 4e6, "drag_normal": 1.5, "drag_tangential": 0.01}
LIGHT = {"diameter": 0.02, "mass_per_length": 0.5, "axial_stiffness": 2e6, "drag_normal": 1.2, "drag_tangential": 0.01}


def _spec(**analysis):
    spec = {"type": "towed_dynamic", "vessel": {"type": "straight", "speed": 1.5}, "duration": 20.0, "time_step": 1.0,
                "n_nodes": 21, "body": {"mass": 300.0, "weight_in_water": 2000.0, "drag_area": 0.3}}
    spec.update(analysis)
    return {"name": "tow", "line_types": {"c": CABLE, "p": LIGHT}, "line": {"line_type": "c", "length": 200.0},
                "environment": {"water_density": 1025.0}, "analysis": spec}


def _case(**analysis):
    return sc.Case.parse(_spec(**analysis))


def _two_part(**analysis):
    spec = _spec(**analysis)
    spec["line"] = {"segments": [{"line_type": "p", "length": 50.0}, {"line_type": "c", "length": 150.0}],
                    "attachments": [{"s": 50.0, "mass": 300.0, "weight_in_water": 2000.0, "drag_area": 0.3,
                                     "lift_coefficient": -0.6, "reference_area": 0.5, "kind": "depressor"}]}
    return sc.Case.parse(spec)


def test_haul_in_past_the_cable_is_refused_with_the_time_and_length():
    case = _case(winch={"rate": -10.0, "length": 2.0})
    with pytest.raises(InputError, match=r"hauls the cable in to 2 m deployed at t = [0-9.]+ s, past its length: "
                                         r"the lower end is at s = 0 m .* least length the model keeps is 5 m"):
        sc.check(case)


def test_haul_in_past_a_depressor_in_line_is_refused():
    case = _two_part(winch={"rate": -10.0, "length": 40.0})
    with pytest.raises(InputError, match=r"hauls the cable in to 40 m deployed .* the top segment starts at "
                                         r"s = 50 m \(a joint, an attachment or the body cannot pass the sheave\)"):
        sc.check(case)


def test_a_pay_out_table_not_increasing_in_time_is_refused():
    with pytest.raises(InputError, match=r"the pay-out table's times must increase, but times\[2\] = 5 s follows "
                                         r"times\[1\] = 10 s"):
        _case(winch={"times": [0.0, 10.0, 5.0], "lengths": [200.0, 210.0, 220.0]})


def test_a_pay_out_table_that_does_not_start_at_the_lines_length_is_refused():
    with pytest.raises(InputError, match=r"starts at 250 m deployed, but the line is 200 m long"):
        sc.check(_case(winch={"times": [0.0, 10.0], "lengths": [250.0, 260.0]}))


def test_a_rate_that_runs_away_from_its_target_length_is_refused():
    with pytest.raises(InputError, match=r"rate 1 m/s pays out but the target length 150 m is shorter than the "
                                         r"line's 200 m"):
        sc.check(_case(winch={"rate": 1.0, "length": 150.0}))


@pytest.mark.parametrize("where", ["body", "attachment"])
def test_a_lift_coefficient_without_its_area_is_refused(where):
    spec = _spec()
    if where == "body":
        spec["analysis"]["body"]["lift_coefficient"] = -0.5
    else:
        spec["line"]["attachments"] = [{"s": 100.0, "mass": 10.0, "lift_coefficient": 0.4}]
    with pytest.raises(InputError, match=r"lift_coefficient (-0.5|0.4) needs reference_area \(m\^2\), the area it "
                                         r"refers to, got None"):
        sc.Case.parse(spec)


def test_a_box_run_whose_steady_start_is_below_the_seabed_is_refused():
    spec = _spec(formulation="box", body={"mass": 300.0, "weight_in_water": 2000.0, "drag_area": 0.3})
    spec["line_types"]["c"]["bending_stiffness"] = 30.0
    spec["environment"]["depth"] = 40.0
    with pytest.raises(InputError, match=r"puts node 0 \(the towed body\) [0-9.]+ m deep, below the seabed at 40 m "
                                         r".* Suggested fix: formulation: finite_element"):
        sc.check(sc.Case.parse(spec))


def test_a_tow_point_below_the_seabed_is_refused(tmp_path):
    table = tmp_path / "path.csv"
    table.write_text("time,x,y,z\n" + "".join(f"{t},{1.5 * t},0,-50\n" for t in range(31)))
    spec = _spec(vessel={"type": "table", "file": str(table), "kind": "position"})
    spec["environment"]["depth"] = 40.0
    with pytest.raises(InputError, match=r"the tow point starts 50 m deep, below the seabed at 40 m"):
        sc.check(sc.Case.parse(spec))


def test_the_box_formulation_refuses_what_it_does_not_model():
    with pytest.raises(InputError, match="the box formulation has a fixed cable length"):
        _case(formulation="box", winch={"rate": 1.0})
    with pytest.raises(InputError, match="the box formulation does not model a body's lift"):
        _case(formulation="box", body={"mass": 1.0, "lift_coefficient": -0.5, "reference_area": 1.0})
    two = _two_part(formulation="box")
    with pytest.raises(InputError, match="use formulation: finite_element"):
        sc.check(two)


def test_validate_exits_non_zero_with_the_message(tmp_path, capsys):
    path = tmp_path / "haul.yaml"
    path.write_text(yaml.safe_dump(_spec(winch={"rate": -10.0, "length": 2.0})))
    assert main(["validate", str(path)]) == 2
    err = capsys.readouterr().err
    assert "hauls the cable in to 2 m deployed" in err and "Traceback" not in err


def test_the_result_names_each_body_its_layback_and_depth_and_the_length_paid_out():
    case = _two_part(winch={"rate": 0.5, "start_time": 2.0, "ramp": 4.0}, duration=20.0)
    ds = sc.run(case)
    assert list(ds.point.values) == ["body", "attachments[0] (depressor)"]
    np.testing.assert_allclose(ds.point_s.values, [0.0, 50.0])
    tow_x, tow_y = ds.vessel_x.values, ds.vessel_y.values
    body = ds.isel(node=0)
    np.testing.assert_allclose(ds.point_layback.values[:, 0], np.hypot(body.x - tow_x, body.y - tow_y), rtol=1e-12)
    np.testing.assert_allclose(ds.point_depth.values[:, 0], -body.z.values, rtol=1e-12)  # the tow point at z = 0
    assert np.all(ds.point_depth.values[:, 0] > ds.point_depth.values[:, 1])  # the body below the depressor
    L = case.analysis.winch.deployed(ds.time.values, 200.0)
    np.testing.assert_allclose(ds.deployed_length.values, L, rtol=1e-12)
    np.testing.assert_allclose(ds.paid_out_length.values, L - 200.0, atol=1e-9)
    top = ds.top_angle.values
    assert np.all((top > 0.0) & (top < math.pi / 2))
    assert ds.top_angle.attrs["units"] == "rad" and ds.point_layback.attrs["units"] == "m"
    assert '"formulation": "finite_element"' in ds.attrs["settings"]


def test_a_seabed_profile_is_for_the_finite_element_tow_only():
    spec = _spec()
    spec["environment"]["seabed"] = {"profile": {"distance": [0.0, 500.0], "depth": [150.0, 130.0]}}
    ds = sc.run(sc.Case.parse(spec))  # the towfish at 2 kN on 200 m at 1.5 m/s flies clear of it
    assert ds.seabed_clearance.values.min() > 0.0
    box = _spec(formulation="box")
    box["environment"]["seabed"] = spec["environment"]["seabed"]
    with pytest.raises(InputError, match=r"environment.seabed.profile is given, but analysis 'towed_dynamic' does "
                                         r"not use it \(the profile is taken by towed_dynamic's finite_element "
                                         r"formulation only\)"):
        sc.Case.parse(box)
    both = _spec()
    both["environment"]["seabed"] = {"slope": 0.05, "profile": spec["environment"]["seabed"]["profile"]}
    with pytest.raises(InputError, match="seabed.slope 0.05 rad and seabed.profile both give the seabed"):
        sc.Case.parse(both)


def test_a_sled_on_a_rising_seabed_profile_rides_on_it():
    """A heavy sled on 300 m of cable in 100 m of water rising to 70 m: it stays on the seabed (pressed in by
    millimetres) as the seabed rises under it, and the clearance is the lowest node's height above the profile."""
    spec = _spec(body=dict(mass=600.0, weight_in_water=5000.0, drag_area=0.2, seabed_area=2.0),
                 vessel=dict(type="straight", speed=1.0), duration=150.0, time_step=1.0, n_nodes=31)
    spec["line"]["length"] = 300.0
    spec["environment"]["seabed"] = {"profile": {"distance": [-400.0, -260.0, 0.0], "depth": [100.0, 100.0, 70.0]},
                                     "friction": 0.3}
    ds = sc.run(sc.Case.parse(spec))
    x, z = ds.x.values[:, 0], ds.z.values[:, 0]
    floor = -np.interp(x, [-400.0, -260.0, 0.0], [100.0, 100.0, 70.0])
    assert np.all(np.abs(z - floor) < 0.01)  # on the seabed as it rises (penetration W / (k A) < 1 mm)
    assert floor[-1] - floor[0] > 5.0  # it has climbed
    np.testing.assert_allclose(ds.seabed_clearance.values, np.nanmin(ds.z.values - (-np.interp(
        ds.x.values, [-400.0, -260.0, 0.0], [100.0, 100.0, 70.0])), axis=1), atol=1e-12)


def test_a_box_run_whose_steady_start_is_above_the_surface_is_refused():
    """The box scheme weighs every node in water (issue 37, item 1): a body buoyant by 5 kN (the 200 m cable
    weighs 2.5 kN in water) floats the lower end up past the tow point at the surface; refused before the run
    (by validate too), naming the node."""
    spec = _spec(formulation="box", body={"mass": 300.0, "weight_in_water": -5000.0, "drag_area": 0.3})
    spec["line_types"]["c"]["bending_stiffness"] = 30.0
    with warnings.catch_warnings():   # the steady tow's own warning of a shape above the tow point
        warnings.simplefilter("ignore", sc.SeacableWarning)
        with pytest.raises(InputError, match=r"puts node 0 \(the towed body\) [0-9.]+ m above the sea surface"):
            sc.check(sc.Case.parse(spec))


def test_surface_excursion_is_the_highest_node_but_the_tow_point_and_warns_when_out_of_the_water():
    """Three output times of three nodes (the last the tow point, 2 m up on a deck): the highest of the others,
    and a warning naming the first time and node out of the water."""
    from seacable.towed.seabed import surface_excursion

    z = np.array([[-5.0, -1.0, 2.0], [-5.0, 0.5, 2.0], [0.25, -1.0, 2.0]])
    with pytest.warns(sc.SeacableWarning, match=r"at t = 1 s node 1 is 0.5 m above the sea surface"):
        h = surface_excursion([0.0, 1.0, 2.0], z, analysis="test")
    np.testing.assert_array_equal(h, [-1.0, 0.5, 0.25])
    np.testing.assert_array_equal(surface_excursion([0.0], z[:1, :2], analysis="test", skip_last=False), [-1.0])

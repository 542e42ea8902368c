"""Mooring-system cases (seacable.system.case, seacable.system.run): files, checks, results.

The physics asserted: the equilibrium of the body (the lines' horizontal pull balances the external
load), the mirror symmetry of the spread, the anchor loads as components of the solver's end force,
the damaged body drifting away from the broken line's anchor, the watch circle at no load being the
static equilibrium, the restoring force equal to the load, and the compliance of small loads
against the inverse of the reported stiffness.
"""

from __future__ import annotations

import json
import math
import pickle
import re
from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.cli import main
from seacable.io import dump_case, parse_case
from seacable.results import open_netcdf, stiffness_matrix
from seacable.system import SystemCase, SystemOffsetsAnalysis, SystemStaticAnalysis

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SPREAD = EXAMPLES / "spread_mooring.yaml"
WATCH = EXAMPLES / "spread_mooring_watch_circle.yaml"
LOAD = 5.0e5  # the environmental load of spread_mooring.yaml along +x [N]


def _data(path=SPREAD) -> dict:
    return yaml.safe_load(path.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def spread():
    """The example case and its system_static result (intact and line1 broken)."""
    case = sc.load_case(SPREAD)
    return case, sc.run(case)


@pytest.fixture(scope="module")
def offsets():
    """A small watch-circle sweep of the example (no constant load on the buoy), and the static case."""
    case = sc.load_case(WATCH)
    small = case.replace(analysis=SystemOffsetsAnalysis(body="buoy", loads=(0.0, 1.0e3, 2.5e5, 5.0e5),
                                                        headings=(0.0, math.pi / 3, -math.pi / 3, math.pi),
                                                        damaged_lines=("line1",)))
    static = case.replace(analysis=SystemStaticAnalysis(damaged_lines=("line1",)))
    return small, sc.run(small), sc.run(static)


# --- files ----------------------------------------------------------------------------------------

def test_a_file_with_lines_and_no_line_is_a_system_case_and_single_line_cases_are_unchanged():
    case = sc.load_case(SPREAD)
    assert isinstance(case, SystemCase)
    assert set(case.lines) == {"line1", "line2", "line3"}
    assert case.lines["line1"].line.segments[0].line_type.axial_stiffness == 7.7e8
    assert case.analysis.damaged_lines == "most_loaded"  # line1 under its load (the damaged tests below)
    assert isinstance(sc.load_case(EXAMPLES / "oc3_hywind_static.yaml"), sc.Case)


def test_a_file_with_line_and_lines_is_refused():
    data = {**_data(), "line": {"line_type": "chain", "length": 650.0}}
    with pytest.raises(sc.CaseFileError, match="has 'line' .* and 'lines' .*; a case is one or the other"):
        parse_case(data)


def test_segments_form_equals_the_short_form():
    data = _data()
    long = {**data, "lines": {**data["lines"], "line1": {"segments": [{"line_type": "chain", "length": 650.0}],
                                                         "end_a": "anchor1", "end_b": "fairlead1"}}}
    assert parse_case(long) == parse_case(data)


def test_dump_parse_round_trip_and_pickle():
    case = sc.load_case(SPREAD)
    assert parse_case(yaml.safe_load(dump_case(case))) == case
    assert pickle.loads(pickle.dumps(case)) == case


@pytest.mark.parametrize("edit, expected", [
    (("lines", "line1", "end_b", "fairled1"),
     ("lines.line1.end_b: point 'fairled1' is not defined (points: anchor1, anchor2, anchor3, fairlead1, fairlead2, "
      "fairlead3). Did you mean 'fairlead1'?")),
    (("points", "fairlead2", "body", "boy"), ("points.fairlead2.body: body 'boy' is not defined (bodies: buoy). "
                                              "Did you mean 'buoy'?")),
    (("bodies", "buoy", "mass", -1.0), "bodies.buoy.mass must be >= 0 kg, got -1 kg"),
    (("bodies", "buoy", "inertia", [5.9e7, -1.0, 3.0e7]), "bodies.buoy inertia must hold three moments >= 0"),
    (("lines", "line2", "length", -650.0), "lines.line2.length must be > 0 m, got -650 m"),
    (("lines", "line2", "line_type", "chian"), ("lines.line2.line_type 'chian' is not defined in line_types "
                                                "(defined: chain). Did you mean 'chain'?")),
    (("analysis", "damaged_lines", ["line4"]), "analysis.damaged_lines[0]: line 'line4' is not defined"),
    (("points", "anchor1", "position", [-606.0, 0.0, -160.0]), ("points.anchor1.position: z = -160 m is below "
                                                                "the seabed at z = -150 m")),
    (("environment", "depth", None), "needs environment.depth"),
])
def test_bad_system_files_name_the_key_the_value_and_a_fix(edit, expected):
    data = _data()
    node = data
    for key in edit[:-2]:
        node = node[key]
    node[edit[-2]] = edit[-1]
    with pytest.raises(sc.CaseFileError) as info:
        parse_case(data, source="f.yaml")
    assert expected in str(info.value)
    assert "\n" not in str(info.value)  # one message


def test_a_free_body_with_no_lines_and_no_horizontal_restoring_is_refused_before_solving(tmp_path, capsys):
    """The issue's bad input 'a body with no lines': a free body no line ends on has no horizontal restoring, so
    system_static has no equilibrium for it: one message naming the body, its surge and sway stiffness and the fixes
    (seacable validate refuses it as run would). The file itself is valid (the dynamics run such a body)."""
    data = _data()
    data["bodies"]["spare"] = {"mass": 1.0e3, "volume": 1.0}
    case = parse_case(data)
    assert "spare" in case.bodies
    path = tmp_path / "spare.yaml"
    path.write_text(yaml.safe_dump(data))
    assert main(["validate", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("seacable: error:") == 1 and "Traceback" not in err
    assert ("bodies.spare: a free body that no line of 'lines' ends on has no horizontal restoring (surge 0 N/m, sway 0 N/m"
            in err and "Suggested fix:" in err and "system_dynamic" in err)


@pytest.mark.parametrize("change", [{"kind": "fixed"}, {"kind": "prescribed"}])
def test_a_held_body_with_no_lines_is_part_of_the_system(change):
    """A fixed or prescribed body no line ends on stays where it is given; the rest of the system is unchanged
    (the same tensions as without it: 1e-12, the same equilibrium solved twice)."""
    base = sc.run(parse_case(_data()))
    data = _data()
    data["bodies"]["spare"] = {"mass": 1.0e3, "volume": 1.0, "position": [50.0, 0.0, -5.0, 0.0, 0.0, 0.0], **change}
    ds = sc.run(parse_case(data))
    assert ds["body_x"].sel(body="spare").values == pytest.approx(50.0)
    assert np.allclose(ds["fairlead_tension"].values, base["fairlead_tension"].values, rtol=1e-12, equal_nan=True)


@pytest.mark.parametrize("damaged, expected", [
    (["line4"], ("damaged condition (analysis.damaged_lines ['line4'] removed): bodies.marker: a free body that no "
                 "line of 'lines' ends on has no horizontal restoring")),
    (["line1", "line2", "line3", "line4"], "removes every line"),
])
def test_a_damaged_system_that_leaves_a_body_without_lines_is_refused_before_solving(tmp_path, capsys, damaged,
                                                                                    expected):
    data = _data()
    data["bodies"]["marker"] = {"mass": 1.0e3, "volume": 2.0, "waterplane_area": 1.0,
                                "position": [-500.0, 0.0, 0.0, 0.0, 0.0, 0.0]}  # line4 reaches it from anchor1
    data["points"]["marker_eye"] = {"kind": "body", "body": "marker", "position": [0.0, 0.0, -1.0]}
    data["lines"]["line4"] = {"line_type": "chain", "length": 200.0, "end_a": "anchor1", "end_b": "marker_eye"}
    data["analysis"]["damaged_lines"] = damaged
    path = tmp_path / "d.yaml"
    path.write_text(yaml.safe_dump(data))
    assert main(["validate", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("seacable: error:") == 1 and "Traceback" not in err
    assert expected in err


def test_offsets_needs_a_free_body_and_increasing_loads():
    data = _data(WATCH)
    for change, expected in (({"body": "bouy"}, "body 'bouy' is not defined (bodies: buoy). Did you mean 'buoy'?"),
                             ({"loads": [0.0, 5.0e5, 2.5e5]}, "loads must increase"),
                             ({"loads": [-1.0]}, "loads[0] must be a finite number >= 0 N, got -1.0 N")):
        with pytest.raises(sc.CaseFileError, match="analysis") as info:
            parse_case({**data, "analysis": {**data["analysis"], **change}})
        assert expected in str(info.value)
    data["bodies"]["buoy"]["kind"] = "fixed"
    with pytest.raises(sc.CaseFileError, match="'buoy' is 'fixed'"):
        parse_case(data)


def test_validate_accepts_the_examples(capsys):
    assert main(["validate", str(SPREAD), str(WATCH)]) == 0
    assert capsys.readouterr().out.count("3 line(s), 1 body(ies), 6 point(s)") == 2


# --- system_static: physics ------------------------------------------------------------------------

def test_result_holds_the_solver_values(spread):
    """The result's tensions, anchor loads and stiffness are the solver's (the intact system)."""
    from seacable.system.statics import solve_equilibrium

    case, ds = spread
    eq = solve_equilibrium(case.system(), case.environment, tol=case.analysis.tolerance)
    intact = ds.sel(condition="intact")
    order = [list(eq.line_names).index(n) for n in ds.line.values]
    np.testing.assert_allclose(intact.anchor_tension.values, np.asarray(eq.end_a_tension)[order], rtol=1e-12)
    np.testing.assert_allclose(intact.fairlead_tension.values, np.asarray(eq.end_b_tension)[order], rtol=1e-12)
    fa = np.asarray(eq.end_a_force)[order]
    np.testing.assert_allclose(intact.anchor_horizontal_force.values, np.hypot(fa[:, 0], fa[:, 1]), rtol=1e-12)
    np.testing.assert_allclose(intact.anchor_vertical_force.values, fa[:, 2], rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(intact.grounded_length.values, np.asarray(eq.grounded_length)[order], rtol=1e-12)
    np.testing.assert_allclose(stiffness_matrix(intact).sel(body="buoy").values, eq.body_stiffness("buoy"), rtol=1e-12)
    np.testing.assert_allclose(stiffness_matrix(intact, "coupled_stiffness").values, eq.stiffness, rtol=1e-12)


def test_anchor_loads_are_the_components_of_the_anchor_tension(spread):
    _, ds = spread
    h, v = ds.anchor_horizontal_force.values, ds.anchor_vertical_force.values
    ok = np.isfinite(h)
    # the end force's magnitude is the end tension (same numbers, rounding only)
    np.testing.assert_allclose(np.hypot(h, v)[ok], ds.anchor_tension.values[ok], rtol=1e-9)
    np.testing.assert_allclose(np.tan(ds.anchor_uplift_angle.values[ok]), (v / h)[ok], rtol=1e-9, atol=1e-12)


def test_the_lines_hold_the_load(spread):
    """Body equilibrium in the horizontal plane: the lines' pull on the fairleads balances the load."""
    _, ds = spread
    for condition in ds.condition.values:
        d = ds.sel(condition=condition)
        fx = np.nansum(d.fairlead_force_x.values)   # every line ends B on the buoy
        fy = np.nansum(d.fairlead_force_y.values)
        # the solver's tolerance is 1e-8 relative; 1e-6 of the load leaves room for its scaling
        assert abs(fx + LOAD) < 1e-6 * LOAD, (condition, fx)
        assert abs(fy) < 1e-6 * LOAD, (condition, fy)


def test_the_spread_is_symmetric_about_the_load(spread):
    """Lines 2 and 3 are mirror images about the x axis, as is the load: equal tensions, no sway."""
    _, ds = spread
    for condition in ds.condition.values:
        d = ds.sel(condition=condition)
        # mirror symmetry holds to the solver's tolerance (1e-8); 1e-6 relative
        np.testing.assert_allclose(d.fairlead_tension.sel(line="line2"), d.fairlead_tension.sel(line="line3"),
                                   rtol=1e-6)
        assert abs(float(d.body_y.sel(body="buoy"))) < 1e-6 * float(d.body_offset.sel(body="buoy"))
    i = ds.sel(condition="intact")
    # line1 is upwind of the +x load: it holds the most
    assert float(i.fairlead_tension.sel(line="line1")) > float(i.fairlead_tension.sel(line="line2"))
    assert float(i.body_x.sel(body="buoy")) > 0


def test_the_damaged_body_drifts_away_from_the_broken_line(spread):
    _, ds = spread
    assert list(ds.condition.values) == ["intact", "damaged"]
    assert ds.line_present.sel(condition="damaged").values.tolist() == [0, 1, 1]
    assert np.isnan(ds.fairlead_tension.sel(condition="damaged", line="line1"))
    intact, damaged = (float(ds.body_x.sel(condition=c, body="buoy")) for c in ("intact", "damaged"))
    # line1's anchor is at -x: without it the buoy goes further along +x, and the others take the load
    assert damaged > intact + 1.0
    t = ds.fairlead_tension.sel(line="line2")
    assert float(t.sel(condition="damaged")) > float(t.sel(condition="intact"))


def test_translational_stiffness_is_symmetric_and_positive(spread):
    _, ds = spread
    k = stiffness_matrix(ds).sel(condition="intact", body="buoy").values
    # translations: the lines' force derives from their elastic and gravity energy, so the translational
    # block is symmetric to rounding (the rotational blocks are not under a net line moment)
    t = k[:3, :3]
    np.testing.assert_allclose(t, t.T, rtol=1e-6, atol=1e-9 * np.abs(t).max())
    assert k[0, 0] > 0 and k[1, 1] > 0 and k[5, 5] > 0
    assert ds.stiffness_translation.dims == ("condition", "body", "dof", "dof2")
    assert list(ds.dof.values) == ["surge", "sway", "heave", "roll", "pitch", "yaw"]


def test_profiles_run_from_anchor_to_fairlead(spread):
    _, ds = spread
    d = ds.sel(condition="intact", line="line1")
    # the profile's ends are the line's end points (anchor1 and fairlead1)
    a, b = ds.sel(condition="intact", point="anchor1"), ds.sel(condition="intact", point="fairlead1")
    np.testing.assert_allclose([d.x[0], d.y[0], d.z[0]], [a.point_x, a.point_y, a.point_z], atol=1e-6)
    np.testing.assert_allclose([d.x[-1], d.y[-1], d.z[-1]], [b.point_x, b.point_y, b.point_z], atol=1e-6)
    assert float(d.s[-1]) == 650.0
    np.testing.assert_allclose(float(d.tension[-1]), float(d.fairlead_tension), rtol=1e-6)


def test_every_variable_is_labelled_and_the_netcdf_round_trips(spread, tmp_path):
    _, ds = spread
    for name in list(ds.data_vars) + list(ds.coords):
        assert {"units", "long_name"} <= set(ds[name].attrs), name
    path = sc.write_netcdf(ds, tmp_path / "r.nc")
    back = sc.read_netcdf(path)
    for name in ds.data_vars:
        np.testing.assert_array_equal(back[name].values, ds[name].values, err_msg=name)
    assert list(back.line.values) == ["line1", "line2", "line3"]
    assert back.attrs["analysis"] == "system_static"
    assert isinstance(parse_case(yaml.safe_load(back.attrs["case"])), SystemCase)


# --- system_offsets: physics -----------------------------------------------------------------------

def test_watch_circle_at_no_load_is_the_static_equilibrium(offsets):
    _, ds, static = offsets
    for condition in ds.condition.values:
        at_rest = ds.sel(condition=condition, applied_load=0.0)
        s = static.sel(condition=condition)
        for name in ("body_x", "body_y", "body_z"):
            # the same equilibrium solved twice from the same start: equal to the solver's tolerance
            np.testing.assert_allclose(at_rest[name].sel(body="buoy").values,
                                       np.full(ds.heading.size, float(s[name].sel(body="buoy"))), atol=1e-6)


def test_restoring_force_is_the_load(offsets):
    """At equilibrium the lines' horizontal pull on the buoy against the heading equals the load."""
    _, ds, _ = offsets
    load = ds.applied_load.values[None, :, None]
    # the residual tolerance is 1e-8 relative; 1e-6 of the largest load
    np.testing.assert_allclose(ds.restoring_force.values, np.broadcast_to(load, ds.restoring_force.shape),
                               atol=1e-6 * ds.applied_load.values.max())


def test_small_loads_follow_the_stiffness(offsets):
    """A 1 kN load displaces the buoy by the compliance: the inverse of the total 6x6 stiffness."""
    _, ds, static = offsets
    s = static.sel(condition="intact")
    k = stiffness_matrix(s).sel(body="buoy").values + stiffness_matrix(s, "hydrostatic_stiffness").sel(body="buoy").values
    d = ds.sel(condition="intact")
    f = 1.0e3
    for h in d.heading.values:
        u = np.array([math.cos(h), math.sin(h), 0, 0, 0, 0])
        expected = f * u[:2] @ np.linalg.solve(k, u)[:2]
        moved = float(d.offset.sel(applied_load=f, heading=h) - d.offset.sel(applied_load=0.0, heading=h))
        # linear for a 1 kN load (the surge stiffness changes by < 0.1 % over the 1 kN offset)
        assert moved == pytest.approx(expected, rel=2e-3), h


def test_watch_circle_is_symmetric_and_largest_against_the_broken_line(offsets):
    _, ds, _ = offsets
    i = ds.sel(condition="intact", applied_load=5.0e5)
    # the headings +60 and -60 deg are mirror images about the x axis
    a, b = i.sel(heading=math.pi / 3), i.sel(heading=-math.pi / 3)
    np.testing.assert_allclose(float(a.body_offset_x.sel(body="buoy")), float(b.body_offset_x.sel(body="buoy")),
                               rtol=1e-6)
    np.testing.assert_allclose(float(a.body_offset_y.sel(body="buoy")), -float(b.body_offset_y.sel(body="buoy")),
                               rtol=1e-6)
    # a load towards +x (heading 0) pulls the buoy away from line1's anchor: with line1 broken the offset
    # along the heading is larger
    off = ds.offset.sel(applied_load=5.0e5, heading=0.0)
    assert float(off.sel(condition="damaged")) > float(off.sel(condition="intact"))


# --- command line ----------------------------------------------------------------------------------

def test_cli_runs_and_plots_a_system_case(tmp_path, capsys):
    out = tmp_path / "spread.nc"
    assert main(["run", str(SPREAD), "-o", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "spread_system.png" in printed and "spread_tensions.png" in printed
    assert main(["plot", str(out), "-o", str(tmp_path / "figs")]) == 0
    assert sorted(p.name for p in (tmp_path / "figs").glob("*.png")) == ["spread_system.png", "spread_tensions.png"]
    ds = open_netcdf(out)
    assert ds.attrs["analysis"] == "system_static"
    ds.close()


def test_no_equilibrium_names_the_residual_the_offset_and_a_ramp(tmp_path, capsys):
    data = _data()
    data["analysis"]["max_iterations"] = 1
    path = tmp_path / "stuck.yaml"
    path.write_text(yaml.safe_dump(data))
    assert main(["run", str(path), "--no-plots", "-o", str(tmp_path / "r.nc")]) == 2
    err = capsys.readouterr().err
    assert err.count("seacable: error:") == 1 and "Traceback" not in err
    assert "no equilibrium found" in err and "intact condition" in err
    assert "offset" in err and "Suggested fix" in err and "load_steps" in err


def test_load_steps_reach_the_same_equilibrium(spread):
    case, ds = spread
    ramped = sc.run(case.replace(analysis=SystemStaticAnalysis(load_steps=4)))
    # the same equilibrium reached through 4 steps: equal to the solver's tolerance
    np.testing.assert_allclose(ramped.body_x.values[0], ds.body_x.values[0], atol=1e-6)


def _write(tmp_path, data, name="case.yaml") -> str:
    path = tmp_path / name
    path.write_text(yaml.safe_dump(data))
    return str(path)


@pytest.mark.parametrize("change, expected", [
    # metacentric height 7.5 + 0.6 - 20 < 0: roll stiffness rho g (I + V z_B) - m g z_G < 0, lines too weak
    (("bodies", "buoy", "center_of_gravity", [0.0, 0.0, 5.0]), ["bodies.buoy", "roll", "capsizes"]),
])
def test_validate_refuses_what_run_would_before_solving(tmp_path, capsys, change, expected):
    data = _data()
    node = data
    for key in change[:-2]:
        node = node[key]
    node[change[-2]] = change[-1]
    path = _write(tmp_path, data)
    for argv in (["validate", path], ["run", path, "--no-plots", "-o", str(tmp_path / "r.nc")]):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert err.count("seacable: error:") == 1 and "Traceback" not in err
        for word in expected:
            assert word in err, (word, err)
    assert not (tmp_path / "r.nc").exists()


def test_a_current_is_validated_and_run_with_the_finite_element_statics(tmp_path, capsys):
    """A current (which the catenary lines cannot carry) is no longer refused: validate passes and the run
    says it used the finite-element statics, with the stiffness by central differences; the buoy is carried
    downstream (+x) of its still-water equilibrium."""
    data = _data()
    data["environment"]["current"] = {"speed": 1.0}
    data["analysis"] = {"type": "system_static"}
    path = _write(tmp_path, data)
    assert main(["validate", path]) == 0
    capsys.readouterr()
    case = sc.load_case(path)
    ds = sc.run(case)
    assert ds.attrs["statics"] == "finite_element" and "current" in ds.attrs["statics_reason"]
    assert ds.attrs["stiffness_method"] == "central differences of the finite-element statics"
    still = sc.run(case.replace(environment=case.environment.model_copy(update={"current": sc.Current()})))
    assert still.attrs["statics"] == "catenary"
    assert float(ds.body_x[0, 0]) > float(still.body_x[0, 0])


def test_the_case_file_chooses_the_statics(tmp_path, capsys):
    """``analysis.statics`` in the file: 'finite_element' in still water gives the FE statics, whose fairlead
    tensions agree with the catenary's to the resolution of the touchdown by the nodes: the grounded length
    is known to an element, and half an element of suspended chain more or less moves the fairlead tension
    by at most w le / 2 (le = 650 m / 20 elements, w the chain's submerged weight: 25 kN, the measured gap
    is 2.6 kN; test_system_statics_fe shows the order of convergence); 'catenary' with a current is refused
    at validate, naming the current and the fix."""
    data = _data()
    data["analysis"] = {"type": "system_static", "statics": "finite_element"}
    fe = sc.run(sc.load_case(_write(tmp_path, data)))
    assert fe.attrs["statics"] == "finite_element"
    data["analysis"]["statics"] = "catenary"
    cat = sc.run(sc.load_case(_write(tmp_path, data)))
    assert cat.attrs["statics"] == "catenary"
    chain = sc.load_case(_write(tmp_path, data)).line_types["chain"]
    w = (chain.mass_per_length - 1025.0 * np.pi / 4 * chain.diameter ** 2) * 9.80665
    np.testing.assert_allclose(fe.fairlead_tension.values, cat.fairlead_tension.values, rtol=0,
                               atol=w * (650.0 / 20) / 2)
    assert not np.allclose(fe.fairlead_tension.values, cat.fairlead_tension.values, rtol=1e-6)  # two solvers
    data["environment"]["current"] = {"speed": 1.0}
    path = _write(tmp_path, data)
    assert main(["validate", path]) == 2
    err = capsys.readouterr().err
    assert "current" in err and "Suggested fix" in err and "Traceback" not in err


def test_points_below_a_sloping_seabed_are_refused_where_the_plane_is(tmp_path, capsys):
    """On a seabed rising towards +x by 0.05 rad the bed under x is at -150 + tan(0.05) x: anchor1 at
    x = -606 m may sit 30.3 m below -150 m (it was refused against the flat -150 m), and anchor2 at
    x = 303 m, 15.2 m under its bed, is refused with the bed's height in the message."""
    data = _data()
    data["environment"]["seabed"] = {"slope": 0.05}
    bed1 = -150.0 + math.tan(0.05) * -606.0
    data["points"]["anchor1"]["position"] = [-606.0, 0.0, bed1]
    data["points"]["anchor2"]["position"] = [303.0, 524.811, -150.0 + math.tan(0.05) * 303.0]
    data["points"]["anchor3"]["position"] = [303.0, -524.811, -150.0 + math.tan(0.05) * 303.0]
    data["analysis"] = {"type": "system_static"}
    assert main(["validate", _write(tmp_path, data)]) == 0
    data["points"]["anchor2"]["position"] = [303.0, 524.811, -150.0]
    assert main(["validate", _write(tmp_path, data)]) == 2
    err = capsys.readouterr().err
    assert "points.anchor2.position: z = -150 m is below the seabed at z = -134.8" in err
    assert "seabed.slope 0.05 rad at x = 303 m" in err


def test_no_equilibrium_under_a_load_the_lines_cannot_hold(tmp_path, capsys):
    """A 1e9 N m yaw moment on a buoy with no waterplane: the solver gives up with its residual, the
    body's last offset, and the case's fix (a load ramp)."""
    data = _data()
    data["bodies"]["buoy"].update(waterplane_area=0.0, waterplane_moments=[0.0, 0.0],
                                  external_force=[5.0e5, 0.0, 0.0, 0.0, 0.0, 1.0e9])
    path = _write(tmp_path, data)
    assert main(["validate", path]) == 0   # legal input: only solving finds it
    capsys.readouterr()
    assert main(["run", path, "--no-plots", "-o", str(tmp_path / "r.nc")]) == 2
    err = capsys.readouterr().err
    assert err.count("seacable: error:") == 1 and "Traceback" not in err
    assert "no equilibrium found" in err and "residual" in err and "last offsets buoy" in err
    assert "Suggested fix: ramp the bodies' external loads up in steps (analysis.load_steps: 10)" in err


def test_a_line_above_its_breaking_load_is_warned():
    data = _data()
    data["lines"]["line2"]["length"] = 500.0   # shorter than the 610 m between its ends: stretched 20 %
    case = parse_case(data)
    with pytest.warns(sc.SeacableWarning) as record:
        sc.run(case)
    # every line pulls taut (the buoy is drawn towards anchor2): each is named with its tension
    said = " ".join(str(w.message) for w in record)
    assert re.search(r"lines\.line2 carries 2\.\d+e\+07 N, above its breaking_load 7\.3e\+06 N", said), said
    # one warning per line over the run, not one more from each equilibrium solve (the solver's own, filtered)
    assert sum("line2" in str(w.message) for w in record) == 1, said


def test_a_line_that_cannot_reach_is_named_by_its_name():
    data = _data()
    data["lines"]["line1"]["length"] = 100.0   # 600 m across and 140 m up: a strain of 5
    with pytest.raises(sc.NoSolutionError) as err:
        sc.check(parse_case(data))
    said = str(err.value)
    # the name the file uses, not the solver's index into its vectorised sub-lines
    assert "lines.line1 cannot reach" in said and "line[" not in said, said


def _line_weight(case, name) -> float:
    """Weight in water per metre of a one-segment line: (m - rho pi d^2 / 4) g. [N/m]"""
    lt = case.lines[name].line.segments[0].line_type
    env = case.environment
    return (lt.mass_per_length - env.water_density * math.pi * lt.diameter ** 2 / 4) * env.gravity


@pytest.mark.parametrize("length", [650.0, 612.0])   # on the seabed at its anchor; lifting its anchor
def test_each_line_is_in_vertical_equilibrium(length):
    """The forces of a line on its two ends carry its suspended weight: V_A + F_Bz = -w (L - grounded).

    The seabed carries the grounded part (its friction acts horizontally only). 612 m over the 610 m
    between anchor and fairlead pulls every line off the seabed: then the anchor is lifted.
    """
    data = _data()
    for name in data["lines"]:
        data["lines"][name]["length"] = length
    case = parse_case(data)
    ds = sc.run(case)
    for name in case.lines:
        w = _line_weight(case, name)
        d = ds.sel(line=name)
        ok = d.line_present.values == 1
        lhs = (d.anchor_vertical_force + d.fairlead_force_z).values[ok]
        rhs = -w * (length - d.grounded_length.values[ok])
        # catenary closure to the solver's tolerance (1e-8 of the force scale); 1e-6 of the line's weight
        np.testing.assert_allclose(lhs, rhs, atol=1e-6 * w * length)
        # the fairlead angle below the horizontal: tan = (suspended weight + anchor uplift) / H
        h_b = np.hypot(d.fairlead_force_x, d.fairlead_force_y).values[ok]
        np.testing.assert_allclose(np.tan(d.fairlead_angle.values[ok]),
                                   (-rhs + d.anchor_vertical_force.values[ok]) / h_b, rtol=1e-6)
    i = ds.sel(condition="intact")
    if length < 615.0:
        assert np.all(i.grounded_length.values == 0)
        assert np.all(i.anchor_uplift_angle.values > 0.01)   # the anchors are pulled up, not only along
    else:
        assert np.all(i.grounded_length.values > 100.0)
        np.testing.assert_allclose(i.anchor_vertical_force.values, 0.0, atol=1e-6 * w * length)


def test_schema_of_system_cases(capsys):
    import json

    assert main(["schema", "--system"]) == 0
    schema = json.loads(capsys.readouterr().out)
    assert {"points", "bodies", "lines", "analysis"} <= set(schema["properties"])
    assert main(["schema"]) == 0
    assert "line" in json.loads(capsys.readouterr().out)["properties"]


def test_an_interrupted_watch_circle_keeps_the_equilibria_it_found(monkeypatch):
    from seacable.system import run as system_run

    case = sc.load_case(WATCH)
    case = case.replace(analysis=SystemOffsetsAnalysis(body="buoy", loads=(0.0, 1.0e3, 2.5e5, 5.0e5),
                                                       headings=(0.0, math.pi), damaged_lines=("line1",)))
    whole = sc.run(case)
    solve, calls = system_run._solve_path, []

    def interrupted_after_three(*args, **kwargs):
        calls.append(1)
        if len(calls) > 3:
            raise KeyboardInterrupt
        return solve(*args, **kwargs)

    monkeypatch.setattr(system_run, "_solve_path", interrupted_after_three)
    ds = sc.run(case)
    assert ds.attrs["interrupted"] == 1 and whole.attrs["interrupted"] == 0
    # three solves: the intact no-load state, then the first heading's 1 kN and 250 kN: the loads 0, 1 kN and
    # 250 kN at heading 0 are the uninterrupted run's exactly; every other case is NaN
    got = ds.offset.sel(condition="intact", heading=0.0).values
    np.testing.assert_array_equal(got[:3], whole.offset.sel(condition="intact", heading=0.0).values[:3])
    assert np.isnan(got[3:]).all()
    assert np.isnan(ds.offset.sel(condition="intact", heading=math.pi).values).all()
    assert np.isnan(ds.offset.sel(condition="damaged").values).all()


# ----------------------------------------------------------------------------- gravity or water switched off, no lines

def _two_line_case(gravity: float, water_density: float = 1025.0) -> dict:
    """A 1e4 kg body (5 m^3) at z = -50 between two anchors 100 m away along x, held by taut 98 m lines to fairleads
    1 m either side of its reference point (50 kg/m, EA 1e7 N); its centre of gravity 1 m below the reference."""
    return {
        "name": "taut", "line_types": {"rope": {"diameter": 0.1, "mass_per_length": 50.0, "axial_stiffness": 1.0e7}},
        "environment": {"water_density": water_density, "gravity": gravity, "depth": 200.0},
        "bodies": {"b": {"mass": 1.0e4, "volume": 5.0, "center_of_gravity": [0.0, 0.0, -1.0],
                         "inertia": [1.0e4, 1.0e4, 1.0e4], "position": [0.0, 0.0, -50.0, 0.0, 0.0, 0.0]}},
        "points": {"a1": {"kind": "fixed", "position": [-100.0, 0.0, -50.0]},
                   "a2": {"kind": "fixed", "position": [100.0, 0.0, -50.0]},
                   "f1": {"kind": "body", "body": "b", "position": [-1.0, 0.0, 0.0]},
                   "f2": {"kind": "body", "body": "b", "position": [1.0, 0.0, 0.0]}},
        "lines": {"l1": {"line_type": "rope", "length": 98.0, "end_a": "a1", "end_b": "f1"},
                  "l2": {"line_type": "rope", "length": 98.0, "end_a": "a2", "end_b": "f2"}},
        "analysis": {"type": "system_static"},
    }


def test_gravity_off_has_no_weight_effects():
    """gravity: 0 (a system environment may switch it off, as MoorDyn's g = 0): nothing weighs, so the body stays at
    z = -50 and the lines are straight, each carrying EA (99 / 98 - 1) at both ends. Closed form, 1e-9 relative
    (straight weightless lines are exact). With gravity the same system sags (the body's net weight 4.7e4 N)."""
    ds = sc.run(parse_case(_two_line_case(gravity=0.0)))
    expect = 1.0e7 * (99.0 / 98.0 - 1.0)
    assert np.allclose(ds["fairlead_tension"].sel(condition="intact").values, expect, rtol=1e-9)
    assert np.allclose(ds["anchor_tension"].sel(condition="intact").values, expect, rtol=1e-9)
    assert ds["body_z"].sel(condition="intact", body="b").item() == pytest.approx(-50.0, abs=1e-9)
    assert np.allclose(ds["z"].sel(condition="intact").values, -50.0, atol=1e-9)  # the profiles are straight
    heavy = sc.run(parse_case(_two_line_case(gravity=9.81)))
    assert heavy["body_z"].sel(condition="intact", body="b").item() < -50.5


def test_water_off_has_no_buoyancy():
    """water_density: 0 (MoorDyn's WtrDnsty = 0): the body hangs from one vertical line with no buoyancy on it
    nor on the line (its 5 m^3 and the rope's volume displace nothing): the top carries (M + m L) g, the bottom M g,
    and the body hangs L + (M g L + m g L^2 / 2) / EA below the top. Closed form of a vertical elastic line, 1e-9."""
    data = _two_line_case(gravity=9.81, water_density=0.0)
    data["points"] = {"top": {"kind": "fixed", "position": [0.0, 0.0, -10.0]},
                      "eye": {"kind": "body", "body": "b", "position": [0.0, 0.0, 0.0]}}
    data["lines"] = {"l1": {"line_type": "rope", "length": 30.0, "end_a": "eye", "end_b": "top"}}
    data["bodies"]["b"]["position"] = [0.0, 0.0, -40.0, 0.0, 0.0, 0.0]
    ds = sc.run(parse_case(data))
    g, M, m, L, ea = 9.81, 1.0e4, 50.0, 30.0, 1.0e7
    assert ds["fairlead_tension"].item() == pytest.approx((M + m * L) * g, rel=1e-9)
    assert ds["anchor_tension"].item() == pytest.approx(M * g, rel=1e-9)
    assert ds["body_z"].item() == pytest.approx(-10.0 - L - (M * g * L + m * g * L**2 / 2) / ea, rel=1e-9)


def test_only_system_environments_switch_gravity_or_water_off():
    """A single-line case keeps its checks (gravity and density > 0); a system environment takes 0, but not waves
    without gravity."""
    from seacable.environment import Environment, SystemEnvironment

    with pytest.raises(sc.InputError, match=r"gravity must be > 0"):
        Environment.parse({"gravity": 0.0})
    assert SystemEnvironment.parse({"gravity": 0.0, "water_density": 0.0}).gravity == 0.0
    with pytest.raises(sc.InputError, match=r"waves need gravity"):
        SystemEnvironment.parse({"gravity": 0.0, "waves": {"height": 1.0, "period": 8.0}})


def _no_line_case(analysis: dict) -> dict:
    """A 1 m pinned rod (10 kg, 0.0491 m^3, RodPinnedFloating of MoorDyn's tests), lying at z = -5: no lines."""
    return {"name": "rod", "environment": {"depth": 10.0},
            "bodies": {"rod": {"pinned": True, "mass": 10.0, "volume": 0.0490874, "center_of_gravity": [0, 0, 0.5],
                               "center_of_buoyancy": [0, 0, 0.5], "inertia": [0.8724, 0.8724, 0.0781],
                               "position": [0.0, 0.0, -5.0, 0.0, math.pi / 2, 0.0]}},
            "analysis": analysis}


def test_a_system_without_lines_has_an_empty_line_dimension_that_writes_and_plots(tmp_path):
    """A system of bodies alone (MoorDyn runs rods without lines): the pinned buoyant rod turns upright (pitch 0)
    and its pin holds its net buoyancy, (rho V - m) g = 395.35 N (closed form, 1e-9); the result has an empty
    ``line`` dimension, is valid NetCDF and plots; so does a run in time (system_dynamic)."""
    from seacable.plot.system import plot_system_dynamic, plot_system_static

    ds = sc.run(parse_case(_no_line_case({"type": "system_static"})))
    assert ds.sizes["line"] == 0
    assert abs(ds["body_pitch"].item()) < 1e-7
    assert ds["pin_reaction_z"].item() == pytest.approx(-(1025.0 * 0.0490874 - 10.0) * 9.81, rel=1e-9)
    ds.to_netcdf(tmp_path / "rod.nc")
    with open_netcdf(tmp_path / "rod.nc") as back:
        assert back.sizes["line"] == 0 and back["body_pitch"].item() == pytest.approx(ds["body_pitch"].item())
    assert plot_system_static(ds)
    # in time the same rod, free (the dynamics hold no pin): released level, it rises
    data = _no_line_case({"type": "system_dynamic", "duration": 0.2, "time_step": 0.01, "output_interval": 0.1,
                          "start": "held"})
    data["bodies"]["rod"]["pinned"] = False
    dyn = sc.run(parse_case(data))
    z = dyn.body_position.sel(body="rod", axis="z").values
    assert dyn.sizes["line"] == 0 and np.all(np.isfinite(z)) and z[-1] > z[0]
    dyn.to_netcdf(tmp_path / "rod_dyn.nc")
    assert plot_system_dynamic(dyn)


def test_a_free_body_without_lines_held_by_its_hydrostatic_matrix_has_an_equilibrium():
    """A free body no line ends on with a 6x6 hydrostatic matrix restoring every direction (a user's model of a
    moored or dynamically positioned hull) has an equilibrium: under a horizontal load F it moves F / K11, and its
    net buoyancy (rho V - m) g lifts it by that over K33. Closed form of a linear spring, 1e-9."""
    k = [2.0e5, 3.0e5, 4.0e6, 1.0e9, 1.0e9, 5.0e8]
    data = {"name": "dp", "environment": {"depth": 100.0},
            "bodies": {"hull": {"mass": 1.0e6, "volume": 1000.0, "inertia": [1e9, 1e9, 1e9],
                                "hydrostatic_stiffness": [[k[i] if i == j else 0.0 for j in range(6)]
                                                          for i in range(6)],
                                "external_force": [1.0e5, 0.0, 0.0, 0.0, 0.0, 0.0]}},
            "analysis": {"type": "system_static"}}
    ds = sc.run(parse_case(data))
    assert ds.sizes["line"] == 0
    assert ds["body_x"].item() == pytest.approx(1.0e5 / k[0], rel=1e-9)
    assert ds["body_z"].item() == pytest.approx((1025.0 * 1000.0 - 1.0e6) * 9.81 / k[2], rel=1e-9)


# --- damaged_lines: most_loaded (issue 37) ---------------------------------------------------------

def _spread_loaded_towards(heading: float, damaged="most_loaded") -> SystemCase:
    """spread_mooring.yaml with its 500 kN load turned to ``heading`` [rad]."""
    data = _data()
    data["bodies"]["buoy"]["external_force"] = [LOAD * math.cos(heading), LOAD * math.sin(heading), 0, 0, 0, 0]
    data["analysis"]["damaged_lines"] = damaged
    return parse_case(data)


def test_most_loaded_removes_the_line_of_the_largest_intact_tension_and_the_body_drifts_further():
    """ALS is the system after the failure of its most loaded line. With the 500 kN load turned to 240 deg, away
    from line2's anchor (at 60 deg), line2 holds the most in the intact equilibrium (921 kN against 427 kN for
    the two others), so 'most_loaded' removes line2, not the first line; without it the buoy drifts further
    (622 m against 17 m). Removing the least loaded line instead (line1 or line3) would move the buoy less far
    than removing line2: the check below compares with both."""
    ds = sc.run(_spread_loaded_towards(math.radians(240.0)))
    intact = ds.fairlead_tension.sel(condition="intact")
    assert str(intact.idxmax("line").values) == "line2"
    assert float(intact.sel(line="line2")) > 2.0 * float(intact.sel(line="line1"))  # clearly the most loaded
    assert ds.line_present.sel(condition="damaged").values.tolist() == [1, 0, 1]
    assert json.loads(ds.attrs["settings"])["damaged_lines"] == ["line2"]
    off = ds.body_offset.sel(body="buoy")
    assert float(off.sel(condition="damaged")) > 10.0 * float(off.sel(condition="intact"))
    # the same case with line2 named gives the same damaged equilibrium; with the least loaded line removed
    # the buoy moves less than with line2 removed
    named = sc.run(_spread_loaded_towards(math.radians(240.0), ["line2"]))
    np.testing.assert_allclose(named.body_x.values, ds.body_x.values, rtol=1e-12)
    least = sc.run(_spread_loaded_towards(math.radians(240.0), ["line1"]))
    assert float(least.body_offset.sel(condition="damaged", body="buoy")) < float(off.sel(condition="damaged"))


def test_most_loaded_in_a_watch_circle_is_chosen_heading_by_heading():
    """The watch circle's damaged condition removes at each heading the line most loaded by that heading's
    largest load: a load towards 0, 120 and 240 deg pulls away from the anchors of line1 (180 deg), line3 (300
    deg) and line2 (60 deg). Each heading's damaged offset along the load exceeds the intact one."""
    case = sc.load_case(WATCH)
    case = case.replace(analysis=SystemOffsetsAnalysis(body="buoy", loads=(0.0, 5.0e5), damaged_lines="most_loaded",
                                                       headings=(0.0, 2 * math.pi / 3, 4 * math.pi / 3)))
    ds = sc.run(case)
    assert ds.damaged_line.values.tolist() == ["line1", "line3", "line2"]
    assert ds.line_present.dims == ("condition", "heading", "line")
    assert ds.line_present.sel(condition="damaged").values.tolist() == [[0, 1, 1], [1, 1, 0], [1, 0, 1]]
    at = ds.sel(applied_load=5.0e5)
    for h in ds.heading.values:
        t = at.fairlead_tension.sel(condition="intact", heading=h)
        assert str(t.idxmax("line").values) == str(ds.damaged_line.sel(heading=h).values)
        assert float(at.offset.sel(condition="damaged", heading=h)) > float(at.offset.sel(condition="intact",
                                                                                          heading=h))


def test_most_loaded_ties_go_to_the_first_line_and_the_word_is_checked():
    """Under a load along +x the spread is symmetric about the x axis: turned to 180 deg (towards line1's anchor),
    line2 and line3 carry the same tension to the solver's tolerance: the first of them, line2, is taken."""
    from seacable.system.damaged import most_loaded_line

    ds = sc.run(_spread_loaded_towards(math.pi))
    t = ds.fairlead_tension.sel(condition="intact")
    assert float(t.sel(line="line2")) == pytest.approx(float(t.sel(line="line3")), rel=1e-6)
    assert json.loads(ds.attrs["settings"])["damaged_lines"] == ["line2"]
    assert most_loaded_line(("a", "b", "c"), [1.0, 2.0, 2.0 * (1 + 1e-7)]) == "b"  # within 1e-6: a tie
    assert most_loaded_line(("a", "b", "c"), [1.0, 2.0, 2.0 * (1 + 1e-5)]) == "c"
    with pytest.raises(sc.CaseFileError, match="damaged_lines"):
        _spread_loaded_towards(0.0, "most_loded")


def test_most_loaded_of_a_design_run_is_a_weather_line_and_the_spar_drifts_further():
    """The OC3-Hywind design runs (oc3_hywind_storm.yaml, 600 kN along +x): line1 is the lee line (606 kN at the
    mean position, against 1178 kN for each weather line), lines 2 and 3 tie by symmetry, so 'most_loaded'
    removes line2 (the first of the tie). Its mean position is the damaged static equilibrium: the spar drifts
    762 m (420.7 m in x, -635.4 m in y) against 20.2 m intact; removing the lee line instead (the demo's old
    choice) moved it back, to 7.8 m. The result records the removed line, which the design tables read."""
    from seacable.design import summary
    from seacable.system.dynamics import most_loaded_at_start

    case = sc.load_case(EXAMPLES / "oc3_hywind_storm.yaml")
    runs = {}
    for damaged in ((), "most_loaded"):
        c = case.replace(analysis=case.analysis.model_copy(update={"duration": 1.0, "damaged_lines": damaged}))
        runs[damaged] = sc.run(c)
    assert most_loaded_at_start(c) == "line2"
    ds = runs["most_loaded"]
    assert ds.line.values.tolist() == ["line1", "line3"]
    assert json.loads(ds.attrs["settings"])["damaged_lines"] == ["line2"]
    assert summary.failed_lines(ds) == {"line2": 0.0}
    assert summary.failed_lines(runs[()]) == {}
    start = {k: np.hypot(*v.body_position.isel(time=0, body=0).values[:2]) for k, v in runs.items()}
    # the static equilibria solved alone gave 20.24 m and 762.0 m; the run starts there (1e-3 m)
    assert start[()] == pytest.approx(20.24, abs=0.01) and start["most_loaded"] == pytest.approx(762.0, abs=0.1)

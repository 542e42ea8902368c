"""The ``system_dynamic`` analysis as a case (issue 18): YAML and MoorDyn decks, the API and the command line.

A small system keeps the runs short: a surface buoy (20 t, 40 m^3) on three 110 m chains in 50 m of
water, 10 elements a line. Physics asserted: a run from rest stays at its static start; the start is
the exact elastic catenary's equilibrium (:func:`seacable.system.statics.solve_equilibrium`) to the
finite elements' second-order discretisation error; a constant external force read from a CSV beside
the case file moves the buoy to the static offset under that load; a failed line end goes slack and the
failure time is recorded; MoorDyn decks with bodies run as ``system_static`` (the same tensions as the
system statics of the deck) and with a duration as ``system_dynamic``, their FAILURE rows mapped.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import matplotlib
import numpy as np
import pytest
import yaml

matplotlib.use("Agg")

import seacable as sc  # noqa: E402
from seacable.cli import main  # noqa: E402
from seacable.errors import InputError  # noqa: E402
from seacable.io.moordyn import load_moordyn_case, moordyn_system, read_moordyn  # noqa: E402
from seacable.mooring.outputs import line_end_forces  # noqa: E402
from seacable.results import body_pose, open_netcdf  # noqa: E402
from seacable.system.dynamics import LineFailure, build_system_fe, static_system  # noqa: E402
from seacable.system.statics import solve_equilibrium  # noqa: E402

DECKS = Path(__file__).resolve().parents[1] / "validation" / "data" / "moordyn_decks"
BODY_DECK = DECKS / "MoorDyn" / "example" / "body.txt"
FAIL_DECK = DECKS / "r-test" / "modules" / "moordyn" / "md_lineFail" / "moordyn.dat"

#: chain: 60 kg/m, d = 0.1 m: submerged weight per unstretched length [N/m]
W0 = 60.0 * 9.81 - 1025.0 * 9.81 * math.pi * 0.05 ** 2


def _case(**analysis) -> dict:
    """A buoy on three 110 m chains in 50 m of water (anchors 100 m from the centre, 120 deg apart)."""
    diag = lambda *v: [[v[i] if i == j else 0.0 for j in range(6)] for i in range(6)]  # noqa: E731
    return {
        "name": "buoy3",
        "line_types": {"chain": {"diameter": 0.1, "mass_per_length": 60.0, "axial_stiffness": 5.0e8}},
        "environment": {"water_density": 1025.0, "gravity": 9.81, "depth": 50.0},
        "bodies": {"buoy": {
            "position": [0.0] * 6, "mass": 2.0e4, "center_of_gravity": [0.0, 0.0, -1.0],
            "inertia": [5.0e4, 5.0e4, 5.0e4], "volume": 40.0, "center_of_buoyancy": [0.0, 0.0, -1.0],
            "waterplane_area": 12.0, "waterplane_moments": [40.0, 40.0],
            "added_mass": diag(2.0e4, 2.0e4, 1.0e4, 0.0, 0.0, 0.0),
            "linear_damping": diag(2.0e4, 2.0e4, 2.0e4, 1.0e5, 1.0e5, 1.0e5)}},
        "points": {
            "anchor1": {"kind": "fixed", "position": [-100.0, 0.0, -50.0]},
            "anchor2": {"kind": "fixed", "position": [50.0, 86.6025, -50.0]},
            "anchor3": {"kind": "fixed", "position": [50.0, -86.6025, -50.0]},
            "fairlead1": {"kind": "body", "body": "buoy", "position": [-2.0, 0.0, -2.0]},
            "fairlead2": {"kind": "body", "body": "buoy", "position": [1.0, 1.732, -2.0]},
            "fairlead3": {"kind": "body", "body": "buoy", "position": [1.0, -1.732, -2.0]}},
        "lines": {f"line{i}": {"line_type": "chain", "length": 110.0, "end_a": f"anchor{i}", "end_b": f"fairlead{i}"}
                  for i in (1, 2, 3)},
        "analysis": {"type": "system_dynamic", "duration": 5.0, "time_step": 0.1, "output_interval": 0.5,
                     "n_elements": 10, **analysis},
    }


def _write(path: Path, data: dict) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    return path


def _fairlead_point_tension(tension_end_element, z_fairlead, z_next):
    """The tension AT the fairlead from the end element's (mid-element) tension: along a catenary the
    effective tension changes by the submerged weight times the rise, dT = w0 dz (exact)."""
    return tension_end_element + W0 * (z_fairlead - 0.5 * (z_fairlead + z_next))


@pytest.fixture(scope="module")
def rest(tmp_path_factory):
    """The small case run from rest via load_case + run (5 s)."""
    path = _write(tmp_path_factory.mktemp("rest") / "buoy3.yaml", _case())
    case = sc.load_case(path)
    return path, case, sc.run(case)


def test_run_from_rest_stays_at_the_static_start(rest):
    _, _, ds = rest
    assert ds.attrs["analysis"] == "system_dynamic"
    bp = body_pose(ds.sel(body="buoy"))
    ten = ds.fairlead_tension.values
    # The run starts at the static equilibrium of the same FE system and nothing loads it: the only
    # change is the Newton residual of each step (1e-7 relative on forces of ~1e5 N -> ~1e-2 N, on
    # stiffnesses of ~1e5 N/m -> ~1e-7 m). Bounds: 1e-6 m, 1e-6 rad and 1e-6 relative tension, 10x that.
    assert np.max(np.abs(bp[:, :3] - bp[0, :3])) < 1e-6
    assert np.max(np.abs(bp[:, 3:] - bp[0, 3:])) < 1e-6
    assert np.max(np.abs(ten / ten[0] - 1.0)) < 1e-6
    assert np.all(np.isnan(ds.failure_time.values))
    # symmetric system: lines 2 and 3 carry the same tension (mirror images about y = 0)
    assert ten[0, 1] == pytest.approx(ten[0, 2], rel=1e-9)


def test_start_is_the_catenary_equilibrium_to_second_order(rest):
    """The FE start (10 elements a line) against the exact elastic catenary: heave and fairlead tension
    differ by the discretisation error, which falls by 4 per halving of the element length."""
    _, case, ds = rest
    eq = solve_equilibrium(case.system(), case.environment)
    z0 = ds.body_position.sel(body="buoy", axis="z").values[0]
    # measured 4.64e-3 m at 10 elements (4.6e-3 = the FE sag error of 11 m elements); 6e-3 bounds it
    assert abs(z0 - eq.body_position[0, 2]) < 6e-3
    assert abs(ds.body_position.sel(body="buoy", axis="x").values[0] - eq.body_position[0, 0]) < 1e-6  # symmetric
    # the fairlead tension is the line's end force (its end element and half element, as a single line's): the
    # catenary's at the fairlead to the discretisation error
    t_fair = ds.fairlead_tension.values[0]
    np.testing.assert_allclose(t_fair, eq.end_b_tension, rtol=5e-3)  # measured 3.5e-3 at 10 elements
    # second order: the same statics at 10, 20 and 40 elements; the errors' ratios are 4 (+-5 %), for the end
    # force as the run reports it (seacable.mooring.outputs.line_end_forces) and for the end element's tension
    # carried to the fairlead by the catenary's dT = w dz
    errs_z, errs_t, errs_f = [], [], []
    for n in (10, 20, 40):
        fe = build_system_fe(case.system(), case.environment, case.analysis.model_copy(update={"n_elements": n}))
        st = static_system(fe, tol=1e-10)
        errs_z.append(st.body_position[0, 2] - eq.body_position[0, 2])
        t = [_fairlead_point_tension(st.tension[els[-1]], st.position[nodes[-1], 2], st.position[nodes[-2], 2])
             for nodes, els in zip(fe.line_nodes, fe.line_elements)]
        errs_t.append(np.array(t) / eq.end_b_tension - 1.0)
        f = [np.linalg.norm(line_end_forces(fe.model, st.position, line=j)[1]) for j in range(len(fe.line_names))]
        errs_f.append(np.array(f) / eq.end_b_tension - 1.0)
        if n == 10:
            np.testing.assert_allclose(f, t_fair, rtol=1e-6)  # the run's start is that statics (1e-6: at rest)
    assert errs_z[0] == pytest.approx(z0 - eq.body_position[0, 2], abs=1e-6)  # the run's start is that statics
    for a, b in zip(errs_f, errs_f[1:]):
        np.testing.assert_allclose(a / b, 4.0, rtol=0.05)
    for a, b in zip(errs_z, errs_z[1:]):
        assert a / b == pytest.approx(4.0, rel=0.05)
    for a, b in zip(errs_t, errs_t[1:]):
        np.testing.assert_allclose(a / b, 4.0, rtol=0.05)


def test_cli_validate_run_plot_and_netcdf_round_trip(rest, tmp_path, capsys):
    path, _, ds = rest
    assert main(["validate", str(path)]) == 0
    assert "system_dynamic" in capsys.readouterr().out
    out = tmp_path / "out" / "buoy3.nc"
    assert main(["run", str(path), "-o", str(out), "--no-plots"]) == 0
    with open_netcdf(out) as back:
        assert back.attrs["analysis"] == "system_dynamic"
        # the same deterministic run: bit-for-bit up to NetCDF's float64 storage
        np.testing.assert_array_equal(back.fairlead_tension.values, ds.fairlead_tension.values)
        np.testing.assert_array_equal(body_pose(back), body_pose(ds))
        assert list(back.line.values) == ["line1", "line2", "line3"]
        for name in list(back.data_vars) + list(back.coords):
            assert {"units", "long_name"} <= set(back[name].attrs), name
    capsys.readouterr()
    assert main(["plot", str(out), "-o", str(tmp_path / "figs")]) == 0
    assert len(list((tmp_path / "figs").glob("*.png"))) == 3
    import matplotlib.pyplot as plt

    from seacable.plot.system import plot_system_dynamic

    figs = plot_system_dynamic(ds)
    assert len(figs) == 3
    plt.close("all")


def test_external_force_csv_beside_the_case_moves_the_buoy_to_the_static_offset(tmp_path, monkeypatch):
    """A force ramped over 10 s to 20 kN (surge) from a CSV next to the case file, read while the working
    directory is elsewhere; with critical surge damping the buoy settles on the static offset."""
    base = _case()
    case0 = sc.load_case(_write(tmp_path / "probe.yaml", base))
    eq0 = solve_equilibrium(case0.system(), case0.environment)
    force = 2.0e4
    eqf = solve_equilibrium(case0.system(), case0.environment, external={"buoy": (force, 0, 0, 0, 0, 0)})
    k11, mass = eq0.stiffness[0, 0], 2.0e4 + 2.0e4  # surge: mooring stiffness, mass + added mass
    data = _case(duration=60.0, time_step=0.2, output_interval=1.0,
                 external_forces={"buoy": {"file": "loads/force.csv"}})
    critical = 2.0 * math.sqrt(k11 * mass)  # surge period 2 pi sqrt(M/K) = 4.8 s; settles in a few periods
    data["bodies"]["buoy"]["linear_damping"][0][0] = critical
    folder = tmp_path / "cases"
    (folder / "loads").mkdir(parents=True)
    (folder / "loads" / "force.csv").write_text(f"time,fx\n0,0\n10,{force}\n60,{force}\n", encoding="utf-8")
    path = _write(folder / "pull.yaml", data)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    ds = sc.run(sc.load_case(path))
    bp = body_pose(ds.sel(body="buoy"))
    offset = bp[ds.time.values >= 50.0, :3].mean(axis=0) - bp[0, :3]
    static = eqf.body_position[0, :3] - eq0.body_position[0, :3]  # (0.2856, 0, -0.0111) m
    # Surge: the FE lines' stiffness carries their discretisation error (0.35 % in tension at 10
    # elements, test above), the last 10 s a residual of the transient (< 2e-4 m): 0.5 %.
    assert offset[0] == pytest.approx(static[0], rel=5e-3)
    assert abs(offset[1]) < 1e-9
    assert offset[2] == pytest.approx(static[2], abs=5e-4)  # heave set-down 11 mm: 0.5 mm (5 %)
    # without the force file the case fails to load (proves the file was read, not ignored)
    (folder / "loads" / "force.csv").unlink()
    with pytest.raises(InputError, match="force.csv"):
        sc.run(sc.load_case(path))


def test_failure_at_a_time_is_recorded_and_the_end_goes_slack(tmp_path):
    data = _case(duration=3.0, time_step=0.05, output_interval=0.05,
                 failures=[{"line": "line1", "end": "b", "time": 1.0}])
    ds = sc.run(sc.load_case(_write(tmp_path / "break.yaml", data)))
    ft = ds.failure_time.values
    assert ft[0] == pytest.approx(1.0, abs=1e-12) and np.all(np.isnan(ft[1:]))
    t = ds.time.values
    ten = ds.fairlead_tension.values
    # intact up to the failure (the static tension, 1e-6 as in the rest test)
    np.testing.assert_allclose(ten[t <= 1.0 + 1e-9, 0], ten[0, 0], rtol=1e-6)
    # A free end carries no force: the line's force on its released end node is that node's equation of
    # motion's residual (F - M a), which Newton leaves below its tolerance, and its end element goes slack within
    # one axial transit of the 11 m element (11 / sqrt(EA/m) = 4 ms): from 0.1 s after the failure on, the end
    # element is slack (0, trusses take no compression) and the end force is the residual
    assert np.all(ds.segment_tension.values[t >= 1.1 - 1e-9, 0, -1] == 0.0)
    assert np.all(ten[t >= 1.1 - 1e-9, 0] < 1e-6 * ten[0, 0]), ten[t >= 1.1 - 1e-9, 0].max() / ten[0, 0]
    # the other lines take the buoy's load: their tension rises above the intact value in the transient
    assert ten[t > 1.0, 1].max() > 1.05 * ten[0, 1]


# --- MoorDyn decks with structures ------------------------------------------------------------------


def test_moordyn_deck_with_a_body_validates_and_runs_as_system_static(tmp_path, capsys):
    assert main(["validate", str(BODY_DECK)]) == 0
    assert "system_static" in capsys.readouterr().out
    out = tmp_path / "body.nc"
    assert main(["run", str(BODY_DECK), "-o", str(out), "--no-plots"]) == 0
    system, environment = moordyn_system(read_moordyn(BODY_DECK))
    eq = solve_equilibrium(system, environment)
    with open_netcdf(out) as ds:
        assert ds.attrs["analysis"] == "system_static"
        # the same statics: the run is moordyn_system + solve_equilibrium (all line ends B on the body)
        np.testing.assert_allclose(ds.fairlead_tension.values.ravel(), eq.end_b_tension, rtol=1e-9)
    # OC3-Hywind (Jonkman 2010): a 902.2 m chain from 320 m depth to a fairlead 70 m down: ~0.9 MN
    assert 8.0e5 < eq.end_b_tension.min() < 1.0e6


def test_moordyn_deck_with_a_body_and_a_duration_runs_system_dynamic(tmp_path, capsys):
    out = tmp_path / "body_dyn.nc"
    assert main(["run", str(BODY_DECK), "-o", str(out), "--no-plots", "--duration", "1", "--time-step", "0.1",
                 "--output-interval", "0.5"]) == 0
    with open_netcdf(out) as ds:
        assert ds.attrs["analysis"] == "system_dynamic"
        np.testing.assert_allclose(ds.time.values, [0.0, 0.5, 1.0])
        ten = ds.fairlead_tension.values
        # the coupled body is held: the lines stay at their FE start (Newton residual 1e-7; 1e-6)
        np.testing.assert_allclose(ten, np.broadcast_to(ten[0], ten.shape), rtol=1e-6)
    eq = solve_equilibrium(*moordyn_system(read_moordyn(BODY_DECK)))
    # end element of 45 m (20 segments) vs the catenary's end value: w0 dz over half an element,
    # about 1.1 %; 2 % bounds it
    np.testing.assert_allclose(ten[0], eq.end_b_tension, rtol=2e-2)


def test_moordyn_failure_rows_map_to_line_failures():
    case = load_moordyn_case(FAIL_DECK)
    assert case.has_structures and case.analysis_type == "system_static"
    assert case.system_case().analysis.type == "system_static"
    failures = case.with_run(duration=20.0).system_case().analysis.failures
    # FailureID Node Line(s) FailTime FailTen: 1 R1a 2 15 0 | 2 2 1 11 0 | 3 R1A 3 10 1e5 | 4 R1B 4 5 0
    assert failures == [LineFailure(line="line2", end="b", time=15.0),
                        LineFailure(line="line1", end="b", time=11.0),
                        LineFailure(line="line3", end="b", time=10.0, tension=1.0e5),
                        LineFailure(line="line4", end="a", time=5.0)]


_DECK = """MoorDyn input file
a buoy body on one chain
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI   Cd   Ca   CdAx  CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (-)  (-)  (-)  (-)   (-)
main       0.09    77.7066    384.243E6  -0.8        0    1.6  1.0  0.1   0.0
----------------------- BODIES ------------------------------------------------------
ID   Attachment  X0   Y0   Z0   r0    p0    y0   Mass  CG*   I*     Volume  CdA*   Ca*
(#)     (-)      (m)  (m)  (m) (deg) (deg) (deg) (kg)  (m) (kg-m^2) (m^3)   (m^2)  (-)
1    Coupled      0    0    0    0     0     0     0    0     0       0       0     0
---------------------- POINTS --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     853.87  0       -320.0  0      0       0      0
2     Body1     5.2     0.0     -70.0   0      0       0      0
3     Fixed     -853.87 0       -320.0  0      0       0      0
4     Body1     -5.2    0.0     -70.0   0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     main       1        2         902.2     10      -
2     main       3        4         902.2     10      -
---------------------- FAILURE ----------------------
FailureID    Node    Line(s)   FailTime   FailTen
()           ()       (,)      (s or 0)   (N or 0)
1            {node}        {line}          {time}          0
---------------------- OPTIONS -----------------------------------------
320           WtrDpth
------------------------- need this line --------------------------------------
"""


def test_moordyn_failure_of_a_line_not_at_its_point_is_refused(tmp_path):
    deck = tmp_path / "bad_fail.txt"
    deck.write_text(_DECK.format(node=4, line=1, time=5), encoding="utf-8")  # line 1 ends at points 1 and 2
    with pytest.raises(InputError, match=r"line 1 is not attached to 4.*Suggested fix"):
        load_moordyn_case(deck)


def test_moordyn_failure_with_both_triggers_zero_breaks_at_the_start(tmp_path):
    """MoorDyn-F: FailTime 0 and FailTen 0 break the line at the start (a LineFailure at t = 0)."""
    deck = tmp_path / "fail0.txt"
    deck.write_text(_DECK.format(node=2, line=1, time=0), encoding="utf-8")
    failures = load_moordyn_case(deck).with_run(duration=1.0).system_case().analysis.failures
    assert failures == [LineFailure(line="line1", end="b", time=0.0)]


def test_vessel_motion_of_offsets_for_a_deck_with_a_coupled_body_is_refused(tmp_path, capsys):
    """A coupled body moves in six degrees of freedom: offsets x, y, z are refused, before the run, naming the body
    and the CSV header that works."""
    from seacable.mooring.motion import motion_from_csv

    motion_csv = tmp_path / "m.csv"
    motion_csv.write_text("time,x,y,z\n0,0,0,0\n10,1,0,0\n", encoding="utf-8")
    case = load_moordyn_case(BODY_DECK).with_run(duration=10.0, motion=motion_from_csv(motion_csv))
    with pytest.raises(InputError, match=r"coupled bodies \(body1\).*Suggested fix.*surge, sway, heave, roll"):
        case.system_case()
    assert main(["run", str(BODY_DECK), "--duration", "10", "--motion", str(motion_csv), "--no-plots",
                 "-o", str(tmp_path / "x.nc")]) == 2
    err = capsys.readouterr().err
    assert err.count("seacable: error:") == 1 and "six degrees of freedom" in err and "Traceback" not in err
    assert not (tmp_path / "x.nc").exists()


def test_vessel_motion_for_a_deck_with_nothing_coupled_is_refused(tmp_path):
    """The body made Free: no coupled point, body or rod for the motion to move; refused before the run."""
    from seacable.mooring.motion import PlatformMotion

    free = tmp_path / "free_body.txt"
    free.write_text(BODY_DECK.read_text().replace("1    Coupled      0    0  -70", "1    Free         0    0  -70"),
                    encoding="utf-8")
    motion = PlatformMotion(amplitude=(1.0, 0.0, 0.0, 0.0, 0.0, 0.0), period=10.0)
    case = load_moordyn_case(free).with_run(duration=1.0, motion=motion)
    with pytest.raises(InputError, match=r"no coupled point, body or rod for it to move.*Suggested fix"):
        case.system_case()


def _static_fairlead_tensions(deck) -> np.ndarray:
    """The fairlead tensions of a deck's system statics on its NumSegs lumped-mass lines (the dynamics' lines)."""
    case = load_moordyn_case(deck).system_case()
    case = case.model_copy(update={"analysis": case.analysis.model_copy(update={"statics": "finite_element"})})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sc.SeacableWarning)
        return sc.run(case).fairlead_tension.values[0]


def test_vessel_motion_for_a_deck_with_a_coupled_body_moves_the_body(tmp_path):
    """``seacable run body.txt --motion platform.csv``: the coupled body follows the six motions (surge 2 m, a
    cosine ramp over 20 s, then held) and the lines settle where the statics of the deck with the body 2 m over put
    them (the body row written at X0 = 2 m)."""
    t = np.arange(0.0, 61.0)
    surge = np.where(t < 20.0, 1.0 - np.cos(np.pi * t / 20.0), 2.0)
    motion_csv = tmp_path / "platform.csv"
    motion_csv.write_text("time,surge,sway,heave,roll,pitch,yaw\n"
                          + "".join(f"{a:g},{b:.17g},0,0,0,0,0\n" for a, b in zip(t, surge)), encoding="utf-8")
    out = tmp_path / "body.nc"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sc.SeacableWarning)
        assert main(["run", str(BODY_DECK), "--duration", "40", "--motion", str(motion_csv), "--time-step", "0.2",
                     "--output-interval", "1", "--no-plots", "-q", "-o", str(out)]) == 0
    ds = sc.read_netcdf(out)
    # the body's reference point is the motion, to the spline's exactness at its knots
    np.testing.assert_allclose(ds.body_position.sel(time=[0.0, 10.0, 30.0], body="body1").values[:, 0],
                               [0.0, 1.0, 2.0], atol=1e-9)
    moved = tmp_path / "body_moved.txt"
    moved.write_text(BODY_DECK.read_text().replace("1    Coupled      0    0  -70", "1    Coupled      2    0  -70"),
                     encoding="utf-8")
    static = _static_fairlead_tensions(moved)
    assert abs(static[0] - _static_fairlead_tensions(BODY_DECK)[0]) > 0.05 * static[0]  # the offset matters: 5 %
    # the last 10 s (20 s after the ramp) still ring by +-0.2 % (the lines' axial modes, BA -0.8); their mean lies
    # 0.02 % from the statics (measured): 0.1 % leaves room and is 50 times below the effect of the offset
    settled = ds.fairlead_tension.sel(time=slice(31.0, 40.0)).mean("time").values
    np.testing.assert_allclose(settled, static, rtol=1e-3)


def test_system_dynamic_bad_inputs_through_the_cli(tmp_path, capsys):
    """Unknown body in body_motions / external_forces, an unknown failed line, output_interval > duration:
    exit 2, one message naming the key, no traceback (more in test_bad_inputs.py's corpus)."""
    zeros = {"times": [0.0, 10.0], "values": [[0.0] * 6, [0.0] * 6]}
    cases = {
        "motion": ({"body_motions": {"bouy": {"amplitude": [1.0, 0, 0, 0, 0, 0], "period": 10.0}}},
                   ["analysis.body_motions", "bouy", "Did you mean 'buoy'"]),
        "force": ({"external_forces": {"bouy": zeros}}, ["analysis.external_forces", "bouy"]),
        "failure": ({"failures": [{"line": "line9", "end": "a", "time": 1.0}]}, ["failures[0].line", "line9"]),
        "interval": ({"output_interval": 6.0}, ["output_interval", "6 s", "duration"]),
    }
    for name, (extra, words) in cases.items():
        path = _write(tmp_path / f"{name}.yaml", _case(**extra))
        for argv in (["validate", str(path)], ["run", str(path), "--no-plots", "-o", str(tmp_path / f"{name}.nc")]):
            assert main(argv) == 2, (name, argv)
            err = capsys.readouterr().err
            assert err.count("seacable: error:") == 1 and "Traceback" not in err, err
            for word in words:
                assert word in err, (name, word, err)

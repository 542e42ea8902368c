"""Unit tests of the mooring model: motions, network, errors, MoorDyn networks, CLI, interruption."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import seacable as sc
from seacable.cli import main
from seacable.mooring.motion import HarmonicMotion, PlatformMotion, TimeSeriesMotion
from seacable.mooring.network import element_damping, network_from_line
from seacable.mooring.solver import MooringModel, Water, simulate, static_equilibrium
from seacable.results import open_netcdf

EXAMPLES = Path(__file__).parents[2] / "examples"
CHAIN = sc.LineType(diameter=0.09, mass_per_length=77.7066, weight_in_water=698.094, axial_stiffness=384.243e6)


def _fd(fn, t, h=1e-4):
    return (fn(t + h) - fn(t - h)) / (2 * h)


def test_harmonic_motion_derivatives_and_ramp():
    m = HarmonicMotion(amplitude=(2.0, 0.0, 1.0), period=7.0, phase=0.3, ramp=5.0)
    base = np.array([[10.0, 0.0, -5.0]])
    t = np.array([0.0, 1.3, 4.9, 6.0, 12.0])
    x, v, a = m.channels(t, base)
    inner = t > 0  # at t = 0 the ramp's second derivative jumps; the start is checked below
    # central differences, h = 1e-4 s: error h^2 x'''/6 ~ 1e-9
    assert v[inner] == pytest.approx(_fd(lambda s: m.channels(s, base)[0], t)[inner], abs=1e-6)
    assert a[inner] == pytest.approx(_fd(lambda s: m.channels(s, base)[1], t)[inner], abs=1e-6)
    # starts at rest at the base position
    assert x[0] == pytest.approx(base) and np.all(v[0] == 0)
    # after the ramp, the plain harmonic
    assert x[-1, 0, 0] == pytest.approx(10.0 + 2.0 * math.sin(2 * math.pi * 12.0 / 7.0 + 0.3), abs=1e-12)


def test_platform_yaw_moves_fairleads_on_circles():
    arm = np.array([[30.0, 0.0, -10.0], [-15.0, 25.98, -10.0]])
    m = PlatformMotion(amplitude=(0, 0, 0, 0, 0, 0.2), period=20.0)
    x, v, a = m.channels(np.linspace(0, 20, 9), arm)
    r0 = np.linalg.norm(arm[:, :2], axis=1)
    # a yaw about the reference keeps each fairlead at its radius and depth (rigid body)
    assert np.linalg.norm(x[..., :2], axis=-1) == pytest.approx(np.broadcast_to(r0, (9, 2)), rel=1e-12)
    assert x[..., 2] == pytest.approx(-10.0)
    # the velocity is yaw rate x arm: speed = r |d psi/dt|; at t = 0, d psi/dt = 0.2 * 2 pi / 20
    rate = 0.2 * 2 * math.pi / 20
    assert np.linalg.norm(v[0], axis=-1) == pytest.approx(r0 * rate, rel=1e-6)
    # and there (yaw 0, d2 psi/dt2 = 0) the acceleration is centripetal, r (d psi/dt)^2 towards the axis
    # (differences of step 1e-4 in the motions: truncation 1e-8, round-off 1e-14 m / 1e-8 = 1e-6 m/s^2)
    assert a[0, :, :2] == pytest.approx(-arm[:, :2] * rate**2, abs=1e-5)


def test_time_series_motion_reads_csv(tmp_path):
    f = tmp_path / "m.csv"
    t = np.linspace(0, 10, 101)
    np.savetxt(f, np.column_stack([t, 0.5 * t**2]), delimiter=",", header="time,z", comments="")
    m = TimeSeriesMotion(file=str(f))
    x, v, a = m.channels(np.array([2.0, 5.0]), np.zeros((1, 3)))
    # a natural cubic spline of a parabola: exact away from the ends to ~1e-3 relative
    assert x[:, 0, 2] == pytest.approx([2.0, 12.5], rel=1e-3)
    assert v[:, 0, 2] == pytest.approx([2.0, 5.0], rel=1e-2)
    # the natural end condition (zero curvature) decays within a few of the 0.1 s knots: at 2 s and 5 s the
    # spline's second derivative is the parabola's, 1 m/s^2
    assert a[:, 0, 2] == pytest.approx([1.0, 1.0], rel=1e-2)
    with pytest.raises(sc.InputError, match="covers 0 to 10 s"):
        m.channels(np.array([11.0]), np.zeros((1, 3)))
    bad = tmp_path / "bad.csv"
    bad.write_text("t,height\n0,1\n1,2\n")
    with pytest.raises(sc.InputError, match="columns 'time'"):
        TimeSeriesMotion(file=str(bad)).channels(np.array([0.5]), np.zeros((1, 3)))
    with pytest.raises(sc.InputError, match="does not exist"):
        TimeSeriesMotion(file=str(tmp_path / "none.csv")).channels(np.array([0.5]), np.zeros((1, 3)))


def test_network_puts_a_node_at_each_attachment_and_segment_end():
    clump = sc.LineType(diameter=0.5, mass_per_length=500.0, weight_in_water=4000.0, axial_stiffness=1e9)
    line = sc.Line(segments=(sc.Segment(line_type=CHAIN, length=100.0), sc.Segment(line_type=clump, length=7.0),
                             sc.Segment(line_type=CHAIN, length=200.0)),
                   attachments=(sc.PointMass(s=250.5, mass=1000.0, volume=2.0),))
    net = network_from_line(line, (0, 0, -100), (280, 0, -10), water_density=1025, gravity=9.81, n_elements=30)
    for s in (100.0, 107.0, 250.5, 307.0):
        assert np.min(np.abs(net.arc_length - s)) < 1e-12
    # weights conserve: nodes carry the whole line's and the buoy's net weight
    total = 100 * 698.094 + 7 * 4000 + 200 * 698.094 + (1000 - 1025 * 2.0) * 9.81
    assert net.node_weight().sum() == pytest.approx(total, rel=1e-12)


def test_element_damping_is_moordyns_rule():
    # BA = zeta l sqrt(EA m) (MoorDyn Line.cpp), plus beta EA for Rayleigh's stiffness part
    assert element_damping(1e9, 100.0, 10.0, ratio=0.8) == pytest.approx(0.8 * 10 * math.sqrt(1e11))
    assert element_damping(1e9, 100.0, 10.0, stiffness_proportional=0.01) == pytest.approx(1e7)


def _oc3(**analysis):
    return sc.parse_case({"line_types": {"c": {"diameter": 0.09, "mass_per_length": 77.7066,
                                               "weight_in_water": 698.094, "axial_stiffness": 384.243e6}},
                          "line": {"line_type": "c", "length": 902.2},
                          "environment": {"depth": 320.0},
                          "analysis": {"fairlead": [848.67, -70.0], **analysis}})


@pytest.mark.parametrize("analysis, message", [
    ({"type": "mooring_dynamic", "duration": 1.0, "output_interval": 2.0}, "must not exceed duration"),
    ({"type": "mooring_dynamic", "duration": 1.0, "end_b": "free",
      "motion": {"type": "harmonic", "amplitude": [1, 0, 0], "period": 5}}, "free end B cannot follow"),
    ({"type": "mooring_dynamic", "duration": 1.0, "release_from": [1, 1]}, "needs 'end_b: free'"),
    ({"type": "mooring_dynamic", "duration": 1.0, "rayleigh": [-1, 0]}, "rayleigh must hold"),
    ({"type": "mooring_dynamic", "duration": 1.0,
      "motion": {"type": "platform", "amplitude": [1, 0, 0, 0, 0, 0]}}, "needs 'period'"),
    ({"type": "mooring_pushover"}, "needs 'offsets'"),
])
def test_bad_mooring_analyses_are_refused(analysis, message):
    with pytest.raises(sc.InputError, match=message):
        _oc3(**analysis)


def test_missing_axial_stiffness_is_refused():
    with pytest.raises(sc.InputError, match="needs an axial_stiffness"):
        sc.parse_case({"line": {"line_type": {"diameter": 0.09, "mass_per_length": 77.7}, "length": 902.2},
                       "environment": {"depth": 320.0},
                       "analysis": {"type": "mooring_static", "fairlead": [848.67, -70.0]}})


def test_static_non_convergence_reports_the_residual():
    net = network_from_line(sc.Line.single(CHAIN, 902.2), (0, 0, -320), (848.67, 0, -70), water_density=1025,
                            gravity=9.81, n_elements=20)
    # from a straight start, 3 iterations are far too few: the error says so, with the residual
    with pytest.raises(sc.ConvergenceError, match="did not converge in 3 iterations") as err:
        static_equilibrium(MooringModel(net, Water(depth=320.0)), max_iter=3)
    assert err.value.residual > 0


def test_interrupted_run_keeps_what_it_computed():
    net = network_from_line(sc.Line.single(CHAIN, 902.2), (0, 0, -320), (848.67, 0, -70), water_density=1025,
                            gravity=9.81, n_elements=20)
    model = MooringModel(net, Water(depth=320.0))
    calls = []

    def progress(t, duration):
        calls.append(t)
        if t >= 2.0:
            raise KeyboardInterrupt

    run = simulate(model, None, 10.0, 0.1, 0.5, progress=progress)
    assert run.interrupted and run.time[-1] == pytest.approx(2.0)
    assert run.position.shape[0] == run.tension.shape[0] == run.time.size == 5


def test_regular_waves_load_a_shallow_line_at_the_wave_period():
    """A taut line near the surface in 2 m waves: the fairlead tension varies with the wave period."""
    case = sc.parse_case({"line_types": {"c": {"diameter": 0.2, "mass_per_length": 40.0, "weight_in_water": 100.0,
                                               "axial_stiffness": 1e8, "drag_normal": 1.2}},
                          "line": {"line_type": "c", "length": 100.0},
                          "environment": {"depth": 50.0, "waves": {"height": 2.0, "period": 8.0}},
                          "analysis": {"type": "mooring_dynamic", "anchor": [0.0, -10.0], "fairlead": [99.0, -10.0],
                                       "duration": 40.0, "time_step": 0.1, "output_interval": 0.1,
                                       "n_elements": 20}})
    ds = sc.run(case)
    tension = ds.fairlead_tension.where(ds.time >= 16.0, drop=True).values
    spectrum = np.abs(np.fft.rfft(tension - tension.mean()))
    freq = np.fft.rfftfreq(tension.size, 0.1)
    # the wave drives the line at 1/8 Hz or its harmonic 1/4 Hz (drag is quadratic), to the FFT's bin (1/24 Hz)
    peak = freq[np.argmax(spectrum)]
    assert min(abs(peak - 0.125), abs(peak - 0.25)) < 1.0 / 24.0
    assert np.ptp(tension) > 0.01 * tension.mean()


THREE_LINES = """--------------------- MoorDyn Input File ------------------------------------
three chains meeting at a free connection point under a buoy
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.1     60         5e8        -0.5        0          1.2    1.0    0.2     0.0
---------------------- POINTS ----------------------------------------
ID    Attachment  X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)         (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed       -300    0       -100    0      0       0      0
2     Fixed       150     259.8076 -100    0      0       0      0
3     Fixed       150     -259.8076 -100    0      0       0      0
4     Free        0       0       -50     100    30      1.0    1.0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        4         320       16      -
2     chain      2        4         320       16      -
3     chain      3        4         320       16      -
---------------------- OPTIONS -----------------------------------------
300           WtrDpth       water depth (m)
------------------------- need this line --------------------------------------
"""


def test_moordyn_network_of_three_lines_and_a_buoy(tmp_path):
    from seacable.mooring.moordyn import moordyn_model, run_moordyn_file

    f = tmp_path / "three.txt"
    f.write_text(THREE_LINES)
    ds = run_moordyn_file(f)
    assert ds.sizes["line"] == 3
    model = moordyn_model(f)
    st = static_equilibrium(model)
    # the free point: its net buoyancy (30 m^3 of water less 100 kg) balances the three lines' pulls,
    # and by symmetry it sits over the origin
    lift = (1025.0 * 30 - 100.0) * 9.80665
    # anchors on a circle of 300 m (to the 1e-7 of the printed coordinates): the point sits over the centre
    assert np.hypot(*st.position[3, :2]) < 1e-3
    # vertical balance of the whole system (the seabed is far below): the anchors hold the lines' weight in
    # water less the lift
    w_lines = 3 * 320.0 * (60.0 - 1025.0 * math.pi * 0.1**2 / 4) * 9.80665
    assert -np.sum(st.support[:3, 2]) == pytest.approx(w_lines - lift, rel=1e-6)
    # the three anchor tensions are equal by symmetry
    assert np.ptp(ds.anchor_tension.values) < 1e-4 * float(ds.anchor_tension.mean())


def test_cli_runs_a_moordyn_file(tmp_path, capsys):
    f = tmp_path / "three.txt"
    f.write_text(THREE_LINES)
    out = tmp_path / "three.nc"
    assert main(["run", str(f), "-o", str(out), "--no-plots"]) == 0
    assert out.exists()
    assert main(["run", str(f), "--motion", str(tmp_path / "m.csv"), "--no-plots"]) == 2
    assert "--motion needs --duration" in capsys.readouterr().err
    bad = tmp_path / "bad.txt"
    bad.write_text(THREE_LINES.replace("1     chain      1        4", "1     chainX     1        4"))
    assert main(["run", str(bad), "--no-plots"]) == 2
    err = capsys.readouterr().err
    assert "chainX" in err and "Traceback" not in err


def test_cli_moves_vessel_points_rigidly_from_a_platform_csv(tmp_path):
    """A CSV with surge and yaw columns is a rigid platform motion: the three fairleads move on it."""

    from seacable.mooring.moordyn import run_moordyn_file

    f = tmp_path / "spread.txt"
    lines = THREE_LINES.replace("4     Free        0       0       -50     100    30      1.0    1.0",
                                "4     Vessel      0       0       -50     0      0       0      0")
    f.write_text(lines)
    t = np.linspace(0.0, 4.0, 41)
    csv = tmp_path / "platform.csv"
    np.savetxt(csv, np.column_stack([t, 2.0 * np.sin(t), 0.05 * t]), delimiter=",", header="time,surge,yaw",
               comments="")
    out = tmp_path / "spread.nc"
    assert main(["run", str(f), "--duration", "2", "--motion", str(csv), "-o", str(out), "--no-plots"]) == 0
    ds = open_netcdf(out)
    ref = run_moordyn_file(f, duration=2.0, motion=PlatformMotion(file=str(csv)))
    # the CLI ran the platform motion (not offsets of x): the same tensions as the Python API, to the
    # NetCDF round trip
    assert ds.fairlead_tension.values == pytest.approx(ref.fairlead_tension.values, rel=1e-12)
    # the point at the origin only surges (the yaw turns it in place): x = 2 sin(2) at t = 2 s (the spline
    # through 41 samples of sin is exact to ~1e-5)
    assert float(ds.x.sel(time=2.0).isel(line=0, node=-1)) == pytest.approx(2 * math.sin(2.0), abs=1e-4)


def test_a_lumped_clump_sinking_into_a_soft_seabed_is_warned():
    """A 20 t clump as a point load on 15 m elements of chain sits W / (k A) = 0.05 m deep at 3e6 Pa/m (less
    than the 0.09 m chain: no warning); at 3e5 Pa/m, 0.5 m: the warning names the node and the fix."""
    line = sc.Line(segments=(sc.Segment(line_type=CHAIN, length=900.0),),
                   attachments=(sc.PointMass(s=90.0, mass=2e4),))
    net = network_from_line(line, (0, 0, -300), (850, 0, -50), water_density=1025, gravity=9.81, n_elements=60)
    static_equilibrium(MooringModel(net, Water(depth=300.0)))  # the suite turns warnings into errors
    with pytest.warns(sc.SeacableWarning, match=r"node 6 \(s = 90 m\) sinks 0\.\d+ m into the seabed"):
        static_equilibrium(MooringModel(net, Water(depth=300.0, seabed_stiffness=3e5)))


def test_cli_takes_the_spectral_radius_of_a_moordyn_file(tmp_path, capsys):
    """--spectral-radius reaches the generalised-alpha step of a line-only deck (recorded in the result, and
    the tensions differ from average acceleration's: the scheme damps); outside [0, 1] it is refused with
    the range; a YAML case takes it in its analysis; a deck with a body (the system dynamics, average
    acceleration only) refuses it."""

    f = tmp_path / "three.txt"
    f.write_text(THREE_LINES.replace("4     Free        0       0       -50     100    30      1.0    1.0",
                                     "4     Vessel      0       0       -50     0      0       0      0"))
    t = np.linspace(0.0, 4.0, 41)
    csv = tmp_path / "m.csv"
    np.savetxt(csv, np.column_stack([t, 2.0 * np.sin(3 * t), 0 * t, 0 * t]), delimiter=",", header="time,x,y,z",
               comments="")
    runs = {}
    for rho in ("1", "0.5"):
        out = tmp_path / f"r{rho}.nc"
        assert main(["run", str(f), "--duration", "3", "--motion", str(csv), "--time-step", "0.1",
                     "--spectral-radius", rho, "-o", str(out), "--no-plots"]) == 0
        runs[rho] = open_netcdf(out)
    assert '"spectral_radius": 0.5' in runs["0.5"].attrs["settings"]
    assert '"spectral_radius": 1.0' in runs["1"].attrs["settings"]
    assert not np.allclose(runs["1"].fairlead_tension.values, runs["0.5"].fairlead_tension.values, rtol=1e-6)
    capsys.readouterr()
    assert main(["run", str(f), "--duration", "3", "--spectral-radius", "1.5", "--no-plots"]) == 2
    err = capsys.readouterr().err
    assert "spectral radius" in err and "1.5" in err and "Suggested fix" in err and "Traceback" not in err
    assert main(["run", str(EXAMPLES / "oc3_hywind_line.yaml"), "--spectral-radius", "0.8", "--no-plots"]) == 2
    assert "set them in" in capsys.readouterr().err
    body = Path(__file__).parents[1] / "validation" / "data" / "moordyn_decks" / "MoorDyn" / "example" / "body.txt"
    assert main(["run", str(body), "--duration", "1", "--spectral-radius", "0.8", "--no-plots",
                 "-o", str(tmp_path / "b.nc")]) == 2
    assert "average acceleration only" in capsys.readouterr().err

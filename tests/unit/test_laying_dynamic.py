"""The laying_dynamic analysis: slope payout (CPRATE), repeaters, ship speed, input errors, files.

The numbers asserted are closed forms of the laying kinematics (slack on a slope, speeds of the
ship schedule) or properties every run must have (conservation, repeater on the seabed).
"""

import math
import textwrap
from pathlib import Path

import numpy as np
import pytest

import seacable as sc
from seacable.cli import main
from seacable.errors import CaseFileError, InputError
from seacable.laying.inputs import Seabed2D
from seacable.simulate import check
from seacable.statics.laying import laying_angle

CABLE = sc.LineType(diameter=0.0225, mass_per_length=0.867, weight_in_water=4.49, drag_normal=1.85,
                    drag_tangential=0.0, name="paper 001 cable")
ENV = sc.Environment(water_density=1030.0, depth=50.0)
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def case(line=None, env=ENV, **analysis):
    analysis.setdefault("ship", sc.ShipMotion(speed=2.0))
    analysis.setdefault("duration", 20.0)
    analysis.setdefault("segment_length", 2.0)
    return sc.Case(name="lay", line=line or sc.Line.single(CABLE, 3000.0), environment=env,
                   analysis=sc.LayingDynamicAnalysis(**analysis))


def test_slope_payout_keeps_the_slack():
    """CPRATE: on a 1:10 down-slope the payout adds 1/cos(beta) and the growth of the suspended length,
    so the slack over the seabed distance stays at its target."""
    bathy = sc.Bathymetry(distance=(-1000.0, 100.0, 600.0, 2000.0), depth=(50.0, 50.0, 100.0, 100.0))
    ds = sc.run(case(bathymetry=bathy, payout=sc.PayoutSlack(slack=0.03), duration=300.0, output_interval=5.0))
    on_slope = (ds.touchdown_x > 200.0) & (ds.touchdown_x < 550.0)
    assert int(on_slope.sum()) > 10
    # landings are discrete (one per 2 m): 2e-3 of slack
    assert np.nanmax(np.abs(ds.slack.values[on_slope.values] - 0.03)) < 2e-3
    # without the compensation the laid cable on the slope falls short of the target
    ds0 = sc.run(case(bathymetry=bathy, payout=sc.PayoutSlack(slack=0.03, slope_compensation=False),
                      duration=300.0, output_interval=5.0))
    on0 = (ds0.touchdown_x > 200.0) & (ds0.touchdown_x < 550.0)
    # without it the suspended length's growth comes out of the laid cable. Straight lay at alpha down a
    # slope dz/dx = -m: the touchdown runs at V_td = V_s / (1 + m cot alpha), the suspended length grows at
    # m V_td / sin(alpha), so slack = (V_c - m V_td / sin(alpha)) / (V_td sqrt(1 + m^2)) - 1
    alpha, m, vs = float(laying_angle(2.0, 4.49, 0.0225, 1.85, 1030.0)), 0.1, 2.0
    v_td = vs / (1.0 + m / math.tan(alpha))
    expected = (1.03 * vs - m * v_td / math.sin(alpha)) / (v_td * math.hypot(1.0, m)) - 1.0
    assert np.nanmean(ds0.slack.values[on0.values]) == pytest.approx(expected, abs=2e-3)
    assert expected < 0.03 - 3e-3                  # a real shortfall, beyond the 2e-3 above


def test_repeater_slows_the_ship_and_lands():
    """examples/paper001_repeater.yaml: the ship slows for the repeater's descent and recovers after it."""
    example = sc.load_case(EXAMPLES / "paper001_repeater.yaml")
    ds = sc.run(example.replace(analysis=example.analysis.replace(duration=500.0)))
    zr = ds.repeater_z.values[:, 0]
    landed = np.nonzero(zr == -50.0)[0]
    assert landed.size and np.isnan(zr[0])           # on board at first, on the seabed at the end
    t_land = float(ds.time[landed[0]])
    ship = example.analysis.ship
    # the ship slows at its acceleration to the repeater speed while the repeater descends ...
    assert float(ds.ship_speed.min()) == pytest.approx(ship.repeater_speed, abs=1e-9)
    dv = np.abs(np.diff(ds.ship_speed.values)) / np.diff(ds.time.values)
    assert np.all(dv <= ship.acceleration + 1e-9)
    # ... and is back at full speed (speed - repeater_speed) / acceleration after the touchdown
    recovery = (ship.speed - ship.repeater_speed) / ship.acceleration
    after = ds.ship_speed.sel(time=slice(t_land + recovery + float(ds.time[1] - ds.time[0]), None)).values
    assert after.size and np.all(after == ship.speed)
    # the repeater stays where it landed; payout follows the ship at 5 % slack throughout
    assert np.ptp(ds.repeater_x.values[landed, 0]) == 0.0
    np.testing.assert_allclose(ds.payout_speed, (1.0 + example.analysis.payout.slack) * ds.ship_speed, rtol=1e-12)


def test_speed_schedule_and_output():
    ship = sc.ShipMotion(times=(0.0, 10.0, 20.0), speeds=(2.0, 1.0, 1.0))
    ds = sc.run(case(ship=ship, duration=30.0, output_interval=5.0))
    np.testing.assert_allclose(ds.time, np.arange(0.0, 30.01, 5.0))
    # the schedule is followed exactly (linear between its points): 2, 1.5, 1, 1, ...
    np.testing.assert_allclose(ds.ship_speed, [2.0, 1.5, 1.0, 1.0, 1.0, 1.0, 1.0], atol=1e-12)
    # the ship's track is the integral of the speed: 15 + 7.5 ... = 20 m run in 0-10 s
    assert float(ds.ship_x.sel(time=10.0)) == pytest.approx(15.0, abs=1e-9)
    # NaN padding beyond each time's node count, never inside it
    counts = np.sum(~np.isnan(ds.x.values), axis=1)
    for k, n in enumerate(counts):
        assert not np.isnan(ds.x.values[k, :n]).any()


def test_interrupted_run_keeps_its_result():
    calls = []

    def progress(t, duration):
        calls.append(t)
        if t >= 10.0:
            raise KeyboardInterrupt

    ds = sc.run(case(duration=30.0, output_interval=2.0), progress=progress)
    assert ds.attrs["interrupted"] == 1
    assert float(ds.time[-1]) == pytest.approx(10.0)
    assert calls[0] == pytest.approx(2.0)


@pytest.mark.parametrize("where", ["record", "touchdown"])
def test_an_interrupt_inside_the_bookkeeping_keeps_the_outputs_all_lists_hold(monkeypatch, where):
    """SIGTERM landing inside an output's recording (between its lists' appends) or a touchdown's bookkeeping
    (between the laid points' lists): the run still returns its result, flagged interrupted, the outputs and
    laid points up to the last whole one (the lists were left of different lengths, and the result was lost)."""
    from seacable.laying import events

    calls = []
    if where == "record":
        original = events._Lay.repeater_positions   # the last append of an output

        def interrupted(self):
            calls.append(1)
            if len(calls) == 4:
                raise KeyboardInterrupt
            return original(self)

        monkeypatch.setattr(events._Lay, "repeater_positions", interrupted)
    else:
        original = events._Lay.touchdowns

        def interrupted(self, t):
            calls.append(t)
            if t > 12.0:   # part way through: the laid points of one list appended, not of the others
                self.laid["p"].append(self.laid["p"][-1])
                raise KeyboardInterrupt
            return original(self, t)

        monkeypatch.setattr(events._Lay, "touchdowns", interrupted)
    ds = sc.run(case(duration=30.0, output_interval=2.0))
    assert ds.attrs["interrupted"] == 1
    assert float(ds.time[-1]) == pytest.approx(4.0 if where == "record" else 12.0)
    assert np.all(np.isfinite(ds.top_tension.values))


def test_floating_cable_is_refused():
    floater = CABLE.replace(weight_in_water=-1.0)
    with pytest.raises(InputError, match="must sink"):
        sc.run(case(line=sc.Line.single(floater, 3000.0)))


def test_bottom_tension_needs_an_elastic_cable():
    with pytest.raises(InputError, match="extensible: true"):
        case(payout=sc.PayoutBottomTension(tension=100.0))


def test_needs_depth_or_bathymetry():
    with pytest.raises(InputError, match="environment.depth"):
        case(env=sc.Environment(water_density=1030.0))


@pytest.mark.parametrize("kwargs, message", [
    (dict(distance=(0.0, 10.0), depth=(50.0, -1.0)), "depth\\[1\\] must be > 0 m"),
    (dict(distance=(10.0, 0.0), depth=(50.0, 50.0)), "strictly increasing"),
    (dict(distance=(0.0,), depth=(50.0,)), "length >= 2"),
    (dict(), "either 'distance' and 'depth'"),
])
def test_bad_bathymetry(kwargs, message):
    with pytest.raises(InputError, match=message):
        sc.Bathymetry(**kwargs)


def test_ship_needs_speed_or_schedule():
    with pytest.raises(InputError, match="either 'speed'"):
        sc.ShipMotion()
    with pytest.raises(InputError, match="strictly increasing"):
        sc.ShipMotion(times=(0.0, 0.0), speeds=(1.0, 1.0))


def test_line_too_short():
    with pytest.raises(InputError, match="make the line"):
        sc.run(case(line=sc.Line.single(CABLE, 300.0)))


def test_seabed_profile_functions():
    bed = Seabed2D(np.array([0.0, 100.0, 200.0]), np.array([50.0, 60.0, 60.0]))
    assert float(bed.z(50.0)) == -55.0
    assert bed.slope(50.0) == pytest.approx(-0.1)
    assert bed.slope(150.0) == 0.0
    # arc length along the slope: 100 m run at 1:10 is sqrt(100^2 + 10^2)
    assert float(bed.arc(100.0)) == pytest.approx(math.hypot(100.0, 10.0))
    assert float(bed.arc(-5.0)) == pytest.approx(-5.0)       # straight beyond the ends


def test_case_file_with_bathymetry_file(tmp_path):
    (tmp_path / "bed.csv").write_text("distance,depth\n-2000,50\n0,50\n500,60\n3000,60\n")
    (tmp_path / "lay.yaml").write_text(textwrap.dedent("""
        name: lay_file
        line_types:
          cable: {diameter: 0.0225, mass_per_length: 0.867, weight_in_water: 4.49, drag_normal: 1.85}
        line: {line_type: cable, length: 3000.0}
        environment: {water_density: 1030.0}
        analysis:
          type: laying_dynamic
          ship: {speed: 2.0}
          payout: {type: slack, slack: 0.05}
          bathymetry: {file: bed.csv}
          duration: 4.0
          segment_length: 2.0
        """))
    out = tmp_path / "lay.nc"
    assert main(["run", str(tmp_path / "lay.yaml"), "-o", str(out), "--no-plots"]) == 0
    ds = sc.read_netcdf(out)
    assert ds.attrs["analysis"] == "laying_dynamic"
    assert float(ds.seabed_z.min()) >= -60.0
    (tmp_path / "bed.csv").write_text("distance,height\n0,50\n")
    assert main(["run", str(tmp_path / "lay.yaml"), "-o", str(out), "--no-plots"]) == 2


def test_missing_bathymetry_file_is_a_clear_error(tmp_path, capsys):
    bathy = sc.Bathymetry(file=str(tmp_path / "nope.csv"))
    with pytest.raises(InputError, match="nope.csv. does not exist"):
        sc.run(case(bathymetry=bathy))


def test_case_file_error_names_the_key():
    data = {"name": "x", "line": {"line_type": {"diameter": 0.02, "mass_per_length": 1.0}, "length": 1000.0},
            "environment": {"depth": 50.0},
            "analysis": {"type": "laying_dynamic", "ship": {"speed": -1.0}, "duration": 10.0}}
    with pytest.raises(CaseFileError, match="ship.speed"):
        sc.parse_case(data)


@pytest.mark.parametrize("current", [sc.Current.uniform(0.5), sc.Current.profile((0.0, 100.0), (0.5, 0.5))])
def test_current_along_the_track_sets_the_relative_speed(current):
    """Morison drag on the relative velocity: a 0.5 m/s current with the ship makes a 2 m/s lay hang at
    the straight-line angle of 1.5 m/s (eq. (7) with V_s - u; 17.343 deg in Table 1)."""
    env = sc.Environment(water_density=1030.0, depth=50.0, current=current)
    ds = sc.run(case(env=env, duration=200.0, output_interval=5.0, payout=sc.PayoutSlack(slack=0.05)))
    expected = math.degrees(float(laying_angle(1.5, 4.49, 0.0225, 1.85, 1030.0)))
    # the steady straight lay is exact in the lumped model; 1e-3 deg is the decayed start-up
    assert math.degrees(float(ds.entry_angle[-1])) == pytest.approx(expected, abs=1e-3)


def _sliding(friction: float, **analysis):
    env = sc.Environment(water_density=1030.0, depth=50.0, seabed=sc.Seabed(friction=friction))
    return case(env=env, laid_cable="sliding", **analysis)


def test_sliding_laid_cable_needs_a_friction(tmp_path):
    """Nothing would hold a laid cable free to slide on a frictionless seabed: refused by run and validate (exit 2),
    with the input and a fix; a friction given for a held cable is said to be unused."""
    with pytest.raises(InputError, match=r"friction coefficient > 0, got environment.seabed.friction = 0\b.*fix"):
        sc.run(_sliding(0.0))
    path = tmp_path / "lay.yaml"
    path.write_text(textwrap.dedent("""\
        name: lay
        line_types: {c: {diameter: 0.0225, mass_per_length: 0.867, weight_in_water: 4.49, drag_normal: 1.85}}
        line: {line_type: c, length: 3000.0}
        environment: {water_density: 1030.0, depth: 50.0}
        analysis: {type: laying_dynamic, ship: {speed: 2.0}, duration: 20.0, segment_length: 2.0,
                   laid_cable: sliding}
        """))
    assert main(["validate", str(path)]) == 2
    assert main(["run", str(path), "-o", str(tmp_path / "out.nc")]) == 2
    with pytest.warns(sc.SeacableWarning, match="friction = 0.5 is not used"):
        check(case(env=sc.Environment(water_density=1030.0, depth=50.0, seabed=sc.Seabed(friction=0.5))))


def test_straight_lay_of_a_sliding_cable_is_the_held_lay():
    """A straight 2-D lay under 100 N of bottom tension: the laid cable lies straight with its tension uniform,
    so friction has nothing to hold and the sliding lay is the held one. Tolerances: the friction's spring lets a
    laid node move up to its slip distance, 1 mm (measured: touchdown 1.4 mm, bottom tension 0.016 N of 100 N,
    top tension 0.015 N of 327 N). The tension left in the laid cable is the target bottom tension, uniform along
    it, to the ripple of the 1 m nodes landing every fourth step: the laid cable, held by the friction's spring,
    carries that ripple some 100 m back (98.05 to 101.47 N there, 1.8 N either side of 100 N). The cable fixed
    beyond keeps the value of the step it was fixed at (measured 98.36 N), the 60 m free to slide 100.49-100.56 N."""
    elastic = sc.Line.single(CABLE.replace(axial_stiffness=3e7), 3000.0)
    kwargs = {"line": elastic, "ship": sc.ShipMotion(speed=1.0), "duration": 400.0, "segment_length": 1.0,
              "output_interval": 10.0, "extensible": True, "payout": sc.PayoutBottomTension(tension=100.0)}
    held = sc.run(case(**kwargs))
    sliding = sc.run(_sliding(0.5, **kwargs))
    np.testing.assert_allclose(sliding.touchdown_x, held.touchdown_x, rtol=0, atol=5e-3)
    np.testing.assert_allclose(sliding.bottom_tension, held.bottom_tension, rtol=0, atol=0.05)
    np.testing.assert_allclose(sliding.top_tension, held.top_tension, rtol=0, atol=0.05)
    recent = sliding.laid_time.values > 200.0
    np.testing.assert_allclose(sliding.laid_residual_tension.values[recent], 100.0, rtol=0, atol=1.8)

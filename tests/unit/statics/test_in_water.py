"""The single-line statics never return an equilibrium that leaves the water (issue 37, item 1).

The multi-segment catenary weighs every part at its weight in water and meets the seabed only under a line
anchored on it; a solution above the surface or through the seabed is refused with where it leaves the water.
The system statics weighs a part above the water at its dry weight; a buoyant part that would float along the
surface (buoyant when immersed, heavy in the air) has no equilibrium there and is refused, not returned after
its surface crossings stop being moved.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import seacable as sc
from seacable.errors import NoSolutionError
from seacable.system.model import MooringSystem, SystemLine, SystemPoint
from seacable.system.statics import solve_equilibrium

REPRO = Path(__file__).parents[4] / "shared" / "repro" / "lazywave_above_surface.yaml"

CABLE = sc.LineType(diameter=0.15, mass_per_length=45.0, axial_stiffness=5.0e8)
FLOAT = sc.LineType(diameter=0.6, mass_per_length=60.0, axial_stiffness=5.0e8)   # -2254 N/m in water


def _lazy_wave(float_length=80.0, fairlead=(450.0, -10.0)):
    line = sc.Line(segments=[sc.Segment(line_type=CABLE, length=380.0),
                             sc.Segment(line_type=FLOAT, length=float_length),
                             sc.Segment(line_type=CABLE, length=160.0)])
    return sc.Case(name="lazy", line=line, environment=sc.Environment(depth=200.0, gravity=9.81),
                   analysis=sc.StaticAnalysis(fairlead=fairlead))


def test_a_buoyant_arch_above_the_surface_is_refused_not_returned():
    """The issue's lazy wave: 80 m of -2254 N/m float. In water-weight statics its arch peaks 94.9 m above
    the surface (today's code returned that, with a 62.5 kN fairlead tension); it is refused, naming how
    high and where, by `run` and by `check` (what `seacable validate` runs)."""
    case = _lazy_wave()
    for call in (sc.run, sc.check):
        with pytest.raises(NoSolutionError, match=r"rises 94\.9\d m above the sea surface .*\(segment 2"):
            call(case)


@pytest.mark.skipif(not REPRO.exists(), reason="shared/repro is not beside the project")
def test_the_repro_file_is_refused_by_validate(capsys):
    from seacable.cli import main

    assert main(["validate", str(REPRO)]) == 2
    err = capsys.readouterr().err
    assert "above the sea surface" in err and "Traceback" not in err


def test_a_small_float_that_stays_under_water_is_solved():
    """10 m of the same float: the arch stays under water, so the result is returned (no false refusal);
    its highest point is below z = 0 and the fairlead tension is the system statics' (the same exact
    catenary, another solver: 1e-6 relative)."""
    case = _lazy_wave(float_length=10.0)
    ds = sc.run(case)
    assert float(ds.z.max()) <= -10.0 + 1e-9
    system = MooringSystem(points={"a": SystemPoint(kind="fixed", position=(0.0, 0.0, -200.0)),
                                   "f": SystemPoint(kind="fixed", position=(450.0, 0.0, -10.0))},
                           lines={"l": SystemLine(line=case.line, end_a="a", end_b="f")})
    eq = solve_equilibrium(system, case.environment)
    assert float(ds.fairlead_tension) == pytest.approx(float(eq.end_b_tension[0]), rel=1e-6)


def test_the_system_statics_refuses_a_line_that_would_float_along_the_surface():
    """The same 80 m float between two fixed points in the system statics: immersed it arches 95 m up,
    in the air it weighs 589 N/m and falls back under, so no split at the surface is a fixed point. Today's
    code returned the immersed shape after 8 rounds of moving the crossings; it is refused, naming the
    line and the part in the air."""
    case = _lazy_wave()
    system = MooringSystem(points={"a": SystemPoint(kind="fixed", position=(0.0, 0.0, -200.0)),
                                   "f": SystemPoint(kind="fixed", position=(450.0, 0.0, -10.0))},
                           lines={"l": SystemLine(line=case.line, end_a="a", end_b="f")})
    with pytest.raises(NoSolutionError, match=r"lines\.l \(s = 30\d\.\d+-59\d\.\d+ m\) rises above the sea"):
        solve_equilibrium(system, case.environment)


def test_a_fairlead_above_the_water_is_refused_with_the_system_statics_as_the_fix():
    """A chain to a fairlead 5 m above the water: its top 5 m would weigh their in-water weight; refused,
    pointing at system_static (which weighs them dry: tests/validation/test_system_statics_surface.py)."""
    chain = sc.LineType(diameter=0.09, mass_per_length=77.7, axial_stiffness=3.8e8)
    case = sc.Case(name="deck", line=sc.Line.single(chain, 900.0), environment=sc.Environment(depth=320.0),
                   analysis=sc.StaticAnalysis(fairlead=(850.0, 5.0)))
    with pytest.raises(NoSolutionError, match=r"rises 5 m above the sea surface.*system_static"):
        sc.run(case)


def test_a_line_through_the_seabed_under_an_anchor_above_it_is_refused():
    """An anchor 50 m above a 200 m seabed (no contact modelled for it) and a line long enough to sag
    through it. Closed form of the check: a chain of w N/m between (0, -150) and (300, -20) with 700 m of
    line hangs far below -200 m. Refused, naming how far below and where."""
    chain = sc.LineType(diameter=0.09, mass_per_length=77.7, axial_stiffness=3.8e8)
    env = sc.Environment(depth=200.0)
    case = sc.Case(name="deep_sag", line=sc.Line.single(chain, 700.0), environment=env,
                   analysis=sc.StaticAnalysis(anchor=(0.0, -150.0), fairlead=(300.0, -20.0)))
    with pytest.raises(NoSolutionError, match=r"m below the seabed .* anchor \(z = -150 m\) is above the seabed"):
        sc.run(case)
    # the same line 350 m long stays above the seabed: solved, its lowest point above z = -200 m
    short = case.model_copy(update={"line": sc.Line.single(chain, 350.0)})
    ds = sc.run(short)
    assert float(ds.z.min()) > -200.0
    assert math.isfinite(float(ds.fairlead_tension))


def test_a_pushover_that_lifts_a_buoyant_arch_out_of_the_water_is_refused_at_that_offset():
    """A 35 m float under water at the reference span (its arch peaks below z = 0, 0.7 m under at -50 m):
    pulled in by 100 m, the slacker line arches 10 m above the surface; the pushover is refused naming that
    offset."""
    case = _lazy_wave(float_length=35.0)
    assert float(sc.run(case).z.max()) < 0.0
    push = sc.Case(name="push", line=case.line, environment=case.environment,
                   analysis=sc.PushoverAnalysis(fairlead=(450.0, -10.0), offsets=(0.0, -50.0, -100.0)))
    with pytest.raises(NoSolutionError, match=r"at offset -100 m: the line's equilibrium rises 10\.\d+ m above"):
        sc.run(push)


def test_a_steady_tow_lifted_above_the_tow_point_by_a_float_is_refused():
    """Paper 000's cable (17.7 N/m in water) with a 2 kN float at its lower end, towed at 0.5 m/s: the float
    lifts the end above the tow point, which is at the surface; the steady tow (weights in water) is refused.
    With a 2 kN clump instead it hangs below (z < 0 everywhere)."""
    cable = sc.LineType(diameter=0.035, mass_per_length=2.79, weight_in_water=17.7, axial_stiffness=4.233e5,
                        drag_normal=1.5, drag_tangential=0.01)

    def tow(weight):
        line = sc.Line(segments=[sc.Segment(line_type=cable, length=170.0)],
                       attachments=[sc.PointMass(s=0.0, weight_in_water=weight, drag_area=0.1)])
        return sc.Case(name="float_tow", line=line, environment=sc.Environment(),
                       analysis=sc.TowedSteadyAnalysis(vessel_speed=0.5))

    with pytest.raises(NoSolutionError, match=r"rises .* m above the tow point"):
        sc.run(tow(-2000.0))
    assert float(sc.run(tow(2000.0)).z.max()) <= 1e-9

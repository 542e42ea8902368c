"""The lay planner (``lay_plan``) against closed forms and the 2-D dynamic laying model.

Closed forms: Zajac's straight line (paper 001 section 2) with and without a current, the turn of
the span's plane by a cross-current (derived in :func:`seacable.laying.plan.straight_direction`),
the catenary under a bottom tension (with the payout's centripetal term), the payout of a slack
lay over a slope (the 2-D model's CPRATE) and a repeater's slow-down.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import seacable as sc
from seacable.case import LayPlanAnalysis
from seacable.laying.inputs import LayTarget, PlanShip
from seacable.laying.route import Route
from seacable.statics.laying import laying_angle, straight_line_lay

RHO = 1025.0
G = 9.81            # the Environment default


def _cable(**kw):
    base = {"diameter": 0.035, "mass_per_length": 1.4, "drag_normal": 1.2, "drag_tangential": 0.01,
            "added_mass_normal": 1.0}
    return sc.LineType(**{**base, **kw}, name="tel35")


def _case(*, depth=None, bathymetry=None, waypoints=((0.0, 0.0), (10000.0, 0.0)), speed=1.5, target=None,
          current=None, line_type=None, attachments=(), ship=None, kp_step=100.0, length=40000.0):
    env = sc.Environment(depth=depth, water_density=RHO, current=current or sc.Current())
    analysis = LayPlanAnalysis(route=Route(waypoints=waypoints), ship=ship or PlanShip(speed=speed),
                               target=target or LayTarget(slack=0.03), bathymetry=bathymetry, kp_step=kp_step)
    line = sc.Line.single(line_type or _cable(), length, attachments=attachments)
    return sc.Case(name="plan", line=line, environment=env, analysis=analysis)


def test_straight_route_no_current_is_zajacs_straight_line():
    """Flat seabed, still water, 5 % slack: the span is paper 001's straight line (angle, layback, suspended
    length, top tension with the tangential drag of the payout V_c - V_s cos(alpha)), and the payout is
    (1 + slack) V_s. The uniform-current span is one exact step, so the tolerance is round-off."""
    lt = _cable()
    ds = sc.run(_case(depth=1000.0, target=LayTarget(slack=0.05), line_type=lt))
    w = lt.submerged_weight(RHO, G)
    ref = straight_line_lay(1000.0, 1.5, w, lt.diameter, lt.drag_normal, lt.drag_tangential,
                            payout_speed=1.05 * 1.5, water_density=RHO)
    mid = ds.sel(kp=5000.0)
    assert float(mid.entry_angle) == pytest.approx(ref.angle, rel=1e-12)
    assert float(mid.layback) == pytest.approx(ref.layback, rel=1e-10)
    assert float(mid.suspended_length) == pytest.approx(ref.suspended_length, rel=1e-10)
    assert float(mid.top_tension) == pytest.approx(ref.top_tension, rel=1e-9)
    assert float(mid.payout_speed) == pytest.approx(1.05 * 1.5, rel=1e-9)
    assert float(mid.touchdown_offset) == pytest.approx(0.0, abs=1e-9)
    assert float(mid.touchdown_kp) == pytest.approx(5000.0 - ref.layback, rel=1e-12)
    assert float(mid.route_slack) == pytest.approx(0.05, rel=1e-9)
    assert float(ds.time[-1]) == pytest.approx(10000.0 / 1.5, rel=1e-12)


@pytest.mark.parametrize("heading", [math.pi / 2, math.radians(60.0), math.radians(-135.0)])
def test_cross_current_turns_the_span_plane(heading):
    """A uniform current c at ``heading``: the span's vertical plane lies along the ship's velocity through the
    water W = V_s e_1 - c, at Zajac's angle for |W|, so it turns off the route by atan(c_2 / (V_s - c_1)) and
    the touchdown sits h cot(alpha) sin(that) down-current of the route (derivation in
    seacable.laying.plan.straight_direction). Exact for a straight span: round-off tolerance."""
    lt = _cable()
    c = 0.4
    c1, c2 = c * math.cos(heading), c * math.sin(heading)
    ds = sc.run(_case(depth=500.0, current=sc.Current(speed=c, heading=heading), line_type=lt))
    rel = math.hypot(1.5 - c1, c2)
    alpha = float(laying_angle(rel, lt.submerged_weight(RHO, G), lt.diameter, lt.drag_normal, RHO))
    turn = math.atan2(c2, 1.5 - c1)
    mid = ds.sel(kp=5000.0)
    reach = 500.0 / math.tan(alpha)
    assert float(mid.entry_angle) == pytest.approx(alpha, rel=1e-12)
    assert float(mid.layback) == pytest.approx(reach, rel=1e-10)
    assert float(mid.touchdown_offset) == pytest.approx(reach * math.sin(turn), rel=1e-10)
    assert float(mid.touchdown_kp) == pytest.approx(5000.0 - reach * math.cos(turn), rel=1e-12)
    assert math.copysign(1.0, float(mid.touchdown_offset)) == math.copysign(1.0, c2)   # down-current


def test_bottom_tension_span_is_the_catenary_with_the_payout_term():
    """No drag (C_dn = C_dt = 0): under a bottom tension T_0 on a flat seabed the span is a catenary of the
    effective tension T - (m + m_a) V_c^2 (the material turning along the curve at the payout speed): with
    a = (T_0 - (m + m_a) V_c^2) / w, S = sqrt(h^2 + 2 a h), layback a asinh(S / a), T_top = T_0 + w h.
    RK4 with 80 steps, the last one cut at the surface linearly: 1e-5 of the layback, 1e-6 of the rest."""
    lt = _cable(drag_normal=0.0, drag_tangential=0.0, axial_stiffness=None)
    ds = sc.run(_case(depth=200.0, target=LayTarget(bottom_tension=500.0), line_type=lt))
    mid = ds.sel(kp=5000.0)
    w = lt.submerged_weight(RHO, G)
    vc = float(mid.payout_speed)
    assert vc == pytest.approx(1.5, rel=1e-9)       # inextensible: the laid length is the distance run
    a = (500.0 - (lt.mass_per_length + lt.added_mass_per_length(RHO)) * vc**2) / w
    s = math.sqrt(200.0**2 + 2.0 * a * 200.0)
    assert float(mid.suspended_length) == pytest.approx(s, rel=1e-6)
    assert float(mid.layback) == pytest.approx(a * math.asinh(s / a), rel=1e-5)
    assert float(mid.top_tension) == pytest.approx(500.0 + w * 200.0, rel=1e-6)
    assert float(mid.entry_angle) == pytest.approx(math.atan(s / a), rel=1e-5)


def test_slack_lay_over_a_slope_pays_out_as_cprate():
    """A constant seabed slope: the payout is the 2-D model's CPRATE, V_td ((1 + s) sqrt(1 + b^2) - b / sin(alpha))
    with the touchdown speed V_td = V_s / (1 - b cot(alpha)) (b = dz/dx, rising ahead): the laid length plus
    the change of the suspended length. Everything is linear in KP on the slope, so the differences are exact."""
    lt = _cable()
    bath = sc.Bathymetry(distance=(0.0, 2000.0, 12000.0, 20000.0), depth=(800.0, 800.0, 300.0, 300.0))
    ds = sc.run(_case(bathymetry=bath, waypoints=((0.0, 0.0), (16000.0, 0.0)), target=LayTarget(slack=0.04),
                      line_type=lt))
    b = 500.0 / 10000.0
    alpha = float(laying_angle(1.5, lt.submerged_weight(RHO, G), lt.diameter, lt.drag_normal, RHO))
    vtd = 1.5 / (1.0 - b / math.tan(alpha))
    expected = vtd * (1.04 * math.sqrt(1.0 + b * b) - b / math.sin(alpha))
    on_slope = (ds.touchdown_kp > 2500.0) & (ds.touchdown_kp < 11500.0)
    assert int(on_slope.sum()) > 50
    np.testing.assert_allclose(ds.payout_speed.where(on_slope, drop=True), expected, rtol=1e-9)
    np.testing.assert_allclose(ds.touchdown_speed.where(on_slope, drop=True), vtd * math.sqrt(1 + b * b), rtol=1e-9)


def test_repeater_slows_the_ship_between_entry_and_touchdown():
    """A repeater at s = 3000 m: the ship slows from its water entry (cable paid out = s) to its touchdown (cable
    laid = s) at the acceleration a, v^2 = v_0^2 - 2 a (KP - KP_entry), and regains speed the same way."""
    ship = PlanShip(speed=1.5, repeater_speed=0.6, acceleration=0.01)
    rep = sc.PointMass(s=3000.0, mass=400.0, volume=0.15, kind="repeater", name="R1")
    ds = sc.run(_case(depth=300.0, ship=ship, attachments=(rep,), kp_step=20.0))
    entry, landing = float(ds.repeater_entry_kp[0]), float(ds.repeater_touchdown_kp[0])
    assert float(np.interp(entry, ds.kp, ds.paid_out)) == pytest.approx(3000.0, rel=1e-9)
    assert float(np.interp(landing, ds.kp, ds.laid_length)) == pytest.approx(3000.0, rel=1e-9)
    kp, v = ds.kp.values, ds.ship_speed.values
    assert np.all(v[kp < entry] == 1.5)
    first = int(np.searchsorted(kp, entry))                 # the first station inside the window
    ramp = (kp > entry) & (kp < entry + (1.5**2 - 0.6**2) / 0.02 - 20.0)
    # stations decelerate from the last one outside the window (the speeds are taken at the stations)
    np.testing.assert_allclose(v[ramp], np.sqrt(1.5**2 - 2 * 0.01 * (kp[ramp] - kp[first - 1])), rtol=1e-12)
    assert np.all(np.isclose(v[(kp > entry + 120.0) & (kp <= landing)], 0.6))
    assert v[-1] == 1.5
    assert float(ds.repeater_touchdown_time[0]) > float(ds.repeater_entry_time[0])


def test_target_table_is_taken_at_the_touchdown_kp():
    """A slack target by KP (2 % at KP 0, 6 % at 5 km, 2 % at 10 km) is where the cable lands: each row's slack is
    the table at that row's touchdown KP, which lies a layback (2.9 km in 1000 m of water) behind the ship (to
    1e-6: the touchdown KP of the last iteration against the one the target was taken at; measured 5e-7), and
    the cable laid per metre of route there is 1 + that slack."""
    table = LayTarget(kp=(0.0, 5000.0, 10000.0), slack=(0.02, 0.06, 0.02))
    ds = sc.run(_case(depth=1000.0, target=table))
    expected = np.interp(ds.touchdown_kp.values, table.kp, table.slack)
    np.testing.assert_allclose(ds.slack.values, expected, rtol=0, atol=1e-6)
    at_ship = np.interp(ds.kp.values, table.kp, table.slack)
    assert float(np.max(np.abs(ds.slack.values - at_ship))) > 0.02        # the ship's KP would be a layback early
    steady = (ds.touchdown_kp.values > 500.0) & (ds.kp.values < 9000.0)
    np.testing.assert_allclose(ds.route_slack.values[steady], ds.slack.values[steady], rtol=0, atol=2e-3)


def test_span_follows_a_slow_down_smoothly():
    """The lag: the span sees the ship's velocity through a first-order lag of h / (V_s sin(alpha)), so through a slow-down the
    touchdown KP keeps increasing (no jump to the slow span's shorter layback) and the payout stays >= 0."""
    ship = PlanShip(kp=(0.0, 5000.0, 5100.0, 20000.0), speeds=(1.5, 1.5, 0.5, 0.5))
    ds = sc.run(_case(depth=1000.0, ship=ship, waypoints=((0.0, 0.0), (20000.0, 0.0))))
    step = np.diff(ds.touchdown_kp.values)
    change = float(ds.layback.sel(kp=4900.0) - ds.layback.sel(kp=19000.0))      # 2400 m shorter when slow
    assert step.min() > 0.0
    # without the lag the touchdown would jump by the whole change between two stations; with it, a tenth of it
    # at most (the lag's time, 2800 s at 0.5 m/s, is 14 stations of 200 s)
    assert step.max() - 100.0 < 0.1 * change
    assert float(ds.payout_speed.min()) >= 0.0
    late = ds.sel(kp=19000.0)
    alpha = float(laying_angle(0.5, _cable().submerged_weight(RHO, G), 0.035, 1.2, RHO))
    assert float(late.layback) == pytest.approx(1000.0 / math.tan(alpha), rel=1e-3)   # 14 000 m = 14 lag lengths


@pytest.fixture(scope="module")
def dynamic_and_plan():
    """The 2-D dynamic model (laying_dynamic, 2 m segments) and the planner on the same straight route: 200 m
    of water, 500 N bottom tension, 1.5 m/s, elastic cable."""
    lt = _cable(axial_stiffness=3.0e7)
    line = sc.Line.single(lt, 20000.0)
    env = sc.Environment(depth=200.0, water_density=RHO)
    dyn = sc.Case(name="dyn", line=line, environment=env, analysis=sc.LayingDynamicAnalysis(
        ship=sc.ShipMotion(speed=1.5), payout=sc.PayoutBottomTension(tension=500.0), duration=1500.0,
        segment_length=2.0, output_interval=50.0, extensible=True))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        d = sc.run(dyn)
    p = sc.run(_case(depth=200.0, target=LayTarget(bottom_tension=500.0), line_type=lt))
    return d, p


def test_plan_against_the_dynamic_model_under_bottom_tension(dynamic_and_plan):
    """Once the start's transient has passed (the last 500 s of 1500 s), the dynamic model's layback, top
    tension and entry angle equal the planner's steady span. Tolerances: the lumped-mass model's 2 m
    segments (the bend at the touchdown is resolved by them) and its bottom-tension control holding 500 N to
    within a few N; measured: bottom tension 499.66 N, layback -0.06 %, top tension -8e-6, entry angle 1e-11,
    payout -9e-6."""
    d, p = dynamic_and_plan
    late = d.time >= 1000.0
    mid = p.sel(kp=5000.0)
    assert float(d.bottom_tension.where(late).mean()) == pytest.approx(500.0, abs=5.0)
    assert float(d.layback.where(late).mean()) == pytest.approx(float(mid.layback), rel=3e-3)
    assert float(d.top_tension.where(late).mean()) == pytest.approx(float(mid.top_tension), rel=1e-4)
    assert float(d.entry_angle.where(late).mean()) == pytest.approx(float(mid.entry_angle), rel=1e-6)
    assert float(d.payout_speed.where(late).mean()) == pytest.approx(float(mid.payout_speed), rel=1e-4)


def _station(case):
    """The case's cable as the planner sees it (its station properties)."""
    from seacable.laying.plan_run import _station_props

    return _station_props(case)(np.zeros(1))[0]


def test_steady_turn_tends_to_the_straight_lay_and_is_symmetric():
    """`steady_turn` (the span in the frame turning with the ship): on a circle of 1e7 m it is paper 001's
    straight line (angle, layback, length, top tension; tolerance 1e-6: the turn itself changes the layback by
    about 0.15 L^2 / 2R = 3e-4 m of 2800 m); the cut is the same to port and starboard (1e-9 m: mirror
    images), and on wide circles it goes as 1/R (the lateral drag is linear in the small lateral velocity
    about the span's own sinking speed; 1e-3 between R = 20 and 40 km), under a rigid span's tractrix cut
    R - sqrt(R^2 - L^2)."""
    from seacable.laying.plan import steady_turn

    lt = _cable()
    p = _station(_case(depth=1000.0, line_type=lt))
    ref = straight_line_lay(1000.0, 1.5, p[0], lt.diameter, lt.drag_normal, lt.drag_tangential,
                            payout_speed=1.05 * 1.5, water_density=RHO)
    far = steady_turn(p, 1000.0, 1.5, 1e7, water_density=RHO, slack=0.05)
    assert far["entry_angle"] == pytest.approx(ref.angle, rel=1e-6)
    assert far["layback"] == pytest.approx(ref.layback, rel=1e-6)
    assert far["suspended_length"] == pytest.approx(ref.suspended_length, rel=1e-6)
    assert far["top_tension"] == pytest.approx(ref.top_tension, rel=1e-6)
    port = steady_turn(p, 1000.0, 1.5, 20000.0, water_density=RHO, slack=0.05)
    starboard = steady_turn(p, 1000.0, 1.5, -20000.0, water_density=RHO, slack=0.05)
    assert starboard["cut"] == pytest.approx(port["cut"], abs=1e-9)
    assert starboard["angle"] == pytest.approx(port["angle"], abs=1e-12)
    wider = steady_turn(p, 1000.0, 1.5, 40000.0, water_density=RHO, slack=0.05)
    assert 2.0 * wider["cut"] == pytest.approx(port["cut"], rel=1e-3)
    tractrix = 20000.0 - math.sqrt(20000.0**2 - port["layback"] ** 2)
    assert 0.0 < port["cut"] < tractrix


def _paper001_cable(tension=None):
    return sc.LineType(diameter=0.0225, mass_per_length=0.867, weight_in_water=4.49, drag_normal=1.85,
                       drag_tangential=0.01, axial_stiffness=3e7 if tension else None, name="paper001")


@pytest.mark.parametrize("speed, tension", [(0.5, None), (1.0, None), (1.0, 200.0), (1.0, 500.0), (0.5, 200.0),
                                            (2.0, None)])
def test_linear_spread_gives_the_steady_turn_cut(speed, tension):
    """The spread's linear theory (:mod:`seacable.laying.lateral`, the span's lateral balance linearised about the
    straight lay) predicts the cut on a wide circle, ``g_2 / R``: against `steady_turn` (the full span in the
    turning frame, integrated) on R = 30 km, 100 m of water, paper 001's cable, 5 % slack or a bottom tension.
    Tolerance 0.5 % (measured 0.08-0.3 %: the lateral inertia, which the linear theory leaves out, and
    `steady_turn`'s 80 RK4 steps over the span; a massless cable's steady cut with 800 steps is the linear one to
    0.015 % at 2 m/s), and 2 % at 2 m/s, where the 80 steps make the cut 1.5 % long (measured 1.6 %)."""
    from seacable.laying.plan import span_spread, steady_turn

    cable = _paper001_cable(tension)
    case = sc.Case(name="turn", line=sc.Line.single(cable, 1000.0),
                   environment=sc.Environment(water_density=1030.0, depth=100.0), analysis=LayPlanAnalysis(
                       route=Route(waypoints=((0.0, 0.0), (1000.0, 0.0))), ship=PlanShip(speed=speed),
                       target=LayTarget(slack=0.05)))
    target = {"slack": 0.05} if tension is None else {"bottom_tension": tension}
    p = _station(case)
    g2 = span_spread(p, 100.0, speed, water_density=1030.0, **target)["g2"]
    cut = steady_turn(p, 100.0, speed, 30000.0, water_density=1030.0, **target)["cut"]
    assert cut == pytest.approx(g2 / 30000.0, rel=0.02 if speed == 2.0 else 5e-3)


@pytest.mark.parametrize("speed, tension", [(0.5, None), (2.0, None), (1.0, 200.0)])
def test_plan_spreads_a_sharp_alter_course_as_the_dynamic_lay(speed, tension):
    """A sharp 20 deg alter-course to port in 100 m of water (paper 001's cable, 5 % slack or 200 N): the plan's
    touchdown offset against the dynamic 3-D lay's, at every ship KP past the waypoint. The spread of the turn is
    the span's lateral response (derived, its length the layback and its shape the span's), so the corner's cut
    follows the speed and the tension: the dynamic lay's largest cut is 6.66 m at 0.5 m/s, 12.35 m at 2 m/s and
    14.60 m under 200 N (10.44 m at 1 m/s, in the test above); a spread fitted at 1 m/s over the depth gave 4.3,
    14.2 and 20.4 m. Tolerances: the largest cut and every KP's offset to 4 % of the dynamic lay's largest cut
    (measured -2.7 % and +2.0 %; 2.7 % and 2.7 %): the plan's span is steady at each KP, the spread leaves out the
    lateral inertia (0.3 % of the cut), and the dynamic touchdown is interpolated between 2 m segments. At 2 m/s,
    7 % (measured +5.8 % and 5.9 %): there the plan's cut comes from a steady turn 1.5 % long (its RK4 steps, see
    above), and the remaining 4 % is not explained."""
    tolerance = 0.07 if speed == 2.0 else 0.04
    a = math.radians(20.0)
    route = Route(waypoints=((0.0, 0.0), (1000.0, 0.0), (1000.0 + 3000.0 * math.cos(a), 3000.0 * math.sin(a))))
    line = sc.Line.single(_paper001_cable(tension), 20000.0)
    env = sc.Environment(water_density=1030.0, depth=100.0)
    target = LayTarget(slack=0.05) if tension is None else LayTarget(bottom_tension=tension)
    plan = sc.run(sc.Case(name="plan", line=line, environment=env, analysis=LayPlanAnalysis(
        route=route, ship=PlanShip(speed=speed), target=target, kp_step=5.0)))
    payout = sc.PayoutSlack(slack=0.05) if tension is None else sc.PayoutBottomTension(tension=tension)
    # the ship sails 5 laybacks past the corner (to KP 2400 at most): there both offsets have decayed below
    # 0.3 % of the largest cut (measured to KP 2400: 0.2 % at 0.5 m/s, 0.05 % under 200 N), so the later KPs
    # asserted nothing more
    end_kp = min(2400.0, 1000.0 + 5.0 * float(np.interp(1000.0, plan.kp.values, plan.layback.values)))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        lay = sc.run(sc.Case(name="lay", line=line, environment=env, analysis=sc.LayingDynamicAnalysis(
            ship=sc.ShipMotion(speed=speed, start_x=600.0), payout=payout,
            duration=5.0 / speed * math.ceil((end_kp - 600.0) / 5.0),
            segment_length=2.0, output_interval=5.0 / speed, route=route, extensible=tension is not None)))
    kp = lay.ship_kp.values
    after = kp > 1000.0
    planned = np.interp(kp, plan.kp.values, plan.touchdown_offset.values)[after]
    dynamic = lay.touchdown_offset.values[after]
    assert float(planned.max()) == pytest.approx(float(dynamic.max()), rel=tolerance)
    assert float(np.max(np.abs(planned - dynamic))) < tolerance * float(dynamic.max())


def test_plan_through_alter_courses_matches_the_dynamic_lay():
    """A route with a sharp 20 deg alter-course to port, then a U-turn to starboard sailed on two 90 deg arcs of
    300 m (`turn_radius`), 100 m of water, 1 m/s, 5 % slack (paper 001's cable): the planner's touchdown offset
    against the dynamic 3-D lay's, at every ship KP from the first alter-course on.

    * On the arc, once the span is in its steady turn, both are `steady_turn`'s cut of 11.376 m (the planner's
      span in the turning frame, placed on the route moved by its steady offset; measured: plan 11.374 m, dynamic
      11.366 m; tolerances 0.01 and 0.05 m as in the circle test).
    * At the sharp alter-course the touchdown cuts the corner by 10.44 m (dynamic) and 10.55 m (plan), not the
      layback's tractrix (26 m): the route's change of heading is spread over the transient by the span's lateral
      response (:mod:`seacable.laying.lateral`); peak to 0.2 m.
    * Everywhere, including the transients into and out of the arcs: within 1 m (measured 0.67 m, where the
      touchdown reaches the sharp alter-course)."""
    from seacable.laying.plan import steady_turn

    a = math.radians(20.0)
    b, c = a - math.pi / 2.0, a - math.pi
    p2 = (1000.0 + 1500.0 * math.cos(a), 1500.0 * math.sin(a))
    p3 = (p2[0] + 1000.0 * math.cos(a), p2[1] + 1000.0 * math.sin(a))
    p4 = (p3[0] + 600.0 * math.cos(b), p3[1] + 600.0 * math.sin(b))
    p5 = (p4[0] + 2000.0 * math.cos(c), p4[1] + 2000.0 * math.sin(c))
    route = Route(waypoints=((0.0, 0.0), (1000.0, 0.0), p2, p3, p4, p5), turn_radius=(0.0, 0.0, 300.0, 300.0))
    cable = sc.LineType(diameter=0.0225, mass_per_length=0.867, weight_in_water=4.49, drag_normal=1.85,
                        drag_tangential=0.01, name="paper001")
    env = sc.Environment(water_density=1030.0, depth=100.0)
    line = sc.Line.single(cable, 20000.0)
    plan_case = sc.Case(name="plan", line=line, environment=env, analysis=LayPlanAnalysis(
        route=route, ship=PlanShip(speed=1.0), target=LayTarget(slack=0.05), kp_step=5.0))
    plan = sc.run(plan_case)
    lay = sc.run(sc.Case(name="lay", line=line, environment=env, analysis=sc.LayingDynamicAnalysis(
        ship=sc.ShipMotion(speed=1.0, start_x=600.0), payout=sc.PayoutSlack(slack=0.05), duration=3900.0,
        segment_length=2.0, output_interval=5.0, route=route)))
    kp = lay.ship_kp.values
    planned = np.interp(kp, plan.kp.values, plan.touchdown_offset.values)
    dynamic = lay.touchdown_offset.values
    after = kp > 1000.0
    np.testing.assert_allclose(planned[after], dynamic[after], rtol=0, atol=1.0)
    corner = (kp > 1000.0) & (kp < 1500.0)
    assert float(planned[corner].max()) == pytest.approx(float(dynamic[corner].max()), abs=0.2)
    cut = steady_turn(_station(plan_case), 100.0, 1.0, -300.0, water_density=1030.0, slack=0.05)["cut"]
    steady = (kp > 3900.0) & (kp < 4100.0)
    np.testing.assert_allclose(planned[steady], -cut, rtol=0, atol=0.01)
    np.testing.assert_allclose(dynamic[steady], -cut, rtol=0, atol=0.05)
    # on the arc the laid cable runs R - cut from the centre: per metre of route KP it lays 1.05 (R - cut) / R
    # (measured to 1e-5)
    on_arc = (plan.kp.values > 3900.0) & (plan.kp.values < 4100.0)
    np.testing.assert_allclose(plan.route_slack.values[on_arc], 1.05 * (300.0 - cut) / 300.0 - 1.0, rtol=0, atol=1e-4)

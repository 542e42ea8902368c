"""The ``laying_dynamic`` analysis: a case in, a labelled xarray Dataset out."""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from .._limits import check_run_size
from ..case import Case, LayingDynamicAnalysis
from ..errors import InputError, SeacableWarning
from ..results import make_dataset, var
from ..statics.laying import laying_angle
from ..vessel_motion import bind_vessel_motion, sea_of_environment
from .bathymetry import seabed_map
from .inputs import PayoutRate, PayoutSlack, Seabed2D, sinking_weights
from .kernel import P_CDN, P_DIAMETER, P_WEIGHT
from .solver import _MIN_SPEED, LayParameters, Repeater, initial_state, props_row, simulate
from .track import Track2D, Track3D

__all__ = ["LayingSetup", "lay_parameters", "lay_seabed", "prepare_laying_dynamic", "run_laying_dynamic"]

_N_SERIES = 16      # time series stored per output time (ship_x, top_tension, ...)

REFERENCES = (
    "Paper 001: Park, H. I. et al., two-dimensional laying simulation of subsea cables by the finite "
    "difference method (seeds/001): section 3, eq. (12)-(18); section 4, Table 1.",
    "Walton, T. S. & Polachek, H. (1960). Calculation of transient motion of submerged cables. "
    "Mathematics of Computation 14, 27-46.",
    "Zajac, E. E. (1957). Dynamics and kinematics of the laying and recovery of submarine cable. "
    "Bell System Technical Journal 36(5), 1129-1207.",
)


def lay_parameters(case: Case) -> LayParameters:
    """Cable, repeater and water data of a ``laying_dynamic`` case."""
    a: LayingDynamicAnalysis = case.analysis
    env, line = case.environment, case.line
    rho, g = env.water_density, env.gravity
    rows = []
    for seg, w in zip(line.segments, sinking_weights(line, rho, g), strict=True):
        lt = seg.line_type
        ea = lt.effective_axial_stiffness() if a.extensible else math.inf
        rows.append(props_row(lt.mass_per_length, w, lt.diameter, *lt.effective_drag(),
                              lt.added_mass_normal * rho * lt.area, lt.added_mass_tangential * rho * lt.area,
                              0.0 if math.isinf(ea) else 1.0 / ea))
    repeaters = tuple(Repeater(s=p.s, mass=p.mass, added_mass=p.added_mass, weight=p.net_weight(rho, g),
                               drag_area=p.drag_area, name=p.name or f"repeater {i + 1}")
                      for i, p in enumerate(line.attachments))
    cur = env.current
    along = math.cos(cur.heading)
    if a.route is None and abs(math.sin(cur.heading)) > 1e-6 and (cur.speed != 0.0 or cur.speeds is not None):
        warnings.warn("laying_dynamic is 2-D without a route: only the current component along the track (x) is "
                      f"used, {along:.3g} of its speed. Suggested fix: give analysis.route to lay in 3-D.",
                      SeacableWarning, stacklevel=3)
    if cur.depths is None:
        depths, speeds = np.zeros(1), np.array([cur.speed])
    else:
        depths, speeds = np.asarray(cur.depths, float), np.asarray(cur.speeds, float)
    if a.route is None:
        velocity = np.column_stack([speeds * along, np.zeros_like(speeds)])               # (along x, vertical)
    else:
        velocity = np.column_stack([speeds * along, speeds * math.sin(cur.heading), np.zeros_like(speeds)])
    return LayParameters(props=np.array(rows), type_ends=np.cumsum([seg.length for seg in line.segments]),
                         segment_length=a.segment_length, cable_length=line.length, repeaters=repeaters,
                         water_density=rho, current_depths=depths, current_velocity=velocity,
                         friction=env.seabed.friction if a.laid_cable == "sliding" else None,
                         friction_distance=a.friction_distance)


def lay_track(case: Case) -> Track2D | Track3D:
    """Where the ship goes and the seabed: 2-D (:func:`lay_seabed`) or, with a route, 3-D over the bathymetry
    by KP, the grid, or a flat environment.depth."""
    a: LayingDynamicAnalysis = case.analysis
    if a.route is None:
        return Track2D(lay_seabed(case))
    route = a.route.geometry()
    depth = case.environment.depth if case.environment.depth is not None else math.nan
    return Track3D(route, seabed_map(route, a.bathymetry, a.bathymetry_grid, depth))


def lay_seabed(case: Case) -> Seabed2D:
    """The seabed along the 2-D track: the bathymetry table, or the environment's depth and slope."""
    a: LayingDynamicAnalysis = case.analysis
    if a.bathymetry is not None:
        x, h = a.bathymetry.table()
        return Seabed2D(x, h)
    reach = case.line.length + 1e4 + 10.0 * a.duration * max(a.ship.speed or 0.0, max(a.ship.speeds or (0.0,)))
    return Seabed2D.plane(case.environment.depth, case.environment.seabed.slope, a.ship.start_x - reach,
                          a.ship.start_x + reach)


@dataclass(frozen=True)
class LayingSetup:
    """What the time loop of a ``laying_dynamic`` case needs, checked (see :func:`prepare_laying_dynamic`)."""

    parameters: LayParameters
    track: Track2D | Track3D
    steps: float            # estimated time steps [1]
    stored_values: float    # estimated values kept for the result [1]
    motion: object = None   # the chute's motion on the vessel's RAOs (seacable.vessel_motion), or None


def _ship_speed_range(case: Case) -> tuple[float, float]:
    """Smallest and largest scheduled ship speed over the run (the schedule is linear between its
    points, so the extremes are at its points inside the run or at its ends). [m/s]"""
    a: LayingDynamicAnalysis = case.analysis
    ship = a.ship
    times = [0.0, a.duration] + [t for t in (ship.times or ()) if 0.0 < t < a.duration]
    speeds = [ship.scheduled(t) for t in times]
    return min(speeds), max(speeds)


def _check_moving_ship(case: Case) -> None:
    """Refuse a ship at rest: the laying theory of the model has no meaning there.

    The run starts from the straight steady lay at the ship speed (paper 001 eq. (7)), the slack is
    the laid length over the distance run minus one and the payout modes 'slack' and
    'bottom_tension' pay out in proportion to the ship speed: with the ship at rest the first is a
    vertical cable with no steady state, the slack is 0/0, and the payout stops.
    """
    a: LayingDynamicAnalysis = case.analysis
    ship = a.ship
    low, _ = _ship_speed_range(case)
    if not low > 0.0:
        where = ("analysis.ship.speed" if ship.times is None else "analysis.ship.speeds")
        raise InputError(
            f"{where}: the ship speed reaches {low:g} m/s during the run (0 to {a.duration:g} s); laying_dynamic "
            "needs a moving ship (> 0 m/s) throughout: the straight-line start (paper 001 eq. (7)) and the slack "
            "(laid length over the distance run) are undefined for a ship at rest, and the slack and bottom-tension "
            "payouts stop with it. Suggested fix: give a ship speed > 0 m/s, e.g. 'ship: {speed: 1.0}', or end "
            "the run (duration) before the ship stops.")
    if ship.repeater_speed is not None and not ship.repeater_speed > 0.0 and case.line.attachments:
        raise InputError(
            f"analysis.ship.repeater_speed must be > 0 m/s, got {ship.repeater_speed:g} m/s: the ship would stop "
            "while a repeater descends, where the laying model is undefined (see analysis.ship.speed). "
            "Suggested fix: give the slow-down speed, e.g. 0.5 m/s, or leave repeater_speed out.")


def prepare_laying_dynamic(case: Case) -> LayingSetup:
    """Every check of a ``laying_dynamic`` case that can be made before the time loop.

    Cable and water data (the cable must sink), the seabed, a moving ship (see
    :func:`_check_moving_ship`) and the size of the run: time steps ``duration / dt`` with the
    time step of the solver at the largest speed (steps end on the output times), and stored values (output times x the largest
    suspended node count x the node and segment variables, plus the time series), checked with
    :func:`seacable._limits.check_run_size`.

    Parameters
    ----------
    case
        A case with a :class:`~seacable.case.LayingDynamicAnalysis`.

    Returns
    -------
    LayingSetup

    Raises
    ------
    InputError
        If the case cannot be run, with the input and a suggested fix.
    """
    a: LayingDynamicAnalysis = case.analysis
    _check_moving_ship(case)
    if a.laid_cable == "held" and case.environment.seabed.friction > 0.0:
        warnings.warn(f"environment.seabed.friction = {case.environment.seabed.friction:g} is not used: the laid cable is "
                      "held where it lands (analysis.laid_cable 'held', the default). Suggested fix: give laid_cable: "
                      "sliding to let it slide against that friction.", SeacableWarning, stacklevel=3)
    if a.laid_cable == "sliding" and not case.environment.seabed.friction > 0.0:
        raise InputError(
            f"analysis.laid_cable 'sliding' needs a friction coefficient > 0, got environment.seabed.friction = "
            f"{case.environment.seabed.friction:g}: without friction nothing holds the laid cable, and the bottom "
            "tension would drag all of it. Suggested fix: give environment.seabed.friction (0.3-1 for cables on sand "
            "and clay), or laid_cable: held.")
    par = lay_parameters(case)
    track = lay_track(case)
    # time steps: dt = l / (n max(V_s, V_c)), at most max_time_step (seacable.laying.solver.simulate)
    _, v_ship = _ship_speed_range(case)
    p = a.payout
    if isinstance(p, PayoutRate):
        v_pay = max([p.speed or 0.0, *(p.speeds or ())])
    elif isinstance(p, PayoutSlack):
        v_pay = (1.0 + p.slack) * v_ship * 1.1      # slope compensation: a few per cent more
    else:
        v_pay = 2.0 * v_ship                         # the bottom-tension controller's ceiling
    dt = min(a.segment_length / (a.steps_per_segment * max(v_ship, v_pay, _MIN_SPEED)), a.max_time_step)
    steps = math.ceil(a.output_interval / dt) * (a.duration / a.output_interval)    # steps end on output times
    # suspended nodes: the straight lay over the deepest seabed at the largest speed (smallest angle),
    # twice that for the curvature under bottom tension, at most the whole cable
    x0, x1 = a.ship.start_x - par.cable_length, a.ship.start_x + v_ship * a.duration
    if isinstance(track, Track2D):
        seabed = track.seabed
        xs = np.concatenate([[x0, x1], seabed.x[(seabed.x > x0) & (seabed.x < x1)]])
        depth = max(float(np.max(-seabed.z(xs))), 0.0)
    else:
        # along the ship's path, every segment length and at the waypoints; a grid must cover it
        route = track.route
        if not route.kp[0] <= a.ship.start_x <= route.kp_end:
            raise InputError(f"analysis.ship.start_x = {a.ship.start_x:.6g} m lies outside the route, which runs from "
                             f"KP {route.kp[0]:.6g} to {route.kp_end:.6g} m (start_x is the ship's KP on a route). "
                             "Suggested fix: a start_x on the route, or route.kp_start for the first waypoint's KP.")
        kp = np.unique(np.concatenate([np.arange(a.ship.start_x, x1, a.segment_length), [x1],
                                       route.kp[(route.kp > a.ship.start_x) & (route.kp < x1)]]))
        track.seabed.check_covers(route.point(kp), "ship's path", kp)
        if x1 > route.kp_end + 1e-6:
            warnings.warn(f"the ship runs past the route's last waypoint (KP {route.kp_end:.6g} m) to KP {x1:.6g} m at its "
                          "largest speed; beyond it, it goes on along the last leg. Suggested fix: shorten "
                          "analysis.duration, or extend the route.", SeacableWarning, stacklevel=3)
        depth = max(float(np.max(track.seabed.depth(route.point(kp)))), 0.0)
    row = par.props[0]
    alpha = float(laying_angle(max(v_ship, _MIN_SPEED), row[P_WEIGHT], row[P_DIAMETER], row[P_CDN],
                               par.water_density))
    suspended = min(2.0 * depth / max(math.sin(alpha), 1e-3), par.cable_length)
    nodes = suspended / a.segment_length + 3.0 + len(par.repeaters)
    outputs = a.duration / a.output_interval + 1.0
    laid = (par.cable_length / a.segment_length + len(par.repeaters)) * 4.0
    stored = outputs * (3.0 * nodes + _N_SERIES + 2.0 * len(par.repeaters)) + laid
    motion = lay_motion(case, track)
    # the starting lay (the straight span and the cable already on the seabed behind it): its line and seabed
    initial_state(par, a.ship, a.payout, track, a.initial_angle, motion)
    check_run_size(f"laying_dynamic case {case.name!r}", steps=steps, stored_values=stored,
                   fix="shorten analysis.duration, lengthen analysis.output_interval or analysis.segment_length, "
                       "or lower analysis.steps_per_segment")
    return LayingSetup(parameters=par, track=track, steps=steps, stored_values=stored, motion=motion)


def lay_motion(case: Case, track):
    """The chute's motion on the vessel's RAOs (``analysis.motion``, :func:`seacable.vessel_motion.bind_vessel_motion`)
    about the ship's track, the vessel heading along the track at the start; None without it."""
    a: LayingDynamicAnalysis = case.analysis
    if a.motion is None:
        return None
    p0 = track.point(a.ship.start_x)
    e = track.direction(a.ship.start_x)
    heading = 0.0 if track.dim == 2 else math.atan2(float(e[1]), float(e[0]))
    start = (float(p0[0]), 0.0) if track.dim == 2 else (float(p0[0]), float(p0[1]))
    motion = bind_vessel_motion(a.motion, case.environment, heading=heading, start=start, duration=a.duration,
                                dims=track.dim)
    sea = sea_of_environment(case.environment)
    period = 2 * math.pi / float(sea.omega[int(np.argmax(sea.amplitude))])
    if a.max_time_step > period / 20.0:
        warnings.warn(f"analysis.max_time_step = {a.max_time_step:g} s is more than 1/20 of the period of the waves "
                      f"that move the chute ({period:.3g} s, the largest component's): the implicit (backward Euler) step damps the chute's "
                      f"motion. Suggested fix: max_time_step <= {period / 20.0:.3g} s.", SeacableWarning, stacklevel=3)
    return motion



def _laid_slack(laid) -> np.ndarray:
    """Slack of each laid segment: its cable length over the seabed distance between its nodes, minus one."""
    p, length = laid["p"], np.diff(laid["s"])
    out = np.full(len(length) + 1, np.nan)
    chord = np.sqrt(np.sum(np.diff(p, axis=0) ** 2, axis=1))
    out[1:] = length / np.where(chord > 0.0, chord, np.nan) - 1.0
    return out


def run_laying_dynamic(case: Case, progress=None):
    """Run a ``laying_dynamic`` case; see :func:`seacable.run`.

    The Dataset has dims ``time``, ``node`` (suspended nodes from the touchdown node, node 0, the
    first node on the seabed counting from the ship, to the water entry; NaN beyond the count at each
    time), ``segment``, ``laid`` (nodes landed, in order, with the cable on the seabed at the start),
    ``seabed_point`` and ``repeater``. ``touchdown_x`` is interpolated between node 0 and node 1 and
    ``layback`` is ``ship_x - touchdown_x``. The case is checked first by
    :func:`prepare_laying_dynamic`.
    """
    a: LayingDynamicAnalysis = case.analysis
    setup = prepare_laying_dynamic(case)
    par, track = setup.parameters, setup.track
    res = simulate(par, a.ship, a.payout, track, a.duration, output_interval=a.output_interval,
                   steps_per_segment=a.steps_per_segment, max_time_step=a.max_time_step,
                   initial_angle=a.initial_angle, slack_window=a.slack_window, tol=a.tolerance,
                   max_iter=a.max_iterations, progress=progress, motion=setup.motion)
    s = res.series
    t1 = "time"
    three = track.dim == 3
    data = {
        "x": var(("time", "node"), res.pos[..., 0], "m", "node x" + ("" if three else " along the track")),
        "z": var(("time", "node"), res.pos[..., -1], "m", "node elevation (z up, 0 at the sea surface)"),
        "tension": var(("time", "segment"), res.tension, "N", "segment tension (0: slack)"),
        "ship_x": var(t1, res.ship[:, 0], "m", "water-entry point x"),
        "ship_speed": var(t1, s["ship_speed"], "m s-1", "ship speed"),
        "payout_speed": var(t1, s["payout_speed"], "m s-1", "payout speed"),
        "paid_out": var(t1, s["paid_out"], "m", "cable paid out since t = 0"),
        "top_tension": var(t1, s["top_tension"], "N", "tension at the water entry"),
        "bottom_tension": var(t1, s["bottom_tension"], "N", "tension at the touchdown"),
        "entry_angle": var(t1, s["entry_angle"], "rad", "cable angle to the sea surface at the water entry"),
        "touchdown_x": var(t1, res.touchdown[:, 0], "m", "touchdown x (interpolated between nodes)"),
        "touchdown_z": var(t1, res.touchdown[:, -1], "m", "touchdown elevation"),
        "layback": var(t1, s["layback"], "m", "layback: horizontal distance from the water entry to the touchdown"),
        "slack": var(t1, s["slack"], "1", "laid length / seabed distance - 1 over the slack window "
                     "(NaN until 3 nodes have landed in the window)"),
        "suspended_length": var(t1, s["suspended_length"], "m", "cable length between touchdown and water entry"),
        "laid_length": var(t1, s["laid_length"], "m", "cable laid since t = 0"),
        "laid_x": var("laid", res.laid["p"][:, 0], "m", "x of the laid nodes"),
        "laid_z": var("laid", res.laid["p"][:, -1], "m", "elevation of the laid nodes"),
        "laid_s": var("laid", res.laid["s"], "m", "arc length of the laid nodes from end A"),
        "laid_time": var("laid", res.laid["time"], "s", "time of touchdown (0: on the seabed at the start)"),
        "laid_slack": var("laid", _laid_slack(res.laid), "1", "cable length over seabed distance minus one, of "
                          "the segment ending at the laid node (NaN for the first)"),
        "laid_tension": var("laid", np.where(res.laid["time"] > 0.0, np.interp(res.laid["time"], res.time,
                                                                              s["bottom_tension"]), np.nan),
                            "N", "bottom tension when the node landed (NaN: on the seabed at the start)"),
        "laid_residual_tension": var("laid", res.laid["T"], "N",
                                     "tension left at the end of the run in the laid segment ending at the node: "
                                     "the tension it landed with, or (laid_cable 'sliding') what the friction holds; "
                                     "0 for the cable on the seabed at the start"),
    }
    if three:
        route = track.route
        td_kp, td_off = route.locate(res.touchdown[:, :2])
        laid_kp, laid_off = route.locate(res.laid["p"][:, :2])
        data.update({
            "y": var(("time", "node"), res.pos[..., 1], "m", "node y"),
            "ship_y": var(t1, res.ship[:, 1], "m", "water-entry point y"),
            "ship_kp": var(t1, s["ship_x"], "m", "ship KP (distance run along the route)"),
            "touchdown_y": var(t1, res.touchdown[:, 1], "m", "touchdown y"),
            "touchdown_kp": var(t1, td_kp, "m", "touchdown KP"),
            "touchdown_offset": var(t1, td_off, "m", "touchdown offset from the route (+ to port)"),
            "laid_y": var("laid", res.laid["p"][:, 1], "m", "y of the laid nodes"),
            "laid_kp": var("laid", laid_kp, "m", "KP of the laid nodes"),
            "laid_offset": var("laid", laid_off, "m", "offset of the laid nodes from the route (+ to port)"),
            **route.variables(),
        })
        for who, dim, xy in (("ship", t1, res.ship[:, :2]), ("touchdown", t1, res.touchdown[:, :2]),
                             ("laid", "laid", res.laid["p"][:, :2])):
            geo = route.to_geographic(xy)           # a route in latitude and longitude: the positions so too
            if geo is not None:
                data[f"{who}_latitude"] = var(dim, geo[0], "degree_north", f"{who} latitude (WGS84)")
                data[f"{who}_longitude"] = var(dim, geo[1], "degree_east", f"{who} longitude (WGS84)")
        kp = np.linspace(min(float(np.nanmin(laid_kp)), float(s["ship_x"][0])), float(np.nanmax(s["ship_x"])), 200)
        data["seabed_kp"] = var("seabed_point", kp, "m", "seabed profile KP (along the route)")
        data["seabed_z"] = var("seabed_point", track.zb(route.point(kp)), "m", "seabed elevation on the route")
    else:
        seabed = track.seabed
        lo = min(float(np.nanmin(res.pos[..., 0])), float(res.laid["p"][0, 0]))
        hi = float(np.nanmax(s["ship_x"]))
        inner = seabed.x[(seabed.x > lo) & (seabed.x < hi)]
        sx = np.concatenate([[lo], inner, [hi]])
        data["seabed_x"] = var("seabed_point", sx, "m", "seabed profile x")
        data["seabed_z"] = var("seabed_point", seabed.z(sx), "m", "seabed profile elevation")
    if par.repeaters:
        data["repeater_x"] = var(("time", "repeater"), res.repeater_pos[..., 0], "m", "repeater x")
        if three:
            data["repeater_y"] = var(("time", "repeater"), res.repeater_pos[..., 1], "m", "repeater y")
        data["repeater_z"] = var(("time", "repeater"), res.repeater_pos[..., -1], "m", "repeater elevation")
        data["repeater_s"] = var("repeater", np.array([r.s for r in sorted(par.repeaters, key=lambda r: r.s)]),
                                 "m", "repeater arc length from end A")
    if setup.motion is not None:
        off = setup.motion(res.time)[0]
        for k, axis in enumerate(("x", "y", "z") if three else ("x", "z")):
            data[f"vessel_motion_{axis}"] = var(t1, off[:, k], "m", f"{axis} offset of the chute from the ship's track "
                                                                     "by the vessel's motion on its RAOs")
    coords = {"time": var("time", res.time, "s", "time")}
    settings = {"segment_length": a.segment_length, "steps_per_segment": a.steps_per_segment,
                "extensible": int(a.extensible), "payout": a.payout.type, "steps": res.steps,
                "newton_iterations": res.iterations, "halved_steps": res.halvings, "lifted_nodes": res.lifts,
                "max_nodes": int(res.pos.shape[1]), "wall_time_s": round(res.wall_time, 4),
                "interrupted": int(res.interrupted), "stop_reason": res.stop_reason,
                "dimensions": track.dim,
                "scheme": "lumped mass, backward Euler with implicit drag, Newton on positions and tensions "
                          f"({track.dim + 1}x{track.dim + 1} block tri-diagonal), slack segments by an active set"}
    ds = make_dataset(data, coords, analysis="laying_dynamic", case=case, references=REFERENCES,
                      settings=settings)
    ds.attrs["interrupted"] = int(res.interrupted)
    return ds

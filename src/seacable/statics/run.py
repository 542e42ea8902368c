"""Runners of the static analyses: a case in, a labelled Dataset out.

Each runner ``run_X`` calls its ``solve_X``, which makes every check and solve that can refuse the case
and builds no Dataset (no xarray): :func:`seacable.simulate.check` (``seacable validate``) calls the same
``solve_X``.

``static`` and ``pushover`` (multi-segment elastic catenary), ``towed_steady`` (paper 000's
steady tow) and ``laying_theory`` (paper 001's straight-line theory).
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..case import Case, LayingTheoryAnalysis, PushoverAnalysis, StaticAnalysis, TowedSteadyAnalysis
from ..errors import InputError, NoSolutionError, SeacableWarning
from ..line import resolve_sections

__all__ = ["line_arrays", "run_laying_theory", "run_pushover", "run_static", "run_towed_steady",
           "solve_laying_theory", "solve_pushover", "solve_static", "solve_towed_steady"]

REF_CATENARY = ("Irvine, H. M. (1981). Cable Structures. MIT Press.",
                "Jonkman, J. M. (2007). Dynamics modeling and loads analysis of an offshore floating wind "
                "turbine. NREL/TP-500-41958, Appendix: quasi-static mooring line model.")
REF_000 = "Paper 000: 3-D nonlinear dynamics of a low-tension towed cable (seeds/000), Table 2."
REF_001 = "Paper 001: 2-D laying simulation of a subsea cable (seeds/001), section 2 and Table 1."


def line_arrays(case: Case):
    """Per-segment arrays of a case's line: lengths, weights, EA, and the point loads.

    Of the equivalent line when the line has sections (:func:`seacable.line.resolve_sections`: smeared buoyancy
    sections as segments of their own, discrete modules as point loads).

    Returns
    -------
    lengths, weights, axial_stiffness : numpy.ndarray
        [m], [N/m], [N] (infinite for an inextensible line type).
    point_loads : tuple of (s, net weight)
        [m], [N].
    """
    env = case.environment
    rho, g = env.water_density, env.gravity
    line = resolve_sections(case.line, rho, g)
    lengths = np.array([seg.length for seg in line.segments])
    weights = np.array(line.weights(rho, g))
    ea = np.array([seg.line_type.effective_axial_stiffness() for seg in line.segments])
    return lengths, weights, ea, line.point_loads(rho, g)


def _spans(case: Case, fairlead) -> tuple[float, float, float, float, bool]:
    ax, az = case.anchor_position()
    fx, fz = fairlead
    depth = case.environment.depth
    on_seabed = depth is not None and abs(az + depth) <= 1e-9 * max(depth, 1.0)
    if depth is not None and az < -depth - 1e-9 * depth:
        raise InputError(f"anchor z must be >= -depth = {-depth:g} m, got {az:g} m. "
                         "Suggested fix: put the anchor on or above the seabed.")
    if fx < ax:
        raise InputError(f"fairlead x must be >= anchor x = {ax:g} m, got {fx:g} m. Suggested fix: "
                         "measure x from the anchor towards the fairlead.")
    return ax, az, fx - ax, fz - az, on_seabed


def equilibrium(case: Case, fairlead):
    from .multisegment import line_equilibrium

    lengths, weights, ea, loads = line_arrays(case)
    ax, az, h, v, on_seabed = _spans(case, fairlead)
    seabed = case.environment.seabed
    eq = line_equilibrium(lengths, weights, ea, h, v, point_loads=loads, seabed=on_seabed,
                          seabed_friction=seabed.friction if on_seabed else 0.0,
                          seabed_slope=seabed.slope if on_seabed else 0.0)
    check_in_water(case, eq, ax, az, on_seabed)
    return eq, ax, az, on_seabed


def _seabed_z(env, x):
    """Seabed elevation under ``x`` (the plane through -depth at x = 0 with its slope, or the profile),
    NaN without a seabed. [m]"""
    x = np.asarray(x, float)
    if env.seabed.profile is not None:
        return -np.interp(x, env.seabed.profile.distance, env.seabed.profile.depth)
    if env.depth is None:
        return np.full_like(x, np.nan)
    return -env.depth + math.tan(env.seabed.slope) * x


def check_in_water(case: Case, eq, ax: float, az: float, on_seabed: bool, where: str = "") -> None:
    """Refuse an equilibrium of the single-line statics that leaves the water.

    The multi-segment catenary weighs every part of the line at its weight in water, and meets the
    seabed only under a line anchored on it. A solution that rises above the sea surface (z = 0), or
    that passes below the seabed where the line has no contact with it, is not the line's equilibrium:
    it is refused (:class:`NoSolutionError`) with where it leaves the water, rather than returned.
    """
    prof = eq.profile(points_per_segment=16)   # the sag and hog bends are among the samples: the extremes
    x, z, s = np.asarray(prof.x) + ax, np.asarray(prof.z) + az, np.asarray(prof.s)
    tol = 1e-6 * max(case.line.length, abs(az), 1.0)
    k = int(np.argmax(z))
    if z[k] > tol:
        seg = int(prof.segment[k])
        weights = line_arrays(case)[1]   # for the message only
        at_end = k in (0, z.size - 1)
        fix = ("run the line as a mooring system (system_static), which weighs the part above the water at its "
               "dry weight; or put the end under water." if at_end else
               "a buoyant part arching above the water would float along the surface, partly immersed, which no "
               "statics here models: keep it under water (less or shorter buoyancy, a shorter line, a deeper "
               "fairlead).")
        raise NoSolutionError(
            f"{where}the line's equilibrium rises {z[k]:.4g} m above the sea surface at s = {s[k]:.6g} m from the "
            f"anchor (segment {seg + 1}, {weights[seg]:.4g} N/m in water), but the single-line statics weighs "
            f"every part of the line at its weight in water, which is wrong in the air. Suggested fix: {fix}")
    if on_seabed:
        return
    bed = _seabed_z(case.environment, x)
    below = bed - z
    if np.any(below > tol):
        k = int(np.nanargmax(below))
        raise NoSolutionError(
            f"{where}the line's equilibrium passes {below[k]:.4g} m below the seabed at s = {s[k]:.6g} m from the "
            f"anchor (x = {x[k]:.6g} m, seabed at z = {bed[k]:.6g} m), but its anchor (z = {az:.6g} m) is above "
            "the seabed, so the single-line statics gives it no contact with the seabed. Suggested fix: put the "
            "anchor on the seabed (z = -depth) so that the line may lie on it, or shorten the line.")


_END_FORCES = {
    "H_fairlead": ("N", "horizontal tension at the fairlead"),
    "V_fairlead": ("N", "vertical tension at the fairlead"),
    "H_anchor": ("N", "horizontal tension at the anchor"),
    "V_anchor": ("N", "vertical tension at the anchor"),
    "fairlead_tension": ("N", "tension at the fairlead"),
    "anchor_tension": ("N", "tension at the anchor"),
    "grounded_length": ("m", "length of line on the seabed"),
}


def solve_static(case: Case):
    """The equilibrium of a ``static`` case and its profile: what :func:`run_static` reports.

    Returns
    -------
    eq, ax, az, on_seabed, prof
        As :func:`equilibrium`, and ``eq.profile`` at the analysis' points per segment.
    """
    a: StaticAnalysis = case.analysis
    eq, ax, az, on_seabed = equilibrium(case, a.fairlead)
    return eq, ax, az, on_seabed, eq.profile(points_per_segment=a.points_per_segment)


def run_static(case: Case):
    from ..results import make_dataset, var

    eq, ax, az, on_seabed, prof = solve_static(case)
    data = {
        "x": var("point", np.asarray(prof.x) + ax, "m", "horizontal position"),
        "z": var("point", np.asarray(prof.z) + az, "m", "elevation (0 at the sea surface)"),
        "tension": var("point", prof.tension, "N", "effective tension"),
        "segment": var("point", prof.segment, "1", "segment index from the anchor"),
        "touchdown_x": var((), float(eq.touchdown_x) + ax, "m", "touchdown position"),
        "stiffness": var(("force", "displacement"), eq.stiffness, "N m-1",
                         "fairlead stiffness d(H, V)/d(x, z)"),
    }
    for name, (units, long_name) in _END_FORCES.items():
        data[name] = var((), float(getattr(eq, name)), units, long_name)
    if case.environment.depth is not None:
        data["seabed_z"] = var((), -case.environment.depth, "m", "seabed elevation under the origin")
    coords = {"s": var("point", prof.s, "m", "unstretched arc length from the anchor"),
              "force": var("force", ["H", "V"], "1", "fairlead force component"),
              "displacement": var("displacement", ["x", "z"], "1", "fairlead displacement component")}
    return make_dataset(data, coords, analysis="static", case=case, references=REF_CATENARY,
                        settings={"solver": "multi-segment elastic catenary, Newton", "seabed": on_seabed})


def solve_pushover(case: Case):
    """The force-excursion curve of a ``pushover`` case: ``(po, offsets, ax)``, the
    :func:`~seacable.statics.multisegment.pushover` result, the offsets [m] and the anchor's x [m]."""
    from .multisegment import pushover

    a: PushoverAnalysis = case.analysis
    lengths, weights, ea, loads = line_arrays(case)
    ax, az, h, v, on_seabed = _spans(case, a.fairlead)
    offsets = np.asarray(a.offset_values(), float)
    if np.any(h + offsets < 0):
        raise InputError(f"offsets must keep the fairlead at x >= the anchor's, got a smallest offset "
                         f"of {offsets.min():g} m with a span of {h:g} m.")
    seabed = case.environment.seabed
    def in_water(eq, offset):
        check_in_water(case, eq, ax, az, on_seabed, where=f"at offset {offset:g} m: ")

    po = pushover(lengths, weights, ea, h, v, offsets, check=in_water, point_loads=loads, seabed=on_seabed,
                  seabed_friction=seabed.friction if on_seabed else 0.0,
                  seabed_slope=seabed.slope if on_seabed else 0.0)
    return po, offsets, ax


def run_pushover(case: Case):
    from ..results import make_dataset, var

    po, offsets, ax = solve_pushover(case)
    data = {
        "H_fairlead": var("offset", po.H_fairlead, "N", "horizontal tension at the fairlead"),
        "V_fairlead": var("offset", po.V_fairlead, "N", "vertical tension at the fairlead"),
        "fairlead_tension": var("offset", po.fairlead_tension, "N", "tension at the fairlead"),
        "touchdown_x": var("offset", np.asarray(po.touchdown_x) + ax, "m", "touchdown position"),
        "grounded_length": var("offset", po.grounded_length, "m", "length of line on the seabed"),
        "stiffness_horizontal": var("offset", po.stiffness_horizontal, "N m-1",
                                    "horizontal fairlead stiffness dH/dx"),
    }
    coords = {"offset": var("offset", offsets, "m", "horizontal fairlead offset")}
    return make_dataset(data, coords, analysis="pushover", case=case, references=REF_CATENARY,
                        settings={"solver": "multi-segment elastic catenary, Newton with continuation"})


def solve_towed_steady(case: Case):
    """The steady tow of a ``towed_steady`` case: ``(res, points, speed, clearance)``, the
    :func:`~seacable.statics.towed.towed_line_steady` result and points, the relative flow speed [m/s]
    (or its profile) and the lowest point's height above the seabed [m] (None without a depth)."""
    from .towed import towed_line_steady

    a: TowedSteadyAnalysis = case.analysis
    env = case.environment
    cur = env.current
    along = math.cos(cur.heading)  # the current's part along the tow (the steady tow is 2-D)
    if cur.depths is None:
        speed = a.vessel_speed - cur.speed * along
    else:  # the relative flow at the profile's depths (the tow point at the surface)
        speed = (np.asarray(cur.depths, float), a.vessel_speed - np.asarray(cur.speeds, float) * along)
    body = a.body
    # the line's end A is the towed end: its segments and attachments from the body up to the tow point
    with warnings.catch_warnings():   # a shape above the tow point is refused below, not warned of
        warnings.filterwarnings("ignore", "part of the towed cable lies", SeacableWarning)
        res, points = towed_line_steady(case.line, speed, water_density=env.water_density, gravity=env.gravity,
                                        body_weight=body.weight_in_water if body else 0.0,
                                        body_drag_area=body.steady_drag_area() if body else 0.0,
                                        body_lift_area=body.lift_area() if body else 0.0,
                                        tangential_drag=a.tangential_drag, n_points=a.n_nodes)
    k = int(np.argmax(res.z))
    if res.z[k] > 1e-6 * max(case.line.length, 1.0):   # the tow point is at the surface: z = 0
        raise NoSolutionError(
            f"towed_steady: the cable at s = {res.s[k]:.6g} m from the lower end rises {res.z[k]:.4g} m above the "
            "tow point, which is at the sea surface, but the steady tow weighs every part at its weight in "
            "water, which is wrong in the air. Suggested fix: less buoyancy in line (floats), a heavier body or "
            "lower end, or a slower tow.")
    clearance = None
    if env.depth is not None:  # the tow point at the surface: z is the depth; the steady tow has no seabed
        k = int(np.argmin(res.z))
        clearance = float(res.z[k]) + float(env.depth)
        if clearance < 0:
            warnings.warn(f"towed_steady: the cable at s = {res.s[k]:g} m from the lower end is {-res.z[k]:g} m deep, "
                          f"below the seabed at {env.depth:g} m (environment.depth); the steady tow has no seabed "
                          "contact, so this shape goes through it. Suggested fix: tow faster, shorten the cable or "
                          "lighten the body.", SeacableWarning, stacklevel=3)
    return res, points, speed, clearance


def run_towed_steady(case: Case):
    from ..results import make_dataset, var

    a: TowedSteadyAnalysis = case.analysis
    res, points, speed, clearance = solve_towed_steady(case)
    at = [i for _, i in points]
    extra = {}
    if clearance is not None:
        extra["seabed_clearance"] = var((), clearance, "m", "lowest point's height above the seabed (negative: "
                                        "through it; the steady tow has no seabed contact)")
    data = {
        "x": var("node", res.x, "m", "position relative to the tow point, positive astern"),
        "z": var("node", res.z, "m", "elevation relative to the tow point"),
        "tension": var("node", res.tension, "N", "effective tension"),
        "angle": var("node", res.angle, "rad", "cable angle to the horizontal"),
        "top_tension": var((), res.top_tension, "N", "tension at the tow point"),
        "top_angle": var((), res.top_angle, "rad", "cable angle below the horizontal at the tow point"),
        "layback": var((), res.layback, "m", "layback of the lower end"),
        "lower_end_depth": var((), res.depth_of_lower_end, "m", "depth of the lower end below the tow point"),
        "critical_angle": var((), res.critical_angle, "rad", "critical angle of the lowest segment"),
        "relative_speed": var((), speed if np.ndim(speed) == 0 else float(np.interp(0.0, *speed)), "m s-1",
                              "flow speed relative to the cable (at the tow point's depth with a current profile)"),
        "point_layback": var("point", res.x[at], "m",
                             "layback of each segment joint and attachment above the lower end"),
        "point_depth": var("point", -res.z[at], "m", "depth of each segment joint and attachment below the tow point"),
        **extra,
    }
    coords = {"s": var("node", res.s, "m", "unstretched arc length from the lower end (a joint's twice)"),
              "point_s": var("point", np.array([p for p, _ in points], float), "m",
                             "arc length of each joint and attachment from the lower end")}
    return make_dataset(data, coords, analysis="towed_steady", case=case, references=(REF_000,),
                        settings={"tangential_drag": a.tangential_drag})


def solve_laying_theory(case: Case):
    """Paper 001's straight-line lay of a ``laying_theory`` case: ``(speeds, exact, small)``, the ship
    speeds [m/s] and the exact and small-angle :func:`~seacable.statics.laying.straight_line_lay` results."""
    from .laying import straight_line_lay

    a: LayingTheoryAnalysis = case.analysis
    env = case.environment
    lt = case.line.segments[0].line_type
    speeds = np.asarray(a.ship_speeds, float)
    common = dict(water_depth=env.depth, ship_speed=speeds,
                  weight_per_length=lt.submerged_weight(env.water_density, env.gravity),
                  diameter=lt.diameter, drag_normal=lt.effective_drag()[0], drag_tangential=lt.effective_drag()[1],
                  payout_speed=speeds * (1.0 + a.slack), bottom_tension=a.bottom_tension,
                  water_density=env.water_density)
    exact = straight_line_lay(**common, method="exact")
    with warnings.catch_warnings():  # the small-angle column is reported beside the exact one on purpose
        warnings.simplefilter("ignore", SeacableWarning)
        small = straight_line_lay(**common, method="small_angle")
    return speeds, exact, small


def run_laying_theory(case: Case):
    from ..results import make_dataset, var

    a: LayingTheoryAnalysis = case.analysis
    speeds, exact, small = solve_laying_theory(case)
    data = {
        "angle": var("ship_speed", exact.angle, "rad", "entry angle (exact root)"),
        "angle_small": var("ship_speed", small.angle, "rad", "entry angle (H/V small-angle)"),
        "layback": var("ship_speed", exact.layback, "m", "layback ship to touchdown"),
        "suspended_length": var("ship_speed", exact.suspended_length, "m", "suspended cable length"),
        "top_tension": var("ship_speed", exact.top_tension, "N", "tension at the ship"),
        "slack": var("ship_speed", exact.slack, "1", "payout speed / ship speed - 1"),
    }
    coords = {"ship_speed": var("ship_speed", speeds, "m s-1", "ship speed")}
    return make_dataset(data, coords, analysis="laying_theory", case=case, references=(REF_001,),
                        settings={"bottom_tension": a.bottom_tension, "slack": a.slack})

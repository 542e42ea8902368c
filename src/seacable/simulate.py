"""The one place that wires line + environment + analysis to a model and a result.

:func:`run` is a pure function of its :class:`~seacable.case.Case`: the same case
gives the same Dataset, and a case can be pickled and sent to another process.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from .case import (
    Case,
    LayingTheoryAnalysis,
    ModalAnalysis,
    PushoverAnalysis,
    StaticAnalysis,
    TowedSteadyAnalysis,
    VerticalModesAnalysis,
)
from .errors import InputError, SeacableWarning
from .results import make_dataset, var

__all__ = ["run", "line_arrays"]

REF_CATENARY = ("Irvine, H. M. (1981). Cable Structures. MIT Press.",
                "Jonkman, J. M. (2007). Dynamics modeling and loads analysis of an offshore floating wind "
                "turbine. NREL/TP-500-41958, Appendix: quasi-static mooring line model.")
REF_000 = "Paper 000: 3-D nonlinear dynamics of a low-tension towed cable (seeds/000), Table 2."
REF_001 = "Paper 001: 2-D laying simulation of a subsea cable (seeds/001), section 2 and Table 1."
REF_002 = "Lee, S.-M. & Kim, Y.-C. (1986). A simple technique to predict the natural frequencies of the " \
          "sagged cable structures. J. Soc. Naval Architects of Korea 23(3)."


def line_arrays(case: Case):
    """Per-segment arrays of a case's line: lengths, weights, EA, and the point loads.

    Returns
    -------
    lengths, weights, axial_stiffness : numpy.ndarray
        [m], [N/m], [N] (infinite for an inextensible line type).
    point_loads : tuple of (s, net weight)
        [m], [N].
    """
    env, line = case.environment, case.line
    rho, g = env.water_density, env.gravity
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


def _equilibrium(case: Case, fairlead):
    from .statics.multisegment import line_equilibrium

    lengths, weights, ea, loads = line_arrays(case)
    ax, az, h, v, on_seabed = _spans(case, fairlead)
    seabed = case.environment.seabed
    eq = line_equilibrium(lengths, weights, ea, h, v, point_loads=loads, seabed=on_seabed,
                          seabed_friction=seabed.friction if on_seabed else 0.0,
                          seabed_slope=seabed.slope if on_seabed else 0.0)
    return eq, ax, az, on_seabed


_END_FORCES = {
    "H_fairlead": ("N", "horizontal tension at the fairlead"),
    "V_fairlead": ("N", "vertical tension at the fairlead"),
    "H_anchor": ("N", "horizontal tension at the anchor"),
    "V_anchor": ("N", "vertical tension at the anchor"),
    "tension_fairlead": ("N", "tension at the fairlead"),
    "tension_anchor": ("N", "tension at the anchor"),
    "grounded_length": ("m", "length of line on the seabed"),
}


def _run_static(case: Case) -> "xr.Dataset":  # noqa: F821
    a: StaticAnalysis = case.analysis
    eq, ax, az, on_seabed = _equilibrium(case, a.fairlead)
    prof = eq.profile(points_per_segment=a.points_per_segment)
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


def _run_pushover(case: Case):
    from .statics.multisegment import pushover

    a: PushoverAnalysis = case.analysis
    lengths, weights, ea, loads = line_arrays(case)
    ax, az, h, v, on_seabed = _spans(case, a.fairlead)
    offsets = np.asarray(a.offset_values(), float)
    if np.any(h + offsets < 0):
        raise InputError(f"offsets must keep the fairlead at x >= the anchor's, got a smallest offset "
                         f"of {offsets.min():g} m with a span of {h:g} m.")
    seabed = case.environment.seabed
    po = pushover(lengths, weights, ea, h, v, offsets, point_loads=loads, seabed=on_seabed,
                  seabed_friction=seabed.friction if on_seabed else 0.0,
                  seabed_slope=seabed.slope if on_seabed else 0.0)
    data = {
        "H_fairlead": var("offset", po.H_fairlead, "N", "horizontal tension at the fairlead"),
        "V_fairlead": var("offset", po.V_fairlead, "N", "vertical tension at the fairlead"),
        "tension_fairlead": var("offset", po.tension_fairlead, "N", "tension at the fairlead"),
        "touchdown_x": var("offset", np.asarray(po.touchdown_x) + ax, "m", "touchdown position"),
        "grounded_length": var("offset", po.grounded_length, "m", "length of line on the seabed"),
        "stiffness_horizontal": var("offset", po.stiffness_horizontal, "N m-1",
                                    "horizontal fairlead stiffness dH/dx"),
    }
    coords = {"offset": var("offset", offsets, "m", "horizontal fairlead offset")}
    return make_dataset(data, coords, analysis="pushover", case=case, references=REF_CATENARY,
                        settings={"solver": "multi-segment elastic catenary, Newton with continuation"})


def _run_modal(case: Case):
    from .modal.eigen import cable_modes

    a: ModalAnalysis = case.analysis
    env = case.environment
    eq, ax, az, on_seabed = _equilibrium(case, a.fairlead)
    line = case.line
    total = line.length
    # Nodes: every segment boundary and attachment, the rest spread by length.
    breaks = sorted(set(line.segment_ends) | {p.s for p in line.attachments})
    s_nodes = [0.0]
    for s0, s1 in zip(breaks[:-1], breaks[1:]):
        k = max(2, int(round(a.n_elements * (s1 - s0) / total)))
        s_nodes.extend(np.linspace(s0, s1, k + 1)[1:])
    s_nodes = np.asarray(s_nodes)
    # Sample the equilibrium densely and interpolate: with ~2000 points a segment the chord error
    # (ds^2/8 times the curvature) is far below the discretisation error of the modal model.
    prof = eq.profile(points_per_segment=2000)

    def at(s, values):
        return np.interp(s, prof.s, values)

    x, z, tension = at(s_nodes, prof.x), at(s_nodes, prof.z), at(s_nodes, prof.tension)
    s_mid = 0.5 * (s_nodes[1:] + s_nodes[:-1])
    seg = np.clip(np.searchsorted(line.segment_ends, s_mid, side="right") - 1, 0, len(line.segments) - 1)
    types = [line.segments[i].line_type for i in seg]
    t_mid = at(s_mid, prof.tension)
    masses = np.zeros(s_nodes.size)
    for p in line.attachments:
        masses[np.argmin(abs(s_nodes - p.s))] += p.mass + p.added_mass
    grounded = np.flatnonzero(s_nodes <= eq.grounded_length + 1e-9) if on_seabed else np.array([0])
    fixed = sorted(set(grounded.tolist()) | {0, s_nodes.size - 1})
    modes = cable_modes(np.column_stack([x, z]), np.diff(s_nodes), t_mid,
                        np.array([t.mass_per_length for t in types]),
                        np.array([t.effective_axial_stiffness() for t in types]),
                        added_mass_per_length=np.array([t.added_mass_per_length(env.water_density)
                                                        for t in types]),
                        point_masses=masses, fixed=tuple(fixed), n_modes=a.n_modes)
    # Paper 002's estimate: a lateral wave's round trip over the suspended line.
    m_eff = np.array([t.mass_per_length + t.added_mass_per_length(env.water_density) for t in types])
    susp = s_mid > eq.grounded_length
    travel = np.sum(np.diff(s_nodes)[susp] / np.sqrt(np.maximum(t_mid[susp], 1e-300) / m_eff[susp]))
    data = {
        "frequency": var("mode", modes.frequency, "Hz", "natural frequency"),
        "period": var("mode", modes.period, "s", "natural period"),
        "plane": var("mode", modes.plane.astype(str), "1", "plane of the mode (in/out)"),
        "shape": var(("mode", "node", "direction"), modes.shape, "1", "mode shape (unit max displacement)"),
        "x": var("node", x + ax, "m", "static horizontal position"),
        "z": var("node", z + az, "m", "static elevation"),
        "tension": var("node", tension, "N", "static tension"),
        "wave_period": var((), 2.0 * travel, "s", "fundamental period from the lateral wave speed (paper 002)"),
    }
    coords = {"s": var("node", s_nodes, "m", "unstretched arc length from the anchor"),
              "mode": var("mode", np.arange(1, modes.frequency.size + 1), "1", "mode number"),
              "direction": var("direction", ["x", "y", "z"], "1", "displacement component")}
    return make_dataset(data, coords, analysis="modal", case=case, references=REF_CATENARY + (REF_002,),
                        settings={"elements": int(s_nodes.size - 1), "mass": "lumped",
                                  "fixed_nodes": len(fixed)})


def _run_towed_steady(case: Case):
    from .statics.towed import towed_cable_steady

    a: TowedSteadyAnalysis = case.analysis
    env = case.environment
    lt = case.line.segments[0].line_type
    cur = env.current
    speed = a.vessel_speed - cur.speed * math.cos(cur.heading)
    body = a.body
    res = towed_cable_steady(case.line.length, lt.submerged_weight(env.water_density, env.gravity),
                             lt.diameter, speed, lt.drag_normal, lt.drag_tangential,
                             water_density=env.water_density, axial_stiffness=lt.axial_stiffness,
                             body_weight=body.weight_in_water if body else 0.0,
                             body_drag_area=body.drag_area if body else 0.0,
                             tangential_drag=a.tangential_drag, n_points=a.n_nodes)
    data = {
        "x": var("node", res.x, "m", "position relative to the tow point, positive astern"),
        "z": var("node", res.z, "m", "elevation relative to the tow point"),
        "tension": var("node", res.tension, "N", "effective tension"),
        "angle": var("node", np.degrees(res.angle), "degree", "cable angle to the horizontal"),
        "top_tension": var((), res.top_tension, "N", "tension at the tow point"),
        "layback": var((), res.layback, "m", "layback of the lower end"),
        "lower_end_depth": var((), res.depth_of_lower_end, "m", "depth of the lower end below the tow point"),
        "critical_angle": var((), math.degrees(res.critical_angle), "degree", "critical angle"),
        "relative_speed": var((), speed, "m s-1", "flow speed relative to the cable"),
    }
    coords = {"s": var("node", res.s, "m", "unstretched arc length from the lower end")}
    return make_dataset(data, coords, analysis="towed_steady", case=case, references=(REF_000,),
                        settings={"tangential_drag": a.tangential_drag})


def _run_laying_theory(case: Case):
    from .statics.laying import straight_line_lay

    a: LayingTheoryAnalysis = case.analysis
    env = case.environment
    lt = case.line.segments[0].line_type
    speeds = np.asarray(a.ship_speeds, float)
    common = dict(water_depth=env.depth, ship_speed=speeds,
                  weight_per_length=lt.submerged_weight(env.water_density, env.gravity),
                  diameter=lt.diameter, drag_normal=lt.drag_normal, drag_tangential=lt.drag_tangential,
                  payout_speed=speeds * (1.0 + a.slack), bottom_tension=a.bottom_tension,
                  water_density=env.water_density)
    exact = straight_line_lay(**common, method="exact")
    with warnings.catch_warnings():  # the small-angle column is reported beside the exact one on purpose
        warnings.simplefilter("ignore", SeacableWarning)
        small = straight_line_lay(**common, method="small_angle")
    data = {
        "angle": var("ship_speed", np.degrees(exact.angle), "degree", "entry angle (exact root)"),
        "angle_small": var("ship_speed", np.degrees(small.angle), "degree", "entry angle (H/V small-angle)"),
        "layback": var("ship_speed", exact.layback, "m", "layback ship to touchdown"),
        "suspended_length": var("ship_speed", exact.suspended_length, "m", "suspended cable length"),
        "top_tension": var("ship_speed", exact.top_tension, "N", "tension at the ship"),
        "slack": var("ship_speed", exact.slack, "1", "payout speed / ship speed - 1"),
    }
    coords = {"ship_speed": var("ship_speed", speeds, "m s-1", "ship speed")}
    return make_dataset(data, coords, analysis="laying_theory", case=case, references=(REF_001,),
                        settings={"bottom_tension": a.bottom_tension, "slack": a.slack})


def _run_vertical_modes(case: Case):
    from .modal.vertical import vertical_cable_frequencies

    a: VerticalModesAnalysis = case.analysis
    env = case.environment
    lt = case.line.segments[0].line_type
    methods = ["string", "exact", "wave"]
    omega = np.array([
        np.asarray(vertical_cable_frequencies(
            case.line.length, a.bottom_tension, lt.mass_per_length,
            lt.added_mass_per_length(env.water_density), method=m, n_modes=a.n_modes,
            weight_per_length=lt.submerged_weight(env.water_density, env.gravity),
            gravity=env.gravity)).reshape(-1)
        for m in methods])
    data = {"period": var(("solution", "mode"), 2 * np.pi / omega, "s", "natural period"),
            "frequency": var(("solution", "mode"), omega / (2 * np.pi), "Hz", "natural frequency")}
    coords = {"solution": var("solution", methods, "1", "string (row A), exact Bessel (B), wave eq. 15 (C)"),
              "mode": var("mode", np.arange(1, a.n_modes + 1), "1", "mode number")}
    return make_dataset(data, coords, analysis="vertical_modes", case=case, references=(REF_002,))


def _run_towed_dynamic(case: Case, progress=None):
    from .towed.run import run_towed_dynamic

    return run_towed_dynamic(case, progress=progress)


def _run_laying_dynamic(case: Case, progress=None):
    from .laying.run import run_laying_dynamic

    return run_laying_dynamic(case, progress=progress)


def _run_mooring_static(case: Case):
    from .mooring.run import run_mooring_static

    return run_mooring_static(case)


def _run_mooring_pushover(case: Case):
    from .mooring.run import run_mooring_pushover

    return run_mooring_pushover(case)


def _run_mooring_dynamic(case: Case, progress=None):
    from .mooring.run import run_mooring_dynamic

    return run_mooring_dynamic(case, progress=progress)


def _run_towline_dynamic(case: Case, progress=None):
    from .towline.run import run_towline_dynamic

    return run_towline_dynamic(case, progress=progress)


_RUNNERS = {
    "static": _run_static,
    "pushover": _run_pushover,
    "modal": _run_modal,
    "towed_steady": _run_towed_steady,
    "towed_dynamic": _run_towed_dynamic,
    "laying_theory": _run_laying_theory,
    "laying_dynamic": _run_laying_dynamic,
    "vertical_modes": _run_vertical_modes,
    "mooring_static": _run_mooring_static,
    "mooring_pushover": _run_mooring_pushover,
    "mooring_dynamic": _run_mooring_dynamic,
    "towline_dynamic": _run_towline_dynamic,
}


def run(case: Case, progress=None):
    """Run a case and return its result.

    Parameters
    ----------
    case
        A validated case, from :func:`seacable.load_case` or built in code.
    progress
        Optional ``progress(t, duration)`` callback of time-domain analyses, called as the
        simulation advances (the CLI prints a progress line with it). [s]

    Returns
    -------
    xarray.Dataset
        Labelled result with units, long names and provenance; its ``analysis``
        attribute names the analysis type.
    """
    if not isinstance(case, Case):
        raise InputError(f"run() takes a seacable.Case, got {type(case).__name__}. "
                         "Suggested fix: seacable.load_case('file.yaml') or seacable.Case(...).")
    runner = _RUNNERS[case.analysis.type]
    if progress is not None and case.analysis.type in _TIME_DOMAIN:
        return runner(case, progress=progress)
    return runner(case)


_TIME_DOMAIN = ("towed_dynamic", "laying_dynamic", "mooring_dynamic", "towline_dynamic")

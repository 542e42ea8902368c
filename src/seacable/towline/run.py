"""The ``towline_dynamic`` analysis of a case as a Dataset (paper 003)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._limits import check_run_size
from .._validate import in_range
from ..case import Case, TowlineDynamicAnalysis
from ..errors import InputError
from ..results import make_dataset, var
from ..towed.vessel import initial_heading, sample_path
from .solver import (
    State,
    TowlineModel,
    TowlineRun,
    check_time_step,
    initial_state,
    simulate,
    stable_time_step,
)

__all__ = ["REFERENCES", "PreparedTowline", "case_model", "prepare_towline_dynamic", "run_result",
           "run_towline_dynamic"]

#: Largest plausible sizes [m]: a towline longer than this, or a barge larger, is taken for a unit
#: mistake (the largest ships afloat are about 460 m long and 70 m wide, 30 m deep in draft).
MAX_LINE_LENGTH = 20_000.0
MAX_BARGE = {"length": 1000.0, "beam": 200.0, "draft": 50.0}
MAX_TOW_POINT_HEIGHT = 100.0

#: Node and element values stored per output time (x, y, z, tension, slack; 3 centres, released)
_PER_NODE, _PER_ELEMENT, _PER_TIME = 5, 4, 10

REFERENCES = (
    ("Paper 003: Yoon, H.-K., Lee, H.-S., Park, J.-K. & Kim, Y.-K. (2011). Modelling and simulation of towline "
     "dynamics by multibody element theory. KINPR spring conference (seeds/003)."),
    "Fossen, T. I. (2011). Handbook of Marine Craft Hydrodynamics and Motion Control. Wiley (barge model).",
    "Newman, J. N. (1977). Marine Hydrodynamics. MIT Press, section 4.13 (Kirchhoff's equations, Munk moment).",
)


def case_model(case: Case) -> TowlineModel:
    """The towline model of a case (SI)."""
    a: TowlineDynamicAnalysis = case.analysis
    lt = case.line.segments[0].line_type
    ea = lt.axial_stiffness if a.elongation_at_break is None else lt.breaking_load / a.elongation_at_break
    env = case.environment
    return TowlineModel(
        n_elements=a.n_elements, length=case.line.length, diameter=lt.diameter, mass_per_length=lt.mass_per_length,
        axial_stiffness=ea, drag_normal=lt.effective_drag()[0], drag_tangential=lt.effective_drag()[1],
        added_mass=lt.added_mass_normal, damping_ratio=a.damping_ratio, bending_damping_ratio=a.bending_damping_ratio,
        transverse_damping_fraction=a.transverse_damping_fraction, water_density=env.water_density,
        gravity=env.gravity, brake_tension=a.brake_tension, impact=a.impact,
        barge=a.barge, held=a.barge_held, depth=env.depth, seabed_stiffness=a.seabed_contact.stiffness,
        seabed_damping=a.seabed_contact.damping, friction=env.seabed.friction,
        friction_velocity=a.seabed_contact.friction_velocity)


def _tug(case: Case):
    a = case.analysis

    def track(times):
        p, v = sample_path(a.tug, np.atleast_1d(np.asarray(times, float)))
        p = p.copy()
        p[:, 2] = a.tug_tow_point_height
        v = v.copy()
        v[:, 2] = 0.0
        return p, v

    return track


def _check_sizes(case: Case) -> None:
    """The line and barge dimensions must be finite and physically plausible."""
    a: TowlineDynamicAnalysis = case.analysis
    fix = "give the sizes in metres (SI), not millimetres or feet."
    in_range("line.length", case.line.length, 0.0, MAX_LINE_LENGTH, "m",
             f"a towline is at most a few km long; {fix}")
    in_range("analysis.tug_tow_point_height", a.tug_tow_point_height, -MAX_TOW_POINT_HEIGHT,
             MAX_TOW_POINT_HEIGHT, "m", f"give the height of the tug's tow point above the water; {fix}")
    b = a.barge
    for key, top in MAX_BARGE.items():
        in_range(f"analysis.barge.{key}", getattr(b, key), 0.0, top, "m",
                 f"the largest ships afloat are about 460 m long, 70 m wide and 30 m deep; {fix}")
    in_range("analysis.barge.tow_point_height", b.tow_point_height, -MAX_TOW_POINT_HEIGHT,
             MAX_TOW_POINT_HEIGHT, "m", fix)
    in_range("analysis.barge.tow_point_x", b.tow_x, -MAX_BARGE["length"], MAX_BARGE["length"], "m",
             f"give it forward of midship, within a barge length; {fix}")
    in_range("analysis.barge.yaw_radius_of_gyration", b.gyradius, 0.0, b.length, "m",
             "about 0.25 * length for a barge (paper 003)")
    depth = case.environment.depth
    if depth is not None and b.draft >= depth:
        raise InputError(f"analysis.barge.draft must be less than environment.depth = {depth:g} m, got "
                         f"{b.draft:g} m: the barge would sit on the seabed. Suggested fix: check the draft and "
                         "the depth (both in metres).")


@dataclass(frozen=True)
class PreparedTowline:
    """What the time loop of a towline run needs: the model, the tug's track, the initial heading and
    state, and the explicit time step."""

    model: TowlineModel
    tug: object
    heading: float
    state: State
    time_step: float


def prepare_towline_dynamic(case: Case) -> PreparedTowline:
    """Every check of a ``towline_dynamic`` case that can be made before its time loop.

    The line and barge sizes (finite and plausible), the model (stiffness, time step against the
    stability bound), the tug's track over the whole run (a table must cover it), the initial
    heading (from the tug's displacement, :func:`seacable.towed.vessel.initial_heading`), the
    initial state (the tow points' heights against the line's length) and the size of the run
    (:func:`seacable._limits.check_run_size`). With ``environment.depth`` the line has seabed contact (flat,
    ``environment.seabed.slope`` is refused).

    Raises
    ------
    InputError
        Naming the input, as :func:`run_towline_dynamic` would before its first step.
    """
    a: TowlineDynamicAnalysis = case.analysis
    _check_sizes(case)
    model = case_model(case)
    # the explicit step: the given one, not above the stability bound, or a fraction of the bound
    check_time_step(model, a.time_step)
    dt = stable_time_step(model) if a.time_step is None else float(a.time_step)
    sub = max(1, math.ceil(a.output_interval / dt - 1e-9))
    n_out = round(a.duration / a.output_interval)
    n = model.n_elements
    check_run_size(f"towline_dynamic case '{case.name}'", steps=n_out * sub,
                   stored_values=(n_out + 1) * ((n + 1) * _PER_NODE + n * _PER_ELEMENT + _PER_TIME),
                   fix="shorten analysis.duration, lengthen analysis.output_interval or use fewer elements")
    tug = _tug(case)
    tug(np.array([0.0, a.duration]))  # a table too short fails here, before the run
    # the line lies astern of where the tug goes: the direction of its first displacement
    heading = initial_heading(a.tug, a.duration, distance=1e-3 * model.length)
    p0, _ = tug(np.array([0.0]))
    state = initial_state(model, p0[0], start=a.start, heading=heading, drop_height=a.drop_height)
    return PreparedTowline(model, tug, heading, state, dt)


def run_result(model: TowlineModel, run: TowlineRun, *, case=None, settings=None):
    """The Dataset of a towline run (dims ``time``, ``node`` from the tug, ``element``)."""
    t = ("time",)
    tn, te = ("time", "node"), ("time", "element")
    n = model.n_elements
    speed = np.hypot(run.barge[:, 3], run.barge[:, 4])
    data = {
        "x": var(tn, run.nodes[..., 0], "m", "joint x (node 0: tug tow point, last: barge tow point)"),
        "y": var(tn, run.nodes[..., 1], "m", "joint y"),
        "z": var(tn, run.nodes[..., 2], "m", "joint z (up, 0 at the water surface)"),
        "tension": var(tn, run.tension, "N", "joint tension along the line"),
        "slack": var(tn, run.slack, "1", "joint slack (no tension)"),
        "top_tension": var(t, run.tension[:, 0], "N", "towline tension at the tug"),
        "barge_tension": var(t, run.tension[:, n], "N", "towline tension at the barge"),
        "element_x": var(te, run.centres[..., 0], "m", "element centre x"),
        "element_y": var(te, run.centres[..., 1], "m", "element centre y"),
        "element_z": var(te, run.centres[..., 2], "m", "element centre z"),
        "released": var(te, run.released, "1", "element off the bitt"),
        "tug_x": var(t, run.tug[:, 0], "m", "tug tow point x"),
        "tug_y": var(t, run.tug[:, 1], "m", "tug tow point y"),
        "barge_x": var(t, run.barge[:, 0], "m", "barge midship x"),
        "barge_y": var(t, run.barge[:, 1], "m", "barge midship y"),
        "barge_heading": var(t, run.barge[:, 2], "rad", "barge heading from +x"),
        "barge_speed": var(t, speed, "m s-1", "barge speed through the water"),
    }
    coords = {"time": var("time", run.time, "s", "time"), "node": var("node", np.arange(n + 1), "1", "joint"),
              "element": var("element", np.arange(n), "1", "element")}
    depth = None if case is None else case.environment.depth
    if depth is not None:
        data["seabed_clearance"] = var(t, np.nanmin(run.nodes[..., 2], axis=1) + depth,
                                       "m", "least height of a joint above the seabed (contact modelled: a joint on "
                                            "it is pressed in by the line's weight over the contact stiffness)")
    ds = make_dataset(data, coords, analysis="towline_dynamic", case=case, references=REFERENCES,
                      settings={"time_step": run.time_step, "steps": run.steps,
                                "element_period": model.element_period, **(settings or {})})
    ds.attrs["n_elements"] = n
    ds.attrs["element_length"] = model.element_length
    ds.attrs["interrupted"] = int(run.interrupted)
    ds.attrs["wall_time"] = run.wall_time
    return ds


def run_towline_dynamic(case: Case, progress=None):
    """Time-domain towline run (analysis ``towline_dynamic``)."""
    a: TowlineDynamicAnalysis = case.analysis
    prep = prepare_towline_dynamic(case)
    run = simulate(prep.model, prep.tug, a.duration, a.output_interval, prep.state, time_step=a.time_step,
                   progress=progress)
    ds = run_result(prep.model, run, case=case, settings={"start": a.start, "damping_ratio": a.damping_ratio,
                                                          "initial_heading": prep.heading})
    ds.attrs["scenario"] = case.description or case.name
    return ds

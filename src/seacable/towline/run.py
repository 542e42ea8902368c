"""The ``towline_dynamic`` analysis of a case as a Dataset (paper 003)."""

from __future__ import annotations

import numpy as np

from ..case import Case, TowlineDynamicAnalysis
from ..results import make_dataset, var
from ..towed.vessel import sample_path
from .solver import TowlineModel, TowlineRun, initial_state, simulate

__all__ = ["REFERENCES", "case_model", "run_result", "run_towline_dynamic"]

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
        axial_stiffness=ea, drag_normal=lt.drag_normal, drag_tangential=lt.drag_tangential,
        added_mass=lt.added_mass_normal, damping_ratio=a.damping_ratio, bending_damping_ratio=a.bending_damping_ratio,
        transverse_damping_fraction=a.transverse_damping_fraction, water_density=env.water_density,
        gravity=env.gravity, brake_tension=a.brake_tension, impact=a.impact,
        barge=a.barge, held=a.barge_held)


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
    model = case_model(case)
    tug = _tug(case)
    p0, v0 = tug(np.array([0.0, a.duration]))
    heading = float(np.arctan2(v0[0, 1], v0[0, 0])) if np.hypot(*v0[0, :2]) > 0 else getattr(a.tug, "heading", 0.0)
    state = initial_state(model, p0[0], start=a.start, heading=heading, drop_height=a.drop_height)
    run = simulate(model, tug, a.duration, a.output_interval, state, time_step=a.time_step, progress=progress)
    ds = run_result(model, run, case=case, settings={"start": a.start, "damping_ratio": a.damping_ratio})
    ds.attrs["scenario"] = case.description or case.name
    return ds

"""The ``towed_dynamic`` analysis: a case in, a labelled xarray Dataset out."""

from __future__ import annotations

import functools

import numpy as np

from ..case import Case, TowedDynamicAnalysis
from ..errors import InputError
from ..results import make_dataset, var
from .equations import I_OB, I_ON, I_PH, I_SB, I_SN, I_T, I_TH, I_VB, I_VN, I_VT
from .solver import TowedBodyParameters, cable_parameters, simulate
from .vessel import sample_path

__all__ = ["run_towed_dynamic", "case_setup"]

REFERENCES = (
    "Paper 000: Park, H. I. & Jung, D. H., nonlinear dynamic analysis of a low-tension towed cable by the "
    "finite difference method (seeds/000): eq. (2)-(21), Tables 1-3, Fig. 4-6.",
    "Ablow, C. M. & Schechter, S. (1983). Numerical simulation of undersea cable dynamics. Ocean Eng. 10(6).",
    "Gobat, J. I. & Grosenbaugh, M. A. (2006). Time-domain numerical simulation of ocean cable structures. "
    "Ocean Eng. 33, 1373-1400.",
)


def case_setup(case: Case):
    """Parameter vector, node count, vessel path (callable), body and solver keywords of a case."""
    a: TowedDynamicAnalysis = case.analysis
    env = case.environment
    if len(case.line.segments) != 1 or case.line.attachments:
        raise InputError(
            f"towed_dynamic models a uniform cable, but the line has {len(case.line.segments)} segment(s) "
            f"and {len(case.line.attachments)} attachment(s). Suggested fix: give one line type and put a "
            "weight at the lower end as 'analysis.body'.")
    lt = case.line.segments[0].line_type
    par = cable_parameters(
        case.line.length, a.n_nodes, lt.mass_per_length, lt.submerged_weight(env.water_density, env.gravity),
        lt.diameter, axial_stiffness=lt.effective_axial_stiffness(), bending_stiffness=lt.bending_stiffness,
        drag_normal=lt.drag_normal, drag_tangential=lt.drag_tangential, added_mass_normal=lt.added_mass_normal,
        added_mass_tangential=lt.added_mass_tangential, water_density=env.water_density,
        tangential_drag=a.tangential_drag)
    body = None
    if a.body is not None:
        body = TowedBodyParameters(mass=a.body.mass, added_mass=a.body.added_mass,
                                   weight_in_water=a.body.weight_in_water, drag_area=a.body.drag_area)
    path = functools.partial(sample_path, a.vessel)
    path(np.array([0.0, a.duration]))  # a table too short fails here, before the run
    kwargs = dict(output_interval=a.output_interval, current=env.current, body=body,
                  water_density=env.water_density, current_follows_vessel=a.current_follows_vessel,
                  tol=a.tolerance, max_iter=a.max_iterations)
    return par, a.n_nodes, path, kwargs


def run_towed_dynamic(case: Case, progress=None):
    """Run a ``towed_dynamic`` case; see :func:`seacable.run`.

    The Dataset has dims ``time`` and ``node`` (node 0 at the lower end, the last at the vessel),
    coordinate ``s`` (unstretched arc length from the lower end) and the positions, forces,
    curvatures, velocities and angles of every node, plus ``top_tension`` and the vessel track.
    An interrupted run (Ctrl-C) returns what it computed, with the attribute ``interrupted = 1``.
    """
    a: TowedDynamicAnalysis = case.analysis
    par, n, path, kwargs = case_setup(case)
    res = simulate(par, n, path, a.duration, a.time_step, progress=progress, **kwargs)
    h, pos, vel = res.state, res.position, res.velocity
    td = ("time", "node")
    data = {
        "x": var(td, pos[..., 0], "m", "node position X"),
        "y": var(td, pos[..., 1], "m", "node position Y"),
        "z": var(td, pos[..., 2], "m", "node elevation (Z up, 0 at the sea surface)"),
        "tension": var(td, h[..., I_T], "N", "effective tension"),
        "shear_n": var(td, h[..., I_SN], "N", "shear force, normal direction"),
        "shear_b": var(td, h[..., I_SB], "N", "shear force, binormal direction"),
        "curvature_n": var(td, h[..., I_ON], "m-1", "curvature about the normal, d(theta)/ds"),
        "curvature_b": var(td, h[..., I_OB], "m-1", "curvature about the binormal, cos(theta) d(phi)/ds"),
        "velocity_t": var(td, h[..., I_VT], "m s-1", "cable velocity, tangential component"),
        "velocity_n": var(td, h[..., I_VN], "m s-1", "cable velocity, normal component"),
        "velocity_b": var(td, h[..., I_VB], "m s-1", "cable velocity, binormal component"),
        "velocity_x": var(td, vel[..., 0], "m s-1", "cable velocity X"),
        "velocity_y": var(td, vel[..., 1], "m s-1", "cable velocity Y"),
        "velocity_z": var(td, vel[..., 2], "m s-1", "cable velocity Z"),
        "azimuth": var(td, np.degrees(h[..., I_PH]), "degree", "tangent azimuth phi, from X towards Y"),
        "inclination": var(td, np.degrees(h[..., I_TH]), "degree",
                           "tangent angle theta below the horizontal (negative: rising to the vessel)"),
        "top_tension": var("time", h[:, -1, I_T], "N", "tension at the vessel"),
        "lower_end_depth": var("time", -pos[:, 0, 2], "m", "depth of the lower end below the surface"),
        "vessel_x": var("time", res.vessel_position[:, 0], "m", "tow point X"),
        "vessel_y": var("time", res.vessel_position[:, 1], "m", "tow point Y"),
    }
    coords = {"time": var("time", res.time, "s", "time"),
              "s": var("node", res.s, "m", "unstretched arc length from the lower end")}
    settings = dict(res.settings)
    settings.update({"n_nodes": n, "newton_iterations": res.iterations, "steps": res.steps,
                     "halved_steps": res.halvings, "wall_time_s": round(res.wall_time, 4),
                     "interrupted": int(res.interrupted), "tangential_drag": a.tangential_drag,
                     "current_follows_vessel": int(a.current_follows_vessel),
                     "scheme": "box (centred in s and t), Newton-Raphson, block tri-diagonal solve"})
    ds = make_dataset(data, coords, analysis="towed_dynamic", case=case, references=REFERENCES,
                      settings=settings)
    ds.attrs["interrupted"] = int(res.interrupted)
    return ds

"""Runners of the modal analyses: ``modal`` (eigen-analysis of a line about its static shape) and
``vertical_modes`` (paper 002's vertical cable)."""

from __future__ import annotations

import numpy as np

from ..case import Case, ModalAnalysis, VerticalModesAnalysis
from ..results import make_dataset, var
from ..statics.run import REF_CATENARY, equilibrium

__all__ = ["run_modal", "run_vertical_modes"]

REF_002 = "Lee, S.-M. & Kim, Y.-C. (1986). A simple technique to predict the natural frequencies of the " \
          "sagged cable structures. J. Soc. Naval Architects of Korea 23(3)."


def run_modal(case: Case):
    from .eigen import cable_modes

    a: ModalAnalysis = case.analysis
    env = case.environment
    eq, ax, az, on_seabed = equilibrium(case, a.fairlead)
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


def run_vertical_modes(case: Case):
    from .vertical import vertical_cable_frequencies

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

"""Runners of the modal analyses: ``modal`` (eigen-analysis of a line about its static shape) and
``vertical_modes`` (paper 002's vertical cable).

Each runner ``run_X`` calls its ``solve_X``, which makes every check and solve that can refuse the case
and builds no Dataset (no xarray): :func:`seacable.simulate.check` (``seacable validate``) calls the same
``solve_X``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..case import Case, ModalAnalysis, VerticalModesAnalysis
from ..errors import InputError
from ..statics.run import REF_CATENARY, equilibrium, line_arrays

__all__ = ["ModalSolution", "run_modal", "run_vertical_modes", "solve_modal", "solve_vertical_modes"]

REF_002 = "Lee, S.-M. & Kim, Y.-C. (1986). A simple technique to predict the natural frequencies of the " \
          "sagged cable structures. J. Soc. Naval Architects of Korea 23(3)."


def _node_arcs(line, n_elements):
    """Node arc lengths from end A: every segment boundary and attachment, the rest spread by length."""
    breaks = sorted(set(line.segment_ends) | {p.s for p in line.attachments})
    s_nodes = [0.0]
    for s0, s1 in zip(breaks[:-1], breaks[1:]):
        k = max(2, int(round(n_elements * (s1 - s0) / line.length)))
        s_nodes.extend(np.linspace(s0, s1, k + 1)[1:])
    return np.asarray(s_nodes)


def _hanging(case: Case, s_nodes, s_mid):
    """A line hanging straight down from the fairlead, end A free: node (x, z) and tensions.

    The tension at ``s`` is the weight in water of everything below it (line and attachments); each
    element stretches by its mid-element tension (exact for the linear tension of a uniform element).
    """
    a: ModalAnalysis = case.analysis
    env, line = case.environment, case.line
    lengths, weights, ea, loads = line_arrays(case)
    ends = np.concatenate([[0.0], np.cumsum(lengths)])

    def tension(s):
        s = np.asarray(s, float)
        below = np.zeros_like(s)
        for k, w in enumerate(weights):
            below += w * np.clip(s - ends[k], 0.0, lengths[k])
        for sp, weight in loads:
            below += np.where(s > sp, weight, 0.0)
        return below

    t_mid = tension(s_mid)
    if np.any(t_mid <= 0):
        i = int(np.argmax(t_mid <= 0))
        raise InputError(
            f"analysis.free_end: a hanging line needs weight below every point, but the tension at "
            f"s = {s_mid[i]:g} m (from the free end) is {t_mid[i]:.4g} N: the line or its attachments float. "
            "Suggested fix: give the line types their weight in water, or model the line between two ends.")
    seg = np.clip(np.searchsorted(line.segment_ends, s_mid, side="right") - 1, 0, len(lengths) - 1)
    stretched = np.diff(s_nodes) * (1.0 + t_mid / ea[seg])
    fx, fz = a.fairlead
    z = fz - np.concatenate([np.cumsum(stretched[::-1])[::-1], [0.0]])
    depth = env.depth
    if depth is not None and z[0] < -depth:
        raise InputError(f"analysis.free_end: the line hanging from the fairlead at z = {fz:g} m reaches "
                         f"z = {z[0]:.4g} m, below the seabed at {-depth:g} m. Suggested fix: a shorter line, "
                         "a higher fairlead, or the line between an anchor and the fairlead (free_end: false).")
    return np.full(s_nodes.size, float(fx)), z, tension(s_nodes), t_mid


@dataclass(frozen=True)
class ModalSolution:
    """What :func:`solve_modal` finds and :func:`run_modal` reports."""

    modes: object            # the :func:`~seacable.modal.eigen.cable_modes` result
    s_nodes: np.ndarray      # node arc lengths from end A [m]
    x: np.ndarray            # static node positions relative to the anchor [m]
    z: np.ndarray
    tension: np.ndarray      # static node tensions [N]
    ax: float                # the anchor's position [m]
    az: float
    fixed: list              # the fixed nodes
    travel: float            # a lateral wave's travel time over the suspended line [s]


def solve_modal(case: Case) -> ModalSolution:
    """The static shape and the modes of a ``modal`` case: every check and solve of :func:`run_modal`."""
    from .eigen import cable_modes

    a: ModalAnalysis = case.analysis
    env = case.environment
    line = case.line
    s_nodes = _node_arcs(line, a.n_elements)
    s_mid = 0.5 * (s_nodes[1:] + s_nodes[:-1])
    if a.free_end:
        x, z, tension, t_mid = _hanging(case, s_nodes, s_mid)
        ax = az = 0.0
        grounded_length = 0.0
        fixed = [s_nodes.size - 1]
    else:
        eq, ax, az, on_seabed = equilibrium(case, a.fairlead)
        # Sample the equilibrium densely and interpolate: with ~2000 points a segment the chord error
        # (ds^2/8 times the curvature) is far below the discretisation error of the modal model.
        prof = eq.profile(points_per_segment=2000)

        def at(s, values):
            return np.interp(s, prof.s, values)

        x, z, tension = at(s_nodes, prof.x), at(s_nodes, prof.z), at(s_nodes, prof.tension)
        t_mid = at(s_mid, prof.tension)
        grounded_length = eq.grounded_length
        grounded = np.flatnonzero(s_nodes <= grounded_length + 1e-9) if on_seabed else np.array([0])
        fixed = sorted(set(grounded.tolist()) | {0, s_nodes.size - 1})
    seg = np.clip(np.searchsorted(line.segment_ends, s_mid, side="right") - 1, 0, len(line.segments) - 1)
    types = [line.segments[i].line_type for i in seg]
    masses = np.zeros(s_nodes.size)
    for p in line.attachments:
        masses[np.argmin(abs(s_nodes - p.s))] += p.mass + p.added_mass
    modes = cable_modes(np.column_stack([x, z]), np.diff(s_nodes), t_mid,
                        np.array([t.mass_per_length for t in types]),
                        np.array([t.effective_axial_stiffness() for t in types]),
                        added_mass_per_length=np.array([t.added_mass_per_length(env.water_density)
                                                        for t in types]),
                        point_masses=masses, fixed=tuple(fixed), n_modes=a.n_modes)
    # Paper 002's estimate: a lateral wave's round trip over the suspended line.
    m_eff = np.array([t.mass_per_length + t.added_mass_per_length(env.water_density) for t in types])
    susp = s_mid > grounded_length
    travel = np.sum(np.diff(s_nodes)[susp] / np.sqrt(np.maximum(t_mid[susp], 1e-300) / m_eff[susp]))
    return ModalSolution(modes, s_nodes, x, z, tension, ax, az, fixed, travel)


def run_modal(case: Case):
    from ..results import make_dataset, var

    sol = solve_modal(case)
    modes, s_nodes, x, z, tension, ax, az, fixed, travel = (
        sol.modes, sol.s_nodes, sol.x, sol.z, sol.tension, sol.ax, sol.az, sol.fixed, sol.travel)
    a: ModalAnalysis = case.analysis
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
    coords = {"s": var("node", s_nodes, "m", "unstretched arc length from end A (the anchor, or the free end)"),
              "mode": var("mode", np.arange(1, modes.frequency.size + 1), "1", "mode number"),
              "direction": var("direction", ["x", "y", "z"], "1", "displacement component")}
    return make_dataset(data, coords, analysis="modal", case=case, references=REF_CATENARY + (REF_002,),
                        settings={"elements": int(s_nodes.size - 1), "mass": "lumped",
                                  "fixed_nodes": len(fixed), "free_end": int(a.free_end)})


#: What each solution of ``vertical_modes`` is, and the tension it uses (paper 002, Table 1).
VERTICAL_SOLUTIONS = {
    "string": "uniform string at the bottom tension T0, gravity neglected: T1 = 2 L sqrt(M / T0) "
              "(Table 1 row A)",
    "exact": "exact Bessel solution, tension T0 + w z growing up from the bottom (row B; T0 = 0: the "
             "hanging chain, lower end free)",
    "wave": "round trip of a lateral wave in the tension T0 + w z, eq. (15) (row C)",
}


def solve_vertical_modes(case: Case):
    """Paper 002's frequencies of a ``vertical_modes`` case: ``(methods, omega)``, the solutions and their
    angular frequencies [rad/s] (one row a solution, one column a mode)."""
    from .vertical import vertical_cable_frequencies

    a: VerticalModesAnalysis = case.analysis
    env = case.environment
    lt = case.line.segments[0].line_type
    methods = list(a.solutions())
    omega = np.array([
        np.asarray(vertical_cable_frequencies(
            case.line.length, a.bottom_tension, lt.mass_per_length,
            lt.added_mass_per_length(env.water_density), method=m, n_modes=a.n_modes,
            weight_per_length=lt.submerged_weight(env.water_density, env.gravity),
            gravity=env.gravity)).reshape(-1)
        for m in methods])
    return methods, omega


def run_vertical_modes(case: Case):
    from ..results import make_dataset, var

    a: VerticalModesAnalysis = case.analysis
    methods, omega = solve_vertical_modes(case)
    data = {"period": var(("solution", "mode"), 2 * np.pi / omega, "s", "natural period"),
            "frequency": var(("solution", "mode"), omega / (2 * np.pi), "Hz", "natural frequency"),
            "description": var("solution", np.array([VERTICAL_SOLUTIONS[m] for m in methods]), "1",
                               "what the solution is and the tension it uses")}
    coords = {"solution": var("solution", methods, "1", "string (row A), exact Bessel (B), wave eq. 15 (C)"),
              "mode": var("mode", np.arange(1, a.n_modes + 1), "1", "mode number")}
    ds = make_dataset(data, coords, analysis="vertical_modes", case=case, references=(REF_002,))
    ds.attrs["string_tension"] = "bottom tension T0 (paper 002 Table 1 row A)"
    if a.methods is None and a.bottom_tension == 0:
        ds.attrs["note"] = ("'string' (a uniform string at the bottom tension) is left out: the bottom "
                            "tension is 0 N (a free lower end), where a string has no frequency.")
    return ds

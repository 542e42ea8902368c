"""Which statics a mooring system's environment needs: the catenary statics or the finite-element ones.

A light module (no kernels, no solver): :func:`seacable.system.run.statics_used` reads it for every check
of a system case (``seacable validate``), before any statics module is imported.
:mod:`seacable.system.statics.fe` re-exports its names.
"""

from __future__ import annotations

__all__ = ["STIFFNESS_ANALYTIC", "STIFFNESS_FD", "line_reasons", "needs_fe"]

STIFFNESS_FD = "central differences of the finite-element statics"
STIFFNESS_ANALYTIC = "analytic (catenary tangents)"


def needs_fe(env, lines=None) -> str:
    """Why the catenary statics cannot model ``env`` ('' when they can): a current, a sloping seabed or a seabed
    grid, a wind (its
    force on a body turns with the body's heading); and, given the system's ``lines`` ({name: SystemLine}), a line
    with sections (buoyancy modules, bend stiffeners), with ties to the seabed (clamps, tethers) or with an end held
    in bending (clamped, a rotational spring), which need the finite-element line's bending and its sections
    resolved on the mesh."""
    cur = env.current
    speeds = [cur.speed] if cur.depths is None else list(cur.speeds)
    why = []
    if any(abs(v) > 0 for v in speeds):
        why.append(f"a current of {max(abs(v) for v in speeds):g} m/s")
    if env.seabed.slope != 0:
        why.append(f"a seabed sloping at {env.seabed.slope:g} rad")
    if env.seabed.grid is not None:
        why.append("a seabed grid (environment.seabed.grid)")
    wind = getattr(env, "wind", None)
    if wind is not None and wind.speed > 0:
        why.append(f"a wind of {wind.speed:g} m/s on the bodies")
    lines = line_reasons(lines or {})
    return " and ".join(why + ([lines] if lines else []))


def line_reasons(lines) -> str:
    """Why the catenary statics cannot carry the system's ``lines`` ({name: SystemLine}; '' when they can): a line
    with sections, with ties to the seabed or with an end held in bending."""
    why = []
    for name, line in lines.items():
        ties = sum(getattr(sec, "type", None) in ("clamp", "tether") for sec in line.line.sections)
        parts = (["sections (buoyancy modules or bend stiffeners)"] if len(line.line.sections) > ties else []) + (
            ["ties to the seabed (clamps or tethers)"] if ties else [])
        if parts:
            why.append(f"line '{name}' with {' and '.join(parts)}")
        held = [k for k in ("end_a", "end_b") if getattr(line, f"{k}_condition").holds]
        if held:
            kinds = "/".join(sorted({getattr(line, f"{k}_condition").type for k in held}))
            why.append(f"line '{name}' with {' and '.join(held)} held in bending ({kinds})")
    return " and ".join(why)

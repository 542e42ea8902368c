"""Which statics a mooring system's environment needs: the catenary statics or the finite-element ones.

A light module (no kernels, no solver): :func:`seacable.system.run.statics_used` reads it for every check
of a system case (``seacable validate``), before any statics module is imported.
:mod:`seacable.system.statics.fe` re-exports its names.
"""

from __future__ import annotations

__all__ = ["STIFFNESS_ANALYTIC", "STIFFNESS_FD", "needs_fe"]

STIFFNESS_FD = "central differences of the finite-element statics"
STIFFNESS_ANALYTIC = "analytic (catenary tangents)"


def needs_fe(env) -> str:
    """Why the catenary statics cannot model ``env`` ('' when they can): a current, a sloping seabed, a wind (its
    force on a body turns with the body's heading)."""
    cur = env.current
    speeds = [cur.speed] if cur.depths is None else list(cur.speeds)
    why = []
    if any(abs(v) > 0 for v in speeds):
        why.append(f"a current of {max(abs(v) for v in speeds):g} m/s")
    if env.seabed.slope != 0:
        why.append(f"a seabed sloping at {env.seabed.slope:g} rad")
    wind = getattr(env, "wind", None)
    if wind is not None and wind.speed > 0:
        why.append(f"a wind of {wind.speed:g} m/s on the bodies")
    return " and ".join(why)

"""Where the system statics split lines between rounds: at the sea surface a line crosses (floating parts in air)
and where a suspended line sags into the seabed; see :mod:`seacable.system.statics`.
"""

from __future__ import annotations

import numpy as np

from ...statics.catenary import CatenaryProfile, CatenaryRegime
from .catenary import sub_profile
from .evaluation import Evaluation, State, node_positions
from .problem import _Problem


def _surface(prob: _Problem, st: State, ev: Evaluation, sag_cuts: dict):
    """Where each line crosses the surface z = 0 and the arc-length intervals above it, from the
    catenaries of sub-lines with an end above the water: ``({line: (s, ...)}, {line: ((s0, s1), ...)})``."""
    asm = prob.asm
    P = node_positions(asm, st.X, st.R, st.P)
    eps = 1e-9 * max(1.0, float(np.abs(P[:, 2]).max(initial=0.0)))
    # a heavy catenary is highest at an end; a buoyant one (w < 0) arches up between its ends, which may
    # both be under water while its middle is above it
    up = (P[asm.sub_a, 2] > eps) | (P[asm.sub_b, 2] > eps) | (asm.sub_w < 0)
    cross: dict = {}
    air: dict = {}
    for k in np.flatnonzero(up):
        name = asm.line_names[asm.sub_line[k]]
        a_is = ev.anchor_is_a[k]
        low = asm.sub_a[k] if a_is else asm.sub_b[k]
        prof = sub_profile(ev.cat, k, 801, asm.tables, CatenaryProfile)
        z = P[low, 2] + prof.z
        s = asm.sub_s0[k] + (prof.s if a_is else asm.sub_L[k] - prof.s)
        if not a_is:
            z, s = z[::-1], s[::-1]
        above = z > eps
        start = s[0] if above[0] else None
        for j in np.flatnonzero(above[1:] != above[:-1]):
            sc = s[j] + (s[j + 1] - s[j]) * z[j] / (z[j] - z[j + 1])      # linear: z = 0 between samples
            cross.setdefault(name, []).append(float(sc))
            if above[j]:
                air.setdefault(name, []).append((start, float(sc)))
                start = None
            else:
                start = float(sc)
        if start is not None:
            air.setdefault(name, []).append((start, float(s[-1])))
    out = {}
    for n, v in cross.items():
        # no node within _SURFACE_GAP x length of a line end or another node (a sub-line that short is
        # ill-conditioned); the piece between goes with its sub-line's middle (a weight error below
        # _SURFACE_GAP of the line's)
        line = prob.system.lines[n].line
        nodes = list(line.segment_ends) + [a.s for a in line.attachments] + list(sag_cuts.get(n, ()))
        gap = _SURFACE_GAP * line.length
        keep = []
        for c in sorted(v):
            near_own = any(abs(c - t) < gap for t in keep)
            near_node = any(abs(c - t) < gap for t in nodes)
            if not near_own and not near_node and gap < c < line.length - gap:
                keep.append(c)
        if keep:
            out[n] = tuple(keep)
    return out, {n: tuple(v) for n, v in air.items()}


_MERGE_S = 1e-6         # crossings moved less than this (x line length) stay where they are
_SURFACE_GAP = 1e-3     # no surface node nearer than this (x line length) to a line end or another node


def _floating(prob: _Problem, air: dict) -> str:
    """The message for lines whose surface crossings do not settle: a part buoyant in water and heavy in
    air, which would float along the surface, partly immersed."""
    def spans(v):
        merged = []
        for a, b in sorted(v):     # the pieces in air of one line, joined where they touch
            if merged and a - merged[-1][1] <= 1e-9 * max(1.0, abs(b)):
                merged[-1][1] = b
            else:
                merged.append([a, b])
        return ", ".join(f"{a:.6g}-{b:.6g}" for a, b in merged)

    names = ", ".join(f"lines.{n} (s = {spans(v)} m)" for n, v in sorted(air.items()))
    return (f"no static equilibrium this model can represent: {names or 'a line'} rises above the sea "
            "surface while immersed and sinks under its dry weight once above it, so it would float along the "
            "surface, partly immersed, which the catenary statics does not model (a line's buoyancy is all or "
            "nothing at z = 0). Suggested fix: less buoyancy on the lines (smaller or fewer buoyancy modules), "
            "more length or depth under them, or a buoy as a point, which may float at the surface.")


def _same_split(surf, old_surf, air, old_air, asm) -> bool:
    """The surface crossings and the parts in air are those of the last round (to 1e-6 x line length)."""
    if set(surf) != set(old_surf) or set(air) != set(old_air):
        return False
    for n in surf:
        if len(surf[n]) != len(old_surf[n]):
            return False
    lengths = dict(zip(asm.line_names, np.bincount(asm.sub_line, weights=asm.sub_L)))
    for n in surf:
        if np.abs(np.subtract(surf[n], old_surf[n])).max() > _MERGE_S * lengths[n]:
            return False
    for n in air:
        if len(air[n]) != len(old_air[n]) or np.abs(np.subtract(air[n], old_air[n])).max() > _MERGE_S * lengths[n]:
            return False
    return True


_SUSPENDED = int(CatenaryRegime.SUSPENDED)


def _merge_cuts(cuts: dict, more: dict) -> dict:
    out = {k: tuple(v) for k, v in cuts.items()}
    for k, v in more.items():
        out[k] = tuple(sorted(set(out.get(k, ())) | set(v)))
    return out


def _sag_cuts(prob: _Problem, st: State, ev: Evaluation) -> dict:
    """``{line: (arc length,)}`` of the lowest point of each suspended sub-line whose sag reaches below
    the seabed (it would pass through it: the catenary of a sub-line lies on the seabed only from a
    node on it)."""
    asm = prob.asm
    if asm.depth is None:
        return {}
    cat = ev.cat
    H, VA, w = cat.H_anchor, cat.V_anchor, asm.sub_w
    sag = (~cat.seabed) & (w > 0) & (VA < 0) & (H > 0) & (cat.regime == _SUSPENDED)
    out: dict = {}
    if not sag.any():
        return out
    P = node_positions(asm, st.X, st.R, st.P)
    for k in np.flatnonzero(sag):
        dip = H[k] / w[k] * (np.hypot(1.0, VA[k] / H[k]) - 1.0) + VA[k] ** 2 / (2.0 * w[k] * asm.sub_EA[k])
        low = asm.sub_a[k] if ev.anchor_is_a[k] else asm.sub_b[k]
        if P[low, 2] - dip >= -asm.depth - 1e-6 * asm.depth:
            continue
        s_low = -VA[k] / w[k]              # unstretched arc length from the lower end to where V = 0
        if not 1e-3 * asm.sub_L[k] < s_low < (1 - 1e-3) * asm.sub_L[k]:
            continue
        s = asm.sub_s0[k] + (s_low if ev.anchor_is_a[k] else asm.sub_L[k] - s_low)
        name = asm.line_names[asm.sub_line[k]]
        out[name] = tuple(sorted(set(out.get(name, ())) | {float(s)}))
    return out

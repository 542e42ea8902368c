"""The smallest distance from a cable to the other lines of its system (issue 40), from a result alone.

A system result (``system_static``, ``system_dynamic``) holds every line's node positions ``x``, ``y``, ``z`` on the
dimensions ``line`` and ``node`` (and ``time``); each line is the polyline through its nodes. At each state the
distance between two lines is the smallest distance between any segment of one and any segment of the other
(:func:`segment_distances`, the closest points of two segments, exact for straight segments: Ericson 2005, 5.1.9),
and :func:`line_distance` gives its smallest over the states, where on both lines (the arc lengths ``s``) and when.
:func:`line_clearance_check` checks it against ``analysis.design.line_clearance`` (the smallest distance allowed
between the centrelines, which holds the two lines' radii and a margin) as a :class:`seacable.design.cable.CableCheck`.

References
----------
Ericson, C. (2005). Real-Time Collision Detection, section 5.1.9 (closest points of two line segments). Morgan
Kaufmann.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import xarray as xr

from ..errors import InputError
from .cable import CableCheck
from .summary import case_data

__all__ = ["LineDistance", "line_clearance_check", "line_distance", "segment_distances"]

#: A segment shorter than this squared is taken as a point (a padded or a coincident node). [m^2]
_TINY = 1e-24


def segment_distances(p0, p1, q0, q1):
    """The smallest distance between segments ``p0``-``p1`` and ``q0``-``q1`` and where it is on each.

    Parameters
    ----------
    p0, p1, q0, q1
        End points, arrays of shape (..., 3) broadcast together. [m]

    Returns
    -------
    distance, a, b : numpy.ndarray
        The distance [m] and the closest points' fractions ``a``, ``b`` in [0, 1] along each segment (the point
        ``p0 + a (p1 - p0)`` and ``q0 + b (q1 - q0)``). Parallel segments take the closest pair with ``a`` the
        smallest; a segment of no length is its point.

    References
    ----------
    Ericson (2005), section 5.1.9: the unconstrained closest points of the two lines, clamped to the first
    segment and the second recomputed, clamped to it and the first recomputed.
    """
    p0, p1, q0, q1 = np.broadcast_arrays(*(np.asarray(v, float) for v in (p0, p1, q0, q1)))
    d1, d2, r = p1 - p0, q1 - q0, p0 - q0
    aa = np.einsum("...k,...k->...", d1, d1)
    ee = np.einsum("...k,...k->...", d2, d2)
    f = np.einsum("...k,...k->...", d2, r)
    c = np.einsum("...k,...k->...", d1, r)
    b_ = np.einsum("...k,...k->...", d1, d2)
    denom = aa * ee - b_ * b_
    point_p, point_q = aa <= _TINY, ee <= _TINY
    with np.errstate(divide="ignore", invalid="ignore"):
        # both segments of length: the lines' closest point on p clamped (parallel: a = 0)
        s = np.where(denom > _TINY * np.maximum(aa * ee, _TINY), np.clip((b_ * f - c * ee) / denom, 0.0, 1.0), 0.0)
        t = (b_ * s + f) / ee
        # t outside [0, 1]: clamp it and find s again
        s = np.where(t < 0.0, np.clip(-c / aa, 0.0, 1.0), np.where(t > 1.0, np.clip((b_ - c) / aa, 0.0, 1.0), s))
        t = np.clip(t, 0.0, 1.0)
        # a segment that is a point
        s = np.where(point_p, 0.0, s)
        t = np.where(point_p, np.clip(f / ee, 0.0, 1.0), t)
        s = np.where(point_q & ~point_p, np.clip(-c / aa, 0.0, 1.0), s)
        t = np.where(point_q, 0.0, t)
    gap = (p0 + s[..., None] * d1) - (q0 + t[..., None] * d2)
    return np.sqrt(np.einsum("...k,...k->...", gap, gap)), s, t


@dataclass(frozen=True)
class LineDistance:
    """The smallest distance from a line to another line of its system over a result's states.

    Attributes
    ----------
    line, other
        The two lines.
    distance
        The smallest distance between their centrelines over the states. [m]
    s, s_other
        Where: the unstretched arc length from end A of the closest point on each. [m]
    time
        When: the state's time [s] (NaN for a static result: one state, or a system_static's conditions; its
        ``history`` is on the conditions).
    position, position_other
        The closest points, (x, y, z). [m]
    history
        The smallest distance at each state (a DataArray on the state dimension, or of no dimension). [m]
    """

    line: str
    other: str
    distance: float
    s: float
    s_other: float
    time: float
    position: tuple[float, float, float]
    position_other: tuple[float, float, float]
    history: xr.DataArray


def _lines(ds: xr.Dataset) -> list[str]:
    if "line" not in ds.dims:
        raise InputError("the result has no 'line' dimension: the distance between lines needs a system result "
                         "(system_static or system_dynamic) of several lines. Suggested fix: run the cable and the "
                         "mooring lines as one system.")
    return [str(v) for v in ds["line"].values]


def _positions(ds: xr.Dataset, line: str) -> tuple[np.ndarray, np.ndarray, np.ndarray | None, str | None]:
    """A line's node positions (states, node, 3) [m], their arc lengths (node,) [m] (NaN padding dropped), the
    states' values (times [s], or a statics' conditions: their coordinate, else their index; None for one state) and
    the states' dimension (``time``, ``condition``; None for one state)."""
    extra = [d for d in ds["x"].dims if d not in ("line", "node")]
    if len(extra) > 1:
        raise InputError(f"the result's positions have the dimensions {list(ds['x'].dims)}; the distance between lines "
                         f"takes one state or a series of states (times, or a statics' conditions). Suggested fix: "
                         f"select one value of {', '.join(extra[1:])}, e.g. ds.isel({extra[1]}=0).")
    one = ds.sel(line=line)
    states = extra[0] if extra else None  # time, or a system_static's condition
    xyz = np.stack([np.asarray(one[c].transpose(*((states,) if states else ()), "node").values, float)
                    for c in "xyz"], axis=-1)
    if states is None:
        xyz = xyz[None]
    keep = np.all(np.isfinite(xyz[0]), axis=-1)
    s = np.asarray(one["s"].values, float) if "s" in one.variables else np.arange(xyz.shape[1], dtype=float)
    times = None
    if states is not None:
        times = (np.asarray(ds[states].values, float) if states in ds.coords and ds[states].dtype.kind in "fiu"
                 else np.arange(ds.sizes[states], dtype=float))
    return xyz[:, keep], s[keep], times, states


def line_distance(ds: xr.Dataset, line: str, others=None, *, block: int = 2_000_000) -> list[LineDistance]:
    """The smallest distance from ``line`` to each other line of a system result, over its states.

    Parameters
    ----------
    ds
        A system result (``line`` and ``node`` dimensions, and ``time`` for a dynamic run).
    line
        The line (the cable).
    others
        The other lines (names); None: all the result's other lines.
    block
        Segment pairs evaluated at once (memory: about 200 bytes each).

    Returns
    -------
    list of LineDistance
        One per other line, in the result's order.

    Raises
    ------
    InputError
        A result without lines, a line it does not hold.
    """
    names = _lines(ds)
    for name in [line] + list(others or []):
        if name not in names:
            raise InputError(f"line '{name}' is not in the result (its lines: {', '.join(names)}). Suggested fix: "
                             "give one of them.")
    others = [n for n in names if n != line] if others is None else [n for n in others if n != line]
    P, sp, times, states = _positions(ds, line)
    out = []
    for other in others:
        Q, sq, _, _ = _positions(ds, other)
        n_states, m, n = P.shape[0], P.shape[1] - 1, Q.shape[1] - 1
        if m < 1 or n < 1:
            raise InputError(f"line '{line if m < 1 else other}' has fewer than two nodes in the result. Suggested fix: "
                             "give a result of lines with nodes.")
        best = np.full(n_states, np.inf)
        where = np.zeros((n_states, 4))  # i, j, a, b at each state's smallest
        per = max(1, block // (m * n))
        for lo in range(0, n_states, per):
            p0, p1 = P[lo:lo + per, :-1, None, :], P[lo:lo + per, 1:, None, :]
            q0, q1 = Q[lo:lo + per, None, :-1, :], Q[lo:lo + per, None, 1:, :]
            d, a, b = segment_distances(p0, p1, q0, q1)
            flat = d.reshape(d.shape[0], -1)
            k = np.argmin(flat, axis=1)
            rows = np.arange(d.shape[0])
            best[lo:lo + per] = flat[rows, k]
            i, j = np.unravel_index(k, (m, n))
            where[lo:lo + per] = np.column_stack([i, j, a.reshape(d.shape[0], -1)[rows, k],
                                                  b.reshape(d.shape[0], -1)[rows, k]])
        kt = int(np.argmin(best))
        i, j, a, b = int(where[kt, 0]), int(where[kt, 1]), where[kt, 2], where[kt, 3]
        pos = P[kt, i] + a * (P[kt, i + 1] - P[kt, i])
        pos_o = Q[kt, j] + b * (Q[kt, j + 1] - Q[kt, j])
        history = xr.DataArray(best if times is not None else best[0], dims=(states,) if times is not None else (),
                               coords={states: times} if times is not None else None, name="line_distance",
                               attrs={"units": "m", "long_name": f"smallest distance from {line} to {other}"})
        out.append(LineDistance(line, other, float(best[kt]), float(sp[i] + a * (sp[i + 1] - sp[i])),
                                float(sq[j] + b * (sq[j + 1] - sq[j])),
                                float(times[kt]) if states == "time" else math.nan,
                                tuple(float(v) for v in pos), tuple(float(v) for v in pos_o), history))
    return out


def _limit_of(ds: xr.Dataset) -> float | None:
    design = ((case_data(ds) or {}).get("analysis") or {}).get("design") or {}
    value = design.get("line_clearance")
    return None if value is None else float(value)


def line_clearance_check(ds: xr.Dataset, line: str, limit: float | None = None, others=None) -> CableCheck:
    """The check of the smallest distance from ``line`` to the other lines of a system result against ``limit``
    (None: the case's ``analysis.design.line_clearance``): the smallest over the other lines and the states,
    ``d >= d_req``, margin ``d - d_req`` [m], utilisation ``d_req / d``; "not checked" without a limit.

    Raises
    ------
    InputError
        A limit that is not a finite number > 0 m; what :func:`line_distance` refuses.
    """
    if limit is None:
        limit = _limit_of(ds)
    if limit is not None and not (math.isfinite(limit) and limit > 0.0):
        raise InputError(f"line_clearance must be a distance > 0 m, got {limit} m. Suggested fix: give the smallest "
                         "distance allowed between the centrelines, e.g. 10 m.")
    distances = line_distance(ds, line, others)
    name = "line clearance"
    if limit is None:
        nan = math.nan
        return CableCheck(name, "line_distance", "m", "min", nan, nan, None, nan, None,
                          "not checked: no analysis.design.line_clearance given", nan, nan, nan, "")
    if not distances:
        nan = math.nan
        return CableCheck(name, "line_distance", "m", "min", nan, nan, None, nan, None,
                          "not checked: the result holds no other line", nan, nan, nan, "")
    worst = min(distances, key=lambda d: d.distance)
    margin = worst.distance - limit
    passed = bool(margin >= 0.0)
    return CableCheck(name, "line_distance", "m", "min", worst.distance, limit,
                      limit / worst.distance if worst.distance > 0 else None, margin, passed,
                      "pass" if passed else "FAIL", worst.s, worst.time, math.nan,
                      f"smallest distance to {worst.other} (at its s = {worst.s_other:.6g} m) >= {limit:.6g} m")

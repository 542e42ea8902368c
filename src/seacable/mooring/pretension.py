"""A pretension helper: the unstretched length of a line's segment that gives a target fairlead tension or
fairlead angle in the static equilibrium (issue 41).

:func:`line_length_for` solves ``q(L) = target`` for the length ``L`` of one segment, where ``q`` is the fairlead
tension or angle of the case's own static analysis run through the public API (:func:`seacable.run`): a single
line's ``static`` (the elastic catenary) or ``mooring_static`` (the finite-element line), or a mooring system's
``system_static`` (the named line's tension at its end B, every free body and point re-solved). The root is
bracketed by stepping the length from the case's own, in the direction that moves ``q`` toward the target, with
steps that double, then found by Brent's method (``scipy.optimize.brentq``). A target the line cannot reach (a
tension below what the line gives however long its segment, or above what it gives as short as the
geometry allows; an angle outside the range) is refused with the range that was reached.

The fairlead angle is the line's angle at its end B (the fairlead) below the horizontal [rad], as
``system_static``'s ``fairlead_angle``: 0 for a line arriving horizontally, pi/2 for a line hanging vertically
from the fairlead. Its complement is the angle from the vertical.

References
----------
Brent, R. P. (1973). Algorithms for Minimization without Derivatives. Prentice-Hall, ch. 4.
Irvine, H. M. (1981). Cable Structures. MIT Press (the elastic catenary the ``static`` analysis solves).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, NoSolutionError, SeacableError

__all__ = ["PretensionResult", "line_length_for"]

#: the analyses whose equilibrium the helper solves
ANALYSES = ("static", "mooring_static", "system_static")
MAX_STEPS = 60   # length steps while bracketing (the step doubles: 2^60 times the first)


@dataclass(frozen=True)
class PretensionResult:
    """What :func:`line_length_for` found.

    Attributes
    ----------
    length
        The unstretched length of the segment. [m]
    segment
        The index of the segment (0 at end A).
    tension
        The fairlead tension at that length. [N]
    angle
        The fairlead angle below the horizontal at that length. [rad]
    case
        The case with that length (its analysis unchanged): ``seacable.run(result.case)`` gives the equilibrium.
    evaluations
        How many static equilibria were solved.
    """

    length: float
    segment: int
    tension: float
    angle: float
    case: object
    evaluations: int


def _line_of(case, line: str | None):
    """The :class:`~seacable.line.Line` the helper changes: the case's own, or the system's line ``line``."""
    kind = getattr(case.analysis, "type", None)
    if kind not in ANALYSES:
        raise InputError(f"line_length_for needs a case whose analysis is one of {', '.join(ANALYSES)}, got "
                         f"analysis.type '{kind}'. Suggested fix: give the case with analysis.type: static (the "
                         "catenary), mooring_static or system_static at the mean position.")
    if kind == "system_static":
        if line not in case.lines:
            raise InputError(f"line_length_for: line '{line}' is not a line of the system (lines: "
                             f"{', '.join(case.lines)}). Suggested fix: line='{next(iter(case.lines), 'NAME')}'.")
        return case.lines[line].line
    if line is not None:
        raise InputError(f"line_length_for: line='{line}' names a line of a mooring system, and this is a "
                         f"single-line '{kind}' case. Suggested fix: leave line out.")
    return case.line


def _with_length(case, line: str | None, segment: int, length: float):
    """``case`` with segment ``segment`` of its line (or of the system's line ``line``) ``length`` long; the
    attachments beyond the segment move with its end B (those on it keep their arc length)."""
    old = _line_of(case, line)
    end = old.segment_ends[segment + 1]
    change = length - old.segments[segment].length
    segments = tuple(s.model_copy(update={"length": length}) if k == segment else s
                     for k, s in enumerate(old.segments))
    attachments = tuple(a.model_copy(update={"s": a.s + change}) if a.s >= end - 1e-12 * old.length else a
                        for a in old.attachments)
    new = type(old).model_validate({**dict(old), "segments": segments, "attachments": attachments})
    if line is None:
        return case.model_copy(update={"line": new})
    lines = dict(case.lines)
    lines[line] = lines[line].model_copy(update={"line": new})
    return case.model_copy(update={"lines": lines})


def _fairlead(ds, line: str | None) -> tuple[float, float]:
    """(tension [N], angle below the horizontal [rad]) at the fairlead (end B) of a static result."""
    kind = ds.attrs["analysis"]
    if kind == "system_static":
        at = ds.sel(condition=ds.condition.values[0], line=line)
        return float(at.fairlead_tension), float(at.fairlead_angle)
    if kind == "static":  # the catenary's fairlead forces: H along the span, V up
        return float(ds.fairlead_tension), math.atan2(float(ds.V_fairlead), float(ds.H_fairlead))
    # mooring_static: the force of the line on its end B, pulling it down and along the line
    fx, fy, fz = (float(np.asarray(ds[f"fairlead_force_{k}"]).ravel()[0]) for k in "xyz")
    return float(np.asarray(ds.fairlead_tension).ravel()[0]), math.atan2(-fz, math.hypot(fx, fy))


def line_length_for(case, *, target_tension: float | None = None, target_angle: float | None = None,
                    line: str | None = None, segment: int = -1, xtol: float = 1e-9) -> PretensionResult:
    """The unstretched length of one segment that gives a target fairlead tension or fairlead angle.

    Parameters
    ----------
    case
        A :class:`~seacable.case.Case` with analysis ``static`` or ``mooring_static``, or a
        :class:`~seacable.system.case.SystemCase` with analysis ``system_static`` (its first condition, the
        intact system, is used). The segment's length in the case is the first guess.
    target_tension
        The fairlead (end B) tension wanted. [N]
    target_angle
        Or the line's angle at the fairlead below the horizontal wanted (0 horizontal, pi/2 vertical). [rad]
    line
        For a system: the name of the line whose segment changes and whose end-B tension or angle is the target.
    segment
        The index of the segment whose length changes (0 at end A, the anchor; -1, the default, the segment at
        end B, the fairlead, as a winch or chain jack pays it in or out).
    xtol
        The tolerance on the length, relative to the segment's length in the case. [-]

    Returns
    -------
    PretensionResult
        The length, the tension and angle it gives, and the case with that length.

    Raises
    ------
    InputError
        No target or both, a target not a positive finite number, an analysis the helper does not solve, an
        unknown line or segment.
    NoSolutionError
        The target is outside what the segment's length can reach (the message gives the range reached and the
        lengths that gave it).

    References
    ----------
    Brent, R. P. (1973). Algorithms for Minimization without Derivatives, ch. 4 (``scipy.optimize.brentq``).
    """
    from scipy.optimize import brentq

    from ..simulate import run

    if (target_tension is None) == (target_angle is None):
        raise InputError("line_length_for needs one target: target_tension [N] or target_angle [rad], got "
                         f"{'both' if target_tension is not None else 'neither'}. Suggested fix: give "
                         "target_tension=1.2e6 (N) or target_angle=0.7 (rad, below the horizontal).")
    by_tension = target_tension is not None
    target = float(target_tension if by_tension else target_angle)
    what, unit = ("target_tension", "N") if by_tension else ("target_angle", "rad")
    if not math.isfinite(target) or target <= 0 or (not by_tension and target >= math.pi / 2):
        expected = "> 0 N" if by_tension else "between 0 and pi/2 rad (below the horizontal)"
        raise InputError(f"line_length_for: {what} must be {expected}, got {target:g} {unit}. Suggested fix: "
                         + ("give the fairlead tension in newtons, e.g. 1.2e6." if by_tension else
                            "give the angle in radians, e.g. math.radians(40)."))
    old = _line_of(case, line)
    n = len(old.segments)
    if not -n <= segment < n:
        raise InputError(f"line_length_for: segment {segment} is not a segment of the line ({n} segment(s), "
                         f"0 to {n - 1}, or -1 for the last). Suggested fix: segment=-1 (end B) or 0 (end A).")
    segment %= n
    start = float(old.segments[segment].length)
    evaluations = []

    def measure(length: float) -> tuple[float, float]:
        evaluations.append(length)
        return _fairlead(run(_with_length(case, line, segment, length)), line)

    def value(length: float) -> float:
        return measure(length)[0 if by_tension else 1]

    q0 = value(start)
    if q0 == target:
        return _result(case, line, segment, start, (q0, q0), by_tension, evaluations, measure)
    # the direction that moves q toward the target: a longer line slackens (tension down, angle steeper)
    up = (q0 > target) if by_tension else (q0 < target)
    step = 0.05 * start
    length, q = start, q0
    seen = [(start, q0)]
    for _ in range(MAX_STEPS):
        trial = length + step if up else max(length - step, 0.5 * length)
        try:
            qt = value(trial)
        except SeacableError as err:
            _unreachable(what, unit, target, seen, line, segment, f"at {trial:.6g} m the equilibrium fails: "
                         f"{str(err).splitlines()[0]}")
        seen.append((trial, qt))
        if (qt - target) * (q - target) <= 0:
            lo, hi = sorted((length, trial))
            found = brentq(lambda x: value(x) - target, lo, hi, xtol=xtol * start, rtol=4 * np.finfo(float).eps)
            return _result(case, line, segment, found, None, by_tension, evaluations, measure)
        if abs(qt - target) >= abs(q - target):  # moving away: the range's end is behind
            _unreachable(what, unit, target, seen, line, segment, "it turns back there")
        if abs(qt - q) <= 1e-9 * abs(q) and up:  # no further change: the asymptote (excess on the seabed)
            _unreachable(what, unit, target, seen, line, segment, "it no longer changes with length")
        length, q = trial, qt
        step *= 2.0
        if not up and length < 1e-9 * start:
            break
    _unreachable(what, unit, target, seen, line, segment, "the bracket was not found")


def _result(case, line, segment, length, _, by_tension, evaluations, measure) -> PretensionResult:
    tension, angle = measure(length)
    return PretensionResult(length=float(length), segment=segment, tension=tension, angle=angle,
                            case=_with_length(case, line, segment, length), evaluations=len(evaluations))


def _unreachable(what, unit, target, seen, line, segment, why):
    values = [q for _, q in seen]
    lengths = [s for s, _ in seen]
    where = f"line '{line}'" if line else "the line"
    fmt = (lambda q: f"{q / 1e3:.6g} kN") if unit == "N" else (lambda q: f"{q:.6g} rad ({math.degrees(q):.4g} deg)")
    raise NoSolutionError(
        f"line_length_for: {what} = {fmt(target)} cannot be reached with segment {segment} of {where}: over lengths "
        f"{min(lengths):.6g} to {max(lengths):.6g} m the fairlead {'tension' if unit == 'N' else 'angle'} ranges "
        f"from {fmt(min(values))} to {fmt(max(values))}, and {why}. Suggested fix: a target in that range, another "
        "segment (segment=...), or move the anchor or the fairlead.")

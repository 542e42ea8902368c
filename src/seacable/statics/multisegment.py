"""Static equilibrium of a multi-segment mooring line with point masses, buoys and clump segments.

Segments run from the anchor (origin) to the fairlead, Z up; each has its own unstretched
length, weight in water per length and EA; point loads (masses > 0, buoys < 0) sit at given
arc lengths; a distributed clump weight is a heavy segment. Each piece between segment ends and
point loads is an elastic catenary in closed form (Irvine 1981 eq. 2.15-2.16, written without
the 1/w cancellation), point loads are jumps in the vertical tension. Newton iterates on
``(H, V_A)`` with ``V(s) = V_A + W(s)``, ``W(s)`` the weight between the anchor and ``s``:
``V_A > 0`` is the anchor uplift of a fully suspended line; ``V_A <= 0`` means the line lies on a
flat rigid seabed from the anchor to the touchdown (the first point where ``V > 0``, inside
a segment or exactly at a point mass, which then rests with a partial reaction) and ``-V_A`` is
the seabed reaction. Coulomb friction on the grounded part opposes a pull toward the fairlead
(Jonkman 2007). The Jacobian is analytic; its inverse is the fairlead stiffness. One contact
zone is represented: a buoy or buoyant segment on the grounded part, or a suspended span
dipping below the seabed, raises :class:`~seacable.errors.NoSolutionError`.

References
----------
.. [1] Irvine, H. M. (1981). Cable Structures. MIT Press, ch. 2.
.. [2] Jonkman, J. M. (2007). Dynamics modeling and loads analysis of an offshore floating wind
   turbine. NREL/TP-500-41958, section 2.2.1.
.. [3] Paper 004 of the seacable sources (Lena guyed tower mooring lines with clump weights).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from .. import _validate as v
from ..errors import ConvergenceError, InputError, NoSolutionError

__all__ = ["LineEquilibrium", "LineProfile", "Pushover", "line_equilibrium", "pushover"]

#: Largest mean strain accepted before a line is declared unable to reach its fairlead.
MAX_STRAIN = 0.2


@dataclass(frozen=True)
class LineProfile:
    """Sampled shape of a line in equilibrium (all arrays of equal length, anchor to fairlead).

    Attributes
    ----------
    s : unstretched arc length from the anchor. [m]
    x, z : position, anchor at the origin, Z up. [m]
    tension : effective tension magnitude; at a point load two samples share one ``s``. [N]
    segment : index of the segment each sample belongs to.
    """

    s: np.ndarray
    x: np.ndarray
    z: np.ndarray
    tension: np.ndarray
    segment: np.ndarray


@dataclass(frozen=True)
class LineEquilibrium:
    """Static equilibrium of a multi-segment line (see :func:`line_equilibrium`).

    Attributes
    ----------
    H_fairlead, V_fairlead : force the line exerts on the fairlead, horizontal component
        pointing back toward the anchor and vertical component pointing down. [N]
    H_anchor, V_anchor : force the line exerts on the anchor, toward the fairlead and upward
        (``V_anchor`` = 0 when the line lies on the seabed at the anchor). [N]
    fairlead_tension, anchor_tension : tension magnitudes at the ends. [N]
    touchdown_s : unstretched arc length of the touchdown from the anchor, 0 when the line is
        fully suspended. [m]
    touchdown_x : horizontal position of the touchdown. [m]
    grounded_length : unstretched length on the seabed (equals ``touchdown_s``). [m]
    touchdown_segment : index of the segment holding the touchdown (lift-off point of a clump
        segment), -1 when fully suspended.
    segment_grounded_length : unstretched length of each segment lying on the seabed. [m]
    stiffness : 2x2 matrix d(H_fairlead, V_fairlead)/d(x_fairlead, z_fairlead). [N/m]
    iterations : Newton iterations used.
    """

    H_fairlead: float
    V_fairlead: float
    H_anchor: float
    V_anchor: float
    fairlead_tension: float
    anchor_tension: float
    touchdown_s: float
    touchdown_x: float
    grounded_length: float
    touchdown_segment: int
    segment_grounded_length: np.ndarray
    stiffness: np.ndarray
    iterations: int
    _line: "_Line" = field(repr=False, compare=False)
    _V_A: float = field(repr=False, compare=False)

    def profile(self, points_per_segment: int = 50) -> LineProfile:
        """Sample the line: ``points_per_segment`` equally spaced samples per segment plus every
        segment end, point-load location (both sides), touchdown and sag/hog bend. -> LineProfile
        """
        n = int(v.at_least("points_per_segment", points_per_segment, 2, "",
                           "give at least 2 points per segment"))
        return _profile(self._line, self.H_fairlead, self._V_A, n, self.touchdown_x)

    def profile_at(self, s, points_per_segment: int = 50) -> tuple[np.ndarray, np.ndarray]:
        """The line's position ``(x, z)`` at unstretched arc lengths ``s`` [m] from the anchor, linear between the
        samples of :meth:`profile` (``points_per_segment``; at a point load, its first sample), the end values
        beyond the ends; only the samples read are evaluated. [m]"""
        n = int(v.at_least("points_per_segment", points_per_segment, 2, "",
                           "give at least 2 points per segment"))
        s = np.asarray(s, float)
        prof = _profile(self._line, self.H_fairlead, self._V_A, n, self.touchdown_x, at=s)
        keep = np.concatenate(([True], np.diff(prof.s) > 0))  # a point load repeats its arc length
        return np.interp(s, prof.s[keep], prof.x[keep]), np.interp(s, prof.s[keep], prof.z[keep])


@dataclass(frozen=True)
class Pushover:
    """Force-excursion curve of a line (see :func:`pushover`).

    Attributes
    ----------
    offset : horizontal fairlead offset from the reference span. [m]
    H_fairlead, V_fairlead, fairlead_tension : fairlead forces. [N]
    touchdown_x : horizontal touchdown position. [m]
    grounded_length : unstretched grounded length. [m]
    segment_grounded_length : grounded length of each segment, shape (n_offsets, n_segments). [m]
    stiffness_horizontal : dH_fairlead/dx_fairlead at fixed fairlead height. [N/m]
    """

    offset: np.ndarray
    H_fairlead: np.ndarray
    V_fairlead: np.ndarray
    fairlead_tension: np.ndarray
    touchdown_x: np.ndarray
    grounded_length: np.ndarray
    segment_grounded_length: np.ndarray
    stiffness_horizontal: np.ndarray

    def liftoff_offset(self, segment: int) -> float | None:
        """First offset at which ``segment`` is off the seabed after resting on it (resolution:
        the offset step), ``None`` if that does not happen in the sequence. [m]"""
        g = self.segment_grounded_length[:, segment]
        for i in range(1, g.size):
            if g[i - 1] > 0.0 and g[i] <= 0.0:
                return float(self.offset[i])
        return None


# --- line description ---
@dataclass(frozen=True)
class _Line:
    """Pieces between consecutive segment ends / point loads (internal)."""

    nodes: np.ndarray        # s of piece ends, length n+1
    jump: np.ndarray         # point load at each node, length n+1 (ends are 0)
    w: np.ndarray            # weight per length of each piece
    ea: np.ndarray           # EA of each piece
    seg: np.ndarray          # segment index of each piece
    c_start: np.ndarray      # W(s_i+) at the start of each piece (after the jump there)
    w_total: float
    seabed: bool
    mu: float
    n_segments: int

    @property
    def length(self) -> float:
        return float(self.nodes[-1])


def _build_line(lengths, weights, ea, point_loads, seabed, mu) -> _Line:
    bounds = np.concatenate([[0.0], np.cumsum(lengths)])
    total = bounds[-1]
    s_loads = np.array([p[0] for p in point_loads], dtype=float)
    nodes = np.unique(np.concatenate([bounds, s_loads]))
    # merge nodes closer than round-off so no piece has zero length
    keep = np.concatenate([[True], np.diff(nodes) > 1e-12 * total])
    nodes = nodes[keep]
    nodes[-1] = total
    jump = np.zeros(nodes.size)
    for s, wp in point_loads:
        jump[np.argmin(np.abs(nodes - s))] += wp
    mid = 0.5 * (nodes[:-1] + nodes[1:])
    seg = np.minimum(np.searchsorted(bounds, mid) - 1, len(lengths) - 1)
    w = np.asarray(weights, float)[seg]
    eap = np.asarray(ea, float)[seg]
    lp = np.diff(nodes)
    c_start = np.cumsum(jump[:-1]) + np.concatenate([[0.0], np.cumsum(w * lp)[:-1]])
    w_total = float(np.sum(w * lp) + np.sum(jump))
    return _Line(nodes, jump, w, eap, seg, c_start, w_total, bool(seabed), float(mu), len(lengths))


# --- one elastic catenary piece ---
def _asinhc(y):
    """asinh(y)/y, accurate near 0."""
    if abs(y) < 1e-4:
        return 1.0 - y * y / 6.0 + 0.075 * y ** 4
    return np.arcsinh(y) / y


def _piece(H, V0, w, l, ea):
    """Span (dx, dz) of an elastic catenary piece (tension (H, V0) at its lower-s end) and the
    derivatives dxdH, dxdV0, dzdH, dzdV0, dxdl, dzdl; Irvine (1981) eq. 2.15-2.16 rewritten
    without the 1/w cancellation."""
    V1 = V0 + w * l
    T0, T1 = np.hypot(H, V0), np.hypot(H, V1)
    Vs = V0 + V1
    cross = -H * l * Vs / (T0 * T1 * (T0 + T1))          # dx/dV0 = dz/dH (rigid part)
    if V0 * V1 >= 0.0:
        D = V1 * T0 + V0 * T1
        if D == 0.0:                                         # weightless horizontal piece
            dx, dz, dxdH, dzdV0 = l, 0.0, 0.0, l / H
        else:
            y = w * l * Vs / D
            dx = H * l * Vs / D * _asinhc(y)
            dz = l * Vs / (T0 + T1)
            dzdV0 = H * H * l * Vs / (D * T0 * T1)
            dxdH = dx / H - dzdV0
    else:                                                    # V changes sign: no cancellation
        dx = H / w * (np.arcsinh(V1 / H) - np.arcsinh(V0 / H))
        dz = (T1 - T0) / w
        dzdV0 = (V1 / T1 - V0 / T0) / w
        dxdH = dx / H - dzdV0
    dx += H * l / ea
    dz += Vs * l / (2.0 * ea)
    return (dx, dz, dxdH + l / ea, cross, cross, dzdV0 + l / ea,
            H / T1 + H / ea, V1 / T1 + V1 / ea)


def _span(H, V0, w, l, ea):
    """The span (dx, dz) of :func:`_piece` alone, by the same operations."""
    V1 = V0 + w * l
    T0, T1 = float(np.hypot(H, V0)), float(np.hypot(H, V1))
    Vs = V0 + V1
    if V0 * V1 >= 0.0:
        D = V1 * T0 + V0 * T1
        if D == 0.0:                                         # weightless horizontal piece
            dx, dz = l, 0.0
        else:
            y = w * l * Vs / D
            dx = H * l * Vs / D * float(_asinhc(y))
            dz = l * Vs / (T0 + T1)
    else:                                                    # V changes sign: no cancellation
        dx = H / w * float(np.arcsinh(V1 / H) - np.arcsinh(V0 / H))
        dz = (T1 - T0) / w
    dx += H * l / ea
    dz += Vs * l / (2.0 * ea)
    return dx, dz


def _clip_integral(c0, c1, length):
    """Integral over t in [0, length] of max(c0 + c1 t, 0) and the measure where it is > 0."""
    c_end = c0 + c1 * length
    if c0 >= 0.0 and c_end >= 0.0:
        return 0.5 * (c0 + c_end) * length, length
    if c0 <= 0.0 and c_end <= 0.0:
        return 0.0, 0.0
    t0 = -c0 / c1                                            # sign change inside
    if c0 > 0.0:
        return 0.5 * c0 * t0, t0
    return 0.5 * c_end * (length - t0), length - t0


# --- shooting: (H, V_A) -> fairlead position, Jacobian, touchdown ---
def _touchdown(line: _Line, V_A: float):
    """Return (kind, index, s_td): kind 'none' (suspended), 'node' (at a point load) or 'piece'."""
    if not line.seabed or V_A > 0.0:
        return "none", 0, 0.0
    for i in range(line.w.size):
        V0 = V_A + line.c_start[i]
        if V0 > 0.0:                                         # jump at node i lifted the line
            return "node", i, float(line.nodes[i])
        V1 = V0 + line.w[i] * (line.nodes[i + 1] - line.nodes[i])
        if V1 > 0.0:
            return "piece", i, float(line.nodes[i] - V0 / line.w[i])
    return "piece", line.w.size - 1, line.length                       # formally all grounded


def _shoot(line: _Line, H: float, V_A: float):
    """Fairlead position (X, Z) for unknowns (H, V_A) and the 2x2 Jacobian d(X, Z)/d(H, V_A)."""
    kind, itd, s_td = _touchdown(line, V_A)
    X = Z = x_td = 0.0
    J, first_susp = np.zeros((2, 2)), 0
    if kind != "none":
        mu = line.mu
        last = itd + 1 if kind == "piece" else itd
        for j in range(last):
            a = line.nodes[j]
            lg = (s_td if (kind == "piece" and j == itd) else line.nodes[j + 1]) - a
            c0 = H + mu * (V_A + line.c_start[j])
            integ, meas = _clip_integral(c0, mu * line.w[j], lg)
            X += lg + integ / line.ea[j]
            J[0, 0] += meas / line.ea[j]
            J[0, 1] += mu * meas / line.ea[j]
        x_td = X
        if kind == "piece":
            w, ea = line.w[itd], line.ea[itd]
            J[0, 1] += -(1.0 + H / ea) / w                   # d s_td / d V_A = -1/w
            lp = line.nodes[itd + 1] - s_td
            dx, dz, dxdH, _, dzdH, _, dxdl, dzdl = _piece(H, 0.0, w, lp, ea)
            X, Z, J = X + dx, Z + dz, J + [[dxdH, dxdl / w], [dzdH, dzdl / w]]
            first_susp = itd + 1
        else:
            first_susp = itd
    for j in range(first_susp, line.w.size):
        dx, dz, dxdH, dxdV, dzdH, dzdV, _, _ = _piece(
            H, V_A + line.c_start[j], line.w[j], line.nodes[j + 1] - line.nodes[j], line.ea[j])
        X, Z, J = X + dx, Z + dz, J + [[dxdH, dxdV], [dzdH, dzdV]]
    return X, Z, J, (kind, itd, s_td, x_td)


def _hang(line: _Line, V_A: float):
    """Height of the part above the touchdown hanging vertically (H = 0) and d(height)/dV_A."""
    kind, itd, s_td = _touchdown(line, V_A)
    Z = dZ = 0.0
    for j in range(itd if kind == "node" else itd + 1, line.w.size):
        l, ea = line.nodes[j + 1] - line.nodes[j], line.ea[j]
        V0 = V_A + line.c_start[j]
        Z += l + (2 * V0 + line.w[j] * l) * l / (2 * ea)
        dZ += l / ea
    if kind == "piece":
        w, ea, l = line.w[itd], line.ea[itd], line.nodes[itd + 1] - s_td
        Z += l + w * l * l / (2 * ea)
        dZ += (1 + w * l / ea) / w
    return Z, dZ, s_td


def _touchdown_bound(line: _Line, Z: float) -> float:
    """An upper bound of the touchdown's arc length of the line hanging vertically to height ``Z`` from the
    seabed (:func:`_slack_touchdown`), so that a span beyond it skips that search (its line is not slack); inf
    with buoyancy. The hanging part is ``L - s_td`` long unstretched, stretched by at most the whole weight over
    the least EA: ``Z <= (L - s_td) (1 + W / EA_min)``."""
    if np.any(line.w < 0.0) or np.any(line.jump < 0.0) or Z <= 0.0:
        return np.inf
    bound = line.length - Z / (1.0 + line.w_total / float(np.min(line.ea)))
    return bound * (1.0 + 1e-9) + 1e-9 * line.length


def _slack_touchdown(line: _Line, Z: float):
    """V_A at which the line hangs vertically to height Z from a flat seabed, or None."""
    w_max = max(np.max(line.c_start), np.max(line.c_start + line.w * np.diff(line.nodes)))
    if w_max <= 0.0 or _hang(line, 0.0)[0] <= Z:
        return None
    lo, hi = -w_max, 0.0
    for _ in range(200):                                     # bisection: _hang is monotone
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _hang(line, mid)[0] < Z else (lo, mid)
        if hi - lo <= 1e-15 * w_max:
            break
    return 0.5 * (lo + hi)


# --- profile and post-processing ---
def _profile(line: _Line, H: float, V_A: float, n_per_seg: int, x_slack=0.0, at=None) -> LineProfile:
    """Sample the line; with H = 0 the grounded part runs straight to ``x_slack`` and piles there.

    ``at``: the arc lengths [m] at which the caller interpolates the profile linearly (``np.interp`` on the samples
    of distinct ``s``, :meth:`LineEquilibrium.profile_at`): only the samples that interpolation reads are evaluated
    (with each piece's last, where the next piece starts, and the touchdown), the same values as in the whole
    profile, which holds those samples only."""
    kind, itd, s_td = _touchdown(line, V_A)
    seg_len = np.bincount(line.seg, weights=np.diff(line.nodes), minlength=line.n_segments)
    grids = []
    for j in range(line.w.size):
        a, b, w = line.nodes[j], line.nodes[j + 1], line.w[j]
        nseg = max(int(np.ceil(n_per_seg * (b - a) / seg_len[line.seg[j]])), 1)
        ts = np.linspace(a, b, nseg + 1)
        V0 = V_A + line.c_start[j]
        if kind == "piece" and j == itd:
            ts = np.unique(np.append(ts, s_td))
        elif V0 * (V0 + w * (b - a)) < 0.0 and (kind == "none" or j > itd):
            ts = np.unique(np.append(ts, a - V0 / w))       # sag/hog bend extremum of z
        if j > 0 and line.jump[j] == 0.0:
            ts = ts[1:]                                      # shared end already sampled
        grids.append(ts)
    need = None if at is None else _needed(grids, at, s_td if kind == "piece" else None)
    S, XX, ZZ, TT, GG = [], [], [], [], []
    x0 = z0 = x_td = 0.0
    first = 0  # index of the piece's first sample among all
    # Python floats (the same values and operations as numpy's scalars, a few times faster)
    H, V_A, s_td = float(H), float(V_A), float(s_td)
    nodes, ws, eas, starts = line.nodes.tolist(), line.w.tolist(), line.ea.tolist(), line.c_start.tolist()
    for j, ts in enumerate(grids):
        a, w, ea = nodes[j], ws[j], eas[j]
        td_here = kind == "piece" and j == itd
        c0 = H + line.mu * (V_A + starts[j])
        for s in (ts if need is None else ts[need[first:first + ts.size]]).tolist():
            if kind != "none" and (j < itd or (td_here and s <= s_td)):
                integ = _clip_integral(c0, line.mu * w, s - a)[0]
                x, z, t = x0 + (s - a) + integ / ea, 0.0, max(c0 + line.mu * w * (s - a), 0.0)
                if H == 0.0:
                    x = min(x, x_slack)
                if td_here and s == s_td:
                    x_td = x
            elif H == 0.0:                                   # slack: vertical hanging part
                lo, Vlo, zl = (s_td, 0.0, 0.0) if td_here else (a, V_A + starts[j], z0)
                V1 = Vlo + w * (s - lo)
                x, z, t = x_slack, zl + (s - lo) + (Vlo + V1) * (s - lo) / (2 * ea), V1
            else:
                lo, Vlo, xl, zl = ((s_td, 0.0, x_td, 0.0) if td_here
                                   else (a, V_A + starts[j], x0, z0))
                dx, dz = _span(H, Vlo, w, s - lo, ea)
                x, z, t = xl + dx, zl + dz, float(np.hypot(H, Vlo + w * (s - lo)))
            S.append(s), XX.append(x), ZZ.append(z), TT.append(t), GG.append(line.seg[j])
        x0, z0 = XX[-1], ZZ[-1]
        first += ts.size
    return LineProfile(np.array(S), np.array(XX), np.array(ZZ), np.array(TT), np.array(GG, int))


def _needed(grids, at, s_td) -> np.ndarray:
    """Which samples of the pieces' grids (:func:`_profile`) a linear interpolation at ``at`` over the samples of
    distinct ``s`` reads (the two around each point, the first and the last), with each piece's last sample and
    the touchdown ``s_td`` (None: none), which the samples after them start from."""
    S = np.concatenate(grids)
    # the first of samples sharing an s (a point load)
    distinct = np.flatnonzero(np.concatenate(([True], np.diff(S) > 0)))
    j = np.searchsorted(S[distinct], np.asarray(at, float).ravel(), side="right") - 1
    need = np.zeros(S.size, bool)
    need[distinct[np.clip(np.concatenate((j, j + 1, [0, distinct.size - 1])), 0, distinct.size - 1)]] = True
    need[np.cumsum([ts.size for ts in grids]) - 1] = True
    if s_td is not None:
        need[S == s_td] = True
    return need


def _check_representable(line: _Line, H, V_A, kind, itd, s_td, L):
    """Raise NoSolutionError for configurations the single-contact model cannot represent."""
    if not line.seabed:
        return
    fix = ("which this single-contact model does not represent. Suggested fix: move buoyancy "
           "above the touchdown.")
    for j in range(0 if kind == "none" else itd + 1 if kind == "piece" else itd):
        if line.w[j] < 0.0:
            raise NoSolutionError(f"segment {line.seg[j]} is buoyant ({line.w[j]:.6g} N/m) but "
                                  f"lies on the grounded part; it would lift off in a second span, {fix}")
    for k in range(1, 0 if kind == "none" else itd + (1 if kind == "piece" else 0)):
        if line.jump[k] < 0.0:
            raise NoSolutionError(f"the buoy at s = {line.nodes[k]:.6g} m ({line.jump[k]:.6g} N) lies "
                                  f"on the grounded part; it would lift off in a second span, {fix}")
    if np.all(line.w >= 0.0) and np.all(line.jump >= 0.0):
        # no buoyancy: V = V_A + W(s) never falls along the line, so past the touchdown (V > 0) every piece rises
        # (dz >= 0, its elastic stretch too) and no span can dip below the seabed: the profile is not needed
        return
    prof = _profile(line, H, V_A, 20)                        # includes every V = 0 point
    susp = prof.s > s_td
    if susp.any() and prof.z[susp].min() < -1e-9 * L:
        s_bad = prof.s[susp][np.argmin(prof.z[susp])]
        raise NoSolutionError(f"the suspended line dips {-prof.z[susp].min():.6g} m below the "
                              f"seabed near s = {s_bad:.6g} m (a second touchdown), {fix}")


# --- public functions ---
def _validate(lengths, weights, axial_stiffness, point_loads, seabed_friction, seabed_slope, tol,
              max_iter):
    lengths = np.atleast_1d(v.positive("lengths", lengths, "m", "give unstretched lengths in m"))
    n = lengths.size
    weights = np.atleast_1d(v.finite("weights", weights, "N/m", "give weights in water in N/m"))
    ea = np.atleast_1d(v.positive("axial_stiffness", axial_stiffness, "N", "give EA in N"))
    for name, arr in (("weights", weights), ("axial_stiffness", ea)):
        if arr.ndim != 1 or arr.size not in (1, n):
            raise InputError(f"{name} must have one value per segment ({n}), got {arr.size} values. "
                             "Suggested fix: list one value per segment, anchor to fairlead.")
    weights, ea = np.broadcast_to(weights, (n,)).astype(float), np.broadcast_to(ea, (n,)).astype(float)
    loads, total = [], float(lengths.sum())
    for k, p in enumerate(point_loads):
        try:
            s, wp = p
        except (TypeError, ValueError):
            raise InputError(f"point_loads[{k}] must be a pair (s, net_weight), got {p!r}. Suggested "
                             "fix: give (arc length from the anchor [m], net weight [N]).") from None
        s = v.in_range(f"point_loads[{k}] arc length", s, 0.0, total, "m",
                       "place the load strictly between the anchor and the fairlead; a load at "
                       "an end is carried by the anchor or the vessel", inclusive=False)
        loads.append((s, v.finite(f"point_loads[{k}] net weight", wp, "N")))
    v.nonnegative("seabed_friction", seabed_friction, "", "give a Coulomb coefficient, e.g. 0.5")
    slope = v.in_range("seabed_slope", seabed_slope, -np.pi / 2, np.pi / 2, "rad",
                       "give the slope in radians", inclusive=False)
    if slope != 0.0:
        raise InputError(f"seabed_slope must be 0 rad (a sloping seabed is not implemented), got "
                         f"{slope:.6g} rad. Suggested fix: use a flat seabed (slope: 0) for static "
                         "analyses; sloped seabeds are not yet supported there.")
    v.in_range("tol", tol, 0.0, 1e-2, "", "give a relative tolerance such as 1e-9", inclusive=False)
    v.at_least("max_iter", max_iter, 1, "", "allow at least one iteration")
    return lengths, weights, ea, loads


def _initial_guess(line: _Line, X, Z):
    """Equivalent uniform line with the guess of Jonkman (2007) / Peyrot & Goulois."""
    L = line.length
    w = abs(line.w_total) / L
    if w == 0.0:
        w = max(float(np.max(np.abs(line.w))), 1e-9)
    lam = 0.2 if np.hypot(X, Z) >= L else np.sqrt(3.0 * ((L * L - Z * Z) / (X * X) - 1.0))
    H = max(abs(w * X / (2.0 * lam)), 1e-3 * w * L)
    VF = 0.5 * w * (Z / np.tanh(lam) + L)
    chord = np.hypot(X, Z)
    if chord >= L:                                           # taut: straight-bar tension
        T = (chord - L) / np.sum(np.diff(line.nodes) / line.ea)
        if T * X / chord > H:
            return T * X / chord, T * Z / chord - 0.5 * line.w_total
    return H, VF * np.sign(line.w_total or 1.0) - line.w_total


def _newton(line: _Line, X, Z, H, V_A, tol, max_iter):
    L = line.length
    scale_f = max(float(np.max(np.abs(line.w))) * L, float(np.max(np.abs(line.jump))), 1.0)
    u, nonneg = np.array([H, V_A], float), np.all(line.w >= 0) and np.all(line.jump >= 0)
    Xc, Zc, J, _ = _shoot(line, *u)
    r = np.array([Xc - X, Zc - Z])
    for it in range(1, max_iter + 1):
        try:
            du = np.linalg.solve(J, -r)
        except np.linalg.LinAlgError:
            du = np.linalg.lstsq(J, -r, rcond=None)[0]
        if u[0] + du[0] < 0.1 * u[0]:                       # keep H > 0
            du *= 0.9 * u[0] / -du[0]
        if line.seabed and nonneg and u[1] + du[1] + line.w_total <= 0.0 < u[1] + line.w_total:
            du *= 0.9 * (u[1] + line.w_total) / -du[1]       # keep the fairlead end off the seabed
        if line.seabed and line.w[0] < 0.0 and u[1] + du[1] <= 0.0 < u[1]:
            du *= 0.9 * u[1] / -du[1]                        # a buoyant first piece cannot ground
        alpha, norm0 = 1.0, np.linalg.norm(r)
        for _ in range(30):
            ut = u + alpha * du
            Xt, Zt, Jt, _ = _shoot(line, *ut)
            rt = np.array([Xt - X, Zt - Z])
            if np.linalg.norm(rt) < (1.0 - 1e-4 * alpha) * norm0 or norm0 < tol * L:
                break
            alpha *= 0.5
        step, u, r, J = alpha * du, ut, rt, Jt
        small = abs(step[0]) <= tol * (u[0] + scale_f) and abs(step[1]) <= tol * (abs(u[1]) + scale_f)
        if np.all(np.isfinite(r)) and np.max(np.abs(r)) <= tol * L and small:
            return u, J, it
    raise ConvergenceError(
        f"line equilibrium did not converge in {max_iter} iterations (position residual "
        f"{np.max(np.abs(r)):.3g} m, H = {u[0]:.6g} N). Suggested fix: raise max_iter, check that "
        "the fairlead position is reachable, or start from a nearby solution (pushover).",
        iterations=max_iter, residual=float(np.max(np.abs(r))))


def line_equilibrium(lengths, weights, axial_stiffness, horizontal_span, vertical_span, *,
                     point_loads=(), seabed=True, seabed_friction=0.0, seabed_slope=0.0,
                     tol=1e-9, max_iter=100, initial_guess=None) -> LineEquilibrium:
    """Static equilibrium of a multi-segment elastic catenary mooring line.

    Segments are listed from the anchor (at the origin) to the fairlead at
    ``(horizontal_span, vertical_span)``, Z up.

    Parameters
    ----------
    lengths : array_like
        Unstretched length of each segment. [m]
    weights : array_like
        Weight in water per unstretched length of each segment, negative if buoyant; one value
        per segment or a scalar. [N/m]
    axial_stiffness : array_like
        Axial stiffness EA of each segment, one value per segment or a scalar. [N]
    horizontal_span : float
        Horizontal distance from the anchor to the fairlead, > 0. [m]
    vertical_span : float
        Height of the fairlead above the anchor (> 0 with a seabed). [m]
    point_loads : sequence of (float, float)
        ``(s, net_weight)`` pairs: a point mass (net weight > 0) or buoy (< 0) at unstretched
        arc length ``s`` from the anchor, strictly inside the line. [m], [N]
    seabed : bool
        True: a flat rigid seabed through the anchor; the line may lie on it from the anchor
        to the touchdown. False: the anchor end hangs in mid-water.
    seabed_friction : float
        Coulomb friction coefficient on the grounded part (friction opposes a pull toward
        the fairlead). [-]
    seabed_slope : float
        Seabed slope; only 0 (flat) is implemented. [rad]
    tol : float
        Relative tolerance: position residual below ``tol`` times the line length and Newton
        steps below ``tol`` times the force scale. [-]
    max_iter : int
        Maximum Newton iterations. [-]
    initial_guess : tuple of float, optional
        ``(H, V_A)`` to start from (used by :func:`pushover` for continuation). [N]

    Returns
    -------
    LineEquilibrium

    Raises
    ------
    InputError
        A bad input.
    NoSolutionError
        The line cannot reach the fairlead, the fairlead is at or below the seabed, or the
        equilibrium needs a second seabed contact (a buoy on the grounded part, a span
        dipping below the seabed).
    ConvergenceError
        Newton did not converge.

    Notes
    -----
    A line too slack for any H > 0 (its grounded part, with the rest hanging vertically, is
    longer than the span) is returned with H = 0: the line lies on the seabed, bunched at the
    touchdown below the fairlead, and hangs vertically from there (MoorPy's slack profile).
    The stiffness is then [[0, 0], [0, dV/dz]].

    References
    ----------
    .. [1] Irvine, H. M. (1981). Cable Structures. MIT Press, eq. 2.15-2.16.
    .. [2] Jonkman, J. M. (2007). NREL/TP-500-41958, section 2.2.1.
    """
    lengths, weights, ea, loads = _validate(lengths, weights, axial_stiffness, point_loads,
                                            seabed_friction, seabed_slope, tol, max_iter)
    X = v.positive("horizontal_span", horizontal_span, "m", "give the anchor-fairlead distance")
    Z = v.finite("vertical_span", vertical_span, "m")
    line = _build_line(lengths, weights, ea, loads, seabed, seabed_friction)
    L = line.length
    dist = float(np.hypot(X, Z))
    if dist > L * (1.0 + MAX_STRAIN):
        raise NoSolutionError(f"the line ({L:.6g} m) cannot reach the fairlead {dist:.6g} m away without a "
                              f"strain above {MAX_STRAIN:.0%}. Suggested fix: lengthen the line.")
    if seabed and Z <= 0.0:
        raise NoSolutionError(f"vertical_span must be > 0 m with a seabed (fairlead must be above the "
                              f"seabed), got {Z:.6g} m. Suggested fix: use seabed=False or raise it.")
    slack_err = None
    if seabed and not X > _touchdown_bound(line, Z):
        VA_slack = _slack_touchdown(line, Z)
        if VA_slack is not None and X <= _touchdown(line, VA_slack)[2]:
            try:
                return _slack_result(line, X, Z, VA_slack)
            except NoSolutionError as exc:                   # buoyancy: look for H > 0 instead
                slack_err = exc
    guesses = [initial_guess] if initial_guess is not None else []
    H0, VA0 = _initial_guess(line, X, Z)
    guesses += [(H0, VA0), (10.0 * H0, VA0), (0.1 * H0, VA0)]
    u = err = nosol = None
    for g in guesses:
        try:
            u, J, its = _newton(line, X, Z, float(g[0]), float(g[1]), tol, int(max_iter))
            _check_representable(line, u[0], u[1], *_touchdown(line, u[1]), L)
            break
        except ConvergenceError as exc:
            u, err = None, exc
        except NoSolutionError as exc:                       # another root may be representable
            u, nosol = None, exc
            break
    if u is None and seabed:                                 # a suspended line clear of the seabed
        try:
            uf, Jf, itf = _newton(replace(line, seabed=False), X, Z, H0, abs(VA0), tol, int(max_iter))
            if uf[1] > 0:
                _check_representable(line, uf[0], uf[1], "none", 0, 0.0, L)
                u, J, its = uf, Jf, itf
        except ConvergenceError:
            pass
        except NoSolutionError as exc:
            nosol = exc
    if u is None and (nosol or slack_err) is not None:
        raise nosol or slack_err
    if u is None:
        if seabed and (np.any(line.w < 0) or np.any(line.jump < 0)):
            err.args = (err.args[0] + " With buoyant parts on a seabed the equilibrium may need a "
                        "second seabed contact, which this model does not represent.",)
        raise err
    H, V_A = float(u[0]), float(u[1])
    kind, itd, s_td = _touchdown(line, V_A)
    V_F = V_A + line.w_total
    if kind == "none":
        H_A, V_anchor, x_td, td_seg = H, V_A, 0.0, -1
    else:
        H_A, V_anchor = max(H + seabed_friction * V_A, 0.0), 0.0
        x_td = _shoot(line, H, V_A)[3][3]
        td_seg = int(line.seg[itd])
    return LineEquilibrium(H, V_F, H_A, V_anchor, float(np.hypot(H, V_F)), float(np.hypot(H_A, V_anchor)),
                           s_td, float(x_td), s_td, td_seg, _grounded_per_segment(line, s_td),
                           np.linalg.inv(J), its, line, V_A)


def _grounded_per_segment(line: _Line, s_td):
    gl = np.zeros(line.n_segments)
    np.add.at(gl, line.seg, np.clip(np.minimum(line.nodes[1:], s_td) - line.nodes[:-1], 0, None))
    return gl


def _slack_result(line: _Line, X, Z, V_A) -> LineEquilibrium:
    """H = 0: the line lies on the seabed (bunched if longer than the span) and hangs vertically."""
    kind, itd, s_td = _touchdown(line, V_A)
    _check_representable(line, 0.0, V_A, kind, itd, s_td, line.length)
    first = itd + 1 if kind == "piece" else itd
    ends = np.append(line.c_start[1:] - line.jump[1:-1], line.w_total)
    if np.any(V_A + line.c_start[first:] < 0) or np.any(V_A + ends[first:] < 0):
        raise NoSolutionError("the line is slack (H = 0) and a buoyant part would put its vertical "
                              "hanging part in compression (a fold), which this model does not "
                              "represent. Suggested fix: shorten the line or increase the span.")
    dZ = _hang(line, V_A)[1]
    V_F = V_A + line.w_total
    return LineEquilibrium(0.0, V_F, 0.0, 0.0, abs(V_F), 0.0, s_td, float(X), s_td,
                           int(line.seg[min(itd, line.w.size - 1)]), _grounded_per_segment(line, s_td),
                           np.array([[0.0, 0.0], [0.0, 1.0 / dZ]]), 0, line, V_A)


def pushover(lengths, weights, axial_stiffness, horizontal_span, vertical_span, offsets,
             check=None, **options) -> Pushover:
    """Force-excursion curve: :func:`line_equilibrium` at each offset, each started from the
    previous solution (continuation; give the offsets in a monotone order).

    Parameters
    ----------
    lengths, weights, axial_stiffness, horizontal_span, vertical_span
        As for :func:`line_equilibrium`. [m], [N/m], [N], [m], [m]
    offsets : array_like
        Horizontal fairlead offsets added to ``horizontal_span``. [m]
    check : callable, optional
        ``check(equilibrium, offset)``, called on each solution (it may raise to refuse one).
    **options
        Keyword options of :func:`line_equilibrium` (point_loads, seabed, seabed_friction, ...).

    Returns
    -------
    Pushover
    """
    offsets = np.atleast_1d(v.finite("offsets", offsets, "m"))
    options.pop("initial_guess", None)
    rows, guess = [], None
    for off in offsets:
        eq = line_equilibrium(lengths, weights, axial_stiffness, horizontal_span + off, vertical_span,
                              initial_guess=guess, **options)
        if check is not None:
            check(eq, float(off))
        guess = (eq.H_fairlead, eq._V_A) if eq.H_fairlead > 0 else None
        rows.append(eq)
    return Pushover(offsets, *(np.array([getattr(e, k) for e in rows]) for k in (
        "H_fairlead", "V_fairlead", "fairlead_tension", "touchdown_x", "grounded_length",
        "segment_grounded_length")), np.array([e.stiffness[0, 0] for e in rows]))

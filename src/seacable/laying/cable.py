"""The suspended cable of a laying run: its node storage (:class:`_Cable`), the straight cable it starts from,
the nodes' material coordinates, the tensions at its ends and the seabed's reaction on laid nodes.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from ..errors import InputError
from .kernel import P_CDN, P_DIAMETER, P_WEIGHT
from .parameters import LayParameters
from .span import straight_direction

_MARGIN = 16          # free rows kept below the touchdown node for nodes picked up again


class _Cable:
    """Node storage: rows ``lo .. hi`` of fixed-capacity arrays are the suspended cable."""

    def __init__(self, capacity: int, dim: int):
        self.pos = np.zeros((capacity, dim))
        self.vel = np.zeros((capacity, dim))
        self.s = np.zeros(capacity)
        self.point = np.zeros((capacity, 4))
        self.rep = np.full(capacity, -1, dtype=np.int64)
        self.L = np.zeros(capacity)
        self.T = np.zeros(capacity)
        self.active = np.ones(capacity, dtype=np.int64)
        self.seg_type = np.zeros(capacity, dtype=np.int64)
        self.new_pos = np.zeros((capacity, dim))
        self.new_vel = np.zeros((capacity, dim))
        self.contact = np.zeros(capacity, dtype=np.int64)
        self.normal = np.zeros((capacity, dim))
        self.grip = np.zeros(capacity)
        self.anchor = np.zeros((capacity, dim))
        self.lb = 0
        self.lo = 0
        self.hi = 0
        self._moves = 0                   # how often the arrays were made anew (_move): see window()
        self._window = (None, None)       # (key, views) of window()

    _NAMES = ("pos", "vel", "s", "point", "rep", "L", "T", "active", "seg_type", "new_pos", "new_vel", "contact",
              "normal", "grip", "anchor")

    def _move(self, start: int) -> None:
        """Move rows ``lb .. hi`` to begin at ``start``, doubling the capacity if they do not fit."""
        n = self.hi - self.lb + 1
        cap = self.pos.shape[0]
        new_cap = cap if start + n + 2 * _MARGIN < cap else 2 * (start + n + 2 * _MARGIN)
        for name in self._NAMES:
            a = getattr(self, name)
            b = np.zeros((new_cap,) + a.shape[1:], dtype=a.dtype)
            if name == "rep":
                b[:] = -1
            b[start:start + n] = a[self.lb:self.hi + 1]
            setattr(self, name, b)
        self.lb, self.lo, self.hi = start, start + self.lo - self.lb, start + n - 1
        self._moves += 1

    def window(self) -> tuple[np.ndarray, ...]:
        """Views of the rows ``lb .. hi`` that a step reads and writes: ``pos, vel, point, new_pos, new_vel, contact,
        normal, grip, anchor`` (nodes) and ``L, seg_type, T, active`` (segments), made again only when those rows or
        the arrays change (a step is solved several times over the same rows)."""
        key = (self.lb, self.hi, self._moves)
        if self._window[0] != key:
            n, m = slice(self.lb, self.hi + 1), slice(self.lb, self.hi)
            self._window = (key, (self.pos[n], self.vel[n], self.point[n], self.new_pos[n], self.new_vel[n],
                                  self.contact[n], self.normal[n], self.grip[n], self.anchor[n],
                                  self.L[m], self.seg_type[m], self.T[m], self.active[m]))
        return self._window[1]

    def make_room(self) -> None:
        """Room for a row above ``hi`` (a birth)."""
        if self.hi + 2 >= self.pos.shape[0]:
            self._move(_MARGIN)

    def make_room_below(self) -> None:
        """Room for a row below ``lb`` (a node picked up off the seabed, or laid cable free to slide again)."""
        if self.lb < 1:
            self._move(_MARGIN)


def _initial_tangent(par: LayParameters, track, d: float, speed: float, depth: float,
                     initial_angle: float | None) -> np.ndarray:
    """Unit tangent of the initial straight cable, up towards the ship (``dim`` components).

    Default: the straight lay's direction (paper 001 eq. (7)) for the ship's velocity through the water
    at mid-depth, in the vertical plane of that velocity (:func:`seacable.laying.span.straight_direction`:
    a cross-current turns the plane), vertical at rest. ``initial_angle`` [rad] instead: that angle to the
    horizontal, in the plane of the ship's heading.
    """
    e = track.direction(d)
    if initial_angle is not None:
        return np.concatenate([math.cos(initial_angle) * e, [math.sin(initial_angle)]])
    p = par.props[par.type_at(0.0)]
    c = np.array([np.interp(0.5 * depth, par.current_depths, par.current_velocity[:, k])
                  for k in range(track.dim - 1)])
    across = np.array([-e[1], e[0]]) if track.dim == 3 else np.zeros(1)
    kn = 0.5 * par.water_density * p[P_CDN] * p[P_DIAMETER]
    t1, t2, t3 = straight_direction(p[P_WEIGHT], kn, speed, float(c @ e), float(c @ across) if track.dim == 3 else 0.0)
    h = t1 * e + (t2 * across if track.dim == 3 else 0.0)
    return np.concatenate([h, [t3]])


def _touchdown_distance(track, chute: np.ndarray, t: np.ndarray, step: float) -> float:
    """Length along the straight line from the water entry ``chute`` down along ``-t`` to the seabed. [m]"""
    def f(ell):
        p = chute - ell * t
        return p[-1] - float(track.zb(p[:-1]))
    a, fa = 0.0, f(0.0)
    if fa <= 0.0:
        raise InputError(f"the seabed at the water entry {tuple(round(float(v), 3) for v in chute[:-1])} m is at or "
                         f"above the sea surface (z = {float(track.zb(chute[:-1])):g} m). Suggested fix: check the "
                         "depth or bathymetry.")
    # the first step down the line that reaches the seabed, looked for in blocks of steps (a seabed look-up each)
    done, block = 0, 64
    while done < 10**6:
        ends = [a]
        for _ in range(min(block, 10**6 - done)):
            ends.append(ends[-1] + step)
        p = chute - np.array(ends[1:])[:, None] * t
        # (past the seabed the line may leave a grid: looked up without the grid's check, which comes with f)
        height = p[:, -1] - track.zb(p[:, :-1], strict=False)
        below = np.flatnonzero(~(height > 0.0))
        if below.size:
            k = int(below[0])
            return brentq(f, ends[k], ends[k + 1], xtol=1e-12)
        a = ends[-1]
        done += len(ends) - 1
        block = min(2 * block, 4096)
    raise InputError("the cable from the ship does not reach the seabed within 1e6 segments. "
                     "Suggested fix: check the depth (m) and the segment length (m).")


def _node_coordinates(length: float, seg: float, marks) -> list[float]:
    """Material coordinates of the nodes on [0, length]: every ``seg``, plus the repeaters."""
    s = [0.0]
    marks = sorted(m for m in marks if 0.0 < m < length - 0.5 * seg)
    while True:
        nxt = s[-1] + seg
        pending = [m for m in marks if m > s[-1] + 1e-9]
        if pending and pending[0] - nxt < 0.5 * seg:
            nxt = pending[0]
        if nxt > length - 0.5 * seg:
            break
        s.append(nxt)
    s.append(length)
    return s


def _length(v: np.ndarray) -> float:
    """Length of a vector of a few coordinates: ``numpy.linalg.norm``'s own arithmetic (the square root of
    ``v.dot(v)``, bit for bit), without its checks and dispatch, a few microseconds a call in the time loop. [m]"""
    return math.sqrt(float(v.dot(v)))


def _end_tensions(c: _Cable, props, f_td: float = 0.0) -> tuple[float, float, float]:
    """Tension at the water entry and at the touchdown, and the entry angle to the horizontal [rad].

    The segment tensions are mid-segment values: the top one is moved to the water entry by the
    weight of half a segment, the bottom one to the touchdown (see :func:`_bottom_tension`).
    """
    hi = c.hi
    d_top = c.pos[hi] - c.pos[hi - 1]
    ln_top = _length(d_top)
    # (in Python floats: numpy's float64 arithmetic, to the bit)
    top = (float(c.T[hi - 1]) * int(c.active[hi - 1]) + 0.5 * float(props[c.seg_type[hi - 1], P_WEIGHT])
           * float(c.L[hi - 1]) * float(d_top[-1]) / ln_top)
    bottom = _bottom_tension(c, props, c.pos, c.lo, f_td)
    angle = math.atan2(d_top[-1], _length(d_top[:-1]))
    return top, bottom, angle


def _bottom_tension(c: _Cable, props, pos: np.ndarray, lo: int, f_td: float) -> float:
    """Tension at the touchdown, at the fraction ``f_td`` of the bottom segment (row ``lo`` of
    ``pos``) from the touchdown node: the mid-segment tension moved there by the weight of the cable
    between the two (see :meth:`_Lay.touchdown`). [N]"""
    if not c.active[lo]:
        return 0.0
    d_bot = pos[lo + 1] - pos[lo]
    # (in Python floats: numpy's float64 arithmetic, to the bit)
    return max(float(c.T[lo]) - (0.5 - f_td) * float(props[c.seg_type[lo], P_WEIGHT]) * float(c.L[lo])
               * float(d_bot[-1]) / _length(d_bot), 0.0)


def seabed_reaction(below: np.ndarray, at: np.ndarray, above: np.ndarray, t_below: np.ndarray, t_above: np.ndarray,
                    weight: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """The seabed's normal reaction on nodes ``at`` resting on it, between the nodes ``below`` and ``above``.

    What the node's weight in water ``weight`` [N] and the tensions of its two segments ``t_below``,
    ``t_above`` [N] press into the seabed, whose upward unit normal is ``normal``: ``W n_z - F_T . n``,
    ``F_T`` the tensions' pull along the chords; clipped at 0 (a node pulled off the seabed). Rows are nodes. [N]
    """
    up, down = above - at, at - below
    pull = (t_above / np.linalg.norm(up, axis=1))[:, None] * up - (t_below / np.linalg.norm(down, axis=1))[:, None] * down
    return np.maximum(weight * normal[:, -1] - np.einsum("ij,ij->i", pull, normal), 0.0)

"""Fatigue of a dynamic power cable or umbilical: the armour's stress from tension and curvature, rainflow-counted
at points around the cross-section along the line, an S-N curve and Miner's sum (issue 40).

The stress model is the simple stress resultant a cable maker's data sheet supports: at a point of the armour at
angle ``phi`` around the section,

    sigma(phi) = c_T T + c_kappa kappa (n . e(phi)),

``T`` the effective tension at the node [N], ``kappa`` its curvature [1/m] (the result's ``curvature``: 0 at a pinned
end), ``n`` the unit principal normal of the bend (towards the centre of curvature, from the node's two elements:
``(b - a) / |b - a|`` of the unit directions before and after it; at an end node its neighbour's), ``e(phi) = cos phi
e_1 + sin phi e_2`` the point's direction in the section (``e_1`` horizontal, normal to the line, ``e_2 = t x e_1``;
the section does not twist: seacable models no torsion), ``c_T`` the armour stress per unit tension [Pa/N] (about
``1 / (A_armour cos^2 alpha)`` for wires at lay angle alpha) and ``c_kappa`` the stress per unit curvature [Pa m] (``E
r cos^2 alpha`` while the wires stick, less once they slip: the user gives the value that holds for the ranges at
hand). The point on the inside of the bend (``n . e = 1``) is compressed by the bend when ``c_kappa`` is given
negative: the sign only moves which point is the hot spot, and the damage is the largest over all points.

Cycles: the rainflow count (ASTM E1049-85, the ``rainflow`` package, as :mod:`seacable.design.fatigue`) of each
point's stress record; the S-N curve ``N = a s^-m`` on the stress range ``s`` [MPa], one slope or two (``m2`` below
the range at ``n_knee`` cycles, as DNV-RP-C203's curves in seawater with cathodic protection); Miner's sum, half
cycles counting half. The damage is per record; its life over a scatter diagram is
:func:`seacable.design.fatigue.fatigue_life`'s.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate as v
from ..errors import InputError

__all__ = ["SNCurve", "armour_stress", "cable_fatigue_damage"]


@dataclass(frozen=True)
class SNCurve:
    """An S-N curve on the stress range ``s`` [MPa]: ``N = a s^-m`` above the knee (``n_knee`` cycles), ``N = a2
    s^-m2`` below it with ``a2`` making the curve continuous there; one slope when ``m2`` is None.

    Parameters
    ----------
    a
        Intercept of the first slope. [MPa^m]
    m
        First slope. [-]
    m2
        Second slope, below the knee; None: one slope. [-]
    n_knee
        Cycles at the knee. [1]
    """

    a: float
    m: float
    m2: float | None = None
    n_knee: float = 1e7

    def __post_init__(self):
        v.positive("S-N curve a", self.a, "MPa^m", "give the intercept of N = a s^-m, e.g. 1.0e12")
        v.positive("S-N curve m", self.m, "", "give the slope of N = a s^-m, e.g. 3")
        if self.m2 is not None:
            v.positive("S-N curve m2", self.m2, "", "give the second slope, e.g. 5, or none for one slope")
            v.positive("S-N curve n_knee", self.n_knee, "cycles", "give the cycles at the knee, e.g. 1e7")

    @property
    def knee_range(self) -> float:
        """The stress range at the knee [MPa] (inf for one slope)."""
        return math.inf if self.m2 is None else (self.a / self.n_knee) ** (1.0 / self.m)

    def cycles_to_failure(self, stress_range):
        """Cycles to failure at the stress ranges ``stress_range`` [MPa]. [1]"""
        s = np.asarray(stress_range, float)
        with np.errstate(divide="ignore"):
            first = self.a * s ** -self.m
            if self.m2 is None:
                return first
            knee = self.knee_range
            return np.where(s >= knee, first, self.n_knee * (s / knee) ** -self.m2)


def _unit(vec):
    norm = np.linalg.norm(vec, axis=-1, keepdims=True)
    return np.divide(vec, norm, out=np.zeros_like(vec), where=norm > 0)


def _section_frames(X):
    """Per node of a line's positions ``X`` (time, n, 3): the principal normal ``n`` of the bend and the section
    axes ``e1`` (horizontal, normal to the line) and ``e2 = t x e1``, ``t`` the line's direction there."""
    d = np.diff(X, axis=-2)
    seg = _unit(d)
    t = np.empty_like(X)
    t[..., 1:-1, :] = _unit(seg[..., :-1, :] + seg[..., 1:, :])
    t[..., 0, :], t[..., -1, :] = seg[..., 0, :], seg[..., -1, :]
    normal = np.zeros_like(X)
    normal[..., 1:-1, :] = _unit(seg[..., 1:, :] - seg[..., :-1, :])
    normal[..., 0, :], normal[..., -1, :] = normal[..., 1, :], normal[..., -2, :]
    up = np.array([0.0, 0.0, 1.0])
    e1 = np.cross(t, up)
    flat = np.linalg.norm(e1, axis=-1) < 1e-9  # a vertical line: e1 along x
    e1[flat] = np.cross(t[flat], np.array([0.0, 1.0, 0.0]))
    e1 = _unit(e1)
    return normal, e1, np.cross(t, e1)


def armour_stress(ds, tension_factor: float, curvature_factor: float, *, points: int = 8):
    """The armour's stress (time, node, point) [Pa] of a result with ``curvature`` (see the module): ``c_T`` =
    ``tension_factor`` [Pa/N], ``c_kappa`` = ``curvature_factor`` [Pa m], at ``points`` points evenly around the
    section (angle ``2 pi j / points`` from ``e_1``). A static result (no time) is one time."""
    if "curvature" not in ds:
        raise InputError("the result has no curvature: cable fatigue needs a line with bending stiffness "
                         "(line_types.*.bending_stiffness > 0). Suggested fix: give the cable's EI and run again.")
    v.finite("tension_factor", tension_factor, "Pa/N", "give the armour stress per newton of tension")
    v.finite("curvature_factor", curvature_factor, "Pa m", "give the armour stress per 1/m of curvature")
    if int(points) < 1:
        raise InputError(f"points must be at least 1, got {points}. Suggested fix: 8 points around the section.")
    X = np.stack([np.asarray(ds[c].values, float) for c in ("x", "y", "z")], axis=-1)
    kappa = np.asarray(ds["curvature"].values, float)
    tension = np.asarray(ds["tension"].values, float)
    if X.ndim == 2:
        X, kappa, tension = X[None], kappa[None], tension[None]
    normal, e1, e2 = _section_frames(X)
    phi = 2.0 * math.pi * np.arange(int(points)) / int(points)
    along = (np.einsum("tnk,tnk->tn", normal, e1)[..., None] * np.cos(phi)
             + np.einsum("tnk,tnk->tn", normal, e2)[..., None] * np.sin(phi))
    return tension_factor * tension[..., None] + curvature_factor * kappa[..., None] * along


def cable_fatigue_damage(ds, curve: SNCurve, tension_factor: float, curvature_factor: float, *, points: int = 8):
    """Miner's damage along the line of a dynamic result: per node the largest over ``points`` points around the
    section of the rainflow damage of that point's armour stress record (:func:`armour_stress`), with the S-N
    ``curve``. Returns ``(damage, hot_point)``: (node,) damage of the record [1] and the angle of each node's most
    damaged point [rad]."""
    from .fatigue import tension_cycles  # the rainflow count of a record

    if "time" not in ds.dims:
        raise InputError("cable fatigue needs a time-domain result (mooring_dynamic); this one has no time. "
                         "Suggested fix: run the case as mooring_dynamic.")
    stress = armour_stress(ds, tension_factor, curvature_factor, points=points) / 1e6  # MPa
    n_nodes, n_points = stress.shape[1], stress.shape[2]
    damage = np.zeros((n_nodes, n_points))
    for i in range(n_nodes):
        for j in range(n_points):
            ranges, counts = tension_cycles(stress[:, i, j])
            with np.errstate(divide="ignore"):  # a zero range: infinitely many cycles to failure
                damage[i, j] = float(np.sum(counts / curve.cycles_to_failure(ranges)))
    hot = np.argmax(damage, axis=1)
    return damage[np.arange(n_nodes), hot], 2.0 * math.pi * hot / n_points

"""The static equilibrium of a mooring system as it is returned (:class:`SystemEquilibrium`) and its
stiffness (:func:`system_stiffness`); see :mod:`seacable.system.statics`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...errors import InputError
from ...statics.catenary import CatenaryProfile, CatenaryResult
from .catenary import sub_profile
from .model import Assembly, EquilibriumFields


@dataclass(frozen=True)
class SystemEquilibrium(EquilibriumFields):
    """The static equilibrium of a mooring system.

    Attributes
    ----------
    system, environment
        What was solved.
    body_names : list of str
        Every body (free, fixed, prescribed), in the system's order.
    body_position : ndarray, shape (nb, 6)
        x, y, z [m], roll, pitch, yaw [rad] of each body's reference point.
    free_body_names : list of str
        The free bodies, the order of the stiffness matrices' 6-blocks.
    point_names : list of str
    point_position : ndarray, shape (np, 3)
        Global position of every point (points on bodies included). [m]
    line_names : list of str
    end_a_force, end_b_force : ndarray, shape (nl, 3)
        Force each line exerts on its end A / end B point, global axes. [N]
    end_a_tension, end_b_tension : ndarray, shape (nl,)
        Tension magnitude at each end. [N]
    grounded_length : ndarray, shape (nl,)
        Unstretched length lying on the seabed. [m]
    stiffness : ndarray, shape (6 nbf, 6 nbf)
        Coupled mooring stiffness of the free bodies, free points condensed out (Schur
        complement); translations then small rotations about the global axes, per body. [N/m,
        N/rad, N m/m, N m/rad]
    hydrostatic : ndarray, shape (6 nbf, 6 nbf)
        Restoring of the bodies' weight, buoyancy and waterplane (block diagonal).
    iterations : int
        Newton iterations (all load steps).
    residual : float
        Largest residual, relative to the system's force scale (moments also divided by its
        length scale). [-]
    indeterminate : list of str
        Rotations of free bodies that nothing resists nor loads (a rod's spin about its own axis:
        every line point and its centres of gravity and buoyancy on the axis), held where they
        start; their stiffness is zero.
    pin_reaction : ndarray, shape (nbf, 3)
        Force the pin exerts on each pinned free body (zero for the others), global axes. [N]
    surfaced : list of str
        Free points (and line attachments) floating at the surface z = 0, partly immersed: their
        buoyancy lifts them, their dry weight alone would not.
    """

    _asm: Assembly = field(repr=False)
    _cat: CatenaryResult = field(repr=False)
    _anchor_is_a: np.ndarray = field(repr=False)
    _e: np.ndarray = field(repr=False)
    _node_position: np.ndarray = field(repr=False)
    indeterminate: list = field(default_factory=list)
    pin_reaction: np.ndarray | None = None
    _rounds: tuple = field(default=({}, {}, {}), repr=False)   # (sag cuts, surface cuts, parts in air)
    surfaced: list = field(default_factory=list)

    def anchor_loads(self) -> dict:
        """Loads on the anchors: for each line with an end on a fixed point.

        Returns
        -------
        dict
            ``{line: (horizontal [N], vertical [N] (> 0 uplift), uplift angle [rad])}`` from the
            force the line exerts on that point (end A if both are fixed).
        """
        out = {}
        for i, name in enumerate(self.line_names):
            sl = self.system.lines[name]
            for end, f in (("end_a", self.end_a_force[i]), ("end_b", self.end_b_force[i])):
                if self.system.points[getattr(sl, end)].kind == "fixed":
                    H = float(np.hypot(f[0], f[1]))
                    out[name] = (H, float(f[2]), float(np.arctan2(f[2], H)))
                    break
        return out

    def line_profile(self, line_name: str, n: int = 100):
        """Shape and tension along a line from end A to end B, for plots.

        Parameters
        ----------
        line_name : str
        n : int
            Points, evenly spaced in unstretched arc length, >= 2.

        Returns
        -------
        positions : ndarray, shape (n, 3)
            Global positions. [m]
        tension : ndarray, shape (n,)
            Effective tension (at a clump, the value on one side). [N]
        """
        if line_name not in self.line_names:
            from ..._model import suggest

            raise InputError(f"line '{line_name}' is not in this system (lines: {', '.join(self.line_names)})."
                             f"{suggest(line_name, self.line_names)}")
        n = int(n)
        if n < 2:
            raise InputError(f"n must be >= 2, got {n}. Suggested fix: use 100.")
        asm = self._asm
        il = self.line_names.index(line_name)
        subs = range(asm.line_first[il], asm.line_last[il] + 1)
        total = sum(asm.sub_L[k] for k in subs)
        S, X, T = [], [], []
        for k in subs:
            m = max(4, int(np.ceil(2 * n * asm.sub_L[k] / total)) + 2)
            prof = sub_profile(self._cat, k, m, asm.tables, CatenaryProfile)
            a_is = self._anchor_is_a[k]
            pA = self._node_position[asm.sub_a[k] if a_is else asm.sub_b[k]]
            e = self._e[k]
            s = asm.sub_s0[k] + (prof.s if a_is else asm.sub_L[k] - prof.s)
            order = np.argsort(s, kind="stable")
            pos = np.empty((3, m))   # rows x, y, z: pA + (x e_x, x e_y, z)
            pos[0], pos[1], pos[2] = pA[0] + prof.x * e[0], pA[1] + prof.x * e[1], pA[2] + prof.z
            S.append(s[order])
            X.append(pos[:, order])
            T.append(prof.tension[order])
        if len(S) > 1:
            S, X, T = np.concatenate(S), np.concatenate(X, axis=1), np.concatenate(T)
        else:
            S, X, T = S[0], X[0], T[0]
        s = np.linspace(0.0, total, n)
        pos = np.empty((n, 3))
        for j in range(3):
            pos[:, j] = np.interp(s, S, X[j])
        return pos, np.interp(s, S, T)


def system_stiffness(eq: SystemEquilibrium, hydrostatics: bool = False) -> np.ndarray:
    """Coupled stiffness of all free bodies of an equilibrium (free points condensed out).

    Parameters
    ----------
    eq : SystemEquilibrium
    hydrostatics : bool
        Add the bodies' hydrostatic restoring.

    Returns
    -------
    ndarray, shape (6 nbf, 6 nbf)
    """
    return eq.stiffness + eq.hydrostatic if hydrostatics else eq.stiffness.copy()

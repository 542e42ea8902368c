"""The static equilibrium of a mooring system as it is returned (:class:`SystemEquilibrium`) and its
stiffness (:func:`system_stiffness`); see :mod:`seacable.system.statics`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...errors import InputError
from ...statics.catenary import CatenaryResult
from .catenary import line_profiles
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
        pos, tension = self.line_profiles([line_name], n)
        return pos[0], tension[0]

    def line_profiles(self, line_names=None, n: int = 100):
        """:meth:`line_profile` of several lines at once (default every line), in one compiled call.

        Returns
        -------
        positions : ndarray, shape (len(line_names), n, 3)
            Global positions. [m]
        tension : ndarray, shape (len(line_names), n)
            Effective tension. [N]
        """
        names = self.line_names if line_names is None else list(line_names)
        for name in names:
            if name not in self.line_names:
                from ..._model import suggest

                raise InputError(f"line '{name}' is not in this system (lines: {', '.join(self.line_names)})."
                                 f"{suggest(name, self.line_names)}")
        n = int(n)
        if n < 2:
            raise InputError(f"n must be >= 2, got {n}. Suggested fix: use 100.")
        asm, cat = self._asm, self._cat
        lines = np.array([self.line_names.index(name) for name in names], np.int64)
        pos, tension = np.empty((lines.size, n, 3)), np.empty((lines.size, n))
        if lines.size:
            lo, hi, tT, te = asm.tables if asm.tables is not None else _NO_TABLES
            c = np.ascontiguousarray
            line_profiles(n, lines, asm.line_first, asm.line_last, asm.sub_L, asm.sub_s0, asm.sub_a, asm.sub_b,
                          self._anchor_is_a, self._node_position, c(self._e), c(cat.length), c(cat.horizontal_span),
                          c(cat.vertical_span), c(cat.axial_stiffness), c(cat.weight_per_length),
                          c(cat.seabed_friction), c(cat.H_fairlead), c(cat.V_fairlead), c(cat.grounded_length),
                          c(cat.regime), lo, hi, tT, te, asm.tables is not None, pos, tension)
        return pos, tension


#: the tables' arguments of :func:`~seacable.system.statics.catenary.line_profiles` for a system without tables
_NO_TABLES = (np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros(0), np.zeros(0))


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

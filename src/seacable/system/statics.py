"""Static equilibrium and analytic stiffness of a mooring system (the ``system_static`` engine).

:func:`solve_equilibrium` finds the equilibrium of every free body (6 DOF) and free point
(3 DOF) of a :class:`~seacable.system.model.MooringSystem` under weight, buoyancy, hydrostatics,
external loads and the line forces; :class:`SystemEquilibrium` holds the result: body offsets,
point positions, line end forces and tensions, grounded lengths, anchor loads, and the
stiffness of the free bodies from the analytic line tangents (free points condensed out).

Model
-----
* Each line is split at segment boundaries and attachments into homogeneous sub-lines; each
  sub-line is one elastic catenary (:func:`seacable.statics.catenary.catenary`) in the vertical
  plane through its ends, all sub-lines solved in one vectorised call per Newton iteration.
  A sub-line whose lower end is on the seabed (within 1e-6 x depth) may lie on it, with the
  environment's Coulomb friction; otherwise it hangs free. Attachments become free nodes
  carrying their net weight ``(m - rho V) g``.
* A line type with a strain-tension table (``LineType.tension_strain``) is the elastic catenary
  with strain eps(T): its stretch is the integral of eps(T(s)) along the unstretched length,
  T = sqrt(H^2 + V(s)^2) suspended and T = H - mu w (L_B - s) (down to 0) on the seabed, in
  closed form per piece of the table, with the analytic tangent (:mod:`._stat_cat`). The table is
  taken from the origin (a first point at a strain > 0 is joined to it by a straight line).
  Weightless, buoyant and slack-on-the-seabed parts of a tabled line take its constant EA (a warning
  says so). MoorDyn holds the tension flat beyond the table's last point; an equilibrium that needs
  more tension than that is refused (``NoSolutionError``).
* A free body carries its weight ``m g`` at the centre of gravity and a buoyancy ``rho g V`` at
  the centre of buoyancy (both rotate with the body), a heave restoring
  ``-rho g A_wp (z - z_given)`` at the reference point (``volume`` is the displacement at the
  position given), and a waterplane moment ``rho g (I_xx a_y, -I_yy a_x, 0)``, ``a = R e_z``,
  which is ``-rho g I phi`` for small roll or pitch. With ``I_xx = I_yy = I`` this is exactly
  MoorPy's ``Body`` (buoyancy at the metacentre ``rM``): ``rM = r_CB + (0, 0, I/V)``, MoorPy's
  ``v`` our ``volume``, ``AWP`` our ``waterplane_area``, its heave measured from z = 0 (give
  the body at z = 0 in both). A body with a ``hydrostatic_stiffness`` matrix instead gets
  ``F(q_given) - K_hs (q - q_given)`` with ``F(q_given)`` its weight and buoyancy at the
  position given (Euler angle differences for the rotations).
* Body rotation ``R = Rz(yaw) Ry(pitch) Rx(roll)`` (MoorPy's ``rotationMatrix``). Loads are
  (Fx, Fy, Fz, Mx, My, Mz), global axes, about the reference point.
* Stiffness: ``K = -dF/dq`` with ``q`` = (translations, small rotations about the global axes),
  as MoorPy's ``getStiffnessA``/``getCoupledStiffnessA`` (not symmetric away from equilibrium:
  it contains the moment of the end forces as their arms rotate). At zero rotation the small
  rotations are the Euler angle increments.

* A point (clump, buoy, attachment, a point on a body) above the water (z > 0) weighs its dry
  weight ``m g``: a point is a point, so its buoyancy switches off at z = 0, a step (no partial
  immersion of its volume). The Jacobian has no term for the step (its derivative is zero on
  either side). A free point that rises through z = 0 stops there and is held, as a point landing
  on the seabed, while immersed it is lifted and with its dry weight alone it is not (floating
  partly immersed: the surface takes the difference, and the stiffness holds its height); it is
  released to sink or to rise into the air when either no longer holds
  (``SystemEquilibrium.surfaced``). A point on a body only switches (the body has no such hold).
* A free point (clump, junction, attachment) that reaches the seabed rests on it (its height is
  held while the net force pushes it down, released when it pulls up); it slides without
  friction. A sub-line between two points on the seabed lies flat.
* Equilibrium: Newton on all free DOFs (6 per free body: translations and small rotations about
  the global axes; 3 per free point) with the analytic Jacobian; each sub-line's catenary
  restarts from its previous end forces (compiled, :mod:`._stat_cat`). Steps are clipped per
  body and point (5 % of the longest sub-line, 0.2 rad) and kept if the residual norm grows
  less than tenfold (non-monotone: a line lifting off or a point landing), else halved, then
  replaced by the Newton step scaled as a whole with backtracking; when that fails the external
  loads are ramped up in 5, then 20 steps.

* A pinned free body (``Body.pinned``) keeps its reference point where it is given; only its
  rotations are solved (``SystemEquilibrium.pin_reaction``: the force of the pin). So is a pinned
  prescribed body (MoorDyn's ``CoupledPinned``: the reference point follows the vessel, held at
  ``position`` in statics, the rotations free): its rotations are solved for moment equilibrium, its
  pose is in ``body_position``, and it is not a free body of the result (its rotations are condensed
  out of the stiffness with the free points). A rotation
  that no load resists nor loads - every line point and the centres of gravity and buoyancy on
  one axis through the reference point (a rod's spin about its own axis) - is indeterminate: held
  where it starts and listed in ``SystemEquilibrium.indeterminate``. A body unstable where it
  starts is checked again at the equilibrium (its lines may take load on the way).
* A suspended sub-line whose sag would pass through the seabed gets a node at its lowest point,
  which lands (the catenaries either side touch down there, MoorPy's "U" profile); a line part
  above the water weighs its dry weight ``m g``: a node where a line crosses z = 0, moved to the
  last solution's crossing until it stays (not nearer than 1e-3 x length to another node).
* ``max_strain`` (default 1) bounds the strain a line may take; a soft spring line needs more.
  Where Newton has no step (a weightless slack line at its length) the step follows the forces.

Not modelled here (refused with an ``InputError``): current (no drag on the catenaries), a
sloping seabed, line ends inside the seabed, lines without EA. A buoyant sub-line is not
checked against rising above the surface. The system analyses (``system_static``,
``system_offsets``, damaged lines; :mod:`seacable.system.run`) solve a current or a sloping seabed
with the finite-element statics instead (:mod:`seacable.system._stat_fe`: the coupled
finite-element lines and bodies at rest, stiffness by central differences of equilibria).

References
----------
.. [1] M. Hall et al., MoorPy (NREL), ``moorpy/body.py`` (``getForces``, ``getStiffnessA``),
   ``moorpy/system.py`` (``solveEquilibrium``, ``getCoupledStiffnessA``), v1.3.0.
.. [2] J. Jonkman, "Definition of the Floating System for Phase IV of OC3",
   NREL/TP-500-47535, 2010.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field, replace

import numpy as np

from ..environment import Environment
from ..errors import ConvergenceError, InputError, NoSolutionError, SeacableWarning
from ..statics.catenary import CatenaryProfile, CatenaryRegime, CatenaryResult
from . import _stat_kernel as _kern
from ._stat_cat import sub_profile, table_strain
from ._stat_eval import Evaluation, State, body_data, evaluate, node_positions
from ._stat_model import BODY, Assembly, EquilibriumFields, assemble, euler, rotation
from .model import MooringSystem

__all__ = ["SystemEquilibrium", "check_statics", "solve_equilibrium", "system_stiffness"]

_DOF = ("surge", "sway", "heave", "roll", "pitch", "yaw")


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
            from .._model import suggest

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
            pos = pA + np.column_stack([prof.x * e[0], prof.x * e[1], prof.z])
            s = asm.sub_s0[k] + (prof.s if a_is else asm.sub_L[k] - prof.s)
            order = np.argsort(s, kind="stable")
            S.append(s[order])
            X.append(pos[order])
            T.append(prof.tension[order])
        S, X, T = np.concatenate(S), np.concatenate(X), np.concatenate(T)
        s = np.linspace(0.0, total, n)
        pos = np.column_stack([np.interp(s, S, X[:, j]) for j in range(3)])
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


# ---------------------------------------------------------------------------------------------


class _Problem:
    """Newton iteration on the free DOFs of an assembled system."""

    def __init__(self, system, env, external, tol, max_iter, cuts=None, max_strain=1.0, air=None):
        self.system, self.env = system, env
        self.max_strain = max_strain
        self.asm, base = _assembly(system, env, cuts, air)
        _check_external(system, self.asm, external)
        self.bd = base
        if external:
            ext = base.external.copy()
            for name, load in external.items():
                ext[self.asm.free_bodies.index(self.asm.body_names.index(name))] += np.asarray(load, float)
            self.bd = replace(base, external=ext, external_scale=float(np.abs(ext).max(initial=0.0)))
        self.tol, self.max_iter = tol, max_iter
        asm = self.asm
        self.nb = len(asm.free_bodies)
        self.nfree = asm.free_nodes.size
        const = getattr(asm, "_problem_constants", None)
        if const is None:
            # what depends on the assembly only (kept with it in the cache): scales, the moments'
            # weights, the pinned bodies and the indeterminate rotations
            reach = [np.abs(asm.node_rel[asm.node_kind == 1]).max(initial=0.0)]
            reach += [np.abs(base.rcg).max(initial=0.0), np.abs(base.rcb).max(initial=0.0)]
            length_scale = max(1.0, *reach)
            weights = np.ones(6 * self.nb + 3 * self.nfree)     # 1 / length scale on the moments
            for k in range(self.nb):
                weights[6 * k + 3:6 * k + 6] = 1.0 / length_scale
            weights.flags.writeable = False
            # held DOFs: a pinned body's translations; rotations about an axis that no load has an arm
            # about (every point, the centre of gravity and of buoyancy on it: a rod's spin), indeterminate
            bodies = [system.bodies[asm.body_names[i]] for i in asm.free_bodies]
            pinned = np.array([b.pinned for b in bodies], bool)
            spin = [_indeterminate_rotations(asm, k, b) for k, b in enumerate(bodies)]
            const = (length_scale, max(1.0, 0.05 * float(asm.sub_L.max(initial=0.0))), weights, pinned, spin,
                     float(np.abs(asm.node_force).max(initial=0.0)))
            asm._problem_constants = const
        self.length_scale, self.step_len, self.weights, self.pinned, spin, asm._force_max = const
        self.spin = list(spin)
        self.any_held = bool(self.pinned.any()) or any(a.size for a in self.spin)
        self.depth_nan = np.nan if asm.depth is None else float(asm.depth)
        # nodes whose buoyancy switches off above the water
        self.floats = np.zeros(asm.node_kind.size, bool) if asm.node_buoy is None else asm.node_buoy > 0
        self.iterations = 0
        self.refused = ""         # why the last refused trial step was refused (a line that cannot reach)
        self.warm = None          # last end forces of every sub-line: the catenaries' next start
        self.spin_k = 1.0         # stiffness the indeterminate rotations are held with [N m/rad], set per evaluation

    def initial_state(self, initial: SystemEquilibrium | None) -> State:
        asm = self.asm
        nb = self.nb
        X = np.zeros((nb, 3))
        R = np.zeros((nb, 3, 3))
        P = asm.node_pos0.copy()
        for k, i in enumerate(asm.free_bodies):
            q = np.asarray(self.system.bodies[asm.body_names[i]].position, float)
            if initial is not None:
                q = initial.body_position[i]
            X[k], R[k] = q[:3], rotation(q[3:])
        if initial is not None and initial._node_position.shape == P.shape:
            P[asm.free_nodes] = initial._node_position[asm.free_nodes]
        grounded = np.zeros(P.shape[0], bool)
        if asm.depth is not None:
            low = P[asm.free_nodes, 2] <= -asm.depth
            P[asm.free_nodes[low], 2] = -asm.depth
            grounded[asm.free_nodes[low]] = True
        return State(X, R, P, grounded, np.zeros(P.shape[0], bool))

    def _z_dof(self, st: State) -> np.ndarray:
        """DOF indices of the z of the free nodes held on the seabed or at the surface."""
        if not (st.grounded.any() or st.surfaced.any()):
            return _NO_DOF
        held = st.grounded | st.surfaced
        j = np.flatnonzero(held[self.asm.free_nodes])
        return 6 * self.nb + 3 * j + 2

    def point_dofs(self, st: State) -> np.ndarray:
        """DOF indices of the free points that are not held on the seabed or at the surface (condensed out)."""
        allp = np.arange(6 * self.nb, 6 * self.nb + 3 * self.nfree)
        if not self.nfree or not (st.grounded.any() or st.surfaced.any()):
            return allp
        return np.setdiff1d(allp, self._z_dof(st))

    def eval(self, st: State, load: float) -> Evaluation:
        ev = evaluate(self.asm, self.bd, st, load_factor=load, warm=self.warm, max_strain=self.max_strain)
        self.warm = (ev.cat.H_fairlead, ev.cat.V_fairlead)
        self._hold(st, ev)
        zd = self._z_dof(st)
        if zd.size:
            # a grounded node pushed down rests (the seabed takes it); pulled up it lifts off. A node
            # stopped at the surface (counted immersed) stays there while its buoyancy lifts it and its
            # dry weight alone would not (partly immersed: the surface takes the difference); it sinks
            # when immersed it is pulled down, and rises into the air when its dry weight alone is lifted
            node = self.asm.free_nodes[(zd - 6 * self.nb) // 3]
            res = ev.residual[zd]
            if st.surfaced.any():
                lift = np.where(st.grounded[node], res > 0, (res <= 0) | (res - self.asm.node_buoy[node] > 0))
            else:
                lift = res > 0
            if lift.any():
                st.grounded[node[lift]] = False
                st.surfaced[node[lift]] = False
            zd = zd[~lift]
            ev.residual[zd] = 0.0
            for J in (ev.jac, ev.jac_lines):
                J[zd, :] = 0.0
                J[:, zd] = 0.0
                J[zd, zd] = 1.0
        ev.scaled = ev.residual * self.weights / ev.scale
        return ev

    def _hold(self, st: State, ev: Evaluation) -> None:
        """Hold a pinned body's translations (the residual there is the pin's reaction, kept in
        ``ev.reaction``) and give the indeterminate rotations a stiffness in the Newton Jacobian only
        (their moment is zero whatever the rotation, so the step has no component along them)."""
        ev.reaction = np.zeros((self.nb, 3))
        if not self.any_held:
            return
        for k in np.flatnonzero(self.pinned):
            t = slice(6 * k, 6 * k + 3)
            ev.reaction[k] = -ev.residual[t]
            ev.residual[t] = 0.0
            ev.jac[t, :] = 0.0
            ev.jac[:, t] = 0.0
            ev.jac[t, t] = np.eye(3)
        if not any(a.size for a in self.spin):
            return
        self.spin_k = ev.scale * self.length_scale
        for k, axes in enumerate(self.spin):
            if axes.size:
                A = st.R[k] @ axes.T          # global directions of the indeterminate rotations
                r = slice(6 * k + 3, 6 * k + 6)
                ev.jac[r, r] -= self.spin_k * (A @ A.T)

    def held_rotations(self, st: State) -> list:
        """The indeterminate rotations, for the result: '<body>: rotation about (ax, ay, az) (global)'."""
        out = []
        for k, axes in enumerate(self.spin):
            name = self.asm.body_names[self.asm.free_bodies[k]]
            for a in axes:
                g = st.R[k] @ a
                g = np.where(np.abs(g) < 1e-9, 0.0, g) + 0.0
                out.append(f"{name}: rotation about ({g[0]:.4g}, {g[1]:.4g}, {g[2]:.4g}) (global axes)")
        return out

    def error(self, ev: Evaluation) -> float:
        """Largest residual relative to the force scale (moments also to the length scale)."""
        return float(np.abs(self._scaled(ev)).max(initial=0.0))

    def step(self, st: State, dq: np.ndarray, alpha: float) -> State:
        X, R, P = np.empty_like(st.X), np.empty_like(st.R), np.empty_like(st.P)
        grounded = st.grounded.copy()
        surfaced = st.surfaced.copy()
        _kern.step_state(st.X, st.R, st.P, dq, float(alpha), self.asm.free_nodes, self.depth_nan, X, R, P, grounded,
                         self.floats, surfaced)
        return State(X, R, P, grounded, surfaced)

    def newton(self, st: State, load: float, ev: Evaluation | None = None):
        """Newton with step limits and backtracking; returns (state, evaluation, converged).

        ``ev``: the evaluation at ``st`` if already made (with the same load).
        """
        if ev is None:
            ev = self.eval(st, load)
        err = self.error(ev)
        stalls = 0
        for _ in range(self.max_iter):
            if err <= self.tol:
                return st, ev, True
            self.iterations += 1
            try:
                dq = _kern.solve(ev.jac, -ev.residual)
            except np.linalg.LinAlgError:
                # singular or not finite: numpy's own solve, least squares if singular
                try:
                    dq = np.linalg.solve(ev.jac, -ev.residual)
                except np.linalg.LinAlgError:
                    dq = np.linalg.lstsq(ev.jac, -ev.residual, rcond=None)[0]
            if not np.all(np.isfinite(dq)):
                return st, ev, False
            if np.abs(dq).max(initial=0.0) <= 1e-12 * self.step_len:
                # no Newton step though the residual is not zero: nothing resists yet (a weightless line
                # exactly at its length, slack, carrying a weight): move along the net forces instead
                g = self._scaled(ev)
                dq = g / np.abs(g).max() * self.step_len
            merit = _norm(self._scaled(ev))
            accepted = fallback = None
            # the step clipped per object (translations to step_len, rotations to 0.2 rad); kept
            # if the residual norm grows less than GROWTH-fold (a change of regime - a line lifting
            # off, a point landing - makes it non-monotone), else halved, then the Newton
            # direction scaled as a whole (a descent direction of the norm) with backtracking
            alpha = 1.0
            cand = self.clip(dq)
            for trial_n in range(8):
                if trial_n == 3:
                    cand, alpha = dq * self.uniform_limit(dq), 1.0
                trial = self.step(st, cand, alpha)
                alpha *= 0.5
                try:
                    ev2 = self.eval(trial, load)
                except (NoSolutionError, ConvergenceError) as err:
                    self.refused = str(err)
                    continue
                if fallback is None:
                    fallback = (trial, ev2)
                m2 = _norm(self._scaled(ev2))
                if m2 < (_GROWTH if trial_n < 3 else 1.0) * merit:
                    accepted = (trial, ev2)
                    stalls = stalls + 1 if m2 >= merit else 0
                    break
            if accepted is None:
                # no trial acceptable: take the clipped step anyway (a stiff line pulled round a
                # pendulum's arc grows the residual at any step along the tangent), counted as a stall
                stalls += 1
                accepted = fallback
            if accepted is None or stalls > 30:
                return st, ev, False
            st, ev = accepted
            err = self.error(ev)
        return st, ev, err <= self.tol

    def uniform_limit(self, dq):
        """Factor that brings the largest translation to step_len and rotation to 0.2 rad."""
        return float(_kern.uniform_limit(dq, self.nb, float(self.step_len)))

    def clip(self, dq):
        """Step limits per object: translations to step_len, rotations to 0.2 rad."""
        out = np.empty_like(dq)
        _kern.clip_step(dq, self.nb, float(self.step_len), out)
        return out

    def _scaled(self, ev):
        if ev.scaled is not None:
            return ev.scaled
        return ev.residual * self.weights / ev.scale


_NO_DOF = np.zeros(0, int)
_NO_DOF.flags.writeable = False
_GROWTH = 10.0     # a clipped Newton step may raise the residual norm this much (non-monotone)
_CACHE: dict = {}


def _assembly(system: MooringSystem, env: Environment, cuts: dict | None = None, air: dict | None = None):
    """The flattened system and its bodies' constants, kept for the last few (system, environment,
    added cuts, parts in air) (the models are frozen)."""
    cuts = {k: tuple(v) for k, v in sorted((cuts or {}).items())}
    air = {k: tuple(v) for k, v in sorted((air or {}).items())}
    key = (id(system), id(env), tuple(cuts.items()), tuple(air.items()))
    hit = _CACHE.get(key)
    if hit is not None and hit[0] is system and hit[1] is env:
        return hit[2], hit[3]
    asm = assemble(system, env, cuts, air)
    base = body_data(asm, system, None)
    if len(_CACHE) >= 8:
        _CACHE.pop(next(iter(_CACHE)))
    _CACHE[key] = (system, env, asm, base)
    return asm, base


def _norm(v) -> float:
    return math.sqrt(float(np.dot(v, v)))


def _rotvec(th) -> np.ndarray:
    """Rotation matrix of the rotation vector th (Rodrigues)."""
    a = float(np.linalg.norm(th))
    if a < 1e-300:
        return np.eye(3)
    k = th / a
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + np.sin(a) * K + (1 - np.cos(a)) * (K @ K)


def _indeterminate_rotations(asm, k: int, body) -> np.ndarray:
    """Body-frame unit axes (m, 3) of the rotations of free body ``k`` that nothing resists nor loads.

    A rotation about the reference point along ``n`` changes the moment along ``n`` of no load
    applied at ``r`` with ``n x r = 0``: when every line point, the centre of gravity (with mass) and
    of buoyancy (with volume) lie on one line through the reference point, the rotation about that
    line (a rod's spin) is indeterminate; all three when they are all at the reference point. The
    waterplane moment depends on the body z axis only: it leaves the spin about body z free (with
    I_xx = I_yy, which makes its moment along that axis zero) and no other. A user hydrostatic
    matrix decides for itself (nothing held).
    """
    if body.hydrostatic_stiffness is not None:
        return np.zeros((0, 3))
    arms = [asm.node_rel[n] for n in np.flatnonzero((asm.node_kind == BODY) & (asm.node_body == k))]
    if body.mass > 0:
        arms.append(np.asarray(body.center_of_gravity, float))
    if body.volume > 0:
        arms.append(np.asarray(body.center_of_buoyancy, float))
    arms = np.array(arms, float).reshape(-1, 3)
    size = max(float(np.abs(arms).max(initial=0.0)), 1e-300)
    arms = arms[np.linalg.norm(arms, axis=1) > 1e-9 * size]
    if arms.size == 0:
        axes = np.eye(3)
    else:
        n = arms[np.argmax(np.linalg.norm(arms, axis=1))]
        n = n / np.linalg.norm(n)
        if np.abs(np.cross(arms, n)).max() > 1e-9 * size:
            return np.zeros((0, 3))
        axes = n[None, :]
    if any(body.waterplane_moments):
        ixx, iyy = body.waterplane_moments
        keep = [a for a in axes if abs(a[0]) < 1e-12 and abs(a[1]) < 1e-12 and abs(ixx - iyy) <= 1e-12 * abs(ixx)]
        axes = np.array([[0.0, 0.0, 1.0]]) if keep else np.zeros((0, 3))
    return axes


def _check_external(system, asm, external):
    for name, load in (external or {}).items():
        if name not in system.bodies or system.bodies[name].kind != "free":
            from .._model import suggest

            free = [asm.body_names[i] for i in asm.free_bodies]
            raise InputError(f"external['{name}']: no free body of that name (free bodies: "
                             f"{', '.join(free) or 'none'}).{suggest(name, free)} Suggested fix: name a free body.")
        arr = np.asarray(load, float)
        if arr.shape != (6,) or not np.all(np.isfinite(arr)):
            raise InputError(f"external['{name}'] must be 6 finite numbers (Fx, Fy, Fz [N], Mx, My, Mz [N m]), "
                             f"got {load!r}. Suggested fix: give a 6-component load in global axes.")


def _condense(K: np.ndarray, nb, keep_points: np.ndarray) -> np.ndarray:
    """Schur complement of the free-point DOFs: K_bb - K_bp K_pp^-1 K_pb (``nb``: the number of bodies,
    whose DOFs are the first 6 nb, or the body DOF indices to keep)."""
    b = np.arange(6 * nb) if np.ndim(nb) == 0 else np.asarray(nb, int)
    p = keep_points
    if p.size == 0:
        return K[:b.size, :b.size].copy()
    Kpp = K[np.ix_(p, p)]
    Kpb = K[np.ix_(p, b)]
    try:
        X = np.linalg.solve(Kpp, Kpb)
    except np.linalg.LinAlgError:
        X = np.linalg.lstsq(Kpp, Kpb, rcond=None)[0]
    return K[np.ix_(b, b)] - K[np.ix_(b, p)] @ X


def _check_stability(prob: _Problem, st: State, ev: Evaluation) -> None:
    """Refuse a body DOF whose hydrostatics is unstable (or absent under a load) with no mooring."""
    nb = prob.nb
    if nb == 0:
        return
    hyd = ev.hydro
    moor = _condense(-ev.jac_lines, nb, prob.point_dofs(st))
    for k, axes in enumerate(prob.spin):
        if not axes.size:
            continue
        A = st.R[k] @ axes.T
        r = slice(6 * k + 3, 6 * k + 6)
        moment = A.T @ ev.residual[r]
        if np.abs(moment).max() > prob.tol * ev.scale * prob.length_scale:
            name = prob.asm.body_names[prob.asm.free_bodies[k]]
            a = A[:, int(np.argmax(np.abs(moment)))]
            raise InputError(
                f"bodies.{name}: nothing resists a rotation about ({a[0]:.4g}, {a[1]:.4g}, {a[2]:.4g}) (global axes; "
                "every line point, the centre of gravity and of buoyancy are on that axis) but a moment of "
                f"{np.abs(moment).max():.4g} N m loads it there, so the body spins without end. Suggested fix: "
                "remove the moment about the axis from external_force, or attach a line off the axis.")
        moor[r, r] += prob.spin_k * (A @ A.T)
    dh, dm = np.diag(hyd), np.diag(moor)
    tot = dh + dm
    # reference per kind of DOF: the largest diagonal term of any body's translations / rotations
    ah, am = np.abs(dh).reshape(nb, 6), np.abs(dm).reshape(nb, 6)
    refs = [max(float(ah[:, sl].max()), float(am[:, sl].max()), 1e-300) for sl in (slice(0, 3), slice(3, 6))]
    ref_dof = np.tile(np.repeat(refs, 3), nb)
    weak = ~(tot > 1e-9 * ref_dof)
    weak.reshape(nb, 6)[prob.pinned, :3] = False      # held by the pin
    for i in np.flatnonzero(weak):
        k, j = divmod(int(i), 6)
        name = prob.asm.body_names[prob.asm.free_bodies[k]]
        unit = "N/m" if j < 3 else "N m/rad"
        if hyd[i, i] < 0 and tot[i] < 0:
            raise InputError(
                f"bodies.{name}: the hydrostatic stiffness in {_DOF[j]} is {hyd[i, i]:.4g} {unit} (unstable: "
                f"the centre of gravity is too high for the buoyancy and waterplane) and the lines add "
                f"only {moor[i, i]:.4g} {unit}, so the body capsizes. Suggested fix: check "
                "center_of_gravity, center_of_buoyancy and waterplane_moments (or hydrostatic_stiffness), "
                "or moor the body so the lines restore it.")
        if abs(ev.residual[i]) > prob.tol * ev.scale * (1 if j < 3 else prob.length_scale):
            raise InputError(
                f"bodies.{name}: nothing restores the body in {_DOF[j]} (hydrostatic {hyd[i, i]:.4g} {unit}, "
                f"lines {moor[i, i]:.4g} {unit}) but it is loaded there by {ev.residual[i]:.4g} "
                f"{'N' if j < 3 else 'N m'}, so it has no equilibrium. Suggested fix: add waterplane_area/"
                "waterplane_moments or a hydrostatic_stiffness, attach the lines away from the reference "
                "point, or remove the load.")


def check_statics(system: MooringSystem, environment: Environment, *, external: dict | None = None,
                  max_strain: float = 1.0) -> None:
    """Every check :func:`solve_equilibrium` makes before iterating, without solving.

    For a ``prepare_<analysis>`` step (``seacable validate``): what the catenary lines cannot
    model (current, sloping seabed, no EA), points below the seabed, unknown bodies in
    ``external``, lines that cannot reach at the starting positions, and bodies that are
    hydrostatically unstable with no mooring restoring (or loaded in a DOF nothing restores).

    Raises
    ------
    InputError, NoSolutionError
        As :func:`solve_equilibrium`.
    """
    max_strain = _check_max_strain(max_strain)
    prob = _Problem(system, environment, external, 1e-8, 1, max_strain=max_strain)
    st0 = prob.initial_state(None)
    try:
        ev0 = prob.eval(st0, 1.0)
    except NoSolutionError as err:
        raise NoSolutionError(f"at the starting positions: {err} (Or start the bodies and free points where "
                              "every line can reach.)") from None
    try:
        _check_stability(prob, st0, ev0)
    except InputError:
        # a body unstable where it starts may be restored once the lines take load (a rod hanging from
        # a line that is unloaded at the start): the solve decides, as solve_equilibrium does
        solve_equilibrium(system, environment, external=external, max_strain=max_strain)


def _check_max_strain(max_strain) -> float:
    m = float(max_strain)
    if not (m > 0 and np.isfinite(m)):
        raise InputError(f"max_strain must be > 0, got {max_strain!r}. Suggested fix: use 1.0 (100 %), or more "
                         "for a soft spring line (a MoorDyn spring test).")
    return m


def solve_equilibrium(system: MooringSystem, environment: Environment, *, external: dict | None = None,
                      tol: float = 1e-8, max_iter: int = 200,
                      initial: SystemEquilibrium | None = None, max_strain: float = 1.0) -> SystemEquilibrium:
    """Static equilibrium of every free body and free point of a mooring system.

    Parameters
    ----------
    system : MooringSystem
    environment : Environment
        Water density, gravity, depth, seabed friction (no current, flat seabed: for those,
        :func:`seacable.system._stat_fe.fe_equilibrium`).
    external : dict, optional
        ``{body name: (Fx, Fy, Fz, Mx, My, Mz)}`` loads added to the named free bodies, global
        axes, about the reference point, on top of ``Body.external_force``. [N, N m]
    tol : float
        Largest residual force relative to the system's force scale (the largest line end
        force, weight, buoyancy or load; moments also divided by its length scale). [-]
    max_iter : int
        Newton iterations per load step.
    initial : SystemEquilibrium, optional
        A previous solution of the same system to start from (sweeps).
    max_strain : float
        Largest strain T/EA a line may take; a line that would need more cannot reach
        (``NoSolutionError``). Raise it for a soft spring line (a line above 10 % warns). [-]

    Returns
    -------
    SystemEquilibrium

    Raises
    ------
    InputError
        What the catenary lines cannot model, unknown body names in ``external``, an unstable
        body with no mooring restoring.
    NoSolutionError
        A line cannot reach at the starting positions, or the equilibrium needs a tension above the
        last point of a line's strain-tension table.
    ConvergenceError
        No equilibrium found with a plain Newton iteration nor a load ramp; names the residual
        and the last offset of each body.
    """
    tol = float(tol)
    if not (tol > 0 and np.isfinite(tol)):
        raise InputError(f"tol must be > 0, got {tol!r}. Suggested fix: use 1e-8.")
    max_iter = int(max_iter)
    if max_iter < 1:
        raise InputError(f"max_iter must be >= 1, got {max_iter}. Suggested fix: use 200.")
    max_strain = _check_max_strain(max_strain)
    if initial is not None and initial.system is not system:
        raise InputError("initial must be an equilibrium of the same system object. Suggested fix: pass the "
                         "previous solve_equilibrium result of this system, or None.")
    # a line sagging into the seabed between its nodes gets a node at its lowest point, where it may
    # land (the catenaries either side then touch down there): split before solving if it sags at
    # the start, and after solving if it sags at the equilibrium, at most _SAG_ROUNDS times
    cuts, surf, air = initial._rounds if initial is not None else ({}, {}, {})
    sag_rounds = surf_rounds = 0
    while True:
        prob = _Problem(system, environment, external, tol, max_iter, _merge_cuts(cuts, surf), max_strain, air)
        st0 = prob.initial_state(initial)
        try:
            ev0 = prob.eval(st0, 1.0)
        except NoSolutionError as err:
            raise NoSolutionError(f"at the starting positions: {err} (Or start the bodies and free points where "
                                  "every line can reach.)") from None
        more = _sag_cuts(prob, st0, ev0) if sag_rounds < _SAG_ROUNDS else {}
        if more:
            cuts = _merge_cuts(cuts, more)
            sag_rounds += 1
            continue
        try:
            _check_stability(prob, st0, ev0)
            unstable_start = None
        except InputError as err:
            # unstable where it starts, maybe not at equilibrium (lines unloaded at the start): solve, then
            # check the equilibrium; refuse with this message if no stable equilibrium is found
            unstable_start = err
        st, ev, ok = prob.newton(st0, 1.0, ev0)
        if not ok:
            # load ramp: external loads in steps from zero, each step from the last solution
            for n_steps in (5, 20):
                s = prob.initial_state(initial)
                good = True
                for lam in np.linspace(1.0 / n_steps, 1.0, n_steps):
                    s, ev, good = prob.newton(s, float(lam))
                    if not good:
                        break
                st = s
                if good:
                    ok = True
                    break
        if unstable_start is not None:
            if not ok:
                raise unstable_start
            try:
                _check_stability(prob, st, ev)
            except InputError as err:
                raise InputError(f"at the equilibrium found: {err}") from None
        more = _sag_cuts(prob, st, ev) if sag_rounds < _SAG_ROUNDS else {}
        if more:
            cuts = _merge_cuts(cuts, more)
            sag_rounds += 1
            continue
        # parts of lines above the water weigh their dry weight: a node where a line crosses the
        # surface, moved to where the last solution crosses it until it stays (a fixed point)
        if ok:
            new_surf, new_air = _surface(prob, st, ev, cuts)
            if not _same_split(new_surf, surf, new_air, air, prob.asm):
                if surf_rounds == _SURFACE_ROUNDS:
                    raise NoSolutionError(_floating(prob, new_air or air))
                surf, air = new_surf, new_air
                surf_rounds += 1
                continue
        break
    beyond = _beyond_table(prob, ev)
    if beyond:
        raise NoSolutionError(beyond)
    if not ok:
        err = prob.error(ev)
        offs = []
        for k, i in enumerate(prob.asm.free_bodies):
            name = prob.asm.body_names[i]
            q0 = np.asarray(system.bodies[name].position, float)
            d = np.concatenate([st.X[k] - q0[:3], np.degrees(euler(st.R[k]) - q0[3:])])
            offs.append(f"{name}: ({d[0]:.4g}, {d[1]:.4g}, {d[2]:.4g}) m, ({d[3]:.3g}, {d[4]:.3g}, {d[5]:.3g}) deg")
        raise ConvergenceError(
            f"system statics did not converge: residual {err:.3g} x force scale ({ev.scale:.4g} N) after "
            f"{prob.iterations} Newton iterations with a load ramp (tol {tol:g}); last offsets "
            f"{'; '.join(offs) or '(no free body)'}. Suggested fix: apply the load in smaller steps by "
            "sweeping with `initial=`, start the bodies nearer their equilibrium, check that the lines are "
            "long enough (a line pulled taut) or not so slack that a point has no restoring, or raise max_iter."
            + (f" The last step refused was: {prob.refused}" if prob.refused else ""),
            iterations=prob.iterations, residual=err)
    eq = _result(prob, st, ev, (cuts, surf, air))
    _warn_strain(eq)
    return eq


def _beyond_table(prob: _Problem, ev: Evaluation) -> str:
    """The message for a line whose tension exceeds the last point of its strain-tension table at the
    state reached (a solution or the last iterate), else ''."""
    asm = prob.asm
    if asm.tables is None:
        return ""
    lo, hi, tT, te = asm.tables
    T = np.maximum(ev.cat.fairlead_tension, ev.cat.anchor_tension)
    worst, over = -1, 0.0
    for k in np.flatnonzero(hi > lo):
        r = T[k] / tT[hi[k] - 1]
        if r > 1.0 + 1e-9 and r > over:
            worst, over = int(k), r
    if worst < 0:
        return ""
    name = asm.line_names[asm.sub_line[worst]]
    t_last, e_last = tT[hi[worst] - 1], te[hi[worst] - 1]
    loads = [f"{asm.body_names[i]}: |F| = {np.linalg.norm(prob.bd.external[k, :3]):.4g} N"
             for k, i in enumerate(asm.free_bodies) if np.any(prob.bd.external[k])]
    il = int(asm.sub_line[worst])
    held = all(asm.node_kind[n] == 0 for n in (asm.sub_a[asm.line_first[il]], asm.sub_b[asm.line_last[il]]))
    load = ("the external load on " + ", ".join(loads)) if loads else \
        ("the positions of its held ends" if held else "the weights, buoyancy and point loads")
    verb = "need" if load.startswith(("the positions", "the weights")) else "needs"
    return (f"lines.{name}: no static equilibrium: {load} {verb} a tension of {T[worst]:.6g} N in this line, above "
            f"the last point of its tension-strain table ({t_last:.6g} N at strain {e_last:.4g}); beyond the table "
            "the tension is held flat (as MoorDyn), so the line yields without end. Suggested fix: extend the "
            "table to the strains this load needs, or reduce the load (or share it among more lines).")


_SURFACE_ROUNDS = 8     # times the surface crossings of lines are moved to the last solution's


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
_SAG_ROUNDS = 3         # times lines sagging into the seabed are split and the system solved again


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


_STRAIN_WARN = 0.1      # a mooring line stretched by more than 10 % is almost surely an input slip


def _warn_strain(eq: SystemEquilibrium) -> None:
    """Warn about lines stretched beyond 10 %, loaded beyond their breaking load, or sagging into the seabed."""
    asm = eq._asm
    T = np.maximum(eq._cat.fairlead_tension, eq._cat.anchor_tension)
    strain = T / asm.sub_EA
    if asm.tables is not None:
        tabled = np.flatnonzero(asm.tables[1] > asm.tables[0])
        for k in tabled:
            strain[k] = table_strain(T[k], k, asm.tables)[0]
        # tabled sub-lines the catenary kernel leaves to the public function (constant EA): buoyant,
        # weightless, slack on the seabed
        approx = [k for k in tabled if int(eq._cat.regime[k]) not in (1, 2, 3, 5, 6) or asm.sub_w[k] <= 0]
        if approx:
            name = asm.line_names[asm.sub_line[approx[0]]]
            warnings.warn(f"lines.{name}: its tension-strain table is applied exactly to weighty lines hanging or "
                          "lying on the seabed under tension; this part (buoyant, weightless, or slack on the "
                          f"seabed: {CatenaryRegime(int(eq._cat.regime[approx[0]])).name}) takes the constant EA "
                          f"{asm.sub_EA[approx[0]]:.4g} N (axial_stiffness, else the table's secant). Suggested fix: "
                          "none needed at low tension; give axial_stiffness as the slope at the tension expected.",
                          SeacableWarning, stacklevel=3)
    k = int(np.argmax(strain)) if strain.size else -1
    if k >= 0 and strain[k] > _STRAIN_WARN:
        name = asm.line_names[asm.sub_line[k]]
        warnings.warn(f"lines.{name}: stretched by {100 * strain[k]:.3g} % at equilibrium (tension {T[k]:.4g} N, "
                      f"EA {asm.sub_EA[k]:.4g} N): the line is pulled almost straight between its ends, or is a soft "
                      "spring. Suggested fix: check its length, EA and its end positions (or the load on the "
                      "bodies); a spring line stretched so far is fine.",
                      SeacableWarning, stacklevel=3)
    cat = eq._cat
    depth = eq.environment.depth
    if depth is not None:
        # a mid-water sub-line sagging below its lower end (V_A < 0) must not reach the seabed,
        # which it would cross unnoticed (seabed=False): lowest point of the elastic catenary
        H, VA, w = cat.H_anchor, cat.V_anchor, asm.sub_w
        sag = (~cat.seabed) & (w > 0) & (VA < 0) & (H > 0) & (cat.regime == _SUSPENDED)
        if sag.any():
            Hs, Vs, ws = H[sag], VA[sag], w[sag]
            dip = Hs / ws * (np.hypot(1.0, Vs / Hs) - 1.0) + Vs * Vs / (2.0 * ws * asm.sub_EA[sag])
            low = np.where(eq._anchor_is_a[sag], asm.sub_a[sag], asm.sub_b[sag])
            bottom = eq._node_position[low, 2] - dip
            k = int(np.argmin(bottom))
            if bottom[k] < -depth - 1e-6 * depth:
                name = asm.line_names[asm.sub_line[np.flatnonzero(sag)[k]]]
                warnings.warn(f"lines.{name}: a suspended part sags to z = {bottom[k]:.4g} m, below the seabed at "
                              f"{-depth:g} m; the system statics lets a line lie on the seabed only from a point "
                              "on it, so this part passes through the seabed. Suggested fix: shorten the line, or "
                              "add a point on the seabed where it touches down.", SeacableWarning, stacklevel=3)
    mbls = getattr(asm, "_breaking_loads", None)
    if mbls is None:
        # weakest segment's breaking load of each line (None: not given), kept with the cached assembly
        mbls = [min((seg.line_type.breaking_load for seg in eq.system.lines[name].line.segments
                     if seg.line_type.breaking_load is not None), default=None) for name in eq.line_names]
        asm._breaking_loads = mbls
    for i, name in enumerate(eq.line_names):
        mbl = mbls[i]
        if mbl is None:
            continue
        t = max(eq.end_a_tension[i], eq.end_b_tension[i])
        if mbl is not None and t > mbl:
            warnings.warn(f"lines.{name}: tension {t:.4g} N exceeds the breaking load {mbl:.4g} N of its weakest "
                          "segment. Suggested fix: check the load, or the line's breaking_load.",
                          SeacableWarning, stacklevel=3)


def _result(prob: _Problem, st: State, ev: Evaluation, rounds: tuple = ({}, {}, {})) -> SystemEquilibrium:
    asm, system = prob.asm, prob.system
    nb = prob.nb
    P = node_positions(asm, st.X, st.R, st.P)
    given = getattr(asm, "_result_constants", None)
    if given is None:
        # positions given of every body, the system's point names and their nodes (kept with the cached assembly)
        point_names = list(system.points)
        given = (np.array([np.asarray(system.bodies[n].position, float) for n in asm.body_names]).reshape(-1, 6),
                 point_names, np.array([asm.point_node[n] for n in point_names], int))
        asm._result_constants = given
    body_pos = given[0].copy()
    for k, i in enumerate(asm.free_bodies):
        body_pos[i, :3] = st.X[k]
        body_pos[i, 3:] = _continuous(euler(st.R[k]), body_pos[i, 3:])
    # a prescribed pinned body (MoorDyn's CoupledPinned) is solved for its rotations but is not a free body
    # of the result: its rotations are condensed out with the free points, its translations are held
    split = getattr(asm, "_result_free", None)
    if split is None:
        free_k = np.array([k for k, i in enumerate(asm.free_bodies)
                           if system.bodies[asm.body_names[i]].kind == "free"], int)
        coupled_k = np.setdiff1d(np.arange(nb), free_k)
        split = asm._result_free = (free_k, (6 * free_k[:, None] + np.arange(6)).ravel(),
                                    (6 * coupled_k[:, None] + np.arange(3, 6)).ravel())
    free_k, b, coupled_rot = split
    if coupled_rot.size:
        K = _condense(-ev.jac_lines, b, np.concatenate([coupled_rot, prob.point_dofs(st)]))
        hyd = ev.hydro[np.ix_(b, b)]
    else:
        K = _condense(-ev.jac_lines, nb, prob.point_dofs(st))
        hyd = ev.hydro
    fa = ev.fa[asm.line_first]
    fb = ev.fb[asm.line_last]
    grounded = np.bincount(asm.sub_line, weights=ev.cat.grounded_length, minlength=len(asm.line_names))
    point_names = list(given[1])
    return SystemEquilibrium(
        system=system, environment=prob.env, body_names=list(asm.body_names), body_position=body_pos,
        free_body_names=[asm.body_names[asm.free_bodies[k]] for k in free_k], point_names=point_names,
        point_position=P[given[2]], line_names=list(asm.line_names),
        end_a_force=fa, end_b_force=fb, end_a_tension=np.linalg.norm(fa, axis=1),
        end_b_tension=np.linalg.norm(fb, axis=1), grounded_length=grounded, stiffness=K, hydrostatic=hyd,
        iterations=prob.iterations, residual=prob.error(ev), _asm=asm, _cat=ev.cat,
        _anchor_is_a=ev.anchor_is_a, _e=ev.e, _node_position=P, indeterminate=prob.held_rotations(st),
        pin_reaction=ev.reaction[free_k] if coupled_rot.size else ev.reaction.copy(), _rounds=rounds,
        surfaced=[asm.node_label[n].removeprefix("points.") for n in np.flatnonzero(st.surfaced)])


def _continuous(angles, ref):
    """Euler angles shifted by whole turns to lie nearest the reference angles."""
    return ref + (angles - ref + np.pi) % (2 * np.pi) - np.pi


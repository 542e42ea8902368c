"""The Newton iteration of the system statics on the free DOFs of an assembled system (:class:`_Problem`),
with the checks on its start and its stability; see :mod:`seacable.system.statics`.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ...environment import Environment
from ...errors import ConvergenceError, InputError, NoSolutionError
from ..model import MooringSystem
from . import kernel as _kern
from .evaluation import Evaluation, State, body_data, evaluate
from .model import BODY, assemble, rotation
from .result import SystemEquilibrium

_DOF = ("surge", "sway", "heave", "roll", "pitch", "yaw")


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
            from ..._model import suggest

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

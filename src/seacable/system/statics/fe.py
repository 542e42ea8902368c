"""Finite-element statics of a mooring system: the fallback of ``system_static`` for what the catenary
lines cannot model (a current, a sloping seabed).

The system is the coupled finite-element model of the dynamics (:func:`seacable.system.dynamics.build_system_fe`:
truss elements, lumped weight and drag, a penalty seabed, the free bodies' weight, buoyancy, waterplane and
quadratic damping in the current), and its equilibrium is the dynamics' pseudo-transient Newton
(:func:`seacable.system.dynamics.static_system`). :func:`fe_equilibrium` returns a :class:`FEEquilibrium`
with the attributes and methods of :class:`~seacable.system.statics.SystemEquilibrium` that the system
analyses read, so that :mod:`seacable.system.run` reports both the same way.

* End forces: the force a line exerts on its end node is the single line's
  (:func:`seacable.mooring.outputs.line_end_forces`, the same function, as ``system_dynamic`` reports it): its
  end element's tension along its chord plus the half element lumped there (its weight in water, its drag in
  the current, its seabed contact) and, for a line with bending stiffness, its hinges' forces on the end node
  (a held end's shear). The chord tension is the tension at the element's middle to second order, and the
  half-element load carries it to the end, so the end force converges to the continuous line's at second
  order in the element length (as the profile).
  At an end resting on the seabed (an anchor) the seabed carries the half element's weight as far as the line
  lies there (:func:`seacable.mooring.outputs.grounded_end_force`: the end element's pull less that weight's
  part normal to the seabed, never pressing the end into it; the catenary's grounded anchor takes no vertical
  load).
* Grounded length: the unstretched length of the elements whose two nodes press on the seabed (penalty
  force > 0): first order in the element length.
* Stiffness: ``K = -dF/dq`` of the lines' force and moment on each free body (about its reference point,
  global axes), by central differences of finite-element equilibria with the free bodies held (free
  points and nodes equilibrated): translations by ``+-delta`` [m], rotations by ``+-delta_r`` [rad] about
  the global axes (``R -> Rot(th) R``, the analytic statics' convention). The hydrostatic matrix is the
  analytic one of the catenary statics (the bodies' own weight, buoyancy and waterplane).
* Seabed friction (``analysis.static_friction``, :mod:`seacable.mooring.friction`, as a single line's statics):
  the dynamics' friction acts on the velocity and gives no static force, so the statics take OrcaFlex's friction
  targets instead. The *as-laid* state is the frictionless equilibrium in still water, without wind and without
  the applied loads (the bodies' and points' ``external_force``, the ramp's and the sweep's loads), the free bodies
  free from their given positions; its grounded nodes' positions are the targets, and the current, the wind and
  the applied loads are then applied with friction in load steps (:func:`seacable.mooring.friction.load_steps`,
  the single line's: each a fraction of the current's and the wind's speeds and of the loads). A solve from an
  ``initial`` equilibrium with friction (a ramp's next step, a sweep's next load) keeps its targets and goes from
  its loads to the new ones: one monotonic loading. The stiffness's equilibria keep the targets, the bodies moved
  by ``+-delta`` at most ``SLIDE_FACTOR friction_distance`` (1 cm at the default: the regularised friction's
  tangent for a small further load; a larger move from the friction's state does not converge). ``mode: off`` or
  seabed friction 0: frictionless, as before to the bit.
* Pinned bodies (only their rotations free) are not modelled by the finite-element system: refused.
"""

from __future__ import annotations

import copy
import dataclasses
import math
import warnings

import numpy as np

from ...errors import ConvergenceError, InputError, SeacableWarning
from ...mooring import kernel as MK
from ...mooring.friction import SLIDE_FACTOR, _active
from ...mooring.outputs import height_above_seabed, line_end_forces
from ..statics_mode import STIFFNESS_ANALYTIC, STIFFNESS_FD, needs_fe
from .model import EquilibriumFields, euler, rotation

__all__ = ["STIFFNESS_ANALYTIC", "STIFFNESS_FD", "FEEquilibrium", "fe_equilibrium", "needs_fe"]


def check_fe(system, env, where: str = "", friction=None) -> None:
    """Refuse what the finite-element statics cannot model (pinned bodies); warn when the seabed has friction and
    the statics do not (``friction``, the analysis's ``static_friction``, None or mode 'off')."""
    for name, body in system.bodies.items():
        if body.pinned:
            raise InputError(f"{where}bodies.{name}: a pinned body (only its rotations free) is not modelled by the "
                             "finite-element statics, which the system statics use for a current or a sloping seabed. "
                             "Suggested fix: drop 'pinned' (tie the body by a short stiff line instead), or set the "
                             "current to 0 and the seabed slope to 0 for the catenary statics.")
    if env.seabed.friction > 0 and env.depth is not None and (friction is None or friction.mode == "off"):
        warnings.warn(f"{where}environment.seabed.friction = {env.seabed.friction:g}: the finite-element statics "
                      "(used for a current, a sloping seabed, sections or held ends) are frictionless: "
                      + ("analysis.static_friction.mode is 'off'. " if friction is not None else
                         "this analysis has no static friction (the dynamics' friction acts on the velocity and gives "
                         "no static force). ")
                      + "Suggested fix: none needed if friction does not hold the lines; else set "
                      "analysis.static_friction.mode: as_laid in system_static or system_offsets.",
                      SeacableWarning, stacklevel=3)


@dataclasses.dataclass(frozen=True)
class FEEquilibrium(EquilibriumFields):
    """The static equilibrium of the finite-element system, read as a
    :class:`~seacable.system.statics.SystemEquilibrium` (same attribute names and units)."""

    fe: object = dataclasses.field(repr=False)
    state: object = dataclasses.field(repr=False)
    indeterminate: list = dataclasses.field(default_factory=list)
    pin_reaction: np.ndarray | None = None
    surfaced: list = dataclasses.field(default_factory=list)
    base_fe: object = dataclasses.field(default=None, repr=False)   # the system without ``external``
    stiffness_method: str = STIFFNESS_FD
    statics: str = "finite_element"
    targets: np.ndarray | None = dataclasses.field(default=None, repr=False)  # the friction targets (n, 3) [m]

    def line_nodes(self, line_name: str):
        """Unstretched arc length (k,) [m], node positions (k, 3) [m] and element tensions (k - 1,) [N]."""
        fe = self.fe
        il = fe.line_names.index(line_name)
        nodes, els = fe.line_nodes[il], fe.line_elements[il]
        s = np.r_[0.0, np.cumsum(fe.model.network.length[els])]
        return s, self.state.position[nodes], self.state.tension[els]

    def line_profile(self, line_name: str, n: int = 100):
        """Shape and tension along a line from end A to end B, ``n`` points evenly spaced in unstretched
        arc length, linear between the nodes; the tension at the nodes is the mean of the adjacent
        elements', at the ends the end tension. [m], [N]"""
        s, X, Te = self.line_nodes(line_name)
        il = self.line_names.index(line_name)
        Tn = np.r_[self.end_a_tension[il], 0.5 * (Te[1:] + Te[:-1]), self.end_b_tension[il]]
        t = np.linspace(0.0, s[-1], int(n))
        pos = np.column_stack([np.interp(t, s, X[:, j]) for j in range(3)])
        return pos, np.interp(t, s, Tn)


def _on_seabed(model, X) -> np.ndarray:
    """Nodes pressing on the penalty seabed (penetration above minus the contact ramp). (n,) bool"""
    w = model.water
    if w.depth is None:
        return np.zeros(X.shape[0], bool)
    if w.grid is not None:  # the grid's cell under each node, along its normal
        return -height_above_seabed(w, X) > -model.env[MK.E_BEDRAMP]
    sl = w.slope
    pen = -(-math.sin(sl) * X[:, 0] + math.cos(sl) * (X[:, 2] + w.depth))
    return pen > -model.env[MK.E_BEDRAMP]


def _with_loads(fe, external: dict | None):
    """``fe`` with ``external`` ({free body: 6 loads}) added to its bodies' constant external force."""
    if not external:
        return fe
    from ..dynamics import body as DB

    bpar = fe.bpar.copy()
    for name, load in external.items():
        k = fe.free_bodies.index(name)
        bpar[k, DB.B_FEXT:DB.B_FEXT + 6] += np.asarray(load, float)
    return dataclasses.replace(fe, bpar=bpar)


def _rotated(q, axis: int, th: float) -> np.ndarray:
    """Pose ``q`` turned by ``th`` [rad] about global axis ``axis`` (R -> Rot(th) R)."""
    out = np.array(q, float)
    c, s = math.cos(th), math.sin(th)
    i, j = (axis + 1) % 3, (axis + 2) % 3       # right-handed: about z turns x towards y
    Rg = np.eye(3)
    Rg[i, i], Rg[i, j], Rg[j, i], Rg[j, j] = c, -s, s, c
    out[3:] = euler(Rg @ rotation(out[3:]))
    return out


def fd_stiffness(fe, state, tol: float, delta: float, delta_r: float, targets=None,
                 friction_distance: float = 1e-3) -> np.ndarray:
    """Coupled mooring stiffness (6 nb, 6 nb) of the free bodies by central differences of equilibria with
    the bodies held (free points and line nodes equilibrated; ``targets``: with the seabed's static friction
    towards them). [N/m, N/rad, N m/m, N m/rad]"""
    from ..dynamics import body_line_force, static_system

    q0 = state.body_position.reshape(-1, 6)
    nb = q0.shape[0]
    K = np.zeros((6 * nb, 6 * nb))
    for b in range(nb):
        for j in range(6):
            cols = []
            for sign in (1.0, -1.0):
                q = q0.copy()
                if j < 3:
                    q[b, j] += sign * delta
                else:
                    q[b] = _rotated(q[b], j - 3, sign * delta_r)
                st = static_system(fe, held=True, q=q, X=state.position, tol=tol, targets=targets,
                                   friction_distance=friction_distance)
                cols.append(body_line_force(fe, st.position, q).ravel())
            K[:, 6 * b + j] = -(cols[0] - cols[1]) / (2.0 * (delta if j < 3 else delta_r))
    return K


def fe_equilibrium(system, env, *, external: dict | None = None, tol: float = 1e-8, max_iter: int = 1000,
                   initial: FEEquilibrium | None = None, n_elements: int | None = None,
                   stiffness: bool = True, friction=None) -> FEEquilibrium:
    """Static equilibrium of ``system`` in ``env`` with finite-element lines (a current, a sloping seabed).

    Parameters
    ----------
    system : MooringSystem
    env : Environment
    external : dict, optional
        ``{free body: (Fx, Fy, Fz, Mx, My, Mz)}`` added to the bodies' external force. [N, N m]
    tol : float
        Force tolerance of the pseudo-transient Newton, relative. [-]
    max_iter : int
        Iterations of one equilibrium.
    initial : FEEquilibrium, optional
        A previous equilibrium of the same system to start from (sweeps).
    n_elements : int, optional
        Elements of every line (default: each line's ``n_elements``).
    stiffness : bool
        Compute the stiffness (12 more equilibria per free body).
    friction : StaticFriction, optional
        The seabed's static friction (the analysis's ``static_friction``; None: frictionless), from the as-laid
        state or ``initial``'s targets (module docstring).

    Returns
    -------
    FEEquilibrium
    """
    from ..dynamics import build_system_fe, static_system

    check_fe(system, env, friction=friction)
    if initial is not None and n_elements is None:
        fe0 = initial.base_fe         # without the loads ``initial`` was solved under
    else:
        fe0 = build_system_fe(system, env, None, n_elements=n_elements)
    fe = _with_loads(fe0, external)
    targets = None
    if friction is not None and _active(fe.model, friction):
        st, targets = _friction_path(fe, initial, friction, tol, max_iter)
    else:
        try:
            if initial is not None:
                st = static_system(fe, q=initial.state.body_position, X=initial.state.position, tol=tol,
                                   max_iter=max_iter)
            else:
                st = static_system(fe, tol=tol, max_iter=max_iter)
        except ConvergenceError as err:
            said, _, fix = _unheld_hint(fe, tol, max_iter).partition(" Suggested fix: ")
            if not said:
                raise
            unheld = ConvergenceError(f"{str(err).split(' Suggested fix:')[0]}{said} Suggested fix: {fix}",
                                      iterations=err.iterations, residual=err.residual)
            unheld.fix = fix.rstrip(".")  # the sweep's message (seacable.system.run) gives it first
            raise unheld from None
    model = fe.model
    X = st.position
    nl = len(fe.line_names)
    fa, fb, grounded = np.zeros((nl, 3)), np.zeros((nl, 3)), np.zeros(nl)
    bed = _on_seabed(model, X)
    net = model.network
    for il in range(nl):
        els = fe.line_elements[il]
        fa[il], fb[il] = line_end_forces(model, X, line=il)
        e2 = net.elements[els]
        grounded[il] = float(net.length[els][bed[e2[:, 0]] & bed[e2[:, 1]]].sum())
    body_names = list(system.bodies)
    free = list(fe.free_bodies)
    bpos = np.array([np.asarray(system.bodies[n].position, float) for n in body_names]).reshape(-1, 6)
    q = st.body_position.reshape(-1, 6)
    for k, name in enumerate(free):
        bpos[body_names.index(name)] = q[k]
    point_names = list(system.points)
    ppos = X[[fe.point_node[n] for n in point_names]] if point_names else np.zeros((0, 3))
    scale = max(1.0, float(np.abs(fa).max(initial=0.0)), float(np.abs(fb).max(initial=0.0)))
    nbf = len(free)
    K = np.zeros((6 * nbf, 6 * nbf))
    if stiffness and nbf:
        span = max([float(np.ptp(X[:, k])) for k in range(3)] + [1.0])
        delta = 1e-4 * span
        if targets is not None:  # within the friction's reach: the held equilibria converge from the state
            delta = min(delta, SLIDE_FACTOR * friction.friction_distance)
        K = fd_stiffness(fe, st, tol=min(tol, 1e-10), delta=delta, delta_r=1e-4, targets=targets,
                         friction_distance=friction.friction_distance if targets is not None else 1e-3)
    return FEEquilibrium(
        system=system, environment=env, body_names=body_names, body_position=bpos, free_body_names=free,
        point_names=point_names, point_position=ppos, line_names=list(fe.line_names), end_a_force=fa,
        end_b_force=fb, end_a_tension=np.linalg.norm(fa, axis=1), end_b_tension=np.linalg.norm(fb, axis=1),
        grounded_length=grounded, stiffness=K, hydrostatic=hydrostatic(system, env, free, q), iterations=st.iterations,
        residual=st.residual / scale, fe=fe, state=st, base_fe=fe0, targets=targets)


def _scaled(fe, t: float):
    """``fe`` with its loads times ``t``: the current's speeds, the wind's (and the bodies' force series), the
    bodies' and the points' external forces (0: the as-laid state's still water)."""
    from ..dynamics import body as DB

    model = copy.copy(fe.model)
    water = model.water
    model.water = dataclasses.replace(water, current_speeds=tuple(t * v for v in water.current_speeds))
    model.cur_speed = t * fe.model.cur_speed
    bpar = fe.bpar.copy()
    bpar[:, DB.B_FEXT:DB.B_FEXT + 6] *= t
    return dataclasses.replace(fe, model=model, bpar=bpar, ext_f=t * fe.ext_f, node_fext=t * fe.node_fext)


def _between(fa, fb, t: float):
    """The loads of ``fa`` (its current, wind, external forces) moved ``t`` of the way to ``fb``'s (same mesh):
    ``fb`` itself at ``t = 1``."""
    if t == 1.0:
        return fb
    from ..dynamics import body as DB

    def lerp(a, b):
        return a + t * (b - a)

    model = copy.copy(fb.model)
    speeds = lerp(np.asarray(fa.model.water.current_speeds, float), np.asarray(fb.model.water.current_speeds, float))
    model.water = dataclasses.replace(fb.model.water, current_speeds=tuple(float(v) for v in speeds))
    model.cur_speed = lerp(fa.model.cur_speed, fb.model.cur_speed)
    bpar = fb.bpar.copy()
    sl = slice(DB.B_FEXT, DB.B_FEXT + 6)
    bpar[:, sl] = lerp(fa.bpar[:, sl], fb.bpar[:, sl])
    return dataclasses.replace(fb, model=model, bpar=bpar, ext_f=lerp(fa.ext_f, fb.ext_f),
                               node_fext=lerp(fa.node_fext, fb.node_fext))


def _friction_path(fe, initial, settings, tol: float, max_iter: int):
    """The equilibrium of ``fe`` with the seabed's static friction and its targets: from ``initial``'s state and
    targets when it has them, else from the as-laid state (module docstring), in load steps."""
    from ...mooring.checks import seabed_hold_hint
    from ...mooring.friction import friction_targets, load_steps
    from ..dynamics import static_system

    if initial is not None and initial.targets is not None:
        start_fe, start, targets, laid_iterations = initial.fe, initial.state, initial.targets, 0
        what = "the statics with seabed friction, the loads applied from the last equilibrium"
    else:
        start_fe = _scaled(fe, 0.0)
        try:
            start = static_system(start_fe, tol=tol, max_iter=max_iter)
        except ConvergenceError as err:
            raise ConvergenceError(
                f"the as-laid state (the frictionless equilibrium in still water, without wind or applied loads, "
                f"which gives the static friction its targets) has no solution: {err} If friction alone holds the "
                "lines there, set analysis.static_friction.mode: off.", iterations=err.iterations,
                residual=err.residual) from None
        targets, laid_iterations = friction_targets(fe.model, start.position), start.iterations
        what = ("the statics with seabed friction, the current, the wind and the applied loads applied from the "
                "as-laid state")

    def solve(t, last, targets, iterations):
        return static_system(_between(start_fe, fe, t), q=last.body_position, X=last.position, tol=tol,
                             max_iter=max_iter if iterations >= 500 else iterations, targets=targets,
                             friction_distance=settings.friction_distance)

    state, targets, spent = load_steps(
        solve, fe.model, start, targets, settings, what=what,
        hint=lambda t, last: seabed_hold_hint(_between(start_fe, fe, t).model, last.position, True))
    return dataclasses.replace(state, iterations=spent + laid_iterations), targets


def _unheld_hint(fe, tol: float, max_iter: int) -> str:
    """Why the frictionless statics of ``fe`` may have failed: a grounded line that a current pushes along the
    seabed with no friction to hold it (:func:`seacable.mooring.checks.seabed_hold_hint` at the still-water state;
    "" when not that, or when that state has no solution either)."""
    from ...mooring.checks import seabed_hold_hint
    from ..dynamics import static_system

    if not np.any(fe.model.cur_speed) or fe.model.water.depth is None:
        return ""
    try:
        still = static_system(_scaled(fe, 0.0), tol=tol, max_iter=max_iter)
    except ConvergenceError:
        return ""
    return seabed_hold_hint(fe.model, still.position, False)


def hydrostatic(system, env, free: list, q: np.ndarray) -> np.ndarray:
    """Block-diagonal hydrostatic restoring (6 nb, 6 nb) of the free bodies at poses ``q`` (nb, 6): the
    analytic one of the catenary statics (weight, buoyancy, waterplane, or the user's matrix)."""
    from types import SimpleNamespace

    from .evaluation import body_own

    nb = len(free)
    if not nb:
        return np.zeros((0, 0))
    names = list(system.bodies)
    asm = SimpleNamespace(free_bodies=[names.index(n) for n in free], body_names=names, rho=env.water_density,
                          g=env.gravity)
    X = np.asarray(q, float).reshape(nb, 6)[:, :3].copy()
    R = np.array([rotation(p[3:]) for p in np.asarray(q, float).reshape(nb, 6)])
    _, own_jac = body_own(asm, system, X, R)
    H = np.zeros((6 * nb, 6 * nb))
    for k in range(nb):
        H[6 * k:6 * k + 6, 6 * k:6 * k + 6] = -own_jac[k]
    return H

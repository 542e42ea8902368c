"""The system statics' entry points: :func:`solve_equilibrium` (rounds of Newton solves, the lines split at the
surface and the seabed between them) and :func:`check_statics`; see :mod:`seacable.system.statics`.
"""

from __future__ import annotations

import warnings

import numpy as np

from ...environment import Environment
from ...errors import ConvergenceError, InputError, NoSolutionError, SeacableWarning
from ...statics.catenary import CatenaryRegime
from ..model import MooringSystem
from .catenary import table_strain
from .evaluation import Evaluation, State, node_positions
from .model import euler
from .problem import _check_stability, _condense, _Problem
from .result import SystemEquilibrium
from .splits import _SUSPENDED, _floating, _merge_cuts, _sag_cuts, _same_split, _surface


class CheckedStart:
    """The starting state :func:`check_statics` evaluated, which :func:`solve_equilibrium` (``start=``) takes
    instead of evaluating it again: the Newton problem, the state and the evaluation there, for one
    system, environment, external load and ``max_strain``. A solve uses it once (it iterates from it)."""

    __slots__ = ("system", "environment", "external", "max_strain", "prob", "st0", "ev0")

    def __init__(self, system, environment, external, max_strain, prob, st0, ev0):
        self.system, self.environment, self.external, self.max_strain = system, environment, external, max_strain
        self.prob, self.st0, self.ev0 = prob, st0, ev0

    def take(self, system, environment, external, max_strain):
        """(problem, state, evaluation) if this is the start of that solve and unused, else None."""
        if (self.prob is None or self.system is not system or self.environment is not environment
                or self.external is not external or self.max_strain != max_strain):
            return None
        out = (self.prob, self.st0, self.ev0)
        self.prob = self.st0 = self.ev0 = None
        return out


def check_statics(system: MooringSystem, environment: Environment, *, external: dict | None = None,
                  max_strain: float = 1.0) -> CheckedStart | None:
    """Every check :func:`solve_equilibrium` makes before iterating, without solving.

    For a ``prepare_<analysis>`` step (``seacable validate``): what the catenary lines cannot
    model (current, sloping seabed, no EA), points below the seabed, unknown bodies in
    ``external``, lines that cannot reach at the starting positions, and bodies that are
    hydrostatically unstable with no mooring restoring (or loaded in a DOF nothing restores).

    Returns
    -------
    CheckedStart or None
        The start evaluated for these checks, which ``solve_equilibrium(..., start=)`` of the same
        system, environment, ``external`` (the same object) and ``max_strain`` iterates from rather
        than evaluate it again (the same equilibrium to the bit); None when the checks solved the
        system (a body unstable where it starts).

    Raises
    ------
    InputError, NoSolutionError
        As :func:`solve_equilibrium`.
    """
    max_strain = _check_max_strain(max_strain)
    prob = _Problem(system, environment, external, 1e-8, 1, max_strain=max_strain)
    st0 = prob.initial_state(None)
    ev0 = _eval_at_start(prob, st0)
    try:
        _check_stability(prob, st0, ev0)
    except InputError:
        # a body unstable where it starts may be restored once the lines take load (a rod hanging from
        # a line that is unloaded at the start): the solve decides, as solve_equilibrium does
        solve_equilibrium(system, environment, external=external, max_strain=max_strain)
        return None
    return CheckedStart(system, environment, external, max_strain, prob, st0, ev0)


def _eval_at_start(prob, st0):
    """The evaluation at the starting state, a line that cannot reach there said to be at the start."""
    try:
        return prob.eval(st0, 1.0)
    except NoSolutionError as err:
        raise NoSolutionError(f"at the starting positions: {err} (Or start the bodies and free points where "
                              "every line can reach.)") from None


def _check_max_strain(max_strain) -> float:
    m = float(max_strain)
    if not (m > 0 and np.isfinite(m)):
        raise InputError(f"max_strain must be > 0, got {max_strain!r}. Suggested fix: use 1.0 (100 %), or more "
                         "for a soft spring line (a MoorDyn spring test).")
    return m


def solve_equilibrium(system: MooringSystem, environment: Environment, *, external: dict | None = None,
                      tol: float = 1e-8, max_iter: int = 200,
                      initial: SystemEquilibrium | None = None, max_strain: float = 1.0,
                      start: CheckedStart | None = None) -> SystemEquilibrium:
    """Static equilibrium of every free body and free point of a mooring system.

    Parameters
    ----------
    system : MooringSystem
    environment : Environment
        Water density, gravity, depth, seabed friction (no current, flat seabed: for those,
        :func:`seacable.system.statics.fe.fe_equilibrium`).
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
    start : CheckedStart, optional
        What :func:`check_statics` of this system, environment, ``external`` and ``max_strain`` returned:
        the solve starts from the state it evaluated instead of evaluating it again (ignored with
        ``initial``, or when it is of another solve or was used).

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
    checked = start.take(system, environment, external, max_strain) if start is not None and initial is None \
        else None
    while True:
        stable_at_start = False
        if checked is not None:  # the first round's start, evaluated by check_statics (no cuts yet)
            (prob, st0, ev0), checked = checked, None
            # check_statics found the start stable at its tolerance (else it returns no start): so it is at any
            # larger one (every bound of _check_stability grows with the tolerance)
            stable_at_start = tol >= prob.tol
            prob.tol, prob.max_iter = tol, max_iter
        else:
            prob = _Problem(system, environment, external, tol, max_iter, _merge_cuts(cuts, surf), max_strain, air)
            st0 = prob.initial_state(initial)
            ev0 = _eval_at_start(prob, st0)
        more = _sag_cuts(prob, st0, ev0) if sag_rounds < _SAG_ROUNDS else {}
        if more:
            cuts = _merge_cuts(cuts, more)
            sag_rounds += 1
            continue
        try:
            if not stable_at_start:
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


_SAG_ROUNDS = 3         # times lines sagging into the seabed are split and the system solved again


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

"""A coupling interface for other codes: seacable's mooring lines driven by a code that owns the body.

A hydrodynamics or turbine code (OpenFAST, WEC-Sim, an in-house time-domain solver) integrates its floating
body itself and needs, at each of its steps, the force of the moorings on the body for the motion it gives. That
is what MoorDyn's API offers (``MoorDyn_Init``, ``MoorDyn_Step``, ``MoorDyn_Close``); :class:`Coupling` offers the
same over seacable's finite-element lines and rigid bodies (:mod:`seacable.system.dynamics`)::

    from seacable.coupling import Coupling

    moor = Coupling("examples/coupling_hull.yaml")   # a system case, or a MoorDyn deck
    f = moor.init(x0)                                 # statics with the coupled DOFs at x0; f: their forces
    for k in range(n):
        f = moor.step(x[k + 1], xd[k + 1], t[k], dt)  # the lines from t[k] to t[k] + dt; forces at t[k] + dt
        K = moor.stiffness()                          # the lines' stiffness at the last x (statics)
    ds = moor.close()                                 # the run as system_dynamic's Dataset

The coupled degrees of freedom (``x``, ``xd``, the forces) are, in this order (MoorDyn's), six per coupled body
and three per coupled point:

- a body of kind ``prescribed`` (its synonym ``coupled``; MoorDyn's ``Coupled`` body or rod read from a deck) is
  ``(x, y, z, roll, pitch, yaw)`` of its reference point [m, rad], the rotation ``R = Rz(yaw) Ry(pitch) Rx(roll)``
  (the system model's; :mod:`seacable.system.model`), its points at ``r + R p``; its force is
  ``(Fx, Fy, Fz, Mx, My, Mz)`` [N, N m], global axes, the moment about the reference point;
- a point of kind ``coupled`` is ``(x, y, z)`` [m]; its force ``(Fx, Fy, Fz)`` [N].

MoorDyn 2.7 turns a coupled body by ``Rx(roll) Ry(pitch) Rz(yaw)`` (checked against ``moordyn.GetPointPos``: the
two agree to first order in the angles only); ``Coupling(..., angles="moordyn")`` takes the angles and their rates
in MoorDyn's convention and converts them (the forces, moments and stiffness are in global axes either way).
Bodies come first, in the system's order, then points in theirs (:attr:`Coupling.dof_names` lists them). The
force is the force the lines put on the coupled object (MoorDyn's sign): each of its nodes' line forces, weight
and drag of the half elements, less their inertia (``F - M a`` of the node), and the point's own net weight and
external force. Free bodies and free points of the system move with the lines, as in ``system_dynamic``.

Time. ``step(x, xd, t, dt)`` advances from ``t`` (the coupling's time: steps follow each other) to ``t + dt``,
with ``x`` and ``xd`` the coupled DOFs at the step's *end*: between the last ``(x, xd)`` and the new one they move
along the cubic that matches both ends' positions and velocities (Hermite), sampled at the internal steps
(``time_step``; ``dt`` is cut into equal steps no longer than it). The lines step by Newmark's average
acceleration with Newton iterations (the ``system_dynamic`` kernel, :func:`seacable.system.dynamics.kernel.
coupled_steps`), implicit: ``time_step`` may be far above MoorDyn's explicit ``dtM``.

Names mapped (MoorDyn v2's C API and its Python wrapper ``moordyn``, 2.7.2):

=====================================================  ========================================================
MoorDyn                                                seacable
=====================================================  ========================================================
``moordyn.Create(file)`` / ``MoorDyn_Create``          ``Coupling(file_or_case)`` (a MoorDyn deck reads as one)
``moordyn.NCoupledDOF`` / ``MoorDyn_NCoupledDOF``      ``Coupling.n_dof``; the names: ``Coupling.dof_names``
``moordyn.Init(x, xd)`` / ``MoorDyn_Init``             ``Coupling.init(x, xd)``: the static equilibrium of the
                                                       lines (and free bodies) with the coupled DOFs at ``x``
``moordyn.Init_NoIC`` / ``MoorDyn_Init_NoIC``          ``Coupling.init(x, xd, settle=False)``: the lines on their
                                                       catenary start shapes, unsettled
``moordyn.Step(x, xd, t, dt)`` / ``MoorDyn_Step``      ``Coupling.step(x, xd, t, dt)``; MoorDyn's ``x`` is at the
                                                       step's start (extrapolated with ``xd`` over ``dt``),
                                                       seacable's at its end (see Time); both return the forces
                                                       at ``t + dt``
``moordyn.GetFASTtens`` / ``MoorDyn_GetFASTtens``      ``Coupling.fast_tensions()``: (fairlead H, V, anchor H, V)
``moordyn.GetLineNodePos``, ``GetLineFairTen``         ``Coupling.node_positions(line)``, ``Coupling.tensions()``
MoorPy's ``getCoupledStiffnessA``                      ``Coupling.stiffness(x)``: the system statics' analytic
                                                       stiffness (:mod:`seacable.system.statics`)
``moordyn.Close`` / ``MoorDyn_Close``                  ``Coupling.close()``: the run as a Dataset
=====================================================  ========================================================

Not taken: an irregular sea (its kinematics grid needs the run's length) and free bodies with a radiation memory
(their kernel is sampled at one step): a coupled code owns the body's hydrodynamics.

References
----------
.. [1] M. Hall, MoorDyn v2, ``source/MoorDyn2.h`` (``MoorDyn_Init``, ``MoorDyn_Step``, ``MoorDyn_GetFASTtens``) and
   the Python wrapper ``moordyn`` 2.7.2 (FloatingArrayDesign/MoorDyn, BSD-3).
.. [2] M. Hall et al., MoorPy, ``moorpy/system.py`` (``getCoupledStiffnessA``), v1.3.0.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np

from .errors import ConvergenceError, InputError, SeacableWarning

__all__ = ["Coupling"]

_DOF6 = ("x", "y", "z", "roll", "pitch", "yaw")
#: the UDUNITS units of the coupled DOFs' variables by kind (translation, rotation), by the translation's name
_COUPLED_UNITS = {"coupled_position": ("m", "rad"), "coupled_velocity": ("m s-1", "rad s-1"),
                  "coupled_force": ("N", "N m")}


def _case_of(case):
    """A :class:`~seacable.system.case.SystemCase` from a path (YAML or MoorDyn deck), a MoorDyn case or itself, and
    the largest strain its statics admit (the case's; a MoorDyn deck's: MoorDyn has no limit, and its spring decks
    stretch lines ten times, :data:`seacable.io.moordyn._DECK_MAX_STRAIN`)."""
    from .io import load_case
    from .io.moordyn import _DECK_MAX_STRAIN, MoorDynCase
    from .system.case import SystemCase

    if isinstance(case, (str, Path)):
        case = load_case(case)
    max_strain = getattr(getattr(case, "analysis", None), "max_strain", 1.0)
    if isinstance(case, MoorDynCase):
        max_strain = _DECK_MAX_STRAIN
        # a run's duration gives the deck's failures and checks its water kinematics; the coupling sets its own time
        case = case.with_run(duration=1.0).system_case() if case.has_structures else _deck_points_case(case)
    if not isinstance(case, SystemCase):
        raise InputError(f"Coupling needs a mooring system case (points, bodies, lines) or a MoorDyn deck, got "
                         f"{type(case).__name__}. Suggested fix: give a system case file (top-level 'lines', "
                         "'points', 'bodies') or a MoorDyn input file.")
    return case, max_strain


def _deck_points_case(deck):
    """A MoorDyn deck of lines and points only as a system case (``system_dynamic``, its failures)."""
    from .io.moordyn._case import _line_failures
    from .system.case import SystemCase, SystemDynamicAnalysis

    system, environment = deck.system()
    analysis = SystemDynamicAnalysis(duration=1.0, failures=_line_failures(deck.data))
    return SystemCase(name=deck.name, description=f"MoorDyn file {deck.path}", environment=environment,
                      points=system.points, bodies=system.bodies, lines=system.lines, analysis=analysis)


class Coupling:
    """seacable's lines as a mooring module of another code: ``init``, ``step``, ``stiffness``, ``close``.

    See the module's docstring (:mod:`seacable.coupling`) for the degrees of freedom, the time convention and
    how it maps to MoorDyn's API.

    Parameters
    ----------
    case
        A system case (:class:`~seacable.system.case.SystemCase`, or the path of its YAML file) or a MoorDyn
        input file (or its :class:`~seacable.io.moordyn.MoorDynCase`). Its coupled objects are its bodies of kind
        ``prescribed`` (or ``coupled``) and its points of kind ``coupled``. A ``system_dynamic`` analysis gives
        the damping, elements, seabed contact and failures; its motions are not used (the coupled code drives).
    time_step
        Longest internal time step; each ``step``'s ``dt`` is cut into equal steps no longer. Default: the
        analysis's ``time_step`` (0.1 s). [s]
    n_elements
        Elements of every line (default: each line's own). [-]
    output_interval
        Time between the states kept for :meth:`close`'s Dataset (each ``step`` end at or past the next multiple
        is kept); default every step. [s]
    tolerance
        Newton tolerance of the statics and the steps, relative. [-]
    angles
        ``"seacable"`` (``R = Rz(yaw) Ry(pitch) Rx(roll)``, MoorPy's) or ``"moordyn"`` (``R = Rx(roll) Ry(pitch)
        Rz(yaw)``, MoorDyn 2.7's): the convention of the coupled bodies' angles in ``x`` and ``xd``.

    Attributes
    ----------
    dof_names : tuple of str
        ``'body NAME x'`` ... ``'body NAME yaw'``, ``'point NAME x'`` ...: the coupled DOFs in order.
    n_dof : int
        Their number (MoorDyn's ``NCoupledDOF``).
    time : float
        The coupling's time (None before :meth:`init`). [s]
    forces : ndarray
        The coupled forces at ``time`` (None before :meth:`init`). [N, N m]
    """

    def __init__(self, case, *, time_step: float | None = None, n_elements: int | None = None,
                 output_interval: float | None = None, tolerance: float = 1e-8, angles: str = "seacable"):
        from . import _validate
        from .system.case import SystemDynamicAnalysis

        self.case, self._max_strain = _case_of(case)
        a = self.case.analysis
        self.analysis = a if isinstance(a, SystemDynamicAnalysis) else None
        step = time_step if time_step is not None else (self.analysis.time_step if self.analysis else 0.1)
        self.time_step = _validate.positive("time_step", step, "s", "give the longest internal step, e.g. 0.1")
        self.output_interval = None if output_interval is None else _validate.positive(
            "output_interval", output_interval, "s", "give the time between kept states, or None for every step")
        self.tolerance = _validate.in_range("tolerance", tolerance, 1e-14, 1e-2, "",
                                            "use 1e-8 (statics) or 1e-7")
        if n_elements is not None and (int(n_elements) != n_elements or not 1 <= n_elements <= 100_000):
            raise InputError(f"n_elements must be a whole number in 1..100000, got {n_elements!r}. Suggested fix: "
                             "give the elements per line, or None for each line's own.")
        self.n_elements = n_elements
        if angles not in ("seacable", "moordyn"):
            raise InputError(f"angles must be 'seacable' (Rz Ry Rx) or 'moordyn' (Rx Ry Rz), got {angles!r}. "
                             "Suggested fix: angles='moordyn' for a code written for MoorDyn's API.")
        self.angles = angles
        system = self.case.system()
        self.system = system
        bodies = [n for n, b in system.bodies.items() if b.kind == "prescribed"]
        for n in bodies:
            if system.bodies[n].pinned:
                raise InputError(f"bodies.{n}: a pinned coupled body (MoorDyn's CoupledPinned) is not taken by the "
                                 "coupling (its rotations are the lines' to find). Suggested fix: couple all six "
                                 "DOFs (pinned: false), or give its fairleads as coupled points.")
        points = [n for n, p in system.points.items() if p.kind == "coupled"]
        if not bodies and not points:
            raise InputError("the system has no coupled object: the coupling needs bodies of kind 'prescribed' (or "
                             "'coupled') or points of kind 'coupled' for the other code to drive. Suggested fix: set "
                             "'kind: coupled' on the hull body (or on the fairlead points).")
        self.bodies, self.points = tuple(bodies), tuple(points)
        self.dof_names = tuple([f"body {n} {d}" for n in bodies for d in _DOF6]
                               + [f"point {n} {d}" for n in points for d in "xyz"])
        self.n_dof = len(self.dof_names)
        env = self.case.environment
        free = [n for n, b in system.bodies.items() if b.kind == "free"]
        for n in free:
            b = system.bodies[n]
            if b.hydrodynamics is not None:
                raise InputError(f"bodies.{n}: a free body with a hydrodynamic database (radiation memory) is not "
                                 "taken by the coupling. Suggested fix: let the coupled code own that body (kind "
                                 "'coupled'), or give it added mass and damping matrices.")
            if b.mass <= 0:
                raise InputError(f"bodies.{n}.mass: a free body needs a mass > 0 kg for the dynamics, got "
                                 f"{b.mass:g} kg. Suggested fix: give its mass in air.")
        from .environment import IrregularWaves

        if isinstance(env.waves, IrregularWaves):
            raise InputError("the coupling takes still water or a regular wave, not an irregular sea (its kinematics "
                             "grid is sized by the run's length). Suggested fix: remove the irregular sea from the "
                             "case's environment.")
        self.time = None
        self.forces = None
        self._fe = None
        self._state = "new"  # 'new', 'running', 'failed' (a step did not converge), 'closed'

    # ------------------------------------------------------------------------------------------- inputs

    def _dofs(self, name: str, values, unit: str, *, allow_none=False) -> np.ndarray:
        if values is None and allow_none:
            return np.zeros(self.n_dof)
        try:
            v = np.asarray(values, float).ravel()
        except (TypeError, ValueError):
            raise InputError(f"{name} must be {self.n_dof} numbers ({unit}), got {values!r}. Suggested fix: give one "
                             f"value per coupled DOF ({', '.join(self.dof_names[:3])}...).") from None
        if v.size != self.n_dof:
            raise InputError(f"{name} must have {self.n_dof} values (6 per coupled body, 3 per coupled point: "
                             f"{', '.join(self.dof_names)}), got {v.size}. Suggested fix: give one value per coupled "
                             "DOF, bodies first, in Coupling.dof_names order.")
        bad = np.flatnonzero(~np.isfinite(v))
        if bad.size:
            k = int(bad[0])
            raise InputError(f"{name}[{k}] ({self.dof_names[k]}) must be a finite number in {unit}, got {v[k]}. "
                             "Suggested fix: check the coupled code's state before passing it (no NaN or inf).")
        return v

    def _convert(self, x: np.ndarray, xd: np.ndarray | None, near: np.ndarray | None = None):
        """``x`` and ``xd`` with the bodies' angles in seacable's convention (``angles="moordyn"``: from MoorDyn's
        ``Rx Ry Rz``; the Euler branch nearest ``near``'s angles), the rates mapped through the angular velocity."""
        if self.angles == "seacable" or not self.bodies:
            return x, xd
        from .system.statics.model import euler, euler_rate_map

        x, xd = x.copy(), None if xd is None else xd.copy()
        for k in range(0, 6 * len(self.bodies), 6):
            a, b, c = x[k + 3:k + 6]
            ca, sa, cb, sb, cc, sc = math.cos(a), math.sin(a), math.cos(b), math.sin(b), math.cos(c), math.sin(c)
            rx = np.array([[1.0, 0.0, 0.0], [0.0, ca, -sa], [0.0, sa, ca]])
            ry = np.array([[cb, 0.0, sb], [0.0, 1.0, 0.0], [-sb, 0.0, cb]])
            rz = np.array([[cc, -sc, 0.0], [sc, cc, 0.0], [0.0, 0.0, 1.0]])
            ang = euler(rx @ ry @ rz)
            if near is not None:
                ref = near[k + 3:k + 6]
                ang = ref + (ang - ref + np.pi) % (2 * np.pi) - np.pi
            if xd is not None:  # w = rate_a e_x + rate_b Rx e_y + rate_c Rx Ry e_z
                E = np.column_stack([np.array([1.0, 0.0, 0.0]), rx[:, 1], (rx @ ry)[:, 2]])
                xd[k + 3:k + 6] = np.linalg.lstsq(euler_rate_map(ang), E @ xd[k + 3:k + 6], rcond=None)[0]
            x[k + 3:k + 6] = ang
        return x, xd

    def _system_at(self, x: np.ndarray, free_pose=None):
        """The mooring system with the coupled bodies and points at ``x`` (free bodies at ``free_pose``)."""
        from .system.model import MooringSystem

        s = self.system
        bodies = dict(s.bodies)
        for k, n in enumerate(self.bodies):
            bodies[n] = bodies[n].model_copy(update={"position": tuple(float(v) for v in x[6 * k:6 * k + 6])})
        for n, pose in (free_pose or {}).items():
            bodies[n] = bodies[n].model_copy(update={"position": tuple(float(v) for v in pose)})
        points = dict(s.points)
        o = 6 * len(self.bodies)
        for k, n in enumerate(self.points):
            points[n] = points[n].model_copy(update={"position": tuple(float(v) for v in x[o + 3 * k:o + 3 * k + 3])})
        return MooringSystem(points=points, bodies=bodies, lines=s.lines)

    # ------------------------------------------------------------------------------------------- kinematics

    def _channel_kinematics(self, pos, vel, acc):
        """Positions, velocities, accelerations (m, n_channels, 3) of the prescribed nodes from the coupled DOFs'
        (m, n_dof) ones: a body's point at ``r + R p`` moves with ``v + w x Rp`` and ``a + alpha x Rp + w x (w x
        Rp)``, ``w = E(angles) angles'`` (:func:`seacable.system.statics.model.euler_rate_map`)."""
        from .mooring.motion import rotation_matrix
        from .system.statics.model import euler_rate_map

        m = pos.shape[0]
        nch = max(len(self._fe.channel_source), 1)
        px, pv, pa = np.zeros((m, nch, 3)), np.zeros((m, nch, 3)), np.zeros((m, nch, 3))
        for c, (k, arm) in enumerate(self._chan):
            if arm is None:  # a coupled point
                px[:, c], pv[:, c], pa[:, c] = pos[:, k:k + 3], vel[:, k:k + 3], acc[:, k:k + 3]
                continue
            for i in range(m):
                ang, rate, racc = pos[i, k + 3:k + 6], vel[i, k + 3:k + 6], acc[i, k + 3:k + 6]
                rp = rotation_matrix(*ang) @ arm
                E = euler_rate_map(ang)
                eps = 1e-6
                Edot = (euler_rate_map(ang + eps * rate) - euler_rate_map(ang - eps * rate)) / (2 * eps)
                w = E @ rate
                alpha = E @ racc + Edot @ rate
                px[i, c] = pos[i, k:k + 3] + rp
                pv[i, c] = vel[i, k:k + 3] + np.cross(w, rp)
                pa[i, c] = acc[i, k:k + 3] + np.cross(alpha, rp) + np.cross(w, np.cross(w, rp))
        return px, pv, pa

    def _hermite(self, t0, dt, x0, v0, x1, v1, times):
        """The cubic through (x0, v0) at t0 and (x1, v1) at t0 + dt: positions, velocities, accelerations."""
        s = ((np.asarray(times, float) - t0) / dt)[:, None]
        s2, s3 = s * s, s * s * s
        pos = (2 * s3 - 3 * s2 + 1) * x0 + (s3 - 2 * s2 + s) * dt * v0 + (3 * s2 - 2 * s3) * x1 + (s3 - s2) * dt * v1
        vel = ((6 * s2 - 6 * s) * x0 + (3 * s2 - 4 * s + 1) * dt * v0 + (6 * s - 6 * s2) * x1
               + (3 * s2 - 2 * s) * dt * v1) / dt
        acc = ((12 * s - 6) * x0 + (6 * s - 4) * dt * v0 + (6 - 12 * s) * x1 + (6 * s - 2) * dt * v1) / dt ** 2
        return pos, vel, acc

    # ------------------------------------------------------------------------------------------- init

    def init(self, x, xd=None, *, settle: bool = True, t: float = 0.0) -> np.ndarray:
        """Start the lines with the coupled DOFs at ``x`` (MoorDyn's ``Init``; ``settle=False``: ``Init_NoIC``).

        With ``settle`` the static equilibrium of the finite-element lines, free points and free bodies is solved
        with the coupled objects held at ``x`` (Newton; MoorDyn relaxes its lines in time towards it); without,
        the lines start on their catenary shapes between their ends. The lines start at rest, the coupled objects
        at the velocity ``xd`` (default zero), the accelerations those of the equations of motion at ``t``.

        Parameters
        ----------
        x
            Coupled DOFs (``n_dof``: :attr:`dof_names`). [m, rad]
        xd
            Their velocities. [m/s, rad/s]
        settle
            Solve the static start (MoorDyn's IC generation).
        t
            The coupling's time at the start. [s]

        Returns
        -------
        ndarray, shape (n_dof,)
            The coupled forces at the start. [N, N m]
        """
        from .mooring.solver import line_end_nodes
        from .system.dynamics import build_system_fe, static_system
        from .system.dynamics import frames as DF
        from .system.dynamics.loop import SystemState, initial_accelerations

        given = self._dofs("x", x, "m and rad")
        given_d = self._dofs("xd", xd, "m/s and rad/s", allow_none=True)
        x, xd = self._convert(given, given_d)
        if self._state == "closed":
            raise InputError("init after close: the coupling has ended. Suggested fix: create a new Coupling.")
        if not math.isfinite(t):
            raise InputError(f"t must be a finite time in s, got {t}. Suggested fix: start at t = 0.")
        system = self._system_at(x)
        fe = build_system_fe(system, self.case.environment, self.analysis, n_elements=self.n_elements)
        if fe.model.water.sea is not None:
            raise InputError("the coupling takes no irregular sea. Suggested fix: remove it from the environment.")
        if fe.memory_kernel is not None and fe.memory_kernel.shape[1] > 1:
            raise InputError("a free body's radiation memory is not taken by the coupling. Suggested fix: couple it.")
        self._fe = fe
        m = fe.model
        net = m.network
        # channel -> (first coupled DOF of its object, arm in body axes or None for a point)
        start = {n: 6 * k for k, n in enumerate(self.bodies)}
        start.update({n: 6 * len(self.bodies) + 3 * k for k, n in enumerate(self.points)})
        self._chan = [(start[src[1]], np.asarray(src[2], float) if src[0] == "body" else None)
                      for src in fe.channel_source]
        self._pres = np.flatnonzero(net.channel >= 0)
        if settle:
            st = static_system(fe, tol=self.tolerance)
        else:
            st = SystemState(net.position.copy(), fe.q0.copy(), np.zeros(net.n_elements), 0, 0.0, "catenary")
        X = st.position.copy()
        V, A = np.zeros_like(X), np.zeros_like(X)
        q = st.body_position.copy().reshape(-1, 6)
        nb = len(fe.free_bodies)
        qd, qdd = np.zeros((nb, 6)), np.zeros((nb, 6))
        px, pv, pa = self._channel_kinematics(x[None], xd[None], np.zeros((1, self.n_dof)))
        ch = net.channel[self._pres]
        X[self._pres], V[self._pres], A[self._pres] = px[0, ch], pv[0, ch], pa[0, ch]
        frame = np.zeros((nb, DF.F_SIZE))
        frame[:, DF.F_GLOB:DF.F_GLOB + 3] = q[:, 3:]
        for b in range(nb):
            DF.rechart(q[b], qd[b], qdd[b], frame[b], DF.CHART_LIMIT)
        m.settle_viscoelastic(X, np.zeros_like(X))
        initial_accelerations(fe, X, V, A, q, qd, qdd, frame, pv[0], pa[0])
        self._X, self._V, self._A = X, V, A
        self._q, self._qd, self._qdd, self._frame = q, qd, qdd, frame
        self._con_target = fe.con_target.copy()
        self._active = np.ones(len(fe.con_node), np.int64)
        self._fail_at = np.full(len(fe.con_node), np.nan)
        self._F, self._M = np.zeros((net.n_nodes, 3)), np.zeros((net.n_nodes, 3, 3))
        self._tension = np.zeros(net.n_elements)
        self._stats = np.zeros(3)
        self._rker = np.zeros((nb, 1, 6, 6))
        self._rhist, self._rhead = np.zeros((nb, 1, 6)), np.zeros(nb, np.int64)
        self._x, self._xd = x, xd
        self._given = (given, given_d)
        self._state = "running"
        self.time = float(t)
        self._steps = self._iterations = 0
        _, _, tension, _ = m.evaluate(X, V, A, self.time, settled=True)
        self._tension[:] = tension
        self.forces = self._coupled_forces()
        self._store = {k: [] for k in ("time", "X", "V", "A", "tension", "q", "qd", "w", "x", "xd", "xs", "xds",
                                       "f")}
        self._knodes = line_end_nodes(net)  # the lines' end nodes and their neighbours: their accelerations kept
        self._next_out = self.time
        self._keep()
        return self.forces.copy()

    # ------------------------------------------------------------------------------------------- step

    def step(self, x, xd, t: float, dt: float) -> np.ndarray:
        """Advance the lines from ``t`` to ``t + dt`` with the coupled DOFs reaching ``x``, ``xd`` at ``t + dt``
        (MoorDyn's ``Step``; see the module's Time).

        Returns
        -------
        ndarray, shape (n_dof,)
            The force of the lines on each coupled object at ``t + dt``, global axes, moments about the body's
            reference point. [N, N m]

        Raises
        ------
        InputError
            Before :meth:`init`; ``x`` or ``xd`` of the wrong length or not finite; ``t`` not the coupling's time
            (a step back or a gap); ``dt`` not > 0.
        ConvergenceError
            A step that does not converge after 6 halvings, with the time and the residual.
        """
        from .mooring.solver import advance_interval
        from .system.dynamics import kernel as DK

        self._need_init("step")
        given = self._dofs("x", x, "m and rad")
        given_d = self._dofs("xd", xd, "m/s and rad/s")
        x, xd = self._convert(given, given_d, near=self._x)
        if not (isinstance(t, (int, float, np.floating, np.integer)) and math.isfinite(t)):
            raise InputError(f"t must be a finite time in s, got {t!r}. Suggested fix: pass the step's start time.")
        if not (isinstance(dt, (int, float, np.floating, np.integer)) and math.isfinite(dt) and dt > 0):
            raise InputError(f"dt must be a finite time step > 0 s, got {dt!r}. Suggested fix: pass the coupled "
                             "code's step, e.g. 0.05.")
        if abs(t - self.time) > 1e-9 * max(1.0, abs(self.time)) + 1e-12:
            what = "goes back" if t < self.time else "skips ahead"
            raise InputError(f"t = {t:.9g} s {what}: the coupling is at t = {self.time:.9g} s, and each step starts "
                             "where the last ended. Suggested fix: pass t = Coupling.time (to restart, call init "
                             "again).")
        fe, m = self._fe, self._fe.model
        net = m.network
        n = max(1, math.ceil(dt / self.time_step - 1e-9))
        h = dt / n
        x0, v0, t0 = self._x, self._xd, self.time

        def channels(times):
            pos, vel, acc = self._hermite(t0, dt, x0, v0, x, xd, times)
            return self._channel_kinematics(pos, vel, acc)

        X, V, A, q, qd, qdd = self._X, self._V, self._A, self._q, self._qd, self._qdd
        args, bargs = fe.kernel_args(), fe.body_args()
        a = self.analysis
        max_iter = a.max_iterations if a is not None else 30
        nd = a.numerical_damping if a is not None else 0.0
        beta, gamma = (1 + nd) ** 2 / 4, 0.5 + nd
        tol = min(self.tolerance * 10, 1e-4)

        def coupled(tk, dtk, px, pv, pa):
            return DK.coupled_steps(X, V, A, q, qd, qdd, tk, dtk, px, pv, pa, net.channel, args, m.weight, m.fidx,
                                    m.nfree, m.bw, m.env, m.cur_depth, m.cur_speed, True, m.sea, fe.node_fext,
                                    fe.con_node, fe.con_body, fe.con_arm, self._con_target, self._active, fe.con_chan,
                                    fe.fail_time, fe.fail_tension, fe.fail_elem, self._fail_at, *bargs, beta, gamma,
                                    tol, max_iter, self._F, self._M, self._tension, self._stats, self._frame,
                                    self._rker, self._rhist, self._rhead, h)

        try:
            done, spent = advance_interval(t0, h, n, channels, coupled, self._stats, 6, max_iter, "coupling",
                                           "a smaller Coupling time_step, or check the coupled motion for a jump (x "
                                           "and xd that disagree)")
        except ConvergenceError:
            self._state = "failed"  # the lines stand part way through the step: only init can restart them
            raise
        self._steps += done
        self._iterations += spent
        self._x, self._xd = x, xd
        self._given = (given, given_d)
        self.time = t0 + dt
        self.forces = self._coupled_forces()
        if not np.all(np.isfinite(self.forces)):
            self._state = "failed"
            raise ConvergenceError(f"the coupled forces are not finite at t = {self.time:.6g} s. Suggested fix: a "
                                   "smaller time_step.", time=self.time)
        self._keep()
        return self.forces.copy()

    def _coupled_forces(self) -> np.ndarray:
        """The force of the lines on each coupled object at the current state (see the module docstring)."""
        fe, m = self._fe, self._fe.model
        net = m.network
        F, M, _, _ = m.evaluate(self._X, self._V, self._A, self.time, settled=True)
        F = F + fe.node_fext
        out = np.zeros(self.n_dof)
        nodes = [[] for _ in self._chan]
        for i in self._pres:
            nodes[net.channel[i]].append(i)
        for j in range(len(fe.con_node)):  # a failing line end at a coupled point: its own node, tied while intact
            if fe.con_chan[j] >= 0 and fe.con_body[j] == -1 and self._active[j]:
                nodes[fe.con_chan[j]].append(fe.con_node[j])
        for c, (k, arm) in enumerate(self._chan):
            for i in nodes[c]:
                f = F[i] - M[i] @ self._A[i]
                out[k:k + 3] += f
                if arm is not None:
                    out[k + 3:k + 6] += np.cross(self._X[i] - self._x[k:k + 3], f)
        return out

    def _keep(self) -> None:
        """Keep the state for :meth:`close` (every step, or at ``output_interval``)."""
        if self.output_interval is not None and self.time < self._next_out - 1e-9 * max(1.0, abs(self.time)):
            return
        if self.output_interval is not None:
            self._next_out += self.output_interval * max(1, math.floor((self.time - self._next_out)
                                                                       / self.output_interval + 1 + 1e-9))
        from .system.dynamics.loop import _global_state, tied_accelerations

        g = _global_state(self._q, self._qd, self._frame)
        s = self._store
        # the nodes' accelerations for the lines' end forces, a tied node's that of what it is tied to
        acc = tied_accelerations(self._fe, self._A, self._q, self._qd, self._qdd, self._frame, self._active, None,
                                 self.time)[self._knodes]
        for key, v in (("time", self.time), ("X", self._X), ("V", self._V), ("A", acc), ("tension", self._tension),
                       ("q", g[0]), ("qd", g[1]), ("w", g[2]), ("x", self._given[0]), ("xd", self._given[1]), ("xs", self._x), ("xds", self._xd),
                       ("f", self.forces)):
            s[key].append(np.array(v, float, copy=True))

    # ------------------------------------------------------------------------------------------- outputs

    def _need_init(self, what: str) -> None:
        if self._state == "new":
            raise InputError(f"{what} before init: the lines have no state yet. Suggested fix: call "
                             "Coupling.init(x0) with the coupled DOFs at the start first.")
        if self._state == "closed":
            raise InputError(f"{what} after close: the coupling has ended. Suggested fix: create a new Coupling "
                             "(or call close last).")
        if self._state == "failed" and what in ("step", "close"):
            raise InputError(f"{what} after a step that did not converge: the lines stand part way through it. "
                             "Suggested fix: call init again (a smaller time_step), or catch the ConvergenceError "
                             "and stop.")

    def tensions(self) -> dict:
        """Fairlead and anchor tension of each line (its end elements' effective tension) at :attr:`time`.

        Returns
        -------
        dict
            ``{line: (fairlead tension, anchor tension)}`` [N]; the fairlead is the end on a body or coupled
            point (end B when both or neither are).
        """
        self._need_init("tensions")
        fe = self._fe
        out = {}
        for j, (name, els) in enumerate(zip(fe.line_names, fe.line_elements, strict=True)):
            ends = (float(self._tension[els[0]]), float(self._tension[els[-1]]))
            out[name] = (ends[fe.fairlead_end[j]], ends[1 - fe.fairlead_end[j]])
        return out

    def fast_tensions(self) -> np.ndarray:
        """MoorDyn's ``GetFASTtens``: per line, the horizontal and vertical force of the line's end element at the
        fairlead and at the anchor, (n_lines, 4) as (fairlead H, fairlead V, anchor H, anchor V). [N]"""
        self._need_init("fast_tensions")
        fe = self._fe
        X = self._X
        out = np.zeros((len(fe.line_names), 4))
        for j, (nodes, els) in enumerate(zip(fe.line_nodes, fe.line_elements, strict=True)):
            fair_b = fe.fairlead_end[j] == 1
            for col, (end, inner, e) in ((0, (nodes[-1], nodes[-2], els[-1]) if fair_b else (nodes[0], nodes[1], els[0])),
                                         (2, (nodes[0], nodes[1], els[0]) if fair_b else (nodes[-1], nodes[-2], els[-1]))):
                d = X[inner] - X[end]
                f = self._tension[e] * d / max(float(np.linalg.norm(d)), 1e-300)
                out[j, col], out[j, col + 1] = math.hypot(f[0], f[1]), abs(f[2])
        return out

    def node_positions(self, line: str) -> np.ndarray:
        """Positions (n_nodes, 3) of a line's nodes from end A at :attr:`time` (MoorDyn's ``GetLineNodePos``). [m]"""
        self._need_init("node_positions")
        fe = self._fe
        if line not in fe.line_names:
            from ._model import suggest

            raise InputError(f"line '{line}' is not in the system (lines: {', '.join(fe.line_names)})."
                             f"{suggest(line, fe.line_names)}")
        return self._X[fe.line_nodes[fe.line_names.index(line)]].copy()

    # ------------------------------------------------------------------------------------------- statics

    def static_forces(self, x=None) -> np.ndarray:
        """The coupled forces in the static equilibrium of the system with the coupled DOFs at ``x`` (default the
        last ``x``): the catenary statics (:func:`seacable.system.statics.solve_equilibrium`), free points and
        bodies at their equilibrium. [N, N m]"""
        return self._statics(x)[0]

    def stiffness(self, x=None) -> np.ndarray:
        """The lines' stiffness at the coupled DOFs ``K = -dF/dx`` (n_dof, n_dof), static: the free points and free
        bodies re-found at equilibrium (condensed out), as MoorPy's ``getCoupledStiffnessA``.

        The analytic tangent of the system statics' elastic catenaries (:mod:`seacable.system.statics`) at the
        equilibrium with the coupled objects at ``x`` (default the last ``x``): each coupled body is made a
        free body of its lines alone and each coupled point a free body's reference point, the statics' Jacobian
        is evaluated there and the free points' and free bodies' DOFs condensed out (Schur complement). A body's
        rotations are small rotations about the global axes (the Euler angle increments at zero angles).
        [N/m, N/rad, N m/m, N m/rad]

        Raises
        ------
        InputError
            A current or a sloping seabed (the catenary statics take neither).
        """
        return self._statics(x, stiffness=True)[1]

    def _statics(self, x, stiffness: bool = False):
        from .system.model import Body, SystemPoint
        from .system.statics import solve_equilibrium
        from .system.statics.evaluation import State
        from .system.statics.model import rotation
        from .system.statics.problem import _condense, _Problem

        if x is None:
            self._need_init("stiffness (with no x)")
            x = self._x
        else:
            x = self._convert(self._dofs("x", x, "m and rad"), None)[0]
        env = self.case.environment
        max_strain = self._max_strain
        system = self._system_at(x)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", SeacableWarning)  # the statics' notes were given by the case's checks
            eq = solve_equilibrium(system, env, tol=1e-10, max_strain=max_strain)
        # the force on each coupled object: its points' line end forces, net weights and external forces
        f = np.zeros(self.n_dof)
        rho, g = env.water_density, env.gravity
        at = {n: i for i, n in enumerate(eq.point_names)}
        on = {}
        for n, p in system.points.items():
            if p.kind == "body" and p.body in self.bodies:
                on[n] = (6 * self.bodies.index(p.body), True)
            elif p.kind == "coupled":
                on[n] = (6 * len(self.bodies) + 3 * self.points.index(n), False)
        load = {n: np.asarray(system.points[n].external_force, float) - [0.0, 0.0, system.points[n].net_weight(rho, g)]
                for n in on}
        for i, name in enumerate(eq.line_names):
            sl = system.lines[name]
            load[sl.end_a] = load.get(sl.end_a, 0.0) + eq.end_a_force[i]
            load[sl.end_b] = load.get(sl.end_b, 0.0) + eq.end_b_force[i]
        for n, (k, body) in on.items():
            f[k:k + 3] += load[n]
            if body:
                f[k + 3:k + 6] += np.cross(eq.point_position[at[n]] - x[k:k + 3], load[n])
        if not stiffness:
            return f, None
        # the coupled objects as free bodies of their lines alone (a body of the defaults: no mass, volume, loads),
        # everything else where the equilibrium put it
        bodies = {}
        for n, b in system.bodies.items():
            pose = tuple(map(float, eq.body_position[eq.body_names.index(n)]))
            bodies[n] = Body(kind="free", position=pose) if n in self.bodies else b.model_copy(update={"position": pose})
        points = {}
        for n, p in system.points.items():
            if p.kind == "coupled":
                holder = f"__coupled_{n}"
                bodies[holder] = Body(kind="free", position=(*p.position, 0.0, 0.0, 0.0))
                points[n] = SystemPoint(**{**p.model_dump(), "kind": "body", "body": holder, "position": (0.0,) * 3})
            elif p.kind == "free":
                points[n] = p.model_copy(update={"position": tuple(map(float, eq.point_position[at[n]]))})
            else:
                points[n] = p
        from .system.model import MooringSystem

        free_sys = MooringSystem(points=points, bodies=bodies, lines=system.lines)
        cuts, surf, air = eq._rounds
        merged = {k: tuple(sorted(set(cuts.get(k, ())) | set(surf.get(k, ())))) for k in set(cuts) | set(surf)}
        prob = _Problem(free_sys, env, None, 1e-10, 1, merged, max_strain, air)
        asm = prob.asm
        nb = prob.nb
        Xb, Rb = np.zeros((nb, 3)), np.zeros((nb, 3, 3))
        for k, i in enumerate(asm.free_bodies):
            pose = np.asarray(free_sys.bodies[asm.body_names[i]].position, float)
            Xb[k], Rb[k] = pose[:3], rotation(pose[3:])
        P = asm.node_pos0.copy()
        if eq._node_position.shape == P.shape:
            P[asm.free_nodes] = eq._node_position[asm.free_nodes]
        grounded = np.zeros(P.shape[0], bool)
        if asm.depth is not None:
            low = P[asm.free_nodes, 2] <= -asm.depth * (1 - 1e-9)
            P[asm.free_nodes[low], 2] = -asm.depth
            grounded[asm.free_nodes[low]] = True
        st = State(Xb, Rb, P, grounded, np.zeros(P.shape[0], bool))
        ev = prob.eval(st, 1.0)
        K = -ev.jac_lines
        K[:6 * nb, :6 * nb] += ev.hydro
        K = _condense(K, nb, prob.point_dofs(st))  # (6 nb, 6 nb): the free points condensed out
        # the coupled DOFs kept, the free bodies' condensed out
        keep, index = [], {asm.body_names[i]: k for k, i in enumerate(asm.free_bodies)}
        for n in self.bodies:
            keep += list(range(6 * index[n], 6 * index[n] + 6))
        for n in self.points:
            k = index[f"__coupled_{n}"]
            keep += list(range(6 * k, 6 * k + 3))
        keep = np.array(keep, int)
        rest = np.setdiff1d(np.arange(6 * nb), keep)
        rest = rest[[asm.body_names[asm.free_bodies[r // 6]] not in self.bodies
                     and not asm.body_names[asm.free_bodies[r // 6]].startswith("__coupled_") for r in rest]] \
            if rest.size else rest
        Kk = K[np.ix_(keep, keep)]
        if rest.size:
            Krr = K[np.ix_(rest, rest)]
            try:
                Kk = Kk - K[np.ix_(keep, rest)] @ np.linalg.solve(Krr, K[np.ix_(rest, keep)])
            except np.linalg.LinAlgError:
                Kk = Kk - K[np.ix_(keep, rest)] @ np.linalg.lstsq(Krr, K[np.ix_(rest, keep)], rcond=None)[0]
        return f, Kk

    # ------------------------------------------------------------------------------------------- close

    def close(self):
        """End the coupling (MoorDyn's ``Close``) and return the run as ``system_dynamic``'s Dataset
        (:func:`seacable.system.dynamics.system_result`), with the coupled DOFs and forces at each kept time
        (``coupled_position``, ``coupled_velocity``, ``coupled_force``, dimension ``coupled_dof``) and the coupled
        bodies' ``body_position`` and ``body_velocity`` from the coupled code's motion."""
        from ._cf import body_pose, dof_kind, split_by_kind
        from .results import var
        from .system.dynamics import system_result
        from .system.dynamics.loop import SystemRun

        self._need_init("close")
        s = self._store
        nt = len(s["time"])
        nb = len(self._fe.free_bodies)
        run = SystemRun(time=np.array(s["time"]), position=np.array(s["X"]), velocity=np.array(s["V"]),
                        tension=np.array(s["tension"]), body_position=np.array(s["q"]).reshape(nt, nb, 6),
                        body_velocity=np.array(s["qd"]).reshape(nt, nb, 6), failure_time=self._fail_at.copy(),
                        time_step=self.time_step, steps=self._steps, iterations=self._iterations, wall_time=0.0,
                        interrupted=False, body_angular_velocity=np.array(s["w"]).reshape(nt, nb, 3),
                        acceleration=np.array(s["A"]).reshape(nt, self._knodes.size, 3), kinematic_nodes=self._knodes)
        ds = system_result(self._fe, run, case=self.case, settings={"coupling": 1})
        x, xd = np.array(s["x"]), np.array(s["xd"])
        xs, xds = np.array(s["xs"]), np.array(s["xds"])
        ds = ds.assign_coords(coupled_dof=var("coupled_dof", list(self.dof_names), "1", "coupled degree of freedom"))
        # one unit per variable (CF): the translations, rotations, forces and moments of the coupled DOFs apart,
        # each NaN at the DOFs of the other kind (seacable._cf.split_by_kind; seacable._cf.joined puts them back)
        kinds = [dof_kind(n) for n in self.dof_names]
        for value, names, what in ((x, ("coupled_position", "coupled_rotation"), "given by the coupled code"),
                                   (xd, ("coupled_velocity", "coupled_rotation_rate"), "given by the coupled code"),
                                   (np.array(s["f"]), ("coupled_force", "coupled_moment"),
                                    "of the lines on the coupled object (moments about its reference point)")):
            parts = split_by_kind(value.reshape(nt, len(kinds)), kinds, axis=1)
            for (name, units), kind in zip(zip(names, _COUPLED_UNITS[names[0]]), ("translation", "rotation")):
                ds[name] = var(("time", "coupled_dof"), parts.get(kind, np.full((nt, len(kinds)), np.nan)), units,
                               f"{name.replace('_', ' ')} {what} (NaN at the coupled DOFs of the other kind)")
        if "body" in ds.dims:
            names = list(ds["body"].values)
            bp, bv = body_pose(ds), body_pose(ds, "body_velocity", "body_rotation_rate")
            for k, n in enumerate(self.bodies):
                bp[:, names.index(n)] = xs[:, 6 * k:6 * k + 6]  # seacable's angles, as every body's
                bv[:, names.index(n)] = xds[:, 6 * k:6 * k + 6]
            ds["body_position"].values[:], ds["body_rotation"].values[:] = bp[..., :3], bp[..., 3:]
            ds["body_velocity"].values[:], ds["body_rotation_rate"].values[:] = bv[..., :3], bv[..., 3:]
        self._fe = None
        self._state = "closed"
        return ds

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self._fe = None
        self._state = "closed"
        return False

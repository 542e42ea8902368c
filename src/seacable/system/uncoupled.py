"""The uncoupled route of ``system_dynamic`` (``coupling: uncoupled``, issue 39): a floating body's low- and
wave-frequency motions solved apart, the lines driven by their sum.

The frequency-domain practice of API RP 2SK and DNV-OS-E301, in the time domain:

1. **Mean.** The body's static equilibrium with its lines (:func:`seacable.system.statics.solve_equilibrium`,
   or the finite-element statics with a current: its drag on the body, from its ``quadratic_damping`` and its
   current table ``1/2 rho |u| u C(beta)`` at the heading found, is then in the mean) under its weight,
   buoyancy, hydrostatics, ``external_force`` and the mean loads: the sea's mean drift
   (:func:`seacable.hydro.loads.mean_drift_force`) and the mean wind's force. The mooring's stiffness ``K_m``
   (lines only, about the reference point) is the statics' at that position.
2. **Low frequency.** Cummins' equation (:func:`seacable.hydro.cummins.simulate_cummins`) in six DOFs about the
   mean, with the restoring ``C + K_m`` (the database's hydrostatics with the weight's moment, the mooring),
   the radiation memory, the body's linear and quadratic damping, the wind's and the current table's damping
   (:func:`~seacable.system.hydro.body_wind_loads`, :func:`~seacable.system.hydro.body_current_loads`: ``-dF/dv`` of
   the relative velocity's force at the mean), and the lines' damping
   ``mooring_damping`` (a fraction ``z`` of critical in surge, sway and yaw: ``2 z sqrt(K_jj (M_jj + A_jj(0)))``),
   forced by the slowly varying loads only: the slow drift less its mean (Newman's approximation or the full
   QTF, when the body's ``drift`` is ``newman`` or ``qtf``) and the wind's gusts. Heave, roll and pitch are solved too: the wind's moment
   and the slow drift pitch a semi-submersible, and the fairleads move with it.
3. **Wave frequency.** The body's RAOs from its database at the sea's own frequencies (:func:`sea_raos`: its rigid
   mass, ``A(w)``, ``B(w)``, ``X(w)`` and linear damping, the restoring ``C + K_m``) in the case's sea, with the phases referred
   to the body's reference point as the coupled route's wave loads are (:func:`seacable.system.hydro.body_wave_loads`):
   the same sea, the same phases. The wave response starts with the body's ``ramp``, as the coupled wave loads do.
4. **Lines.** The body, made ``prescribed``, follows ``mean + LF + WF`` and drives its lines: in time through the
   ``system_dynamic`` kernel (``lines: dynamic``: their inertia, drag in the waves and current, seabed), or by
   each line's elastic catenary at each output time (``lines: quasi_static``: fast; single-segment lines from a
   fixed point to the body in still water, no drag).

The result has the coupled route's variables (one vocabulary: ``body_position`` is the summed motion), plus
``body_low_frequency_motion`` and ``body_wave_frequency_motion`` (each about the mean) and the attributes
``coupling`` ('uncoupled'), ``lines``, ``mooring_damping`` and ``mean_position``.

When it is not conservative (README): the lines' damping is an estimate (too much of it under-predicts the slow
drift, the largest part of a semi's or spar's offset); the LF-WF interaction is lost (the wave-drift damping,
the RAOs taken about the mean rather than the instantaneous offset); with quasi-static lines their dynamic
tension (inertia and drag amplifying the wave-frequency tension of chain in deep water) is left out. Left out on
the safe side: the current's damping of the LF motion through the body's ``quadratic_damping`` (``2 B2 |u|``, which
the coupled route has; the current table's is in).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass

import numpy as np

from .._ramp import smooth_ramp
from ..errors import ConvergenceError, InputError, NoSolutionError, SeacableWarning
from ..mooring.motion import PlatformMotion, _ramped, _rigid_channels, sea_of
from ..mooring.outputs import at_motion_start, water_of_environment
from .case import SystemDynamicAnalysis, UncoupledRoute
from .model import MooringSystem

__all__ = ["LF_DOFS", "LF_STEP", "SummedMotion", "UncoupledSetup", "prepare_system_uncoupled", "run_system_uncoupled",
           "sea_raos", "uncoupled_motion"]

#: The DOFs ``mooring_damping`` damps (surge, sway, yaw), indices into the six.
LF_DOFS = (0, 1, 5)
#: The low-frequency equation's step, about (a whole multiple of the run's step, or the run's step when longer): its
#: motions' periods are 20 s and more (heave and pitch of a semi-submersible; surge, sway and yaw 60-300 s), where
#: Newmark's period error (w dt)^2 / 12 is under 0.1 %; the slow drift's difference frequencies above them move the
#: body by their force over its inertia, a little. [s]
LF_STEP = 0.5


@dataclass(frozen=True)
class SummedMotion:
    """The uncoupled body's motion about its given position: ``mean + LF(t) + WF(t)`` (six DOFs [m, rad]).

    ``time``, ``low``, ``low_rate``: the low-frequency motion and its rate from Cummins' equation at its steps
    (cubic Hermite between them); ``wave``: times -> the wave-frequency motion and its two derivatives (6, nt)
    each, None without one; ``ramp`` [s] the smooth start of the wave response. It has what a body motion of
    ``system_dynamic`` has (``reference``, ``model_copy``, ``dofs``, ``channels``).
    """

    reference: tuple
    mean: np.ndarray
    time: np.ndarray
    low: np.ndarray
    low_rate: np.ndarray
    wave: object = None
    ramp: float = 0.0

    def __post_init__(self):
        from scipy.interpolate import CubicHermiteSpline

        # built once: the time loop asks for the motion at every step
        object.__setattr__(self, "_spline", CubicHermiteSpline(self.time, self.low, self.low_rate, axis=0))

    def model_copy(self, update=None):
        return dataclasses.replace(self, **(update or {}))

    def low_frequency(self, times):
        """The low-frequency motion (nt, 6) and its two derivatives, about the mean."""
        t = np.asarray(times, float)
        return self._spline(t), self._spline(t, 1), self._spline(t, 2)

    def wave_frequency(self, times):
        """The wave-frequency motion (nt, 6) and its two derivatives, ramped."""
        t = np.asarray(times, float)
        if self.wave is None:
            z = np.zeros((t.size, 6))
            return z, z, z
        return _ramped(*(m.T for m in self.wave(t, derivatives=True)), t, self.ramp)

    def dofs(self, times):
        """The six motions (nt, 6) [m, rad] from the given position and their derivatives."""
        lo, wf = self.low_frequency(times), self.wave_frequency(times)
        return lo[0] + wf[0] + self.mean, lo[1] + wf[1], lo[2] + wf[2]

    def channels(self, times, base):
        return _rigid_channels(self.reference, base, *self.dofs(times))


@dataclass
class UncoupledSetup:
    """What the uncoupled route needs (:func:`prepare_system_uncoupled`)."""

    case: object
    options: UncoupledRoute
    body: str
    system: MooringSystem            # the case's system, the body free (its database resolved)
    mean: np.ndarray                 # (6,) the equilibrium under the mean loads, from the given position
    mean_loads: np.ndarray           # (6,) the mean drift and wind on the body [N, N m]
    mass: np.ndarray                 # (6, 6) rigid body about the reference point
    stiffness: np.ndarray            # (6, 6) hydrostatics and weight
    mooring_stiffness: np.ndarray    # (6, 6) lines only, at the mean
    linear_damping: np.ndarray       # (6, 6) global axes: the body's, the wind's, the current table's, the lines'
                                     # estimate
    quadratic_damping: np.ndarray    # (6, 6) global axes
    wave_damping: np.ndarray         # (6, 6) the linear damping of the RAOs (no line estimate)
    sea: object                      # SeaComponents or None
    dynamic: object = None           # SystemDynamicSetup of the prescribed system (lines: dynamic)
    fe: object = None                # SystemFE of the prescribed system


def _rotate(m: np.ndarray, yaw: float) -> np.ndarray:
    """A 6x6 matrix in body axes turned to the global ones by ``yaw`` [rad]."""
    c, s = math.cos(yaw), math.sin(yaw)
    r = np.eye(6)
    r[:2, :2] = r[3:5, 3:5] = [[c, -s], [s, c]]
    return r @ m @ r.T


def _prescribed_case(case, name: str):
    """The case with the body ``name`` prescribed (held still until its motion is known), the wind left out (it
    acts on the body only), as a coupled ``system_dynamic``."""
    bodies = {**case.bodies, name: case.bodies[name].model_copy(update={"kind": "prescribed"})}
    a = case.analysis.model_copy(update={"coupling": "coupled", "uncoupled": None,
                                         "body_motions": {name: PlatformMotion(amplitude=(0.0,) * 6, period=1.0)}})
    env = case.environment.model_copy(update={"wind": None})
    return case.model_copy(update={"bodies": bodies, "analysis": a, "environment": env})


def _check_quasi_static(case, system: MooringSystem, name: str) -> None:
    """Refuse what the quasi-static lines (one elastic catenary each) cannot model."""
    env = case.environment
    fix = "Suggested fix: 'lines: dynamic' (the lines in time), or a system the catenaries can model."
    from .statics_mode import needs_fe

    if needs_fe(env.model_copy(update={"wind": None})):  # the wind acts on the body alone
        raise InputError("analysis.uncoupled.lines 'quasi_static': the catenary lines take no current and no sloping "
                         f"seabed, and the environment has one of them (seabed slope {env.seabed.slope:g} rad). {fix}")
    for ln, line in system.lines.items():
        segs = line.line.segments
        ends = [system.points[line.end_a], system.points[line.end_b]]
        kinds = sorted(p.kind for p in ends)
        on_body = [p for p in ends if p.kind == "body"]
        if (len(segs) != 1 or line.line.attachments or line.line.sections or line.holds_ends
                or kinds != ["body", "fixed"] or on_body[0].body != name):
            raise InputError(f"lines.{ln}: analysis.uncoupled.lines 'quasi_static' takes lines of one segment without "
                             f"attachments, sections or ends held in bending from a fixed point to the body '{name}'. {fix}")
        lt = segs[0].line_type
        if getattr(lt, "tension_strain", None) is not None:
            raise InputError(f"lines.{ln}: analysis.uncoupled.lines 'quasi_static' takes a constant axial stiffness, "
                             f"not a strain-tension table. {fix}")


def prepare_system_uncoupled(case) -> UncoupledSetup:
    """Every check of an uncoupled ``system_dynamic`` case before its motions are computed, and its mean position.

    One free body with a hydrodynamic database (its RAOs and its low-frequency model come from it); the sea
    within its database (the loads' checks at t = 0); the statics under the mean loads; the prescribed
    system's checks of ``system_dynamic`` (the lines, the run size, the sea's grid) for ``lines: dynamic``, the
    catenaries' limits for ``lines: quasi_static``.
    """
    from .case import SystemCase
    from .hydro import body_current_loads, body_wave_loads, body_wind_loads, database, memory_kernels

    a = getattr(case, "analysis", None)
    if not isinstance(case, SystemCase) or not isinstance(a, SystemDynamicAnalysis) or a.coupling != "uncoupled":
        raise InputError("run_system_uncoupled takes a system case with analysis type 'system_dynamic' and "
                         "'coupling: uncoupled'. Suggested fix: seacable.run(case) runs either route.")
    opts = a.uncoupled or UncoupledRoute()
    system = case.system()
    free = [n for n, b in system.bodies.items() if b.kind == "free"]
    if len(free) != 1:
        raise InputError(f"coupling 'uncoupled' moves one free body, the case has {len(free)} "
                         f"({', '.join(free) or 'none'}). Suggested fix: make the others fixed or prescribed, or use "
                         "coupling: coupled.")
    name = free[0]
    body, given = system.bodies[name], case.bodies[name]
    if body.hydrodynamics is None:
        raise InputError(f"bodies.{name}: coupling 'uncoupled' needs the body's hydrodynamic database "
                         f"(bodies.{name}.hydrodynamics): its RAOs and its low-frequency model come from it. "
                         "Suggested fix: give the WAMIT files, or use coupling: coupled.")
    if body.pinned:
        raise InputError(f"bodies.{name}: a pinned body cannot be run by the uncoupled route. Suggested fix: "
                         "coupling: coupled.")
    if opts.lines == "quasi_static":
        _check_quasi_static(case, system, name)
    env = case.environment
    rho, g = env.water_density, env.gravity
    db = database(body, rho, g)
    memory_kernels(system, (name,), rho, g, a.time_step)  # the memory's cut checked at the step
    water = water_of_environment(env, a.seabed_contact, 0.0)
    sea = sea_of(water)
    h = body.hydrodynamics
    # the loads' checks (the sea within the database, the drift's headings) at t = 0, and the mean drift
    body_wave_loads(body, name, sea, rho, g, np.zeros(1))
    mean = np.zeros(6)
    if sea is not None and h.drift != "none":
        from ..hydro.loads import mean_drift_force
        from .hydro import _moved

        mean += mean_drift_force(db, _moved(sea, body.position[0], body.position[1]))
    wind_damping = np.zeros((6, 6))
    if env.wind is not None and body.wind is not None:
        steady = body_wind_loads(body, name, env.wind.model_copy(update={"spectrum": "none"}), np.zeros(1))
        if steady is not None:  # None: no wind speed
            mean += steady[0][0]
            wind_damping = steady[1]
    elif env.wind is not None:
        raise InputError("environment.wind is given, but no free body gives its wind areas (bodies.NAME.wind), so "
                         "it would load nothing (the lines take no wind). Suggested fix: give the bodies' wind "
                         "areas, or remove environment.wind.")
    # 1. the mean position and the mooring's stiffness there
    from .statics_mode import needs_fe

    external = {name: tuple(float(v) for v in mean)}
    env = env.model_copy(update={"wind": None})  # its mean force is in ``external`` (at the body's given heading)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", SeacableWarning)  # the statics' remarks are the run's own
            if needs_fe(env, system.lines):
                from .statics.fe import fe_equilibrium

                eq = fe_equilibrium(system, env, external=external, tol=a.tolerance, n_elements=a.n_elements)
            else:
                from .statics import solve_equilibrium

                eq = solve_equilibrium(system, env, external=external)
    except (NoSolutionError, ConvergenceError) as err:
        raise InputError(f"coupling 'uncoupled': the equilibrium of body '{name}' under its mean loads "
                         f"({', '.join(f'{v:.4g}' for v in mean)} N, N m: drift and wind) was not found: {err} "
                         "Suggested fix: check the mooring holds the body against them.") from None
    k = list(eq.free_body_names).index(name)
    pose = np.asarray(eq.body_position[list(eq.body_names).index(name)], float)
    moor = np.asarray(eq.stiffness, float)[6 * k:6 * k + 6, 6 * k:6 * k + 6]
    hydrostatic = np.asarray(body.hydrostatic_stiffness, float)
    mass = given.mass_matrix()  # the rigid body's (a body with a database gives no added mass)
    yaw = float(pose[5])
    lin = _rotate(body.matrix("linear_damping") + wind_damping, yaw)
    # the hull's current table: its force is in the statics' mean (at the heading found), its damping of the relative
    # velocity linearised there (the coupled step takes the table with the relative velocity at every step)
    current = body_current_loads(body, env.current, pose, rho)
    if current is not None:
        lin += current[1]
    quad = _rotate(body.matrix("quadratic_damping"), yaw)
    wave_damping = lin.copy()
    total = hydrostatic + moor
    a0 = db.added_mass_zero if db.added_mass_zero is not None else db.added_mass[0]
    for j, z in zip(LF_DOFS, opts.mooring_damping, strict=True):
        if z > 0 and total[j, j] > 0:
            lin[j, j] += 2.0 * z * math.sqrt(total[j, j] * (mass[j, j] + a0[j, j]))
    undamped = [("surge", "sway", "heave", "roll", "pitch", "yaw")[j] for j in LF_DOFS
                if lin[j, j] <= 0 and quad[j, j] <= 0]
    if undamped and sea is not None:
        warnings.warn(f"coupling 'uncoupled': body '{name}' has no damping in {', '.join(undamped)} but the "
                      "radiation's, which is nearly nothing at the low frequencies: its slow drift there is a "
                      "lightly damped resonance. Suggested fix: give analysis.uncoupled.mooring_damping (the lines' "
                      "damping, e.g. 0.05 of critical) or the body's linear_damping.", SeacableWarning, stacklevel=2)
    setup = UncoupledSetup(case=case, options=opts, body=name, system=system,
                           mean=pose - np.asarray(body.position, float), mean_loads=mean, mass=mass,
                           stiffness=hydrostatic, mooring_stiffness=moor, linear_damping=lin, quadratic_damping=quad,
                           wave_damping=wave_damping, sea=sea)
    prescribed = _prescribed_case(case, name)
    if opts.lines == "dynamic":
        from .dynamics import prepare_system_dynamic

        setup.dynamic = prepare_system_dynamic(prescribed)
        setup.fe = setup.dynamic.fe
    else:
        from .dynamics import build_system_fe

        setup.fe = build_system_fe(prescribed.system(), prescribed.environment, prescribed.analysis)
    return setup


def sea_raos(db, sea, mass, stiffness, damping):
    """The body's RAOs (:class:`seacable.raos.RAOTable`) at the frequencies of the sea's components, at its one
    heading (a long-crested sea) or the database's headings: ``(C - w^2 (M + A(w)) - i w (B(w) + B_v)) H = X(w, b)``
    (:func:`seacable.hydro.response.raos` at the database's frequencies), with ``A``, ``B`` and ``X`` interpolated
    at each component's frequency as the coupled route's loads are: no RAO is interpolated across a resonance."""
    from ..hydro.response import coefficients_at
    from ..raos import RAOTable

    omega = np.unique(np.asarray(sea.omega, float))
    if omega.size == 1:  # a regular wave: a second node beside it (a table has two); the wave's own is exact
        other = omega[0] * (0.99 if omega[0] * 0.99 >= db.excitation_omega[0] else 1.01)
        omega = np.sort(np.r_[omega, other])
    heads = np.unique(np.mod(np.asarray(sea.heading, float) + math.pi, 2 * math.pi) - math.pi)
    if heads.size > 1:
        heads = np.asarray(db.heading, float)
    a, b = coefficients_at(db, omega)
    system = (np.asarray(stiffness)[None] - omega[:, None, None] ** 2 * (np.asarray(mass)[None] + a)
              - 1j * omega[:, None, None] * (b + np.asarray(damping)[None]))
    x = np.stack([db.excitation_at(omega, np.full_like(omega, hd)) for hd in heads])  # (nh, nw, 6)
    try:
        h = np.linalg.solve(system[None], x[..., None])[..., 0]
    except np.linalg.LinAlgError:
        raise InputError("the body's equation of motion is singular at a wave frequency (a DOF with neither restoring "
                         "nor inertia nor damping). Suggested fix: give the mass, inertias and the mooring.") from None
    return RAOTable(omega=omega, heading=heads, values=np.transpose(h, (2, 0, 1)), source=f"RAOs of {db.source}")


def uncoupled_motion(case, setup: UncoupledSetup | None = None) -> SummedMotion:
    """The uncoupled body's motion (:class:`SummedMotion`) of an uncoupled ``system_dynamic`` case: its mean
    position, its low-frequency motion by Cummins' equation at the step :data:`LF_STEP` (steps 1-2 of the module
    docstring) and its
    wave-frequency motion through its RAOs (step 3), without the lines' run."""
    from ..hydro import simulate_cummins
    from ..raos import RAOResponse
    from .hydro import _moved, body_wind_loads, database

    s = setup if setup is not None else prepare_system_uncoupled(case)
    a = s.case.analysis
    env = s.case.environment
    body = s.system.bodies[s.body]
    h = body.hydrodynamics
    db = database(body, env.water_density, env.gravity)
    dt = float(a.time_step) * max(1, round(LF_STEP / float(a.time_step)))
    t = dt * np.arange(math.ceil(a.duration / dt - 1e-9) + 2)
    force = np.zeros((t.size, 6))
    local = None if s.sea is None else _moved(s.sea, body.position[0], body.position[1])
    if local is not None and h.drift in ("newman", "qtf"):
        from ..hydro.loads import mean_drift_force, qtf_drift_force, slow_drift_force

        r = smooth_ramp(t, float(h.ramp))[0] if h.ramp > 0 else (t > 0).astype(float)
        slow = slow_drift_force(db, local, t) if h.drift == "newman" else qtf_drift_force(db, local, t)
        force += r[:, None] * (slow - mean_drift_force(db, local))
    if env.wind is not None and body.wind is not None and env.wind.spectrum != "none" and env.wind.speed > 0:
        gusty = body_wind_loads(body, s.body, env.wind, t)[0]
        steady = body_wind_loads(body, s.body, env.wind.model_copy(update={"spectrum": "none"}), t[:1])[0][0]
        force += gusty - steady  # the gusts: the mean is in the statics
    low = simulate_cummins(db, s.mass, force, dt, stiffness=s.stiffness + s.mooring_stiffness,
                           linear_damping=s.linear_damping, quadratic_damping=s.quadratic_damping,
                           kernel_length=float(h.kernel_length))
    wave = None
    if local is not None and h.excitation:
        table = sea_raos(db, s.sea, s.mass, s.stiffness + s.mooring_stiffness, s.wave_damping)
        wave = RAOResponse(table, s.sea, at=tuple(body.position[:2]))
    return SummedMotion(reference=tuple(body.position[:3]), mean=s.mean, time=low.time, low=low.position,
                        low_rate=low.velocity, wave=wave, ramp=float(h.ramp))



def _profiles(n: int, cat, xF, zF, L: float, EA: float, w: float, mu: float):
    """The solved catenaries ``cat`` (nt,) at ``n`` points evenly spaced in unstretched length: x, z from the
    anchor and the tension (nt, n) each, by the system statics' compiled closed forms
    (:func:`seacable.system.statics.catenary.closed_form_profile`, the bits of the catenary's own profile)."""
    from .statics.catenary import closed_form_profile

    s = np.linspace(0.0, L, n)
    nt = np.size(xF)
    x, z, T = np.zeros((nt, n)), np.zeros((nt, n)), np.zeros((nt, n))
    H, VF = np.asarray(cat.H_fairlead, float), np.asarray(cat.V_fairlead, float)
    LB, regime = np.asarray(cat.grounded_length, float), np.asarray(cat.regime).astype(np.int64)
    for i in range(nt):
        closed_form_profile(s, float(xF[i]), float(zF[i]), L, EA, w, mu, float(H[i]), float(VF[i]), float(LB[i]),
                            int(regime[i]), x[i], z[i], T[i])
    return x, z, T


def _quasi_static_run(s: UncoupledSetup, motion: SummedMotion, times: np.ndarray):
    """The lines at the output ``times`` as their elastic catenaries between their anchors and the fairleads the
    motion puts there: a :class:`~seacable.system.dynamics.SystemRun` of the prescribed system's nodes (each
    line's nodes at its elements' ends, its element tensions at their middles), at rest."""
    import time as _time

    from ..statics.catenary import catenary
    from .dynamics import SystemRun

    clock = _time.perf_counter()
    fe, env = s.fe, s.case.environment
    net = fe.model.network
    nt = times.size
    X = np.broadcast_to(net.position, (nt, *net.position.shape)).copy()
    tension = np.zeros((nt, net.n_elements))
    ends = np.zeros((nt, len(fe.line_names), 2, 3))  # the catenaries' force on their end points, end A then end B
    x_ch = motion.channels(times, net.channel_positions())[0]  # (nt, channels, 3)
    depth = float(env.depth)
    for il, name in enumerate(fe.line_names):
        line = s.system.lines[name]
        nodes, els = np.asarray(fe.line_nodes[il]), np.asarray(fe.line_elements[il])
        body_end = s.system.points[line.end_b].kind == "body"
        anchor_node, fair_node = (nodes[0], nodes[-1]) if body_end else (nodes[-1], nodes[0])
        anchor = net.position[anchor_node]
        fair = x_ch[:, net.channel[fair_node]]
        d = fair[:, :2] - anchor[:2]
        span = np.linalg.norm(d, axis=1)
        unit = d / np.maximum(span, 1e-300)[:, None]
        seg = line.line.segments[0]
        lt = seg.line_type
        w = float(np.asarray(net.weight_per_length)[els[0]])  # the finite elements' own weight in water
        on_bed = anchor[2] <= -depth + 1e-6 * depth
        try:
            cat = catenary(span, fair[:, 2] - anchor[2], float(seg.length), float(lt.axial_stiffness), w,
                           env.seabed.friction, bool(on_bed))
        except (InputError, NoSolutionError) as err:
            raise InputError(f"lines.{name}: the quasi-static line (analysis.uncoupled.lines 'quasi_static') has no "
                             f"catenary at some time of the motion: {err} Suggested fix: 'lines: dynamic'.") from None
        ne = els.size
        px, pz, pt = _profiles(2 * ne + 1, cat, span, fair[:, 2] - anchor[2], float(seg.length),
                               float(lt.axial_stiffness), w, float(env.seabed.friction))
        xs = anchor + np.concatenate([px[:, ::2, None] * unit[:, None, :], pz[:, ::2, None]], axis=2)
        t_mid = pt[:, 1::2]
        if not body_end:
            xs, t_mid = xs[:, ::-1], t_mid[:, ::-1]
        X[:, nodes] = xs
        tension[:, els] = t_mid
        # the line pulls its fairlead towards the anchor and down (H, V the fairlead's force on the line) and its
        # anchor towards the fairlead and up
        at_fair = np.concatenate([-np.asarray(cat.H_fairlead)[:, None] * unit, -np.asarray(cat.V_fairlead)[:, None]],
                                 axis=1)
        at_anchor = np.concatenate([np.asarray(cat.H_anchor)[:, None] * unit, np.asarray(cat.V_anchor)[:, None]],
                                   axis=1)
        ends[:, il] = np.stack([at_anchor, at_fair] if body_end else [at_fair, at_anchor], axis=1)
    nb = len(fe.free_bodies)
    return SystemRun(time=times, position=X, velocity=np.zeros_like(X), tension=tension,
                     body_position=np.zeros((nt, nb, 6)), body_velocity=np.zeros((nt, nb, 6)),
                     failure_time=np.full(len(fe.con_node), np.nan), time_step=float(s.case.analysis.output_interval),
                     steps=nt - 1, iterations=0, wall_time=_time.perf_counter() - clock, interrupted=False,
                     end_force=ends)


def run_system_uncoupled(case, progress=None):
    """An uncoupled ``system_dynamic`` case (module docstring) as the coupled route's Dataset.

    Parameters
    ----------
    case : SystemCase
        With ``analysis.coupling: uncoupled``.
    progress : callable, optional
        ``progress(t, duration)`` of the lines' run (``lines: dynamic``).
    """
    from ..results import var
    from .dynamics import simulate_system, start_state, system_result
    from .dynamics.loop import _channels_fn

    s = prepare_system_uncoupled(case)
    motion = uncoupled_motion(case, s)
    a = case.analysis
    fe = s.fe
    if s.options.lines == "dynamic":
        run_a = s.dynamic.analysis.model_copy(update={"body_motions": {s.body: motion}})
        channels = _channels_fn(fe, run_a, a.duration)  # binds the motion (fe.body_motions) for the outputs too
        start_fe = dataclasses.replace(fe, model=at_motion_start(fe.model, channels))
        start = start_state(start_fe, run_a, case.environment)
        nd = a.numerical_damping
        run = simulate_system(fe, start, a.duration, a.time_step, a.output_interval, analysis=run_a,
                              tol=min(a.tolerance * 10, 1e-4), max_iter=a.max_iterations, progress=progress,
                              beta=(1 + nd) ** 2 / 4, gamma=0.5 + nd)
    else:
        fe.body_motions[s.body] = motion
        times = a.output_interval * np.arange(math.floor(a.duration / a.output_interval + 1e-9) + 1)
        run = _quasi_static_run(s, motion, times)
    mean = s.mean + np.asarray(s.system.bodies[s.body].position, float)
    ds = system_result(fe, run, case=case, settings={
        "damping_ratio": a.damping_ratio, "rayleigh": list(a.rayleigh), "start": "equilibrium", "damaged_lines": [],
        "coupling": "uncoupled", "lines": s.options.lines})
    ds.attrs.update(coupling="uncoupled", lines=s.options.lines, mooring_damping=list(s.options.mooring_damping),
                    mean_position=[float(v) for v in mean])
    t = np.asarray(ds["time"])
    body = list(ds["body"].values).index(s.body)
    for key, part, long in (("body_low_frequency", motion.low_frequency(t)[0],
                             "low-frequency {} of the body about its mean position (uncoupled route)"),
                            ("body_wave_frequency", motion.wave_frequency(t)[0],
                             "wave-frequency {} of the body about its mean position (uncoupled route)")):
        full = np.zeros((t.size, ds.sizes["body"], 6))
        full[:, body] = part
        # one unit per variable (CF): translations [m] and rotations [rad] apart, as body_position, body_rotation
        ds[f"{key}_motion"] = var(("time", "body", "axis"), full[..., :3], "m", long.format("motion"))
        ds[f"{key}_rotation"] = var(("time", "body", "angle"), full[..., 3:], "rad", long.format("rotation"))
    return ds

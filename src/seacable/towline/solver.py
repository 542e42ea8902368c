"""The towline model (paper 003) set up from SI parameters, its initial states and its time stepping."""

from __future__ import annotations

import math
import time as _time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from .._atomic import keep_whole_outputs
from .._validate import positive
from ..errors import ConvergenceError, InputError
from . import kernel as K
from .barge import Barge, barge_parameters

#: the joints' stiffness across the line (the pin's penalty), a fraction of the axial k: with k / 3 the
#: pins' stiffest mode is no stiffer than the line's axial one (see seacable.towline.kernel)
PIN_STIFFNESS = 1.0 / 3.0

__all__ = ["PIN_STIFFNESS", "TowlineModel", "TowlineRun", "check_time_step", "energy", "initial_state", "simulate",
           "stable_time_step"]

#: tug tow-point track: times (n,) -> positions (n, 3), velocities (n, 3)
TugFn = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]


@dataclass
class TowlineModel:
    """A towline of ``n_elements`` rigid elements between a tug and a barge (all SI).

    ``axial_stiffness`` is EA of the line (paper 003: breaking load over elongation at break). The
    rigid elements stretch only at their n + 1 joints (the two tow points included), so each joint
    spring is ``k = (n + 1) EA / L`` and the springs in series have the line's ``EA / L``; paper 003's
    ``k_j = P / d`` (per element, ``EA / l``) makes the line (n + 1) / n times too soft, 9 % with 11
    elements. Across the line each joint is a pin held by the penalty stiffness ``PIN_STIFFNESS k``.
    ``drag_tangential`` is the skin-friction coefficient
    C_f on the wetted perimeter, ``drag_normal`` C_D on the diameter, ``added_mass`` C_a across the
    line. ``damping_ratio`` (zeta, axial) and ``bending_damping_ratio`` (zeta_m) set the material
    damping of the joints. ``held`` holds the barge still; ``barge`` None is a fixed end at
    ``held_tow_point_height`` above the water.
    """

    n_elements: int
    length: float
    diameter: float
    mass_per_length: float
    axial_stiffness: float
    drag_normal: float = 1.2
    drag_tangential: float = 0.015
    added_mass: float = 1.0
    damping_ratio: float = 0.5
    bending_damping_ratio: float = 0.5
    transverse_damping_fraction: float = 0.1
    water_density: float = 1025.0
    gravity: float = 9.80665
    brake_tension: float = 0.0
    impact: bool = True
    drag: bool = True
    barge: Barge | None = None
    held: bool = False
    held_tow_point_height: float = 1.0
    depth: float | None = None
    seabed_stiffness: float = 3.0e6
    seabed_damping: float = 3.0e5
    friction: float = 0.0
    friction_velocity: float = 0.01
    params: np.ndarray = field(init=False, repr=False)
    barge_params: np.ndarray = field(init=False, repr=False)

    def __post_init__(self):
        n, L = self.n_elements, self.length
        if n < 1:
            raise InputError(f"n_elements must be >= 1, got {n}. Suggested fix: use the paper's 11 or more.")
        for name, unit in (("length", "m"), ("diameter", "m"), ("mass_per_length", "kg/m"),
                           ("axial_stiffness", "N")):
            positive(name, getattr(self, name), unit)
        el = L / n
        m = self.mass_per_length * el
        # n + 1 joint springs in series (both tow points included) give the line's EA / L
        k = self.axial_stiffness * (n + 1) / L
        P = np.zeros(K.P_SIZE)
        P[K.P_L], P[K.P_M], P[K.P_I] = el, m, m * el * el / 12.0
        P[K.P_D], P[K.P_AREA] = self.diameter, 0.25 * math.pi * self.diameter**2
        P[K.P_CA], P[K.P_CD], P[K.P_CF] = self.added_mass, self.drag_normal, self.drag_tangential
        P[K.P_K] = k
        P[K.P_KT] = PIN_STIFFNESS * k
        P[K.P_CX] = 2.0 * self.damping_ratio * math.sqrt(k * m)
        P[K.P_CT] = self.transverse_damping_fraction * P[K.P_CX]
        P[K.P_ZM] = self.bending_damping_ratio
        P[K.P_RHO], P[K.P_G] = self.water_density, self.gravity
        P[K.P_BRAKE] = self.brake_tension
        P[K.P_IMPACT] = float(self.impact)
        P[K.P_DRAG] = float(self.drag)
        P[K.P_DEPTH] = math.inf if self.depth is None else float(self.depth)
        P[K.P_KBOT], P[K.P_CBOT] = self.seabed_stiffness, self.seabed_damping
        P[K.P_MU], P[K.P_VFRIC] = self.friction, self.friction_velocity
        self.params = P
        self.barge_params = (barge_parameters(self.barge, self.water_density) if self.barge is not None
                             else np.zeros(1))

    @property
    def barge_tow_point(self) -> tuple[float, float]:
        """Tow point on the barge: (x forward of midship, height above the water). [m]"""
        if self.barge is None:
            return 0.0, self.held_tow_point_height
        return self.barge.tow_x, self.barge.tow_point_height

    @property
    def element_length(self) -> float:
        return self.length / self.n_elements

    @property
    def element_period(self) -> float:
        """Axial natural period of an element on its joint spring, ``2 pi sqrt(m / k)``. [s]"""
        return 2 * math.pi * math.sqrt(self.params[K.P_M] / self.params[K.P_K])


def stable_time_step(model: TowlineModel, safety: float = 0.8) -> float:
    """The explicit step, a fraction of the element's axial period ``T_n = 2 pi sqrt(m / k)``. [s]

    Paper 003 bounds the step by ``alpha T_n`` without giving alpha; here it follows from the
    stability of the symplectic Euler scheme (``omega dt < 2``) on the chain's stiffest modes, in air
    (no added mass): neighbours moving against each other along the line, ``omega^2 = 4 k / m``, and
    all elements turning the same way about their centres, which opens every joint across the line
    by ``l theta`` against the pin stiffness ``k_t``: ``omega^2 = k_t l^2 / I = 12 k_t / m``. With
    ``k_t = k / 3`` both give ``dt < sqrt(m / k)`` (= T_n / 2 pi). The joint and bending dampers are taken
    implicitly along the whole line and do not bound the step; the seabed's spring and damper (explicit) do,
    where there is a seabed.
    """
    P = model.params
    bound = min(math.sqrt(P[K.P_M] / P[K.P_K]), math.sqrt(P[K.P_M] / (3.0 * P[K.P_KT])))
    if math.isfinite(P[K.P_DEPTH]):
        # an element on the seabed: its spring k_b d l (omega dt < 2, with the rocking mode's factor 3 as the pins')
        # and its explicit damper c_b d l (dt < m / c, inside the damped oscillator's bound)
        kb, cb = P[K.P_KBOT] * P[K.P_D] * P[K.P_L], P[K.P_CBOT] * P[K.P_D] * P[K.P_L]
        if kb > 0.0:
            bound = min(bound, math.sqrt(P[K.P_M] / (3.0 * kb)))
        if cb > 0.0:
            bound = min(bound, P[K.P_M] / cb)
    return safety * bound


def check_time_step(model: TowlineModel, time_step: float | None) -> float:
    """Refuse a given ``time_step`` [s] above the stability bound; returns the bound. [s]"""
    bound = stable_time_step(model, 1.0)
    if time_step is not None and not 0.0 < time_step <= bound:
        raise InputError(f"time_step must be > 0 s and not above the explicit scheme's stability bound "
                         f"{bound:.4g} s (sqrt(m / k) of the {model.element_length:g} m elements), got "
                         f"{time_step:g} s. Suggested fix: leave time_step out (it is set automatically) or "
                         "use fewer elements.")
    return bound


@dataclass
class State:
    """The towline's state: element centres R (n, 3), frames E (n, 3, 3), body velocities nu (n, 3),
    angular velocities om (n, 2) = (q, r), the first element off the bitt, and the barge (x, y,
    heading, u, v, r)."""

    R: np.ndarray
    E: np.ndarray
    nu: np.ndarray
    om: np.ndarray
    first: int
    barge: np.ndarray


def _barge_point(model: TowlineModel, barge) -> np.ndarray:
    p = np.zeros(3)
    K.barge_point(barge, *model.barge_tow_point, p, np.zeros(3))
    return p


def initial_state(model: TowlineModel, tug_point, *, start: str = "straight", heading: float = 0.0,
                  drop_height: float | None = None) -> State:
    """The line at rest behind a tug whose tow point is at ``tug_point`` heading ``heading`` [rad].

    ``start``: ``"straight"`` lays the line straight astern of the tug, from the tow point down (or up)
    to the barge's tow point height, with the barge at its end; ``"dropped"`` lays it horizontal at
    ``drop_height`` above the water, the end elements sloping to the tow points (paper 003's drop);
    ``"coiled"`` keeps the whole line on the tug's bitt with the barge's tow point at the tug's (the
    payout scenario).
    """
    n, el = model.n_elements, model.element_length
    tug = np.asarray(tug_point, float)
    back = -np.array([math.cos(heading), math.sin(heading), 0.0])
    xt, zt = model.barge_tow_point
    R, E = np.zeros((n, 3)), np.zeros((n, 3, 3))
    nu, om = np.zeros((n, 3)), np.zeros((n, 2))
    if start == "coiled":
        end = tug.copy()
        end[2] = zt
        first = n
        R[:] = tug
        for k in range(n):
            K.frame_from_axis(back.copy(), E[k])
    else:
        first = 0
        if start == "straight":
            dz = zt - tug[2]
            if abs(dz) >= model.length:
                raise InputError(f"the tow points differ in height by {abs(dz):g} m, more than the line's "
                                 f"{model.length:g} m.")
            h = math.sqrt(model.length**2 - dz**2)
            pts = tug + np.linspace(0.0, 1.0, n + 1)[:, None] * (h * back + np.array([0.0, 0.0, dz]))
        elif start == "dropped":
            if drop_height is None:
                raise InputError("start 'dropped' needs drop_height in m (paper 003: 1 m above the water).")
            pts = np.zeros((n + 1, 3))
            pts[0] = tug
            for j in range(1, n + 1):
                target = drop_height if j < n else zt
                dz = target - pts[j - 1, 2]
                dz = max(-el * 0.99, min(el * 0.99, dz))
                pts[j] = pts[j - 1] + math.sqrt(el * el - dz * dz) * back + np.array([0.0, 0.0, dz])
        else:
            raise InputError(f"start must be 'straight', 'dropped' or 'coiled', got {start!r}.")
        end = pts[-1]
        for k in range(n):
            e1 = pts[k + 1] - pts[k]
            e1 /= np.linalg.norm(e1)
            K.frame_from_axis(e1, E[k])
            R[k] = 0.5 * (pts[k] + pts[k + 1])
    # the barge's midship behind its bow tow point, on the tug's heading
    barge = np.array([end[0] + xt * back[0], end[1] + xt * back[1], heading, 0.0, 0.0, 0.0])
    return State(R, E, nu, om, first, barge)


def joint_positions(model: TowlineModel, state: State, tug_point) -> np.ndarray:
    """Positions of the nodes (n + 1, 3): the tug's tow point, the joints, the barge's tow point."""
    n, half = model.n_elements, 0.5 * model.element_length
    e1 = state.E[:, :, 0]
    front, aft = state.R - half * e1, state.R + half * e1
    out = np.full((n + 1, 3), np.nan)
    out[0] = tug_point
    out[1:n] = 0.5 * (aft[:-1] + front[1:])
    out[1:state.first + 1] = np.nan
    out[n] = _barge_point(model, state.barge)
    return out


def energy(model: TowlineModel, state: State, tug_point) -> float:
    """Kinetic (with added mass) plus gravity and joint-spring energy of the line. [J]

    For the energy balance of the free line in air (no buoyancy, no drag, no damping). The spring
    energy follows the joint law of the kernel: ``k_t |gap|^2 / 2`` across the line (the mean direction
    of the joint's elements), and along it ``k g^2 / 2`` in tension (``g > 0``), nothing while the gap
    closes, and ``k_t (g + l/2)^2 / 2`` for an overlap ``-g`` beyond half an element.
    """
    P = model.params
    m, I = P[K.P_M], P[K.P_I]
    ke = 0.5 * m * np.sum(state.nu**2) + 0.5 * I * np.sum(state.om**2)
    pe = m * model.gravity * float(np.sum(state.R[:, 2]))
    half = 0.5 * model.element_length
    e1 = state.E[:, :, 0]
    prev = np.vstack([np.asarray(tug_point, float)[None], state.R + half * e1])    # joint j: aft of j - 1
    nxt = np.vstack([state.R - half * e1, _barge_point(model, state.barge)[None]])  # front of j
    gap = nxt - prev
    axis = np.zeros_like(gap)
    axis[:-1] += e1
    axis[1:] += e1
    axis /= np.linalg.norm(axis, axis=1, keepdims=True)
    g = np.sum(gap * axis, axis=1)
    across = np.sum(gap**2, axis=1) - g**2
    along = np.where(g > 0.0, P[K.P_K] * g**2, P[K.P_KT] * np.minimum(g + half, 0.0) ** 2)
    spring = 0.5 * float(np.sum(P[K.P_KT] * across + along))
    return ke + pe + spring


@dataclass(frozen=True)
class TowlineRun:
    """Stored states of a run at the output times."""

    time: np.ndarray
    nodes: np.ndarray          # (nt, n + 1, 3)
    centres: np.ndarray        # (nt, n, 3), NaN on the bitt
    axes: np.ndarray           # (nt, n, 3) e1
    tension: np.ndarray        # (nt, n + 1)
    slack: np.ndarray          # (nt, n + 1)
    released: np.ndarray       # (nt, n)
    tug: np.ndarray            # (nt, 3)
    barge: np.ndarray          # (nt, 6)
    time_step: float
    steps: int
    interrupted: bool
    wall_time: float
    final: State


def simulate(model: TowlineModel, tug: TugFn, duration: float, output_interval: float, state: State, *,
             time_step: float | None = None, safety: float = 0.8, progress=None) -> TowlineRun:
    """Explicit time stepping from ``state``; the tug's tow point follows ``tug(times)``.

    ``time_step`` None takes :func:`stable_time_step` (``safety`` times the stability bound), rounded
    down to divide ``output_interval``. A state that stops being finite raises
    :class:`~seacable.errors.ConvergenceError` with the time; Ctrl-C returns what was computed.
    """
    if not output_interval > 0 or output_interval > duration:
        raise InputError(f"output_interval must be > 0 s and not above duration ({duration:g} s), got "
                         f"{output_interval:g} s.")
    bound = check_time_step(model, time_step)
    dt0 = stable_time_step(model, safety) if time_step is None else float(time_step)
    sub = max(1, math.ceil(output_interval / dt0 - 1e-9))
    dt = output_interval / sub
    n_out = round(duration / output_interval)
    n = model.n_elements
    S = state
    R, E, nu, om = S.R.copy(), S.E.copy(), S.nu.copy(), S.om.copy()
    bs = S.barge.copy()
    first = np.array([S.first], np.int64)
    ma_prev = np.zeros((n, 3))
    inert = np.full(n, model.params[K.P_I])
    tension, slack = np.zeros(n + 1), np.zeros(n + 1, np.bool_)
    held = model.held or model.barge is None
    xt, zt = model.barge_tow_point
    P, BP = model.params, model.barge_params

    def snapshot(t, tug_point):
        st = State(R, E, nu, om, int(first[0]), bs)
        nodes = joint_positions(model, st, tug_point)
        centres = R.copy()
        centres[:first[0]] = np.nan
        rel = np.arange(n) >= first[0]
        return nodes, centres, E[:, :, 0].copy(), tension.copy(), slack.copy(), rel, bs.copy()

    p0, v0 = tug(np.array([0.0]))
    K.evaluate(R, E, nu, om, int(first[0]), P, p0[0], v0[0], bs, xt, zt, inert, tension, slack, ma_prev)
    records = [snapshot(0.0, p0[0])]
    times, tugs = [0.0], [p0[0]]
    steps = 0
    interrupted = False
    start = _time.perf_counter()
    try:
        block = max(1, 2**16 // sub)  # output intervals whose tug track is sampled in one call
        for k in range(n_out):
            t0 = k * output_interval
            if k % block == 0:
                times_b = t0 + dt * np.arange(min(block, n_out - k) * sub + 1)
                tug_p, tug_v = tug(times_b)
            i = (k % block) * sub
            tt, tp, tv = times_b[i:i + sub + 1], tug_p[i:i + sub + 1], tug_v[i:i + sub + 1]
            done = K.run_steps(dt, tp, tv, R, E, nu, om, first, P, bs, BP, xt, zt, held, ma_prev, inert,
                               tension, slack)
            steps += done
            if done < sub:
                raise ConvergenceError(
                    f"the towline state stopped being finite at t = {t0 + done * dt:.6g} s (time step "
                    f"{dt:.3g} s, stability bound {bound:.3g} s). Suggested fix: a smaller "
                    "time_step.",
                    iterations=steps, residual=float("nan"))
            K.evaluate(R, E, nu, om, int(first[0]), P, tp[-1], tv[-1], bs, xt, zt, inert, tension, slack,
                       np.zeros((n, 3)))
            times.append(tt[-1])
            tugs.append(tp[-1])
            records.append(snapshot(tt[-1], tp[-1]))
            if progress is not None:
                progress(tt[-1], duration)
    except KeyboardInterrupt:
        interrupted = True
        # an interrupt between an output's appends: keep the outputs all three lists hold
        keep_whole_outputs(times, tugs, records)
    cols = list(zip(*records))
    return TowlineRun(np.array(times), *(np.array(c) for c in cols[:6]), np.array(tugs), np.array(cols[6]),
                      dt, steps, interrupted, _time.perf_counter() - start,
                      State(R, E, nu, om, int(first[0]), bs))

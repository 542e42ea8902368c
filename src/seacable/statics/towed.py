"""Steady state of a cable towed in a current (2-D): uniform cables (:func:`towed_cable_steady`), composite
ones with points in line and current profiles (:func:`towed_line_steady`).

A cable is towed at a relative flow speed ``U`` (vessel speed over ground minus the current
component along the tow direction; paper 000's Table 1 case, vessel 1.0 m/s into a current of
-1.0 m/s, is ``U = 2 m/s``). Its lower end is free or carries a towed body. In steady uniform
flow the shape does not change with time, and the 2-D equations of paper 000, eq. (2) with all
time derivatives, shear forces and curvatures set to zero, reduce to (derived here, Z up,
angle ``phi`` of the cable to the horizontal, ``s`` the unstretched arc length from the lower
end, ``e = T/EA`` the strain)::

    dT/ds   = w sin(phi) + D_t
    T dphi/ds = w cos(phi) - D_n
    dx/ds   = -(1 + e) cos(phi)        (x positive astern, i.e. with the relative flow)
    dz/ds   =  (1 + e) sin(phi)

with the normal and tangential drag per unstretched length

    D_n = 1/2 rho C_dn d U^2 sin(phi)|sin(phi)| * f(e)
    D_t = 1/2 rho C_dt pi d U^2 cos(phi)|cos(phi)| * f(e)      (wetted perimeter pi d)

where ``f(e) = sqrt(1 + e)`` in paper 000 eq. (6) (the diameter of a constant-volume cable shrinks
as ``(1+e)^-1/2`` while its length grows as ``1+e``) and ``f = 1`` in the common form. Eq. (6)
is ``R_t = -1/2 rho d pi C_dt v_t|v_t| (1+e)^1/2`` with ``v_t = -U cos(phi)`` the relative
tangential velocity: the same form as the common ``1/2 rho C_dt pi d U^2 cos(phi)|cos(phi)|``
up to the stretch factor, so the two options differ only through ``f(e)`` (and not at all for
an inextensible cable). A third option refers ``C_dt`` to the diameter ``d`` instead of
``pi d`` (a convention found in other towed-cable codes); it is ``1/pi`` times the others.

Boundary conditions: at the lower end the cable tension balances the body's weight, drag and
lift (free end: ``T = 0``, and ``dphi/ds`` finite then requires ``w cos(phi) = D_n``, the critical
angle); at the top the cable is attached to the tow point. Because the flow is uniform both
lower-end conditions are known, so the two-point problem reduces to an initial-value problem
from the lower end, followed by a rigid translation that puts the top at the tow point.

References
----------
.. [1] Paper 000 (seeds/000_e4cc68758a51635b.txt): 3-D nonlinear dynamics of a low-tension
   towed cable, eq. (2) and (6), Tables 1 and 2.
.. [2] Ablow, C. M. and Schechter, S., 1983. Numerical simulation of undersea cable dynamics.
   Ocean Engineering 10(6), 443-457.
"""

from __future__ import annotations

import itertools
import warnings
from dataclasses import dataclass
from typing import Literal

import numpy as np

from .. import _validate as v
from ..errors import ConvergenceError, InputError, NoSolutionError, SeacableWarning

__all__ = ["TangentialDragForm", "TowedCableSteady", "critical_angle", "towed_cable_steady", "towed_line_steady"]

TangentialDragForm = Literal["paper000", "common", "diameter"]
"""Form of the tangential drag per unstretched length.

``"paper000"``
    Paper 000 eq. (6): ``1/2 rho C_dt pi d U^2 cos|cos| sqrt(1+e)``; the normal drag also
    carries ``sqrt(1+e)``.
``"common"``
    ``1/2 rho C_dt pi d U^2 cos|cos|``, no stretch factor on either drag.
``"diameter"``
    ``1/2 rho C_dt d U^2 cos|cos|`` (``C_dt`` referred to the diameter), no stretch factor.
"""

_TANGENTIAL_FORMS = ("paper000", "common", "diameter")


def _critical_cos(weight_per_length, normal_drag_scale):
    """cos(phi) of the root of ``w cos(phi) = q sin^2(phi)``, ``q = 1/2 rho C_dn d U^2``.

    With ``c = cos(phi)`` the equation is ``q c^2 + w c - q = 0``; the positive root written as
    ``2q / (w + sqrt(w^2 + 4 q^2))`` is free of cancellation and gives ``c = 0`` (vertical)
    for ``q = 0``.
    """
    w = np.asarray(weight_per_length, dtype=float)
    q = np.asarray(normal_drag_scale, dtype=float)
    return 2.0 * q / (w + np.sqrt(w * w + 4.0 * q * q))


def critical_angle(weight_per_length, diameter, speed, drag_normal, water_density=1025.0):
    """Critical angle of a free-ended cable towed in a uniform flow.

    The angle ``phi`` to the horizontal at which the normal component of the weight balances
    the normal drag, ``w cos(phi) = 1/2 rho C_dn d U^2 sin^2(phi)``; a long uniform cable with
    a free lower end lies straight at this angle. Solved in closed form as a quadratic in
    ``cos(phi)``. The same root is the laying angle of the straight-line laying theory
    (paper 001 eq. (7)).

    Parameters
    ----------
    weight_per_length : array_like
        Weight in water per unit length, positive (the cable sinks). [N/m]
    diameter : array_like
        Hydrodynamic diameter. [m]
    speed : array_like
        Relative flow speed: vessel speed minus the current along the tow direction. [m/s]
    drag_normal : array_like
        Normal drag coefficient C_dn. [-]
    water_density : array_like, optional
        Density of sea water. [kg/m^3]

    Returns
    -------
    numpy.ndarray or float
        Angle of the cable to the horizontal, in ``(0, pi/2]`` (``pi/2`` at zero speed). [rad]

    Raises
    ------
    InputError
        If an input is out of range (weight, diameter, density not > 0; speed or drag < 0).

    References
    ----------
    .. [1] Paper 000, Table 2 and its free-end boundary condition eq. (14).
    .. [2] Paper 001 eq. (7): ``w cos(alpha) = C_D rho V_s^2 sin^2(alpha) / 2``.
    """
    w = v.positive("weight_per_length", weight_per_length, "N/m",
                   "give the weight in water (positive for a cable that sinks)")
    d = v.positive("diameter", diameter, "m", "give the outer diameter in metres")
    u = v.nonnegative("speed", speed, "m/s", "give the relative flow speed (vessel minus current)")
    cdn = v.nonnegative("drag_normal", drag_normal, "", "use a normal drag coefficient such as 1.2-1.8")
    rho = v.positive("water_density", water_density, "kg/m^3", "sea water is about 1025 kg/m^3")
    q = 0.5 * rho * cdn * d * np.asarray(u) ** 2
    out = np.arccos(np.clip(_critical_cos(w, q), 0.0, 1.0))
    return out if np.ndim(out) else float(out)


@dataclass(frozen=True)
class TowedCableSteady:
    """Steady shape and tension of a towed cable (result of :func:`towed_cable_steady`).

    Attributes
    ----------
    s : numpy.ndarray
        Unstretched arc length from the lower end. [m]
    x : numpy.ndarray
        Horizontal position relative to the tow point, positive astern (with the flow). [m]
    z : numpy.ndarray
        Vertical position relative to the tow point, positive up (so mostly negative). [m]
    tension : numpy.ndarray
        Effective tension. [N]
    angle : numpy.ndarray
        Angle of the cable to the horizontal, positive when it descends astern. [rad]
    top_tension : float
        Tension at the tow point. [N]
    top_angle : float
        Angle to the horizontal at the tow point. [rad]
    layback : float
        Horizontal distance from the tow point to the lower end, positive astern. [m]
    depth_of_lower_end : float
        Depth of the lower end below the tow point (positive down). [m]
    critical_angle : float
        Critical angle of the bare cable at this speed (the angle a long cable tends to). [rad]
    """

    s: np.ndarray
    x: np.ndarray
    z: np.ndarray
    tension: np.ndarray
    angle: np.ndarray
    top_tension: float
    top_angle: float
    layback: float
    depth_of_lower_end: float
    critical_angle: float


@dataclass(frozen=True)
class _Piece:
    """A stretch of uniform cable between two points where forces act: its length [m], weight in water w
    [N/m], normal and tangential drag scales qn, qt [N/m], EA [N] (None: inextensible) and whether the drags
    carry paper 000's stretch factor."""

    length: float
    w: float
    qn: float
    qt: float
    ea: float | None
    stretch_drag: bool


def _piece(length, w, d, cdn, cdt, ea, u, rho, tangential_drag) -> _Piece:
    perimeter = d if tangential_drag == "diameter" else np.pi * d
    return _Piece(float(length), float(w), 0.5 * rho * cdn * d * u * u, 0.5 * rho * cdt * perimeter * u * u, ea,
                  tangential_drag == "paper000" and ea is not None)


def _steady(pieces, joints, tail, s_out, rtol, what, flow=None):
    """Integrate the steady equations piece after piece from the lower end (module docstring).

    ``pieces`` from the lower end up; ``joints[k]`` the (drag astern at the pieces' flow speed, drag that does
    not follow the flow, net weight down, lift up at the pieces' flow speed) [N] of the point between piece k and k + 1, ``tail`` that of the
    lower end's body and its lift up at the pieces' flow speed (zeros: a free end). The tension's horizontal and vertical parts step by a joint's forces
    (its force balance). ``flow(z)``: the square of the flow speed at height z above the lower end relative to
    the pieces' (a current varying with depth; None: uniform), scaling every drag that follows the flow. ``s_out``: the unstretched arc lengths to
    report (from the lower end, increasing, from 0 to the whole length); a joint's s is reported twice, below
    and above it. ``what``: the
    lower end's body, for the slack message. Returns a :class:`TowedCableSteady` (``critical_angle`` of the
    lowest piece) and the indices of the points just above each joint in its arrays."""
    from scipy.integrate import solve_ivp

    total = sum(p.length for p in pieces)
    scale = max(sum(abs(p.w) * p.length for p in pieces), 1e-300)
    t_small = 1e-9 * scale
    if flow is None:
        def flow(_z):
            return 1.0
    h, vv = tail[0] * flow(0.0) + tail[1], tail[2] - tail[3] * flow(0.0)
    x0 = z0 = s0 = 0.0
    ss, ys, above = [], [], []
    phi_c = float(np.arccos(np.clip(_critical_cos(pieces[0].w, pieces[0].qn * flow(0.0)), 0.0, 1.0)))
    nfev = 0
    for k, p in enumerate(pieces):
        t0 = float(np.hypot(h, vv))
        free_end = k == 0 and t0 <= 1e-12 * scale

        def strain(t, p=p):
            return 0.0 if p.ea is None else t / p.ea

        def factor(t, p=p):
            return np.sqrt(1.0 + strain(t)) if p.stretch_drag else 1.0

        def g_normal(phi, t, z=0.0, p=p):  # w cos(phi) - D_n  [N/m]
            sp = np.sin(phi)
            return p.w * np.cos(phi) - p.qn * flow(z) * sp * abs(sp) * factor(t)

        def dtds(phi, t, z=0.0, p=p):
            cp = np.cos(phi)
            return p.w * np.sin(phi) + p.qt * flow(z) * cp * abs(cp) * factor(t)

        if free_end:
            t0, phi0 = 0.0, phi_c
            # limit of dphi/ds = g/T as T -> 0 along the regular solution: with psi = phi - phi_c,
            # T ~ a s, g ~ g_phi psi + g_T T, the regular solution psi = k s gives
            # k = g_T / (1 - g_phi / a).
            # (and with a flow varying in height, the term g_z dz/ds = g_z sin(phi_c) beside g_T a)
            a = dtds(phi0, 0.0)
            qn = p.qn * flow(0.0)
            g_phi = -p.w * np.sin(phi0) - 2.0 * qn * np.sin(phi0) * np.cos(phi0)
            g_t = -qn * np.sin(phi0) ** 2 * 0.5 / p.ea if p.stretch_drag else 0.0
            dz = 1e-6 * total
            g_z = -p.qn * (flow(dz) - flow(-dz)) / (2 * dz) * np.sin(phi0) ** 2
            k_lim = (g_t * a + g_z * np.sin(phi0)) / (a - g_phi) if a > 0 else 0.0
        elif t0 <= t_small:
            raise NoSolutionError(
                f"the cable tension vanishes at s = {s0:.6g} m (the point there cancels the load below it): no "
                "taut steady shape exists. Suggested fix: make the points below heavier than their lift or buoyancy.")
        else:
            phi0 = float(np.arctan2(vv, h))
            k_lim = 0.0

        def rhs(_s, y, free_end=free_end, k_lim=k_lim, strain=strain, g_normal=g_normal, dtds=dtds):
            t, phi = y[0], y[1]
            one_e = 1.0 + strain(t)
            dphi = k_lim if (free_end and t <= t_small) else g_normal(phi, t, y[3]) / t
            return [dtds(phi, t, y[3]), dphi, -one_e * np.cos(phi), one_e * np.sin(phi)]

        def slack_event(_s, y):  # tension falls to (almost) zero
            return y[0] - t_small

        slack_event.terminal = True
        slack_event.direction = -1
        s1 = s0 + p.length if k < len(pieces) - 1 else total
        inner = s_out[(s_out > s0) & (s_out < s1)]
        t_eval = np.concatenate(([s0], inner, [s1]))
        sol = solve_ivp(rhs, (s0, s1), [t0, phi0, x0, z0], method="Radau", t_eval=t_eval, rtol=rtol,
                        atol=[rtol * max(scale, t0, 1.0), rtol, rtol * total, rtol * total],
                        events=None if free_end else slack_event)
        nfev += sol.nfev
        if sol.status == 1:
            raise NoSolutionError(
                f"the cable tension vanishes at s = {sol.t_events[0][0]:.6g} m above the towed body ({what}): no "
                "taut steady shape exists. Suggested fix: make the body heavier than its lift, add drag, or tow "
                "faster.")
        if not sol.success:
            raise ConvergenceError(
                f"towed_cable_steady: the integrator failed ({sol.message}) after {nfev} evaluations. "
                "Suggested fix: loosen rtol or check the inputs for extreme values.", iterations=int(nfev))
        if not np.all(np.isfinite(sol.y)):
            raise ConvergenceError("towed_cable_steady: the integration produced non-finite values. "
                                   "Suggested fix: check the body forces and cable properties.",
                                   iterations=int(nfev))
        above.append(len(ss))
        ss.extend(sol.t)
        ys.extend(sol.y.T)
        t1, phi1, x0, z0 = sol.y[:, -1]
        s0 = s1
        if k < len(joints):
            qd, fd, down, up = joints[k]
            h, vv = t1 * np.cos(phi1) + qd * flow(z0) + fd, t1 * np.sin(phi1) + down - up * flow(z0)
    y = np.array(ys)
    tension, angle = y[:, 0], y[:, 1]
    x = y[:, 2] - y[-1, 2]
    z = y[:, 3] - y[-1, 3]
    if np.any(z > 1e-9 * total):
        warnings.warn(f"part of the towed cable lies up to {z.max():.3g} m above the tow point; the "
                      "free surface is not modelled. Check the body weight and lift.",
                      SeacableWarning, stacklevel=3)
    res = TowedCableSteady(s=np.array(ss), x=x, z=z, tension=tension, angle=angle,
                           top_tension=float(tension[-1]), top_angle=float(angle[-1]),
                           layback=float(x[0]), depth_of_lower_end=float(-z[0]), critical_angle=phi_c)
    return res, above[1:]


def _checked_body(body_weight, body_drag_area, body_drag_force, body_lift, rtol, n_points):
    """The towed body's forces and the solution's settings, checked: (W [N], C_D A [m^2], drag [N], lift [N],
    rtol, n_points)."""
    wb = v.finite("body_weight", body_weight, "N", "give the body's weight in water in newtons")
    cda = v.nonnegative("body_drag_area", body_drag_area, "m^2", "give C_D times the reference area")
    fdb = v.nonnegative("body_drag_force", body_drag_force, "N", "give the body's drag in newtons")
    lift = v.finite("body_lift", body_lift, "N", "give the vertical force in newtons, positive up")
    rtol = v.in_range("rtol", rtol, 1e-13, 1e-3, "", "use a relative tolerance such as 1e-10")
    n_points = int(v.at_least("n_points", n_points, 2, "", "ask for at least the two ends"))
    return wb, cda, fdb, lift, rtol, n_points


def towed_cable_steady(length, weight_per_length, diameter, speed, drag_normal, drag_tangential=0.0,
                       *, water_density=1025.0, axial_stiffness=None, body_weight=0.0,
                       body_drag_area=0.0, body_drag_force=0.0, body_lift=0.0,
                       tangential_drag: TangentialDragForm = "paper000",
                       n_points=101, rtol=1e-10) -> TowedCableSteady:
    """Steady 2-D shape and tension of a cable towed in a uniform current.

    Integrates the steady cable equations (module docstring) from the lower end, where the
    tension and angle follow from the body (or the critical angle with ``T = 0`` for a free
    end), to the tow point with :func:`scipy.integrate.solve_ivp` (Radau, tight tolerances),
    and then translates the shape so that the top is at the tow point.

    Parameters
    ----------
    length : float
        Unstretched cable length. [m]
    weight_per_length : float
        Weight in water per unit unstretched length, positive when the cable sinks. [N/m]
    diameter : float
        Hydrodynamic diameter. [m]
    speed : float
        Relative flow speed: vessel speed minus the current along the tow direction
        (paper 000 Table 1: 1.0 - (-1.0) = 2.0). [m/s]
    drag_normal : float
        Normal drag coefficient C_dn. [-]
    drag_tangential : float, optional
        Tangential drag coefficient C_dt (0 disables tangential drag). [-]
    water_density : float, optional
        Density of sea water. [kg/m^3]
    axial_stiffness : float or None, optional
        Axial stiffness EA; ``None`` for an inextensible cable. [N]
    body_weight : float, optional
        Weight in water of the towed body, positive when it sinks. [N]
    body_drag_area : float, optional
        Drag area C_D*A of the body; its drag is ``1/2 rho C_D A U^2``. [m^2]
    body_drag_force : float, optional
        Additional body drag given as a force (added to the drag from the area). [N]
    body_lift : float, optional
        Vertical hydrodynamic force on the body, positive up (a depressor gives a negative
        value). [N]
    tangential_drag : {"paper000", "common", "diameter"}, optional
        Form of the tangential drag, see :data:`TangentialDragForm`. [-]
    n_points : int, optional
        Number of equally spaced output points along the cable (>= 2). [-]
    rtol : float, optional
        Relative tolerance of the integrator. [-]

    Returns
    -------
    TowedCableSteady
        Arrays ``s, x, z, tension, angle`` from the lower end (index 0) to the tow point
        (index -1), and the summary values.

    Raises
    ------
    InputError
        If an input is out of range or ``tangential_drag`` is not a known form.
    NoSolutionError
        If the tension vanishes above a towed body (the body's net force points up and the cable
        would go slack).
    ConvergenceError
        If the integrator fails.

    Warns
    -----
    SeacableWarning
        If part of the cable lies above the tow point (a buoyant or lifting body).

    References
    ----------
    .. [1] Paper 000, eq. (2), (6), (14), Tables 1 and 2.
    """
    length = v.positive("length", length, "m", "give the unstretched cable length in metres")
    w = v.positive("weight_per_length", weight_per_length, "N/m",
                   "give the weight in water (positive for a cable that sinks)")
    d = v.positive("diameter", diameter, "m", "give the outer diameter in metres")
    u = v.nonnegative("speed", speed, "m/s", "give the relative flow speed (vessel minus current)")
    cdn = v.nonnegative("drag_normal", drag_normal, "", "use a normal drag coefficient such as 1.2-1.8")
    cdt = v.nonnegative("drag_tangential", drag_tangential, "",
                        "use a tangential drag coefficient such as 0.003-0.02")
    rho = v.positive("water_density", water_density, "kg/m^3", "sea water is about 1025 kg/m^3")
    ea = None if axial_stiffness is None else v.positive(
        "axial_stiffness", axial_stiffness, "N", "give EA in newtons, or None for an inextensible cable")
    wb, cda, fdb, lift, rtol, n_points = _checked_body(body_weight, body_drag_area, body_drag_force, body_lift, rtol,
                                                       n_points)
    for name, val in (("length", length), ("weight_per_length", w), ("diameter", d), ("speed", u)):
        if np.ndim(val):
            raise InputError(f"{name} must be a scalar for towed_cable_steady, got an array of shape "
                             f"{np.shape(val)}. Suggested fix: loop over the cases.")
    v.one_of("tangential_drag", tangential_drag, _TANGENTIAL_FORMS)

    piece = _piece(length, w, d, cdn, cdt, ea, u, rho, tangential_drag)
    return _steady([piece], [], (0.5 * rho * cda * u * u, fdb, wb - lift, 0.0), np.linspace(0.0, length, n_points),
                   rtol, f"body weight {wb:.6g} N, lift {lift:.6g} N")[0]


def towed_line_steady(line, speed, *, water_density=1025.0, gravity=9.80665, body_weight=0.0, body_drag_area=0.0,
                      body_drag_force=0.0, body_lift=0.0, body_lift_area=0.0,
                      tangential_drag: TangentialDragForm = "paper000", n_points=101, rtol=1e-10):
    """Steady 2-D shape and tension of a composite towed cable (:func:`towed_cable_steady` segment by segment).

    The line's end A is the lower (towed) end, end B the tow point: its segments (each line type's weight in
    water, diameter, drag coefficients and EA) follow each other from the towed body up, and each attachment
    (:class:`seacable.line.PointMass`: a clump, a depressor's weight, a float) acts at its arc length from the
    lower end with its net weight in water and its drag ``1/2 rho C_D A U^2`` astern. At a point where forces
    act the tension's horizontal and vertical parts step by them (its force balance); between, the steady
    equations of the module docstring hold with that segment's properties. An attachment at the lower end adds
    to the body; one at the tow point acts on the vessel, not on the cable.

    Parameters
    ----------
    line : seacable.line.Line
        The cable, end A at the towed end.
    speed : float or (depths, speeds)
        Relative flow speed (vessel minus current along the tow) [m/s], or its profile: depths below the tow
        point [m] (increasing) and the relative speeds there (>= 0), linear between, constant beyond. With a
        profile each drag (the cable's, a point's, the body's) takes the flow at its depth, and the lower end's
        depth is found so that the top comes to the tow point (a root in one variable, Brent's method, each
        trial a whole integration).
    water_density, gravity : float
        [kg/m^3], [m/s^2]
    body_weight, body_drag_area, body_drag_force, body_lift
        The body at the lower end, as in :func:`towed_cable_steady`. [N], [m^2], [N], [N]
    body_lift_area
        The body's lift coefficient times its reference area, C_L A, positive up: a lift
        ``1/2 rho C_L A U^2`` at the flow past it (a depressor's is negative). [m^2]
    tangential_drag : {"paper000", "common", "diameter"}
        Form of the tangential drag, see :data:`TangentialDragForm`.
    n_points : int
        Equally spaced output points along the whole line (>= 2); each segment joint and attachment is
        reported too, twice (below and above it). [-]
    rtol : float
        Relative tolerance of the integrator. [-]

    Returns
    -------
    tuple
        The :class:`TowedCableSteady` (arrays from the lower end to the tow point) and, for each point where
        forces act above the lower end (joints and attachments, in order up the line), ``(s, index)``: its arc
        length and the index of the array entry just above it.
    """
    from scipy.optimize import brentq

    from ..line import Line

    if not isinstance(line, Line):
        raise InputError(f"line must be a seacable.Line, got {type(line).__name__}. Suggested fix: build it "
                         "with Line(segments=...) or Line.single(line_type, length).")
    profile = None
    if np.ndim(speed) == 0:
        u = v.nonnegative("speed", speed, "m/s", "give the relative flow speed (vessel minus current)")
    else:
        try:
            zd, us = (np.asarray(a, float).ravel() for a in speed)
        except (TypeError, ValueError):
            raise InputError("speed must be a relative flow speed in m/s or a pair (depths [m], speeds [m/s]), got "
                             f"{speed!r}. Suggested fix: give the profile as two lists of the same length.") from None
        if zd.size == 0 or zd.size != us.size or not np.all(np.isfinite(zd)) or np.any(np.diff(zd) <= 0):
            raise InputError(f"the flow profile's depths {zd.tolist()} m must be increasing, finite and as many as its "
                             f"speeds ({us.size}). Suggested fix: list depths below the tow point from the top down.")
        bad = np.flatnonzero(~(us >= 0.0))
        if bad.size:
            raise InputError(f"the relative flow speed at {zd[bad[0]]:g} m depth is {us[bad[0]]:g} m/s, expected >= 0: "
                             "the current outruns the vessel there, and the steady 2-D tow assumes the flow passes "
                             "the cable astern at every depth. Suggested fix: tow faster than the current, or run "
                             "towed_dynamic.")
        u = float(us.max())
        profile = (zd, us)
    rho = v.positive("water_density", water_density, "kg/m^3", "sea water is about 1025 kg/m^3")
    g = v.positive("gravity", gravity, "m/s^2", "use 9.80665")
    wb, cda, fdb, lift, rtol, n_points = _checked_body(body_weight, body_drag_area, body_drag_force, body_lift, rtol,
                                                       n_points)
    cla = v.finite("body_lift_area", body_lift_area, "m^2", "give C_L times its reference area, positive up")
    v.one_of("tangential_drag", tangential_drag, _TANGENTIAL_FORMS)
    total = float(line.length)
    tol_s = 1e-9 * total
    # the points where forces act: segment joints (none) and attachments, merged where they coincide
    ends = np.cumsum([sg.length for sg in line.segments])
    cuts = {}
    for s in ends[:-1]:
        cuts.setdefault(round(float(s) / tol_s), [float(s), 0.0, 0.0, 0.0])
    # drag at the speed u (scaled by the flow), fixed drag, net weight down, lift up at the speed u
    tail = [0.5 * rho * cda * u * u, fdb, wb - lift, 0.5 * rho * cla * u * u]
    for k, att in enumerate(line.attachments):
        if att.axial_drag_area is not None and att.axial_drag_area != att.drag_area:
            raise InputError(f"line.attachments[{k}] has a drag along the line ({att.axial_drag_area:g} m^2) other than "
                             f"across it ({att.drag_area:g} m^2): the steady tow takes an attachment's drag along the "
                             "flow. Suggested fix: give its drag in the flow as drag_area alone, or run towed_dynamic "
                             "(its finite-element formulation takes both).")
        drag, down, up = 0.5 * rho * att.drag_area * u * u, att.net_weight(rho, g), 0.5 * rho * att.lift_area() * u * u
        if att.s <= tol_s:
            tail[0] += drag
            tail[2] += down
            tail[3] += 0.5 * rho * att.lift_area() * u * u
        elif att.s < total - tol_s:
            c = cuts.setdefault(round(float(att.s) / tol_s), [float(att.s), 0.0, 0.0, 0.0])
            c[1] += drag
            c[2] += down
            c[3] += up
    joints = sorted(cuts.values())
    bounds = [0.0] + [j[0] for j in joints] + [total]
    pieces = []
    for s0, s1 in itertools.pairwise(bounds):
        k = min(int(np.searchsorted(ends, 0.5 * (s0 + s1))), len(ends) - 1)
        lt = line.segments[k].line_type
        pieces.append(_piece(s1 - s0, lt.submerged_weight(rho, g), lt.diameter, *lt.effective_drag(),
                             lt.axial_stiffness, u, rho, tangential_drag))
    if pieces[0].w <= 0.0 and not any(tail):
        raise InputError(f"the lowest segment of the towed line floats (weight in water {pieces[0].w:.6g} N/m) and "
                         "has no body at its end: it has no steady shape below the tow point. Suggested fix: add a "
                         "body (body_weight) or a heavier line type.")
    knots = [(j[1], 0.0, j[2], j[3]) for j in joints]
    s_out = np.linspace(0.0, total, n_points)
    what = f"body weight {wb:.6g} N, lift {lift:.6g} N"
    if profile is None or u == 0.0:
        res, above = _steady(pieces, knots, tuple(tail), s_out, rtol, what)
        return res, [(j[0], i) for j, i in zip(joints, above, strict=True)]

    def solve(z_base):
        """The tow with its lower end at height z_base [m] (<= 0) relative to the tow point."""
        def flow(z):
            return (np.interp(-(z_base + z), profile[0], profile[1]) / u) ** 2
        return _steady(pieces, knots, tuple(tail), s_out, rtol, what, flow)

    def miss(z_base):  # how far above the tow point the top comes
        return z_base + solve(z_base)[0].depth_of_lower_end

    lo, hi = -2.0 * total, 0.0  # the lower end lies within the stretched length (under twice the length) below
    f_lo, f_hi = miss(lo), miss(hi)
    if f_lo > 0.0 or f_hi < 0.0:
        raise NoSolutionError(f"no depth of the lower end brings the towed line's top to the tow point in the flow "
                              f"profile (misses {f_lo:.6g} m and {f_hi:.6g} m at the bracket's ends). Suggested fix: "
                              "check the profile and the line's weight.")
    z_base = brentq(miss, lo, hi, xtol=1e-10 * total, rtol=4 * np.finfo(float).eps)
    res, above = solve(z_base)
    return res, [(j[0], i) for j, i in zip(joints, above, strict=True)]

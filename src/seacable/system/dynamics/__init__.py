"""Coupled dynamics of a mooring system (analysis ``system_dynamic``): finite-element lines and rigid bodies.

Every line of a :class:`~seacable.system.model.MooringSystem` is discretised into truss elements as
the single-line mooring model (:func:`seacable.mooring.network.network_from_line`: segments,
attachments, element count); lines that end at the same point share its node. Fixed points are held,
coupled points follow a motion, free points move with their mass, volume, added mass and drag area.
A point on a free body is tied to it (``x = r + R(theta) p``); a point on a fixed body is held, a
point on a prescribed body follows the body's 6-DOF motion.

A free body has six degrees of freedom: the reference point (x, y, z) and the angles (roll, pitch,
yaw), ``R = Rz(yaw) Ry(pitch) Rx(roll)``. Its loads (global axes, moments about the reference point):
weight ``m g`` at the centre of gravity and buoyancy ``rho g V`` at the centre of buoyancy (both turning
with the body), the waterplane's heave restoring ``-rho g A_wp (z - z_given)`` at the reference point
(the volume is the one at the body's given position) and its moment ``rho g (I_xx a_y, -I_yy a_x, 0)`` with ``a = R e_z``
(``-rho g I phi`` for small roll or pitch) -- or, when given, the user's 6x6 hydrostatic matrix about
the given position (weight and buoyancy then as at that position): the conventions of the system
statics (:mod:`seacable.system.statics`, MoorPy's Body);
the constant external force, an optional external force time series, linear and quadratic damping
(6x6, body axes: ``-B1 v - B2 |v_r| v_r``, ``v_r`` the velocity relative to the current at the reference
point -- at the surface when it is above --, so that a body in a current drifts to where its lines
balance the current's drag; waves act on the lines only), added mass (6x6, body axes) and the forces
of the lines at its points. The inertia is the rigid body's about the reference point (``I_cg`` moved by the parallel-axis
rule, the coupling ``m skew(c)`` of an offset centre of gravity).

One implicit step advances the lines and the bodies together: Newmark's average acceleration (beta
1/4, gamma 1/2) with Newton iterations on the free nodes and the body DOFs at once; the banded
system of the nodes is bordered by the bodies and solved by its Schur complement
(:mod:`seacable.system.dynamics.kernel`), so a step costs no more than one of the prescribed-motion
model (``bench/bench_system_dynamics.py``). Rotations: the unknowns are the angles and the geometry is exact at any angle; the angular
velocity is ``w = E(angles) d(angles)/dt`` (``w = roll' Rz Ry e_x + pitch' Rz e_y + yaw' e_z``) and the
rigid body's rotational inertia acts on ``dw/dt = E angles'' + E' angles'``, with its gyroscopic moment
``w x (I w)`` and the centripetal force ``m w x (w x c)`` of an offset centre of gravity (those of the added
mass in a turning frame are left out); the moments enter as the angles' generalised forces ``E^T M``.
``E`` is singular at pitch +-90 deg, so each body carries a chart: ``R = R0 R(angles)`` with a base
rotation ``R0`` (the identity to start with). After a converged step (and at the start) a body whose
|pitch| exceeds 1 rad is re-charted: ``R0 <- R0 R(angles)``, angles <- 0, and the rates re-expressed so
that the angular velocity and acceleration are unchanged (``angles' = R0^T w``, ``angles'' = R0^T alpha -
E'(0) angles'``, :func:`seacable.system.dynamics.frames.rechart`), and from then on after every step (its
angles then stay within one step's turn of 0: incremental rotations, as accurate whichever way the body
points, and its Newton matrix takes the velocity part of the angular acceleration too,
:func:`~seacable.system.dynamics.frames.rate_tangent`); everything that uses the rotation (points,
centres of gravity and buoyancy, inertia, added mass, damping, waterplane) uses ``R0 R(angles)``, ``E``
becomes ``R0 E``. A body that never passes 1 rad of pitch keeps ``R0 = I`` and its results are those
without charts, bit for bit. The output ``body_position`` angles are the global (roll, pitch, yaw) of
``R = Rz(yaw) Ry(pitch) Rx(roll)`` followed continuously from step to step (of their two Euler branches,
moved by whole turns, the one nearest the last; pitch then leaves [-pi/2, pi/2] when the body turns
over): continuous except at pitch +-90 deg itself, where only roll -+ yaw is defined. ``body_velocity``
reports the reference point's velocity and the rates of those angles (``E^-1 w``, regularised at pitch
+-90 deg as the Newton step is), ``body_angular_velocity`` the angular velocity ``w`` (global axes),
which stays regular there.

The statics (and the static start) leave out of each Newton step the turn about a body's free spin
axis, when it has one: the line through its reference point on which all its line points and its
centres of gravity and buoyancy lie (a MoorDyn rod), turning about which changes none of its loads.
Without it the Newton matrix's unsymmetric turning terms give that stiffness-free turn steps of
hundreds of radians, and the step limit (0.1 rad) then stalls the whole solve.

A line end can fail (``failures``): at a given time, or when the tension of its end element first
reaches a given value; the end's node (a node of its own from the start, tied to its point until
then: held there, on its body, or at a free point on the point's node, ``x_end = x_point``, the tie's
force passing to the point) is released with the position and velocity it has and moves freely with
its half element; the point keeps its own mass, volume and the other lines. The time is recorded
(``failure_time``).

The run starts from the static equilibrium of the same finite-element system, bodies included (and
the current's drag on them; pseudo-transient Newton on the same bordered system with the inertia
replaced by a pseudo-mass); ``release_offsets`` then hold named free bodies at their equilibrium plus an offset while the lines
settle, and release them at t = 0 (a free decay); ``start: held`` instead holds the free bodies at
their given positions for the static start, as MoorDyn starts its free bodies.

Stiff modes the step cannot resolve (the axial ringing of a snapped line end) are not damped by the
average-acceleration rule; the lines' axial damping (``damping_ratio``), water drag and seabed
friction take them, and ``numerical_damping`` adds Newmark's first-order dissipation when needed.

The package's modules: :mod:`.fe` builds the finite-element system, :mod:`.loop` solves its static start and
steps it in time, :mod:`.outputs` writes the result, :mod:`.analysis` runs a ``system_dynamic`` case; the
compiled core is :mod:`.kernel` (the Newton iteration and the time steps), :mod:`.frames` (rotations and
charts), :mod:`.body` (a body's loads) and :mod:`.linsolve` (band and dense solves).
"""

from __future__ import annotations

from ..case import BodyMotion, ExternalForceSeries, LineFailure, SystemDynamicAnalysis  # noqa: F401  (public here)
from .analysis import (
    SystemDynamicSetup,
    most_loaded_at_start,
    prepare_system_dynamic,
    run_system_dynamic,
    start_state,
)
from .fe import SystemFE, build_system_fe, lines_only
from .loop import SystemRun, SystemState, body_line_force, simulate_system, static_system
from .outputs import DOFS, REFERENCES, system_result

__all__ = [
    "DOFS",
    "REFERENCES",
    "ExternalForceSeries",
    "LineFailure",
    "SystemDynamicAnalysis",
    "SystemDynamicSetup",
    "SystemFE",
    "SystemRun",
    "SystemState",
    "body_line_force",
    "build_system_fe",
    "lines_only",
    "most_loaded_at_start",
    "prepare_system_dynamic",
    "run_system_dynamic",
    "simulate_system",
    "start_state",
    "static_system",
    "system_result",
]

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
  closed form per piece of the table, with the analytic tangent (:mod:`.catenary`). The table is
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
  restarts from its previous end forces (compiled, :mod:`.catenary`). Steps are clipped per
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
with the finite-element statics instead (:mod:`seacable.system.statics.fe`: the coupled
finite-element lines and bodies at rest, stiffness by central differences of equilibria).

References
----------
.. [1] M. Hall et al., MoorPy (NREL), ``moorpy/body.py`` (``getForces``, ``getStiffnessA``),
   ``moorpy/system.py`` (``solveEquilibrium``, ``getCoupledStiffnessA``), v1.3.0.
.. [2] J. Jonkman, "Definition of the Floating System for Phase IV of OC3",
   NREL/TP-500-47535, 2010.

The package's modules: :mod:`.solve` (the entry points and the rounds), :mod:`.problem` (the Newton
iteration), :mod:`.splits` (lines split at the surface and the seabed), :mod:`.result` (the result and its
stiffness); below them :mod:`.model` (the assembled arrays), :mod:`.evaluation` (forces and Jacobian),
:mod:`.catenary` and :mod:`.kernel` (compiled); :mod:`.fe` is the finite-element statics and
:mod:`.examples` the reference systems of the validation.
"""

from __future__ import annotations

from .result import SystemEquilibrium, system_stiffness
from .solve import check_statics, solve_equilibrium

__all__ = ["SystemEquilibrium", "check_statics", "solve_equilibrium", "system_stiffness"]

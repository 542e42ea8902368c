"""Forces and analytic Jacobian of a flattened mooring system (private to :mod:`seacable.system.statics`).

State: each free body's reference point X and rotation matrix R, each free node's position.
Degrees of freedom of an increment: per free body (dx, dy, dz, th_x, th_y, th_z) with th a small
rotation about the *global* axes (R -> Rot(th) R), then (dx, dy, dz) per free node. The Jacobian
is the exact derivative of the residual (net force and moment about the reference point, global
axes) with respect to these increments; the stiffness is its negative (MoorPy's analytic
convention, ``Body.getStiffnessA``).

Sub-line end forces in 3-D: the catenary runs from its lower end ("anchor", catenary end A) to
its upper end ("fairlead"), in the vertical plane through both, horizontal unit vector ``e``
from anchor to fairlead. The line pulls the fairlead by ``(-H_F e, -V_F)`` and the anchor by
``(H_A e, V_A)``. With the catenary's 2x2 ``K = d(H_F, V_F)/d(x_F, z_F)`` the fairlead block of
the 3x3 stiffness is ``[[K00 e e^T + (H_F/h)(I - e e^T), K01 e], [K10 e^T, K11]]``; the
transverse term ``H_F/h`` (h the horizontal span) is the rotation of the catenary plane about
the anchor, and tends to ``K00`` for a vertical line (H is odd in the horizontal span there).
The anchor's force follows from ``H_A = H_F`` (suspended) or ``H_A = H_F - mu (w L - V_F)``
(grounded, Coulomb friction), ``V_A = V_F - w L`` (suspended) or 0 (grounded), and moving both
ends together leaves every force unchanged (the seabed is flat), so the anchor's columns are the
negated fairlead columns.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from ...errors import NoSolutionError
from ...statics.catenary import CatenaryRegime
from . import kernel as _k
from .catenary import frame_and_catenaries
from .model import Assembly, rotation

_GROUNDED = np.zeros(max(CatenaryRegime) + 1, bool)        # regime code -> lies on the seabed
_GROUNDED[[CatenaryRegime.ON_SEABED, CatenaryRegime.TOUCHDOWN, CatenaryRegime.TOUCHDOWN_SLACK_ANCHOR,
           CatenaryRegime.SLACK_SEABED]] = True


@dataclass
class BodyData:
    """Per free body constants (arrays over free bodies)."""

    mass: np.ndarray          # (nb,)
    rcg: np.ndarray           # (nb, 3) body frame
    volume: np.ndarray
    rcb: np.ndarray
    awp: np.ndarray
    iwp: np.ndarray           # (nb, 2)
    z0: np.ndarray            # reference heave of the displaced volume
    khs: list                 # 6x6 or None
    q0: np.ndarray            # (nb, 6) position given (for a user hydrostatic matrix)
    f0: np.ndarray            # (nb, 6) weight + buoyancy at the given position (user matrix only)
    external: np.ndarray      # (nb, 6)
    external_scale: float     # largest component of the external loads [N or N m]


@dataclass
class State:
    X: np.ndarray             # (nb, 3)
    R: np.ndarray             # (nb, 3, 3)
    P: np.ndarray             # (nn, 3) every node (free nodes are the state; others derived)
    grounded: np.ndarray      # (nn,) bool: free node resting on the seabed (z held)
    surfaced: np.ndarray | None = None   # (nn,) bool: free node with buoyancy stopped at the surface z = 0


@dataclass
class Evaluation:
    residual: np.ndarray      # (ndof,) net force on each DOF [N, N m]
    jac: np.ndarray           # (ndof, ndof) d residual / d increment (all terms)
    jac_lines: np.ndarray     # lines and node loads only (no body weight/hydrostatics)
    cat: object               # CatenaryResult
    anchor_is_a: np.ndarray   # (ns,) bool: sub-line end A is the catenary's lower end
    fa: np.ndarray            # (ns, 3) force of each sub-line on its end-A node [N]
    fb: np.ndarray            # (ns, 3) force on its end-B node [N]
    e: np.ndarray             # (ns, 2) horizontal unit vectors anchor -> fairlead
    node_force: np.ndarray    # (nn, 3) total force on each node (lines + node loads) [N]
    scale: float              # force scale for the relative residual [N]
    hydro: np.ndarray         # (6 nb, 6 nb) restoring of the bodies' weight, buoyancy, waterplane
    reaction: np.ndarray | None = None   # (nb, 3) force of the pin on each body (zero unless pinned) [N]
    scaled: np.ndarray | None = None     # residual / scale (moments also / length scale), set by the solver


def body_data(asm: Assembly, system, external: dict | None) -> BodyData:
    bodies = [system.bodies[asm.body_names[i]] for i in asm.free_bodies]
    nb = len(bodies)
    ext = np.array([b.external_force for b in bodies], float).reshape(nb, 6)
    for name, load in (external or {}).items():
        k = asm.free_bodies.index(asm.body_names.index(name))
        ext[k] += np.asarray(load, float)
    f0 = np.zeros((nb, 6))
    rho, g = asm.rho, asm.g
    for k, b in enumerate(bodies):
        R0 = rotation(b.position[3:])
        W = np.array([0.0, 0.0, -b.mass * g])
        B = np.array([0.0, 0.0, rho * g * b.volume])
        rg, rb = R0 @ np.asarray(b.center_of_gravity), R0 @ np.asarray(b.center_of_buoyancy)
        f0[k, :3] = W + B
        f0[k, 3:] = np.cross(rg, W) + np.cross(rb, B)
    arr = lambda key: np.array([getattr(b, key) for b in bodies], float)
    return BodyData(mass=arr("mass"), rcg=arr("center_of_gravity").reshape(nb, 3), volume=arr("volume"),
                    rcb=arr("center_of_buoyancy").reshape(nb, 3), awp=arr("waterplane_area"),
                    iwp=arr("waterplane_moments").reshape(nb, 2),
                    z0=np.array([b.position[2] for b in bodies], float),
                    khs=[None if b.hydrostatic_stiffness is None else np.asarray(b.hydrostatic_stiffness, float)
                         for b in bodies],
                    q0=arr("position").reshape(nb, 6), f0=f0, external=ext,
                    external_scale=float(np.abs(ext).max(initial=0.0)))


def node_positions(asm: Assembly, X, R, P):
    """Global positions of every node; body nodes from their body's X and R."""
    out = np.empty_like(P)
    _k.node_positions(P, X, R, asm.node_kind, asm.node_body, asm.node_rel, out)
    return out


def evaluate(asm: Assembly, bd: BodyData, st: State, *, load_factor=1.0, warm=None, max_strain=1.0) -> Evaluation:
    """Residual (net loads on every DOF) and its Jacobian at state ``st``.

    ``load_factor`` scales the bodies' external loads (the load ramp); ``warm`` is the sub-lines'
    previous (H, V) for the catenaries' start; ``max_strain`` the largest strain a sub-line may take.
    """
    nb, nfree = len(asm.free_bodies), asm.free_nodes.size
    nn = asm.node_kind.size
    ns = asm.sub_a.size
    ndof = 6 * nb + 3 * nfree
    P = node_positions(asm, st.X, st.R, st.P)
    try:
        cat, anchor_is_a, e, tiny = frame_and_catenaries(P, asm.sub_a, asm.sub_b, asm.sub_L, asm.sub_EA, asm.sub_w,
                                                         asm.friction, asm.depth, warm, max_strain=max_strain,
                                                         tables=asm.tables)
    except NoSolutionError as err:
        k = getattr(err, "sub_line", None)
        if k is None:
            raise
        name = asm.line_names[int(asm.sub_line[k])]
        raise NoSolutionError(re.sub(r"the line\[\d+\]", f"lines.{name}", str(err), count=1)) from None
    node_force = asm.node_force
    # what sits at a node above the water weighs its dry weight (the buoyancy switches off at z = 0; a
    # step, no term in the Jacobian; a node stopped at the surface counts as immersed): in the kernel
    node_buoy = asm.node_buoy if asm.node_buoy is not None else np.zeros(nn)
    HF, VF, HA, VA = cat.H_fairlead, cat.V_fairlead, cat.H_anchor, cat.V_anchor
    fa, fb, nf = np.empty((ns, 3)), np.empty((ns, 3)), np.empty((nn, 3))
    res, jac_lines = np.empty(ndof), np.empty((ndof, ndof))
    force_max = getattr(asm, "_force_max", None)
    if force_max is None:
        force_max = float(np.abs(asm.node_force).max(initial=0.0))
    floor = max(1.0, force_max, bd.external_scale)
    if not any(k is not None for k in bd.khs):
        # everything in one compiled call
        jac, hydro = np.empty((ndof, ndof)), np.empty((6 * nb, 6 * nb))
        scale = _k.assemble_all(P, st.X, st.R, asm.sub_a, asm.sub_b, anchor_is_a, e, tiny, HF, VF, HA, VA,
                                cat.stiffness, cat.regime, _GROUNDED,
                                float(asm.friction), node_force, node_buoy, asm.node_kind, asm.node_body,
                                asm.node_dof, nb, ndof, bd.mass, bd.rcg, bd.volume, bd.rcb, bd.awp, bd.iwp, bd.z0,
                                asm.rho, asm.g, bd.external, float(load_factor), floor, fa, fb, nf, res, jac_lines, jac, hydro)
        return Evaluation(res, jac, jac_lines, cat, anchor_is_a, fa, fb, e, nf, scale, hydro)
    grounded = _GROUNDED[cat.regime]
    K = cat.stiffness
    _k.assemble(P, st.X, asm.sub_a, asm.sub_b, anchor_is_a, e, tiny, HF, VF, HA, VA, K, grounded, float(asm.friction), node_force, node_buoy, asm.node_kind,
                asm.node_body, asm.node_dof, nb, ndof, fa, fb, nf, res, jac_lines)
    own, own_jac = _own_terms(asm, bd, st.X, st.R)
    jac = jac_lines.copy()
    hydro = np.zeros((6 * nb, 6 * nb))
    res[:6 * nb] += (own + load_factor * bd.external).ravel()
    for k in range(nb):
        b = slice(6 * k, 6 * k + 6)
        jac[b, b] += own_jac[k]
        hydro[b, b] = -own_jac[k]
    scale = _k.force_scale(fa, fb, own, floor)
    return Evaluation(res, jac, jac_lines, cat, anchor_is_a, fa, fb, e, nf, scale, hydro)


def _own_terms(asm, bd: BodyData, X, R):
    """The free bodies' own loads (nb, 6) (weight, buoyancy, waterplane, or the user's hydrostatic matrix)
    and their derivatives (nb, 6, 6) at reference points X (nb, 3) and rotations R (nb, 3, 3)."""
    nb = X.shape[0]
    own = np.zeros((nb, 6))
    own_jac = np.zeros((nb, 6, 6))
    if nb:
        _k.body_terms(R, X, bd.mass, bd.rcg, bd.volume, bd.rcb, bd.awp, bd.iwp, bd.z0, asm.rho, asm.g,
                      own, own_jac)
        for k in range(nb):
            if bd.khs[k] is not None:
                from .model import euler, euler_rate_map
                ang = euler(R[k])
                dq = np.concatenate([X[k] - bd.q0[k, :3], ang - bd.q0[k, 3:]])
                own[k] = bd.f0[k] - bd.khs[k] @ dq
                M = np.eye(6)
                M[3:, 3:] = np.linalg.inv(euler_rate_map(ang))
                own_jac[k] = -bd.khs[k] @ M
    return own, own_jac


def body_own(asm, system, X, R):
    """:func:`_own_terms` of ``system``'s free bodies (``asm`` needs free_bodies, body_names, rho, g)."""
    return _own_terms(asm, body_data(asm, system, None), np.asarray(X, float), np.asarray(R, float))

"""Line ends held on a free body (a cable's hang-off, a J-tube exit): the clamp's direction turns with the body,
and its moment acts back on the body (compiled helpers of :func:`seacable.system.dynamics.kernel.iterate`).

A held end's bending (:func:`seacable.mooring.kernel.end_bending_loads`) is a couple on the line's end element:
the force ``f`` on the neighbour node ``x_w`` and ``-f`` on the end node ``x_e``, of moment ``d x f`` about the
end (``d = x_w - x_e``). The end node is tied to the body, which takes ``-f`` through the tie; the body takes the
reaction moment too::

    m = -(d x f)

so that the forces and moments on the line and body together sum to zero. The end's direction is
``e = R e_b``, ``e_b`` in the body's axes (``R`` the body's rotation), so ``f`` depends on the body's rotation
``phi`` (a rotation vector, global axes) as well as on the two nodes. Since ``f`` turns with a rigid rotation
of ``d`` and ``e`` together (``f(Q d, Q e) = Q f(d, e)``), its slope on ``e`` follows from its slope on the
nodes alone: ``(df/de) skew(e) = skew(f) - J skew(d)``, ``J = df/dx_w``, and

    df/dphi = J skew(d) - skew(f),      dm/dx_w = skew(f) - skew(d) J = -dm/dx_e,
    dm/dphi = skew(d) (J skew(d) - skew(f))

which the coupled Newton iteration takes (:func:`seacable.system.dynamics.kernel.iterate`): its convergence
stays quadratic.
"""

from __future__ import annotations

import numpy as np

from ..._jit import njit
from ...mooring._elements import end_bending_loads
from ...mooring._indices import H_D
from .frames import F_SIZE, body_rotation

#: Columns of :attr:`seacable.system.dynamics.fe.SystemFE.clamps`: the row of the hinge table, the free body, the
#: direction into the line in the body's axes (3)
C_ROW, C_BODY, C_DIR = 0, 1, 2


@njit(cache=True)
def turn_clamps(q, frame, clamps, hinge_ei):
    """Each held end on a free body takes the direction ``R e_b`` of its body's pose ``q[b]`` (chart ``frame[b]``),
    in place in the hinge table."""
    R = np.empty((3, 3))
    for c in range(clamps.shape[0]):
        h = int(clamps[c, C_ROW])
        b = int(clamps[c, C_BODY])
        body_rotation(q[b], frame[b], R)
        for r in range(3):
            hinge_ei[h, H_D + r] = (R[r, 0] * clamps[c, C_DIR] + R[r, 1] * clamps[c, C_DIR + 1]
                                    + R[r, 2] * clamps[c, C_DIR + 2])


@njit(cache=True)
def end_nodes(hinges, h):
    """The end node and its neighbour of the end hinge ``h`` (a row ``(ie, ie, iw)`` or ``(iw, ie, ie)``)."""
    if hinges[h, 0] == hinges[h, 1]:
        return hinges[h, 1], hinges[h, 2]
    return hinges[h, 1], hinges[h, 0]


@njit(cache=True)
def clamp_state(X, hinges, hinge_ei, h, f, J, d):
    """The held end ``h``'s force ``f`` on the neighbour node [N], its slope ``J = df/dx_w`` [N/m] and the end
    element's chord ``d = x_w - x_e`` [m], in place (by :func:`seacable.mooring.kernel.end_bending_loads` on the
    two nodes alone)."""
    ie, iw = end_nodes(hinges, h)
    X2 = np.empty((2, 3))
    for r in range(3):
        X2[0, r] = X[ie, r]
        X2[1, r] = X[iw, r]
        d[r] = X[iw, r] - X[ie, r]
    F2 = np.zeros((2, 3))
    band = np.zeros((3, 5))
    fidx = np.array([-1, 0])
    end_bending_loads(X2, 0, 1, hinge_ei[h], F2, band, 2, fidx)
    for r in range(3):
        f[r] = F2[1, r]
        for c in range(3):
            J[r, c] = -band[r, 2 + c - r]


@njit(cache=True)
def clamp_moment(f, d, m):
    """The held end's moment on its body, ``m = -(d x f)`` [N m], in place."""
    m[0] = -(d[1] * f[2] - d[2] * f[1])
    m[1] = -(d[2] * f[0] - d[0] * f[2])
    m[2] = -(d[0] * f[1] - d[1] * f[0])


@njit(cache=True)
def clamp_slopes(f, J, d, Bw, Bm, Bphi):
    """The slopes of a held end (module docstring), in place: ``Bw = -df/dphi = skew(f) - J skew(d)`` (the neighbour
    node's residual on the body's rotation), ``Bm = -dm/dx_w = skew(d) J - skew(f)`` (the body's moment residual on
    the neighbour node; ``-Bm`` on the end node) and ``Bphi = -dm/dphi = skew(d) (J skew(d) - skew(f))``."""
    Sd = np.zeros((3, 3))
    Sf = np.zeros((3, 3))
    Sd[0, 1], Sd[0, 2], Sd[1, 0], Sd[1, 2], Sd[2, 0], Sd[2, 1] = -d[2], d[1], d[2], -d[0], -d[1], d[0]
    Sf[0, 1], Sf[0, 2], Sf[1, 0], Sf[1, 2], Sf[2, 0], Sf[2, 1] = -f[2], f[1], f[2], -f[0], -f[1], f[0]
    JSd = np.zeros((3, 3))
    for r in range(3):
        for c in range(3):
            JSd[r, c] = J[r, 0] * Sd[0, c] + J[r, 1] * Sd[1, c] + J[r, 2] * Sd[2, c]
    for r in range(3):
        for c in range(3):
            Bw[r, c] = Sf[r, c] - JSd[r, c]
            Bm[r, c] = Sd[r, 0] * J[0, c] + Sd[r, 1] * J[1, c] + Sd[r, 2] * J[2, c] - Sf[r, c]
            Bphi[r, c] = (Sd[r, 0] * (JSd[0, c] - Sf[0, c]) + Sd[r, 1] * (JSd[1, c] - Sf[1, c])
                          + Sd[r, 2] * (JSd[2, c] - Sf[2, c]))


def clamp_moments(fe, X, q=None, frame=None) -> np.ndarray:
    """The held ends' moments on the free bodies (nb, 3) [N m] at node positions ``X``, the bodies at ``q`` (their
    directions turned there first when given; else the hinge table's as it stands)."""
    nb = len(fe.free_bodies)
    out = np.zeros((nb, 3))
    clamps = fe.clamps
    if clamps is None or not clamps.shape[0]:
        return out
    m = fe.model
    if q is not None:
        fr = np.zeros((nb, F_SIZE)) if frame is None else frame
        turn_clamps(np.asarray(q, float).reshape(nb, 6), fr, clamps, m.hinge_ei)
    f, J, d, mo = np.zeros(3), np.zeros((3, 3)), np.zeros(3), np.zeros(3)
    for c in range(clamps.shape[0]):
        clamp_state(np.asarray(X, float), m.hinges, m.hinge_ei, int(clamps[c, C_ROW]), f, J, d)
        clamp_moment(f, d, mo)
        out[int(clamps[c, C_BODY])] += mo
    return out

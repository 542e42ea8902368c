"""The 3-D towed-cable equations of paper 000 and their box-scheme residual and Jacobian.

Ten unknowns per node, ``H = (T, S_n, S_b, v_t, v_n, v_b, phi, theta, Omega_n, Omega_b)``: the
effective tension, the two shear forces, the cable velocity in the local frame, the two Euler
angles and the two curvatures. Derived here (and checked term by term against paper 000's eq.
(2)-(6) with the corrections listed in SPEC.md), with X, Y horizontal, Z up, ``s`` the
unstretched arc length from the lower end (node 0) to the vessel, and the local frame obtained by
turning ``phi`` about Z and then ``theta`` about the new normal::

    t = ( cos th cos ph, cos th sin ph, -sin th)
    n = (-sin ph,        cos ph,         0     )          (t x n = b)
    b = ( sin th cos ph, sin th sin ph,  cos th)

so that ``theta`` is the angle of the tangent below the horizontal (a towed cable rising to the
vessel has ``theta < 0``). The frame turns in space at ``Omega = (-sin th phi', th', cos th phi')``
and in time at ``omega = (-sin th phidot, thdot, cos th phidot)``. With ``e = T/EA``, the mass ``m``
and added masses ``m_at``, ``m_an`` per unstretched length, the weight in water ``w0`` along -Z, the
drag ``R`` (eq. (6), with the velocity relative to the current) and dots for time derivatives, the
equations are ``A(H) H' = B(H) Hdot + C(H)`` row by row::

    1  T'          = (m+m_at) a_t + S_n Om_b - S_b Om_n - w0 sin th - R_t
    2  S_n'        = (m+m_an) a_n - Om_b T - tan th Om_b S_b - R_n
    3  S_b'        = (m+m_an) a_b + tan th Om_b S_n + Om_n T + w0 cos th - R_b
    4  v_t'        = Tdot/EA - Om_n v_b + Om_b v_n
    5  v_n'        = (1+e) cos th phidot - Om_b v_t - tan th Om_b v_b
    6  v_b'        = -(1+e) thdot + tan th Om_b v_n + Om_n v_t
    7  cos th phi' = Om_b
    8  th'         = Om_n
    9  EI Om_n'    = -EI tan th Om_b^2 + (1+e)^3 S_b
    10 EI Om_b'    =  EI tan th Om_n Om_b - (1+e)^3 S_n

with the accelerations of the frame ``a_t = v_t-dot + v_b thdot - v_n cos th phidot``,
``a_n = v_n-dot + phidot (v_t cos th + v_b sin th)``, ``a_b = v_b-dot - v_n sin th phidot -
v_t thdot``. Rows 1-3 are Newton's law for an element (``dF/ds + f = m a`` with
``F = T t + S_n n + S_b b``), rows 4-6 the compatibility of position and velocity
(``d/dt[(1+e) t] = dv/ds``), rows 7-8 the definition of the curvatures and rows 9-10 the moment
balance with ``M = EI (Om_n n + Om_b b)`` (no torsion). Departures from the printed paper:
the tension term of eq. (2) is ``T'``; the Euler-angle matrix and the gravity terms are those of
the Z-up frame above; K(1,8) = m v_b and K(3,8) = -m v_t; row 4 has ``Tdot/EA``; the added mass
multiplies the whole normal acceleration (the printed eq. (2) applies it to ``v_n-dot`` and
``v_b-dot`` only) and the tangential drag uses the relative velocity. The fluid acceleration is
zero: the current field is steady (no waves), so the Froude-Krylov term vanishes.

The box scheme (paper 000 eq. (13), with the time difference taken at each node) centres every
equation on the cell ``(j+1/2, i+1/2)``::

    1/2 [Abar^{i+1} D_s H^{i+1} + Abar^i D_s H^i] - 1/2 sum_{k=j,j+1} B(H_k^{i+1/2}) D_t H_k
        - 1/4 sum_{corners} C = 0

and the steady problem (the initial state, time derivatives zero) is the same residual with
``H^{i+1} = H^i``: ``Abar D_s H - 1/2 (C_j + C_{j+1}) = 0``.

Everything here is compiled with numba; arrays are float64 and the parameters are packed in a
vector (see :data:`PARAMETERS`).
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import njit

__all__ = ["NV", "PARAMETERS", "ORDER", "c_terms", "g_terms", "box_assemble", "frame",
           "current_velocity", "integrate_positions"]

NV = 10
"""Unknowns per node."""

I_T, I_SN, I_SB, I_VT, I_VN, I_VB, I_PH, I_TH, I_ON, I_OB = range(NV)

PARAMETERS = ("mass", "added_mass_tangential", "added_mass_normal", "weight", "inverse_axial_stiffness",
              "bending_stiffness", "drag_tangential", "drag_normal", "stretch_drag", "shear_power",
              "ds")
"""Order of the entries of the parameter vector ``par``: m [kg/m], m_at [kg/m], m_an [kg/m],
w0 [N/m], 1/EA [1/N], EI [N m^2], k_t = 1/2 rho C_dt (pi) d [kg/m^2], k_n = 1/2 rho C_dn d [kg/m^2],
1 if the drag carries the stretch factor sqrt(1+e) else 0, the power of (1+e) in the moment
balance, and the node spacing ds [m]."""

P_M, P_MAT, P_MAN, P_W, P_IEA, P_EI, P_KT, P_KN, P_STRETCH, P_POW, P_DS = range(len(PARAMETERS))

ORDER = np.array([3, 4, 5, 6, 7, 0, 1, 2, 8, 9])
"""Box equations in the order they enter the block rows: the first five (compatibility and
curvature rows, which carry ``-1/ds`` on the velocities and angles of the left node) close the
block of the left node, the last five (force and moment rows, ``+1/ds`` on the forces and
curvatures of the right node) open the block of the right node, so that every diagonal block is
dominated by ``1/ds`` terms."""

_TINY = 1e-12


@njit(cache=True)
def frame(phi, theta):
    """Unit vectors ``t, n, b`` (rows of a 3x3 array) of the local frame."""
    cp, sp, ct, st = math.cos(phi), math.sin(phi), math.cos(theta), math.sin(theta)
    r = np.empty((3, 3))
    r[0, 0], r[0, 1], r[0, 2] = ct * cp, ct * sp, -st
    r[1, 0], r[1, 1], r[1, 2] = -sp, cp, 0.0
    r[2, 0], r[2, 1], r[2, 2] = st * cp, st * sp, ct
    return r


@njit(cache=True)
def current_velocity(z, depths, speeds, cos_heading, sin_heading, out):
    """Current velocity at elevation ``z`` (profile linear in depth, constant beyond) into ``out``."""
    speed = np.interp(-z, depths, speeds)
    out[0] = speed * cos_heading
    out[1] = speed * sin_heading
    out[2] = 0.0


@njit(cache=True)
def c_terms(h, u, par, c, dc, want_jacobian):
    """Terms ``C(H)`` of one node (no time derivatives) and, if asked, ``dC/dH``.

    ``h`` is the node's state (10), ``u`` the current velocity at the node (3, global).
    """
    tension, sn, sb, vt, vn, vb, ph, th, om_n, om_b = (h[0], h[1], h[2], h[3], h[4], h[5], h[6],
                                                      h[7], h[8], h[9])
    cth, sth = math.cos(th), math.sin(th)
    cph, sph = math.cos(ph), math.sin(ph)
    tth = sth / cth
    sec2 = 1.0 / (cth * cth)
    w0, iea, ei, kt, kn = par[P_W], par[P_IEA], par[P_EI], par[P_KT], par[P_KN]
    horiz = cph * u[0] + sph * u[1]
    ut = cth * horiz - sth * u[2]
    un = -sph * u[0] + cph * u[1]
    ub = sth * horiz + cth * u[2]
    rt, rn, rb = vt - ut, vn - un, vb - ub
    one_e = 1.0 + tension * iea
    if one_e < 1e-3:  # a compressed section beyond any physical strain: keep the algebra finite
        one_e = 1e-3
    if par[P_STRETCH] > 0.0:
        g = math.sqrt(one_e)
        g_t = 0.5 * iea / g
    else:
        g, g_t = 1.0, 0.0
    q = math.sqrt(rn * rn + rb * rb)
    drag_t = -kt * g * rt * abs(rt)
    drag_n = -kn * g * rn * q
    drag_b = -kn * g * rb * q
    power = par[P_POW]
    pe = one_e ** power

    c[I_T] = sn * om_b - sb * om_n - w0 * sth - drag_t
    c[I_SN] = -om_b * tension - tth * om_b * sb - drag_n
    c[I_SB] = tth * om_b * sn + om_n * tension + w0 * cth - drag_b
    c[I_VT] = -om_n * vb + om_b * vn
    c[I_VN] = -om_b * vt - tth * om_b * vb
    c[I_VB] = tth * om_b * vn + om_n * vt
    c[I_PH] = om_b
    c[I_TH] = om_n
    c[I_ON] = -ei * tth * om_b * om_b + pe * sb
    c[I_OB] = ei * tth * om_n * om_b - pe * sn
    if not want_jacobian:
        return

    dc[:, :] = 0.0
    # drag derivatives with respect to the relative velocity, the tension and the angles
    d_t_drt = -2.0 * kt * g * abs(rt)
    if q > _TINY:
        a_nn, a_nb, a_bb = q + rn * rn / q, rn * rb / q, q + rb * rb / q
    else:
        a_nn, a_nb, a_bb = 0.0, 0.0, 0.0
    d_n_drn, d_n_drb = -kn * g * a_nn, -kn * g * a_nb
    d_b_drn, d_b_drb = -kn * g * a_nb, -kn * g * a_bb
    drn_dph = cth * ut + sth * ub          # d(r_n)/d(phi)
    drt_dph, drt_dth = -cth * un, ub
    drb_dph, drb_dth = -sth * un, -ut
    dt_ph = d_t_drt * drt_dph
    dt_th = d_t_drt * drt_dth
    dn_ph = d_n_drn * drn_dph + d_n_drb * drb_dph
    dn_th = d_n_drb * drb_dth
    db_ph = d_b_drn * drn_dph + d_b_drb * drb_dph
    db_th = d_b_drb * drb_dth

    # row 1: T'
    dc[0, I_SN] = om_b
    dc[0, I_SB] = -om_n
    dc[0, I_OB] = sn
    dc[0, I_ON] = -sb
    dc[0, I_TH] = -w0 * cth - dt_th
    dc[0, I_PH] = -dt_ph
    dc[0, I_VT] = -d_t_drt
    dc[0, I_T] = kt * g_t * rt * abs(rt)
    # row 2: S_n'
    dc[1, I_T] = -om_b + kn * g_t * rn * q
    dc[1, I_SB] = -tth * om_b
    dc[1, I_OB] = -tension - tth * sb
    dc[1, I_TH] = -sec2 * om_b * sb - dn_th
    dc[1, I_PH] = -dn_ph
    dc[1, I_VN] = -d_n_drn
    dc[1, I_VB] = -d_n_drb
    # row 3: S_b'
    dc[2, I_SN] = tth * om_b
    dc[2, I_OB] = tth * sn
    dc[2, I_ON] = tension
    dc[2, I_T] = om_n + kn * g_t * rb * q
    dc[2, I_TH] = sec2 * om_b * sn - w0 * sth - db_th
    dc[2, I_PH] = -db_ph
    dc[2, I_VN] = -d_b_drn
    dc[2, I_VB] = -d_b_drb
    # row 4: v_t'
    dc[3, I_ON] = -vb
    dc[3, I_VB] = -om_n
    dc[3, I_OB] = vn
    dc[3, I_VN] = om_b
    # row 5: v_n'
    dc[4, I_OB] = -vt - tth * vb
    dc[4, I_VT] = -om_b
    dc[4, I_VB] = -tth * om_b
    dc[4, I_TH] = -sec2 * om_b * vb
    # row 6: v_b'
    dc[5, I_OB] = tth * vn
    dc[5, I_VN] = tth * om_b
    dc[5, I_TH] = sec2 * om_b * vn
    dc[5, I_ON] = vt
    dc[5, I_VT] = om_n
    # rows 7, 8: curvatures
    dc[6, I_OB] = 1.0
    dc[7, I_ON] = 1.0
    # rows 9, 10: moments
    dpe = power * one_e ** (power - 1.0) * iea
    dc[8, I_TH] = -ei * sec2 * om_b * om_b
    dc[8, I_OB] = -2.0 * ei * tth * om_b
    dc[8, I_SB] = pe
    dc[8, I_T] = dpe * sb
    dc[9, I_TH] = ei * sec2 * om_n * om_b
    dc[9, I_ON] = ei * tth * om_b
    dc[9, I_OB] = ei * tth * om_n
    dc[9, I_SN] = -pe
    dc[9, I_T] = -dpe * sn


@njit(cache=True)
def g_terms(h, hdot, par, g, dg, bmat):
    """Time terms ``G = B(H) Hdot`` of one node, ``dG/dH`` at fixed ``Hdot`` and ``B = dG/dHdot``."""
    tension, vt, vn, vb, th = h[0], h[3], h[4], h[5], h[7]
    td, vtd, vnd, vbd, phd, thd = hdot[0], hdot[3], hdot[4], hdot[5], hdot[6], hdot[7]
    cth, sth = math.cos(th), math.sin(th)
    iea = par[P_IEA]
    mt = par[P_M] + par[P_MAT]
    mn = par[P_M] + par[P_MAN]
    one_e = 1.0 + tension * iea
    g[:] = 0.0
    g[0] = mt * (vtd + vb * thd - vn * cth * phd)
    g[1] = mn * (vnd + phd * (vt * cth + vb * sth))
    g[2] = mn * (vbd - vn * sth * phd - vt * thd)
    g[3] = td * iea
    g[4] = one_e * cth * phd
    g[5] = -one_e * thd

    dg[:, :] = 0.0
    dg[0, I_VB] = mt * thd
    dg[0, I_VN] = -mt * cth * phd
    dg[0, I_TH] = mt * vn * sth * phd
    dg[1, I_VT] = mn * phd * cth
    dg[1, I_VB] = mn * phd * sth
    dg[1, I_TH] = mn * phd * (-vt * sth + vb * cth)
    dg[2, I_VN] = -mn * sth * phd
    dg[2, I_VT] = -mn * thd
    dg[2, I_TH] = -mn * vn * cth * phd
    dg[4, I_T] = iea * cth * phd
    dg[4, I_TH] = -one_e * sth * phd
    dg[5, I_T] = -iea * thd

    bmat[:, :] = 0.0
    bmat[0, I_VT] = mt
    bmat[0, I_TH] = mt * vb
    bmat[0, I_PH] = -mt * vn * cth
    bmat[1, I_VN] = mn
    bmat[1, I_PH] = mn * (vt * cth + vb * sth)
    bmat[2, I_VB] = mn
    bmat[2, I_PH] = -mn * vn * sth
    bmat[2, I_TH] = -mn * vt
    bmat[3, I_T] = iea
    bmat[4, I_PH] = one_e * cth
    bmat[5, I_TH] = -one_e


@njit(cache=True)
def box_assemble(hn, ho, cn, dcn, co, gm, dgm, bm, dt, par, steady, res, jl, jr):
    """Residual ``res (n-1, 10)`` of every box and its Jacobians with respect to the new state of
    the left (``jl``) and right (``jr``) node, ``(n-1, 10, 10)``, rows in equation order.

    ``cn, dcn`` are the C terms and their Jacobian at the new level, ``co`` at the old level,
    ``gm, dgm, bm`` the time terms at the nodes' time mid-points (see :func:`g_terms`). With
    ``steady`` true the residual is the steady one (``ho``, ``co``, ``g`` unused).
    """
    n = hn.shape[0]
    ds = par[P_DS]
    ei = par[P_EI]
    for j in range(n - 1):
        k = j + 1
        for r in range(NV):
            jl[j, r, :] = 0.0
            jr[j, r, :] = 0.0
        if steady:
            wa, wc = 1.0, 0.5
        else:
            wa, wc = 0.5, 0.25
        for r in range(NV):
            if r == I_PH:
                an = 0.5 * (math.cos(hn[j, I_TH]) + math.cos(hn[k, I_TH]))
            elif r == I_ON or r == I_OB:
                an = ei
            else:
                an = 1.0
            val = wa * an * (hn[k, r] - hn[j, r]) / ds - wc * (cn[j, r] + cn[k, r])
            jl[j, r, r] -= wa * an / ds
            jr[j, r, r] += wa * an / ds
            if not steady:
                if r == I_PH:
                    ao = 0.5 * (math.cos(ho[j, I_TH]) + math.cos(ho[k, I_TH]))
                else:
                    ao = an
                val += wa * ao * (ho[k, r] - ho[j, r]) / ds - wc * (co[j, r] + co[k, r])
                val -= 0.5 * (gm[j, r] + gm[k, r])
            res[j, r] = val
        # d(cos th)/d(th) in the phi' row
        dphi = (hn[k, I_PH] - hn[j, I_PH]) / ds
        jl[j, I_PH, I_TH] -= wa * 0.5 * math.sin(hn[j, I_TH]) * dphi
        jr[j, I_PH, I_TH] -= wa * 0.5 * math.sin(hn[k, I_TH]) * dphi
        for r in range(NV):
            for col in range(NV):
                jl[j, r, col] -= wc * dcn[j, r, col]
                jr[j, r, col] -= wc * dcn[k, r, col]
                if not steady:
                    jl[j, r, col] -= 0.5 * (0.5 * dgm[j, r, col] + bm[j, r, col] / dt)
                    jr[j, r, col] -= 0.5 * (0.5 * dgm[k, r, col] + bm[k, r, col] / dt)


@njit(cache=True)
def integrate_positions(h, top, par, out):
    """Node positions ``out (n, 3)`` from the angles and strains, integrating ``r' = (1+e) t`` by
    the trapezoidal rule down from the tow point ``top (3)`` (node n-1)."""
    n = h.shape[0]
    ds, iea = par[P_DS], par[P_IEA]
    for k in range(3):
        out[n - 1, k] = top[k]
    tp = frame(h[n - 1, I_PH], h[n - 1, I_TH])[0] * (1.0 + h[n - 1, I_T] * iea)
    for j in range(n - 2, -1, -1):
        tj = frame(h[j, I_PH], h[j, I_TH])[0] * (1.0 + h[j, I_T] * iea)
        for d in range(3):
            out[j, d] = out[j + 1, d] - 0.5 * ds * (tj[d] + tp[d])
        tp = tj

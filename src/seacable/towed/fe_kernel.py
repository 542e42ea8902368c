"""Compiled time loop of the finite-element towed system, with the cable's length changing at the tow point.

The system is the mooring model's (:mod:`seacable.mooring.kernel`): one line of nodes 0 (the lower end) to
``n - 1`` (the tow point, moved by the vessel: motion channel 0), element ``e`` joining nodes e and e + 1.
Arrays are allocated for the most nodes the run can have and used up to the ``n`` nodes in the water.

Pay-out and haul-in change the unstretched length of the top element (node n - 2 to the tow point) to the
deployed length at each step's end less the arc length of node n - 2, ``ell = L(t) - s[n - 2]``:

- when ``ell`` exceeds 3/2 of the paid-out line type's element length ``ds``, a node is born ``ds`` above node
  n - 2, on the chord to the tow point at the fraction ``ds / ell``, with the position, velocity and
  acceleration that the element's linear shape functions give there (the material of the top element moves
  as it did: its momentum under the consistent mass is kept, and nothing jumps);
- when ``ell`` falls under ``ds / 2`` (haul-in), node n - 2 goes onto the winch: the element below it takes
  its length and runs to the tow point. A node of the top segment's start (a joint, an attachment) never goes.

The node masses follow the elements' lengths (the kernel lumps half of each element's mass on each end), and
the weights and seabed contact areas of the nodes next to the changed elements are refreshed at every step.
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import copy_1d, copy_2d, njit
from ..mooring import kernel as K

__all__ = ["refresh_node", "towed_outputs", "towed_steps"]

#: A node is born when the top element grows past SPLIT element lengths, and retired below MERGE.
SPLIT = 1.5
MERGE = 0.5

# Slots of the integer state ``ia``: nodes in the water, free nodes, and node events (births, retirements).
I_N, I_NFREE, I_BORN, I_GONE = 0, 1, 2, 3


@njit(cache=True)
def refresh_node(i, n, L0, wpl, dia, pw, pc, weight, bedc):
    """Weight in water [N] and seabed contact area [m^2] of node ``i`` of ``n`` from its elements' lengths, its
    attachments' weight ``pw`` and contact area ``pc`` (a body's)."""
    w = pw[i]
    c = pc[i]
    if i > 0:
        w += 0.5 * wpl[i - 1] * L0[i - 1]
        c += 0.5 * dia[i - 1] * L0[i - 1]
    if i < n - 1:
        w += 0.5 * wpl[i] * L0[i]
        c += 0.5 * dia[i] * L0[i]
    weight[i] = w
    bedc[i] = c


@njit(cache=True)
def _copy_element(src, dst, arrays, ts_lo, ts_hi, visco):
    """Element ``dst`` of the same line type as ``src``."""
    for a in arrays:
        a[dst] = a[src]
    ts_lo[dst] = ts_lo[src]
    ts_hi[dst] = ts_hi[src]
    if visco.shape[0] > 0:
        for c in range(visco.shape[1]):  # a loop: numba's row assignment compiles its error message (4 CPU-s)
            visco[dst, c] = visco[src, c]


@njit(cache=True)
def _birth(ia, X, V, A, G, L0, ds, rate, elems, ts_lo, ts_hi, visco, fidx, channel, hinges, hinge_ei, s_node):
    """A node born ``ds`` above node n - 2 (module docstring); the tow point moves to the next slot.

    The top element's unstretched length is still the step start's: the new node goes where its pieces'
    tensions balance its weight along the chord (at the fraction ``ds / ell`` of it without weight: both pieces
    keep the element's strain), lifted off the chord by the cable's sag (a quadratic leaving node n - 2 along its
    tangent), with the velocity and acceleration of the material there, linear between node n - 2's and the
    material's at the tow point (the tow point's plus the pay-out ``rate`` [m/s] down the chord)."""
    n = ia[I_N]
    j = n - 1  # the new node's slot, the tow point's until now
    below = n - 2
    ell = L0[below]
    f = min(ds / ell, 1.0) if ell > 0.0 else 1.0
    d0, d1, d2 = X[below, 0] - X[j, 0], X[below, 1] - X[j, 1], X[below, 2] - X[j, 2]
    chord = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
    down = (d0 / chord, d1 / chord, d2 / chord) if chord > 0.0 else (0.0, 0.0, -1.0)
    if 0.0 < f < 1.0 and chord > 0.0:
        # where on the chord the new node's weight W (half of each piece) is balanced along it: the upper piece's
        # tension exceeds the lower's by W (-down . e_z), EA (c - a) / L_u - EA a / L_l = that, for the distance a
        # from node n - 2 (the chord's fraction ds / ell when weightless); else the weight the node takes from
        # the tow point unbalances it and starts an axial wave
        ea, lu = elems[0][below], ell - ds
        dT = elems[9][below] * 0.5 * ell * (-down[2])
        a = (chord / lu - dT / ea) / (1.0 / lu + 1.0 / ds)
        f = min(max(a / chord, 0.0), 1.0)
    # the cable's tangent at node n - 2, the mean of the element below's direction and the chord's (up the line)
    tb = np.zeros(3)
    if below > 0 and chord > 0.0:
        e0, e1, e2 = X[below, 0] - X[below - 1, 0], X[below, 1] - X[below - 1, 1], X[below, 2] - X[below - 1, 2]
        le = math.sqrt(e0 * e0 + e1 * e1 + e2 * e2)
        if le > 0.0:
            tb[0], tb[1], tb[2] = e0 / le - down[0], e1 / le - down[1], e2 / le - down[2]
            lt = math.sqrt(tb[0] ** 2 + tb[1] ** 2 + tb[2] ** 2)
            tb *= 0.5 * chord / lt if lt > 0.0 else 0.0
    for r in range(3):
        X[n, r], V[n, r], A[n, r], G[n, r] = X[j, r], V[j, r], A[j, r], 0.0
        # on the quadratic from node n - 2 (leaving it along its tangent) to the tow point: the cable's sag
        # between them, not its chord (a node put on the chord starts a transverse wave)
        chord_r = X[below, r] + f * (X[n, r] - X[below, r])
        X[j, r] = chord_r + 2.0 * f * (1.0 - f) * (X[below, r] + tb[r] - 0.5 * (X[below, r] + X[n, r]))
        V[j, r] = V[below, r] + f * (V[n, r] + rate * down[r] - V[below, r])
        A[j, r] = A[below, r] + f * (A[n, r] - A[below, r])
        G[j, r] = G[below, r]
    _copy_element(below, j, elems, ts_lo, ts_hi, visco)
    L0[below] = ds
    L0[j] = ell - ds
    s_node[j] = s_node[below] + ds
    fidx[j] = ia[I_NFREE]
    fidx[n] = -1
    channel[j] = -1
    channel[n] = 0
    nh = n - 2  # hinges before the birth: the inner nodes 1 .. n - 2
    if hinges.shape[0] > 0 and nh >= 1:
        hinges[nh, 0], hinges[nh, 1], hinges[nh, 2] = below, j, n
        for q in range(hinge_ei.shape[1]):
            hinge_ei[nh, q] = hinge_ei[nh - 1, q]
    ia[I_N] = n + 1
    ia[I_NFREE] += 1
    ia[I_BORN] += 1


@njit(cache=True)
def _retire(ia, X, V, A, G, L0, fidx, channel, s_node):
    """Node n - 2 goes onto the winch: the element below it runs to the tow point (module docstring)."""
    n = ia[I_N]
    gone = n - 2
    for r in range(3):
        X[gone, r], V[gone, r], A[gone, r], G[gone, r] = X[n - 1, r], V[n - 1, r], A[n - 1, r], 0.0
    L0[gone - 1] += L0[gone]
    s_node[gone] = s_node[n - 1]
    fidx[gone] = -1
    fidx[n - 1] = -1
    channel[gone] = 0
    channel[n - 1] = -1
    # bending: the hinge of node n - 2 goes with it; the next one down already ends at slot n - 2, the tow point's
    ia[I_N] = n - 1
    ia[I_NFREE] -= 1
    ia[I_GONE] += 1


@njit(cache=True)
def _set_length(ia, length, rate, ds, s_lock, X, V, A, G, L0, elems, ts_lo, ts_hi, visco, fidx, channel, hinges,
                hinge_ei, s_node, wpl, dia, pw, pc, weight, bedc):
    """The top element to the deployed ``length`` [m] at the step's end, with the node births and retirements it
    calls for (made on the state at the step's start), ``rate`` [m/s] the pay-out over the step."""
    while length - s_node[ia[I_N] - 2] > SPLIT * ds and ia[I_N] < X.shape[0]:
        _birth(ia, X, V, A, G, L0, ds, rate, elems, ts_lo, ts_hi, visco, fidx, channel, hinges, hinge_ei, s_node)
    while length - s_node[ia[I_N] - 2] < MERGE * ds and s_node[ia[I_N] - 2] > s_lock and ia[I_N] > 2:
        _retire(ia, X, V, A, G, L0, fidx, channel, s_node)
    n = ia[I_N]
    L0[n - 2] = length - s_node[n - 2]
    s_node[n - 1] = length
    for i in range(max(n - 3, 0), n):
        refresh_node(i, n, L0, wpl, dia, pw, pc, weight, bedc)


@njit(cache=True)
def towed_steps(ia, X, V, A, G, t0, dt, px, pv, pa, lengths, ds, s_lock, s_node, wpl, pw, pc, args, fidx, channel, bw,
                env, cur_depth, cur_speed, sea, beta, gamma, alpha_m, alpha_f, tol, max_iter, F, M, tension, stats,
                band, R, D, Xn, Vn, An, envw):
    """Advance ``px.shape[0]`` steps of ``dt`` from ``t0`` (:func:`seacable.mooring.kernel.newmark_work`, one
    step at a time), the deployed length ``lengths[k]`` [m] at the end of step k (NaN: no winch). Returns the
    number of steps that converged; a failed step leaves the state at its start (with the nodes born for it)."""
    (elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda, bedc, buoy, pbuoy,
     ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco) = args
    elems = (EA, cdamp, mpl, dia, cdn, cdt, can, cat, buoy, wpl)
    for k in range(px.shape[0]):
        if not math.isnan(lengths[k]):
            rate = (lengths[k] - s_node[ia[I_N] - 1]) / dt
            _set_length(ia, lengths[k], rate, ds, s_lock, X, V, A, G, L0, elems, ts_lo, ts_hi, visco, fidx, channel,
                        hinges, hinge_ei, s_node, wpl, dia, pw, pc, weight, bedc)
        n = ia[I_N]
        ne = n - 1
        nf = ia[I_NFREE]
        nh = max(n - 2, 0) if hinges.shape[0] > 0 else 0
        nv = ne if visco.shape[0] > 0 else 0
        got = K.newmark_work(
            X[:n], V[:n], A[:n], t0 + k * dt, dt, px[k:k + 1], pv[k:k + 1], pa[k:k + 1], channel[:n], elements[:ne],
            L0[:ne], EA[:ne], cdamp[:ne], mpl[:ne], dia[:ne], cdn[:ne], cdt[:ne], can[:ne], cat[:ne], weight[:n],
            pmass[:n], padd[:n], pvol[:n], pcda[:n], bedc[:n], buoy[:ne], pbuoy[:n], ts_lo[:ne], ts_hi[:ne], ts_x,
            ts_y, hinges[:nh], hinge_ei[:nh], visco[:nv], fidx[:n], nf, bw, env, cur_depth, cur_speed, np.bool_(True), sea,
            beta, gamma, alpha_m, alpha_f, G[:n], tol, max_iter, F[:n], M[:n], tension[:ne], stats, band[:3 * nf],
            R[:3 * nf], D[:3 * nf], Xn[:n], Vn[:n], An[:n], envw)
        if got < 1:
            return k
    return px.shape[0]


@njit(cache=True)
def record(row, t, ia, X, V, A, args, fidx, bw, env, cur_depth, cur_speed, sea, F, M, tension, s_node, times, pos,
           vel, ten, top, nact, arc):
    """Store the state in output row ``row``: positions and velocities of the nodes in the water (NaN beyond),
    element tensions, the force on the tow point ``top`` (its support force, 3) and the node count."""
    (elements, L0, EA, cdamp, mpl, dia, cdn, cdt, can, cat, weight, pmass, padd, pvol, pcda, bedc, buoy, pbuoy,
     ts_lo, ts_hi, ts_x, ts_y, hinges, hinge_ei, visco) = args
    n = ia[I_N]
    ne = n - 1
    nh = max(n - 2, 0) if hinges.shape[0] > 0 else 0
    nv = ne if visco.shape[0] > 0 else 0
    K.loads(X[:n], V[:n], t, elements[:ne], L0[:ne], EA[:ne], cdamp[:ne], mpl[:ne], dia[:ne], cdn[:ne], cdt[:ne],
            can[:ne], cat[:ne], weight[:n], pmass[:n], padd[:n], pvol[:n], pcda[:n], bedc[:n], buoy[:ne], pbuoy[:n],
            ts_lo[:ne], ts_hi[:ne], ts_x, ts_y, hinges[:nh], hinge_ei[:nh], visco[:nv], fidx[:n], env, cur_depth,
            cur_speed, np.bool_(True), sea, F[:n], M[:n], tension[:ne], np.zeros((0, 2 * bw + 1)), bw, 0.0, 0.0)
    times[row] = t
    pos[row] = np.nan
    vel[row] = np.nan
    ten[row] = np.nan
    arc[row] = np.nan
    copy_2d(pos[row, :n], X[:n])
    copy_2d(vel[row, :n], V[:n])
    copy_1d(ten[row, :ne], tension[:ne])
    copy_1d(arc[row, :n], s_node[:n])
    for r in range(3):
        f = F[n - 1, r]
        for c in range(3):
            f -= M[n - 1, r, c] * A[n - 1, c]
        top[row, r] = f
    nact[row] = n


@njit(cache=True)
def towed_outputs(k0, k1, interval, h, sub, px, pv, pa, lengths, ia, X, V, A, G, ds, s_lock, s_node, wpl, pw, pc, args,
                  fidx, channel, bw, env, env_rec, cur_depth, cur_speed, sea, beta, gamma, alpha_m, alpha_f, tol,
                  max_iter, F, M, tension, stats, count, band, R, D, Xn, Vn, An, envw, times, pos, vel, ten, top, nact,
                  arc):
    """Outputs ``k0 + 1`` .. ``k1`` (``sub`` steps of ``h`` each, their motion samples and deployed lengths in
    ``px``, ``pv``, ``pa``, ``lengths`` from output k0's end on), recorded in rows k + 1 - k0. Returns the last
    output reached; ``count`` (steps, Newton iterations, steps done of a failed interval) is advanced."""
    for k in range(k0, k1):
        j0 = (k - k0) * sub
        stats[0] = 0.0
        got = towed_steps(ia, X, V, A, G, k * interval, h, px[j0:j0 + sub], pv[j0:j0 + sub], pa[j0:j0 + sub],
                          lengths[j0:j0 + sub], ds, s_lock, s_node, wpl, pw, pc, args, fidx, channel, bw, env, cur_depth,
                          cur_speed, sea, beta, gamma, alpha_m, alpha_f, tol, max_iter, F, M, tension, stats, band, R,
                          D, Xn, Vn, An, envw)
        count[0] += got
        count[1] += int(stats[0])
        if got < sub:
            count[2] = got
            return k
        record(k + 1 - k0, (k + 1) * interval, ia, X, V, A, args, fidx, bw, env_rec, cur_depth, cur_speed, sea, F, M,
               tension, s_node, times, pos, vel, ten, top, nact, arc)
    return k1

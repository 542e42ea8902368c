"""Elastic catenary of one homogeneous line, in every regime, vectorised.

One plain function, :func:`catenary`, solves the static shape of an elastic line of
unstretched length ``L``, axial stiffness ``EA`` and weight in water ``w`` per metre between
end A (the anchor, at the origin) and end B (the fairlead, at ``(horizontal_span,
vertical_span)``, Z up), optionally with a horizontal seabed at the anchor's height on which
the line may lie with Coulomb friction.  Thousands of cases are solved together by a masked,
vectorised Newton iteration with analytic Jacobians.

Equations (unknowns: the fairlead tension components ``H`` and ``V_F``; ``V(s) = V_A + w s``,
``T = sqrt(H^2 + V^2)``, ``dx/ds = H/T + H/EA``, ``dz/ds = V/T + V/EA``):

* suspended (no seabed contact), with ``a = V_F/H``, ``b = V_A/H = (V_F - w L)/H``::

      x_F = H/w [asinh a - asinh b] + H L / EA
      z_F = H/w [sqrt(1+a^2) - sqrt(1+b^2)] + (V_F L - w L^2/2) / EA

* touching down (seabed, grounded length ``L_B = L - V_F/w``, friction ``mu``)::

      x_F = L_B + H/w asinh a + H L/EA - mu w / (2 EA) [L_B^2 - max(0, x_B)^2]
      z_F = H/w [sqrt(1+a^2) - 1] + V_F^2 / (2 w EA),      x_B = L_B - H/(mu w)

  (Irvine 1981, eqs. 2.26-2.27; Jonkman 2007, eqs. 2-35 to 2-42).  Both are evaluated in
  forms free of the division by ``w`` (``H/w = L/(a - b)``), so nearly weightless lines are
  accurate.

Sign convention (MoorPy's internal one): ``(H_fairlead, V_fairlead)`` is the force the
fairlead exerts on the line (the line pulls the fairlead by ``(-H_fairlead, -V_fairlead)``);
``(H_anchor, V_anchor)`` is the force the line exerts on the anchor (``H_anchor > 0`` pulls the
anchor toward the fairlead, ``V_anchor > 0`` lifts it).  With no seabed reaction
``V_fairlead = V_anchor + w L``.

Buoyant lines (``w < 0``) are solved as the mirror image (``z -> -z``) of a line of weight
``-w``.  A buoyant line whose two ends are at or above the seabed arches upward and can never
touch it (its height is a concave function of arc length), so for ``w < 0`` the seabed only
requires ``vertical_span >= 0`` and has no other effect; the sea surface is not modelled (check
that the line does not rise above it).

References
----------
.. [1] H. M. Irvine, *Cable Structures*, MIT Press, 1981, ch. 2.
.. [2] J. M. Jonkman, "Dynamics modeling and loads analysis of an offshore floating wind
   turbine", NREL/TP-500-41958, 2007, section 2.3 (quasi-static mooring lines).
.. [3] A. H. Peyrot and A. M. Goulois, "Analysis of cable structures", Computers & Structures
   10, 805-813, 1979 (initial guess).
.. [4] M. Hall et al., MoorPy, ``moorpy/Catenary.py`` (NREL), profile types and conventions.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum

import numpy as np

from .. import _validate
from ..errors import ConvergenceError, InputError, NoSolutionError

__all__ = ["CatenaryRegime", "CatenaryProfile", "CatenaryResult", "catenary"]

_VERTICAL_EPS = 1e-12   # spans below this fraction of L count as exactly zero
_H_FLOOR = 1e-15        # H is kept above this fraction of the tension scale in the iteration


class CatenaryRegime(IntEnum):
    """Shape of the solved line (numbers follow MoorPy's ``ProfileType`` where they overlap)."""

    ON_SEABED = 0        #: the whole line lies on the seabed (vertical_span == 0)
    SUSPENDED = 1        #: no seabed contact, H > 0 (includes U shapes with seabed=False)
    TOUCHDOWN = 2        #: part of the line on the seabed, anchor tension > 0
    TOUCHDOWN_SLACK_ANCHOR = 3  #: friction takes all the tension before the anchor
    SLACK_SEABED = 4     #: H = 0: line on the seabed (bunched if needed), then hanging vertically
    SLACK_U = 5          #: H = 0, seabed=False, zero horizontal span: both ends hang to a fold
    VERTICAL = 6         #: zero horizontal span, straight vertical line, no seabed contact
    WEIGHTLESS = 7       #: w = 0: straight elastic bar (zero tension if slack)


@dataclass(frozen=True)
class CatenaryProfile:
    """Shape and tension along one line, from the anchor (s = 0) to the fairlead.

    Attributes
    ----------
    s : ndarray
        Unstretched arc length from the anchor. [m]
    x, z : ndarray
        Position relative to the anchor, Z up. [m]
    tension : ndarray
        Effective tension. [N]
    """

    s: np.ndarray
    x: np.ndarray
    z: np.ndarray
    tension: np.ndarray


@dataclass(frozen=True)
class CatenaryResult:
    """Solution of :func:`catenary`; every array has the broadcast shape of the inputs.

    Attributes
    ----------
    H_fairlead, V_fairlead : ndarray
        Force the fairlead exerts on the line (the line pulls the fairlead the opposite way);
        ``V_fairlead > 0`` when the fairlead holds the line up. [N]
    H_anchor, V_anchor : ndarray
        Force the line exerts on the anchor; ``H_anchor > 0`` pulls toward the fairlead,
        ``V_anchor > 0`` lifts the anchor. [N]
    fairlead_tension, anchor_tension : ndarray
        Tension magnitude at each end. [N]
    grounded_length : ndarray
        Unstretched length lying on the seabed. [m]
    stiffness : ndarray
        Shape ``(..., 2, 2)``: ``d(H_fairlead, V_fairlead)/d(x_F, z_F)``, fairlead moved with
        the anchor fixed. Exactly 0 where a slack line does not react; ``inf`` for
        ``dV/dz`` of a tensioned line lying flat on the seabed (one-sided square-root
        lift-off). [N/m]
    regime : ndarray of int8
        :class:`CatenaryRegime` codes.
    iterations : int
        Newton iterations used by the slowest case (0 if all were closed-form).
    horizontal_span, vertical_span, length, axial_stiffness, weight_per_length, \
seabed_friction, seabed : ndarray
        The broadcast inputs (kept for :meth:`profile`).
    """

    H_fairlead: np.ndarray
    V_fairlead: np.ndarray
    H_anchor: np.ndarray
    V_anchor: np.ndarray
    fairlead_tension: np.ndarray
    anchor_tension: np.ndarray
    grounded_length: np.ndarray
    stiffness: np.ndarray
    regime: np.ndarray
    iterations: int
    horizontal_span: np.ndarray
    vertical_span: np.ndarray
    length: np.ndarray
    axial_stiffness: np.ndarray
    weight_per_length: np.ndarray
    seabed_friction: np.ndarray
    seabed: np.ndarray

    def profile(self, n_points: int = 100, index=None) -> CatenaryProfile:
        """Shape and tension of one line at ``n_points`` points evenly spaced in ``s``.

        Parameters
        ----------
        n_points : int
            Number of points, >= 2.
        index : int or tuple, optional
            Which case of an array result (an index into the broadcast shape); required
            unless the result is scalar.

        Returns
        -------
        CatenaryProfile
            Arrays of length ``n_points``; ``s`` from 0 (anchor) to ``length`` (fairlead).
        """
        n_points = int(n_points)
        if n_points < 2:
            raise InputError(f"n_points must be >= 2, got {n_points}. Suggested fix: use 100.")
        shape = np.shape(self.H_fairlead)
        if index is None:
            if shape != ():
                raise InputError(f"index must be given for an array result of shape {shape}. "
                                 "Suggested fix: pass index=(i, ...) of the case to draw.")
            index = ()
        get = (lambda a: float(np.asarray(a)[index]))
        return _profile(n_points, get(self.horizontal_span), get(self.vertical_span),
                        get(self.length), get(self.axial_stiffness), get(self.weight_per_length),
                        get(self.seabed_friction), get(self.H_fairlead), get(self.V_fairlead),
                        get(self.grounded_length), int(np.asarray(self.regime)[index]))


# ---------------------------------------------------------------------------------------------
# stable pieces of the closed forms


def _asinh_over(q):
    """asinh(q)/q, accurate near q = 0."""
    q = np.asarray(q, dtype=float)
    small = np.abs(q) < 1e-3
    qs = np.where(small, 1.0, q)
    return np.where(small, 1.0 - q * q / 6.0 + 0.075 * q ** 4, np.arcsinh(qs) / qs)


def _g_c(a, b):
    """g = (asinh a - asinh b)/(a - b) and c = (a Rb - b Ra)/(a - b), Ra = sqrt(1 + a^2).

    Limits a -> b handled; no catastrophic cancellation for either sign pattern.
    """
    Ra, Rb = np.hypot(1.0, a), np.hypot(1.0, b)
    same = a * b > 0
    with np.errstate(divide="ignore", invalid="ignore"):
        c_same = (a + b) / (a * Rb + b * Ra)
        g_same = _asinh_over((a - b) * c_same) * c_same
        d = a - b
        zero = d == 0
        d = np.where(zero, 1.0, d)
        c_opp = np.where(zero, 1.0, (a * Rb - b * Ra) / d)
        g_opp = np.where(zero, 1.0, (np.arcsinh(a) - np.arcsinh(b)) / d)
    return np.where(same, g_same, g_opp), np.where(same, c_same, c_opp), Ra, Rb


def _spans(H, V, L, EA, w, mu, seabed):
    """Fairlead position (x, z) and Jacobian d(x, z)/d(H, V) for w > 0 (flipped frame)."""
    # fully suspended
    a, b = V / H, (V - w * L) / H
    g, c, Ra, Rb = _g_c(a, b)
    LH = L / H
    x = L * g + H * L / EA
    z = L * (a + b) / (Ra + Rb) + (V * L - 0.5 * w * L * L) / EA
    m = LH * (a + b) / ((Ra + Rb) * Ra * Rb)        # int H V / T^3 ds
    n = LH * c / (Ra * Rb)                          # int H^2 / T^3 ds
    Jxh, Jxv, Jzh, Jzv = LH * g - n + L / EA, -m, -m, n + L / EA
    # touching down (only where the seabed is present and V < w L)
    grd = seabed & (V < w * L)
    if np.any(grd):
        Hg, Vg, Lg, EAg, wg, mug = (arr[grd] for arr in (H, V, L, EA, w, mu))
        ag = Vg / Hg
        Rg = np.hypot(1.0, ag)
        LB = Lg - Vg / wg
        with np.errstate(divide="ignore", invalid="ignore"):
            xB = np.where(mug > 0, LB - Hg / (mug * wg), 0.0)
        xBp = np.maximum(xB, 0.0)
        small = np.abs(ag) < 1e-3
        as_ = np.where(small, 1.0, ag)
        asinh_minus = np.where(small, ag ** 3 / 3.0 - 0.3 * ag ** 5, np.arcsinh(as_) - as_ / np.hypot(1, as_))
        x[grd] = (LB + Vg / wg * _asinh_over(ag) + Hg * Lg / EAg
                  - 0.5 * mug * wg / EAg * (LB * LB - xBp * xBp))
        z[grd] = Vg / wg * ag / (Rg + 1.0) + Vg * Vg / (2.0 * wg * EAg)
        Jxh[grd] = asinh_minus / wg + (Lg - xBp) / EAg
        Jxv[grd] = -ag * ag / (Rg * (Rg + 1.0)) / wg + mug * (LB - xBp) / EAg
        Jzh[grd] = -ag * ag / (Rg * (Rg + 1.0)) / wg
        Jzv[grd] = ag / Rg / wg + Vg / (wg * EAg)
    return x, z, Jxh, Jxv, Jzh, Jzv, grd


def _guess(x, z, L, EA, w):
    """Peyrot & Goulois (1979) initial (H, V_F), raised to the straight-bar tension when taut."""
    chord = np.hypot(x, z)
    with np.errstate(divide="ignore", invalid="ignore"):
        lam = np.sqrt(np.maximum(3.0 * ((L * L - z * z) / (x * x) - 1.0), 0.0))
    lam = np.where((L <= chord) | ~np.isfinite(lam) | (lam < 0.2), 0.2, np.minimum(lam, 1e6))
    H = 0.5 * w * x / lam
    V = 0.5 * w * (z / np.tanh(lam) + L)
    taut = chord >= L
    T = EA * (chord / L - 1.0)
    H = np.where(taut, np.maximum(H, T * x / chord), H)
    V = np.where(taut, T * z / np.where(taut, chord, 1.0) + 0.5 * w * L, V)
    return np.maximum(H, _H_FLOOR * (w * L + np.abs(V))), V


def _newton(x, z, L, EA, w, mu, seabed, tol, max_iter, flat_index, shape):
    """Masked vectorised Newton with Armijo backtracking; all inputs 1-D, w > 0."""
    H, V = _guess(x, z, L, EA, w)
    scale = np.maximum(L, np.hypot(x, z))
    act = np.arange(x.size)
    it = 0

    def resid(idx, Hi, Vi):
        out = _spans(Hi, Vi, L[idx], EA[idx], w[idx], mu[idx], seabed[idx])
        fx, fz = out[0] - x[idx], out[1] - z[idx]
        return fx, fz, out

    fx, fz, out = resid(act, H, V)
    while True:
        err = np.maximum(np.abs(fx), np.abs(fz)) / scale[act]
        done = err <= tol
        keep = ~done
        act, fx, fz, err = act[keep], fx[keep], fz[keep], err[keep]
        Jxh, Jxv, Jzh, Jzv = (j[keep] for j in out[2:6])
        if act.size == 0:
            break
        if it >= max_iter:
            k = int(np.argmax(err))
            case = tuple(int(i) for i in np.unravel_index(flat_index[act[k]], shape)) if shape else "0"
            raise ConvergenceError(
                f"catenary did not converge for case {case} "
                f"(horizontal_span={x[act[k]]:.6g} m, |vertical_span|={z[act[k]]:.6g} m, "
                f"length={L[act[k]]:.6g} m) after {it} iterations; span residual "
                f"{err[k]:.3g} x length. Suggested fix: raise max_iter or loosen tol.",
                iterations=it, residual=float(err[k]))
        it += 1
        Ha, Va = H[act], V[act]
        det = Jxh * Jzv - Jxv * Jzh
        dH = -(Jzv * fx - Jxv * fz) / det
        dV = -(-Jzh * fx + Jxh * fz) / det
        bad = ~(np.isfinite(dH) & np.isfinite(dV))
        dH, dV = np.where(bad, 0.5 * Ha, dH), np.where(bad, 0.0, dV)
        alpha = np.ones_like(Ha)
        shrink = Ha + dH < 0.1 * Ha
        alpha = np.where(shrink, np.minimum(alpha, 0.9 * Ha / np.where(shrink, -dH, 1.0)), alpha)
        sb = seabed[act] & (Va > 0)
        vneg = sb & (Va + dV < 0.1 * Va)
        alpha = np.where(vneg, np.minimum(alpha, 0.9 * Va / np.where(vneg, -dV, 1.0)), alpha)
        f2 = fx * fx + fz * fz
        todo = np.arange(act.size)
        Hn, Vn = Ha.copy(), Va.copy()
        fxn, fzn = fx.copy(), fz.copy()
        outn = [np.empty_like(Ha) for _ in range(4)]
        for _ in range(30):
            Ht = Ha[todo] + alpha[todo] * dH[todo]
            Vt = Va[todo] + alpha[todo] * dV[todo]
            Ht = np.maximum(Ht, _H_FLOOR * (w[act[todo]] * L[act[todo]] + np.abs(Vt)))
            gx, gz, o = resid(act[todo], Ht, Vt)
            ok = np.isfinite(gx) & np.isfinite(gz) & (gx * gx + gz * gz <= (1 - 1e-4 * alpha[todo]) * f2[todo])
            last = _ == 29
            acc = ok | last
            sel = todo[acc]
            Hn[sel], Vn[sel], fxn[sel], fzn[sel] = Ht[acc], Vt[acc], gx[acc], gz[acc]
            for j in range(4):
                outn[j][sel] = o[2 + j][acc]
            todo = todo[~acc]
            if todo.size == 0:
                break
            alpha[todo] *= 0.5
        H[act], V[act] = Hn, Vn
        fx, fz = fxn, fzn
        out = (None, None, *outn)
    return H, V, it


def _as_array(name, value, unit, fix, check):
    return np.asarray(check(name, value, unit, fix), dtype=float)


def catenary(horizontal_span, vertical_span, length, axial_stiffness, weight_per_length,
             seabed_friction=0.0, seabed=True, *, tol=1e-10, max_iter=100, max_strain=1.0):
    """Elastic catenary of one homogeneous line, with an optional frictional seabed.

    Parameters
    ----------
    horizontal_span : array_like
        Horizontal distance from the anchor (end A) to the fairlead (end B), >= 0. [m]
    vertical_span : array_like
        Height of the fairlead above the anchor (Z up); >= 0 when ``seabed`` is True. [m]
    length : array_like
        Unstretched line length. [m]
    axial_stiffness : array_like
        Axial stiffness EA. [N]
    weight_per_length : array_like
        Weight in water per unit unstretched length; negative for a buoyant line. [N/m]
    seabed_friction : array_like, optional
        Coulomb friction coefficient of the grounded line (axial). [-]
    seabed : bool or array_like of bool, optional
        True: a flat seabed at the anchor's height on which the line may lie from the anchor
        (the grounded tension falls by ``mu w`` per metre toward the anchor, not below zero).
        False: end A hangs in mid-water and the line may sag below it.
    tol : float, optional
        Convergence tolerance on the span residuals, relative to ``max(length, chord)``. [-]
    max_iter : int, optional
        Maximum Newton iterations.
    max_strain : float, optional
        Largest admissible strain ``T/EA``; a line that would need more "cannot reach". [-]

    Returns
    -------
    CatenaryResult
        End forces, tensions, grounded length, fairlead stiffness and regime, each with the
        broadcast shape of the inputs.

    Raises
    ------
    InputError
        Negative spans or lengths, EA <= 0, NaN/inf, negative friction, fairlead below the
        seabed.
    NoSolutionError
        The line can only reach with a strain above ``max_strain``.
    ConvergenceError
        Newton did not converge (names the case, iterations and residual).

    Notes
    -----
    Closed forms are used where the iteration is singular: the line flat on the seabed
    (``vertical_span == 0``), the slack "L" shape with zero horizontal tension (hanging
    length ``Ls`` from ``z = Ls + w Ls^2/(2 EA)``; any excess lies bunched on the seabed), a
    zero horizontal span (straight vertical line or, without seabed, a U folded at its
    lowest point), and ``w == 0`` (straight elastic bar).  Spans smaller than ``1e-12 L`` are
    treated as zero.

    References
    ----------
    .. [1] H. M. Irvine, *Cable Structures*, MIT Press, 1981, eqs. 2.26-2.27.
    .. [2] J. M. Jonkman, NREL/TP-500-41958, 2007, eqs. 2-35 to 2-42.
    .. [3] A. H. Peyrot and A. M. Goulois, Computers & Structures 10, 805-813, 1979.
    """
    xs = _as_array("horizontal_span", horizontal_span, "m",
                   "give the horizontal distance from anchor to fairlead (>= 0)", _validate.nonnegative)
    zs = _as_array("vertical_span", vertical_span, "m", "give the fairlead height above the anchor",
                   _validate.finite)
    Ls = _as_array("length", length, "m", "give the unstretched line length in metres", _validate.positive)
    EAs = _as_array("axial_stiffness", axial_stiffness, "N", "give EA in newtons (E [Pa] x area [m^2])",
                    _validate.positive)
    ws = _as_array("weight_per_length", weight_per_length, "N/m",
                   "give the weight in water per metre (negative if buoyant)", _validate.finite)
    mus = _as_array("seabed_friction", seabed_friction, "",
                    "use a friction coefficient >= 0 (0 for none)", _validate.nonnegative)
    try:
        sbs = np.asarray(seabed, dtype=bool)
    except (TypeError, ValueError):
        raise InputError(f"seabed must be True or False, got {seabed!r}. Suggested fix: pass a bool.") from None
    tol = float(_validate.positive("tol", tol, "", "use e.g. 1e-10"))
    max_strain = float(_validate.positive("max_strain", max_strain, "", "use e.g. 1.0 (100 %)"))
    max_iter = int(_validate.at_least("max_iter", max_iter, 1, "", "use e.g. 100"))
    try:
        arrs = np.broadcast_arrays(xs, zs, Ls, EAs, ws, mus, sbs)
    except ValueError:
        raise InputError("the inputs of catenary must broadcast together, got shapes "
                         f"{[np.shape(a) for a in (xs, zs, Ls, EAs, ws, mus, sbs)]}. "
                         "Suggested fix: give arrays of one shape or scalars.") from None
    shape = arrs[0].shape
    x, z, L, EA, w, mu, sb = (np.array(a).ravel() for a in arrs)
    below = sb & (z < 0)
    if below.any():
        k = int(np.argmax(below))
        raise InputError(f"vertical_span{_where(k, shape)} must be >= 0 m when seabed=True, got "
                         f"{z[k]:.6g} m. Suggested fix: the fairlead cannot be below the seabed at the "
                         "anchor's height; use seabed=False for a line hanging below end A.")
    chord = np.hypot(x, z)
    strain = chord / L - 1.0
    over = strain > max_strain
    if over.any():
        k = int(np.argmax(over))
        raise NoSolutionError(_cannot_reach(k, shape, x, z, L, EA, strain[k], max_strain))

    n = x.size
    sign = np.where(w < 0, -1.0, 1.0)
    zp, wp = sign * z, np.abs(w)
    sbp = sb & (w > 0)                        # a buoyant line never touches the seabed
    H, V, VA, LB = (np.zeros(n) for _ in range(4))
    HA = np.zeros(n)
    K = np.zeros((n, 2, 2))
    reg = np.full(n, -1, dtype=np.int8)
    eps = _VERTICAL_EPS * L

    # w == 0: straight elastic bar
    m0 = w == 0
    if m0.any():
        c = chord[m0]
        T = EA[m0] * np.maximum(c / L[m0] - 1.0, 0.0)
        cs = np.where(c > 0, c, 1.0)
        nx, nz = x[m0] / cs, zp[m0] / cs
        H[m0], V[m0], HA[m0], VA[m0] = T * nx, T * nz, T * nx, T * nz
        kt, kl = T / cs, np.where(T > 0, EA[m0] / L[m0], 0.0)
        K[m0, 0, 0] = kl * nx * nx + kt * (1 - nx * nx)
        K[m0, 0, 1] = K[m0, 1, 0] = (kl - kt) * nx * nz
        K[m0, 1, 1] = kl * nz * nz + kt * (1 - nz * nz)
        reg[m0] = CatenaryRegime.WEIGHTLESS
    # whole line flat on the seabed
    m1 = ~m0 & sbp & (zp <= eps)
    if m1.any():
        x1, L1, EA1, w1, mu1 = x[m1], L[m1], EA[m1], wp[m1], mu[m1]
        dL = np.maximum(x1 - L1, 0.0)
        Hfull = EA1 * dL / L1 + 0.5 * mu1 * w1 * L1        # anchor tension > 0
        Hpart = np.sqrt(2.0 * mu1 * w1 * EA1 * dL)         # friction takes it all
        part = (mu1 > 0) & (Hpart < mu1 * w1 * L1)
        H1 = np.where(dL > 0, np.where(part, Hpart, Hfull), 0.0)
        H[m1], HA[m1], LB[m1] = H1, np.maximum(H1 - mu1 * w1 * L1, 0.0), L1
        with np.errstate(divide="ignore"):
            K[m1, 0, 0] = np.where(H1 > 0, np.where(part, mu1 * w1 * EA1 / np.where(part, H1, 1.0),
                                                    EA1 / L1), 0.0)
        K[m1, 1, 1] = np.where(H1 > 0, np.inf, w1)
        reg[m1] = CatenaryRegime.ON_SEABED
    # zero horizontal tension: hanging length from z = Ls + w Ls^2 / (2 EA)
    Lh = 2.0 * np.abs(zp) / (1.0 + np.sqrt(1.0 + 2.0 * np.abs(zp) * wp / EA))
    m2 = (reg < 0) & sbp & (L - Lh >= x)
    if m2.any():
        V[m2], LB[m2] = wp[m2] * Lh[m2], L[m2] - Lh[m2]
        K[m2, 1, 1] = wp[m2] / (1.0 + wp[m2] * Lh[m2] / EA[m2])
        reg[m2] = CatenaryRegime.SLACK_SEABED
    # zero horizontal span
    m3 = (reg < 0) & (x <= eps)
    if m3.any():
        z3, L3, EA3, w3 = zp[m3], L[m3], EA[m3], wp[m3]
        f = 1.0 + 0.5 * w3 * L3 / EA3
        taut = np.abs(z3) >= L3 * f
        VA3 = EA3 * (z3 - np.sign(z3) * L3) / L3 - 0.5 * w3 * L3
        with np.errstate(divide="ignore", invalid="ignore"):
            dxdH = np.abs(np.log1p(w3 * L3 / VA3)) / w3 + L3 / EA3
        d = z3 / f                                     # L2 - L1 of the U
        V3 = np.where(taut, VA3 + w3 * L3, 0.5 * w3 * (L3 + d))
        V[m3], VA[m3] = V3, np.where(taut, VA3, V3 - w3 * L3)
        K[m3, 0, 0] = np.where(taut & np.isfinite(dxdH), 1.0 / dxdH, 0.0)
        K[m3, 1, 1] = np.where(taut, EA3 / L3, 0.5 * w3 / f)
        reg[m3] = np.where(taut, CatenaryRegime.VERTICAL, CatenaryRegime.SLACK_U)
    # everything else: Newton
    m4 = reg < 0
    iters = 0
    if m4.any():
        idx = np.flatnonzero(m4)
        H4, V4, iters = _newton(x[m4], zp[m4], L[m4], EA[m4], wp[m4], mu[m4], sbp[m4], tol, max_iter,
                                idx, shape)
        _, _, Jxh, Jxv, Jzh, Jzv, grd = _spans(H4, V4, L[m4], EA[m4], wp[m4], mu[m4], sbp[m4])
        det = Jxh * Jzv - Jxv * Jzh
        K[m4, 0, 0], K[m4, 0, 1] = Jzv / det, -Jxv / det
        K[m4, 1, 0], K[m4, 1, 1] = -Jzh / det, Jxh / det
        L4, w4, mu4 = L[m4], wp[m4], mu[m4]
        LB4 = np.where(grd, L4 - V4 / w4, 0.0)
        HA4 = np.where(grd, np.maximum(H4 - mu4 * w4 * LB4, 0.0), H4)
        H[m4], V[m4], LB[m4], HA[m4] = H4, V4, LB4, HA4
        VA[m4] = np.where(grd, 0.0, V4 - w4 * L4)
        reg[m4] = np.where(grd, np.where(HA4 > 0, CatenaryRegime.TOUCHDOWN,
                                         CatenaryRegime.TOUCHDOWN_SLACK_ANCHOR), CatenaryRegime.SUSPENDED)
    HA = np.where(np.isin(reg, (CatenaryRegime.SUSPENDED, CatenaryRegime.WEIGHTLESS,
                                CatenaryRegime.VERTICAL, CatenaryRegime.SLACK_U)), H, HA)
    # back from the mirrored frame of buoyant lines
    V, VA = sign * V, sign * VA
    K[:, 0, 1] *= sign
    K[:, 1, 0] *= sign
    TF, TA = np.hypot(H, V), np.hypot(HA, VA)
    over = np.maximum(TF, TA) / EA > max_strain
    if over.any():
        k = int(np.argmax(over))
        raise NoSolutionError(_cannot_reach(k, shape, x, z, L, EA, max(TF[k], TA[k]) / EA[k], max_strain,
                                            by_weight=np.hypot(x[k], z[k]) <= L[k]))
    r = lambda a: a.reshape(shape)  # noqa: E731
    return CatenaryResult(r(H), r(V), r(HA), r(VA), r(TF), r(TA), r(LB), K.reshape(shape + (2, 2)),
                          r(reg), int(iters), *(r(a) for a in (x, z, L, EA, w, mu, sb)))


def _where(k, shape):
    if not shape:
        return ""
    idx = tuple(int(i) for i in np.unravel_index(k, shape))
    return f"[{idx[0] if len(idx) == 1 else idx}]"


def _cannot_reach(k, shape, x, z, L, EA, strain, max_strain, *, by_weight=False):
    where = (f"horizontal_span={x[k]:.6g} m, vertical_span={z[k]:.6g} m, length={L[k]:.6g} m, "
             f"axial_stiffness={EA[k]:.6g} N")
    if by_weight:
        # The chord is reachable, but the line's own tension stretches it past the bound.
        return (f"the line{_where(k, shape)} would stretch by {strain:.3g} > max_strain={max_strain:.3g} "
                f"under its own tension: {where}. Suggested fix: check axial_stiffness (N) and "
                "weight_per_length (N/m) for a unit slip; a real line this soft needs max_strain raised.")
    return (f"the line{_where(k, shape)} cannot reach its fairlead: {where} would need a strain of "
            f"{strain:.3g} > max_strain={max_strain:.3g}. Suggested fix: lengthen the line or bring the ends "
            "closer (or raise max_strain if the material really stretches so far).")


def _profile(n, xF, zF, L, EA, w, mu, H, VF, LB, regime):
    """Points along one solved line (scalars in, arrays out); see CatenaryResult.profile."""
    s = np.linspace(0.0, L, n)
    sg = -1.0 if w < 0 else 1.0
    w, zF, VF = abs(w), sg * zF, sg * VF
    x, z, T = np.zeros(n), np.zeros(n), np.zeros(n)
    R = CatenaryRegime
    if regime == R.WEIGHTLESS:
        T[:] = np.hypot(H, VF)
        x, z = xF * s / L, zF * s / L
    elif regime == R.VERTICAL:
        VA = VF - w * L
        V = VA + w * s
        T, x, z = np.abs(V), np.full(n, xF), np.sign(zF) * s + (VA * s + 0.5 * w * s * s) / EA
    elif regime == R.SLACK_U:
        L1 = L - VF / w
        a = s <= L1
        T = w * np.abs(s - L1)
        d1 = L1 + 0.5 * w * L1 * L1 / EA
        z = np.where(a, -(s + w / EA * (L1 * s - 0.5 * s * s)), -d1 + (s - L1) + 0.5 * w * (s - L1) ** 2 / EA)
        x = np.full(n, xF)
    elif regime == R.SUSPENDED:
        VA = VF - w * L
        V = VA + w * s
        x, z, T = _suspended_arc(s, H, VA, V, w, EA)
    else:   # on the seabed for s <= LB, then suspended from the touchdown (V = 0 there)
        on = s <= LB
        if regime == R.SLACK_SEABED or H == 0:    # zero tension; bunched evenly if longer than x_F
            xTD = min(xF, LB)
            xg, Tg = np.minimum(s, LB) * (xTD / LB if LB > 0 else 0.0), np.zeros(n)
        else:
            xg, Tg = _grounded(np.append(np.minimum(s, LB), LB), H, LB, mu, w, EA)
            xTD, xg, Tg = xg[-1], xg[:-1], Tg[:-1]
        u = np.maximum(s - LB, 0.0)
        if regime == R.ON_SEABED:
            xa, za, Ta = np.zeros(n), np.zeros(n), Tg
        elif regime == R.SLACK_SEABED:
            xa, za, Ta = np.zeros(n), u + 0.5 * w * u * u / EA, w * u
        else:
            xa, za, Ta = _suspended_arc(u, H, 0.0, w * u, w, EA)
        x, z, T = np.where(on, xg, xTD + xa), np.where(on, 0.0, za), np.where(on, Tg, Ta)
    return CatenaryProfile(s, np.asarray(x, float), sg * np.asarray(z, float), np.asarray(T, float))


def _suspended_arc(s, H, VA, V, w, EA):
    """x, z, T at unstretched distance s from a point where the vertical tension is VA."""
    a, b = V / H, np.full_like(V, VA / H)
    g, _, Ra, Rb = _g_c(a, b)
    x = s * g + H * s / EA
    z = s * (a + b) / (Ra + Rb) + (VA * s + 0.5 * w * s * s) / EA
    return x, z, np.hypot(H, V)


def _grounded(s, H, LB, mu, w, EA):
    """x and T along a grounded length LB whose tension at the touchdown is H (s <= LB)."""
    if mu <= 0:
        return s + H * s / EA, np.full_like(s, H)
    xB = max(LB - H / (mu * w), 0.0)          # tension is zero on [0, xB]
    u = np.maximum(s, xB)
    stretch = ((H - mu * w * LB) * (u - xB) + 0.5 * mu * w * (u * u - xB * xB)) / EA
    return s + stretch, np.maximum(H - mu * w * (LB - s), 0.0)

"""Irregular seas: wave spectra, random-phase synthesis and linear kinematics on a grid.

Spectra (one-sided, in angular frequency omega [rad/s], S [m^2 s/rad]; DNV-RP-C205 [1]_ 3.5.5):

- Pierson-Moskowitz: ``S_PM = 5/16 Hs^2 wp^4 w^-5 exp(-5/4 (w / wp)^-4)``, ``wp = 2 pi / Tp``.
- JONSWAP: ``S_J = A_gamma S_PM gamma^exp(-(w - wp)^2 / (2 sigma^2 wp^2))`` with sigma = 0.07 for
  w <= wp and 0.09 above, and DNV's normalising factor ``A_gamma = 1 - 0.287 ln(gamma)`` (eq. 3.5.5.2;
  gamma = 1 is Pierson-Moskowitz exactly).
- A user table (omega [rad/s], S [m^2 s/rad]), linear between its points, zero outside.

Synthesis (linear random-phase model): ``n`` components on equal bands of width ``dw`` over the
frequency range (default: where the spectrum holds all but 1 % of its energy, see
:func:`frequency_range`), each at a frequency drawn uniformly inside its band (so the record has
no repeat period; equally spaced frequencies would repeat after ``2 pi / dw``), with amplitude
``a_j = sqrt(2 S(w_j) dw)`` and a phase uniform on [0, 2 pi) from a seeded
:class:`numpy.random.Generator`. The amplitudes are scaled by a common factor (close to 1, the
energy of the truncated tails and DNV's approximate A_gamma) so that ``sum a_j^2 / 2 = Hs^2 / 16``:
the generated sea has the significant wave height asked for (``Hs = 4 sqrt(m0)``).

Directional spreading (short-crested seas): DNV's cos-2s function [1]_ (3.5.8.4)

    D(b) = Gamma(s + 1) / (2 sqrt(pi) Gamma(s + 1/2)) cos^(2s)((b - b0) / 2),   |b - b0| <= pi,

applied by giving each frequency component one direction drawn from D (the single-direction-
per-frequency method, Jefferys [3]_): the point spectrum of the elevation stays the target one and
the sea is ergodic (no phase locking as with a double sum).

Kinematics are the linear (Airy) superposition of the components (:mod:`seacable.waves` for each:
dispersion relation, ``cosh(k (z + d)) / sinh(k d)`` profiles). For the time loop they are
precomputed on a grid (:func:`kinematics_grid`): in time, along and across the mean heading,
and in depth below the still-water level (levels closer near the surface), and interpolated
(multi-)linearly in the compiled kernel (:func:`grid_point`), so that a step costs the same as with a
regular wave. The grid covers the nodes above the depth where the waves die out (:func:`cutoff_depth`;
below it no wave kinematics), holds only the components that matter at the highest of them
(:func:`significant`), and a long run takes it in windows of time
(:meth:`seacable.mooring.solver.MooringModel.ensure_sea`). A run with a free body takes it in depth bands
(:class:`SeaBands`, :func:`depth_bands`): below the top band, each band holds only the components that carry
0.1 % or more of the acceleration's standard deviation there, on steps that follow the shortest of them
(``BAND_REFINE`` times finer), and a column that none of the points reaches in a band's depths holds no levels
of its own. Above z = 0 the kinematics are the z = 0 values (constant extrapolation, the default) or
Wheeler-stretched [2]_ (``z' = (z - eta) d / (d + eta)``, ``z' = z - eta`` in deep water): the stretched
point ``z'`` is where the linear-theory kinematics are taken, so that the crest's kinematics are those of z = 0
and the seabed stays at the seabed.

References
----------
.. [1] DNV-RP-C205, 2021. Environmental conditions and environmental loads, sections 3.5.5 and 3.5.8.
.. [2] Wheeler, J. D., 1970. Method for calculating forces produced by irregular waves. Journal of
   Petroleum Technology 22(3), 359-367.
.. [3] Jefferys, E. R., 1987. Directional seas should be ergodic. Applied Ocean Research 9(4), 186-191.
.. [4] Bendat, J. S. & Piersol, A. G., 2010. Random Data, 4th ed. Wiley, section 8.2 (sampling
   error of a variance estimate).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ._jit import njit
from .waves import STANDARD_GRAVITY, wave_number

__all__ = [
    "GRID_HEADER",
    "SeaBands",
    "SeaComponents",
    "SeaGrid",
    "cos2s_spreading",
    "cos_sin",
    "cutoff_depth",
    "depth_bands",
    "frequency_range",
    "grid_eta",
    "grid_point",
    "grid_points",
    "jonswap",
    "jonswap_gamma",
    "kinematics_grid",
    "no_sea",
    "pierson_moskowitz",
    "significant",
    "synthesise",
    "table_spectrum",
]

#: Energy fraction left out of the default frequency range (half below, half above). [-]
TAIL_ENERGY = 1e-2

# Packed sea array (the kernel's ``sea`` argument): header, then the grid.
S_MODE, S_STRETCH = 0, 1          # mode: 0 no irregular sea, 1 grid; stretching: 0 constant, 1 Wheeler
S_T0, S_DT, S_NT = 2, 3, 4        # time grid
S_X0, S_DX, S_NX = 5, 6, 7        # along the mean heading (xi = x cos b + y sin b)
S_Y0, S_DY, S_NY = 8, 9, 10       # across it (zeta = -x sin b + y cos b)
S_COS, S_SIN = 11, 12             # cos b, sin b of the mean heading
S_ZC, S_ZH, S_NZ = 13, 14, 15     # depth levels z = -c (exp(i h) - 1), i = i0 .. i0 + nz - 1
S_DEPTH = 16                      # water depth (inf: deep) [m]
S_ZMIN = 17                       # the grid's deepest point: no wave kinematics below [m]
S_I0 = 18                         # the index i0 of the grid's top level (0: z = 0)
S_NQ, S_NP = 19, 20               # values a point (4: long-crested, along its heading; 6) and points a time
S_ETAMAX = 21                     # the largest |elevation| of the grid's window [m]
S_SINGLE = 22                     # 1: the kinematics stored in single precision (float32 pairs), 0: double
S_NEXT = 23                       # offset (values) of the next depth band's header from this one's (0: the last)
GRID_HEADER = 24

#: Below the depth where the sea's horizontal velocity standard deviation falls under this fraction of its
#: value at z = 0 the kinematics grid stops and the waves' kinematics are neglected (:func:`cutoff_depth`). [-]
CUTOFF = 1e-3

#: The ratio of the shortest wave numbers of two successive depth bands of a banded grid (:func:`depth_bands`). [-]
BAND_RATIO = 2.0

#: The points a period and a wavelength of a banded grid's depth bands below the top one, relative to the top band's
#: (:class:`SeaBands`). Multilinear interpolation takes ``(w dt)^2 / 8 + (k dx)^2 / 8`` off each component's
#: amplitude between grid points, a bias shared by all the points rather than a random error; on a band's steps
#: following its own shortest component the components that carry the sea lose more than on the top band's, and
#: the lines' tensions with them (a held buoy's fairlead tensions' sea share lost 1.1 % of the one grid's standard
#: deviation with 1, within 0.4 % with 1.4; tests/validation/test_system_dynamics_irregular_sea.py). [-]
BAND_REFINE = 1.4


def pierson_moskowitz(omega, hs, tp):
    """Pierson-Moskowitz spectrum (DNV-RP-C205 eq. 3.5.5.1).

    Parameters
    ----------
    omega : array_like
        Angular frequency (> 0). [rad/s]
    hs : float
        Significant wave height. [m]
    tp : float
        Peak period. [s]

    Returns
    -------
    numpy.ndarray
        Spectral density. [m^2 s/rad]
    """
    w = np.asarray(omega, float)
    wp = 2.0 * math.pi / tp
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        s = 5.0 / 16.0 * hs ** 2 * wp ** 4 * w ** -5.0 * np.exp(-1.25 * (w / wp) ** -4.0)
    return np.where(w > 0, s, 0.0)


def jonswap_gamma(hs, tp) -> float:
    """JONSWAP's peak enhancement factor when none is given: DNV-RP-C205 (2021) 3.5.5.5's rule from
    ``r = Tp / sqrt(Hs)`` (Tp in s, Hs in m): 5 for ``r <= 3.6``, ``exp(5.75 - 1.15 r)`` between, 1 (a
    Pierson-Moskowitz sea) for ``r >= 5``. [-]

    The one place seacable's default gamma is made (:func:`jonswap`, :class:`seacable.environment.IrregularWaves`).
    """
    r = float(tp) / math.sqrt(float(hs))
    if r <= 3.6:
        return 5.0
    if r >= 5.0:
        return 1.0
    return math.exp(5.75 - 1.15 * r)


def jonswap(omega, hs, tp, gamma=None):
    """JONSWAP spectrum with DNV's normalisation ``A_gamma = 1 - 0.287 ln(gamma)`` (DNV-RP-C205 3.5.5.2).

    Peak shape width sigma = 0.07 for omega <= omega_p, 0.09 above. ``gamma`` = 1 is
    :func:`pierson_moskowitz`. A_gamma makes m0 = Hs^2/16 to about 1 % for 1 <= gamma <= 7. ``gamma`` None
    (the default) is DNV-RP-C205's rule from Tp / sqrt(Hs) (:func:`jonswap_gamma`).

    Parameters
    ----------
    omega : array_like
        Angular frequency (> 0). [rad/s]
    hs : float
        Significant wave height. [m]
    tp : float
        Peak period. [s]
    gamma : float, optional
        Peak enhancement factor (>= 1); None: :func:`jonswap_gamma` of ``hs`` and ``tp``. [-]

    Returns
    -------
    numpy.ndarray
        Spectral density. [m^2 s/rad]
    """
    if gamma is None:
        gamma = jonswap_gamma(hs, tp)
    w = np.asarray(omega, float)
    wp = 2.0 * math.pi / tp
    sigma = np.where(w <= wp, 0.07, 0.09)
    peak = gamma ** np.exp(-0.5 * ((w - wp) / (sigma * wp)) ** 2)
    return (1.0 - 0.287 * math.log(gamma)) * pierson_moskowitz(w, hs, tp) * peak


def table_spectrum(omega, table_omega, table_density):
    """A user spectrum: linear between the table's points, zero outside. [m^2 s/rad]"""
    return np.interp(np.asarray(omega, float), table_omega, table_density, left=0.0, right=0.0)


def cos2s_spreading(theta, s):
    """DNV's cos-2s directional spreading function D(theta - theta_0) (DNV-RP-C205 3.5.8.4). [1/rad]

    ``D = Gamma(s+1) / (2 sqrt(pi) Gamma(s+1/2)) cos^(2s)(theta / 2)`` for |theta| <= pi; integrates to 1.
    """
    th = np.asarray(theta, float)
    norm = math.exp(math.lgamma(s + 1.0) - math.lgamma(s + 0.5)) / (2.0 * math.sqrt(math.pi))
    return np.where(np.abs(th) <= math.pi, norm * np.abs(np.cos(0.5 * th)) ** (2.0 * s), 0.0)


def frequency_range(spectrum, wp, tail=TAIL_ENERGY):
    """The band [w_lo, w_hi] holding all but ``tail`` of a spectrum's energy (half each side). [rad/s]

    Found on a fine grid from 0.05 wp to 20 wp (Pierson-Moskowitz-like tails: the energy above w
    falls as w^-4).
    """
    w = np.linspace(0.05 * wp, 20.0 * wp, 40001)
    s = spectrum(w)
    c = np.concatenate(([0.0], np.cumsum(0.5 * (s[1:] + s[:-1]) * np.diff(w))))
    c /= c[-1]
    lo = float(np.interp(0.5 * tail, c, w))
    hi = float(np.interp(1.0 - 0.5 * tail, c, w))
    return lo, hi


@dataclass(frozen=True)
class SeaComponents:
    """The components of an irregular sea (linear superposition of Airy waves).

    ``eta(x, y, t) = sum_j a_j cos(k_j (x cos b_j + y sin b_j) - w_j t + p_j)``.

    Attributes
    ----------
    amplitude : numpy.ndarray
        Component amplitudes a_j. [m]
    omega : numpy.ndarray
        Angular frequencies w_j, increasing. [rad/s]
    wave_number : numpy.ndarray
        Wave numbers k_j from the dispersion relation. [rad/m]
    heading : numpy.ndarray
        Direction each component travels towards, from +X towards +Y. [rad]
    phase : numpy.ndarray
        Phases p_j. [rad]
    depth : float
        Water depth (inf: deep water). [m]
    gravity : float
        Acceleration of gravity. [m/s^2]
    mean_heading : float
        Mean direction of travel. [rad]
    band : float
        Width of the frequency bands dw. [rad/s]
    scale : float
        Factor applied to the amplitudes for sum a^2/2 = Hs^2/16 (1 for a table spectrum). [-]
    """

    amplitude: np.ndarray
    omega: np.ndarray
    wave_number: np.ndarray
    heading: np.ndarray
    phase: np.ndarray
    depth: float
    gravity: float
    mean_heading: float = 0.0
    band: float = 0.0
    scale: float = 1.0

    @property
    def m0(self) -> float:
        """Variance of the elevation, sum a_j^2 / 2. [m^2]"""
        return float(0.5 * np.sum(self.amplitude ** 2))

    def _spatial(self, x, y):
        kx = self.wave_number * np.cos(self.heading)
        ky = self.wave_number * np.sin(self.heading)
        return np.exp(1j * (np.multiply.outer(np.asarray(x, float), kx) + np.multiply.outer(np.asarray(y, float), ky)
                            + self.phase))

    def elevation(self, t, x=0.0, y=0.0):
        """Surface elevation at one point (x, y) at times ``t``, by direct summation. [m]"""
        t = np.asarray(t, float)
        e = self._spatial(x, y) * self.amplitude
        return np.real(np.exp(-1j * np.multiply.outer(t, self.omega)) @ e)

    def profiles(self, z):
        """Linear-theory depth profiles C = cosh(k (z + d)) / sinh(k d) ... as in :mod:`seacable.waves`.

        Returns ``(ch, sh)``, shape ``z.shape + (n,)``: ``g k / w^2 cosh(k (z + d)) / cosh(k d)`` and
        the same with sinh, ``z`` clamped to [-d, 0]. [-]
        """
        z = np.clip(np.asarray(z, float), -self.depth, 0.0)[..., None]
        k = self.wave_number
        d = self.depth
        kd = k * d
        deep = kd > 20.0
        with np.errstate(over="ignore", invalid="ignore"):
            e1 = np.exp(-2.0 * k * (z + d)) if math.isfinite(d) else np.zeros_like(z * k)
            ez = np.exp(k * z) / (1.0 + (np.exp(-2.0 * kd) if math.isfinite(d) else 0.0))
            ch_deep, sh_deep = ez * (1.0 + e1), ez * (1.0 - e1)
            kdf = np.where(deep, 1.0, kd)
            ckd = np.cosh(kdf)
            zz = z + (d if math.isfinite(d) else 0.0)
            ch_fin = np.cosh(k * np.where(deep, 0.0, zz)) / ckd
            sh_fin = np.sinh(k * np.where(deep, 0.0, zz)) / ckd
        ch = np.where(deep, ch_deep, ch_fin)
        sh = np.where(deep, sh_deep, sh_fin)
        f = self.gravity * k / self.omega ** 2
        return f * ch, f * sh

    def kinematics(self, t, x, y, z):
        """Velocity, local acceleration and elevation at points (x, y, z) at times ``t`` (direct sum).

        ``x, y, z`` broadcast together (points, shape P); ``t`` is 1-D (nt). ``z`` is taken in
        [-d, 0] (the caller stretches or clamps). Returns ``(vel, acc, eta)`` of shapes
        (nt, *P, 3), (nt, *P, 3) and (nt, *P). [m/s], [m/s^2], [m]
        """
        x, y, z = np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float), np.asarray(z, float))
        shape = x.shape
        x, y, z = x.ravel(), y.ravel(), z.ravel()
        t = np.atleast_1d(np.asarray(t, float))
        qr, qi = self.phasors(x, y, z)
        wt = np.multiply.outer(t, self.omega)
        out = (np.cos(wt) @ qr + np.sin(wt) @ qi).reshape(t.size, 7, -1)
        vel = np.moveaxis(out[:, :3], 1, -1).reshape((t.size, *shape, 3))
        acc = np.moveaxis(out[:, 3:6], 1, -1).reshape((t.size, *shape, 3))
        return vel, acc, out[:, 6].reshape((t.size, *shape))

    def phasors(self, x, y, z, planar: bool = False):
        """Real and imaginary parts ``(qr, qi)``, shape (n, 7 P), of the seven quantities' phasors at P points.

        For points (x, y, z) (1-D, z in [-d, 0]) the quantities (u, v, w, ax, ay, az, eta) at time t are
        ``cos(w t) @ qr + sin(w t) @ qi`` (``Re(Q exp(-i w t))``), with ``u_h = a w C cos(theta)``,
        ``w = a w S sin(theta)``, ``a_h = a w^2 C sin(theta)``, ``a_z = -a w^2 S cos(theta)``. With ``planar``
        (a long-crested sea, every component along one heading b): the four (u_h, w, a_h, a_z), shape (n, 4 P),
        of which u, v = u_h (cos b, sin b) and ax, ay = a_h (cos b, sin b).
        """
        E = self._spatial(x, y) * self.amplitude                      # (P, n)
        ch, sh = self.profiles(z)                                      # (P, n)
        w = self.omega
        uh = E * w * ch
        ah = -1j * E * w * w * ch
        if planar:
            Q = np.concatenate((uh, -1j * E * w * sh, ah, -E * w * w * sh)).T
            return np.ascontiguousarray(Q.real), np.ascontiguousarray(Q.imag)
        cb, sb = np.cos(self.heading), np.sin(self.heading)
        Q = np.concatenate((uh * cb, uh * sb, -1j * E * w * sh, ah * cb, ah * sb, -E * w * w * sh, E)).T
        return np.ascontiguousarray(Q.real), np.ascontiguousarray(Q.imag)


def synthesise(spectrum, *, n_components, omega_range, seed, heading=0.0, spreading=None, depth=None,
               gravity=STANDARD_GRAVITY, hs=None) -> SeaComponents:
    """Random-phase components of a spectrum (see the module docstring).

    Parameters
    ----------
    spectrum : callable
        ``S(omega)`` [m^2 s/rad].
    n_components : int
        Number of components (frequency bands).
    omega_range : tuple of float
        Band [w_lo, w_hi] divided into ``n_components`` equal bands. [rad/s]
    seed : int
        Seed of the random generator (frequencies in their bands, phases, directions).
    heading : float, optional
        Mean direction of travel. [rad]
    spreading : float or None, optional
        Exponent s of the cos-2s spreading; None for a long-crested sea. [-]
    depth : float or None, optional
        Water depth; None for deep water. [m]
    gravity : float, optional
        [m/s^2]
    hs : float or None, optional
        Scale the amplitudes so that sum a^2/2 = hs^2/16; None keeps the spectrum's level. [m]
    """
    rng = np.random.default_rng(seed)
    lo, hi = omega_range
    dw = (hi - lo) / n_components
    omega = lo + dw * (np.arange(n_components) + rng.uniform(0.0, 1.0, n_components))
    amp = np.sqrt(2.0 * spectrum(omega) * dw)
    phase = rng.uniform(0.0, 2.0 * math.pi, n_components)
    if spreading is None:
        head = np.full(n_components, float(heading))
    else:
        th = np.linspace(-math.pi, math.pi, 20001)
        cdf = np.concatenate(([0.0], np.cumsum(0.5 * (cos2s_spreading(th[1:], spreading)
                                                      + cos2s_spreading(th[:-1], spreading)) * np.diff(th))))
        cdf /= cdf[-1]
        head = heading + np.interp(rng.uniform(0.0, 1.0, n_components), cdf, th)
    scale = 1.0
    if hs is not None:
        m0 = 0.5 * float(np.sum(amp ** 2))
        scale = math.sqrt(hs ** 2 / 16.0 / m0) if m0 > 0 else 1.0
        amp = amp * scale
    d = math.inf if depth is None else float(depth)
    k = np.asarray(wave_number(2.0 * math.pi / omega, d, gravity), float)
    return SeaComponents(amplitude=amp, omega=omega, wave_number=k, heading=head, phase=phase, depth=d,
                         gravity=float(gravity), mean_heading=float(heading), band=dw, scale=scale)


def cutoff_depth(sea: SeaComponents, fraction=CUTOFF) -> float:
    """The depth below which the sea's horizontal velocity standard deviation ``sqrt(sum (a w C(z))^2 / 2)``
    is under ``fraction`` of its value at z = 0 (the seabed, -d, when it never is). [m]"""
    top = 60.0 / float(np.min(sea.wave_number))     # exp(-60): far below any fraction asked
    if math.isfinite(sea.depth):
        top = min(top, sea.depth)
    z = -np.linspace(0.0, top, 2001)
    # the levels from the top down, in blocks of 128, 256, ... levels, until one is below the fraction: the same
    # numbers as all 2001 levels at once (each level's profiles and sum are its own), a part of the work when the
    # waves die out part way down (the profiles were most of a mooring run's set-up and of validating a sweep)
    a_w = sea.amplitude * sea.omega
    start, size, sd0 = 0, 128, None
    while start < z.size:
        ch, _ = sea.profiles(z[start:start + size])
        sd = np.sqrt(np.sum((a_w * ch) ** 2, axis=-1))
        if sd0 is None:
            sd0 = sd[0]
        below = np.flatnonzero(sd < fraction * sd0)
        if below.size:
            return float(z[start + below[0]])
        start, size = start + size, 2 * size
    return -top


def significant(sea: SeaComponents, z_top: float, fraction=CUTOFF) -> SeaComponents:
    """The components that matter at and below depth ``z_top`` [m] (<= 0): the shortest ones are dropped
    while their velocity variance at ``z_top`` (``(a w C(z_top))^2 / 2`` each) adds up to less than
    ``fraction^2`` of the sea's there (a velocity error under ``fraction`` of its standard deviation).

    A model whose nodes all stay below ``z_top`` needs neither their kinematics (they decay as exp(k z)) nor
    their elevation (no node comes near the surface; with Wheeler stretching they shift the stretched depth
    by their few centimetres of amplitude), and the grid's steps follow the shortest component kept.
    """
    ch, _ = sea.profiles(np.array([min(z_top, 0.0)]))
    var = (sea.amplitude * sea.omega * ch[0]) ** 2
    order = np.argsort(sea.wave_number)[::-1]           # shortest first
    dropped = np.cumsum(var[order]) < fraction ** 2 * np.sum(var)
    keep = np.sort(order[~dropped])
    if keep.size == sea.omega.size:
        return sea
    return SeaComponents(amplitude=sea.amplitude[keep], omega=sea.omega[keep], wave_number=sea.wave_number[keep],
                         heading=sea.heading[keep], phase=sea.phase[keep], depth=sea.depth, gravity=sea.gravity,
                         mean_heading=sea.mean_heading, band=sea.band, scale=sea.scale)


def grid_size(sea: SeaComponents, t_end, box, z_min, per_period=20, per_wavelength=10, z_max=0.0, levels=None):
    """Grid counts (nt, nx, ny, nz) and steps (dt, dx, zc, zh) of :func:`kinematics_grid` (for a size check
    first), and the index i0 of its top level. ``levels``: the depth levels' (zc, zh), when not the sea's own
    (a depth band of :class:`SeaBands` takes those of the band on top)."""
    wmax = float(np.max(sea.omega))
    kmax = float(np.max(sea.wave_number))
    dt = 2.0 * math.pi / wmax / per_period
    nt = math.ceil(t_end / dt) + 2
    dx = 2.0 * math.pi / kmax / per_wavelength
    (x0, x1), (y0, y1) = box
    nx = max(math.ceil((x1 - x0) / dx) + 1, 1) if x1 > x0 else 1
    long_crested = bool(np.all(sea.heading == sea.mean_heading))
    ny = 1 if long_crested or y1 <= y0 else max(math.ceil((y1 - y0) / dx) + 1, 1)
    zc = 3.0 / kmax                         # top level spacing about 0.3 / k_max
    zh = 0.1                                # levels 10 % further apart each
    if levels is not None:
        zc, zh = levels
    depth_span = max(-z_min, 0.0)
    nz = math.ceil(math.log1p(depth_span / zc) / zh) + 2
    # the levels above z_max are left out: the level at or just above it is the top one
    i0 = min(math.floor(math.log1p(max(-z_max, 0.0) / zc) / zh), nz - 2)
    return (nt, nx, ny, nz - i0), (dt, dx, zc, zh), i0


@njit(cache=True)
def cos_sin(omega, t):
    """``[cos(w t), sin(w t)]`` (len(t), 2 len(w)). Times a constant step apart (a run's step grid) rotate the
    last row's pairs by ``w h`` (a product instead of a sine and a cosine of a large argument, a fifth of the
    cost), computed afresh every 32 rows and wherever the step changes. The step is taken from the times, whose
    rounding (ulp(t), 2e-12 s at 3 h) the 31 rotations accumulate: the phases err by at most 31 w ulp(t),
    1e-10 rad at 3 h (a motion's relative error of 1e-10)."""
    n, m = omega.size, t.size
    out = np.empty((m, 2 * n))
    ch, sh = np.empty(n), np.empty(n)
    h = math.nan
    for j in range(m):
        step = t[j] - t[j - 1] if j > 0 else math.nan
        if j % 32 == 0 or not abs(step - h) <= 1e-12 * max(abs(t[j]), 1.0):
            for k in range(n):
                out[j, k] = math.cos(omega[k] * t[j])
                out[j, n + k] = math.sin(omega[k] * t[j])
            if j > 0 and step != h:
                h = step
                for k in range(n):
                    ch[k] = math.cos(omega[k] * h)
                    sh[k] = math.sin(omega[k] * h)
        else:
            for k in range(n):
                c, s = out[j - 1, k], out[j - 1, n + k]
                out[j, k] = c * ch[k] - s * sh[k]
                out[j, n + k] = s * ch[k] + c * sh[k]
    return out


def _nearest_own(own, nx, ny):
    """For each column of an (nx, ny) grid, the (flat) index of the nearest column of ``own`` (itself when it is
    one)."""
    if np.all(own):
        return np.arange(own.size)
    if ny == 1:
        idx, c = np.flatnonzero(own), np.arange(nx)
        pos = np.searchsorted(idx, c)  # idx[pos - 1] < c <= idx[pos]
        left, right = idx[np.maximum(pos - 1, 0)], idx[np.minimum(pos, idx.size - 1)]
        return np.where(np.abs(c - left) <= np.abs(right - c), left, right)
    from scipy.ndimage import distance_transform_edt

    ix, iy = distance_transform_edt(~own.reshape(nx, ny), return_distances=False, return_indices=True)
    return (ix * ny + iy).ravel()


class SeaGrid:
    """The plan of an irregular sea's kinematics grid (see :func:`kinematics_grid`): its points and their
    phasors, computed once; :meth:`window` gives the packed array of the compiled kernel for a window of time.

    The packed array: the header (``GRID_HEADER`` values, ``S_*``), the column table (three values a column of
    the grid, columns ordered along then across the heading: the first and last of its levels that are computed,
    and the offset of its points, so that level l of the column is point ``offset + l``), the elevation
    (nt, nx, ny), and the kinematics (nt, points, nq): per point (u_h, w, a_h, a_z) along the heading b of a
    long-crested sea (nq = 4; u, v = u_h (cos b, sin b), and so the accelerations) or (u, v, w, ax, ay, az)
    (nq = 6). A level outside its column's band reads the band's edge value, as a point beyond the box reads
    the box's edge; a column given no levels of its own (-1 in ``columns``: no point comes near it) reads the
    nearest column's (and so its level offset), and holds that column's elevation (computed only where a point may
    look it up: a tenth of the cost of the elevation everywhere when a few lines reach the surface of a wide box).

    ``single``: the kinematics computed and stored in single precision (``S_SINGLE``; float32 pairs in the
    array's doubles): half the memory and half the time of the products. A value then errs by its rounding and
    that of its sum, at most ``2n`` units of 2^-24 of the sum of its ``2n`` terms' magnitudes and in practice
    about ``sqrt(2n)`` of them (3e-6 and 1e-6 of a w C summed over 100 components), three orders below the
    grid's interpolation error (1.2 % of the shortest component's, :func:`grid_point`). The elevation stays in
    double precision.
    """

    #: Values of the phasor matrices kept for the next window (beyond: computed again each window).
    KEEP_VALUES = 2 ** 23

    def __init__(self, sea: SeaComponents, box, z_min, *, stretching="none", per_period=20, per_wavelength=10,
                 z_max=0.0, columns=None, chunk=2048, single=False, levels=None, elevation=True):
        (_, nx, ny, nz), (dt, dx, zc, zh), i0 = grid_size(sea, 0.0, box, z_min, per_period, per_wavelength, z_max,
                                                          levels)
        self.sea, self.sizes, self.steps, self.chunk = sea, (nx, ny, nz), (dt, dx, zc, zh), chunk
        self.dtype = np.float32 if single else np.float64
        (x0, _), (y0, _) = box
        cb, sb = math.cos(sea.mean_heading), math.sin(sea.mean_heading)
        self.planar = bool(np.all(sea.heading == sea.mean_heading))
        self.nq = 4 if self.planar else 6
        head = np.zeros(GRID_HEADER)
        head[[S_MODE, S_DT, S_X0, S_DX, S_NX, S_Y0, S_DY, S_NY, S_COS, S_SIN, S_ZC, S_ZH, S_NZ, S_DEPTH, S_ZMIN,
              S_I0, S_NQ]] = (1.0, dt, x0, dx, nx, y0, dx, ny, cb, sb, zc, zh, nz, sea.depth, z_min, i0, self.nq)
        head[S_STRETCH] = 1.0 if stretching == "wheeler" else 0.0
        head[S_SINGLE] = 1.0 if single else 0.0
        own = np.ones(nx * ny, bool)
        if columns is None:
            lo, hi = np.zeros(nx * ny, int), np.full(nx * ny, nz - 1)
        else:
            cols = np.asarray(columns, int).reshape(nx * ny, 2)
            own = cols[:, 0] >= 0
            if not np.any(own):
                raise ValueError("a sea grid needs a column with levels of its own (all the columns are -1)")
            lo, hi = np.clip(cols[:, 0], 0, nz - 1), np.clip(cols[:, 1], 0, nz - 1)
            hi = np.maximum(hi, lo)
        count = np.where(own, hi - lo + 1, 0)
        start = np.concatenate(([0], np.cumsum(count)[:-1]))
        self.n_points = int(count.sum())
        head[S_NP] = self.n_points
        self.head = head
        share = _nearest_own(own, nx, ny)  # a column without levels of its own reads the nearest one's
        self.table = np.stack((lo[share], hi[share], (start - lo)[share]), axis=-1).astype(float).ravel()
        # the points, column after column, each column's levels lo..hi
        xi = x0 + dx * np.arange(nx)
        ze = y0 + dx * np.arange(ny)
        XI, ZE = np.meshgrid(xi, ze, indexing="ij")
        self.gx, self.gy = (XI * cb - ZE * sb).ravel(), (XI * sb + ZE * cb).ravel()  # columns' global x, y
        col = np.repeat(np.arange(nx * ny), count)
        lev = np.arange(self.n_points) - np.repeat(start, count) + np.repeat(lo, count)
        self.px, self.py = self.gx[col], self.gy[col]
        self.pz = np.maximum(-zc * np.expm1(zh * (i0 + lev)), -sea.depth)
        self._q = None
        self._buffer = np.empty(0)
        self._eta_q = None  # without the elevation (a depth band below the top one, whose is read): zeros
        # the elevation of the columns with levels of their own (a column without reads the nearest one's, as its
        # kinematics): a node looks its surface up only near the surface, where its column has levels
        self._eta_own = np.flatnonzero(own)
        self._eta_share = None if own.all() else np.searchsorted(self._eta_own, share)
        if elevation:
            cx, cy = self.gx[self._eta_own], self.gy[self._eta_own]
            E = sea._spatial(cx, cy) * sea.amplitude  # the columns' elevation phasors (columns, n)
            self._eta_q = np.ascontiguousarray(np.concatenate((E.real.T, E.imag.T)))  # [Re; Im] (2 n, columns)

    def _phasors(self, c0, c1):
        """Phasor matrix [qr; qi] (2 n, (c1 - c0) nq) of the points c0..c1 - 1, point after point."""
        sl = slice(c0, c1)
        qr, qi = self.sea.phasors(self.px[sl], self.py[sl], self.pz[sl], planar=self.planar)
        m = c1 - c0
        if not self.planar:
            qr, qi = qr[:, :6 * m], qi[:, :6 * m]  # the elevation's block is the columns' own
        n = qr.shape[0]
        q = np.concatenate((qr, qi)).reshape(2 * n, self.nq, m).transpose(0, 2, 1)
        return np.ascontiguousarray(q.reshape(2 * n, m * self.nq), dtype=self.dtype)

    def samples(self, t_start, t_end) -> int:
        """The times of a window from ``t_start`` to ``t_end`` [s] (:meth:`window`)."""
        return math.ceil((t_end - t_start) / self.steps[0]) + 2

    def packed_size(self, nt) -> int:
        """Values of the packed array of a window of ``nt`` times."""
        nx, ny, _ = self.sizes
        per = 2 if self.dtype == np.float32 else 1  # values a slot of the array holds
        return GRID_HEADER + 3 * nx * ny + nt * nx * ny + -(-nt * self.n_points * self.nq // per)

    def window(self, t_start, t_end, out=None) -> np.ndarray:
        """The packed array of the times ``t_start`` to ``t_end`` [s] (the grid's step; one more sample each
        side of the interval when it falls between samples). It lies in the memory of the last window, which it
        replaces: a window is valid until the next one is asked for (or in ``out``, of :meth:`packed_size`
        values, when given)."""
        nx, ny, _ = self.sizes
        dt = self.steps[0]
        nt = self.samples(t_start, t_end)
        ncol, npt, nq = nx * ny, self.n_points, self.nq
        o_eta = GRID_HEADER + 3 * ncol
        o_kin = o_eta + nt * ncol
        nkin = nt * npt * nq
        size = self.packed_size(nt)
        if out is not None:
            packed = out[:size]
        else:
            if self._buffer.size < size:
                self._buffer = np.empty(size)
            packed = self._buffer[:size]  # the last window's memory: no fresh pages to fault in each window
        packed[:GRID_HEADER] = self.head
        packed[S_T0], packed[S_NT] = t_start, nt
        packed[GRID_HEADER:o_eta] = self.table
        W = cos_sin(self.sea.omega, t_start + dt * np.arange(nt))  # (nt, 2 n): Re(Q exp(-i w t)) = W @ [qr; qi]
        if self._eta_q is None:
            packed[o_eta:o_kin] = 0.0
        elif self._eta_share is None:
            np.matmul(W, self._eta_q, out=packed[o_eta:o_kin].reshape(nt, ncol))
        else:
            np.take(W @ self._eta_q, self._eta_share, axis=1, out=packed[o_eta:o_kin].reshape(nt, ncol))
        packed[S_ETAMAX] = float(np.max(np.abs(packed[o_eta:o_kin]))) if ncol else 0.0
        W = W.astype(self.dtype, copy=False)
        kin = packed[o_kin:].view(self.dtype)[:nkin].reshape(nt, npt * nq)
        chunk = max(int(self.chunk), 1)
        spans = [(c0, min(c0 + chunk, npt)) for c0 in range(0, npt, chunk)]
        keep = 2 * self.sea.omega.size * npt * nq <= self.KEEP_VALUES
        if keep and self._q is None:
            self._q = [self._phasors(c0, c1) for c0, c1 in spans]
        for k, (c0, c1) in enumerate(spans):
            q = self._q[k] if keep else self._phasors(c0, c1)
            if len(spans) == 1:
                np.matmul(W, q, out=kin)
            else:
                kin[:, c0 * nq:c1 * nq] = W @ q
        return packed


class SeaBands:
    """A kinematics grid in depth bands: the :class:`SeaGrid` plans of :func:`depth_bands`' bands, the top one
    first, each band with the components that matter in it and its own steps in time and along the heading (the
    shortest of its components' period and wavelength over ``per_period`` and ``per_wavelength``, below the top
    band ``BAND_REFINE`` times those), and all with
    the top band's depth levels. A band's header holds the depth down to which it serves (``S_ZMIN``; the last
    band's: the grid's deepest point, below it no wave kinematics) and the offset of the next band
    (``S_NEXT``); :func:`grid_point` and :func:`grid_points` take a point's values from the band of its depth,
    :func:`grid_eta` the elevation from the top band (all of its components, over the whole box; the others' plans
    are made without it, ``elevation=False``). One band is :class:`SeaGrid`'s array as it stands.

    Against the direct sum a point's values then err by at most its band's interpolation bound (the
    multilinear one of :func:`kinematics_grid` with the band's steps: ``(w dt)^2 / 8 + (k dx)^2 / 8 +
    (k dz)^2 / 8`` of each component's amplitude at the cell's top) plus the amplitudes of the components its
    band leaves out, which together carry under ``fraction`` of the standard deviation of the sea's
    acceleration, and so of its velocity, at the band's top and, as the shorter waves decay faster, below it
    (:func:`depth_bands`).
    """

    def __init__(self, plans):
        self.plans = list(plans)
        self._buffer = np.empty(0)

    @property
    def n_points(self) -> int:
        """Points of the grid (all bands) at each time."""
        return sum(p.n_points for p in self.plans)

    def window(self, t_start, t_end) -> np.ndarray:
        """The packed array of the bands' windows (:meth:`SeaGrid.window`), one after the other: the top band's
        of ``t_start`` to ``t_end`` [s], and the others' of the times it covers (its last sample's too). It lies
        in the memory of the last window, valid until the next one is asked for."""
        first = self.plans[0]
        nt0 = first.samples(t_start, t_end)
        end = t_start + first.steps[0] * (nt0 - 1)
        nts = [nt0] + [p.samples(t_start, end) for p in self.plans[1:]]
        sizes = [p.packed_size(nt) for p, nt in zip(self.plans, nts)]
        total = sum(sizes)
        if self._buffer.size < total:
            self._buffer = np.empty(total)
        packed = self._buffer[:total]
        o = 0
        for b, (plan, size) in enumerate(zip(self.plans, sizes)):
            part = plan.window(t_start, t_end if b == 0 else end, out=packed[o:o + size])
            part[S_NEXT] = size if b + 1 < len(self.plans) else 0.0
            o += size
        return packed


def _band_kept(sea: SeaComponents, z, fraction):
    """The number of components (the longest, in order of wave number) that matter at each depth of ``z`` [m]:
    the shortest are left out while their acceleration variance there (``(a w^2 C(z))^2 / 2`` horizontally,
    with S vertically) adds up to less than ``fraction^2`` of the sea's, in both directions; and the order."""
    ch, sh = sea.profiles(np.asarray(z, float))
    order = np.argsort(sea.wave_number)[::-1]  # shortest first
    a2 = sea.amplitude[order] * sea.omega[order] ** 2
    kept = np.zeros(np.shape(z), int)
    for prof in (ch, sh):
        var = (a2 * prof[..., order]) ** 2
        small = np.cumsum(var, axis=-1) < fraction ** 2 * np.sum(var, axis=-1, keepdims=True)
        kept = np.maximum(kept, sea.omega.size - np.sum(small, axis=-1))
    return np.maximum(kept, 1), order


def _subset(sea: SeaComponents, keep) -> SeaComponents:
    keep = np.sort(keep)
    return SeaComponents(amplitude=sea.amplitude[keep], omega=sea.omega[keep], wave_number=sea.wave_number[keep],
                         heading=sea.heading[keep], phase=sea.phase[keep], depth=sea.depth, gravity=sea.gravity,
                         mean_heading=sea.mean_heading, band=sea.band, scale=sea.scale)


def depth_bands(sea: SeaComponents, z_top, z_bottom, fraction=CUTOFF, ratio=BAND_RATIO):
    """The depth bands of a banded kinematics grid (:class:`SeaBands`) from ``z_top`` down to ``z_bottom`` [m]:
    ``[(z_b, sea_b)]``, band b from depth z_b (the first: ``z_top``, with all of ``sea``) down to the next's.

    A band begins where the components that matter (:func:`_band_kept`: those left out carry under
    ``fraction`` of the standard deviation of the acceleration there, and so of the velocity, as they are the
    shortest and fastest) have their shortest wave number at most ``1 / ratio`` of the band above's, and holds
    those components: a grid twice as coarse in space (and 1.4 times in time). Each component's share decays
    with depth faster the shorter it is (``cosh(k (z + d))``, ``sinh``), so what a band leaves out stays under
    ``fraction`` below its top too.
    """
    bands = [(float(z_top), sea)]
    if not z_bottom < z_top or sea.omega.size < 2:
        return bands
    z = np.linspace(z_top, z_bottom, 513)
    kept, order = _band_kept(sea, z, fraction)
    k_sorted = sea.wave_number[order]  # shortest first
    kmax = k_sorted[sea.omega.size - kept]  # the shortest kept at each depth
    top = float(np.max(sea.wave_number))
    while True:
        below = np.flatnonzero(kmax <= top / ratio)
        if not below.size or kept[below[0]] < 1:
            return bands
        i = below[0]
        if z[i] <= z_bottom:
            return bands
        band = _subset(sea, order[sea.omega.size - kept[i]:])
        bands.append((float(z[i]), band))
        top = float(kmax[i])


def kinematics_grid(sea: SeaComponents, t_end, box, z_min, *, t_start=0.0, stretching="none", per_period=20,
                    per_wavelength=10, chunk=2048, z_max=0.0, columns=None, single=False):
    """The packed sea array of the compiled kernel: kinematics of ``sea`` on a grid (see :func:`grid_point`
    and :class:`SeaGrid`, which keeps the points' phasors for the windows of a long run).

    Time from ``t_start`` to ``t_end`` [s] (step: the shortest component period / ``per_period``); along and
    across the mean heading over ``box`` ((xi0, xi1), (zeta0, zeta1)) [m] in the rotated coordinates
    ``xi = x cos b + y sin b``, ``zeta = -x sin b + y cos b`` (step: the shortest wavelength /
    ``per_wavelength``; one point across for a long-crested sea, whose field does not vary across); in
    depth from z = 0 (or the level at or just above ``z_max`` [m], when the points all lie below it) down to
    ``z_min`` [m] on levels ``z = -c (exp(i h) - 1)`` (spacing 0.3 / k_max at the surface, 10 % more at each
    level; a point above the top level gets its values, as a point beyond the horizontal edges gets the
    edge's). ``columns`` (nx, ny, 2), when given, holds for each column of the grid the first and last of its
    levels (indices from the top one, inclusive) that points can reach: only those are computed and stored,
    and the levels above and below read the values of the first and last (the band's edges, as the box's).
    Linear interpolation between grid points errs by at most ``(2 pi / per_period)^2 / 8`` (1.2 % at 20
    points a period) of the shortest component. ``single``: the kinematics in single precision (:class:`SeaGrid`).
    """
    plan = SeaGrid(sea, box, z_min, stretching=stretching, per_period=per_period,
                   per_wavelength=per_wavelength, z_max=z_max, columns=columns, chunk=chunk, single=single)
    return plan.window(t_start, t_end)


def no_sea(stretching="none"):
    """The packed sea array without an irregular sea (the regular wave's stretching flag only)."""
    head = np.zeros(GRID_HEADER)
    head[S_STRETCH] = 1.0 if stretching == "wheeler" else 0.0
    return head


@njit(cache=True)
def _cell(v, v0, h, n):
    """Index and weight of v on a uniform axis v0 + i h (i < n), clamped to its ends."""
    if n <= 1:
        return 0, 0.0
    s = (v - v0) / h
    if s <= 0.0:
        return 0, 0.0
    if s >= n - 1:
        return n - 2, 1.0
    i = int(s)
    return i, s - i


@njit(cache=True)
def _plan_cells(sea, x, y, t, b=0):
    """The grid's sizes (nt, nx, ny) and the cells and fractions of time ``t`` and of the point (x, y) in the
    grid's axes along and across the sea's heading: ``(nt, nx, ny, it, ft, ix, fx, iy, fy)``; of the depth band
    whose header is at ``b`` (:class:`SeaBands`)."""
    cb, sb = sea[b + S_COS], sea[b + S_SIN]
    nt, nx, ny = int(sea[b + S_NT]), int(sea[b + S_NX]), int(sea[b + S_NY])
    it, ft = _cell(t, sea[b + S_T0], sea[b + S_DT], nt)
    ix, fx = _cell(x * cb + y * sb, sea[b + S_X0], sea[b + S_DX], nx)
    iy, fy = _cell(-x * sb + y * cb, sea[b + S_Y0], sea[b + S_DY], ny)
    return nt, nx, ny, it, ft, ix, fx, iy, fy


@njit(cache=True)
def _band_of(sea, zs):
    """The offset of the header of the depth band (:class:`SeaBands`) that holds the linear-theory depth ``zs``
    [m], or -1 below the grid's deepest point (no wave kinematics)."""
    b = 0
    while zs < sea[b + S_ZMIN]:
        step = int(sea[b + S_NEXT])
        if step <= 0:
            return -1
        b += step
    return b


@njit(cache=True)
def grid_eta(sea, x, y, t):
    """Surface elevation of the packed grid at (x, y, t) (multilinear; clamped at the grid's edges). [m]"""
    _, nx, ny, it, ft, ix, fx, iy, fy = _plan_cells(sea, x, y, t)
    o = GRID_HEADER + 3 * nx * ny
    s = 0.0
    for a in range(2):
        wa = ft if a else 1.0 - ft
        if wa == 0.0:
            continue
        for b in range(2):
            wb = fx if b else 1.0 - fx
            if wb == 0.0:
                continue
            for c in range(2):
                wc = fy if c else 1.0 - fy
                if wc == 0.0:
                    continue
                s += wa * wb * wc * sea[o + ((it + a) * nx + ix + b) * ny + iy + c]
    return s


@njit(cache=True)
def _trilinear(data, r, q, ft, fx, fz, a00, a01, a10, a11, j):
    """Value ``j`` of a point, multilinear in time (rows ``r`` and ``r + q`` of ``data``), along the heading
    (columns at offsets ``a0*`` and ``a1*``) and in depth (levels ``a*0`` and ``a*1``)."""
    return ((1.0 - ft) * ((1.0 - fx) * ((1.0 - fz) * data[r + a00 + j] + fz * data[r + a01 + j])
                          + fx * ((1.0 - fz) * data[r + a10 + j] + fz * data[r + a11 + j]))
            + ft * ((1.0 - fx) * ((1.0 - fz) * data[r + q + a00 + j] + fz * data[r + q + a01 + j])
                    + fx * ((1.0 - fz) * data[r + q + a10 + j] + fz * data[r + q + a11 + j])))


@njit(cache=True)
def grid_points(sea, X, zs, t, out):
    """:func:`grid_point` at the points ``(X[k, 0], X[k, 1])`` and linear-theory depths ``zs[k]`` (NaN: none,
    zeros) at time ``t``, into ``out[k, 0:6]``: the same values. A long-crested sea in single precision (a run's
    grid) takes its own loop: the time's cell found once, each point's eight corners read without branches."""
    ny, nq = int(sea[S_NY]), int(sea[S_NQ])
    if ny != 1 or nq != 4 or sea[S_SINGLE] <= 0.0:
        for k in range(zs.size):
            if math.isnan(zs[k]):
                out[k, 0] = out[k, 1] = out[k, 2] = out[k, 3] = out[k, 4] = out[k, 5] = 0.0
            else:
                out[k, 0], out[k, 1], out[k, 2], out[k, 3], out[k, 4], out[k, 5] = grid_point(
                    sea, X[k, 0], X[k, 1], zs[k], t)
        return
    if sea[S_NEXT] <= 0.0:  # one band
        _points_band(sea, 0, X, zs, t, out, np.arange(zs.size))
        return
    # depth bands (SeaBands): each point to its band's (below the deepest: the last, which gives it zeros)
    last = 0
    while sea[last + S_NEXT] > 0.0:
        last += int(sea[last + S_NEXT])
    band = np.empty(zs.size, np.int64)
    for k in range(zs.size):
        bk = _band_of(sea, zs[k])
        band[k] = last if bk < 0 else bk
    b = 0
    while True:
        _points_band(sea, b, X, zs, t, out, np.flatnonzero(band == b))
        if b == last:
            return
        b += int(sea[b + S_NEXT])


@njit(cache=True)
def _points_band(sea, b, X, zs, t, out, which):
    """:func:`grid_points` of the points ``which`` in a long-crested single-precision grid's depth band at ``b``
    (:class:`SeaBands`), all of whose points it holds (the last band: zeros below its deepest point)."""
    nt, nx = int(sea[b + S_NT]), int(sea[b + S_NX])
    cb, sb = sea[b + S_COS], sea[b + S_SIN]
    nz, npt = int(sea[b + S_NZ]), int(sea[b + S_NP])
    it, ft = _cell(t, sea[b + S_T0], sea[b + S_DT], nt)
    data = sea.view(np.float32)
    q = 4 * npt  # floats a time
    r = 2 * (b + GRID_HEADER + 3 * nx + nt * nx) + it * q
    zmin, x0, dx, zc, zh, i0 = sea[b + S_ZMIN], sea[b + S_X0], sea[b + S_DX], sea[b + S_ZC], sea[b + S_ZH], sea[b + S_I0]
    for k in which:
        z = zs[k]
        if not z >= zmin:  # below the grid (no waves) or NaN
            out[k, 0] = out[k, 1] = out[k, 2] = out[k, 3] = out[k, 4] = out[k, 5] = 0.0
            continue
        ix, fx = _cell(X[k, 0] * cb + X[k, 1] * sb, x0, dx, nx)
        iz, fz = _cell(math.log1p(max(-z, 0.0) / zc) / zh, i0, 1.0, nz)
        c0 = b + GRID_HEADER + 3 * ix
        c1 = b + GRID_HEADER + 3 * min(ix + 1, nx - 1)
        lo0, hi0, off0 = int(sea[c0]), int(sea[c0 + 1]), int(sea[c0 + 2])
        lo1, hi1, off1 = int(sea[c1]), int(sea[c1 + 1]), int(sea[c1 + 2])
        a00 = 4 * (off0 + min(max(iz, lo0), hi0))
        a01 = 4 * (off0 + min(max(iz + 1, lo0), hi0))
        a10 = 4 * (off1 + min(max(iz, lo1), hi1))
        a11 = 4 * (off1 + min(max(iz + 1, lo1), hi1))
        uh = _trilinear(data, r, q, ft, fx, fz, a00, a01, a10, a11, 0)
        ah = _trilinear(data, r, q, ft, fx, fz, a00, a01, a10, a11, 2)
        out[k, 0], out[k, 1] = uh * cb, uh * sb
        out[k, 2] = _trilinear(data, r, q, ft, fx, fz, a00, a01, a10, a11, 1)
        out[k, 3], out[k, 4] = ah * cb, ah * sb
        out[k, 5] = _trilinear(data, r, q, ft, fx, fz, a00, a01, a10, a11, 3)


@njit(cache=True)
def _kin(sea, half, single, p):
    """The grid's kinematic value at ``p``: a float of ``half`` (the array's floats) when ``single``, else of
    ``sea``."""
    return np.float64(half[p]) if single else sea[p]


@njit(cache=True)
def grid_point(sea, x, y, zs, t):
    """Kinematics of the packed grid at (x, y) and linear-theory depth ``zs`` (<= 0) at time ``t``.

    Returns ``(u, v, w, ax, ay, az)`` [m/s], [m/s^2]: multilinear in t, xi, zeta and the depth
    level's index; clamped at the grid's horizontal and time edges and at each column's band of levels
    (:class:`SeaGrid`). Below the grid's deepest point (``sea[S_ZMIN]``, :func:`cutoff_depth` or the seabed)
    the waves' kinematics are neglected: zeros.
    """
    ob = _band_of(sea, zs)
    if ob < 0:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    nt, nx, ny, it, ft, ix, fx, iy, fy = _plan_cells(sea, x, y, t, ob)
    nz = int(sea[ob + S_NZ])
    nq = int(sea[ob + S_NQ])
    npt = int(sea[ob + S_NP])
    # depth level: z = -c (exp(s h) - 1) -> s = log1p(-z / c) / h, counted from the top level's i0
    zlev = math.log1p(max(-zs, 0.0) / sea[ob + S_ZC]) / sea[ob + S_ZH]
    iz, fz = _cell(zlev, sea[ob + S_I0], 1.0, nz)
    oc = ob + GRID_HEADER
    o = ob + GRID_HEADER + 3 * nx * ny + nt * nx * ny
    single = sea[ob + S_SINGLE] > 0.0
    half = sea.view(np.float32)  # single precision: the kinematics' floats, two a slot from the slot o on
    if single:
        o *= 2
    u = v = w = ax = ay = az = 0.0
    for a in range(2):
        wa = ft if a else 1.0 - ft
        if wa == 0.0:
            continue
        row = o + (it + a) * npt * nq
        for b in range(2):
            wb = fx if b else 1.0 - fx
            if wb == 0.0:
                continue
            for c in range(2):
                wc = fy if c else 1.0 - fy
                if wc == 0.0:
                    continue
                col = oc + 3 * ((ix + b) * ny + iy + c)
                lo, hi, off = int(sea[col]), int(sea[col + 1]), int(sea[col + 2])
                # the two levels around the point, each clamped to the column's band
                p0 = row + (off + min(max(iz, lo), hi)) * nq
                p1 = row + (off + min(max(iz + 1, lo), hi)) * nq
                f = wa * wb * wc
                f0, f1 = f * (1.0 - fz), f * fz
                if nq == 4:
                    u += f0 * _kin(sea, half, single, p0) + f1 * _kin(sea, half, single, p1)
                    w += f0 * _kin(sea, half, single, p0 + 1) + f1 * _kin(sea, half, single, p1 + 1)
                    ax += f0 * _kin(sea, half, single, p0 + 2) + f1 * _kin(sea, half, single, p1 + 2)
                    az += f0 * _kin(sea, half, single, p0 + 3) + f1 * _kin(sea, half, single, p1 + 3)
                else:
                    u += f0 * _kin(sea, half, single, p0) + f1 * _kin(sea, half, single, p1)
                    v += f0 * _kin(sea, half, single, p0 + 1) + f1 * _kin(sea, half, single, p1 + 1)
                    w += f0 * _kin(sea, half, single, p0 + 2) + f1 * _kin(sea, half, single, p1 + 2)
                    ax += f0 * _kin(sea, half, single, p0 + 3) + f1 * _kin(sea, half, single, p1 + 3)
                    ay += f0 * _kin(sea, half, single, p0 + 4) + f1 * _kin(sea, half, single, p1 + 4)
                    az += f0 * _kin(sea, half, single, p0 + 5) + f1 * _kin(sea, half, single, p1 + 5)
    if nq == 4:  # along the heading: its components
        cb, sb = sea[ob + S_COS], sea[ob + S_SIN]
        return u * cb, u * sb, w, ax * cb, ax * sb, az
    return u, v, w, ax, ay, az

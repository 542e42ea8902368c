"""Statics, pushover and time stepping of a mooring :class:`~seacable.mooring.network.Network`.

:class:`MooringModel` binds a network to its water (density, gravity, current, waves, seabed) and
holds the arrays the compiled kernel needs. :func:`static_equilibrium` finds the rest shape,
:func:`pushover` the force-excursion curve, :func:`simulate` the response to prescribed fairlead
motion (the generalised-alpha method with Newton iterations at each step; by default its
special case without numerical damping, Newmark's average acceleration, beta 1/4, gamma 1/2).
"""

from __future__ import annotations

import math
import sys
import time as _time
import warnings
from collections.abc import Callable
from dataclasses import InitVar, dataclass, field, replace

import numpy as np

from .._atomic import deferred_interrupts
from ..errors import ConvergenceError, InputError, SeacableWarning
from ..seastate import SeaBands, SeaGrid, no_sea

#: Largest irregular-sea grid held at once (values, 8 bytes each); a longer run takes it in time windows.
SEA_WINDOW_VALUES = 2.5e7
#: Values (16 MB) of a block of outputs of :func:`simulate` given ``on_outputs`` (see there).
BLOCK_VALUES = 2**21
from . import kernel as K
from ._alpha import generalized_alpha
from .checks import check_network, seabed_hold_hint
from .network import FREE, PRESCRIBED, Network

__all__ = [
    "MooringModel",
    "MooringRun",
    "StaticState",
    "Water",
    "generalized_alpha",
    "line_end_nodes",
    "pushover",
    "recommended_time_step",
    "simulate",
    "static_equilibrium",
    "wave_number_or_zero",
]


@dataclass(frozen=True)
class Water:
    """The water around a mooring: density, gravity, seabed, current and regular waves (all SI).

    ``depth`` None means no seabed. The seabed plane passes through (0, 0, -depth) and rises
    towards +x at ``slope`` [rad]. ``seabed_stiffness`` [Pa/m] and ``seabed_damping`` [Pa s/m] act
    per unit of projected area (diameter times length); ``friction`` is Coulomb's coefficient,
    regularised below ``friction_velocity`` [m/s]. ``current_depths`` (>= 0, increasing) and
    ``current_speeds`` give a profile towards ``current_heading``. Waves: ``wave_height`` (crest to
    trough), ``wave_period``, ``wave_heading``, ``wave_phase``; an irregular sea ``sea``
    (:class:`seacable.seastate.SeaComponents`, its kinematics precomputed on a grid by
    :meth:`MooringModel.prepare_sea`); ``stretching`` the kinematics above the still-water level
    ("none": the z = 0 values, "wheeler": Wheeler stretching). ``rayleigh_mass`` is the
    mass-proportional Rayleigh coefficient [1/s]. ``slack_damping``: the elements' axial damper
    ``c dl/dt / L`` also acts when they are slack (MoorDyn's rule, set for MoorDyn decks; False: only
    in taut elements, with the tension-only spring). ``full_seabed_damping``: the seabed damper acts with
    the whole ``seabed_damping`` on a node pressed into the seabed beyond the contact spring's rounding
    band (where the spring is linear), rounded with the spring's slope inside it (MoorDyn's rule, set for
    MoorDyn decks: ``(kBot pen - cBot v_n) d l``); False: it engages gradually, as ``q / (q + b)`` of the
    rounded penetration ``q`` and the band ``b`` (two thirds of it at a node's static penetration ``2 b``).
    ``compression``: the elements of linear EA carry compression too, ``EA eps`` for ``eps < 0`` (a cable with
    bending stiffness, a beam; False: tension only, MoorDyn's rule). ``profile``: the seabed's depths along X
    instead of the plane, ``(distances, depths)`` [m]. ``grid``: the seabed on an x, y grid instead
    (:class:`seacable.bathymetry.SeabedGrid`; ``depth`` then the water depth at the origin, for the waves).
    """

    density: float = 1025.0
    gravity: float = 9.80665
    depth: float | None = None
    slope: float = 0.0
    seabed_stiffness: float = 3.0e6
    seabed_damping: float = 3.0e5
    friction: float = 0.0
    friction_velocity: float = 0.01
    current_depths: tuple[float, ...] = (0.0,)
    current_speeds: tuple[float, ...] = (0.0,)
    current_heading: float = 0.0
    wave_height: float = 0.0
    wave_period: float = 10.0
    wave_heading: float = 0.0
    wave_phase: float = 0.0
    rayleigh_mass: float = 0.0
    sea: object = field(default=None, compare=False)  # an irregular sea (seastate.SeaComponents) or None
    stretching: str = "none"      # kinematics above z = 0: "none" (constant) or "wheeler"
    slack_damping: bool = False   # the axial damper acts in slack elements too (MoorDyn's rule)
    full_seabed_damping: bool = False  # the seabed damper in full on a node pressed in (MoorDyn's rule)
    # a seabed profile along X instead of the plane: (distances [m], depths [m]), linear between, level beyond
    profile: tuple | None = None
    compression: bool = False  # the elements of linear EA carry compression too (a cable as a beam: E_COMPRESS)
    grid: object = None  # a seabed grid over x, y instead of the plane (seacable.bathymetry.SeabedGrid)

    @property
    def tabulated(self) -> bool:
        """Whether the seabed is a profile or a grid (not the plane of ``depth`` and ``slope``)."""
        return self.profile is not None or self.grid is not None

    def env_vector(self, bed_ramp: float = 1e-3) -> np.ndarray:
        m = 0 if self.profile is None else len(self.profile[0])
        block = None if self.grid is None else self.grid.env_block()
        env = np.zeros(K.ENV_SIZE + (2 * m if block is None else block.size))
        if m:
            env[K.E_BEDTAB] = m
            env[K.ENV_SIZE:K.ENV_SIZE + m] = self.profile[0]
            env[K.ENV_SIZE + m:] = -np.asarray(self.profile[1], float)
        if block is not None:  # the grid: -nx, ny, then its lines and elevations (kernel.grid_at)
            env[K.E_BEDTAB], env[K.E_BEDNY] = -self.grid.x.size, self.grid.y.size
            env[K.ENV_SIZE:] = block
        depth = math.inf if self.depth is None else float(self.depth)
        env[[K.E_RHO, K.E_G, K.E_DEPTH, K.E_SLOPE]] = self.density, self.gravity, depth, self.slope
        env[[K.E_KBOT, K.E_CBOT, K.E_MU, K.E_VFRIC]] = (self.seabed_stiffness, self.seabed_damping, self.friction,
                                                        self.friction_velocity)
        env[[K.E_WH, K.E_WT, K.E_WK, K.E_WHEAD, K.E_WPHASE]] = (
            self.wave_height, self.wave_period, wave_number_or_zero(self), self.wave_heading, self.wave_phase)
        env[[K.E_CHEAD, K.E_ALPHA, K.E_WDEPTH]] = self.current_heading, self.rayleigh_mass, depth
        env[K.E_BEDRAMP] = bed_ramp
        env[K.E_VDT] = math.inf  # viscoelastic elements at their static stiffness unless a time step says
        env[K.E_SLACKDAMP] = float(bool(self.slack_damping))
        env[K.E_BEDFULL] = float(bool(self.full_seabed_damping))
        env[K.E_COMPRESS] = float(bool(self.compression))
        return env

    def seabed_z(self, x, y=None) -> np.ndarray:
        """Seabed elevation under ``x`` (and ``y``, on a grid: 0 if not given) (NaN without a seabed). [m]"""
        x = np.asarray(x, float)
        if self.grid is not None:
            return self.grid.at(x, np.zeros_like(x) if y is None else np.asarray(y, float))[0]
        if self.profile is not None:
            return -np.interp(x, self.profile[0], self.profile[1])
        if self.depth is None:
            return np.full_like(x, np.nan)
        return -self.depth + np.tan(self.slope) * x


def _sea_columns(xi, ze, z, box, dx, sizes, levels, pad, depths=None):
    """The band of levels (first, last; from the grid's top level, inclusive) of each column of the sea's grid
    (nx, ny, 2) that the points (``xi``, ``ze`` along and across the heading, ``z`` [m]) can reach: from the
    highest to the lowest of the points within ``pad`` [m] of the column horizontally, widened by ``pad`` up and
    down (the box's own margin, :meth:`MooringModel.prepare_sea`); one level where no point comes near.

    ``depths`` (top, bottom) [m], a depth band's (:class:`seacable.seastate.SeaBands`): a column none of whose
    points (so widened) reaches the band is marked (-1, -1), none of its own (:class:`seacable.seastate.SeaGrid`
    gives it the nearest column's), unless no column reaches it."""
    from scipy.ndimage import maximum_filter, minimum_filter

    (x0, _), (y0, _) = box
    nx, ny, nz = sizes
    zc, zh, i0 = levels
    ix = np.clip(np.rint((xi - x0) / dx).astype(int), 0, nx - 1)
    iy = np.clip(np.rint((ze - y0) / dx).astype(int), 0, ny - 1) if ny > 1 else np.zeros(xi.size, int)
    high, low = np.full((nx, ny), -np.inf), np.full((nx, ny), np.inf)
    np.maximum.at(high, (ix, iy), z)
    np.minimum.at(low, (ix, iy), z)
    reach = 2 * math.ceil(pad / dx) + 3  # the columns within pad (and the cell's own width) each side
    size = (reach, reach if ny > 1 else 1)
    high = maximum_filter(high, size=size, mode="constant", cval=-np.inf)
    low = minimum_filter(low, size=size, mode="constant", cval=np.inf)

    def level(zv):
        return np.log1p(np.maximum(-zv, 0.0) / zc) / zh - i0

    near = np.isfinite(high)
    # a point between levels s and s + 1 interpolates between them: the band holds both of its ends' cells
    first = np.where(near, np.floor(level(np.minimum(np.where(near, high, 0.0) + pad, 0.0))) - 1, 0)
    last = np.where(near, np.ceil(level(np.where(near, low, 0.0) - pad)) + 1, 0)
    out = np.clip(np.stack((first, last), axis=-1), 0, nz - 1).astype(int)
    if depths is not None:
        top, bottom = depths
        reach = near & (high + pad >= bottom) & (low - pad <= top)
        if np.any(reach):
            out[~reach] = -1
    return out


def wave_number_or_zero(water: Water) -> float:
    if water.wave_height <= 0.0:
        return 0.0
    from ..waves import wave_number

    return float(wave_number(water.wave_period, water.depth, water.gravity))


@dataclass
class MooringModel:
    """A network in its water, with the kernel's arrays (free nodes ordered for a narrow band).

    ``checked`` (keyword): the network's start was checked already (:func:`seacable.mooring.checks.check_network`,
    which the model otherwise runs), as when it is a checked network's only line renumbered."""

    network: Network
    water: Water
    fidx: np.ndarray = field(init=False)
    nfree: int = field(init=False)
    bw: int = field(init=False)
    checked: InitVar[bool] = False

    def __post_init__(self, checked):
        net = self.network
        if not checked:
            check_network(net, depth=self.water.depth, slope=self.water.slope, profile=self.water.profile,
                          grid=self.water.grid)
        free = np.flatnonzero(net.kind == FREE)
        order = _band_order(net, free)
        self.fidx = np.full(net.n_nodes, -1, np.int64)
        self.fidx[order] = np.arange(len(order))
        self.nfree = len(order)
        el = net.elements
        both = (self.fidx[el[:, 0]] >= 0) & (self.fidx[el[:, 1]] >= 0)
        gap = int(np.max(np.abs(self.fidx[el[both, 0]] - self.fidx[el[both, 1]]), initial=0))
        # bending couples each inner node's two neighbours: the band holds them (a truss: no hinges)
        self.hinges, self.hinge_ei = net.hinge_arrays()
        for j, k in ((0, 1), (1, 2), (0, 2)):
            fj, fk = self.fidx[self.hinges[:, j]], self.fidx[self.hinges[:, k]]
            ok = (fj >= 0) & (fk >= 0)
            gap = max(gap, int(np.max(np.abs(fj[ok] - fk[ok]), initial=0)))
        self.bw = 3 * gap + 2
        bedc = np.zeros(net.n_nodes)
        half = 0.5 * net.diameter * net.length
        np.add.at(bedc, el[:, 0], half)
        np.add.at(bedc, el[:, 1], half)
        self.bedc = bedc
        self.weight = net.node_weight()
        # buoyancy the weight in water holds, given back above the surface: per length of each element and
        # of each attachment (weight in air minus weight in water) [N/m], [N]
        g = self.water.gravity
        self.buoyancy = net.mass_per_length * g - net.weight_per_length
        self.point_buoyancy = net.point_mass * g - net.point_weight
        # seabed damper ramp: half the mean static penetration of a node under its own weight
        if self.water.seabed_stiffness > 0 and np.any(bedc > 0):  # no elements (bodies alone): no ramp
            sink = np.abs(self.weight) / (self.water.seabed_stiffness * np.maximum(bedc, 1e-300))
            ramp = 0.5 * float(np.median(sink[bedc > 0]))
        else:
            ramp = 1e-3
        self.env = self.water.env_vector(max(ramp, 1e-9))
        self.sea = no_sea(self.water.stretching)  # the kernel's packed irregular sea (prepare_sea fills it)
        self._sea_spec = None
        self.cur_depth = np.asarray(self.water.current_depths, float)
        self.cur_speed = np.asarray(self.water.current_speeds, float)
        # strain-tension tables (lo, hi, strain, tension) of the elements that have one
        self.tension_strain = net.tension_strain_arrays()
        # viscoelastic elements: parameters and the slow stretch (kernel.V_*), no rows when there are none
        # and Syrope ropes: their working curve and largest mean tension so far (kernel.syrope_tension)
        self.visco = np.zeros((0, K.V_SIZE))
        syrope = getattr(net, "element_syrope", None)
        if net.element_viscoelastic is not None or syrope is not None:
            self.visco = np.zeros((net.n_elements, K.V_SIZE))
        if net.element_viscoelastic is not None:
            self.visco[:, [K.V_EAD, K.V_LM, K.V_BAD]] = net.element_viscoelastic
        if syrope is not None:
            self.visco[:, [K.V_WC, K.V_K1, K.V_K2, K.V_TM0]] = syrope
            self.visco[:, K.V_TM] = self.visco[:, K.V_TM0]

    def _sea_grid(self, duration: float, positions, bands: bool = False):
        """(box, bands, window [s]) of the irregular sea's grid over ``positions``, size-checked: each band's
        (components, z_min, z_max, columns, levels, steps: its points a period and a wavelength, when not the
        defaults); one band unless ``bands`` (:func:`seacable.seastate.depth_bands`)."""
        from .._limits import check_run_size
        from ..seastate import BAND_REFINE, cutoff_depth, depth_bands, grid_size, significant

        sea = self.water.sea
        P = np.array(positions, float).reshape(-1, 3)
        if self.water.depth is not None:  # the kernel reads a node pressed into the seabed at the seabed
            P[:, 2] = np.maximum(P[:, 2], -float(self.water.depth))
        # only the points above the depth where the waves die out need the grid (below it: no kinematics)
        zcut = cutoff_depth(sea)
        P = P[P[:, 2] >= zcut] if np.any(P[:, 2] >= zcut) else P[np.argmax(P[:, 2])][None]
        # the components that matter below the highest point (all of them when it is near the surface)
        sea = significant(sea, float(P[:, 2].max()) + 4.0 * math.sqrt(sea.m0))
        cb, sb = math.cos(sea.mean_heading), math.sin(sea.mean_heading)
        xi = P[:, 0] * cb + P[:, 1] * sb
        ze = -P[:, 0] * sb + P[:, 1] * cb
        _, (_, dx, _, _), _ = grid_size(sea, duration, ((0.0, 0.0), (0.0, 0.0)), 0.0)
        pad = 4.0 * math.sqrt(sea.m0) + 2.0 * dx
        box = ((float(xi.min()) - pad, float(xi.max()) + pad), (float(ze.min()) - pad, float(ze.max()) + pad))
        zmin = max(float(P[:, 2].min()) - pad, zcut)
        if self.water.depth is not None:
            zmin = max(zmin, -float(self.water.depth))
        # the levels above the highest point (plus the pad) are left out: a deep line needs no surface layer
        zmax = min(float(P[:, 2].max()) + pad, 0.0)
        split = depth_bands(sea, zmax, zmin) if bands else [(zmax, sea)]
        (nt, nx, ny, nz), (dt, gdx, zc, zh), i0 = grid_size(sea, duration, box, split[1][0] if len(split) > 1 else zmin,
                                                            z_max=zmax)
        nq = 4 if bool(np.all(sea.heading == sea.mean_heading)) else 6
        fix = (f"narrow environment.waves.frequency_range or shorten the lines near the surface (a grid of {nx} x {ny} "
               f"horizontal x {nz} depth points at each of {nt} times)")
        # first a bound from below, before the columns' own tables (nx ny each) are made: a column holds at least
        # one level, and a window at least 8 times; its times count as steps (each one a product over components)
        check_run_size("the irregular sea's kinematics grid", steps=nt,
                       stored_values=min(nt, 10) * (nq + 1) * float(nx) * ny + 8.0 * nx * ny, fix=fix)
        # in each column, only the levels that the points near it (within the pad) can reach
        columns = _sea_columns(xi, ze, P[:, 2], box, gdx, (nx, ny, nz), (zc, zh, i0), pad,
                               (zmax, split[1][0]) if len(split) > 1 else None)
        per_column = np.clip(columns[..., 1], 0, nz - 1) - np.clip(columns[..., 0], 0, nz - 1) + 1
        per_column[columns[..., 0] < 0] = 0
        per_time = float(nq * np.sum(np.maximum(per_column, 1) if len(split) == 1 else per_column) + nx * ny)
        plans = [(sea, split[1][0] if len(split) > 1 else zmin, zmax, columns, None, {})]
        finer = {"per_period": 20 * BAND_REFINE, "per_wavelength": 10 * BAND_REFINE}  # grid_size's defaults, refined
        per_second = per_time / dt
        for b in range(1, len(split)):  # the depth bands below the top one, on its levels
            top, part = split[b]
            bottom = split[b + 1][0] if b + 1 < len(split) else zmin
            (_, bnx, bny, bnz), (bdt, bdx, _, _), bi0 = grid_size(part, duration, box, bottom, z_max=top,
                                                                  levels=(zc, zh), **finer)
            cols = _sea_columns(xi, ze, P[:, 2], box, bdx, (bnx, bny, bnz), (zc, zh, bi0), pad, (top, bottom))
            count = np.clip(cols[..., 1], 0, bnz - 1) - np.clip(cols[..., 0], 0, bnz - 1) + 1
            count[cols[..., 0] < 0] = 0
            per_second += float(nq * np.sum(count) + bnx * bny) / bdt
            plans.append((part, bottom, top, cols, (zc, zh), finer))
        if len(plans) > 1:
            per_time = per_second * dt  # the values of all bands over one of the top band's steps
        # a window of time at most SEA_WINDOW_VALUES values (the whole run when it fits), at least 8 samples
        window = min(duration, max(math.floor(SEA_WINDOW_VALUES / per_time) - 2, 8) * dt)
        nw = min(nt, math.ceil(window / dt) + 2)
        check_run_size("the irregular sea's kinematics grid", steps=0.0, stored_values=nw * per_time, fix=fix)
        return box, plans, window

    def check_sea(self, duration: float, positions, bands: bool = False) -> None:
        """Refuse an irregular sea whose kinematics grid would exceed the size limits (no grid built)."""
        if self.water.sea is not None:
            self._sea_grid(duration, positions, bands)

    def prepare_sea(self, duration: float, positions, bands: bool = False) -> None:
        """Precompute the irregular sea's kinematics on a grid for a run of ``duration`` [s].

        The grid (:func:`seacable.seastate.kinematics_grid`) covers, along and across the mean heading,
        the box of those ``positions`` (n, 3) [m] (the nodes' start and the prescribed nodes' range) that lie
        above the depth where the waves die out (:func:`seacable.seastate.cutoff_depth`: their velocity
        standard deviation under 0.1 % of the surface's; below it the kinematics are neglected), widened
        by 4 sqrt(m0) (about Hs) and two grid steps each side, and in depth the water from the highest of them
        (so widened; the surface when it reaches it) down to the deepest (or that depth, or the seabed), in each
        column only the levels the points near it reach (:func:`_sea_columns`). A point outside the box gets
        the values at its edge. Only
        the components that matter below the highest of them (plus 4 sqrt(m0)) are gridded
        (:func:`seacable.seastate.significant`): deep lines need no short waves, and a coarser
        grid. The kinematics are stored in single precision (:class:`seacable.seastate.SeaGrid`: their rounding,
        about 1e-6 of the values, is far below the grid's interpolation error). Its size is checked
        against the run size limits (:func:`seacable._limits.check_run_size`). No irregular sea: nothing
        to do.

        ``bands``: the grid in depth bands (:class:`seacable.seastate.SeaBands`, :func:`seacable.seastate.depth_bands`):
        below the top band the components that carry under 0.1 % of the acceleration's standard deviation are left
        out and the grid's steps follow the shortest of those kept (:data:`seacable.seastate.BAND_REFINE` times finer;
        lines reaching deep: a fraction of the work).
        """
        if self.water.sea is None:
            return
        box, plans, window = self._sea_grid(duration, positions, bands)
        grids = [SeaGrid(sea, box, zmin, stretching=self.water.stretching, z_max=zmax, columns=columns, single=True,
                         levels=levels, elevation=b == 0, **steps)
                 for b, (sea, zmin, zmax, columns, levels, steps) in enumerate(plans)]
        plan = grids[0] if len(grids) == 1 else SeaBands(grids)
        self._sea_spec = (plan, window, duration)
        self.sea = no_sea(self.water.stretching)
        self.ensure_sea(0.0, 0.0)

    def sea_end(self) -> float:
        """The last time the irregular sea's grid window covers [s] (inf without an irregular sea)."""
        from ..seastate import S_DT, S_MODE, S_NT, S_T0

        s = self.sea
        if self._sea_spec is None or s[S_MODE] <= 0:
            return math.inf
        return float(s[S_T0] + s[S_DT] * (s[S_NT] - 1))

    def sea_spans(self, ts, waves: bool = True):
        """``(i0, i1)`` runs of the times ``ts`` [s] (increasing) that one window of the irregular sea's grid
        covers, each made current before it is yielded; one run of all without an irregular sea."""
        i, n = 0, len(ts)
        while i < n:
            if not waves or self._sea_spec is None:
                yield i, n
                return
            self.ensure_sea(float(ts[i]), float(ts[i]))
            end = self.sea_end()
            j = i + 1
            while j < n and float(ts[i]) <= ts[j] <= end:
                j += 1
            yield i, j
            i = j

    def ensure_sea(self, t0: float, t1: float) -> None:
        """Make the irregular sea's grid cover the times [t0, t1] [s] (see :meth:`prepare_sea`).

        A run whose grid is larger than ``SEA_WINDOW_VALUES`` values takes it in windows of time: the
        window starting at ``t0`` is computed when [t0, t1] leaves the current one (a time loop calls this
        once per output interval, results once per stored time, in increasing time). Nothing to do
        without an irregular sea or before :meth:`prepare_sea`.
        """
        spec = self._sea_spec
        if spec is None:
            return
        from ..seastate import S_DT, S_MODE, S_NT, S_T0

        s = self.sea
        if s[S_MODE] > 0 and s[S_T0] <= t0 and t1 <= s[S_T0] + s[S_DT] * (s[S_NT] - 1):
            return
        plan, window, duration = spec
        self.sea = plan.window(t0, max(t1, min(t0 + window, duration)))

    def element_args(self):
        n = self.network
        return (n.elements, n.length, n.axial_stiffness, n.axial_damping, n.mass_per_length, n.diameter, n.cdn,
                n.cdt, n.can, n.cat, self.weight, n.point_mass, n.point_added_mass, n.point_volume,
                n.point_hydrodynamics(), self.bedc, self.buoyancy, self.point_buoyancy, *self.tension_strain,
                self.hinges, self.hinge_ei, self.visco)

    def evaluate(self, X, V, A, t=0.0, waves=True, settled=False):
        """Node forces F (without inertia and supports), masses M and element tensions at a state.

        Returns ``F, M, tension, support`` with ``support = F - M a`` the force each node applies to its
        support (meaningful at fixed and prescribed nodes). Viscoelastic elements are at their static
        stiffness, or with ``settled`` at their slow stretch of the last converged time step (a
        time-domain state). [N], [kg], [N], [N]
        """
        n = self.network.n_nodes
        F, M = np.zeros((n, 3)), np.zeros((n, 3, 3))
        tension = np.zeros(self.network.n_elements)
        env = self.env
        if waves:
            self.ensure_sea(t, t)
        if settled and self.visco.shape[0]:
            env = env.copy()
            env[K.E_VDT] = 0.0
        K.loads(X, V, t, *self.element_args(), self.fidx, env, self.cur_depth, self.cur_speed, waves, self.sea,
                F, M, tension, np.zeros((0, 2 * self.bw + 1)), self.bw, 0.0, 0.0)
        support = F - np.einsum("nij,nj->ni", M, A)
        return F, M, tension, support

    def settle_viscoelastic(self, X, V) -> None:
        """Start the viscoelastic elements' slow stretch at its static value at positions ``X``."""
        if self.visco.shape[0]:
            self.evaluate(X, V, np.zeros_like(X), waves=False)
            K.commit_viscoelastic(self.visco)


def _band_order(net: Network, free: np.ndarray) -> np.ndarray:
    """Free nodes in reverse Cuthill-McKee order (a narrow band for networks of several lines)."""
    if len(net.line_nodes) == 1 or free.size == 0:
        return free
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import reverse_cuthill_mckee

    el = net.elements
    n = net.n_nodes
    g = coo_matrix((np.ones(2 * len(el)), (np.r_[el[:, 0], el[:, 1]], np.r_[el[:, 1], el[:, 0]])),
                   shape=(n, n)).tocsr()
    sub = g[free][:, free]
    perm = reverse_cuthill_mckee(sub, symmetric_mode=True)
    return free[perm]


@dataclass(frozen=True)
class StaticState:
    """A static equilibrium: node positions, element tensions and support forces."""

    position: np.ndarray
    tension: np.ndarray
    support: np.ndarray
    iterations: int
    residual: float


def static_equilibrium(model: MooringModel, initial=None, *, tol: float = 1e-9, max_iter: int = 500,
                       max_step: float | None = None, targets=None, friction_distance: float = 1e-3) -> StaticState:
    """Static equilibrium by damped Newton from ``initial`` positions (default the network's).

    ``targets`` (n, 3) [m]: the seabed's static friction towards these friction targets (a row of NaN: none), with
    the slip distance ``friction_distance`` [m] (:mod:`seacable.mooring._friction`, :mod:`seacable.mooring.friction`);
    None: frictionless statics.

    The Newton steps move a node by at most ``max_step`` [m] (default half the mean element length). A solve
    that does not converge (a finely meshed one, a line of more than ``2 COARSE_ELEMENTS`` elements, in
    ``FINE_DIRECT_ITERATIONS``) is started again by mesh sequencing (:mod:`seacable.mooring.sequencing`: the
    equilibrium of the same lines at about ``COARSE_ELEMENTS`` elements each, itself solved so, interpolated onto
    the fine mesh), then from ``initial`` with the limit cut to a quarter, twice: a slack chain lying on the seabed
    can wander for hundreds of steps at the full limit (its grounded nodes have no stiffness across, and each step
    throws some through the seabed) and converge in a few tens at a smaller one. Raises
    :class:`~seacable.errors.ConvergenceError` with the residual when none converges.
    """
    net = model.network
    X0 = np.array(net.position if initial is None else initial, float)
    n = net.n_nodes
    F, M = np.zeros((n, 3)), np.zeros((n, 3, 3))
    tension = np.zeros(net.n_elements)
    stats = np.zeros(3)
    step = max_step if max_step is not None else (0.5 * float(np.mean(net.length)) if net.n_elements else 1.0)
    spent = 0
    tried = []
    fine = any(len(nodes) - 1 > 2 * COARSE_ELEMENTS for nodes in net.line_nodes)
    held = np.zeros((0, 3)) if targets is None else np.ascontiguousarray(targets, float)
    for how in ("direct", "sequenced", 0.25, 0.0625):
        X = X0.copy()
        limit, iterations = step, max_iter
        if how == "direct" and fine:
            iterations = min(max_iter, FINE_DIRECT_ITERATIONS)
        elif how == "sequenced":
            if not fine:
                continue
            tried.append(how)
            X = _sequenced_start(model, X0, tol, max_iter)
            if X is None:  # the coarse mesh did not converge either
                continue
        elif how != "direct":
            limit = step * how
        ok = K.static_solve(X, *model.element_args(), model.fidx, model.nfree, model.bw, model.env,
                            model.cur_depth, model.cur_speed, tol, iterations, limit, F, M, tension, stats, held,
                            friction_distance)
        spent += int(stats[0])
        if ok:
            break
    if not ok:
        also = " from a coarser mesh's equilibrium," if "sequenced" in tried else ""
        generic = (" Suggested fix: check that the line is long enough to reach its fairlead and that buoys cannot "
                   "lift it out of the water.")
        raise ConvergenceError(
            f"the static equilibrium of the mooring did not converge in {max_iter} iterations,{also} nor with the "
            f"step limit {step:.3g} m cut to a quarter and a sixteenth: force residual {stats[1]:.3g} N against a "
            f"tolerance of {stats[2]:.3g} N ({spent} iterations in all).{_held_end_hint(model, X0, tol)}"
            f"{_seabed_current_hint(model, X, targets is not None) or generic}", iterations=spent,
            residual=float(stats[1]))
    _, _, tension, support = model.evaluate(X, np.zeros_like(X), np.zeros_like(X), waves=False)
    _warn_sinking(model, X)
    return StaticState(X, tension, support, spent, float(stats[1]))


def _held_end_hint(model: MooringModel, X0, tol: float) -> str:
    """Why a line with an end held at a direction (clamped, or a rotational spring) may have no static equilibrium
    (:func:`static_equilibrium`'s message; "" when it is not that).

    The elements carry no compression (MoorDyn's rule). As the mesh is refined, the tension of a held end's end
    element tends to the component of the line's force along the end's given direction, ``T cos(Delta)`` with
    ``Delta`` the angle between the line's pull and that direction (the bending boundary layer turns the line,
    not its force): a coarse end element's is larger by O(l). Where ``cos(Delta) <= 0`` (a steep wave's base
    clamped straight up while the line pulls sideways or down) the end must carry compression: a fine mesh then
    has no equilibrium. ``Delta`` and ``T`` are those of the line with its held ends pinned, solved here."""
    net = model.network
    held = [(line, end, direction) for line, end, _, _, direction in net.end_hinges]
    if not held or model.water.compression:
        return ""
    try:
        pinned = static_equilibrium(MooringModel(net.replace(end_hinges=()), model.water, checked=True), X0,
                                    tol=tol)
    except ConvergenceError:
        return ""
    out = []
    for line, end, direction in held:
        nodes = net.line_nodes[line]
        ie, iw = (nodes[0], nodes[1]) if end == 0 else (nodes[-1], nodes[-2])
        pull = pinned.position[iw] - pinned.position[ie]
        into = np.asarray(direction, float) * (1.0 if end == 0 else -1.0)
        cos = float(pull @ into / (np.linalg.norm(pull) * np.linalg.norm(into)))
        T = float(np.linalg.norm(pinned.support[ie]))
        if cos < 0.1:
            out.append(f" Its end {'AB'[end]} is held at a direction {math.degrees(math.acos(min(max(cos, -1), 1))):.1f} "
                       f"deg from the line's pull there (pinned, the line pulls with {T:.4g} N): the end element "
                       f"would carry T cos(angle) = {T * cos:.4g} N, and the elements carry no compression, so a "
                       "fine mesh has no equilibrium there. Let the elements carry compression (a mooring analysis's "
                       "'compression: true'), or hold the end closer to the line's direction (or the line so that it "
                       "pulls along the held direction: buoyancy nearer the end).")
    return "".join(out)


def _seabed_current_hint(model: MooringModel, X, friction: bool = False) -> str:
    """Why a line lying on the seabed may have no static equilibrium (:func:`static_equilibrium`'s message; ""
    when it is not that): a current at the seabed, or the slope, loads the grounded line along the seabed more than
    the statics' friction holds (``friction``: the statics had friction targets; else none holds it).
    :func:`seacable.mooring.checks.seabed_hold_hint`; ``X`` is the last state tried."""
    return seabed_hold_hint(model, X, friction)


#: Elements a line takes in the coarse network of mesh sequencing (:func:`static_equilibrium`).
COARSE_ELEMENTS = 60
#: Iterations a finely meshed network's statics is given from its start before mesh sequencing takes over: from a
#: catenary start a fine lazy wave does not converge in 1500 (it needs tens of metres of steps each smaller than
#: its elements), from the coarse mesh's equilibrium in 14-32.
FINE_DIRECT_ITERATIONS = 150


def _sequenced_start(model: MooringModel, X0, tol: float, max_iter: int):
    """A start for ``model``'s statics from the equilibrium of its lines meshed coarsely (None when they cannot be
    meshed more coarsely, or the coarse statics fails too): :mod:`seacable.mooring.sequencing`. The coarse network starts
    from ``X0`` at its nodes."""
    from .sequencing import coarsen, spline_start

    coarse = coarsen(model.network.replace(position=np.asarray(X0, float)), COARSE_ELEMENTS)
    if coarse is None:
        return None
    try:
        state = static_equilibrium(MooringModel(coarse, model.water, checked=True), tol=tol, max_iter=max_iter)
    except ConvergenceError:
        return None
    return spline_start(model.network, coarse, state.position)


def _warn_sinking(model: MooringModel, X) -> None:
    """Warn when a node sinks into the penalty seabed deeper than the line is thick (a heavy point load)."""
    water, net = model.water, model.network
    if water.depth is None or water.seabed_stiffness <= 0:
        return
    if water.grid is not None:  # along the grid's normal under each node
        depth_in = (water.seabed_z(X[:, 0], X[:, 1]) - X[:, 2]) * water.grid.normal(X[:, 0], X[:, 1])[:, 2]
    else:
        depth_in = (water.seabed_z(X[:, 0]) - X[:, 2]) * math.cos(water.slope)
    thick = np.zeros(net.n_nodes)
    np.maximum.at(thick, net.elements[:, 0], net.diameter)
    np.maximum.at(thick, net.elements[:, 1], net.diameter)
    k = int(np.argmax(depth_in - thick))
    if depth_in[k] > thick[k] > 0:
        warnings.warn(
            f"node {k} (s = {net.arc_length[k]:.4g} m) sinks {depth_in[k]:.3g} m into the seabed, more than the "
            f"line's {thick[k]:.3g} m diameter: its {model.weight[k]:.4g} N bear on the adjacent elements' "
            f"projected area {model.bedc[k]:.3g} m^2 at seabed_stiffness {water.seabed_stiffness:.3g} Pa/m. "
            "Suggested fix: model a clump weight as a segment of its own (a distributed clump), or raise "
            "the seabed stiffness.", SeacableWarning, stacklevel=3)


def pushover(model: MooringModel, offsets, direction=(1.0, 0.0, 0.0), *, tol: float = 1e-9,
             initial: StaticState | None = None) -> list[StaticState]:
    """Quasi-static force-excursion: the prescribed nodes moved by ``offsets`` [m] along ``direction``."""
    net = model.network
    d = np.asarray(direction, float)
    d = d / np.linalg.norm(d)
    moving = net.kind == PRESCRIBED
    base = net.position.copy()
    X = (initial.position if initial is not None else static_equilibrium(model, tol=tol).position).copy()
    states = []
    for off in np.asarray(offsets, float):
        X[moving] = base[moving] + off * d
        states.append(static_equilibrium(model, X, tol=tol))
        X = states[-1].position.copy()
    return states


MotionFn = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]

#: Steps of a run whose prescribed motion is evaluated together (:class:`StepSamples`).
SAMPLE_BLOCK = 512


class StepSamples:
    """Functions of time (a prescribed motion, a winch schedule) at a run's step times, the same floats however
    the run is cut into chunks.

    Step ``i`` (from 0) of a run of ``sub`` steps of ``h`` [s] per output interval of ``interval`` [s] ends at
    ``interval k + h (s + 1)`` with ``k, s = divmod(i, sub)``. ``fn`` (times -> a tuple of arrays, times first)
    is evaluated on fixed blocks of ``block`` steps aligned to the step index from the run's start (the last one
    cut at step ``total``), never on a chunk's own range: a value does not depend on the chunk it falls in (an
    evaluation of many times at once, a matrix product whose kernel and summation order change with the number
    of rows, the sines of :func:`seacable.seastate.cos_sin` taken afresh every 32 rows from its first, may round
    a time's value differently by where it stands in the array), and so not on the wall clock that sizes the
    chunks. Blocks before the last one asked for are dropped."""

    def __init__(self, fn, interval: float, h: float, sub: int, total: int, block: int = SAMPLE_BLOCK):
        self.fn, self.interval, self.h, self.sub, self.total, self.block = fn, interval, h, sub, total, block
        self._blocks: dict[int, tuple] = {}

    def _evaluate(self, b: int) -> tuple:
        i = np.arange(b * self.block, min((b + 1) * self.block, self.total))
        k, s = np.divmod(i, self.sub)
        return tuple(np.asarray(c) for c in self.fn(self.interval * k + self.h * (s + 1)))

    def __call__(self, i0: int, i1: int) -> tuple:
        """The values at steps ``i0`` to ``i1 - 1`` (contiguous arrays)."""
        b0, b1 = i0 // self.block, (i1 - 1) // self.block
        self._blocks = {b: v for b, v in self._blocks.items() if b >= b0}
        for b in range(b0, b1 + 1):
            if b not in self._blocks:
                self._blocks[b] = self._evaluate(b)
        parts = [(self._blocks[b], max(i0 - b * self.block, 0), min(i1 - b * self.block, self.block))
                 for b in range(b0, b1 + 1)]
        return tuple(np.ascontiguousarray(np.concatenate([v[j][lo:hi] for v, lo, hi in parts]))
                     for j in range(len(parts[0][0])))



def advance_interval(t0, h, sub, channels, steps, stats, max_halvings, max_iter, what, fix, *, failed_at=None):
    """Advance the state one output interval: ``sub`` steps of ``h`` from ``t0``, each failed step halved.

    ``steps(t, dt, px, pv, pa)`` runs the compiled time loop over the motion channels sampled at the
    steps' end times, filling ``stats`` (iterations, residual, tolerance), and returns how many steps
    converged; from the first that did not, the rest of the interval is redone at half the step, up to
    ``max_halvings`` times. ``failed_at`` resumes an interval whose first ``failed_at`` steps of ``h``
    converged and whose next did not (``stats`` holding that failure). Returns (steps taken, Newton
    iterations), those of ``failed_at`` not included.

    Raises
    ------
    ConvergenceError
        A step that does not converge at the smallest step, with the time, step and residual.
    """
    done, level, taken, spent = 0, 0, 0, 0

    def fail(dtk):
        raise ConvergenceError(
            f"the {what} time step did not converge at t = {t0 + done * dtk:.6g} s with dt = {dtk:.3g} s "
            f"after {max_halvings} halvings: force residual {stats[1]:.3g} N (tolerance {stats[2]:.3g} N). "
            f"Suggested fix: {fix}.", time=t0 + done * dtk, iterations=max_iter, residual=float(stats[1]))

    if failed_at is not None:
        done = failed_at
        if max_halvings == 0:
            fail(h)
        done, level = 2 * failed_at, 1
    while done < sub * 2 ** level:
        dtk = h / 2 ** level
        m = sub * 2 ** level - done
        px, pv, pa = channels(t0 + dtk * (done + np.arange(1, m + 1)))
        stats[:] = 0.0
        got = steps(t0 + done * dtk, dtk, px, pv, pa)
        spent += int(stats[0])
        taken += got
        done += got
        if got < m:
            if level == max_halvings:
                fail(dtk)
            done *= 2
            level += 1
    return taken, spent


def recommended_time_step(model: MooringModel, forcing_period: float | None = None, *,
                          steps_per_period: int = 50, steps_per_axial_period: int = 10) -> tuple[float, str]:
    """A time step for the Newmark integration of ``model`` and why: the smaller of the forcing period
    over ``steps_per_period`` and the line's first axial period over ``steps_per_axial_period``.

    The axial wave speed of element ``e`` is ``c_e = sqrt(EA_e / m_e)`` (mass per length in air); a wave
    crosses it in ``L_e / c_e`` and runs along a line in ``tau = sum L_e / c_e``; the first axial period
    of a line held at both ends is ``2 tau``. Fifty steps per forcing period keep the average-acceleration
    scheme's period error ``(w dt)^2 / 12`` below 0.15 %; ten per axial period keep the axial (snatch)
    response of a taut line. A slack line that snaps taut sends an axial wave front across each element
    in ``L_e / c_e``: its peak tension needs steps about that long (said in the returned text).

    Parameters
    ----------
    model
        The mooring model.
    forcing_period
        The period of the motion or the waves [s]; None when unknown (a time series).
    steps_per_period, steps_per_axial_period
        Steps per forcing period and per first axial period. [1]

    Returns
    -------
    (float, str)
        The recommended step [s] and a one-line explanation.
    """
    net = model.network
    c = np.sqrt(net.axial_stiffness / np.maximum(net.mass_per_length, 1e-300))
    cross = net.length / c
    tau = max((float(np.sum(cross[net.element_line == k])) for k in range(len(net.line_nodes))), default=0.0)
    options = []
    if tau > 0.0:
        options.append((2.0 * tau / steps_per_axial_period,
                        f"1/{steps_per_axial_period} of the first axial period 2 sum(L/c) = {2 * tau:.3g} s"))
    if forcing_period is not None and forcing_period > 0:
        options.append((forcing_period / steps_per_period,
                        f"1/{steps_per_period} of the forcing period {forcing_period:.3g} s"))
    if not options:
        return math.inf, "no elements and no forcing period"
    dt, why = min(options)
    k = int(np.argmax(c)) if c.size else 0
    why += (f"; axial wave speed sqrt(EA/m) up to {c[k]:.4g} m/s crosses an element in {float(np.min(cross)):.3g} s "
            "(the step to resolve snap loads of a line going slack)") if c.size else ""
    return dt, why


@dataclass(frozen=True)
class MooringRun:
    """Stored states of a time-domain run (``output`` times)."""

    time: np.ndarray
    position: np.ndarray       # (nt, n, 3)
    velocity: np.ndarray       # (nt, n, 3)
    tension: np.ndarray        # (nt, e)
    support: np.ndarray        # (nt, n, 3)
    time_step: float
    iterations: int
    steps: int
    interrupted: bool
    wall_time: float
    acceleration: np.ndarray | None = None  # (nt, n, 3)
    spectral_radius: float = 1.0  # of the generalised-alpha scheme (1: average acceleration)
    recommended_time_step: float = math.nan  # :func:`recommended_time_step` [s]
    kinematic_nodes: np.ndarray | None = None  # the nodes of velocity and acceleration (nt, k, 3); None: all


def _start_jump_fix(model: MooringModel, V, pres) -> str:
    """The suggested fix of a time step that fails in a run whose motion starts moving from rest ("" if it does not):
    the moved nodes start at the motion's velocity ``V[pres]`` beside nodes at rest, a jump that sends an axial wave
    of ``sqrt(EA m) dv`` along each moved end's element (its impedance), which can slacken and snap a taut line."""
    if pres.size == 0:
        return ""
    net = model.network
    dv = np.linalg.norm(V[pres], axis=-1)
    k = int(np.argmax(dv))
    if dv[k] <= 0.0:
        return ""
    node = int(pres[k])
    e = np.flatnonzero((net.elements == node).any(axis=1))
    wave = float(np.max(np.sqrt(net.axial_stiffness[e] * net.mass_per_length[e]))) * float(dv[k]) if e.size else 0.0
    return (f"the motion starts from rest at {dv[k]:.3g} m/s (moved node {node}), a jump that sends an axial wave of "
            f"sqrt(EA m) dv = {wave:.3g} N along the line: give the motion a smooth start (its 'ramp' [s], e.g. one "
            "period), or a smaller time_step or more elements")


def simulate(model: MooringModel, motion: MotionFn | None, duration: float, dt: float, output_interval: float,
             *, initial: np.ndarray | None = None, tol: float = 1e-7, max_iter: int = 30,
             beta: float | None = None, gamma: float | None = None, spectral_radius: float = 1.0, progress=None,
             max_halvings: int = 6, chunk_seconds: float = 0.25, forcing_period: float | None = None,
             kinematics=None, on_outputs=None, block_outputs: int | None = None) -> MooringRun:
    """Generalised-alpha time stepping from rest at ``initial`` positions (default a static equilibrium).

    ``motion(times)`` returns positions, velocities and accelerations of the motion channels,
    shape (len(times), n_channels, 3). ``spectral_radius`` is the scheme's amplification of the
    highest frequencies per step (:func:`generalized_alpha`; 1, the default: Newmark's average
    acceleration, no numerical damping; 0.7-0.9 damps the ringing of stiff axial modes at a coarse
    step). ``beta`` and ``gamma`` set a Newmark scheme of their own instead (equilibrium at the
    step's end; only with ``spectral_radius`` 1). A step that does not converge is retried with
    half the time step, six times at most; then :class:`~seacable.errors.ConvergenceError` reports
    the time and the residual. Ctrl-C stops the run and returns what was computed (``interrupted``).

    The time loop is compiled (:func:`seacable.mooring.loop.run_outputs`): it runs output interval
    after output interval into preallocated arrays, in chunks of about ``chunk_seconds`` of computing
    [s] between which Python samples the motion on the chunk's step grid (once for each step), moves an
    irregular sea's grid window on (a chunk stays inside one window) and calls ``progress(t, duration)``
    for each output of the chunk; an interval with a failed step is finished here at the halved steps.

    The step used and the one :func:`recommended_time_step` gives for ``forcing_period`` [s] are in the
    result; with ``progress`` (an interactive run) they are also printed on stderr. ``kinematics`` (node
    indices) stores the velocities and accelerations of those nodes only (None: of every node), e.g.
    :func:`line_end_nodes` for the end forces of the lines: a long run's stored results shrink by half.

    ``on_outputs(block)``: the outputs go out in blocks as the run goes, each a :class:`MooringRun` of at
    most ``block_outputs`` consecutive outputs (from t = 0 on, each once, the last one when the run ends
    or is interrupted), instead of being kept: a run's memory is then that of one block whatever its
    length. By default a block is the largest power of two of outputs within :data:`BLOCK_VALUES` values.
    A block also goes out before an irregular sea's grid window moves on, so that the block's states lie
    in the window of ``model.sea``. The run returned then holds no outputs (its arrays have
    0 rows), only its counts and times.
    """
    from . import loop as LP

    alpha_m, alpha_f, beta_g, gamma_g = generalized_alpha(spectral_radius)
    if (beta is not None or gamma is not None) and float(spectral_radius) != 1.0:
        raise InputError(f"beta/gamma ({beta}, {gamma}) and spectral_radius {spectral_radius} both set the time "
                         "integration. Suggested fix: give either the spectral radius or Newmark's beta and gamma.")
    beta = beta_g if beta is None else beta
    gamma = gamma_g if gamma is None else gamma
    net = model.network
    n = net.n_nodes
    X = (static_equilibrium(model).position if initial is None else np.array(initial, float)).copy()
    V, A = np.zeros_like(X), np.zeros_like(X)
    n_out = int(round(duration / output_interval))  # noqa: RUF046 (a numpy float rounds to a float)
    sub = max(1, math.ceil(output_interval / dt - 1e-9))
    h = output_interval / sub
    dt_rec, why = recommended_time_step(model, forcing_period)
    if progress is not None:
        print(f"seacable: time step {h:.4g} s; recommended {dt_rec:.4g} s ({why})", file=sys.stderr, flush=True)
    F, M = np.zeros((n, 3)), np.zeros((n, 3, 3))
    tension = np.zeros(net.n_elements)
    nch = max(net.n_channels, 1)

    def channels(times):
        if motion is None or net.n_channels == 0:
            shape = (len(times), nch, 3)
            return np.broadcast_to(net.channel_positions(), shape).copy(), np.zeros(shape), np.zeros(shape)
        return motion(times)

    # the state at t = 0: prescribed nodes where the motion puts them, at its velocity
    x0, v0, a0 = channels(np.zeros(1))
    pres = np.flatnonzero(net.channel >= 0)
    X[pres], V[pres], A[pres] = x0[0, net.channel[pres]], v0[0, net.channel[pres]], a0[0, net.channel[pres]]
    model.settle_viscoelastic(X, np.zeros_like(V))
    # an irregular sea: its kinematics on a grid over the nodes and the fairleads' range
    if model.water.sea is not None:
        t_out = np.linspace(0.0, duration, n_out + 1)
        model.prepare_sea(duration, np.concatenate((X, channels(t_out)[0].reshape(-1, 3))))
    Fi, Mi, _, _ = model.evaluate(X, V, A, settled=True)
    free = model.fidx >= 0
    A[free] = np.linalg.solve(Mi[free], Fi[free][..., None])[..., 0]
    hist = np.zeros_like(X)  # the step start's share of the generalised-alpha equilibrium
    K.alpha_history(Fi, Mi, A, hist, alpha_m, alpha_f, model.fidx)

    knodes = np.arange(n) if kinematics is None else np.asarray(kinematics, np.int64)
    if block_outputs is None:  # a power of two of outputs within BLOCK_VALUES values
        per_output = 1 + 6 * n + net.n_elements + 6 * knodes.size  # times, positions, support, tension, kinematics
        block_outputs = 2 ** max(1, (BLOCK_VALUES // per_output).bit_length() - 1)
    rows = n_out + 1 if on_outputs is None else max(2, min(int(block_outputs), n_out + 1))
    times = np.zeros(rows)
    pos = np.zeros((rows, n, 3))
    vel, acc = np.zeros((rows, knodes.size, 3)), np.zeros((rows, knodes.size, 3))
    ten, sup = np.zeros((rows, net.n_elements)), np.zeros((rows, n, 3))
    env_rec = model.env
    if model.visco.shape[0]:
        env_rec = env_rec.copy()
        env_rec[K.E_VDT] = 0.0  # outputs: viscoelastic elements at the last converged step's slow stretch
    args = model.element_args()
    store = (times, pos, vel, acc, ten, sup)
    base = 0  # the output in row 0 of the stored arrays

    def record(k):
        # ``evaluated`` given, as run_outputs gives it: one compiled record_output for both
        LP.record_output(k - base, k * output_interval, X, V, A, knodes, *args, model.fidx, model.bw, env_rec,
                         model.cur_depth, model.cur_speed, model.sea, F, M, tension, *store, False)

    def block(stop, last=False):
        """The stored outputs ``base`` to ``stop - 1`` as a run (copies: the rows are used again; the ``last``
        block's, not used again, as they are)."""
        m = stop - base
        take = (lambda a: a[:m]) if last else (lambda a: a[:m].copy())
        return MooringRun(time=take(times), position=take(pos), velocity=take(vel), tension=take(ten),
                          support=take(sup), time_step=h, iterations=int(count[2]),
                          steps=int(count[1]), interrupted=interrupted, wall_time=_time.perf_counter() - start,
                          acceleration=take(acc),
                          spectral_radius=float(spectral_radius), recommended_time_step=dt_rec,
                          kinematic_nodes=None if kinematics is None else knodes)

    def send(stop, last=False):
        """Hand the outputs ``base`` to ``stop - 1`` to ``on_outputs``; their rows are free again (``last``: the
        run's last block, its rows handed over as they are). Ctrl-C and SIGTERM wait for the end (then raise): a
        block goes out whole, once."""
        nonlocal base
        if on_outputs is not None and stop > base:
            with deferred_interrupts():
                on_outputs(block(stop, last))
                base = stop

    record(0)
    stats = np.zeros(3)
    count = np.zeros(4, np.int64)  # outputs stored, steps, Newton iterations, steps of a failed interval
    fix = _start_jump_fix(model, V, pres) or "smaller time_step, more elements, or check the motion for a jump"
    interrupted = False
    start = _time.perf_counter()
    reported, reporting = 0, False

    def newmark(t, dtk, px, pv, pa):
        return K.newmark_steps(X, V, A, t, dtk, px, pv, pa, net.channel, *args, model.fidx, model.nfree, model.bw,
                               model.env, model.cur_depth, model.cur_speed, True, model.sea, beta, gamma, alpha_m,
                               alpha_f, hist, tol, max_iter, F, M, tension, stats)

    samples = StepSamples(channels, output_interval, h, sub, n_out * sub)
    try:
        k, size = 0, 1
        while k < n_out:
            if k + 1 - base >= rows or (model.sea_end() < (k + 1) * output_interval):
                send(k + 1)  # the arrays are full, or the sea's window moves on: the outputs so far go out
            k1 = min(n_out, k + size, base + rows - 1)
            model.ensure_sea(k * output_interval, (k + 1) * output_interval)  # an irregular sea's grid window
            if math.isfinite(model.sea_end()):  # the chunk inside the window
                k1 = min(k1, max(k + 1, math.floor(model.sea_end() / output_interval + 1e-9)))
            px, pv, pa = samples(k * sub, k1 * sub)  # the motion at the chunk's steps (whatever the chunk)
            tick = _time.perf_counter()
            got = LP.run_outputs(k, k1, base, output_interval, h, sub, px, pv, pa, X, V, A, knodes, net.channel, *args,
                                 model.fidx, model.nfree, model.bw, model.env, env_rec, model.cur_depth,
                                 model.cur_speed, model.sea, beta, gamma, alpha_m, alpha_f, hist, tol, max_iter, F, M,
                                 tension, stats, count, *store)
            if got < k1:  # a step failed: the rest of that interval at halved steps, then on
                done, spent = advance_interval(got * output_interval, h, sub, channels, newmark, stats,
                                               max_halvings, max_iter, "mooring", fix, failed_at=int(count[3]))
                count[1] += done
                count[2] += spent
                record(got + 1)
                count[0] = got + 1
            took = _time.perf_counter() - tick
            k = int(count[0])
            # the next chunk: about chunk_seconds of computing, at most 100 000 steps of motion samples
            size = max(1, min(int(size * chunk_seconds / max(took, 1e-6)), 2 * size + 8, 100_000 // sub))
            if progress is not None:
                reporting = True
                while reported < k:
                    reported += 1
                    progress(times[reported - base], duration)
                reporting = False
    except KeyboardInterrupt:
        interrupted = True
    wall = _time.perf_counter() - start
    # an interrupt in the progress callback keeps the outputs reported (as when it ran after each output)
    nt = reported + 1 if interrupted and reporting else int(count[0]) + 1
    if on_outputs is not None:
        send(max(nt, base), last=True)
        return replace(block(base), wall_time=wall)
    return MooringRun(time=times[:nt].copy(), position=pos[:nt], velocity=vel[:nt], tension=ten[:nt],
                      support=sup[:nt], time_step=h, iterations=int(count[2]), steps=int(count[1]),
                      interrupted=interrupted, wall_time=wall, acceleration=acc[:nt],
                      spectral_radius=float(spectral_radius), recommended_time_step=dt_rec,
                      kinematic_nodes=None if kinematics is None else knodes)


def line_end_nodes(network: Network) -> np.ndarray:
    """The nodes whose velocity and acceleration the end forces of the lines need: each line's two end nodes
    and their neighbours (:func:`seacable.mooring.run.line_end_forces`), sorted."""
    return np.unique(np.concatenate([np.asarray(nodes)[[0, 1, -2, -1]] if len(nodes) > 1 else np.asarray(nodes)
                                     for nodes in network.line_nodes] or [np.zeros(0, np.int64)])).astype(np.int64)

"""The environment: water, gravity, depth, current and seabed.

Coordinates: Z up, z = 0 at the mean sea surface, the seabed at z = -depth
under the origin. Angles are in radians; a heading is the direction the current
flows *towards*, measured from +X towards +Y.
"""

from __future__ import annotations

import math
import warnings
from typing import Literal

import numpy as np
from pydantic import Field, field_validator, model_serializer, model_validator

from ._model import Model, input_error, quantity, unit_float
from .bathymetry import BathymetryGrid
from .errors import SeacableWarning
from .waves import MIN_WAVELENGTH, STANDARD_GRAVITY, check_sea_state

__all__ = ["Current", "Environment", "IrregularWaves", "Seabed", "SystemEnvironment", "Waves"]


def _warn_if_degrees(name: str, value: float, limit: float) -> None:
    if abs(value) > limit:
        warnings.warn(f"{name} = {value:g} rad looks like degrees "
                      f"({math.radians(value):.4g} rad if it was meant as {value:g} deg). "
                      "seacable takes angles in radians.", SeacableWarning, stacklevel=4)


class Current(Model):
    """A current, uniform or varying with depth, flowing towards ``heading``.

    Parameters
    ----------
    speed
        Speed of a uniform current; ignored when ``depths`` are given. Negative
        flows against ``heading``. [m/s]
    heading
        Direction the current flows towards, from +X towards +Y. [rad]
    depths
        Depths below the surface of a profile, increasing (>= 0). [m]
    speeds
        Current speeds at ``depths``; linear in between, constant beyond. [m/s]
    """

    speed: quantity("m/s") = Field(0.0, description="Uniform current speed. [m/s]")
    heading: quantity("rad") = Field(0.0, description="Direction the current flows towards. [rad]")
    depths: tuple[unit_float("m"), ...] | None = Field(None, description="Profile depths below the surface. [m]")
    speeds: tuple[unit_float("m/s"), ...] | None = Field(None, description="Profile speeds. [m/s]")

    @model_validator(mode="after")
    def _check(self) -> Current:
        _warn_if_degrees("current.heading", self.heading, 2 * math.pi)
        if (self.depths is None) != (self.speeds is None):
            raise ValueError("needs both 'depths' and 'speeds' for a profile, or neither. "
                             "Suggested fix: give two lists of equal length.")
        if self.depths is not None:
            d = np.asarray(self.depths, float)
            v = np.asarray(self.speeds, float)
            if d.size != v.size or d.size < 1:
                raise ValueError(f"depths and speeds must have the same non-zero length, got "
                                 f"{d.size} and {v.size}.")
            if not (np.all(np.isfinite(d)) and np.all(np.isfinite(v))):
                raise ValueError("depths and speeds must be finite numbers [m, m/s].")
            if np.any(d < 0) or np.any(np.diff(d) <= 0):
                raise ValueError(f"depths must be >= 0 m and strictly increasing, got {[float(v) for v in d]} m. "
                                 "Suggested fix: give depths below the surface as positive numbers, "
                                 "top first.")
        return self

    @classmethod
    def uniform(cls, speed: float, heading: float = 0.0) -> Current:
        """A current of one ``speed`` [m/s] at every depth, towards ``heading`` [rad]."""
        return cls(speed=speed, heading=heading)

    @classmethod
    def profile(cls, depths, speeds, heading: float = 0.0) -> Current:
        """A depth profile: ``speeds`` [m/s] at ``depths`` [m] below the surface."""
        return cls(depths=tuple(float(d) for d in depths), speeds=tuple(float(v) for v in speeds),
                   heading=heading)

    def speed_at(self, z) -> np.ndarray:
        """Current speed at elevation ``z`` (<= 0 in the water). [m/s]"""
        z = np.asarray(z, dtype=float)
        if self.depths is None:
            return np.full_like(z, self.speed)
        return np.interp(-z, self.depths, self.speeds)

    def velocity(self, z) -> np.ndarray:
        """Current velocity (u, v, 0) at elevation ``z``; shape ``z.shape + (3,)``. [m/s]"""
        speed = self.speed_at(z)
        return np.stack([speed * math.cos(self.heading), speed * math.sin(self.heading),
                         np.zeros_like(speed)], axis=-1)


class SeabedProfile(Model):
    """Water depths at distances along X: the seabed's elevation is linear between the points and level beyond
    them, the same across Y."""

    distance: tuple[unit_float("m"), ...] = Field(description="Distances along X, increasing. [m]")
    depth: tuple[unit_float("m"), ...] = Field(description="Water depths there, > 0. [m]")

    @model_validator(mode="after")
    def _check(self):
        from .laying.inputs import _check_table

        _check_table(self.distance, self.depth, "seabed.profile")
        return self


class Seabed(Model):
    """A plane seabed, a profile along X, or a grid over X and Y.

    Parameters
    ----------
    slope
        Slope angle, positive when the seabed rises towards +X. [rad]
    friction
        Coulomb friction coefficient of the line on the seabed. [-]
    profile
        Depths along X instead of the plane (towed_dynamic's finite-element formulation).
    grid
        Depths on an x, y grid instead of the plane (:class:`seacable.bathymetry.BathymetryGrid`, the lay
        planner's: inline, CSV or NetCDF, GEBCO-like elevations, land masked), bilinear between its points:
        the finite-element line of moorings, systems and towed cables.
    """

    slope: quantity("rad", gt=-math.pi / 2, lt=math.pi / 2,
                    fix="give the slope in radians (5 deg = 0.0873 rad).") = Field(
        0.0, description="Slope, positive rising towards +X. [rad]")
    friction: quantity("-", ge=0, fix="give a friction coefficient such as 0.5 (chain on clay ~ 1).") = Field(
        0.0, description="Coulomb friction coefficient. [-]")
    profile: SeabedProfile | None = Field(None, description="Depths along X instead of the plane.")
    grid: BathymetryGrid | None = Field(None, description="Depths on an x, y grid instead of the plane.")

    @model_validator(mode="after")
    def _check(self) -> Seabed:
        _warn_if_degrees("seabed.slope", self.slope, math.radians(45))
        if self.profile is not None and self.slope != 0.0:
            raise ValueError(f"seabed.slope {self.slope:g} rad and seabed.profile both give the seabed. Suggested "
                             "fix: give the slope in the profile's depths, and leave slope out.")
        if self.grid is not None and (self.profile is not None or self.slope != 0.0):
            given = "seabed.profile" if self.profile is not None else f"seabed.slope {self.slope:g} rad"
            raise ValueError(f"seabed.grid and {given} both give the seabed. Suggested fix: give the seabed once: "
                             "its depths in the grid, and leave the slope and the profile out.")
        return self

    @model_serializer(mode="wrap")
    def _omit_unset_grid(self, handler):
        # 'grid' appears in a dumped case (a result's 'case' attribute) only when given: the cases without it read
        # as they did before it existed
        data = handler(self)
        if isinstance(data, dict) and data.get("grid", 0) is None:
            del data["grid"]
        return data

    @property
    def tabulated(self) -> bool:
        """Whether the seabed is a profile or a grid (it gives the depth: the environment's depth may be left out)."""
        return self.profile is not None or self.grid is not None


def seabed_elevation(seabed: Seabed, x: float, y: float, what: str) -> float:
    """The elevation [m] of ``seabed``'s grid under ``(x, y)`` [m], for ``what`` stands there (an anchor); an
    InputError naming it, where, and a fix when the grid does not cover the point or it lies over land."""
    from .bathymetry import cartesian_grid

    grid = cartesian_grid(seabed.grid)
    grid.check_covers(np.array([[x, y, 0.0]]), what)
    return float(grid.at(x, y)[0])


class Waves(Model):
    """Regular (Airy) waves: height, period, heading and phase (see :mod:`seacable.waves`).

    Parameters
    ----------
    height
        Crest-to-trough height. [m]
    period
        Period. [s]
    heading
        Direction the waves travel towards, from +X towards +Y. [rad]
    phase
        Phase of the elevation at the origin at t = 0. [rad]
    stretching
        Kinematics above the still-water level: "none" (the z = 0 values up to the instantaneous
        surface, the default) or "wheeler" (Wheeler stretching, see :func:`seacable.mooring.kernel._fluid`).
    """

    height: quantity("m", ge=0, fix="give the crest-to-trough height in metres.") = Field(
        description="Wave height. [m]")
    period: quantity("s", gt=0, fix="give the wave period in seconds, e.g. 10.") = Field(
        description="Wave period. [s]")
    heading: quantity("rad") = Field(0.0, description="Direction of travel. [rad]")
    phase: quantity("rad") = Field(0.0, description="Phase at the origin at t = 0. [rad]")
    stretching: Literal["none", "wheeler"] = Field(
        "none", description="Kinematics above z = 0: 'none' (constant) or 'wheeler' (Wheeler stretching).")

    @model_validator(mode="after")
    def _check(self) -> Waves:
        _warn_if_degrees("waves.heading", self.heading, 2 * math.pi)
        return self


#: Least share of a spectrum's energy a given frequency_range must hold (:meth:`IrregularWaves.energy_share`). [-]
MIN_ENERGY_SHARE = 0.5


class IrregularWaves(Model):
    """An irregular sea from a spectrum, by random-phase linear superposition (see :mod:`seacable.seastate`).

    Parameters
    ----------
    spectrum
        "jonswap" (DNV-RP-C205 3.5.5.2, with hs, tp, gamma), "pierson_moskowitz" (hs, tp) or "table"
        (``frequencies`` and ``density``).
    hs
        Significant wave height Hs = 4 sqrt(m0); the generated sea has exactly this m0. [m]
    tp
        Peak period. [s]
    gamma
        JONSWAP peak enhancement factor (>= 1; 1 is Pierson-Moskowitz); left out (None), DNV-RP-C205
        3.5.5.5's rule from Tp / sqrt(Hs): 5 up to 3.6, ``exp(5.75 - 1.15 Tp / sqrt(Hs))`` between, 1 from 5
        (:func:`seacable.seastate.jonswap_gamma`; :meth:`peak_enhancement` gives the value used). [-]
    frequencies
        A table spectrum's angular frequencies, strictly increasing (> 0). [rad/s]
    density
        A table spectrum's one-sided spectral density at ``frequencies`` (>= 0). [m^2 s/rad]
    heading
        Mean direction the waves travel towards, from +X towards +Y. [rad]
    spreading
        Exponent s of DNV's cos-2s directional spreading (> 0); left out for a long-crested sea. [-]
    seed
        Seed of the random phases, frequencies and directions (the same seed, the same sea).
    n_components
        Number of wave components (equal frequency bands, a random frequency in each).
    frequency_range
        [lowest, highest] angular frequency of the components; default the band holding all but 1 %
        of the spectrum's energy. [rad/s]
    stretching
        Kinematics above the still-water level: "none" (the z = 0 values) or "wheeler".
    """

    spectrum: Literal["jonswap", "pierson_moskowitz", "table"] = Field(description="Spectrum shape.")
    hs: quantity("m", gt=0, fix="give the significant wave height in metres, e.g. 4.") | None = Field(
        None, description="Significant wave height. [m]")
    tp: quantity("s", gt=0, fix="give the peak period in seconds, e.g. 10.") | None = Field(
        None, description="Peak period. [s]")
    gamma: quantity("-", ge=1, fix="give a peak enhancement factor between 1 (Pierson-Moskowitz) and 7 (3.3 is "
                                   "the JONSWAP mean), or leave it out for DNV-RP-C205's rule from "
                                   "Tp / sqrt(Hs).") | None = Field(
        None, description="Peak enhancement; None: DNV-RP-C205 3.5.5.5's rule from Tp / sqrt(Hs). [-]")
    frequencies: tuple[float, ...] | None = Field(None, description="Table frequencies. [rad/s]")
    density: tuple[float, ...] | None = Field(None, description="Table spectral density. [m^2 s/rad]")
    heading: quantity("rad") = Field(0.0, description="Mean direction of travel. [rad]")
    spreading: quantity("-", gt=0, fix="give the cos-2s exponent s, e.g. 15 for wind sea, or leave it out for "
                                       "a long-crested sea.") | None = Field(
        None, description="cos-2s spreading exponent s; None: long-crested. [-]")
    seed: int = Field(0, ge=0, description="Random seed.")
    n_components: int = Field(200, ge=1, le=100000, description="Number of wave components.")
    frequency_range: tuple[unit_float("rad/s"), unit_float("rad/s")] | None = Field(None, description="Component frequency band. [rad/s]")
    stretching: Literal["none", "wheeler"] = Field(
        "none", description="Kinematics above z = 0: 'none' (constant) or 'wheeler' (Wheeler stretching).")

    @model_validator(mode="after")
    def _check(self) -> IrregularWaves:
        _warn_if_degrees("waves.heading", self.heading, 2 * math.pi)
        if self.spectrum == "table":
            if self.frequencies is None or self.density is None:
                raise ValueError("spectrum 'table' needs 'frequencies' [rad/s] and 'density' [m^2 s/rad]. "
                                 "Suggested fix: give both lists, of equal length.")
            if self.hs is not None or self.tp is not None:
                raise ValueError("spectrum 'table' takes its Hs and Tp from the table; 'hs' and 'tp' must be "
                                 "left out. Suggested fix: drop them, or scale the table's density.")
            w = np.asarray(self.frequencies, float)
            s = np.asarray(self.density, float)
            if w.size != s.size or w.size < 2:
                raise ValueError(f"frequencies and density must have the same length (>= 2), got {w.size} and "
                                 f"{s.size}. Suggested fix: one density per frequency.")
            if not (np.all(np.isfinite(w)) and np.all(np.isfinite(s))):
                raise ValueError("frequencies and density must be finite numbers [rad/s, m^2 s/rad].")
            if w[0] <= 0 or np.any(np.diff(w) <= 0):
                raise ValueError(f"frequencies must be > 0 rad/s and strictly increasing, got {[float(x) for x in w]} rad/s. "
                                 "Suggested fix: sort the table by frequency (angular, rad/s = 2 pi Hz).")
            if np.any(s < 0) or not np.any(s > 0):
                raise ValueError(f"density must be >= 0 m^2 s/rad with some positive value, got {[float(x) for x in s]}.")
        else:
            if self.frequencies is not None or self.density is not None:
                raise ValueError(f"'frequencies' and 'density' belong to spectrum 'table', not '{self.spectrum}'. "
                                 "Suggested fix: drop them, or set spectrum: table.")
            missing = [k for k in ("hs", "tp") if getattr(self, k) is None]
            if missing:
                raise ValueError(f"spectrum '{self.spectrum}' needs {' and '.join(missing)}. Suggested fix: "
                                 "give hs [m] and tp [s].")
            if self.spectrum == "jonswap" and self.gamma is not None and self.gamma > 7.0:
                warnings.warn(f"waves.gamma = {self.gamma:g} is outside DNV's 1-7 range of JONSWAP peak factors "
                              "(A_gamma = 1 - 0.287 ln gamma is fitted there).", SeacableWarning, stacklevel=3)
        if self.frequency_range is not None:
            lo, hi = self.frequency_range
            if not (math.isfinite(lo) and math.isfinite(hi) and 0 < lo < hi):
                raise ValueError(f"frequency_range must be [lowest, highest] with 0 < lowest < highest [rad/s], "
                                 f"got {list(self.frequency_range)}. Suggested fix: e.g. [0.3, 2.5] rad/s.")
            shortest = 2.0 * math.pi * STANDARD_GRAVITY / hi ** 2  # deep water's, the longest at hi
            if shortest < MIN_WAVELENGTH:
                raise ValueError(f"frequency_range's highest frequency {hi:g} rad/s gives components {shortest:.3g} m "
                                 f"long, under {MIN_WAVELENGTH:g} m: capillary ripples, not gravity waves (and a "
                                 "kinematics grid a tenth of that apart). Suggested fix: a highest frequency of a few "
                                 "rad/s (frequencies in rad/s = 2 pi Hz), or leave frequency_range out.")
            share = self.energy_share(lo, hi)
            if share < MIN_ENERGY_SHARE:
                raise ValueError(f"frequency_range [{lo:g}, {hi:g}] rad/s holds {share:.3g} of the spectrum's energy "
                                 f"(less than {MIN_ENERGY_SHARE:g}); the components are scaled to the sea's Hs, so the "
                                 "sea would be made of these frequencies alone, not of the spectrum asked for. "
                                 "Suggested fix: a band around the peak (2 pi / tp rad/s), or leave frequency_range "
                                 "out (the band holding 99 % of the energy).")
        return self

    def energy_share(self, lo: float, hi: float) -> float:
        """The fraction of the spectrum's variance m0 between ``lo`` and ``hi`` [rad/s]. [-]"""
        wp = self.peak_frequency()
        if self.spectrum == "table":
            w = np.union1d(np.asarray(self.frequencies, float), [lo, hi])
        else:
            w = np.union1d(np.linspace(0.05 * wp, 20.0 * wp, 40001), [lo, hi])
        s = self.spectral_density(w)
        inside = (w >= lo) & (w <= hi)
        total = float(np.trapezoid(s, w))
        return float(np.trapezoid(s[inside], w[inside])) / total if total > 0 else 0.0

    def sea_state(self) -> tuple[float, float, str]:
        """``(Hs [m], Tp [s], how)``: the given ones, or a table spectrum's ``Hs = 4 sqrt(m0)`` (``m0`` the
        table's integral, linear between its points) and peak period, ``how`` saying so for messages."""
        if self.spectrum != "table":
            return float(self.hs), float(self.tp), ""
        m0 = float(np.trapezoid(np.asarray(self.density, float), np.asarray(self.frequencies, float)))
        tp = 2.0 * math.pi / self.peak_frequency()
        return 4.0 * math.sqrt(m0), tp, f" (Hs = 4 sqrt(m0), m0 = {m0:.4g} m^2 the table's integral)"

    def peak_enhancement(self) -> float | None:
        """The JONSWAP peak enhancement factor the sea uses: the given ``gamma``, else DNV-RP-C205's rule
        (:func:`seacable.seastate.jonswap_gamma`); None for another spectrum. [-]"""
        from . import seastate as ss

        if self.spectrum != "jonswap":
            return None
        return float(self.gamma) if self.gamma is not None else ss.jonswap_gamma(self.hs, self.tp)

    def spectral_density(self, omega):
        """The target one-sided spectrum S(omega) [m^2 s/rad] at angular frequencies ``omega`` [rad/s]."""
        from . import seastate as ss

        if self.spectrum == "table":
            return ss.table_spectrum(omega, self.frequencies, self.density)
        if self.spectrum == "pierson_moskowitz":
            return ss.pierson_moskowitz(omega, self.hs, self.tp)
        return ss.jonswap(omega, self.hs, self.tp, self.peak_enhancement())

    def peak_frequency(self) -> float:
        """Angular frequency of the spectrum's peak. [rad/s]"""
        if self.spectrum == "table":
            return float(self.frequencies[int(np.argmax(self.density))])
        return 2.0 * math.pi / self.tp

    def components(self, depth=None, gravity=9.80665):
        """The sea's components (:func:`seacable.seastate.synthesise`) in water of ``depth`` [m]."""
        from . import seastate as ss

        band = self.frequency_range or ss.frequency_range(self.spectral_density, self.peak_frequency())
        return ss.synthesise(self.spectral_density, n_components=self.n_components, omega_range=band,
                             seed=self.seed, heading=self.heading, spreading=self.spreading, depth=depth,
                             gravity=gravity, hs=self.hs)


class Wind(Model):
    """Wind over the water (issue 39): a mean speed with its profile and a gust spectrum (DNV-RP-C205 2.3,
    :mod:`seacable.wind`), loading the bodies that give their wind areas (``bodies.NAME.wind``).

    Parameters
    ----------
    speed
        The 1-hour mean speed at 10 m above the still-water level, U0. [m/s]
    heading
        The direction the wind blows towards, from +x towards +y. [rad]
    spectrum
        ``npd`` (Froya), ``api`` (API RP 2A / 2SK, peak ``peak``) or ``none`` (a steady wind).
    peak
        API's spectral peak f_p. [Hz]
    seed
        Seed of the gust record.
    n_components
        Components of the gust record (0.001-0.5 Hz).
    """

    speed: quantity("m/s", ge=0, fix="give the 1-hour mean wind speed at 10 m in m/s.") = Field(
        description="1-hour mean speed at 10 m, U0. [m/s]")
    heading: quantity("rad") = Field(0.0, description="Direction the wind blows towards. [rad]")
    spectrum: Literal["npd", "api", "none"] = Field("npd", description="Gust spectrum: npd, api or none.")
    peak: quantity("Hz", ge=0.01, le=0.1) = Field(0.025, description="API's spectral peak f_p. [Hz]")
    seed: int = Field(0, ge=0, description="Seed of the gust record.")
    n_components: int = Field(1000, ge=1, le=100_000, description="Components of the gust record.")


class Environment(Model):
    """Water, gravity, depth, current and seabed.

    Parameters
    ----------
    water_density
        Sea water density. [kg/m^3]
    gravity
        Acceleration of gravity. [m/s^2]
    depth
        Water depth at the origin; ``None`` for deep water with no seabed. [m]
    current
        The current.
    seabed
        The seabed.
    waves
        Regular waves (:class:`Waves`) or an irregular sea (:class:`IrregularWaves`, a mapping with a
        ``spectrum`` key), used by the mooring dynamics; ``None`` for calm water.
    wind
        The wind (:class:`Wind`) on the bodies of a mooring system's dynamics; ``None`` for no wind.
    """

    water_density: quantity("kg/m^3", gt=0, fix="sea water is about 1025 kg/m^3.") = Field(
        1025.0, description="Water density. [kg/m^3]")
    gravity: quantity("m/s^2", gt=0) = Field(9.81, description="Gravity. [m/s^2]")
    depth: quantity("m", gt=0, fix="give the water depth in metres as a positive number.") | None = Field(
        None, description="Water depth; left out for deep water. [m]")
    current: Current = Current()
    seabed: Seabed = Seabed()
    waves: Waves | IrregularWaves | None = None
    wind: Wind | None = None

    @field_validator("waves", mode="before")
    @classmethod
    def _which_waves(cls, value):
        # a mapping with 'spectrum' is an irregular sea, any other mapping regular waves
        if isinstance(value, dict):
            return IrregularWaves(**value) if "spectrum" in value else Waves(**value)
        return value

    @model_validator(mode="after")
    def _sea_state(self) -> Environment:
        """The one breaking and steepness check of the waves, regular or irregular
        (:func:`seacable.waves.check_sea_state`): refuse the impossible, warn the suspicious."""
        w = self.waves
        if w is None or not self.gravity > 0:
            return self
        if isinstance(w, IrregularWaves):
            hs, tp, how = w.sea_state()
            keys = ("hs", "tp") if w.spectrum != "table" else ("density's Hs", "frequencies' peak period Tp")
            found = check_sea_state(hs, tp, self.depth, self.gravity, irregular=True, how=how,
                                    height_key=keys[0], period_key=keys[1])
        else:
            found = check_sea_state(w.height, w.period, self.depth, self.gravity, irregular=False,
                                    height_key="height", period_key="period")
        if found.refused:  # each message starts with its key: "environment.waves" + ".hs = ..."
            raise input_error([(("waves",), "." + m) for m in found.refused])
        for message in found.warned:
            warnings.warn(f"environment.waves.{message}", SeacableWarning, stacklevel=3)
        return self

    def origin_depth(self) -> float | None:
        """The water depth under the origin [m]: ``depth``, else the seabed profile's or grid's there (the grid's
        nearest edge beyond it); None without a seabed."""
        if self.depth is not None or not self.seabed.tabulated:
            return self.depth
        if self.seabed.profile is not None:
            return float(np.interp(0.0, self.seabed.profile.distance, self.seabed.profile.depth))
        from .bathymetry import cartesian_grid

        return float(-cartesian_grid(self.seabed.grid).at(0.0, 0.0)[0])

    @model_validator(mode="after")
    def _check(self) -> Environment:
        if not 900.0 <= self.water_density <= 1100.0:
            warnings.warn(f"environment.water_density = {self.water_density:g} kg/m^3 is far from "
                          "water's ~1000-1030 kg/m^3.", SeacableWarning, stacklevel=3)
        return self


class SystemEnvironment(Environment):
    """The environment of a mooring system (:class:`~seacable.system.case.SystemCase`).

    As :class:`Environment`, except that gravity and water density may be 0, as MoorDyn's own test
    decks use them to switch effects off:

    - ``gravity: 0`` switches gravity off: nothing has weight nor buoyancy (lines, points and bodies),
      no waterplane restoring; masses keep their inertia in the dynamics. Waves need gravity and are
      refused.
    - ``water_density: 0`` switches the water off: no buoyancy (lines weigh ``m g`` per metre, bodies
      and points their weight in air), no waterplane restoring, no drag and no added mass.

    Parameters
    ----------
    water_density
        Sea water density; 0 for no buoyancy nor hydrodynamic loads. [kg/m^3]
    gravity
        Acceleration of gravity; 0 for no weight nor buoyancy. [m/s^2]
    """

    water_density: quantity("kg/m^3", ge=0, fix="sea water is about 1025 kg/m^3 (0 switches buoyancy off).") = \
        Field(1025.0, description="Water density; 0 for no buoyancy nor hydrodynamic loads. [kg/m^3]")
    gravity: quantity("m/s^2", ge=0, fix="give g, e.g. 9.81 m/s^2 (0 switches gravity off).") = Field(
        9.81, description="Gravity; 0 for no weight nor buoyancy. [m/s^2]")

    @model_validator(mode="after")
    def _check(self) -> SystemEnvironment:
        if self.water_density != 0.0 and not 900.0 <= self.water_density <= 1100.0:
            warnings.warn(f"environment.water_density = {self.water_density:g} kg/m^3 is far from "
                          "water's ~1000-1030 kg/m^3 (0 switches buoyancy off).", SeacableWarning, stacklevel=3)
        if self.gravity == 0.0 and self.waves is not None:
            raise ValueError("environment.waves need gravity (their dispersion omega^2 = g k tanh(k d)), but "
                             "environment.gravity = 0 m/s^2 switches it off. Suggested fix: give gravity (e.g. "
                             "9.81 m/s^2) or drop the waves.")
        return self

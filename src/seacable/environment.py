"""The environment: water, gravity, depth, current and seabed.

Coordinates: Z up, z = 0 at the mean sea surface, the seabed at z = -depth
under the origin. Angles are in radians; a heading is the direction the current
flows *towards*, measured from +X towards +Y.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from pydantic import Field, model_validator

from ._model import Model, quantity
from .errors import SeacableWarning

__all__ = ["Current", "Environment", "Seabed", "SystemEnvironment", "Waves"]


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
    depths: tuple[float, ...] | None = Field(None, description="Profile depths below the surface. [m]")
    speeds: tuple[float, ...] | None = Field(None, description="Profile speeds. [m/s]")

    @model_validator(mode="after")
    def _check(self) -> "Current":
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
                raise ValueError(f"depths must be >= 0 m and strictly increasing, got {list(d)} m. "
                                 "Suggested fix: give depths below the surface as positive numbers, "
                                 "top first.")
        return self

    @classmethod
    def uniform(cls, speed: float, heading: float = 0.0) -> "Current":
        """A current of one ``speed`` [m/s] at every depth, towards ``heading`` [rad]."""
        return cls(speed=speed, heading=heading)

    @classmethod
    def profile(cls, depths, speeds, heading: float = 0.0) -> "Current":
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


class Seabed(Model):
    """A plane seabed.

    Parameters
    ----------
    slope
        Slope angle, positive when the seabed rises towards +X. [rad]
    friction
        Coulomb friction coefficient of the line on the seabed. [-]
    """

    slope: quantity("rad", gt=-math.pi / 2, lt=math.pi / 2,
                    fix="give the slope in radians (5 deg = 0.0873 rad).") = Field(
        0.0, description="Slope, positive rising towards +X. [rad]")
    friction: quantity("-", ge=0, fix="give a friction coefficient such as 0.5 (chain on clay ~ 1).") = Field(
        0.0, description="Coulomb friction coefficient. [-]")

    @model_validator(mode="after")
    def _check(self) -> "Seabed":
        _warn_if_degrees("seabed.slope", self.slope, math.radians(45))
        return self


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
    """

    height: quantity("m", ge=0, fix="give the crest-to-trough height in metres.") = Field(
        description="Wave height. [m]")
    period: quantity("s", gt=0, fix="give the wave period in seconds, e.g. 10.") = Field(
        description="Wave period. [s]")
    heading: quantity("rad") = Field(0.0, description="Direction of travel. [rad]")
    phase: quantity("rad") = Field(0.0, description="Phase at the origin at t = 0. [rad]")

    @model_validator(mode="after")
    def _check(self) -> "Waves":
        _warn_if_degrees("waves.heading", self.heading, 2 * math.pi)
        return self


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
        Regular waves, used by the mooring dynamics; ``None`` for calm water.
    """

    water_density: quantity("kg/m^3", gt=0, fix="sea water is about 1025 kg/m^3.") = Field(
        1025.0, description="Water density. [kg/m^3]")
    gravity: quantity("m/s^2", gt=0) = Field(9.81, description="Gravity. [m/s^2]")
    depth: quantity("m", gt=0, fix="give the water depth in metres as a positive number.") | None = Field(
        None, description="Water depth; left out for deep water. [m]")
    current: Current = Current()
    seabed: Seabed = Seabed()
    waves: Waves | None = None

    @model_validator(mode="after")
    def _check(self) -> "Environment":
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

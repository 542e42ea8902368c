"""A lay or tow vessel that moves in the sea: its chute or tow point on the vessel's RAOs (issue 41).

A ``laying_dynamic`` or ``towed_dynamic`` case's ``motion`` moves the water entry (the chute) or the tow point
with the vessel's first-order response to the case's waves, on top of the planned track (the lay's ship track,
the tow's vessel path). The six motions come from the RAO path the moorings use (:class:`seacable.mooring.motion.
RAOMotion`, :class:`seacable.raos.RAOResponse`): the RAO table of ``file`` read at the sea's components, regular
waves as one component or the environment's irregular sea (:mod:`seacable.seastate`), with the smooth ``ramp``.

Frames. The vessel frame has x forward (along the track at the start), y to port and z up from the mean waterline;
``reference`` is the RAO reference point (the centre of the rotations) and ``point`` the chute or tow point in it.
With the six motions ``q = (surge, sway, heave, roll, pitch, yaw)`` (R = Rz(yaw) Ry(pitch) Rx(roll)) the point
moves from its place at rest by

    o(t) = d(t) + (R(t) - I) (point - reference)                                 (d: surge, sway, heave)

in the vessel frame, turned into the global frame by the vessel's heading psi (from +X towards +Y):
heave and pitch at a chute ``a`` metres astern of the reference lift it by ``heave + a pitch``; pitch at a chute
``h`` metres above the waterline moves it forward by ``h pitch``. The track's ground point is the point's position
at rest (the run's chute or tow point as without motion), and ``o`` is added to it, with its velocity (and, for
the finite-element tow, its acceleration). In paper 001's 2-D plane (a lay without a route) the x and z of ``o``
enter, the y is not modelled (a warning says how large it is).

The vessel keeps its heading psi for its motions: psi is the track's direction at the start, or the one that puts
the mean waves at ``wave_heading`` off the bow. The RAOs are read at the absolute wave frequencies and the phases
at the reference point's start position: a vessel that lays or tows at a few knots meets the waves at the
encounter frequency ``w - k U cos(beta)``, which zero-speed RAOs do not give (a limit of the model, as of the
RAOs of most lay vessels).

References
----------
.. [1] Faltinsen, O. M. (1990). Sea Loads on Ships and Offshore Structures. Cambridge University Press,
   ch. 3 (rigid-body motions of a ship in waves, RAOs, the motion of a point on the ship).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from typing import Literal

import numpy as np
from pydantic import Field, model_serializer, model_validator

from ._model import Model, quantity, unit_float
from ._window import omit_unset_window
from .errors import InputError, SeacableWarning
from .mooring.motion import RAOMotion, _rigid_channels

__all__ = ["VesselMotion", "VesselMotionOption", "bind_vessel_motion", "sea_of_environment"]

_XYZ = tuple[unit_float("m"), unit_float("m"), unit_float("m")]


class VesselMotion(Model):
    """The vessel's motion in the case's waves from its RAO table, at the chute (lay) or the tow point (tow).

    See :mod:`seacable.vessel_motion` for the frames and the formula.
    """

    type: Literal["rao"] = "rao"
    file: str = Field(description="RAO table of the vessel: WAMIT option-4 output ('.4'), or a CSV in SI units "
                                  "(frequency [rad/s], heading [rad], dof, amplitude, phase [rad]); relative to the "
                                  "case file.")
    format: Literal["auto", "wamit", "csv"] = Field(
        "auto", description="Format of 'file': 'auto' reads a '.csv' as CSV and anything else as WAMIT '.4'.")
    ulen: quantity("m", gt=0, fix="give WAMIT's length scale ULEN in metres (1 when the file is dimensional).") = \
        Field(1.0, description="WAMIT's length scale ULEN: rotations in the file are per ULEN. [m]")
    reference: _XYZ = Field((0.0, 0.0, 0.0), description="RAO reference point (centre of the rotations) in the "
                                                          "vessel frame: x forward, y to port, z up from the mean "
                                                          "waterline. [m]")
    point: _XYZ = Field(description="The chute (laying_dynamic: where the cable leaves the vessel) or the tow point "
                                    "(towed_dynamic) in the vessel frame, at or above the waterline. [m]")
    wave_heading: quantity("rad") | None = Field(
        None, description="Direction the mean waves travel towards, relative to the bow (the RAO table's heading: 0 "
                          "following seas, pi head seas, pi/2 waves travelling to port); default the waves' heading "
                          "relative to the track's direction at the start. [rad]")
    ramp: quantity("s", ge=0) = Field(0.0, description="Duration of the smooth start of the motion. [s]")

    @model_validator(mode="after")
    def _check(self):
        for key, vec in (("reference", self.reference), ("point", self.point)):
            if not all(math.isfinite(v) for v in vec):
                raise ValueError(f"motion.{key} must hold three finite numbers (x, y, z) in m, got {vec}.")
        if self.point[2] < 0.0:
            raise ValueError(f"motion.point z = {self.point[2]:g} m puts the chute or tow point under water (z is up from "
                             "the mean waterline, and the cable leaves the vessel there). Suggested fix: give its "
                             "height above the waterline (>= 0 m), e.g. 3 m for a stern chute.")
        b = self.wave_heading
        if b is not None and not -2 * math.pi <= b <= 2 * math.pi:
            raise ValueError(f"motion.wave_heading = {b:g} rad is out of range: a heading lies within [-2 pi, 2 pi] rad "
                             f"([-360, 360] deg). Suggested fix: give it in radians, or with a unit ('{b:g} deg' is "
                             f"{math.radians(b):.4g} rad).")
        return self

    def rao_motion(self, at=(0.0, 0.0)) -> RAOMotion:
        """The mooring model's :class:`~seacable.mooring.motion.RAOMotion` of this table, its phases referred to the
        point ``at`` (x, y) [m] of the frame the sea is given in."""
        return RAOMotion(file=self.file, format=self.format, ulen=self.ulen, reference=(at[0], at[1], 0.0),
                         ramp=self.ramp)


class VesselMotionOption(Model):
    """The ``motion`` option of the lay and tow analyses (a mixin): the vessel on its RAOs in the case's waves,
    which such a case then takes (its ``uses``)."""

    motion: VesselMotion | None = Field(
        None, description="The vessel's motion in the waves from its RAOs, at the chute or tow point (type 'rao').")

    def uses(self, env) -> frozenset[str]:
        """The environment inputs of the analysis: its ``USES``, and the waves that move the vessel."""
        return frozenset(self.USES) | ({"waves"} if self.motion is not None else frozenset())

    @model_serializer(mode="wrap")
    def _omit_unset_window(self, handler):
        """Drop an unset ``motion`` (and an unset ``statistics_from``, :func:`seacable._window.omit_unset_window`: one
        serializer serves the class) from the dumped analysis, so that a case without them dumps, and a result records
        it, as before the options existed."""
        data = handler(self)
        if isinstance(data, dict) and "motion" in data and data["motion"] is None:
            del data["motion"]
        return omit_unset_window(data)


def sea_of_environment(environment):
    """The waves of an environment as sea components (:class:`seacable.seastate.SeaComponents`): its irregular
    sea's components, its regular wave as one component, or None in calm water (as
    :func:`seacable.mooring.motion.sea_of` for a mooring's water)."""
    from .environment import IrregularWaves
    from .seastate import SeaComponents
    from .waves import wave_number

    w, g, depth = environment.waves, environment.gravity, environment.depth
    if w is None:
        return None
    if isinstance(w, IrregularWaves):
        return w.components(depth, g)
    if w.height <= 0.0:
        return None
    k = float(wave_number(w.period, depth, g))
    return SeaComponents(amplitude=np.array([0.5 * w.height]), omega=np.array([2 * math.pi / w.period]),
                         wave_number=np.array([k]), heading=np.array([w.heading]), phase=np.array([w.phase]),
                         depth=math.inf if depth is None else float(depth), gravity=g, mean_heading=w.heading)


def bind_vessel_motion(motion: VesselMotion | None, environment, *, heading: float, start, duration: float,
                       dims: int = 3):
    """The chute's or tow point's offset from its track, a function of time, or None without ``motion``.

    Parameters
    ----------
    motion
        The case's vessel motion.
    environment
        The case's environment (its waves).
    heading
        The vessel's heading, from +X towards +Y: the track's direction at the start. [rad]
    start
        The point's ground position (x, y) at t = 0 (its RAO phases are referred to the reference point there). [m]
    duration
        The run's duration; the motion is evaluated at 0 and ``duration`` here, so that what fails, fails
        before the run. [s]
    dims
        3 (x, y, z) or 2 (x, z: paper 001's plane along +X).

    Returns
    -------
    callable or None
        ``f(times)`` -> offsets, velocities and accelerations, each (len(times), dims). [m, m/s, m/s^2]

    Raises
    ------
    InputError
        Calm water, an RAO file that does not exist or does not cover the sea.
    """
    if motion is None:
        return None
    sea = sea_of_environment(environment)
    if sea is None:
        raise InputError("analysis.motion moves the vessel on its RAOs in the case's waves, but the environment has "
                         "none. Suggested fix: give environment.waves (regular waves, or an irregular sea with "
                         "'spectrum'), or leave motion out.")
    psi = float(heading) if motion.wave_heading is None else float(sea.mean_heading) - float(motion.wave_heading)
    c, s = math.cos(psi), math.sin(psi)
    arm = np.asarray(motion.point, float) - np.asarray(motion.reference, float)
    # the reference point at the start, in axes turned by psi (the frame of the RAO table's headings)
    gx = float(start[0]) - (c * arm[0] - s * arm[1])
    gy = float(start[1]) - (s * arm[0] + c * arm[1])
    at = (c * gx + s * gy, -s * gx + c * gy)
    turned = dataclasses.replace(sea, heading=np.asarray(sea.heading, float) - psi,
                                 mean_heading=float(sea.mean_heading) - psi)
    try:
        bound = motion.rao_motion(at).in_sea(turned)
    except InputError as err:
        text = str(err)
        raise InputError(text if text.startswith("motion.") else f"analysis.motion: {text}") from None

    def offsets(times, dims=dims):
        q, dq, ddq = bound.dofs(np.atleast_1d(np.asarray(times, float)))
        # the point about the reference at the origin: o = x - arm, exactly 0 when the motions are (R = I)
        x, v, a = _rigid_channels((0.0, 0.0, 0.0), arm[None, :], q, dq, ddq)
        out = []
        for vec in (x[:, 0] - arm, v[:, 0], a[:, 0]):
            gxv = c * vec[:, 0] - s * vec[:, 1]
            cols = (gxv, vec[:, 2]) if dims == 2 else (gxv, s * vec[:, 0] + c * vec[:, 1], vec[:, 2])
            out.append(np.column_stack(cols))
        return tuple(out)

    offsets(np.array([0.0, float(duration)]))
    if dims == 2:
        across = float(np.max(np.abs(offsets(np.linspace(0.0, float(duration), 2001), 3)[0][:, 1])))
        if across > 1e-6:                 # (a heading of pi leaves round-off across: 1e-16 m)
            warnings.warn(f"analysis.motion moves the chute up to {across:.3g} m across the track (sway, roll, yaw), "
                          "which paper 001's 2-D plane does not model: only the motion along the track and up enters. "
                          "Suggested fix: give analysis.route to lay in 3-D.", SeacableWarning, stacklevel=2)
    return offsets

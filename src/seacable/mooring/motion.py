"""Prescribed fairlead motion: harmonic, a time series (CSV), or a rigid platform carrying fairleads.

Each motion is a case-file model with a method ``channels(times, base)`` returning the positions,
velocities and accelerations of the moved points, shape (len(times), n_points, 3), given their
positions ``base`` (n_points, 3) at rest. Motions start from rest at ``base``: the offset is
multiplied by a smooth ramp ``r(t) = (1 - cos(pi t / T_ramp)) / 2`` over ``ramp`` seconds.
"""

from __future__ import annotations

import functools
import io
import math
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Literal

import numpy as np
from pydantic import Field, model_validator

from .._model import UNION_TAGS, Model, quantity, unit_float
from .._ramp import smooth_ramp
from .._text import read_text_file
from ..errors import InputError, SeacableWarning

__all__ = ["HarmonicMotion", "Motion", "PlatformMotion", "RAOMotion", "SeaRAOMotion", "TimeSeriesMotion", "bind",
           "forcing_period", "rotation_matrix", "sea_of"]

_XYZ = tuple[unit_float("m"), unit_float("m"), unit_float("m")]
#: x, y, z [m], roll, pitch, yaw [rad]
_SIX = tuple[unit_float("m"), unit_float("m"), unit_float("m"), unit_float("rad"), unit_float("rad"), unit_float("rad")]
_PHASES = tuple[(unit_float("rad"),) * 6]


def _ramped(off, doff, ddoff, times, T):
    """Offset signals (nt, k) times the ramp, with the product rule."""
    r, dr, ddr = (a[:, None] for a in smooth_ramp(times, T))
    return off * r, doff * r + off * dr, ddoff * r + 2 * doff * dr + off * ddr


class HarmonicMotion(Model):
    """Harmonic translation ``x(t) = base + amplitude sin(2 pi t / period + phase)`` of every moved point."""

    type: Literal["harmonic"] = "harmonic"
    amplitude: _XYZ = Field(description="Amplitude of the motion in x, y, z. [m]")
    period: quantity("s", gt=0, fix="give the period in seconds, e.g. 10.") = Field(description="Period. [s]")
    phase: quantity("rad") = Field(0.0, description="Phase at t = 0. [rad]")
    ramp: quantity("s", ge=0) = Field(0.0, description="Duration of the smooth start. [s]")

    def channels(self, times, base):
        t = np.asarray(times, float)
        w = 2 * math.pi / self.period
        amp = np.asarray(self.amplitude, float)
        arg = (w * t + self.phase)[:, None]
        off, doff, ddoff = _ramped(np.sin(arg) * amp, w * np.cos(arg) * amp, -w * w * np.sin(arg) * amp, t, self.ramp)
        return _apply(base, off, doff, ddoff)


def _apply(base, off, doff, ddoff):
    base = np.asarray(base, float)
    nt, k = off.shape[0], base.shape[0]
    x = base[None, :, :] + off[:, None, :]
    v = np.broadcast_to(doff[:, None, :], (nt, k, 3)).copy()
    a = np.broadcast_to(ddoff[:, None, :], (nt, k, 3)).copy()
    return x, v, a


def _read_table(path: Path, names: tuple[str, ...], what: str = "motion file") -> np.ndarray:
    """A CSV of named columns (a header row; '#' comments) -> array with the columns of ``names``; ``what`` the
    file is, for messages (a motion file, a force series)."""
    text = read_text_file(path, what, "give its path relative to the case file")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # numpy's own warnings on odd rows: the checks below say what is wrong
            data = np.genfromtxt(io.StringIO(text), delimiter=",", names=True, comments="#", dtype=float)
    except ValueError as err:
        raise InputError(f"{what} '{path}' is not a CSV table of numbers: {err}.") from None
    have = data.dtype.names or ()
    missing = [n for n in names if n not in have]
    if "time" in missing or len(missing) == len(names):
        raise InputError(f"{what} '{path}' needs a header with columns 'time' and some of "
                         f"{', '.join(names[1:])}; found {', '.join(have) or 'none'}.")
    cols = [np.atleast_1d(data[n]) if n in have else np.zeros(np.atleast_1d(data["time"]).size) for n in names]
    table = np.column_stack(cols)
    if table.shape[0] < 2:
        raise InputError(f"{what} '{path}' needs at least two rows of numbers, got {table.shape[0]}. Suggested fix: "
                         "one row per time, the first at or before the run's start and the last at or after its end.")
    rows, columns = np.nonzero(~np.isfinite(table))
    if rows.size:
        raise InputError(f"{what} '{path}': the value of '{names[columns[0]]}' in data row {rows[0] + 1} is not a "
                         "finite number (empty, a word, nan or inf). Suggested fix: one number per cell, SI units.")
    if np.any(np.diff(table[:, 0]) <= 0):
        raise InputError(f"{what} '{path}': time must increase strictly from row to row.")
    return table


@functools.lru_cache(maxsize=16)
def _fitted_table(path: str, stamp: tuple, names: tuple[str, ...]):
    """The table of a motion file and its natural cubic spline, read and fitted once for each version of the
    file (``stamp``: its modification time and size)."""
    from scipy.interpolate import CubicSpline

    table = _read_table(Path(path), names)
    return table[0, 0], table[-1, 0], CubicSpline(table[:, 0], table[:, 1:], bc_type="natural")


def _spline(path: Path, names: tuple[str, ...], times):
    """The columns ``names[1:]`` of a motion file at ``times`` (a natural cubic spline against its time
    column), with two derivatives. The file is read and fitted once (:func:`_fitted_table`)."""
    t = np.asarray(times, float)
    try:
        st = path.stat()
    except OSError:
        st = None
    if st is None:
        _read_table(path, names)  # its message: the file does not exist
    t0, t1, cs = _fitted_table(str(path.resolve()), (st.st_mtime_ns, st.st_size), names)
    if t.size and (t.min() < t0 - 1e-9 or t.max() > t1 + 1e-9):
        raise InputError(f"motion file '{path}' covers {t0:g} to {t1:g} s, the run needs {t.min():g} to "
                         f"{t.max():g} s. Suggested fix: extend the table or shorten 'duration'.")
    return cs(t), cs(t, 1), cs(t, 2)


class TimeSeriesMotion(Model):
    """Offsets of the moved points from a CSV file with columns ``time, x, y, z`` (any of x, y, z may be
    left out), as displacements from the rest position; a natural cubic spline gives velocity and
    acceleration."""

    type: Literal["time_series"] = "time_series"
    file: str = Field(description="CSV file, relative to the case file.")
    ramp: quantity("s", ge=0) = Field(0.0, description="Duration of the smooth start. [s]")

    def channels(self, times, base):
        off, doff, ddoff = _ramped(*_spline(Path(self.file), ("time", "x", "y", "z"), times),
                                   np.asarray(times, float), self.ramp)
        return _apply(base, off, doff, ddoff)


def rotation_matrix(roll, pitch, yaw):
    """Rotation matrices R = Rz(yaw) Ry(pitch) Rx(roll), shape (..., 3, 3)."""
    cr, sr, cp, sp, cy, sy = (np.cos(roll), np.sin(roll), np.cos(pitch), np.sin(pitch), np.cos(yaw), np.sin(yaw))
    R = np.empty(np.shape(roll) + (3, 3))
    R[..., 0, 0] = cy * cp
    R[..., 0, 1] = cy * sp * sr - sy * cr
    R[..., 0, 2] = cy * sp * cr + sy * sr
    R[..., 1, 0] = sy * cp
    R[..., 1, 1] = sy * sp * sr + cy * cr
    R[..., 1, 2] = sy * sp * cr - cy * sr
    R[..., 2, 0] = -sp
    R[..., 2, 1] = cp * sr
    R[..., 2, 2] = cp * cr
    return R


class PlatformMotion(Model):
    """Rigid-body motion of a platform carrying the moved points (fairleads).

    Six degrees of freedom (surge, sway, heave [m]; roll, pitch, yaw [rad], rotations about the
    platform's ``reference`` point, R = Rz Ry Rx) either harmonic (``amplitude`` and ``phase`` of each,
    one ``period``) or from a CSV with columns ``time, surge, sway, heave, roll, pitch, yaw``. A fairlead
    at rest at ``p`` moves to ``reference + d + R (p - reference)``.
    """

    type: Literal["platform"] = "platform"
    reference: _XYZ = Field((0.0, 0.0, 0.0), description="Centre of rotation at rest. [m]")
    amplitude: _SIX | None = Field(None, description="Harmonic amplitudes [m, m, m, rad, rad, rad].")
    phase: _PHASES = Field((0.0,) * 6, description="Phases of the six motions. [rad]")
    period: quantity("s", gt=0) | None = Field(None, description="Period of the harmonic motion. [s]")
    file: str | None = Field(None, description="CSV of the six motions, relative to the case file.")
    ramp: quantity("s", ge=0) = Field(0.0, description="Duration of the smooth start. [s]")

    @model_validator(mode="after")
    def _one_source(self):
        if (self.file is None) == (self.amplitude is None):
            raise ValueError("give either 'amplitude' (with 'period') for harmonic motion or 'file' for a time "
                             "series, not both or neither.")
        if self.amplitude is not None and self.period is None:
            raise ValueError("harmonic platform motion needs 'period' in s.")
        return self

    def dofs(self, times):
        """The six motions (nt, 6) and their time derivatives."""
        t = np.asarray(times, float)
        if self.file is not None:
            q, dq, ddq = _spline(Path(self.file), ("time", "surge", "sway", "heave", "roll", "pitch", "yaw"), t)
        else:
            w = 2 * math.pi / self.period
            arg = w * t[:, None] + np.asarray(self.phase)
            amp = np.asarray(self.amplitude, float)
            q, dq, ddq = amp * np.sin(arg), w * amp * np.cos(arg), -w * w * amp * np.sin(arg)
        return _ramped(q, dq, ddq, t, self.ramp)

    def channels(self, times, base):
        return _rigid_channels(self.reference, base, *self.dofs(times))


def _rigid_channels(reference, base, q, dq, ddq):
    """Positions, velocities and accelerations (nt, k, 3) of points at ``base`` (k, 3) at rest on a platform
    moving by the six motions ``q`` (nt, 6) about ``reference``, with the motions' derivatives."""
    base = np.asarray(base, float)
    ref = np.asarray(reference, float)
    arm = base - ref

    def position(q):
        R = rotation_matrix(q[:, 3], q[:, 4], q[:, 5])
        return ref + q[:, None, :3] + np.einsum("tij,kj->tki", R, arm)

    # velocity and acceleration of the rotating arm by central differences in the motions (not in time,
    # so a time series is never read outside its table): v = P'(q) q', a = P'(q) q'' + q'^T P''(q) q'
    h = 1e-4
    x = position(q)
    xp, xm = position(q + h * dq), position(q - h * dq)
    v = (xp - xm) / (2 * h)
    a = (xp - 2 * x + xm) / (h * h) + (position(q + h * ddq) - position(q - h * ddq)) / (2 * h)
    return x, v, a


@functools.lru_cache(maxsize=8)
def _rao_table(path: str, stamp: tuple, form: str, ulen: float):
    """The RAO table of a file, read once for each version of the file (``stamp``: its modification time and
    size)."""
    from ..raos import read_rao_csv, read_wamit4

    return read_rao_csv(path) if form == "csv" else read_wamit4(path, ulen)


class RAOMotion(Model):
    """Rigid-body motion of a platform from its response amplitude operators in the case's waves (issue 20).

    The six motions (surge, sway, heave [m]; roll, pitch, yaw [rad], about ``reference``, R = Rz Ry Rx) are
    the platform's mean position ``mean_offset`` (under steady wind, current and drift loads: given, or for a
    body of a mooring system ``equilibrium``, the body's static equilibrium under its ``external_force`` with
    the lines of the run, intact or damaged, :mod:`seacable.system.statics`) plus its first-order response to
    the environment's irregular sea or regular waves through the RAO table of ``file`` (:func:`seacable.raos.rao_motion`; the RAO phases are referred to the
    wave elevation at the reference point's horizontal position, at rest). The wave response starts with
    the smooth ramp; the mean offset is there from the start, where the static start puts the lines. A
    fairlead at rest at ``p`` moves to ``reference + d + R (p - reference)`` as with :class:`PlatformMotion`.
    """

    type: Literal["rao"] = "rao"
    file: str = Field(description="RAO table: WAMIT option-4 output ('.4'), or a CSV in SI units (frequency "
                                  "[rad/s], heading [rad], dof, amplitude, phase [rad]); relative to the case file.")
    format: Literal["auto", "wamit", "csv"] = Field(
        "auto", description="Format of 'file': 'auto' reads a '.csv' as CSV and anything else as WAMIT '.4'.")
    ulen: quantity("m", gt=0, fix="give WAMIT's length scale ULEN in metres (1 when the file is dimensional).") = \
        Field(1.0, description="WAMIT's length scale ULEN: rotations in the file are per ULEN. [m]")
    reference: _XYZ = Field((0.0, 0.0, 0.0), description="RAO reference point (centre of rotation) at rest. [m]")
    mean_offset: _SIX | Literal["equilibrium"] = Field(
        (0.0,) * 6, description="Mean position about which the platform moves: surge, sway, heave [m], roll, pitch, "
                                "yaw [rad]; or, for a body of a system, 'equilibrium': its static equilibrium under "
                                "its steady external_force with the run's lines.")
    ramp: quantity("s", ge=0) = Field(0.0, description="Duration of the smooth start of the wave response. [s]")

    def table(self):
        """The RAO table of ``file`` (:class:`seacable.raos.RAOTable`)."""
        path = Path(self.file)
        if not path.is_file():
            raise InputError(f"motion.file: RAO file '{path}' does not exist or is not a file. Suggested fix: give "
                             "its path relative to the case file.")
        form = self.format if self.format != "auto" else ("csv" if path.suffix.lower() == ".csv" else "wamit")
        st = path.stat()
        return _rao_table(str(path.resolve()), (st.st_mtime_ns, st.st_size), form, float(self.ulen))

    def in_sea(self, sea) -> SeaRAOMotion:
        """This motion in the sea ``sea`` (:class:`seacable.seastate.SeaComponents`, None in calm water)."""
        if self.mean_offset == "equilibrium":
            raise InputError("motion.mean_offset 'equilibrium' is the static position of a body of a mooring system "
                             "(a system_dynamic case's body_motions); this motion moves the fairlead of a single line. "
                             "Suggested fix: give the mean offset [surge, sway, heave, roll, pitch, yaw] in m and rad.")
        if sea is None:
            raise InputError("a motion of type 'rao' moves the platform in waves, but the environment has none. "
                             "Suggested fix: give environment.waves (an irregular sea with 'spectrum', or regular "
                             "waves), or use a 'platform' motion.")
        table = self.table()
        from ..raos import RAOResponse, outside_table

        response = RAOResponse(table, sea, at=self.reference[:2])  # frequencies and headings outside it: refused
        wave_dofs = functools.partial(_rao_dofs, response)
        outside, share = outside_table(table, sea)
        if outside.any():  # left out, and said so
            w = np.asarray(sea.omega)[outside]
            warnings.warn(f"motion.file: {table.source} covers {table.omega[0]:.4g}-{table.omega[-1]:.4g} rad/s; "
                          f"{int(outside.sum())} components of the sea ({w.min():.4g}-{w.max():.4g} rad/s, {share:.2%} "
                          "of its variance) lie outside and move the platform by nothing (the table is not "
                          "extended). Suggested fix: extend the table, or narrow environment.waves.frequency_range.",
                          SeacableWarning, stacklevel=2)
        return SeaRAOMotion(self, wave_dofs)

    def channels(self, times, base):
        raise InputError("a motion of type 'rao' needs the case's waves: it is bound to them when the run is "
                         "prepared (seacable.mooring.motion.bind). Suggested fix: run the case, or call "
                         "motion.in_sea(sea).channels(times, base).")


def _rao_dofs(response, times):
    return tuple(m.T for m in response(times, derivatives=True))


@dataclass(frozen=True)
class SeaRAOMotion:
    """An :class:`RAOMotion` in a given sea: the six motions and the fairleads' channels at any times."""

    motion: RAOMotion
    wave_dofs: object  # times -> the wave response (nt, 6) and its two derivatives

    @property
    def reference(self):
        return self.motion.reference

    def dofs(self, times):
        """The six motions (nt, 6) [m, rad] and their time derivatives: the mean offset plus the ramped wave
        response."""
        t = np.asarray(times, float)
        q, dq, ddq = _ramped(*self.wave_dofs(t), t, self.motion.ramp)
        return q + np.asarray(self.motion.mean_offset, float), dq, ddq

    def channels(self, times, base):
        return _rigid_channels(self.motion.reference, base, *self.dofs(times))


def motion_from_csv(path) -> TimeSeriesMotion | PlatformMotion:
    """The motion a CSV describes: a rigid platform when its header names any of surge, sway, heave,
    roll, pitch, yaw (about the origin; [m], [rad]), otherwise offsets x, y, z of every moved point [m].

    The whole table is read and checked here, so that a file that is missing, a folder, unreadable,
    binary, empty or not a table of numbers is refused before a run starts.

    Raises
    ------
    InputError
        Naming the file and what is wrong with it.
    """
    path = Path(path)
    fix = "give a CSV text file with a header row, e.g. 'time,x,y,z', and one row of numbers per time"
    text = read_text_file(path, "motion file", fix)
    header = next((ln for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")), "")
    if not header:
        raise InputError(f"motion file '{path}' is empty (no header row). Suggested fix: {fix}.")
    columns = {c.strip().lower() for c in header.split(",")}
    platform = bool(columns & {"surge", "sway", "heave", "roll", "pitch", "yaw"})
    names = ("time", "surge", "sway", "heave", "roll", "pitch", "yaw") if platform else ("time", "x", "y", "z")
    try:
        _read_table(path, names)
    except InputError as err:  # on one line (numpy's reader lists the bad rows on several)
        raise InputError(" ".join(str(err).split())) from None
    except Exception as err:  # noqa: BLE001  (numpy's CSV reader: any failure means a bad table)
        raise InputError(f"motion file '{path}' is not a CSV table of numbers: {' '.join(str(err).split())}. "
                         f"Suggested fix: {fix}.") from None
    return PlatformMotion(file=str(path)) if platform else TimeSeriesMotion(file=str(path))


Motion = Annotated[HarmonicMotion | TimeSeriesMotion | PlatformMotion | RAOMotion, Field(discriminator="type")]
UNION_TAGS.update(("harmonic", "time_series", "platform", "rao"))


def forcing_period(motion, wave_period: float | None = None) -> float | None:
    """The shortest period forcing a run: a harmonic motion's (fairlead or platform) and the waves'. [s]

    None when neither is periodic (no motion, or a time series, in still water).
    """
    periods = [wave_period] if wave_period is not None and wave_period > 0 else []
    if isinstance(motion, HarmonicMotion) or (isinstance(motion, PlatformMotion) and motion.period is not None):
        periods.append(float(motion.period))
    return min(periods, default=None)


def sea_of(water):
    """The waves of a :class:`~seacable.mooring.solver.Water` as sea components
    (:class:`seacable.seastate.SeaComponents`): its irregular sea, its regular wave as one component, or None
    in calm water."""
    if water.sea is not None:
        return water.sea
    if water.wave_height <= 0.0:
        return None
    from ..seastate import SeaComponents
    from ..waves import wave_number

    depth = math.inf if water.depth is None else float(water.depth)
    k = float(wave_number(water.wave_period, water.depth, water.gravity))
    return SeaComponents(amplitude=np.array([0.5 * water.wave_height]), omega=np.array([2 * math.pi /
                         water.wave_period]), wave_number=np.array([k]), heading=np.array([water.wave_heading]),
                         phase=np.array([water.wave_phase]), depth=depth, gravity=water.gravity,
                         mean_heading=water.wave_heading)


def bind(motion, base, duration: float, sea=None):
    """``motion`` applied to the points at ``base`` (n, 3) as a function of time, or None for no motion.

    The function returns positions, velocities and accelerations (len(times), n, 3). It is evaluated once
    at 0 and ``duration`` here, so that a time series too short fails before a run starts. An RAO motion
    (:class:`RAOMotion`) moves in the sea ``sea`` (:func:`sea_of`).
    """
    if motion is None:
        return None
    if isinstance(motion, RAOMotion):
        motion = motion.in_sea(sea)
    base = np.asarray(base, float)

    def channels(times):
        return motion.channels(times, base)

    channels(np.array([0.0, duration]))
    return channels

"""Vessel motions from response amplitude operators (RAOs) in an irregular sea (issue 20).

An RAO table gives, for each degree of freedom (surge, sway, heave [m/m]; roll, pitch, yaw [rad/m]), wave
frequency [rad/s] and wave heading [rad, the direction the waves travel towards, from +X towards +Y], the
complex response to a unit-amplitude wave whose elevation at the origin is ``cos(w t)``: the motion is
``|H| cos(w t + phase)``. In seacable's complex convention (``e^(-i w t)``, :class:`seacable.seastate.SeaComponents`)
that is ``H = |H| e^(-i phase)``, and a sea of components ``a_k cos(k_k . x - w_k t + p_k)`` moves the vessel by

    x_j(t) = sum_k a_k Re{ H_j(w_k, b_k) e^(i (p_k - w_k t)) }                                  (:func:`rao_motion`)

with H interpolated linearly (real and imaginary parts) in frequency and in heading (periodic over 2 pi).

Tables are read from WAMIT's option-4 output (``.4``: PER, BETA, I, |xi|, phase, Re, Im per line; period [s],
heading and phase [deg], rotations made dimensional by 1/ULEN; WAMIT's phase is the same lead on the incident
elevation at the origin, WAMIT User Manual v7, section 4.9) and from CSV tables in SI units
(:func:`read_rao_csv`).
"""

from __future__ import annotations

import io
import math
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ._heading import heading_weights
from ._text import read_text_file
from .errors import InputError
from .seastate import cos_sin

__all__ = ["DOFS", "RAOResponse", "RAOTable", "outside_table", "rao_motion", "read_rao_csv", "read_wamit4"]

DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")


@dataclass(frozen=True)
class RAOTable:
    """RAOs: ``values[j, h, f]`` the complex response of DOF ``j`` (:data:`DOFS`) at ``heading[h]`` [rad] and
    ``omega[f]`` [rad/s] ([m/m] for translations, [rad/m] for rotations; convention of the module)."""

    omega: np.ndarray
    heading: np.ndarray
    values: np.ndarray
    source: str = "RAO table"

    def __post_init__(self):
        w, b, v = (np.asarray(a) for a in (self.omega, self.heading, self.values))
        if w.ndim != 1 or w.size < 2 or not np.all(np.diff(w) > 0) or w[0] <= 0:
            raise InputError(f"{self.source}: the frequencies must be at least two, positive and increasing, got "
                             f"{w.tolist()[:8]}. Suggested fix: list each frequency once, in rad/s.")
        if b.ndim != 1 or b.size < 1 or np.unique(np.mod(b, 2 * math.pi)).size != b.size:
            raise InputError(f"{self.source}: each heading must be given once, got {np.degrees(b).tolist()} deg. "
                             "Suggested fix: remove the repeated headings.")
        if v.shape != (6, b.size, w.size):
            raise InputError(f"{self.source}: the RAOs must have the shape (6 DOFs, {b.size} headings, {w.size} "
                             f"frequencies), got {v.shape}.")

    def at(self, omega, heading) -> np.ndarray:
        """The RAOs at frequencies ``omega`` [rad/s] and headings ``heading`` [rad] (arrays of one shape):
        (6, ...) complex. Frequencies outside the table are refused (:func:`rao_motion` says which)."""
        w = np.asarray(omega, float)
        order, lo, hi, frac = heading_weights(self.heading, heading)
        vals = self.values[:, order]
        nh = order.size
        out = np.empty((6,) + w.shape, complex)
        for j in range(6):
            re = [np.interp(w, self.omega, vals[j, h].real) for h in range(nh)]
            im = [np.interp(w, self.omega, vals[j, h].imag) for h in range(nh)]
            f = np.array(re) + 1j * np.array(im)  # (nh, ...)
            idx = np.indices(w.shape)
            out[j] = (1 - frac) * f[(lo, *idx)] + frac * f[(hi, *idx)]
        return out


class RAOResponse:
    """The six motions (:data:`DOFS`) of a vessel in the sea ``sea`` (:class:`seacable.seastate.SeaComponents`)
    through the RAO ``table``, with their velocities and accelerations, at any times: the table is read at the
    sea's components once, and each call is one product ``[cos(w t), sin(w t)] @ G`` (G: 2 n x 18).

    The RAO phases are referred to the wave elevation at ``at`` = (x, y) [m] (the vessel's reference point):
    a component of wave number k and heading b reaches it with the phase ``p + k (x cos b + y sin b)``.
    The table must cover the frequencies of the sea's components: components outside it that carry more than
    ``energy_outside`` of the sea's variance are refused (named); the others are left out, and their share
    is reported in the message of a refusal. A table of one heading applies to waves of that heading only."""

    def __init__(self, table: RAOTable, sea, *, at=(0.0, 0.0), energy_outside: float = 1e-3):
        w = np.asarray(sea.omega, float)
        a = np.asarray(sea.amplitude, float)
        b = np.broadcast_to(np.asarray(sea.heading, float), w.shape)
        outside, share = outside_table(table, sea)
        if share > energy_outside:
            missing = np.unique(np.round(w[outside], 4))
            raise InputError(f"{table.source} covers {table.omega[0]:.4g}-{table.omega[-1]:.4g} rad/s, but the sea "
                             f"has {share:.1%} of its variance at {missing.size} frequencies outside it (e.g. "
                             f"{', '.join(f'{x:g}' for x in missing[:4])} rad/s). Suggested fix: extend the RAO "
                             "table over the spectrum, or narrow the sea's frequency_range.")
        if table.heading.size == 1:
            off = np.abs(np.angle(np.exp(1j * (b - table.heading[0]))))
            if np.any(off > 1e-9):
                raise InputError(f"{table.source} has the single heading {math.degrees(table.heading[0]):g} deg, "
                                 f"but the sea's components travel towards up to {math.degrees(float(off.max())):g} "
                                 "deg from it. Suggested fix: give RAOs for the sea's headings (its heading and "
                                 "spreading).")
        keep = ~outside
        w, b = w[keep], b[keep]
        h = table.at(w, b)  # (6, n)
        k = np.broadcast_to(np.asarray(sea.wave_number, float), outside.shape)[keep]
        reach = np.asarray(sea.phase, float)[keep] + k * (at[0] * np.cos(b) + at[1] * np.sin(b))
        # x(t) = Re(sum c H e^(-i w t)) = cos(w t) Re(c H) + sin(w t) Im(c H); d/dt e^(-i w t) = -i w e^(-i w t)
        z = (a[keep] * np.exp(1j * reach)) * np.concatenate((h, h * (-1j * w), h * (-(w ** 2))))  # (18, n)
        self.omega = w
        self.gain = np.ascontiguousarray(np.concatenate((z.real, z.imag), axis=1).T)  # (2 n, 18)

    def __call__(self, times, derivatives: bool = False):
        """The motions (6, len(times)) [m, rad] at ``times`` [s]; with ``derivatives``, the motions, their
        velocities and their accelerations, each (6, len(times))."""
        t = np.asarray(times, float).ravel()
        out = np.empty((t.size, 18))
        g = self.gain if derivatives else self.gain[:, :6]
        for lo in range(0, t.size, _CHUNK):  # (times, components) in chunks: bounded memory for any run
            out[lo:lo + _CHUNK, :g.shape[1]] = cos_sin(self.omega, np.ascontiguousarray(t[lo:lo + _CHUNK])) @ g
        if not derivatives:
            return out[:, :6].T.copy()
        return tuple(out[:, 6 * j:6 * j + 6].T.copy() for j in range(3))


def rao_motion(table: RAOTable, sea, times, *, at=(0.0, 0.0), derivatives: bool = False,
               energy_outside: float = 1e-3):
    """The 6 motions (:data:`DOFS`) of a vessel at ``times`` [s] in the sea ``sea``
    (:class:`seacable.seastate.SeaComponents`): (6, len(times)) [m, rad]; with ``derivatives``, the motions,
    their velocities and their accelerations, each (6, len(times)). See :class:`RAOResponse` (which a run
    keeps, to evaluate the table once)."""
    return RAOResponse(table, sea, at=at, energy_outside=energy_outside)(times, derivatives)


def outside_table(table: RAOTable, sea):
    """The sea's components outside the table's frequencies (a boolean per component) and their share of the
    sea's variance [-] (:func:`rao_motion` leaves them out, or refuses the sea when the share is too large)."""
    w = np.asarray(sea.omega, float)
    a = np.asarray(sea.amplitude, float)
    outside = (w < table.omega[0]) | (w > table.omega[-1])
    return outside, float(np.sum(a[outside] ** 2) / max(np.sum(a**2), 1e-300))


_CHUNK = 4096  # times per block of RAOResponse: 4096 x 2 x 200 components x 8 bytes = 13 MB


#: Largest plausible RAO amplitudes: translations [m/m] and rotations [rad/m]. A linear response of more than
#: 100 m of motion, or half a turn, per metre of wave amplitude is no damped floating body's (moored platforms
#: and ships peak at a few m/m and a few tenths of a rad/m at resonance): such a table holds a unit error
#: (mm for m, degrees for radians) or an undamped resonance, and would drive the lines by kilometres.
MAX_RAO = (100.0, math.pi)


def _row_of(i: int, row_of) -> str:
    """The data row (numbers, after the header) of the table's i-th entry, counted from 1."""
    return f"row {row_of[i] if row_of is not None else i + 1}"


def _table(dof_of: np.ndarray, source: str, omega_of, heading_of, value_of, line_of=None) -> RAOTable:
    """An RAOTable from rows, each a DOF (1-6), a frequency [rad/s], a heading [rad] and a complex value; every
    row checked here, whichever file it came from (``line_of``: each entry's data row in the file, for messages;
    default the entries' order)."""
    dof_f = np.asarray(dof_of, float)
    omega_of, heading_of = np.asarray(omega_of, float), np.asarray(heading_of, float)
    value_of = np.asarray(value_of, complex)
    if dof_f.size == 0:
        raise InputError(f"{source} holds no RAO rows. Suggested fix: one row per DOF, heading and frequency.")
    frac = np.flatnonzero(dof_f != np.round(dof_f))
    if frac.size:
        i = int(frac[0])
        raise InputError(f"{source} {_row_of(i, line_of)}: dof = {dof_f[i]:g} is not a whole number; degrees of "
                         "freedom are 1 surge, 2 sway, 3 heave, 4 roll, 5 pitch, 6 yaw. Suggested fix: check the "
                         "column order (frequency, heading, dof, amplitude, phase).")
    far = np.flatnonzero(np.abs(heading_of) > 2.0 * math.pi)
    if far.size:
        i = int(far[0])
        raise InputError(f"{source} {_row_of(i, line_of)}: heading = {heading_of[i]:g} rad is beyond 2 pi: it looks "
                         f"like degrees ({math.radians(heading_of[i]):.4g} rad if it was meant as {heading_of[i]:g} "
                         "deg). Suggested fix: give the headings in radians (WAMIT .4 files are read in degrees).")
    w = np.unique(omega_of)
    b = np.unique(heading_of)
    v = np.full((6, b.size, w.size), np.nan + 0j)
    dof = np.round(dof_f).astype(int)
    if np.any((dof < 1) | (dof > 6)):
        wrong = sorted(set(dof.tolist()) - set(range(1, 7)))
        raise InputError(f"{source}: degrees of freedom must be 1-6 (surge to yaw), got {wrong}. Suggested fix: "
                         "number them 1 surge, 2 sway, 3 heave, 4 roll, 5 pitch, 6 yaw.")
    amp = np.abs(value_of)
    bound = np.where(dof <= 3, MAX_RAO[0], MAX_RAO[1])
    big = np.flatnonzero(amp > bound)
    if big.size:
        i = int(big[0])
        unit = "m/m" if dof[i] <= 3 else "rad/m"
        raise InputError(f"{source} {_row_of(i, line_of)}: the {DOFS[dof[i] - 1]} RAO amplitude is {amp[i]:.6g} {unit} "
                         f"at {omega_of[i]:.4g} rad/s, above the plausible {bound[i]:.3g} {unit} (100 m of motion or "
                         "half a turn per metre of wave amplitude: no damped floating body responds so). Suggested "
                         "fix: check the units (m and rad per m of wave amplitude, not mm or deg) or the resonance's "
                         "damping.")
    hi, fi = np.searchsorted(b, heading_of), np.searchsorted(w, omega_of)
    key = (dof - 1) * (b.size * w.size) + hi * w.size + fi
    _, first, counts = np.unique(key, return_index=True, return_counts=True)
    if np.any(counts > 1):
        twice = np.flatnonzero(key == key[first[np.argmax(counts > 1)]])
        i, j = int(twice[0]), int(twice[1])
        raise InputError(f"{source} {_row_of(i, line_of)} and {_row_of(j, line_of)} both give the {DOFS[dof[i] - 1]} RAO "
                         f"at heading {heading_of[i]:g} rad and {omega_of[i]:.4g} rad/s (the last would be kept "
                         "silently). Suggested fix: give each DOF, heading and frequency once.")
    v[dof - 1, hi, fi] = value_of
    hole = np.argwhere(np.isnan(v.real))
    if hole.size:
        j, h, f = hole[0]
        raise InputError(f"{source}: {len(hole)} (DOF, heading, frequency) entries are missing, e.g. {DOFS[j]} at "
                         f"heading {math.degrees(b[h]):g} deg and {w[f]:.4g} rad/s. Suggested fix: give every DOF at "
                         "every heading and frequency of the table.")
    return RAOTable(w, b, v, source)


def read_wamit4(path, ulen: float = 1.0) -> RAOTable:
    """The RAOs of a WAMIT option-4 file (``.4``): lines ``PER BETA I MOD PHS RE IM`` (period [s], heading [deg],
    DOF 1-6, |xi|, phase [deg], ...); rotations divided by ``ulen`` [m], WAMIT's length scale. Lines of zero or
    negative period (WAMIT's infinite and zero frequency limits) are skipped."""
    path = Path(path)
    if not path.is_file():
        raise InputError(f"RAO file '{path}' does not exist or is not a file. Suggested fix: check the path.")
    if not ulen > 0:
        raise InputError(f"ulen must be > 0 m (WAMIT's ULEN), got {ulen}. Suggested fix: the ULEN of the .gdf file.")
    text = read_text_file(path, "RAO file", "give the WAMIT option-4 output (.4)")
    try:
        data = np.loadtxt(io.StringIO(text), ndmin=2)
    except ValueError as err:
        raise InputError(f"RAO file '{path}' is not a WAMIT .4 table of numbers: {err}. Suggested fix: give the "
                         "option-4 output (PER BETA I MOD PHS RE IM on each line).") from None
    if data.shape[1] < 5:
        raise InputError(f"RAO file '{path}' has {data.shape[1]} columns, expected 7 (PER BETA I MOD PHS RE IM).")
    if not np.all(np.isfinite(data)):
        i = int(np.argwhere(~np.isfinite(data))[0, 0])
        raise InputError(f"RAO file '{path}' row {i + 1} holds a NaN or an infinity: {data[i].tolist()}. Suggested "
                         "fix: one finite number per column.")
    rows = np.flatnonzero(data[:, 0] > 0)
    data = data[rows]
    dof = data[:, 2]
    scale = np.where(dof >= 4, 1.0 / ulen, 1.0)
    value = data[:, 3] * scale * np.exp(-1j * np.radians(data[:, 4]))
    return _table(dof, f"RAO file '{path.name}'", 2 * math.pi / data[:, 0], np.radians(data[:, 1]), value,
                  line_of=rows + 1)


def read_rao_csv(path) -> RAOTable:
    """The RAOs of a CSV table in SI units, header ``frequency,heading,dof,amplitude,phase``: frequency [rad/s],
    heading [rad], dof 1-6 (surge to yaw), amplitude [m/m or rad/m], phase [rad] (the motion is
    ``amplitude cos(w t + phase)`` for the elevation ``cos(w t)`` at the origin)."""
    path = Path(path)
    if not path.is_file():
        raise InputError(f"RAO file '{path}' does not exist or is not a file. Suggested fix: check the path.")
    names = ("frequency", "heading", "dof", "amplitude", "phase")
    text = read_text_file(path, "RAO file", f"a header row '{','.join(names)}' and one row per DOF, heading and "
                                            "frequency (SI units: rad/s, rad, m/m or rad/m, rad)")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # numpy's own warnings on odd rows: the checks below say what is wrong
            table = np.genfromtxt(io.StringIO(text), delimiter=",", names=True, dtype=float)
    except (ValueError, IndexError) as err:
        raise InputError(f"RAO file '{path}' is not a CSV table: {err}. Suggested fix: a header row "
                         f"'{','.join(names)}' and rows of numbers.") from None
    if table.dtype.names is None or any(n not in table.dtype.names for n in names):
        raise InputError(f"RAO file '{path}' needs the columns {', '.join(names)}, got "
                         f"{', '.join(table.dtype.names or ())}. Suggested fix: a header row '{','.join(names)}'.")
    table = np.atleast_1d(table)
    for n in names:
        bad = np.flatnonzero(~np.isfinite(table[n]))
        if bad.size:
            raise InputError(f"RAO file '{path}' row {int(bad[0]) + 1}: column {n} is empty or not a number. Suggested "
                             "fix: one number per cell.")
    neg = np.flatnonzero(table["amplitude"] < 0)
    if neg.size:
        i = int(neg[0])
        raise InputError(f"RAO file '{path}' row {i + 1}: amplitude = {table['amplitude'][i]:g} is negative; an "
                         "amplitude is >= 0 (its sign belongs to the phase). Suggested fix: give |amplitude| and add "
                         "pi rad to the phase.")
    value = table["amplitude"] * np.exp(-1j * table["phase"])
    return _table(table["dof"], f"RAO file '{path.name}'", table["frequency"], table["heading"], value)

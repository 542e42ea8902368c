"""WAMIT's output files read into a :class:`~seacable.hydro.database.HydroDatabase`, as HydroDyn reads them.

Files of one root ``ROOT`` (WAMIT User Manual v7, chapter 4; HydroDyn's ``PotFile``):

===========  ==================================================  ==========================================
file         lines                                               made dimensional by
===========  ==================================================  ==========================================
``.1``       ``PER I J A [B]``                                    ``A rho L^k``, ``B rho w L^k``
``.3``       ``PER BETA I |X| phase Re Im``                       ``X rho g L^m``
``.hst``     ``I J C``                                            ``C rho g L^(k-1)``
``.8/.9``    ``PER BETA1 BETA2 I |F| phase Re Im``                ``F rho g L^(m-1)``
``.12d``     ``PER1 PER2 BETA1 BETA2 I |F| phase Re Im``          ``F rho g L^(m-1)``
===========  ==================================================  ==========================================

with ``L`` WAMIT's length scale ULEN (HydroDyn's ``WAMITULEN``), ``k = 3 + [i > 3] + [j > 3]`` and ``m = 2 +
[i > 3]``. ``PER`` is the wave period [s] (WAMIT's default input of periods, the one HydroDyn assumes);
``PER = -1`` is the zero-frequency limit (infinite period) and ``PER = 0`` the infinite-frequency limit, both
without damping. Headings ``BETA`` [deg] are the direction the waves travel towards, from +x; WAMIT's phase
is a lead on the incident elevation at the origin with ``e^(i w t)``, so seacable's complex amplitude
(``e^(-i w t)``, :mod:`seacable.raos`) is the conjugate of WAMIT's ``Re + i Im``. A heading given twice (-180
and 180 deg) is kept once. The mean drift is taken from the first of ``.12d`` (its diagonal ``PER1 = PER2``,
``BETA1 = BETA2``), ``.9`` (pressure integration) and ``.8`` (momentum) that exists, or as ``drift=``. A
``.12d`` file with pairs of different periods also gives the full difference-frequency QTF (``qtf``: its
conjugate, the other triangle filled by symmetry, the pairs of one heading only; :func:`_read_qtf`).

A missing DOF pair of ``.1`` or ``.hst`` is zero (WAMIT leaves out the negligible ones); a missing DOF of
``.3`` at a heading and frequency is refused, as are frequencies that differ between the DOFs.
"""

from __future__ import annotations

import io
import math
from pathlib import Path

import numpy as np

from .._text import read_text_file
from ..errors import InputError
from .database import HydroDatabase

__all__ = ["read_wamit"]

_DRIFT_FILES = (".12d", ".9", ".8")


def _table(path: Path, columns: int, what: str) -> np.ndarray:
    """The numbers of a WAMIT output file, at least ``columns`` per line (lines may be longer: ``.1`` gives no
    damping at its limits; the shorter ones are padded with NaN); a clear message on anything else."""
    text = read_text_file(path, f"WAMIT {what} file", f"give WAMIT's {path.suffix} output")
    try:  # the usual file: every line of one length, read by numpy's parser (a 2 MB .3 file in 0.1 s)
        data = np.loadtxt(io.StringIO(text), ndmin=2)
        if data.size and data.shape[1] >= columns and np.all(np.isfinite(data)):
            return data
    except ValueError:
        pass  # lines of different lengths, or a word: read line by line below, which says where
    rows = []
    for n, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        try:
            rows.append([float(v.replace("D", "E").replace("d", "e")) for v in line.split()])
        except ValueError:
            raise InputError(f"WAMIT {what} file '{path}' line {n} is not a row of numbers: {line.strip()[:60]!r}. "
                             f"Suggested fix: give the unchanged WAMIT {path.suffix} output.") from None
        if len(rows[-1]) < columns:
            raise InputError(f"WAMIT {what} file '{path}' line {n} has {len(rows[-1])} numbers, expected at least "
                             f"{columns}. Suggested fix: give the unchanged WAMIT {path.suffix} output.")
        if not all(math.isfinite(v) for v in rows[-1]):
            raise InputError(f"WAMIT {what} file '{path}' line {n} holds a NaN or an infinity: {line.strip()[:60]!r}.")
    if not rows:
        raise InputError(f"WAMIT {what} file '{path}' is empty. Suggested fix: give the WAMIT {path.suffix} output.")
    width = max(len(r) for r in rows)
    data = np.full((len(rows), width), np.nan)
    for k, r in enumerate(rows):
        data[k, :len(r)] = r
    return data


def _dofs(data: np.ndarray, cols, path: Path) -> list[np.ndarray]:
    out = []
    for c in cols:
        d = data[:, c]
        bad = np.flatnonzero((d != np.round(d)) | (d < 1) | (d > 6))
        if bad.size:
            raise InputError(f"WAMIT file '{path}' line {int(bad[0]) + 1}: DOF {d[bad[0]]:g} is not 1-6. Seacable reads "
                             "one body's six DOFs. Suggested fix: run WAMIT with one body (NBODY = 1), or give that "
                             "body's rows only.")
        out.append(d.astype(int) - 1)
    return out


def _length_power(i, j=None, base=3):
    """WAMIT's power of ULEN: ``base + [i > 3] (+ [j > 3])`` for 0-based DOFs."""
    k = base + (np.asarray(i) >= 3)
    return k if j is None else k + (np.asarray(j) >= 3)


def _read_radiation(path: Path, rho: float, ulen: float):
    data = _table(path, 4, "added mass and damping (.1)")
    per = data[:, 0]
    i, j = _dofs(data, (1, 2), path)
    scale = rho * ulen ** _length_power(i, j)
    freq = per > 0
    if not np.any(per == 0):
        raise InputError(f"WAMIT file '{path}' has no infinite-frequency added mass (PER = 0 lines). The radiation "
                         "memory needs it. Suggested fix: run WAMIT with the infinite-frequency limit (PER = 0 in "
                         "the .frc/.cfg inputs).")
    if np.any(freq & np.isnan(data[:, -1])) or data.shape[1] < 5:
        n = int(np.flatnonzero(freq & np.isnan(data[:, -1]))[0]) + 1 if data.shape[1] >= 5 else 1
        raise InputError(f"WAMIT file '{path}' gives no damping on line {n} (a positive period needs PER I J A B). "
                         "Suggested fix: give the unchanged .1 output.")
    limits = {}
    for label, p in (("inf", 0.0), ("zero", -1.0)):
        rows = np.flatnonzero(per == p)
        if rows.size:
            m = np.zeros((6, 6))
            m[i[rows], j[rows]] = data[rows, 3] * scale[rows]
            limits[label] = m
    periods = np.unique(per[freq])
    omega = np.sort(2 * math.pi / periods)
    idx = np.searchsorted(omega, 2 * math.pi / per[freq])
    rows = np.flatnonzero(freq)
    a = np.zeros((omega.size, 6, 6))
    b = np.zeros((omega.size, 6, 6))
    a[idx, i[rows], j[rows]] = data[rows, 3] * scale[rows]
    b[idx, i[rows], j[rows]] = data[rows, 4] * scale[rows] * omega[idx]
    return omega, a, b, limits["inf"], limits.get("zero")


def _heading_grid(beta_deg: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The distinct headings [rad] of a file (one of -180 and 180 kept) and each line's index into them."""
    wrapped = np.round(np.mod(beta_deg, 360.0), 9)
    unique = np.unique(wrapped)
    return np.radians(np.where(unique > 180.0, unique - 360.0, unique)), np.searchsorted(unique, wrapped)


def _read_excitation(path: Path, rho: float, g: float, ulen: float):
    data = _table(path, 7, "wave excitation (.3)")
    data = data[data[:, 0] > 0]  # WAMIT's limits carry no excitation
    if data.size == 0:
        raise InputError(f"WAMIT file '{path}' has no excitation at a positive period. Suggested fix: give the .3 output.")
    (dof,) = _dofs(data, (2,), path)
    heading, hidx = _heading_grid(data[:, 1])
    omega = np.sort(2 * math.pi / np.unique(data[:, 0]))
    widx = np.searchsorted(omega, 2 * math.pi / data[:, 0])
    x = np.full((heading.size, omega.size, 6), np.nan + 0j)
    x[hidx, widx, dof] = (data[:, 5] - 1j * data[:, 6]) * rho * g * ulen ** _length_power(dof, base=2)
    missing = np.argwhere(np.isnan(x.real))
    if missing.size:
        h, f, j = missing[0]
        raise InputError(f"WAMIT file '{path}' has no excitation of DOF {j + 1} at heading "
                         f"{math.degrees(heading[h]):g} deg and period {2 * math.pi / omega[f]:.6g} s "
                         f"({len(missing)} such gaps). Suggested fix: give every DOF at every heading and period "
                         "(WAMIT's IOPTN(3) = 1 with all modes).")
    order = np.argsort(heading)
    return heading[order], omega, x[order]


def _read_hydrostatics(path: Path, rho: float, g: float, ulen: float) -> np.ndarray:
    data = _table(path, 3, "hydrostatics (.hst)")
    i, j = _dofs(data, (0, 1), path)
    c = np.zeros((6, 6))
    c[i, j] = data[:, 2] * rho * g * ulen ** _length_power(i, j, base=2)
    return c


def _read_drift(path: Path, rho: float, g: float, ulen: float):
    """The mean drift of a .8/.9 file (``BETA1 = BETA2``) or the diagonal of a .12d file; for a .12d file with
    pairs off its diagonal also the full difference-frequency QTF (:func:`_read_qtf`), else None."""
    qtf = path.suffix == ".12d"
    data = _table(path, 9 if qtf else 8, "mean drift")
    col = 1 if qtf else 0  # the heading columns start after one or two periods
    full = _read_qtf(data, path, rho, g, ulen) if qtf else None
    if qtf:
        data = data[(data[:, 0] == data[:, 1]) & (data[:, 0] > 0)]
    data = data[(data[:, col + 1] == data[:, col + 2]) & (data[:, 0] > 0)]
    if data.size == 0:
        raise InputError(f"WAMIT file '{path}' has no mean drift (no line with equal periods and headings). "
                         "Suggested fix: give a .8, .9 or .12d output with its diagonal.")
    (dof,) = _dofs(data, (col + 3,), path)
    heading, hidx = _heading_grid(data[:, col + 1])
    omega = np.sort(2 * math.pi / np.unique(data[:, 0]))
    widx = np.searchsorted(omega, 2 * math.pi / data[:, 0])
    d = np.zeros((heading.size, omega.size, 6))
    # the mean of a second-order force is real: WAMIT's Re column (its Im is round-off on the diagonal)
    d[hidx, widx, dof] = data[:, col + 6] * rho * g * ulen ** _length_power(dof, base=1)
    order = np.argsort(heading)
    return heading[order], omega, d[order], full


def _read_qtf(data: np.ndarray, path: Path, rho: float, g: float, ulen: float):
    """The full difference-frequency QTF of a .12d file's lines ``PER1 PER2 BETA1 BETA2 I |F| phase Re Im``:
    ``(heading, omega, qtf)`` with ``qtf[h, i, j]`` at ``omega[i]``, ``omega[j]`` (module docstring of
    :mod:`seacable.hydro.database`), or None when the file holds its diagonal only.

    WAMIT's ``F(w1, w2)`` multiplies ``A1 conj(A2) e^(i (w1 - w2) t)`` with its ``e^(i w t)`` amplitudes ``A``;
    seacable's ``qtf(w1, w2)`` is its conjugate. WAMIT writes one triangle (``PER1 <= PER2``); the other is
    filled by ``qtf(w2, w1) = conj(qtf(w1, w2))``, a pair given both ways is checked against it. Only the pairs of
    one heading (``BETA1 = BETA2``) are kept; the diagonal is real (WAMIT's Im there is round-off). A DOF the file
    leaves out is zero; a pair of frequencies missing for a DOF it gives is refused."""
    data = data[(data[:, 0] > 0) & (data[:, 1] > 0) & (data[:, 2] == data[:, 3])]
    if not np.any(data[:, 0] != data[:, 1]):
        return None
    (dof,) = _dofs(data, (4,), path)
    heading, hidx = _heading_grid(data[:, 2])
    omega = np.sort(2 * math.pi / np.unique(data[:, :2]))
    i = np.searchsorted(omega, 2 * math.pi / data[:, 0])
    j = np.searchsorted(omega, 2 * math.pi / data[:, 1])
    value = (data[:, 7] - 1j * np.where(i == j, 0.0, data[:, 8])) * rho * g * ulen ** _length_power(dof, base=1)
    q = np.full((heading.size, omega.size, omega.size, 6), np.nan + 0j)
    q[hidx, i, j, dof] = value
    mirrored = np.full_like(q, np.nan)
    mirrored[hidx, j, i, dof] = np.conj(value)
    both = ~np.isnan(q.real) & ~np.isnan(mirrored.real)
    scale = np.abs(np.nan_to_num(q, nan=0.0)).max(axis=(0, 1, 2))
    gap = np.where(both, np.abs(q - mirrored), 0.0) / np.where(scale > 0, scale, 1.0)
    if np.any(gap > 1e-3):  # WAMIT prints 6 significant digits
        h, a, b, k = np.unravel_index(int(np.argmax(gap)), gap.shape)
        raise InputError(f"WAMIT file '{path}': the QTF of DOF {k + 1} at the periods {2 * math.pi / omega[a]:.6g} s and "
                         f"{2 * math.pi / omega[b]:.6g} s, given both ways, is not conjugate-symmetric. Suggested fix: "
                         "give the unchanged .12d output (WAMIT's difference-frequency QTF).")
    q = np.where(np.isnan(q.real), mirrored, np.where(both, 0.5 * (q + mirrored), q))
    present = np.zeros(6, bool)
    present[dof] = True
    missing = np.argwhere(np.isnan(q.real) & present)
    if missing.size:
        h, a, b, k = missing[0]
        raise InputError(f"WAMIT file '{path}' has the difference-frequency QTF off its diagonal but not of DOF {k + 1} "
                         f"at the periods {2 * math.pi / omega[a]:.6g} s and {2 * math.pi / omega[b]:.6g} s, heading "
                         f"{math.degrees(heading[h]):g} deg ({len(missing)} such gaps). Suggested fix: give the whole "
                         "triangle of periods WAMIT writes, or only its diagonal for the mean drift.")
    q = np.nan_to_num(q, nan=0.0)
    order = np.argsort(heading)
    return heading[order], omega, q[order]


def read_wamit(root, *, ulen: float = 1.0, rho: float = 1025.0, g: float = 9.80665, drift=None,
               reference=(0.0, 0.0, 0.0)) -> HydroDatabase:
    """The hydrodynamic database of WAMIT's output files ``ROOT.1``, ``ROOT.hst`` and, where they exist,
    ``ROOT.3`` and the mean drift (module docstring).

    Parameters
    ----------
    root : str or Path
        The files' path without the extension (HydroDyn's ``PotFile``), or the path of the ``.1`` file.
    ulen : float
        WAMIT's length scale ULEN [m] (HydroDyn's ``WAMITULEN``).
    rho, g : float
        Water density [kg/m^3] and gravity [m/s^2] the coefficients are made dimensional with.
    drift : str or Path, optional
        The mean drift file (``.8``, ``.9`` or ``.12d``); by default the first of ``ROOT.12d``, ``.9``, ``.8``.
    reference : sequence of 3 float
        The point the coefficients are about, in the body's axes [m] (HydroDyn's ``PtfmRefxt``, ...).
    """
    root = Path(root)
    if root.suffix == ".1":
        root = root.with_suffix("")
    if not ulen > 0 or not math.isfinite(ulen):
        raise InputError(f"ulen must be a length > 0 m (WAMIT's ULEN), got {ulen}. Suggested fix: the ULEN of the "
                         ".gdf file (HydroDyn's WAMITULEN).")
    if not (rho > 0 and g > 0):
        raise InputError(f"rho = {rho} kg/m^3 and g = {g} m/s^2 must be > 0.")
    files = {ext: Path(f"{root}{ext}") for ext in (".1", ".3", ".hst", *_DRIFT_FILES)}
    for ext, what in ((".1", "added mass and damping"), (".hst", "hydrostatics")):
        if not files[ext].is_file():
            raise InputError(f"WAMIT {what} file '{files[ext]}' does not exist. A body model needs it. Suggested fix: "
                             f"give the root of the WAMIT files (the path without '{ext}').")
    omega, a, b, a_inf, a_zero = _read_radiation(files[".1"], rho, ulen)
    kwargs = {}
    if files[".3"].is_file():
        heading, w3, x = _read_excitation(files[".3"], rho, g, ulen)
        kwargs.update(heading=heading, excitation_omega=w3, excitation=x)
    drift_path = Path(drift) if drift is not None else next((files[e] for e in _DRIFT_FILES if files[e].is_file()), None)
    if drift_path is not None:
        if not drift_path.is_file():
            raise InputError(f"WAMIT mean drift file '{drift_path}' does not exist. Suggested fix: check the path.")
        if drift_path.suffix not in _DRIFT_FILES:
            raise InputError(f"WAMIT mean drift file '{drift_path}' is not a .8, .9 or .12d file. Suggested fix: give "
                             "one of those.")
        dh, dw, d, full = _read_drift(drift_path, rho, g, ulen)
        kwargs.update(drift_heading=dh, drift_omega=dw, drift=d)
        if full is not None:
            kwargs.update(qtf_heading=full[0], qtf_omega=full[1], qtf=full[2])
    return HydroDatabase(omega=omega, added_mass=a, damping=b, added_mass_inf=a_inf, added_mass_zero=a_zero,
                         hydrostatics=_read_hydrostatics(files[".hst"], rho, g, ulen),
                         reference=np.asarray(reference, float), rho=rho, g=g, source=f"WAMIT files '{root}'",
                         **kwargs)

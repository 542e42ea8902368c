"""MoorDyn 2.7.2 and seacable on MoorDyn v2's quasi-static chain cases, against OrcaFlex.

Shared by the validation test ``tests/validation/test_moordyn_chain_rms.py`` and the speed race
(``bench/moordyn_peer.py``, ``bench/bench_mooring.py``, which put this folder on ``sys.path``). It
runs MoorDyn (python wrapper, ``pip install moordyn``) on the three single-chain cases of MoorDyn's
public test suite, ``../shared/peers/moordyn/WD{0050,0200,0600}_Chain.txt``, with the 'Vessel'
point moved in heave as in ``QuasiStatic/ZZP1_A{1,2}.txt`` (:func:`run_moordyn`), runs seacable on
the same deck and motion (:func:`run_seacable`), and measures either's error against the OrcaFlex
series ``QuasiStatic/WDxxxx_Chain_ZZP1_Ax.txt`` (:func:`accuracy`), by default on the same times
and optionally the way MoorDyn's own test (``tests/quasi_static_chain.cpp``) does.

What MoorDyn's test does (``tests/quasi_static_chain.cpp``, FloatingArrayDesign/MoorDyn)
----------------------------------------------------------------------------------------
* ``MoorDyn_Init(x=0, v=0)``; static fairlead / anchor tension = ``hypot(H, V)`` from
  ``MoorDyn_GetFASTtens``, compared with the OrcaFlex static values 991.6 / 2065.4 / 5232.6 kN
  (fairlead) and 826.2 / 1402.2 / 3244.2 kN (anchor); accepted if the *signed* relative error
  is <= 10 % (so a static tension that is too low always passes; we report ``|error|``).
* One ``MoorDyn_Step`` per 0.1 s row ``i`` of the motion file: MoorDyn time ``t = t_i - t_0``
  (the motion starts at -10 s, MoorDyn at 0 s), position ``x = row i`` (columns 1-3) and
  velocity the forward difference ``(row[i+1] - row[i]) / 0.1``. MoorDyn moves the coupled
  point as ``x + v (t - t_i)`` inside the step, so the point follows the piecewise-linear
  interpolant of the samples exactly.
* Rows with ``t_i < 0`` (the first 10 s) are a run-in and are not checked. For ``t_i >= 0`` the
  state *after* the step (time ``t_i + 0.1``) is compared with reference row ``t_i``: a one-row
  (0.1 s) offset. Only dynamic parts are compared, ``T - T_static`` against
  ``T_ref - T_ref_static``; the error is ``max |difference| / (2 max |T_ref - T_ref_static|)``
  (twice the largest excursion, a stand-in for the peak-to-peak range), accepted if <= 15 %.
  The anchor reference excursion is multiplied by 2.0 and the anchor error is not checked.

:func:`accuracy` reproduces that with ``mirror_moordyn_test=True``; by default it compares on
the same (not shifted) times and divides by the true peak-to-peak range of the reference.

The reference files (established here, see :func:`load_reference`)
------------------------------------------------------------------
* ``ZZP1_Ax.txt``: 301 rows, tab separated, ``t x y z roll pitch yaw`` [s, m, m, m, deg?];
  t = -10 ... 20 s by 0.1 s; only z is non-zero: ``z = A sin(2 pi t / 10)``, A = 2 m (A1) or
  5 m (A2), to the 3 printed decimals. No ramp: the motion starts at full amplitude at -10 s
  (velocity jumps from 0 to 2 pi A / 10 there), hence the 10 s run-in.
* ``WDxxxx_Chain_ZZP1_Ax.txt``: 201 rows, t = 0 ... 20 s by 0.1 s; columns ``t``, horizontal
  anchor-fairlead distance (constant 400 / 700 / 1500 m: the fairlead x in OrcaFlex's frame,
  anchor at x = 0), fairlead z [m] (OrcaFlex's own record; it lags the ZZP1 motion by a
  constant 0.029 s, amplitude 2.0002 / 5.0001 m), fairlead tension [kN], anchor tension [kN],
  and an angle [deg] = 90 deg + the line's angle below the horizontal at the fairlead (the
  elastic catenary gives 123.5 / 137.2 / 141.7 deg; the file starts at 123.3 / 137.2 / 141.6).
  The mean of the tension columns over 0-20 s equals the static values to 0.3 % (A1).

MoorDyn's numbers (v2.7.2, these inputs)
---------------------------------------
* ``dtM = CFL * 2 pi l sqrt(m / EA)`` (the axial period of one segment): CFL 0.1, segment
  l = 10 m in all three cases (41 / 76 / 170 segments), so ``dtM = 3.033e-3 s`` for all, RK2.
* Static tension 1014.0 / 2078.2 / 5250.2 kN (+2.3 / +0.6 / +0.3 % on OrcaFlex); MoorPy's
  frictionless elastic catenary gives 1001.7 / 2070.1 / 5236.2 kN.
* The dynamic anchor tension of MoorDyn (GetFASTtens, and the tension of the first segment
  alike) swings 2-4 times more than OrcaFlex's (50 m, A1: 210 vs 100 kN peak-to-peak), which
  is why MoorDyn's test doubles the reference excursion and leaves the anchor unchecked.

References
----------
MoorDyn v2, tests/quasi_static_chain.cpp and tests/Mooring/ (BSD-3),
https://github.com/FloatingArrayDesign/MoorDyn.
M. Hall and A. Goupee, "Validation of a lumped-mass mooring line model with DeepCwind
semisubmersible model test data", Ocean Engineering 104, 590-603, 2015.
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import sys
import tempfile
import time as _time
from pathlib import Path

import numpy as np

from seacable import _validate
from seacable.errors import ConvergenceError, InputError

__all__ = [
    "PEER_DIR",
    "STATIC_REFERENCE",
    "accuracy",
    "heave_motion",
    "load_reference",
    "run_moordyn",
    "run_seacable",
]

#: Where the shared MoorDyn cases live (read-only): ``shared/`` beside the checkout (CI's layout), else
#: the workplace's copy (for a checkout elsewhere); None when neither is there (the tests skip).
PEER_DIR = next((p for p in (Path(__file__).resolve().parents[3] / "shared" / "peers" / "moordyn",
                             Path("/work/shared/peers/moordyn")) if p.is_dir()), None)

#: OrcaFlex static (fairlead, anchor) tension [N], from MoorDyn's test and the README.
STATIC_REFERENCE = {
    "WD0050": (991.6e3, 826.2e3),
    "WD0200": (2065.4e3, 1402.2e3),
    "WD0600": (5232.6e3, 3244.2e3),
}
_AMPLITUDES = {"A1": 2.0, "A2": 5.0}


def _check_tags(depth_tag, amplitude_tag):
    if depth_tag not in STATIC_REFERENCE:
        raise InputError(f"depth_tag must be one of {sorted(STATIC_REFERENCE)}, got {depth_tag!r}. "
                         "Suggested fix: use 'WD0050', 'WD0200' or 'WD0600'.")
    if amplitude_tag not in _AMPLITUDES:
        raise InputError(f"amplitude_tag must be 'A1' (2 m) or 'A2' (5 m), got {amplitude_tag!r}. "
                         "Suggested fix: use 'A1' or 'A2'.")


def _forward_difference(t, y):
    """(y[i+1] - y[i]) / (t[i+1] - t[i]), last value repeated (MoorDyn's test convention)."""
    d = np.diff(y) / np.diff(t)
    return np.append(d, d[-1])


def load_reference(depth_tag: str, amplitude_tag: str = "A1", *, peer_dir=None) -> dict:
    """Read one OrcaFlex reference series and its prescribed fairlead motion.

    Parameters
    ----------
    depth_tag : str
        'WD0050', 'WD0200' or 'WD0600' (water depth 50, 200, 600 m).
    amplitude_tag : str, default 'A1'
        'A1' (heave amplitude 2 m) or 'A2' (5 m); period 10 s.
    peer_dir : path-like, optional
        Folder holding ``QuasiStatic/``; defaults to :data:`PEER_DIR`.

    Returns
    -------
    dict
        ``time`` [s] (0 ... 20 s), ``fairlead_tension``, ``anchor_tension`` [N] (files in kN),
        ``fairlead_z`` [m] and ``horizontal_span`` [m] and ``angle_deg`` [deg] as recorded by
        OrcaFlex, ``static_fairlead_tension``, ``static_anchor_tension`` [N] (OrcaFlex statics),
        ``amplitude`` [m], ``period`` [s], ``depth_tag``, ``amplitude_tag``, and ``motion``: a
        dict with ``time`` (-10 ... 20 s), ``x``, ``y``, ``z`` [m] (the vessel point's offset
        from its input position) and ``x_dot``, ``y_dot``, ``z_dot`` [m/s] (forward
        differences, as MoorDyn's test feeds them).

    Raises
    ------
    InputError
        Unknown tag, or the files are missing.
    """
    _check_tags(depth_tag, amplitude_tag)
    folder = Path(peer_dir) if peer_dir is not None else PEER_DIR
    if folder is None:
        raise InputError("peer_dir must be given: ../shared/peers/moordyn is not there. Suggested fix: "
                         "pass peer_dir= the folder that holds MoorDyn's chain decks and QuasiStatic/.")
    qs = folder / "QuasiStatic"
    ref_file = qs / f"{depth_tag}_Chain_ZZP1_{amplitude_tag}.txt"
    mot_file = qs / f"ZZP1_{amplitude_tag}.txt"
    for f in (ref_file, mot_file):
        if not f.is_file():
            raise InputError(f"reference file {f} does not exist. Suggested fix: pass peer_dir= "
                             "the folder that holds MoorDyn's QuasiStatic/ series.")
    ref = np.loadtxt(ref_file, ndmin=2)
    mot = np.loadtxt(mot_file, ndmin=2)
    tm = mot[:, 0]
    motion = {"time": tm, "x": mot[:, 1], "y": mot[:, 2], "z": mot[:, 3]}
    for k in ("x", "y", "z"):
        motion[k + "_dot"] = _forward_difference(tm, motion[k])
    f0, a0 = STATIC_REFERENCE[depth_tag]
    return {
        "time": ref[:, 0],
        "horizontal_span": ref[:, 1],
        "fairlead_z": ref[:, 2],
        "fairlead_tension": 1e3 * ref[:, 3],
        "anchor_tension": 1e3 * ref[:, 4],
        "angle_deg": ref[:, 5],
        "static_fairlead_tension": f0,
        "static_anchor_tension": a0,
        "amplitude": _AMPLITUDES[amplitude_tag],
        "period": 10.0,
        "depth_tag": depth_tag,
        "amplitude_tag": amplitude_tag,
        "motion": motion,
    }


def heave_motion(amplitude: float, period: float = 10.0, *, t_start: float = -10.0,
                 duration: float = 100.0, dt: float = 0.1) -> dict:
    """Sinusoidal heave ``z = A sin(2 pi t / period)`` from ``t_start`` (no ramp), like ZZP1.

    Equals ``ZZP1_A1.txt`` / ``ZZP1_A2.txt`` to their 3 printed decimals, and extends them
    beyond 20 s for timing runs.

    Parameters
    ----------
    amplitude : float
        Heave amplitude. [m]
    period : float, default 10.0
        Heave period. [s]
    t_start : float, default -10.0
        First time of the motion (MoorDyn time 0). [s]
    duration : float, default 100.0
        Length of the motion. [s]
    dt : float, default 0.1
        Sampling interval. [s]

    Returns
    -------
    dict
        ``time`` [s], ``x``, ``y``, ``z`` [m], ``x_dot``, ``y_dot``, ``z_dot`` [m/s]
        (forward differences).
    """
    _validate.finite("amplitude", amplitude, "m")
    _validate.positive("period", period, "s")
    _validate.positive("duration", duration, "s")
    _validate.positive("dt", dt, "s")
    n = round(duration / dt)
    t = t_start + dt * np.arange(n + 1)
    z = amplitude * np.sin(2.0 * np.pi * t / period)
    zero = np.zeros_like(t)
    return {"time": t, "x": zero, "y": zero.copy(), "z": z, "x_dot": zero.copy(),
            "y_dot": zero.copy(), "z_dot": _forward_difference(t, z)}


@contextlib.contextmanager
def _quiet(enabled=True):
    """Silence the C library's stdout/stderr (MoorDyn prints its banner and IC progress)."""
    if not enabled:
        yield
        return
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    with open(os.devnull, "w") as null:
        os.dup2(null.fileno(), 1)
        os.dup2(null.fileno(), 2)
        try:
            yield
        finally:
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])


def _prepare_input(input_file: Path, workdir: Path, use_ic_file: bool) -> Path:
    """Copy the input file (and its ``fileIC`` state if used) into ``workdir``.

    MoorDyn writes ``<name>.log`` and ``<name>.out`` next to its input, and resolves
    ``fileIC`` relative to the input file's folder; a missing IC file makes ``Init`` fail
    (error -1). With ``use_ic_file=False`` the option line is dropped and MoorDyn builds its
    initial condition from scratch (catenary guess + dynamic relaxation up to TmaxIC).
    """
    text = input_file.read_text()
    pattern = re.compile(r"^\s*(\S+)\s+(fileIC|ICfile)\b.*$", re.IGNORECASE | re.MULTILINE)
    m = pattern.search(text)
    if m:
        if use_ic_file:
            src = (input_file.parent / m.group(1))
            if not src.is_file():
                raise InputError(f"fileIC of {input_file.name} must exist, got {src}. "
                                 "Suggested fix: pass use_ic_file=False to let MoorDyn compute "
                                 "its initial condition.")
            shutil.copyfile(src, workdir / src.name)
            text = pattern.sub(lambda mm: f"{src.name}  {mm.group(2)}  (copied by moordyn_peer)",
                               text)
        else:
            text = pattern.sub("", text)
    dest = workdir / input_file.name
    dest.write_text(text)
    return dest


def _moordyn_version() -> str:
    from importlib.metadata import PackageNotFoundError, version
    try:
        return version("moordyn")
    except PackageNotFoundError:  # pragma: no cover
        return "unknown"


def run_moordyn(input_file, motion: dict, duration: float = 100.0, *, dt_out: float = 0.1,
                use_ic_file: bool = True, quiet: bool = True) -> dict:
    """Run MoorDyn from its static state with the coupled 'Vessel' point following ``motion``.

    The input file is copied to a temporary folder (with its ``fileIC`` state file) so that
    MoorDyn's ``.log`` / ``.out`` files never land next to the (read-only) original. One
    ``moordyn.Step`` is made per ``dt_out``: MoorDyn time starts at 0 at ``motion['time'][0]``;
    the vessel position is ``motion`` interpolated on that grid and its velocity the forward
    difference, exactly as in MoorDyn's ``quasi_static_chain`` test. Inside a step MoorDyn
    integrates with its own ``dtM`` (from ``dtM`` or ``CFL`` in the file).

    Parameters
    ----------
    input_file : path-like
        MoorDyn v2 input file with exactly one coupled ('Vessel') point and one line.
    motion : dict
        ``time`` [s] and ``x``, ``z`` (``y`` optional) [m]: offsets of the vessel point from
        its position in the input file.
    duration : float, default 100.0
        Simulated time after ``motion['time'][0]``; must lie within the motion. [s]
    dt_out : float, default 0.1
        Coupling / output interval. [s]
    use_ic_file : bool, default True
        Load the ``fileIC`` state named in the input file before MoorDyn's IC solver.
    quiet : bool, default True
        Silence MoorDyn's console output.

    Returns
    -------
    dict
        ``time`` [s] (in the motion's time frame; first entry the static state),
        ``fairlead_tension``, ``anchor_tension`` [N] (``hypot(H, V)`` of
        ``moordyn.GetFASTtens``), ``fairlead_z`` [m] (point position after each step),
        ``static_fairlead_tension``, ``static_anchor_tension`` [N], ``wall_time`` [s]
        (time stepping only), ``wall_time_init`` [s] (``Create`` + ``Init``), ``dt`` [s]
        (MoorDyn's internal ``dtM``), ``cfl``, ``n_segments``, ``n_steps``, ``version``.

    Raises
    ------
    InputError
        Bad duration / dt_out, motion too short, file missing, or not one coupled point.
    ConvergenceError
        MoorDyn's Init or Step returned an error code, or a tension is not finite.
    """
    import cmoordyn
    import moordyn  # the test extra's peer code (skipped without it)

    input_file = Path(input_file)
    if not input_file.is_file():
        raise InputError(f"input_file must be an existing MoorDyn file, got {input_file}. "
                         "Suggested fix: check the path (../shared/peers/moordyn/WD0050_Chain.txt).")
    _validate.positive("duration", duration, "s")
    _validate.positive("dt_out", dt_out, "s")
    tm = np.asarray(motion["time"], dtype=float)
    n_steps = round(duration / dt_out)
    t_grid = tm[0] + dt_out * np.arange(n_steps + 1)
    if t_grid[-1] > tm[-1] + 1e-9 * max(1.0, abs(tm[-1])):
        raise InputError(f"duration must be <= the motion's span {tm[-1] - tm[0]:.6g} s, got "
                         f"{duration:.6g} s. Suggested fix: use heave_motion(..., duration=...) "
                         "for a longer motion, or a shorter duration.")
    pos = np.zeros((n_steps + 1, 3))
    for j, key in enumerate("xyz"):
        if key in motion:
            pos[:, j] = np.interp(t_grid, tm, np.asarray(motion[key], dtype=float))
    vel = np.diff(pos, axis=0) / dt_out

    with tempfile.TemporaryDirectory(prefix="moordyn_peer_") as tmp:
        local = _prepare_input(input_file, Path(tmp), use_ic_file)
        with _quiet(quiet):
            t0 = _time.perf_counter()
            system = moordyn.Create(str(local))
            n_dof = moordyn.NCoupledDOF(system)
            if n_dof != 3:
                moordyn.Close(system)
                raise InputError(f"input_file must have exactly one coupled point (3 DOF), got "
                                 f"{n_dof} DOF. Suggested fix: one 'Vessel' point only.")
            err = moordyn.Init(system, pos[0].tolist(), [0.0, 0.0, 0.0])
            wall_init = _time.perf_counter() - t0
        if err != 0:
            moordyn.Close(system)
            raise ConvergenceError(f"MoorDyn Init failed with error code {err}. Suggested fix: "
                                   "check the input file and its fileIC (use_ic_file=False).",
                                   time=0.0)
        try:
            dtm = float(cmoordyn.get_dt(system))  # moordyn.GetDt 2.7.2 drops the return value
            cfl = float(cmoordyn.get_cfl(system))
            line = moordyn.GetLine(system, 1)
            n_seg = int(moordyn.GetLineN(line))
            point = [moordyn.GetPoint(system, i + 1) for i in range(moordyn.GetNumberPoints(system))]
            cpl = next(p for p in point if moordyn.GetPointType(p) == moordyn.POINT_TYPE_COUPLED)

            def tensions():
                fh, fv, ah, av = moordyn.GetFASTtens(system, 1)
                return np.hypot(fh[0], fv[0]), np.hypot(ah[0], av[0])

            fair = np.empty(n_steps + 1)
            anch = np.empty(n_steps + 1)
            zf = np.empty(n_steps + 1)
            fair[0], anch[0] = tensions()
            zf[0] = moordyn.GetPointPos(cpl)[2]
            t_md = 0.0
            t0 = _time.perf_counter()
            for i in range(n_steps):
                moordyn.Step(system, pos[i].tolist(), vel[i].tolist(), t_md, dt_out)
                t_md += dt_out
                fair[i + 1], anch[i + 1] = tensions()
                zf[i + 1] = moordyn.GetPointPos(cpl)[2]
            wall = _time.perf_counter() - t0
        finally:
            moordyn.Close(system)
    bad = ~(np.isfinite(fair) & np.isfinite(anch))
    if bad.any():
        k = int(np.argmax(bad))
        raise ConvergenceError(f"MoorDyn returned a non-finite tension at t = {t_grid[k]:.6g} s. "
                               "Suggested fix: lower CFL or dtM in the input file.",
                               time=float(t_grid[k]), iterations=k, residual=float("nan"))
    return {"time": t_grid, "fairlead_tension": fair, "anchor_tension": anch, "fairlead_z": zf,
            "static_fairlead_tension": float(fair[0]), "static_anchor_tension": float(anch[0]),
            "wall_time": wall, "wall_time_init": wall_init, "dt": dtm, "cfl": cfl,
            "n_segments": n_seg, "n_steps": n_steps, "version": _moordyn_version()}


def run_seacable(input_file, motion: dict, duration: float = 30.0, *, dt: float = 0.1,
                 spectral_radius: float = 1.0, tol: float = 1e-6) -> dict:
    """Run seacable's mooring model of a MoorDyn deck from its static state under ``motion``.

    The model is :func:`seacable.mooring.moordyn.moordyn_model` of the deck; the coupled point
    follows the cubic spline through the motion samples (positions, and the spline's first and
    second derivatives as velocity and acceleration) from ``motion['time'][0]`` on, time step and
    output interval ``dt``.

    Parameters
    ----------
    input_file : path-like
        MoorDyn v2 input file with one coupled ('Vessel') point and one line.
    motion : dict
        ``time`` [s] and ``x``, ``y``, ``z`` [m]: offsets of the vessel point from its position in
        the input file (:func:`load_reference`'s ``motion`` or :func:`heave_motion`).
    duration : float, default 30.0
        Simulated time after ``motion['time'][0]``. [s]
    dt : float, default 0.1
        Time step and output interval. [s]
    spectral_radius : float, default 1.0
        The generalised-alpha step's high-frequency amplification (1: average acceleration).
    tol : float, default 1e-6
        Newton tolerance of :func:`seacable.mooring.solver.simulate`.

    Returns
    -------
    dict
        ``time`` [s] (in the motion's time frame), ``fairlead_tension``, ``anchor_tension`` [N]
        (magnitude of the support force at the line's last and first node),
        ``static_fairlead_tension``, ``static_anchor_tension`` [N] (static equilibrium),
        ``wall_time`` [s] (static solve and time stepping).
    """
    from scipy.interpolate import CubicSpline

    from seacable.mooring.moordyn import moordyn_model
    from seacable.mooring.network import PRESCRIBED
    from seacable.mooring.solver import simulate, static_equilibrium

    tm = np.asarray(motion["time"], dtype=float)
    offsets = np.column_stack([np.asarray(motion.get(k, np.zeros_like(tm)), dtype=float) for k in "xyz"])
    spline = CubicSpline(tm - tm[0], offsets)
    t0 = _time.perf_counter()
    model = moordyn_model(Path(input_file))
    st = static_equilibrium(model)
    base = model.network.position[model.network.kind == PRESCRIBED]

    def moved(t):
        t = np.asarray(t, float)
        return base[None] + spline(t)[:, None, :], spline(t, 1)[:, None, :], spline(t, 2)[:, None, :]

    run = simulate(model, moved, duration, dt, dt, initial=st.position, tol=tol,
                   spectral_radius=spectral_radius)
    wall = _time.perf_counter() - t0
    anchor, fair = model.network.line_nodes[0][0], model.network.line_nodes[0][-1]
    return {"time": tm[0] + run.time, "fairlead_tension": np.linalg.norm(run.support[:, fair], axis=1),
            "anchor_tension": np.linalg.norm(run.support[:, anchor], axis=1),
            "static_fairlead_tension": float(np.linalg.norm(st.support[fair])),
            "static_anchor_tension": float(np.linalg.norm(st.support[anchor])), "wall_time": wall}


def accuracy(result: dict, reference: dict, *, mirror_moordyn_test: bool = False) -> dict:
    """Static and dynamic tension errors of a run against an OrcaFlex reference series.

    Dynamic parts are compared (``T - T_static`` of each code, so a static offset does not
    count twice) on the reference times inside the run.

    Parameters
    ----------
    result : dict
        Output of :func:`run_moordyn` or :func:`run_seacable` (or any dict with their keys).
    reference : dict
        Output of :func:`load_reference`.
    mirror_moordyn_test : bool, default False
        False: compare at the same times (linear interpolation of the run) and divide by the
        reference's peak-to-peak range ``max - min``. True: reproduce
        ``quasi_static_chain.cpp``: the run's state at ``t + 0.1 s`` against the reference at
        ``t`` (t = 0 ... 19.9 s), divide by ``2 max |T_ref - T_ref_static|``, and double the
        anchor reference excursion.

    Returns
    -------
    dict
        ``static_fairlead_error_pct``, ``static_anchor_error_pct`` (signed, [%]);
        ``fairlead_max_error_pct``, ``anchor_max_error_pct`` [%] and the times where they
        occur ``fairlead_max_error_time``, ``anchor_max_error_time`` [s];
        ``fairlead_max_error``, ``anchor_max_error`` [N]; the root-mean-square differences
        ``fairlead_rms_error``, ``anchor_rms_error`` [N] and ``..._rms_error_pct`` [%] (of the
        same range); ``fairlead_range_ref``, ``anchor_range_ref`` [N]; ``n_compared``;
        ``passes``: ``|static fairlead error|`` <= 10 % and dynamic fairlead error <= 15 %
        (MoorDyn's acceptance; the anchor dynamic error is not checked there either).
    """
    t_run = np.asarray(result["time"], dtype=float)
    t_ref = np.asarray(reference["time"], dtype=float)
    shift = 0.1 if mirror_moordyn_test else 0.0
    eps = 1e-9
    keep = (t_ref + shift >= t_run[0] - eps) & (t_ref + shift <= t_run[-1] + eps)
    if mirror_moordyn_test:
        keep &= t_ref < t_ref[-1] - eps  # the test stops one row before the end of the motion
    if not keep.any():
        raise InputError("result and reference must overlap in time, got run "
                         f"{t_run[0]:.6g}-{t_run[-1]:.6g} s and reference {t_ref[0]:.6g}-"
                         f"{t_ref[-1]:.6g} s. Suggested fix: run from the motion's start over its "
                         "whole span.")
    tk = t_ref[keep]
    out = {"n_compared": int(keep.sum())}
    worst = {}
    for name, factor in (("fairlead", 1.0), ("anchor", 2.0 if mirror_moordyn_test else 1.0)):
        s_run = result[f"static_{name}_tension"]
        s_ref = reference[f"static_{name}_tension"]
        out[f"static_{name}_tension"] = s_run
        out[f"static_{name}_tension_ref"] = s_ref
        out[f"static_{name}_error_pct"] = 100.0 * (s_run - s_ref) / s_ref
        dyn_run = np.interp(tk + shift, t_run, result[f"{name}_tension"]) - s_run
        dyn_ref = factor * (reference[f"{name}_tension"][keep] - s_ref)
        diff = np.abs(dyn_run - dyn_ref)
        scale = 2.0 * np.abs(dyn_ref).max() if mirror_moordyn_test else np.ptp(dyn_ref)
        k = int(np.argmax(diff))
        worst[name] = 100.0 * diff[k] / scale
        rms = float(np.sqrt(np.mean(diff**2)))
        out[f"{name}_rms_error"] = rms
        out[f"{name}_rms_error_pct"] = 100.0 * rms / scale
        out[f"{name}_max_error"] = float(diff[k])
        out[f"{name}_max_error_pct"] = float(worst[name])
        out[f"{name}_max_error_time"] = float(tk[k])
        out[f"{name}_range_ref"] = float(scale)
    out["passes"] = bool(abs(out["static_fairlead_error_pct"]) <= 10.0
                         and worst["fairlead"] <= 15.0)
    return out

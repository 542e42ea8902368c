"""Speed of the towed-cable dynamics (seacable.towed.solver.simulate) on paper 000's turn.

Run: ``python bench/bench_towed.py`` (about 2.5 min), ``--quick`` (7 and 50 nodes only, no cold
compilation), ``--survey`` (only section 5, about 1 min), ``--no-cold`` (skip the cold numba compilation in a subprocess), ``--full-dense``
(run the dense LU over the whole 100 s at 200 nodes, about 2 min more, instead of timing a short
part of it and extrapolating).

The case is ``examples/paper000_turn.yaml``: 170 m cable, d = 0.035 m, m = 2.7904 kg/m,
w0 = 17.7 N/m, EA = 4.2333e5 N, EI = 32.41 N m^2, C_dn = 1.5, C_dt = 0.01, current -1 m/s, the
vessel at 1 m/s turning left at 0.5 deg/s, 100 s with a 0.5 s step. The script prints

1. the one-time numba cost: import, the first call against later calls, whether numba's on-disk
   cache was warm (the dispatchers' cache hits and misses) and, in a subprocess with an empty
   cache directory, the cold compilation;
2. paper 000's comparison (its block tri-diagonal solve was 72 times faster than Gauss-Jordan on
   the full matrix: 10 min against 12 h for 100 s at 7 nodes on a 150 MHz Pentium): the whole run
   with the block solve, LAPACK's band LU and LAPACK's dense LU of the same Newton systems, at
   7, 50 and 200 nodes (800 only if the dense run would take < 60 s), and the linear solve alone
   on one Newton system of each size;
3. the block solver's wall time, time per step and per Newton iteration at 7, 50, 200 and 800
   nodes, the fitted exponent of time against nodes and the issue's targets;
4. whether the solvers agree (top tension at the end of the run, 1e-6 relative);
5. issue 21's towed system (:func:`survey_case`: 1000 m of cable and a body, 100 nodes, a 3-D turn, 1200 s at
   1 s, ``seacable.run`` with its result): the box scheme against the finite-element formulation, the
   finite element with 200 m paid out, and its cost against nodes.

Wall times are medians of repeated runs after a warm-up run, with ``time.perf_counter``. This is a
benchmark, not a test: it prints, it does not assert.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

CASE_FILE = Path(__file__).resolve().parent.parent / "examples" / "paper000_turn.yaml"
DURATION = 100.0        # s, paper 000's turn
TIME_STEP = 0.5         # s, as in the case file
REPEATS = 5             # counted runs after the warm-up
DENSE_BUDGET = 60.0     # s, longest dense run we start (estimated from the warm-up)
AGREE_RTOL = 1e-6       # top tension, solver against block


# ------------------------------------------------------------------------------------------
# set-up
# ------------------------------------------------------------------------------------------

def _setup(n_nodes):
    """(par, n, path, kwargs) of the paper 000 turn with ``n_nodes`` nodes."""
    import seacable
    from seacable.towed.run import case_setup

    case = seacable.load_case(CASE_FILE)
    case = case.model_copy(update={"analysis": case.analysis.model_copy(update={"n_nodes": n_nodes})})
    return case_setup(case)


def _run(n_nodes, solver="block", duration=DURATION):
    """One simulate() call: (call wall time [s], TowedRun)."""
    from seacable.towed.solver import simulate

    par, n, path, kw = _setup(n_nodes)
    t0 = time.perf_counter()
    run = simulate(par, n, path, duration, TIME_STEP, linear_solver=solver, **kw)
    return time.perf_counter() - t0, run


def _dispatchers():
    """Every numba dispatcher of the towed-cable modules."""
    from numba.core.registry import CPUDispatcher

    from seacable.towed import equations, linalg, scheme

    out = {}
    for mod in (equations, scheme, linalg):
        for name, obj in vars(mod).items():
            if isinstance(obj, CPUDispatcher):
                out[f"{mod.__name__.rsplit('.', 1)[-1]}.{name}"] = obj
    return out


def _cache_counts():
    hits = misses = 0
    for d in _dispatchers().values():
        hits += sum(d.stats.cache_hits.values())
        misses += sum(d.stats.cache_misses.values())
    return hits, misses


# ------------------------------------------------------------------------------------------
# 1. one-time cost
# ------------------------------------------------------------------------------------------

def first_call():
    """Import time, first 7-node call, later calls and the dispatchers' cache hits/misses."""
    t0 = time.perf_counter()
    import seacable.towed.solver  # noqa: F401  (numba compiles lazily: this is the import only)

    t_import = time.perf_counter() - t0
    t_first, run = _run(7)
    hits, misses = _cache_counts()
    later = [_run(7)[0] for _ in range(REPEATS)]
    cache_dir = next(iter(_dispatchers().values())).stats.cache_path
    return {"import": t_import, "first": t_first, "first_integration": run.wall_time,
            "later": statistics.median(later), "hits": hits, "misses": misses,
            "cache_dir": cache_dir}


def cold_compile():
    """first_call() in a subprocess whose numba cache directory is empty and thrown away."""
    tmp = tempfile.mkdtemp(prefix="seacable_numba_cold_")
    try:
        env = dict(os.environ, NUMBA_CACHE_DIR=tmp)
        out = subprocess.run([sys.executable, __file__, "--_first-call"], env=env, check=True,
                             capture_output=True, text=True, timeout=600)
        return json.loads(out.stdout.strip().splitlines()[-1])
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def print_one_time(warm, cold):
    print("1. One-time numba cost (7 nodes, 100 s of the turn, block solver)")
    state = ("WARM (every compiled function loaded from disk)" if warm["misses"] == 0 and warm["hits"] > 0
             else f"COLD ({warm['misses']} compilations)" if warm["hits"] == 0
             else f"partly warm ({warm['hits']} loaded, {warm['misses']} compiled)")
    print(f"   numba on-disk cache in {warm['cache_dir']}: {state}")
    print(f"   import seacable.towed.solver        {warm['import']:8.3f} s")
    print(f"   first call                          {warm['first']:8.3f} s")
    print(f"   later calls (median of {REPEATS})          {warm['later']:8.3f} s")
    print(f"   => cache load, one-time             {warm['first'] - warm['later']:8.3f} s")
    if cold is not None:
        print(f"   cold compilation (empty cache, subprocess): first call {cold['first']:.1f} s, later "
              f"{cold['later']:.3f} s => compile {cold['first'] - cold['later']:.1f} s "
              f"({cold['misses']} compilations, {cold['hits']} cache hits)")
    print()


# ------------------------------------------------------------------------------------------
# 2. block vs banded vs dense, 3. scaling
# ------------------------------------------------------------------------------------------

def _failed(n_nodes, solver, exc):
    return {"n": n_nodes, "solver": solver, "error": f"{type(exc).__name__}: {str(exc)[:60]}..."}


def time_solver(n_nodes, solver, repeats=REPEATS, duration=DURATION):
    """Warm-up (1 s of the turn), then ``repeats`` runs: medians and the last TowedRun.

    A run that raises a seacable error gives a record with ``error`` instead.
    """
    from seacable.errors import SeacableError

    try:
        return _time_solver(n_nodes, solver, repeats, duration)
    except SeacableError as exc:
        return _failed(n_nodes, solver, exc)


def _time_solver(n_nodes, solver, repeats, duration):
    _run(n_nodes, solver, duration=1.0)
    calls, loops, last = [], [], None
    for _ in range(repeats):
        t, last = _run(n_nodes, solver, duration)
        calls.append(t)
        loops.append(last.wall_time)
    return {"n": n_nodes, "solver": solver, "call": statistics.median(calls),
            "loop": statistics.median(loops), "spread": (min(calls), max(calls)), "run": last,
            "duration": duration, "repeats": repeats}


def time_dense(n_nodes, iterations_full, est_per_iter, full):
    """Dense LU at ``n_nodes``: the whole run if it fits the budget (or ``full``), else a part.

    ``est_per_iter`` is the time per Newton iteration expected from the smaller size (None:
    unknown). Returns the time_solver() record with ``extrapolated`` (s, or None) and
    ``per_iter``; None when even one step is too long to time.
    """
    if est_per_iter is not None and est_per_iter * 6 > DENSE_BUDGET:
        return None
    from seacable.errors import SeacableError

    try:
        return _time_dense(n_nodes, iterations_full, full)
    except SeacableError as exc:
        return _failed(n_nodes, "dense", exc)


def _time_dense(n_nodes, iterations_full, full):
    _run(n_nodes, "dense", duration=1.0)  # warm-up and a first measure of one iteration
    t, part = _run(n_nodes, "dense", duration=1.0)
    per_iter = part.wall_time / max(part.iterations, 1)
    estimate = per_iter * iterations_full
    if full or estimate * REPEATS <= DENSE_BUDGET:
        rec = _time_solver(n_nodes, "dense", REPEATS if estimate * REPEATS <= DENSE_BUDGET else 1, DURATION)
        rec["extrapolated"] = None
    else:
        part_duration = 2.0  # 4 steps: the dense LU dominates, so the time per iteration is its cost
        calls, loops, last = [], [], None
        for _ in range(3):
            t, last = _run(n_nodes, "dense", duration=part_duration)
            calls.append(t)
            loops.append(last.wall_time)
        rec = {"n": n_nodes, "solver": "dense", "call": statistics.median(calls),
               "loop": statistics.median(loops), "spread": (min(calls), max(calls)), "run": last,
               "duration": part_duration, "repeats": 3}
        rec["extrapolated"] = rec["loop"] / last.iterations * iterations_full
    rec["per_iter"] = rec["loop"] / rec["run"].iterations
    return rec


def newton_system(n_nodes):
    """One Newton system (lower, diag, upper, rhs) of the steady tow at ``n_nodes`` nodes.

    The steady Jacobian has the size and block structure of the dynamic ones (the time terms
    only change entries inside the same blocks), so the linear solve costs the same. It is taken
    at the steady state perturbed by 1e-3 (relative, fixed seed), as in a first Newton
    iteration: at the solution itself the right-hand side would be rounding noise.
    """
    from seacable.towed.equations import NV
    from seacable.towed.scheme import newton_step, workspace
    from seacable.towed.solver import body_parameters, steady_tow

    par, n, path, kw = _setup(n_nodes)
    _, vel = path(np.array([0.0]))
    cur = kw["current"]
    h = steady_tow(par, n, vel[0], cur, None, water_density=kw["water_density"])
    u = np.tile([cur.speed * math.cos(cur.heading), cur.speed * math.sin(cur.heading), 0.0], (n, 1))
    w = workspace(n)
    hn = h * (1.0 + 1e-3 * np.random.default_rng(0).standard_normal(h.shape))
    newton_step(hn, h, np.zeros((n, NV)), u, u, vel[0], 1.0, par, body_parameters(None), True,
                np.ones(NV), 0.0, 1, w)
    return w[8].copy(), w[9].copy(), w[10].copy(), w[11].copy()


def time_linear_solves(n_nodes, dense=True):
    """Median time [s] of one linear solve per solver, and the largest relative difference."""
    from seacable.towed.lapack import solve_banded, solve_dense
    from seacable.towed.linalg import solve_block_tridiagonal

    system = newton_system(n_nodes)
    solvers = {"block": solve_block_tridiagonal, "banded": solve_banded}
    if dense:
        solvers["dense"] = solve_dense
    out, xs, failed = {}, {}, []
    for name, fn in solvers.items():
        x = np.zeros_like(system[3])
        status = fn(*system, x)
        if status != 0:  # timed all the same (the work is done), but its answer is not compared
            failed.append(f"{name} returned status {status}")
        else:
            xs[name] = x.copy()
        t0 = time.perf_counter()
        fn(*system, x)
        one = time.perf_counter() - t0
        # about 0.05 s per sample; calling a numba function from Python costs ~0.4 us, negligible
        loops = max(1, min(2000, int(0.05 / max(one, 1e-7))))
        samples = []
        for _ in range(5):
            t0 = time.perf_counter()
            for _ in range(loops):
                fn(*system, x)
            samples.append((time.perf_counter() - t0) / loops)
        out[name] = statistics.median(samples)
    ref = xs["block"]
    size = np.maximum(np.max(np.abs(ref), axis=0), 1e-300)  # each unknown's scale over the nodes
    dev = max((float(np.max(np.abs(x - ref) / size)) for x in xs.values()), default=0.0)
    return out, dev, failed


def print_comparison(records, solves, dense_skipped):
    print("2. Paper 000's comparison: the same Newton systems solved by the block tri-diagonal "
          "algorithm, LAPACK band LU and LAPACK dense LU")
    print(f"   call: whole simulate() call for {DURATION:g} s of the turn, median of {REPEATS} after a "
          "warm-up; loop: the time integration alone;")
    print("   1 solve: the linear solve alone on one Newton system of that size (median of 5 batches)")
    print(f"   {'nodes':>5} {'N=10n':>6} {'solver':>7} {'call [s]':>10} {'x block':>8} {'loop [s]':>9} "
          f"{'min-max call [s]':>17} {'iters':>6} {'/iter [ms]':>10} {'1 solve [us]':>13} {'x block':>8}")
    notes = []
    for n in sorted({r["n"] for r in records}):
        rows = [r for r in records if r["n"] == n]
        block = next(r for r in rows if r["solver"] == "block")
        solve_block = solves.get(n, {}).get("block", math.nan)
        for r in rows:
            solve = solves.get(n, {}).get(r["solver"], math.nan)
            if "error" in r or "error" in block:
                print(f"   {n:>5} {10 * n:>6} {r['solver']:>7}  FAILED (1 solve {1e6 * solve:.1f} us): "
                      f"{r.get('error', 'block run failed')}")
                continue
            run = r["run"]
            call, star = r["call"], " "
            if r.get("extrapolated") is not None:
                call, star = r["extrapolated"] + (block["call"] - block["loop"]), "*"
                notes.append(f"   * {n} nodes dense: median of {r['repeats']} runs of the first "
                             f"{run.time[-1]:g} s "
                             f"({run.iterations} iterations; loop and min-max are theirs); call extrapolated "
                             f"as /iter x block's {block['run'].iterations} iterations + block's set-up")
            spread = f"{r['spread'][0]:.3f}-{r['spread'][1]:.3f}"
            print(f"   {n:>5} {10 * n:>6} {r['solver']:>7} {call:>9.3f}{star} {call / block['call']:>8.1f} "
                  f"{r['loop']:>9.3f} {spread:>17} {run.iterations:>6} "
                  f"{1e3 * r['loop'] / run.iterations:>10.3f} "
                  f"{1e6 * solve:>13.1f} {solve / solve_block:>8.1f}")
    for n, why in dense_skipped:
        print(f"   {n:>5} {10 * n:>6} {'dense':>7}  not run: {why}")
    for note in notes:
        print(note)
    r7 = [r for r in records if r["n"] == 7]
    if len(r7) == 3 and not any("error" in r for r in r7):
        b = next(r for r in r7 if r["solver"] == "block")
        d = next(r for r in r7 if r["solver"] == "dense")
        s = solves.get(7, {})
        print("   Paper 000: block 72x faster than Gauss-Jordan (10 min vs 12 h, 100 s at 7 nodes, 150 MHz "
              f"Pentium). Ours at 7 nodes: dense/block {d['call'] / b['call']:.2f}")
        print(f"   for the whole run, {s.get('dense', math.nan) / s.get('block', math.nan):.1f} for the "
              "linear solve alone. At 7 nodes the dense matrix is only 70 x 70: LU 2/3 70^3 = 0.23 Mflop")
        print("   (Gauss-Jordan 70^3 = 0.34 Mflop) against ~7 x 4.7 kflop = 0.033 Mflop for the block Thomas "
              "algorithm, 7-10x by flop count, and the solve")
        print("   is a small part of an iteration (assembling the box equations dominates), so the whole-run "
              "ratio stays small; the paper's 72x is more")
        print("   than the flop count explains at 7 nodes. Dense/block grows as n^2 (see 50 and 200 nodes). "
              f"Our block run: {b['call']:.3f} s vs the paper's 10 min.")
    print()


def print_scaling(blocks):
    print(f"3. Block tri-diagonal solver, {DURATION:g} s of the turn, {TIME_STEP:g} s step "
          f"(median of {REPEATS} after a warm-up)")
    print(f"   {'nodes':>5} {'call [s]':>10} {'loop [s]':>10} {'steps':>6} {'halved':>6} {'iters':>6} "
          f"{'/step [ms]':>10} {'/iter [ms]':>10} {'/iter/node [us]':>16}")
    for r in blocks:
        if "error" in r:
            print(f"   {r['n']:>5}  FAILED: {r['error']}")
            continue
        run = r["run"]
        print(f"   {r['n']:>5} {r['call']:>10.3f} {r['loop']:>10.3f} {run.steps:>6} {run.halvings:>6} "
              f"{run.iterations:>6} {1e3 * r['loop'] / run.steps:>10.3f} "
              f"{1e3 * r['loop'] / run.iterations:>10.3f} "
              f"{1e6 * r['loop'] / run.iterations / r['n']:>16.2f}")
    big = [r for r in blocks if r["n"] >= 50 and "error" not in r]
    if len(big) >= 2:
        n = np.array([r["n"] for r in big], float)
        for label, y in (("call time", [r["call"] for r in big]),
                         ("time per Newton iteration", [r["loop"] / r["run"].iterations for r in big])):
            slope = np.polyfit(np.log(n), np.log(y), 1)[0]
            two = math.log(y[-1] / y[0]) / math.log(n[-1] / n[0])
            print(f"   exponent of {label} vs nodes, {int(n[0])}..{int(n[-1])}: least squares "
                  f"{slope:.2f}, end points {two:.2f} (target about 1: linear)")
    targets = {7: 0.1, 200: 2.0}
    for r in blocks:
        if r["n"] in targets and "error" not in r:
            lim = targets[r["n"]]
            print(f"   target {r['n']} nodes < {lim:g} s: {r['call']:.3f} s, "
                  f"{'met' if r['call'] < lim else 'MISSED'}")
    print()


def print_agreement(records):
    print(f"4. Agreement between solvers: top tension at the end of each run (relative to block, "
          f"limit {AGREE_RTOL:g})")
    from seacable.towed.equations import I_T

    for n in sorted({r["n"] for r in records}):
        block = next(r for r in records if r["n"] == n and r["solver"] == "block").get("run")
        for r in records:
            if r["n"] != n or r["solver"] == "block" or block is None or "error" in r:
                continue
            run = r["run"]
            t_end = run.time[-1]
            k = int(np.argmin(np.abs(block.time - t_end)))
            ref = block.state[k, -1, I_T]
            dev = abs(run.state[-1, -1, I_T] - ref) / abs(ref)
            print(f"   {n:>4} nodes, {r['solver']:>6} vs block at t = {t_end:5.1f} s: T_top = "
                  f"{run.state[-1, -1, I_T]:.6f} N vs {ref:.6f} N, rel. diff {dev:.1e} "
                  f"({'agree' if dev <= AGREE_RTOL else 'DISAGREE'})")
    print()


# ------------------------------------------------------------------------------------------
# 5. the towed system of issue 21: a 1000 m cable and a body in a 3-D turn, box and finite element
# ------------------------------------------------------------------------------------------

SURVEY_DURATION = 1200.0   # s
SURVEY_STEP = 1.0          # s
SURVEY_NODES = 100


def survey_case(formulation, n_nodes=SURVEY_NODES, winch=None):
    """1000 m of paper 000's cable and a 2 kN body (C_D A 0.5 m^2) behind a vessel at 2 m/s that turns left at
    0.15 deg/s from t = 200 s for 600 s (a 3-D turn through 90 degrees), 1200 s at 1 s, outputs every 1 s."""
    import seacable as sc

    analysis = {"type": "towed_dynamic", "formulation": formulation, "n_nodes": n_nodes,
                "duration": SURVEY_DURATION, "time_step": SURVEY_STEP, "output_interval": SURVEY_STEP,
                "tangential_drag": "common",
                "vessel": {"type": "turn", "speed": 2.0, "heading": 0.0, "start_time": 200.0,
                           "turn_rate": math.radians(0.15), "end_time": 800.0},
                "body": {"mass": 300.0, "added_mass": 100.0, "weight_in_water": 2000.0, "drag_area": 0.5}}
    if winch is not None:
        analysis["winch"] = winch
    return sc.Case.parse({
        "name": f"survey_{formulation}", "environment": {"water_density": 1025.0},
        "line_types": {"c": {"diameter": 0.035, "mass_per_length": 2.7904, "weight_in_water": 17.7,
                             "axial_stiffness": 4.2333e5, "bending_stiffness": 32.41, "drag_normal": 1.5,
                             "drag_tangential": 0.01, "added_mass_normal": 1.0}},
        "line": {"line_type": "c", "length": 1000.0}, "analysis": analysis})


#: The winch of the pay-out run: 200 m paid out at 0.5 m/s (ramped over 10 s) from t = 300 s.
SURVEY_WINCH = {"rate": 0.5, "start_time": 300.0, "ramp": 10.0, "length": 1200.0}


def time_survey(formulation, n_nodes=SURVEY_NODES, winch=None, repeats=5):
    """Median wall time [s] of seacable.run on the survey case (the result Dataset included), after a warm-up,
    and the last result."""
    import seacable as sc

    case = survey_case(formulation, n_nodes, winch)
    sc.run(case)
    times, ds = [], None
    for _ in range(repeats):
        t0 = time.perf_counter()
        ds = sc.run(case)
        times.append(time.perf_counter() - t0)
    return statistics.median(times), ds


def print_survey(quick=False):
    print(f"5. Issue 21's towed system: 1000 m cable and a body, a 90 deg turn, {SURVEY_DURATION:g} s at "
          f"{SURVEY_STEP:g} s, {SURVEY_NODES} nodes, seacable.run including the result (median of 5)")
    box, ds_box = time_survey("box")
    fe, ds_fe = time_survey("finite_element")
    pay, ds_pay = time_survey("finite_element", winch=SURVEY_WINCH)
    print(f"   box scheme (paper 000, the code before issue 21)   {box:7.3f} s")
    print(f"   finite element                                      {fe:7.3f} s   {box / fe:5.1f}x faster "
          "(target >= 3.5x)")
    print(f"   finite element, 200 m paid out at 0.5 m/s           {pay:7.3f} s   {100 * (pay / fe - 1):+5.1f} % "
          "(target <= +20 %)")
    dT = float(abs(ds_fe.top_tension[-1] - ds_box.top_tension[-1]) / ds_box.top_tension[-1])
    dL = float(abs(ds_fe.layback[-1] - ds_box.layback[-1]))
    print(f"   agreement at the end: top tension {float(ds_box.top_tension[-1]):.1f} (box) vs "
          f"{float(ds_fe.top_tension[-1]):.1f} N (FE), {100 * dT:.2f} %; layback differs by {dL:.2f} m; with pay-out "
          f"{float(ds_pay.top_tension[-1]):.1f} N, {int(ds_pay.nodes_in_water[-1])} nodes")
    sizes = (50, 100, 200) if quick else (50, 100, 200, 400)
    walls = [time_survey("finite_element", n, repeats=1)[0] for n in sizes]
    slope = np.polyfit(np.log(sizes), np.log(walls), 1)[0]
    print("   finite element against nodes: " + ", ".join(f"{n}: {w:.3f} s" for n, w in zip(sizes, walls))
          + f"; time ~ nodes^{slope:.2f}")
    print()


# ------------------------------------------------------------------------------------------

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="7 and 50 nodes only, no cold compilation")
    ap.add_argument("--no-cold", action="store_true", help="skip the cold compilation subprocess")
    ap.add_argument("--full-dense", action="store_true",
                    help="run the dense LU over the whole run at 200 nodes (about 2 min)")
    ap.add_argument("--survey", action="store_true", help="only section 5, issue 21's towed system (about 1 min)")
    ap.add_argument("--_first-call", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args._first_call:
        print(json.dumps(first_call()))
        return
    if args.survey:
        print_survey()
        return
    t_start = time.perf_counter()
    import numba
    import scipy

    print(f"seacable towed-cable benchmark: Python {sys.version.split()[0]}, numpy {np.__version__}, "
          f"scipy {scipy.__version__}, numba {numba.__version__}, {os.cpu_count()} CPUs")
    print(f"case {CASE_FILE.name}: {DURATION:g} s of the turn, time step {TIME_STEP:g} s\n")
    warm = first_call()
    cold = None if (args.quick or args.no_cold) else cold_compile()
    print_one_time(warm, cold)

    sizes = (7, 50) if args.quick else (7, 50, 200, 800)
    # the dense LU is O(N^3): 200 nodes (N = 2000) costs minutes, so only with --full-dense
    compare = (7, 50, 200) if args.full_dense else (7, 50)
    records, blocks, solves, skipped, notes = [], [], {}, [], []
    dense_per_iter = None  # per-iteration dense time at the last size, for the N^3 estimate
    last_n = None
    for n in sizes:
        block = time_solver(n, "block")
        blocks.append(block)
        if n not in compare:
            continue
        records.append(block)
        records.append(time_solver(n, "banded"))
        est = None if dense_per_iter is None else dense_per_iter * (n / last_n) ** 3
        iterations = block["run"].iterations if "run" in block else 500
        dense = time_dense(n, iterations, est, full=args.full_dense)
        if dense is None:
            why = (f"about {est:.0f} s per Newton iteration (N^3 from {last_n} nodes), "
                   f"{est * iterations / 3600:.1f} h for the run (> {DENSE_BUDGET:g} s)")
            skipped.append((n, why))
        else:
            records.append(dense)
            if "per_iter" in dense:
                dense_per_iter, last_n = dense["per_iter"], n
        solves[n], dev, failed = time_linear_solves(n, dense=dense is not None)
        if dev > 1e-8:
            notes.append(f"linear solvers differ by {dev:.1e} (relative) on the {n}-node system")
        if failed:
            notes.append(f"one linear solve at {n} nodes (well-conditioned system, the block solve "
                         f"succeeded): {', '.join(failed)}")
    print_comparison(records, solves, skipped)
    print_scaling(blocks)
    print_agreement(records)
    print_survey(quick=args.quick)
    for note in notes:
        print(f"note: {note}")
    print(f"total benchmark time {time.perf_counter() - t_start:.0f} s")


if __name__ == "__main__":
    main()

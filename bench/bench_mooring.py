"""Speed race on MoorDyn's WD0200 chain: seacable's implicit truss FE vs MoorDyn v2, at equal accuracy.

The case (issue 19): MoorDyn's ``../shared/peers/moordyn/WD0200_Chain.txt`` (a 760 m studless chain in
200 m of water) with its line cut into 20, 50, 100 and 200 segments, the fairlead moved 2 m in heave
at 10 s (no ramp), 100 s simulated, the fairlead tension stored every 0.1 s.

Equal accuracy, found per code and per mesh: each code runs at a ladder of steps (seacable: Newmark
steps 0.1, 0.05, 0.025 s; MoorDyn: CFL 0.4, 0.2, 0.17, 0.14, 0.12, 0.1, its dtM = CFL 2 pi L sqrt(m / EA)); its
converged peak fairlead tension is that of a run at a step 8 (seacable, 0.0125 s) or 2 (MoorDyn, CFL
0.05) times finer than the finest of its ladder; the step it is timed at is the largest of the
ladder whose peak tension is within 1 % of that converged peak (a run that blows up does not count).
Each code is compared with itself: the two models differ (MoorDyn's peak is higher, by its seabed
and lumping), which is the accuracy race of ``bench/moordyn_peer.py``, not this one.

Timing: seacable's is the whole user path, ``run_moordyn_case``: reading the file, the model, the
statics, the time loop and the result Dataset (``wall total``). MoorDyn's is ``Create + Init`` (its
initial-condition solve, a dynamic relaxation) plus the stepping (``wall total``), and the stepping
alone; the ratio is given against both. The two codes run in turn, ``repeat`` pairs in one process (the
machine is shared): medians of wall and CPU time, and of the ratios pair by pair.

The snap-load case (``python bench/bench_mooring.py snap``): a 33 m tank-scale chain of 83 segments whose
fairlead moves on a 0.2 m circle every 1.25 s, the same ladders and 1 % rule (see :func:`snap`).

The overhead around seacable's time loop (issue 38): seacable's ``stepping`` is the compiled time loop alone
(``seacable.mooring.loop.run_outputs``, timed from outside); the rest of the whole call is the file, the model,
the statics, the checks and the Dataset. Target of issue 38: at 20 segments, seacable's whole call at most 0.5
times MoorDyn's stepping (``python bench/bench_mooring.py 5 20``, about a minute). Last measured (7 pairs, a
shared and heavily loaded 2-core machine, main's source and this one in turn, two runs each): 0.61x and 0.60x
before, 0.63x and 0.59x after the overhead was cut again; the wall ratio moves with MoorDyn's own stepping (98-148
ms in those runs, 60 ms on a quieter machine), while the time around seacable's stepping fell from 0.93-1.02 to
0.75-0.78 times the stepping (in thread CPU time, 30 calls of each source three times in turn: from 1.05 to 0.87
times it, 21.8 to 19.7 ms around 21 ms of stepping). That cut: a single line's end forces read from the run's
stored support forces (the same floats) instead of evaluating the 1001 outputs again, the end part of a line's
network built once per model, a single line's view not checked again, the last block of outputs handed over
without copies, the sink's variables taken by the Dataset without copies, the finite check without reshaped
copies, plain floats checked without numpy. Before it: 0.68x and 0.68x (the round before), 0.77x and 0.83x before
the run path was first leaned; the issue's first figure was 1.09x.

The round after: a line's support forces read at its two end nodes only instead of copied for all its nodes, the
grounded length and the node tensions without their temporaries (each as large as an output variable: about 230
fewer page faults a call), no second-touchdown profile in the catenary start of a line without buoyancy, a deck
line's elements listed at once. Thread CPU time, 40 calls of main's source and this one in turn in two warm
processes, twice (the machine loaded to 5, then to 1.3, on its 2 cores): around the stepping 17.95 -> 16.50 and
17.62 -> 14.77 ms (medians; paired differences 1.4 and 1.8 ms, wide quartiles), 0.83 -> 0.76 and 0.83 -> 0.78
times the stepping (20-22 ms there). The race, each source in turn (5 pairs, load 1.3): 0.58x and 0.58x (around
seacable's stepping 17.2 and 16.7 ms of wall time; MoorDyn's stepping 69 and 60 ms): not met, and the ratio
follows MoorDyn's own time as much as seacable's. The stepping alone is about 0.3x MoorDyn's: what is left around it (in a
warm call, thread CPU on that machine) is the file (about 1 ms), the model with its catenary start (2.5-3.5 ms,
the start's line solve 1.5-2.3 ms), the statics (0.3 ms), the exact-catenary check (1.5-2.3 ms: the deck built
and solved as a system, which the system statics' own leaning shortens; reusing the start's catenary instead
would change the check's figure in its last bits), the run's Python side (the motion samples, the start, 1.5-2
ms) and the outputs and Dataset (about 5 ms: the line's positions copied in its node order, 0.5 ms, kept so
for the layout later sums follow; its network variables, 2 ms; the Dataset and its checks, 1 ms).

Run: ``python bench/bench_mooring.py [repeat [segments ...]]`` or ``... snap`` (needs ``pip install
moordyn``; a bench-only dependency).
"""

from __future__ import annotations

import re
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
import moordyn_peer as md

import seacable.mooring.loop as _loop
from seacable.errors import ConvergenceError
from seacable.io.moordyn import load_moordyn_case
from seacable.mooring.moordyn import run_moordyn_case
from seacable.mooring.motion import HarmonicMotion, PlatformMotion

SEGMENTS = (20, 50, 100, 200)
DURATION, AMPLITUDE, PERIOD, OUTPUT = 100.0, 2.0, 10.0, 0.1
SEACABLE_STEPS = (0.1, 0.05, 0.025)
SEACABLE_CONVERGED = 0.0125
MOORDYN_CFL = (0.4, 0.2, 0.17, 0.14, 0.12, 0.1)
MOORDYN_CONVERGED = 0.05
TOLERANCE = 0.01  # each code within 1 % of its own converged peak tension
TARGET = 0.5  # issue 38: seacable's whole call at most half MoorDyn's stepping, at 20 segments
_STEPPING = [0.0]  # seconds in the compiled time loop since the last reset


def _timed_loop(run_outputs):
    def timed(*args, **kwargs):
        start = time.perf_counter()
        try:
            return run_outputs(*args, **kwargs)
        finally:
            _STEPPING[0] += time.perf_counter() - start
    return timed


_loop.run_outputs = _timed_loop(_loop.run_outputs)  # the solver calls it through the module: timed from outside


def deck(segments: int, cfl: float = 0.1, folder=None) -> Path:
    """WD0200_Chain.txt with ``segments`` segments and MoorDyn's ``cfl``, without its saved IC (written to a
    temporary folder; the original is read only)."""
    text = (md.PEER_DIR / "WD0200_Chain.txt").read_text()
    text = re.sub(r"^(1\s+chain\s+1\s+2\s+760\s+)\d+", lambda m: m.group(1) + str(segments), text, flags=re.MULTILINE)
    text = re.sub(r"^.*fileIC.*$", "", text, flags=re.MULTILINE)
    text = re.sub(r"^\S+(\s+cfl\b)", lambda m: f"{cfl:g}" + m.group(1), text, flags=re.MULTILINE)
    path = Path(folder or tempfile.mkdtemp(prefix="bench_mooring_")) / f"WD0200_{segments}_{cfl:g}.txt"
    path.write_text(text)
    return path


def run_seacable(segments: int, dt: float) -> dict:
    """The whole user path: file -> model -> statics -> time loop -> Dataset; the fairlead tension."""
    path = deck(segments)
    _STEPPING[0] = 0.0
    # the CPU clock read outside the wall-clock window: with numba's and OpenBLAS's threads alive, reading the
    # process's CPU time took 2-4 ms on a loaded machine, which the whole call's figure counted once
    cpu = time.process_time()
    start = time.perf_counter()
    case = load_moordyn_case(path).with_run(duration=DURATION, time_step=dt, output_interval=OUTPUT,
                                            motion=HarmonicMotion(amplitude=(0.0, 0.0, AMPLITUDE), period=PERIOD))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the deck's MoorDyn-only options (writeLog, ...)
        ds = run_moordyn_case(case)
    wall = time.perf_counter() - start
    cpu = time.process_time() - cpu
    fair = np.asarray(ds["fairlead_tension"]).reshape(-1)[np.asarray(ds["time"]) >= SNAP_SETTLED - 1e-9]
    return {"peak": float(np.max(fair)), "wall": wall, "cpu": cpu, "stepping": _STEPPING[0],
            "recommended": float(ds.attrs["recommended_time_step"])}


def run_moordyn(segments: int, cfl: float) -> dict | None:
    """MoorDyn from Create to the last step; None when it blows up."""
    motion = md.heave_motion(AMPLITUDE, PERIOD, duration=DURATION + 1.0)
    cpu = time.process_time()
    try:
        with md._quiet():  # its messages when a step blows up
            r = md.run_moordyn(deck(segments, cfl), motion, duration=DURATION, use_ic_file=False)
    except (ConvergenceError, RuntimeError):  # MoorDyn's step error: the step is unstable
        return None
    if not np.all(np.isfinite(r["fairlead_tension"])):
        return None
    settled = np.asarray(r["time"]) >= SNAP_SETTLED - 1e-9
    return {"peak": float(np.max(np.asarray(r["fairlead_tension"])[settled])), "wall": r["wall_time"] + r["wall_time_init"],
            "cpu": time.process_time() - cpu, "loop": r["wall_time"], "dt": r["dt"]}


def _largest_accurate(ladder, run, converged):
    """(step, result) of the largest step of ``ladder`` within TOLERANCE of ``converged``'s peak, and the
    errors [%] of every step."""
    errors = {}
    for step in ladder:
        r = run(step)
        errors[step] = np.nan if r is None else 100.0 * abs(r["peak"] / converged["peak"] - 1.0)
    ok = [s for s in ladder if errors[s] <= 100.0 * TOLERANCE]
    return (max(ok) if ok else None), errors


def _race(n, sc_dt, md_cfl, repeat):
    """seacable and MoorDyn in turn, ``repeat`` pairs (so that both see the same machine load): the median
    of each figure, and the median of the ratios pair by pair."""
    pairs = [(run_seacable(n, sc_dt), run_moordyn(n, md_cfl)) for _ in range(repeat)]
    med = {}
    for key in ("wall", "cpu"):
        med[f"sc_{key}"] = float(np.median([a[key] for a, _ in pairs]))
        med[f"md_{key}"] = float(np.median([b[key] for _, b in pairs]))
        med[f"ratio_{key}"] = float(np.median([a[key] / b[key] for a, b in pairs]))
    med["md_loop"] = float(np.median([b["loop"] for _, b in pairs]))
    med["sc_stepping"] = float(np.median([a["stepping"] for a, _ in pairs]))
    med["ratio_loop"] = float(np.median([a["wall"] / b["loop"] for a, b in pairs]))
    return pairs[0][0], pairs[0][1], med


# the snap deck of tests/validation/test_moordyn_snap_deck.py, its CFL set per run
SNAP_DECK = re.sub(r"^\S+(\s+cfl\s)", r"{cfl}\1",
                   (Path(__file__).parents[1] / "tests" / "validation" / "data" / "snap_deck.txt").read_text(),
                   count=1, flags=re.MULTILINE)
SNAP_FAIRLEAD = (32.0, 0.0, -0.3)
SNAP_RADIUS, SNAP_PERIOD, SNAP_RAMP, SNAP_DURATION, SNAP_OUTPUT = 0.2, 1.25, 2.5, 10.0, 5e-4
SNAP_SETTLED = 6.25  # [s] the start of cycle 5: MoorDyn's own start state gives low first cycles


def snap_motion():
    """The fairlead on a 0.2 m radius circle in the x-z plane every 1.25 s, ramped in over 2.5 s."""
    return PlatformMotion(amplitude=(SNAP_RADIUS, 0.0, SNAP_RADIUS, 0.0, 0.0, 0.0),
                          phase=(np.pi / 2, 0.0, 0.0, 0.0, 0.0, 0.0), period=SNAP_PERIOD, reference=SNAP_FAIRLEAD,
                          ramp=SNAP_RAMP)


def snap_deck(cfl: float = 0.1) -> Path:
    path = Path(tempfile.mkdtemp(prefix="bench_snap_")) / f"snap_{cfl:g}.txt"
    path.write_text(SNAP_DECK.format(cfl=f"{cfl:g}"))
    return path


def run_snap_seacable(dt: float) -> dict | None:
    """The snap case through ``run_moordyn_case``; None when a step does not converge."""
    start, cpu = time.perf_counter(), time.process_time()
    # the peak read at every step: a snap rises over about 10 ms, which coarser outputs sample with a 2-4 % scatter
    case = load_moordyn_case(snap_deck()).with_run(duration=SNAP_DURATION, time_step=dt, output_interval=dt,
                                                   motion=snap_motion())
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ds = run_moordyn_case(case)
    except ConvergenceError as err:
        print(f"  seacable dt {dt:g} s: {str(err)[:160]}")
        return None
    fair = np.asarray(ds["fairlead_tension"]).reshape(-1)[np.asarray(ds["time"]) >= SNAP_SETTLED - 1e-9]
    return {"peak": float(np.max(fair)), "wall": time.perf_counter() - start, "cpu": time.process_time() - cpu}


def run_snap_moordyn(cfl: float) -> dict | None:
    """MoorDyn on the same deck, its coupled point on the same (ramped) circle sampled every output."""
    t = np.arange(0.0, SNAP_DURATION + 1.0 + 1e-9, SNAP_OUTPUT)
    x = snap_motion().channels(t, np.array([SNAP_FAIRLEAD]))[0][:, 0]
    motion = {"time": t, "x": x[:, 0], "y": x[:, 1], "z": x[:, 2]}  # run_moordyn's Init takes them absolute
    cpu = time.process_time()
    try:
        with md._quiet():
            r = md.run_moordyn(snap_deck(cfl), motion, duration=SNAP_DURATION, dt_out=SNAP_OUTPUT,
                               use_ic_file=False)
    except (ConvergenceError, RuntimeError):
        return None
    settled = np.asarray(r["time"]) >= SNAP_SETTLED - 1e-9
    return {"peak": float(np.max(np.asarray(r["fairlead_tension"])[settled])), "wall": r["wall_time"] + r["wall_time_init"],
            "cpu": time.process_time() - cpu, "loop": r["wall_time"], "dt": r["dt"]}


def _peak(r) -> str:
    return "failed" if r is None else f"{r['peak']:.2f} N"


def snap(repeat: int = 3):
    """The snap-load case (issue 19: a 33 m tank-scale chain, 83 segments, its fairlead on a 0.2 m circle
    every 1.25 s; the chain and seabed written here, MoorDyn's cBot lowered to 1e4 Pa s/m, which its CFL
    step does not resolve at 3e5): each code's peak fairlead tension along its ladder of steps, and the
    race at equal accuracy when both have a step within 1 % of their own converged peak."""
    print(f"snap case: 33 m chain, 83 segments, fairlead on a {SNAP_RADIUS:g} m circle every {SNAP_PERIOD:g} s, "
          f"{SNAP_DURATION:g} s; peaks over t >= {SNAP_SETTLED:g} s, seacable's at every step, MoorDyn's every "
          f"{SNAP_OUTPUT:g} s")
    codes = {"seacable": ((0.0025, 0.00125, 1e-3, 5e-4), run_snap_seacable, run_snap_seacable(1.25e-4)),
             "MoorDyn": ((0.14, 0.1, 0.07), run_snap_moordyn, run_snap_moordyn(0.035))}
    chosen = {}
    for name, (ladder, run, ref) in codes.items():
        runs = {step: run(step) for step in ladder}
        ok = [st for st, r in runs.items() if r is not None and ref is not None
              and abs(r["peak"] / ref["peak"] - 1.0) <= TOLERANCE]
        chosen[name] = max(ok) if ok else None
        print(f"  {name}: converged peak {_peak(ref)}; along the ladder "
              + ", ".join(f"{st:g}: {_peak(r)}" for st, r in runs.items())
              + f"; largest step within 1 %: {chosen[name]}")
    if None in chosen.values():
        print("  no race at equal accuracy: a code has no step of its ladder within 1 % of its converged peak")
        return
    pairs = [(run_snap_seacable(chosen["seacable"]), run_snap_moordyn(chosen["MoorDyn"])) for _ in range(repeat)]
    print(f"  wall [s] (median of {repeat} pairs): seacable {float(np.median([a['wall'] for a, _ in pairs])):.3f} at "
          f"{chosen['seacable']:g} s, MoorDyn {float(np.median([b['wall'] for _, b in pairs])):.3f} at CFL "
          f"{chosen['MoorDyn']:g} ({pairs[0][1]['dt']:.3g} s); seacable / MoorDyn wall "
          f"{float(np.median([a['wall'] / b['wall'] for a, b in pairs])):.2f}, cpu "
          f"{float(np.median([a['cpu'] / b['cpu'] for a, b in pairs])):.2f}")


def main(repeat: int = 5, segments=SEGMENTS):
    print(f"WD0200 chain, {AMPLITUDE:g} m heave at {PERIOD:g} s, {DURATION:g} s, fairlead tension every {OUTPUT:g} s; "
          f"each code at its largest step within {100 * TOLERANCE:g} % of its own converged peak tension")
    run_seacable(20, 0.1)  # compile once
    rows = []
    for n in segments:
        sc_ref = run_seacable(n, SEACABLE_CONVERGED)
        sc_dt, sc_err = _largest_accurate(SEACABLE_STEPS, lambda s, n=n: run_seacable(n, s), sc_ref)
        md_ref = run_moordyn(n, MOORDYN_CONVERGED)
        md_cfl, md_err = _largest_accurate(MOORDYN_CFL, lambda c, n=n: run_moordyn(n, c), md_ref)
        sc, mdr, m = _race(n, sc_dt, md_cfl, repeat)
        rows.append((n, sc_dt, md_cfl, mdr["dt"], m))
        print(f"\n{n} segments")
        print(f"  {'code':9s} {'step [s]':>9s} {'peak [kN]':>9s} {'conv. [kN]':>10s} {'err %':>6s} "
              f"{'wall [s]':>9s} {'cpu [s]':>8s} {'stepping [s]':>12s}  errors % along the ladder (nan: blew up)")
        print(f"  {'seacable':9s} {sc_dt:9.3g} {sc['peak'] / 1e3:9.1f} {sc_ref['peak'] / 1e3:10.1f} "
              f"{sc_err[sc_dt]:6.2f} {m['sc_wall']:9.3f} {m['sc_cpu']:8.3f} {m['sc_stepping']:12.3f}  "
              + ", ".join(f"{s:g} s: {e:.2f}" for s, e in sc_err.items()))
        print(f"  {'MoorDyn':9s} {mdr['dt']:9.3g} {mdr['peak'] / 1e3:9.1f} {md_ref['peak'] / 1e3:10.1f} "
              f"{md_err[md_cfl]:6.2f} {m['md_wall']:9.3f} {m['md_cpu']:8.3f} {m['md_loop']:12.3f}  "
              + ", ".join(f"CFL {c:g}: {e:.2f}" for c, e in md_err.items()))
        print(f"  seacable / MoorDyn (median of {repeat} pairs): wall {m['ratio_wall']:.2f}, cpu {m['ratio_cpu']:.2f}, "
              f"seacable's whole wall against MoorDyn's stepping alone {m['ratio_loop']:.2f}; seacable's "
              f"recommended step {sc['recommended']:.3g} s")
    print("\n| segments | seacable dt | MoorDyn CFL (dtM) | seacable wall (stepping) | MoorDyn wall (stepping) | "
          "ratio wall | ratio cpu | ratio vs MoorDyn stepping |")
    print("|---|---|---|---|---|---|---|---|")
    for n, sc_dt, md_cfl, md_dt, m in rows:
        print(f"| {n} | {sc_dt:g} s | {md_cfl:g} ({md_dt:.3g} s) | {m['sc_wall']:.3f} s ({m['sc_stepping']:.3f} s) | "
              f"{m['md_wall']:.3f} s ({m['md_loop']:.3f} s) | {m['ratio_wall']:.2f} | {m['ratio_cpu']:.2f} | "
              f"{m['ratio_loop']:.2f} |")
    for n, _, _, _, m in rows:
        if n == 20:
            print(f"\nissue 38, WD0200 at 20 segments: seacable's whole call {1e3 * m['sc_wall']:.1f} ms "
                  f"({1e3 * m['sc_stepping']:.1f} ms stepping, {1e3 * (m['sc_wall'] - m['sc_stepping']):.1f} ms "
                  f"around it) against MoorDyn's stepping {1e3 * m['md_loop']:.1f} ms: {m['ratio_loop']:.2f}x "
                  f"(target <= {TARGET:g}x: {'met' if m['ratio_loop'] <= TARGET else 'not met'}); seacable's "
                  f"stepping alone {m['sc_stepping'] / m['md_loop']:.2f}x")
    return rows


if __name__ == "__main__" and sys.argv[1:2] == ["snap"]:
    snap()
elif __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 5,
         tuple(int(a) for a in sys.argv[2:]) or SEGMENTS)

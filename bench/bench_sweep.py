"""Speed-up of a sweep on a 2-worker local Dask cluster over the serial loop, and the engine's per-task cost.

The sweep is the example examples/paper001_speed_sweep.yaml: paper 001's cable laid at 18 ship speeds
from 0.75 to 5 m/s (the work per case grows about as the speed squared, so the cases are unequal).

Timed, each from a fresh output folder, after a warm-up that compiles the numba kernels:
- the serial loop: ``seacable.run`` on each case in turn, in this process;
- ``seacable.sweep(..., scheduler="synchronous")``: the same loop with the sweep's bookkeeping
  (per-case NetCDF and records, summary);
- ``seacable.sweep(..., workers=2)``: the default, a local cluster started and stopped by seacable
  (what ``seacable sweep`` does), its start-up included;
- the same sweep sent to an already running 2-worker cluster (``scheduler=ADDRESS``);
- the machine's own limit: two plain processes, each running its half of the cases (split by their
  serial run times, longest first) in a loop, timed inside the processes (no Dask, no start-up).

The per-task overhead of the engine is measured on 400 tiny cases (a static catenary, a few ms each
with its NetCDF) on the running cluster: (wall time x workers - the cases' own time, NetCDF written in
the worker included) / cases.
The issue's target: a speed-up of at least 1.7 on 2 cores.

Whether a sweep of small cases keeps both cores busy (issue 38: a sweep of 10 000 three-line system statics
saturates both cores): ``python bench/bench_sweep.py saturate [N]`` sweeps examples/spread_mooring.yaml (intact
and its most loaded line broken) over N values of the buoy's steady load (default 10 000, for minutes: each case
is two equilibria, its Dataset, its NetCDF file and record; ``saturate 1000`` for a quicker look) on a 2-worker cluster
started beforehand (its start-up not timed), each case's NetCDF and record written. Printed: the wall time,
the CPU time of the workers and of this process (the client, which writes the records), and the cores kept
busy: the workers' CPU time / wall time (2.0: both cores saturated).

Run: ``python bench/bench_sweep.py`` or ``python bench/bench_sweep.py saturate [N]``.
"""

from __future__ import annotations

import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import seacable as sc
from seacable.sweeps import load_sweep

SWEEP = Path(__file__).parents[1] / "examples" / "paper001_speed_sweep.yaml"
WORKERS = 2


def timed(fn):
    start = time.perf_counter()
    out = fn()
    return time.perf_counter() - start, out


def _loop(indices) -> float:
    """Run the sweep's cases ``indices`` in a loop in this process (after a warm-up); the loop's time."""
    spec = load_sweep(SWEEP)
    cases = [c.case for c in spec.cases()]
    sc.run(cases[0].replace(analysis=cases[0].analysis.replace(duration=10.0)))
    start = time.perf_counter()
    for i in indices:
        sc.run(cases[i])
    return time.perf_counter() - start


def _halves(times) -> list[list[int]]:
    """Longest-first greedy split of the cases over two processes."""
    halves, load = [[], []], [0.0, 0.0]
    for i in np.argsort(times)[::-1]:
        k = int(np.argmin(load))
        halves[k].append(int(i))
        load[k] += times[i]
    return halves


def main() -> None:
    from distributed import LocalCluster

    spec = load_sweep(SWEEP)
    cases = [c.case for c in spec.cases()]
    sc.run(cases[0].replace(analysis=cases[0].analysis.replace(duration=10.0)))   # compile
    print(f"{SWEEP.name}: {len(cases)} laying cases, {os.cpu_count()} cores, {WORKERS} workers")

    times = []
    start = time.perf_counter()
    for c in cases:
        times.append(timed(lambda c=c: sc.run(c))[0])
    t_loop = time.perf_counter() - start
    import multiprocessing

    with multiprocessing.get_context("spawn").Pool(WORKERS) as pool:
        t_limit = max(pool.map(_loop, _halves(np.array(times))))
    with tempfile.TemporaryDirectory() as tmp:
        t_sync, _ = timed(lambda: sc.sweep(spec, Path(tmp) / "sync", scheduler="synchronous"))
        t_local, summary = timed(lambda: sc.sweep(spec, Path(tmp) / "local", workers=WORKERS))
        with LocalCluster(n_workers=WORKERS, threads_per_worker=1, processes=True, dashboard_address=None,
                          silence_logs=40) as cluster:
            address = cluster.scheduler_address
            sc.sweep(sc.Sweep(spec.base, grid={"analysis.duration": [10.0, 12.0]}), Path(tmp) / "warm",
                     scheduler=address)   # workers import seacable and load the kernels
            t_warm, _ = timed(lambda: sc.sweep(spec, Path(tmp) / "running", scheduler=address))

            static = sc.Case(name="tiny", line=sc.Line.single(sc.LineType(
                diameter=0.09, mass_per_length=77.7066, axial_stiffness=384.243e6), 902.2),
                environment=sc.Environment(depth=320.0),
                analysis=sc.StaticAnalysis(fairlead=(848.67, -70.0), points_per_segment=2))
            tiny = sc.Sweep(static, grid={"analysis.fairlead[0]": list(np.linspace(840.0, 850.0, 400))})
            t_tiny, tiny_summary = timed(lambda: sc.sweep(tiny, Path(tmp) / "tiny", scheduler=address))

    case_time = float(summary.wall_time.sum())
    print()
    print(f"{'run':<44} {'wall [s]':>9} {'speed-up':>9}")
    print(f"{'serial loop of seacable.run':<44} {t_loop:9.2f} {1.0:9.2f}")
    print(f"{'sweep, synchronous (one process)':<44} {t_sync:9.2f} {t_loop / t_sync:9.2f}")
    print(f"{'sweep, local cluster started by seacable':<44} {t_local:9.2f} {t_loop / t_local:9.2f}")
    print(f"{'sweep, running 2-worker cluster':<44} {t_warm:9.2f} {t_loop / t_warm:9.2f}")
    print(f"{'limit: 2 plain processes, balanced halves':<44} {t_limit:9.2f} {t_loop / t_limit:9.2f}")
    print()
    n_tiny = tiny_summary.sizes["case"]
    tiny_run = float(tiny_summary.wall_time.sum())
    per_task = (t_tiny * WORKERS - tiny_run) / n_tiny
    mean_case = case_time / len(cases)
    print(f"laying cases: {mean_case:.2f} s each on average in the workers ({min(summary.wall_time.values):.2f} "
          f"to {max(summary.wall_time.values):.2f} s)")
    print(f"engine per task: {per_task * 1e3:.1f} ms of worker time ({n_tiny} static cases of "
          f"{tiny_run / n_tiny * 1e3:.2f} ms each, their NetCDF written in the worker: submit, schedule, "
          "gather the outcome, write the record)")
    print(f"per-task overhead / laying case time: {per_task / mean_case:.2%}")


SYSTEM = Path(__file__).parents[1] / "examples" / "spread_mooring.yaml"


def _cpu() -> float:
    """This process's CPU time, user and system. [s]"""
    import resource

    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def saturate(n: int = 10_000) -> None:
    """Sweep ``n`` system statics on a running 2-worker cluster: the cores the workers keep busy."""
    from distributed import Client, LocalCluster

    base = str(SYSTEM)  # a sweep takes a system case as its file
    loads = list(np.linspace(3e5, 6e5, n))
    spec = sc.Sweep(base, grid={"bodies.buoy.external_force[0]": loads})
    with tempfile.TemporaryDirectory() as tmp, LocalCluster(
            n_workers=WORKERS, threads_per_worker=1, processes=True, dashboard_address=None,
            silence_logs=40) as cluster, Client(cluster) as client:
        sc.sweep(sc.Sweep(base, grid={"bodies.buoy.external_force[0]": loads[:2 * WORKERS]}), Path(tmp) / "warm",
                 scheduler=client)  # the workers import seacable and load the kernels
        before, cpu, start = client.run(_cpu), _cpu(), time.perf_counter()
        summary = sc.sweep(spec, Path(tmp) / "run", scheduler=client, write_summary=False)
        wall, cpu = time.perf_counter() - start, _cpu() - cpu
        after = client.run(_cpu)
    workers = sum(after[w] - before[w] for w in after)
    ok = int((summary.status.values == "done").sum())
    run_time = float(summary.wall_time.sum())
    print(f"{SYSTEM.name}: {n} system_static cases ({ok} done) on {WORKERS} workers ({os.cpu_count()} cores)")
    print(f"  wall {wall:.1f} s, {1e3 * wall / n:.2f} ms per case; the cases' own time {run_time:.1f} s "
          f"({1e3 * run_time / n:.2f} ms each)")
    print(f"  CPU: workers {workers:.1f} s, this process (client, records) {cpu:.1f} s")
    print(f"  cores kept busy by the workers: {workers / wall:.2f} of {WORKERS} "
          f"({100 * workers / wall / WORKERS:.0f} %); with this process: {(workers + cpu) / wall:.2f}")


if __name__ == "__main__" and sys.argv[1:2] == ["saturate"]:
    saturate(int(sys.argv[2]) if len(sys.argv) > 2 else 10_000)
elif __name__ == "__main__":
    main()

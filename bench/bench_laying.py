"""Speed of the cable-laying dynamics (the ``laying_dynamic`` analysis, issue 4).

Run: ``python bench/bench_laying.py`` (about 30 s), ``--repeat N`` (best of N counted runs per
case, default 3), ``--duration T`` (simulated time per run, default 1000 s); ``--route`` adds issue 22's
3-D lay along a 100 km route in 1000 m of water with 5 m segments (``--route-duration``, default 3600 s of
it; target at least 200 x real time), see :func:`route_case`, and a table of the same lay along routes of
many waypoints over a KP bathymetry table (:func:`long_route_case`: 10 and 500 waypoints, 1000 s each), where
every seabed look-up locates points on the route. ``--sliding`` times the 3-D lay under 500 N of bottom tension with
the laid cable held and free to slide (``laid_cable: sliding``) at two frictions (:func:`sliding_bench`).

The issue's measurement: the wall time to lay 1 km of cable in 100 m of water at 1 m/s ship speed
with 1 m segments; target: faster than real time by a factor of at least 100 on this machine. The
cable is paper 001's (seeds/001; the same line type as ``examples/paper001_lay_2ms_50m.yaml``):
d = 0.0225 m, m = 0.867 kg/m, w = 4.49 N/m in water, C_dn = 1.85, C_dt = 0, C_an = 1, rho = 1030
kg/m^3, inextensible, payout ``{type: slack, slack: 0.05}``. "Lay 1 km" is taken as 1000 s of ship
time: at 1 m/s with 5 % slack that pays out about 1050 m (the laid length reached is printed). The
case is built in code (seacable.Case / LineType / Line / Environment / LayingDynamicAnalysis,
output every 10 s) and run with ``seacable.run``. Two more rows: 2 m segments at 1 m/s, and 1 m
segments at 2 m/s (the same 1000 s, so about 2.1 km laid). The cable on board is 4000 m long,
more than any row pays out, so no run stops for lack of cable (checked: ``interrupted``).

Columns: nodes = the largest number of suspended nodes in the run (settings ``max_nodes``; the
cable between touchdown and water entry, about 232 m at 1 m/s in 100 m of water), steps and
Newton iterations from the Dataset's settings, simulated s = the run's duration, wall s = the
whole ``seacable.run`` call (case set-up, time integration and building the xarray Dataset; the
integration alone, settings ``wall_time_s``, is printed as "loop s"), real-time factor =
simulated s / wall s. Wall times are the best of ``--repeat`` runs with ``time.perf_counter``,
after a warm-up run of 5 s per case so that numba's compilation (or loading its on-disk cache) is
excluded; that one-time cost is printed separately. This is a benchmark, not a test: it prints,
it does not assert.

Measured (issue 38: the time loop's work between steps done once a step, in fewer numpy calls, and the step's
block solve compiled for its block size; the same results to the bit), on the shared 2-core machine, best of 3,
wall s (real-time factor) before -> after: 1 m segments at 1 m/s 1.85 s (541 x) -> 1.10 s (911 x); 2 m segments
at 1 m/s 0.66 s (1512 x) -> 0.42 s (2378 x); 1 m segments at 2 m/s 5.55 s (180 x) -> 3.55 s (282 x).
Then (issue 38: the events between steps on Python floats, the heading and the step's array views kept, the
same results to the bit), CPU s of ``seacable.run`` (time.process_time, best of 5, the range of two runs each on
the shared machine, whose wall times varied twofold), before -> after: 1 m segments at 1 m/s 1.54-1.83 ->
1.10-1.27; 2 m segments at 1 m/s 0.52-0.66 -> 0.40-0.47; 1 m segments at 2 m/s 4.09-4.86 -> 4.03-4.21 (445 nodes:
the kernel's time); the whole benchmark process 0.74 of the CPU time before (median of 3 pairs).
Then (issue 38: the step kernel's node matrices, assembly and chords compiled for the dimension as a constant;
the seabed's look-ups of a 3-D lay compiled, a KP table's route location and a grid's bilinear depth, without the
memory of looked-up points; the same results to the bit), best of 3 wall s on the loaded shared machine,
2026-11-30, one run each, before -> after: 1 m segments at 1 m/s 1.25 -> 0.93; 2 m segments at 1 m/s 0.36 ->
0.31; 1 m segments at 2 m/s 3.53 -> 2.73; ``--sliding``: held 6.28 -> 5.10, mu = 0.5 13.08 -> 9.91, mu = 0.2
12.08 -> 11.01.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

import numpy as np

DEPTH = 100.0           # m, the water depth
DURATION = 1000.0       # s of ship time: "lay 1 km" at 1 m/s
WARM_UP = 5.0           # s, the warm-up run per case (excluded from the timings)
OUTPUT_INTERVAL = 10.0  # s between stored states
CABLE_LENGTH = 4000.0   # m on board: more than 1000 s at 2 m/s with 5 % slack pays out (2100 m)
SLACK = 0.05            # payout slack, paper 001 section 4
TARGET = 100.0          # issue 4: at least 100 times faster than real time
CASES = (               # (label, segment length [m], ship speed [m/s])
    ("1 m segments, 1 m/s", 1.0, 1.0),
    ("2 m segments, 1 m/s", 2.0, 1.0),
    ("1 m segments, 2 m/s", 1.0, 2.0),
)


def make_case(segment_length, speed, duration):
    """The issue's laying case (paper 001's cable, 100 m of water, 5 % slack) built in code."""
    import seacable

    cable = seacable.LineType(diameter=0.0225, mass_per_length=0.867, weight_in_water=4.49,
                              drag_normal=1.85, drag_tangential=0.0, added_mass_normal=1.0,
                              name="paper001_cable")
    return seacable.Case(
        name="bench_laying",
        description="Issue 4 speed benchmark: paper 001's cable laid in 100 m of water.",
        line=seacable.Line.single(cable, CABLE_LENGTH),
        environment=seacable.Environment(water_density=1030.0, depth=DEPTH),
        analysis=seacable.LayingDynamicAnalysis(
            ship=seacable.ShipMotion(speed=speed), payout=seacable.PayoutSlack(slack=SLACK),
            duration=duration, segment_length=segment_length,
            output_interval=min(OUTPUT_INTERVAL, duration)),
    )


def run_once(segment_length, speed, duration):
    """One ``seacable.run`` call: a record of its wall time and the Dataset's counts."""
    import seacable

    case = make_case(segment_length, speed, duration)
    t0 = time.perf_counter()
    ds = seacable.run(case)
    wall = time.perf_counter() - t0
    settings = json.loads(ds.attrs["settings"])
    return {"wall": wall, "loop": float(settings["wall_time_s"]), "steps": int(settings["steps"]),
            "iterations": int(settings["newton_iterations"]), "halved": int(settings["halved_steps"]),
            "nodes": int(settings["max_nodes"]),
            "nodes_end": int(np.isfinite(ds.x.values[-1]).sum()),
            "laid": float(ds.laid_length.values[-1]), "simulated": float(ds.time.values[-1]),
            "interrupted": int(ds.attrs["interrupted"]), "stop_reason": settings.get("stop_reason", "")}


def _dispatchers():
    """Every numba dispatcher of the laying kernel."""
    from numba.core.registry import CPUDispatcher

    from seacable.laying import kernel

    return [obj for obj in vars(kernel).values() if isinstance(obj, CPUDispatcher)]


def warm_up():
    """Import time, the first (compiling or cache-loading) warm-up call and the cache counts."""
    t0 = time.perf_counter()
    import seacable  # noqa: F401
    from seacable.laying import kernel  # noqa: F401

    t_import = time.perf_counter() - t0
    first = run_once(*CASES[0][1:], WARM_UP)["wall"]
    later = run_once(*CASES[0][1:], WARM_UP)["wall"]
    hits = sum(sum(d.stats.cache_hits.values()) for d in _dispatchers())
    misses = sum(sum(d.stats.cache_misses.values()) for d in _dispatchers())
    for _, ds_, v in CASES[1:]:  # same signatures, but warm every case's code path all the same
        run_once(ds_, v, WARM_UP)
    return {"import": t_import, "first": first, "later": later, "hits": hits, "misses": misses}


def bench(label, segment_length, speed, duration, repeat):
    """Best of ``repeat`` runs (by wall time) of one case."""
    runs = [run_once(segment_length, speed, duration) for _ in range(repeat)]
    best = min(runs, key=lambda r: r["wall"])
    best["label"] = label
    best["spread"] = (min(r["wall"] for r in runs), max(r["wall"] for r in runs))
    return best


def print_table(rows, repeat):
    print(f"Laying dynamics, {DEPTH:g} m of water, paper 001's cable, payout slack {SLACK:g} "
          f"(best of {repeat} after the warm-up)")
    head = (f"{'case':<22} {'nodes':>6} {'steps':>7} {'Newton iterations':>18} {'simulated s':>12} "
            f"{'wall s':>8} {'real-time factor':>17}   {'laid m':>7} {'loop s':>7} {'min-max wall s':>15}")
    print(head)
    print("-" * len(head))
    for r in rows:
        print(f"{r['label']:<22} {r['nodes']:>6} {r['steps']:>7} {r['iterations']:>18} "
              f"{r['simulated']:>12.0f} {r['wall']:>8.3f} {r['simulated'] / r['wall']:>17.0f}   "
              f"{r['laid']:>7.1f} {r['loop']:>7.3f} {r['spread'][0]:>7.3f}-{r['spread'][1]:.3f}")
    print()
    main = rows[0]
    factor = main["simulated"] / main["wall"]
    print(f"Issue 4 target: {main['label']} at >= {TARGET:g}x real time: {factor:.0f}x, "
          f"{'met' if factor >= TARGET else 'MISSED'} ({main['laid']:.0f} m laid in {main['wall']:.2f} s, "
          f"{main['nodes']} suspended nodes, {1e3 * main['loop'] / main['steps']:.3f} ms per step, "
          f"{1e6 * main['loop'] / main['iterations'] / main['nodes']:.2f} us per Newton iteration "
          f"and node)")
    for r in rows:
        if r["interrupted"] or r["halved"] or r["nodes_end"] != r["nodes"]:
            print(f"note: {r['label']}: interrupted={r['interrupted']} {r['stop_reason']!r}, "
                  f"{r['halved']} halved steps, {r['nodes_end']} suspended nodes at the end "
                  f"(max {r['nodes']})")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3, metavar="N",
                    help="counted runs per case, the best is reported (default 3)")
    ap.add_argument("--duration", type=float, default=DURATION, metavar="T",
                    help=f"simulated time per run [s] (default {DURATION:g})")
    ap.add_argument("--route", action="store_true", help="also the 3-D lay along a 100 km route (issue 22)")
    ap.add_argument("--route-duration", type=float, default=3600.0, metavar="T",
                    help="simulated time of the 3-D lay [s] (default 3600)")
    ap.add_argument("--sliding", action="store_true",
                    help="also the 3-D lay under a bottom tension, its laid cable held and sliding")
    args = ap.parse_args(argv)
    if args.repeat < 1:
        ap.error(f"--repeat must be >= 1, got {args.repeat}")
    if not args.duration >= OUTPUT_INTERVAL:
        ap.error(f"--duration must be >= {OUTPUT_INTERVAL:g} s, got {args.duration:g}")
    t_start = time.perf_counter()
    import numba
    import scipy

    print(f"seacable laying benchmark: Python {sys.version.split()[0]}, numpy {np.__version__}, "
          f"scipy {scipy.__version__}, numba {numba.__version__}, {os.cpu_count()} CPUs")
    w = warm_up()
    state = ("warm: every compiled function loaded from disk" if w["misses"] == 0 and w["hits"] > 0
             else f"cold: {w['misses']} compilations" if w["hits"] == 0
             else f"partly warm: {w['hits']} loaded, {w['misses']} compiled")
    print(f"numba warm-up ({WARM_UP:g} s runs, excluded from the table): import {w['import']:.2f} s, "
          f"first call {w['first']:.2f} s, second {w['later']:.3f} s => one-time "
          f"{w['first'] - w['later']:.2f} s (on-disk cache {state})\n")
    rows = [bench(label, ds_, v, args.duration, args.repeat) for label, ds_, v in CASES]
    print_table(rows, args.repeat)
    if args.route:
        route_bench(args.route_duration, args.repeat)
        long_route_bench(args.repeat)
    if args.sliding:
        sliding_bench(args.repeat)
    print(f"total benchmark time {time.perf_counter() - t_start:.0f} s")


ROUTE_TARGET = 200.0    # issue 22: a 100 km route at 1000 m, 5 m segments, in 3-D: >= 200 x real time


def route_case(duration, route=None, bathymetry=None):
    """Issue 22's 3-D lay: a telecom cable (35 mm, 4.1 N/m in water) along a 100 km route of two legs (an
    alter-course of 22 degrees at KP 50 km), 1000 m of water, 0.2 m/s of current at 57 degrees to the first
    leg, 3 % slack, 1.5 m/s, 5 m segments (about 660 suspended nodes), output every 100 s; or along another
    ``route`` over a ``bathymetry`` table by KP."""
    import seacable
    from seacable.laying.route import Route

    route = route or Route(waypoints=((-10e3, 0.0), (50e3, 0.0), (96e3, 18.6e3)), kp_start=-10e3)
    cable = seacable.LineType(diameter=0.035, mass_per_length=1.4, axial_stiffness=3e7, drag_normal=1.2,
                              drag_tangential=0.01, added_mass_normal=1.0, name="tel35")
    return seacable.Case(
        name="bench_lay_route", line=seacable.Line.single(cable, 200e3),
        environment=seacable.Environment(depth=1000.0, current=seacable.Current(speed=0.2, heading=1.0)),
        analysis=seacable.LayingDynamicAnalysis(
            ship=seacable.ShipMotion(speed=1.5), payout=seacable.PayoutSlack(slack=0.03), duration=duration,
            segment_length=5.0, output_interval=min(100.0, duration), route=route, bathymetry=bathymetry))


def route_bench(duration, repeat):
    """The 3-D lay: ``duration`` s of it (the whole 100 km at 1.5 m/s is 18.5 h), best of ``repeat``."""
    import seacable

    seacable.run(route_case(100.0))                   # warm-up: compile or load the 3-D kernel
    runs = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        ds = seacable.run(route_case(duration))
        runs.append((time.perf_counter() - t0, ds))
    wall, ds = min(runs, key=lambda r: r[0])
    st = json.loads(ds.attrs["settings"])
    factor = duration / wall
    print(f"\n3-D lay along a route (issue 22): 1000 m of water, 5 m segments, {st['max_nodes']} suspended nodes, "
          f"{duration:g} s simulated (best of {repeat})")
    print(f"  wall {wall:.2f} s (loop {st['wall_time_s']:.2f} s), {st['steps']} steps, {st['newton_iterations']} Newton "
          f"iterations: {factor:.0f} x real time; target >= {ROUTE_TARGET:g} x: {'met' if factor >= ROUTE_TARGET else 'MISSED'}"
          f" (the whole 100 km, {100e3 / 1.5 / 3600:.1f} h, would take about {100e3 / 1.5 / factor / 60:.0f} min)")


LONG_ROUTE_DURATION = 1000.0    # s simulated per long-route row
LONG_ROUTES = (                 # (waypoints, seabed: "kp" a bathymetry table by KP, "flat" environment.depth)
    (10, "flat"),
    (10, "kp"),
    (500, "kp"),
)


def long_route_case(n_waypoints, seabed, duration):
    """Issue 22's lay (:func:`route_case`: cable, 1000 m, current, slack, speed, 5 m segments) along a route of
    ``n_waypoints`` from x = -10 km to 90 km (KP -10 km at the first), y = 300 sin(x / 3 km) m, and for more than
    20 waypoints a seeded random 20 m (1 sigma) across at each (500 waypoints: 200 m legs that all turn); the
    current pushes the suspended nodes up to 650 m off the route. ``seabed="kp"``: the depth by KP, a table of
    1301 rows, 1000 m +- 60 m (period 25 km) +- 20 m (period 4.4 km); ``"flat"``: 1000 m everywhere."""
    from seacable.laying.inputs import Bathymetry
    from seacable.laying.route import Route

    x = np.linspace(-10e3, 90e3, n_waypoints)
    y = 300.0 * np.sin(x / 3000.0)
    if n_waypoints > 20:
        y = y + np.random.default_rng(7).normal(0.0, 20.0, n_waypoints)
    bathymetry = None
    if seabed == "kp":
        kp = np.linspace(-10e3, 120e3, 1301)
        depth = 1000.0 + 60.0 * np.sin(kp / 4000.0) + 20.0 * np.sin(kp / 700.0)
        bathymetry = Bathymetry(distance=tuple(kp), depth=tuple(depth))
    return route_case(duration, Route(waypoints=tuple(zip(x.tolist(), y.tolist())), kp_start=-10e3), bathymetry)


def long_route_bench(repeat):
    """The 3-D lay along routes of many waypoints (:data:`LONG_ROUTES`), best of ``repeat`` runs each."""
    import seacable

    print(f"\n3-D lay along long routes: {LONG_ROUTE_DURATION:g} s simulated each, best of {repeat}; target >= "
          f"{ROUTE_TARGET:g} x real time")
    head = (f"{'waypoints':>9} {'seabed':>9} {'nodes':>6} {'steps':>6} {'Newton iterations':>18} {'wall s':>7} "
            f"{'loop s':>7} {'real-time factor':>17}")
    print(head)
    print("-" * len(head))
    for n, seabed in LONG_ROUTES:
        seacable.run(long_route_case(n, seabed, 20.0))                 # warm-up (the k-d tree, imports)
        runs = []
        for _ in range(repeat):
            case = long_route_case(n, seabed, LONG_ROUTE_DURATION)
            t0 = time.perf_counter()
            ds = seacable.run(case)
            runs.append((time.perf_counter() - t0, ds))
        wall, ds = min(runs, key=lambda r: r[0])
        st = json.loads(ds.attrs["settings"])
        table = "KP table" if seabed == "kp" else "flat"
        print(f"{n:>9} {table:>9} {st['max_nodes']:>6} {st['steps']:>6} {st['newton_iterations']:>18} {wall:>7.2f} "
              f"{st['wall_time_s']:>7.2f} {LONG_ROUTE_DURATION / wall:>17.0f}")


def sliding_bench(repeat, duration=1200.0):
    """:func:`route_case` (1000 m of water, 5 m segments) under 500 N of bottom tension, elastic, for ``duration``
    s through its alter-course region's approach: the laid cable held where it lands, and free to slide against
    a friction of 0.5 and 0.2 (the laid cable kept in the step reaches 1.25 T_b / (mu w), 300 m and 760 m)."""
    import seacable

    base = route_case(duration)
    base = base.replace(analysis=base.analysis.replace(payout=seacable.PayoutBottomTension(tension=500.0),
                                                       extensible=True))
    print(f"\n3-D lay under 500 N of bottom tension, 1000 m of water, 5 m segments, {duration:g} s "
          f"(best of {repeat})")
    head = f"{'laid cable':<22} {'steps':>7} {'Newton iterations':>18} {'wall s':>8} {'real-time factor':>17}"
    print(head)
    print("-" * len(head))
    for label, friction in (("held", None), ("sliding, mu = 0.5", 0.5), ("sliding, mu = 0.2", 0.2)):
        case = base if friction is None else base.replace(
            environment=base.environment.replace(seabed=seacable.Seabed(friction=friction)),
            analysis=base.analysis.replace(laid_cable="sliding"))
        seacable.run(case.replace(analysis=case.analysis.replace(duration=20.0, output_interval=20.0)))  # warm
        walls, ds = [], None
        for _ in range(repeat):
            t0 = time.perf_counter()
            ds = seacable.run(case)
            walls.append(time.perf_counter() - t0)
        settings = json.loads(ds.attrs["settings"])
        print(f"{label:<22} {int(settings['steps']):>7} {int(settings['newton_iterations']):>18} {min(walls):>8.2f} "
              f"{duration / min(walls):>17.0f}")


if __name__ == "__main__":
    main()


"""Speed of a coupled storm of a floating platform with its hydrodynamic database (issue 39).

The IEA-15 MW VolturnUS-S on its three chains (the public MoorDyn deck: 850 m of 685 kg/m chain, anchors 837.6 m
out in 200 m of water, fairleads at 14 m draft), its WAMIT database (radiation memory over 60 s, first-order
excitation, Newman slow drift from the .12d diagonal), in a 3-hour JONSWAP storm (Hs 8 m, Tp 12 s, heading 0,
200 components), stepped at 0.1 s with the lines at ``N`` elements. The body's mass properties are the platform's
and turbine's rounded (mass 2.03e7 kg, centre of gravity 2 m below the water line, inertias 4e10, 4e10, 2.4e10 kg
m^2): a speed figure, not a validation. Issue 39's target: under 30 s on one core with 40 elements a line.

The lines feel the irregular sea (its kinematics on a grid, as a single line's run; in depth bands,
:class:`seacable.seastate.SeaBands`, when ``seacable.system.dynamics.loop.SEA_BANDS`` is on, the
default). Measured 2026-11-30 (one process, shared 2-core machine), 40
elements a line, dt 0.1 s:

  database                             600 s run                3-hour storm                     target
  tests' extract (sea to 1.45 rad/s)     2.8 s (215x)             45.9 s wall, 45.8 s CPU (235x)   1.5x over 30 s
  full (sea to 2.45 rad/s), one grid     6.8 s (88x)              109 s wall, 190 s CPU (99x)      3.6x over 30 s
  full, one grid, at load 4.6           22.8 s wall, 8.6 s CPU    302 s wall, 171 s CPU            10x over 30 s
  full, depth bands, at load 4.6         7.7 s wall, 3.0 s CPU    80.5 s wall, 50.6 s CPU          2.7x over 30 s
  full, depth bands, at load 3.1                                  50.0 s wall, 49.0 s CPU (216x)   1.7x over 30 s
  full, one grid (bands off), merged main, load 0.6               100 s wall, 158 s CPU (108x)     3.3x over 30 s
  full, bands refined 1.4x (the default), merged main, load 1.2   36.8 s wall, 48.5 s CPU (294x)   1.2x over 30 s
  the same, one core (taskset -c 0), idle machine, no wind          24.5 s (440x)                  met
  the same with NPD wind 25 m/s and the wind table (the target's      22.2-22.5 s run, 24.5 s the      met
  case), held kinematics, one core pinned, 3 runs                      whole process (median)
  examples/volturnus_storm.yaml (Hs 10 m, Tp 14 s, wind 30 m/s,      29.0-30.0 s run, 31.8 s the      at the target
  current 1 m/s, quadratic drag; ``--example``), one core, 3 runs      whole process (median)

(the two rows at load 4.6 in the same minutes, one after the other). With the bands made the default (held still, a
buoy's lines keep the one grid's tensions, tests/validation/test_system_dynamics_irregular_sea.py; the bands below
the top one on 1.4 times finer steps, ``seacable.seastate.BAND_REFINE``), 1200 s of storm on the whole database,
alternating twice: one grid 18.7-19.3 s CPU (10.5-10.8 s wall), bands 5.2-6.6 s CPU (3.5-4.8 s wall; on their
own steps 4.9-5.2 s): 3.2 times less; surge largest 8.63 and 8.64 m, fairlead tension largest 2926 and 2913 kN.
Profiled over 1200 s with the bands (load 3, on their own steps): 6.96 s, of which 3.37 s in the coupled steps
(about 30 s for 3 hours: the stepping alone is now over the target), 2.20 s in the grid's windows (16.7 s of 21 s
with one grid), 0.59 s in the body's first-order loads' set-up (``seacable.hydro.loads._phasor_sum``).

The depth bands (below the top band only the components carrying 0.1 % or more of the acceleration's standard
deviation, on steps that follow the shortest kept; columns no point reaches in a band's depths hold no levels):
3.4 times less CPU for the storm, 2.9 times for 600 s; the grid's windows 5.7 times less (0.63 against 3.6-4.2 s
of CPU per 300 s of storm at load 5-10, window by window). The coupled steps, profiled at load about 1 before the
bands, took 0.59 s per 300 s (0.38 s with a calm sea: the waves' share, more Newton iterations and look-ups).
The storm's statistics stay: surge mean 2.00 m, largest 10.36 m (10.37 m with one grid), largest fairlead tension
3111 kN (3116 kN). At 0.1 s a few steps need halving (the first at t = 273.8 s), which the radiation memory
allows (:func:`seacable.system.dynamics.kernel.coupled_steps`).

The uncoupled route (``--quasi_static``, ``--dynamic``; the lines' damping of the slow drift at 5 % of critical),
measured 2026-11-30 on the tests' extract at load 7-11 (so the wall times are inflated; the CPU times less so):

  route                                 run       wall     CPU     surge mean/max [m]  max fairlead [kN]   target
  uncoupled, quasi-static lines         3 hours    6.8 s    2.7 s   1.77/10.28          3036                10 s: met
  same, whole database, load 2, merged   3 hours    1.7 s    2.1 s   2.12/10.75          3060                10 s: met
  uncoupled, lines in time (40 el.)     600 s     18.2 s    3.5 s   1.81/6.97           2774

The quasi-static route's time (profiled, 5.3 s at load 5): the three catenaries and their profiles at the 10 801
outputs 2.4 s, the slow drift's sum over the 200 components (on the low-frequency step, 0.5 s) 1.3 s, the Dataset
1.0 s, Cummins' equation 0.2 s. With the lines in time it costs what the coupled run's lines do (the same kernel,
the body prescribed): the fast route is the quasi-static one.

Reads the whole database from the project (``examples/data/volturnus``, the sea cut at 2.45 rad/s: its drift
coefficients stop at 2.5 rad/s). The figures above marked "tests' extract" were taken with the tests' extract of it
(its excitation stops at 1.45 rad/s).

Since 2026-11-30 the storm has NPD's wind (25 m/s at 10 m, its gusts) on the parked turbine's table of the example,
as issue 39's target names it, and the coupled step holds the sea's kinematics over its Newton iterations. Profiled on
one core over 1200 s of the example: the coupled steps 2.0 s (2.9 Newton passes a step against 2.0 in a calm sea: the
body's wave-frequency motion, not the kinematics, which held change none), the grid's windows 1.6 s (the top band,
200 components at 2145 points x 4 values over 865 times a window, is 80 % of them: a single-precision product at
the core's peak, about 100 GFlop/s), the rest 0.3 s.

Run: ``python bench/bench_floating.py [DURATION_S [ELEMENTS [TIME_STEP_S]]] [--quasi_static | --dynamic | --example]``
(default 10800 s, 40, 0.1 s, the coupled route; ``--quasi_static`` / ``--dynamic``: the uncoupled route with its
lines quasi-static or in time, the lines' damping at 5 % of critical; ``--example``: examples/volturnus_storm.yaml
for the duration, the other numbers its own). On one core: ``taskset -c 0 python bench/bench_floating.py``.
"""

from __future__ import annotations

import math
import os
import sys
import tempfile
import time
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
#: the whole database in the project (examples/data/volturnus: the full .1 and .3, the .12d diagonal)
DATABASE = ROOT / "examples" / "data" / "volturnus" / "IEA-15-240-RWT-UMaineSemi"
EXAMPLE = ROOT / "examples" / "volturnus_storm.yaml"


#: the parked turbine's wind table of examples/volturnus_storm.yaml (C A 1700 m^2 at 72 m, the same every way)
_HEADINGS = [k * math.pi / 6.0 for k in range(12)]
WIND_TABLE = {"height": 72.0, "headings": _HEADINGS, "surge": [1700.0 * math.cos(b) for b in _HEADINGS],
              "sway": [1700.0 * math.sin(b) for b in _HEADINGS], "yaw": [0.0] * 12}


def case(duration: float, elements: int, time_step: float = 0.1, route: str = "coupled") -> dict:
    database, top = DATABASE, 2.45  # the sea cut where the drift coefficients end (2.5 rad/s)
    fair = [(-58.0, 0.0), (29.0, 50.229), (29.0, -50.229)]
    anchor = [(-837.6, 0.0), (418.8, 725.383), (418.8, -725.383)]
    points, lines = {}, {}
    for k in range(3):
        points[f"fair{k}"] = {"kind": "body", "body": "hull", "position": [*fair[k], -14.0]}
        points[f"anchor{k}"] = {"kind": "fixed", "position": [*anchor[k], -200.0]}
        lines[f"chain{k}"] = {"line_type": "chain", "length": 850.0, "end_a": f"anchor{k}", "end_b": f"fair{k}"}
    return {
        "name": "volturnus_storm",
        "line_types": {"chain": {"diameter": 0.333, "mass_per_length": 685.0, "axial_stiffness": 3.27e9,
                                 "drag_normal": 2.0, "added_mass_normal": 0.82, "drag_tangential": 0.4}},
        "environment": {"water_density": 1025.0, "gravity": 9.80665, "depth": 200.0,
                        "waves": {"spectrum": "jonswap", "hs": 8.0, "tp": 12.0, "seed": 1, "n_components": 200,
                                  "frequency_range": [0.25, top]},
                        "wind": {"speed": 25.0, "heading": 0.0, "spectrum": "npd", "seed": 1}},
        "bodies": {"hull": {"kind": "free", "mass": 2.03e7, "center_of_gravity": [0.0, 0.0, -2.0],
                            "inertia": [4e10, 4e10, 2.4e10], "volume": 20206.34889,
                            "hydrodynamics": {"file": str(database), "kernel_length": 60.0, "drift": "newman",
                                              "ramp": 60.0},
                            "wind": WIND_TABLE}},
        "points": points, "lines": lines,
        "analysis": {"type": "system_dynamic", "duration": duration, "time_step": time_step, "output_interval": 1.0,
                     "n_elements": elements, **_route(route)},
    }


def _route(route: str) -> dict:
    """The analysis keys of a route: 'coupled', or the uncoupled one with its lines 'quasi_static' or 'dynamic' (the
    lines' damping of the low-frequency motion estimated at 5 % of critical: the hull has no viscous damping)."""
    if route == "coupled":
        return {}
    return {"coupling": "uncoupled", "uncoupled": {"lines": route, "mooring_damping": 0.05}}


def example(duration: float) -> dict:
    """examples/volturnus_storm.yaml (Hs 10 m, Tp 14 s, wind 30 m/s, current 1 m/s, HydroDyn's quadratic drag)
    for ``duration`` [s], its database's path made absolute."""
    data = yaml.safe_load(EXAMPLE.read_text())
    hydro = data["bodies"]["hull"]["hydrodynamics"]
    hydro["file"] = str(EXAMPLE.parent / hydro["file"])
    data["analysis"]["duration"] = duration
    return data


def main(duration: float = 10800.0, elements: int = 40, time_step: float = 0.1, route: str = "coupled") -> None:
    import seacable as sc

    folder = Path(tempfile.mkdtemp(prefix="bench_floating_"))
    path = folder / "volturnus.yaml"
    make = example if route == "example" else lambda d: case(d, elements, time_step, route)
    path.write_text(yaml.safe_dump(make(duration), sort_keys=False))
    print(f"VolturnUS-S, {route}, {duration:g} s storm, {elements} elements a line, dt {time_step:g} s, "
          f"load {os.getloadavg()[0]:.2f}")
    loaded = sc.load_case(path)
    warm = make(2.0)  # the kernels compiled (or loaded from the cache) before the timing
    (folder / "warm.yaml").write_text(yaml.safe_dump(warm, sort_keys=False))
    sc.run(sc.load_case(folder / "warm.yaml"))
    cpu, wall = time.process_time(), time.perf_counter()
    ds = sc.run(loaded)
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    surge = ds["body_position"].values[:, 0, 0]
    tension = ds["fairlead_tension"].values
    print(f"{'wall [s]':>9} {'CPU [s]':>8} {'x real time':>12} {'surge mean/max [m]':>19} {'max fairlead [kN]':>18}")
    print(f"{wall:9.1f} {cpu:8.1f} {duration / wall:12.0f} {surge.mean():9.2f}/{surge.max():<8.2f} "
          f"{tension.max() / 1e3:18.0f}")


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    flags = [a.removeprefix("--") for a in sys.argv[1:] if a.startswith("--")]
    main(float(args[0]) if args else 10800.0, int(args[1]) if len(args) > 1 else 40,
         float(args[2]) if len(args) > 2 else 0.1, flags[0] if flags else "coupled")

"""Snap loads of the tank chain (``examples/snap_load_tank_chain.yaml``): cycle maxima against step, mesh
and the generalised-alpha spectral radius.

For each step and spectral radius, the largest fairlead tension of each period after the ramp (every
step stored, so that a peak is sampled at the step), their spread over the cycles, the largest error
against the finest run (83 segments, rho_inf 1) and the wall time of the time loop. Then the mesh: 41, 83
and 166 segments at fine steps. The test ``tests/validation/test_mooring_snap_loads.py`` runs a part.

Run: ``python bench/bench_snap_convergence.py [cycles]`` (default 2 cycles after the 1.25 s ramp; about
5 minutes on one core, with the reference run); ``python bench/bench_snap_convergence.py deck [taut]``: the
mesh study of the MoorDyn snap deck (below, about 10 minutes; ``taut``: the damper in taut elements only).

Measured (2 cycles; two runs in parallel on a shared 2-core machine, so wall times are indicative; spread is
max - min of the cycle maxima and err the largest error, both in % of the reference):

    reference (83 segments, dt 6.25e-5 s, rho_inf 1): cycle maxima [86.95 87.22] N
    segs    dt [s]  rho               maxima [N] spread % max err % wall [s]
      83     0.002 1.00            [416.6 335.4]     93.2     379.1     0.59
      83     0.002 0.90            [233.8 509.5]    316.6     484.1     0.64
      83     0.002 0.80            [237.7 241.2]      4.1     176.6     1.16
      83     0.002 0.60            [146.8 137.1]     11.1      68.8     1.53
      83     0.001 1.00              [81.1 82.8]      1.9      -6.7     2.69
      83     0.001 0.90              [85.1 71.3]     15.9     -18.2     3.75
      83     0.001 0.80              [91.1 83.2]      9.1       4.8     3.80
      83     0.001 0.60              [86.  87.2]      1.4      -1.1     3.71
      83    0.0005 1.00              [93.2 85.3]      9.1       7.2     6.50
      83    0.0005 0.90              [90.3 87.6]      3.1       3.9     7.22
      83    0.0005 0.80              [91.2 89.1]      2.5       4.9     7.19
      83    0.0005 0.60              [88.9 97. ]      9.3      11.2     4.68
      83   0.00025 1.00              [88.1 87.5]      0.7       1.3    12.74
      83   0.00025 0.90              [88.4 89.6]      1.4       2.7    16.31
      83   0.00025 0.80              [89.6 88.9]      0.9       3.1    15.32
      83   0.00025 0.60              [87.8 87.8]      0.0       1.0    11.22
      83  0.000125 1.00              [87.1 87.7]      0.6       0.5    23.94
      83  0.000125 0.90              [87.3 87.8]      0.5       0.6    34.02
      83  0.000125 0.80              [86.9 87.6]      0.8       0.5    10.07
      83  0.000125 0.60              [87.4 87.8]      0.4       0.7     8.10
      83  6.25e-05 0.80              [86.9 87.3]      0.4       0.1    17.58
      41   0.00025 1.00              [80.6 77.6]      3.5     -11.0     5.16
      41  0.000125 1.00              [80.2 79.5]      0.8      -8.9    11.12
     166  0.000125 1.00              [87.6 85.2]      2.7      -2.3    36.80
     166  6.25e-05 1.00              [88.7 85.4]      3.8      -2.1    55.17

The peak converges once the highest axial mode is resolved (2 c / h = 3500 rad/s: omega dt <= 0.9,
dt <= 2.5e-4 s, within 1.3 % with rho_inf 1), whatever the spectral radius; rho_inf < 1 converges no
sooner (at 2.5e-4 s, 1.0-3.1 %). At coarser steps the spectral radius damps the ringing of the
unresolved modes (at 2e-3 s the maxima fall from 4.8 to 1.7 times the converged with rho_inf 0.6; 0.9, whose
amplification at omega dt = 7 is still 0.99 a step, does not help) but does
not give the converged peak: at 1e-3 and 5e-4 s every radius is 1-18 % off (the 1.1 % of rho_inf 0.6 at
1e-3 s is not systematic: 11 % at 5e-4 s). The mesh: 41 segments are 9-11 % low; 166 segments are within
2.3 % of 83 per cycle and 0.6 % in the mean of the two cycles (the finer mesh's cycles differ by 3-4 %).
332 segments (3.125e-5 s; 6.25e-5 s: 47.6 and 46.1 N) give [47.5 46.9] N: the example's maxima do not
converge with the mesh. Its chain has no axial damper and no EI, and the maximum comes while nearly all of
it is slack (78 of 83, 151 of 166 elements): a 1-2 ms jerk of a slack stretch coming taut.

The MoorDyn snap deck (``deck``; 1.25 s ramp, maxima over 1.875-3.125 s and 3.125-4.375 s, around the
snaps; "slack": slack elements at each maximum; "vs previous": against the mesh above at the same step):

          BA   EI segs    dt [s]       maxima [N]     slack  vs previous % wall [s]
        53.6  0.5   83    0.0005    [55.94 53.93]     [0 0]                     2.1
        53.6  0.5   83  0.000125    [55.81 53.63]     [0 0]                     6.0
        53.6  0.5  166   0.00025    [55.62 53.45]     [0 0]                     7.4
        53.6  0.5  166  0.000125    [55.51 53.36]     [0 0]  [-0.52 -0.5 ]     12.1
        53.6  0.5  332  0.000125    [55.45 53.24]     [0 0]  [-0.12 -0.21]     24.6
        53.6  0.5  664  0.000125    [55.43 53.23]     [0 0]  [-0.03 -0.03]     52.8
        53.6  0.5  664  6.25e-05    [55.42 53.21]     [0 0]                   114.2
        -0.8  0.5   83  0.000125    [55.81 53.63]     [0 0]                     9.1
        -0.8  0.5  166  0.000125    [65.94 63.44]     [0 0]  [18.16 18.31]     16.0
        -0.8  0.5  332  0.000125    [74.66 72.72]     [0 0]  [13.21 14.62]     27.2
        53.6    0   83  0.000125    [57.29 57.04]     [0 0]                     3.3
        53.6    0  166  0.000125    [55.46 55.12]     [0 0]  [-3.19 -3.38]      8.9
        53.6    0  332  0.000125    [71.73 81.16] [286 295]  [29.33 47.26]     15.5
        53.6    0  664  6.25e-05    [52.63 50.33]     [0 0]                    64.6
        -0.8    0   83  0.000125    [57.29 57.04]     [0 0]                     4.5
        -0.8    0  166  0.000125    [65.41 64.96]     [0 0]  [14.18 13.88]      7.5
        -0.8    0  332  0.000125    [73.12 73.82]     [0 0]  [11.78 13.65]     14.7
        -0.8    0  664  6.25e-05    [76.45 76.76]     [0 0]                    62.9

    and with the damper in taut elements only (``deck taut``; BA 53.6 N s, EI 0.5 N m^2):

        53.6  0.5   83   0.00025  [168.62 169.14]   [81 80]                     6.1
        53.6  0.5   83  0.000125  [134.98 135.21]   [81 82]                     9.8
        53.6  0.5  166   0.00025  [271.13 225.38] [165 162]  [60.79 33.25]     12.5
        53.6  0.5  166  0.000125  [156.66 130.46] [163 141]  [16.06 -3.51]     21.3
        53.6  0.5  332  0.000125  [152.17 229.08] [297 270]  [-2.87 75.6 ]     93.4

The maxima converge with the mesh only for the same physical line on every mesh, a damper coefficient
(BA in N s: the deck's -0.8 of a segment's critical damping is 0.8 l sqrt(EA m), halved with l), with a
bending stiffness (without it a slack stretch folds on the segment's scale: at 332 segments a jerk of the
slack line, 0.25 s before the snap, is the maximum, and 664 segments are 4-9 % below 332) and MoorDyn's
damper in slack segments too (in taut ones only, slack elements come taut as impacts, spikes of 130-270 N
with nearly every element slack, converged in neither step nor mesh). Then 55.81, 55.51, 55.45, 55.43 N
(53.63, 53.36, 53.24, 53.23 N), a Richardson limit of 55.42 (53.22) N: 83 segments within 0.8 %, 166
within 0.3 % (tests/validation/test_moordyn_snap_deck.py).
"""

from __future__ import annotations

import dataclasses
import sys
import time
from pathlib import Path

import numpy as np

import seacable as sc
from seacable.io.moordyn import load_moordyn_case
from seacable.mooring.moordyn import prepare_moordyn
from seacable.mooring.motion import PlatformMotion, bind
from seacable.mooring.run import prepare_mooring_dynamic
from seacable.mooring.solver import simulate, static_equilibrium

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "snap_load_tank_chain.yaml"
PERIOD = 1.25


def cycle_maxima(n_elements: int, dt: float, rho: float, cycles: int):
    """Largest fairlead tension of each period after the ramp [N] and the wall time of the time loop [s]."""
    data = sc.load_case(EXAMPLE).model_dump(mode="json", exclude_none=True)
    data["analysis"].update(n_elements=n_elements, duration=PERIOD * (cycles + 1), time_step=dt,
                            output_interval=dt, spectral_radius=rho)
    case = sc.Case(**data)
    a = case.analysis
    setup = prepare_mooring_dynamic(case)
    start = static_equilibrium(setup.model, tol=a.tolerance).position
    t0 = time.perf_counter()
    run = simulate(setup.model, setup.motion, a.duration, dt, dt, initial=start, tol=min(a.tolerance * 10, 1e-4),
                   spectral_radius=rho)
    wall = time.perf_counter() - t0
    fair = setup.model.network.line_nodes[0][-1]
    tension = np.linalg.norm(run.support[:, fair], axis=1)
    k = np.floor(run.time / PERIOD - 1e-9).astype(int)
    return np.array([tension[k == c].max() for c in range(1, cycles + 1)]), wall


def main(cycles: int = 2):
    ref, _ = cycle_maxima(83, 6.25e-5, 1.0, cycles)
    print(f"reference (83 segments, dt 6.25e-5 s, rho_inf 1): cycle maxima {np.round(ref, 2)} N")
    print(f"{'segs':>4s} {'dt [s]':>9s} {'rho':>4s} {'maxima [N]':>24s} {'spread %':>8s} {'max err %':>9s} "
          f"{'wall [s]':>8s}")
    rows = [(83, dt, rho) for dt in (2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4) for rho in (1.0, 0.9, 0.8, 0.6)]
    rows += [(83, 6.25e-5, 0.8), (41, 2.5e-4, 1.0), (41, 1.25e-4, 1.0), (166, 1.25e-4, 1.0), (166, 6.25e-5, 1.0)]
    for n, dt, rho in rows:
        m, wall = cycle_maxima(n, dt, rho, cycles)
        err = (m - ref) / ref * 100
        print(f"{n:4d} {dt:9.3g} {rho:4.2f} {np.array2string(np.round(m, 1)):>24s} "
              f"{np.ptp(m) / np.mean(ref) * 100:8.1f} {err[np.argmax(np.abs(err))]:9.1f} {wall:8.2f}", flush=True)


DECK = (Path(__file__).resolve().parents[1] / "tests" / "validation" / "data" / "snap_deck.txt").read_text()
CHAIN = "chain      0.0054  0.0948     3.0e5      -0.8        0 "
SEGMENTS = "33.0      83 "
BA_83 = 0.8 * (33.0 / 83) * float(np.sqrt(3.0e5 * 0.0948))  # [N s], the deck's BA = -0.8 at 83 segments


def deck_maxima(segments: int, dt: float, ba: float, ei: float, tmp: Path, slack_damping: bool = True):
    """The snap deck (tests/validation/data/snap_deck.txt) with ``segments`` segments, axial damping column
    ``ba`` [N s, or -zeta] and EI ``ei`` [N m^2], 1.25 s ramp: the largest fairlead tension in each of the
    periods 1.875-3.125 s and 3.125-4.375 s (around the snaps at about 2.5 and 3.8 s), read every
    max(dt, 2.5e-4 s) [N], the number of slack elements at each and the wall time of the time loop [s].
    ``slack_damping`` False: the damper in taut elements only (seacable's rule for its own cases)."""
    path = tmp / f"snap_{segments}.txt"
    path.write_text(DECK.replace(CHAIN, f"chain      0.0054  0.0948     3.0e5      {ba!r}  {ei!r} ")
                    .replace(SEGMENTS, f"33.0      {segments} "))
    motion = PlatformMotion(amplitude=(0.2, 0.0, 0.2, 0.0, 0.0, 0.0), phase=(np.pi / 2, 0.0, 0.0, 0.0, 0.0, 0.0),
                            period=PERIOD, reference=(32.0, 0.0, -0.3), ramp=1.25)
    out = max(dt, 2.5e-4)
    case = load_moordyn_case(path).with_run(duration=4.375, time_step=dt, output_interval=out, motion=motion)
    model = prepare_moordyn(case)
    model = type(model)(model.network, dataclasses.replace(model.water, slack_damping=slack_damping))
    st = static_equilibrium(model, tol=1e-8)
    fn = bind(case.motion, model.network.channel_positions(st.position), case.duration)
    t0 = time.perf_counter()
    run = simulate(model, fn, case.duration, dt, out, initial=st.position, tol=1e-7)
    wall = time.perf_counter() - t0
    tension = np.linalg.norm(run.support[:, model.network.line_nodes[0][-1]], axis=1)
    window = np.floor((run.time - 1.875) / PERIOD - 1e-9)
    peaks = [np.flatnonzero(window == k)[np.argmax(tension[window == k])] for k in (0, 1)]
    return tension[peaks], np.sum(run.tension[peaks] <= 0.0, axis=1), wall


def deck_mesh(taut_only: bool = False):
    """The snap deck's cycle maxima against the mesh: with its damping ratio per segment (BA = -0.8) or the
    same damper as a coefficient on every mesh (BA = 53.64 N s, its value at 83 segments), without and with
    a bending stiffness EI of 0.5 N m^2; ``taut_only``: the coefficient and EI with the damper in taut
    elements only."""
    import tempfile
    tmp = Path(tempfile.mkdtemp())
    print(f"{'BA':>8s} {'EI':>4s} {'segs':>4s} {'dt [s]':>9s} {'maxima [N]':>16s} {'slack':>9s} "
          f"{'vs previous %':>14s} {'wall [s]':>8s}")
    rows = [(BA_83, 0.5, n, dt) for n, dt in ((83, 5e-4), (83, 1.25e-4), (166, 2.5e-4), (166, 1.25e-4),
                                               (332, 1.25e-4), (664, 1.25e-4), (664, 6.25e-5))]
    rows += [(-0.8, 0.5, n, dt) for n, dt in ((83, 1.25e-4), (166, 1.25e-4), (332, 1.25e-4))]
    rows += [(ba, 0.0, n, dt) for ba in (BA_83, -0.8) for n, dt in ((83, 1.25e-4), (166, 1.25e-4), (332, 1.25e-4),
                                                                     (664, 6.25e-5))]
    if taut_only:
        rows = [(BA_83, 0.5, n, dt) for n, dt in ((83, 2.5e-4), (83, 1.25e-4), (166, 2.5e-4), (166, 1.25e-4),
                                                   (332, 1.25e-4))]
    last = {}
    for ba, ei, n, dt in rows:
        m, slack, wall = deck_maxima(n, dt, ba, ei, tmp, slack_damping=not taut_only)
        prev = last.get((ba, ei, dt))
        diff = np.array2string(np.round((m - prev) / prev * 100, 2)) if prev is not None else ""
        last[(ba, ei, dt)] = m
        print(f"{ba:8.3g} {ei:4.2g} {n:4d} {dt:9.3g} {np.array2string(np.round(m, 2)):>16s} "
              f"{np.array2string(slack):>9s} {diff:>14s} {wall:8.1f}", flush=True)


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "deck":
        deck_mesh(taut_only=sys.argv[2:] == ["taut"])
    else:
        main(int(sys.argv[1]) if len(sys.argv) > 1 else 2)

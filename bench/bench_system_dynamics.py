"""Per-step time of the coupled body-line dynamics against the prescribed-motion model (same lines).

Three 20-element chains on a free buoy (system_dynamic), and the same network with the buoy's points
moved by a prescribed platform motion (the mooring model's simulate): seconds per time step of each and
Newton iterations per step. The two runs alternate, a pair at a time, so that a shared machine's drift
hits both; printed: the best time of each and the median of the pairs' ratios (CPU time of the process, so that
other work on a shared machine counts less).
Run: PYTHONPATH=src python bench/bench_system_dynamics.py [pairs]
"""

import math
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "validation"))
from test_system_dynamics import ENV, buoy_system

from seacable.mooring.network import PRESCRIBED
from seacable.mooring.solver import MooringModel, simulate
from seacable.system.dynamics import SystemDynamicAnalysis, build_system_fe, simulate_system, static_system


def main(duration=200.0, dt=0.1, pairs=7):
    system = buoy_system(body={"center_of_gravity": (0, 0, -10)})
    a = SystemDynamicAnalysis(duration=duration, time_step=dt, output_interval=1.0, release_offsets={"buoy": (2, 0, 0, 0, 0, 0)})
    fe = build_system_fe(system, ENV, a)
    st = static_system(fe)
    r = simulate_system(fe, st, duration, dt, 1.0, analysis=a)  # compiles; its surge moves the prescribed model
    # the prescribed model: the fairlead nodes held, moved by the coupled run's body surge
    net = fe.model.network
    kind = net.kind.copy()
    chan = np.full(net.n_nodes, -1)
    for j, node in enumerate(fe.con_node):
        kind[node] = PRESCRIBED
        chan[node] = j
    pm = MooringModel(net.replace(kind=kind, channel=chan, n_channels=len(fe.con_node),
                                  channel_names=tuple(f"f{j}" for j in range(len(fe.con_node)))), fe.model.water)
    base = st.position[fe.con_node]

    def motion(times):
        x = np.interp(times, r.time, r.body_position[:, 0, 0] - st.body_position[0, 0])
        X = base[None] + np.stack([x, 0 * x, 0 * x], -1)[:, None, :]
        return X, np.zeros_like(X), np.zeros_like(X)

    simulate(pm, motion, 2.0, dt, 1.0, initial=st.position)  # compile
    coupled, prescribed, ratios = math.inf, math.inf, []
    for _ in range(pairs):
        t = time.process_time()
        rc = simulate_system(fe, st, duration, dt, 1.0, analysis=a)
        c = (time.process_time() - t) / rc.steps
        t = time.process_time()
        pr = simulate(pm, motion, duration, dt, 1.0, initial=st.position)
        p = (time.process_time() - t) / pr.steps
        coupled, prescribed = min(coupled, c), min(prescribed, p)
        ratios.append(c / p)
    print(f"coupled (free body, {net.n_nodes} nodes): {coupled * 1e6:.1f} us/step, "
          f"{rc.iterations / rc.steps:.2f} Newton iterations/step")
    print(f"prescribed motion (same lines):      {prescribed * 1e6:.1f} us/step, "
          f"{pr.iterations / pr.steps:.2f} Newton iterations/step")
    print(f"ratio coupled / prescribed: {coupled / prescribed:.2f} (best times), {np.median(ratios):.2f} (median of "
          f"{pairs} pairs, {min(ratios):.2f} to {max(ratios):.2f})")


if __name__ == "__main__":
    main(pairs=int(sys.argv[1]) if len(sys.argv) > 1 else 7)

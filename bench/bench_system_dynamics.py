"""Per-step time of the coupled body-line dynamics against the prescribed-motion model (same lines).

Three 20-element chains on a free buoy (system_dynamic), and the same network with the buoy's points
moved by a prescribed platform motion (the mooring model's simulate): seconds per time step of each.
Run: PYTHONPATH=src python bench/bench_system_dynamics.py
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


def main(duration=200.0, dt=0.1, repeat=5):
    system = buoy_system(body={"center_of_gravity": (0, 0, -10)})
    a = SystemDynamicAnalysis(duration=duration, time_step=dt, output_interval=1.0, release_offsets={"buoy": (2, 0, 0, 0, 0, 0)})
    fe = build_system_fe(system, ENV, a)
    st = static_system(fe)
    simulate_system(fe, st, 2.0, dt, 1.0, analysis=a)  # compile
    coupled = math.inf
    for _ in range(repeat):  # the best of a few runs: the machine is shared
        t = time.perf_counter()
        r = simulate_system(fe, st, duration, dt, 1.0, analysis=a)
        coupled = min(coupled, (time.perf_counter() - t) / r.steps)
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

    simulate(pm, motion, 2.0, dt, 1.0, initial=st.position)
    prescribed = math.inf
    for _ in range(repeat):
        t = time.perf_counter()
        pr = simulate(pm, motion, duration, dt, 1.0, initial=st.position)
        prescribed = min(prescribed, (time.perf_counter() - t) / pr.steps)
    print(f"coupled (free body, {net.n_nodes} nodes): {coupled * 1e6:.1f} us/step, "
          f"{r.iterations / r.steps:.2f} Newton iterations/step")
    print(f"prescribed motion (same lines):      {prescribed * 1e6:.1f} us/step, "
          f"{pr.iterations / pr.steps:.2f} Newton iterations/step")
    print(f"ratio coupled / prescribed: {coupled / prescribed:.2f}")


if __name__ == "__main__":
    main()

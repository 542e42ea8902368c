"""Drive seacable's mooring lines from another code: a prescribed surge of a coupled hull (:mod:`seacable.coupling`).

The hull of ``coupling_hull.yaml`` (OC3-Hywind's three catenaries on a body of kind ``coupled``) surges
``x(t) = A sin(w t)``, ramped in over its first period, as a hydrodynamics code would move it; at each of the code's
steps seacable advances the lines and returns their force on the hull (global axes, moments about its reference
point: what the code adds to its equations of motion). Printed: the force table every 5 s, the mooring stiffness at
rest and at the largest offset, and the run's Dataset (system_dynamic's variables). The same loop with MoorDyn reads
``moordyn.Init(s, x, xd)``, ``moordyn.Step(s, x, xd, t, dt)``, ``moordyn.Close(s)``.

Run: ``python examples/coupling_surge.py`` (about 10 s).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from seacable.coupling import Coupling

A, PERIOD, DT, DURATION = 8.0, 30.0, 0.2, 60.0  # surge amplitude [m], period [s], the code's step [s], run [s]


def surge(t: float) -> tuple[np.ndarray, np.ndarray]:
    """The hull's pose and velocity at t: a surge oscillation ramped in (half cosine) over its first period."""
    w = 2 * math.pi / PERIOD
    r, dr = (1.0, 0.0) if t >= PERIOD else ((1 - math.cos(math.pi * t / PERIOD)) / 2,
                                            math.pi / PERIOD * math.sin(math.pi * t / PERIOD) / 2)
    x, xd = np.zeros(6), np.zeros(6)
    x[0] = A * r * math.sin(w * t)
    xd[0] = A * (dr * math.sin(w * t) + r * w * math.cos(w * t))
    return x, xd


def main():
    moor = Coupling(Path(__file__).with_name("coupling_hull.yaml"), time_step=0.1)
    print("coupled DOFs:", ", ".join(moor.dof_names))
    f = moor.init(surge(0.0)[0])
    print(f"{'t [s]':>6} {'surge [m]':>10} {'Fx [kN]':>10} {'Fz [kN]':>10} {'My [kN m]':>11} {'max T [kN]':>11}")
    n = round(DURATION / DT)
    for k in range(n + 1):
        t = k * DT
        if k:
            x, xd = surge(t)
            f = moor.step(x, xd, t - DT, DT)  # from t - DT to t, the hull at x, xd at t
        if k % round(5.0 / DT) == 0:
            top = max(max(pair) for pair in moor.tensions().values())
            print(f"{t:6.1f} {surge(t)[0][0]:10.3f} {f[0] / 1e3:10.1f} {f[2] / 1e3:10.1f} {f[4] / 1e3:11.1f} "
                  f"{top / 1e3:11.1f}")
    np.set_printoptions(precision=4, suppress=False)
    print("stiffness at rest, surge row [N/m, N/m, N/m, N/rad, N/rad, N/rad]:", moor.stiffness(np.zeros(6))[0])
    print(f"stiffness in surge at +{A:g} m: {moor.stiffness(np.r_[A, np.zeros(5)])[0, 0]:.4g} N/m")
    ds = moor.close()
    print(ds[["fairlead_tension", "coupled_force"]])


if __name__ == "__main__":
    main()

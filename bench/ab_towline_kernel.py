"""A/B timing of two versions of the towline kernel (``seacable/towline/kernel.py``) in one process.

Whole-run timings (``bench_towline.py``) on a shared, loaded machine scatter by +-30 % between runs; this script
times only ``run_steps``, in CPU seconds of this process, alternating the two kernels step block by step block
from the same saved state of the paper 003 zig-zag case (1000 steps a block by default), and reports each one's
minimum and median ns an element-step and the median of the B/A ratios, pair by pair. It ends with the largest
relative difference of the two kernels' final states (round-off for the same physics; the towline's state is
sensitive to round-off where a joint's law switches, e.g. a damper as the joint goes slack, so compare a few
hundred steps for that).

Run: ``python bench/ab_towline_kernel.py A_KERNEL.py B_KERNEL.py [n_elements] [blocks] [steps] [t_start]``, e.g.
main's kernel against a worktree's: ``python bench/ab_towline_kernel.py ../main/src/seacable/towline/kernel.py
src/seacable/towline/kernel.py 100``. The state at ``t_start`` (60 s) is simulated once with the installed
package and cached in the temporary directory.
"""

from __future__ import annotations

import hashlib
import importlib.util
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import yaml

import seacable as sc
from seacable.towline.run import prepare_towline_dynamic
from seacable.towline.solver import simulate

CASE = Path(__file__).parents[1] / "examples" / "paper003_zigzag.yaml"
WORK = Path(tempfile.gettempdir()) / "seacable_ab_towline"


def _load(path: str, tag: str):
    """The kernel file as its own module (its numba cache beside the copy), the barge and ``_jit`` from the package."""
    text = Path(path).read_text().replace("from .barge import", "from seacable.towline.barge import")
    text = text.replace("from .._jit import", "from seacable._jit import")
    name = f"kernel_{tag}_{hashlib.sha1(text.encode()).hexdigest()[:10]}"
    dst = WORK / f"{name}.py"
    if not dst.exists():
        dst.write_text(text)
    spec = importlib.util.spec_from_file_location(name, dst)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def main(a_path, b_path, n=100, blocks=20, steps=1000, t_start=60.0):
    WORK.mkdir(exist_ok=True)
    KA, KB = _load(a_path, "a"), _load(b_path, "b")
    data = yaml.safe_load(CASE.read_text())
    data["analysis"].update(n_elements=n, duration=t_start, output_interval=1.0)
    prep = prepare_towline_dynamic(sc.parse_case(data))
    saved = WORK / f"state_{n}_{t_start:g}.npz"
    if not saved.exists():
        f = simulate(prep.model, prep.tug, t_start, 1.0, prep.state).final
        np.savez(saved, R=f.R, E=f.E, nu=f.nu, om=f.om, first=f.first, barge=f.barge)
    S = np.load(saved)
    model = prep.model
    P, BP = model.params, model.barge_params
    xt, zt = model.barge_tow_point
    held = model.held or model.barge is None
    dt = prep.time_step
    tug_p, tug_v = prep.tug(t_start + dt * np.arange(steps + 1))

    def run(K, count):
        R, E, nu, om = S["R"].copy(), S["E"].copy(), S["nu"].copy(), S["om"].copy()
        first, bs = np.array([int(S["first"])], np.int64), S["barge"].copy()
        ma, inert = np.zeros((n, 3)), np.full(n, P[K.P_I])
        tension, slack = np.zeros(n + 1), np.zeros(n + 1, np.bool_)
        K.evaluate(R, E, nu, om, int(first[0]), P, tug_p[0], tug_v[0], bs, xt, zt, inert, tension, slack, ma)
        start = time.process_time()
        done = K.run_steps(dt, tug_p[:count + 1], tug_v[:count + 1], R, E, nu, om, first, P, bs, BP, xt, zt, held,
                           ma, inert, tension, slack)
        cpu = time.process_time() - start
        if done != count:
            raise RuntimeError(f"the state stopped being finite after {done} steps")
        return cpu / count / n * 1e9, (R, E, nu, om, bs, tension)

    run(KA, 2), run(KB, 2)  # compiled (or loaded from the cache) before the clock
    ta, tb = [], []
    for _ in range(blocks):
        a, sa = run(KA, steps)
        b, sb = run(KB, steps)
        ta.append(a)
        tb.append(b)
    ta, tb = np.array(ta), np.array(tb)
    ratio = tb / ta
    print(f"{n} elements, {blocks} blocks of {steps} steps, CPU ns an element-step: A min {ta.min():.1f} median "
          f"{np.median(ta):.1f}, B min {tb.min():.1f} median {np.median(tb):.1f}; B/A median {np.median(ratio):.3f} "
          f"(quartiles {np.quantile(ratio, 0.25):.3f}, {np.quantile(ratio, 0.75):.3f})")
    dev = max(float(np.max(np.abs(x - y)) / max(np.max(np.abs(x)), 1e-300)) for x, y in zip(sa, sb))
    print(f"largest relative difference of the final states after {steps} steps: {dev:.2e}")


if __name__ == "__main__":
    args = sys.argv[1:]
    if len(args) < 2:
        raise SystemExit(__doc__)
    main(args[0], args[1], *(int(x) for x in args[2:5]), *(float(x) for x in args[5:6]))

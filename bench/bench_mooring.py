"""Speed race on MoorDyn's quasi-static chain cases: seacable's implicit truss FE vs MoorDyn v2.

Same input files (``../shared/peers/moordyn/WD{0050,0200,0600}_Chain.txt``, equal segment
counts), same heave motion (2 m or 5 m at 10 s, no ramp), 100 s simulated after the statics. The
accuracy of both is measured against the OrcaFlex fairlead-tension series over its 20 s, as the
largest error of the swing about each code's static value in % of OrcaFlex's peak-to-peak range
(MoorDyn's test accepts 15 %). Wall times are for the time stepping alone, best of ``repeat``;
the statics (seacable's Newton, MoorDyn's IC) are listed separately.

Run: ``python bench/bench_mooring.py [A1|A2]`` (needs ``pip install moordyn``; a bench-only
dependency).
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np
from scipy.interpolate import CubicSpline

sys.path.insert(0, str(Path(__file__).parent))
import moordyn_peer as md

from seacable.mooring.moordyn import moordyn_model
from seacable.mooring.network import PRESCRIBED
from seacable.mooring.solver import simulate, static_equilibrium


def _motion_fn(base, motion):
    t0 = motion["time"][0]
    spline = CubicSpline(motion["time"] - t0, np.column_stack([motion["x"], motion["y"], motion["z"]]))

    def fn(t):
        t = np.asarray(t, float)
        return base[None] + spline(t)[:, None, :], spline(t, 1)[:, None, :], spline(t, 2)[:, None, :]

    return fn


def run_seacable(case: Path, motion: dict, duration: float, dt: float):
    """Statics then ``duration`` s of the motion; dict in the layout of ``moordyn_peer.run_moordyn``."""
    start = time.perf_counter()
    model = moordyn_model(case)
    st = static_equilibrium(model)
    t_static = time.perf_counter() - start
    base = model.network.position[model.network.kind == PRESCRIBED]
    start = time.perf_counter()
    run = simulate(model, _motion_fn(base, motion), duration, dt, 0.1, initial=st.position, tol=1e-6)
    wall = time.perf_counter() - start
    fair = model.network.line_nodes[0][-1]
    return {"time": run.time + motion["time"][0],
            "fairlead_tension": np.linalg.norm(run.support[:, fair], axis=1),
            "anchor_tension": np.linalg.norm(run.support[:, 0], axis=1),
            "static_fairlead_tension": float(np.linalg.norm(st.support[fair])),
            "static_anchor_tension": float(np.linalg.norm(st.support[0])),
            "wall_time": wall, "wall_time_init": t_static, "steps": run.steps, "iterations": run.iterations,
            "n_segments": model.network.n_elements}


def main(amplitude_tag: str = "A1", duration: float = 100.0, repeat: int = 3, dts=(0.1, 0.05)):
    print(f"MoorDyn chain cases, heave {amplitude_tag} (10 s), {duration:g} s simulated; "
          "error = max |swing - OrcaFlex swing| / OrcaFlex peak-to-peak")
    print(f"{'case':7s} {'code':14s} {'segs':>4s} {'dt [s]':>9s} {'static [s]':>10s} {'100 s [s]':>9s} "
          f"{'ratio':>6s} {'T0 [kN]':>8s} {'T0 Orca':>8s} {'dyn err %':>9s} {'anchor %':>8s}")
    for tag in md.STATIC_REFERENCE:
        ref = md.load_reference(tag, amplitude_tag)
        case = md.PEER_DIR / f"{tag}_Chain.txt"
        span = ref["motion"]["time"][-1] - ref["motion"]["time"][0]
        long_motion = md.heave_motion(ref["amplitude"], duration=duration + 1.0)
        acc_md = md.accuracy(md.run_moordyn(case, ref["motion"], duration=span), ref)
        runs = [md.run_moordyn(case, long_motion, duration=duration) for _ in range(repeat)]
        t_md = min(r["wall_time"] for r in runs)
        print(f"{tag:7s} {'MoorDyn ' + runs[0]['version']:14s} {runs[0]['n_segments']:4d} {runs[0]['dt']:9.2e} "
              f"{min(r['wall_time_init'] for r in runs):10.3f} {t_md:9.3f} {1.0:6.2f} "
              f"{acc_md['static_fairlead_tension'] / 1e3:8.1f} {acc_md['static_fairlead_tension_ref'] / 1e3:8.1f} "
              f"{acc_md['fairlead_max_error_pct']:9.2f} {acc_md['anchor_max_error_pct']:8.2f}")
        for dt in dts:
            acc = md.accuracy(run_seacable(case, ref["motion"], span, dt), ref)
            runs = [run_seacable(case, long_motion, duration, dt) for _ in range(repeat)]
            t_sc = min(r["wall_time"] for r in runs)
            print(f"{tag:7s} {'seacable':14s} {runs[0]['n_segments']:4d} {dt:9.2e} "
                  f"{min(r['wall_time_init'] for r in runs):10.3f} {t_sc:9.3f} {t_sc / t_md:6.2f} "
                  f"{acc['static_fairlead_tension'] / 1e3:8.1f} {acc['static_fairlead_tension_ref'] / 1e3:8.1f} "
                  f"{acc['fairlead_max_error_pct']:9.2f} {acc['anchor_max_error_pct']:8.2f}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "A1")

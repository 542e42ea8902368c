"""MoorDyn side of the mooring speed race: MoorDyn v2's quasi-static chain cases.

The runner, the reference reader and the error measure live in
``tests/validation/_moordyn_peer.py`` (shared with the validation test
``tests/validation/test_moordyn_chain_rms.py``; its docstring describes MoorDyn's test, the
reference files and MoorDyn's numbers) and are re-exported here for ``bench/bench_mooring.py`` and
``bench/bench_snap_deck.py``. Run ``python bench/moordyn_peer.py [A1|A2]`` for MoorDyn's table.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "validation"))
from _moordyn_peer import (  # noqa: F401
    PEER_DIR,
    STATIC_REFERENCE,
    _quiet,
    accuracy,
    heave_motion,
    load_reference,
    run_moordyn,
    run_seacable,
)


def main(amplitude_tag: str = "A1", duration: float = 100.0, repeat: int = 3) -> list[dict]:
    """Print MoorDyn's speed and accuracy on the three depths; return the rows.

    Accuracy comes from one run over the motion file (-10 ... 20 s); the wall times are the
    best of ``repeat`` runs of ``duration`` seconds of :func:`heave_motion` (same motion,
    extended), since the machine is shared.
    """
    rows = []
    print(f"MoorDyn quasi-static chain cases, heave {amplitude_tag}, period 10 s")
    print(f"{'case':7s} {'segs':>4s} {'dtM [s]':>9s} {'init [s]':>8s} {'100 s [s]':>9s} "
          f"{'T0 MD [kN]':>10s} {'T0 Orca':>8s} {'err %':>6s} {'dyn % (ours)':>12s} "
          f"{'dyn % (MD test)':>15s} {'anchor dyn %':>12s} pass")
    for tag in STATIC_REFERENCE:
        ref = load_reference(tag, amplitude_tag)
        case = PEER_DIR / f"{tag}_Chain.txt"
        span = ref["motion"]["time"][-1] - ref["motion"]["time"][0]
        acc_run = run_moordyn(case, ref["motion"], duration=span)
        motion = heave_motion(ref["amplitude"], duration=duration)
        runs = [run_moordyn(case, motion, duration=duration) for _ in range(max(1, repeat))]
        long = min(runs, key=lambda r: r["wall_time"])
        long["wall_time_init"] = min(r["wall_time_init"] for r in runs)
        acc = accuracy(acc_run, ref)
        acc_md = accuracy(acc_run, ref, mirror_moordyn_test=True)
        row = {"case": tag, "n_segments": long["n_segments"], "dt": long["dt"],
               "wall_time_init": long["wall_time_init"], "wall_time": long["wall_time"],
               **acc, "fairlead_max_error_pct_moordyn_test": acc_md["fairlead_max_error_pct"],
               "passes_moordyn_test": acc_md["passes"]}
        rows.append(row)
        print(f"{tag:7s} {row['n_segments']:4d} {row['dt']:9.3e} {row['wall_time_init']:8.3f} "
              f"{row['wall_time']:9.3f} {acc['static_fairlead_tension'] / 1e3:10.1f} "
              f"{acc['static_fairlead_tension_ref'] / 1e3:8.1f} "
              f"{acc['static_fairlead_error_pct']:6.2f} {acc['fairlead_max_error_pct']:12.2f} "
              f"{acc_md['fairlead_max_error_pct']:15.2f} {acc['anchor_max_error_pct']:12.2f} "
              f"{acc['passes'] and acc_md['passes']}")
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(sys.argv[1] if len(sys.argv) > 1 else "A1")

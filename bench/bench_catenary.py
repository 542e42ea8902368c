"""Speed of seacable.statics.catenary (one vectorised call) against MoorPy's per-case catenary.

Run: ``python bench/bench_catenary.py``.  Draws random mooring-line cases over every
regime MoorPy supports (suspended, touchdown with and without friction, slack, near-taut,
mid-water), times our vectorised call on N = 1, 100, 10 000, 100 000 cases and MoorPy's
``catenary`` in a Python loop on a few hundred of the same cases, prints cases per second
and the ratio, and checks that the two agree (fairlead and anchor forces, 1e-5 relative).
"""

from __future__ import annotations

import time
import warnings

import numpy as np

from seacable.statics.catenary import catenary


def random_cases(n: int, seed: int = 0):
    rng = np.random.default_rng(seed)
    L = rng.uniform(50.0, 1500.0, n)
    x = L * rng.uniform(0.05, 1.0, n)
    z = L * rng.uniform(0.05, 1.0, n)
    chord = np.hypot(x, z)
    shrink = np.where(chord > 1.002 * L, 1.002 * L / chord, 1.0)   # at most 0.2 % chord strain
    x, z = x * shrink, z * shrink
    w = rng.uniform(50.0, 3000.0, n)
    EA = w * L * 10 ** rng.uniform(2.0, 5.0, n)
    mu = rng.uniform(0.0, 1.0, n) * (rng.random(n) < 0.5)
    return x, z, L, EA, w, mu


def time_ours(cases, repeat: int) -> float:
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        catenary(*cases)
        best = min(best, time.perf_counter() - t0)
    return best


def main():
    try:
        from moorpy.Catenary import catenary as moorpy_catenary
    except ImportError:  # pragma: no cover - moorpy is a bench-only dependency
        moorpy_catenary = None

    n_mp = 300
    mp_rate, max_dev = np.nan, np.nan
    if moorpy_catenary is not None:
        cases = random_cases(n_mp)
        ours = catenary(*cases)
        out = np.empty((n_mp, 4))
        dips = np.zeros(n_mp, dtype=bool)
        t0 = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            for i in range(n_mp):
                x, z, L, EA, w, mu = (float(c[i]) for c in cases)
                FxA, FzA, FxB, FzB, _ = moorpy_catenary(x, z, L, EA, w, CB=mu, Tol=1e-9 * L, MaxIter=200)
                out[i] = FxA, FzA, -FxB, -FzB
                # MoorPy's "crude check" (ZF/XF > 0.2 and nearly taut) forces a fully suspended
                # profile; with FzA < 0 that line dips below the seabed at the anchor
                dips[i] = (FzA < 0) and _["ProfileType"] == 1
        mp_rate = n_mp / (time.perf_counter() - t0)
        mine = np.column_stack([ours.H_anchor, ours.V_anchor, ours.H_fairlead, ours.V_fairlead])
        scale = np.abs(out[:, 2:]).max(axis=1, keepdims=True)
        dev = np.max(np.abs(mine - out) / scale, axis=1)
        max_dev = float(np.max(dev[~dips]))
        print(f"{dips.sum()} of {n_mp} MoorPy answers dip below the seabed (FzA < 0); their largest "
              f"deviation from ours is {dev[dips].max() if dips.any() else 0:.2e}; excluded below")

    print(f"MoorPy catenary, Python loop over {n_mp} cases: {mp_rate:,.0f} cases/s; "
          f"max |ours - MoorPy| / max(|HF|, |VF|) = {max_dev:.2e} "
          f"({'agree' if max_dev < 1e-5 else 'DISAGREE'} at 1e-5)")
    print(f"{'N':>8} {'time [s]':>10} {'cases/s':>14} {'x MoorPy':>10}")
    for n in (1, 100, 10_000, 100_000):
        cases = random_cases(n, seed=1)
        t = time_ours(cases, repeat=5 if n <= 10_000 else 2)
        rate = n / t
        print(f"{n:>8} {t:>10.4f} {rate:>14,.0f} {rate / mp_rate:>10.1f}")


if __name__ == "__main__":
    main()

"""CPU time numba spends compiling seacable's kernels from an empty cache, by family and by function (issue 38).

A fresh install (and the README's test command from a fresh home folder) compiles every kernel family first:
most of a cold test run. This runs each family's short examples (``_FAMILIES`` of ``tests/conftest.py``, the
same the suite's workers compile first) through :func:`seacable.run` in one process, with the kernel cache in
an empty temporary folder, and listens to numba's ``numba:compile`` events: each compile's CPU time, and its
own time less that of the compiles it started (its callees). It prints the CPU-seconds of each family (later
families reuse what earlier ones compiled, as one process does), the functions with the largest compiles of
their own, and what numba spent compiling the error message of slice assignments from arrays
(``ol_raise_with_shape_context_cpu``: str, repr and join of shape tuples, once per function and shapes), with
the kernels that asked for it.

Measured (2-core machine, quiet, 2026-11-29): families 108 (mooring + system dynamics),
43 (towline), 38 (towed box), 20 (towed FE), 29 (system statics), 29 (laying) CPU-s, about 266 in all; largest
own compiles ``towline.kernel.run_steps`` 20.2, ``towline.kernel.evaluate`` 14.6,
``system.dynamics.kernel.iterate`` 11.4, ``mooring._loads.loads_water`` 10.6, ``coupled_steps`` 10.5,
``towed.linalg.block_thomas_small`` 8.8 CPU-s (12.1 with its general copy); slice-assignment messages 13.5
CPU-s (``mooring.kernel.static_solve``, ``newmark_work``, ``towline.kernel.frame_from_axis`` and ``run_steps``,
``system.statics.kernel.assemble``, numba's own ``np.linalg.solve``), 4.9 after those copies became loops
(``seacable._jit.copy_1d``, ``copy_2d``; left: ``system.dynamics.kernel.iterate`` and ``coupled_static``).
After those became copy loops too (and the towed box scheme's rows), the same 5.4-5.6 CPU-s moved to the next
functions with one (``system.dynamics.frames.track_frame``, ``towed.fe_kernel.record``): numba compiles the
message once per pair of shapes, for whichever function asks first, so it goes only when the last one does
(2026-11-29 23:55, loaded machine: families 134, 48, 40, 24, 29, 36 CPU-s). With those loops too: 2.9 CPU-s,
asked by ``towed.scheme._body_force`` and numba's own ``np.linalg.solve`` (2026-11-30 00:44); after
``_body_force``'s in-place row update (``df[d, :] -= ...``) became a loop, ``towed.fe_kernel._copy_element`` asked
first (4.1 CPU-s: a viscoelastic row copied); with that a loop too, numba's own ``np.linalg.solve`` alone (0.3
CPU-s; every family from an empty cache, 2026-11-30 03:20).

Tried and not kept (2026-11-30, loaded machine, one example a family from an empty cache, CPU-s): numba's own
compile dominates, not LLVM's (``NUMBA_OPT=0``: 115 instead of 136 CPU-s for the mooring family, 48 and 48 for
the towline), and its cost is per function as much as per line: ``mooring._loads.loads_water`` split into three
kernels (water, elements, nodes) compiled in 21.3 CPU-s instead of 15.9. The towline without numba's IR
inlining (``inline="always"``, which types each helper once per caller) compiles in 21-24 CPU-s instead of 47,
but its steps are 5 % slower and its results move by round-off (1e-10 relative after 1000 steps; its fastmath
lets LLVM reorder across the call), against the issue's same-bits rule: kept inlined.

Run: ``python bench/bench_compile.py [TOP]`` (about 5 minutes of one core).
"""

from __future__ import annotations

import collections
import os
import sys
import tempfile
import time
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main(top: int = 25) -> None:
    with tempfile.TemporaryDirectory(prefix="seacable-bench-compile-") as cache:
        # before numba and seacable's cache locator are imported: every kernel compiles into the empty folder
        os.environ["NUMBA_CACHE_DIR"] = os.environ["XDG_CACHE_HOME"] = cache
        from numba.core import event

        records, stack = [], []

        class _Listener(event.Listener):
            def on_start(self, ev):
                fn = getattr(ev.data.get("dispatcher"), "py_func", None)
                stack.append((time.process_time(), f"{fn.__module__}.{fn.__qualname__}" if fn else "?"))

            def on_end(self, ev):
                start, name = stack.pop()
                records.append((name, stack[-1][1] if stack else None, time.process_time() - start))

        event.register("numba:compile", _Listener())
        sys.path.insert(0, str(ROOT / "tests"))
        from conftest import _FAMILIES, _run_example

        print(f"{'family (its first example)':36s} {'compile + run CPU [s]':>22s}")
        for family, _ in _FAMILIES:
            start = time.process_time()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                for name, analysis in family:
                    _run_example(name, analysis)
            print(f"{family[0][0]:36s} {time.process_time() - start:22.1f}")

    total, children = collections.Counter(), collections.Counter()
    for name, parent, seconds in records:
        total[name] += seconds
        if parent is not None:
            children[parent] += seconds
    print(f"\n{'own [s]':>8s} {'with callees [s]':>17s}  function (largest compiles of their own)")
    for name in sorted(total, key=lambda n: children[n] - total[n])[:top]:
        print(f"{total[name] - children[name]:8.2f} {total[name]:17.2f}  {name}")
    shape = [(seconds, parent) for name, parent, seconds in records if "raise_with_shape_context" in name]
    print(f"\nslice assignments from arrays, their error message compiled: {sum(s for s, _ in shape):.1f} CPU-s")
    for seconds, parent in shape:
        print(f"{seconds:8.2f}  asked by {parent}")


if __name__ == "__main__":
    main(*(int(a) for a in sys.argv[1:2]))

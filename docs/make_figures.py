"""Make the example figures the documentation shows (``docs/_static/examples/NAME_*.png``).

The site does not run cases when it is built (the build must stay fast and offline); these figures are made by
running the short examples below with ``seacable run`` and are kept in the repository. Run this again after a
change to the plots or to these examples::

    python docs/make_figures.py            # about 10 s a case

Each example's figures are the ones ``seacable run`` writes beside its result.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "docs" / "_static" / "examples"

#: short examples (statics, theory tables, a pushover, a relaxation): each runs in seconds
EXAMPLES = ("paper000_steady_statics", "paper001_table1", "paper002_vertical_cable", "oc3_hywind_static",
            "oc3_hywind_pushover", "paper004_lena_pushover", "spread_mooring", "lazy_wave_80m", "lay_plan_route")


def main() -> int:
    OUT.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        for name in EXAMPLES:
            result = Path(tmp) / f"{name}.nc"
            subprocess.run([sys.executable, "-m", "seacable", "run", str(ROOT / "examples" / f"{name}.yaml"),
                            "-o", str(result), "-q"], check=True)
            for old in OUT.glob(f"{name}_*.png"):
                old.unlink()
            for png in sorted(Path(tmp).glob(f"{name}_*.png")):
                shutil.copy(png, OUT / png.name)
                print(f"wrote {OUT / png.name}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

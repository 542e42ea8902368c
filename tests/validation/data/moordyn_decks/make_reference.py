"""Write ``reference.json``: MoorDyn's own initial static state of every vendored deck.

Run from the repository root (needs the ``moordyn`` Python bindings, 2.7.2 when this was written)::

    PYTHONPATH=src python tests/validation/data/moordyn_decks/make_reference.py [deck ...]

For each deck MoorDyn-C is created from the file and ``moordyn.Init`` computes its initial
condition by MoorDyn's own relaxation (its options ``TmaxIC``, ``threshIC``, ... as written in the
deck), with every coupled body, rod and point held where the deck puts it. Recorded per line: the
force each end node passes to what it is attached to (``GetLineNodeForce`` at node 0 and node N,
MoorDyn's end-node net force, weight of the half segment included: the force a catenary end
carries); per body and rod: its position; per point: its position. A deck MoorDyn refuses or
that does not finish in ``TIMEOUT`` seconds is recorded with the reason. Each deck runs in its own
process (MoorDyn prints to the console and a failed Init can abort).
"""

from __future__ import annotations

import json
import math
import os
import re
import shutil
import subprocess
import tempfile
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
TIMEOUT = 240.0

# Decks whose points are on FAST.Farm turbines (``TurbineN``): where FAST.Farm puts each turbine's platform
# reference point, (x, y, z [m], roll, pitch, yaw [rad]). SharedMooring2 (OpenFAST r-test
# glue-codes/fast-farm/MD_Shared, commit 71a5adcc): FAST.Farm.fstf places turbine 1 at WT_X, WT_Y, WT_Z = (0, 0, 0)
# and turbine 2 at (1600, 0, 0); the ElastoDyn inputs of the two turbines (IEA-15-240-RWT-UMaineSemi_ElastoDynT1/T2.dat)
# start their platforms displaced by PtfmSurge, PtfmSway, PtfmHeave [m] and PtfmRoll, PtfmPitch, PtfmYaw [deg]:
# T1 (20.3, -0.18, -0.70; -0.26, -2.40, 180), T2 (20.9, 0.13, -0.34; 0.28, 2.4, 0.41) (FAST.Farm.T2.out at t = 0 reads
# the same). MoorDyn and MoorPy run a copy of the deck with those points made Fixed where the turbines put them.
TURBINES = {
    "r-test/glue-codes/fast-farm/MD_Shared/SharedMooring2.dat": {
        1: (20.3, -0.18, -0.70, math.radians(-0.26), math.radians(-2.40), math.radians(180.0)),
        2: (1620.9, 0.13, -0.34, math.radians(0.28), math.radians(2.4), math.radians(0.41)),
    },
}

# the child imports MoorDyn only: the coupled DOFs come from the parent (_coupled_dofs) as JSON, whose floats
# read back bit for bit, so that a child costs MoorDyn's run and not seacable's import too
_CHILD = r"""
import json, sys, math
import moordyn
path = sys.argv[1]
x = json.loads(sys.argv[2])
s = moordyn.Create(path)
n = moordyn.NCoupledDOF(s)
if n != len(x):
    raise SystemExit(f"coupled DOFs: MoorDyn {n}, deck {len(x)}")
moordyn.Init(s, x, [0.0] * len(x))
out = {"lines": {}, "bodies": {}, "rods": {}, "points": {}}
for i in range(1, moordyn.GetNumberLines(s) + 1):
    L = moordyn.GetLine(s, i)
    nn = moordyn.GetLineN(L)
    out["lines"][str(i)] = {"end_a_force": list(moordyn.GetLineNodeForce(L, 0)),
                            "end_b_force": list(moordyn.GetLineNodeForce(L, nn)),
                            "fair_ten": moordyn.GetLineFairTen(L)}
for i in range(1, moordyn.GetNumberBodies(s) + 1):
    r, _ = moordyn.GetBodyState(moordyn.GetBody(s, i))
    out["bodies"][str(i)] = list(r)
for i in range(1, moordyn.GetNumberRods(s) + 1):
    R = moordyn.GetRod(s, i)
    k = moordyn.GetRodN(R)
    out["rods"][str(i)] = [list(moordyn.GetRodNodePos(R, 0)), list(moordyn.GetRodNodePos(R, k))]
for i in range(1, moordyn.GetNumberPoints(s) + 1):
    out["points"][str(i)] = list(moordyn.GetPointPos(moordyn.GetPoint(s, i)))
moordyn.Close(s)
print("JSON" + json.dumps(out))
"""

_MOORPY = r"""
import json, sys, warnings
warnings.simplefilter("ignore")
import moorpy as mp
from seacable.io.moordyn import read_moordyn
md = read_moordyn(sys.argv[1])
ms = mp.System(file=sys.argv[1], depth=md.water_depth or 0.0, rho=md.water_density, g=md.gravity)
ms.initialize()
ok = ms.solveEquilibrium(tol=1e-6, maxIter=2000)
out = {"converged": bool(ok) if ok is not None else True,
       "lines": {str(k + 1): {"end_a_tension": float(ln.TA), "end_b_tension": float(ln.TB)}
                 for k, ln in enumerate(ms.lineList)},
       "bodies": {str(k + 1): [float(v) for v in b.r6] for k, b in enumerate(ms.bodyList)}}
print("JSON" + json.dumps(out))
"""


def decks():
    from seacable.io.moordyn import is_moordyn_file

    return sorted(p for p in HERE.rglob("*") if p.suffix in (".txt", ".dat") and is_moordyn_file(p))


def _coupled_dofs(deck: Path) -> list[float]:
    """The deck's coupled degrees of freedom where the deck puts them, in MoorDyn's order (coupled bodies' 6, coupled
    rods' ends (a pinned rod's second end 0, 0, 0), vessel points' 3): what ``moordyn.Init`` takes."""
    import warnings

    from seacable.io.moordyn import read_moordyn

    with warnings.catch_warnings():  # the child read the deck with -W ignore
        warnings.simplefilter("ignore")
        md = read_moordyn(deck)
    x = []
    for b in md.bodies:
        if b.attachment == "coupled":
            x += list(b.position[:3]) + list(b.position[3:])
    for r in md.rods:
        if r.attachment == "coupled":
            x += list(r.end_a) + ([0.0, 0.0, 0.0] if r.pinned else list(r.end_b))
    for p in md.points:
        if p.attachment == "vessel":
            x += list(p.position)
    return [float(v) for v in x]


def _child(code: str, deck: Path, env: dict, *args: str) -> tuple[dict | None, str, float]:
    t0 = time.time()
    try:
        proc = subprocess.run([sys.executable, "-W", "ignore", "-c", code, str(deck), *args], capture_output=True,
                              text=True, timeout=TIMEOUT, cwd=deck.parent, env=env)
    except subprocess.TimeoutExpired:
        return None, f"did not finish in {TIMEOUT:g} s", TIMEOUT
    seconds = round(time.time() - t0, 2)
    for line in proc.stdout.splitlines():
        if line.startswith("JSON"):
            return json.loads(line[4:]), proc.stdout, seconds
    tail = (proc.stderr or proc.stdout).strip().splitlines()[-3:]
    return None, " | ".join(tail)[-400:] or f"exit code {proc.returncode}", seconds


def run(deck: Path, moorpy: bool = True) -> dict:
    """MoorDyn's state (``error`` if it fails; ``ic_residual``: the last 'Remaining error' MoorDyn prints, in
    m/s^2, and ``ic_converged``: below 1 % of g and a line carrying tension; for a deck relaxed dynamically
    (``ICgenDynamic 1``) ``ic_tension_change``, MoorDyn's measure then: the largest relative change of a
    fairlead tension over its last convergence checks) and, unless ``moorpy`` is false
    (the tests that check MoorDyn's numbers alone), MoorPy's (``moorpy``).

    MoorDyn writes its .out and .log files beside the deck, so both codes read a copy of the deck's folder
    in a temporary folder: the vendored data stays as it is."""
    rel = deck.relative_to(HERE).as_posix() if deck.is_relative_to(HERE) else None  # other tests' decks too
    # a deck (or a table beside it) naming a file one folder up (the SYROPE decks' '../owc.dat') is copied with
    # that folder
    up = any("../" in f.read_text(errors="replace") for f in deck.parent.iterdir()
             if f.is_file() and f.suffix in (".txt", ".dat"))
    root = deck.parent.parent if up else deck.parent
    with tempfile.TemporaryDirectory(prefix="seacable-deck-") as tmp:
        copy = Path(tmp) / root.name
        shutil.copytree(root, copy, ignore=shutil.ignore_patterns("*.out", "*.log"))
        target = copy / deck.relative_to(root)
        if rel in TURBINES:
            _place_turbines(target, TURBINES[rel])
        out = _run(target, moorpy)
    if rel in TURBINES:
        out["turbine_positions"] = {str(n): list(pose) for n, pose in TURBINES[rel].items()}
    return out


def _place_turbines(path: Path, poses: dict) -> None:
    """Rewrite the deck at ``path``: each point on a turbine becomes a Fixed point where the turbine's pose
    puts it (global = position + R(roll, pitch, yaw) r, R = Rz Ry Rx)."""
    def rotation(roll, pitch, yaw):
        cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw),
                                  math.sin(yaw))
        return ((cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr),
                (sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr),
                (-sp, cp * sr, cp * cr))

    lines = path.read_text().splitlines()
    for i, line in enumerate(lines):
        tokens = line.split()
        m = re.fullmatch(r"turbine(\d+)", tokens[1], re.IGNORECASE) if len(tokens) >= 5 else None
        if m is None:
            continue
        pose = poses[int(m.group(1))]
        R = rotation(*pose[3:])
        r = [float(v) for v in tokens[2:5]]
        g = [pose[k] + sum(R[k][j] * r[j] for j in range(3)) for k in range(3)]
        lines[i] = " ".join([tokens[0], "Fixed"] + [f"{v:.9g}" for v in g] + tokens[5:])
    path.write_text("\n".join(lines) + "\n")


def _run(deck: Path, moorpy: bool = True) -> dict:
    src = str(HERE.parents[3] / "src")  # this checkout's seacable, whatever the working folder
    env = {**os.environ, "PYTHONPATH": src + os.pathsep + os.environ.get("PYTHONPATH", "")}
    try:
        x = _coupled_dofs(deck)
    except Exception as err:  # recorded as the child recorded a deck it could not read
        result, text, seconds = None, f"{type(err).__name__}: {err}", 0.0
    else:
        result, text, seconds = _child(_CHILD, deck, env, json.dumps(x))
    if result is None:
        out = {"error": "MoorDyn: " + text, "seconds": seconds}
    else:
        import re

        found = re.findall(r"Remaining error after [\d.eE+-]+ s = ([\d.eE+-]+) m/s2", text)
        residual = float(found[-1]) if found else None
        loaded = any(any(v != 0 for v in ln["end_b_force"]) for ln in result["lines"].values())
        out = {**result, "seconds": seconds, "ic_residual": residual,
               "ic_converged": bool(loaded and (residual is None or residual < 0.098))}
        # the dynamic relaxation (ICgenDynamic 1) prints its own measure instead: the largest relative
        # change of a fairlead tension over its last convergence checks (dtIC apart), in per cent
        changed = re.findall(r"Remaining error after [\d.eE+-]+ s = ([\d.eE+-]+)% on line", text)
        if changed:
            out["ic_tension_change"] = float(changed[-1]) / 100
    if moorpy:
        mp_result, mp_text, _ = _child(_MOORPY, deck, env)
        out["moorpy"] = mp_result if mp_result is not None else {"error": "MoorPy: " + mp_text}
    return out


def main(argv):
    import moordyn

    target = HERE / "reference.json"
    data = json.loads(target.read_text()) if target.is_file() else {"decks": {}}
    data["moordyn_version"] = getattr(moordyn, "__version__", None) or _version()
    data["moorpy_version"] = _version("moorpy")
    chosen = [Path(a).resolve() for a in argv] or decks()
    for deck in chosen:
        rel = deck.relative_to(HERE).as_posix()
        result = run(deck)
        data["decks"][rel] = result
        print(f"{rel}: {'error: ' + result['error'] if 'error' in result else 'ok'} ({result.get('seconds')} s), "
              f"converged {result.get('ic_converged')} residual {result.get('ic_residual')}, "
              f"MoorPy {'error' if 'error' in result['moorpy'] else 'ok'}", flush=True)
    target.write_text(json.dumps(data, indent=1, sort_keys=True) + "\n")


def _version(name="moordyn"):
    from importlib.metadata import version

    return version(name)


if __name__ == "__main__":
    main(sys.argv[1:])

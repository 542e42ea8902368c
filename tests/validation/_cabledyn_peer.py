"""CableDyn 0.3.0 on seacable's lazy-wave case: a deck written from the case, its driver run, its static read.

Shared by ``tests/validation/test_cabledyn_lazy_wave.py`` and ``bench/bench_lazy_wave.py`` (which puts this
folder on ``sys.path``). CableDyn (Apache-2.0, github.com/SMI-Lab-Inha/CableDyn; ``pip install cabledyn``, whose
Linux wheel carries the Fortran driver ``cabledyn/bin/cabledyn``) reads a MoorDyn-v2-style deck with a SECTIONS
table (one line of several line types, each with its element count); :func:`write_deck` writes
``examples/lazy_wave_80m.yaml`` as such a deck, the buoyant stretch as the smeared equivalent line type seacable
makes of its modules (:func:`seacable.line.resolve_sections`), hang-off first (CableDyn's End A), so it is the
example deck ``lozon_gomex80_power_cable.dat`` of CableDyn's repository with the same numbers.
"""

from __future__ import annotations

import subprocess
import time
from pathlib import Path

import numpy as np

import seacable as sc

CASE = Path(__file__).parents[2] / "examples" / "lazy_wave_80m.yaml"

_DECK = """--------------------- CableDyn Input File ------------------------------------
{title}
--------------------- LINE TYPES ---------------------------------------------
TypeName  Diam   MassDenInAir  EA       BA   EI       Cd_n  Cd_t  Ca_n  Ca_t
(-)       (m)    (kg/m)        (N)      (-)  (N-m2)   (-)   (-)   (-)   (-)
{types}
--------------------- POINTS ------------------------------------------------
ID  Type     X       Y    Z
(-) (-)      (m)     (m)  (m)
1   Coupled  {fx:.6g}  0.0  {fz:.6g}
2   Fixed    {ax:.6g}  0.0  {az:.6g}
--------------------- LINES -------------------------------------------------
ID  NodeA  NodeB  Outputs
(-) (-)    (-)    (-)
1   1      2      -
--------------------- SECTIONS ----------------------------------------------
LineID  LineType  Length   NumSegs
(-)     (-)       (m)      (-)
{sections}
--------------------- OPTIONS -----------------------------------------------
{gravity:.6g}  g
{rho:.6g}   rhoW
{depth:.6g}     WtrDpth
{kbot:.6g}    kBot
{cbot:.6g}    cBot
0.05     dtM
0.0      TMax
True     tensile_safety
--------------------- OUTPUTS -----------------------------------------------
"FairTen1"
"AnchTen1"
--------------------- need this line ----------------------------------------
"""


def driver() -> Path | None:
    """The CableDyn driver of the installed wheel, or None without one."""
    try:
        import cabledyn
    except ImportError:
        return None
    path = Path(cabledyn.__file__).parent / "bin" / "cabledyn"
    return path if path.exists() else None


def write_deck(case, path, element_length: float = 0.166, num_segs=None) -> None:
    """``case`` (a single line, its sections resolved) as a CableDyn deck at ``path``, hang-off (seacable's end B)
    first: elements of about ``element_length`` [m] in every section, or ``num_segs`` per section (hang-off
    first)."""
    env, a = case.environment, case.analysis
    line = sc.line.resolve_sections(case.line, env.water_density, env.gravity)
    if line.attachments:
        raise ValueError("write_deck writes smeared sections only (CableDyn's ATTACHMENTS are not written)")
    names, types, rows = {}, [], []
    for k, seg in enumerate(reversed(line.segments)):
        t = seg.line_type
        key = (t.diameter, t.mass_per_length, t.drag_normal, t.drag_tangential, t.added_mass_normal)
        if key not in names:
            names[key] = f"type{len(names) + 1}"
            types.append(f"{names[key]}  {t.diameter:.10g}  {t.mass_per_length:.10g}  {t.axial_stiffness:.10g}  0.0  "
                         f"{t.bending_stiffness:.10g}  {t.drag_normal:.10g}  {t.drag_tangential:.10g}  "
                         f"{t.added_mass_normal:.10g}  {t.added_mass_tangential:.10g}")
        rows.append(f"1  {names[key]}  {seg.length:.10g}  {num_segs[k] if num_segs else max(1, round(seg.length / element_length))}")
    ax, az = case.anchor_position()
    fx, fz = a.fairlead
    Path(path).write_text(_DECK.format(
        title=f"{case.name}: written by seacable's tests/validation/_cabledyn_peer.py", types="\n".join(types),
        sections="\n".join(rows), fx=fx - ax, fz=fz, ax=0.0, az=az, gravity=env.gravity, rho=env.water_density,
        depth=env.depth, kbot=a.seabed_contact.stiffness, cbot=a.seabed_contact.damping))


def run_cabledyn(case, folder, element_length: float = 0.166, num_segs=None) -> dict:
    """Run CableDyn's driver on ``case`` in ``folder``: the hang-off and end tensions [N], the peak nodal
    curvature [1/m], the sag- and hog-bend depths [m] and the driver's wall time [s] (process start to end)."""
    folder = Path(folder)
    deck = folder / "case.dat"
    write_deck(case, deck, element_length, num_segs)
    start = time.perf_counter()
    subprocess.run([str(driver()), str(deck), str(folder / "out")], check=True, capture_output=True, timeout=300)
    wall = time.perf_counter() - start
    table = np.loadtxt(folder / "out.static.out", skiprows=3)
    s, z, tension, kappa = table[:, 2], table[:, 5], table[:, 6], table[:, 7]
    return {"tension": float(tension[0]), "anchor_tension": float(tension[-1]), "curvature": float(kappa.max()),
            "sag_z": float(z[(s > 30.0) & (s < 68.114)].min()),
            "hog_z": float(z[(s > 68.114) & (s < 118.114)].max()), "wall": wall}

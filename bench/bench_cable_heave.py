"""A lazy-wave power cable in 800 m of water: its static shape and 60 s of 3 m heave at 12 s, seacable against
CableDyn 0.3.0 and MoorDyn 2.7.2 (issue 40's speed target: at most 0.5 of CableDyn's wall time and 0.1 of MoorDyn's,
each code at its own 1 % on the peak curvature).

The cable (a stand-in for a deep-water dynamic umbilical, our own numbers): 0.2 m, 70 kg/m (37.8 kg/m in water), EA
700 MN, EI 20 kN m^2, Cd 1.2, Ca 1; 1400 m from an anchor on the seabed to a hang-off 900 m away and 20 m down: 700 m
of bare cable (on the seabed, then rising), 150 m of smeared buoyancy (0.473 m, 120 kg/m: 60 kg/m net up), 550 m of
bare cable up to the hang-off (pinned: MoorDyn's ends are). The hang-off heaves 3 m at 12 s after a 12 s ramp. The
static hang-off tension is 213.08 kN in all three codes (CableDyn 213.082, seacable 213.080, MoorDyn 213.04 kN).

Accuracy on the peak curvature (the largest nodal ``4 sin(theta/2) / (l1 + l2)``, at the end of the buoyant section),
seacable statics (mesh sequencing from 60 elements): elements of 4 / 2 / 1 / 0.5 / 0.25 m give 0.016165 / 0.016469 /
0.016552 / 0.016573 / 0.016586 1/m, so 2 m elements are within 0.7 % of the converged 0.01659 (second order), 1 m
within 0.2 %. In time, 0.1 s and 0.05 s steps give the hang-off's largest tension 251.6 and 251.3 kN (0.1 %).
CableDyn's own 1 % mesh is searched for the same way, on the peak of its own curvature output (cubic Hermite, so
it overshoots on coarse meshes) against seacable's converged 0.016581 1/m: 4 / 3 / 2.5 / 2 / 1 m give +6.9 / +2.2 /
+0.15 / +0.33 / -0.07 %, so its 1 % mesh is 2.5 m (560 elements), and it runs the heave there (its deck's fixed
step 0.05 s) and at 2 m. MoorDyn's hinges are seacable's (the same discrete rod), so its 1 % mesh is seacable's 2 m;
it joins the three sections at free points, which carry no moment, so its curvature peaks elsewhere (0.016327 1/m
at 2 m segments, in the arch), and its static solve at 2 m alone takes minutes: it runs at 2 m.

Measured 2026-11-29 and -30 on the shared 2-core machine at load 0.5-8 (other jobs running; one process each; wall times):

=========================  ==========================  ==================================================
code, mesh                 statics                     60 s of heave
=========================  ==========================  ==================================================
seacable, 2 m elements     0.14-0.47 s                 1.15-1.28 s at 0.1 s steps, spectral radius 0.9
                                                       (5.9 Newton iterations a step); 1.57 s at 0.05 s
                                                       (3.8 a step; once 4.1 s at load 7); 7.1 s
                                                       at 0.1 s and radius 1 (no numerical damping: 16.7
                                                       iterations a step, and halvings)
CableDyn 0.3.0, 2.5 m      0.19 s                      5.7 s at its 0.05 s (largest hang-off 251.6 kN)
CableDyn 0.3.0, 2 m        0.21-0.24 s                 6.7-7.4 s at its 0.05 s (largest hang-off 251.6 kN)
MoorDyn 2.7.2, 2 m         139-242 s (IC to 2.3e-3     about 89 s (2.96 s for 2 s at dtM 2e-4 s)
                           m/s^2 in its 200 s; 20 s
                           leaves 0.5 kN)
=========================  ==========================  ==================================================

Statics plus heave, each code at its own 1 % mesh: seacable 1.3-1.4 s at its own 0.1 s step against CableDyn's
5.9 s at 2.5 m, 0.22-0.24 of it (target 0.5; at CableDyn's 0.05 s step, 1.7 s, 0.29; at CableDyn's 2 m, 6.9-7.7 s), and against MoorDyn's 230-330 s under 0.01 (target 0.1). MoorDyn's static solve needs
its free points started near the answer (from a rough guess it diverged to 2e8 N); they are started at seacable's
static positions. The average-acceleration step (spectral radius 1, the mooring default) rings in the cable's
unresolved axial and bending modes here, and Newton pays for it; at 0.9 (as CableDyn's generalised-alpha damps
them) the response the heave drives keeps its peak (the hang-off's largest tension 251.7 kN at 1, 251.6 kN at 0.9).

Run: ``python bench/bench_cable_heave.py [--moordyn]`` (MoorDyn takes minutes; ``pip install -e ".[bench]"``).
"""

from __future__ import annotations

import math
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import yaml

#: (line type, length [m]) from the anchor to the hang-off
SECTIONS = (("cable", 700.0), ("buoyant", 150.0), ("cable", 550.0))
CABLE = {"diameter": 0.2, "mass_per_length": 70.0, "axial_stiffness": 7e8, "bending_stiffness": 2.0e4,
         "drag_normal": 1.2, "added_mass_normal": 1.0}
BUOYANT = {**CABLE, "diameter": 0.473, "mass_per_length": 120.0}
HANG_OFF = (900.0, -20.0)  # from the anchor [m], and its depth [m]
DEPTH = 800.0


def case(element_length: float, *, heave: bool = False, spectral_radius: float = 0.9, time_step: float = 0.1) -> dict:
    """The seacable case: statics, or 60 s of 3 m heave at 12 s after a 12 s ramp, at ``time_step`` [s]."""
    analysis = {"type": "mooring_static", "fairlead": list(HANG_OFF)}
    if heave:
        analysis = {"type": "mooring_dynamic", "fairlead": list(HANG_OFF), "duration": 60.0, "time_step": time_step,
                    "output_interval": 0.5, "spectral_radius": spectral_radius,
                    "motion": {"type": "harmonic", "amplitude": [0.0, 0.0, 3.0], "period": 12.0, "ramp": 12.0}}
    return {"name": "lazy_wave_800", "line_types": {"cable": CABLE, "buoyant": BUOYANT},
            "line": {"segments": [{"line_type": t, "length": L, "n_elements": max(2, round(L / element_length))}
                                  for t, L in SECTIONS]},
            "environment": {"water_density": 1025.0, "gravity": 9.81, "depth": DEPTH}, "analysis": analysis}


def peak_curvature(x, z) -> float:
    """The largest nodal curvature ``4 sin(theta/2) / (l1 + l2)`` [1/m] of a shape (x, z) [m]."""
    d = np.diff(np.stack([x, z], axis=-1), axis=0)
    length = np.linalg.norm(d, axis=1)
    t = d / length[:, None]
    theta = np.arccos(np.clip(np.sum(t[:-1] * t[1:], axis=1), -1.0, 1.0))
    return float(np.max(4.0 * np.sin(theta / 2.0) / (length[:-1] + length[1:])))


def moordyn_deck(path: Path, segment: float, joints) -> None:
    """The same cable as a MoorDyn v2 deck: three lines joined at two free points started at ``joints`` ((x, z) of
    the two section ends, in MoorDyn's frame with the hang-off at x = 0)."""
    n = [max(2, round(L / segment)) for _, L in SECTIONS]
    rows = [f"{k + 1}    {t}    {k + 1}    {k + 2}    {L}    {n[k]}    -" for k, (t, L) in enumerate(SECTIONS)]
    (j1x, j1z), (j2x, j2z) = joints
    path.write_text(f"""--------------------- MoorDyn Input File ------------------------------------
Lazy wave in 800 m (seacable bench/bench_cable_heave.py)
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam     Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)      (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
cable      0.2      70.0       7.0e8      -0.8        2.0e4      1.2    1.0    0.0     0.0
buoyant    0.473    120.0      7.0e8      -0.8        2.0e4      1.2    1.0    0.0     0.0
---------------------- POINTS --------------------------------
ID    Attachment  X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)         (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed       {-HANG_OFF[0]}    0    {-DEPTH}    0    0    0    0
2     Free        {j1x:.2f}    0    {j1z:.2f}    0    0    0    0
3     Free        {j2x:.2f}    0    {j2z:.2f}    0    0    0    0
4     Coupled     0    0    {HANG_OFF[1]}    0    0    0    0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)  (name)     (#)      (#)      (m)       (-)      (-)
{chr(10).join(rows)}
---------------------- OPTIONS -----------------------------------------
2e-4          dtM           time step (s)
3.0e6         kBot          bottom stiffness (Pa/m)
3.0e5         cBot          bottom damping (Pa-s/m)
{DEPTH}         WtrDpth       water depth (m)
1025.0        WtrDnsty      water density (kg/m^3)
9.81          g             gravity (m/s^2)
5.0           CdScaleIC     IC drag factor
200           TmaxIC        IC max time (s)
1.0           dtIC          IC convergence test interval (s)
1e-3          threshIC      IC threshold
------------------------- need this line --------------------------------------
""")


def run_moordyn(path: Path, duration: float = 60.0, dt: float = 0.01):
    """MoorDyn's static start and ``duration`` s of the heave: (static s, dynamic s, hang-off force [N], peak
    curvature [1/m] of the static shape)."""
    import moordyn

    wall = time.perf_counter()
    system = moordyn.Create(str(path))
    r0 = np.array([0.0, 0.0, HANG_OFF[1]])
    moordyn.Init(system, r0, np.zeros(3))
    static = time.perf_counter() - wall
    shape = []
    for k in (1, 2, 3):
        line = moordyn.GetLine(system, k)
        nodes = np.array([moordyn.GetLineNodePos(line, i) for i in range(moordyn.GetLineN(line) + 1)])
        shape.append(nodes if k == 1 else nodes[1:])
    shape = np.concatenate(shape)
    point = moordyn.GetPoint(system, 4)
    force = float(np.linalg.norm(moordyn.GetPointForce(point)))
    wall, t = time.perf_counter(), 0.0
    for _ in range(round(duration / dt)):
        ramp = 0.5 * (1.0 - math.cos(math.pi * min(t / 12.0, 1.0)))
        z = HANG_OFF[1] + ramp * 3.0 * math.sin(2.0 * math.pi / 12.0 * (t + dt))
        r = np.array(moordyn.GetPointPos(point))
        moordyn.Step(system, r, np.array([0.0, 0.0, (z - r[2]) / dt]), t, dt)
        t += dt
    moordyn.Close(system)
    return static, time.perf_counter() - wall, force, peak_curvature(shape[:, 0], shape[:, 2])


def run_cabledyn(case, folder: Path, element_length: float = 2.0, dt: float = 0.05, heave: bool = True):
    """CableDyn 0.3.0 on the same case (the deck written by ``tests/validation/_cabledyn_peer.py``, its hang-off a
    coupled point driven through its MoorDyn-like Python API with the heave's position, velocity and acceleration at
    each step's end, at its deck's fixed step ``dt``): (static s, dynamic s, static hang-off [N], largest hang-off
    tension of the heave [N], the static shape's peak curvature [1/m] from its own cubic-Hermite output); without
    ``heave`` the statics alone (dynamic s and the largest tension then 0)."""
    sys.path.insert(0, str(Path(__file__).parents[1] / "tests" / "validation"))
    import _cabledyn_peer as peer
    from cabledyn.model import CableDyn

    deck = folder / "lazy_wave_800.dat"
    peer.write_deck(case, deck, element_length=element_length)
    wall = time.perf_counter()
    model = CableDyn()
    model.init_deck(deck)
    static = time.perf_counter() - wall
    q0, _, _ = model.get_coupled_motion()
    top = model.channel("FairTen1")
    kappa = float(np.max(np.abs(model.line(1).curvature())))
    if not heave:
        model.close()
        return static, 0.0, top, 0.0, kappa
    omega, ramp, t, largest = 2.0 * math.pi / 12.0, 12.0, 0.0, 0.0
    wall = time.perf_counter()
    for _ in range(round(60.0 / dt)):
        t += dt
        x = min(t / ramp, 1.0)
        r = 0.5 * (1.0 - math.cos(math.pi * x))
        dr = 0.5 * math.pi / ramp * math.sin(math.pi * x) if t < ramp else 0.0
        ddr = 0.5 * (math.pi / ramp) ** 2 * math.cos(math.pi * x) if t < ramp else 0.0
        sn, cs = math.sin(omega * t), math.cos(omega * t)
        q, v, a = q0.copy(), np.zeros_like(q0), np.zeros_like(q0)
        q[2] += 3.0 * r * sn
        v[2] = 3.0 * (dr * sn + r * omega * cs)
        a[2] = 3.0 * (ddr * sn + 2.0 * dr * omega * cs - r * omega * omega * sn)
        model.step(dt, q, v, a)
        largest = max(largest, model.channel("FairTen1"))
    model.close()
    return static, time.perf_counter() - wall, top, largest, kappa


def main(with_moordyn: bool = False) -> None:
    import seacable as sc

    folder = Path(tempfile.mkdtemp(prefix="bench_cable_heave_"))

    def solve(data):
        path = folder / "case.yaml"
        path.write_text(yaml.safe_dump(data, sort_keys=False))
        loaded = sc.load_case(path)
        wall, cpu = time.perf_counter(), time.process_time()
        ds = sc.run(loaded)
        return ds, time.perf_counter() - wall, time.process_time() - cpu

    solve(case(50.0))  # the kernels compiled (or loaded from the cache) before the timing
    solve(case(50.0, heave=True))
    print(f"{'seacable mesh [m]':>17} {'statics [s]':>12} {'peak curvature [1/m]':>21} {'hang-off [kN]':>14}")
    peaks = {}
    for h in (4.0, 2.0, 1.0, 0.5):
        ds, wall, _ = solve(case(h))
        peaks[h] = peak_curvature(ds['x'].values, ds['z'].values)
        print(f"{h:17.2f} {wall:12.2f} {peaks[h]:21.6f} {float(ds['fairlead_tension']) / 1e3:14.3f}")
    converged = peaks[0.5] + (peaks[0.5] - peaks[1.0]) / 3.0  # Richardson: the nodal curvature is second order
    print(f"converged peak curvature (Richardson, 1 and 0.5 m): {converged:.6f} 1/m; seacable at 2 m "
          f"{100.0 * (peaks[2.0] / converged - 1.0):+.2f} %")
    for dt in (0.1, 0.05):
        ds, wall, cpu = solve(case(2.0, heave=True, time_step=dt))
        print(f"seacable 2 m, 60 s of heave at {dt:g} s, spectral radius 0.9: {wall:.2f} s wall, {cpu:.2f} s CPU, "
              f"hang-off {ds['fairlead_tension'].values.min() / 1e3:.1f}-"
              f"{ds['fairlead_tension'].values.max() / 1e3:.1f} kN")
    try:
        import cabledyn  # noqa: F401
    except ImportError:
        print("CableDyn: not installed (pip install cabledyn)")
    else:
        path = folder / "case.yaml"
        path.write_text(yaml.safe_dump(case(2.0), sort_keys=False))
        own = 2.0
        for h in (4.0, 3.0, 2.5, 2.0):  # CableDyn's own 1 % mesh: the coarsest within 1 % of the converged peak
            static, _, top, _, kappa = run_cabledyn(sc.load_case(path), folder, element_length=h, heave=False)
            error = kappa / converged - 1.0
            print(f"CableDyn {h:g} m: statics {static:.2f} s, peak curvature {kappa:.6f} 1/m ({100.0 * error:+.2f} %)")
            if abs(error) <= 0.01:
                own = max(own, h)
        for h in sorted({own, 2.0}, reverse=True):
            static, dynamic, top, largest, _ = run_cabledyn(sc.load_case(path), folder, element_length=h)
            print(f"CableDyn {h:g} m: statics {static:.2f} s (hang-off {top / 1e3:.3f} kN), 60 s of heave at 0.05 s "
                  f"{dynamic:.2f} s (largest hang-off {largest / 1e3:.1f} kN)")
    if with_moordyn:
        st, _, _ = solve(case(2.0))
        s = st["s"].values
        joints = [(float(np.interp(edge, s, st["x"].values)) - HANG_OFF[0], float(np.interp(edge, s, st["z"].values)))
                  for edge in (700.0, 850.0)]
        deck = folder / "lazy_wave_800.txt"
        moordyn_deck(deck, 2.0, joints)
        static, dynamic, force, kappa = run_moordyn(deck)
        print(f"MoorDyn 2 m: statics {static:.1f} s, 60 s of heave {dynamic:.1f} s, hang-off {force / 1e3:.2f} kN, "
              f"peak curvature {kappa:.6f} 1/m")


if __name__ == "__main__":
    main("--moordyn" in sys.argv[1:])

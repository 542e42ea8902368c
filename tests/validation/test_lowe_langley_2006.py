"""Lowe and Langley (2006): the flexible jumper that MoorDyn's own test suite runs, statics and the top end moved.

Issue 40, validation: "the Low & Langley (2006) hanging riser case that MoorDyn's own test suite runs, static top
and bottom tensions and its dynamic response, side by side with MoorDyn 2.7.2". The case is MoorDyn's
``tests/Mooring/lowe_and_langley_2006`` (github.com/FloatingArrayDesign/MoorDyn, BSD 3-Clause;
``tests/lowe_and_langley_2006.cpp``): 170 m of a 0.396 m jumper (165 kg/m, EA 500 MN, EI 120.8 kN m^2, Cd 1, Ca
1) hung from (-100, 0, -55) m to (0, 0, -5) m in 100 m of fresh water, 68 segments; ``jumper.dat`` beside the
data is its deck with the wave option off (cases 1-3 have no waves: MoorDyn's test never sets any). The paper's
numbers, as MoorDyn's test holds them: top force (11.40, 0, 45.71) kN, bottom (-11.40, 0, 24.04) kN; and its
top-tension records for the top end moved 10 m in x, y and z at 27 s after a quintic ramp of one period,
digitised by MoorDyn's authors (``top_tension.csv``: every 2 s of their 0.1 s samples).

Measured (seacable at dt 0.05 s; 0.02 and 0.01 s change nothing above 0.002 kN), the top tension after the ramp:

======  =========================  =========================  ======================================
case    vs the paper: max / RMS    vs MoorDyn 2.7.2 (its       MoorDyn's own test tolerance
                                   top node's force): max
======  =========================  =========================  ======================================
1 (x)   0.44 / 0.11 kN             0.17 kN                    1 kN at every sample
2 (y)   0.22 / 0.09 kN             0.11 kN
3 (z)   0.41 / 0.16 kN             0.42 kN
======  =========================  =========================  ======================================

In the regular waves of cases 4-6 (5 m amplitude, 10 s, heading 0, 45 and 90 deg; the case written as YAML, the
single line's frame putting the anchor at x = 0, so the waves' phase moves by the 100 m to MoorDyn's origin), the
top tension over the 30 s recorded, 20 s after the waves start at full height: max / RMS error 0.75 / 0.33,
0.66 / 0.32 and 0.33 / 0.17 kN (dt 0.05 and 0.02 s the same to 0.02 kN).

MoorDyn's top-node force (``GetLineNodeForce``) is the force the line puts on the fairlead, as seacable's
``fairlead_tension`` is; its top segment's tension (``GetLineNodeTen``) lacks the top half segment's weight,
inertia and drag and differs from both by up to 1.7 kN in case 3.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from _evidence import check

from seacable.mooring.moordyn import run_moordyn_file
from seacable.mooring.motion import TimeSeriesMotion

DATA = Path(__file__).resolve().parents[1] / "data" / "lowe_langley_2006"
DECK = DATA / "jumper.dat"
PERIOD, AMPLITUDE = 27.0, 10.0  # the top end's motion [s], [m], as MoorDyn's test moves it
RAMP = PERIOD  # one period of MoorDyn's quintic ramp, after which the records start


def _motion(tmp_path: Path, axis: int, duration: float) -> TimeSeriesMotion:
    """The top end's offset along ``axis`` as MoorDyn's test drives it: ``f(t) A sin(2 pi t / T)`` with the
    quintic ramp ``f = s^3 (6 s^2 - 15 s + 10)``, ``s = min(t / T, 1)``, sampled every 0.05 s (the spline of
    :class:`TimeSeriesMotion` between)."""
    t = np.arange(0.0, duration + 1.0, 0.05)
    s = np.clip(t / RAMP, 0.0, 1.0)
    off = np.zeros((t.size, 3))
    off[:, axis] = s ** 3 * (6 * s * s - 15 * s + 10) * AMPLITUDE * np.sin(2 * math.pi / PERIOD * t)
    path = tmp_path / f"motion_{axis}.csv"
    np.savetxt(path, np.column_stack([t, off]), delimiter=",", header="time,x,y,z", comments="")
    return TimeSeriesMotion(file=str(path))


def _top_tension(tmp_path: Path, axis: int, duration: float):
    """seacable's fairlead tension [kN] and its times [s] from the end of the ramp."""
    ds = run_moordyn_file(DECK, duration=duration, motion=_motion(tmp_path, axis, duration), time_step=0.05,
                          output_interval=0.1)
    return ds["time"].values - RAMP, ds["fairlead_tension"].values / 1e3


def test_static_forces_at_both_ends_are_the_papers():
    """Top (11.40, 0, 45.71) kN and bottom (-11.40, 0, 24.04) kN: the force each end puts on the line, the
    opposite of seacable's ``point_force`` (the line's pull on the point). Tolerance 0.02 kN: the paper's
    last digit (0.01 kN) plus the 68-segment lumped line's discretisation (its static catenary forces err by
    about (L/N)^2 / 12 of the curvature's effect, under 0.01 kN here); MoorDyn 2.7.2's own top force on the deck,
    (-11.405, 0, -45.698) kN, is inside it too."""
    ds = run_moordyn_file(DECK)
    pull = np.stack([ds[f"point_force_{c}"].values for c in "xyz"], axis=-1) / 1e3  # (points, 3): bottom, top
    for end, k, published in (("top", 1, [11.40, 0.0, 45.71]), ("bottom", 0, [-11.40, 0.0, 24.04])):
        check(-pull[k], published, atol=0.02, source="Lowe & Langley (2006) jumper (MoorDyn's test case)", unit="kN",
              quantity=f"static {end} force (x, y, z) on the line",
              why="the paper's last digit plus the 68-segment line's discretisation (< 0.01 kN)")


@pytest.mark.parametrize(("case", "axis", "max_error", "rms_error"),
                         [(1, 0, 0.6, 0.2), (2, 1, 0.4, 0.15), (3, 2, 0.6, 0.25)])
def test_top_tension_follows_the_papers_record(tmp_path, case, axis, max_error, rms_error):
    """The top tension after the ramp against the paper's digitised record (40 samples over 78 s, three periods
    of the motion). Bounds: measured 0.44 / 0.22 / 0.41 kN at most and 0.11 / 0.09 / 0.16 kN RMS (1 % and 0.3 % of
    the 45 kN mean), held to about 1.4 times that: the digitised curve steps by 0.03-0.3 kN between its samples
    (the plot's line width) and MoorDyn's own test allows 1 kN at every sample. Measured on our own records: a
    phase error of 1 s fails every case (at most 1.86 / 1.00 / 3.24 kN); a dynamic range 5 % too large fails cases
    1 and 3 (RMS 0.20 kN, at most 0.81 kN) but not case 2, whose range is the smallest (4.8 kN: 0.28 / 0.13 kN)."""
    ref = pd.read_csv(DATA / "top_tension.csv", comment="#")
    t, tension = _top_tension(tmp_path, axis, RAMP + 80.0)
    error = np.interp(ref[f"time_case{case}"], t, tension) - ref[f"case{case}"].to_numpy()
    assert np.max(np.abs(error)) < max_error
    assert math.sqrt(np.mean(error ** 2)) < rms_error


def _jumper_in_waves(case: int) -> dict:
    """The jumper as a YAML case in the regular waves of ``case`` (4, 5, 6) as MoorDyn's test makes them: 5 m
    amplitude, 10 s, heading ``(case - 4) 45`` deg, phase 230, 165 or 0 deg at MoorDyn's origin (the top end, 100 m
    from the anchor along x: seacable's single line has its anchor at x = 0, so the phase there is ``phi - 100 k
    cos(heading)``, k the deep-water wave number MoorDyn's test takes)."""
    heading = (case - 4) * 0.25 * math.pi
    phi = math.radians({4: 230.0, 5: 165.0, 6: 0.0}[case])
    k = (2 * math.pi / 10.0) ** 2 / 9.81
    return {"name": f"lowe_langley_case{case}",
            "line_types": {"main": {"diameter": 0.396, "mass_per_length": 165.0, "axial_stiffness": 500e6,
                                    "bending_stiffness": 120.8e3, "drag_normal": 1.0, "added_mass_normal": 1.0}},
            "line": {"line_type": "main", "length": 170.0},
            "environment": {"water_density": 1000.0, "gravity": 9.807, "depth": 100.0,
                            "waves": {"height": 10.0, "period": 10.0, "heading": heading,
                                      "phase": phi - 100.0 * k * math.cos(heading)}},
            "analysis": {"type": "mooring_dynamic", "anchor": [0.0, -55.0], "fairlead": [100.0, -5.0],
                         "n_elements": 68, "duration": 50.0, "time_step": 0.05, "output_interval": 0.1,
                         "damping_ratio": 0.5}}


@pytest.mark.parametrize(("case", "max_error", "rms_error"), [(4, 1.0, 0.45), (5, 0.9, 0.45), (6, 0.5, 0.25)])
def test_top_tension_in_regular_waves_follows_the_papers_record(tmp_path, case, max_error, rms_error):
    """Cases 4-6, the jumper in regular waves from three headings: the top tension against the paper's digitised
    record (30 samples over 29 s, 20 s after the waves start). Bounds: measured 0.75 / 0.66 / 0.33 kN at most and
    0.33 / 0.32 / 0.17 kN RMS, held to about 1.35 times that (MoorDyn's own test: 1 kN at every sample). Waves from
    the wrong heading, or their phase left at MoorDyn's origin, miss by kilonewtons."""
    import yaml

    import seacable

    path = tmp_path / "jumper.yaml"
    path.write_text(yaml.safe_dump(_jumper_in_waves(case)))
    ds = seacable.run(seacable.load_case(path))
    ref = pd.read_csv(DATA / "top_tension_waves.csv", comment="#")
    t, tension = ds["time"].values - 20.0, ds["fairlead_tension"].values / 1e3
    error = np.interp(ref[f"time_case{case}"], t, tension) - ref[f"case{case}"].to_numpy()
    assert np.max(np.abs(error)) < max_error
    assert math.sqrt(np.mean(error ** 2)) < rms_error


def _moordyn_top_force(axis: int, duration: float, dt: float = 0.005):
    """MoorDyn 2.7.2 on the same deck and motion (its test's drive: the velocity that reaches the next step's
    position), the magnitude of its top node's force [kN] every 0.1 s, times from the end of the ramp."""
    import moordyn

    system = moordyn.Create(str(DECK))
    r0 = np.array([0.0, 0.0, -5.0])
    moordyn.Init(system, r0, np.zeros(3))
    line, point = moordyn.GetLine(system, 1), moordyn.GetPoint(system, 2)
    times, forces = [], []
    t = 0.0
    for k in range(round(duration / dt)):
        s = min(t / RAMP, 1.0)
        x = s ** 3 * (6 * s * s - 15 * s + 10) * AMPLITUDE * math.sin(2 * math.pi / PERIOD * (t + dt))
        r = np.array(moordyn.GetPointPos(point))
        u = np.zeros(3)
        u[axis] = (r0[axis] + x - r[axis]) / dt
        moordyn.Step(system, r, u, t, dt)
        t = (k + 1) * dt
        if (k + 1) % 20 == 0:
            times.append(t - RAMP)
            forces.append(np.linalg.norm(moordyn.GetLineNodeForce(line, 68)) / 1e3)
    moordyn.Close(system)
    return np.array(times), np.array(forces)


def test_heave_case_beside_moordyn(tmp_path):
    """Case 3 (the top end heaved 10 m, the largest tension range, 36-58 kN) beside MoorDyn 2.7.2 over the ramp
    and one period after it: the two codes' top forces within 0.6 kN at every 0.1 s (measured 0.42 kN over 80 s,
    1.9 % of the range: MoorDyn steps at 0.005 s with its k = 0.5 implicit Euler and a quintic drive sampled per
    step, seacable at 0.05 s with Newmark's average acceleration)."""
    pytest.importorskip("moordyn")
    duration = RAMP + PERIOD
    t_md, f_md = _moordyn_top_force(2, duration)
    t, tension = _top_tension(tmp_path, 2, duration)
    keep = t_md >= -RAMP + 1.0  # past MoorDyn's first second (its start from its own initial conditions)
    assert np.max(np.abs(np.interp(t_md[keep], t, tension) - f_md[keep])) < 0.6

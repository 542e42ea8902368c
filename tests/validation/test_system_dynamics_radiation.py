"""The radiation memory of a free body in ``system_dynamic`` (issue 39): the coupled lines-and-bodies time loop
carries Cummins' convolution, and a regular wave then moves the body as the frequency domain says.

The body: the VolturnUS-S hull (tests/data/volturnus: WAMIT's infinite-frequency added mass, hydrostatics and
kernel), the mass of its displacement, the platform's inertias, springs of 80 kN/m in surge and sway and
200 MN m/rad in yaw and a viscous damping of 5-20 % of critical in its 6x6 matrices, on three light taut ropes
(EA 1 MN, their stiffness under 5 % of the springs', their mass 450 kg), driven by the first-order force of a
unit regular wave from 0 deg (an external force series). Its steady surge, heave and pitch are compared with the
frequency domain's ``(C - w^2 (M + A) - i w (B + B_v))^-1 X`` using the A and B of the kernel the run carries
(Ogilvie's relations of it, :mod:`seacable.hydro.radiation`): within 0.5 % and 0.002 rad, for the time step's error
(Newmark's and the convolution's, second order: 0.12 % at 0.1 s and 0.55 % at 0.2 s, measured) and the ropes'.
Without the memory the surge is 14 % off; without the current step's share of it (``dt K(0) / 2``, solved with the
step) the surge's phase is 0.007 rad off (measured; 2e-4 with it): the test sees both.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from seacable.environment import Environment
from seacable.hydro import frequency_response, ogilvie, read_wamit, retardation_kernel
from seacable.line import Line, LineType
from seacable.system.dynamics import build_system_fe, simulate_system, static_system
from seacable.system.model import MooringSystem

ROOT = Path(__file__).parents[1] / "data" / "volturnus" / "IEA-15-240-RWT-UMaineSemi"
RHO, G = 1025.0, 9.80665
VOLUME = 20206.34889
MASS = RHO * VOLUME
INERTIA = (1.2507e10, 1.2507e10, 2.3667e10)
DAMPING = np.diag([6e5, 6e5, 1.4e6, 1.4e9, 1.4e9, 6e8])
ROPE = {"diameter": 0.02, "mass_per_length": 0.5, "axial_stiffness": 1e6, "drag_normal": 0.0, "added_mass_normal": 0.0}
DT, KERNEL, OMEGA = 0.1, 60.0, 0.85


@pytest.fixture(scope="module")
def hull():
    db = read_wamit(ROOT, rho=RHO, g=G)
    stiffness = db.hydrostatics.copy()
    stiffness[0, 0] = stiffness[1, 1] = 8e4
    stiffness[5, 5] = 2e8
    points, lines = {}, {}
    for k in range(3):
        ang = 2 * math.pi * k / 3
        points[f"anchor{k}"] = {"kind": "fixed", "position": (300 * math.cos(ang), 300 * math.sin(ang), -200.0)}
        points[f"fair{k}"] = {"kind": "body", "body": "hull", "position": (40 * math.cos(ang), 40 * math.sin(ang), -14.0)}
        lines[f"rope{k}"] = {"line": Line.single(LineType(**ROPE), 300.0), "end_a": f"anchor{k}", "end_b": f"fair{k}",
                             "n_elements": 10}
    body = {"kind": "free", "mass": MASS, "inertia": INERTIA, "volume": VOLUME,
            "hydrostatic_stiffness": stiffness.tolist(), "added_mass": db.added_mass_inf.tolist(),
            "linear_damping": DAMPING.tolist()}
    system = MooringSystem(points=points, bodies={"hull": body}, lines=lines)
    fe = build_system_fe(system, Environment(depth=200.0, water_density=RHO, gravity=G))
    return db, stiffness, fe, static_system(fe)


def _steady(fe, start, db, memory: bool):
    period = 2 * math.pi / OMEGA
    duration = round(40 * period)
    t = np.arange(0.0, duration + 1.0, DT)
    ramp = np.clip(t / (5 * period), 0.0, 1.0)
    ramp = ramp * ramp * (3 - 2 * ramp)
    x = db.excitation_at(OMEGA, 0.0)
    fe.ext_t, fe.ext_f, fe.ext_n = t[None], (ramp[:, None] * np.real(x * np.exp(-1j * OMEGA * t)[:, None]))[None], \
        np.array([t.size])
    _, kernel = retardation_kernel(db, DT, KERNEL)
    kernel[-1] *= 0.5
    fe.memory_kernel, fe.memory_step = (kernel[None], DT) if memory else (np.zeros((1, 1, 6, 6)), 0.0)
    run = simulate_system(fe, start, float(duration), DT, DT)
    window = run.time > run.time[-1] - 10 * period
    basis = np.column_stack([np.cos(OMEGA * run.time[window]), np.sin(OMEGA * run.time[window]), np.ones(window.sum())])
    coef = np.linalg.lstsq(basis, run.body_position[window, 0, :], rcond=None)[0]
    return coef[0] + 1j * coef[1], x, kernel


def test_a_regular_wave_moves_the_coupled_body_as_the_frequency_domain(hull):
    db, stiffness, fe, start = hull
    h, x, kernel = _steady(fe, start, db, memory=True)
    t = DT * np.arange(kernel.shape[0])
    a, b = (m[0] for m in ogilvie(t, kernel, db.added_mass_inf, OMEGA))
    ref = frequency_response(np.diag([MASS, MASS, MASS, *INERTIA]), a, b + DAMPING, stiffness, x, OMEGA)
    for j in (0, 2, 4):
        assert abs(h[j]) == pytest.approx(abs(ref[j]), rel=0.005), j
        assert abs(np.angle(h[j] / ref[j])) < 0.002, j
    h_none, _, _ = _steady(fe, start, db, memory=False)
    assert abs(abs(h_none[0]) / abs(ref[0]) - 1) > 0.1  # the memory is what gives the surge its response


def test_a_kernel_of_another_step_is_refused(hull):
    db, _, fe, start = hull
    _, kernel = retardation_kernel(db, 0.2, KERNEL)
    fe.memory_kernel, fe.memory_step = kernel[None], 0.2
    from seacable.errors import InputError
    with pytest.raises(InputError, match=r"kernel is sampled every 0.2 s, and the run steps 0.1 s"):
        simulate_system(fe, start, 1.0, DT, DT)

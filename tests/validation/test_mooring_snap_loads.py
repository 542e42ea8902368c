"""Snap loads of a tank-scale chain: the cycle maxima converge with the step, and the ringing of a coarse step.

The case of issue 19 (``examples/snap_load_tank_chain.yaml``): 33 m of chain in a 3 m deep tank, 83
segments, its fairlead moved on a circle of 0.2 m radius every 1.25 s (a platform motion: surge and heave
a quarter period apart, 1.25 s ramp). The chain's properties are a tank-scale studless chain of our own (3.6 mm volume-equivalent diameter,
0.0818 kg/m, EA 4e4 N, C_dn 2.4, C_dt 0.4, C_an 1, C_at 0.5; anchor 31 m from the fairlead, which is
0.7 m below the surface): the line goes slack as the fairlead comes down towards the anchor and snaps
taut as it rises away, about 87 N against 1.6 N at rest.

The snap travels along the line as an axial wave (c = sqrt(EA / m) = 700 m/s, element 0.4 m: the
highest axial frequency 2 c / h = 3500 rad/s), so its peak needs a step that resolves it,
omega dt <~ 1. The full study (steps 2e-3 to 6.25e-5 s, 41, 83 and 166 segments, several spectral radii)
is ``bench/bench_snap_convergence.py``; measured there with 6.25e-5 s: cycle maxima 86.95 and 87.22 N
(rho_inf 1), 86.9 and 87.3 N (0.8); with 166 segments 88.7 and 85.4 N (2.3 % per cycle, 0.6 % in the
mean of the two), with 41 segments 80.2 and 79.5 N (9 % low), with 332 segments (dt 3.1e-5 and 6.25e-5 s)
47.5 and 46.9 N, 47.6 and 46.1 N: these maxima do not converge with the mesh. The example's chain has no
axial damper (damping_ratio 0, taut-only), no bending stiffness, and its maximum comes while most of the
line is slack (78 of 83, 151 of 166 elements at the peak): a 1-2 ms jerk of a slack stretch coming taut,
whose folds have no length scale but the segment's. The mesh convergence of snap maxima is tested where
it holds, on the MoorDyn snap deck with a physical damper (a coefficient, the same on every mesh) and a
bending stiffness (``test_moordyn_snap_deck.py::test_snap_maxima_converge_with_the_mesh_for_a_physical_damper``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import seacable as sc
from seacable.mooring.run import prepare_mooring_dynamic
from seacable.mooring.solver import simulate, static_equilibrium

EXAMPLE = Path(__file__).parents[2] / "examples" / "snap_load_tank_chain.yaml"
PERIOD = 1.25  # [s], the fairlead's circle


def snap_case(time_step, spectral_radius=1.0, cycles=1, n_elements=83):
    """The example case, ``cycles`` periods after the ramp, every step stored."""
    data = sc.load_case(EXAMPLE).model_dump(mode="json", exclude_none=True)
    data["analysis"].update(n_elements=n_elements, duration=PERIOD * (cycles + 1), time_step=time_step,
                            output_interval=time_step, spectral_radius=spectral_radius)
    return sc.Case(**data)


def cycle_maxima(case):
    """The largest fairlead tension of each period after the ramp, and the run. [N]"""
    a = case.analysis
    setup = prepare_mooring_dynamic(case)
    start = static_equilibrium(setup.model, tol=a.tolerance).position
    run = simulate(setup.model, setup.motion, a.duration, a.time_step, a.output_interval, initial=start,
                   tol=min(a.tolerance * 10, 1e-4), spectral_radius=a.spectral_radius)
    fair = setup.model.network.line_nodes[0][-1]
    tension = np.linalg.norm(run.support[:, fair], axis=1)
    cycle = np.floor(run.time / PERIOD - 1e-9).astype(int)
    n = round(a.duration / PERIOD) - 1
    return np.array([tension[cycle == k].max() for k in range(1, n + 1)]), run, tension


@pytest.fixture(scope="module")
def converged():
    """The first cycle's maximum at dt = 6.25e-5 s (omega dt = 0.22 for the highest axial mode)."""
    return cycle_maxima(snap_case(6.25e-5))[0]


def test_snap_load_maxima_converge_with_the_step(converged):
    """Halving the step from 1.25e-4 s (omega dt 0.44) to 6.25e-5 s moves the snap maximum by < 2 %, with
    average acceleration and with rho_inf = 0.8 (whose dissipation per step at omega dt = 0.44, 1 - rho(A),
    is 2.4e-5).

    Measured: 87.01 N at 1.25e-4 s, 86.98 N at 6.25e-5 s (0.04 %); rho_inf = 0.8 at 1.25e-4 s 87.48 N
    (0.6 %). At 2.5e-4 s, 88.67 N (1.9 % above 1.25e-4 s: the peak's time resolved to a coarser step). The
    slack chain's snap is chaotic at the per-cent level: a start moved by 1e-9 m (random, four draws) moves
    these maxima by up to 1 % (86.77-87.08 N at 6.25e-5 s, 86.84-87.14 N at 1.25e-4 s, 87.05-87.43 N at
    2.5e-4 s, 87.13-87.64 N with rho_inf 0.8), and the start shape sampled exactly at the nodes instead of
    interpolated (2 mm apart; their static equilibria 3e-11 m apart) gives 87.54 N at 1.25e-4 s and 89.29 N
    (2.0 %) at 2.5e-4 s. The issue's 2 % bounds the change; the pair compared is the finer one, whose
    difference (under 0.9 % in every draw) the jitter does not take near the bound.
    """
    fine = cycle_maxima(snap_case(1.25e-4))[0]
    assert 80.0 < converged[0] < 95.0  # a snap: 50 times the 1.6 N at rest (not a slack-free swing)
    assert fine == pytest.approx(converged, rel=0.02)
    damped = cycle_maxima(snap_case(1.25e-4, spectral_radius=0.8))[0]
    assert damped == pytest.approx(converged, rel=0.02)


def test_a_coarse_step_rings_with_average_acceleration_and_numerical_damping_tames_it(converged):
    """dt = 2e-3 s (omega dt = 7 for the highest axial mode), six cycles after the ramp: average
    acceleration keeps the unresolved axial modes at amplification 1, and the snaps ring in them: measured
    cycle maxima 478, 243, 230, 234, 381 and 410 N, mean 329 N, 3.8 times the converged 87.0 N (the issue's
    86-112 N against 68 N at its step). The generalised-alpha scheme multiplies those modes by
    rho(A(omega dt)) < 1 each step (0.81 at omega dt = 7 for rho_inf = 0.6; test_mooring_generalized_alpha):
    rho_inf = 0.6 gives a mean maximum of 80 N, and cuts the RMS of the step-to-step (Nyquist) oscillation
    of the tension fourfold (0.25). Neither is the converged peak: a snap load needs omega dt <~ 1
    (2.5e-4 s here) whatever the spectral radius, since numerical damping removes the unresolved modes, it
    does not resolve them.

    The ringing of a coarse step is chaotic: a start moved by 1e-9 m (random, four draws) gives mean
    maxima of 295-391 N with average acceleration and 78-101 N with rho_inf = 0.6, and Nyquist RMS ratios of
    0.25-0.41; over two cycles instead of six the ratio spreads over 0.28-0.52 (the start shape sampled
    exactly at the nodes, whose static equilibrium is 3e-11 m from this one, gives 0.52). Hence means over
    six cycles, with the bounds below: twice the converged maximum (the defect), half the excess and half
    the Nyquist RMS (the cure), each cleared by every draw.
    """
    ringing, _, t_avg = cycle_maxima(snap_case(2e-3, cycles=6))
    damped, _, t_damped = cycle_maxima(snap_case(2e-3, spectral_radius=0.6, cycles=6))

    def nyquist_rms(tension):
        alternating = (tension[2:] - 2 * tension[1:-1] + tension[:-2]) / 4
        return float(np.sqrt(np.mean(alternating[round(PERIOD / 2e-3):] ** 2)))  # after the ramp

    # the defect: maxima more than twice the converged one with average acceleration
    assert ringing.mean() > 2.0 * converged[0]
    # the spurious excess over the converged maximum at least halved, and the ringing too
    assert damped.mean() - converged[0] < 0.5 * (ringing.mean() - converged[0])
    assert nyquist_rms(t_damped) < 0.5 * nyquist_rms(t_avg)

"""Cummins' equation in the time domain (issue 39): a regular wave on the VolturnUS-S gives the frequency domain's
response, at second order in the time step; the radiation memory is what damps and stiffens it.

The body: the VolturnUS-S database (tests/data/volturnus), the mass of its displaced volume (20 206 m^3, HydroDyn's
PtfmVol0) and the platform's inertias (ElastoDyn: 1.2507e10, 1.2507e10, 2.3667e10 kg m^2) at the reference
point, a mooring-like stiffness in surge, sway (80 kN/m) and yaw (200 MN m/rad), and a linear damping of 5-20 %
of critical in every DOF, which the frequency domain carries too: it damps the start-up's free oscillation (a
transient of the lightly damped surge at 128 s would otherwise stay in the fitted window).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from seacable.errors import InputError
from seacable.hydro import frequency_response, ogilvie, read_wamit, retardation_kernel, simulate_cummins

ROOT = Path(__file__).parents[2] / "data" / "volturnus" / "IEA-15-240-RWT-UMaineSemi"
MASS = 1025.0 * 20206.34889
INERTIA = (1.2507e10, 1.2507e10, 2.3667e10)
DAMPING = np.diag([6e5, 6e5, 1.4e6, 1.4e9, 1.4e9, 6e8])
KERNEL = 60.0


@pytest.fixture(scope="module")
def body():
    db = read_wamit(ROOT)
    stiffness = db.hydrostatics.copy()
    stiffness[0, 0] = stiffness[1, 1] = 8e4
    stiffness[5, 5] = 2e8
    return db, np.diag([MASS, MASS, MASS, *INERTIA]), stiffness


def _regular(db, mass, stiffness, omega, dt, periods=40):
    """The steady response to a unit regular wave from 0 deg (ramped over five periods), fitted over the last ten
    periods: H with x = Re(H e^(-i w t))."""
    period = 2 * math.pi / omega
    t = dt * np.arange(round(periods * period / dt) + 1)
    ramp = np.clip(t / (5 * period), 0.0, 1.0)
    ramp = ramp * ramp * (3 - 2 * ramp)
    x = db.excitation_at(omega, 0.0)
    force = ramp[:, None] * np.real(x[None, :] * np.exp(-1j * omega * t)[:, None])
    motion = simulate_cummins(db, mass, force, dt, stiffness=stiffness, linear_damping=DAMPING, kernel_length=KERNEL)
    window = t > t[-1] - 10 * period
    basis = np.column_stack([np.cos(omega * t[window]), np.sin(omega * t[window])])
    coef = np.linalg.lstsq(basis, motion.position[window], rcond=None)[0]
    return coef[0] + 1j * coef[1], x  # Re(H e^(-i w t)) = Re(H) cos(w t) + Im(H) sin(w t)


def _frequency_domain(db, mass, stiffness, omega, x, kernel_pair: bool):
    if kernel_pair:  # the A and B the time domain's kernel carries (its truncated trapezoid, Ogilvie)
        t, k = retardation_kernel(db, 0.1, KERNEL)
        k = k.copy()
        k[-1] *= 0.5
        a, b = (m[0] for m in ogilvie(t, k, db.added_mass_inf, omega))
    else:  # WAMIT's own, linear between its frequencies
        a, b = (np.array([[np.interp(omega, db.omega, c[:, i, j]) for j in range(6)] for i in range(6)])
                for c in (db.added_mass, db.damping))
    return frequency_response(mass, a, b + DAMPING, stiffness, x, omega)


@pytest.mark.parametrize("omega", [0.45, 0.85, 1.25])
def test_a_regular_wave_gives_the_frequency_domain_response(body, omega):
    """Surge, heave and pitch in a regular wave against the frequency domain with the kernel's own A and B:
    within 0.5 % and 0.005 rad at 0.1 s (Newmark's period error, (w dt)^2 / 12, is 1.3e-3 at 1.25 rad/s; measured
    0.05-0.3 %), and against WAMIT's A and B within 1 % (these frequencies are away from the under-sampled
    damping peaks of tests/unit/hydro/test_radiation.py)."""
    db, mass, stiffness = body
    h, x = _regular(db, mass, stiffness, omega, 0.1)
    ref = _frequency_domain(db, mass, stiffness, omega, x, kernel_pair=True)
    wamit = _frequency_domain(db, mass, stiffness, omega, x, kernel_pair=False)
    for j in (0, 2, 4):
        assert abs(h[j]) == pytest.approx(abs(ref[j]), rel=0.005), j
        assert abs(np.angle(h[j] / ref[j])) < 0.005, j
        assert abs(h[j]) == pytest.approx(abs(wamit[j]), rel=0.01), j


def test_the_time_domain_converges_at_second_order(body):
    """Newmark's average acceleration and the memory's trapezoidal rule are both second order: halving the step
    divides the error against the frequency domain by about 4 (measured 3.9 in surge at 1.25 rad/s); > 3."""
    db, mass, stiffness = body
    errors = []
    for dt in (0.1, 0.05):
        h, x = _regular(db, mass, stiffness, 1.25, dt)
        ref = _frequency_domain(db, mass, stiffness, 1.25, x, kernel_pair=True)
        errors.append(abs(h[0] - ref[0]) / abs(ref[0]))
    assert errors[0] / errors[1] > 3.0, errors


def test_the_memory_is_the_radiation_damping(body):
    """Heave free decay without viscous damping: the memory alone damps it, by B33(w_n) / (2 w_n (M + A33(w_n)))
    of critical. The decay of successive peaks gives the damping ratio within 15 % (the memory's damping changes
    with frequency within the decaying motion's band, and a period's peaks are 4 % apart in time)."""
    db, mass, stiffness = body
    dt = 0.05
    t = dt * np.arange(round(300 / dt) + 1)
    force = np.zeros((t.size, 6))
    motion = simulate_cummins(db, mass, force, dt, stiffness=stiffness, kernel_length=KERNEL,
                              position=(0, 0, 1.0, 0, 0, 0))
    z = motion.position[:, 2]
    peaks = np.flatnonzero((z[1:-1] > z[:-2]) & (z[1:-1] > z[2:])) + 1
    peaks = peaks[z[peaks] > 0][1:6]
    period = np.mean(np.diff(t[peaks]))
    w = 2 * math.pi / period
    zeta = np.log(z[peaks[0]] / z[peaks[-1]]) / (2 * math.pi * (len(peaks) - 1))
    a33 = np.interp(w, db.omega, db.added_mass[:, 2, 2])
    b33 = np.interp(w, db.omega, db.damping[:, 2, 2])
    # the natural period from the closed form with the added mass at its own frequency
    assert period == pytest.approx(2 * math.pi * math.sqrt((MASS + a33) / stiffness[2, 2]), rel=0.01)
    assert zeta == pytest.approx(b33 / (2 * w * (MASS + a33)), rel=0.15)


def test_bad_inputs_are_refused(body):
    db, mass, _ = body
    with pytest.raises(InputError, match=r"force must be \(n >= 2 times, 6 DOFs\)"):
        simulate_cummins(db, mass, np.zeros((10, 3)), 0.1)
    with pytest.raises(InputError, match="force holds a NaN"):
        simulate_cummins(db, mass, np.full((10, 6), np.nan), 0.1)
    with pytest.raises(InputError, match=r"mass must be a finite 6x6 matrix"):
        simulate_cummins(db, np.eye(3), np.zeros((10, 6)), 0.1)


def test_the_slow_drift_surge_variance_is_pinksters_through_the_low_frequency_transfer(body):
    """Newman's slow drift of a 3-hour JONSWAP sea (Hs 6 m, Tp 10 s, heading 0) drives the moored body (surge at
    128 s, damped at 20 % of critical): the surge variance of the time domain, averaged over twelve seeds, is the
    frequency domain's (each difference-frequency term of the force through H_LF(mu), :func:`slow_drift_variance`)
    within 12 %. A 3-hour record of a narrow-band response scatters: 14 % rms from seed to seed over twenty seeds
    (measured; mean ratio 0.999), so twelve seeds' mean has a 4 % standard error, and 12 % is three of them. The
    mean offset is the mean drift over the stiffness, within 3 % a seed (2.1 % at most over twenty, measured: the
    mean of a slow, narrow-band record)."""
    from seacable.hydro.loads import mean_drift_force, slow_drift_force
    from seacable.hydro.response import coefficients_at, natural_periods, slow_drift_variance
    from seacable.seastate import jonswap, synthesise

    db, mass, stiffness = body
    periods = natural_periods(db, mass, stiffness)
    assert periods[0] == pytest.approx(128.3, abs=0.1)  # 2 pi sqrt((M + A11(w_n)) / 80 kN/m)
    w_n = 2 * math.pi / periods[0]
    critical = 2 * math.sqrt(stiffness[0, 0] * (MASS + coefficients_at(db, w_n)[0][0, 0, 0]))
    damping = DAMPING.copy()
    damping[0, 0] = damping[1, 1] = 0.2 * critical
    dt = 1.0
    t = np.arange(0.0, 10800.0 + dt / 2, dt)
    ratios = []
    for seed in range(1, 13):
        sea = synthesise(lambda w: jonswap(w, 6.0, 10.0), n_components=200, omega_range=(0.3, 1.45), seed=seed,
                         depth=200.0, hs=6.0)
        offset = np.zeros(6)
        dofs = [0, 2, 4]  # the mean drift moves surge, heave and pitch (heading 0)
        offset[dofs] = np.linalg.solve(stiffness[np.ix_(dofs, dofs)], mean_drift_force(db, sea)[dofs])
        motion = simulate_cummins(db, mass, slow_drift_force(db, sea, t), dt, stiffness=stiffness,
                                  linear_damping=damping, kernel_length=KERNEL, position=offset)
        surge = motion.position[t > 1000.0, 0]  # after the start's free oscillation has decayed
        assert surge.mean() == pytest.approx(offset[0], rel=0.03)
        ratios.append(surge.var() / slow_drift_variance(db, sea, mass, stiffness, damping)[0])
    assert np.mean(ratios) == pytest.approx(1.0, abs=0.12), ratios

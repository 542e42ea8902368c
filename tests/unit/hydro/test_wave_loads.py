"""Wave loads on a body in a sea (issue 39): first order, mean drift and Newman's slow drift."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from seacable.errors import InputError
from seacable.hydro import HydroDatabase, read_wamit
from seacable.hydro.loads import first_order_force, mean_drift_force, slow_drift_force
from seacable.seastate import SeaComponents, jonswap, synthesise

ROOT = Path(__file__).parents[2] / "data" / "volturnus" / "IEA-15-240-RWT-UMaineSemi"


@pytest.fixture(scope="module")
def db():
    return read_wamit(ROOT)


def _sea(amplitude, omega, phase, heading=0.0):
    n = len(amplitude)
    return SeaComponents(amplitude=np.asarray(amplitude, float), omega=np.asarray(omega, float),
                         wave_number=np.asarray(omega, float) ** 2 / 9.80665, heading=np.full(n, heading),
                         phase=np.asarray(phase, float), depth=math.inf, gravity=9.80665)


def test_a_regular_wave_gives_its_excitation_and_its_mean_drift(db):
    """One component a cos(-w t + p): the force Re(X a e^(i p) e^(-i w t)) and the mean drift a^2 D(w)."""
    a, w, p = 2.5, 0.65, 0.7
    sea = _sea([a], [w], [p])
    t = np.linspace(0.0, 30.0, 7)
    x = db.excitation_at(w, 0.0)
    np.testing.assert_allclose(first_order_force(db, sea, t), np.real(np.outer(np.exp(-1j * w * t), x * a * np.exp(1j * p))),
                               rtol=1e-12, atol=1e-9 * np.abs(x).max())
    d = db.drift_at(w, 0.0)
    np.testing.assert_allclose(mean_drift_force(db, sea), a * a * d, rtol=1e-14)
    # the slow drift of a single component is its mean drift, at every time
    np.testing.assert_allclose(slow_drift_force(db, sea, t), np.tile(a * a * d, (t.size, 1)), rtol=1e-12,
                               atol=1e-12 * np.abs(d).max())
    # surge drift pushes the platform the way the waves travel (0 deg: +x)
    assert d[0] > 0


def test_newmans_slow_drift_of_two_components_by_hand():
    """Two components: a1^2 D1 + a2^2 D2 + 2 a1 a2 sqrt(D1 D2) cos((w1 - w2) t - p1 + p2) when D1 and D2 have one
    sign; when they differ, the sign split keeps each component's own mean and no cross term."""
    w = np.array([0.4, 0.9])
    eye = np.eye(6)
    for d1, d2 in ((3.0, 5.0), (3.0, -5.0)):
        drift = np.zeros((1, 2, 6))
        drift[0, :, 0] = (d1, d2)
        db = HydroDatabase(omega=w, added_mass=np.stack([eye, eye]), damping=np.zeros((2, 6, 6)), added_mass_inf=eye,
                           hydrostatics=np.zeros((6, 6)), drift_omega=w, drift_heading=np.zeros(1), drift=drift)
        a, p = np.array([1.5, 0.8]), np.array([0.3, 2.0])
        t = np.linspace(0.0, 40.0, 9)
        f = slow_drift_force(db, _sea(a, w, p), t)[:, 0]
        cross = 2 * a[0] * a[1] * math.sqrt(d1 * d2) * np.cos((w[0] - w[1]) * t - p[0] + p[1]) if d1 * d2 > 0 else 0.0
        np.testing.assert_allclose(f, a[0] ** 2 * d1 + a[1] ** 2 * d2 + cross, rtol=1e-12)


def test_the_slow_drift_of_a_storm_has_the_mean_drift_and_pinksters_variance(db):
    """3-hour JONSWAP seas (Hs 6 m, Tp 10 s, 200 components) on the VolturnUS-S drift table, heading 0. Over a
    record the slow drift's mean is the mean drift (within 1 %: measured 0.4 % at most over five seeds), and its
    variance Pinkster's, 2 sum_{i<j} a_i^2 a_j^2 D_i D_j (each difference-frequency term's own variance). A record's
    variance differs from it by the products of terms whose frequencies differ by less than 1 / T: 4.5 % rms over
    the seeds (-7.7 % to +4.2 % measured), so the mean of five seeds is held to 3 standard errors, 6 %."""
    t = np.arange(0.0, 10800.0, 1.0)  # the slow drift holds difference frequencies below 1.3 rad/s: 1 s resolves them
    ratios = []
    for seed in range(1, 6):
        sea = synthesise(lambda w: jonswap(w, 6.0, 10.0), n_components=200, omega_range=(0.3, 1.6), seed=seed,
                         depth=200.0, hs=6.0)
        f = slow_drift_force(db, sea, t)[:, 0]
        mean = mean_drift_force(db, sea)[0]
        assert f.mean() == pytest.approx(mean, rel=0.01)
        assert mean > 0
        s = sea.amplitude ** 2 * db.drift_at(sea.omega, sea.heading)[:, 0]
        ratios.append(f.var() / (s.sum() ** 2 - (s ** 2).sum()))
    assert np.mean(ratios) == pytest.approx(1.0, abs=0.06), ratios


def test_a_drift_for_one_heading_is_not_used_for_another(db):
    sea = _sea([1.0], [0.6], [0.0], heading=math.radians(30))
    with pytest.raises(InputError, match=r"mean drift for waves towards 0 deg only, and a component of the sea "
                                         r"travels towards 30 deg"):
        mean_drift_force(db, sea)
    with pytest.raises(InputError, match=r"asked for at 2 rad/s, outside its frequencies 0.05-1.45 rad/s"):
        first_order_force(db, _sea([1.0], [2.0], [0.0]), [0.0])

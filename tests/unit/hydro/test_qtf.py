"""The full difference-frequency QTF (issue 39): WAMIT's ``.12d`` read whole, and its slow-drift force in a sea.

The VolturnUS-S extract tests/data/volturnus/qtf (every pair of periods for 0.30-1.00 rad/s, heading 0: README
there). WAMIT's second-order force (WAMIT User Manual v7, the .12d file; its ``e^(i w t)`` amplitudes ``A``) is
``Re sum_i sum_j A_i conj(A_j) F(w_i, w_j) e^(i (w_i - w_j) t)`` over every ordered pair, so that a bichromatic
sea's force at the difference frequency is ``2 a1 a2 |F12| cos((w1 - w2) t - p1 + p2 + phase12)`` in seacable's
phases (elevation ``a cos(w t - p)`` at the origin, ``A = a e^(-i p)``): the closed form below, from the file's own
modulus and phase columns.
"""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from seacable.errors import InputError
from seacable.hydro import HydroDatabase, read_wamit
from seacable.hydro.loads import mean_drift_force, qtf_at, qtf_drift_force, slow_drift_force
from seacable.seastate import SeaComponents, jonswap

DATA = Path(__file__).parents[2] / "data" / "volturnus"
ROOT = DATA / "IEA-15-240-RWT-UMaineSemi"
QTF = DATA / "qtf" / "IEA-15-240-RWT-UMaineSemi.12d"
RHO, G = 1025.0, 9.80665


@pytest.fixture(scope="module")
def db():
    return read_wamit(ROOT, drift=QTF, rho=RHO, g=G)


def _sea(amplitude, omega, phase, heading=0.0):
    n = len(amplitude)
    heading = np.broadcast_to(np.asarray(heading, float), (n,)).copy()
    return SeaComponents(amplitude=np.asarray(amplitude, float), omega=np.asarray(omega, float),
                         wave_number=np.asarray(omega, float) ** 2 / G, heading=heading,
                         phase=np.asarray(phase, float), depth=math.inf, gravity=G)


def _line(per1: float, per2: float, dof: int) -> list[float]:
    """The .12d line (as numbers) of the periods (to WAMIT's five digits) and DOF (1-6)."""
    for text in QTF.read_text().splitlines():
        v = [float(x) for x in text.split()]
        if abs(v[0] - per1) < 5e-4 * per1 and abs(v[1] - per2) < 5e-4 * per2 and int(v[4]) == dof:
            return v
    raise AssertionError(f"no line {per1} {per2} {dof}")


def test_the_qtf_is_read_conjugated_with_its_other_triangle_by_symmetry(db):
    """WAMIT writes PER1 <= PER2; seacable's qtf(w1, w2) is the conjugate of WAMIT's Re + i Im (rho g, ULEN 1),
    and qtf(w2, w1) its conjugate again: the grid is the extract's 15 frequencies at heading 0."""
    assert db.qtf.shape == (1, 15, 15, 6) and db.qtf_heading.tolist() == [0.0]
    np.testing.assert_allclose(db.qtf_omega, 0.30 + 0.05 * np.arange(15), rtol=5e-5)  # WAMIT's 5-digit periods
    w = db.qtf_omega
    i, j = 7, 4  # 0.65 and 0.50 rad/s: w_i > w_j, the file's PER1 < PER2
    for dof in (1, 3, 5):
        v = _line(2 * math.pi / w[i], 2 * math.pi / w[j], dof)
        wamit = (v[7] + 1j * v[8]) * RHO * G
        assert db.qtf[0, i, j, dof - 1] == pytest.approx(np.conj(wamit), rel=1e-14)
        assert db.qtf[0, j, i, dof - 1] == pytest.approx(wamit, rel=1e-14)
    # Hermitian everywhere, the diagonal real
    np.testing.assert_array_equal(db.qtf, np.conj(np.swapaxes(db.qtf, 1, 2)))


def test_the_qtf_diagonal_is_the_mean_drift_used_now(db):
    """The full QTF's diagonal is the mean drift table (the same lines), which is the diagonal-only extract's at
    those frequencies; one component's QTF force, off the grid, is its mean drift a^2 D at every time, and a sea's
    mean is the mean drift force."""
    k = np.arange(db.qtf_omega.size)
    np.testing.assert_array_equal(db.qtf[0, k, k, :].real, db.drift[0])
    diagonal_only = read_wamit(ROOT, rho=RHO, g=G)
    assert diagonal_only.qtf is None
    at = np.searchsorted(np.round(diagonal_only.drift_omega, 4), np.round(db.drift_omega, 4))
    np.testing.assert_array_equal(diagonal_only.drift[0, at], db.drift[0])
    a, w, p = 1.7, 0.6234, 0.4
    t = np.linspace(0.0, 300.0, 11)
    f = qtf_drift_force(db, _sea([a], [w], [p]), t)
    np.testing.assert_allclose(f, np.tile(a * a * db.drift_at(w, 0.0), (t.size, 1)), rtol=1e-12,
                               atol=1e-12 * np.abs(db.drift).max())
    sea = _sea([1.0, 0.6, 1.3], [0.41, 0.52, 0.77], [0.1, 2.0, 4.0])
    # the difference frequencies are multiples of 0.01 rad/s: over 2 pi / 0.01 s the cross terms average to zero
    tt = np.linspace(0.0, 2 * math.pi / 0.01, 400, endpoint=False)
    np.testing.assert_allclose(qtf_drift_force(db, sea, tt).mean(axis=0)[[0, 2, 4]],
                               mean_drift_force(db, sea)[[0, 2, 4]], rtol=1e-10)


def test_a_bichromatic_sea_gives_the_qtf_entry_at_the_difference_frequency(db):
    """Two components on the grid (0.65 and 0.50 rad/s): the force is the two mean drifts plus
    2 a1 a2 |F| cos((w1 - w2) t - p1 + p2 + phase) from the file's modulus and phase (WAMIT's convention, module
    docstring), in surge, heave and pitch, in either order of the components. Exact but for WAMIT's 6 printed
    digits (Re, Im against modulus, phase): 1e-4 of the amplitude."""
    w = db.qtf_omega
    w1, w2, a1, a2, p1, p2 = w[7], w[4], 1.5, 2.2, 0.9, -2.1
    t = np.linspace(0.0, 2 * math.pi / (w1 - w2), 40)
    for order in ((0, 1), (1, 0)):
        amp, om, ph = (np.array(x)[list(order)] for x in ((a1, a2), (w1, w2), (p1, p2)))
        f = qtf_drift_force(db, _sea(amp, om, ph), t)
        for dof in (1, 3, 5):
            v = _line(2 * math.pi / w1, 2 * math.pi / w2, dof)
            mod, phase = v[5] * RHO * G, math.radians(v[6])
            mean = a1 ** 2 * db.drift_at(w1, 0.0)[dof - 1] + a2 ** 2 * db.drift_at(w2, 0.0)[dof - 1]
            closed = mean + 2 * a1 * a2 * mod * np.cos((w1 - w2) * t - p1 + p2 + phase)
            np.testing.assert_allclose(f[:, dof - 1], closed, rtol=0, atol=1e-4 * 2 * a1 * a2 * mod)
            # the difference-frequency component by projection: amplitude and phase of the entry
            c = 2 * np.mean((f[:-1, dof - 1] - mean) * np.exp(-1j * (w1 - w2) * t[:-1]))
            assert abs(c) == pytest.approx(2 * a1 * a2 * mod, rel=1e-4)
            assert np.angle(c * np.exp(-1j * (-p1 + p2 + phase))) == pytest.approx(0.0, abs=1e-4)


def test_the_sum_of_squares_is_the_double_sum(db):
    """Twelve components off the grid, headings 0: the force is Re sum_ij c_i conj(c_j) T_ij e^(-i (w_i - w_j) t)
    with T of :func:`qtf_at`, to round-off."""
    rng = np.random.default_rng(3)
    n = 12
    w = np.sort(rng.uniform(0.31, 0.99, n))
    sea = _sea(rng.uniform(0.2, 1.5, n), w, rng.uniform(0, 2 * math.pi, n))
    t = np.linspace(0.0, 500.0, 101)
    c = sea.amplitude * np.exp(1j * sea.phase)
    u = c[None, :] * np.exp(-1j * np.outer(t, w))
    direct = np.einsum("ti,ijm,tj->tm", u, qtf_at(db, w, 0.0), np.conj(u)).real
    scale = np.abs(direct).max(axis=0)
    np.testing.assert_allclose(qtf_drift_force(db, sea, t), direct, rtol=0, atol=1e-12 * scale.max())
    np.testing.assert_allclose(qtf_drift_force(db, sea, t)[:, [0, 2, 4]], direct[:, [0, 2, 4]], rtol=1e-10)


def test_newmans_approximation_against_the_full_qtf_near_the_diagonal(db):
    """Pinkster's slow-drift force spectrum S_F(mu) = 8 int S(w) S(w + mu) |T(w + mu, w)|^2 dw of a JONSWAP sea
    (Hs 8 m, Tp 12 s, gamma 3.3, cut to the extract's 0.30-1.00 rad/s) with the full QTF and with Newman's (sign-split
    sqrt(D_i D_j)). At mu -> 0 both are the diagonal's; at the VolturnUS-S surge natural frequency (142.0 s, Allen
    et al. 2020, NREL/TP-5000-76773: mu = 0.0442 rad/s) the full QTF's surge spectrum is 1.31 times Newman's (the
    semi-submersible's QTF off the diagonal, larger than sqrt(D_i D_j) below 0.6 rad/s: Newman's approximation is
    not conservative here), and at mu = 0.1 rad/s 1.63 times. Deterministic: the tolerance 0.01 is the quadrature's
    (halving dw moves the ratios by < 0.002)."""
    dw = 0.0025
    x = np.arange(0.30, 0.9975, dw)
    t = qtf_at(db, x, 0.0)
    d = db.drift_at(x, np.zeros(x.size))
    s = jonswap(x, 8.0, 12.0, gamma=3.3)  # the sea the ratios are of (DNV-RP-C205's rule would give 2.39)
    ratios = []
    for mu in (0.0, 2 * math.pi / 142.0, 0.1):
        k = round(mu / dw)
        i = np.arange(x.size - k)
        full = np.sum(s[i] * s[i + k] * np.abs(t[i + k, i, 0]) ** 2)
        dp, dm = np.maximum(d[:, 0], 0), np.maximum(-d[:, 0], 0)
        newman = np.sum(s[i] * s[i + k] * (np.sqrt(dp[i] * dp[i + k]) - np.sqrt(dm[i] * dm[i + k])) ** 2)
        ratios.append(full / newman)
    assert ratios[0] == pytest.approx(1.0, rel=1e-12)
    assert ratios[1] == pytest.approx(1.31, abs=0.01)
    assert ratios[2] == pytest.approx(1.63, abs=0.01)


def test_the_qtf_and_newmans_slow_drift_agree_in_a_narrow_sea(db):
    """Six components within 0.05 rad/s of each other near 0.9 rad/s, where the QTF's first off-diagonal is
    0.91-1.04 times Newman's sqrt(D_i D_j) with a phase of 0.06-0.19 rad: the full QTF's slow drift in surge is
    Newman's within 10 % rms of its oscillation (measured 6.6 %), and the means are the same (the diagonal)."""
    w = np.linspace(0.88, 0.93, 6)
    sea = _sea(np.full(6, 0.5), w, np.linspace(0.0, 5.0, 6))
    t = np.linspace(0.0, 2 * math.pi / 0.01, 600, endpoint=False)
    q = qtf_drift_force(db, sea, t)[:, 0]
    n = slow_drift_force(db, sea, t)[:, 0]
    assert q.mean() == pytest.approx(n.mean(), rel=1e-10)
    assert np.sqrt(np.mean((q - n) ** 2)) < 0.10 * np.std(n)


@pytest.mark.parametrize("sea_changes, message", [
    ({"heading": np.linspace(-0.3, 0.3, 4)}, "long-crested sea"),
    ({"heading": 0.5}, "for waves towards 0 deg only"),
    ({"omega": [0.2, 0.5, 0.6, 0.7]}, r"outside its frequencies 0.3-1 rad/s"),
])
def test_a_sea_the_qtf_does_not_cover_is_refused(db, sea_changes, message):
    base = {"amplitude": [1.0] * 4, "omega": [0.4, 0.5, 0.6, 0.7], "phase": [0.0] * 4, "heading": 0.0}
    base.update(sea_changes)
    with pytest.raises(InputError, match=message):
        qtf_drift_force(db, _sea(**base), np.zeros(3))


def test_a_file_without_pairs_has_no_qtf_and_says_so(db):
    diagonal_only = read_wamit(ROOT)
    with pytest.raises(InputError, match=r"no full difference-frequency QTF .*drift: newman"):
        qtf_drift_force(diagonal_only, _sea([1.0], [0.5], [0.0]), np.zeros(2))


def test_a_gap_in_the_triangle_is_refused(tmp_path):
    for ext in (".1", ".3", ".hst"):
        shutil.copy(f"{ROOT}{ext}", tmp_path / f"b{ext}")
    lines = QTF.read_text().splitlines(keepends=True)
    gone = next(k for k, s in enumerate(lines) if s.split()[0] != s.split()[1] and s.split()[4] == "3")
    (tmp_path / "b.12d").write_text("".join(lines[:gone] + lines[gone + 1:]))
    with pytest.raises(InputError, match=r"QTF off its diagonal but not of DOF 3 at the periods .* \(2 such gaps\)"):
        read_wamit(tmp_path / "b")


def test_a_qtf_that_is_not_hermitian_is_refused(db):
    q = np.array(db.qtf)
    q[0, 3, 5, 0] *= 1.1
    with pytest.raises(InputError, match="must be Hermitian"):
        HydroDatabase(omega=db.omega, added_mass=db.added_mass, damping=db.damping, added_mass_inf=db.added_mass_inf,
                      hydrostatics=db.hydrostatics, qtf_omega=db.qtf_omega, qtf_heading=db.qtf_heading, qtf=q)


def test_the_frequency_domain_slow_drift_variance_takes_the_full_qtf(db):
    """``slow_drift_variance(drift="qtf")``: with a QTF that is Newman's matrix (sign-split sqrt(D_i D_j), on the
    grid's frequencies) it is Newman's variance to round-off; with the VolturnUS-S QTF and a body held by a
    stiffness of 1e16 (x = F / K to 1e-7: mu^2 (M + A) / K < 1e-7) it is the time-domain variance of
    :func:`qtf_drift_force` over K^2, exactly so for a sea whose difference frequencies are distinct multiples of
    0.01 rad/s over 2 pi / 0.01 s (each pair's term its own variance, 2 a_i^2 a_j^2 |T_ij|^2)."""
    from seacable.hydro.response import slow_drift_variance

    mass, stiffness, damping = np.diag([2e7] * 3 + [1e10] * 3), 1e16 * np.eye(6), np.diag([1e5] * 3 + [1e8] * 3)
    d = db.drift[0]
    plus, minus = np.sqrt(np.maximum(d, 0.0)), np.sqrt(np.maximum(-d, 0.0))
    newman_qtf = (plus[:, None, :] * plus[None, :, :] - minus[:, None, :] * minus[None, :, :])[None] + 0j
    shaped = HydroDatabase(omega=db.omega, added_mass=db.added_mass, damping=db.damping,
                           added_mass_inf=db.added_mass_inf, hydrostatics=db.hydrostatics, drift_omega=db.drift_omega,
                           drift_heading=db.drift_heading, drift=db.drift, qtf_omega=db.qtf_omega,
                           qtf_heading=db.qtf_heading, qtf=newman_qtf)
    on_grid = _sea([1.0, 0.7, 1.2, 0.5], db.qtf_omega[[2, 5, 6, 10]], [0.0, 1.0, 2.0, 3.0])
    np.testing.assert_allclose(slow_drift_variance(shaped, on_grid, mass, stiffness, damping, drift="qtf"),
                               slow_drift_variance(shaped, on_grid, mass, stiffness, damping), rtol=1e-12)
    w = np.array([0.40, 0.41, 0.43, 0.47, 0.52, 0.60])  # differences 0.01 to 0.20, all distinct
    sea = _sea([1.0, 1.4, 0.8, 1.1, 0.9, 1.3], w, [0.3, 1.1, 2.9, 4.0, 5.2, 0.7])
    t = np.linspace(0.0, 2 * math.pi / 0.01, 400, endpoint=False)
    force = qtf_drift_force(db, sea, t)
    var = slow_drift_variance(db, sea, mass, stiffness, damping, drift="qtf")
    np.testing.assert_allclose(var[[0, 2, 4]], force.var(axis=0)[[0, 2, 4]] / 1e32, rtol=1e-6)
    with pytest.raises(InputError, match="drift must be 'newman' or 'qtf'"):
        slow_drift_variance(db, sea, mass, stiffness, damping, drift="full")

"""WAMIT's files read into a hydrodynamic database (issue 39): the scaling of every DOF class, the conventions,
the database's own consistency (Haskind) and one clear message per bad file.

The reference data: an extract of the IEA-15 MW VolturnUS-S database (tests/data/volturnus, provenance there).
"""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from seacable.errors import InputError
from seacable.hydro import read_wamit
from seacable.waves import wave_number

DATA = Path(__file__).parents[2] / "data" / "volturnus"
ROOT = DATA / "IEA-15-240-RWT-UMaineSemi"
RHO, G = 1025.0, 9.80665
DEPTH = 200.0  # the VolturnUS-S WAMIT run's water depth (Allen et al. 2020, table 1)


@pytest.fixture(scope="module")
def db():
    return read_wamit(ROOT)


def _line(ext: str, pred) -> list[float]:
    return next([float(v) for v in s.split()] for s in Path(f"{ROOT}{ext}").read_text().splitlines()
                if s.strip() and pred([float(v) for v in s.split()]))


def test_the_values_are_made_dimensional_as_wamit_defines_them(db):
    """One line of each file, by hand: A rho, B rho w, X rho g (conjugated: seacable's e^(-i w t)), C rho g."""
    a_bar = _line(".1", lambda v: v[0] == 0 and v[1] == 1 and v[2] == 1)[3]
    assert db.added_mass_inf[0, 0] == pytest.approx(a_bar * RHO, rel=1e-15)
    per, _, _, a_bar, b_bar = _line(".1", lambda v: v[0] > 0 and v[1] == 3 and v[2] == 3)
    w = 2 * math.pi / per
    f = int(np.argmin(np.abs(db.omega - w)))
    assert db.added_mass[f, 2, 2] == pytest.approx(a_bar * RHO, rel=1e-15)
    assert db.damping[f, 2, 2] == pytest.approx(b_bar * RHO * w, rel=1e-12)
    per, _, _, _, pha, re, im = _line(".3", lambda v: v[1] == 30 and v[2] == 1)
    h = int(np.argmin(np.abs(db.heading - math.radians(30))))
    f = int(np.argmin(np.abs(db.excitation_omega - 2 * math.pi / per)))
    assert db.excitation[h, f, 0] == pytest.approx((re - 1j * im) * RHO * G, rel=1e-12)
    # the seacable convention: a wave a cos(w t) at the origin exerts |X| a cos(w t + phase)
    assert np.angle(db.excitation[h, f, 0]) == pytest.approx(-math.radians(pha), abs=1e-5)
    assert db.hydrostatics[2, 2] == pytest.approx(_line(".hst", lambda v: v[0] == 3 and v[1] == 3)[2] * RHO * G)


def test_every_dof_class_scales_with_its_power_of_ulen(tmp_path, db):
    """WAMIT's length scale: A ~ L^(3, 4, 5), B the same, X ~ L^(2, 3), C ~ L^(2, 3, 4), drift ~ L^(1, 2) for
    (force, coupling, moment). With ULEN = 2 every entry is 2^power times the ULEN = 1 one."""
    big = read_wamit(ROOT, ulen=2.0)
    for name, (ff, fm, mm) in (("added_mass_inf", (3, 4, 5)), ("hydrostatics", (2, 3, 4))):
        ref, got = getattr(db, name), getattr(big, name)
        assert got[2, 2] == pytest.approx(2 ** ff * ref[2, 2], rel=1e-14)
        assert got[2, 4] == pytest.approx(2 ** fm * ref[2, 4], rel=1e-14)
        assert got[4, 4] == pytest.approx(2 ** mm * ref[4, 4], rel=1e-14)
    np.testing.assert_allclose(big.damping[:, 0, 4], 2 ** 4 * db.damping[:, 0, 4], rtol=1e-14)
    np.testing.assert_allclose(big.excitation[..., 0], 2 ** 2 * db.excitation[..., 0], rtol=1e-14)
    np.testing.assert_allclose(big.excitation[..., 4], 2 ** 3 * db.excitation[..., 4], rtol=1e-14)
    np.testing.assert_allclose(big.drift[..., 0], 2 ** 1 * db.drift[..., 0], rtol=1e-14)
    np.testing.assert_allclose(big.drift[..., 4], 2 ** 2 * db.drift[..., 4], rtol=1e-14)


def test_the_grids_limits_and_headings(db):
    assert db.omega.size == 100 and db.omega[0] == pytest.approx(0.05, rel=1e-6) and db.omega[-1] == pytest.approx(5.0, rel=1e-6)
    assert db.added_mass_zero is not None and db.added_mass_zero[0, 0] > db.added_mass_inf[0, 0]
    # -180 and 180 deg are one heading: 36 of them, sorted, 10 deg apart
    assert db.heading.size == 36
    np.testing.assert_allclose(np.diff(db.heading), math.radians(10), rtol=1e-12)
    # the mean drift: the .12d diagonal, heading 0
    assert db.drift.shape == (1, 46, 6) and db.drift_heading[0] == 0.0


def test_the_waterplane_stiffness_is_the_columns_waterplane(db):
    """C33 = rho g A_wp: three 12.5 m offset columns and a 10 m centre column (Allen et al. 2020, table 5),
    446.7 m^2. WAMIT's panels inscribe the circles: 32 panels around a column lose 0.6 % of its area, so 1.5 %."""
    a_wp = 3 * math.pi * 6.25 ** 2 + math.pi * 5.0 ** 2
    assert db.hydrostatics[2, 2] / (RHO * G) == pytest.approx(a_wp, rel=0.015)


def test_haskind_relation_gives_the_damping_from_the_excitation(db):
    """Newman's (1962) relation of the damping to the excitation at all headings, in water of depth h:

        B_jj(w) = k / (8 pi rho g c_g) int_0^2pi |X_j(b)|^2 db,   c_g = (w / 2k)(1 + 2kh / sinh 2kh).

    The two sides come from different integrals of WAMIT's panel solution (the damping from the radiation
    potentials, the excitation from the diffraction ones), so they agree to the discretisation: 2 % of the
    coefficient's peak. The heading integral (the trapezoidal rule over the 36 headings) is exact for |X(b)|^2
    with harmonics below 36 in b; those of a 58 m radius platform reach about 2kR, so the check stops at
    1.45 rad/s (2kR = 25)."""
    w = db.excitation_omega
    k = wave_number(2 * math.pi / w, DEPTH)
    cg = w / k / 2 * (1 + 2 * k * DEPTH / np.sinh(2 * k * DEPTH))
    integral = np.sum(np.abs(db.excitation) ** 2, axis=0) * (2 * math.pi / db.heading.size)
    haskind = k[:, None] / (8 * math.pi * RHO * G * cg[:, None]) * integral
    for j in range(6):
        b = np.interp(w, db.omega, db.damping[:, j, j])
        peak = np.max(np.abs(db.damping[:, j, j]))
        assert np.max(np.abs(haskind[:, j] - b)) < 0.02 * peak, j


def test_excitation_between_headings_and_frequencies(db):
    x = db.excitation
    # the headings run from -170 to 180 deg: WAMIT's -180 and 180 are one
    assert math.degrees(db.heading[0]) == pytest.approx(-170) and math.degrees(db.heading[-1]) == pytest.approx(180)
    # on the grid: the table itself; 180 deg from either side is the same heading
    assert np.array_equal(db.excitation_at(db.excitation_omega[3], math.pi), x[-1, 3])
    assert np.array_equal(db.excitation_at(db.excitation_omega[3], -math.pi), x[-1, 3])
    # head seas (travelling towards -x) push no sway, roll or yaw: the platform is symmetric about y = 0
    assert np.all(np.abs(x[-1, :, [1, 3, 5]]) < 1e-6 * np.abs(x[-1, :, [0, 2, 4]]).max())
    # half way between two headings and two frequencies: the mean of the four corners
    mid = db.excitation_at(0.5 * (db.excitation_omega[2] + db.excitation_omega[3]), 0.5 * (db.heading[4] + db.heading[5]))
    np.testing.assert_allclose(mid, 0.25 * (x[4, 2] + x[4, 3] + x[5, 2] + x[5, 3]), rtol=1e-12)
    # between the last heading (180 deg) and the first (-170): periodic
    wrap = db.excitation_at(db.excitation_omega[1], math.radians(-175))
    np.testing.assert_allclose(wrap, 0.5 * (x[-1, 1] + x[0, 1]), rtol=1e-12)
    with pytest.raises(InputError, match=r"6 rad/s, outside its frequencies 0.05-1.45 rad/s"):
        db.excitation_at(6.0, 0.0)


def _copy(tmp_path: Path, edit: dict[str, str] | None = None, drop=()) -> Path:
    for ext in (".1", ".3", ".hst", ".12d"):
        if ext not in drop:
            shutil.copy(f"{ROOT}{ext}", tmp_path / f"b{ext}")
    for ext, text in (edit or {}).items():
        (tmp_path / f"b{ext}").write_text(text)
    return tmp_path / "b"


def _text(ext: str) -> str:
    return Path(f"{ROOT}{ext}").read_text()


@pytest.mark.parametrize("edit, drop, message", [
    (None, (".1",), r"added mass and damping file '.*b\.1' does not exist"),
    (None, (".hst",), r"hydrostatics file '.*b\.hst' does not exist"),
    ({".1": "".join(s + "\n" for s in _text(".1").splitlines() if not s.split()[0].startswith("0.0"))}, (),
     r"no infinite-frequency added mass \(PER = 0 lines\)"),
    ({".1": _text(".1").replace("  1.256637E+02     1     1", "  1.256637E+02     7     1", 1)}, (),
     r"DOF 7 is not 1-6.*NBODY = 1"),
    ({".3": "\n".join(ln for ln in _text(".3").splitlines() if ln.split()[1:3] != ["0.000000E+00", "2"])}, (),
     r"no excitation of DOF 2 at heading 0 deg and period 125.664 s \(8 such gaps\)"),
    ({".hst": _text(".hst").replace("4.430486E+02", "nan")}, (), r"line 15 holds a NaN or an infinity"),
    ({".hst": _text(".hst").replace("4.430486E+02", "abc")}, (), r"line 15 is not a row of numbers: .*abc"),
    ({".1": "\n".join(ln + (" x" if k == 49 else "") for k, ln in enumerate(_text(".1").splitlines()))}, (),
     r"line 50 is not a row of numbers"),
    ({".3": "\n".join(s[:40] for s in _text(".3").splitlines())}, (), r"has 4 numbers, expected at least 7"),
    ({".12d": ""}, (), r"is empty"),
])
def test_a_bad_file_gets_one_clear_message(tmp_path, edit, drop, message):
    with pytest.raises(InputError, match=message):
        read_wamit(_copy(tmp_path, edit, drop))


def test_a_bad_length_scale_is_refused(tmp_path):
    with pytest.raises(InputError, match=r"ulen must be a length > 0 m \(WAMIT's ULEN\), got -1"):
        read_wamit(ROOT, ulen=-1.0)


@pytest.mark.parametrize("changes, message", [
    ({"excitation_omega": None}, r"the excitation needs its headings and frequencies"),
    ({"drift": np.zeros((1, 3, 6))},
     r"the mean drift must have the shape \(1 headings, 46 frequencies, 6 DOFs\), got \(1, 3, 6\)"),
    ({"drift_heading": None}, r"the mean drift needs its headings and frequencies"),
    ({"heading": np.zeros(36)}, r"each excitation heading must be given once"),
])
def test_a_database_with_tables_that_do_not_match_is_refused(db, changes, message):
    import dataclasses

    with pytest.raises(InputError, match=message):
        dataclasses.replace(db, **changes)

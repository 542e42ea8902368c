"""Vessel motions from RAO tables (issue 20): WAMIT .4 and CSV tables, interpolation, the motion in a sea,
and the refusals of tables that do not cover the sea."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seacable.errors import InputError
from seacable.raos import rao_motion, read_rao_csv, read_wamit4
from seacable.seastate import SeaComponents

PERIODS = (8.0, 10.0, 12.5)
HEADINGS = (0.0, 90.0, 180.0, 270.0)


def _mod_phase(per, beta, dof):
    """A made-up table: |xi| and phase [deg] per (period, heading, DOF)."""
    return 0.1 * dof + 0.01 * per + 0.001 * beta, 10.0 * dof - 3.0 * per + 0.1 * beta


def _wamit(tmp_path, skip=None):
    lines = ["  -1.000000E+00   0.000000E+00     1   1.0E+00   0.0E+00   1.0E+00   0.0E+00"]  # zero-frequency limit
    for per in PERIODS:
        for beta in HEADINGS:
            for dof in range(1, 7):
                if (per, beta, dof) == skip:
                    continue
                mod, phs = _mod_phase(per, beta, dof)
                re, im = mod * math.cos(math.radians(phs)), mod * math.sin(math.radians(phs))
                lines.append(f"  {per:.6E}  {beta:.6E}  {dof:4d}  {mod:.6E}  {phs:.6E}  {re:.6E}  {im:.6E}")
    path = tmp_path / "ship.4"
    path.write_text("\n".join(lines) + "\n")
    return path


def _sea(omega, heading=0.0, amplitude=2.0, phase=0.7):
    w = np.atleast_1d(np.asarray(omega, float))
    return SeaComponents(amplitude=np.full(w.shape, amplitude), omega=w, wave_number=w**2 / 9.81,
                         heading=np.full(w.shape, heading), phase=np.full(w.shape, phase), depth=math.inf, gravity=9.81)


def test_a_wamit_rao_moves_the_vessel_as_its_amplitude_and_phase_say(tmp_path):
    """One wave of 2 m at T = 10 s, heading 90 deg, phase 0.7 rad (elevation 2 cos(w t - 0.7) at the origin):
    each DOF moves by 2 |xi| cos(w t - 0.7 + PHS), rotations divided by ULEN = 10 m (WAMIT's convention)."""
    table = read_wamit4(_wamit(tmp_path), ulen=10.0)
    assert table.omega.tolist() == pytest.approx([2 * math.pi / p for p in sorted(PERIODS, reverse=True)])
    w = 2 * math.pi / 10.0
    t = np.linspace(0.0, 30.0, 61)
    x = rao_motion(table, _sea(w, heading=math.radians(90.0)), t)
    for dof in range(1, 7):
        mod, phs = _mod_phase(10.0, 90.0, dof)
        scale = 0.1 if dof >= 4 else 1.0
        expected = 2.0 * mod * scale * np.cos(w * t - 0.7 + math.radians(phs))
        np.testing.assert_allclose(x[dof - 1], expected, rtol=0, atol=1e-5 * mod)  # the file's 7 digits


def test_raos_between_frequencies_and_headings_are_interpolated_linearly(tmp_path):
    """Half-way in frequency between T = 10 and 12.5 s, and at 45 deg between 0 and 90 deg (and at 315 deg,
    between 270 and 0 across north), the RAO is the mean of its neighbours' complex values."""
    table = read_wamit4(_wamit(tmp_path))
    wa, wb = 2 * math.pi / 12.5, 2 * math.pi / 10.0

    def h(per, beta, dof=3):
        mod, phs = _mod_phase(per, beta, dof)
        return mod * np.exp(-1j * math.radians(phs))

    mid = table.at(np.array([0.5 * (wa + wb)]), np.array([0.0]))[2, 0]
    assert mid == pytest.approx(0.5 * (h(12.5, 0.0) + h(10.0, 0.0)), abs=1e-6)
    at45 = table.at(np.array([wb]), np.array([math.radians(45.0)]))[2, 0]
    assert at45 == pytest.approx(0.5 * (h(10.0, 0.0) + h(10.0, 90.0)), abs=1e-6)
    at315 = table.at(np.array([wb]), np.array([math.radians(315.0)]))[2, 0]
    assert at315 == pytest.approx(0.5 * (h(10.0, 270.0) + h(10.0, 0.0)), abs=1e-6)


def test_a_csv_table_in_si_units_is_the_same_table(tmp_path):
    wamit = read_wamit4(_wamit(tmp_path))
    rows = ["frequency,heading,dof,amplitude,phase"]
    for f, w in enumerate(wamit.omega):
        for b, beta in enumerate(wamit.heading):
            for j in range(6):
                v = wamit.values[j, b, f]
                rows.append(f"{float(w)!r},{float(beta)!r},{j + 1},{float(abs(v))!r},{float(-np.angle(v))!r}")
    path = tmp_path / "ship.csv"
    path.write_text("\n".join(rows) + "\n")
    csv = read_rao_csv(path)
    np.testing.assert_allclose(csv.values, wamit.values, rtol=1e-12, atol=1e-15)


def test_tables_that_do_not_cover_the_sea_are_refused(tmp_path):
    table = read_wamit4(_wamit(tmp_path))
    with pytest.raises(InputError, match=r"covers 0\.5027-0\.7854 rad/s, but the sea has 50\.0% of its variance "
                                         r"at 1 frequencies outside it \(e\.g\. 1 rad/s\)"):
        rao_motion(table, _sea([0.6, 1.0]), [0.0, 1.0])
    # a negligible share outside is left out
    x = rao_motion(table, SeaComponents(amplitude=np.array([1.0, 1e-3]), omega=np.array([0.6, 1.0]),
                                        wave_number=np.array([0.04, 0.1]), heading=np.zeros(2), phase=np.zeros(2),
                                        depth=math.inf, gravity=9.81), [0.0])
    assert np.all(np.isfinite(x))
    with pytest.raises(InputError, match=r"1 \(DOF, heading, frequency\) entries are missing, e\.g\. heave at "
                                         r"heading 90 deg and 0\.6283 rad/s"):
        read_wamit4(_wamit(tmp_path, skip=(10.0, 90.0, 3)))
    one = read_wamit4(_wamit(tmp_path))
    one = type(one)(one.omega, one.heading[:1], one.values[:, :1], "one heading")
    with pytest.raises(InputError, match="single heading 0 deg, but the sea's components travel towards up to 90 deg"):
        rao_motion(one, _sea(0.6, heading=math.radians(90.0)), [0.0])
    with pytest.raises(InputError, match=r"ulen must be > 0 m"):
        read_wamit4(_wamit(tmp_path), ulen=0.0)
    bad = tmp_path / "bad.csv"
    bad.write_text("frequency,heading,amplitude\n1,0,1\n")
    with pytest.raises(InputError, match="needs the columns frequency, heading, dof, amplitude, phase"):
        read_rao_csv(bad)


_HEADER = "frequency,heading,dof,amplitude,phase\n"
_GOOD = [(w, 0.0, d, 1.0 if d == 3 else 0.1, 0.2) for w in (0.2, 0.5, 1.0) for d in range(1, 7)]


def _csv(tmp_path, rows, name="r.csv"):
    path = tmp_path / name
    path.write_text(_HEADER + "".join(",".join(str(x) for x in r) + "\n" for r in rows))
    return path


def test_a_good_csv_table_reads_its_numbers(tmp_path):
    # the reference for the refusals below: the same rows, each read back as amplitude e^(-i phase)
    t = read_rao_csv(_csv(tmp_path, _GOOD))
    assert t.values[2, 0, 1] == pytest.approx(1.0 * np.exp(-0.2j), rel=1e-15)
    assert t.values[0, 0, 2] == pytest.approx(0.1 * np.exp(-0.2j), rel=1e-15)


@pytest.mark.parametrize("rows, text, match", [
    (None, "", r"is empty"),                                                          # before: IndexError (exit 3)
    (None, _HEADER, r"holds no RAO rows"),
    ([(w, 90.0, d, a, p) for (w, _, d, a, p) in _GOOD], None, r"row 1: heading = 90 rad is beyond 2 pi: it looks "
                                                                r"like degrees \(1.571 rad"),  # before: read as rad
    ([(w, b, d, 1e9 if d == 1 else a, p) for (w, b, d, a, p) in _GOOD], None,
     r"row 1: the surge RAO amplitude is 1e\+09 m/m at 0.2 rad/s, above the plausible 100 m/m"),
    ([(w, b, d, 20.0 if d == 4 else a, p) for (w, b, d, a, p) in _GOOD], None,
     r"row 4: the roll RAO amplitude is 20 rad/m .* above the plausible 3.14 rad/m"),
    ([(w, b, 2.5 if d == 2 else d, a, p) for (w, b, d, a, p) in _GOOD], None,
     r"row 2: dof = 2.5 is not a whole number"),                                       # before: truncated to sway
    ([(w, b, d, -a, p) for (w, b, d, a, p) in _GOOD], None, r"row 1: amplitude = -0.1 is negative"),
    (_GOOD + [_GOOD[4]], None, r"row 5 and row 19 both give the pitch RAO"),            # before: last kept silently
])
def test_a_bad_csv_table_is_refused_naming_its_row(tmp_path, rows, text, match):
    path = tmp_path / "bad.csv"
    if rows is not None:
        path = _csv(tmp_path, rows, "bad.csv")
    else:
        path.write_text(text)
    with pytest.raises(InputError, match=match):
        read_rao_csv(path)


def test_a_bad_wamit_table_is_refused(tmp_path):
    rows = [(2 * math.pi / w, 0.0, d, a, 0.0, a, 0.0) for (w, _, d, a, _) in _GOOD]
    path = tmp_path / "bad.4"
    path.write_text("".join(" ".join(f"{x:g}" for x in (T, b, 3.5 if d == 3 else d, *r)) + "\n"
                            for (T, b, d, *r) in rows))
    with pytest.raises(InputError, match=r"dof = 3.5 is not a whole number"):
        read_wamit4(path)
    path.write_text("".join(" ".join(f"{x:g}" for x in (T, b, d, 5e3 if d == 3 else a, *r)) + "\n"
                            for (T, b, d, a, *r) in rows))
    with pytest.raises(InputError, match=r"the heave RAO amplitude is 5000 m/m"):
        read_wamit4(path)

"""Validation of the straight-line laying theory against paper 001, section 2 and section 4.1.

Source: paper 001, Park, H. I., Kim, D. H., Kim, M. J. and Chin, K. H., "Two dimensional laying
simulation of subsea cables" (Korean, with English abstract),
/work/shared/seeds/001_24abb5c08bf41930.txt: eq. (7)-(11), Table 1 (incident angle at the surface
vs ship speed: straight-line theory and numerical), and the ship tension of section 4.1.

Cable: C_d = 1.85, rho = 1030 kg/m^3, d = 0.0225 m, w = 4.49 N/m.

Findings:
- The "straight-line theory" column is alpha = H / V_s converted to degrees with 57.3 deg/rad
  (not 180/pi): with 57.3 every row, including 0.025 m/s (1048.96 deg), is reproduced to the
  printed 0.001 deg; with 180/pi the column is 0.008 % lower (max 0.004 deg for 0.5-5 m/s).
- The "numerical" column (the paper's finite-difference program) equals the exact root of
  eq. (7) within 0.0005 deg from 0.75 to 5 m/s. At 0.5 m/s the paper's 48.310 deg is 0.0147 deg
  above the exact root 48.2953 deg (independent brentq root in tests/unit): the table's value
  there is the simulation's, not the theory's, so the exact root cannot be met to 0.01 deg in
  that row; we assert 0.02 deg there and say so.
- At 0.025 m/s, H/V_s = 18.3 rad = 1048.96 deg is meaningless (beyond 90 deg; the small-angle
  formula holds below about 30 deg, as the paper says after eq. (8)); the exact root is
  89.83 deg (an almost stopped ship leaves the cable almost vertical) while the paper's program
  gave 68.70 deg, presumably not yet settled; neither theory covers that row's 68.70.
- Section 4.1 swaps two numbers (SPEC.md): H = 0.4577 m/s rad and alpha(2 m/s) = 0.2288 rad = 13.11 deg.
"""

import numpy as np
import pytest
from _evidence import check

from seacable.errors import SeacableWarning
from seacable.statics.laying import hydrodynamic_constant, laying_angle, straight_line_lay

CD, RHO, D, W = 1.85, 1030.0, 0.0225, 4.49

# ship speed [m/s], straight-line theory [deg], numerical [deg]  (paper 001 Table 1)
TABLE1 = np.array([
    [0.5, 52.448, 48.310], [0.75, 34.965, 33.798], [1.0, 26.224, 25.744], [1.25, 20.979, 20.736],
    [1.5, 17.483, 17.343], [1.75, 14.985, 14.897], [2.0, 13.112, 13.053], [2.25, 11.655, 11.614],
    [2.5, 10.490, 10.459], [2.75, 9.536, 9.513], [3.0, 8.741, 8.724], [3.25, 8.069, 8.055],
    [3.5, 7.493, 7.481], [3.75, 6.993, 6.984], [4.0, 6.556, 6.548], [4.25, 6.170, 6.164],
    [4.5, 5.828, 5.822], [4.75, 5.521, 5.516], [5.0, 5.245, 5.241],
])
SLOW_ROW = (0.025, 1048.960, 68.700)


def _small_angle(vs):
    # Speeds below ~0.87 m/s give more than 30 deg and warn (outside the formula's validity).
    if np.any(hydrodynamic_constant(W, D, CD, RHO) / np.asarray(vs) > np.radians(30.0)):
        with pytest.warns(SeacableWarning, match="exceeds 30 deg"):
            return laying_angle(vs, W, D, CD, RHO, method="small_angle")
    return laying_angle(vs, W, D, CD, RHO, method="small_angle")


def test_hydrodynamic_constant_and_2_m_s_angle():
    # SPEC.md (corrected swap): H = 0.4577 m/s rad, printed to 4 digits -> +-5e-5.
    check(hydrodynamic_constant(W, D, CD, RHO), 0.4577, atol=5e-5, source="Paper 001 (cable laying), section 4.1", unit="m/s rad",
          quantity="hydrodynamic constant H (the text's swap corrected)", why="printed to 4 digits")
    a = _small_angle(2.0)
    assert a == pytest.approx(0.2288, abs=5e-5)
    check(np.degrees(a), 13.11, atol=5e-3, source="Paper 001 (cable laying), section 4.1", unit="deg",
          quantity="laying angle H/Vs at 2 m/s", why="printed to 2 decimals")


def test_table1_straight_line_theory_column():
    a = np.degrees(_small_angle(TABLE1[:, 0]))
    # Brief's band 0.01 deg; measured worst 0.0041 deg (the paper's 57.3 deg/rad, see docstring).
    check(a, TABLE1[:, 1], atol=0.01, source="Paper 001 (cable laying), Table 1", unit="deg",
          quantity="incident angle, straight-line theory column, 0.5-5 m/s",
          why="0.01 deg band; the paper converts with 57.3 deg/rad (worst 0.0041 deg)")
    # With the paper's conversion factor the printed values come out to their last digit.
    a573 = _small_angle(TABLE1[:, 0]) * 57.3
    np.testing.assert_allclose(a573, TABLE1[:, 1], atol=6e-4)


def test_table1_numerical_column_is_exact_root():
    a = np.degrees(laying_angle(TABLE1[:, 0], W, D, CD, RHO))
    # 0.75-5 m/s: measured worst 0.0005 deg, the printing resolution; 0.01 deg per the brief.
    check(a[1:], TABLE1[1:, 2], atol=6e-4, source="Paper 001 (cable laying), Table 1", unit="deg",
          quantity="incident angle, numerical column (the exact root), 0.75-5 m/s",
          why="the printing resolution, 0.0005 deg")
    np.testing.assert_allclose(a[1:], TABLE1[1:, 2], atol=6e-4)
    # 0.5 m/s: the paper's simulated 48.310 deg is 0.0147 deg above the exact root (docstring);
    # 0.02 deg bounds that known discrepancy of the paper's program, not an error of ours.
    assert a[0] == pytest.approx(48.2953, abs=1e-4)
    check(a[0], TABLE1[0, 2], atol=0.02, source="Paper 001 (cable laying), Table 1", unit="deg",
          quantity="incident angle, numerical column, 0.5 m/s",
          why="the paper's simulation is 0.0147 deg above the exact root there (a known discrepancy of its program)")


def test_table1_slow_row_outside_both_theories():
    vs, small_printed, numerical_printed = SLOW_ROW
    with pytest.warns(SeacableWarning):
        a0 = laying_angle(vs, W, D, CD, RHO, method="small_angle")
    assert a0 * 57.3 == pytest.approx(small_printed, abs=6e-3)   # the paper's H/V_s, 57.3 deg/rad
    assert a0 > np.pi / 2                                         # no geometric meaning
    exact = np.degrees(laying_angle(vs, W, D, CD, RHO))
    assert exact == pytest.approx(89.829, abs=1e-3)               # nearly vertical
    assert abs(exact - numerical_printed) > 20.0                  # the paper's 68.70 is not a steady root


def test_ship_tension_zero_bottom_tension():
    r = straight_line_lay(50.0, 2.0, W, D, CD, water_density=RHO)
    # eq. (10): T_s = w h = 224.5 N exactly (no tangential drag).
    assert r.top_tension == pytest.approx(224.5, rel=1e-14)
    # The paper's program gives 220 +- 10 N.
    check(r.top_tension, 220.0, atol=10.0, source="Paper 001 (cable laying), section 4", unit="N",
          quantity="ship tension with zero bottom tension, 50 m", why="the paper's program gives 220 +- 10 N")
    check(r.top_tension, 224.5, rtol=1e-14, source="Closed form: straight-line lay", unit="N",
          quantity="ship tension w h, 4.49 N/m x 50 m", why="exact to rounding")
    # eq. (11) with a bottom tension.
    r0 = straight_line_lay(50.0, 2.0, W, D, CD, water_density=RHO, bottom_tension=100.0)
    assert r0.top_tension == pytest.approx(324.5, rel=1e-14)

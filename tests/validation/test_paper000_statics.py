"""Validation of the steady towed cable against paper 000, Tables 1 and 2.

Source: paper 000, "Nonlinear dynamic analysis of a towed low-tension cable" (Korean, with English
abstract), /work/shared/seeds/000_e4cc68758a51635b.txt: Table 1 (input data), Table 2 (quasi-static
tension by node, present work and the WHOI Cable program).

Table 1: L = 170 m, 7 nodes, d = 0.035 m, w0 = 17.7 N/m, current -1.0 m/s against the tow,
E = 4.4e8 N/m^2, C_dn = C_db = 1.5, C_dt = 0.01, vessel 1.0 m/s, so the relative flow speed is
U = 2 m/s; rho = 1025 kg/m^3 (not printed; it reproduces the table).

Calibration, not validation: the density (not printed) and the absence of tangential drag (C_dt =
0.01 is printed) are the choices that reproduce Table 2, so agreement with the table's numbers does
not validate them. What is validated is the physics behind them: the closed form of the critical
angle and the linear tension (test_analytic_slope_and_critical_angle, to 1e-8); the peer code's
column (WHOI Cable) is reproduced by the same choices within 0.12 %.

Finding: Table 2 corresponds to the cable *without* tangential drag. A free-ended cable lies
straight at the critical angle (22.906 deg) with dT/ds = w0 sin(phi) = 6.889 N/m, i.e. 1171.1 N at
the top, the paper's 1171.15 N. With eq. (6)'s tangential drag at C_dt = 0.01 (wetted perimeter
pi d) dT/ds gains 1/2 rho C_dt pi d U^2 cos^2(phi) = 1.912 N/m and the top tension is 1496.3 N,
28 % above the table.
"""

import numpy as np
import pytest
from _evidence import check

from seacable.statics.towed import critical_angle, towed_cable_steady

L, D, W, CDN, CDT, RHO = 170.0, 0.035, 17.7, 1.5, 0.01, 1025.0
U = 1.0 - (-1.0)                       # vessel speed minus current along the tow [m/s]
EA = 4.4e8 * np.pi / 4 * D**2          # E A of the solid section, 4.23e5 N

TABLE2_PRESENT = np.array([0.0, 195.50, 390.38, 585.57, 780.76, 975.96, 1171.15])
TABLE2_WHOI = np.array([0.0, 195.42, 390.78, 586.19, 780.79, 975.87, 1172.32])


def test_table2_tension_by_node_without_tangential_drag():
    r = towed_cable_steady(L, W, D, U, CDN, 0.0, water_density=RHO, n_points=7)
    # 0.5 % is the brief's acceptance band; the measured worst deviation is 0.16 % at node 2,
    # where the paper's own values are not exactly linear in s (195.50 * 6 = 1173 != 1171.15).
    check(r.tension[1:], TABLE2_PRESENT[1:], rtol=5e-3, source="Paper 000 (towed cable), Table 2", unit="N",
          quantity="quasi-static tension by node, free end to vessel (no tangential drag)",
          why="0.5 % acceptance band; the printed values are not exactly linear in s (195.50 x 6 != 1171.15)")
    assert r.tension[0] == 0.0
    # Peer code (WHOI Cable) column, same band: measured worst 0.12 %.
    check(r.tension[1:], TABLE2_WHOI[1:], rtol=5e-3, source="WHOI Cable (paper 000, Table 2)", unit="N",
          quantity="quasi-static tension by node, free end to vessel",
          why="0.5 % band as for the paper's own column; WHOI Cable is a different discretisation")
    # Top value: ours 1171.16 N vs 1171.15 N; 0.05 N is the rounding of the printed 1171.1 check.
    check(r.top_tension, 1171.1, atol=0.1, source="Paper 000 (towed cable), Table 2", unit="N", quantity="top tension (SPEC's check)",
          why="the printed 1171.1 N has one decimal")


def test_analytic_slope_and_critical_angle():
    phi = critical_angle(W, D, U, CDN, RHO)
    # SPEC.md: 6.889 N/m (printed to 4 digits, so +-0.0005 N/m).
    check(W * np.sin(phi), 6.889, atol=5e-4, source="Paper 000 (towed cable), critical angle", unit="N/m",
          quantity="tension gradient w0 sin(phi) at the critical angle", why="printed to 4 digits")
    r = towed_cable_steady(L, W, D, U, CDN, 0.0, water_density=RHO, n_points=7)
    # The integrated tension is the closed form to the integrator tolerance (rtol 1e-10).
    np.testing.assert_allclose(np.diff(r.tension) / np.diff(r.s), W * np.sin(phi), rtol=1e-8)


def test_table2_with_elastic_stretch_of_table1():
    # Including EA and eq. (6)'s sqrt(1+e) drag factor changes the top tension by only -0.03 %
    # (strain 0.28 % at the top), so the table is reproduced within the same 0.5 % band.
    r = towed_cable_steady(L, W, D, U, CDN, 0.0, water_density=RHO, axial_stiffness=EA, n_points=7)
    np.testing.assert_allclose(r.tension[1:], TABLE2_PRESENT[1:], rtol=5e-3)
    assert r.top_tension < towed_cable_steady(L, W, D, U, CDN, 0.0, n_points=7).top_tension


def test_top_tension_with_tangential_drag_eq6():
    phi = critical_angle(W, D, U, CDN, RHO)
    analytic = L * (W * np.sin(phi) + 0.5 * RHO * CDT * np.pi * D * U**2 * np.cos(phi) ** 2)
    r = towed_cable_steady(L, W, D, U, CDN, CDT, water_density=RHO, n_points=7)
    # Closed form (straight cable, linear tension) to the integrator tolerance.
    check(r.top_tension, analytic, rtol=1e-8, source="Closed form: straight towed cable", unit="N",
          quantity="top tension with tangential drag, L (w sin phi + 1/2 rho Cdt pi d U^2 cos^2 phi)",
          why="the integrator's tolerance")
    # SPEC.md's "about 1496 N": 0.5 % band of the brief; measured 1496.3 N.
    check(r.top_tension, 1496.0, rtol=5e-3, source="Paper 000 (towed cable), eq. (6)", unit="N",
          quantity="top tension with eq. (6)'s tangential drag (SPEC: about 1496 N)",
          why="0.5 % band; SPEC gives 'about' 1496 N")
    # And it is clearly not Table 2: the paper's table was computed without tangential drag.
    assert r.top_tension > 1.2 * TABLE2_PRESENT[-1]


def test_table1_cable_with_heavy_towed_body_is_near_vertical():
    # Independent statics: a 1e6 N body keeps the cable within ~0.02 rad of vertical, so the top
    # force is (body drag + q_n L, W_b + w L) up to O(eps^2) and q_n eps L / W_b ~ 4e-4 terms.
    wb, cda = 1.0e6, 0.1
    r = towed_cable_steady(L, W, D, U, CDN, CDT, water_density=RHO, body_weight=wb, body_drag_area=cda)
    qn = 0.5 * RHO * CDN * D * U**2
    assert r.top_tension * np.cos(r.top_angle) == pytest.approx(0.5 * RHO * cda * U**2 + qn * L, rel=2e-3)
    assert r.top_tension * np.sin(r.top_angle) == pytest.approx(wb + W * L, rel=2e-3)

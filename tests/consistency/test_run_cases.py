"""run(case) end to end: the example case files give the same numbers as the physics functions,
and the models that can answer the same question agree with each other."""

import math
from pathlib import Path

import numpy as np
import pytest

import seacable as sc
from seacable.statics import catenary, line_equilibrium

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def oc3():
    return sc.load_case(EXAMPLES / "oc3_hywind_static.yaml")


def test_static_case_equals_the_single_line_catenary(oc3):
    ds = sc.run(oc3)
    ref = catenary(848.67, 250.0, 902.2, 384.243e6, 698.094)
    # Two independent solvers (multi-segment shooting vs the vectorised single-line Newton), each
    # converged to ~1e-10: agreement to 1e-6 relative is the exactness requirement.
    for name in ("H_fairlead", "V_fairlead", "H_anchor", "grounded_length"):
        assert float(ds[name]) == pytest.approx(float(getattr(ref, name)), rel=1e-6), name
    # the profile ends at the fairlead, in absolute coordinates
    assert (float(ds.x[-1]), float(ds.z[-1])) == pytest.approx((848.67, -70.0), abs=1e-6)
    assert float(ds.z.min()) == pytest.approx(-320.0, abs=1e-6)


def test_pushover_starts_at_the_static_solution(oc3):
    ds = sc.run(sc.load_case(EXAMPLES / "oc3_hywind_pushover.yaml"))
    static = sc.run(oc3)
    at_zero = ds.sel(offset=0.0)
    assert float(at_zero.H_fairlead) == pytest.approx(float(static.H_fairlead), rel=1e-9)
    # Moving the fairlead away from the anchor stiffens a catenary mooring: H and dH/dx rise.
    assert np.all(np.diff(ds.H_fairlead) > 0) and np.all(np.diff(ds.stiffness_horizontal) > 0)
    # dH/dx agrees with the slope of the curve. The central difference on the h = 1 m grid errs by
    # h^2 H'''/6, and h^2 H''' is the second difference of dH/dx: allow twice that estimate.
    k = ds.stiffness_horizontal.values
    slope = np.gradient(ds.H_fairlead.values, ds.offset.values)
    truncation = np.abs(k[2:] - 2 * k[1:-1] + k[:-2]) / 6
    assert np.all(np.abs(slope[1:-1] - k[1:-1]) <= 2 * truncation + 1e-9 * k[1:-1])


def test_modal_case_fundamental_brackets_the_wave_speed_estimate(oc3):
    ds = sc.run(sc.load_case(EXAMPLES / "oc3_hywind_modes.yaml"))
    first_out = float(ds.period.where(ds.plane == "out", drop=True)[0])
    suspended = ds.tension.values[ds.s.values > float(sc.run(oc3).grounded_length)]
    # Paper 002's wave-speed period and the eigen period of the same line both lie within the Sturm
    # bracket sqrt(Tmax/Tmin) of each other (see tests/validation/test_modal_closed_forms.py).
    bracket = np.sqrt(suspended.max() / suspended.min())
    assert 1 / bracket < float(ds.wave_period) / first_out < bracket
    # modes are sorted, and both planes are present
    assert np.all(np.diff(ds.frequency) >= 0) and set(ds.plane.values) == {"in", "out"}


def test_lena_case_reproduces_the_clump_lift_off():
    ds = sc.run(sc.load_case(EXAMPLES / "paper004_lena_pushover.yaml"))
    # At about 1 MN of pretension (zero offset) most of the 36.58 m clump rests on the seabed beyond the
    # 396.2 m anchor line; at 12 m of offset the whole clump has lifted (lift-off near 7 m, see
    # tests/validation/test_paper004_mooring.py), so less than the anchor line remains in contact.
    assert float(ds.seabed_contact_length[0]) > 396.2 + 36.58 / 2
    assert float(ds.seabed_contact_length[-1]) < 396.2
    assert 0.9e6 < float(ds.H_fairlead[0]) < 1.1e6


def test_paper000_case_matches_the_analytic_top_tension():
    case = sc.load_case(EXAMPLES / "paper000_steady_statics.yaml")
    # Analytic check (SPEC.md): a free-ended cable lies straight at the critical angle, the root of
    # w cos(phi) = q sin^2(phi) with q = rho C_dn d U^2 / 2, and T_top = L (w sin(phi) + D_t),
    # D_t = rho C_dt pi d U^2 cos^2(phi) / 2. The case adds EA (stretch), hence the 0.5 %.
    w, rho, d, u, cdn, cdt, length = 17.7, 1025.0, 0.035, 2.0, 1.5, 0.01, 170.0
    q = 0.5 * rho * cdn * d * u**2
    cos_phi = (np.sqrt(w**2 + 4 * q**2) - w) / (2 * q)
    top = length * (w * np.sqrt(1 - cos_phi**2) + 0.5 * rho * cdt * np.pi * d * u**2 * cos_phi**2)
    assert float(sc.run(case).top_tension) == pytest.approx(top, rel=5e-3)
    no_drag = case.replace(line=sc.Line.single(
        case.line.segments[0].line_type.replace(drag_tangential=0.0, axial_stiffness=None), 170.0))
    ds = sc.run(no_drag)
    # paper 000 Table 2, within the 0.5 %
    table2 = [0.0, 195.50, 390.38, 585.57, 780.76, 975.96, 1171.15]
    np.testing.assert_allclose(ds.tension.values, table2, rtol=5e-3, atol=1e-9)


def test_paper001_case_reproduces_table1():
    ds = sc.run(sc.load_case(EXAMPLES / "paper001_table1.yaml"))
    numerical = {0.75: 33.798, 1.0: 25.744, 2.0: 13.053, 3.0: 8.724, 5.0: 5.241}
    small = {0.75: 34.965, 1.0: 26.224, 2.0: 13.112, 3.0: 8.741, 5.0: 5.245}
    for v in numerical:
        # the 0.01 deg for both columns (the paper prints 3 decimals)
        assert math.degrees(float(ds.angle.sel(ship_speed=v))) == pytest.approx(numerical[v], abs=0.01)
        assert math.degrees(float(ds.angle_small.sel(ship_speed=v))) == pytest.approx(small[v], abs=0.01)
    # ship tension with zero bottom tension: w h = 4.49 * 50 = 224.5 N (no tangential drag here)
    np.testing.assert_allclose(ds.top_tension.values, 224.5, rtol=1e-12)


def test_vertical_case_rows_a_b_c():
    ds = sc.run(sc.load_case(EXAMPLES / "paper002_vertical_cable.yaml"))
    row = ds.period.isel(mode=0)
    # v = 30.5 m/s, L = 152.4 m: string 2L/v = 9.993 s (row A); exact below it; eq. 15 within 5 % of exact
    assert float(row.sel(solution="string")) == pytest.approx(2 * 152.4 / 30.5, rel=1e-9)
    assert float(row.sel(solution="exact")) < float(row.sel(solution="string"))
    assert float(row.sel(solution="wave")) == pytest.approx(float(row.sel(solution="exact")), rel=0.05)


def test_run_is_pure_and_rejects_non_cases(oc3):
    a, b = sc.run(oc3), sc.run(oc3)
    assert a.identical(b)
    with pytest.raises(sc.InputError, match="run\\(\\) takes a seacable.Case"):
        sc.run({"line": 1})


def test_multisegment_equals_catenary_when_one_segment():
    eq = line_equilibrium([902.2], [698.094], [384.243e6], 848.67, 250.0)
    ref = catenary(848.67, 250.0, 902.2, 384.243e6, 698.094)
    np.testing.assert_allclose(eq.stiffness, ref.stiffness, rtol=1e-6)

"""Elastic catenary against the peer code MoorPy.

Reference: M. Hall et al., MoorPy (NREL), ``moorpy.Catenary.catenary`` (a port of J. Jonkman's
FAST v7 catenary routine, NREL/TP-500-41958, 2007).  MoorPy is in the ``test`` extra
(``pip install -e ".[test]"``); without it this module is skipped, except under CI (``CI`` set),
where a missing MoorPy is an error so that the comparison cannot silently stop running.

MoorPy returns ``(FxA, FzA, FxB, FzB, info)``: the forces the line exerts on end A and on
end B.  In seacable's convention ``H_anchor = FxA``, ``V_anchor = FzA``,
``H_fairlead = -FxB``, ``V_fairlead = -FzB``; MoorPy's ``info['stiffnessB']`` is our
``stiffness`` (d(HF, VF)/d(XF, ZF)), ``info['LBot']`` our ``grounded_length``.  Its ``CB < 0``
means "no seabed, end A this far above it": we pass a large negative ``CB`` for seabed=False
and for buoyant lines.

Tolerance 1e-5 relative: MoorPy iterates to an absolute span error Tol (passed here as
1e-9 * L), so its forces carry relative errors of about Tol/L x (stiffness x L / T) which is
below 1e-6 for these cases; 1e-5 covers it with margin.
"""

import importlib
import os

import numpy as np
import pytest
from _evidence import check

from seacable.statics.catenary import CatenaryRegime as R
from seacable.statics.catenary import catenary

if os.environ.get("CI"):
    moorpy_catenary = importlib.import_module("moorpy.Catenary").catenary
else:
    moorpy_catenary = pytest.importorskip("moorpy.Catenary").catenary


def _grid():
    cases = []
    L, EA, w = 900.0, 1e9, 700.0
    # suspended: fairlead high (x, z) with seabed far below end A for seabed=False
    for x in (300.0, 500.0, 700.0):
        for z in (650.0, 800.0):
            cases.append((x, z, L, EA, w, 0.0, True))
    # touchdown with and without friction, including friction taking all tension
    for x in (600.0, 700.0, 800.0):
        for mu in (0.0, 0.3, 1.0):
            cases.append((x, 250.0, L, EA, w, mu, True))
    # slack: L shape
    cases += [(100.0, 250.0, L, EA, w, 0.0, True), (300.0, 100.0, L, EA, w, 0.5, True)]
    # mid-water U shapes and fairlead below end A
    for z in (-100.0, 50.0, 200.0):
        cases.append((500.0, z, L, 5e8, w, 0.0, False))
    # near-taut
    cases += [(700.0, 566.0, 900.0, 1e8, 100.0, 0.0, True)]
    # buoyant
    cases += [(300.0, 100.0, 400.0, 1e8, -200.0, 0.0, True), (300.0, 50.0, 400.0, 1e8, -200.0, 0.0, False)]
    # flat on the seabed, stretched
    cases += [(901.0, 0.0, L, 1e8, w, 0.0, True), (905.0, 0.0, L, 1e8, w, 0.5, True),
              (900.5, 0.0, L, 1e8, w, 0.5, True)]
    return cases


CASES = _grid()


def _moorpy(x, z, L, EA, w, mu, seabed):
    # a buoyant line anchored on the seabed never touches it (see seacable's docstring);
    # MoorPy instead lets it float along a surface at the anchor's height when CB >= 0 and
    # depth is unset, so buoyant cases are compared with MoorPy's "no contact" option.
    cb = mu if (seabed and w > 0) else -1e4
    FxA, FzA, FxB, FzB, info = moorpy_catenary(x, z, L, EA, w, CB=cb, Tol=1e-9 * L, MaxIter=200)
    return FxA, FzA, -FxB, -FzB, info


@pytest.mark.parametrize("case", CASES, ids=[f"x{c[0]:g}_z{c[1]:g}_w{c[4]:g}_mu{c[5]:g}_sb{c[6]:d}"
                                              for c in CASES])
def test_end_forces_match_moorpy(case):
    HA, VA, HF, VF, info = _moorpy(*case)
    r = catenary(*case)
    scale = max(abs(HF), abs(VF))
    # 1e-5 of the larger fairlead component (see module docstring)
    check([float(v) for v in (r.H_fairlead, r.V_fairlead, r.H_anchor, r.V_anchor)], [HF, VF, HA, VA],
          rtol=1e-5, atol=1e-5 * scale, source="MoorPy (catenary)", unit="N",
          quantity=f"end forces H_B, V_B, H_A, V_A: span {case[0]:g} m, height {case[1]:g} m, L {case[2]:g} m, "
                   f"w {case[4]:g} N/m, mu {case[5]:g}, seabed {bool(case[6])}",
          why="1e-5 of the larger fairlead component: both solve the same equations to 1e-9 L")
    assert float(r.grounded_length) == pytest.approx(info["LBot"], rel=1e-5, abs=1e-5 * case[2])


# MoorPy's stiffness is exact (inverse analytic Jacobian) only for a suspended line or a
# frictionless touchdown; for slack lines it uses deliberate approximations (0.01 w, w).
STIFF_CASES = [c for c in CASES if c[5] == 0.0 and catenary(*c).regime in (R.SUSPENDED, R.TOUCHDOWN)]


@pytest.mark.parametrize("case", STIFF_CASES, ids=lambda c: f"x{c[0]:g}_z{c[1]:g}_w{c[4]:g}")
def test_stiffness_matches_moorpy_where_it_is_exact(case):
    r = catenary(*case)
    K = _moorpy(*case)[4]["stiffnessB"]
    # MoorPy inverts the same analytic Jacobian; 1e-5 relative to the largest entry
    np.testing.assert_allclose(r.stiffness, K, rtol=1e-5, atol=1e-5 * np.abs(K).max())


def test_where_moorpy_lets_a_near_taut_line_dip_below_the_seabed():
    # Found by bench/bench_catenary.py: for a near-taut line (chord 0.2 % longer than L) with
    # ZF/XF > 0.2, MoorPy's "crude check" forces a fully suspended profile (ProfileType 1),
    # whose anchor force points down (FzA < 0): the line leaves the anchor downward, through
    # the seabed.  seacable finds a 16 m touchdown instead, and reproduces MoorPy's answer
    # when told there is no seabed.
    case = (809.9283595887815, 195.19560036221273, 831.454891052171, 373190158.9260187,
            2557.583202551956, 0.45404422794919563)
    FxA, FzA, HF, VF, info = _moorpy(*case, True)
    assert info["ProfileType"] == 1 and FzA < 0
    r = catenary(*case)
    assert r.regime == R.TOUCHDOWN and float(r.grounded_length) > 10.0
    free = catenary(*case, seabed=False)
    # same 1e-5 tolerance as above
    assert float(free.H_fairlead) == pytest.approx(HF, rel=1e-5)
    assert float(free.V_anchor) == pytest.approx(FzA, rel=1e-5)

"""Multi-segment line statics against closed forms and the clump-weight trends of paper 004.

Sources
-------
- Jonkman, J. M. (2007). Dynamics modeling and loads analysis of an offshore floating wind
  turbine. NREL/TP-500-41958, section 2.2.1, eqs. for the elastic catenary with a frictional
  seabed (also Irvine, H. M. (1981). Cable Structures, MIT Press, eq. 2.15-2.16 for the fully
  suspended line). The closed forms are solved here independently with ``scipy.optimize.fsolve``.
- Paper 004 (``seeds/004_0937ea53f45f7fd0.txt``): Lena guyed tower mooring line, Table 1
  (guy line 640 m of 68.45 kg/m, clump 36.58 m of 4315 kg/m, anchor line 396.2 m, EA 1.87e9
  taken as N, depth 305 m, fairlead 15.24 m below the surface, so a 289.76 m vertical span).
  The table gives masses per length; we use them as weights in water times g (the paper's
  "unit length weight" in kgf/m). The paper gives no anchor radius; we start at a 980 m span,
  where the clump rests on the seabed. Paper 004 compares its force-excursion curves in words
  only, so we check its trends, not numbers:
  a clump lumped at one node is stiffer than the distributed clump before lift-off and lifts off
  at a smaller offset; with an anchor line the line softens after lift-off; without an anchor
  line it does not.
"""

import numpy as np
import pytest
from scipy.optimize import fsolve

from seacable.statics.multisegment import line_equilibrium, pushover

G = 9.80665


def jonkman(X, Z, L, w, EA, cb, seabed=True):
    """Jonkman (2007) eqs. 2-1, 2-2 (suspended) and 2-3, 2-4 (seabed with friction), solved for (H, V_F)."""

    def f(u):
        H, V = u
        if seabed and V < w * L:
            LB = L - V / w
            x = LB + H / w * np.arcsinh(V / H) + H * L / EA
            if cb > 0:
                x += cb * w / (2 * EA) * (-LB**2 + (LB - H / (cb * w)) * max(LB - H / (cb * w), 0.0))
            z = H / w * (np.sqrt(1 + (V / H) ** 2) - 1) + V**2 / (2 * EA * w)
        else:
            VA = V - w * L
            x = H / w * (np.arcsinh(V / H) - np.arcsinh(VA / H)) + H * L / EA
            z = H / w * (np.sqrt(1 + (V / H) ** 2) - np.sqrt(1 + (VA / H) ** 2)) + (V * L - w * L * L / 2) / EA
        return [(x - X) / L, (z - Z) / L]

    # our solution, perturbed by 1 %, is only fsolve's start point (the root is unique)
    eq = line_equilibrium(L, w, EA, X, Z, seabed=seabed, seabed_friction=cb)
    sol, info, _, _ = fsolve(f, [eq.H_fairlead * 1.01, eq.V_fairlead * 0.99], xtol=1e-12,
                             full_output=True)
    assert np.max(np.abs(info["fvec"])) < 1e-12             # closed form satisfied to 1e-12 L
    return sol, eq


@pytest.mark.parametrize("X, Z, cb, seabed", [
    (800.0, 250.0, 0.0, True),     # long grounded part, no friction
    (800.0, 250.0, 0.5, True),     # friction takes all of H: anchor tension 0
    (900.0, 250.0, 1.0, True),     # friction takes all of H with a shorter grounded part
    (985.0, 250.0, 0.3, True),     # friction takes part of H: anchor tension > 0
    (1030.0, 250.0, 0.0, True),    # taut, anchor uplift (fully suspended)
    (800.0, 250.0, 0.0, False),    # mid-water anchor, slack: V_A < 0
    (700.0, -100.0, 0.0, False),   # mid-water, fairlead below anchor
])
def test_one_segment_matches_jonkman_closed_form(X, Z, cb, seabed):
    (H, V), eq = jonkman(X, Z, 1000.0, 700.0, 5e8, cb, seabed)
    # 1e-6 relative: both sides are converged to ~1e-12; the margin covers fsolve's stopping rule
    assert eq.H_fairlead == pytest.approx(H, rel=1e-6)
    assert eq.V_fairlead == pytest.approx(V, rel=1e-6)
    if seabed and V < 700.0 * 1000.0:
        LB = 1000.0 - V / 700.0
        assert eq.grounded_length == pytest.approx(LB, rel=1e-6)
        # Jonkman's anchor tension: H reduced by the friction of the grounded length, >= 0
        assert eq.H_anchor == pytest.approx(max(H - cb * 700.0 * LB, 0.0), rel=1e-6, abs=1e-6 * H)


def test_irvine_suspended_elastic_closed_form():
    """Irvine (1981) eq. 2.15-2.16: the fairlead position from the found (H, V_A) is exact."""
    L, w, EA, X, Z = 500.0, 300.0, 2e7, 420.0, 150.0
    eq = line_equilibrium(L, w, EA, X, Z, seabed=False)
    H, VA = eq.H_anchor, eq.V_anchor
    VF = VA + w * L
    x = H * L / EA + H / w * (np.arcsinh(VF / H) - np.arcsinh(VA / H))
    z = (VF**2 - VA**2) / (2 * EA * w) + (np.hypot(H, VF) - np.hypot(H, VA)) / w
    # 1e-9 of the span: the solver's own position tolerance is 1e-9 of the length (500 m)
    assert x == pytest.approx(X, abs=1e-9 * L * 2)
    assert z == pytest.approx(Z, abs=1e-9 * L * 2)
    assert eq.V_fairlead == pytest.approx(VF, rel=1e-12)


# ----------------------------------------------------------------------------------------------
# Paper 004, Lena guyed tower line
# ----------------------------------------------------------------------------------------------
LENGTHS = [396.2, 36.58, 640.0]
W_LINE, W_CLUMP = 68.45 * G, 4315.0 * G
EA_LENA = 1.87e9
DEPTH_SPAN = 305.0 - 15.24
OFFSETS = np.arange(0.0, 40.01, 1.0)
X0 = 980.0


@pytest.fixture(scope="module")
def lena():
    dist = pushover(LENGTHS, [W_LINE, W_CLUMP, W_LINE], EA_LENA, X0, DEPTH_SPAN, OFFSETS)
    # the clump lumped at the node joining it to the guy line, keeping total weight and length
    lump = pushover(LENGTHS, [W_LINE] * 3, EA_LENA, X0, DEPTH_SPAN, OFFSETS,
                    point_loads=[(LENGTHS[0] + LENGTHS[1] - 1e-9, (W_CLUMP - W_LINE) * LENGTHS[1])])
    return dist, lump


def test_lena_clump_rests_then_lifts_off(lena):
    dist, _ = lena
    clump = dist.segment_grounded_length[:, 1]
    assert clump[0] == pytest.approx(LENGTHS[1])              # on the seabed at small offset
    assert clump[-1] == 0.0                                     # lifted at 40 m
    assert np.all(np.diff(clump) <= 1e-9)                       # lifts progressively
    # the touchdown runs up the clump from its guy-line end toward the anchor line
    lo = dist.liftoff_offset(1)
    assert lo is not None and 20.0 < lo < 35.0


def test_lena_lumped_clump_is_stiffer_and_lifts_off_earlier(lena):
    dist, lump = lena
    lo_d, lo_l = dist.liftoff_offset(1), lump.liftoff_offset(1)
    assert lo_l < lo_d                                          # paper 004: smaller offset at lift-off
    before = OFFSETS < lo_l - 1.0
    # a resting point mass is a fixed point; the distributed clump's upper end lifts gradually
    assert np.all(lump.stiffness_horizontal[before] >= dist.stiffness_horizontal[before] * (1 - 1e-9))
    # measured ratio at 21.5 m offset is ~1.3-1.5 (paper: about 1.39, span not given)
    ratio = lump.stiffness_horizontal[22] / dist.stiffness_horizontal[22]
    assert 1.2 < ratio < 1.8


def test_lena_softens_after_liftoff_only_with_anchor_line(lena):
    dist, _ = lena
    k = dist.stiffness_horizontal
    i_lift = int(np.argmax(dist.segment_grounded_length[:, 1] == 0.0))
    assert k[i_lift] < 0.5 * k[i_lift - 1]                      # stiffness drops at lift-off
    none = pushover(LENGTHS[1:], [W_CLUMP, W_LINE], EA_LENA, X0 - LENGTHS[0], DEPTH_SPAN, OFFSETS)
    assert np.all(np.diff(none.stiffness_horizontal) > 0.0)     # no anchor line: no softening

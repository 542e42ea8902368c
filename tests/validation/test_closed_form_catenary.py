"""Elastic catenary against its closed forms and against direct integration of the cable ODEs.

References
----------
H. M. Irvine, *Cable Structures*, MIT Press, 1981, eqs. 2.26-2.27 (elastic catenary).
J. M. Jonkman, "Dynamics modeling and loads analysis of an offshore floating wind turbine",
NREL/TP-500-41958, 2007, eqs. 2-35 to 2-42 (elastic catenary with seabed friction).

Two independent checks of every regime:

1. the solved end forces substituted into the *textbook* span equations (written here in
   their printed asinh form, not the cancellation-free form the solver uses) give back the
   spans; the solver's tolerance is 1e-10 of the length, so 1e-6 relative leaves a margin of
   10^4 for round-off in the textbook forms;
2. integrating dx/ds = (H/T)(1 + T/EA), dz/ds = (V/T)(1 + T/EA), dV/ds = w (suspended) and
   dT/ds = mu w (grounded, tension > 0) with scipy's DOP853 (rtol 1e-12) from the solved
   anchor force reaches the fairlead to 1e-6 of the chord: an independent check of the
   closed forms themselves.
"""

import numpy as np
import pytest
from _evidence import check
from scipy.integrate import solve_ivp

from seacable.statics.catenary import CatenaryRegime as R
from seacable.statics.catenary import catenary

# (name, x, z, L, EA, w, mu, seabed, expected regime)
CASES = [
    ("suspended", 400.0, 250.0, 470.0, 5e8, 800.0, 0.0, True, R.SUSPENDED),
    ("suspended U", 300.0, 50.0, 500.0, 5e8, 800.0, 0.0, False, R.SUSPENDED),
    ("suspended, fairlead below", 300.0, -100.0, 450.0, 5e7, 300.0, 0.0, False, R.SUSPENDED),
    ("touchdown, friction", 800.0, 250.0, 900.0, 1e9, 700.0, 0.5, True, R.TOUCHDOWN),
    ("touchdown, no friction", 800.0, 250.0, 900.0, 1e9, 700.0, 0.0, True, R.TOUCHDOWN),
    ("touchdown, friction takes all", 700.0, 250.0, 900.0, 1e9, 700.0, 1.0, True,
     R.TOUCHDOWN_SLACK_ANCHOR),
    ("slack L shape", 100.0, 250.0, 900.0, 1e9, 700.0, 0.5, True, R.SLACK_SEABED),
    ("vertical taut, seabed", 0.0, 500.1, 500.0, 1e9, 700.0, 0.0, True, R.VERTICAL),
    ("vertical taut, mid-water", 0.0, 500.1, 500.0, 1e9, 700.0, 0.0, False, R.VERTICAL),
    ("vertical hanging down", 0.0, -500.1, 500.0, 1e9, 700.0, 0.0, False, R.VERTICAL),
    ("U fold", 0.0, 100.0, 500.0, 1e7, 700.0, 0.0, False, R.SLACK_U),
    ("flat on seabed, anchor loaded", 905.0, 0.0, 900.0, 1e8, 700.0, 0.5, True, R.ON_SEABED),
    ("flat on seabed, friction takes all", 900.5, 0.0, 900.0, 1e8, 700.0, 0.5, True, R.ON_SEABED),
    ("near-taut", 400.0, 300.0, 499.9, 1e8, 100.0, 0.0, True, R.SUSPENDED),
    ("buoyant, seabed", 300.0, 100.0, 400.0, 1e8, -200.0, 0.0, True, R.SUSPENDED),
    ("buoyant, fairlead below", 300.0, -50.0, 400.0, 1e8, -200.0, 0.0, False, R.SUSPENDED),
    ("weightless bar", 300.0, 400.0, 499.0, 1e7, 0.0, 0.0, True, R.WEIGHTLESS),
]
IDS = [c[0] for c in CASES]


def _textbook_spans(r, x, z, L, EA, w, mu):
    """Jonkman (2007) eqs. 2-35/2-36 (suspended) and 2-39/2-42 (touchdown), printed forms."""
    H, VF = float(r.H_fairlead), float(r.V_fairlead)
    if r.regime == R.SUSPENDED:
        VA = VF - w * L
        xs = H / w * (np.arcsinh(VF / H) - np.arcsinh(VA / H)) + H * L / EA
        zs = H / w * (np.sqrt(1 + (VF / H) ** 2) - np.sqrt(1 + (VA / H) ** 2)) + (VF * L - w * L * L / 2) / EA
        return xs, zs
    if r.regime in (R.TOUCHDOWN, R.TOUCHDOWN_SLACK_ANCHOR):
        LB = L - VF / w
        xB = max(LB - H / (mu * w), 0.0) if mu > 0 else 0.0
        xs = (LB + H / w * np.arcsinh(VF / H) + H * L / EA
              - mu * w / (2 * EA) * (LB ** 2 - xB ** 2))
        zs = H / w * (np.sqrt(1 + (VF / H) ** 2) - 1) + VF ** 2 / (2 * w * EA)
        return xs, zs
    if r.regime in (R.VERTICAL, R.SLACK_U):
        VA = VF - w * L
        if r.regime == R.VERTICAL:   # straight: z = +-L + (VA L + w L^2/2)/EA
            return 0.0, np.sign(z) * L + (VA * L + w * L * L / 2) / EA
        L2, L1 = VF / w, -VA / w     # two hanging legs joined at the fold
        return 0.0, (L2 + w * L2 ** 2 / (2 * EA)) - (L1 + w * L1 ** 2 / (2 * EA))
    if r.regime == R.SLACK_SEABED:
        Ls = VF / w
        assert L - Ls >= x            # the grounded part reaches past the fairlead
        return x, Ls + w * Ls ** 2 / (2 * EA)
    if r.regime == R.ON_SEABED:
        xB = max(L - H / (mu * w), 0.0) if mu > 0 else 0.0
        return L + (H * L - mu * w * (L ** 2 - xB ** 2) / 2) / EA, 0.0
    if r.regime == R.WEIGHTLESS:
        T = float(r.fairlead_tension)
        return L * (1 + T / EA) * H / T, L * (1 + T / EA) * VF / T


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_textbook_spans_recovered(case):
    _, x, z, L, EA, w, mu, seabed, regime = case
    r = catenary(x, z, L, EA, w, mu, seabed)
    assert r.regime == regime
    xs, zs = _textbook_spans(r, x, z, L, EA, w, mu)
    chord = np.hypot(x, z)
    # solver tol 1e-10 * L; 1e-6 leaves room for the round-off of the printed asinh forms
    assert abs(xs - x) <= 1e-6 * chord
    assert abs(zs - z) <= 1e-6 * chord


def _integrate(r, x, z, L, EA, w, mu):
    """March the cable ODEs from the anchor; return the end point."""
    reg = int(r.regime)
    HA, VA, LB = float(r.H_anchor), float(r.V_anchor), float(r.grounded_length)
    HF = float(r.H_fairlead)
    opts = dict(method="DOP853", rtol=1e-12, atol=1e-12 * L)
    x0 = 0.0
    if LB > 0:
        # grounded: T rises by mu w per metre from the anchor once T > 0 (x_B: start of tension)
        xB = max(LB - HF / (mu * w), 0.0) if mu > 0 else 0.0

        def ground(s, y):
            T = HA + mu * w * s if reg != R.TOUCHDOWN_SLACK_ANCHOR and reg != R.SLACK_SEABED \
                else (max(mu * w * (s - xB), 0.0) if reg != R.SLACK_SEABED else 0.0)
            return [1.0 + T / EA]
        if reg == R.ON_SEABED and HA == 0 and HF > 0:
            reg = R.TOUCHDOWN_SLACK_ANCHOR     # same tension law on the ground
        sol = solve_ivp(ground, (0.0, LB), [0.0], **opts)
        x0 = sol.y[0, -1]
        if reg == R.SLACK_SEABED:
            x0 = x                               # the grounded part lies bunched under the fairlead
        if LB >= L:
            return x0, 0.0
        VA = 0.0
    H = float(r.H_anchor) if LB == 0 else HF

    def air(s, y):
        V = VA + w * s
        T = np.hypot(H, V)
        if T == 0:
            return [0.0, np.sign(w) * 1.0]
        return [H / T * (1 + T / EA), V / T * (1 + T / EA)]
    sol = solve_ivp(air, (0.0, L - LB), [x0, 0.0], **opts)
    return sol.y[0, -1], sol.y[1, -1]


@pytest.mark.parametrize("case", [c for c in CASES if c[8] != R.WEIGHTLESS], ids=[c[0] for c in CASES
                                                                                 if c[8] != R.WEIGHTLESS])
def test_ode_integration_reaches_fairlead(case):
    _, x, z, L, EA, w, mu, seabed, regime = case
    r = catenary(x, z, L, EA, w, mu, seabed)
    xe, ze = _integrate(r, x, z, L, EA, w, mu)
    chord = np.hypot(x, z)
    # DOP853 at rtol 1e-12 is far below 1e-6 of the chord; the kink of |V| at the U's
    # lowest point (vertical cases) is integrated through with a step bounded by rtol too.
    assert abs(xe - x) <= 1e-6 * chord
    assert abs(ze - z) <= 1e-6 * chord


def test_inextensible_limit_matches_textbook_catenary():
    # EA -> inf: x = (H/w)[asinh(VF/H) - asinh(VA/H)], z = (H/w)[cosh(...) - cosh(...)], and
    # the suspended length s = (VF - VA)/w = L exactly; EA = 1e16 N makes the elastic terms
    # (~ T L / EA ~ 1e-9 m) negligible against 1e-9 relative.
    x, z, L, w = 400.0, 250.0, 500.0, 800.0
    r = catenary(x, z, L, 1e16, w, seabed=False)
    H, VF = float(r.H_fairlead), float(r.V_fairlead)
    VA = VF - w * L
    # textbook form: with a = asinh(VA/H), z = (H/w)(cosh(a + w x / H) - cosh a)
    a = np.arcsinh(VA / H)
    check([H / w * (np.cosh(a + w * x / H) - np.cosh(a)), H / w * (np.sinh(a + w * x / H) - np.sinh(a))], [z, L],
          rtol=1e-9, source="Closed form: inextensible catenary", unit="m",
          quantity="height and length from the solved end forces (400 m span, 250 m height, 500 m line)",
          why="EA = 1e16 N makes the elastic terms about 1e-9 m")


def test_taut_limit_matches_straight_elastic_bar():
    # w -> 0 (1e-6 N/m, i.e. w L / T ~ 1e-8): the tension is EA (chord/L - 1) along the chord
    x, z, L, EA = 300.0, 400.0, 499.0, 1e7
    T = EA * (500.0 / L - 1.0)
    r = catenary(x, z, L, EA, 1e-6)
    check([float(r.H_fairlead), float(r.V_fairlead)], [T * x / 500.0, T * z / 500.0], rtol=1e-7, unit="N",
          source="Closed form: straight elastic bar", quantity="taut weightless line's end forces EA (chord/L - 1)",
          why="w L / T ~ 1e-8")
    assert r.regime == R.SUSPENDED


def test_vertical_hanging_line():
    # fairlead straight above the anchor, line hanging free: V_F = w L + V_A and
    # z = L + (V_A L + w L^2 / 2) / EA exactly (closed form, round-off only)
    L, EA, w = 500.0, 1e9, 700.0
    VA = 2000.0
    z = L + (VA * L + w * L * L / 2) / EA
    r = catenary(0.0, z, L, EA, w, seabed=False)
    check(float(r.V_anchor), VA, rtol=1e-9, source="Closed form: vertical hanging line", unit="N",
          quantity="anchor force of a line hanging straight down", why="round-off of the Newton solve")
    check(float(r.V_fairlead), VA + w * L, rtol=1e-12, source="Closed form: vertical hanging line", unit="N",
          quantity="fairlead force V_A + w L", why="round-off only")
    # slack on the seabed: the hanging length carries V_F = w L_s, z = L_s + w L_s^2 / (2 EA)
    r = catenary(50.0, 100.0, 500.0, 1e9, 700.0)
    Ls = float(r.V_fairlead) / 700.0
    assert Ls + 700.0 * Ls ** 2 / 2e9 == pytest.approx(100.0, rel=1e-12)
    assert float(r.grounded_length) == pytest.approx(500.0 - Ls, rel=1e-12)

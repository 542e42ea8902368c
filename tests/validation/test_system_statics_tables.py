"""System statics of lines with a nonlinear axial law (a strain-tension table, MoorDyn's nonlinear EA).

Issue 18: a line type with ``tension_strain`` is solved as the exact elastic catenary with strain
eps(T) (the stretch is the integral of eps(T(s)) along the unstretched length, closed form per piece
of the table), not with the table's secant EA. References:

- a linear table is the constant-EA catenary (the same equations, 1e-10);
- a vertical line hanging a weight, bilinear table: closed form of the stretch,
  int_0^L eps(W + w s) ds = (G(W + w L) - G(W)) / w with G the integral of eps (as
  ``test_nonlinear_axial_stiffness``, which checks the finite elements against it);
- the finite-element statics of the mooring model (lumped masses, straight elements, the same table):
  converges to the catenary at second order in the element length;
- a grounded line with Coulomb friction: the fairlead position by quadrature of the shape ODE
  (dx/ds = (1 + eps(T)) H / T, dz/ds = (1 + eps(T)) V / T, on the seabed T = H - mu w (L_B - s)),
  independent of the closed-form pieces.

The analytic stiffness of a tabled system against central differences is in
``test_system_statics.py`` (the tabled OC3 build).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad

import seacable as sc
from seacable.environment import Environment
from seacable.mooring.network import network_from_line
from seacable.mooring.run import line_end_forces
from seacable.mooring.solver import MooringModel, Water, static_equilibrium
from seacable.statics.catenary import CatenaryProfile
from seacable.system.statics import examples as ex
from seacable.system.statics.catenary import sub_profile
from seacable.system.model import MooringSystem, SystemLine, SystemPoint
from seacable.system.statics import solve_equilibrium

RHO, G = 1025.0, 9.80665


def _line_type(table, weight, ea=None, mass=None):
    return sc.LineType(diameter=0.1, mass_per_length=mass or 1.2 * weight / G, weight_in_water=weight,
                       axial_stiffness=ea, tension_strain=table, drag_normal=0.0, drag_tangential=0.0,
                       added_mass_normal=0.0, added_mass_tangential=0.0)


def _with_type(system, line_type):
    lines = {k: v.model_copy(update={"line": sc.Line.single(line_type, v.line.length)})
             for k, v in system.lines.items()}
    return MooringSystem(points=system.points, bodies=system.bodies, lines=lines)


def _inverse(table):
    strain, tension = np.array(table, float).T
    return lambda T: np.interp(T, tension, strain)


def test_a_linear_table_is_the_constant_ea_catenary():
    """OC3-Hywind with friction 0.5 under a 800 kN surge load: a table (0, 0) - (0.1, 0.1 EA) gives the
    equilibrium, tensions and stiffness of the constant EA. The closed-form pieces reduce to the constant-EA
    terms (eps = T/EA: the asinh part vanishes), so only round-off separates them; both solved to 1e-12:
    1e-10 relative."""
    system, env = ex.oc3_hywind()
    env = env.model_copy(update={"seabed": env.seabed.model_copy(update={"friction": 0.5})})
    ea = ex.OC3_CHAIN.axial_stiffness
    tabled = _with_type(system, ex.OC3_CHAIN.model_copy(update={"tension_strain": ((0.0, 0.0), (0.1, 0.1 * ea))}))
    load = {"platform": [8e5, 2e5, 0.0, 0.0, 0.0, 0.0]}
    e0 = solve_equilibrium(system, env, external=load, tol=1e-12)
    e1 = solve_equilibrium(tabled, env, external=load, tol=1e-12)
    assert e1.body_position[0] == pytest.approx(e0.body_position[0], rel=1e-10, abs=1e-10)
    assert e1.end_a_tension == pytest.approx(e0.end_a_tension, rel=1e-10)
    assert e1.end_b_tension == pytest.approx(e0.end_b_tension, rel=1e-10)
    assert e1.grounded_length == pytest.approx(e0.grounded_length, rel=1e-10)
    assert np.abs(e1.stiffness - e0.stiffness).max() <= 1e-10 * np.abs(e0.stiffness).max()


# the bilinear line of test_nonlinear_axial_stiffness: slope 5.5 MN to strain 0.01 (55 kN), then 20 MN
EPS1, EA1, EA2 = 0.01, 5.5e6, 2.0e7
T1 = EA1 * EPS1
BILINEAR = ((0.0, 0.0), (EPS1, T1), (0.05, T1 + EA2 * (0.05 - EPS1)))


def _G(T):
    """int_0^T eps(t) dt of BILINEAR (T above T1 and within the table)."""
    return T1 * EPS1 / 2 + EPS1 * (T - T1) + (T - T1) ** 2 / (2 * EA2) if T > T1 else T * T / (2 * EA1)


def test_a_vertical_line_with_a_bilinear_table_stretches_as_the_closed_form():
    """A 100 m line of 100 N/m hangs a 50 kN weight (a free point) from a point 10 m down: the lower half
    works on the table's first slope, the upper half on its second. Stretch (G(W + w L) - G(W)) / w =
    0.9835 m (a constant secant EA, 17.1 MN, would give 0.32 m). Newton to 1e-12 of the 60 kN force
    scale moves the weight by ~1e-12 x 60 kN / (EA / L ~ 5e4 N/m) ~ 1e-12 m: 1e-9 relative."""
    W, w, L, top = 50e3, 100.0, 100.0, -10.0
    lt = _line_type(BILINEAR, w)
    system = MooringSystem(points={"top": SystemPoint(kind="fixed", position=(0.0, 0.0, top)),
                                   "weight": SystemPoint(kind="free", position=(0.0, 0.0, top - L),
                                                         mass=W / G)},
                           lines={"l": SystemLine(line=sc.Line.single(lt, L), end_a="weight", end_b="top")})
    eq = solve_equilibrium(system, Environment(water_density=RHO, gravity=G, depth=500.0), tol=1e-12)
    stretch = (_G(W + w * L) - _G(W)) / w
    assert stretch == pytest.approx(0.98352, abs=1e-5)
    z = eq.point_position[eq.point_names.index("weight"), 2]
    assert top - L - z == pytest.approx(stretch, rel=1e-9)
    assert eq.end_b_tension[0] == pytest.approx(W + w * L, rel=1e-12)
    # the profile along the line (from the weight, the lower end): each part's stretch is the closed form
    prof = sub_profile(eq._cat, 0, 5, eq._asm.tables, CatenaryProfile)
    s = np.linspace(0.0, L, 5)
    assert prof.z == pytest.approx([si + (_G(W + w * si) - _G(W)) / w for si in s], abs=1e-9)
    assert prof.tension == pytest.approx(W + w * s, rel=1e-12)


def test_a_tabled_catenary_is_the_limit_of_the_finite_element_statics():
    """A 135 m line of 1000 N/m between (0, 0, -100) and (80, 0, -5) (no seabed), with a table kinked at
    80 kN inside its tension range (37 to 131 kN): the mooring model's finite-element statics (straight
    elements, the same table) converges to the catenary's fairlead force at second order in the element
    length (observed order 2.00 +- 0.02 from 20 to 160 elements; relative error 1e-5 at 160)."""
    table = ((0.0, 0.0), (0.01, 8e4), (0.05, 8e4 + 0.04 * 2e7))
    line = sc.Line.single(_line_type(table, 1000.0), 135.0)
    A, B = (0.0, 0.0, -100.0), (80.0, 0.0, -5.0)
    system = MooringSystem(points={"a": SystemPoint(kind="fixed", position=A),
                                   "b": SystemPoint(kind="fixed", position=B)},
                           lines={"l": SystemLine(line=line, end_a="a", end_b="b")})
    eq = solve_equilibrium(system, Environment(water_density=RHO, gravity=G, depth=None), tol=1e-12)
    ref = eq.end_b_force[0]
    T_a, T_b = eq.end_a_tension[0], eq.end_b_tension[0]
    assert T_a < 8e4 < T_b                  # both pieces of the table are used
    errors = []
    for n in (20, 40, 80, 160):
        start = eq.line_profile("l", n + 1)[0]       # the catenary as the start (the FE needs one that hangs)
        assert start[-1] == pytest.approx(B, abs=1e-9)
        net = network_from_line(line, A, B, water_density=RHO, gravity=G, n_elements=n, initial=start)
        model = MooringModel(net, Water(depth=None, density=RHO, gravity=G))
        st = static_equilibrium(model, tol=1e-12)
        f = line_end_forces(model, st.position)[1]
        errors.append(np.abs(f - ref).max() / np.abs(ref).max())
    order = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert order == pytest.approx(2.0, abs=0.02), errors
    assert errors[-1] < 2e-5


@pytest.mark.parametrize("x_f, kink", [(360.0, 1.0e5), (380.0, 2.0e5)])
def test_a_grounded_tabled_line_with_friction_reaches_its_fairlead_by_quadrature(x_f, kink):
    """A 400 m line of 800 N/m from an anchor on the seabed (100 m deep) to a fixed fairlead at (x_f, 0, -10),
    friction 0.6, table kinked inside the line's tension range: at 360 m friction takes all the tension
    before the anchor (anchor tension 0), at 380 m not (the kink is on the seabed part). From the end
    forces solved, the shape ODE integrated by adaptive quadrature (on the seabed T = max(H - mu w (L_B - s),
    0), then the suspended catenary) lands on the fairlead. Quadrature to 1e-10 m per piece, pieces
    split at the kinks, Newton to 1e-12 of the force scale: 1e-8 m."""
    table = ((0.0, 0.0), (0.005, kink), (0.04, kink + 0.035 * 4e7))
    w, L, mu = 800.0, 400.0, 0.6
    lt = _line_type(table, w)
    env = Environment(water_density=RHO, gravity=G, depth=100.0)
    env = env.model_copy(update={"seabed": env.seabed.model_copy(update={"friction": mu})})
    system = MooringSystem(points={"a": SystemPoint(kind="fixed", position=(0.0, 0.0, -100.0)),
                                   "b": SystemPoint(kind="fixed", position=(x_f, 0.0, -10.0))},
                           lines={"l": SystemLine(line=sc.Line.single(lt, L), end_a="a", end_b="b")})
    eq = solve_equilibrium(system, env, tol=1e-12)
    H, V = -eq.end_b_force[0, 0], -eq.end_b_force[0, 2]
    LB = L - V / w
    T_anchor = max(H - mu * w * LB, 0.0)
    assert 0 < LB < L and T_anchor < kink < eq.end_b_tension[0]
    assert eq.end_a_tension[0] == pytest.approx(T_anchor, rel=1e-12, abs=1e-9 * H)
    eps = _inverse(table)
    # on the seabed: x = int (1 + eps(T)) ds, T = max(H - mu w (LB - s), 0)
    s_k = [LB - (H - t) / (mu * w) for t in (0.0, kink) if T_anchor < t < H]     # kinks, and where T reaches 0
    xg = sum(quad(lambda s: 1 + eps(max(H - mu * w * (LB - s), 0.0)), a, b, epsabs=1e-10, epsrel=1e-12)[0]
             for a, b in zip([0.0] + s_k, s_k + [LB]))
    # suspended: s from the touchdown, V = w s
    T = lambda s: np.hypot(H, w * s)
    s_k = [np.sqrt(t * t - H * H) / w for t in (kink,) if H < t < np.hypot(H, V)]
    bounds = list(zip([0.0] + s_k, s_k + [V / w]))
    xs = sum(quad(lambda s: (1 + eps(T(s))) * H / T(s), a, b, epsabs=1e-10, epsrel=1e-12)[0] for a, b in bounds)
    zs = sum(quad(lambda s: (1 + eps(T(s))) * w * s / T(s), a, b, epsabs=1e-10, epsrel=1e-12)[0] for a, b in bounds)
    assert xg + xs == pytest.approx(x_f, abs=1e-8)
    assert zs == pytest.approx(90.0, abs=1e-8)


def test_a_load_beyond_the_end_of_the_table_has_no_equilibrium():
    """MoorDyn holds the tension flat beyond a table's last point: a static load that needs more has no
    equilibrium (the line yields without end). A 1 MN weight on the bilinear line (table ends at 855 kN), and
    OC3-Hywind pulled by 4 MN on lines whose table ends at 2 MN: a NoSolutionError naming the line, the
    table's last tension and the load, with a fix; just inside the table (a 700 kN weight) it solves."""
    w, L, top = 100.0, 100.0, -10.0
    lt = _line_type(BILINEAR, w)
    env = Environment(water_density=RHO, gravity=G, depth=500.0)

    def hang(weight):
        return MooringSystem(points={"top": SystemPoint(kind="fixed", position=(0.0, 0.0, top)),
                                     "weight": SystemPoint(kind="free", position=(0.0, 0.0, top - L),
                                                           mass=weight / G)},
                             lines={"l": SystemLine(line=sc.Line.single(lt, L), end_a="weight", end_b="top")})

    with pytest.raises(sc.errors.NoSolutionError, match=r"lines\.l: no static equilibrium: the weights.* need a tension of "
                       r"1\.01e\+06 N .* table \(855000 N at strain 0\.05\).*Suggested fix: extend the table"):
        solve_equilibrium(hang(1e6), env)
    eq = solve_equilibrium(hang(7e5), env)
    assert eq.end_b_tension[0] == pytest.approx(7e5 + w * L, rel=1e-9)

    system, env = ex.oc3_hywind()
    short = ex.OC3_CHAIN.model_copy(update={"tension_strain": ((0.0, 0.0), (2e6 / ex.OC3_CHAIN.axial_stiffness, 2e6))})
    with pytest.raises(sc.errors.NoSolutionError, match=r"lines\.line1: no static equilibrium: the external load on "
                       r"platform: \|F\| = 4e\+06 N needs a tension of .* \(2e\+06 N at strain"):
        solve_equilibrium(_with_type(system, short), env, external={"platform": [4e6, 0, 0, 0, 0, 0]})

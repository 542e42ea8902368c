"""Nonlinear axial stiffness (a strain-tension table, MoorDyn's nonlinear EA) in the mooring finite elements.

Issue 18 (MoorDyn decks with an EA table): an element whose line type has ``tension_strain`` takes its
tension from the table, piecewise linear in strain, and the table's slope in its tangent stiffness.
Closed forms: the stretch of a vertical line hanging a weight (exact per element when the table's kink
falls on an element end), the period of a mass on a light spring (``2 pi sqrt(m / k_t)``, with the
line's mass ratio as the only correction), the tangent against a finite difference of the forces, and
a linear table against the constant-EA model.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

import seacable as sc
from seacable.mooring import kernel as K
from seacable.mooring.moordyn import moordyn_model
from seacable.mooring.network import network_from_line
from seacable.mooring.run import line_end_forces
from seacable.mooring.solver import MooringModel, Water, simulate, static_equilibrium

RHO, G = 1025.0, 9.81
TOP = -10.0  # the fixed upper end [m]
LENGTH, N_EL = 100.0, 20  # 5 m elements
W_LINE = 100.0  # line weight in water [N/m]
W_END = 50e3  # the hanging weight [N]
EPS1, EA1, EA2 = 0.01, 5.5e6, 2.0e7  # bilinear: slope EA1 up to strain EPS1 (55 kN), then EA2
T1 = EA1 * EPS1
BILINEAR = ((0.0, 0.0), (EPS1, T1), (0.05, T1 + EA2 * (0.05 - EPS1)))


def _line_type(table, *, ea=None, weight=W_LINE, mass=15.0):
    return sc.LineType(diameter=0.05, mass_per_length=mass, weight_in_water=weight, axial_stiffness=ea,
                       tension_strain=table, drag_normal=0.0, drag_tangential=0.0, added_mass_normal=0.0,
                       added_mass_tangential=0.0)


def _hanging(line_type, *, weight=W_END, mass=0.0, n=N_EL, length=LENGTH):
    """A vertical line from a fixed point at z = TOP, its lower end free and carrying ``weight``."""
    line = sc.Line.single(line_type, length,
                          attachments=(sc.PointMass(s=length, mass=mass, weight_in_water=weight),))
    net = network_from_line(line, (0, 0, TOP), (0, 0, TOP - length), water_density=RHO, gravity=G,
                            n_elements=n, end_b="free")
    return MooringModel(net, Water(depth=None, density=RHO, gravity=G))


def _closed_form_stretch():
    """Stretch of the continuous line: the integral of eps(T(s)) with T = W + w s, s up from the weight.

    Below s1 = (T1 - W) / w the strain is T / EA1, above it EPS1 + (T - T1) / EA2. Both pieces are
    linear in s, and s1 = 50 m is an element end: the lumped model (each element at its middle
    tension) integrates them exactly (midpoint rule on a linear integrand).
    """
    s1 = (T1 - W_END) / W_LINE
    assert s1 == pytest.approx(50.0) and s1 % (LENGTH / N_EL) == pytest.approx(0.0)
    lower = (W_END * s1 + W_LINE * s1**2 / 2) / EA1
    upper = EPS1 * (LENGTH - s1) + W_LINE * (LENGTH - s1) ** 2 / 2 / EA2
    return lower + upper


def test_a_hanging_weight_stretches_a_bilinear_line_as_the_table_says():
    """W = 50 kN on a 100 m line of 100 N/m: the lower half on the table's first slope (5.5 MN), the
    upper half on its second (20 MN). Closed-form stretch 0.9835 m; a constant EA (the table's secant
    at its end, 17.1 MN) would stretch it 0.32 m, the first slope alone 1.0 m.
    """
    model = _hanging(_line_type(BILINEAR))
    st = static_equilibrium(model, tol=1e-12)
    stretch = TOP - st.position[-1, 2] - LENGTH
    # the discrete model is exact here (see _closed_form_stretch); the force tolerance 1e-12 of 60 kN
    # moves the end by < 1e-12 m, and round-off in coordinates of 100 m is ~1e-14 m: 1e-6 is far above
    # both and far below a wrong slope or a wrong piece of the table (errors of tens of percent)
    assert stretch == pytest.approx(_closed_form_stretch(), rel=1e-6)
    # each element's tension is the weight below its middle (statically determinate)
    k = np.arange(1, N_EL + 1)  # elements counted from the weight up
    expected = W_END + W_LINE * LENGTH / N_EL * (k - 0.5)
    tension = model.evaluate(st.position, 0 * st.position, 0 * st.position)[2][::-1]
    assert tension == pytest.approx(expected, rel=1e-9)


def test_a_linear_table_is_the_constant_ea_model():
    """The table (0, 0), (1, EA) is Hooke's law up to 100 % strain: the same equilibrium as EA, to round-off."""
    ea = 2.0e7
    for make in (lambda lt: _hanging(lt),
                 lambda lt: MooringModel(network_from_line(sc.Line.single(lt, 902.2), (0, 0, -320),
                                                           (848.67, 0, -70), water_density=RHO, gravity=G,
                                                           n_elements=40),
                                         Water(depth=320.0, density=RHO, gravity=G))):
        lin = static_equilibrium(make(_line_type(None, ea=ea)), tol=1e-10)
        tab = static_equilibrium(make(_line_type(((0.0, 0.0), (1.0, ea)), ea=ea)), tol=1e-10)
        # the table's tension is 0 + (ea / 1) (eps - 0) = ea eps bit for bit, and its slope ea: the same
        # Newton iterates; 1e-12 m on coordinates of ~1e3 m allows for a few ulps of round-off
        assert np.max(np.abs(tab.position - lin.position)) < 1e-12 * 1e3
        assert tab.tension == pytest.approx(lin.tension, rel=1e-12, abs=1e-9)


def _full_tangent(model, X):
    """-dF/dx at the free nodes assembled by the kernel (band storage unpacked). [N/m]"""
    n = model.network.n_nodes
    nd = 3 * model.nfree
    band = np.zeros((nd, 2 * model.bw + 1))
    F, M, T = np.zeros((n, 3)), np.zeros((n, 3, 3)), np.zeros(model.network.n_elements)
    K.loads(X, np.zeros_like(X), 0.0, *model.element_args(), model.fidx, model.env, model.cur_depth,
            model.cur_speed, False, model.sea, F, M, T, band, model.bw, 0.0, 0.0)
    full = np.zeros((nd, nd))
    for r in range(nd):
        for c in range(max(0, r - model.bw), min(nd, r + model.bw + 1)):
            full[r, c] = band[r, model.bw + c - r]
    return full, F


def test_the_tangent_of_a_tabled_element_is_the_tables_slope():
    """The Newton matrix of a stretched, tilted line equals a central difference of the node forces.

    Three elements, strains 1.2 %, 3 % and 4 % (both pieces of the table, below and above its kink),
    moved off the vertical so that the geometric stiffness T / l enters too. A tangent with the
    secant EA instead of the table's slope is off by 15 % (EA2) to 200 % (EA1) along the element.
    """
    model = _hanging(_line_type(BILINEAR, weight=0.0), weight=0.0, n=3, length=30.0)
    X = np.array([[0, 0, TOP], [1.0, 0.5, TOP - 10.12], [2.5, 0.2, TOP - 20.42], [3.0, 1.4, TOP - 30.85]])
    full, _ = _full_tangent(model, X)
    free = np.flatnonzero(model.fidx >= 0)
    h = 1e-6  # strain steps of 1e-7, far from the kink: the central difference of a piecewise-linear law is exact
    fd = np.zeros_like(full)
    for i in free:
        for r in range(3):
            Xp, Xm = X.copy(), X.copy()
            Xp[i, r] += h
            Xm[i, r] -= h
            Fp = model.evaluate(Xp, 0 * X, 0 * X)[0]
            Fm = model.evaluate(Xm, 0 * X, 0 * X)[0]
            col = 3 * model.fidx[i] + r
            for j in free:
                fd[3 * model.fidx[j]:3 * model.fidx[j] + 3, col] = -(Fp[j] - Fm[j]) / (2 * h)
    # round-off of the difference: 1e-16 * 6e5 N / 1e-6 m ~ 1e-4 N/m against entries of ~1e6 N/m
    assert full == pytest.approx(fd, rel=1e-6, abs=1e-6 * np.max(np.abs(fd)))


def test_a_mass_on_a_nonlinear_line_oscillates_with_the_tables_tangent_stiffness():
    """A 10 t mass (98.1 kN) on a 50 m neutrally buoyant line: static strain 0.01 + (98.1 - 55) / 20000
    = 3.2 %, on the table's second piece, so the small-oscillation period is 2 pi sqrt(m L / EA2) = 1.571 s
    (the secant at the table's end, 17.1 MN, would give 1.70 s; the first slope 3.00 s).
    """
    mass, length, n = 10e3, 50.0, 10
    mpl = 0.2  # the line's mass is 10 kg, a ratio mu = 1e-3 of the mass
    model = _hanging(_line_type(BILINEAR, weight=0.0, mass=mpl), weight=mass * G, mass=mass, n=n, length=length)
    st = static_equilibrium(model, tol=1e-12)
    strain = (TOP - st.position[-1, 2]) / length - 1
    assert strain == pytest.approx(EPS1 + (mass * G - T1) / EA2, rel=1e-9)
    period = 2 * math.pi * math.sqrt(mass * length / EA2)
    x0 = st.position.copy()
    x0[1:, 2] -= 1e-3 * np.arange(1, n + 1) / n  # 1 mm down at the mass: a strain change of 2e-5, far from the kink
    run = simulate(model, None, 4 * period, period / 400, period / 400, initial=x0, tol=1e-10)
    z = run.position[:, -1, 2] - st.position[-1, 2]
    k = np.flatnonzero(np.diff(np.sign(z)) != 0)
    tz = run.time[k] - z[k] * (run.time[k + 1] - run.time[k]) / (z[k + 1] - z[k])
    observed = 2 * np.mean(np.diff(tz))
    # the line's own mass lengthens the period by about mu / 6 = 1.7e-4 (Rayleigh's m + m_line / 3),
    # Newmark by (omega dt)^2 / 12 = 2e-5, the zero-crossing interpolation by ~4e-5: 1e-3 covers them and
    # is 1/80 of the 8 % of the secant EA
    assert observed == pytest.approx(period, rel=1e-3)


DECK = Path(__file__).parent / "data" / "nonlinear_ea" / "polyester_table.txt"
MOORDYN = json.loads((DECK.parent / "moordyn_reference.json").read_text())


def test_a_moordyn_deck_with_an_ea_table_agrees_with_moordyn():
    """The polyester deck of MoorDyn's tests with its EA as a 4-piece strain-tension table (slopes 150 to
    350 MN), solved on the network path: the fairlead tension against MoorDyn 2.7.2's initial condition
    (``moordyn_reference.json``, written as the live test below does): its dynamic relaxation over 150 s,
    whose fairlead tension then changes by 3e-6 from check to check and is within 0.02 % of where it comes
    to rest (1.22504 MN after 1000 s; see ``data/nonlinear_ea/README.md``).

    None of the vendored decks can serve: the only ones with a table (syrope/*) are refused by MoorDyn
    2.7.2 and by MoorPy. The constant EA the network used before (the table's secant at its end,
    333 MN) gives 1.52 MN, 25 % above MoorDyn's 1.22 MN.
    """
    model = moordyn_model(DECK)
    assert model.network.element_tension_strain[0][2] == (0.004, 9.0e5)
    st = static_equilibrium(model)
    fair = np.linalg.norm(line_end_forces(model, st.position)[1])
    ref = MOORDYN["lines"]["1"]["fair_ten"]
    assert MOORDYN["ic_converged"]
    assert MOORDYN["ic_tension_change"] < 1e-5  # MoorDyn's relaxation had come to rest
    # 1 %: the agreement target for decks; the constant-EA polyester deck agrees to 0.003 %, this
    # one to 0.015 % (MoorDyn's two ends' horizontal forces differ by 2e-5, and the lumped models place the
    # seabed touchdown differently)
    assert fair == pytest.approx(ref, rel=0.01)


def test_moordyn_live_reads_the_same_table():
    """The cached MoorDyn numbers are MoorDyn's: run MoorDyn 2.7.2 on the deck here (about 3 s: 150 s of its
    dynamic relaxation; the stationary solver it had before took 2000 s and 18 s, and stopped 0.24 % short of
    rest)."""
    pytest.importorskip("moordyn")
    import importlib.util

    script = Path(__file__).parent / "data" / "moordyn_decks" / "make_reference.py"
    spec = importlib.util.spec_from_file_location("make_reference", script)
    m = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(m)
    # MoorDyn runs in its own process (make_reference's child) as before; MoorPy, which this test does not
    # read, is left out
    live = m.run(DECK, moorpy=False)
    # the same code and input: MoorDyn is deterministic, 1e-6 allows for a different build's round-off
    assert live["lines"]["1"]["fair_ten"] == pytest.approx(MOORDYN["lines"]["1"]["fair_ten"], rel=1e-6)


def test_the_system_model_hangs_the_weight_on_the_table_too():
    """The same hanging line as a mooring system (a fixed point, a free point with the 50 kN weight as a
    point mass of 50e3 / g kg with no volume), solved by the coupled system kernel: the closed-form stretch.
    """
    from seacable.environment import Environment
    from seacable.system.dynamics import build_system_fe, static_system
    from seacable.system.model import MooringSystem

    system = MooringSystem(
        points={"top": {"kind": "fixed", "position": (0.0, 0.0, TOP)},
                "end": {"kind": "free", "position": (0.0, 0.0, TOP - LENGTH), "mass": W_END / G}},
        lines={"l": {"line": sc.Line.single(_line_type(BILINEAR), LENGTH), "end_a": "top", "end_b": "end",
                     "n_elements": N_EL}})
    fe = build_system_fe(system, Environment(depth=1000.0, water_density=RHO, gravity=G))
    st = static_system(fe, tol=1e-12)
    end = fe.model.network.line_nodes[0][-1]
    # as above: the discrete model is exact, the solver's tolerance and round-off are below 1e-9 m
    assert TOP - st.position[end, 2] - LENGTH == pytest.approx(_closed_form_stretch(), rel=1e-6)


@pytest.mark.parametrize("strain, expected", [
    (0.03, T1 + EA2 * 0.02),  # inside: linear between the points (475 kN)
    (EPS1, T1),  # on the kink
    (0.08, BILINEAR[-1][1]),  # beyond the table: held at its last tension (MoorDyn's interp clamps)
    (-0.01, 0.0),  # compression: no tension
])
def test_an_element_follows_moordyns_table_convention(strain, expected):
    """One weightless element between a fixed and a held node, stretched to ``strain``: its tension is the
    table's value by MoorDyn's convention (``Line::getNonlinearEA``: interpolation, clamped beyond the
    last point, zero in compression)."""
    lt = _line_type(BILINEAR, weight=0.0)
    net = network_from_line(sc.Line.single(lt, 10.0), (0, 0, -50.0), (10.0 * (1 + strain), 0, -50.0),
                            water_density=RHO, gravity=G, n_elements=1)
    model = MooringModel(net, Water(depth=None, density=RHO, gravity=G))
    X = net.position
    tension = model.evaluate(X, 0 * X, 0 * X)[2][0]
    # the slack rounding acts only within |strain| < 1e-8 here (a massless-looking element: 15 kg/m), and
    # round-off of l / L - 1 is ~1e-16: 1e-9 relative (1e-3 N absolute at zero) is far below any table error
    assert tension == pytest.approx(expected, rel=1e-9, abs=1e-3)

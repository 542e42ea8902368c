"""Sections along a line (seacable.sections): buoyancy sections smeared or discrete, bend stiffeners.

The mapping onto the finite-element line's per-element arrays is checked against closed forms (the smeared
per-length properties, the stiffener's EI at the elements' mid arc lengths, a neutrally buoyant cable hanging
straight), and the two representations of one buoyancy section against each other.
"""

import math
from pathlib import Path

import numpy as np
import pytest

import seacable as sc
from seacable.errors import InputError
from seacable.line import resolve_sections
from seacable.mooring.network import network_from_line
from seacable.sections import BendStiffener, BuoyancyModule, BuoyancySection, Cone

RHO, G = 1025.0, 9.80665
CABLE = sc.LineType(name="cable", diameter=0.16, mass_per_length=36.70, axial_stiffness=4.69e8,
                    bending_stiffness=1.99e4, drag_normal=1.2, drag_tangential=0.1, added_mass_normal=1.0)
MODULE = BuoyancyModule(length=1.5, diameter=0.9, mass=120.0, net_buoyancy=2500.0, drag_normal=1.1, drag_axial=0.8,
                        added_mass=0.7)


def _line(*sections, length=170.0, n=None):
    return sc.Line(segments=(sc.Segment(line_type=CABLE, length=length, n_elements=n),), sections=sections)


def _net(line, h=0.5):
    return network_from_line(line, (0, 0, -80.0), (120.0, 0, -14.0), water_density=RHO, gravity=G,
                             element_length=h)


def test_smeared_section_per_length_properties_are_the_cable_plus_the_modules_over_the_pitch():
    # closed forms: net weight w + W_m / p (W_m = -net buoyancy), mass m + m_m / p, added mass
    # Ca rho A + Cm rho V / p, normal drag area Cd d + Cd_m (D_m - d) L_m / p, axial pi Cdt d + Cda_m pi/4 (D^2-d^2) / p
    sec = BuoyancySection(start=50.0, length=40.0, pitch=4.0, module=MODULE)
    net = _net(_line(sec))
    mid = 0.5 * (net.arc_length[:-1] + net.arc_length[1:])
    inside, outside = (mid > 50.0) & (mid < 90.0), (mid < 50.0) | (mid > 90.0)
    p, d, a = 4.0, CABLE.diameter, CABLE.area
    vol = (2500.0 / G + 120.0) / RHO
    w_cable = (CABLE.mass_per_length - RHO * a) * G
    expected = {
        "weight_per_length": w_cable - 2500.0 / p,
        "mass_per_length": CABLE.mass_per_length + 120.0 / p,
        "added_mass": RHO * (1.0 * a + 0.7 * vol / p),
        "drag_normal": 1.2 * d + 1.1 * (0.9 - d) * 1.5 / p,
        "drag_axial": math.pi * 0.1 * d + 0.8 * math.pi / 4 * (0.9**2 - d**2) / p,
        "area": a + vol / p,
    }
    got = {
        "weight_per_length": net.weight_per_length, "mass_per_length": net.mass_per_length,
        "added_mass": net.can * RHO * math.pi / 4 * net.diameter**2, "drag_normal": net.cdn * net.diameter,
        "drag_axial": math.pi * net.cdt * net.diameter, "area": math.pi / 4 * net.diameter**2,
    }
    for key, value in expected.items():
        # the same sums in another order: rounding only
        np.testing.assert_allclose(got[key][inside], value, rtol=1e-12, err_msg=key)
    np.testing.assert_allclose(net.weight_per_length[outside], w_cable, rtol=1e-12)
    # nodes at the section's ends, so that no element straddles them
    assert np.min(np.abs(net.arc_length - 50.0)) < 1e-9 and np.min(np.abs(net.arc_length - 90.0)) < 1e-9
    # the bending stiffness over the section is the cable's
    np.testing.assert_array_equal(net.bending_stiffness, CABLE.bending_stiffness)


def test_discrete_modules_are_attachments_at_their_centres_with_the_smeared_totals():
    sec = BuoyancySection(start=50.0, length=40.0, pitch=4.0, module=MODULE, representation="discrete")
    net = _net(_line(sec))
    centres = 50.0 + (np.arange(10) + 0.5) * 4.0
    loaded = np.flatnonzero(net.point_weight)
    np.testing.assert_allclose(net.arc_length[loaded], centres, atol=1e-9)
    np.testing.assert_allclose(net.point_weight[loaded], -2500.0, rtol=1e-12)
    np.testing.assert_allclose(net.point_drag_area[loaded], 1.1 * (0.9 - 0.16) * 1.5, rtol=1e-12)
    np.testing.assert_allclose(net.point_axial_drag_area[loaded], 0.8 * math.pi / 4 * (0.9**2 - 0.16**2),
                               rtol=1e-12)
    # totals over the section equal the smeared section's
    smeared = _net(_line(sec.model_copy(update={"representation": "smeared"})))
    total = lambda n: float(np.sum(n.weight_per_length * n.length) + np.sum(n.point_weight))
    assert total(net) == pytest.approx(total(smeared), rel=1e-12)
    mass = lambda n: float(np.sum(n.mass_per_length * n.length) + np.sum(n.point_mass))
    assert mass(net) == pytest.approx(mass(smeared), rel=1e-12)
    # and so are the added mass and the drag areas across and along (the dynamics see the same modules)
    def added(n):
        return float(np.sum(n.can * RHO * math.pi / 4 * n.diameter**2 * n.length) + np.sum(n.point_added_mass))

    def across(n):
        return float(np.sum(n.cdn * n.diameter * n.length) + np.sum(n.point_drag_area))

    def along(n):
        axial = n.point_drag_area if n.point_axial_drag_area is None else n.point_axial_drag_area
        return float(np.sum(math.pi * n.cdt * n.diameter * n.length) + np.sum(axial))

    for quantity in (added, across, along):
        assert quantity(net) == pytest.approx(quantity(smeared), rel=1e-12), quantity.__name__


def _static(line, anchor, fairlead, depth=200.0, h=1.0):
    case = sc.Case(name="t", line=line, environment=sc.Environment(depth=depth, water_density=RHO, gravity=G),
                   analysis=sc.MooringStaticAnalysis(anchor=anchor, fairlead=fairlead, element_length=h))
    return sc.run(case)


def test_neutrally_buoyant_section_hangs_straight_between_two_points_under_tension():
    # modules whose net buoyancy per pitch is exactly the cable's weight over the pitch: weight 0 per length,
    # so the cable is straight between two ends at one depth, at the tension EA (chord / L - 1)
    p = 5.0
    w = (CABLE.mass_per_length - RHO * CABLE.area) * G
    mod = BuoyancyModule(length=2.0, diameter=0.6, mass=80.0, net_buoyancy=w * p)
    line = _line(BuoyancySection(start=0.0, length=100.0, pitch=p, module=mod), length=100.0)
    ds = _static(line, (0.0, -100.0), (100.05, -100.0))
    # straight to the solver's tolerance (1e-8 of the forces): a 1e-6 m sag would take a weight of 1e-2 N/m
    assert np.max(np.abs(ds.z.values + 100.0)) < 1e-6
    assert float(ds.fairlead_tension) == pytest.approx(4.69e8 * 0.05 / 100.0, rel=1e-6)


def test_discrete_and_smeared_sections_give_the_same_static_lazy_wave():
    base = sc.load_case(Path(__file__).parents[2] / "examples" / "lazy_wave_80m.yaml")

    def run(rep, h):
        sec = base.line.sections[0].model_copy(update={"representation": rep})
        return sc.run(base.model_copy(update={
            "line": base.line.model_copy(update={"sections": (sec,)}),
            "analysis": base.analysis.model_copy(update={"element_length": h})}))

    smeared, discrete = run("smeared", 0.5), run("discrete", 0.5)
    s = smeared.s.values
    gap = np.hypot(smeared.x.values - np.interp(s, discrete.s.values, discrete.x.values),
                   smeared.z.values - np.interp(s, discrete.s.values, discrete.z.values))
    # Ten modules of 1190 N lift at 5 m against the smeared 80 N/m: the difference is a zero-mean periodic load
    # (238 N/m down between modules), which bends the 19.9 kN m^2 cable between modules by about
    # w p^4 / (384 EI) = 0.02 m and shifts the arch by a few of that; measured 0.053 m at 0.5 m and 0.25 m
    # elements alike (the difference is the modules', not the mesh's). CableDyn's own comparison of its two decks
    # (in a current): all nodes within 0.035 m. A module misplaced by half a pitch moves the arch by 0.2 m.
    assert gap.max() < 0.1
    # the hang-off tension: 9320.1 against 9323.8 N (0.04 %)
    assert float(discrete.fairlead_tension) == pytest.approx(float(smeared.fairlead_tension), rel=1e-3)


def test_bend_stiffener_adds_its_tapered_ei_at_the_elements_mid_arc_length():
    table = ((0.0, 4.0e5), (1.0, 2.0e5), (4.0, 0.0))
    stiff = BendStiffener(end="B", length=4.0, table=table)
    net = _net(_line(stiff, length=170.0), h=0.25)
    mid = 0.5 * (net.arc_length[:-1] + net.arc_length[1:])
    x = 170.0 - mid  # from the root at end B
    expected = CABLE.bending_stiffness + np.where(x <= 4.0, np.interp(x, *np.array(table).T), 0.0)
    np.testing.assert_allclose(net.bending_stiffness, expected, rtol=1e-12)
    # a node at the tip
    assert np.min(np.abs(net.arc_length - 166.0)) < 1e-9
    # a cone: E pi / 64 (D(x)^4 - d^4), D linear from root to tip
    cone = BendStiffener(end="A", length=3.0, cone=Cone(root_diameter=0.6, tip_diameter=0.2, modulus=5.0e7))
    net = _net(_line(cone), h=0.25)
    mid = 0.5 * (net.arc_length[:-1] + net.arc_length[1:])
    on = mid <= 3.0
    dia = 0.6 - 0.4 * mid[on] / 3.0
    np.testing.assert_allclose(net.bending_stiffness[on],
                               CABLE.bending_stiffness + 5.0e7 * math.pi / 64 * (dia**4 - 0.16**4), rtol=1e-12)
    np.testing.assert_array_equal(net.bending_stiffness[~on], CABLE.bending_stiffness)


def test_a_line_without_sections_is_its_own_equivalent():
    line = _line()
    assert resolve_sections(line, RHO, G) is line


@pytest.mark.parametrize("make, message", [
    (lambda: _line(BuoyancySection(start=0.0, length=200.0, pitch=5.0, module=MODULE)),
     "200 m long, longer than the line (170 m)"),
    (lambda: _line(BuoyancySection(start=150.0, length=40.0, pitch=5.0, module=MODULE)),
     "beyond the end of the line at 170 m. Suggested fix: start it at s <= 130 m"),
    (lambda: sc.Line(segments=(sc.Segment(line_type=CABLE, length=3.0), sc.Segment(line_type=CABLE, length=167.0)),
                     sections=(BendStiffener(end="A", length=4.0, table=((0, 1e5), (4, 0))),)),
     "bend stiffener at end A is 4 m long, longer than the segment it sits on (line.segments[0], 3 m)"),
    (lambda: resolve_sections(_line(BuoyancySection(start=0.0, length=170.0, pitch=2.0, module=MODULE)), RHO, G),
     "would float the whole cable"),
    (lambda: _net(_line(BendStiffener(end="B", length=2.0, table=((0, 1e5), (2, 0)))), h=1.0),
     "elements of at most 0.5 m"),
    (lambda: BuoyancySection(start=0.0, length=12.0, pitch=5.0, module=MODULE), "whole number of pitches"),
    (lambda: BuoyancyModule(length=1.0, diameter=1.0, mass=10.0), "exactly one of 'volume'"),
])
def test_bad_sections_get_one_clear_message(make, message):
    with pytest.raises((InputError, ValueError)) as err:
        make()
    assert message in str(err.value)
    assert "Suggested fix" in str(err.value)


def test_floating_cable_says_by_how_much_and_validate_refuses_it():
    line = _line(BuoyancySection(start=0.0, length=170.0, pitch=2.0, module=MODULE))
    w = (CABLE.mass_per_length - RHO * CABLE.area) * G
    short = 85 * 2500.0 - 170.0 * w  # the lift less the cable's weight [N]
    with pytest.raises(InputError) as err:
        resolve_sections(line, RHO, G)
    assert f"{-short:.6g} N" in str(err.value)
    with pytest.raises(InputError, match="would float the whole cable"):
        sc.Case(name="t", line=line, environment=sc.Environment(depth=200.0, water_density=RHO, gravity=G),
                analysis=sc.MooringStaticAnalysis(fairlead=(120.0, -14.0)))


def test_an_invalid_line_type_is_reported_once_not_as_a_floating_cable():
    # the line type that stands in for an invalid one during validation (1 m diameter, 1 kg/m) floats; the cable
    # must not be reported floating for it, only the line type's own problem
    data = {"name": "t", "line_types": {"cable": {**CABLE.model_dump(exclude={"name"}), "minimum_bend_radius": 0.0}},
            "line": {"segments": [{"line_type": "cable", "length": 170.0}],
                     "sections": [{"type": "buoyancy", "start": 50.0, "length": 40.0, "pitch": 4.0,
                                   "module": MODULE.model_dump()}]},
            "environment": {"depth": 200.0}, "analysis": {"type": "mooring_static", "fairlead": [120.0, -14.0]}}
    with pytest.raises(InputError) as err:
        sc.Case.parse(data)
    assert "line_types.cable.minimum_bend_radius must be > 0 m" in str(err.value)
    assert "float" not in str(err.value)


def test_analyses_without_the_finite_element_line_refuse_sections():
    line = _line(BuoyancySection(start=50.0, length=40.0, pitch=4.0, module=MODULE))
    with pytest.raises(InputError, match="does not take line.sections"):
        sc.Case(name="t", line=line, environment=sc.Environment(depth=200.0),
                analysis=sc.StaticAnalysis(fairlead=(120.0, -14.0)))


def test_mesh_too_coarse_for_the_stiffener_is_refused_by_validate():
    line = _line(BendStiffener(end="B", length=2.0, cone=Cone(root_diameter=0.5, tip_diameter=0.2, modulus=5e7)))
    case = sc.Case(name="t", line=line, environment=sc.Environment(depth=80.0, water_density=RHO, gravity=G),
                   analysis=sc.MooringStaticAnalysis(anchor=(0.0, -80.0), fairlead=(120.0, -14.0), element_length=1.0))
    with pytest.raises(InputError, match="too coarse for the bend stiffener"):
        sc.check(case)


def test_system_lines_take_sections_as_the_single_line_does():
    # issue 40: a system line's sections are resolved onto its finite-element line by the single line's own
    # network_from_line (the same nodes: one at each section's end), and the catenary statics refuse them
    from seacable.mooring.network import network_from_line
    from seacable.system.dynamics import build_system_fe
    from seacable.system.model import MooringSystem, SystemLine, SystemPoint
    from seacable.system.statics import solve_equilibrium

    line = _line(BuoyancySection(start=50.0, length=40.0, pitch=4.0, module=MODULE))
    system = MooringSystem(points={"a": SystemPoint(kind="fixed", position=(0.0, 0.0, -100.0)),
                                   "b": SystemPoint(kind="fixed", position=(150.0, 0.0, -20.0))},
                           lines={"c": SystemLine(line=line, end_a="a", end_b="b", n_elements=40)})
    env = sc.Environment(depth=100.0)
    fe = build_system_fe(system, env)
    single = network_from_line(line, (0.0, 0.0, -100.0), (150.0, 0.0, -20.0), water_density=env.water_density,
                               gravity=env.gravity, n_elements=40)
    els = fe.line_elements[0]
    assert np.array_equal(fe.model.network.length[els], single.length)
    assert np.array_equal(fe.model.network.weight_per_length[els], single.weight_per_length)
    with pytest.raises(InputError, match="cannot carry a line 'c' with sections"):
        solve_equilibrium(system, env)


def test_stiffened_beam_deflects_as_euler_bernoulli_with_the_tapered_ei():
    # A 10 m beam pinned at both ends, level, under 10 N/m, EI 1e5 N m^2, with a stiffener over its last 3 m whose
    # own EI falls linearly from 1e5 at the root to 0 at the tip. Unit-load method (simply supported, small
    # deflection): delta_mid = int M(x) m(x) / EI(x) dx, M = w x (L - x) / 2, m = min(x, L - x) / 2:
    # 0.0126881 m (0.0130208 m, 5 w L^4 / 384 EI, without the stiffener: 2.6 % more).
    from scipy.integrate import quad

    L, w, EI = 10.0, 10.0, 1.0e5
    table = ((0.0, 1.0e5), (3.0, 0.0))
    exact = quad(lambda x: w * x * (L - x) / 2 * min(x, L - x) / 2
                 / (EI + (np.interp(L - x, *np.array(table).T) if L - x <= 3.0 else 0.0)),
                 0.0, L, points=[5.0, 7.0], limit=200)[0]
    beam = sc.LineType(diameter=0.05, mass_per_length=2.0, weight_in_water=w, axial_stiffness=1.0e5,
                       bending_stiffness=EI)
    line = sc.Line(segments=(sc.Segment(line_type=beam, length=L, n_elements=40),),
                   sections=(BendStiffener(end="B", length=3.0, table=table),))
    ds = sc.run(sc.Case(name="beam", line=line, environment=sc.Environment(depth=100.0),
                        analysis=sc.MooringStaticAnalysis(anchor=(0.0, -50.0), fairlead=(L, -50.0), tolerance=1e-6)))
    sag = -50.0 - float(np.interp(L / 2, ds.s.values, ds.z.values))
    # measured +0.036 % on 20 elements, +0.005 % on 40, -0.001 % on 80 (the hinge bending converges to the beam);
    # the membrane tension of a 2.7e-6 strain and the Newton tolerance are each below 0.01 %: 0.05 %
    assert sag == pytest.approx(exact, rel=5e-4)

"""Moment-curvature laws (seacable.moment_curvature): the table's checks, and the law's moment, slope, energy and sums
against closed forms; bad laws, restrictors and stiffeners get one clear message each, in ``validate`` too."""

from __future__ import annotations

import numpy as np
import pytest
import yaml

import seacable as sc
from seacable.cli import main
from seacable.errors import InputError
from seacable.moment_curvature import (
    check_table,
    law_energy,
    law_moment,
    law_slope,
    law_sum,
    linear_law,
    lock_law,
)
from seacable.sections import BendRestrictor, BendStiffener, Cone

BILINEAR = ((0.0, 0.0), (0.1, 2000.0), (0.5, 4000.0))   # 20000 then 5000 N m^2


def test_bilinear_law_moment_slope_and_energy():
    """M, dM/dkappa and W = integral M dk of the bilinear law at curvatures on both pieces, beyond the table (its
    last slope) and negative (odd; W even): closed forms, to rounding."""
    k = np.array([0.05, 0.1, 0.3, 0.7, -0.3])
    m = np.array([1000.0, 2000.0, 3000.0, 5000.0, -3000.0])
    wy = 0.5 * 2e4 * 0.1**2   # 100 J/m at the knot
    w = np.array([0.5 * 2e4 * 0.05**2, wy, wy + 2000 * 0.2 + 0.5 * 5000 * 0.2**2,
                  wy + 2000 * 0.6 + 0.5 * 5000 * 0.6**2, wy + 2000 * 0.2 + 0.5 * 5000 * 0.2**2])
    assert law_moment(BILINEAR, k) == pytest.approx(m, rel=1e-14)
    assert law_slope(BILINEAR, k) == pytest.approx([2e4, 5e3, 5e3, 5e3, 5e3], rel=1e-14)
    assert law_energy(BILINEAR, k) == pytest.approx(w, rel=1e-14)


def test_law_sum_and_lock_law():
    """A cable's EI plus a restrictor locking at R = 4 m with k = 1e6 N m^2: EI kappa below 0.25 1/m, then
    EI kappa + k (kappa - 0.25), on the knots' union and beyond."""
    law = law_sum([linear_law(1e4), lock_law(4.0, 1e6)])
    k = np.array([0.1, 0.25, 0.3, 2.0])
    assert law_moment(law, k) == pytest.approx(1e4 * k + 1e6 * np.maximum(k - 0.25, 0.0), rel=1e-14)


def test_full_odd_table_is_its_positive_half():
    full = ((-0.5, -4000.0), (-0.1, -2000.0), (0.0, 0.0), (0.1, 2000.0), (0.5, 4000.0))
    assert check_table(full, "t") == BILINEAR


_LT = {"diameter": 0.15, "mass_per_length": 40.0, "axial_stiffness": 5e8}


def _cone_with_law():
    from seacable.mooring.network import network_from_line

    cone = Cone(root_diameter=0.4, tip_diameter=0.2, modulus=5e7)   # root EI 5e7 pi / 64 (0.4^4 - 0.15^4) = 61,589 N m^2
    stiffener = BendStiffener(length=4.0, cone=cone, moment_curvature=((0, 0), (0.1, 600.0)))
    line = sc.Line(segments=(sc.Segment(line_type=sc.LineType(**_LT, bending_stiffness=1e4), length=20.0),),
                   sections=(stiffener,))
    return network_from_line(line, (0, 0, -30), (15, 0, -5), water_density=1025.0, gravity=9.81, element_length=0.5)


@pytest.mark.parametrize("make, message", [
    (lambda: sc.LineType(**_LT, moment_curvature=((0, 0), (0.1, 2000), (0.2, 1500))), "the law must be monotone"),
    (lambda: sc.LineType(**_LT, moment_curvature=((-0.1, -1000), (0, 0), (0.1, 2000))), "is not odd"),
    (lambda: sc.LineType(**_LT, moment_curvature=((0.01, 100), (0.1, 2000))), "must start at (0, 0)"),
    (lambda: sc.LineType(**_LT, moment_curvature=((0, 0),)), "at least 2 (curvature [1/m], moment [N m]) pairs"),
    (lambda: sc.LineType(**_LT, bending_stiffness=2e3, moment_curvature=BILINEAR),
     "moment_curvature starts at slope M/kappa = 20000 N m^2, but bending_stiffness is 2000 N m^2"),
    (lambda: BendRestrictor(length=3.0, locking_radius=0.0, diameter=0.3), "must be > 0 m, got 0 m"),
    (lambda: BendRestrictor(length=3.0, locking_radius=-2.0, diameter=0.3), "must be > 0 m, got -2 m"),
    (lambda: sc.Line(segments=(sc.Segment(line_type=sc.LineType(**_LT), length=2.0),
                               sc.Segment(line_type=sc.LineType(**_LT), length=50.0)),
                     sections=(BendRestrictor(end="A", length=3.0, locking_radius=2.0, diameter=0.3),)),
     "bend restrictor at end A is 3 m long, longer than the segment it sits on (line.segments[0], 2 m)"),
    (lambda: BendStiffener(length=4.0, table=((0, 2e5), (4, 1e3)), density=1150.0), "no geometry for its mass"),
    (lambda: BendStiffener(length=4.0, table=((0, 2e5), (4, 1e3)), moment_curvature=BILINEAR),
     "moment_curvature starts at slope 20000 N m^2, but its EI at the root is 200000 N m^2"),
    (lambda: BendStiffener(length=4.0, cone=Cone(root_diameter=0.4, tip_diameter=0.2, modulus=5e7),
                           geometry=((0, 0.4), (4, 0.2))), "'geometry' is not used"),
    (lambda: BendStiffener(length=4.0, table=((0, 2e5), (4, 1e3)), density=1150.0, geometry=((0, 0.4), (3, 0.2))),
     "geometry must run from x = 0 (the root) to x = length = 4 m"),
    (_cone_with_law, "moment_curvature starts at slope 6000 N m^2, but its cone's EI at the root is 61589.3 N m^2"),
])
def test_bad_laws_restrictors_and_stiffeners_get_one_clear_message(make, message):
    with pytest.raises((InputError, ValueError)) as err:
        make()
    assert message in str(err.value)
    assert "Suggested fix" in str(err.value)


_CASE = """
name: hang
line_types:
  cable: {diameter: 0.15, mass_per_length: 40, axial_stiffness: 5e8, moment_curvature: [[0, 0], [0.05, 1000], [0.1, 1500]]}
line: {line_type: cable, length: 160}
environment: {depth: 100}
analysis: {type: mooring_static, anchor: [0, -100], fairlead: [80, -10], n_elements: 20,
           fairlead_end_condition: {type: spring, declination: 0.1, stiffness: 1e5}}
"""


@pytest.mark.parametrize("edit, message", [
    (lambda d: None, "a spring in series with a nonlinear half element is not supported"),
    (lambda d: d["line_types"]["cable"].update(moment_curvature=[[0, 0], [0.05, 1000], [0.04, 1500]]),
     "the law must be monotone"),
    (lambda d: d["line"].update(sections=[{"type": "bend_restrictor", "length": 3, "locking_radius": 0,
                                           "diameter": 0.3}]), "must be > 0 m, got 0 m"),
])
def test_validate_refuses_them_before_a_run(tmp_path, capsys, edit, message):
    data = yaml.safe_load(_CASE)
    edit(data)
    path = tmp_path / "c.yaml"
    path.write_text(yaml.safe_dump(data))
    assert main(["validate", str(path)]) == 2
    assert message in capsys.readouterr().err


def test_elements_take_the_cable_the_stiffener_and_the_restrictor_laws():
    """Per element (its mid arc length x from the root): a bilinear cable (20000 then 5000 N m^2) inside a table
    stiffener with a root law (EI 2e5 N m^2 to 0.02 1/m, then 5e4) tapering to 1e3 N m^2 at 4 m, and inside a
    restrictor at the other end locking at 4 m with the default LOCK_FACTOR: M(kappa) = M_cable + EI_s(x) / EI_s(0)
    M_root(kappa), and M_cable + LOCK_FACTOR 2e4 (kappa - 0.25)+; the element's EI the initial slope. To rounding."""
    from seacable.mooring.network import network_from_line
    from seacable.sections import LOCK_FACTOR

    cable = sc.LineType(**_LT, moment_curvature=BILINEAR)
    root = ((0.0, 0.0), (0.02, 4000.0), (0.1, 8000.0))
    stiffener = BendStiffener(end="B", length=4.0, table=((0, 2e5), (4, 1e3)), moment_curvature=root)
    restrictor = BendRestrictor(end="A", length=3.0, locking_radius=4.0, diameter=0.3)
    line = sc.Line(segments=(sc.Segment(line_type=cable, length=20.0),), sections=(stiffener, restrictor))
    net = network_from_line(line, (0, 0, -30), (15, 0, -5), water_density=1025.0, gravity=9.81, element_length=0.5)
    mid = 0.5 * (net.arc_length[:-1] + net.arc_length[1:])
    k = np.array([0.01, 0.05, 0.2, 0.3, 1.0])
    for e, law in enumerate(net.element_moment_curvature):
        expected = law_moment(BILINEAR, k)
        if mid[e] > 16.0:
            expected = expected + np.interp(20.0 - mid[e], [0, 4], [2e5, 1e3]) / 2e5 * law_moment(root, k)
        if mid[e] < 3.0:
            expected = expected + LOCK_FACTOR * 2e4 * np.maximum(k - 0.25, 0.0)
        assert law_moment(law, k) == pytest.approx(expected, rel=1e-12)
        assert net.bending_stiffness[e] == pytest.approx(law_slope(law, 0.0), rel=1e-12)


def test_a_restrictors_and_a_cones_drag_and_added_mass_are_on_their_outer_diameter():
    """Per element: the drag C_dn d' = C_dn <D> and the added mass C_an pi/4 d'^2 = C_an <pi/4 D^2> (<> the element's
    mean: a restrictor's constant D = 0.3 m, a cone's D(x) linear, its mean the mid value and its mean square
    exact), and outside the sections the cable's own. To rounding."""
    from seacable.mooring.network import network_from_line

    cable = sc.LineType(**_LT, bending_stiffness=1e4, drag_normal=1.1, drag_tangential=0.2, added_mass_normal=0.9)
    cone = BendStiffener(end="B", length=4.0, cone=Cone(root_diameter=0.5, tip_diameter=0.2, modulus=5e7),
                         density=1150.0)
    restrictor = BendRestrictor(end="A", length=3.0, locking_radius=4.0, diameter=0.3, mass_per_length=8.0)
    line = sc.Line(segments=(sc.Segment(line_type=cable, length=20.0),), sections=(cone, restrictor))
    net = network_from_line(line, (0, 0, -30), (15, 0, -5), water_density=1025.0, gravity=9.81, element_length=0.5)
    s = net.arc_length
    x0, x1 = 20.0 - s[:-1], 20.0 - s[1:]          # from the cone's root

    def dia(x):
        return np.where((x >= 0) & (x <= 4), 0.5 - 0.3 * x / 4, 0.15)

    mean_d = np.where(s[1:] <= 3.0 + 1e-9, 0.3, np.where(s[:-1] >= 16.0 - 1e-9, dia(0.5 * (x0 + x1)), 0.15))
    d0, d1 = dia(x0), dia(x1)
    cone_sq = (d0**2 + d0 * d1 + d1**2) / 3   # the mean of a linear D's square
    mean_sq = np.where(s[1:] <= 3.0 + 1e-9, 0.09, np.where(s[:-1] >= 16.0 - 1e-9, cone_sq, 0.15**2))
    assert net.cdn * net.diameter == pytest.approx(1.1 * mean_d, rel=1e-12)
    assert net.cdt * net.diameter == pytest.approx(0.2 * mean_d, rel=1e-12)
    assert net.can * net.diameter**2 == pytest.approx(0.9 * mean_sq, rel=1e-12)

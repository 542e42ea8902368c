"""Unit tests of seacable.line: validation, derived weights, immutability."""

import math
import pickle

import pydantic
import pytest

import seacable as sc


def chain(**kw):
    base = dict(diameter=0.09, mass_per_length=77.7066, axial_stiffness=384.243e6)
    return sc.LineType(**{**base, **kw})


def test_weight_derived_from_mass_and_displaced_volume():
    # OC3-Hywind (Jonkman 2010, NREL/TP-500-47535, Table 5-1): 77.7066 kg/m, d = 0.09 m gives an
    # apparent weight in water of 698.094 N/m with rho = 1025 and g = 9.80665. The table prints
    # 6 significant digits, hence 1e-6 relative.
    assert chain().submerged_weight(1025.0, 9.80665) == pytest.approx(698.094, rel=1e-6)


def test_given_weight_in_water_wins():
    assert chain(weight_in_water=700.0).submerged_weight(1025.0, 9.81) == 700.0


def test_buoyant_line_type_has_negative_weight():
    # A 0.05 m rope of 1.725 kg/m (paper 003's floating towline) displaces 2.01 kg/m.
    rope = sc.LineType(diameter=0.05, mass_per_length=1.725)
    expected = (1.725 - 1025.0 * math.pi * 0.05**2 / 4) * 9.81
    assert rope.submerged_weight() == pytest.approx(expected, rel=1e-12)
    assert rope.submerged_weight() < 0


def test_inextensible_line_type_has_infinite_stiffness():
    assert sc.LineType(diameter=0.02, mass_per_length=1.0).effective_axial_stiffness() == math.inf


@pytest.mark.parametrize("key, value, expected", [
    ("diameter", -0.08, "diameter must be > 0 m, got -0.08 m. Suggested fix"),
    ("diameter", float("nan"), "diameter must be a finite number"),
    ("diameter", "thick", "diameter must be a number in m, got 'thick'"),
    ("mass_per_length", 0.0, "mass_per_length must be > 0 kg/m"),
    ("axial_stiffness", -1.0, "axial_stiffness must be > 0 N"),
    ("drag_normal", -0.5, "drag_normal must be >= 0"),
    ("weight_in_water", 1e5, "must not exceed the weight in air"),
    ("diamter", 0.1, "unknown key 'diamter'. Did you mean 'diameter'?"),
])
def test_bad_line_type_values_are_named_with_units(key, value, expected):
    with pytest.raises(sc.InputError, match=None) as info:
        chain(**{key: value})
    assert expected in str(info.value)


def test_boolean_is_not_a_number():
    with pytest.raises(sc.InputError, match="must be a number"):
        chain(diameter=True)


def test_objects_are_immutable_and_picklable():
    line = sc.Line(segments=[sc.Segment(line_type=chain(), length=500.0),
                             sc.Segment(line_type=chain(mass_per_length=4315.0), length=36.58)],
                   attachments=[sc.PointMass(s=100.0, mass=5000.0, volume=1.0)])
    assert pickle.loads(pickle.dumps(line)) == line
    with pytest.raises(pydantic.ValidationError, match="frozen"):
        line.segments = ()
    assert line.length == pytest.approx(536.58)
    assert line.segment_ends == pytest.approx((0.0, 500.0, 536.58))


def test_point_mass_net_weight():
    buoy = sc.PointMass(s=10.0, mass=1000.0, volume=3.0, kind="buoy")
    assert buoy.net_weight(1025.0, 9.81) == pytest.approx((1000.0 - 3075.0) * 9.81)


def test_attachment_beyond_the_line_is_rejected():
    with pytest.raises(sc.InputError, match=r"attachments\[0\]\.s must be <= the line length 100 m"):
        sc.Line.single(chain(), 100.0, attachments=[sc.PointMass(s=150.0, mass=1.0)])


def test_empty_line_is_rejected():
    with pytest.raises(sc.InputError, match="segments"):
        sc.Line(segments=[])


def test_a_faired_line_type_needs_its_chord_and_a_chord_needs_the_faired_law():
    with pytest.raises(ValueError, match="drag_law 'faired' needs fairing_chord"):
        sc.LineType(diameter=0.03, mass_per_length=1.0, drag_law="faired")
    with pytest.raises(ValueError, match="fairing_chord 0.1 m is given but drag_law is 'morison'"):
        sc.LineType(diameter=0.03, mass_per_length=1.0, fairing_chord=0.1)

"""CableDyn's cable decks read as MoorDyn decks (seacable.io.moordyn._cabledyn): SECTIONS, EQUIVALENT BUOYANCY,
END CONNECTIONS, and what is refused by name.

The deck is CableDyn 0.3.0's ``examples/lozon_gomex80_power_cable.dat`` (Apache-2.0) in its layout: POINTS rows of
five columns, LINES rows of four, LINE TYPES in CableDyn's ``Cd_n Cd_t Ca_n Ca_t`` order, keyword-first and ``--``
OPTIONS rows; its mesh is coarsened fourfold to keep the test fast.
"""

import math
import warnings

import pytest

import seacable as sc
from seacable.errors import InputError
from seacable.io.moordyn import read_moordyn

DECK = """--------------------- CableDyn Input File ------------------------------------
Lozon et al. (2025) Gulf of Mexico 80 m lazy-wave dynamic power cable
-- CableDyn determines touchdown during static initialisation.
--------------------- LINE TYPES ---------------------------------------------
TypeName  Diam   MassDenInAir  EA       BA   EI       Cd_n  Cd_t  Ca_n  Ca_t
(-)       (m)    (kg/m)        (N)      (-)  (N-m2)   (-)   (-)   (-)   (-)
bare      0.160  36.70         4.69e8   0.0  1.99e4   1.2   0.1   1.0   0.0
buoy      0.290  59.53         4.69e8   0.0  1.99e4   1.2   0.1   1.0   0.0
--------------------- POINTS ------------------------------------------------
ID  Type     X       Y    Z
(-) (-)      (m)     (m)  (m)
1   Coupled  5.0     0.0  -14.0
2   Fixed    125.0   0.0  -80.0
--------------------- LINES -------------------------------------------------
ID  NodeA  NodeB  Outputs
(-) (-)    (-)    (-)
1   1      2      -
--------------------- SECTIONS ----------------------------------------------
LineID  LineType  Length   NumSegs
(-)     (-)       (m)      (-)
1       bare      68.114   112
1       buoy      50.000   80
1       bare      52.101   64
{extra}--------------------- OPTIONS -----------------------------------------------
9.80665  g               - Gravitational acceleration (m/s^2)
1025.0   rhoW            - Water density (kg/m^3)
80.0     WtrDpth         - Water depth for the flat seabed (m)
1.0e5    kBot            - Seabed penalty stiffness base (Pa/m)
1.0e4    cBot            - Seabed normal damping base (Pa-s/m)
0.4      rhoInf          - Generalised-alpha spectral radius
0.0      TMax            - 0 selects static initialisation only
dynamic_solver 1.0e-8 1.0e-14 30 12 - Relative tolerance, absolute tolerance, max iterations, backtracks
{current}      current           - Current model
-- Complete option/default reference: cabledyn_options_reference.dat and doc/options.rst.
--------------------- OUTPUTS -----------------------------------------------
"FairTen1"
--------------------- need this line ----------------------------------------
"""


def _deck(extra="", current="none"):
    return DECK.format(extra=extra, current=current)


def test_sections_make_one_line_of_three_pieces_in_cabledyn_column_order():
    md = read_moordyn(_deck())
    (line,) = md.lines
    assert line.sections == (("bare", 68.114, 112), ("buoy", 50.0, 80), ("bare", 52.101, 64))
    assert line.length == pytest.approx(170.215, rel=1e-15) and line.n_segments == 256
    bare = md.line_types["bare"]
    # Cd_n Cd_t Ca_n Ca_t = 1.2 0.1 1.0 0.0, not MoorDyn's Cd Ca CdAx CaAx
    assert (bare.drag_normal, bare.drag_tangential, bare.added_mass_normal, bare.added_mass_tangential) == \
        (1.2, 0.1, 1.0, 0.0)
    assert md.points[0].attachment == "vessel" and md.points[0].mass == 0.0
    # CableDyn's solver settings (rhoInf, TMax, dynamic_solver) and 'none' current are dropped as MoorDyn's dtM is
    assert not md.notes


def test_cabledyn_friction_is_the_seabed_friction_coefficient():
    md = read_moordyn(_deck().replace("0.0      TMax", "0.3      frictionMu\n0.0      TMax"))
    assert md.options["FrictionCoefficient"] == 0.3 and not md.notes


def test_equivalent_buoyancy_rewrites_diameter_and_mass_from_the_weight_in_water():
    extra = ("--------------------- EQUIVALENT BUOYANCY -----------------------------\n"
             "LineType  Diam  SubmergedWeightNpm\n(-)  (m)  (N/m)\nbuoy  0.30  -90.0\n")
    md = read_moordyn(_deck(extra))
    buoy = md.line_types["buoy"]
    # closed form: m = w / g + rho pi d^2 / 4, so that (m - rho pi d^2 / 4) g = w
    assert buoy.diameter == 0.30
    assert buoy.mass_per_length == pytest.approx(-90.0 / 9.80665 + 1025.0 * math.pi * 0.09 / 4, rel=1e-14)
    assert (buoy.mass_per_length - 1025.0 * math.pi * 0.3**2 / 4) * 9.80665 == pytest.approx(-90.0, rel=1e-12)


@pytest.mark.parametrize("extra, current, message", [
    (("--------------------- END CONNECTIONS -------------------------------\nLineID End Stiffness EzX EzY EzZ "
      "TorsStiffness NxX NxY NxZ\n(-) (-) (N-m/rad) (-) (-) (-) (N-m/rad) (-) (-) (-)\n"
      "1 A Rigid 0.17 0.0 -0.98 Rigid 0 1 0\n"), "none", "TorsStiffness 'Rigid' restrains the line's twist"),
    (("--------------------- END CONNECTIONS -------------------------------\nLineID End Stiffness EzX EzY EzZ\n"
      "(-) (-) (N-m/rad) (-) (-) (-)\n1 A Rigid 0 0 0\n"), "none", "must be a non-zero vector"),
    (("--------------------- ATTACHMENTS ----------------------------------\nLineID ArcLength Mass Volume CdA Ca\n"
     "(-) (m) (kg) (m^3) (m^2) (-)\n1 170.614:5.0:175.614 114.15 0.2297 0.78 1.0\n"), "none",
     "arc length 170.614 m lies outside line 1 (0 to 170.215 m)"),
    ("", "uniform 0.5 0.0 0.0", "CableDyn's option current 'uniform 0.5 0.0 0.0' is not read"),
    (("--------------------- EQUIVALENT BUOYANCY -----------------------------\nLineType Diam SubmergedWeightNpm\n"
     "(-) (m) (N/m)\nbuoy 0.01 -90.0\n"), "none", "needs a mass in air of"),
])
def test_what_seacable_does_not_read_is_refused_by_name(extra, current, message):
    with pytest.raises(InputError) as err:
        read_moordyn(_deck(extra, current))
    assert message in str(err.value) and "Suggested fix" in str(err.value)


def test_held_end_connections_are_read_as_end_conditions():
    """A Rigid row is a clamp, a positive Stiffness a rotational spring, both along (EzX, EzY, EzZ) towards End B."""
    extra = ("--------------------- END CONNECTIONS -------------------------------\n"
             "LineID End Stiffness EzX EzY EzZ\n(-) (-) (N-m/rad) (-) (-) (-)\n1 A Rigid 0.6 0.0 -0.8\n"
             "1 B 2.5e4 0 3 4\n")
    md = read_moordyn(_deck(extra))
    assert md.end_connections[(1, 0)] == ("clamp", None, pytest.approx((0.6, 0.0, -0.8), abs=1e-15))
    assert md.end_connections[(1, 1)] == ("spring", 2.5e4, pytest.approx((0.0, 0.6, 0.8), abs=1e-15))


def test_pinned_end_connections_are_read():
    extra = ("--------------------- END CONNECTIONS -------------------------------\n"
             "LineID End Stiffness EzX EzY EzZ\n(-) (-) (N-m/rad) (-) (-) (-)\n1 B Pinned 1 0 0\n")
    assert read_moordyn(_deck(extra)).lines[0].sections


def test_cabledyn_deck_runs_its_lazy_wave_statics(tmp_path):
    path = tmp_path / "lozon_gomex80_power_cable.dat"
    path.write_text(_deck())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the CableDyn options seacable does not honour, noted
        ds = sc.run(sc.load_case(path))
    # CableDyn on its 1024-element mesh: 9320.17 N at the hang-off. On this deck's 0.6 m elements seacable's
    # case-file twin (tests/validation/test_cabledyn_lazy_wave.py) moves by < 0.05 N between 1 and 0.5 m elements:
    # 1 N holds the mesh and the deck's kBot contact
    assert float(ds.fairlead_tension) == pytest.approx(9320.17, abs=1.0)
    assert ds.z.values.min() == pytest.approx(-80.0, abs=0.05)  # its tail on the seabed (kBot 1e5: 1 cm in)


MODULES = ("--------------------- ATTACHMENTS -------------------------------------------\n"
           "LineID  ArcLength               Mass     Volume   CdA    Ca    CdAx\n"
           "(-)     (m)                     (kg)     (m^3)    (m^2)  (-)   (m^2)\n"
           "1       70.614:5.0:115.614      114.15   0.2297   0.78   1.0   0.2042\n")


def test_attachments_are_point_loads_at_their_nodes_and_give_cabledyns_modules_deck(tmp_path):
    # CableDyn's lazy_wave_buoyancy_modules.dat in still water: the bare cable with ten modules of 114.15 kg and
    # 0.2297 m^3 at a 5 m pitch from 70.614 m of arc (hang-off first); the deck's mesh coarsened fourfold still puts
    # a node on every module (0.625 m elements over the middle section)
    deck = _deck(MODULES).replace("1       buoy      50.000   80", "1       bare      50.000   80")
    md = read_moordyn(deck)
    arcs = [a[0] for a in md.lines[0].attachments]
    assert arcs == pytest.approx([70.614 + 5.0 * k for k in range(10)], abs=1e-12)
    path = tmp_path / "modules.dat"
    path.write_text(deck)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ds = sc.run(sc.load_case(path))
    # CableDyn 0.3.0 on the deck's 1024 elements: 9324.68 N at the hang-off (seacable on them: 9324.677 N); the
    # fourfold coarser mesh moves the smeared twin by < 0.05 N: 1 N (the smeared section gives 9320.17 N, and a
    # module misplaced by one pitch or its lift lost moves it by far more)
    assert float(ds.fairlead_tension) == pytest.approx(9324.68, abs=1.0)

"""MoorDyn input files, issue 17 items 10, 11, 13 and 14, and the reader's checks of every number.

- Item 14: ``!``, ``#`` and ``%`` start a comment (MoorDyn ``docs/inputs.rst``: "!, #, and % are
  comment characters ... any of these characters will prevent MoorDyn from reading the rest of that
  line"; MoorDyn-C 2.7.2 reads a commented points row as the row before the comment).
- Item 11: without ``WtrDpth`` the seabed is at the deepest point (MoorDyn-C ``ReadInFile`` in
  ``source/MoorDyn2.cpp``: "make default water depth at least the depth of the lowest node (so water
  depth input is optional)"). The anchor tension of a chain lying on that seabed is checked against
  the elastic catenary with seabed contact (Jonkman 2007, NREL/TP-500-41958, eq. for a line resting
  on a frictionless seabed), solved here on its own.
- Item 10: options seacable honours change the physics (checked by a consequence: weight, buoyancy,
  seabed penetration); each option it cannot honour is warned with its value and what is done instead.
- Item 13: :func:`seacable.load_case` reads a MoorDyn file as a case.
- A corpus of bad decks: each is an :class:`InputError` naming the file line and the column.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import fsolve

import seacable
from seacable.errors import InputError, SeacableWarning
from seacable.io.moordyn import MoorDynCase, load_moordyn_case, read_moordyn
from seacable.mooring.moordyn import prepare_moordyn, run_moordyn_case, run_moordyn_file

HEAD = "--------------------- MoorDyn Input File ------------------------------------\ntest deck\n"
TYPES = ("----------------------- LINE TYPES ------------------------------------------\n"
         "TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx\n"
         "(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)\n")
POINTS = ("---------------------- POINTS ----------------------------------------------\n"
          "ID    Attachment  X       Y       Z       Mass   Volume  CdA    Ca\n"
          "(#)   (-)         (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)\n")
LINES = ("---------------------- LINES ----------------------------------------\n"
         "ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs\n"
         "(#)   (name)     (#)      (#)       (m)       (-)     (-)\n")
OPTIONS = "---------------------- OPTIONS -----------------------------------------\n"
END = "------------------------- need this line -----------\n"

TYPE = "chain      0.1     120.0      5.0e8      -1.0        0          1.2    1.0    0.2     0.0"
ANCHOR = "1     Fixed       -400.0  0.0     -100.0  0      0       0      0"
FAIRLEAD = "2     Vessel      0.0     0.0     -5.0    0      0       0      0"
LINE = "1     chain      1        2         450.0     90      -"


def deck(types=(TYPE,), points=(ANCHOR, FAIRLEAD), lines=(LINE,), options=("1.0e9  kBot  stiff seabed",),
         outputs=None):
    text = HEAD + TYPES + "".join(r + "\n" for r in types) + POINTS + "".join(r + "\n" for r in points)
    text += LINES + "".join(r + "\n" for r in lines) + OPTIONS + "".join(r + "\n" for r in options)
    if outputs is not None:
        text += "---------------------- OUTPUTS -----------------------------------------\n" + outputs + "\n"
    return text + END


def _file(tmp_path, text, name="lines.txt") -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


# ----------------------------------------------------------------------------- item 14: comments

def test_comments_are_read_as_moordyn_reads_them():
    """A '#', '!' or '%' ends the row: the commented deck reads exactly as the plain one.

    On the reader before the fix the point row below had 13 tokens, was taken for the 12-column
    layout and failed with "point 3 FZ must be a finite number in N, got '#'"."""
    free = "3     Free   -150 0 -60 1000 0 1 0"
    lines = ("1 chain 1 3 180.0 20 -", "2 chain 3 2 300.0 30 -")
    plain = read_moordyn(deck(points=(ANCHOR, FAIRLEAD, free), lines=lines,
                              options=("1.0e9 kBot", "100 WtrDpth"), outputs="FairTen1\nAnchTen1"))
    commented = read_moordyn(deck(
        types=(TYPE + "   # studless chain, 0.1 m nominal",),
        points=(ANCHOR + " ! anchor on the seabed", FAIRLEAD + " % fairlead", free + " # 1 2 3 4 a buoy"),
        lines=(lines[0] + " # lower", lines[1] + "   ! upper 1 2 3"),
        options=("1.0e9 kBot # stiff", "100 WtrDpth % metres", "# a whole commented line", "! 5 WtrDpth"),
        outputs="FairTen1 # fairlead\nAnchTen1 ! anchor\n% nothing"))
    for field in ("line_types", "points", "lines", "options", "outputs"):
        assert getattr(commented, field) == getattr(plain, field), field
    assert commented.points[2].drag_area == 1.0 and commented.points[2].added_mass_coefficient == 0.0


def test_commented_header_line_is_not_a_section():
    text = deck().replace(LINES, "# ---------- LINES are below ----------\n" + LINES)
    assert len(read_moordyn(text).lines) == 1


# ----------------------------------------------------------------------------- item 11: the depth

def _catenary_on_seabed(length, weight, ea, span, height):
    """Elastic catenary resting on a frictionless seabed: (H, V) at the fairlead. [N]

    x = L - V/w + (H/w) asinh(V/H) + H L / EA and h = (H/w)(sqrt(1 + (V/H)^2) - 1) + V^2 / (2 EA w)
    (Jonkman 2007, NREL/TP-500-41958, Appendix: a line with part of it on the seabed, C_B = 0).
    """
    def residual(p):
        h_, v_ = p
        return [length - v_ / weight + h_ / weight * np.arcsinh(v_ / h_) + h_ * length / ea - span,
                h_ / weight * (np.sqrt(1 + (v_ / h_) ** 2) - 1) + v_**2 / (2 * ea * weight) - height]

    h_, v_ = fsolve(residual, [0.1 * weight * length, 0.5 * weight * length], xtol=1e-13)
    return h_, v_


def test_no_wtrdpth_puts_the_seabed_at_the_deepest_point(tmp_path):
    """450 m of chain from an anchor at z = -100 m to a fairlead 400 m away at z = -5 m, no WtrDpth.

    With the seabed at the anchor 315 m of chain rests on it and, the seabed frictionless, the
    anchor holds the horizontal tension H of the catenary. Before the fix the deck had no seabed:
    the chain sagged below its anchor and the tensions were those of a free-hanging line."""
    path = _file(tmp_path, deck())
    assert read_moordyn(path).water_depth == 100.0
    ds = run_moordyn_file(path)
    assert ds.attrs["depth"] == 100.0
    w = (120.0 - 1025.0 * math.pi * 0.1**2 / 4) * 9.80665
    h_, v_ = _catenary_on_seabed(450.0, w, 5.0e8, 400.0, 95.0)
    assert 450.0 - v_ / w == pytest.approx(315.0, abs=1.0)  # the grounded length, for the record
    # the anchor end lies on a frictionless seabed: its tension is the line's horizontal tension, the same
    # as the fairlead's horizontal pull (discrete equilibrium, to the static tolerance): the two differ by the
    # sum of the x residuals of the 89 free nodes, each below the solver's force tolerance (run_moordyn_file's
    # 1e-8 of the line's weight, 4.9e-3 N) plus its round-off floor (1024 ulp of the seabed's largest term
    # k_b d_n (z + depth), kBot 1e9 Pa/m on d L = 0.1 m x 5 m at 100 m: 1.1e-2 N): 1.4 N, 2.6e-5 of H
    # (measured 0.009 N; seabed friction would be of order 1e4 N)
    node_tolerance = 1e-8 * w * 450.0 + 1024 * np.finfo(float).eps * 1.0e9 * 0.1 * 5.0 * 100.0
    assert float(ds.anchor_tension) == pytest.approx(-float(ds.fairlead_force_x), abs=89 * node_tolerance)
    # 90 elements of 5 m against the continuous catenary: measured -9.1e-4 (anchor) and -4.4e-4 (fairlead);
    # with 45 / 180 / 360 elements +3.8e-3 / -1.5e-4 / +3.5e-5 (anchor): the touchdown falls inside an
    # element, so the error is not monotone; 1.5e-3 and 1e-3 are 1.6 and 2.3 times the error at 90
    assert float(ds.anchor_tension) == pytest.approx(h_, rel=1.5e-3)
    assert float(ds.fairlead_tension) == pytest.approx(math.hypot(h_, v_), rel=1e-3)
    assert float(ds.z.min()) > -100.0 - 1e-3  # nothing below the seabed (kBot 1e9 Pa/m: 0.01 mm)


def test_moordyn_itself_puts_the_seabed_at_the_deepest_point(tmp_path):
    """The peer: MoorDyn-C (the moordyn wheel) runs the same deck without WtrDpth and its chain rests on
    z = -100 m, the anchor's depth, as ours does (before the fix ours hung to z = -141 m)."""
    moordyn = pytest.importorskip("moordyn")
    path = _file(tmp_path, deck())
    system = moordyn.Create(str(path))
    fairlead = list(moordyn.GetPointPos(moordyn.GetPoint(system, 2)))
    moordyn.Init(system, fairlead, [0.0, 0.0, 0.0])
    line = moordyn.GetLine(system, 1)
    theirs = min(moordyn.GetLineNodePos(line, k)[2] for k in range(moordyn.GetLineN(line) + 1))
    moordyn.Close(system)
    ours = float(run_moordyn_file(path).z.min())
    # kBot = 1e9 Pa/m: the chain sinks w / (kBot d) = 0.01 mm into the seabed in both codes
    assert theirs == pytest.approx(-100.0, abs=1e-3) and ours == pytest.approx(-100.0, abs=1e-3)


def _oc4_deck() -> str:
    """The OC4-DeepCwind semi-submersible's mooring, from its definition's published numbers, no WtrDpth.

    Robertson et al. (2014), Definition of the semisubmersible floating system for phase II of OC4,
    NREL/TP-5000-60601, section 3.4: 200 m of water; three catenary chains 120 deg apart, 835.5 m long,
    0.0766 m in diameter, 113.35 kg/m, EA 753.6 MN; fairleads 14 m below the still water level at a radius
    of 40.868 m, anchors at 837.6 m on the seabed. OpenFAST's regression deck gives neither the depth nor
    a seabed, so MoorDyn takes the seabed at the anchors.
    """
    points, lines = [], []
    for k, heading in enumerate((60.0, 180.0, 300.0)):
        c, s_ = math.cos(math.radians(heading)), math.sin(math.radians(heading))
        points.append(f"{2 * k + 1}  Fixed   {837.6 * c:.4f} {837.6 * s_:.4f} -200.0  0 0 0 0")
        points.append(f"{2 * k + 2}  Vessel  {40.868 * c:.4f} {40.868 * s_:.4f} -14.0   0 0 0 0")
        lines.append(f"{k + 1}  main  {2 * k + 1}  {2 * k + 2}  835.5  20  -")
    main = "main  0.0766  113.35  7.536E8  -1.0  0  2.0  0.8  0.4  0.25"
    return deck(types=(main,), points=tuple(points), lines=tuple(lines), options=("3.0e6 kBot",))


def test_oc4_semisubmersible_without_wtrdpth_against_moorpy(tmp_path):
    """The issue's case: without WtrDpth the lines hung below their anchors (1.322 MN at the fairleads of
    OpenFAST's deck, where MoorDyn gives 1.091 MN and MoorPy 1.106 MN). With the seabed at the anchors each
    fairlead tension matches MoorPy's elastic catenary with seabed contact, run live on the same deck
    (1.0988 MN here: the deck is rebuilt from the definition's numbers, not OpenFAST's file)."""
    mp = pytest.importorskip("moorpy")
    path = _file(tmp_path, _oc4_deck())
    ds = run_moordyn_file(path)
    assert ds.attrs["depth"] == 200.0
    ms = mp.System(file=str(path), depth=200.0)
    ms.initialize()
    ms.solveEquilibrium()
    theirs = np.array([line.TB for line in ms.lineList])
    # 20 elements of 42 m per line against MoorPy's continuous catenary, the touchdown inside an element:
    # measured 2.0e-3 (the old reader: 1.33 MN, +21 %); 5e-3 leaves room for where the touchdown falls
    assert ds.fairlead_tension.values == pytest.approx(theirs, rel=5e-3)


# ----------------------------------------------------------------------------- item 10: options

def _vertical_forces(text, tmp_path):
    """Sum of the vertical support forces of a line hung between two fixed points well off the seabed."""
    path = _file(tmp_path, text)
    model = prepare_moordyn(path)
    from seacable.mooring.solver import static_equilibrium

    st = static_equilibrium(model)
    return -float(np.sum(st.support[:2, 2]))


@pytest.mark.parametrize("options, rho, g", [
    ((), 1025.0, 9.80665),                                   # MoorDyn's defaults
    (("1000 WtrDnsty", "9.81 g"), 1000.0, 9.81),
    (("1000 rhoW", "9.7 gravity"), 1000.0, 9.7),            # MoorDyn-F spellings
    (("1000 RHO", "9.7 G"), 1000.0, 9.7),                   # MoorDyn-F: names in any case
])
def test_density_and_gravity_options_set_the_weight_in_water(tmp_path, options, rho, g):
    points = ("1 Fixed -100 0 -50 0 0 0 0", "2 Fixed 100 0 -50 0 0 0 0")
    text = deck(points=points, lines=("1 chain 1 2 240 24 -",), options=options + ("500 WtrDpth",))
    # the anchors carry the whole weight in water of the line, (m - rho pi d^2 / 4) g L; round-off only
    expected = (120.0 - rho * math.pi * 0.1**2 / 4) * g * 240.0
    assert _vertical_forces(text, tmp_path) == pytest.approx(expected, rel=1e-9)


@pytest.mark.parametrize("spelling", ["kBot", "kbot", "kb", "KBOT"])
def test_seabed_stiffness_option_sets_the_penetration(tmp_path, spelling):
    """A chain lying flat on the seabed sinks w / (kBot d) into it (MoorDyn's seabed, per projected area)."""
    points = ("1 Fixed -100 0 -100 0 0 0 0", "2 Fixed 100 0 -100 0 0 0 0")
    text = deck(points=points, lines=("1 chain 1 2 200 20 -",), options=(f"2.0e6 {spelling}", "100 WtrDpth"))
    path = _file(tmp_path, text)
    ds = run_moordyn_case(load_moordyn_case(path))
    w = (120.0 - 1025.0 * math.pi * 0.1**2 / 4) * 9.80665
    sink = w / (2.0e6 * 0.1)  # 5.5 mm; the default 3e6 would give 3.7 mm
    interior = ds.z.values[2:-2]
    assert interior == pytest.approx(-100.0 - sink, rel=1e-9)  # a flat line on a linear spring bed


def test_friction_options_map_onto_the_seabed_friction(tmp_path):
    def water(*options):
        return prepare_moordyn(_file(tmp_path, deck(options=options + ("100 WtrDpth",)))).water

    assert water().friction == 0.0
    assert water("0.4 FrictionCoefficient").friction == 0.4
    assert water("0.3 mu_kT", "0.3 mu_kA").friction == 0.3          # MoorDyn-F, isotropic
    with pytest.warns(SeacableWarning, match=r"mu_kT = 0.6 and mu_kA = 0 \(MoorDyn-F's default 0"):
        assert water("0.6 MU_KT").friction == 0.3  # MoorDyn-F: mu_kA defaults to 0
    assert water("1.0 StatDynFricScale", "0.5 FrictionCoefficient").friction == 0.5  # ratio 1: honoured
    assert water("4e6 cBot").seabed_damping == 4e6
    with pytest.warns(SeacableWarning, match=r"mu_kT = 0.2 and mu_kA = 0.6 .* isotropic and uses their mean, 0.4\."):
        assert water("0.2 mu_kT", "0.6 mu_kA").friction == pytest.approx(0.4, rel=1e-15)


@pytest.mark.parametrize("option, match", [
    ("2 WaveKin", r":\d+: option WaveKin = 2 .* runs this file in still water"),
    ("1 Currents", r":\d+: option Currents = 1 .* without current"),
    ("bathy.txt SeafloorFile", r"option SeafloorFile = 'bathy.txt' .* flat seabed at z = -100 m \(WtrDpth\)"),
    ("waterkin.dat WaterKin", r"option WaterKin = 'waterkin.dat' .* still water"),
    ("100 WtrDepth", r"option WtrDepth = 100 is not a MoorDyn option .* ignored\. Did you mean 'WtrDpth'\?"),
    ("3 frobnicate", r"option frobnicate = 3 is not a MoorDyn option seacable knows"),
])
def test_options_seacable_cannot_honour_are_warned(tmp_path, option, match):
    path = _file(tmp_path, deck(options=(option, "100 WtrDpth")))
    with pytest.warns(SeacableWarning, match=match):
        prepare_moordyn(path)


@pytest.mark.parametrize("options, match", [
    (("0.5 FrictionCoefficient", "100 FricDamp"), r"option FricDamp = 100 \(MoorDyn's friction ramp"),
    (("0.5 mu_kT", "0.5 mu_kA", "150 CV"), r"option CV = 150 .* Coulomb friction"),
    (("0.5 FrictionCoefficient", "0.8 StatDynFricScale"), r"StatDynFricScale = 0.8 \(static/dynamic"),
    (("0.5 FrictionCoefficient", "0.3 mu_kT"), r"mu_kT/mu_kA \(MoorDyn-F\) are ignored: FrictionCoefficient = 0.5"),
])
def test_friction_details_not_honoured_are_warned(tmp_path, options, match):
    with pytest.warns(SeacableWarning, match=match):
        prepare_moordyn(_file(tmp_path, deck(options=options + ("100 WtrDpth",))))


def test_a_bathymetry_file_in_wtrdpth_is_refused_with_the_reason():
    with pytest.raises(InputError, match=r"option WtrDpth must be a number in m, got 'bathy.txt' \(MoorDyn-F reads a "
                                         r"bathymetry file here"):
        read_moordyn(deck(options=("bathy.txt WtrDpth",)))


def test_viv_lift_coefficient_is_warned(tmp_path):
    types = (TYPE + "  0.8  0.08  0.18",)
    with pytest.warns(SeacableWarning, match=r":6: line type 'chain' Cl = 0.8 .* no VIV model"):
        prepare_moordyn(_file(tmp_path, deck(types=types)))
    prepare_moordyn(_file(tmp_path, deck(types=(TYPE + "  0  0.08  0.18",))))  # Cl = 0: VIV off, no warning


def test_numerics_and_output_options_need_no_warning(tmp_path):
    """MoorDyn's own integrator, start and output settings do not change the problem (the suite turns
    any SeacableWarning into an error, so this passes only if none is raised)."""
    options = ("2 writeLog", "0.001 dtM", "0.5 cfl", "RK4 tScheme", "1.0 dtIC", "60 TmaxIC", "4 CdScaleIC",
               "0.01 threshIC", "0 ICgenDynamic", "0.1 dtOut", "1 WriteUnits", "1 disableOutTime", "0 WaveKin",
               "0 Currents", "0.25 dtWave", "0.1 FricDamp", "100 WtrDpth")
    prepare_moordyn(_file(tmp_path, deck(options=options)))


# ----------------------------------------------------------------------------- item 13: a case

def test_load_case_of_a_moordyn_file_is_a_case_that_runs(tmp_path):
    path = _file(tmp_path, deck(), name="spread.dat")
    case = seacable.load_case(path)
    assert isinstance(case, MoorDynCase) and case.name == "spread" and case.analysis_type == "mooring_static"
    assert "1 line(s), 2 point(s), 90 segment(s)" in case.describe() and "depth 100 m" in case.describe()
    ds = run_moordyn_case(case)
    assert ds.attrs["analysis"] == "mooring_static"
    dynamic = case.with_run(duration=1.0, time_step=0.1, output_interval=0.5)
    assert dynamic.analysis_type == "mooring_dynamic" and case.duration is None  # immutable
    dd = run_moordyn_case(dynamic)
    # held still at its equilibrium the line stays there: the fairlead tension of the static run, to the
    # Newton tolerance of the time steps (1e-7 of the tension)
    assert dd.fairlead_tension.values == pytest.approx(float(ds.fairlead_tension), rel=1e-6)


def test_seacable_run_accepts_a_moordyn_case(tmp_path):
    case = seacable.load_case(_file(tmp_path, deck()))
    assert seacable.run(case).attrs["analysis"] == "mooring_static"


@pytest.mark.parametrize("kwargs, match", [
    ({"duration": 0.0}, r"duration must be > 0 s, got 0 s"),
    ({"duration": math.nan}, "duration must be a finite number"),
    ({"duration": 10.0, "time_step": -0.1}, r"time step must be > 0 s, got -0.1 s"),
    ({"duration": 10.0, "output_interval": math.inf}, "output interval must be a finite number"),
    ({"duration": 10.0, "time_step": 0.5, "output_interval": 0.1}, r"output interval must be >= the time step"),
    ({"motion": object()}, "a vessel motion needs a duration"),
])
def test_run_settings_are_checked(tmp_path, kwargs, match):
    case = load_moordyn_case(_file(tmp_path, deck()))
    with pytest.raises(InputError, match=match):
        case.with_run(**kwargs)


def test_a_run_too_long_is_refused_before_it_starts(tmp_path):
    case = load_moordyn_case(_file(tmp_path, deck())).with_run(duration=1e300)
    with pytest.raises(InputError, match=r"mooring_dynamic run of lines needs about 1e\+301 time steps"):
        prepare_moordyn(case)


def test_a_free_point_without_a_line_is_refused(tmp_path):
    """It has no static equilibrium: the Newton iteration failed with a ConvergenceError before."""
    path = _file(tmp_path, deck(points=(ANCHOR, FAIRLEAD, "3 Free 0 0 -50 10 0 0 0")))
    with pytest.raises(InputError, match=r"point 3 is Free but no line is attached to it"):
        prepare_moordyn(path)


def test_a_line_that_cannot_reach_its_points_is_refused(tmp_path):
    """The issue's example: 410 m of chain between points 4000 m apart ran to 1.47e10 N."""
    points = ("1 Fixed -4000 0 -100 0 0 0 0", FAIRLEAD)
    path = _file(tmp_path, deck(points=points, lines=("1 chain 1 2 410 41 -",)))
    with pytest.raises(InputError, match=r"'line 1' \(410 m unstretched\) cannot span the 4001.13 m"):
        prepare_moordyn(path)


# ----------------------------------------------------------------------------- the corpus of bad decks

def _variant(section, row):
    """A deck with ``row`` in ``section`` (replacing its first row; several rows split by newlines), and the
    1-based number of its (last) line in the file."""
    kw = {"types": (TYPE,), "points": (ANCHOR, FAIRLEAD), "lines": (LINE,), "options": ("100 WtrDpth",)}
    if row is None:
        kw[section] = ()
    else:
        kw[section] = tuple(row.split("\n")) + kw[section][1:]
    text = deck(**kw)
    lines = text.splitlines()
    if row is None:
        header = {"types": "LINE TYPES", "points": "POINTS", "lines": "LINES"}[section]
        return text, next(i for i, ln in enumerate(lines, 1) if "---" in ln and header in ln)
    return text, lines.index(row.split("\n")[-1]) + 1


BAD = [  # section, row, words the message must contain (the column or field)
    ("types", "chain -0.1 120 5e8 -1 0 1.2 1 0.2 0", "Diam"),
    ("types", "chain nan 120 5e8 -1 0 1.2 1 0.2 0", "Diam"),
    ("types", "chain abc 120 5e8 -1 0 1.2 1 0.2 0", "Diam"),
    ("types", "chain 0.1 inf 5e8 -1 0 1.2 1 0.2 0", "MassDen"),
    ("types", "chain 0.1 0 5e8 -1 0 1.2 1 0.2 0", "MassDen"),
    ("types", "chain 0.1 120 -5e8 -1 0 1.2 1 0.2 0", "EA"),
    ("types", "chain 0.1 120 ea.dat -1 0 1.2 1 0.2 0", "EA"),
    ("types", "chain 0.1 120 5e8 nan 0 1.2 1 0.2 0", "BA/-zeta"),
    ("types", "chain 0.1 120 5e8 -1 -3 1.2 1 0.2 0", "EI"),
    ("types", "chain 0.1 120 5e8 -1 0 -1.2 1 0.2 0", "Cd"),
    ("types", "chain 0.1 120 5e8 -1 0 1.2 1 1e999 0", "CdAx"),
    ("types", "chain 0.1 120 5e8 -1 0 1.2 1 0.2", "10 columns"),
    ("types", None, "LINE TYPES section has no rows"),
    ("points", "1 Fixed west 0 -100 0 0 0 0", "point 1 X"),
    ("points", "1 Fixed -400 0 nan 0 0 0 0", "point 1 Z"),
    ("points", "1 Fixed -400 0 -100 -5 0 0 0", "point 1 Mass"),
    ("points", "1 Fixed -400 0 -100 0 1e400 0 0", "point 1 Volume"),
    ("points", "1 Fixed -400 0 -100 0 0 -1 0", "point 1 CdA"),
    ("points", "1 Fixed -400 0 -100 0 0 0 x", "point 1 Ca"),
    ("points", "1 Fixed -400 0 -100 0 0 0", "POINTS row must have 9"),
    ("points", "one Fixed -400 0 -100 0 0 0 0", "point ID"),
    ("points", "1.5 Fixed -400 0 -100 0 0 0 0", "point ID"),
    ("points", "1 Anchr -400 0 -100 0 0 0 0", "point 1 type"),
    ("points", "1 Fixed -400 0 -100 0 0 5 0 0 0 0", "point 1 constant force (FX FY FZ)"),
    ("points", "1 Fixed -400 0 -150 0 0 0 0", "point 1 Z must be >= -WtrDpth"),
    ("points", None, "POINTS section has no rows"),
    ("lines", "1 chain 1 2 -1e400 90 -", "UnstrLen"),
    ("lines", "1 chain 1 2 nan 90 -", "UnstrLen"),
    ("lines", "1 chain 1 2 long 90 -", "UnstrLen"),
    ("lines", "1 chain 1 2 1e400 90 -", "UnstrLen"),
    ("lines", "1 chain 1 2 -0 90 -", "UnstrLen"),
    ("lines", "1 chain 1 2 450 1e8 -", "NumSegs"),
    ("lines", "1 chain 1 2 450 1e30 -", "NumSegs"),
    ("lines", "1 chain 1 2 450 0 -", "NumSegs"),
    ("lines", "1 chain 1 2 450 -3 -", "NumSegs"),
    ("lines", "1 chain 1 2 450 2.5 -", "NumSegs"),
    ("lines", "1 chian 1 2 450 90 -", "LineType"),
    ("lines", "1 chain 1 9 450 90 -", "AttachB"),
    ("lines", "1 chain X1 2 450 90 -", "AttachA"),
    ("lines", "1 chain 2 2 450 90 -", "AttachA and AttachB"),
    ("lines", "1 chain 1 2 450 90", "LINES row must have 7"),
    ("lines", "x chain 1 2 450 90 -", "line ID"),
    ("lines", None, "LINES section has no rows"),
    ("options", "-100 WtrDpth", "option WtrDpth"),
    ("options", "nan WtrDpth", "option WtrDpth"),
    ("options", "deep WtrDpth", "option WtrDpth"),
    ("options", "heavy g", "option g"),
    ("options", "-3e6 kBot", "option kBot"),
    ("options", "1.5 WaveKin", "option WaveKin"),
    ("options", "-1 FrictionCoefficient", "option FrictionCoefficient"),
    ("options", "-0.5 mu_kA", "option mu_kA"),
    ("options", "0 StatDynFricScale", "option StatDynFricScale"),
    ("options", "1e999 dtM", "option dtM"),
    ("options", "100", "option line must be 'value name"),
]


def test_negative_length_factor_on_coincident_points_is_refused():
    """MoorDyn: UnstrLen < 0 is a factor on the end-point distance; with both ends at one place it is 0."""
    points = (ANCHOR, "2 Vessel -400 0 -100 0 0 0 0")
    with pytest.raises(InputError, match=r"^<MoorDyn text>:15: line 1 UnstrLen \(unstretched length\) must be > 0 m"):
        read_moordyn(deck(points=points, lines=("1 chain 1 2 -1.5 90 -",)))
    ok = read_moordyn(deck(lines=("1 chain 1 2 -1.2 90 -",)))  # 1.2 x |(400, 0, 95)|
    assert ok.lines[0].length == pytest.approx(1.2 * math.hypot(400.0, 95.0), rel=1e-14)


@pytest.mark.parametrize("section, row, field", BAD, ids=[f"{s}:{r}" for s, r, _ in BAD])
def test_bad_deck_is_one_input_error_naming_line_and_field(section, row, field):
    text, lineno = _variant(section, row)
    try:
        read_moordyn(text)
    except InputError as exc:
        message = str(exc)
    except Exception as exc:  # noqa: BLE001 - the point of the test: no other exception type
        pytest.fail(f"{type(exc).__name__} instead of InputError: {exc}")
    else:
        pytest.fail("no error")
    assert message.startswith(f"<MoorDyn text>:{lineno}: "), message
    assert field in message, message
    assert "Suggested fix:" in message

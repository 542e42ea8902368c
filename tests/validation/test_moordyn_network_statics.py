"""A MoorDyn deck's line-network statics (``mooring_static``: the deck's NumSegs lumped-mass segments) against the
exact elastic catenary, and the warning that says when they differ.

Four plain line-and-point decks differed from MoorPy by more than 1 % in the network's statics: the r-test
MHK_RM1_Floating chains (13.2 % at an anchor), MoorPy's case6 (5.9 %, now 2.4 %) and MoorDyn's seafloor pendulum (MoorPy
stalls there). The first two are the network's discretisation: the chains bend at touchdown with a radius of
curvature H / w (2.3 m, 29 m) near or under their segment length (5.1 m, 33 m), and the network's horizontal
tension is off until the segments are refined; MoorPy and seacable's system statics (exact catenaries) agree with
the closed form below. The run now says so (:func:`seacable.mooring.moordyn.catenary_check`). The seafloor
pendulum's tension is m g (closed form; test_a_pendulum_on_a_stiff_slack_line_swings_down_plumb) in the network as
in the system statics: MoorPy is the one that is wrong there.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from _evidence import check
from scipy.optimize import fsolve

from seacable.errors import SeacableWarning
from seacable.io.moordyn import load_moordyn_case
from seacable.mooring.moordyn import run_moordyn_case

HERE = Path(__file__).parent / "data" / "moordyn_decks"

# Line 2 of OpenFAST r-test glue-codes/openfast/MHK_RM1_Floating/MHK_RM1_Floating_MoorDyn.dat (commit e4f825bd,
# Apache-2.0), alone: a 152 m studless chain from an anchor at 50 m (no WtrDpth: the seabed at the deepest point, as
# MoorDyn-C sets it) to a fairlead 40 m above it and 118 m away, 30 segments, most of it on the seabed.
MHK_LINE = """--------------------- MoorDyn Input File ------------------------------------
MHK_RM1_Floating line 2 (OpenFAST r-test)
----------------------- LINE TYPES ------------------------------------------
Name     Diam     MassDen     EA        BA/-zeta   EI   Cd   Ca   CdAx   CaAx
(-)      (m)      (kg/m)      (N)       (N-s/-)    (-)  (-)  (-)  (-)    (-)
main     0.324    644.8       85.4e8    -0.8       0.8  2.4  1.0  1.15   0.5
---------------------- POINTS -----------------------------------------------
Node     Type      X        Y        Z       M     V      CdA    CA
(-)      (-)       (m)      (m)      (m)     (kg)  (m^3)  (m^2)  (-)
1        Fixed     -152.0   0.0      -50.0   0     0      0      0
2        Vessel    -34.0    0.0      -10.0   0     0      0      0
---------------------- LINES ------------------------------------------------
Line     LineType  AttachA  AttachB   UnstrLen   NumSegs   Outputs
(-)      (-)       (-)      (-)       (m)        (-)       (-)
1        main      1        2         152.0      {n}         -
---------------------- SOLVER OPTIONS ---------------------------------------
3.0e6    kbot      - bottom stiffness (Pa/m)
3.0e5    cbot      - bottom damping (Pa-s/m)
------------------------- need this line ------------------------------------
"""


def _touchdown_catenary(span, height, length, w, ea):
    """The elastic catenary of a line lying on a frictionless seabed from its anchor (Jonkman 2007, eq. 2-3 with the
    friction coefficient 0): the horizontal span and height of the fairlead above the anchor give H and V,

    span   = L - V / w + (H / w) asinh(V / H) + H L / EA
    height = (H / w) (sqrt(1 + (V / H)^2) - 1) + V^2 / (2 EA w)

    Returns (anchor tension H, fairlead tension sqrt(H^2 + V^2)) [N]."""
    def residual(x):
        h, v = np.exp(x)  # positive unknowns
        return [length - v / w + h / w * math.asinh(v / h) + h * length / ea - span,
                h / w * (math.sqrt(1 + (v / h) ** 2) - 1) + v**2 / (2 * ea * w) - height]

    x, _, ok, msg = fsolve(residual, np.log([1e4, w * 40.0]), xtol=1e-13, full_output=True)
    assert ok == 1, msg
    h, v = np.exp(x)
    assert length - v / w > 0  # part of the line lies on the seabed, as the closed form assumes
    return h, math.hypot(h, v)


def _mhk_closed_form():
    w = (644.8 - 1025.0 * math.pi * 0.324**2 / 4) * 9.80665
    return _touchdown_catenary(118.0, 40.0, 152.0, w, 85.4e8)


def _run(tmp_path, segments):
    deck = tmp_path / f"mhk_{segments}.dat"
    deck.write_text(MHK_LINE.replace("{n}", str(segments)))
    return run_moordyn_case(load_moordyn_case(deck))


def test_moorpy_solves_the_mhk_chain_as_the_closed_form():
    """MoorPy 1.3.0 on the same line: its anchor and fairlead tensions are the closed form's to 1e-6 (both exact
    catenaries; the closed form's own solve is at 1e-13)."""
    mp = pytest.importorskip("moorpy")
    anchor, fair = _mhk_closed_form()
    import tempfile

    with tempfile.TemporaryDirectory() as tmp, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        path = Path(tmp) / "mhk.dat"
        path.write_text(MHK_LINE.replace("{n}", "30"))
        ms = mp.System(file=str(path), depth=50.0, rho=1025.0, g=9.80665)
        ms.initialize()
        ms.solveEquilibrium(tol=1e-8)
    line = ms.lineList[0]
    check([line.TA, line.TB], [anchor, fair], rtol=1e-6, source="Closed form: elastic catenary (MHK chain)",
          unit="N", quantity="MoorPy 1.3.0's anchor and fairlead tensions of the MHK chain",
          why="both are exact catenaries; the closed form is solved to 1e-13")
    assert anchor == pytest.approx(12467.19, rel=1e-5) and fair == pytest.approx(232247.09, rel=1e-5)


def test_a_network_too_coarse_for_its_touchdown_says_so(tmp_path):
    """The deck's 30 segments of 5.07 m on a chain whose touchdown radius of curvature is H / w = 2.27 m: the
    network's anchor tension is 13.2 % over the closed form (14110 N against 12467 N). The run warns, naming the
    line end, both tensions and H / w, and records the difference; before the check it said nothing."""
    anchor, fair = _mhk_closed_form()
    with pytest.warns(SeacableWarning, match=r"line 1 end A: 14109\.\d N in the network, 12467\.2 N in the exact "
                                             r"catenary \(\+13\.2 %; 30 segments of 5\.07 m, its catenary's H / w "
                                             r"2\.27 m\)"):
        ds = _run(tmp_path, 30)
    # the network's own answer is the one off (the discretisation), by 13 % at the anchor and 2.4 % at the fairlead
    assert float(ds["anchor_tension"]) == pytest.approx(anchor * 1.1317, rel=1e-3)
    assert float(ds["fairlead_tension"]) == pytest.approx(fair * 1.0245, rel=1e-3)
    assert ds.attrs["catenary_difference"] == pytest.approx(0.1317, abs=1e-3)


def test_the_refined_network_converges_to_the_closed_form(tmp_path):
    """The same line on 240 segments (0.63 m, under H / w): the network is within 0.3 % of the closed form at both
    ends (measured 0.18 % at the anchor, 0.03 % at the fairlead), and the run does not warn (pytest makes a
    SeacableWarning an error)."""
    anchor, fair = _mhk_closed_form()
    ds = _run(tmp_path, 240)
    assert float(ds["anchor_tension"]) == pytest.approx(anchor, rel=3e-3)
    assert float(ds["fairlead_tension"]) == pytest.approx(fair, rel=3e-3)
    assert ds.attrs["catenary_difference"] < 3e-3


def test_case6_network_warns_where_its_touchdown_is_coarse():
    """MoorPy's case6 (a W of three chains through a buoy and a sinker on the seabed): its 33 m segments against
    H / w = 29 m at the sinker. The network's two line ends at the sinker (line 3 lifting off 2.35 m from it, within
    its first segment) are both the network's H, 2.44 % under the exact catenary's H = 133288 N (MoorPy's to 1e-7:
    test_statics_agree_with_moorpy); the run says so. Line 3's end read 141161 N (+5.9 %) when the end force at a
    grounded end was its segment's pull alone (seacable.mooring.run.grounded_end_force)."""
    with pytest.warns(SeacableWarning, match=r"up to 2\.4\d % .*line 3 end A: 130031 N in the network, 133288 N"):
        ds = run_moordyn_case(load_moordyn_case(HERE / "MoorPy/tests/case6.dat"))
    assert ds.attrs["catenary_difference"] == pytest.approx(0.0244, abs=5e-4)


def test_seafloor_pendulum_network_hangs_by_its_weight():
    """MoorDyn's seafloor deck: a 10 kg point on a 32 m line as dense as the water, EA 1e9 N. The network, like
    the system statics, carries m g = 98.0665 N (closed form; 1e-5: the line's residual buoyancy is 5e-6 of m g).
    MoorPy 1.3.0 stalls on it (1999 iterations, a residual of -98.07 N = m g on the point: its point is not in
    equilibrium), so its 'answer' is not compared. The deck's SeafloorFile (a seabed sloping up to z = -30 + 0.1 x,
    which the pendulum was meant to hit) is not read; the run warns that it takes the flat seabed at WtrDpth 500 m
    instead, as MoorPy does."""
    with pytest.warns(SeacableWarning, match="SeafloorFile"):
        ds = run_moordyn_case(load_moordyn_case(HERE / "MoorDyn/tests/Mooring/seafloor.txt"))
    weight = 10.0 * 9.80665
    assert float(ds["fairlead_tension"]) == pytest.approx(weight, rel=1e-5)
    assert float(ds["anchor_tension"]) == pytest.approx(weight, rel=1e-5)
    assert ds.attrs["catenary_difference"] < 1e-5

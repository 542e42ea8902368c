"""The pretension helper (issue 41), :func:`seacable.mooring.pretension.line_length_for`, against the elastic
catenary with seabed contact in closed form and against MoorPy's catenary.

References
----------
Irvine, H. M. (1981). Cable Structures, MIT Press; Jonkman, J. M. (2007). Dynamics modeling and loads analysis of
an offshore floating wind turbine, NREL/TP-500-41958, eqs. (C-2): the elastic catenary resting on a frictionless
seabed, in closed form given its horizontal tension H.
Hall, M. et al., MoorPy (NREL), ``moorpy.Catenary.catenary`` (in the ``test`` extra; under CI a missing MoorPy is an
error, as in test_moorpy_catenary.py).

The OC3-Hywind line (Jonkman 2010, NREL/TP-500-47535 Table 5-1): anchor 320 m deep, fairlead 70 m deep 848.67 m
away, w = 698.094 N/m, EA = 384.243e6 N, 902.2 m long in the case.
"""

import importlib
import math
import os
from pathlib import Path

import pytest
import yaml
from scipy.optimize import brentq

import seacable as sc
from seacable.errors import InputError, NoSolutionError
from seacable.mooring.pretension import line_length_for

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
X_F, Z_F, W, EA = 848.67, 250.0, 698.094, 384.243e6

if os.environ.get("CI"):
    moorpy_catenary = importlib.import_module("moorpy.Catenary").catenary
else:
    moorpy_catenary = pytest.importorskip("moorpy.Catenary").catenary


@pytest.fixture(scope="module")
def oc3():
    return sc.load_case(EXAMPLES / "oc3_hywind_static.yaml")


def _closed_form(H: float) -> tuple[float, float]:
    """(unstretched length L [m], fairlead tension [N]) of the elastic catenary on a frictionless seabed spanning
    (X_F, Z_F) with horizontal tension H: the suspended length Ls from the height equation
    z = H/w (sqrt(1 + (w Ls / H)^2) - 1) + w Ls^2 / (2 EA), then L from the span equation
    x = L - Ls + H/w asinh(w Ls / H) + H L / EA; the tension sqrt(H^2 + (w Ls)^2)."""
    def height(ls):
        return H / W * (math.sqrt(1 + (W * ls / H) ** 2) - 1) + W * ls**2 / (2 * EA) - Z_F

    ls = brentq(height, 0.0, 10 * Z_F, xtol=1e-13, rtol=1e-15)
    length = (X_F + ls - H / W * math.asinh(W * ls / H)) / (1 + H / EA)
    assert ls < length  # part of the line on the seabed: the closed form's regime
    return length, math.hypot(H, W * ls)


@pytest.mark.parametrize("H", [2.0e5, 4.0e5, 7.5e5])
def test_the_length_from_a_target_tension_is_the_closed_forms(oc3, H):
    """The closed form gives the tension of a line of length L; asked for that tension, the helper returns L.
    Tolerance 1e-7 relative on L: the root is found to xtol = 1e-9 of the length (9e-7 m), and the catenary's
    Newton solve stops at a tension about 1e-8 relative off (4e-9 measured), which through dT/dL of 1e4 to 1e5 N/m
    moves L by less than 1e-6 m. The tension at the root is off by dT/dL x xtol, 1e-7 relative at most."""
    length, tension = _closed_form(H)
    found = line_length_for(oc3, target_tension=tension)
    assert found.length == pytest.approx(length, rel=1e-7)
    assert found.tension == pytest.approx(tension, rel=1e-7)
    # the angle below the horizontal of that line: atan(w Ls / H)
    assert found.angle == pytest.approx(math.atan2(math.sqrt(tension**2 - H**2), H), rel=1e-7)
    # and the case it returns runs to that tension
    assert float(sc.run(found.case).fairlead_tension) == pytest.approx(tension, rel=1e-7)


def test_the_length_from_a_target_angle_is_the_closed_forms(oc3):
    """The same line by its fairlead angle below the horizontal (tolerance as above)."""
    length, tension = _closed_form(5.0e5)
    angle = math.acos(5.0e5 / tension)
    found = line_length_for(oc3, target_angle=angle)
    assert found.length == pytest.approx(length, rel=1e-7)
    assert found.angle == pytest.approx(angle, rel=1e-7)


def test_moorpy_chain_tension_gives_back_its_length(oc3):
    """MoorPy's catenary of the OC3 chain at 880 m gives a fairlead tension; the helper, asked for it, returns
    880 m. Tolerance 1e-6 relative: MoorPy iterates to a span error Tol = 1e-9 L, and its tension agrees with
    seacable's catenary to 1e-6 relative or better (test_moorpy_catenary.py: 1e-5 bound); near the OC3 line,
    dT/dL = -2.9e4 N/m, so 1e-6 of 9e5 N is 3e-5 m of length, 3e-8 relative."""
    true_length = 880.0
    _, _, fxb, fzb, _ = moorpy_catenary(X_F, Z_F, true_length, EA, W, CB=0.0, Tol=1e-9 * true_length)
    tension = math.hypot(fxb, fzb)
    found = line_length_for(oc3, target_tension=tension)
    assert found.length == pytest.approx(true_length, rel=1e-6)


def test_mooring_static_finite_element_line_agrees(oc3):
    """The helper on the finite-element line (mooring_static, 2 m elements) finds the catenary's length to the
    element discretisation error (the FE line's fairlead tension is within 0.1 % of the catenary's at this
    mesh: a length within 0.3 %, dT/dL amplifying it by T/(L dT/dL) ~ 3)."""
    data = yaml.safe_load((EXAMPLES / "oc3_hywind_static.yaml").read_text())
    data["analysis"] = {"type": "mooring_static", "fairlead": [X_F, -70.0], "element_length": 20.0}
    case = sc.Case.parse(data)
    length, tension = _closed_form(7.5e5)
    found = line_length_for(case, target_tension=tension)
    assert found.tension == pytest.approx(tension, rel=1e-8)
    assert found.length == pytest.approx(length, rel=3e-3)
    # the two ways of reading the angle agree (the FE fairlead force against the catenary's V/H)
    assert found.angle == pytest.approx(line_length_for(oc3, target_tension=tension).angle, rel=1e-2)


def test_a_system_line_for_its_pretension_with_the_body_re_solved():
    """The spread mooring's line1 lengthened to a lower pretension: the buoy moves (re-solved), and the run of the
    returned case gives the target to the solver's tolerance."""
    data = yaml.safe_load((EXAMPLES / "spread_mooring.yaml").read_text())
    data["analysis"] = {"type": "system_static"}   # the intact system (the damaged condition is not needed)
    case = sc.SystemCase.parse(data)
    before = sc.run(case)
    t0 = float(before.fairlead_tension.sel(condition="intact", line="line1"))
    found = line_length_for(case, target_tension=0.8 * t0, line="line1")
    after = sc.run(found.case)
    assert float(after.fairlead_tension.sel(condition="intact", line="line1")) == pytest.approx(0.8 * t0, rel=1e-8)
    assert found.length > case.lines["line1"].line.length        # a slacker line is a longer one
    moved = abs(float(after.body_x.sel(condition="intact").values[0] - before.body_x.sel(condition="intact")
                      .values[0]))
    assert moved > 1e-3  # the buoy re-solved: it moved away from the slackened line


def test_unreachable_targets_are_refused_with_the_range(oc3):
    # below w h = 698.094 N/m x 250 m = 174.5 kN: no length of this line hangs lighter from the fairlead
    with pytest.raises(NoSolutionError, match=r"target_tension = 100 kN cannot be reached.*174\.\d+ kN"):
        line_length_for(oc3, target_tension=1e5)
    with pytest.raises(NoSolutionError, match="target_angle"):
        line_length_for(oc3, target_angle=0.01)   # flatter than a taut line can be between these ends
    with pytest.raises(InputError, match="one target"):
        line_length_for(oc3)
    with pytest.raises(InputError, match="target_tension must be > 0 N, got -5 N"):
        line_length_for(oc3, target_tension=-5.0)
    with pytest.raises(InputError, match=r"between 0 and pi/2 rad.*got 40 rad.*Suggested fix"):
        line_length_for(oc3, target_angle=40.0)
    with pytest.raises(InputError, match="segment 3 is not a segment"):
        line_length_for(oc3, target_tension=1e6, segment=3)
    with pytest.raises(InputError, match="analysis.type 'modal'"):
        line_length_for(sc.load_case(EXAMPLES / "oc3_hywind_modes.yaml"), target_tension=1e6)

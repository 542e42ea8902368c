"""Validation of the mooring finite-element model (truss elements, Newmark) of paper 004.

Sources
-------
- Paper 004 (``seeds/004_0937ea53f45f7fd0.txt``), Park & Lee, "A Study on the Behaviour of Mooring
  System for Guyed Tower": truss elements with geometric nonlinearity (eq. A6-A10), Newmark
  beta = 1/4, gamma = 1/2 with equilibrium iterations, and the Lena guyed tower guy line (Table 1:
  640 m guy line of 68.45 kg/m, 36.58 m clump of 4315 kg/m, 396.2 m anchor line, EA 1.87e9,
  305 m of water, fairlead 15.24 m below the surface). "kg/m" is read as kgf/m of weight in water
  and EA as newtons (SPEC.md; /tmp/paper004_reading.md section 4). Its findings (Figs 5-8, text
  L164-L179) are stated in words and percentages only; the figures are lost in the OCR.
- Irvine, H. M. (1981). Cable Structures. MIT Press, eq. 2.15-2.16, and Jonkman, J. M. (2007),
  NREL/TP-500-41958, section 2.2.1: the multi-segment elastic catenary of
  ``seacable.statics.multisegment``, the reference for the finite-element statics.
- Jonkman, J. (2010). Definition of the floating system for phase IV of OC3. NREL/TP-500-47535,
  Table 5-1 (the OC3-Hywind line of ``examples/oc3_hywind_line.yaml``).
- Newmark's average-acceleration rule conserves the energy of a linear undamped system exactly and
  is second-order accurate (Hughes, T. J. R. (2000). The Finite Element Method, Dover, ch. 9.1).

The seabed of the finite-element model is a penalty spring, 3e6 Pa/m by default (MoorDyn's kBot):
a line resting on it sinks by ``w / (k d)``, 2.6 mm for the OC3 line and 5.8 mm for the Lena clump;
the catenary's seabed is rigid. The sinkage enters the comparisons only at the 1e-5 level of the span.
"""

from pathlib import Path

import numpy as np
import pytest
import yaml
from _evidence import check
from scipy.optimize import brentq

import seacable
from seacable.line import Line, LineType, PointMass, Segment
from seacable.mooring.network import network_from_line
from seacable.mooring.solver import MooringModel, Water, pushover, simulate, static_equilibrium
from seacable.statics import multisegment as ms

G = 9.80665
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

# --- Lena guy line (paper 004 Table 1) ---
DEPTH, Z_FAIR = 305.0, -15.24
V_SPAN = DEPTH + Z_FAIR
EA_LENA = 1.87e9
# A "hard" seabed for the Lena runs (paper 004 L145: "hard enough to support the clump weight").
# The default 3e6 Pa/m lets a lumped clump, which bears on the line's 0.127 m diameter only, sink
# W / (k d l) = 1.55e6 / (3e6 * 0.127 * 1 m) = 4 m; 3e9 Pa/m makes that 4 mm.
HARD_BED = 3.0e9


def _lt(weight_kgf, diameter=0.127):
    return LineType(diameter=diameter, mass_per_length=weight_kgf, weight_in_water=weight_kgf * G,
                    axial_stiffness=EA_LENA)


GUY = _lt(68.45)


def lena_line(anchor=396.2, clump_length=36.58, clump_weight=4315.0, lumped=False, h=5.0, dh=1.0):
    """The Lena line from the anchor: anchor line, clump (a heavy segment or a PointMass at its
    middle), 640 m guy line; elements of ``h`` on the wire and ``dh`` on and near the clump. [m]"""
    segs, att = [], ()
    if anchor > 0:
        segs.append(Segment(line_type=GUY, length=anchor, n_elements=max(2, round(anchor / h))))
    if lumped:
        half = clump_length / 2
        segs.append(Segment(line_type=GUY, length=half, n_elements=max(2, round(half / dh))))
        segs.append(Segment(line_type=GUY, length=half + 640.0, n_elements=round((half + 640.0) / h)))
        att = (PointMass(s=anchor + half, weight_in_water=clump_weight * G * clump_length,
                         mass=clump_weight * clump_length, kind="clump"),)
    else:
        segs.append(Segment(line_type=_lt(clump_weight, 2.438), length=clump_length,
                            n_elements=max(4, round(clump_length / dh))))
        segs.append(Segment(line_type=GUY, length=640.0, n_elements=round(640.0 / h)))
    return Line(segments=tuple(segs), attachments=att)


def statics_args(line, rho=1025.0, g=G):
    return ([s.length for s in line.segments], list(line.weights(rho, g)),
            [s.line_type.axial_stiffness for s in line.segments], line.point_loads(rho, g))


def fe_model(line, anchor, fairlead, water, n_elements=None, seabed=True):
    """Network of ``line`` started on the catenary (so that Newton starts close), and the catenary."""
    L, w, ea, pl = statics_args(line, water.density, water.gravity)
    eq = ms.line_equilibrium(L, w, ea, fairlead[0] - anchor[0], fairlead[2] - anchor[2], point_loads=pl,
                             seabed=seabed)
    net = network_from_line(line, anchor, fairlead, water_density=water.density, gravity=water.gravity,
                            n_elements=n_elements)
    prof = eq.profile(points_per_segment=2000)
    keep = np.r_[True, np.diff(prof.s) > 0]
    x = anchor[0] + np.interp(net.arc_length, prof.s[keep], prof.x[keep])
    z = anchor[2] + np.interp(net.arc_length, prof.s[keep], prof.z[keep])
    return MooringModel(net.replace(position=np.column_stack([x, 0 * x, z])), water), eq, x, z


def static_errors(line, anchor, fairlead, water, n_elements=None, seabed=True):
    """Relative errors of the FE statics against the catenary: fairlead tension, anchor tension,
    largest node distance from the catenary point of the same arc length over the span."""
    model, eq, x, z = fe_model(line, anchor, fairlead, water, n_elements, seabed)
    st = static_equilibrium(model)
    # end tensions as the force of the line on its supports (it includes the half element's weight
    # lumped at the end node; that difference is part of the O(h^2) discretisation error)
    t_fair = np.linalg.norm(st.support[-1])
    t_anch = np.linalg.norm(st.support[0])
    pos = np.max(np.hypot(st.position[:, 0] - x, st.position[:, 2] - z)) / (fairlead[0] - anchor[0])
    return (abs(t_fair / eq.fairlead_tension - 1), abs(t_anch / eq.anchor_tension - 1), pos), st, eq


OC3 = LineType(diameter=0.09, mass_per_length=77.7066, weight_in_water=698.094, axial_stiffness=384.243e6)

# Tolerances of the FE statics against the analytic catenary: about three times the largest error
# measured for each case (issue 17: the former common 2e-3 was 20-150x looser than the agreement, so a
# physics error of 1e-3 would have passed). Each error is the lumped model's O(h^2) discretisation
# error, which is deterministic: a change of several times it means the model changed.
TOL_SUSPENDED_20 = 1.5e-3  # suspended line with 20 elements: measured 8.9e-4 (anchor), scaled by (20 / n)^2
TOL_OC3 = 1.5e-4           # OC3 line, 100 elements: measured 4.7e-5 (anchor), 3.8e-5 (fairlead)
TOL_LENA = 2.5e-4          # Lena line, distributed clump, 1 m clump elements: measured 8.5e-5 (1001 m span)
TOL_LENA_LUMPED = 5e-4     # Lena line, lumped clump: measured 1.9e-4 (1001 m, on the hard seabed)


def test_suspended_line_matches_catenary_and_converges_as_1_over_n2():
    # (a) 600 m of the OC3 line hanging between (0, -320) and (500, -70), no seabed.
    line = Line.single(OC3, 600.0)
    water = Water(density=1025.0, gravity=G, depth=None)
    errs = []
    for n in (20, 40, 80):
        e, _, _ = static_errors(line, (0, 0, -320.0), (500.0, 0, -70.0), water, n, seabed=False)
        errs.append(e)
        assert max(e) < TOL_SUSPENDED_20 * (20 / n) ** 2
    errs = np.array(errs)
    # Lumped weights on straight chords: the error is O(h^2). Measured ratios per halving 4.00 for
    # both tensions and the position (6.5e-4 -> 1.6e-4 -> 4.1e-5 in the fairlead tension);
    # [3.5, 4.5] is the band of an observed order 1.8-2.2.
    ratio = errs[:-1] / errs[1:]
    assert np.all((ratio > 3.5) & (ratio < 4.5)), ratio


def test_oc3_line_with_seabed_contact_matches_catenary():
    # (b) examples/oc3_hywind_line.yaml through the case path (mooring_static) and the low level.
    d = yaml.safe_load((EXAMPLES / "oc3_hywind_line.yaml").read_text())
    d["analysis"] = {"type": "mooring_static", "fairlead": d["analysis"]["fairlead"], "n_elements": 100}
    ds = seacable.run(seacable.parse_case(d))
    eq = ms.line_equilibrium([902.2], [698.094], [384.243e6], 848.67, 250.0)
    # measured: fairlead 3.8e-5, anchor 4.7e-5 with 100 elements; the error is not monotone in N
    # (+1.6e-4, -3.8e-5, +3e-7 for 50, 100, 200) because the touchdown falls between nodes,
    # so no order is asserted, only the bound of about 3x the measured error at N = 100.
    check(float(ds["fairlead_tension"]), eq.fairlead_tension, rtol=TOL_OC3, unit="N",
          source="Closed form: elastic catenary with seabed contact",
          quantity="OC3-Hywind line, fairlead tension, 100 truss elements (mooring_static)",
          why="about 3x the measured 3.8e-5; the touchdown falls between nodes, so no order")
    check(float(ds["anchor_tension"]), eq.anchor_tension, rtol=TOL_OC3, unit="N",
          source="Closed form: elastic catenary with seabed contact",
          quantity="OC3-Hywind line, anchor tension, 100 truss elements (mooring_static)",
          why="about 3x the measured 4.7e-5")
    water = Water(density=1025.0, gravity=G, depth=320.0)
    e, st, _ = static_errors(Line.single(OC3, 902.2), (0, 0, -320.0), (848.67, 0, -70.0), water, 100)
    assert max(e) < TOL_OC3, e
    # the grounded nodes sink by the penalty spring's w / (k d) = 698.094 / (3e6 * 0.09) = 2.59 mm
    # (nodes 2-7, well before the touchdown near node 10; 1 % covers the slope of the line there)
    grounded = st.position[2:8, 2] + 320.0
    np.testing.assert_allclose(grounded, -698.094 / (3e6 * 0.09), rtol=0.01)


def test_lena_distributed_clump_matches_catenary():
    # (c) Lena line at a 1001 m span (pretension about 1 MN) with the clump partly lifted
    # (29.6 of 36.58 m grounded) and at 980 m with the clump on the seabed. The clump needs fine
    # elements: H depends strongly on where it lifts off (with 2 elements on the clump, i.e. 50 on
    # the line, the error is 5.8 %). Measured with 1 m clump elements: 1.3e-5 (980 m) and 8.5e-5
    # (1001 m) in tension, 6e-6 of the span in position.
    water = Water(density=1025.0, gravity=G, depth=DEPTH)
    for span in (980.0, 1001.0):
        e, _, eq = static_errors(lena_line(), (0, 0, -DEPTH), (span, 0, Z_FAIR), water)
        assert eq.segment_grounded_length[1] > 0.0  # the clump touches the seabed
        assert max(e) < TOL_LENA, (span, e)


def test_lena_lumped_clump_matches_catenary():
    # (d) the clump as one PointMass at the clump's middle. Resting on the seabed (1001 m span),
    # the point load bears on the line's diameter only, so a hard seabed is needed (see HARD_BED:
    # the default 3e6 Pa/m gives +1.6 %, +3.3 %, +5.5 % for 40/80/160 anchor-line elements, an error
    # that grows with refinement, as the contact area d * l shrinks). Lifted (1012 m), the
    # seabed plays no part.
    for span, bed in ((1001.0, 3e10), (1012.0, 3e6)):
        water = Water(density=1025.0, gravity=G, depth=DEPTH, seabed_stiffness=bed)
        line = lena_line(lumped=True)
        e, _, eq = static_errors(line, (0, 0, -DEPTH), (span, 0, Z_FAIR), water)
        s_clump = line.attachments[0].s
        # resting: touchdown at the clump (a partial reaction); lifted: touchdown on the anchor line
        assert (eq.touchdown_s == pytest.approx(s_clump)) if span < 1010 else (0 < eq.touchdown_s < s_clump)
        assert max(e) < TOL_LENA_LUMPED, (span, e)


# --- paper 004 Figs 5-8: force-excursion trends of the Lena line ---
H0 = 1.0e6  # pretension: not printed; ~1 MN (anchor radius ~1001 m) reproduces the 39 % of Fig. 5
STEP = 0.5  # pushover offset step [m]; lift-off is then located by extrapolating the clump reaction


def span_for_pretension(line, H=H0):
    """Horizontal span at which the catenary's fairlead tension has horizontal part ``H``. [m]"""
    L, w, ea, pl = statics_args(line)
    total = sum(L)
    return brentq(lambda x: ms.line_equilibrium(L, w, ea, x, V_SPAN, point_loads=pl).H_fairlead - H,
                  total - V_SPAN, np.sqrt(total**2 - V_SPAN**2) + 0.005 * total, xtol=1e-6)


def force_excursion(anchor=396.2, clump_length=36.58, clump_weight=4315.0, lumped=False, max_offset=12.0):
    """FE pushover from the 1 MN pretension: offsets, H, lift-off offset and H there, secant stiffness.

    Lift-off is when the whole clump has left the seabed (paper 004 L166, "모두 들릴 때"): the
    seabed reaction on the clump nodes, linear in the grounded length near lift-off, is extrapolated
    to zero from the last two grounded offsets, and the FE line is solved again there.
    """
    line = lena_line(anchor, clump_length, clump_weight, lumped)
    water = Water(density=1025.0, gravity=G, depth=DEPTH, seabed_stiffness=HARD_BED)
    span = span_for_pretension(line)
    model, *_ = fe_model(line, (0, 0, -DEPTH), (span, 0, Z_FAIR), water)
    offsets = np.arange(0.0, max_offset + 1e-9, STEP)
    states = pushover(model, offsets)
    H = np.array([-st.support[-1, 0] for st in states])
    s = model.network.arc_length
    if lumped:
        on = np.isclose(s, line.attachments[0].s)
    else:
        on = (s >= anchor - 1e-9) & (s <= anchor + clump_length + 1e-9)
    on[0] = False  # the anchor node (no anchor line) is fixed
    reaction = np.array([np.sum(HARD_BED * model.bedc[on] * np.maximum(-(st.position[on, 2] + DEPTH), 0.0))
                         for st in states])
    i = int(np.flatnonzero(reaction <= 0.0)[0])
    x_lift = offsets[i - 1] + STEP * reaction[i - 1] / (reaction[i - 2] - reaction[i - 1])
    H_lift = -pushover(model, [x_lift], initial=states[i - 1])[0].support[-1, 0]
    return {"offsets": offsets, "H": H, "i": i, "x_lift": x_lift, "H_lift": H_lift, "span": span,
            "stiffness": (H_lift - H[0]) / x_lift}


def test_fe_pushover_matches_statics_pushover():
    # FE against the analytic pushover at offsets before (0, 3, 6 m) and after (9 m) clump lift-off,
    # through the case path (mooring_pushover) with the example's line. Measured: <= 2.3e-4.
    # 0.5 %: the brief's bound; the discretisation error here is ~1e-4 (1 m clump elements).
    d = yaml.safe_load((EXAMPLES / "paper004_lena_pushover.yaml").read_text())
    d["line"]["segments"][1]["n_elements"] = 36
    offsets = [0.0, 3.0, 6.0, 9.0]
    d["analysis"] = {"type": "mooring_pushover", "fairlead": [1001.0, Z_FAIR], "offsets": offsets,
                     "element_length": 2.0, "seabed_contact": {"stiffness": HARD_BED}}
    case = seacable.parse_case(d)
    ds = seacable.run(case)
    L = [s.length for s in case.line.segments]
    w = list(case.line.weights(case.environment.water_density, case.environment.gravity))
    ref = ms.pushover(L, w, [EA_LENA] * 3, 1001.0, DEPTH + Z_FAIR, offsets)
    np.testing.assert_allclose(ds["H_fairlead"].values, ref.H_fairlead, rtol=5e-3)
    assert ref.segment_grounded_length[0, 1] > 0 and ref.segment_grounded_length[-1, 1] == 0  # both branches


@pytest.fixture(scope="module")
def lena_curves():
    out = {"distributed": force_excursion(), "lumped": force_excursion(lumped=True)}
    for length in (24.38, 48.77):
        out[f"length {length}"] = force_excursion(clump_length=length, clump_weight=4315.0 * 36.58 / length)
    for weight in (2232.0, 3423.0, 5209.0):
        out[f"weight {weight}"] = force_excursion(clump_weight=weight)
    for anchor in (305.0, 488.0, 1524.0):
        out[f"anchor {anchor}"] = force_excursion(anchor=anchor)
    out["no anchor line"] = force_excursion(anchor=0.0)
    return out


def test_lumped_clump_overestimates_initial_stiffness(lena_curves):
    """Fig. 5 (L164): the lumped clump overestimates the initial stiffness by about 39 % and lifts
    off at a smaller offset.

    Measured: lift-off at 7.18 m (distributed) and 5.26 m (lumped) at H = 3.60 and 3.63 MN; secant
    stiffness from the 1 MN pretension to lift-off 362 and 501 kN/m: ratio 1.383 against the paper's
    1.39. The ratio depends on the pretension, which is not printed (1.32 at 0.9 MN, 1.49 at 1.2 MN
    in the catenary model of /tmp/paper004_reading.md, a slope of 0.57 per MN), so the band +-0.03 is
    the ratio's change for a +-5 % change of pretension about 1 MN.
    """
    d, lump = lena_curves["distributed"], lena_curves["lumped"]
    assert lump["x_lift"] < d["x_lift"]
    check(lump["stiffness"] / d["stiffness"], 1.39, atol=0.03, source="Paper 004 (guyed-tower mooring), Fig. 5",
          quantity="Lena tower: initial stiffness of a lumped clump over a distributed one",
          why="the ratio's change for +-5 % of the unprinted pretension about 1 MN")


def test_longer_clump_is_softer_and_lifts_later(lena_curves):
    """Fig. 6 (L166): same total weight, clump 24.38 / 36.58 / 48.77 m: the stiffness falls and the
    offset at full lift-off rises (no percentages printed). Measured: 401 / 362 / 332 kN/m and
    6.40 / 7.18 / 7.95 m."""
    runs = [lena_curves["length 24.38"], lena_curves["distributed"], lena_curves["length 48.77"]]
    k = [r["stiffness"] for r in runs]
    x = [r["x_lift"] for r in runs]
    assert k[0] > k[1] > k[2]
    assert x[0] < x[1] < x[2]


def test_heavier_clump_is_stiffer(lena_curves):
    """Fig. 7 (L168): clump 2232 / 3423 / 4316 / 5209 kgf/m raises the initial stiffness by
    +42 / +86 / +120 % over 2232 kgf/m, less than the weight ratios +53 / +93 / +133 %.

    Measured: +44 / +74 / +101 % (4316 taken as 4315, the Table 1 clump). The first is within 2
    points of the paper; the heavier two are 12 and 19 points below it. The trend and its
    less-than-proportional size are reproduced; the paper's larger values for the heavy clumps cannot
    be reached with a 1 MN pretension (which fixes Fig. 5's 39 %) and are not otherwise
    recoverable: the anchor radius and pretension of each run are not printed, and a
    pretension that varies with the clump changes the secant. Asserted: the trend, each increase
    below the weight ratio, +42 % within 5 points, and the heavier two within 25 points below.
    """
    base = lena_curves["weight 2232.0"]["stiffness"]
    gain = np.array([lena_curves["weight 3423.0"]["stiffness"], lena_curves["distributed"]["stiffness"],
                     lena_curves["weight 5209.0"]["stiffness"]]) / base - 1
    assert np.all(np.diff(gain) > 0) and gain[0] > 0
    assert np.all(gain < np.array([3423.0, 4315.0, 5209.0]) / 2232.0 - 1)
    check(gain[0], 0.42, atol=0.05, source="Paper 004 (guyed-tower mooring), Fig. 7",
          quantity="Lena tower: initial stiffness gain of a 3423 over a 2232 kgf/m clump",
          why="5 points: the runs' pretension and anchor radius are not printed (docstring)")
    assert np.all((gain[1:] > np.array([0.86, 1.20]) - 0.25) & (gain[1:] < np.array([0.86, 1.20])))


def test_longer_anchor_line_lifts_later(lena_curves):
    """Fig. 8 (L179): anchor line 305 / 396 / 488 / 1524 m raises the offset at lift-off by about
    7 / 14 / 167 % over 305 m.

    Measured (same 1 MN pretension): +1.9 / +3.7 / +24 %: the trend only. On a frictionless seabed
    the extra anchor line only adds its stretch between pretension and lift-off,
    (H_lift - H0) dL / EA, which is linear in dL; the paper's 7:14 is linear but its 167 % is not,
    so its model held extra anchor-line compliance that cannot be recovered. Asserted: the trend
    and our closed-form stretch increment (1.69 m for 1219 m more anchor line) within 3 %, the
    resolution of the extrapolated lift-off (~0.02 m on 1.7 m) plus the 0.1 % spread of H_lift.
    """
    runs = [lena_curves["anchor 305.0"], lena_curves["distributed"], lena_curves["anchor 488.0"],
            lena_curves["anchor 1524.0"]]
    x = np.array([r["x_lift"] for r in runs])
    assert np.all(np.diff(x) > 0)
    a, b = runs[0], runs[-1]
    stretch = (0.5 * (a["H_lift"] + b["H_lift"]) - H0) * (1524.0 - 305.0) / EA_LENA
    check(b["x_lift"] - a["x_lift"], stretch, rtol=0.03, source="Closed form: anchor-line stretch (Lena tower)",
          unit="m", quantity="lift-off offset gained by 1219 m more anchor line = (H_lift - H0) dL / EA",
          why="the extrapolated lift-off's resolution (~0.02 m on 1.7 m) and H_lift's 0.1 % spread")


def test_anchor_line_gives_softening_after_liftoff(lena_curves):
    """Paper 004 L179: without an anchor line the offset keeps growing at about the same stiffness
    after the clump lifts (no softening); with one, the line softens. Tangent slopes over the
    0.5 m steps just before and after lift-off: measured after/before 1.64 without the anchor line
    (it even stiffens), 0.24 with it. Bounds 0.9 and 0.5 separate the two behaviours with margin."""

    def after_over_before(r):
        H, i = r["H"], r["i"]
        return (H[i + 2] - H[i + 1]) / (H[i - 1] - H[i - 2])

    assert after_over_before(lena_curves["no anchor line"]) > 0.9
    assert after_over_before(lena_curves["distributed"]) < 0.5


# --- Newmark (beta 1/4, gamma 1/2) without damping ---
def swinging_line():
    """10 elements of a 10 m line (1 kg/m, EA 1e4 N) between fixed ends 8 m apart, in vacuum (no
    drag, no added mass, no seabed), and a start: the static sag rotated 40 deg about the chord.

    The rigid rotation keeps every element at its static length, so the start excites the slow
    swing (period ~3.5 s) and only weakly the axial modes (~300 rad/s).
    """
    lt = LineType(diameter=0.01, mass_per_length=1.0, weight_in_water=G, axial_stiffness=1e4,
                  drag_normal=0.0, drag_tangential=0.0, added_mass_normal=0.0, added_mass_tangential=0.0)
    net = network_from_line(Line.single(lt, 10.0), (0, 0, 0), (8.0, 0, 0), water_density=0.0, gravity=G,
                            n_elements=10)
    model = MooringModel(net, Water(density=0.0, gravity=G, depth=None))
    s = net.arc_length
    sag = np.column_stack([0.8 * s, 0 * s, -3.0 * np.sin(np.pi * s / 10.0)])
    X = static_equilibrium(model, sag).position
    th = np.radians(40.0)
    start = X.copy()
    start[:, 1], start[:, 2] = -X[:, 2] * np.sin(th), X[:, 2] * np.cos(th)
    return model, start


def total_energy(model, run):
    """Kinetic 1/2 v^T M v (lumped mass), strain sum 1/2 EA/L (l - L)^2 of taut elements and the
    potential of the node weights, at each stored time. [J]"""
    net = model.network
    mass = np.zeros(net.n_nodes)
    half = 0.5 * net.mass_per_length * net.length
    np.add.at(mass, net.elements[:, 0], half)
    np.add.at(mass, net.elements[:, 1], half)
    kinetic = 0.5 * np.einsum("n,tni,tni->t", mass, run.velocity, run.velocity)
    chord = run.position[:, net.elements[:, 1]] - run.position[:, net.elements[:, 0]]
    stretch = np.maximum(np.linalg.norm(chord, axis=-1) - net.length, 0.0)
    strain = 0.5 * np.sum(net.axial_stiffness / net.length * stretch**2, axis=-1)
    potential = np.einsum("n,tn->t", net.node_weight(), run.position[:, :, 2])
    return kinetic + strain + potential, kinetic


def test_newmark_conserves_energy_without_damping():
    # 20 s (about 6 swings), dt 5 ms. Average acceleration conserves the energy of a linear system
    # exactly; for this nonlinear one the drift is O(dt^2) and the Newton tolerance's. Measured:
    # max - min of the total energy 5.4e-5 of the largest kinetic energy (38 J). 1e-3 allows for the
    # tolerance of the Newton iterations (1e-10 of the force scale) while a dissipative rule
    # (gamma 0.6, beta 0.3025, tested below) loses 7.2 % of it; the 1 % bound shows the energy test
    # can fail.
    model, start = swinging_line()
    run = simulate(model, None, 20.0, 0.005, 0.05, initial=start, tol=1e-10)
    energy, kinetic = total_energy(model, run)
    assert kinetic.max() > 30.0  # the line really swings
    assert np.ptp(energy) < 1e-3 * kinetic.max()
    damped = simulate(model, None, 20.0, 0.005, 0.05, initial=start, tol=1e-10, gamma=0.6, beta=0.3025)
    e_damped, _ = total_energy(model, damped)
    assert e_damped[0] - e_damped[-1] > 1e-2 * kinetic.max()


def test_newmark_is_second_order():
    # Position error of all nodes at t = 1 s against a run with dt = 1/12800 s (its own error is
    # 1/64 of the dt = 1/1600 s run's, which biases the last order by < 0.03). Measured orders 1.94
    # and 1.99 for dt 1/400 -> 1/800 -> 1/1600 s. Coarser steps are not yet asymptotic (1.62, 1.95,
    # 1.77 from 1/50 to 1/400 s): the start excites the axial modes weakly (about 300 rad/s, so
    # omega dt = 0.75-6 there) and their period error is not yet O(dt^2). [1.8, 2.2] is the brief's
    # band for order 2.
    model, start = swinging_line()

    def at_one_second(n):
        return simulate(model, None, 1.0, 1.0 / n, 1.0, initial=start, tol=1e-8).position[-1]

    ref = at_one_second(12800)
    err = np.array([np.linalg.norm(at_one_second(n) - ref) for n in (400, 800, 1600)])
    order = np.log2(err[:-1] / err[1:])
    check(order, 2.0, atol=0.2, source="Closed form: Newmark's order of accuracy",
          quantity="observed order of the average-acceleration step, dt 1/400 -> 1/800 -> 1/1600 s",
          why="[1.8, 2.2], the brief's band for order 2 (measured 1.94 and 1.99)")

"""The coupling interface (:mod:`seacable.coupling`) against MoorDyn 2.7.2's own API and a closed form.

Peer: MoorDyn v2 (FloatingArrayDesign/MoorDyn, BSD-3) through its Python wrapper ``moordyn`` (``Create``,
``Init``, ``Step``, ``Close``), driven by the same prescribed motion as :class:`seacable.coupling.Coupling`, on two
public decks vendored in ``data/moordyn_decks`` (``PROVENANCE.md``): ``MoorDyn/example/body.txt`` (OC3-Hywind's
three chains on a coupled body, 6 DOF) and ``MoorDyn/tests/Mooring/lines.txt`` (the same chains on three vessel
points, 9 DOF). MoorDyn takes the pose at a step's start and extrapolates it with the velocity; seacable takes it at
the step's end: each is given the same motion sampled where it wants it.

Closed form: a single suspended elastic catenary (Irvine, *Cable Structures*, 1981, eqs. 2.24-2.25): the span
``X(H, V)``, ``Z(H, V)`` of a line of unstretched length ``L``, weight ``w`` per metre and stiffness ``EA`` hanging
from an anchor, and its fairlead stiffness, the inverse of the flexibility ``d(X, Z)/d(H, V)``, with ``H / X`` out of
the plane (the line turning about the vertical through its anchor).
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from seacable.coupling import Coupling

HERE = Path(__file__).parent / "data" / "moordyn_decks" / "MoorDyn"
BODY_DECK = HERE / "example" / "body.txt"
POINTS_DECK = HERE / "tests" / "Mooring" / "lines.txt"


def _quiet_coupling(deck, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the deck's MoorDyn-only options (dtM, IC settings) are noted elsewhere
        return Coupling(deck, **kw)


def _surge(x0, t, amplitude=5.0, period=20.0, stride=6, turns=(0.0, 0.0, 0.0)):
    """x0 moved in x by a surge that starts from rest, ``A (1 - cos w t) / 2``, and its velocity; a body's roll,
    pitch and yaw by ``turns`` [rad] in the same way."""
    w = 2 * math.pi / period
    x, xd = np.array(x0, float), np.zeros(len(x0))
    amplitude = np.r_[amplitude, turns] if stride == 6 else amplitude
    dofs = [0, 3, 4, 5] if stride == 6 else slice(None, None, stride)
    x[dofs] += amplitude * (1 - math.cos(w * t)) / 2
    xd[dofs] = amplitude * w * math.sin(w * t) / 2
    return x, xd


def _moordyn_forces(deck, tmp_path, x0, stride, n, dt, turns):
    moordyn = pytest.importorskip("moordyn")
    local = tmp_path / "deck.txt"  # MoorDyn writes its log beside the deck; its saved IC file is not vendored
    local.write_text("".join(row for row in deck.read_text().splitlines(True) if "fileIC" not in row))
    system = moordyn.Create(str(local))
    try:
        assert moordyn.NCoupledDOF(system) == len(x0)
        x, xd = _surge(x0, 0.0, stride=stride, turns=turns)
        assert moordyn.Init(system, x.tolist(), xd.tolist()) == 0
        out = []
        for k in range(n):
            x, xd = _surge(x0, k * dt, stride=stride, turns=turns)  # MoorDyn: the pose at the step's start
            out.append(moordyn.Step(system, x.tolist(), xd.tolist(), k * dt, dt))
    finally:
        moordyn.Close(system)
    return np.array(out, float)


def _seacable_forces(coupling, x0, stride, n, dt, turns):
    coupling.init(*_surge(x0, 0.0, stride=stride, turns=turns))
    out = []
    for k in range(n):
        x, xd = _surge(x0, (k + 1) * dt, stride=stride, turns=turns)  # seacable: the pose at the step's end
        out.append(coupling.step(x, xd, k * dt, dt))
    return np.array(out)


@pytest.mark.parametrize("deck, stride, turns", [
    (BODY_DECK, 6, (0.0, 0.0, 0.0)), (BODY_DECK, 6, (0.03, 0.05, 0.08)), (POINTS_DECK, 3, (0.0, 0.0, 0.0))],
    ids=["coupled_body", "coupled_body_turning", "coupled_points"])
def test_forces_follow_moordyn_under_the_same_surge(deck, stride, turns, tmp_path):
    """6 s of a 5 m surge (20 s period, from rest: 3.3 m reached; the body also turning by up to 0.03, 0.05, 0.08 rad
    in roll, pitch and yaw, given in MoorDyn's angles, Rx Ry Rz) at a 0.1 s coupling step: every coupled force and
    moment within 1 % of its largest magnitude (what the decks' statics already agree to, test_moordyn_decks:
    MoorDyn's 20 lumped masses against seacable's 20 finite elements, its explicit dtM 2 ms against Newmark at
    0.05 s; measured 0.2-0.5 % on the body, 0.7 % on the points over 20 s)."""
    n, dt = 60, 0.1
    coupling = _quiet_coupling(deck, time_step=0.05, angles="moordyn")
    x0 = np.zeros(6) if stride == 6 else np.array([coupling.system.points[p].position for p in coupling.points]).ravel()
    ours = _seacable_forces(coupling, x0, stride, n, dt, turns)
    theirs = _moordyn_forces(deck, tmp_path, x0, stride, n, dt, turns)
    scale = np.abs(theirs).max(axis=0)
    # a component far smaller than the others (sway and roll, zero by symmetry without the turns) is held to 1e-4 of
    # the largest force (or moment) instead: the agreement of the two statics (test_moordyn_decks) in absolute terms
    moment = np.r_[False, False, False, True, True, True] if stride == 6 else np.zeros(len(x0), bool)
    floor = np.where(moment, scale[moment].max(initial=0.0), scale[~moment].max()) * 1e-4
    err = np.abs(ours - theirs).max(axis=0)
    assert np.all(err <= 0.01 * scale + floor), (err / np.maximum(scale, 1.0))
    # the surge moved the force by more than the tolerance: a frozen line would fail
    assert np.ptp(theirs[:, 0]) > 0.05 * scale[0]


def _catenary_case(n_elements=60):
    from seacable.system.case import SystemCase

    return SystemCase.parse({
        "name": "one_catenary",
        "line_types": {"chain": {"diameter": 0.09, "mass_per_length": 77.7, "axial_stiffness": 3.84e8}},
        "environment": {"depth": 300.0},
        "points": {"anchor": {"kind": "fixed", "position": [0.0, 0.0, -150.0]},
                   "fairlead": {"kind": "coupled", "position": [300.0, 0.0, -10.0]}},
        "lines": {"chain": {"line_type": "chain", "length": 360.0, "end_a": "anchor", "end_b": "fairlead",
                            "n_elements": n_elements}},
        "analysis": {"type": "system_dynamic", "duration": 1.0}})


def _irvine(X, Z, L, w, EA):
    """(H, V at the top) and the in-plane stiffness of a suspended elastic catenary spanning (X, Z) (Irvine)."""
    from scipy.optimize import fsolve

    def span(hv):
        H, V = hv
        a, b = V / H, (V - w * L) / H
        return np.array([H / w * (math.asinh(a) - math.asinh(b)) + H * L / EA - X,
                         H / w * (math.hypot(1, a) - math.hypot(1, b)) + (V * L - w * L * L / 2) / EA - Z])

    H, V = fsolve(span, [w * L, w * L], xtol=1e-13)
    a, b = V / H, (V - w * L) / H
    ra, rb = math.hypot(1, a), math.hypot(1, b)
    flex = np.array([[(math.asinh(a) - math.asinh(b) - a / ra + b / rb) / w + L / EA, (1 / ra - 1 / rb) / w],
                     [(1 / ra - 1 / rb) / w, (a / ra - b / rb) / w + L / EA]])
    return H, V, np.linalg.inv(flex)


def test_one_catenary_fairlead_force_and_stiffness_are_irvines():
    """The fairlead of a single suspended chain: its static force (the catenary statics: exact) and stiffness
    (their analytic tangent) to 1e-6 of Irvine's closed form (both solved to ~1e-10); the finite-element start
    of ``init`` to 1e-3 (60 two-node elements carrying their weight at the nodes: an O(1/N^2) error, measured
    1.2e-4; the catenary statics' force: 1e-15)."""
    case = _catenary_case()
    lt = case.line_types["chain"]
    w = (lt.mass_per_length - case.environment.water_density * math.pi * lt.diameter ** 2 / 4) * case.environment.gravity
    H, V, K2 = _irvine(300.0, 140.0, 360.0, w, lt.axial_stiffness)
    sag = H / w * (math.hypot(1, (V - w * 360.0) / H) - 1)  # the lowest point's depth below the anchor (inextensible)
    assert -150.0 - sag > -300.0 + 50.0  # suspended: well clear of the seabed, as the closed form assumes
    coupling = Coupling(case)
    x = np.array([300.0, 0.0, -10.0])
    f = coupling.static_forces(x)
    assert f == pytest.approx([-H, 0.0, -V], rel=1e-6, abs=1e-6 * H)
    K = coupling.stiffness(x)
    expect = np.zeros((3, 3))
    expect[np.ix_([0, 2], [0, 2])] = K2
    expect[1, 1] = H / 300.0  # out of the plane: the line turns about the anchor's vertical
    assert K == pytest.approx(expect, rel=1e-6, abs=1e-6 * np.abs(K2).max())
    f0 = coupling.init(x)
    assert f0 == pytest.approx([-H, 0.0, -V], rel=1e-3, abs=1e-3 * H)


def test_the_example_hulls_surge_stiffness_is_oc3s():
    """examples/coupling_hull.yaml is OC3-Hywind's mooring: its surge stiffness at rest is the definition's
    41,180 N/m (Jonkman 2010, NREL/TP-500-47535, Table 5-1, to its four figures: 0.05 %)."""
    moor = Coupling(Path(__file__).parents[2] / "examples" / "coupling_hull.yaml")
    assert moor.stiffness(np.zeros(6))[0, 0] == pytest.approx(41180.0, rel=5e-4)

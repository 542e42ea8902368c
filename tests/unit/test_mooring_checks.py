"""Issue 17 items 3, 7, 9 and 12 for the mooring model: one geometric check for every path, a Newton
tolerance with a floor, the pre-time-loop preparation, and each line's own end tensions in a network."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import seacable as sc
from seacable.errors import InputError
from seacable.mooring.run import prepare_mooring_dynamic, prepare_mooring_pushover, prepare_mooring_static

CHAIN = {"diameter": 0.1512, "mass_per_length": 140.4, "axial_stiffness": 6.03e8}


def _case(analysis, length=410.0, depth=200.0, line_type=CHAIN):
    return sc.Case(name="chk", line_types={"chain": line_type}, line={"line_type": "chain", "length": length},
                   environment={"depth": depth}, analysis=analysis)


def _dynamic(**geometry):
    return {"type": "mooring_dynamic", "duration": 1.0, "n_elements": 10, **geometry}


@pytest.mark.parametrize("kind", ["mooring_static", "mooring_pushover", "mooring_dynamic"])
def test_a_line_too_short_for_its_ends_is_refused_by_every_analysis(kind):
    """The issue's 410 m chain between points 4000 m apart (it ran, exit 0, 1.47e10 N): an error naming the
    line, the start strain and the limit."""
    analysis = {"type": kind, "fairlead": [4000.0, -15.0], "n_elements": 10}
    analysis.update({"mooring_dynamic": {"duration": 1.0}, "mooring_pushover": {"max_offset": 10.0}}.get(kind, {}))
    with pytest.raises(InputError) as err:
        sc.run(_case(analysis))
    msg = str(err.value)
    assert "'line'" in msg and "410 m unstretched" in msg and "20%" in msg and "Suggested fix" in msg


def test_the_stretch_limit_is_the_breaking_strain_when_the_breaking_load_is_known():
    """EA 6.03e8 N and MBL 6.03e6 N: the line breaks at 1 % strain; a start at 1.5 % is refused, one at
    0.5 % is accepted (without a breaking load 1.5 % is fine: the limit is then 20 %)."""
    rated = {**CHAIN, "breaking_load": 6.03e6}
    fair = (math.sqrt((410.0 * 1.015) ** 2 - 185.0**2), -15.0)
    with pytest.raises(InputError, match="breaking load"):
        prepare_mooring_dynamic(_case(_dynamic(fairlead=list(fair)), line_type=rated))
    prepare_mooring_dynamic(_case(_dynamic(fairlead=list(fair))))
    ok = (math.sqrt((410.0 * 1.005) ** 2 - 185.0**2), -15.0)
    prepare_mooring_dynamic(_case(_dynamic(fairlead=list(ok)), line_type=rated))


@pytest.mark.parametrize("where", ["anchor", "fairlead"])
def test_an_end_under_the_seabed_is_refused_by_the_dynamic_analysis(where):
    geometry = {"fairlead": [300.0, -15.0], "anchor": [0.0, -200.0]}
    geometry[where] = [geometry[where][0], -230.0]
    with pytest.raises(InputError) as err:
        prepare_mooring_dynamic(_case(_dynamic(**geometry), length=500.0))
    msg = str(err.value)
    assert "'line'" in msg and "30 m under the seabed" in msg and "Suggested fix" in msg


def test_pushover_checks_its_largest_offset():
    case = _case({"type": "mooring_pushover", "fairlead": [350.0, -15.0], "n_elements": 10,
                  "offsets": [0.0, 5000.0]})
    with pytest.raises(InputError, match="cannot span"):
        prepare_mooring_pushover(case)


def test_prepare_refuses_a_run_too_long_before_any_solve():
    case = _case(_dynamic(fairlead=[350.0, -15.0], time_step=1e-9, output_interval=1e-9), length=500.0)
    with pytest.raises(InputError, match="time steps"):
        prepare_mooring_dynamic(case)
    assert prepare_mooring_static(_case({"type": "mooring_static", "fairlead": [350.0, -15.0]}, length=500.0))


MOORDYN = """--------------------- MoorDyn Input File ------------------------------------
two chains in series through a free point, between two anchors
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI         Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.1     60         5e8        -0.5        0          1.2    1.0    0.2     0.0
---------------------- POINTS ----------------------------------------
ID    Attachment  X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)         (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed       -300    0       -100    0      0       0      0
2     Fixed       300     0       -100    0      0       0      0
3     Free        0       0       -50     100    30      1.0    1.0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        3         320       16      -
2     chain      2        3         320       16      -
---------------------- OPTIONS -----------------------------------------
300           WtrDpth       water depth (m)
------------------------- need this line --------------------------------------
"""


def test_moordyn_network_lines_report_their_own_end_tensions(tmp_path):
    """Two chains meeting at a buoyant free point: each line's tension at the point is its own pull, not the
    point's support force (about 0 for a free point in equilibrium)."""
    from seacable.mooring.moordyn import run_moordyn_file

    f = tmp_path / "two.txt"
    f.write_text(MOORDYN)
    ds = run_moordyn_file(f)
    lift = (1025.0 * 30 - 100.0) * 9.80665
    # the point is in equilibrium under its net buoyancy and the two lines' pulls: the lines' own end forces
    # at the point add up to minus the lift (to the static tolerance, 1e-8 of the force scale)
    fz = ds.fairlead_force_z.values
    assert fz.sum() == pytest.approx(-lift, rel=1e-6)
    # by symmetry each line pulls with half the lift vertically; its end tension is at least that
    assert fz == pytest.approx([-lift / 2, -lift / 2], rel=1e-6)
    assert np.all(ds.fairlead_tension.values > lift / 2)


def test_moordyn_points_too_far_apart_for_the_lines_between_them_are_refused(tmp_path):
    """Anchors 4000 m apart joined by 2 x 320 m of chain through a free point: the path is too short."""
    from seacable.mooring.moordyn import run_moordyn_file

    f = tmp_path / "far.txt"
    f.write_text(MOORDYN.replace("2     Fixed       300     0       -100", "2     Fixed       3700    0       -100"))
    with pytest.raises(InputError) as err:
        run_moordyn_file(f)
    msg = str(err.value)
    assert "'line 1'" in msg and "'line 2'" in msg and "640 m unstretched" in msg


TANK = {
    "name": "tank_chain",
    "line_types": {"chain": {"diameter": 0.0054, "mass_per_length": 0.0948, "axial_stiffness": 3.0e5}},
    "line": {"line_type": "chain", "length": 33.0},
    "environment": {"depth": 2.5, "water_density": 1000.0},
    "analysis": {"type": "mooring_dynamic", "fairlead": [32.0, -0.1], "n_elements": 66,
                 "seabed_contact": {"stiffness": 1.0e9, "damping": 3.0e5},
                 "motion": {"type": "harmonic", "amplitude": [0.5, 0, 0], "period": 4.0, "ramp": 2.0},
                 "duration": 6.0, "time_step": 0.01, "output_interval": 0.05, "damping_ratio": 0.8},
}


def test_a_tank_scale_chain_with_a_slack_phase_runs():
    """Issue 17 item 7: a 33 m tank chain (0.7 N/m in water) on a 1e9 Pa/m seabed, its fairlead surging
    0.5 m: every element goes slack at times. It stopped with "did not converge ... force residual
    6e-06 N (tolerance 1e-08 N)" (the tolerance fell to the weight of one node, and Newton cycled between
    slack and taut elements); it must run to the end."""
    from seacable.statics.catenary import catenary

    ds = sc.run(sc.parse_case(TANK))
    assert float(ds.time[-1]) == 6.0 and not ds.attrs["interrupted"]
    assert int(ds.slack_elements.max()) > 0.9 * 66  # the slack phase this test is about
    # the start is the static catenary with seabed contact: w = (0.0948 - 1000 pi 0.0054^2 / 4) 9.80665
    w = (0.0948 - 1000.0 * math.pi * 0.0054**2 / 4) * 9.80665
    ref = catenary(32.0, 2.4, 33.0, 3.0e5, w)
    # 66 elements of 0.5 m: the lumped model's end tension is the catenary's to half an element's weight
    assert float(ds.fairlead_tension[0]) == pytest.approx(float(ref.fairlead_tension), abs=0.5 * w * 0.5)


def test_a_motion_that_takes_the_fairlead_under_the_seabed_or_beyond_reach_is_refused_before_running():
    """Heave of 10 m from 5 m above the seabed: under it at t = 3/4 of the 20 s period. Surge of 500 m on a
    410 m chain: beyond its reach at a quarter period. Both are refused by the preparation, naming the time."""
    heave = {"type": "harmonic", "amplitude": [0, 0, 10.0], "period": 20.0}
    with pytest.raises(InputError) as err:
        prepare_mooring_dynamic(_case(_dynamic(fairlead=[300.0, -195.0], motion=heave, duration=20.0,
                                               output_interval=0.5), length=500.0))
    assert "t = 15 s" in str(err.value) and "under the seabed" in str(err.value) and "'line'" in str(err.value)
    surge = {"type": "harmonic", "amplitude": [500.0, 0, 0], "period": 20.0}
    with pytest.raises(InputError) as err:
        prepare_mooring_dynamic(_case(_dynamic(fairlead=[300.0, -15.0], motion=surge, duration=20.0,
                                               output_interval=0.5)))
    assert "t = 5 s" in str(err.value) and "cannot span" in str(err.value)


def test_point_forces_of_a_network_are_reported_separately(tmp_path):
    """The force on each point's support: about 0 at the free point in equilibrium, and at the two anchors
    the lines' pull (their vertical parts carry the two lines' weight in water less the buoy's lift)."""
    from seacable.mooring.moordyn import moordyn_model
    from seacable.mooring.run import point_variables
    from seacable.mooring.solver import static_equilibrium

    f = tmp_path / "two.txt"
    f.write_text(MOORDYN)
    model = moordyn_model(f)
    st = static_equilibrium(model)
    pv = point_variables(model, st.support)
    nodes = list(pv["point_node"].values)
    assert nodes == [0, 1, 2]  # MoorDyn points 1, 2 (anchors) and 3 (the free point)
    lift = (1025.0 * 30 - 100.0) * 9.80665
    assert pv["point_force"].values[2] < 1e-6 * lift
    w_lines = 2 * 320.0 * (60.0 - 1025.0 * math.pi * 0.1**2 / 4) * 9.80665
    assert -np.sum(pv["point_force_z"].values[:2]) == pytest.approx(w_lines - lift, rel=1e-6)


def test_a_single_line_is_checked_along_its_chain_without_a_graph_search(monkeypatch):
    """A network that is one line (each element joining its next two nodes) has one path between its held ends:
    its reach is summed along it, as the graph search sums it, without building the graph; a shorter reach is
    refused with the same message."""
    import scipy.sparse.csgraph as csgraph
    from scipy.sparse import coo_matrix

    from seacable.mooring.checks import _chain, _chain_distances, check_network
    from seacable.mooring.network import network_from_line

    line = sc.Case(name="chk", line_types={"chain": CHAIN}, line={"line_type": "chain", "length": 410.0},
                   environment={"depth": 200.0}, analysis={"type": "mooring_static", "fairlead": [300.0, -15.0]}).line
    net = network_from_line(line, (0.0, 0.0, -200.0), (300.0, 0.0, -15.0), water_density=1025.0, gravity=9.81,
                            n_elements=12)
    reach = net.length * 1.2 + np.linspace(0.0, 1e-3, net.n_elements)  # unequal: the order of the sums shows
    held = np.flatnonzero(net.kind != 0)
    graph = coo_matrix((reach, (net.elements[:, 0], net.elements[:, 1])), shape=(net.n_nodes,) * 2).tocsr()
    expected = csgraph.dijkstra(graph, directed=False, indices=held)
    place = _chain(net)
    assert place is not None and _chain_distances(place, held, reach).tobytes() == expected.tobytes()
    reversed_net = net.replace(line_nodes=(np.asarray(net.line_nodes[0])[::-1],))
    assert _chain(reversed_net) is None  # its elements do not run along its nodes: the graph search

    def no_search(*args, **kwargs):
        raise AssertionError("the graph was searched")

    monkeypatch.setattr(csgraph, "dijkstra", no_search)
    check_network(net, depth=200.0)
    far = net.position.copy()
    far[held[-1]] = (600.0, 0.0, -15.0)
    with pytest.raises(InputError, match=r"'line' \(410 m unstretched\) cannot span"):
        check_network(net.replace(position=far), depth=200.0)


def test_a_single_line_view_is_not_checked_again_and_refuses_what_its_network_refuses(tmp_path, monkeypatch):
    """The view of a network's only line (its own network, renumbered: the same nodes, positions and elements)
    skips the start check its network passed (issue 38: the overhead of a run); a network of several lines
    checks each view; a model made with ``checked`` skips it, one made without refuses a bad start."""
    import seacable.mooring.solver as S
    from seacable.mooring.moordyn import _line_views, moordyn_model
    from seacable.mooring.solver import MooringModel

    deck = Path(__file__).parents[1] / "validation" / "data" / "three_chains_deck.txt"
    wd = (Path(__file__).parents[1] / "validation" / "data" / "moordyn_decks" / "MoorDyn" / "tests" / "Mooring"
          / "WD0200_Chain.txt")
    single, three = moordyn_model(wd), moordyn_model(deck)
    calls = []
    real = S.check_network
    monkeypatch.setattr(S, "check_network", lambda *a, **k: calls.append(a) or real(*a, **k))
    _line_views(single)
    assert not calls
    _line_views(three)
    assert len(calls) == 3
    net = single.network
    sunk = net.replace(position=net.position - [0.0, 0.0, 50.0])  # the anchor 50 m under the seabed
    with pytest.raises(InputError, match="under the seabed"):
        MooringModel(sunk, single.water)
    assert MooringModel(sunk, single.water, checked=True).nfree == single.nfree


def test_plain_float_arguments_are_checked_as_arrays_are():
    """The checks take a plain float without numpy (issue 38): the same value back, the same refusals."""
    from seacable import _validate as v

    for check in (v.finite, v.positive, v.nonnegative):
        for x in (2.5, 1e-300, 1e300):
            got = check("x", x)
            assert type(got) is float and got == x
            assert check("x", np.float64(x)) == got
    assert math.copysign(1.0, v.nonnegative("x", -0.0)) == -1.0
    for bad in (math.nan, math.inf, -math.inf):
        for check in (v.finite, v.positive, v.nonnegative):
            with pytest.raises(InputError, match="finite number"):
                check("x", bad)
    with pytest.raises(InputError, match="> 0"):
        v.positive("x", 0.0)
    with pytest.raises(InputError, match=">= 0"):
        v.nonnegative("x", -1.0)

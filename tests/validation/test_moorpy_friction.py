"""The statics' seabed friction against MoorPy's catenary with seabed friction (issue 40).

MoorPy (NREL; ``moorpy.Catenary.catenary(XF, ZF, L, EA, W, CB)``, the test extras' peer) solves the elastic
catenary of a line lying partly on a seabed of friction coefficient ``CB``, the friction fully mobilised along the
grounded length as when the line has been pulled out monotonically: the tension falls from the touchdown towards the
anchor by ``CB w`` per length, to ``max(H - CB w L_B, 0)`` at the anchor.

Here a 400 m line (w 893 N/m, EA 1e8 N) in 100 m of water is laid slack, its fairlead 305 m from the anchor (the
as-laid state: the frictionless equilibrium, 1.08 kN of tension on the seabed), and pulled out monotonically along
an incremental pushover (``static_friction.pushover_path: incremental``, friction 0.5) to 320, 360, 370 and 380 m:
at the first two the friction holds the line short of its anchor (MoorPy: anchor tension 0), at the last two the
whole grounded line slides (anchor tension 106 and 359 kN against 184 and 398 kN frictionless).

The seabed's penalty stiffness is raised to 3e8 Pa/m so that the nodes sink 6.5 um into it: at MoorPy's default the
line lies 0.65 mm into the seabed between ends held on its surface, and the end elements' slope ``pen / l_e`` lifts
``T pen / l_e`` off the normal force next to the ends, an error that grows as the mesh is refined.
"""

from __future__ import annotations

import numpy as np
import pytest
from _evidence import check

import seacable as sc

moorpy_catenary = pytest.importorskip("moorpy.Catenary").catenary

L, EA, DEPTH, MASS, D, MU, G, RHO = 400.0, 1.0e8, 100.0, 100.0, 0.1, 0.5, 9.81, 1025.0
W = (MASS - RHO * np.pi / 4 * D * D) * G  # weight in water per length (the environment's g and rho) [N/m]
X0 = 305.0
OFFSETS = (15.0, 55.0, 65.0, 75.0)


def _pushover(n):
    return sc.run(sc.Case.parse({
        "name": "moorpy_friction",
        "line_types": {"line": {"diameter": D, "mass_per_length": MASS, "axial_stiffness": EA}},
        "line": {"segments": [{"line_type": "line", "length": L}]},
        "environment": {"depth": DEPTH, "seabed": {"friction": MU}},
        "analysis": {"type": "mooring_pushover", "anchor": [0.0, -DEPTH], "fairlead": [X0, 0.0], "n_elements": n,
                     "seabed_contact": {"stiffness": 3e8}, "offsets": list(OFFSETS),
                     "static_friction": {"pushover_path": "incremental", "friction_distance": 1e-4}}}))


@pytest.fixture(scope="module")
def runs():
    """The pushover at 100, 200 and 400 elements (4, 2 and 1 m), and MoorPy's catenaries at its offsets."""
    ref = []
    for off in OFFSETS:
        fah, fav, fbh, fbv, info = moorpy_catenary(X0 + off, DEPTH, L, EA, W, CB=MU, Tol=1e-12, MaxIter=500)
        ref.append((-fbh, -fbv, float(np.hypot(fah, fav)), info["LBot"]))
    return {n: _pushover(n) for n in (100, 200, 400)}, np.array(ref)


def test_the_fairlead_force_and_the_touchdown_are_moorpys(runs):
    """At 2 and 1 m elements the fairlead's horizontal and vertical forces are MoorPy's within 1e-3 (0.06 % at
    most: the lumped masses' error on the hanging part), and the grounded length within 2 elements (it counts whole
    elements on the seabed: first order)."""
    ds_by_n, ref = runs
    for n in (200, 400):
        ds = ds_by_n[n]
        check(ds.H_fairlead.values, ref[:, 0], rtol=1e-3, source="MoorPy (catenary with seabed friction)", unit="N",
              quantity=f"line pulled out incrementally: fairlead horizontal force, {n} elements",
              why="the lumped masses' error on the hanging part (0.06 % at most)")
        check(-ds.fairlead_force_z.values, ref[:, 1], rtol=1e-3, source="MoorPy (catenary with seabed friction)",
              unit="N", quantity=f"line pulled out incrementally: fairlead vertical force, {n} elements",
              why="the lumped masses' error on the hanging part")
        np.testing.assert_allclose(ds.seabed_contact_length.values, ref[:, 3], rtol=0, atol=2 * L / n)


def test_the_anchor_tension_of_a_line_pulled_out_is_moorpys_at_first_order(runs):
    """Where the whole grounded line slides (370 and 380 m) the anchor tension is MoorPy's ``H - mu w L_B``
    plus ``mu w l_e / 2``, the friction the anchor's half element does not have (its load is the anchor's), to 1e-3 of
    it (at most 0.05 % here), so that the error falls by 2 as the elements halve (1.9-2.1: first order) and is 0.22 and 0.06 %
    at 1 m elements. Where friction holds the line short of its anchor (320 and 360 m) MoorPy's anchor tension is 0
    (friction fully mobilised from an untensioned lay); here the far part still lies as laid, with the as-laid
    tension (1079 N, the frictionless catenary at 305 m, 1 % of the pull at 360 m), and at 360 m the slid length
    ``(H - 1079 N) / (mu w)`` ends 10 m from the anchor, within the partly mobilised reach of the regularisation and
    the anchor's half element: 0.95 to 1.5 times the as-laid tension."""
    ds_by_n, ref = runs
    laid = moorpy_catenary(X0, DEPTH, L, EA, W, CB=0.0, Tol=1e-12, MaxIter=500)
    laid_tension = float(np.hypot(laid[0], laid[1]))
    slid = ref[:, 2] > 0.0
    assert list(slid) == [False, False, True, True]
    errors = []
    for n, ds in ds_by_n.items():
        half = MU * W * L / n / 2
        anchor = ds.anchor_tension.values
        np.testing.assert_allclose(anchor[slid], ref[slid, 2] + half, rtol=1e-3)
        assert np.all((anchor[~slid] > 0.95 * laid_tension) & (anchor[~slid] < 1.5 * laid_tension))
        errors.append(anchor[slid] - ref[slid, 2])
    ratio = np.array(errors[:-1]) / np.array(errors[1:])
    assert np.all((ratio > 1.9) & (ratio < 2.1)), ratio
    assert np.all(np.abs(errors[-1]) < 2.5e-3 * ref[slid, 2])

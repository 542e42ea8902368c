"""Seabed grids under moorings, systems and towed lines (issue 41): ``environment.seabed.grid``, the lay planner's
:class:`seacable.bathymetry.BathymetryGrid` (inline, CSV, NetCDF; land masked) under the finite-element line.

The kernel's contact on a grid (:func:`seacable.mooring._seabed.grid_at`, :func:`~seacable.mooring._seabed.penetration`)
takes the bilinear elevation and its gradient in the cell under each node, the normal ``(-dz/dx, -dz/dy, 1) / norm``,
the penetration along it and the friction in its plane. A grid that is a plane gives the sloped plane's results, a
grid built from a profile the profile's, and a chain across a slope in y slides down it into the closed-form
catenary of its weight's component along the seabed.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import seacable as sc
from seacable.bathymetry import BathymetryGrid, SeabedGrid, cartesian_grid
from seacable.case import Case
from seacable.errors import InputError
from seacable.mooring.outputs import height_above_seabed
from seacable.mooring.run import case_model

CHAIN = {"diameter": 0.09, "mass_per_length": 77.7, "weight_in_water": 698.0, "axial_stiffness": 3.8e8}
SLOPE = 0.05  # [rad]


def _mooring(seabed, *, depth=100.0, analysis=None, length=400.0, fairlead=(350.0, -20.0), current=None, **more):
    env = {"seabed": seabed, **({"depth": depth} if depth is not None else {}),
           **({"current": current} if current else {})}
    a = {"type": "mooring_static", "fairlead": list(fairlead), "element_length": 10.0, **(analysis or {})}
    return Case.parse({"name": "grid", "line_types": {"ch": CHAIN}, "line": {"line_type": "ch", "length": length},
                       "environment": env, "analysis": a, **more})


def _grid(x, y, depth):
    return {"x": [float(v) for v in x], "y": [float(v) for v in y], "depth": [[float(d) for d in row] for row in depth]}


def _plane_grid(slope=SLOPE, depth=100.0):
    """The plane z = -depth + tan(slope) x on a grid over the line (11 x 2 points: bilinear is exact on a plane)."""
    x, y = np.linspace(-50.0, 450.0, 11), np.array([-100.0, 100.0])
    return _grid(x, y, [depth - math.tan(slope) * x] * 2)


def test_the_kernel_and_numpy_read_the_same_bilinear_grid():
    """The compiled lookup (cells by bisection) and :class:`SeabedGrid`'s NumPy one agree to rounding at points
    inside, on the lines and beyond the edges (level beyond: the gradient along that axis 0); on a plane both give
    its elevation and gradient exactly (bilinear interpolation reproduces a linear function), and the normal is
    ``(-dz/dx, -dz/dy, 1) / norm``."""
    from seacable.mooring.kernel import ENV_SIZE, grid_at
    from seacable.mooring.solver import Water

    rng = np.random.default_rng(41)
    x, y = np.array([0.0, 10.0, 25.0, 40.0]), np.array([-5.0, 0.0, 12.0])
    g = SeabedGrid(x, y, rng.uniform(-110.0, -90.0, (3, 4)))
    env = Water(depth=100.0, grid=g).env_vector()
    assert env.size == ENV_SIZE + 4 + 3 + 12
    px = np.r_[rng.uniform(-10.0, 50.0, 200), x, 0.0, 40.0]
    py = np.r_[rng.uniform(-10.0, 20.0, 200), y[[0, 1, 2, 0]], -5.0, 12.0]
    got = np.array([grid_at(env, a, b) for a, b in zip(px, py)])
    np.testing.assert_allclose(got, np.column_stack(g.at(px, py)), rtol=0, atol=1e-12)  # rounding of ~100 m
    beyond = px > 40.0
    assert np.all(got[beyond, 1] == 0.0) and np.any(beyond)
    # the contact's penetration along the normal, and the normal it writes, as the outputs' height above the seabed
    from seacable.mooring._seabed import penetration

    water = Water(depth=100.0, grid=g)
    pz = rng.uniform(-112.0, -88.0, px.size)
    nrm = np.zeros(3)
    for k in range(px.size):
        pen = penetration(env, px[k], py[k], pz[k], True, 100.0, nrm)
        assert pen == pytest.approx(-float(height_above_seabed(water, np.array([px[k], py[k], pz[k]]))), abs=1e-12)
        np.testing.assert_allclose(nrm, g.normal(px[k], py[k]), rtol=0, atol=1e-14)
    # a plane, z = -100 + 0.03 x - 0.02 y: exact elevation and gradient, and its unit normal
    plane = SeabedGrid(x, y, -100.0 + 0.03 * x[None, :] - 0.02 * y[:, None])
    inside = (px > 0) & (px < 40) & (py > -5) & (py < 12)
    zb, gx, gy = plane.at(px[inside], py[inside])
    np.testing.assert_allclose(zb, -100.0 + 0.03 * px[inside] - 0.02 * py[inside], rtol=0, atol=1e-12)
    np.testing.assert_allclose(gx, 0.03, rtol=1e-12)
    np.testing.assert_allclose(gy, -0.02, rtol=1e-12)
    np.testing.assert_allclose(plane.normal(5.0, 1.0), np.array([-0.03, 0.02, 1.0]) / math.sqrt(1.0013), rtol=1e-12)


@pytest.mark.parametrize("friction", [0.0, 0.8])
def test_a_plane_grid_gives_the_sloped_seabed_statics(friction):
    """A grid that is the plane of a 0.05 rad slope gives the sloped plane's static line to the solver's
    tolerance: positions within 1 micrometre and tensions within 1e-8 of the largest (Newton stops at a force
    residual 1e-8 of it; the two normals differ by rounding only), and the same touchdown, in a 1 m/s current
    across the line; with the seabed's static friction too (its targets and force in the seabed's plane, which hold
    the grounded chain 46 m nearer its as-laid line than without). The anchor, given by neither, sits on the grid
    under the origin."""
    cur = {"speed": 1.0, "heading": math.pi / 2}
    a = sc.run(_mooring({"slope": SLOPE, "friction": friction}, current=cur))
    b = sc.run(_mooring({"grid": _plane_grid(), "friction": friction}, current=cur))
    assert float(np.max(np.abs(b.y.values))) > (1.0 if friction else 40.0)  # the current moves the line across
    for v in ("x", "y", "z"):
        np.testing.assert_allclose(b[v].values, a[v].values, rtol=0, atol=1e-6)
    top = float(a.tension.max())
    np.testing.assert_allclose(b.tension.values, a.tension.values, rtol=0, atol=1e-8 * top)
    np.testing.assert_allclose(float(b.touchdown_x), float(a.touchdown_x), rtol=0, atol=1e-6)
    assert 100.0 < float(b.touchdown_x) < 340.0  # a touchdown between the ends: the contact is exercised
    assert float(b.z[0]) == pytest.approx(-100.0, abs=1e-12)


def test_a_plane_grid_gives_the_sloped_seabed_dynamics():
    """The same in a short dynamic run (4 s of a 1 m surge at 20 s, 0.1 s steps, friction 0.5 and axial damping
    so that the grounded chain does not chatter): the grid's and the plane's positions agree within 1e-6 m and
    tensions within 1e-8 of the largest (Newton's tolerance each step; measured 2e-12 m and 2e-6 N of 58 kN), the
    seabed's friction acting in the grid's plane as in the plane's."""
    dyn = {"type": "mooring_dynamic", "duration": 4.0, "time_step": 0.1, "output_interval": 0.5,
           "damping_ratio": 0.5, "motion": {"type": "harmonic", "amplitude": [1.0, 0.0, 0.0], "period": 20.0}}
    a = sc.run(_mooring({"slope": SLOPE, "friction": 0.5}, analysis=dyn))
    b = sc.run(_mooring({"grid": _plane_grid(), "friction": 0.5}, analysis=dyn))
    np.testing.assert_allclose(b.x.values, a.x.values, rtol=0, atol=1e-6)
    np.testing.assert_allclose(b.z.values, a.z.values, rtol=0, atol=1e-6)
    top = float(np.max(a.tension.values))
    np.testing.assert_allclose(b.tension.values, a.tension.values, rtol=0, atol=1e-8 * top)
    assert float(np.ptp(a.x.values[:, -1])) > 0.9  # the fairlead moved
    assert float(np.max(a.seabed_contact_length)) > 100.0  # on the seabed


def test_a_grid_built_from_a_profile_gives_the_profile_run():
    """A profile along X (rising at 0.05 then at 0.1 beyond x = 150 m: the frictionless grounded chain held
    taut by its anchor against its weight down the slope, a unique equilibrium), and the grid of the same depths
    on two lines of y: the same static line to solver tolerance."""
    dist, dep = [-50.0, 150.0, 450.0], [102.5, 92.5, 62.5]
    a = sc.run(_mooring({"profile": {"distance": dist, "depth": dep}}, depth=None, fairlead=(350.0, -10.0)))
    b = sc.run(_mooring({"grid": _grid(dist, [-50.0, 50.0], [dep, dep])}, depth=None, fairlead=(350.0, -10.0)))
    for v in ("x", "z"):
        np.testing.assert_allclose(b[v].values, a[v].values, rtol=0, atol=1e-6)
    np.testing.assert_allclose(b.tension.values, a.tension.values, rtol=0, atol=1e-8 * float(a.tension.max()))
    np.testing.assert_allclose(float(b.touchdown_x), float(a.touchdown_x), rtol=0, atol=1e-6)


def _ridge():
    """A ridge 8 m high and 40 m wide across the line, its crest oblique (x = 150 + 0.3 y): a 3-D grid of 5 m."""
    x, y = np.arange(-50.0, 451.0, 5.0), np.arange(-60.0, 61.0, 5.0)
    X, Y = np.meshgrid(x, y)
    return x, y, 100.0 - 8.0 * np.exp(-((X - 150.0 - 0.3 * Y) / 40.0) ** 2)


def test_a_chain_across_a_ridge_lies_on_the_grids_surface():
    """A chain grounded across an oblique ridge (the anchor on the grid under the origin, no depth given) drapes
    over it: every grounded node lies in the seabed by the contact's static sag, ``w l / (k_b d l)`` (its weight over
    the contact stiffness on its projected area, 2.6 mm), along the grid's normal, within 0.6-1.5 of it (the line's
    tension over the ridge's curvature, T kappa ~ 100 N/m against w = 698 N/m, and the slope's cos presses a node
    on the crest harder and one at the foot less; measured 0.88-1.32), the node over the crest 7.9 m above the
    base; the touchdown is on the grid's seabed."""
    x, y, dep = _ridge()
    case = _mooring({"grid": _grid(x, y, dep)}, depth=None)
    ds = sc.run(case)
    model = case_model(case)
    P = np.stack([ds.x.values, ds.y.values, ds.z.values], axis=-1)
    h = height_above_seabed(model.water, P)
    sag = model.weight / (model.water.seabed_stiffness * model.bedc)
    grounded = (ds.s.values > 0.0) & (ds.s.values < float(ds.touchdown_s) - 10.0)
    assert grounded.sum() >= 25
    ratio = -h[grounded] / sag[grounded]
    assert np.all((ratio > 0.6) & (ratio < 1.5)), ratio
    crest = int(np.argmin(np.abs(P[:, 0] - 150.0 - 0.3 * P[:, 1])))
    assert grounded[crest] and P[crest, 2] > -92.2  # draped over the crest, 7.8 m up
    td = np.array([[float(ds.touchdown_x), float(ds.touchdown_y)]])
    zt = model.water.grid.at(td[:, 0], td[:, 1])[0]
    k = int(np.searchsorted(ds.s.values, float(ds.touchdown_s)))
    assert abs(float(ds.z[k - 1]) - zt[0]) < 0.5  # the node before the touchdown on the seabed under it


def test_a_chain_across_a_slope_in_y_slides_down_it_into_the_in_plane_catenary():
    """The normal's direction: 320 m of chain between two points 300 m apart on a seabed falling towards -y at
    0.1 rad, frictionless. The contact carries ``w cos(a)``; the rest of the weight, ``w sin(a)``, pulls the chain down
    the slope in the seabed's plane, into the catenary of that load: ``L = 2 c sinh(D / 2c)``, sag ``c (cosh(D / 2c)
    - 1)`` = 48.53 m, tension ``c w sin(a)``. The middle node lies 48.53 cos(a) = 48.28 m towards -y and the tension at
    the ends is 16.69 kN, within 0.5 % (the 5 m elements' discretisation and the contact's 2.6 mm sag; measured
    0.05 %). A normal with its y component's sign wrong pushes the chain uphill instead, and fails."""
    from scipy.optimize import brentq

    a, L, D, w = 0.1, 320.0, 300.0, CHAIN["weight_in_water"]
    y = np.array([-150.0, 50.0])
    grid = _grid([-50.0, 350.0], y, [[100.0 - math.tan(a) * v] * 2 for v in y])
    ds = sc.run(_mooring({"grid": grid}, depth=None, length=L, fairlead=(D, -100.0),
                         analysis={"element_length": 5.0}))
    c = brentq(lambda c: 2 * c * math.sinh(D / (2 * c)) - L, 10.0, 1e4)
    sag = c * (math.cosh(D / (2 * c)) - 1.0)
    mid = int(np.argmin(np.abs(ds.s.values - L / 2)))
    assert float(ds.y[mid]) == pytest.approx(-sag * math.cos(a), rel=5e-3)
    assert float(ds.z[mid]) == pytest.approx(-100.0 - sag * math.sin(a), rel=5e-3)
    assert float(ds.x[mid]) == pytest.approx(D / 2, abs=1e-6)  # symmetric
    wa = w * math.sin(a)
    assert float(ds.tension.min()) == pytest.approx(c * wa, rel=5e-3)  # H, in the middle
    # the first element's, at its middle 2.5 m from the anchor: sqrt(H^2 + (w' (L/2 - 2.5))^2)
    assert float(ds.tension[0]) == pytest.approx(math.hypot(c * wa, wa * (L / 2 - 2.5)), rel=5e-3)


def _write_csv(path, x, y, depth, names=("x", "y", "depth")):
    rows = [",".join(names)] + [f"{a},{b},{depth[j][i]}" for j, b in enumerate(y) for i, a in enumerate(x)]
    path.write_text("\n".join(rows) + "\n")
    return str(path)


def test_a_grid_that_does_not_cover_the_line_is_refused(tmp_path):
    """The anchor (its default, on the seabed under the origin), a fairlead or the line's nodes beyond the grid:
    refused by validate and run alike, naming what, where and the grid's span, with a fix."""
    x, y = [50.0, 450.0], [-50.0, 50.0]
    off = _mooring({"grid": _grid(x, y, [[100.0, 80.0]] * 2)}, depth=None)
    for call in (sc.check, sc.run):
        with pytest.raises(InputError, match=r"environment.seabed.grid does not cover the anchor \(its default: the "
                                             r"origin\): no seabed under x = 0.0 m, y = 0.0 m \(the grid spans x "
                                             r"50..450 m, y -50..50 m\). Suggested fix: extend the grid"):
            call(off)
    short = _mooring({"grid": _grid([-50.0, 300.0], y, [[100.0, 85.0]] * 2)}, depth=None)
    with pytest.raises(InputError, match=r"does not cover the anchors, fairleads and points: no seabed under x = "
                                         r"350.0 m, y = 0.0 m .*Suggested fix"):
        sc.check(short)


def test_land_under_the_line_and_a_grid_in_degrees_are_refused(tmp_path):
    """A CSV grid (the lay planner's reader) with a land point (depth -3 m, marked a hole) next to the line's path:
    refused by validate, naming the point and the cell; a grid in longitude and latitude, which a mooring's metres
    cannot be placed on, and scattered points likewise, each with a fix."""
    x, y = [-50.0, 100.0, 150.0, 200.0, 450.0], [-50.0, 0.0, 50.0]
    depth = [[100.0, 100.0, 100.0, 100.0, 90.0], [100.0, 100.0, -3.0, 100.0, 90.0], [100.0] * 4 + [90.0]]
    land = _mooring({"grid": {"file": _write_csv(tmp_path / "land.csv", x, y, depth)}}, depth=None)
    with pytest.raises(InputError, match=r"environment.seabed.grid: the line's nodes at x = 1[0-9.]+ m, y = 0.0 m "
                                         r"lies over land or a hole in the grid \(a cell x 100..150 m, y 0..50 m "
                                         r"with a corner at or above the surface.*Suggested fix: move the line off"):
        sc.check(land)
    degrees = _write_csv(tmp_path / "ll.csv", x, y, [[100.0] * 5] * 3, ("longitude", "latitude", "depth"))
    with pytest.raises(InputError, match=r"is in longitude and latitude \(degrees\).*Suggested fix: project the grid"):
        sc.check(_mooring({"grid": {"file": degrees}}, depth=None))
    scattered = tmp_path / "pts.csv"
    scattered.write_text("x,y,depth\n-50,-50,100\n450,-50,90\n-50,50,100\n400,60,90\n")
    with pytest.raises(InputError, match=r"holds 4 scattered points, not a complete rectangular grid"):
        sc.check(_mooring({"grid": {"file": str(scattered)}}, depth=None))
    both = {"grid": _plane_grid(), "slope": 0.01}
    with pytest.raises(InputError, match=r"seabed.grid and seabed.slope 0.01 rad both give the seabed"):
        _mooring(both)


def test_an_analysis_without_contact_refuses_the_grid():
    """The catenary statics (analysis 'static') have no grid: the grid is refused as an input it does not use."""
    with pytest.raises(InputError, match=r"environment.seabed.grid is given, but analysis 'static' does not use it"):
        Case.parse({"name": "c", "line_types": {"ch": CHAIN}, "line": {"line_type": "ch", "length": 400.0},
                    "environment": {"depth": 100.0, "seabed": {"grid": _plane_grid()}},
                    "analysis": {"type": "static", "fairlead": [350.0, -20.0]}})


def test_the_lay_planner_and_the_moorings_read_one_grid_class():
    """One reader: the lay planner's BathymetryGrid is seacable.bathymetry's, and a NetCDF elevation grid (GEBCO's
    sign, up) reads as the same depths as the inline grid, NaN where it is land."""
    import xarray as xr

    from seacable.laying import bathymetry as lay

    assert lay.BathymetryGrid is BathymetryGrid is sc.BathymetryGrid
    x, y = np.array([0.0, 10.0, 20.0]), np.array([-5.0, 5.0])
    elev = np.array([[-100.0, -90.0, 4.0], [-100.0, -90.0, -80.0]])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        import tempfile

        with tempfile.TemporaryDirectory() as folder:
            path = f"{folder}/g.nc"
            xr.Dataset({"elevation": (("y", "x"), elev)}, coords={"x": x, "y": y}).to_netcdf(path)
            g = cartesian_grid(BathymetryGrid(file=path))
    np.testing.assert_array_equal(g.x, x)
    np.testing.assert_array_equal(g.elevation, np.where(elev < 0, elev, np.nan))


def _spread(seabed, anchors_on_seabed=True, statics="auto"):
    """The example spread mooring (3 chains of 650 m to a buoy in 150 m) with its anchors given by x, y only."""
    import yaml

    data = yaml.safe_load((EXAMPLES / "spread_mooring.yaml").read_text())
    data["environment"]["seabed"] = seabed
    data["analysis"] = {"type": "system_static", "statics": statics}
    for k in ("anchor1", "anchor2", "anchor3"):
        p = data["points"][k]["position"]
        data["points"][k]["position"] = [p[0], p[1]] if anchors_on_seabed else [p[0], p[1], "seabed"]
    from seacable.system.case import SystemCase

    return SystemCase.parse(data)


EXAMPLES = __import__("pathlib").Path(sc.__file__).resolve().parents[2] / "examples"


def test_a_system_on_a_plane_grid_gives_the_sloped_seabeds_statics():
    """The spread mooring's finite-element statics (a sloped seabed or a grid need them: the catenary statics'
    seabed is level) on a 0.03 rad slope and on the grid of that plane, the anchors given at (x, y) only (on the
    seabed: the plane's or the grid's under them, -168.19 m at x = -606 m): the same fairlead and anchor tensions
    within 1e-8 of the largest (Newton's tolerance; measured 1e-10), and the same anchor positions."""
    x = np.linspace(-700.0, 700.0, 15)
    grid = _grid(x, [-700.0, 700.0], [150.0 - math.tan(0.03) * x] * 2)
    a, b = _spread({"slope": 0.03}, False), _spread({"grid": grid})
    assert b.points["anchor1"].position == pytest.approx((-606.0, 0.0, -150.0 - math.tan(0.03) * 606.0), abs=1e-9)
    assert a.points["anchor1"].position == pytest.approx(b.points["anchor1"].position, abs=1e-9)
    ra, rb = sc.run(a), sc.run(b)
    assert ra.attrs["statics"] == rb.attrs["statics"] == "finite_element"
    top = float(ra.fairlead_tension.max())
    for v in ("fairlead_tension", "anchor_tension", "anchor_vertical_force"):
        np.testing.assert_allclose(rb[v].values, ra[v].values, rtol=0, atol=1e-8 * top)
    catenary = _spread({"grid": grid}, statics="catenary")
    with pytest.raises(InputError, match=r"environment.seabed.grid is not supported by the system catenary statics"):
        sc.run(catenary)


def test_a_system_point_off_the_grid_is_refused():
    """An anchor given on the seabed (x, y only) beyond the grid: the case is refused, naming the point."""
    grid = _grid([-500.0, 700.0], [-700.0, 700.0], [[150.0, 150.0]] * 2)
    with pytest.raises(InputError, match=r"environment.seabed.grid does not cover the point 'anchor1' \(given on the "
                                         r"seabed\): no seabed under x = -606.0 m, y = 0.0 m"):
        _spread({"grid": grid})


def test_a_towed_sled_rides_on_a_grid_as_on_the_profile():
    """The towed finite-element line: a heavy sled on 300 m of cable towed over a seabed rising from 100 to 70 m
    (the profile of towed/test_fe_inputs' sled) and over the grid of the same depths: the same run (positions within
    1 mm, the contact's rounding of the grid's normal; measured below 1e-9 m) and the same clearance, the grid's
    depth under each node."""
    import copy

    spec = {"name": "tow", "line_types": {"c": {"diameter": 0.03, "mass_per_length": 2.0, "axial_stiffness": 4e6,
                                               "drag_normal": 1.5, "drag_tangential": 0.01}},
            "line": {"line_type": "c", "length": 300.0}, "environment": {"water_density": 1025.0},
            "analysis": {"type": "towed_dynamic", "vessel": {"type": "straight", "speed": 1.0}, "duration": 40.0,
                         "time_step": 1.0, "n_nodes": 31,
                         "body": {"mass": 600.0, "weight_in_water": 5000.0, "drag_area": 0.2, "seabed_area": 2.0}}}
    dist, dep = [-400.0, -260.0, 0.0, 100.0], [100.0, 100.0, 70.0, 70.0]
    a, b = copy.deepcopy(spec), copy.deepcopy(spec)
    a["environment"]["seabed"] = {"profile": {"distance": dist, "depth": dep}, "friction": 0.3}
    b["environment"]["seabed"] = {"grid": _grid(dist, [-50.0, 50.0], [dep, dep]), "friction": 0.3}
    ra, rb = sc.run(sc.Case.parse(a)), sc.run(sc.Case.parse(b))
    for v in ("x", "z"):
        np.testing.assert_allclose(rb[v].values, ra[v].values, rtol=0, atol=1e-3)
    np.testing.assert_allclose(rb.seabed_clearance.values, ra.seabed_clearance.values, rtol=0, atol=1e-3)
    assert float(np.max(rb.z.values[:, 0])) > -100.0 + 1.0  # the sled has climbed the rise
    b["analysis"]["vessel"]["speed"] = 12.0  # 480 m in 40 s: past the grid's end at x = 100 m
    with pytest.raises(InputError, match=r"does not cover the tow point's path: no seabed under x = 1[0-9.]+ m"):
        sc.check(sc.Case.parse(b))


def test_the_box_tows_clearance_is_over_the_grid():
    """The box scheme has no contact: its clearance is each node's height above the grid's seabed under it (here a
    seabed rising 10 m across the tow, in y), and its warning names the grid; with a wrong floor the clearance
    differs."""
    from seacable.towed.seabed import seabed_clearance

    z = np.array([[-80.0, -60.0, -5.0], [-95.0, -60.0, -5.0]])
    floor = np.array([[-90.0, -85.0, -80.0], [-90.0, -85.0, -80.0]])
    with pytest.warns(sc.SeacableWarning, match=r"at t = 1 s node 0 is 95 m deep, below the seabed at 90 m "
                                                r"\(environment.seabed.grid\)"):
        h = seabed_clearance([0.0, 1.0], z, 100.0, analysis="test", floor=floor)
    np.testing.assert_array_equal(h, [10.0, -5.0])
    np.testing.assert_array_equal(seabed_clearance([0.0], z[:1], 100.0, analysis="test"), [20.0])
    # a box run over a grid rising from 170 to 130 m along the tow (no depth given): its clearance is the least
    # height over the grid's bilinear (here linear) seabed under each node, not over the depth at the origin
    spec = {"name": "tow", "line_types": {"c": {"diameter": 0.03, "mass_per_length": 2.0, "axial_stiffness": 4e6,
                                               "drag_normal": 1.5, "drag_tangential": 0.01, "bending_stiffness": 30.0}},
            "line": {"line_type": "c", "length": 200.0}, "environment": {"water_density": 1025.0, "seabed": {
                "grid": _grid([-400.0, 100.0], [-100.0, 100.0], [[170.0, 130.0]] * 2)}},
            "analysis": {"type": "towed_dynamic", "formulation": "box", "vessel": {"type": "straight", "speed": 1.5},
                         "duration": 10.0, "time_step": 1.0, "n_nodes": 21,
                         "body": {"mass": 300.0, "weight_in_water": 2000.0, "drag_area": 0.3}}}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sc.SeacableWarning)  # the box scheme's 'no seabed contact' warning
        ds = sc.run(sc.Case.parse(spec))
    floor = -170.0 + 40.0 * (ds.x.values + 400.0) / 500.0
    np.testing.assert_allclose(ds.seabed_clearance.values, np.nanmin(ds.z.values - floor, axis=1), rtol=0, atol=1e-9)
    # not the plane at the depth under the origin, 138 m (the body, 150 m behind it, is 12 m deeper there)
    assert np.all(np.abs(ds.seabed_clearance.values - np.nanmin(ds.z.values + 138.0, axis=1)) > 5.0)


def test_a_system_dynamic_run_on_a_plane_grid_gives_the_sloped_seabeds():
    """The system dynamics take the grid through the same environment vector: 2 s of the spread mooring from its
    equilibrium on the 0.03 rad slope (its anchors given with ``z: seabed``) and on the grid of that plane (no depth
    given; its anchors at x, y only): the same tensions and anchor forces within 1e-8 of the largest (measured
    1e-10)."""
    import copy

    import yaml

    from seacable.system.case import SystemCase

    d = yaml.safe_load((EXAMPLES / "spread_mooring.yaml").read_text())
    d["analysis"] = {"type": "system_dynamic", "duration": 2.0, "time_step": 0.1, "output_interval": 0.5}
    x = np.linspace(-700.0, 700.0, 15)
    a, b = copy.deepcopy(d), copy.deepcopy(d)
    a["environment"]["seabed"] = {"slope": 0.03}
    del b["environment"]["depth"]
    b["environment"]["seabed"] = {"grid": _grid(x, [-700.0, 700.0], [150.0 - math.tan(0.03) * x] * 2)}
    for k in ("anchor1", "anchor2", "anchor3"):
        p = d["points"][k]["position"]
        a["points"][k]["position"] = [p[0], p[1], "seabed"]
        b["points"][k]["position"] = [p[0], p[1]]
    ra, rb = sc.run(SystemCase.parse(a)), sc.run(SystemCase.parse(b))
    top = float(ra.fairlead_tension.max())
    for v in ("fairlead_tension", "anchor_tension", "anchor_vertical_force", "fairlead_force_x"):
        np.testing.assert_allclose(rb[v].values, ra[v].values, rtol=0, atol=1e-8 * top)
    assert rb.attrs["depth"] == pytest.approx(150.0)  # the grid's under the origin

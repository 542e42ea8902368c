"""The coupled lines-and-bodies time loop of ``system_dynamic`` gives the lines the kinematics of an irregular sea
(issue 39): the kinematics precomputed on a grid (:meth:`seacable.mooring.solver.MooringModel.prepare_sea`) as
the single-line solver and a system of prescribed bodies (:func:`seacable.system.dynamics.loop._simulate_lines`)
have them.

A free buoy held nearly still by a stiff spring (10^12 N/m, 10^14 N m/rad: the lines' pull varies by about 10^5 N,
so the buoy moves about 10^-8 m) is the fixed buoy, whose lines run in the mooring model's
compiled loop: the same lines, in the same JONSWAP sea, give the same tensions.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml

import seacable as sc
import seacable.system.dynamics as D
from seacable.results import body_pose
from seacable.system.dynamics import kernel as DK
from seacable.system.dynamics import loop as DL

SPREAD = Path(__file__).parents[2] / "examples" / "spread_mooring.yaml"
VOLTURNUS = Path(__file__).parents[1] / "data" / "volturnus" / "IEA-15-240-RWT-UMaineSemi"
SEA = {"spectrum": "jonswap", "hs": 6.0, "tp": 9.0, "seed": 3, "n_components": 100}
STIFF = np.diag([1e12] * 3 + [1e14] * 3)


def _spread(kind: str, waves=SEA):
    data = yaml.safe_load(SPREAD.read_text())
    body = data["bodies"]["buoy"]
    body.pop("external_force")
    body["kind"] = kind
    if kind == "free":  # held nearly still where the case puts it
        for key in ("waterplane_area", "waterplane_moments"):
            body.pop(key)
        body["hydrostatic_stiffness"] = STIFF.tolist()
    data["environment"]["waves"] = waves
    data["analysis"] = {"type": "system_dynamic", "duration": 30.0, "time_step": 0.1, "output_interval": 0.5,
                        "n_elements": 20}
    return sc.parse_case(data)


@pytest.mark.filterwarnings("ignore:the water's waves act on the lines only:seacable.errors.SeacableWarning")
def test_a_free_body_held_still_gives_its_lines_the_tensions_of_a_fixed_one(monkeypatch):
    """The free buoy's coupled run and the fixed buoy's lines-only run in one irregular sea: fairlead tensions
    within 1e-4 of the mean fairlead tension (50 N of 0.51 MN; measured 2.3e-5). Both take the same Newmark steps
    of the same equations, each converged to the Newton tolerance only, and the chains' dynamics amplify that
    difference over the run: in calm water the two agree to 0.003 N, in the sea to 12 N after 30 s, to 180 N with
    the tolerance 100 times looser and to 2 N with it 10 times tighter; the buoy moves 1e-8 m. The same with the
    coupled grid's box widened by the free body's excursion allowance (15 m each way: the kinematics interpolated
    between other grid points; measured the same 12 N) and without it (``SEA_EXCURSION`` 0: the two grids alike).
    The sea's own share of the tensions, their largest difference from calm water (measured 1970 N), is over 20
    times the tolerance: lines given still water instead fail the comparison. All with the one grid of the
    lines-only run (``SEA_BANDS`` off here).

    Then the coupled run's own grid, in depth bands (``SEA_BANDS``, the default), against the one grid, in the sea
    of seed 4 at a step of 0.05 s: the sea share (tension minus calm water's) within 0.75 % in standard deviation
    and 3 % at its largest on each line (measured 0.41 % and 0.61 %; with the seeds 1, 2, 3, 5 at most 0.21 % and
    0.27 %). The one grid refined four times in time and space moves the share's standard deviation by 0.46 % here:
    the tolerance is the two grids' own errors. On the bands' own steps, without ``seacable.seastate.BAND_REFINE``,
    they took 1.1 % off it (the interpolation's bias, see there), and fail. At the 0.1 s step above the comparison
    is ill-conditioned: the touchdown node of line 0 lands at about t = 22 s (seed 3), a seabed contact whose period
    (about 0.12 s) the step does not resolve, and after it any change of the kinematics is amplified (the one grid
    refined twice moves line 0's largest sea share by 14 %, the bands by 17 %; before it, all agree within 70 N)."""
    monkeypatch.setattr(DL, "SEA_BANDS", False)
    held = _spread("fixed")
    setup = D.prepare_system_dynamic(held)
    assert D.lines_only(setup.fe)  # the mooring model's compiled loop
    ref = sc.run(held).fairlead_tension.values
    mean = float(np.mean(ref))
    free = _spread("free")
    assert not D.lines_only(D.prepare_system_dynamic(free).fe)  # the coupled loop
    widened = sc.run(free)
    q = body_pose(widened)
    assert float(np.max(np.abs(q - q[0]))) < 1e-6  # held nearly still
    calm = sc.run(_spread("free", waves=None)).fairlead_tension.values
    tol = 1e-4 * mean
    sea_share = float(np.max(np.abs(ref - calm)))
    assert sea_share > 20 * tol, sea_share / mean
    assert float(np.max(np.abs(widened.fairlead_tension.values - ref))) < tol
    monkeypatch.setattr(DL, "SEA_EXCURSION", 0.0)
    same = sc.run(free).fairlead_tension.values
    assert float(np.max(np.abs(same - ref))) < tol, float(np.max(np.abs(same - ref))) / mean
    monkeypatch.setattr(DL, "SEA_BANDS", True)
    assert DL.sea_bands(D.prepare_system_dynamic(free).fe)
    half, sea = {"time_step": 0.05}, {**SEA, "seed": 4}
    still = _run(_spread("free", waves=None), half)
    share, banded = _run(_spread("fixed", sea), half) - still, _run(_spread("free", sea), half) - still
    std = np.std(banded, axis=0) / np.std(share, axis=0) - 1.0
    top = np.max(np.abs(banded), axis=0) / np.max(np.abs(share), axis=0) - 1.0
    assert np.all(np.abs(std) < 0.0075) and np.all(np.abs(top) < 0.03), (std, top)


def _run(case, analysis):
    """The fairlead tensions of ``case`` run with its analysis changed by ``analysis``. [N]"""
    return sc.run(case.model_copy(update={"analysis": case.analysis.model_copy(update=analysis)})).fairlead_tension.values


ROPE = {"diameter": 0.1, "mass_per_length": 8.0, "axial_stiffness": 1e8}


def _hull(hull_case, tmp_path: Path, waves) -> Path:
    """The VolturnUS-S hull of tests/validation/conftest.py on three ropes with drag, 60 s."""
    return hull_case(tmp_path, waves=waves, rope=ROPE, body={"hydrodynamics": {"file": str(VOLTURNUS), "kernel_length": 60.0,
                                                                                   "ramp": 20.0}},
                     analysis={"duration": 60.0, "output_interval": 0.5})


def test_a_floating_body_with_its_database_runs_in_an_irregular_sea(tmp_path, hull_case):
    """The hull with its WAMIT database (radiation memory, first-order excitation) in a JONSWAP sea (Hs 4 m, Tp
    10 s, cut at the extract's 1.45 rad/s), refused before as an irregular sea with a free body: the coupled run
    goes through, the body heaves with the sea (a heave range of 0.05 to 4 m in the 40 s after the 20 s ramp:
    the semi-submersible's heave RAO is 0.1-1 below its 20 s heave period, against a surface range of about
    1.5 Hs), and the ropes' tensions move with it."""
    sea = {"spectrum": "jonswap", "hs": 4.0, "tp": 10.0, "seed": 2, "n_components": 80, "frequency_range": [0.3, 1.45]}
    ds = sc.run(sc.load_case(_hull(hull_case, tmp_path, sea)))
    t = ds.time.values
    after = t > 20.0
    heave = body_pose(ds)[:, 0, 2]
    assert np.all(np.isfinite(body_pose(ds))) and np.all(np.isfinite(ds.fairlead_tension.values))
    assert 0.05 < float(np.ptp(heave[after])) < 4.0, float(np.ptp(heave[after]))
    eta = ds.wave_elevation.values
    assert 2.0 < float(np.ptp(eta[after])) < 12.0  # the irregular sea stored, about Hs to 2.5 Hs in a minute
    ten = ds.fairlead_tension.values
    assert float(np.ptp(ten[after])) > 1e3


def test_a_body_with_radiation_memory_halves_a_step_that_fails(tmp_path, monkeypatch, hull_case):
    """A step that does not converge is redone at half steps for a body with radiation memory too (its history
    kept at the full step; a half step takes it as it stands, see
    :func:`seacable.system.dynamics.kernel.coupled_steps`), where it stopped the run before: the hull in a
    2 m regular wave (7.4 s) with the interval at 30 s forced to halve keeps its surge, heave and pitch within 1 %
    of their ranges of the run stepped whole throughout (measured 0.23 % in surge, 0.05 % in heave and pitch):
    the interval's ten half steps integrate differently (Newmark's error, second order in the step) and their
    memory force is lagged by at most one step (0.1 s of the kernel's 60 s), a difference the lightly damped
    surge (5 % of critical) carries on; and the halved interval does change the run."""
    case = sc.load_case(_hull(hull_case, tmp_path, {"height": 2.0, "period": 7.4}))
    ref = body_pose(sc.run(case))[:, 0]
    orig = DK.coupled_steps
    forced = []

    def flaky(*args):
        if not forced and abs(args[6] - 30.0) < 1e-9 and args[7] == 0.1:  # the interval from 30 s: fails
            forced.append(args[6])
            return 0
        return orig(*args)

    monkeypatch.setattr(DK, "coupled_steps", flaky)
    halved = body_pose(sc.run(case))[:, 0]
    assert forced == [30.0]
    span = np.ptp(ref, axis=0)
    err = np.max(np.abs(halved - ref), axis=0)
    assert np.all(err[[0, 2, 4]] < 1e-2 * span[[0, 2, 4]]), err / span
    assert np.any(err > 0.0)


def test_a_body_that_leaves_the_seas_grid_is_said_once(tmp_path, monkeypatch, hull_case):
    """No silent edge values: when a free body's fairlead is outside the sea's grid after an output interval
    (:func:`seacable.system.dynamics.loop.outside_sea`, below; here made to say so from the first interval, since
    the grid spans the anchors and a moored body rarely leaves it) the run says so once, with the time and where,
    and goes on."""
    from seacable.errors import SeacableWarning

    sea = {"spectrum": "jonswap", "hs": 2.0, "tp": 10.0, "seed": 2, "n_components": 40, "frequency_range": [0.4, 1.4]}
    case = sc.load_case(hull_case(tmp_path, waves=sea, rope=ROPE, analysis={"duration": 2.0, "output_interval": 0.5}))
    seen = []
    monkeypatch.setattr(DL, "outside_sea", lambda grid, points: seen.append(len(points)) or 0)
    with pytest.warns(SeacableWarning, match=r"at t = 0.5 s a free body's fairlead \(x = .* m, y = .* m\) has left "
                                             r"the irregular sea's kinematics grid") as said:
        ds = sc.run(case)
    assert len([w for w in said if "left the irregular sea" in str(w.message)]) == 1
    assert seen == [3] and ds.time.values[-1] == 2.0  # checked until it is said (the three fairleads), then run on


def test_outside_the_grid_along_and_across_the_mean_heading():
    """The grid's horizontal extent, in its own axes: a long-crested sea's only along its heading."""
    from seacable.seastate import GRID_HEADER, S_COS, S_DX, S_DY, S_MODE, S_NX, S_NY, S_SIN, S_X0, S_Y0

    sea = np.zeros(GRID_HEADER)
    sea[[S_MODE, S_X0, S_DX, S_NX, S_Y0, S_DY, S_NY, S_COS, S_SIN]] = (1, -10, 1, 21, -5, 1, 11, 0, 1)  # heading +y
    inside, beyond_along, beyond_across = (0.0, 9.0, 0.0), (0.0, 11.0, 0.0), (6.0, 0.0, 0.0)
    assert DL.outside_sea(sea, [inside]) is None
    assert DL.outside_sea(sea, [inside, beyond_along]) == 1
    assert DL.outside_sea(sea, [beyond_across]) == 0
    sea[S_NY] = 1  # long-crested: no extent across
    assert DL.outside_sea(sea, [beyond_across]) is None
    assert DL.outside_sea(None, [beyond_along]) is None

"""A floating body's database from a case file in its other forms (issue 39): a Capytaine NetCDF dataset for
``hydrodynamics.file`` (``format``, or by the extension ``.nc``), and the slow drift from the full
difference-frequency QTF (``drift: qtf``, WAMIT's ``.12d`` with its pairs of periods).

The VolturnUS-S hull of tests/validation/conftest.py. Its WAMIT database written in Capytaine's layout
(tests/unit/hydro/test_capytaine.py: added_mass, radiation_damping, excitation_force, hydrostatic_stiffness; rho,
g) gives the statics the same matrices as the WAMIT files, to the bit; the QTF extract (tests/data/volturnus/qtf)
gives the run's wave loads the full QTF's slow drift of :func:`seacable.hydro.loads.qtf_drift_force` in place of
Newman's.
"""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import seacable as sc
from seacable.errors import InputError
from seacable.hydro import read_capytaine, read_wamit
from seacable.hydro.loads import qtf_drift_force, slow_drift_force
from seacable.system.hydro import body_wave_loads

DATA = Path(__file__).parents[1] / "data" / "volturnus"
ROOT = DATA / "IEA-15-240-RWT-UMaineSemi"
RHO, G = 1025.0, 9.80665
ROPE = {"diameter": 0.02, "mass_per_length": 0.5, "axial_stiffness": 1e6, "drag_normal": 0.0, "added_mass_normal": 0.0}
DOFS = ["Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw"]
STATIC = {"type": "system_static"}
WAVES = {"height": 2.0, "period": 8.0}


def _as_capytaine(path: Path, rho=RHO, g=G) -> Path:
    """The WAMIT database written as a Capytaine NetCDF dataset (omega with 0 and inf, complex values split)."""
    db = read_wamit(ROOT, rho=RHO, g=G)
    omega = np.r_[0.0, db.omega, math.inf]
    a = np.concatenate([db.added_mass_zero[None], db.added_mass, db.added_mass_inf[None]])
    b = np.concatenate([np.zeros((1, 6, 6)), db.damping, np.zeros((1, 6, 6))])
    rad = ("omega", "influenced_dof", "radiating_dof")
    ds = xr.Dataset({"added_mass": (rad, a), "radiation_damping": (rad, b),
                     "hydrostatic_stiffness": (("influenced_dof", "radiating_dof"), db.hydrostatics)},
                    coords={"omega": omega, "influenced_dof": DOFS, "radiating_dof": DOFS, "rho": rho, "g": g})
    exc = xr.Dataset({"excitation_force": (("omega", "wave_direction", "influenced_dof"),
                                           np.transpose(db.excitation, (1, 0, 2)))},
                     coords={"omega": db.excitation_omega, "wave_direction": db.heading, "influenced_dof": DOFS})
    ds = xr.merge([ds, exc], join="outer", compat="no_conflicts")  # NaN where one of them was not solved
    x = ds["excitation_force"]
    ds["excitation_force"] = xr.DataArray(np.stack([x.values.real, x.values.imag]), dims=("complex",) + x.dims)
    ds = ds.assign_coords(complex=["re", "im"])
    ds.to_netcdf(path)
    return path


def test_a_capytaine_dataset_gives_the_statics_the_wamit_matrices(tmp_path, hull_case):
    """By its extension, the .nc file is read as Capytaine's: with ``weight_in_hydrostatics: false`` (these
    hydrostatics are WAMIT's, without the weight) the body's stiffness and added mass are the WAMIT case's to the
    bit; by default a Capytaine database holds the weight's moment, so none is added."""
    nc = _as_capytaine(tmp_path / "hull.nc")
    assert read_capytaine(nc).excitation is not None
    wamit = sc.load_case(hull_case(tmp_path, waves=WAVES, rope=ROPE, analysis=STATIC)).system().bodies["hull"]
    body = {"hydrodynamics": {"file": str(nc), "weight_in_hydrostatics": False}}
    capy = sc.load_case(hull_case(tmp_path, waves=WAVES, rope=ROPE, analysis=STATIC, body=body)).system().bodies["hull"]
    np.testing.assert_array_equal(np.asarray(capy.hydrostatic_stiffness), np.asarray(wamit.hydrostatic_stiffness))
    np.testing.assert_array_equal(np.asarray(capy.added_mass), np.asarray(wamit.added_mass))
    body = {"hydrodynamics": {"file": str(nc), "format": "capytaine"}}
    default = sc.load_case(hull_case(tmp_path, waves=WAVES, rope=ROPE, analysis=STATIC, body=body)).system()
    np.testing.assert_array_equal(np.asarray(default.bodies["hull"].hydrostatic_stiffness),
                                  read_wamit(ROOT, rho=RHO, g=G).hydrostatics)


@pytest.mark.parametrize("hydrodynamics, message", [
    ({"ulen": 2.0}, r"ulen is WAMIT's length scale; a Capytaine dataset is dimensional"),
    ({"rho": 1000.0}, r"was solved with the water density 1000 and the case has 1025"),
    ({"file": "missing.nc"}, r"Capytaine dataset '.*missing.nc' does not exist"),
])
def test_a_capytaine_dataset_that_does_not_fit_the_case_is_refused(tmp_path, hull_case, hydrodynamics, message):
    rho = hydrodynamics.pop("rho", RHO)
    nc = _as_capytaine(tmp_path / "hull.nc", rho=rho)
    body = {"hydrodynamics": {"file": str(nc), **hydrodynamics}}
    with pytest.raises(Exception, match=message):
        sc.load_case(hull_case(tmp_path, waves=WAVES, rope=ROPE, analysis=STATIC, body=body)).system()


def _qtf_root(folder: Path, twelve_d: Path) -> Path:
    for ext in (".1", ".3", ".hst"):
        shutil.copy(f"{ROOT}{ext}", folder / f"hull{ext}")
    shutil.copy(twelve_d, folder / "hull.12d")
    return folder / "hull"


SEA = {"spectrum": "jonswap", "hs": 6.0, "tp": 11.0, "seed": 3, "n_components": 60, "frequency_range": [0.3, 0.99]}


def test_drift_qtf_gives_the_run_the_full_qtfs_slow_drift(tmp_path, hull_case):
    """``drift: qtf``: the body's wave loads differ from Newman's by the full QTF's slow drift less Newman's, to
    round-off, and the case passes the run's checks."""
    root = _qtf_root(tmp_path, DATA / "qtf" / "IEA-15-240-RWT-UMaineSemi.12d")
    cases = {drift: sc.load_case(hull_case(tmp_path, waves=SEA, rope=ROPE, analysis={"duration": 20.0}, body={
        "hydrodynamics": {"file": str(root), "kernel_length": 60.0, "drift": drift}})) for drift in ("qtf", "newman")}
    t = np.arange(0.0, 200.0, 0.5)
    env = cases["qtf"].environment
    sea = env.waves.components(env.depth, env.gravity)
    loads = {d: body_wave_loads(c.system().bodies["hull"], "hull", sea, RHO, G, t) for d, c in cases.items()}
    db = read_wamit(root, rho=RHO, g=G)
    newman = slow_drift_force(db, sea, t)
    expected = qtf_drift_force(db, sea, t) - newman
    # from t > 0 (ramp 0: the oscillating loads start from zero at t = 0, the mean from the start)
    np.testing.assert_allclose((loads["qtf"] - loads["newman"])[1:], expected[1:], rtol=0,
                               atol=1e-9 * np.abs(loads["newman"]).max())
    assert np.std(expected[:, 0]) > 0.1 * np.std(newman[:, 0])  # the two slow drifts differ
    sc.check(cases["qtf"])


@pytest.mark.parametrize("waves, twelve_d, message", [
    # the mean drift's checks come first: a drift table of one heading, frequencies within the table's
    ({**SEA, "spreading": 10.0}, "qtf", r"bodies.hull.hydrodynamics: .*gives the mean drift for waves towards 0 deg only"),
    (SEA, "diagonal", r"bodies.hull.hydrodynamics: .*no full difference-frequency QTF .*drift: newman"),
    ({**SEA, "frequency_range": [0.3, 1.4]}, "qtf", r"bodies.hull.hydrodynamics: .*is asked for at 1.01 rad/s, outside its frequencies 0.3-1 rad/s"),
])
def test_drift_qtf_without_its_qtf_or_its_sea_is_refused_before_the_run(tmp_path, hull_case, waves, twelve_d, message):
    """One clear message each, from the run's checks (validate's)."""
    twelve_d = DATA / "qtf" / "IEA-15-240-RWT-UMaineSemi.12d" if twelve_d == "qtf" else Path(f"{ROOT}.12d")
    root = _qtf_root(tmp_path, twelve_d)
    case = sc.load_case(hull_case(tmp_path, waves=waves, rope=ROPE, analysis={"duration": 10.0}, body={
        "hydrodynamics": {"file": str(root), "kernel_length": 60.0, "drift": "qtf"}}))
    with pytest.raises(InputError, match=message):
        sc.check(case)

"""Capytaine's datasets read into a hydrodynamic database (issue 39), on datasets written here in Capytaine's layout.

The layout is that of ``cpt.assemble_dataset`` / ``BEMSolver.fill_dataset`` (Capytaine 2.x-3.0: variables
``added_mass``, ``radiation_damping`` (frequency, influenced_dof, radiating_dof), ``excitation_force``,
``Froude_Krylov_force``, ``diffraction_force`` (frequency, wave_direction, influenced_dof), ``hydrostatic_stiffness``,
``inertia_matrix``; scalar coordinates ``rho``, ``g``, ``water_depth``, ``forward_speed``; ``rotation_center`` along
``space_coordinate``), saved to NetCDF with the complex values along a ``complex`` dimension (``re``, ``im``) as
``capytaine.io.xarray.separate_complex_values`` does. These tests need neither Capytaine nor its solver; the
dataset Capytaine itself computes is read in tests/validation/test_capytaine_hemisphere.py (skipped without it).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

from seacable.errors import InputError
from seacable.hydro import read_capytaine

DOFS = ["Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw"]


def _dataset(*, omega=(0.0, 0.4, 0.8, 1.2, math.inf), directions=(0.0, math.pi / 2, 3 * math.pi / 2, 2 * math.pi),
             dofs=DOFS, seed=1):
    """A dataset in Capytaine's layout: random coefficients, each entry its own value, NaN where Capytaine leaves
    them (no diffraction at zero and infinite frequency), the DOFs in the order ``dofs``."""
    rng = np.random.default_rng(seed)
    w = np.asarray(omega, float)
    nf, nb, n = w.size, len(directions), len(dofs)
    a = rng.uniform(1e3, 1e6, (nf, n, n))
    b = rng.uniform(1e2, 1e5, (nf, n, n))
    b[~np.isfinite(w) | (w == 0)] = 0.0
    fk = rng.normal(size=(nf, nb, n)) * 1e5 + 1j * rng.normal(size=(nf, nb, n)) * 1e5
    diff = rng.normal(size=(nf, nb, n)) * 1e4 + 1j * rng.normal(size=(nf, nb, n)) * 1e4
    fk[~np.isfinite(w) | (w == 0)] = np.nan
    diff[~np.isfinite(w) | (w == 0)] = np.nan
    rad = ("omega", "influenced_dof", "radiating_dof")
    dif = ("omega", "wave_direction", "influenced_dof")
    return xr.Dataset(
        {"added_mass": (rad, a), "radiation_damping": (rad, b), "Froude_Krylov_force": (dif, fk),
         "diffraction_force": (dif, diff), "excitation_force": (dif, fk + diff),
         "hydrostatic_stiffness": (("influenced_dof", "radiating_dof"), rng.uniform(0, 1e6, (n, n))),
         "inertia_matrix": (("influenced_dof", "radiating_dof"), rng.uniform(0, 1e6, (n, n)))},
        coords={"omega": w, "wave_direction": list(directions), "influenced_dof": list(dofs),
                "radiating_dof": list(dofs), "rho": 1025.0, "g": 9.81, "water_depth": math.inf, "forward_speed": 0.0,
                "space_coordinate": ["x", "y", "z"], "rotation_center": ("space_coordinate", [1.0, -2.0, 0.5])})


def _separated(ds: xr.Dataset) -> xr.Dataset:
    """The complex variables split along a ``complex`` dimension, as Capytaine's separate_complex_values."""
    ds = ds.copy()
    for name in list(ds.data_vars):
        if np.iscomplexobj(ds[name].values):
            da = ds[name]
            ds[name] = xr.DataArray(np.stack([da.values.real, da.values.imag]), dims=("complex",) + da.dims)
    return ds.assign_coords(complex=["re", "im"])


def test_the_coefficients_keep_their_rows_columns_frequencies_and_limits():
    """``added_mass[f, i, j]`` is the force in ``influenced_dof`` i of the motion in ``radiating_dof`` j, the DOFs
    taken by name (the dataset's order reversed here), the finite frequencies sorted, omega = inf and 0 the
    limits; the hydrostatics, inertia, rho, g and the rotation centre as given."""
    ds = _dataset(dofs=DOFS[::-1])
    db = read_capytaine(ds)
    a = ds["added_mass"].sel(influenced_dof=DOFS, radiating_dof=DOFS).values
    np.testing.assert_array_equal(db.omega, [0.4, 0.8, 1.2])
    np.testing.assert_array_equal(db.added_mass, a[1:4])
    np.testing.assert_array_equal(db.added_mass_inf, a[4])
    np.testing.assert_array_equal(db.added_mass_zero, a[0])
    np.testing.assert_array_equal(db.damping, ds["radiation_damping"].sel(influenced_dof=DOFS, radiating_dof=DOFS).values[1:4])
    assert db.added_mass[1, 2, 4] == ds["added_mass"].sel(omega=0.8, influenced_dof="Heave", radiating_dof="Pitch")
    np.testing.assert_array_equal(db.hydrostatics,
                                  ds["hydrostatic_stiffness"].sel(influenced_dof=DOFS, radiating_dof=DOFS).values)
    np.testing.assert_array_equal(db.inertia, ds["inertia_matrix"].sel(influenced_dof=DOFS, radiating_dof=DOFS).values)
    assert (db.rho, db.g) == (1025.0, 9.81)
    np.testing.assert_array_equal(db.reference, [1.0, -2.0, 0.5])


def test_the_excitation_is_seacables_as_it_is_and_the_headings_wrap():
    """Capytaine's phasors are seacable's (e^(-i w t), wave_direction the way the waves travel): no conjugate. The
    directions 0, 90, 270, 360 deg are the headings -90, 0, 90 deg (360 is 0, kept once: the first)."""
    ds = _dataset()
    db = read_capytaine(ds)
    np.testing.assert_allclose(db.heading, [-math.pi / 2, 0.0, math.pi / 2], atol=1e-12)
    np.testing.assert_array_equal(db.excitation_omega, [0.4, 0.8, 1.2])
    x = ds["excitation_force"].sel(influenced_dof=DOFS).values  # (omega, direction, dof)
    np.testing.assert_array_equal(db.excitation[0], x[1:4, 2])   # 270 deg -> -90
    np.testing.assert_array_equal(db.excitation[1], x[1:4, 0])   # 0 deg
    np.testing.assert_array_equal(db.excitation[2], x[1:4, 1])   # 90 deg
    # without the total, the sum of its parts
    parts = read_capytaine(ds.drop_vars("excitation_force"))
    np.testing.assert_allclose(parts.excitation, db.excitation, rtol=1e-15)
    # no excitation at all: a radiation-only database
    assert read_capytaine(ds.drop_vars(["excitation_force", "Froude_Krylov_force", "diffraction_force"])).excitation is None


def test_a_netcdf_file_reads_as_the_dataset(tmp_path):
    """Written with the complex values split (re, im) and the DOF names as strings, as Capytaine saves it: the same
    database to the bit."""
    ds = _dataset()
    path = tmp_path / "body.nc"
    _separated(ds).to_netcdf(path, encoding={"radiating_dof": {"dtype": "U"}, "influenced_dof": {"dtype": "U"}})
    a, b = read_capytaine(ds), read_capytaine(path)
    for name in ("omega", "added_mass", "damping", "added_mass_inf", "added_mass_zero", "hydrostatics", "heading",
                 "excitation_omega", "excitation", "inertia", "reference"):
        np.testing.assert_array_equal(getattr(b, name), getattr(a, name), err_msg=name)
    assert b.source == f"Capytaine dataset '{path}'"


def test_a_dataset_by_period_is_read_by_its_omega_coordinate():
    """Capytaine's main frequency dimension may be the period, with omega a coordinate along it (decreasing)."""
    ds = _dataset(omega=(0.4, 0.8, 1.2, math.inf))
    period = 2 * math.pi / ds["omega"].values
    by_period = ds.rename(omega="period").assign_coords(period=period, omega=("period", ds["omega"].values))
    by_period = by_period.isel(period=[3, 2, 1, 0])  # Capytaine sorts by its main dimension: periods increasing
    db, ref = read_capytaine(by_period), read_capytaine(ds)
    np.testing.assert_array_equal(db.omega, ref.omega)
    np.testing.assert_array_equal(db.added_mass, ref.added_mass)
    np.testing.assert_array_equal(db.added_mass_inf, ref.added_mass_inf)
    np.testing.assert_array_equal(db.excitation, ref.excitation)


@pytest.mark.parametrize("change, message", [
    (lambda ds: ds.sel(omega=[0.0, 0.4, 0.8, 1.2]), r"no infinite-frequency added mass \(omega = inf\).*numpy.inf"),
    (lambda ds: ds.assign_coords(influenced_dof=[f"a__{d}" for d in DOFS], radiating_dof=[f"a__{d}" for d in DOFS]),
     r"influenced_dofs are \['a__Surge'.*one rigid body's six DOFs"),
    (lambda ds: ds.sel(influenced_dof=DOFS[:3], radiating_dof=DOFS[:3]), r"seacable reads one rigid body's six DOFs"),
    (lambda ds: ds.assign_coords(forward_speed=2.0), r"forward speed of 2.0 m/s"),
    (lambda ds: ds.drop_vars("hydrostatic_stiffness"), r"has no hydrostatic_stiffness.*center_of_mass"),
    (lambda ds: ds.drop_vars("added_mass"), r"has no added_mass"),
    (lambda ds: ds.drop_vars("rho"), r"has no 'rho'"),
    (lambda ds: xr.concat([ds, ds.assign_coords(water_depth=50.0)], dim="water_depth"),
     r"added_mass varies along water_depth \(2 values\)"),
    (lambda ds: xr.concat([ds, ds.assign_coords(rho=1000.0)], dim="rho"), r"several values of rho: \[1000.0, 1025.0\]"),
])
def test_a_dataset_seacable_cannot_use_gets_one_clear_message(change, message):
    with pytest.raises(InputError, match=message):
        read_capytaine(change(_dataset()))


def test_a_missing_or_foreign_file_is_refused(tmp_path):
    with pytest.raises(InputError, match="does not exist"):
        read_capytaine(tmp_path / "none.nc")
    (tmp_path / "text.nc").write_text("not a netcdf file")
    with pytest.raises(InputError, match="is not a NetCDF file"):
        read_capytaine(tmp_path / "text.nc")

"""Capytaine's datasets read into a :class:`~seacable.hydro.database.HydroDatabase` (issue 39).

Capytaine (Ancellin & Dias 2019; https://github.com/capytaine/capytaine) solves the linear radiation and
diffraction problems and returns an :class:`xarray.Dataset` (``cpt.assemble_dataset`` or
``BEMSolver.fill_dataset``), saved to NetCDF with its complex values split along a ``complex`` dimension
(``re``, ``im``: ``capytaine.io.xarray.separate_complex_values``, ``save_dataset_as_netcdf``). The variables
read, all dimensional SI, with the DOFs named ``Surge``, ``Sway``, ``Heave``, ``Roll``, ``Pitch``, ``Yaw``
(``cpt.rigid_body_dofs``) about the dataset's ``rotation_center``:

=========================  ===========================================  ======================================
variable                   dimensions                                   in the database
=========================  ===========================================  ======================================
``added_mass``             frequency, ``influenced_dof``,               ``added_mass`` (finite frequencies),
                           ``radiating_dof``                            ``added_mass_inf`` (``omega = inf``),
                                                                        ``added_mass_zero`` (``omega = 0``)
``radiation_damping``      the same                                     ``damping``
``excitation_force``       frequency, ``wave_direction``,               ``excitation`` (else the sum of
                           ``influenced_dof``                           ``Froude_Krylov_force`` and
                                                                        ``diffraction_force``)
``hydrostatic_stiffness``  ``influenced_dof``, ``radiating_dof``        ``hydrostatics``
``inertia_matrix``         the same                                     ``inertia``
``rho``, ``g``             scalar coordinates                           ``rho``, ``g``
=========================  ===========================================  ======================================

The frequency dimension is Capytaine's main one (``omega``, ``period``, ``freq``, ``wavenumber`` or
``wavelength``), with the ``omega`` coordinate [rad/s] along it. Conventions (Capytaine's documentation,
"Conventions and differences to other codes"): phasors are ``x(t) = Re(X e^(-i w t))``, seacable's
(:mod:`seacable.raos`); the incident wave of unit amplitude ``Phi_0 = -i g/w e^(kz) e^(ik(x cos b + y sin b))``
has the elevation ``cos(k (x cos b + y sin b) - w t)``, so ``wave_direction`` [rad] is the direction the waves
travel towards, seacable's heading, and the elevation at the origin is ``cos(w t)``: Capytaine's excitation is
seacable's as it is (WAMIT's is its conjugate). A force matrix's row is ``influenced_dof`` (the force) and its
column ``radiating_dof`` (the motion). Headings are kept once in -pi..pi.

The infinite-frequency added mass, which the radiation memory needs, is the ``omega = inf`` entry: Capytaine
solves it directly (``omega`` given as ``numpy.inf`` in the test matrix); a dataset without it is refused (the
limit is not extrapolated from the finite frequencies). Capytaine's ``hydrostatic_stiffness`` of a rigid body
holds the weight's moment about the rotation centre, from its ``center_of_mass`` and mass (the displaced mass
unless given): a system body with such a database has ``weight_in_hydrostatics`` true by default. The mean
drift is not in Capytaine's dataset (its far-field drift is a separate post-processing of the RAOs): a database
read here has none, and no QTF.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..errors import InputError
from .database import HydroDatabase

__all__ = ["CAPYTAINE_DOFS", "read_capytaine"]

#: Capytaine's names of a rigid body's DOFs (``cpt.rigid_body_dofs``), in seacable's order.
CAPYTAINE_DOFS = ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")
_FREQUENCY_DIMS = ("omega", "period", "freq", "wavenumber", "wavelength")
_SCALAR_DIMS = ("rho", "g", "water_depth", "forward_speed", "body")


def _open(path_or_dataset):
    """The dataset and a name for messages: an :class:`xarray.Dataset`, or a NetCDF file read into memory."""
    import xarray as xr

    if isinstance(path_or_dataset, xr.Dataset):
        return path_or_dataset, "Capytaine dataset"
    path = Path(path_or_dataset)
    if not path.is_file():
        raise InputError(f"Capytaine dataset '{path}' does not exist. Suggested fix: give the NetCDF file Capytaine's "
                         "save_dataset_as_netcdf (or separate_complex_values(ds).to_netcdf) wrote.")
    try:
        with xr.open_dataset(path) as ds:
            return ds.load(), f"Capytaine dataset '{path}'"
    except (OSError, ValueError) as err:
        raise InputError(f"Capytaine dataset '{path}' is not a NetCDF file xarray can read ({err}). Suggested fix: "
                         "give the .nc file Capytaine's save_dataset_as_netcdf wrote.") from None


def _merged(ds):
    """The complex variables stored as a ``complex`` dimension (``re``, ``im``) put back together."""
    if "complex" not in ds.dims:
        return ds
    parts = [str(v) for v in np.asarray(ds["complex"].values).astype(str)] if "complex" in ds.coords else ["re", "im"]
    if parts != ["re", "im"]:
        raise ValueError(f"the 'complex' dimension must be ['re', 'im'], got {parts}")
    ds = ds.copy()
    for name in list(ds.data_vars):
        if "complex" in ds[name].dims:
            da = ds[name]
            ds[name] = da.isel(complex=0, drop=True) + 1j * da.isel(complex=1, drop=True)
    return ds.drop_vars("complex", errors="ignore")


def _scalar(ds, name: str, src: str, required: bool = True):
    if name not in ds.coords and name not in ds.data_vars:
        if required:
            raise InputError(f"{src} has no '{name}'. Suggested fix: give the dataset Capytaine assembled (it stamps "
                             f"rho and g on it).")
        return None
    values = np.unique(np.asarray(ds[name].values, float).ravel())
    if values.size != 1:
        raise InputError(f"{src} holds several values of {name}: {values.tolist()}. Seacable reads one body at one "
                         f"{name}. Suggested fix: select one, ds.sel({name}=...).")
    return float(values[0])


def _squeezed(da, name: str, src: str):
    """``da`` without the dimensions of one value (rho, g, water depth, forward speed); several refused."""
    for dim in _SCALAR_DIMS:
        if dim in da.dims:
            if da.sizes[dim] != 1:
                raise InputError(f"{src}: {name} varies along {dim} ({da.sizes[dim]} values). Seacable reads one "
                                 f"{dim}. Suggested fix: select one, ds.sel({dim}=...).")
            da = da.isel({dim: 0}, drop=True)
    return da


def _frequency_dim(da, src: str) -> str:
    dims = [d for d in da.dims if d in _FREQUENCY_DIMS]
    if len(dims) != 1:
        raise InputError(f"{src}: the radiation coefficients must have one frequency dimension (one of "
                         f"{', '.join(_FREQUENCY_DIMS)}), got the dimensions {list(da.dims)}.")
    return dims[0]


def _dof_order(da, dim: str, src: str) -> list[str]:
    names = [str(v) for v in np.asarray(da[dim].values).astype(str)]
    if sorted(names) != sorted(CAPYTAINE_DOFS):
        raise InputError(f"{src}: the {dim}s are {names}; seacable reads one rigid body's six DOFs "
                         f"{list(CAPYTAINE_DOFS)}. Suggested fix: solve with cpt.rigid_body_dofs() on one body (a "
                         "multibody dataset's DOFs are named 'body__Surge'...: solve each body alone).")
    return list(CAPYTAINE_DOFS)


def _matrix_over_frequency(da, freq_dim: str, src: str, what: str) -> np.ndarray:
    da = _squeezed(da, what, src)
    if "wave_direction" in da.dims:  # radiation is the same at every wave direction (Capytaine's optional dim)
        da = da.isel(wave_direction=0, drop=True)
    _dof_order(da, "influenced_dof", src)
    _dof_order(da, "radiating_dof", src)
    da = da.sel(influenced_dof=list(CAPYTAINE_DOFS), radiating_dof=list(CAPYTAINE_DOFS))
    return np.asarray(da.transpose(freq_dim, "influenced_dof", "radiating_dof").values)


def read_capytaine(path_or_dataset, *, reference=None) -> HydroDatabase:
    """The hydrodynamic database of a Capytaine dataset (module docstring).

    Parameters
    ----------
    path_or_dataset : str, Path or xarray.Dataset
        A NetCDF file Capytaine wrote (``save_dataset_as_netcdf`` or ``separate_complex_values(ds).to_netcdf``), or
        the dataset itself (``cpt.assemble_dataset``, ``BEMSolver.fill_dataset``).
    reference : sequence of 3 float, optional
        The point the coefficients are about, in the body's axes [m]; by default the dataset's
        ``rotation_center`` (the origin when it has none).
    """
    ds, src = _open(path_or_dataset)
    try:
        ds = _merged(ds)
    except ValueError as err:
        raise InputError(f"{src}: {err}. Suggested fix: give the dataset as Capytaine wrote it.") from None
    for name in ("added_mass", "radiation_damping"):
        if name not in ds.data_vars:
            raise InputError(f"{src} has no {name}. A body model needs the radiation coefficients. Suggested fix: "
                             "solve the radiation problems of the six rigid-body DOFs (radiating_dof in the test "
                             "matrix).")
    forward = _scalar(ds, "forward_speed", src, required=False)
    if forward not in (None, 0.0):
        raise InputError(f"{src} was solved at a forward speed of {forward} m/s; seacable's bodies are moored "
                         "(zero forward speed). Suggested fix: solve with forward_speed = 0.")
    rho, g = _scalar(ds, "rho", src), _scalar(ds, "g", src)
    freq_dim = _frequency_dim(ds["added_mass"], src)
    if "omega" not in ds.coords and "omega" not in ds.data_vars:
        raise InputError(f"{src} has no omega coordinate along {freq_dim}. Suggested fix: assemble the dataset with "
                         "omega=True (Capytaine's default).")
    omega_all = np.asarray(ds["omega"].transpose(freq_dim).values, float) if ds["omega"].dims else np.atleast_1d(
        float(ds["omega"]))
    a = _matrix_over_frequency(ds["added_mass"], freq_dim, src, "added_mass").real
    b = _matrix_over_frequency(ds["radiation_damping"], freq_dim, src, "radiation_damping").real
    finite = np.isfinite(omega_all) & (omega_all > 0)
    # a frequency solved for diffraction only (outer join): no radiation there, left out
    solved = finite & np.all(np.isfinite(a), axis=(1, 2)) & np.all(np.isfinite(b), axis=(1, 2))
    inf = np.flatnonzero(np.isinf(omega_all) & np.all(np.isfinite(a), axis=(1, 2)))
    if inf.size == 0:
        raise InputError(f"{src} has no infinite-frequency added mass (omega = inf). The radiation memory (Cummins' "
                         "equation) needs it, and it is not extrapolated from the finite frequencies. Suggested fix: "
                         "add numpy.inf to the omega of Capytaine's test matrix (Capytaine solves the limit "
                         "directly), e.g. xr.Dataset(coords={'omega': [..., np.inf], ...}).")
    zero = np.flatnonzero((omega_all == 0) & np.all(np.isfinite(a), axis=(1, 2)))
    order = np.flatnonzero(solved)[np.argsort(omega_all[solved])]
    kwargs = {}
    if zero.size:
        kwargs["added_mass_zero"] = a[zero[0]]
    excitation = _excitation(ds, freq_dim, omega_all, src)
    if excitation is not None:
        kwargs.update(heading=excitation[0], excitation_omega=excitation[1], excitation=excitation[2])
    if "hydrostatic_stiffness" not in ds.data_vars:
        raise InputError(f"{src} has no hydrostatic_stiffness. A body model needs its hydrostatics. Suggested fix: "
                         "give the body a center_of_mass so that Capytaine computes it (assemble_dataset's "
                         "hydrostatics=True), or add body.compute_hydrostatic_stiffness() to the dataset.")
    hydrostatics = _matrix_over_frequency(ds["hydrostatic_stiffness"].expand_dims(_k=1), "_k", src,
                                          "hydrostatic_stiffness")[0].real
    if "inertia_matrix" in ds.data_vars:
        kwargs["inertia"] = _matrix_over_frequency(ds["inertia_matrix"].expand_dims(_k=1), "_k", src,
                                                   "inertia_matrix")[0].real
    if reference is None:
        reference = np.asarray(ds["rotation_center"].values, float) if "rotation_center" in ds.variables else np.zeros(3)
    return HydroDatabase(omega=omega_all[order], added_mass=a[order], damping=b[order], added_mass_inf=a[inf[0]],
                         hydrostatics=hydrostatics, reference=np.asarray(reference, float), rho=rho, g=g,
                         source=src, **kwargs)


def _excitation(ds, freq_dim: str, omega_all: np.ndarray, src: str):
    """``(heading, omega, excitation)`` of the dataset's excitation (or Froude-Krylov plus diffraction), at its
    finite frequencies, headings wrapped to -pi..pi and kept once; None when it has none."""
    if "excitation_force" in ds.data_vars:
        x = ds["excitation_force"]
    elif "Froude_Krylov_force" in ds.data_vars and "diffraction_force" in ds.data_vars:
        x = ds["Froude_Krylov_force"] + ds["diffraction_force"]
    else:
        return None
    x = _squeezed(x, "excitation_force", src)
    if "wave_direction" not in x.dims or freq_dim not in x.dims:
        raise InputError(f"{src}: the excitation must have the dimensions ({freq_dim}, wave_direction, "
                         f"influenced_dof), got {list(x.dims)}.")
    _dof_order(x, "influenced_dof", src)
    values = np.asarray(x.sel(influenced_dof=list(CAPYTAINE_DOFS)).transpose(
        "wave_direction", freq_dim, "influenced_dof").values).astype(complex)
    beta = np.asarray(x["wave_direction"].values, float)
    finite = np.isfinite(omega_all) & (omega_all > 0)
    solved = finite & np.all(np.isfinite(values), axis=(0, 2))
    if not np.any(solved):
        return None
    gaps = finite & ~solved & np.any(np.isfinite(values), axis=(0, 2))
    if np.any(gaps):
        w = float(omega_all[np.flatnonzero(gaps)[0]])
        raise InputError(f"{src}: the excitation at {w:.6g} rad/s is missing for some wave directions or DOFs. "
                         "Suggested fix: solve every wave direction at every frequency.")
    wrapped = np.round(np.mod(beta, 2 * math.pi), 9)
    _, first = np.unique(wrapped, return_index=True)
    first = np.sort(first)
    heading = np.where(wrapped[first] > math.pi, wrapped[first] - 2 * math.pi, wrapped[first])
    order = np.argsort(heading)
    w_order = np.flatnonzero(solved)[np.argsort(omega_all[solved])]
    table = values[first][order][:, w_order]
    return heading[order], omega_all[w_order], table

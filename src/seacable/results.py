"""The result schema: labelled xarray Datasets with units, provenance and NetCDF I/O.

Every variable and coordinate carries ``units`` and ``long_name`` attributes.
Dataset attributes record the seacable version, the analysis, its settings, the
whole case (YAML) and the references, so that a result file says how it was made.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Iterable

import numpy as np
import xarray as xr

from ._version import __version__
from .errors import InputError

__all__ = ["var", "make_dataset", "write_netcdf", "read_netcdf", "check_schema"]


def var(dims: str | Iterable[str], values, units: str, long_name: str, **attrs) -> xr.Variable:
    """A variable with its ``units`` and ``long_name``.

    Parameters
    ----------
    dims
        Dimension name(s); ``()`` for a scalar.
    values
        The data.
    units
        UDUNITS-style unit string (``"N"``, ``"m s-1"``, ``"1"`` for dimensionless).
    long_name
        A human-readable name, used as the axis label of plots.
    """
    dims = (dims,) if isinstance(dims, str) else tuple(dims)
    return xr.Variable(dims, np.asarray(values), attrs={"units": units, "long_name": long_name, **attrs})


def _attr_value(value: Any):
    if isinstance(value, (str, int, float, np.integer, np.floating)):
        return value
    if isinstance(value, bool):
        return int(value)
    return json.dumps(value, default=str)


def make_dataset(data_vars: dict[str, xr.Variable], coords: dict[str, xr.Variable], *,
                 analysis: str, case=None, settings: dict | None = None,
                 references: Iterable[str] = (), title: str | None = None) -> xr.Dataset:
    """Assemble a result Dataset and stamp its provenance.

    Parameters
    ----------
    data_vars, coords
        Variables made with :func:`var`.
    analysis
        The analysis type (``"static"``, ``"pushover"``, ...); :mod:`seacable.plot`
        chooses its figures by it.
    case
        The :class:`~seacable.case.Case` that produced the result; stored as YAML.
    settings
        Solver or model settings worth recording (JSON-able).
    references
        Citations of the methods used.
    title
        A title for plots; the case name by default.
    """
    ds = xr.Dataset(data_vars=data_vars, coords=coords)
    attrs = {
        "title": title or (case.name if case is not None else analysis),
        "analysis": analysis,
        "seacable_version": __version__,
        "Conventions": "CF-1.8",
        "source": f"seacable {__version__}",
        "settings": _attr_value(settings or {}),
        "references": "\n".join(references),
    }
    if case is not None:
        from .io.case_file import dump_case

        attrs["case_name"] = case.name
        attrs["case"] = dump_case(case)
        if case.description:
            attrs["comment"] = case.description
    ds.attrs.update(attrs)
    check_schema(ds)
    return ds


def check_schema(ds: xr.Dataset) -> None:
    """Raise if a variable or coordinate lacks ``units`` or ``long_name``.

    A guard on seacable's own results, so that every output file is labelled.
    """
    for name, item in {**ds.data_vars, **ds.coords}.items():
        missing = [k for k in ("units", "long_name") if k not in item.attrs]
        if missing:
            raise AssertionError(f"result variable '{name}' lacks {missing}")


def write_netcdf(ds: xr.Dataset, path: str | Path) -> Path:
    """Write a result to NetCDF-4, creating the folder if needed. Returns the path."""
    path = Path(path)
    if path.suffix.lower() not in (".nc", ".nc4", ".netcdf"):
        raise InputError(f"output file '{path}' must end in .nc. Suggested fix: -o {path.with_suffix('.nc')}")
    path.parent.mkdir(parents=True, exist_ok=True)
    encoding = {name: {"zlib": True, "complevel": 4} for name, v in ds.data_vars.items()
                if v.dtype.kind in "fiu" and v.ndim > 0}
    ds.to_netcdf(path, engine="netcdf4", encoding=encoding)
    return path


def read_netcdf(path: str | Path) -> xr.Dataset:
    """Read a seacable result file (loaded into memory, file closed)."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"result file '{path}' does not exist. Suggested fix: run 'seacable run CASE.yaml "
                         f"-o {path}' first.")
    try:
        with xr.open_dataset(path, engine="netcdf4") as ds:
            ds = ds.load()
    except (OSError, ValueError) as err:
        raise InputError(f"'{path}' is not a readable NetCDF file: {err}.") from None
    if "analysis" not in ds.attrs:
        raise InputError(f"'{path}' is not a seacable result (no 'analysis' attribute).")
    return ds

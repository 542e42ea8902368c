"""The CF conventions (CF-1.8) of seacable's NetCDF results: what a result file says beyond its numbers.

A result in memory keeps seacable's one vocabulary (``time`` in seconds from the start of the run, units
``"s"``); the file written from it (:func:`seacable.results.write_netcdf`, a streamed run's
:class:`seacable.sink.NetcdfSink`, a sweep's summary) is CF-1.8 as its ``Conventions`` attribute says:

- ``time`` is a CF time coordinate: units ``"seconds since 1970-01-01 00:00:00"`` (:data:`TIME_UNITS`),
  ``calendar`` ``"standard"``, ``standard_name`` ``"time"`` and ``axis`` ``"T"``. seacable's models have no
  calendar: t = 0, the start of the run, is written as the nominal epoch 1970-01-01 00:00:00 (the POSIX epoch),
  so that a tool that decodes CF times (xarray, ncview, Panoply) shows the run's clock from midnight of that
  day. :func:`decode` turns the file's time back into seconds from the start (units ``"s"``) on reading; so
  does ``xarray.open_dataset(path, decode_times=False)`` but for the units string.
- every unit is a UDUNITS-2 string (``"m"``, ``"N"``, ``"m s-1"``, ``"rad"``, ``"1"`` for a dimensionless
  number); a quantity whose components have different units is two variables (``body_position`` [m] and
  ``body_rotation`` [rad]), or, along a dimension that mixes kinds (the 6x6 stiffness of a body, a coupled code's
  degrees of freedom), one variable per unit with NaN where a component is another kind
  (:func:`split_by_kind`, :func:`joined`).
- ``standard_name`` where the CF standard-name table has an entry that means the quantity (:data:`STANDARD_NAMES`,
  a short list: each name is checked against the table shipped by the IOOS compliance checker, and its units
  against the entry's canonical units, in tests/unit/test_cf.py).
- integers are written as 32-bit integers (CF-1.8 knows no 64-bit type), and a dimension coordinate has no
  ``_FillValue`` (CF 2.5.1).
- a dimension of names (``line``, ``body``, ``dof``, ``condition``) has no coordinate variable in the file (a CF
  coordinate variable is numeric and monotonic): its names are the label variable ``line_label`` (CF 6.1), listed
  in the ``coordinates`` attribute of the variables along it; :func:`decode` makes it the coordinate again.

References
----------
Eaton, B. et al. (2020). NetCDF Climate and Forecast (CF) Metadata Conventions, version 1.8. Sections 2.2
(data types), 2.5.1 (missing data), 3.1 (units), 3.3 (standard names), 4.4 (time coordinate).
CF Standard Name Table, version 93 (2026).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

__all__ = ["ANGLES", "STANDARD_NAMES", "STIFFNESS_BLOCKS", "TIME_UNITS", "annotate", "body_pose", "decode",
           "dof_kind", "encode", "int32_dtype", "joined", "matrix_variables", "split_by_kind", "stiffness_matrix"]

#: The units of the time coordinate in a result file: t = 0 (the start of the run) at a nominal epoch.
TIME_UNITS = "seconds since 1970-01-01 00:00:00"
TIME_CALENDAR = "standard"
#: the suffix of the label variable that holds a dimension's names in a file (``line`` -> ``line_label``)
LABEL = "_label"

#: result variable -> its CF standard name. Only genuine table entries whose meaning is the variable's (the
#: table's platform_surge ... platform_yaw are displacements of a platform from rest along its own forward axis,
#: and its platform_course/orientation clockwise from North: seacable's body poses are in the global frame, its
#: headings anticlockwise from x, so they have none).
STANDARD_NAMES: dict[str, str] = {
    "time": "time",
    # the seabed's depth below the still (mean) water level along a lay route, and at the touchdown point
    "water_depth": "sea_floor_depth_below_mean_sea_level",
    "touchdown_depth": "sea_floor_depth_below_mean_sea_level",
    # the depth of a towed line's lower end below the still water level (positive down): CF's 'depth'
    "lower_end_depth": "depth",
}


def annotate(variables) -> None:
    """Add the ``standard_name`` of :data:`STANDARD_NAMES` to the variables of a result (a Dataset's
    ``variables`` or a dict of Variables), in place; ``time`` is left to :func:`encode` (in memory its units
    are ``"s"``, which is not a CF time)."""
    for name, v in variables.items():
        standard = STANDARD_NAMES.get(name)
        if standard is not None and name != "time" and "standard_name" not in v.attrs:
            v.attrs["standard_name"] = standard
            if standard == "depth":  # a vertical coordinate's direction (CF 4.3): a depth grows downward
                v.attrs["positive"] = "down"


def time_attrs(attrs: dict) -> dict:
    """The attributes of the ``time`` coordinate as written: CF time units, calendar, standard name, axis."""
    attrs = dict(attrs)
    if attrs.get("units") == "s":
        attrs.update(units=TIME_UNITS, calendar=TIME_CALENDAR, standard_name="time", axis="T")
    return attrs


def int32_dtype(values: np.ndarray):
    """``np.int32`` for 64-bit integers that fit in 32 bits (CF-1.8 has no 64-bit integers), else None."""
    values = np.asarray(values)
    if values.dtype.kind in "iu" and values.dtype.itemsize > 4:
        info = np.iinfo(np.int32)
        if values.size == 0 or (values.min() >= info.min and values.max() <= info.max):
            return np.dtype(np.int32)
    return None


def encode(ds: xr.Dataset, encoding: dict | None = None) -> tuple[xr.Dataset, dict]:
    """A result as it is written: a shallow copy with CF attributes, and the encoding for ``to_netcdf``.

    Parameters
    ----------
    ds
        A result Dataset (unchanged).
    encoding
        Encoding already chosen (compression, chunks) by variable name; completed, not replaced.

    Returns
    -------
    The Dataset to write (its attributes CF's, its values the same objects) and the encoding.
    """
    out = ds.copy(deep=False)
    annotate(out.variables)
    encoding = {name: dict(enc) for name, enc in (encoding or {}).items()}
    if "time" in out.variables:
        out["time"].attrs = time_attrs(out["time"].attrs)
    for name, v in out.variables.items():
        enc = encoding.setdefault(name, {})
        small = int32_dtype(v.values) if v.dtype.kind in "iu" else None
        if small is not None:
            enc["dtype"] = small
        if name in out.dims and v.dtype.kind in "fc":  # a coordinate variable holds no missing values
            enc["_FillValue"] = None
    # a dimension of names (lines, bodies, degrees of freedom) has no CF coordinate variable (numeric and monotonic,
    # CF 1.2, 5): its names are a label variable NAME_label (CF 6.1), named in its variables' coordinates attribute
    labels = {name: name + LABEL for name in out.dims if name in out.variables and out[name].dtype.kind in "OUS"}
    if labels:
        out = out.rename_vars(labels)
        encoding = {labels.get(name, name): enc for name, enc in encoding.items()}
    if "history" not in out.attrs:
        out.attrs["history"] = f"written by {out.attrs.get('source', 'seacable')}"
    return out, encoding


def decode(ds: xr.Dataset) -> xr.Dataset:
    """A result file as read (``decode_times=False``) back in seacable's vocabulary: ``time`` in seconds from
    the start of the run (units ``"s"``), and each dimension's names (``line_label``) its coordinate (``line``)
    again; files written before (units ``"s"``, names as coordinates) pass unchanged. Returns the Dataset."""
    labels = {name: name[:-len(LABEL)] for name in ds.variables if name.endswith(LABEL)
              and ds[name].dims == (name[:-len(LABEL)],) and name[:-len(LABEL)] not in ds.variables}
    if labels:  # the names of a dimension back as its coordinate, with its index (ds.sel(line="line1"))
        ds = ds.rename_vars(labels)
        for name in labels.values():
            ds = ds.set_xindex(name)
    if "time" in ds.variables:
        attrs = ds["time"].attrs
        if attrs.get("units") == TIME_UNITS:
            attrs["units"] = "s"
            for key in ("calendar", "standard_name", "axis"):
                attrs.pop(key, None)
    return ds


def split_by_kind(values: np.ndarray, kinds, axis: int) -> dict[str, np.ndarray]:
    """Split an array along ``axis`` whose components are of different kinds into one array per kind, each
    NaN where a component is of another kind.

    Parameters
    ----------
    values
        The array (float).
    kinds
        The kind of each component along ``axis`` (for example ``"translation"``, ``"rotation"``).
    axis
        The axis that mixes kinds.
    """
    values = np.asarray(values, float)
    kinds = np.asarray(kinds)
    out = {}
    for kind in dict.fromkeys(kinds.tolist()):
        mask = np.expand_dims(kinds == kind, tuple(k for k in range(values.ndim) if k != axis % values.ndim))
        out[kind] = np.where(mask, values, np.nan)
    return out


def joined(parts) -> np.ndarray:
    """The array that :func:`split_by_kind` split: each entry from the one part that is not NaN there (NaN
    where every part is NaN)."""
    parts = [np.asarray(p, float) for p in parts]
    out = np.full(parts[0].shape, np.nan)
    for p in parts:
        out = np.where(np.isnan(out), p, out)
    return out


#: The rotations of a body, the labels of the ``angle`` dimension of ``body_rotation`` (about x, y, z).
ANGLES = ("roll", "pitch", "yaw")

#: The blocks of a body's 6x6 matrix by the kinds of its rows (force, moment) and columns (translation,
#: rotation): (row kind, column kind, suffix of the variable's name, UDUNITS units, what the block is).
STIFFNESS_BLOCKS = (
    ("translation", "translation", "_translation", "N m-1", "force per unit translation"),
    ("translation", "rotation", "_force_rotation", "N rad-1", "force per unit rotation"),
    ("rotation", "translation", "_moment_translation", "N m m-1", "moment per unit translation"),
    ("rotation", "rotation", "_rotation", "N m rad-1", "moment per unit rotation"),
)


def dof_kind(label: str) -> str:
    """``"rotation"`` for a degree of freedom named (or ending in) roll, pitch or yaw, else ``"translation"``."""
    return "rotation" if str(label).split()[-1] in ANGLES else "translation"


def matrix_variables(name: str, dims: tuple[str, ...], values, rows, columns, long_name: str) -> dict:
    """A matrix whose units differ by block (a body's stiffness: N/m, N/rad, N m/m, N m/rad) as one variable per
    block of :data:`STIFFNESS_BLOCKS`, each over the whole matrix's dimensions and NaN outside its block.

    Parameters
    ----------
    name
        The matrix's name (``stiffness``); the variables are ``name + suffix`` (``stiffness_translation``, ...).
    dims
        The dimensions, the last two the matrix's rows and columns.
    values
        The matrices, shape of ``dims``. [N m-1, N rad-1, N m m-1, N m rad-1 by block]
    rows, columns
        The degrees of freedom of the rows and the columns (labels, kind by :func:`dof_kind`).
    long_name
        What the matrix is.
    """
    values = np.asarray(values, float)
    r = np.array([dof_kind(x) for x in rows])[:, None]
    c = np.array([dof_kind(x) for x in columns])[None, :]
    out = {}
    for row, column, suffix, units, what in STIFFNESS_BLOCKS:
        block = np.where((r == row) & (c == column), values, np.nan)
        out[name + suffix] = xr.Variable(dims, block, attrs={"units": units, "long_name": f"{long_name}: {what} "
                                                             "(NaN outside this block)"})
    return out


def stiffness_matrix(ds, name: str = "stiffness") -> xr.DataArray:
    """A body's whole matrix from a result: the blocks of :func:`matrix_variables` joined (mixed units: N/m,
    N/rad, N m/m, N m/rad by block), or the single variable of a file written before the split."""
    if name in ds.variables:
        return ds[name]
    parts = [ds[name + suffix] for *_, suffix, _, _ in STIFFNESS_BLOCKS]
    out = parts[0].copy(data=joined([p.values for p in parts]))
    out.attrs = {"units": "N/m, N/rad, N m/m, N m/rad by block", "long_name": name}
    return out.rename(name)


def body_pose(ds, position: str = "body_position", rotation: str = "body_rotation") -> np.ndarray:
    """The bodies' six degrees of freedom (x, y, z [m], roll, pitch, yaw [rad]) along the last axis, from a result's
    ``body_position`` (time, body, axis) and ``body_rotation`` (time, body, angle); from a file written before
    the split, its ``body_position`` of six components (dimension ``dof``). Works for ``body_velocity`` and
    ``body_rotation_rate`` likewise."""
    v = ds[position]
    if "dof" in v.dims and v.sizes["dof"] == 6:  # an older file: one variable of six components
        return np.asarray(v.values, float)
    return np.concatenate([np.asarray(v.values, float), np.asarray(ds[rotation].values, float)], axis=-1)

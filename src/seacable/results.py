"""The result schema: labelled xarray Datasets with units, provenance and NetCDF I/O.

Every variable and coordinate carries ``units`` and ``long_name`` attributes.
Dataset attributes record the seacable version, the analysis, its settings, the
whole case (YAML) and the references, so that a result file says how it was made.
"""

from __future__ import annotations

import json
import tempfile
import weakref
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from . import _cf
from ._cf import body_pose, joined, stiffness_matrix
from ._model import dump_yaml
from ._version import __version__
from .errors import ConvergenceError, InputError

__all__ = ["ANALYSIS_VARIABLES", "FiniteGuard", "body_pose", "check_output_file", "check_output_folder",
           "check_result", "check_schema", "check_time", "compression", "dataset", "joined", "make_dataset",
           "open_netcdf", "read_netcdf", "result_file", "stiffness_matrix", "var", "write_error",
           "write_netcdf"]

#: analysis type -> the variables and coordinates its result must hold: those its standard figures and
#: animation draw unconditionally (optional ones, such as ``seabed_z``, are not listed). A result file
#: is checked against this before it is plotted, so that a file that lacks one gets a message naming it.
ANALYSIS_VARIABLES: dict[str, tuple[str, ...]] = {
    "static": ("s", "x", "z", "tension", "fairlead_tension", "anchor_tension"),
    "pushover": ("offset", "H_fairlead", "fairlead_tension", "stiffness_horizontal"),
    "modal": ("mode", "plane", "period", "wave_period", "s", "x", "z", "shape", "direction"),
    "towed_steady": ("s", "x", "z", "tension", "relative_speed", "top_tension"),
    "laying_theory": ("ship_speed", "angle", "angle_small", "layback"),
    "vertical_modes": ("solution", "mode", "period"),
    "mooring_static": ("x", "y", "z", "tension", "fairlead_tension", "anchor_tension"),
    "mooring_pushover": ("offset", "x", "y", "z", "tension", "fairlead_tension", "seabed_contact_length"),
    "mooring_dynamic": ("time", "x", "y", "z", "tension", "fairlead_tension", "anchor_tension",
                        "seabed_contact_length"),
    "towed_dynamic": ("time", "s", "x", "y", "z", "tension", "top_tension"),
    "laying_dynamic": ("time", "x", "z", "ship_x", "top_tension", "bottom_tension", "slack", "entry_angle",
                       "ship_speed", "payout_speed"),
    "lay_plan": ("kp", "ship_speed", "payout_speed", "touchdown_kp", "touchdown_offset", "touchdown_depth", "layback",
                 "top_tension", "bottom_tension", "entry_angle", "route_slack", "water_depth", "ship_x", "ship_y",
                 "touchdown_x", "touchdown_y", "waypoint_x", "waypoint_y"),
    "towline_dynamic": ("time", "x", "y", "z", "top_tension", "barge_tension", "tug_x", "tug_y", "barge_x",
                        "barge_y"),
    "sweep": ("status",),
    "system_static": ("condition", "line", "x", "y", "z", "body_x", "body_y", "body_z", "point_x", "point_y",
                      "point_z", "point_kind", "fairlead_tension", "anchor_tension"),
    "system_offsets": ("condition", "applied_load", "heading", "body", "body_offset_x", "body_offset_y", "offset",
                       "restoring_force", "fairlead_tension"),
    "system_dynamic": ("time", "line", "x", "y", "z", "fairlead_tension", "anchor_tension", "failure_time"),
}


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
    array = np.asarray(values)
    # numbers, booleans and strings taken as they are (xarray's conversions change only dates, object arrays and
    # pandas or masked data), and names (an object array of str) too: xarray's check of object arrays for dates
    # (a round trip through pandas, 20 times the cost of the variable) leaves them unchanged
    plain = type(array) is np.ndarray and (array.dtype.kind in "biufcSU" or (
        array.dtype.kind == "O" and array.ndim > 0 and all(type(item) is str for item in array.flat)))
    return xr.Variable(dims, array, attrs={"units": units, "long_name": long_name, **attrs}, fastpath=plain)


def _attr_value(value: Any):
    if isinstance(value, (str, int, float, np.integer, np.floating)):
        return value
    if isinstance(value, bool):
        return int(value)
    return json.dumps(value, default=str)


#: The state variables of a time-domain result: never NaN at every node of an output (padding, as nodes not yet
#: paid out or lines of fewer nodes, leaves some of them finite).
STATE_VARIABLES = ("x", "y", "z")


class FiniteGuard:
    """The check, before a time-domain result is written, that no result variable holds a non-finite number
    silently: every result passes it (:func:`make_dataset`, and each block of a streamed run,
    :mod:`seacable.sink`).

    A float variable along ``time`` is refused (:class:`~seacable.errors.ConvergenceError`, naming the variable
    and the time) when it holds an infinity; when it is NaN throughout an output after an output at which it had
    finite values (the solution diverged); or, for the state (:data:`STATE_VARIABLES`), when it is NaN throughout
    any output. NaN in part of an output is the results' own padding (nodes not yet paid out, lines of fewer
    nodes, a slack not yet measured) and passes. The time coordinate must be finite."""

    def __init__(self):
        self.seen: set[str] = set()  # variables finite somewhere in an earlier output
        self.checked: set[str] = set()  # variables of the blocks checked so far

    def check(self, data_vars: dict, coords: dict) -> None:
        """Check one block of outputs (or a whole result); raise on the first non-finite value found."""
        time = coords.get("time")
        if time is None:
            return
        self.checked.update(data_vars)
        t = np.asarray(getattr(time, "values", time), float).ravel()
        if t.size and not np.all(np.isfinite(t)):
            k = int(np.flatnonzero(~np.isfinite(t))[0])
            raise ConvergenceError(f"the result's time {k} is {t[k]}: the time loop produced a non-finite time. "
                                   "Suggested fix: check analysis.time_step and duration.")
        for name, v in data_vars.items():
            dims = tuple(getattr(v, "dims", ()))
            if "time" not in dims:
                continue
            values = np.asarray(v.values)
            if values.dtype.kind != "f":
                continue
            if values.size and t.size and np.isfinite(values).all():  # finite throughout, in any layout
                self.seen.add(name)
                continue
            a = np.moveaxis(values, dims.index("time"), 0).reshape(len(t), -1)
            if a.shape[1] == 0:
                continue
            if a.shape[0] and np.isfinite(a).all():  # finite throughout: nothing to refuse
                self.seen.add(name)
                continue
            unit = v.attrs.get("units", "")
            inf = np.isinf(a)
            if inf.any():
                k, j = (int(x) for x in np.argwhere(inf)[0])
                self._fail(name, t[k], f"is {a[k, j]} {unit} at entry {j}".rstrip())
            finite = np.isfinite(a).any(axis=1)
            lost = ~finite
            if name in STATE_VARIABLES and lost.any():
                self._fail(name, t[int(np.flatnonzero(lost)[0])], "is NaN at every node")
            before = np.cumsum(finite) > 0
            if name in self.seen:
                before[:] = True
            late = lost & np.concatenate(([name in self.seen], before[:-1]))
            if late.any():
                self._fail(name, t[int(np.flatnonzero(late)[0])], "is NaN throughout, after finite values before")
            if finite.any():
                self.seen.add(name)

    @staticmethod
    def _fail(name: str, time: float, what: str):
        raise ConvergenceError(f"the result variable '{name}' {what} at t = {time:.6g} s: the solution is not a "
                               "number there (diverged or undefined), and is not written. Suggested fix: a smaller "
                               "time step, or check the inputs for values far outside their physical range (a line's "
                               "stiffness, its segments, the waves).", time=float(time))


def make_dataset(data_vars: dict[str, xr.Variable], coords: dict[str, xr.Variable], *,
                 analysis: str, case=None, settings: dict | None = None,
                 references: Iterable[str] = (), title: str | None = None,
                 guard: FiniteGuard | None = None, owned: bool = False) -> xr.Dataset:
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
    guard
        The :class:`FiniteGuard` that already checked the variables along ``time`` block by block (a streamed
        run's sink); the variables it has not seen are checked with it. None: every variable is checked here.
    owned
        The variables were made for this result and nothing else holds them: the Dataset takes them as they are
        instead of shallow copies (:func:`dataset`).

    Raises
    ------
    ConvergenceError
        A time-domain variable holding a non-finite value that is not padding (:class:`FiniteGuard`).
    """
    if guard is None:  # no non-finite result written silently
        FiniteGuard().check(data_vars, coords)
    else:  # the blocks were checked as they came: the variables added at the end only
        guard.check({k: v for k, v in data_vars.items() if k not in guard.checked}, coords)
    ds = dataset(data_vars, coords, owned)
    _cf.annotate(ds.variables)   # CF standard names (seacable._cf)
    attrs = {
        "title": title or (case.name if case is not None else analysis),
        "analysis": analysis,
        "seacable_version": __version__,
        "Conventions": "CF-1.8",
        "history": f"created by seacable {__version__}",   # CF 2.6.2: the file's audit trail
        "source": f"seacable {__version__}",
        "settings": _attr_value(settings or {}),
        "references": "\n".join(references),
    }
    if case is not None:
        attrs["case_name"] = case.name
        attrs["case"] = case_yaml(case)
        if case.description:
            attrs["comment"] = case.description
    ds.attrs.update(attrs)
    check_schema(ds)
    return ds


#: (name, dtype, shape, values) -> the default index xarray makes of a dimension coordinate and the data of its
#: coordinate variable (:func:`dataset`)
_INDEXES: dict[tuple, tuple] = {}
_INDEXES_KEPT = 256     # indexes kept (the oldest forgotten first)
_INDEX_CACHED = 1000    # largest coordinate whose index is kept


def _default_index(name, v: xr.Variable):
    """The index ``xarray.Dataset`` makes of the dimension coordinate ``name`` (``PandasIndex.from_variables``)
    and its coordinate variable (``create_variables``), the index and the variable's data (the index wrapped)
    kept for a coordinate of text or numbers of at most :data:`_INDEX_CACHED` values: the same names (lines,
    bodies, degrees of freedom, conditions) come back run after run, and making a pandas index of them costs more
    than the Dataset around it. xarray treats both as immutable and shares them between Datasets itself (a
    shallow copy of a Dataset shares them); the variable, with its own attributes, is made each time."""
    from xarray.indexes import PandasIndex

    array = v.values
    key = None
    if array.size <= _INDEX_CACHED:
        if array.dtype.kind in "iu" or (array.dtype.kind == "f" and array.dtype.itemsize >= 4):
            key = (name, array.dtype.str, array.shape, array.tobytes())
        elif array.dtype.kind == "O" and all(type(item) is str for item in array.flat):
            key = (name, "O", array.shape, tuple(array.tolist()))
    kept = _INDEXES.get(key) if key is not None else None
    if kept is None:
        index = PandasIndex.from_variables({name: v}, options={})
        variable = index.create_variables({name: v})[name]
        if key is not None:
            if len(_INDEXES) >= _INDEXES_KEPT:
                _INDEXES.pop(next(iter(_INDEXES)))
            _INDEXES[key] = (index, variable._data)
        return index, variable
    index, data = kept
    return index, xr.IndexVariable(v.dims, data, attrs=v.attrs, encoding=v.encoding, fastpath=True)


def dataset(data_vars: dict[str, xr.Variable], coords: dict[str, xr.Variable], owned: bool = False) -> xr.Dataset:
    """``xarray.Dataset(data_vars=data_vars, coords=coords)``, the same Dataset built without xarray's merge.

    The constructor merges and aligns its arguments (it takes DataArrays, tuples, pandas objects): for a
    result of a few dozen :func:`var` variables that is most of a small run's time. Here, when every
    argument is an ``xarray.Variable`` and the names leave nothing to merge (no name both a variable and a
    coordinate, no variable named after a dimension, every coordinate named after a dimension one-dimensional
    along it, indexes of numbers or text), the Dataset is put together directly: each variable a shallow copy
    as the constructor makes, each dimension coordinate with the default index the constructor makes
    (:func:`_default_index`), in the constructor's order (the variables, then the coordinates). Anything else
    goes to the constructor. tests/unit/test_results_lean.py checks the two give identical Datasets (values,
    attributes, order, dimensions, indexes).

    ``owned``: the variables were made for this Dataset and nothing else holds them, so they are taken as they
    are rather than copied (shallow copies, as the constructor makes, cost as much as the variables).
    """
    construct = getattr(xr.Dataset, "_construct_direct", None)
    if construct is None or not _direct(data_vars, coords):
        return xr.Dataset(data_vars=data_vars, coords=coords)
    variables = dict(data_vars) if owned else {name: v.copy(deep=False) for name, v in data_vars.items()}
    indexes = {}
    for name, v in coords.items():
        if v.dims == (name,):
            indexes[name], variables[name] = _default_index(name, v)
        else:
            variables[name] = v if owned else v.copy(deep=False)
    try:
        return construct(variables, set(coords), indexes=indexes)
    except TypeError:  # xarray's private constructor changed its signature: the public one, slower
        return xr.Dataset(data_vars=data_vars, coords=coords)


def _direct(data_vars: dict, coords: dict) -> bool:
    """Whether :func:`dataset` can build the Dataset itself (see there)."""
    both = (*data_vars.values(), *coords.values())
    if any(type(v) is not xr.Variable for v in both) or not data_vars.keys().isdisjoint(coords):
        return False
    dims = {d for v in both for d in v.dims}
    if not dims.isdisjoint(data_vars):
        return False
    for name, v in coords.items():
        if name in dims and (v.dims != (name,) or v.dtype.kind not in "iufO" or v.dtype == np.float16):
            return False
    return True


#: id of a case -> its YAML text, while the case lives (:func:`case_yaml`)
_CASE_YAML: dict[int, str] = {}


def case_yaml(case) -> str:
    """The YAML text of a case (:func:`seacable._model.dump_yaml`), dumped once per case object.

    Cases are immutable (frozen models), so a case run again (a convergence study, a benchmark, the same
    case under other solver options) is stamped with the text dumped the first time; the text is
    forgotten when the case is.
    """
    key = id(case)
    text = _CASE_YAML.get(key)
    if text is None:
        text = dump_yaml(case)
        try:
            weakref.finalize(case, _CASE_YAML.pop, key, None)
        except TypeError:  # not weakly referenceable: not kept
            return text
        _CASE_YAML[key] = text
    return text


def check_schema(ds: xr.Dataset) -> None:
    """Raise if a variable or coordinate lacks ``units`` or ``long_name``.

    A guard on seacable's own results, so that every output file is labelled.
    """
    for name, item in ds.variables.items():  # the Variables themselves: no DataArray built for each
        missing = [k for k in ("units", "long_name") if k not in item.attrs]
        if missing:
            raise AssertionError(f"result variable '{name}' lacks {missing}")


def check_result(ds: xr.Dataset, source: str = "the result") -> str:
    """Check that a result holds what its analysis's figures need; return the analysis type.

    Parameters
    ----------
    ds
        A result Dataset (from :func:`seacable.run` or :func:`read_netcdf`).
    source
        Where it came from, for messages (the file name).

    Raises
    ------
    InputError
        If the ``analysis`` attribute is missing or unknown, or the result lacks variables of
        :data:`ANALYSIS_VARIABLES` (all of them named).
    """
    analysis = ds.attrs.get("analysis")
    if analysis is None:
        raise InputError(f"{source} is not a seacable result: it has no 'analysis' attribute. Suggested fix: "
                         "give a file written by 'seacable run' or 'seacable sweep'.")
    if analysis not in ANALYSIS_VARIABLES:
        raise InputError(f"{source} has analysis '{analysis}', which seacable does not know. Expected one of "
                         f"{', '.join(ANALYSIS_VARIABLES)}. Suggested fix: give a file written by 'seacable run'.")
    missing = [name for name in ANALYSIS_VARIABLES[analysis] if name not in ds.variables]
    if missing:
        raise InputError(f"{source} is a '{analysis}' result without the variable(s) {', '.join(missing)} that "
                         f"its figures need. Suggested fix: rerun the case with seacable {__version__} "
                         "('seacable run CASE.yaml'), or give the file written by that run.")
    check_time(ds, source)
    return analysis


def check_time(ds: xr.Dataset, source: str = "the result") -> None:
    """Check a result's ``time`` coordinate, if it has one: finite and increasing.

    A run writes its output times finite and increasing; a file whose times are not (edited, damaged, or
    written by something else) would give figures without axes and statistics of NaN.

    Raises
    ------
    InputError
        Naming the first time that is not finite, or the first that does not increase.
    """
    if "time" not in ds.variables:
        return
    t = np.asarray(ds["time"].values)
    if t.dtype.kind not in "fiu":
        raise InputError(f"{source}: its 'time' is not a number (dtype {t.dtype}). Suggested fix: give the file "
                         "written by 'seacable run' or 'seacable sweep', or run the case again.")
    t = t.astype(float).ravel()
    bad = np.flatnonzero(~np.isfinite(t))
    if bad.size:
        k = int(bad[0])
        raise InputError(f"{source}: time[{k}] is {t[k]} s, expected finite times ({bad.size} of {t.size} are not). "
                         "Suggested fix: give the file written by 'seacable run' or 'seacable sweep', or run the "
                         "case again.")
    back = np.flatnonzero(np.diff(t) <= 0)
    if back.size:
        k = int(back[0]) + 1
        raise InputError(f"{source}: time[{k}] = {t[k]:g} s does not come after time[{k - 1}] = {t[k - 1]:g} s, "
                         "expected increasing times. Suggested fix: give the file written by 'seacable run' or "
                         "'seacable sweep', or run the case again.")


_NETCDF_SUFFIXES = (".nc", ".nc4", ".netcdf")


def check_output_file(path: str | Path, option: str = "-o", suffixes=_NETCDF_SUFFIXES) -> Path:
    """Check, before a run starts, that a result can be written at ``path``.

    Parameters
    ----------
    path
        The file to write.
    option
        The command-line option or argument that gave it, for messages.
    suffixes
        The suffixes allowed (lower case), the first one suggested.

    Raises
    ------
    InputError
        If the suffix is wrong, ``path`` is a folder, a parent is a file, or its folder cannot
        be written to.
    """
    path = Path(path)
    if path.is_dir():
        raise InputError(f"{option} {path}: that is a folder, expected a file name. Suggested fix: "
                         f"{option} {path / ('result' + suffixes[0])}")
    if path.suffix.lower() not in suffixes:
        raise InputError(f"{option} {path}: the file must end in {' or '.join(suffixes)}, got "
                         f"'{path.suffix or 'no suffix'}'. Suggested fix: {option} {path.with_suffix(suffixes[0])}")
    check_output_folder(path.parent, option, what=f"{option} {path}")
    return path


def check_output_folder(folder: str | Path, option: str, what: str | None = None) -> Path:
    """Check, before a run starts, that files can be written in ``folder`` (created later if needed).

    Raises
    ------
    InputError
        If ``folder`` or one of its parents is a file, or the nearest existing folder cannot be
        written to (read-only, no permission, ...).
    """
    folder = Path(folder)
    what = what or f"{option} {folder}"
    probe = folder
    while not probe.exists():  # the nearest existing parent: every missing one will be created
        if probe.parent == probe:
            break
        probe = probe.parent
    if not probe.is_dir():
        raise InputError(f"{what}: '{probe}' is a file, not a folder, so nothing can be written under it. "
                         f"Suggested fix: give {option} a path in a folder.")
    try:  # a real write: access() says yes to root even on a read-only file system
        with tempfile.TemporaryFile(dir=probe, prefix=".seacable-probe-"):
            pass
    except OSError as err:
        raise InputError(f"{what}: cannot write in the folder '{probe}': {err.strerror or err}. Suggested fix: "
                         f"give {option} a folder you can write to.") from None
    return folder


def _make_folder(folder: Path, what: str) -> None:
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise InputError(f"cannot create the folder '{folder}' for {what}: {err.strerror or err}. Suggested "
                         "fix: give a folder you can write to.") from None


def write_netcdf(ds: xr.Dataset, path: str | Path) -> Path:
    """Write a result to NetCDF-4, whole, creating the folder if needed. Returns the path.

    The file follows the CF-1.8 conventions (:mod:`seacable._cf`): its ``time`` is a CF time coordinate, in
    seconds since the nominal epoch 1970-01-01 00:00:00 at the start of the run; :func:`read_netcdf` reads it back
    in seconds.

    The file is written under a temporary name in the same folder and renamed into place
    (:func:`seacable._atomic.atomic_path`), so that a failed or interrupted write leaves the file
    that was there before intact. Ctrl-C or SIGTERM during the write takes effect once the file is
    written (:func:`seacable._atomic.deferred_interrupts`).

    Raises
    ------
    InputError
        If the suffix is not ``.nc``, or the file cannot be written (a folder of that name, a
        read-only folder, a full disk).
    """
    from ._atomic import atomic_path, deferred_interrupts

    path = result_file(path)
    # CF-1.8 as the file says: CF time, 32-bit integers, no fill value on coordinates (seacable._cf)
    ds, encoding = _cf.encode(ds, {name: compression(v) for name, v in ds.data_vars.items()})
    # Ctrl-C and SIGTERM wait for the end of the write (then raise): never half a file or a held lock;
    # a failed write (full disk, no permission, the NetCDF library's HDF error) is an InputError naming the file
    with deferred_interrupts(), atomic_path(path, "the result") as tmp:
        ds.to_netcdf(tmp, engine="netcdf4", encoding=encoding)
    return path


def result_file(path: str | Path) -> Path:
    """``path`` as a result file to be written: checked (a ``.nc`` name, not a folder) and its folder made.

    Raises
    ------
    InputError
        If the suffix is not ``.nc``, ``path`` is a folder, or its folder cannot be made.
    """
    path = Path(path)
    if path.suffix.lower() not in _NETCDF_SUFFIXES:
        raise InputError(f"output file '{path}' must end in .nc. Suggested fix: -o {path.with_suffix('.nc')}")
    if path.is_dir():
        raise InputError(f"output file '{path}' is a folder. Suggested fix: -o {path / 'result.nc'}")
    _make_folder(path.parent, f"the result '{path.name}'")
    return path


def compression(v) -> dict:
    """The NetCDF encoding of a data variable: zlib level 4 for numbers with dimensions, none otherwise."""
    return {"zlib": True, "complevel": 4} if v.dtype.kind in "fiu" and v.ndim > 0 else {}


def write_error(path: Path, err: BaseException) -> InputError:
    """What to tell when the result ``path`` cannot be written: :func:`seacable._atomic.write_failure`."""
    from ._atomic import write_failure

    return write_failure(path, err, "the result")


def open_netcdf(path: str | Path) -> xr.Dataset:
    """A NetCDF result opened lazily (variables read when used; close it), its ``time`` in seconds from the start
    of the run (:func:`seacable._cf.decode`). Raises what ``xarray.open_dataset`` raises."""
    return _cf.decode(xr.open_dataset(path, engine="netcdf4", decode_times=False))


def read_netcdf(path: str | Path) -> xr.Dataset:
    """Read a seacable result file (loaded into memory, file closed), its ``time`` in seconds from the start of
    the run (:func:`seacable._cf.decode`)."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"result file '{path}' does not exist. Suggested fix: run 'seacable run CASE.yaml "
                         f"-o {path}' first.")
    if path.is_dir():
        raise InputError(f"result file '{path}' is a folder, expected a .nc file. Suggested fix: give the "
                         "path of the .nc file 'seacable run' wrote.")
    try:
        with xr.open_dataset(path, engine="netcdf4", decode_times=False) as ds:
            ds = _cf.decode(ds.load())
    except (OSError, ValueError, RuntimeError, KeyError, TypeError) as err:
        raise InputError(f"result file '{path}' is not a readable NetCDF file: {err}. Suggested fix: give a "
                         "file written by 'seacable run', or run the case again.") from None
    if "analysis" not in ds.attrs:
        raise InputError(f"result file '{path}' is not a seacable result (no 'analysis' attribute). Suggested "
                         "fix: give a file written by 'seacable run'.")
    return ds

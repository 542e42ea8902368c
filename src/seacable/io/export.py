"""A result file as files other tools read: CSV tables and MoorDyn ``.out`` files (``seacable export``).

CSV (:func:`export_csv`): headers ``name [units]``, numbers as Python writes them (the shortest text that reads
back to the same float, so a table holds the NetCDF values to the bit).

- ``<stem>.csv``: one row per state (``time``; a pushover's ``offset``; a system cable's ``condition``; a static
  result is one row) and a column per quantity and entry of its other axes (a line, a point, a body and its
  degrees of freedom): ``fairlead_tension (line 1) [N]``, ``body_position (body1, pitch) [...]``.
- ``<stem>_<line>.csv``, one per line (``<stem>_nodes.csv`` for a single-line result): the node-resolved
  quantities as a tidy table, a row per state and node (``time [s], node, s [m], x [m], ..., tension [N]``); element
  quantities (``segment_tension``) in ``<stem>_<line>_elements.csv``, a row per state and element.

Quantities that are not along the states (snap events, a result's constants) or that would spread over more than
1000 columns (spectra) are listed as not exported.

MoorDyn (:func:`export_moordyn`): the files MoorDyn v2 writes (layout taken from MoorDyn 2.7.2's own output,
``MoorDyn::WriteOutputs`` and ``Line::Output``): ``<stem>_Line<N>.out`` per line with the node positions
(``Node<i>px`` ...; MoorDyn's line output flag ``p``) and the segment tensions (``Seg<j>Te``; flag ``t``), and
``<stem>.out`` with ``FairTen<N>`` and ``AnchTen<N>`` of every line (MoorDyn's end B and end A) and the forces on the
points ``Point<N>Fx`` ... (points numbered from 1 in the deck's order). Each file has a names line and a units line,
``Time`` in a 10-character column (``%10.4f``) and the channels in 20-character columns (``%20.7e``); the units are in
parentheses in a line file and bare in the main file, as MoorDyn writes them. A static result is one row at time 0.

References
----------
.. [1] MoorDyn v2, https://github.com/FloatingArrayDesign/MoorDyn (BSD-3): ``docs/inputs.rst`` (output channels),
   ``source/MoorDyn2.cpp`` and ``source/Line.cpp`` (the ``.out`` files).
"""

from __future__ import annotations

import itertools
import math
import re
from pathlib import Path

import numpy as np
import xarray as xr

from .._atomic import atomic_write
from ..errors import InputError

__all__ = ["EXPORT_FORMATS", "export_csv", "export_moordyn", "export_result"]

#: the formats of :func:`export_result`
EXPORT_FORMATS = ("csv", "moordyn")

#: the axes a result's states run along: a time series, a pushover's offsets, a system cable's conditions
_STATE_DIMS = ("time", "offset", "condition")
_NODE_DIMS = ("node", "element")
#: the most columns one quantity may spread over in the state table (a spectrum's frequencies are not a table's)
_MAX_COLUMNS = 1000


def _state_dim(ds: xr.Dataset) -> str | None:
    return next((d for d in _STATE_DIMS if d in ds.dims), None)


def _header(name: str, v: xr.DataArray) -> str:
    return f"{name} [{v.attrs.get('units', '')}]"


def _labels(ds: xr.Dataset, dim: str) -> list[str]:
    """The labels of a dimension's entries: its coordinate (``line 1``), else ``<dim> <index>``."""
    if dim in ds.coords and ds[dim].dtype.kind in "OUS":
        return [str(v) for v in ds[dim].values]
    if dim in ds.coords:
        return [f"{dim} {v}" for v in ds[dim].values]
    return [f"{dim} {i}" for i in range(ds.sizes[dim])]


def _slug(label: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "", label.replace(" ", "")) or "line"


def _numeric(v: xr.DataArray) -> bool:
    return v.dtype.kind in "fiub"


def _write_csv(path: Path, columns: dict) -> Path:
    import pandas as pd

    table = pd.DataFrame(columns)
    return atomic_write(path, lambda tmp: table.to_csv(tmp, index=False), "the CSV table")


def _state_column(ds: xr.Dataset, state: str | None) -> dict:
    if state is None:
        return {}
    values = ds[state].values if state in ds.coords else np.arange(ds.sizes[state])
    units = ds[state].attrs.get("units", "") if state in ds.coords else ""
    return {f"{state} [{units}]": values}


def _plan(ds: xr.Dataset):
    """Sort the data variables: (state table, node tables by kind, not exported)."""
    state = _state_dim(ds)
    table, nodes, skipped = [], {"node": [], "element": []}, []
    for name, v in ds.data_vars.items():
        dims = set(v.dims)
        on_nodes = dims & set(_NODE_DIMS)
        if not _numeric(v) or (state is not None and state not in dims):
            skipped.append(name)
        elif not on_nodes and math.prod(v.sizes[d] for d in dims - {state}) <= _MAX_COLUMNS:
            table.append(name)
        elif len(on_nodes) == 1 and dims - on_nodes - {state} <= {"line"}:
            nodes[on_nodes.pop()].append(name)
        else:
            skipped.append(name)
    return state, table, nodes, skipped


def _table_columns(ds: xr.Dataset, names, state) -> dict:
    """A column per entry of each quantity's other axes: ``body_position (body1, x) [m]``."""
    columns = _state_column(ds, state)
    n_rows = ds.sizes[state] if state else 1
    for name in names:
        v = ds[name]
        extra = [d for d in v.dims if d != state]
        data = v.transpose(*([state] if state else []), *extra).values.reshape(n_rows, -1)
        units = v.attrs.get("units", "")
        if not extra:
            columns[f"{name} [{units}]"] = data[:, 0]
            continue
        for k, labels in enumerate(itertools.product(*(_labels(ds, d) for d in extra))):
            columns[f"{name} ({', '.join(labels)}) [{units}]"] = data[:, k]
    return columns


def _node_table(ds: xr.Dataset, names, state, dim, line: int | None) -> dict | None:
    """The tidy table of one line's ``dim`` (node or element) quantities: a row per state and node."""
    if not names:
        return None
    n_rows, n = (ds.sizes[state] if state else 1), ds.sizes[dim]
    data = {}
    for name in names:
        v = ds[name]
        if line is not None and "line" in v.dims:
            v = v.isel(line=line)
        order = [state, dim] if state in v.dims else [dim]
        a = v.transpose(*order).values
        data[_header(name, v)] = np.broadcast_to(a if state in v.dims else a[None], (n_rows, n)).reshape(-1)
    keep = ~np.all(np.isnan(np.column_stack([np.asarray(c, float) for c in data.values()])), axis=1)
    coords = {}
    for cname, c in ds.coords.items():  # the arc length s of each node, a coordinate of the result
        if cname != dim and dim in c.dims and set(c.dims) <= {dim, "line"} and _numeric(c):
            c = c.isel(line=line) if line is not None and "line" in c.dims else c
            coords[_header(cname, c)] = np.broadcast_to(c.values[None], (n_rows, n)).reshape(-1)
    columns = {}
    if state is not None:
        columns.update({k: np.repeat(c, n)[keep] for k, c in _state_column(ds, state).items()})
    columns[dim] = np.tile(np.arange(n), n_rows)[keep]
    columns.update({k: c[keep] for k, c in coords.items()})
    columns.update({k: c[keep] for k, c in data.items()})
    return columns


def export_csv(ds: xr.Dataset, folder, stem: str) -> tuple[list[Path], list[str]]:
    """Write a result as CSV tables (the module's layout). Returns (the files written, the variables not exported).

    Parameters
    ----------
    ds : xarray.Dataset
        A seacable result.
    folder : path-like
        Where to write (created if missing).
    stem : str
        The files' name stem (the result file's).

    Raises
    ------
    InputError
        A result with nothing a table can hold.
    """
    folder = Path(folder)
    state, table, nodes, skipped = _plan(ds)
    if not table and not any(nodes.values()):
        raise InputError(f"the result ({ds.attrs.get('analysis', 'unknown analysis')}) has no quantity along a state "
                         f"axis ({', '.join(_STATE_DIMS)}), a line, a point or the nodes to write as a CSV table. "
                         "Suggested fix: read the NetCDF file itself (xarray.open_dataset).")
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    if table:
        written.append(_write_csv(folder / f"{stem}.csv", _table_columns(ds, table, state)))
    lines = [(k, _slug(lab)) for k, lab in enumerate(_labels(ds, "line"))] if "line" in ds.dims else [(None, "nodes")]
    for k, name in lines:
        for dim, suffix in (("node", ""), ("element", "_elements")):
            cols = _node_table(ds, nodes[dim], state, dim, k)
            if cols is not None:
                written.append(_write_csv(folder / f"{stem}_{name}{suffix}.csv", cols))
    return written, skipped


# ----------------------------------------------------------------------------------------------------- MoorDyn

def _moordyn_text(names, units, time, columns, *, bare_units: bool) -> str:
    """A MoorDyn ``.out`` file's text: names, units, a row per time (MoorDyn 2.7.2's widths)."""
    unit = (lambda u: u) if bare_units else (lambda u: f"({u})")
    head = f"{'Time':>10}" + "".join(f"{n:>20}" for n in names)
    units_line = f"{'(s)':>10}" + "".join(f"{unit(u):>20}" for u in units)
    data = np.column_stack(columns) if columns else np.zeros((len(time), 0))
    rows = [f"{t:10.4f}" + "".join(f"{v:20.7e}" for v in row) for t, row in zip(time, data)]
    return "\n".join([head, units_line, *rows]) + "\n"


def _write_text(path: Path, text: str) -> Path:
    return atomic_write(path, lambda tmp: Path(tmp).write_text(text), "the MoorDyn output file")


def _line_numbers(ds: xr.Dataset) -> list[int]:
    """MoorDyn's line numbers: from the labels ``line <N>`` of a deck's result, else 1, 2, ..."""
    if "line" not in ds.dims:
        return [1]
    labels = _labels(ds, "line")
    found = [re.fullmatch(r"line\s*(\d+)", lab) for lab in labels]
    if all(found) and len({int(m.group(1)) for m in found}) == len(found):
        return [int(m.group(1)) for m in found]
    return list(range(1, len(labels) + 1))


def _end_b_is_fairlead(ds: xr.Dataset, line) -> bool:
    """Whether the result's ``fairlead_tension`` of a line is at its end B (MoorDyn's FairTen): seacable's fairlead
    is the moved end, end B unless only end A moves. Told from the first state's end force, which pulls the end
    towards the line: along the end segment from that end inwards."""
    if "fairlead_force_x" not in ds:
        return True
    sel = {} if line is None else {"line": line}
    first = {"time": 0} if "time" in ds.dims else {}
    f = np.array([float(ds[f"fairlead_force_{c}"].isel(**sel, **first)) for c in "xyz"])
    p = np.column_stack([ds[c].isel(**sel, **first).values for c in "xyz"])
    p = p[~np.isnan(p).any(axis=1)]
    if len(p) < 2:
        return True
    a, b = p[1] - p[0], p[-2] - p[-1]
    return float(f @ b) / (np.linalg.norm(b) or 1.0) >= float(f @ a) / (np.linalg.norm(a) or 1.0)


def export_moordyn(ds: xr.Dataset, folder, stem: str) -> list[Path]:
    """Write a result as MoorDyn v2's ``.out`` files (the module's layout). Returns the files written.

    Parameters
    ----------
    ds : xarray.Dataset
        A seacable result with node positions ``x``, ``y``, ``z`` [m]: a time series, or a static state
        (written as one row at time 0).
    folder : path-like
        Where to write (created if missing).
    stem : str
        The files' name stem (MoorDyn's: the input file's name without its extension).

    Raises
    ------
    InputError
        A result without node positions, or whose states are not times (a pushover's offsets).
    """
    folder = Path(folder)
    analysis = ds.attrs.get("analysis", "unknown analysis")
    state = _state_dim(ds)
    if state not in (None, "time"):
        raise InputError(f"the result ({analysis}) runs along '{state}' ({ds.sizes[state]} states), not time: "
                         "MoorDyn's .out files are time series. Suggested fix: export it with --format csv (a row "
                         f"per {state}).")
    if not all(c in ds and "node" in ds[c].dims for c in "xyz"):
        raise InputError(f"the result ({analysis}) has no node positions x, y, z [m]: MoorDyn's line files hold a "
                         "line's nodes. Suggested fix: export it with --format csv.")
    extra = {d for c in "xyz" for d in ds[c].dims} - {"time", "node", "line"}
    if extra:
        raise InputError(f"the result ({analysis}) has node positions along {', '.join(sorted(extra))} too: MoorDyn's "
                         "line files hold one line's nodes over time. Suggested fix: export it with --format csv.")
    time = ds["time"].values if state == "time" else np.zeros(1)
    nt = len(time)

    def series(v, line):
        v = ds[v] if line is None or "line" not in ds[v].dims else ds[v].isel(line=line)
        return v.transpose(*(d for d in ("time", "node", "element") if d in v.dims), ...).values.reshape(nt, -1) \
            if "time" in v.dims else np.broadcast_to(v.values.reshape(1, -1), (nt, v.values.size))

    folder.mkdir(parents=True, exist_ok=True)
    written = []
    numbers = _line_numbers(ds)
    main_names, main_units, main_cols = [], [], []
    ends = {}
    for k, number in enumerate(numbers):
        line = k if "line" in ds.dims else None
        xyz = [series(c, line) for c in "xyz"]
        valid = ~np.isnan(xyz[0]).all(axis=0)  # a shorter line of a padded network
        n_nodes = int(valid.sum())
        names, units, cols = [], [], []
        for i in range(n_nodes):
            for c, a in zip("xyz", xyz):
                names.append(f"Node{i}p{c}")
                units.append("m")
                cols.append(a[:, i])
        if "segment_tension" in ds:
            te = series("segment_tension", line)
            for j in range(n_nodes - 1):
                names.append(f"Seg{j + 1}Te")
                units.append("N")
                cols.append(te[:, j])
        written.append(_write_text(folder / f"{stem}_Line{number}.out",
                                   _moordyn_text(names, units, time, cols, bare_units=False)))
        if "fairlead_tension" in ds and "anchor_tension" in ds:
            fair, anch = series("fairlead_tension", line)[:, 0], series("anchor_tension", line)[:, 0]
            ends[number] = (fair, anch) if _end_b_is_fairlead(ds, line) else (anch, fair)
    for number, (b, _) in ends.items():
        main_names.append(f"FairTen{number}")
        main_units.append("N")
        main_cols.append(b)
    for number, (_, a) in ends.items():
        main_names.append(f"AnchTen{number}")
        main_units.append("N")
        main_cols.append(a)
    if all(f"point_force_{c}" in ds for c in "xyz") and "point" in ds.dims:
        forces = [series(f"point_force_{c}", None) for c in "xyz"]
        for p in range(ds.sizes["point"]):
            for c, f in zip("xyz", forces):
                main_names.append(f"Point{p + 1}F{c}")
                main_units.append("N")
                main_cols.append(f[:, p])
    if main_names:
        written.insert(0, _write_text(folder / f"{stem}.out",
                                      _moordyn_text(main_names, main_units, time, main_cols, bare_units=True)))
    return written


def export_result(path, fmt: str, folder=None) -> tuple[list[Path], list[str]]:
    """``seacable export``: a result file as CSV tables or MoorDyn ``.out`` files beside it (or in ``folder``).

    Returns (the files written, the variables not exported).

    Raises
    ------
    InputError
        An unknown format, a result file that cannot be read, or a result the format cannot hold.
    """
    from ..results import read_netcdf

    if fmt not in EXPORT_FORMATS:
        raise InputError(f"export format must be one of {', '.join(EXPORT_FORMATS)}, got '{fmt}'. Suggested fix: "
                         "--format csv (tables) or --format moordyn (MoorDyn .out files).")
    path = Path(path)
    ds = read_netcdf(path)
    folder = path.parent if folder is None else Path(folder)
    if folder.exists() and not folder.is_dir():
        raise InputError(f"-o '{folder}' is a file, expected a folder for the exported files. Suggested fix: give "
                         "a folder (created if missing).")
    if fmt == "csv":
        return export_csv(ds, folder, path.stem)
    return export_moordyn(ds, folder, path.stem), []

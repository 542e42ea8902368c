"""Where a time-domain run's outputs go as they are computed: into memory, or into a NetCDF file.

A long run's result can outgrow memory: a 3-hour run of three 40-element lines with an output every
0.1 s is 0.57 GB of results. The mooring time loop hands its outputs over in blocks
(:func:`seacable.mooring.solver.simulate`, ``on_outputs``); the result variables of each block go to a
sink, through :meth:`~MemorySink.append`:

- :class:`MemorySink` allocates each variable once at the run's full length and fills it block by
  block. No copy of the whole run is ever made, so the process holds the result and one block.
- :class:`NetcdfSink` writes each block into a NetCDF-4 file as it comes (``time`` an unlimited
  dimension), so that the process holds one block whatever the run's length. The file is written
  under a temporary name beside the target and renamed into place when the run is finished
  (:mod:`seacable._atomic`). An interrupted run's file holds every output computed.

:meth:`~MemorySink.finish` adds the variables without time (events found over the whole run, read back
with :meth:`~MemorySink.read`) and the attributes, and gives the result Dataset. Used as a context manager,
a sink whose run raises is dropped (:meth:`~MemorySink.abort`: a file's temporary deleted).
"""

from __future__ import annotations

import contextlib
import math
import os
from pathlib import Path

import numpy as np
import xarray as xr

from . import _cf
from ._atomic import is_write_failure
from .results import FiniteGuard, check_schema, compression, make_dataset, result_file, write_error

__all__ = ["MemorySink", "NetcdfSink", "open_sink"]

#: values of a variable's NetCDF chunk (1 MB of float64): a block of outputs is written in whole chunks
CHUNK_VALUES = 2**17


def _time_axis(v: xr.Variable) -> int | None:
    return v.dims.index("time") if "time" in v.dims else None


def _at(axis: int, start: int, stop: int) -> tuple:
    return (slice(None),) * axis + (slice(start, stop),)


class MemorySink:
    """A run's result in memory: each variable along ``time`` allocated at ``n_time`` outputs on the first
    block, then filled block by block.

    Parameters
    ----------
    n_time
        The number of outputs of the whole run (a run interrupted before its end keeps those it made).
    """

    def __init__(self, n_time: int):
        self.n_time = int(n_time)
        self.filled = 0
        self._vars: dict[str, xr.Variable] = {}
        self._coords: dict[str, xr.Variable] = {}
        self._guard = FiniteGuard()  # each block checked before it is stored or written

    def append(self, data: dict[str, xr.Variable], coords: dict[str, xr.Variable]) -> None:
        """Store one block: ``data`` and ``coords`` with their ``time`` dimension the block's outputs (the
        ``time`` coordinate among them), the others the same for every block (kept from the first)."""
        n = coords["time"].size
        if self.filled + n > self.n_time:
            raise AssertionError(f"{self.filled + n} outputs given to a sink of {self.n_time}")
        self._guard.check(data, coords)
        whole = self.filled == 0 and n == self.n_time  # the run in one block: its variables kept as they are
        for store, given in ((self._vars, data), (self._coords, coords)):
            for name, v in given.items():
                axis = _time_axis(v)
                if name not in store:
                    if axis is None or whole:
                        store[name] = v
                        continue
                    shape = v.shape[:axis] + (self.n_time,) + v.shape[axis + 1:]
                    store[name] = xr.Variable(v.dims, np.empty(shape, v.dtype), attrs=v.attrs)
                if axis is not None:
                    store[name].values[_at(axis, self.filled, self.filled + n)] = v.values
        self.filled += n

    def read(self, name: str, index: tuple = ()) -> np.ndarray:
        """The stored values of ``name`` (the outputs so far), ``index`` taken on its leading axes."""
        v = self._vars[name] if name in self._vars else self._coords[name]
        axis = _time_axis(v)
        values = v.values if axis is None else v.values[_at(axis, 0, self.filled)]
        return values[index]

    def finish(self, data: dict[str, xr.Variable], attrs: dict | None = None, **provenance) -> xr.Dataset:
        """The result: the blocks (their outputs so far), ``data`` (variables without ``time``), the
        attributes of :func:`seacable.results.make_dataset` (``provenance``: its keywords) and ``attrs``."""
        cut = {"time": slice(0, self.filled)}

        def done(v):  # an interrupted run: its outputs so far
            return v if self.filled == self.n_time else v.isel(cut, missing_dims="ignore")

        # the stored variables were made for this result, and the sink lets go of them: taken as they are (owned);
        # ``data``, the caller's, as shallow copies (what make_dataset makes of variables it does not own)
        ds = make_dataset({**{k: done(v) for k, v in self._vars.items()},
                           **{k: v.copy(deep=False) for k, v in data.items()}},
                          {k: done(v) for k, v in self._coords.items()}, guard=self._guard, owned=True, **provenance)
        self._vars, self._coords = {}, {}
        ds.attrs.update(attrs or {})
        return ds

    def abort(self) -> None:
        """Drop what was stored (a run that failed)."""
        self._vars, self._coords = {}, {}

    def __enter__(self):
        return self

    def __exit__(self, kind, error, trace) -> None:
        """A run that raised (an error, a second Ctrl-C) leaves nothing behind: :meth:`abort`."""
        if kind is not None:
            self.abort()


class NetcdfSink(MemorySink):
    """A run's result written into the NetCDF-4 file ``path`` block by block (compressed, as
    :func:`seacable.results.write_netcdf` writes it); :meth:`finish` returns the Dataset read lazily from the
    finished file (its variables are read when used).

    Raises
    ------
    InputError
        If the suffix is not ``.nc``, or the file cannot be written (a read-only folder, a full disk):
        :func:`seacable.results.result_file`, :func:`seacable.results.write_error`.
    """

    def __init__(self, n_time: int, path: str | Path):
        super().__init__(n_time)
        from ._atomic import clean_folder_once, temporary_path

        path = result_file(path)
        clean_folder_once(path.parent)   # the temporaries of runs killed outright (SIGKILL) go
        self.path, self.tmp = path, temporary_path(path)
        self._nc = None
        self._timed: dict[str, int] = {}  # name -> time axis of the variables along time

    def _failed(self, err: BaseException):
        error = write_error(self.path, err)   # before the temporary goes: a full disk is seen full
        self.abort()
        return error

    def append(self, data: dict[str, xr.Variable], coords: dict[str, xr.Variable]) -> None:
        n = coords["time"].size
        self._guard.check(data, coords)
        try:
            if self._nc is None:
                self._create(data, coords)
            else:
                for name, axis in self._timed.items():
                    v = data[name] if name in data else coords[name]
                    self._nc[name][_at(axis, self.filled, self.filled + n)] = v.values
        except Exception as err:
            if not is_write_failure(err):
                raise
            raise self._failed(err) from None
        self.filled += n

    def _create(self, data, coords) -> None:
        import netCDF4

        ds = xr.Dataset(data, coords)
        check_schema(ds)
        encoding = {}
        for name, v in ds.variables.items():
            axis = _time_axis(v)
            enc = compression(v) if name in ds.data_vars else {}
            if axis is not None:
                self._timed[name] = axis
                # a power of two of outputs, so that blocks of a power of two fill whole chunks
                other = math.prod(v.shape[:axis] + v.shape[axis + 1:])
                rows = 2 ** max(0, (CHUNK_VALUES // max(other, 1)).bit_length() - 1)
                enc["chunksizes"] = v.shape[:axis] + (rows,) + v.shape[axis + 1:]
            encoding[name] = enc
        ds, encoding = _cf.encode(ds, encoding)   # CF-1.8: CF time, 32-bit integers (seacable._cf)
        del ds.attrs["history"]   # the file's global attributes are written at the end (finish)
        ds.to_netcdf(self.tmp, engine="netcdf4", encoding=encoding, unlimited_dims=["time"])
        self._nc = netCDF4.Dataset(self.tmp, "a")
        self._nc.set_auto_mask(False)
        for name in self._timed:  # a chunk or two cached per variable, not the library's 64 MB
            out = self._nc[name]
            out.set_var_chunk_cache(size=2 * math.prod(out.chunking()) * out.dtype.itemsize, nelems=61,
                                    preemption=1.0)

    def read(self, name: str, index: tuple = ()) -> np.ndarray:
        v = self._nc[name]
        axis = self._timed.get(name)
        full = tuple(index) + (slice(None),) * (v.ndim - len(index))
        if axis is not None:
            full = full[:axis] + (slice(0, self.filled),) + full[axis + 1:]
        return np.asarray(v[full])

    def finish(self, data: dict[str, xr.Variable], attrs: dict | None = None, **provenance) -> xr.Dataset:
        from ._atomic import deferred_interrupts
        from .results import _attr_value

        header = make_dataset(data, {}, **provenance)
        try:
            with deferred_interrupts():
                nc = self._nc
                for dim, size in header.sizes.items():
                    if dim not in nc.dimensions:
                        nc.createDimension(dim, size)
                for name, v in header.data_vars.items():
                    fill = np.nan if v.dtype.kind == "f" else None
                    dtype = _cf.int32_dtype(v.values) or v.dtype   # CF-1.8 has no 64-bit integers
                    out = nc.createVariable(name, dtype, v.dims, fill_value=fill, **compression(v))
                    out.setncatts(v.attrs)
                    out[...] = v.values
                final = {**header.attrs, **(attrs or {})}
                final.setdefault("history", f"written by {final.get('source', 'seacable')}")
                nc.setncatts({k: _attr_value(val) for k, val in final.items()})
                nc.close()
                self._nc = None
                os.replace(self.tmp, self.path)
        except Exception as err:
            if not is_write_failure(err):
                raise
            raise self._failed(err) from None
        # seconds from the start, as in memory (the file's CF time: seacable._cf)
        return _cf.decode(xr.open_dataset(self.path, engine="netcdf4", decode_times=False))

    def abort(self) -> None:
        """Close and delete the temporary file (a run that failed)."""
        if self._nc is not None:
            with contextlib.suppress(Exception):
                self._nc.close()
            self._nc = None
        with contextlib.suppress(OSError):
            self.tmp.unlink()


def open_sink(n_time: int, out: str | Path | None = None) -> MemorySink:
    """A :class:`NetcdfSink` writing ``out``, or a :class:`MemorySink` without it."""
    return MemorySink(n_time) if out is None else NetcdfSink(n_time, out)

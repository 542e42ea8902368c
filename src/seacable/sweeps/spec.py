"""Sweep files: a base case and the parameters varied over it, expanded into cases.

A sweep file is YAML::

    name: lay_speeds
    base: paper001_lay_2ms_50m.yaml        # a case file (relative to this file) or the case itself
    grid:                                  # every combination of the lists
      analysis.ship.speed: [0.75, 1.0, 1.5]
      environment.current.speed: {start: 0.0, stop: 0.5, step: 0.25}

or, instead of ``grid``, ``table: cases.csv``: one case per row, one parameter path per column (or the
columns written in the file: ``table: {environment.waves.hs: [4.0, 8.0], environment.waves.tp: [9.0, 12.0]}``).
With both, each row of the table is run at every combination of the grid: sea states x headings x seeds,
for instance.
A parameter is addressed by its key path in the case file, dots between keys and ``[i]`` (or
``.i``) for list items: ``line_types.cable.diameter``, ``line.segments[1].length``. Every path is
checked against the case's schema before anything runs; an unknown one gets a did-you-mean.
"""

from __future__ import annotations

import copy
import csv
import io
import difflib
import hashlib
import itertools
import json
import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml
from pydantic import Field, field_validator, model_validator

from .._limits import check_case_count
from .._model import YAML_LOADER, Model, load_yaml
from ..case import Case
from ..errors import CaseFileError, InputError
from ..io.case_file import dump_case, load_case_data, parse_case, read_yaml, resolve_files
from ..line import LineType

__all__ = ["Range", "Sweep", "SweepCase", "SweepFile", "is_sweep_file", "load_sweep", "parse_path"]


class Range(Model):
    """Evenly spaced values from ``start`` to ``stop`` (both included): give ``step`` or ``num``."""

    start: float = Field(description="First value (SI units of the parameter).")
    stop: float = Field(description="Last value (SI units of the parameter).")
    step: float | None = Field(None, description="Spacing; the last value is 'stop' when it falls on the grid.")
    num: int | None = Field(None, ge=2, le=1_000_000, description="Number of values.")

    @model_validator(mode="after")
    def _one_of(self):
        if not (math.isfinite(self.start) and math.isfinite(self.stop)):
            raise ValueError(f"start {self.start:g} and stop {self.stop:g} must be finite numbers. Suggested fix: "
                             "e.g. {start: 0.5, stop: 5.0, step: 0.25}.")
        if (self.step is None) == (self.num is None):
            raise ValueError("needs exactly one of 'step' or 'num'. Suggested fix: e.g. "
                             "{start: 0.5, stop: 5.0, step: 0.25}.")
        if self.step is not None:
            if not math.isfinite(self.step) or self.step == 0 or (self.stop - self.start) / self.step < 0:
                raise ValueError(f"step {self.step:g} does not lead from start {self.start:g} to stop "
                                 f"{self.stop:g}. Suggested fix: give a step of the sign of stop - start.")
            if (self.stop - self.start) / self.step > 1_000_000:
                raise ValueError("gives more than 1 000 000 values. Suggested fix: a larger step.")
        return self

    def values(self) -> list[float]:
        """The values, start to stop."""
        if self.num is not None:
            return [self.start + (self.stop - self.start) * i / (self.num - 1) for i in range(self.num)]
        n = math.floor((self.stop - self.start) / self.step * (1 + 1e-12) + 1e-9)
        return [self.start + i * self.step for i in range(n + 1)]


class SweepFile(Model):
    """The keys of a sweep file."""

    name: str = Field("sweep", min_length=1, description="Name of the sweep; the cases are NAME_0000, ...")
    description: str = Field("", description="Free text, kept in the summary.")
    base: str | dict[str, Any] = Field(description="The base case: a case file (path relative to the sweep "
                                                   "file) or the case's keys.")
    grid: dict[str, Any] | None = Field(
        None, description="Parameter path -> list of values (or a range {start, stop, step or num}); the sweep is "
                          "every combination.")
    table: str | dict[str, list[Any]] | None = Field(
        None, description="Cases row by row: a CSV file (path relative to the sweep file; a header of parameter "
                          "paths, one case per row) or its columns (parameter path -> values, all of one length); "
                          "with a grid, each row at every combination of the grid.")

    @field_validator("grid", mode="after")
    @classmethod
    def _grid_values(cls, grid):
        # a list of values or a range, said in one message (a union type reported both branches' errors)
        if grid is None:
            return grid
        out = {}
        for path, values in grid.items():
            if isinstance(values, dict):
                try:
                    out[path] = Range.parse(values)
                except InputError as err:
                    raise ValueError(f"parameter '{path}', a range {values}: {err}") from None
            elif isinstance(values, list):
                out[path] = values
            else:
                raise ValueError(f"parameter '{path}' must be a list of values or a range {{start, stop, step or "
                                 f"num}}, got {values!r}. Suggested fix: e.g. '{path}: [1.0, 2.0]'.")
        return out

    @model_validator(mode="after")
    def _one_of(self):
        if self.grid is None and self.table is None:
            raise ValueError("needs 'grid' (parameter lists, every combination), 'table' (a CSV file or columns, "
                             "one case per row) or both (each row at every combination).")
        if self.grid is not None:
            if not self.grid:
                raise ValueError("grid is empty. Suggested fix: add e.g. 'analysis.ship.speed: [1.0, 2.0]'.")
            for path, values in self.grid.items():
                if isinstance(values, list) and not values:
                    raise ValueError(f"grid parameter '{path}' has no values. Suggested fix: list at least one.")
        return self


_TOKEN = re.compile(r"([^.\[\]]+)|\[(\d+)\]")


def parse_path(path: str) -> tuple[str | int, ...]:
    """Split a parameter path into keys (str) and list indices (int).

    ``"line.segments[1].length"`` and ``"line.segments.1.length"`` both give
    ``("line", "segments", 1, "length")``.
    """
    text = str(path).strip()
    parts: list[str | int] = []
    pos = 0
    for match in _TOKEN.finditer(text):
        gap = text[pos:match.start()]
        if gap not in ("", ".") or (gap == "." and not parts):
            break
        key, index = match.groups()
        parts.append(int(index) if index is not None else int(key) if key.isdigit() else key)
        pos = match.end()
    if not parts or pos != len(text) or isinstance(parts[0], int):
        raise InputError(f"parameter path '{path}' is not a key path. Expected keys separated by dots, list "
                         "items as [i], e.g. 'analysis.ship.speed' or 'line.segments[0].length'.")
    return tuple(parts)


def format_path(parts) -> str:
    """The text of a parsed path, list items as ``[i]``."""
    out = ""
    for p in parts:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else str(p))
    return out


class _PathError(Exception):
    """A path that does not fit the structure of the data (through a value, past a list's end)."""


def _get(data, parts):
    node = data
    for p in parts:
        if isinstance(p, int):
            if not isinstance(node, list) or p >= len(node):
                raise KeyError(p)
        elif not isinstance(node, dict) or p not in node:
            raise KeyError(p)
        node = node[p]
    return node


def _set(data: dict, parts, value) -> None:
    node = data
    for i, p in enumerate(parts):
        last = i == len(parts) - 1
        where = format_path(parts[:i]) or "the case"
        if isinstance(p, int):
            if not isinstance(node, list):
                raise _PathError(f"{where} is not a list, so it has no item [{p}]")
            if p >= len(node):
                raise _PathError(f"{where} has {len(node)} item(s), so no item [{p}]")
        elif not isinstance(node, dict):
            raise _PathError(f"{where} is a value ({node!r}), not a mapping of keys, so it has no key '{p}'")
        if last:
            node[p] = value
        else:
            if isinstance(node, dict) and p not in node:
                node[p] = [] if isinstance(parts[i + 1], int) else {}
            node = node[p]


def _paths(data, prefix=()) -> list[tuple]:
    """Every key path of nested mappings and lists."""
    out = []
    items = data.items() if isinstance(data, dict) else enumerate(data) if isinstance(data, list) else ()
    for k, v in items:
        out.append(prefix + (k,))
        out.extend(_paths(v, prefix + (k,)))
    return out


@dataclass(frozen=True)
class SweepCase:
    """One case of a sweep: its index, name and parameter values; the case, or why it is invalid."""

    index: int
    name: str
    values: tuple
    case: Case | None
    error: str | None
    key: str

    @property
    def stem(self) -> str:
        """File name stem of the case's result: its index, zero-padded."""
        return f"{self.index:04d}"


class Sweep:
    """A base case and the parameter values to run it at.

    Parameters
    ----------
    base
        The base case: a :class:`~seacable.case.Case`, a case file, or the case's keys (a mapping).
    grid
        Parameter path -> values; the sweep is every combination, the last parameter varying fastest.
    table
        Parameter path -> values, all the same length: one case per position (a CSV file's columns). With a
        grid too, each row of the table at every combination of the grid (the table's parameters first).
    name, description
        Name of the sweep (cases are ``NAME_0000``, ...) and free text.
    source
        Where the sweep came from, for messages.

    Raises
    ------
    InputError
        If a parameter path is not a key of the case (with a did-you-mean), or if no case is valid.
    """

    def __init__(self, base, *, grid: dict | None = None, table: dict | None = None, name: str = "sweep",
                 description: str = "", source: str = "sweep", text: str | None = None):
        if grid is None and table is None:
            raise InputError("a sweep needs 'grid', 'table' or both.")
        self.name, self.description, self.source = name, description, source
        self.base = _base_data(base)
        if grid is not None and table is not None:
            twice = sorted(set(map(str, grid)) & set(map(str, table)))
            if twice:
                raise InputError(f"{source}: {', '.join(twice)} is in both the grid and the table. Suggested fix: "
                                 "give each parameter once.")
        spec = {**(table or {}), **(grid or {})}
        n_table = len(table or {})
        self.parameters = tuple(str(p) for p in spec)
        for path, values in spec.items():
            if not isinstance(values, Range) and (isinstance(values, (str, bytes, dict))
                                                  or not hasattr(values, "__iter__")):
                raise InputError(f"{source}: parameter '{path}' needs a list of values (or a range), got "
                                 f"{values!r}. Suggested fix: write e.g. [{values!r}].")
        spec = {p: v if isinstance(v, Range) or hasattr(v, "__len__") else list(v) for p, v in spec.items()}
        sizes = [_count(v) for v in spec.values()]
        columns = [[_plain(x) for x in (v.values() if isinstance(v, Range) else v)] for v in spec.values()]
        rows = [()]
        if table is not None:
            lengths = {len(c) for c in columns[:n_table]}
            if len(lengths) != 1:
                raise InputError(f"{source}: the table's columns have different lengths {sorted(lengths)}. "
                                 "Suggested fix: give every column one value per case.")
            rows = list(zip(*columns[:n_table]))
        if grid is not None:   # counted before the grid is expanded: 5000 x 5000 is refused at once
            counts = [len(rows)] * (table is not None) + sizes[n_table:]
            check_case_count(f"{source}: the {'table x grid' if table is not None else 'grid'} "
                             f"({' x '.join(str(n) for n in counts)})", math.prod(counts),
                             "sweep fewer values, or split the sweep into several")
            self.rows = [r + g for r in rows for g in itertools.product(*columns[n_table:])]
        else:
            check_case_count(f"{source}: the table", len(rows), "split the table into several")
            self.rows = rows
        if not self.rows:
            raise InputError(f"{source}: the sweep has no cases. Suggested fix: give each parameter a value.")
        self.kind = "table x grid" if grid is not None and table is not None else ("grid" if grid is not None
                                                                                    else "table")
        parts = {"table": dict(zip(self.parameters[:n_table], columns[:n_table])) if table is not None else None,
                 "grid": dict(zip(self.parameters[n_table:], columns[n_table:])) if grid is not None else None}
        self.text = text if text is not None else yaml.safe_dump(
            {"name": name, "description": description, "base": self.base,
             **{k: {p: list(c) for p, c in v.items()} for k, v in parts.items() if v is not None}}, sort_keys=False)
        self._parts = [parse_path(p) for p in self.parameters]
        self._check_paths()
        self._cases = None

    def __len__(self) -> int:
        return len(self.rows)

    def cases(self, require_valid: bool = True) -> list[SweepCase]:
        """Every case, validated: a case that fails validation carries its message instead.

        Raises
        ------
        InputError
            If no case is valid (unless ``require_valid`` is False).
        """
        if self._cases is None:
            self._cases = [self._make(i, row) for i, row in enumerate(self.rows)]
        if require_valid and all(c.case is None for c in self._cases):
            raise InputError(f"{self.source}: no case of the sweep is valid; case 0: {self._cases[0].error}")
        return self._cases

    def _make(self, index: int, row) -> SweepCase:
        name = f"{self.name}_{index:04d}"
        data = copy.deepcopy(self.base)
        data["name"] = name
        where = f"case {index} ({', '.join(f'{p} = {v!r}' for p, v in zip(self.parameters, row))})"
        try:
            for parts, value in zip(self._parts, row):
                try:
                    _set(data, parts, value)
                except _PathError as err:   # a path through a value an earlier parameter set
                    raise InputError(f"{where}: {err}.") from None
            case = parse_case(data, source=where)
        except InputError as err:
            text = json.dumps(data, sort_keys=True, default=str)
            return SweepCase(index, name, tuple(row), None, str(err), hashlib.sha256(text.encode()).hexdigest())
        return SweepCase(index, name, tuple(row), case, None, hashlib.sha256(dump_case(case).encode()).hexdigest())

    def _check_paths(self) -> None:
        """Fail before anything runs if a path is not a key of the case."""
        candidates = None
        for path, parts, probe in zip(self.parameters, self._parts, self.rows[0]):
            try:
                _get(self.base, parts)
                continue
            except KeyError:
                pass
            data = copy.deepcopy(self.base)
            problem = None
            try:
                _set(data, parts, probe)
            except _PathError as err:
                problem = str(err)
            else:
                try:
                    Case.parse(data)
                except InputError as err:
                    for loc, tail in getattr(err, "problems", ()):
                        m = re.search(r"unknown key '([^']*)'", tail)
                        if m and m.group(1) in parts:
                            where = format_path(parts[:parts.index(m.group(1))]) or "the case"
                            problem = f"{where} has no key '{m.group(1)}'"
                            break
            if problem is not None:
                if candidates is None:
                    candidates = self._candidates()
                raise InputError(f"{self.source}: parameter '{path}' is not a key path of the case: {problem}."
                                 f"{_did_you_mean(format_path(parts), candidates)} Suggested fix: write the "
                                 "path of the key as in the case file ('seacable schema' lists the keys).")

    def _candidates(self) -> list[str]:
        """Key paths a parameter may take: the base's, and every key of a valid case with its defaults."""
        paths = {format_path(p) for p in _paths(self.base)}
        try:
            case = Case.parse({**self.base, "name": self.name})
        except InputError:
            case = None
        if case is not None:
            paths |= {format_path(p) for p in _paths(case.model_dump(mode="json"))}
        for type_name in (self.base.get("line_types") or {}):
            paths |= {f"line_types.{type_name}.{f}" for f in LineType.model_fields}
        return sorted(paths)


def _count(values) -> int:
    """Number of values of a parameter (a range's without listing them)."""
    if isinstance(values, Range):
        if values.num is not None:
            return values.num
        return math.floor((values.stop - values.start) / values.step * (1 + 1e-12) + 1e-9) + 1
    return len(values)


def _plain(value):
    """A numpy scalar as the Python number it holds (for YAML, JSON and the case's validation)."""
    return value.item() if hasattr(value, "item") and getattr(value, "ndim", None) == 0 else value


def _did_you_mean(path: str, candidates: list[str]) -> str:
    close = difflib.get_close_matches(path, candidates, n=1, cutoff=0.6)
    if close:
        return f" Did you mean '{close[0]}'?"
    last = path.rsplit(".", 1)[-1]
    same = [c for c in candidates if c.rsplit(".", 1)[-1] == last][:4]
    if same:
        return " Did you mean " + " or ".join(f"'{c}'" for c in same) + "?"
    return ""


def _base_data(base) -> dict:
    if isinstance(base, Case):
        return base.model_dump(mode="json")
    if isinstance(base, (str, Path)):
        return load_case_data(base)
    if isinstance(base, dict):
        return copy.deepcopy(base)
    raise InputError(f"a sweep's base must be a Case, a case file or a mapping of case keys, got "
                     f"{type(base).__name__}.")


def _read_table(path: Path, source: str) -> dict[str, list]:
    """Columns of a CSV table of cases, each cell read as a YAML scalar (numbers, true/false, text)."""
    from .._text import read_text_file

    try:
        text = read_text_file(path, f"{source}: table", "give a CSV file of parameter paths and values, its path "
                                                        "relative to the sweep file")
        rows = list(csv.reader(io.StringIO(text, newline="")))
    except InputError as err:
        raise CaseFileError(str(err)) from None
    except csv.Error as err:
        raise CaseFileError(f"{source}: table '{path}' cannot be read: {err}.") from None
    rows = [r for r in rows if any(cell.strip() for cell in r)]
    if len(rows) < 2:
        raise CaseFileError(f"{source}: table '{path}' needs a header of parameter paths and at least one row "
                            "of values.")
    header = [h.strip() for h in rows[0]]
    columns: dict[str, list] = {h: [] for h in header}
    if len(columns) != len(header) or "" in columns:
        raise CaseFileError(f"{source}: table '{path}' has an empty or repeated column name in its header "
                            f"{header}.")
    for line, row in enumerate(rows[1:], start=2):
        if len(row) != len(header):
            raise CaseFileError(f"{source}: table '{path}' line {line} has {len(row)} values for "
                                f"{len(header)} columns.")
        for h, cell in zip(header, row):
            if not cell.strip():
                raise CaseFileError(f"{source}: table '{path}' line {line}, column '{h}' is empty. Suggested "
                                    "fix: give every case a value.")
            try:
                columns[h].append(load_yaml(cell))
            except yaml.YAMLError:
                columns[h].append(cell.strip())
    return columns


def is_sweep_file(path: str | Path) -> bool:
    """Whether a YAML file is a sweep (top-level 'base' and 'grid' or 'table') rather than a case."""
    try:
        # the top-level keys from the parsed node tree, not the values built from it (half of the read's time)
        node = yaml.compose(Path(path).read_text(encoding="utf-8"), Loader=YAML_LOADER)
    except (OSError, UnicodeDecodeError, yaml.YAMLError):
        return False
    if not isinstance(node, yaml.MappingNode):
        return False
    keys = {key.value for key, _ in node.value if isinstance(key, yaml.ScalarNode)}
    return "base" in keys and ("grid" in keys or "table" in keys)


def load_sweep(path: str | Path) -> Sweep:
    """Read and check a sweep file (YAML).

    Raises
    ------
    CaseFileError
        If the file, its base case or its table cannot be read, or a key is unknown.
    InputError
        If a parameter path is not a key of the case (with a did-you-mean).
    """
    path = Path(path)
    source = str(path)
    data, text = read_yaml(path, "sweep file")
    if not isinstance(data, dict):
        raise CaseFileError(f"{path}: a sweep file must be a mapping with 'base' and 'grid' or 'table'.")
    if "base" not in data and ("analysis" in data or "line" in data):
        raise CaseFileError(f"{path} is a case file, not a sweep file ('base' and 'grid' or 'table'). Suggested "
                            f"fix: 'seacable run {path}', or a sweep file with 'base: {path.name}' and a 'grid'.")
    try:
        spec = SweepFile.parse(data)
    except InputError as err:
        raise CaseFileError(f"{path}: {err}") from None
    base = spec.base
    if isinstance(base, str):
        base = path.parent / base
        if base.is_file() and is_sweep_file(base):
            raise CaseFileError(f"{path}: base '{spec.base}' is a sweep file, not a case: a sweep varies one case. "
                                "Suggested fix: give the case file its sweep is based on, and merge the two grids.")
    else:
        base = copy.deepcopy(base)
        resolve_files(base, path.parent)
    try:
        table = spec.table
        if isinstance(table, str):
            table = _read_table(path.parent / table, source)
        return Sweep(base, grid=spec.grid, table=table, name=spec.name, description=spec.description,
                     source=source, text=text)
    except CaseFileError:
        raise
    except InputError as err:
        raise CaseFileError(str(err)) from None

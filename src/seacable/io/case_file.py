"""Case files: YAML to :class:`~seacable.case.Case` and back.

A case file is YAML with the keys of :class:`~seacable.case.Case`; SI units
throughout. ``seacable schema`` prints the JSON schema an editor can use to
check and complete case files.
"""

from __future__ import annotations

import json
from os import PathLike
from pathlib import Path
from typing import Any

import yaml

from .._model import YAML_LOADER, dump_yaml
from ..case import Case
from ..errors import CaseFileError, InputError
from ..system.case import SystemCase, is_system_data
from .moordyn import MoorDynCase, is_moordyn_file, load_moordyn_case

__all__ = ["case_schema", "dump_case", "load_case", "load_case_data", "parse_case", "read_yaml", "resolve_files"]


class _DuplicateKey(yaml.YAMLError):
    """A key given twice in one YAML mapping (YAML would silently keep the last)."""

    def __init__(self, key, first, second):
        super().__init__(f"duplicate key {key!r}")
        self.key, self.first, self.second = key, first, second


class _StrictLoader(YAML_LOADER):
    """``yaml.SafeLoader`` (libyaml's parser when PyYAML has it) that refuses a key given twice in the same mapping.

    YAML 1.2 requires the keys of a mapping to be unique, but PyYAML keeps the last value
    silently: two ``analysis:`` blocks would run the second and drop the first. Keys brought
    in by a merge (``<<: *anchor``) may be overridden, as YAML intends.
    """

    def construct_mapping(self, node, deep=False):
        if isinstance(node, yaml.MappingNode):
            seen = {}
            for key_node, _ in node.value:
                if key_node.tag == "tag:yaml.org,2002:merge":
                    continue
                key = self.construct_object(key_node, deep=True)
                try:
                    hash(key)
                except TypeError:
                    continue  # the base class reports an unhashable key
                line = key_node.start_mark.line + 1
                if key in seen:
                    raise _DuplicateKey(key, seen[key], line)
                seen[key] = line
        return super().construct_mapping(node, deep=deep)


def _safe_load(text: str):
    """``yaml.safe_load`` with duplicate keys refused (:class:`_DuplicateKey`)."""
    return yaml.load(text, Loader=_StrictLoader)


def parse_case(data: Any, *, source: str = "case") -> Case | SystemCase:
    """Validate plain data (a mapping, as read from YAML) into a :class:`Case` or a :class:`SystemCase`.

    A mapping with ``lines``, ``points`` or ``bodies`` at the top and no ``line`` is a mooring-system
    case (:class:`~seacable.system.case.SystemCase`); any other is a single-line case.

    Raises
    ------
    CaseFileError
        With one line per problem: the key path, the value with its unit, what
        was expected and a fix.
    """
    if not isinstance(data, dict):
        raise CaseFileError(f"{source}: a case file must be a mapping of keys to values at the top level, "
                            f"got {type(data).__name__}. Suggested fix: start from a file in examples/.")
    both = [k for k in ("lines", "points", "bodies") if k in data]
    if "line" in data and both:
        raise CaseFileError(f"{source}: has 'line' (a single-line case) and '{both[0]}' (a mooring system); a case is "
                            "one or the other. Suggested fix: keep 'line' for one line, or write the line under "
                            "'lines' with its end points for a system.")
    try:
        return SystemCase.parse(data) if is_system_data(data) else Case.parse(data)
    except InputError as err:
        raise CaseFileError(f"{source}: {err}") from None


def read_yaml(path: str | Path, what: str = "case file") -> tuple[Any, str]:
    """Read a YAML file: its data and its text.

    Raises
    ------
    CaseFileError
        If the file cannot be read or is not YAML, or if a mapping gives the same key twice
        (named with both line numbers); ``what`` names the file in the message.
    """
    from .._text import read_text_file

    path = Path(path)
    try:
        text = read_text_file(path, what, "give a YAML file; examples/ holds ready-made ones")
    except InputError as err:
        raise CaseFileError(str(err)) from None
    try:
        return _safe_load(text), text
    except _DuplicateKey as err:
        raise CaseFileError(f"{path}: key {err.key!r} is given twice in the same mapping, at line {err.first} "
                            f"and at line {err.second}; YAML would keep only the second silently. Suggested "
                            f"fix: merge the two '{err.key}' entries into one (or delete the one you do not "
                            "mean).") from None
    except yaml.YAMLError as err:
        mark = getattr(err, "problem_mark", None)
        where = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        problem = getattr(err, "problem", None) or str(err)
        raise CaseFileError(f"{path}: not valid YAML{where}: {problem}. Suggested fix: check the "
                            "indentation and the ':' after each key.") from None


def load_case_data(path: str | Path) -> dict:
    """Read a YAML case file into plain data, not yet validated.

    Relative ``file`` entries (vessel, tug, motion, route and bathymetry tables) are made relative to
    the file's folder.

    Raises
    ------
    CaseFileError
        If the file cannot be read or is not YAML.
    """
    _check_path(path)
    path = Path(path)
    data, _ = read_yaml(path)
    if not isinstance(data, dict):
        raise CaseFileError(f"{path}: a case file must be a mapping of keys to values at the top level, "
                            f"got {type(data).__name__}. Suggested fix: start from a file in examples/.")
    resolve_files(data, path.parent)
    return data


def load_case(path: str | Path) -> Case | SystemCase | MoorDynCase:
    """Read and validate a case file: YAML, or a MoorDyn input file.

    Parameters
    ----------
    path
        The case file. A MoorDyn input file (recognised by
        :func:`~seacable.io.moordyn.is_moordyn_file`) is read as a MoorDyn network case.

    Returns
    -------
    Case, SystemCase or MoorDynCase
        The validated, immutable case (a system case when the file has ``lines``, ``points`` or
        ``bodies`` and no ``line``); :func:`seacable.run` runs any of them.
    """
    _check_path(path)
    if is_moordyn_file(path):
        return load_moordyn_case(path)
    return parse_case(load_case_data(path), source=str(path))


def _check_path(path) -> None:
    """Refuse what is not a file path (a mapping of a case given where its file is expected, say)."""
    if not isinstance(path, (str, PathLike)):
        fix = ("give a mapping of a case to seacable.io.parse_case, or a case object to seacable.run"
               if isinstance(path, dict) else "give the path of a YAML case file or a MoorDyn input file")
        raise InputError(f"a case file's path must be a str or a path, got {type(path).__name__}. "
                         f"Suggested fix: {fix}.")


def resolve_files(data, folder: Path) -> None:
    """Make the relative ``file`` of a vessel, tug, motion, route, bathymetry or force table, and of a body's
    hydrodynamic database, relative to the case file's folder."""
    bodies = data.get("bodies") if isinstance(data, dict) else None
    hydro = [b.get("hydrodynamics") for b in bodies.values() if isinstance(b, dict)] if isinstance(bodies, dict) else []
    analysis = data.get("analysis") if isinstance(data, dict) else None
    if not isinstance(analysis, dict):
        _relative(hydro + [_seabed_grid(data)], folder)
        return
    tables = hydro + [_seabed_grid(data)] + [analysis.get(key) for key in ("vessel", "bathymetry", "bathymetry_grid", "route", "lay_table", "motion",
                                            "tug")]
    for key in ("body_motions", "point_motions", "external_forces"):  # system_dynamic: one table per name
        named = analysis.get(key)
        if isinstance(named, dict):
            tables += list(named.values())
    _relative(tables, folder)


def _seabed_grid(data):
    """The case's ``environment.seabed.grid`` mapping, or None."""
    bed = (data.get("environment") or {}).get("seabed") if isinstance(data.get("environment"), dict) else None
    return bed.get("grid") if isinstance(bed, dict) else None


def _relative(tables, folder: Path) -> None:
    for table in tables:
        if isinstance(table, dict) and isinstance(table.get("file"), str):
            f = Path(table["file"])
            if not f.is_absolute():
                table["file"] = str(folder / f)


def dump_case(case: Case | SystemCase) -> str:
    """The case as YAML text, every value explicit (defaults included)."""
    return dump_yaml(case)


def case_schema(system: bool = False) -> str:
    """The JSON schema of case files, as text: single-line cases, or with ``system`` mooring-system cases."""
    return json.dumps((SystemCase if system else Case).model_json_schema(), indent=2)

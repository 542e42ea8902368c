"""The cable checks of every cable in a mooring system's result (issue 40), from the result alone.

A system result holds several lines; those with bending stiffness (a power cable, an umbilical) get the single
line's checks (:func:`seacable.design.cable.cable_checks`: curvature against the MBR, tension, compression, the sag
and hog bends' clearance, the hang-off declination range, bend restrictors and moment-curvature tables) with the
limits of their own line types and the analysis's ``design`` block, and the smallest distance to the other lines
(:func:`seacable.design.clearance.line_clearance_check`):

- a ``system_static`` result: each condition on its own (``intact``, and ``damaged`` with ``damaged_lines``), on the
  line's finite-element nodes (``fe_x``, ``fe_y``, ``fe_z``, ``fe_segment_tension`` and the bending outputs): the
  line as a single line's static result (:func:`system_cable_view`), its curvature against the static MBR;
- a ``system_dynamic`` result: over the run's times, its curvature against the dynamic MBR.

The hang-off is the line's end B, as for a single line (the system takes end B as a line's fairlead unless only
end A is on a body or a coupled point; a case that asks for a hang-off declination range of a cable hung off at
end A is refused, :class:`seacable.system.case.SystemCase`). A line removed in a condition (a damaged line) has no
checks in it.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import xarray as xr

from ..errors import InputError
from . import cable as cable_
from .clearance import line_clearance_check
from .summary import case_data

__all__ = ["SYSTEM_ANALYSES", "cable_lines", "conditions", "system_cable_check_table", "system_cable_checks",
           "system_cable_states", "system_cable_view"]

#: The system analyses whose results hold the lines' shapes the checks read.
SYSTEM_ANALYSES = ("system_static", "system_dynamic")


def _is_system(ds: xr.Dataset) -> bool:
    return str(ds.attrs.get("analysis", "")) in SYSTEM_ANALYSES and "line" in ds.dims


def _case_line(data: dict, name: str) -> dict:
    """A line of the case a system result records (its ``lines.NAME``, the line's data under ``line``)."""
    entry = (data.get("lines") or {}).get(name)
    return entry if isinstance(entry, dict) else {}


def _bends_in_case(data: dict, name: str) -> bool | None:
    """Whether the case gives line ``name`` bending stiffness (a segment's EI > 0, a bend stiffener or a held end);
    None when the result records no case for it."""
    entry = _case_line(data, name)
    if not entry:
        return None
    segments = cable_._segments(data, name)
    if any(float(lt.get("bending_stiffness") or 0.0) > 0.0 for *_, lt in segments):
        return True
    line = entry.get("line") if isinstance(entry.get("line"), dict) else entry
    if any(isinstance(s, dict) and s.get("type") in ("bend_stiffener", "bend_restrictor")
           for s in (line.get("sections") or [])):
        return True
    return any((entry.get(k) or {}).get("type", "pinned") != "pinned" for k in ("end_a_condition", "end_b_condition")
               if isinstance(entry.get(k), dict))


def cable_lines(ds: xr.Dataset) -> list[str]:
    """The lines of a system result that bend: those the recorded case gives bending stiffness (a line type's
    ``bending_stiffness`` > 0, a bend stiffener or restrictor, an end held in bending), else those whose curvature is
    somewhere finite and not 0 (a line without bending stiffness has curvature 0). [] without curvature."""
    if "curvature" not in ds.variables or "line" not in ds.dims:
        return []
    data = case_data(ds) or {}
    out = []
    for name in (str(v) for v in ds["line"].values):
        told = _bends_in_case(data, name)
        if told is None:
            kappa = np.asarray(ds["curvature"].sel(line=name).values, float)
            told = bool(np.any(np.isfinite(kappa) & (kappa != 0.0)))
        if told:
            out.append(name)
    return out


def conditions(ds: xr.Dataset) -> list[str]:
    """The conditions of a ``system_static`` result (``intact``, ``damaged``); ``[""]`` for a result without them
    (a ``system_dynamic`` run: its one run)."""
    if "condition" in ds.dims:
        return [str(v) for v in ds["condition"].values]
    return [""]


def _condition_index(ds: xr.Dataset, condition) -> int:
    names = conditions(ds)
    if isinstance(condition, (int, np.integer)) and not isinstance(condition, bool):
        if 0 <= int(condition) < len(names):
            return int(condition)
    elif condition in names:
        return names.index(condition)
    raise InputError(f"condition={condition!r} is not one of the result's conditions {names}. Suggested fix: give "
                     f"one of them (or its index).")


def system_cable_view(ds: xr.Dataset, line: str | None = None, condition: str | int = 0) -> xr.Dataset:
    """A ``system_static`` result's cable in one condition as a single line's static result: its finite-element
    nodes' shape (``fe_x``, ``fe_y``, ``fe_z`` as ``x``, ``y``, ``z``), tensions and bending outputs on ``node`` and
    ``element`` with ``s``, the result's attributes (its case) and the line's name as a scalar coordinate ``line``
    (its limits: :func:`seacable.design.cable.cable_limits`).

    Parameters
    ----------
    ds
        A ``system_static`` result with bending outputs.
    line
        The line; None: the first line that bends (:func:`cable_lines`).
    condition
        The condition, by name (``"intact"``, ``"damaged"``) or index; 0, the intact one, by default.

    Raises
    ------
    InputError
        A result without a line with curvature, a ``line`` it does not hold, a condition it has not.
    """
    if "fe_s" not in ds.variables:
        raise InputError(f"the result ('{ds.attrs.get('analysis', '?')}') has no finite-element nodes (fe_s): a "
                         "system_static's cable view needs the finite-element statics' shape. Suggested fix: give the "
                         "result of a system_static case with a line with bending stiffness.")
    bends = cable_lines(ds)
    if line is None and bends:
        line = bends[0]
    if line not in bends:
        raise InputError(f"the system result has no line {line!r} with curvature (lines with bending stiffness: "
                         f"{bends or 'none'}). Suggested fix: give one of them.")
    one = ds.sel(line=line)
    k = _condition_index(ds, condition)
    if "condition" in one.dims:
        one = one.isel(condition=k)
    s = np.asarray(one["fe_s"].values, float)
    n = int(np.isfinite(s).sum())
    node = {c: ("node", np.asarray(one[f"fe_{c}"].values, float)[:n]) for c in "xyz"}
    node.update({c: ("node", np.asarray(one[c].values, float)[:n]) for c in ("curvature", "bend_moment",
                                                                            "declination")})
    element = {"segment_tension": ("element", np.asarray(one["fe_segment_tension"].values, float)[:n - 1]),
               "shear_force": ("element", np.asarray(one["shear_force"].values, float)[:n - 1])}
    view = xr.Dataset({**node, **element}, coords={"s": ("node", s[:n]), "line": line}, attrs=dict(ds.attrs))
    view["tension"] = cable_.node_tension(view["segment_tension"])
    name = conditions(ds)[k]
    if name:
        view.attrs["condition"] = name
    return view


def system_cable_states(ds: xr.Dataset, line: str) -> xr.Dataset:
    """A ``system_static`` result's cable in every condition it is in, as :func:`system_cable_view` gives each,
    stacked on the dimension ``condition`` (its names as the coordinate): what
    :func:`seacable.design.cable.range_graphs` takes for the range over the conditions."""
    keep = [k for k in range(len(conditions(ds)))
            if _present(ds.isel(condition=k) if "condition" in ds.dims else ds, line)]
    views = [system_cable_view(ds, line, k) for k in keep]
    out = xr.concat(views, dim="condition", coords="minimal", compat="override", combine_attrs="drop_conflicts")
    out = out.assign_coords(condition=("condition", [conditions(ds)[k] or "intact" for k in keep]))
    out.attrs.pop("condition", None)
    return out


def _present(ds: xr.Dataset, line: str) -> bool:
    """Whether a line is in a state of a result (a damaged condition's removed line is NaN)."""
    x = ds["fe_x"] if "fe_x" in ds.variables else ds["x"]
    return bool(np.isfinite(np.asarray(x.sel(line=line).values, float)).any())


def system_cable_checks(ds: xr.Dataset, lines=None) -> list[tuple[str, str, list[cable_.CableCheck]]]:
    """The cable checks of each cable of a system result, in each condition.

    Parameters
    ----------
    ds
        A ``system_static`` result (the finite-element statics, with bending outputs) or a ``system_dynamic`` one.
    lines
        The lines to check; None: every line that bends (:func:`cable_lines`).

    Returns
    -------
    list of (line, condition, checks)
        For each line and condition (a ``system_static``'s ``intact``, ``damaged``; ``""`` for a
        ``system_dynamic`` run) in which the line is: the single line's checks
        (:func:`seacable.design.cable.cable_checks`, the limits of the line's own line types and the analysis's
        ``design``; the static MBR in a static condition, the dynamic MBR over a dynamic run), then ``line
        clearance``, its smallest distance to the other lines in that condition
        (:func:`seacable.design.clearance.line_clearance_check`).

    Raises
    ------
    InputError
        A result that is not a system's, a line it does not hold or that does not bend.
    """
    if not _is_system(ds):
        raise InputError(f"the result has analysis '{ds.attrs.get('analysis', '?')}': the system's cable checks take "
                         "a system_static or system_dynamic result. Suggested fix: for a single line, use "
                         "seacable.design.cable.cable_checks.")
    bends = cable_lines(ds)
    lines = bends if lines is None else list(lines)
    for name in lines:
        if name not in bends:
            raise InputError(f"line {name!r} is not a line of the result with bending stiffness (those: "
                             f"{bends or 'none'}). Suggested fix: give one of them.")
    static = str(ds.attrs["analysis"]) == "system_static"
    out = []
    for k, condition in enumerate(conditions(ds)):
        state = ds.isel(condition=k) if "condition" in ds.dims else ds
        present = [str(v) for v in ds["line"].values if _present(state, str(v))]
        for name in lines:
            if name not in present:
                continue  # removed in this condition
            if static:
                view = system_cable_view(ds, name, k)
                checks = cable_.cable_checks(view, cable_.cable_limits(view))
            else:
                checks = cable_.cable_checks(ds, None, name)
            # the other lines of this condition: the positions of the profiles (a static) or the nodes (a run)
            others = [o for o in present if o != name]
            checks.append(line_clearance_check(state, name, others=others))
            out.append((name, condition, checks))
    return out


def system_cable_check_table(ds: xr.Dataset, lines=None) -> pd.DataFrame:
    """:func:`system_cable_checks` as one table: columns ``line`` and ``condition``, then the fields of
    :class:`seacable.design.cable.CableCheck` (utilisation NaN where it has none)."""
    frames = []
    for name, condition, checks in system_cable_checks(ds, lines):
        table = cable_.cable_check_table(checks)
        table.insert(0, "condition", condition)
        table.insert(0, "line", name)
        frames.append(table)
    if not frames:
        return pd.DataFrame(columns=["line", "condition", *cable_._COLUMNS])
    return pd.concat(frames, ignore_index=True)


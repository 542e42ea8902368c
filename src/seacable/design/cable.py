"""Range graphs and design checks of a dynamic power cable or umbilical (issue 40), from a result alone.

A result of ``mooring_static``, ``mooring_pushover`` or ``mooring_dynamic`` for a line with bending stiffness holds,
at its nodes, the effective ``tension``, ``curvature``, ``bend_moment`` and ``declination`` (and per element
``segment_tension`` and ``shear_force``). This module reads those (never a model's internals):

- :func:`range_graphs`: along the unstretched arc length ``s``, the minimum, maximum and mean over the run's
  states (its times, or a pushover's offsets; a static result's one state: all three its value) of the effective
  tension, curvature, bend moment, declination and seabed clearance (:func:`seabed_clearance`), as a Dataset
  with units and long names (NetCDF-writable), and :func:`plot_range_graphs` its figure, a panel a quantity.
- :func:`cable_limits` reads the limits from the case the result records: the line types' ``minimum_bend_radius``
  (static), ``minimum_bend_radius_dynamic``, ``allowable_tension`` and ``allowable_compression``, by arc length
  (a node at a joint of two segments takes the stricter), and the analysis's ``design`` block
  (:class:`seacable.case.CableDesign`): the bends' clearances and the hang-off declination range.
- :func:`cable_checks`: each check's worst value over the line and the states, against its limit, with its
  utilisation, margin, pass or fail, and where (``s``) and when (``time``, or a pushover's ``offset``) it was.

The checks (each a row; a check without its limit or its data is "not checked: <why>"):

- **curvature** (bound: max): ``kappa <= 1 / MBR``, utilisation ``kappa MBR`` (= MBR / R, R = 1 / kappa the bend
  radius), margin ``1 / MBR - kappa`` [1/m]. The static MBR is the limit of a static result (``mooring_static``,
  ``mooring_pushover``), the dynamic MBR of a dynamic run's extremes (``mooring_dynamic``, over all its times);
  neither stands in for the other.
- **tension** (max): the element's effective tension ``segment_tension`` (``tension`` at the nodes where a result
  has no element tensions) ``T <= T_allow``, utilisation ``T / T_allow``, margin ``T_allow - T`` [N].
- **compression** (min): ``T >= -C_allow`` (``C_allow`` the allowable compression, 0 N unless given), margin
  ``T + C_allow`` [N], utilisation ``max(-T, 0) / C_allow`` where ``C_allow > 0`` (none where it is 0: the margin
  says it).
- **sag bend clearance**, **hog bend clearance** (min): the bends are found on the line's mean shape (the static
  shape of a static result): the *hog bend* is the crest of its most prominent arch, an inner node that is a local
  maximum of the height above the seabed standing at least :data:`ARCH_PROMINENCE` of the line's height range above
  the lowest point on either side of it; the *sag bend* is the lowest inner node between that crest and end B (the
  hang-off). At each state the sag bend's clearance is the smallest height above the seabed of the nodes from the
  crest's node to end B: it is 0 or below when the sag bend touches down early (the wave collapsing onto the seabed);
  the hog bend's clearance is the largest height of the nodes between the lowest node from end A to the crest and the
  sag bend's node (the arch's crest, wherever it moves). Check: the smallest over the states >= the required
  clearance (``design.sag_bend_clearance``, ``hog_bend_clearance``, 0 m by default), margin ``c - c_req`` [m],
  utilisation ``c_req / c`` where both are > 0. A line without an arch (a plain catenary: its only sag bend is the
  touchdown, on the seabed by design) or without a seabed (no depth) is not checked.
- **bend restrictor**, **moment-curvature table** (:func:`section_checks`): a restrictor locked or free, with its
  utilisation ``kappa R_lock``; a hinge past the end of a user's moment-curvature table.
- **hang-off declination** (a range, two rows: its lowest against the range's lower end, its highest against the
  upper): the declination at end B (the result's ``declination`` at the last node: the direction of the end
  element, the angle the cable leaves its hang-off at, also at a clamped end, whose given direction is fixed) over
  the states within ``(lo, hi)``; margins ``theta_min - lo`` and ``hi - theta_max`` [rad], utilisations
  ``max(hi - theta_min, 0) / (hi - lo)`` and ``max(theta_max - lo, 0) / (hi - lo)`` (the position in the range
  from its far end: 1 at the limit, 0 beyond the far end).

The seabed clearance is the node's height above the seabed vertically below it, ``z - z_seabed(x)``: the seabed
a plane through ``z = -depth`` at ``x = 0`` rising at ``slope`` towards +x (``z_seabed = -depth + x tan(slope)``),
or a profile of depths along x (linear between its points, level beyond), from the case's ``environment``, else
the result's ``attrs["depth"]`` (flat). A node on the seabed shows the contact's penetration (a few mm below 0).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass, fields

import numpy as np
import pandas as pd
import xarray as xr

from ..errors import InputError
from .summary import case_data

__all__ = ["ARCH_PROMINENCE", "CableCheck", "CableLimits", "bends", "cable_check_table", "cable_checks",
           "cable_limits", "has_curvature", "plot_range_graphs", "range_graphs", "seabed_clearance",
           "seabed_elevation", "section_checks"]

#: An arch (a hog bend) stands above the lowest point on either side of it by at least this share of the line's
#: height range above the seabed, so that a ripple of the mesh or of the contact is not taken for one. [-]
ARCH_PROMINENCE = 0.02

#: The quantities of the range graphs: name -> (dimension, units, long name).
QUANTITIES = {
    "tension": ("node", "N", "effective tension"),
    "curvature": ("node", "1/m", "curvature"),
    "bend_moment": ("node", "N m", "bend moment"),
    "declination": ("node", "rad", "declination from the upward vertical (towards end B)"),
    "seabed_clearance": ("node", "m", "height above the seabed"),
    "shear_force": ("element", "N", "shear force across the line"),
}

_STATE_DIMS = ("time", "offset", "condition")  # a system_static cable's conditions, stacked
_STATS = {"min": "minimum", "max": "maximum", "mean": "mean"}


# ------------------------------------------------------------------------------------------------ reading

def has_curvature(ds: xr.Dataset) -> bool:
    """Whether a result holds a line's curvature (a mooring line with bending stiffness or a held end)."""
    return "curvature" in ds.variables


def _state_dim(ds: xr.Dataset) -> str | None:
    """The dimension of the result's states: ``time`` (dynamic), ``offset`` (pushover); None for one state."""
    for d in _STATE_DIMS:
        if d in ds["x"].dims:
            return d
    return None


def _line_view(ds: xr.Dataset, line: str | None) -> xr.Dataset:
    """The result of one line: a result with a ``line`` dimension needs ``line``; one without takes none."""
    if "line" in ds.dims:
        names = [str(v) for v in ds["line"].values]
        if line is None or line not in names:
            raise InputError(f"the result holds the lines {names}; line={line!r} does not name one. Suggested fix: "
                             f"give line= one of {names}.")
        return ds.sel(line=line)
    return ds


def _states(da: xr.DataArray, state: str | None, last: str) -> np.ndarray:
    """A variable as (states, ``last``): a single state as one row."""
    if state is not None and state in da.dims:
        return np.asarray(da.transpose(state, last).values, float)
    return np.asarray(da.transpose(last).values, float)[None, :]


def node_tension(segment_tension: xr.DataArray) -> xr.DataArray:
    """The effective tension at the nodes from the elements' (the mean of a node's two elements, an end node its one
    element's, as the mooring analyses' ``tension``), on ``node`` in place of ``element``. [N]"""
    t = np.asarray(segment_tension.values, float)
    pad = np.full(t.shape[:-1] + (1,), np.nan)
    before, after = np.concatenate([pad, t], axis=-1), np.concatenate([t, pad], axis=-1)
    with warnings.catch_warnings():  # a padded node's two NaN: NaN, as it should be
        warnings.simplefilter("ignore", RuntimeWarning)
        nodes = np.nanmean(np.stack([before, after]), axis=0)
    dims = tuple("node" if d == "element" else d for d in segment_tension.dims)
    coords = {k: c for k, c in segment_tension.coords.items() if "element" not in c.dims}
    return xr.DataArray(nodes, dims=dims, coords=coords,
                        attrs={"units": "N", "long_name": "effective tension (node average)"})


def _environment(ds: xr.Dataset) -> dict:
    return ((case_data(ds) or {}).get("environment") or {})


def seabed_elevation(ds: xr.Dataset):
    """The seabed a result tells: a function ``z_seabed(x)`` [m] -> [m] (the seabed's elevation under ``x``), and
    what it is, or ``(None, reason)`` when the result tells no seabed.

    From the case the result records: ``environment.seabed.profile`` (depths along x, linear between the points,
    level beyond them), else ``environment.depth`` and ``seabed.slope`` (a plane through ``z = -depth`` at x = 0,
    rising towards +x); else the result's ``attrs["depth"]`` (flat)."""
    env = _environment(ds)
    seabed = env.get("seabed") or {}
    profile = seabed.get("profile") if isinstance(seabed, dict) else None
    if isinstance(profile, dict) and profile.get("distance") and profile.get("depth"):
        dist = np.asarray(profile["distance"], float)
        depth = np.asarray(profile["depth"], float)
        return (lambda x: -np.interp(x, dist, depth)), "the case's seabed profile"
    depth = env.get("depth")
    slope = float((seabed or {}).get("slope") or 0.0) if isinstance(seabed, dict) else 0.0
    if depth is None and ds.attrs.get("depth") is not None:
        depth, slope = ds.attrs["depth"], 0.0
    if depth is None:
        return None, "the result tells no water depth or seabed"
    d, tan = float(depth), math.tan(slope)
    what = f"a flat seabed at {d:g} m depth" if slope == 0.0 else \
        f"a seabed plane at {d:g} m depth under x = 0 sloping at {slope:g} rad"
    return (lambda x: -d + tan * np.asarray(x, float)), what


def seabed_clearance(ds: xr.Dataset, line: str | None = None) -> xr.DataArray | None:
    """Height of each node above the seabed vertically below it, ``z - z_seabed(x)`` [m], with the result's state
    dimension (time or offset) if any; None when the result tells no seabed (:func:`seabed_elevation`)."""
    one = _line_view(ds, line)
    floor, _ = seabed_elevation(ds)
    if floor is None:
        return None
    h = one["z"] - xr.apply_ufunc(floor, one["x"])
    h.attrs = {"units": "m", "long_name": "height above the seabed"}
    return h.rename("seabed_clearance")


def _node_s(one: xr.Dataset) -> np.ndarray:
    return np.asarray(one["s"].values, float)


def _element_s(one: xr.Dataset) -> np.ndarray:
    s = _node_s(one)
    return 0.5 * (s[:-1] + s[1:])


# ------------------------------------------------------------------------------------------- range graphs

def range_graphs(ds: xr.Dataset, line: str | None = None) -> xr.Dataset:
    """The range graphs of a line's result: min, max and mean over its states at every arc length.

    Parameters
    ----------
    ds
        A ``mooring_static``, ``mooring_pushover`` or ``mooring_dynamic`` result (a Dataset, as :func:`seacable.run`
        returns or a result file holds).
    line
        The line, where the result has a ``line`` dimension.

    Returns
    -------
    xarray.Dataset
        On the dimension ``node`` (coordinate ``s``, the unstretched arc length from end A [m]) the variables
        ``QUANTITY_min``, ``QUANTITY_max`` and ``QUANTITY_mean`` of ``tension`` [N], ``curvature`` [1/m],
        ``bend_moment`` [N m], ``declination`` [rad] and ``seabed_clearance`` [m] (those the result holds: the
        bending ones with bending stiffness, the clearance with a seabed), and of ``shear_force`` [N] on
        ``element`` (coordinate ``element_s``, the element's middle); over the states of the dimension
        ``attrs["statistics_over"]`` (``time``, ``offset``, a system cable's ``condition``
        (:func:`seacable.design.system_cable.system_cable_states`), or ``none``: a single state, the three equal). Each
        variable has ``units`` and ``long_name``.

    Raises
    ------
    InputError
        A result without the positions and tension of a line.
    """
    if "tension" not in ds.variables and "segment_tension" in ds.variables:
        ds = ds.assign(tension=node_tension(ds["segment_tension"]))  # a system_dynamic result keeps the elements'
    missing = [k for k in ("x", "z", "tension", "s") if k not in ds.variables]
    if missing:
        raise InputError(f"the result ('{ds.attrs.get('analysis', '?')}') has no {', '.join(missing)}: range graphs "
                         "need a line's shape and tension along its arc length. Suggested fix: give the result of a "
                         "mooring_static, mooring_pushover or mooring_dynamic case.")
    one = _line_view(ds, line)
    state = _state_dim(one)
    source = {k: one[k] for k in QUANTITIES if k in one.variables}
    clearance = seabed_clearance(ds, line)
    if clearance is not None:
        source["seabed_clearance"] = clearance
    data = {}
    for name, da in source.items():
        dim, units, long_name = QUANTITIES[name]
        values = _states(da, state, dim)
        keep = np.isfinite(values).any(axis=0)  # a line padded to a longer one's nodes (NaN)
        values = np.where(keep, values, np.nan)
        for stat, word in _STATS.items():
            with warnings.catch_warnings():  # a padded node's all-NaN column is NaN, as it should be
                warnings.simplefilter("ignore", RuntimeWarning)
                v = getattr(np, f"nan{stat}")(values, axis=0) if keep.any() else values[0]
            data[f"{name}_{stat}"] = xr.Variable(dim, v, {"units": units, "long_name": f"{word} {long_name}"})
    coords = {"s": ("node", _node_s(one), {"units": "m", "long_name": "unstretched arc length from end A"})}
    if "shear_force" in source:
        coords["element_s"] = ("element", _element_s(one),
                               {"units": "m", "long_name": "unstretched arc length of the element's middle"})
    n_states = 1 if state is None else int(one.sizes[state])
    _, seabed = seabed_elevation(ds)
    attrs = {"analysis": str(ds.attrs.get("analysis", "")), "case_name": str(ds.attrs.get("case_name", "")),
             "statistics_over": state or "none", "states": n_states, "seabed": seabed,
             "comment": "range graphs: minimum, maximum and mean over the states at every arc length (seacable."
                        "design.cable.range_graphs)"}
    if line is not None:
        attrs["line"] = line
    return xr.Dataset(data, coords=coords, attrs=attrs)


#: The panels of the figure: quantity -> (axis label, scale of the SI value shown).
_PANELS = {"tension": ("effective tension [kN]", 1e-3), "curvature": ("curvature [1/m]", 1.0),
           "bend_moment": ("bend moment [kN m]", 1e-3), "declination": ("declination [deg]", 180.0 / math.pi),
           "seabed_clearance": ("height above seabed [m]", 1.0)}


def plot_range_graphs(rg: xr.Dataset, limits: CableLimits | None = None, *, colour: str = "#0072b2"):
    """The range graphs as a figure: a panel a quantity against the arc length ``s``, the band between the
    minimum and maximum shaded, the mean a line (a static result: its value), and where ``limits`` give them
    the curvature's ``1 / MBR``, the allowable tension and compression (dashed red).

    Parameters
    ----------
    rg
        What :func:`range_graphs` returns.
    limits
        The limits to draw (:func:`cable_limits`), or None.

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib.pyplot as plt

    names = [q for q in _PANELS if f"{q}_mean" in rg]
    fig, axes = plt.subplots(len(names), 1, figsize=(10.4, 1.9 * len(names) + 0.6), sharex=True, squeeze=False)
    s = np.asarray(rg["s"].values, float)
    single = rg.attrs.get("statistics_over", "none") == "none"
    for ax, q in zip(axes[:, 0], names, strict=True):
        label, scale = _PANELS[q]
        lo, hi, mean = (np.asarray(rg[f"{q}_{k}"].values, float) * scale for k in ("min", "max", "mean"))
        if not single:
            ax.fill_between(s, lo, hi, color=colour, alpha=0.25, lw=0, label="min to max")
            ax.plot(s, lo, color=colour, lw=0.7)
            ax.plot(s, hi, color=colour, lw=0.7)
        ax.plot(s, mean, color=colour if single else "#1d2733", lw=1.2, label="static" if single else "mean")
        if limits is not None:
            _draw_limits(ax, q, s, limits, scale, rg.attrs.get("analysis", ""))
        if q == "seabed_clearance":
            ax.axhline(0.0, color="#7f7f7f", lw=0.8)
        ax.set_ylabel(label)
        ax.yaxis.get_major_formatter().set_useOffset(False)
    shown: dict = {}
    for ax in axes[:, 0]:  # one legend for the figure: the band, the mean and each limit drawn, once
        for handle, text in zip(*ax.get_legend_handles_labels(), strict=True):
            shown.setdefault(text, handle)
    axes[0, 0].legend(shown.values(), shown.keys(), loc="lower left", bbox_to_anchor=(0.0, 1.0), fontsize=8,
                      frameon=False, ncol=len(shown))
    axes[-1, 0].set_xlabel("arc length s from end A [m]")
    axes[-1, 0].set_xlim(np.nanmin(s), np.nanmax(s))  # a line padded to a longer one's nodes: its s ends in NaN
    fig.align_ylabels(axes[:, 0])
    return fig


def _draw_limits(ax, q, s, limits: CableLimits, scale, analysis) -> None:
    dynamic = analysis in ("mooring_dynamic", "system_dynamic")
    if q == "curvature":
        mbr = limits.minimum_bend_radius_dynamic if dynamic else limits.minimum_bend_radius
        if mbr is not None and np.isfinite(mbr).any():
            ax.plot(s, scale / mbr, color="#c00000", lw=1.0, ls="-.",
                    label=f"1 / MBR ({'dynamic' if dynamic else 'static'})")
    elif q == "tension":
        if limits.allowable_tension is not None and np.isfinite(limits.allowable_tension).any():
            ax.plot(s, limits.allowable_tension * scale, color="#c00000", lw=1.0, ls="--", label="allowable tension")
        if np.any(limits.allowable_compression > 0):
            ax.plot(s, -limits.allowable_compression * scale, color="#c00000", lw=1.0, ls=":",
                    label="allowable compression")
        ax.axhline(0.0, color="#7f7f7f", lw=0.6)


# ------------------------------------------------------------------------------------------------- limits

@dataclass(frozen=True)
class CableLimits:
    """The limits of the cable checks, at the line's nodes.

    Attributes
    ----------
    minimum_bend_radius, minimum_bend_radius_dynamic
        Static and dynamic MBR at each node, NaN where not given; None: nowhere. [m]
    allowable_tension
        Allowable effective tension at each node, NaN where not given; None: nowhere. [N]
    allowable_compression
        Allowable compression at each node, >= 0 (0: none). [N]
    sag_bend_clearance, hog_bend_clearance
        Required heights of the sag bend and the hog bend's crest above the seabed. [m]
    hang_off_declination
        ``(lowest, highest)`` declination at end B, or None. [rad]
    element_allowable_tension, element_allowable_compression
        The allowables at the elements (each its segment's); None: from the nodes' (:func:`_element_value`). [N]
    """

    minimum_bend_radius: np.ndarray | None
    minimum_bend_radius_dynamic: np.ndarray | None
    allowable_tension: np.ndarray | None
    allowable_compression: np.ndarray
    sag_bend_clearance: float = 0.0
    hog_bend_clearance: float = 0.0
    hang_off_declination: tuple[float, float] | None = None
    element_allowable_tension: np.ndarray | None = None
    element_allowable_compression: np.ndarray | None = None

    @classmethod
    def uniform(cls, n_nodes: int, *, minimum_bend_radius=None, minimum_bend_radius_dynamic=None,
                allowable_tension=None, allowable_compression=0.0, sag_bend_clearance=0.0, hog_bend_clearance=0.0,
                hang_off_declination=None) -> CableLimits:
        """The same limits along the whole line of ``n_nodes`` nodes, checked as a case file's are: an MBR or
        allowable tension not > 0, a negative allowable compression or clearance, a declination range outside
        [0, pi] or not increasing is refused (:class:`~seacable.errors.InputError`)."""
        from ..case import CableDesign
        from ..line import LineType

        given = {k: v for k, v in (("minimum_bend_radius", minimum_bend_radius),
                                   ("minimum_bend_radius_dynamic", minimum_bend_radius_dynamic),
                                   ("allowable_tension", allowable_tension),
                                   ("allowable_compression", allowable_compression)) if v is not None}
        LineType.parse({"diameter": 1.0, "mass_per_length": 1.0, **given}, root="limits")
        design = CableDesign.parse({"sag_bend_clearance": sag_bend_clearance, "hog_bend_clearance": hog_bend_clearance,
                                    "hang_off_declination": hang_off_declination}, root="limits")

        def full(v):
            return None if v is None else np.full(n_nodes, float(v))

        return cls(full(minimum_bend_radius), full(minimum_bend_radius_dynamic), full(allowable_tension),
                   np.full(n_nodes, float(allowable_compression or 0.0)), design.sag_bend_clearance,
                   design.hog_bend_clearance, design.hang_off_declination)


def _segments(data: dict, name: str | None = None) -> list[tuple[float, float, dict]]:
    """``(s_start, s_end, line type)`` of the case's line segments, from end A: a single-line case's ``line``, or a
    system case's line ``name`` (its ``segments``, or its one ``line_type`` and ``length``, in the file's form or
    under ``line`` as a result stores it). [m]"""
    line = data.get("line") or {}
    lines = data.get("lines")
    if name is not None and isinstance(lines, dict) and isinstance(lines.get(name), dict):
        line = lines[name]
        if isinstance(line.get("line"), dict):  # the case as a result stores it: the line under its own key
            line = line["line"]
        if not line.get("segments") and line.get("line_type") is not None:
            line = {"segments": [{"line_type": line["line_type"], "length": line.get("length")}]}
    types = data.get("line_types") or {}
    out, s0 = [], 0.0
    for seg in line.get("segments") or []:
        if not isinstance(seg, dict):
            continue
        lt = seg.get("line_type")
        lt = types.get(lt) if isinstance(lt, str) else lt
        length = float(seg.get("length") or 0.0)
        out.append((s0, s0 + length, lt if isinstance(lt, dict) else {}))
        s0 += length
    return out


def _by_arc_length(segments, s: np.ndarray, key: str, stricter) -> np.ndarray | None:
    """A line-type value at each arc length ``s`` (NaN where its segment has none; at a joint of two segments the
    ``stricter`` of the two); None when no segment gives it."""
    if not any(lt.get(key) is not None for *_, lt in segments):
        return None
    out = np.full(s.shape, np.nan)
    tol = 1e-9 * max(1.0, segments[-1][1])
    for a, b, lt in segments:
        v = lt.get(key)
        if v is None:
            continue
        on = (s >= a - tol) & (s <= b + tol)
        out[on] = np.where(np.isnan(out[on]), float(v), stricter(out[on], float(v)))
    return out


def cable_limits(ds: xr.Dataset) -> CableLimits:
    """The cable checks' limits from the case a result records (its ``case`` attribute; a system result's line
    selected, ``ds.sel(line=NAME)``): the line types' ``minimum_bend_radius``, ``minimum_bend_radius_dynamic``, ``allowable_tension`` and
    ``allowable_compression`` at each node by its arc length (at a joint, the stricter: the larger MBR, the
    smaller allowable), and the analysis's ``design`` block (:class:`seacable.case.CableDesign`); the defaults
    (no MBR or allowable tension, no compression, clearances 0 m, no declination range) where it has none."""
    data = case_data(ds) or {}
    # a system result's line, selected (ds.sel(line=NAME)): its own segments in the system case
    segments = _segments(data, _line_name(ds))
    s = np.asarray(ds["s"].values, float)
    if "line" in ds["s"].dims:
        s = s[0]
    mbr = _by_arc_length(segments, s, "minimum_bend_radius", np.maximum)
    mbr_d = _by_arc_length(segments, s, "minimum_bend_radius_dynamic", np.maximum)
    allow = _by_arc_length(segments, s, "allowable_tension", np.minimum)
    comp = _by_arc_length(segments, s, "allowable_compression", np.minimum)
    comp = np.zeros(s.shape) if comp is None else np.nan_to_num(comp, nan=0.0)
    middle = 0.5 * (s[:-1] + s[1:])
    allow_e = _by_arc_length(segments, middle, "allowable_tension", np.minimum)
    comp_e = _by_arc_length(segments, middle, "allowable_compression", np.minimum)
    comp_e = np.zeros(middle.shape) if comp_e is None else np.nan_to_num(comp_e, nan=0.0)
    design = (data.get("analysis") or {}).get("design") or {}
    r = design.get("hang_off_declination")
    return CableLimits(mbr, mbr_d, allow, comp, float(design.get("sag_bend_clearance") or 0.0),
                       float(design.get("hog_bend_clearance") or 0.0), None if r is None else (float(r[0]), float(r[1])),
                       allow_e, comp_e)


# ------------------------------------------------------------------------------------------------- checks

@dataclass(frozen=True)
class CableCheck:
    """One cable check: the worst value of a quantity over the line and the states against its limit.

    Attributes
    ----------
    check
        ``"curvature (dynamic MBR)"``, ``"curvature (static MBR)"``, ``"tension"``, ``"compression"``, ``"sag bend
        clearance"``, ``"hog bend clearance"``, ``"hang-off declination (lowest)"``, ``"hang-off declination
        (highest)"``, ``"bend restrictor at end A"`` (or B), ``"moment-curvature table (<whose>)"``.
    quantity
        The result's variable checked (``curvature``, ``segment_tension``, ``seabed_clearance``, ``declination``).
    unit
        Unit of value, limit and margin: ``1/m``, ``N``, ``m`` or ``rad``.
    bound
        ``"max"``: the value must not exceed the limit; ``"min"``: must not fall below it.
    value
        The worst value over the line and the states (NaN: not checked). [unit]
    limit
        The limit at the worst point (NaN: not checked). [unit]
    utilisation
        As the module says for each check; None where there is no ratio (a zero capacity). [-]
    margin
        What is left before the limit, negative when the check fails. [unit]
    passed
        ``margin >= 0``; None: not checked.
    status
        ``"pass"``, ``"FAIL"`` or ``"not checked: <why>"``; a bend restrictor's ``"free"`` or ``"LOCKED"``.
    s
        Where: the arc length of the worst node or element's middle. [m]
    time
        When: the time of the worst state (NaN: a static result or a pushover). [s]
    offset
        A pushover's offset of the worst state (NaN otherwise). [m]
    formula
        The check's formula and its numbers, one line.
    """

    check: str
    quantity: str
    unit: str
    bound: str
    value: float
    limit: float
    utilisation: float | None
    margin: float
    passed: bool | None
    status: str
    s: float
    time: float
    offset: float
    formula: str


def _skip(check, quantity, unit, bound, why) -> CableCheck:
    nan = math.nan
    return CableCheck(check, quantity, unit, bound, nan, nan, None, nan, None, f"not checked: {why}", nan, nan, nan,
                      "")


def _row(check, quantity, unit, bound, value, limit, utilisation, where, formula) -> CableCheck:
    """A checked row: margin ``limit - value`` (max) or ``value - limit`` (min), pass at margin >= 0."""
    value, limit = float(value), float(limit)
    margin = limit - value if bound == "max" else value - limit
    passed = bool(margin >= 0.0)
    u = None if utilisation is None or not math.isfinite(utilisation) else float(utilisation)
    s, time, offset = where
    return CableCheck(check, quantity, unit, bound, value, limit, u, margin, passed, "pass" if passed else "FAIL",
                      float(s), float(time), float(offset), formula)


def _where(state_dim, state_values, k_state, s) -> tuple[float, float, float]:
    t = float(state_values[k_state]) if state_dim == "time" else math.nan
    off = float(state_values[k_state]) if state_dim == "offset" else math.nan
    return s, t, off


def bends(height: np.ndarray) -> tuple[int, int, int] | None:
    """The bends of a shape from its nodes' heights above the seabed (from end A to end B): ``(low_a, crest,
    sag)``, the node indices of the lowest point from end A to the hog bend's crest, the crest (the inner local
    maximum of the largest prominence, at least :data:`ARCH_PROMINENCE` of the height range), and the sag bend
    (the lowest inner node between the crest and end B); None without an arch or without a sag bend."""
    h = np.asarray(height, float)
    n = h.size
    if n < 4 or not np.all(np.isfinite(h)):
        return None
    span = float(np.max(h) - np.min(h))
    best, crest = 0.0, None
    for i in range(1, n - 2):
        if not (h[i] >= h[i - 1] and h[i] > h[i + 1]):
            continue
        prominence = h[i] - max(np.min(h[:i]), np.min(h[i + 1:]))
        if prominence > best:
            best, crest = prominence, i
    if crest is None or best < ARCH_PROMINENCE * span:
        return None
    sag = crest + 1 + int(np.argmin(h[crest + 1:n - 1]))
    if sag >= n - 1 or not h[sag] < h[crest]:
        return None
    low_a = int(np.argmin(h[:crest]))
    return low_a, crest, sag


def cable_checks(ds: xr.Dataset, limits: CableLimits | None = None, line: str | None = None) -> list[CableCheck]:
    """The cable checks of a result (the module's list): curvature against the MBR (the static one for a static
    result or a pushover, the dynamic one for a dynamic run), tension against the allowable, compression, the sag
    and hog bends' seabed clearance, the hang-off declination range.

    Parameters
    ----------
    ds
        A ``mooring_static``, ``mooring_pushover`` or ``mooring_dynamic`` result of a line.
    limits
        The limits (:class:`CableLimits`); None: those of the case the result records (:func:`cable_limits`).
    line
        The line, where the result has a ``line`` dimension.

    Returns
    -------
    list of CableCheck
        In the order curvature, tension, compression, sag bend, hog bend, hang-off declination (lowest, highest),
        then a row a bend restrictor and a row a moment-curvature table (:func:`section_checks`).
    """
    one = _line_view(ds, line)
    if limits is None:
        limits = cable_limits(one)
    state = _state_dim(one)
    states = np.asarray(one[state].values, float) if state else np.zeros(1)
    s_node = _node_s(one)
    dynamic = str(ds.attrs.get("analysis", "")) == "mooring_dynamic" or state == "time"
    out = [_curvature(one, limits, state, states, s_node, dynamic)]
    out += _tension_checks(one, limits, state, states, s_node)
    out += _clearance_checks(ds, one, limits, state, states, s_node, line)
    out += _declination_checks(one, limits, state, states, s_node)
    out += section_checks(one, state, states, s_node)
    return out


def _line_name(one: xr.Dataset) -> str | None:
    """The line of a system result's selected line (``ds.sel(line=NAME)``: its scalar ``line``), else None."""
    return str(one["line"].values) if "line" in one.coords and one["line"].ndim == 0 else None


def _spans(data: dict, name: str | None = None) -> list[tuple[str, float, float, dict]]:
    """``(kind, s_from, s_to, data)`` of the case's bend restrictors and moment-curvature tables (a line type's over
    its segments, a stiffener's over its length), by arc length from end A: a single-line case's line, or a system
    case's line ``name``. [m]"""
    segments = _segments(data, name)
    total = segments[-1][1] if segments else 0.0
    line = data.get("line") or {}
    entry = (data.get("lines") or {}).get(name) if name is not None and isinstance(data.get("lines"), dict) else None
    if isinstance(entry, dict):  # a system's line: its sections beside its segments (under 'line' as stored)
        line = entry["line"] if isinstance(entry.get("line"), dict) else entry
    out = []
    for i, (a, b, lt) in enumerate(segments):
        if lt.get("moment_curvature"):
            out.append((f"line type {lt['name']}" if lt.get("name") else f"line.segments[{i}]", a, b, lt))
    for sec in (line.get("sections") or []):
        if not isinstance(sec, dict) or sec.get("type") not in ("bend_restrictor", "bend_stiffener"):
            continue
        length = float(sec.get("length") or 0.0)
        a, b = (0.0, length) if sec.get("end", "B") == "A" else (total - length, total)
        if sec["type"] == "bend_restrictor":
            out.append(("restrictor", a, b, sec))
        elif sec.get("moment_curvature"):
            out.append((f"bend stiffener at end {sec.get('end', 'B')}", a, b, sec))
    return out


def section_checks(one: xr.Dataset, state, states, s_node) -> list[CableCheck]:
    """The rows of a line's bend restrictors and moment-curvature tables, from the case the result records.

    - **bend restrictor at end A/B** (bound: max): the largest curvature over its length against its locking
      curvature ``1 / R_lock``, utilisation ``kappa R_lock``, margin ``1 / R_lock - kappa`` [1/m]; status ``free``
      or ``LOCKED`` (locked: the vertebrae carry the moment beyond the lock, the curvature held near ``1 / R_lock``).
    - **moment-curvature table (<whose>)** (max): the largest curvature where a user's table applies (a line type's
      segments, a stiffener's length) against the table's last curvature: beyond it the law is extrapolated along
      its last slope, utilisation ``kappa / kappa_last``.

    None of either: no rows. A result without curvature: no rows either (the curvature row says why).
    """
    data = case_data(one) or {}
    spans = _spans(data, _line_name(one))
    if not spans or "curvature" not in one.variables:
        return []
    kappa = _states(one["curvature"], state, "node")
    tol = 1e-9 * max(1.0, float(np.max(np.abs(s_node))))
    out = []
    for kind, a, b, sec in spans:
        on = np.flatnonzero((s_node >= a - tol) & (s_node <= b + tol))
        if kind == "restrictor":
            check = f"bend restrictor at end {sec.get('end', 'B')}"
            limit = 1.0 / float(sec["locking_radius"])
            formula = f"kappa <= 1 / R_lock = 1 / {float(sec['locking_radius']):.6g} m (free below, locked above)"
        else:
            table = sec["moment_curvature"]
            check = f"moment-curvature table ({kind})"
            limit = max(abs(float(k)) for k, _ in table)
            formula = f"kappa <= {limit:.6g} 1/m, the table's last curvature (extrapolated beyond)"
        if on.size == 0:
            out.append(_skip(check, "curvature", "1/m", "max", "no node of the result lies on it"))
            continue
        sub = kappa[:, on]
        k_state, k_node = np.unravel_index(int(np.nanargmax(sub)), sub.shape)
        value = float(sub[k_state, k_node])
        row = _row(check, "curvature", "1/m", "max", value, limit, value / limit,
                   _where(state, states, k_state, s_node[on[k_node]]), formula)
        if kind == "restrictor":
            row = dataclasses.replace(row, status="free" if row.passed else "LOCKED")
        out.append(row)
    return out


def _curvature(one, limits, state, states, s_node, dynamic) -> CableCheck:
    kind = "dynamic" if dynamic else "static"
    check = f"curvature ({kind} MBR)"
    mbr = limits.minimum_bend_radius_dynamic if dynamic else limits.minimum_bend_radius
    key = "minimum_bend_radius_dynamic" if dynamic else "minimum_bend_radius"
    if "curvature" not in one.variables:
        return _skip(check, "curvature", "1/m", "max", "no curvature in the result (a line without bending "
                                                        "stiffness)")
    if mbr is None or not np.isfinite(mbr).any():
        other = ("the static MBR does not apply to a dynamic run's extremes" if dynamic else
                 "the dynamic MBR does not apply to a static result")
        return _skip(check, "curvature", "1/m", "max", f"no line type gives {key} ({other})")
    kappa = _states(one["curvature"], state, "node")
    u = np.where(np.isfinite(mbr)[None, :], kappa * mbr[None, :], np.nan)
    if not np.isfinite(u).any():
        return _skip(check, "curvature", "1/m", "max", "no finite curvature where an MBR is given")
    k_state, k_node = np.unravel_index(int(np.nanargmax(u)), u.shape)
    value, r = float(kappa[k_state, k_node]), float(mbr[k_node])
    radius = 1.0 / value if value > 0 else math.inf
    return _row(check, "curvature", "1/m", "max", value, 1.0 / r, value * r,
                _where(state, states, k_state, s_node[k_node]),
                f"kappa <= 1 / MBR = 1 / {r:.6g} m (bend radius 1 / kappa = {radius:.6g} m)")


def _tension_checks(one, limits, state, states, s_node) -> list[CableCheck]:
    if "segment_tension" in one.variables:
        T, where_s, name = _states(one["segment_tension"], state, "element"), 0.5 * (s_node[:-1] + s_node[1:]), \
            "segment_tension"
        allow, comp = limits.element_allowable_tension, limits.element_allowable_compression
        if limits.allowable_tension is not None and allow is None:
            allow = _element_value(limits.allowable_tension)
        if comp is None:
            comp = _element_value(limits.allowable_compression)
    else:
        T, where_s, name = _states(one["tension"], state, "node"), s_node, "tension"
        allow, comp = limits.allowable_tension, limits.allowable_compression
    out = []
    if allow is None or not np.isfinite(allow).any():
        out.append(_skip("tension", name, "N", "max", "no line type gives allowable_tension"))
    else:
        u = np.where(np.isfinite(allow)[None, :], T / allow[None, :], np.nan)
        k_state, k = np.unravel_index(int(np.nanargmax(u)), u.shape)
        out.append(_row("tension", name, "N", "max", T[k_state, k], allow[k], T[k_state, k] / allow[k],
                        _where(state, states, k_state, where_s[k]), f"T <= T_allow = {allow[k]:.6g} N"))
    margin = T + comp[None, :]
    k_state, k = np.unravel_index(int(np.nanargmin(margin)), margin.shape)
    c, t = float(comp[k]), float(T[k_state, k])
    out.append(_row("compression", name, "N", "min", t, -c if c > 0 else 0.0, max(-t, 0.0) / c if c > 0 else None,
                    _where(state, states, k_state, where_s[k]),
                    f"T >= -C_allow = {(-c if c > 0 else 0.0):.6g} N" + (" (no compression allowed)" if c == 0 else "")))
    return out


def _element_value(node_values: np.ndarray) -> np.ndarray:
    """A uniform node limit at the elements (:meth:`CableLimits.uniform`; a case's limits are given at the
    elements by their segments): the larger of the element's two nodes' values."""
    v = np.asarray(node_values, float)
    return np.fmax(v[:-1], v[1:])


def _clearance_checks(ds, one, limits, state, states, s_node, line) -> list[CableCheck]:
    names = ("sag bend clearance", "hog bend clearance")
    h_da = seabed_clearance(ds, line)
    if h_da is None:
        return [_skip(n, "seabed_clearance", "m", "min", "the result tells no seabed (no depth)") for n in names]
    h = _states(h_da, state, "node")
    keep = np.isfinite(h).all(axis=0)  # a line padded to a longer one's nodes (NaN) is its own nodes
    h, s_node = h[:, keep], s_node[keep]
    found = bends(np.mean(h, axis=0))
    if found is None:
        why = ("the line's mean shape has no arch (a hog bend): its only sag bend is the touchdown, on the seabed "
               "by design")
        return [_skip(n, "seabed_clearance", "m", "min", why) for n in names]
    low_a, crest, sag = found
    sag_h = h[:, crest:]                          # the crest to end B: its lowest is the sag bend
    k_state, k = np.unravel_index(int(np.argmin(sag_h)), sag_h.shape)
    c, req = float(sag_h[k_state, k]), limits.sag_bend_clearance
    out = [_row("sag bend clearance", "seabed_clearance", "m", "min", c, req,
                req / c if (req > 0 and c > 0) else None, _where(state, states, k_state, s_node[crest + k]),
                f"min over the sag bend (s = {s_node[crest]:.6g} m to end B) of z - z_seabed >= {req:.6g} m")]
    arch = h[:, low_a:sag + 1]
    top = np.argmax(arch, axis=1)                 # the crest at each state
    crest_h = arch[np.arange(arch.shape[0]), top]
    k_state = int(np.argmin(crest_h))
    c, req = float(crest_h[k_state]), limits.hog_bend_clearance
    out.append(_row("hog bend clearance", "seabed_clearance", "m", "min", c, req,
                    req / c if (req > 0 and c > 0) else None,
                    _where(state, states, k_state, s_node[low_a + int(top[k_state])]),
                    f"min over the states of the crest's height (s = {s_node[low_a]:.6g} m to {s_node[sag]:.6g} m) "
                    f"above the seabed >= {req:.6g} m"))
    return out


def _declination_checks(one, limits, state, states, s_node) -> list[CableCheck]:
    names = ("hang-off declination (lowest)", "hang-off declination (highest)")
    r = limits.hang_off_declination
    if r is None:
        return [_skip(n, "declination", "rad", b, "no analysis.design.hang_off_declination range given")
                for n, b in zip(names, ("min", "max"), strict=True)]
    if "declination" not in one.variables:
        return [_skip(n, "declination", "rad", b, "no declination in the result (a line without bending stiffness)")
                for n, b in zip(names, ("min", "max"), strict=True)]
    theta = _states(one["declination"], state, "node")
    finite = np.flatnonzero(np.isfinite(theta).any(axis=0))
    end_b = int(finite[-1])
    tb = theta[:, end_b]
    lo, hi = r
    k_lo, k_hi = int(np.argmin(tb)), int(np.argmax(tb))
    width = hi - lo
    return [_row(names[0], "declination", "rad", "min", tb[k_lo], lo, max(hi - tb[k_lo], 0.0) / width,
                 _where(state, states, k_lo, s_node[end_b]), f"declination at end B >= {lo:.6g} rad "
                 f"({math.degrees(lo):.4g} deg)"),
            _row(names[1], "declination", "rad", "max", tb[k_hi], hi, max(tb[k_hi] - lo, 0.0) / width,
                 _where(state, states, k_hi, s_node[end_b]), f"declination at end B <= {hi:.6g} rad "
                 f"({math.degrees(hi):.4g} deg)")]


_COLUMNS = tuple(f.name for f in fields(CableCheck))


def cable_check_table(checks) -> pd.DataFrame:
    """The cable checks as a table, one row a check (:class:`CableCheck`'s fields as columns; utilisation NaN
    where it has none)."""
    rows = []
    for i, c in enumerate(checks):
        if not isinstance(c, CableCheck):
            raise InputError(f"checks[{i}] must be a CableCheck, got {type(c).__name__}. Suggested fix: pass what "
                             "cable_checks returns.")
        row = {f: getattr(c, f) for f in _COLUMNS}
        row["utilisation"] = math.nan if c.utilisation is None else c.utilisation
        rows.append(row)
    return pd.DataFrame(rows, columns=list(_COLUMNS))

"""A 3-D interactive view of a result: one self-contained HTML page (plotly, its script embedded).

The lines of any result with a shape (``static``, ``towed_steady``, ``modal``, ``mooring_*``, ``system_static``,
``system_dynamic``, ``towed_dynamic``, ``laying_dynamic``, ``towline_dynamic``) are drawn in 3-D, Z up, coloured by
their tension
(kN, one colour bar), over the sea surface (z = 0) and the seabed the result knows: the case's flat or sloped
plane, its profile along X or its seabed grid (land left open), or the lay's seabed on its track or route. Bodies,
vessels and the lay ship are markers. A result with several states (output times, pushover offsets, system conditions) is animated: one
frame a state, a slider and a play button; output times are decimated evenly to at most ``max_frames`` frames
(the first and the last kept), so that a 3-hour run's page stays a few megabytes (plotly's own script is 4.8 MB
of it). The page needs no network: plotly's script is written into it (``include_plotlyjs=True``).

Only results are read (never a model's internals); the page is written whole or not at all
(:func:`seacable._atomic.atomic_path`).

References
----------
Plotly Technologies Inc., plotly.py (MIT): https://plotly.com/python/ -- 3-D scatter and surface traces, frames,
sliders and ``Figure.write_html``.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import InputError

__all__ = ["SHAPE_ANALYSES", "view", "view_figure"]

#: analysis types whose results hold line shapes (x and z along a line, y where the result is 3-D)
SHAPE_ANALYSES = ("static", "towed_steady", "modal", "mooring_static", "mooring_pushover", "mooring_dynamic",
                  "system_static", "system_dynamic", "towed_dynamic", "laying_dynamic",
                  "towline_dynamic")

#: the dimensions along a line (the last dimension of ``x``)
_ALONG = ("node", "point")
#: the dimension that tells lines apart (one trace each); every other dimension of ``x`` is a frame
_LINE = "line"
#: the lines' colour scale (a perceptually uniform one, readable in grey)
COLORSCALE = "Viridis"
#: points along x and along y at which a seabed grid is drawn (bilinear between them)
_GRID_SAMPLES = 41
#: sea surface and seabed colours
SEA = "rgb(70,130,180)"
SEABED = "rgb(194,166,120)"
#: vessels and bodies: (x, y, z or None, dims holding a body or vessel name or None, label)
_MARKERS = (("body_x", "body_y", "body_z", "body", "body"),
            ("ship_x", "ship_y", None, None, "ship (water entry)"),
            ("vessel_x", "vessel_y", None, None, "tow point"),
            ("tug_x", "tug_y", None, None, "tug"),
            ("barge_x", "barge_y", None, None, "barge"))
#: the vertical scale is exaggerated when the depth is under this share of the horizontal extent
_FLAT = 0.15


@dataclass
class _Scene:
    """What is drawn: per frame, the lines' and the markers' coordinates [m] and tensions [N]."""

    labels: list[str]                                   # one a frame
    index: dict                                         # frame dim -> the result's index of each frame
    lines: list[tuple[str, np.ndarray, np.ndarray, np.ndarray, np.ndarray | None]] = field(default_factory=list)
    markers: list[tuple[str, np.ndarray, np.ndarray, np.ndarray]] = field(default_factory=list)
    seabed: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None   # surface x, y, z [m]
    tension_range: tuple[float, float] | None = None                  # over the whole result, every time [N]
    box: tuple[float, float, float, float] = (0.0, 1.0, 0.0, 1.0)     # x0, x1, y0, y1 of lines and markers [m]


def _refuse(ds, source: str) -> None:
    analysis = ds.attrs.get("analysis")
    if analysis is None:
        raise InputError(f"{source} is not a seacable result: it has no 'analysis' attribute. Suggested fix: give a "
                         "file written by 'seacable run'.")
    if analysis not in SHAPE_ANALYSES or "x" not in ds.variables or "z" not in ds.variables:
        missing = [n for n in ("x", "z") if n not in ds.variables]
        why = (f"it holds no line shape (no variable {' or '.join(missing)})" if missing
               else "its analysis has no line shape")
        raise InputError(f"{source} is a '{analysis}' result: {why}, so there is nothing to view in 3-D. Expected a "
                         f"result of one of {', '.join(SHAPE_ANALYSES)}. Suggested fix: view the result of a "
                         "static, pushover or time-domain run of the line or system ('seacable plot' makes the "
                         f"figures of a '{analysis}' result).")
    along = ds["x"].dims[-1] if ds["x"].dims else None
    if along not in _ALONG:
        raise InputError(f"{source}: its variable 'x' has dimensions {ds['x'].dims}, expected the last one along "
                         f"the line ({' or '.join(_ALONG)}). Suggested fix: give a file written by 'seacable run'.")


def _frames(ds, max_frames: int) -> tuple[list[str], dict]:
    """The frame dimensions of ``x`` (all but the line and along it), their indices and labels."""
    dims = [d for d in ds["x"].dims[:-1] if d != _LINE]
    if not dims:
        return [""], {}
    shape = [ds.sizes[d] for d in dims]
    n = int(np.prod(shape))
    keep = np.arange(n)
    if "time" in dims and n > max_frames:  # evenly in time, first and last kept (the first alone for 1)
        keep = np.unique(np.round(np.linspace(0, n - 1, max_frames)).astype(int))
    flat = np.unravel_index(keep, shape)
    index = {d: np.asarray(i) for d, i in zip(dims, flat, strict=True)}
    labels = []
    for k in range(keep.size):
        parts = []
        for d in dims:
            coord = ds[d] if d in ds.coords else None
            value = coord.values[index[d][k]] if coord is not None else index[d][k]
            units = coord.attrs.get("units", "") if coord is not None else ""
            unit = f" {units}" if units not in ("", "1") else ""
            text = f"{value:.6g}" if isinstance(value, (float, np.floating)) else str(value)
            parts.append(f"{'t' if d == 'time' else d} = {text}{unit}")
        labels.append(", ".join(parts))
    return labels, index


def _pick(da, index: dict, nf: int) -> np.ndarray:
    """``da`` at the frames (leading axis of length ``nf``), its other dimensions after, in their order."""
    sel = {d: ("_f", i) for d, i in index.items() if d in da.dims}
    import xarray as xr

    if sel:
        da = da.isel({d: xr.DataArray(i, dims="_f") for d, (_, i) in sel.items()})
        da = da.transpose("_f", ...)
        return np.asarray(da.values, dtype=float)
    values = np.asarray(da.values, dtype=float)
    return np.broadcast_to(values, (nf,) + values.shape)


def _tension_name(ds) -> str | None:
    """The tension variable: at the nodes (``tension`` along ``x``'s last dimension) or per segment (one fewer)."""
    along, n_along = ds["x"].dims[-1], ds["x"].shape[-1]
    for name in ("tension", "segment_tension"):
        if name in ds.variables and ds[name].dims:
            last = ds[name].dims[-1]
            if last == along or ds.sizes[last] == n_along - 1:
                return name
    return None


def _node_tension(ds, index: dict, nf: int) -> np.ndarray | None:
    """The tension at the nodes [N] (frames, [line,] node); segment tensions are averaged to the nodes (an end
    node takes its segment's)."""
    name = _tension_name(ds)
    if name is None:
        return None
    values = _pick(ds[name], index, nf)
    if ds[name].dims[-1] == ds["x"].dims[-1]:
        return values
    node = np.empty(values.shape[:-1] + (values.shape[-1] + 1,))
    node[..., 0], node[..., -1] = values[..., 0], values[..., -1]
    node[..., 1:-1] = 0.5 * (values[..., :-1] + values[..., 1:])
    return node


def _lines(ds, index: dict, nf: int) -> list:
    x = _pick(ds["x"], index, nf)
    z = _pick(ds["z"], index, nf)
    y = _pick(ds["y"], index, nf) if "y" in ds.variables else np.zeros_like(x)  # a 2-D result: the x-z plane
    tension = _node_tension(ds, index, nf)
    if _LINE in ds["x"].dims:
        names = [str(v) for v in ds[_LINE].values] if _LINE in ds.coords else [str(k) for k in range(x.shape[1])]
    else:
        names = [str(ds.attrs.get("case_name") or "line")]
        x, y, z = x[:, None], y[:, None], z[:, None]
        tension = None if tension is None else tension[:, None]
    out = []
    for k, name in enumerate(names):
        out.append((name, x[:, k], y[:, k], z[:, k], None if tension is None else tension[:, k]))
    return out


def _markers(ds, index: dict, nf: int) -> list:
    out = []
    for xn, yn, zn, dim, label in _MARKERS:
        if xn not in ds.variables or (yn not in ds.variables and "y" in ds.variables):
            continue
        mx = _pick(ds[xn], index, nf)
        my = _pick(ds[yn], index, nf) if yn in ds.variables else np.zeros_like(mx)  # a 2-D result: y = 0
        mz = _pick(ds[zn], index, nf) if zn and zn in ds.variables else np.zeros_like(mx)
        if dim and dim in ds[xn].dims:
            names = [str(v) for v in ds[dim].values] if dim in ds.coords else [str(k) for k in range(mx.shape[1])]
            out += [(f"{label} {n}", mx[:, k], my[:, k], mz[:, k]) for k, n in enumerate(names)]
        else:
            out.append((label, mx, my, mz))
    if "body_position" in ds.variables and "body_x" not in ds.variables:  # system_dynamic: (time, body, axis)
        pos = _pick(ds["body_position"], index, nf)
        names = [str(v) for v in ds["body"].values] if "body" in ds.coords else [str(k) for k in range(pos.shape[1])]
        out += [(f"body {n}", pos[:, k, 0], pos[:, k, 1], pos[:, k, 2]) for k, n in enumerate(names)]
    return out


def _case_seabed(ds):
    """(depth [m], slope [rad], profile (distance, depth) [m] or None) of the case stamped in the result, its seabed
    grid (:class:`seacable.bathymetry.SeabedGrid`), or None."""
    text = ds.attrs.get("case")
    if not text:
        return None
    import yaml

    from .._model import load_yaml
    from ..environment import Seabed

    try:
        env = (load_yaml(text) or {}).get("environment") or {}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")   # the run warned already
            bed = Seabed.model_validate(env.get("seabed") or {})
    except (yaml.YAMLError, AttributeError, TypeError, ValueError):
        return None  # a result written by another tool: no seabed drawn rather than no page
    if bed.grid is not None:  # a seabed grid (issue 41): drawn as it is (its file read again: a path may have moved)
        from ..bathymetry import cartesian_grid
        from ..errors import InputError

        try:
            return cartesian_grid(bed.grid)
        except (InputError, OSError, ValueError):
            return None
    profile = None if bed.profile is None else (np.asarray(bed.profile.distance), np.asarray(bed.profile.depth))
    depth = env.get("depth")
    if profile is None and depth is None:
        return None
    try:
        return (None if depth is None else float(depth)), float(bed.slope), profile
    except (TypeError, ValueError):
        return None


def _kp_origin(rx, ry, rkp, ds) -> float:
    """The KP of the route's first vertex [m]: the ship's KP less its distance along the vertices' polyline
    (the median over the output times)."""
    px, py = np.asarray(ds["ship_x"].values, float).ravel(), np.asarray(ds["ship_y"].values, float).ravel()
    ship_kp = np.asarray(ds["ship_kp"].values, float).ravel()
    ax, ay = rx[:-1, None], ry[:-1, None]
    ex, ey = np.diff(rx)[:, None], np.diff(ry)[:, None]
    length2 = np.where(ex**2 + ey**2 > 0, ex**2 + ey**2, 1.0)
    u = np.clip(((px - ax) * ex + (py - ay) * ey) / length2, 0.0, 1.0)          # (leg, time)
    gap = np.hypot(ax + u * ex - px, ay + u * ey - py)
    leg = np.argmin(gap, axis=0)
    cols = np.arange(px.size)
    along = rkp[leg] + u[leg, cols] * np.sqrt(length2[leg, 0])
    ok = np.isfinite(along) & np.isfinite(ship_kp)
    return float(np.median(ship_kp[ok] - along[ok])) if ok.any() else 0.0


def _seabed(ds, box) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """The seabed surface (x, y, z) [m] over the horizontal ``box`` (x0, x1, y0, y1) [m]."""
    x0, x1, y0, y1 = box
    if "seabed_z" in ds.variables and ds["seabed_z"].ndim == 1:
        bz = np.asarray(ds["seabed_z"].values, float)
        if "route_x" in ds.variables and "seabed_kp" in ds.variables:
            # a lay along a route: the seabed on the route (KP: distance along the track's vertices), a ribbon
            kp = np.asarray(ds["seabed_kp"].values, float)
            rx, ry = np.asarray(ds["route_x"].values, float), np.asarray(ds["route_y"].values, float)
            rkp = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(rx), np.diff(ry)))])
            if "ship_kp" in ds.variables and "ship_y" in ds.variables:   # where the route's KP 0 is: the ship's
                rkp += _kp_origin(rx, ry, rkp, ds)
            cx, cy = np.interp(kp, rkp, rx), np.interp(kp, rkp, ry)
            half = 0.5 * max(y1 - y0, x1 - x0) * 0.25
            tx, ty = np.gradient(cx), np.gradient(cy)
            norm = np.hypot(tx, ty)
            norm[norm == 0] = 1.0
            nx, ny = -ty / norm, tx / norm
            return (np.stack([cx - half * nx, cx + half * nx], axis=1),
                    np.stack([cy - half * ny, cy + half * ny], axis=1),
                    np.stack([bz, bz], axis=1))
        if "seabed_x" in ds.variables:       # a lay in its plane: the profile under the track, level across
            bx = np.asarray(ds["seabed_x"].values, float)
            keep = np.isfinite(bx) & np.isfinite(bz)
            bx, bz = bx[keep], bz[keep]
            if bx.size >= 2:
                xs = np.unique(np.concatenate([[x0, x1], bx[(bx > x0) & (bx < x1)]]))
                zs = np.interp(xs, bx, bz)
                return np.stack([xs, xs], 1), np.tile([y0, y1], (xs.size, 1)), np.stack([zs, zs], 1)
    bed = _case_seabed(ds)
    if bed is not None and not isinstance(bed, tuple):   # a seabed grid: sampled over the box (land NaN: a gap)
        gx = np.linspace(max(x0, bed.x[0]), min(x1, bed.x[-1]), _GRID_SAMPLES)
        gy = np.linspace(max(y0, bed.y[0]), min(y1, bed.y[-1]), _GRID_SAMPLES)
        X, Y = np.meshgrid(gx, gy, indexing="ij")
        return X, Y, bed.at(X, Y)[0]
    if bed is None:
        if "seabed_z" in ds.variables and ds["seabed_z"].ndim == 0:
            depth, slope, profile = -float(ds["seabed_z"].values), 0.0, None
        else:
            return None
    else:
        depth, slope, profile = bed
    if profile is not None:
        dist, dep = profile
        xs = np.unique(np.concatenate([[x0, x1], dist[(dist > x0) & (dist < x1)]]))
        zs = -np.interp(xs, dist, dep)       # linear between the points, level beyond them (environment.Seabed)
    else:
        xs = np.linspace(x0, x1, 2)
        zs = -depth + xs * math.tan(slope)   # positive slope rising towards +X (environment.Seabed)
    return np.stack([xs, xs], 1), np.tile([y0, y1], (xs.size, 1)), np.stack([zs, zs], 1)


def _scene(ds, max_frames: int, source: str) -> _Scene:
    from ..results import check_time

    _refuse(ds, source)
    check_time(ds, source)
    labels, index = _frames(ds, max_frames)
    nf = len(labels)
    scene = _Scene(labels=labels, index=index, lines=_lines(ds, index, nf), markers=_markers(ds, index, nf))
    pts = [np.concatenate([a.ravel() for a in arrays]) for arrays in
           zip(*[(x, y, z) for _, x, y, z, _ in scene.lines] + [(x, y, z) for _, x, y, z in scene.markers],
               strict=True)]
    xs, ys = pts[0][np.isfinite(pts[0])], pts[1][np.isfinite(pts[1])]
    if xs.size == 0:
        raise InputError(f"{source}: every position of its lines is NaN (no node in the water at any output time). "
                         "Suggested fix: check the run's log; rerun the case.")
    dx = float(xs.max() - xs.min()) or 1.0
    pad = 0.05 * dx
    y0, y1 = float(ys.min()), float(ys.max())
    if y1 - y0 < 0.2 * dx:                       # a line in its plane: a strip of seabed and sea either side
        mid = 0.5 * (y0 + y1)
        y0, y1 = mid - 0.1 * dx, mid + 0.1 * dx
    box = (float(xs.min()) - pad, float(xs.max()) + pad, y0 - pad, y1 + pad)
    scene.seabed = _seabed(ds, box)
    scene.box = box
    name = _tension_name(ds)
    if name is not None:
        values = np.asarray(ds[name].values, float)
        values = values[np.isfinite(values)]
        if values.size:   # every output time, not only the frames': one scale for every decimation
            scene.tension_range = (float(values.min()), float(values.max()))
    return scene


def view_figure(ds, *, max_frames: int = 120, source: str = "the result"):
    """The 3-D view of a result as a plotly Figure (see the module's docstring).

    Parameters
    ----------
    ds : xarray.Dataset
        A result with line shapes (one of :data:`SHAPE_ANALYSES`).
    max_frames
        Largest number of animation frames of a time-domain result, at least 1; output times are taken evenly
        (first and last kept). The states of a pushover or of a system's conditions are all drawn.
    source
        Where the result came from, for messages.

    Returns
    -------
    plotly.graph_objects.Figure
        Traces: the sea surface, the seabed (when known), one line trace a line (coordinates [m], colour:
        tension [kN]) and one marker trace a body or vessel; frames of the same line and marker traces.

    Raises
    ------
    InputError
        If the result holds no line shape (or its time is not increasing), or ``max_frames`` is under 1.
    """
    import plotly.graph_objects as go

    if not isinstance(max_frames, (int, np.integer)) or isinstance(max_frames, bool) or max_frames < 1:
        raise InputError(f"max_frames {max_frames!r}: expected a whole number of frames, at least 1. Suggested "
                         "fix: max_frames=120.")
    scene = _scene(ds, int(max_frames), source)
    nf = len(scene.labels)
    coloured = scene.tension_range is not None and any(t is not None for *_, t in scene.lines)
    cmin, cmax = (scene.tension_range[0] / 1e3, scene.tension_range[1] / 1e3) if coloured else (0.0, 1.0)
    if cmax <= cmin:
        cmax = cmin + 1.0

    def moving(f: int) -> list:
        out = []
        for name, x, y, z, t in scene.lines:
            line = {"width": 6}
            if t is not None and coloured:
                line.update(color=t[f] / 1e3, coloraxis="coloraxis")
            else:
                line.update(color="rgb(0,114,178)")
            hover = f"{name}<br>x %{{x:.2f}} m<br>y %{{y:.2f}} m<br>z %{{z:.2f}} m"
            if t is not None and coloured:
                hover += "<br>T %{line.color:.1f} kN"
            out.append(go.Scatter3d(x=x[f], y=y[f], z=z[f], mode="lines", name=name, line=line, legendgroup=name,
                                    showlegend=False, connectgaps=False, hovertemplate=hover + "<extra></extra>"))
        for name, x, y, z in scene.markers:
            out.append(go.Scatter3d(x=np.atleast_1d(x[f]), y=np.atleast_1d(y[f]), z=np.atleast_1d(z[f]),
                                    mode="markers", name=name,
                                    marker={"size": 6, "color": "rgb(213,94,0)", "symbol": "square"}))
        return out

    fixed = []
    xs = np.concatenate([np.ravel(x) for _, x, _, _, _ in scene.lines])
    xs = xs[np.isfinite(xs)]
    zs = np.concatenate([np.ravel(z) for _, _, _, z, _ in scene.lines])
    zs = zs[np.isfinite(zs)]
    if scene.seabed is not None:
        bx, by, bz = scene.seabed
        fixed.append(go.Surface(x=bx, y=by, z=bz, surfacecolor=np.zeros_like(bz), showscale=False,
                                colorscale=[[0, SEABED], [1, SEABED]], opacity=0.9, name="seabed",
                                hoverinfo="skip", showlegend=True))
        lo, hi = scene.box[0::2], scene.box[1::2]      # the lines' and markers' box, and the seabed's
        sx = (min(float(bx.min()), lo[0]), max(float(bx.max()), hi[0]))
        sy = (min(float(by.min()), lo[1]), max(float(by.max()), hi[1]))
        zlo = min(float(zs.min()), float(bz.min()))
    else:
        xs_all = xs if xs.size else np.array([0.0])
        span = float(xs_all.max() - xs_all.min()) or 1.0
        sx = (float(xs_all.min()) - 0.05 * span, float(xs_all.max()) + 0.05 * span)
        ys = np.concatenate([np.ravel(y) for _, _, y, _, _ in scene.lines])
        ys = ys[np.isfinite(ys)]
        mid = 0.5 * (float(ys.min()) + float(ys.max())) if ys.size else 0.0
        half = max(0.5 * (float(ys.max()) - float(ys.min())) if ys.size else 0.0, 0.1 * span) + 0.05 * span
        sy = (mid - half, mid + half)
        zlo = float(zs.min()) if zs.size else -1.0
    fixed.append(go.Surface(x=np.array([sx, sx]).T, y=np.array([[sy[0]] * 2, [sy[1]] * 2]).T, z=np.zeros((2, 2)),
                            surfacecolor=np.zeros((2, 2)), colorscale=[[0, SEA], [1, SEA]], showscale=False,
                            opacity=0.25, name="sea surface", hoverinfo="skip", showlegend=True))
    zhi = max(0.0, float(zs.max()) if zs.size else 0.0)
    zpad = 0.05 * ((zhi - zlo) or 1.0)
    ranges = {"x": sx, "y": sy, "z": (zlo - zpad, zhi + zpad)}
    spans = {k: v[1] - v[0] for k, v in ranges.items()}
    big = max(spans["x"], spans["y"])
    ratio = {k: spans[k] / big for k in spans}
    title = f"{ds.attrs.get('title') or ds.attrs.get('case_name', '')} ({ds.attrs.get('analysis')})"
    if ratio["z"] < _FLAT:                       # a shallow scene: the depth exaggerated to be seen
        factor = _FLAT / ratio["z"]
        ratio["z"] = _FLAT
        title += f"; vertical scale x {factor:.3g}"
    # the lines' legend entries: a trace of no point each, in one colour, grouped with its line (a legend
    # drawn from a line of typed-array colours warns 'Invalid color specifier' in the browser's console)
    fixed += [go.Scatter3d(x=[None], y=[None], z=[None], mode="lines", name=name, legendgroup=name,
                           line={"color": "rgb(80,80,80)", "width": 6}, hoverinfo="skip")
              for name, *_ in scene.lines]
    fig = go.Figure(data=fixed + moving(0))
    n_fixed = len(fixed)
    moving_idx = list(range(n_fixed, n_fixed + len(scene.lines) + len(scene.markers)))
    axis = {k: {"range": list(ranges[k]), "title": f"{k} [m]", "autorange": False, "nticks": 5} for k in ranges}
    fig.update_layout(title={"text": title, "font": {"size": 14}}, template="plotly_white",
                      scene={"xaxis": axis["x"], "yaxis": axis["y"], "zaxis": axis["z"], "aspectmode": "manual",
                             "aspectratio": {"x": ratio["x"], "y": ratio["y"], "z": ratio["z"]}},
                      legend={"x": 0.0, "y": 1.0}, margin={"l": 0, "r": 0, "t": 40, "b": 0})
    if coloured:
        fig.update_layout(coloraxis={"colorscale": COLORSCALE, "cmin": cmin, "cmax": cmax,
                                     "colorbar": {"title": {"text": "tension [kN]"}}})
    if nf > 1:
        fig.frames = [go.Frame(data=moving(f), traces=moving_idx, name=str(f)) for f in range(nf)]
        step = {"frame": {"duration": 0, "redraw": True}, "mode": "immediate", "transition": {"duration": 0}}
        play = {"frame": {"duration": 100, "redraw": True}, "fromcurrent": True, "transition": {"duration": 0},
                "mode": "immediate"}
        buttons = [{"label": "play", "method": "animate", "args": [None, play]},
                   {"label": "pause", "method": "animate", "args": [[None], step]}]
        fig.update_layout(
            updatemenus=[{"type": "buttons", "direction": "left", "x": 0.0, "y": 0.0, "xanchor": "left",
                          "yanchor": "top", "pad": {"t": 30}, "buttons": buttons}],
            sliders=[{"active": 0, "x": 0.15, "len": 0.85, "y": 0.0, "yanchor": "top", "pad": {"t": 20},
                      "currentvalue": {"prefix": "", "font": {"size": 13, "color": "#444"}},
                      "font": {"color": "rgba(0,0,0,0)"},    # no label under every tick: the value above them
                      "steps": [{"label": label, "method": "animate", "args": [[str(f)], step]}
                                for f, label in enumerate(scene.labels)]}])
    fig.layout.meta = {"frame_index": {d: [int(i) for i in v] for d, v in scene.index.items()}}
    return fig


def view(ds, output: str | Path | None = None, *, max_frames: int = 120, source: str = "the result"):
    """A 3-D interactive view of a result: a self-contained HTML page (no network needed to open it).

    Parameters
    ----------
    ds : xarray.Dataset
        A result with line shapes: from :func:`seacable.run` or :func:`seacable.read_netcdf`.
    output
        The HTML page to write (``.html``), whole or not at all; ``None`` writes nothing.
    max_frames
        Largest number of animation frames of a time-domain result. A 3-hour run's page, 120 frames of a few
        lines of 40-odd nodes, is under 6.5 MB, 4.8 MB of it plotly's script.
    source
        Where the result came from, for messages.

    Returns
    -------
    plotly.graph_objects.Figure
        The figure (:func:`view_figure`); ``fig.show()`` opens it in a notebook or a browser.

    Raises
    ------
    InputError
        If the result holds no line shape, or the page cannot be written.

    Examples
    --------
    >>> import seacable as sc
    >>> ds = sc.read_netcdf("storm.nc")                      # doctest: +SKIP
    >>> sc.view(ds, "storm.html")                            # doctest: +SKIP
    """
    fig = view_figure(ds, max_frames=max_frames, source=source)
    if output is not None:
        from .._atomic import atomic_path
        from ..results import check_output_file

        path = check_output_file(output, "output", (".html", ".htm"))
        with atomic_path(path, "the 3-D view") as tmp:
            fig.write_html(tmp, include_plotlyjs=True, full_html=True, auto_play=False,
                           config={"displaylogo": False, "responsive": True})
    return fig

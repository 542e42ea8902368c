"""The seabed of the models that do not model contact with it (``towed_dynamic``, ``towline_dynamic``).

Neither the towed-cable box scheme nor the towline's multibody model has seabed contact: a node
may go below ``environment.depth`` and the run goes on as if the water were deeper. Until they
have it, a depth given to them is not silently ignored: :func:`warn_depth_not_modelled` says so
before the run, and :func:`seabed_clearance` gives the result the minimum clearance over the
nodes at every output time and warns, naming the time, the node and the depth, when a node
crosses the seabed.
"""

from __future__ import annotations

import warnings

import numpy as np

from ..errors import SeacableWarning

__all__ = ["seabed_clearance", "surface_excursion", "warn_depth_not_modelled"]


def warn_depth_not_modelled(analysis: str, depth: float | None) -> None:
    """Warn (once, before a run) that ``environment.depth`` sets no seabed in ``analysis``.

    Parameters
    ----------
    analysis
        The analysis type, for the message.
    depth
        ``environment.depth``; nothing is said when it is None. [m]
    """
    if depth is None:
        return
    warnings.warn(
        f"environment.depth = {depth:g} m: analysis '{analysis}' does not model seabed contact, so a line "
        "that reaches the seabed goes on through it. The result carries 'seabed_clearance' (the lowest "
        "node's height above the seabed) and the run warns if a node goes below the seabed. Suggested fix: "
        "check 'seabed_clearance' stays positive, or leave 'depth' out for deep water.",
        SeacableWarning, stacklevel=3)


def seabed_clearance(time, z, depth: float, *, analysis: str, node_name=None, floor=None) -> np.ndarray:
    """Minimum height of the nodes above the seabed at each output time; warns if it is negative.

    Parameters
    ----------
    time
        Output times, shape (nt,). [s]
    z
        Node elevations (Z up, 0 at the surface), shape (nt, nodes); NaN entries (nodes not in
        the water, e.g. line still on a bitt) are left out. [m]
    depth
        Water depth, the seabed at ``z = -depth``. [m]
    analysis
        The analysis type, for the message.
    node_name
        Optional ``node_name(j) -> str`` describing node ``j`` (e.g. "node 0, the lower end").
    floor
        The seabed's elevation under each node instead of ``-depth`` (a grid's,
        :class:`seacable.bathymetry.SeabedGrid`), shape (nt, nodes); ``depth`` then only names it. [m]

    Returns
    -------
    numpy.ndarray
        ``min over nodes (z + depth)`` (or ``z - floor``) at each time, shape (nt,); negative where a node is
        below the seabed. [m]
    """
    z = np.asarray(z, float)
    height = z + float(depth) if floor is None else z - np.asarray(floor, float)
    finite = np.isfinite(height)
    clearance = np.where(finite.any(axis=1), np.min(np.where(finite, height, np.inf), axis=1), np.nan)
    below = np.flatnonzero(clearance < 0)
    if below.size:
        i = int(below[0])
        j = int(np.nanargmin(height[i]))
        worst = int(np.nanargmin(clearance))
        name = node_name(j) if node_name is not None else f"node {j}"
        at = f"{depth:g} m (environment.depth)" if floor is None else \
            f"{-float(floor[i, j]):g} m (environment.seabed.grid)"
        warnings.warn(
            f"{analysis}: at t = {float(time[i]):g} s {name} is {-z[i, j]:g} m deep, below the seabed at "
            f"{at}; this model has no seabed contact, so the line went on through "
            f"it (deepest: {-float(clearance[worst]):g} m below the seabed at t = {float(time[worst]):g} s). "
            "The result's 'seabed_clearance' is negative where a node is below the seabed. Suggested fix: "
            "a shorter or lighter line, a faster tow, or a model with seabed contact (mooring_dynamic).",
            SeacableWarning, stacklevel=3)
    return clearance


def surface_excursion(time, z, *, analysis: str, skip_last: bool = True) -> np.ndarray:
    """Highest elevation of the nodes above the still water level at each output time; warns if positive.

    For a model that weighs every node in water (the towed-cable box scheme): a node above the surface is
    weighed and loaded as if immersed, so the result there is not the cable's.

    Parameters
    ----------
    time
        Output times, shape (nt,). [s]
    z
        Node elevations (Z up, 0 at the surface), shape (nt, nodes). [m]
    analysis
        The analysis type, for the message.
    skip_last
        Leave out the last node (the tow point, held by the vessel wherever it is). [-]

    Returns
    -------
    numpy.ndarray
        ``max over nodes z`` at each time, shape (nt,); positive where a node is above the water. [m]
    """
    z = np.asarray(z, float)
    free = z[:, :-1] if skip_last else z
    height = np.nanmax(free, axis=1)
    tol = 1e-6 * max(1.0, float(np.nanmax(np.abs(free), initial=0.0)))
    above = np.flatnonzero(height > tol)
    if above.size:
        i = int(above[0])
        j = int(np.nanargmax(free[i]))
        worst = int(np.nanargmax(height))
        warnings.warn(
            f"{analysis}: at t = {float(time[i]):g} s node {j} is {float(free[i, j]):.4g} m above the sea surface, "
            "but this model weighs and loads every node as immersed, so the cable's shape and tensions there are "
            f"not right (highest: {float(height[worst]):.4g} m at t = {float(time[worst]):g} s). The result's "
            "'surface_excursion' is positive where a node is above the water. Suggested fix: a heavier cable or "
            "body (less buoyancy), a tow point at the surface, or formulation: finite_element, which weighs a "
            "node above the water at its dry weight.", SeacableWarning, stacklevel=3)
    return height

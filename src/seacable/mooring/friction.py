"""The seabed's Coulomb friction in the statics of a mooring line or cable: where the friction targets come from,
how they follow a line that slides, and the analyses' choice (:class:`StaticFriction`).

The dynamics' friction acts on the nodes' velocity (:mod:`seacable.mooring._loads`): at rest it gives no force, so
the statics used to be frictionless, and a current at the seabed dragged a grounded cable with nothing to hold it.
The statics now take OrcaFlex's model (Orcina, *OrcaFlex help: Friction theory*): each grounded node has a
friction *target position* and the friction acts in the seabed's plane towards it, elastic (a shear spring) up to
``mu N`` and sliding beyond, regularised smoothly (:mod:`seacable.mooring._friction`, with its exact tangent).

**The targets** (``mode: as_laid``, the default, OrcaFlex's): the *as-laid* state is the frictionless equilibrium
in still water at the nominal positions (the case's fairlead; no current, no offset); every free node on the seabed
there takes its position as its target, and the analysis's loads (the current, the pushover's offsets) are then
applied with friction, from that state, in load steps: the whole load first, a step that fails cut to a quarter
(down to :data:`SMALLEST_STEP`); after each step a node that touched down takes its position as its target and one
that lifted off loses its (a slid node keeps its target within one monotonic loading, so that its force stays
``mu N``). In still water the result is the frictionless one, to the bit (the as-laid state is in equilibrium with
no friction force). A node off the seabed has no target and no friction. The dynamics keep the velocity's friction,
and their static start the frictionless statics (a start held by static friction would slide at t = 0).
``mode: off`` keeps the frictionless statics. Seabed friction 0 (``environment.seabed.friction``, the default) is
frictionless whatever the mode, to the bit as before.

**A pushover** (``pushover_path``): ``as_laid`` (the default) loads each offset from the as-laid targets, so that
each offset is the line pulled monotonically from its lay to that offset, independent of the others and of their
order; ``incremental`` applies the offsets in the order given, the first from the as-laid state, each from the
previous offset's slid state: after each offset the targets follow the nodes that slid (a node farther than
``SLIDE_FACTOR d_f`` from its target has it moved along the slip to that distance behind it: the force stays
within 0.5 % of ``mu N``), a node that touched down takes its position as its target and one that lifted off loses
its. That is the path dependence of a real lay: a line pulled out and then pushed back stays where friction holds
it.

**The regularisation scale** ``friction_distance`` ``d_f`` (default 1 mm, as the laying analysis's): a grounded
node moved ``d`` from its target feels ``mu N d / sqrt(d^2 + d_f^2)``, so that a line held by friction (a lateral
drag ``q < mu w``) moves ``d_f r / sqrt(1 - r^2)`` with ``r = q / (mu w)``, and a line pulled along itself mobilises
its friction over the length where its stretch has moved it more than about ``d_f``: the shear-lag length
``sqrt(2 EA d_f / (mu w))`` (tens of metres for a stiff cable at 1 mm): a smaller ``d_f`` is nearer rigid-plastic
Coulomb friction (MoorPy's), at more Newton iterations.
"""

from __future__ import annotations

import dataclasses
from typing import Literal

import numpy as np
from pydantic import Field

from .._model import Model, quantity
from ..errors import ConvergenceError

__all__ = ["SLIDE_FACTOR", "StaticFriction", "StaticFrictionOption", "friction_pushover", "friction_static",
           "friction_targets", "load_steps", "slide_targets"]

#: The smallest load step (a fraction of the load from the last equilibrium) the statics with friction take before
#: they give up (:func:`friction_static`): 4^-3.
SMALLEST_STEP = 1.0 / 64.0
#: The iterations of a load step cut after a failure (:func:`_load_path`): it starts from the last equilibrium, a
#: little load away (the lazy wave's steps converge in 10-60), so that a load no friction can hold fails in seconds.
CUT_STEP_ITERATIONS = 150
#: A node farther than this many ``friction_distance`` from its target has slid: an incremental path moves its
#: target along the slip to that distance behind it (the regularised force there is 10 / sqrt(101) = 0.995 of mu N).
SLIDE_FACTOR = 10.0


class StaticFriction(Model):
    """The seabed's friction in the statics of a mooring line (``mooring_static``, ``mooring_pushover``).

    ``mode``: ``as_laid`` (the default): friction towards the targets of the as-laid state (the frictionless
    equilibrium in still water at the nominal fairlead), the analysis's current and offsets applied from there;
    ``off``: frictionless statics. ``pushover_path``: ``as_laid``, each offset loaded from the as-laid targets, or
    ``incremental``, each from the previous offset's slid state (the offsets in the order given).
    ``friction_distance``: the slip at which the friction reaches its limit, the regularisation's scale [m]
    (:mod:`seacable.mooring.friction`)."""

    mode: Literal["as_laid", "off"] = Field(
        "as_laid", description="'as_laid': Coulomb friction in the statics towards the as-laid positions (the "
                               "frictionless equilibrium in still water); 'off': frictionless statics.")
    pushover_path: Literal["as_laid", "incremental"] = Field(
        "as_laid", description="A pushover's offsets each loaded from the as-laid targets ('as_laid'), or in the "
                               "order given, each from the previous offset's slid state ('incremental').")
    friction_distance: quantity("m", gt=0, fix="give the slip in metres at which the friction reaches mu N, e.g. "
                                               "0.001.") = Field(
        1e-3, description="Slip at which the static friction reaches its limit mu N; below it a shear spring of "
                          "stiffness mu N / friction_distance. [m]")


class StaticFrictionOption(Model):
    """The ``static_friction`` key of the mooring analyses that solve statics (a mix-in of their schemas)."""

    static_friction: StaticFriction = Field(
        default_factory=StaticFriction,
        description="The seabed's friction in the statics (with environment.seabed.friction > 0): its targets, a "
                    "pushover's path and the slip distance.")


def _active(model, settings: StaticFriction | None) -> bool:
    water = model.water
    return (settings is not None and settings.mode != "off" and water.friction > 0.0 and water.seabed_stiffness > 0.0
            and (water.depth is not None or water.tabulated))


def _still(model):
    """``model`` in still water (no current): the as-laid state's."""
    from .solver import MooringModel

    water = model.water
    if not any(water.current_speeds):
        return model
    still = dataclasses.replace(water, current_speeds=(0.0,) * len(water.current_speeds))
    return MooringModel(model.network, still, checked=True)


def _normals(water, x, y=None):
    """The seabed's unit normal under each ``x`` (k, 3), from its slope along X; on a grid, its normal under each
    ``(x, y)`` (:meth:`seacable.bathymetry.SeabedGrid.normal`). [-]"""
    if water.grid is not None:
        return water.grid.normal(x, y)
    h = 1e-6
    slope = (water.seabed_z(x + h) - water.seabed_z(x - h)) / (2 * h)
    c = 1.0 / np.sqrt(1.0 + slope * slope)
    return np.column_stack([-slope * c, np.zeros_like(c), c])


def _in_contact(model, X) -> np.ndarray:
    """The free nodes that press on the seabed (a normal force > 0: penetration above minus the contact's rounding
    band, as the kernel's), (n,) bool."""
    from . import kernel as K

    water = model.water
    X = np.asarray(X, float)
    pen = (water.seabed_z(X[:, 0], X[:, 1]) - X[:, 2]) * _normals(water, X[:, 0], X[:, 1])[:, 2]
    return (pen > -model.env[K.E_BEDRAMP]) & (model.bedc > 0.0) & (model.fidx >= 0)


def friction_targets(model, X) -> np.ndarray:
    """The friction targets of the state ``X`` (n, 3): the positions of the free nodes on the seabed there, NaN rows
    for the others (no friction). [m]"""
    X = np.asarray(X, float)
    targets = np.full_like(X, np.nan)
    on = _in_contact(model, X)
    targets[on] = X[on]
    return targets


def slide_targets(model, X, targets, friction_distance: float, follow: bool = True) -> np.ndarray:
    """The targets after a converged load step at ``X`` (module docstring): those of nodes that slid farther than
    ``SLIDE_FACTOR friction_distance`` follow them to that distance (unless ``follow`` is False: the load steps of
    one monotonic loading, where the regularised force of a slid node must stay ``mu N``), touched-down nodes take
    their positions, lifted-off ones none. [m]"""
    X = np.asarray(X, float)
    out = np.full_like(X, np.nan)
    on = _in_contact(model, X)
    held = on & np.isfinite(targets[:, 0])
    out[on & ~held] = X[on & ~held]
    r = X[held] - targets[held]
    n = _normals(model.water, X[held, 0], X[held, 1])
    d = r - np.sum(r * n, axis=1)[:, None] * n
    size = np.linalg.norm(d, axis=1)
    reach = SLIDE_FACTOR * friction_distance
    far = (size > reach) & follow
    moved = targets[held].copy()
    moved[far] = X[held][far] - reach * d[far] / size[far, None]
    out[held] = moved
    return out


def _loaded(model, fraction: float):
    """``model`` with its current's speeds times ``fraction``."""
    from .solver import MooringModel

    water = model.water
    if fraction == 1.0 or not any(water.current_speeds):
        return model
    speeds = tuple(fraction * v for v in water.current_speeds)
    return MooringModel(model.network, dataclasses.replace(water, current_speeds=speeds), checked=True)


def load_steps(solve, model, start, targets, settings, *, what: str, hint=None):
    """Apply a load from the equilibrium ``start`` with friction targets ``targets`` in load steps: the whole load
    first; a step that fails is cut to a quarter, down to :data:`SMALLEST_STEP`; after each, touched-down nodes take
    their positions as targets and lifted-off ones lose theirs (:func:`slide_targets`; a slid node keeps its target:
    one monotonic loading). The single line's statics and the system's finite-element statics share it.

    ``solve(fraction, last, targets, max_iter)`` returns the equilibrium (with ``position`` (n, 3) [m] and
    ``iterations``) under ``fraction`` of the load, started from ``last`` (``start`` or the last step's
    equilibrium), or raises :class:`ConvergenceError`; ``model`` (a :class:`~seacable.mooring.solver.MooringModel`)
    gives the seabed and the nodes for the targets; ``hint(fraction, last)`` says why a step may fail (appended to
    the message). Returns the state, its targets and the iterations spent."""
    done, step, spent, state, last = 0.0, 1.0, 0, None, start
    while state is None or done < 1.0:
        nxt = min(1.0, done + step)
        try:
            state = solve(nxt, last, targets, 500 if step == 1.0 else CUT_STEP_ITERATIONS)
        except ConvergenceError as err:
            if step <= SMALLEST_STEP:
                # why, from the last equilibrium (the failed step's last state wanders)
                said = hint(nxt, last) if done > 0.0 and hint is not None else ""
                raise ConvergenceError(
                    f"{what}, applied in load steps down to {step:.3g} of it, did not converge beyond {done:.3g} of "
                    f"the load.{said if said not in str(err) else ''} The last step: {err}",
                    iterations=spent + (err.iterations or 0), residual=err.residual) from None
            step *= 0.25
            continue
        spent += state.iterations
        done, last = nxt, state
        targets = slide_targets(model, state.position, targets, settings.friction_distance, follow=False)
        step = min(4.0 * step, 1.0)
    return state, targets, spent


def _load_path(model, X, targets, settings, tol, *, to, current_from: float, what: str):
    """From the equilibrium ``X`` with friction targets ``targets`` to ``model``'s: the prescribed nodes moved from
    their places in ``X`` to ``to``, the current from ``current_from`` of its speeds to all of them, in load steps
    (:func:`load_steps`). Returns the state, its targets and the iterations spent."""
    from types import SimpleNamespace

    from .checks import seabed_hold_hint
    from .network import PRESCRIBED
    from .solver import static_equilibrium

    moving = model.network.kind == PRESCRIBED
    begin = X[moving].copy()

    def stepped(fraction):
        return _loaded(model, current_from + fraction * (1.0 - current_from))

    def solve(fraction, last, targets, max_iter):
        Y = last.position.copy()
        Y[moving] = begin + fraction * (to - begin)
        return static_equilibrium(stepped(fraction), Y, tol=tol, targets=targets, max_iter=max_iter,
                                  friction_distance=settings.friction_distance)

    return load_steps(solve, model, SimpleNamespace(position=X), targets, settings, what=what,
                      hint=lambda fraction, last: seabed_hold_hint(stepped(fraction), last.position, True))


def _as_laid(model, tol):
    """The as-laid state: the frictionless equilibrium in still water at the nominal positions."""
    from .solver import static_equilibrium

    try:
        return static_equilibrium(_still(model), tol=tol)
    except ConvergenceError as err:
        raise ConvergenceError(
            f"the as-laid state (the frictionless equilibrium in still water, which gives the static friction its "
            f"targets) has no solution: {err} If the line lies across a slope that only friction holds, the as-laid "
            "state cannot be found: set analysis.static_friction.mode: off and give the line a layout its tension "
            "holds.", iterations=getattr(err, "iterations", None), residual=getattr(err, "residual", None)) from None


def friction_static(model, settings: StaticFriction | None, *, tol: float = 1e-9):
    """The static equilibrium of ``model`` with the seabed's friction, from the as-laid state (module docstring);
    frictionless (:func:`seacable.mooring.solver.static_equilibrium`, unchanged) when ``settings`` is None or off, or
    the seabed has no friction. Its ``iterations`` count the as-laid state's and every load step's."""
    from .network import PRESCRIBED
    from .solver import static_equilibrium

    if not _active(model, settings):
        return static_equilibrium(model, tol=tol)
    laid = _as_laid(model, tol)
    moving = model.network.kind == PRESCRIBED
    state, _, spent = _load_path(model, laid.position, friction_targets(model, laid.position), settings, tol,
                                 to=laid.position[moving], current_from=0.0,
                                 what="the statics with seabed friction, the current applied from the as-laid state")
    return dataclasses.replace(state, iterations=spent + laid.iterations)


def friction_pushover(model, offsets, direction, settings: StaticFriction | None, *, tol: float = 1e-9):
    """A pushover (:func:`seacable.mooring.solver.pushover`) with the seabed's friction: each offset from the
    as-laid state, or along the incremental path (module docstring); the frictionless one when ``settings`` is
    None or off, or the seabed has no friction."""
    from .network import PRESCRIBED
    from .solver import pushover

    if not _active(model, settings):
        return pushover(model, offsets, direction, tol=tol)
    d = np.asarray(direction, float)
    d = d / np.linalg.norm(d)
    moving = model.network.kind == PRESCRIBED
    base = model.network.position
    laid = _as_laid(model, tol)
    laid_targets = friction_targets(model, laid.position)
    X, targets, loaded = laid.position, laid_targets, 0.0
    states = []
    for off in np.asarray(offsets, float):
        if settings.pushover_path == "as_laid":
            X, targets, loaded = laid.position, laid_targets, 0.0
        state, targets, spent = _load_path(
            model, X, targets, settings, tol, to=base[moving] + off * d, current_from=loaded,
            what=f"the statics with seabed friction at the offset {off:g} m")
        states.append(dataclasses.replace(state, iterations=spent))
        X, loaded = state.position, 1.0
        if settings.pushover_path == "incremental":  # the next offset from this one's slid state
            targets = slide_targets(model, X, targets, settings.friction_distance)
    return states

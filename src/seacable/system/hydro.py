"""Bodies with a hydrodynamic database in a mooring system (issue 39): their matrices for the statics and the
dynamics, and what the coupled time loop adds (radiation memory, wave loads).

:func:`resolve_bodies` gives each body with ``hydrodynamics`` (:class:`~seacable.system.model.BodyHydrodynamics`)
the database's hydrostatic stiffness, with the weight's moment added unless the database holds it, and its
infinite-frequency added mass, so that the statics and the dynamics use them as a user's matrices.
:func:`body_wave_loads` and :func:`memory_kernels` are the time loop's: the first-order force of the case's sea
at the body's position and its mean or slow drift (Newman's, or the full QTF's), as a force series; the retardation
kernels at the run's step. :func:`body_wind_velocity` and :func:`area_tables`: the wind at a body and its wind and
current tables, whose forces the coupled step takes with the relative velocity; :func:`body_wind_loads` and
:func:`body_current_loads` the same forces linearised about the body at rest (the uncoupled route's).
"""

from __future__ import annotations

import functools
import math
from pathlib import Path

import numpy as np

from .._ramp import smooth_ramp
from ..errors import InputError
from .model import Body, MooringSystem

__all__ = ["MEMORY_TAIL", "area_tables", "body_current_loads", "body_wave_loads", "body_wind_loads", "body_wind_velocity",
           "database", "memory_kernels", "resolve_bodies", "weight_stiffness"]

#: The largest value of a body's retardation kernel at its cut (``kernel_length``), relative to its peak, in any DOF.
#: The VolturnUS-S kernel is at 0.5 % of its peak at 60 s (HydroDyn's RdtnTMax for it), 0.03 % at 120 s, 2.9 % at 30 s. [-]
MEMORY_TAIL = 0.02


@functools.lru_cache(maxsize=8)
def _read(root: str, stamp: tuple, fmt: str, ulen: float, rho: float, g: float):
    if fmt == "capytaine":
        from ..hydro import read_capytaine

        return read_capytaine(root)
    from ..hydro import read_wamit

    return read_wamit(root, ulen=ulen, rho=rho, g=g)


def database(body: Body, rho: float, g: float):
    """The :class:`~seacable.hydro.HydroDatabase` of a body's ``hydrodynamics`` (read once per version of its files):
    WAMIT's files made dimensional with the case's ``rho`` and ``g``, or a Capytaine dataset (dimensional already:
    its ``rho`` and ``g`` must be the case's)."""
    h = body.hydrodynamics
    fmt = h.database_format
    root = Path(h.file)
    if fmt == "capytaine":
        if not root.is_file():
            raise InputError(f"hydrodynamics.file: Capytaine dataset '{root}' does not exist. Suggested fix: give the "
                             "NetCDF file Capytaine's save_dataset_as_netcdf wrote, relative to the case file.")
        st = root.stat()
        db = _read(str(root.resolve()), (st.st_mtime_ns, st.st_size), fmt, 1.0, 0.0, 0.0)
        for name, case, data in (("water density", rho, db.rho), ("gravity", g, db.g)):
            if abs(case - data) > 1e-6 * case:
                raise InputError(f"hydrodynamics.file: Capytaine dataset '{root}' was solved with the {name} {data:g} "
                                 f"and the case has {case:g} (SI): its dimensional coefficients would not be the "
                                 f"case's. Suggested fix: solve with the case's environment, or set its {name} to "
                                 f"{data:g}.")
        return db
    one = Path(f"{root}.1")
    if not one.is_file():
        raise InputError(f"hydrodynamics.file: WAMIT file '{one}' does not exist. Suggested fix: give the root of "
                         "the WAMIT files (the path without '.1', '.3', '.hst') relative to the case file, or a "
                         "Capytaine dataset ending in .nc.")
    st = one.stat()
    return _read(str(root.resolve()), (st.st_mtime_ns, st.st_size), fmt, float(h.ulen), float(rho), float(g))


def weight_stiffness(body: Body, g: float) -> np.ndarray:
    """The restoring of the body's weight about its reference point (6, 6), in its axes: ``-skew(F) skew(c)`` for
    ``F = (0, 0, -m g)`` at the centre of gravity ``c`` (the rows and columns of roll, pitch and yaw)."""
    k = np.zeros((6, 6))
    f = -body.mass * g
    cx, cy, cz = body.center_of_gravity
    k[3, 3] = k[4, 4] = f * cz
    k[3, 5] = -f * cx
    k[4, 5] = -f * cy
    return k


def resolve_bodies(system: MooringSystem, rho: float, g: float) -> MooringSystem:
    """The system with each body's ``hydrodynamics`` turned into its hydrostatic stiffness and added mass."""
    if not any(b.hydrodynamics is not None for b in system.bodies.values()):
        return system
    bodies = {}
    for name, b in system.bodies.items():
        if b.hydrodynamics is None:
            bodies[name] = b
            continue
        db = database(b, rho, g)
        stiffness = db.hydrostatics.copy()
        if not b.hydrodynamics.weight_included:
            stiffness += weight_stiffness(b, g)
        if b.volume <= 0:
            raise InputError(f"bodies.{name}: a body with hydrodynamics needs its displaced volume (volume, m^3: "
                             "WAMIT's, HydroDyn's PtfmVol0); the database's hydrostatics hold only the restoring.")
        if b.kind == "free" and (b.mass <= 0 or min(b.inertia) <= 0):
            raise InputError(f"bodies.{name}: a free body with hydrodynamics needs its mass (kg) and its three moments "
                             f"of inertia about the centre of gravity (kg m^2), got mass {b.mass:g} kg and inertia "
                             f"{list(b.inertia)} kg m^2: the database holds the water's inertia, not the body's. "
                             "Suggested fix: give the platform's (and turbine's) mass and inertia, as ElastoDyn's "
                             "PtfmMass and PtfmRIner, PtfmPIner, PtfmYIner.")
        bodies[name] = b.model_copy(update={"hydrostatic_stiffness": tuple(map(tuple, stiffness)),
                                            "added_mass": tuple(map(tuple, db.added_mass_inf))})
    return MooringSystem(points=system.points, bodies=bodies, lines=system.lines)


def memory_kernels(system: MooringSystem, free_bodies, rho: float, g: float, dt: float) -> np.ndarray:
    """The free bodies' retardation kernels at the step ``dt`` (nb, n_k, 6, 6), the last sample halved (the
    trapezoidal rule), zeros for a body without a database; (nb, 1, 6, 6) zeros when none has one."""
    from ..hydro import retardation_kernel

    kernels = []
    for name in free_bodies:
        b = system.bodies[name]
        if b.hydrodynamics is None:
            kernels.append(None)
            continue
        _, k = retardation_kernel(database(b, rho, g), dt, float(b.hydrodynamics.kernel_length))
        tail = max(float(np.max(np.abs(k[-1, j, j])) / max(np.max(np.abs(k[:, j, j])), 1e-300)) for j in range(6))
        if tail > MEMORY_TAIL:
            raise InputError(f"bodies.{name}.hydrodynamics.kernel_length: the radiation memory is cut at "
                             f"{b.hydrodynamics.kernel_length:g} s where it is still {tail:.1%} of its peak (more "
                             f"than {MEMORY_TAIL:.0%}): the memory dropped would change the damping. Suggested fix: "
                             f"a kernel_length of {2 * b.hydrodynamics.kernel_length:g} s or more.")
        k[-1] *= 0.5
        kernels.append(k)
    n = max((k.shape[0] for k in kernels if k is not None), default=1)
    out = np.zeros((len(free_bodies), n, 6, 6))
    for i, k in enumerate(kernels):
        if k is not None:
            out[i, :k.shape[0]] = k
    return out


def body_wave_loads(body: Body, name: str, sea, rho: float, g: float, t: np.ndarray) -> np.ndarray | None:
    """The first-order wave force and the drift the body's ``hydrodynamics`` asks for, in the sea ``sea``
    (:class:`~seacable.seastate.SeaComponents`, None: calm) at the times ``t`` (nt, 6) [N, N m], global axes, at
    the body's position (the sea's phases moved to its reference point); None when there is nothing."""
    h = body.hydrodynamics
    if h is None or sea is None or (not h.excitation and h.drift == "none"):
        return None
    from ..hydro.loads import first_order_force, mean_drift_force, qtf_drift_force, slow_drift_force

    db = database(body, rho, g)
    if abs(body.position[5]) > 1e-12 or abs(body.position[3]) > 1e-12 or abs(body.position[4]) > 1e-12:
        raise InputError(f"bodies.{name}: a body with hydrodynamics starts at zero roll, pitch and yaw (its database's "
                         f"axes are the global ones), got {body.position[3:]} rad. Suggested fix: give the headings "
                         "of the sea relative to the body instead.")
    x0, y0 = body.position[0], body.position[1]
    local = _moved(sea, x0, y0)
    oscillating = np.zeros((t.size, 6))
    try:
        mean = mean_drift_force(db, local) if h.drift != "none" else np.zeros(6)
        if h.excitation:
            oscillating += first_order_force(db, local, t)
        if h.drift == "newman":
            oscillating += slow_drift_force(db, local, t) - mean
        elif h.drift == "qtf":
            oscillating += qtf_drift_force(db, local, t) - mean
    except InputError as err:
        raise InputError(f"bodies.{name}.hydrodynamics: {err}") from None
    # the mean from the start (the static start's load), the rest from zero at t = 0 through the ramp
    r = smooth_ramp(t, float(h.ramp))[0] if h.ramp > 0 else (t > 0).astype(float)
    return mean + r[:, None] * oscillating


def _moved(sea, x0: float, y0: float):
    """The sea with its phases referred to the point (x0, y0): ``p + k (x0 cos b + y0 sin b)``."""
    import dataclasses

    if x0 == 0.0 and y0 == 0.0:
        return sea
    shift = sea.wave_number * (x0 * np.cos(sea.heading) + y0 * np.sin(sea.heading))
    return dataclasses.replace(sea, phase=np.mod(np.asarray(sea.phase) + shift, 2 * math.pi))


def body_wind_velocity(body: Body, wind, t: np.ndarray | None = None) -> np.ndarray | None:
    """The environment's ``wind`` (:class:`seacable.environment.Wind`) at a body's centre of pressure: its velocity
    (nt, 2) [m/s] in the global axes at the times ``t`` (the 1-hour mean of the NPD profile at the height, and the
    gusts of the wind's spectrum); ``t`` None: the mean alone (1, 2). ``None`` when the body has no wind areas or
    there is no wind."""
    if body.wind is None or wind is None or wind.speed <= 0.0:
        return None
    from ..wind import api_spectrum, gust_series, npd_profile, npd_spectrum

    z = float(body.wind.height)
    mean = float(npd_profile(wind.speed, z))  # the 1-hour mean at the centre of pressure
    if t is None or wind.spectrum == "none":
        gust = np.zeros(1 if t is None else t.size)
    else:
        if wind.spectrum == "npd":
            spectrum = lambda f: npd_spectrum(f, wind.speed, z)
        else:
            spectrum = lambda f: api_spectrum(f, wind.speed, z, wind.peak)
        gust = gust_series(spectrum, t, seed=wind.seed, n_components=wind.n_components)
    return np.outer(mean + gust, [math.cos(wind.heading), math.sin(wind.heading)])


def body_wind_loads(body: Body, name: str, wind, t: np.ndarray, rho_air: float | None = None):
    """The environment's ``wind`` on a body with wind areas, the body held at its given position: the force and
    moment (nt, 6) [N, N m] of the mean wind and its gusts (:func:`body_wind_velocity`) at the times ``t``, and the
    linear damping (6, 6) in the body's axes of the wind relative to its motion, ``-dF/dv`` at the mean wind
    (``rho_air C A U`` along the wind): the linearised loads of a frequency-domain or uncoupled model (the coupled
    dynamics take the wind's force with the instantaneous relative velocity,
    :func:`seacable.system.dynamics.body.body_load`); ``None`` when the body has no wind areas or there is no
    wind."""
    velocity = body_wind_velocity(body, wind, t)
    if velocity is None:
        return None
    from ..wind import AIR_DENSITY

    rho_air = AIR_DENSITY if rho_air is None else rho_air
    coef = body.wind.coefficients()
    yaw = float(body.position[5])
    f3 = coef.force(velocity, yaw=yaw, rho_air=rho_air)
    force = np.zeros((t.size, 6))
    force[:, [0, 1, 5]] = f3
    # the damping of the relative wind: -dF/dv at the mean wind
    damping_global = _table_damping(coef, body_wind_velocity(body, wind)[0], yaw, rho_air)
    c, s_ = math.cos(yaw), math.sin(yaw)
    rot = np.eye(6)
    rot[:2, :2] = [[c, -s_], [s_, c]]
    return force, rot.T @ damping_global @ rot


def body_current_loads(body: Body, current, pose, rho: float):
    """The environment's ``current`` (:class:`seacable.environment.Current`) on a body with current areas
    (``body.current``), the body at rest at ``pose`` (6,) [m, rad]: its force and yaw moment (6,) [N, N m], global
    axes, ``1/2 rho |u| u C(beta)`` of the current ``u`` at the reference point's depth (the surface's when the point
    is above the water) with ``beta`` its direction in the body's axes at the pose's yaw, and the linear damping
    (6, 6) [N s/m, N s] in the global axes of the current relative to the body's velocity ``v``, ``-dF/dv`` at
    ``v = 0`` (central differences of the force law; ``rho C |u|`` along the current for a table flat in heading,
    and ``1/2 rho |u| dC/dbeta`` across it): the loads the coupled step takes with the relative velocity
    (:func:`seacable.system.dynamics.body.body_load`), linearised for a frequency-domain or uncoupled model.
    ``None`` when the body has no current areas or the current is nil there.

    Parameters
    ----------
    body : Body
        With ``current`` (:class:`~seacable.system.model.BodyCurrent`).
    current : seacable.environment.Current
        The environment's current.
    pose : array_like
        The body's reference point and angles (x, y, z, roll, pitch, yaw). [m, rad]
    rho : float
        The water's density. [kg/m^3]
    """
    if body.current is None:
        return None
    pose = np.asarray(pose, float)
    u = np.asarray(current.velocity(min(float(pose[2]), 0.0)), float)[:2]
    if not np.any(u):
        return None
    coef = body.current.coefficients()
    yaw = float(pose[5])
    force = np.zeros(6)
    force[[0, 1, 5]] = coef.force(u, yaw=yaw, rho_air=rho)
    return force, _table_damping(coef, u, yaw, rho)


def _table_damping(coef, flow, yaw: float, rho: float) -> np.ndarray:
    """The linear damping (6, 6) [N s/m, N s], global axes, of a coefficient table's force ``1/2 rho |w| w C(beta)``
    on the flow ``w = flow - v`` relative to the body's velocity ``v`` (2,) [m/s]: ``-dF/dv`` at ``v = 0`` by
    central differences of the force law (steps of 1e-3 of the flow speed), in the surge, sway and yaw rows."""
    jac = np.zeros((3, 2))
    h = 1e-3 * max(float(np.hypot(*flow)), 1.0)
    for k in range(2):
        dv = np.zeros(2)
        dv[k] = h
        jac[:, k] = (coef.force(flow, body_velocity=dv, yaw=yaw, rho_air=rho)
                     - coef.force(flow, body_velocity=-dv, yaw=yaw, rho_air=rho)) / (2 * h)
    damping = np.zeros((6, 6))
    damping[np.ix_([0, 1, 5], [0, 1])] = -jac
    return damping


def area_tables(body: Body) -> tuple[int, int, np.ndarray]:
    """A body's current and wind tables as the coupled dynamics take them (:mod:`seacable.system.dynamics.body`,
    ``B_TAB``): the rows of each and the rows' values (heading in [0, 2 pi) ascending, surge, sway and yaw areas),
    the current's then the wind's, flattened."""
    rows = []
    for table in (body.current, body.wind):
        if table is None:
            rows.append(np.zeros((0, 4)))
            continue
        c = table.coefficients()
        b = np.mod(np.atleast_1d(np.asarray(c.heading, float)), 2 * math.pi)
        order = np.argsort(b)
        rows.append(np.stack([b[order]] + [np.atleast_1d(np.asarray(getattr(c, k), float))[order]
                                           for k in ("surge", "sway", "yaw")], axis=1))
    return len(rows[0]), len(rows[1]), np.concatenate(rows).ravel()

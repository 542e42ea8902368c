"""The ``lay_plan`` analysis: a case in, the lay table by KP out (an xarray Dataset, and CSV)."""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..case import Case, LayPlanAnalysis
from ..errors import InputError, SeacableWarning
from ..results import make_dataset, var
from .bathymetry import seabed_map
from .inputs import sinking_weights
from .plan import N_STATION_PROPS, S_CDN, S_CDT, S_COMPLIANCE, S_D, S_MEFF, S_MT, S_W, plan_lay

__all__ = ["LAY_TABLE_COLUMNS", "run_lay_plan", "write_lay_table", "write_repeater_table"]

_STATION_STEP = 100.0     # m, the longest step between the plan's stations (rows may be further apart)
_MIN_STATION_STEP = 5.0   # m, the shortest (rows closer together are interpolated between stations)

REFERENCES = (
    ("Zajac, E. E. (1957). Dynamics and kinematics of the laying and recovery of submarine cable. Bell System "
     "Technical Journal 36(5), 1129-1207."),
    "Paper 001 (seeds/001), section 2: straight-line laying theory, eq. (1)-(11).",
)

#: The lay table's columns, in order: name, units, long name.
LAY_TABLE_COLUMNS = (
    ("kp", "m", "ship KP"),
    ("time", "s", "time from the start of the table"),
    ("ship_speed", "m s-1", "ship speed over ground"),
    ("payout_speed", "m s-1", "payout speed"),
    ("paid_out", "m", "cable paid out from the start of the lay"),
    ("touchdown_kp", "m", "touchdown KP"),
    ("touchdown_offset", "m", "touchdown offset from the route (+ to port)"),
    ("layback", "m", "layback: horizontal distance from the water entry to the touchdown"),
    ("top_tension", "N", "tension at the water entry"),
    ("bottom_tension", "N", "tension at the touchdown"),
    ("entry_angle", "rad", "cable angle to the sea surface at the water entry"),
    ("slack", "1", "laid length over the seabed distance, minus one"),
    ("route_slack", "1", "laid length per metre of route KP, minus one"),
    ("water_depth", "m", "water depth at the ship"),
    ("touchdown_depth", "m", "water depth at the touchdown"),
    ("suspended_length", "m", "cable length from touchdown to water entry"),
    ("laid_length", "m", "cable laid from the start of the lay"),
    ("ship_x", "m", "ship x"),
    ("ship_y", "m", "ship y"),
    ("ship_heading", "rad", "ship heading (route leg), from +x towards +y"),
    ("touchdown_x", "m", "touchdown x"),
    ("touchdown_y", "m", "touchdown y"),
    ("touchdown_speed", "m s-1", "touchdown speed over the seabed"),
    ("layback_along", "m", "layback along the ship's heading"),
    ("layback_across", "m", "layback across the ship's heading (+ to port)"),
    ("span_speed", "m s-1", "ship speed over ground the span is in steady state for (the lagged speed)"),
    ("turn_rate", "rad s-1", "turn rate the span is in steady state for (+ to port: the route's curvature, spread "
                             "over the alter-course, times the speed)"),
    ("span_clearance", "m", "smallest height of the span's chord above the seabed (< 0: a ridge under it)"),
)


def _station_props(case: Case):
    """``props_at(s)``: the (n, 6) station properties of the cable at material coordinates ``s``."""
    env, line = case.environment, case.line
    rho, g = env.water_density, env.gravity
    rows, ends = [], np.cumsum([seg.length for seg in line.segments])
    for seg, w in zip(line.segments, sinking_weights(line, rho, g), strict=True):
        lt = seg.line_type
        cdn, cdt = lt.effective_drag()
        ea = lt.effective_axial_stiffness()
        row = np.zeros(N_STATION_PROPS)
        row[[S_W, S_D, S_CDN, S_CDT, S_MEFF, S_COMPLIANCE, S_MT]] = (
            w, lt.diameter, cdn, cdt, lt.mass_per_length + lt.added_mass_per_length(rho),
            0.0 if math.isinf(ea) else 1.0 / ea, lt.mass_per_length + lt.added_mass_tangential * rho * lt.area)
        rows.append(row)
    table = np.array(rows)

    def props_at(s):
        return table[np.minimum(np.searchsorted(ends, s, side="right"), len(ends) - 1)]

    return props_at


def run_lay_plan(case: Case):
    """Run a ``lay_plan`` case; see :func:`seacable.run` and :mod:`seacable.laying.plan` for the model.

    The Dataset has the dimension ``kp`` (the ship KPs of the table, every ``kp_step``, with the route's
    waypoints among them) with the columns of :data:`LAY_TABLE_COLUMNS`, the dimension ``repeater``
    (water entry and touchdown of each attachment, by ship KP and time, and where it lands), and
    ``waypoint`` (the route). Geographic routes add the latitude and longitude of ship and touchdown.
    """
    a: LayPlanAnalysis = case.analysis
    route = a.route.geometry()
    seabed = seabed_map(route, a.bathymetry, a.bathymetry_grid, case.environment.depth or math.nan)
    lo = route.kp[0] if a.kp_start is None else a.kp_start
    hi = route.kp[-1] if a.kp_end is None else a.kp_end
    for name, value in (("kp_start", a.kp_start), ("kp_end", a.kp_end)):
        if value is not None and not route.kp[0] - 1e-6 <= value <= route.kp[-1] + 1e-6:
            raise InputError(f"analysis.{name} = {value:g} m lies outside the route (KP {route.kp[0]:g} to "
                             f"{route.kp[-1]:g} m). Suggested fix: a KP on the route, or leave it out.")
    # rows every kp_step from the first (round KPs), the last, and where an alter-course starts or ends
    inner = route.turn_kp[(route.turn_kp > lo + 1e-6) & (route.turn_kp < hi - 1e-6)]
    kp = np.unique(np.concatenate([lo + a.kp_step * np.arange(math.ceil((hi - lo) / a.kp_step - 1e-9)), [hi], inner]))
    kp = kp[np.concatenate([[True], np.diff(kp) > 1e-3])]         # (an arc's end within 1 mm of a row: one row)
    # the plan is computed on stations every _STATION_STEP at most (rows further apart among them): a repeater's
    # slow-down, the span's lag and the turns' spread are shorter than a kilometre, and rows 1 km apart gave a lay
    # 10 % longer in time than rows 100 m apart; and _MIN_STATION_STEP apart at least (rows closer than that are
    # interpolated: a quasi-static plan has nothing to say between them, and rows every 0.5 m took 10 minutes)
    base = kp
    if a.kp_step < _MIN_STATION_STEP:
        base = np.unique(np.concatenate([lo + _MIN_STATION_STEP * np.arange(math.ceil((hi - lo) / _MIN_STATION_STEP
                                                                                      - 1e-9)), [hi], inner]))
        base = base[np.concatenate([[True], np.diff(base) > 1e-3])]
    fine = lo + _STATION_STEP * np.arange(math.ceil((hi - lo) / _STATION_STEP))
    i = np.clip(np.searchsorted(base, fine), 1, base.size - 1)
    fine = fine[np.minimum(np.abs(fine - base[i - 1]), np.abs(fine - base[i])) > 1e-3]   # (not within 1 mm of one)
    stations = np.union1d(base, fine)
    kp_rows, kp = kp, stations
    target = a.target.at          # by the touchdown's KP
    plan = plan_lay(route, seabed, kp, scheduled_speed=a.ship.at(kp),
                    slack=None if a.target.slack is None else target,
                    bottom_tension=None if a.target.bottom_tension is None else target,
                    props_at=_station_props(case), current=case.environment.current,
                    water_density=case.environment.water_density,
                    repeaters=[(p.name or f"repeater {i + 1}", p.s) for i, p in enumerate(case.line.attachments)],
                    repeater_speed=a.ship.repeater_speed, acceleration=a.ship.acceleration)
    cols = plan.columns
    if float(np.max(cols["paid_out"])) > case.line.length:
        i = int(np.argmax(cols["paid_out"] > case.line.length))
        raise InputError(f"the lay needs {float(np.max(cols['paid_out'])):.6g} m of cable but the line is "
                         f"{case.line.length:.6g} m long: it runs out at ship KP {kp[i]:.1f} m. Suggested fix: "
                         "make the line (the cable on board) longer, or end the table earlier (kp_end).")
    notes = list(plan.notes)
    loads = [seg.line_type.breaking_load for seg in case.line.segments if seg.line_type.breaking_load]
    if loads and float(np.nanmax(cols["top_tension"])) > min(loads):
        over = cols["top_tension"] > min(loads)
        note = (f"the top tension reaches {float(np.nanmax(cols['top_tension'])):.6g} N, over the cable's minimum "
                f"breaking load of {min(loads):.6g} N, at ship KP {kp[over][0]:.1f} to {kp[over][-1]:.1f} m: the lay "
                "as planned would break it. Suggested fix: a lower bottom tension, or a check of the line type")
        warnings.warn(f"lay plan: {note}.", SeacableWarning, stacklevel=2)
        notes.append(note)
    if a.kp_step < _MIN_STATION_STEP:
        cols = {name: np.interp(kp_rows, kp, value) for name, value in cols.items()}
    else:
        rows = np.isin(kp, kp_rows)
        cols = {name: np.asarray(value)[rows] for name, value in cols.items()}
    n_stations, kp = kp.size, kp_rows
    data = {name: var("kp", cols[name], units, long) for name, units, long in LAY_TABLE_COLUMNS if name != "kp"}
    geo = route.to_geographic(np.column_stack([cols["ship_x"], cols["ship_y"]]))
    if geo is not None:
        td = route.to_geographic(np.column_stack([cols["touchdown_x"], cols["touchdown_y"]]))
        for who, (lat, lon) in (("ship", geo), ("touchdown", td)):
            data[f"{who}_latitude"] = var("kp", lat, "degree_north", f"{who} latitude (WGS84)")
            data[f"{who}_longitude"] = var("kp", lon, "degree_east", f"{who} longitude (WGS84)")
    data.update(route.variables())
    r = plan.repeaters
    if r["name"]:
        data["repeater_name"] = var("repeater", np.array(r["name"], dtype=object), "", "repeater name")
        for key, units, long in (("s", "m", "cable length from the start of the lay"),
                                 ("entry_kp", "m", "ship KP at the repeater's water entry"),
                                 ("entry_time", "s", "time of the repeater's water entry"),
                                 ("touchdown_kp", "m", "ship KP at the repeater's touchdown"),
                                 ("touchdown_time", "s", "time of the repeater's touchdown"),
                                 ("landing_kp", "m", "KP where the repeater lands"),
                                 ("landing_offset", "m", "offset from the route where it lands (+ to port)")):
            data[f"repeater_{key}"] = var("repeater", r[key], units, long)
    coords = {"kp": var("kp", kp, "m", "ship KP")}
    settings = {"kp_step": a.kp_step, "stations": int(n_stations), "iterations": plan.iterations,
                "wall_time_s": round(plan.wall_time, 4), "target": "slack" if a.target.slack is not None else
                "bottom_tension", "notes": "; ".join(notes) or "none",
                "model": "quasi-static: the steady span at each KP (straight-line theory for zero bottom tension, "
                         "the catenary with drag under a bottom tension), in the plane of the ship's leg"}
    return make_dataset(data, coords, analysis="lay_plan", case=case, references=REFERENCES, settings=settings)


def write_lay_table(ds, path) -> None:
    """Write the lay table of a ``lay_plan`` result as CSV (atomically), headers ``name [units]``."""
    import pandas as pd

    from .._atomic import atomic_write

    names = [name for name, _, _ in LAY_TABLE_COLUMNS]
    extra = [n for n in ("ship_latitude", "ship_longitude", "touchdown_latitude", "touchdown_longitude") if n in ds]
    table = pd.DataFrame({f"{n} [{ds[n].attrs.get('units', '')}]": np.asarray(ds[n]) for n in names + extra})
    atomic_write(path, lambda tmp: table.to_csv(tmp, index=False, float_format="%.10g"))


def write_repeater_table(ds, path) -> bool:
    """Write the repeaters' events of a ``lay_plan`` result as CSV (atomically): name, cable length, water entry
    and touchdown by ship KP and time, where each lands. False (nothing written) without repeaters."""
    import pandas as pd

    from .._atomic import atomic_write

    if "repeater_name" not in ds:
        return False
    columns = {"name []": [str(v) for v in ds.repeater_name.values]}
    for key in ("s", "entry_kp", "entry_time", "touchdown_kp", "touchdown_time", "landing_kp", "landing_offset"):
        da = ds[f"repeater_{key}"]
        columns[f"{key} [{da.attrs.get('units', '')}]"] = np.asarray(da)
    table = pd.DataFrame(columns)
    atomic_write(path, lambda tmp: table.to_csv(tmp, index=False, float_format="%.10g"))
    return True

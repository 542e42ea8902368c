"""Figures of the static and modal analyses: static, pushover, modal, towed_steady, laying_theory,
vertical_modes."""

from __future__ import annotations

import numpy as np

from ._core import _degrees, _label


def _static(ds, plt):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax1.plot(ds.x, ds.z, "-", lw=1.5)
    if "seabed_z" in ds:
        ax1.axhline(float(ds.seabed_z), color="sienna", lw=1)
    ax1.axhline(0.0, color="steelblue", lw=0.8, ls="--")
    ax1.set(xlabel=_label(ds.x), ylabel=_label(ds.z), title="Static shape")
    ax1.set_aspect("equal", adjustable="datalim")
    ax2.plot(ds.s, ds.tension / 1e3)
    ax2.set(xlabel=_label(ds.s), ylabel="effective tension [kN]",
            title=f"Fairlead {float(ds.fairlead_tension) / 1e3:.1f} kN, "
                  f"anchor {float(ds.anchor_tension) / 1e3:.1f} kN")
    return {"shape": fig}


def _pushover(ds, plt):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax1.plot(ds.offset, ds.H_fairlead / 1e3, label="horizontal")
    ax1.plot(ds.offset, ds.fairlead_tension / 1e3, label="total")
    ax1.set(xlabel=_label(ds.offset), ylabel="fairlead tension [kN]", title="Force-excursion")
    ax1.legend()
    ax2.plot(ds.offset, ds.stiffness_horizontal / 1e3)
    ax2.set(xlabel=_label(ds.offset), ylabel="dH/dx [kN/m]", title="Horizontal stiffness")
    return {"pushover": fig}


def _modal(ds, plt):
    fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(15, 4.2))
    planes = ds.plane.values.astype(str)
    for plane, marker in (("in", "o"), ("out", "s")):
        keep = planes == plane
        ax1.plot(ds.mode.values[keep], ds.period.values[keep], marker, label=f"{plane}-plane")
    ax1.axhline(float(ds.wave_period), color="k", ls="--", lw=0.8, label="wave-speed estimate")
    ax1.set(xlabel="mode", ylabel=_label(ds.period), title="Natural periods")
    ax1.legend()
    span = float(np.ptp(ds.x.values)) or float(np.ptp(ds.z.values)) or 1.0
    ax2.plot(ds.x, ds.z, "k-", lw=2, label="static")
    for k in np.flatnonzero(planes == "in")[:3]:
        shp = ds.shape.isel(mode=k).values
        ax2.plot(ds.x + 0.08 * span * shp[:, 0], ds.z + 0.08 * span * shp[:, 2],
                 label=f"mode {k + 1} ({float(ds.period[k]):.2f} s)")
    ax2.set(xlabel=_label(ds.x), ylabel=_label(ds.z), title="In-plane modes")
    ax2.legend(fontsize=8)
    for k in np.flatnonzero(planes == "out")[:3]:
        ax3.plot(ds.s, ds.shape.isel(mode=k).sel(direction="y"),
                 label=f"mode {k + 1} ({float(ds.period[k]):.2f} s)")
    ax3.set(xlabel=_label(ds.s), ylabel="y displacement [-]", title="Out-of-plane modes")
    ax3.legend(fontsize=8)
    return {"modes": fig}


def _towed(ds, plt):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax1.plot(ds.x, ds.z, "o-")
    ax1.set(xlabel=_label(ds.x), ylabel=_label(ds.z),
            title=f"Steady tow, relative speed {float(ds.relative_speed):.2f} m/s")
    ax2.plot(ds.s, ds.tension, "o-")
    ax2.set(xlabel=_label(ds.s), ylabel=_label(ds.tension), title=f"Top tension {float(ds.top_tension):.1f} N")
    return {"towed": fig}


def _laying(ds, plt):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax1.plot(ds.ship_speed, _degrees(ds.angle), "o-", label="exact root")
    ax1.plot(ds.ship_speed, _degrees(ds.angle_small), "x--", label="small angle H/V")
    ax1.set(xlabel=_label(ds.ship_speed), ylabel="entry angle [deg]", title="Laying angle", ylim=(0, 90))
    ax1.legend()
    ax2.plot(ds.ship_speed, ds.layback, "o-")
    ax2.set(xlabel=_label(ds.ship_speed), ylabel=_label(ds.layback), title="Layback")
    return {"laying": fig}


def _vertical(ds, plt):
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for solution in ds.solution.values:
        ax.plot(ds.mode, ds.period.sel(solution=solution), "o-", label=str(solution))
    ax.set(xlabel="mode", ylabel=_label(ds.period), title="Vertical cable periods")
    ax.legend()
    return {"periods": fig}


STATICS_FIGURES = {
    "static": _static,
    "pushover": _pushover,
    "modal": _modal,
    "towed_steady": _towed,
    "laying_theory": _laying,
    "vertical_modes": _vertical,
}

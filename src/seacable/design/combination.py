"""The combined low-frequency (LF) and wave-frequency (WF) tension of a mooring line (issue 39), and which of
its parts a run modelled.

A line's tension in a storm is a mean (pretension, and the mean loads of wind, current and wave drift), a
low-frequency part (the slow drift and the wind's gusts near the surge, sway and yaw natural periods, 60-300 s)
and a wave-frequency part (the first-order motions, 4-25 s). The standards combine the two dynamic parts'
extremes:

- API RP 2SK (3rd ed., 2005), frequency-domain analysis: ``T_max`` is the larger of
  ``T_mean + T_lf,max + T_wf,sig`` and ``T_mean + T_lf,sig + T_wf,max``, with the significant value
  ``T_sig = 2 sigma`` and the maximum the most probable of a Rayleigh-distributed process over the storm,
  ``T_max = sigma sqrt(2 ln N)``, ``N = duration / T_z`` its cycles (:func:`api_combined_tension`).
- DNV-OS-E301 (2010) Ch.2 Sec.2 B, the characteristic tension ``T_c = T_c,mean + T_c,dyn``: the LF and WF
  processes are independent and Gaussian, so their sum is, with ``sigma^2 = sigma_lf^2 + sigma_wf^2`` and the
  up-crossing rate ``nu = sqrt(sigma_lf^2 nu_lf^2 + sigma_wf^2 nu_wf^2) / sigma`` (Rice: ``m2`` adds as ``m0``
  does); ``T_c,dyn`` is its most probable maximum ``sigma sqrt(2 ln(nu T))`` (:func:`dnv_combined_tension`),
  which :func:`seacable.design.checks.dnv_uls` takes with ``T_c,mean`` the mean from pretension, wind,
  current and drift.

In a time-domain run the record holds both parts already; :func:`split_tension` separates them by an ideal
(FFT) filter at ``split_period`` (default 30 s: above the wave periods, below the slow-drift periods), giving the
components these functions take, so that the time-domain extremes can be set beside the standards' combination.

The standards' own pages could not be read from the sources available here: the API rule is as engineering
texts and codes quote it (e.g. the TU Delft *Floating and submerged structures* notes; the MOSES RP 2SK sample),
DNV's as the Gaussian sum of independent processes; check both against the edition a project is designed to.

:func:`modelled_components` reads a run's case (the YAML stored with the result) and says which of the parts
(waves WF, LF slow drift, mean drift, wind, current) it modelled and how, for the report.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate as v
from ..errors import InputError

__all__ = ["API_COMBINATION", "DNV_COMBINATION", "SPLIT_PERIOD", "CombinedTension", "TensionComponents",
           "api_combined_tension", "combined_table", "dnv_combined_tension", "modelled_components",
           "most_probable_maximum", "split_columns", "split_tension"]

API_COMBINATION = ("API RP 2SK 3rd ed. (2005), frequency-domain analysis: T_max = max(T_mean + T_lf,max + T_wf,sig, "
                   "T_mean + T_lf,sig + T_wf,max), T_sig = 2 sigma, T_max = sigma sqrt(2 ln N)")
DNV_COMBINATION = ("DNV-OS-E301 (2010) Ch.2 Sec.2 B: T_c = T_c,mean + T_c,dyn, T_c,dyn = sigma sqrt(2 ln(nu T)) of the "
                   "Gaussian sum of the LF and WF parts, sigma^2 = sigma_lf^2 + sigma_wf^2")

#: Period separating the low-frequency from the wave-frequency tension (:func:`split_tension`). [s]
SPLIT_PERIOD = 30.0


@dataclass(frozen=True)
class TensionComponents:
    """A line tension's parts: ``mean`` [N], the standard deviations of its low- and wave-frequency parts
    ``lf_std``, ``wf_std`` [N], their mean zero up-crossing periods ``lf_period``, ``wf_period`` [s], the
    largest excursions of each part above zero over the record ``lf_max``, ``wf_max`` [N] (None: not known),
    and the record's ``duration`` [s] (None: not a record)."""

    mean: float
    lf_std: float
    wf_std: float
    lf_period: float
    wf_period: float
    lf_max: float | None = None
    wf_max: float | None = None
    duration: float | None = None


@dataclass(frozen=True)
class CombinedTension:
    """A combined extreme tension: ``mean`` [N], ``dynamic`` [N] (the extreme less the mean: DNV's
    ``T_c,dyn``), ``maximum`` [N], the ``rule`` that made it and its ``terms`` [N] by name."""

    mean: float
    dynamic: float
    maximum: float
    rule: str
    terms: dict


def most_probable_maximum(std: float, period: float, duration: float) -> float:
    """The most probable largest peak of a narrow-band Gaussian process above its mean over ``duration`` [s]:
    ``sigma sqrt(2 ln N)``, ``N = duration / period`` its cycles (Rayleigh peaks; Naess & Moan 2013, ch. 6);
    0 for a process without variance. [N]

    Raises
    ------
    InputError
        A negative or NaN standard deviation, a period or duration not > 0, fewer than 2 cycles.
    """
    s = float(v.nonnegative("std", std, "N", "give the standard deviation of the tension part"))
    if s == 0.0:
        return 0.0
    t_z = float(v.positive("period", period, "s", "give the mean zero up-crossing period of the part"))
    t = float(v.positive("duration", duration, "s", "give the storm's duration, e.g. 10800 for 3 hours"))
    n = t / t_z
    if n < 2.0:
        raise InputError(f"a storm of {t:g} s holds {n:.3g} cycles of period {t_z:g} s: too few for a most probable "
                         "maximum (2 at least). Suggested fix: give the storm's duration (10800 s for 3 hours).")
    return s * math.sqrt(2.0 * math.log(n))


def _part_max(given, std, period, duration):
    return float(given) if given is not None else most_probable_maximum(std, period, duration)


def api_combined_tension(mean: float, lf_std: float, wf_std: float, lf_period: float, wf_period: float,
                         duration: float = 10800.0, *, lf_max: float | None = None,
                         wf_max: float | None = None) -> CombinedTension:
    """API RP 2SK's combined maximum line tension of a frequency-domain analysis.

    ``T_max = max(T_mean + T_lf,max + T_wf,sig, T_mean + T_lf,sig + T_wf,max)``, with ``T_sig = 2 sigma`` and
    ``T_max = sigma sqrt(2 ln(duration / T_z))`` (:func:`most_probable_maximum`) unless the part's maximum is
    given (``lf_max``, ``wf_max``: above the mean).

    Parameters
    ----------
    mean
        Mean tension: pretension and the mean loads of wind, current and wave drift. [N]
    lf_std, wf_std
        Standard deviations of the low- and wave-frequency tension. [N]
    lf_period, wf_period
        Mean zero up-crossing periods of the two parts. [s]
    duration
        The storm's duration (API: 3 hours). [s]
    lf_max, wf_max
        The parts' maxima above the mean, when known (a time-domain record's); None: from the standard deviation.
        [N]

    Returns
    -------
    CombinedTension
        ``maximum`` T_max [N], ``dynamic`` T_max - T_mean [N], the terms ``lf_max, lf_sig, wf_max, wf_sig``.
    """
    mean = float(v.finite("mean", mean, "N", "give the mean tension in N"))
    lf_sig, wf_sig = 2.0 * float(lf_std), 2.0 * float(wf_std)
    lf_m = _part_max(lf_max, lf_std, lf_period, duration)
    wf_m = _part_max(wf_max, wf_std, wf_period, duration)
    dyn = max(lf_m + wf_sig, lf_sig + wf_m)
    return CombinedTension(mean, dyn, mean + dyn, API_COMBINATION,
                           {"lf_max": lf_m, "lf_sig": lf_sig, "wf_max": wf_m, "wf_sig": wf_sig})


def dnv_combined_tension(mean: float, lf_std: float, wf_std: float, lf_period: float, wf_period: float,
                         duration: float = 10800.0) -> CombinedTension:
    """DNV-OS-E301's characteristic tension from independent Gaussian LF and WF parts.

    ``sigma = sqrt(sigma_lf^2 + sigma_wf^2)``, the up-crossing rate ``nu = sqrt(sigma_lf^2 / T_lf^2 +
    sigma_wf^2 / T_wf^2) / sigma``, ``T_c,dyn = sigma sqrt(2 ln(nu duration))`` and ``T_c = T_c,mean + T_c,dyn``:
    give ``mean`` and ``dynamic`` to :func:`seacable.design.checks.dnv_uls`.

    Parameters
    ----------
    mean, lf_std, wf_std, lf_period, wf_period, duration
        As :func:`api_combined_tension`. [N, s]

    Returns
    -------
    CombinedTension
        ``dynamic`` T_c,dyn [N], ``maximum`` T_c [N], the terms ``std`` sigma [N] and ``period`` 1/nu [s].
    """
    mean = float(v.finite("mean", mean, "N", "give the mean tension in N"))
    s_lf = float(v.nonnegative("lf_std", lf_std, "N", "give the LF standard deviation"))
    s_wf = float(v.nonnegative("wf_std", wf_std, "N", "give the WF standard deviation"))
    sigma = math.hypot(s_lf, s_wf)
    if sigma == 0.0:
        return CombinedTension(mean, 0.0, mean, DNV_COMBINATION, {"std": 0.0, "period": math.nan})
    rate2 = 0.0
    for s, t, name in ((s_lf, lf_period, "lf_period"), (s_wf, wf_period, "wf_period")):
        if s > 0.0:
            rate2 += (s / float(v.positive(name, t, "s", "give the part's mean zero up-crossing period"))) ** 2
    period = sigma / math.sqrt(rate2)
    dyn = most_probable_maximum(sigma, period, duration)
    return CombinedTension(mean, dyn, mean + dyn, DNV_COMBINATION, {"std": sigma, "period": period})


def _zero_crossing_period(spectrum: np.ndarray, omega: np.ndarray) -> float:
    m0 = float(np.sum(spectrum))
    m2 = float(np.sum(spectrum * omega ** 2))
    return 2.0 * math.pi * math.sqrt(m0 / m2) if m0 > 0.0 and m2 > 0.0 else math.nan


def split_tension(tension, time, split_period: float = SPLIT_PERIOD) -> TensionComponents:
    """A tension record's mean and its low- and wave-frequency parts, split by an ideal filter.

    The record (uniform time step) is Fourier transformed; components of period longer than ``split_period``
    are the LF part, the others the WF part. Each part's standard deviation and mean zero up-crossing period
    (``2 pi sqrt(m0 / m2)`` of its periodogram) and its largest value over the record are returned.

    Parameters
    ----------
    tension
        The tension record. [N]
    time
        Its times, equally spaced. [s]
    split_period
        The period between LF and WF (default :data:`SPLIT_PERIOD`, 30 s). [s]

    Returns
    -------
    TensionComponents

    Raises
    ------
    InputError
        Records of different lengths or under 8 samples, a non-uniform time step, non-finite values, a record
        shorter than two split periods.
    """
    t = np.asarray(time, float).ravel()
    x = np.asarray(tension, float).ravel()
    if t.size != x.size or t.size < 8:
        raise InputError(f"the tension record ({x.size} samples) and its times ({t.size}) must have the same length, "
                         "8 samples at least. Suggested fix: give one line's record and the result's time.")
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(t))):
        raise InputError("the tension record holds non-finite values. Suggested fix: give the record of a completed "
                         "run (an interrupted result holds NaN after its end).")
    dt = np.diff(t)
    if not (dt[0] > 0 and np.allclose(dt, dt[0], rtol=1e-6, atol=0.0)):
        raise InputError(f"the times must be equally spaced and increasing (steps from {dt.min():g} to {dt.max():g} "
                         "s). Suggested fix: give the result's output times (a constant output interval).")
    split = float(v.positive("split_period", split_period, "s", "give the period between LF and WF, e.g. 30"))
    duration = float(t[-1] - t[0] + dt[0])
    if duration < 2.0 * split:
        raise InputError(f"the record lasts {duration:g} s, under two split periods ({split:g} s): its low-frequency "
                         "part cannot be told. Suggested fix: a longer record (a 3-hour storm), or a shorter "
                         "split_period.")
    mean = float(x.mean())
    spec = np.fft.rfft(x - mean)
    freq = np.fft.rfftfreq(x.size, dt[0])  # [Hz]
    low = (freq > 0.0) & (freq < 1.0 / split)
    high = freq >= 1.0 / split
    parts, stats_ = {}, {}
    for name, mask in (("lf", low), ("wf", high)):
        part = np.fft.irfft(np.where(mask, spec, 0.0), n=x.size)
        power = np.abs(np.where(mask, spec, 0.0)) ** 2
        parts[name] = part
        stats_[name] = (float(part.std()), _zero_crossing_period(power, 2.0 * math.pi * freq), float(part.max()))
    (lf_std, lf_t, lf_max), (wf_std, wf_t, wf_max) = stats_["lf"], stats_["wf"]
    return TensionComponents(mean, lf_std, wf_std, lf_t, wf_t, lf_max, wf_max, duration)


# ------------------------------------------------------------------------------------ what a run modelled

def _nonzero(values) -> bool:
    try:
        return any(abs(float(x)) > 0.0 for x in values or ())
    except (TypeError, ValueError):
        return False


def modelled_components(case: dict | None) -> list[dict]:
    """Which parts of a mooring's load a run modelled, read from its case (the mapping stored with the result).

    Returns
    -------
    list of dict
        One per component, in order: ``waves (WF)``, ``LF slow drift``, ``mean wave drift``, ``wind``,
        ``current``; each with ``status`` ("modelled", "steady only" or "NOT MODELLED") and ``how`` (one line).
        A case that cannot be read gives every status "unknown".
    """
    names = ("waves (WF)", "LF slow drift", "mean wave drift", "wind", "current")
    if not isinstance(case, dict):
        return [{"component": n, "status": "unknown", "how": "the result stores no case"} for n in names]
    env = case.get("environment") or {}
    waves = env.get("waves") or {}
    bodies = {k: b for k, b in (case.get("bodies") or {}).items() if isinstance(b, dict)}
    motions = ((case.get("analysis") or {}).get("body_motions") or {})
    hydro = {k: b["hydrodynamics"] for k, b in bodies.items()
             if isinstance(b.get("hydrodynamics"), dict) and b.get("kind", "free") == "free"}
    steady = [k for k, b in bodies.items() if _nonzero((b.get("external_force") or ())[:3])]
    irregular = isinstance(waves, dict) and "spectrum" in waves
    regular = isinstance(waves, dict) and not irregular and _nonzero([waves.get("height", 0.0)])
    out = []
    if irregular or regular:
        sea = (f"irregular sea Hs {waves.get('hs')} m, Tp {waves.get('tp')} s ({waves.get('spectrum')})" if irregular
               else f"regular wave H {waves.get('height')} m, T {waves.get('period')} s")
        drivers = []
        if motions:
            drivers.append("prescribed body motions (" + ", ".join(
                f"{k}: {m.get('type', '?')}" for k, m in motions.items() if isinstance(m, dict)) + ")")
        if any(h.get("excitation", True) for h in hydro.values()):
            drivers.append("first-order wave forces on free bodies (hydrodynamic database)")
        drivers.append("wave kinematics on the lines")
        out.append({"component": names[0], "status": "modelled", "how": f"{sea}; " + "; ".join(drivers)})
    else:
        out.append({"component": names[0], "status": "NOT MODELLED", "how": "no waves in the case"})
    newman = [k for k, h in hydro.items() if h.get("drift", "newman") == "newman"]
    qtf = [k for k, h in hydro.items() if h.get("drift") == "qtf"]
    mean_drift = [k for k, h in hydro.items() if h.get("drift", "newman") in ("mean", "newman", "qtf")]
    if (newman or qtf) and irregular:
        how = "; ".join(([f"Newman's slow drift on {', '.join(newman)}"] if newman else [])
                        + ([f"the full QTF's slow drift on {', '.join(qtf)}"] if qtf else []))
        out.append({"component": names[1], "status": "modelled", "how": f"{how} (hydrodynamic database)"})
    else:
        why = ("the bodies follow prescribed (RAO) motions: first order only" if motions and not hydro else
               "no free body with a hydrodynamic database and drift: newman or qtf in an irregular sea")
        out.append({"component": names[1], "status": "NOT MODELLED",
                    "how": f"{why}; the slow drift near the surge, sway and yaw periods is missing from the "
                           "extremes (non-conservative)"})
    wind = env.get("wind") or {}
    wind_bodies = [k for k, b in bodies.items() if b.get("wind")]
    if mean_drift and (irregular or regular):
        out.append({"component": names[2], "status": "modelled",
                    "how": f"mean drift of {', '.join(mean_drift)} from the database"})
    elif steady:
        out.append({"component": names[2], "status": "steady only",
                    "how": f"within the constant external force on {', '.join(steady)} (a given total)"})
    else:
        out.append({"component": names[2], "status": "NOT MODELLED", "how": "no drift force on the bodies"})
    if isinstance(wind, dict) and _nonzero([wind.get("speed", 0.0)]) and wind_bodies:
        gust = wind.get("spectrum", "npd")
        out.append({"component": names[3], "status": "modelled" if gust != "none" else "steady only",
                    "how": f"{wind.get('speed')} m/s at 10 m on {', '.join(wind_bodies)}"
                           + (f", {gust} gust spectrum" if gust != "none" else ", no gusts")})
    elif steady:
        out.append({"component": names[3], "status": "steady only",
                    "how": f"within the constant external force on {', '.join(steady)}: no gusts"})
    else:
        out.append({"component": names[3], "status": "NOT MODELLED", "how": "no wind on the bodies"})
    current = env.get("current") or {}
    flowing = isinstance(current, dict) and (_nonzero([current.get("speed", 0.0)]) or _nonzero(current.get("speeds")))
    if flowing:
        hulls = [k for k, b in bodies.items() if b.get("current") or b.get("quadratic_damping")]
        on = "the lines" + (f" and {', '.join(hulls)} (current areas or quadratic drag)" if hulls else "")
        out.append({"component": names[4], "status": "modelled", "how": f"current drag on {on}"})
    elif steady:
        out.append({"component": names[4], "status": "steady only",
                    "how": f"within the constant external force on {', '.join(steady)}; none on the lines"})
    else:
        out.append({"component": names[4], "status": "NOT MODELLED", "how": "no current in the case"})
    return out


# ------------------------------------------------------------------------------------ the design tables' part

def split_columns(record, time, split_period: float = SPLIT_PERIOD) -> dict:
    """The seed table's LF/WF columns of one record (:func:`split_tension`): ``lf_std, wf_std [N], lf_period,
    wf_period [s]``, NaN where the record is too short to split."""
    try:
        c = split_tension(record, time, split_period)
    except InputError:
        return {"lf_std": math.nan, "wf_std": math.nan, "lf_period": math.nan, "wf_period": math.nan}
    return {"lf_std": c.lf_std, "wf_std": c.wf_std, "lf_period": c.lf_period, "wf_period": c.wf_period}


_COMBINED_COLUMNS = ["load_case", "line", "seeds", "storm", "mean", "lf_std", "wf_std", "lf_period", "wf_period",
                     "api_maximum", "dnv_dynamic", "dnv_maximum", "time_domain_maximum", "note"]


def combined_table(seeds, extremes, storm_duration: float | None = None):
    """Per load case and line (fairlead), the LF/WF parts (the seeds' mean of :func:`split_columns`) and the
    standards' combined maxima over the storm (:func:`api_combined_tension`, :func:`dnv_combined_tension`),
    beside the time-domain design maximum of ``extremes``.

    Returns
    -------
    pandas.DataFrame
        Columns ``load_case, line, seeds, storm [s], mean [N], lf_std [N], wf_std [N], lf_period [s], wf_period
        [s], api_maximum [N], dnv_dynamic [N], dnv_maximum [N], time_domain_maximum [N], note``.
    """
    import pandas as pd

    rows = []
    fair = seeds[seeds["end"] == "fairlead"]
    for (load_case, line), g in fair.groupby(["load_case", "line"], sort=False):
        storm = float(g["duration"].mean()) if storm_duration is None else float(storm_duration)
        e = extremes[(extremes["load_case"] == load_case) & (extremes["line"] == line)
                     & (extremes["end"] == "fairlead")]
        row = {"load_case": load_case, "line": line, "seeds": len(g), "storm": storm,
               "mean": float(g["mean"].mean()), "time_domain_maximum": float(e["design_maximum"].iloc[0])
               if len(e) else math.nan, "note": ""}
        for k in ("lf_std", "wf_std", "lf_period", "wf_period"):
            row[k] = float(g[k].mean()) if k in g and g[k].notna().all() else math.nan
        try:
            if math.isnan(row["lf_std"]):
                raise InputError("the records are too short to split at the LF/WF period "
                                 f"({SPLIT_PERIOD:g} s): two split periods at least")
            parts = (row["mean"], row["lf_std"], row["wf_std"], row["lf_period"], row["wf_period"], storm)
            api, dnv = api_combined_tension(*parts), dnv_combined_tension(*parts)
            row.update(api_maximum=api.maximum, dnv_dynamic=dnv.dynamic, dnv_maximum=dnv.maximum)
        except InputError as err:
            row.update(api_maximum=math.nan, dnv_dynamic=math.nan, dnv_maximum=math.nan,
                       note="not combined: " + str(err).split(" Suggested fix:")[0])
        rows.append(row)
    return pd.DataFrame(rows, columns=_COMBINED_COLUMNS)

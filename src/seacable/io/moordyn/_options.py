"""A MoorDyn deck's OPTIONS and OUTPUTS: their values, checks, and a note for each option seacable cannot
honour."""

from __future__ import annotations

import re
import warnings

from ... import _validate
from ..._model import suggest
from ...errors import SeacableWarning
from ._records import (
    _CBOT,
    _CFL,
    _DEPTH,
    _DT,
    _FRIC_DAMP,
    _FRIC_SCALE,
    _G,
    _KBOT,
    _MU,
    _MU_A,
    _MU_T,
    _RHO,
    _lookup,
)
from ._sections import _as_float, _strip_comment


def _read_options(rd, section) -> dict[str, float | str]:
    options: dict[str, float | str] = {}
    for lineno, line in section[3]:
        tokens = _strip_comment(line).split()
        if not tokens:
            continue
        if len(tokens) < 2:
            raise rd.error(lineno, f"an option line must be 'value name [comment]', got "
                                   f"{line.strip()!r}. Suggested fix: write the value, then the option "
                                   "name (e.g. '100 WtrDpth').")
        value = _as_float(tokens[0])
        if value is None and _as_float(tokens[1]) is not None:
            # the OPTIONS rows' order is 'value name': MoorDyn reads the first word as the value, whatever it is
            warnings.warn(f"{rd.label}:{lineno}: the OPTIONS row {line.strip()!r} gives a name then a number, but "
                          f"MoorDyn reads options as 'value name': it takes {tokens[0]!r} as the value of an option "
                          f"named {tokens[1]!r}, and so does seacable (an option it does not know: ignored). Suggested "
                          f"fix: write '{tokens[1]} {tokens[0]}'.", SeacableWarning, stacklevel=4)
        _check_option(rd, lineno, tokens[1], tokens[0], value)
        options[tokens[1]] = tokens[0] if value is None else value
        rd.option_lines[tokens[1]] = lineno
    return options


_OPTION_CHECKS = {  # name (lower case): (check, unit, fix)
    **{k.lower(): (_validate.positive, "m", ("give the water depth as a positive number of metres, or remove "
                   "the line (MoorDyn then takes the depth of the deepest point)")) for k in _DEPTH},
    # MoorDyn's own tests switch gravity or buoyancy off with 0: read, and refused by the models that need them
    **{k.lower(): (_validate.nonnegative, "kg/m^3", "give the water density, e.g. 1025") for k in _RHO},
    **{k.lower(): (_validate.nonnegative, "m/s^2", "give g in m/s^2, e.g. 9.80665") for k in _G},
    **{k.lower(): (_validate.nonnegative, "Pa/m", "give the seabed stiffness per contact area, e.g. 3e6")
       for k in _KBOT},
    **{k.lower(): (_validate.nonnegative, "Pa s/m", "give the seabed damping per contact area, e.g. 3e5")
       for k in _CBOT},
    **{k.lower(): (_validate.positive, "s", "give the mooring time step in seconds, e.g. 0.001") for k in _DT},
    **{k.lower(): (_validate.positive, "", "give a CFL factor such as 0.5") for k in _CFL},
    **{k.lower(): (_validate.nonnegative, "", "give a friction coefficient >= 0, e.g. 0.5")
       for k in _MU + _MU_T + _MU_A},
    **{k.lower(): (_validate.nonnegative, "N s/m", "give the friction damping scale, default 200")
       for k in _FRIC_DAMP},
    **{k.lower(): (_validate.positive, "", "give the static/dynamic friction ratio, default 1")
       for k in _FRIC_SCALE},
    **{k.lower(): (_validate.nonnegative, "", "give a whole number: 0 (none) or a MoorDyn mode")
       for k in ("WaveKin", "Currents")},
    **{k.lower(): (_validate.nonnegative, "s", "give a time in seconds")
       for k in ("dtWave", "waveKin_rampT", "dtIC", "ICdt", "TmaxIC", "ICTmax", "dtOut", "inertialF_rampT")},
    **{k.lower(): (_validate.positive, "", "give a positive number") for k in ("CdScaleIC", "ICDfac")},
    **{k.lower(): (_validate.nonnegative, "", "give a number >= 0") for k in ("threshIC", "ICthresh")},
}
_WHOLE = {"wavekin", "currents"}

# Options that only steer MoorDyn's own numerics (explicit time integration, the dynamic-relaxation
# start, coupled-body inertia) or its own files and console: they do not change the mooring problem.
# seacable solves the static equilibrium by Newton's method and integrates in time with an implicit
# Newmark scheme at the time step the user gives (``--time-step``), so they need no counterpart.
_NUMERICS = {k.lower() for k in ("dtM", "DT", "cfl", "tScheme", "dtIC", "ICdt", "TmaxIC", "ICTmax",
                                 "CdScaleIC", "ICDfac", "threshIC", "ICthresh", "ICgenDynamic", "fileIC",
                                 "inertialF", "inertialF_rampT", "writeLog", "WriteUnits", "dtOut",
                                 "disableOutput", "disableOutTime", "OutSwitch", "Echo")}
# Options honoured by the model (``moordyn_model``) or read with the waves they belong to.
_MODEL = {k.lower() for k in _DEPTH + _RHO + _G + _KBOT + _CBOT + _MU + _MU_T + _MU_A + _FRIC_DAMP + _FRIC_SCALE
          + ("WaveKin", "Currents", "WaterKin", "dtWave", "waveKin_rampT", "UnifyCurrentGrid", "SeafloorFile")}
_KNOWN_OPTIONS = ("WtrDpth", "WtrDnsty", "rhoW", "g", "kBot", "cBot", "FrictionCoefficient", "FricDamp",
                  "StatDynFricScale", "mu_kT", "mu_kA", "MC", "CV", "WaveKin", "Currents", "WaterKin", "dtWave",
                  "waveKin_rampT", "UnifyCurrentGrid", "SeafloorFile", "dtM", "cfl", "tScheme", "dtIC",
                  "TmaxIC", "CdScaleIC", "threshIC", "ICgenDynamic", "fileIC", "inertialF", "inertialF_rampT",
                  "writeLog", "WriteUnits", "dtOut", "disableOutput", "disableOutTime", "OutSwitch")


def _check_option(rd, lineno, name, token, value):
    key = name.lower()
    if key not in _OPTION_CHECKS:
        return
    check, unit, fix = _OPTION_CHECKS[key]
    if value is None:
        why = (" (MoorDyn-F reads a bathymetry file here; seacable has a flat seabed and does not read it)"
               if key in {k.lower() for k in _DEPTH} else "")
        raise rd.error(lineno, f"option {name} must be a number in {unit or 'SI units'}, got {token!r}{why}. "
                               f"Suggested fix: {fix}.")
    rd.check(lineno, check, f"option {name}", value, unit, fix)
    if key in _WHOLE and value != int(value):
        raise rd.error(lineno, f"option {name} must be a whole number, got {token!r}. Suggested fix: {fix}.")


def _fmt_value(value) -> str:
    return f"{value:g}" if isinstance(value, float) else repr(value)


def _option_notes(rd, options: dict, depth: float | None, depth_source: str) -> list[str]:
    """What seacable does about each option it cannot honour (see :class:`MoorDynInput` ``notes``)."""
    notes = []
    seabed = (f"a flat seabed at z = {-depth:g} m ({depth_source})" if depth is not None else "no seabed")
    for name, value in options.items():
        key = name.lower()
        if key in _NUMERICS or key in _MODEL:
            continue
        hint = suggest(name, _KNOWN_OPTIONS)
        notes.append(f"{rd.at(name)}option {name} = {_fmt_value(value)} is not a MoorDyn option seacable knows; it is "
                     f"ignored.{hint}")
    wave_kin = _lookup(options, ("WaveKin",))
    if wave_kin:
        notes.append(f"{rd.at('WaveKin')}option WaveKin = {wave_kin:g} asks MoorDyn for wave kinematics (from its wave files or "
                     "a coupled code); seacable runs this file in still water for its statics (as MoorDyn finds its "
                     "initial conditions) and refuses a dynamic run of it. Suggested fix: for waves (regular, or "
                     "an irregular sea from a spectrum) write the mooring as a YAML case with environment.waves.")
    currents = _lookup(options, ("Currents",))
    if currents:
        notes.append(f"{rd.at('Currents')}option Currents = {currents:g} asks MoorDyn for a current read from its current files; "
                     "seacable runs this file without current for its statics and refuses a dynamic run of it. "
                     "Suggested fix: for a current profile write the mooring as a YAML case with environment.current.")
    water_kin = _lookup(options, ("WaterKin",))
    if water_kin is not None and str(water_kin).strip("\"'").lower() not in ("", "unused", "none", "0"):
        notes.append(f"{rd.at('WaterKin')}option WaterKin = {_fmt_value(water_kin)} (MoorDyn-F water kinematics) is not read; "
                     "seacable runs this file in still water.")
    floor = _lookup(options, ("SeafloorFile",))
    if floor is not None:
        notes.append(f"{rd.at('SeafloorFile')}option SeafloorFile = {_fmt_value(floor)} (a 3-D bathymetry) is not read; seacable uses "
                     f"{seabed}.")
    mu = _lookup(options, _MU)
    mu_t, mu_a = _lookup(options, _MU_T), _lookup(options, _MU_A)
    if mu is not None and (mu_t is not None or mu_a is not None):
        notes.append(f"{rd.at('mu_kT')}options mu_kT/mu_kA (MoorDyn-F) are ignored: FrictionCoefficient = {mu:g} is used for "
                     "the seabed friction.")
    elif (mu_t is not None or mu_a is not None) and (mu_t or 0.0) != (mu_a or 0.0):
        mu_t, mu_a = mu_t or 0.0, mu_a or 0.0  # MoorDyn-F's default for either is 0
        notes.append(f"{rd.at('mu_kT' if _lookup(options, _MU_T) is not None else 'mu_kA')}options mu_kT = "
                     f"{mu_t:g} and mu_kA = {mu_a:g} (MoorDyn-F's default 0 where not given) give different "
                     "transverse and axial seabed friction; seacable's seabed friction is isotropic and uses "
                     f"their mean, {(mu_t + mu_a) / 2:g}.")
    friction = mu if mu is not None else max(v for v in (mu_t, mu_a, 0.0) if v is not None)
    damp = [(n, v) for n, v in options.items() if n.lower() in {k.lower() for k in _FRIC_DAMP}]
    if friction > 0 and damp:
        name, value = damp[-1]
        notes.append(f"{rd.at(name)}option {name} = {value:g} (MoorDyn's friction ramp, F = mu * {name} * |v| up to mu N) "
                     "is not used: seacable applies Coulomb friction mu N regularised over 0.01 m/s of "
                     "sliding speed.")
    scale = [(n, v) for n, v in options.items() if n.lower() in {k.lower() for k in _FRIC_SCALE}]
    if friction > 0 and scale and scale[-1][1] != 1.0:
        name, value = scale[-1]
        notes.append(f"{rd.at(name)}option {name} = {value:g} (static/dynamic friction ratio) is not used: seacable's "
                     "static and dynamic friction coefficients are equal (ratio 1).")
    return notes


def _read_outputs(section) -> tuple[str, ...]:
    names = []
    for _, line in section[3]:
        for token in re.split(r"[\s,]+", _strip_comment(line).strip()):
            token = token.strip("\"'")
            if token:
                names.append(token)
    return tuple(names)

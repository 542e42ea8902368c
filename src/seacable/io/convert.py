"""A MoorDyn deck as a seacable case file, and a case file as a MoorDyn deck (``seacable convert``).

Deck -> case (:func:`deck_to_yaml`): the deck's mooring system (:func:`seacable.io.moordyn.moordyn_system`: points
``point<ID>``, lines ``line<ID>``, bodies ``body<ID>``) as a ``system_static`` case, written minimal: no nulls, no
value equal to its default, the line types once under ``line_types``, SI numbers. A deck of lines and points is
solved with its lines' NumSegs lumped-mass elements (``statics: finite_element``, ``n_elements``), as
``seacable run deck.txt`` solves it, so the case gives the deck's numbers; a deck with bodies or rods keeps the system
statics ``seacable run`` gives it. What the deck sets and a case file has no place for (MoorDyn's time step and
initial-condition settings, the axial damping BA, the soft seabed kBot/cBot, the output channels) is listed in
comments at the top of the file.

Case -> deck (:func:`case_to_deck`): a ``SystemCase``'s line types, bodies, points and lines as a MoorDyn v2 deck
(bodies and points numbered 1, 2, ... in the case's order, a point on a body ``Body<N>`` at its position in body axes;
line ``<i>`` in its order; the outputs FairTen and AnchTen of every line). A body is a MoorDyn body row
(:mod:`seacable.io.convert_bodies`: mass, centre of gravity, inertia, volume, drag areas, added mass; free, fixed,
prescribed as Coupled) when it has nothing a row cannot hold. Refused, each with what to change: a body's
hydrodynamic database, waterplane or hydrostatic stiffness (MoorDyn bodies have none), centre of buoyancy off its
reference point, wind or current areas, damping or added mass a row cannot hold, external force (the module says
which), lines of several sections or with attachments (clump weights,
buoyancy modules), ends held in bending, line types with a weight in water of their own or a nonlinear or
viscoelastic EA, points with an external force, and an environment with current, waves, wind or a sloping seabed.
The deck's time step ``dtM`` is a tenth of the shortest segment's axial wave time; ``threshIC`` 1e-7 (``TmaxIC``
500 s) has MoorDyn relax its initial condition to the statics to 7 digits (its default, 0.01, stops 1e-4 short). MoorDyn's axial damping BA
has no counterpart in a case: the deck gets ``BA = -1`` (a critically damped segment
axial mode, which MoorDyn's own examples use; it damps the dynamics only, not the statics), said in its title lines.

References
----------
.. [1] MoorDyn v2 input file format: ``docs/inputs.rst`` of https://github.com/FloatingArrayDesign/MoorDyn (BSD-3).
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import yaml

from .._atomic import atomic_write
from ..errors import InputError
from .convert_bodies import BODY_HEADER, body_point_attachment, deck_bodies

__all__ = ["case_to_deck", "convert", "deck_to_yaml"]

#: MoorDyn's axial damping written into a converted deck: -zeta, the segment's axial mode critically damped
DECK_AXIAL_DAMPING = -1.0

_YAML_SUFFIXES = (".yaml", ".yml")


# ------------------------------------------------------------------------------------------------ deck -> case

class _Dumper(yaml.SafeDumper):
    """Lists of numbers on one line (``position: [0.0, 0.0, -5.0]``), the rest in block style."""


def _list(dumper, data):
    flow = all(isinstance(v, (int, float, str)) for v in data)
    return dumper.represent_sequence("tag:yaml.org,2002:seq", data, flow_style=flow)


_Dumper.add_representer(list, _list)


def _minimal(full, short):
    """``short`` (the defaults left out) with the discriminators (``type``) of ``full`` put back, nested."""
    if isinstance(full, dict) and isinstance(short, dict):
        out = {}
        if "type" in full and "type" not in short:
            out["type"] = full["type"]
        for k, v in short.items():
            out[k] = _minimal(full.get(k), v) if k in full else v
        return out
    if isinstance(full, list) and isinstance(short, list) and len(full) == len(short):
        return [_minimal(f, s) for f, s in zip(full, short)]
    return short


def _shared_line_types(data: dict) -> None:
    """Lines of one section without attachments as ``line_type: NAME, length: L``, their types under ``line_types``."""
    types = data.setdefault("line_types", {})
    for line in data.get("lines", {}).values():
        spec = line.get("line")
        if not isinstance(spec, dict) or set(spec) != {"segments"} or len(spec["segments"]) != 1:
            continue
        seg = spec["segments"][0]
        if set(seg) != {"line_type", "length"}:
            continue
        lt = dict(seg["line_type"])
        name = lt.pop("name", None)
        if name is None or types.get(name, lt) != lt:
            continue
        types[name] = lt
        del line["line"]
        rest = dict(line)
        line.clear()
        line.update({"line_type": name, "length": seg["length"], **rest})
    if not types:
        del data["line_types"]


def _comment(lines) -> str:
    return "".join(f"# {ln}".rstrip() + "\n" for ln in lines)


def _left_out(md) -> list[str]:
    """What the deck sets that the case file has no place for, one line each."""
    out = []
    honoured = {"wtrdpth", "depth", "waterdepth", "wtrdnsty", "rho", "rhow", "g", "gravity", "frictioncoefficient"}
    numerics = [f"{k} {v}" for k, v in md.options.items() if k.lower() not in honoured]
    if numerics:
        out.append(f"MoorDyn options: {', '.join(numerics)}: MoorDyn's own numerics and output (seacable solves the "
                   "statics by Newton's method and steps its dynamics at analysis.time_step).")
    bas = sorted({f"{lt.name} {lt.axial_damping:g}" for lt in md.line_types.values()})
    if bas:
        out.append(f"BA/-zeta of the line types ({', '.join(bas)}): MoorDyn's axial damping, not in a case file (a "
                   "system_dynamic analysis takes damping_ratio or rayleigh).")
    out.append(f"kBot {md.kbot:g} Pa/m, cBot {md.cbot:g} Pa s/m: MoorDyn's soft seabed; the system statics hold the "
               "line on a rigid one (a system_dynamic analysis takes seabed_contact).")
    if md.outputs:
        out.append(f"OUTPUTS {' '.join(md.outputs)}: 'seacable export RESULT.nc --format moordyn' writes MoorDyn's "
                   ".out files of a result.")
    if md.failures:
        out.append(f"FAILURE: {len(md.failures)} row(s): a system_dynamic analysis's 'failures'.")
    out.extend(md.notes)
    return out


def deck_to_yaml(path) -> str:
    """A MoorDyn deck as the text of a minimal seacable case file (the module's mapping).

    Parameters
    ----------
    path : path-like
        The MoorDyn input file.

    Returns
    -------
    str
        The YAML text, comments first.

    Raises
    ------
    InputError
        What :func:`seacable.io.moordyn.read_moordyn` and :func:`seacable.io.moordyn.moordyn_system` refuse.
    """
    from .. import __version__
    from .moordyn import load_moordyn_case

    path = Path(path)
    with warnings.catch_warnings():  # the notes are written into the file as comments
        warnings.simplefilter("ignore")
        deck = load_moordyn_case(path)
        case = deck.system_case()
    network = not deck.has_structures
    if network:  # the deck's lumped-mass lines, as 'seacable run deck.txt' solves them
        case = case.model_copy(update={"analysis": case.analysis.model_copy(update={"statics": "finite_element"})})
    case = case.model_copy(update={"description": f"MoorDyn file {path.name}, converted by seacable convert"})
    full = case.model_dump(mode="json")
    data = _minimal(full, case.model_dump(mode="json", exclude_defaults=True, exclude_none=True))
    data = {"name": case.name, **{k: v for k, v in data.items() if k != "name"}}
    _shared_line_types(data)
    order = ("name", "description", "line_types", "environment", "bodies", "points", "lines", "analysis")
    data = {k: data[k] for k in order if k in data} | {k: v for k, v in data.items() if k not in order}
    head = [(f"{case.name}: the MoorDyn file {path.name} as a seacable case file (seacable {__version__}, "
             "'seacable convert'). Units: SI (m, kg, N, s, rad)."),
            *(f"deck title: {t}" for t in deck.data.title.splitlines() if t.strip() and "---" not in t),
            ("statics: finite_element with each line's NumSegs as n_elements: the deck's lumped-mass lines, the "
             "numbers 'seacable run' gives the deck." if network else
             "the deck has bodies or rods: 'seacable run' runs it as this mooring system."),
            "", "Left out (no counterpart in a case file):", *(f"- {t}" for t in _left_out(deck.data))]
    return _comment(head) + yaml.dump(data, Dumper=_Dumper, sort_keys=False, width=110)


# ------------------------------------------------------------------------------------------------ case -> deck

def _refuse(what: str, fix: str):
    raise InputError(f"{what}: MoorDyn cannot express it. Suggested fix: {fix}.")


def _deck_line_type(name: str, lt, rho: float, g: float) -> str:
    if lt.tension_strain is not None or lt.dynamic_axial_stiffness is not None:
        _refuse(f"line type '{name}' has a nonlinear or viscoelastic axial stiffness",
                "give it a constant axial_stiffness, or write its table into the deck by hand")
    if lt.weight_in_water is not None:
        own = (lt.mass_per_length - rho * math.pi * lt.diameter ** 2 / 4) * g
        if not math.isclose(lt.weight_in_water, own, rel_tol=1e-9, abs_tol=1e-9):
            _refuse(f"line type '{name}' has weight_in_water {lt.weight_in_water:g} N/m, MoorDyn takes (m - rho pi "
                    f"d^2 / 4) g = {own:g} N/m from its diameter and mass",
                    "leave out weight_in_water, or set diameter to the volume-equivalent one")
    cd, ca = getattr(lt, "drag_normal", 1.2), getattr(lt, "added_mass_normal", 1.0)
    return (f"{name:<12} {lt.diameter!r:<10} {lt.mass_per_length!r:<10} {lt.axial_stiffness!r:<14} "
            f"{DECK_AXIAL_DAMPING!r:<8} {lt.bending_stiffness!r:<10} {cd!r:<6} {ca!r:<6} {lt.drag_tangential!r:<6} "
            f"{lt.added_mass_tangential!r}")


def _time_step(case) -> float:
    """MoorDyn's ``dtM`` for a converted deck: a tenth of the shortest time an axial wave takes to cross a segment,
    ``l / sqrt(EA / m)``, rounded down to one significant figure (MoorDyn's own default from its CFL factor can be
    several times that and blows a stiff chain up). [s]"""
    times = []
    for line in case.lines.values():
        seg = line.line.segments[0]
        lt = seg.line_type
        n = seg.n_elements or line.n_elements
        times.append(seg.length / n / math.sqrt(lt.axial_stiffness / lt.mass_per_length))
    dt = 0.1 * min(times, default=0.01)
    scale = 10.0 ** math.floor(math.log10(dt))
    return math.floor(dt / scale) * scale


def _same_type(a, b) -> bool:
    return a.model_dump(exclude={"name"}) == b.model_dump(exclude={"name"})


def case_to_deck(case) -> str:
    """A system case as the text of a MoorDyn v2 deck (the module's mapping).

    Raises
    ------
    InputError
        A case or a part of it MoorDyn cannot express, naming it and what to change.
    """
    from ..system.case import SystemCase

    if not isinstance(case, SystemCase):
        _refuse(f"case '{case.name}' is a single-line case ({case.analysis.type})",
                "write it as a system case (points, lines) to convert it to a MoorDyn deck")
    env = case.environment
    rho, g = env.water_density, env.gravity
    rows_bodies, body_number = deck_bodies(case)
    cur = env.current
    if getattr(cur, "speed", 0.0) or getattr(cur, "speeds", None):
        _refuse("environment.current", "remove the current (MoorDyn takes currents from its own water-kinematics "
                                       "files)")
    for key in ("waves", "wind"):
        if getattr(env, key, None) is not None:
            _refuse(f"environment.{key}", f"remove environment.{key}")
    bed = env.seabed
    if getattr(bed, "slope", 0.0) or getattr(bed, "profile", None) is not None:
        _refuse("environment.seabed (a slope or a profile)", "use a flat seabed (MoorDyn's is flat at WtrDpth, or "
                                                             "a bathymetry file written by hand)")
    types: dict[str, object] = {}
    rows_lines = []
    number = {name: k + 1 for k, name in enumerate(case.points)}
    for k, (name, line) in enumerate(case.lines.items(), start=1):
        segments = line.line.segments
        if len(segments) != 1 or line.line.attachments:
            _refuse(f"line '{name}' has {len(segments)} sections and {len(line.line.attachments)} attachments",
                    "give the line one line type and no attachments (MoorDyn's lines are uniform)")
        for end in ("a", "b"):
            cond = getattr(line, f"end_{end}_condition")
            if cond != type(cond)():
                _refuse(f"line '{name}' end {end.upper()} is held in bending ({cond})",
                        "leave the end pinned (MoorDyn v2's line ends are pinned)")
        seg = segments[0]
        lt = seg.line_type
        lt_name = lt.name or next((n for n, t in case.line_types.items() if _same_type(t, lt)), f"type{len(types) + 1}")
        if types.get(lt_name, lt) != lt:
            lt_name = f"{lt_name}_{k}"
        types[lt_name] = lt
        n = seg.n_elements or line.n_elements
        rows_lines.append(f"{k:<4} {lt_name:<12} {number[line.end_a]:<8} {number[line.end_b]:<8} {seg.length!r:<12} "
                          f"{n:<8} -")
    rows_points = []
    for name, p in case.points.items():
        if any(p.external_force):
            _refuse(f"point '{name}' has an external force {tuple(p.external_force)} N",
                    "leave out external_force (MoorDyn's 12-column POINTS layout is MoorDyn-F's only)")
        kind = ({"fixed": "Fixed", "coupled": "Coupled", "free": "Free"}.get(p.kind)
                or body_point_attachment(name, p, body_number))
        ca = p.added_mass / (rho * p.volume) if p.volume > 0 else 0.0
        if p.added_mass > 0 and not p.volume > 0:
            _refuse(f"point '{name}' has added_mass {p.added_mass:g} kg and no volume: MoorDyn's Ca is per displaced "
                    "volume", "give the point its volume")
        x, y, z = (float(v) for v in p.position)
        rows_points.append(f"{number[name]:<4} {kind:<10} {x!r:<12} {y!r:<12} {z!r:<12} {p.mass!r:<10} "
                           f"{p.volume!r:<10} {p.drag_area!r:<10} {ca!r}")
    options = [f"{_time_step(case)!r:<14} dtM       time step (s): a tenth of the shortest segment's axial wave time",
               "1.0e-7         threshIC  initial condition converged to 1e-7 (-): the statics to 7 digits",
               "500.0          TmaxIC    longest dynamic relaxation of the initial condition (s)",
               f"{rho!r:<14} WtrDnsty  water density (kg/m^3)", f"{g!r:<14} g         gravity (m/s^2)"]
    if env.depth is not None:
        options.append(f"{float(env.depth)!r:<14} WtrDpth   water depth (m)")
    friction = float(getattr(bed, "friction", 0.0) or 0.0)
    if friction:
        options.append(f"{friction!r:<14} FrictionCoefficient  seabed friction (-)")
    outputs = " ".join([f"FairTen{k}" for k in range(1, len(rows_lines) + 1)]
                       + [f"AnchTen{k}" for k in range(1, len(rows_lines) + 1)])
    rule = "-" * 20
    text = [f"{rule} MoorDyn Input File {rule}",
            f"{case.name}: converted from a seacable case by 'seacable convert'. SI units.",
            f"BA/-zeta {DECK_AXIAL_DAMPING:g}: MoorDyn's axial damping (a case has none); it damps the dynamics only.",
            f"{rule} LINE TYPES {rule}",
            "TypeName     Diam       Mass/m     EA             BA/-zeta EI         Cd     Ca     CdAx   CaAx",
            "(name)       (m)        (kg/m)     (N)            (N-s/-)  (N-m^2)    (-)    (-)    (-)    (-)",
            *(_deck_line_type(n, lt, rho, g) for n, lt in types.items()),
            *([f"{rule} BODIES {rule}", *BODY_HEADER, *rows_bodies] if rows_bodies else []),
            f"{rule} POINTS {rule}",
            "ID   Attachment X            Y            Z            Mass       Volume     CdA        Ca",
            "(#)  (-)        (m)          (m)          (m)          (kg)       (m^3)      (m^2)      (-)",
            *rows_points,
            f"{rule} LINES {rule}",
            "ID   LineType     AttachA  AttachB  UnstrLen     NumSegs  LineOutputs",
            "(#)  (name)       (#)      (#)      (m)          (-)      (-)",
            *rows_lines,
            f"{rule} OPTIONS {rule}",
            *options,
            f"{rule} OUTPUTS {rule}",
            outputs,
            f"{rule} need this line {rule}"]
    return "\n".join(text) + "\n"


# ------------------------------------------------------------------------------------------------ the command

def convert(source, output) -> Path:
    """``seacable convert``: a MoorDyn deck into a case file (``output`` .yaml/.yml), or a case file into a deck.

    Returns the path written (atomically).

    Raises
    ------
    InputError
        A source that is neither, an output of the wrong kind (a deck converted into a .txt), or what
        :func:`deck_to_yaml` and :func:`case_to_deck` refuse.
    """
    from .case_file import load_case
    from .moordyn import is_moordyn_file

    source, output = Path(source), Path(output)
    if not source.is_file():
        raise InputError(f"convert: source '{source}' is not a file. Suggested fix: give a MoorDyn input file or a "
                         "seacable case file (.yaml).")
    if output.exists() and output.is_dir():
        raise InputError(f"convert: -o '{output}' is a folder. Suggested fix: give the file to write.")
    if output.resolve() == source.resolve():
        raise InputError(f"convert: -o '{output}' is the source itself. Suggested fix: write to another file.")
    to_case = is_moordyn_file(source)
    if to_case and output.suffix.lower() not in _YAML_SUFFIXES:
        raise InputError(f"convert: {source} is a MoorDyn file, so -o must be a case file (.yaml), got '{output}'. "
                         f"Suggested fix: -o {output.with_suffix('.yaml').name}.")
    if not to_case and output.suffix.lower() in _YAML_SUFFIXES:
        raise InputError(f"convert: {source} is a case file, so -o is the MoorDyn deck to write, got the case file "
                         f"'{output}'. Suggested fix: -o {output.with_suffix('.txt').name}.")
    text = deck_to_yaml(source) if to_case else case_to_deck(load_case(source))
    output.parent.mkdir(parents=True, exist_ok=True)
    return atomic_write(output, lambda tmp: Path(tmp).write_text(text), "the converted file")

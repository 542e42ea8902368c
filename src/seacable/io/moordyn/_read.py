"""Read a MoorDyn deck (:func:`read_moordyn`), recognise one (:func:`is_moordyn_file`), and refuse the water
kinematics a dynamic run cannot honour (:func:`check_water_kinematics`)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

from ..._model import suggest
from ...errors import InputError
from . import _cabledyn
from ._options import _fmt_value, _option_notes, _read_options, _read_outputs
from ._records import MoorDynInput, _lookup
from ._sections import (
    _UNSUPPORTED,
    _check_column_order,
    _load,
    _Reader,
    _section_kind,
    _split_sections,
    _table,
)
from ._tables import (
    _integer,
    _read_bodies,
    _read_external_loads,
    _read_failures,
    _read_line_types,
    _read_lines,
    _read_points,
    _read_rod_types,
    _read_rods,
)


def read_moordyn(path_or_text, *, name=None) -> MoorDynInput:
    """Read a MoorDyn v2 (or v1) input file: every section (line and rod types, bodies, rods, points, lines,
    failures, external loads, options, outputs).

    Parameters
    ----------
    path_or_text : str or pathlib.Path
        A path to the file, or the file's text (a string containing a newline).
    name : str, optional
        The name used for the file in error messages (default: the path, or ``<MoorDyn text>``).

    Returns
    -------
    MoorDynInput
        The file's contents in SI units, with convenience properties for the options.

    Raises
    ------
    InputError
        With the file, line number, what was wrong, what was expected and a fix: a missing
        LINE TYPES/POINTS/LINES section; a row with too few columns; a value that is not a
        number; an unknown line type, rod type, point, body or rod ID; a duplicate line,
        body or rod ID; a non-positive diameter, mass, EA or length; fewer than one segment, or
        more than memory allows (see :mod:`seacable._limits`); a line whose two ends are one
        point; an empty LINE TYPES, POINTS or LINES section (without bodies or rods); rows in
        CONTROL; a strain-tension or Syrope file that is missing or not increasing; a BA or EI
        table; an unknown point, body or rod attachment; a failure at a point its lines do not
        end at; a point below a given ``WtrDpth``; an option value out of range or not a number.

    Warns
    -----
    SeacableWarning
        When point IDs are not 1..N in file order (MoorDyn and seacable number the points by
        position), or when a section seacable does not know has rows. Options seacable cannot
        honour are not warned here but listed in :attr:`MoorDynInput.notes`, for the model.

    References
    ----------
    .. [1] MoorDyn-C ``source/MoorDyn2.cpp`` (``ReadInFile``), FloatingArrayDesign/MoorDyn.
    """
    text, path, label = _load(path_or_text, name)
    rd = _Reader(label, Path(path).parent if path else None)
    title, echo, sections = _split_sections(rd, text)
    cable = _cabledyn.is_cabledyn(sections)  # CableDyn's cable extensions (SECTIONS and the rest)
    for kind, header in (("equivalent_buoyancy", "EQUIVALENT BUOYANCY"), ("end_connections", "END CONNECTIONS")):
        if kind in sections and not cable and _table(rd, sections[kind])[1]:
            raise rd.error(sections[kind][1], f"a {header} section (CableDyn's) in a deck without a SECTIONS table. "
                                              "Suggested fix: give the lines' sections in SECTIONS, as CableDyn's "
                                              "cable decks do.")
    for kind, header in _UNSUPPORTED.items():
        if kind in sections:
            _, rows = _table(rd, sections[kind])
            if rows:
                raise rd.error(rows[0][0], f"the {header} section has {len(rows)} row(s); seacable does not read "
                                           f"MoorDyn-F's {header} (OpenFAST-coupled). Suggested fix: remove the "
                                           f"{header} section, or give the loads as body external forces in a "
                                           "seacable system case.")
    rod_types = _read_rod_types(rd, sections["rod_types"]) if "rod_types" in sections else {}
    bodies, _ = _read_bodies(rd, sections["bodies"]) if "bodies" in sections else ([], {})
    body_ids = {b.id: b for b in bodies}
    rods, _ = _read_rods(rd, sections["rods"], rod_types, body_ids) if "rods" in sections else ([], {})
    rod_ids = {r.id: r for r in rods}
    structures = bool(bodies or rods)
    required = (("line_types", "LINE TYPES"), ("points", "POINTS"), ("lines", "LINES"))
    for kind, header in required:
        if kind not in sections and not (structures and (kind != "line_types" or "lines" not in sections)):
            raise rd.error(None, f"the file must have a {header} section (a line of dashes containing "
                                 f"'{header}'), found none. Suggested fix: check that this is a MoorDyn "
                                 "input file and that the section header is spelled as MoorDyn expects.")
    types = _read_line_types(rd, sections["line_types"], cable) if "line_types" in sections else {}
    if "points" in sections and (sections["points"][3] or not structures):
        _, point_rows = _table(rd, sections["points"])
        if point_rows or not structures:
            points, point_lines = _read_points(rd, sections["points"], short=cable)
        else:
            points, point_lines = [], {}
    else:
        points, point_lines = [], {}
    by_id = {p.id: p for p in points}
    for p in points:
        if p.attachment == "body" and p.body not in body_ids:
            raise rd.error(point_lines[p.id], f"point {p.id} is on body {p.body}, which is not in the BODIES "
                                              f"section (IDs {', '.join(str(b) for b in body_ids) or 'none'}). "
                                              "Suggested fix: add the body or correct the attachment.")
    cable_sections = _cabledyn.read_cable_sections(rd, sections["cable_sections"], types) if cable else None
    lines = (_read_lines(rd, sections["lines"], types, by_id, rod_ids, cable_sections)
             if "lines" in sections and (sections["lines"][3] or not structures)
             and (_table(rd, sections["lines"])[1] or not structures) else [])
    if "attachments" in sections:
        lines = _cabledyn.read_attachments(rd, sections["attachments"], lines)
    failures = _read_failures(rd, sections["failure"], by_id, rod_ids, lines) if "failure" in sections else []
    loads = (_read_external_loads(rd, sections["external_loads"], by_id, body_ids, rod_ids)
             if "external_loads" in sections else [])
    if "syrope_wc" in sections:
        names, rows = _table(rd, sections["syrope_wc"])
        _check_column_order(rd, sections["syrope_wc"], names, "syrope_wc")
        for lineno, t in rows:
            rd.columns(lineno, t, 4, "SYROPE WORKING CURVES", "LineType WCType k1 k2")
            if t[0] not in types:
                raise rd.error(lineno, f"SYROPE WORKING CURVES names line type {t[0]!r}, which is not in LINE TYPES."
                                       f"{suggest(t[0], types)} Suggested fix: use a line type's name.")
            if t[1].upper() not in ("LINEAR", "QUADRATIC", "EXP"):
                raise rd.error(lineno, f"SYROPE WORKING CURVES WCType must be LINEAR, QUADRATIC or EXP, got {t[1]!r}. "
                                       "Suggested fix: use one of MoorDyn's Syrope working curves.")
            k1, k2 = (rd.number(lineno, v, f"SYROPE WORKING CURVES {c}", "-") for v, c in zip(t[2:4], ("k1", "k2")))
            types[t[0]] = dataclasses.replace(types[t[0]], syrope=(t[1].upper(), k1, k2))
    for name, lineno in rd.syrope_types.items():
        if types[name].syrope is None:
            raise rd.error(lineno, f"line type {name!r} is a Syrope rope whose file is its original working curve, "
                                   "but no SYROPE WORKING CURVES row gives its working curve. Suggested fix: add a row "
                                   f"'{name} LINEAR k1 k2' to a SYROPE WORKING CURVES section.")
    syrope_ic = {}
    if "syrope_ic" in sections:
        names, rows = _table(rd, sections["syrope_ic"])
        _check_column_order(rd, sections["syrope_ic"], names, "syrope_ic")
        for lineno, t in rows:
            rd.columns(lineno, t, 3, "SYROPE IC", "Line(s) Tmax0 Tmean0")
            tmax, tmean = (rd.number(lineno, v, f"SYROPE IC {c}", "N") for v, c in zip(t[1:3], ("Tmax0", "Tmean0")))
            for token in t[0].split(","):
                syrope_ic[_integer(rd, lineno, token, "SYROPE IC line")] = (tmax, tmean)
    if cable and "options" in sections:
        sections["options"] = _cabledyn.cabledyn_options(rd, sections["options"])
    options = _read_options(rd, sections["options"]) if "options" in sections else {}
    if echo is not None:
        options.setdefault("Echo", echo)
    outputs = _read_outputs(sections["outputs"]) if "outputs" in sections else ()
    lowered = [n.lower() for n in _table(rd, sections["line_types"])[0]] if "line_types" in sections else []
    line_names = _table(rd, sections["lines"])[0] if "lines" in sections else []
    v1 = (rd.v1_counts or ("ei" not in lowered and ("can" in lowered or "cdn" in lowered or len(lowered) == 9))
          or (len(line_names) > 2 and "len" in line_names[2].lower()))  # v1 LINE PROPERTIES columns
    result = MoorDynInput(path, "\n".join(title), types, tuple(points), tuple(lines), options, outputs,
                          rod_types=rod_types, bodies=tuple(bodies), rods=tuple(rods), failures=tuple(failures),
                          layout="v1" if v1 else "v2", external_loads=tuple(loads),
                          syrope_ic=syrope_ic)
    if "end_connections" in sections:
        ends = _cabledyn.read_end_connections(rd, sections["end_connections"], {ln.id for ln in lines})
        result = dataclasses.replace(result, end_connections=ends)
    if "equivalent_buoyancy" in sections:
        result = dataclasses.replace(result, line_types=_cabledyn.apply_equivalent_buoyancy(
            rd, sections["equivalent_buoyancy"], types, result.water_density, result.gravity))
    given = result.given_water_depth
    if given is not None:
        for p in points:
            if p.attachment in ("fixed", "free", "vessel") and p.position[2] < -given * (1.0 + 1e-9):
                raise rd.error(point_lines[p.id], f"point {p.id} Z must be >= -WtrDpth = {-given:g} m, "
                                                  f"got {p.position[2]:g} m (below the seabed; MoorDyn would "
                                                  f"move the seabed down to it with a warning). Suggested fix: "
                                                  f"raise the point, set WtrDpth to at least "
                                                  f"{-p.position[2]:g} m, or remove the WtrDpth line (the "
                                                  "depth is then that of the deepest point, as in MoorDyn).")
        source = "WtrDpth"
    else:
        globals_ = [p for p in points if p.attachment in ("fixed", "free", "vessel")]
        if globals_:
            deepest = min(globals_, key=lambda p: p.position[2])
            source = f"no WtrDpth: the depth of the deepest point, point {deepest.id}, as in MoorDyn"
        else:
            source = "no WtrDpth: the depth of the deepest rod end, as in MoorDyn"
    rd.notes.extend(_option_notes(rd, options, result.water_depth, source))
    return dataclasses.replace(result, notes=tuple(rd.notes))


def is_moordyn_file(path) -> bool:
    """Cheap sniff: is ``path`` a MoorDyn text input file?

    True when the file is text (no NUL bytes) and one of its first 40 lines is a MoorDyn
    section header (a line of dashes naming LINE TYPES, LINE DICTIONARY, POINTS, ...), or one
    of its first 5 lines mentions ``MoorDyn``. False for YAML/JSON case files, MoorDyn's binary
    ``.ic`` state files, directories and missing files.
    """
    path = Path(path)
    if path.suffix.lower() in (".yaml", ".yml", ".json", ".nc", ".ic") or not path.is_file():
        return False
    try:
        with path.open("rb") as handle:
            head = handle.read(8192)
    except OSError:
        return False
    if b"\x00" in head:
        return False
    lines = head.decode("utf-8", errors="replace").splitlines()[:40]
    if any("---" in ln and _section_kind(ln) in ("line_types", "points", "lines") for ln in lines):
        return True
    return any("MoorDyn" in ln and not ln.lstrip().startswith("#") for ln in lines[:5])


def check_water_kinematics(md: MoorDynInput, what: str = "a dynamic run") -> None:
    """Refuse a time-domain run of a deck that asks MoorDyn for wave or current kinematics.

    Non-zero ``WaveKin`` and ``Currents`` make MoorDyn take the water kinematics from its own input files
    (wave elevation series, frequency components, a current profile on a grid) or from a coupled code
    through its API; seacable reads none of them. Statics does not need them (MoorDyn's initial
    conditions are found in still water), so only a dynamic run is refused.

    Raises
    ------
    InputError
        Naming the file, the option and its value, and how to give the sea to seacable instead.
    """
    label = md.path or "MoorDyn file"
    for name, fix in (("WaveKin", "give the waves in a YAML case, environment.waves: regular (height, period) or "
                                  "irregular (spectrum: jonswap, hs, tp, gamma, seed), or set WaveKin to 0 to run "
                                  "the deck in still water"),
                      ("Currents", "give the current in a YAML case (environment.current: speed or depths and "
                                   "speeds), or set Currents to 0 to run the deck without current")):
        value = _lookup(md.options, (name,))
        if value not in (None, 0, 0.0):
            raise InputError(f"{label}: option {name} = {_fmt_value(value)} asks MoorDyn for "
                             f"{'wave' if name == 'WaveKin' else 'current'} kinematics from its own input files or "
                             f"a coupled code, which seacable does not read, so {what} of this file cannot honour "
                             f"it. Suggested fix: {fix}.")

"""The rows of a MoorDyn deck's tables as records: line types (constant, viscoelastic, table and Syrope EA),
points, lines, rod types, bodies, rods, failures and external loads."""

from __future__ import annotations

import math
import re
import warnings

from ... import _limits, _validate
from ..._model import suggest
from ..._text import read_text_file
from ...errors import InputError, SeacableWarning
from ._records import (
    MoorDynBody,
    MoorDynExternalLoad,
    MoorDynFailure,
    MoorDynLine,
    MoorDynLineType,
    MoorDynPoint,
    MoorDynRod,
    MoorDynRodType,
)
from ._sections import _ATTACH, _as_float, _check_column_order, _key, _strip_comment, _table


def _coefficient(rd, lineno, type_name, token, column, unit):
    value = _as_float(token)
    if value is None:
        if "|" in token or "." in token or "/" in token or "\\" in token or token[:1].isalpha():
            raise rd.error(lineno, f"line type {type_name!r} column {column} must be a constant in "
                                   f"{unit}, got {token!r}, a nonlinear table (file name or '|' list) "
                                   "that seacable does not read for this column. Suggested fix: replace it with a "
                                   f"constant {column} (e.g. the secant value at the working tension).")
        raise rd.error(lineno, f"line type {type_name!r} column {column} must be a finite number in "
                               f"{unit}, got {token!r}. Suggested fix: write a plain number in SI units.")
    return value


def _bar_values(rd, lineno, type_name, token, column, unit, counts):
    """The numbers of a MoorDyn '|' list (``EA_s|EA_d``), each checked; ``counts`` the allowed lengths."""
    parts = token.split("|")
    if len(parts) not in counts:
        raise rd.error(lineno, f"line type {type_name!r} column {column} must hold "
                               f"{' or '.join(str(c) for c in counts)} values separated by '|', got {token!r}. "
                               f"Suggested fix: write {column} as MoorDyn v2 does, e.g. EA_s|EA_d or "
                               "EA_s|EA_Dc|EA_D_Lm for the viscoelastic model (docs/inputs.rst of MoorDyn).")
    return [rd.number(lineno, v, f"line type {type_name!r} {column} value {k + 1} of {token!r}", unit)
            for k, v in enumerate(parts)]


def _syrope(rd, lineno, type_name, token):
    """A Syrope configuration file (``value key`` lines: OWC table path relative to the deck, WCType, k1,
    k2): ((WCType, k1, k2), OWC path, OWC table)."""
    if rd.folder is None or not (rd.folder / token).is_file():
        raise rd.error(lineno, f"line type {type_name!r} names the Syrope file {token!r}, which is not a file"
                               f"{'' if rd.folder is None else f' (looked for {rd.folder / token})'}. Suggested fix: "
                               "put it next to the deck and read the deck from its file.")
    values, numeric = {}, 0
    for line in read_text_file(rd.folder / token, "Syrope file").splitlines():
        tokens = _strip_comment(line).split()
        if len(tokens) >= 2:
            values[tokens[1].upper()] = tokens[0]
            numeric += _as_float(tokens[0]) is not None and _as_float(tokens[1]) is not None
    if "OWC" not in values and numeric >= 2:
        # the other MoorDyn Syrope syntax: the file is the original working curve itself, and the working
        # curve comes from the SYROPE WORKING CURVES section (filled in by read_moordyn)
        return None, token, _tension_strain_table(rd, lineno, type_name, token)
    missing = [k for k in ("OWC", "WCTYPE", "K1", "K2") if k not in values]
    if missing:
        raise InputError(f"{rd.folder / token}: the Syrope file must give OWC, WCType, k1 and k2 as 'value key' "
                         f"lines; {', '.join(missing)} missing. Suggested fix: follow MoorDyn's Syrope input format.")
    wc = values["WCTYPE"].upper()
    if wc not in ("LINEAR", "QUADRATIC", "EXP"):
        raise InputError(f"{rd.folder / token}: WCType must be LINEAR, QUADRATIC or EXP, got {values['WCTYPE']!r}. "
                         "Suggested fix: use one of MoorDyn's Syrope working curves.")
    k1, k2 = (rd.number(lineno, values[k], f"line type {type_name!r} Syrope {k.lower()}", "N") for k in ("K1", "K2"))
    table = _tension_strain_table(rd, lineno, type_name, values["OWC"])
    return (wc, k1, k2), values["OWC"], table


def _tension_strain_table(rd, lineno, type_name, token):
    """A MoorDyn nonlinear EA: a file of (strain, tension) rows next to the deck, read and checked.

    MoorDyn-C (``getCoefficientOrCurve``) reads two numbers per line and skips lines that do not
    start with numbers (titles, column names, units); seacable does the same.
    """
    if rd.folder is None:
        raise rd.error(lineno, f"line type {type_name!r} EA names the table file {token!r}, but the deck was "
                               "given as text, so there is no folder to find it in. Suggested fix: read the "
                               "deck from its file, next to the table.")
    path = rd.folder / token
    if not path.is_file():
        raise rd.error(lineno, f"line type {type_name!r} EA names the strain-tension table {token!r}, which is "
                               f"not a file (looked for {path}). Suggested fix: put the table next to the deck, "
                               "or write a constant EA in N.")
    rows = []
    for k, line in enumerate(read_text_file(path, "strain-tension table").splitlines(), start=1):
        tokens = _strip_comment(line).split()
        if len(tokens) < 2 or _as_float(tokens[0]) is None:
            continue
        strain, tension = _as_float(tokens[0]), _as_float(tokens[1])
        if tension is None:
            raise InputError(f"{path}:{k}: the tension of a strain-tension row must be a finite number in N, got "
                             f"{tokens[1]!r}. Suggested fix: write 'strain tension' per line.")
        rows.append((k, strain, tension))
    if len(rows) < 2:
        raise InputError(f"{path}: a strain-tension table needs at least 2 rows of 'strain tension', found "
                         f"{len(rows)}. Suggested fix: give the curve from strain 0 up to the largest strain "
                         "expected.")
    for (k0, e0, t0), (k1, e1, t1) in zip(rows, rows[1:]):
        if e1 <= e0 or t1 < t0:
            raise InputError(f"{path}:{k1}: the strain-tension table must have increasing strain and non-decreasing "
                             f"tension, got ({e1:g}, {t1:g} N) after ({e0:g}, {t0:g} N) at line {k0}. Suggested "
                             "fix: sort the rows by strain; a softening rope curve is not supported.")
    if rows[0][1] < 0 or rows[0][2] < 0:
        raise InputError(f"{path}:{rows[0][0]}: the strain-tension table must start at strain >= 0 and tension "
                         f">= 0, got ({rows[0][1]:g}, {rows[0][2]:g} N). Suggested fix: start the table at (0, 0).")
    for k, strain, _ in rows:
        if strain > MAX_TABLE_STRAIN:
            raise InputError(f"{path}:{k}: strain {strain:g} ({100 * strain:g} %) in a strain-tension table: no mooring "
                             f"line stretches beyond {MAX_TABLE_STRAIN:g} (nylon breaks near 0.3-0.4, steel near "
                             "0.05). Suggested fix: give strain as a fraction (0.02 for 2 %), not in per cent.")
    if rows[-1][2] <= 0:
        raise InputError(f"{path}:{rows[-1][0]}: the strain-tension table's tension stays 0 N up to strain "
                         f"{rows[-1][1]:g}: the line has no axial stiffness. Suggested fix: give the tension (N) at "
                         "each strain.")
    return tuple((e, t) for _, e, t in rows)


#: Largest strain of a strain-tension table: a line stretched to twice its length. [-]
MAX_TABLE_STRAIN = 1.0


def _empty(rd, section, header, row):
    _, header_no, _, _ = section
    return rd.error(header_no, f"the {header} section has no rows; a MoorDyn file needs at least one. "
                               f"Suggested fix: add a row '{row}' after its column-names and units lines.")


def _read_line_types(rd, section, cable=False) -> dict[str, MoorDynLineType]:
    names, rows = _table(rd, section)
    lowered = [n.lower() for n in names]
    # a CableDyn deck's LINE TYPES header selects its column order (its doc/driver_format.md): its decks write
    # Cd_n Cd_t Ca_n Ca_t after EI, MoorDyn's order being Cd Ca CdAx CaAx
    swapped = cable and [_key(n) for n in names[6:10]] == ["cdn", "cdt", "can", "cat"]
    v1 = not swapped and "ei" not in lowered and ("can" in lowered or "cdn" in lowered or len(names) == 9)
    layout = ("name d m EA BA/-zeta Can Cat Cdn Cdt" if v1
              else "name d m EA BA EI Cd_n Cd_t Ca_n Ca_t" if swapped
              else "name d m EA BA/-zeta EI Cd Ca CdAx CaAx")
    if not swapped:
        _check_column_order(rd, section, names, "line_types_v1" if v1 else "line_types")
    if not rows:
        raise _empty(rd, section, "LINE TYPES", layout)
    out: dict[str, MoorDynLineType] = {}
    for lineno, t in rows:
        rd.columns(lineno, t, 9 if v1 else 10, "LINE TYPES", layout)
        name = t[0]
        if name in out:
            raise rd.error(lineno, f"line type {name!r} is defined twice. Suggested fix: give each "
                                   "line type its own name.")
        d = rd.number(lineno, t[1], f"line type {name!r} Diam (diameter)", "m")
        m = rd.number(lineno, t[2], f"line type {name!r} MassDen (mass per length)", "kg/m")
        table = dynamic = ba_dynamic = table_file = syrope = None
        if t[3].upper().startswith("SYROPE:"):  # MoorDyn's Syrope polyester model: SYROPE:file|EA_Dc|EA_D_Lm
            parts = t[3][7:].split("|")
            if len(parts) != 3:
                raise rd.error(lineno, f"line type {name!r} EA {t[3]!r} must be SYROPE:<file>|EA_Dc|EA_D_Lm. "
                                       "Suggested fix: write it as MoorDyn's Syrope documentation does.")
            dynamic = tuple(rd.number(lineno, v, f"line type {name!r} Syrope {c}", u)
                            for v, c, u in zip(parts[1:], ("EA_Dc", "EA_D_Lm"), ("N", "-")))
            syrope, table_file, table = _syrope(rd, lineno, name, parts[0])
            rd.syrope_types[name] = lineno
            e_last, t_last = table[-1]
            ea = t_last / e_last
        elif "|" in t[3]:  # viscoelastic (MoorDyn v2): EA_s|EA_d or EA_s|EA_Dc|EA_D_Lm
            ea, *dyn = _bar_values(rd, lineno, name, t[3], "EA", "N", (2, 3))
            dynamic = tuple(dyn)
            for label, value in zip(("EA_d" if len(dyn) == 1 else "EA_Dc", "EA_D_Lm"), dyn):
                rd.check(lineno, _validate.nonnegative, f"line type {name!r} {label}", value,
                         "N" if label != "EA_D_Lm" else "", "give the dynamic stiffness of the viscoelastic model")
        elif _as_float(t[3]) is None and not v1 and (t[3][:1].isalpha() or "." in t[3] or "/" in t[3]):
            table = _tension_strain_table(rd, lineno, name, t[3])
            table_file = t[3]
            e_last, t_last = table[-1]
            ea = t_last / e_last if e_last > 0 else 0.0  # secant EA at the table's end
        else:
            ea = _coefficient(rd, lineno, name, t[3], "EA", "N")
        if "|" in t[4]:  # viscoelastic: BA_s|BA_d (BA_s may be -zeta)
            ba, ba_dynamic = _bar_values(rd, lineno, name, t[4], "BA/-zeta", "N s (or -zeta)", (2,))
            rd.check(lineno, _validate.nonnegative, f"line type {name!r} BA_d (dynamic damping)", ba_dynamic,
                     "N s", "give the dynamic damping in N s (MoorDyn takes no damping ratio here)")
        else:
            ba = _coefficient(rd, lineno, name, t[4], "BA/-zeta", "N s (or -zeta)")
        if v1:
            ei = 0.0
            can, cat, cdn, cdt = (rd.number(lineno, t[k], f"line type {name!r} {c}", "-")
                                  for k, c in zip(range(5, 9), ("Can", "Cat", "Cdn", "Cdt")))
        else:
            ei = _coefficient(rd, lineno, name, t[5], "EI", "N m^2")
            cdn, can, cdt, cat = (rd.number(lineno, t[k], f"line type {name!r} {c}", "-")
                                  for k, c in zip(range(6, 10), ("Cd", "Ca", "CdAx", "CaAx")))
            if swapped:  # CableDyn's Cd_n Cd_t Ca_n Ca_t
                can, cdt = cdt, can
            if len(t) > 10:  # MoorDyn v2.3+: optional Cl dF cF (vortex-induced vibration)
                cl = rd.number(lineno, t[10], f"line type {name!r} Cl (VIV lift coefficient)", "-")
                if cl != 0:
                    rd.notes.append(f"{rd.label}:{lineno}: line type {name!r} Cl = {cl:g} asks for MoorDyn's "
                                    "vortex-induced vibration lift; seacable has no VIV model and runs the line "
                                    "without it.")
        rd.check(lineno, _validate.positive, f"line type {name!r} Diam (diameter)", d, "m",
                 "give the volume-equivalent diameter in metres")
        rd.check(lineno, _validate.positive, f"line type {name!r} MassDen (mass per length)", m, "kg/m",
                 "give the mass per metre in air in kg/m")
        rd.check(lineno, _validate.positive, f"line type {name!r} EA", ea, "N",
                 "give the axial stiffness EA in newtons")
        rd.check(lineno, _validate.nonnegative, f"line type {name!r} EI", ei, "N m^2",
                 "give the bending stiffness in N m^2, or 0")
        for label, value in (("Cd", cdn), ("Ca", can), ("CdAx", cdt), ("CaAx", cat)):
            rd.check(lineno, _validate.nonnegative, f"line type {name!r} {label}", value, "",
                     "hydrodynamic coefficients are >= 0")
        out[name] = MoorDynLineType(name, d, m, ea, ba, ei, cdn, can, cdt, cat, table, dynamic, ba_dynamic,
                                    table_file, syrope)
    return out


def _attachment(rd, lineno, word, point_id) -> tuple[str, int | None]:
    """A POINTS attachment: (kind, N of BodyN/TurbineN or None)."""
    letters = re.match(r"[A-Za-z]*", word).group(0).upper()
    for kind, words in _ATTACH.items():
        if letters in words and not word[len(letters):]:
            return kind, None
    number = word[len(letters):]
    if letters in ("BODY", "TURBINE") and number.isdigit() and int(number) >= 1:
        return letters.lower(), int(number)
    known = [w.title() for ws in _ATTACH.values() for w in ws] + ["Body1", "Turbine1"]
    why = f"{word!r}, not a point type{suggest(word.title(), known)}"
    raise rd.error(lineno, f"point {point_id} type must be Fixed, Vessel, Free, BodyN or TurbineN, got {why}. "
                           "Suggested fix: use Fixed (anchor), Vessel/Coupled (fairlead moved by the "
                           "vessel), Free (connection point), Body1 (fixed on body 1) or Turbine1 (FAST.Farm).")


def _read_points(rd, section, short=False) -> tuple[list[MoorDynPoint], dict[int, int]]:
    names, rows = _table(rd, section)
    if short:  # a CableDyn deck: rows may stop after 'ID Type X Y Z' (no mass, volume or drag)
        rows = [(n, tk + ["0"] * 4 if len(tk) == 5 else tk) for n, tk in rows]
        names = names if len(names) > 5 else []
    forces = any(len(t) >= 12 for _, t in rows) or "fx" in {_key(n) for n in names}
    # the names are checked against the layout they can name: the forces' only where they name FX or every row
    # holds them (rows of both kinds under MoorDyn's nine names are read by their own length)
    named_forces = "fx" in {_key(n) for n in names} or bool(rows) and all(len(t) >= 12 for _, t in rows)
    _check_column_order(rd, section, names, "points_forces" if named_forces else "points")
    points, where, written = [], {}, []
    layout = "ID type X Y Z mass volume CdA Ca, or ID type X Y Z mass volume FX FY FZ CdA Ca"
    if not rows:
        raise _empty(rd, section, "POINTS", "ID type X Y Z mass volume CdA Ca")
    for lineno, t in rows:
        rd.columns(lineno, t, 9, "POINTS", layout)
        pid = _integer(rd, lineno, t[0], "point ID")
        written.append(pid)
        pid = len(points) + 1  # MoorDyn-C numbers the points by position and never reads the ID column
        kind, owner = _attachment(rd, lineno, t[1], pid)
        x, y, z = (rd.number(lineno, t[k], f"point {pid} {c}", "m") for k, c in zip((2, 3, 4), "XYZ"))
        mass = rd.number(lineno, t[5], f"point {pid} Mass", "kg")
        vol = rd.number(lineno, t[6], f"point {pid} Volume", "m^3")
        if len(t) >= 12:
            forces = [rd.number(lineno, t[k], f"point {pid} F{c}", "N") for k, c in zip((7, 8, 9), "XYZ")]
            if any(forces):
                raise rd.error(lineno, f"point {pid} constant force (FX FY FZ) must be 0, got {forces}; "
                                       "seacable does not apply constant point forces. Suggested fix: "
                                       "model the load as a point mass or buoyancy (mass, volume).")
            cda_tok, ca_tok = t[10], t[11]
        else:
            cda_tok, ca_tok = t[7], t[8]
        cda = rd.number(lineno, cda_tok, f"point {pid} CdA", "m^2")
        ca = rd.number(lineno, ca_tok, f"point {pid} Ca", "-")
        for label, value, unit in (("Mass", mass, "kg"), ("Volume", vol, "m^3"), ("CdA", cda, "m^2"),
                                   ("Ca", ca, "")):
            rd.check(lineno, _validate.nonnegative, f"point {pid} {label}", value, unit,
                     "point masses, volumes and coefficients are >= 0")
        points.append(MoorDynPoint(pid, kind, (x, y, z), mass, vol, cda, ca, owner if kind == "body" else None,
                                   owner if kind == "turbine" else None))
        where[pid] = lineno
    if written != list(range(1, len(written) + 1)):
        warnings.warn(f"{rd.label}: point IDs {written} are not 1..{len(written)} in file order; MoorDyn numbers the "
                      "points by their position in the list (it never reads the ID column), and so does seacable: "
                      "lines attach to points 1..N in file order. Suggested fix: number the points 1, 2, 3, ... in "
                      "order.", SeacableWarning, stacklevel=4)
    return points, where


def _integer(rd, lineno, token, what) -> int:
    value = _as_float(token)
    if value is None or value != int(value):
        raise rd.error(lineno, f"{what} must be a whole number, got {token!r}. "
                               "Suggested fix: write an integer such as 1.")
    return int(value)


def _point_ref(rd, lineno, token, points, line_id, end, rods=None):
    """The point ID of a LINES attachment (``end`` names it, e.g. ``'A (AttachA)'``), or a rod end
    ``(rod ID, 'A'|'B')`` for ``R1A``/``Rod1B``."""
    m = re.fullmatch(r"([A-Za-z]*)(\d+)([A-Za-z]*)", token)
    prefix = m.group(1).upper() if m else ""
    if m and prefix in ("R", "ROD") and m.group(3).upper() in ("A", "B"):
        rid, side = int(m.group(2)), m.group(3).upper()
        if not rods or rid not in rods:
            ids = [str(k) for k in (rods or {})]
            raise rd.error(lineno, f"line {line_id} end {end} is attached to rod end {token!r}, but rod {rid} is "
                                   f"not in the RODS section (IDs {', '.join(ids) or 'none'}). Suggested fix: add "
                                   "the rod or correct the ID.")
        return rid, side
    if not m or m.group(3) or prefix not in ("", "C", "CON", "P", "POINT"):
        raise rd.error(lineno, f"line {line_id} end {end} must be a point ID (e.g. 1, C1 or Point1) or a rod end "
                               f"(R1A, R1B), got {token!r}. Suggested fix: write the ID of a row of the POINTS "
                               "section.")
    pid = int(m.group(2))
    if pid not in points:
        ids = [str(k) for k in points]
        raise rd.error(lineno, f"line {line_id} end {end} refers to point {pid}, which is not in the "
                               f"POINTS section (IDs {', '.join(ids)}).{suggest(str(pid), ids)} "
                               "Suggested fix: add the point or correct the ID.")
    return pid


# memory of one node in the model and its result: position, velocity, acceleration and the band of the
# Newton matrix (about 50 values), element properties and the stored shape and tensions [values]
_VALUES_PER_NODE = 64


def _end_position(points, rods, ref):
    """Global position of a line end for a negative UnstrLen (None if it is not global)."""
    if isinstance(ref, tuple):
        rod = rods[ref[0]]
        if rod.attachment == "body":
            return None
        return rod.end_a if ref[1] == "A" else rod.end_b
    p = points[ref]
    return p.position if p.attachment in ("fixed", "free", "vessel") else None


def _read_lines(rd, section, types, points, rods=None, cable_sections=None) -> list[MoorDynLine]:
    names, rows = _table(rd, section)
    if cable_sections is not None:
        return _read_cable_lines(rd, rows, types, points, rods, cable_sections, section)
    v1 = len(names) > 2 and "len" in names[2].lower()
    layout = ("ID type UnstrLen NumSegs NodeAnch NodeFair flags" if v1
              else "ID type AttachA AttachB UnstrLen NumSegs outputs")
    _check_column_order(rd, section, names, "lines_v1" if v1 else "lines")
    if not rows:
        raise _empty(rd, section, "LINES", layout)
    cols = (4, 5, 2, 3) if v1 else (2, 3, 4, 5)  # attach A, attach B, length, segments
    ends = ("NodeAnch", "NodeFair") if v1 else ("AttachA", "AttachB")
    out, seen, nodes = [], {}, len(points)
    for lineno, t in rows:
        rd.columns(lineno, t, 7, "LINES", layout)
        lid = _integer(rd, lineno, t[0], "line ID")
        if lid in seen:
            raise rd.error(lineno, f"line ID {lid} is used twice (first at line {seen[lid]}). "
                                   "Suggested fix: number the lines 1, 2, 3, ... once each.")
        seen[lid] = lineno
        if t[1] not in types:
            raise rd.error(lineno, f"line {lid} LineType must be one of {sorted(types)}, got "
                                   f"{t[1]!r}.{suggest(t[1], types)} Suggested fix: use a name from the "
                                   "LINE TYPES section (names are case-sensitive).")
        a = _point_ref(rd, lineno, t[cols[0]], points, lid, f"A ({ends[0]})", rods)
        b = _point_ref(rd, lineno, t[cols[1]], points, lid, f"B ({ends[1]})", rods)
        length = rd.number(lineno, t[cols[2]], f"line {lid} UnstrLen (unstretched length)", "m")
        nseg = _integer(rd, lineno, t[cols[3]], f"line {lid} NumSegs (number of segments)")
        rd.check(lineno, _validate.at_least, f"line {lid} NumSegs (number of segments)", nseg, "",
                 "use at least 1 segment (MoorDyn needs about 10 or more for dynamics)", 1)
        nodes += nseg - 1
        try:
            _limits.check_run_size(f"line {lid} NumSegs = {nseg:.6g} (the file's network of {nodes:.3g} nodes)",
                                   steps=1, stored_values=_VALUES_PER_NODE * nodes,
                                   fix="use fewer segments: about 1 per 5-20 m of line is usual")
        except InputError as exc:
            raise rd.error(lineno, str(exc)) from None
        if a == b:
            raise rd.error(lineno, f"line {lid} AttachA and AttachB are the same point ({a}). Suggested fix: "
                                   "attach the line's two ends to two different points.")
        if length < 0:  # MoorDyn: a negative length is a factor on the end-point distance
            pa, pb = _end_position(points, rods, a), _end_position(points, rods, b)
            if pa is None or pb is None:
                raise rd.error(lineno, f"line {lid} UnstrLen {t[cols[2]]} is negative (a factor on the distance "
                                       "between the ends), but an end is on a body, whose global position seacable "
                                       "does not compute while reading. Suggested fix: give the length in metres.")
            length = -length * math.dist(pa, pb)
        rd.check(lineno, _validate.positive, f"line {lid} UnstrLen (unstretched length)", length, "m",
                 "give the unstretched length in metres (or -factor times the end-point distance)")
        rod_a, rod_b = (a if isinstance(a, tuple) else None), (b if isinstance(b, tuple) else None)
        out.append(MoorDynLine(lid, t[1], None if rod_a else a, None if rod_b else b, length, nseg, t[6],
                               rod_a, rod_b))
    return out


def _read_cable_lines(rd, rows, types, points, rods, cable_sections, section) -> list[MoorDynLine]:
    """The LINES of a CableDyn deck: ``ID NodeA NodeB Outputs`` with the line's SECTIONS rows, or a stock MoorDyn
    row (``ID LineType AttachA AttachB UnstrLen NumSegs Outputs``) for a line without them."""
    if not rows:
        raise _empty(rd, section, "LINES", "ID NodeA NodeB Outputs")
    out, seen = [], {}
    for lineno, t in rows:
        if len(t) >= 7 and _as_float(t[4]) is not None:
            if _integer(rd, lineno, t[0], "line ID") in cable_sections:
                raise rd.error(lineno, f"line {t[0]} has both a MoorDyn LINES row (type and length) and SECTIONS rows. "
                                       "Suggested fix: give its sections in SECTIONS only ('ID NodeA NodeB Outputs').")
            stock = (None, lineno, "LINES", [(lineno, "ID type AttachA AttachB UnstrLen NumSegs outputs"),
                                             (lineno, "(-)"), (lineno, " ".join(t))])
            out.extend(_read_lines(rd, stock, types, points, rods))
            seen[out[-1].id] = lineno
            continue
        rd.columns(lineno, t, 3, "LINES", "ID NodeA NodeB Outputs (CableDyn, with SECTIONS)")
        lid = _integer(rd, lineno, t[0], "line ID")
        if lid in seen:
            raise rd.error(lineno, f"line ID {lid} is used twice (first at line {seen[lid]}). "
                                   "Suggested fix: number the lines 1, 2, 3, ... once each.")
        seen[lid] = lineno
        pieces = cable_sections.get(lid)
        if not pieces:
            raise rd.error(lineno, f"line {lid} has no SECTIONS rows (its LINES row gives no type or length). "
                                   f"Suggested fix: add its sections, e.g. '{lid} TYPE LENGTH NUMSEGS', from end A.")
        a = _point_ref(rd, lineno, t[1], points, lid, "A (NodeA)", rods)
        b = _point_ref(rd, lineno, t[2], points, lid, "B (NodeB)", rods)
        if a == b:
            raise rd.error(lineno, f"line {lid} NodeA and NodeB are the same point ({a}). Suggested fix: attach the "
                                   "line's two ends to two different points.")
        rod_a, rod_b = (a if isinstance(a, tuple) else None), (b if isinstance(b, tuple) else None)
        out.append(MoorDynLine(lid, pieces[0][0], None if rod_a else a, None if rod_b else b,
                               float(sum(p[1] for p in pieces)), int(sum(p[2] for p in pieces)),
                               t[3] if len(t) > 3 else "-", rod_a, rod_b, sections=pieces))
    unknown = sorted(set(cable_sections) - set(seen))
    if unknown:
        raise rd.error(None, f"SECTIONS rows name line(s) {unknown}, which are not in LINES. Suggested fix: use the "
                             "IDs of the LINES rows.")
    return out


_BODY_KINDS = {"FREE": ("free", False), "FIXED": ("fixed", False), "FIX": ("fixed", False),
               "COUPLED": ("coupled", False), "VESSEL": ("coupled", False), "CPLD": ("coupled", False),
               "VES": ("coupled", False), "COUPLEDPINNED": ("coupled", True), "VESSELPINNED": ("coupled", True),
               "CPLDPIN": ("coupled", True)}
_ROD_KINDS = {**_BODY_KINDS, "PINNED": ("free", True), "PIN": ("free", True)}


def _bar_list(rd, lineno, token, what, unit, counts):
    """A value, or several separated by '|' (MoorDyn's CG, I, CdA, Ca columns), each a number >= 0 except CG."""
    parts = token.split("|")
    if len(parts) not in counts:
        raise rd.error(lineno, f"{what} must be {' or '.join(str(c) for c in counts)} value(s) separated by '|' "
                               f"(no spaces), got {token!r}. Suggested fix: e.g. 0 or 0|0|-10.")
    return [rd.number(lineno, v, what, unit) for v in parts]


def _read_rod_types(rd, section) -> dict[str, MoorDynRodType]:
    names, rows = _table(rd, section)
    _check_column_order(rd, section, names, "rod_types")
    layout = "TypeName Diam Mass/m Cd Ca CdEnd CaEnd"
    out: dict[str, MoorDynRodType] = {}
    for lineno, t in rows:
        rd.columns(lineno, t, 7, "ROD TYPES", layout)
        name = t[0]
        if name in out:
            raise rd.error(lineno, f"rod type {name!r} is defined twice. Suggested fix: give each rod type its own "
                                   "name.")
        values = [rd.number(lineno, t[k], f"rod type {name!r} {c}", u) for k, c, u in
                  zip(range(1, 7), ("Diam", "Mass/m", "Cd", "Ca", "CdEnd", "CaEnd"), ("m", "kg/m", "", "", "", ""))]
        rd.check(lineno, _validate.positive, f"rod type {name!r} Diam", values[0], "m",
                 "give the rod's diameter in metres")
        for label, value, unit in zip(("Mass/m", "Cd", "Ca", "CdEnd", "CaEnd"), values[1:],
                                      ("kg/m", "", "", "", "")):
            rd.check(lineno, _validate.nonnegative, f"rod type {name!r} {label}", value, unit,
                     "rod masses and coefficients are >= 0")
        out[name] = MoorDynRodType(name, *values)
    return out


def _read_bodies(rd, section) -> tuple[list[MoorDynBody], dict[int, int]]:
    names, rows = _table(rd, section)
    layout = "ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca"
    early = any(n.lower() == "xcg" for n in names)
    _check_column_order(rd, section, names, "bodies_v2alpha" if early else "bodies")
    if early:
        # the early MoorDyn-F v2 layout (OpenFAST r-test 5MW_OC4): 'BodyID X0 Y0 Z0 r0 p0 y0 Xcg Ycg Zcg M V IX IY IZ
        # CdA Ca', the ID and attachment written together ('1coupled'): rewritten into today's columns
        old = "BodyID X0 Y0 Z0 r0 p0 y0 Xcg Ycg Zcg M V IX IY IZ CdA Ca"
        rewritten = []
        for lineno, t in rows:
            rd.columns(lineno, t, 17, "BODIES", old)
            m = re.fullmatch(r"(\d+)([A-Za-z]\w*)", t[0])
            if not m:
                raise rd.error(lineno, f"the body ID and attachment of this layout ({old}) are written together, e.g. "
                                       f"'1coupled', got {t[0]!r}. Suggested fix: write the ID then the attachment.")
            rewritten.append((lineno, [m.group(1), m.group(2), *t[1:7], t[10], "|".join(t[7:10]), "|".join(t[12:15]),
                                       t[11], t[15], t[16]]))
        rows = rewritten
    bodies, where = [], {}
    for lineno, t in rows:
        rd.columns(lineno, t, 14, "BODIES", layout)
        bid = _integer(rd, lineno, t[0], "body ID")
        if bid in where:
            raise rd.error(lineno, f"body ID {bid} is used twice (first at line {where[bid]}). Suggested fix: number "
                                   "the bodies 1, 2, 3, ... once each.")
        word = t[1].upper()
        turbine = None
        if word in _BODY_KINDS:
            kind, pinned = _BODY_KINDS[word]
        elif word.startswith("TURBINE") and word[7:].isdigit():
            kind, pinned, turbine = "turbine", False, int(word[7:])
        else:
            raise rd.error(lineno, f"body {bid} Attachment must be Free, Fixed, Coupled (Vessel), CoupledPinned or "
                                   f"TurbineN, got {t[1]!r}.{suggest(t[1].title(), ['Free', 'Fixed', 'Coupled'])} "
                                   "Suggested fix: use one of those words.")
        x, y, z = (rd.number(lineno, t[k], f"body {bid} {c}0", "m") for k, c in zip((2, 3, 4), "XYZ"))
        angles = tuple(math.radians(rd.number(lineno, t[k], f"body {bid} {c}", "deg"))
                       for k, c in zip((5, 6, 7), ("r0", "p0", "y0")))
        mass = rd.number(lineno, t[8], f"body {bid} Mass", "kg")
        cg = _bar_list(rd, lineno, t[9], f"body {bid} CG", "m", (1, 3))
        cg = (0.0, 0.0, cg[0]) if len(cg) == 1 else tuple(cg)  # one value: along the body's z axis
        inertia = _bar_list(rd, lineno, t[10], f"body {bid} I", "kg m^2", (1, 3))
        inertia = tuple(inertia * 3) if len(inertia) == 1 else tuple(inertia)
        volume = rd.number(lineno, t[11], f"body {bid} Volume", "m^3")
        cda = _bar_list(rd, lineno, t[12], f"body {bid} CdA", "m^2", (1, 2, 3, 6))
        cda = {1: lambda v: v * 6, 2: lambda v: [v[0]] * 3 + [v[1]] * 3, 3: lambda v: v * 2,
               6: lambda v: v}[len(cda)](cda)
        ca = _bar_list(rd, lineno, t[13], f"body {bid} Ca", "-", (1, 3))
        ca = tuple(ca * 3) if len(ca) == 1 else tuple(ca)
        for label, value, unit in (("Mass", mass, "kg"), ("Volume", volume, "m^3"),
                                   *((f"I[{k}]", v, "kg m^2") for k, v in enumerate(inertia)),
                                   *((f"CdA[{k}]", v, "m^2") for k, v in enumerate(cda)),
                                   *((f"Ca[{k}]", v, "") for k, v in enumerate(ca))):
            rd.check(lineno, _validate.nonnegative, f"body {bid} {label}", value, unit,
                     "body masses, inertias, volumes and coefficients are >= 0")
        bodies.append(MoorDynBody(bid, kind, (x, y, z, *angles), mass, cg, inertia, volume, tuple(cda), ca,
                                  pinned, turbine))
        where[bid] = lineno
    return bodies, where


def _read_rods(rd, section, rod_types, bodies) -> tuple[list[MoorDynRod], dict[int, int]]:
    names, rows = _table(rd, section)
    _check_column_order(rd, section, names, "rods")
    layout = "ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs"
    rods, where = [], {}
    for lineno, t in rows:
        rd.columns(lineno, t, 11, "RODS", layout)
        rid = _integer(rd, lineno, t[0], "rod ID")
        if rid in where:
            raise rd.error(lineno, f"rod ID {rid} is used twice (first at line {where[rid]}). Suggested fix: number "
                                   "the rods 1, 2, 3, ... once each.")
        if t[1] not in rod_types:
            raise rd.error(lineno, f"rod {rid} RodType must be one of {sorted(rod_types)}, got {t[1]!r}."
                                   f"{suggest(t[1], rod_types)} Suggested fix: use a name from the ROD TYPES section.")
        word = t[2].upper()
        body = turbine = None
        m = re.fullmatch(r"(BODY|TURBINE)(\d+)(PINNED|PIN)?", word)
        if word in _ROD_KINDS or re.fullmatch(r"PINNED\d+", word):  # MoorDyn-F's r-test writes 'Pinned1'
            kind, pinned = _ROD_KINDS.get(word, ("free", True))
        elif m and m.group(1) == "BODY":
            kind, pinned, body = "body", m.group(3) is not None, int(m.group(2))
            if body not in bodies:
                raise rd.error(lineno, f"rod {rid} is attached to body {body}, which is not in the BODIES section "
                                       f"(IDs {', '.join(str(b) for b in bodies) or 'none'}). Suggested fix: add the "
                                       "body or correct the ID.")
        elif m:
            kind, pinned, turbine = "turbine", m.group(3) is not None, int(m.group(2))
        else:
            raise rd.error(lineno, f"rod {rid} Attachment must be Fixed, Pinned, Free, Coupled (Vessel), "
                                   f"CoupledPinned, BodyN, BodyNPinned or TurbineN, got {t[2]!r}."
                                   f"{suggest(t[2].title(), ['Fixed', 'Pinned', 'Free', 'Coupled', 'Body1'])} "
                                   "Suggested fix: use one of those words.")
        ends = [rd.number(lineno, t[k], f"rod {rid} {c}", "m") for k, c in
                zip(range(3, 9), ("Xa", "Ya", "Za", "Xb", "Yb", "Zb"))]
        nseg = _integer(rd, lineno, t[9], f"rod {rid} NumSegs")
        rd.check(lineno, _validate.nonnegative, f"rod {rid} NumSegs", nseg, "",
                 "use 0 (a point-like rod) or more segments")
        rod = MoorDynRod(rid, t[1], kind, tuple(ends[:3]), tuple(ends[3:]), nseg, t[10], pinned, body, turbine)
        if rod.length == 0 and nseg > 0:
            raise rd.error(lineno, f"rod {rid} has its two ends at the same place {tuple(ends[:3])} m but {nseg} "
                                   "segment(s). Suggested fix: give the rod a length, or NumSegs 0.")
        if rod.length > 0 and nseg == 0:  # MoorDyn takes a rod of no segments as point-like, of zero length
            raise rd.error(lineno, f"rod {rid} NumSegs = 0 but its ends are {rod.length:.6g} m apart: a rod of 0 "
                                   "segments is point-like (no length, no nodes along it), so its length would be "
                                   "lost. Suggested fix: give NumSegs >= 1, or put both ends at the same place.")
        rods.append(rod)
        where[rid] = lineno
    return rods, where


def _read_failures(rd, section, points, rods, lines) -> list[MoorDynFailure]:
    names, rows = _table(rd, section)
    _check_column_order(rd, section, names, "failure" if rows and len(rows[0][1]) >= 5 else "failure_no_id")
    out = []
    line_ids = {ln.id: ln for ln in lines}
    for index, (lineno, t) in enumerate(rows, start=1):
        if len(t) >= 5:
            fid = _integer(rd, lineno, t[0], "failure ID")
            t = t[1:]
        else:
            rd.columns(lineno, t, 4, "FAILURE", "FailureID Point Line(s) FailTime FailTen")
            fid = index
        ref = t[0]
        m = re.fullmatch(r"(?:R|ROD)(\d+)([AB])", ref.upper())
        if m:
            where = (int(m.group(1)), m.group(2))
            if where[0] not in rods:
                raise rd.error(lineno, f"failure {fid} is at rod end {ref!r}, but there is no rod {where[0]}. "
                                       "Suggested fix: name a rod end of the RODS section, e.g. R1A.")
        else:
            where = _point_ref(rd, lineno, ref, points, f"of failure {fid}", "(Point)")
        ids = []
        for token in t[1].split(","):
            lid = _integer(rd, lineno, token, f"failure {fid} Line(s) entry")
            if lid not in line_ids:
                raise rd.error(lineno, f"failure {fid} names line {lid}, which is not in the LINES section. "
                                       "Suggested fix: list IDs of lines, separated by commas without spaces.")
            ln = line_ids[lid]
            at = [ln.point_a, ln.point_b] if isinstance(where, int) else [ln.rod_a, ln.rod_b]
            if where not in at:
                raise rd.error(lineno, f"failure {fid}: line {lid} is not attached to {ref} (its ends are "
                                       f"{_end_name(ln.point_a, ln.rod_a)} and {_end_name(ln.point_b, ln.rod_b)}). "
                                       "Suggested fix: name the point or rod end the line ends at.")
            ids.append(lid)
        time = rd.number(lineno, t[2], f"failure {fid} FailTime", "s")
        tension = rd.number(lineno, t[3], f"failure {fid} FailTen", "N")
        rd.check(lineno, _validate.nonnegative, f"failure {fid} FailTime", time, "s", "give a time in s, or 0")
        rd.check(lineno, _validate.nonnegative, f"failure {fid} FailTen", tension, "N",
                 "give a tension in N, or 0")
        if time == 0 and tension == 0:
            rd.notes.append(f"{rd.label}:{lineno}: failure {fid} has FailTime 0 and FailTen 0: MoorDyn-F then "
                            "breaks the line(s) at the start.")
        out.append(MoorDynFailure(fid, where, tuple(ids), time, tension))
    return out


def _read_external_loads(rd, section, points, bodies, rods) -> list[MoorDynExternalLoad]:
    names, rows = _table(rd, section)
    _check_column_order(rd, section, names, "external_loads")
    out = []
    for lineno, t in rows:
        rd.columns(lineno, t, 5, "EXTERNAL LOADS", "ID Object Fext Blin Bquad [CSys]")
        lid = _integer(rd, lineno, t[0], "external load ID")
        m = re.fullmatch(r"(BODY|POINT|ROD)(\d+)", t[1].upper())
        pool = {"BODY": bodies, "POINT": points, "ROD": rods}
        if not m or int(m.group(2)) not in pool[m.group(1)]:
            raise rd.error(lineno, f"external load {lid} Object must name a body, point or rod of the deck (e.g. "
                                   f"Body1, Point3, Rod2), got {t[1]!r}. Suggested fix: use the object's kind and ID.")
        kind, target = m.group(1).lower(), int(m.group(2))
        force = _bar_list(rd, lineno, t[2], f"external load {lid} Fext", "N", (3,))
        damp_counts = (2,) if kind == "rod" else (3,)
        blin = _bar_list(rd, lineno, t[3], f"external load {lid} Blin", "N s/m", damp_counts)
        bquad = _bar_list(rd, lineno, t[4], f"external load {lid} Bquad", "N s^2/m^2", damp_counts)
        for label, values in (("Blin", blin), ("Bquad", bquad)):
            for v in values:
                rd.check(lineno, _validate.nonnegative, f"external load {lid} {label}", v, "",
                         "damping coefficients are >= 0")
        frame = t[5].upper() if len(t) > 5 else "G"
        if kind == "body" and frame not in ("G", "L"):
            raise rd.error(lineno, f"external load {lid} CSys must be G (global) or L (body axes) for a body, got "
                                   f"{t[5]!r}. Suggested fix: write G or L.")
        out.append(MoorDynExternalLoad(lid, kind, target, tuple(force), tuple(blin), tuple(bquad),
                                       frame if kind == "body" else "G"))
    return out


def _end_name(point, rod) -> str:
    return f"R{rod[0]}{rod[1]}" if rod else f"point {point}"

"""A MoorDyn deck's text in sections: the reader's state and messages, comments, section headers, a table's
column names and rows, and the check of the column names against the order MoorDyn reads them."""

from __future__ import annotations

import functools
import math
import re
import warnings
from pathlib import Path

from ..._text import read_text_file
from ...errors import InputError, SeacableWarning

_SECTION_KEYS = (  # order matters: 'LINE TYPES' before 'LINES', 'ROD TYPES' before 'RODS'
    # CableDyn's cable extensions (seacable.io.moordyn._cabledyn); 'BUOYANCY SECTIONS' before 'SECTIONS'
    ("equivalent_buoyancy", ("EQUIVALENT BUOYANCY", "EQUIVALENT SECTIONS", "BUOYANCY SECTIONS")),
    ("end_connections", ("END CONNECTION",)),
    ("cable_sections", ("SECTIONS",)),
    ("attachments", ("LINE ATTACHMENTS", "ATTACHMENTS", "CLUMPS")),
    ("line_types", ("LINE DICTIONARY", "LINE TYPES")),
    ("rod_types", ("ROD DICTIONARY", "ROD TYPES")),
    ("bodies", ("BODIES", "BODY LIST", "BODY PROPERTIES")),
    ("points", ("POINTS", "POINT LIST", "POINT PROPERTIES", "CONNECTION PROPERTIES", "NODE PROPERTIES")),
    ("rods", ("RODS", "ROD LIST", "ROD PROPERTIES")),
    ("lines", ("LINES", "LINE LIST", "LINE PROPERTIES")),
    ("failure", ("FAILURE",)),
    ("syrope_ic", ("SYROPE IC",)),
    ("syrope_wc", ("SYROPE WORKING CURVES",)),
    ("control", ("CONTROL",)),
    ("external_loads", ("EXTERNAL LOADS",)),
    ("options", ("OPTIONS",)),
    ("outputs", ("OUTPUT",)),
)
_UNSUPPORTED = {"control": "CONTROL"}
_COUNT = re.compile(r"^N[A-Za-z]+$")  # v1 count lines: '3 NLines - number of line objects'

_ATTACH = {"fixed": ("FIXED", "FIX", "ANCHOR"), "vessel": ("VESSEL", "VES", "COUPLED", "CPLD", "FAIRLEAD"),
           "free": ("FREE", "POINT", "CONNECT", "CON")}
_FORTRAN_EXP = re.compile(r"^([+-]?(\d+\.?\d*|\.\d+))[dD]([+-]?\d+)$")


def _as_float(token: str) -> float | None:
    """The token as a finite float, or None (accepts Fortran ``1.0d5``)."""
    m = _FORTRAN_EXP.match(token)
    if m:
        token = f"{m.group(1)}e{m.group(3)}"
    try:
        value = float(token)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


class _Reader:
    """State of one parse: the source label for messages and the lines of text."""

    def __init__(self, label: str, folder: Path | None = None):
        self.label = label
        self.folder = folder  # where files named in the deck (nonlinear tables) are looked up
        self.v1_counts = False
        self.syrope_types: dict[str, int] = {}  # Syrope line types and their line
        self.notes: list[str] = []
        self.option_lines: dict[str, int] = {}
        self.names_line: dict[int, int] = {}  # a table's header line -> the line of its column names

    def at(self, name: str) -> str:
        """``file:line: `` of the option ``name`` (any case), for the notes."""
        lineno = next((n for k, n in self.option_lines.items() if k.lower() == name.lower()), None)
        return f"{self.label}:{lineno}: " if lineno else f"{self.label}: "

    def error(self, lineno: int | None, message: str) -> InputError:
        where = f"{self.label}:{lineno}" if lineno else self.label
        return InputError(f"{where}: {message}")

    def number(self, lineno, token, what, unit, fix="write a plain number in SI units") -> float:
        value = _as_float(token)
        if value is None:
            raise self.error(lineno, f"{what} must be a finite number in {unit}, got {token!r}. "
                                     f"Suggested fix: {fix}.")
        return value

    def check(self, lineno, check, what, value, unit, fix, *args):
        """Run a ``seacable._validate`` check and prefix its message with file and line."""
        try:
            return check(what, value, *args, unit, fix)
        except InputError as exc:
            raise self.error(lineno, str(exc)) from None

    def columns(self, lineno, tokens, needed, what, layout):
        if len(tokens) < needed:
            raise self.error(lineno, f"a {what} row must have {needed} columns ({layout}), got "
                                     f"{len(tokens)}: {' '.join(tokens)!r}. Suggested fix: "
                                     "fill in every column; write 0 or - where a value does not apply.")


def _load(path_or_text, name):
    """Return (text, path or None, label)."""
    if isinstance(path_or_text, Path) or (isinstance(path_or_text, str) and "\n" not in path_or_text):
        path = Path(path_or_text)
        label = name or str(path)
        if not path.is_file():
            raise InputError(f"MoorDyn file {str(path)!r} not found. Suggested fix: check the path, "
                             "or pass the file's text (with its newlines) instead of a path.")
        text = read_text_file(path, "MoorDyn file", "pass the MoorDyn .txt input (not a binary .ic state file)")
        return text, str(path), label
    if isinstance(path_or_text, str):
        return path_or_text, None, name or "<MoorDyn text>"
    raise InputError(f"read_moordyn needs a path or the file's text, got {type(path_or_text).__name__}. "
                     "Suggested fix: pass a str or pathlib.Path.")


def _section_kind(line: str) -> str | None:
    upper = line.upper()
    for kind, keys in _SECTION_KEYS:
        if any(k in upper for k in keys):
            return kind
    return None


def _is_end(line: str) -> bool:
    stripped = line.strip().upper()
    if "---" in line and "END CONNECTION" in stripped:  # CableDyn's END CONNECTIONS section, not the end
        return False
    if stripped == "END" or stripped.startswith("END "):
        return True
    return "---" in line and ("NEED THIS LINE" in stripped or _END.search(stripped) is not None)


_END = re.compile(r"\bEND\b")


_COMMENT = re.compile(r"[!#%]")


def _strip_comment(line: str) -> str:
    """The line without its comment: MoorDyn v2 ignores the rest of a line from a '!', '#' or '%'.

    ``docs/inputs.rst`` of MoorDyn ("!, #, and % are comment characters ... any of these characters
    will prevent MoorDyn from reading the rest of that line"); MoorDyn-C 2.7.2 reads a points row
    ``3 Free -150 0 -60 1000 0 1 0 # 1 2 3 4`` as the 9-column row before the ``#``.
    """
    match = _COMMENT.search(line)
    return line if match is None else line[:match.start()]


def _split_sections(rd: _Reader, text: str):
    """Return (title lines, echo, {kind: (header lineno, header text, [(lineno, line)])})."""
    title, sections, echo, unknown = [], {}, None, []
    current = None  # [kind, header lineno, header text, rows] of the section being filled
    for lineno, raw in enumerate(text.splitlines(), start=1):
        # the title is free text; from the first section on, '!', '#' and '%' start a comment
        line = (_strip_comment(raw) if sections or current is not None else raw).rstrip()
        if _is_end(line):
            break
        if "---" in line:
            kind = _section_kind(line)
            if kind is None:  # a header seacable does not know (or the title banner)
                current = None if not sections else ("unknown", lineno, line.strip(), [])
                if current is not None:
                    unknown.append(current)
                continue
            if kind in sections:
                raise rd.error(lineno, f"a second {kind.replace('_', ' ').upper()} section (the first "
                                       f"starts at line {sections[kind][1]}); MoorDyn reads only the "
                                       "first. Suggested fix: merge the two sections into one.")
            current = (kind, lineno, line.strip(), [])
            sections[kind] = current
            continue
        if current is None:  # free text before the first section
            tokens = line.split()
            if len(tokens) >= 2 and tokens[1] == "Echo":
                echo = tokens[0]
            elif tokens:
                title.append(line.strip())
            continue
        current[3].append((lineno, line))
    for _, lineno, header, rows in unknown:
        if any(r.strip() for _, r in rows):
            warnings.warn(f"{rd.label}:{lineno}: section {header.strip(' -')!r} is not a MoorDyn "
                          "section seacable knows; its rows are ignored.", SeacableWarning, stacklevel=3)
    return title, echo, sections


def _table(rd: _Reader, section):
    """Return (column names, [(lineno, tokens)]) of a table section, skipping names and units."""
    _, header_no, header, body = section
    count = None
    first = body[0][1].split() if body else []
    if len(first) >= 2 and _as_float(first[0]) is not None and _COUNT.match(first[1]):
        # MoorDyn v1 (MoorDyn-F before v2): a count line 'N NTypes' opens the section
        count = (body[0][0], first[1], first[0])
        body = body[1:]
        rd.v1_counts = True
    names = body[0][1].split() if body else []
    if body:
        rd.names_line[header_no] = body[0][0]
    rows = []
    for index, (lineno, line) in enumerate(body):
        tokens = line.split()
        if index < 2:
            if tokens and _as_float(tokens[0]) is not None:
                which = "column names" if index == 0 else "units"
                raise rd.error(lineno, f"the {which} line of {header.strip(' -')!r} (header at line "
                                       f"{header_no}) must be text, got the data row {line.strip()!r}; "
                                       "MoorDyn skips the two lines after a table header unread. "
                                       "Suggested fix: add the column-names and units lines.")
            continue
        if tokens:
            rows.append((lineno, tokens))
    if count is not None:
        lineno, word, token = count
        value = _as_float(token)
        if value != len(rows):
            raise rd.error(lineno, f"{word} must be the number of rows of {header.strip(' -')!r}, got {token!r} "
                                   f"but the section has {len(rows)} row(s). Suggested fix: write {len(rows)}, or "
                                   "add the missing rows (MoorDyn v1 reads exactly that many).")
    return names, rows


# MoorDyn's column order of each table section (it reads every row by position and never the column names), each
# column with the names decks write for it (compared without case, spaces and punctuation: 'BA/-zeta' is 'bazeta').
# The first name is the one the warning shows.
_COLUMNS = {
    "line_types": (("Name", "LineType", "TypeName", "Type", "ID"), ("Diam", "D", "Diameter", "d_vol"),
                   ("MassDen", "MassDenInAir", "Mass/m", "MassDensity", "Mass", "m", "w"), ("EA", "EAs"),
                   ("BA/-zeta", "BA", "BA/zeta", "c", "zeta"), ("EI",),
                   ("Cd", "Cdn", "CdN"), ("Ca", "Can", "CaN"), ("CdAx", "Cdt", "CdT", "CdA_x"), ("CaAx", "Cat", "CaT"),
                   ("Cl", "CL"), ("dF",), ("cF",)),
    # MoorDyn v1 (no EI column): the coefficients in another order
    "line_types_v1": (("Name", "LineType", "TypeName", "Type", "ID"), ("Diam", "D", "Diameter"),
                      ("MassDen", "MassDenInAir", "Mass/m", "MassDensity", "Mass", "m", "w"), ("EA",),
                      ("BA/-zeta", "BA", "BA/zeta", "c", "zeta"), ("Can", "Ca", "CaN"), ("Cat", "CaAx", "CaT"),
                      ("Cdn", "Cd", "CdN"), ("Cdt", "CdAx", "CdT")),
    "rod_types": (("TypeName", "Name", "RodType", "Type", "ID"), ("Diam", "D", "Diameter"),
                  ("Mass/m", "MassDen", "MassDenInAir", "Mass", "m"), ("Cd", "Cdn"), ("Ca", "Can"),
                  ("CdEnd", "CdE"), ("CaEnd", "CaE")),
    "points": (("ID", "Node", "Point", "Connection", "Num", "Number", "Name"),
               ("Attachment", "Type", "Attach"), ("X",), ("Y",), ("Z",), ("Mass", "M"), ("Volume", "V", "Vol"),
               ("CdA",), ("Ca", "CA")),
    "points_forces": (("ID", "Node", "Point", "Connection", "Num", "Number", "Name"),
                      ("Attachment", "Type", "Attach"), ("X",), ("Y",), ("Z",), ("Mass", "M"),
                      ("Volume", "V", "Vol"), ("FX",), ("FY",), ("FZ",), ("CdA",), ("Ca", "CA")),
    "lines": (("ID", "Line", "Name", "Num", "Number"), ("LineType", "Type", "TypeName"),
              ("AttachA", "NodeA", "EndA", "NodeAnch", "Anchor", "ConnectionA", "PointA"),
              ("AttachB", "NodeB", "EndB", "NodeFair", "Fairlead", "ConnectionB", "PointB"),
              ("UnstrLen", "UnstrLength", "Length", "L"), ("NumSegs", "NSegs", "Segments", "N"),
              ("Outputs", "LineOutputs", "Flags/Outputs", "Flags", "Output")),
    "lines_v1": (("ID", "Line", "Name", "Num", "Number"), ("LineType", "Type", "TypeName"),
                 ("UnstrLen", "UnstrLength", "Length", "L"), ("NumSegs", "NSegs", "Segments", "N"),
                 ("NodeAnch", "AttachA", "NodeA", "EndA", "Anchor"), ("NodeFair", "AttachB", "NodeB", "EndB", "Fairlead"),
                 ("Flags/Outputs", "Flags", "Outputs", "LineOutputs", "Output")),
    "bodies": (("ID", "BodyID", "Body", "Name"), ("Attachment", "Type", "Attach"), ("X0", "X"), ("Y0", "Y"),
               ("Z0", "Z"), ("r0", "Roll", "Roll0"), ("p0", "Pitch", "Pitch0"), ("y0", "Yaw", "Yaw0"),
               ("Mass", "M"), ("CG", "CG*", "CoG", "Xcg"), ("I", "I*", "Inertia"), ("Volume", "V", "Vol"),
               ("CdA", "CdA*"), ("Ca", "Ca*", "CA")),
    # the early MoorDyn-F v2 layout (ID and attachment in one column), rewritten into today's by _read_bodies
    "bodies_v2alpha": (("BodyID", "ID", "Body"), ("X0", "X"), ("Y0", "Y"), ("Z0", "Z"), ("r0", "Roll"),
                       ("p0", "Pitch"), ("y0", "Yaw"), ("Xcg",), ("Ycg",), ("Zcg",), ("M", "Mass"),
                       ("V", "Volume", "Vol"), ("IX",), ("IY",), ("IZ",), ("CdA",), ("Ca", "CA")),
    "rods": (("ID", "Rod", "Name", "Num", "Number"), ("RodType", "Type", "TypeName"), ("Attachment", "Attach"),
             ("Xa",), ("Ya",), ("Za",), ("Xb",), ("Yb",), ("Zb",), ("NumSegs", "NSegs", "Segments", "N"),
             ("RodOutputs", "Outputs", "Flags", "Output")),
    "failure": (("FailureID", "ID"), ("Point", "Attachment", "Attach", "Object", "Node"),
                ("Line(s)", "Lines", "Line", "LineIDs"), ("FailTime", "Time", "T"), ("FailTen", "Tension", "Ten")),
    "external_loads": (("ID",), ("Object", "Obj"), ("Fext", "Force", "F"), ("Blin",), ("Bquad",),
                       ("CSys", "Frame")),
    "syrope_ic": (("Line", "Lines", "Line(s)", "ID", "LineIDs"), ("Tmax0", "Tmax"), ("Tmean0", "Tmean")),
    "syrope_wc": (("LineType", "Name", "Type", "TypeName"), ("WCType", "Type"), ("k1",), ("k2",)),
}
_COLUMNS["failure_no_id"] = _COLUMNS["failure"][1:]  # the ID column is optional
_SECTION_TITLES = {"line_types": "LINE TYPES", "rod_types": "ROD TYPES", "points": "POINTS", "lines": "LINES",
                   "bodies": "BODIES", "rods": "RODS", "failure": "FAILURE", "external_loads": "EXTERNAL LOADS",
                   "syrope_ic": "SYROPE IC", "syrope_wc": "SYROPE WORKING CURVES"}


_NOT_KEY = re.compile(r"[^a-z0-9]")


def _key(name: str) -> str:
    return _NOT_KEY.sub("", name.lower())


@functools.cache
def _layout_keys(layout: str) -> tuple[frozenset[str], ...]:
    """The keys (:func:`_key`) of each column's names of a ``_COLUMNS`` layout."""
    return tuple(frozenset(_key(a) for a in aliases) for aliases in _COLUMNS[layout])


def _check_column_order(rd: _Reader, section, names, layout: str) -> None:
    """Warn when a table's column names put a column MoorDyn reads elsewhere (it reads rows by position only).

    ``layout`` is a key of ``_COLUMNS``: MoorDyn's order of the section, as seacable reads it. A name that is one
    of MoorDyn's columns but stands at another column's place (``Can Cat Cdn Cdt`` written over the v2 line
    types' ``Cd Ca CdAx CaAx``; a column name missing or added, shifting the rest) is reported; names seacable does
    not know (``tbd``, units) are not. The rows are still read by position, as MoorDyn reads them.
    """
    if len(section[3]) <= 2:   # the names and units lines, no row: an empty section reads nothing by them
        return
    columns = _COLUMNS[layout]
    keys = _layout_keys(layout)
    wrong = []
    for index, name in enumerate(names):
        key = _key(name)
        if not key or (index < len(keys) and key in keys[index]):
            continue
        meant = next((j for j, ks in enumerate(keys) if key in ks), None)
        if meant is not None and meant != index:
            at = f"reads it as {columns[index][0]}" if index < len(columns) else "has no column there"
            wrong.append(f"column {index + 1} is named {name!r} (MoorDyn's {columns[meant][0]}, its column {meant + 1}) "
                         f"but MoorDyn {at}")
    if not wrong:
        return
    kind, header_no = section[0], section[1]
    title = _SECTION_TITLES.get(kind, kind.upper())
    lineno = rd.names_line.get(header_no, header_no)
    warnings.warn(f"{rd.label}:{lineno}: the {title} column names ({' '.join(names)}) are not in the order MoorDyn "
                  f"reads the section ({' '.join(c[0] for c in columns)}): {'; '.join(wrong)}. MoorDyn reads the rows "
                  "by position and never the names, and so does seacable. Suggested fix: check that each row's values "
                  "are in MoorDyn's order, and write the column names in that order.", SeacableWarning, stacklevel=4)

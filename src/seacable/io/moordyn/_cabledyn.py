"""CableDyn's extensions of the MoorDyn v2 deck, for its cable decks: SECTIONS, EQUIVALENT BUOYANCY, END CONNECTIONS.

CableDyn 0.3.0 (Apache-2.0, github.com/SMI-Lab-Inha/CableDyn, ``doc/driver_format.md``) reads MoorDyn v2 decks
and adds, for dynamic power cables:

* ``SECTIONS`` (``LineID LineType Length NumSegs``, rows from End A to End B): a line of several line types, each
  with its own element count; its ``LINES`` rows then give only ``ID NodeA NodeB Outputs``, and its ``POINTS``
  rows may stop after ``ID Type X Y Z`` (no mass, volume or drag); its LINE TYPES header selects the column
  order (its decks write ``Cd_n Cd_t Ca_n Ca_t`` after EI, MoorDyn ``Cd Ca CdAx CaAx``), and ``--`` starts a
  comment row;
* ``EQUIVALENT BUOYANCY`` (``LineType Diam SubmergedWeightNpm``): a line type rewritten to a given diameter and
  weight in water per metre, its mass in air ``w / g + rho pi d^2 / 4`` with the deck's final rho and g;
* ``END CONNECTIONS`` (``LineID End Stiffness EzX EzY EzZ``): the bending boundary of a line end, pinned by default;
* ``ATTACHMENTS`` (``LineID ArcLength Mass Volume CdA Ca [CdAx]``): point loads on a line (buoyancy modules, clump
  weights), each at the node nearest its arc length;
* OPTIONS rows of its own, some written keyword first (``dynamic_solver 1e-8 1e-14 30 12``): its solver's settings
  (dropped, as MoorDyn's ``dtM`` is: seacable's statics and time steps are its own), ``frictionMu`` (read as MoorDyn's
  ``FrictionCoefficient``), ``current`` and ``waves`` (``none`` only).

seacable reads SECTIONS, EQUIVALENT BUOYANCY, ATTACHMENTS and END CONNECTIONS (pinned, rigid: a clamp, or a
rotational spring, :class:`seacable.mooring.ends.EndCondition`; a torsional restraint is refused, the line carrying
no torque); it refuses CableDyn's ``current`` and ``waves`` options other than ``none``. The lines and points are otherwise MoorDyn's, read by the same tables.
"""

from __future__ import annotations

import dataclasses
import math

from ..._model import suggest
from ._sections import _as_float, _table

#: OPTIONS rows CableDyn writes keyword first (several values after it): solver settings seacable has its own of
_KEYWORD_FIRST = ("dynamic_solver", "static_solver", "sequenced", "cable_statics")
#: CableDyn's environment options: seacable refuses any value but 'none' rather than run without it
_ENVIRONMENT = ("current", "waves")
#: CableDyn's value-first OPTIONS that steer its own solver, not the problem (as MoorDyn's dtM and threshIC do): seacable
#: has its own statics and time steps, and drops them without a note, as it drops MoorDyn's
_SOLVER = frozenset(k.lower() for k in ("rhoInf", "modified_newton", "TMax", "adaptive_mesh", "tensile_safety",
                                        "tensile_strain_tolerance", "recovery_max_substeps", "alpha_force_blend"))


def is_cabledyn(sections) -> bool:
    """Whether a deck split into sections uses CableDyn's cable extensions (it has a SECTIONS table)."""
    return "cable_sections" in sections


def read_cable_sections(rd, section, types) -> dict[int, tuple[tuple[str, float, int], ...]]:
    """The SECTIONS table: per line ID, its ``(line type, length [m], elements)`` from End A to End B."""
    _names, rows = _table(rd, section)
    out: dict[int, list] = {}
    for lineno, t in rows:
        rd.columns(lineno, t, 4, "SECTIONS", "LineID LineType Length NumSegs")
        lid = _whole(rd, lineno, t[0], "SECTIONS LineID")
        if t[1] not in types:
            raise rd.error(lineno, f"SECTIONS row of line {lid} names line type {t[1]!r}, which is not in LINE TYPES"
                                   f" ({', '.join(sorted(types))}).{suggest(t[1], types)} Suggested fix: use a line "
                                   "type's name (case-sensitive).")
        length = rd.number(lineno, t[2], f"SECTIONS line {lid} Length", "m")
        if not length > 0:
            raise rd.error(lineno, f"SECTIONS line {lid} Length must be > 0 m, got {length:g} m. Suggested fix: give "
                                   "the section's unstretched length in metres.")
        n = _whole(rd, lineno, t[3], f"SECTIONS line {lid} NumSegs")
        if n < 1:
            raise rd.error(lineno, f"SECTIONS line {lid} NumSegs must be >= 1, got {n}. Suggested fix: give the "
                                   "section's element count, e.g. one per metre.")
        out.setdefault(lid, []).append((t[1], length, n))
    return {k: tuple(v) for k, v in out.items()}


def apply_equivalent_buoyancy(rd, section, types, water_density: float, gravity: float):
    """The line types with the EQUIVALENT BUOYANCY rows applied: diameter and weight in water given, mass in air
    ``w / g + rho pi d^2 / 4``. [m], [N/m], [kg/m]"""
    _, rows = _table(rd, section)
    types, seen = dict(types), set()
    for lineno, t in rows:
        rd.columns(lineno, t, 3, "EQUIVALENT BUOYANCY", "LineType Diam SubmergedWeightNpm")
        name = t[0]
        if name not in types:
            raise rd.error(lineno, f"EQUIVALENT BUOYANCY names line type {name!r}, which is not in LINE TYPES."
                                   f"{suggest(name, types)} Suggested fix: use a line type's name.")
        if name in seen:
            raise rd.error(lineno, f"EQUIVALENT BUOYANCY rewrites line type {name!r} twice. Suggested fix: one row "
                                   "per line type.")
        seen.add(name)
        d = rd.number(lineno, t[1], f"EQUIVALENT BUOYANCY {name} Diam", "m")
        w = rd.number(lineno, t[2], f"EQUIVALENT BUOYANCY {name} SubmergedWeightNpm", "N/m")
        if not d > 0:
            raise rd.error(lineno, f"EQUIVALENT BUOYANCY {name} Diam must be > 0 m, got {d:g} m. Suggested fix: give "
                                   "the equivalent (displaced-volume) diameter in metres.")
        mass = w / gravity + water_density * math.pi * d**2 / 4.0
        if not mass > 0:
            raise rd.error(lineno, f"EQUIVALENT BUOYANCY {name}: a weight in water of {w:g} N/m at diameter {d:g} m "
                                   f"needs a mass in air of {mass:.6g} kg/m, not > 0. Suggested fix: a larger "
                                   "equivalent diameter, or check the sign (N/m, negative for uplift).")
        types[name] = dataclasses.replace(types[name], diameter=d, mass_per_length=mass)
    return types


def _line_id(rd, lineno, token, table: str, line_ids) -> int:
    """The line ID ``token`` of a ``table`` row, which must name a line of LINES (``line_ids``)."""
    lid = _whole(rd, lineno, token, f"{table} LineID")
    if lid not in line_ids:
        raise rd.error(lineno, f"{table} names line {lid}, which is not in LINES "
                               f"({', '.join(map(str, sorted(line_ids)))}). Suggested fix: use a line's ID.")
    return lid


#: END CONNECTIONS Stiffness keywords: a pinned end, and a rigid one (a clamp)
_PINNED = ("pinned", "free", "zero")
_RIGID = ("rigid", "infinity", "inf")


def read_end_connections(rd, section, line_ids) -> dict:
    """The END CONNECTIONS rows as ``{(line ID, end): (kind, stiffness, direction)}`` for the ends held in bending:
    ``end`` 0 for End A, 1 for End B; ``kind`` ``"clamp"`` (Stiffness Rigid, Infinity or Inf) or ``"spring"`` (a
    rotational stiffness > 0 [N m/rad]); ``direction`` the unit vector ``(EzX, EzY, EzZ)`` along the line towards
    End B (CableDyn's convention, as :class:`seacable.mooring.ends.EndCondition`'s), global axes. Pinned ends
    (Pinned, Free, Zero or 0) are left out: seacable's ends are pinned by default. The torsion columns are refused
    (the line carries no torque)."""
    _, rows = _table(rd, section)
    out = {}
    for lineno, t in rows:
        rd.columns(lineno, t, 3, "END CONNECTIONS", "LineID End Stiffness EzX EzY EzZ")
        lid = _line_id(rd, lineno, t[0], "END CONNECTIONS", line_ids)
        letter = t[1].strip("'\"").upper()
        if letter not in ("A", "B"):
            raise rd.error(lineno, f"END CONNECTIONS line {lid}: End must be A or B, got {t[1]!r}. Suggested fix: "
                                   "write A or B.")
        end = "AB".index(letter)
        if (lid, end) in out:
            raise rd.error(lineno, f"END CONNECTIONS line {lid} End {letter} is given twice. Suggested fix: keep one "
                                   "row per line end.")
        if len(t) > 6 and t[6].strip("'\"").lower() not in ("free", "zero", "0", "0.0"):
            raise rd.error(lineno, f"END CONNECTIONS line {lid} End {letter}: TorsStiffness {t[6]!r} restrains the "
                                   "line's twist, and seacable's line carries no torsion. Suggested fix: write Free.")
        token = t[2].strip("'\"").lower()
        if token in _PINNED or (token not in _RIGID and _as_float(token) == 0.0):
            continue
        rd.columns(lineno, t, 6, "END CONNECTIONS", "LineID End Stiffness EzX EzY EzZ")
        if token in _RIGID:
            kind, stiffness = "clamp", None
        else:
            stiffness = _as_float(token)
            if stiffness is None or not math.isfinite(stiffness) or stiffness < 0:
                raise rd.error(lineno, f"END CONNECTIONS line {lid} End {letter}: Stiffness {t[2]!r} must be Pinned, "
                                       "Rigid or a rotational stiffness >= 0 in N m/rad. Suggested fix: e.g. 1e5.")
            kind = "spring"
        d = [rd.number(lineno, v, f"END CONNECTIONS {c}", "-") for v, c in zip(t[3:6], ("EzX", "EzY", "EzZ"))]
        norm = math.sqrt(sum(v * v for v in d))
        if not norm > 0 or not math.isfinite(norm):
            raise rd.error(lineno, f"END CONNECTIONS line {lid} End {letter}: the direction ({', '.join(t[3:6])}) "
                                   "must be a non-zero vector along the line towards End B. Suggested fix: e.g. "
                                   "0 0 1 for a line rising vertically to a hang-off.")
        out[(lid, end)] = (kind, stiffness, tuple(v / norm for v in d))
    return out


def end_condition(kind: str, stiffness, direction, rotation=None):
    """The :class:`seacable.mooring.ends.EndCondition` of an END CONNECTIONS row (:func:`read_end_connections`),
    its direction turned into a body's axes by the transpose of ``rotation`` (the body's rotation at its given pose)
    when the end is on a body."""
    from ...mooring.ends import EndCondition

    d = [float(v) for v in direction]
    if rotation is not None:
        d = [float(sum(rotation[r][c] * d[r] for r in range(3))) for c in range(3)]
    declination = math.acos(max(-1.0, min(1.0, d[2])))
    azimuth = math.atan2(d[1], d[0]) if math.hypot(d[0], d[1]) > 1e-12 else 0.0
    if kind == "clamp":
        return EndCondition(type="clamped", declination=declination, azimuth=azimuth)
    return EndCondition(type="spring", declination=declination, azimuth=azimuth, stiffness=stiffness)


def read_attachments(rd, section, lines):
    """The lines with CableDyn's ATTACHMENTS rows (``LineID ArcLength Mass Volume CdA Ca [CdAx]``, the arc length
    one value or a series ``first:pitch:last``) as their ``attachments``: ``(s [m], mass [kg], volume [m^3], CdA
    [m^2], Ca [-], CdAx [m^2])`` from end A as written."""
    _, rows = _table(rd, section)
    by_id = {ln.id: ln for ln in lines}
    found: dict[int, list] = {}
    for lineno, t in rows:
        rd.columns(lineno, t, 6, "ATTACHMENTS", "LineID ArcLength Mass Volume CdA Ca [CdAx]")
        lid = _line_id(rd, lineno, t[0], "ATTACHMENTS", by_id)
        line = by_id[lid]
        parts = t[1].split(":")
        if len(parts) not in (1, 3):
            raise rd.error(lineno, f"ATTACHMENTS ArcLength {t[1]!r} must be one arc length or a series first:pitch:last"
                                   " (m). Suggested fix: e.g. 70.614:5.0:115.614.")
        values = [rd.number(lineno, v, "ATTACHMENTS ArcLength", "m") for v in parts]
        if len(values) == 3:
            first, pitch, last = values
            if not pitch > 0 or first > last:
                raise rd.error(lineno, f"ATTACHMENTS series {t[1]!r} needs a pitch > 0 and first <= last. "
                                       "Suggested fix: write first:pitch:last in metres.")
            count = math.floor((last - first) / pitch + 1e-9) + 1
            arcs = [first + k * pitch for k in range(count)]
        else:
            arcs = values
        mass, volume, cda, ca = (rd.number(lineno, v, f"ATTACHMENTS {c}", u) for v, c, u in
                                 zip(t[2:6], ("Mass", "Volume", "CdA", "Ca"), ("kg", "m^3", "m^2", "-")))
        cdax = rd.number(lineno, t[6], "ATTACHMENTS CdAx", "m^2") if len(t) > 6 else 0.0
        if min(mass, volume, cda, ca, cdax) < 0 or not any((mass, volume, cda, cdax)):
            raise rd.error(lineno, "ATTACHMENTS Mass, Volume, CdA, Ca and CdAx must be >= 0 and not all of Mass, "
                                   "Volume, CdA, CdAx 0. Suggested fix: give the module's mass (kg) and volume (m^3).")
        for s in arcs:
            if not 0.0 <= s <= line.length * (1 + 1e-12):
                raise rd.error(lineno, f"ATTACHMENTS arc length {s:g} m lies outside line {lid} (0 to "
                                       f"{line.length:g} m). Suggested fix: give arc lengths from the line's end A.")
            found.setdefault(lid, []).append((s, mass, volume, cda, ca, cdax))
    return [dataclasses.replace(ln, attachments=tuple(found.get(ln.id, ()))) for ln in lines]


def cabledyn_options(rd, section):
    """The OPTIONS section without CableDyn's own solver settings (keyword-first rows such as ``dynamic_solver``,
    and ``rhoInf``, ``TMax`` and the like: dropped as MoorDyn's ``dtM`` is); its ``frictionMu`` as MoorDyn's
    ``FrictionCoefficient``; its ``current`` and ``waves`` dropped when ``none`` and refused otherwise."""
    kind, header_no, header, body = section
    kept = []
    for lineno, line in body:
        tokens = line.split()
        if tokens and tokens[0].startswith("--"):  # CableDyn's comment row
            continue
        if tokens and (tokens[0].lower() in _KEYWORD_FIRST or (len(tokens) > 1 and tokens[1].lower() in _SOLVER)):
            continue
        if len(tokens) > 1 and tokens[1].lower() == "frictionmu":
            if tokens[0].lower() != "none":  # the seabed's Coulomb coefficient, MoorDyn's name for it
                kept.append((lineno, f"{tokens[0]} FrictionCoefficient"))
            continue
        at = next((k for k, w in enumerate(tokens[1:], 1) if w.lower() in _ENVIRONMENT), None)
        if at is not None:
            if [w.lower() for w in tokens[:at]] in (["none"], ["0"]):
                continue
            raise rd.error(lineno, f"CableDyn's option {tokens[at]} {' '.join(tokens[:at])!r} is not read by seacable's "
                                   "MoorDyn reader. Suggested fix: write 'none' there and give the current or waves in "
                                   "a seacable case file (environment.current, environment.waves).")
        kept.append((lineno, line))
    return (kind, header_no, header, kept)


def _whole(rd, lineno, token, what) -> int:
    value = _as_float(token)
    if value is None or value != int(value):
        raise rd.error(lineno, f"{what} must be a whole number, got {token!r}. Suggested fix: write an integer.")
    return int(value)

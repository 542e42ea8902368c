"""Quantities typed with units in case files (``speed: 3 kn``), turned into the SI number a field holds.

Every physical float of the case-file schema passes through :func:`seacable._model.quantity`, whose
check calls :func:`to_si` for a value that is text but not a plain number. The units are pint's
(its default registry, loaded once, on the first unit met: ``import seacable`` and a case file
written in plain SI numbers never load pint). A value is accepted when its dimension is the field's
and, pint counting the radian as dimensionless, when its angle exponent is the field's too, so that
``turn_rate: 3 deg/s`` is a rate of turn but ``turn_rate: 3 Hz`` (a factor 2 pi apart) and
``length: 3 m rad`` are refused. A few unit names that engineers read two ways are refused with the
names to write instead (:data:`AMBIGUOUS`).

References
----------
.. [1] pint, a Python package to define, operate and manipulate physical quantities,
   https://pint.readthedocs.io
"""

from __future__ import annotations

import functools
import re

__all__ = ["AMBIGUOUS", "UNIT_PATTERN", "UnitProblem", "to_si"]

#: Unit names read two ways in marine work -> what to write instead. pint would take the first reading
#: silently (``nm`` as a nanometre, ``ton`` as a short ton of 907 kg, ``kt`` as a knot).
AMBIGUOUS: dict[str, str] = {
    "nm": "'nmi' (nautical mile) or 'nanometer'",
    "ton": "'t' (tonne, 1000 kg), 'short_ton' or 'long_ton'",
    "tons": "'t' (tonne, 1000 kg), 'short_ton' or 'long_ton'",
    "kt": "'kn' (knot)",
    "kts": "'kn' (knot)",
}

#: What the JSON schema says a field with a unit accepts besides a number (a number, a space, a unit)
UNIT_PATTERN = r"^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*\S.*$"

_WORD = re.compile(r"[A-Za-z_\u00b0\u00b5\u03bc\u2126]+")


class UnitProblem(ValueError):
    """A value typed with a unit that cannot be the field's quantity; the message reads on from the key."""


@functools.cache
def _registry():
    import pint  # a fifth of a second with its registry: only when a case file holds a unit

    return pint.UnitRegistry()


def _angle_exponent(registry, units) -> float:
    """The power of the radian in ``units`` (pint counts the radian as dimensionless, a factor 2 pi away)."""
    return dict(registry.get_root_units(units)[1]._units).get("radian", 0)


_KINDS = {("[length]", 0): "a length", ("[mass]", 0): "a mass", ("[time]", 0): "a time",
          ("[length] / [time]", 0): "a speed", ("[mass] * [length] / [time] ** 2", 0): "a force",
          ("[mass] / [length]", 0): "a mass per length", ("[mass] / [length] ** 3", 0): "a density",
          ("[mass] / [length] / [time] ** 2", 0): "a pressure", ("[length] ** 2", 0): "an area",
          ("[length] ** 3", 0): "a volume", ("1 / [time]", 0): "a frequency",
          ("[length] / [time] ** 2", 0): "an acceleration", ("dimensionless", 0): "a number without unit",
          ("dimensionless", 1): "an angle", ("1 / [time]", 1): "a rate of turn",
          ("[mass] / [time] ** 2", 0): "a force per length", ("[mass] * [length] / [time]", 0): "an impulse"}


def _kind(registry, units) -> str:
    """What a quantity in ``units`` is, in words ("a speed", "an angle"), or its dimension."""
    key = (str(units.dimensionality), _angle_exponent(registry, units))
    return _KINDS.get(key, f"a quantity of dimension {key[0]}" + (f" x angle^{key[1]:g}" if key[1] else ""))


def to_si(value: str, unit: str) -> float:
    """The number of SI ``unit`` in ``value``, a number followed by a unit (``"3 kn"``, ``"45 deg"``).

    Parameters
    ----------
    value : str
        The value as typed in the case file.
    unit : str
        The field's SI unit, as :func:`seacable._model.quantity` declares it (``"m/s"``, ``"rad"``,
        ``"N m/rad"``). [-]

    Returns
    -------
    float
        ``value`` in ``unit``. [unit]

    Raises
    ------
    UnitProblem
        An unknown or ambiguous unit, a dimension or an angle exponent other than the field's, or a field
        without dimension (a ratio, a coefficient), which takes a plain number only.
    """
    try:
        return float(value)   # a plain number is in the field's unit already
    except ValueError:
        pass
    for word in _WORD.findall(value):
        if word in AMBIGUOUS:
            raise UnitProblem(f"has an ambiguous unit '{word}' in {value!r}. "
                              f"Suggested fix: write {AMBIGUOUS[word]}.")
    if unit in ("", "-", "1") or "^m" in unit:
        raise UnitProblem(f"takes a plain number (no unit), got {value!r}. Suggested fix: write the number alone.")
    import pint

    registry = _registry()
    try:
        target = registry.Unit(unit)
    except Exception:  # noqa: BLE001  (a field whose unit pint cannot read, as "m, rad": no units there)
        raise UnitProblem(f"takes a plain number in {unit}, got {value!r}. Suggested fix: write the number "
                          f"in {unit}.") from None
    kind = _kind(registry, target)
    example = {"an angle": " (as '45 deg' or '0.8 rad')", "a rate of turn": " (as '3 deg/s')",
               "a speed": " (as '3 kn')", "a force": " (as '7500 kN')", "a mass": " (as '10 t')",
               "a length": " (as '160 mm')"}.get(kind, "")
    fix = f"Suggested fix: write {kind}{example}, or a plain number in {unit}."
    try:
        quantity = registry.Quantity(value)
    except pint.UndefinedUnitError as err:
        name = err.unit_names[0] if getattr(err, "unit_names", None) else ""
        raise UnitProblem(f"has an unknown unit {name!r} in {value!r}, expected {kind} in {unit}. {fix} "
                          "Units are spelled as pint spells them (mm, m, nmi, kn, deg, rad, s, kN, MN, t, kg/m).") from None
    except Exception:  # noqa: BLE001  (pint's parser raises many kinds for text that is no quantity)
        raise UnitProblem(f"must be {kind} in {unit}, got {value!r}. {fix}") from None
    if not isinstance(quantity, registry.Quantity) or not isinstance(quantity.magnitude, (int, float)):
        raise UnitProblem(f"must be {kind} in {unit}, got {value!r}. {fix}")
    if (quantity.dimensionality != target.dimensionality
            or _angle_exponent(registry, quantity.units) != _angle_exponent(registry, target)):
        raise UnitProblem(f"must be {kind} in {unit}, got {value!r}, {_kind(registry, quantity.units)}. {fix}")
    return float(quantity.to(target).magnitude)

"""The base of every input object: immutable, picklable, validated on construction.

Input objects (line types, environments, cases) are frozen pydantic models. A
value is checked where it is declared, with its unit, through :func:`quantity`;
a number may also be written with a unit (``"3 kn"``), read into the field's SI
unit by :mod:`seacable._units`; every validation failure, whether the object is built in code or read from a
case file, surfaces as one :class:`~seacable.errors.InputError` whose lines name
the key path, the value with its unit, what was expected and a fix. Unknown keys
get a "did you mean" suggestion.
"""

from __future__ import annotations

import difflib
import math
from typing import Annotated, Any

import yaml
from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, ValidationError, model_validator

from .errors import InputError

__all__ = ["Model", "quantity", "unit_float", "dump_yaml", "load_yaml", "YAML_LOADER", "format_validation_error", "input_error", "suggest"]


def dump_yaml(model: BaseModel) -> str:
    """The model as YAML text, every value explicit (defaults included): a case as a case file holds it.

    Here, below the results and the case-file reader, so that a result records its case
    (:func:`seacable.results.make_dataset`) without importing the reader (:func:`seacable.io.dump_case`).
    """
    return yaml.dump(model.model_dump(mode="json"), Dumper=_DUMPER, sort_keys=False)


#: PyYAML's safe dumper, its C emitter (libyaml) when PyYAML has it: the same text as ``yaml.safe_dump``, in a
#: fifth of the time (a result stamps its case with it: :func:`seacable.results.make_dataset`)
_DUMPER = getattr(yaml, "CSafeDumper", yaml.SafeDumper)

#: PyYAML's safe loader, its C parser (libyaml) when PyYAML has it: the same data as ``yaml.safe_load`` (the same
#: Python constructor and resolver), in about a sixth of the time
YAML_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def load_yaml(text: str):
    """``yaml.safe_load`` of ``text`` with libyaml's parser when PyYAML has it (:data:`YAML_LOADER`)."""
    return yaml.load(text, Loader=YAML_LOADER)


def suggest(word: str, choices) -> str:
    """Return ``" Did you mean 'x'?"`` for the closest of ``choices``, or ``""``."""
    close = difflib.get_close_matches(str(word), [str(c) for c in choices], n=1, cutoff=0.6)
    return f" Did you mean '{close[0]}'?" if close else ""


def _number_checker(unit: str, gt, ge, lt, le, fix: str | None):
    shown_unit = "" if unit in ("", "-") else f" {unit}"
    hint = f" Suggested fix: {fix}" if fix else ""

    def check(value: Any) -> float:
        number = value
        if isinstance(value, str):  # YAML 1.1 reads "1e9" as text
            try:
                number = float(value)
            except ValueError:
                if any(c.isdigit() for c in value):  # a number with a unit ("3 kn"): its SI number
                    from ._units import to_si

                    number = to_si(value, unit)
        if isinstance(number, bool) or not isinstance(number, (int, float)):
            raise ValueError(f"must be a number{shown_unit and ' in' + shown_unit}, got {value!r}."
                             + (hint or " Suggested fix: write a plain number in SI units."))
        value = float(number)
        if not math.isfinite(value):
            raise ValueError(f"must be a finite number, got {value}{shown_unit}.{hint}")
        for bound, ok, sign in ((gt, lambda v, b: v > b, ">"), (ge, lambda v, b: v >= b, ">="),
                                (lt, lambda v, b: v < b, "<"), (le, lambda v, b: v <= b, "<=")):
            if bound is not None and not ok(value, bound):
                raise ValueError(f"must be {sign} {bound:g}{shown_unit}, got {value:g}{shown_unit}.{hint}")
        return value

    return check


def _unit_schema(unit: str):
    """The JSON schema of a field in ``unit``: a number in SI, or (with a dimension) a number with a unit as text."""
    if unit in ("", "-", "1") or "^m" in unit:
        return {"unit": unit}

    def edit(schema: dict) -> None:
        from ._units import UNIT_PATTERN

        schema.pop("type", None)
        schema["unit"] = unit
        schema["anyOf"] = [{"type": "number"},
                           {"type": "string", "pattern": UNIT_PATTERN,
                            "description": f"a number and a unit convertible to {unit} (as '3 kn', '45 deg', '7500 kN')"}]

    return edit


def quantity(unit: str, *, gt: float | None = None, ge: float | None = None, lt: float | None = None,
             le: float | None = None, fix: str | None = None):
    """A float field in SI ``unit`` with bounds, checked with a house-style message.

    Use as a type: ``diameter: quantity("m", gt=0) = Field(description="... [m]")``.
    Strings holding numbers (``"1e9"``, as YAML 1.1 reads them) are accepted, and so are a
    number with a unit (``"3 kn"``, ``"45 deg"``, ``"7500 kN"``), turned into ``unit`` by
    :func:`seacable._units.to_si` (a unit of another dimension, an unknown or an ambiguous one is
    an error naming the key); booleans, NaN and infinities are not.
    """
    return Annotated[float, BeforeValidator(_number_checker(unit, gt, ge, lt, le, fix)),
                     Field(json_schema_extra=_unit_schema(unit))]


def _unit_converter(unit: str):
    def convert(value: Any) -> Any:
        if isinstance(value, str) and any(c.isdigit() for c in value):
            try:
                float(value)
            except ValueError:
                from ._units import to_si

                return to_si(value, unit)
        return value

    return convert


def unit_float(unit: str):
    """A float in SI ``unit`` that also takes a number with a unit (``"120 m"``), for the items of vectors and tables.

    Unlike :func:`quantity` it adds no check of its own: a plain number is validated as the field's ``float``
    always was (so that a vector's own checks and messages stay), a number with a unit is turned into ``unit``
    by :func:`seacable._units.to_si`. Use as an item type: ``fairlead: tuple[unit_float("m"), unit_float("m")]``.
    """
    return Annotated[float, BeforeValidator(_unit_converter(unit)), Field(json_schema_extra=_unit_schema(unit))]


#: Values of discriminated-union tags; pydantic puts them in error locations, where they
#: would read as keys (``analysis.static.fairlead``), so they are left out of paths.
UNION_TAGS: set[str] = set()


def _path(loc) -> str:
    parts: list[str] = []
    for i, item in enumerate(loc):
        # a union's tag stands before the member's own field (a field of the same name, as payout 'slack''s
        # 'slack', comes after it, or last, or before an index)
        if (i > 0 and isinstance(item, str) and item in UNION_TAGS and i + 1 < len(loc)
                and isinstance(loc[i + 1], str)):
            continue
        if isinstance(item, int):
            parts.append(f"[{item}]")
        elif str(item).startswith("function-") or str(item) in ("tagged-union",):
            continue
        else:
            parts.append(("." if parts else "") + str(item))
    return "".join(parts)


def _problems(error: ValidationError) -> list[tuple[tuple, str]]:
    """(key path, message tail) of each problem; tails read on from the path."""
    out: list[tuple[tuple, str]] = []
    for err in error.errors(include_url=False):
        loc = tuple(err.get("loc", ()))
        kind, msg, ctx = err.get("type", ""), err.get("msg", ""), err.get("ctx") or {}
        inner = ctx.get("error")
        if kind == "value_error" and isinstance(inner, InputError) and getattr(inner, "problems", None):
            # A nested seacable object raised its own problems: put them under this path.
            out.extend((loc + sub, tail) for sub, tail in inner.problems)
            continue
        if kind == "value_error":
            msg = msg.removeprefix("Value error, ")
            tail = f" {msg}" if msg[:1].islower() else f": {msg}"
        elif kind == "missing":
            tail = f" is required but missing. Suggested fix: add the key '{loc[-1]}'."
        elif kind == "extra_forbidden":
            tail = ": unknown key."
        elif kind == "union_tag_invalid":
            tag, expected = ctx.get("tag"), ctx.get("expected_tags", "")
            choices = [t.strip(" '") for t in str(expected).split(",")]
            loc = loc + (str(ctx.get("discriminator", "type")).strip("'"),)
            tail = f" must be one of {expected}, got '{tag}'.{suggest(tag, choices)}"
        elif kind == "union_tag_not_found":
            tail = ": the key 'type' is missing. Suggested fix: add 'type:' naming what to compute."
        elif kind == "literal_error":
            expected = ctx.get("expected", "")
            choices = [t.strip(" '") for t in str(expected).replace(" or ", ",").split(",")]
            tail = f" must be {expected}, got {err.get('input')!r}.{suggest(err.get('input'), choices)}"
        elif kind in ("dict_type", "model_type", "dataclass_type", "model_attributes_type"):
            tail = f" must be a mapping of keys to values, got {err.get('input')!r}."
        elif kind in ("tuple_type", "list_type"):
            tail = f" must be a list, got {err.get('input')!r}."
        elif kind == "too_short" and any(len(e["loc"]) > len(loc) and tuple(e["loc"][:len(loc)]) == loc
                                         for e in error.errors(include_url=False)):
            continue  # an item inside failed; pydantic then also counts the container short
        else:
            tail = f": {msg} (got {err.get('input')!r})."
        out.append((loc, tail))
    return list(dict.fromkeys(out))


def _join(problems: list[tuple[tuple, str]], root: str) -> str:
    lines = [(_path(((root,) if root else ()) + loc) + tail).lstrip(": ") for loc, tail in problems]
    if len(lines) == 1:
        return lines[0]
    return f"{len(lines)} problems:\n" + "\n".join(f"  - {line}" for line in lines)


def format_validation_error(error: ValidationError, root: str = "") -> str:
    """Turn a pydantic ValidationError into seacable's one-line-per-problem text."""
    return _join(_problems(error), root)


def input_error(problems: list[tuple[tuple, str]], root: str = "") -> InputError:
    """An InputError listing ``problems`` ((key path, message tail) pairs) under ``root``."""
    exc = InputError(_join(problems, root))
    exc.problems = problems
    return exc


class Model(BaseModel):
    """Frozen, validated, picklable base of all seacable input objects.

    Construction errors raise :class:`~seacable.errors.InputError`, never a
    pydantic error, so that callers need to know one exception type.
    """

    model_config = ConfigDict(frozen=True, extra="forbid", validate_default=True,
                              arbitrary_types_allowed=False, populate_by_name=True)

    def __init__(self, /, **data: Any) -> None:
        try:
            super().__init__(**data)
        except ValidationError as err:
            raise input_error(_problems(err), type(self).__name__) from None

    @classmethod
    def parse(cls, data: Any, *, root: str = ""):
        """Validate plain data (as read from a file) into this class.

        Parameters
        ----------
        data
            A mapping of keys to values.
        root
            A prefix for the key paths in error messages.
        """
        try:
            return cls.model_validate(data)
        except ValidationError as err:
            raise input_error(_problems(err), root) from None

    @model_validator(mode="before")
    @classmethod
    def _reject_unknown_keys(cls, data: Any) -> Any:
        if isinstance(data, dict):
            known = set(cls.model_fields)
            known |= {f.alias for f in cls.model_fields.values() if f.alias}
            for key in data:
                if key not in known:
                    listing = ", ".join(sorted(k for k in cls.model_fields if not k.startswith("_")))
                    raise ValueError(f"has an unknown key '{key}'.{suggest(key, known)} "
                                     f"Known keys here: {listing}.")
        return data

    def replace(self, **changes: Any):
        """Return a copy with some fields changed, validated again."""
        return type(self)(**{**{k: getattr(self, k) for k in type(self).model_fields}, **changes})

    def model_copy(self, *, update: dict[str, Any] | None = None, deep: bool = False):
        """A copy; with ``update``, the changed copy validated again as :meth:`replace` makes it.

        Pydantic's own ``model_copy(update=...)`` skips validation: a negative length, or a case whose line
        types changed while its line kept the old ones, would pass silently to a run.
        """
        if update:
            return self.replace(**update)
        return super().model_copy(deep=deep)

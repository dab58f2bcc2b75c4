"""The API type of each input, from its row of the field table (``api_type``).

Text numbers (a query string, or a string in JSON) must be plain ASCII decimals
(``NUMBER_TEXT``): the page parses its form with the same rule, so both accept the
same. A number is finite and within its row's bounds (``bounded_number``); a text or
list of texts keeps to ``TEXT_PATTERN``; a torque curve is 'rpm:torque' points or JSON
pairs, rising in speed (``curve_type``); a retired choice reads as its current one.
"""

import json
import math
import re
from collections.abc import Callable
from typing import Annotated, Any, Literal

from pydantic import (
    AfterValidator,
    BeforeValidator,
    Field,
    SerializationInfo,
    SerializerFunctionWrapHandler,
    WithJsonSchema,
    WrapSerializer,
)
from pydantic_core import PydanticCustomError

from app.contract.input_field import InputField

#: optional sign, digits with an optional point (or a point and digits), optional exponent.
ASCII_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
ASCII_SPACE = " \t\n\r\f\v"
#: the error for text that is not a number: pydantic's type, and what the API expects (the
#: page form also reads a decimal comma and fractions, ``app.contract.exact.read_exact``).
NOT_A_NUMBER = {
    "float": (
        "float_parsing",
        "Input should be a valid number: a JSON number, or as text an ASCII decimal such "
        "as 20.5 or 1.5e3 (no decimal comma, fraction or digit grouping)",
    ),
    "int": ("int_parsing", "Input should be a valid integer, unable to parse string as an integer"),
}


def _not_bool(value: Any) -> Any:
    """JSON true/false is not a number (pydantic's lax mode would read it as 1/0)."""
    if isinstance(value, bool):
        raise ValueError("must be a number, not a boolean")
    return value


def _number_text(target: Literal["float", "int"]) -> BeforeValidator:
    """Refuse number text other than an ASCII decimal: no '１００', '1_000', 'nan' or 'inf'.

    Python's float() and pydantic's lax parsing accept all of those; the rule keeps the
    API's query and the page's form to what an engineer types. Non-text passes unchanged.
    """

    def check(value: Any) -> Any:
        if not isinstance(value, str):
            return value
        text = value.strip(ASCII_SPACE)
        if not ASCII_NUMBER.fullmatch(text):
            raise PydanticCustomError(*NOT_A_NUMBER[target])
        return text

    return BeforeValidator(check)


NotBool = BeforeValidator(_not_bool)
NUMBER_TEXT = _number_text("float")
WHOLE_NUMBER_TEXT = _number_text("int")


def bounded_number(ge: float, le: float, description: str) -> Any:
    """Finite number in [ge, le]; the bounds keep every result finite.

    Put it first in ``Annotated``, before any validator: pydantic writes the bounds as JSON
    Schema's ``minimum`` and ``maximum`` only on the inner type.
    """
    return Field(ge=ge, le=le, allow_inf_nan=False, description=description)


def describe(field: InputField) -> str:
    """The field's API description from the table: label, API unit, help (its
    ``api_help`` where it has one), and for a yes-no field shown as a choice what true and
    false mean (a field without help: its label and unit alone). A box the page leaves
    empty is a field the API leaves out: the help's "empty" reads "left out".

    >>> from app.contract.fields import BY_API
    >>> describe(BY_API["ambient_c"])
    'Ambient temperature [°C]. Around the screw.'
    >>> describe(BY_API["positioning_tolerance_mm"])
    'Positioning tolerance [mm]. Allowed positioning error; left out for no check.'
    """
    unit = f" [{field.unit}]" if field.unit else ""
    meanings = "".join(f" {c.value}: {c.text}." for c in field.choices if field.kind == "yes-no")
    words = field.api_help or re.sub(r"\bempty\b", "left out", field.help)
    return f"{field.label}{unit}." + (f" {words}." if words else "") + meanings


#: Text inputs (ids, material names): letters, digits and a few separators, 1-60 long.
TEXT_PATTERN = r"^[A-Za-z0-9][A-Za-z0-9 ._()+/-]{0,59}$"
#: At most this many items in a list input.
MAX_ITEMS = 50


def _split_text(value: Any) -> Any:
    """A list input given as text ('TR-C45, B' from the page or a share link) as a list;
    a repeated query parameter or a JSON list as its items, each without the spaces
    around it (as the page reads them: ``["B "]`` is family B)."""
    if isinstance(value, str):
        return [item.strip() for item in value.split(",") if item.strip()]
    if isinstance(value, list):
        return [item.strip() if isinstance(item, str) else item for item in value]
    return value


def _one_text(none_word: str) -> BeforeValidator:
    """A text input as the page reads it: without the spaces around it, and the field's
    word for none in any case ('ANY' is 'any'), so that the API and a share link of its
    answer select the same."""

    def clean(value: Any) -> Any:
        if not isinstance(value, str):
            return value
        text = value.strip()
        return none_word if none_word and text.casefold() == none_word else text

    return BeforeValidator(clean)


def _each_text(value: list[str]) -> list[str]:
    """Every item of a list input is text of ``TEXT_PATTERN`` (the error names the field)."""
    for item in value:
        if not re.fullmatch(TEXT_PATTERN, item):
            raise ValueError(f"'{item[:60]}' is not an id: letters, digits and . _ ( ) + / -")
    return value


def _list_out(
    value: list[str], handler: SerializerFunctionWrapHandler, info: SerializationInfo
) -> Any:
    """A list input as JSON keeps its list; as Python values (share links, the printed
    summary, CSV) it is the comma-separated text the page reads back."""
    return handler(value) if info.mode_is_json() else ",".join(value)


def text_type(field: InputField) -> Any:
    """Text, or a list of texts, matching ``TEXT_PATTERN``; a list also as comma text."""
    if field.kind == "text":
        text = Field(pattern=TEXT_PATTERN, description=describe(field))
        return Annotated[str, text, _one_text(field.none_word)]
    schema = {"type": "array", "items": {"type": "string"}, "minItems": 1}
    schema |= {"maxItems": MAX_ITEMS, "description": describe(field)}
    return Annotated[
        list[str],
        BeforeValidator(_split_text),
        AfterValidator(_each_text),
        WrapSerializer(_list_out),
        Field(min_length=1, max_length=MAX_ITEMS),
        WithJsonSchema(schema),
    ]


#: At most this many points in a curve input.
MAX_POINTS = 50
#: One point of a curve as text: "x:y" (query strings) or "x y" (a line on the page).
POINT_SEPARATOR = re.compile(r"\s*[:\s]\s*")


def _point(text: str, number: int) -> list[float]:
    """One point typed as 'x:y' or 'x y', as two numbers; the error names the point."""
    parts = POINT_SEPARATOR.split(text.strip(ASCII_SPACE))
    if len(parts) != 2 or not all(ASCII_NUMBER.fullmatch(p) for p in parts):
        raise ValueError(f"point {number} '{text.strip()[:40]}' is not two numbers 'rpm torque'")
    return [float(parts[0]), float(parts[1])]


def _json_points(text: str) -> Any:
    """A curve written as JSON: ``[[rpm, torque], ...]``, or one point ``[rpm, torque]``
    (a repeated query parameter) as a list of that one point."""
    try:
        parsed = json.loads(text)
    except (ValueError, RecursionError):
        raise ValueError(f"'{text[:40]}' is not a JSON list of [rpm, torque] pairs") from None
    if isinstance(parsed, list) and parsed and not any(isinstance(x, list) for x in parsed):
        return [parsed]
    return parsed


def _text_points(text: str, first: int) -> list[Any]:
    """The points of one text: JSON, or ``rpm:torque`` items separated by commas, lines or
    semicolons ('rpm torque' on a line; one 'rpm,torque' pair alone); numbered from
    ``first`` in the errors."""
    text = text.strip(ASCII_SPACE)
    if text.startswith("["):
        points = _json_points(text)
        return points if isinstance(points, list) else [points]
    items = [item.strip(ASCII_SPACE) for item in re.split(r"[,\n;]", text)]
    items = [item for item in items if item]
    if len(items) == 2 and all(ASCII_NUMBER.fullmatch(item) for item in items):
        items = [" ".join(items)]
    return [_point(item, number) for number, item in enumerate(items, start=first)]


def _split_curve(value: Any) -> Any:
    """A curve given as text (``rpm:torque,rpm:torque``, lines of 'rpm torque', or JSON
    ``[[rpm, torque], ...]``) as a list of pairs; a query parameter arrives as a list of
    such texts, one per occurrence (each one point or several). A JSON list of pairs
    passes unchanged, each item checked to be a pair of numbers."""
    if isinstance(value, str):
        value = [value]
    if isinstance(value, list) and value and all(isinstance(item, str) for item in value):
        points: list[Any] = []
        for text in value:
            points += _text_points(text, len(points) + 1)
        value = points
    if isinstance(value, list):
        for number, point in enumerate(value, start=1):
            if not isinstance(point, list | tuple) or len(point) != 2:
                raise ValueError(f"point {number} is not a pair [rpm, torque]")
            if not all(isinstance(x, int | float) and not isinstance(x, bool) for x in point):
                raise ValueError(f"point {number} is not two numbers [rpm, torque]")
    return value


def _curve_points(value: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """At least two points, finite, rpm not negative and strictly ascending, torque
    positive, at most ``MAX_POINTS``; the error names the first point that is wrong."""
    if not 2 <= len(value) <= MAX_POINTS:
        raise ValueError(f"needs 2 to {MAX_POINTS} points (rpm, torque), not {len(value)}")
    previous = -math.inf
    for number, (rpm, torque) in enumerate(value, start=1):
        point = f"point {number} ({rpm:g}, {torque:g})"
        if not (math.isfinite(rpm) and math.isfinite(torque)):
            raise ValueError(f"{point}: rpm and torque must be finite")
        if rpm < 0.0 or torque <= 0.0:
            raise ValueError(f"{point}: rpm must be 0 or more and torque above 0")
        if rpm <= previous:
            raise ValueError(f"{point}: rpm must ascend")
        previous = rpm
    return value


def _curve_out(
    value: list[tuple[float, float]],
    handler: SerializerFunctionWrapHandler,
    info: SerializationInfo,
) -> Any:
    """A curve as JSON keeps its pairs; as Python values (share links, the printed
    summary, CSV) it is the compact ``rpm:torque,rpm:torque`` text the page reads back."""
    if info.mode_is_json():
        return handler(value)
    return ",".join(f"{exact_text(rpm)}:{exact_text(torque)}" for rpm, torque in value)


def exact_text(value: float) -> str:
    """The shortest decimal that reads back to ``value`` exactly.

    >>> exact_text(749.9999992498), exact_text(3000.0), exact_text(1e-7)
    ('749.9999992498', '3000', '1e-07')
    """
    return repr(float(value)).removesuffix(".0")


def curve_type(field: InputField) -> Any:
    """Points (rpm, torque): JSON pairs, or text ``rpm:torque,...`` / lines 'rpm torque'."""
    pair = {"type": "array", "items": {"type": "number"}, "minItems": 2, "maxItems": 2}
    schema = {"type": "array", "items": pair, "minItems": 2, "maxItems": MAX_POINTS}
    schema |= {"description": describe(field)}
    return Annotated[
        list[tuple[Annotated[float, NotBool], Annotated[float, NotBool]]],
        BeforeValidator(_split_curve),
        AfterValidator(_curve_points),
        WrapSerializer(_curve_out),
        WithJsonSchema(schema),
    ]


def _retired(field: InputField) -> Callable[[Any], Any]:
    """A choice's retired value read as the value it now means (``InputField.retired``).

    >>> from app.contract.fields import BY_API
    >>> _retired(BY_API["advice"])("rank"), _retired(BY_API["advice"])(["rank"])
    ('warn', ['rank'])
    """

    def current(value: Any) -> Any:
        return field.retired.get(value, value) if isinstance(value, str) else value

    return current


def api_type(field: InputField) -> Any:
    """The pydantic type of one table field: bounded finite number, whole number, bool or
    the core's Literal; optional (``| None``) when it has no default and is not required."""
    low, high = field.bounds or (0.0, 0.0)
    if field.kind == "number":
        # the bounds before the validators: pydantic publishes them as minimum and maximum
        # only on the inner type (after a validator they would be ge/le, not JSON Schema)
        kind: Any = Annotated[
            float, bounded_number(low, high, describe(field)), NotBool, NUMBER_TEXT
        ]
    elif field.kind == "whole number":
        bounded = Field(ge=int(low), le=int(high), description=describe(field))
        kind = Annotated[int, bounded, NotBool, WHOLE_NUMBER_TEXT]
    elif field.kind == "yes-no":
        kind = Annotated[bool, Field(description=describe(field))]
    elif field.kind in ("text", "list"):
        kind = text_type(field)
    elif field.kind == "curve":
        kind = curve_type(field)
    else:
        kind = Annotated[
            field.options, Field(description=describe(field)), BeforeValidator(_retired(field))
        ]
    if field.required or field.default is not None:
        return kind
    # the description again outside the union: OpenAPI shows a parameter's own
    # description, not the one inside anyOf's first branch
    return Annotated[kind | None, Field(description=describe(field))]

"""The API's application input model, generated from the field table (``app.contract.fields``).

``ApplicationIn`` is built with ``pydantic.create_model`` from ``FIELDS``: one field per
table row, with its bounds, default and description, so the API, the page and the share
links cannot disagree about an input. Everything that is not per field lives in the
hand-written base ``ApplicationInputs``: ``extra="forbid"``, the rule that a field's
``needs`` are given, and ``to_core`` (the SI ``Application`` of the core).

Typing: mypy cannot see the fields of a model made at run time, so for mypy
``ApplicationIn`` is the base class itself. Reading an input as an attribute
(``inputs.<api name>``) is then a type error on purpose; code reads ``inputs.to_core()``, a
typed dataclass in SI, or goes through the table.

Text numbers (a query string, or a string in JSON) must be plain ASCII decimals
(``NUMBER_TEXT``): the page parses its form with the same rule, so both accept the same.
"""

import json
import math
import re
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import (
    AfterValidator,
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    SerializationInfo,
    SerializerFunctionWrapHandler,
    ValidationError,
    ValidationInfo,
    WithJsonSchema,
    WrapSerializer,
    create_model,
    field_validator,
    model_validator,
)
from pydantic_core import InitErrorDetails, PydanticCustomError

from app.catalog.motors import Motor, check_motor, with_motor
from app.catalog.supports import SupportUnit, check_support, with_support
from app.contract.cycle import MAX_MOVES, MoveIn, closing_error_mm, parse_moves_text, span_mm
from app.contract.fields import BY_API, FIELDS, InputField
from app.core import motion
from app.core.model import Application

#: The API name of each core attribute.
API_OF = {field.core: field.api for field in FIELDS}
#: Seconds in a day, the most the cycles of a day can take [s].
SECONDS_PER_DAY = 86400.0

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
    """The field's API description from the table: label, API unit, help, and for a yes-no
    field shown as a choice what true and false mean.

    >>> describe(BY_API["ambient_c"])
    'Ambient temperature [°C]. Around the screw.'
    """
    unit = f" [{field.unit}]" if field.unit else ""
    meanings = "".join(f" {c.value}: {c.text}." for c in field.choices if field.kind == "yes-no")
    return f"{field.label}{unit}. {field.help}.{meanings}"


#: Text inputs (ids, material names): letters, digits and a few separators, 1-60 long.
TEXT_PATTERN = r"^[A-Za-z0-9][A-Za-z0-9 ._()+/-]{0,59}$"
#: At most this many items in a list input.
MAX_ITEMS = 50
#: The screw's length, which bounds the span from the thrust bearing to the nut.
LENGTH = next(field for field in FIELDS if field.core == "length_m")
#: The support unit of the library that rates the thrust bearing.
SUPPORT = next(field for field in FIELDS if field.core == "support_unit")


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


def _definitions() -> dict[str, Any]:
    """``create_model`` field definitions: API name -> (type, default or ``...``)."""
    return {f.api: (api_type(f), ... if f.required else f.default) for f in FIELDS}


def check_drivable(value: float | None, supply_v: float, current_a: float, ohm: float) -> None:
    """The drive voltage must exceed the winding's I R, or the current is never reached."""
    if value is not None and supply_v <= current_a * ohm:
        raise ValueError(
            f"a {supply_v:g} V drive cannot push {current_a:g} A through {ohm:g} ohm: "
            "raise the drive voltage or lower the phase current"
        )


class ApplicationInputs(BaseModel):
    """The axis an engineer wants to drive, in the API units named by each field.

    Lower bounds are physical (1 mN, 1 um/s, 1 mm ...) rather than "> 0", so that no
    input can drive a result to overflow or to zero division.
    """

    model_config = ConfigDict(extra="forbid")

    moves: Annotated[list[MoveIn], BeforeValidator(parse_moves_text)] = Field(
        default_factory=list,
        max_length=MAX_MOVES,
        description="The cycle as its moves, each with its own distance, speed, ramps, "
        "dwell, mass and load (``app.contract.cycle``); in a query string one text, "
        "distance:speed:accel:decel:dwell:mass:load:direction in mm, mm/s, mm/s², s, kg "
        "and N, moves joined by ';'. Empty: out and back over the stroke from the scalar "
        "inputs. With moves, the stroke (when not given) is the span the nut covers.",
    )

    @field_validator("*")
    @classmethod
    def _needs(cls, value: Any, info: ValidationInfo) -> Any:
        """A field with ``needs`` (the required life) is refused without those fields.

        Fields validate in table order, so the needed ones are already in ``info.data``.
        """
        field = BY_API.get(str(info.field_name))
        needs = () if field is None else field.needs
        if value is not None and any(info.data.get(name) is None for name in needs):
            raise ValueError("needs " + " and ".join(needs))
        return value

    @field_validator("hours_per_day", check_fields=False)
    @classmethod
    def _one_duty(cls, value: float | None, info: ValidationInfo) -> float | None:
        """The duty is cycles a day or hours a day, never both (they could disagree)."""
        if value is not None and info.data.get("cycles_per_day") is not None:
            raise ValueError("give cycles_per_day or hours_per_day, not both")
        return value

    @field_validator("required_life_years", check_fields=False)
    @classmethod
    def _a_duty(cls, value: float | None, info: ValidationInfo) -> float | None:
        """A required life needs a duty to turn a life into years: cycles or hours a day."""
        given = [info.data.get(name) for name in ("cycles_per_day", "hours_per_day")]
        if value is not None and all(v is None for v in given):
            raise ValueError("needs cycles_per_day or hours_per_day")
        return value

    @field_validator("motor", check_fields=False)
    @classmethod
    def _known_motor(cls, value: str | None, info: ValidationInfo) -> str | None:
        """Read in any case and without the spaces around it, held as the library writes
        its ids (``check_motor``), so the API, the page and the share link carry one id;
        checked against the library passed as validation context (the page's form), the
        API's body where the catalog is (``to_core``)."""
        motors = (info.context or {}).get("motors") if isinstance(info.context, dict) else None
        return check_motor(BY_API["motor"].to_si(value), motors)

    @field_validator(SUPPORT.api, check_fields=False)
    @classmethod
    def _known_support(cls, value: str | None, info: ValidationInfo) -> str | None:
        """Checked against the support library passed as validation context (the page's
        form); the API's body is checked where the catalog is (``to_core``)."""
        context = info.context if isinstance(info.context, dict) else {}
        return check_support(SUPPORT.to_si(value), context.get("supports"))

    @field_validator("bearing_to_nut_mm", check_fields=False)
    @classmethod
    def _within_length(cls, value: float | None, info: ValidationInfo) -> float | None:
        """The span from the thrust bearing to the nut lies on the screw."""
        length = info.data.get(LENGTH.api)
        if value is not None and length is not None and value > length:
            raise ValueError(f"at most the screw length, {length:g} ({LENGTH.api})")
        return value

    @field_validator("max_step_rate_hz", check_fields=False)
    @classmethod
    def _step_angle_known(cls, value: float | None, info: ValidationInfo) -> float | None:
        """A step rate limit needs the step angle, given or the library motor's."""
        known = info.data.get("step_angle_deg") is not None or info.data.get("motor")
        if value is not None and not known:
            raise ValueError('needs step_angle_deg or a library motor ("any" for every one)')
        return value

    @field_validator("motor_holding_torque_nm", check_fields=False)
    @classmethod
    def _drivable(cls, value: float | None, info: ValidationInfo) -> float | None:
        names = ("motor_supply_v", "motor_phase_current_a", "motor_resistance_ohm")
        given = [info.data.get(name) for name in names]
        if all(v is not None for v in given):
            check_drivable(value, *(float(v or 0.0) for v in given))
        return value

    @field_validator(API_OF["stroke_m"], check_fields=False)
    @classmethod
    def _stroke_fits(cls, value: float | None, info: ValidationInfo) -> float | None:
        """The nut travels between the screw's ends: the stroke is at most the screw
        length less the nut length given (less nothing without one: each catalog nut's
        own length is then the stroke-travel check's)."""
        length = info.data.get(API_OF["length_m"])
        nut = info.data.get(API_OF["nut_length_m"])
        if value is None or length is None:
            return value
        room = float(length) - float(nut or 0.0)
        if value > room:
            less = f" less the nut length ({float(length):g} - {float(nut or 0.0):g} mm)"
            raise ValueError(
                f"must be at most the screw length{less if nut else ''}, {room:g} mm: the "
                "nut cannot travel past the screw's end"
            )
        return value

    @model_validator(mode="after")
    def _moves_fit(self) -> "ApplicationInputs":
        """A cycle of moves ends where it starts (it repeats), and the nut's span stays on
        the screw (its length less the nut length given); refused on ``moves``."""
        if not self.moves:
            return self
        length = float(getattr(self, API_OF["length_m"]))
        room = length - float(getattr(self, API_OF["nut_length_m"]) or 0.0)
        closing, span = closing_error_mm(self.moves), span_mm(self.moves)
        message = ""
        if closing:
            message = f"must end where they start (to repeat): they sum to {closing:.6g} mm"
        elif span > room:
            message = f"span {span:.6g} mm, more than the {room:g} mm the nut can travel"
        if not message:
            return self
        error = InitErrorDetails(
            type=PydanticCustomError("moves", message), loc=("moves",), input=self.moves
        )
        raise ValidationError.from_exception_data(type(self).__name__, [error])

    @model_validator(mode="after")
    def _cycles_fit_a_day(self) -> "ApplicationInputs":
        """The cycles per day fit in a day: at most 86,400 s over the cycle's time (out
        and back with the dwells, ``motion.move_profile``); refused on cycles_per_day."""
        name = API_OF["cycles_per_day"]
        cycles = getattr(self, name, None)
        if cycles is None:
            return self
        p = motion.move_profile(self.axis())
        # a day exactly filled passes (its product may round a hair above 86,400 s)
        if p is None or cycles * p.cycle_time_s <= SECONDS_PER_DAY * (1.0 + 1e-12):
            return self
        most = SECONDS_PER_DAY / p.cycle_time_s
        message = (
            f"must be at most {most:.6g}: one cycle (out and back, with the dwells) takes "
            f"{p.cycle_time_s:.6g} s, and a day has 86400 s"
        )
        error = InitErrorDetails(
            type=PydanticCustomError("cycles_per_day", message),
            loc=(name,),
            input=cycles,
        )
        raise ValidationError.from_exception_data(type(self).__name__, [error])

    def to_core(
        self, motors: Mapping[str, Motor], supports: Mapping[str, SupportUnit] | None = None
    ) -> Application:
        """The same application in SI for the core: each value times its ``si_factor``,
        with the library motor's curve, inertia, continuous torque and step angle filled
        in from ``motors`` (``with_motor``; UnknownMotor for an id it lacks), and the
        library support unit's axial ratings from ``supports`` (``with_support``;
        UnknownSupport for an id it lacks)."""
        return with_support(with_motor(self.axis(), motors), supports or {})

    def axis(self) -> Application:
        """The application in SI as given, without a library motor's values filled in:
        for the axis's own numbers (length, speed, a torque limit typed in)."""
        values = {f.core: f.to_si(getattr(self, f.api)) for f in FIELDS}
        if self.moves:
            values["moves"] = tuple(m.to_core() for m in self.moves)
            if values["stroke_m"] is None:
                values["stroke_m"] = span_mm(self.moves) * BY_API[API_OF["stroke_m"]].si_factor
        return Application(**values)


if TYPE_CHECKING:
    ApplicationIn = ApplicationInputs
else:
    ApplicationIn = create_model(
        "ApplicationIn",
        __base__=ApplicationInputs,
        __module__=__name__,
        __doc__=ApplicationInputs.__doc__,
        **_definitions(),
    )

"""The page's form and query string: readable names in the user's display units.

``/?load=100&speed=50&length=500&lead=10&force_unit=N&length_unit=mm`` is the share link
of a result. Every input's page name, display quantity, kind and default come from the
field table (``app.contract.fields``); this module maps the form to and from the API's
``ApplicationIn``, so the page and the API validate the same model. Numbers typed on the
page are read by the API's own rule (``app.contract.input_types.NUMBER_TEXT``): the page
accepts every number text the API's query string accepts, to the same value, and also the
ways engineers write numbers by hand (``app.contract.exact.read_number``): a decimal comma
('20,5') and, in imperial, fractions ('5/16', '1 1/4', '1-1/4'). The API keeps to JSON
numbers and ASCII decimals: a spreadsheet or script writes those, and a comma in a query
string is ambiguous. A motor's torque curve is read and written by
``app.contract.torque_curve``; a result's share link is written by
``app.contract.share_link``.
"""

import math
import re
from collections.abc import Collection, Iterable, Mapping
from typing import Any

from pydantic import ValidationError

from app.contract.exact import PLAIN_MESSAGES, link_number, page_value, read_number, sig_figures
from app.contract.fields import BY_API, BY_PAGE, FIELDS
from app.contract.figures import bound_sig, sig
from app.contract.input_field import InputField
from app.contract.inputs import ApplicationIn
from app.contract.torque_curve import convert_curve, curve_text, curve_to_api
from app.contract.units import (
    ACCEL_UNITS,
    DEFAULT_UNITS,
    FORCE_UNITS,
    LENGTH_UNITS,
    TORQUE_UNITS,
    UNIT_QUANTITIES,
    Quantity,
    accel_choice,
    from_api,
    to_api,
)

UNIT_CHOICES = {
    "force_unit": FORCE_UNITS,
    "length_unit": LENGTH_UNITS,
    "torque_unit": TORQUE_UNITS,
    "accel_unit": ACCEL_UNITS,
}
#: prefix of the hidden fields that record which units the form's numbers are in.
ENTERED_PREFIX = "from_"
#: prefix of the hidden fields that keep a number as typed, with its unit ('50|N').
TYPED_PREFIX = "typed_"
#: The query name of the cycle's moves, on the page as in the API (``app.contract.cycle``).
MOVES = "moves"
#: pydantic error type -> (message template, context key of the bound).
BOUND_MESSAGES = {
    "greater_than": ("Must be more than {bound}.", "gt"),
    "greater_than_equal": ("Must be at least {bound}.", "ge"),
    "less_than": ("Must be less than {bound}.", "lt"),
    "less_than_equal": ("Must be at most {bound}.", "le"),
    # a length bounded by the screw's (``ApplicationInputs``): the bound in the form's unit
    "within_length": ("Must be at most the screw length, {bound}.", "le"),
    "stroke_room": (
        "Must be at most the screw length less the nut length, {bound}: the nut cannot "
        "travel past the screw's end.",
        "le",
    ),
}
#: the context keys of a lower bound (its message's figure is rounded up, ``bound_sig``).
LOWER_BOUNDS = frozenset({"gt", "ge"})
TRUE_WORDS = {"1", "true", "on", "yes"}
FALSE_WORDS = {"0", "false", "off", "no"}
#: An input's API name in a pydantic message, to be given its label: a whole word, never
#: part of a longer name or of a quoted value ('motor_margin' is no 'motor' field).
API_NAME = re.compile(
    r"(?<![\w'])(?:"
    + "|".join(map(re.escape, sorted(BY_API, key=len, reverse=True)))
    + r")(?![\w'])"
)


def yes_no(raw: str) -> bool | None:
    """A yes-no field's text read: True or False for a yes- or a no-word (any case),
    None for anything else.

    >>> yes_no("Yes"), yes_no("0"), yes_no("maybe")
    (True, False, None)
    """
    word = raw.lower()
    return True if word in TRUE_WORDS else False if word in FALSE_WORDS else None


def parse_units(params: Mapping[str, str]) -> dict[str, str]:
    """Display units from the query, unknown values falling back to metric (the
    acceleration to in/s² on a page in inches, ``accel_choice``)."""
    units = {
        key: params.get(key, default) if params.get(key, default) in UNIT_CHOICES[key] else default
        for key, default in DEFAULT_UNITS.items()
    }
    units["accel_unit"] = accel_choice({**units, "accel_unit": params.get("accel_unit", "")})
    return units


def _api_value(field: InputField, raw: str, units: dict[str, str]) -> tuple[Any, str]:
    """(API value, error message) of one typed page field; numbers converted from display units.

    Whole numbers and choices go to the model as text, so its own messages apply.
    """
    if field.kind == "yes-no":
        answer = yes_no(raw)
        return bool(answer), "" if answer is not None else "Choose yes or no (true or false)."
    if field.kind == "curve":
        return curve_to_api(raw, units), ""
    if field.kind != "number":
        return raw, ""
    number, error = read_number(raw)
    if number is None:
        return number, error
    return page_value(field, raw, units), ""


def page_to_api(
    params: Mapping[str, str], units: dict[str, str]
) -> tuple[dict[str, Any], dict[str, str]]:
    """Convert page fields to API fields. Returns (API data, errors by page field).

    Empty fields are left out (defaults apply), as is a field's ``none_word`` ('any'
    lead). Numbers in display units are converted; text that is not a number is reported.
    """
    data: dict[str, Any] = {}
    errors: dict[str, str] = {}
    for field in FIELDS:
        raw = params.get(field.page, "").strip()
        if raw == "" or (field.none_word and raw.lower() == field.none_word):
            continue
        value, error = _api_value(field, raw, units)
        if error:
            errors[field.page] = error
        else:
            data[field.api] = value
    if params.get(MOVES, "").strip():
        # the moves in the API's units, as the API's query string carries them
        data[MOVES] = params[MOVES]
    return data, errors


def entered_units(params: Mapping[str, str], units: dict[str, str]) -> dict[str, str]:
    """Units the form's numbers were typed in (hidden ``from_*`` fields), else ``units``."""
    return {
        key: params.get(ENTERED_PREFIX + key, "")
        if params.get(ENTERED_PREFIX + key, "") in UNIT_CHOICES[key]
        else units[key]
        for key in DEFAULT_UNITS
    }


def converted_fields(
    entered: Mapping[str, str], units: Mapping[str, str], fields: Iterable[InputField] = FIELDS
) -> list[str]:
    """Page fields (of ``fields``: the application's, or a custom screw's) whose numbers
    change when going from ``entered`` to ``units``.

    >>> same = {"length_unit": "mm", "accel_unit": "mm_s2"}
    >>> converted_fields(
    ...     {"force_unit": "N", "torque_unit": "N_m", **same},
    ...     {"force_unit": "lbf", "torque_unit": "oz_in", **same})
    ... # doctest: +NORMALIZE_WHITESPACE
    ['load', 'moving_mass_kg', 'coupling_inertia', 'support_static', 'support_dynamic',
     'brake_torque', 'detent_torque', 'max_torque', 'motor_rms_torque', 'motor_inertia',
     'motor_holding_torque']
    """
    changed = {q for key, qs in UNIT_QUANTITIES.items() if entered[key] != units[key] for q in qs}
    return [field.page for field in fields if field.quantity in changed]


def unit_key(quantity: Quantity) -> str:
    """The display-unit key that sets a quantity's unit ('length_unit' for a speed)."""
    return next(key for key, qs in UNIT_QUANTITIES.items() if quantity in qs)


def convert_text(text: str, quantity: Quantity, source: str, target: str) -> str:
    """A typed number re-expressed from unit ``source`` into unit ``target`` with one figure
    more than was typed (at least 4, at most 6): '50' N is '11.24' lbf, not '11.2404'."""
    number, _ = read_number(text)
    if number is None:
        return text
    key = unit_key(quantity)
    api = to_api(number, quantity, {**DEFAULT_UNITS, key: source})
    digits = min(max(sig_figures(text) + 1, 4), 6)
    shown = from_api(api, quantity, {**DEFAULT_UNITS, key: target})
    # past any float in the new unit (1e308 N in lbf): kept as typed, for its bound's message
    return f"{shown:.{digits}g}" if math.isfinite(shown) else text


def read_typed(record: str, quantity: Quantity) -> tuple[str, str] | None:
    """(text, unit) of a ``typed_*`` record 'text|unit'; None when there is none or it
    names no unit of ``quantity`` (a record is page state, so a bad one is ignored).

    >>> read_typed("50|N", "force"), read_typed("50|evil", "force"), read_typed("50", "force")
    (('50', 'N'), None, None)
    """
    text, bar, unit = record.partition("|")
    known = unit in UNIT_CHOICES[unit_key(quantity)]
    return (text, unit) if bar and text and known else None


def typed_origin(raw: str, record: str, quantity: Quantity, entered_unit: str) -> tuple[str, str]:
    """(text, unit) the shown number came from: the recorded typed text while the field
    still shows its conversion, else the field's own text in the unit it is shown in."""
    typed = read_typed(record, quantity)
    if typed is not None and convert_text(typed[0], quantity, typed[1], entered_unit) == raw:
        return typed
    return raw, entered_unit


def one_value_each(params: Mapping[str, str]) -> dict[str, str]:
    """The page's parameters, one value each: a list field given more than once
    (family=B&family=ZBX, as the API takes it) joined with commas; any other name given
    more than once keeps its last (``repeated`` names it as an error).

    >>> from starlette.datastructures import QueryParams
    >>> one_value_each(QueryParams("family=B&family=ZBX&load=5"))
    {'family': 'B,ZBX', 'load': '5'}
    """
    values = dict(params)
    for field in FIELDS:
        if field.kind == "list" and len(many := _all_of(params, field.page)) > 1:
            values[field.page] = ",".join(many)
    return values


def repeated(params: Mapping[str, str], own: Collection[str] = ()) -> dict[str, str]:
    """Each name given more than once -> its message, but a list field's and a route's
    ``own`` names (a compare link's ``ids``: the route reads each).

    >>> from starlette.datastructures import QueryParams
    >>> repeated(QueryParams("load=5&load=6&family=B&family=ZBX"))
    {'load': "'load' is given 2 times: give it once."}
    """
    lists = {f.page for f in FIELDS if f.kind == "list"}
    return {
        name: f"'{name}' is given {n} times: give it once."
        for name in dict.fromkeys(params)
        if name not in lists and name not in own and (n := len(_all_of(params, name))) > 1
    }


def _all_of(params: Mapping[str, str], name: str) -> list[str]:
    """Every value of ``name`` in a query's parameters (a plain mapping holds one)."""
    getlist = getattr(params, "getlist", None)
    if getlist is None:
        return [params[name]] if name in params else []
    return list(getlist(name))


def typed_exactly(values: Mapping[str, str], units: Mapping[str, str]) -> dict[str, str]:
    """The form's ``values`` (``convert_entered``'s) to read, each number still shown as
    the conversion of one typed in another unit (its ``typed_*`` record) replaced by the
    typed number itself in the shown unit, exactly (``link_number``): the rounded
    conversion shown ('3.15' in/s for 80 mm/s, 80.01 mm/s) never moves the axis judged.

    >>> inch = {**DEFAULT_UNITS, "length_unit": "in"}
    >>> typed_exactly({"speed": "3.15", "typed_speed": "80|mm"}, inch)["speed"]
    '3.1496062992125984'
    >>> typed_exactly({"speed": "3.2", "typed_speed": "80|mm"}, inch)["speed"]  # edited
    '3.2'
    """
    data = dict(values)
    for field in FIELDS:
        record = values.get(TYPED_PREFIX + field.page, "")
        raw = values.get(field.page, "").strip()
        if field.quantity is None or not record or read_number(raw)[0] is None:
            continue
        key = unit_key(field.quantity)
        text, unit = typed_origin(raw, record, field.quantity, units[key])
        # a number no float holds in the shown unit is shown as typed, and read so
        if unit != units[key] and raw != text:
            api = page_value(field, text, {**DEFAULT_UNITS, **units, key: unit})
            data[field.page] = link_number(field, api, units)
    return data


def convert_entered(
    params: Mapping[str, str], entered: dict[str, str], units: dict[str, str]
) -> tuple[dict[str, str], dict[str, str]]:
    """The page fields with every number re-expressed from ``entered`` into ``units`` (a
    new typed record among them, as its hidden field names it), and the typed record
    ('text|unit') of each field shown in another unit than typed, while it shows the
    conversion (``typed_exactly`` reads the number typed).

    Numbers convert from what was typed, not from the last conversion, and switching back
    to the typed unit restores the typed text exactly. Text that is not a number (or
    'any' lead) is kept as typed; a yes or no word ('no', '0') is written as the form's
    control writes it ('false'), so that it shows what is read.

    >>> units = {"force_unit": "lbf", "length_unit": "mm", "torque_unit": "N_m"}
    >>> convert_entered({"load": "50", "lead": "any"}, DEFAULT_UNITS, units)
    ({'load': '11.24', 'lead': 'any', 'typed_load': '50|N'}, {'load': '50|N'})
    >>> convert_entered({"load": "11.24", "typed_load": "50|N"}, units, DEFAULT_UNITS)[0]
    {'load': '50', 'typed_load': '50|N'}
    """
    values, typed = one_value_each(params), {}
    for field in FIELDS:
        raw = params.get(field.page, "").strip()
        if field.kind == "yes-no" and (answer := yes_no(raw)) is not None:
            values[field.page] = "true" if answer else "false"
        if field.kind == "curve" and raw and entered["torque_unit"] != units["torque_unit"]:
            values[field.page] = convert_curve(raw, entered, units)
        if field.quantity is None or not raw or read_number(raw)[0] is None:
            continue
        key = unit_key(field.quantity)
        record = params.get(TYPED_PREFIX + field.page, "")
        text, unit = typed_origin(raw, record, field.quantity, entered[key])
        if entered[key] == units[key]:
            if unit != units[key]:  # still shown as its conversion: the record is kept
                typed[field.page] = record
            continue
        if unit == units[key]:
            values[field.page] = text
        else:
            values[field.page] = convert_text(text, field.quantity, unit, units[key])
            typed[field.page] = values[TYPED_PREFIX + field.page] = f"{text}|{unit}"
    return values, typed


def value_text(field: InputField, value: Any, units: Mapping[str, str]) -> str:
    """An API value as the page writes it: numbers in display units to 6 figures,
    yes-no as 'true'/'false', choices as their value.

    >>> value_text(BY_PAGE["stroke"], 254.0, {**DEFAULT_UNITS, "length_unit": "in"})
    '10'
    """
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        return f"{field.display_value(value, units):.6g}"
    if field.kind == "curve" and value:
        return curve_text(value, units)
    return str(value)


def form_defaults(units: dict[str, str]) -> dict[str, str]:
    """Default of each optional page field as form text, numbers in display units.

    Fields without a default (required, or optional like stroke) are left out.

    >>> defaults = form_defaults({"force_unit": "N", "length_unit": "in", "torque_unit": "N_m"})
    >>> defaults["accel"], defaults["compression"], defaults["end_fixity"]
    ('39.3701', 'true', 'fixed-simple')
    """
    return {f.page: value_text(f, f.default, units) for f in FIELDS if f.default is not None}


def _page_message(error: Mapping[str, Any], page: str, units: dict[str, str]) -> str:
    """A pydantic error in the page's words: bounds in display units, API names as labels."""
    kind = str(error.get("type", ""))
    field = BY_PAGE.get(page) or _move_field(page)
    if kind in BOUND_MESSAGES:
        template, key = BOUND_MESSAGES[kind]
        bound = float(error.get("ctx", {}).get(key, 0.0))
        if field is not None and field.quantity is not None:
            figure = bound_sig(field.display_value(bound, units), key in LOWER_BOUNDS)
            return template.format(bound=f"{figure} {field.display_unit(units)}")
        return template.format(bound=sig(bound))
    if kind in PLAIN_MESSAGES:
        return PLAIN_MESSAGES[kind]
    message = str(error.get("msg", "")).removeprefix("Value error, ")
    message = API_NAME.sub(lambda m: BY_API[m[0]].label.lower(), message)
    return message[:1].upper() + message[1:].rstrip(".") + "."


def _move_field(page: str) -> InputField | None:
    """The scalar input whose unit and bounds a move's value shares (``moves.0.speed_mm_s``:
    the speed; the distance: the stroke), else None."""
    api = page.rpartition(".")[2] if page.startswith(MOVES + ".") else ""
    if api == "distance_mm":
        return next(f for f in FIELDS if f.core == "stroke_m")
    return BY_API.get(api)


def _error_page(loc: tuple[Any, ...]) -> str:
    """The page name an error is said at: a field's page name, ``moves`` for the cycle as a
    whole, ``moves.<move>.<api name>`` for one value of a move, else 'form'."""
    if loc and loc[0] == MOVES:
        return ".".join(str(part) for part in loc[:3])
    field = BY_API.get(str(loc[0])) if loc else None
    return "form" if field is None else field.page


def parse_inputs(
    params: Mapping[str, str],
    units: dict[str, str],
    motors: Mapping[str, Any] | None = None,
    supports: Mapping[str, Any] | None = None,
) -> tuple[ApplicationIn | None, dict[str, str]]:
    """Validate the page fields as an ``ApplicationIn``, the motor against the library
    ``motors`` and the support unit against ``supports`` when given. Returns (inputs,
    errors by field).

    Messages name bounds in the display units; an error of no one field is under 'form'.
    """
    data, errors = page_to_api(params, units)
    try:
        context = {"motors": motors, "supports": supports}
        inputs = ApplicationIn.model_validate(data, context=context)
    except ValidationError as exc:
        for error in exc.errors():
            page = _error_page(tuple(error.get("loc", ())))
            errors.setdefault(page, _page_message(error, page, units))
        return None, errors
    return (inputs, {}) if not errors else (None, errors)

"""The page's query string: readable names in the user's display units.

``/?load=100&speed=50&length=500&lead=10&force_unit=N&length_unit=mm`` is the share link
of a result. This module maps it to and from the API's ``ApplicationIn`` fields, so the
page and the API validate the same model.
"""

import math
from collections.abc import Mapping
from typing import Any
from urllib.parse import urlencode

from pydantic import ValidationError

from app.schemas import ApplicationIn
from app.units import (
    DEFAULT_UNITS,
    FORCE_UNITS,
    LENGTH_UNITS,
    TORQUE_UNITS,
    Quantity,
    from_api,
    label,
    sig,
    to_api,
)

#: page field -> (API field, quantity converted by the display units, or None).
PAGE_FIELDS: dict[str, tuple[str, Quantity | None]] = {
    "load": ("load_n", "force"),
    "lead": ("lead_mm", "length"),
    "speed": ("speed_mm_s", "speed"),
    "length": ("length_mm", "length"),
    "accel": ("accel_mm_s2", "accel"),
    "moving_mass_kg": ("moving_mass_kg", None),
    "end_fixity": ("end_fixity", None),
    "orientation": ("orientation", None),
    "compression": ("compression", None),
    "require_anti_backlash": ("require_anti_backlash", None),
    "coating": ("coating", None),
    "oil_present": ("oil_present", None),
    "vacuum": ("vacuum", None),
    "ambient_c": ("ambient_c", None),
    "stroke": ("stroke_mm", "length"),
    "cycles_per_day": ("cycles_per_day", None),
    "critical_speed_safety_factor": ("critical_speed_safety_factor", None),
    "buckling_safety_factor": ("buckling_safety_factor", None),
    "torque_safety_factor": ("torque_safety_factor", None),
    "max_torque": ("max_torque_nm", "torque"),
    "required_life_years": ("required_life_years", None),
    "positioning_tolerance": ("positioning_tolerance_mm", "length"),
    "rank_by": ("rank_by", None),
    "limit": ("limit", None),
}
API_TO_PAGE = {api: page for page, (api, _) in PAGE_FIELDS.items()}
UNIT_CHOICES = {"force_unit": FORCE_UNITS, "length_unit": LENGTH_UNITS, "torque_unit": TORQUE_UNITS}
#: page field -> the label shown on the form.
PAGE_LABELS = {
    "load": "Axial load",
    "lead": "Lead",
    "speed": "Linear speed",
    "length": "Screw length",
    "accel": "Acceleration",
    "moving_mass_kg": "Moving mass",
    "end_fixity": "End fixity",
    "orientation": "Orientation",
    "compression": "Load direction",
    "require_anti_backlash": "Anti-backlash nut required",
    "coating": "Coating",
    "oil_present": "Oil present",
    "vacuum": "Vacuum",
    "ambient_c": "Ambient temperature",
    "stroke": "Stroke",
    "cycles_per_day": "Cycles per day",
    "critical_speed_safety_factor": "Critical-speed factor",
    "buckling_safety_factor": "Buckling factor",
    "torque_safety_factor": "Torque safety factor",
    "max_torque": "Max drive torque",
    "required_life_years": "Required life",
    "positioning_tolerance": "Positioning tolerance",
    "rank_by": "Rank by",
    "limit": "Number of results",
}
#: display-unit key -> the quantities whose numbers it sets.
UNIT_QUANTITIES: dict[str, tuple[Quantity, ...]] = {
    "force_unit": ("force",),
    "length_unit": ("length", "speed", "accel"),
    "torque_unit": ("torque",),
}
#: prefix of the hidden fields that record which units the form's numbers are in.
ENTERED_PREFIX = "from_"
#: pydantic error type -> (message template, context key of the bound).
BOUND_MESSAGES = {
    "greater_than": ("Must be more than {bound}.", "gt"),
    "greater_than_equal": ("Must be at least {bound}.", "ge"),
    "less_than": ("Must be less than {bound}.", "lt"),
    "less_than_equal": ("Must be at most {bound}.", "le"),
}
PLAIN_MESSAGES = {
    "missing": "Required.",
    "float_parsing": "Enter a number.",
    "int_parsing": "Enter a whole number.",
    "int_from_float": "Enter a whole number.",
    "finite_number": "Enter a finite number.",
}
BOOLEAN_FIELDS = {"compression", "require_anti_backlash", "oil_present", "vacuum"}
TRUE_WORDS = {"1", "true", "on", "yes"}


def parse_units(params: Mapping[str, str]) -> dict[str, str]:
    """Display units from the query, unknown values falling back to metric."""
    return {
        key: params.get(key, default) if params.get(key, default) in UNIT_CHOICES[key] else default
        for key, default in DEFAULT_UNITS.items()
    }


def page_to_api(
    params: Mapping[str, str], units: dict[str, str]
) -> tuple[dict[str, Any], dict[str, str]]:
    """Convert page fields to API fields. Returns (API data, errors by page field).

    Empty fields are left out (defaults apply); 'any' lead means no lead. Numbers in
    display units are converted; text that is not a number is reported per field.
    """
    data: dict[str, Any] = {}
    errors: dict[str, str] = {}
    for page, (api, quantity) in PAGE_FIELDS.items():
        raw = params.get(page, "").strip()
        if raw == "" or (page == "lead" and raw.lower() == "any"):
            continue
        if page in BOOLEAN_FIELDS:
            data[api] = raw.lower() in TRUE_WORDS
            continue
        if quantity is None:
            data[api] = raw
            continue
        try:
            value = float(raw)
        except ValueError:
            errors[page] = "Enter a number."
            continue
        if not math.isfinite(value):
            errors[page] = "Enter a finite number."
            continue
        data[api] = to_api(value, quantity, units)
    return data, errors


def entered_units(params: Mapping[str, str], units: dict[str, str]) -> dict[str, str]:
    """Units the form's numbers were typed in (hidden ``from_*`` fields), else ``units``."""
    return {
        key: params.get(ENTERED_PREFIX + key, "")
        if params.get(ENTERED_PREFIX + key, "") in UNIT_CHOICES[key]
        else units[key]
        for key in DEFAULT_UNITS
    }


def converted_fields(entered: dict[str, str], units: dict[str, str]) -> list[str]:
    """Page fields whose numbers change when going from ``entered`` to ``units``.

    >>> converted_fields({"force_unit": "N", "length_unit": "mm", "torque_unit": "N_m"},
    ...     {"force_unit": "lbf", "length_unit": "mm", "torque_unit": "oz_in"})
    ['load', 'max_torque']
    """
    changed = {q for key, qs in UNIT_QUANTITIES.items() if entered[key] != units[key] for q in qs}
    return [page for page, (_, quantity) in PAGE_FIELDS.items() if quantity in changed]


def convert_entered(
    params: Mapping[str, str], entered: dict[str, str], units: dict[str, str]
) -> dict[str, str]:
    """The page fields with every number re-expressed from ``entered`` into ``units``.

    Text that is not a number (or 'any' lead) is kept as typed.

    >>> convert_entered({"load": "100", "lead": "any"}, {"force_unit": "N", "length_unit": "mm",
    ...     "torque_unit": "N_m"}, {"force_unit": "lbf", "length_unit": "in", "torque_unit": "N_m"})
    {'load': '22.4809', 'lead': 'any'}
    """
    values = dict(params)
    for page, (_, quantity) in PAGE_FIELDS.items():
        raw = params.get(page, "").strip()
        if quantity is None or entered == units or not raw:
            continue
        try:
            number = float(raw)
        except ValueError:
            continue
        values[page] = f"{from_api(to_api(number, quantity, entered), quantity, units):.6g}"
    return values


def form_defaults(units: dict[str, str]) -> dict[str, str]:
    """Default of each optional page field as form text, numbers in display units.

    Fields without a default (required, or optional like stroke) are left out.

    >>> defaults = form_defaults({"force_unit": "N", "length_unit": "in", "torque_unit": "N_m"})
    >>> defaults["accel"], defaults["compression"], defaults["end_fixity"]
    ('39.3701', 'true', 'fixed-simple')
    """
    texts: dict[str, str] = {}
    for page, (api, quantity) in PAGE_FIELDS.items():
        default = ApplicationIn.model_fields[api].default
        if isinstance(default, bool):
            texts[page] = "true" if default else "false"
        elif isinstance(default, int | float):
            value = float(default) if quantity is None else from_api(default, quantity, units)
            texts[page] = f"{value:.6g}"
        elif isinstance(default, str):
            texts[page] = default
    return texts


def _page_message(error: Mapping[str, Any], page: str, units: dict[str, str]) -> str:
    kind = str(error.get("type", ""))
    if kind in BOUND_MESSAGES:
        template, key = BOUND_MESSAGES[kind]
        bound = float(error.get("ctx", {}).get(key, 0.0))
        quantity = PAGE_FIELDS.get(page, ("", None))[1]
        if quantity is not None:
            return template.format(
                bound=f"{sig(from_api(bound, quantity, units))} {label(quantity, units)}"
            )
        return template.format(bound=sig(bound))
    if kind in PLAIN_MESSAGES:
        return PLAIN_MESSAGES[kind]
    message = str(error.get("msg", "")).removeprefix("Value error, ")
    for api, name in sorted(API_TO_PAGE.items(), key=lambda item: -len(item[0])):
        message = message.replace(api, PAGE_LABELS[name].lower())
    return message[:1].upper() + message[1:].rstrip(".") + "."


def parse_inputs(
    params: Mapping[str, str], units: dict[str, str]
) -> tuple[ApplicationIn | None, dict[str, str]]:
    """Validate the page fields as an ``ApplicationIn``. Returns (inputs, errors by field).

    Messages name bounds in the display units; an error of no one field is under 'form'.
    """
    data, errors = page_to_api(params, units)
    try:
        inputs = ApplicationIn.model_validate(data)
    except ValidationError as exc:
        for error in exc.errors():
            loc = error.get("loc", ())
            page = API_TO_PAGE.get(str(loc[0]), "form") if loc else "form"
            errors.setdefault(page, _page_message(error, page, units))
        return None, errors
    return (inputs, {}) if not errors else (None, errors)


def share_query(inputs: ApplicationIn, units: Mapping[str, str] = DEFAULT_UNITS) -> str:
    """Query string of the page link for these inputs: required fields and non-defaults."""
    defaults = ApplicationIn.model_fields
    pairs: list[tuple[str, str]] = []
    for page, (api, quantity) in PAGE_FIELDS.items():
        value = getattr(inputs, api)
        required = defaults[api].is_required()
        if not required and value == defaults[api].default:
            continue
        if isinstance(value, bool):
            text = "true" if value else "false"
        elif isinstance(value, int | float) and quantity is not None:
            text = f"{from_api(float(value), quantity, dict(units)):.6g}"
        else:
            text = f"{value:.6g}" if isinstance(value, float) else str(value)
        pairs.append((page, text))
    pairs += [(k, v) for k, v in units.items() if v != DEFAULT_UNITS[k]]
    return urlencode(pairs)

"""The page's query string: readable names in the user's display units.

``/?load=100&speed=50&length=500&lead=10&force_unit=N&length_unit=mm`` is the share link
of a result. This module maps it to and from the API's ``ApplicationIn`` fields, so the
page and the API validate the same model.
"""

from collections.abc import Mapping
from typing import Any
from urllib.parse import urlencode

from app.schemas import ApplicationIn
from app.units import (
    DEFAULT_UNITS,
    FORCE_UNITS,
    LENGTH_UNITS,
    TORQUE_UNITS,
    Quantity,
    from_api,
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
        data[api] = to_api(value, quantity, units)
    return data, errors


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

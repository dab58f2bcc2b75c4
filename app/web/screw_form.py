"""The custom screw's form and query string, declared once from the API's own models.

Each row of the screw's field table (``app.contract.screw_fields``: its geometry,
friction, drag, inertia, PV limit and pitch, and the user's own material) becomes one page
field under its API name (``outer_diameter_mm``), with the row's label, unit and hint.
A field in the API's unit of a dimension a page switch sets (mm, N m, MPa m/s) is typed,
shown and linked in the chosen unit (inches, oz in, psi ft/min), converted exactly by the
unit table; the others (deg, Pa, kg/m³) in the API's. The material is a choice of the
named materials or 'custom', which takes the ``MaterialIn`` fields.
"""

import math
from collections.abc import Container, Mapping
from dataclasses import dataclass
from typing import Any, get_args

from pydantic import BaseModel, ValidationError

from app.contract import screw_fields
from app.contract.exact import PLAIN_MESSAGES, link_number, page_value
from app.contract.figures import bound_sig, sig
from app.contract.form import BOUND_MESSAGES, LOWER_BOUNDS, unit_key
from app.contract.input_field import InputField
from app.contract.screw_link import OWN_MATERIAL, default_text
from app.contract.screws import NUT_API, NUT_FIELD, CustomScrewIn, MaterialIn
from app.contract.share_link import encode_query
from app.contract.units import DEFAULT_UNITS, Quantity, label, si_to_api
from app.core.model import ScrewSpec

#: the form's label of the material choice.
MATERIAL_LABEL = "Screw material"


@dataclass(frozen=True, slots=True)
class ScrewField:
    """One number of the custom screw: page and API name, label, API unit, hint, default,
    and the dimension a page switch sets when the unit is the API's unit of it."""

    name: str
    label: str
    unit: str
    help: str
    required: bool
    default: str
    quantity: Quantity | None

    def display_unit(self, units: Mapping[str, str]) -> str:
        """The unit the field is typed and shown in: 'in' for a length in inches."""
        return self.unit if self.quantity is None else label(self.quantity, dict(units))

    @property
    def row(self) -> InputField:
        """The field table's row of this number (``app.contract.screw_fields``)."""
        return screw_fields.BY_NAME[self.name]


def _page_field(row: InputField) -> ScrewField:
    """One row of the screw's field table as the page shows it (its default as text)."""
    default = default_text(row)
    return ScrewField(row.page, row.label, row.unit, row.help, row.required, default, row.quantity)


SCREW_FIELDS = tuple(map(_page_field, screw_fields.SCREW_FIELDS))
MATERIAL_FIELDS = tuple(map(_page_field, screw_fields.MATERIAL_FIELDS))
BY_NAME = {f.name: f for f in SCREW_FIELDS + MATERIAL_FIELDS}
#: the named materials the API knows, then the user's own.
MATERIALS = (
    *get_args(get_args(CustomScrewIn.model_fields["material"].annotation)[0]),
    OWN_MATERIAL,
)
DEFAULT_MATERIAL = str(CustomScrewIn.model_fields["material"].default)


def _message(error: Mapping[str, Any], units: Mapping[str, str]) -> str:
    """A pydantic error of one screw field in the page's words, bounds in display units."""
    kind = str(error.get("type", ""))
    if kind in BOUND_MESSAGES:
        template, key = BOUND_MESSAGES[kind]
        field = BY_NAME.get(str(error.get("loc", ("",))[0]))
        bound = float(error.get("ctx", {}).get(key, 0.0))
        if field is None:
            return template.format(bound=sig(bound))
        unit = field.display_unit(units)
        figure = bound_sig(field.row.display_value(bound, units), key in LOWER_BOUNDS)
        shown = figure + (f" {unit}" if unit else "")
        return template.format(bound=shown)
    if kind in PLAIN_MESSAGES:
        return PLAIN_MESSAGES[kind]
    context = error.get("ctx", {})
    field = BY_NAME.get(str(error.get("loc", ("",))[0]))
    if "lengths" in context and field is not None:  # lengths [mm] said in the form's unit
        unit = field.display_unit(units)
        said = {
            name: f"{sig(field.row.display_value(value, units))} {unit}"
            for name, value in context["lengths"].items()
        }
        message = str(context["template"]).format(**said)
        return message[:1].upper() + message[1:].rstrip(".") + "."
    message = str(error.get("msg", "")).removeprefix("Value error, ")
    for field in sorted(BY_NAME.values(), key=lambda f: -len(f.name)):
        message = message.replace(field.name, field.label.lower())
    return message[:1].upper() + message[1:].rstrip(".") + "."


def _numbers(
    params: Mapping[str, str], fields: tuple[ScrewField, ...], units: Mapping[str, str]
) -> tuple[dict[str, float], dict[str, str]]:
    """(API values by name, errors by name) of ``fields``, typed in display units (the
    exact number times the unit's factor, rounded once); empty fields left out."""
    data: dict[str, float] = {}
    errors: dict[str, str] = {}
    for field in fields:
        raw = params.get(field.name, "").strip()
        if not raw:
            continue
        try:  # the exact number times the unit's factor, rounded once
            data[field.name] = page_value(field.row, raw, units)
        except ValueError as error:
            errors[field.name] = str(error)
    return data, errors


def _validate(
    model: type[BaseModel],
    data: Mapping[str, Any],
    errors: dict[str, str],
    units: Mapping[str, str],
) -> BaseModel | None:
    """``model`` from ``data``; its errors added to ``errors`` by field, None on any error."""
    try:
        value = model.model_validate(data)
    except ValidationError as exc:
        for error in exc.errors():
            loc = error.get("loc", ())
            errors.setdefault(str(loc[0]) if loc else "form", _message(error, units))
        return None
    return None if errors else value


def parse_screw(
    params: Mapping[str, str], units: Mapping[str, str] = DEFAULT_UNITS
) -> tuple[CustomScrewIn | None, dict[str, str]]:
    """Validate the screw fields, typed in ``units``, as a ``CustomScrewIn``. Returns
    (screw, errors by field)."""
    numbers, errors = _numbers(params, SCREW_FIELDS, units)
    data: dict[str, Any] = dict(numbers)
    material = params.get("material", "").strip() or DEFAULT_MATERIAL
    if material == OWN_MATERIAL:
        own, own_errors = _numbers(params, MATERIAL_FIELDS, units)
        data["material"] = _validate(MaterialIn, own, own_errors, units) or DEFAULT_MATERIAL
        errors.update(own_errors)
    elif material in MATERIALS:
        data["material"] = material
    else:
        errors["material"] = f"Choose one of: {', '.join(MATERIALS)}."
    nut = params.get(NUT_FIELD, "").strip()
    if nut:
        data[NUT_API] = nut
    screw = _validate(CustomScrewIn, data, errors, units)
    return (screw if isinstance(screw, CustomScrewIn) else None), errors


def convert_screw(
    values: Mapping[str, str], entered: Mapping[str, str], units: Mapping[str, str]
) -> dict[str, str]:
    """The screw's typed numbers re-expressed from the ``entered`` units into ``units``
    (a unit switch), those that change only, each the shortest text that reads back to the
    same API value (as a move's cell and a curve's torque are), so that the screw judged
    is the one typed and switching back restores the typed number; text that is no
    number as typed.

    >>> inch = {**DEFAULT_UNITS, "length_unit": "in"}
    >>> convert_screw({"outer_diameter_mm": "12.7", "lead_mm": "3"}, DEFAULT_UNITS, inch)
    {'outer_diameter_mm': '0.5', 'lead_mm': '0.11811023622047244'}
    >>> convert_screw({"lead_mm": "0.11811023622047244"}, inch, DEFAULT_UNITS)
    {'lead_mm': '3'}
    """
    converted = {}
    for field in SCREW_FIELDS + MATERIAL_FIELDS:
        raw = values.get(field.name, "").strip()
        if field.quantity is None or not raw:
            continue
        key = unit_key(field.quantity)
        if entered[key] == units[key]:
            continue
        try:
            value = page_value(field.row, raw, entered)
        except ValueError:  # no number: kept as typed, for its field's message
            continue
        converted[field.name] = link_number(field.row, value, units)
    return converted


def _material_values(spec: ScrewSpec) -> dict[str, float | str | None]:
    """The material of a catalog screw: its name when the API knows it, else its values."""
    if spec.material_name in MATERIALS and spec.material_name != OWN_MATERIAL:
        return {"material": spec.material_name}
    return {
        "material": OWN_MATERIAL,
        "youngs_modulus_pa": spec.youngs_modulus_pa,
        "density_kg_m3": spec.density_kg_m3,
        "yield_strength_pa": spec.yield_strength_pa,
    }


def nut_carries_over(spec: ScrewSpec, nuts: Container[str]) -> bool:
    """Whether a catalog screw's nut is one of the custom form's nut materials (``nuts``):
    a seed nut's ratings (design load, wear, length) are not, and stay behind."""
    return spec.variant in nuts


def _nut_values(spec: ScrewSpec, nuts: Container[str]) -> dict[str, float | str | None]:
    """A catalog screw's nut as the custom form's: its nut material when it is one of the
    catalog's (``nuts``), with the thread pitch it is rated over (the nut length is the
    nut material's family's, as the catalog's)."""
    if not nut_carries_over(spec, nuts):
        return {}
    return {
        NUT_FIELD: spec.variant,
        "pitch_mm": None if spec.pitch_m is None else si_to_api(spec.pitch_m, "length"),
    }


def catalog_screw_query(
    spec: ScrewSpec, units: Mapping[str, str] = DEFAULT_UNITS, nuts: Container[str] = ()
) -> str:
    """A catalog screw's geometry, friction, material, inertia, largest drag, PV limit and
    nut material (one of ``nuts``, with its pitch) as the custom form's
    query (in the display ``units``), to try the same screw with other values."""
    pv_limit = spec.pv_limit_pa_m_s
    values = {
        "outer_diameter_mm": si_to_api(spec.outer_diameter_m, "length"),
        "root_diameter_mm": si_to_api(spec.root_diameter_m, "length"),
        "lead_mm": si_to_api(spec.lead_m, "length"),
        "thread_half_angle_deg": math.degrees(spec.thread_half_angle_rad),
        "friction_dynamic": spec.friction_dynamic,
        "friction_static": spec.friction_static,
        "drag_torque_nm": spec.drag_torque_max_nm,
        "pv_limit_mpa_m_s": None if pv_limit is None else si_to_api(pv_limit, "pv"),
        "inertia_kg_m2_per_m": spec.inertia_kg_m2_per_m,
        **_nut_values(spec, nuts),
        **_material_values(spec),
    }
    return encode_query(
        {
            k: v if isinstance(v, str) else _shown(k, v, units)
            for k, v in values.items()
            if v is not None
        }
    )


def _shown(name: str, value: float, units: Mapping[str, str]) -> str:
    """A catalog screw's API value in the field's display unit, to 6 figures."""
    field = BY_NAME.get(name)
    shown = value if field is None else field.row.display_value(value, units)
    return f"{shown:.12g}"

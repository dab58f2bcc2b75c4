"""The custom screw's form and query string, declared once from the API's own models.

Each geometry, friction, drag and nut field of ``CustomScrewIn`` and each field of
``MaterialIn`` becomes one page field under its API name (``outer_diameter_mm``), with
its label, unit and hint read from the model's description ('Outer diameter [mm].'),
in the API's units. The material is a choice of the named materials or 'custom', which
takes the ``MaterialIn`` fields.
"""

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, get_args
from urllib.parse import urlencode

from pydantic import BaseModel, ValidationError
from pydantic.fields import FieldInfo

from app.contract.form import BOUND_MESSAGES, PLAIN_MESSAGES, read_number
from app.contract.schemas import CustomScrewIn, MaterialIn
from app.contract.units import si_to_api, sig
from app.core.model import ScrewSpec

#: the material choice that takes the user's own modulus, density and yield strength.
OWN_MATERIAL = "custom"
#: the form's label of the material choice.
MATERIAL_LABEL = "Screw material"


@dataclass(frozen=True, slots=True)
class ScrewField:
    """One number of the custom screw: page and API name, label, API unit, hint, default."""

    name: str
    label: str
    unit: str
    help: str
    required: bool
    default: str


def _description(info: FieldInfo) -> str:
    """The field's description, also when it sits inside an optional annotation."""
    if info.description:
        return info.description
    for arg in get_args(info.annotation):
        for meta in getattr(arg, "__metadata__", ()):
            if isinstance(meta, FieldInfo) and meta.description:
                return meta.description
    return ""


def split_description(text: str) -> tuple[str, str, str]:
    """(label, unit, hint) of a model description.

    >>> split_description("Flank half-angle [deg]: 14.5 Acme, 15 trapezoidal.")
    ('Flank half-angle', 'deg', '14.5 Acme, 15 trapezoidal')
    >>> split_description("Running friction coefficient.")
    ('Running friction coefficient', '', '')
    """
    label, bracket, rest = text.rstrip(".").partition(" [")
    unit, _, hint = rest.partition("]")
    hint = hint.lstrip(",;: ")
    return label, unit if bracket else "", hint[:1].upper() + hint[1:]


def _number_fields(model: type[BaseModel]) -> tuple[ScrewField, ...]:
    """The number fields of ``model`` (all but the material) in declaration order."""
    fields = []
    for name, info in model.model_fields.items():
        if name == "material":
            continue
        default = "" if info.is_required() or info.default is None else f"{info.default:g}"
        label, unit, hint = split_description(_description(info))
        fields.append(ScrewField(name, label, unit, hint, info.is_required(), default))
    return tuple(fields)


SCREW_FIELDS = _number_fields(CustomScrewIn)
MATERIAL_FIELDS = _number_fields(MaterialIn)
BY_NAME = {f.name: f for f in SCREW_FIELDS + MATERIAL_FIELDS}
#: the named materials the API knows, then the user's own.
MATERIALS = (
    *get_args(get_args(CustomScrewIn.model_fields["material"].annotation)[0]),
    OWN_MATERIAL,
)
DEFAULT_MATERIAL = str(CustomScrewIn.model_fields["material"].default)


def _message(error: Mapping[str, Any]) -> str:
    """A pydantic error of one screw field in the page's words."""
    kind = str(error.get("type", ""))
    if kind in BOUND_MESSAGES:
        template, key = BOUND_MESSAGES[kind]
        field = BY_NAME.get(str(error.get("loc", ("",))[0]))
        unit = f" {field.unit}" if field is not None and field.unit else ""
        return template.format(bound=sig(float(error.get("ctx", {}).get(key, 0.0))) + unit)
    if kind in PLAIN_MESSAGES:
        return PLAIN_MESSAGES[kind]
    message = str(error.get("msg", "")).removeprefix("Value error, ")
    for field in sorted(BY_NAME.values(), key=lambda f: -len(f.name)):
        message = message.replace(field.name, field.label.lower())
    return message[:1].upper() + message[1:].rstrip(".") + "."


def _numbers(
    params: Mapping[str, str], fields: tuple[ScrewField, ...]
) -> tuple[dict[str, float], dict[str, str]]:
    """(typed numbers by name, errors by name) of ``fields``; empty fields left out."""
    data: dict[str, float] = {}
    errors: dict[str, str] = {}
    for field in fields:
        raw = params.get(field.name, "").strip()
        if not raw:
            continue
        number, error = read_number(raw)
        if number is None:
            errors[field.name] = error
        else:
            data[field.name] = number
    return data, errors


def _validate(
    model: type[BaseModel], data: Mapping[str, Any], errors: dict[str, str]
) -> BaseModel | None:
    """``model`` from ``data``; its errors added to ``errors`` by field, None on any error."""
    try:
        value = model.model_validate(data)
    except ValidationError as exc:
        for error in exc.errors():
            loc = error.get("loc", ())
            errors.setdefault(str(loc[0]) if loc else "form", _message(error))
        return None
    return None if errors else value


def parse_screw(params: Mapping[str, str]) -> tuple[CustomScrewIn | None, dict[str, str]]:
    """Validate the screw fields as a ``CustomScrewIn``. Returns (screw, errors by field)."""
    numbers, errors = _numbers(params, SCREW_FIELDS)
    data: dict[str, Any] = dict(numbers)
    material = params.get("material", "").strip() or DEFAULT_MATERIAL
    if material == OWN_MATERIAL:
        own, own_errors = _numbers(params, MATERIAL_FIELDS)
        data["material"] = _validate(MaterialIn, own, own_errors) or DEFAULT_MATERIAL
        errors.update(own_errors)
    elif material in MATERIALS:
        data["material"] = material
    else:
        errors["material"] = f"Choose one of: {', '.join(MATERIALS)}."
    screw = _validate(CustomScrewIn, data, errors)
    return (screw if isinstance(screw, CustomScrewIn) else None), errors


def screw_values(screw: CustomScrewIn) -> dict[str, str]:
    """The page fields of a screw: the material and each number not at its default
    (6 figures)."""
    dump = screw.model_dump()
    material = dump.pop("material")
    values = {"material": material if isinstance(material, str) else OWN_MATERIAL}
    if isinstance(material, dict):
        dump.update(material)
    for name, value in dump.items():
        text = "" if value is None else f"{value:.6g}"
        if name in BY_NAME and text not in ("", BY_NAME[name].default):
            values[name] = text
    return values


def screw_query(screw: CustomScrewIn) -> str:
    """The screw's part of a share link."""
    return urlencode(screw_values(screw))


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


def catalog_screw_query(spec: ScrewSpec) -> str:
    """A catalog screw's geometry, friction, material, largest drag and PV limit as the
    custom form's query (API units), to try the same screw with other values."""
    pv_limit = spec.pv_limit_pa_m_s or spec.nut_pv_limit_pa_m_s
    values = {
        "outer_diameter_mm": si_to_api(spec.outer_diameter_m, "length"),
        "root_diameter_mm": si_to_api(spec.root_diameter_m, "length"),
        "lead_mm": si_to_api(spec.lead_m, "length"),
        "thread_half_angle_deg": math.degrees(spec.thread_half_angle_rad),
        "friction_dynamic": spec.friction_dynamic,
        "friction_static": spec.friction_static,
        "drag_torque_nm": spec.drag_torque_max_nm,
        "pv_limit_mpa_m_s": None if pv_limit is None else si_to_api(pv_limit, "pv"),
        **_material_values(spec),
    }
    return urlencode(
        {k: v if isinstance(v, str) else f"{v:.6g}" for k, v in values.items() if v is not None}
    )

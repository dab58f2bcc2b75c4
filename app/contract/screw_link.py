"""A custom screw as the fields of its share link (the /custom page's query): the material
and each number not at its default, in the display units, exactly."""

from collections.abc import Mapping

from app.contract.exact import link_number
from app.contract.input_field import InputField
from app.contract.inputs import ApplicationIn
from app.contract.screw_fields import BY_NAME
from app.contract.screws import NUT_API, NUT_FIELD, CustomScrewIn
from app.contract.share_link import encode_query, share_query
from app.contract.units import DEFAULT_UNITS

#: the material choice that takes the user's own modulus, density and yield strength.
OWN_MATERIAL = "custom"


def default_text(field: InputField) -> str:
    """A screw field's default as its page field writes it ("" without one)."""
    return "" if field.default is None else f"{field.default:g}"


def _value_text(name: str, value: float, units: Mapping[str, str]) -> str:
    """A screw value as its page field writes it: in the display unit (the API's for a
    number no switch sets: degrees, Pa, friction), exactly (the fewest figures that read
    back to it); a value of no field to 6 figures."""
    if name not in BY_NAME:
        return f"{value:.6g}"
    return link_number(BY_NAME[name], value, units)


def screw_values(screw: CustomScrewIn, units: Mapping[str, str] = DEFAULT_UNITS) -> dict[str, str]:
    """The page fields of a screw: the material and each number not at its default, in
    the display ``units``."""
    dump = screw.model_dump()
    material = dump.pop("material")
    nut = dump.pop(NUT_API)
    values = {"material": material if isinstance(material, str) else OWN_MATERIAL}
    if nut is not None:
        values[NUT_FIELD] = nut
    if isinstance(material, dict):
        dump.update(material)
    for name, value in dump.items():
        text = "" if value is None else _value_text(name, value, units)
        if name in BY_NAME and text not in ("", default_text(BY_NAME[name])):
            values[name] = text
    return values


def screw_query(screw: CustomScrewIn, units: Mapping[str, str] = DEFAULT_UNITS) -> str:
    """The screw's part of a share link, in the display ``units``."""
    return encode_query(screw_values(screw, units))


def custom_query(
    inputs: ApplicationIn, screw: CustomScrewIn, units: Mapping[str, str] = DEFAULT_UNITS
) -> str:
    """The query of the page of one's own screw: the screw, then the application without
    the fields that choose among the catalog's screws (which that page does not read), in
    the display ``units``."""
    parts = (screw_query(screw, units), share_query(inputs, units, catalog=False))
    return "&".join(part for part in parts if part)

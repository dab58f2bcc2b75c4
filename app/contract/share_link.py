"""A result's share link and the printed summary of its inputs: every required input and
every input not at its default (``shown_inputs``), numbers exactly in the display units
(``share_query``), the same inputs to 4 figures for a reader (``summary_rows``). The form
they are read back with is ``app.contract.form``'s.
"""

from collections.abc import Mapping, Sequence
from typing import Any
from urllib.parse import urlencode

from app.contract.cycle import moves_text
from app.contract.exact import link_number
from app.contract.fields import FIELDS
from app.contract.figures import sig
from app.contract.form import (
    MOVES,
    TYPED_PREFIX,
    convert_text,
    read_typed,
    unit_key,
    value_text,
)
from app.contract.input_field import InputField
from app.contract.inputs import ApplicationIn
from app.contract.torque_curve import curve_text
from app.contract.units import DEFAULT_UNITS, accel_choice


def shown_inputs(inputs: Mapping[str, Any]) -> list[tuple[InputField, Any]]:
    """(field, API value) of every required input and every input not at its default,
    in table order: what a share link carries and the printed summary shows."""
    return [
        (field, inputs[field.api])
        for field in FIELDS
        if field.required or inputs[field.api] != field.default
    ]


def link_text(field: InputField, value: Any, units: Mapping[str, str]) -> str:
    """An API value as a link carries it: numbers exactly (``link_number``), the rest as
    the page writes them."""
    if isinstance(value, float):
        return link_number(field, value, units)
    return value_text(field, value, units)


def _exact_curve(inputs: ApplicationIn, field: InputField) -> Any:
    """A curve's points as floats, else None."""
    return getattr(inputs, field.api) if field.kind == "curve" else None


def _unit_default(key: str, units: Mapping[str, str]) -> str:
    """The choice a link without ``key`` is read with (the acceleration's follows the
    length's: in/s² in inches), so a link names every other."""
    if key == "accel_unit":
        return accel_choice({**units, "accel_unit": ""})
    return DEFAULT_UNITS[key]


#: What a link's query leaves as typed: the separators of the moves ("300:250:...") and
#: of a curve or a list ("0:0.5,600:0.3"), which RFC 3986 allows in a query; everything
#: else is encoded as ``urlencode`` does.
LINK_SAFE = ":,"


def encode_query(pairs: Sequence[tuple[str, str]] | Mapping[str, str]) -> str:
    """``pairs`` as a link's query string, its separators readable (``LINK_SAFE``).

    >>> encode_query([("moves", "300:250:2500:2500:0.2:2.5:10:opposes"), ("ids", "a,b c&d")])
    'moves=300:250:2500:2500:0.2:2.5:10:opposes&ids=a,b+c%26d'
    """
    return urlencode(pairs, safe=LINK_SAFE)


def share_query(
    inputs: ApplicationIn,
    units: Mapping[str, str] = DEFAULT_UNITS,
    catalog: bool = True,
    typed: Mapping[str, str] | None = None,
) -> str:
    """Query string of the page link for these inputs: required fields and non-defaults,
    each number reproducing the input exactly; without the fields that choose among the
    catalog's screws (``catalog_only``: the lead, the families, the limit) for a page that
    judges one screw of its own (``catalog`` False). A field ``typed`` in another unit
    (its record 'text|unit', ``convert_entered``) is written as the form shows it, with
    its record, which the page reads back exactly (``typed_exactly``)."""
    pairs: list[tuple[str, str]] = []
    for f, v in shown_inputs(inputs.model_dump()):
        if not catalog and f.catalog_only:
            continue
        record, quantity = (typed or {}).get(f.page, ""), f.quantity
        origin = read_typed(record, quantity) if record and quantity else None
        if origin is None or quantity is None:
            pairs.append((f.page, link_text(f, _exact_curve(inputs, f) or v, units)))
            continue
        text, unit = origin
        shown = convert_text(text, quantity, unit, units[unit_key(quantity)])
        pairs += [(f.page, shown), (TYPED_PREFIX + f.page, record)]
    if inputs.moves:
        pairs.append((MOVES, moves_text(inputs.moves)))
    pairs += [(k, v) for k, v in units.items() if v != _unit_default(k, units)]
    return encode_query(pairs)


def summary_rows(inputs: Mapping[str, Any], units: Mapping[str, str]) -> list[dict[str, str]]:
    """The printed inputs summary: label, value and unit of each shown input, numbers in
    display units to 4 figures, a choice by its text, yes-no as 'yes'/'no'."""
    rows = []
    for field, value in shown_inputs(inputs):
        if field.choices:
            text = field.choice_text(value_text(field, value, units))
        elif isinstance(value, bool):
            text = "yes" if value else "no"
        elif isinstance(value, int | float):
            text = sig(field.display_value(value, units))
        elif field.kind == "curve":
            text = curve_text(value, units, digits=4)
        else:
            text = str(value)
        unit = field.display_unit(units)
        rows.append({"name": field.page, "label": field.label, "value": text, "unit": unit})
    return rows

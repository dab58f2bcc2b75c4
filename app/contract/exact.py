"""Numbers typed on the page and written in share links, exactly.

A typed number is read by the API's own rule (``app.contract.input_types.NUMBER_TEXT``)
and also as engineers write numbers by hand (``read_number``): a decimal comma ('20,5')
and fractions ('5/16', '1 1/4', '1-1/4'), each read exactly before the one rounding to a
float. A value in a display unit is written back as the shortest decimal that reads to
the same float (``link_number``), so a share link reproduces its result.
"""

import math
import re
import sys
from collections.abc import Mapping
from decimal import Decimal, localcontext
from fractions import Fraction
from functools import lru_cache
from typing import Annotated

from pydantic import Field, TypeAdapter, ValidationError

from app.contract.input_field import InputField
from app.contract.input_types import NUMBER_TEXT
from app.contract.units import DEFAULT_UNITS, Quantity, display_system, exact_factor, exact_offset

PLAIN_MESSAGES = {
    "missing": "Required.",
    "float_parsing": "Enter a number.",
    "int_parsing": "Enter a whole number.",
    "int_from_float": "Enter a whole number.",
    "finite_number": "Enter a finite number.",
}
#: a fraction as engineers write one: '5/16', '1 1/4', '1-1/4', signed, at most 20 digits
#: a part (enough for any fraction of a unit; longer text is a mistake, not a measure).
FRACTION = re.compile(r"([+-]?)(?:([0-9]{1,20})(?: +|-))?([0-9]{1,20})/([0-9]{1,20})")
#: a decimal comma in place of the point: '20,5', ',5', '-0,125', '1,5e3'.
DECIMAL_COMMA = re.compile(r"[+-]?[0-9]*,[0-9]+(?:[eE][+-]?[0-9]+)?")
#: '1,234' or '12,500': a thousands separator to some readers, a decimal comma to others.
THOUSANDS = re.compile(r"[+-]?[1-9][0-9]{0,2}(?:,[0-9]{3})+")
ZERO_DENOMINATOR = "A fraction's denominator cannot be 0."
AMBIGUOUS_COMMA = (
    "Ambiguous: {text} reads as {point} with a decimal comma and as {whole} with a "
    "thousands separator; write {point} or {whole}."
)
#: figures enough for any decimal to read back to the float it was written from (17 are
#: enough for a float; the display unit's factor takes one more).
LINK_DIGITS = 24
#: significant digits of the longest exact decimal of a float (2**-1074 has 751).
FLOAT_DIGITS = 800
#: decimal exponents read exactly: wider than any float times a unit's factor.
EXPONENT_REACH = 400
#: the largest finite float, exactly
MAX_FLOAT = Fraction(sys.float_info.max)
#: a typed number read as the API reads a query parameter: ASCII decimal, finite.
PAGE_NUMBER: TypeAdapter[float] = TypeAdapter(
    Annotated[float, NUMBER_TEXT, Field(allow_inf_nan=False)]
)


def _fraction(match: re.Match[str]) -> tuple[Fraction | None, str]:
    """The exact value of a matched fraction ('-1 1/4': -5/4), or (None, the message)."""
    sign, whole, numerator, denominator = match.groups()
    if int(denominator) == 0:
        return None, ZERO_DENOMINATOR
    value = int(whole or 0) + Fraction(int(numerator), int(denominator))
    return (-value if sign == "-" else value), ""


def read_exact(text: str) -> tuple[Fraction | float | None, str]:
    """(the exact value, '') of a number text the page accepts, else (None, the message).

    The API's ASCII decimals are read exactly (a float past ``EXPONENT_REACH``, which no
    input's bounds allow); a decimal comma as the point ('20,5'), except where it could be
    a thousands separator ('1,234'); a fraction or mixed number ('5/16', '1 1/4', '1-1/4').
    Every accepted value is a finite float.

    >>> read_exact("20,5"), read_exact("1-1/4"), read_exact("1/0")[1]
    ((Fraction(41, 2), ''), (Fraction(5, 4), ''), "A fraction's denominator cannot be 0.")
    """
    text = text.strip(" \t\n\r\f\v")
    fraction = FRACTION.fullmatch(text)
    if fraction is not None:
        value, error = _fraction(fraction)
        if value is not None and not math.isfinite(float(value)):
            return None, PLAIN_MESSAGES["finite_number"]
        return value, error
    if THOUSANDS.fullmatch(text):
        point, whole = text.replace(",", ".", 1), text.replace(",", "")
        if text.count(",") == 1:
            return None, AMBIGUOUS_COMMA.format(text=text, point=point, whole=whole)
        return None, f"Write {whole} without the thousands separators."
    if DECIMAL_COMMA.fullmatch(text):
        text = text.replace(",", ".")
    try:
        number = PAGE_NUMBER.validate_python(text)
    except ValidationError as exc:
        return None, PLAIN_MESSAGES.get(exc.errors()[0]["type"], "Enter a number.")
    decimal = Decimal(text)
    if not -EXPONENT_REACH <= decimal.adjusted() <= EXPONENT_REACH:
        return number, ""
    return Fraction(decimal), ""


def read_number(text: str) -> tuple[float | None, str]:
    """(the number, '') for number text the page accepts (``read_exact``), else (None, the
    page's message).

    >>> read_number(" 1e3"), read_number("1_000"), read_number("1e400"), read_number("5/16")
    ((1000.0, ''), (None, 'Enter a number.'), (None, 'Enter a finite number.'), (0.3125, ''))
    """
    value, error = read_exact(text)
    return (None, error) if value is None else (float(value), "")


def sig_figures(text: str) -> int:
    """Significant digits written in a number text (leading zeros and exponent left out).

    >>> sig_figures("50"), sig_figures("0.0125"), sig_figures("1.50e3")
    (2, 3, 3)
    """
    mantissa = text.strip().lower().split("e")[0].lstrip("+-")
    return len(mantissa.replace(".", "").lstrip("0")) or 1


def _factor(field: InputField, units: Mapping[str, str]) -> Fraction:
    """The factor from ``field``'s display unit to its API unit, as the decimal it is
    defined as (25.4, not the binary float nearest to it); a temperature scale's exactly
    (5/9 for °F), so that its offset cancels: 32 °F reads as 0 °C, not 1e-31."""
    if not field.quantity:
        return Fraction(1)
    return _scale(field.quantity, tuple(sorted({**DEFAULT_UNITS, **units}.items())))[0]


def _offset(field: InputField, units: Mapping[str, str]) -> Fraction:
    """The API value at the zero of ``field``'s display unit, exactly: 0 but for °F."""
    if not field.quantity:
        return Fraction(0)
    return _scale(field.quantity, tuple(sorted({**DEFAULT_UNITS, **units}.items())))[1]


@lru_cache(maxsize=512)
def _scale(quantity: Quantity, units: tuple[tuple[str, str], ...]) -> tuple[Fraction, Fraction]:
    """(factor, offset) of ``quantity`` from the display ``units`` to the API's, exactly;
    a few dozen unit choices, each worked out once (``_factor``, ``_offset``)."""
    chosen = dict(units)
    offset = exact_offset(quantity, chosen)
    if offset:
        return exact_factor(quantity, chosen), offset
    return Fraction(repr(display_system(chosen)[quantity][1])), Fraction(0)


def page_value(field: InputField, text: str, units: Mapping[str, str]) -> float:
    """The API value of number ``text`` the page accepts (``read_exact``), typed in
    ``field``'s display unit: the exact number times the unit's factor, rounded once, so
    that every API value has a text that reads back to it exactly (``link_number``). A
    decimal beyond any float's reach (``1e-99999999``) is read as a float, without its
    exact value.

    >>> from app.contract.fields import BY_PAGE
    >>> inch = {**DEFAULT_UNITS, "length_unit": "in"}
    >>> page_value(BY_PAGE["length"], "3937.0078", inch), page_value(BY_PAGE["lead"], "5/16", inch)
    (99999.99812, 7.9375)
    """
    number, error = read_exact(text)
    if number is None:
        raise ValueError(error)
    if isinstance(number, float):
        return number
    return _rounded(number * _factor(field, units) + _offset(field, units))


def _rounded(exact: Fraction) -> float:
    """An exact API value rounded once to a float; past the largest float (1e308 lbf:
    past every input's bounds, which the model names) the largest of its sign."""
    if abs(exact) > MAX_FLOAT:
        return sys.float_info.max if exact > 0 else -sys.float_info.max
    return float(exact)


def _trimmed(text: str) -> str:
    """A formatted decimal without the trailing zeros of its mantissa ('1.500e+6': '1.5e+6')."""
    mantissa, e, exponent = text.partition("e")
    if "." in mantissa:
        mantissa = mantissa.rstrip("0").rstrip(".")
    return mantissa + e + exponent


def decimal_text(value: float, factor: Fraction, offset: Fraction = Fraction(0)) -> str:
    """``value`` less ``offset`` over ``factor`` as the decimal with the fewest figures (6
    at least) that reads back, times ``factor`` plus ``offset`` rounded once, to exactly
    ``value``."""
    if factor == 1 and offset == 0:  # the shortest text that reads back is the float's repr
        return _trimmed(repr(value))
    exact = (Fraction(value) - offset) / factor
    # an offset (°F) can need every digit of the float: 1e-142 °C is 32.000...0018 °F
    reach = LINK_DIGITS if offset == 0 else FLOAT_DIGITS
    with localcontext(prec=reach):
        shown = Decimal(exact.numerator) / Decimal(exact.denominator)
    for digits in range(6, reach):
        text = _trimmed(f"{shown:.{digits}g}")
        # read back as the page reads it (``page_value``): the largest float's decimal in
        # another unit rounds past it at first (1.7976931348623157e308 mm in inches)
        if _rounded(Fraction(Decimal(text)) * factor + offset) == value:
            break
    return text


def link_number(field: InputField, value: float, units: Mapping[str, str]) -> str:
    """A number of a link in display units, with the fewest figures (6 at least) that the
    page reads back (``page_value``) to exactly ``value``.

    >>> from app.contract.fields import BY_PAGE
    >>> inch = {**DEFAULT_UNITS, "length_unit": "in"}
    >>> link_number(BY_PAGE["length"], 100000.0, inch), link_number(BY_PAGE["load"], 100.4824, {})
    ('3937.007874015748', '100.4824')
    """
    units = {**DEFAULT_UNITS, **units}
    return decimal_text(value, _factor(field, units), _offset(field, units))

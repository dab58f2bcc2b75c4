"""Unit conversion at the edge. The core is SI; the API speaks mm, mm/s, N, N m, MPa m/s;
the page lets the user pick display units. One table per quantity: factor to the API unit.
"""

from collections.abc import Mapping
from typing import Literal

from app.core.phrase import Amount, Phrase
from app.core.phrase import Quantity as CoreQuantity

Quantity = Literal["force", "length", "speed", "accel", "torque", "mass"]

#: display unit -> factor that converts a value in that unit to the API unit.
FORCE_UNITS = {"N": 1.0, "lbf": 4.4482216152605, "kgf": 9.80665}
LENGTH_UNITS = {"mm": 1.0, "in": 25.4}
TORQUE_UNITS = {"N_m": 1.0, "oz_in": 0.0070615518333, "lb_in": 0.112984829027617}
TORQUE_LABELS = {"N_m": "N m", "oz_in": "oz in", "lb_in": "lb in"}
#: a mass follows the force unit: pounds with pound-force, kilograms otherwise.
MASS_UNITS = {"N": ("kg", 1.0), "lbf": ("lb", 0.45359237), "kgf": ("kg", 1.0)}
DEFAULT_UNITS = {"force_unit": "N", "length_unit": "mm", "torque_unit": "N_m"}


def factor(quantity: Quantity, units: Mapping[str, str]) -> float:
    """Factor from the chosen display unit of ``quantity`` to the API unit."""
    if quantity == "force":
        return FORCE_UNITS[units["force_unit"]]
    if quantity == "torque":
        return TORQUE_UNITS[units["torque_unit"]]
    if quantity == "mass":
        return MASS_UNITS[units["force_unit"]][1]
    return LENGTH_UNITS[units["length_unit"]]


def label(quantity: Quantity, units: Mapping[str, str]) -> str:
    """Display label of the chosen unit, e.g. 'in/s' for speed in inches."""
    if quantity == "force":
        return units["force_unit"]
    if quantity == "torque":
        return TORQUE_LABELS[units["torque_unit"]]
    if quantity == "mass":
        return MASS_UNITS[units["force_unit"]][0]
    base = units["length_unit"]
    return {"length": base, "speed": f"{base}/s", "accel": f"{base}/s²"}[quantity]


def to_api(value: float, quantity: Quantity, units: Mapping[str, str]) -> float:
    return value * factor(quantity, units)


def from_api(value: float, quantity: Quantity, units: Mapping[str, str]) -> float:
    return value / factor(quantity, units)


#: core quantity -> (API unit label, factor from SI to the API unit).
API_UNITS: dict[CoreQuantity, tuple[str, float]] = {
    "force": ("N", 1.0),
    "length": ("mm", 1e3),
    "speed": ("mm/s", 1e3),
    "accel": ("mm/s^2", 1e3),
    "torque": ("N m", 1.0),
    "rpm": ("rpm", 1.0),
    "pv": ("MPa m/s", 1e-6),
    "pressure": ("MPa", 1e-6),
    "years": ("years", 1.0),
    "temperature": ("°C", 1.0),
    "factor": ("", 1.0),
}
#: core quantity -> number format in sentences (a speed in rpm needs no decimals).
TEXT_FORMATS: dict[CoreQuantity, str] = {
    "force": ".4g",
    "length": ".4g",
    "speed": ".4g",
    "accel": ".4g",
    "torque": ".3g",
    "rpm": ".0f",
    "pv": ".3g",
    "pressure": ".4g",
    "years": ".3g",
    "temperature": "g",
    "factor": "g",
}
SWITCHABLE: dict[CoreQuantity, Quantity] = {
    "force": "force",
    "length": "length",
    "speed": "speed",
    "accel": "accel",
    "torque": "torque",
}


def api_value(value_si: float, quantity: CoreQuantity | None) -> tuple[float, str]:
    """An SI value in the API's unit, with the unit's label.

    >>> api_value(0.1, "speed")
    (100.0, 'mm/s')
    """
    if quantity is None:
        return value_si, ""
    unit, scale = API_UNITS[quantity]
    return value_si * scale, unit


def amount_text(amount: Amount, units: Mapping[str, str] = DEFAULT_UNITS) -> str:
    """An amount in the reader's units: '4.5 in/s', '300 rpm', '0.175 MPa m/s'.

    >>> amount_text(Amount(0.0254, "length"), {**DEFAULT_UNITS, "length_unit": "in"})
    '1 in'
    """
    value, unit = api_value(amount.value, amount.quantity)
    switch = SWITCHABLE.get(amount.quantity)
    if switch is not None:
        value, unit = from_api(value, switch, dict(units)), label(switch, dict(units))
    return f"{value:{TEXT_FORMATS[amount.quantity]}} {unit}".strip()


def render(phrase: Phrase, units: Mapping[str, str] = DEFAULT_UNITS) -> str:
    """A core sentence in the reader's units (the API's units by default).

    >>> render(Phrase("Run at most {v}.", {"v": Amount(0.1, "speed")}))
    'Run at most 100 mm/s.'
    """
    values = {
        name: render(v, units)
        if isinstance(v, Phrase)
        else v
        if isinstance(v, str)
        else amount_text(v, units)
        for name, v in phrase.values.items()
    }
    return phrase.template.format(**values)


#: API unit of a check value -> the display quantity it is converted with.
API_UNIT_QUANTITY: dict[str, Quantity] = {
    "N": "force",
    "mm": "length",
    "mm/s": "speed",
    "N m": "torque",
}

#: SI unit of a catalog value -> (display unit, factor from SI).
CATALOG_UNITS = {
    "m": ("mm", 1e3),
    "Pa": ("GPa", 1e-9),
    "Pa m/s": ("MPa m/s", 1e-6),
    "1/K": ("µm/(m K)", 1e6),
    "m/m": ("mm/m", 1e3),
    "kg m2/m": ("kg m²/m", 1.0),
    "kg/m3": ("kg/m³", 1.0),
    "C": ("°C", 1.0),
}
#: catalog field-name prefix -> (display unit, factor from SI), where mm would mislead.
CATALOG_FIELD_UNITS = {"max_length": ("m", 1.0), "life": ("km", 1e-3)}


def sig(value: float, digits: int = 4) -> str:
    """``value`` to ``digits`` significant figures; whole numbers past that, no exponent.

    >>> sig(4298.213), sig(12345.6), sig(0.20705016), sig(22.480894)
    ('4298', '12346', '0.2071', '22.48')
    """
    if abs(value) >= 10**digits:
        return f"{round(value):d}"
    return f"{value:.{digits}g}"


def _catalog_text(value: object, scale: float) -> str:
    if isinstance(value, tuple | list):
        return "(" + ", ".join(_catalog_text(v, scale) for v in value) + ")"
    if isinstance(value, int | float) and not isinstance(value, bool):
        return sig(float(value) * scale)
    return str(value)


def catalog_value(name: str, value: object, unit: str) -> tuple[str, str]:
    """A catalog value (SI) as display text and unit: lengths in mm, moduli in GPa ...

    Two numbers are a range, more a list; a list of tuples is a table of rows.

    >>> catalog_value("root_diameter", 0.009906, "m")
    ('9.906', 'mm')
    >>> catalog_value("leads", (0.001, 0.0025, 0.0127), "m")
    ('1, 2.5, 12.7', 'mm')
    >>> catalog_value("temperature_range", (0.0, 93.0), "C")
    ('0 – 93', '°C')
    >>> catalog_value("outgassing", ((24.0, 0.2), (48.0, 0.26)), "h, %")
    ('(24, 0.2), (48, 0.26)', 'h, %')
    """
    shown, scale = next(
        (u for prefix, u in CATALOG_FIELD_UNITS.items() if name.startswith(prefix)),
        CATALOG_UNITS.get(unit, (unit, 1.0)),
    )
    if not isinstance(value, tuple | list):
        return _catalog_text(value, scale), shown
    texts = [_catalog_text(v, scale) for v in value]
    is_range = len(texts) == 2 and not any(isinstance(v, tuple | list) for v in value)
    return (" – " if is_range else ", ").join(texts), shown


class Display:
    """API-unit values (N, mm, mm/s, N m) shown in the user's display units."""

    def __init__(self, units: dict[str, str]) -> None:
        self.units = units

    def value(self, api_value: float, quantity: Quantity) -> float:
        """The number in display units."""
        return from_api(api_value, quantity, self.units)

    def text(self, api_value: float | None, quantity: Quantity, digits: int = 4) -> str:
        """The number in display units as text; an em dash for None."""
        if api_value is None:
            return "—"
        return sig(self.value(api_value, quantity), digits)

    def label(self, quantity: Quantity) -> str:
        return label(quantity, self.units)

    def check(self, api_value: float | None, api_unit: str) -> str:
        """A check's value or limit with its unit, converted where the unit is a display one.

        >>> Display({"force_unit": "lbf", "length_unit": "in", "torque_unit": "N_m"}).check(
        ...     100.0, "N")
        '22.48 lbf'
        """
        if api_value is None:
            return "—"
        quantity = API_UNIT_QUANTITY.get(api_unit)
        if quantity is None:
            return f"{sig(api_value)} {api_unit}".strip()
        return f"{self.text(api_value, quantity)} {self.label(quantity)}"

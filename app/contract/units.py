"""Units at the edge: one table of units, the API's unit system, the page's display units.

The core holds every dimension (``app.core.phrase.Quantity``, the app's one list of
them) in one unit, SI but for speeds of rotation in rpm, life in years and temperatures in
°C. ``UNITS`` (the table itself, in ``app.core.units`` so the catalog reads the same rows)
defines every other unit the app reads or shows by its exact factor to that unit, derived
as the definitions are (pint's shape: 1 lbf = 1 lb x g_n, 1 psi = 1 lbf/in²), with the
float factors both ways computed once from the exact fractions.
``API_SYSTEM`` names the unit of each dimension in the API (mm, mm/s, N, N m, MPa m/s);
``DISPLAY_CHOICES`` the units the page's three switches offer, each a selection from the
same table. Values convert at the edges only, by one float multiplication or division:
``to_si``/``from_si`` by unit, ``api_to_si``/``si_to_api`` by dimension, and
``to_api``/``from_api`` between the API's and the reader's units.

References
----------
1. NIST SP 811 (2008), Guide for the Use of the International System of Units, appendix
   B.8: 1 in = 0.0254 m, 1 ft = 0.3048 m, 1 lb = 0.45359237 kg, standard acceleration of
   gravity g_n = 9.80665 m/s², 1 kgf = g_n N, 1 lbf = 4.4482216152605 N (lb x g_n),
   1 psi = 1 lbf/in², 1 ozf in = 1/16 lbf in, 1 oz = 1/16 lb, all exact; appendix B.9:
   t/°C = (t/°F - 32)/1.8, and a difference of 1 °F is 5/9 K.
"""

import math
from collections.abc import Mapping
from fractions import Fraction
from functools import cached_property
from itertools import product
from typing import TypeGuard, get_args

from app.contract.figures import bound_text, sig
from app.core.phrase import Amount, Phrase
from app.core.phrase import Quantity as Quantity
from app.core.units import SI_UNITS as SI_UNITS
from app.core.units import UNITS as UNITS
from app.core.units import Unit as Unit
from app.core.units import from_si as from_si
from app.core.units import to_si as to_si

#: the API's unit system: dimension -> unit (the unit every API field name carries).
API_SYSTEM: dict[Quantity, str] = {
    **SI_UNITS,
    "length": "mm",
    "travel": "km travelled",
    "speed": "mm/s",
    "accel": "mm/s²",
    "pv": "MPa m/s",
    "pressure": "MPa",
    "wear_rate": "mm³/(N m)",
    "inductance": "mH",
}
#: dimension -> (API unit text, factor from the core's unit to the API unit).
API_UNITS: dict[Quantity, tuple[str, float]] = {
    d: (UNITS[u].text, UNITS[u].from_si) for d, u in API_SYSTEM.items()
}
_API_TO_SI: dict[Quantity, float] = {d: UNITS[u].si for d, u in API_SYSTEM.items()}

#: the page's unit switches: switch -> choice -> the unit it gives each dimension it sets
#: (a mass follows the force: pounds with pound-force; inches bring the US customary
#: contact pressure and PV, psi and psi ft/min; a rotor inertia follows the torque: oz in²
#: with oz in; temperatures in °F with inches). Dimensions no switch sets are shown in the
#: API's unit.
DISPLAY_CHOICES: dict[str, dict[str, dict[Quantity, str]]] = {
    "force_unit": {
        "N": {"force": "N", "mass": "kg"},
        "lbf": {"force": "lbf", "mass": "lb"},
        "kgf": {"force": "kgf", "mass": "kg"},
    },
    "length_unit": {
        "mm": {
            "length": "mm", "speed": "mm/s", "pressure": "MPa", "pv": "MPa m/s",
            "temperature": "°C", "temperature_rise": "K", "travel": "km travelled",
        },
        "in": {
            "length": "in", "speed": "in/s", "pressure": "psi",
            "pv": "psi ft/min", "temperature": "°F", "temperature_rise": "°F rise",
            "travel": "mi",
        },
    },
    "accel_unit": {
        "mm_s2": {"accel": "mm/s²"},
        "m_s2": {"accel": "m/s²"},
        "g": {"accel": "g"},
        "in_s2": {"accel": "in/s²"},
    },
    "torque_unit": {
        "N_m": {"torque": "N m", "inertia": "kg m²"},
        "oz_in": {"torque": "oz in", "inertia": "oz in²"},
        "lb_in": {"torque": "lb in", "inertia": "lb in²"},
    },
}  # fmt: skip
#: the page's default choices: the API's units.
DEFAULT_UNITS = {
    "force_unit": "N",
    "length_unit": "mm",
    "torque_unit": "N_m",
    "accel_unit": "mm_s2",
}
#: the acceleration unit a page in inches takes when its query names none (in/s²).
INCH_ACCEL = "in_s2"
#: switch -> the dimensions it sets.
UNIT_QUANTITIES: dict[str, tuple[Quantity, ...]] = {
    key: tuple(choices[DEFAULT_UNITS[key]]) for key, choices in DISPLAY_CHOICES.items()
}
#: the dimensions a page switch sets.
SWITCHED: frozenset[Quantity] = frozenset(q for qs in UNIT_QUANTITIES.values() for q in qs)


def _ratio(symbol: str) -> float:
    """Factor from a unit to the API's unit of its dimension, from the exact factors."""
    unit = UNITS[symbol]
    return float(unit.exact / UNITS[API_SYSTEM[unit.dimension]].exact)


def _choice_factors(key: str, main: Quantity) -> dict[str, float]:
    """Choice of a page switch -> factor from its unit of ``main`` to the API unit."""
    return {c: _ratio(units[main]) for c, units in DISPLAY_CHOICES[key].items()}


#: choice -> factor from the chosen unit to the API unit, per switch.
FORCE_UNITS = _choice_factors("force_unit", "force")
LENGTH_UNITS = _choice_factors("length_unit", "length")
TORQUE_UNITS = _choice_factors("torque_unit", "torque")
ACCEL_UNITS = _choice_factors("accel_unit", "accel")
#: torque and acceleration choices -> their symbols, for the page's switches.
TORQUE_LABELS = {c: u["torque"] for c, u in DISPLAY_CHOICES["torque_unit"].items()}
UNIT_LABELS = {
    **TORQUE_LABELS,
    **{c: u["accel"] for c, u in DISPLAY_CHOICES["accel_unit"].items()},
    "g": "g (standard)",
}


def accel_choice(units: Mapping[str, str]) -> str:
    """The acceleration switch's choice: the one given, else in/s² on a page in inches
    and mm/s² otherwise (a link from before the switch keeps its unit).

    >>> accel_choice({"length_unit": "in"}), accel_choice({"length_unit": "in", "accel_unit": "g"})
    ('in_s2', 'g')
    """
    given = units.get("accel_unit")
    if given in DISPLAY_CHOICES["accel_unit"]:
        return given
    return INCH_ACCEL if units.get("length_unit") == "in" else DEFAULT_UNITS["accel_unit"]


def _key(units: Mapping[str, str]) -> tuple[str, ...]:
    """The display system's key of the page's ``units``: its choices in the switches'
    order."""
    chosen = {**units, "accel_unit": accel_choice(units)}
    return tuple(chosen[key] for key in DISPLAY_CHOICES)


def _offset(symbol: str) -> float:
    """The API value at a unit's zero: 0 but for a temperature scale (°F: -160/9 °C)."""
    unit = UNITS[symbol]
    api = UNITS[API_SYSTEM[unit.dimension]]
    return float((unit.offset - api.offset) / api.exact)


def _chosen(choices: tuple[str, ...]) -> dict[Quantity, str]:
    """The unit (table key) of each dimension under the page's ``choices``."""
    chosen = dict(API_SYSTEM)
    for key, choice in zip(DISPLAY_CHOICES, choices, strict=True):
        chosen.update(DISPLAY_CHOICES[key][choice])
    return chosen


def _system(choices: tuple[str, ...]) -> dict[Quantity, tuple[str, float]]:
    """One display system: dimension -> (unit text, factor from it to the API unit)."""
    return {d: (UNITS[u].text, _ratio(u)) for d, u in _chosen(choices).items()}


_ALL_CHOICES = list(product(*map(list, DISPLAY_CHOICES.values())))
#: every display system the page offers, by its choices in ``DISPLAY_CHOICES`` order.
DISPLAY_SYSTEMS = {c: _system(c) for c in _ALL_CHOICES}
#: per display system, the API value at the zero of each unit with an offset (°F).
DISPLAY_OFFSETS = {
    c: {d: _offset(u) for d, u in _chosen(c).items() if _offset(u)} for c in _ALL_CHOICES
}


def _display_unit(quantity: Quantity, units: Mapping[str, str]) -> Unit:
    return UNITS[_chosen(_key(units))[quantity]]


def exact_factor(quantity: Quantity, units: Mapping[str, str]) -> Fraction:
    """The factor from the display unit of ``quantity`` to the API unit, exactly (5/9
    for °F)."""
    return _display_unit(quantity, units).exact / UNITS[API_SYSTEM[quantity]].exact


def exact_offset(quantity: Quantity, units: Mapping[str, str]) -> Fraction:
    """``offset`` exactly, from the table: -160/9 for °F."""
    api = UNITS[API_SYSTEM[quantity]]
    return (_display_unit(quantity, units).offset - api.offset) / api.exact


def offset(quantity: Quantity, units: Mapping[str, str]) -> float:
    """The API value at the zero of the display unit of ``quantity``: 0 but for °F.

    >>> offset("temperature", {**DEFAULT_UNITS, "length_unit": "in"})
    -17.77777777777778
    """
    return DISPLAY_OFFSETS[_key(units)].get(quantity, 0.0)


def display_system(units: Mapping[str, str]) -> dict[Quantity, tuple[str, float]]:
    """The display system of the page's choices: dimension -> (symbol, factor to API).

    >>> display_system({"force_unit": "lbf", "length_unit": "in", "torque_unit": "N_m"})[
    ...     "speed"]
    ('in/s', 25.4)
    """
    return DISPLAY_SYSTEMS[_key(units)]


def api_to_si(value: float, quantity: Quantity) -> float:
    """A value in the API's unit of ``quantity`` in the core's unit.

    >>> api_to_si(50.0, "speed")
    0.05
    """
    return value * _API_TO_SI[quantity]


def si_to_api(value: float, quantity: Quantity) -> float:
    """A value in the core's unit in the API's unit of ``quantity``.

    >>> si_to_api(0.01, "length"), si_to_api(2.5e6, "pv")
    (10.0, 2.5)
    """
    return value * API_UNITS[quantity][1]


def factor(quantity: Quantity, units: Mapping[str, str]) -> float:
    """Factor from the chosen display unit of ``quantity`` to the API unit."""
    return display_system(units)[quantity][1]


def label(quantity: Quantity, units: Mapping[str, str]) -> str:
    """Display label of the chosen unit, e.g. 'in/s' for speed in inches."""
    return display_system(units)[quantity][0]


def to_api(value: float, quantity: Quantity, units: Mapping[str, str]) -> float:
    """A value in the reader's unit of ``quantity`` in the API's unit.

    >>> to_api(212.0, "temperature", {**DEFAULT_UNITS, "length_unit": "in"})
    100.0
    """
    return value * display_system(units)[quantity][1] + offset(quantity, units)


def from_api(value: float, quantity: Quantity, units: Mapping[str, str]) -> float:
    """A value in the API's unit of ``quantity`` in the reader's unit.

    >>> from_api(-40.0, "temperature", {**DEFAULT_UNITS, "length_unit": "in"})
    -40.0
    """
    return _in_display(value, quantity, display_system(units), DISPLAY_OFFSETS[_key(units)])


def _in_display(
    value: float,
    quantity: Quantity,
    system: Mapping[Quantity, tuple[str, float]],
    offsets: Mapping[Quantity, float],
) -> float:
    """``from_api`` in the display system ``system`` with its ``offsets``."""
    return (value - offsets.get(quantity, 0.0)) / system[quantity][1]


#: dimension -> number format in sentences (a speed in rpm needs no decimals).
TEXT_FORMATS: dict[Quantity, str] = {
    **dict.fromkeys(get_args(Quantity), ".4g"),
    "torque": ".3g",
    "rpm": ".0f",
    "pv": ".3g",
    "years": ".3g",
    "temperature": ".4g",
    "travel": ",.4g",
    "temperature_rise": ".3g",
    "factor": "g",
    "frequency": ".6g",
    "voltage": ".3g",
}


def api_value(value_si: float, quantity: Quantity | None) -> tuple[float, str]:
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
    value, _ = api_value(amount.value, amount.quantity)
    key = _key(units)  # the display system looked up once (``from_api``'s arithmetic)
    unit, scale = DISPLAY_SYSTEMS[key][amount.quantity]
    shown = (value - DISPLAY_OFFSETS[key].get(amount.quantity, 0.0)) / scale
    return f"{bound_text(shown, TEXT_FORMATS[amount.quantity], amount.rounded)} {unit}".strip()


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


#: API unit of a check value -> the display dimension it is converted with.
API_UNIT_QUANTITY: dict[str, Quantity] = {API_SYSTEM[q]: q for q in sorted(SWITCHED)}

#: SI unit text of a catalog value -> the unit it is shown in.
CATALOG_UNITS = {
    "m": "mm",
    "Pa": "GPa",
    "Pa m/s": "MPa m/s",
    "1/K": "µm/(m K)",
    "m/m": "mm/m",
    "kg m2/m": "kg m²/m",
    "kg/m3": "kg/m³",
    "C": "°C",
    "m³/(N m)": "mm³/(N m)",
}
#: catalog field-name prefix -> the unit it is shown in, where mm would mislead.
CATALOG_FIELD_UNITS = {"max_length": "m", "life": "km"}


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
    shown = next(
        (u for prefix, u in CATALOG_FIELD_UNITS.items() if name.startswith(prefix)),
        CATALOG_UNITS.get(unit),
    )
    scale = 1.0 if shown is None else UNITS[shown].from_si
    shown = unit if shown is None else shown
    if not isinstance(value, tuple | list):
        return _catalog_text(value, scale), shown
    texts = [_catalog_text(v, scale) for v in value]
    is_range = len(texts) == 2 and not any(isinstance(v, tuple | list) for v in value)
    return (" – " if is_range else ", ").join(texts), shown


def worked_out(value: float | None) -> TypeGuard[float]:
    """Whether a value is a number to write: given, and finite (a non-finite one is null
    in the JSON, as ``app.server.responses.ModelJSON`` writes it; an infinite inertia
    ratio from a rotor of 5e-324 kg m²)."""
    return value is not None and math.isfinite(value)


class Display:
    """API-unit values (N, mm, mm/s, N m) shown in the user's display units."""

    def __init__(self, units: dict[str, str]) -> None:
        self.units = units

    @cached_property
    def _system(self) -> tuple[dict[Quantity, tuple[str, float]], dict[Quantity, float]]:
        """The display system and its offsets, looked up once: a results table converts
        some two hundred numbers (``from_api``'s arithmetic)."""
        key = _key(self.units)
        return DISPLAY_SYSTEMS[key], DISPLAY_OFFSETS[key]

    def value(self, api_value: float, quantity: Quantity) -> float:
        """The number in display units."""
        return _in_display(api_value, quantity, *self._system)

    def text(self, api_value: float | None, quantity: Quantity, digits: int = 4) -> str:
        """The number in display units as text; an em dash for a number not worked out
        (``worked_out``)."""
        if not worked_out(api_value):
            return "—"
        return sig(self.value(api_value, quantity), digits)

    def label(self, quantity: Quantity) -> str:
        return self._system[0][quantity][0]

    def check(self, api_value: float | None, api_unit: str) -> str:
        """A check's value or limit with its unit, converted where the unit is a display one.

        >>> Display({"force_unit": "lbf", "length_unit": "in", "torque_unit": "N_m"}).check(
        ...     100.0, "N")
        '22.48 lbf'
        >>> Display(dict(DEFAULT_UNITS)).check(float("inf"), "")
        '—'
        """
        if not worked_out(api_value):
            return "—"
        quantity = API_UNIT_QUANTITY.get(api_unit)
        if quantity is None:
            return f"{sig(api_value)} {api_unit}".strip()
        return f"{self.text(api_value, quantity)} {self.label(quantity)}"

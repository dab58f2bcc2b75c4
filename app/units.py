"""Unit conversion at the edge. The core is SI; the API speaks mm, mm/s, N, N m, MPa m/s;
the page lets the user pick display units. One table per quantity: factor to the API unit.
"""

from typing import Literal

Quantity = Literal["force", "length", "speed", "accel", "torque"]

#: display unit -> factor that converts a value in that unit to the API unit.
FORCE_UNITS = {"N": 1.0, "lbf": 4.4482216152605, "kgf": 9.80665}
LENGTH_UNITS = {"mm": 1.0, "in": 25.4}
TORQUE_UNITS = {"N_m": 1.0, "oz_in": 0.0070615518333, "lb_in": 0.112984829027617}
TORQUE_LABELS = {"N_m": "N m", "oz_in": "oz in", "lb_in": "lb in"}
DEFAULT_UNITS = {"force_unit": "N", "length_unit": "mm", "torque_unit": "N_m"}


def factor(quantity: Quantity, units: dict[str, str]) -> float:
    """Factor from the chosen display unit of ``quantity`` to the API unit."""
    if quantity == "force":
        return FORCE_UNITS[units["force_unit"]]
    if quantity == "torque":
        return TORQUE_UNITS[units["torque_unit"]]
    return LENGTH_UNITS[units["length_unit"]]


def label(quantity: Quantity, units: dict[str, str]) -> str:
    """Display label of the chosen unit, e.g. 'in/s' for speed in inches."""
    if quantity == "force":
        return units["force_unit"]
    if quantity == "torque":
        return TORQUE_LABELS[units["torque_unit"]]
    base = units["length_unit"]
    return {"length": base, "speed": f"{base}/s", "accel": f"{base}/s²"}[quantity]


def to_api(value: float, quantity: Quantity, units: dict[str, str]) -> float:
    return value * factor(quantity, units)


def from_api(value: float, quantity: Quantity, units: dict[str, str]) -> float:
    return value / factor(quantity, units)


#: SI unit of a core check value -> (API unit label, factor from SI).
CHECK_UNITS = {
    "m/s": ("mm/s", 1e3),
    "m": ("mm", 1e3),
    "Pa m/s": ("MPa m/s", 1e-6),
    "rpm": ("rpm", 1.0),
    "N": ("N", 1.0),
    "N m": ("N m", 1.0),
    "year": ("year", 1.0),
    "": ("", 1.0),
}

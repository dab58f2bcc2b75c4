"""The test machine's axes, written once for the API's and the page's machine tests: a
printer's Z axis (vertical, with a brake) carried by its X axis, in the API's input names,
and the same axes as the selector links the machine page reads."""

from typing import Any
from urllib.parse import urlencode

from app.contract.fields import BY_API

Z: dict[str, Any] = {
    "load_n": 0,
    "moving_mass_kg": 0.5,
    "speed_mm_s": 10,
    "length_mm": 250,
    "accel_mm_s2": 200,
    "orientation": "vertical",
    "stroke_mm": 200,
    "lead_mm": 8,
    "motor": "17hs19-2004s1",
    "brake_torque_nm": 0.1,
}
X: dict[str, Any] = {
    "load_n": 0,
    "moving_mass_kg": 0.8,
    "speed_mm_s": 100,
    "length_mm": 400,
    "accel_mm_s2": 1000,
    "stroke_mm": 300,
    "motor": "17hs19-2004s1",
}


def page_query(inputs: dict[str, Any]) -> str:
    """An axis's inputs as the query of its selector link, in the page's names
    ('load_n' -> 'load'), in the same order.

    >>> page_query({"load_n": 0, "speed_mm_s": 10, "orientation": "vertical"})
    'load=0&speed=10&orientation=vertical'
    """
    return urlencode({BY_API[name].page: value for name, value in inputs.items()})

"""Worked requests for /docs: two axes an engineer sizes, each a request body of the
operations that take one (validated and posted by ``tests/api/test_docs_examples.py``).

- The Z axis of a desktop 3D printer: a 1 kg gantry lifted on an 8 mm lead at 12 mm/s,
  200 mm strokes 40 times a day for 5 years, held by the energised motor (a drop with
  the power off accepted, as on most printers).
- A pick-and-place axis with a library stepper, the STEPPERONLINE 17HS19-2004S1: a
  1.5 kg head, no process load, 300 mm/s, 10 m/s², 400 mm strokes on a 500 mm screw,
  20 000 cycles a day.
"""

from collections.abc import Sequence
from typing import Any

from app.contract.inputs import ApplicationIn
from app.contract.params import api_url

Z_AXIS: dict[str, Any] = {
    "load_n": 0,
    "moving_mass_kg": 1.0,
    "orientation": "vertical",
    "speed_mm_s": 12,
    "accel_mm_s2": 200,
    "length_mm": 350,
    "stroke_mm": 200,
    "lead_mm": 8,
    "cycles_per_day": 40,
    "required_life_years": 5,
    "hold_power_off": False,
}
PICK_AND_PLACE: dict[str, Any] = {
    "load_n": 0,
    "moving_mass_kg": 1.5,
    "speed_mm_s": 300,
    "length_mm": 500,
    "accel_mm_s2": 10000,
    "stroke_mm": 400,
    "cycles_per_day": 20000,
    "motor": "17hs19-2004s1",
}
#: The catalog screw each axis is evaluated on.
Z_SCREW, PICK_AND_PLACE_SCREW = "Tr8x8(P2)-bronze", "B4000-L25-TFE"

Z_TEXT = (
    "Z axis of a 3D printer",
    "A 1 kg gantry lifted on an 8 mm lead at 12 mm/s (200 mm/s²), 200 mm strokes on a "
    "350 mm screw, 40 a day for 5 years; the energised motor holds it.",
)
PICK_TEXT = (
    "Pick-and-place with a library motor",
    "A 1.5 kg head at 300 mm/s and 10 m/s², 400 mm strokes on a 500 mm screw, 20 000 "
    "cycles a day, driven by the library's 17HS19-2004S1 stepper.",
)


def _example(text: tuple[str, str], value: dict[str, Any]) -> dict[str, Any]:
    return {"summary": text[0], "description": text[1], "value": value}


#: The bodies of select and pairs (pairs set the motor aside and try every one).
APPLICATION_EXAMPLES = {
    "z_axis": _example(Z_TEXT, Z_AXIS),
    "pick_and_place": _example(PICK_TEXT, PICK_AND_PLACE),
}
#: The bodies of evaluate: each axis on one catalog screw.
EVALUATE_EXAMPLES = {
    "z_axis": _example(Z_TEXT, {"application": Z_AXIS, "screw": {"catalog_id": Z_SCREW}}),
    "pick_and_place": _example(
        PICK_TEXT,
        {"application": PICK_AND_PLACE, "screw": {"catalog_id": PICK_AND_PLACE_SCREW}},
    ),
}


def example_query(route: str, extra: Sequence[tuple[str, str]] = ()) -> str:
    """The GET of ``route`` for the Z axis: the worked query a GET's description shows."""
    return api_url(route, ApplicationIn.model_validate(Z_AXIS), extra)

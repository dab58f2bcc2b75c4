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

from app.contract.fields import FIELDS
from app.contract.inputs import ApplicationIn
from app.contract.params import api_url
from app.contract.units import si_to_api

#: Each input by the label the form shows it under (the field table's).
BY_LABEL = {field.label: field for field in FIELDS}


def _application(values: dict[str, Any]) -> dict[str, Any]:
    """An application written by the form's labels, in the API's units (the unit each API
    name carries), as an API body: each value under its API name."""
    return {BY_LABEL[label].api: value for label, value in values.items()}


Z_AXIS = _application(
    {
        "Axial load": 0,  # N: the gantry's weight is its mass's
        "Moving mass": 1.0,  # kg
        "Orientation": "vertical",
        "Linear speed": 12,  # mm/s
        "Acceleration": 200,  # mm/s²
        "Screw length": 350,  # mm
        "Stroke": 200,  # mm
        "Lead": 8,  # mm
        "Cycles per day": 40,
        "Required life": 5,  # years
        "Must hold with the power off": False,
        "Nut lubrication": "greased",  # a bronze nut's wear is rated lubricated
    }
)
PICK_AND_PLACE = _application(
    {
        "Axial load": 0,  # N: no process force, the head's mass alone
        "Moving mass": 1.5,  # kg
        "Linear speed": 300,  # mm/s
        "Screw length": 500,  # mm
        "Acceleration": si_to_api(10.0, "accel"),  # 10 m/s², in mm/s²
        "Stroke": 400,  # mm
        "Cycles per day": 20000,
        "Library motor": "17hs19-2004s1",
    }
)
#: The catalog screw each axis is evaluated on.
Z_SCREW, PICK_AND_PLACE_SCREW = "Tr8x8(P2)-bronze", "B4000-L25-TFE"

Z_TEXT = (
    "Z axis of a 3D printer",
    "A 1 kg gantry lifted on an 8 mm lead at 12 mm/s (200 mm/s²), 200 mm strokes on a "
    "350 mm screw, 40 a day for 5 years, the nut greased; the energised motor holds it.",
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

"""A motor's torque curve as text on the page and in share links: 'rpm:torque' pairs
in the display torque unit, read to the API's curve (N m) and written back exactly.
"""

import re
from collections.abc import Mapping
from fractions import Fraction
from typing import Any

from pydantic import TypeAdapter, ValidationError

from app.contract.exact import decimal_text, read_exact
from app.contract.fields import FIELDS
from app.contract.figures import sig
from app.contract.input_types import ASCII_NUMBER, curve_type, exact_text
from app.contract.units import DEFAULT_UNITS, display_system

#: a curve's points (rpm, N m) as the model reads and checks them.
CURVE: TypeAdapter[list[tuple[float, float]]] = TypeAdapter(
    curve_type(next(f for f in FIELDS if f.kind == "curve"))
)


def _torque_factor(units: Mapping[str, str]) -> Fraction:
    """The exact factor from the display torque unit to N m (a curve's torques)."""
    return Fraction(repr(display_system({**DEFAULT_UNITS, **units})["torque"][1]))


def curve_to_api(text: str, units: Mapping[str, str]) -> Any:
    """A curve typed on the page, torques in the display unit, as the API's points (rpm,
    N m), each torque its exact product rounded once; text the model refuses is passed
    as typed, so that its message names the point.

    >>> curve_to_api("0:16,3000:8", {"torque_unit": "oz_in"})
    [[0.0, 0.1129848290276167], [3000.0, 0.05649241451380835]]
    """
    factor = _torque_factor(units)
    try:
        exact = _typed_points(text, CURVE.validate_python(text))
    except ValidationError:
        read = _hand_points(text)
        if read is None:
            return text
        exact = read
    return [[float(rpm), float(Fraction(torque) * factor)] for rpm, torque in exact]


def _typed_points(
    text: str, points: list[tuple[float, float]]
) -> list[tuple[Fraction | float, Fraction | float]]:
    """The model's ``points`` of ``text`` with each torque the exact value of its decimal
    as typed, not the float nearest it: a link's torque in oz in is written so that the
    exact product with the unit's factor rounds to the API's torque (``decimal_text``).

    >>> _typed_points("0:0.1,1:2", [(0.0, 0.1), (1.0, 2.0)])
    [(0.0, Fraction(1, 10)), (1.0, Fraction(2, 1))]
    """
    torques = ASCII_NUMBER.findall(text)[1::2]
    if len(torques) != len(points) or any(
        float(typed) != torque for typed, (_, torque) in zip(torques, points, strict=True)
    ):
        return [(rpm, Fraction(repr(torque))) for rpm, torque in points]
    return [(rpm, Fraction(typed)) for typed, (rpm, _) in zip(torques, points, strict=True)]


def _hand_points(text: str) -> list[tuple[Fraction | float, Fraction | float]] | None:
    """A curve written by hand, a line (or ';') per point 'rpm torque', each number read
    as the page reads one (``read_exact``: '0,5', '1/2', '1 1/4'); None if a line is not.

    >>> _hand_points("0 1/2; 3000 0,25")
    [(Fraction(0, 1), Fraction(1, 2)), (Fraction(3000, 1), Fraction(1, 4))]
    >>> _hand_points("0 1 1/4"), _hand_points("0 x")
    ([(Fraction(0, 1), Fraction(5, 4))], None)
    """
    points = []
    for line in re.split(r"[\n;]", text):
        if not line.strip():
            continue
        rpm_text, *torque_text = re.split(r"\s+", line.strip(), maxsplit=1)
        rpm, torque = read_exact(rpm_text)[0], read_exact("".join(torque_text))[0]
        if rpm is None or torque is None:
            return None
        points.append((rpm, torque))
    return points


def curve_text(value: Any, units: Mapping[str, str], digits: int | None = None) -> str:
    """The API's curve (pairs, or its 'rpm:torque,...' text) with torques in the display
    unit, each the shortest decimal that reads back to the API's torque exactly (or to
    ``digits`` significant figures, for reading).

    >>> curve_text("0:0.1129848290276167,3000:0.05649241451380835", {"torque_unit": "oz_in"})
    '0:16,3000:8'
    """
    factor = _torque_factor(units)
    points = CURVE.validate_python(value)
    if digits is not None:
        return ",".join(f"{rpm:g}:{sig(t / float(factor), digits)}" for rpm, t in points)
    return ",".join(f"{exact_text(rpm)}:{decimal_text(torque, factor)}" for rpm, torque in points)


def convert_curve(text: str, source: Mapping[str, str], target: Mapping[str, str]) -> str:
    """A curve typed with torques in ``source``'s unit re-expressed in ``target``'s, as the
    page writes it (a line 'rpm torque' per point); text that is no curve as typed."""
    points = curve_to_api(text, source)
    if isinstance(points, str):
        try:
            points = CURVE.validate_python(points)
        except ValidationError:
            return text
    return curve_text(points, target).replace(",", "\n").replace(":", " ")

"""A cycle of moves at the edge: one move's API model, and the compact text a query
string and a share link carry.

A move is an object with its units in its names (``distance_mm``: above 0 up or out,
below 0 down or back; ``speed_mm_s``, ``accel_mm_s2``, ``decel_mm_s2``, ``dwell_s``,
``moving_mass_kg``, ``load_n``, ``load_direction``), each bounded as the scalar input of
the same name (``app.contract.fields``); its dwell, mass, load and load direction left out
are the axis's (those scalar inputs'). In a query string the list is one ``moves``
parameter, each move ``distance:speed:accel:decel:dwell:mass:load:direction`` in those
API units and moves joined by ``;`` (``moves_text`` writes it, ``parse_moves_text``
reads it, for the API and the page alike).
"""

import math
from collections.abc import Mapping
from typing import Any

from pydantic import BaseModel, ConfigDict, Field, field_validator
from pydantic_core import PydanticCustomError

from app.contract.fields import BY_API, FIELDS
from app.contract.input_field import InputField
from app.core import motion
from app.core.model import LoadDirection, Move

#: The most moves a cycle may have (every result stays quick).
MAX_MOVES = 50
#: The move's fields in the order the compact text gives them.
ORDER = (
    "distance_mm",
    "speed_mm_s",
    "accel_mm_s2",
    "decel_mm_s2",
    "dwell_s",
    "moving_mass_kg",
    "load_n",
    "load_direction",
)


def _bounds(api: str) -> tuple[float, float]:
    """The bounds of the scalar input ``api`` (low, high) in its API unit."""
    return BY_API[api].bounds or (0.0, 0.0)


SPEED, ACCEL = _bounds("speed_mm_s"), _bounds("accel_mm_s2")


def _by_core(core: str) -> InputField:
    """The scalar input of the core attribute ``core``."""
    return next(f for f in FIELDS if f.core == core)


#: The longest move [mm]: the longest screw.
DISTANCE = (_by_core("length_m").bounds or (0.0, 0.0))[1]
#: The shortest move [mm], either way: the shortest stroke. A shorter one is no travel
#: in SI (5e-324 mm is 0 m) and a cycle of them no time.
SHORTEST = (_by_core("stroke_m").bounds or (0.0, 0.0))[0]
#: A move shorter than ``SHORTEST``, up (True) or down: the bound it breaks as pydantic
#: says a bound (error type, context key, message), which the page says in its unit.
TOO_SHORT = {
    True: ("greater_than_equal", "ge", "Input should be greater than or equal to {ge}"),
    False: ("less_than_equal", "le", "Input should be less than or equal to {le}"),
}
#: A cycle ends where it starts to this share of its longest move: the binary rounding
#: of the typed decimals, nothing more (``closing_error_mm``).
CLOSING_SHARE = 1e-12
#: A move's values that, left out, are the axis's: each the scalar input of the same name,
#: whose API name is its core name and whose API unit is SI (s, kg, N).
AXIS_VALUES = ("dwell_s", "moving_mass_kg", "load_n", "load_direction")


def _or_axis(api: str, description: str) -> Any:
    """A move's value that, left out, is the axis's (``AXIS_VALUES``): bounded as the
    scalar input ``api`` of the same name."""
    low, high = _bounds(api)
    return Field(
        default=None, ge=low, le=high, description=f"{description}; left out: the axis's {api}."
    )


class MoveIn(BaseModel):
    """One move of the cycle, in the API's units; the dwell after it."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    distance_mm: float = Field(
        ge=-DISTANCE,
        le=DISTANCE,
        description=f"Travel of the move [mm]: above 0 up (out), below 0 down (back); "
        f"{SHORTEST:g} or more either way.",
    )
    speed_mm_s: float = Field(ge=SPEED[0], le=SPEED[1], description="Top speed [mm/s].")
    accel_mm_s2: float = Field(
        ge=ACCEL[0], le=ACCEL[1], description="Acceleration [mm/s²]; 0: the speed at once."
    )
    decel_mm_s2: float | None = Field(
        default=None,
        ge=ACCEL[0],
        le=ACCEL[1],
        description="Deceleration [mm/s²]; left out: the acceleration.",
    )
    dwell_s: float | None = _or_axis("dwell_s", "Rest after the move [s]")
    moving_mass_kg: float | None = _or_axis("moving_mass_kg", "Mass the move carries [kg]")
    load_n: float | None = _or_axis("load_n", "External axial load [N]")
    load_direction: LoadDirection | None = Field(
        default=None,
        description="How the load acts, as the scalar load_direction: auto (down when "
        "vertical, as a weight acts, against the motion when horizontal), opposes "
        "(against the motion), fixed (against the up or out move); left out: the axis's "
        "load_direction. A load has no mass: a payload's mass goes in moving_mass_kg.",
    )

    @field_validator("distance_mm")
    @classmethod
    def _moves(cls, value: float) -> float:
        if value == 0.0:
            raise ValueError("must not be 0: a pause is the dwell of the move before it")
        if abs(value) < SHORTEST:
            kind, key, message = TOO_SHORT[value > 0]
            raise PydanticCustomError(kind, message, {key: math.copysign(SHORTEST, value)})
        return value

    def to_core(self, axis: Mapping[str, Any]) -> Move:
        """The move in SI; its dwell, mass, load and load direction, where left out, the
        axis's (``axis``: the application's values in SI by core name; ``AXIS_VALUES``),
        so that a cycle of moves that gives none of them carries the axis's load."""
        accel = self.accel_mm_s2 * _si("accel_mm_s2")
        decel = accel if self.decel_mm_s2 is None else self.decel_mm_s2 * _si("decel_mm_s2")
        own = {name: getattr(self, name) for name in AXIS_VALUES}
        return Move(
            distance_m=self.distance_mm * _by_core("stroke_m").si_factor,
            speed_m_s=self.speed_mm_s * _si("speed_mm_s"),
            accel_m_s2=accel,
            decel_m_s2=decel,
            **{name: axis[name] if value is None else value for name, value in own.items()},
        )


def move_in(move: Move) -> MoveIn:
    """A core move's travel, speed and ramps in the API's units (to 12 significant
    figures: the unit's binary rounding left out); its dwell, mass, load and load
    direction left out: the axis's."""
    factors = {
        "distance_mm": _by_core("stroke_m").si_factor,
        "speed_mm_s": _si("speed_mm_s"),
        "accel_mm_s2": _si("accel_mm_s2"),
        "decel_mm_s2": _si("decel_mm_s2"),
    }
    values = (move.distance_m, move.speed_m_s, move.accel_m_s2, move.decel_m_s2)
    return MoveIn(
        **{
            name: float(f"{v / f:.12g}")
            for (name, f), v in zip(factors.items(), values, strict=True)
        }
    )


def _si(api: str) -> float:
    field: InputField = BY_API[api]
    return field.si_factor


def parse_moves_text(value: Any) -> Any:
    """Moves as the query string gives them (one text, or the texts of a repeated
    parameter, ``;`` between moves and ``:`` between a move's values in ``ORDER``) as
    move objects for ``MoveIn`` to validate; anything else as it is (JSON's list of
    objects). A value left empty takes the field's default.

    >>> parse_moves_text("300:250:2500:2500:0.2:2.5:10:opposes;-300:250:2500:2500")
    ... # doctest: +NORMALIZE_WHITESPACE
    [{'distance_mm': '300', 'speed_mm_s': '250', 'accel_mm_s2': '2500',
      'decel_mm_s2': '2500', 'dwell_s': '0.2', 'moving_mass_kg': '2.5', 'load_n': '10',
      'load_direction': 'opposes'},
     {'distance_mm': '-300', 'speed_mm_s': '250', 'accel_mm_s2': '2500',
      'decel_mm_s2': '2500'}]
    """
    if isinstance(value, list) and all(isinstance(v, str) for v in value):
        value = ";".join(value)
    if not isinstance(value, str):
        return value
    moves: list[dict[str, str]] = []
    for text in (t for t in value.split(";") if t.strip()):
        parts = [p.strip() for p in text.split(":")]
        if len(parts) > len(ORDER):
            raise ValueError(
                f"move {len(moves)} has {len(parts)} values; a move has at most "
                f"{len(ORDER)}: {':'.join(ORDER)}"
            )
        moves.append({name: part for name, part in zip(ORDER, parts, strict=False) if part})
    return moves


def _number(value: float) -> str:
    """A number as its shortest exact text ('300', '0.2', '2.5e-05')."""
    return repr(value).removesuffix(".0") if math.isfinite(value) else "0"


def moves_text(moves: list[MoveIn]) -> str:
    """The moves as one query value (``parse_moves_text`` reads it back exactly)."""
    rows = []
    for move in moves:
        values = [getattr(move, name) for name in ORDER]
        rows.append(
            ":".join("" if v is None else v if isinstance(v, str) else _number(v) for v in values)
        )
    return ";".join(rows)


def span_mm(moves: list[MoveIn]) -> float:
    """The nut's travel range over the cycle [mm]: the highest position less the lowest,
    from the start at 0 (``motion.position_span``)."""
    return motion.position_span(move.distance_mm for move in moves)


def closing_error_mm(moves: list[MoveIn]) -> float:
    """Where the cycle ends, from its start [mm], 0 for a cycle that can repeat (within
    ``CLOSING_SHARE`` of its longest move: 0 then).

    >>> closing_error_mm([MoveIn(distance_mm=0.1, speed_mm_s=1, accel_mm_s2=1),
    ...     MoveIn(distance_mm=0.2, speed_mm_s=1, accel_mm_s2=1),
    ...     MoveIn(distance_mm=-0.3, speed_mm_s=1, accel_mm_s2=1)])
    0.0
    """
    end = math.fsum(m.distance_mm for m in moves)
    longest = max((abs(m.distance_mm) for m in moves), default=0.0)
    return 0.0 if abs(end) <= CLOSING_SHARE * longest else end

"""What the motor library and the screw + motor pairs look like at the edge: the
library's motors with every value's provenance, and the ranked pairs."""

from typing import Any, Literal

from pydantic import BaseModel, Field, ValidationInfo, field_validator

from app.catalog.axis_motor import CurveOrigin
from app.contract.fields import FIELDS
from app.contract.inputs import ApplicationIn
from app.contract.outputs import API_URL, MOTOR_CURVE_ORIGIN, SourcedOut
from app.core.model import RankBy

PairRankIn = Literal["motor_margin", "motor_size", "torque"]
#: What each pair ranking sorts by, in words (the API's ``ranked_by`` and the page).
PAIR_RANKS: dict[str, str] = {
    "motor_margin": "the share of the motor used (lowest first)",
    "motor_size": "the motor's standstill torque, a cost proxy (smallest first), then "
    "the share used",
    "torque": "the peak drive torque (lowest first)",
}


#: The application's ranking (``RANK_BY``) -> the pairs' ranking it means (the motor's margin, the
#: smallest motor for the smallest screw, the lowest torque); any other ranks the pairs
#: by the motor's margin. The page and the API rank the pairs by it unless asked otherwise.
PAIR_RANK_OF: dict[str, PairRankIn] = {
    "motor_margin": "motor_margin",
    "size": "motor_size",
    "torque": "torque",
}
DEFAULT_PAIR_RANK: PairRankIn = "motor_margin"
#: The application's input that ranks the screws (its choices are the core's ``RankBy``).
RANK_BY = next(field for field in FIELDS if field.options is RankBy)


def pair_rank_of(inputs: ApplicationIn, asked: PairRankIn | None = None) -> PairRankIn:
    """The pairs' ranking: the one ``asked`` for, else the one the application's
    ranking (``RANK_BY``) means (``PAIR_RANK_OF``), as the page ranks them."""
    if asked is not None:
        return asked
    ranked = str(inputs.model_dump(include={RANK_BY.api})[RANK_BY.api])
    return PAIR_RANK_OF.get(ranked, DEFAULT_PAIR_RANK)


class MotorOut(BaseModel):
    id: str
    name: str
    frame: str
    kind: Literal["stepper", "servo"]
    values: dict[str, SourcedOut] = Field(
        description="Each datasheet value in the unit its name carries (inductance_mh in "
        "mH, rotor_inertia_g_cm2 in g cm², torques in N m, angles in deg, speeds in rpm) "
        "with its provenance; a stepper's curve is its maker's published one where the "
        "motor carries it (pull_out_curve: (rpm, N m) points read off the maker's chart), "
        "otherwise drawn by the stepper model; a servo's by the servo model (GET "
        "/api/v1/formulas)"
    )
    curve: list[tuple[float, float]] = Field(
        description="The torque-speed curve the checks use: (rpm, N m) points"
    )
    continuous_torque_nm: float | None = Field(
        description="A servo's rated torque, the RMS limit; none for a stepper"
    )


class MotorsOut(BaseModel):
    catalog_version: str
    motors: list[MotorOut]


class PairOut(BaseModel):
    screw_id: str
    series: str
    motor: str
    motor_name: str
    motor_kind: Literal["stepper", "servo"]
    frame: str
    motor_curve_origin: CurveOrigin | None = Field(description=MOTOR_CURVE_ORIGIN)
    motor_use: float = Field(
        description="The largest share of the motor used over its torque, curve, RMS and "
        "speed checks (0-1; 1 - motor_use is the margin)"
    )
    motor_limit: str = Field(
        description="The motor check motor_use is, the one nearest its limit: the name of "
        "a check of GET /api/v1/checks that judges the motor (its curve, RMS torque, speed "
        "or torque)"
    )
    torque_nm: float = Field(description="Peak drive torque with the motor's rotor [N m]")
    peak_rpm: float = Field(description="The screw's top speed in the move [rpm]")
    motor_size_nm: float = Field(description="The motor's standstill torque [N m]")
    ranked_value: float = Field(description="The number the pairs are ranked by")
    ranked_unit: str


class PairsOut(BaseModel):
    inputs: ApplicationIn
    rank: PairRankIn
    ranked_by: str
    catalog_version: str
    screws_eligible: int
    screws_passing_alone: int = Field(
        description="Screws passing every check without a motor. These are paired, and "
        "those that fail only a check a motor's own holding or detent torque may clear "
        "(holding the load)"
    )
    motors: int = Field(
        description="Library motors paired: every one, but a stepper the drive voltage "
        "given (motor_supply_v) cannot push its rated current through; each stepper runs "
        "on that voltage where one is given"
    )
    pairs_passed: int
    pairs: list[PairOut]
    share_url: str = Field(
        description="The page of the same axis with the motor 'any', which shows the pairs "
        f"(ranked as the application's {RANK_BY.api} means)."
    )
    api_url: str = Field(description=API_URL)


class PairsQuery(ApplicationIn):
    """The GET pairs' query: the application's fields and the ranking of the pairs."""

    pair_rank: PairRankIn | None = Field(
        None,
        description=f"By default the ranking the application's {RANK_BY.api} means, as the page "
        "ranks the pairs ("
        + ", ".join(f"{k} -> {v}" for k, v in PAIR_RANK_OF.items())
        + f"; any other -> {DEFAULT_PAIR_RANK}); motor_margin: "
        + PAIR_RANKS["motor_margin"]
        + "; motor_size: "
        + PAIR_RANKS["motor_size"]
        + "; torque: "
        + PAIR_RANKS["torque"],
    )

    @field_validator("*")
    @classmethod
    def _needs(cls, value: Any, info: ValidationInfo) -> Any:
        """The application's fields as ``ApplicationIn`` checks them; ``pair_rank`` as is."""
        if info.field_name == "pair_rank":
            return value
        return super()._needs(value, info)

    def application(self) -> ApplicationIn:
        """The application's fields alone, as the body of a POST would give them."""
        values = {name: getattr(self, name) for name in ApplicationIn.model_fields}
        return ApplicationIn.model_construct(self.model_fields_set - {"pair_rank"}, **values)

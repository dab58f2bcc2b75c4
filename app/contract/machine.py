"""A machine of stacked axes in the API: its axes in, each axis sized out
(``app.core.machine``)."""

from types import GenericAlias
from typing import Any, Optional, cast

from pydantic import BaseModel, ConfigDict, Field, create_model, field_validator

from app.contract.inputs import ApplicationIn
from app.contract.schemas import CandidateSummaryOut
from app.contract.sections import ProvenanceOut
from app.core.machine import MotorMassOrigin

#: The most axes a stack may have (Z on X on Y).
MAX_AXES = 3


class AxisIn(BaseModel):
    """One axis of the stack, in the API's units."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    name: str = Field(
        min_length=1,
        max_length=40,
        pattern=r"\S",
        description="The axis's name, e.g. Z: not blank, since the answer names the "
        "governing axis by it.",
        examples=["Z"],
    )
    inputs: ApplicationIn = Field(
        description="The axis as the select call takes it; its moving mass is its own "
        "carriage and payload, without the axes above it."
    )
    frame_kg: float = Field(
        default=0.0,
        ge=0.0,
        le=10_000.0,
        description="Mass that moves with this axis when it rides on the one below, "
        "besides its moving mass, screw and motor: rails, base plate, bearings [kg].",
    )
    motor_kg: float | None = Field(
        default=None,
        ge=0.0,
        le=1_000.0,
        description="Its motor's mass [kg] (0: counted in frame_kg). Typed, it wins; left "
        "out (null), the published mass of the library motor the axis names (inputs.motor, "
        "GET /api/v1/motors: mass_kg) counts, else 0.",
    )
    choice: str | None = Field(
        default=None,
        max_length=100,
        description="The catalog screw chosen for this axis (null or empty: its "
        "first-ranked). It decides the mass the axes below carry.",
    )

    @field_validator("choice", mode="before")
    @classmethod
    def _empty_is_first_ranked(cls, value: object) -> object:
        """An empty choice is no choice, as on the page: the first-ranked screw."""
        return None if isinstance(value, str) and not value.strip() else value


class MachineIn(BaseModel):
    """The axes of a machine, the top one first: each rides on the next."""

    model_config = ConfigDict(extra="forbid")

    axes: list[AxisIn] = Field(min_length=1, max_length=MAX_AXES)

    @field_validator("axes")
    @classmethod
    def _named_once(cls, axes: list[AxisIn]) -> list[AxisIn]:
        """Each axis by a name of its own: the answer names the governing axis by it."""
        names = [a.name.strip().casefold() for a in axes]
        twice = sorted({a.name for a, n in zip(axes, names, strict=True) if names.count(n) > 1})
        if twice:
            raise ValueError(f"each axis needs a name of its own: {', '.join(twice)} repeats")
        return axes


MachineAxisOut = create_model(
    "MachineAxisOut",
    __doc__="One axis sized, with the axes above it in its moving mass.",
    name=(str, ...),
    carried_kg=(float, Field(description="Mass of the axes above, added to its own [kg].")),
    uncounted=(
        list[str],
        Field(
            description="The axes above whose screw the carried mass leaves out: none "
            "passes there and none is chosen, so its mass is not known (choose one)."
        ),
    ),
    parallel=(
        list[str],
        Field(
            description="The vertical axes above this one when it is vertical too: "
            "parallel to it, so their own thrust reaches its nut (parallel_thrust_n). "
            "Every other pair of axes is taken at right angles: the upper one's thrust "
            "goes into the guides below, not the screw."
        ),
    ),
    parallel_thrust_n=(
        float,
        Field(
            description="The thrust beyond their weight and their standing load (their "
            "m a, a load that opposes their motion) that the parallel axes above pass to "
            "this axis's nut when they move while it moves, the largest of each summed [N] "
            "(stacking.parallel_reaction). Not in its sizing, which moves them one at a "
            "time: when they move together, add it to this axis's load. 0 without a "
            "parallel axis above."
        ),
    ),
    standing_load_n=(
        float,
        Field(
            description="The load that acts one way (a weight, spring or press) on the "
            "parallel axes above, which stands on this axis's nut whether either moves "
            "[N]: added to this axis's load, acting down, in its sizing and its share "
            "link (machine.with_standing_load). Where this axis's own load opposes its "
            "motion, its out and back are sized as two moves: up with the sum, down with "
            "the difference. 0 without one."
        ),
    ),
    sized_mass_kg=(
        float,
        Field(
            description="The moving mass it was sized with: its own and the carried, of "
            "its heaviest move in a cycle of moves [kg]."
        ),
    ),
    screw_kg=(
        float | None,
        Field(
            description="The chosen screw's mass over the axis's length [kg] "
            "(geometry.screw_mass); null when no screw is chosen."
        ),
    ),
    motor_kg=(
        float,
        Field(
            description="Its motor's mass in total_kg [kg]: motor_kg as typed, else the "
            "published mass of the library motor it names, at the top of its range where "
            "the library gives one (motor_mass_origin), else 0."
        ),
    ),
    motor_mass_origin=(
        cast(Any, MotorMassOrigin),
        Field(
            description="Where motor_kg comes from: typed (the axis's motor_kg), library "
            "(the library motor's published mass: motor_mass_provenance), none (0 kg: "
            "neither typed nor a library motor with a mass named)."
        ),
    ),
    motor_mass_motor=(
        str | None,
        Field(
            description="The library motor whose mass counts; null unless the origin is library."
        ),
    ),
    motor_mass_provenance=(
        Optional[ProvenanceOut],  # noqa: UP045 (a run-time type)
        Field(
            description="The library mass's provenance (kind and source, as GET "
            "/api/v1/motors gives it); null unless the origin is library."
        ),
    ),
    total_kg=(
        float,
        Field(
            description="What it brings to the axis below: moving mass, frame, motor and "
            "screw [kg]."
        ),
    ),
    evaluated=(int, ...),
    passed=(int, ...),
    chosen=(
        cast(Any, Optional[CandidateSummaryOut]),  # noqa: UP045 (a run-time type)
        Field(description="The chosen screw (summary view); null when none passes."),
    ),
    verdict=(
        str | None,
        Field(description="The chosen screw's verdict in one or two sentences."),
    ),
    energy_j=(
        dict[str, float | None] | None,
        Field(
            description="The chosen screw's energy per cycle [J], by the output table's "
            "keys (cycle_motor_work_j ...: /api/v1/formulas); null when none is chosen."
        ),
    ),
    candidates=(
        cast(Any, GenericAlias(list, (CandidateSummaryOut,))),
        Field(description="Its ranked passing screws (summary view)."),
    ),
    share_url=(str, Field(description="This axis alone, with the carried mass, on the page.")),
)


MachineOut = create_model(
    "MachineOut",
    __doc__="A machine of stacked axes sized together.",
    axes=(
        cast(Any, GenericAlias(list, (MachineAxisOut,))),
        Field(description="Each axis, the top one first."),
    ),
    governing=(
        str | None,
        Field(
            description="The axis nearest its limit or furthest past it: one with no screw "
            "chosen first, else of the chosen screws that fail the one with the highest "
            "governing utilization, else the highest governing utilization of all."
        ),
    ),
    moved_kg=(float, Field(description="The mass the bottom axis moves [kg].")),
    catalog_version=(str, ...),
)

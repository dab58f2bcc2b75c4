"""The API's application input model, generated from the field table (``app.contract.fields``).

``ApplicationIn`` is built with ``pydantic.create_model`` from ``FIELDS``: one field per
table row, with its bounds, default and description, so the API, the page and the share
links cannot disagree about an input. Everything that is not per field lives in the
hand-written base ``ApplicationInputs``: ``extra="forbid"``, the rule that a field's
``needs`` are given, and ``to_core`` (the SI ``Application`` of the core).

Typing: mypy cannot see the fields of a model made at run time, so for mypy
``ApplicationIn`` is the base class itself. Reading an input as an attribute
(``inputs.<api name>``) is then a type error on purpose; code reads ``inputs.to_core()``, a
typed dataclass in SI, or goes through the table.

Each field's type (number text, bounds, texts and lists, torque curves) is made by
``app.contract.input_types``.
"""

from collections.abc import Mapping
from typing import TYPE_CHECKING, Annotated, Any, NamedTuple

from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationError,
    ValidationInfo,
    create_model,
    field_validator,
    model_validator,
)
from pydantic_core import InitErrorDetails, PydanticCustomError

from app.catalog.axis_motor import CurveOrigin, curve_origin, drive_problem, with_motor
from app.catalog.axis_provenance import axis_provenance
from app.catalog.motors import Motor, UndrivableMotor, check_motor, undrivable_message
from app.catalog.supports import SupportUnit, check_support, with_support
from app.contract.cycle import MAX_MOVES, MoveIn, closing_error_mm, parse_moves_text, span_mm
from app.contract.fields import BY_API, FIELDS
from app.contract.figures import bound_sig
from app.contract.input_types import api_type
from app.core import duty, motion
from app.core.formulas import life
from app.core.model import Application, AxisProvenance

#: The API name of each core attribute.
API_OF = {field.core: field.api for field in FIELDS}
#: The screw's length, which bounds the span from the thrust bearing to the nut.
LENGTH = next(field for field in FIELDS if field.core == "length_m")
#: The support unit of the library that rates the thrust bearing.
SUPPORT = next(field for field in FIELDS if field.core == "support_unit")


def _definitions() -> dict[str, Any]:
    """``create_model`` field definitions: API name -> (type, default or ``...``)."""
    return {f.api: (api_type(f), ... if f.required else f.default) for f in FIELDS}


def check_drivable(value: float | None, supply_v: float, current_a: float, ohm: float) -> None:
    """The drive voltage must exceed the winding's I R, or the current is never reached."""
    message = undrivable_message(supply_v, current_a, ohm)
    if value is not None and message is not None:
        raise ValueError(message)


class Traced(NamedTuple):
    """An application in SI for the core, where its motor curve comes from, and the
    provenance of its values that the checks' capacities are (``to_core_traced``)."""

    app: Application
    origin: CurveOrigin | None
    provenance: AxisProvenance


class ApplicationInputs(BaseModel):
    """The axis an engineer wants to drive, in the API units named by each field.

    Lower bounds are physical (1 mN, 1 um/s, 1 mm ...) rather than "> 0", so that no
    input can drive a result to overflow or to zero division.
    """

    model_config = ConfigDict(extra="forbid")

    moves: Annotated[list[MoveIn], BeforeValidator(parse_moves_text)] = Field(
        default_factory=list,
        max_length=MAX_MOVES,
        description="The cycle as its moves, each with its own distance, speed, ramps, "
        "dwell, mass and load (``app.contract.cycle``); in a query string one text, "
        "distance:speed:accel:decel:dwell:mass:load:direction in mm, mm/s, mm/s², s, kg "
        "and N, moves joined by ';'; a move's dwell, mass, load or direction left out is "
        "the axis's (the scalar input). Empty: out and back over the stroke from the "
        "scalar inputs. With moves, the stroke (when not given) is the span the nut covers.",
    )

    @field_validator("*")
    @classmethod
    def _needs(cls, value: Any, info: ValidationInfo) -> Any:
        """A field with ``needs`` (the required life) is refused without those fields,
        unless it is left at its default (a dwell of 0). A cycle of moves gives the stroke
        (the span the nut covers: ``axis``).

        Fields validate in table order, after ``moves``, so the needed ones are already
        in ``info.data``.
        """
        field = BY_API.get(str(info.field_name))
        if field is None or value is None or value == field.default:
            return value
        given = {name for name in field.needs if info.data.get(name) is not None}
        if info.data.get("moves"):
            given.add(API_OF["stroke_m"])
        if not given.issuperset(field.needs):
            raise ValueError("needs " + " and ".join(field.needs))
        return value

    @field_validator("hours_per_day", check_fields=False)
    @classmethod
    def _one_duty(cls, value: float | None, info: ValidationInfo) -> float | None:
        """The duty is cycles a day or hours a day, never both (they could disagree)."""
        if value is not None and info.data.get("cycles_per_day") is not None:
            raise ValueError("give cycles_per_day or hours_per_day, not both")
        return value

    @field_validator("required_life_years", check_fields=False)
    @classmethod
    def _a_duty(cls, value: float | None, info: ValidationInfo) -> float | None:
        """A required life needs a duty to turn a life into years: cycles or hours a day."""
        given = [info.data.get(name) for name in ("cycles_per_day", "hours_per_day")]
        if value is not None and all(v is None for v in given):
            raise ValueError("needs cycles_per_day or hours_per_day")
        return value

    @field_validator("motor", check_fields=False)
    @classmethod
    def _known_motor(cls, value: str | None, info: ValidationInfo) -> str | None:
        """Read in any case and without the spaces around it, held as the library writes
        its ids (``check_motor``), so the API, the page and the share link carry one id;
        checked against the library passed as validation context (the page's form), the
        API's body where the catalog is (``to_core``)."""
        motors = (info.context or {}).get("motors") if isinstance(info.context, dict) else None
        return check_motor(BY_API["motor"].to_si(value), motors)

    @field_validator(SUPPORT.api, check_fields=False)
    @classmethod
    def _known_support(cls, value: str | None, info: ValidationInfo) -> str | None:
        """Checked against the support library passed as validation context (the page's
        form); the API's body is checked where the catalog is (``to_core``)."""
        context = info.context if isinstance(info.context, dict) else {}
        return check_support(SUPPORT.to_si(value), context.get("supports"))

    @field_validator("bearing_to_nut_mm", "nut_length_mm", check_fields=False)
    @classmethod
    def _within_length(cls, value: float | None, info: ValidationInfo) -> float | None:
        """The span from the thrust bearing to the nut, and the nut, lie on the screw."""
        length = info.data.get(LENGTH.api)
        if value is not None and length is not None and value > length:
            raise PydanticCustomError(
                "within_length",
                "at most the screw length, {shown} mm ({length})",
                {"le": float(length), "shown": f"{length:g}", "length": LENGTH.api},
            )
        return value

    @field_validator("max_step_rate_hz", check_fields=False)
    @classmethod
    def _step_angle_known(cls, value: float | None, info: ValidationInfo) -> float | None:
        """A step rate limit needs the step angle, given or the library motor's."""
        known = info.data.get("step_angle_deg") is not None or info.data.get("motor")
        if value is not None and not known:
            raise ValueError('needs step_angle_deg or a library motor ("any" for every one)')
        return value

    @field_validator("motor_holding_torque_nm", check_fields=False)
    @classmethod
    def _drivable(cls, value: float | None, info: ValidationInfo) -> float | None:
        names = ("motor_supply_v", "motor_phase_current_a", "motor_resistance_ohm")
        given = [info.data.get(name) for name in names]
        if all(v is not None for v in given):
            check_drivable(value, *(float(v or 0.0) for v in given))
        return value

    @field_validator(API_OF["stroke_m"], check_fields=False)
    @classmethod
    def _stroke_fits(cls, value: float | None, info: ValidationInfo) -> float | None:
        """The nut travels between the screw's ends: the stroke is at most the screw
        length less the nut length given (less nothing without one: each catalog nut's
        own length is then the stroke-travel check's)."""
        length = info.data.get(API_OF["length_m"])
        nut = info.data.get(API_OF["nut_length_m"])
        if value is None or length is None:
            return value
        room = float(length) - float(nut or 0.0)
        if value > room:
            less = f" less the nut length ({float(length):g} - {float(nut or 0.0):g} mm)"
            raise PydanticCustomError(
                "stroke_room" if nut else "within_length",
                f"must be at most the screw length{less if nut else ''}, {{shown}} mm: the "
                "nut cannot travel past the screw's end",
                {"le": room, "shown": f"{room:g}"},
            )
        return value

    @model_validator(mode="after")
    def _library_stepper_drivable(self, info: ValidationInfo) -> "ApplicationInputs":
        """A drive voltage, phase current or winding resistance typed for a library
        stepper (its other values the library's) must reach the current: checked
        against the library passed as validation context (the page's form), the API's
        body where the catalog is (``to_core``); refused on the drive voltage."""
        motors = (info.context or {}).get("motors") if isinstance(info.context, dict) else None
        motor_id = getattr(self, "motor", None)
        motor = None if motors is None or motor_id is None else motors.get(motor_id)
        problem = None if motor is None else drive_problem(self.axis(), motor)
        if problem is None:
            return self
        error = InitErrorDetails(
            type=PydanticCustomError(UndrivableMotor.field, problem),
            loc=(UndrivableMotor.field,),
            input=getattr(self, UndrivableMotor.field),
        )
        raise ValidationError.from_exception_data(type(self).__name__, [error])

    @model_validator(mode="after")
    def _moves_fit(self) -> "ApplicationInputs":
        """A cycle of moves ends where it starts (it repeats), and the nut's span stays on
        the screw (its length less the nut length given); refused on ``moves``."""
        if not self.moves:
            return self
        length = float(getattr(self, API_OF["length_m"]))
        room = length - float(getattr(self, API_OF["nut_length_m"]) or 0.0)
        closing, span = closing_error_mm(self.moves), span_mm(self.moves)
        message = ""
        if closing:
            message = f"must end where they start (to repeat): they sum to {closing:.6g} mm"
        elif span > room:
            message = f"span {span:.6g} mm, more than the {room:g} mm the nut can travel"
        if not message:
            return self
        error = InitErrorDetails(
            type=PydanticCustomError("moves", message), loc=("moves",), input=self.moves
        )
        raise ValidationError.from_exception_data(type(self).__name__, [error])

    @model_validator(mode="after")
    def _span_holds_the_travel(self) -> "ApplicationInputs":
        """The span from the thrust bearing to the nut at the far end of its travel is at
        least the travel: the stroke, or the span of a cycle of moves; refused on the
        span (``input_rules.least_inputs``)."""
        span = getattr(self, API_OF["bearing_to_nut_m"])
        stroke = getattr(self, API_OF["stroke_m"])
        travel = span_mm(self.moves) if self.moves else stroke
        if span is None or travel is None or span >= travel:
            return self
        what = "the moves' span" if self.moves else "the stroke"
        error = InitErrorDetails(
            type=PydanticCustomError(
                "span_holds_travel",
                f"must be at least {what}, {travel:g} mm: the nut at the far end of its "
                "travel is that far from the thrust bearing",
            ),
            loc=(API_OF["bearing_to_nut_m"],),
            input=span,
        )
        raise ValidationError.from_exception_data(type(self).__name__, [error])

    @model_validator(mode="after")
    def _cycles_fit_a_day(self) -> "ApplicationInputs":
        """The cycles per day fit in a day: at most 86,400 s over the cycle's time (out
        and back with the dwells, ``motion.move_profile``); refused on cycles_per_day."""
        name = API_OF["cycles_per_day"]
        cycles = getattr(self, name, None)
        if cycles is None:
            return self
        p = motion.move_profile(self.axis())
        if p is None or duty.cycles_fit_a_day(cycles, p):
            return self
        cycle = "its moves" if self.moves else "out and back"
        # the bound written down, so that the figure named is one the rule accepts
        most = bound_sig(duty.most_cycles_per_day(p) or 0.0, False, 6)  # p is a move
        message = (
            f"must be at most {most}: one cycle ({cycle}, with the dwells) takes "
            f"{p.cycle_time_s:.6g} s, and a day has {life.SECONDS_PER_DAY:.0f} s"
        )
        error = InitErrorDetails(
            type=PydanticCustomError("cycles_per_day", message),
            loc=(name,),
            input=cycles,
        )
        raise ValidationError.from_exception_data(type(self).__name__, [error])

    def to_core(
        self, motors: Mapping[str, Motor], supports: Mapping[str, SupportUnit] | None = None
    ) -> Application:
        """The same application in SI for the core: each value times its ``si_factor``,
        with the library motor's curve, inertia, continuous torque and step angle filled
        in from ``motors`` (``with_motor``; UnknownMotor for an id it lacks), and the
        library support unit's axial ratings from ``supports`` (``with_support``;
        UnknownSupport for an id it lacks)."""
        return self.to_core_traced(motors, supports).app

    def to_core_traced(
        self, motors: Mapping[str, Motor], supports: Mapping[str, SupportUnit] | None = None
    ) -> "Traced":
        """``to_core``'s application, where its motor curve comes from
        (``axis_motor.curve_origin``: "entered", "published" or "model"; None without a
        curve), for the responses to say beside the curve checks' results, and the
        provenance of the values the checks' capacities are (``axis_provenance``)."""
        entered = self.axis()
        app = with_support(with_motor(entered, motors), supports or {})
        origin = curve_origin(entered, app, motors)
        return Traced(app, origin, axis_provenance(entered, app, origin, motors, supports or {}))

    def axis(self) -> Application:
        """The application in SI as given, without a library motor's values filled in:
        for the axis's own numbers (length, speed, a torque limit typed in)."""
        values = {f.core: f.to_si(getattr(self, f.api)) for f in FIELDS}
        if self.moves:
            values["moves"] = tuple(m.to_core(values) for m in self.moves)
            if values["stroke_m"] is None:
                values["stroke_m"] = span_mm(self.moves) * BY_API[API_OF["stroke_m"]].si_factor
        return Application(**values)


if TYPE_CHECKING:
    ApplicationIn = ApplicationInputs
else:
    ApplicationIn = create_model(
        "ApplicationIn",
        __base__=ApplicationInputs,
        __module__=__name__,
        __doc__=ApplicationInputs.__doc__,
        **_definitions(),
    )

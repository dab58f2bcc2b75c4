"""Where the axis's values that a check's capacity is come from (``AxisProvenance``,
keyed by ``Check.capacity_given``): the motor's torque-speed curve and its rated torque,
a stepper's holding and detent torques, the support unit's ratings. Each is the user's
where typed in, else the library motor's or support unit's value, with that entry's
provenance. A curve a model draws is derived, and no more certain than the least certain
value the model reads (a drive voltage the library assumes makes the curve assumed).
"""

from collections.abc import Mapping

from app.catalog.axis_motor import DRIVE_VALUES, CurveOrigin
from app.catalog.motors import CURVE, MODEL_VALUES, Motor
from app.catalog.supports import SupportUnit
from app.core.model import RMS_ZONE, Application, Provenance
from app.core.record import CERTAINTY

#: The application's field for each value a library stepper's model reads: one typed
#: there replaces the library's in the curve.
STEPPER_FIELDS = {
    **{name: field for field, name in DRIVE_VALUES},
    "step_angle_deg": "step_angle_deg",
    "holding_torque_nm": "motor_holding_torque_nm",
}
#: Each support rating's key (``Check.capacity_given``): the application's field that
#: types it, and the library's.
SUPPORT_RATINGS = {
    "support_static": ("support_static_n", "static_axial_n"),
    "support_dynamic": ("support_dynamic_n", "dynamic_axial_n"),
}


def _model_curve(entered: Application, motor: Motor | None) -> Provenance:
    """A curve the stepper or servo model draws: derived from the values it reads, as
    certain as the least certain of the library's values the user did not type."""
    if motor is None:
        return Provenance("derived", "the microstepping model, from the datasheet values typed in")
    names = [
        n
        for n in MODEL_VALUES[motor.kind]
        if getattr(entered, STEPPER_FIELDS.get(n, ""), None) is None
    ]
    kinds = ["derived", *(motor.values[n].provenance.kind for n in names)]
    least = min(kinds, key=CERTAINTY.index)
    assumed = [n for n in names if motor.values[n].provenance.kind == "assumed"]
    model = "microstepping" if motor.kind == "stepper" else "servo"
    source = f"the {model} model, from the datasheet values of {motor.name}"
    for name in assumed:
        source += f"; assumed {name}: {motor.values[name].provenance.source}"
    return Provenance(least, source)


def _curve(origin: CurveOrigin, entered: Application, motor: Motor | None) -> Provenance:
    if origin == "entered":
        return Provenance("user", "the torque-speed curve typed in")
    if origin == "published" and motor is not None:
        return motor.values[CURVE].provenance
    return _model_curve(entered, motor)


def _continuous(motor: Motor) -> Provenance:
    """A library servo's continuous rating where its continuous duty zone narrows it above
    the rated speed: the less certain of the rated torque's and the zone's top torque's
    provenance (``RMS_ZONE``)."""
    rated = motor.values["rated_torque_nm"].provenance
    top = motor.values["top_speed_continuous_nm"].provenance
    if CERTAINTY.index(top.kind) >= CERTAINTY.index(rated.kind):
        return rated
    return Provenance(top.kind, f"{rated.source}; continuous duty zone: {top.source}")


def _holding(entered: Application, motor: Motor) -> dict[str, Provenance]:
    """A library stepper's torques that hold the load where the user typed none: its
    holding torque, energised (``energised_holding``: the brake torque the holding check
    reads), and its detent torque with the power off."""
    found = {}
    energised = entered.holding_source == "energised" and entered.brake_torque_nm is None
    if energised and entered.motor_holding_torque_nm is None and motor.kind == "stepper":
        found["motor_holding"] = motor.values["holding_torque_nm"].provenance
    if entered.detent_torque_nm is None and "detent_torque_nm" in motor.values:
        found["motor_detent"] = motor.values["detent_torque_nm"].provenance
    return found


def axis_provenance(
    entered: Application,
    app: Application,
    origin: CurveOrigin | None,
    motors: Mapping[str, Motor],
    supports: Mapping[str, SupportUnit],
) -> dict[str, Provenance]:
    """The provenance of ``app``'s values that the checks' capacities are, where not typed
    in: ``entered`` is the axis before its library motor and support unit were filled in
    (``with_motor``, ``with_support``), ``origin`` where its motor curve comes from
    (``curve_origin``)."""
    found: dict[str, Provenance] = {}
    motor = motors.get(app.motor or "")
    if origin is not None:
        found["motor_curve"] = _curve(origin, entered, motor)
    if motor is not None and motor.kind == "servo" and entered.motor_rms_torque_nm is None:
        found["motor_rms_torque"] = motor.values["rated_torque_nm"].provenance
        if app.motor_rms_curve and not entered.motor_rms_curve:
            found[RMS_ZONE] = _continuous(motor)
    if motor is not None:
        found.update(_holding(entered, motor))
    unit = supports.get(app.support_unit or "")
    for key, (field, name) in SUPPORT_RATINGS.items():
        if unit is not None and getattr(entered, field) is None:
            found[key] = unit.values[name].provenance
    return found

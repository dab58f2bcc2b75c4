"""A motor on the axis: the application with its motor's curve, inertia, continuous
torque, step angle and holding filled in at the edge (``with_motor``, called by
``app.contract.inputs``), and where that curve comes from (``curve_origin``).

A library motor (``app.catalog.motors``) gives a stepper's pull-out curve, the maker's
published curve where the entry carries one and otherwise drawn by the stepper model at
the drive voltage of the maker's curve, its rotor inertia and step angle; a servo's peak
envelope (the curve), its rated torque (the RMS limit) and its rotor inertia; unless the
user gives those inputs directly. A stepper's datasheet values typed in are drawn the
same way, and a drive voltage, current or winding value typed for a library stepper
replaces the library's. The screw + motor pairs run the axis with each library motor in
turn (``pair_applications``).
"""

import math
from collections.abc import Mapping
from dataclasses import replace
from typing import Literal, cast

import numpy as np

from app.catalog.motors import (
    ANY_MOTOR,
    MODEL_VALUES,
    Curve,
    Motor,
    UndrivableMotor,
    UnknownMotor,
    model_curve,
    undrivable_message,
    unknown_motor_message,
)
from app.core.formulas import stepper
from app.core.machine import LibraryMotorMass
from app.core.model import Application

#: The stepper model's datasheet values (``motors.model_curve``).
ModelArgs = tuple[float, float, float, float, float, float]


def _datasheet_curve(app: Application) -> tuple[tuple[float, float], ...]:
    """The pull-out curve of the stepper whose electrical values the user gave (none
    without them)."""
    values = (
        app.motor_supply_v,
        app.motor_phase_current_a,
        app.motor_resistance_ohm,
        app.motor_inductance_h,
        app.step_angle_deg,
    )
    if app.motor_holding_torque_nm is None or any(v is None for v in values):
        return ()
    supply, current, resistance, inductance, step = (float(v or 0.0) for v in values)
    if stepper.corner_speed_rpm(supply, current, resistance, inductance, step) <= 0.0:
        return ()
    args = (supply, current, resistance, inductance, step, app.motor_holding_torque_nm)
    return model_curve(args, app.motor_current_rms)


#: Where the torque-speed curve the checks read comes from.
CurveOrigin = Literal["entered", "published", "model"]
#: Each origin as the motor chart's legend and the API's description name it.
CURVE_ORIGINS: dict[CurveOrigin, str] = {
    "entered": "as entered",
    "published": "maker's published curve",
    "model": "model, from datasheet values",
}


def curve_origin(
    entered: Application, app: Application, motors: Mapping[str, Motor]
) -> CurveOrigin | None:
    """Where ``app``'s motor curve (``with_motor``'s) comes from: "entered" where the
    inputs ``entered`` (the axis before ``with_motor``) carry a curve of their own,
    "published" where it is the library motor's published curve (``Motor.published_curve``,
    at the share of it the drive's current gives: ``Motor.curve``), "model" where it is
    drawn from datasheet values (the stepper or servo model), None without a curve."""
    if not app.motor_curve:
        return None
    if entered.motor_curve:
        return "entered"
    motor = motors.get(app.motor or "")
    if motor is None or motor.published_curve() is None:
        return "model"
    return "published" if motor.curve(app.motor_current_rms) == app.motor_curve else "model"


def with_motor(app: Application, motors: Mapping[str, Motor]) -> Application:
    """``app`` with its motor's curve, inertia, continuous torque and step angle filled
    in: a given curve first, then one drawn from the datasheet values, then the library
    motor's (raise UnknownMotor for an id ``motors`` lacks); a drive voltage only where
    the model draws the curve (``model_drive_only``)."""
    curve = app.motor_curve or _datasheet_curve(app)
    if app.motor is None or app.motor == ANY_MOTOR:
        held = energised_holding(app, app.motor_holding_torque_nm)
        return model_drive_only(app, replace(held, motor_curve=curve), motors)
    motor = motors.get(app.motor)
    if motor is None:
        raise UnknownMotor(unknown_motor_message(app.motor, motors))
    driven = with_library_motor(replace(app, motor_curve=curve), motor)
    return model_drive_only(app, driven, motors)


def model_drive_only(
    entered: Application, driven: Application, motors: Mapping[str, Motor]
) -> Application:
    """``driven`` (``entered`` with its motor) carrying a drive voltage only where the
    model draws its curve (``curve_origin`` "model"): the motor-curve check reads the
    model's confirmed range and supply range from it, and neither applies to a maker's
    published curve or to a curve typed in, whatever datasheet values come with it."""
    if curve_origin(entered, driven, motors) == "model":
        return driven
    return replace(driven, motor_supply_v=None)


def energised_holding(app: Application, holding_nm: float | None) -> Application:
    """``app`` held by the stepper's energised holding torque ``holding_nm`` [N m] where
    the user says the motor holds the load (``holding_source`` "energised") and gave no
    holding torque of their own."""
    if app.holding_source != "energised" or app.brake_torque_nm is not None:
        return app
    return app if holding_nm is None else replace(app, brake_torque_nm=holding_nm)


def with_library_motor(app: Application, motor: Motor) -> Application:
    """``app`` driven by ``motor``, keeping any motor value the user gave; a stepper
    holding the load energised holds it with its holding torque (``energised_holding``),
    and a stepper drawn from the model carries the values the model's validity range is
    read from (``with_model_values``). A stepper given a drive voltage, phase current,
    winding value or holding torque of the user's (``drive_retyped``) is drawn by the
    model at those values, and a maker's published curve lowered where the model says
    they give less, never raised (``_retyped_curve``; raise UndrivableMotor where that
    voltage never reaches that current)."""
    inertia = app.motor_inertia_kg_m2
    rms = app.motor_rms_torque_nm
    detent = app.detent_torque_nm
    if not app.motor_curve and motor.kind == "stepper":
        retyped = drive_retyped(app, motor)
        app = with_model_values(app, motor)
        if retyped:
            app = replace(app, motor_curve=_retyped_curve(app, motor))
    holding = app.motor_holding_torque_nm if motor.kind == "stepper" else None
    return replace(
        energised_holding(app, holding or motor.holding_torque_nm()),
        detent_torque_nm=detent if detent is not None else motor.detent_torque_nm(),
        motor=motor.id,
        motor_curve=app.motor_curve or motor.curve(app.motor_current_rms),
        motor_inertia_kg_m2=inertia if inertia is not None else motor.value("rotor_inertia_g_cm2"),
        motor_rms_torque_nm=rms if rms is not None else motor.continuous_torque_nm(),
        # a continuous torque typed in holds at every speed, unless a zone is typed too
        motor_rms_curve=app.motor_rms_curve or (motor.continuous_curve() if rms is None else ()),
        step_angle_deg=app.step_angle_deg or motor.step_angle_deg(),
    )


#: A library stepper's drive and winding values a value typed in replaces: (the
#: Application's field, the library's value).
DRIVE_VALUES = (
    ("motor_supply_v", "supply_v"),
    ("motor_phase_current_a", "phase_current_a"),
    ("motor_resistance_ohm", "resistance_ohm"),
    ("motor_inductance_h", "inductance_mh"),
)


def library_motor_mass(app: Application, motors: Mapping[str, Motor]) -> LibraryMotorMass | None:
    """The published mass of the library motor ``app`` names (``with_motor``'s
    application: its ``motor`` is the library's id), at the top of its range where the
    library gives one (``Motor.heaviest_kg``), with its provenance, for the machine to
    count on the axis below; None without a library motor (none, or "any") or where the
    library gives no mass."""
    motor = motors.get(app.motor) if app.motor is not None else None
    mass = None if motor is None else motor.mass()
    heaviest = None if motor is None else motor.heaviest_kg()
    if motor is None or mass is None or heaviest is None:
        return None
    return LibraryMotorMass(motor.id, heaviest, mass.provenance)


def drive_retyped(app: Application, motor: Motor) -> bool:
    """Whether the user typed a drive voltage, phase current, winding value or holding
    torque for library stepper ``motor`` other than the library's: its curve is then
    the model's at those values (a maker's published curve holds only at its chart's
    drive voltage and current)."""
    typed: list[tuple[float | None, float | None]] = [
        (getattr(app, field), motor.value(name)) for field, name in DRIVE_VALUES
    ]
    typed.append((app.motor_holding_torque_nm, motor.holding_torque_nm()))
    # the library's own value typed back (a form's unit conversion may move its last bit)
    return any(
        value is not None and not math.isclose(value, library or 0.0) for value, library in typed
    )


def holding_at(motor: Motor, current_a: float) -> float:
    """A library stepper's holding torque at phase current ``current_a`` [A]: its rated
    holding torque times the current over its rated current, at most the rated torque
    (torque proportional to current below the rating, the torque constant; above it the
    iron saturates, and no more than the rating is claimed) [N m]."""
    rated_a = motor.value("phase_current_a")
    return motor.value("holding_torque_nm") * min(1.0, current_a / rated_a)


def with_model_values(app: Application, motor: Motor) -> Application:
    """``app`` with library stepper ``motor``'s drive voltage, phase current, winding and
    holding torque wherever the user typed none (``DRIVE_VALUES``; the holding torque
    at the phase current, ``holding_at``), those its curve is drawn from: what the
    motor-curve check reads the model's confirmed range from
    (``stepper.confirmed_range_rpm``); and its winding resistance, for the copper loss of
    a cycle (``cycle_energy.cycle_energy``)."""
    current = app.motor_phase_current_a or motor.value("phase_current_a")
    return replace(
        app,
        motor_supply_v=app.motor_supply_v or motor.value("supply_v"),
        motor_phase_current_a=current,
        motor_resistance_ohm=app.motor_resistance_ohm or motor.value("resistance_ohm"),
        motor_inductance_h=app.motor_inductance_h or motor.value("inductance_mh"),
        motor_holding_torque_nm=app.motor_holding_torque_nm or holding_at(motor, current),
    )


def drive_problem(app: Application, motor: Motor) -> str | None:
    """Why ``app``'s drive cannot run library motor ``motor`` (``undrivable_message``
    at the values ``with_library_motor`` draws its curve from); None where it can, or
    where the library's own values or a curve of the user's draw it."""
    if motor.kind != "stepper" or app.motor_curve or not drive_retyped(app, motor):
        return None
    return _undrivable(with_model_values(app, motor))


def _undrivable(app: Application) -> str | None:
    """``undrivable_message`` at ``app``'s drive voltage, phase current and winding."""
    current, ohm = app.motor_phase_current_a or 0.0, app.motor_resistance_ohm or 0.0
    return undrivable_message(app.motor_supply_v or 0.0, current, ohm)


def _retyped_curve(app: Application, motor: Motor) -> Curve:
    """The pull-out curve of library stepper ``motor`` at the values typed in
    (``with_model_values``'s): the model's, or for a motor whose maker publishes its
    curve, that curve lowered as the model says the typed drive lowers it
    (``under_published``); raise UndrivableMotor where that drive voltage never reaches
    that phase current."""
    message = _undrivable(app)
    if message is not None:
        raise UndrivableMotor(message)
    step = app.step_angle_deg or motor.step_angle_deg()
    typed = _datasheet_curve(replace(app, step_angle_deg=step))
    published = motor.published_curve()
    if published is None:
        return motor.within_top_speed(typed)
    values = tuple(motor.value(name) for name in MODEL_VALUES["stepper"])
    library = model_curve(cast(ModelArgs, values), app.motor_current_rms)
    return under_published(published, typed, library)


def under_published(published: Curve, typed: Curve, library: Curve) -> Curve:
    """A maker's published pull-out curve at another drive: at each of its points, the
    least of its torque, that torque times the model's at the typed drive (``typed``)
    over the model's at the drive of the maker's chart (``library``), and the model's
    at the typed drive. The chart is the only data: a drive the model says gives less
    lowers it, none raises it above the maker's published torque (the model runs up to
    1.3 times above some makers' charts) or above the model's own figure, nor runs the
    motor past the chart's last speed.

    >>> under_published(((0.0, 0.4), (600.0, 0.3)), ((0.0, 0.5), (600.0, 0.2)),
    ...                 ((0.0, 0.5), (600.0, 0.4)))
    ((0.0, 0.4), (600.0, 0.15))
    >>> under_published(((0.0, 0.4), (600.0, 0.3)), ((0.0, 0.2), (600.0, 0.1)),
    ...                 ((0.0, 0.2), (600.0, 0.2)))
    ((0.0, 0.2), (600.0, 0.1))
    """
    scaled = []
    for rpm, nm in published:
        given, chart = _torque_at(typed, rpm), _torque_at(library, rpm)
        share = min(1.0, given / chart) if chart > 0.0 else float(given > 0.0)
        scaled.append((rpm, min(nm * share, given)))
    return tuple(scaled)


def _torque_at(curve: Curve, rpm: float) -> float:
    """``curve``'s torque at ``rpm``, linear between its points [N m] (0 past its last)."""
    speeds, torques = zip(*curve, strict=True)
    return 0.0 if rpm > speeds[-1] else float(np.interp(rpm, speeds, torques))


def without_motor(app: Application) -> Application:
    """``app`` with no motor: no library id, curve, rotor inertia, continuous torque,
    datasheet values or step angle (the controller's microsteps and rate stay)."""
    return replace(
        app,
        motor=None,
        motor_curve=(),
        motor_inertia_kg_m2=None,
        motor_rms_torque_nm=None,
        motor_rms_curve=(),
        motor_supply_v=None,
        motor_phase_current_a=None,
        motor_resistance_ohm=None,
        motor_inductance_h=None,
        motor_holding_torque_nm=None,
        step_angle_deg=None,
    )


def pair_applications(
    app: Application, motors: Mapping[str, Motor]
) -> tuple[Application, dict[str, Application]]:
    """``app`` without a motor, and driven by each library motor in turn: what
    ``app.core.pairs.rank_pairs`` reads. Each motor with the library's values, but a
    stepper on the drive voltage typed in, the drive's and the same for every stepper
    (``with_library_motor``: the model at that voltage); a stepper that voltage cannot
    push its rated current through is left out (UndrivableMotor)."""
    alone = without_motor(app)
    driven: dict[str, Application] = {}
    for mid, motor in motors.items():
        drive = app.motor_supply_v if motor.kind == "stepper" else None
        try:
            on_drive = with_library_motor(replace(alone, motor_supply_v=drive), motor)
        except UndrivableMotor:
            continue
        driven[mid] = model_drive_only(alone, on_drive, motors)
    return alone, driven

"""The motor library (``motors.toml`` in any catalog directory): steppers with their
datasheet's electrical values and servos with their torque ratings, each value with its
provenance, validated with the catalog (file, entry and field named on error) and held
on the ``Catalog`` the app passes around.

A library motor becomes the application's motor at the edge (``with_motor``, called by
``app.contract.inputs``): a stepper's pull-out curve, the maker's published curve where
the entry carries one (``pull_out_curve``) and otherwise drawn by the stepper model at
the drive voltage of the maker's curve, its rotor inertia and step angle; a servo's peak
envelope (the curve), its rated torque (the RMS limit) and its rotor inertia; unless the
user gives those inputs directly. A stepper's datasheet values typed in are drawn the
same way.
"""

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, replace
from functools import lru_cache
from itertools import pairwise
from pathlib import Path
from typing import Any, Literal

from app.catalog.entry import Entry
from app.catalog.errors import CatalogError
from app.catalog.files import library_entries, merge_libraries
from app.catalog.models import Sourced
from app.core.formulas import servo, stepper
from app.core.model import Application
from app.core.units import to_si

#: The library's file name; family loading skips it in every catalog directory.
MOTOR_FILE = "motors.toml"
SCHEMA = 1
#: Field -> the unit its value is written in, by motor kind.
FIELDS = {
    "stepper": {
        "step_angle_deg": "",
        "holding_torque_nm": "N m",
        "phase_current_a": "",
        "resistance_ohm": "",
        "inductance_mh": "mH",
        "rotor_inertia_g_cm2": "g cm²",
        "supply_v": "",
    },
    "servo": {
        "rated_torque_nm": "N m",
        "peak_torque_nm": "N m",
        "rated_rpm": "",
        "max_rpm": "",
        "top_speed_torque_nm": "N m",
        "rotor_inertia_g_cm2": "g cm²",
    },
}
PLAIN = frozenset({"name", "frame", "kind"})
#: Values a stepper's entry may leave out where its datasheet does not publish them.
OPTIONAL = {"stepper": {"detent_torque_nm": "N m", "pull_out_curve": ""}, "servo": {}}
#: A published pull-out curve: rows of (speed [rpm], torque [N m]) read at the maker's
#: plotted points, at the drive and supply its source names.
CURVE = "pull_out_curve"
#: Each field's unit as held (SI, or the datasheet's own for angles, currents, voltages
#: and speeds); the edges show each value in the unit its name carries (``NAMED_UNITS``).
SI_UNITS = {
    "step_angle_deg": "deg",
    "holding_torque_nm": "N m",
    "phase_current_a": "A",
    "resistance_ohm": "ohm",
    "inductance_mh": "H",
    "rotor_inertia_g_cm2": "kg m²",
    "supply_v": "V",
    "rated_torque_nm": "N m",
    "peak_torque_nm": "N m",
    "rated_rpm": "rpm",
    "max_rpm": "rpm",
    "top_speed_torque_nm": "N m",
    "detent_torque_nm": "N m",
    CURVE: "rpm, N m",
}
#: Field -> the unit (a key of the unit table) its name carries and its file is written
#: in: the API shows the value in it (the fields not listed are held in that unit).
NAMED_UNITS = {
    name: unit
    for units in (*FIELDS.values(), *OPTIONAL.values())
    for name, unit in units.items()
    if unit
}
#: The motor input that asks for every library motor: the selection runs without a
#: motor and the screw + motor pairs are ranked (``pair_applications``).
ANY_MOTOR = "any"
#: Values that may be zero (a brushed DC motor's envelope falls from standstill).
MAY_BE_ZERO = frozenset({"rated_rpm"})
#: The stepper model's curve is drawn up to this speed [rpm]: hybrid steppers on
#: leadscrews rarely run faster, and past it the model's 1 / n fall is unchecked.
MAX_STEPPER_RPM = 3000.0


class UnknownMotor(ValueError):
    """A motor id the loaded library does not hold (a 422 on the ``motor`` field)."""


class UndrivableMotor(ValueError):
    """A drive voltage typed for a library stepper that cannot push its phase current
    through its winding: a 422 on the drive voltage."""

    #: the API input the message is about
    field = "motor_supply_v"


def undrivable_message(supply_v: float, current_a: float, ohm: float) -> str | None:
    """Why a drive of ``supply_v`` [V] never reaches ``current_a`` [A] through ``ohm``
    (the voltage must exceed the winding's I R); None where it does."""
    if supply_v > current_a * ohm:
        return None
    return (
        f"a {supply_v:g} V drive cannot push {current_a:g} A through {ohm:g} ohm: "
        "raise the drive voltage or lower the phase current"
    )


@dataclass(frozen=True, slots=True)
class Motor:
    """One library motor: its name, frame and kind ("stepper" or "servo"), and its values
    in SI with provenance (step angle in degrees, current in A, resistance in ohm,
    voltage in V, speeds in rpm)."""

    id: str
    name: str
    frame: str
    values: Mapping[str, Sourced]
    kind: str = "stepper"

    def value(self, name: str) -> float:
        number: float = self.values[name].value
        return number

    def corner_rpm(self) -> float:
        """The stepper model's corner speed at the library's drive voltage [rpm]."""
        return stepper.corner_speed_rpm(
            self.value("supply_v"),
            self.value("phase_current_a"),
            self.value("resistance_ohm"),
            self.value("inductance_mh"),
            self.value("step_angle_deg"),
        )

    def published_curve(self) -> tuple[tuple[float, float], ...] | None:
        """A stepper's pull-out curve as its maker publishes it, (rpm, N m) from the
        plotted points, with the first point's torque held down to standstill (the
        charts start at a speed; a stepper's pull-out does not rise towards standstill
        in them); None where the library draws the curve from the model."""
        curve = self.values.get(CURVE)
        if curve is None:
            return None
        points: tuple[tuple[float, float], ...] = curve.value
        return ((0.0, points[0][1]), *points) if points[0][0] > 0.0 else points

    def curve(self, current_is_rms: bool = False) -> tuple[tuple[float, float], ...]:
        """The torque the motor gives against speed: a stepper's pull-out curve from the
        stepper model (its drive's current set as RMS where ``current_is_rms``, else as
        the sine's peak), a servo's peak envelope from the servo model."""
        published = self.published_curve()
        if published is not None:
            return published
        if self.kind == "servo":
            return servo.peak_curve(
                self.value("peak_torque_nm"),
                self.value("rated_rpm"),
                self.value("max_rpm"),
                self.value("top_speed_torque_nm"),
            )
        args = (
            self.value("supply_v"),
            self.value("phase_current_a"),
            self.value("resistance_ohm"),
            self.value("inductance_mh"),
            self.value("step_angle_deg"),
            self.value("holding_torque_nm"),
        )
        return model_curve(args, current_is_rms)

    def detent_torque_nm(self) -> float | None:
        """A stepper's published detent torque (unpowered); None where not published."""
        detent = self.values.get("detent_torque_nm")
        return None if detent is None else float(detent.value)

    def continuous_torque_nm(self) -> float | None:
        """A servo's rated (S1) torque, the limit of the cycle's RMS torque; None for a
        stepper (its holding torque is already the curve's ceiling)."""
        return self.value("rated_torque_nm") if self.kind == "servo" else None

    def step_angle_deg(self) -> float | None:
        return self.value("step_angle_deg") if self.kind == "stepper" else None

    def holding_torque_nm(self) -> float | None:
        """A stepper's energised holding torque (at its rated current); None for a servo,
        whose torque at standstill its datasheet does not give as a holding figure."""
        return self.value("holding_torque_nm") if self.kind == "stepper" else None


def _check_servo(entry: Entry, motor: Motor) -> None:
    """The ratings in the order a servo's datasheet implies them."""
    if motor.value("peak_torque_nm") < motor.value("rated_torque_nm"):
        raise entry.fail("peak_torque_nm", "below the rated torque")
    if motor.value("top_speed_torque_nm") > motor.value("peak_torque_nm"):
        raise entry.fail("top_speed_torque_nm", "above the peak torque")
    if motor.value("rated_rpm") >= motor.value("max_rpm"):
        raise entry.fail("rated_rpm", "must be below max_rpm")


def motor_key(text: str) -> str:
    """A motor id as typed, as the library holds it: without the spaces around it, in
    lowercase (a datasheet writes 17HS19-2004S1, the library 17hs19-2004s1).

    >>> motor_key(" 17HS19-2004S1 ")
    '17hs19-2004s1'
    """
    return text.strip().lower()


def _motor(file: str, motor_id: str, data: Any) -> Motor:
    if not isinstance(data, dict):
        raise CatalogError(file, f"motors.{motor_id}", "-", "must be a table")
    if motor_key(motor_id) != motor_id:
        reason = f"a motor id is lowercase ('{motor_key(motor_id)}'): inputs read any case"
        raise CatalogError(file, f"motors.{motor_id}", "-", reason)
    entry = Entry(file, f"motors.{motor_id}", data)
    kind = data.get("kind", "stepper")
    if kind not in FIELDS:
        raise entry.fail("kind", f"must be one of {', '.join(FIELDS)}")
    entry.check_known(frozenset(FIELDS[kind]) | frozenset(OPTIONAL[kind]) | PLAIN)
    for name in PLAIN - {"kind"}:
        if not isinstance(data.get(name), str) or not data[name].strip():
            raise entry.fail(name, "missing or not text")
    values = {}
    given = {n: u for n, u in OPTIONAL[kind].items() if n in data and n != CURVE}
    if CURVE in data:
        values[CURVE] = Sourced(_curve(entry), SI_UNITS[CURVE], entry.prov(CURVE))
    for name, unit in {**FIELDS[kind], **given}.items():
        number = entry.number(name, allow_zero=name in MAY_BE_ZERO)
        value = to_si(number, unit) if unit else number
        values[name] = Sourced(value, SI_UNITS[name], entry.prov(name))
    motor = Motor(motor_id, data["name"], data["frame"], values, kind)
    if kind == "servo":
        _check_servo(entry, motor)
    elif motor.corner_rpm() <= 0.0:
        raise entry.fail("supply_v", "at most the winding's I R: it cannot drive the current")
    return motor


def _curve(entry: Entry) -> tuple[tuple[float, float], ...]:
    """A published pull-out curve: at least two (rpm, N m) points, speeds rising, every
    torque above zero (a curve may rise at low speed, out of a resonance dip)."""
    rows = entry.rows(CURVE, 2)
    speeds, torques = [r[0] for r in rows], [r[1] for r in rows]
    if len(rows) < 2 or any(b <= a for a, b in pairwise(speeds)):
        raise entry.fail(CURVE, "needs two or more points, speeds rising")
    if min(torques) <= 0.0:
        raise entry.fail(CURVE, "every torque above zero")
    return tuple((r[0], r[1]) for r in rows)


def load_motors(path: Path, digest: Any = None) -> dict[str, Motor]:
    """Every motor of one library file, validated (its bytes feed ``digest``)."""
    name, motors = library_entries(path, digest, "motors", SCHEMA)
    return {mid: _motor(name, mid, data) for mid, data in motors.items()}


def load_library(directories: Iterable[Path], digest: Any = None) -> dict[str, Motor]:
    """The motors of every directory's library file, ids unique across directories."""
    return merge_libraries(directories, MOTOR_FILE, lambda p: load_motors(p, digest), "motor")


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


#: How many steppers' model curves are kept (``model_curve``): the library's, each on
#: its own drive and the RMS reading, and those of recent drives typed in.
MODEL_CURVES_KEPT = 256


@lru_cache(maxsize=MODEL_CURVES_KEPT)
def model_curve(
    args: tuple[float, float, float, float, float, float], current_is_rms: bool
) -> tuple[tuple[float, float], ...]:
    """``stepper.microstep_pull_out_curve`` up to ``MAX_STEPPER_RPM`` for the datasheet
    values ``args`` (supply [V], current [A], resistance [ohm], inductance [H], step angle
    [deg], holding torque [N m]), kept for the last ``MODEL_CURVES_KEPT`` of them: every
    request with a library stepper reads its curve, and a pairs request every library
    stepper's (some 0.3 ms each to draw)."""
    return stepper.microstep_pull_out_curve(args, MAX_STEPPER_RPM, current_is_rms=current_is_rms)


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
    "published" where it is the library motor's published curve (``Motor.published_curve``),
    "model" where it is drawn from datasheet values (the stepper or servo model), None
    without a curve."""
    if not app.motor_curve:
        return None
    if entered.motor_curve:
        return "entered"
    motor = motors.get(app.motor or "")
    published = None if motor is None else motor.published_curve()
    return "published" if published == app.motor_curve else "model"


def with_motor(app: Application, motors: Mapping[str, Motor]) -> Application:
    """``app`` with its motor's curve, inertia, continuous torque and step angle filled
    in: a given curve first, then one drawn from the datasheet values, then the library
    motor's (raise UnknownMotor for an id ``motors`` lacks). A curve given is the one the
    checks read, so it carries no drive voltage: no range of the model's applies to it,
    whatever datasheet values come with it."""
    if app.motor_curve:
        app = replace(app, motor_supply_v=None)
    curve = app.motor_curve or _datasheet_curve(app)
    if app.motor is None or app.motor == ANY_MOTOR:
        held = energised_holding(app, app.motor_holding_torque_nm)
        return replace(held, motor_curve=curve)
    motor = motors.get(app.motor)
    if motor is None:
        raise UnknownMotor(unknown_motor_message(app.motor, motors))
    return with_library_motor(replace(app, motor_curve=curve), motor)


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
    model at those values, its maker's published curve too (raise UndrivableMotor where
    that voltage never reaches that current)."""
    inertia = app.motor_inertia_kg_m2
    rms = app.motor_rms_torque_nm
    detent = app.detent_torque_nm
    if not app.motor_curve and motor.kind == "stepper":
        retyped = drive_retyped(app, motor)
        app = with_model_values(app, motor, modelled=retyped or motor.published_curve() is None)
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


def with_model_values(app: Application, motor: Motor, modelled: bool = True) -> Application:
    """``app`` with library stepper ``motor``'s drive voltage, phase current, winding and
    holding torque wherever the user typed none (``DRIVE_VALUES``; the holding torque
    at the phase current, ``holding_at``), those its curve is drawn from: what the
    motor-curve check reads the model's confirmed range from
    (``stepper.confirmed_range_rpm``); and its winding resistance, for the copper loss of
    a cycle (``cycle_energy.cycle_energy``). A stepper whose curve is the maker's (not
    ``modelled``) carries no drive voltage: no model range applies to it."""
    current = app.motor_phase_current_a or motor.value("phase_current_a")
    return replace(
        app,
        motor_supply_v=(app.motor_supply_v or motor.value("supply_v")) if modelled else None,
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


def _retyped_curve(app: Application, motor: Motor) -> tuple[tuple[float, float], ...]:
    """The model's pull-out curve of library stepper ``motor`` at the values typed in
    (``with_model_values``'s); raise UndrivableMotor where that drive voltage never
    reaches that phase current."""
    message = _undrivable(app)
    if message is not None:
        raise UndrivableMotor(message)
    step = app.step_angle_deg or motor.step_angle_deg()
    return _datasheet_curve(replace(app, step_angle_deg=step))


def without_motor(app: Application) -> Application:
    """``app`` with no motor: no library id, curve, rotor inertia, continuous torque,
    datasheet values or step angle (the controller's microsteps and rate stay)."""
    return replace(
        app,
        motor=None,
        motor_curve=(),
        motor_inertia_kg_m2=None,
        motor_rms_torque_nm=None,
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
            driven[mid] = with_library_motor(replace(alone, motor_supply_v=drive), motor)
        except UndrivableMotor:
            continue
    return alone, driven


def unknown_motor_message(value: str, motors: Mapping[str, Motor]) -> str:
    ids = ", ".join(motors)
    return f"unknown motor '{value[:100]}'; the library has {ids} (or '{ANY_MOTOR}')"


def check_motor(value: str | None, motors: Mapping[str, Motor] | None) -> str | None:
    """A motor id of the library (or none) in any case, as the library holds it
    (``motor_key``): the 422 names the ids on offer. Without a library to hand (``motors``
    None) the id is checked where the catalog is."""
    value = None if value is None else motor_key(value)
    if value is not None and value != ANY_MOTOR and motors is not None and value not in motors:
        raise ValueError(unknown_motor_message(value, motors))
    return value

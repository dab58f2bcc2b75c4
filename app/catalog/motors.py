"""The motor library (``motors.toml`` in any catalog directory): steppers with their
datasheet's electrical values and servos with their torque ratings, each value with its
provenance, validated with the catalog (file, entry and field named on error) and held
on the ``Catalog`` the app passes around; a motor's curve (``Motor.curve``: the maker's
published one, or the stepper or servo model's), and the ids the inputs may name.
``app.catalog.axis_motor`` puts a motor on the axis.
"""

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from functools import lru_cache
from itertools import pairwise
from pathlib import Path
from typing import Any

import numpy as np

from app.catalog.entry import Entry
from app.catalog.errors import CatalogError
from app.catalog.files import library_entries, merge_libraries
from app.catalog.models import Sourced
from app.core.formulas import servo, stepper
from app.core.units import to_si

#: The library's file name; family loading skips it in every catalog directory.
MOTOR_FILE = "motors.toml"
#: A torque-speed curve: (speed [rpm], torque [N m]) points, speeds rising.
Curve = tuple[tuple[float, float], ...]
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
#: Values an entry may leave out where its datasheet does not publish them; the motor's
#: mass (``mass_kg``, what it adds to the moving mass of the axis that carries it) is
#: optional for a user's library, and the built-in library gives it for every motor.
OPTIONAL = {
    "stepper": {
        "detent_torque_nm": "N m",
        "pull_out_curve": "",
        "curve_current_a": "",
        "max_rpm": "",
        "mass_kg": "",
    },
    "servo": {"top_speed_continuous_nm": "N m", "mass_kg": ""},
}
#: The values each kind's model draws its curve from, in the order its model takes them
#: (``stepper.microstep_pull_out_curve`` through ``model_curve``; ``servo.peak_curve``).
MODEL_VALUES = {
    "stepper": (
        "supply_v",
        "phase_current_a",
        "resistance_ohm",
        "inductance_mh",
        "step_angle_deg",
        "holding_torque_nm",
    ),
    "servo": ("peak_torque_nm", "rated_rpm", "max_rpm", "top_speed_torque_nm"),
}
#: A published pull-out curve: rows of (speed [rpm], torque [N m]) read at the maker's
#: plotted points, at the drive and supply its source names.
CURVE = "pull_out_curve"
#: Each field's unit as held (SI, or the datasheet's own for angles, currents, voltages
#: and speeds); the edges show each value in the unit its name carries (``NAMED_UNITS``).
SI_UNITS = {
    "step_angle_deg": "deg",
    "holding_torque_nm": "N m",
    "phase_current_a": "A",
    #: the phase current a published pull-out curve was drawn at, as its sine's peak
    "curve_current_a": "A",
    "resistance_ohm": "ohm",
    "inductance_mh": "H",
    "rotor_inertia_g_cm2": "kg m²",
    "supply_v": "V",
    "rated_torque_nm": "N m",
    "peak_torque_nm": "N m",
    "rated_rpm": "rpm",
    "max_rpm": "rpm",
    "top_speed_torque_nm": "N m",
    "top_speed_continuous_nm": "N m",
    "detent_torque_nm": "N m",
    "mass_kg": "kg",
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
    #: the high end of each value given with a range, by name (SI)
    tops: Mapping[str, float] = field(default_factory=dict)

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
            share = self.curve_share(current_is_rms)
            return tuple((rpm, torque * share) for rpm, torque in published)
        values = tuple(self.value(name) for name in MODEL_VALUES[self.kind])
        if self.kind == "servo":
            return servo.peak_curve(*values)
        return self.within_top_speed(model_curve(values, current_is_rms))

    def curve_share(self, current_is_rms: bool) -> float:
        """The share of a published curve's torque the drive gives at the library's phase
        current (set as RMS where ``current_is_rms``, else as the sine's peak) where the
        chart was drawn at another current (``curve_current_a``, its peak): the drive's
        peak over the chart's, at most 1 (torque follows the current below saturation,
        and a lower current costs as much or less of it at speed, where the winding's
        back EMF limits it); 1 where the library does not say the chart's current."""
        chart = self.values.get("curve_current_a")
        if chart is None:
            return 1.0
        peak = self.value("phase_current_a") * (math.sqrt(2.0) if current_is_rms else 1.0)
        return min(1.0, peak / float(chart.value))

    def within_top_speed(self, curve: Curve) -> Curve:
        """A stepper model's ``curve`` up to the top speed its maker publishes (its
        maximum slewing rate, ``max_rpm``): the model draws every stepper to
        ``MAX_STEPPER_RPM``, past what some makers allow. The curve as it is without one."""
        if "max_rpm" not in self.values:
            return curve
        return up_to(curve, self.value("max_rpm"))

    def detent_torque_nm(self) -> float | None:
        """A stepper's published detent torque (unpowered); None where not published."""
        detent = self.values.get("detent_torque_nm")
        return None if detent is None else float(detent.value)

    def mass(self) -> Sourced | None:
        """The motor's published mass [kg] with its provenance; None where the library
        gives none."""
        return self.values.get("mass_kg")

    def heaviest_kg(self) -> float | None:
        """The motor's mass at the top of its range where the library gives one, else its
        mass [kg]: what an axis carrying it counts (the heavier the safer side there);
        None where the library gives none."""
        mass = self.mass()
        return None if mass is None else self.tops.get("mass_kg", float(mass.value))

    def continuous_torque_nm(self) -> float | None:
        """A servo's rated (S1) torque, the limit of the cycle's RMS torque; None for a
        stepper (its holding torque is already the curve's ceiling)."""
        return self.value("rated_torque_nm") if self.kind == "servo" else None

    def continuous_curve(self) -> Curve:
        """A servo's continuous duty zone as (rpm, N m) points: its rated torque up to its
        rated speed, then straight to the continuous torque it allows at its top speed
        (``top_speed_continuous_nm``); empty where the library gives none (the rated
        torque holds at every speed) and for a stepper."""
        if self.kind != "servo" or "top_speed_continuous_nm" not in self.values:
            return ()
        return servo.peak_curve(
            self.value("rated_torque_nm"),
            self.value("rated_rpm"),
            self.value("max_rpm"),
            self.value("top_speed_continuous_nm"),
        )

    def step_angle_deg(self) -> float | None:
        return self.value("step_angle_deg") if self.kind == "stepper" else None

    def holding_torque_nm(self) -> float | None:
        """A stepper's energised holding torque (at its rated current); None for a servo,
        whose torque at standstill its datasheet does not give as a holding figure."""
        return self.value("holding_torque_nm") if self.kind == "stepper" else None


def up_to(curve: Curve, top_rpm: float) -> Curve:
    """``curve``'s points below ``top_rpm`` and its torque there, linear between points
    (the curve as it is where it ends below).

    >>> up_to(((0.0, 1.0), (1000.0, 0.6), (3000.0, 0.2)), 1500.0)
    ((0.0, 1.0), (1000.0, 0.6), (1500.0, 0.5))
    """
    if curve[-1][0] <= top_rpm:
        return curve
    speeds, torques = zip(*curve, strict=True)
    below = tuple(p for p in curve if p[0] < top_rpm)
    return (*below, (top_rpm, float(np.interp(top_rpm, speeds, torques))))


def _check_servo(entry: Entry, motor: Motor) -> None:
    """The ratings in the order a servo's datasheet implies them."""
    if motor.value("peak_torque_nm") < motor.value("rated_torque_nm"):
        raise entry.fail("peak_torque_nm", "below the rated torque")
    if motor.value("top_speed_torque_nm") > motor.value("peak_torque_nm"):
        raise entry.fail("top_speed_torque_nm", "above the peak torque")
    if motor.value("rated_rpm") >= motor.value("max_rpm"):
        raise entry.fail("rated_rpm", "must be below max_rpm")
    if "top_speed_continuous_nm" in motor.values:
        top = motor.value("top_speed_continuous_nm")
        if top > motor.value("rated_torque_nm"):
            raise entry.fail("top_speed_continuous_nm", "above the rated torque")
        if top > motor.value("top_speed_torque_nm"):
            raise entry.fail("top_speed_continuous_nm", "above top_speed_torque_nm")


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
    values, tops = {}, {}
    given = {n: u for n, u in OPTIONAL[kind].items() if n in data and n != CURVE}
    if CURVE in data:
        values[CURVE] = Sourced(_curve(entry), SI_UNITS[CURVE], entry.prov(CURVE))
    for name, unit in {**FIELDS[kind], **given}.items():
        number = entry.number(name, allow_zero=name in MAY_BE_ZERO)
        value = to_si(number, unit) if unit else number
        values[name] = Sourced(value, SI_UNITS[name], entry.prov(name))
        ends = entry.ends(name)
        if ends is not None:
            tops[name] = to_si(ends[1], unit) if unit else ends[1]
    motor = Motor(motor_id, data["name"], data["frame"], values, kind, tops)
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

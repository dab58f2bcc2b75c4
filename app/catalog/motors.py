"""The motor library (``catalog/motors.toml``): common steppers with their datasheet
values, each with its provenance, validated at load with the file, entry and field named.

A library motor becomes the application's motor at the edge (``with_motor``, called by
``app.contract.inputs``): its pull-out curve drawn by the stepper model at the drive voltage of
the maker's curve, its rotor inertia and its step angle, unless the user gives those
inputs directly; a stepper's datasheet values typed in are drawn the same way.
"""

import hashlib
from collections.abc import Mapping
from dataclasses import dataclass, replace
from functools import cache
from pathlib import Path
from typing import Any

from app.catalog.entry import Entry
from app.catalog.errors import CatalogError
from app.catalog.files import read_file
from app.catalog.models import Sourced
from app.contract.units import to_si
from app.core.formulas import stepper
from app.core.model import Application
from app.server.paths import resource_dir

#: The library's file name; family loading skips it in every catalog directory.
MOTOR_FILE = "motors.toml"
SCHEMA = 1
#: Field -> the unit its value is written in.
FIELDS = {
    "step_angle_deg": "",
    "holding_torque_nm": "N m",
    "phase_current_a": "",
    "resistance_ohm": "",
    "inductance_mh": "mH",
    "rotor_inertia_g_cm2": "g cm²",
    "supply_v": "",
}
PLAIN = frozenset({"name", "frame"})
#: The stepper model's curve is drawn up to this speed [rpm]: hybrid steppers on
#: leadscrews rarely run faster, and past it the model's 1 / n fall is unchecked.
MAX_STEPPER_RPM = 3000.0


@dataclass(frozen=True, slots=True)
class Motor:
    """One library motor: its name and frame, and its values in SI with provenance
    (step angle in degrees, current in A, resistance in ohm, voltage in V)."""

    id: str
    name: str
    frame: str
    values: Mapping[str, Sourced]

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

    def curve(self) -> tuple[tuple[float, float], ...]:
        """The pull-out curve the stepper model draws from the datasheet values."""
        holding = self.value("holding_torque_nm")
        return stepper.pull_out_curve(holding, self.corner_rpm(), MAX_STEPPER_RPM)


def _motor(file: str, motor_id: str, data: Any) -> Motor:
    if not isinstance(data, dict):
        raise CatalogError(file, f"motors.{motor_id}", "-", "must be a table")
    entry = Entry(file, f"motors.{motor_id}", data)
    entry.check_known(frozenset(FIELDS) | PLAIN)
    for name in PLAIN:
        if not isinstance(data.get(name), str) or not data[name].strip():
            raise entry.fail(name, "missing or not text")
    values = {}
    for name, unit in FIELDS.items():
        value = to_si(entry.number(name), unit) if unit else entry.number(name)
        values[name] = Sourced(value, unit, entry.prov(name))
    motor = Motor(motor_id, data["name"], data["frame"], values)
    if motor.corner_rpm() <= 0.0:
        raise entry.fail("supply_v", "at most the winding's I R: it cannot drive the current")
    return motor


def load_motors(path: Path) -> dict[str, Motor]:
    """Every motor of one library file, validated."""
    source = read_file(path, hashlib.sha256())
    if source.data.get("schema") != SCHEMA:
        raise CatalogError(source.name, "-", "schema", f"must be {SCHEMA}")
    unknown = set(source.data) - {"schema", "motors"}
    if unknown:
        raise CatalogError(source.name, "-", sorted(unknown)[0], "unknown key")
    motors = source.data.get("motors")
    if not isinstance(motors, dict) or not motors:
        raise CatalogError(source.name, "-", "motors", "no [motors.ID] entries")
    return {mid: _motor(source.name, mid, data) for mid, data in motors.items()}


@cache
def library() -> dict[str, Motor]:
    """The built-in motor library, read once."""
    return load_motors(resource_dir("catalog") / MOTOR_FILE)


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
    corner = stepper.corner_speed_rpm(*(float(v or 0.0) for v in values))
    return stepper.pull_out_curve(app.motor_holding_torque_nm, corner, MAX_STEPPER_RPM)


def with_motor(app: Application) -> Application:
    """``app`` with its motor's curve, inertia and step angle filled in: a given curve
    first, then one drawn from the datasheet values, then the library motor's."""
    motor = library().get(app.motor or "")
    curve = app.motor_curve or _datasheet_curve(app)
    if motor is None:
        return replace(app, motor_curve=curve)
    return replace(
        app,
        motor_curve=curve or motor.curve(),
        motor_inertia_kg_m2=(
            app.motor_inertia_kg_m2
            if app.motor_inertia_kg_m2 is not None
            else motor.value("rotor_inertia_g_cm2")
        ),
        step_angle_deg=app.step_angle_deg or motor.value("step_angle_deg"),
    )


def check_motor(value: str | None) -> str | None:
    """A motor id of the library (or none): the API's 422 names the ids on offer."""
    if value is not None and value not in library():
        raise ValueError(f"unknown motor '{value}'; the library has {', '.join(library())}")
    return value

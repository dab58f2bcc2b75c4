"""A machine of stacked axes sized (``app.core.machine``), as the API's answer."""

import math
from typing import Any

from app.catalog import Catalog
from app.catalog.axis_motor import library_motor_mass
from app.catalog.motors import UndrivableMotor, UnknownMotor
from app.catalog.supports import UnknownSupport
from app.contract.cycle import move_in
from app.contract.fields import LOAD, LOAD_DIRECTION, MOVING_MASS
from app.contract.machine import MachineIn
from app.contract.reported import REPORTED
from app.contract.share_link import share_query
from app.contract.source import Writer
from app.contract.units import DEFAULT_UNITS
from app.core import motion
from app.core.machine import Axis, AxisResult, size_machine
from app.report.present import candidate_json
from app.report.service import INPUT_RANGES, INPUT_WORDS

#: The energy per cycle's numbers of the output table (their keys are the record's).
ENERGY_KEYS = tuple(r.key for r in REPORTED if r.quantity == "energy")


def energy_of(r: AxisResult) -> dict[str, float | None] | None:
    """The chosen screw's energy per cycle [J] by the output table's keys; None without
    a chosen screw."""
    if r.chosen is None:
        return None
    values = {key: float(getattr(r.chosen.quantities.energy, key)) for key in ENERGY_KEYS}
    return {key: v if math.isfinite(v) else None for key, v in values.items()}


def motor_mass_json(r: AxisResult) -> dict[str, Any]:
    """The axis's motor mass in its total, where it comes from, and for a library motor's
    published mass that motor and the value's provenance."""
    library = r.axis.library_motor if r.motor_origin == "library" else None
    return {
        "motor_kg": r.motor_kg,
        "motor_mass_origin": r.motor_origin,
        "motor_mass_motor": None if library is None else library.motor,
        "motor_mass_provenance": None
        if library is None
        else {"kind": library.provenance.kind, "source": library.provenance.source},
    }


class UnknownChoice(LookupError):
    """An axis's chosen screw that the catalog does not hold: (axis index, id)."""


class AxisInputError(ValueError):
    """An axis's input the libraries refuse (an unknown motor or support unit, a drive
    that cannot reach its current): (the input's path in the body, the message)."""


def machine_axes(body: MachineIn, catalog: Catalog) -> list[Axis]:
    """The core's axes from the API's, each application in SI with its library motor;
    ``AxisInputError`` naming the axis whose input a library refuses."""
    axes = []
    for i, a in enumerate(body.axes):
        try:
            app, _, provenance = a.inputs.to_core_traced(catalog.motors, catalog.supports)
        except (UnknownMotor, UnknownSupport, UndrivableMotor) as exc:
            field = getattr(exc, "field", "motor")
            raise AxisInputError(f"axes.{i}.inputs.{field}", str(exc)) from exc
        library = library_motor_mass(app, catalog.motors)
        axes.append(Axis(a.name, app, a.frame_kg, a.motor_kg, a.choice, provenance, library))
    return axes


def _sized(given: Any, r: AxisResult, sized: Any) -> Any:
    """The axis's inputs (or one move's) as it was sized: the mass of the axes above
    added to its moving mass and, where it is sized with it, the load of ``sized`` (the
    core's application or move it became: ``app.core.machine.with_standing_load``), in
    N as the API's. A move's mass left out stays so: it is the axis's, which carries it."""
    update: dict[str, Any] = {}
    mass = getattr(given, MOVING_MASS.api)
    if mass is not None:
        update[MOVING_MASS.api] = mass + r.carried_kg
    if r.standing_load_n > 0.0:
        update[LOAD.api] = getattr(sized, LOAD.core)
        update[LOAD_DIRECTION.api] = getattr(sized, LOAD_DIRECTION.core)
    return given.model_copy(update=update)


def _sized_moves(given: Any, r: AxisResult) -> list[Any]:
    """The axis's moves as it was sized: its own, or the out and back over its stroke
    that sizing it with a standing load made of it (its own load opposing the motion)."""
    moves = given.moves or [move_in(m) for m in r.app.moves]
    return [_sized(m, r, c) for m, c in zip(moves, r.app.moves, strict=True)]


def _axis_out(body: MachineIn, i: int, r: AxisResult) -> dict[str, Any]:
    given = body.axes[i].inputs
    inputs = _sized(given, r, r.app).model_copy(update={"moves": _sized_moves(given, r)})
    return {
        "name": r.axis.name,
        "carried_kg": r.carried_kg,
        "uncounted": list(r.uncounted),
        "parallel": list(r.parallel),
        "parallel_thrust_n": r.parallel_thrust_n,
        "standing_load_n": r.standing_load_n,
        "sized_mass_kg": motion.heaviest_mass(r.app),
        "screw_kg": None if r.chosen is None else r.screw_kg,
        **motor_mass_json(r),
        "total_kg": r.total_kg,
        "evaluated": r.selection.evaluated,
        "passed": r.selection.passed,
        "chosen": None if r.chosen is None else candidate_json(r.chosen, "summary"),
        "energy_j": energy_of(r),
        "verdict": None if r.chosen is None else Writer(DEFAULT_UNITS).text(r.chosen.verdict.text),
        "candidates": [candidate_json(c, "summary") for c in r.selection.candidates],
        "share_url": "/?" + share_query(inputs),
    }


def run_machine(body: MachineIn, catalog: Catalog) -> dict[str, Any]:
    """Size the machine's axes, top first (``MachineOut``'s fields as JSON values);
    ``UnknownChoice`` for a chosen id the catalog lacks."""
    axes = machine_axes(body, catalog)
    for i, a in enumerate(axes):
        if a.choice is not None and a.choice not in catalog.index.positions:
            raise UnknownChoice(i, a.choice)
    machine = size_machine(axes, catalog.index, INPUT_RANGES, INPUT_WORDS)
    return {
        "axes": [_axis_out(body, i, r) for i, r in enumerate(machine.axes)],
        "governing": machine.governing,
        "moved_kg": machine.moved_kg,
        "catalog_version": catalog.version,
    }

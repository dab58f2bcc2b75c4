"""The motor library and the screw + motor pairs as the API and the page show them."""

from typing import Any

from app.catalog import Catalog
from app.catalog.axis_motor import curve_origin, pair_applications
from app.catalog.models import Sourced
from app.catalog.motors import (
    ANY_MOTOR,
    NAMED_UNITS,
    Motor,
    UnknownMotor,
    unknown_motor_message,
)
from app.catalog.supports import with_support
from app.contract.inputs import ApplicationIn
from app.contract.pairs import (
    PAIR_RANKS,
    MotorOut,
    MotorsOut,
    PairRankIn,
    PairsOut,
    pair_rank_of,
)
from app.contract.params import api_url
from app.contract.share_link import share_query
from app.contract.units import UNITS, from_si
from app.core.model import Application
from app.core.pairs import Pair, rank_pairs


def named_value(name: str, held: Sourced) -> dict[str, Any]:
    """A library value as the API shows it: in the unit its name carries (``inductance_mh``
    in mH, ``rotor_inertia_g_cm2`` in g cm², as the datasheet and the file give it), with
    its provenance."""
    unit = NAMED_UNITS.get(name)
    value = held.value if unit is None else from_si(held.value, unit)
    return {
        "value": value,
        "unit": held.unit if unit is None else UNITS[unit].text,
        "provenance": {"kind": held.provenance.kind, "source": held.provenance.source},
    }


def motor_out(motor: Motor) -> MotorOut:
    values = {name: named_value(name, v) for name, v in motor.values.items()}
    return MotorOut.model_validate(
        {
            "id": motor.id,
            "name": motor.name,
            "frame": motor.frame,
            "kind": motor.kind,
            "values": values,
            "curve": list(motor.curve()),
            "continuous_torque_nm": motor.continuous_torque_nm(),
        }
    )


def motors_out(catalog: Catalog) -> MotorsOut:
    return MotorsOut(
        catalog_version=catalog.version,
        motors=[motor_out(m) for m in catalog.motors.values()],
    )


def _ranked(rank: PairRankIn, pair: Pair) -> tuple[float, str]:
    if rank == "motor_size":
        return pair.motor_size_nm, "N m"
    if rank == "torque":
        return pair.torque_nm, "N m"
    return pair.motor_use, ""


def _pair_out(
    pair: Pair, rank: PairRankIn, catalog: Catalog, alone: Application, driven: Application
) -> dict[str, Any]:
    """One pair as ``PairOut``: ``driven`` is the axis ``alone`` with the pair's motor."""
    motor = catalog.motors[pair.motor]
    value, unit = _ranked(rank, pair)
    return {
        "screw_id": pair.screw.id,
        "series": pair.screw.series_name,
        "motor": motor.id,
        "motor_name": motor.name,
        "motor_kind": motor.kind,
        "frame": motor.frame,
        "motor_curve_origin": curve_origin(alone, driven, catalog.motors),
        "motor_use": pair.motor_use,
        "motor_limit": pair.motor_limit,
        "torque_nm": pair.torque_nm,
        "peak_rpm": pair.peak_rpm,
        "motor_size_nm": pair.motor_size_nm,
        "ranked_value": value,
        "ranked_unit": unit,
    }


def run_pairs(inputs: ApplicationIn, catalog: Catalog, asked: PairRankIn | None = None) -> PairsOut:
    """Every eligible catalog screw with every library motor for the axis of ``inputs``
    (any motor given there is set aside; a library support unit's ratings filled in, as
    select and evaluate fill them), the passing pairs ranked as ``asked``, else as the
    application's own ranking means (``pair_rank_of``: the page's ranking)."""
    rank = pair_rank_of(inputs, asked)
    axis = with_support(inputs.axis(), catalog.supports)
    if axis.motor not in (None, ANY_MOTOR, *catalog.motors):  # set aside, but named right
        raise UnknownMotor(unknown_motor_message(axis.motor or "", catalog.motors))
    alone, motors = pair_applications(axis, catalog.motors)
    found = rank_pairs(alone, motors, catalog.index, rank)
    return PairsOut.model_validate(
        {
            "inputs": inputs,
            "rank": rank,
            "ranked_by": PAIR_RANKS[rank],
            "catalog_version": catalog.version,
            "screws_eligible": found.screws_eligible,
            "screws_passing_alone": found.screws_passing_alone,
            "motors": found.motors,
            "pairs_passed": found.pairs_passed,
            "pairs": [_pair_out(p, rank, catalog, alone, motors[p.motor]) for p in found.pairs],
            **pairs_urls(inputs, asked),
        }
    )


def pairs_urls(inputs: ApplicationIn, asked: PairRankIn | None) -> dict[str, str]:
    """The page of the same axis with the motor "any" (it shows the pairs) and the API's
    GET of the same pairs (its ``pair_rank`` where one was asked for)."""
    extra = [] if asked is None else [("pair_rank", asked)]
    return {
        "share_url": "/?" + share_query(inputs.model_copy(update={"motor": ANY_MOTOR})),
        "api_url": api_url("pairs", inputs, extra),
    }

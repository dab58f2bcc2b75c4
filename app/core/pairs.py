"""Screw + motor pairs: every catalog screw with every motor of a library, ranked.

The screws are screened once without a motor. A motor only adds demands (its rotor's
inertia torque, its curve, RMS, speed and controller limits), so a screw that fails
without one fails with every motor: only the screws that pass go on. For each motor
those are screened again together, as arrays, with the motor's curve, inertia and
ratings in the application; the passing rows are the pairs, each with the share of the
motor it uses (``motor_use``: the largest of the torque, curve, RMS and speed
utilisations).
"""

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np

from app.core.index import CatalogIndex
from app.core.model import Application, ScrewSpec
from app.core.screening import Screening, screen_table
from app.core.selection import motor_use, screen

#: How pairs rank: the smallest share of the motor used; the smallest motor (its torque
#: at standstill, a cost proxy), then the share used; the lowest drive torque.
PairRank = Literal["motor_margin", "motor_size", "torque"]


@dataclass(frozen=True, slots=True)
class Pair:
    """One passing screw + motor pair: the share of the motor it uses (0-1), the peak
    drive torque [N m] with the motor's rotor, the screw's top speed [rpm] and the
    motor's standstill torque [N m] (its size)."""

    screw: ScrewSpec
    motor: str
    motor_use: float
    torque_nm: float
    peak_rpm: float
    motor_size_nm: float


@dataclass(frozen=True, slots=True)
class Pairs:
    """The ranked pairs (cut to ``limit``) and the counts behind them."""

    pairs: Sequence[Pair]
    screws_eligible: int
    screws_passing_alone: int
    motors: int
    pairs_passed: int


def _motor_pairs(motor: str, app: Application, alone: Screening, index: CatalogIndex) -> list[Pair]:
    """The pairs of ``motor`` (driving ``app``) with the screws that pass alone."""
    rows = np.flatnonzero(alone.passed)
    table = alone.table.take(rows)
    s = screen_table(app, table, alone.index[rows], index.table.reach)
    use, torque, rpm = motor_use(s), s.total_torque_nm, s.quantities.peak_rpm
    size = app.motor_curve[0][1] if app.motor_curve else float("nan")
    return [
        Pair(table.screws[i], motor, float(use[i]), float(torque[i]), float(rpm[i]), size)
        for i in np.flatnonzero(s.passed).tolist()
    ]


def _key(rank: PairRank, pair: Pair) -> tuple[float, ...]:
    if rank == "motor_size":
        return (pair.motor_size_nm, pair.motor_use, pair.torque_nm)
    if rank == "torque":
        return (pair.torque_nm, pair.motor_use)
    return (pair.motor_use, pair.torque_nm)


def rank_pairs(
    app: Application,
    motors: Mapping[str, Application],
    index: CatalogIndex,
    rank: PairRank = "motor_margin",
) -> Pairs:
    """Every eligible screw of ``index`` with every motor, ``motors`` giving each motor's
    id and ``app`` driven by it; ``app`` itself has no motor. The passing pairs ranked by
    ``rank``, the first ``app.limit`` kept."""
    alone = screen(app, index)
    found = [
        pair
        for motor, motor_app in motors.items()
        for pair in _motor_pairs(motor, motor_app, alone, index)
    ]
    found.sort(key=lambda pair: _key(rank, pair))
    return Pairs(
        pairs=found[: app.limit],
        screws_eligible=len(alone.passed),
        screws_passing_alone=int(np.count_nonzero(alone.passed)),
        motors=len(motors),
        pairs_passed=len(found),
    )

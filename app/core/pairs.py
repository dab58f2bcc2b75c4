"""Screw + motor pairs: every catalog screw with every motor of a library, ranked.

The screws are screened once without a motor. A motor adds demands (its rotor's
inertia torque, its curve, RMS, speed and controller limits), so a screw that fails
without one fails with every motor, but where only a check a motor's own values may
clear fails (``Check.motor_may_clear``: a stepper's energised holding torque or its
detent torque holds the load): the other screws go on. For each motor
those are screened again together, as arrays, with the motor's curve, inertia and
ratings in the application; the passing rows are the pairs, each with the share of the
motor it uses (``motor_use``: the largest of the torque, curve, RMS and speed
utilisations).
"""

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Literal, NamedTuple

import numpy as np
from numpy.typing import NDArray

from app.core.checks.base import Reach
from app.core.index import CatalogIndex
from app.core.model import Application, ScrewSpec
from app.core.record import MOTOR_CHECKS
from app.core.screening import failing_beyond, screen_table
from app.core.selection import motor_limit, motor_use, screen, shown_torque
from app.core.table import Array, CandidateTable

#: How pairs rank: the smallest share of the motor used; the smallest motor (its torque
#: at standstill, a cost proxy), then the share used; the lowest drive torque.
PairRank = Literal["motor_margin", "motor_size", "torque"]


@dataclass(frozen=True, slots=True)
class Pair:
    """One passing screw + motor pair: the share of the motor it uses (0-1), the peak
    drive torque [N m] with the motor's rotor (the results table's, ``shown_torque``:
    the largest of any moving segment and of starting from rest), the screw's top
    speed [rpm] and the motor's standstill torque [N m] (its size)."""

    screw: ScrewSpec
    motor: str
    motor_use: float
    torque_nm: float
    peak_rpm: float
    motor_size_nm: float
    #: the motor check ``motor_use`` is (``record.MOTOR_CHECKS``; "" when none ran)
    motor_limit: str = ""


@dataclass(frozen=True, slots=True)
class Pairs:
    """The ranked pairs (cut to ``limit``) and the counts behind them."""

    pairs: Sequence[Pair]
    screws_eligible: int
    screws_passing_alone: int
    motors: int
    pairs_passed: int


class _Found(NamedTuple):
    """The passing pairs of every motor as arrays: the row (in the screws that pass
    alone), the motor's position, its share used, the drive torque, the top speed, and
    which motor check the share is (``selection.motor_limit``)."""

    row: NDArray[np.intp]
    motor: NDArray[np.intp]
    use: Array
    torque: Array
    rpm: Array
    limit: NDArray[np.intp]


def _motor_pairs(
    motor: int, app: Application, table: CandidateTable, rows: NDArray[np.intp], reach: Reach
) -> _Found:
    """The pairs of motor number ``motor`` (driving ``app``) with the screws of ``table``
    (those that pass without a motor, rows ``rows`` of the catalog), as arrays."""
    s = screen_table(app, table, rows, reach)
    ok = np.flatnonzero(s.passed)
    return _Found(
        ok,
        np.full(len(ok), motor),
        motor_use(s)[ok],
        shown_torque(s)[ok],
        s.quantities.motor.peak_rpm[ok],
        motor_limit(s)[ok],
    )


def _order(rank: PairRank, found: _Found, size: Array) -> NDArray[np.intp]:
    """Positions of the pairs in rank order (``np.lexsort``: the last key first)."""
    keys = {
        "motor_size": (found.torque, found.use, size[found.motor]),
        "torque": (found.use, found.torque),
        "motor_margin": (found.torque, found.use),
    }[rank]
    return np.lexsort(keys)


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
    # those that pass alone, or fail only checks a motor's own values may clear
    candidates = np.flatnonzero(~failing_beyond(alone, lambda check: check.motor_may_clear))
    table, rows = alone.table.take(candidates), alone.index[candidates]
    ids = list(motors)
    size = np.array([m.motor_curve[0][1] if m.motor_curve else np.nan for m in motors.values()])
    parts = [
        _motor_pairs(k, motors[mid], table, rows, index.table.reach) for k, mid in enumerate(ids)
    ]
    empty = _Found(
        np.empty(0, np.intp), np.empty(0, np.intp), *(np.empty(0),) * 3, np.empty(0, np.intp)
    )
    found = _Found(*(np.concatenate(column) for column in zip(empty, *parts, strict=True)))
    top = _order(rank, found, size)[: app.limit]
    return Pairs(
        pairs=[
            Pair(
                table.screws[found.row[i]],
                ids[found.motor[i]],
                float(found.use[i]),
                float(found.torque[i]),
                float(found.rpm[i]),
                float(size[found.motor[i]]),
                MOTOR_CHECKS[found.limit[i]] if found.limit[i] >= 0 else "",
            )
            for i in top.tolist()
        ],
        screws_eligible=len(alone.passed),
        screws_passing_alone=int(np.count_nonzero(alone.passed)),
        motors=len(motors),
        pairs_passed=len(found.row),
    )

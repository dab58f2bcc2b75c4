"""The screening's arrays at the positions of a batch of candidates, read when first
asked for: the columns (one per quantity, verdict or table column, taken for the whole
batch at once), each candidate's check results and its move. The candidate records
(``app.core.record``) and their sections (``app.core.sections``) read their numbers here.
"""

import math
from collections.abc import Mapping, Sequence
from functools import cached_property
from typing import Any, Literal, NamedTuple

import numpy as np
from numpy.typing import NDArray

from app.core import motion, segments
from app.core.checks import BY_NAME
from app.core.checks.base import Check
from app.core.dry_run import screw_as_run
from app.core.duty import ball_life_revolutions, ball_load_factors, travel_thrusts
from app.core.input_rules import read_inputs, refused
from app.core.model import Application, AxisProvenance, ScrewSpec
from app.core.phrase import Amount, Phrase, Quantity
from app.core.quantities import PART_OF, PARTS, Quantities, quantity
from app.core.reach import size_of
from app.core.screening import Screening
from app.core.table import Array
from app.core.timeline import Direction, Motion, Segment, SegmentName

#: The screening's per-candidate verdicts a record reads as columns.
VERDICTS = frozenset({"passed", "max_utilization"})
#: Positions in a screening, as an index array (NumPy picks with one four times faster
#: than with a list).
Positions = NDArray[np.intp]


def positions_array(positions: Sequence[int]) -> Positions:
    """``positions`` as an index array."""
    return np.asarray(positions, dtype=np.intp)


class Batch:
    """The screening's arrays at the positions of some candidates: each column taken for
    all of them at once, when first read (``column``); ``axis`` is the provenance of the
    axis's values the checks' capacities are (``Check.capacity_given``)."""

    def __init__(
        self,
        app: Application,
        sc: Screening,
        positions: Sequence[int],
        axis: AxisProvenance | None = None,
    ) -> None:
        self.app, self.screening, self.axis = app, sc, axis or {}
        self.positions = [int(i) for i in positions]
        self.at = positions_array(self.positions)
        self._columns: dict[str, list[Any]] = {}

    def column(self, name: str) -> list[Any]:
        """The screening's column ``name`` at the batch's positions, as Python values: a
        quantity (``Quantities``), else a verdict (``passed``, ``max_utilization``), else a
        column of the table; taken once, when first read."""
        if name not in self._columns:
            sc = self.screening
            source = quantity(sc.quantities, name) if name in PART_OF else None
            if source is None:
                source = getattr(sc, name) if name in VERDICTS else getattr(sc.table, name)
            self._columns[name] = source[self.at].tolist()
        return self._columns[name]

    @cached_property
    def reached_speed_m_s(self) -> float:
        """The top speed the axis reaches (``motion.reached_speed``), the same for every
        candidate: worked out once per batch."""
        return motion.reached_speed(self.app)

    @cached_property
    def duty(self) -> tuple[float | None, float | None]:
        """The equivalent stroke [m] and the cycles a day (``motion.equivalent_stroke``,
        ``motion.cycles_per_day``) that turn a travel into years: once per batch."""
        return motion.equivalent_stroke(self.app), motion.cycles_per_day(self.app)

    @cached_property
    def moving_segment_names(self) -> list[tuple[SegmentName, Direction]]:
        """The moving segments' names and directions (``segments.moving_segment_names``),
        the same for every candidate: worked out once per batch."""
        return segments.moving_segment_names(self.app)

    @cached_property
    def l10_revolutions(self) -> list[float]:
        """Each candidate's ball nut L10 life over the cycle [revolutions]
        (``duty.ball_life_revolutions``: both sides of a preloaded nut; NaN without a
        rating): worked out for the whole batch at once; infinite for every nut without a
        stroke (nothing moves over one)."""
        if not travel_thrusts(self.app)[0]:
            return [math.inf] * len(self.positions)
        table = self.screening.table
        rating, preload = table.dynamic_load_n[self.at], table.preload_n[self.at]
        factor = ball_load_factors(self.app, table.nut_length_m[self.at])
        revolutions: list[float] = ball_life_revolutions(self.app, rating, preload, factor).tolist()
        return revolutions

    @cached_property
    def slots(self) -> list["Slot"]:
        """Each candidate's slot: what its sections and checks read."""
        sc, app = self.screening, self.app
        return [Slot(app, sc, i) for i in self.positions]

    @cached_property
    def results(self) -> list[tuple["CheckResult", ...]]:
        """Per candidate, every check that applies, in registry order: read from the
        screening's arrays in one pass over the checks. Demand and capacity are NaN for
        a yes/no check; the utilisation None where it is not a finite number (no demand
        or limit, or a zero limit)."""
        sc, at, slots = self.screening, self.at, self.slots
        nan = [math.nan] * len(at)
        per: list[list[CheckResult]] = [[] for _ in at]
        for name, m in sc.measures.items():
            check = BY_NAME[name]
            rows = zip(
                m.applicable[at].tolist(),
                nan if m.demand is None else m.demand[at].tolist(),
                nan if m.capacity is None else m.capacity[at].tolist(),
                _utilizations(sc.utilization[name], at),
                sc.failed[name][at].tolist(),
                slots,
                per,
                strict=True,
            )
            for applies, demand, capacity, utilization, failed, slot, out in rows:
                if applies:
                    out.append(
                        CheckResult(
                            name, check.kind, not failed, utilization, demand, capacity, check, slot
                        )
                    )
        return [tuple(checks) for checks in per]

    @cached_property
    def skipped(self) -> list[tuple[Check, ...]]:
        """Per candidate, every check that runs for this application but not for this
        candidate (a value it reads is missing), in registry order."""
        sc, at = self.screening, self.at
        per: list[list[Check]] = [[] for _ in at]
        for name, m in sc.measures.items():
            for applies, out in zip(m.applicable[at].tolist(), per, strict=True):
                if not applies:
                    out.append(BY_NAME[name])
        return [tuple(checks) for checks in per]

    @cached_property
    def motions(self) -> list[Motion | None]:
        """The move and its segments' torques per candidate (None each without a stroke)."""
        p = motion.move_profile(self.app)
        if p is None:
            return [None] * len(self.at)
        hold = np.array(self.column("brake_nm"))
        parts = segments.segments(self.app, self.screening.table.take(self.at), hold)
        columns = [
            (s, s.rpm.tolist(), s.thrust_n.tolist(), s.torque_nm.tolist(), self._curve(s))
            for s in parts
        ]
        peak, rms = self.column("motor_peak_nm"), self.column("motor_rms_nm")
        worst = self.column("motor_worst_segment")
        return [
            Motion(
                profile=p,
                segments=tuple(
                    Segment(
                        s.name,
                        s.direction,
                        s.duration_s,
                        rpm[k],
                        thrust[k],
                        torque[k],
                        None if curve is None else curve[k],
                        i == worst[k],
                    )
                    for i, (s, rpm, thrust, torque, curve) in enumerate(columns)
                ),
                peak_nm=peak[k],
                rms_nm=rms[k],
            )
            for k in range(len(self.at))
        ]

    def _curve(self, s: Segment[Array]) -> list[float] | None:
        """The motor's usable torque each candidate's segment ``s`` is held against [N m],
        as the curve check holds it (``segments.segment_curve``: a ramp's lowest from
        standstill to its top speed); None without a curve."""
        if not self.app.motor_curve:
            return None
        curve: list[float] = segments.segment_curve(self.app, s.name, s.rpm)[0].tolist()
        return curve


def _utilizations(values: Array | None, index: Positions) -> list[float | None]:
    if values is None:
        return [None] * len(index)
    picked = values[index]
    finite = np.isfinite(picked).tolist()
    return [v if ok else None for v, ok in zip(picked.tolist(), finite, strict=True)]


class Numbers:
    """One candidate's quantities (as ``Quantities``, SI), each read when first asked
    for: ``record.quantities.torque.total_nm`` (``part``: the part it reads)."""

    __slots__ = ("_batch", "_k", "_part")

    def __init__(self, batch: Batch, k: int, part: str | None = None) -> None:
        self._batch, self._k, self._part = batch, k, part

    def __getattr__(self, name: str) -> Any:
        if self._part is None:
            if name not in PARTS:
                raise AttributeError(name)
            return Numbers(self._batch, self._k, name)
        if PART_OF.get(name) != self._part:
            raise AttributeError(f"{self._part}.{name}")
        return float(self._batch.column(name)[self._k])


class CheckResult(NamedTuple):
    """One check of one candidate: demand against capacity, with the message and the fix.

    ``value`` (demand) and ``limit`` (capacity) are SI in ``quantity``; None for yes/no
    checks. ``utilization`` = value / limit. The message, the fix and ``input_limits``
    (application inputs any one of which, set to the given SI value, would make the check
    pass, e.g. {"load_n": 120.0}) are written when read: most results are ranked or
    counted, not read.
    """

    name: str
    kind: Literal["limit", "advice"]
    passed: bool
    utilization: float | None
    demand: float
    capacity: float
    check: Check
    slot: "Slot"

    @property
    def label(self) -> str:
        return self.check.label

    @property
    def formula(self) -> str:
        return self.check.formula

    @property
    def sources(self) -> tuple[str, ...]:
        """The catalog values the check reads, then the axis's value its capacity is."""
        given = self.check.capacity_given
        return (*self.check.sources, given) if given else self.check.sources

    @property
    def numeric(self) -> bool:
        return not (math.isnan(self.demand) or math.isnan(self.capacity))

    @property
    def value(self) -> float | None:
        return self.demand if self.numeric else None

    @property
    def limit(self) -> float | None:
        return self.capacity if self.numeric else None

    @property
    def quantity(self) -> Quantity | None:
        return self.check.quantity if self.numeric else None

    @property
    def message(self) -> Phrase:
        at = self.slot
        return self.check.explain(at.app, at.screw, at.row, self.passed)

    @property
    def fix(self) -> Phrase | None:
        return None if self.passed else self.slot.fix_of(self.check)

    @property
    def left_out(self) -> tuple[str, ...]:
        """The catalog values the check ran without (``Check.left_out``)."""
        at = self.slot
        return self.check.left_out(at.app, at.screw, at.row)

    @property
    def input_limits(self) -> Mapping[str, float] | None:
        if self.passed:
            return None
        return dict(self.slot.limits_of(self.check)) or None


class Slot:
    """What a candidate's checks read to write their sentences: the application, its
    screw, its quantities and the catalog's reach, and its fixes, each written once. (A
    slot holds no reference to the record or its batch, so the batch keeps the slots
    and a record holds no reference cycle: it is freed as soon as it is dropped.)"""

    __slots__ = ("_fixes", "_limits", "_row", "app", "position", "screening", "screw")

    def __init__(self, app: Application, sc: Screening, position: int) -> None:
        self.app, self.screening, self.position = app, sc, position
        self.screw: ScrewSpec = screw_as_run(sc.table, position)
        self._row: Quantities[float] | None = None
        self._fixes: dict[str, Phrase | None] = {}
        self._limits: dict[str, dict[str, float]] = {}

    @property
    def row(self) -> Quantities[float]:
        """Every quantity as a float (NaN: no such limit)."""
        if self._row is None:
            self._row = self.screening.quantities.at(self.position)
        return self._row

    def limits_of(self, check: Check) -> dict[str, float]:
        """The inputs of ``check``'s ``input_limits`` the application reads
        (``read_inputs``), each worked out once (some search the model again)."""
        if check.name not in self._limits:
            limits = check.input_limits(self.app, self.screw, self.row)
            self._limits[check.name] = read_inputs(self.app, limits)
        return self._limits[check.name]

    def fix_of(self, check: Check) -> Phrase | None:
        """What would make ``check`` pass, within what the catalog offers, and where
        a value it names is one the inputs' own rules refuse, why
        (``input_rules.refused``: a move too slow for the cycles a day)."""
        if check.name not in self._fixes:
            app, screw, row = self.app, self.screw, self.row
            fix = check.fix(app, screw, row, self.screening.reach)
            # only the cycles a day refuse a move: without them no check's limits are read
            note = None
            if fix is not None and app.cycles_per_day is not None:
                note = refused(app, self.limits_of(check))
            if fix is not None and note is not None:  # the fix's own fields kept as named
                fix = Phrase(fix.template + " {refused}", {**fix.values, "refused": note})
            lead = None if fix is None else fix.values.get("lead")
            other = self._at_lead(lead.value) if isinstance(lead, Amount) else None
            if fix is not None and other is not None:
                fix = Phrase(fix.template + " {at_lead}", {**fix.values, "at_lead": other})
            self._fixes[check.name] = fix
        return self._fixes[check.name]

    def _at_lead(self, lead_m: float) -> Phrase | None:
        """How the screw of this size and nut at ``lead_m`` fares on the axis, where the
        screening holds it (a lead offered by a fix turns the screw faster or needs more
        torque, which other checks judge): the checks it fails, or that it passes them;
        None where it was not screened (another lead asked for)."""
        sc, size = self.screening, size_of(self.screw)
        lead = sc.table.lead_m
        for k in np.flatnonzero(lead == lead_m).tolist():
            other = sc.table.screws[k]
            if size_of(other) != size:
                continue
            failed = [BY_NAME[n].label for n, mask in sc.failed_by_check.items() if mask[k]]
            if not failed:
                return Phrase("{other} passes every check of this axis.", {"other": other.id})
            return Phrase(f"{{other}} fails {', '.join(failed)} on this axis.", {"other": other.id})
        return None

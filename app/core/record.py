"""One screened candidate as a record: every number of it, read from the screening's
arrays when first asked for.

``records(app, sc, positions)`` gives the candidates at ``positions`` of a screening. A
record reads its numbers through ``quantities`` (one column of the screening, taken for
every record of the batch at once, when first read) and builds its sections (torque,
critical speed, buckling, PV, life, accuracy, checks, the move) when first read too: the
compact forms, which read a few numbers and the checks' utilisation, never pay for the
messages, breakdowns and segments of the full one. Every form of a candidate reads the
same record, so they cannot disagree.
"""

import math
from collections.abc import Callable, Mapping, Sequence
from operator import attrgetter
from typing import Any, Generic, Literal, NamedTuple, TypeVar

import numpy as np
from numpy.typing import NDArray

from app.core import motion
from app.core.checks import BY_NAME
from app.core.checks.base import Check
from app.core.model import (
    PV,
    Accuracy,
    Application,
    Buckling,
    J,
    Judged,
    Motion,
    Profile,
    Provenance,
    ProvenanceKind,
    ScrewSpec,
    Segment,
    failed_advice,
)
from app.core.phrase import Phrase, Quantity
from app.core.quantities import Quantities
from app.core.robustness import Robustness
from app.core.screening import Screening
from app.core.sections import Column, CriticalSpeed, Life, Torque, number
from app.core.table import Array
from app.core.verdict import Verdict, verdict

Owner = TypeVar("Owner")
T = TypeVar("T")


class once(Generic[Owner, T]):
    """A value computed when first read, then kept on the instance: ``cached_property``
    without its per-instance lock (Python 3.11 takes one on every first read, about a
    microsecond; a record is read from one thread)."""

    def __init__(self, compute: Callable[[Owner], T]) -> None:
        self.compute, self.name = compute, compute.__name__

    def __get__(self, owner: Owner, cls: type) -> T:
        value = self.compute(owner)
        owner.__dict__[self.name] = value
        return value


#: Provenance kinds from the least to the most certain.
CERTAINTY: tuple[ProvenanceKind, ...] = (
    "assumed",
    "derived",
    "user",
    "vendor",
    "handbook",
    "seed",
    "standard",
)
#: Catalog fields behind the geometry, efficiency and torque of every candidate.
GEOMETRY_SOURCES = (
    "outer_diameter",
    "root_diameter",
    "lead",
    "friction_dynamic",
    "friction_static",
    "thread_half_angle",
    "inertia_per_length",
    "drag_torque",
)
#: The screening's per-candidate verdicts a record reads as columns.
VERDICTS = frozenset({"passed", "max_utilization"})
#: The checks that judge the motor: a candidate's motor use is the largest of their
#: utilisations (and the ranking by motor margin reads them).
MOTOR_CHECKS = ("torque", "motor_curve", "motor_rms", "motor_speed")
#: Positions in a screening, as an index array (NumPy picks with one four times faster
#: than with a list).
Positions = NDArray[np.intp]


def positions_array(positions: Sequence[int]) -> Positions:
    """``positions`` as an index array."""
    return np.asarray(positions, dtype=np.intp)


def governing(app: Application, checks: Sequence[J]) -> J | None:
    """Among the checks that reject (limits; advice too when the user asks), the one with
    the highest utilisation, or the first failed yes/no check when no numeric one fails."""
    rejecting = [c for c in checks if c.kind == "limit" or app.advice == "reject"]
    utilized = [c for c in rejecting if c.utilization is not None]
    top = max(utilized, key=attrgetter("utilization")) if utilized else None
    failed = [c for c in rejecting if not c.passed]
    if failed and (top is None or top.passed):
        return failed[0]
    return top


def limit_provenance(check: Judged | None, s: ScrewSpec) -> ProvenanceKind | None:
    """How certain the governing check's limit is: the least certain provenance of the
    catalog values its capacity rests on ("user" when the capacity is the user's input)."""
    if check is None:
        return None
    fields = BY_NAME[check.name].capacity_sources
    if not fields:
        return "user"
    kinds = [s.provenance[f].kind for f in fields if f in s.provenance]
    return min(kinds, key=CERTAINTY.index) if kinds else None


class Columns(dict[str, list[Any]]):
    """The screening's columns at a batch's positions, as Python values, each taken when
    first read: a quantity (``Quantities``), else a verdict (``passed``,
    ``max_utilization``), else a column of the table. (A dict, so that reading a taken
    column is one subscript.)"""

    def __init__(self, sc: Screening, at: Positions) -> None:
        super().__init__()
        self.screening, self.at = sc, at

    def __missing__(self, name: str) -> list[Any]:
        sc = self.screening
        source = getattr(sc.quantities, name, None)
        if source is None:
            source = getattr(sc, name) if name in VERDICTS else getattr(sc.table, name)
        values: list[Any] = source[self.at].tolist()
        self[name] = values
        return values


class Batch:
    """The screening's arrays at the positions of some candidates: each column taken for
    all of them at once, when first read (``columns``)."""

    def __init__(self, app: Application, sc: Screening, positions: Sequence[int]) -> None:
        self.app, self.screening = app, sc
        self.positions = [int(i) for i in positions]
        self.at = positions_array(self.positions)
        self.columns = Columns(sc, self.at)

    @once
    def slots(self) -> list["Slot"]:
        """Each candidate's slot: what its sections and checks read."""
        sc, app = self.screening, self.app
        return [Slot(app, sc, i) for i in self.positions]

    @once
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
                    values = (name, check.kind, not failed, utilization, demand, capacity)
                    # tuple.__new__ builds the named tuple without its Python-level __new__
                    out.append(tuple.__new__(CheckResult, (*values, check, slot)))
        return [tuple(checks) for checks in per]

    @once
    def motions(self) -> list[Motion | None]:
        """The move and its segments' torques per candidate (None each without a stroke)."""
        p = motion.move_profile(self.app)
        if p is None:
            return [None] * len(self.at)
        hold = np.array(self.columns["brake_nm"])
        parts = motion.segments(self.app, p, self.screening.table.take(self.at), hold)
        columns = [(s, s.rpm.tolist(), s.thrust_n.tolist(), s.torque_nm.tolist()) for s in parts]
        peak, rms = self.columns["motor_peak_nm"], self.columns["motor_rms_nm"]
        return [
            Motion(
                profile=p,
                segments=tuple(
                    Segment(s.name, s.direction, s.duration_s, rpm[k], thrust[k], torque[k])
                    for s, rpm, thrust, torque in columns
                ),
                peak_nm=peak[k],
                rms_nm=rms[k],
            )
            for k in range(len(self.at))
        ]


def _utilizations(values: Array | None, index: Positions) -> list[float | None]:
    if values is None:
        return [None] * len(index)
    picked = values[index]
    finite = np.isfinite(picked).tolist()
    return [v if ok else None for v, ok in zip(picked.tolist(), finite, strict=True)]


class Numbers:
    """One candidate's quantities (``Quantities``' names, SI), each read when first asked
    for: ``record.quantities.total_nm``."""

    __slots__ = ("_batch", "_k")

    def __init__(self, batch: Batch, k: int) -> None:
        self._batch, self._k = batch, k

    def __getattr__(self, name: str) -> float:
        return float(self._batch.columns[name][self._k])


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
        return self.check.sources

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
    def input_limits(self) -> Mapping[str, float] | None:
        if self.passed:
            return None
        at = self.slot
        limits = self.check.input_limits(at.app, at.screw, at.row)
        return dict(limits) if limits else None


class Slot:
    """What a candidate's checks read to write their sentences: the application, its
    screw, its quantities and the catalog's reach, and its fixes, each written once. (A
    slot holds no reference to the record or its batch, so the batch keeps the slots
    and a record holds no reference cycle: it is freed as soon as it is dropped.)"""

    __slots__ = ("_fixes", "_row", "app", "position", "screening", "screw")

    def __init__(self, app: Application, sc: Screening, position: int) -> None:
        self.app, self.screening, self.position = app, sc, position
        self.screw: ScrewSpec = sc.table.screws[position]
        self._row: Quantities[float] | None = None
        self._fixes: dict[str, Phrase | None] = {}

    @property
    def row(self) -> Quantities[float]:
        """Every quantity as a float (NaN: no such limit)."""
        if self._row is None:
            self._row = self.screening.quantities.at(self.position)
        return self._row

    def fix_of(self, check: Check) -> Phrase | None:
        """What would make ``check`` pass, within what the catalog offers."""
        if check.name not in self._fixes:
            reach = self.screening.reach
            self._fixes[check.name] = check.fix(self.app, self.screw, self.row, reach)
        return self._fixes[check.name]


class Candidate:
    """One screened candidate against one application, SI; its numbers are read and its
    sections built when first read. ``judged`` is its robustness when known."""

    axial_load_n = Column[float]("force_n")
    peak_axial_load_n = Column[float]("peak_force_n")
    rpm = Column[float]("rpm")
    pitch_diameter_m = Column[float]("pitch_diameter_m")
    lead_angle_rad = Column[float]("lead_angle_rad")
    efficiency = Column[float]("efficiency")
    efficiency_square_thread = Column[float]("efficiency_square_thread")
    backdrive_efficiency = Column[float]("backdrive_efficiency")
    backdrive_efficiency_running = Column[float]("backdrive_efficiency_running")
    self_locking = Column[bool]("self_locking")
    seed_rule_no_backdrive = Column[bool]("seed_rule_no_backdrive")
    max_self_locking_lead_m = Column[float]("max_self_locking_lead_m")
    max_self_locking_lead_with_margin_m = Column[float]("max_self_locking_lead_with_margin_m")
    holding_torque_seed_nm = Column[float]("holding_seed_nm")
    holding_torque_physics_nm = Column[float]("holding_physics_nm")
    brake_nm = Column[float]("brake_nm")
    max_utilization = Column[float]("max_utilization")
    passed = Column[bool]("passed")

    def __init__(self, batch: Batch, k: int, judged: Robustness | None = None) -> None:
        self.batch, self.k, self.judged = batch, k, judged
        self.app = batch.app

    @once
    def screw(self) -> ScrewSpec:
        return self.batch.slots[self.k].screw

    @once
    def quantities(self) -> Numbers:
        """Every quantity (``Quantities``' names, SI), each read when first asked for."""
        return Numbers(self.batch, self.k)

    def with_robustness(self, judged: Robustness) -> "Candidate":
        """The same candidate with its robustness known."""
        return Candidate(self.batch, self.k, judged)

    @property
    def robust(self) -> bool | None:
        return None if self.judged is None else self.judged.robust

    @property
    def hinges_on(self) -> tuple[str, ...]:
        return () if self.judged is None else self.judged.hinges_on

    @property
    def checks(self) -> tuple[CheckResult, ...]:
        """Every check that applies, in registry order."""
        return self.batch.results[self.k]

    @once
    def governing(self) -> CheckResult | None:
        return governing(self.app, self.checks)

    @property
    def governing_check(self) -> str | None:
        return None if self.governing is None else self.governing.name

    @property
    def governing_limit_provenance(self) -> ProvenanceKind | None:
        return limit_provenance(self.governing, self.screw)

    @once
    def verdict(self) -> Verdict:
        """Why this screw in two lines: what governs, what it rests on, what to watch."""
        return verdict(self)

    @property
    def failed_checks(self) -> tuple[CheckResult, ...]:
        """The failed limits: what rejects the candidate."""
        return tuple(c for c in self.checks if not c.passed and c.kind == "limit")

    @property
    def failed(self) -> tuple[CheckResult, ...]:
        """Every failed check, limits and advice, in check order."""
        return tuple(c for c in self.checks if not c.passed)

    @property
    def warnings(self) -> tuple[CheckResult, ...]:
        """Failed advice: reported beside the candidate, not a rejection."""
        return tuple(failed_advice(self.checks))

    @property
    def warned(self) -> tuple[str, ...]:
        return tuple(c.name for c in failed_advice(self.checks))

    @property
    def utilization(self) -> dict[str, float | None]:
        """Check -> demand / capacity (None for a yes/no check)."""
        return {c.name: c.utilization for c in self.checks}

    @property
    def motor_use(self) -> float | None:
        """The largest share of the motor used over the motor checks (``MOTOR_CHECKS``);
        None when no motor is given (no motor check has a number)."""
        used = self.utilization
        shares = [u for name in MOTOR_CHECKS if (u := used.get(name)) is not None]
        return max(shares) if shares else None

    @property
    def fixes(self) -> tuple[Phrase, ...]:
        """What would make each failed check pass, where the catalog offers it."""
        return tuple(fix for c in self.checks if (fix := c.fix) is not None)

    @property
    def provenance(self) -> dict[str, Provenance]:
        """Catalog field -> provenance, for the fields this candidate's numbers use."""
        used = {src for c in self.checks for src in c.sources} | set(GEOMETRY_SOURCES)
        return {k: p for k, p in self.screw.provenance.items() if k in used}

    @property
    def outgassing(self) -> tuple[tuple[float, float], ...] | None:
        """(hours, weight loss [%]) in a vacuum; None otherwise."""
        return self.screw.outgassing if self.app.vacuum else None

    @property
    def self_locking_with_margin(self) -> bool:
        return bool(self.quantities.locks_with_margin)

    @property
    def traverse_speed_limit_m_s(self) -> float | None:
        return number(self.batch.columns["traverse_limit_m_s"][self.k])

    @property
    def traverse_extrapolated(self) -> bool:
        extrapolated = bool(self.batch.columns["traverse_extrapolated"][self.k])
        return self.traverse_speed_limit_m_s is not None and extrapolated

    @once
    def torque(self) -> Torque:
        return Torque(self.batch, self.k)

    @once
    def critical_speed(self) -> CriticalSpeed:
        return CriticalSpeed(self.batch, self.k)

    @once
    def buckling(self) -> Buckling:
        q = self.quantities
        transition = number(q.transition_slenderness)
        short = transition is not None and q.slenderness < transition
        return Buckling(
            applies=q.compressive_force_n > 0.0,
            critical_load_n=q.critical_load_n,
            allowed_load_n=q.allowed_load_n,
            safety_factor=self.app.buckling_safety_factor,
            slenderness=q.slenderness,
            transition_slenderness=transition,
            mode="johnson" if short else "euler",
            root_stress_pa=q.root_stress_pa,
            yield_strength_pa=self.screw.yield_strength_pa,
        )

    @once
    def pv(self) -> PV:
        """The nut's PV against its permissible PV: the rating derated to the nut's
        temperature and raised by its lubrication (``formulas.pv_derating``)."""
        q, limit = self.quantities, self.screw.pv_limit_pa_m_s
        return PV(
            value_pa_m_s=q.pv_pa_m_s,
            limit_pa_m_s=None if limit is None else q.pv_limit_pa_m_s,
            pressure_pa=q.pressure_pa,
            surface_speed_m_s=q.surface_speed_m_s,
            contact_area_m2=q.contact_area_m2,
            max_load_n=None if limit is None else q.pv_max_load_n,
            max_speed_m_s=None if limit is None else q.pv_max_speed_m_s,
        )

    @once
    def life(self) -> Life | None:
        """The rated life, else the wear life; None for a nut with neither (no rating,
        no wear rate, or no thrust to wear it)."""
        s = self.screw
        if s.life_min_m is not None and s.life_max_m is not None:
            return Life(self.batch, self.k)
        worn = Life(self.batch, self.k)
        return worn if all(math.isfinite(h) for h in worn.hours) else None

    @once
    def accuracy(self) -> Accuracy:
        s, q = self.screw, self.quantities
        return Accuracy(
            lead_error_m=number(q.lead_error_m),
            repeatability_m=s.repeatability_m,
            backlash_min_m=s.backlash_min_m,
            backlash_max_m=s.backlash_max_m,
            thermal_growth_m=q.thermal_growth_m,
        )

    @property
    def motion(self) -> Motion | None:
        """The move profile and the torque of each segment (None: no stroke given)."""
        return self.batch.motions[self.k]

    @property
    def profile(self) -> Profile | None:
        """The move over the stroke (None: no stroke given)."""
        return None if self.motion is None else self.motion.profile

    @property
    def segments(self) -> tuple[Segment[float], ...] | None:
        """Each segment of the cycle with its torque (None: no stroke given)."""
        return None if self.motion is None else self.motion.segments


def records(
    app: Application,
    sc: Screening,
    positions: Sequence[int],
    judged: Sequence[Robustness | None] | None = None,
) -> list[Candidate]:
    """The candidates at ``positions`` of a screening (in ``sc.table``), one batch;
    ``judged`` gives each one's robustness when it is known."""
    batch = Batch(app, sc, positions)
    found = judged if judged is not None else [None] * len(batch.positions)
    return [Candidate(batch, k, r) for k, r in enumerate(found)]

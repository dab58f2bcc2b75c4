"""One screened candidate as a record: every number of it, read from the screening's
arrays when first asked for.

``records(app, sc, positions)`` gives the candidates at ``positions`` of a screening. A
record reads its numbers through ``quantities`` (one column of the screening, taken for
every record of the batch at once, when first read: ``app.core.batch``) and builds its
sections (torque, critical speed, buckling, PV, life, accuracy, checks, the move) when
first read too (``functools.cached_property``): the
compact forms, which read a few numbers and the checks' utilisation, never pay for the
messages, breakdowns and segments of the full one. Every form of a candidate reads the
same record, so they cannot disagree.
"""

import math
from collections.abc import Mapping, Sequence
from functools import cached_property
from operator import attrgetter
from typing import cast

from app.core.batch import Batch, CheckResult, Numbers
from app.core.checks import BY_NAME, REGISTRY
from app.core.checks.back_driving import rule_note
from app.core.checks.base import Check
from app.core.formulas import geometry
from app.core.holding import unpowered_holder
from app.core.model import (
    PV,
    RMS_ZONE,
    Accuracy,
    Application,
    AxisProvenance,
    Buckling,
    J,
    Judged,
    Provenance,
    ProvenanceKind,
    ScrewSpec,
    failed_advice,
    holds,
)
from app.core.phrase import Phrase
from app.core.quantities import Quantities
from app.core.robustness import Robustness
from app.core.screening import Screening
from app.core.sections import Column, CriticalSpeed, Life, Torque, number
from app.core.timeline import Motion, Profile, Segment
from app.core.verdict import Verdict, verdict

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
#: The checks that judge the motor: a candidate's motor use is the largest of their
#: utilisations (and the ranking by motor margin reads them).
MOTOR_CHECKS = tuple(c.name for c in REGISTRY if c.judges_motor)


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


#: The provenance of an axis's value the user typed (``AxisProvenance``'s default).
TYPED = Provenance("user", "the value typed in")


def limit_provenance(
    check: Judged | None, provenance: Mapping[str, Provenance]
) -> ProvenanceKind | None:
    """How certain the governing check's limit is: the least certain provenance of the
    catalog values its capacity rests on, else that of the axis's value it is
    (``Check.capacity_given``: "user" when typed in), in ``provenance`` (a record's)."""
    if check is None:
        return None
    c = BY_NAME[check.name]
    if not c.capacity_sources:
        return provenance.get(c.capacity_given, TYPED).kind
    kinds = [provenance[f].kind for f in c.capacity_sources if f in provenance]
    return min(kinds, key=CERTAINTY.index) if kinds else None


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
    holding_torque_with_margin_nm = Column[float]("holding_distrusted_nm")
    brake_nm = Column[float]("brake_nm")
    brake_needed_nm = Column[float]("brake_needed_nm")
    brake_to_fit_nm = Column[float]("brake_to_fit_nm")
    max_utilization = Column[float]("max_utilization")
    passed = Column[bool]("passed")

    def __init__(self, batch: Batch, k: int, judged: Robustness | None = None) -> None:
        self.batch, self.k, self.judged = batch, k, judged
        self.app = batch.app

    @cached_property
    def screw(self) -> ScrewSpec:
        return self.batch.slots[self.k].screw

    @cached_property
    def quantities(self) -> Quantities[float]:
        """Every quantity (as ``Quantities``, SI), each read when first asked for."""
        return cast("Quantities[float]", Numbers(self.batch, self.k))

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

    @property
    def skipped(self) -> tuple[Check, ...]:
        """The checks that run for this application but could not for this screw."""
        return self.batch.skipped[self.k]

    @cached_property
    def governing(self) -> CheckResult | None:
        return governing(self.app, self.checks)

    @property
    def governing_check(self) -> str | None:
        return None if self.governing is None else self.governing.name

    @cached_property
    def value_provenance(self) -> dict[str, Provenance]:
        """The provenance of every value a check may read: the screw's catalog values and
        the axis's values that the checks' capacities are (``Batch.axis``)."""
        return {**self.screw.provenance, **self._typed_nut_length, **self.axis_provenance}

    @property
    def _typed_nut_length(self) -> dict[str, Provenance]:
        """The nut length's provenance where the axis gives one (the catalog's replaced):
        the user's, as typed in."""
        given = self.app.nut_length_m is not None and "nut_length" in self.screw.provenance
        return {"nut_length": TYPED} if given else {}

    @property
    def axis_provenance(self) -> dict[str, Provenance]:
        """The provenance of the axis's values the checks' capacities are (``Batch.axis``),
        a library motor's continuous rating as this candidate's cycle reads it: that of its
        continuous duty zone (``RMS_ZONE``) where the cycle runs where the zone narrows."""
        axis = dict(self.batch.axis)
        zone = axis.pop(RMS_ZONE, None)
        motor = self.quantities.motor
        if zone is not None and motor.motor_rms_zone_nm > motor.motor_rms_nm:
            axis["motor_rms_torque"] = zone
        return axis

    @property
    def governing_limit_provenance(self) -> ProvenanceKind | None:
        return limit_provenance(self.governing, self.value_provenance)

    @cached_property
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

    @cached_property
    def utilization(self) -> dict[str, float | None]:
        """Check -> demand / capacity (None for a yes/no check); read by the response and
        by the motor's use alike, so built once."""
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
        """Catalog field -> provenance, for the fields this candidate's numbers use (its
        checks', its geometry's, its accuracy's and its life's); then
        the axis's values the checks' capacities are (a motor's curve: typed in, or the
        library's)."""
        used = {src for c in self.checks for src in c.sources} | set(GEOMETRY_SOURCES)
        used |= set(BY_NAME["accuracy"].sources)  # the accuracy every candidate shows
        used |= set(() if self.life is None else self.life.sources)  # and its life
        screw = {**self.screw.provenance, **self._typed_nut_length}
        found = {k: p for k, p in screw.items() if k in used}
        axis = self.axis_provenance
        given = (c.check.capacity_given for c in self.checks if c.check.capacity_given)
        return found | {key: axis.get(key, TYPED) for key in given}

    @property
    def outgassing(self) -> tuple[tuple[float, float], ...] | None:
        """(hours, weight loss [%]) in a vacuum; None otherwise."""
        return self.screw.outgassing if self.app.vacuum else None

    @property
    def self_locking_with_margin(self) -> bool:
        return bool(self.quantities.holding.locks_with_margin)

    @property
    def hold_margin(self) -> float | None:
        """The power-off hold's margin (``efficiency.hold_margin``); None where holding
        with the power off is not required or no load is held."""
        return number(self.quantities.holding.hold_margin)

    @property
    def holds_power_off(self) -> bool | None:
        """The answer to "must hold with the power off": yes at a margin of 1 or more."""
        margin = self.hold_margin
        return None if margin is None else bool(holds(margin))

    @property
    def holds_by(self) -> str | None:
        """What holds the load with the power off, the means whose margin ``hold_margin``
        is (``app.core.holding.hold_margins``): the thread when it alone holds with the
        friction margin (a brake beside it is then a second means), else the brake or the
        detent torque where one is given, else the thread (that does not hold); None where
        nothing is required or held."""
        if self.hold_margin is None:
            return None
        if self.quantities.holding.hold_by_thread:
            return "thread"
        return unpowered_holder(self.app)

    @property
    def holding_rule(self) -> Phrase | None:
        """Where the catalog's rule of thumb (lead < OD / 8) and the physics disagree:
        which governs and why."""
        return rule_note(self.app, self.screw, self.self_locking_with_margin)

    @property
    def traverse_speed_limit_m_s(self) -> float | None:
        return number(self.batch.column("traverse_limit_m_s")[self.k])

    @property
    def traverse_extrapolated(self) -> bool:
        extrapolated = bool(self.batch.column("traverse_extrapolated")[self.k])
        return self.traverse_speed_limit_m_s is not None and extrapolated

    @cached_property
    def torque(self) -> Torque:
        return Torque(self.batch, self.k)

    @cached_property
    def critical_speed(self) -> CriticalSpeed:
        return CriticalSpeed(self.batch, self.k)

    @cached_property
    def buckling(self) -> Buckling:
        q = self.quantities
        transition = number(q.column.transition_slenderness)
        short = transition is not None and q.column.slenderness < transition
        return Buckling(
            applies=q.axis.compressive_force_n > 0.0,
            critical_load_n=q.column.critical_load_n,
            allowed_load_n=q.column.allowed_load_n,
            safety_factor=self.app.buckling_safety_factor,
            slenderness=q.column.slenderness,
            transition_slenderness=transition,
            mode="johnson" if short else "euler",
            root_stress_pa=q.column.root_stress_pa,
            yield_strength_pa=self.screw.yield_strength_pa,
        )

    @cached_property
    def pv(self) -> PV | None:
        """The nut's PV by the seed's method (three threads in contact) against its
        permissible PV: the rating derated to the nut's temperature and raised by its
        lubrication (``formulas.pv_derating``). None for a ball nut (rolling contact) and
        for a standard thread's nut without a seed PV rating: its engaged flanks are
        judged instead (the nut contact pressure check), over the nut's own length, where
        three threads' area would give a second, different pressure."""
        q, s = self.quantities, self.screw
        limit = s.pv_limit_pa_m_s
        if s.screw_type == "ball" or (limit is None and s.pitch_m is not None):
            return None
        return PV(
            force_n=q.nut.pv_force_n,
            speed_m_s=geometry.linear_speed(q.nut.pv_rpm, s.lead_m),
            value_pa_m_s=q.nut.pv_pa_m_s,
            limit_pa_m_s=None if limit is None else q.nut.pv_limit_pa_m_s,
            pressure_pa=q.nut.pressure_pa,
            surface_speed_m_s=q.nut.surface_speed_m_s,
            contact_area_m2=q.nut.contact_area_m2,
            max_load_n=None if limit is None else q.nut.pv_max_load_n,
            max_speed_m_s=None if limit is None else q.nut.pv_max_speed_m_s,
        )

    @cached_property
    def life(self) -> Life | None:
        """The rated life, else the wear life; None for a nut with neither (no rating,
        no wear rate, or no thrust to wear it)."""
        s = self.screw
        if s.life_min_m is not None and s.life_max_m is not None:
            return Life(self.batch, self.k)
        worn = Life(self.batch, self.k)
        return worn if all(math.isfinite(h) for h in worn.hours) else None

    @cached_property
    def accuracy(self) -> Accuracy:
        s, q = self.screw, self.quantities
        return Accuracy(
            lead_error_m=number(q.accuracy.lead_error_m),
            repeatability_m=s.repeatability_m,
            backlash_min_m=s.backlash_min_m,
            backlash_max_m=s.backlash_max_m,
            thermal_growth_m=q.accuracy.thermal_growth_m,
            heat_growth_m=number(q.accuracy.heat_growth_m),
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
    axis: AxisProvenance | None = None,
) -> list[Candidate]:
    """The candidates at ``positions`` of a screening (in ``sc.table``), one batch;
    ``judged`` gives each one's robustness when it is known; ``axis`` the provenance of
    the axis's values the checks' capacities are (typed in where not given)."""
    batch = Batch(app, sc, positions, axis)
    found = judged if judged is not None else [None] * len(batch.positions)
    return [Candidate(batch, k, r) for k, r in enumerate(found)]

"""Vertical axis with a brake: the holding torque needed against the brake's."""

import numpy as np

from app.core import motion
from app.core.checks.base import (
    Application,
    Array,
    CandidateTable,
    Check,
    Mapping,
    Measure,
    Quantities,
    Reach,
    ScrewSpec,
    everywhere,
    same,
)
from app.core.formulas import efficiency
from app.core.phrase import Amount, Phrase


class Holding(Check):
    name = "holding"
    label = "Holding torque (vertical axis)"
    description = (
        "On a vertical axis the brake, or the motor's holding torque, must hold the load "
        "at standstill wherever the thread is not reliably self-locking: the larger of the "
        "seed's holding torque and the physical one, times the torque safety factor."
    )
    quantity = "torque"
    formula = "T_hold = 0 if locks else SF * max(T_seed, T_physics); T_available = T_brake"
    source = "seed catalog, Back Driving (T_b = F lead eta / 2 pi); Shigley sec. 8-2"
    sources = ("friction_static", "friction_dynamic", "thread_half_angle")

    def applies(self, app: Application) -> bool:
        return motion.holds_a_load(app) and app.brake_torque_nm is not None

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.brake_needed_nm, same(t, app.brake_torque_nm))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "locks": q.locks_with_margin.astype(bool),
            "SF": app.torque_safety_factor,
            "T_seed": efficiency.holding_torque(q.holding_force_n, t.lead_m, t.efficiency),
            "T_physics": q.holding_physics_nm,
            "T_brake": np.float64(app.brake_torque_nm or 0.0),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        if r.locks_with_margin:
            return Phrase("Self-locking with margin: the brake is not needed to hold.")
        verb = "holds" if passed else "is short of"
        return Phrase(
            "The {brake} brake " + verb + " the {needed} needed ({sf} x the larger of "
            "{seed} (seed method) and {physics} (physics)).",
            {
                "brake": Amount(app.brake_torque_nm or 0.0, "torque"),
                "needed": Amount(r.brake_needed_nm, "torque"),
                "sf": Amount(app.torque_safety_factor, "factor"),
                "seed": Amount(r.holding_seed_nm, "torque"),
                "physics": Amount(r.holding_physics_nm, "torque"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            "Fit a brake of at least {needed}, or use a lead of at most {lead} "
            "(self-locking with margin).",
            {
                "needed": Amount(r.brake_needed_nm, "torque"),
                "lead": Amount(r.max_lock_lead_m, "length"),
            },
        )

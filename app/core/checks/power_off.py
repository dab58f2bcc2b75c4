"""A stepper's holding torque holds only while it is energised: with the power off only
its detent torque (and the thread) holds the load."""

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
from app.core.checks.holding import brake_or_lead, holding_phrase, needed_symbols
from app.core.holding import unpowered_holder
from app.core.phrase import Phrase


class HoldingPowerOff(Check):
    name = "holding_power_off"
    motor_may_clear = True
    capacity_given = "motor_detent"
    why_none = "the motor's detent torque holds this load on no screw: add a brake"
    label = "Holding with the power off (detent torque)"
    description = (
        "The energised holding torque of a stepper holds the load only while the power is "
        "on. With the power off only the motor's detent torque holds it where the thread "
        "is not reliably self-locking: the same torque as the holding check needs (the "
        "larger of the seed's and the physical one at the distrusted static friction, "
        "times the brake safety factor) against the detent torque."
    )
    quantity = "torque"
    formula = "T_hold = 0 if locks else SF * max(T_seed, T_physics); T_available = T_detent"
    source = (
        "seed catalog, Back Driving (T_b = F lead eta / 2 pi); Shigley sec. 8-2; the "
        "motor's detent (unpowered) torque"
    )
    sources = ("friction_static", "friction_dynamic", "thread_half_angle")

    def applies(self, app: Application) -> bool:
        """Holding with the power off is required and the detent torque given is what holds
        then (``unpowered_holder``: no brake given)."""
        needed = app.hold_power_off and motion.holds_a_load(app)
        return needed and unpowered_holder(app) == "detent"

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.holding.brake_needed_nm, same(t, app.detent_torque_nm))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {**needed_symbols(app, t, q), "T_detent": app.detent_torque_nm}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        if r.holding.locks_with_margin:
            return Phrase("Self-locking with margin: the load stays put with the power off.")
        detent = app.detent_torque_nm or 0.0
        return holding_phrase(app, r, detent, passed, "with the power off (detent torque)")

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return brake_or_lead(
            "Fit a brake of at least {needed} (it holds with the power off)", s, r, reach
        )

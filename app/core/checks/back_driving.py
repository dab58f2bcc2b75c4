"""A load held at rest (a vertical axis's weight, or a load of fixed direction) without a
brake: the thread must self-lock, with a margin on friction."""

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
)
from app.core.checks.holding import brake_or_lead
from app.core.formulas import efficiency
from app.core.holding import unpowered_holder
from app.core.phrase import Amount, Phrase


class BackDriving(Check):
    name = "back_driving"
    motor_may_clear = True
    why_none = (
        "every screw back-drives under this load: add a brake (its torque as an input) or a "
        "self-locking worm stage"
    )
    label = "Self-locking (load held at rest, no brake)"
    description = (
        "Where the axis holds a load at rest (a vertical axis's weight, or a load of fixed "
        "direction) and no brake is given, the load pushes the nut. The thread holds it "
        "only while its lead angle stays below the static friction angle; since friction "
        "drops with vibration and lubrication, the screw counts as self-locking only with "
        "static friction reduced by the self-locking friction factor. Give a brake's "
        "holding torque to judge holding instead. A stepper's energised holding torque "
        "holds only while the power is on: without its detent torque this check judges "
        "holding with the power off."
    )
    quantity = "length"
    formula = "lead = lead_screw; lead_max = pi * d_p * f * mu_s / cos(a_n)"
    source = "Shigley's Mechanical Engineering Design, sec. 8-2 (self-locking condition)"
    sources = ("friction_static", "thread_half_angle")
    capacity_sources = ("friction_static", "thread_half_angle")

    def applies(self, app: Application) -> bool:
        """Holding with the power off is required, and nothing else holds then
        (``unpowered_holder``): no brake given, nor a stepper's detent torque (its
        energised holding torque does not count)."""
        needed = app.hold_power_off and motion.holds_a_load(app)
        return needed and unpowered_holder(app) is None

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), t.lead_m, q.holding.max_self_locking_lead_with_margin_m)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "lead_screw": t.lead_m,
            "d_p": t.pitch_diameter_m,
            "f": app.self_locking_friction_factor,
            "mu_s": t.friction_static,
            "a_n": np.arccos(t.cos_half_angle),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        if s.screw_type == "ball" and not passed:
            return Phrase(
                "A ball screw always back-drives (rolling friction, efficiency near 90 % "
                "both ways): the load drives the screw {way} with the power off; holding "
                "torque {physics}. A brake is needed.",
                {"physics": Amount(r.holding.holding_distrusted_nm, "torque"), "way": way(app)},
            )
        rule = rule_note(app, s, passed)
        rule_text = "" if rule is None else " {rule}"
        values: dict[str, Amount | Phrase] = {
            "f": Amount(app.self_locking_friction_factor, "factor")
        }
        if rule is not None:
            values["rule"] = rule
        if passed:
            return Phrase(
                "Self-locking even with static friction at {f} x its value: the load cannot "
                "drive the screw {way}." + rule_text,
                {**values, "way": way(app)},
            )
        return Phrase(
            "Not reliably self-locking (static friction at {f} x its value): the load can "
            "drive the screw {way}; holding torque {seed} (seed method), {physics} "
            "(physics at {f} x static friction)." + rule_text,
            {
                **values,
                "way": way(app),
                "seed": Amount(r.holding.holding_seed_nm, "torque"),
                "physics": Amount(r.holding.holding_distrusted_nm, "torque"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return brake_or_lead(
            "Give a brake (it holds with the power off) of at least {needed}", s, r, reach
        )


def way(app: Application) -> str:
    """Which way a held load drives the nut: down a vertical axis, back on another."""
    return "down" if app.orientation == "vertical" else "back"


def rule_note(app: Application, s: ScrewSpec, locks_with_margin: bool) -> Phrase | None:
    """Where the catalog's rule of thumb (lead under OD / 8) and the physics (static
    friction at the self-locking factor against the lead angle) disagree: what the rule
    says, and that the physics governs, and why; None where they agree."""
    seed = efficiency.seed_backdrive_rule(s.lead_m, s.outer_diameter_m)
    if seed == locks_with_margin or s.screw_type == "ball":  # a sliding thread's rule
        return None
    return Phrase(
        "The catalog's rule of thumb (lead under OD / 8 = {od8}) says it "
        + ("holds" if seed else "back-drives")
        + "; the friction calculation governs (static friction at {f} x its value "
        "against the lead angle): the rule takes no account of this nut's friction, the "
        "thread angle or the margin on friction.",
        {
            "od8": Amount(s.outer_diameter_m / 8.0, "length"),
            "f": Amount(app.self_locking_friction_factor, "factor"),
        },
    )

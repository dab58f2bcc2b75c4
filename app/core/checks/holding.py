"""Vertical axis with a brake: the holding torque needed against the brake's."""

import numpy as np

from app.core import motion
from app.core.checks.base import (
    MARGIN_NOTE,
    Application,
    Array,
    CandidateTable,
    Check,
    Mapping,
    Measure,
    Quantities,
    Reach,
    ScrewSpec,
    at_most,
    everywhere,
    least,
    same,
)
from app.core.formulas import efficiency
from app.core.holding import brake_factor
from app.core.phrase import Amount, Phrase


def power_state(app: Application) -> str:
    """Which holding the given torque judges, in words."""
    if app.holding_source == "energised":
        return "with the power on (the motor's energised holding torque)"
    return "with the power off (a brake)"


def needed_symbols(app: Application, t: CandidateTable, q: Quantities[Array]) -> dict[str, object]:
    """The names of the torque a held load needs (``T_hold``'s side of the formula),
    shared by the holding checks; each adds the torque it judges it against."""
    return {
        "locks": q.holding.locks_with_margin.astype(bool),
        "SF": brake_factor(app),
        "T_seed": efficiency.holding_torque(q.axis.holding_force_n, t.lead_m, t.efficiency),
        "T_physics": q.holding.holding_distrusted_nm,
    }


def holding_phrase(
    app: Application, r: Quantities[float], available_nm: float, passed: bool, state: str
) -> Phrase:
    """The holding verdict: the torque available, what is needed and why, and the power
    state it holds in."""
    verb = "holds" if passed else "is short of"
    return Phrase(
        "Holding " + state + ": {available} " + verb + " the {needed} needed ({sf} x the "
        "larger of {seed} (seed method) and {physics} (physics at {f} x static friction)).",
        {
            "available": Amount(available_nm, "torque"),
            # a requirement: rounded up, so that the figure read holds
            "needed": Amount(r.holding.brake_needed_nm, "torque", "up"),
            "sf": Amount(brake_factor(app), "factor"),
            "seed": Amount(r.holding.holding_seed_nm, "torque"),
            "physics": Amount(r.holding.holding_distrusted_nm, "torque"),
            "f": Amount(app.self_locking_friction_factor, "factor"),
        },
    )


class Holding(Check):
    name = "holding"
    motor_may_clear = True
    capacity_given = "motor_holding"
    why_none = "no brake torque given holds this load on any screw: a larger brake"
    label = "Holding torque (load held at rest)"
    description = (
        "Where the axis holds a load at rest (vertical, or a load of fixed direction) the "
        "brake, or the motor's energised holding torque, must hold it wherever the thread "
        "is not reliably self-locking: the larger of the seed's holding torque and the "
        "physical one at the distrusted static friction (f mu_s, the friction the "
        "self-locking margin trusts), times the holding safety factor (for a brake, when "
        "none is typed, at least its service factor 1.5: it holds by friction, and wears). "
        "A brake holds with the power off; a stepper's holding torque only while it is "
        "energised."
    )
    quantity = "torque"
    formula = "T_hold = 0 if locks else SF * max(T_seed, T_physics); T_available = T_brake"
    source = (
        "seed catalog, Back Driving (T_b = F lead eta / 2 pi); Shigley sec. 8-2 "
        "(lowering torque at the distrusted friction); a brake's service factor: Machine "
        "Design, 'Mechatronics Q & A: Hold It Steady' (2007)"
    )
    sources = ("friction_static", "friction_dynamic", "thread_half_angle")

    def applies(self, app: Application) -> bool:
        return motion.holds_a_load(app) and app.brake_torque_nm is not None

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.holding.brake_needed_nm, same(t, app.brake_torque_nm))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {**needed_symbols(app, t, q), "T_brake": np.float64(app.brake_torque_nm or 0.0)}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        if r.holding.locks_with_margin:
            return Phrase("Self-locking with margin: the brake is not needed to hold.")
        return holding_phrase(app, r, app.brake_torque_nm or 0.0, passed, power_state(app))

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return brake_or_lead("Fit a brake of at least {needed}", s, r, reach)


def brake_or_lead(start: str, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
    """``start`` (naming the brake to fit, ``{needed}``: with a brake's safety factor), or
    the largest lead this size is made in that self-locks with margin, when it is made in
    one."""
    values = {"needed": least(r.holding.brake_to_fit_nm, "torque")}
    # the lead FIX_MARGIN inside the self-locking limit, as the fix promises
    limit = at_most(r.holding.max_self_locking_lead_with_margin_m)
    lead = reach.made_lead(s, limit, larger=False)
    if lead is None:
        return Phrase(start + "." + MARGIN_NOTE, values)
    return Phrase(
        start + ", or use a lead of {lead} (self-locking with margin)." + MARGIN_NOTE,
        {**values, "lead": Amount(lead, "length", "down")},
    )

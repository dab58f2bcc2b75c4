"""A stepper whose curve the microstepping model draws: its supply within the model's
range, at least 4 times its winding's rated voltage I R."""

import numpy as np

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
from app.core.checks.motor_curve import supply_known, supply_too_low
from app.core.formulas import stepper
from app.core.phrase import Amount, Phrase


class MotorSupply(Check):
    name = "motor_supply"
    why_none = "the stepper's supply is too low for its curve to be known: a higher supply"
    judges_motor = True
    label = "Stepper supply (model range)"
    description = (
        "Where a stepper's pull-out curve is drawn from its datasheet values (the "
        "microstepping model), its drive's supply at least 4 times its winding's rated "
        "voltage I R: below it makers' curves fall far faster than the model (STEPPERONLINE "
        "17HS24-0644S at 2.6 times I R: under a quarter of the model's figure at 420 rpm), "
        "so no pass can rest on it. A maker's published curve or a curve typed in is not "
        "judged."
    )
    formula = "passes when V_supply >= k * I * R"
    source = (
        "the microstepping model's validity range (app/core/formulas/stepper.py, "
        "supply_in_range; /validation)"
    )
    sources = ()

    def applies(self, app: Application) -> bool:
        return supply_known(app)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        # yes or no: a condition of the model's validity, not a margin of the axis
        return Measure(everywhere(t), flagged=np.full(len(t), supply_too_low(app)))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "k": stepper.LEAST_SUPPLY_PER_IR,
            "I": app.motor_phase_current_a,
            "R": app.motor_resistance_ohm,
            "V_supply": app.motor_supply_v,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is at least" if passed else "is below"
        end = "." if passed else ": outside the model's range, its curve is not known."
        return Phrase(
            "The supply {v} " + verb + " 4 times the winding's rated voltage I R, {least}" + end,
            {
                "v": Amount(app.motor_supply_v or 0.0, "voltage"),
                "least": Amount(_least_v(app), "voltage"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            "A supply of at least {least}, or the maker's pull-out curve at this supply "
            "(the motor curve input).",
            # a least supply written rounded up: the figure read is enough
            {"least": Amount(_least_v(app), "voltage", "up")},
        )


def _least_v(app: Application) -> float:
    """The least supply of the model's range [V] (``stepper.least_supply_v``)."""
    return stepper.least_supply_v(app.motor_phase_current_a or 0.0, app.motor_resistance_ohm or 0.0)

"""The travel of one step pulse against the positioning tolerance."""

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
from app.core.checks.step_rate import steps_per_rev
from app.core.phrase import Amount, Phrase


class StepResolution(Check):
    name = "step_resolution"
    label = "Step resolution"
    description = (
        "The travel of one step pulse (lead over 360 / step angle x microsteps) against "
        "the positioning tolerance: the axis cannot be told to stop between two pulses."
    )
    quantity = "length"
    formula = "delta = lead / (360 / step_angle * microsteps); tol_allowed = tol"
    source = "Prusa calculators (steps per mm); kinematics"
    sources = ("lead",)

    def applies(self, app: Application) -> bool:
        return app.step_angle_deg is not None and app.positioning_tolerance_m is not None

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(
            everywhere(t), q.motor.step_resolution_m, same(t, app.positioning_tolerance_m)
        )

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "lead": t.lead_m,
            "step_angle": app.step_angle_deg,
            "microsteps": app.microsteps,
            "tol": app.positioning_tolerance_m,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        per_rev = steps_per_rev(app)
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "{per_rev} steps per turn of the {lead} lead: one step moves {delta}, which "
            + verb
            + " the {tol} tolerance.",
            {
                "per_rev": f"{per_rev:g}",
                "lead": Amount(s.lead_m, "length"),
                "delta": Amount(r.motor.step_resolution_m, "length"),
                "tol": Amount(app.positioning_tolerance_m or 0.0, "length"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase("More microsteps, a finer step angle or a shorter lead.")

"""Worst-case positioning error over the stroke against the user's tolerance."""

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
    same,
    where_given,
)
from app.core.phrase import Amount, Phrase


class Accuracy(Check):
    name = "accuracy"
    label = "Positioning accuracy"
    description = (
        "Lead error over the stroke plus the largest backlash plus repeatability, against "
        "the tolerance."
    )
    quantity = "length"
    formula = "e = a_lead * stroke + b_max + r; e_allowed = tol"
    source = "seed catalog, Screw Accuracy"
    sources = ("lead_accuracy", "backlash", "repeatability")

    def applies(self, app: Application) -> bool:
        return app.positioning_tolerance_m is not None

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        error = q.lead_error_m + t.backlash_max_m + t.repeatability_m
        tolerance = same(t, app.positioning_tolerance_m)
        return Measure(where_given(t.lead_accuracy), error, tolerance)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "a_lead": t.lead_accuracy,
            "stroke": app.stroke_m if app.stroke_m is not None else app.length_m,
            "b_max": t.backlash_max_m,
            "r": t.repeatability_m,
            "tol": app.positioning_tolerance_m,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        error = r.lead_error_m + s.backlash_max_m + (s.repeatability_m or 0.0)
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "Worst-case error {e} " + verb + " the {tol} tolerance.",
            {
                "e": Amount(error, "length"),
                "tol": Amount(app.positioning_tolerance_m or 0.0, "length"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        if s.anti_backlash or not reach.anti_backlash:
            return Phrase("Choose a precision lead grade, or widen the tolerance.")
        return Phrase("Choose an anti-backlash series (no backlash) or a precision lead grade.")
